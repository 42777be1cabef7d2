"""Joint assemblies that close a kinematic loop analytically
(Modelica.Mechanics.MultiBody.Joints.Assemblies): JointSSP, JointSSR, JointUSR, JointUSP,
JointRRR and JointRRP, and JointUPS, with MSL's names, parameters, defaults and sign
conventions.

As in MSL, the assembly computes the coordinate of its joint with a length constraint
(MSL's Internal.PrismaticWithLengthConstraint / RevoluteWithLengthConstraint) in closed
form from the positions of its two outer frames, so the loop adds no constraint row and
no multiplier: the tree fires the assembly's relation (``StructureBuilder.relation``) and
its reaction is the rod force. Where the loop is arranged so that the outer frames are not
both known before the joint's coordinate (the closed form cannot fire), the same relation
closes the loop as a constraint row instead, numerically.

MSL picks the branch of the closed form (one of two roots) at initialization, the one
nearest to the guess (s_guess, phi_guess); here it is the option ``positiveBranch``
(default True: MSL's positive branch, the one of its usual assembly). Where the two roots
meet, the loop is singular: the run stops there with MSL's message (``k1a`` reaches 0).
"""
from __future__ import annotations

import math

import casadi as ca

from ... import frames
from ...core import Parameter, RotationalFlange, TranslationalFlange
from ...core.ports import ROTATIONAL, TRANSLATIONAL
from ..interfaces import unit_direction
from .interfaces import Animated, Frame_a, Frame_b
from .loop_joints import rod_with_mass, universal_rod_frame

__all__ = ["JointSSP", "JointSSR", "JointUSR", "JointRRR", "JointUSP", "JointRRP",
           "JointUPS", "length_constraint_distance", "length_constraint_angle"]


def length_constraint_distance(r_a, r_b, e, length, positive: bool):
    """MSL's PrismaticWithLengthConstraint: the distance d [m] along the unit axis e with
    |d·e + r_b − r_a| = length [m] (r_a, r_b [m] resolved in the prismatic joint's
    frames): d = −B/2 ± sqrt(B²/4 − C), B = 2e·(r_b − r_a), C = |r_b − r_a|² − length²;
    and k1a = B²/4 − C [m²], positive where the loop has two solutions (0: singular)."""
    rbra = r_b - r_a
    k1 = ca.dot(e, rbra)
    k1a = k1 * k1 - (ca.dot(rbra, rbra) - length * length)
    k2 = ca.sqrt(ca.fmax(k1a, 1e-12))
    return -k1 + (k2 if positive else -k2), k1a


def length_constraint_angle(r_a, r_b, e, length, positive: bool):
    """MSL's RevoluteWithLengthConstraint: the angle [rad] of rotation about the unit axis e
    with |r_b − T_rel(angle)·r_a| = length [m] (r_a resolved in the revolute's frame_a,
    r_b in its frame_b): A·cos + B·sin + C = 0, A = −2(r_b·r_a − (e·r_b)(e·r_a)), B =
    2r_b·(e × r_a), C = |r_a|² + |r_b|² − length² − 2(e·r_b)(e·r_a), solved by atan2 in
    (−π, π]; and k1a = A² + B² − C² [m⁴], positive where the loop has two solutions."""
    e_r_a, e_r_b = ca.dot(e, r_a), ca.dot(e, r_b)
    A = -2 * (ca.dot(r_b, r_a) - e_r_b * e_r_a)
    B = 2 * ca.dot(r_b, ca.cross(e, r_a))
    C = ca.dot(r_a, r_a) + ca.dot(r_b, r_b) - length * length - 2 * e_r_b * e_r_a
    k1a = A * A + B * B - C * C
    k2 = ca.sqrt(ca.fmax(k1a, 1e-12))
    s = 1 if positive else -1
    return ca.atan2(-B * C - s * A * k2, -A * C + s * B * k2), k1a


