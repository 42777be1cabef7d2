"""Ideal rolling wheels on the ground plane z = 0 (MSL's Joints.RollingWheel,
Joints.RollingWheelSet, Joints.Internal.RollingConstraintVerticalWheel, Parts.RollingWheel,
Parts.RollingWheelSet), with MSL's names, parameters, frames and signs. Gravity must point
along −z (``World(n=(0, 0, -1))``), as MSL requires.

No slip is a constraint on velocities (the contact point's velocity along the wheel's
longitudinal and lateral directions is zero) that does not reduce the positions: it is
declared with ``PhysicsBuilder.velocity_constraint`` and its unknown forces f_long, f_lat
[N] act on the wheel at the contact point; the compiler eliminates one rate per row
(``acausal.compiler.nonholonomic``).

Coordinates. A free wheel has its own coordinates, MSL's: x, y [m] of the wheel centre and
angles[3] [rad], the rotation sequence {3, 2, 1} (about z, then y, then x) from the world to
frame_a (Frames.axesRotations). MSL keeps the centre's height z and the contact point as
unknowns of one position constraint (the wheel touches the ground) and the two conditions
on the contact point's position; here they are solved in closed form: with u = e_axis_0 the
wheel axis in the world, the contact point is r_0 + delta_0, delta_0 = radius·(u_z·u −
e_z)/√(1 − u_z²), so z = radius·√(1 − u_z²) and frame_a is a function of x, y and angles
(``StructureBuilder.pose``): 5 positional and 3 velocity degrees of freedom, states x, y,
angles, der_angles as MSL's (der(x), der(y) follow from the no-slip rows). The normal force
f_n is the reaction of that pose (recorded from frame_a's cut force).

A wheel set's coordinates are MSL's x, y [m] (centre between the wheels), phi [rad] (turn
of the axis about z) and theta1, theta2 [rad] (the wheels' angles about their axis), its
frames placed as MSL's assembly places them (frameMiddle at height radius; frame1, frame2
at ±track/2 along its y axis, turned by theta1, theta2 about it). The wheels'
RollingConstraintVerticalWheel rows: no slip along both wheels, no lateral slip at wheel 1
(wheel 2 free laterally, MSL's lateralSlidingConstraint=false, else the set would be over-
constrained). ``support`` (MSL: a Mounting1D on frameMiddle with n = {1, 0, 0}, whose
torque the plane motion of frameMiddle takes up) is fixed here: the reaction of the axis
drives goes to the ground, which gives the same motion; the cut torque at frameMiddle
differs from MSL's by it. The cut forces at frameMiddle, frame1, frame2 are the reactions
of these placements, not of MSL's internal joints.

``animation`` and the visualization parameters (width, hollowFraction, color) are kept for
the animation (``acausal.analysis.animation`` draws the wheels as discs).
"""
from __future__ import annotations

import casadi as ca

from ... import frames
from ...core import Component, Parameter, RotationalFlange, StateSelect
from ...core.ports import ROTATIONAL, TRANSLATIONAL
from .interfaces import Animated, Frame_a, Frame_b
from .parts import _record, rigid_body

__all__ = ["RollingWheel", "RollingWheelSet", "RollingWheelJoint", "RollingWheelSetJoint",
           "RollingConstraintVerticalWheel"]

_EZ = ca.DM([0.0, 0.0, 1.0])


def axes_rotations_321(a) -> ca.SX:
    """MSL's Frames.axesRotations({3, 2, 1}, a).T: about z by a[0], y by a[1], x by a[2]."""
    T = ca.SX.eye(3)
    for axis, angle in ((2, a[0]), (1, a[1]), (0, a[2])):
        e = [0.0, 0.0, 0.0]
        e[axis] = 1.0
        T = ca.mtimes(frames.planar_rotation(e, angle), T)
    return T


def wheel_pose(q, par):
    """frame_a of a free rolling wheel from (x, y, angles[1..3]) and (radius,)."""
    (radius,) = par
    T = axes_rotations_321(q[2:5])
    uz = T[1, 2]                                 # e_axis_0 = T[1, :] (frame_a's y axis)
    return ca.vertcat(q[0], q[1], radius * ca.sqrt(1 - uz ** 2)), T


def _middle(q, par):
    radius = par[0]
    return ca.vertcat(q[0], q[1], radius), frames.planar_rotation([0.0, 0.0, 1.0], q[2])


