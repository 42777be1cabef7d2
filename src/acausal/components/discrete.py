"""Sampled-data blocks, after Modelica.Blocks.Discrete (MSL 4.0): Sampler, ZeroOrderHold,
FirstOrderHold, UnitDelay, TransferFunction, StateSpace with a fixed sample period, and
TriggeredSampler, TriggeredMax sampling at the rising edges of a Boolean input.

Each block with a period samples at the instants startTime + k·samplePeriod [s] (MSL's
``sampleTrigger = sample(startTime, samplePeriod)``, recorded as ``<block>.sampleTrigger``):
time events where the integrator restarts, and where the block's discrete Real variables
(``StructureBuilder.discrete``, recorded by their MSL names) take their new values in the
event iteration; between the instants they are constant, so a held value is exact. At an
instant every sampled value settles together, so a chain Sampler → Gain → ZeroOrderHold
holds the value sampled at that very instant, as Modelica's sorted when-equations give.
Blocks whose update reads pre values (FirstOrderHold, UnitDelay, TransferFunction,
StateSpace: pre(x), the state before the instant) read them at the event iteration's
first round and keep them while their inputs settle (a Boolean mode ``sampled``).

The simulation's start is initialization: the blocks whose MSL equations sample there
(``when {sampleTrigger, initial()}``: Sampler, ZeroOrderHold) take u there (if time >=
startTime); the others, whose when-clause is not active at initialization, keep their
start values (UnitDelay y_start, TransferFunction and StateSpace x_start and y = 0,
TriggeredSampler y_start, TriggeredMax 0; FirstOrderHold holds u at the start, its
initial equations). A sample instant at the final time is not taken.

ZeroOrderHold's y is MSL's pre(ySample), FirstOrderHold's y at an instant the sample of
the instant before: a loop closed algebraically through them (no state in between) is
broken by that delay. Smooth compilation (``compile(model, smooth=True)``) is refused with
a StructureError naming the block.
"""
from __future__ import annotations

import casadi as ca

from ..core import BooleanInput, Component, Parameter, RealInput, RealOutput
from .signals.continuous import _Coefficients, _Matrices
from .signals.interfaces import _start, _StartValues, refuse_smooth

__all__ = ["DiscreteBlock", "DiscreteSISO", "DiscreteMIMO", "Sampler", "ZeroOrderHold",
           "FirstOrderHold", "UnitDelay", "TransferFunction", "StateSpace", "TriggeredSampler",
           "TriggeredMax"]


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


class DiscreteMIMO(DiscreteBlock):
    """A discrete block with Real inputs ``u[1]`` .. ``u[nin]`` and Real outputs ``y[1]``
    .. ``y[nout]`` (MSL DiscreteMIMO; the sizes fixed by the block)."""


class _PreValues(DiscreteBlock):
    """A block whose update at a sample instant reads pre values, the values before the
    instant: a Boolean mode ``sampled`` (true through the event iteration once the block
    has read them, at the iteration's first round, where every value is still its pre
    value) tells the first round from the next ones, where the block keeps what it read
    and takes the inputs again until they settle. The sample trigger is false at
    initialization (MSL's ``when sampleTrigger``)."""

    def structure(self, s):
        super().structure(s)
        s.sample("sampleTrigger", self.startTime, self.samplePeriod,
                 description="true, if sample time instant")
        s.mode("sampled", 0, values=(0, 1),
               description="true, once the pre values are read at the present sample instant")

    def instant(self, e) -> tuple[ca.SX, ca.SX]:
        """(sample trigger, first round of the event iteration at the instant)."""
        trigger, sampled = e.mode("sampleTrigger"), e.mode("sampled")
        e.mode_update(sampled, trigger)
        return trigger, ca.logic_and(trigger, ca.logic_not(sampled))