class _LengthConstraintAssembly(Animated):
    """MSL's JointSSP / JointSSR / JointUSR: rod1 joins frame_a to frame_im (a spherical
    joint there), which rod2 (rRod2_ib [m], resolved in frame_ib) holds fixed to frame_ib;
    frame_ib moves relative to frame_b by the joint (axis n_b [1], resolved in frame_b)
    whose coordinate follows from the positions of frame_a and frame_b in closed form, for
    the rod length. ``axis`` follows the joint's coordinate and ``bearing`` is fixed (MSL's),
    so a 1-D drive can act on the joint. Records k1a (the closed form's discriminant).

    The rod (``_SphericalRod``, ``_UniversalRod``) gives ``_length()`` [m],
    ``_rod_structure`` and ``_rod_physics``; the joint (``_PrismaticJoint``,
    ``_RevoluteJoint``) its MSL name ``_joint``, ``_domain``, ``_coordinates`` (MSL's names
    of the coordinate with and without offset), ``_closed_form``, ``_offset()`` [m or rad]
    and ``_declare_joint``."""
    options = {"positiveBranch": True, "checkTotalPower": False}
    n_b = Parameter((0.0, 0.0, 1.0), "1", "axis of the joint fixed and resolved in frame_b")
    rRod2_ib = Parameter((1.0, 0.0, 0.0), "m", "vector from origin of frame_ib to spherical "
                                               "joint in the middle, resolved in frame_ib")
    frame_a = Frame_a("coordinate system fixed to the component with one cut-force and "
                      "cut-torque")
    frame_b = Frame_b("coordinate system fixed to the component with one cut-force and "
                      "cut-torque")
    frame_ib = Frame_b("coordinate system at origin of frame_b fixed at the joint")
    frame_im = Frame_b("coordinate system at origin of spherical joint in the middle fixed "
                       "at the joint")

    @staticmethod
    def _inputs(vals_a, vals_b):
        """r_a: frame_a's origin relative to frame_b, resolved in frame_b [m]."""
        ra, _ = frames.parts(vals_a)
        rb, Tb = frames.parts(vals_b)
        return ca.mtimes(Tb, ra - rb)

    def _axis_b(self):
        return unit_direction(self, "n_b", "(0, 0, 1)")

    def structure(self, s):
        e_b = self._axis_b()
        branch = bool(self.positiveBranch)
        total, own = self._coordinates
        q_total = s.node(f"{self._joint}.{total}", self._domain, preferred=False)
        q = s.node(f"{self._joint}.{own}", self._domain, preferred=False)
        closed_form, inputs = self._closed_form, self._inputs

        def solve(vals, par):
            e, r_ib, length = par
            return closed_form(inputs(vals[0], vals[1]), r_ib, e, length, branch)[0], None

        def residual(vals, par):
            return vals[2] - solve(vals, par)[0]

        s.relation([self.frame_a, self.frame_b, q_total], [e_b, self.rRod2_ib, self._length()],
                   solve={2: solve}, residual=residual, rows=(total,),
                   name=f"length constraint {'+' if branch else '-'}")
        s.linear({q_total: 1.0, q: -1.0}, self._offset(), f"{self.path}: offset")
        self._declare_joint(s, q_total, e_b)
        s.transform(self.frame_ib, self.frame_im, self.rRod2_ib)
        s.linear({self.axis: 1.0, q: -1.0}, 0.0, f"{self.path}: axis")
        s.linear({self.bearing: 1.0}, 0.0, f"{self.path}: bearing")
        self._rod_structure(s)

    def physics(self, e):
        self._rod_physics(e)
        r_a = self._inputs(e.pos(self.frame_a), e.pos(self.frame_b))
        _, k1a = self._closed_form(r_a, self.rRod2_ib, self._axis_b(), self._length(), True)
        e.variable("k1a", k1a, self._k1a_unit, "discriminant of the length constraint (0: "
                                               "singular position of the loop)")
        e.indicator("singular", k1a, self._k1a_unit, "the loop reaches a singular position")
        e.terminate(k1a <= 1e-10,
                    f"{self.path}: singular position of loop (either no or two analytic "
                    f"solutions; the mechanism has lost one degree of freedom in this "
                    f"position); build the loop with basic joints instead")


class _SphericalRod:
    """rod1 of JointSSP / JointSSR: spherical joints at both ends, length rod1Length [m], an
    optional point mass rod1Mass [kg] in its middle; records f_rod [N] (MSL's sign: positive
    on frame_a, when directed from frame_a to frame_im), rod1.f_rod and rod1.rRod_0."""
    options = {"showMass": True}
    rod1Length = Parameter(1.0, "m", "distance between the origins of frame_a and frame_im "
                                     "(rod 1)", positive=True)
    rod1Mass = Parameter(0.0, "kg", "mass of rod 1 (= point mass located in middle of rod)",
                         nonnegative=True)

    def _length(self):
        return self.rod1Length

    def _rod_structure(self, s):
        pass

    def _rod_physics(self, e):
        f_rod = rod_with_mass(e, self.frame_a, self.frame_im, self.rod1Mass, "rod1.")
        e.variable("f_rod", f_rod, "N", "constraint force in direction of the rod (positive "
                                        "on frame_a, when directed from frame_a to frame_im)")



