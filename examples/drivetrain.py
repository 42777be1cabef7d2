"""A drivetrain: DC motor -> gearbox -> elastic shaft -> fan drum, with a load torque step.

    Ramp (0 -> 100 V in 0.5 s) --> DCMotor --> IdealGear (ratio) --> TorqueSensor
        --> SpringDamper (elastic shaft) --> Inertia (drum) <-- QuadraticSpeedDependentTorque (fan)
                                                            <-- TorqueStep (extra load at 2.5 s)
    SpeedSensor on the drum

Written as one would draw it in Modelica.Mechanics.Rotational (same names, parameters and
sign conventions; the model is acausal.models.drivetrains.Drivetrain). The motor has MSL's
DC_PermanentMagnet data (100 V, 100 A nominal). The script

- simulates 4 s and checks the final operating point against the steady state solved by
  hand (motor torque through the gear = fan + extra load; current from the armature
  equation),
- prints the shaft's torsional frequency from the hand formula ω² = c·(1/J_drum +
  1/(ratio²·J_motor)) next to the oscillation seen in the shaft torque after the load step,
- re-runs with another gear ratio (a parameter: no recompiling),

and saves ``drivetrain.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import math
import os
import time

import numpy as np

import acausal
from acausal.models.drivetrains import (C_SHAFT, FAN_TAU, FAN_W, J_DRUM, RATIO, STEP_TAU,
                                       STEP_TIME, VOLTAGE, Drivetrain)


def steady_state(ratio, p, V=VOLTAGE):
    """Drum speed and motor current where ratio·k·i = −(fan + extra load), i = (V − k·w)/R:
    a quadratic in the drum speed, solved by hand."""
    R, k = p["motor.R"], p["motor.k"]
    # FAN_TAU/FAN_W²·wd² − (ratio·k)²/R·wd + ratio·k·V/R + STEP_TAU = 0
    roots = np.roots([FAN_TAU / FAN_W ** 2, -(ratio * k) ** 2 / R, ratio * k * V / R + STEP_TAU])
    wd = float(max(r.real for r in roots if abs(r.imag) < 1e-12 and r.real > 0))
    return wd, (V - k * ratio * wd) / R


def main():
    t0 = time.perf_counter()
    model = acausal.compile(Drivetrain())
    t1 = time.perf_counter()
    grid = np.linspace(0.0, 4.0, 2001)
    res = model.simulate(4.0, t=grid)
    alt_ratio = 8.0
    alt = model.simulate(4.0, t=grid, params={"gear.ratio": alt_ratio})
    t2 = time.perf_counter()
    print(model)
    print(f"states: {model.x_names}")
    print(f"compiled in {t1 - t0:.3f} s, two 4 s simulations in {t2 - t1:.3f} s")

    p = model.param_defaults
    for ratio, r in ((RATIO, res), (alt_ratio, alt)):
        wd, i = steady_state(ratio, p)
        print(f"gear ratio {ratio:4.1f}: drum {r.final('drumSpeed.w'):7.3f} rad/s "
              f"(hand steady state {wd:7.3f}), motor current {r.final('motor.i'):6.1f} A "
              f"(hand {i:6.1f}), peak current {np.max(r['motor.i']):6.1f} A, peak shaft "
              f"torque {np.max(np.abs(r['shaftTorque.tau'])):6.1f} N.m")

    Jm = p["motor.J"]
    f_hand = math.sqrt(C_SHAFT * (1 / J_DRUM + 1 / (RATIO ** 2 * Jm))) / (2 * math.pi)
    after = grid > STEP_TIME
    tau = res["shaftTorque.tau"][after] - res.final("shaftTorque.tau")
    crossings = np.flatnonzero(np.diff(np.sign(tau)) != 0)
    if len(crossings) >= 3:
        period = 2 * np.mean(np.diff(grid[after][crossings][:6]))
        print(f"shaft torsional mode: hand formula {f_hand:.2f} Hz, ringing after the load "
              f"step {1 / period:.2f} Hz (the motor's back-emf and the fan shift it)")
    loss = res["shaft.lossPower"]
    print(f"energy dissipated in the shaft damper: "
          f"{np.sum(0.5 * (loss[1:] + loss[:-1]) * np.diff(grid)):.2f} J")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(3, 1, sharex=True, figsize=(7, 8))
    for label, r in ((f"ratio {RATIO:g}", res), (f"ratio {alt_ratio:g}", alt)):
        axes[0].plot(grid, r["drumSpeed.w"], label=f"drum, {label}")
        axes[0].plot(grid, r["motor.w"] / (RATIO if r is res else alt_ratio), "--", lw=0.8,
                     label=f"motor / ratio, {label}")
        axes[1].plot(grid, r["shaftTorque.tau"], label=label)
        axes[2].plot(grid, r["motor.i"], label=label)
    axes[0].set_ylabel("speed [rad/s]")
    axes[1].set_ylabel("shaft torque [N.m]")
    axes[2].set_ylabel("motor current [A]")
    axes[2].set_xlabel("time [s]")
    for ax in axes:
        ax.grid(True)
        ax.legend(fontsize=8)
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "drivetrain.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
