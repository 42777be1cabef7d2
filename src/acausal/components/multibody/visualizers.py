"""Visualizers (Modelica.Mechanics.MultiBody.Visualizers): FixedShape, FixedFrame and
FixedArrow, parts without physics (no force, torque, mass or equation on frame_a) whose
shape an animation draws at frame_a, with MSL's parameters and defaults, so MSL models that
use them translate as they are.

Each is attached to frame_a (which must be connected: the shape moves with it) and keeps
its drawing data: the numeric ones as Parameters (changeable by ``params=`` like any other,
in the compiled model's parameters), ``shapeType`` (MSL's ShapeType string: "box",
"sphere", "cylinder", "cone", "pipe", "beam", "gearwheel", "spring" or a file name) as an
attribute; ``shape()`` gives them all as a dict of numbers and tuples in frame_a (the
animation reads them there, together with frame_a's r_0 and R.T from a result). Colors
are RGB in 0..255.
"""
from __future__ import annotations

from ...core import Parameter
from .interfaces import Animated, Frame_a

__all__ = ["FixedShape", "FixedFrame", "FixedArrow"]


class _Visualizer(Animated):
    """A drawing fixed at frame_a; no physics."""
    frame_a = Frame_a("coordinate system in which the visualization data is resolved",
                      required=True)

    def shape(self) -> dict:
        """The drawing data: every parameter's value (and ``shapeType`` where there is one),
        resolved in frame_a, with ``animation``."""
        data = {name: self._values[name] for name in self.parameters()}
        data["animation"] = self.animation
        return data


class FixedShape(_Visualizer):
    """A shape fixed at frame_a: shapeType (default "box") of length × width × height [m]
    along lengthDirection / widthDirection from r_shape [m] (resolved in frame_a), color,
    extra (MSL's additional shape data), specularCoefficient."""
    r_shape = Parameter((0.0, 0.0, 0.0), "m", "vector from frame_a to shape origin, "
                                              "resolved in frame_a")
    lengthDirection = Parameter((1.0, 0.0, 0.0), "1", "vector in length direction of shape, "
                                                      "resolved in frame_a")
    widthDirection = Parameter((0.0, 1.0, 0.0), "1", "vector in width direction of shape, "
                                                     "resolved in frame_a")
    length = Parameter(1.0, "m", "length of shape", nonnegative=True)
    width = Parameter(0.1, "m", "width of shape", nonnegative=True)
    height = Parameter(0.1, "m", "height of shape", nonnegative=True)
    color = Parameter((0.0, 128.0, 255.0), "1", "color of shape")
    extra = Parameter(0.0, "1", "additional data for cylinder, cone, pipe, gearwheel and "
                                "spring")
    specularCoefficient = Parameter(0.7, "1", "reflection of ambient light (= 0: light is "
                                              "completely absorbed)", nonnegative=True)

    def __init__(self, name: str | None = None, shapeType: str = "box", **params):
        super().__init__(name, **params)
        self.__dict__["shapeType"] = str(shapeType)

    def shape(self) -> dict:
        return {**super().shape(), "shapeType": self.shapeType}


class FixedFrame(_Visualizer):
    """The axes of frame_a drawn as three arrows of ``length`` [m] (default 0.5) and
    ``diameter`` [m] (default length/40, MSL's world.defaultFrameDiameterFraction), colors
    color_x, color_y, color_z; ``showLabels`` (default True)."""
    options = {"showLabels": True}
    length = Parameter(0.5, "m", "length of axes arrows", nonnegative=True)
    diameter = Parameter(0.0125, "m", "diameter of axes arrows", nonnegative=True)
    color_x = Parameter((0.0, 0.0, 0.0), "1", "color of x-arrow")
    color_y = Parameter((0.0, 0.0, 0.0), "1", "color of y-arrow")
    color_z = Parameter((0.0, 0.0, 0.0), "1", "color of z-arrow")
    specularCoefficient = Parameter(0.7, "1", "reflection of ambient light (= 0: light is "
                                              "completely absorbed)", nonnegative=True)

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)           # (checks the values given first)
        if "length" in params and "diameter" not in params:
            self.diameter = self.length / 40
        for c in ("color_y", "color_z"):
            if "color_x" in params and c not in params:
                setattr(self, c, self.color_x)

    def shape(self) -> dict:
        return {**super().shape(), "showLabels": self.showLabels}


class FixedArrow(_Visualizer):
    """An arrow fixed at frame_a: from r_tail [m] along n (both resolved in frame_a) of
    ``length`` [m] (default 0.1), ``diameter`` [m] (default 0.025, MSL's
    world.defaultArrowDiameter: the world's nominal length 1 m / 40), color."""
    r_tail = Parameter((0.0, 0.0, 0.0), "m", "vector from frame_a to arrow tail, resolved in "
                                             "frame_a")
    n = Parameter((1.0, 0.0, 0.0), "1", "vector in arrow direction, resolved in frame_a")
    length = Parameter(0.1, "m", "length of complete arrow", nonnegative=True)
    diameter = Parameter(0.025, "m", "diameter of arrow line", nonnegative=True)
    color = Parameter((0.0, 0.0, 255.0), "1", "color of arrow")
    specularCoefficient = Parameter(0.7, "1", "reflection of ambient light (= 0: light is "
                                              "completely absorbed)", nonnegative=True)
