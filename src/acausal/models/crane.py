"""Gantry crane, a worked case of machine-dynamics courses: a cart on a damped rail with a load hanging from
it on a rope.

A cart (mass M) runs on a horizontal rail with a viscous damper c to the ground and is pushed
by a force F(t); a load (point mass m) hangs on a rope of length L from a hinge on the cart,
with a rotational damper c_T in the hinge; gravity g (the World's). Coordinates x = ``rail.s``
(cart position along the rail), θ = ``hinge.phi`` (rope angle from the downward vertical,
counter-clockwise); input ``F`` [N].

Components (PlanarMechanics and MSL names):

    World  base: Fixed.frame ── rail: Prismatic(useFlange) ── cart: Body (m=M, I=0)
                                   │ axis ← railDamper (to rail.support), force ← Input F
                                   └ frame_b ── hinge: Revolute(useFlange) ── rope: FixedTranslation
                                                  │ axis ← hingeDamper            r = (0, −L)
                                                  └─────────────────────── load: Body (m, I=0)
"""
from __future__ import annotations

from ..components import rotational as rot
from ..components import translational as tr
from ..components.planar import Body, Fixed, FixedTranslation, Prismatic, Revolute, World
from ..core import Input, Model

CART_MASS, LOAD_MASS, ROPE = 5.0, 2.0, 1.0       # kg, kg, m
RAIL_DAMPING, HINGE_DAMPING = 0.5, 0.05          # N.s/m, N.m.s/rad


class GantryCrane(Model):
    """Cart on a damped rail with a pendulum load; input ``F`` [N] pushes the cart along +x.

    M: cart mass [kg]; m: load mass [kg]; L: rope length [m]; c: rail damping [N.s/m];
    c_T: hinge damping [N.m.s/rad].
    """

    def __init__(self, name="crane", M=CART_MASS, m=LOAD_MASS, L=ROPE, c=RAIL_DAMPING,
                 c_T=HINGE_DAMPING):
        super().__init__(name)
        self.world = World()
        self.base = Fixed()
        self.rail = Prismatic(r=(1.0, 0.0), useFlange=True)
        self.cart = Body(m=M, I=0.0)
        self.hinge = Revolute(useFlange=True)
        self.rope = FixedTranslation(r=(0.0, -L))
        self.load = Body(m=m, I=0.0)
        self.railDamper = tr.Damper(d=c)
        self.hingeDamper = rot.Damper(d=c_T)
        self.F = Input(unit="N", description="force pushing the cart")
        self.force = tr.Force()
        for a, b in [(self.base.frame, self.rail.frame_a), (self.rail.frame_b, self.cart.frame_a),
                     (self.rail.frame_b, self.hinge.frame_a),
                     (self.hinge.frame_b, self.rope.frame_a),
                     (self.rope.frame_b, self.load.frame_a),
                     (self.rail.support, self.railDamper.flange_a),
                     (self.railDamper.flange_b, self.rail.axis),
                     (self.hinge.support, self.hingeDamper.flange_a),
                     (self.hingeDamper.flange_b, self.hinge.axis),
                     (self.F.y, self.force.f), (self.force.flange, self.rail.axis)]:
            self.connect(a, b)
