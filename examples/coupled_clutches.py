"""Clutches on state events: MSL's CoupledClutches (four inertias behind three clutches
engaged one after the other, acausal.models.clutches) and MSL's OneWayClutch example (a
sine torque drives an output inertia through a one-way clutch: the freewheel locks when the
input catches up, the output overruns when the input slows down).

Prints the event log (clutch modes: -1 backward, 0 stuck, 1 forward, 2 free; the one-way
clutch's stuck / startForward) and saves ``coupled_clutches.png`` (in $ACAUSAL_OUT, default
the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.models.clutches import (INTERVAL, ONE_WAY_START, ONE_WAY_STOP_TIME, START,
                                     STOP_TIME, CoupledClutches, OneWayClutchDrive)


def main():
    grid = np.arange(0.0, STOP_TIME + INTERVAL / 2, INTERVAL)
    res = acausal.compile(CoupledClutches()).simulate(STOP_TIME, t=grid, x0=START,
                                                       rtol=1e-8, atol=1e-10)
    for event in res.events:
        print(event)
    one_way = acausal.compile(OneWayClutchDrive()).simulate(
        ONE_WAY_STOP_TIME, x0=ONE_WAY_START, t=np.arange(0.0, 2.0 + 5e-4, 1e-3), rtol=1e-8,
        atol=1e-10)
    print(f"one-way clutch: {len(one_way.events)} events, locked at "
          + ", ".join(f"{ev.time:.6f}" for ev in one_way.events
                      if ev.modes.get("oneWayClutch.stuck") == (0.0, 1.0)) + " s")

    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(4, 1, sharex=False, figsize=(7, 9))
    for k in (1, 2, 3, 4):
        axes[0].plot(res.t, res[f"J{k}.w"], label=f"J{k}.w")
    axes[0].set_ylabel("speed [rad/s]")
    for k in (1, 2, 3):
        axes[1].plot(res.t, res[f"clutch{k}.tau"], label=f"clutch{k}.tau")
        axes[2].step(res.t, res[f"clutch{k}.mode"], where="post", label=f"clutch{k}.mode")
    axes[1].set_ylabel("friction torque [N.m]")
    axes[2].set_ylabel("mode")
    for name in ("inertiaIn.w", "inertiaOut.w"):
        axes[3].plot(one_way.t, one_way[name], label=name)
    axes[3].set_ylabel("one-way clutch\nspeed [rad/s]")
    axes[3].set_xlabel("time [s]")
    for ax in axes:
        ax.grid(True)
        ax.legend(loc="upper right", fontsize=7)
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "coupled_clutches.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"saved {out}")


if __name__ == "__main__":
    main()
