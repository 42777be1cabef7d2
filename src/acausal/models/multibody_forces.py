"""MSL MultiBody examples with forces, 1-D springs and drive trains, rebuilt line by line
(component names, parameters, connections as in the MSL):
``Examples.Elementary.ForceAndTorque``, ``SpringMassSystem``, ``PointGravity``,
``ThreeSprings`` and ``Examples.Rotational3DEffects.MovingActuatedDrive``,
``GyroscopicEffects``. Free bodies and spherical joints (not in the library yet) are
written as chains of prismatic and revolute joints that move the same (see each model).
MSL's visualization parameters (widths, diameters, colors) are left out; the World's
defaults apply.
"""
from __future__ import annotations

import casadi as ca

from ..components import rotational, signals, translational
from ..components.multibody import (Body, BodyCylinder, BodyShape, Fixed, FixedRotation,
                                    FixedTranslation, Mounting1D, Prismatic, Revolute,
                                    Rotor1D, World)
from ..components.multibody import forces
from ..components.multibody.resolving import ResolveInFrameAB
from ..core import Model

__all__ = ["ForceAndTorqueExample", "SpringMassSystem", "MovingActuatedDrive", "PointGravity",
           "ThreeSprings", "GyroscopicEffects"]


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


def _translations(model: Model, prefix: str, frame_a, axes=((1, 0, 0), (0, 1, 0), (0, 0, 1))):
    """Prismatic joints ``<prefix>x``, ``<prefix>y``, ``<prefix>z`` in series from
    ``frame_a`` along the world axes; returns the last frame_b (world orientation)."""
    for axis, n in zip("xyz", axes):
        joint = Prismatic(n=n)
        setattr(model, f"{prefix}{axis}", joint)
        model.connect(frame_a, joint.frame_a)
        frame_a = joint.frame_b
    return frame_a


class PointGravity(Model):
    """Elementary.PointGravity: two bodies (m = 1 kg, I = 0.1·1 kg.m², centre of mass at
    frame_a) in the point gravity field of the World (mu = 1 m³/s²), starting at
    r_0 = {0, 0.6, 0} m with v_0 = {1, 0, 0} m/s (a circle) and at {0.6, 0.6, 0} m with
    {0.6, 0, 0} m/s (an ellipse), at rest in rotation.

    MSL's bodies are free (6 degrees of freedom); here each hangs from the world on three
    prismatic joints (``body1_x`` .. ``body1_z``), which keep its orientation: the same
    motion, exactly, since gravity acts at the centre of mass (no torque) and the bodies
    start without angular velocity. x0 = ``START``."""
    START = {"body1_x.s": 0.0, "body1_y.s": 0.6, "body1_x.v": 1.0,
             "body2_x.s": 0.6, "body2_y.s": 0.6, "body2_x.v": 0.6}

    def __init__(self, name: str | None = None):
        super().__init__(name or "PointGravity")
        from ..components.multibody import GravityTypes
        self.world = World(mu=1, gravityType=GravityTypes.PointGravity)
        for k in (1, 2):
            body = Body(m=1, I_11=0.1, I_22=0.1, I_33=0.1, r_CM=(0, 0, 0))
            setattr(self, f"body{k}", body)
            self.connect(_translations(self, f"body{k}_", self.world.frame_b), body.frame_a)


class ThreeSprings(Model):
    """Elementary.ThreeSprings: a body (m = 0.8 kg, r_CM = {0, -0.2, 0} m, I = 0.1·1
    kg.m²) hanging under gravity from three 3-D Springs connected in series and parallel
    without mass at their junction: spring1 (c = 20 N/m) from bar1 ({0.3, 0, 0}) and
    spring3 (c = 20 N/m) from bar2 ({0, 0, 0.3}) to the junction, spring2 (c = 40 N/m) from
    the junction to the body; unstretched lengths 0.1 m. The body starts at r_0 = {0.5,
    -0.3, 0} m at rest, its frame parallel to the world's.

    The junction's orientation is fixed by spring3's fixedRotationAtFrame_b, as in MSL (its
    position spring3.r_b_0 is then algebraic: no mass, the spring forces in balance). MSL's
    body is free; here it hangs from the world on three prismatic joints (``body_x`` ..
    ``body_z``) and three revolutes about x, y, z (``body_rx`` .. ``body_rz``: MSL's angles
    sequence {1, 2, 3} as coordinates, singular only at a ±90° second angle), which move
    the same. x0 = ``START``, guess = ``GUESS`` (MSL's guess of the junction, {0.1, -0.2,
    0.2} m)."""
    START = {"body_x.s": 0.5, "body_y.s": -0.3}
    GUESS = {"spring3.r_b_0[1]": 0.1, "spring3.r_b_0[2]": -0.2, "spring3.r_b_0[3]": 0.2}

    def __init__(self, name: str | None = None):
        super().__init__(name or "ThreeSprings")
        self.world = World()
        self.body1 = Body(r_CM=(0, -0.2, 0), m=0.8, I_11=0.1, I_22=0.1, I_33=0.1)
        self.bar1 = FixedTranslation(r=(0.3, 0, 0))
        self.spring1 = forces.Spring(s_unstretched=0.1, c=20)
        self.bar2 = FixedTranslation(r=(0, 0, 0.3))
        self.spring2 = forces.Spring(s_unstretched=0.1, c=40)
        self.spring3 = forces.Spring(s_unstretched=0.1, c=20, fixedRotationAtFrame_b=True)
        self.connect(self.world.frame_b, self.bar1.frame_a)
        self.connect(self.world.frame_b, self.bar2.frame_a)
        self.connect(self.bar1.frame_b, self.spring1.frame_a)
        self.connect(self.bar2.frame_b, self.spring3.frame_a)
        self.connect(self.spring2.frame_b, self.body1.frame_a)
        self.connect(self.spring3.frame_b, self.spring1.frame_b)
        self.connect(self.spring2.frame_a, self.spring1.frame_b)
        frame = _translations(self, "body_", self.world.frame_b)
        for axis, n in zip(("rx", "ry", "rz"), ((1, 0, 0), (0, 1, 0), (0, 0, 1))):
            joint = Revolute(n=n)
            setattr(self, f"body_{axis}", joint)
            self.connect(frame, joint.frame_a)
            frame = joint.frame_b
        self.connect(frame, self.body1.frame_a)


