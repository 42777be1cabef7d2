"""Blocks with Boolean signals, after Modelica.Blocks.Logical (MSL 4.0), with the Boolean
sources of Modelica.Blocks.Sources and the conversions of Modelica.Blocks.Math; kept apart
from ``signals`` (Real blocks), which they use.

Boolean signals flow through ``BooleanInput`` / ``BooleanOutput`` ports, carried as 0 (false)
and 1 (true): a kind of port of its own, so a Boolean output connected to a Real input is
refused (``BooleanToReal`` and ``RealToBoolean`` convert). Names, connectors (u, u1, u2, u3,
y), parameters and defaults are those of the MSL blocks.

Relations (``GreaterThreshold``, ``Greater``, ``Hysteresis``, ``OnOffController``,
``RealToBoolean``) work as a Modelica tool's: the output y is a discrete Boolean (a mode,
constant between events, recorded as ``<block>.y``), and an indicator ``switching`` (the
distance of the inputs from changing y, positive while y holds) makes the simulator locate
the instant where the relation changes, to its event tolerance, instead of stepping across
the jump; the event iteration then sets y, and every other mode that depends on it.
Logical blocks (``And``, ``Not``, ``Switch``, ...) are expressions of their inputs, exact
between the events of the blocks that feed them. ``Pre`` is MSL's: y = pre(u), the event
iteration continuing until u = pre(u), which breaks loops of Boolean blocks.

Smooth compilation (``compile(model, smooth=True)``, for optimal control): blocks whose
output is a mode (relations, Hysteresis, OnOffController, Pre) refuse it with a
StructureError naming the block; a switching law for optimal control is written as a
smooth expression instead (e.g. a tanh blend of the two signals of a Switch). The logical
blocks and the Boolean sources (expressions of their inputs and of time) compile either way.

``TerminateSimulation`` ends a simulation at the event where its condition becomes true
(``PhysicsBuilder.terminate``; ``Result.terminated``).

Edge detectors (``Edge``, ``FallingEdge``, ``Change``, MathBoolean's ``RisingEdge``,
``ChangingEdge``) and ``SampleTrigger`` are true only within the event iteration at their
instants, as Modelica's edge(), change() and sample(): blocks they feed (``RSFlipFlop``,
``Timer``) act there; the Result, recorded after each event, shows them false.

After MSL 4.1 also ZeroCrossing (an edge as above, at the state event where u crosses 0),
TriggeredTrapezoid, LogicalDelay and MathBoolean.OnDelay (their when-clauses assign discrete
variables at the edges of u; the delayed switchings and ramp ends are state events),
AssertCondition, BooleanReplicator.

MathBoolean: MSL has two blocks named And (Or, Xor, Nand, Nor, Not): Logical.And with the
inputs u1, u2 and MathBoolean.And with a vector input u[nu]. Logical's keep their plain
names here (``And``, as before); MathBoolean's are in the namespace class ``MathBoolean``,
written as in MSL: ``MathBoolean.And(nu=3)``, ``MathBoolean.OnDelay(delayTime=1)``.
MathBoolean.Not, RisingEdge, FallingEdge and ChangingEdge are Logical's classes (the same
equations). Not available: MultiSwitch and the Integer blocks (no Integer connectors).

Not here yet: Integer signals; model-level Boolean inputs and outputs (``Input`` /
``Output`` are Real: put a BooleanToReal in between).
"""
from __future__ import annotations

from functools import reduce

import casadi as ca
import numpy as np

from ..core import (BooleanInput, BooleanOutput, Component, Parameter, RealInput, RealOutput,
                    Unavailable)
from ..core.component import who
from ..errors import ParameterError
from .signals.interfaces import _MultiInput, refuse_smooth
from .signals.sources import Extrapolation
from .signals.routing import _Replicating

__all__ = [
    "partialBooleanSISO", "partialBooleanSI2SO", "partialBooleanSO",
    "partialBooleanThresholdComparison", "partialBooleanComparison",
    "And", "Or", "Xor", "Nand", "Nor", "Not", "Pre",
    "GreaterThreshold", "GreaterEqualThreshold", "LessThreshold", "LessEqualThreshold",
    "Greater", "GreaterEqual", "Less", "LessEqual", "Hysteresis", "OnOffController",
    "Switch", "LogicalSwitch",
    "BooleanConstant", "BooleanExpression", "BooleanStep", "BooleanPulse", "BooleanTable",
    "BooleanToReal", "RealToBoolean", "BooleanPassThrough", "TerminateSimulation",
    "Edge", "FallingEdge", "Change", "RisingEdge", "ChangingEdge", "Timer", "RSFlipFlop",
    "SampleTrigger", "ZeroCrossing", "TriggeredTrapezoid", "LogicalDelay", "AssertCondition",
    "BooleanReplicator", "PartialBooleanMISO", "MathBoolean",
]


