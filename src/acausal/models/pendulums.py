"""Planar pendulum chains: N identical links hanging from a fixed pivot, gravity along −y.

Link i: a Revolute ``rev{i}`` (relative angle, 0 = hanging along the previous link), a
massless bar ``bar{i}`` (FixedTranslation r = (0, −L)) and a Body ``body{i}`` at the bar's
end, where the next joint sits. Coordinates rev1.phi … revN.phi (an open chain: Featherstone's
articulated-body recursion).
"""
from __future__ import annotations

from ..components.planar import Body, Fixed, FixedTranslation, Revolute, World
from ..core import Model


class PendulumChain(Model):
    """n links [-]; L: link length [m]; m: mass of each body [kg]; I: inertia of each body
    about its centre of mass [kg.m²]; g: gravity [m/s²]."""

    def __init__(self, n: int, L=0.5, m=1.0, I=0.01, g=9.81, name=None):
        super().__init__(name or f"pendulum{n}")
        self.world, self.fixed = World(g=g), Fixed()
        prev = self.fixed.frame
        for i in range(1, n + 1):
            rev, bar, body = Revolute(), FixedTranslation(r=(0.0, -L)), Body(m=m, I=I)
            setattr(self, f"rev{i}", rev)
            setattr(self, f"bar{i}", bar)
            setattr(self, f"body{i}", body)
            self.connect(prev, rev.frame_a)
            self.connect(rev.frame_b, bar.frame_a)
            self.connect(bar.frame_b, body.frame_a)
            prev = bar.frame_b