def _rod_frame_towards(vals, par):
    """The rod frame of a universal joint at frame vals[0] whose rod points at the origin of
    frame vals[1] (``loop_joints.universal_rod_frame``; par: axis 1 in frame_a, the rod's
    direction in the rod frame), for ``StructureBuilder.relation``'s solve."""
    n1, rod = par
    ra, Ta = frames.parts(vals[0])
    rb, _ = frames.parts(vals[1])
    return universal_rod_frame(vals[0], ca.mtimes(Ta, rb - ra), n1, rod), None

class _UniversalRod:
    """rod1 of JointUSR / JointRRR: a universal joint at frame_a (axis 1 n1_a [1], resolved in
    frame_a) and a spherical joint at frame_im, the rod rRod1_ia [m] resolved in frame_ia,
    the frame fixed to the rod at frame_a's origin (MSL's UniversalSpherical rod frame:
    ``loop_joints.universal_rod_frame``); massless, length |rRod1_ia|. Not recorded: MSL's
    f_rod (the rod's share of frame_a's cut force, which frame_ia's loads also enter)."""
    options = {"showUniversalAxes": True}
    n1_a = Parameter((0.0, 0.0, 1.0), "1", "axis 1 of universal joint fixed and resolved in "
                                           "frame_a (axis 2 is orthogonal to axis 1 and to "
                                           "rod 1)")
    rRod1_ia = Parameter((1.0, 0.0, 0.0), "m", "vector from origin of frame_a to spherical "
                                               "joint in the middle, resolved in frame_ia")
    frame_ia = Frame_a("coordinate system at origin of frame_a fixed at connecting rod of "
                       "universal and spherical joint")

    def _length(self):
        return ca.norm_2(self.rRod1_ia)

    def _axis_1(self):
        return unit_direction(self, "n1_a", "(0, 0, 1)")

    def _rod_structure(self, s):
        rod_frame = _rod_frame_towards

        def residual(vals, par):
            return s.frame_residual(rod_frame(vals, par)[0], vals[2])

        s.relation([self.frame_a, self.frame_im, self.frame_ia], [self._axis_1(),
                                                                  self.rRod1_ia],
                   solve={2: rod_frame}, residual=residual,
                   rows=tuple(f"frame_ia.{r}" for r in frames.FRAME_ROWS), name="rod frame")

    def _rod_physics(self, e):
        pass


class _PrismaticJoint:
    """The prismatic joint with length constraint (MSL's PrismaticWithLengthConstraint):
    frame_ib slides along n_b from frame_b by distance = s_offset + s [m]
    (``length_constraint_distance``); ``axis``.s = s; records prismatic.distance,
    prismatic.s. MSL's s_guess is accepted; it does not choose the branch here."""
    _joint, _domain, _coordinates, _k1a_unit = "prismatic", TRANSLATIONAL, ("distance", "s"), "m2"
    _closed_form = staticmethod(length_constraint_distance)
    s_offset = Parameter(0.0, "m", "relative distance offset of prismatic joint (distance "
                                   "between frame_b and frame_ib = s + s_offset)")
    s_guess = Parameter(0.0, "m", "select the configuration such that at initial time "
                                  "|s(t0)-s_guess| is minimal (not used here: positiveBranch)")
    axis = TranslationalFlange("1-dim. translational flange that drives the prismatic joint")
    bearing = TranslationalFlange("1-dim. translational flange of the drive bearing")

    def _offset(self):
        return self.s_offset

    def _declare_joint(self, s, distance, e_b):
        s.prismatic(self.frame_b, self.frame_ib, distance, e_b)


class _RevoluteJoint:
    """The revolute joint with length constraint (MSL's RevoluteWithLengthConstraint):
    frame_ib turns about n_b from frame_b by angle = phi_offset + phi [rad]
    (``length_constraint_angle``); ``axis``.phi = phi; records revolute.angle, revolute.phi.
    phi_offset, phi_guess in degrees (MSL's); phi_guess is accepted, it does not choose the
    branch here."""
    _joint, _domain, _coordinates, _k1a_unit = "revolute", ROTATIONAL, ("angle", "phi"), "m4"
    _closed_form = staticmethod(length_constraint_angle)
    phi_offset = Parameter(0.0, "deg", "relative angle offset of revolute joint (angle = "
                                       "phi(t) + from_deg(phi_offset))")
    phi_guess = Parameter(0.0, "deg", "select the configuration such that at initial time "
                                      "|phi(t0) - from_deg(phi_guess)| is minimal (not used "
                                      "here: positiveBranch)")
    axis = RotationalFlange("1-dim. rotational flange that drives the revolute joint")
    bearing = RotationalFlange("1-dim. rotational flange of the drive bearing")

    def _offset(self):
        return self.phi_offset * math.pi / 180

    def _declare_joint(self, s, angle, e_b):
        s.revolute(self.frame_b, self.frame_ib, angle, n=e_b)


