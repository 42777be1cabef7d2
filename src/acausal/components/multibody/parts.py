"""Parts (Modelica.Mechanics.MultiBody.Parts): the fixed frames, rigid bodies and point
masses of 3-D multibody systems, with MSL's names, parameters, defaults and frame
conventions.

A body contributes its kinetic energy ½m|v_CM|² + ½wᵀIw (v, w the twist of frame_a resolved
in frame_a, I about the centre of mass, parallel to frame_a) and its potential energy in
the World's gravity field; the compiler derives the Newton–Euler equations from them
(Lagrange's equations by AD), so MSL's frame_a.f = m(a_CM − g) and frame_a.t equations are
the reactions recorded at the frames connected to it (a joint's frame_b.f, t). Each body
records MSL's variables: r_0, v_0, a_0 [m, m/s, m/s²] (frame_a, world frame), w_a, z_a
[rad/s, rad/s²] (resolved in frame_a) and g_0 (gravity at the centre of mass); BodyShape,
BodyBox and BodyCylinder record the last three under ``body.`` as their MSL inner Body.

A body with no joint path to the world moves freely with MSL's states and start values
(``_BodyStates``). ``animation`` only keeps a part out of the animation
(``interfaces.Animated``). Not here yet: the other visualization parameters. RollingWheel
and RollingWheelSet are in ``rolling``.
"""
from __future__ import annotations

from enum import Enum

import casadi as ca

from ... import frames
from ...core import Parameter, RotationalFlange, StateSelect, Unavailable
from ...core.ports import ROTATIONAL
from ...core.component import who
from ...errors import ParameterError
from ..interfaces import unit_direction
from .interfaces import Animated, Frame_a, Frame_b
from .world import World

__all__ = ["Fixed", "FixedTranslation", "RotationTypes", "FixedRotation", "Body", "BodyShape",
           "BodyBox", "BodyCylinder", "PointMass"]

_I_DOC = "inertia tensor (resolved in center of mass, parallel to frame_a)"


def _record(e, name: str, v, unit: str, description: str = "") -> None:
    """Record the 3-vector v as name[1], name[2], name[3]."""
    for k, x in enumerate(ca.vertsplit(v)):
        e.variable(f"{name}[{k + 1}]", x, unit, description)


def _frame_kinematics(e, frame):
    """(r_0, T, v_0, a_0, v, w, z) of a 3-D frame: position, orientation and world velocity
    and acceleration, and its twist (v, w) and angular acceleration z resolved in it."""
    r0, T = frames.parts(e.pos(frame))
    vel, acc = e.vel(frame), e.acc(frame)
    v, w, vd, z = vel[:3], vel[3:6], acc[:3], acc[3:6]
    return r0, T, frames.resolve1(T, v), frames.resolve1(T, vd + ca.cross(w, v)), v, w, z


def rigid_body(e, frame, m, r_CM, I, prefix: str = "") -> None:
    """Kinetic and potential energy of a rigid body fixed to the 3-D ``frame``: mass m [kg]
    at r_CM [m] (resolved in the frame), inertia tensor I [kg.m²] about the centre of mass
    (parallel to the frame); records MSL's Body variables (w_a, z_a, g_0 under ``prefix``)."""
    r0, T, v0, a0, v, w, z = _frame_kinematics(e, frame)
    e.rigid_body(frame, m, I, r_CM=r_CM)           # ½m|v + w×r_CM|² + ½wᵀIw
    world = e.outer(World)
    r_cm = r0 + frames.resolve1(T, r_CM)
    e.potential_energy(m * world.potential(r_cm))
    _record(e, "r_0", r0, "m", "position vector from origin of world frame to origin of "
                               "frame_a")
    _record(e, "v_0", v0, "m/s", "absolute velocity of frame_a, resolved in world frame")
    _record(e, "a_0", a0, "m/s2", "absolute acceleration of frame_a resolved in world frame")
    _record(e, prefix + "w_a", w, "rad/s", "absolute angular velocity of frame_a resolved "
                                           "in frame_a")
    _record(e, prefix + "z_a", z, "rad/s2", "absolute angular acceleration of frame_a "
                                            "resolved in frame_a")
    _record(e, prefix + "g_0", world.gravity_acceleration(r_cm), "m/s2",
            "gravity acceleration resolved in world frame")