# ---- interfaces (Modelica.Blocks.Interfaces) --------------------------------------------------
class partialBooleanSO(Component):
    """Single Boolean output ``y`` (MSL partialBooleanSO / partialBooleanSource)."""
    partial = True
    y = BooleanOutput("connector of Boolean output signal")


class partialBooleanSISO(partialBooleanSO):
    """Boolean input ``u``, Boolean output ``y``."""
    partial = True
    u = BooleanInput("connector of Boolean input signal")


class partialBooleanSI2SO(partialBooleanSO):
    """Boolean inputs ``u1``, ``u2``, Boolean output ``y``."""
    partial = True
    u1 = BooleanInput("connector of first Boolean input signal")
    u2 = BooleanInput("connector of second Boolean input signal")


class _Relation(partialBooleanSO):
    """y = the relation ``sign·difference > 0`` (``strict``) or ``>= 0`` of Real inputs, a
    Boolean mode on state events (module docstring)."""
    _sign, _strict = 1, True

    def difference(self, e):
        """The difference the relation compares with 0."""
        raise NotImplementedError

    def structure(self, s):
        refuse_smooth(self, s)
        s.mode("y", 0, values=(0, 1), description="Boolean output (relation of the inputs)")

    def physics(self, e):
        y = e.mode("y")
        w = self._sign * self.difference(e)
        e.mode_update(y, w > 0 if self._strict else w >= 0)
        e.indicator("switching", ca.if_else(y, w, -w), "",
                    "distance of the inputs from switching y, positive while y holds")
        e.output(self.y, y)


class partialBooleanThresholdComparison(_Relation):
    """Real input ``u`` compared with ``threshold``; Boolean output ``y``."""
    partial = True
    threshold = Parameter(0.0, "", "comparison with respect to threshold")
    u = RealInput("connector of Real input signal")

    def difference(self, e):
        return e.input(self.u) - self.threshold


class partialBooleanComparison(_Relation):
    """Real inputs ``u1``, ``u2`` compared; Boolean output ``y``."""
    partial = True
    u1 = RealInput("connector of first Real input signal")
    u2 = RealInput("connector of second Real input signal")

    def difference(self, e):
        return e.input(self.u1) - e.input(self.u2)


# ---- relations --------------------------------------------------------------------------------
class GreaterThreshold(partialBooleanThresholdComparison):
    """y = u > threshold."""


class GreaterEqualThreshold(partialBooleanThresholdComparison):
    """y = u >= threshold."""
    _strict = False


class LessThreshold(partialBooleanThresholdComparison):
    """y = u < threshold."""
    _sign = -1


class LessEqualThreshold(partialBooleanThresholdComparison):
    """y = u <= threshold."""
    _sign, _strict = -1, False


class Greater(partialBooleanComparison):
    """y = u1 > u2."""


class GreaterEqual(partialBooleanComparison):
    """y = u1 >= u2."""
    _strict = False


class Less(partialBooleanComparison):
    """y = u1 < u2."""
    _sign = -1


class LessEqual(partialBooleanComparison):
    """y = u1 <= u2."""
    _sign, _strict = -1, False


class RealToBoolean(partialBooleanThresholdComparison):
    """y = u >= threshold (MSL Math.RealToBoolean; threshold default 0.5)."""
    _strict = False
    threshold = Parameter(0.5, "", "output signal y is true, if input u >= threshold")


class _SwitchedByPre(Component):
    """A Boolean output ``y``, a mode that starts at ``pre_y_start`` (option) and is set from
    its own pre value and the inputs (``update``), on state events at ``margin`` (positive
    while y holds)."""
    options = {"pre_y_start": False}
    y = BooleanOutput("connector of Boolean output signal")

    def update(self, e, y):
        raise NotImplementedError

    def margin(self, e, y):
        raise NotImplementedError

    def structure(self, s):
        refuse_smooth(self, s)
        s.mode("y", int(self.pre_y_start), values=(0, 1),
               description="Boolean output; its start value is pre_y_start")

    def physics(self, e):
        y = e.mode("y")
        e.mode_update(y, self.update(e, y))
        e.indicator("switching", self.margin(e, y), "",
                    "distance of the input from switching y, positive while y holds")
        e.output(self.y, y)


class Hysteresis(_SwitchedByPre):
    """Real to Boolean with hysteresis: y = not pre(y) and u > uHigh or pre(y) and u >= uLow
    (MSL Logical.Hysteresis): y switches to true when u rises above uHigh, to false when u
    falls below uLow. Input ``u`` (Real), output ``y`` (Boolean).

    Parameters: uLow, uHigh (required, as in MSL; uHigh > uLow); option ``pre_y_start``
    (False): the value of pre(y) at the start (the start value of the mode ``y``, also given
    at simulation time as ``params={"<block>.y": 1}``).
    """
    required = ("uLow", "uHigh")
    uLow = Parameter(0.0, "", "if y=true and u<uLow, switch to y=false")
    uHigh = Parameter(1.0, "", "if y=false and u>uHigh, switch to y=true")
    u = RealInput("connector of Real input signal")

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        if not self.uHigh > self.uLow:
            raise ParameterError(f"{who(self)}: hysteresis limits wrong: uHigh (= {self.uHigh})"
                                 f" <= uLow (= {self.uLow})")

    def update(self, e, y):
        u = e.input(self.u)
        return ca.if_else(y, u >= self.uLow, u > self.uHigh)

    def margin(self, e, y):
        u = e.input(self.u)
        return ca.if_else(y, u - self.uLow, self.uHigh - u)


