"""Sensors (Modelica.Mechanics.MultiBody.Sensors): absolute and relative kinematics, angles,
cut force and torque, distance and power of 3-D frames, with MSL's names, outputs,
``resolveInFrame`` (and ``frame_resolve``) and definitions.

Kinematic sensors exert no force or torque. With T_X = X.R.T of the frame X a vector is
resolved in (``resolving``), and a frame's twist (v, w) resolved in it:

- AbsolutePosition r = T_X·frame_a.r_0; AbsoluteVelocity v = T_X·der(frame_a.r_0);
  AbsoluteAngularVelocity w = T_X·w_0 (w_0 frame_a's angular velocity in the world);
  AbsoluteAngles: the angles that rotate the world into frame_a about the axes
  ``sequence`` (MSL's Frames.axesRotationsAngles, with guessAngle1); AbsoluteSensor: all of
  them and a = T_X·der(v_0), z = T_X·der(w_0) (MSL's get_* flags are accepted; every output
  exists).
- RelativePosition r_rel = T_X·(frame_b.r_0 − frame_a.r_0); RelativeVelocity v_rel =
  T_X·T_aᵀ·der(T_a·(frame_b.r_0 − frame_a.r_0)) (the rate seen from frame_a);
  RelativeAngularVelocity w_rel = T_X·(w_b,0 − w_a,0); RelativeAngles (frame_a into
  frame_b); RelativeSensor: r_rel, v_rel = der(r_rel resolved in resolveInFrame), a_rel =
  der(v_rel), w_rel, z_rel = der(w_rel) (each resolved in resolveInFrame before the
  derivative), resolved afterwards in resolveInFrameAfterDifferentiation (default
  resolveInFrame).
- Distance between the origins (MSL's smooth guard below s_small).
- Inline sensors (frame_a and frame_b rigidly joined, the cut force passes): CutForce,
  CutTorque, CutForceAndTorque (frame_a.f / frame_a.t resolved per ResolveInFrameA, sign by
  ``positiveSign``), Power = frame_a.f·v_a + frame_a.t·w_a [W]. Measured cut forces may feed
  outputs and states, not forces of the model.
"""
from __future__ import annotations

import casadi as ca

from ... import frames
from ...core import Component, Parameter, RealOutput, VectorPort
from ...core.component import who
from ...errors import ParameterError
from .interfaces import Animated, Frame_a, Frame_b
from .resolving import ResolveInFrameA, ResolveInFrameAB, Resolving, output3

__all__ = ["AbsolutePosition", "AbsoluteVelocity", "AbsoluteAngularVelocity",
           "AbsoluteAngles", "AbsoluteSensor", "RelativePosition", "RelativeVelocity",
           "RelativeAngularVelocity", "RelativeAngles", "RelativeSensor", "Distance",
           "CutForce", "CutTorque", "CutForceAndTorque", "Power"]


def _world_twist(e, frame):
    """(r_0, T, v_0, w_0): position, orientation and world-resolved velocity and angular
    velocity of a 3-D frame."""
    r0, T = frames.parts(e.pos(frame))
    vel = e.vel(frame)
    return r0, T, frames.resolve1(T, vel[:3]), frames.resolve1(T, vel[3:6])


def _vector(n: int, what: str, unit: str):
    return VectorPort(RealOutput, n, f"{what} [{unit}]")


class _Angles(Component):
    """``sequence`` (default {1, 2, 3}) and guessAngle1 [rad] (default 0) of MSL's angle
    sensors."""
    sequence = Parameter((1.0, 2.0, 3.0), "1", "angles are returned to rotate about axes "
                                               "sequence[1], sequence[2] and finally "
                                               "sequence[3]")
    guessAngle1 = Parameter(0.0, "rad", "select angles[1] such that abs(angles[1] - "
                                        "guessAngle1) is a minimum")

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        seq = self._values["sequence"]
        if any(k not in (1.0, 2.0, 3.0) for k in seq) or seq[1] in (seq[0], seq[2]):
            raise ParameterError(f"{who(self)}: sequence = "
                                 f"{tuple(seq)} is not valid: use axes 1, 2, 3 with "
                                 f"sequence[1] != sequence[2] != sequence[3], e.g. (1, 2, 3)")

    def _angles(self, T):
        return frames.axes_rotations_angles(T, self._values["sequence"], self.guessAngle1)


