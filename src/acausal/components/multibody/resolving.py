"""MSL's ``resolveInFrame`` of 3-D forces and sensors (MultiBody.Types.ResolveInFrameA/B/AB,
the same enumerations as the planar library's) and the optional ``frame_resolve``.

A vector given or measured "in frame X" is resolved in X's axes: with T_X = X.R.T (from the
world to X), a world vector v_0 reads T_X·v_0 in X (MSL's resolve2) and a vector v_X reads
T_Xᵀ·v_X in the world (resolve1). ``frame_resolve`` is a conditional Frame_resolve port that
exists when resolveInFrame is ``frame_resolve``; it must then be connected and carries no
force or torque.
"""
from __future__ import annotations

import casadi as ca

from ... import frames
from ...core import Component, ConditionalPort
from ...core.ports import MultiBodyFrame
from ..planar import ResolveInFrameA, ResolveInFrameAB, ResolveInFrameB

__all__ = ["ResolveInFrameA", "ResolveInFrameB", "ResolveInFrameAB", "Frame_resolve",
           "Resolving", "record"]


class Frame_resolve(MultiBodyFrame):
    """Coordinate system in which vectors are resolved (MSL's Frame_resolve: no cut force
    or torque passes through it)."""


def record(e, name: str, v, unit: str, description: str = "") -> None:
    """Record the 3-vector v as name[1], name[2], name[3]."""
    for k, x in enumerate(ca.vertsplit(v)):
        e.variable(f"{name}[{k + 1}]", x, unit, description)


def output3(e, ports, v) -> None:
    """Set the three outputs ``ports`` (a PortVector) to the 3-vector v."""
    for k, port in enumerate(ports):
        e.output(port, v[k])


class Resolving(Component):
    """A component with MSL's ``resolveInFrame`` (structural, fixed at construction, given
    as the enumeration or its name; subclasses give the enumeration and MSL's default in
    ``options``) and the conditional ``frame_resolve``."""
    options = {"resolveInFrame": ResolveInFrameAB.frame_b}
    frame_resolve = ConditionalPort(
        Frame_resolve("coordinate system in which vectors are optionally resolved",
                      required=True), "resolveInFrame", "frame_resolve")

    def _T(self, e, which=None) -> ca.SX:
        """T = R.T [1] of the frame ``which`` (default: resolveInFrame); identity for the
        world."""
        which = which or self.resolveInFrame.value
        if which == "world":
            return ca.SX.eye(3)
        return frames.parts(e.pos(getattr(self, which)))[1]

    def to_world(self, e, v) -> ca.SX:
        """A vector resolved in resolveInFrame, resolved in the world (resolve1)."""
        return frames.resolve1(self._T(e), v)

    def from_world(self, e, v0) -> ca.SX:
        """A world vector resolved in resolveInFrame (resolve2)."""
        return ca.mtimes(self._T(e), v0)
