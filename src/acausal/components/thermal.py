"""Lumped thermal components after Modelica.Thermal.HeatTransfer (Components, Sources,
Sensors).

Heat ports carry the temperature T [K] and the heat flow rate Q_flow [W] into the port (into
the component); a connection set has one temperature and its heat flows sum to zero, as
compiled by ``acausal.compiler.networks``. A two-port element (MSL's ``Element1D``) has
dT = port_a.T − port_b.T and the heat flow Q_flow = port_a.Q_flow = −port_b.Q_flow from
port_a to port_b. Start values of the states are constructor keywords
(``HeatCapacitor(C=10, T_start=350)``, MSL's ``T(start=350)``).

ThermalCollector's m ports are the vector port ``port_a[1]`` .. ``port_a[m]`` (``m`` a
constructor argument, as Blocks' vector inputs). The classes of MSL's Celsius, Fahrenheit and
Rankine packages are in ``acausal.components.celsius``, ``.fahrenheit`` and ``.rankine``
(their MSL names would shadow the Kelvin classes here).

Two HeatCapacitors joined directly (or to a FixedTemperature) fix one temperature twice: a
higher-index network, refused when compiled; join them through a ThermalConductor.
"""
from __future__ import annotations

from ..core import (Component, HeatPort_a, HeatPort_b, Parameter, RealInput, RealOutput,
                    VectorPort)
from .signals.interfaces import _size, _Sized, _start

__all__ = ["Element1D", "HeatCapacitor", "ThermalConductor", "ThermalResistor", "Convection",
           "ConvectiveResistor", "BodyRadiation", "ThermalCollector", "FixedTemperature",
           "PrescribedTemperature", "FixedHeatFlow", "PrescribedHeatFlow", "TemperatureSensor",
           "RelTemperatureSensor", "HeatFlowSensor", "ConditionalFixedHeatFlowSensor", "SIGMA"]

#: Stefan-Boltzmann constant [W/(m2.K4)], Modelica.Constants.sigma
SIGMA = 5.670374419e-8
_T_FIXED = 293.15          # K, ConditionalFixedHeatFlowSensor's fixed temperature (final)


class Element1D(Component):
    """Heat flow Q_flow [W] from port_a to port_b, dT = port_a.T − port_b.T [K]
    (MSL Interfaces.Element1D)."""
    port_a = HeatPort_a("heat port a")
    port_b = HeatPort_b("heat port b")

    def _dT(self, e):
        return e.potential(self.port_a) - e.potential(self.port_b)

    def _heat_flow(self, e, value=None):
        """Q_flow: ``value`` if given, otherwise an unknown this component gives an equation
        for; port_b.Q_flow = −Q_flow. Records Q_flow and dT."""
        Q = e.flow_of(self.port_a) if value is None else value
        if value is not None:
            e.flow(self.port_a, Q)
        e.flow(self.port_b, -Q)
        e.variable("Q_flow", Q, "W", "heat flow rate from port_a -> port_b")
        e.variable("dT", self._dT(e), "K", "port_a.T - port_b.T")
        return Q


class HeatCapacitor(Component):
    """Lumped heat capacity: C·der(T) = port.Q_flow, T = port.T; state T [K] (start
    ``T_start``, 293.15 K); der_T [K/s] recorded."""
    required = ("C",)
    C = Parameter(1.0, "J/K", "heat capacity of element (= cp*m)", positive=True)
    port = HeatPort_a("heat port")

    def __init__(self, name: str | None = None, *, T_start=293.15, **params):
        super().__init__(name, **params)
        self.__dict__["T_start"] = _start(T_start, f"{type(self).__name__}: T_start")

    def structure(self, s):
        s.state("T", self.T_start, "K", "temperature of element")

    def physics(self, e):
        T, Q = e.state("T"), e.flow_of(self.port)
        e.residual(e.potential(self.port) - T)
        e.derivative(T, Q / self.C)
        e.variable("der_T", Q / self.C, "K/s", "time derivative of temperature (= der(T))")


