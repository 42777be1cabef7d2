"""A mass on a spring and a damper to the ground (1-D translational): the oscillator whose
stiffness and damping the parameter-estimation example and the OCP tests estimate.

    fixed.flange ── spring (c) ── mass (m)
                 └─ damper (d) ──┘

Coordinate ``mass.s`` [m] (the spring's length s_rel0 = 0: mass.s = 0 at rest).
"""
from __future__ import annotations

from ..components import translational as tr
from ..core import Model


class Oscillator(Model):
    """Mass on a spring and a damper in parallel to the ground. m: mass [kg]; c: spring
    stiffness [N/m]; d: damping [N.s/m]."""

    def __init__(self, name="oscillator", m=1.0, c=1.0, d=0.1):
        super().__init__(name)
        self.fixed = tr.Fixed()
        self.spring = tr.Spring(c=c)
        self.damper = tr.Damper(d=d)
        self.mass = tr.Mass(m=m)
        self.connect(self.fixed.flange, self.spring.flange_a)
        self.connect(self.spring.flange_b, self.mass.flange_a)
        self.connect(self.fixed.flange, self.damper.flange_a)
        self.connect(self.damper.flange_b, self.mass.flange_a)
