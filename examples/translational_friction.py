"""Friction, stops and hard stops in translation on state events: MSL's
Translational.Examples.Friction (acausal.models.translational_friction) and a ball bouncing
to rest on a HardStop with restitution.

MSL's example: stop1 (MassWithStopAndFriction, Stribeck friction) and a Mass on a
SupportFriction with the same characteristic as a table are driven by 25·sin(2π·0.25·t) N
and move alike; stop2 starts at −5 m/s on a spring, hits its stop at smin (its speed set to
0), slides back and forth and sticks at 1.05 s. Prints the mode changes and saves
``translational_friction.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components import translational as tr
from acausal.models.translational_friction import TranslationalFriction as Friction

G, H, E = 9.81, 1.0, 0.8          # gravity [m/s²], drop height [m], restitution [1]


def bouncing_to_rest():
    """Impacts at t1 = √(2H/g), then every 2·E^k·v1/g; at rest once slower than v_small."""
    m = acausal.Model("ball")
    m.body, m.gravity = tr.Mass(m=1.0), tr.ConstantForce(f_constant=-G)
    m.stop = tr.HardStop(smin=0.0, smax=10.0, e=E, v_small=0.05)
    m.connect(m.gravity.flange, m.body.flange_a)
    m.connect(m.stop.flange, m.body.flange_a)
    res = acausal.compile(m).simulate(5.0, x0={"body.s": H}, rtol=1e-10, atol=1e-12)
    impacts = [ev.time for ev in res.events if ev.indicator == "stop.gap_min"]
    v1 = np.sqrt(2 * G * H)
    closed = np.sqrt(2 * H / G) + np.concatenate(
        [[0.0], np.cumsum([2 * E ** k * v1 / G for k in range(1, len(impacts))])])
    print(f"{len(impacts)} impacts, largest difference to the closed form "
          f"{np.abs(np.array(impacts) - closed).max():.1e} s; at rest from "
          f"{impacts[-1]:.6f} s")
    return res


def main():
    ball = bouncing_to_rest()
    res = acausal.compile(Friction()).simulate(
        Friction.STOP_TIME, x0=Friction.START, rtol=1e-8, atol=1e-10,
        t=np.arange(0.0, Friction.STOP_TIME + Friction.INTERVAL / 2, Friction.INTERVAL))
    for event in res.events:
        if any(name.endswith(".mode") for name in event.modes):
            print(event)

    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "translational_friction.png")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2, ax3) = plt.subplots(3, 1, figsize=(7, 8))
    ax1.plot(res.t, res["stop1.v"], label="stop1.v (MassWithStopAndFriction)")
    ax1.plot(res.t, res["mass.v"], "--", label="mass.v (Mass + SupportFriction)")
    ax1.set_ylabel("speed [m/s]")
    ax2.plot(res.t, res["stop2.s"], label="stop2.s (stops at ±0.4 m)")
    ax2.step(res.t, 0.1 * res["stop2.mode"], where="post", label="0.1·stop2.mode")
    ax2.set_ylabel("position [m]")
    ax2.set_xlabel("time [s]")
    ax3.plot(ball.t, ball["body.s"], label="ball on a HardStop, e = 0.8")
    ax3.set_xlabel("time [s]")
    ax3.set_ylabel("height [m]")
    for ax in (ax1, ax2, ax3):
        ax.legend(loc="upper right")
        ax.grid(True)
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    print(f"saved {out}")


if __name__ == "__main__":
    main()
