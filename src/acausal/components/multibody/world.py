"""The World (Modelica.Mechanics.MultiBody.World): the inertial frame and the gravity field
every body of the model uses (Modelica's inner/outer: exactly one World per model)."""
from __future__ import annotations

from enum import Enum

import casadi as ca

from ...core import Component, Parameter, Unavailable
from ..interfaces import unit_direction
from .interfaces import Frame_b

__all__ = ["GravityTypes", "World"]


class GravityTypes(str, Enum):
    """Type of the gravity field (MultiBody.Types.GravityTypes)."""
    NoGravity = "NoGravity"
    UniformGravity = "UniformGravity"
    PointGravity = "PointGravity"


class World(Component):
    """The world frame ``frame_b`` (origin at r_0 = 0, axes of the world) and the gravity
    field, after MultiBody's World with its defaults:

    - ``gravityType`` UniformGravity (default): acceleration g·n/|n|, g [m/s²] =
      9.80665 (Modelica.Constants.g_n), n = {0, -1, 0} (n = 0 is refused);
    - PointGravity: acceleration −mu/|r|²·r/|r| towards the world origin, mu [m³/s²] =
      3.986004418e14 (the earth's);
    - NoGravity.

    Bodies use it as a potential energy (``potential``): −g·n/|n|·r, −mu/|r| or 0 per
    unit mass. The animation switches (enableAnimation, animateWorld, animateGravity,
    animateGround) are accepted and change nothing (no animation yet); not here: the other
    animation parameters, a redeclared gravity function."""
    options = {"gravityType": GravityTypes.UniformGravity, "enableAnimation": True,
               "animateWorld": True, "animateGravity": True, "animateGround": False,
               "driveTrainMechanics3D": Unavailable(True, "1-D drive trains without 3-D "
                                                          "effects (Rotor1D, Mounting1D)")}
    g = Parameter(9.80665, "m/s2", "constant gravity acceleration", nonnegative=True)
    n = Parameter((0.0, -1.0, 0.0), "1", "direction of gravity resolved in world frame "
                                         "(gravity = g*n/length(n))")
    mu = Parameter(3.986004418e14, "m3/s2", "gravity field constant (default = field "
                                            "constant of earth)", nonnegative=True)
    frame_b = Frame_b("coordinate system fixed in the origin of the world frame")

    def structure(self, s):
        s.transform(None, self.frame_b, (0.0, 0.0, 0.0))

    def gravity_acceleration(self, r) -> ca.SX:
        """MSL's world.gravityAcceleration(r) [m/s²] at the point r [m] (world frame)."""
        kind = self.gravityType
        if kind is GravityTypes.UniformGravity:
            return self.g * unit_direction(self, "n", "(0, -1, 0)")
        if kind is GravityTypes.PointGravity:
            d = ca.norm_2(r)
            return -self.mu / d ** 3 * r
        return ca.SX.zeros(3)

    def potential(self, r) -> ca.SX:
        """The gravity potential per unit mass [J/kg] at the point r [m] (world frame), whose
        negative gradient is ``gravity_acceleration``."""
        kind = self.gravityType
        if kind is GravityTypes.UniformGravity:
            return -ca.dot(self.gravity_acceleration(r), r)
        if kind is GravityTypes.PointGravity:
            return -self.mu / ca.norm_2(r)
        return ca.SX(0)
