"""MSL's Translational.Examples.HeatLosses: every dissipating element of a translational
drive line sends its lossPower through its heatPort (useHeatPort=True) to one convection
element (Gc = 20 W/K) to an ambient of 25 °C.

    sine1 → force ─ mass1 ─ springDamper ─ mass2 ─ supportFriction ─ spring ─ mass3 ─ brake
                     │  │                                                sine2 ─┘ │
          fixed1 ─ damper  elastoGap ─ fixed2          massWithStopAndFriction ─ springDamper1
    heatPorts of damper, springDamper, elastoGap, supportFriction, brake, springDamper1,
    massWithStopAndFriction → convection.solid; convection.fluid → TAmbient

The experiment: StopTime 2 s, Interval 0.001 s; ``START`` holds MSL's initial values (all at
rest; the masses (L = 0.1 m) one after another with the springs unstretched).

Against the published reference (Dymola): equal until massWithStopAndFriction hits its stop
(0.4285 s, ``reinit(v, 0)``). There Dymola, whose states include springDamper1's relative
s_rel, v_rel (stateSelect prefer), keeps v_rel and so moves mass3 with the stopped mass;
acausal's coordinates are the masses' own, mass3 keeps its speed and springDamper1.v_rel
jumps: the results part from then on.
"""
from __future__ import annotations

from ..components import signals as sig
from ..components import thermal as th
from ..components import translational as tr
from ..core import Model

STOP_TIME, INTERVAL = 2.0, 0.001            # s, the MSL experiment


class TranslationalHeatLosses(Model):
    """MSL's Translational.Examples.HeatLosses with its parameters: masses m = 1 kg, L = 0.1 m;
    springDamper c = 100 N/m, d = 10 N.s/m; damper d = 10 N.s/m; elastoGap c = 100 N/m,
    d = 20 N.s/m, s_rel0 = −0.02 m; spring c = 100 N/m; supportFriction (MSL's default
    table); brake fn_max = 10 N; massWithStopAndFriction F_prop = 0.5, F_Coulomb = 1,
    F_Stribeck = 2, fexp = 2, smin = 0, smax = 0.4 m; springDamper1 c = 1e4 N/m,
    d = 1000 N.s/m; force = 20 sin(2π t) N, brake f_normalized = 10 sin(4π t)."""
    START = {"mass1.s": 0.0, "mass1.v": 0.0, "mass2.s": 0.1, "mass2.v": 0.0,
             "mass3.s": 0.2, "mass3.v": 0.0, "massWithStopAndFriction.s": 0.3,
             "massWithStopAndFriction.v": 0.0}

    def __init__(self, name="HeatLosses"):
        super().__init__(name)
        self.mass1 = tr.Mass(m=1.0, L=0.1)
        self.springDamper = tr.SpringDamper(c=100.0, d=10.0, useHeatPort=True)
        self.damper = tr.Damper(d=10.0, useHeatPort=True)
        self.elastoGap = tr.ElastoGap(c=100.0, d=20.0, s_rel0=-0.02, useHeatPort=True)
        self.fixed1, self.fixed2 = tr.Fixed(), tr.Fixed()
        self.force = tr.Force()
        self.sine1 = sig.Sine(f=1.0, amplitude=20.0)
        self.mass2 = tr.Mass(m=1.0, L=0.1)
        self.supportFriction = tr.SupportFriction(useHeatPort=True)
        self.spring = tr.Spring(c=100.0)
        self.mass3 = tr.Mass(m=1.0, L=0.1)
        self.brake = tr.Brake(fn_max=10.0, useHeatPort=True)
        self.sine2 = sig.Sine(amplitude=10.0, f=2.0)
        self.massWithStopAndFriction = tr.MassWithStopAndFriction(
            L=0.1, m=1.0, F_prop=0.5, F_Coulomb=1.0, F_Stribeck=2.0, fexp=2.0, smin=0.0,
            smax=0.4, useHeatPort=True)
        self.convection = th.Convection()
        self.const = sig.Constant(k=20.0)
        self.TAmbient = th.FixedTemperature(T=298.15)
        self.springDamper1 = tr.SpringDamper(c=10000.0, d=1000.0, useHeatPort=True)
        for a, b in [(self.mass1.flange_b, self.springDamper.flange_a),
                     (self.sine1.y, self.force.f), (self.force.flange, self.mass1.flange_a),
                     (self.mass1.flange_a, self.damper.flange_a),
                     (self.damper.flange_b, self.fixed1.flange),
                     (self.springDamper.flange_b, self.mass2.flange_a),
                     (self.mass2.flange_b, self.supportFriction.flange_a),
                     (self.supportFriction.flange_b, self.spring.flange_a),
                     (self.spring.flange_b, self.mass3.flange_a),
                     (self.mass3.flange_b, self.brake.flange_a),
                     (self.sine2.y, self.brake.f_normalized),
                     (self.elastoGap.flange_b, self.mass1.flange_a),
                     (self.const.y, self.convection.Gc),
                     (self.TAmbient.port, self.convection.fluid),
                     (self.elastoGap.flange_a, self.fixed2.flange),
                     (self.brake.flange_b, self.springDamper1.flange_a),
                     (self.springDamper1.flange_b, self.massWithStopAndFriction.flange_a)]:
            self.connect(a, b)
        for heated in (self.elastoGap, self.damper, self.springDamper, self.supportFriction,
                       self.brake, self.massWithStopAndFriction, self.springDamper1):
            self.connect(heated.heatPort, self.convection.solid)
