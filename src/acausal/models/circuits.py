"""MSL's Electrical.Analog examples rebuilt from acausal.components.electrical (and thermal)."""
from __future__ import annotations

from ..core import Model
from ..components import electrical as el
from ..components import thermal as th

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


class ChuaCircuit(Model):
    """MSL's Electrical.Analog.Examples.ChuaCircuit: Chua's chaotic circuit, L (18 H, i = 0)
    in series with Ro (12.5 mΩ) from the node of C2 (100 F, v = 0) to ground, the
    Conductor G (0.565 S) to the node of C1 (10 F, v = 4 V) and the NonlinearResistor Nr
    (Ga = −0.757576 S, Gb = −0.409091 S, Ve = 1 V); StopTime 50000 s."""

    def __init__(self, name=None):
        super().__init__(name)
        self.L = el.Inductor(L=18.0)
        self.Ro = el.Resistor(R=12.5e-3)
        self.G = el.Conductor(G=0.565)
        self.C1 = el.Capacitor(C=10.0, v_start=4.0)
        self.C2 = el.Capacitor(C=100.0)
        self.Nr = el.NonlinearResistor(Ga=-0.757576, Gb=-0.409091, Ve=1.0)
        self.Gnd = el.Ground()
        for a, b in [(self.L.n, self.Ro.p), (self.C2.p, self.G.p), (self.L.p, self.G.p),
                     (self.G.n, self.Nr.p), (self.C1.p, self.G.n), (self.Ro.n, self.Gnd.p),
                     (self.C2.n, self.Gnd.p), (self.Gnd.p, self.C1.n), (self.Gnd.p, self.Nr.n)]:
            self.connect(a, b)


class ResistorExample(Model):
    """MSL's Electrical.Analog.Examples.Resistor ("Resistor with simple thermal network",
    MSL 3's Examples.HeatingResistor): SineVoltage1 (220 V, 1 Hz) across ``resistor`` (R =
    100 Ω at T_ref = 293.15 K, alpha = 1e-3 1/K, useHeatPort), whose heat flows through
    ``thermalConductor`` (G = 50 W/K) to ``fixedTemperature`` (Celsius 20 °C = 293.15 K).
    No states: the resistor's temperature and current solve 0 = v − R_actual·i,
    T = 293.15 K + v·i/G at every instant. StopTime 5 s."""

    def __init__(self, name=None):
        super().__init__(name)
        self.resistor = el.Resistor(R=100.0, alpha=1e-3, T_ref=293.15, useHeatPort=True)
        self.G = el.Ground()
        self.SineVoltage1 = el.SineVoltage(V=220.0, f=1.0)
        self.thermalConductor = th.ThermalConductor(G=50.0)
        self.fixedTemperature = th.FixedTemperature(T=293.15)
        for a, b in [(self.SineVoltage1.n, self.G.p),
                     (self.resistor.heatPort, self.thermalConductor.port_a),
                     (self.SineVoltage1.p, self.resistor.p), (self.G.p, self.resistor.n),
                     (self.thermalConductor.port_b, self.fixedTemperature.port)]:
            self.connect(a, b)


class HeatingRectifier(Model):
    """MSL's Electrical.Analog.Examples.HeatingRectifier: SineVoltage1 (1 V, 1 Hz) through
    HeatingDiode1 (a Diode with useTemperatureDependency and useHeatPort, MSL's defaults
    otherwise) onto Capacitor1 (1 F, v = 0) in parallel with R (1 Ω); the diode's heat flows
    through ThermalConductor1 (10 W/K) into HeatCapacitor1 (1 J/K, T = 293.15 K). StopTime
    5 s."""

    def __init__(self, name=None):
        super().__init__(name)
        self.HeatingDiode1 = el.Diode(useTemperatureDependency=True, useHeatPort=True)
        self.G = el.Ground()
        self.SineVoltage1 = el.SineVoltage(V=1.0, f=1.0)
        self.Capacitor1 = el.Capacitor(C=1.0)
        self.HeatCapacitor1 = th.HeatCapacitor(C=1.0, T_start=293.15)
        self.ThermalConductor1 = th.ThermalConductor(G=10.0)
        self.R = el.Resistor(R=1.0)
        for a, b in [(self.SineVoltage1.p, self.HeatingDiode1.p),
                     (self.SineVoltage1.n, self.G.p), (self.Capacitor1.n, self.G.p),
                     (self.HeatingDiode1.n, self.Capacitor1.p),
                     (self.HeatingDiode1.heatPort, self.ThermalConductor1.port_a),
                     (self.ThermalConductor1.port_b, self.HeatCapacitor1.port),
                     (self.R.p, self.Capacitor1.p), (self.R.n, self.Capacitor1.n)]:
            self.connect(a, b)
