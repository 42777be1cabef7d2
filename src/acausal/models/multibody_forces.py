"""MSL MultiBody examples with forces, 1-D springs and drive trains, rebuilt line by line
(component names, parameters, connections as in the MSL):
``Examples.Elementary.ForceAndTorque``, ``SpringMassSystem``, ``PointGravity``,
``ThreeSprings`` and ``Examples.Rotational3DEffects.MovingActuatedDrive``,
``GyroscopicEffects`` (free bodies and Spherical joints with their quaternion states and
MSL's start values), and ``FreeBody``. MSL's visualization parameters (widths, diameters, colors) are left out; the World's
defaults apply.
"""
from __future__ import annotations

import casadi as ca

from ..components import rotational, signals, translational
from ..components.multibody import (Body, BodyCylinder, BodyShape, Fixed, FixedRotation,
                                    FixedTranslation, GravityTypes, Mounting1D, Prismatic,
                                    Revolute, Rotor1D, Spherical, World)
from ..components.multibody import forces
from ..components.multibody.resolving import ResolveInFrameAB
from ..core import Model

__all__ = ["ForceAndTorqueExample", "SpringMassSystem", "MovingActuatedDrive", "PointGravity",
           "ThreeSprings", "GyroscopicEffects", "FreeBody"]


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


class PointGravity(Model):
    """Elementary.PointGravity: two free bodies (m = 1 kg, I = 0.1·1 kg.m², centre of mass
    at frame_a) in the point gravity field of the World (mu = 1 m³/s²), starting at
    r_0 = {0, 0.6, 0} m with v_0 = {1, 0, 0} m/s (a circle) and at {0.6, 0.6, 0} m with
    {0.6, 0, 0} m/s (an ellipse), at rest in rotation (MSL's start values, the bodies'
    13 states each)."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "PointGravity")
        self.world = World(mu=1, gravityType=GravityTypes.PointGravity)
        self.body1 = Body(m=1, I_11=0.1, I_22=0.1, I_33=0.1, r_0_start=(0, 0.6, 0),
                          v_0_start=(1, 0, 0), angles_fixed=True, w_0_fixed=True,
                          r_CM=(0, 0, 0))
        self.body2 = Body(m=1, I_11=0.1, I_22=0.1, I_33=0.1, r_0_start=(0.6, 0.6, 0),
                          v_0_start=(0.6, 0, 0), angles_fixed=True, w_0_fixed=True,
                          r_CM=(0, 0, 0))


class ThreeSprings(Model):
    """Elementary.ThreeSprings: a free body (m = 0.8 kg, r_CM = {0, -0.2, 0} m, I = 0.1·1
    kg.m²) hanging under gravity from three 3-D Springs connected in series and parallel
    without mass at their junction: spring1 (c = 20 N/m) from bar1 ({0.3, 0, 0}) and
    spring3 (c = 20 N/m) from bar2 ({0, 0, 0.3}) to the junction, spring2 (c = 40 N/m) from
    the junction to the body; unstretched lengths 0.1 m. The body starts at r_0 = {0.5,
    -0.3, 0} m at rest, its frame parallel to the world's (MSL's start values).

    The junction's orientation is fixed by spring3's fixedRotationAtFrame_b, as in MSL (its
    position spring3.r_b_0 is then algebraic: no mass, the spring forces in balance).
    guess = ``GUESS``: MSL's spring1.lineForce.r_rel_0(start = {-0.2, -0.2, 0.2}) m."""
    GUESS = {"spring1.r_rel_0[1]": -0.2, "spring1.r_rel_0[2]": -0.2,
             "spring1.r_rel_0[3]": 0.2}

    def __init__(self, name: str | None = None):
        super().__init__(name or "ThreeSprings")
        self.world = World()
        self.body1 = Body(r_CM=(0, -0.2, 0), m=0.8, I_11=0.1, I_22=0.1, I_33=0.1,
                          r_0_start=(0.5, -0.3, 0), angles_fixed=True, w_0_fixed=True)
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


