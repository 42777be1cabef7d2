"""The interfaces of the blocks (Modelica.Blocks.Interfaces: SO, SISO, SI2SO) and what the
blocks of every module share: start values, sized classes, initialization (``Init``), the
refusal of a smooth form by blocks whose output changes at events only (``refuse_smooth``, for
the logical, discrete and electrical switching blocks too)."""
from __future__ import annotations

import math
from enum import Enum

import casadi as ca
import numpy as np

from ...core import BooleanInput, Component, Parameter, RealInput, RealOutput, VectorPort
from ...core.component import who
from ...errors import ParameterError, StructureError


#: Modelica.Constants.eps: the smallest relative difference the MSL blocks distinguish.
EPS = 1e-15


class SO(Component):
    """Single output ``y``."""
    partial = True
    y = RealOutput("connector of Real output signal")


class SISO(SO):
    """Single input ``u``, single output ``y``."""
    partial = True
    u = RealInput("connector of Real input signal")


class SI2SO(SO):
    """Two inputs ``u1``, ``u2``, single output ``y``."""
    partial = True
    u1 = RealInput("connector of Real input signal 1")
    u2 = RealInput("connector of Real input signal 2")


class SignalSource(SO):
    """A source y = offset + (``before()`` before startTime, else ``signal(time)``).

    Subclasses implement ``signal(t)``: the value without offset at time t ≥ startTime [s],
    and ``before()`` if it is not 0.
    """
    partial = True
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


def refuse_smooth(block: Component, builder) -> None:
    """A StructureError when the model is compiled in smooth form (``builder.smooth``) and
    ``block`` has no smooth form (its output changes at events only)."""
    if builder.smooth:
        raise StructureError(
            f"{who(block)} has no smooth form: its output is a discrete value that changes "
            f"at events only; compile without smooth=True, or write the switching law as a "
            f"smooth expression (e.g. a tanh blend) for optimal control")


def _start(value, what: str) -> float:
    """A start value given to a constructor, as float (a ParameterError otherwise)."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ParameterError(f"{what} must be a number, got {value!r}") from None
    if not math.isfinite(v):
        raise ParameterError(f"{what} must be finite, got {v}")
    return v


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
                "__qualname__": base.__qualname__, "_key": key,
                "partial": base.__dict__.get("partial", False), **base._declare(*key)})
        return base._classes[key]

    def __reduce_ex__(self, protocol):
        return _new_sized, (type(self).__bases__[0], self._key), self.__dict__


def _new_sized(base: type, key: tuple) -> Component:
    """An empty instance of the sized block class ``base`` made for ``key`` (unpickling)."""
    return object.__new__(base._variant(*key))


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


def _size(value, what: str, least: int) -> int:
    """A block's size given at construction, as int (a ParameterError otherwise)."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < least:
        raise ParameterError(f"{what} must be an integer >= {least}, got {value!r}")
    return int(value)


class _MultiInput(_Sized, Component):
    """A block with ``nu`` inputs ``u[1]`` .. ``u[nu]`` (constructor argument; MSL's
    connectorSizing counts them) of the port class ``_input``, its class made per nu (MSL
    PartialRealMISO, PartialBooleanMISO)."""
    _classes: dict = {}
    _least = 1
    _input: type = RealInput

    def __new__(cls, name=None, *, nu: int = 1, **params):
        return super().__new__(cls._variant(_size(nu, f"{cls.__qualname__}: nu (number of "
                                                      f"inputs)", cls._least)))

    @classmethod
    def _declare(cls, nu: int) -> dict:
        kind = "Boolean" if issubclass(cls._input, BooleanInput) else "Real"
        return {"u": VectorPort(cls._input, nu, tuple(f"connector of {kind} input signal {i}"
                                                       for i in range(1, nu + 1)))}

    def __init__(self, name: str | None = None, *, nu: int = 1, **params):
        super().__init__(name, **params)

    @property
    def nu(self) -> int:
        """Number of inputs."""
        return self._key[0]

    def inputs(self, e) -> list:
        return [e.input(p) for p in self.u]