def check_sequence(c, name: str) -> None:
    """A rotation sequence parameter (MSL's Types.RotationSequence): each axis 1, 2 or 3,
    no two consecutive axes equal; else a ParameterError naming it."""
    seq = getattr(c, name)
    if any(k not in (1.0, 2.0, 3.0) for k in seq) or seq[1] in (seq[0], seq[2]):
        raise ParameterError(f"{who(c)}: {name} = {seq}: each axis must be 1, 2 or 3 and no "
                             f"two consecutive axes equal, e.g. (1, 2, 3)")


def _inertia(c) -> ca.SX:
    """MSL's I[3,3] = [I_11, I_21, I_31; I_21, I_22, I_32; I_31, I_32, I_33]."""
    return ca.vertcat(ca.horzcat(c.I_11, c.I_21, c.I_31), ca.horzcat(c.I_21, c.I_22, c.I_32),
                      ca.horzcat(c.I_31, c.I_32, c.I_33))


class Fixed(Animated):
    """Frame ``frame_b`` fixed in the world frame at position r [m] (default 0), with the
    world's orientation."""
    r = Parameter((0.0, 0.0, 0.0), "m", "position vector from world frame to frame_b, "
                                        "resolved in world frame")
    frame_b = Frame_b("coordinate system fixed in the world frame")

    def structure(self, s):
        s.transform(None, self.frame_b, self.r)


class FixedTranslation(Animated):
    """Fixed translation of frame_b with respect to frame_a: frame_b.r_0 = frame_a.r_0 +
    resolve1(frame_a.R, r), same orientation; massless. r [m] has no default (as in MSL)."""
    required = ("r",)
    r = Parameter((0.0, 0.0, 0.0), "m", "vector from frame_a to frame_b resolved in frame_a")
    frame_a = Frame_a("coordinate system fixed to the component with one cut-force and "
                      "cut-torque")
    frame_b = Frame_b("coordinate system fixed to the component with one cut-force and "
                      "cut-torque")

    def structure(self, s):
        s.transform(self.frame_a, self.frame_b, self.r)


class RotationTypes(str, Enum):
    """How FixedRotation's rotation is given (MultiBody.Types.RotationTypes)."""
    RotationAxis = "RotationAxis"
    TwoAxesVectors = "TwoAxesVectors"
    PlanarRotationSequence = "PlanarRotationSequence"


class FixedRotation(Animated):
    """Fixed translation r [m] (resolved in frame_a) and fixed rotation of frame_b with
    respect to frame_a; massless. ``rotationType`` (RotationTypes):

    - RotationAxis (default): by ``angle`` [deg] about the axis n (default {1, 0, 0});
    - TwoAxesVectors: frame_b's x axis along n_x, its y axis in the plane of n_x and n_y
      (Frames.from_nxy);
    - PlanarRotationSequence: rotations by ``angles`` [deg] about the axes ``sequence``
      (each 1, 2 or 3; default {1, 2, 3}), one after the other (Frames.axesRotations).

    Angles are in degrees, as MSL's Angle_deg parameters."""
    options = {"rotationType": RotationTypes.RotationAxis}
    r = Parameter((0.0, 0.0, 0.0), "m", "vector from frame_a to frame_b resolved in frame_a")
    n = Parameter((1.0, 0.0, 0.0), "1", "axis of rotation in frame_a (= same as in frame_b)")
    angle = Parameter(0.0, "deg", "angle to rotate frame_a around axis n into frame_b")
    n_x = Parameter((1.0, 0.0, 0.0), "1", "vector along x-axis of frame_b resolved in frame_a")
    n_y = Parameter((0.0, 1.0, 0.0), "1", "vector along y-axis of frame_b resolved in frame_a")
    sequence = Parameter((1.0, 2.0, 3.0), "1", "sequence of rotations")
    angles = Parameter((0.0, 0.0, 0.0), "deg", "rotation angles around the axes defined in "
                                               "'sequence'")
    frame_a = Frame_a("coordinate system fixed to the component with one cut-force and "
                      "cut-torque")
    frame_b = Frame_b("coordinate system fixed to the component with one cut-force and "
                      "cut-torque")

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        if self.rotationType is RotationTypes.PlanarRotationSequence:
            check_sequence(self, "sequence")

    def R_rel(self) -> ca.SX:
        """The relative orientation T from frame_a to frame_b."""
        kind = self.rotationType
        if kind is RotationTypes.RotationAxis:
            return frames.planar_rotation(unit_direction(self, "n", "(0, 0, 1)"),
                                          self.angle * ca.pi / 180)
        if kind is RotationTypes.TwoAxesVectors:
            return frames.from_nxy(self.n_x, self.n_y)
        T = ca.SX.eye(3)
        for k in range(3):
            axis = ca.vertcat(*[self.sequence[k] == i for i in (1, 2, 3)])
            T = ca.mtimes(frames.planar_rotation(axis, self.angles[k] * ca.pi / 180), T)
        return T

    def structure(self, s):
        s.transform(self.frame_a, self.frame_b, self.r, T=self.R_rel())


