"""Writing your own components: a few lines each.

Three components, written as a user writes them, are in ``acausal.models.custom_components``
(read its source: each declares parameters and ports, and has the two optional methods every
component has, ``structure(s)`` for kinematic relations, internal points and states, and
``physics(e)`` for energies, flows on ports, state derivatives and recorded variables):

- ``CubicSpring``: a hardening spring f = c·δ + c3·δ³ (δ = s_rel − s_rel0), reusing the
  translational ``PartialCompliant`` base (which supplies flanges, s_rel, v_rel and f);
- ``Flywheel``: a rotational inertia J [kg.m2] (the library has
  ``acausal.components.rotational.Inertia``; this shows how such a body is written);
- ``SimpleDCMotor``: a permanent-magnet DC motor with its armature current i as a state,
  L·di/dt = v − R·i − k·w, driving its flange with the torque k·i.

Run ``python examples/custom_components.py``: it simulates a mass on the cubic spring (the
period shrinks with the amplitude) and the motor spinning up a flywheel, prints a summary and
saves ``custom_components.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.models.custom_components import duffing_model, motor_model


def _period(t, x):
    up = t[1:][(x[:-1] < 0) & (x[1:] >= 0)]
    return float(np.mean(np.diff(up))) if len(up) > 1 else float("nan")


def main():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    duffing = acausal.compile(duffing_model())
    t = np.linspace(0, 10.0, 2001)
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 7))
    print("mass on a hardening spring (m = 1 kg, c = 4 N/m, c3 = 40 N/m3):")
    print(f"  linear period 2*pi/sqrt(c/m) = {2 * np.pi / 2.0:.4f} s")
    for amp in (0.05, 0.2, 0.5):
        res = duffing.simulate(10.0, t=t, x0={"mass.s": amp})
        print(f"  amplitude {amp:4.2f} m: period {_period(t, res['mass.s']):.4f} s")
        res.plot("mass.s", ax=ax1)
        ax1.lines[-1].set_label(f"mass.s, amplitude {amp} m")
    ax1.legend()

    drive = acausal.compile(motor_model())
    res = drive.simulate(1.0, t=np.linspace(0, 1.0, 1001))
    print("DC motor (R = 0.5 Ohm, L = 0.02 H, k = 0.08 N.m/A) spinning up J = 2e-3 kg.m2 at 12 V:")
    print(f"  peak current {res['motor.i'].max():.2f} A, speed after 1 s "
          f"{res['rotor.w'][-1]:.2f} rad/s (no-load speed V/k = {12 / 0.08:.1f} rad/s)")
    res.plot("rotor.w", "motor.i", ax=ax2)

    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "custom_components.png")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
