"""Electrical sensors (after Modelica.Electrical.Analog.Sensors): potential, voltage, current,
power and the MultiSensor."""
from __future__ import annotations

from ...core import Component, NegativePin, PositivePin, RealOutput
from .interfaces import OnePort


class PotentialSensor(Component):
    """Potential of the pin p, phi = p.v [V] (MSL Sensors.PotentialSensor); no current."""
    p = PositivePin("pin to be measured")
    phi = RealOutput("absolute voltage potential as output signal [V]")

    def physics(self, e):
        e.flow(self.p, 0.0)
        e.output(self.phi, e.potential(self.p))


class VoltageSensor(OnePort):
    """Voltage between p and n, v = p.v − n.v [V]; no current."""
    v = RealOutput("voltage between pin p and n (= p.v - n.v) as output signal [V]")

    def physics(self, e):
        self._current(e, 0.0)
        e.output(self.v, self._v(e))


class CurrentSensor(OnePort):
    """Current from p to n, i = p.i [A]; no voltage drop (p.v = n.v)."""
    i = RealOutput("current in the branch from p to n as output signal [A]")

    def physics(self, e):
        i = self._current(e)
        e.residual(self._v(e))
        e.output(self.i, i)


class PowerSensor(Component):
    """Instantaneous power [W]: the current from pc to nc (no voltage drop there) times the
    voltage between pv and nv (no current there)."""
    pc = PositivePin("positive pin, current path")
    nc = NegativePin("negative pin, current path")
    pv = PositivePin("positive pin, voltage path")
    nv = NegativePin("negative pin, voltage path")
    power = RealOutput("instantaneous power as output signal [W]")

    def _current_and_voltage(self, e):
        """The current i from pc to nc [A] and the voltage pv.v − nv.v [V]."""
        i = e.flow_of(self.pc)
        e.flow(self.nc, -i)
        e.residual(e.potential(self.pc) - e.potential(self.nc))
        e.flow(self.pv, 0.0)
        e.flow(self.nv, 0.0)
        return i, e.potential(self.pv) - e.potential(self.nv)

    def physics(self, e):
        i, v = self._current_and_voltage(e)
        e.output(self.power, v * i)


class MultiSensor(PowerSensor):
    """The PowerSensor with its current and voltage as outputs too (MSL
    Sensors.MultiSensor): i = pc.i [A], v = pv.v − nv.v [V], power = v·i [W]."""
    i = RealOutput("current as output signal [A]")
    v = RealOutput("voltage as output signal [V]")

    def physics(self, e):
        i, v = self._current_and_voltage(e)
        e.output(self.i, i)
        e.output(self.v, v)
        e.output(self.power, v * i)
