"""Controllers in simulate(): continuous (CasADi Function, symbolic callable) against the
closed loop's matrix exponential, sampled against the exact discretization of the loop;
Ctrl-C returning the run so far; the progress bar off by default."""
import importlib
import math
import warnings

import casadi as ca
import numpy as np
import pytest
from scipy.linalg import expm

import acausal
from acausal.components.translational import Force, Mass
from acausal.errors import SimulationError
from acausal.simulation import Controller
from interrupt import InterruptAfter
from lti import held_input_flow

simulate_module = importlib.import_module("acausal.simulation.simulate")

MASS, KP, KD, REF = 2.0, 8.0, 3.0, 1.0
A = np.array([[0.0, 1.0], [0.0, 0.0]])
B = np.array([0.0, 1.0 / MASS])
GRID = np.linspace(0.0, 3.0, 61)


@pytest.fixture(scope="module")
def compiled():
    m = acausal.Model("pushed")
    m.mass = Mass(m=MASS)
    m.force = Force()
    m.F = acausal.Input(unit="N")
    m.connect(m.force.flange, m.mass.flange_a)
    m.connect(m.F.y, m.force.f)
    return acausal.compile(m)


def pd(s, v):
    return KP * (REF - s) - KD * v


def continuous_loop(t, x0):
    """[s, v] of m s'' = KP (REF − s) − KD s' (the error e = s − REF decays as e' = A_cl e)."""
    Acl = A - np.outer(B, [KP, KD])
    e0 = np.asarray(x0) - [REF, 0.0]
    return np.array([expm(Acl * tk) @ e0 for tk in t]) + [REF, 0.0]


def test_casadi_function_controller_equals_the_closed_loop(compiled):
    y = ca.SX.sym("y", 2)
    ctrl = ca.Function("pd", [ca.SX.sym("t"), y], [pd(y[0], y[1])])
    res = compiled.simulate(3.0, t=GRID, inputs={"F": Controller(ctrl, of=["mass.s", "mass.v"])},
                            rtol=1e-10, atol=1e-12)
    exact = continuous_loop(GRID, [0.0, 0.0])
    np.testing.assert_allclose(res["mass.s"], exact[:, 0], atol=1e-8)
    np.testing.assert_allclose(res["F"], pd(exact[:, 0], exact[:, 1]), atol=1e-7)
    np.testing.assert_allclose(res["force.f"], res["F"], atol=1e-12)


def test_symbolic_python_controller_of_named_states(compiled):
    res = compiled.simulate(3.0, t=GRID, x0={"mass.v": 0.5}, rtol=1e-10, atol=1e-12,
                            inputs={"F": lambda t, y: pd(y["mass.s"], y["mass.v"])})
    np.testing.assert_allclose(res["mass.s"], continuous_loop(GRID, [0.0, 0.5])[:, 0],
                               atol=1e-8)


def test_a_controller_that_rejects_symbols_needs_a_period(compiled):
    def bang_bang(t, y):
        return 1.0 if y["mass.s"] < REF else -1.0
    with pytest.raises(SimulationError, match="period"):
        compiled.simulate(1.0, inputs={"F": bang_bang})


def test_a_controller_that_makes_nan_of_symbols_is_refused(compiled):
    """Python's float() and the math module turn a CasADi symbol into NaN without an error:
    such a controller would feed NaN into the equations; it is refused by name."""
    with pytest.raises(SimulationError, match="input 'F': the controller turns CasADi "
                                              "symbols into NaN"):
        compiled.simulate(1.0, inputs={"F": lambda t, y: -10.0 * math.tanh(y["mass.s"])})


def sampled_loop(period, t, x0):
    """The exact discretization: x(t_k + τ) = e^{Aτ} x_k + ∫_0^τ e^{Aσ} dσ B u_k, u_k the PD
    of x_k held over [t_k, t_k + period)."""
    out, x, tk = [], np.asarray(x0, dtype=float), 0.0
    for ti in t:
        while ti >= tk + period - 1e-12:
            Phi, Gam = held_input_flow(A, B, period)
            x, tk = Phi @ x + Gam * pd(*x), tk + period
        Phi, Gam = held_input_flow(A, B, ti - tk)
        out.append(Phi @ x + Gam * pd(*x))
    return np.array(out)


def test_sampled_controller_equals_the_exact_discretization(compiled):
    calls = []

    def ctrl(t, y):
        calls.append(t)
        return pd(y["mass.s"], y["mass.v"])
    res = compiled.simulate(3.0, t=GRID, inputs={"F": Controller(ctrl, period=0.2)},
                            rtol=1e-11, atol=1e-13)
    np.testing.assert_allclose(res["mass.s"], sampled_loop(0.2, GRID, [0.0, 0.0])[:, 0],
                               atol=1e-9)
    np.testing.assert_allclose(calls, 0.2 * np.arange(15), atol=1e-12)   # once per sample


