"""Sources (Modelica.Blocks.Sources): signals of time, tables, point-to-point motion."""
from __future__ import annotations

from enum import Enum
from functools import reduce

import casadi as ca
import numpy as np

from ...core import (BooleanOutput, Component, ConditionalPort, Parameter, RealInput,
                     RealOutput, Unavailable, VectorPort)
from ...core.component import BoundParameters, bound_twin, who
from ...errors import ParameterError
from .interfaces import EPS, SignalSource, _Sized, SO, _start


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
        sd_inv = reduce(ca.fmax, [ca.fabs(d / v) for d, v in zip(dq, self._vector("qd_max"))])
        sdd_inv = reduce(ca.fmax, [ca.fabs(d / a) for d, a in zip(dq, self._vector("qdd_max"))])
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


class ContinuousClock(SignalSource):
    """The current time: y = offset + (0 before startTime, else time − startTime)."""

    def signal(self, t):
        return t - self.startTime


class Exponentials(BoundParameters, SignalSource):
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


bound_twin(Exponentials, "fallTimeConst",
           Parameter(0.1, "s", "fall time constant", positive=True))


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


class _VariableFrequencyWave(Component):
    """The logic of MSL's ...VariableFrequencyAndAmplitude sources (Blocks.Sources and
    Electrical.Analog.Sources): offset + amplitude·wave(phi) with der(phi) = 2π·f, the
    phase phi [rad] a state (start ``phi_start``); the amplitude the input named
    ``_amplitude`` or constantAmplitude (``useConstantAmplitude``), f [Hz] the input ``f``
    or constantFrequency (``useConstantFrequency``). ``wave`` is sin or cos; each source
    declares the parameters and inputs in its units."""
    options = {"useConstantAmplitude": False, "useConstantFrequency": False}
    _amplitude: str
    wave: staticmethod

    def __init__(self, name: str | None = None, phi_start: float = 0.0, **params):
        super().__init__(name, **params)
        self.__dict__["phi_start"] = _start(phi_start, f"{type(self).__name__}: phi_start")

    def structure(self, s):
        s.state("phi", self.phi_start, "rad", "phase of the sine wave")

    def _wave_value(self, e):
        """offset + amplitude·wave(phi), with der(phi) = 2π·f."""
        phi = e.state("phi")
        f = self.constantFrequency if self.useConstantFrequency else e.input(self.f)
        amplitude = (self.constantAmplitude if self.useConstantAmplitude
                     else e.input(getattr(self, self._amplitude)))
        e.derivative(phi, 2 * ca.pi * f)
        return self.offset + amplitude * self.wave(phi)


class _VariableFrequencyAndAmplitude(_VariableFrequencyWave, SO):
    """y = offset + amplitude·wave(phi), der(phi) = 2π·f: the phase phi [rad] (a state,
    start value ``phi_start``, MSL's phi(start = 0)) integrates the frequency, so a
    changing f changes the wave's rate without a jump. amplitude and f [Hz] are the inputs
    of those names, or with ``useConstantAmplitude`` / ``useConstantFrequency`` the
    parameters constantAmplitude / constantFrequency (the input is then absent). No
    startTime (MSL): an amplitude of 0 keeps y at offset."""
    constantAmplitude = Parameter(1.0, "", "constant amplitude")
    constantFrequency = Parameter(1.0, "Hz", "constant frequency")
    offset = Parameter(0.0, "", "offset of the sine wave")
    amplitude = ConditionalPort(RealInput("amplitude"), "useConstantAmplitude", False)
    f = ConditionalPort(RealInput("frequency [Hz]"), "useConstantFrequency", False)
    _amplitude = "amplitude"

    def physics(self, e):
        e.output(self.y, self._wave_value(e))


class SineVariableFrequencyAndAmplitude(_VariableFrequencyAndAmplitude):
    __doc__ = ("Sine with variable frequency and amplitude (MSL "
               "Sources.SineVariableFrequencyAndAmplitude): "
               + _VariableFrequencyAndAmplitude.__doc__.replace("wave(phi)", "sin(phi)", 1))
    wave = staticmethod(ca.sin)


class CosineVariableFrequencyAndAmplitude(_VariableFrequencyAndAmplitude):
    __doc__ = ("Cosine with variable frequency and amplitude (MSL "
               "Sources.CosineVariableFrequencyAndAmplitude): "
               + _VariableFrequencyAndAmplitude.__doc__.replace("wave(phi)", "cos(phi)", 1))
    wave = staticmethod(ca.cos)


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
