"""Input and Output: the top-level signal interface of a model.

An ``Input`` becomes an input of the compiled model (a value given at simulation time, an FMU
input, an OCP control), named by its instance path; an ``Output`` becomes an output. The
model's own RealInput / RealOutput connectors (class attributes of a Model subclass, what
makes it a block to connect in a bigger model) are inputs and outputs too, by their names,
when that model is the one compiled: Modelica's top-level connectors.
"""
from __future__ import annotations

from .component import Component
from .ports import RealInput, RealOutput


class Input(Component):
    """A model input: its value ``y`` is given from outside (constant, function of time, samples).

    ``start`` is the value used when simulate() is not given one; ``unit`` and ``description``
    document it (and become FMU attributes).
    """
    y = RealOutput("the input value")

    def __init__(self, name: str | None = None, *, start: float = 0.0, unit: str = "",
                 description: str = ""):
        super().__init__(name)
        self.__dict__.update(start=float(start), unit=unit, description=description)

    def physics(self, e):
        e.output(self.y, e.model_input(self))


class Output(Component):
    """A model output: records the signal connected to ``u`` under this instance's name."""
    u = RealInput("the output value")

    def __init__(self, name: str | None = None, *, unit: str = "", description: str = ""):
        super().__init__(name)
        self.__dict__.update(unit=unit, description=description)

    def physics(self, e):
        e.model_output(self, e.input(self.u))
