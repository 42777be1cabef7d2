"""Forces (Modelica.Mechanics.MultiBody.Forces): external and relative forces and torques
given by input signals, and line-force elements, with MSL's names, parameters, defaults,
``resolveInFrame`` and sign conventions.

A component puts its force f and torque t on a frame as MSL writes them (``frame.f``,
``frame.t``: the flows into the component, resolved in that frame); what is connected to the
frame feels −f, −t. Lagrange's generalized forces follow from the frame's twist (virtual
work), so a force element needs no equation of its own.

- WorldForce, WorldTorque, WorldForceAndTorque: input vectors force[3] [N] / torque[3]
  [N.m] acting on frame_b, resolved in the world (default), frame_b or frame_resolve.
- Force, Torque, ForceAndTorque: between frame_a and frame_b (frame_b gets the input, frame_a
  the opposite force and the torque that balances both about frame_a's origin), resolved in
  frame_b (default), frame_a, the world or frame_resolve.
- Line forces along the line from frame_a's origin to frame_b's: Spring (optional point mass
  m on the line), Damper, SpringDamperParallel (``useHeatPort``, as MSL's, T = 293.15 K), and
  LineForceWithMass (1-D translational flanges flange_a, flange_b: flange_b.s = length, so
  a Translational force law acts along the line; optional point mass).

Line forces record MSL's variables: length, s (the distance guarded by s_small), r_rel_0,
e_rel_0, r_rel_a, e_a, f (> 0 pushes frame_b away from frame_a: frame_a.f = −e_a·f, MSL's
PartialLineForce). ``animation`` and the shape parameters are accepted and record nothing.

``fixedRotationAtFrame_a`` / ``fixedRotationAtFrame_b`` (MSL's, to connect line forces
directly, without a body at the junction): that frame keeps the world's orientation and
gets its position r_a_0[1..3] / r_b_0[1..3] [m] (world) as coordinates of this element,
through three prismatic motions along the world axes; a junction without mass has them as
algebraic variables (the forces in balance). Such a frame must get its position from line
forces only (else it closes a 3-D loop, refused).

Not here: the 3-D SpringDamperSeries and LineForceWithTwoMasses.
"""
from __future__ import annotations

import casadi as ca

from ... import frames
from ...core import Parameter, RealInput, TranslationalFlange, VectorPort
from ...core.ports import MULTIBODY, TRANSLATIONAL
from ..interfaces import PartialElementaryConditionalHeatPortWithoutT
from .interfaces import Animated, Frame_a, Frame_b
from .resolving import ResolveInFrameAB, ResolveInFrameB, Resolving, record
from .world import World

__all__ = ["WorldForce", "WorldTorque", "WorldForceAndTorque", "Force", "Torque",
           "ForceAndTorque", "Spring", "Damper", "SpringDamperParallel", "LineForceWithMass"]

_ZERO3 = ca.SX.zeros(3)


def _inputs(e, ports) -> ca.SX:
    return ca.vertcat(*[e.input(p) for p in ports])


# ---- forces and torques given by signals --------------------------------------------------
class _World(Resolving, Animated):
    """Acts on frame_b only; inputs resolved in ResolveInFrameB (default world)."""
    options = {"resolveInFrame": ResolveInFrameB.world}
    frame_b = Frame_b("coordinate system fixed to the component with one cut-force and "
                      "cut-torque", required=True)

    def _on_b(self, e, v) -> ca.SX:
        """Input vector v (resolved in resolveInFrame), resolved in frame_b."""
        T_b = self._T(e, "frame_b")
        return ca.mtimes(T_b, self.to_world(e, v))


class WorldForce(_World):
    """External force force[1..3] [N] (input signals) acting at frame_b's origin, resolved
    in resolveInFrame (ResolveInFrameB: world (default), frame_b, frame_resolve):
    frame_b.f = −force resolved in frame_b, frame_b.t = 0."""
    force = VectorPort(RealInput, 3, "x-, y-, z-coordinates of force resolved in frame "
                                     "defined by resolveInFrame [N]")

    def physics(self, e):
        e.flow(self.frame_b, ca.vertcat(-self._on_b(e, _inputs(e, self.force)), _ZERO3))