class ThermalConductor(Element1D):
    """Heat conduction: Q_flow = G·dT [W]."""
    required = ("G",)
    G = Parameter(1.0, "W/K", "constant thermal conductance of material")

    def physics(self, e):
        self._heat_flow(e, self.G * self._dT(e))


class ThermalResistor(Element1D):
    """Heat conduction: dT = R·Q_flow [K] (R = 0 allowed: no temperature difference)."""
    required = ("R",)
    R = Parameter(1.0, "K/W", "constant thermal resistance of material", nonnegative=True)

    def physics(self, e):
        Q = self._heat_flow(e)
        e.residual(self._dT(e) - self.R * Q)


class _Convective(Component):
    """Convection from ``solid`` to ``fluid`` (MSL's Convection, ConvectiveResistor): dT =
    solid.T − fluid.T [K], Q_flow [W] from solid to fluid."""
    solid = HeatPort_a("solid side")
    fluid = HeatPort_b("fluid side")

    def _dT(self, e):
        return e.potential(self.solid) - e.potential(self.fluid)

    def _heat_flow(self, e, value=None):
        """Q_flow as Element1D._heat_flow, between solid and fluid."""
        Q = e.flow_of(self.solid) if value is None else value
        if value is not None:
            e.flow(self.solid, Q)
        e.flow(self.fluid, -Q)
        e.variable("Q_flow", Q, "W", "heat flow rate from solid -> fluid")
        e.variable("dT", self._dT(e), "K", "= solid.T - fluid.T")
        return Q


class Convection(_Convective):
    """Convection: Q_flow = Gc·dT [W] from ``solid`` to ``fluid``, dT = solid.T − fluid.T,
    the convective conductance Gc [W/K] an input."""
    Gc = RealInput("signal representing the convective thermal conductance [W/K]")

    def physics(self, e):
        self._heat_flow(e, e.input(self.Gc) * self._dT(e))


class ConvectiveResistor(_Convective):
    """Convection: dT = Rc·Q_flow [K], Q_flow [W] from ``solid`` to ``fluid``, dT = solid.T
    − fluid.T, the convective resistance Rc [K/W] an input (Rc = 0 allowed: no temperature
    difference)."""
    Rc = RealInput("signal representing the convective thermal resistance [K/W]")

    def physics(self, e):
        Q = self._heat_flow(e)
        e.residual(self._dT(e) - e.input(self.Rc) * Q)


class ThermalCollector(_Sized, Component):
    """Collects m heat flows: the m ports ``port_a[1]`` .. ``port_a[m]`` and ``port_b`` at one
    temperature, port_b.Q_flow + Σ port_a[i].Q_flow = 0. ``m`` (constructor argument, ≥ 1,
    default 3) is MSL's structural parameter ``m``."""
    _classes: dict = {}

    def __new__(cls, name=None, *, m: int = 3, **params):
        return super().__new__(cls._variant(_size(m, "ThermalCollector: m (number of "
                                                      "collected heat flows)", 1)))

    @staticmethod
    def _declare(m: int) -> dict:
        return {"port_a": VectorPort(HeatPort_a, m, "heat port a"),
                "port_b": HeatPort_b("heat port b")}

    def __init__(self, name: str | None = None, *, m: int = 3, **params):
        super().__init__(name, **params)

    @property
    def m(self) -> int:
        """Number of collected heat flows."""
        return self._key[0]

    def physics(self, e):
        T = e.potential(self.port_b)
        Q = 0.0
        for port in self.port_a:
            Q = Q + e.flow_of(port)
            e.residual(e.potential(port) - T)
        e.flow(self.port_b, -Q)


class BodyRadiation(Element1D):
    """Radiation: Q_flow = Gr·sigma·(port_a.T⁴ − port_b.T⁴) [W]."""
    required = ("Gr",)
    Gr = Parameter(1.0, "m2", "net radiation conductance between two surfaces")

    def physics(self, e):
        Ta, Tb = e.potential(self.port_a), e.potential(self.port_b)
        self._heat_flow(e, self.Gr * SIGMA * (Ta ** 4 - Tb ** 4))


