"""MSL MultiBody's rolling examples rebuilt line by line (component names, parameters,
connections): ``Examples.Elementary.RollingWheel``, ``RollingWheelSetDriving`` and
``RollingWheelSetPulling``. Their start values (MSL's x(start=...), der_angles(start=...),
fixed) are the dicts ``*_START``, to pass as ``x0``.
"""
from __future__ import annotations

from ..components.multibody import (Body, FixedTranslation, RollingWheel, RollingWheelSet,
                                    World)
from ..components.multibody.forces import WorldForce
from ..components.rotational import Torque2
from ..components.signals import CombiTimeTable, Sine
from ..core import Model

ROLLING_WHEEL_START = {"wheel1.x": 0.2, "wheel1.y": 0.2, "wheel1.der_angles[1]": 0.0,
                       "wheel1.der_angles[2]": 5.0, "wheel1.der_angles[3]": 1.0}
WHEEL_SET_START = {"wheelSet.x": 0.1, "wheelSet.y": 0.1}


class RollingWheelExample(Model):
    """Examples.Elementary.RollingWheel: a RollingWheel (radius 0.3 m, m = 2 kg, I_axis =
    0.06, I_long = 0.12 kg.m²) starting at x = y = 0.2 m with der_angles = {0, 5, 1} rad/s
    (``ROLLING_WHEEL_START``), gravity along −z."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "RollingWheel")
        self.wheel1 = RollingWheel(radius=0.3, m=2, I_axis=0.06, I_long=0.12,
                                   hollowFraction=0.6)
        self.world = World(n=(0, 0, -1))


class _WheelSetVehicle(Model):
    """The wheel set (R_wheel 0.1 m, m_wheel 0.5 kg, I_wheelAxis 0.01, I_wheelLong 0.02
    kg.m², track 0.5 m) with a body (m = 0.01 kg) 0.2 m ahead of frameMiddle."""

    def __init__(self, name):
        super().__init__(name)
        self.world = World(n=(0, 0, -1))
        self.wheelSet = RollingWheelSet(R_wheel=0.1, m_wheel=0.5, I_wheelAxis=0.01,
                                        I_wheelLong=0.02, track=0.5)
        self.body = Body(m=0.01, r_CM=(0, 0, 0), animation=False)
        self.fixedTranslation = FixedTranslation(r=(0.2, 0, 0))
        self.connect(self.fixedTranslation.frame_a, self.wheelSet.frameMiddle)
        self.connect(self.fixedTranslation.frame_b, self.body.frame_a)


class RollingWheelSetDriving(_WheelSetVehicle):
    """Examples.Elementary.RollingWheelSetDriving: the wheels driven by Torque2s between
    their axes and the support, 2·sin(2πt) and 2·sin(2πt + π/2) N.m; starts at rest at
    x = y = 0.1 m (``WHEEL_SET_START``)."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "RollingWheelSetDriving")
        self.sine1 = Sine(f=1, amplitude=2)
        self.sine2 = Sine(f=1, amplitude=2, phase=1.5707963267949)
        self.torque1, self.torque2 = Torque2(), Torque2()
        self.connect(self.wheelSet.axis1, self.torque1.flange_a)
        self.connect(self.torque1.flange_b, self.wheelSet.support)
        self.connect(self.wheelSet.axis2, self.torque2.flange_a)
        self.connect(self.wheelSet.support, self.torque2.flange_b)
        self.connect(self.sine1.y, self.torque1.tau)
        self.connect(self.sine2.y, self.torque2.tau)


class RollingWheelSetPulling(_WheelSetVehicle):
    """Examples.Elementary.RollingWheelSetPulling: a WorldForce from a CombiTimeTable
    ([0, 1, 0, 0; 1, 1, 0, 0; 2, 0, 2, 0; 3, 0, 2, 0] N) pulls at the body; starts at rest
    at x = y = 0.1 m (``WHEEL_SET_START``)."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "RollingWheelSetPulling")
        self.force = WorldForce()
        self.combiTimeTable = CombiTimeTable(table=[[0, 1, 0, 0], [1, 1, 0, 0], [2, 0, 2, 0],
                                                    [3, 0, 2, 0]])
        for k in (1, 2, 3):
            self.connect(self.combiTimeTable.y[k], self.force.force[k])
        self.connect(self.force.frame_b, self.fixedTranslation.frame_b)
