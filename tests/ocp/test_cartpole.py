"""Cart-pole swing-up with minimum effort (acausal.models.cartpole, examples/ocp_cartpole.py):
the model built from planar components through acausal.ocp gives the same optimum as a
hand-written casadi.Opti formulation of the closed-form equations with the same transcription,
solved in the same run: the costs agree to 1e-6 relative (observed ~1e-13) and the
trajectories to 1e-6. Also: an infeasible swing-up reports IPOPT's status, and a bound on a
recorded variable (the tip's position, checked by hand from x and θ) holds at the nodes.

The problem (M. Kelly, "An introduction to trajectory optimization", SIAM Review 2017, 6):
minimize ∫₀ᵀ F² dt, T = 2 s, |F| ≤ 20 N, |x| ≤ 2 m, from rest hanging down at x = 0 to rest
upright (θ = π) at x = 1 m. The hand-written equations (Lagrange, eliminated for the
accelerations):

    ẍ = (m2 l sinθ θ̇² + F + m2 g cosθ sinθ) / (m1 + m2 sin²θ)
    θ̈ = −(m2 l cosθ sinθ θ̇² + F cosθ + (m1 + m2) g sinθ) / (l (m1 + m2 sin²θ))
"""
import casadi as ca
import numpy as np
import pytest

import acausal
from acausal.models.cartpole import LENGTH, M_CART, M_POLE, CartPole
from acausal.ocp import OCP, SolveError

G = 9.81                                               # m/s²
T_FINAL, DISTANCE, F_MAX, X_MAX = 2.0, 1.0, 20.0, 2.0  # s, m, N, m
START = {"rail.s": 0.0, "hinge.phi": 0.0, "rail.v": 0.0, "hinge.w": 0.0}
TARGET = {"rail.s": DISTANCE, "hinge.phi": np.pi, "rail.v": 0.0, "hinge.w": 0.0}
IPOPT = {"tol": 1e-10}
N = 25


def swing_up(compiled, N=30, method="collocation", **kw) -> OCP:
    """The swing-up problem through acausal.ocp (not yet solved)."""
    ocp = OCP(compiled, N=N, T=T_FINAL, method=method, **kw)
    ocp.minimize(ocp.integral(lambda v: v["F"] ** 2))
    ocp.bounds("F", -F_MAX, F_MAX)
    ocp.bounds("rail.s", -X_MAX, X_MAX)
    ocp.initial(START)
    ocp.final(TARGET)
    return ocp


# ---- the hand-written reference --------------------------------------------------------------
def cartpole_ode(x, F, m1=M_CART, m2=M_POLE, l=LENGTH, g=G):
    """Closed-form right-hand side for x = [x, θ, ẋ, θ̇] and force F."""
    th, thd = x[1], x[3]
    s, c = ca.sin(th), ca.cos(th)
    den = m1 + m2 * s ** 2
    xdd = (m2 * l * s * thd ** 2 + F + m2 * g * c * s) / den
    thdd = -(m2 * l * c * s * thd ** 2 + F * c + (m1 + m2) * g * s) / (l * den)
    return ca.vertcat(x[2], x[3], xdd, thdd)


def collocation_coefficients(d: int, scheme: str):
    """Collocation points ('radau' or 'legendre') and the matrices of the Lagrange basis
    through τ = 0 and them (numpy polynomials, as in CasADi's direct_collocation example):
    C[r, j] = l_r'(τ_j) and D[r] = l_r(1)."""
    tau = np.append(0.0, ca.collocation_points(d, scheme))
    C, D = np.zeros((d + 1, d)), np.zeros(d + 1)
    for r in range(d + 1):
        p = np.poly1d([1.0])
        for s in range(d + 1):
            if s != r:
                p *= np.poly1d([1.0, -tau[s]]) / (tau[r] - tau[s])
        D[r] = p(1.0)
        C[r] = np.polyder(p)(tau[1:])
    return tau, C, D