class OnOffController(_SwitchedByPre):
    """On-off controller: y = pre(y) and (u < reference + bandwidth/2) or (u < reference −
    bandwidth/2) (MSL Logical.OnOffController): y (the actuator) switches on when the
    measurement ``u`` falls below reference − bandwidth/2, off when it rises to reference +
    bandwidth/2. Inputs ``reference``, ``u`` (Real), output ``y`` (Boolean).

    Parameters: bandwidth (required, as in MSL); option ``pre_y_start`` (False).
    """
    required = ("bandwidth",)
    bandwidth = Parameter(0.1, "", "bandwidth around reference signal", nonnegative=True)
    reference = RealInput("connector of Real input signal used as reference signal")
    u = RealInput("connector of Real input signal used as measurement signal")

    def _limits(self, e):
        u, ref = e.input(self.u), e.input(self.reference)
        return u, ref + self.bandwidth / 2, ref - self.bandwidth / 2

    def update(self, e, y):
        u, upper, lower = self._limits(e)
        return ca.if_else(y, u < upper, u < lower)

    def margin(self, e, y):
        u, upper, lower = self._limits(e)
        return ca.if_else(y, upper - u, u - lower)


# ---- logical ----------------------------------------------------------------------------------
class And(partialBooleanSI2SO):
    """y = u1 and u2."""

    def physics(self, e):
        e.output(self.y, ca.logic_and(e.input(self.u1), e.input(self.u2)))


class Or(partialBooleanSI2SO):
    """y = u1 or u2."""

    def physics(self, e):
        e.output(self.y, ca.logic_or(e.input(self.u1), e.input(self.u2)))


class Xor(partialBooleanSI2SO):
    """y = u1 xor u2: true if exactly one input is true."""

    def physics(self, e):
        e.output(self.y, e.input(self.u1) != e.input(self.u2))


class Nand(partialBooleanSI2SO):
    """y = not (u1 and u2)."""

    def physics(self, e):
        e.output(self.y, ca.logic_not(ca.logic_and(e.input(self.u1), e.input(self.u2))))


class Nor(partialBooleanSI2SO):
    """y = not (u1 or u2)."""

    def physics(self, e):
        e.output(self.y, ca.logic_not(ca.logic_or(e.input(self.u1), e.input(self.u2))))


class Not(partialBooleanSISO):
    """y = not u."""

    def physics(self, e):
        e.output(self.y, ca.logic_not(e.input(self.u)))


class Pre(partialBooleanSISO):
    """y = pre(u): the input's value before the present event iteration round (MSL
    Logical.Pre); the event iteration continues until u = pre(u). It breaks loops of
    Boolean blocks. Option ``pre_u_start`` (False): pre(u) at the start (the start value
    of the mode ``y``)."""
    options = {"pre_u_start": False}

    def structure(self, s):
        refuse_smooth(self, s)
        s.mode("y", int(self.pre_u_start), values=(0, 1), description="pre(u)")

    def physics(self, e):
        y = e.mode("y")
        e.mode_update(y, e.input(self.u))
        e.output(self.y, y)


class _EdgeDetector(partialBooleanSISO):
    """A Boolean output that is true only within the event iteration at an instant where
    the input changes: y = ``detected(u, pre(u))``, pre(u) the mode ``pre_u`` (start
    ``pre_u_start``, option) that takes u at every event, so the iteration's next round
    gives y = false again. Blocks fed by y act at that instant (an RSFlipFlop is set); the
    Result shows y false, as MSL's results after the event."""
    options = {"pre_u_start": False}

    def detected(self, u, pre_u):
        raise NotImplementedError

    def structure(self, s):
        refuse_smooth(self, s)
        s.mode("pre_u", int(self.pre_u_start), values=(0, 1),
               description="pre(u): the input before the event; start pre_u_start")

    def physics(self, e):
        u, pre_u = e.input(self.u), e.mode("pre_u")
        e.mode_update(pre_u, u)
        e.output(self.y, self.detected(u, pre_u))


class Edge(_EdgeDetector):
    """Rising edge: y = edge(u) = u and not pre(u) (MSL Logical.Edge), true at the instant
    u becomes true. Option ``pre_u_start`` (False): pre(u) at the start."""

    def detected(self, u, pre_u):
        return ca.logic_and(u, ca.logic_not(pre_u))


