"""Planar multibody mechanics, after PlanarMechanics (the Modelica library by D. Zimmer).

Frames carry x, y [m], phi [rad] and the cut force fx, fy [N] and torque t [N.m] resolved in
the world frame (positive into the component, t counter-clockwise, t about the frame's
origin). A World gives gravity g [m/s²] along the unit direction n (default {0, -1}, i.e.
PlanarMechanics' ``constantGravity = {0, -9.81}``); every Body uses the model's one World.
Joint coordinates are the generalized coordinates wherever the joint graph is a tree
(``rev.phi``, ``prism.s``); a Body with no path to the ground gets its frame's x, y, phi as
coordinates (start values by any recorded name: ``x0={"body.r[1]": 1, "body.v[2]": 0}``).
Joints can carry a 1-D flange on their axis (``useFlange=True``: ``axis`` and ``support``,
PlanarMechanics 2's names), so that the rotational and translational libraries drive and
load them.

Names, parameters, defaults and sign conventions follow PlanarMechanics (Parts, Joints,
Sources, Sensors), so that a PlanarMechanics model translates line by line:

- Parts: Fixed, FixedTranslation, FixedRotation, Body, Spring, Damper, SpringDamper, and the
  line-force elements LineSpring and LineSpringDamper (not in PlanarMechanics, see below).
- Joints: Revolute, Prismatic.
- Sources: WorldForce, RelativeForce, and WorldTorque (after MultiBody.Forces.WorldTorque).
- Sensors: AbsolutePosition, AbsoluteVelocity, AbsoluteAcceleration, RelativePosition,
  RelativeVelocity, RelativeAcceleration, Distance, CutForce, CutTorque, CutForceAndTorque,
  Power.

Force elements. PlanarMechanics' ``Spring`` and ``SpringDamper`` are *x/y/phi* elements:
forces c_x·(Δx − s_relx0), c_y·(Δy − s_rely0) along the world axes (and, for SpringDamper,
a torque c_phi·(Δphi − phi_rel0) + d_phi·w_rel); their ``Damper`` is a *line* damper acting
along the line between the frame origins. The line spring and spring-damper (force along
the line from frame_a to frame_b, no torque about the origins) are provided as
``LineSpring(c, s_rel0)`` and ``LineSpringDamper(c, d, s_rel0)``, whose ``f`` is the tension
(f > 0 pulls the frames together), as in MSL's 1-D and MultiBody springs.

``resolveInFrame`` (PlanarMechanics' ``Types.ResolveInFrameA/B/AB``) is a keyword fixed at
construction, given as the enumeration (``ResolveInFrameAB.world``) or its name
(``"world"``); ``frame_resolve`` adds the port of that name, which must be connected.

Vector signals are numbered from 1 as in Modelica: ``connect(src.y, wf.force[1])``,
``sensor.r[3]``. WorldForce and RelativeForce take the force as ``force[2]`` and the torque
as a separate input ``torque``, as PlanarMechanics 2 (PlanarMechanics 1 had ``force[3]``).

MSL options that change nothing here are accepted (``stateSelect``, a hint; Spring's
``enableAssert``, a warning); those acausal does not implement yet accept only their "off"
value (Damper's ``enableAssert=False``) and refuse the other with a ParameterError saying
what is missing. The dissipating elements (SpringDamper, Damper, LineSpringDamper) have
MSL's conditional ``heatPort`` (``useHeatPort=True``: heatPort.Q_flow = −lossPower).
Body's ``enableGravity`` is implemented.

Not here: visualization parameters (animate, color, ...), IdealRolling/slip-based wheels,
gear components, QuadraticSpeedDependentForce, the prescribed-motion sources. Differences
from PlanarMechanics are listed in each docstring.
"""
from __future__ import annotations

from enum import Enum

import casadi as ca

from ..core import (Component, ConditionalPort, Frame, Parameter, PortVector, RealInput,
                    RealOutput, RotationalFlange, StateSelect, TranslationalFlange,
                    Unavailable, VectorPort)
from ..core.ports import ROTATIONAL, TRANSLATIONAL
from .interfaces import (PartialDrivenJoint, PartialElementaryConditionalHeatPortWithoutT,
                         drive_flanges, unit_direction)

__all__ = [
    # types
    "ResolveInFrameA", "ResolveInFrameB", "ResolveInFrameAB", "StateSelect",
    # world and parts
    "World", "Fixed", "FixedTranslation", "FixedRotation", "Body",
    "Spring", "Damper", "SpringDamper", "LineSpring", "LineSpringDamper",
    # joints
    "Revolute", "Prismatic",
    # sources
    "WorldForce", "WorldTorque", "RelativeForce",
    # sensors
    "AbsolutePosition", "AbsoluteVelocity", "AbsoluteAcceleration", "RelativePosition",
    "RelativeVelocity", "RelativeAcceleration", "Distance", "CutForce", "CutTorque",
    "CutForceAndTorque", "Power",
    # partials
    "PartialLineForce", "PartialXYCompliant",
]