class _BodyStates(Animated):
    """A body's states when its frame_a has no path through joints to the world (MSL's
    free body, the implicit free joint: ``compiler.charts``): frame_a.r_0 [m], v_0 [m/s]
    (world frame), the quaternion Q from the world to frame_a and w_a [rad/s] (resolved in
    frame_a); 13 states. Their start values as MSL's: ``r_0_start``, ``v_0_start`` (MSL's
    r_0(start=...), v_0(start=...)), the orientation by ``angles_start`` [rad] about the
    axes ``sequence_start``, ``w_0_start`` [rad/s] (resolved in the world). The ``*_fixed``
    switches are accepted: the start values are always used (``x0``/``guess`` by state name
    take precedence); MSL's z_0_start (an acceleration) is not accepted.
    ``useQuaternions=False`` (angles as states) and ``enforceStates`` are accepted and
    change nothing: the states are always quaternions, never singular; the angles in
    ``sequence_angleStates`` from the world to frame_a are recorded as ``phi`` [rad], their
    rates as ``phi_d`` (outputs, undefined at gimbal lock; all three phi, and phi_d, given
    by name in ``x0`` or ``guess`` set Q and w_a). Bodies moved by joints have no states of their own
    (these start values are then unused)."""
    options = {"enforceStates": False, "useQuaternions": True, "angles_fixed": False,
               "w_0_fixed": False, "z_0_fixed": False}
    r_0_start = Parameter((0.0, 0.0, 0.0), "m", "initial position of frame_a, resolved in "
                                                "world frame (MSL's r_0(start=...))")
    v_0_start = Parameter((0.0, 0.0, 0.0), "m/s", "initial velocity of frame_a, resolved in "
                                                  "world frame (MSL's v_0(start=...))")
    angles_start = Parameter((0.0, 0.0, 0.0), "rad", "initial values of angles to rotate "
                                                     "world frame around 'sequence_start' "
                                                     "axes into frame_a")
    sequence_start = Parameter((1.0, 2.0, 3.0), "1", "sequence of rotations to rotate world "
                                                     "frame into frame_a at initial time")
    w_0_start = Parameter((0.0, 0.0, 0.0), "rad/s", "initial values of angular velocity of "
                                                    "frame_a resolved in world frame")
    sequence_angleStates = Parameter((1.0, 2.0, 3.0), "1", "sequence of rotations to rotate "
                                                           "world frame into frame_a around "
                                                           "the 3 angles recorded as phi")
    #: prefix of the state names Q and w_a (MSL's BodyShape has them in its inner ``body``)
    _states_in = ""

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        check_sequence(self, "sequence_start")
        check_sequence(self, "sequence_angleStates")

    def structure(self, s):
        T0 = frames.axes_rotations(self.sequence_start, self.angles_start)
        b = self._states_in
        s.free_frame(self.frame_a, r=tuple(f"frame_a.r_0[{i}]" for i in (1, 2, 3)),
                     v=tuple(f"v_0[{i}]" for i in (1, 2, 3)),
                     Q=tuple(f"{b}Q[{i}]" for i in (1, 2, 3, 4)),
                     w=tuple(f"{b}w_a[{i}]" for i in (1, 2, 3)),
                     start={"r": ca.vertcat(self.r_0_start), "v": ca.vertcat(self.v_0_start),
                            "Q": frames.axes_rotations_Q(self.sequence_start,
                                                         self.angles_start),
                            "w": ca.mtimes(T0, ca.vertcat(self.w_0_start))},
                     angles=tuple(f"{b}phi[{i}]" for i in (1, 2, 3)),
                     angle_rates=tuple(f"{b}phi_d[{i}]" for i in (1, 2, 3)),
                     sequence=self.sequence_angleStates)

    def _angles(self, e) -> None:
        _, T = frames.parts(e.pos(self.frame_a))
        phi = frames.axes_rotations_angles(T, self.sequence_angleStates)
        _record(e, self._states_in + "phi", phi, "rad", "angles from the world frame to "
                                                         "frame_a in the sequence "
                                                         "sequence_angleStates")
        _record(e, self._states_in + "phi_d", e.der(phi), "rad/s", "= der(phi)")