class FallingEdge(_EdgeDetector):
    """Falling edge: y = edge(not u) = pre(u) and not u (MSL Logical.FallingEdge), true at
    the instant u becomes false. Option ``pre_u_start`` (False): pre(u) at the start."""

    def detected(self, u, pre_u):
        return ca.logic_and(pre_u, ca.logic_not(u))


class Change(_EdgeDetector):
    """Rising or falling edge: y = change(u) = (u <> pre(u)) (MSL Logical.Change). Option
    ``pre_u_start`` (False): pre(u) at the start."""

    def detected(self, u, pre_u):
        return u != pre_u


class RisingEdge(Edge):
    """MSL MathBoolean.RisingEdge: the equations of Logical.Edge, y = edge(u)."""


class ChangingEdge(Change):
    """MSL MathBoolean.ChangingEdge: the equations of Logical.Change, y = change(u)."""


class Timer(Component):
    """Timer (MSL Logical.Timer): y = time − entryTime [s] while the Boolean input u is
    true, 0 while it is false; ``entryTime`` (a discrete variable, 0 at the start) is the
    instant u last became true (``when u then entryTime = time``, pre(u) the mode
    ``pre_u``). At that instant y is already 0 in the event iteration. The when-clause is
    inactive at initialization, as in MSL: ``pre_u`` starts true, so a u true from the
    start t0 is no rising edge, entryTime keeps 0 and y = time (not time − t0) until u
    falls."""
    u = BooleanInput("connector of Boolean input signal")
    y = RealOutput("connector of Real output signal")

    def structure(self, s):
        refuse_smooth(self, s)
        s.mode("pre_u", 1, values=(0, 1),
               description="pre(u): the input before the event; true at the start (no "
                           "edge at initialization)")
        s.discrete("entryTime", 0.0, "s", "time instant when u became true")

    def physics(self, e):
        u, pre_u, entry = e.input(self.u), e.mode("pre_u"), e.mode("entryTime")
        entry_now = ca.if_else(ca.logic_and(u, ca.logic_not(pre_u)), e.time, entry)
        e.mode_update(entry, entry_now)
        e.mode_update(pre_u, u)
        e.output(self.y, ca.if_else(u, e.time - entry_now, 0))


class RSFlipFlop(Component):
    """A basic RS flip flop (MSL Logical.RSFlipFlop): Q is set by the input S, reset by R,
    and keeps its value in between; QI is its inverse. MSL's network of two Nor blocks and a
    Pre: Q = not (pre.y or R), pre.y = pre(not (S or Q)), QI = pre.y; the mode ``pre.y``
    starts at not Qini (option ``Qini``, False: the start value of Q). S and R both true
    give Q = QI = false."""
    options = {"Qini": False}
    S = BooleanInput("set input")
    R = BooleanInput("reset input")
    Q = BooleanOutput("output Q")
    QI = BooleanOutput("inverse output QI")

    def structure(self, s):
        refuse_smooth(self, s)
        s.mode("pre.y", int(not self.Qini), values=(0, 1),
               description="pre(nor.y): the flip flop's memory (= QI); start not Qini")

    def physics(self, e):
        qi = e.mode("pre.y")
        q = ca.logic_not(ca.logic_or(qi, e.input(self.R)))
        e.mode_update(qi, ca.logic_not(ca.logic_or(e.input(self.S), q)))
        e.output(self.Q, q)
        e.output(self.QI, qi)


class _WhenChanged(Component):
    """A block with Modelica's ``when {initial(), u, not u}``: the mode ``pre_u`` is pre(u),
    −1 before the event iteration at the start (``initial()``), so ``when_changed`` tells the
    start and every instant where the Boolean input ``u`` changes; ``discretes`` (name →
    (start, unit, description)) are the discrete Real variables that the subclass sets
    there (``assign``). The outputs use the assigned values, as the equations after a
    when-clause do, so they are right at both limits of an event."""
    u = BooleanInput("connector of Boolean input signal")
    discretes: dict = {}

    def structure(self, s):
        refuse_smooth(self, s)
        s.mode("pre_u", -1, values=(-1, 0, 1),
               description="pre(u): the input before the event; -1 before the start")
        for name, (start, unit, text) in self.discretes.items():
            s.discrete(name, start, unit, text)

    def when_changed(self, e):
        """(u, initial, changed): the input, whether this is the start, whether u changed
        (or this is the start); pre_u takes u."""
        u, pre_u = e.input(self.u), e.mode("pre_u")
        e.mode_update(pre_u, u)
        return u, pre_u < 0, u != pre_u

    @staticmethod
    def assign(e, variable, value):
        """``variable`` (a discrete variable) takes ``value`` at events; returns ``value``."""
        e.mode_update(variable, value)
        return value


