"""Gantry crane transfer in minimum time (acausal.models.crane, examples/ocp_crane_min_time.py),
free final time: minimize T with |F| ≤ F_max, from rest at x = 0 to rest at x = D with the
rope vertical.

References independent of acausal: the optimal piecewise-constant force replayed through
scipy's solve_ivp on the textbook's closed-form crane equations (M(q) q̈ + C q̇ = gravity +
coriolis + [F, 0]) brings the load to rest at the target (to 1e-6: the transcription's
error) and follows the optimized nodes (to 1e-6); the minimum time exceeds the rigid
transfer's 2·sqrt(D (M + m) / F_max); the force is bang-bang. Collocation and multiple
shooting agree on T to 1e-5.
"""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.models import crane
from acausal.ocp import OCP, FreeTime

DISTANCE, F_MAX = 1.0, 10.0                  # m, N
REST = {"hinge.phi": 0.0, "rail.v": 0.0, "hinge.w": 0.0}
IPOPT = {"tol": 1e-10}
N = 40


def min_time_transfer(compiled, N=40, method="collocation", **kw) -> OCP:
    """The minimum-time transfer through acausal.ocp (not yet solved)."""
    ocp = OCP(compiled, N=N, T=FreeTime(guess=3.0, lower=0.1, upper=20.0), method=method, **kw)
    ocp.minimize(ocp.T)
    ocp.bounds("F", -F_MAX, F_MAX)
    ocp.initial({"rail.s": 0.0, **REST})
    ocp.final({"rail.s": DISTANCE, **REST})
    return ocp


def rigid_bound() -> float:
    """Minimum time [s] of the transfer of a rigid cart-and-load (no sway) from rest to rest:
    accelerate, then brake, 2·sqrt(D (M + m) / F_max)."""
    return 2.0 * np.sqrt(DISTANCE * (crane.CART_MASS + crane.LOAD_MASS) / F_MAX)


def closed_form_rhs(t, y, F, M=crane.CART_MASS, m=crane.LOAD_MASS, L=crane.ROPE,
                    c=crane.RAIL_DAMPING, cT=crane.HINGE_DAMPING, g=9.81):
    """the textbook's gantry crane, y = [x, θ, ẋ, θ̇]."""
    th, xd, thd = y[1], y[2], y[3]
    Mq = np.array([[M + m, m * L * np.cos(th)], [m * L * np.cos(th), m * L ** 2]])
    rhs = np.array([F + m * L * np.sin(th) * thd ** 2 - c * xd, -m * g * L * np.sin(th) - cT * thd])
    return np.concatenate([[xd, thd], np.linalg.solve(Mq, rhs)])


@pytest.fixture(scope="module")
def solutions():
    compiled = acausal.compile(crane.GantryCrane())
    return {m: min_time_transfer(compiled, N=N, method=m).solve(IPOPT)
            for m in ("collocation", "shooting")}


def replay(sol):
    """Integrate the closed form with the optimal force, interval by interval."""
    F, t = sol.control("F"), sol.t
    y, out = np.zeros(4), [np.zeros(4)]
    for k in range(N):
        r = solve_ivp(closed_form_rhs, (t[k], t[k + 1]), y, args=(F[k],), rtol=1e-12,
                      atol=1e-12, method="DOP853")
        y = r.y[:, -1]
        out.append(y)
    return np.array(out).T


@pytest.mark.parametrize("method", ["collocation", "shooting"])
def test_replayed_force_moves_the_load_to_rest_at_the_target(solutions, method):
    sol = solutions[method]
    Y = replay(sol)
    names = ["rail.s", "hinge.phi", "rail.v", "hinge.w"]
    for row, name in enumerate(names):
        np.testing.assert_allclose(sol[name], Y[row], atol=1e-6)
    np.testing.assert_allclose(Y[:, -1], [DISTANCE, 0.0, 0.0, 0.0], atol=1e-6)
    # the load (recorded by the planar Body) is above the target and at rest
    assert sol["load.r[1]"][-1] == pytest.approx(DISTANCE, abs=1e-9)
    assert abs(sol["load.v[1]"][-1]) < 1e-9


def test_minimum_time_is_bang_bang_and_above_the_rigid_bound(solutions):
    sol = solutions["collocation"]
    F = sol.control("F")
    assert np.max(np.abs(F)) <= F_MAX + 1e-7
    assert np.sum(np.abs(np.abs(F) - F_MAX) < 1e-6) >= N - 4      # a few switch intervals
    assert sol.T > rigid_bound()
    assert sol.cost == pytest.approx(sol.T, rel=1e-12)
    assert solutions["shooting"].T == pytest.approx(sol.T, rel=1e-5)
