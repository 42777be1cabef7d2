"""Parameter: a named, documented constant of a component, a CasADi symbol once compiled."""
from __future__ import annotations

from .errors import ParameterError


class Parameter:
    """A component parameter, declared as a class attribute.

    ``default`` is the value used when none is given; ``unit`` is the SI unit (text);
    ``positive`` requires the value to be > 0 (masses, inertias); ``nonzero`` requires it to be
    different from 0 (gear ratios, radii).

    On an instance the attribute reads as the numeric value; while the instance is being
    compiled it reads as the CasADi symbol that stands for it, so the equations a component
    writes keep the parameter symbolic and it can be changed at simulation time.
    """

    def __init__(self, default: float, unit: str = "", description: str = "", *,
                 positive: bool = False, nonzero: bool = False, nonnegative: bool = False):
        self.default = float(default)
        self.unit = unit
        self.description = description
        self.positive = positive
        self.nonzero = nonzero
        self.nonnegative = nonnegative
        self.name = ""

    def __set_name__(self, owner, name):
        self.name = name

    def __get__(self, instance, owner=None):
        if instance is None:
            return self
        symbols = instance.__dict__.get("_symbols")
        if symbols is not None:
            return symbols[self.name]
        return instance.__dict__["_values"][self.name]

    def __set__(self, instance, value):
        instance.__dict__["_values"][self.name] = self.check(value, instance)

    def check(self, value, where) -> float:
        """The value as float, or a ParameterError naming ``where`` (a component or a name)."""
        try:
            v = float(value)
        except (TypeError, ValueError):
            raise ParameterError(f"parameter '{_label(where)}.{self.name}' must be a number, "
                                 f"got {value!r}") from None
        if self.positive and not v > 0:
            raise ParameterError(f"parameter '{_label(where)}.{self.name}' must be > 0 "
                                 f"({self.description or self.name}), got {v}")
        if self.nonnegative and not v >= 0:
            raise ParameterError(f"parameter '{_label(where)}.{self.name}' must be >= 0 "
                                 f"({self.description or self.name}), got {v}")
        if self.nonzero and v == 0:
            raise ParameterError(f"parameter '{_label(where)}.{self.name}' must not be 0 "
                                 f"({self.description or self.name})")
        return v


def _label(where) -> str:
    return where if isinstance(where, str) else getattr(where, "path", type(where).__name__)