def _sampled(e, trigger, modes: list, values: list) -> None:
    """Each discrete variable of ``modes`` takes its value of ``values`` at the sample
    instants (``trigger`` true) and keeps its value otherwise."""
    for m, v in zip(modes, values):
        e.mode_update(m, ca.if_else(trigger, v, m))


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


class FirstOrderHold(_PreValues, DiscreteSISO):
    """First order hold (MSL Discrete.FirstOrderHold): y is the extrapolation through the
    values of the last two sampled inputs, y = pre_uSample + c·(time − tSample), where at
    each sample instant tSample = time, uSample = u, pre_uSample = the uSample before the
    instant, c = (uSample − pre_uSample)/samplePeriod [1/s] (0 at the first instant,
    startTime). So y runs linearly from the sample of the previous instant to the present
    one over a sample period, and at an instant y = pre_uSample, independent of u: a loop
    closed through the hold has no algebraic loop (MSL's pre(c), equal to c between the
    instants). At initialization (MSL's initial equations) uSample = pre_uSample = u,
    tSample = time, c = 0: y = u(t0) until the second instant. Modelica's initial() is
    ``initialTrigger`` (sample(startTime, samplePeriod), also true at the start) and not
    ``sampleTrigger``: true through the start's event iteration, so u settles there as
    at an instant."""

    def structure(self, s):
        super().structure(s)
        s.sample("initialTrigger", self.startTime, self.samplePeriod, initial=True,
                 description="true at the start and at the sample instants")
        s.discrete("tSample", 0.0, "s", "time of the last sample instant")
        s.discrete("uSample", 0.0, description="u at the last sample instant")
        s.discrete("pre_uSample", 0.0, description="u at the sample instant before the last")
        s.discrete("c", 0.0, "1/s", "slope of the extrapolation")

    def physics(self, e):
        trigger, first = self.instant(e)
        init = ca.logic_and(e.mode("initialTrigger"), ca.logic_not(trigger))
        u, t = e.input(self.u), e.time
        t_s, u_s, pre_u, c = (e.mode(n) for n in ("tSample", "uSample", "pre_uSample", "c"))
        pre_u_now = ca.if_else(init, u, ca.if_else(first, u_s, pre_u))
        first_trigger = t <= self.startTime + self.samplePeriod / 2
        c_now = ca.if_else(ca.logic_or(init, first_trigger), 0,
                           (u - pre_u_now) / self.samplePeriod)
        _sampled(e, ca.logic_or(init, trigger), [t_s, u_s, pre_u, c], [t, u, pre_u_now, c_now])
        e.output(self.y, pre_u + c * (t - t_s))


class UnitDelay(_PreValues, DiscreteSISO):
    """Unit delay y = u/z: at each sample instant y = pre(u), the input's value just before
    the instant (MSL Discrete.UnitDelay), so y is the input of the previous instant when u
    is itself a sampled signal; y = y_start (constructor argument, 0) before the first
    sample instant after the start. It takes u at the event iteration's first round, where
    every value is still its pre value."""

    def __init__(self, name: str | None = None, *, y_start=0.0, **params):
        super().__init__(name, **params)
        self.__dict__["y_start"] = _start(y_start, f"{type(self).__name__}: y_start")

    def structure(self, s):
        super().structure(s)
        s.discrete("y", self.y_start, description="output: u at the previous sample instant")

    def physics(self, e):
        _, first = self.instant(e)
        y = e.mode("y")
        _sampled(e, first, [y], [e.input(self.u)])
        e.output(self.y, y)


