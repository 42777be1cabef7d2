"""A 3-D frame placed by coordinates of its own: r_0 and R.T given as functions of 1-D
nodes (a wheel's x, y and angles), the relation a component declares with
``StructureBuilder.pose``.

It fires in the tree like a joint (the frame from its coordinates, never a coordinate from
the frame); its velocity (the frame's twist) and the Jacobian that maps the frame's cut
force and torque to the coordinates' generalized forces come by AD from the pose
(``FrameRelation``). Each pose function gets a class of its own, since the relations' AD
Functions are cached by class.
"""
from __future__ import annotations

from ..frames import pose
from .relations import SpatialRelation

_classes: dict = {}


class CoordinatePose(SpatialRelation):
    """frame = pose(*fn(coordinates, params)): ``fn`` maps the coordinates (a list of scalar
    SX) and the parameters (a list of SX) to (r_0 [m], T = R.T)."""
    fn = None

    def __init__(self, owner, frame, coordinates, params, name=""):
        self.dims = (12,) + (1,) * len(coordinates)
        super().__init__(owner, [frame, *coordinates], params, name)

    def solve_local(self, j, vals, par):
        r, T = type(self).fn([vals[i] for i in range(1, len(self.dims))], par)
        return pose(r, T), None


def coordinate_pose(fn) -> type:
    """The CoordinatePose class of the pose function ``fn`` (one per function)."""
    if fn not in _classes:
        _classes[fn] = type(f"Pose_{fn.__name__}", (CoordinatePose,), {"fn": staticmethod(fn)})
    return _classes[fn]