class WorldTorque(_World):
    """External torque torque[1..3] [N.m] (input signals) acting on frame_b, resolved in
    resolveInFrame (ResolveInFrameB: world (default), frame_b, frame_resolve):
    frame_b.t = −torque resolved in frame_b, frame_b.f = 0."""
    torque = VectorPort(RealInput, 3, "x-, y-, z-coordinates of torque resolved in frame "
                                      "defined by resolveInFrame [N.m]")

    def physics(self, e):
        e.flow(self.frame_b, ca.vertcat(_ZERO3, -self._on_b(e, _inputs(e, self.torque))))


class WorldForceAndTorque(_World):
    """WorldForce and WorldTorque in one: force[3] [N] at frame_b's origin and torque[3]
    [N.m], both resolved in resolveInFrame (default world)."""
    force = VectorPort(RealInput, 3, "x-, y-, z-coordinates of force resolved in frame "
                                     "defined by resolveInFrame [N]")
    torque = VectorPort(RealInput, 3, "x-, y-, z-coordinates of torque resolved in frame "
                                      "defined by resolveInFrame [N.m]")

    def physics(self, e):
        e.flow(self.frame_b, ca.vertcat(-self._on_b(e, _inputs(e, self.force)),
                                        -self._on_b(e, _inputs(e, self.torque))))


class _TwoFrames(Resolving, Animated):
    """A force and/or torque between frame_a and frame_b (MSL's BasicForce/BasicTorque):
    with f_b_0, t_b_0 the flows at frame_b resolved in the world (−input), frame_b.f =
    T_b·f_b_0, frame_b.t = T_b·t_b_0, frame_a.f = −T_a·f_b_0, frame_a.t = −T_a·(t_b_0 +
    r_0 × f_b_0), r_0 = frame_b.r_0 − frame_a.r_0. ResolveInFrameAB, default frame_b."""
    options = {"resolveInFrame": ResolveInFrameAB.frame_b}
    frame_a = Frame_a("coordinate system fixed to the component with one cut-force and "
                      "cut-torque", required=True)
    frame_b = Frame_b("coordinate system fixed to the component with one cut-force and "
                      "cut-torque", required=True)

    def _apply(self, e, force, torque) -> None:
        """force, torque [N, N.m] on frame_b, resolved in resolveInFrame (None: zero)."""
        f_b_0 = -self.to_world(e, force) if force is not None else _ZERO3
        t_b_0 = -self.to_world(e, torque) if torque is not None else _ZERO3
        r_a, T_a = frames.parts(e.pos(self.frame_a))
        r_b, T_b = frames.parts(e.pos(self.frame_b))
        r_0 = r_b - r_a
        e.flow(self.frame_b, ca.vertcat(ca.mtimes(T_b, f_b_0), ca.mtimes(T_b, t_b_0)))
        e.flow(self.frame_a, ca.vertcat(-ca.mtimes(T_a, f_b_0),
                                        -ca.mtimes(T_a, t_b_0 + ca.cross(r_0, f_b_0))))
        if force is not None:
            record(e, "basicForce.r_0", r_0, "m", "position vector from origin of frame_a to "
                                                  "origin of frame_b resolved in world frame")
            record(e, "basicForce.f_b_0", f_b_0, "N", "frame_b.f resolved in world frame")
        if torque is not None:
            record(e, "basicTorque.t_b_0", t_b_0, "N.m", "frame_b.t resolved in world frame")


class Force(_TwoFrames):
    """Force force[1..3] [N] (input signals, resolved in resolveInFrame, default frame_b)
    acting at frame_b's origin; frame_a gets the opposite force and the torque −r_0 ×
    f_b_0 (force and torque balance of the massless element)."""
    force = VectorPort(RealInput, 3, "x-, y-, z-coordinates of force resolved in frame "
                                     "defined by resolveInFrame [N]")

    def physics(self, e):
        self._apply(e, _inputs(e, self.force), None)


class Torque(_TwoFrames):
    """Torque torque[1..3] [N.m] (input signals, resolved in resolveInFrame, default
    frame_b) acting on frame_b; frame_a gets the opposite torque."""
    torque = VectorPort(RealInput, 3, "x-, y-, z-coordinates of torque resolved in frame "
                                      "defined by resolveInFrame [N.m]")

    def physics(self, e):
        self._apply(e, None, _inputs(e, self.torque))


class ForceAndTorque(_TwoFrames):
    """Force and Torque in one: force[3] [N] at frame_b's origin and torque[3] [N.m] on
    frame_b, both resolved in resolveInFrame (default frame_b); frame_a gets the balancing
    force and torque."""
    force = VectorPort(RealInput, 3, "x-, y-, z-coordinates of force resolved in frame "
                                     "defined by resolveInFrame [N]")
    torque = VectorPort(RealInput, 3, "x-, y-, z-coordinates of torque resolved in frame "
                                      "defined by resolveInFrame [N.m]")

    def physics(self, e):
        self._apply(e, _inputs(e, self.force), _inputs(e, self.torque))