class TransferFunction(_Coefficients, _StartValues, _PreValues, DiscreteSISO):
    """Discrete transfer function (MSL Discrete.TransferFunction)::

                b[1]·z^(nb−1) + b[2]·z^(nb−2) + ... + b[nb]
        y(z) = --------------------------------------------- · u(z)
                a[1]·z^(na−1) + a[2]·z^(na−2) + ... + a[na]

    ``b`` and ``a`` (given at construction, default {1}; their sizes nb ≤ na fix the block,
    their values are the parameters ``b[1]`` .. ``b[nb]``, ``a[1]`` .. ``a[na]``). MSL's
    discrete variables of the controller canonical form: at each sample instant::

        x1   = (u − a[2:na]·pre(x))/a[1]
        xext = [x1; pre(x)]            (na values)
        x    = xext[1:na−1]            (nx = na − 1 states)
        y    = [zeros(na − nb); b]·xext

    so y depends on u at the instant only if nb = na. Between the instants every value is
    held; before the first instant after the start y = 0 and x = x_start (constructor
    argument, nx values, default 0: MSL's start values of x; x1, xext and y start at 0)."""
    _starts = ("x_start",)
    _classes: dict = {}

    def structure(self, s):
        super().structure(s)
        s.discrete("x1", 0.0, description="first state of the extended state vector")
        for i in range(self.nx + 1):
            s.discrete(f"xext[{i + 1}]", 0.0, description="extended state vector [x1; pre(x)]")
        for i in range(self.nx):
            s.discrete(f"x[{i + 1}]", self.x_start[i],
                       description="state of transfer function from controller canonical form")
        s.discrete("y", 0.0, description="output at the last sample instant")

    def physics(self, e):
        trigger, first = self.instant(e)
        nb, na = self._key
        a, nx = self.a, self.nx
        x, xext = [e.mode(f"x[{i + 1}]") for i in range(nx)], \
            [e.mode(f"xext[{i + 1}]") for i in range(na)]
        pre_x = [ca.if_else(first, xi, xe) for xi, xe in zip(x, xext[1:])]
        x1 = (e.input(self.u) - sum((a[i + 1] * p for i, p in enumerate(pre_x)), ca.SX(0))) \
            / a[0]
        new_xext = [x1] + pre_x
        bb = [0] * (na - nb) + [self.b[i] for i in range(nb)]
        y = e.mode("y")
        _sampled(e, trigger, [e.mode("x1"), *xext, *x, y],
                 [x1, *new_xext, *new_xext[:nx],
                  sum((c * v for c, v in zip(bb, new_xext)), ca.SX(0))])
        e.output(self.y, y)


class StateSpace(_Matrices, _StartValues, _PreValues, DiscreteMIMO):
    """Discrete state space system (MSL Discrete.StateSpace): at each sample instant::

        x = A·pre(x) + B·u
        y = C·pre(x) + D·u

    pre(x) the state at the previous instant; held in between. ``A`` (nx × nx), ``B``
    (nx × nin), ``C`` (nout × nx), ``D`` (nout × nin, default zeros), given at construction
    (MSL's defaults: A = [1, 0; 0, 1], B = [1; 1], C = [1, 1]); their shapes fix the block,
    their values are the parameters ``A[1]`` .. ``A[nx·nx]`` (row by row), likewise B, C,
    D. Inputs ``u[1]`` .. ``u[nin]``, outputs ``y[1]`` .. ``y[nout]`` (0 before the first
    instant after the start), states ``x[1]`` .. ``x[nx]`` starting at x_start (constructor
    argument, nx values, default 0); ``pre_x[i]`` holds pre(x) through the event
    iteration."""
    _starts = ("x_start",)
    _classes: dict = {}

    def structure(self, s):
        super().structure(s)
        for i in range(self.nx):
            s.discrete(f"x[{i + 1}]", self.x_start[i], description="state vector")
            s.discrete(f"pre_x[{i + 1}]", 0.0,
                       description="pre(x): the state before the last sample instant")
        for i in range(self.nout):
            s.discrete(f"y[{i + 1}]", 0.0, description="output at the last sample instant")

    def physics(self, e):
        trigger, first = self.instant(e)
        A, B, C, D = self._system()
        x = [e.mode(f"x[{i + 1}]") for i in range(self.nx)]
        pre_x = [e.mode(f"pre_x[{i + 1}]") for i in range(self.nx)]
        y = [e.mode(f"y[{i + 1}]") for i in range(self.nout)]
        before = ca.vertcat(*(ca.if_else(first, xi, pi) for xi, pi in zip(x, pre_x)))
        u = ca.vertcat(*(e.input(p) for p in self.u))
        x_new, y_new = A @ before + B @ u, C @ before + D @ u
        _sampled(e, trigger, x + pre_x + y, ca.vertsplit(ca.vertcat(x_new, before, y_new)))
        for port, yi in zip(self.y, y):
            e.output(port, yi)