# =========================================================================================
# Types and helpers
# =========================================================================================
class ResolveInFrameA(str, Enum):
    """Frame in which an absolute vector is resolved (MultiBody.Types.ResolveInFrameA)."""
    world = "world"
    frame_a = "frame_a"
    frame_resolve = "frame_resolve"


class ResolveInFrameB(str, Enum):
    """Frame in which a vector at frame_b is resolved (MultiBody.Types.ResolveInFrameB)."""
    world = "world"
    frame_b = "frame_b"
    frame_resolve = "frame_resolve"


class ResolveInFrameAB(str, Enum):
    """Frame in which a relative vector is resolved (MultiBody.Types.ResolveInFrameAB)."""
    world = "world"
    frame_a = "frame_a"
    frame_b = "frame_b"
    frame_resolve = "frame_resolve"


def _rot(phi, v):
    """R(phi)·v: a 2-vector resolved in a frame at angle phi, resolved in the world."""
    c, s = ca.cos(phi), ca.sin(phi)
    return ca.vertcat(c * v[0] - s * v[1], s * v[0] + c * v[1])


def _rot_t(phi, v):
    """R(phi)ᵀ·v: a world 2-vector resolved in a frame at angle phi."""
    c, s = ca.cos(phi), ca.sin(phi)
    return ca.vertcat(c * v[0] + s * v[1], -s * v[0] + c * v[1])


def _output_vector(e, ports: PortVector, values) -> None:
    for k, port in enumerate(ports):
        e.output(port, values[k])


class _Resolving(Component):
    """A component with PlanarMechanics' ``resolveInFrame`` choice (structural, fixed at
    construction; subclasses give the enumeration and its default in ``options``).
    ``frame_resolve`` adds a required frame of that name."""
    options = {"resolveInFrame": ResolveInFrameA.frame_a}
    frame_resolve = ConditionalPort(Frame("frame in which vectors are resolved (no force)",
                                          required=True), "resolveInFrame", "frame_resolve")

    def _angle(self, e):
        """Angle [rad] of the frame vectors are resolved in (0 for the world)."""
        which = self.resolveInFrame.value
        if which == "world":
            return ca.SX(0)
        return e.pos(getattr(self, which))[2]


# =========================================================================================
# World and parts
# =========================================================================================
class World(Component):
    """Gravity for every Body of the model: acceleration g [m/s²] along n, as MultiBody's
    World: gravity = g·n/|n| (n need not be a unit vector; n = {0, 0} is refused).

    PlanarMechanics' PlanarWorld gives one vector ``constantGravity`` = {0, -9.81}: here
    g·n/|n| with the defaults g = 9.81, n = {0, -1} (MultiBody's World parametrization)."""
    g = Parameter(9.81, "m/s2", "gravity constant", nonnegative=True)
    n = Parameter((0.0, -1.0), "1", "direction of gravity (gravity = g*n/length(n))")

    def gravity(self) -> ca.SX:
        """The gravity acceleration g·n/|n| [m/s²], resolved in the world frame."""
        return self.g * unit_direction(self, "n", "(0, -1)")


class Fixed(Component):
    """A frame fixed in the world at position r [m] and angle phi [rad] (port ``frame``)."""
    r = Parameter((0.0, 0.0), "m", "fixed x,y-position")
    phi = Parameter(0.0, "rad", "fixed angle")
    frame = Frame("the fixed frame")

    def structure(self, s):
        s.transform(None, self.frame, self.r, self.phi)


class FixedTranslation(Component):
    """A massless rigid bar: frame_b at r [m] from frame_a, resolved in frame_a.

    Difference from PlanarMechanics: r has the default {1, 0} (PlanarMechanics gives none)."""
    r = Parameter((1.0, 0.0), "m", "translation vector from frame_a to frame_b, in frame_a")
    frame_a = Frame("left frame")
    frame_b = Frame("right frame")

    def structure(self, s):
        s.transform(self.frame_a, self.frame_b, self.r, 0.0)


class FixedRotation(Component):
    """frame_b rotated by alpha [rad] with respect to frame_a (same origin)."""
    alpha = Parameter(0.0, "rad", "fixed rotation angle")
    frame_a = Frame("left frame")
    frame_b = Frame("right frame")

    def structure(self, s):
        s.transform(self.frame_a, self.frame_b, (0.0, 0.0), self.alpha)


