"""A ball bouncing on the floor (1-D translational): the state event with a reinit.

    gravity (constant force −m·g) ── ball (Mass m) ── floor (Floor e)

Coordinates ``ball.s`` [m] (height of the ball's flange above the floor at s = 0) and
``ball.v`` [m/s]. Between impacts the ball falls freely; when its height falls through 0
(the floor's indicator ``floor.h``) its velocity is reinitialized to −e·v (Modelica's
``when h < 0 then reinit(v, -e*pre(v))``).
"""
from __future__ import annotations

from ..components import translational as tr
from ..core import Component, Model, Parameter, TranslationalFlange

G = 9.81          # gravitational acceleration [m/s²]


class Floor(Component):
    """The floor at s = 0 that a body bounces off, with the coefficient of restitution ``e``
    (the ratio of the speeds after and before an impact). Indicator ``h`` [m]: the height of
    ``flange`` above the floor; an impact (h falling through 0) reinitializes the flange's
    velocity to −e times its value before. Exerts no force between impacts."""
    e = Parameter(0.8, "1", "coefficient of restitution", nonnegative=True)
    flange = TranslationalFlange("flange of the body that bounces")

    def physics(self, e):
        v = e.vel(self.flange)
        e.indicator("h", e.pos(self.flange), "m", "height above the floor")
        e.reinit(v, -self.e * v, when="h", direction=-1)


class BouncingBall(Model):
    """A ball of mass m [kg] in gravity g [m/s²] (a constant force −m·g) bouncing on a floor
    with restitution e."""

    def __init__(self, name="bouncing_ball", m=1.0, e=0.8, g=G):
        super().__init__(name)
        self.ball = tr.Mass(m=m)
        self.gravity = tr.ConstantForce(f_constant=-m * g)
        self.floor = Floor(e=e)
        self.connect(self.gravity.flange, self.ball.flange_a)
        self.connect(self.floor.flange, self.ball.flange_a)
