"""MSL's Modelica.Mechanics.Rotational.Examples.ElasticBearing: a gearbox whose housing is not
fixed to the ground but held by a stiff spring-damper, so that the housing's small motion
(a relative angle of ~4e-4 rad) can be examined.

    ramp ─→ torque(useSupport) ── shaft ── idealGear(ratio 3, useSupport) ── spring ── load
                 │ support                        │ support
               fixed ── springDamper ── multiSensor ── housing

The experiment: StopTime 10 s, Interval 0.01 s, MSL's default Tolerance 1e-6; every state
starts at 0 (shaft.phi, shaft.w, load.w, spring.phi_rel, springDamper.phi_rel and w_rel
fixed at 0). The housing's angle is springDamper.phi_rel (flange_a is fixed) and carries
its nominal phi_nominal = 1e-4 rad; the example gives springDamper.w_rel the nominal 1e-4
rad/s (``nominal={"w_rel": 1e-4}``, MSL's ``w_rel(nominal=1e-4)``). Coordinates shaft.phi,
load.phi, housing.phi.
"""
from __future__ import annotations

from ..components import rotational as rot
from ..components import signals as sig
from ..core import Model

STOP_TIME = 10.0        # s, the MSL experiment
TOLERANCE = 1e-6        # MSL's default experiment tolerance (the example gives none)


class ElasticBearing(Model):
    """MSL's ElasticBearing with its parameters: shaft J = 1, load J = 50, housing J = 5
    [kg.m²]; spring c = 1e3 N.m/rad; springDamper c = 1e5 N.m/rad, d = 5 N.m.s/rad; gear
    ratio 3; the torque a ramp to 100 N.m over 5 s."""

    def __init__(self, name="ElasticBearing"):
        super().__init__(name)
        self.shaft = rot.Inertia(J=1.0)
        self.load = rot.Inertia(J=50.0)
        self.spring = rot.Spring(c=1e3)
        self.fixed = rot.Fixed()
        self.springDamper = rot.SpringDamper(c=1e5, d=5.0, nominal={"w_rel": 1e-4})
        self.torque = rot.Torque(useSupport=True)
        self.ramp = sig.Ramp(duration=5.0, height=100.0)
        self.idealGear = rot.IdealGear(ratio=3.0, useSupport=True)
        self.housing = rot.Inertia(J=5.0)
        self.multiSensor = rot.MultiSensor()
        for a, b in [(self.torque.flange, self.shaft.flange_a),
                     (self.spring.flange_b, self.load.flange_a),
                     (self.springDamper.flange_a, self.fixed.flange),
                     (self.shaft.flange_b, self.idealGear.flange_a),
                     (self.idealGear.flange_b, self.spring.flange_a),
                     (self.idealGear.support, self.housing.flange_b),
                     (self.ramp.y, self.torque.tau),
                     (self.fixed.flange, self.torque.support),
                     (self.housing.flange_a, self.multiSensor.flange_b),
                     (self.multiSensor.flange_a, self.springDamper.flange_b)]:
            self.connect(a, b)
