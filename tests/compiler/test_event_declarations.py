"""What components declare for events, as the compiled record holds it: modes appended to the
parameters, indicator records with their owners, reinits resolved to the state they set, the
Functions in (t, x, z, u, p); declaration errors naming the component."""
import casadi as ca
import numpy as np
import pytest

import acausal
from acausal.components.translational import Mass
from acausal.core import Component, TranslationalFlange
from acausal.errors import StructureError
from acausal.models import BouncingBall


class Switch(Component):
    """A mode 'on' (start 1) that turns off when the flange passes s = 1 m going up, and an
    indicator of it; reinit of the flange's speed to 2 m/s there."""
    flange = TranslationalFlange("flange")

    def structure(self, s):
        s.mode("on", 1, values=(0, 1), description="Boolean")

    def physics(self, e):
        on, s = e.mode("on"), e.pos(self.flange)
        e.flow(self.flange, -on * 1.0)               # pushes with 1 N while on
        e.indicator("above", s - 1.0, "m")
        e.mode_update(on, ca.if_else(s > 1.0, 0, on))
        e.reinit(e.vel(self.flange), 2.0, when="above", direction=1)


def switch_model(comp=None):
    model = acausal.Model("switch")
    model.mass = Mass(m=2.0, L=0.4)
    model.switch = comp or Switch()
    model.connect(model.mass.flange_b, model.switch.flange)
    return model


def test_modes_indicators_and_reinits_in_the_record():
    c = acausal.compile(switch_model())
    assert [v.name for v in c.modes] == ["switch.on"]
    assert c.mode_params == [len(c.params) - 1]                  # appended last to p
    assert c.modes[0].start == 1.0 and c.modes[0].component == "switch"
    (ind,) = c.state_events.indicators
    assert (ind.name, ind.unit, ind.component) == ("switch.above", "m", "switch")
    (r,) = c.state_events.reinits
    assert c.x_names[r.state] == "mass.v" and (r.indicator, r.direction) == (0, 1)
    p = c.param_vector()
    x = np.array([0.9, 0.5])                      # mass centre 0.9 m: flange_b at 1.1 m
    g = float(c.indicator_function(0.0, x, [], [], p))
    assert g == pytest.approx(0.9 + 0.2 - 1.0)
    modes, reinit = c.event_update_function(0.0, x, [], [], p)
    assert float(modes) == 0.0 and float(reinit) == 2.0
    xdot = np.array(c.f(x=x, p=p)["xdot"]).ravel()
    assert xdot[1] == pytest.approx(1.0 / 2.0)                  # 1 N on 2 kg while on
    p[c.mode_params] = 0.0
    assert np.array(c.f(x=x, p=p)["xdot"]).ravel()[1] == 0.0


def test_params_set_a_modes_start():
    c = acausal.compile(switch_model())
    assert c.param_vector({"switch.on": 0.0})[c.mode_params[0]] == 0.0


class BadStart(Component):
    flange = TranslationalFlange("flange")

    def structure(self, s):
        s.mode("mode", 2, values=(-1, 0, 1))


class NotAState(Component):
    flange = TranslationalFlange("flange")

    def physics(self, e):
        e.indicator("h", e.pos(self.flange))
        e.reinit(e.pos(self.flange) * e.vel(self.flange), 0.0, when="h")


class TwiceUpdated(Switch):
    def physics(self, e):
        super().physics(e)
        e.mode_update(e.mode("on"), 1)


@pytest.mark.parametrize("comp, message", [
    (BadStart(), "BadStart 'switch': mode 'mode' starts at 2, not one of its values"),
    (NotAState(), "NotAState 'switch': reinit of .* not a state"),
    (TwiceUpdated(), "switch: mode_update of 'switch.on' given twice"),
])
def test_declaration_errors_name_the_component(comp, message):
    with pytest.raises(StructureError, match=message):
        acausal.compile(switch_model(comp))


def test_models_without_events_have_none():
    c = acausal.compile(BouncingBall())
    assert c.has_events and c.mode_params == []
    from acausal.models import Oscillator
    plain = acausal.compile(Oscillator())
    assert not plain.has_events and plain.state_events.indicator.numel() == 0
