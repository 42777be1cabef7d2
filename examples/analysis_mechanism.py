"""Kinematics, inverse and mixed dynamics of a four-bar linkage (acausal.analysis).

The crank-rocker of four_bar.py with its crank joint rev1 driven through its flange
(acausal.models.linkages.DrivenFourBar):

1. kinematic analysis and inverse dynamics: a Position source (exact=True) turns the crank
   as phi_ref(t) = 1 + 2t + 0.3 sin(2π·0.5·t) [rad]; positions by Newton–Raphson, then
   velocities and accelerations, the drive torque and every joint reaction;
2. mixed dynamics: a Torque source fed by the model Input T drives the crank; the linkage is
   simulated under T = T0 sin(ωt), then the simulated rocker angle rev3.phi is prescribed
   and the torque recovered from it.

Prints a summary and saves ``analysis_mechanism.png`` (in $ACAUSAL_OUT, default the
current directory).
"""
from __future__ import annotations

import os
import warnings

import numpy as np

import acausal
from acausal.analysis import inverse_dynamics, mixed_dynamics
from acausal.models.linkages import DrivenFourBar

T0, OMEGA = 2.0, 3.0                          # N.m, rad/s: the torque of the mixed problem
GUESS = {"rev2.phi": -0.5, "rev3.phi": 1.6}   # rad: the assembly branch (rocker up)


def phi_ref(t):
    """The crank angle the Position source prescribes [rad]."""
    return 1.0 + 2.0 * t + 0.3 * np.sin(np.pi * t)


def main():
    t = np.linspace(0.0, 3.0, 301)
    driven = acausal.compile(DrivenFourBar("position"))
    inv = inverse_dynamics(driven, t, guess=GUESS)
    print(f"kinematic analysis of {driven.name}: coordinates {driven.coordinates}, "
          f"{len(t)} times")
    print(f"crank {inv['rev1.phi'][0]:.3f} -> {inv['rev1.phi'][-1]:.3f} rad (phi_ref error "
          f"{np.max(np.abs(inv['rev1.phi'] - phi_ref(t))):.1e}); rocker "
          f"{inv['rev3.phi'].min():.3f}..{inv['rev3.phi'].max():.3f} rad")
    print(f"drive torque on the crank rev1.t: {inv['rev1.t'].min():.3f}..{inv['rev1.t'].max():.3f}"
          f" N.m; prescribed flanges: {list(inv.drivers)}")
    fx, fy = inv["rev4.frame_b.fx"], inv["rev4.frame_b.fy"]
    print(f"coupler-rocker joint force |F|: max {np.hypot(fx, fy).max():.3f} N")

    forward = acausal.compile(DrivenFourBar("torque"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sim = forward.simulate(3.0, t=t, inputs={"T": lambda s: T0 * np.sin(OMEGA * s)},
                               x0={"rev1.phi": 1.0, "rev1.w": 2.0}, guess=GUESS,
                               rtol=1e-11, atol=1e-12)
    motion = {"rev3.phi": (t, sim["rev3.phi"], sim["rev3.w"], sim["rev3.z"])}
    mixed = mixed_dynamics(forward, t, motion, ["T"], guess={"rev1.phi": 1.0, **GUESS})
    err = np.max(np.abs(mixed.drivers["T"] - T0 * np.sin(OMEGA * t))) / T0
    print(f"mixed dynamics: rocker motion prescribed, crank torque recovered to {err:.1e} "
          f"(relative to T0 = {T0} N.m)")

    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "analysis_mechanism.png")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    ax[0].plot(t, inv["rev1.phi"], label="crank rev1.phi [rad]")
    ax[0].plot(t, inv["rev3.phi"], label="rocker rev3.phi [rad]")
    ax[0].plot(t, inv["rev3.z"], label="rocker rev3.z [rad/s²]")
    ax[1].plot(t, inv["rev1.t"], label="drive torque rev1.t [N.m]")
    ax[1].plot(t, fx, label="rev4.frame_b.fx [N]")
    ax[1].plot(t, fy, label="rev4.frame_b.fy [N]")
    ax[2].plot(t, T0 * np.sin(OMEGA * t), label="applied T [N.m]")
    ax[2].plot(t, mixed.drivers["T"], "--", label="recovered T [N.m]")
    ax[2].set_xlabel("time [s]")
    for a in ax:
        a.grid(True)
        a.legend(fontsize=8)
    fig.suptitle("Four-bar: kinematics, inverse and mixed dynamics")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