class _Body(_BodyStates):
    """Mass properties of MSL's Body: m [kg], r_CM [m], I_11..I_32 [kg.m²] (defaults 0.001
    on the diagonal, 0 off it)."""
    r_CM = Parameter((0.0, 0.0, 0.0), "m", "vector from frame_a to center of mass, resolved "
                                           "in frame_a")
    m = Parameter(1.0, "kg", "mass of rigid body", nonnegative=True)
    I_11 = Parameter(0.001, "kg.m2", f"element (1,1) of {_I_DOC}", nonnegative=True)
    I_22 = Parameter(0.001, "kg.m2", f"element (2,2) of {_I_DOC}", nonnegative=True)
    I_33 = Parameter(0.001, "kg.m2", f"element (3,3) of {_I_DOC}", nonnegative=True)
    I_21 = Parameter(0.0, "kg.m2", f"element (2,1) of {_I_DOC}")
    I_31 = Parameter(0.0, "kg.m2", f"element (3,1) of {_I_DOC}")
    I_32 = Parameter(0.0, "kg.m2", f"element (3,2) of {_I_DOC}")
    frame_a = Frame_a("coordinate system fixed at body")


class Body(_Body):
    """Rigid body with mass m [kg], centre of mass at r_CM [m] from frame_a (resolved in
    frame_a) and inertia tensor I_11..I_32 [kg.m²] about the centre of mass, parallel to
    frame_a; gravity from the model's World. m and r_CM have no default (as in MSL).
    Records r_0, v_0, a_0, w_a, z_a, g_0 (see the module)."""
    required = ("r_CM", "m")

    def physics(self, e):
        rigid_body(e, self.frame_a, self.m, self.r_CM, _inertia(self))
        self._angles(e)


class BodyShape(_Body):
    """Rigid body with two frames: frame_b at r [m] from frame_a (resolved in frame_a,
    rigidly), mass properties as Body. r, r_CM, m have no default (as in MSL). Records
    r_0, v_0, a_0 and body.w_a, body.z_a, body.g_0."""
    required = ("r", "r_CM", "m")
    r = Parameter((0.0, 0.0, 0.0), "m", "vector from frame_a to frame_b resolved in frame_a")
    frame_b = Frame_b("coordinate system fixed at body")
    _states_in = "body."

    def structure(self, s):
        super().structure(s)
        s.transform(self.frame_a, self.frame_b, self.r)

    def physics(self, e):
        rigid_body(e, self.frame_a, self.m, self.r_CM, _inertia(self), "body.")
        self._angles(e)


