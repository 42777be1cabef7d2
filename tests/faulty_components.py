"""Components whose events misbehave on purpose, shared by the tests of the event engine and
of the FMUs' event handling: each must end in an error that names it."""
from __future__ import annotations

import casadi as ca

import acausal
from acausal.components.translational import Mass
from acausal.core import Component, Parameter, TranslationalFlange


class Relay(Component):
    """Ideal Coulomb friction without a stuck mode: the force ∓F_c switches with the sign of
    the speed, which chatters about 0."""
    F_c = Parameter(1.0, "N", "sliding friction force")
    flange = TranslationalFlange("the sliding body")

    def structure(self, s):
        s.mode("direction", 1, values=(-1, 1))

    def physics(self, e):
        v, mode = e.vel(self.flange), e.mode("direction")
        e.flow(self.flange, self.F_c * mode)
        e.indicator("v", v, "m/s")
        e.mode_update(mode, ca.if_else(v > 0, 1, -1))


class Toggle(Component):
    """A mode whose update always flips it: the event iteration cannot settle."""
    flange = TranslationalFlange("any flange")

    def structure(self, s):
        s.mode("on", 0, values=(0, 1))

    def physics(self, e):
        on = e.mode("on")
        e.mode_update(on, 1 - on)


def on_a_mass(name: str, part: Component) -> acausal.Model:
    """Model ``name``: a 1 kg mass with ``part`` (as ``model.<name>``) on its flange_a."""
    model = acausal.Model(name)
    model.mass = Mass(m=1.0)
    setattr(model, name, part)
    model.connect(model.mass.flange_a, part.flange)
    return model
