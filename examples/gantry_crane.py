"""Gantry crane, a worked case of machine-dynamics courses, built from planar and 1-D components.

A cart (mass M) runs on a horizontal rail with a viscous damper c to the ground and is pushed
by a force F(t); a load (point mass m) hangs on a rope of length L from a hinge on the cart,
with a rotational damper c_T in the hinge; gravity g. With q = [x, θ] (x the cart position
along the rail, θ the rope angle from the downward vertical, counter-clockwise):

    M(q) = [[M+m, mL cosθ], [mL cosθ, mL²]],  C = diag(c, c_T),  K = 0,
    gravity = [0, −mgL sinθ],  coriolis = [mL sinθ θ̇², 0],  B = [1, 0]ᵀ (input F).

The model, built from PlanarMechanics and MSL components, is
``acausal.models.crane.GantryCrane``; its coordinates are x = ``rail.s``, θ = ``hinge.phi``.
The script compares the compiled M, C, K, gravity, Coriolis and B with the closed forms at a
sample state and simulates a "move and stop" manoeuvre, one full sine period of force
F0 sin(2πt/T) for t < T, twice: with T = 2 s, and with T = two periods of the linearized
sway (the force's spectrum then vanishes at the sway frequency, and the load arrives almost
without residual sway). It saves
``gantry_crane.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os
import time

import casadi as ca
import numpy as np

import acausal
from acausal.models.crane import (CART_MASS, HINGE_DAMPING, LOAD_MASS, RAIL_DAMPING, ROPE,
                                 GantryCrane)

F0 = 8.0                                         # N, force amplitude


def closed_form(q, qd, M, m, L, c, c_T, g):
    """The textbook's pieces for q = [x, θ]: M, C, K, gravity, coriolis, B."""
    th, thd = q[1], qd[1]
    return {"M": np.array([[M + m, m * L * np.cos(th)], [m * L * np.cos(th), m * L ** 2]]),
            "C": np.diag([c, c_T]), "K": np.zeros((2, 2)),
            "gravity": np.array([0.0, -m * g * L * np.sin(th)]),
            "coriolis": np.array([m * L * np.sin(th) * thd ** 2, 0.0]),
            "B": np.array([1.0, 0.0])}


def move_force(T):
    """F(t) [N]: one full sine period of length T [s] (push, then brake), zero afterwards;
    t may be a CasADi symbol."""
    return lambda t: ca.if_else(t < T, F0 * ca.sin(2 * ca.pi * t / T), 0.0)


def main():
    t0 = time.perf_counter()
    model = acausal.compile(GantryCrane())
    t1 = time.perf_counter()
    lag = model.lagrange
    print(model)
    print(f"coordinates {lag.q_names} (x = rail.s, θ = hinge.phi), inputs {lag.u_names}; "
          f"compiled in {t1 - t0:.3f} s")

    names = ["M", "C", "K", "gravity", "coriolis", "B"]
    q, qd = [0.3, 0.4], [0.5, -0.7]
    got = lag.function(*names)(q=q, qd=qd, u=[0.0], t=0.0, p=model.param_vector())
    ref = closed_form(q, qd, CART_MASS, LOAD_MASS, ROPE, RAIL_DAMPING, HINGE_DAMPING, 9.81)
    print(f"at q = {q}, q' = {qd}: M = {np.array(got['M']).round(6).tolist()}")
    for n in names:
        err = np.max(np.abs(np.array(got[n]).ravel() - np.ravel(ref[n])))
        print(f"  {n:9s} max |compiled - closed form| = {err:.1e}")

    omega = np.sqrt(9.81 / ROPE * (CART_MASS + LOAD_MASS) / CART_MASS)
    print(f"small-sway frequency with the cart free: sqrt(g/L·(M+m)/M) = {omega:.3f} rad/s "
          f"(period {2 * np.pi / omega:.2f} s)")
    grid = np.linspace(0.0, 10.0, 1001)
    runs = {}
    for T in (2.0, 2 * (2 * np.pi / omega)):
        t2 = time.perf_counter()
        res = model.simulate(10.0, t=grid, inputs={"F": move_force(T)})
        t3 = time.perf_counter()
        x, th = res["rail.s"], res["hinge.phi"]
        late = grid > T + 2.0
        print(f"T = {T:.2f} s (simulated 10 s in {t3 - t2:.3f} s): cart at {x[-1]:.3f} m, peak "
              f"sway {np.degrees(np.max(np.abs(th))):5.2f} deg, residual sway (t > T + 2 s) "
              f"{np.degrees(np.max(np.abs(th[late]))):5.2f} deg")
        runs[T] = res

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(3, 1, sharex=True, figsize=(7, 7))
    for k, (T, res) in enumerate(runs.items()):
        F, col = move_force(T), f"C{k}"
        axes[0].plot(grid, [float(ca.evalf(F(tk))) for tk in grid], col, label=f"T = {T:.2f} s")
        axes[1].plot(grid, res["rail.s"], col, label=f"cart, T = {T:.2f} s")
        axes[1].plot(grid, res["load.r[1]"], col, ls="--", lw=0.8, label=f"load, T = {T:.2f} s")
        axes[2].plot(grid, np.degrees(res["hinge.phi"]), col, label=f"T = {T:.2f} s")
    axes[0].set_ylabel("F [N]")
    axes[1].set_ylabel("x position [m]")
    axes[2].set_ylabel("sway θ [deg]")
    axes[2].set_xlabel("time [s]")
    for ax in axes:
        ax.grid(True)
        ax.legend(fontsize=8)
    axes[0].set_title("Gantry crane: move and stop")
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "gantry_crane.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
