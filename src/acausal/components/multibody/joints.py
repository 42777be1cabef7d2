"""Joints (Modelica.Mechanics.MultiBody.Joints): Revolute and Prismatic, with MSL's names,
parameters, defaults and sign conventions.

A joint's coordinate (``phi`` / ``s``) is a generalized coordinate of the model wherever
the joint graph is a tree: frame_b follows frame_a through it, and the cut forces and
torques at both frames are the reactions the compiler recovers (``frame_b.f``, ``frame_b.t``
recorded, resolved in frame_b). ``useAxisFlange=True`` adds the 1-D flanges ``axis``
(axis.phi = phi, axis.s = s) and ``support`` (fixed in the world, as MSL's), so motors, dampers
and drive trains of the Rotational and Translational libraries drive and load the joint;
``tau`` / ``f`` is then the drive torque/force (= axis.tau / axis.f), 0 without the flange,
as MSL's ``tau = -frame_b.t*e``.

``animation`` is accepted and changes nothing. The joints with several degrees of
freedom are in ``joints_multi``, the loop-closing ones in ``loop_joints`` and ``assemblies``.
The visualization parameters other than ``animation`` are not declared.
"""
from __future__ import annotations

from ...core import Parameter, RotationalFlange, StateSelect, TranslationalFlange
from ...core.ports import ROTATIONAL, TRANSLATIONAL
from ..interfaces import PartialDrivenJoint, drive_flanges, unit_direction
from .interfaces import PartialTwoFrames

__all__ = ["Revolute", "Prismatic"]


class _Joint(PartialDrivenJoint, PartialTwoFrames):
    """frame_a, frame_b and the optional drive flanges (``useAxisFlange``); ``stateSelect``
    is accepted as a hint (StateSelect)."""
    drive_option = "useAxisFlange"
    options = {"useAxisFlange": False, "stateSelect": StateSelect.prefer}


class Revolute(_Joint):
    """Revolute joint: frame_b rotates about the axis n (resolved in frame_a, = in frame_b;
    default {0, 0, 1}) through the common origin by phi [rad] (MSL: R_rel =
    planarRotation(e, phi), e = n/|n|); the frames coincide at phi = 0.

    Records phi [rad], w = der(phi) [rad/s], a = der(w) [rad/s²], angle = phi and tau
    [N.m], the driving torque in the direction of the axis (= axis.tau; 0 without flange)."""
    n = Parameter((0.0, 0.0, 1.0), "1", "axis of rotation resolved in frame_a (= same as in "
                                        "frame_b)")
    axis, support = drive_flanges(RotationalFlange, "rotational", "useAxisFlange")

    def structure(self, s):
        phi = s.node("phi", ROTATIONAL, velocity="w", acceleration="a")
        s.revolute(self.frame_a, self.frame_b, phi, n=unit_direction(self, "n", "(0, 0, 1)"))
        self._link_flange(s, phi)

    def physics(self, e):
        e.variable("angle", e.pos(e.node("phi")), "rad", "= phi")
        e.variable("tau", self._drive_force(e), "N.m", "driving torque in direction of axis "
                                                       "of rotation")


class Prismatic(_Joint):
    """Prismatic joint: frame_b is translated by s [m] along the axis n (resolved in frame_a,
    default {1, 0, 0}) with respect to frame_a, same orientation (MSL: frame_b.r_0 =
    frame_a.r_0 + resolve1(frame_a.R, e·s)).

    Records s [m], v = der(s) [m/s], a = der(v) [m/s²] and f [N], the actuation force in
    the direction of the axis (= axis.f; 0 without flange)."""
    n = Parameter((1.0, 0.0, 0.0), "1", "axis of translation resolved in frame_a (= same as "
                                        "in frame_b)")
    axis, support = drive_flanges(TranslationalFlange, "translational", "useAxisFlange")

    def structure(self, s):
        s_rel = s.node("s", TRANSLATIONAL, velocity="v", acceleration="a")
        s.prismatic(self.frame_a, self.frame_b, s_rel, unit_direction(self, "n", "(1, 0, 0)"))
        self._link_flange(s, s_rel)

    def physics(self, e):
        e.variable("f", self._drive_force(e), "N", "actuation force in direction of joint "
                                                   "axis")
