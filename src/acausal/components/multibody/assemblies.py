"""Joint assemblies that close a kinematic loop analytically
(Modelica.Mechanics.MultiBody.Joints.Assemblies): JointSSP and JointSSR, with MSL's names,
parameters, defaults and sign conventions.

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
from .loop_joints import rod_with_mass

__all__ = ["JointSSP", "JointSSR", "length_constraint_distance", "length_constraint_angle"]


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
    """MSL's JointSSP / JointSSR: rod1 (length rod1Length [m], optional point mass rod1Mass
    [kg] in its middle) joins frame_a by a spherical joint to frame_im, which rod2 (rRod2_ib
    [m], resolved in frame_ib) holds fixed to frame_ib; frame_ib moves relative to frame_b
    by the joint (axis n_b [1], resolved in frame_b) whose coordinate follows from the
    positions of frame_a and frame_b in closed form. ``axis`` follows the joint's
    coordinate and ``bearing`` is fixed (MSL's), so a 1-D drive can act on the joint.

    Subclasses give the joint's kind: ``_joint`` (its name in MSL), ``_domain``, ``_flange``,
    ``_coordinates`` (MSL's names of the offset coordinate and the coordinate),
    ``_closed_form`` and ``_offset()`` [m or rad], and ``_declare_joint``."""
    options = {"positiveBranch": True, "showMass": True, "checkTotalPower": False}
    rod1Length = Parameter(1.0, "m", "distance between the origins of frame_a and frame_im "
                                     "(rod 1)", positive=True)
    rod1Mass = Parameter(0.0, "kg", "mass of rod 1 (= point mass located in middle of rod)",
                         nonnegative=True)
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

    def _inputs(self, vals_a, vals_b):
        """r_a: frame_a's origin relative to frame_b, resolved in frame_b [m]."""
        ra, _ = frames.parts(vals_a)
        rb, Tb = frames.parts(vals_b)
        return ca.mtimes(Tb, ra - rb)

    def structure(self, s):
        e_b = unit_direction(self, "n_b", "(0, 0, 1)")
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

        s.relation([self.frame_a, self.frame_b, q_total], [e_b, self.rRod2_ib,
                                                           self.rod1Length],
                   solve={2: solve}, residual=residual, rows=(total,),
                   name=f"length constraint {'+' if branch else '-'}")
        s.linear({q_total: 1.0, q: -1.0}, self._offset(), f"{self.path}: offset")
        self._declare_joint(s, q_total, e_b)
        s.transform(self.frame_ib, self.frame_im, self.rRod2_ib)
        s.linear({self.axis: 1.0, q: -1.0}, 0.0, f"{self.path}: axis")
        s.linear({self.bearing: 1.0}, 0.0, f"{self.path}: bearing")

    def physics(self, e):
        f_rod = rod_with_mass(e, self.frame_a, self.frame_im, self.rod1Mass, "rod1.")
        e.variable("f_rod", f_rod, "N", "constraint force in direction of the rod (positive "
                                        "on frame_a, when directed from frame_a to frame_im)")
        r_a = self._inputs(e.pos(self.frame_a), e.pos(self.frame_b))
        _, k1a = self._closed_form(r_a, self.rRod2_ib, unit_direction(self, "n_b", "(0, 0, 1)"),
                                   self.rod1Length, True)
        e.variable("k1a", k1a, self._k1a_unit, "discriminant of the length constraint (0: "
                                               "singular position of the loop)")
        e.indicator("singular", k1a, self._k1a_unit, "the loop reaches a singular position")
        e.terminate(k1a <= 1e-10,
                    f"{self.path}: singular position of loop (either no or two analytic "
                    f"solutions; the mechanism has lost one degree of freedom in this "
                    f"position); build the loop with basic joints instead")


class JointSSP(_LengthConstraintAssembly):
    """Spherical - spherical - prismatic joint aggregation (MSL's JointSSP), no constraints
    and no states (see ``_LengthConstraintAssembly``): frame_ib slides along n_b from
    frame_b by the prismatic joint's distance = s_offset + s [m], from
    ``length_constraint_distance``; ``axis``.s = s, a translational flange.

    Records prismatic.distance, prismatic.s [m], f_rod [N] (rod1's force, MSL's sign; also
    rod1.f_rod, rod1.rRod_0) and k1a [m²] (the discriminant). MSL's s_guess is accepted; it
    does not choose the branch here (``positiveBranch``)."""
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


class JointSSR(_LengthConstraintAssembly):
    """Spherical - spherical - revolute joint aggregation (MSL's JointSSR), no constraints
    and no states (see ``_LengthConstraintAssembly``): frame_ib turns about n_b from
    frame_b by the revolute joint's angle = phi_offset + phi [rad], from
    ``length_constraint_angle``; ``axis``.phi = phi, a rotational flange.

    Records revolute.angle, revolute.phi [rad], f_rod [N] (rod1's force, MSL's sign; also
    rod1.f_rod, rod1.rRod_0) and k1a [m⁴] (the discriminant). phi_offset, phi_guess are in
    degrees as MSL's; phi_guess is accepted and does not choose the branch here
    (``positiveBranch``)."""
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
