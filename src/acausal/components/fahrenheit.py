"""Temperatures in degree Fahrenheit, after Modelica.Thermal.HeatTransfer.Fahrenheit: the
conversion blocks ToKelvin and FromKelvin, and the temperature sources and sensor of
``thermal`` with their signals and parameters in degF (heat ports stay in K):
K = (degF − 32)·5/9 + 273.15.

A module of its own, named as MSL's package (as ``celsius``), so that MSL's class names stay
as they are: ``fahrenheit.FixedTemperature(T=68)`` reads as MSL's
``Fahrenheit.FixedTemperature(T=68)``.

Difference from the MSL: TemperatureSensor's output T has no unit there; here it is in
degF, as the package's other signals.
"""
from __future__ import annotations

from ..core import Parameter, RealInput, RealOutput
from .temperature_scales import (FAHRENHEIT, _FixedTemperature, _FromKelvin,
                                 _PrescribedTemperature, _TemperatureSensor, _ToKelvin)

__all__ = ["ToKelvin", "FromKelvin", "TemperatureSensor", "FixedTemperature",
           "PrescribedTemperature"]


class ToKelvin(_ToKelvin):
    """Conversion from degree Fahrenheit to Kelvin: Kelvin = (Fahrenheit − 32)·5/9 + 273.15."""
    scale = FAHRENHEIT
    Fahrenheit = RealInput("temperature [degF]")
    Kelvin = RealOutput("temperature [K]")


class FromKelvin(_FromKelvin):
    """Conversion from Kelvin to degree Fahrenheit: Fahrenheit = (Kelvin − 273.15)·9/5 + 32."""
    scale = FAHRENHEIT
    Kelvin = RealInput("temperature [K]")
    Fahrenheit = RealOutput("temperature [degF]")


class TemperatureSensor(_TemperatureSensor):
    """Absolute temperature T [degF] of ``port``; no heat flow."""
    scale = FAHRENHEIT
    T = RealOutput("absolute temperature in degree Fahrenheit as output signal [degF]")


class FixedTemperature(_FixedTemperature):
    """Fixed temperature boundary condition in degree Fahrenheit: port.T = (T − 32)·5/9 +
    273.15 [K]. Required: T [degF] (MSL gives no default)."""
    scale = FAHRENHEIT
    T = Parameter(68.0, "degF", "fixed temperature at the port")


class PrescribedTemperature(_PrescribedTemperature):
    """Variable temperature boundary condition in degree Fahrenheit: port.T = (T − 32)·5/9
    + 273.15 [K], the input T [degF]."""
    scale = FAHRENHEIT
    T = RealInput("temperature at port [degF]")
