"""A gear with losses that sticks, and backlash: MSL's LossyGearDemo1 and Backlash
(acausal.models.gears).

LossyGearDemo1: a sine torque drives inertia1 through a LossyGear (ratio 2, efficiency 0.5
both ways) against a load on inertia2; the gear rolls backward, sticks (the load cannot drive
it back through an efficiency of 0.5), rolls forward, sticks, rolls backward. Prints the event
log and the loss energy against the power the flanges lose (MSL's check: both the same).
Backlash: an inertia swinging on an ElastoBacklash against one on a SpringDamper. Saves
``lossy_gear.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.models.gears import INTERVAL, START, STOP_TIME, Backlash, LossyGearDemo1


def main():
    grid = np.arange(0.0, STOP_TIME["LossyGearDemo1"] + INTERVAL / 2, INTERVAL)
    gear = acausal.compile(LossyGearDemo1()).simulate(
        grid[-1], t=grid, x0=START["LossyGearDemo1"], rtol=1e-8, atol=1e-10)
    for event in gear.events:
        if event.modes:
            print(event)
    flanges = (gear["gear.flange_a.tau"] * gear["Inertia1.w"]
               + gear["gear.flange_b.tau"] * gear["Inertia2.w"])    # MSL's PowerLoss
    print(f"max |lossPower - power lost at the flanges| = "
          f"{np.abs(gear['gear.lossPower'] - flanges).max():.1e} W")

    grid = np.arange(0.0, STOP_TIME["Backlash"] + INTERVAL / 2, INTERVAL)
    swing = acausal.compile(Backlash()).simulate(grid[-1], t=grid, x0=START["Backlash"],
                                                 rtol=1e-8, atol=1e-10)

    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "lossy_gear.png")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2, ax3) = plt.subplots(3, 1, figsize=(7, 8))
    ax1.plot(gear.t, gear["Inertia1.w"], label="Inertia1.w")
    ax1.plot(gear.t, gear["Inertia2.w"], label="Inertia2.w")
    ax1.set_ylabel("speed [rad/s]")
    ax2.step(gear.t, gear["gear.mode"], where="post", label="gear.mode")
    ax2.set_ylabel("mode")
    for name in ("springDamper.phi_rel", "elastoBacklash.phi_rel", "elastoBacklash2.phi_rel"):
        ax3.plot(swing.t, swing[name], label=name)
    ax3.set_ylabel("angle [rad]")
    ax3.set_xlabel("time [s]")
    for ax in (ax1, ax2, ax3):
        ax.grid(True)
        ax.legend(loc="upper right")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"saved {out}")


if __name__ == "__main__":
    main()
