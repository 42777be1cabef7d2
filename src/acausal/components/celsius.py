"""Temperatures in degree Celsius, after Modelica.Thermal.HeatTransfer.Celsius: the
conversion blocks ToKelvin and FromKelvin, and the temperature sources and sensor of
``thermal`` with their signals and parameters in degC (heat ports stay in K).

A module of its own, named as MSL's package, so that MSL's class names stay as they are
without shadowing thermal's Kelvin classes of the same names: ``celsius.FixedTemperature(T=20)``
reads as MSL's ``Celsius.FixedTemperature(T=20)``, ``thermal.FixedTemperature(T=293.15)`` as
``Sources.FixedTemperature``. MSL's Fahrenheit and Rankine packages (the same classes in
other units) are not here.
"""
from __future__ import annotations

from ..core import Component, HeatPort_a, Parameter, RealInput, RealOutput
from .thermal import _Temperature

__all__ = ["ToKelvin", "FromKelvin", "TemperatureSensor", "FixedTemperature",
           "PrescribedTemperature", "T_ZERO"]

#: Absolute zero temperature [degC], Modelica.Constants.T_zero: K = degC − T_ZERO
T_ZERO = -273.15


class ToKelvin(Component):
    """Conversion from degree Celsius to Kelvin: Kelvin = Celsius − T_ZERO."""
    Celsius = RealInput("temperature [degC]")
    Kelvin = RealOutput("temperature [K]")

    def physics(self, e):
        e.output(self.Kelvin, e.input(self.Celsius) - T_ZERO)


class FromKelvin(Component):
    """Conversion from Kelvin to degree Celsius: Celsius = Kelvin + T_ZERO."""
    Kelvin = RealInput("temperature [K]")
    Celsius = RealOutput("temperature [degC]")

    def physics(self, e):
        e.output(self.Celsius, e.input(self.Kelvin) + T_ZERO)


class TemperatureSensor(Component):
    """Absolute temperature T [degC] of ``port``; no heat flow."""
    port = HeatPort_a("heat port")
    T = RealOutput("absolute temperature in degree Celsius as output signal [degC]")

    def physics(self, e):
        e.flow(self.port, 0.0)
        e.output(self.T, e.potential(self.port) + T_ZERO)


class FixedTemperature(_Temperature):
    """Fixed temperature boundary condition in degree Celsius: port.T = T − T_ZERO [K].
    Required: T [degC] (MSL gives no default)."""
    required = ("T",)
    T = Parameter(20.0, "degC", "fixed temperature at the port")

    def _T(self, e):
        return self.T - T_ZERO


class PrescribedTemperature(_Temperature):
    """Variable temperature boundary condition in degree Celsius: port.T = T − T_ZERO [K],
    the input T [degC]."""
    T = RealInput("temperature at port [degC]")

    def _T(self, e):
        return e.input(self.T) - T_ZERO
