"""The integrators simulate() offers give the closed-form oscillator."""
import numpy as np
import pytest

import acausal
from acausal.components.translational import Fixed, Mass, Spring


def oscillator():
    m = acausal.Model("osc")
    m.wall, m.spring, m.mass = Fixed(), Spring(c=9.0), Mass(m=1.0)
    m.connect(m.wall.flange, m.spring.flange_a)
    m.connect(m.spring.flange_b, m.mass.flange_a)
    return acausal.compile(m)


@pytest.mark.parametrize("solver, options, tol", [
    ("cvodes", {}, 1e-6), ("adams", {}, 1e-6), ("idas", {}, 1e-6),
    ("rk", {"number_of_finite_elements": 50}, 1e-6)])
def test_solvers_give_closed_form(solver, options, tol):
    t = np.linspace(0.0, 2.0, 41)
    res = oscillator().simulate(2.0, t=t, x0={"mass.s": 0.1}, solver=solver, options=options)
    np.testing.assert_allclose(res["mass.s"], 0.1 * np.cos(3.0 * t), atol=tol)


def test_unknown_solver_is_refused():
    with pytest.raises(acausal.SimulationError, match="unknown solver"):
        oscillator().simulate(1.0, solver="euler")


def overdamped(d: float):
    """A mass on a spring (c = 1 N/m) and a damper d [N.s/m]: eigenvalues
    (−d ± sqrt(d² − 4))/2, one fast decay and one slow one for large d."""
    from acausal.components.translational import Damper
    m = acausal.Model("overdamped")
    m.wall, m.spring, m.damper, m.mass = Fixed(), Spring(c=1.0), Damper(d=d), Mass(m=1.0)
    for a, b in [(m.wall.flange, m.spring.flange_a), (m.wall.flange, m.damper.flange_a),
                 (m.spring.flange_b, m.mass.flange_a), (m.damper.flange_b, m.mass.flange_a)]:
        m.connect(a, b)
    return acausal.compile(m)


def test_default_solver_follows_stiffness():
    """Undamped oscillator: not stiff -> Adams; d = 1e4 (decay 1e4 /s against a 1e-4 /s mode):
    stiff -> BDF. Both match their closed forms."""
    t = np.linspace(0.0, 2.0, 41)
    res = oscillator().simulate(2.0, t=t, x0={"mass.s": 0.1})
    assert res.solver == "adams"
    np.testing.assert_allclose(res["mass.s"], 0.1 * np.cos(3.0 * t), atol=1e-7)
    d = 1e4
    lam = np.array([(-d + np.sqrt(d * d - 4)) / 2, (-d - np.sqrt(d * d - 4)) / 2])
    res = overdamped(d).simulate(2.0, t=t, x0={"mass.s": 0.1, "mass.v": 0.0})
    assert res.solver == "cvodes"
    # s = a e^{λ1 t} + b e^{λ2 t} with s(0) = 0.1, v(0) = 0
    a, b = np.linalg.solve([[1.0, 1.0], lam], [0.1, 0.0])
    np.testing.assert_allclose(res["mass.s"], a * np.exp(lam[0] * t) + b * np.exp(lam[1] * t),
                               rtol=1e-6, atol=1e-12)