class TriggeredTrapezoid(_WhenChanged):
    """Triggered trapezoid generator (MSL Logical.TriggeredTrapezoid): the Real output ``y``
    rises from ``offset`` to offset + ``amplitude`` within ``rising`` [s] when the Boolean
    input ``u`` becomes true, and falls back within ``falling`` [s] when it becomes false;
    an edge during a ramp turns it at the value it has reached, with the other slope. With
    MSL's discrete variables: at the start and at every change of u, endValue = offset +
    amplitude if u else offset, rate = ±amplitude/rising (falling), T = time + (endValue −
    pre(y))/rate (time where no ramp: rising or falling 0, amplitude 0, the start);
    y = endValue − (T − time)·rate for time < T, endValue after (a state event at T).

    ``falling`` defaults to ``rising`` as given at construction (MSL: falling = rising).
    """
    amplitude = Parameter(1.0, "", "amplitude of trapezoid")
    rising = Parameter(0.0, "s", "rising duration of trapezoid", nonnegative=True)
    falling = Parameter(0.0, "s", "falling duration of trapezoid (default: rising)",
                        nonnegative=True)
    offset = Parameter(0.0, "", "offset of output signal")
    y = RealOutput("connector of Real output signal")
    discretes = {"endValue": (0.0, "", "value of y at time of recent edge"),
                 "rate": (0.0, "1/s", "current rising/falling rate"),
                 "T": (0.0, "s", "predicted time of output reaching endValue")}

    def __init__(self, name: str | None = None, **params):
        params.setdefault("falling", params.get("rising", 0.0))
        super().__init__(name, **params)

    @staticmethod
    def _output(t, end, rate, T):
        return ca.if_else(t < T, end - (T - t) * rate, end)

    def physics(self, e):
        t = e.time
        u, initial, changed = self.when_changed(e)
        end, rate, T = (e.mode(n) for n in ("endValue", "rate", "T"))
        end_new = ca.if_else(u, self.offset + self.amplitude, self.offset)
        rate_new = ca.if_else(ca.logic_and(u, self.rising > 0), self.amplitude / self.rising,
                              ca.if_else(ca.logic_and(ca.logic_not(u), self.falling > 0),
                                         -self.amplitude / self.falling, 0))
        no_ramp = ca.logic_or(ca.logic_or(rate_new == 0, ca.fabs(self.amplitude) <= 0),
                              initial)
        safe_rate = ca.if_else(rate_new == 0, 1, rate_new)
        T_new = ca.if_else(no_ramp, t,
                           t + (end_new - self._output(t, end, rate, T)) / safe_rate)
        now = [self.assign(e, sym, ca.if_else(changed, new, sym))
               for sym, new in ((end, end_new), (rate, rate_new), (T, T_new))]
        e.indicator("ramp_end", t - T, "s", "time since the ramp reached endValue")
        e.output(self.y, self._output(t, *now))


class LogicalDelay(_WhenChanged):
    """Delay a Boolean signal (MSL Logical.LogicalDelay): when ``u`` becomes true, ``y1``
    becomes true at once and ``y2`` ``delayTime`` [s] later; when u becomes false, y2
    becomes false at once and y1 delayTime later. tSwitch, the instant of u's last change
    (time − 2·delayTime at the start), is a discrete variable; the delayed switchings are
    state events at tSwitch + delayTime."""
    delayTime = Parameter(0.0, "s", "time delay", nonnegative=True)
    y1 = BooleanOutput("true at once when u becomes true, false delayTime after it falls")
    y2 = BooleanOutput("true delayTime after u becomes true, false at once when it falls")
    discretes = {"tSwitch": (0.0, "s", "time instant of the last change of u")}

    def physics(self, e):
        t = e.time
        u, initial, changed = self.when_changed(e)
        t_switch = e.mode("tSwitch")
        now = self.assign(e, t_switch, ca.if_else(initial, t - 2 * self.delayTime,
                                                  ca.if_else(changed, t, t_switch)))
        late = t >= now + self.delayTime
        e.indicator("delayed", t - t_switch - self.delayTime, "s",
                    "time since delayTime passed after the last change of u")
        e.output(self.y1, ca.logic_or(u, ca.logic_not(late)))
        e.output(self.y2, ca.logic_and(u, late))


class ZeroCrossing(partialBooleanSO):
    """Trigger zero crossings of ``u`` (MSL Logical.ZeroCrossing): y is true at the instant
    the Real input ``u`` crosses zero (a state event) while the Boolean input ``enable`` is
    true, false elsewhere and at instants where enable changes: y = change(u_pos) and not
    edge(enable) and not edge(not enable), u_pos = enable and u >= 0; pre(u_pos) and
    pre(enable) are modes starting false. As the edge blocks, y is true only within the
    event iteration (the Result shows it false): blocks it feeds (Timer, RSFlipFlop) act
    there."""
    u = RealInput("connector of Real input signal")
    enable = BooleanInput("zero input crossing is triggered if the enable input signal is "
                          "true")

    def structure(self, s):
        refuse_smooth(self, s)
        s.mode("pre_u_pos", 0, values=(0, 1), description="pre(u_pos): enable and u >= 0")
        s.mode("pre_enable", 0, values=(0, 1), description="pre(enable)")

    def physics(self, e):
        u, enable = e.input(self.u), e.input(self.enable)
        pre_pos, pre_enable = e.mode("pre_u_pos"), e.mode("pre_enable")
        u_pos = ca.logic_and(enable, u >= 0)
        e.mode_update(pre_pos, u_pos)
        e.mode_update(pre_enable, enable)
        e.indicator("crossing", ca.if_else(enable, u, 1), "", "u while enabled")
        e.output(self.y, ca.logic_and(u_pos != pre_pos, enable == pre_enable))


