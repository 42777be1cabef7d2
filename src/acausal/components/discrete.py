"""Sampled-data blocks with a fixed sample period, after Modelica.Blocks.Discrete (MSL 4.0).

Each block samples at the instants startTime + k·samplePeriod [s] (MSL's
``sampleTrigger = sample(startTime, samplePeriod)``, recorded as ``<block>.sampleTrigger``):
time events where the integrator restarts, and where the block's discrete Real variables
(``StructureBuilder.discrete``, recorded by their MSL names) take their new values in the
event iteration; between the instants they are constant, so a held value is exact. At an
instant every sampled value settles together, so a chain Sampler → Gain → ZeroOrderHold
holds the value sampled at that very instant, as Modelica's sorted when-equations give.

The simulation's start is initialization: the blocks whose MSL equations sample there
(``when {sampleTrigger, initial()}``: Sampler, ZeroOrderHold) take u there (if time >=
startTime); UnitDelay, whose when-clause is not active at initialization, keeps y_start.
A sample instant at the final time is not taken.

ZeroOrderHold's y is MSL's pre(ySample): a loop closed algebraically through the hold (no
state in between) is broken by that infinitesimal delay. Smooth compilation
(``compile(model, smooth=True)``) is refused with a StructureError naming the block.
Not here yet: FirstOrderHold, the discrete TransferFunction and StateSpace (the continuous
ones are in ``signals``), TriggeredSampler, TriggeredMax.
"""
from __future__ import annotations

import casadi as ca

from ..core import Component, Parameter, RealInput, RealOutput
from .logical import refuse_smooth
from .signals import _start

__all__ = ["DiscreteBlock", "DiscreteSISO", "Sampler", "ZeroOrderHold", "UnitDelay"]


class DiscreteBlock(Component):
    """Base of the discrete blocks: samplePeriod [s] (required, as in MSL), startTime [s]
    (first sample instant, 0)."""
    required = ("samplePeriod",)
    samplePeriod = Parameter(0.1, "s", "sample period of component", positive=True)
    startTime = Parameter(0.0, "s", "first sample time instant")

    def structure(self, s):
        refuse_smooth(self, s)


class DiscreteSISO(DiscreteBlock):
    """A discrete block with Real input ``u`` and Real output ``y``."""
    u = RealInput("connector of Real input signal")
    y = RealOutput("connector of Real output signal")


class _SampleAndHold(DiscreteSISO):
    """``when {sampleTrigger, initial()} then <held> = if time >= startTime then u else
    pre(<held>)``, y = <held> (start 0)."""
    _held = "y"

    def structure(self, s):
        super().structure(s)
        s.sample("sampleTrigger", self.startTime, self.samplePeriod, initial=True,
                 description="true, if sample time instant")
        s.discrete(self._held, 0.0, description="value of u at the last sample instant")

    def physics(self, e):
        e.output(self.y, self.sampled(e))

    def sampled(self, e):
        """The held value (its update at the sample instants written)."""
        trigger, held = e.mode("sampleTrigger"), e.mode(self._held)
        now = ca.if_else(e.time >= self.startTime, e.input(self.u), held)
        e.mode_update(held, ca.if_else(trigger, now, held))
        return held


class Sampler(_SampleAndHold):
    """Ideal sampling of a continuous signal: y = u at the sample instants, held in between
    (MSL Discrete.Sampler; y starts at 0 until startTime)."""


class ZeroOrderHold(_SampleAndHold):
    """Zero order hold: y = the input sampled at the last sample instant (MSL
    Discrete.ZeroOrderHold): its discrete variable ``ySample`` (0 until startTime) takes u
    at the sample instants, and y = pre(ySample), MSL's infinitesimal delay: y (a discrete
    variable of its own) keeps its value while the sample trigger is true and takes
    ySample in the event iteration's round after it. So ySample is u with y at its value
    before the instant (and every other sampled value at the instant's), and a loop closed
    algebraically through the hold (u depending on y without a state in between) is a
    difference equation, y_k+1 = f(y_k), as in MSL."""
    _held = "ySample"

    def structure(self, s):
        super().structure(s)
        s.discrete("y", 0.0, description="pre(ySample): ySample after the sample instant")

    def physics(self, e):
        y, held = e.mode("y"), self.sampled(e)
        e.mode_update(y, ca.if_else(e.mode("sampleTrigger"), y, held))
        e.output(self.y, y)


class UnitDelay(DiscreteSISO):
    """Unit delay y = u/z: at each sample instant y = pre(u), the input's value just before
    the instant (MSL Discrete.UnitDelay), so y is the input of the previous instant when u
    is itself a sampled signal; y = y_start (constructor argument, 0) before the first
    sample instant after the start.

    ``sampled`` (a Boolean mode, true through the event iteration once y has taken pre(u))
    makes the update happen once per instant, at the iteration's first round, where every
    value is still its pre value."""

    def __init__(self, name: str | None = None, *, y_start=0.0, **params):
        super().__init__(name, **params)
        self.__dict__["y_start"] = _start(y_start, f"{type(self).__name__}: y_start")

    def structure(self, s):
        super().structure(s)
        s.sample("sampleTrigger", self.startTime, self.samplePeriod,
                 description="true, if sample time instant")
        s.mode("sampled", 0, values=(0, 1),
               description="true, once y took pre(u) at the present sample instant")
        s.discrete("y", self.y_start, description="output: u at the previous sample instant")

    def physics(self, e):
        trigger, sampled, y = e.mode("sampleTrigger"), e.mode("sampled"), e.mode("y")
        e.mode_update(y, ca.if_else(ca.logic_and(trigger, ca.logic_not(sampled)),
                                    e.input(self.u), y))
        e.mode_update(sampled, trigger)
        e.output(self.y, y)
