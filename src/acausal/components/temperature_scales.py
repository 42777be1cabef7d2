"""Temperature scales besides Kelvin, and what MSL's packages Celsius, Fahrenheit and Rankine
of Modelica.Thermal.HeatTransfer share: each is the same five classes (ToKelvin, FromKelvin,
TemperatureSensor, FixedTemperature, PrescribedTemperature) with its signals and parameter in
its own unit, the heat ports staying in K.

A scale is affine in Kelvin (MSL's Modelica.Units.Conversions): K = factor·(T − zero), with
``zero`` the scale's reading at absolute zero and ``factor`` the kelvins per degree. The
partial classes below hold the equations once; ``celsius``, ``fahrenheit`` and ``rankine``
declare MSL's classes on them with the scale and MSL's connectors and parameter (in the
scale's unit).
"""
from __future__ import annotations

from dataclasses import dataclass

from ..core import Component, HeatPort_a
from .thermal import _Temperature

__all__ = ["TemperatureScale", "CELSIUS", "FAHRENHEIT", "RANKINE"]


@dataclass(frozen=True)
class TemperatureScale:
    """An affine temperature scale: K = factor·(T − zero)."""
    name: str           # MSL's name of the conversion blocks' connector ("Celsius")
    unit: str           # MSL's NonSI unit ("degC")
    zero: float         # absolute zero on this scale [unit]
    factor: float       # kelvins per degree of this scale [K/unit]

    def to_kelvin(self, T):
        """The temperature T [unit] in K (MSL's from_degC, from_degF, from_degRk)."""
        return self.factor * (T - self.zero)

    def from_kelvin(self, T):
        """The temperature T [K] in this scale's unit (MSL's to_degC, to_degF, to_degRk)."""
        return T / self.factor + self.zero


#: degree Celsius: K = degC + 273.15 (Modelica.Constants.T_zero = −273.15 degC)
CELSIUS = TemperatureScale("Celsius", "degC", -273.15, 1.0)
#: degree Fahrenheit: K = (degF − 32)·5/9 + 273.15
FAHRENHEIT = TemperatureScale("Fahrenheit", "degF", -459.67, 5 / 9)
#: degree Rankine: K = 5/9·degRk
RANKINE = TemperatureScale("Rankine", "degRk", 0.0, 5 / 9)


class _ToKelvin(Component):
    """Kelvin = the input (the connector named as the scale) converted to K."""
    partial = True
    scale: TemperatureScale

    def physics(self, e):
        e.output(self.Kelvin, self.scale.to_kelvin(e.input(getattr(self, self.scale.name))))


class _FromKelvin(Component):
    """The output (the connector named as the scale) = the input Kelvin in the scale."""
    partial = True
    scale: TemperatureScale

    def physics(self, e):
        e.output(getattr(self, self.scale.name), self.scale.from_kelvin(e.input(self.Kelvin)))


class _TemperatureSensor(Component):
    """T = port.T in the scale; no heat flow."""
    partial = True
    scale: TemperatureScale
    port = HeatPort_a("heat port")

    def physics(self, e):
        e.flow(self.port, 0.0)
        e.output(self.T, self.scale.from_kelvin(e.potential(self.port)))


class _FixedTemperature(_Temperature):
    """port.T = the parameter T [scale's unit] in K."""
    partial = True
    scale: TemperatureScale
    required = ("T",)

    def _T(self, e):
        return self.scale.to_kelvin(self.T)


class _PrescribedTemperature(_Temperature):
    """port.T = the input T [scale's unit] in K."""
    partial = True
    scale: TemperatureScale

    def _T(self, e):
        return self.scale.to_kelvin(e.input(self.T))