# ---- line forces --------------------------------------------------------------------------
class _LineForce(Animated):
    """A force along the line between the origins of frame_a and frame_b (MSL's
    LineForceBase and PartialLineForce): length = |r_rel_0| [m], s = max(length, s_small)
    (the direction e_rel_0 = r_rel_0/s is regularized at zero length), and a point mass m
    [kg] on the line at lengthFraction from frame_a (subclasses with mass), which moves with
    the line and feels gravity: its kinetic and potential energy are the element's
    (equivalent to MSL's force balance of the point mass; m = 0, the default, is a massless
    line: built with 0, m is fixed at 0 in the compiled model). Subclasses give ``line_force``
    (f [N], > 0 pushes the frames apart). ``fixedRotationAtFrame_a/b``: see the module."""
    options = {"fixedRotationAtFrame_a": False, "fixedRotationAtFrame_b": False}
    s_small = Parameter(1e-10, "m", "prevent zero-division if distance between frame_a and "
                                    "frame_b is zero", positive=True)
    frame_a = Frame_a("coordinate system fixed to the force element with one cut-force and "
                      "cut-torque", required=True)
    frame_b = Frame_b("coordinate system fixed to the force element with one cut-force and "
                      "cut-torque", required=True)

    def structure(self, s):
        for side in ("a", "b"):
            if getattr(self, f"fixedRotationAtFrame_{side}"):
                frame = s.node(f"frame_{side}_world", MULTIBODY, preferred=False)
                s.transform(None, frame, (0.0, 0.0, 0.0))
                for k, axis in enumerate(((1.0, 0, 0), (0, 1.0, 0), (0, 0, 1.0)), start=1):
                    r = s.node(f"r_{side}_0[{k}]", TRANSLATIONAL, velocity=f"v_{side}_0[{k}]")
                    nxt = getattr(self, f"frame_{side}") if k == 3 else \
                        s.node(f"frame_{side}_{k}", MULTIBODY, preferred=False)
                    s.prismatic(frame, nxt, r, axis)
                    frame = nxt

    def line_force(self, e, length, s, s_dot):
        """The line force f [N] from the guarded distance s [m] and its rate [m/s]."""
        raise NotImplementedError

    def _point_mass(self, e, r_a, r_rel_0) -> None:
        m = getattr(self, "m", None)
        if m is None:
            return
        r_cm = r_a + r_rel_0 * self.lengthFraction
        v_cm = e.der(r_cm)
        e.kinetic_energy(0.5 * m * ca.dot(v_cm, v_cm))
        e.potential_energy(m * e.outer(World).potential(r_cm))

    def physics(self, e):
        r_a, T_a = frames.parts(e.pos(self.frame_a))
        r_b, T_b = frames.parts(e.pos(self.frame_b))
        r_rel_0 = r_b - r_a
        length = ca.norm_2(r_rel_0)
        s = ca.fmax(length, self.s_small)
        e_rel_0 = r_rel_0 / s
        f = self.line_force(e, length, s, ca.dot(e_rel_0, e.der(r_rel_0)))
        if f is not None:
            e.flow(self.frame_a, ca.vertcat(-ca.mtimes(T_a, e_rel_0) * f, _ZERO3))
            e.flow(self.frame_b, ca.vertcat(ca.mtimes(T_b, e_rel_0) * f, _ZERO3))
            e.variable("f", f, "N", "line force acting on frame_a and on frame_b (positive, "
                                    "if acting on frame_b and directed from frame_a to "
                                    "frame_b)")
            r_rel_a = ca.mtimes(T_a, r_rel_0)
            record(e, "r_rel_a", r_rel_a, "m", "position vector from origin of frame_a to "
                                               "origin of frame_b, resolved in frame_a")
            record(e, "e_a", r_rel_a / s, "1", "unit vector on the line from frame_a to "
                                               "frame_b, resolved in frame_a")
        self._point_mass(e, r_a, r_rel_0)
        e.variable("length", length, "m", "distance between the origin of frame_a and the "
                                          "origin of frame_b")
        e.variable("s", s, "m", "(guarded) distance between the origin of frame_a and the "
                                "origin of frame_b (>= s_small)")
        record(e, "r_rel_0", r_rel_0, "m", "position vector from frame_a to frame_b resolved "
                                           "in world frame")
        record(e, "e_rel_0", e_rel_0, "1", "unit vector in direction from frame_a to frame_b, "
                                           "resolved in world frame")


