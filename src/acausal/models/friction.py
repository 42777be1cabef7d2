"""MSL's Modelica.Mechanics.Rotational.Examples.Friction: a drive train with a clutch and a
brake (Coulomb friction on state events).

    sine·step2 ─→ torque(useSupport) ── inertia3 ── clutch ── inertia2 ── spring ── brake ── inertia1
                     │ support            const ─┘ f_normalized        step ─┘ f_normalized
                   fixed ───────────────────────────────────────────────── brake.support

The torque 200·sin(100 t) N.m drives inertia3 until startTime (step2 falls from 1 to 0), when
the brake is applied (step rises from 0 to 1); the clutch is always engaged (f_normalized 1).
The experiment: StopTime 3 s, Interval 0.001 s; inertia3 starts at 100 rad/s, inertia2 and
inertia1 at 90 rad/s, all angles and the spring at 0 (``START``, for ``x0``). Coordinates
inertia3.phi, inertia2.phi, inertia1.phi.
"""
from __future__ import annotations

import math

from ..components import rotational as rot
from ..components import signals as sig
from ..core import Model

STOP_TIME, INTERVAL = 3.0, 0.001            # s, the MSL experiment
START = {"inertia3.phi": 0.0, "inertia3.w": 100.0, "inertia2.phi": 0.0, "inertia2.w": 90.0,
         "inertia1.phi": 0.0, "inertia1.w": 90.0}


class RotationalFriction(Model):
    """MSL's Rotational.Examples.Friction with its parameters: inertia3 J = 1, inertia2
    J = 0.05, inertia1 J = 1 [kg.m²]; clutch fn_max = 160 N, brake fn_max = 1600 N (mu 0.5,
    MSL's defaults); spring c = 160 N.m/rad, d = 1 N.m.s/rad; startTime [s] of both steps."""

    def __init__(self, name="Friction", startTime=0.5):
        super().__init__(name)
        self.torque = rot.Torque(useSupport=True)
        self.inertia3 = rot.Inertia(J=1.0)
        self.clutch = rot.Clutch(fn_max=160.0)
        self.inertia2 = rot.Inertia(J=0.05)
        self.spring = rot.SpringDamper(c=160.0, d=1.0)
        self.inertia1 = rot.Inertia(J=1.0)
        self.brake = rot.Brake(fn_max=1600.0, useSupport=True)
        self.const = sig.Constant(k=1.0)
        self.step = sig.Step(startTime=startTime)
        self.step2 = sig.Step(height=-1.0, offset=1.0, startTime=startTime)
        self.sine = sig.Sine(amplitude=200.0, f=50.0 / math.pi)
        self.product = sig.Product()
        self.fixed = rot.Fixed()
        for a, b in [(self.torque.flange, self.inertia3.flange_a),
                     (self.inertia3.flange_b, self.clutch.flange_a),
                     (self.clutch.flange_b, self.inertia2.flange_a),
                     (self.inertia2.flange_b, self.spring.flange_a),
                     (self.spring.flange_b, self.brake.flange_a),
                     (self.brake.flange_b, self.inertia1.flange_a),
                     (self.sine.y, self.product.u1), (self.step2.y, self.product.u2),
                     (self.product.y, self.torque.tau),
                     (self.const.y, self.clutch.f_normalized),
                     (self.step.y, self.brake.f_normalized),
                     (self.torque.support, self.fixed.flange),
                     (self.brake.support, self.fixed.flange)]:
            self.connect(a, b)