class Body(Component):
    """A rigid body: mass m [kg], inertia I [kg.m²] about its centre of mass, which is
    frame_a; gravity from the model's World.

    Records, as PlanarMechanics: r[1], r[2] [m], v[1], v[2] [m/s], a[1], a[2] [m/s²],
    phi [rad], w [rad/s], z [rad/s²] of frame_a, and f[1], f[2] [N] = frame_a.fx, fy
    (f + m·g = m·a; f = m·a with ``enableGravity=False``, a body gravity does not act on).
    ``stateSelect`` is accepted as a hint (StateSelect). Differences from PlanarMechanics:
    m, I have defaults (1, 0.1); no local gravity parameter g (it is the World's)."""
    options = {"enableGravity": True, "stateSelect": StateSelect.default}
    m = Parameter(1.0, "kg", "mass of the body", positive=True)
    I = Parameter(0.1, "kg.m2", "inertia of the body with respect to its centre of mass",
                  nonnegative=True)
    frame_a = Frame("the frame at the centre of mass")

    def structure(self, s):
        s.states(self.frame_a, ("r[1]", "r[2]", "phi"), ("v[1]", "v[2]", "w"))

    def physics(self, e):
        # split once: indexing an SX from Python costs as much as an operation
        r, v, a = (ca.vertsplit(x) for x in (e.pos(self.frame_a), e.vel(self.frame_a),
                                             e.acc(self.frame_a)))
        gx, gy = ca.vertsplit(e.outer(World).gravity()) if self.enableGravity else (0, 0)
        e.rigid_body(self.frame_a, self.m, self.I)
        e.potential_energy(-self.m * (gx * r[0] + gy * r[1]))
        for k, name in enumerate(("r[1]", "r[2]", "phi")):
            e.variable(name, r[k], "rad" if k == 2 else "m")
        for k, name in enumerate(("v[1]", "v[2]", "w")):
            e.variable(name, v[k], "rad/s" if k == 2 else "m/s")
        for k, name in enumerate(("a[1]", "a[2]", "z")):
            e.variable(name, a[k], "rad/s2" if k == 2 else "m/s2")
        e.variable("f[1]", self.m * (a[0] - gx), "N", "force on the body at frame_a, x")
        e.variable("f[2]", self.m * (a[1] - gy), "N", "force on the body at frame_a, y")


# ---- x/y/phi compliant elements (PlanarMechanics.Parts.Spring, SpringDamper) -----------
class PartialXYCompliant(Component):
    """Forces along the world axes and a torque between frame_a and frame_b, functions of
    s_relx = frame_b.x − frame_a.x, s_rely = frame_b.y − frame_a.y [m], phi_rel =
    frame_b.phi − frame_a.phi [rad] and their rates: frame_b gets (f_x, f_y, tau), frame_a
    the opposite. As in PlanarMechanics, the couple of the two forces (when they are not
    along the line between the origins) is not balanced by a torque."""
    partial = True
    frame_a = Frame("left frame")
    frame_b = Frame("right frame")

    def forces(self, s_relx, s_rely, phi_rel, v_relx, v_rely, w_rel):
        """(f_x [N], f_y [N], tau [N.m]) on frame_b."""
        raise NotImplementedError

    def record(self, e, s_relx, s_rely, phi_rel, v_relx, v_rely, w_rel, f_x, f_y, tau):
        """Record the variables of the element (subclasses)."""

    def physics(self, e):
        d = e.pos(self.frame_b) - e.pos(self.frame_a)
        dv = e.vel(self.frame_b) - e.vel(self.frame_a)
        f_x, f_y, tau = self.forces(d[0], d[1], d[2], dv[0], dv[1], dv[2])
        f = ca.vertcat(f_x, f_y, tau)
        e.flow(self.frame_b, f)
        e.flow(self.frame_a, -f)
        e.variable("s_relx", d[0], "m", "spring length in x (= frame_b.x - frame_a.x)")
        e.variable("s_rely", d[1], "m", "spring length in y (= frame_b.y - frame_a.y)")
        e.variable("phi_rel", d[2], "rad", "spring angle (= frame_b.phi - frame_a.phi)")
        e.variable("f_x", f_x, "N", "force in x direction (= frame_b.fx)")
        e.variable("f_y", f_y, "N", "force in y direction (= frame_b.fy)")
        self.record(e, d[0], d[1], d[2], dv[0], dv[1], dv[2], f_x, f_y, tau)