# ---- absolute sensors ---------------------------------------------------------------------
class _Absolute(Resolving, Animated):
    """Measures frame_a (no force); ResolveInFrameA, default frame_a."""
    options = {"resolveInFrame": ResolveInFrameA.frame_a}
    frame_a = Frame_a("coordinate system from which absolute quantities are provided as "
                      "output signals", required=True)


class AbsolutePosition(_Absolute):
    """Output r[3] [m]: frame_a's origin resolved in resolveInFrame (default frame_a)."""
    r = _vector(3, "absolute position vector resolved in frame defined by resolveInFrame",
                "m")

    def physics(self, e):
        output3(e, self.r, self.from_world(e, _world_twist(e, self.frame_a)[0]))


class AbsoluteVelocity(_Absolute):
    """Output v[3] [m/s]: der(frame_a.r_0) resolved in resolveInFrame (default frame_a)."""
    v = _vector(3, "absolute velocity vector resolved in frame defined by resolveInFrame",
                "m/s")

    def physics(self, e):
        output3(e, self.v, self.from_world(e, _world_twist(e, self.frame_a)[2]))


class AbsoluteAngularVelocity(_Absolute):
    """Output w[3] [rad/s]: frame_a's angular velocity resolved in resolveInFrame (default
    frame_a)."""
    w = _vector(3, "absolute angular velocity vector", "rad/s")

    def physics(self, e):
        output3(e, self.w, self.from_world(e, _world_twist(e, self.frame_a)[3]))


class AbsoluteAngles(_Angles, Animated):
    """Output angles[3] [rad]: rotate the world frame about the axes ``sequence`` into
    frame_a (MSL's axesRotationsAngles)."""
    frame_a = Frame_a("coordinate system for which the absolute angles are provided",
                      required=True)
    angles = _vector(3, "angles to rotate world frame into frame_a via 'sequence'", "rad")

    def physics(self, e):
        output3(e, self.angles, self._angles(frames.parts(e.pos(self.frame_a))[1]))


class AbsoluteSensor(_Absolute, _Angles):
    """All absolute quantities of frame_a: r [m], v [m/s], a [m/s²] (= der(v_0)), w
    [rad/s], z [rad/s²] (= der(w_0)), resolved in resolveInFrame (default frame_a), and
    angles [rad] (world into frame_a via sequence). MSL's get_r .. get_angles are accepted;
    every output exists (an unconnected output costs nothing)."""
    options = {"get_r": False, "get_v": False, "get_a": False, "get_w": False,
               "get_z": False, "get_angles": False}
    r = _vector(3, "absolute position vector frame_a.r_0 resolved in frame defined by "
                   "resolveInFrame", "m")
    v = _vector(3, "absolute velocity vector", "m/s")
    a = _vector(3, "absolute acceleration vector", "m/s2")
    angles = _vector(3, "angles to rotate world frame into frame_a via 'sequence'", "rad")
    w = _vector(3, "absolute angular velocity vector", "rad/s")
    z = _vector(3, "absolute angular acceleration vector", "rad/s2")

    def physics(self, e):
        r0, T, v0, w0 = _world_twist(e, self.frame_a)
        for ports, vec in ((self.r, r0), (self.v, v0), (self.a, e.der(v0)), (self.w, w0),
                           (self.z, e.der(w0))):
            output3(e, ports, self.from_world(e, vec))
        output3(e, self.angles, self._angles(T))


# ---- relative sensors ---------------------------------------------------------------------
class _Relative(Resolving, Animated):
    """Measures frame_b relative to frame_a (no force); ResolveInFrameAB, default frame_a."""
    options = {"resolveInFrame": ResolveInFrameAB.frame_a}
    frame_a = Frame_a("coordinate system a", required=True)
    frame_b = Frame_b("coordinate system b", required=True)

    def _relative(self, e):
        """(r_rel_0, w_rel_0, T_a): frame_b's origin minus frame_a's and its angular velocity
        minus frame_a's, in the world, and frame_a's orientation."""
        ra, Ta, _, wa = _world_twist(e, self.frame_a)
        rb, _, _, wb = _world_twist(e, self.frame_b)
        return rb - ra, wb - wa, Ta


