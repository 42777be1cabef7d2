"""Parameter estimation: a spring stiffness and a damping from noisy position measurements.

A mass m on a spring c and a damper d to the ground (acausal.models.oscillators.Oscillator:
translational Mass, Spring, Damper, Fixed), released from rest at s0. Its position is
measured every Δt for 10 s with Gaussian noise σ (fixed seed). acausal.ocp estimates c, d
and the unknown release position s0 by least squares, Σ (s(t_i) − y_i)², with the
measurement times as the collocation mesh and c, d as free parameters (decision variables).
An independent fit, scipy's least_squares on scipy's solve_ivp of the hand-written ODE
m s̈ = −c s − d ṡ, gives the same estimates and their standard deviations
σ·sqrt(diag((JᵀJ)⁻¹)). The script saves ``ocp_parameter_estimation.png`` (in $ACAUSAL_OUT,
default the current directory).
"""
from __future__ import annotations

import os
import time

import casadi as ca
import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import least_squares

import acausal
from acausal.models.oscillators import Oscillator
from acausal.ocp import OCP

MASS, STIFFNESS, DAMPING, S0 = 1.0, 4.0, 0.4, 0.5     # kg, N/m, N.s/m, m (the truth)
SIGMA, DT, DURATION, SEED = 0.01, 0.1, 10.0, 0         # m, s, s
GUESS = {"spring.c": 3.0, "damper.d": 0.2}             # N/m, N.s/m


def hand_positions(t, c, d, s0, m=MASS):
    """s(t) [m] of m s̈ = −c s − d ṡ from rest at s0 (scipy, rtol 1e-11)."""
    r = solve_ivp(lambda _, y: [y[1], -(c * y[0] + d * y[1]) / m], (t[0], t[-1]), [s0, 0.0],
                  t_eval=t, rtol=1e-11, atol=1e-13, method="DOP853")
    return r.y[0]


def measurements():
    """(times [s], noisy positions [m]) of the true oscillator."""
    t = np.linspace(0.0, DURATION, int(round(DURATION / DT)) + 1)
    noise = SIGMA * np.random.default_rng(SEED).standard_normal(t.size)
    return t, hand_positions(t, STIFFNESS, DAMPING, S0) + noise


def estimate(compiled, t, y, method="collocation", **kw):
    """c, d and s0 by acausal.ocp: the Solution (free parameters in sol.parameters)."""
    ocp = OCP(compiled, N=t.size - 1, T=t[-1] - t[0], t0=t[0], method=method,
              free=["spring.c", "damper.d"], **kw)
    ocp.minimize(ca.sumsqr(ocp["mass.s"] - y))
    ocp.initial({"mass.v": 0.0})
    ocp.bounds("spring.c", 0.0, None)
    ocp.bounds("damper.d", 0.0, None)
    ocp.guess({**GUESS, "mass.s": y})
    return ocp.solve({"tol": 1e-12})


def reference_fit(t, y):
    """(estimates [c, d, s0], standard deviations) by scipy on the hand ODE."""
    fit = least_squares(lambda th: hand_positions(t, *th) - y,
                        [GUESS["spring.c"], GUESS["damper.d"], y[0]], xtol=1e-14, ftol=1e-14,
                        gtol=1e-14)
    cov = SIGMA ** 2 * np.linalg.inv(fit.jac.T @ fit.jac)
    return fit.x, np.sqrt(np.diag(cov))


def main():
    t, y = measurements()
    compiled = acausal.compile(Oscillator())
    t0 = time.perf_counter()
    sol = estimate(compiled, t, y)
    t1 = time.perf_counter()
    ref, std = reference_fit(t, y)
    t2 = time.perf_counter()
    got = [sol.parameters["spring.c"], sol.parameters["damper.d"], sol["mass.s"][0]]
    print(f"acausal.ocp ({sol.iterations} iterations, {t1 - t0:.2f} s) vs scipy least_squares "
          f"on solve_ivp ({t2 - t1:.2f} s):")
    for name, truth, a, b, s in zip(["c [N/m]", "d [N.s/m]", "s0 [m]"],
                                    [STIFFNESS, DAMPING, S0], got, ref, std):
        print(f"  {name:9s} true {truth:.4f}  ocp {a:.6f}  scipy {b:.6f} ± {s:.4f}  "
              f"|ocp - scipy| = {abs(a - b):.1e}")
    rms = np.sqrt(np.mean((sol["mass.s"] - y) ** 2))
    print(f"residual rms {rms:.4f} m (noise σ = {SIGMA} m)")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 3.5))
    ax.plot(t, y, ".", ms=3, label="measurements")
    ax.plot(sol.t, sol["mass.s"], label=f"fit: c = {got[0]:.3f} N/m, d = {got[1]:.3f} N.s/m")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("mass.s [m]")
    ax.grid(True)
    ax.legend()
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "ocp_parameter_estimation.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
