"""MSL's Translational.Examples.HeatLosses (below) and Rotational.Examples.HeatLosses
(``RotationalHeatLosses``): every dissipating element of a drive line sends its lossPower
through its heatPort (useHeatPort=True) to one convection element (Gc = 20 W/K) to an
ambient of 25 °C.

    sine1 → force ─ mass1 ─ springDamper ─ mass2 ─ supportFriction ─ spring ─ mass3 ─ brake
                     │  │                                                sine2 ─┘ │
          fixed1 ─ damper  elastoGap ─ fixed2          massWithStopAndFriction ─ springDamper1
    heatPorts of damper, springDamper, elastoGap, supportFriction, brake, springDamper1,
    massWithStopAndFriction → convection.solid; convection.fluid → TAmbient

The experiment: StopTime 2 s, Interval 0.001 s; ``START`` holds MSL's initial values (all at
rest; the masses (L = 0.1 m) one after another with the springs unstretched).

Against the published reference (Dymola): equal over the 2 s, through the two impacts of
massWithStopAndFriction on its stop (0.4285 s, 1.4992 s, ``reinit(v, 0)``). A reinit keeps
the states a Modelica tool keeps (``PhysicsBuilder.reinit``): springDamper1's relative
velocity v_rel is one (MSL's PartialCompliantWithRelativeStates, stateSelect prefer), so
mass3 jumps with the stopped mass (by −v of it) and v_rel runs on continuously.
"""
from __future__ import annotations

from ..components import rotational as rot
from ..components import signals as sig
from ..components import thermal as th
from ..components import translational as tr
from ..core import Model

STOP_TIME, INTERVAL = 2.0, 0.001            # s, the MSL experiment (Translational)
ROTATIONAL_STOP_TIME, ROTATIONAL_INTERVAL = 1.0, 1e-4     # s, the MSL experiment (Rotational)


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