class RelativePosition(_Relative):
    """Output r_rel[3] [m] = frame_b.r_0 − frame_a.r_0 resolved in resolveInFrame (default
    frame_a)."""
    r_rel = _vector(3, "relative position vector resolved in frame defined by "
                       "resolveInFrame", "m")

    def physics(self, e):
        output3(e, self.r_rel, self.from_world(e, self._relative(e)[0]))


class RelativeVelocity(_Relative):
    """Output v_rel[3] [m/s]: der of the relative position resolved in frame_a (the
    velocity of frame_b's origin seen from frame_a), then resolved in resolveInFrame
    (default frame_a)."""
    v_rel = _vector(3, "relative velocity vector resolved in frame defined by "
                       "resolveInFrame", "m/s")

    def physics(self, e):
        r_rel, _, Ta = self._relative(e)
        v_rel_a = e.der(ca.mtimes(Ta, r_rel))
        output3(e, self.v_rel, self.from_world(e, frames.resolve1(Ta, v_rel_a)))


class RelativeAngularVelocity(_Relative):
    """Output w_rel[3] [rad/s]: frame_b's angular velocity relative to frame_a resolved in
    resolveInFrame (default frame_a)."""
    w_rel = _vector(3, "relative angular velocity vector", "rad/s")

    def physics(self, e):
        output3(e, self.w_rel, self.from_world(e, self._relative(e)[1]))


class RelativeAngles(_Angles, Animated):
    """Output angles[3] [rad]: rotate frame_a about the axes ``sequence`` into frame_b (MSL's
    axesRotationsAngles of relativeRotation(frame_a.R, frame_b.R))."""
    frame_a = Frame_a("coordinate system a", required=True)
    frame_b = Frame_b("coordinate system b", required=True)
    angles = _vector(3, "angles to rotate frame_a into frame_b via 'sequence'", "rad")

    def physics(self, e):
        Ta = frames.parts(e.pos(self.frame_a))[1]
        Tb = frames.parts(e.pos(self.frame_b))[1]
        output3(e, self.angles, self._angles(ca.mtimes(Tb, Ta.T)))


class RelativeSensor(_Relative, _Angles):
    """All relative quantities of frame_b with respect to frame_a: r_rel [m], w_rel
    [rad/s] resolved in resolveInFrame (default frame_a); v_rel = der(r_rel), a_rel =
    der(v_rel), z_rel = der(w_rel) with the derivatives of the vectors resolved in
    resolveInFrame, then resolved in resolveInFrameAfterDifferentiation (default: the same,
    a ResolveInFrameAB or its name); angles (frame_a into frame_b). MSL's get_* flags are
    accepted; every output exists."""
    options = {"resolveInFrameAfterDifferentiation": ResolveInFrameAB.frame_a,
               "get_r_rel": False,
               "get_v_rel": False, "get_a_rel": False, "get_w_rel": False,
               "get_z_rel": False, "get_angles": False}
    r_rel = _vector(3, "relative position vector frame_b.r_0 - frame_a.r_0 resolved in "
                       "frame defined by resolveInFrame", "m")
    v_rel = _vector(3, "relative velocity vector", "m/s")
    a_rel = _vector(3, "relative acceleration vector", "m/s2")
    angles = _vector(3, "angles to rotate frame_a into frame_b via 'sequence'", "rad")
    w_rel = _vector(3, "relative angular velocity vector", "rad/s")
    z_rel = _vector(3, "relative angular acceleration vector", "rad/s2")

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        key = "resolveInFrameAfterDifferentiation"
        if key not in params:
            self.__dict__[key] = self.resolveInFrame
        if self.__dict__[key] is ResolveInFrameAB.frame_resolve and \
                self.resolveInFrame is not ResolveInFrameAB.frame_resolve:
            raise ParameterError(f"{who(self)}: {key}=frame_resolve needs "
                                 f"resolveInFrame=frame_resolve (the frame_resolve port)")

    def physics(self, e):
        r_rel_0, w_rel_0, Ta = self._relative(e)
        T_in = self._T(e)
        after = self.resolveInFrameAfterDifferentiation.value
        T_out = ca.mtimes(self._T(e, after), T_in.T)          # resolveInFrame -> after
        r_rel, w_rel = ca.mtimes(T_in, r_rel_0), ca.mtimes(T_in, w_rel_0)
        v_rel = e.der(r_rel)
        output3(e, self.r_rel, r_rel)
        output3(e, self.w_rel, w_rel)
        output3(e, self.v_rel, ca.mtimes(T_out, v_rel))
        output3(e, self.a_rel, ca.mtimes(T_out, e.der(v_rel)))
        output3(e, self.z_rel, ca.mtimes(T_out, e.der(w_rel)))
        Tb = frames.parts(e.pos(self.frame_b))[1]
        output3(e, self.angles, self._angles(ca.mtimes(Tb, Ta.T)))


