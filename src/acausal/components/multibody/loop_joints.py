"""Joints that close kinematic loops cheaply (Modelica.Mechanics.MultiBody.Joints):
RevolutePlanarLoopConstraint, SphericalSpherical, UniversalSpherical, with MSL's names,
parameters, defaults and sign conventions.

They have no coordinates and no orientation states: each is a constraint between its two
frames, with fewer rows than a joint of the spanning tree would close the loop with
(``StructureBuilder.relation``; multipliers -> cut forces and torques by virtual work, so
MSL's force equations hold without being written). Any loop of 3-D frames also closes
without them, at a Revolute or Prismatic whose frames are both fixed by other paths (6
rows, redundant ones found from the rank: ``compiler.loops``).
"""
from __future__ import annotations

import casadi as ca

from ... import frames
from ...core import Parameter
from ..interfaces import unit_direction
from .interfaces import Frame_a, PartialTwoFrames
from .world import World

__all__ = ["RevolutePlanarLoopConstraint", "SphericalSpherical", "UniversalSpherical",
           "rod_with_mass", "universal_rod_frame"]


def _planar_axes(e):
    """MSL's (ex_a, ey_a): unit vectors orthogonal to the unit axis e and to each other."""
    nnx = ca.if_else(ca.fabs(e[0]) > 0.1, ca.vertcat(0, 1, 0),
                     ca.if_else(ca.fabs(e[1]) > 0.1, ca.vertcat(0, 0, 1), ca.vertcat(1, 0, 0)))
    ey = ca.cross(e, nnx)
    ey = ey / ca.norm_2(ey)
    return ca.cross(ey, e), ey


def _rel_position(vals):
    """r_b − r_a [m] resolved in frame_a, and frame_a's T."""
    ra, Ta = frames.parts(vals[0])
    rb, _ = frames.parts(vals[1])
    return ca.mtimes(Ta, rb - ra), Ta


class RevolutePlanarLoopConstraint(PartialTwoFrames):
    """Revolute joint that cuts a planar loop with its 2 positional constraints only (MSL):
    the origin of frame_b lies on the axis n [1] (resolved in frame_a, default {0, 0, 1})
    through frame_a's origin, ex_a·r_rel_a = ey_a·r_rel_a = 0. The rotation about n and the
    other constraints of a revolute follow from the planar loop; the cut force along n and
    the cut torques, which such a loop leaves undetermined, are 0 (frame_a.t = frame_b.t
    = 0; frame_a.f = [ex_a, ey_a]·f_c). As MSL, it is for loops whose joints all turn about
    n (MSL asserts it at run time; here a non-planar loop is simply not closed by it)."""
    n = Parameter((0.0, 0.0, 1.0), "1", "axis of rotation resolved in frame_a (= same as in "
                                        "frame_b)")

    def structure(self, s):
        e = unit_direction(self, "n", "(0, 0, 1)")

        def residual(vals, par):
            ex, ey = _planar_axes(par[0])
            r_rel, _ = _rel_position(vals)
            return ca.vertcat(ca.dot(ex, r_rel), ca.dot(ey, r_rel))

        s.relation([self.frame_a, self.frame_b], [e], residual=residual,
                   rows=("ex_a*r_rel_a", "ey_a*r_rel_a"), name="planar loop constraint")


def _rod_length(c, s, length):
    """The rod length [m]: ``length`` (an expression of parameters), or with
    ``computeRodLength`` a constant the initialization computes (MSL's parameter with
    fixed = false): a state with der = 0 starting at ``length``, fixed where the start
    values (x0) fix the loop's configuration, recorded as ``rodLength``."""
    if not c.computeRodLength:
        return length
    return s.state("rodLength", start=length, unit="m", der=0.0,
                   description="distance between the origins of frame_a and frame_b "
                               "(computed at initialization)")