class JointSSP(_SphericalRod, _PrismaticJoint, _LengthConstraintAssembly):
    """Spherical - spherical - prismatic joint aggregation (MSL's JointSSP), no constraints
    and no states: rod1 with spherical joints (``_SphericalRod``) and the prismatic joint
    with length constraint (``_PrismaticJoint``), closed in closed form
    (``_LengthConstraintAssembly``)."""


class JointSSR(_SphericalRod, _RevoluteJoint, _LengthConstraintAssembly):
    """Spherical - spherical - revolute joint aggregation (MSL's JointSSR), no constraints
    and no states: rod1 with spherical joints (``_SphericalRod``) and the revolute joint
    with length constraint (``_RevoluteJoint``), closed in closed form
    (``_LengthConstraintAssembly``)."""


class JointUSR(_UniversalRod, _RevoluteJoint, _LengthConstraintAssembly):
    """Universal - spherical - revolute joint aggregation (MSL's JointUSR), no constraints
    and no states: rod1 with a universal joint at frame_a carrying frame_ia
    (``_UniversalRod``) and the revolute joint with length constraint (``_RevoluteJoint``),
    closed in closed form (``_LengthConstraintAssembly``). rRod2_ib default {−1, 0, 0} m
    (MSL's)."""
    rRod2_ib = Parameter((-1.0, 0.0, 0.0), "m", "vector from origin of frame_ib to spherical "
                                                "joint in the middle, resolved in frame_ib")


class JointUSP(_UniversalRod, _PrismaticJoint, _LengthConstraintAssembly):
    """Universal - spherical - prismatic joint aggregation (MSL's JointUSP), no constraints
    and no states: rod1 with a universal joint at frame_a carrying frame_ia
    (``_UniversalRod``) and the prismatic joint with length constraint
    (``_PrismaticJoint``), closed in closed form (``_LengthConstraintAssembly``). n_b and
    rRod2_ib default {−1, 0, 0} (MSL's)."""
    n_b = Parameter((-1.0, 0.0, 0.0), "1", "axis of prismatic joint fixed and resolved in "
                                           "frame_b")
    rRod2_ib = Parameter((-1.0, 0.0, 0.0), "m", "vector from origin of frame_ib to spherical "
                                                "joint in the middle, resolved in frame_ib")


class JointRRP(JointUSP):
    """Planar revolute - revolute - prismatic joint aggregation (MSL's JointRRP): a JointUSP
    whose universal joint's first axis is n_a [1] (resolved in frame_a, default {0, 0, 1}),
    for planar loops whose revolute axes are all parallel to n_a, the prismatic axis n_b
    (resolved in frame_b, default {−1, 0, 0}) orthogonal to them; no constraints, no
    states."""
    n_a = Parameter((0.0, 0.0, 1.0), "1", "axes of the two revolute joints resolved in "
                                          "frame_a (both axes are parallel to each other)")

    def _axis_1(self):
        return unit_direction(self, "n_a", "(0, 0, 1)")


class JointRRR(JointUSR):
    """Planar revolute - revolute - revolute joint aggregation (MSL's JointRRR): a JointUSR
    whose universal joint's first axis is n_a [1] (resolved in frame_a, default {0, 0, 1}),
    for planar loops whose axes are all parallel to n_a; no constraints, no states.

    Difference from MSL: MSL computes n_b (the revolute's axis, resolved in frame_b) at
    initialization, n_a resolved in frame_b; here it is a parameter with default n_a (frame_a
    and frame_b parallel, the usual case); give it where they are not."""
    n_a = Parameter((0.0, 0.0, 1.0), "1", "axes of revolute joints resolved in frame_a (all "
                                          "axes are parallel to each other)")
    n_b = Parameter((0.0, 0.0, 1.0), "1", "axis of revolute joint fixed and resolved in "
                                          "frame_b (default n_a, taken when built)")

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        if "n_b" not in params:
            self.n_b = self.n_a

    def _axis_1(self):
        return unit_direction(self, "n_a", "(0, 0, 1)")


