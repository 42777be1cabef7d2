"""simulate(..., solver='dop853'): scipy's explicit Runge–Kutta method of order 8 on the
model's right-hand side, in process and on the generated C (codegen=True).

References: closed forms (the pendulum's Jacobi elliptic functions, the oscillator's step
response across an input jump, the free mass under a constant force); scipy's
``solve_ivp(method='DOP853')`` run by hand on a double pendulum's equations of motion written
here in numpy (the same method and step control: equal to ~1e-12, also with nominals, which
scale the absolute tolerance as a per-state atol does); the full run (for Ctrl-C)."""
from __future__ import annotations

import importlib
import sys

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.special import ellipj, ellipk

import acausal
import acausal.toolchain as toolchain
from acausal.components.translational import Damper, Fixed, Force, Mass, Spring
from acausal.errors import SimulationError
from acausal.models import FourBar
from acausal.models.bouncing_ball import BouncingBall
from acausal.models.pendulums import PendulumChain
from acausal.simulation import Controller, Samples
from forced_oscillator import forced_oscillator
from interrupt import InterruptAfter

simulate_module = importlib.import_module("acausal.simulation.simulate")
HAS_CC = any(toolchain.shutil.which(c) for c in ("cc", "gcc", "clang"))
CODEGEN = [False, pytest.param(True, marks=pytest.mark.skipif(not HAS_CC,
                                                              reason="no C compiler"))]
L, M, I, G = 0.5, 1.0, 0.01, 9.81                    # PendulumChain's link [m, kg, kg.m², m/s²]


@pytest.fixture(scope="module", autouse=True)
def cache(codegen_cache):
    """This module's cache of generated code."""
    return codegen_cache


@pytest.fixture(scope="module")
def pendulum():
    return acausal.compile(PendulumChain(1))


@pytest.fixture(scope="module")
def double():
    return acausal.compile(PendulumChain(2))


@pytest.mark.parametrize("codegen", CODEGEN)
def test_pendulum_swings_as_the_elliptic_closed_form(pendulum, codegen):
    """Released from rest at θ0: θ(t) = 2 asin(k sn(K(k) − ω0 t, k)), k = sin(θ0/2),
    ω0² = m g L / (I + m L²)."""
    theta0, t = 2.5, np.linspace(0.0, 4.0, 201)
    res = pendulum.simulate(4.0, t=t, x0={"rev1.phi": theta0}, solver="dop853", rtol=1e-12,
                            atol=1e-14, codegen=codegen)
    k, w0 = np.sin(theta0 / 2), np.sqrt(M * G * L / (I + M * L ** 2))
    sn = ellipj(ellipk(k ** 2) - w0 * t, k ** 2)[0]
    assert res.solver == "dop853"
    np.testing.assert_allclose(res["rev1.phi"], 2 * np.arcsin(k * sn), rtol=0, atol=1e-10)


def double_pendulum(t, y, names):
    """The double pendulum of PendulumChain(2) in numpy, in the model's states ``names``
    (relative angles φ1, φ2 and their rates): the Lagrange equations in the absolute angles
    θ1 = φ1, θ2 = φ1 + φ2 of two bodies (m, I) at the ends of massless bars of length L."""
    s = dict(zip(names, y))
    th1, th2 = s["rev1.phi"], s["rev1.phi"] + s["rev2.phi"]
    w1, w2 = s["rev1.w"], s["rev1.w"] + s["rev2.w"]
    c, sn, mL2 = np.cos(th1 - th2), np.sin(th1 - th2), M * L ** 2
    Mass = np.array([[2 * mL2 + I, mL2 * c], [mL2 * c, mL2 + I]])
    rhs = -np.array([mL2 * sn * w2 ** 2 + 2 * M * G * L * np.sin(th1),
                     -mL2 * sn * w1 ** 2 + M * G * L * np.sin(th2)])
    a1, a2 = np.linalg.solve(Mass, rhs)
    der = {"rev1.phi": s["rev1.w"], "rev2.phi": s["rev2.w"], "rev1.w": a1, "rev2.w": a2 - a1}
    return np.array([der[n] for n in names])


@pytest.mark.parametrize("codegen", CODEGEN)
def test_double_pendulum_equals_scipy_dop853_by_hand(double, codegen):
    names, grid = double.x_names, np.linspace(0.0, 3.0, 151)
    start = {"rev1.phi": 1.2, "rev2.phi": -0.7, "rev1.w": 0.5, "rev2.w": 0.0}
    nominal = {"rev1.w": 5.0, "rev2.phi": 0.1}
    y0 = np.array([start[n] for n in names])
    atol = 1e-10 * np.array([nominal.get(n, 1.0) for n in names])
    ref = solve_ivp(double_pendulum, (0.0, 3.0), y0, method="DOP853", t_eval=grid, rtol=1e-8,
                    atol=atol, args=(names,))
    assert ref.success
    res = double.simulate(3.0, t=grid, x0=start, solver="dop853", rtol=1e-8, atol=1e-10,
                          nominal=nominal, codegen=codegen)
    np.testing.assert_allclose(np.array([res[n] for n in names]), ref.y, rtol=0, atol=1e-12)
    # with the nominals, not the same steps as without them
    plain = double.simulate(3.0, t=grid, x0=start, solver="dop853", codegen=codegen)
    assert np.max(np.abs(np.array([plain[n] for n in names]) - ref.y)) > 1e-9


