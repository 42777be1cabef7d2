"""Temperatures in degree Rankine, after Modelica.Thermal.HeatTransfer.Rankine: the
conversion blocks ToKelvin and FromKelvin, and the temperature sources and sensor of
``thermal`` with their signals and parameters in degRk (heat ports stay in K):
K = 5/9·degRk.

A module of its own, named as MSL's package (as ``celsius``), so that MSL's class names stay
as they are: ``rankine.FixedTemperature(T=527.67)`` reads as MSL's
``Rankine.FixedTemperature(T=527.67)``.

Difference from the MSL: TemperatureSensor's output T has no unit there; here it is in
degRk, as the package's other signals.
"""
from __future__ import annotations

from ..core import Parameter, RealInput, RealOutput
from .temperature_scales import (RANKINE, _FixedTemperature, _FromKelvin,
                                 _PrescribedTemperature, _TemperatureSensor, _ToKelvin)

__all__ = ["ToKelvin", "FromKelvin", "TemperatureSensor", "FixedTemperature",
           "PrescribedTemperature"]


class ToKelvin(_ToKelvin):
    """Conversion from degree Rankine to Kelvin: Kelvin = 5/9·Rankine."""
    scale = RANKINE
    Rankine = RealInput("temperature [degRk]")
    Kelvin = RealOutput("temperature [K]")


class FromKelvin(_FromKelvin):
    """Conversion from Kelvin to degree Rankine: Rankine = 9/5·Kelvin."""
    scale = RANKINE
    Kelvin = RealInput("temperature [K]")
    Rankine = RealOutput("temperature [degRk]")


class TemperatureSensor(_TemperatureSensor):
    """Absolute temperature T [degRk] of ``port``; no heat flow."""
    scale = RANKINE
    T = RealOutput("absolute temperature in degree Rankine as output signal [degRk]")


class FixedTemperature(_FixedTemperature):
    """Fixed temperature boundary condition in degree Rankine: port.T = 5/9·T [K].
    Required: T [degRk] (MSL gives no default)."""
    scale = RANKINE
    T = Parameter(527.67, "degRk", "fixed temperature at the port")


class PrescribedTemperature(_PrescribedTemperature):
    """Variable temperature boundary condition in degree Rankine: port.T = 5/9·T [K], the
    input T [degRk]."""
    scale = RANKINE
    T = RealInput("temperature at port [degRk]")