def _spherical(model: Model, prefix: str, frame_a, sequence=(2, 3, 1)):
    """Three revolutes ``<prefix>1..3`` in series from ``frame_a`` about the axes
    ``sequence`` (a spherical joint in angle coordinates, singular where the second angle is
    ±90°); returns the last frame_b."""
    for k, axis in enumerate(sequence, start=1):
        n = [0.0, 0.0, 0.0]
        n[axis - 1] = 1.0
        joint = Revolute(n=tuple(n))
        setattr(model, f"{prefix}{k}", joint)
        model.connect(frame_a, joint.frame_a)
        frame_a = joint.frame_b
    return frame_a


class GyroscopicEffects(Model):
    """Rotational3DEffects.GyroscopicEffects: a steel rod (BodyCylinder, 0.25 m × 0.05 m)
    hanging from a spherical joint at the world's origin carries, behind a 45° turn about
    y, a cylinder (0.2 m × 0.1 m) spinning about its axis at 10 rad/s, once as a
    Revolute with the BodyCylinder on it (bodyCylinder2), once as the same cylinder fixed
    to the rod (bodyCylinder4) plus a Rotor1D of its axial inertia (J = bodyCylinder4's
    I[1, 1]); both start with the joints at 0 and at rest but for the spin: x0 = ``START``.

    MSL's Spherical joints are written as three revolutes about y, z, x (``spherical1_1``
    .. ``spherical1_3``; the angles sequence {2, 3, 1} starting at 0, singular only where
    the rod would point vertically), which move the same."""
    START = {"revolute.w": 10.0, "rotor1D.w": 10.0}

    def __init__(self, name: str | None = None):
        super().__init__(name or "GyroscopicEffects")
        self.world = World(driveTrainMechanics3D=True)
        self.bodyCylinder1 = BodyCylinder(r=(0.25, 0, 0), diameter=0.05)
        self.fixedRotation1 = FixedRotation(angle=45, n=(0, 1, 0))
        self.revolute = Revolute(n=(1, 0, 0))
        self.fixedTranslation = FixedTranslation(r=(-0.1, 0, 0))
        self.bodyCylinder2 = BodyCylinder(diameter=0.1, r=(0.2, 0, 0))
        self.fixed = Fixed()
        self.bodyCylinder3 = BodyCylinder(r=(0.25, 0, 0), diameter=0.05)
        self.fixedRotation2 = FixedRotation(n=(0, 1, 0), angle=45)
        self.fixedTranslation1 = FixedTranslation(r=(-0.1, 0, 0))
        self.bodyCylinder4 = BodyCylinder(diameter=0.1, r=(0.2, 0, 0))
        J = float(ca.evalf(self.bodyCylinder4.mass_properties()[2][0, 0]))
        self.rotor1D = Rotor1D(J=J, n=(1, 0, 0))
        self.connect(_spherical(self, "spherical1_", self.world.frame_b),
                     self.bodyCylinder1.frame_a)
        self.connect(self.bodyCylinder1.frame_b, self.fixedRotation1.frame_a)
        self.connect(self.fixedRotation1.frame_b, self.revolute.frame_a)
        self.connect(self.revolute.frame_b, self.fixedTranslation.frame_a)
        self.connect(self.fixedTranslation.frame_b, self.bodyCylinder2.frame_a)
        self.connect(_spherical(self, "spherical2_", self.fixed.frame_b),
                     self.bodyCylinder3.frame_a)
        self.connect(self.bodyCylinder3.frame_b, self.fixedRotation2.frame_a)
        self.connect(self.fixedRotation2.frame_b, self.fixedTranslation1.frame_a)
        self.connect(self.fixedTranslation1.frame_b, self.bodyCylinder4.frame_a)
        self.connect(self.rotor1D.frame_a, self.fixedRotation2.frame_b)
