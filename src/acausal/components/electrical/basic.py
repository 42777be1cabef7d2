"""Basic analog electrical components (after Modelica.Electrical.Analog.Basic): Ground,
resistors and conductors (temperature dependent, with MSL's optional heat port), capacitors
and inductors (fixed, variable, saturating), the transformers, the controlled sources VCV,
VCC, CCV, CCC, the Gyrator, the electromotoric forces to rotational and translational
flanges, and Chua's NonlinearResistor."""
from __future__ import annotations

import casadi as ca
import numpy as np

from ...core import (Component, ConditionalPort, NegativePin, Parameter, Pin, PositivePin,
                     RealInput, VectorPort)
from ...core.component import BoundParameters, bound_twin, who
from ...errors import ParameterError
from .. import rotational, translational
from ..signals.interfaces import EPS, _size, _Sized, _start
from .interfaces import OnePort, TwoPort, _ConditionalHeatPort, _LimitedOpAmp


class Ground(Component):
    """Ground node: p.v = 0 [V]; its current p.i [A] is what the circuit returns to ground."""
    p = Pin("pin to be grounded")

    def physics(self, e):
        e.flow_of(self.p)
        e.residual(e.potential(self.p))


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


class OpAmp(_LimitedOpAmp):
    """Simple nonideal operational amplifier with limitation (MSL Basic.OpAmp): no input or
    supply currents, and the smooth characteristic out.v = (VMax.v + VMin.v)/2 +
    |Slope|·vin/(1 + |Slope|·|f·vin|) [V], vin = in_p.v − in_n.v [V], f = 2/(VMax.v −
    VMin.v) [1/V]: the slope |Slope| at vin = 0, out.v approaching VMax.v and VMin.v as vin
    grows (C1: no events). The output current is whatever the circuit draws (the supply
    pins carry none). MSL declares Slope with start value 10000 but no default; 10000 is
    the default here. Records vin."""
    Slope = Parameter(10000.0, "1", "slope of the out.v/vin characteristic at vin=0")

    def physics(self, e):
        vin, _ = self._input_and_output(e)
        vmax, vmin = self._limits(e)
        slope, f = ca.fabs(self.Slope), 2 / (vmax - vmin)
        law = (vmax + vmin) / 2 + slope * vin / (1 + slope * ca.fabs(f * vin))
        # divided by the slope: the residual is the input voltage's error, not that error
        # amplified by the high gain beyond round-off
        e.residual((e.potential(self.out) - law) / ca.fmax(1, slope))
        e.variable("vin", vin, "V", "input voltage")
