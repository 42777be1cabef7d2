"""Cart-pole swing-up with minimum effort (examples/ocp_cartpole.py): the model built from
planar components through acausal.ocp gives the same optimum as a hand-written casadi.Opti
formulation of the closed-form equations with the same transcription, solved in the same
run: the costs agree to 1e-6 relative (observed ~1e-13) and the trajectories to 1e-6.
"""
import sys
from pathlib import Path

import numpy as np
import pytest

import acausal

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "examples"))
import ocp_cartpole as ex  # noqa: E402

IPOPT = {"tol": 1e-10}
N = 25


@pytest.fixture(scope="module")
def compiled():
    return acausal.compile(ex.CartPole())


def solve_both(compiled, method, **kw):
    sol = ex.swing_up(compiled, N=N, method=method, **kw).solve(IPOPT)
    opti, X, U = ex.hand_written(N=N, method=method, **kw)
    opti.solver("ipopt", {"print_time": False, "ipopt": {"print_level": 0, "sb": "yes", **IPOPT}})
    ref = opti.solve()
    return sol, ref.value(opti.f), ref.value(X), ref.value(U)


@pytest.mark.parametrize("method, kw", [("collocation", {"scheme": "radau", "degree": 3}),
                                        ("collocation", {"scheme": "legendre", "degree": 2}),
                                        ("shooting", {})])
def test_same_optimum_as_hand_written_opti(compiled, method, kw):
    sol, cost, X, U = solve_both(compiled, method, **kw)
    assert sol.status == "Solve_Succeeded"
    assert abs(sol.cost - cost) <= 1e-6 * cost
    for row, name in enumerate(["rail.s", "hinge.phi", "rail.v", "hinge.w"]):
        np.testing.assert_allclose(sol[name], X[row], atol=1e-6)
    np.testing.assert_allclose(sol.control("F"), U, atol=1e-5)
    # the boundary conditions, read from recorded variables of the planar model: the tip is
    # straight above the cart at the end, l above the rail, and at rest
    assert sol["tip.r[1]"][-1] == pytest.approx(ex.DISTANCE, abs=1e-9)
    assert sol["tip.r[2]"][-1] == pytest.approx(ex.LENGTH, abs=1e-9)
    assert abs(sol["tip.v[1]"][-1]) < 1e-9 and abs(sol["tip.v[2]"][-1]) < 1e-9
    assert np.max(np.abs(sol.control("F"))) <= ex.F_MAX + 1e-6


def test_cost_is_the_integral_of_the_squared_force(compiled):
    """The integral ∫F² dt of piecewise-constant F is h·ΣF_k² (closed form)."""
    ocp = ex.swing_up(compiled, N=N)
    sol = ocp.solve(IPOPT)
    h = ex.T_FINAL / N
    assert sol.cost == pytest.approx(h * np.sum(sol.control("F") ** 2), rel=1e-12)
    assert sol.value(ocp["F"]) == pytest.approx(sol.control("F"), abs=0)
