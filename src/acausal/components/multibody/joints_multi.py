"""Joints with more than one degree of freedom (Modelica.Mechanics.MultiBody.Joints):
Spherical, FreeMotion, Universal, Cylindrical, Planar, with MSL's names, parameters,
defaults and sign conventions.

Universal, Cylindrical and Planar are, as in MSL, chains of Revolute and Prismatic joints
through internal frames: their coordinates are joint angles and lengths (minimal, the
generalized coordinates of the tree). Spherical and FreeMotion hold the relative motion
in a free 3-D node of their own (``rel``): frame_b = frame_a followed by rel's pose; rel's
orientation state is a quaternion Q (4 states, kept on |Q| = 1) with the relative angular
velocity resolved in frame_b as velocity state, and for FreeMotion the relative position
r_rel_a with its rate v_rel_a (resolved in frame_a): 13 states (see
``acausal.compiler.charts`` for why quaternions, and for what ``compiled.lagrange``
holds). MSL's ``useQuaternions=False`` (three angles as states) is accepted and changes
nothing: the states are always quaternions, so no orientation is singular; the angles MSL
would use as states, in the sequence ``sequence_angleStates``, are recorded as ``phi``, their
rates as ``phi_d`` (outputs: they jump by 2π and are undefined at gimbal lock, the states
are not). Given by name in ``x0`` or ``guess``, phi set Q (any angles, also beyond the
range the recorded phi take; those not given at their start values), and with all three
phi all three phi_d set w.

Start values as MSL's: the relative orientation by ``angles_start`` [rad] about the axes
``sequence_start``, the relative angular velocity ``w_rel_a_start`` [rad/s] (resolved in
frame_a); FreeMotion's relative position and velocity by ``r_rel_a_start`` [m] and
``v_rel_a_start`` [m/s] (MSL's r_rel_a(start=...), v_rel_a(start=...)). The ``*_fixed``
switches are accepted: the start values are always used (nothing else fixes these states;
``x0`` and ``guess`` of ``simulate`` by state name take precedence). MSL's z_rel_a start
values (accelerations) are not accepted: accelerations are no states here.

The ``animation`` switch and the visualization parameters are not used (no animation).
"""
from __future__ import annotations

import casadi as ca

from ... import frames
from ...core import Parameter, StateSelect
from ...core.ports import MULTIBODY, ROTATIONAL, TRANSLATIONAL
from ..interfaces import unit_direction
from .interfaces import PartialTwoFrames
from .parts import _record, check_sequence

__all__ = ["Spherical", "FreeMotion", "Universal", "Cylindrical", "Planar"]


class _FreeRotation(PartialTwoFrames):
    """The relative orientation held by the internal node ``rel`` (quaternion states)."""
    options = {"angles_fixed": False, "w_rel_a_fixed": False, "z_rel_a_fixed": False,
               "enforceStates": False, "useQuaternions": True}
    angles_start = Parameter((0.0, 0.0, 0.0), "rad", "initial values of angles to rotate "
                                                     "frame_a around 'sequence_start' axes "
                                                     "into frame_b")
    sequence_start = Parameter((1.0, 2.0, 3.0), "1", "sequence of rotations to rotate frame_a "
                                                     "into frame_b at initial time")
    w_rel_a_start = Parameter((0.0, 0.0, 0.0), "rad/s", "initial values of angular velocity "
                                                        "of frame_b with respect to frame_a, "
                                                        "resolved in frame_a")
    sequence_angleStates = Parameter((1.0, 2.0, 3.0), "1", "sequence of rotations to rotate "
                                                           "frame_a into frame_b around the 3 "
                                                           "angles recorded as phi")
    translation = False
    w_name = "w_rel"

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        check_sequence(self, "sequence_start")
        check_sequence(self, "sequence_angleStates")

    def structure(self, s):
        rel = s.node("rel", MULTIBODY)
        T0 = frames.axes_rotations(self.sequence_start, self.angles_start)
        start = {"Q": frames.axes_rotations_Q(self.sequence_start, self.angles_start),
                 "w": ca.mtimes(T0, ca.vertcat(self.w_rel_a_start))}
        start.update(self._start_translation())
        s.free_frame(rel, r=_names("r_rel_a"), v=_names("v_rel_a"), Q=_names("Q", 4),
                     w=_names(self.w_name), translation=self.translation, start=start,
                     angles=_names("phi"), angle_rates=_names("phi_d"),
                     sequence=self.sequence_angleStates)
        s.compose(self.frame_a, self.frame_b, rel)

    def _start_translation(self) -> dict:
        return {}

    def physics(self, e):
        rel = e.node("rel")
        _, T = frames.parts(e.pos(rel))
        phi = frames.axes_rotations_angles(T, self.sequence_angleStates)
        _record(e, "phi", phi, "rad", "relative rotation angles in the sequence "
                                      "sequence_angleStates (output)")
        _record(e, "phi_d", e.der(phi), "rad/s", "= der(phi)")
        _record(e, "z_rel_b" if self.translation else "z_rel", e.acc(rel)[3:], "rad/s2",
                "relative angular acceleration of frame_b with respect to frame_a, resolved "
                "in frame_b")
        return rel, T