def test_ctrl_c_in_a_sampled_run_returns_the_run_so_far(compiled):
    def ctrl(t, y):
        if t > 1.0:
            raise KeyboardInterrupt
        return pd(y["mass.s"], y["mass.v"])
    full = compiled.simulate(3.0, t=GRID, inputs={"F": Controller(
        lambda t, y: pd(y["mass.s"], y["mass.v"]), period=0.2)})
    with pytest.warns(UserWarning, match="interrupted"):
        part = compiled.simulate(3.0, t=GRID, inputs={"F": Controller(ctrl, period=0.2)})
    assert part.partial and not full.partial
    # the full run is the exact discretization (default tolerances of simulate())
    np.testing.assert_allclose(full["mass.s"], sampled_loop(0.2, GRID, [0.0, 0.0])[:, 0],
                               atol=1e-7)
    n = part.t.size
    assert 1.0 <= part.t[-1] < 1.2 + 1e-9
    np.testing.assert_array_equal(part.t, GRID[:n])
    np.testing.assert_allclose(part["mass.s"], full["mass.s"][:n], rtol=0, atol=1e-14)


def test_ctrl_c_in_simulate_returns_the_run_so_far(compiled, monkeypatch):
    full = compiled.simulate(3.0, t=GRID, inputs={"F": 1.0}, progress=True, rtol=1e-10,
                             atol=1e-12)
    monkeypatch.setattr(simulate_module, "progress_bar", InterruptAfter(1.0))
    with pytest.warns(UserWarning, match="interrupted"):
        part = compiled.simulate(3.0, t=GRID, inputs={"F": 1.0}, progress=True, rtol=1e-10,
                                 atol=1e-12)
    n = part.t.size
    assert part.partial and 0.9 < part.t[-1] < 1.2
    np.testing.assert_allclose(part["mass.s"], full["mass.s"][:n], rtol=0, atol=1e-14)
    # the free mass under a constant force: s = F t² / (2 m)
    np.testing.assert_allclose(full["mass.s"], GRID ** 2 / (2 * MASS), atol=1e-8)


def test_progress_is_off_by_default(compiled, capfd):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        compiled.simulate(1.0, inputs={"F": 1.0})
    assert capfd.readouterr().err == ""


def test_ctrl_c_between_state_events_returns_the_run_so_far(monkeypatch):
    from acausal.models.bouncing_ball import BouncingBall
    e, g, h = 0.8, 9.81, 1.0
    model = acausal.compile(BouncingBall(e=e, g=g))
    full = model.simulate(2.0, x0={"ball.s": h}, rtol=1e-10, atol=1e-12)
    monkeypatch.setattr(simulate_module, "progress_bar", InterruptAfter(1.0))
    with pytest.warns(UserWarning, match="interrupted"):
        part = model.simulate(2.0, x0={"ball.s": h}, rtol=1e-10, atol=1e-12, progress=True)
    n = part.t.size
    hit = np.sqrt(2 * h / g)                    # the first impact, by the closed form
    assert part.partial and n < full.t.size and part.t[-1] >= hit - 1e-9
    np.testing.assert_array_equal(part.t, full.t[:n])
    np.testing.assert_allclose(part["ball.s"], full["ball.s"][:n], rtol=0, atol=1e-14)
    assert part.events[0].time == pytest.approx(hit, abs=1e-9)


def test_continuous_controller_on_a_model_with_impacts():
    """A ball held by a controller F = −k·s (a spring to the floor level) in gravity,
    bouncing on the floor: between impacts s = s_eq + A cos ω(t − t_i) + B sin ω(t − t_i)
    (s_eq = −m g / k), at an impact v → −e·v."""
    from acausal.models.bouncing_ball import Floor
    from acausal.components.translational import ConstantForce
    m_, g, e, k, s0 = 1.0, 9.81, 0.8, 20.0, 1.0
    model = acausal.Model("held_ball")
    model.ball, model.gravity, model.floor = Mass(m=m_), ConstantForce(f_constant=-m_ * g), \
        Floor(e=e)
    model.force, model.F = Force(), acausal.Input(unit="N")
    for a, b in [(model.gravity.flange, model.ball.flange_a),
                 (model.floor.flange, model.ball.flange_a),
                 (model.force.flange, model.ball.flange_b), (model.F.y, model.force.f)]:
        model.connect(a, b)
    compiled = acausal.compile(model)
    t = np.linspace(0.0, 0.6, 61)
    res = compiled.simulate(0.6, t=t, x0={"ball.s": s0}, rtol=1e-11, atol=1e-13,
                            inputs={"F": lambda t, y: -k * y["ball.s"]})
    w, s_eq = np.sqrt(k / m_), -m_ * g / k
    t1 = np.arccos(-s_eq / (s0 - s_eq)) / w                   # the first impact
    v1 = -e * (-(s0 - s_eq) * w * np.sin(w * t1))             # the speed after it
    tt = res.t
    exact = np.where(tt < t1, s_eq + (s0 - s_eq) * np.cos(w * tt),
                     s_eq - s_eq * np.cos(w * (tt - t1)) + v1 / w * np.sin(w * (tt - t1)))
    assert len(res.events) == 1 and res.events[0].time == pytest.approx(t1, abs=1e-9)
    np.testing.assert_allclose(res["ball.s"], exact, atol=1e-8)
    np.testing.assert_allclose(res["F"], -k * res["ball.s"], atol=1e-12)