class AssertCondition(Component):
    """Assert that the Boolean input ``u`` is true (MSL Logical.AssertCondition): simulate()
    stops with a SimulationError naming the block and ``message`` (constructor argument)
    at the first point where u is false (``PhysicsBuilder.assertion``).

    MSL differences: the assertion level is error only (no ``assertionLevel`` warning).
    """
    u = BooleanInput("connector of Boolean input signal")

    def __init__(self, name: str | None = None, *, message: str = "Assert block failed",
                 **params):
        super().__init__(name, **params)
        self.__dict__["message"] = str(message)

    def physics(self, e):
        e.assertion(e.input(self.u), self.message)


class Switch(Component):
    """y = if u2 then u1 else u3: switch between two Real signals by a Boolean one (MSL
    Logical.Switch). Inputs ``u1``, ``u3`` (Real), ``u2`` (Boolean); output ``y`` (Real)."""
    u1 = RealInput("connector of first Real input signal")
    u2 = BooleanInput("connector of Boolean input signal")
    u3 = RealInput("connector of second Real input signal")
    y = RealOutput("connector of Real output signal")

    def physics(self, e):
        e.output(self.y, ca.if_else(e.input(self.u2), e.input(self.u1), e.input(self.u3)))


class LogicalSwitch(Component):
    """y = if u2 then u1 else u3, for Boolean signals (MSL Logical.LogicalSwitch)."""
    u1 = BooleanInput("connector of first Boolean input signal")
    u2 = BooleanInput("connector of second Boolean input signal")
    u3 = BooleanInput("connector of third Boolean input signal")
    y = BooleanOutput("connector of Boolean output signal")

    def physics(self, e):
        e.output(self.y, ca.if_else(e.input(self.u2), e.input(self.u1), e.input(self.u3)))


# ---- conversions (Modelica.Blocks.Math) ---------------------------------------------------------
class BooleanToReal(Component):
    """y = if u then realTrue else realFalse (MSL Math.BooleanToReal)."""
    realTrue = Parameter(1.0, "", "output signal for true input")
    realFalse = Parameter(0.0, "", "output signal for false input")
    u = BooleanInput("connector of Boolean input signal")
    y = RealOutput("connector of Real output signal")

    def physics(self, e):
        e.output(self.y, ca.if_else(e.input(self.u), self.realTrue, self.realFalse))


# ---- sources (Modelica.Blocks.Sources) ----------------------------------------------------------
def _event_tolerance(t):
    """How far [s] a time event at t may lie from where a signal's own arithmetic puts its
    jump (rounding, ~1e-16·|t|): a signal evaluated at its time event gives its value after
    the jump, which the event iteration needs; below the 1e-12·|t| where integration
    towards the event stops (``numerics.just_before``), which still sees the value before."""
    return 1e-13 * ca.fmax(1, ca.fabs(t))


class BooleanConstant(partialBooleanSO):
    """y = k (option ``k``, True as in MSL)."""
    options = {"k": True}

    def physics(self, e):
        e.output(self.y, int(self.k))


class BooleanExpression(partialBooleanSO):
    """y = the Boolean value given as ``y`` (constructor argument, False as in MSL
    Sources.BooleanExpression), e.g. MSL TotalHarmonicDistortion's
    ``BooleanExpression(y=not useFirstHarmonic)``.

    MSL difference: MSL's y may be any Boolean expression of the model's variables
    (``y = pulse.y and step.y``); here it is a constant, and such an expression is built
    from the logical blocks (And, Or, Not; relations such as GreaterThreshold, which locate
    the instants where it changes as state events)."""

    def __init__(self, name: str | None = None, *, y: bool = False, **params):
        if not isinstance(y, (bool, np.bool_)):
            raise ParameterError(
                f"BooleanExpression: y must be True or False, got {y!r}; build an expression "
                f"of signals from logical blocks (y = pulse.y and step.y: an And with u1 from "
                f"pulse.y, u2 from step.y)")
        super().__init__(name, **params)
        self.__dict__["value"] = bool(y)

    def physics(self, e):
        e.output(self.y, int(self.value))