class _ShapedBody(_BodyStates):
    """A body of homogeneous ``density`` [kg/m³] (default 7700, steel) shaped along
    ``lengthDirection`` from r_shape [m] (both resolved in frame_a), with frame_b at r [m]
    from frame_a. Defaults that follow other parameters (MSL's lengthDirection = r −
    r_shape, length = |r − r_shape|, width = length/world.defaultWidthFraction (20), ...)
    are taken when the component is built; changed later (``params=``) they do not follow."""
    required = ("r",)
    r = Parameter((0.1, 0.0, 0.0), "m", "vector from frame_a to frame_b resolved in frame_a")
    r_shape = Parameter((0.0, 0.0, 0.0), "m", "vector from frame_a to shape origin, resolved "
                                              "in frame_a")
    lengthDirection = Parameter((1.0, 0.0, 0.0), "1", "vector in length direction, resolved "
                                                      "in frame_a")
    length = Parameter(0.1, "m", "length of the shape", nonnegative=True)
    density = Parameter(7700.0, "kg/m3", "density of the shape (e.g., steel: 7700 .. 7900, "
                                         "wood : 400 .. 800)", positive=True)
    frame_a = Frame_a("coordinate system fixed to the component with one cut-force and "
                      "cut-torque")
    frame_b = Frame_b("coordinate system fixed to the component with one cut-force and "
                      "cut-torque")
    #: defaults that follow other parameters, in order: (name, values -> default)
    _follow = (("lengthDirection", lambda v: tuple(a - b for a, b in zip(v["r"], v["r_shape"]))),
               ("length", lambda v: sum((a - b) ** 2 for a, b in zip(v["r"], v["r_shape"]))
                ** 0.5))

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        for pname, default in self._follow:
            if pname not in params:
                setattr(self, pname, default(self._values))

    _states_in = "body."

    def mass_properties(self):
        """(m [kg], r_CM [m], I [kg.m²] about the centre of mass, parallel to frame_a)."""
        raise NotImplementedError

    def structure(self, s):
        super().structure(s)
        s.transform(self.frame_a, self.frame_b, self.r)

    def physics(self, e):
        m, r_CM, I = self.mass_properties()
        rigid_body(e, self.frame_a, m, r_CM, I, "body.")
        self._angles(e)
        e.variable("m", m, "kg", "mass")
        _record(e, "r_CM", r_CM, "m", "position vector from origin of frame_a to center of "
                                      "mass, resolved in frame_a")

    def _r_CM(self):
        return self.r_shape + unit_direction(self, "lengthDirection", "(1, 0, 0)") \
            * self.length / 2


class BodyBox(_ShapedBody):
    """Rigid body with box shape (MSL's BodyBox): a box of ``length`` × ``width`` ×
    ``height`` [m] along lengthDirection (and widthDirection, default {0, 1, 0}), with an
    optional rectangular hole innerWidth × innerHeight [m]; mass and inertia from the
    geometry and density as MSL computes them (m = density·length·(width·height −
    innerWidth·innerHeight), I from the box's principal values rotated by
    from_nxy(r, widthDirection)). Defaults: width = length/20, height = width,
    innerWidth = 0, innerHeight = innerWidth."""
    widthDirection = Parameter((0.0, 1.0, 0.0), "1", "vector in width direction of box, "
                                                     "resolved in frame_a")
    width = Parameter(0.005, "m", "width of box", nonnegative=True)
    height = Parameter(0.005, "m", "height of box", nonnegative=True)
    innerWidth = Parameter(0.0, "m", "width of inner box surface (0 <= innerWidth <= width)",
                           nonnegative=True)
    innerHeight = Parameter(0.0, "m", "height of inner box surface (0 <= innerHeight <= "
                                      "height)", nonnegative=True)

    _follow = _ShapedBody._follow + (("width", lambda v: v["length"] / 20),
                                     ("height", lambda v: v["width"]),
                                     ("innerHeight", lambda v: v["innerWidth"]))

    def mass_properties(self):
        L, w, h, wi, hi = self.length, self.width, self.height, self.innerWidth, \
            self.innerHeight
        mo, mi = self.density * L * w * h, self.density * L * wi * hi
        D = ca.diag(ca.vertcat(mo * (w * w + h * h) - mi * (wi * wi + hi * hi),
                               mo * (L * L + h * h) - mi * (L * L + hi * hi),
                               mo * (L * L + w * w) - mi * (L * L + wi * wi)) / 12)
        R = frames.from_nxy(self.r, self.widthDirection)
        return mo - mi, self._r_CM(), frames.resolve_dyade1(R, D)


