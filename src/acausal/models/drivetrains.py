"""A drivetrain: DC motor -> gearbox -> elastic shaft -> fan drum, with a load torque step.

    Ramp (0 -> 100 V in 0.5 s) --> DCMotor --> IdealGear (ratio) --> TorqueSensor
        --> SpringDamper (elastic shaft) --> Inertia (drum) <-- QuadraticSpeedDependentTorque (fan)
                                                            <-- TorqueStep (extra load at 2.5 s)
    SpeedSensor on the drum

Written as one would draw it in Modelica.Mechanics.Rotational (same names, parameters and
sign conventions). The motor has MSL's DC_PermanentMagnet data (100 V, 100 A nominal).
"""
from __future__ import annotations

from ..components.rotational import (DCMotor, IdealGear, Inertia, QuadraticSpeedDependentTorque,
                                     SpeedSensor, SpringDamper, TorqueSensor, TorqueStep)
from ..components.signals import Ramp
from ..core import Model

VOLTAGE, RAMP_TIME = 100.0, 0.5         # V, s: the armature voltage ramps up to VOLTAGE
RATIO = 10.0                            # gear ratio motor/drum
J_DRUM = 20.0                           # kg.m²
C_SHAFT, D_SHAFT = 2.0e4, 40.0          # N.m/rad, N.m.s/rad
FAN_TAU, FAN_W = -500.0, 14.0           # fan load: tau = FAN_TAU·(w/FAN_W)² [N.m], w [rad/s]
STEP_TAU, STEP_TIME = -150.0, 2.5       # extra load torque [N.m] from STEP_TIME [s]


class Drivetrain(Model):
    """DC motor (``motor``, state ``motor.i`` [A]) driving the drum (``drum``, J_DRUM) through
    the gear (``gear.ratio``, RATIO) and the elastic shaft (``shaft``: C_SHAFT, D_SHAFT); the
    fan and the extra load act on the drum; ``shaftTorque.tau`` [N.m] and ``drumSpeed.w``
    [rad/s] are measured. No inputs: the supply is the Ramp ``supply`` [V]."""

    def __init__(self, name="drivetrain"):
        super().__init__(name)
        self.supply = Ramp(height=VOLTAGE, duration=RAMP_TIME)
        self.motor = DCMotor()
        self.gear = IdealGear(ratio=RATIO)
        self.shaftTorque = TorqueSensor()
        self.shaft = SpringDamper(c=C_SHAFT, d=D_SHAFT)
        self.drum = Inertia(J=J_DRUM)
        self.fan = QuadraticSpeedDependentTorque(tau_nominal=FAN_TAU, w_nominal=FAN_W)
        self.extraLoad = TorqueStep(stepTorque=STEP_TAU, startTime=STEP_TIME)
        self.drumSpeed = SpeedSensor()
        for a, b in [(self.supply.y, self.motor.v), (self.motor.flange, self.gear.flange_a),
                     (self.gear.flange_b, self.shaftTorque.flange_a),
                     (self.shaftTorque.flange_b, self.shaft.flange_a),
                     (self.shaft.flange_b, self.drum.flange_a),
                     (self.fan.flange, self.drum.flange_b),
                     (self.extraLoad.flange, self.drum.flange_b),
                     (self.drumSpeed.flange, self.drum.flange_b)]:
            self.connect(a, b)