def middle_pose(q, par):
    """frameMiddle of a wheel set from (x, y, phi) and (radius, track)."""
    return _middle(q, par)


def _wheel_of_set(q, par, side):
    r, T = _middle(q, par)
    track = par[1]
    r = r + frames.resolve1(T, ca.vertcat(0, side * track / 2, 0))
    return r, ca.mtimes(frames.planar_rotation([0.0, 1.0, 0.0], q[3]), T)


def wheel1_pose(q, par):
    """frame1 (left wheel) of a wheel set from (x, y, phi, theta1) and (radius, track)."""
    return _wheel_of_set(q, par, 1.0)


def wheel2_pose(q, par):
    """frame2 (right wheel) of a wheel set from (x, y, phi, theta2) and (radius, track)."""
    return _wheel_of_set(q, par, -1.0)


def rolling_contact(e, frame, delta_0, lateral: bool = True):
    """No slip of the wheel fixed to ``frame`` at its contact point r_0 + ``delta_0`` [m]
    (world frame) on the plane z = 0: the rows vContact_0·e_long_0 = 0 (and ·e_lat_0 = 0
    with ``lateral``), their forces f_long, f_lat [N] on the wheel at the contact point
    put on ``frame``. Returns f_wheel_0 [N] (world frame) without the normal force."""
    r0, T = frames.parts(e.pos(frame))
    vel = e.vel(frame)
    v_0, w_0 = frames.resolve1(T, vel[:3]), frames.resolve1(T, vel[3:6])
    e_axis_0 = T[1, :].T
    aux = ca.cross(_EZ, e_axis_0)
    e_long_0 = aux / ca.norm_2(aux)
    e_lat_0 = ca.cross(e_long_0, _EZ)
    vContact_0 = v_0 + ca.cross(w_0, delta_0)
    f_long = e.velocity_constraint("f_long", ca.dot(vContact_0, e_long_0), "N",
                                   "contact force acting on wheel in longitudinal direction")
    f_wheel_0 = f_long * e_long_0
    if lateral:
        f_lat = e.velocity_constraint("f_lat", ca.dot(vContact_0, e_lat_0), "N",
                                      "contact force acting on wheel in lateral direction")
        f_wheel_0 = f_wheel_0 + f_lat * e_lat_0
    else:
        e.variable("f_lat", 0.0, "N", "contact force acting on wheel in lateral direction")
    e.flow(frame, ca.vertcat(-ca.mtimes(T, f_wheel_0), -ca.mtimes(T, ca.cross(delta_0,
                                                                            f_wheel_0))))
    return f_wheel_0


class RollingWheelJoint(Animated):
    """Joint (no mass) of an ideal rolling wheel on the plane z = 0 (MSL's
    Joints.RollingWheel): frame_a fixed in the wheel centre (y axis along the wheel axis).
    radius [m] has no default (as in MSL). Coordinates x, y [m], angles[1..3] [rad] with
    rates der_angles[1..3] [rad/s] (see the module). Records z, r_road_0, f_wheel_0, f_n,
    f_lat, f_long [N] and err [m] (|delta_0| − radius, 0)."""
    options = {"stateSelect": StateSelect.always}
    required = ("radius",)
    radius = Parameter(0.3, "m", "wheel radius", positive=True)
    frame_a = Frame_a("frame fixed in wheel center point. x-Axis: upwards, y-axis: along "
                      "wheel axis")

    def structure(self, s):
        x = s.node("x", TRANSLATIONAL)
        y = s.node("y", TRANSLATIONAL)
        angles = [s.node(f"angles[{k}]", ROTATIONAL, velocity=f"der_angles[{k}]",
                         acceleration=f"a_angles[{k}]") for k in (1, 2, 3)]
        s.pose(self.frame_a, [x, y, *angles], wheel_pose, [self.radius])

    def physics(self, e):
        r0, T = frames.parts(e.pos(self.frame_a))
        u = T[1, :].T
        s_ = ca.sqrt(1 - u[2] ** 2)
        delta_0 = self.radius * (u[2] * u - _EZ) / s_
        rolling_contact(e, self.frame_a, delta_0)
        cut = e.cut_flow(self.frame_a)               # all the joint exerts, normal force too
        f_total_0 = -frames.resolve1(T, cut[:3])
        e.variable("z", r0[2], "m", "z-coordinate of wheel axis")
        e.variable("f_n", f_total_0[2], "N", "contact force acting on wheel in normal "
                                             "direction")
        _record(e, "f_wheel_0", f_total_0, "N", "contact force acting on wheel, resolved in "
                                                "world frame")
        _record(e, "r_road_0", r0 + delta_0, "m", "position vector from world frame to "
                                                  "contact point on road, resolved in world "
                                                  "frame")
        e.variable("err", ca.norm_2(delta_0) - self.radius, "m", "|r_road_0 - frame_a.r_0| - "
                                                                 "radius (must be zero)")