@pytest.mark.parametrize("codegen", CODEGEN)
def test_step_of_the_force_restarts_the_run_at_the_jump(codegen):
    """F jumps from 0 to 2 N at t1 = 1.05 s (a time event between output times): from rest,
    s = F/c (1 − cos ω (t − t1)) after it, ω² = c/m."""
    model = acausal.compile(forced_oscillator())
    t, t1 = np.linspace(0.0, 3.0, 61), 1.05
    res = model.simulate(3.0, t=t, inputs={"F": Samples([0.0, t1, t1, 3.0], [0.0, 0.0, 2.0, 2.0],
                                                        "hold")},
                         solver="dop853", rtol=1e-11, atol=1e-13, codegen=codegen)
    exact = np.where(t > t1, 2.0 / 8.0 * (1 - np.cos(4.0 * (t - t1))), 0.0)
    np.testing.assert_allclose(res["mass.s"], exact, rtol=0, atol=1e-10)
    np.testing.assert_allclose(res["F"], np.where(t >= t1, 2.0, 0.0))


def test_continuous_controller_closes_the_loop():
    """A PD controller on the forced oscillator: m s'' = F − c s, F = kp (1 − s) − kd s'
    (linear: the matrix exponential by hand)."""
    from scipy.linalg import expm
    model = acausal.compile(forced_oscillator())
    kp, kd, t = 10.0, 2.0, np.linspace(0.0, 2.0, 41)
    res = model.simulate(2.0, t=t, solver="dop853", rtol=1e-11, atol=1e-13, inputs={
        "F": Controller(lambda t, y: kp * (1.0 - y["mass.s"]) - kd * y["mass.v"])})
    A = np.array([[0.0, 1.0], [-(8.0 + kp) / 0.5, -kd / 0.5]])
    rest = np.array([kp / (8.0 + kp), 0.0])             # where the loop settles
    exact = np.array([rest + expm(A * tk) @ -rest for tk in t])
    np.testing.assert_allclose(res["mass.s"], exact[:, 0], rtol=0, atol=1e-10)


def test_ctrl_c_returns_the_run_so_far(monkeypatch):
    """The oscillator under F = 2 N from rest: s = F/c (1 − cos ω t); interrupted past 1 s,
    the Result holds the output times the steps passed, equal to the full run's."""
    model, grid = acausal.compile(forced_oscillator()), np.linspace(0.0, 3.0, 61)
    full = model.simulate(3.0, t=grid, inputs={"F": 2.0}, solver="dop853", progress=True,
                          rtol=1e-11, atol=1e-13)
    np.testing.assert_allclose(full["mass.s"], 2.0 / 8.0 * (1 - np.cos(4.0 * grid)), rtol=0,
                               atol=1e-10)
    monkeypatch.setattr(simulate_module, "progress_bar", InterruptAfter(1.0))
    with pytest.warns(UserWarning, match="interrupted"):
        part = model.simulate(3.0, t=grid, inputs={"F": 2.0}, solver="dop853", progress=True,
                              rtol=1e-11, atol=1e-13)
    n = part.t.size
    assert part.partial and 1.0 <= part.t[-1] < 1.5
    np.testing.assert_array_equal(part["mass.s"], full["mass.s"][:n])


def test_daes_are_refused():
    with pytest.raises(SimulationError, match="closed kinematic loops.*ODEs only.*idas"):
        acausal.compile(FourBar()).simulate(1.0, solver="dop853")


def test_events_are_refused():
    with pytest.raises(SimulationError, match="state events or modes.*dop853"):
        acausal.compile(BouncingBall()).simulate(1.0, solver="dop853")


def test_stiff_model_stops_after_the_step_limit():
    """A tiny mass on a damper (time constant 1e-6 s against 1 s): too many steps."""
    m = acausal.Model("stiff")
    m.wall, m.spring, m.damper = Fixed(), Spring(c=1.0, s_rel0=0.0), Damper(d=1.0)
    m.mass = Mass(m=1e-6)
    for part in (m.spring, m.damper):
        m.connect(m.wall.flange, part.flange_a)
        m.connect(part.flange_b, m.mass.flange_a)
    with pytest.raises(SimulationError, match="1000 steps.*stiff.*cvodes"):
        acausal.compile(m).simulate(1.0, x0={"mass.s": 0.1}, solver="dop853",
                                    options={"max_num_steps": 1000})


def test_unknown_options_are_refused(pendulum):
    with pytest.raises(SimulationError, match="options.*max_num_steps.*abstol"):
        pendulum.simulate(1.0, solver="dop853", options={"abstol": 1e-6})


def test_without_scipy_the_message_says_how_to_get_it(pendulum, monkeypatch):
    monkeypatch.setitem(sys.modules, "scipy.integrate", None)      # import fails
    with pytest.raises(SimulationError, match=r"needs scipy.*acausal\[analysis\]"):
        pendulum.simulate(1.0, solver="dop853")


@pytest.mark.parametrize("options, match", [({"max_num_steps": 0}, "max_num_steps.*integer"),
                                            ({"first_step": -1.0}, "first_step.*> 0")])
def test_bad_options_are_refused(pendulum, options, match):
    with pytest.raises(SimulationError, match=match):
        pendulum.simulate(1.0, solver="dop853", options=options)


def test_a_force_that_blows_up_fails_in_the_models_terms():
    """F = 1 / (1 − t) N on a free mass: the equations are not finite at t = 1 s."""
    m = acausal.Model("pushed")
    m.mass, m.force, m.F = Mass(m=1.0), Force(), acausal.Input(unit="N")
    m.connect(m.force.flange, m.mass.flange_a)
    m.connect(m.F.y, m.force.f)
    with pytest.raises(SimulationError, match=r"'pushed' with solver='dop853' failed .*at "
                                              r"t = 1 s.*not finite"):
        acausal.compile(m).simulate(2.0, solver="dop853", inputs={"F": lambda t: 1 / (1 - t)})
