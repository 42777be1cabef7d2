"""MSL's clutch examples (Modelica.Mechanics.Rotational.Examples), Coulomb friction on state
events.

CoupledClutches: four inertias J1..J4 (1 kg.m² each) in a row behind three clutches:

    sin1 ─→ torque(useSupport) ── J1 ── clutch1 ── J2 ── clutch2 ── J3 ── clutch3 ── J4
              │ support           sin2 ─┘           step1 ─┘           step2 ─┘
            fixed

The torque 10·sin(2π·5·t) N.m drives J1 (10 rad/s at the start, the others at rest);
clutch1 is pressed by sin2 = cos(2π·0.2·t) (released when it turns negative, at 1.25 s),
clutch2 from T2 = 0.4 s on, clutch3 from T3 = 0.9 s on (fn_max 20 N, peak 1.1, mu 0.5).
The experiment: StopTime 1.5 s, Interval 0.001 s (``STOP_TIME``, ``INTERVAL``; ``START``
for ``x0``). Coordinates J1.phi .. J4.phi.

OneWayClutchDrive (MSL's Examples.OneWayClutch) and OneWayClutchDisengaged: a sine torque
drives inertiaIn, which drives inertiaOut through a one-way clutch (1 kg.m² each, peak 25,
fn_max 3 N, mu 0.5):

    signalTorque ─→ torque ── inertiaIn ── oneWayClutch ── inertiaOut ( ── torqueLoad)
                                 signalEngagement ─┘ f_normalized

OneWayClutchDrive: torque 10·sin(2π·3·t) N.m, the clutch engaged by a pulse (1 for 0.65 s of
every 1.3 s from 0.3 s on). OneWayClutchDisengaged: torque 0.3 + 10·sin(2π·2·t) N.m against
a load of −0.3 N.m on inertiaOut, the clutch never engaged (a freewheel). Both experiments:
StopTime 2 s, Interval 0.001 s; inertiaIn at −0.5 rad/s, inertiaOut at rest (``ONE_WAY_START``).
"""
from __future__ import annotations

import math

from ..components import rotational as rot
from ..components import signals as sig
from ..core import Model

STOP_TIME, INTERVAL = 1.5, 0.001            # s, the MSL experiment
ONE_WAY_STOP_TIME = 2.0                   # s, both one-way clutch experiments
ONE_WAY_START = {"inertiaIn.phi": 0.0, "inertiaIn.w": -0.5, "inertiaOut.phi": 0.0,
                 "inertiaOut.w": 0.0}
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


class _OneWayClutchDrive(Model):
    """inertiaIn (driven by signalTorque) ── oneWayClutch ── inertiaOut, the clutch pressed by
    signalEngagement (the two MSL examples' common part)."""

    def __init__(self, name, signalTorque, signalEngagement):
        super().__init__(name)
        self.torque = rot.Torque()
        self.inertiaIn = rot.Inertia(J=1.0)
        self.oneWayClutch = rot.OneWayClutch(peak=25.0, fn_max=3.0)
        self.inertiaOut = rot.Inertia(J=1.0)
        self.signalTorque, self.signalEngagement = signalTorque, signalEngagement
        for a, b in [(self.torque.flange, self.inertiaIn.flange_a),
                     (self.inertiaIn.flange_b, self.oneWayClutch.flange_a),
                     (self.oneWayClutch.flange_b, self.inertiaOut.flange_a),
                     (self.signalTorque.y, self.torque.tau),
                     (self.signalEngagement.y, self.oneWayClutch.f_normalized)]:
            self.connect(a, b)


class OneWayClutchDrive(_OneWayClutchDrive):
    """MSL's Rotational.Examples.OneWayClutch ("drive train with actively engaged one-way
    clutch")."""

    def __init__(self, name="OneWayClutch"):
        super().__init__(name, sig.Sine(amplitude=10.0, f=3.0),
                         sig.Pulse(amplitude=1.0, width=50.0, period=1.3, startTime=0.3))


class OneWayClutchDisengaged(_OneWayClutchDrive):
    """MSL's Rotational.Examples.OneWayClutchDisengaged ("drive train with disengaged
    one-way clutch"): a load torque tau_constant [N.m] on inertiaOut, offset by the drive."""

    def __init__(self, name="OneWayClutchDisengaged", tau_constant=-0.3):
        super().__init__(name, sig.Sine(amplitude=10.0, offset=-tau_constant, f=2.0),
                         sig.Constant(k=0.0))
        self.torqueLoad = rot.ConstantTorque(tau_constant=tau_constant)
        self.connect(self.inertiaOut.flange_b, self.torqueLoad.flange)
