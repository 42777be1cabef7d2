"""Closed loops of 3-D parts: MSL's Fourbar1 and a four-bar whose revolute axes are all
parallel, built from MultiBody components as in Modelica (``acausal.models.multibody_loops``).

- Fourbar1 (``Modelica.Mechanics.MultiBody.Examples.Loops.Fourbar1``): 6 revolutes and a
  prismatic joint in one spatial loop; the compiler cuts it at a joint (6 constraint
  rows), 7 coordinates, 1 degree of freedom. Started as MSL does (j1.w = 300 deg/s).
- ParallelFourbar: Gruebler's count is 3·6 − 4·5 = −2, but it moves with 1 degree of
  freedom: ``compiled.mobility`` finds the 3 redundant rows (out of the plane) from the
  rank of Φ_q. Its loop stays closed to solver precision (printed, checked by planar
  kinematics of the joint angles).

Saves ``fourbar_3d.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os
import warnings

import numpy as np

import acausal
from acausal.models.multibody_loops import FOURBAR_START, MultiBodyFourbar1, ParallelFourbar


def main():
    warnings.simplefilter("ignore")          # the start speeds moved onto the loops
    fourbar1 = acausal.compile(MultiBodyFourbar1())
    print(f"Fourbar1: coordinates {fourbar1.coordinates}\n  loop rows {fourbar1.loop_rows}")
    res1 = fourbar1.simulate(5.0, t=np.linspace(0, 5, 501), x0=FOURBAR_START,
                             guess={"j2.s": -0.2}, rtol=1e-9, atol=1e-11)
    print(f"  {res1.mobility}")

    parallel = acausal.compile(ParallelFourbar())
    x0 = {"j1.phi": 0.0, "j1.w": 3.0}
    print(f"ParallelFourbar: {parallel.mobility(x0=x0)}")
    res2 = parallel.simulate(10.0, t=np.linspace(0, 10, 1001), x0=x0, rtol=1e-10, atol=1e-12)
    p1, p2, p3 = res2["j1.phi"], res2["j2.phi"], res2["j3.phi"]

    def turn(a, v):
        return np.stack([np.cos(a) * v[0] - np.sin(a) * v[1],
                         np.sin(a) * v[0] + np.cos(a) * v[1]], -1)

    tip = turn(p1, (0, 0.5)) + turn(p1 + p2, (1.2, 0.2)) + turn(p1 + p2 + p3, (0, -0.7))
    print(f"  loop closure over 10 s: {np.max(np.abs(tip - [1.2, 0])):.1e} m")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].plot(res1.t, res1["j1.phi"], label="j1.phi [rad]")
    ax[0].plot(res1.t, res1["j2.s"], label="j2.s [m]")
    ax[0].set_title("Fourbar1")
    ax[0].set_xlabel("t [s]")
    ax[0].legend()
    ax[1].plot(res2.t, np.unwrap(p1), label="crank j1.phi [rad]")
    ax[1].plot(res2.t, res2["j4.phi"], label="rocker j4.phi [rad]")
    ax[1].set_title("ParallelFourbar (1 dof, 3 redundant rows)")
    ax[1].set_xlabel("t [s]")
    ax[1].legend()
    fig.tight_layout()
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "fourbar_3d.png")
    fig.savefig(out, dpi=100)
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
