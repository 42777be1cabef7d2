"""A half-wave rectifier: a 50 Hz sine source, an IdealDiode (MSL's parametric
characteristic: Ron = 1e-5 Ohm conducting, Goff = 1e-5 S blocking) and a load resistor
with a smoothing capacitor.

    SineVoltage --|>|-- node c --+-- Resistor --+
         |         diode         +-- Capacitor -+
       Ground ------------------------------------+

The diode's state (``diode.off``) is a mode switched at state events located where the
auxiliary variable ``diode.s`` crosses 0: conduction ends when the diode current falls to
0 just after the source's peak, and starts again when the source rises above the
capacitor. The script prints these instants and the ripple, and saves ``rectifier.png``
(in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components import electrical as el


class Rectifier(acausal.Model):
    def __init__(self, name=None):
        super().__init__(name)
        self.src = el.SineVoltage(V=10.0, f=50.0)
        self.diode = el.IdealDiode()
        self.load = el.Resistor(R=100.0)
        self.c = el.Capacitor(C=1e-4)
        self.ground = el.Ground()
        for a, b in [(self.src.p, self.diode.p), (self.diode.n, self.load.p),
                     (self.load.p, self.c.p), (self.load.n, self.ground.p),
                     (self.c.n, self.ground.p), (self.src.n, self.ground.p)]:
            self.connect(a, b)


def main():
    res = acausal.compile(Rectifier()).simulate(0.1, t=np.linspace(0.0, 0.1, 2001),
                                                rtol=1e-10, atol=1e-12)
    for ev in res.events:
        if "diode.off" in ev.modes and ev.time > 0:
            what = "stops" if ev.modes["diode.off"][1] else "starts"
            print(f"t = {ev.time * 1e3:8.4f} ms: the diode {what} conducting")
    late = res.t > 0.06
    print(f"output {res['c.v'][late].min():.3f} .. {res['c.v'][late].max():.3f} V "
          f"(ripple {np.ptp(res['c.v'][late]):.3f} V)")

    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
    ax1.plot(res.t * 1e3, res["src.v"], label="source")
    ax1.plot(res.t * 1e3, res["c.v"], label="capacitor")
    ax1.set_ylabel("voltage [V]")
    ax1.legend()
    ax2.plot(res.t * 1e3, res["diode.i"])
    ax2.set_ylabel("diode current [A]")
    ax2.set_xlabel("time [ms]")
    fig.tight_layout()
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "rectifier.png"))


if __name__ == "__main__":
    main()
