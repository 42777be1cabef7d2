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
