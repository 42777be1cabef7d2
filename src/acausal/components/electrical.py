"""Analog electrical components after Modelica.Electrical.Analog (Basic, Sources, Sensors).

Pins carry the potential v [V] and the current i [A] flowing into the pin (MSL's sign); a
connection set has one potential and its currents sum to zero (Kirchhoff), as compiled by
``acausal.compiler.networks``. A two-pin element (MSL's ``OnePort``) has v = p.v − n.v and
the current i = p.i flowing from p through the element to n (n.i = −i). Start values of
the states are constructor keywords (``Capacitor(C=1e-3, v_start=5)``, MSL's
``v(start=5)``), like ``x0`` at simulation.

A circuit needs a ``Ground``; a loop of capacitors and voltage sources, or a node fed only
by inductors and current sources, is a higher-index network, refused when compiled with
an error naming its parts.
"""
from __future__ import annotations

import casadi as ca

from ..core import (Component, ConditionalPort, HeatPort_a, NegativePin, Parameter, Pin,
                    PositivePin, RealInput, RealOutput)
from . import rotational, translational
from .signals import _start

__all__ = ["Ground", "OnePort", "Resistor", "Conductor", "Capacitor", "Inductor",
           "RotationalEMF", "EMF", "TranslationalEMF", "ConstantVoltage", "SignalVoltage", "StepVoltage",
           "SineVoltage", "ConstantCurrent", "SignalCurrent", "VoltageSensor", "CurrentSensor",
           "PowerSensor"]


class Ground(Component):
    """Ground node: p.v = 0 [V]; its current p.i [A] is what the circuit returns to ground."""
    p = Pin("pin to be grounded")

    def physics(self, e):
        e.flow_of(self.p)
        e.residual(e.potential(self.p))


class OnePort(Component):
    """Two pins p, n with v = p.v − n.v [V] and i = p.i = −n.i [A] (MSL Interfaces.OnePort)."""
    p = PositivePin("positive electrical pin")
    n = NegativePin("negative electrical pin")

    def _v(self, e):
        return e.potential(self.p) - e.potential(self.n)

    def _current(self, e, value=None):
        """The current i from p to n: ``value`` if given (an explicit current), otherwise
        an unknown this component gives an equation for; n.i = −i."""
        i = e.flow_of(self.p) if value is None else value
        if value is not None:
            e.flow(self.p, i)
        e.flow(self.n, -i)
        return i

    def _record(self, e, v=None, i=None):
        if v is not None:
            e.variable("v", v, "V", "voltage drop of the two pins (= p.v - n.v)")
        if i is not None:
            e.variable("i", i, "A", "current flowing from pin p to pin n")


class _ConditionalHeatPort(Component):
    """MSL's ConditionalHeatPort: with ``useHeatPort`` the ``heatPort`` (HeatPort_a) takes
    the loss power LossPower [W] (heatPort.Q_flow = −LossPower) and sets the device
    temperature T_heatPort = heatPort.T; without it T_heatPort = T (a parameter)."""
    options = {"useHeatPort": False}
    heatPort = ConditionalPort(HeatPort_a("conditional heat port", required=True),
                               "useHeatPort")

    def _T_heatPort(self, e):
        return e.potential(self.heatPort) if self.useHeatPort else self.T

    def _losses(self, e, loss, T_heatPort):
        if self.useHeatPort:
            e.flow(self.heatPort, -loss)
        e.variable("LossPower", loss, "W", "loss power leaving component via heatPort")
        e.variable("T_heatPort", T_heatPort, "K", "temperature of heatPort")


class Resistor(_ConditionalHeatPort, OnePort):
    """Ideal linear resistor: v = R_actual·i, R_actual = R·(1 + alpha·(T_heatPort − T_ref))
    [Ohm]. ``T`` [K] is the fixed device temperature without heat port; it defaults to
    300.15 K, T_ref's default (MSL sets T = T_ref: give both if T_ref is changed)."""
    R = Parameter(1.0, "Ohm", "resistance at temperature T_ref")
    T_ref = Parameter(300.15, "K", "reference temperature", positive=True)
    alpha = Parameter(0.0, "1/K", "temperature coefficient of resistance (R_actual = "
                                  "R*(1 + alpha*(T_heatPort - T_ref)))")
    T = Parameter(300.15, "K", "fixed device temperature if useHeatPort = false",
                  positive=True)

    def physics(self, e):
        v, i, T = self._v(e), self._current(e), self._T_heatPort(e)
        R_actual = self.R * (1 + self.alpha * (T - self.T_ref))
        e.residual(v - R_actual * i)
        self._record(e, v, i)
        e.variable("R_actual", R_actual, "Ohm", "actual resistance = R*(1 + alpha*(T_heatPort "
                                                "- T_ref))")
        self._losses(e, v * i, T)