class RollingWheel(RollingWheelJoint):
    """Ideal rolling wheel with mass (MSL's Parts.RollingWheel): RollingWheelJoint and
    a body at frame_a of mass m [kg] with inertia I_axis about the wheel axis and I_long
    perpendicular to it [kg.m²] (no defaults, as in MSL). width [m] and hollowFraction are
    MSL's animation parameters (drawn by the animation)."""
    required = ("radius", "m", "I_axis", "I_long")
    m = Parameter(1.0, "kg", "mass of wheel", nonnegative=True)
    I_axis = Parameter(0.001, "kg.m2", "inertia along the wheel axis", nonnegative=True)
    I_long = Parameter(0.001, "kg.m2", "inertia perpendicular to the wheel axis",
                       nonnegative=True)
    width = Parameter(0.035, "m", "width of wheel", nonnegative=True)
    hollowFraction = Parameter(0.8, "1", "for ring-like visualization: wheel radius / inner "
                                         "hole radius", nonnegative=True)

    def physics(self, e):
        super().physics(e)
        rigid_body(e, self.frame_a, self.m, ca.DM.zeros(3),
                   ca.diag(ca.vertcat(self.I_long, self.I_axis, self.I_long)), "body.")


class RollingConstraintVerticalWheel(Component):
    """No slip of a wheel that stays upright on the plane z = 0 (MSL's
    Joints.Internal.RollingConstraintVerticalWheel): frame_a in the wheel centre (y axis
    along the wheel axis), contact point radius [m] below it. ``lateralSlidingConstraint``
    (default True): also no lateral slip (False: f_lat = 0). Records f_long, f_lat [N],
    f_wheel_0[3] [N] (on the wheel, world frame)."""
    options = {"lateralSlidingConstraint": True}
    required = ("radius",)
    radius = Parameter(0.3, "m", "wheel radius", positive=True)
    frame_a = Frame_a("frame fixed in wheel center point. x-Axis: upwards, y-axis: along "
                      "wheel axis")

    def physics(self, e):
        vertical_wheel(e, self.frame_a, self.radius, self.lateralSlidingConstraint)


def vertical_wheel(e, frame, radius, lateral: bool) -> None:
    """RollingConstraintVerticalWheel's equations on ``frame``."""
    f_wheel_0 = rolling_contact(e, frame, ca.vertcat(0, 0, -radius), lateral)
    _record(e, "f_wheel_0", f_wheel_0, "N", "contact force acting on wheel, resolved in "
                                            "world frame")


