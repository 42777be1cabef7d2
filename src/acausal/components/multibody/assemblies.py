"""Joint assemblies that close a kinematic loop analytically
(Modelica.Mechanics.MultiBody.Joints.Assemblies): JointSSP, with MSL's names, parameters,
defaults and sign conventions.

As in MSL, the assembly computes the coordinate of its joint with a length constraint
(MSL's Internal.PrismaticWithLengthConstraint) in closed form from the positions of its
two outer frames, so the loop adds no constraint row and no multiplier: the tree fires the
assembly's relation (``StructureBuilder.relation``) and its reaction is the rod force.
Where the loop is arranged so that the outer frames are not both known before the
joint's coordinate (the closed form cannot fire), the same relation closes the loop as a
constraint row instead, numerically.

MSL picks the branch of the closed form (the root of a quadratic) at initialization, the
one nearest to the guess; here it is the option ``positiveBranch`` (default True: MSL's
``positiveBranch`` for the usual assembly, the larger root).
"""
from __future__ import annotations

import casadi as ca

from ... import frames
from ...core import Parameter, TranslationalFlange
from ...core.ports import TRANSLATIONAL
from ..interfaces import unit_direction
from .interfaces import Animated, Frame_a, Frame_b
from .loop_joints import rod_with_mass

__all__ = ["JointSSP"]


def length_constraint_distance(r_a, r_b, e, length, positive: bool):
    """MSL's PrismaticWithLengthConstraint: the distance d [m] along the unit axis e with
    |d·e + r_b − r_a| = length [m] (r_a, r_b [m] resolved in the prismatic joint's
    frames): d = −B/2 ± sqrt(B²/4 − C), B = 2e·(r_b − r_a), C = |r_b − r_a|² − length²;
    and k1a = B²/4 − C, positive where the loop has two solutions (0: singular)."""
    rbra = r_b - r_a
    k1 = ca.dot(e, rbra)
    k1a = k1 * k1 - (ca.dot(rbra, rbra) - length * length)
    k2 = ca.sqrt(ca.fmax(k1a, 1e-12))
    return -k1 + (k2 if positive else -k2), k1a


class JointSSP(Animated):
    """Spherical - spherical - prismatic joint aggregation (MSL's JointSSP), no constraints
    and no states: rod1 (length rod1Length [m], optional point mass rod1Mass [kg] in its
    middle) joins frame_a by a spherical joint to frame_im, which rod2 (rRod2_ib [m],
    resolved in frame_ib) holds fixed to frame_ib; frame_ib slides along n_b [1] (resolved
    in frame_b) by the prismatic joint's distance = s_offset + s [m] from frame_b. The
    distance follows from the positions of frame_a and frame_b in closed form
    (``length_constraint_distance``, branch ``positiveBranch``); ``axis`` (axis.s = s) and
    ``bearing`` (fixed) are the prismatic joint's 1-D flanges, so a force can drive it.

    Records prismatic.distance, prismatic.s [m], f_rod [N] (rod1's force, MSL's sign; also
    rod1.f_rod, rod1.rRod_0) and
    k1a [m²] (the discriminant; the loop is singular where it reaches 0: the simulation
    then stops with MSL's message). MSL's s_guess is accepted; it does not choose the
    branch here."""
    options = {"positiveBranch": True, "showMass": True, "checkTotalPower": False}
    rod1Length = Parameter(1.0, "m", "distance between the origins of frame_a and frame_im "
                                     "(rod 1)", positive=True)
    rod1Mass = Parameter(0.0, "kg", "mass of rod 1 (= point mass located in middle of rod)",
                         nonnegative=True)
    n_b = Parameter((0.0, 0.0, 1.0), "1", "axis of prismatic joint fixed and resolved in "
                                          "frame_b")
    rRod2_ib = Parameter((1.0, 0.0, 0.0), "m", "vector from origin of frame_ib to spherical "
                                               "joint in the middle, resolved in frame_ib")
    s_offset = Parameter(0.0, "m", "relative distance offset of prismatic joint (distance "
                                   "between frame_b and frame_ib = s + s_offset)")
    s_guess = Parameter(0.0, "m", "select the configuration such that at initial time "
                                  "|s(t0)-s_guess| is minimal (not used here: positiveBranch)")
    frame_a = Frame_a("coordinate system fixed to the component with one cut-force and "
                      "cut-torque")
    frame_b = Frame_b("coordinate system fixed to the component with one cut-force and "
                      "cut-torque")
    frame_ib = Frame_b("coordinate system at origin of frame_b fixed at prismatic joint")
    frame_im = Frame_b("coordinate system at origin of spherical joint in the middle fixed "
                       "at prismatic joint")
    axis = TranslationalFlange("1-dim. translational flange that drives the prismatic joint")
    bearing = TranslationalFlange("1-dim. translational flange of the drive bearing")

    def structure(self, s):
        e_b = unit_direction(self, "n_b", "(1, 0, 0)")
        branch = bool(self.positiveBranch)
        distance = s.node("prismatic.distance", TRANSLATIONAL, preferred=False)
        s_rel = s.node("prismatic.s", TRANSLATIONAL, velocity="prismatic.v", preferred=False)

        def solve(vals, par):
            e, r_ib, length = par
            ra, _ = frames.parts(vals[0])
            rb, Tb = frames.parts(vals[1])
            d, _ = length_constraint_distance(ca.mtimes(Tb, ra - rb), r_ib, e, length, branch)
            return d, None

        def residual(vals, par):
            d, _ = solve(vals, par)
            return vals[2] - d

        s.relation([self.frame_a, self.frame_b, distance], [e_b, self.rRod2_ib,
                                                            self.rod1Length],
                   solve={2: solve}, residual=residual, rows=("distance",),
                   name=f"length constraint {'+' if branch else '-'}")
        s.linear({distance: 1.0, s_rel: -1.0}, self.s_offset, f"{self.path}: s_offset")
        s.prismatic(self.frame_b, self.frame_ib, distance, e_b)
        s.transform(self.frame_ib, self.frame_im, self.rRod2_ib)
        s.linear({self.axis: 1.0, s_rel: -1.0}, 0.0, f"{self.path}: axis")
        s.linear({self.bearing: 1.0}, 0.0, f"{self.path}: bearing")

    def physics(self, e):
        f_rod = rod_with_mass(e, self.frame_a, self.frame_im, self.rod1Mass, "rod1.")
        e.variable("f_rod", f_rod, "N", "constraint force in direction of the rod (positive "
                                        "on frame_a, when directed from frame_a to frame_im)")
        ra, _ = frames.parts(e.pos(self.frame_a))
        rb, Tb = frames.parts(e.pos(self.frame_b))
        _, k1a = length_constraint_distance(ca.mtimes(Tb, ra - rb), self.rRod2_ib,
                                            unit_direction(self, "n_b", "(1, 0, 0)"),
                                            self.rod1Length, True)
        e.variable("k1a", k1a, "m2", "discriminant of the length constraint (0: singular "
                                     "position of the loop)")
        e.indicator("singular", k1a, "m2", "the loop reaches a singular position")
        e.terminate(k1a <= 1e-10,
                    f"{self.path}: singular position of loop (either no or two analytic "
                    f"solutions; the mechanism has lost one degree of freedom in this "
                    f"position); build the loop with basic joints instead")
