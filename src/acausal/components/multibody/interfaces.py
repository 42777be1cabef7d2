"""Connectors of 3-D multibody systems (Modelica.Mechanics.MultiBody.Interfaces).

``Frame`` is core's ``MultiBodyFrame``: r_0[3] [m] (world), orientation R (R.T[3,3], the
transformation matrix from the world to the frame; R.w [rad/s] its angular velocity
resolved in the frame), cut force f[3] [N] and cut torque t[3] [N.m] about its origin,
resolved in the frame, positive into the component. Frame_a and Frame_b are the same
connector (MSL draws them differently).
"""
from __future__ import annotations

from ...core import Component
from ...core.ports import MultiBodyFrame

__all__ = ["Frame", "Frame_a", "Frame_b", "Animated", "PartialTwoFrames"]

Frame = MultiBodyFrame


class Frame_a(MultiBodyFrame):
    """Coordinate system fixed to the component with one cut-force and cut-torque (filled
    icon in MSL; the same connector as Frame)."""


class Frame_b(MultiBodyFrame):
    """Coordinate system fixed to the component with one cut-force and cut-torque (empty
    icon in MSL; the same connector as Frame)."""


class Animated(Component):
    """MSL's ``animation`` switch of a part or joint: False keeps the part out of the
    animation (``acausal.analysis.animation``); it changes nothing else. The other
    visualization parameters MSL has are not accepted (the animation draws MSL's default
    shapes)."""
    options = {"animation": True}


class PartialTwoFrames(Animated):
    """MSL's Interfaces.PartialTwoFrames: a joint's frame_a and frame_b."""
    partial = True
    frame_a = Frame_a("coordinate system fixed to the joint with one cut-force and "
                      "cut-torque")
    frame_b = Frame_b("coordinate system fixed to the joint with one cut-force and "
                      "cut-torque")
