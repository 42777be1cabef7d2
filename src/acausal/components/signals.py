"""Causal signal blocks, after Modelica.Blocks (MSL 4.0): sources, math, continuous blocks.

Names, parameters, defaults and equations are those of the MSL blocks, so a block diagram
written against MSL translates line by line: ``Step(height=2, startTime=1)``,
``connect(step.y, feedback.u1)``, ``PID(k=..., Ti=..., Td=..., Nd=...)``.

Signals are dimensionless in general (``Real``); time parameters are in seconds [s],
frequencies in [Hz], angles in [rad]. Numeric parameters are acausal Parameters (symbolic,
changeable at simulation time without recompiling); structural data (a table, the number of
inputs of ``Sum``) and initial values of block states are constructor arguments.

Initialization: the continuous blocks (Integrator, LimIntegrator, Derivative, FirstOrder,
SecondOrder, PI, PID, LimPID, TransferFunction, StateSpace, CriticalDamping,
LowpassButterworth; Filter's option is MSL's ``init``) take MSL's ``initType`` (``Init``: NoInit,
SteadyState, InitialState, InitialOutput) with MSL's default for each block; SteadyState and
InitialOutput are initial equations (der(states) = 0; y = y_start). With NoInit and
InitialState a block's states start at their start values (``y_start``, ``x_start``, ...),
where nothing else fixes them (what MSL tools do with NoInit). Other initial values are given
at simulation time by the dotted name of a state or of any output, e.g. ``x0={"PI.y": 0.5}``.

Sources are expressions of time built with CasADi functions (``if_else``, ``floor``,
``interpolant``), so they are exact, differentiable where the MSL signal is, and usable
inside optimal control problems. Discontinuous sources (Step, Pulse, SawTooth, table jumps)
declare time events: the integrator restarts there. After MSL 4.1 also ContinuousClock,
Exponentials, Sinc, LogFrequencySweep, Sine/CosineVariableFrequencyAndAmplitude (the phase a
state) and KinematicPTP; RealExpression is not needed in Python (a source is any expression
of time: write a Component whose physics outputs it). Limiter, VariableLimiter and DeadZone generate
state events at their kinks (MSL's default strict=false), so the simulator locates where the
input reaches a limit; compiled with ``smooth=True`` their corners are rounded over a named
width ``u_smooth`` (see Limiter); so does LimPID's output limiter (``y_smooth``). Blocks
with Boolean signals (relations, Switch, Hysteresis, logical blocks) are in
``acausal.components.logical``, sampled-data blocks (Sampler, ZeroOrderHold, the discrete
TransferFunction and StateSpace, ...) in ``acausal.components.discrete``.

Math blocks (Modelica.Blocks.Math, MSL 4.1): Abs and Sign (MSL's ``generateEvent``: state
events where u crosses 0, a smooth form as Limiter's), the functions of one input (Sqrt,
Sin, ..., Log10, Power, Exponentiation; where MSL requires u in a domain, Sqrt, Asin, Acos,
Log, Log10, the requirement is an assertion: simulate() stops with a SimulationError
naming the block), Atan2, Max, Min, MinMax, MultiSum, MultiProduct, MatrixGain, and the
sampled Mean and RootMeanSquare over periods 1/f. Nonlinear: SlewRateLimiter and
PadeDelay (a delay approximated by a rational transfer function). FixedDelay and
VariableDelay (y = u(time − delayTime)) are not available: a true delay makes a delay
differential equation, which the compiled form (an ODE/DAE in the present states) and
its integrators do not express; PadeDelay approximates one.

A loop of blocks must contain a state (Integrator, FirstOrder, PI, ...) or pass through a
mechanical part; a purely algebraic loop is reported by the compiler as an error.
"""
from __future__ import annotations

import math
from enum import Enum

import casadi as ca
import numpy as np

from ..core import (BooleanOutput, Component, ConditionalPort, Parameter, RealInput, RealOutput,
                    Unavailable, VectorPort)
from ..core.component import who
from ..errors import ParameterError
from .filter_design import BESSEL_MAX_ORDER, AnalogFilter, FilterType, base_filter, filter_roots

#: Modelica.Constants.eps: the smallest relative difference the MSL blocks distinguish.
EPS = 1e-15

__all__ = [
    "SO", "SISO", "SI2SO", "SignalSource",
    "Constant", "Step", "Ramp", "Sine", "Cosine", "ExpSine", "Pulse", "Trapezoid", "TimeTable",
    "CombiTimeTable", "Smoothness", "Extrapolation", "TimeEvents", "KinematicPTP2",
    "ContinuousClock", "Exponentials", "SawTooth", "Sinc", "SineVariableFrequencyAndAmplitude",
    "CosineVariableFrequencyAndAmplitude", "LogFrequencySweep", "KinematicPTP",
    "Gain", "Add", "Add3", "Feedback", "Product", "Division", "Sum",
    "Integrator", "Derivative", "FirstOrder", "SecondOrder", "PI", "PID", "LimPID",
    "SimpleController", "Init", "TransferFunction", "StateSpace",
    "LimIntegrator", "Der", "LowpassButterworth", "CriticalDamping", "Filter", "AnalogFilter",
    "FilterType",
    "Limiter", "VariableLimiter", "DeadZone", "LimiterHomotopy", "VariableLimiterHomotopy",
    "RealPassThrough",
    "Abs", "Sign", "Sqrt", "Sin", "Cos", "Tan", "Asin", "Acos", "Atan", "Sinh", "Cosh", "Tanh",
    "Exp", "Power", "Exponentiation", "Log", "Log10", "Atan2", "Max", "Min", "MinMax",
    "MultiSum", "MultiProduct", "MatrixGain", "Mean", "RootMeanSquare", "SlewRateLimiter",
    "PadeDelay", "pade_polynomials", "balance_abc",
]


# ---- interfaces (Modelica.Blocks.Interfaces) --------------------------------------------------
class SO(Component):
    """Single output ``y``."""
    y = RealOutput("connector of Real output signal")


class SISO(SO):
    """Single input ``u``, single output ``y``."""
    u = RealInput("connector of Real input signal")


class SI2SO(SO):
    """Two inputs ``u1``, ``u2``, single output ``y``."""
    u1 = RealInput("connector of Real input signal 1")
    u2 = RealInput("connector of Real input signal 2")


class SignalSource(SO):
    """A source y = offset + (``before()`` before startTime, else ``signal(time)``).

    Subclasses implement ``signal(t)``: the value without offset at time t ≥ startTime [s],
    and ``before()`` if it is not 0.
    """
    offset = Parameter(0.0, "", "offset of output signal y")
    startTime = Parameter(0.0, "s", "output y = offset for time < startTime")

    def signal(self, t):
        raise NotImplementedError

    def before(self):
        """The value without offset for time < startTime (0)."""
        return 0

    def events(self) -> list:
        """Times [s] where the signal jumps or kinks, as (time, period or None) pairs; the
        integrator restarts there instead of stepping across."""
        return [(self.startTime, None)]

    def physics(self, e):
        t = e.time
        e.output(self.y, self.offset + ca.if_else(t < self.startTime, self.before(),
                                                  self.signal(t)))
        for time, period in self.events():
            e.time_event(time, period)


def _start(value, what: str) -> float:
    """A start value given to a constructor, as float (a ParameterError otherwise)."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ParameterError(f"{what} must be a number, got {value!r}") from None
    if not math.isfinite(v):
        raise ParameterError(f"{what} must be finite, got {v}")
    return v


# ---- sources (Modelica.Blocks.Sources) ----------------------------------------------------------
class Constant(SO):
    """Constant output: y = k."""
    k = Parameter(1.0, "", "constant output value")

    def physics(self, e):
        e.output(self.y, self.k)


class Step(SignalSource):
    """Step: y = offset + (0 if time < startTime else height)."""
    height = Parameter(1.0, "", "height of step")

    def signal(self, t):
        return self.height


class Ramp(SignalSource):
    """Ramp from offset to offset + height between startTime and startTime + duration [s]
    (duration = 0 gives a step)."""
    height = Parameter(1.0, "", "height of ramps")
    duration = Parameter(2.0, "s", "duration of ramp (= 0.0 gives a Step)", nonnegative=True)

    def signal(self, t):
        tau = t - self.startTime
        return ca.if_else(tau < self.duration, tau * self.height / self.duration, self.height)

    def events(self):
        return [(self.startTime, None), (self.startTime + self.duration, None)]


class Sine(SignalSource):
    """Sine: y = offset + amplitude·sin(2π·f·(time − startTime) + phase) after startTime;
    before it y = offset, or with ``continuous=True`` offset + amplitude·sin(phase) (no
    jump at startTime)."""
    options = {"continuous": False}
    amplitude = Parameter(1.0, "", "amplitude of sine wave")
    f = Parameter(1.0, "Hz", "frequency of sine wave")
    phase = Parameter(0.0, "rad", "phase of sine wave")

    def signal(self, t):
        return self.amplitude * ca.sin(2 * ca.pi * self.f * (t - self.startTime) + self.phase)

    def before(self):
        return self.amplitude * ca.sin(self.phase) if self.continuous else 0


class Cosine(SignalSource):
    """Cosine: y = offset + amplitude·cos(2π·f·(time − startTime) + phase) after startTime;
    before it y = offset, or with ``continuous=True`` offset + amplitude·cos(phase)."""
    options = {"continuous": False}
    amplitude = Parameter(1.0, "", "amplitude of cosine wave")
    f = Parameter(1.0, "Hz", "frequency of cosine wave")
    phase = Parameter(0.0, "rad", "phase of cosine wave")

    def signal(self, t):
        return self.amplitude * ca.cos(2 * ca.pi * self.f * (t - self.startTime) + self.phase)

    def before(self):
        return self.amplitude * ca.cos(self.phase) if self.continuous else 0


class ExpSine(SignalSource):
    """Exponentially damped sine: y = offset + amplitude·exp(−damping·τ)·sin(2π·f·τ + phase),
    τ = time − startTime ≥ 0."""
    amplitude = Parameter(1.0, "", "amplitude of sine wave")
    f = Parameter(2.0, "Hz", "frequency of sine wave")
    phase = Parameter(0.0, "rad", "phase of sine wave")
    damping = Parameter(1.0, "1/s", "damping coefficient of sine wave")

    def signal(self, t):
        tau = t - self.startTime
        return (self.amplitude * ca.exp(-tau * self.damping)
                * ca.sin(2 * ca.pi * self.f * tau + self.phase))


class _Periodic(SignalSource):
    """A periodic source: period [s], nperiod periods (< 0: infinitely many) from startTime.

    Every corner of the wave is a time event: the integrator restarts there, so it never
    steps over a pulse.
    """
    period = Parameter(1.0, "s", "time for one period", positive=True)
    nperiod = Parameter(-1, "", "number of periods (< 0 means infinite number of periods)")

    def wave(self, tp):
        """The value within one period at tp ∈ [0, period) [s]."""
        raise NotImplementedError

    def corners(self) -> list:
        """Times within a period [s] where the wave jumps or kinks."""
        return []

    def events(self):
        return [(self.startTime + c, self.period) for c in [ca.SX(0)] + self.corners()]

    def signal(self, t):
        tau = t - self.startTime
        count = ca.floor(tau / self.period)
        tp = tau - count * self.period
        done = ca.logic_and(self.nperiod >= 0, count >= self.nperiod)
        return ca.if_else(done, 0, self.wave(tp))


class Pulse(_Periodic):
    """Pulse train: amplitude during the first ``width`` percent of every period, else 0."""
    amplitude = Parameter(1.0, "", "amplitude of pulse")
    width = Parameter(50.0, "%", "width of pulse in % of period", positive=True)

    def wave(self, tp):
        return ca.if_else(tp < self.period * self.width / 100, self.amplitude, 0)

    def corners(self):
        return [self.period * self.width / 100]


class Trapezoid(_Periodic):
    """Trapezoid: rises to amplitude in ``rising``, holds ``width``, falls in ``falling`` [s],
    then 0 until the end of the period."""
    amplitude = Parameter(1.0, "", "amplitude of trapezoid")
    rising = Parameter(0.0, "s", "rising duration of trapezoid", nonnegative=True)
    width = Parameter(0.5, "s", "width duration of trapezoid", nonnegative=True)
    falling = Parameter(0.0, "s", "falling duration of trapezoid", nonnegative=True)

    def wave(self, tp):
        a = self.amplitude
        t_w = self.rising + self.width
        t_f = t_w + self.falling
        return ca.if_else(tp < self.rising, a * tp / self.rising,
                          ca.if_else(tp < t_w, a,
                                     ca.if_else(tp < t_f, a * (t_f - tp) / self.falling, 0)))

    def corners(self):
        t_w = self.rising + self.width
        return [self.rising, t_w, t_w + self.falling]


class Smoothness(str, Enum):
    """Modelica.Blocks.Types.Smoothness: how a table is interpolated."""
    LinearSegments = "LinearSegments"
    ContinuousDerivative = "ContinuousDerivative"
    ConstantSegments = "ConstantSegments"
    MonotoneContinuousDerivative1 = "MonotoneContinuousDerivative1"
    MonotoneContinuousDerivative2 = "MonotoneContinuousDerivative2"
    ModifiedContinuousDerivative = "ModifiedContinuousDerivative"


class Extrapolation(str, Enum):
    """Modelica.Blocks.Types.Extrapolation: a table's value outside its time range."""
    HoldLastPoint = "HoldLastPoint"
    LastTwoPoints = "LastTwoPoints"
    Periodic = "Periodic"
    NoExtrapolation = "NoExtrapolation"


class TimeEvents(str, Enum):
    """Modelica.Blocks.Types.TimeEvents: where a table restarts the integrator."""
    Always = "Always"
    AtDiscontinuities = "AtDiscontinuities"
    NoTimeEvents = "NoTimeEvents"


def _table_values(tau, times: np.ndarray, values, smoothness: Smoothness,
                  extrapolation: Extrapolation) -> list:
    """The value columns of a table at table time ``tau``, one expression per column:
    ``times`` (structural: where the pieces and events are), ``values`` the rows without
    their time, flattened row by row: numbers (folded into the interpolants), or the
    symbols of the ``table`` parameter (an argument of the interpolants, changeable without
    recompiling; every evaluation then passes them). Linear segments are CasADi linear
    interpolants (a binary search, not one branch per row), one per piece between repeated
    times (a jump: the later row holds from that time on); constant segments give the row
    at or before tau."""
    n, symbolic = times.size, isinstance(values, ca.SX)
    m = (values.numel() if symbolic else len(values)) // n
    rows = None if symbolic else np.reshape(values, (n, m))
    vals = ca.reshape(values, m, n).T if symbolic else ca.SX(rows)
    if n == 1:
        return [vals[0, j] for j in range(m)]
    t_min, t_max = times[0], times[-1]
    if extrapolation is Extrapolation.HoldLastPoint:
        tau = ca.fmin(ca.fmax(tau, t_min), t_max)
    elif extrapolation is Extrapolation.Periodic:
        period = t_max - t_min
        tau = tau - period * ca.floor((tau - t_min) / period)
    if smoothness is Smoothness.ConstantSegments:
        out = [ca.pw_const(tau, ca.SX(ca.DM(times[1:])), vals[:, j]) for j in range(m)]
    else:
        cuts = [0] + [i for i in range(1, n) if times[i] == times[i - 1]] + [n]
        pieces = [(a, b) for a, b in zip(cuts[:-1], cuts[1:]) if b - a > 1 or b == n]

        def piece(a, b):
            if b - a == 1:                      # a last row of its own: held
                return vals[a, :].T
            if not symbolic:
                return ca.interpolant("table", "linear", [times[a:b]],
                                      np.ravel(rows[a:b]))(tau)
            f = ca.interpolant("table", "linear", [times[a:b]], m)
            return f(tau, ca.vec(vals[a:b, :].T))

        a, b = pieces[-1]
        expr = piece(a, b)
        for a, b in reversed(pieces[:-1]):
            expr = ca.if_else(tau < times[b], piece(a, b), expr)
        out = [expr[j] for j in range(m)]
    if extrapolation is Extrapolation.NoExtrapolation:
        outside = ca.logic_or(tau < t_min, tau > t_max)
        out = [ca.if_else(outside, np.nan, y) for y in out]
    return out


def _table_events(times: np.ndarray, smoothness: Smoothness, extrapolation: Extrapolation,
                  timeEvents: TimeEvents) -> list:
    """Table times where the interpolated signal restarts the integrator, as (time, period
    or None) pairs in table time: every row with ``Always`` or constant segments, repeated
    times with ``AtDiscontinuities`` (and the wrap of a periodic table)."""
    if times.size == 1 or timeEvents is TimeEvents.NoTimeEvents:
        return []
    periodic = extrapolation is Extrapolation.Periodic
    period = times[-1] - times[0] if periodic else None
    if smoothness is Smoothness.ConstantSegments:
        rows = times[1:]
    elif timeEvents is TimeEvents.Always:
        rows = times[1:-1]
    else:
        rows = times[1:][times[1:] == times[:-1]]
    rows = set(map(float, rows)) | ({float(times[-1])} if periodic else set())
    return [(tk, period) for tk in sorted(rows)]


