"""MSL MultiBody examples with forces, 1-D springs and drive trains, rebuilt line by line
(component names, parameters, connections as in the MSL):
``Examples.Elementary.ForceAndTorque``, ``SpringMassSystem`` and
``Examples.Rotational3DEffects.MovingActuatedDrive``. MSL's visualization parameters
(widths, diameters, colors) are left out; the World's defaults apply.
"""
from __future__ import annotations

from ..components import rotational, signals, translational
from ..components.multibody import (Body, BodyCylinder, BodyShape, Fixed, FixedRotation,
                                    FixedTranslation, Mounting1D, Prismatic, Revolute,
                                    Rotor1D, World)
from ..components.multibody import forces
from ..components.multibody.resolving import ResolveInFrameAB
from ..core import Model

__all__ = ["ForceAndTorqueExample", "SpringMassSystem", "MovingActuatedDrive"]


class ForceAndTorqueExample(Model):
    """Elementary.ForceAndTorque: a BodyCylinder (r = {1, 0, 0} m, steel) on two revolutes
    (z, then y) pulled by a ForceAndTorque element towards a point fixed at {1.5, 0.25, 0}:
    constant force {0, 1000, 0} N and torque {-100, 100, 0} N.m resolved in a frame rotated
    by 30° about z (frame_resolve). Starts at rest, every joint at 0."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "ForceAndTorque")
        self.world = World(animateGravity=False)
        self.body = BodyCylinder(r=(1, 0, 0))
        self.fixed1 = Fixed(r=(0, -0.5, 0))
        self.fixedRotation = FixedRotation(n=(0, 0, 1), angle=30)
        self.forceAndTorque = forces.ForceAndTorque(
            resolveInFrame=ResolveInFrameAB.frame_resolve)
        self.revolute2 = Revolute(n=(0, 1, 0))
        self.revolute1 = Revolute()
        self.fixed2 = Fixed(r=(1.5, 0.25, 0))
        for k, (tk, fk) in enumerate(zip((-100, 100, 0), (0, 1000, 0)), start=1):
            setattr(self, f"torque{k}", signals.Constant(k=tk))
            setattr(self, f"force{k}", signals.Constant(k=fk))
            self.connect(getattr(self, f"force{k}").y, self.forceAndTorque.force[k])
            self.connect(getattr(self, f"torque{k}").y, self.forceAndTorque.torque[k])
        self.connect(self.revolute2.frame_b, self.body.frame_a)
        self.connect(self.forceAndTorque.frame_b, self.body.frame_b)
        self.connect(self.fixed1.frame_b, self.revolute1.frame_a)
        self.connect(self.revolute1.frame_b, self.revolute2.frame_a)
        self.connect(self.fixed2.frame_b, self.forceAndTorque.frame_a)
        self.connect(self.fixedRotation.frame_a, self.fixed1.frame_b)
        self.connect(self.forceAndTorque.frame_resolve, self.fixedRotation.frame_b)


class SpringMassSystem(Model):
    """Elementary.SpringMassSystem: two bodies (m = 1 kg) hanging on prismatic joints along
    −y, one held by a Translational Spring between the joint's support and axis (c = 30
    N/m, s_rel0 = 0.1 m), the other by a MultiBody Spring (c = 30 N/m, s_unstretched = 0.1
    m) between the mount and the body. Both start at s = 0.1 m, at rest:
    x0 = {"p1.s": 0.1, "p2.s": 0.1}."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "SpringMassSystem")
        self.world = World()
        self.p1 = Prismatic(useAxisFlange=True, n=(0, -1, 0))
        self.spring1 = translational.Spring(c=30, s_rel0=0.1)
        self.body1 = Body(m=1, r_CM=(0, 0, 0))
        self.bar1 = FixedTranslation(r=(0.3, 0, 0))
        self.bar2 = FixedTranslation(r=(0.3, 0, 0))
        self.body2 = Body(m=1, r_CM=(0, 0, 0))
        self.p2 = Prismatic(useAxisFlange=True, n=(0, -1, 0))
        self.spring2 = forces.Spring(c=30, s_unstretched=0.1)
        self.connect(self.body1.frame_a, self.p1.frame_b)
        self.connect(self.world.frame_b, self.bar1.frame_a)
        self.connect(self.bar1.frame_b, self.p1.frame_a)
        self.connect(self.spring1.flange_b, self.p1.axis)
        self.connect(self.bar1.frame_b, self.bar2.frame_a)
        self.connect(self.bar2.frame_b, self.p2.frame_a)
        self.connect(self.p2.frame_b, self.body2.frame_a)
        self.connect(self.bar2.frame_b, self.spring2.frame_a)
        self.connect(self.p1.support, self.spring1.flange_a)
        self.connect(self.body2.frame_a, self.spring2.frame_b)