class _WheelSet(Animated):
    """Frames, flanges, coordinates and no-slip rows of a wheel set (see RollingWheelSetJoint);
    subclasses give the wheel radius (``_radius``)."""
    options = {"stateSelect": StateSelect.default}
    track = Parameter(0.5, "m", "distance between the two wheels (= axle track)",
                      positive=True)
    frameMiddle = Frame_a("frame fixed in middle of axis connecting both wheels (y-axis: "
                          "along wheel axis, z-Axis: upwards)")
    frame1 = Frame_a("frame fixed in center point of left wheel (y-axis: along wheel axis, "
                     "z-Axis: upwards)")
    frame2 = Frame_b("frame fixed in center point of right wheel (y-axis: along wheel axis, "
                     "z-Axis: upwards)")
    axis1 = RotationalFlange("1-dim. rotational flange that drives the left wheel")
    axis2 = RotationalFlange("1-dim. rotational flange that drives the right wheel")
    support = RotationalFlange("support of 1D axes")

    def _radius(self):
        raise NotImplementedError

    def structure(self, s):
        x = s.node("x", TRANSLATIONAL)
        y = s.node("y", TRANSLATIONAL)
        phi = s.node("phi", ROTATIONAL)
        th1 = s.node("theta1", ROTATIONAL, velocity="der_theta1")
        th2 = s.node("theta2", ROTATIONAL, velocity="der_theta2")
        par = [self._radius(), self.track]
        s.pose(self.frameMiddle, [x, y, phi], middle_pose, par)
        s.pose(self.frame1, [x, y, phi, th1], wheel1_pose, par)
        s.pose(self.frame2, [x, y, phi, th2], wheel2_pose, par)
        s.linear({self.axis1: 1.0, th1: -1.0}, 0.0, f"{self.path}: axis1")
        s.linear({self.axis2: 1.0, th2: -1.0}, 0.0, f"{self.path}: axis2")
        s.linear({self.support: 1.0}, 0.0, f"{self.path}: support")

    def physics(self, e):
        for frame, lateral, k in ((self.frame1, True, 1), (self.frame2, False, 2)):
            vertical_wheel(_Prefixed(e, f"rolling{k}."), frame, self._radius(), lateral)


class RollingWheelSetJoint(_WheelSet):
    """Joint (no mass) of an ideal rolling wheel set (MSL's Joints.RollingWheelSet): two
    wheels of radius [m] on one axis, track [m] apart (no defaults, as in MSL); frameMiddle
    in the middle of the axis (parallel to the ground, z = radius), frame1 / frame2 in the
    left / right wheel centre, turning with the wheel about its y axis; ``axis1``,
    ``axis2`` the 1-D flanges driving the wheels (angles theta1, theta2), ``support`` their
    support (see the module). Coordinates x, y, phi, theta1, theta2 (rates der_theta1,
    der_theta2 are MSL's states); rolling1.f_long, rolling1.f_lat, rolling2.f_long [N]
    recorded (MSL's inner rolling constraints)."""
    required = ("radius", "track")
    radius = Parameter(0.1, "m", "radius of one wheel", positive=True)

    def _radius(self):
        return self.radius


class _Prefixed:
    """A PhysicsBuilder whose recorded names get a prefix."""

    def __init__(self, e, prefix):
        self._e, self._prefix = e, prefix

    def __getattr__(self, name):
        return getattr(self._e, name)

    def velocity_constraint(self, name, *args):
        return self._e.velocity_constraint(self._prefix + name, *args)

    def variable(self, name, *args, **kw):
        return self._e.variable(self._prefix + name, *args, **kw)


class RollingWheelSet(_WheelSet):
    """Ideal rolling wheel set with mass (MSL's Parts.RollingWheelSet): RollingWheelSetJoint
    with a body of mass m_wheel [kg], inertia I_wheelAxis about the wheel axis and
    I_wheelLong perpendicular to it [kg.m²] at each wheel (body1, body2); R_wheel [m] the
    radius, track [m] (no defaults, as in MSL). The coordinates are MSL's x, y, phi,
    theta1, theta2, der_theta1, der_theta2. width_wheel [m], hollowFraction: MSL's animation
    parameters (drawn by the animation)."""
    required = ("R_wheel", "m_wheel", "I_wheelAxis", "I_wheelLong", "track")
    R_wheel = Parameter(0.1, "m", "radius of one wheel", positive=True)
    m_wheel = Parameter(1.0, "kg", "mass of one wheel", nonnegative=True)
    I_wheelAxis = Parameter(0.001, "kg.m2", "inertia along one wheel axis", nonnegative=True)
    I_wheelLong = Parameter(0.001, "kg.m2", "inertia perpendicular to one wheel axis",
                            nonnegative=True)
    width_wheel = Parameter(0.01, "m", "width of one wheel", nonnegative=True)
    hollowFraction = Parameter(0.8, "1", "for ring-like wheel visualization: wheel radius / "
                                         "inner hole radius", nonnegative=True)

    def _radius(self):
        return self.R_wheel

    def physics(self, e):
        super().physics(e)
        I = ca.diag(ca.vertcat(self.I_wheelLong, self.I_wheelAxis, self.I_wheelLong))
        for k, frame in ((1, self.frame1), (2, self.frame2)):
            rigid_body(_Prefixed(e, f"body{k}."), frame, self.m_wheel, ca.DM.zeros(3), I)