class Spring(PartialXYCompliant):
    """PlanarMechanics' linear 2-D translational spring along the world axes:
    f_x = c_x·(s_relx − s_relx0), f_y = c_y·(s_rely − s_rely0) [N] on frame_b (frame_a gets
    the opposite); no torque. c_x, c_y [N/m] (default 1), s_relx0, s_rely0 [m].

    As in PlanarMechanics, c_phi [N.m/rad] and phi_rel0 [rad] are accepted but exert no
    torque (frame_a.t = frame_b.t = 0); SpringDamper has the rotational part. For a spring
    acting along the line between the frame origins use LineSpring. ``enableAssert`` (a
    warning in PlanarMechanics when the origins coincide, which changes no result here: the
    law does not divide by the distance) and ``stateSelect`` (StateSelect) are accepted."""
    options = {"enableAssert": True, "stateSelect": StateSelect.default}
    c_x = Parameter(1.0, "N/m", "spring constant in x dir", nonnegative=True)
    c_y = Parameter(1.0, "N/m", "spring constant in y dir", nonnegative=True)
    c_phi = Parameter(1.0e5, "N.m/rad", "spring constant (no effect, as in PlanarMechanics)",
                      nonnegative=True)
    s_relx0 = Parameter(0.0, "m", "unstretched spring length")
    s_rely0 = Parameter(0.0, "m", "unstretched spring length")
    phi_rel0 = Parameter(0.0, "rad", "unstretched spring angle (no effect)")

    def forces(self, s_relx, s_rely, phi_rel, v_relx, v_rely, w_rel):
        return (self.c_x * (s_relx - self.s_relx0), self.c_y * (s_rely - self.s_rely0),
                ca.SX(0))


class SpringDamper(PartialXYCompliant, PartialElementaryConditionalHeatPortWithoutT):
    """PlanarMechanics' linear 2-D spring-damper along the world axes and in rotation:
    f_x = c_x·(s_relx − s_relx0) + d_x·v_relx, f_y = c_y·(s_rely − s_rely0) + d_y·v_rely
    [N],
    tau = c_phi·(phi_rel − phi_rel0) + d_phi·w_rel [N.m], all on frame_b (frame_a gets the
    opposite). Defaults: c_x = c_y = 1 N/m, c_phi = 1e5 N.m/rad, d_x = d_y = 1 N.s/m,
    d_phi = 1 N.m.s/rad (PlanarMechanics' start values).

    Records v_relx, v_rely [m/s], w_rel [rad/s], tau [N.m] and lossPower [W] =
    d_x·v_relx² + d_y·v_rely² + d_phi·w_rel² (PlanarMechanics leaves out the last term).
    Options as Spring; ``useHeatPort``: heatPort.Q_flow = −lossPower."""
    options = {"enableAssert": True, "stateSelect": StateSelect.default}
    c_x = Parameter(1.0, "N/m", "spring constant in x dir", nonnegative=True)
    c_y = Parameter(1.0, "N/m", "spring constant in y dir", nonnegative=True)
    c_phi = Parameter(1.0e5, "N.m/rad", "spring constant in phi dir", nonnegative=True)
    d_x = Parameter(1.0, "N.s/m", "damping constant in x dir", nonnegative=True)
    d_y = Parameter(1.0, "N.s/m", "damping constant in y dir", nonnegative=True)
    d_phi = Parameter(1.0, "N.m.s/rad", "damping constant in phi dir", nonnegative=True)
    s_relx0 = Parameter(0.0, "m", "unstretched spring length")
    s_rely0 = Parameter(0.0, "m", "unstretched spring length")
    phi_rel0 = Parameter(0.0, "rad", "unstretched spring angle")

    def forces(self, s_relx, s_rely, phi_rel, v_relx, v_rely, w_rel):
        return (self.c_x * (s_relx - self.s_relx0) + self.d_x * v_relx,
                self.c_y * (s_rely - self.s_rely0) + self.d_y * v_rely,
                self.c_phi * (phi_rel - self.phi_rel0) + self.d_phi * w_rel)

    def record(self, e, s_relx, s_rely, phi_rel, v_relx, v_rely, w_rel, f_x, f_y, tau):
        e.variable("v_relx", v_relx, "m/s", "spring velocity in x")
        e.variable("v_rely", v_rely, "m/s", "spring velocity in y")
        e.variable("w_rel", w_rel, "rad/s", "spring angular velocity")
        e.variable("tau", tau, "N.m", "torque between frames (= frame_b.t)")
        self._loss_power(e, self.d_x * v_relx ** 2 + self.d_y * v_rely ** 2
                         + self.d_phi * w_rel ** 2)