class MovingActuatedDrive(Model):
    """Rotational3DEffects.MovingActuatedDrive (no gravity): the same drive twice, on frames
    turned about y by position-controlled revolutes (r1, r2: 2·sin(2π·t) rad through
    Rotational Position sources whose supports sit on Mounting1Ds): once as a Revolute about
    x with a BodyShape (I_11 = 2 kg.m², massless) driven by a 3-D Torque
    {sin(2π·t), 0, 0} N.m, once as a Rotor1D (J = 2 kg.m²) driven by a Rotational Torque
    whose support is on a Mounting1D on the same frame. revolute.phi = rotor1D.phi."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "MovingActuatedDrive")
        self.bodyCylinder = BodyShape(r=(0.5, 0, 0), m=0, I_11=2, I_22=0, I_33=0,
                                      r_CM=(0, 0, 0))
        self.revolute = Revolute(n=(1, 0, 0))
        self.world = World(g=0, driveTrainMechanics3D=True)
        self.torque = forces.Torque()
        self.rotor1D = Rotor1D(J=2)
        self.torque1 = rotational.Torque(useSupport=True)
        self.mounting1D = Mounting1D()
        self.r1 = Revolute(useAxisFlange=True, n=(0, 1, 0))
        self.position1 = rotational.Position(useSupport=True)
        self.sine2 = signals.Sine(amplitude=2, f=1)
        self.mounting1D1 = Mounting1D(n=(0, 1, 0))
        self.r2 = Revolute(useAxisFlange=True, n=(0, 1, 0))
        self.position2 = rotational.Position(useSupport=True)
        self.mounting1D2 = Mounting1D(n=(0, 1, 0))
        self.fixed = Fixed()
        for k, amplitude in enumerate((1, 0, 0), start=1):
            setattr(self, f"sine1_{k}", signals.Sine(amplitude=amplitude, f=1))
            self.connect(getattr(self, f"sine1_{k}").y, self.torque.torque[k])
        self.connect(self.revolute.frame_b, self.bodyCylinder.frame_a)
        self.connect(self.torque.frame_b, self.bodyCylinder.frame_b)
        self.connect(self.torque1.flange, self.rotor1D.flange_a)
        self.connect(self.mounting1D.flange_b, self.torque1.support)
        self.connect(self.r1.frame_a, self.world.frame_b)
        self.connect(self.position1.flange, self.r1.axis)
        self.connect(self.position1.support, self.mounting1D1.flange_b)
        self.connect(self.mounting1D1.frame_a, self.world.frame_b)
        self.connect(self.sine2.y, self.position1.phi_ref)
        self.connect(self.r1.frame_b, self.revolute.frame_a)
        self.connect(self.torque.frame_a, self.revolute.frame_a)
        self.connect(self.position2.flange, self.r2.axis)
        self.connect(self.position2.support, self.mounting1D2.flange_b)
        self.connect(self.fixed.frame_b, self.r2.frame_a)
        self.connect(self.fixed.frame_b, self.mounting1D2.frame_a)
        self.connect(self.sine2.y, self.position2.phi_ref)
        self.connect(self.r2.frame_b, self.rotor1D.frame_a)
        self.connect(self.r2.frame_b, self.mounting1D.frame_a)
        self.connect(self.sine1_1.y, self.torque1.tau)
