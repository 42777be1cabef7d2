"""Pendulum on a spring-mounted cart, a worked case of machine-dynamics courses.

A cart (mass m1) on a horizontal rail is tied by a spring k to a point whose position u(t) is
prescribed; a pendulum (mass m2, inertia J_S about its centre of mass at distance l from the
hinge) hangs from the cart; gravity g (the World's). Coordinates x = ``rail.s`` (cart
position), φ = ``hinge.phi`` (pendulum angle from the downward vertical, counter-clockwise).

Components (PlanarMechanics and MSL names):

    World  base: Fixed.frame ── rail: Prismatic(useFlange) ── cart: Body (m1, I=0)
              rail.axis ── spring (c = k) ── shaker.flange
                                                 shaker: Position(exact=True, useSupport=True),
                                                 support on rail.support, s_ref ← u: Sine
              rail.frame_b ── hinge: Revolute ── arm: FixedTranslation r = (0, −l)
                                                  ── pendulum: Body (m2, I = J_S)

How u(t) enters: the spring's far end is moved by a translational Position source with
exact=True, which makes the end follow u(t) exactly (its speed and acceleration by algorithmic
differentiation). exact=True needs u to be a function of time only, so u is a signal source
(``u``: Sine, u = U sin(2π f t)), not a model Input: the generalized force k·u(t) then sits in
``lagrange.Q_rest`` and the spring's k·x in K. ``drive="input"`` builds the equivalent with a
model Input ``u`` instead: the spring ties the cart to the ground (rail.support) and a Force
k·u (``gain``: Gain with k, which must be kept equal to ``spring.c``) pushes the cart, so
that B = [k, 0]ᵀ — the form a controller or an optimal-control problem wants.
"""
from __future__ import annotations

from ..components import translational as tr
from ..components.planar import Body, Fixed, FixedTranslation, Prismatic, Revolute, World
from ..components.signals import Gain, Sine
from ..core import Input, Model
from ..errors import ParameterError

CART_MASS, PENDULUM_MASS = 2.0, 0.5     # kg
ARM, J_S = 0.3, 0.015                   # m (hinge to centre of mass), kg.m² (about the centre)
STIFFNESS = 200.0                       # N/m
AMPLITUDE, FREQUENCY = 2.0e-3, 0.5      # m, Hz: u(t) = AMPLITUDE sin(2π FREQUENCY t)


class PendulumOnCart(Model):
    """Cart on a spring whose far end moves by u(t), with a pendulum hanging from the cart.

    m1: cart mass [kg]; m2: pendulum mass [kg]; l: hinge to the pendulum's centre of mass
    [m]; J_S: pendulum inertia about its centre of mass [kg.m²]; k: spring stiffness [N/m].
    drive="position": u is the Sine source ``u`` (amplitude U [m], frequency f [Hz]) moving
    the spring's end through Position(exact=True). drive="input": u [m] is a model Input, the
    spring is tied to the ground and the force k·u acts on the cart (U and f unused).
    """

    def __init__(self, name="pendulumOnCart", m1=CART_MASS, m2=PENDULUM_MASS, l=ARM, J_S=J_S,
                 k=STIFFNESS, U=AMPLITUDE, f=FREQUENCY, drive="position"):
        super().__init__(name)
        if drive not in ("position", "input"):
            raise ParameterError(f"drive must be 'position' or 'input', got {drive!r}")
        self.world = World()
        self.base = Fixed()
        self.rail = Prismatic(r=(1.0, 0.0), useFlange=True)
        self.cart = Body(m=m1, I=0.0)
        self.hinge = Revolute()
        self.arm = FixedTranslation(r=(0.0, -l))
        self.pendulum = Body(m=m2, I=J_S)
        self.spring = tr.Spring(c=k)
        links = [(self.base.frame, self.rail.frame_a), (self.rail.frame_b, self.cart.frame_a),
                 (self.rail.frame_b, self.hinge.frame_a), (self.hinge.frame_b, self.arm.frame_a),
                 (self.arm.frame_b, self.pendulum.frame_a),
                 (self.spring.flange_b, self.rail.axis)]
        if drive == "position":
            self.u = Sine(amplitude=U, f=f)
            self.shaker = tr.Position(exact=True, useSupport=True)
            links += [(self.u.y, self.shaker.s_ref), (self.shaker.support, self.rail.support),
                      (self.shaker.flange, self.spring.flange_a)]
        else:
            self.u = Input(unit="m", description="position of the spring's far end")
            self.gain = Gain(k=k)
            self.force = tr.Force()
            links += [(self.rail.support, self.spring.flange_a), (self.u.y, self.gain.u),
                      (self.gain.y, self.force.f), (self.force.flange, self.rail.axis)]
        for a, b in links:
            self.connect(a, b)