def hand_written(N=30, method="collocation", degree=3, scheme="radau", steps=4):
    """The swing-up in casadi.Opti from the closed form: collocation of ``degree`` at
    ``scheme`` points, or multiple shooting with ``steps`` RK4 steps per interval; returns
    the Opti, the state matrix X and control row U (not yet solved)."""
    opti = ca.Opti()
    h = T_FINAL / N
    X, U = opti.variable(4, N + 1), opti.variable(1, N)
    x_s, u_s = ca.MX.sym("x", 4), ca.MX.sym("F")
    f = ca.Function("f", [x_s, u_s], [cartpole_ode(x_s, u_s)])
    x0, x1 = np.array(list(START.values())), np.array(list(TARGET.values()))
    guess = np.linspace(x0, x1, N + 1).T
    opti.set_initial(X, guess)
    if method == "collocation":
        tau, C, D = collocation_coefficients(degree, scheme)
        for k in range(N):
            Xc = opti.variable(4, degree)
            opti.set_initial(Xc, guess[:, [k]] + np.outer(guess[:, k + 1] - guess[:, k], tau[1:]))
            Z = ca.horzcat(X[:, k], Xc)
            opti.subject_to(h * f(Xc, U[k]) == Z @ C)
            opti.subject_to(X[:, k + 1] == Z @ D)
    else:
        dt = h / steps
        for k in range(N):
            x = X[:, k]
            for _ in range(steps):
                k1 = f(x, U[k])
                k2 = f(x + dt / 2 * k1, U[k])
                k3 = f(x + dt / 2 * k2, U[k])
                k4 = f(x + dt * k3, U[k])
                x = x + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
            opti.subject_to(X[:, k + 1] == x)
    opti.minimize(h * ca.sumsqr(U))
    opti.subject_to(opti.bounded(-F_MAX, U, F_MAX))
    opti.subject_to(opti.bounded(-X_MAX, X[0, :], X_MAX))
    opti.subject_to(X[:, 0] == x0)
    opti.subject_to(X[:, N] == x1)
    return opti, X, U


@pytest.fixture(scope="module")
def compiled():
    return acausal.compile(CartPole())


def solve_both(compiled, method, **kw):
    sol = swing_up(compiled, N=N, method=method, **kw).solve(IPOPT)
    opti, X, U = hand_written(N=N, method=method, **kw)
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
    assert sol["tip.r[1]"][-1] == pytest.approx(DISTANCE, abs=1e-9)
    assert sol["tip.r[2]"][-1] == pytest.approx(LENGTH, abs=1e-9)
    assert abs(sol["tip.v[1]"][-1]) < 1e-9 and abs(sol["tip.v[2]"][-1]) < 1e-9
    assert np.max(np.abs(sol.control("F"))) <= F_MAX + 1e-6


def test_cost_is_the_integral_of_the_squared_force(compiled):
    """The integral ∫F² dt of piecewise-constant F is h·ΣF_k² (closed form)."""
    ocp = swing_up(compiled, N=N)
    sol = ocp.solve(IPOPT)
    h = T_FINAL / N
    assert sol.cost == pytest.approx(h * np.sum(sol.control("F") ** 2), rel=1e-12)
    assert sol.value(ocp["F"]) == pytest.approx(sol.control("F"), abs=0)


def test_infeasible_problem_reports_ipopt_status(compiled):
    ocp = swing_up(compiled, N=10)
    ocp.bounds("F", -0.5, 0.5)                 # far too weak to swing the pole up in 2 s
    with pytest.raises(SolveError) as err:
        ocp.solve({"max_iter": 200})
    assert err.value.status not in ("Solve_Succeeded", "Solved_To_Acceptable_Level")
    assert err.value.status in str(err.value)
    assert np.max(np.abs(err.value.solution.control("F"))) <= 0.5 + 1e-6


def test_bounds_on_a_recorded_variable_hold_at_the_nodes(compiled, tmp_path):
    """A wall at x = 1.3 m for the pole tip (it reaches 1.52 m unconstrained): the tip's
    position, computed by hand from the cart position and θ (x + l sin θ), respects it at every
    node, the bound is active, and the constrained swing-up costs more effort."""
    N, wall = 25, 1.3
    ocp = swing_up(compiled, N=N)
    ocp.bounds("tip.r[1]", None, wall)
    sol = ocp.solve({"tol": 1e-9})
    tip_x = sol["rail.s"] + LENGTH * np.sin(sol["hinge.phi"])
    np.testing.assert_allclose(sol["tip.r[1]"], tip_x, atol=1e-12)
    assert np.max(tip_x) <= wall + 1e-7
    assert np.max(tip_x) == pytest.approx(wall, abs=1e-6)
    free = swing_up(compiled, N=N).solve({"tol": 1e-9})
    assert np.max(free["tip.r[1]"]) > wall + 0.1
    assert sol.cost > free.cost
    assert sol.value(ocp["tip.r[2]"][-1]) == pytest.approx(LENGTH, abs=1e-9)
    fig = sol.plot(path=str(tmp_path))
    assert (tmp_path / "ocp_cartpole.png").exists() and len(fig.axes) == 5