class BooleanStep(partialBooleanSO):
    """y = if time >= startTime then not startValue else startValue (option ``startValue``,
    False); a time event at startTime [s]."""
    options = {"startValue": False}
    startTime = Parameter(0.0, "s", "time instant of step start")

    def physics(self, e):
        before = int(self.startValue)
        e.output(self.y, ca.if_else(e.time >= self.startTime, 1 - before, before))
        e.time_event(self.startTime)


class BooleanPulse(partialBooleanSO):
    """Boolean pulse train: true during the first ``width`` percent of every ``period`` [s]
    from startTime [s], false before startTime and in the rest of each period (MSL
    Sources.BooleanPulse); time events at every edge."""
    width = Parameter(50.0, "%", "width of pulse in % of period", positive=True)
    period = Parameter(1.0, "s", "time for one period", positive=True)
    startTime = Parameter(0.0, "s", "time instant of first pulse")

    def physics(self, e):
        tau, tol = e.time - self.startTime, _event_tolerance(e.time)
        tp = tau - ca.floor((tau + tol) / self.period) * self.period
        e.output(self.y, ca.logic_and(tau >= -tol, tp < self.period * self.width / 100 - tol))
        e.time_event(self.startTime, self.period)
        e.time_event(self.startTime + self.period * self.width / 100, self.period)


class SampleTrigger(partialBooleanSO):
    """y = sample(startTime, period) (MSL Sources.SampleTrigger): true within the event
    iteration at the instants startTime + k·period [s], also at a start that is one of them
    (as MSL's sample() at initialization), false everywhere else (the Result shows it
    false). Time events at the instants."""
    period = Parameter(0.01, "s", "sample period", positive=True)
    startTime = Parameter(0.0, "s", "time instant of first sample trigger")

    def structure(self, s):
        refuse_smooth(self, s)
        s.sample("trigger", self.startTime, self.period, initial=True,
                 description="true at the sample instants and at the start")

    def physics(self, e):
        tau = e.time - self.startTime
        on_grid = ca.fabs(tau - ca.floor(tau / self.period + 0.5) * self.period) \
            <= 1e-9 * (1 + ca.fabs(e.time))
        e.output(self.y, ca.logic_and(e.mode("trigger"),
                                      ca.logic_and(tau > -1e-9 * (1 + ca.fabs(e.time)),
                                                   on_grid)))


class BooleanTable(partialBooleanSO):
    """A Boolean signal that changes to its opposite at every time of ``table`` [s] (a
    constructor argument, strictly increasing; MSL Sources.BooleanTable): ``startValue``
    (option, False) before table[1], then not startValue, and so on; held after the last
    time. ``shiftTime`` [s] shifts the table in time. Time events at the table's times.

    MSL differences: extrapolation is HoldLastPoint only; startTime (output false before
    it, −inf in MSL) is not available.
    """
    options = {"startValue": False,
               "extrapolation": Unavailable(Extrapolation.HoldLastPoint,
                                            "a Boolean table holds its last value")}
    shiftTime = Parameter(0.0, "s", "shift time of table")

    def __init__(self, name: str | None = None, *, table=(0.0, 1.0), **params):
        super().__init__(name, **params)
        try:
            times = np.array(table, dtype=float).ravel()
        except (TypeError, ValueError):
            raise ParameterError(f"{who(self)}: table must be a sequence of times [s], got "
                                 f"{table!r}") from None
        if not np.all(np.isfinite(times)) or np.any(np.diff(times) <= 0):
            raise ParameterError(f"{who(self)}: the times of table must be finite and "
                                 f"strictly increasing, got {times.tolist()}")
        self.__dict__["table"] = times

    def physics(self, e):
        tau = e.time - self.shiftTime
        tau = tau + _event_tolerance(e.time)
        flips = sum((ca.if_else(tau >= tk, 1, 0) for tk in self.table), ca.SX(0))
        e.output(self.y, ca.fmod(flips + int(self.startValue), 2))
        for tk in self.table:
            e.time_event(self.shiftTime + tk)


# ---- routing (Modelica.Blocks.Routing) ---------------------------------------------------------
class BooleanPassThrough(partialBooleanSISO):
    """y = u (MSL Routing.BooleanPassThrough): a Boolean signal passed on under another
    name."""

    def physics(self, e):
        e.output(self.y, e.input(self.u))


class BooleanReplicator(_Replicating):
    """y = fill(u, nout) (MSL Routing.BooleanReplicator): the Boolean input ``u`` copied to
    the ``nout`` outputs ``y[1]`` .. ``y[nout]`` (constructor argument, default 1)."""
    _classes: dict = {}
    _signal = ("Boolean", BooleanInput, BooleanOutput)