class JointUPS(Animated):
    """Universal - prismatic - spherical joint aggregation (MSL's JointUPS), no constraints
    and no states: a universal joint at frame_a (axis 1 n1_a [1], resolved in frame_a; axis 2
    orthogonal to axis 1 and to the line from frame_a to frame_b), a prismatic joint along
    that line and a spherical joint at frame_b. Both frame_a and frame_b are placed by other
    paths; the assembly adds frame_ia (origin at frame_a's, on the line: MSL's universal rod
    frame, parallel to frame_a when the universal joint's angles are 0, the line then along
    nAxis_ia [1], resolved in frame_ia) and frame_ib (origin at frame_b's, parallel to
    frame_ia), where the masses of a hydraulic cylinder's two parts attach. ``axis``.s = s,
    the distance between frame_a and frame_b less s_offset [m] (axisLength = s +
    s_offset); ``bearing`` is fixed; a force on ``axis`` pushes frame_b away from frame_a
    along the line. Massless: the loads on frame_ia and frame_ib pass to frame_a and frame_b
    by virtual work (MSL's force balance, not written). Records s, axisLength [m] and f
    [N] (= axis.f). Singular where the line is parallel to n1_a (as MSL's). ``eAxis_ia``
    is MSL's final parameter, the unit vector along nAxis_ia (for the bodies' r_CM)."""
    options = {"showUniversalAxes": True, "checkTotalPower": False}
    n1_a = Parameter((0.0, 0.0, 1.0), "1", "axis 1 of universal joint resolved in frame_a "
                                           "(axis 2 is orthogonal to axis 1 and to line from "
                                           "universal to spherical joint)")
    nAxis_ia = Parameter((1.0, 0.0, 0.0), "m", "axis vector along line from origin of "
                                               "frame_a to origin of frame_b, resolved in "
                                               "frame_ia")
    s_offset = Parameter(0.0, "m", "relative distance offset (distance between frame_a and "
                                   "frame_b = s(t) + s_offset)")
    frame_a = Frame_a("coordinate system fixed to the component with one cut-force and "
                      "cut-torque")
    frame_b = Frame_b("coordinate system fixed to the component with one cut-force and "
                      "cut-torque")
    frame_ia = Frame_a("coordinate system at origin of frame_a fixed at prismatic joint")
    frame_ib = Frame_b("coordinate system at origin of frame_b fixed at prismatic joint")
    axis = TranslationalFlange("1-dim. translational flange that drives the prismatic joint")
    bearing = TranslationalFlange("1-dim. translational flange of the drive bearing of the "
                                  "prismatic joint")

    @property
    def eAxis_ia(self) -> tuple:
        """Unit vector from origin of frame_a to origin of frame_b, resolved in frame_ia [1]
        (MSL's final parameter: nAxis_ia normalized)."""
        n = [float(v) for v in self.nAxis_ia]
        length = math.sqrt(sum(v * v for v in n))
        return tuple(v / length for v in n)

    def structure(self, s):
        line_frame = _rod_frame_towards

        def parallel_frame(vals, par):
            rb, _ = frames.parts(vals[0])
            _, T_ia = frames.parts(vals[1])
            return frames.pose(rb, T_ia), None

        def residual(solve, k):
            return lambda vals, par: s.frame_residual(solve(vals, par)[0], vals[k])

        rows = tuple(frames.FRAME_ROWS)
        s.relation([self.frame_a, self.frame_b, self.frame_ia],
                   [unit_direction(self, "n1_a", "(0, 0, 1)"), self.nAxis_ia],
                   solve={2: line_frame}, residual=residual(line_frame, 2),
                   rows=tuple(f"frame_ia.{r}" for r in rows), name="universal")
        s.relation([self.frame_b, self.frame_ia, self.frame_ib], [],
                   solve={2: parallel_frame}, residual=residual(parallel_frame, 2),
                   rows=tuple(f"frame_ib.{r}" for r in rows), name="spherical")
        length = s.node("axisLength", TRANSLATIONAL, preferred=False)
        s.distance(self.frame_a, self.frame_b, length)
        s.linear({length: 1.0, self.axis: -1.0}, self.s_offset, f"{self.path}: s_offset")
        s.linear({self.bearing: 1.0}, 0.0, f"{self.path}: bearing")

    def physics(self, e):
        e.variable("s", e.pos(self.axis), "m", "relative distance between frame_a and "
                                               "frame_b along axis nAxis = s + s_offset")
        e.variable("f", e.cut_flow(self.axis), "N", "= axis.f (driving force in the axis; "
                                                    "= -bearing.f)")