class Conductor(_ConditionalHeatPort, OnePort):
    """Ideal linear conductor: i = G_actual·v, G_actual = G/(1 + alpha·(T_heatPort − T_ref))
    [S]; ``T`` as for the Resistor."""
    G = Parameter(1.0, "S", "conductance at temperature T_ref")
    T_ref = Parameter(300.15, "K", "reference temperature", positive=True)
    alpha = Parameter(0.0, "1/K", "temperature coefficient of conductance (G_actual = "
                                  "G/(1 + alpha*(T_heatPort - T_ref)))")
    T = Parameter(300.15, "K", "fixed device temperature if useHeatPort = false",
                  positive=True)

    def physics(self, e):
        v, T = self._v(e), self._T_heatPort(e)
        G_actual = self.G / (1 + self.alpha * (T - self.T_ref))
        i = self._current(e, G_actual * v)
        self._record(e, v, i)
        e.variable("G_actual", G_actual, "S", "actual conductance = G/(1 + alpha*(T_heatPort "
                                              "- T_ref))")
        self._losses(e, v * i, T)


class Capacitor(OnePort):
    """Ideal capacitor: i = C·der(v); state v [V] (start ``v_start``, 0)."""
    C = Parameter(1.0, "F", "capacitance", positive=True)

    def __init__(self, name: str | None = None, *, v_start=0.0, **params):
        super().__init__(name, **params)
        self.__dict__["v_start"] = _start(v_start, f"{type(self).__name__}: v_start")

    def structure(self, s):
        s.state("v", self.v_start, "V", "voltage drop of the two pins (= p.v - n.v)")

    def physics(self, e):
        v, i = e.state("v"), self._current(e)
        e.residual(self._v(e) - v)
        e.derivative(v, i / self.C)
        self._record(e, i=i)


class Inductor(OnePort):
    """Ideal inductor: L·der(i) = v; state i [A] (start ``i_start``, 0)."""
    L = Parameter(1.0, "H", "inductance", positive=True)

    def __init__(self, name: str | None = None, *, i_start=0.0, **params):
        super().__init__(name, **params)
        self.__dict__["i_start"] = _start(i_start, f"{type(self).__name__}: i_start")

    def structure(self, s):
        s.state("i", self.i_start, "A", "current flowing from pin p to pin n")

    def physics(self, e):
        i, v = e.state("i"), self._v(e)
        self._current(e, i)
        e.derivative(i, v / self.L)
        self._record(e, v=v)


class _PartialEMF(OnePort):
    """Electromotoric force between the pins and a mechanical ``flange`` (with the optional
    ``support`` of the mechanical partial it is combined with): k·speed = v, the flange's
    flow −k·i, its reaction on the support (``useSupport``) or the ground; speed relative
    to the support."""

    def _record_motion(self, e, flow):
        raise NotImplementedError

    def physics(self, e):
        v, i = self._v(e), self._current(e)
        flow = -self.k * i
        e.residual(v - self.k * self._rel_speed(e, self.flange))
        self._apply_flange_flow(e, flow)
        self._record(e, v, i)
        self._record_motion(e, flow)


class RotationalEMF(rotational.PartialElementaryOneFlangeAndSupport2, _PartialEMF):
    """Electromotoric force, electrical to rotational (MSL Basic.RotationalEMF): k·w = v,
    tau = flange.tau = −k·i, the reaction k·i on the ``support`` (``useSupport``) or the
    ground. k [N.m/A] is the torque and the back-emf constant [V.s/rad]; w [rad/s] the
    flange's speed relative to the support. Records v, i, phi, w, tau, tauElectrical = k·i."""
    k = Parameter(1.0, "N.m/A", "transformation coefficient")

    def _record_motion(self, e, tau):
        self._record_relative(e, "s", "v")
        e.variable("tau", tau, "N.m", "torque of flange")
        e.variable("tauElectrical", -tau, "N.m", "electrical torque")


