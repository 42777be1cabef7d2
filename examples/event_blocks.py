"""Blocks with events and discrete time: a thermostat and a sampled position controller.

1. Thermostat: an OnOffController (reference 5, bandwidth 2) switches a heater of power 12
   on a first-order plant (time constant 2 s); the relation's state events put every switch
   exactly where the temperature reaches 4 or 6, checked against the closed form
   τ·ln(6/4) (cooling) and τ·ln((12 − 4)/(12 − 6)) (heating).
2. Sampled P controller: a Sampler reads the position of a damped mass every 0.1 s, a
   ZeroOrderHold holds the force K·(1 − x_k) until the next sample (a staircase).

Saves ``event_blocks.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.models import SampledPController, Thermostat

TAU, POWER, REFERENCE, BAND = 2.0, 12.0, 5.0, 2.0


def thermostat():
    m = Thermostat(kind="OnOffController", tau=TAU, power=POWER, lower=REFERENCE - BAND / 2,
                   upper=REFERENCE + BAND / 2)
    res = acausal.compile(m).simulate(12.0, rtol=1e-10, atol=1e-12)
    switches = np.array([ev.time for ev in res.events if ev.component == "ctrl"])
    off, on = switches[1::2] - switches[0::2][:len(switches) // 2], np.diff(switches)[1::2]
    low, high = REFERENCE - BAND / 2, REFERENCE + BAND / 2
    print(f"thermostat: {len(switches)} switches; off for {off[:2]} s (closed form "
          f"{TAU * np.log(high / low):.9f}), on for {on[:2]} s (closed form "
          f"{TAU * np.log((POWER - low) / (POWER - high)):.9f})")
    return res


def sampled_controller():
    m = SampledPController(m=1.0, c=0.0, d=8.0, K=20.0, reference=1.0, samplePeriod=0.1)
    res = acausal.compile(m).simulate(2.0)
    print(f"sampled controller: {len(res.events)} sample instants with a new force; "
          f"x(2 s) = {res.final('mass.s'):.4f} m")
    return res


def main():
    heat, loop = thermostat(), sampled_controller()
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "event_blocks.png")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 6))
    ax1.plot(heat.t, heat["plant.y"], label="temperature (plant.y)")
    ax1.plot(heat.t, heat["heater.y"] / POWER, label="heater on (ctrl.y)")
    ax1.set_xlabel("time [s]")
    ax2.plot(loop.t, loop["mass.s"], label="mass.s [m]")
    ax2.plot(loop.t, loop["zoh.y"] / 20.0, label="force / K (zoh.y / 20)")
    ax2.set_xlabel("time [s]")
    for ax in (ax1, ax2):
        ax.grid(True)
        ax.legend(loc="upper right")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"saved {out}")


if __name__ == "__main__":
    main()