class _Temperature(Component):
    """port.T = the source's temperature [K]; its heat flow is what the network takes."""
    port = HeatPort_b("heat port")

    def _T(self, e):
        raise NotImplementedError

    def physics(self, e):
        e.flow_of(self.port)
        e.residual(e.potential(self.port) - self._T(e))


class FixedTemperature(_Temperature):
    """Fixed temperature boundary: port.T = T [K]."""
    required = ("T",)
    T = Parameter(293.15, "K", "fixed temperature at port", positive=True)

    def _T(self, e):
        return self.T


class PrescribedTemperature(_Temperature):
    """Prescribed temperature: port.T = the input T [K]."""
    T = RealInput("temperature at port [K]")

    def _T(self, e):
        return e.input(self.T)


class _HeatFlow(Component):
    """port.Q_flow = −Q·(1 + alpha·(port.T − T_ref)): Q [W] injected into the network."""
    T_ref = Parameter(293.15, "K", "reference temperature", positive=True)
    alpha = Parameter(0.0, "1/K", "temperature coefficient of heat flow rate")
    port = HeatPort_b("heat port")

    def _Q(self, e):
        raise NotImplementedError

    def physics(self, e):
        T = e.potential(self.port)
        e.flow(self.port, -self._Q(e) * (1 + self.alpha * (T - self.T_ref)))


class FixedHeatFlow(_HeatFlow):
    """Fixed heat flow: Q_flow [W] flows into the component connected to port (for
    Q_flow > 0), scaled by 1 + alpha·(port.T − T_ref)."""
    required = ("Q_flow",)
    Q_flow = Parameter(0.0, "W", "fixed heat flow rate at port")

    def _Q(self, e):
        return self.Q_flow


class PrescribedHeatFlow(_HeatFlow):
    """Prescribed heat flow: the input Q_flow [W] flows into the component connected to port,
    scaled by 1 + alpha·(port.T − T_ref)."""
    Q_flow = RealInput("heat flow rate [W]")

    def _Q(self, e):
        return e.input(self.Q_flow)


class TemperatureSensor(Component):
    """Absolute temperature T [K] of ``port``; no heat flow."""
    port = HeatPort_a("heat port")
    T = RealOutput("absolute temperature as output signal [K]")

    def physics(self, e):
        e.flow(self.port, 0.0)
        e.output(self.T, e.potential(self.port))


class RelTemperatureSensor(Component):
    """Relative temperature T_rel = port_a.T − port_b.T [K]; no heat flow."""
    port_a = HeatPort_a("heat port a")
    port_b = HeatPort_b("heat port b")
    T_rel = RealOutput("relative temperature as output signal [K]")

    def physics(self, e):
        e.flow(self.port_a, 0.0)
        e.flow(self.port_b, 0.0)
        e.output(self.T_rel, e.potential(self.port_a) - e.potential(self.port_b))


class HeatFlowSensor(Component):
    """Heat flow rate Q_flow [W] from port_a to port_b; no temperature difference."""
    port_a = HeatPort_a("heat port a")
    port_b = HeatPort_b("heat port b")
    Q_flow = RealOutput("heat flow from port_a to port_b as output signal [W]")

    def physics(self, e):
        Q = e.flow_of(self.port_a)
        e.flow(self.port_b, -Q)
        e.residual(e.potential(self.port_a) - e.potential(self.port_b))
        e.output(self.Q_flow, Q)


class ConditionalFixedHeatFlowSensor(HeatFlowSensor):
    """HeatFlowSensor with, for ``useFixedTemperature=True`` (default False), port_a held at
    293.15 K (MSL's conditional FixedTemperature at port_a): Q_flow [W] is then the heat flow
    into port_b's side (−port_b.Q_flow); port_a takes what the fixed temperature supplies."""
    options = {"useFixedTemperature": False}

    def physics(self, e):
        if not self.useFixedTemperature:
            return super().physics(e)
        e.flow_of(self.port_a)
        Q = -e.flow_of(self.port_b)
        e.residual(e.potential(self.port_a) - _T_FIXED)
        e.residual(e.potential(self.port_b) - e.potential(self.port_a))
        e.output(self.Q_flow, Q)