# ---- line-force elements ----------------------------------------------------------------
class PartialLineForce(Component):
    """A force along the line between the origins of frame_a and frame_b, no torque about
    them. ``length`` [m] is the distance between the origins, ``v`` = der(length) [m/s],
    e_rel the unit vector from frame_a to frame_b; subclasses give the tension
    ``tension(length, v)`` [N] (> 0 pulls the frames together): frame_b gets tension·e_rel,
    frame_a −tension·e_rel. The direction is regularized below ``s_small`` [m] (the element
    is singular at zero length, as in PlanarMechanics)."""
    partial = True
    s_small = Parameter(1e-10, "m", "prevent zero-division if distance between frame_a and "
                                    "frame_b is zero", positive=True)
    frame_a = Frame("left frame")
    frame_b = Frame("right frame")

    def tension(self, length, v):
        """The force [N] pulling the two frames together."""
        raise NotImplementedError

    def record(self, e, length, v, tension):
        """Record the variables of the element (subclasses)."""

    def physics(self, e):
        d = e.pos(self.frame_b)[:2] - e.pos(self.frame_a)[:2]
        dv = e.vel(self.frame_b)[:2] - e.vel(self.frame_a)[:2]
        length = ca.sqrt(d[0] ** 2 + d[1] ** 2)
        e_rel = d / ca.fmax(length, self.s_small)
        v = ca.dot(e_rel, dv)
        f = self.tension(length, v)
        fb = ca.vertcat(f * e_rel, 0)
        e.flow(self.frame_b, fb)
        e.flow(self.frame_a, -fb)
        e.variable("length", length, "m", "distance between the origin of frame_a and the "
                                          "origin of frame_b")
        e.variable("v", v, "m/s", "relative velocity along the line (= der(length))")
        self.record(e, length, v, f)


class Damper(PartialLineForce, PartialElementaryConditionalHeatPortWithoutT):
    """PlanarMechanics' linear damper acting as a line force between frame_a and frame_b:
    the force f = −d·v [N] (v = der(length)) acts on the origin of frame_b along the line
    from frame_a to frame_b, −f on frame_a. d [N.s/m], default 1. Records length [m], v,
    f [N] (PlanarMechanics' sign: f < 0 when the frames separate) and lossPower = −f·v [W].
    ``stateSelect`` is accepted (StateSelect); ``useHeatPort``: heatPort.Q_flow = −lossPower;
    ``enableAssert`` only False, PlanarMechanics' default (no run-time assertions yet)."""
    options = {"stateSelect": StateSelect.default,
               "enableAssert": Unavailable(False, "an assertion stopping the simulation when "
                                                  "the origins come closer than s_small: "
                                                  "acausal has no run-time assertions")}
    d = Parameter(1.0, "N.s/m", "damping constant", nonnegative=True)

    def tension(self, length, v):
        return self.d * v

    def record(self, e, length, v, tension):
        e.variable("f", -tension, "N", "force on frame_b along the line from frame_a")
        self._loss_power(e, tension * v)


class LineSpring(PartialLineForce):
    """Linear spring acting along the line between the origins of frame_a and frame_b (not in
    PlanarMechanics, whose Spring is an x/y spring; after MultiBody.Forces.Spring):
    f = c·(length − s_rel0) [N] is the tension (> 0 pulls the frames together: frame_b gets
    −f along e_rel from frame_a to frame_b, frame_a +f). c [N/m] (default 1), s_rel0 [m]
    unstretched length (default 0). Records length [m], v [m/s], f [N]."""
    c = Parameter(1.0, "N/m", "spring constant", nonnegative=True)
    s_rel0 = Parameter(0.0, "m", "unstretched spring length", nonnegative=True)

    def tension(self, length, v):
        return self.c * (length - self.s_rel0)

    def record(self, e, length, v, tension):
        e.variable("f", tension, "N", "spring force (tension > 0)")


class LineSpringDamper(PartialLineForce, PartialElementaryConditionalHeatPortWithoutT):
    """Linear spring and damper in parallel along the line between the origins of frame_a
    and frame_b (not in PlanarMechanics; after MultiBody.Forces.SpringDamperParallel):
    tension f = c·(length − s_rel0) + d·v [N], v = der(length). c [N/m], d [N.s/m]
    (defaults 1), s_rel0 [m] (default 0). Records length, v, f and lossPower = d·v² [W]."""
    c = Parameter(1.0, "N/m", "spring constant", nonnegative=True)
    d = Parameter(1.0, "N.s/m", "damping constant", nonnegative=True)
    s_rel0 = Parameter(0.0, "m", "unstretched spring length", nonnegative=True)

    def tension(self, length, v):
        return self.c * (length - self.s_rel0) + self.d * v

    def record(self, e, length, v, tension):
        e.variable("f", tension, "N", "spring-damper force (tension > 0)")
        self._loss_power(e, self.d * v ** 2)


