"""Cart-pole swing-up with minimum effort, through acausal.ocp and by hand in casadi.Opti.

The cart (mass m1) runs on a horizontal rail, pushed by a force F [N] (the model's Input);
a pole of length l carries a point mass m2 at its tip and hangs from a hinge on the cart.
θ is the pole angle from the downward vertical (counter-clockwise). The problem (M. Kelly,
"An introduction to trajectory optimization", SIAM Review 2017, section 6):

    minimize ∫₀ᵀ F² dt,  T = 2 s,  |F| ≤ 20 N,  |x| ≤ 2 m,
    from rest hanging down at x = 0 to rest upright (θ = π) at x = d = 1 m.

The model, built from PlanarMechanics and MSL components, is
``acausal.models.cartpole.CartPole``.

The same problem is written by hand (``hand_written``) in casadi.Opti from the closed-form
equations of motion (Lagrange, eliminated for the accelerations):

    ẍ = (m2 l sinθ θ̇² + F + m2 g cosθ sinθ) / (m1 + m2 sin²θ)
    θ̈ = −(m2 l cosθ sinθ θ̇² + F cosθ + (m1 + m2) g sinθ) / (l (m1 + m2 sin²θ))

with the same transcription (collocation of the same degree and points on the same mesh, or
multiple shooting with RK4 steps), the same guess and the same IPOPT options: both give the
same optimum. The script saves ``ocp_cartpole.png`` (in $ACAUSAL_OUT, default the current
directory).
"""
from __future__ import annotations

import os
import time

import casadi as ca
import numpy as np

import acausal
from acausal.models.cartpole import LENGTH, M_CART, M_POLE, CartPole
from acausal.ocp import OCP

G = 9.81                                               # m/s²
T_FINAL, DISTANCE, F_MAX, X_MAX = 2.0, 1.0, 20.0, 2.0  # s, m, N, m
START = {"rail.s": 0.0, "hinge.phi": 0.0, "rail.v": 0.0, "hinge.w": 0.0}
TARGET = {"rail.s": DISTANCE, "hinge.phi": np.pi, "rail.v": 0.0, "hinge.w": 0.0}


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
    """The swing-up in casadi.Opti from the closed form, written as a competent user would:
    the dynamics as an SX Function mapped over the mesh (collocation of ``degree`` at
    ``scheme`` points, or multiple shooting with ``steps`` RK4 steps per interval, one SX
    Function of the interval), the bounds and boundary values on decision variables, which
    IPOPT receives as variable bounds (``detect_simple_bounds``), and the NLP expanded to
    SX (``OPTIONS``). Returns the Opti, the state matrix X and control row U (not solved)."""
    opti = ca.Opti()
    h = T_FINAL / N
    X, U = opti.variable(4, N + 1), opti.variable(1, N)
    x_s, u_s = ca.SX.sym("x", 4), ca.SX.sym("F")
    f = ca.Function("f", [x_s, u_s], [cartpole_ode(x_s, u_s)])
    x0, x1 = np.array(list(START.values())), np.array(list(TARGET.values()))
    guess = np.linspace(x0, x1, N + 1).T
    opti.set_initial(X, guess)
    if method == "collocation":
        tau, C, D = collocation_coefficients(degree, scheme)
        Xc = opti.variable(4, N * degree)
        opti.set_initial(Xc, np.repeat(guess[:, :-1], degree, axis=1)
                         + np.repeat(np.diff(guess, axis=1), degree, axis=1)
                         * np.tile(tau[1:], N))
        E = np.eye(N)
        Uc = ca.repmat(U, degree, 1).reshape((1, N * degree))        # U_k at its points
        slope = X[:, :N] @ np.kron(E, C[:1]) + Xc @ np.kron(E, C[1:])
        opti.subject_to(h * f.map(N * degree)(Xc, Uc) == slope)
        opti.subject_to(X[:, 1:] == X[:, :N] * D[0] + Xc @ np.kron(E, D[1:, None]))
    else:
        dt, x = h / steps, x_s
        for _ in range(steps):
            k1 = cartpole_ode(x, u_s)
            k2 = cartpole_ode(x + dt / 2 * k1, u_s)
            k3 = cartpole_ode(x + dt / 2 * k2, u_s)
            k4 = cartpole_ode(x + dt * k3, u_s)
            x = x + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        step = ca.Function("interval", [x_s, u_s], [x])
        opti.subject_to(X[:, 1:] == step.map(N)(X[:, :N], U))
    opti.minimize(h * ca.sumsqr(U))
    opti.subject_to(opti.bounded(-F_MAX, U, F_MAX))
    opti.subject_to(opti.bounded(-X_MAX, X[0, :], X_MAX))
    opti.subject_to(X[:, 0] == x0)
    opti.subject_to(X[:, N] == x1)
    return opti, X, U


#: nlpsol options of the hand-written reference: expanded to SX, bounds as variable bounds
OPTIONS = {"expand": True, "detect_simple_bounds": True, "print_time": False}


def main():
    compiled = acausal.compile(CartPole())
    print(compiled)
    ipopt = {"tol": 1e-10}
    t0 = time.perf_counter()
    sol = swing_up(compiled).solve(ipopt)
    t1 = time.perf_counter()
    opti, X, U = hand_written()
    opti.solver("ipopt", {**OPTIONS, "ipopt": {"print_level": 0, "sb": "yes", **ipopt}})
    ref = opti.solve()
    t2 = time.perf_counter()
    print(f"acausal.ocp:  {sol}, {t1 - t0:.3f} s")
    print(f"hand-written: cost {ref.value(opti.f):.10g}, "
          f"{ref.stats()['iter_count']} iterations, {t2 - t1:.3f} s")
    print(f"relative cost difference {abs(sol.cost - ref.value(opti.f)) / ref.value(opti.f):.1e}; "
          f"max |θ - θ_hand| = {np.max(np.abs(sol['hinge.phi'] - ref.value(X[1, :]))):.1e} rad")
    print(f"peak force {np.max(np.abs(sol.control('F'))):.2f} N, tip reaches "
          f"y = {sol['tip.r[2]'][-1]:.4f} m (l = {LENGTH} m)")
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "ocp_cartpole.png")
    sol.plot("rail.s", "hinge.phi", "tip.r[2]", "F", path=out)
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
