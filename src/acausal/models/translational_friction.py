"""MSL's Modelica.Mechanics.Translational.Examples Brake, Friction and PreLoad (friction,
stops and gaps on state events), with MSL's parameters; each class's ``START`` gives its
initial values for ``x0`` and ``STOP_TIME``, ``INTERVAL`` its experiment.

    TranslationalBrake      two masses at 1 m/s braked from t = 0.1 s (one brake grounded
                            implicitly, one through its support), at rest from 1.1 s
    TranslationalFriction   1) MassWithStopAndFriction and 3) Mass + SupportFriction (the same
                            Stribeck characteristic as a table) driven by 25·sin(2π·0.25·t) N;
                            2) MassWithStopAndFriction at −5 m/s on a spring against its stops
    PreLoad                 a valve spool preloaded by one spring through four ElastoGaps,
                            driven by 150·sin(2π·0.01·t) N
"""
from __future__ import annotations

import math

from ..components import signals as sig
from ..components import translational as tr
from ..core import Model


class TranslationalBrake(Model):
    """MSL's Translational.Examples.Brake: mass1, mass2 (m = 1 kg, v = 1 m/s at t = 0); brake
    (fn_max = 1 N, no support) and brake1 (fn_max = 1 N, support fixed), mu = 0.5 (MSL's
    default); step(startTime = 0.1 s, height 2) feeds both f_normalized. Coordinates
    mass1.s, mass2.s."""
    STOP_TIME, INTERVAL = 2.0, 0.001
    START = {"mass1.s": 0.0, "mass1.v": 1.0, "mass2.s": 0.0, "mass2.v": 1.0}

    def __init__(self, name="Brake"):
        super().__init__(name)
        self.brake = tr.Brake(fn_max=1.0)
        self.mass1 = tr.Mass(m=1.0)
        self.step = sig.Step(startTime=0.1, height=2.0)
        self.brake1 = tr.Brake(fn_max=1.0, useSupport=True)
        self.mass2 = tr.Mass(m=1.0)
        self.fixed = tr.Fixed()
        for a, b in [(self.mass1.flange_b, self.brake.flange_a),
                     (self.step.y, self.brake.f_normalized),
                     (self.mass2.flange_b, self.brake1.flange_a),
                     (self.step.y, self.brake1.f_normalized),
                     (self.fixed.flange, self.brake1.support)]:
            self.connect(a, b)


def stribeck_table(F_prop, F_Coulomb, F_Stribeck, fexp, v_max, nTable=100):
    """MSL's Examples.Utilities.GenerateStribeckFrictionTable: rows [v, F_Coulomb + F_prop·v
    + F_Stribeck·exp(−fexp·v)] at nTable speeds v from 0 to v_max [m/s]."""
    rows = []
    for i in range(nTable):
        v = v_max * i / (nTable - 1)
        rows.append((v, F_Coulomb + F_prop * v + F_Stribeck * math.exp(-fexp * v)))
    return rows


class TranslationalFriction(Model):
    """MSL's Translational.Examples.Friction ("Use of model Stop"):

    1) stop1 (MassWithStopAndFriction: L = 1 m, smax = 25, smin = −25 m, m = 1 kg, F_prop =
       1 N.s/m, F_Coulomb = 5 N, F_Stribeck = 10 N, fexp = 2 s/m) pushed by force =
       sineForce (25·sin(2π·0.25·t) N);
    2) stop2 (L = 1 m, smax = 0.9, smin = −0.9 m, F_Coulomb = 3 N, F_Stribeck = 5 N, m = 1 kg,
       F_prop = 1 N.s/m, fexp = 2 s/m; s = 0, v = −5 m/s at t = 0) on spring (c = 500 N/m,
       s_rel0 = 1 m) from fixed2 (s0 = −1.75 m);
    3) mass (m = 1 kg, L = 1 m) on supportFriction with stop1's characteristic as a table
       (``stribeck_table``, v_max = 12 m/s, 50 rows), pushed by force2 = sineForce.
    Coordinates stop1.s, stop2.s, mass.s."""
    STOP_TIME, INTERVAL = 5.0, 0.001
    START = {"stop1.s": 0.0, "stop1.v": 0.0, "stop2.s": 0.0, "stop2.v": -5.0,
             "mass.s": 0.0, "mass.v": 0.0}

    def __init__(self, name="Friction"):
        super().__init__(name)
        self.stop1 = tr.MassWithStopAndFriction(L=1.0, smax=25.0, smin=-25.0, m=1.0,
                                                F_prop=1.0, F_Coulomb=5.0, F_Stribeck=10.0,
                                                fexp=2.0)
        self.force = tr.Force()
        self.sineForce = sig.Sine(amplitude=25.0, f=0.25)
        self.stop2 = tr.MassWithStopAndFriction(L=1.0, smax=0.9, smin=-0.9, F_Coulomb=3.0,
                                                F_Stribeck=5.0, m=1.0, F_prop=1.0, fexp=2.0)
        self.spring = tr.Spring(s_rel0=1.0, c=500.0)
        self.fixed2 = tr.Fixed(s0=-1.75)
        self.force2 = tr.Force()
        self.mass = tr.Mass(m=1.0, L=1.0)
        self.supportFriction = tr.SupportFriction(f_pos=stribeck_table(
            F_prop=1.0, F_Coulomb=5.0, F_Stribeck=10.0, fexp=2.0, v_max=12.0, nTable=50))
        for a, b in [(self.spring.flange_b, self.stop2.flange_a),
                     (self.sineForce.y, self.force.f),
                     (self.spring.flange_a, self.fixed2.flange),
                     (self.force.flange, self.stop1.flange_a),
                     (self.force2.flange, self.mass.flange_a),
                     (self.mass.flange_b, self.supportFriction.flange_a),
                     (self.sineForce.y, self.force2.f)]:
            self.connect(a, b)


