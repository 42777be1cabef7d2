"""Temperatures in degree Celsius, after Modelica.Thermal.HeatTransfer.Celsius: the
conversion blocks ToKelvin and FromKelvin, and the temperature sources and sensor of
``thermal`` with their signals and parameters in degC (heat ports stay in K).

A module of its own, named as MSL's package, so that MSL's class names stay as they are
without shadowing thermal's Kelvin classes of the same names: ``celsius.FixedTemperature(T=20)``
reads as MSL's ``Celsius.FixedTemperature(T=20)``, ``thermal.FixedTemperature(T=293.15)`` as
``Sources.FixedTemperature``. MSL's Fahrenheit and Rankine packages are the modules
``fahrenheit`` and ``rankine``; the equations the three share are in ``temperature_scales``.
"""
from __future__ import annotations

from ..core import Parameter, RealInput, RealOutput
from .temperature_scales import (CELSIUS, _FixedTemperature, _FromKelvin,
                                 _PrescribedTemperature, _TemperatureSensor, _ToKelvin)

__all__ = ["ToKelvin", "FromKelvin", "TemperatureSensor", "FixedTemperature",
           "PrescribedTemperature", "T_ZERO"]

#: Absolute zero temperature [degC], Modelica.Constants.T_zero: K = degC − T_ZERO
T_ZERO = CELSIUS.zero


class ToKelvin(_ToKelvin):
    """Conversion from degree Celsius to Kelvin: Kelvin = Celsius − T_ZERO."""
    scale = CELSIUS
    Celsius = RealInput("temperature [degC]")
    Kelvin = RealOutput("temperature [K]")


class FromKelvin(_FromKelvin):
    """Conversion from Kelvin to degree Celsius: Celsius = Kelvin + T_ZERO."""
    scale = CELSIUS
    Kelvin = RealInput("temperature [K]")
    Celsius = RealOutput("temperature [degC]")


class TemperatureSensor(_TemperatureSensor):
    """Absolute temperature T [degC] of ``port``; no heat flow."""
    scale = CELSIUS
    T = RealOutput("absolute temperature in degree Celsius as output signal [degC]")


class FixedTemperature(_FixedTemperature):
    """Fixed temperature boundary condition in degree Celsius: port.T = T − T_ZERO [K].
    Required: T [degC] (MSL gives no default)."""
    scale = CELSIUS
    T = Parameter(20.0, "degC", "fixed temperature at the port")


class PrescribedTemperature(_PrescribedTemperature):
    """Variable temperature boundary condition in degree Celsius: port.T = T − T_ZERO [K],
    the input T [degC]."""
    scale = CELSIUS
    T = RealInput("temperature at port [degC]")
