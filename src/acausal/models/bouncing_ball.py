"""A ball bouncing on the floor (1-D translational): the state event with a reinit.

    gravity (constant force −m·g) ── ball (Mass m) ── floor (Floor e)

Coordinates ``ball.s`` [m] (height of the ball's flange above the floor at s = 0) and
``ball.v`` [m/s]. Between impacts the ball falls freely; when its height falls through 0
(the floor's indicator ``floor.h``) its velocity is reinitialized to −e·v (Modelica's
``when h < 0 then reinit(v, -e*pre(v))``). Compiled with ``smooth=True`` the floor is a stiff
contact instead (see ``Floor``).
"""
from __future__ import annotations

import casadi as ca

from ..components import translational as tr
from ..core import Component, Model, Parameter, TranslationalFlange

G = 9.81          # gravitational acceleration [m/s²]


class Floor(Component):
    """The floor at s = 0 that a body bounces off, with the coefficient of restitution ``e``
    (the ratio of the speeds after and before an impact). Indicator ``h`` [m]: the height of
    ``flange`` above the floor; an impact (h falling through 0) reinitializes the flange's
    velocity to −e times its value before. Exerts no force between impacts.

    Smooth form (``compile(model, smooth=True)``, for optimal control): no indicator, no
    reinit; the floor pushes the body up with a contact force quadratic in the penetration
    δ = max(−h, 0) [m] (continuous with its first derivative, so that Newton's method and
    IPOPT see smooth equations), stiffer while the body goes in than while it comes out,

        f = c·δ²·(1 + e² + (1 − e²)·tanh(−v/v_smooth))/2,

    so that the elastic energy given back is e² times the energy taken (the restitution
    e for any mass). Against the exact impact, for a body of mass m hitting at speed v_in
    (other forces neglected during the contact): it penetrates δ_max = (3·m·v_in²/(2·c))^(1/3)
    and leaves after the contact time 1.4022·(δ_max/v_in)·(1 + 1/e) (compression, then
    restitution: each ∫₀¹ dξ/√(1 − ξ³) = 1.4022 times δ_max over its speed) at e·v_in, up to
    O(v_smooth/v_in) for the switch of the stiffness at the deepest point; e.g. m = 1 kg at
    4.43 m/s with the default c = 1e7 N/m²: δ_max = 14 mm, 10 ms. Records h [m] and the
    contact force f [N] on the body."""
    e = Parameter(0.8, "1", "coefficient of restitution", nonnegative=True)
    c = Parameter(1e7, "N/m2", "smooth form only: contact stiffness, f = c*depth^2",
                  positive=True)
    v_smooth = Parameter(1e-3, "m/s", "smooth form only: speed over which the contact "
                         "stiffness switches from c to e^2*c", positive=True)
    flange = TranslationalFlange("flange of the body that bounces")

    def physics(self, e):
        v, h = e.vel(self.flange), e.pos(self.flange)
        if e.smooth:
            depth = ca.fmax(-h, 0.0)
            loading = (1 + self.e ** 2 + (1 - self.e ** 2) * ca.tanh(-v / self.v_smooth)) / 2
            f = self.c * depth ** 2 * loading
            e.flow(self.flange, -f)
            e.variable("h", h, "m", "height above the floor")
            e.variable("f", f, "N", "contact force pushing the body up (smooth form)")
            return
        e.indicator("h", h, "m", "height above the floor")
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
