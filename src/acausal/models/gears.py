"""MSL's Rotational examples of gear losses and backlash, with their parameters and
experiments:

- ``LossyGearDemo1``: inertia1 (J 1) driven by 10·sin(2π t) N.m, a LossyGear (ratio 2,
  efficiency 0.5 both ways, no bearing friction) and inertia2 (J 1.5) loaded by a ramp from
  −10 to −5 N.m over 2 s; the gear rolls backward, sticks, rolls forward, sticks, rolls
  backward. StopTime 0.5 s, Interval 0.001 s; all at rest at 0.
- ``LossyGearDemo2``: the same with a BearingFriction (tau_pos [[0, 0.5], [1, 1]]) between
  the drive and inertia1: both friction elements stuck at once have no unique solution
  (MSL's documentation says so): here the simulation follows the reference until that
  happens (0.3083 s) and stops there with an error naming the undetermined torques.
- ``LossyGearDemo3``: inertia1 (J 0.001, w 10 rad/s at the start), a LossyGear (ratio 1,
  lossTable [[0, 0.25, 0.25, 0.625, 2.5]]), inertia2 (J 0.001) loaded by a step of 1 N.m at
  0.5 s; the driving side is not obvious (MSL's LossyGear before 3.1 failed here). StopTime
  1 s, Interval 0.001 s.
- ``Backlash``: three inertias (J 5, at 90° and at rest) against the ground through a
  SpringDamper, an ElastoBacklash and an ElastoBacklash2 (c 20e3 N.m/rad, d 50 N.m.s/rad,
  b 45°). StopTime 1 s, Interval 0.001 s.

``START`` gives each its ``x0`` (MSL's fixed start values).
"""
from __future__ import annotations

import math

from ..components import rotational as rot
from ..components import signals as sig
from ..core import Model

STOP_TIME = {"LossyGearDemo1": 0.5, "LossyGearDemo2": 0.5, "LossyGearDemo3": 1.0,
             "Backlash": 1.0}                                # s, the MSL experiments
INTERVAL = 0.001                                             # s
START = {"LossyGearDemo1": {"Inertia2.phi": 0.0, "Inertia2.w": 0.0},
         "LossyGearDemo2": {"Inertia2.phi": 0.0, "Inertia2.w": 0.0},
         "LossyGearDemo3": {"Inertia2.phi": 0.0, "Inertia1.w": 10.0},
         "Backlash": {f"inertia{k}.{v}": x for k in (1, 2, 3)
                      for v, x in (("phi", math.pi / 2), ("w", 0.0))}}


class LossyGearDemo1(Model):
    """MSL's Rotational.Examples.LossyGearDemo1 (see the module); ``lossTable`` of the gear
    (default MSL's [[0, 0.5, 0.5, 0, 0]])."""

    def __init__(self, name="LossyGearDemo1", lossTable=((0.0, 0.5, 0.5, 0.0, 0.0),)):
        super().__init__(name)
        self.gear = rot.LossyGear(ratio=2.0, lossTable=lossTable, useSupport=True)
        self.Inertia1 = rot.Inertia(J=1.0)
        self.Inertia2 = rot.Inertia(J=1.5)
        self.torque1 = rot.Torque(useSupport=True)
        self.torque2 = rot.Torque(useSupport=True)
        self.DriveSine = sig.Sine(amplitude=10.0, f=1.0)
        self.load = sig.Ramp(height=5.0, duration=2.0, offset=-10.0)
        self.fixed = rot.Fixed()
        self._drive()
        for a, b in [(self.Inertia1.flange_b, self.gear.flange_a),
                     (self.gear.flange_b, self.Inertia2.flange_a),
                     (self.torque2.flange, self.Inertia2.flange_b),
                     (self.load.y, self.torque2.tau),
                     (self.fixed.flange, self.gear.support),
                     (self.fixed.flange, self.torque1.support),
                     (self.fixed.flange, self.torque2.support)]:
            self.connect(a, b)

    def _drive(self):
        self.connect(self.torque1.flange, self.Inertia1.flange_a)
        self.connect(self.DriveSine.y, self.torque1.tau)


class LossyGearDemo2(LossyGearDemo1):
    """MSL's Rotational.Examples.LossyGearDemo2: LossyGearDemo1 with a BearingFriction
    (useSupport, tau_pos [[0, 0.5], [1, 1]] N.m) between torque1 and Inertia1."""

    def __init__(self, name="LossyGearDemo2", lossTable=((0.0, 0.5, 0.5, 0.0, 0.0),)):
        super().__init__(name, lossTable)

    def _drive(self):
        self.bearingFriction = rot.BearingFriction(tau_pos=[[0.0, 0.5], [1.0, 1.0]],
                                                   useSupport=True)
        for a, b in [(self.torque1.flange, self.bearingFriction.flange_a),
                     (self.bearingFriction.flange_b, self.Inertia1.flange_a),
                     (self.DriveSine.y, self.torque1.tau),
                     (self.fixed.flange, self.bearingFriction.support)]:
            self.connect(a, b)


class LossyGearDemo3(Model):
    """MSL's Rotational.Examples.LossyGearDemo3 (see the module)."""

    def __init__(self, name="LossyGearDemo3"):
        super().__init__(name)
        self.gear = rot.LossyGear(ratio=1.0, lossTable=[[0.0, 0.25, 0.25, 0.625, 2.5]])
        self.Inertia1 = rot.Inertia(J=0.001)
        self.Inertia2 = rot.Inertia(J=0.001)
        self.torque1, self.torque2 = rot.Torque(), rot.Torque()
        self.step = sig.Step(height=0.0)
        self.step1 = sig.Step(startTime=0.5, height=1.0, offset=0.0)
        for a, b in [(self.Inertia1.flange_b, self.gear.flange_a),
                     (self.torque1.flange, self.Inertia1.flange_a),
                     (self.step.y, self.torque1.tau),
                     (self.gear.flange_b, self.Inertia2.flange_a),
                     (self.Inertia2.flange_b, self.torque2.flange),
                     (self.step1.y, self.torque2.tau)]:
            self.connect(a, b)


class Backlash(Model):
    """MSL's Rotational.Examples.Backlash (see the module): inertia1 on a SpringDamper,
    inertia2 on an ElastoBacklash, inertia3 on an ElastoBacklash2, each from the ground."""

    def __init__(self, name="Backlash"):
        super().__init__(name)
        law = dict(c=20e3, d=50.0)
        self.springDamper = rot.SpringDamper(**law)
        self.elastoBacklash = rot.ElastoBacklash(b=math.pi / 4, **law)
        self.elastoBacklash2 = rot.ElastoBacklash2(b=math.pi / 4, **law)
        for k, element in enumerate((self.springDamper, self.elastoBacklash,
                                     self.elastoBacklash2), start=1):
            fixed, inertia = rot.Fixed(), rot.Inertia(J=5.0)
            setattr(self, f"fixed{k}", fixed)
            setattr(self, f"inertia{k}", inertia)
            self.connect(fixed.flange, element.flange_a)
            self.connect(element.flange_b, inertia.flange_a)