class GyroscopicEffects(Model):
    """Rotational3DEffects.GyroscopicEffects: a steel rod (BodyCylinder, 0.25 m × 0.05 m)
    hanging from a Spherical joint at the world's origin carries, behind a 45° turn about
    y, a cylinder (0.2 m × 0.1 m) spinning about its axis at 10 rad/s, once as a
    Revolute with the BodyCylinder on it (bodyCylinder2), once as the same cylinder fixed
    to the rod (bodyCylinder4) plus a Rotor1D of its axial inertia (J = bodyCylinder4's
    I[1, 1]); the spherical joints start at angles 0 and at rest (angles_fixed,
    w_rel_a_fixed), the spins by MSL's w(start = 10, fixed = true): x0 = ``START``."""
    START = {"revolute.w": 10.0, "rotor1D.w": 10.0}

    def __init__(self, name: str | None = None):
        super().__init__(name or "GyroscopicEffects")
        self.world = World(driveTrainMechanics3D=True)
        self.spherical1 = Spherical(angles_fixed=True, w_rel_a_fixed=True,
                                    z_rel_a_fixed=False)
        self.bodyCylinder1 = BodyCylinder(r=(0.25, 0, 0), diameter=0.05)
        self.fixedRotation1 = FixedRotation(angle=45, n=(0, 1, 0))
        self.revolute = Revolute(n=(1, 0, 0))
        self.fixedTranslation = FixedTranslation(r=(-0.1, 0, 0))
        self.bodyCylinder2 = BodyCylinder(diameter=0.1, r=(0.2, 0, 0))
        self.fixed = Fixed()
        self.spherical2 = Spherical(angles_fixed=True, w_rel_a_fixed=True,
                                    z_rel_a_fixed=False)
        self.bodyCylinder3 = BodyCylinder(r=(0.25, 0, 0), diameter=0.05)
        self.fixedRotation2 = FixedRotation(n=(0, 1, 0), angle=45)
        self.fixedTranslation1 = FixedTranslation(r=(-0.1, 0, 0))
        self.bodyCylinder4 = BodyCylinder(diameter=0.1, r=(0.2, 0, 0))
        J = float(ca.evalf(self.bodyCylinder4.mass_properties()[2][0, 0]))
        self.rotor1D = Rotor1D(J=J, n=(1, 0, 0))
        self.connect(self.world.frame_b, self.spherical1.frame_a)
        self.connect(self.spherical1.frame_b, self.bodyCylinder1.frame_a)
        self.connect(self.bodyCylinder1.frame_b, self.fixedRotation1.frame_a)
        self.connect(self.fixedRotation1.frame_b, self.revolute.frame_a)
        self.connect(self.revolute.frame_b, self.fixedTranslation.frame_a)
        self.connect(self.fixedTranslation.frame_b, self.bodyCylinder2.frame_a)
        self.connect(self.spherical2.frame_b, self.bodyCylinder3.frame_a)
        self.connect(self.bodyCylinder3.frame_b, self.fixedRotation2.frame_a)
        self.connect(self.fixed.frame_b, self.spherical2.frame_a)
        self.connect(self.fixedTranslation1.frame_b, self.bodyCylinder4.frame_a)
        self.connect(self.fixedRotation2.frame_b, self.fixedTranslation1.frame_a)
        self.connect(self.rotor1D.frame_a, self.fixedRotation2.frame_b)


class FreeBody(Model):
    """Elementary.FreeBody: a free BodyShape (m = 1 kg, I = 1 kg.m² on the diagonal, frame_b
    at r = {0.4, 0, 0} m, r_CM = {0.2, 0, 0} m) held by two Springs (c = 20 N/m,
    s_unstretched = 0) from the world's origin and from bar2's end {0.8, 0, 0} m; it
    starts at r_0 = {0.2, -0.5, 0.1} m, turned by 10° about each of the axes 1, 2, 3, at
    rest (MSL's start values)."""

    def __init__(self, name: str | None = None):
        super().__init__(name or "FreeBody")
        self.world = World()
        self.bar2 = FixedTranslation(r=(0.8, 0, 0), animation=False)
        self.spring1 = forces.Spring(c=20, s_unstretched=0)
        self.body = BodyShape(m=1, I_11=1, I_22=1, I_33=1, r=(0.4, 0, 0), r_CM=(0.2, 0, 0),
                              r_0_start=(0.2, -0.5, 0.1), angles_fixed=True, w_0_fixed=True,
                              angles_start=(0.174532925199433,) * 3)
        self.spring2 = forces.Spring(c=20, s_unstretched=0)
        self.connect(self.bar2.frame_a, self.world.frame_b)
        self.connect(self.spring1.frame_b, self.body.frame_a)
        self.connect(self.bar2.frame_b, self.spring2.frame_a)
        self.connect(self.spring1.frame_a, self.world.frame_b)
        self.connect(self.body.frame_b, self.spring2.frame_b)