class RotationalHeatLosses(Model):
    """MSL's Rotational.Examples.HeatLosses: a drive train whose every dissipating element
    sends its lossPower through its heatPort to one convection (Gc = 20 W/K, a Constant
    input) to an ambient of 25 °C (no heat capacity: convection.solid.T = 298.15 K +
    Σ lossPower/20 W/K at every instant).

        sine (20 sin 10πt N.m) → torque ─ inertia1 ─ springDamper ─ inertia2 ─ elastoBacklash
          ─ inertia3 ─ bearingFriction ─ spring3 ─ inertia4 ─ lossyGear ─ clutch ─ inertia5
          ─ oneWayClutch ─ inertia6 ─ brake;  inertia1 ─ damper ─ fixed
        sine2 (sin 0.4πt) → clutch, oneWayClutch, brake f_normalized
        heatPorts of damper, springDamper, elastoBacklash, bearingFriction, lossyGear,
        clutch, oneWayClutch, brake → convection.solid; convection.fluid → TAmbient

    MSL's parameters: inertias J = 2 kg.m² (all at rest, angles 0); damper d = 10 N.m.s/rad;
    springDamper c = 1e4 N.m/rad, d = 20 N.m.s/rad; elastoBacklash c = 1e5 N.m/rad,
    d = 100 N.m.s/rad, b = 0.001 rad; bearingFriction MSL's default (tau_pos = [0, 1] N.m);
    spring3 c = 1e4 N.m/rad; lossyGear ratio 2, lossTable [[0, 0.8, 0.8, 1, 1],
    [1, 0.7, 0.7, 2, 2]]; clutch fn_max = 10 N; oneWayClutch fn_max = 1 N; brake fn_max =
    2 N (mu_pos [0, 0.5] all). The experiment: StopTime 1 s, Interval 1e-4 s; MSL's start
    values (phi, w of inertia1..4, phi_rel, w_rel of clutch and oneWayClutch, fixed at 0)
    are the defaults: ``START`` is empty.

    Validation: MSL's published reference result of this example is not available here
    (the reference collection at hand holds only its list of comparison signals), so it is
    not compared with one. The tests check instead: the heat balance (the convection takes
    Σ lossPower at every instant, integrated to 1e-8), the energy balance (the torque's
    work = kinetic + spring energy + heat, to 1e-8, with the spring energy MSL's
    ElastoBacklash drops unreported when it stops pushing while still deflected), and the
    first phase (the elastoBacklash's first contact and the bearing's breakaway, ~0.034 s)
    against a hand-written scipy model.

    Statically indeterminate: while lossyGear, clutch, oneWayClutch (locked) and brake are
    all stuck, the torque spring3 puts on the gear may go to the ground through the gear or
    along the clutches to the brake in any split; the simulator takes the least-norm split
    at the event where they stuck (``acausal.simulation.events``), a Modelica tool one of
    its own (by pivoting): the brake's and the gear's breakaway times (0.0377 s, 0.0404 s
    here) depend on that choice.
    """
    START: dict = {}

    def __init__(self, name="HeatLosses"):
        super().__init__(name)
        self.sine = sig.Sine(f=5.0, amplitude=20.0)
        self.torque = rot.Torque()
        self.inertia1 = rot.Inertia(J=2.0)
        self.damper = rot.Damper(d=10.0, useHeatPort=True)
        self.fixed = rot.Fixed()
        self.convection = th.Convection()
        self.TAmbient = th.FixedTemperature(T=298.15)
        self.const = sig.Constant(k=20.0)
        self.springDamper = rot.SpringDamper(c=1e4, d=20.0, useHeatPort=True)
        self.inertia2 = rot.Inertia(J=2.0)
        self.elastoBacklash = rot.ElastoBacklash(c=1e5, d=100.0, b=0.001, useHeatPort=True)
        self.inertia3 = rot.Inertia(J=2.0)
        self.bearingFriction = rot.BearingFriction(useHeatPort=True)
        self.spring3 = rot.Spring(c=1e4)
        self.inertia4 = rot.Inertia(J=2.0)
        self.lossyGear = rot.LossyGear(ratio=2.0, lossTable=[[0, 0.8, 0.8, 1, 1],
                                                             [1, 0.7, 0.7, 2, 2]],
                                       useHeatPort=True)
        self.clutch = rot.Clutch(fn_max=10.0, useHeatPort=True)
        self.inertia5 = rot.Inertia(J=2.0)
        self.sine2 = sig.Sine(f=0.2, amplitude=1.0)
        self.inertia6 = rot.Inertia(J=2.0)
        self.oneWayClutch = rot.OneWayClutch(fn_max=1.0, useHeatPort=True)
        self.brake = rot.Brake(fn_max=2.0, useHeatPort=True)
        for a, b in [(self.sine.y, self.torque.tau), (self.torque.flange, self.inertia1.flange_a),
                     (self.inertia1.flange_b, self.damper.flange_b),
                     (self.damper.flange_a, self.fixed.flange),
                     (self.TAmbient.port, self.convection.fluid),
                     (self.const.y, self.convection.Gc),
                     (self.inertia1.flange_b, self.springDamper.flange_a),
                     (self.springDamper.flange_b, self.inertia2.flange_a),
                     (self.elastoBacklash.flange_a, self.inertia2.flange_b),
                     (self.elastoBacklash.flange_b, self.inertia3.flange_a),
                     (self.inertia3.flange_b, self.bearingFriction.flange_a),
                     (self.spring3.flange_b, self.inertia4.flange_a),
                     (self.bearingFriction.flange_b, self.spring3.flange_a),
                     (self.inertia4.flange_b, self.lossyGear.flange_a),
                     (self.lossyGear.flange_b, self.clutch.flange_a),
                     (self.clutch.flange_b, self.inertia5.flange_a),
                     (self.sine2.y, self.clutch.f_normalized),
                     (self.inertia5.flange_b, self.oneWayClutch.flange_a),
                     (self.oneWayClutch.flange_b, self.inertia6.flange_a),
                     (self.sine2.y, self.oneWayClutch.f_normalized),
                     (self.inertia6.flange_b, self.brake.flange_a),
                     (self.sine2.y, self.brake.f_normalized)]:
            self.connect(a, b)
        for heated in (self.damper, self.springDamper, self.elastoBacklash,
                       self.bearingFriction, self.lossyGear, self.clutch, self.oneWayClutch,
                       self.brake):
            self.connect(heated.heatPort, self.convection.solid)