class PreLoad(Model):
    """MSL's Translational.Examples.PreLoad: a valve spool (m = 0.15 kg, L = 0.19 m) held in
    place by one preloaded spring (c = 20e3 N/m, s_rel0 = 0.025 m) between two spring plates
    (m = 10 g, L = 2 mm) through four ElastoGaps (inner contacts: c = 1e6 N/m, d = 250 N.s/m,
    s_rel0 = 1 mm; outer contacts: s_rel0 = 1.5 mm), rods for the geometry, viscous friction
    (a Damper, d = 2500 N.s/m) and the force 150·sin(2π·0.01·t) N on the spool. Coordinates
    spool.s, springPlateA.s, springPlateB.s."""
    STOP_TIME, INTERVAL = 100.0, 0.1
    START = {"spool.s": 0.01475, "spool.v": 0.0, "springPlateA.s": -0.093,
             "springPlateA.v": 0.0, "springPlateB.s": -0.06925, "springPlateB.v": 0.0}

    def __init__(self, name="PreLoad"):
        super().__init__(name)
        inner = dict(c=1000e3, d=250.0, s_rel0=0.001)
        outer = dict(c=1000e3, d=250.0, s_rel0=0.0015)
        self.innerContactA, self.innerContactB = tr.ElastoGap(**inner), tr.ElastoGap(**inner)
        self.spool = tr.Mass(L=0.19, m=0.150)
        self.fixedLe = tr.Fixed(s0=-0.0955)
        self.springPlateA = tr.Mass(m=10e-3, L=0.002)
        self.springPlateB = tr.Mass(m=10e-3, L=0.002)
        self.spring = tr.Spring(c=20e3, s_rel0=0.025)
        self.outerContactA, self.outerContactB = tr.ElastoGap(**outer), tr.ElastoGap(**outer)
        self.rod1 = tr.Rod(L=0.007)
        self.friction = tr.Damper(d=2500.0)
        self.force = tr.Force()
        self.housing = tr.Rod(L=0.0305)
        self.rod3 = tr.Rod(L=0.00575)
        self.rod4 = tr.Rod(L=0.00575)
        self.rod2 = tr.Rod(L=0.007)
        self.sineForce = sig.Sine(amplitude=150.0, f=0.01)
        for a, b in [(self.outerContactA.flange_b, self.springPlateA.flange_a),
                     (self.springPlateA.flange_b, self.spring.flange_a),
                     (self.spring.flange_b, self.springPlateB.flange_a),
                     (self.springPlateB.flange_b, self.outerContactB.flange_a),
                     (self.outerContactB.flange_b, self.housing.flange_b),
                     (self.springPlateA.flange_b, self.rod1.flange_a),
                     (self.innerContactA.flange_a, self.rod3.flange_a),
                     (self.innerContactA.flange_b, self.rod1.flange_b),
                     (self.rod2.flange_a, self.innerContactB.flange_a),
                     (self.rod4.flange_b, self.innerContactB.flange_b),
                     (self.friction.flange_b, self.rod3.flange_a),
                     (self.rod3.flange_b, self.rod4.flange_a),
                     (self.rod2.flange_b, self.springPlateB.flange_a),
                     (self.spool.flange_a, self.rod4.flange_a),
                     (self.sineForce.y, self.force.f),
                     (self.force.flange, self.spool.flange_a),
                     (self.outerContactA.flange_a, self.fixedLe.flange),
                     (self.housing.flange_a, self.fixedLe.flange),
                     (self.friction.flange_a, self.fixedLe.flange)]:
            self.connect(a, b)
