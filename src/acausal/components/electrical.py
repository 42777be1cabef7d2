"""Analog electrical components after Modelica.Electrical.Analog (Basic, Ideal, Sources,
Sensors).

Pins carry the potential v [V] and the current i [A] flowing into the pin (MSL's sign); a
connection set has one potential and its currents sum to zero (Kirchhoff), as compiled by
``acausal.compiler.networks``. A two-pin element (MSL's ``OnePort``) has v = p.v − n.v and
the current i = p.i flowing from p through the element to n (n.i = −i). Start values of
the states are constructor keywords (``Capacitor(C=1e-3, v_start=5)``, MSL's
``v(start=5)``), like ``x0`` at simulation.

The timed sources (StepVoltage ... TrapezoidCurrent) are MSL's Interfaces.VoltageSource and
CurrentSource: offset + the waveform of the Modelica.Blocks.Sources block MSL redeclares,
evaluated by that block's own code in ``signals``, with its time events.

A circuit needs a ``Ground``; a loop of capacitors and voltage sources, or a node fed only
by inductors and current sources, is a higher-index network, refused when compiled with
an error naming its parts.

The ideal switching elements (IdealDiode, IdealThyristor, IdealGTOThyristor, the opening,
closing, two-way and intermediate switches) are MSL's parametric characteristics: an
auxiliary unknown s places each path on one of two straight segments, chosen by a Boolean
(a mode switched at state events for the semiconductors and the Controlled* switches, the
control input for the others); the modes have no smooth form.
"""
from __future__ import annotations

from types import MethodType

import casadi as ca
import numpy as np

from ..core import (BooleanInput, Component, ConditionalPort, HeatPort_a, NegativePin,
                    Parameter, Pin, PositivePin, RealInput, RealOutput, VectorPort)
from ..core.component import BoundParameters, bound_twin, who
from ..errors import ParameterError
from . import rotational, translational
from . import signals as sig
from .logical import refuse_smooth
from .signals.interfaces import EPS, _size, _Sized, _start
from .signals.sources import _check_table, _table_events, _table_values

