"""Routing and timed Boolean blocks (MSL Routing, Logical, MathBoolean) in one small diagram.

1. Vector signals: a sine and a cosine are multiplexed into y[1..2], with a ramp into
   y[3], the vector reordered by ExtractSignal(extract=[3, 1]) and split again:

       Sine, Cosine, Ramp --> Multiplex3 --> ExtractSignal --> DeMultiplex2 --> ramp, sine

2. A start button (BooleanTable: pressed 1..4 s, 5..5.5 s, 6..9 s) through
   MathBoolean.OnDelay(delayTime=1): the machine runs only when pressed for 1 s; its speed
   set point is a TriggeredTrapezoid (up in 1.5 s, down in 0.5 s) of the delayed signal;
   MathBoolean.And(nu=2) of the button and an enable step (at 2 s).

Run ``python examples/routing.py``: prints the routed values against their sources and the
switching instants against the closed forms; saves ``routing.png`` (in $ACAUSAL_OUT, default
the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components.logical import BooleanStep, BooleanTable, MathBoolean, TriggeredTrapezoid
from acausal.components.signals import (Cosine, DeMultiplex2, ExtractSignal, Multiplex3, Ramp,
                                        Sine)


def build() -> acausal.Model:
    m = acausal.Model("routing")
    m.sine, m.cosine = Sine(f=0.5), Cosine(f=0.5)
    m.ramp = Ramp(height=2.0, duration=10.0)
    m.mux = Multiplex3()                                  # n1 = n2 = n3 = 1
    m.pick = ExtractSignal(nin=3, extract=[3, 1])
    m.demux = DeMultiplex2()
    for src, k in ((m.sine, 1), (m.cosine, 2), (m.ramp, 3)):
        m.connect(src.y, getattr(m.mux, f"u{k}")[1])
        m.connect(m.mux.y[k], m.pick.u[k])
    m.connect(m.pick.y[1], m.demux.u[1])
    m.connect(m.pick.y[2], m.demux.u[2])

    m.button = BooleanTable(table=[1.0, 4.0, 5.0, 5.5, 6.0, 9.0])
    m.start = MathBoolean.OnDelay(delayTime=1.0)
    m.speed = TriggeredTrapezoid(amplitude=100.0, rising=1.5, falling=0.5)
    m.enable = BooleanStep(startTime=2.0)
    m.both = MathBoolean.And(nu=2)
    for a, b in ((m.button.y, m.start.u), (m.start.y, m.speed.u), (m.button.y, m.both.u[1]),
                 (m.enable.y, m.both.u[2])):
        m.connect(a, b)
    return m


def main() -> None:
    t = np.linspace(0.0, 10.0, 1001)
    res = acausal.compile(build()).simulate(10.0, t=t, rtol=1e-10, atol=1e-12)
    same = np.array_equal(res["demux.y1[1]"], res["ramp.y"]) \
        and np.array_equal(res["demux.y2[1]"], res["sine.y"])
    print(f"demux.y1 is the ramp and demux.y2 the sine, exactly: {same}")
    rises = res.t[np.flatnonzero(np.diff(res["start.y"]) > 0) + 1]
    print(f"OnDelay rises at {np.round(rises, 9).tolist()} s (closed form: 2.0, 7.0)")
    print(f"speed at 3.5 s: {np.interp(3.5, res.t, res['speed.y']):.6f} (closed form: 100)")
    both = [float(res["both.y"][np.flatnonzero(np.abs(res.t - tk) < 1e-9)[-1]])
            for tk in (1.5, 3.0)]
    print(f"button and enable at 1.5 s, 3 s: {both} (closed form: [0, 1])")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 1, sharex=True, figsize=(8, 5))
    for name in ("demux.y1[1]", "demux.y2[1]"):
        ax[0].plot(res.t, res[name], label=name)
    ax[0].legend()
    ax[0].set_ylabel("signal")
    ax[1].step(res.t, res["button.y"] * 100, where="post", label="button (×100)")
    ax[1].plot(res.t, res["speed.y"], label="speed set point")
    ax[1].legend()
    ax[1].set_xlabel("t [s]")
    ax[1].set_ylabel("speed")
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "routing.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"saved {out}")


if __name__ == "__main__":
    main()