# ---- terminate (Modelica.Blocks.Logical) --------------------------------------------------------
class TerminateSimulation(Component):
    """Ends the simulation when ``condition`` becomes true (MSL
    Logical.TerminateSimulation: ``when condition then terminate(terminationText)``): the
    run stops at the event where it holds (the right limit there is the last point of the
    Result) and ``Result.terminated`` gives the time, this block and ``terminationText``
    (constructor argument). MSL binds ``condition`` to an expression in the model that
    holds the block; here it is a Boolean input, connected to what computes it (a relation
    block, whose switching is located as a state event, or a Boolean signal that changes
    at time events). Checked at events only, never at the start (a Modelica when-clause is
    inactive at initialization). Compiled in smooth form (``compile(model, smooth=True)``,
    for optimal control over a horizon of its own) it ends nothing."""
    condition = BooleanInput("terminate simulation when condition becomes true")

    def __init__(self, name: str | None = None, *,
                 terminationText: str = "... End condition reached", **params):
        super().__init__(name, **params)
        self.__dict__["terminationText"] = str(terminationText)

    def physics(self, e):
        if not e.smooth:
            e.terminate(e.input(self.condition), self.terminationText)


# ---- MathBoolean (Modelica.Blocks.MathBoolean) --------------------------------------------------
class PartialBooleanMISO(_MultiInput, partialBooleanSO):
    """Boolean inputs ``u[1]`` .. ``u[nu]`` (``nu``: constructor argument, ≥ 1; MSL's
    connectorSizing counts them), Boolean output ``y`` (MSL Interfaces.PartialBooleanMISO)."""
    partial = True
    _classes: dict = {}
    _input = BooleanInput


class MathBoolean:
    """The blocks of Modelica.Blocks.MathBoolean, as ``MathBoolean.And(nu=3)``: And, Or, Xor,
    Nand, Nor have a vector input ``u[1]`` .. ``u[nu]`` (``nu``, constructor argument ≥ 1)
    and are not Logical's And .. Nor (inputs u1, u2) of the same names, so they live in
    this namespace, as in MSL. Not, RisingEdge, FallingEdge and ChangingEdge are the
    equations of Logical.Not, Logical.Edge, Logical.FallingEdge and Logical.Change (the
    same classes' behavior); OnDelay is MathBoolean's own. MultiSwitch, ShowValue and the
    Integer-valued blocks are not available (no Integer connectors)."""

    class And(PartialBooleanMISO):
        """y = u[1] and u[2] and ... and u[nu] (MSL MathBoolean.And)."""
        _classes: dict = {}

        def physics(self, e):
            e.output(self.y, reduce(ca.logic_and, self.inputs(e)))

    class Or(PartialBooleanMISO):
        """y = u[1] or u[2] or ... or u[nu] (MSL MathBoolean.Or)."""
        _classes: dict = {}

        def physics(self, e):
            e.output(self.y, reduce(ca.logic_or, self.inputs(e)))

    class Xor(PartialBooleanMISO):
        """y = oneTrue(u): true if exactly one element of u is true (MSL MathBoolean.Xor)."""
        _classes: dict = {}

        def physics(self, e):
            e.output(self.y, sum(self.inputs(e), ca.SX(0)) == 1)

    class Nand(PartialBooleanMISO):
        """y = not (u[1] and u[2] and ... and u[nu]) (MSL MathBoolean.Nand)."""
        _classes: dict = {}

        def physics(self, e):
            e.output(self.y, ca.logic_not(reduce(ca.logic_and, self.inputs(e))))

    class Nor(PartialBooleanMISO):
        """y = not (u[1] or u[2] or ... or u[nu]) (MSL MathBoolean.Nor)."""
        _classes: dict = {}

        def physics(self, e):
            e.output(self.y, ca.logic_not(reduce(ca.logic_or, self.inputs(e))))

    Not = Not
    RisingEdge = RisingEdge
    FallingEdge = FallingEdge
    ChangingEdge = ChangingEdge

    class OnDelay(_WhenChanged, partialBooleanSO):
        """Delay a rising edge of the Boolean input ``u`` by ``delayTime`` [s], not a
        falling one (MSL MathBoolean.OnDelay): y becomes true delayTime after u became true,
        if u is still true then, and false at once when u becomes false. As MSL's algorithm
        (``when initial()`` first): a u true at the start gives y true at once. t_next, the
        instant y becomes true (time + delayTime at a rising edge), is a discrete variable;
        y's switching there is a state event."""
        required = ("delayTime",)
        delayTime = Parameter(1.0, "s", "delay time", positive=True)
        discretes = {"t_next": (0.0, "s", "time instant where y becomes true if u stays true")}

        def physics(self, e):
            t = e.time
            u, initial, changed = self.when_changed(e)
            t_next = e.mode("t_next")
            rising = ca.logic_and(ca.logic_and(u, changed), ca.logic_not(initial))
            now = self.assign(e, t_next, ca.if_else(rising, t + self.delayTime,
                                                    ca.if_else(changed, t - 1, t_next)))
            e.indicator("delayed", t - t_next, "s", "time since t_next")
            e.output(self.y, ca.logic_and(u, t >= now))
