"""Cart-pole: a cart on a rail with a pole hinged on it (the swing-up problem of M. Kelly, "An
introduction to trajectory optimization", SIAM Review 2017, section 6).

The cart (mass m1) runs on a horizontal rail, pushed by a force F [N] (the model's Input); a
pole of length l carries a point mass m2 at its tip and hangs from a hinge on the cart; gravity
g (the World's). Coordinates x = ``rail.s``, θ = ``hinge.phi`` (pole angle from the downward
vertical, counter-clockwise); input ``F`` [N].

``FrictionCartPole`` adds Coulomb friction between cart and rail.

Components (PlanarMechanics and MSL names):

    World  base: Fixed.frame ── rail: Prismatic(useFlange) ── cart: Body (m1, I = 0)
                                  │ axis ← force: Force ← Input F
                                  └ frame_b ── hinge: Revolute ── pole: FixedTranslation (0, −l)
                                                                    └ tip: Body (m2, I = 0)
"""
from __future__ import annotations

from ..components import translational as tr
from ..components.planar import Body, Fixed, FixedTranslation, Prismatic, Revolute, World
from ..core import Input, Model

M_CART, M_POLE, LENGTH = 1.0, 0.3, 0.5      # kg, kg, m


class CartPole(Model):
    """Cart on a rail (rail.s [m]) with a pole (hinge.phi [rad] from hanging down); input F
    [N] pushes the cart along +x.

    m1: cart mass [kg]; m2: mass at the pole's tip [kg]; l: pole length [m].
    """

    def __init__(self, name="cartpole", m1=M_CART, m2=M_POLE, l=LENGTH):
        super().__init__(name)
        self.world = World()
        self.base = Fixed()
        self.rail = Prismatic(r=(1.0, 0.0), useFlange=True)
        self.cart = Body(m=m1, I=0.0)
        self.hinge = Revolute()
        self.pole = FixedTranslation(r=(0.0, -l))
        self.tip = Body(m=m2, I=0.0)
        self.F = Input(unit="N", description="force pushing the cart")
        self.force = tr.Force()
        for a, b in [(self.base.frame, self.rail.frame_a), (self.rail.frame_b, self.cart.frame_a),
                     (self.rail.frame_b, self.hinge.frame_a),
                     (self.hinge.frame_b, self.pole.frame_a),
                     (self.pole.frame_b, self.tip.frame_a),
                     (self.F.y, self.force.f), (self.force.flange, self.rail.axis)]:
            self.connect(a, b)


class FrictionCartPole(CartPole):
    """The cart-pole with Coulomb friction between cart and rail: a translational
    SupportFriction ``friction`` on the rail's axis, sliding friction ``f_c`` [N] (its
    f_pos table [[0, f_c]], peak 1) and MSL's stuck mode in simulation; in smooth form (for
    optimal control) f = f_c·tanh(v/v_smooth). Defaults m1 = 1 kg, m2 = 0.1 kg, l = 1 m,
    f_c = 2 N."""

    def __init__(self, name="friction_cartpole", m1=1.0, m2=0.1, l=1.0, f_c=2.0):
        super().__init__(name, m1=m1, m2=m2, l=l)
        self.friction = tr.SupportFriction(f_pos=[[0.0, f_c]])
        self.connect(self.friction.flange_a, self.rail.axis)