class TranslationalEMF(translational.PartialElementaryOneFlangeAndSupport2, _PartialEMF):
    """Electromotoric force, electrical to translational (MSL Basic.TranslationalEMF):
    k·vel = v, f = flange.f = −k·i, the reaction k·i on the ``support`` (``useSupport``) or
    the ground. k [N/A] is the force and the back-emf constant [V.s/m]; vel [m/s] the
    flange's velocity relative to the support. Records v, i, s, vel, f, fElectrical = k·i."""
    k = Parameter(1.0, "N/A", "transformation coefficient")

    def _record_motion(self, e, f):
        e.variable("s", self._rel_position(e, self.flange), "m",
                   "position of flange relative to support")
        e.variable("vel", self._rel_speed(e, self.flange), "m/s",
                   "velocity of flange relative to support")
        e.variable("f", f, "N", "force of flange")
        e.variable("fElectrical", -f, "N", "electrical force")


#: MSL 3's name of RotationalEMF
EMF = RotationalEMF


# ---- sources ------------------------------------------------------------------------------
class _VoltageSource(OnePort):
    """A voltage source: v = p.v − n.v given by ``_voltage``; its current i [A] (from p
    through the source to n) is an unknown of the circuit."""

    def _voltage(self, e):
        raise NotImplementedError

    def physics(self, e):
        v, i = self._voltage(e), self._current(e)
        e.residual(self._v(e) - v)
        self._record(e, v, i)


class ConstantVoltage(_VoltageSource):
    """Constant voltage source: v = V [V]."""
    V = Parameter(1.0, "V", "value of constant voltage")

    def _voltage(self, e):
        return self.V


class SignalVoltage(_VoltageSource):
    """Voltage source driven by the input ``v`` [V] (= p.v − n.v)."""
    v = RealInput("voltage between pin p and n (= p.v - n.v) as input signal [V]")

    def _voltage(self, e):
        return e.input(self.v)

    def _record(self, e, v=None, i=None):           # v is the input, recorded as a signal
        super()._record(e, None, i)


class _TimedVoltage(_VoltageSource):
    """MSL Interfaces.VoltageSource: v = offset + (0 if time < startTime else signal)."""
    offset = Parameter(0.0, "V", "voltage offset")
    startTime = Parameter(0.0, "s", "time offset")

    def _signal(self, t):
        raise NotImplementedError

    def _voltage(self, e):
        e.time_event(self.startTime)
        return self.offset + ca.if_else(e.time < self.startTime, 0,
                                        self._signal(e.time))


class StepVoltage(_TimedVoltage):
    """Step voltage source: v = offset + (0 if time < startTime else V) [V]."""
    V = Parameter(1.0, "V", "height of step")

    def _signal(self, t):
        return self.V


class SineVoltage(_TimedVoltage):
    """Sine voltage source: v = offset + V·sin(2π·f·(time − startTime) + phase) after
    startTime, offset before [V]."""
    V = Parameter(1.0, "V", "amplitude of sine wave")
    phase = Parameter(0.0, "rad", "phase of sine wave")
    f = Parameter(1.0, "Hz", "frequency of sine wave")

    def _signal(self, t):
        return self.V * ca.sin(2 * ca.pi * self.f * (t - self.startTime) + self.phase)


class ConstantCurrent(OnePort):
    """Constant current source: i = I [A] from p through the source to n."""
    I = Parameter(1.0, "A", "value of constant current")         # noqa: E741 (MSL's name)

    def physics(self, e):
        self._record(e, self._v(e), self._current(e, self.I))


class SignalCurrent(OnePort):
    """Current source driven by the input ``i`` [A] (from p through the source to n)."""
    i = RealInput("current flowing from pin p to pin n as input signal [A]")

    def physics(self, e):
        self._current(e, e.input(self.i))
        self._record(e, v=self._v(e))


# ---- sensors ------------------------------------------------------------------------------
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

    def physics(self, e):
        i = e.flow_of(self.pc)
        e.flow(self.nc, -i)
        e.residual(e.potential(self.pc) - e.potential(self.nc))
        e.flow(self.pv, 0.0)
        e.flow(self.nv, 0.0)
        e.output(self.power, (e.potential(self.pv) - e.potential(self.nv)) * i)