# =========================================================================================
# Joints
# =========================================================================================
class _Joint(PartialDrivenJoint):
    """A joint between frame_a and frame_b with an optional 1-D drive (``useFlange``):
    ``axis`` follows the joint coordinate and ``support`` is fixed in the world (as in
    PlanarMechanics, the support is *not* fixed in the joint). Unconnected, the flanges are
    free (no drive force); connect them to the 1-D libraries to drive or load the joint.
    Each joint declares the two flanges of its domain (``drive_flanges``).
    ``stateSelect`` is accepted as a hint (see StateSelect)."""
    options = {"useFlange": False, "stateSelect": StateSelect.default}
    frame_a = Frame("frame the joint is fixed to")
    frame_b = Frame("frame moved by the joint")


class Revolute(_Joint):
    """Revolute joint: frame_b = frame_a rotated by phi [rad] about their common origin.

    Coordinate ``phi`` [rad], its rate ``w`` [rad/s], acceleration ``z`` [rad/s²]; t [N.m]
    the drive torque (= axis.tau; 0 without flange). ``useFlange=True`` adds the rotational
    flange ``axis`` (axis.phi = phi) and ``support`` (support.phi = 0, fixed in the world as
    in PlanarMechanics): a torque on axis acts on frame_b and, opposite, on frame_a.
    """
    frame_b = Frame("frame turned by phi")
    axis, support = drive_flanges(RotationalFlange, "rotational", "useFlange")

    def structure(self, s):
        phi = s.node("phi", ROTATIONAL, velocity="w", acceleration="z")
        s.revolute(self.frame_a, self.frame_b, phi)
        self._link_flange(s, phi)

    def physics(self, e):
        e.variable("t", self._drive_force(e), "N.m", "drive torque (= axis.tau)")


class Prismatic(_Joint):
    """Prismatic joint: frame_b = frame_a translated by s [m] along r (direction of the rod
    in frame_a, normalized here: e = r/|r|); no relative rotation.

    Coordinate ``s`` [m], ``v`` [m/s], ``a`` [m/s²]; f [N] the drive force (= axis.f; 0
    without flange). ``useFlange=True`` adds the translational flange ``axis`` (axis.s = s)
    and ``support`` (support.s = 0, fixed in the world). Difference from PlanarMechanics: r
    has the default {1, 0} (PlanarMechanics gives none)."""
    r = Parameter((1.0, 0.0), "m", "direction of the rod wrt. body system at phi=0")
    frame_b = Frame("frame moved by s")
    axis, support = drive_flanges(TranslationalFlange, "translational", "useFlange")

    def structure(self, s):
        e = unit_direction(self, "r", "(1, 0)")
        s_rel = s.node("s", TRANSLATIONAL, velocity="v", acceleration="a")
        s.prismatic(self.frame_a, self.frame_b, s_rel, e)
        self._link_flange(s, s_rel)

    def physics(self, e):
        e.variable("f", self._drive_force(e), "N", "drive force in direction of elongation "
                                                   "(= axis.f)")


# =========================================================================================
# Sources
# =========================================================================================
class _ForceInput(_Resolving):
    """Input signals force[1], force[2] [N] (x-, y-coordinates, resolved per
    ``resolveInFrame``) and torque [N.m], as PlanarMechanics 2."""

    force = VectorPort(RealInput, 2, "force vector [N], resolved in resolveInFrame")
    torque = RealInput("torque [N.m]")

    def _wrench(self, e) -> ca.SX:
        """(fx, fy, t) in world coordinates."""
        F = [e.input(p) for p in self.force]
        return ca.vertcat(_rot(self._angle(e), ca.vertcat(F[0], F[1])), e.input(self.torque))


class WorldForce(_ForceInput):
    """External force and torque on frame_b: the input signals force[1], force[2] [N] are the
    x-, y-coordinates of the force, resolved in frame_b (default), the world or
    frame_resolve (``resolveInFrame``: ResolveInFrameB), ``torque`` [N.m] the torque:
    frame_b.f = −(R·force), frame_b.t = −torque (the force acts on what frame_b is
    connected to)."""
    options = {"resolveInFrame": ResolveInFrameB.frame_b}
    frame_b = Frame("frame the force and torque act on", required=True)

    def physics(self, e):
        e.flow(self.frame_b, -self._wrench(e))


class WorldTorque(Component):
    """External torque ``torque`` [N.m] (input signal, counter-clockwise) on frame_b:
    frame_b.t = −torque. Not in PlanarMechanics (WorldForce has a torque input besides its
    force); after MultiBody.Forces.WorldTorque (a planar torque is the same in every
    frame)."""
    torque = RealInput("torque acting on frame_b [N.m]")
    frame_b = Frame("frame the torque acts on", required=True)

    def physics(self, e):
        tau = e.input(self.torque)
        e.flow(self.frame_b, ca.vertcat(0, 0, -tau))


