"""PlanarMechanics.Examples.Pendulum, line by line, with a cut-force sensor at the pivot.

A body (m = 1 kg, I = 0.1 kg.m²) on a massless bar of length 1 m (FixedTranslation
r = {1, 0}) hangs from a Revolute at a Fixed frame; it starts horizontal (phi = 0) at rest
and swings for 3 s under gravity (PlanarWorld: {0, -9.81}). A CutForce sensor between the
fixed frame and the revolute measures the force the pivot carries.

Checks printed (hand formulas, not the library):
- the period against the exact large-amplitude period of a physical pendulum,
  T = 4/ω0 · K(sin²(θ0/2)), ω0² = m g L / (I + m L²), θ0 = 90° from the bottom;
- the pivot force at the bottom, m·(g + L·w²) with w² = 2 m g L / (I + m L²);
- the mechanical energy, constant to solver tolerance.

Run ``python examples/planar_pendulum.py``: prints a summary and saves
``planar_pendulum.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import math
import os
import time

import numpy as np
from scipy.special import ellipk

import acausal
from acausal.components.planar import Body, CutForce, Fixed, FixedTranslation, Revolute, World


class Pendulum(acausal.Model):
    """PlanarMechanics.Examples.Pendulum (plus a CutForce sensor at the pivot)."""

    def __init__(self, name=None):
        super().__init__(name)
        self.body = Body(m=1, I=0.1)
        self.revolute = Revolute(useFlange=False)
        self.fixedTranslation = FixedTranslation(r=(1, 0))
        self.fixed = Fixed(phi=0)
        self.planarWorld = World()                       # inner PlanarWorld planarWorld
        self.pivotForce = CutForce(resolveInFrame="world")
        c = self.connect
        c(self.fixed.frame, self.pivotForce.frame_a)
        c(self.pivotForce.frame_b, self.revolute.frame_a)
        c(self.revolute.frame_b, self.fixedTranslation.frame_a)
        c(self.fixedTranslation.frame_b, self.body.frame_a)


def main():
    t0 = time.perf_counter()
    model = acausal.compile(Pendulum("Pendulum"))
    t1 = time.perf_counter()
    grid = np.linspace(0.0, 3.0, 3001)                           # experiment(StopTime=3)
    res = model.simulate(3.0, t=grid, x0={"revolute.phi": 0.0, "revolute.w": 0.0},
                         rtol=1e-10, atol=1e-12)
    t2 = time.perf_counter()

    m, I, L, g = 1.0, 0.1, 1.0, 9.81
    J = I + m * L ** 2
    phi, w = res["revolute.phi"], res["revolute.w"]
    # period: back at the start (phi = 0, w = 0) after the swing to the other side and back;
    # w changes sign at every turning point (interpolated between grid points)
    k = np.flatnonzero(np.sign(w[1:-1]) != np.sign(w[2:])) + 1
    crossings = grid[k] - w[k] * (grid[k + 1] - grid[k]) / (w[k + 1] - w[k])
    w0 = math.sqrt(m * g * L / J)
    T_exact = 4 / w0 * ellipk(math.sin(math.pi / 4) ** 2)
    T_sim = crossings[1] if len(crossings) > 1 else float("nan")
    # pivot force at the bottom (phi = -pi/2): m (g + L w²) upwards
    F_bottom = m * (g + L * 2 * m * g * L / J)
    Fy = res["pivotForce.force[2]"]
    # energy
    E = (0.5 * m * (res["body.v[1]"] ** 2 + res["body.v[2]"] ** 2) + 0.5 * I * w ** 2
         + m * g * res["body.r[2]"])

    print(f"PlanarMechanics.Examples.Pendulum: compiled in {t1 - t0:.3f} s, simulated 3 s in "
          f"{t2 - t1:.3f} s; coordinates {model.lagrange.q_names}")
    print(f"period: simulated {T_sim:.6f} s, exact 4/w0*K = {T_exact:.6f} s "
          f"(small-angle 2*pi/w0 = {2 * math.pi / w0:.4f} s)")
    print(f"pivot force at the bottom: simulated {Fy.max():.5f} N, hand m(g + L w^2) = "
          f"{F_bottom:.5f} N")
    print(f"energy drift: {np.ptp(E):.2e} J")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 3, figsize=(13, 3.8))
    ax[0].plot(grid, phi, label="revolute.phi [rad]")
    ax[0].plot(grid, w, label="revolute.w [rad/s]")
    ax[0].set_xlabel("t [s]")
    ax[0].legend()
    ax[0].set_title("joint angle and rate")
    ax[1].plot(grid, res["pivotForce.force[1]"], label="pivot force x [N]")
    ax[1].plot(grid, Fy, label="pivot force y [N]")
    ax[1].axhline(F_bottom, color="k", ls=":", lw=0.8, label="hand: force at the bottom")
    ax[1].set_xlabel("t [s]")
    ax[1].legend(fontsize=8, loc="lower right")
    ax[1].set_title("CutForce at the pivot (world frame)")
    ax[2].plot(res["body.r[1]"], res["body.r[2]"])
    ax[2].plot([0], [0], "ko")
    ax[2].set_aspect("equal")
    ax[2].set_title("path of the body")
    fig.tight_layout()
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "planar_pendulum.png")
    fig.savefig(out, dpi=110)
    print(f"plot saved to {out}")
    gif = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "planar_pendulum.gif")
    res.animate().save(gif, frames=40)     # or .html (interactive), .mp4 (with ffmpeg)
    print(f"animation saved to {gif}")


if __name__ == "__main__":
    main()
