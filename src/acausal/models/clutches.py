"""MSL's clutch examples (Modelica.Mechanics.Rotational.Examples), Coulomb friction on state
events.

CoupledClutches: four inertias J1..J4 (1 kg.m² each) in a row behind three clutches:

    sin1 ─→ torque(useSupport) ── J1 ── clutch1 ── J2 ── clutch2 ── J3 ── clutch3 ── J4
              │ support           sin2 ─┘           step1 ─┘           step2 ─┘
            fixed

The torque 10·sin(2π·5·t) N.m drives J1 (10 rad/s at the start, the others at rest);
clutch1 is pressed by sin2 = cos(2π·0.2·t) (released when it turns negative, at 1.25 s),
clutch2 from T2 = 0.4 s on, clutch3 from T3 = 0.9 s on (fn_max 20 N, peak 1.1, mu 0.5).
The experiment: StopTime 1.5 s, Interval 0.001 s. Coordinates J1.phi .. J4.phi.
"""
from __future__ import annotations

import math

from ..components import rotational as rot
from ..components import signals as sig
from ..core import Model

STOP_TIME, INTERVAL = 1.5, 0.001            # s, the MSL experiment
START = {"J1.phi": 0.0, "J1.w": 10.0, "J2.phi": 0.0, "J2.w": 0.0, "J3.phi": 0.0, "J3.w": 0.0,
         "J4.phi": 0.0, "J4.w": 0.0}


class CoupledClutches(Model):
    """MSL's Rotational.Examples.CoupledClutches ("drive train with 3 dynamically coupled
    clutches") with its parameters: f [Hz] the frequency of sin2 (clutch1's normal force),
    T2, T3 [s] the times clutch2 and clutch3 are engaged."""

    def __init__(self, name="CoupledClutches", f=0.2, T2=0.4, T3=0.9):
        super().__init__(name)
        self.torque = rot.Torque(useSupport=True)
        self.fixed = rot.Fixed()
        self.sin1 = sig.Sine(amplitude=10.0, f=5.0)
        self.sin2 = sig.Sine(amplitude=1.0, f=f, phase=math.pi / 2)
        self.step1 = sig.Step(startTime=T2)
        self.step2 = sig.Step(startTime=T3)
        for k in (1, 2, 3, 4):
            setattr(self, f"J{k}", rot.Inertia(J=1.0))
        for k in (1, 2, 3):
            setattr(self, f"clutch{k}", rot.Clutch(peak=1.1, fn_max=20.0))
        chain = [self.J1, self.clutch1, self.J2, self.clutch2, self.J3, self.clutch3, self.J4]
        self.connect(self.torque.flange, self.J1.flange_a)
        for a, b in zip(chain[:-1], chain[1:]):
            self.connect(a.flange_b, b.flange_a)
        for a, b in [(self.sin1.y, self.torque.tau), (self.sin2.y, self.clutch1.f_normalized),
                     (self.step1.y, self.clutch2.f_normalized),
                     (self.step2.y, self.clutch3.f_normalized),
                     (self.fixed.flange, self.torque.support)]:
            self.connect(a, b)