class RelativeForce(_ForceInput):
    """Force and torque between frame_a and frame_b: force[1], force[2] [N] act on frame_b,
    resolved in frame_a (default), frame_b, the world or frame_resolve (``resolveInFrame``:
    ResolveInFrameAB), ``torque`` [N.m] is the torque on frame_b; frame_a gets the opposite:
    frame_b.f = −(R·force, torque) = −frame_a.f. As in PlanarMechanics the moment of the two
    forces about the origins is not balanced."""
    options = {"resolveInFrame": ResolveInFrameAB.frame_a}
    frame_a = Frame("frame the reaction acts on", required=True)
    frame_b = Frame("frame the force acts on", required=True)

    def physics(self, e):
        fb = self._wrench(e)
        e.flow(self.frame_b, -fb)
        e.flow(self.frame_a, fb)


# =========================================================================================
# Sensors
# =========================================================================================
class _AbsoluteSensor(_Resolving):
    """Measures frame_a (no force); vectors resolved per ``resolveInFrame``
    (ResolveInFrameA, default frame_a): x, y components by R(angle)ᵀ, the angular component
    unchanged."""
    options = {"resolveInFrame": ResolveInFrameA.frame_a}
    frame_a = Frame("coordinate system from which absolute kinematic quantities are "
                    "measured", required=True)

    def _resolved(self, e, w):
        """A world vector (x, y, angular) with x, y resolved in ``resolveInFrame``."""
        return ca.vertcat(_rot_t(self._angle(e), w[:2]), w[2])


class AbsolutePosition(_AbsoluteSensor):
    """Outputs r[1], r[2] [m], r[3] [rad]: the position of frame_a's origin resolved in
    ``resolveInFrame`` and its angle relative to that frame (PlanarMechanics: r[3] = 0 for
    frame_a, frame_a.phi for the world, frame_a.phi − frame_resolve.phi)."""
    r = VectorPort(RealOutput, 3, "absolute position [m] and angle [rad] of frame_a")

    def physics(self, e):
        r = e.pos(self.frame_a)
        phi = self._angle(e)
        _output_vector(e, self.r, ca.vertcat(_rot_t(phi, r[:2]), r[2] - phi))


class AbsoluteVelocity(_AbsoluteSensor):
    """Outputs v[1], v[2] [m/s], v[3] [rad/s]: der(x, y) of frame_a resolved in
    ``resolveInFrame`` (default frame_a) and der(phi)."""
    v = VectorPort(RealOutput, 3, "absolute velocity [m/s] and angular velocity [rad/s] of "
                                  "frame_a")

    def physics(self, e):
        _output_vector(e, self.v, self._resolved(e, e.vel(self.frame_a)))


class AbsoluteAcceleration(_AbsoluteSensor):
    """Outputs a[1], a[2] [m/s²], a[3] [rad/s²]: der(der(x, y)) of frame_a resolved in
    ``resolveInFrame`` (default frame_a) and der(der(phi))."""
    a = VectorPort(RealOutput, 3, "absolute acceleration [m/s2] and angular acceleration "
                                  "[rad/s2]")

    def physics(self, e):
        _output_vector(e, self.a, self._resolved(e, e.acc(self.frame_a)))


class _RelativeSensor(_Resolving):
    """Measures frame_b relative to frame_a (no force); ResolveInFrameAB, default frame_a."""
    options = {"resolveInFrame": ResolveInFrameAB.frame_a}
    frame_a = Frame("coordinate system a", required=True)
    frame_b = Frame("coordinate system b", required=True)

    def _r_rel(self, e, phi):
        """[R(phi)ᵀ·(r_b − r_a); phi_b − phi_a]."""
        d = e.pos(self.frame_b) - e.pos(self.frame_a)
        return ca.vertcat(_rot_t(phi, d[:2]), d[2])

    def _v_rel(self, e):
        """PlanarMechanics' relative velocity: der(r_rel resolved in frame_a), then resolved
        in resolveInFrame: [R(phi_out)ᵀ·R(phi_a)·der(R(phi_a)ᵀ·Δr); der(Δphi)]."""
        phi_a = e.pos(self.frame_a)[2]
        rd = e.der(self._r_rel(e, phi_a))
        return ca.vertcat(_rot_t(self._angle(e), _rot(phi_a, rd[:2])), rd[2])


class RelativePosition(_RelativeSensor):
    """Outputs r_rel[1], r_rel[2] [m] (frame_b's origin minus frame_a's, resolved in
    ``resolveInFrame``, default frame_a) and r_rel[3] = frame_b.phi − frame_a.phi [rad]."""

    r_rel = VectorPort(RealOutput, 3, "relative position [m] and angle [rad]")

    def physics(self, e):
        _output_vector(e, self.r_rel, self._r_rel(e, self._angle(e)))


