"""1-D translational mechanics, after Modelica.Mechanics.Translational.

Sign conventions as in MSL: a flange's cut force f is positive into the component; a
compliant element's ``f`` is the force on flange_b (flange_a gets −f); ``s_rel`` =
flange_b.s − flange_a.s. A Mass's ``s`` is the position of its centre, flange_a.s = s − L/2,
flange_b.s = s + L/2.
"""
from __future__ import annotations

from ..core import Component, Parameter, RealInput, TranslationalFlange
from ..core.ports import TRANSLATIONAL

Flange = TranslationalFlange


class Fixed(Component):
    """Flange fixed in the housing at position s0 [m]."""
    s0 = Parameter(0.0, "m", "fixed offset position of the housing")
    flange = Flange("fixed flange")

    def structure(self, s):
        s.linear({self.flange: 1.0}, self.s0)


class Mass(Component):
    """Sliding mass m [kg] of length L [m]; states s [m] (centre) and v [m/s]; a [m/s²]."""
    m = Parameter(1.0, "kg", "mass of the sliding mass", positive=True)
    L = Parameter(0.0, "m", "length of the component, from left to right flange", nonnegative=True)
    flange_a = Flange("left flange")
    flange_b = Flange("right flange")

    def structure(self, s):
        self._centre = s.node("s", TRANSLATIONAL, velocity="v", acceleration="a")
        s.linear({self.flange_a: 1.0, self._centre: -1.0}, -self.L / 2)
        s.linear({self.flange_b: 1.0, self._centre: -1.0}, self.L / 2)

    def physics(self, e):
        e.kinetic_energy(0.5 * self.m * e.vel(self._centre) ** 2)


class PartialCompliant(Component):
    """Two flanges and a force f [N] = flange_b.f = −flange_a.f, depending on s_rel, v_rel."""
    flange_a = Flange("left flange")
    flange_b = Flange("right flange")

    def force(self, s_rel, v_rel):
        """The force f [N] on flange_b for relative position s_rel [m] and speed v_rel [m/s]."""
        raise NotImplementedError

    def physics(self, e):
        s_rel = e.pos(self.flange_b) - e.pos(self.flange_a)
        v_rel = e.vel(self.flange_b) - e.vel(self.flange_a)
        f = self.force(s_rel, v_rel)
        e.flow(self.flange_b, f)
        e.flow(self.flange_a, -f)
        e.variable("s_rel", s_rel, "m")
        e.variable("v_rel", v_rel, "m/s")
        e.variable("f", f, "N")


class Spring(PartialCompliant):
    """Linear spring: f = c·(s_rel − s_rel0)."""
    c = Parameter(1.0, "N/m", "spring constant", nonnegative=True)
    s_rel0 = Parameter(0.0, "m", "unstretched spring length")

    def force(self, s_rel, v_rel):
        return self.c * (s_rel - self.s_rel0)


class Damper(PartialCompliant):
    """Linear damper: f = d·v_rel."""
    d = Parameter(0.0, "N.s/m", "damping constant", nonnegative=True)

    def force(self, s_rel, v_rel):
        return self.d * v_rel


class Force(Component):
    """External force f [N] (RealInput ``f``) acting on ``flange`` in its positive direction."""
    f = RealInput("driving force as input signal")
    flange = Flange("flange on which the force acts")

    def physics(self, e):
        e.flow(self.flange, -e.input(self.f))