__all__ = ["Ground", "OnePort", "TwoPort", "Resistor", "HeatingResistor", "Conductor",
           "VariableResistor", "VariableConductor", "Potentiometer", "Capacitor", "Inductor",
           "VariableCapacitor", "VariableInductor", "Transformer", "M_Transformer", "VCV",
           "VCC", "CCV", "CCC",
           "RotationalEMF", "EMF", "TranslationalEMF",
           "ConstantVoltage", "SignalVoltage", "StepVoltage", "RampVoltage", "SineVoltage",
           "CosineVoltage", "ExpSineVoltage", "PulseVoltage", "TrapezoidVoltage",
           "SawToothVoltage", "ExponentialsVoltage", "TableVoltage",
           "ConstantCurrent", "SignalCurrent", "StepCurrent", "RampCurrent", "SineCurrent",
           "CosineCurrent", "ExpSineCurrent", "PulseCurrent", "TrapezoidCurrent",
           "SawToothCurrent", "ExponentialsCurrent", "TableCurrent",
           "PotentialSensor", "VoltageSensor", "CurrentSensor", "PowerSensor", "MultiSensor",
           "IdealDiode", "IdealThyristor", "IdealGTOThyristor", "IdealOpeningSwitch",
           "IdealClosingSwitch", "ControlledIdealOpeningSwitch", "ControlledIdealClosingSwitch",
           "IdealTwoWaySwitch", "IdealCommutingSwitch", "ControlledIdealTwoWaySwitch",
           "ControlledIdealCommutingSwitch", "IdealIntermediateSwitch",
           "ControlledIdealIntermediateSwitch", "Short", "Idle",
           "IdealTransformer", "Gyrator", "NonlinearResistor", "IdealOpAmp",
           "IdealOpAmpLimited", "Diode", "ZDiode", "SaturatingInductor"]


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
    temperature T_heatPort = heatPort.T; without it T_heatPort = T, the fixed device
    temperature [K] each subclass declares as MSL binds it."""
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


class _TemperatureDependent(BoundParameters, _ConditionalHeatPort):
    """MSL's ConditionalHeatPort(T=T_ref) of the resistors and conductors: without heat
    port the device sits at T = T_ref [K], which follows T_ref also when T_ref is changed at
    simulation time (so R_actual = R, G_actual = G there); ``T`` given at construction is a
    parameter of its own (``Resistor(T=350)``, MSL's modifier: the class's twin declaring
    T, registered by ``_own_T``)."""
    T_ref = Parameter(300.15, "K", "reference temperature", positive=True)

    @property
    def T(self):
        """Fixed device temperature if useHeatPort = false [K]: T_ref (MSL's binding)."""
        return self.T_ref

    def _scale(self, e, T_heatPort):
        """1 + alpha·(T_heatPort − T_ref), which MSL asserts ≥ eps: simulate() stops with an
        error naming the component where it is not (``PhysicsBuilder.assertion``)."""
        scale = 1 + self.alpha * (T_heatPort - self.T_ref)
        e.assertion(scale >= EPS, "Temperature outside scope of model!")
        return scale


def _own_T(cls):
    """``cls`` with its twin whose T [K] is a parameter of its own (built by
    ``cls(T=...)``)."""
    return bound_twin(cls, "T", Parameter(300.15, "K", "fixed device temperature if "
                                          "useHeatPort = false", positive=True))


class _PartialResistor(_TemperatureDependent, OnePort):
    """The law of MSL's Resistor, v = R_actual·i, R_actual = R·(1 + alpha·(T_heatPort −
    T_ref)) [Ohm], for the Resistor, the VariableResistor and MSL 3's HeatingResistor,
    which give the resistance at T_ref differently (``_resistance``)."""
    alpha = Parameter(0.0, "1/K", "temperature coefficient of resistance (R_actual = "
                                  "R*(1 + alpha*(T_heatPort - T_ref)))")

    def physics(self, e):
        v, i, T = self._v(e), self._current(e), self._T_heatPort(e)
        R_actual = self._resistance(e) * self._scale(e, T)
        e.residual(v - R_actual * i)
        self._record(e, v, i)
        e.variable("R_actual", R_actual, "Ohm", "actual resistance = R*(1 + alpha*(T_heatPort "
                                                "- T_ref))")
        self._losses(e, v * i, T)


@_own_T
class Resistor(_PartialResistor):
    """Ideal linear resistor: v = R_actual·i, R_actual = R·(1 + alpha·(T_heatPort − T_ref))
    [Ohm]; T_heatPort [K] is heatPort.T with ``useHeatPort``, otherwise T, which is T_ref
    unless given (MSL's T = T_ref)."""
    R = Parameter(1.0, "Ohm", "resistance at temperature T_ref")

    def _resistance(self, e):
        return self.R


@_own_T
class VariableResistor(_PartialResistor):
    """Ideal linear resistor with variable resistance (MSL Basic.VariableResistor): the
    Resistor's law with R [Ohm] the input ``R``, R_actual = R·(1 + alpha·(T_heatPort −
    T_ref))."""
    R = RealInput("resistance at temperature T_ref as input signal [Ohm]")

    def _resistance(self, e):
        return e.input(self.R)


class _PartialConductor(_TemperatureDependent, OnePort):
    """The law of MSL's Conductor, i = G_actual·v, G_actual = G/(1 + alpha·(T_heatPort −
    T_ref)) [S], for the Conductor and the VariableConductor (``_conductance``)."""
    alpha = Parameter(0.0, "1/K", "temperature coefficient of conductance (G_actual = "
                                  "G/(1 + alpha*(T_heatPort - T_ref)))")

    def _conductance(self, e):
        raise NotImplementedError

    def physics(self, e):
        v, T = self._v(e), self._T_heatPort(e)
        G_actual = self._conductance(e) / self._scale(e, T)
        i = self._current(e, G_actual * v)
        self._record(e, v, i)
        e.variable("G_actual", G_actual, "S", "actual conductance = G/(1 + alpha*(T_heatPort "
                                              "- T_ref))")
        self._losses(e, v * i, T)


@_own_T
class Conductor(_PartialConductor):
    """Ideal linear conductor: i = G_actual·v, G_actual = G/(1 + alpha·(T_heatPort − T_ref))
    [S]; T_heatPort as for the Resistor."""
    G = Parameter(1.0, "S", "conductance at temperature T_ref")

    def _conductance(self, e):
        return self.G


@_own_T
class VariableConductor(_PartialConductor):
    """Ideal linear conductor with variable conductance (MSL Basic.VariableConductor): the
    Conductor's law with G [S] the input ``G``, G_actual = G/(1 + alpha·(T_heatPort −
    T_ref))."""
    G = RealInput("conductance at temperature T_ref as input signal [S]")

    def _conductance(self, e):
        return e.input(self.G)


@_own_T
class Potentiometer(_TemperatureDependent):
    """Adjustable resistor (MSL Basic.Potentiometer): the resistance R_actual = R·(1 +
    alpha·(T_heatPort − T_ref)) [Ohm] between pin_p and pin_n, split by the sliding
    ``contact`` at r ∈ [0, 1] (clipped; r = 0 at pin_n, 1 at pin_p): Rp = R_actual·(1 − r)
    between pin_p and contact, Rn = R_actual·r between contact and pin_n, so
    pin_p.v − contact.v = Rp·pin_p.i and pin_n.v − contact.v = Rn·pin_n.i, the three pin
    currents summing to zero. r is the parameter rConstant (in [0, 1]), or the input ``r``
    with the option ``useRinput``. T_ref defaults to 293.15 K here (MSL's). LossPower =
    (pin_p.v − contact.v)·pin_p.i + (pin_n.v − contact.v)·pin_n.i [W]. At r = 0 or 1 the
    contact is joined directly to a pin: a capacitor there is then in a loop with whatever
    fixes that pin's potential (give it a series resistance)."""
    options = {"useRinput": False}
    R = Parameter(1.0, "Ohm", "resistance at temperature T_ref")
    T_ref = Parameter(293.15, "K", "reference temperature", positive=True)
    alpha = Parameter(0.0, "1/K", "temperature coefficient of resistance (R_actual = "
                                  "R*(1 + alpha*(T_heatPort - T_ref)))")
    rConstant = Parameter(0.5, "1", "contact between n (r=0) and p (r=1)", nonnegative=True)
    pin_p = PositivePin("positive pin")
    contact = PositivePin("sliding contact")
    pin_n = NegativePin("negative pin")
    r = ConditionalPort(RealInput("contact between n (r=0) and p (r=1) as input signal [1]"),
                        "useRinput")

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        if self.rConstant > 1:
            raise ParameterError(f"parameter '{type(self).__name__}.rConstant' must be <= 1 "
                                 f"(contact between n (r=0) and p (r=1)), got {self.rConstant}")

    def physics(self, e):
        T = self._T_heatPort(e)
        r = e.input(self.r) if self.useRinput else self.rConstant
        r = ca.fmin(1, ca.fmax(0, r))
        R_actual = self.R * self._scale(e, T)
        Rp, Rn = R_actual * (1 - r), R_actual * r
        ip, i_n = e.flow_of(self.pin_p), e.flow_of(self.pin_n)
        e.flow(self.contact, -(ip + i_n))
        vp = e.potential(self.pin_p) - e.potential(self.contact)
        vn = e.potential(self.pin_n) - e.potential(self.contact)
        e.residual(vp - Rp * ip)
        e.residual(vn - Rn * i_n)
        e.variable("Rp", Rp, "Ohm", "actual resistance between pin_p and contact")
        e.variable("Rn", Rn, "Ohm", "actual resistance between contact and pin_n")
        self._losses(e, vp * ip + vn * i_n, T)


class HeatingResistor(_PartialResistor):
    """MSL 3's Basic.HeatingResistor, which MSL 4 converts to its Resistor with
    useHeatPort=true (ConvertModelica_from_3.2.3_to_4.0.0.mos: class HeatingResistor ->
    Resistor, parameter R_ref -> R): the Resistor's law (``_PartialResistor``) with its
    ``heatPort`` always present and MSL 3's parameter names, R_ref [Ohm] the resistance at
    T_ref [K], alpha [1/K]: R_actual = R_ref·(1 + alpha·(heatPort.T − T_ref)). Records what
    the Resistor records (MSL 3 called R_actual R)."""
    options = {"useHeatPort": True}
    R_ref = Parameter(1.0, "Ohm", "resistance at temperature T_ref")

    def __init__(self, name: str | None = None, **params):
        if params.get("useHeatPort", True) is not True:
            raise ParameterError("HeatingResistor always has its heatPort; for a resistor "
                                 "without one use Resistor(R=R_ref)")
        super().__init__(name, **params)

    def _resistance(self, e):
        return self.R_ref


class _InitialValue(OnePort):
    """MSL's IC and UIC of the variable capacitor and inductor: with the option ``UIC`` an
    initial equation (v = IC, i = IC) holds at the start."""
    options = {"UIC": False}

    def _use_initial_condition(self, e, value, what: str):
        if self.UIC:
            e.initial(value - self.IC, f"{what} = IC (UIC = true)")


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


class VariableCapacitor(_InitialValue):
    """Ideal linear capacitor with variable capacitance (MSL Basic.VariableCapacitor): the
    charge Q = max(C, Cmin)·v [A.s] (a state, start 0) with i = der(Q); C [F] the input
    ``C`` (C ≥ 0 asserted), Cmin [F] its lower bound (> 0: no change of index where C
    reaches 0). With the option ``UIC`` the initial equation v = IC [V]."""
    C = RealInput("capacitance as input signal [F]")
    Cmin = Parameter(EPS, "F", "lower bound for variable capacitance", positive=True)
    IC = Parameter(0.0, "V", "initial value")

    def structure(self, s):
        s.state("Q", 0.0, "A.s", "electric charge")

    def physics(self, e):
        Q, C, i = e.state("Q"), e.input(self.C), self._current(e)
        e.assertion(C >= 0, "Capacitance C has to be >= 0!")
        v = Q / ca.fmax(C, self.Cmin)
        e.residual(self._v(e) - v)
        e.derivative(Q, i)
        self._record(e, v, i)
        self._use_initial_condition(e, v, "v")


class VariableInductor(_InitialValue):
    """Ideal linear inductor with variable inductance (MSL Basic.VariableInductor): the flux
    Psi = max(L, Lmin)·i [Wb] (a state, start 0) with v = der(Psi); L [H] the input ``L``
    (L ≥ 0 asserted), Lmin [H] its lower bound (> 0). With the option ``UIC`` the initial
    equation i = IC [A]."""
    L = RealInput("inductance as input signal [H]")
    Lmin = Parameter(EPS, "H", "lower bound for variable inductance", positive=True)
    IC = Parameter(0.0, "A", "initial value")

    def structure(self, s):
        s.state("Psi", 0.0, "Wb", "magnetic flux")

    def physics(self, e):
        Psi, L, v = e.state("Psi"), e.input(self.L), self._v(e)
        e.assertion(L >= 0, "Inductance L has to be >= 0!")
        i = self._current(e, Psi / ca.fmax(L, self.Lmin))
        e.derivative(Psi, v)
        self._record(e, v, i)
        self._use_initial_condition(e, i, "i")


def _saturation_current(Lnom, Lzer, Linf, Inom):
    """MSL SaturatingInductor's Ipar [A], the root of (Lnom − Linf)/(Lzer − Linf) =
    x·(π/2 − atan(x)), x = Ipar/Inom: the right side g(x) = x·atan(1/x) rises from 0 to 1,
    concave (g'' = −2/(1 + x²)²), so Newton's method from x = 0 climbs to the root without
    overshooting; 60 steps reach it to round-off for ratios up to 1 − 1e-10 (x ≈ 6e4).
    Written in CasADi operations: Ipar follows the parameters also when they are changed at
    simulation time."""
    ratio = (Lnom - Linf) / (Lzer - Linf)
    x = 0.0
    for _ in range(60):
        g = x * (ca.pi / 2 - ca.atan(x))
        slope = ca.pi / 2 - ca.atan(x) - x / (1 + x * x)
        x = x + (ratio - g) / slope
    return x * Inom


class SaturatingInductor(OnePort):
    """Simple model of an inductor with saturation (MSL Basic.SaturatingInductor): the flux
    Psi = Linf·i + (Lzer − Linf)·Ipar·atan(i/Ipar) [Wb], v = der(Psi), so the present
    inductance Lact = Psi/i falls from Lzer at i = 0 through Lnom at i = Inom towards Linf
    at large currents; Ipar [A] solves (Lnom − Linf)/(Lzer − Linf) = Ipar/Inom·(π/2 −
    atan(Ipar/Inom)) (MSL's initial equation; ``_saturation_current``). State i [A]
    (start ``i_start``, 0; MSL's i(start=0)), der(i) = v/(dPsi/di), dPsi/di = Linf + (Lzer −
    Linf)/(1 + (i/Ipar)²) > 0. Inom [A] nominal current, Lnom [H] nominal inductance at
    Inom, Lzer [H] inductance near i = 0 (> Lnom), Linf [H] inductance at large currents
    (< Lnom). Records v, i, Lact, Psi."""
    Inom = Parameter(1.0, "A", "nominal current", positive=True)
    Lnom = Parameter(1.0, "H", "nominal inductance at nominal current", positive=True)
    Lzer = Parameter(2.0, "H", "inductance near current = 0", positive=True)
    Linf = Parameter(0.5, "H", "inductance at large currents", positive=True)

    def __init__(self, name: str | None = None, *, i_start=0.0, **params):
        super().__init__(name, **params)
        if not self.Lzer > self.Lnom * (1 + EPS):
            raise ParameterError(f"{who(self)}: Lzer (= {self.Lzer:g} H) has to be > Lnom (= "
                                 f"{self.Lnom:g} H): the inductance near i = 0 exceeds the "
                                 f"nominal one; raise Lzer (MSL's default 2*Lnom)")
        if not self.Linf < self.Lnom * (1 - EPS):
            raise ParameterError(f"{who(self)}: Linf (= {self.Linf:g} H) has to be < Lnom (= "
                                 f"{self.Lnom:g} H): the inductance at large currents is "
                                 f"below the nominal one; lower Linf (MSL's default Lnom/2)")
        self.__dict__["i_start"] = _start(i_start, f"{type(self).__name__}: i_start")

    def structure(self, s):
        s.state("i", self.i_start, "A", "current flowing from pin p to pin n")

    def physics(self, e):
        i, v = e.state("i"), self._v(e)
        e.assertion(self.Lzer > self.Lnom * (1 + EPS), "Lzer has to be > Lnom")
        e.assertion(self.Linf < self.Lnom * (1 - EPS), "Linf has to be < Lnom")
        Ipar = _saturation_current(self.Lnom, self.Lzer, self.Linf, self.Inom)
        x = i / Ipar
        self._current(e, i)
        e.derivative(i, v / (self.Linf + (self.Lzer - self.Linf) / (1 + x * x)))
        self._record(e, v=v)
        psi = self.Linf * i + (self.Lzer - self.Linf) * Ipar * ca.atan(x)
        e.variable("Psi", psi, "Wb", "present flux")
        e.variable("Lact", self.Linf + (self.Lzer - self.Linf) * ca.if_else(
            ca.fabs(x) < EPS, 1.0, ca.atan(x) / ca.if_else(ca.fabs(x) < EPS, 1.0, x)), "H",
            "present inductance")
        e.variable("Ipar", Ipar, "A", "current parameter of the saturation law")


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


class _BlockSignal:
    """The Modelica.Blocks.Sources block ``block`` that MSL's VoltageSource and
    CurrentSource redeclare as ``signalSource``, seen from the electrical ``source`` that
    holds it: the block's own methods (signal, before, events) on the source's values; a
    block parameter reads the source's parameter of the same name, or the one ``renamed``
    maps it to (the amplitude V or I), or, where the source has neither, the block's
    default (Pulse's nperiod in PulseVoltage), as MSL's modifiers bind them."""

    def __init__(self, source: Component, block: type, renamed: dict):
        self._source, self._block, self._renamed = source, block, renamed

    def __getattr__(self, name):
        if name in self._renamed:
            return getattr(self._source, self._renamed[name])
        if name in type(self._source).parameters() or isinstance(
                getattr(type(self._source), name, None), property):   # a parameter or binding
            return getattr(self._source, name)
        options = self._block.all_options()
        if name in options:
            return options[name]
        declared = self._block.parameters().get(name)
        if declared is not None:
            return declared.default
        attribute = getattr(self._block, name)
        return MethodType(attribute, self) if callable(attribute) else attribute


class _SignalSourced(OnePort):
    """MSL Interfaces.VoltageSource / CurrentSource: the source's value [V or A] is
    offset + (``before()`` before startTime, else ``signal(time)``) of its shape's
    Blocks.Sources block (``_block``, whose parameter ``_role`` is the source's amplitude
    ``_amplitude``), with the block's time events (startTime and the corners of the
    periodic waves)."""
    _block: type
    _role = "amplitude"
    _amplitude: str

    def _source_value(self, e):
        block = _BlockSignal(self, self._block, {self._role: self._amplitude})
        for time, period in block.events():
            e.time_event(time, period)
        return self.offset + ca.if_else(e.time < self.startTime, block.before(),
                                        block.signal(e.time))


class _TimedVoltage(_SignalSourced, _VoltageSource):
    """MSL Interfaces.VoltageSource: v = offset + (0 if time < startTime else signal) [V]."""
    _amplitude = "V"
    offset = Parameter(0.0, "V", "voltage offset")
    startTime = Parameter(0.0, "s", "time offset")

    def _voltage(self, e):
        return self._source_value(e)


# the shapes of the sources: the Blocks.Sources block and the parameters a voltage source
# and a current source of that shape share (their amplitude, V or I, is their own)
class _StepShape:
    _block, _role = sig.Step, "height"


class _RampShape:
    _block, _role = sig.Ramp, "height"
    duration = Parameter(2.0, "s", "duration of ramp", positive=True)


class _SineShape:
    _block = sig.Sine
    phase = Parameter(0.0, "rad", "phase of sine wave")
    f = Parameter(1.0, "Hz", "frequency of sine wave")


class _CosineShape:
    _block = sig.Cosine
    phase = Parameter(0.0, "rad", "phase of cosine wave")
    f = Parameter(1.0, "Hz", "frequency of cosine wave")


class _ExpSineShape:
    _block = sig.ExpSine
    f = Parameter(2.0, "Hz", "frequency of sine wave")
    phase = Parameter(0.0, "rad", "phase of sine wave")
    damping = Parameter(1.0, "1/s", "damping coefficient of sine wave")


class _PulseShape:
    _block = sig.Pulse
    width = Parameter(50.0, "%", "width of pulse in % of period", positive=True)
    period = Parameter(1.0, "s", "time for one period", positive=True)


class _TrapezoidShape:
    _block = sig.Trapezoid
    rising = Parameter(0.0, "s", "rising duration of trapezoid", nonnegative=True)
    width = Parameter(0.5, "s", "width duration of trapezoid", nonnegative=True)
    falling = Parameter(0.0, "s", "falling duration of trapezoid", nonnegative=True)
    period = Parameter(1.0, "s", "time for one period", positive=True)
    nperiod = Parameter(-1, "", "number of periods (< 0 means infinite number of periods)")


class _SawToothShape:
    _block = sig.SawTooth
    period = Parameter(1.0, "s", "time for one period", positive=True)


class _ExponentialsShape(BoundParameters):
    """The Exponentials block's rise and fall; fallTimeConst [s] follows riseTimeConst (MSL's
    binding, also at simulation time) unless given at construction, which makes it a
    parameter of its own (the class's twin registered by ``_own_fallTimeConst``)."""
    _block, _role = sig.Exponentials, "outMax"
    riseTime = Parameter(0.5, "s", "rise time", nonnegative=True)
    riseTimeConst = Parameter(0.1, "s", "rise time constant", positive=True)

    @property
    def fallTimeConst(self):
        """Fall time constant [s]: riseTimeConst (MSL's binding)."""
        return self.riseTimeConst


def _own_fallTimeConst(cls):
    """``cls`` with its twin whose fallTimeConst [s] is a parameter of its own (built by
    ``cls(fallTimeConst=...)``)."""
    return bound_twin(cls, "fallTimeConst",
                      Parameter(0.1, "s", "fall time constant", positive=True))


class _TableShape:
    """MSL's TableVoltage / TableCurrent: the Blocks.Sources.TimeTable redeclared with the
    source's ``table`` (constructor argument, rows [time [s], value], times non-decreasing
    from 0, a time given twice a jump; MSL's default [0, 0; 1, 1; 2, 4]), interpolated
    linearly by the TimeTable's own functions at time − startTime (its shiftTime bound to
    startTime, timeScale 1 s), extrapolated through the last two rows; a time event at
    startTime and at every jump. The table is fixed when the model is compiled."""

    def __init__(self, name: str | None = None, *, table=((0.0, 0.0), (1.0, 1.0), (2.0, 4.0)),
                 **params):
        super().__init__(name, **params)
        tab = _check_table(table, who(self), first_at_zero=False)
        if tab.shape[1] != 2:
            raise ParameterError(f"{who(self)}: table must have rows [time, value] (shape "
                                 f"(n, 2)), got shape {tab.shape}")
        if tab.shape[0] > 1 and tab[0, 0] != 0:
            raise ParameterError(f"{who(self)}: the first point in time has to be 0, but is "
                                 f"table[1,1] = {tab[0, 0]}; shift the table with startTime")
        self.__dict__["times"] = tab[:, 0]
        self.__dict__["table"] = tuple(float(v) for v in tab[:, 1])

    def _source_value(self, e):
        smoothness, extrapolation, time_events = sig.TimeTable._modes()
        e.time_event(self.startTime, None)
        for tk, period in _table_events(self.times, smoothness, extrapolation, time_events):
            e.time_event(self.startTime + tk, period)
        value = _table_values(e.time - self.startTime, self.times, self.table, smoothness,
                              extrapolation)[0]
        return self.offset + ca.if_else(e.time < self.startTime, 0.0, value)


class StepVoltage(_StepShape, _TimedVoltage):
    """Step voltage source: v = offset + (0 if time < startTime else V) [V]."""
    V = Parameter(1.0, "V", "height of step")


class RampVoltage(_RampShape, _TimedVoltage):
    """Ramp voltage source (MSL Sources.RampVoltage): v rises linearly from offset to
    offset + V [V] between startTime and startTime + duration [s] (duration > 0)."""
    V = Parameter(1.0, "V", "height of ramp")


class SineVoltage(_SineShape, _TimedVoltage):
    """Sine voltage source: v = offset + V·sin(2π·f·(time − startTime) + phase) after
    startTime, offset before [V]."""
    V = Parameter(1.0, "V", "amplitude of sine wave")


class CosineVoltage(_CosineShape, _TimedVoltage):
    """Cosine voltage source (MSL Sources.CosineVoltage): v = offset + V·cos(2π·f·(time −
    startTime) + phase) after startTime, offset before [V]."""
    V = Parameter(1.0, "V", "amplitude of cosine wave")


class ExpSineVoltage(_ExpSineShape, _TimedVoltage):
    """Exponentially damped sine voltage source (MSL Sources.ExpSineVoltage): v = offset +
    V·exp(−damping·τ)·sin(2π·f·τ + phase), τ = time − startTime ≥ 0, offset before [V]."""
    V = Parameter(1.0, "V", "amplitude of sine wave")


class PulseVoltage(_PulseShape, _TimedVoltage):
    """Pulse voltage source (MSL Sources.PulseVoltage): v = offset + V [V] during the first
    ``width`` percent of every period [s] from startTime, offset otherwise; the edges are
    time events."""
    V = Parameter(1.0, "V", "amplitude of pulse")


class TrapezoidVoltage(_TrapezoidShape, _TimedVoltage):
    """Trapezoidal voltage source (MSL Sources.TrapezoidVoltage): from startTime, every
    period [s] v rises from offset to offset + V [V] in ``rising``, holds ``width``, falls in
    ``falling`` [s], then stays at offset; nperiod periods (< 0: infinitely many); the
    corners are time events."""
    V = Parameter(1.0, "V", "amplitude of trapezoid")


class SawToothVoltage(_SawToothShape, _TimedVoltage):
    """Saw tooth voltage source (MSL Sources.SawToothVoltage): from startTime, v rises
    linearly from offset to offset + V [V] within every period [s] and jumps back at its end
    (a time event there); offset before startTime."""
    V = Parameter(1.0, "V", "amplitude of saw tooth")


@_own_fallTimeConst
class ExponentialsVoltage(_ExponentialsShape, _TimedVoltage):
    """Rising and falling exponential voltage source (MSL Sources.ExponentialsVoltage): for
    τ = time − startTime ≥ 0, v = offset + vMax·(1 − exp(−τ/riseTimeConst)) while τ <
    riseTime [s], then the value reached decays as exp(−(τ − riseTime)/fallTimeConst) [V];
    offset before startTime. fallTimeConst [s] is riseTimeConst unless given (MSL's
    binding). Time events at startTime and at the end of the rise (MSL declares vMax a plain
    Real; it is the voltage's upper bound)."""
    _amplitude = "vMax"
    vMax = Parameter(1.0, "V", "upper bound for rising edge")


class TableVoltage(_TableShape, _TimedVoltage):
    """Voltage source by linear interpolation in a table (MSL Sources.TableVoltage): v =
    offset + the table's voltage [V] at time − startTime, offset before startTime (see
    ``_TableShape``: ``table`` rows [time [s], voltage [V]])."""


class _CurrentSource(OnePort):
    """A current source: i [A] from p through the source to n given by ``_current_value``;
    its voltage v = p.v − n.v [V] is what the circuit sets."""

    def _current_value(self, e):
        raise NotImplementedError

    def physics(self, e):
        self._record(e, self._v(e), self._current(e, self._current_value(e)))


class ConstantCurrent(_CurrentSource):
    """Constant current source: i = I [A] from p through the source to n."""
    I = Parameter(1.0, "A", "value of constant current")         # noqa: E741 (MSL's name)

    def _current_value(self, e):
        return self.I


class _TimedCurrent(_SignalSourced, _CurrentSource):
    """MSL Interfaces.CurrentSource: i = offset + (0 if time < startTime else signal) [A]
    from p through the source to n."""
    _amplitude = "I"
    offset = Parameter(0.0, "A", "current offset")
    startTime = Parameter(0.0, "s", "time offset")

    def _current_value(self, e):
        return self._source_value(e)


class StepCurrent(_StepShape, _TimedCurrent):
    """Step current source (MSL Sources.StepCurrent): i = offset + (0 if time < startTime
    else I) [A]."""
    I = Parameter(1.0, "A", "height of step")                   # noqa: E741 (MSL's name)


class RampCurrent(_RampShape, _TimedCurrent):
    """Ramp current source (MSL Sources.RampCurrent): i rises linearly from offset to
    offset + I [A] between startTime and startTime + duration [s] (duration > 0)."""
    I = Parameter(1.0, "A", "height of ramp")                   # noqa: E741 (MSL's name)


class SineCurrent(_SineShape, _TimedCurrent):
    """Sine current source (MSL Sources.SineCurrent): i = offset + I·sin(2π·f·(time −
    startTime) + phase) after startTime, offset before [A]."""
    I = Parameter(1.0, "A", "amplitude of sine wave")           # noqa: E741 (MSL's name)


class CosineCurrent(_CosineShape, _TimedCurrent):
    """Cosine current source (MSL Sources.CosineCurrent): i = offset + I·cos(2π·f·(time −
    startTime) + phase) after startTime, offset before [A]."""
    I = Parameter(1.0, "A", "amplitude of cosine wave")         # noqa: E741 (MSL's name)


class ExpSineCurrent(_ExpSineShape, _TimedCurrent):
    """Exponentially damped sine current source (MSL Sources.ExpSineCurrent): i = offset +
    I·exp(−damping·τ)·sin(2π·f·τ + phase), τ = time − startTime ≥ 0, offset before [A]
    (MSL declares I a plain Real; it is the current's amplitude)."""
    I = Parameter(1.0, "A", "amplitude of sine wave")           # noqa: E741 (MSL's name)


class PulseCurrent(_PulseShape, _TimedCurrent):
    """Pulse current source (MSL Sources.PulseCurrent): i = offset + I [A] during the first
    ``width`` percent of every period [s] from startTime, offset otherwise; the edges are
    time events."""
    I = Parameter(1.0, "A", "amplitude of pulse")               # noqa: E741 (MSL's name)


class TrapezoidCurrent(_TrapezoidShape, _TimedCurrent):
    """Trapezoidal current source (MSL Sources.TrapezoidCurrent): the TrapezoidVoltage's
    wave for the current i [A], amplitude I; nperiod periods (< 0: infinitely many)."""
    I = Parameter(1.0, "A", "amplitude of trapezoid")           # noqa: E741 (MSL's name)


class SawToothCurrent(_SawToothShape, _TimedCurrent):
    """Saw tooth current source (MSL Sources.SawToothCurrent): the SawToothVoltage's wave
    for the current i [A], amplitude I."""
    I = Parameter(1.0, "A", "amplitude of saw tooth")           # noqa: E741 (MSL's name)


@_own_fallTimeConst
class ExponentialsCurrent(_ExponentialsShape, _TimedCurrent):
    """Rising and falling exponential current source (MSL Sources.ExponentialsCurrent): the
    ExponentialsVoltage's wave for the current i [A], upper bound iMax (a plain Real in
    MSL)."""
    _amplitude = "iMax"
    iMax = Parameter(1.0, "A", "upper bound for rising edge")


class TableCurrent(_TableShape, _TimedCurrent):
    """Current source by linear interpolation in a table (MSL Sources.TableCurrent): i =
    offset + the table's current [A] at time − startTime, offset before startTime (see
    ``_TableShape``: ``table`` rows [time [s], current [A]])."""


class SignalCurrent(OnePort):
    """Current source driven by the input ``i`` [A] (from p through the source to n)."""
    i = RealInput("current flowing from pin p to pin n as input signal [A]")

    def physics(self, e):
        self._current(e, e.input(self.i))
        self._record(e, v=self._v(e))


# ---- sensors ------------------------------------------------------------------------------
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


# ---- ideal switching elements (Modelica.Electrical.Analog.Ideal) --------------------------
class _IdealSwitching(_ConditionalHeatPort, OnePort):
    """MSL's IdealSemiconductor / IdealSwitch: a point s [1] (an algebraic unknown) on a
    two-segment characteristic, v = s·(1 if off else Ron) + Vknee [V], i = s·(Goff if off
    else 1) + Goff·Vknee [A]: a resistance Ron when on, a conductance Goff when off, both
    segments through the knee (Vknee, Goff·Vknee). Records v, i, s, off, LossPower = v·i,
    T_heatPort."""
    Ron = Parameter(1e-5, "Ohm", "forward state-on differential resistance (closed "
                                 "resistance)", nonnegative=True)
    Goff = Parameter(1e-5, "S", "backward state-off conductance (opened conductance)",
                     nonnegative=True)
    #: fixed device temperature if useHeatPort = false [K]: MSL's IdealSwitch has final
    #: T = 293.15 (IdealDiode declares it a parameter)
    T = 293.15
    _Vknee = 0.0

    def structure(self, s):
        s.algebraic("s", 0.0, "1", "auxiliary variable for actual position on the ideal "
                                   "characteristic (s < 0: blocking, s > 0: conducting)")

    def _off(self, e):
        raise NotImplementedError

    def physics(self, e):
        sa, off, v, i = e.state("s"), self._off(e), self._v(e), self._current(e)
        e.residual(v - (sa * ca.if_else(off, 1.0, self.Ron) + self._Vknee))
        e.residual(i - (sa * ca.if_else(off, self.Goff, 1.0) + self.Goff * self._Vknee))
        self._record(e, v, i)
        e.variable("s", sa, "1", "auxiliary variable (s < 0: blocking, s > 0: conducting)")
        e.variable("off", off, "", "switching state (1: off)")
        self._losses(e, v * i, self._T_heatPort(e))


#: how far past the knee [1: A when conducting, V when blocking] the event of an ideal
#: semiconductor is located, so that s < 0 is unambiguous at the event (at s = 0 itself
#: both states hold)
S_NOISE = 1e-10


class _IdealSemiconductor(_IdealSwitching):
    """MSL Interfaces.IdealSemiconductor: the characteristic of ``_IdealSwitching`` through
    the knee (Vknee [V], Goff·Vknee [A]), its Boolean mode off (start true, MSL's) switched
    at events to ``_next_off`` (of the present mode, MSL's pre(off)), and a state event
    where s crosses 0: its indicator ``s`` is located past the knee by ``S_NOISE`` (1e-10:
    a current of 1e-10 A, a voltage of 1e-10 V; the switching instant is late by
    S_NOISE/|ds/dt|, 3e-12 s in the rectifier of the tests), so that s < 0 is unambiguous
    at the event. No smooth form (refused when compiled with smooth=True)."""
    Vknee = Parameter(0.0, "V", "forward threshold voltage", nonnegative=True)
    T = Parameter(293.15, "K", "fixed device temperature if useHeatPort = false",
                  positive=True)

    @property
    def _Vknee(self):
        return self.Vknee

    def structure(self, s):
        refuse_smooth(self, s)
        super().structure(s)
        s.mode("off", 1, values=(0, 1), description="switching state (1: blocking)")

    def _next_off(self, e, off, blocking):
        """The mode off after an event, from the present one and ``blocking`` (s < 0)."""
        raise NotImplementedError

    def _off(self, e):
        off, sa = e.mode("off"), e.state("s")
        e.mode_update(off, self._next_off(e, off, sa < 0))
        e.indicator("s", ca.if_else(off, sa - S_NOISE, sa + S_NOISE), "1",
                    "position on the characteristic past the knee by S_NOISE: the element "
                    "switches where it crosses 0")
        return off


class IdealDiode(_IdealSemiconductor):
    """Ideal diode (MSL Ideal.IdealDiode): the characteristic of ``_IdealSwitching`` with
    off = s < 0, switched at the state event where s crosses 0 (``_IdealSemiconductor``).
    Ron [Ohm] 1e-5, Goff [S] 1e-5, Vknee [V] 0. No smooth form (refused when compiled with
    smooth=True)."""

    def _next_off(self, e, off, blocking):
        return blocking


class IdealThyristor(_IdealSemiconductor):
    """Ideal thyristor (MSL Ideal.IdealThyristor): off = s < 0 or (pre(off) and not fire):
    a blocking thyristor conducts once v > Vknee while the Boolean input ``fire`` is true
    (switched at the event of ``fire``'s rise or of s crossing 0), and keeps conducting
    after ``fire`` falls until its current falls below Goff·Vknee (s < 0). Ron [Ohm] 1e-5,
    Goff [S] 1e-5, Vknee [V] 0; no smooth form."""
    fire = BooleanInput("true => the thyristor may conduct (it turns on if v > Vknee)")

    def _next_off(self, e, off, blocking):
        return ca.logic_or(blocking, ca.logic_and(off, ca.logic_not(e.input(self.fire))))


class IdealGTOThyristor(_IdealSemiconductor):
    """Ideal GTO thyristor or switching transistor (MSL Ideal.IdealGTOThyristor): off = s < 0
    or not fire: conducting while v > Vknee and the Boolean input ``fire`` is true, blocking
    as soon as ``fire`` falls (at its event). Ron [Ohm] 1e-5, Goff [S] 1e-5, Vknee [V] 0;
    no smooth form."""
    fire = BooleanInput("true => conducting if v > Vknee, false => blocking")

    def _next_off(self, e, off, blocking):
        return ca.logic_or(blocking, ca.logic_not(e.input(self.fire)))


class IdealOpeningSwitch(_IdealSwitching):
    """Ideal electrical opener (MSL Ideal.IdealOpeningSwitch): off = control (Boolean
    input ``control``: true opens p—n); Ron [Ohm] 1e-5, Goff [S] 1e-5. The switching
    instants are the events of the block driving ``control``; with smooth=True the law is
    unchanged (smooth between the control's jumps)."""
    control = BooleanInput("true => switch open, false => p--n connected")

    def _off(self, e):
        return e.input(self.control)


class IdealClosingSwitch(_IdealSwitching):
    """Ideal electrical closer (MSL Ideal.IdealClosingSwitch): off = not control (Boolean
    input ``control``: true connects p—n); Ron [Ohm] 1e-5, Goff [S] 1e-5."""
    control = BooleanInput("true => p--n connected, false => switch open")

    def _off(self, e):
        return 1 - e.input(self.control)


class _ControlPin(Component):
    """The control pin of MSL's Controlled* switches: no current (control.i = 0); the
    switch state follows control.v > level [V], a Boolean mode ``above`` switched at the
    state event where control.v − level crosses 0 (indicator ``control``). No smooth form
    (refused when compiled with smooth=True)."""
    level = Parameter(0.5, "V", "switch level")

    def structure(self, s):
        refuse_smooth(self, s)
        super().structure(s)
        s.mode("above", 0, values=(0, 1), description="control.v > level")

    def _above(self, e):
        """The mode control.v > level (1: true)."""
        above, vc = e.mode("above"), e.potential(self.control)
        e.flow(self.control, 0.0)
        e.mode_update(above, vc > self.level)
        e.indicator("control", vc - self.level, "V", "control.v - level: the switch "
                                                      "switches where it crosses 0")
        return above


class ControlledIdealOpeningSwitch(_ControlPin, _IdealSwitching):
    """Controlled ideal electrical opener (MSL Ideal.ControlledIdealOpeningSwitch): off =
    control.v > level [V] (0.5), the pin ``control`` carrying no current; Ron [Ohm] 1e-5,
    Goff [S] 1e-5."""
    control = Pin("control pin: control.v > level switch open, otherwise p--n connected")

    def _off(self, e):
        return self._above(e)


class ControlledIdealClosingSwitch(_ControlPin, _IdealSwitching):
    """Controlled ideal electrical closer (MSL Ideal.ControlledIdealClosingSwitch): off =
    control.v < level [V] (0.5; at control.v = level exactly it is open here, closed in MSL:
    the instant of the crossing), the pin ``control`` carrying no current; Ron [Ohm] 1e-5,
    Goff [S] 1e-5."""
    control = Pin("control pin: control.v > level switch closed, otherwise switch open")

    def _off(self, e):
        return 1 - self._above(e)


class _TwoWaySwitching(_ConditionalHeatPort):
    """MSL's IdealTwoWaySwitch and its controlled twin: the pin p connected to n1 (a
    resistance Ron [Ohm] 1e-5) and not to n2 (a conductance Goff [S] 1e-5) while the
    switch state ``_to_n2`` is false, the other way round while it is true; each path k
    (p–n1, p–n2) a point s_k [1] (an algebraic unknown) on its two-segment characteristic,
    p.v − nk.v = s_k·(Ron if closed else 1), nk.i = −s_k·(1 if closed else Goff),
    p.i = −(n1.i + n2.i). T [K] 293.15 without heat port (MSL's final T); LossPower =
    p.i·p.v + n1.i·n1.v + n2.i·n2.v [W]."""
    Ron = Parameter(1e-5, "Ohm", "closed switch resistance", nonnegative=True)
    Goff = Parameter(1e-5, "S", "opened switch conductance", nonnegative=True)
    T = 293.15
    p = PositivePin("positive pin")
    n1 = NegativePin("negative pin, connected to p while the switch is in its first position")
    n2 = NegativePin("negative pin, connected to p while the switch is in its second position")

    def structure(self, s):
        super().structure(s)
        for k in (1, 2):
            s.algebraic(f"s{k}", 0.0, "1", "auxiliary variable")

    def _to_n2(self, e):
        raise NotImplementedError

    def physics(self, e):
        to_n2 = self._to_n2(e)
        vp, currents, loss = e.potential(self.p), [], 0
        for k, pin, closed in ((1, self.n1, 1 - to_n2), (2, self.n2, to_n2)):
            sk = e.state(f"s{k}")
            e.residual(vp - e.potential(pin) - sk * ca.if_else(closed, self.Ron, 1.0))
            ik = -sk * ca.if_else(closed, 1.0, self.Goff)
            e.flow(pin, ik)
            currents.append(ik)
            loss += ik * e.potential(pin)
        ip = -(currents[0] + currents[1])
        e.flow(self.p, ip)
        self._losses(e, loss + ip * vp, self._T_heatPort(e))


class IdealTwoWaySwitch(_TwoWaySwitching):
    """Ideal two-way switch (MSL Ideal.IdealTwoWaySwitch, MSL 3's IdealCommutingSwitch):
    the Boolean input ``control`` connects p–n2 when true, p–n1 when false (see
    ``_TwoWaySwitching``: Ron [Ohm] 1e-5 closed, Goff [S] 1e-5 open)."""
    control = BooleanInput("true => p--n2 connected, false => p--n1 connected")

    def _to_n2(self, e):
        return e.input(self.control)


class ControlledIdealTwoWaySwitch(_ControlPin, _TwoWaySwitching):
    """Controlled ideal two-way switch (MSL Ideal.ControlledIdealTwoWaySwitch, MSL 3's
    ControlledIdealCommutingSwitch): p–n2 connected while control.v > level [V] (0.5),
    p–n1 otherwise; the pin ``control`` carries no current; Ron [Ohm] 1e-5, Goff [S] 1e-5."""
    control = Pin("control pin: if control.v > level p--n2 connected, otherwise p--n1 "
                  "connected")

    def _to_n2(self, e):
        return self._above(e)


class _IntermediateSwitching(_ConditionalHeatPort):
    """MSL's IdealIntermediateSwitch and its controlled twin: p1–n1 and p2–n2 connected
    while the switch state ``_crossed`` is false, p1–n2 and p2–n1 while it is true; each of
    the four paths a point s_k [1] (an algebraic unknown) on its two-segment
    characteristic, the voltage s_k·(Ron if closed else 1) [V], the currents at the pins
    the sums of the two paths meeting there, s·1 for a closed path and s·Goff for an open
    one [A] (MSL's equations). Ron [Ohm] 1e-5, Goff [S] 1e-5; T [K] 293.15 without heat
    port (MSL's final T); LossPower = Σ pin.i·pin.v [W]."""
    Ron = Parameter(1e-5, "Ohm", "closed switch resistance", nonnegative=True)
    Goff = Parameter(1e-5, "S", "opened switch conductance", nonnegative=True)
    T = 293.15
    p1 = PositivePin("positive pin 1")
    p2 = PositivePin("positive pin 2")
    n1 = NegativePin("negative pin 1")
    n2 = NegativePin("negative pin 2")

    def structure(self, s):
        super().structure(s)
        for k in (1, 2, 3, 4):
            s.algebraic(f"s{k}", 0.0, "1", "auxiliary variable")

    def _crossed(self, e):
        raise NotImplementedError

    def physics(self, e):
        crossed = self._crossed(e)
        # the paths: (k, from, to, closed while crossed)
        paths = ((1, self.p1, self.n1, False), (2, self.p2, self.n2, False),
                 (3, self.p1, self.n2, True), (4, self.p2, self.n1, True))
        current = {}
        for k, a, b, when in paths:
            sk = e.state(f"s{k}")
            closed = crossed if when else 1 - crossed
            e.residual(e.potential(a) - e.potential(b)
                       - sk * ca.if_else(closed, self.Ron, 1.0))
            current[k] = sk * ca.if_else(closed, 1.0, self.Goff)
        flows = ((self.p1, current[1] + current[3]), (self.p2, current[2] + current[4]),
                 (self.n1, -(current[1] + current[4])), (self.n2, -(current[2] + current[3])))
        loss = 0
        for pin, i in flows:
            e.flow(pin, i)
            loss += i * e.potential(pin)
        self._losses(e, loss, self._T_heatPort(e))


class IdealIntermediateSwitch(_IntermediateSwitching):
    """Ideal intermediate switch (MSL Ideal.IdealIntermediateSwitch): the Boolean input
    ``control`` connects p1–n2 and p2–n1 when true, p1–n1 and p2–n2 when false (see
    ``_IntermediateSwitching``: Ron [Ohm] 1e-5, Goff [S] 1e-5)."""
    control = BooleanInput("true => p1--n2, p2--n1 connected, otherwise p1--n1, p2--n2 "
                           "connected")

    def _crossed(self, e):
        return e.input(self.control)


class ControlledIdealIntermediateSwitch(_ControlPin, _IntermediateSwitching):
    """Controlled ideal intermediate switch (MSL Ideal.ControlledIdealIntermediateSwitch):
    p1–n2 and p2–n1 connected while control.v > level [V] (0.5), p1–n1 and p2–n2
    otherwise; the pin ``control`` carries no current; Ron [Ohm] 1e-5, Goff [S] 1e-5."""
    control = Pin("control pin: if control.v > level p1--n2, p2--n1 connected, otherwise "
                  "p1--n1, p2--n2 connected")

    def _crossed(self, e):
        return self._above(e)


#: MSL 3's names of the two-way switches
IdealCommutingSwitch = IdealTwoWaySwitch
ControlledIdealCommutingSwitch = ControlledIdealTwoWaySwitch


class Short(OnePort):
    """Short cut branch (MSL Ideal.Short): v = 0 [V]; its current i [A] is what the circuit
    sends through it."""

    def physics(self, e):
        e.residual(self._v(e))
        self._record(e, i=self._current(e))


class Idle(OnePort):
    """Idle branch (MSL Ideal.Idle): i = 0 [A]; its voltage v [V] is what the circuit
    sets."""

    def physics(self, e):
        self._current(e, 0.0)
        self._record(e, v=self._v(e))


# ---- two-ports ------------------------------------------------------------------------------
class TwoPort(Component):
    """Two pin pairs (MSL Interfaces.TwoPort): v1 = p1.v − n1.v, i1 = p1.i = −n1.i [V, A]
    on the primary side, v2, i2 likewise on the secondary side."""
    p1 = PositivePin("positive pin of the left port")
    n1 = NegativePin("negative pin of the left port")
    p2 = PositivePin("positive pin of the right port")
    n2 = NegativePin("negative pin of the right port")

    def _port(self, e, k, i=None):
        """(v_k, i_k) of port k = 1, 2: i_k is ``i`` if given, else an unknown."""
        p, n = (self.p1, self.n1) if k == 1 else (self.p2, self.n2)
        if i is None:
            i = e.flow_of(p)
        else:
            e.flow(p, i)
        e.flow(n, -i)
        return e.potential(p) - e.potential(n), i

    def _record(self, e, v1, i1, v2, i2):
        for name, value, unit in (("v1", v1, "V"), ("i1", i1, "A"), ("v2", v2, "V"),
                                  ("i2", i2, "A")):
            e.variable(name, value, unit, f"{'voltage drop' if unit == 'V' else 'current'} "
                                          f"of port {name[1]}")


class IdealTransformer(TwoPort):
    """Ideal transformer core (MSL Ideal.IdealTransformer): v1 = n·v2 and the magnetization
    current im1 = i1 + i2/n [A]; without magnetization (option ``considerMagnetization``
    False, MSL's default) im1 = 0, so i1 = −i2/n and the power v1·i1 + v2·i2 = 0 exactly;
    with it, v1 = Lm1·der(im1), im1 a state (start ``im1_start``, 0). n [1] turns ratio
    primary:secondary voltage, Lm1 [H] magnetization inductance w.r.t. the primary side."""
    options = {"considerMagnetization": False}
    n = Parameter(1.0, "1", "turns ratio primary:secondary voltage")
    Lm1 = Parameter(1.0, "H", "magnetization inductance w.r.t. primary side", positive=True)

    def __init__(self, name: str | None = None, *, im1_start=0.0, **params):
        super().__init__(name, **params)
        self.__dict__["im1_start"] = _start(im1_start, f"{type(self).__name__}: im1_start")

    def structure(self, s):
        if self.considerMagnetization:
            s.state("im1", self.im1_start, "A", "magnetization current w.r.t. primary side")

    def physics(self, e):
        v2, i2 = self._port(e, 2)
        im1 = e.state("im1") if self.considerMagnetization else 0.0
        v1, i1 = self._port(e, 1, im1 - i2 / self.n)
        e.residual(v1 - self.n * v2)
        if self.considerMagnetization:
            e.derivative(im1, v1 / self.Lm1)
        self._record(e, v1, i1, v2, i2)
        e.variable("im1", im1, "A", "magnetization current w.r.t. primary side")
        e.variable("psim1", self.Lm1 * im1, "Wb", "magnetic flux w.r.t. primary side")


class Transformer(TwoPort):
    """Transformer with two ports (MSL Basic.Transformer), coupled inductors: v1 = L1·der(i1)
    + M·der(i2), v2 = M·der(i1) + L2·der(i2) [V]; states i1, i2 [A] (start ``i1_start``,
    ``i2_start``, 0). L1, L2 [H] primary and secondary inductances, M [H] the coupling
    inductance, with L1·L2 > M² (the derivatives are solved for: at perfect coupling, M² =
    L1·L2, use the IdealTransformer with considerMagnetization). L1, L2 and M have no
    default (as in MSL). Records the coupling's dv = v1 − v2 = (L1 − M)·der(i1) + (M −
    L2)·der(i2) [V] as MSL does."""
    required = ("L1", "L2", "M")
    L1 = Parameter(1.0, "H", "primary inductance", positive=True)
    L2 = Parameter(1.0, "H", "secondary inductance", positive=True)
    M = Parameter(1.0, "H", "coupling inductance")

    def __init__(self, name: str | None = None, *, i1_start=0.0, i2_start=0.0, **params):
        super().__init__(name, **params)
        if self.L1 * self.L2 - self.M ** 2 <= 0:
            raise ParameterError(
                f"{type(self).__name__}{f' {name!r}' if name else ''}: L1*L2 = "
                f"{self.L1 * self.L2:g} H^2 must exceed M^2 = {self.M ** 2:g} H^2 (coupled "
                f"inductors whose derivatives are solved for); for perfect coupling use "
                f"IdealTransformer(considerMagnetization=True)")
        for key, value in (("i1_start", i1_start), ("i2_start", i2_start)):
            self.__dict__[key] = _start(value, f"{type(self).__name__}: {key}")

    def structure(self, s):
        s.state("i1", self.i1_start, "A", "current of port 1")
        s.state("i2", self.i2_start, "A", "current of port 2")

    def physics(self, e):
        i1, i2 = e.state("i1"), e.state("i2")
        v1, _ = self._port(e, 1, i1)
        v2, _ = self._port(e, 2, i2)
        det = self.L1 * self.L2 - self.M ** 2
        e.assertion(det > 0, "L1*L2 must exceed M^2")
        di1 = (self.L2 * v1 - self.M * v2) / det
        di2 = (self.L1 * v2 - self.M * v1) / det
        e.derivative(i1, di1)
        e.derivative(i2, di2)
        self._record(e, v1, i1, v2, i2)
        e.variable("dv", (self.L1 - self.M) * di1 + (self.M - self.L2) * di2, "V",
                   "difference between voltage drop over primary inductor and voltage drop "
                   "over secondary inductor")


class M_Transformer(_Sized, Component):
    """Generic transformer with N coupled inductors (MSL Basic.M_Transformer): the pins
    ``p[1]`` .. ``p[N]``, ``n[1]`` .. ``n[N]``, v[j] = p[j].v − n[j].v [V], i[j] = p[j].i =
    −n[j].i [A], v = Lm·der(i) with the symmetric inductance matrix Lm [H] from L, its upper
    triangle row by row (``L[1]`` .. ``L[N(N+1)/2]``: Lm[1,1], Lm[1,2], .., Lm[1,N],
    Lm[2,2], ..; MSL's numbering). N (constructor argument, ≥ 1, default 3) is structural;
    L defaults to MSL's {1, 0.1, 0.2, 2, 0.3, 3} for N = 3 and must be given otherwise.
    States i[j] (start 0, MSL's fixed start). der(i) = Lm⁻¹·v is solved for: Lm must be
    positive definite (checked at construction; perfect coupling is the
    IdealTransformer's)."""
    _classes: dict = {}

    def __new__(cls, name=None, *, N: int = 3, **params):
        return super().__new__(cls._variant(_size(N, "M_Transformer: N (number of "
                                                      "inductors)", 1)))

    @staticmethod
    def _declare(N: int) -> dict:
        default = (1.0, 0.1, 0.2, 2.0, 0.3, 3.0) if N == 3 else (0.0,) * (N * (N + 1) // 2)
        return {"L": Parameter(default, "H", "inductances and coupling inductances"),
                "p": VectorPort(PositivePin, N, "positive pin"),
                "n": VectorPort(NegativePin, N, "negative pin")}

    def __init__(self, name: str | None = None, *, N: int = 3, **params):
        if N != 3 and "L" not in params:
            raise ParameterError(f"M_Transformer{f' {name!r}' if name else ''}: give the "
                                 f"{N * (N + 1) // 2} inductances L (the upper triangle of "
                                 f"the inductance matrix, row by row) for N = {N}")
        super().__init__(name, **params)
        if np.linalg.eigvalsh(self._matrix(self.L)).min() <= 0:
            raise ParameterError(f"{who(self)}: the inductance matrix of L = "
                                 f"{list(self.L)} H is not positive definite (coupled "
                                 f"inductors whose derivatives are solved for); lower the "
                                 f"coupling inductances, or for perfect coupling use "
                                 f"IdealTransformer(considerMagnetization=True)")

    @property
    def N(self) -> int:
        """Number of inductors."""
        return self._key[0]

    def _matrix(self, L):
        """The symmetric matrix Lm [H] from the upper-triangle elements L (numbers or
        symbols): a nested list."""
        N, k = self.N, 0
        Lm = [[None] * N for _ in range(N)]
        for r in range(N):
            for c in range(r, N):
                Lm[r][c] = Lm[c][r] = L[k]
                k += 1
        return Lm

    def structure(self, s):
        for j in range(1, self.N + 1):
            s.state(f"i[{j}]", 0.0, "A", f"current through inductor {j}")

    def physics(self, e):
        i = [e.state(f"i[{j}]") for j in range(1, self.N + 1)]
        v = []
        for j, (p, n) in enumerate(zip(self.p, self.n)):
            e.flow(p, i[j])
            e.flow(n, -i[j])
            v.append(e.potential(p) - e.potential(n))
        Lm = ca.vertcat(*[ca.horzcat(*row) for row in self._matrix(self.L)])
        di = ca.solve(Lm, ca.vertcat(*v))
        for j in range(self.N):
            e.derivative(i[j], di[j])
            e.variable(f"v[{j + 1}]", v[j], "V", f"voltage drop over inductor {j + 1}")


class VCV(TwoPort):
    """Linear voltage-controlled voltage source (MSL Basic.VCV): v2 = gain·v1 [V], i1 = 0;
    i2 [A] is what the circuit draws."""
    gain = Parameter(1.0, "1", "voltage gain")

    def physics(self, e):
        v1, i1 = self._port(e, 1, 0.0)
        v2, i2 = self._port(e, 2)
        e.residual(v2 - self.gain * v1)
        self._record(e, v1, i1, v2, i2)


class VCC(TwoPort):
    """Linear voltage-controlled current source (MSL Basic.VCC): i2 = transConductance·v1
    [A], i1 = 0."""
    transConductance = Parameter(1.0, "S", "transconductance")

    def physics(self, e):
        v1, i1 = self._port(e, 1, 0.0)
        v2, i2 = self._port(e, 2, self.transConductance * v1)
        self._record(e, v1, i1, v2, i2)


class CCV(TwoPort):
    """Linear current-controlled voltage source (MSL Basic.CCV): v2 = transResistance·i1
    [V], v1 = 0."""
    transResistance = Parameter(1.0, "Ohm", "transresistance")

    def physics(self, e):
        v1, i1 = self._port(e, 1)
        v2, i2 = self._port(e, 2)
        e.residual(v1)
        e.residual(v2 - self.transResistance * i1)
        self._record(e, v1, i1, v2, i2)


class CCC(TwoPort):
    """Linear current-controlled current source (MSL Basic.CCC): i2 = gain·i1 [A], v1 = 0."""
    gain = Parameter(1.0, "1", "current gain")

    def physics(self, e):
        v1, i1 = self._port(e, 1)
        v2, i2 = self._port(e, 2, self.gain * i1)
        e.residual(v1)
        self._record(e, v1, i1, v2, i2)


class Gyrator(TwoPort):
    """Gyrator (MSL Basic.Gyrator): i1 = G2·v2, i2 = −G1·v1 [A]; G1, G2 [S] the primary and
    secondary gyration conductances (1). With G1 = G2 it is lossless: v1·i1 + v2·i2 = 0."""
    G1 = Parameter(1.0, "S", "primary gyration conductance")
    G2 = Parameter(1.0, "S", "secondary gyration conductance")

    def physics(self, e):
        v1 = e.potential(self.p1) - e.potential(self.n1)
        v2 = e.potential(self.p2) - e.potential(self.n2)
        self._port(e, 1, self.G2 * v2)
        self._port(e, 2, -self.G1 * v1)
        self._record(e, v1, self.G2 * v2, v2, -self.G1 * v1)


class NonlinearResistor(OnePort):
    """Chua's resistor (MSL Electrical.Analog.Examples.Utilities.NonlinearResistor): the
    piecewise-linear i = Ga·v for |v| ≤ Ve, Gb·(v ∓ Ve) ± Ga·Ve outside [A]; Ga, Gb [S]
    inner and outer conductances, Ve [V] the inner range limit (MSL gives no defaults;
    these are ChuaCircuit's). The law is continuous, its kinks at v = ±Ve are integrated
    across (no modes: a crossing there would change nothing)."""
    Ga = Parameter(-0.757576, "S", "conductance in inner voltage range")
    Gb = Parameter(-0.409091, "S", "conductance in outer voltage range")
    Ve = Parameter(1.0, "V", "inner voltage range limit", positive=True)

    def physics(self, e):
        v = self._v(e)
        i = ca.if_else(v < -self.Ve, self.Gb * (v + self.Ve) - self.Ga * self.Ve,
                       ca.if_else(v > self.Ve, self.Gb * (v - self.Ve) + self.Ga * self.Ve,
                                  self.Ga * v))
        self._record(e, v, self._current(e, i))


def _nullator(e, p, n):
    """The input port of an ideal operational amplifier: no current into the pins p, n;
    its voltage p.v − n.v [V] (0 for the nullator: the amplifier's equations fix it)."""
    e.flow(p, 0.0)
    e.flow(n, 0.0)
    return e.potential(p) - e.potential(n)


class IdealOpAmp(TwoPort):
    """Ideal operational amplifier (MSL Ideal.IdealOpAmp), a norator–nullator pair: the
    left port p1, n1 a nullator, v1 = 0 [V] and i1 = 0 [A]; the right port p2, n2 a
    norator, v2 [V] and i2 [A] (i2 = p2.i = −n2.i) whatever the circuit needs. Records
    v1, i1, v2, i2."""

    def physics(self, e):
        v1 = _nullator(e, self.p1, self.n1)
        v2, i2 = self._port(e, 2)
        e.residual(v1)
        self._record(e, v1, 0.0, v2, i2)


class IdealOpAmpLimited(Component):
    """Ideal operational amplifier with limitation (MSL Ideal.IdealOpAmpLimited): no input
    or supply currents; an auxiliary s [1] (algebraic unknown) with vin = in_p.v − in_n.v =
    (s + 1 if s < −1, s − 1 if s > 1, else 0) [V] and out.v = VMin.v if s < −1, VMax.v if
    s > 1, else (VMax.v − VMin.v)·s/2 + (VMax.v + VMin.v)/2: a nullor (vin = 0) while the
    output lies between the supply pins, the output at a supply pin (vin ≠ 0) otherwise.
    Both laws are continuous in s; their kinks are integrated across. Records vin, s."""
    in_p = PositivePin("positive pin of the input port")
    in_n = NegativePin("negative pin of the input port")
    out = PositivePin("output pin")
    VMax = PositivePin("positive output voltage limitation")
    VMin = NegativePin("negative output voltage limitation")

    def structure(self, s):
        s.algebraic("s", 0.0, "1", "auxiliary variable")

    def physics(self, e):
        sa = e.state("s")
        vin = _nullator(e, self.in_p, self.in_n)
        for pin in (self.VMax, self.VMin):
            e.flow(pin, 0.0)
        e.flow_of(self.out)
        vmax, vmin = e.potential(self.VMax), e.potential(self.VMin)
        e.residual(vin - ca.if_else(sa < -1, sa + 1, ca.if_else(sa > 1, sa - 1, 0.0)))
        e.residual(e.potential(self.out) - ca.if_else(
            sa < -1, vmin, ca.if_else(sa > 1, vmax, (vmax - vmin) * sa / 2 + (vmax + vmin) / 2)))
        e.variable("vin", vin, "V", "input voltage")
        e.variable("s", sa, "1", "auxiliary variable")


# ---- semiconductors (Modelica.Electrical.Analog.Semiconductors) ---------------------------
#: Boltzmann constant [J/K] and elementary charge [A.s], Modelica.Constants.k and .q
K_BOLTZMANN, Q_ELECTRON = 1.380649e-23, 1.602176634e-19


def exlin(x, Maxexp):
    """MSL's Semiconductors.exlin: exp(x), continued linearly (value and slope) above
    Maxexp; written exp(m)·(1 + x − m) with m = min(x, Maxexp), one expression whose
    derivative is exp(x) below Maxexp and exp(Maxexp) above (no exp of a large x)."""
    m = ca.fmin(x, Maxexp)
    return ca.exp(m) * (1 + x - m)


class Diode(_ConditionalHeatPort, OnePort):
    """Simple diode (MSL Semiconductors.Diode): an exponential diode in parallel with the
    ohmic resistance R [Ohm], i = id + v/R with id = Ids·(exlin(v/Vt, Maxexp) − 1) [A];
    Ids [A] saturation current, Vt [V] voltage equivalent of temperature (kT/qn), Maxexp
    [1] the exponent above which the characteristic is continued linearly (``exlin``).

    With the option ``useTemperatureDependency`` the device temperature T_heatPort [K]
    enters: vt_t = k·T_heatPort/q, id = Ids·(exlin(v/(N·vt_t), Maxexp) − 1) and
    i = id·(T_heatPort/TNOM)^(XTI/N)·exp((T_heatPort/TNOM − 1)·EG/(N·vt_t)) + v/R, with EG
    [eV] the activation energy, N [1] the emission coefficient, TNOM [K] the parameter
    measurement temperature, XTI [1] the saturation current's temperature exponent.
    ``useHeatPort`` defaults to useTemperatureDependency (MSL's binding); T_heatPort is
    heatPort.T with it, the parameter T (293.15 K) without. LossPower = v·i [W]. Records v,
    i, id, vt_t, LossPower, T_heatPort. The law is smooth (C1 at the knee of exlin): no
    events, and the same form with smooth=True."""
    options = {"useHeatPort": False, "useTemperatureDependency": False}
    Ids = Parameter(1e-6, "A", "saturation current")
    Vt = Parameter(0.04, "V", "voltage equivalent of temperature (kT/qn)")
    Maxexp = Parameter(15.0, "1", "max. exponent for linear continuation", positive=True)
    R = Parameter(1e8, "Ohm", "parallel ohmic resistance")
    EG = Parameter(1.11, "", "activation energy (MSL: a Real; in eV, as EG/(N*vt_t))")
    N = Parameter(1.0, "1", "emission coefficient")
    TNOM = Parameter(300.15, "K", "parameter measurement temperature", positive=True)
    XTI = Parameter(3.0, "1", "temperature exponent of saturation current")
    T = Parameter(293.15, "K", "fixed device temperature if useHeatPort = false",
                  positive=True)

    def __init__(self, name: str | None = None, **params):
        params.setdefault("useHeatPort", params.get("useTemperatureDependency", False))
        super().__init__(name, **params)

    def physics(self, e):
        v, T = self._v(e), self._T_heatPort(e)
        vt_t = K_BOLTZMANN * T / Q_ELECTRON
        if self.useTemperatureDependency:
            i_d = self.Ids * (exlin(v / (self.N * vt_t), self.Maxexp) - 1)
            aux = (T / self.TNOM - 1) * self.EG / (self.N * vt_t)
            law = i_d * (T / self.TNOM) ** (self.XTI / self.N) * ca.exp(aux) + v / self.R
        else:
            i_d = self.Ids * (exlin(v / self.Vt, self.Maxexp) - 1)
            law = i_d + v / self.R
        i = self._current(e, law)
        self._record(e, v, i)
        e.variable("id", i_d, "A", "diode current")
        e.variable("vt_t", vt_t, "V", "temperature voltage")
        self._losses(e, v * i, T)


class ZDiode(_ConditionalHeatPort, OnePort):
    """Zener diode with 3 working areas (MSL Semiconductors.ZDiode): with the ohmic
    parallel conductance v/R [A] in all three,
    forward (v > Maxexp·Vt): i = Ids·(exlin(v/Vt, Maxexp) − 1), the exponential continued
    linearly; breakdown (v + Bv < −Maxexp·Nbv·Vt): i = −Ids − Ibv·exlin(−(v + Bv)/(Nbv·Vt),
    Maxexp), the breakdown exponential continued linearly; between: i = Ids·(exp(v/Vt) − 1)
    − Ibv·exp(−(v + Bv)/(Nbv·Vt)). Ids [A] saturation current, Vt [V] voltage equivalent of
    temperature, Maxexp [1] the exponent of the linear continuation (30), R [Ohm] parallel
    resistance, Bv [V] breakthrough (Zener) voltage, Ibv [A] breakthrough knee current, Nbv
    [1] breakthrough emission coefficient. The device temperature (T [K] 293.15, or
    heatPort.T with ``useHeatPort``) does not enter the law (MSL's); LossPower = v·i [W].
    The law is continuous to round-off (MSL's smooth(1, ...)): no events."""
    Ids = Parameter(1e-6, "A", "saturation current")
    Vt = Parameter(0.04, "V", "voltage equivalent of temperature (kT/qn)", positive=True)
    Maxexp = Parameter(30.0, "1", "max. exponent for linear continuation", positive=True)
    R = Parameter(1e8, "Ohm", "parallel ohmic resistance", positive=True)
    Bv = Parameter(5.1, "V", "breakthrough voltage = Zener- or Z-voltage")
    Ibv = Parameter(0.7, "A", "breakthrough knee current")
    Nbv = Parameter(0.74, "1", "breakthrough emission coefficient", positive=True)
    T = Parameter(293.15, "K", "fixed device temperature if useHeatPort = false",
                  positive=True)

    def physics(self, e):
        v = self._v(e)
        x_forward, x_breakdown = v / self.Vt, -(v + self.Bv) / (self.Nbv * self.Vt)
        forward = self.Ids * (exlin(x_forward, self.Maxexp) - 1)
        breakdown = self.Ibv * exlin(x_breakdown, self.Maxexp)
        i = self._current(e, v / self.R + ca.if_else(
            x_forward > self.Maxexp, forward,
            ca.if_else(x_breakdown > self.Maxexp, -self.Ids - breakdown, forward - breakdown)))
        self._record(e, v, i)
        self._losses(e, v * i, self._T_heatPort(e))