class SphericalSpherical(PartialTwoFrames):
    """Two spherical joints joined by a massless rod of ``rodLength`` [m] (MSL's
    SphericalSpherical): one constraint |r_b − r_a| = rodLength, no states; an optional
    point mass m [kg] in the middle of the rod (kinetic and potential energy of the mid
    point). frame_a.t = frame_b.t = 0; records MSL's f_rod [N] (rod force, positive on
    frame_a when directed from frame_a to frame_b) and rRod_0 [m]. ``computeRodLength``
    = true: rodLength is the guess, the length computed at initialization (``_rod_length``).
    ``kinematicConstraint`` = false (MSL's, for assemblies that hold the length
    themselves): no constraint, the rod's mass and variables only."""
    options = {"computeRodLength": False, "showMass": True, "kinematicConstraint": True,
               "checkTotalPower": False}
    rodLength = Parameter(1.0, "m", "distance between the origins of frame_a and frame_b",
                          positive=True)
    m = Parameter(0.0, "kg", "mass of rod (= point mass located in middle of rod)",
                  nonnegative=True)

    def structure(self, s):
        if not self.kinematicConstraint:
            return

        def residual(vals, par):
            r_rel, _ = _rel_position(vals)
            return ca.norm_2(r_rel) - par[0]

        s.relation([self.frame_a, self.frame_b], [_rod_length(self, s, self.rodLength)],
                   residual=residual,
                   rows=("rodLength",), name="rod")

    def physics(self, e):
        rod_with_mass(e, self.frame_a, self.frame_b, self.m)


def rod_with_mass(e, frame_a, frame_b, m, prefix: str = "") -> ca.SX:
    """MSL's SphericalSpherical rod between two 3-D frames: a point mass m [kg] at its
    middle (kinetic and potential energy), and its variables under ``prefix``: rRod_0 [m]
    and f_rod [N], the rod force (positive on frame_a when directed from frame_a to
    frame_b), MSL's eRod_a·frame_a.f. Half the mass's inertia and weight, f_CM_a/2 (MSL's
    f_CM_a = m·(a_CM − g) resolved in frame_a), acts at frame_a: the constraint's
    reaction recorded at frame_a plus that half is MSL's frame_a.f. Returns f_rod."""
    world = e.outer(World)
    ra, Ta = frames.parts(e.pos(frame_a))
    rb, Tb = frames.parts(e.pos(frame_b))
    r_rod = rb - ra
    e_rod = frames.resolve2(Ta, r_rod) / ca.norm_2(r_rod)
    r_cm = ra + r_rod / 2
    v_cm = (frames.resolve1(Ta, e.vel(frame_a)[:3]) + frames.resolve1(Tb, e.vel(frame_b)[:3])) / 2
    e.kinetic_energy(0.5 * m * ca.dot(v_cm, v_cm))
    e.potential_energy(m * world.potential(r_cm))
    a_cm = (_acceleration_0(e, frame_a, Ta) + _acceleration_0(e, frame_b, Tb)) / 2
    f_cm = m * frames.resolve2(Ta, a_cm - world.gravity_acceleration(r_cm))
    f_rod = ca.dot(e.cut_flow(frame_a)[:3] + f_cm / 2, e_rod)
    e.variable(prefix + "f_rod", f_rod, "N", "constraint force in direction of the rod "
                                             "(positive on frame_a, when directed from "
                                             "frame_a to frame_b)")
    for k in range(3):
        e.variable(f"{prefix}rRod_0[{k + 1}]", r_rod[k], "m", "position vector from frame_a "
                                                              "to frame_b resolved in world "
                                                              "frame")
    return f_rod


def _acceleration_0(e, frame, T):
    """Acceleration [m/s²] of a 3-D frame's origin, resolved in the world."""
    vel, acc = e.vel(frame), e.acc(frame)
    return frames.resolve1(T, acc[:3] + ca.cross(vel[3:], vel[:3]))


def universal_rod_frame(pose_a, r_rel, n1, r_ia):
    """MSL's UniversalSpherical rod frame: the pose of frame_ia (origin at frame_a's) for the
    rod r_rel [m] (frame_a to the spherical joint, resolved in frame_a), axis 1 of the
    universal joint n1 (unit, resolved in frame_a) and the rod r_ia [m] resolved in
    frame_ia: T_ia = [eRod_ia, e2_ia, e3_ia]·[eRod_a, e2_a, e3_a]ᵀ·T_a, e2 ∥ n1 × eRod."""
    def axes(e_rod):
        e2 = ca.cross(n1, e_rod)
        e2 = e2 / ca.norm_2(e2)
        return ca.horzcat(e_rod, e2, ca.cross(e_rod, e2))

    ra, Ta = frames.parts(pose_a)
    T_rel = ca.mtimes(axes(r_ia / ca.norm_2(r_ia)), axes(r_rel / ca.norm_2(r_rel)).T)
    return frames.pose(ra, ca.mtimes(T_rel, Ta))