class Spring(_LineForce):
    """Linear spring along the line between the origins of frame_a and frame_b:
    f = c·(length − s_unstretched) [N] (c [N/m], no default as in MSL; s_unstretched [m],
    default 0), with an optional point mass m [kg] (default 0) at lengthFraction (default
    0.5) of the line from frame_a, in the world's gravity field (MSL's LineForceWithMass)."""
    options = {"showMass": True}
    required = ("c",)
    c = Parameter(1.0, "N/m", "spring constant", nonnegative=True)
    s_unstretched = Parameter(0.0, "m", "unstretched spring length", nonnegative=True)
    m = Parameter(0.0, "kg", "spring mass located on the connection line between the "
                             "origin of frame_a and the origin of frame_b", nonnegative=True,
                  structural_zero=True)
    lengthFraction = Parameter(0.5, "1", "location of spring mass with respect to frame_a "
                                         "as a fraction of the distance from frame_a to "
                                         "frame_b")

    def line_force(self, e, length, s, s_dot):
        return self.c * (length - self.s_unstretched)


class Damper(_LineForce, PartialElementaryConditionalHeatPortWithoutT):
    """Linear damper along the line between the origins of frame_a and frame_b:
    f = d·der(s) [N] (d [N.s/m], MSL's start 0), lossPower = f·der(s) [W] (to heatPort with
    ``useHeatPort``)."""
    d = Parameter(0.0, "N.s/m", "damping constant", nonnegative=True)

    def line_force(self, e, length, s, s_dot):
        f = self.d * s_dot
        self._loss_power(e, f * s_dot)
        return f


class SpringDamperParallel(_LineForce, PartialElementaryConditionalHeatPortWithoutT):
    """Linear spring and damper in parallel along the line between the origins of frame_a
    and frame_b: f = c·(s − s_unstretched) + d·der(s) [N] (c [N/m], no default as in MSL;
    d [N.s/m], default 0; s_unstretched [m], default 0); lossPower = d·der(s)² [W] (to
    heatPort with ``useHeatPort``)."""
    required = ("c",)
    c = Parameter(1.0, "N/m", "spring constant", nonnegative=True)
    s_unstretched = Parameter(0.0, "m", "unstretched spring length", nonnegative=True)
    d = Parameter(0.0, "N.s/m", "damping constant", nonnegative=True)

    def line_force(self, e, length, s, s_dot):
        f_d = self.d * s_dot
        self._loss_power(e, f_d * s_dot)
        return self.c * (s - self.s_unstretched) + f_d


class LineForceWithMass(_LineForce):
    """General line force with an optional point mass m [kg] (default 0) on the line at
    lengthFraction (default 0.5) from frame_a: the 1-D translational flanges flange_a
    (flange_a.s = 0) and flange_b (flange_b.s = length [m]) carry a force law of the
    Translational library (a Spring, Damper, Force between them) along the line: the force
    on flange_b pushes frame_b away from frame_a, its reaction frame_a back (virtual work of
    the 1-D force over der(length)).

    Difference from MSL: flange_a is fixed (it is the line's origin) and takes the reaction
    of what acts between the flanges; a force applied at flange_a alone (flange_b
    unconnected) acts on nothing, where MSL turns it to −force at flange_b."""
    options = {"animateLine": True, "animateMass": True}
    m = Parameter(0.0, "kg", "mass of point mass on the connection line between the origin "
                             "of frame_a and the origin of frame_b", nonnegative=True,
                  structural_zero=True)
    lengthFraction = Parameter(0.5, "1", "location of point mass with respect to frame_a as "
                                         "a fraction of the distance from frame_a to frame_b")
    flange_b = TranslationalFlange("1-dim. translational flange (connect force of "
                                   "Translational library between flange_a and flange_b)")
    flange_a = TranslationalFlange("1-dim. translational flange (connect force of "
                                   "Translational library between flange_a and flange_b)")

    def structure(self, s):
        super().structure(s)
        s.linear({self.flange_a: 1.0}, 0.0, f"{self.path}: flange_a.s = 0")
        s.distance(self.frame_a, self.frame_b, self.flange_b)

    def line_force(self, e, length, s, s_dot):
        return None
