"""A pulse-driven transformer and a tuned LC circuit: new sources and elements of
acausal.components.electrical (after Modelica.Electrical.Analog).

    PulseVoltage -- R1 --+ p1      p2 +-- MultiSensor -- load R2 --+
         |               Transformer  +-- C ----------------------+
       Ground ---------- n1 ------ n2 -----------------------------+

    TrapezoidCurrent --> VariableInductor L(t) (a Ramp block) ∥ C ∥ R

The pulse's edges are time events (the integrator restarts there); the transformer is a
pair of coupled inductors (L1, L2, M), whose leakage inductance rings with C. The
MultiSensor measures the load's current, voltage and power; the script checks the energy
balance of the first circuit (the source's energy = the resistors' losses + the energy
left in the inductors and the capacitor) and prints how the second circuit's ringing
frequency follows the growing inductance, 1/(2π·sqrt(L·C)). It saves
``electrical_sources.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components import electrical as el
from acausal.components import signals as sig


class PulseTransformer(acausal.Model):
    def __init__(self, name=None):
        super().__init__(name)
        self.src = el.PulseVoltage(V=12.0, width=40.0, period=2e-3)
        self.r1 = el.Resistor(R=0.5)
        self.tr = el.Transformer(L1=20e-3, L2=5e-3, M=9.5e-3)
        self.sensor = el.MultiSensor()
        self.load = el.Resistor(R=10.0)
        self.c = el.Capacitor(C=200e-6)
        self.ground = el.Ground()
        for a, b in [(self.src.p, self.r1.p), (self.r1.n, self.tr.p1),
                     (self.tr.n1, self.src.n), (self.src.n, self.ground.p),
                     (self.tr.p2, self.sensor.pc), (self.sensor.nc, self.load.p),
                     (self.sensor.pv, self.load.p), (self.sensor.nv, self.load.n),
                     (self.load.n, self.tr.n2), (self.c.p, self.tr.p2),
                     (self.c.n, self.tr.n2), (self.tr.n2, self.ground.p)]:
            self.connect(a, b)


class TunedCircuit(acausal.Model):
    def __init__(self, name=None):
        super().__init__(name)
        self.src = el.TrapezoidCurrent(I=0.1, rising=1e-4, width=2e-4, falling=1e-4,
                                       period=1.0, nperiod=1)
        self.L = sig.Ramp(height=3e-3, duration=0.02, offset=1e-3)
        self.l = el.VariableInductor()
        self.c = el.Capacitor(C=10e-6)
        self.r = el.Resistor(R=2000.0)
        self.ground = el.Ground()
        for a, b in [(self.L.y, self.l.L), (self.src.p, self.ground.p),
                     (self.src.n, self.l.p), (self.l.p, self.c.p), (self.l.p, self.r.p),
                     (self.l.n, self.ground.p), (self.c.n, self.ground.p),
                     (self.r.n, self.ground.p)]:
            self.connect(a, b)


def main():
    t = np.linspace(0.0, 0.02, 20000)              # no output point on a pulse edge
    res = acausal.compile(PulseTransformer()).simulate(0.02, t=t, rtol=1e-10, atol=1e-12)
    late = t > 0.015
    rms = np.sqrt(np.mean(res["sensor.v"][late] ** 2))
    print(f"load: {res['sensor.v'][late].min():.2f} .. {res['sensor.v'][late].max():.2f} V "
          f"(the transformer passes no DC), {rms:.3f} V rms, "
          f"{res['sensor.power'][late].mean():.3f} W mean")
    supplied = np.trapezoid(-res["src.v"] * res["src.i"], res.t)
    lost = np.trapezoid(res["r1.LossPower"] + res["load.LossPower"], res.t)
    i1, i2 = res["tr.i1"][-1], res["tr.i2"][-1]
    stored = (0.5 * (20e-3 * i1 ** 2 + 2 * 9.5e-3 * i1 * i2 + 5e-3 * i2 ** 2)
              + 0.5 * 200e-6 * res["c.v"][-1] ** 2)
    print(f"energy: supplied {supplied * 1e3:.4f} mJ = lost {lost * 1e3:.4f} mJ + "
          f"stored {stored * 1e3:.4f} mJ (off by {abs(supplied - lost - stored):.1e} J: the "
          f"trapezoidal rule across the pulse's jumps)")

    tt = np.linspace(0.0, 0.02, 8001)
    tuned = acausal.compile(TunedCircuit()).simulate(0.02, t=tt, rtol=1e-10, atol=1e-12)
    v = tuned["c.v"]
    rising = tt[1:][(v[:-1] < 0) & (v[1:] >= 0)]
    for a, b in zip(rising[:-1:3], rising[1::3]):
        L = 1e-3 + 3e-3 * (a + b) / 2 / 0.02
        print(f"t = {(a + b) / 2 * 1e3:5.2f} ms: rings at {1 / (b - a):6.1f} Hz "
              f"(1/(2π·sqrt(L·C)) = {1 / (2 * np.pi * np.sqrt(L * 10e-6)):6.1f} Hz)")

    import matplotlib.pyplot as plt
    fig, (ax1, ax2, ax3) = plt.subplots(3, 1, figsize=(7, 7))
    ax1.plot(t * 1e3, res["src.v"], label="pulse source")
    ax1.plot(t * 1e3, res["sensor.v"], label="load")
    ax1.set_ylabel("voltage [V]")
    ax1.legend()
    ax2.plot(t * 1e3, res["tr.i1"], label="primary i1")
    ax2.plot(t * 1e3, res["tr.i2"], label="secondary i2")
    ax2.set_ylabel("current [A]")
    ax2.legend()
    ax3.plot(tt * 1e3, v)
    ax3.set_ylabel("tuned circuit [V]")
    ax3.set_xlabel("time [ms]")
    fig.tight_layout()
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "electrical_sources.png"))


if __name__ == "__main__":
    main()