class UniversalSpherical(PartialTwoFrames):
    """A universal joint at frame_a and a spherical joint at frame_b joined by a rigid rod
    (MSL's UniversalSpherical): one constraint |r_b − r_a| = |rRod_ia| [m], no states. The
    rod carries frame_ia (origin at frame_a's), oriented analytically as MSL does: axis 1
    of the universal joint is n1_a [1] (resolved in frame_a), axis 2 is orthogonal to it
    and to the rod, and frame_ia is parallel to frame_a when both angles are 0, the rod
    then along rRod_ia (resolved in frame_ia): T_ia = [eRod_ia, e2_ia, e3_ia]·[eRod_a,
    e2_a, e3_a]ᵀ·T_a. Singular where the rod is parallel to n1_a (as MSL's). frame_b.t =
    0; records f_rod [N] (positive if the rod is pressed) and rRod_0, rRod_a [m].
    ``computeRodLength`` = true: rRod_ia gives only the rod's direction, its length is
    computed at initialization (``_rod_length``), as MSL's. ``kinematicConstraint`` =
    false (MSL's, for assemblies that hold the length themselves): frame_ia only, no
    constraint."""
    options = {"computeRodLength": False, "showUniversalAxes": True,
               "kinematicConstraint": True, "checkTotalPower": False}
    n1_a = Parameter((0.0, 0.0, 1.0), "1", "axis 1 of universal joint resolved in frame_a "
                                           "(axis 2 is orthogonal to axis 1 and to rod)")
    rRod_ia = Parameter((1.0, 0.0, 0.0), "m", "vector from origin of frame_a to origin of "
                                              "frame_b, resolved in frame_ia")
    frame_ia = Frame_a("coordinate system at the origin of frame_a, fixed at the rod "
                       "connecting the universal with the spherical joint")

    def structure(self, s):
        constrained = bool(self.kinematicConstraint)

        def rod_frame(vals, par):
            n1, r_ia, length = par
            r_rel, _ = _rel_position(vals)
            return (universal_rod_frame(vals[0], r_rel, n1, r_ia),
                    ca.norm_2(r_rel) - length if constrained else None)

        def residual(vals, par):
            ia, length_row = rod_frame(vals, par)
            return ca.vertcat(s.frame_residual(ia, vals[2]),
                              length_row if constrained else ca.SX(0, 1))

        n1 = unit_direction(self, "n1_a", "(0, 0, 1)")
        length = _rod_length(self, s, ca.norm_2(self.rRod_ia))
        s.relation([self.frame_a, self.frame_b, self.frame_ia], [n1, self.rRod_ia, length],
                   solve={2: rod_frame}, residual=residual,
                   rows=tuple(f"frame_ia.{r}" for r in frames.FRAME_ROWS)
                   + ("rodLength",) * constrained,
                   extra_rows=("rodLength",) * constrained, name=f"rod {constrained}")

    def physics(self, e):
        ra, Ta = frames.parts(e.pos(self.frame_a))
        rb, Tb = frames.parts(e.pos(self.frame_b))
        r_rod = rb - ra
        r_a = frames.resolve2(Ta, r_rod)
        f_b = ca.mtimes([Ta, Tb.T, e.cut_flow(self.frame_b)[:3]])
        e.variable("f_rod", -ca.dot(f_b, r_a / ca.norm_2(r_a)), "N",
                   "constraint force in direction of the rod (positive, if rod is pressed)")
        for k in range(3):
            e.variable(f"rRod_0[{k + 1}]", r_rod[k], "m", "position vector from origin of "
                       "frame_a to origin of frame_b resolved in world frame")
            e.variable(f"rRod_a[{k + 1}]", r_a[k], "m", "position vector from origin of "
                       "frame_a to origin of frame_b resolved in frame_a")