def _names(base: str, n: int = 3) -> tuple:
    return tuple(f"{base}[{i}]" for i in range(1, n + 1))


class Spherical(_FreeRotation):
    """Spherical joint: frame_b rotates freely about the common origin of frame_a and
    frame_b (MSL's Spherical: no torque is transmitted, frame_a.t = frame_b.t = 0).

    States: the quaternion Q from frame_a to frame_b and w_rel [rad/s], the relative
    angular velocity resolved in frame_b (MSL's names). Records phi [rad] (angles in the
    sequence sequence_angleStates) and z_rel [rad/s²]. MSL's default enforceStates=false
    lets Modelica choose states elsewhere (e.g. a body's); here the joint always holds the
    relative rotation, which gives the same motion."""


class FreeMotion(_FreeRotation):
    """Free motion of frame_b with respect to frame_a (MSL's FreeMotion: no force or torque
    is transmitted, frame_a.f = frame_a.t = 0; a FreeMotion between the World and a Body
    makes a free body with relative states).

    States: r_rel_a [m] (frame_a to frame_b, resolved in frame_a), v_rel_a = der(r_rel_a)
    [m/s], the quaternion Q from frame_a to frame_b and w_rel_b [rad/s], the relative
    angular velocity resolved in frame_b (MSL's names). Records a_rel_a [m/s²], phi [rad],
    z_rel_b [rad/s²]. Default enforceStates=true, as MSL's."""
    options = {"enforceStates": True}
    r_rel_a_start = Parameter((0.0, 0.0, 0.0), "m", "initial position vector from origin of "
                                                    "frame_a to origin of frame_b, resolved "
                                                    "in frame_a (MSL's r_rel_a(start=...))")
    v_rel_a_start = Parameter((0.0, 0.0, 0.0), "m/s", "initial value of der(r_rel_a) (MSL's "
                                                      "v_rel_a(start=...))")
    translation = True
    w_name = "w_rel_b"

    def _start_translation(self) -> dict:
        return {"r": ca.vertcat(self.r_rel_a_start), "v": ca.vertcat(self.v_rel_a_start)}

    def physics(self, e):
        rel, T = super().physics(e)
        vel, acc = e.vel(rel), e.acc(rel)
        # rel's twist: v = T·der(r_rel_a); its rate a = T·der²(r_rel_a) − w × v
        _record(e, "a_rel_a", frames.resolve1(T, acc[:3] + ca.cross(vel[3:], vel[:3])),
                "m/s2", "= der(v_rel_a)")


class _JointChain(PartialTwoFrames):
    """MSL's composite joints: Revolute and Prismatic joints in series through internal
    frames; ``stateSelect`` is accepted (a hint)."""
    options = {"stateSelect": StateSelect.prefer}

    def _frame(self, s, name: str):
        return s.node(name, MULTIBODY, preferred=False)