class BodyCylinder(_ShapedBody):
    """Rigid body with cylinder shape (MSL's BodyCylinder): a cylinder of ``length`` and
    ``diameter`` [m] along lengthDirection with an optional bore innerDiameter [m]; mass and
    inertia from the geometry and density as MSL computes them (m = density·π·length·(r² −
    r_i²), I from the principal values ((mo·r² − mi·r_i²)/2, I22, I22) rotated by
    from_nxy(r, {0, 1, 0})). Default diameter = length/20."""
    diameter = Parameter(0.005, "m", "diameter of cylinder", nonnegative=True)
    innerDiameter = Parameter(0.0, "m", "inner diameter of cylinder (0 <= innerDiameter <= "
                                        "diameter)", nonnegative=True)
    _follow = _ShapedBody._follow + (("diameter", lambda v: v["length"] / 20),)

    def mass_properties(self):
        L = self.length
        ro, ri = self.diameter / 2, self.innerDiameter / 2
        mo, mi = self.density * ca.pi * L * ro * ro, self.density * ca.pi * L * ri * ri
        I22 = (mo * (L * L + 3 * ro * ro) - mi * (L * L + 3 * ri * ri)) / 12
        D = ca.diag(ca.vertcat((mo * ro * ro - mi * ri * ri) / 2, I22, I22))
        R = frames.from_nxy(self.r, (0.0, 1.0, 0.0))
        return mo - mi, self._r_CM(), frames.resolve_dyade1(R, D)


class PointMass(Animated):
    """Rigid body whose mass m [kg] is concentrated at the origin of frame_a (no inertia:
    frame_a.t = 0). m has no default (as in MSL). Records r_0, v_0, a_0. A PointMass with
    no path through joints to the world moves freely with the states frame_a.r_0 [m] and
    v_0 [m/s] (world frame; start values ``r_0_start``, ``v_0_start``: MSL's
    r_0(start=...), v_0(start=...)), its frame_a keeping the world's orientation (MSL
    leaves it undetermined; nothing depends on it). ``stateSelect`` is accepted (a hint,
    StateSelect)."""
    options = {"stateSelect": StateSelect.avoid}
    required = ("m",)
    m = Parameter(1.0, "kg", "mass of mass point", nonnegative=True)
    r_0_start = Parameter((0.0, 0.0, 0.0), "m", "initial position of frame_a, resolved in "
                                                "world frame (MSL's r_0(start=...))")
    v_0_start = Parameter((0.0, 0.0, 0.0), "m/s", "initial velocity of frame_a, resolved in "
                                                  "world frame (MSL's v_0(start=...))")
    frame_a = Frame_a("coordinate system fixed at center of mass point")

    def structure(self, s):
        s.free_frame(self.frame_a, r=tuple(f"frame_a.r_0[{i}]" for i in (1, 2, 3)),
                     v=tuple(f"v_0[{i}]" for i in (1, 2, 3)), rotation=False,
                     start={"r": ca.vertcat(self.r_0_start), "v": ca.vertcat(self.v_0_start)})

    def physics(self, e):
        r0, T, v0, a0, v, _, _ = _frame_kinematics(e, self.frame_a)
        e.rigid_body(self.frame_a, self.m, ca.SX.zeros(3, 3))       # ½m|v|²
        e.potential_energy(self.m * e.outer(World).potential(r0))
        _record(e, "r_0", r0, "m", "position vector from origin of world frame to origin of "
                                   "frame_a, resolved in world frame")
        _record(e, "v_0", v0, "m/s", "absolute velocity of frame_a, resolved in world frame")
        _record(e, "a_0", a0, "m/s2", "absolute acceleration of frame_a resolved in world "
                                      "frame")


