"""Hard-disk read/write head, a worked case of machine-dynamics courses, built from planar and 1-D components.

The actuator arm (inertia I about its fixed pivot) is turned by the voice-coil torque T(t)
against a rotational damper c_T; the head (mass m) sits at radius L on a flexible tip that
deflects by δ sideways (perpendicular to the arm, positive towards increasing θ) against a
spring k. The disk is horizontal: gravity is normal to the plane of motion (World g = 0).
With q = [θ, δ]:

    M(q) = [[I + m(L² + δ²), mL], [mL, m]],  K = diag(0, k),  C = diag(c_T, 0),
    coriolis = [−2mδθ̇δ̇, mδθ̇²],  B = [1, 0]ᵀ (input T).

The model, built from PlanarMechanics and MSL components, is
``acausal.models.disk_drive.DiskDriveHead``; its coordinates are θ = ``pivot.phi``,
δ = ``flexure.s``.

The script compares the compiled pieces with the closed forms at a sample state, simulates a
short seek (one sine period of torque, 2 ms) and the residual vibration of the head, prints
the flexure mode's frequency from the linearized closed form
ω² = k (I + mL²)/(m I) next to the one seen in the simulation, and saves
``disk_drive_head.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os
import time

import casadi as ca
import numpy as np

import acausal
from acausal.models.disk_drive import (ARM_INERTIA, FLEXURE_STIFFNESS, HEAD_MASS,
                                      PIVOT_DAMPING, RADIUS, DiskDriveHead)

T0, T_SEEK = 0.02, 2.0e-3   # N.m, s: T = T0 sin(2π t/T_SEEK) for t < T_SEEK


def closed_form(q, qd, I, m, L, k, c_T):
    """The textbook's pieces for q = [θ, δ]: M, C, K, gravity, coriolis, B."""
    d, thd, dd = q[1], qd[0], qd[1]
    return {"M": np.array([[I + m * (L ** 2 + d ** 2), m * L], [m * L, m]]),
            "C": np.diag([c_T, 0.0]), "K": np.diag([0.0, k]), "gravity": np.zeros(2),
            "coriolis": np.array([-2 * m * d * thd * dd, m * d * thd ** 2]),
            "B": np.array([1.0, 0.0])}


def seek_torque(t):
    """T(t) [N.m]: one sine period (accelerate, then brake), zero afterwards; t may be a
    CasADi symbol."""
    return ca.if_else(t < T_SEEK, T0 * ca.sin(2 * ca.pi * t / T_SEEK), 0.0)


def main():
    t0 = time.perf_counter()
    model = acausal.compile(DiskDriveHead())
    t1 = time.perf_counter()
    lag = model.lagrange
    print(model)
    print(f"coordinates {lag.q_names} (θ = pivot.phi, δ = flexure.s), inputs {lag.u_names}; "
          f"compiled in {t1 - t0:.3f} s")

    names = ["M", "C", "K", "gravity", "coriolis", "B"]
    q, qd = [0.3, 2e-5], [40.0, -0.05]
    got = lag.function(*names)(q=q, qd=qd, u=[0.0], t=0.0, p=model.param_vector())
    ref = closed_form(q, qd, ARM_INERTIA, HEAD_MASS, RADIUS, FLEXURE_STIFFNESS, PIVOT_DAMPING)
    for n in names:
        scale = np.max(np.abs(ref[n])) or 1.0
        err = np.max(np.abs(np.array(got[n]).ravel() - np.ravel(ref[n]))) / scale
        print(f"  {n:9s} max |compiled - closed form| / max |closed form| = {err:.1e}")

    t_final = 6.0e-3
    grid = np.linspace(0.0, t_final, 3001)
    res = model.simulate(t_final, t=grid, inputs={"T": seek_torque})
    t2 = time.perf_counter()
    th, delta = res["pivot.phi"], res["flexure.s"]
    after = grid > T_SEEK
    I, m, L, k = ARM_INERTIA, HEAD_MASS, RADIUS, FLEXURE_STIFFNESS
    f_hand = np.sqrt(k * (I + m * L ** 2) / (m * I)) / (2 * np.pi)
    d_res = delta[after] - np.mean(delta[after])
    crossings = np.flatnonzero(np.diff(np.sign(d_res)) != 0)
    f_sim = 0.5 / np.mean(np.diff(grid[after][crossings]))
    print(f"seek (simulated {t_final * 1e3:.0f} ms in {t2 - t1:.3f} s): arm turned "
          f"{np.degrees(th[-1]):.3f} deg = {L * th[-1] * 1e3:.3f} mm at the head; peak tip "
          f"deflection {np.max(np.abs(delta)) * 1e6:.2f} um, residual vibration after the seek "
          f"{np.max(np.abs(d_res)) * 1e6:.2f} um")
    print(f"flexure mode: hand formula sqrt(k(I + mL²)/(mI)) = {f_hand:.1f} Hz, simulated "
          f"residual vibration {f_sim:.1f} Hz")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(3, 1, sharex=True, figsize=(7, 7))
    ms = grid * 1e3
    axes[0].plot(ms, [float(ca.evalf(seek_torque(tk))) * 1e3 for tk in grid])
    axes[0].set_ylabel("T [mN.m]")
    axes[1].plot(ms, np.degrees(th))
    axes[1].set_ylabel("arm angle θ [deg]")
    axes[2].plot(ms, delta * 1e6)
    axes[2].set_ylabel("tip deflection δ [um]")
    axes[2].set_xlabel("time [ms]")
    for ax in axes:
        ax.grid(True)
    axes[0].set_title("Hard-disk head: seek and residual vibration")
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "disk_drive_head.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
