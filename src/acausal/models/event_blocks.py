"""Signal blocks with events and discrete time in a loop (acausal.components.logical,
.discrete): a bang-bang thermostat and a sampled P position controller.

Thermostat: a first-order plant τ·y' = u − y (``plant``, FirstOrder, k = 1, T = tau [s])
heated with power ``power`` while a relation on its output says so, cooled otherwise:

    kind "OnOffController": ref (the middle (lower + upper)/2) ─→ ctrl.reference, plant.y ─→
        ctrl.u; ctrl (OnOffController, bandwidth upper − lower) on below lower, off above
        upper ─→ heater (BooleanToReal: power / 0) ─→ plant.u;
    kind "Hysteresis": plant.y ─→ ctrl (Hysteresis uLow = lower, uHigh = upper, true when
        hot) ─→ heater (Switch: off (0) when true, on (power) when false) ─→ plant.u.

From y = 0 it heats until y = upper, cools until y = lower, and so on (switching times
τ·ln(1 − upper/power) ... logarithms). Coordinate ``plant.y``.

SampledPController: a mass (m [kg]) on a spring (c [N/m]) and a damper (d [N.s/m]) to the
wall, pushed by a force held by a ZeroOrderHold: every ``samplePeriod`` s a Sampler reads
the position, the force K·(reference − x_k) [N] is held until the next instant:

    ref ─→ fb.u1, probe.s ─→ smp ─→ fb.u2, fb ─→ gain (K) ─→ zoh ─→ force ─→ mass

Coordinates mass.s, mass.v; discrete variables smp.y, zoh.ySample, zoh.y.
"""
from __future__ import annotations

from ..components import discrete as dc
from ..components import logical as lg
from ..components import signals as sg
from ..components import translational as tr
from ..core import Model
from ..errors import ParameterError


class Thermostat(Model):
    """The bang-bang thermostat above: kind "OnOffController" or "Hysteresis"; tau [s] the
    plant's time constant, power the heater's, lower / upper the switching temperatures."""

    def __init__(self, name="thermostat", kind="OnOffController", tau=2.0, power=10.0,
                 lower=4.0, upper=6.0):
        super().__init__(name)
        self.plant = sg.FirstOrder(k=1.0, T=tau)
        if kind == "OnOffController":
            self.ctrl = lg.OnOffController(bandwidth=upper - lower, pre_y_start=True)
            self.ref = sg.Constant(k=(upper + lower) / 2)
            self.heater = lg.BooleanToReal(realTrue=power, realFalse=0.0)
            pairs = [(self.ref.y, self.ctrl.reference), (self.plant.y, self.ctrl.u),
                     (self.ctrl.y, self.heater.u), (self.heater.y, self.plant.u)]
        elif kind == "Hysteresis":
            self.ctrl = lg.Hysteresis(uLow=lower, uHigh=upper)      # true (hot): heater off
            self.off, self.on, self.heater = sg.Constant(k=0.0), sg.Constant(k=power), lg.Switch()
            pairs = [(self.plant.y, self.ctrl.u), (self.ctrl.y, self.heater.u2),
                     (self.off.y, self.heater.u1), (self.on.y, self.heater.u3),
                     (self.heater.y, self.plant.u)]
        else:
            raise ParameterError(f"Thermostat: kind must be 'OnOffController' or 'Hysteresis', "
                             f"got {kind!r}")
        for a, b in pairs:
            self.connect(a, b)


class SampledPController(Model):
    """The sampled P controller on a mass above: m [kg], c [N/m], d [N.s/m], gain K [N/m],
    reference [m], samplePeriod [s] of the Sampler and the ZeroOrderHold."""

    def __init__(self, name="sampled_loop", m=1.0, c=4.0, d=0.5, K=12.0, reference=1.0,
                 samplePeriod=0.1):
        super().__init__(name)
        self.ref, self.fb, self.gain = sg.Constant(k=reference), sg.Feedback(), sg.Gain(k=K)
        self.smp = dc.Sampler(samplePeriod=samplePeriod)
        self.zoh = dc.ZeroOrderHold(samplePeriod=samplePeriod)
        self.force, self.mass, self.probe = tr.Force(), tr.Mass(m=m), tr.PositionSensor()
        self.spring, self.damper, self.fixed = tr.Spring(c=c), tr.Damper(d=d), tr.Fixed()
        for a, b in [(self.ref.y, self.fb.u1), (self.probe.s, self.smp.u),
                     (self.smp.y, self.fb.u2), (self.fb.y, self.gain.u),
                     (self.gain.y, self.zoh.u), (self.zoh.y, self.force.f),
                     (self.force.flange, self.mass.flange_b),
                     (self.probe.flange, self.mass.flange_b),
                     (self.fixed.flange, self.spring.flange_a),
                     (self.fixed.flange, self.damper.flange_a),
                     (self.spring.flange_b, self.mass.flange_a),
                     (self.damper.flange_b, self.mass.flange_a)]:
            self.connect(a, b)
