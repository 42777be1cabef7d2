"""Parameter: a named, documented constant of a component, a CasADi symbol once compiled."""
from __future__ import annotations

import copy
from contextlib import contextmanager
from contextvars import ContextVar

import numpy as np

from ..errors import ParameterError
from ..numerics import parameter_problem

#: While a model is compiled: component -> {parameter name: CasADi symbol}. Held by the
#: compiler for the duration of one compile (``symbolic_parameters``), never on a component.
_SYMBOLS: ContextVar[dict | None] = ContextVar("acausal_parameter_symbols", default=None)


@contextmanager
def symbolic_parameters(table: dict):
    """Within the block, the parameters of the components in ``table`` (component -> {name:
    symbol}) read as their symbols; the components themselves are left untouched."""
    token = _SYMBOLS.set(table)
    try:
        yield table
    finally:
        _SYMBOLS.reset(token)


class Parameter:
    """A component parameter, declared as a class attribute.

    ``default`` is the value used when none is given (a number, or a tuple for a vector
    parameter such as a position r: its elements are the parameters ``r[1]``, ``r[2]``);
    ``unit`` is the SI unit (text);
    ``positive`` requires the value to be > 0; ``nonnegative`` ≥ 0; ``nonzero`` requires it to
    be different from 0 (gear ratios, radii). ``structural_zero`` (with nonnegative): the
    value 0 changes the equations (Mass.m = 0 is a massless flange, MSL's min = 0): a
    component built with 0 is compiled with the parameter fixed at 0 (the terms it multiplies
    vanish, so its coordinate becomes an algebraic variable; it is then not a parameter of
    the compiled model), one built with a value > 0 keeps it > 0 there.

    On an instance the attribute reads as the numeric value; while the instance is being
    compiled (``symbolic_parameters``) it reads as the CasADi symbol that stands for it, so
    the equations a component writes keep the parameter symbolic and it can be changed at
    simulation time.
    """

    def __init__(self, default, unit: str = "", description: str = "", *,
                 positive: bool = False, nonzero: bool = False, nonnegative: bool = False,
                 structural_zero: bool = False):
        self.size = None if isinstance(default, (int, float)) else len(default)
        self.default = float(default) if self.size is None else tuple(map(float, default))
        self.unit = unit
        self.description = description
        self.positive = positive
        self.nonzero = nonzero
        self.nonnegative = nonnegative
        self.structural_zero = structural_zero
        self.name = ""
        self.owner = ""

    def __set_name__(self, owner, name):
        self.name, self.owner = name, getattr(owner, "__name__", "")

    def __repr__(self):
        where = f"{self.owner}.{self.name}" if self.owner else self.name or "?"
        value = self.default if self.size is None else list(self.default)
        bounds = ", ".join(k for k, on in (("> 0", self.positive), (">= 0", self.nonnegative),
                                           ("!= 0", self.nonzero)) if on)
        return (f"<Parameter {where} = {value}" + (f" [{self.unit}]" if self.unit else "")
                + (f" ({bounds})" if bounds else "")
                + (f": {self.description}" if self.description else "") + ">")

    def __get__(self, instance, owner=None):
        if instance is None:
            return self
        table = _SYMBOLS.get()
        symbols = table.get(instance) if table is not None else None
        if symbols is not None:
            return symbols[self.name]
        return instance.__dict__["_values"][self.name]

    def __set__(self, instance, value):
        instance.__dict__["_values"][self.name] = self.check(value, instance)

    def element_names(self) -> list[str]:
        """Names of the scalar parameters this one stands for: ``r[1]``, ``r[2]`` for a
        vector (Modelica's numbering), the name itself for a scalar."""
        if self.size is None:
            return [self.name]
        return [f"{self.name}[{i + 1}]" for i in range(self.size)]

    def check(self, value, where):
        """The value as float (a tuple of them for a vector), or a ParameterError naming
        ``where`` (a component or a name)."""
        if self.size is not None and not isinstance(value, (int, float, str)):
            try:
                items = list(value)
            except TypeError:
                items = None
            if items is None or len(items) != self.size:
                raise ParameterError(f"parameter '{_label(where)}.{self.name}' takes "
                                     f"{self.size} values, got {value!r}")
            return tuple(self.check_scalar(v, where, i) for i, v in enumerate(items, 1))
        if self.size is not None:
            raise ParameterError(f"parameter '{_label(where)}.{self.name}' takes {self.size} "
                                 f"values, got {value!r}")
        return self.check_scalar(value, where)

    def check_scalar(self, value, where, element: int | None = None) -> float:
        """One value as float, or a ParameterError naming ``where.name`` (``where.name[i]``
        for ``element`` i of a vector): the one rule for a parameter's value, wherever it is
        set (construction, compile, simulate, FMUs)."""
        name = f"{_label(where)}.{self.name}" + (f"[{element}]" if element else "")
        return checked_value(name, value, self.rule, self.description or self.name, self.unit)

    def compiled(self, value: float) -> "Parameter | None":
        """The declaration whose rule a compiled model built with ``value`` applies: this
        one; for a ``structural_zero`` parameter None at 0 (fixed there) and a copy requiring
        > 0 otherwise (a value of 0 would need other equations: compile again)."""
        if not self.structural_zero:
            return self
        if value == 0.0:
            return None
        out = copy.copy(self)
        out.positive, out.nonnegative = True, False
        return out

    @property
    def rule(self) -> dict[str, bool]:
        """The declared range: ``positive``, ``nonnegative``, ``nonzero``."""
        return {"positive": self.positive, "nonnegative": self.nonnegative,
                "nonzero": self.nonzero}


def checked_value(name: str, value, rule: dict, description: str = "", unit: str = "") -> float:
    """``value`` as float if it is a number that keeps ``rule`` (``Parameter.rule``), else a
    ParameterError naming the parameter ``name`` (text and booleans are no numbers, even
    where Python would convert them)."""
    try:
        if isinstance(value, (str, bytes, bool, np.bool_)):
            raise TypeError
        v = float(value)
    except (TypeError, ValueError):
        raise ParameterError(f"parameter '{name}' must be a number, got {value!r}") from None
    problem = parameter_problem(name, v, description, unit, **rule)
    if problem:
        raise ParameterError(problem)
    return v


def _label(where) -> str:
    return where if isinstance(where, str) else getattr(where, "path", type(where).__name__)