class RelativeVelocity(_RelativeSensor):
    """Outputs v_rel[1..3]: the rate of the relative position as seen in frame_a,
    der(R(phi_a)ᵀ·(r_b − r_a)), resolved in ``resolveInFrame`` (default frame_a), and
    der(phi_b − phi_a) [rad/s] (PlanarMechanics' definition)."""

    v_rel = VectorPort(RealOutput, 3, "relative velocity [m/s] and angular velocity [rad/s]")

    def physics(self, e):
        _output_vector(e, self.v_rel, self._v_rel(e))


class RelativeAcceleration(_RelativeSensor):
    """Outputs a_rel[1..3] = der(v_rel) of RelativeVelocity with the same ``resolveInFrame``
    (PlanarMechanics' definition: for frame_a, the relative acceleration seen in frame_a)."""

    a_rel = VectorPort(RealOutput, 3, "relative acceleration [m/s2] and angular "
                                      "acceleration [rad/s2]")

    def physics(self, e):
        _output_vector(e, self.a_rel, e.der(self._v_rel(e)))


class Distance(Component):
    """Output ``distance`` [m] between the origins of frame_a and frame_b (no force)."""
    frame_a = Frame("coordinate system a", required=True)
    frame_b = Frame("coordinate system b", required=True)
    distance = RealOutput("distance between the origin of frame_a and the origin of frame_b "
                          "[m]")

    def physics(self, e):
        d = e.pos(self.frame_b)[:2] - e.pos(self.frame_a)[:2]
        e.output(self.distance, ca.sqrt(d[0] ** 2 + d[1] ** 2))


class _InlineSensor(Component):
    """frame_a and frame_b rigidly joined (same origin and angle): the cut force and torque
    pass through. Measured values may feed outputs and states, not forces of the model."""
    frame_a = Frame("coordinate system a", required=True)
    frame_b = Frame("coordinate system b", required=True)

    def structure(self, s):
        s.transform(self.frame_a, self.frame_b, (0.0, 0.0), 0.0, f"{self.path}: rigid")


class Power(_InlineSensor):
    """Measures the power flowing from frame_a to frame_b (rigidly joined): output
    ``power`` [W] = {frame_a.fx, frame_a.fy}·der({frame_a.x, frame_a.y}) +
    frame_a.t·der(frame_a.phi)."""
    power = RealOutput("power at frame_a as output signal [W]")

    def physics(self, e):
        f, v = e.cut_flow(self.frame_a), e.vel(self.frame_a)
        e.output(self.power, f[0] * v[0] + f[1] * v[1] + f[2] * v[2])


class _CutSensor(_InlineSensor):
    """An inline sensor of the cut force or torque: ``positiveSign`` (default True) returns
    frame_a's cut flow, else frame_b's (its negative)."""
    options = {"positiveSign": True}

    def _cut(self, e):
        f = e.cut_flow(self.frame_a)
        return f if self.positiveSign else -f


class _CutForceOutputs(_Resolving, _CutSensor):
    """Output ``force[1..2]`` [N]: frame_a.fx, fy (× −1 with positiveSign=False) resolved in
    ``resolveInFrame`` (ResolveInFrameA: world, frame_a (default), frame_resolve)."""
    options = {"resolveInFrame": ResolveInFrameA.frame_a}

    force = VectorPort(RealOutput, 2, "cut force resolved in resolveInFrame [N]")

    def physics(self, e):
        f = self._cut(e)
        _output_vector(e, self.force, _rot_t(self._angle(e), f[:2]))


class CutForce(_CutForceOutputs):
    """Measures the cut force between frame_a and frame_b (rigidly joined): outputs
    force[1], force[2] [N] = {frame_a.fx, frame_a.fy} (the force that what is connected to
    frame_a exerts on what is connected to frame_b), resolved in ``resolveInFrame``
    (default frame_a); with positiveSign=False the negative (= frame_b's)."""


class CutTorque(_CutSensor):
    """Measures the cut torque between frame_a and frame_b (rigidly joined): output
    ``torque`` [N.m] = frame_a.t (with positiveSign=False: frame_b.t)."""
    torque = RealOutput("cut torque [N.m]")

    def physics(self, e):
        e.output(self.torque, self._cut(e)[2])


class CutForceAndTorque(_CutForceOutputs):
    """CutForce and CutTorque in one: outputs force[1..2] [N] (resolved in
    ``resolveInFrame``) and torque [N.m] = frame_a.t (signs by positiveSign)."""
    torque = RealOutput("cut torque [N.m]")

    def physics(self, e):
        super().physics(e)
        e.output(self.torque, self._cut(e)[2])
