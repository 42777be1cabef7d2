"""A phase-controlled half-wave rectifier: a 50 Hz sine source, an IdealThyristor fired by a
short BooleanPulse at the firing angle alpha of every period, and an R-L load.

    SineVoltage --|>|-- Resistor -- SaturatingInductor --+
         |      thyristor  ^ fire: BooleanPulse (alpha)  |
       Ground -------------------------------------------+

The thyristor turns on when ``fire`` rises (its mode ``th.off`` switched at that time
event), keeps conducting after the pulse ends and turns off where its current falls
through 0 (a state event), after the source's zero crossing because the inductor drives
the current on. With a plain resistor the conduction angle would be π − alpha; with a
linear R-L load the current V/Z·(sin(θ − φ) − sin(alpha − φ)·exp(−(θ − alpha)/tan φ)),
φ = atan(ωL/R), falls to 0 at the extinction angle beta. The script prints the instants
and the conduction angle for a linear and a saturating inductor of the same nominal
inductance (the saturating one, smaller at large currents, lets the current rise higher
and die sooner), beta from that closed form, and saves ``thyristor_rectifier.png`` (in
$ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import math
import os

import numpy as np

import acausal
from acausal.components import electrical as el
from acausal.components import logical as lg

F, ALPHA = 50.0, math.pi / 4               # supply frequency [Hz], firing angle [rad]
R, L = 10.0, 0.02                           # load resistance [Ohm], inductance [H]


def extinction_angle():
    """beta [rad]: the zero of the linear R-L load's current after alpha (bisection)."""
    w = 2 * math.pi * F
    phi = math.atan(w * L / R)

    def current(theta):
        return math.sin(theta - phi) - math.sin(ALPHA - phi) * math.exp(
            -(theta - ALPHA) / math.tan(phi))
    lo, hi = math.pi, 2 * math.pi                   # current > 0 at π, < 0 at 2π
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if current(mid) > 0 else (lo, mid)
    return lo


class ThyristorRectifier(acausal.Model):
    def __init__(self, inductor, name=None):
        super().__init__(name)
        self.src = el.SineVoltage(V=325.0, f=F)
        self.th = el.IdealThyristor()
        self.fire = lg.BooleanPulse(period=1 / F, width=5.0, startTime=ALPHA / (2 * math.pi * F))
        self.load = el.Resistor(R=R)
        self.l = inductor
        self.ground = el.Ground()
        for a, b in [(self.src.p, self.th.p), (self.th.n, self.load.p),
                     (self.load.n, self.l.p), (self.l.n, self.ground.p),
                     (self.src.n, self.ground.p), (self.fire.y, self.th.fire)]:
            self.connect(a, b)


def main():
    t = np.linspace(0.0, 0.06, 3001)
    results = {}
    for label, inductor in [("linear", el.Inductor(L=L)),
                            ("saturating", el.SaturatingInductor(Inom=10.0, Lnom=L,
                                                                 Lzer=0.05, Linf=0.005))]:
        res = acausal.compile(ThyristorRectifier(inductor)).simulate(
            0.06, t=t, rtol=1e-10, atol=1e-12)
        results[label] = res
        on = None
        for ev in res.events:
            if "th.off" in ev.modes and ev.time > 0:
                if ev.modes["th.off"][1] == 0:
                    on = ev.time
                elif on is not None:
                    angle = 2 * math.pi * F * (ev.time - on)
                    print(f"{label:>10} inductor: on at {on * 1e3:7.3f} ms, off at "
                          f"{ev.time * 1e3:7.3f} ms, conduction angle {math.degrees(angle):6.1f}"
                          f" deg (resistive load: {math.degrees(math.pi - ALPHA):.1f} deg)")
        print(f"{label:>10} inductor: peak current {res['l.i'].max():.2f} A")
    print(f"closed form, linear R-L load: conduction angle "
          f"{math.degrees(extinction_angle() - ALPHA):6.1f} deg")

    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
    ax1.plot(results["linear"].t * 1e3, results["linear"]["src.v"], label="source")
    for label, res in results.items():
        ax1.plot(res.t * 1e3, res["load.p.v"], label=f"load ({label} L)")
        ax2.plot(res.t * 1e3, res["th.i"], label=label)
    ax1.set_ylabel("voltage [V]")
    ax1.legend()
    ax2.set_ylabel("thyristor current [A]")
    ax2.set_xlabel("time [ms]")
    ax2.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "thyristor_rectifier.png"))


if __name__ == "__main__":
    main()