class Distance(Animated):
    """Output distance [m] between the origins of frame_a and frame_b (no force): |r_rel_0|,
    below s_small [m] (default 1e-10) MSL's smooth L2/(2·s_small)·(3 − L2/s_small²)."""
    s_small = Parameter(1e-10, "m", "prevent zero-division if distance between frame_a and "
                                    "frame_b is zero", positive=True)
    frame_a = Frame_a("coordinate system a", required=True)
    frame_b = Frame_b("coordinate system b", required=True)
    distance = RealOutput("distance between the origin of frame_a and the origin of frame_b "
                          "[m]")

    def physics(self, e):
        d = frames.parts(e.pos(self.frame_b))[0] - frames.parts(e.pos(self.frame_a))[0]
        L2, s2 = ca.dot(d, d), self.s_small ** 2
        e.output(self.distance, ca.if_else(L2 > s2, ca.sqrt(L2),
                                           L2 / (2 * self.s_small) * (3 - L2 / s2)))


# ---- inline sensors -----------------------------------------------------------------------
class _Inline(Animated):
    """frame_a and frame_b rigidly joined (same origin and orientation)."""
    frame_a = Frame_a("coordinate system a", required=True)
    frame_b = Frame_b("coordinate system b", required=True)

    def structure(self, s):
        s.transform(self.frame_a, self.frame_b, (0.0, 0.0, 0.0), name=f"{self.path}: rigid")


class _CutResolved(_Inline, Resolving):
    """Cut vectors resolved per ResolveInFrameA (world, frame_a (default), frame_resolve);
    ``positiveSign`` (default True): frame_a's cut force/torque, else frame_b's (its
    negative)."""
    options = {"resolveInFrame": ResolveInFrameA.frame_a, "positiveSign": True}

    def _cut(self, e):
        f = e.cut_flow(self.frame_a)
        return f if self.positiveSign else -f

    def _resolved(self, e, v_a):
        Ta = frames.parts(e.pos(self.frame_a))[1]
        return self.from_world(e, frames.resolve1(Ta, v_a))


class CutForce(_CutResolved):
    """Output force[3] [N]: the cut force frame_a.f (× −1 with positiveSign=False) resolved
    in resolveInFrame (default frame_a)."""
    force = _vector(3, "cut force resolved in frame defined by resolveInFrame", "N")

    def physics(self, e):
        output3(e, self.force, self._resolved(e, self._cut(e)[:3]))


class CutTorque(_CutResolved):
    """Output torque[3] [N.m]: the cut torque frame_a.t (× −1 with positiveSign=False)
    resolved in resolveInFrame (default frame_a)."""
    torque = _vector(3, "cut torque resolved in frame defined by resolveInFrame", "N.m")

    def physics(self, e):
        output3(e, self.torque, self._resolved(e, self._cut(e)[3:6]))


class CutForceAndTorque(_CutResolved):
    """CutForce and CutTorque in one: outputs force[3] [N], torque[3] [N.m]."""
    force = _vector(3, "cut force resolved in frame defined by resolveInFrame", "N")
    torque = _vector(3, "cut torque resolved in frame defined by resolveInFrame", "N.m")

    def physics(self, e):
        cut = self._cut(e)
        output3(e, self.force, self._resolved(e, cut[:3]))
        output3(e, self.torque, self._resolved(e, cut[3:6]))


class Power(_Inline):
    """Output power [W] flowing from frame_a to frame_b: frame_a.f·v_a + frame_a.t·w_a
    (v_a, w_a frame_a's velocity and angular velocity resolved in frame_a)."""
    power = RealOutput("power at frame_a as output signal [W]")

    def physics(self, e):
        e.output(self.power, ca.dot(e.cut_flow(self.frame_a), e.vel(self.frame_a)))
