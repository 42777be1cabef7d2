"""MSL's Electrical.Analog examples rebuilt from acausal.components.electrical."""
from __future__ import annotations

from ..core import Model
from ..components import electrical as el

L1, L2 = 1.304, 0.8586
C1, C3, C5 = 1.072, 1.682, 0.7262
C2, C4 = 1 / (1.704992 ** 2 * L1), 1 / (1.179945 ** 2 * L2)


class CauerLowPassAnalog(Model):
    """MSL's Electrical.Analog.Examples.CauerLowPassAnalog: a 7th-order Cauer low-pass filter
    (R1 — C1 ∥ ground — L1 ∥ C2 — C3 ∥ ground — L2 ∥ C4 — C5 ∥ ground — R2) driven by a 1 V
    step at 1 s; StopTime 60 s. The capacitors C1, C2, C3 and C3, C4, C5 form two loops:
    compile it with ``index_reduction=True`` (C3 and C5 become expressions of the other
    voltages; every capacitor starts at 0 V as in the MSL, where C1, C3, C5 are fixed)."""

    def __init__(self, name=None):
        super().__init__(name)
        self.G = el.Ground()
        self.C1, self.C2, self.C3 = el.Capacitor(C=C1), el.Capacitor(C=C2), el.Capacitor(C=C3)
        self.C4, self.C5 = el.Capacitor(C=C4), el.Capacitor(C=C5)
        self.L1, self.L2 = el.Inductor(L=L1), el.Inductor(L=L2)
        self.R1, self.R2 = el.Resistor(R=1.0), el.Resistor(R=1.0)
        self.V = el.StepVoltage(startTime=1.0, offset=0.0, V=1.0)
        for a, b in [(self.R1.n, self.C1.p), (self.C1.n, self.G.p), (self.L1.p, self.C2.p),
                     (self.L1.p, self.C1.p), (self.L1.n, self.C2.n), (self.C2.n, self.C3.p),
                     (self.C2.n, self.C4.p), (self.C2.n, self.L2.p), (self.L2.n, self.C4.n),
                     (self.C4.n, self.C5.p), (self.C4.n, self.R2.p), (self.C1.n, self.C3.n),
                     (self.C1.n, self.C5.n), (self.R2.n, self.C1.n), (self.R1.p, self.V.p),
                     (self.V.n, self.G.p)]:
            self.connect(a, b)