class _Triggered(Component):
    """A block that samples at the rising edges of its Boolean input ``trigger`` (MSL's
    ``when trigger``): Real input ``u``, output ``y`` (a discrete variable). ``pre_trigger``
    (pre(trigger)) starts true, so a trigger true at the start is no edge (a when-clause is
    inactive at initialization); ``taking`` (set where an edge is seen, at ``tTrigger``)
    makes y follow u through the rest of that event iteration (at time tTrigger), so a u
    sampled at the same instant gives its new value; it is cleared at the next event."""
    u = RealInput("connector with a Real input signal")
    y = RealOutput("connector with a Real output signal")
    trigger = BooleanInput("trigger input")
    _y_start = 0.0

    def taken(self, e, u, edge, y):
        """The value y takes at a trigger instant (``edge``: the round the edge is seen,
        ``y``: y before the round)."""
        raise NotImplementedError

    def structure(self, s):
        refuse_smooth(self, s)
        s.mode("pre_trigger", 1, values=(0, 1),
               description="pre(trigger); true at the start (no edge at initialization)")
        s.mode("taking", 0, values=(0, 1),
               description="true from a rising edge of trigger to the next event")
        s.discrete("tTrigger", 0.0, "s", "time of the last rising edge of trigger")
        s.discrete("y", self._y_start, description="output: taken at the last trigger instant")

    def physics(self, e):
        pre, taking, t_trigger, y = (e.mode(n) for n in ("pre_trigger", "taking",
                                                         "tTrigger", "y"))
        trigger = e.input(self.trigger)
        edge = ca.logic_and(trigger, ca.logic_not(pre))
        active = ca.logic_or(edge, ca.logic_and(taking, e.time == t_trigger))
        e.mode_update(y, ca.if_else(active, self.taken(e, e.input(self.u), edge, y), y))
        e.mode_update(taking, active)
        e.mode_update(t_trigger, ca.if_else(edge, e.time, t_trigger))
        e.mode_update(pre, trigger)
        e.output(self.y, y)


class TriggeredSampler(_Triggered):
    """Triggered sampling of a continuous signal (MSL Discrete.TriggeredSampler): y = u at
    the instants where the Boolean input ``trigger`` rises (false to true), held in
    between; y = y_start (constructor argument, 0) before the first."""

    def __init__(self, name: str | None = None, *, y_start=0.0, **params):
        super().__init__(name, **params)
        self.__dict__["_y_start"] = _start(y_start, f"{type(self).__name__}: y_start")

    @property
    def y_start(self) -> float:
        """Initial value of the output signal."""
        return self._y_start

    def taken(self, e, u, edge, y):
        return u


class TriggeredMax(_Triggered):
    """Maximum absolute value of a continuous signal at trigger instants (MSL
    Discrete.TriggeredMax): where the Boolean input ``trigger`` rises, y = max(pre(y), |u|);
    y = 0 at the start. ``pre_y`` holds pre(y) through the event iteration."""

    def structure(self, s):
        super().structure(s)
        s.discrete("pre_y", 0.0, description="pre(y): y before the last trigger instant")

    def taken(self, e, u, edge, y):
        pre_y = e.mode("pre_y")
        before = ca.if_else(edge, y, pre_y)
        e.mode_update(pre_y, before)
        return ca.fmax(before, ca.fabs(u))