# ---- 1-D drive trains on 3-D parts ---------------------------------------------------------
class Rotor1D(Animated):
    """1-D inertia J [kg.m²] rotating about the axis n (resolved in frame_a, default
    {1, 0, 0}) in a housing fixed at frame_a (MSL's Rotor1D with
    world.driveTrainMechanics3D = true and exact = true): phi [rad] is the rotor angle
    relative to frame_a (= flange_a.phi = flange_b.phi), w = der(phi), a = der(w).

    As in MSL, the rotor's mass, centre of mass and inertia rotating with the housing belong
    to a body fixed to the housing; Rotor1D adds the kinetic energy of the rotation relative
    to it, ½J·w² + J·w·(e·w_a) (e = n/|n|, w_a the housing's angular velocity resolved in
    frame_a). Lagrange's equations of it are MSL's: J·(a + e·der(w_a)) = flange_a.tau +
    flange_b.tau, and on the housing the gyroscopic torque w_a × (J·e·w) with the axial
    reaction; the 1-D torques between rotor and a support on a Mounting1D on the same frame
    reach the housing by virtual work of the relative angle (MSL: through Mounting1D; the
    sums on the frame are the same).

    ``exact`` only True (MSL's default: False neglects the housing's acceleration in the
    rotor's equation, which no energy gives); ``r_center``, ``cylinderLength``,
    ``cylinderDiameter`` are accepted for animation."""
    options = {"stateSelect": StateSelect.default,
               "exact": Unavailable(True, "exact=false (the rotor's equation without the "
                                          "housing's acceleration)")}
    J = Parameter(1.0, "kg.m2", "moment of inertia of rotor around its axis of rotation",
                  nonnegative=True)
    n = Parameter((1.0, 0.0, 0.0), "1", "axis of rotation resolved in frame_a")
    r_center = Parameter((0.0, 0.0, 0.0), "m", "position vector from origin of frame_a to "
                                               "center of cylinder")
    cylinderLength = Parameter(0.2, "m", "length of cylinder representing the rotor",
                               nonnegative=True)
    cylinderDiameter = Parameter(0.2, "m", "diameter of cylinder representing the rotor",
                                 nonnegative=True)
    flange_a = RotationalFlange("(left) driving flange (flange axis directed INTO cut plane)")
    flange_b = RotationalFlange("(right) driven flange (flange axis directed OUT OF cut "
                                "plane)")
    frame_a = Frame_a("frame in which rotor housing is fixed", required=True)

    def structure(self, s):
        phi = s.node("phi", ROTATIONAL, velocity="w", acceleration="a")
        s.linear({self.flange_a: 1.0, phi: -1.0}, 0.0)
        s.linear({self.flange_b: 1.0, phi: -1.0}, 0.0)

    def physics(self, e):
        w = e.vel(e.node("phi"))
        e_axis = unit_direction(self, "n", "(1, 0, 0)")
        w_a = e.vel(self.frame_a)[3:6]
        e.kinetic_energy(0.5 * self.J * w ** 2 + self.J * w * ca.dot(e_axis, w_a))
        _record(e, "rotorWith3DEffects.w_a", w_a, "rad/s", "angular velocity of frame_a, "
                                                           "resolved in frame_a")


class Mounting1D(Animated):
    """Housing of a 1-D drive train fixed at frame_a (MSL's Mounting1D with
    world.driveTrainMechanics3D = true): flange_b.phi = phi0 [rad] (default 0), the angle
    of the 1-D supports relative to the housing; n (default {1, 0, 0}) the axis of the
    support torque, resolved in frame_a.

    The 1-D angles are relative to the housing, so a torque between a Rotor1D (or a
    Revolute's axis) and a support on this mounting does its virtual work through the
    relative angle: its reaction on the housing is already in the equations (MSL writes it
    here, frame_a.t = −n·flange_b.tau; with the Rotor1D and the Mounting1D on one frame the
    sums are equal). A Mounting1D on another frame than the rotor it supports (MSL puts the
    support torque on that other frame) is not distinguished: the reaction stays with the
    rotor's frame."""
    phi0 = Parameter(0.0, "rad", "fixed offset angle of housing")
    n = Parameter((1.0, 0.0, 0.0), "1", "axis of rotation = axis of support torque "
                                        "(resolved in frame_a)")
    flange_b = RotationalFlange("(right) flange fixed in housing")
    frame_a = Frame_a("frame in which housing is fixed", required=True)

    def structure(self, s):
        s.linear({self.flange_b: 1.0}, self.phi0, f"{self.path}: flange_b.phi = phi0")