class Universal(_JointChain):
    """Universal joint: revolute_a about n_a (resolved in frame_a, default {1, 0, 0}) then
    revolute_b about n_b (resolved in the frame between, default {0, 1, 0}); n_a and n_b
    should be orthogonal (MSL's Universal). Records phi_a, phi_b [rad], w_a, w_b [rad/s],
    a_a, a_b [rad/s²]."""
    n_a = Parameter((1.0, 0.0, 0.0), "1", "axis of revolute joint 1 resolved in frame_a")
    n_b = Parameter((0.0, 1.0, 0.0), "1", "axis of revolute joint 2 resolved in frame_b")

    def structure(self, s):
        mid = self._frame(s, "revolute_a.frame_b")
        phi_a = s.node("phi_a", ROTATIONAL, velocity="w_a", acceleration="a_a")
        phi_b = s.node("phi_b", ROTATIONAL, velocity="w_b", acceleration="a_b")
        s.revolute(self.frame_a, mid, phi_a, n=unit_direction(self, "n_a", "(1, 0, 0)"))
        s.revolute(mid, self.frame_b, phi_b, n=unit_direction(self, "n_b", "(0, 1, 0)"))


class Cylindrical(_JointChain):
    """Cylindrical joint: a Prismatic joint along n (resolved in frame_a, default
    {1, 0, 0}) then a Revolute joint about the same axis (MSL's Cylindrical). Records s
    [m], v [m/s], a [m/s²], phi [rad], w [rad/s], wd [rad/s²]."""
    n = Parameter((1.0, 0.0, 0.0), "1", "cylinder axis resolved in frame_a (= same as in "
                                        "frame_b)")

    def structure(self, s):
        mid = self._frame(s, "prismatic.frame_b")
        s_rel = s.node("s", TRANSLATIONAL, velocity="v", acceleration="a")
        phi = s.node("phi", ROTATIONAL, velocity="w", acceleration="wd")
        e = unit_direction(self, "n", "(1, 0, 0)")
        s.prismatic(self.frame_a, mid, s_rel, e)
        s.revolute(mid, self.frame_b, phi, n=e)


class Planar(_JointChain):
    """Planar joint: frame_b moves in the plane orthogonal to n (resolved in frame_a,
    default {0, 0, 1}): Prismatic joints along the x axis (n_x projected into the plane,
    default {1, 0, 0}) and the y axis (n × n_x), then a Revolute joint about n (MSL's
    Planar). Records s_x, s_y [m], phi [rad], v_x, v_y [m/s], w [rad/s], a_x, a_y
    [m/s²], wd [rad/s²]."""
    n = Parameter((0.0, 0.0, 1.0), "1", "axis orthogonal to unconstrained plane, resolved "
                                        "in frame_a (= same as in frame_b)")
    n_x = Parameter((1.0, 0.0, 0.0), "1", "vector in direction of x-axis of plane, resolved "
                                          "in frame_a (n_x shall be orthogonal to n)")

    def structure(self, s):
        mx, my = self._frame(s, "prismatic_x.frame_b"), self._frame(s, "prismatic_y.frame_b")
        sx = s.node("s_x", TRANSLATIONAL, velocity="v_x", acceleration="a_x")
        sy = s.node("s_y", TRANSLATIONAL, velocity="v_y", acceleration="a_y")
        phi = s.node("phi", ROTATIONAL, velocity="w", acceleration="wd")
        n = unit_direction(self, "n", "(0, 0, 1)")
        nx = ca.vertcat(self.n_x)
        ex = ca.cross(ca.cross(n, nx), n)
        ey = ca.cross(n, nx)
        s.prismatic(self.frame_a, mx, sx, ex / ca.norm_2(ex))
        s.prismatic(mx, my, sy, ey / ca.norm_2(ey))
        s.revolute(my, self.frame_b, phi, n=n)