def _table_parameter(rows: int, columns: int) -> Parameter:
    """The ``table`` parameter of a table of ``rows`` rows and ``columns`` value columns:
    its values without the time column, row by row (``table[1]`` .. ``table[rows·columns]``);
    ``params={"<table>.table": values}`` (shape (rows, columns)) changes them at simulation
    time. The times are structural (the interpolation's pieces and time events)."""
    return Parameter((0.0,) * (rows * columns), "",
                     f"table values ({rows} rows x {columns} columns, without the time "
                     f"column), row by row")


def _check_table(table, kind: str, first_at_zero: bool) -> np.ndarray:
    if table is None:
        raise ParameterError(f"{kind}: no table given; pass table=[[t0, y0], [t1, y1], ...]")
    try:
        tab = np.array(table, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError(f"{kind}: table must be numbers in rows [time, value, ...], got "
                             f"{table!r}") from None
    if tab.ndim == 1 and tab.size >= 2:
        tab = tab.reshape(1, -1)
    if tab.ndim != 2 or tab.shape[1] < 2 or tab.shape[0] < 1:
        raise ParameterError(f"{kind}: table must have rows [time, value, ...] (shape (n, 2) "
                             f"or wider), got shape {tab.shape}")
    if not np.all(np.isfinite(tab)):
        raise ParameterError(f"{kind}: table contains non-finite values")
    if tab.shape[0] > 1:
        if first_at_zero and tab[0, 0] != 0.0:
            raise ParameterError(f"{kind}: the first point in time has to be 0, but is "
                                 f"table[1,1] = {tab[0, 0]}; shift the table with shiftTime")
        if np.any(np.diff(tab[:, 0]) < 0):
            raise ParameterError(f"{kind}: the times (first column) must be non-decreasing")
        if np.any((tab[2:, 0] == tab[1:-1, 0]) & (tab[1:-1, 0] == tab[:-2, 0])):
            raise ParameterError(f"{kind}: a time appears more than twice in the table; a "
                                 f"jump is two rows with the same time")
        if tab[0, 0] == tab[-1, 0]:
            raise ParameterError(f"{kind}: the table spans no time (first time = last time)")
    return tab


class _Table:
    """What TimeTable and CombiTimeTable share: the table, checked once when the block is
    made; the block's class, made per layout (the number of outputs, a ``shiftTime``
    parameter when one is given, a ``table`` parameter with ``table_parameter=True``); the
    value columns at a time and the time events.

    A table block declares ``startTime`` and ``timeScale`` [s], ``_selected(tab, columns)``
    (the checked table reduced to its time and output columns), ``_outputs(nout)`` (what
    its class declares for nout outputs) and ``_modes()`` (its smoothness, extrapolation and
    timeEvents); the class itself keeps ``_classes``, its classes by layout."""
    _first_at_zero = False              # whether the first time of a table must be 0

    def __new__(cls, name=None, *, table=None, columns=None, shiftTime=None,
                table_parameter=False, **params):
        kind = cls.__name__
        if name is not None and not isinstance(name, str):
            raise ParameterError(f"{kind}: give the table by keyword, {kind}(table=...)")
        tab = cls._selected(_check_table(table, kind, cls._first_at_zero), columns)
        if cls is cls._public():
            cls = cls._variant(tab.shape[1] - 1, shiftTime is not None,
                               tab.shape[0] if table_parameter else 0)
        block = super().__new__(cls)
        block.__dict__["_checked"] = tab        # for __init__: the table is checked once
        return block

    @classmethod
    def _public(cls) -> type:
        """TimeTable or CombiTimeTable: the class a block's class is made from."""
        return next(c for c in cls.__mro__ if "_classes" in vars(c))

    @classmethod
    def _variant(cls, nout: int, shifted: bool, rows: int) -> type:
        """The class for nout outputs, a shiftTime parameter or not, and a ``table``
        parameter of ``rows`` rows (0: none); ``cls`` itself when it declares all of it."""
        key = (nout, shifted, rows)
        if key not in cls._classes:
            attrs = cls._outputs(nout)
            if rows:
                attrs["table"] = _table_parameter(rows, nout)
            if shifted:
                attrs["shiftTime"] = Parameter(0.0, "s", "shift time of first table column")
            cls._classes[key] = type(cls.__name__, (cls,), {
                "__doc__": cls.__doc__, "__module__": __name__, "__qualname__": cls.__name__,
                **attrs}) if attrs else cls
        return cls._classes[key]

    def __reduce_ex__(self, protocol):          # the class is made per layout: rebuild it so
        declared = self.parameters()
        return _new_table, (self._public(), len(self.table) // len(self.times),
                            "shiftTime" in declared,
                            len(self.times) if "table" in declared else 0), self.__dict__

    def __init__(self, name: str | None = None, *, table=None, shiftTime=None,
                 table_parameter: bool = False, **params):
        tab = self.__dict__.pop("_checked")
        if shiftTime is not None:
            params["shiftTime"] = shiftTime
        values = tuple(tab[:, 1:].ravel())
        if table_parameter:
            params["table"] = values
        super().__init__(name, **params)
        self.__dict__["times"] = tab[:, 0]
        if not table_parameter:
            self.__dict__["table"] = values

    def _shift(self):
        """shiftTime [s]: the block's own parameter when given, else startTime (MSL's
        binding)."""
        return self.shiftTime if "shiftTime" in self.parameters() else self.startTime

    def _table_at(self, t) -> list:
        """The table's output columns at time t [s], one expression each (without offset
        and startTime)."""
        smoothness, extrapolation, _ = self._modes()
        return _table_values((t - self._shift()) / self.timeScale, self.times, self.table,
                             smoothness, extrapolation)

    def events(self) -> list:
        """startTime and the table's events, as (time [s], period [s] or None) pairs."""
        shift, scale = self._shift(), self.timeScale
        return [(self.startTime, None)] + [
            (shift + scale * tk, None if period is None else scale * period)
            for tk, period in _table_events(self.times, *self._modes())]


class TimeTable(_Table, SignalSource):
    """Linear interpolation in a table of [time, value] rows (MSL Sources.TimeTable).

    ``table`` (constructor argument, an (n, 2) array-like): times in the first column,
    non-decreasing, the first one 0 when n > 1; a time given twice is a jump (the later row
    holds from that time on). For time ≥ startTime [s] the output is
    ``offset + interp((time − shiftTime)/timeScale)``, extrapolated through the first or
    last two rows outside the table; before startTime it is ``offset``; a one-row table gives
    its value. ``shiftTime`` [s] defaults to startTime (the MSL binding: the table then
    follows startTime, also when startTime is changed at simulation time); giving it at
    construction makes it a parameter of its own; timeScale [s] is the time unit of the
    first column.

    The table is a CasADi linear interpolant: the integrator restarts only at jumps
    (repeated times), not at every row. It is fixed when the model is compiled (offset,
    startTime, shiftTime and timeScale are parameters), unless ``table_parameter=True``:
    its values are then the parameter ``table`` (``table[1]`` .. ``table[n]``), changed
    without recompiling by ``params={"<name>.table": values}`` (its times, ``times``, and
    so its events stay; every evaluation of the equations then passes the n values).
    """
    timeScale = Parameter(1.0, "s", "time scale of first table column", positive=True)
    _first_at_zero = True
    _classes: dict = {}

    @staticmethod
    def _selected(tab: np.ndarray, columns) -> np.ndarray:
        if tab.shape[1] != 2:
            raise ParameterError(f"TimeTable: table must have rows [time, value] (shape "
                                 f"(n, 2)), got shape {tab.shape}; CombiTimeTable takes "
                                 f"several columns")
        return tab

    @staticmethod
    def _outputs(nout: int) -> dict:
        return {}                               # the one output y is declared by SO

    @staticmethod
    def _modes() -> tuple:
        return Smoothness.LinearSegments, Extrapolation.LastTwoPoints, TimeEvents.AtDiscontinuities

    def signal(self, t):
        return self._table_at(t)[0]


class CombiTimeTable(_Table, Component):
    """Table look-up in time with several output columns (MSL Sources.CombiTimeTable).

    Constructor arguments (fixed when the model is compiled): ``table`` (rows [time, values
    ...], times non-decreasing; a time given twice is a jump; with ``table_parameter=True``
    its values, the selected columns without the time, are the parameter ``table``, row by
    row: ``params={"<name>.table": values}`` of shape (rows, nout) changes them without
    recompiling, the times stay), ``columns`` (the table
    columns to output, numbered from 1 as in Modelica, time being column 1; default
    2..ncols), the options ``smoothness`` (LinearSegments, ConstantSegments: the row at or
    before the time), ``extrapolation`` (HoldLastPoint, LastTwoPoints, Periodic,
    NoExtrapolation) and ``timeEvents``.

    Parameters: ``offset[i]`` (one per output; ``offset=c`` or ``offset=[...]`` at
    construction), startTime [s] (y = offset before it), ``shiftTime`` [s] (defaults to
    startTime, as MSL's binding; given, it is a parameter of its own) and timeScale [s] (the
    time unit of the first column). For time ≥ startTime:
    ``y[i] = offset[i] + table value of columns[i] at (time − shiftTime)/timeScale``.
    Outputs ``y[1]`` .. ``y[nout]``.

    MSL differences: the default ``timeEvents`` is AtDiscontinuities (MSL: Always, an event
    at every row): linear segments restart the integrator only at repeated times (and at the
    wrap of a periodic table), constant segments at every row. NoExtrapolation gives NaN
    outside the table's times (MSL stops the simulation with an error). With constant
    segments LastTwoPoints holds the first/last value. The spline smoothness options, tables
    on files and verbose extrapolation are not available.
    """
    options = {"smoothness": Smoothness.LinearSegments,
               "extrapolation": Extrapolation.LastTwoPoints,
               "timeEvents": TimeEvents.AtDiscontinuities,
               "tableOnFile": Unavailable(False, "tables read from files"),
               "verboseExtrapolation": Unavailable(False, "warnings outside the table")}
    startTime = Parameter(0.0, "s", "output = offset for time < startTime")
    timeScale = Parameter(1.0, "s", "time scale of first table column", positive=True)
    _classes: dict = {}

    @staticmethod
    def _selected(tab: np.ndarray, columns) -> np.ndarray:
        """The time column and the selected ``columns`` (numbered from 1, time being column
        1), checked."""
        ncol = tab.shape[1]
        cols = list(range(2, ncol + 1)) if columns is None else list(np.atleast_1d(columns))
        if not cols or any(isinstance(c, (bool, np.bool_))
                           or not isinstance(c, (int, np.integer)) or not 2 <= c <= ncol
                           for c in cols):
            raise ParameterError(f"CombiTimeTable: columns must be integers in 2..{ncol} (the "
                                 f"table's value columns; column 1 is time), got {columns!r}")
        return tab[:, [0] + [int(c) - 1 for c in cols]]

    @staticmethod
    def _outputs(nout: int) -> dict:
        return {"_nout": nout,
                "offset": Parameter((0.0,) * nout, "", "offsets of output signals"),
                "y": VectorPort(RealOutput, nout, "connector of Real output signals")}

    def _modes(self) -> tuple:
        return self.smoothness, self.extrapolation, self.timeEvents

    def __init__(self, name: str | None = None, *, table=None, columns=None, shiftTime=None,
                 offset=0.0, table_parameter: bool = False, **params):
        offsets = np.atleast_1d(np.asarray(offset, dtype=object)).ravel()
        if offsets.size not in (1, self._nout):
            raise ParameterError(f"CombiTimeTable: offset has {offsets.size} elements but "
                                 f"there are {self._nout} outputs (give 1 or {self._nout})")
        params["offset"] = tuple(offsets) * (self._nout // offsets.size)
        super().__init__(name, table=table, shiftTime=shiftTime,
                         table_parameter=table_parameter, **params)
        if self.smoothness not in (Smoothness.LinearSegments, Smoothness.ConstantSegments):
            raise ParameterError(f"{who(self)}: smoothness={self.smoothness.value} (a spline) "
                                 f"is not available; use LinearSegments or ConstantSegments")

    @property
    def nout(self) -> int:
        return self._nout

    def physics(self, e):
        t = e.time
        for i, (port, y) in enumerate(zip(self.y, self._table_at(t))):
            e.output(port, self.offset[i] + ca.if_else(t < self.startTime, 0, y))
        for time, period in self.events():
            e.time_event(time, period)


def _new_table(cls, *key) -> Component:
    """An empty instance of the table class ``cls`` made for ``key`` (unpickling)."""
    return object.__new__(cls._variant(*key))


class _Sized:
    """A block whose sizes (numbers of coefficients, states, inputs, outputs) come from the
    values given at construction: its class is made once per layout (``_declare(*key)``
    gives what that class declares: vector parameters and ports), and rebuilt by layout
    when unpickled."""
    _classes: dict
    _key: tuple = ()

    def __init_subclass__(cls, **kwargs):
        cls._written = vars(cls).get("_written", cls.__doc__)   # before the generated reference
        super().__init_subclass__(**kwargs)

    @classmethod
    def _variant(cls, *key) -> type:
        base = cls if "_classes" in vars(cls) else cls.__bases__[0]
        if key not in base._classes:
            base._classes[key] = type(base.__name__, (base,), {
                "__doc__": base._written, "_written": base._written,
                "__module__": base.__module__,
                "__qualname__": base.__name__, "_key": key, **base._declare(*key)})
        return base._classes[key]

    def __reduce_ex__(self, protocol):
        return _new_sized, (type(self).__bases__[0], self._key), self.__dict__


def _new_sized(base: type, key: tuple) -> Component:
    """An empty instance of the sized block class ``base`` made for ``key`` (unpickling)."""
    return object.__new__(base._variant(*key))


class _PointToPoint(_Sized, Component):
    """What KinematicPTP and KinematicPTP2 share: vector parameters given as numbers or
    sequences (``_vectors``: name -> (unit, description, rule, MSL default); a one-element
    one holds for every axis: MSL's rule), nout = the longest of them, the class made per
    nout (``_outputs(nout)``: its ports), ``startTime`` and the normalized path s(t) ∈ [0, 1]
    of the fastest motion over the distances ``_distances()`` within qd_max and qdd_max."""
    _vectors: dict
    startTime = Parameter(0.0, "s", "time instant at which movement starts")

    def __new__(cls, name=None, **kwargs):
        return super().__new__(cls._variant(cls._nout(kwargs)))

    @classmethod
    def _values(cls, kwargs) -> dict:
        out = {}
        for key, (*_, default) in cls._vectors.items():
            try:
                v = np.atleast_1d(np.asarray(kwargs.get(key, default), dtype=float)).ravel()
            except (TypeError, ValueError):
                v = None
            if v is None or v.size < 1:
                raise ParameterError(f"{cls.__name__}: {key} must be a number or a sequence "
                                     f"of numbers, got {kwargs.get(key)!r}")
            out[key] = v
        return out

    @classmethod
    def _nout(cls, kwargs) -> int:
        values = cls._values(kwargs)
        nout = max(v.size for v in values.values())
        wrong = [k for k, v in values.items() if v.size not in (1, nout)]
        if wrong:
            raise ParameterError(f"{cls.__name__}: {wrong[0]} has {values[wrong[0]].size} "
                                 f"elements; give 1 or nout = {nout} (the longest of "
                                 f"{', '.join(cls._vectors)})")
        return nout

    @classmethod
    def _declare(cls, nout: int) -> dict:
        attrs = {"nout": nout}
        for key, (unit, text, rule, default) in cls._vectors.items():
            for i in range(1, nout + 1):
                attrs[f"{key}[{i}]"] = Parameter(default, unit, f"{text} [{i}]", **rule)
        return {**attrs, **cls._outputs(nout)}

    def __init__(self, name: str | None = None, **kwargs):
        values = self._values(kwargs)
        params = {k: v for k, v in kwargs.items() if k not in self._vectors}
        for key, v in values.items():
            for i in range(1, self.nout + 1):
                params[f"{key}[{i}]"] = v[0] if v.size == 1 else v[i - 1]
        super().__init__(name, **params)

    def _vector(self, key: str) -> list:
        return [getattr(self, f"{key}[{i}]") for i in range(1, self.nout + 1)]

    def _distances(self) -> list:
        """The distance each axis moves (expressions of the parameters)."""
        raise NotImplementedError

    def profile(self) -> dict:
        """The normalized path's data, expressions of the parameters (MSL's names): sd_max,
        sdd_max, noWphase, the phase ends Ta1s, Ta2s, Tvs, Tes [s], s1, s2, s3, sd_max2 and
        ``moves`` (false when no axis moves: then s = 0 and endTime = 0)."""
        eps = 10 * 2.220446049250313e-16                     # MSL: 10*Modelica.Constants.eps
        dq = self._distances()
        sd_inv = _vmax([ca.fabs(d / v) for d, v in zip(dq, self._vector("qd_max"))])
        sdd_inv = _vmax([ca.fabs(d / a) for d, a in zip(dq, self._vector("qdd_max"))])
        moves = ca.logic_and(sd_inv > eps, sdd_inv > eps)
        sd_max, sdd_max = 1 / ca.fmax(sd_inv, eps), 1 / ca.fmax(sdd_inv, eps)
        Ta1, Ta2 = ca.sqrt(1 / sdd_max), sd_max / sdd_max
        noW = Ta2 >= Ta1
        Tv = ca.if_else(noW, Ta1, 1 / sd_max)
        Te = ca.if_else(noW, Ta1 + Ta1, Tv + Ta2)
        sd_max2 = sdd_max * Ta1
        s1 = sdd_max * ca.if_else(noW, Ta1 * Ta1, Ta2 * Ta2) / 2
        s2 = s1 + ca.if_else(noW, sd_max2 * (Te - Ta1) - sdd_max / 2 * (Te - Ta1) ** 2,
                             sd_max * (Tv - Ta2))
        s3 = s2 + sd_max * (Te - Tv) - sdd_max / 2 * (Te - Tv) ** 2
        t0 = self.startTime
        return dict(dq=dq, moves=moves, sd_max=sd_max, sdd_max=sdd_max, noWphase=noW,
                    Ta1s=Ta1 + t0, Ta2s=Ta2 + t0, Tvs=Tv + t0, Tes=Te + t0, sd_max2=sd_max2,
                    s1=s1, s2=s2, s3=s3)

    def end_time(self):
        """endTime [s]: the instant the motion stops (an expression of the parameters)."""
        p = self.profile()
        return ca.if_else(p["moves"], p["Tes"], 0.0)

    def normalized_path(self, e, p: dict) -> list:
        """[s, der(s), der(der(s))] at the time of ``e`` on the profile ``p``; declares the
        time events at the phase changes (the acceleration jumps there)."""
        t, t0 = e.time, self.startTime
        a, v, noW = p["sdd_max"], p["sd_max"], p["noWphase"]
        tau = t - t0
        up = (a / 2 * tau ** 2, a * tau, a)                                # accelerating
        # bang-bang: braking from Ta1s; with a cruise phase: cruising to Tvs, then braking
        tb = t - ca.if_else(noW, p["Ta1s"], p["Tvs"])
        sb, vb = ca.if_else(noW, p["s1"], p["s2"]), ca.if_else(noW, p["sd_max2"], v)
        down = (sb + vb * tb - a / 2 * tb ** 2, vb - a * tb, -a)
        cruise = (p["s1"] + v * (t - p["Ta2s"]), v, 0.0)
        rest = (ca.if_else(noW, p["s2"], p["s3"]), 0.0, 0.0)
        phases = [(t < t0, (0.0, 0.0, 0.0)), (t < ca.if_else(noW, p["Ta1s"], p["Ta2s"]), up),
                  (ca.logic_and(ca.logic_not(noW), t < p["Tvs"]), cruise),
                  (t < p["Tes"], down)]
        s = list(rest)
        for cond, values in reversed(phases):
            s = [ca.if_else(cond, x, y) for x, y in zip(values, s)]
        for time in (t0, ca.if_else(noW, p["Ta1s"], p["Ta2s"]),
                     ca.if_else(noW, p["Tes"], p["Tvs"]), p["Tes"]):
            e.time_event(ca.if_else(p["moves"], time, t0))
        return [ca.if_else(p["moves"], x, 0.0) for x in s]


class KinematicPTP2(_PointToPoint):
    """Point-to-point motion as fast as the limits allow (MSL Sources.KinematicPTP2): from
    q_begin to q_end, each axis's speed within qd_max and acceleration within qdd_max
    (> 0), all axes on one normalized path s(t) ∈ [0, 1] (only the axis at its limit is at
    it): accelerate at the largest rate, cruise at the largest speed, brake to rest
    (bang–bang, without cruise phase, when the largest speed is not reached). Outputs
    q = q_begin + Δq·s, qd = Δq·der(s), qdd = Δq·der(der(s)) and moving = time < endTime
    (false for an axis that does not move), vectors of nout = the longest of q_begin,
    q_end, qd_max, qdd_max (a one-element one holds for every axis: MSL's rule); records
    endTime [s] = startTime + duration (0 if nothing moves). Time events at the phase
    changes (the acceleration jumps there).

    Constructor arguments ``q_begin``, ``q_end``, ``qd_max``, ``qdd_max`` (numbers or
    sequences; MSL's defaults 0, 1, 1, 1) give the parameters ``q_begin[i]`` ... (per
    element, changeable at simulation time); ``startTime`` [s]. Ports ``q[i]``, ``qd[i]``,
    ``qdd[i]``, ``moving[i]``, numbered from 1.
    """
    _classes: dict = {}
    _vectors = {"q_begin": ("", "start position", {}, 0.0),
                "q_end": ("", "end position", {}, 1.0),
                "qd_max": ("", "maximum velocity der(q)", {"positive": True}, 1.0),
                "qdd_max": ("", "maximum acceleration der(qd)", {"positive": True}, 1.0)}

    @staticmethod
    def _outputs(nout: int) -> dict:
        return {key: VectorPort(cls, nout, text) for key, cls, text in (
            ("q", RealOutput, "reference position of path planning"),
            ("qd", RealOutput, "reference speed of path planning"),
            ("qdd", RealOutput, "reference acceleration of path planning"),
            ("moving", BooleanOutput, "= true, if end position not yet reached"))}

    def _distances(self) -> list:
        return [b - a for a, b in zip(self._vector("q_begin"), self._vector("q_end"))]

    def physics(self, e):
        p, t = self.profile(), e.time
        s = self.normalized_path(e, p)
        end = self.end_time()
        for k, (qb, dq) in enumerate(zip(self._vector("q_begin"), p["dq"]), start=1):
            e.output(self.q[k], qb + dq * s[0])
            e.output(self.qd[k], dq * s[1])
            e.output(self.qdd[k], dq * s[2])
            e.output(self.moving[k], ca.logic_and(ca.fabs(dq) > 10 * 2.220446049250313e-16,
                                                  t < end))
        e.variable("endTime", end, "s", "time instant at which movement stops")


def _vmax(values: list):
    out = values[0]
    for v in values[1:]:
        out = ca.fmax(out, v)
    return out


# ---- more sources (Modelica.Blocks.Sources, MSL 4.1) ---------------------------------------------
class ContinuousClock(SignalSource):
    """The current time: y = offset + (0 before startTime, else time − startTime)."""

    def signal(self, t):
        return t - self.startTime


class Exponentials(SignalSource):
    """A rising exponential, then a falling one: for τ = time − startTime ≥ 0,
    y = offset + outMax·(1 − exp(−τ/riseTimeConst)) while τ < riseTime, then
    y_riseTime·exp(−(τ − riseTime)/fallTimeConst), y_riseTime = outMax·(1 −
    exp(−riseTime/riseTimeConst)). Time events at startTime and at the end of the rise (a
    kink). fallTimeConst [s] defaults to riseTimeConst (MSL's binding: it follows
    riseTimeConst, also at simulation time, unless it is given at construction, which
    makes it a parameter of its own)."""
    outMax = Parameter(1.0, "", "height of output for infinite riseTime")
    riseTime = Parameter(0.5, "s", "rise time", nonnegative=True)
    riseTimeConst = Parameter(0.1, "s", "rise time constant; rising is defined as "
                                        "outMax*(1-exp(-riseTime/riseTimeConst))",
                              positive=True)
    _with_fallTimeConst: type | None = None

    def __new__(cls, name=None, **params):
        own = cls._with_fallTimeConst if "fallTimeConst" in params else None
        return super().__new__(own or cls)

    @property
    def fallTimeConst(self):
        """The fall time constant [s]: riseTimeConst (MSL's binding)."""
        return self.riseTimeConst

    def signal(self, t):
        tau = t - self.startTime
        y_riseTime = self.outMax * (1 - ca.exp(-self.riseTime / self.riseTimeConst))
        return ca.if_else(tau < self.riseTime,
                          self.outMax * (1 - ca.exp(-tau / self.riseTimeConst)),
                          y_riseTime * ca.exp(-(tau - self.riseTime) / self.fallTimeConst))

    def events(self):
        return [(self.startTime, None), (self.startTime + self.riseTime, None)]


class _ExponentialsFallTimeConst(Exponentials):
    """Exponentials with fallTimeConst given at construction: a parameter of its own."""
    fallTimeConst = Parameter(0.1, "s", "fall time constant", positive=True)


_ExponentialsFallTimeConst.__name__ = "Exponentials"               # shows the MSL class's name
Exponentials._with_fallTimeConst = _ExponentialsFallTimeConst


class SawTooth(_Periodic):
    """Saw tooth: y = offset + amplitude·(time − T_start)/period within each period that
    starts at T_start, from startTime on for nperiod periods (< 0: infinitely many), else
    offset. It jumps back to offset at every period's start: a time event there."""
    amplitude = Parameter(1.0, "", "amplitude of saw tooth")

    def wave(self, tp):
        return self.amplitude * tp / self.period


def _sinc(x):
    """sin(x)/x, 1 at x = 0: near 0 its Taylor series (exact to rounding for |x| < 1e-3,
    and so are its derivatives, which sin(x)/x loses to cancellation there)."""
    x2 = x * x
    series = 1 - x2 / 6 * (1 - x2 / 20 * (1 - x2 / 42))
    small = ca.fabs(x) < 1e-3
    return ca.if_else(small, series, ca.sin(x) / ca.if_else(small, 1, x))


class Sinc(SignalSource):
    """Sinc: y = offset + amplitude·sin(x)/x, x = 2π·f·(time − startTime), after startTime
    (1 at x = 0: no division by zero); before it y = offset, or with ``continuous=True``
    offset + amplitude (no jump at startTime)."""
    options = {"continuous": False}
    amplitude = Parameter(1.0, "", "amplitude of sine wave")
    f = Parameter(1.0, "Hz", "frequency of sine wave")

    def signal(self, t):
        return self.amplitude * _sinc(2 * ca.pi * self.f * (t - self.startTime))

    def before(self):
        return self.amplitude if self.continuous else 0


class _VariableFrequencyAndAmplitude(SO):
    """y = offset + amplitude·wave(phi), der(phi) = 2π·f: the phase phi [rad] (a state,
    start value ``phi_start``, MSL's phi(start = 0)) integrates the frequency, so a
    changing f changes the wave's rate without a jump. amplitude and f [Hz] are the inputs
    of those names, or with ``useConstantAmplitude`` / ``useConstantFrequency`` the
    parameters constantAmplitude / constantFrequency (the input is then absent). No
    startTime (MSL): an amplitude of 0 keeps y at offset."""
    options = {"useConstantAmplitude": False, "useConstantFrequency": False}
    constantAmplitude = Parameter(1.0, "", "constant amplitude")
    constantFrequency = Parameter(1.0, "Hz", "constant frequency")
    offset = Parameter(0.0, "", "offset of the sine wave")
    amplitude = ConditionalPort(RealInput("amplitude"), "useConstantAmplitude", False)
    f = ConditionalPort(RealInput("frequency [Hz]"), "useConstantFrequency", False)

    def __init__(self, name: str | None = None, phi_start: float = 0.0, **params):
        super().__init__(name, **params)
        self.__dict__["phi_start"] = _start(phi_start, f"{type(self).__name__}: phi_start")

    def wave(self, phi):
        raise NotImplementedError

    def structure(self, s):
        s.state("phi", self.phi_start, "rad", "phase of the sine wave")

    def physics(self, e):
        phi = e.state("phi")
        f = self.constantFrequency if self.useConstantFrequency else e.input(self.f)
        amplitude = (self.constantAmplitude if self.useConstantAmplitude
                     else e.input(self.amplitude))
        e.derivative(phi, 2 * ca.pi * f)
        e.output(self.y, self.offset + amplitude * self.wave(phi))


class SineVariableFrequencyAndAmplitude(_VariableFrequencyAndAmplitude):
    __doc__ = ("Sine with variable frequency and amplitude (MSL "
               "Sources.SineVariableFrequencyAndAmplitude): "
               + _VariableFrequencyAndAmplitude.__doc__.replace("wave(phi)", "sin(phi)", 1))

    def wave(self, phi):
        return ca.sin(phi)


class CosineVariableFrequencyAndAmplitude(_VariableFrequencyAndAmplitude):
    __doc__ = ("Cosine with variable frequency and amplitude (MSL "
               "Sources.CosineVariableFrequencyAndAmplitude): "
               + _VariableFrequencyAndAmplitude.__doc__.replace("wave(phi)", "cos(phi)", 1))

    def wave(self, phi):
        return ca.cos(phi)


class LogFrequencySweep(SO):
    """Logarithmic frequency sweep: log10(y) ramps linearly from log10(wMin) to log10(wMax)
    over duration [s] from startTime [s]: y = wMin·(wMax/wMin)^min(1, τ/max(duration, eps)),
    τ = time − startTime; wMin before, wMax after (no offset). wMin and wMax (> 0) are
    required, as in MSL. Time events at the ramp's two kinks."""
    required = ("wMin", "wMax")
    wMin = Parameter(1.0, "", "start frequency", positive=True)
    wMax = Parameter(1.0, "", "end frequency", positive=True)
    startTime = Parameter(0.0, "s", "start time of frequency sweep")
    duration = Parameter(1.0, "s", "duration of ramp (= 0.0 gives a Step)", nonnegative=True)

    def physics(self, e):
        t, duration = e.time, ca.fmax(self.duration, EPS)
        x = ca.fmin(1, (t - self.startTime) / duration)
        e.output(self.y, ca.if_else(t < self.startTime, self.wMin,
                                    ca.if_else(t < self.startTime + duration,
                                               self.wMin * (self.wMax / self.wMin) ** x,
                                               self.wMax)))
        e.time_event(self.startTime)
        e.time_event(self.startTime + duration)


class KinematicPTP(_PointToPoint):
    """Acceleration of the fastest motion over the distances deltaq (MSL
    Sources.KinematicPTP): each axis's speed within qd_max and acceleration within qdd_max
    (> 0), all axes in the same phases (only the axis at its limit is at it): y = deltaq·
    der(der(s)) on KinematicPTP2's normalized path s (accelerate, cruise, brake; bang–bang
    when the largest speed is not reached); integrated twice it gives the positions. Time
    events at the phase changes (the acceleration jumps there).

    Constructor arguments ``deltaq``, ``qd_max``, ``qdd_max`` (numbers or sequences; MSL's
    defaults 1, 1, 1; a one-element one holds for every axis) give the parameters
    ``deltaq[i]`` ... (per element, changeable at simulation time); ``startTime`` [s].
    Outputs ``y[i]``, numbered from 1, nout = the longest of the three. Difference from
    the MSL: where no axis moves (deltaq all 0) y is 0 (MSL divides by zero there).
    """
    _classes: dict = {}
    _vectors = {"deltaq": ("", "distance to move", {}, 1.0),
                "qd_max": ("", "maximum velocity der(q)", {"positive": True}, 1.0),
                "qdd_max": ("", "maximum acceleration der(qd)", {"positive": True}, 1.0)}

    @staticmethod
    def _outputs(nout: int) -> dict:
        return {"y": VectorPort(RealOutput, nout, "connector of Real output signals")}

    def _distances(self) -> list:
        return self._vector("deltaq")

    def physics(self, e):
        p = self.profile()
        sdd = self.normalized_path(e, p)[2]
        for k, dq in enumerate(p["dq"], start=1):
            e.output(self.y[k], dq * sdd)


# ---- routing (Modelica.Blocks.Routing) ---------------------------------------------------------
class RealPassThrough(SISO):
    """y = u (MSL Routing.RealPassThrough): a signal passed on under another name."""

    def physics(self, e):
        e.output(self.y, e.input(self.u))


# ---- math (Modelica.Blocks.Math) ---------------------------------------------------------------
class Gain(SISO):
    """y = k·u."""
    k = Parameter(1.0, "1", "gain value multiplied with input signal")

    def physics(self, e):
        e.output(self.y, self.k * e.input(self.u))


class Add(SI2SO):
    """y = k1·u1 + k2·u2."""
    k1 = Parameter(1.0, "", "gain of input signal 1")
    k2 = Parameter(1.0, "", "gain of input signal 2")

    def physics(self, e):
        e.output(self.y, self.k1 * e.input(self.u1) + self.k2 * e.input(self.u2))


class Add3(SO):
    """y = k1·u1 + k2·u2 + k3·u3."""
    k1 = Parameter(1.0, "", "gain of input signal 1")
    k2 = Parameter(1.0, "", "gain of input signal 2")
    k3 = Parameter(1.0, "", "gain of input signal 3")
    u1 = RealInput("connector of Real input signal 1")
    u2 = RealInput("connector of Real input signal 2")
    u3 = RealInput("connector of Real input signal 3")

    def physics(self, e):
        e.output(self.y, self.k1 * e.input(self.u1) + self.k2 * e.input(self.u2)
                 + self.k3 * e.input(self.u3))


class Feedback(SO):
    """y = u1 − u2 (commanded minus feedback signal)."""
    u1 = RealInput("commanded input")
    u2 = RealInput("feedback input")

    def physics(self, e):
        e.output(self.y, e.input(self.u1) - e.input(self.u2))


class Product(SI2SO):
    """y = u1·u2."""

    def physics(self, e):
        e.output(self.y, e.input(self.u1) * e.input(self.u2))


class Division(SI2SO):
    """y = u1/u2."""

    def physics(self, e):
        e.output(self.y, e.input(self.u1) / e.input(self.u2))


class Sum(_Sized, SO):
    """y = Σ k[i]·u[i], i = 1..nin.

    ``nin`` (constructor argument) is the number of inputs; the inputs are ``u[1]`` ..
    ``u[nin]`` and the gains parameters ``k[1]`` .. ``k[nin]`` (default 1; ``k=[...]`` at
    construction, ``params={"sum.k[2]": -1}`` at simulation time). ``sum.u`` is indexed from
    1 as in Modelica: ``connect(src.y, sum.u[1])``.
    """
    _classes: dict = {}

    def __new__(cls, name=None, *, nin: int = 1, k=None, **params):
        if isinstance(nin, bool) or not isinstance(nin, (int, np.integer)) or nin < 1:
            raise ParameterError(f"Sum: nin (number of inputs) must be an integer >= 1, "
                                 f"got {nin!r}")
        return super().__new__(cls._variant(int(nin)))

    @staticmethod
    def _declare(nin: int) -> dict:
        attrs = {f"k[{i}]": Parameter(1.0, "", f"gain of input u[{i}]")
                 for i in range(1, nin + 1)}
        attrs["u"] = VectorPort(RealInput, nin, tuple(
            f"connector of Real input signal {i}" for i in range(1, nin + 1)))
        return {"_nin": nin, **attrs}

    def __init__(self, name: str | None = None, *, nin: int = 1, k=None, **params):
        if params:
            raise ParameterError(f"Sum has parameters k[1]..k[{self._nin}] only, given as "
                                 f"k=[...]; got {', '.join(params)}")
        super().__init__(name)
        n = self._nin
        if k is not None:
            ks = np.atleast_1d(np.asarray(k, dtype=object)).ravel()
            if ks.size != n:
                raise ParameterError(f"Sum: k has {ks.size} elements but nin = {n}")
            for i, v in enumerate(ks, start=1):
                setattr(self, f"k[{i}]", v)

    @property
    def nin(self) -> int:
        return self._nin

    def physics(self, e):
        e.output(self.y, sum((getattr(self, f"k[{i}]") * e.input(p)
                              for i, p in enumerate(self.u, start=1)), ca.SX(0)))


# ---- nonlinear (Modelica.Blocks.Nonlinear) -----------------------------------------------------
class LimiterHomotopy(str, Enum):
    """Modelica.Blocks.Types.LimiterHomotopy (accepted; it changes nothing here)."""
    NoHomotopy = "NoHomotopy"
    Linear = "Linear"
    UpperLimit = "UpperLimit"
    LowerLimit = "LowerLimit"


class VariableLimiterHomotopy(str, Enum):
    """Modelica.Blocks.Types.VariableLimiterHomotopy (accepted; it changes nothing here)."""
    NoHomotopy = "NoHomotopy"
    Linear = "Linear"
    Fixed = "Fixed"


def _limit(u, lower, upper):
    """MSL's ``if u > upper then upper else if u < lower then lower else u``."""
    return ca.if_else(u > upper, upper, ca.if_else(u < lower, lower, u))


def _check_limits(block, upper: str, lower: str) -> None:
    """A ParameterError when the values at construction have lower > upper (MSL's assert)."""
    hi, lo = getattr(block, upper), getattr(block, lower)
    if hi < lo:
        raise ParameterError(f"{who(block)}: limits must be consistent, but {upper} (= {hi}) "
                             f"< {lower} (= {lo})")


def _smooth_max(a, b, width):
    """max(a, b) with a rounded corner: (a + b + sqrt((a − b)² + width²))/2, above max(a, b)
    by at most width/2 (at a = b), by width²/(4|a − b|) far from it."""
    return (a + b + ca.sqrt((a - b) ** 2 + width ** 2)) / 2


def _smooth_min(a, b, width):
    """min(a, b) with a rounded corner, below it by at most width/2 (see _smooth_max)."""
    return (a + b - ca.sqrt((a - b) ** 2 + width ** 2)) / 2


class _Limiting(SISO):
    """A block that limits u to [lower, upper] (``limited``), as MSL's limiters: ``if u >
    upper then upper else if u < lower then lower else u``; events and smooth form as the
    Limiter's docstring says."""
    u_smooth = Parameter(1e-3, "", "smooth form only: width over which the corners at the "
                                   "limits are rounded (error <= u_smooth/2)", positive=True)

    def structure(self, s):
        _limiter_region(s, not getattr(self, "strict", False))

    def limited(self, e, u, lower, upper):
        """u limited to [lower, upper], and the events that go with it (Limiter)."""
        return _limited(e, u, lower, upper, self.u_smooth, not getattr(self, "strict", False))


def _limiter_region(s, events: bool, prefix: str = "") -> None:
    """Declare the mode ``<prefix>region`` of a limiter with events (not in smooth form)."""
    if events and not s.smooth:
        s.mode(f"{prefix}region", 0, values=(-1, 0, 1),
               description="branch of the limiter: 1 if u > upper limit, -1 if u < lower "
                           "limit, 0 between")


def _limited(e, u, lower, upper, width, events: bool, prefix: str = ""):
    """u limited to [lower, upper] as Limiter's docstring says: in smooth form its corners
    rounded over ``width``; with ``events`` on the mode ``<prefix>region`` and the
    indicators ``<prefix>upper``, ``<prefix>lower``; else the plain expression."""
    if e.smooth:
        return _smooth_min(_smooth_max(u, lower, width), upper, width)
    if not events:
        return _limit(u, lower, upper)
    region = e.mode(f"{prefix}region")
    e.mode_update(region, ca.if_else(u > upper, 1, ca.if_else(u < lower, -1, 0)))
    e.indicator(f"{prefix}upper", ca.if_else(region == 1, u - upper, upper - u), "",
                "distance of u from the upper limit, positive while the region holds")
    e.indicator(f"{prefix}lower", ca.if_else(region == -1, lower - u, u - lower), "",
                "distance of u from the lower limit, positive while the region holds")
    return ca.if_else(region == 1, upper, ca.if_else(region == -1, lower, u))


class _SymmetricLimits(_Limiting):
    """MSL's ``uMax`` (required) and ``uMin`` bound to −uMax: uMin follows uMax, also at
    simulation time, unless it is given at construction, which makes it a parameter of its
    own (the class ``_own_uMin`` derives). Limits with uMax < uMin are refused."""
    required = ("uMax",)
    _with_uMin: type | None = None

    def __new__(cls, name=None, **params):
        own = cls.__dict__.get("_with_uMin") if "uMin" in params else None
        return super().__new__(own or cls)

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        _check_limits(self, "uMax", "uMin")

    @property
    def uMin(self):
        """The lower limit: −uMax (MSL's binding)."""
        return -self.uMax


def _own_uMin(cls, description: str) -> type:
    """The variant of ``cls`` (a _SymmetricLimits) whose uMin is a parameter of its own,
    made when uMin is given at construction; it shows the MSL class's name."""
    variant = type(cls.__name__, (cls,), {
        "__doc__": f"{cls.__name__} with uMin given at construction: a parameter of its own.",
        "__module__": cls.__module__, "__qualname__": f"_{cls.__name__}UMin",
        "uMin": Parameter(-1.0, "", description)})
    cls._with_uMin = variant
    return variant


class Limiter(_SymmetricLimits):
    """Limit the range of a signal: y = uMax if u > uMax, uMin if u < uMin, else u
    (MSL Nonlinear.Limiter).

    Parameters: uMax (required, as in MSL), uMin (default −uMax, MSL's binding: it follows
    uMax, also at simulation time, unless given at construction, which makes it a parameter
    of its own); u_smooth (smooth form only). Options ``strict`` (False: state events at
    the limits, the mode ``region``; True: none, MSL's noEvent) and ``homotopyType``
    (accepted; it changes nothing: the initialization solves the actual model).

    With events (MSL's default, strict=false): the relations are discrete, as a Modelica
    tool makes them: the mode ``region`` (1: u > upper, −1: u < lower, 0: between) says
    which branch holds between events, and the indicators ``upper`` and ``lower`` (the
    distance of u from each limit, positive while the region holds) make the simulator
    locate where u reaches a limit, so a kink is never stepped across, nor missed by an
    integrator that rests (no step limit needed). With ``strict=True`` (MSL's noEvent) the
    plain expression, no events: the integrator's step control resolves the kinks.

    Smooth form (``compile(model, smooth=True)``): the corners rounded over ``u_smooth``,
    y = smooth_min(smooth_max(u, lower), upper) with smooth_max(a, b) = (a + b +
    sqrt((a − b)² + u_smooth²))/2; its error |y − y_exact| ≤ u_smooth/2, reached at the
    limits, decaying as u_smooth²/(4·d) at a distance d from the nearer one.
    """
    options = {"strict": False, "homotopyType": LimiterHomotopy.Linear}
    uMax = Parameter(1.0, "", "upper limits of input signals")

    def physics(self, e):
        e.output(self.y, self.limited(e, e.input(self.u), self.uMin, self.uMax))


_LimiterUMin = _own_uMin(Limiter, "lower limits of input signals")


class VariableLimiter(_Limiting):
    """Limit the range of a signal with variable limits: y = limit1 if u > limit1, limit2 if
    u < limit2, else u (MSL Nonlinear.VariableLimiter). Inputs ``u``, ``limit1`` (maximum),
    ``limit2`` (minimum). Options ``strict`` (events as Limiter's) and ``homotopyType``;
    u_smooth (smooth form only). Events and smooth form: as Limiter's.

    MSL differences: ``homotopyType`` changes nothing (and its ySimplified is not
    declared); MSL's run-time assert limit1 ≥ limit2 is not checked.
    """
    options = {"strict": False, "homotopyType": VariableLimiterHomotopy.Linear}
    limit1 = RealInput("connector of Real input signal used as maximum of input u")
    limit2 = RealInput("connector of Real input signal used as minimum of input u")

    def physics(self, e):
        e.output(self.y, self.limited(e, e.input(self.u), e.input(self.limit2),
                                      e.input(self.limit1)))


class DeadZone(_SymmetricLimits):
    """Region of zero output: y = u − uMax if u > uMax, u − uMin if u < uMin, else 0
    (MSL Nonlinear.DeadZone).

    Parameters: uMax (required, as in MSL), uMin (default −uMax, MSL's binding, as for
    Limiter); u_smooth (smooth form only). y = u − (u limited to [uMin, uMax]), with the
    state events at the zone's edges (mode ``region``) and the smooth form of Limiter
    (the same error bound u_smooth/2).
    """
    uMax = Parameter(1.0, "", "upper limits of dead zones")

    def physics(self, e):
        u = e.input(self.u)
        e.output(self.y, u - self.limited(e, u, self.uMin, self.uMax))


_DeadZoneUMin = _own_uMin(DeadZone, "lower limits of dead zones")


# ---- continuous (Modelica.Blocks.Continuous) ----------------------------------------------------
def _approx_derivative(u, x, k, T):
    """MSL Continuous.Derivative, k·s/(T·s + 1): (der(x), y); both 0 when |k| < eps."""
    zero_gain = ca.fabs(k) < EPS
    return (ca.if_else(zero_gain, 0, (u - x) / T),
            ca.if_else(zero_gain, 0, k / T * (u - x)))


class _StartValues:
    """Start values of a block's states, given as constructor keyword arguments (default 0):
    a number each, or for the names ``_start_size`` gives a length n, n numbers (a tuple;
    a single number is repeated)."""
    _starts: tuple = ()

    def _start_size(self, name: str) -> int | None:
        """The number of values of the start value ``name`` (None: a scalar)."""
        return None

    def __init__(self, name: str | None = None, **kwargs):
        starts = {s: _start_vector(kwargs.pop(s, 0.0), self._start_size(s),
                                   f"{type(self).__name__}: {s}") for s in self._starts}
        super().__init__(name, **kwargs)
        self.__dict__.update(starts)


def _start_vector(value, n: int | None, what: str):
    """A start value as float (n None) or as a tuple of n floats (a ParameterError
    otherwise)."""
    if n is None:
        return _start(value, what)
    items = np.ravel(np.asarray(value, dtype=object))
    if items.size == 1:
        items = np.repeat(items, n)
    if items.size != n:
        raise ParameterError(f"{what} must have {n} values, got {items.size}")
    return tuple(_start(v, f"{what}[{i}]") for i, v in enumerate(items, start=1))


class Init(str, Enum):
    """Modelica.Blocks.Types.Init: how a block's states are initialized."""
    NoInit = "NoInit"
    SteadyState = "SteadyState"
    InitialState = "InitialState"
    InitialOutput = "InitialOutput"


def _initial_equations(e, block, derivatives: dict, output: dict,
                       steady_output: tuple = ()) -> None:
    """MSL's initial equations of a block's ``initType``: SteadyState holds der(s) = 0 for
    every state s of ``derivatives`` (state names → their derivatives); InitialOutput the
    equations ``output`` (labels → expressions held = 0) and der(s) = 0 for the states
    named in ``steady_output``; NoInit and InitialState none (the states start at their
    start values, where nothing else fixes them)."""
    init = block.initType
    if init is Init.SteadyState:
        held = {f"der({s}) = 0": d for s, d in derivatives.items()}
    elif init is Init.InitialOutput:
        held = {**output, **{f"der({s}) = 0": derivatives[s] for s in steady_output}}
    else:
        return
    for label, expr in held.items():
        e.initial(expr, f"{label} (initType={init.value})")


class Integrator(_StartValues, SISO):
    """y = k·∫u dt: der(y) = k·u. Initialization (``initType``, MSL's default InitialState):
    NoInit and InitialState start at y = y_start; SteadyState: der(y) = 0, so k·u = 0 at the
    start (the input must be zero there, or depend on states that can make it zero);
    InitialOutput: y = y_start (held)."""
    _starts = ("y_start",)
    options = {"initType": Init.InitialState}
    k = Parameter(1.0, "1", "integrator gain")

    def structure(self, s):
        s.state("y", self.y_start, description="integrator output (state)")

    def physics(self, e):
        y = e.state("y")
        dy = self.k * e.input(self.u)
        e.derivative(y, dy)
        e.output(self.y, y)
        _initial_equations(e, self, {"y": dy}, {"y = y_start": y - self.y_start})


class Derivative(_StartValues, SISO):
    """Approximated derivative y = k·s/(T·s + 1)·u: der(x) = (u − x)/T, y = (k/T)·(u − x).
    With k = 0 the block gives y = 0. Initialization (``initType``, MSL's default NoInit):
    NoInit and InitialState start at x = x_start; SteadyState: der(x) = 0 (x = u, y = 0);
    InitialOutput: y = y_start (x = u when k = 0)."""
    _starts = ("x_start", "y_start")
    options = {"initType": Init.NoInit}
    k = Parameter(1.0, "1", "gain")
    T = Parameter(0.01, "s", "time constant (T > 0 required)", positive=True)

    def structure(self, s):
        s.state("x", self.x_start, description="state of block")

    def physics(self, e):
        x, u = e.state("x"), e.input(self.u)
        xdot, y = _approx_derivative(u, x, self.k, self.T)
        e.derivative(x, xdot)
        e.output(self.y, y)
        output = ca.if_else(ca.fabs(self.k) < EPS, x - u, y - self.y_start)
        _initial_equations(e, self, {"x": xdot}, {"y = y_start (x = u when k = 0)": output})


class FirstOrder(_StartValues, SISO):
    """First order y = k/(T·s + 1)·u: der(y) = (k·u − y)/T. Initialization (``initType``,
    MSL's default NoInit): NoInit and InitialState start at y = y_start; SteadyState:
    der(y) = 0 (y = k·u); InitialOutput: y = y_start (held)."""
    _starts = ("y_start",)
    options = {"initType": Init.NoInit}
    k = Parameter(1.0, "1", "gain")
    T = Parameter(1.0, "s", "time constant", nonzero=True)

    def structure(self, s):
        s.state("y", self.y_start, description="output (state)")

    def physics(self, e):
        y = e.state("y")
        dy = (self.k * e.input(self.u) - y) / self.T
        e.derivative(y, dy)
        e.output(self.y, y)
        _initial_equations(e, self, {"y": dy}, {"y = y_start": y - self.y_start})


class SecondOrder(_StartValues, SISO):
    """Second order y = k/((s/w)² + 2·D·(s/w) + 1)·u: der(y) = yd,
    der(yd) = w·(w·(k·u − y) − 2·D·yd). Initialization (``initType``, MSL's default
    NoInit): NoInit and InitialState start at y = y_start, yd = yd_start; SteadyState:
    der(y) = der(yd) = 0 (y = k·u, yd = 0); InitialOutput: y = y_start and yd = yd_start
    (held)."""
    _starts = ("y_start", "yd_start")
    options = {"initType": Init.NoInit}
    k = Parameter(1.0, "1", "gain")
    w = Parameter(1.0, "rad/s", "angular frequency")
    D = Parameter(1.0, "1", "damping")

    def structure(self, s):
        s.state("y", self.y_start, description="output (state)")
        s.state("yd", self.yd_start, description="derivative of y (state)")

    def physics(self, e):
        y, yd = e.state("y"), e.state("yd")
        ydd = self.w * (self.w * (self.k * e.input(self.u) - y) - 2 * self.D * yd)
        e.derivative(y, yd)
        e.derivative(yd, ydd)
        e.output(self.y, y)
        _initial_equations(e, self, {"y": yd, "yd": ydd}, {"y = y_start": y - self.y_start,
                                                            "yd = yd_start": yd - self.yd_start})


class PI(_StartValues, SISO):
    """PI controller y = k·(1 + 1/(T·s))·u: der(x) = u/T, y = k·(x + u). Initialization
    (``initType``, MSL's default NoInit): NoInit and InitialState start at x = x_start;
    SteadyState: der(x) = 0, so u = 0 at the start (the input must be zero there, or
    depend on states that can make it zero); InitialOutput: y = y_start."""
    _starts = ("x_start", "y_start")
    options = {"initType": Init.NoInit}
    k = Parameter(1.0, "1", "gain")
    T = Parameter(1.0, "s", "time constant (T > 0 required)", positive=True)

    def structure(self, s):
        s.state("x", self.x_start, description="state of block")

    def physics(self, e):
        x = e.state("x")
        u = e.input(self.u)
        xdot, y = u / self.T, self.k * (x + u)
        e.derivative(x, xdot)
        e.output(self.y, y)
        _initial_equations(e, self, {"x": xdot}, {"y = y_start": y - self.y_start})


class PID(_StartValues, SISO):
    """PID controller in additive form (MSL Continuous.PID): y = k·(P.y + I.y + D.y) with
    P.y = u, I: der(I.y) = u/Ti, D: approximated derivative Td·s/(Td/Nd·s + 1)·u
    (der(D.x) = (u − D.x)/T, D.y = (Td/T)·(u − D.x), T = max(Td/Nd, 100·eps)).

    States ``I.y`` (start xi_start) and ``D.x`` (start xd_start), named as the states of the
    MSL block's sub-blocks (``PID.I.y``, ``PID.D.x``); ``P.y``, ``I.y``, ``D.y`` are recorded.
    Initialization (``initType``, MSL's default InitialState): NoInit and InitialState
    start at the start values; SteadyState: der(I.y) = der(D.x) = 0 (u = 0 at the start,
    as for Integrator); InitialOutput: y = y_start and der(D.x) = 0.
    """
    _starts = ("xi_start", "xd_start", "y_start")
    options = {"initType": Init.InitialState}
    k = Parameter(1.0, "1", "gain")
    Ti = Parameter(0.5, "s", "time constant of integrator", positive=True)
    Td = Parameter(0.1, "s", "time constant of derivative block", nonnegative=True)
    Nd = Parameter(10.0, "1", "the higher Nd, the more ideal the derivative block",
                   positive=True)

    def structure(self, s):
        s.state("I.y", self.xi_start, description="integral part (state)")
        s.state("D.x", self.xd_start, description="state of derivative block")

    def physics(self, e):
        xi, xd = e.state("I.y"), e.state("D.x")
        u = e.input(self.u)
        xi_dot = u / self.Ti
        e.derivative(xi, xi_dot)
        xd_dot, d_y = _approx_derivative(u, xd, self.Td, ca.fmax(self.Td / self.Nd, 100 * EPS))
        e.derivative(xd, xd_dot)
        e.variable("P.y", u, description="proportional part")
        e.variable("D.y", d_y, description="derivative part")
        y = self.k * (u + xi + d_y)
        e.output(self.y, y)
        _initial_equations(e, self, {"I.y": xi_dot, "D.x": xd_dot},
                           {"y = y_start": y - self.y_start}, steady_output=("D.x",))


class SimpleController(str, Enum):
    """Modelica.Blocks.Types.SimpleController: the parts of LimPID."""
    P = "P"
    PI = "PI"
    PD = "PD"
    PID = "PID"


class LimPID(_StartValues, Component):
    """P, PI, PD or PID controller with limited output, anti-windup, set-point weighting and
    optional feed-forward (MSL Continuous.LimPID), the equations of its internal blocks::

        controlError = u_s − u_m
        P.y  = wp·u_s − u_m
        D:   der(D.x) = (wd·u_s − u_m − D.x)/Tf,  D.y = (Td/Tf)·(wd·u_s − u_m − D.x),
             Tf = max(Td/Nd, 1e-14)   (D.y = 0, der(D.x) = 0 when Td < eps)
        I:   der(I.y) = (u_s − u_m + (y − limiter.u)/(k·Ni))/Ti
        limiter.u = k·(P.y + I.y + D.y) + kFF·u_ff
        y = limiter.u clamped to [yMin, yMax]

    Inputs ``u_s`` (set point), ``u_m`` (measurement), ``u_ff`` (feed-forward, with
    ``withFeedForward=True``); output ``y``. Options: ``controllerType`` (P, PI, PD, PID:
    without I or D part the state and its terms are absent), ``withFeedForward``,
    ``initType``, ``strict``, ``homotopyType``.

    Parameters: k [1] (non-zero), Ti [s] (> 0), Td [s] (≥ 0), yMax (required, as in MSL),
    yMin (default −yMax, MSL's binding: follows yMax unless given at construction), wp, wd
    [1] (set-point weights), Ni [1] (Ni·Ti is the anti-windup time constant), Nd [1] (the
    higher, the more ideal the derivative), kFF [1], y_smooth (smooth form only). Start
    values (constructor arguments): xi_start (I.y), xd_start (D.x), y_start. Recorded:
    controlError, P.y, D.y, limiter.u.

    Initialization (``initType``, MSL's default InitialState): NoInit and InitialState
    start the states at xi_start, xd_start; SteadyState: der(I.y) = der(D.x) = 0 (of the
    parts present); InitialOutput: k·(P.y + I.y + D.y) = y_start (the output before the
    feed-forward and the limiter, MSL's gainPID.y; y_start within [yMin, yMax]) and
    der(D.x) = 0.

    The output limiter is MSL's Limiter (``limiter``): with strict=False (MSL's default)
    state events where limiter.u reaches yMax or yMin (mode ``limiter.region``, indicators
    ``limiter.upper``, ``limiter.lower``), with strict=True none; in smooth form its
    corners rounded over ``y_smooth`` (error ≤ y_smooth/2; see Limiter).

    MSL differences: homotopyType changes nothing (the initialization solves the actual
    model).
    """
    _starts = ("xi_start", "xd_start", "y_start")
    options = {"controllerType": SimpleController.PID, "withFeedForward": False,
               "initType": Init.InitialState, "strict": False,
               "homotopyType": LimiterHomotopy.Linear}
    required = ("yMax",)
    u_s = RealInput("connector of setpoint input signal")
    u_m = RealInput("connector of measurement input signal")
    y = RealOutput("connector of actuator output signal")
    u_ff = ConditionalPort(RealInput("optional connector of feed-forward input signal"),
                           "withFeedForward")
    k = Parameter(1.0, "1", "gain of controller, must be non-zero", nonzero=True)
    Ti = Parameter(0.5, "s", "time constant of Integrator block", positive=True)
    Td = Parameter(0.1, "s", "time constant of Derivative block", nonnegative=True)
    yMax = Parameter(1.0, "", "upper limit of output")
    wp = Parameter(1.0, "1", "set-point weight for Proportional block (0..1)",
                   nonnegative=True)
    wd = Parameter(0.0, "1", "set-point weight for Derivative block (0..1)", nonnegative=True)
    Ni = Parameter(0.9, "1", "Ni*Ti is time constant of anti-windup compensation",
                   positive=True)
    Nd = Parameter(10.0, "1", "the higher Nd, the more ideal the derivative block",
                   positive=True)
    kFF = Parameter(1.0, "1", "gain of feed-forward input")
    y_smooth = Parameter(1e-3, "", "smooth form only: width over which the corners of the "
                                   "output limiter are rounded (error <= y_smooth/2)",
                         positive=True)

    def __new__(cls, name=None, **params):
        return super().__new__(_LimPIDyMin if cls is LimPID and "yMin" in params else cls)

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        _check_limits(self, "yMax", "yMin")
        if self.initType is Init.InitialOutput and not self.yMin <= self.y_start <= self.yMax:
            raise ParameterError(f"{who(self)}: start value y_start (= {self.y_start}) is "
                                 f"outside of the limits yMin (= {self.yMin}) and yMax "
                                 f"(= {self.yMax}) (initType=InitialOutput)")

    @property
    def yMin(self):
        """Lower limit of output: −yMax (MSL's binding)."""
        return -self.yMax

    @property
    def _with_I(self) -> bool:
        return self.controllerType in (SimpleController.PI, SimpleController.PID)

    @property
    def _with_D(self) -> bool:
        return self.controllerType in (SimpleController.PD, SimpleController.PID)

    def structure(self, s):
        _limiter_region(s, not self.strict, "limiter.")
        if self._with_I:
            s.state("I.y", self.xi_start, description="integral part (state)")
        if self._with_D:
            s.state("D.x", self.xd_start, description="state of derivative block")

    def physics(self, e):
        u_s, u_m = e.input(self.u_s), e.input(self.u_m)
        p_y = self.wp * u_s - u_m
        d_y = 0
        if self._with_D:
            xd = e.state("D.x")
            xd_dot, d_y = _approx_derivative(self.wd * u_s - u_m, xd, self.Td,
                                             ca.fmax(self.Td / self.Nd, 1e-14))
            e.derivative(xd, xd_dot)
        i_y = e.state("I.y") if self._with_I else 0
        u_ff = e.input(self.u_ff) if self.withFeedForward else 0
        gain_y = self.k * (p_y + i_y + d_y)
        lim_u = gain_y + self.kFF * u_ff
        y = _limited(e, lim_u, self.yMin, self.yMax, self.y_smooth, not self.strict,
                     "limiter.")
        derivatives = {"D.x": xd_dot} if self._with_D else {}
        if self._with_I:
            track = (y - lim_u) / (self.k * self.Ni)
            derivatives["I.y"] = (u_s - u_m + track) / self.Ti
            e.derivative(i_y, derivatives["I.y"])
        _initial_equations(e, self, derivatives, {"k*(P.y + I.y + D.y) = y_start":
                                                  gain_y - self.y_start},
                           steady_output=("D.x",) if self._with_D else ())
        e.variable("controlError", u_s - u_m, description="control error (set point - "
                                                           "measurement)")
        e.variable("P.y", p_y, description="proportional part")
        e.variable("D.y", d_y, description="derivative part")
        e.variable("limiter.u", lim_u, description="controller output before the limiter")
        e.output(self.y, y)


class _LimPIDyMin(LimPID):
    """LimPID with yMin given at construction: a parameter of its own."""
    yMin = Parameter(-1.0, "", "lower limit of output")


_LimPIDyMin.__name__ = "LimPID"


def _matrix(values, name: str, rows: int | None = None, cols: int | None = None) -> np.ndarray:
    """A block's matrix parameter given at construction, as a 2-D float array (one row or
    column may be given flat where the other size is known), checked against ``rows`` and
    ``cols`` when given (a ParameterError naming it otherwise)."""
    try:
        m = np.atleast_1d(np.array(values, dtype=float))
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a matrix of numbers, got {values!r}") from None
    if m.ndim == 1:
        m = m.reshape(-1, 1) if cols == 1 or (rows is not None and rows == m.size != 1) \
            else m.reshape(1, -1)
    if m.ndim != 2 or (rows is not None and m.shape[0] != rows) \
            or (cols is not None and m.shape[1] != cols):
        want = f"({'n' if rows is None else rows}, {'m' if cols is None else cols})"
        raise ParameterError(f"{name} must have shape {want}, got shape {m.shape}")
    if not np.all(np.isfinite(m)):
        raise ParameterError(f"{name} contains non-finite values")
    return m


class _Coefficients(_Sized):
    """The coefficients of a transfer function, b (numerator) and a (denominator), highest
    power first, given at construction: their sizes nb <= na fix the block's class, their
    values are the parameters ``b[1]`` .. ``b[nb]``, ``a[1]`` .. ``a[na]`` (changeable at
    simulation time); a[1] != 0."""

    def __new__(cls, name=None, *, b=(1.0,), a=(1.0,), **params):
        nb, na = (_matrix(v, f"{cls.__name__}: {n}", 1).size for v, n in ((b, "b"), (a, "a")))
        if nb > na:
            raise ParameterError(f"{cls.__name__}: transfer function is not proper: b has "
                                 f"{nb} coefficients, a {na} (nb <= na required: give b "
                                 f"at most as many coefficients as a)")
        return super().__new__(cls._variant(nb, na))

    @staticmethod
    def _declare(nb: int, na: int) -> dict:
        return {"b": Parameter((1.0,) * nb, "", "numerator coefficients of transfer "
                                                "function (e.g., 2*s+3 is specified as {2,3})"),
                "a": Parameter((1.0,) * na, "", "denominator coefficients of transfer "
                                                "function (e.g., 5*s+6 is specified as {5,6})")}

    def __init__(self, name: str | None = None, *, b=(1.0,), a=(1.0,), **params):
        what = type(self).__name__
        coeffs = {n: tuple(_matrix(v, f"{what}: {n}", 1).ravel()) for n, v in (("b", b),
                                                                             ("a", a))}
        super().__init__(name, **coeffs, **params)
        if coeffs["a"][0] == 0:
            raise ParameterError(f"{who(self)}: a[1] must be non-zero (the leading "
                                 f"denominator coefficient), got a = {[float(v) for v in coeffs['a']]}")

    @property
    def nx(self) -> int:
        """Number of states, na − 1."""
        return self._key[1] - 1

    def _start_size(self, name: str) -> int | None:
        return self.nx if name == "x_start" else None


class TransferFunction(_Coefficients, _StartValues, SISO):
    """Linear transfer function (MSL Continuous.TransferFunction)::

                b[1]·s^(nb−1) + b[2]·s^(nb−2) + ... + b[nb]
        y(s) = --------------------------------------------- · u(s)
                a[1]·s^(na−1) + a[2]·s^(na−2) + ... + a[na]

    ``b`` and ``a`` (given at construction; their sizes nb ≤ na fix the block, their
    values are the parameters ``b[1]`` .. ``b[nb]``, ``a[1]`` .. ``a[na]``, changeable at
    simulation time). The states are MSL's: the controller canonical form scaled by
    a_end = a[na] if a[na] > 100·eps·|a|, else 1 (MSL's test, without abs),
    ``x_scaled[1]`` .. ``x_scaled[nx]``
    (nx = na − 1)::

        der(x_scaled[1])    = (−a[2:na]·x_scaled + a_end·u)/a[1]
        der(x_scaled[2:nx]) = x_scaled[1:nx−1]
        y = ((bb[2:na] − d·a[2:na])·x_scaled)/a_end + d·u,  x = x_scaled/a_end

    with bb = b padded with leading zeros to na, d = bb[1]/a[1]; ``x[i]`` are recorded
    (nx = 0: y = d·u). Initialization (``initType``, MSL's default NoInit): NoInit and
    InitialState start at x = x_start; SteadyState: der(x_scaled) = 0; InitialOutput:
    y = y_start and der(x_scaled[2:nx]) = 0. Start values (constructor arguments):
    ``x_start`` (nx values), ``y_start``.
    """
    _starts = ("x_start", "y_start")
    options = {"initType": Init.NoInit}
    _classes: dict = {}

    def __init__(self, name: str | None = None, *, b=(1.0,), a=(1.0,), **params):
        super().__init__(name, b=b, a=a, **params)
        if self.initType is Init.InitialOutput and self.nx == 0:
            raise ParameterError(f"{who(self)}: initType=InitialOutput needs a state (a has "
                                 f"one coefficient: y = d*u, with no initial value to give)")

    def _a_end(self):
        """a[na], or 1 when it is ≈ 0 (MSL's scaling of the states)."""
        a = self.a
        return ca.if_else(a[-1] > 100 * EPS * ca.norm_2(a), a[-1], 1.0)

    def structure(self, s):
        a_end = self._a_end()
        for i in range(self.nx):
            s.state(f"x_scaled[{i + 1}]", self.x_start[i] * a_end,
                    description="scaled state of the controller canonical form")

    def physics(self, e):
        u, a, nb, na = e.input(self.u), self.a, *self._key
        bb = [0] * (na - nb) + [self.b[i] for i in range(nb)]
        d = bb[0] / a[0]
        if self.nx == 0:
            e.output(self.y, d * u)
            return
        a_end = self._a_end()
        xs = [e.state(f"x_scaled[{i + 1}]") for i in range(self.nx)]
        der = [(-sum(a[i + 1] * x for i, x in enumerate(xs)) + a_end * u) / a[0]] + xs[:-1]
        for x, dx in zip(xs, der):
            e.derivative(x, dx)
        y = sum((bb[i + 1] - d * a[i + 1]) * x for i, x in enumerate(xs)) / a_end + d * u
        e.output(self.y, y)
        for i, x in enumerate(xs, start=1):
            e.variable(f"x[{i}]", x / a_end,
                       description="state of transfer function from controller canonical form")
        names = [f"x_scaled[{i}]" for i in range(1, self.nx + 1)]
        _initial_equations(e, self, dict(zip(names, der)), {"y = y_start": y - self.y_start},
                           steady_output=names[1:])


class _Matrices(_Sized):
    """The matrices A (nx × nx), B (nx × nin), C (nout × nx), D (nout × nin, default zeros)
    of a state space system, given at construction (MSL's defaults: A = [1, 0; 0, 1],
    B = [1; 1], C = [1, 1]): their shapes fix the block's class, their values are the
    parameters ``A[1]`` .. ``A[nx·nx]`` (row by row, as a table's values), likewise B, C, D;
    inputs ``u[1]`` .. ``u[nin]``, outputs ``y[1]`` .. ``y[nout]``."""
    _defaults = {"A": [[1.0, 0.0], [0.0, 1.0]], "B": [[1.0], [1.0]], "C": [[1.0, 1.0]]}

    def __new__(cls, name=None, *, A=None, B=None, C=None, D=None, **params):
        A, _, _, D = cls._matrices(A, B, C, D)
        return super().__new__(cls._variant(A.shape[0], *D.shape))

    @classmethod
    def _matrices(cls, A, B, C, D) -> tuple:
        """A, B, C, D as arrays of consistent shapes (MSL's defaults for those not given)."""
        d, what = _Matrices._defaults, cls.__name__
        A = _matrix(d["A"] if A is None else A, f"{what}: A")
        nx = A.shape[0]
        if A.shape != (nx, nx) or nx == 0:
            raise ParameterError(f"{what}: A must be square with at least one row, got "
                                 f"shape {A.shape}")
        B = _matrix(d["B"] if B is None else B, f"{what}: B", nx)
        C = _matrix(d["C"] if C is None else C, f"{what}: C", None, nx)
        D = _matrix(np.zeros((C.shape[0], B.shape[1])) if D is None else D, f"{what}: D",
                    C.shape[0], B.shape[1])
        return A, B, C, D

    @staticmethod
    def _declare(nx: int, nout: int, nin: int) -> dict:
        def matrix(rows, cols, what):
            return Parameter((0.0,) * (rows * cols), "", f"matrix {what} of state space model "
                                                         f"({rows} x {cols}, row by row)")
        return {"A": matrix(nx, nx, "A"), "B": matrix(nx, nin, "B"),
                "C": matrix(nout, nx, "C"), "D": matrix(nout, nin, "D"),
                "u": VectorPort(RealInput, nin, "connector of Real input signals"),
                "y": VectorPort(RealOutput, nout, "connector of Real output signals")}

    def __init__(self, name: str | None = None, *, A=None, B=None, C=None, D=None, **params):
        matrices = self._matrices(A, B, C, D)
        super().__init__(name, **dict(zip("ABCD", (tuple(m.ravel()) for m in matrices))),
                         **params)

    @property
    def nx(self) -> int:
        """Number of states."""
        return self._key[0]

    @property
    def nin(self) -> int:
        """Number of inputs."""
        return self._key[2]

    @property
    def nout(self) -> int:
        """Number of outputs."""
        return self._key[1]

    def _start_size(self, name: str) -> int | None:
        return {"x_start": self.nx, "y_start": self.nout}[name]

    def _symbolic(self, name: str, rows: int, cols: int) -> ca.SX:
        return ca.reshape(getattr(self, name), cols, rows).T

    def _system(self) -> tuple:
        """The symbolic A, B, C, D (of the parameters)."""
        nx, nin, nout = self.nx, self.nin, self.nout
        return (self._symbolic("A", nx, nx), self._symbolic("B", nx, nin),
                self._symbolic("C", nout, nx), self._symbolic("D", nout, nin))


class StateSpace(_Matrices, _StartValues, Component):
    """Linear state space system (MSL Continuous.StateSpace), MIMO::

        der(x) = A·x + B·u
            y  = C·x + D·u

    ``A`` (nx × nx), ``B`` (nx × nin), ``C`` (nout × nx), ``D`` (nout × nin, default
    zeros), given at construction (MSL's defaults: A = [1, 0; 0, 1], B = [1; 1],
    C = [1, 1]); their shapes fix the block, their values are the parameters ``A[1]`` ..
    ``A[nx·nx]`` (row by row, as a table's values; ``params={"<name>.A": matrix}`` changes
    them at simulation time), likewise B, C, D. Inputs ``u[1]`` .. ``u[nin]``, outputs
    ``y[1]`` .. ``y[nout]``, states ``x[1]`` .. ``x[nx]``.

    Initialization (``initType``, MSL's default NoInit): NoInit and InitialState start at
    x = x_start; SteadyState: der(x) = 0; InitialOutput: y = y_start with the remaining
    states in steady state as far as possible, MSL's
    x = equalityLeastSquares(A, −B·u, C, y_start − D·u), written as its optimality
    conditions C·x = y_start − D·u, P·Aᵀ·(A·x + B·u) = 0 with P = I − Cᵀ(C·Cᵀ)⁻¹C (C of
    full row rank). Start values (constructor arguments): ``x_start`` (nx values),
    ``y_start`` (nout values).
    """
    _starts = ("x_start", "y_start")
    options = {"initType": Init.NoInit}
    _classes: dict = {}

    def __init__(self, name: str | None = None, *, A=None, B=None, C=None, D=None, **params):
        super().__init__(name, A=A, B=B, C=C, D=D, **params)
        C = self._matrices(A, B, C, D)[2]
        if self.initType is Init.InitialOutput and np.linalg.matrix_rank(C) < C.shape[0]:
            raise ParameterError(f"{who(self)}: initType=InitialOutput needs C of full row "
                                 f"rank ({C.shape[0]} independent outputs to start at "
                                 f"y_start), got rank {np.linalg.matrix_rank(C)}")

    def structure(self, s):
        for i in range(self.nx):
            s.state(f"x[{i + 1}]", self.x_start[i], description="state vector")

    def physics(self, e):
        nx, nout = self.nx, self.nout
        A, B, C, D = self._system()
        states = [e.state(f"x[{i + 1}]") for i in range(nx)]
        x, u = ca.vertcat(*states), ca.vertcat(*(e.input(p) for p in self.u))
        xdot, y = A @ x + B @ u, C @ x + D @ u
        for i, state in enumerate(states):
            e.derivative(state, xdot[i])
        for i, port in enumerate(self.y):
            e.output(port, y[i])
        output = {f"y[{i + 1}] = y_start[{i + 1}]": y[i] - self.y_start[i]
                  for i in range(nout)}
        if self.initType is Init.InitialOutput:
            rest = (ca.SX.eye(nx) - C.T @ ca.solve(C @ C.T, C)) @ A.T @ xdot
            output.update({f"der(x) least squares, row {i + 1}": rest[i] for i in range(nx)})
        _initial_equations(e, self, {f"x[{i + 1}]": xdot[i] for i in range(nx)}, output)


# ---- continuous: limited integrator, exact derivative, filters (Modelica.Blocks.Continuous) --
def _smoothstep(x):
    """0 for x ≤ 0, 1 for x ≥ 1, x²·(3 − 2x) between: a step with continuous slope."""
    return ca.if_else(x <= 0, 0, ca.if_else(x >= 1, 1, x * x * (3 - 2 * x)))


class LimIntegrator(_StartValues, SISO):
    """Integrator with limited output (MSL Continuous.LimIntegrator): der(y) = k·u, halted
    at the limits: der(y) = 0 if y > outMax and k·u > 0 or y < outMin and k·u < 0.

    Parameters: k, outMax (required, as in MSL), outMin (default −outMax, MSL's binding: it
    follows outMax, also at simulation time, unless given at construction, which makes it
    a parameter of its own); y_smooth (smooth form only). Options ``initType`` (MSL's
    default InitialState: y starts at y_start; InitialOutput: y = y_start held;
    SteadyState: der(y) = 0), ``limitsAtInit`` (False: the SteadyState equation is
    k·u = 0, the limits ignored), ``strict`` (False: state events; True: none, MSL's
    noEvent). Start value (constructor argument): ``y_start``.

    With events (strict=False) the relations y > outMax, y < outMin, k·u > 0 are discrete
    as in a Modelica tool: the indicators ``upper`` (y − outMax), ``lower`` (y − outMin)
    and ``input`` (k·u) locate where they change, and the mode ``region`` (1: halted at
    outMax, −1: halted at outMin, 0: integrating) is set from them at every event. In
    smooth form (``compile(model, smooth=True)``) der(y) = k·u − s(1 + (y − outMax)/y_smooth)
    ·max(k·u, 0) − s(1 + (outMin − y)/y_smooth)·min(k·u, 0), s the smoothstep (0 → 1 with
    continuous slope): the integration slows within y_smooth of a limit and never passes it.
    With strict=True nothing tells the integrator where k·u changes sign while y rests at
    a limit (der(y) = 0 exactly, its steps grow): give ``simulate(max_step=...)`` shorter
    than the input's changes, or keep the events.

    MSL differences: no reset/set ports (use_reset, use_set); limitsAtInit=False does not
    check that y is within the limits after the initialization.
    """
    _starts = ("y_start",)
    options = {"initType": Init.InitialState, "limitsAtInit": True, "strict": False}
    required = ("outMax",)
    k = Parameter(1.0, "1", "integrator gain")
    outMax = Parameter(1.0, "", "upper limit of output")
    y_smooth = Parameter(1e-3, "", "smooth form only: width below each limit over which the "
                                   "integration is halted gradually", positive=True)

    def __new__(cls, name=None, **params):
        return super().__new__(_LimIntegratorOutMin if cls is LimIntegrator and "outMin" in
                               params else cls)

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        _check_limits(self, "outMax", "outMin")

    @property
    def outMin(self):
        """Lower limit of output: −outMax (MSL's binding)."""
        return -self.outMax

    def structure(self, s):
        s.state("y", self.y_start, description="integrator output (state)")
        if not (self.strict or s.smooth):
            s.mode("region", 0, values=(-1, 0, 1),
                   description="1 if halted at outMax, -1 if halted at outMin, 0 integrating")

    def physics(self, e):
        y, ku = e.state("y"), self.k * e.input(self.u)
        upper, lower = self.outMax, self.outMin
        if e.smooth:
            width = self.y_smooth
            dy = (ku - _smoothstep(1 + (y - upper) / width) * ca.fmax(ku, 0)
                  - _smoothstep(1 + (lower - y) / width) * ca.fmin(ku, 0))
        else:
            held = ca.if_else(ca.logic_and(y > upper, ku > 0), 1,
                              ca.if_else(ca.logic_and(y < lower, ku < 0), -1, 0))
            if self.strict:
                dy = ca.if_else(held == 0, ku, 0)
            else:
                region = e.mode("region")
                e.mode_update(region, held)
                e.indicator("upper", y - upper, "", "y - outMax (the relation y > outMax)")
                e.indicator("lower", y - lower, "", "y - outMin (the relation y < outMin)")
                e.indicator("input", ku, "", "k*u (the relations k*u > 0, k*u < 0)")
                dy = ca.if_else(region == 0, ku, 0)
        e.derivative(y, dy)
        e.output(self.y, y)
        _initial_equations(e, self, {"y": dy if self.limitsAtInit else ku},
                           {"y = y_start": y - self.y_start})


class _LimIntegratorOutMin(LimIntegrator):
    """LimIntegrator with outMin given at construction: a parameter of its own."""
    outMin = Parameter(-1.0, "", "lower limit of output")


_LimIntegratorOutMin.__name__ = "LimIntegrator"


class Der(SISO):
    """Exact derivative of the input, y = der(u) (MSL Continuous.Der): u's expression is
    differentiated symbolically, as a Modelica tool differentiates the equations that give
    u. The input must therefore be differentiable: a function of states, time and
    parameters (a filter's output, a source; a step's jump contributes nothing), up to
    three Der blocks in a chain of the same signal; a model input or an algebraic variable
    has no known derivative (a StructureError when compiled; filter it, e.g. with
    Derivative or Filter, instead)."""

    def physics(self, e):
        e.output(self.y, e.der(e.input(self.u)))


def _order(block: str, name: str, value, largest: int | None = None) -> int:
    """A filter's order given at construction, as int (a ParameterError otherwise)."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1 \
            or (largest is not None and value > largest):
        within = f"between 1 and {largest}" if largest else ">= 1"
        raise ParameterError(f"{block}: {name} (order of filter) must be an integer {within}, "
                             f"got {value!r}")
    return int(value)


class _Ordered(_StartValues):
    """A filter whose order (constructor argument ``n``) fixes its number of states."""

    def __init__(self, name: str | None = None, *, n: int = 2, **params):
        self.__dict__["n"] = _order(type(self).__name__ + (f" '{name}'" if name else ""),
                                    "n", n)
        super().__init__(name, **params)


class CriticalDamping(_Ordered, SISO):
    """Filter of order ``n`` with critical damping (MSL Continuous.CriticalDamping): n first
    order sections in series, y = 1/(s/w + 1)^n·u with w = 2π·f/alpha, alpha =
    sqrt(2^(1/n) − 1) if ``normalized`` (the amplitude at f is 1/sqrt(2)), else 1::

        der(x[1]) = (u − x[1])·w,  der(x[i]) = (x[i−1] − x[i])·w,  y = x[n]

    ``n`` (constructor argument, default 2) is the order; f [Hz] (required, as in MSL).
    Initialization (``initType``, MSL's default NoInit): NoInit and InitialState start at
    x = x_start; SteadyState: der(x) = 0 (y = u); InitialOutput: y = y_start and
    der(x[1:n−1]) = 0. Start values (constructor arguments): ``x_start`` (n values),
    ``y_start``.
    """
    _starts = ("x_start", "y_start")
    options = {"normalized": True, "initType": Init.NoInit}
    required = ("f",)
    f = Parameter(1.0, "Hz", "cut-off frequency", positive=True)

    def _start_size(self, name: str) -> int | None:
        return self.n if name == "x_start" else None

    def structure(self, s):
        for i in range(self.n):
            s.state(f"x[{i + 1}]", self.x_start[i], description="filter states")

    def physics(self, e):
        n = self.n
        alpha = math.sqrt(2 ** (1 / n) - 1) if self.normalized else 1.0
        w = 2 * math.pi * self.f / alpha
        x = [e.state(f"x[{i + 1}]") for i in range(n)]
        der = [(before - xi) * w for before, xi in zip([e.input(self.u)] + x[:-1], x)]
        for xi, dx in zip(x, der):
            e.derivative(xi, dx)
        e.output(self.y, x[-1])
        names = [f"x[{i + 1}]" for i in range(n)]
        _initial_equations(e, self, dict(zip(names, der)), {"y = y_start": x[-1] - self.y_start},
                           steady_output=names[:-1])


class LowpassButterworth(_Ordered, SISO):
    """Low pass Butterworth filter of order ``n`` (MSL Continuous.LowpassButterworth): the
    amplitude at the cut-off frequency f is 1/sqrt(2). MSL's realization: m = n div 2
    second order sections with w = 2π·f, D[i] = −cos(π/2 + π/n·(i − 1/2)),
    z[1] = u, z[i+1] = x1[i]::

        der(x1[i]) = x2[i],  der(x2[i]) = w²·z[i] − 2·D[i]·w·x2[i] − w²·x1[i]

    and for odd n a real pole der(xr) = (z[m+1] − xr)·w, y = xr (even n: y = z[m+1]).

    ``n`` (constructor argument, default 2) is the order; f [Hz] (required, as in MSL).
    Initialization (``initType``, MSL's default NoInit): NoInit and InitialState start at
    x1_start, x2_start (m values each), xr_start; SteadyState: all derivatives 0 (y = u);
    InitialOutput: y = y_start, der(x1) = 0 and der(x2[1:m−1]) = 0 (even n), der(x2) = 0
    (odd n: what MSL means by its second der(x1) = 0). For even n there is no state xr
    (MSL's dummy xr = 0).
    """
    _starts = ("x1_start", "x2_start", "xr_start", "y_start")
    options = {"initType": Init.NoInit}
    required = ("f",)
    f = Parameter(1.0, "Hz", "cut-off frequency", positive=True)

    def _start_size(self, name: str) -> int | None:
        return self.n // 2 if name in ("x1_start", "x2_start") else None

    def structure(self, s):
        for i in range(self.n // 2):
            s.state(f"x1[{i + 1}]", self.x1_start[i],
                    description="states 1 of second order filters (der(x1) = x2)")
            s.state(f"x2[{i + 1}]", self.x2_start[i],
                    description="states 2 of second order filters")
        if self.n % 2:
            s.state("xr", self.xr_start, description="state of real pole")

    def physics(self, e):
        n, m = self.n, self.n // 2
        w = 2 * math.pi * self.f
        z, der = e.input(self.u), {}
        for i in range(1, m + 1):
            D = -math.cos(math.pi / 2 + math.pi / n * (i - 0.5))
            x1, x2 = e.state(f"x1[{i}]"), e.state(f"x2[{i}]")
            der[f"x1[{i}]"], der[f"x2[{i}]"] = x2, w * w * (z - x1) - 2 * D * w * x2
            e.derivative(x1, x2)
            e.derivative(x2, der[f"x2[{i}]"])
            z = x1
        if n % 2:
            xr = e.state("xr")
            der["xr"] = (z - xr) * w
            e.derivative(xr, der["xr"])
            z = xr
        e.output(self.y, z)
        steady = [f"x1[{i}]" for i in range(1, m + 1)] + \
            [f"x2[{i}]" for i in range(1, (m if n % 2 else m - 1) + 1)]
        _initial_equations(e, self, der, {"y = y_start": z - self.y_start},
                           steady_output=tuple(steady))


class Filter(_StartValues, SISO):
    """Continuous low pass, high pass, band pass or band stop filter of type CriticalDamping,
    Bessel, Butterworth or ChebyshevI (MSL Continuous.Filter).

    Options: ``analogFilter`` (AnalogFilter, default CriticalDamping), ``filterType``
    (FilterType, default LowPass), ``normalized`` (True: the amplitude at f_cut is -3 dB =
    10^(-3/20) for CriticalDamping, Bessel, ChebyshevI, and 1/sqrt(2) for Butterworth, as
    in MSL), ``init`` (Init, MSL's default SteadyState). Design data, given at construction
    (the coefficients are computed from them then, as MSL computes them at initialization;
    build a new block to change them): ``order`` (default 2), ``f_cut`` [Hz] (required),
    ``A_ripple`` [dB] (ChebyshevI's pass band ripple, default 0.5, > 0), ``f_min`` [Hz]
    (band filters: the band is f_min .. f_cut, both at -3 dB). Parameters: gain (amplitude
    at zero frequency), u_nominal (scale of the states).

    MSL's realization (acausal.components.filter_design computes its coefficients exactly
    as MSL's Internal.Filter functions): real poles r, der(x) = r·(x − uu); conjugate
    complex pairs a ± j·b, der(x1) = a·x1 − b·x2 + ku·uu, der(x2) = b·x1 + a·x2, in
    series from uu = u/u_nominal; each section's output feeds the next: low pass x (x2),
    high pass uu − x (k1·x1 + k2·x2 + uu), band pass k1·x1 + k2·x2, band stop
    k1·x1 + k2·x2 + uu; y = gain·u_nominal·(the last output). States ``x[1]`` ..
    ``x[nx]`` (nx = order, band filters 2·order); MSL's output connectors x are not
    declared (read the states by name).

    Initialization (``init``): SteadyState der(x) = 0; NoInit and InitialState start at
    x = x_start (constructor argument, nx values); InitialOutput: y = y_start and
    der(x[1:nx−1]) = 0.

    Band filters as MSL 4.1 computes them: a band pass's sections have the numerator
    cn·s, cn = w_band·w_cut, without the base filter's c0 (cr), so its gain in the band is
    1 only where those are 1 (Butterworth); a band stop's two sections of a complex pair
    have the zeros s² + c0 of their own c0 (w_cut²/alpha², w_cut²·alpha²), not the double
    zero at w_cut of the exact transformation (exact for real poles: order 1). A band
    transformation that gives real poles (a wide band over CriticalDamping's real poles) is
    refused, as MSL's assert does.
    """
    _starts = ("x_start", "y_start")
    options = {"analogFilter": AnalogFilter.CriticalDamping, "filterType": FilterType.LowPass,
               "normalized": True, "init": Init.SteadyState}
    gain = Parameter(1.0, "1", "gain (= amplitude of frequency response at zero frequency)")
    u_nominal = Parameter(1.0, "", "nominal value of input (used for scaling the states)",
                          positive=True)

    def __init__(self, name: str | None = None, *, order: int = 2, f_cut: float | None = None,
                 A_ripple: float = 0.5, f_min: float = 0.0, **params):
        kind = "Filter" + (f" '{name}'" if name else "")
        given = params.get("filterType", FilterType.LowPass)
        band = given in (FilterType.BandPass, FilterType.BandStop, "BandPass", "BandStop")
        self.__dict__["order"] = _order(kind, "order", order)
        self.__dict__["nx"] = 2 * order if band else order
        super().__init__(name, **params)
        if f_cut is None:
            raise ParameterError(f"{kind}: f_cut (cut-off frequency [Hz]) has no default (as "
                                 f"in MSL); give it: Filter(f_cut=...)")
        f_cut, A_ripple, f_min = (_start(v, f"{kind}: {n}") for v, n in (
            (f_cut, "f_cut"), (A_ripple, "A_ripple"), (f_min, "f_min")))
        if f_cut <= 0:
            raise ParameterError(f"{kind}: f_cut (cut-off frequency) must be > 0 [Hz], got "
                                 f"{f_cut}")
        if A_ripple <= 0:
            raise ParameterError(f"{kind}: A_ripple (pass band ripple of ChebyshevI) must be "
                                 f"> 0 [dB] (MSL asserts it for every analogFilter), got "
                                 f"{A_ripple}")
        if band and not 0 < f_min < f_cut:
            raise ParameterError(f"{kind}: a {self.filterType.value} filter passes/stops the "
                                 f"band f_min .. f_cut: give 0 < f_min < f_cut [Hz], got "
                                 f"f_min = {f_min}, f_cut = {f_cut}")
        if self.analogFilter is AnalogFilter.Bessel:
            _order(kind, "order", order, BESSEL_MAX_ORDER)
        self.__dict__.update(f_cut=f_cut, A_ripple=A_ripple, f_min=f_min)
        base = base_filter(self.analogFilter, self.order, self.normalized, A_ripple)
        try:
            roots = filter_roots(base, self.filterType, f_cut, f_min)
        except ValueError as err:
            raise ParameterError(f"{kind}: {err} for a {self.filterType.value} filter (f_min "
                                 f"= {f_min}, f_cut = {f_cut})") from None
        self.__dict__["roots"] = roots

    def _start_size(self, name: str) -> int | None:
        return self.nx if name == "x_start" else None

    @property
    def initType(self) -> Init:
        """The initialization (the option ``init``)."""
        return self.init

    def structure(self, s):
        for i in range(self.nx):
            s.state(f"x[{i + 1}]", self.x_start[i], description="filter states")

    def physics(self, e):
        r, a, b, ku, k1, k2 = self.roots
        kind = self.filterType
        x = [e.state(f"x[{i + 1}]") for i in range(self.nx)]
        uu, der = e.input(self.u) / self.u_nominal, []
        for ri, xi in zip(r, x):
            der.append(ri * (xi - uu))
            uu = xi if kind is FilterType.LowPass else uu - xi
        for i in range(len(a)):
            x1, x2 = x[len(r) + 2 * i], x[len(r) + 2 * i + 1]
            der += [a[i] * x1 - b[i] * x2 + ku[i] * uu, b[i] * x1 + a[i] * x2]
            if kind is FilterType.LowPass:
                uu = x2
            elif kind is FilterType.BandPass:
                uu = k1[i] * x1 + k2[i] * x2
            else:
                uu = k1[i] * x1 + k2[i] * x2 + uu
        for xi, dx in zip(x, der):
            e.derivative(xi, dx)
        y = self.gain * self.u_nominal * uu
        e.output(self.y, y)
        names = [f"x[{i + 1}]" for i in range(self.nx)]
        _initial_equations(e, self, dict(zip(names, der)), {"y = y_start": y - self.y_start},
                           steady_output=tuple(names[:-1]))


# ---- more math and nonlinear blocks (Modelica.Blocks.Math, Modelica.Blocks.Nonlinear) ----------
#: The smallest positive normal double: Log and Log10 evaluate at max(u, _TINY).
_TINY = 2.2250738585072014e-308


def _sign(e, u, events: bool, width):
    """MSL's ``if u > 0 then 1 elseif u < 0 then -1 else 0``: with ``events`` the mode
    ``region`` of a limiter at [0, 0] (its indicators ``upper`` and ``lower`` locate where u
    crosses 0); in smooth form u/sqrt(u² + width²); else the plain expression (noEvent)."""
    if e.smooth:
        return u / ca.sqrt(u ** 2 + width ** 2)
    if not events:
        return ca.sign(u)
    _limited(e, u, 0, 0, width, True)
    return e.mode("region")


class _Signed(SISO):
    """Abs and Sign: MSL's option ``generateEvent`` (False: noEvent, the plain expression;
    True: state events where u crosses 0, the mode ``region`` = sign(u) between them) and,
    in smooth form, sign(u) ≈ u/sqrt(u² + u_smooth²)."""
    options = {"generateEvent": False}
    u_smooth = Parameter(1e-3, "", "smooth form only: width over which sign(u) is rounded at "
                                   "u = 0", positive=True)

    def structure(self, s):
        _limiter_region(s, self.generateEvent)

    def sign(self, e):
        """sign(u), with the events or in the smooth form that go with it."""
        return _sign(e, e.input(self.u), self.generateEvent, self.u_smooth)


class Abs(_Signed):
    """y = |u| (MSL Math.Abs: ``if u >= 0 then u else -u``). Option ``generateEvent``
    (MSL's default False: no events, the integrator's step control resolves the kink; True:
    state events where u crosses 0, so the kink is located; y = |u| all the same, also at
    an event's left limit, where u may be past 0 by the event tolerance: y is never
    negative, e.g. under a Sqrt). Smooth form (``compile(model, smooth=True)``):
    y = u·u/sqrt(u² + u_smooth²), below |u| by at most 0.3003·u_smooth (at |u| ≈
    0.786·u_smooth), by u_smooth²/(2|u|) far from 0."""

    def physics(self, e):
        u, sign = e.input(self.u), self.sign(e)
        e.output(self.y, u * sign if e.smooth else ca.fabs(u))


class Sign(_Signed):
    """y = sign(u): 1 if u > 0, −1 if u < 0, 0 if u = 0 (MSL Math.Sign). Option
    ``generateEvent`` as Abs's. Smooth form: y = u/sqrt(u² + u_smooth²), off by
    u_smooth²/(2u²) far from 0."""

    def physics(self, e):
        e.output(self.y, self.sign(e))


class _Function(SISO):
    """y = f(u) (``function``). Where MSL requires u in a domain (``domain``: the condition,
    its message, u clipped into the domain) the requirement is an assertion: simulate()
    stops with a SimulationError naming the block, the message and the first output time
    where u is outside (``PhysicsBuilder.assertion``), and f is evaluated at the clipped u,
    so the equations stay finite (no NaN in the integrator) up to there; a violation that
    begins and ends between two output times passes unseen."""

    def function(self, u):
        raise NotImplementedError

    def domain(self, u) -> tuple | None:
        """(condition on u, what MSL requires, u clipped into the domain), or None."""
        return None

    def physics(self, e):
        u = e.input(self.u)
        required = self.domain(u)
        if required is not None:
            holds, what, u = required
            e.assertion(holds, what)
        e.output(self.y, self.function(u))


class Sqrt(_Function):
    """y = sqrt(u), u ≥ 0 required (asserted) (MSL Math.Sqrt)."""

    def function(self, u):
        return ca.sqrt(u)

    def domain(self, u):
        return u >= 0, "the input of Sqrt must be >= 0", ca.fmax(u, 0)


class Sin(_Function):
    """y = sin(u), u [rad] (MSL Math.Sin)."""

    def function(self, u):
        return ca.sin(u)


class Cos(_Function):
    """y = cos(u), u [rad] (MSL Math.Cos)."""

    def function(self, u):
        return ca.cos(u)


class Tan(_Function):
    """y = tan(u), u [rad] (MSL Math.Tan)."""

    def function(self, u):
        return ca.tan(u)


class Asin(_Function):
    """y = asin(u) [rad], |u| ≤ 1 required (asserted) (MSL Math.Asin)."""

    def function(self, u):
        return ca.asin(u)

    def domain(self, u):
        return ca.fabs(u) <= 1, "the input of Asin must be within [-1, 1]", _limit(u, -1, 1)


class Acos(_Function):
    """y = acos(u) [rad], |u| ≤ 1 required (asserted) (MSL Math.Acos)."""

    def function(self, u):
        return ca.acos(u)

    def domain(self, u):
        return ca.fabs(u) <= 1, "the input of Acos must be within [-1, 1]", _limit(u, -1, 1)


class Atan(_Function):
    """y = atan(u) [rad] in [−π/2, π/2] (MSL Math.Atan)."""

    def function(self, u):
        return ca.atan(u)


class Sinh(_Function):
    """y = sinh(u) (MSL Math.Sinh)."""

    def function(self, u):
        return ca.sinh(u)


class Cosh(_Function):
    """y = cosh(u) (MSL Math.Cosh)."""

    def function(self, u):
        return ca.cosh(u)


class Tanh(_Function):
    """y = tanh(u) (MSL Math.Tanh)."""

    def function(self, u):
        return ca.tanh(u)


class Exp(_Function):
    """y = exp(u) (MSL Math.Exp)."""

    def function(self, u):
        return ca.exp(u)


class Power(_Function):
    """y = base^u (MSL Math.Power): with ``useExp`` (MSL's default True) written
    exp(u·log(base)), base > 0 required (checked at construction); without, base^u, where a
    base ≤ 0 needs an integer u (asserted; outside, y is NaN, not clipped: the assertion
    stops a simulation where y is an output only, the integrator fails first where it
    feeds a state)."""
    options = {"useExp": True}
    base = Parameter(math.e, "", "base of power")

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        if self.useExp and not self.base > 0:
            raise ParameterError(f"{who(self)}: base must be > 0 with useExp=True (y = "
                                 f"exp(u*log(base))), got {self.base}; give base > 0 or "
                                 f"useExp=False")

    def function(self, u):
        return ca.exp(u * ca.log(self.base)) if self.useExp else self.base ** u

    def domain(self, u):
        if self.useExp:
            return None
        return (ca.logic_or(self.base > 0, u == ca.floor(u)),
                "Power: base^u with base <= 0 needs an integer input u", u)


class Exponentiation(_Function):
    """y = u^exponent (MSL Math.Exponentiation); a u < 0 needs an integer exponent, u = 0
    an exponent ≥ 0 (asserted; outside, y is NaN or infinite, not clipped, as for
    Power)."""
    exponent = Parameter(2.0, "", "exponent of power")

    def function(self, u):
        return u ** self.exponent

    def domain(self, u):
        p = self.exponent
        integer = p == ca.floor(p)
        return (ca.logic_and(ca.logic_or(u >= 0, integer), ca.logic_or(u != 0, p >= 0)),
                "Exponentiation: u^exponent needs u >= 0 or an integer exponent, and u != 0 "
                "for an exponent < 0", u)


class Log(_Function):
    """y = log(u)/log(base) (MSL Math.Log: natural logarithm by default), u > 0 required
    (asserted); base > 0 and ≠ 1 (checked at construction)."""
    base = Parameter(math.e, "", "base of logarithm")

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        if not (self.base > 0 and self.base != 1):
            raise ParameterError(f"{who(self)}: base must be > 0 and != 1, got {self.base}")

    def function(self, u):
        return ca.log(u) / ca.log(self.base)

    def domain(self, u):
        return u > 0, "the input of Log must be > 0", ca.fmax(u, _TINY)


class Log10(_Function):
    """y = log10(u), u > 0 required (asserted) (MSL Math.Log10)."""

    def function(self, u):
        return ca.log10(u)

    def domain(self, u):
        return u > 0, "the input of Log10 must be > 0", ca.fmax(u, _TINY)


class Atan2(SI2SO):
    """y = atan2(u1, u2) [rad] in [−π, π], the angle of the point (u2, u1) (MSL Math.Atan2;
    u1 = u2 = 0 gives 0)."""

    def physics(self, e):
        e.output(self.y, ca.atan2(e.input(self.u1), e.input(self.u2)))


class Max(SI2SO):
    """y = max(u1, u2) (MSL Math.Max: Modelica's max, no events; the integrator's step
    control resolves the kink, also in smooth form)."""

    def physics(self, e):
        e.output(self.y, ca.fmax(e.input(self.u1), e.input(self.u2)))


class Min(SI2SO):
    """y = min(u1, u2) (MSL Math.Min: no events, as Max)."""

    def physics(self, e):
        e.output(self.y, ca.fmin(e.input(self.u1), e.input(self.u2)))


def _size(value, what: str, least: int) -> int:
    """A block's size given at construction, as int (a ParameterError otherwise)."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < least:
        raise ParameterError(f"{what} must be an integer >= {least}, got {value!r}")
    return int(value)


class _MultiInput(_Sized, Component):
    """A block with ``nu`` inputs ``u[1]`` .. ``u[nu]`` (constructor argument; MSL's
    connectorSizing counts them), its class made per nu (MSL PartialRealMISO)."""
    _classes: dict = {}
    _least = 1

    def __new__(cls, name=None, *, nu: int = 1, **params):
        return super().__new__(cls._variant(_size(nu, f"{cls.__name__}: nu (number of "
                                                      f"inputs)", cls._least)))

    @staticmethod
    def _declare(nu: int) -> dict:
        return {"u": VectorPort(RealInput, nu, tuple(f"connector of Real input signal {i}"
                                                      for i in range(1, nu + 1)))}

    def __init__(self, name: str | None = None, *, nu: int = 1, **params):
        super().__init__(name, **params)

    @property
    def nu(self) -> int:
        """Number of inputs."""
        return self._key[0]

    def inputs(self, e) -> list:
        return [e.input(p) for p in self.u]


class MultiSum(_MultiInput, SO):
    """y = k[1]·u[1] + ... + k[nu]·u[nu] (MSL Math.MultiSum). ``nu`` (constructor argument,
    ≥ 1) inputs ``u[1]`` .. ``u[nu]``; the gains, the vector parameter ``k`` (``k[1]`` ..
    ``k[nu]``, default 1; ``k=[...]`` at construction, ``params={"<name>.k": [...]}`` at
    simulation time)."""
    _classes: dict = {}

    @staticmethod
    def _declare(nu: int) -> dict:
        return {**_MultiInput._declare(nu), "k": Parameter((1.0,) * nu, "", "input gains")}

    def __init__(self, name: str | None = None, *, nu: int = 1, k=None, **params):
        if k is not None:                   # a number is every input's gain
            params["k"] = tuple(np.ravel(k)) if np.ndim(k) else (k,) * self.nu
        super().__init__(name, **params)

    def physics(self, e):
        e.output(self.y, sum((self.k[i] * u for i, u in enumerate(self.inputs(e))),
                             ca.SX(0)))


class MultiProduct(_MultiInput, SO):
    """y = u[1]·u[2]·...·u[nu] (MSL Math.MultiProduct); ``nu`` (constructor argument, ≥ 1)
    inputs ``u[1]`` .. ``u[nu]``."""
    _classes: dict = {}

    def physics(self, e):
        y = ca.SX(1)
        for u in self.inputs(e):
            y = y * u
        e.output(self.y, y)


class MinMax(_MultiInput):
    """The largest and the smallest of the inputs (MSL Math.MinMax): yMax = max(u),
    yMin = min(u) (no events); ``nu`` (constructor argument, ≥ 1) inputs ``u[1]`` ..
    ``u[nu]``."""
    _classes: dict = {}
    yMax = RealOutput("maximal element of u")
    yMin = RealOutput("minimal element of u")

    def physics(self, e):
        u = self.inputs(e)
        e.output(self.yMax, _vmax(u))
        e.output(self.yMin, -_vmax([-v for v in u]))


class MatrixGain(_Sized, Component):
    """y = K·u (MSL Math.MatrixGain): ``K`` (nout × nin, given at construction; MSL's
    default [1, 0; 0, 1]) fixes the block's sizes, its values are the parameter ``K``
    (``K[1]`` .. ``K[nout·nin]``, row by row as StateSpace's matrices; ``params={"<name>.K":
    matrix}`` changes them at simulation time). Inputs ``u[1]`` .. ``u[nin]``, outputs
    ``y[1]`` .. ``y[nout]``."""
    _classes: dict = {}

    def __new__(cls, name=None, *, K=((1.0, 0.0), (0.0, 1.0)), **params):
        return super().__new__(cls._variant(*_matrix(K, f"{cls.__name__}: K").shape))

    @staticmethod
    def _declare(nout: int, nin: int) -> dict:
        return {"K": Parameter((0.0,) * (nout * nin), "", f"gain matrix which is multiplied "
                                                          f"with the input ({nout} x {nin}, "
                                                          f"row by row)"),
                "u": VectorPort(RealInput, nin, "connector of Real input signals"),
                "y": VectorPort(RealOutput, nout, "connector of Real output signals")}

    def __init__(self, name: str | None = None, *, K=((1.0, 0.0), (0.0, 1.0)), **params):
        super().__init__(name, K=tuple(_matrix(K, f"{type(self).__name__}: K").ravel()),
                         **params)

    @property
    def nout(self) -> int:
        """Number of outputs, the rows of K."""
        return self._key[0]

    @property
    def nin(self) -> int:
        """Number of inputs, the columns of K."""
        return self._key[1]

    def physics(self, e):
        K = ca.reshape(self.K, self.nin, self.nout).T
        y = K @ ca.vertcat(*(e.input(p) for p in self.u))
        for i, port in enumerate(self.y):
            e.output(port, y[i])


class _Sampled(_StartValues, SISO):
    """What Mean and RootMeanSquare share: MSL Math.Mean's equations (see Mean) for a
    signal v under the names ``<prefix>integral``, ``<prefix>integral_last``,
    ``<prefix>x``, ``<prefix>y_last``."""
    f = Parameter(50.0, "Hz", "base frequency", positive=True)
    _prefix = ""

    def structure(self, s):
        from .logical import refuse_smooth          # logical builds on this module
        refuse_smooth(self, s)
        p = self._prefix
        s.sample("sampleTrigger", 1 / self.f, 1 / self.f,
                 description="true at the sample instants k/f")
        s.mode("sampled", 0, values=(0, 1),
               description="true, once the integral is read at the present sample instant")
        s.state(f"{p}integral", self.x0, description="integral of the averaged signal from the "
                                                     "start (with x0)")
        s.discrete(f"{p}integral_last", 0.0, description="integral at the last sample instant")
        s.discrete(f"{p}y_last", self._y_start(), description="last sampled mean value")

    def _y_start(self) -> float:
        return self.y0

    def mean(self, e, v, nonnegative: bool):
        """The sampled mean of v over the last period (y_last), its equations written."""
        p = self._prefix
        trigger, sampled = e.mode("sampleTrigger"), e.mode("sampled")
        e.mode_update(sampled, trigger)
        first = ca.logic_and(trigger, ca.logic_not(sampled))
        integral, last, y_last = (e.state(f"{p}integral"), e.mode(f"{p}integral_last"),
                                  e.mode(f"{p}y_last"))
        e.derivative(integral, v)
        y_new = self.f * (integral - last)
        e.mode_update(y_last, ca.if_else(first, ca.fmax(0, y_new) if nonnegative else y_new,
                                         y_last))
        e.mode_update(last, ca.if_else(first, integral, last))
        e.variable(f"{p}x", integral - last, description="integrator state (reset at the "
                                                         "sample instants)")
        return y_last


class Mean(_Sampled):
    """The mean of u over each period 1/f [Hz] (MSL Math.Mean): y = f·∫u dt over the last
    full period, updated at the instants k/f (time events), held in between; y = y0 before
    the first. Option ``yGreaterOrEqualZero`` (y = max(0, ...), for a mean ≥ 0 in exact
    arithmetic). Start values (constructor arguments): x0 (the integrator's state, so the
    first mean is f·(x0 + ∫u dt)), y0. MSL's equations::

        der(x) = u
        when sample(t0 + 1/f, 1/f) then
          y_last = f·pre(x)     (max(0, f·pre(x)) with yGreaterOrEqualZero)
          reinit(x, 0)
        end when
        y = y_last

    with x = x0 and y_last = y0 at the start. A sample instant reinitializes no state
    here, so the state is ``integral`` = ∫u dt (starting at x0), never reset; the discrete
    variable ``integral_last`` keeps its value at the last instant (0 before the first),
    and MSL's x = integral − integral_last is recorded (so is ``y_last``). The mode
    ``sampled`` tells the event iteration's first round at an instant (where the integral
    is read) from the next ones, as the discrete blocks' ``sampled`` does. Refused in
    smooth form (the output changes at events only).

    MSL differences: the instants are counted from time 0 (MSL's t0 is the simulation's
    start: a simulation started at t > 0 has the same instants k/f, its first period cut
    short); the integral over the whole run, not over one period, is the state, so its
    error control is relative to the integral's magnitude (for a long run of an input with
    a large mean, tighten rtol).
    """
    _starts = ("x0", "y0")
    options = {"yGreaterOrEqualZero": False}

    def physics(self, e):
        e.output(self.y, self.mean(e, e.input(self.u), self.yGreaterOrEqualZero))


class RootMeanSquare(_Sampled):
    """The root mean square of u over each period 1/f [Hz] (MSL Math.RootMeanSquare):
    y = sqrt(mean.y), mean.y the Mean (with yGreaterOrEqualZero) of u·u, updated at the
    instants k/f, held in between; y = y0 (≥ 0) before the first. Start values
    (constructor arguments): x0 (the state of the Mean of u², MSL's mean.x0), y0 (≥ 0; the
    Mean of u² starts at y0²). The equations are Mean's (see Mean), recorded under MSL's
    names of the inner Mean: ``mean.x``, ``mean.y_last``, ``mean.y`` (and
    ``mean.integral``, ``mean.integral_last``)."""
    _starts = ("x0", "y0")
    _prefix = "mean."

    def __init__(self, name: str | None = None, **kwargs):
        super().__init__(name, **kwargs)
        if self.y0 < 0:
            raise ParameterError(f"{who(self)}: y0 (start value of the output, a root mean "
                                 f"square) must be >= 0, got {self.y0}")

    def _y_start(self) -> float:
        return self.y0 ** 2

    def physics(self, e):
        u = e.input(self.u)
        mean = self.mean(e, u * u, True)
        e.variable("mean.y", mean, description="mean of u*u over the last period")
        e.output(self.y, ca.sqrt(mean))


class SlewRateLimiter(_StartValues, _Limiting):
    """Limits the slew rate of a signal (MSL Nonlinear.SlewRateLimiter): the input
    differentiated with time constant Td [s], the rate limited to [Falling, Rising] [1/s]::

        val = (u − y)/Td
        der(y) = if val < Falling then Falling else if val > Rising then Rising else val

    Parameters: Rising [1/s] (> 0, default 1), Falling [1/s] (< 0; default −Rising, MSL's
    binding: it follows Rising, also at simulation time, unless given at construction, which
    makes it a parameter of its own), Td [s] (> 0, default 0.001); u_smooth [1/s] (smooth
    form only). Option ``strict``: events and smooth form as Limiter's (mode ``region``,
    indicators ``upper``, ``lower`` on val; ``val`` is recorded). Initialization
    (``initType``, MSL's default SteadyState): SteadyState: y = u; InitialState and
    InitialOutput: y = y_start; NoInit: y starts at y_start (constructor argument).
    """
    _starts = ("y_start",)
    options = {"initType": Init.SteadyState, "strict": False}
    Rising = Parameter(1.0, "1/s", "maximum rising slew rate [+small..+inf)", positive=True)
    Td = Parameter(0.001, "s", "derivative time constant", positive=True)
    _with_Falling: type | None = None

    def __new__(cls, name=None, **params):
        own = cls.__dict__.get("_with_Falling") if "Falling" in params else None
        return super().__new__(own or cls)

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        if not self.Falling < 0:
            raise ParameterError(f"{who(self)}: Falling (maximum falling slew rate) must be "
                                 f"< 0, got {self.Falling}")

    @property
    def Falling(self):
        """Maximum falling slew rate [1/s]: −Rising (MSL's binding)."""
        return -self.Rising

    def structure(self, s):
        super().structure(s)
        s.state("y", self.y_start, description="output (state)")

    def physics(self, e):
        y, u = e.state("y"), e.input(self.u)
        val = (u - y) / self.Td
        e.variable("val", val, "1/s", "rate of the input differentiated with time constant Td")
        e.derivative(y, self.limited(e, val, self.Falling, self.Rising))
        e.output(self.y, y)
        if self.initType is Init.SteadyState:
            e.initial(y - u, "y = u (initType=SteadyState)")
        elif self.initType in (Init.InitialState, Init.InitialOutput):
            e.initial(y - self.y_start, f"y = y_start (initType={self.initType.value})")


class _SlewRateLimiterFalling(SlewRateLimiter):
    """SlewRateLimiter with Falling given at construction: a parameter of its own."""
    Falling = Parameter(-1.0, "1/s", "maximum falling slew rate (-inf..-small]")


_SlewRateLimiterFalling.__name__ = "SlewRateLimiter"
SlewRateLimiter._with_Falling = _SlewRateLimiterFalling


def pade_polynomials(T, n: int, m: int) -> tuple[list, list]:
    """The Padé approximant of exp(−T·s) of numerator order m and denominator order n
    (MSL Nonlinear.PadeDelay's padeCoefficients2): (b, a), the coefficients of the numerator
    and the denominator, highest power of s first (a[−1] = b[−1] = 1), of a number or a
    CasADi expression T [s]. Its Taylor expansion at s = 0 matches exp(−T·s) up to order
    n + m."""
    a, b = [1], [1]
    for i in range(1, n + 1):
        a.append(a[-1] * (T * ((n - i + 1) / (n + m - i + 1)) / i))
        if i <= m:
            b.append(-b[-1] * (T * ((m - i + 1) / (n + m - i + 1)) / i))
    return b[::-1], a[::-1]


def balance_abc(A: np.ndarray, B: np.ndarray, C: np.ndarray) -> np.ndarray:
    """MSL Modelica.Math.Matrices.balanceABC: the scaling (powers of 2, so no round-off)
    T = diag(scale) such that [T⁻¹·A·T, T⁻¹·B; C·T, 0] is better conditioned than
    [A, B; C, 0] (EISPACK's balance on the system matrix)."""
    As, Bs, Cs = (np.array(M, dtype=float) for M in (A, B, C))
    n = As.shape[0]
    scale, radix = np.ones(n), 2.0
    again = True
    while again:
        again = False
        for i in range(n):
            co = np.abs(As[:, i]).sum() - abs(As[i, i]) + np.abs(Cs[:, i]).sum()
            ro = np.abs(As[i, :]).sum() - abs(As[i, i]) + np.abs(Bs[i, :]).sum()
            g, f, s = ro / radix, 1.0, co + ro
            while not (co >= g or co == 0):
                f, co = f * radix, co * radix ** 2
            g = ro * radix
            while not (co < g or ro == 0):
                f, co = f / radix, co / radix ** 2
            if not (co + ro) / f >= 0.95 * s:
                scale[i] *= f
                As[i, :] /= f
                As[:, i] *= f
                Bs[i, :] /= f
                Cs[:, i] *= f
                again = True
    return scale


class PadeDelay(_Sized, SISO):
    """Padé approximation of a delay y(t) ≈ u(t − delayTime) (MSL Nonlinear.PadeDelay): the
    transfer function b(s)/a(s) of ``pade_polynomials(delayTime, n, m)``, whose Taylor
    expansion matches exp(−delayTime·s) up to order n + m, in MSL's controller canonical
    form::

        der(x[1]) = a1·x + b11·u
        der(x[i]) = s[i−1]·x[i−1],  i = 2..n
        y = c·x + d·u

    with a1 = −a[2:n+1]/a[1], b11 = 1/a[1], c = bb[2:n+1] − d·a[2:n+1], d = bb[1]/a[1]
    (bb: b padded with zeros to n + 1), s = 1; with ``balance=True`` (MSL recommends it)
    the states scaled by ``balance_abc`` (scale), a1 = a1·scale/scale[1], b11/scale[1],
    c·scale, s[i] = scale[i]/scale[i+1]. delayTime [s] (> 0) is a parameter (changeable
    at simulation time: the coefficients are expressions of it); ``n`` (≥ 1, default 1) and
    ``m`` (1 ≤ m ≤ n, default n) are constructor arguments, ``balance`` an option.
    States ``x[1]`` .. ``x[n]``. Initialization (MSL's initial equations): with balance
    der(x) = 0 (steady state); without, x[n] = u, the other states at 0.

    MSL differences: the balancing scale is computed from the delayTime given at
    construction (MSL: at initialization): a delayTime changed at simulation time keeps
    that scale (the same transfer function, other states than MSL's).
    """
    options = {"balance": False}
    delayTime = Parameter(1.0, "s", "delay time of output with respect to input signal",
                          positive=True)
    _classes: dict = {}

    def __new__(cls, name=None, *, n: int = 1, m: int | None = None, **params):
        what = cls.__name__
        n = _size(n, f"{what}: n (order of the denominator)", 1)
        m = n if m is None else _size(m, f"{what}: m (order of the numerator)", 1)
        if m > n:
            raise ParameterError(f"{what}: m (order of the numerator, {m}) must be <= n (order "
                                 f"of the denominator, {n}); usually m = n or m = n - 1")
        return super().__new__(cls._variant(n, m))

    @staticmethod
    def _declare(n: int, m: int) -> dict:
        return {}

    def __init__(self, name: str | None = None, *, n: int = 1, m: int | None = None,
                 **params):
        super().__init__(name, **params)
        n = self.n
        scale = np.ones(n)
        if self.balance:
            a1, b11, c, _, _ = self.coefficients(self.delayTime, np.ones(n))
            A = np.diag(np.ones(n - 1), -1)
            A[0, :] = a1
            B = np.zeros((n, 1))
            B[0, 0] = b11
            scale = balance_abc(A, B, np.reshape(c, (1, n)))
        self.__dict__["scale"] = tuple(scale)

    @property
    def n(self) -> int:
        """Order of the denominator, the number of states."""
        return self._key[0]

    @property
    def m(self) -> int:
        """Order of the numerator."""
        return self._key[1]

    def coefficients(self, T, scale) -> tuple:
        """(a1, b11, c, d, s) of MSL's padeCoefficients2 for delay time T [s] (a number or
        an expression) and the states' scaling ``scale`` (n numbers)."""
        n = self.n
        b, a = pade_polynomials(T, n, self.m)
        bb = [0] * (n - self.m) + b
        d = bb[0] / a[0]
        a1 = [-a[i + 1] / a[0] * scale[i] / scale[0] for i in range(n)]
        c = [(bb[i + 1] - d * a[i + 1]) * scale[i] for i in range(n)]
        s = [scale[i] / scale[i + 1] for i in range(n - 1)]
        return a1, 1 / (a[0] * scale[0]), c, d, s

    def structure(self, s):
        for i in range(1, self.n + 1):
            s.state(f"x[{i}]", 0.0, description="state of the transfer function in (balanced) "
                                                "controller canonical form")

    def physics(self, e):
        u = e.input(self.u)
        x = [e.state(f"x[{i}]") for i in range(1, self.n + 1)]
        a1, b11, c, d, s = self.coefficients(self.delayTime, self.scale)
        der = [sum((ai * xi for ai, xi in zip(a1, x)), b11 * u)] + \
            [si * xi for si, xi in zip(s, x[:-1])]
        for xi, dx in zip(x, der):
            e.derivative(xi, dx)
        e.output(self.y, sum((ci * xi for ci, xi in zip(c, x)), d * u))
        if self.balance:
            for i, dx in enumerate(der, start=1):
                e.initial(dx, f"der(x[{i}]) = 0 (balance=true)")
        else:
            e.initial(x[-1] - u, "x[n] = u (balance=false)")
