"""Planar multibody mechanics, after PlanarMechanics (the Modelica library).

Frames carry x, y [m], phi [rad] and the cut force fx, fy [N] and torque t [N.m] resolved in
the world frame (positive into the component, t counter-clockwise). A World gives gravity g
[m/s²] along the unit direction n (default {0, -1}); every Body uses the model's one World.
Joint coordinates are the generalized coordinates wherever the joint graph is a tree
(``rev.phi``, ``prism.s``); a Body with no path to the ground gets its frame's x, y, phi.
Joints can carry a 1-D flange on their axis (``useFlange=True``: flange_a and support), so
that the rotational and translational libraries drive and load them.
"""
from __future__ import annotations

from ..core import Component, Frame, Parameter, RotationalFlange, TranslationalFlange
from ..core.ports import ROTATIONAL, TRANSLATIONAL


class World(Component):
    """Gravity for every Body of the model: acceleration g [m/s²] along n (unit vector)."""
    g = Parameter(9.81, "m/s2", "gravity constant", nonnegative=True)
    n = Parameter((0.0, -1.0), "1", "direction of gravity (normalized)")


class Fixed(Component):
    """A frame fixed in the world at position r [m] and angle phi [rad]."""
    r = Parameter((0.0, 0.0), "m", "fixed frame position")
    phi = Parameter(0.0, "rad", "fixed frame angle")
    frame = Frame("the fixed frame")

    def structure(self, s):
        s.transform(None, self.frame, self.r, self.phi)


class FixedTranslation(Component):
    """A massless rigid bar: frame_b at r [m] from frame_a, resolved in frame_a."""
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
    frame_a. Records r[1], r[2] [m], v[1], v[2] [m/s], phi [rad], w [rad/s] of frame_a."""
    m = Parameter(1.0, "kg", "mass of the body", positive=True)
    I = Parameter(0.1, "kg.m2", "inertia of the body with respect to its centre of mass",
                  nonnegative=True)
    frame_a = Frame("the frame at the centre of mass")

    def physics(self, e):
        world = e.outer(World)
        r, v = e.pos(self.frame_a), e.vel(self.frame_a)
        e.kinetic_energy(0.5 * self.m * (v[0] ** 2 + v[1] ** 2) + 0.5 * self.I * v[2] ** 2)
        e.potential_energy(-self.m * world.g * (world.n[0] * r[0] + world.n[1] * r[1]))
        for k, name in enumerate(("r[1]", "r[2]", "phi")):
            e.variable(name, r[k], "rad" if k == 2 else "m")
        for k, name in enumerate(("v[1]", "v[2]", "w")):
            e.variable(name, v[k], "rad/s" if k == 2 else "m/s")


class Revolute(Component):
    """Revolute joint: frame_b = frame_a rotated by phi [rad] (the coordinate); w [rad/s].

    ``useFlange=True`` adds the rotational flange_a and support, as in PlanarMechanics:
    flange_a.phi = phi (it carries the joint torque) and support.phi = 0 (it takes the
    reaction).
    """
    options = {"useFlange": False}
    frame_a = Frame("frame the joint is fixed to")
    frame_b = Frame("frame turned by phi")

    def _conditional_ports(self):
        if self.useFlange:
            self.flange_a = RotationalFlange("1-D flange that drives the joint", required=True)
            self.support = RotationalFlange("1-D support of the drive", required=True)

    def structure(self, s):
        self._phi = s.node("phi", ROTATIONAL, velocity="w", acceleration="a")
        s.revolute(self.frame_a, self.frame_b, self._phi)
        if self.useFlange:
            s.linear({self.flange_a: 1.0, self._phi: -1.0})
            s.linear({self.support: 1.0}, 0.0)


class Prismatic(Component):
    """Prismatic joint: frame_b = frame_a translated by s [m] (the coordinate) along the unit
    direction r resolved in frame_a; v [m/s].

    ``useFlange=True`` adds the translational flange_a and support, as in PlanarMechanics:
    flange_a.s = s and support.s = 0.
    """
    options = {"useFlange": False}
    r = Parameter((1.0, 0.0), "1", "direction of the rod with respect to frame_a")
    frame_a = Frame("frame the joint is fixed to")
    frame_b = Frame("frame moved by s")

    def _conditional_ports(self):
        if self.useFlange:
            self.flange_a = TranslationalFlange("1-D flange that drives the joint",
                                                required=True)
            self.support = TranslationalFlange("1-D support of the drive", required=True)

    def structure(self, s):
        self._s = s.node("s", TRANSLATIONAL, velocity="v", acceleration="a")
        s.prismatic(self.frame_a, self.frame_b, self._s, self.r)
        if self.useFlange:
            s.linear({self.flange_a: 1.0, self._s: -1.0})
            s.linear({self.support: 1.0}, 0.0)
