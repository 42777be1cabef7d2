"""The 1-D partials shared by the translational and rotational libraries, written once over
the domain, after MSL's ``Translational.Interfaces`` and ``Rotational.Interfaces``.

A domain is an ``Axis``: MSL's names and units of its position, speed and flow (``s``,
``v``, ``f`` or ``phi``, ``w``, ``tau``). ``translational`` and ``rotational`` declare their
MSL classes on top of these: the connectors (``flange``, ``flange_a``, ``flange_b``,
``support``, with MSL's descriptions), the ``axis`` and the domain's method names; the
equations are here.

Sign convention (MSL): a flange's flow (f [N], tau [N.m]) is the force or torque acting *on
the component* through that flange. The helpers that set flows name which flow they take:
``_apply_flange_flow(e, flow_into_flange)`` sets flange.f (flange.tau) and the reaction on
the support, ``_apply_opposite_flows(e, flow_into_flange_b)`` sets flange_b's flow and the
opposite on flange_a.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from enum import Enum

import casadi as ca

from ..core import Component, ConditionalPort, HeatPort_a, Parameter, RealInput
from ..core.component import who
from ..errors import ParameterError
from .signals.nonlinear import _limited, _limiter_region

__all__ = ["Axis", "TRANSLATIONAL_AXIS", "ROTATIONAL_AXIS",
           "PartialElementaryConditionalHeatPortWithoutT", "PartialElementaryConditionalHeatPort",
           "linearTemperatureDependency", "PartialEddyCurrent",
           "PartialTwoFlanges", "PartialCompliant", "PartialElementaryOneFlangeAndSupport2",
           "PartialElementaryTwoFlangesAndSupport2", "linear_law", "quadratic_law", "inverse_law",
           "Regularization", "regularized_sign", "regularization_region", "speed_band_region",
           "Position", "Speed", "Accelerate", "Move", "ConstantSpeed", "FlowToPotentialAdaptor",
           "PotentialToFlowAdaptor", "GeneralFlowToPotentialAdaptor",
           "GeneralPotentialToFlowAdaptor", "drive_flanges",
           "PartialDrivenJoint", "unit_direction"]


@dataclass(frozen=True)
class Axis:
    """MSL's names, units and words of a 1-D mechanical domain."""
    s: str              # position: "s" [m] | "phi" [rad]
    v: str              # speed: "v" [m/s] | "w" [rad/s]; the acceleration is "a"
    f: str              # flow: "f" [N] | "tau" [N.m]
    s_unit: str
    v_unit: str
    a_unit: str
    f_unit: str
    position: str       # words for descriptions
    speed: str
    acceleration: str
    flow: str


TRANSLATIONAL_AXIS = Axis("s", "v", "f", "m", "m/s", "m/s2", "N",
                          "position", "velocity", "acceleration", "force")
ROTATIONAL_AXIS = Axis("phi", "w", "tau", "rad", "rad/s", "rad/s2", "N.m",
                       "angle", "angular velocity", "angular acceleration", "torque")


# =========================================================================================
# The conditional heat port of a dissipating element
# =========================================================================================
class PartialElementaryConditionalHeatPortWithoutT(Component):
    """MSL's Thermal.HeatTransfer.Interfaces.PartialElementaryConditionalHeatPortWithoutT:
    the element records ``lossPower`` [W] (> 0 when heat flows out of the component); with
    ``useHeatPort=True`` the ``heatPort`` (HeatPort_a) exists, must be connected, and takes
    it: heatPort.Q_flow = −lossPower (the heat leaves the component into the thermal
    network). With False (MSL's default) the heat goes nowhere. The element's law does not
    depend on the port's temperature."""
    partial = True
    options = {"useHeatPort": False}
    heatPort = ConditionalPort(
        HeatPort_a("optional port to which dissipated losses are transported in form of heat",
                   required=True), "useHeatPort")

    def _loss_power(self, e, loss) -> None:
        """Record lossPower = ``loss`` [W] and, with the heat port, heatPort.Q_flow = −loss."""
        if self.useHeatPort:
            e.flow(self.heatPort, -loss)
        e.variable("lossPower", loss, "W", "loss power leaving component via heatPort (> 0, "
                                           "if heat is flowing out of component)")


class PartialElementaryConditionalHeatPort(PartialElementaryConditionalHeatPortWithoutT):
    """MSL's Thermal.HeatTransfer.Interfaces.PartialElementaryConditionalHeatPort: as
    PartialElementaryConditionalHeatPortWithoutT, and the element's law may depend on its
    temperature TheatPort [K] = heatPort.T with the port, the parameter T (293.15 K) without
    it (recorded)."""
    partial = True
    T = Parameter(293.15, "K", "fixed device temperature if useHeatPort = false",
                  positive=True)

    def _TheatPort(self, e):
        """TheatPort [K], recorded."""
        T = e.potential(self.heatPort) if self.useHeatPort else self.T
        e.variable("TheatPort", T, "K", "temperature of heatPort")
        return T


def linearTemperatureDependency(RRef, TRef, alpha20, T):
    """MSL's Electrical.Machines.Thermal.linearTemperatureDependency: a value RRef at TRef [K]
    at the temperature T [K], RRef·(1 + alphaRef·(T − TRef)) with the coefficient alpha20
    [1/K] at 20 °C converted to TRef (convertAlpha): alphaRef = alpha20/(1 + alpha20·(TRef −
    293.15))."""
    return RRef * (1 + alpha20 / (1 + alpha20 * (TRef - 293.15)) * (T - TRef))


class PartialEddyCurrent(PartialElementaryConditionalHeatPort):
    """The law shared by MSL's Translational.Sources.EddyCurrentForce and
    Rotational.Sources.EddyCurrentTorque (Kloss' equation): the braking flow
    2·nominal·excitation²·x/(1 + x²), x = speed/(speed_nominal·linearTemperatureDependency(1,
    TRef, alpha20, TheatPort)): the speed of maximum braking moves with the disc's
    temperature. lossPower = flow·speed [W]. The excitation is ``constantExcitation`` or, with
    ``useExcitationInput``, the input ``excitation``."""
    partial = True
    options = {"useExcitationInput": False}
    constantExcitation = Parameter(1.0, "1", "excitation=1 to reach maximum force or torque")
    TRef = Parameter(293.15, "K", "reference temperature", positive=True)
    alpha20 = Parameter(0.0, "1/K", "temperature coefficient of material")
    excitation = ConditionalPort(RealInput("excitation"), "useExcitationInput")

    def _braking(self, e, nominal, speed, speed_nominal):
        """(the braking flow [N, N.m], the normalized speed x)."""
        excitation = (e.input(self.excitation) if self.useExcitationInput
                      else self.constantExcitation)
        x = speed / (speed_nominal * linearTemperatureDependency(1, self.TRef, self.alpha20,
                                                                  self._TheatPort(e)))
        flow = 2 * nominal * excitation ** 2 * x / (1 + x * x)
        self._loss_power(e, flow * speed)
        return flow, x


# =========================================================================================
# Two flanges
# =========================================================================================
class PartialTwoFlanges(Component):
    """``flange_a`` and ``flange_b`` (declared by the domain)."""
    partial = True
    axis: Axis

    def _apply_opposite_flows(self, e, flow_into_flange_b) -> None:
        """flange_b.f = flow_into_flange_b, flange_a.f = −flow_into_flange_b (or .tau)."""
        e.flow(self.flange_b, flow_into_flange_b)
        e.flow(self.flange_a, -flow_into_flange_b)


class PartialCompliant(PartialTwoFlanges):
    """A flow (f [N] or tau [N.m]) = flange_b's = −flange_a's, a function of the relative
    position rel_pos = flange_b − flange_a [m, rad] and its rate rel_speed [m/s, rad/s].

    Records ``s_rel``/``phi_rel``, ``v_rel``/``w_rel``, ``f``/``tau`` (and ``a_rel`` when
    ``records_a_rel``, as MSL's rotational PartialCompliantWithRelativeStates), and
    ``lossPower`` [W] when ``loss_power`` gives one (a dissipating element also extends
    PartialElementaryConditionalHeatPortWithoutT). The domain names the law
    (``force(s_rel, v_rel)``, ``torque(phi_rel, w_rel)``) and maps ``flange_b_flow`` to it.
    ``rel_nominal`` gives the relative position's nominal (MSL's
    PartialCompliantWithRelativeStates: ``s_nominal``, ``phi_nominal``).
    """
    partial = True
    records_a_rel = False

    def rel_nominal(self):
        """The nominal magnitude of rel_pos [m, rad], or None (none declared)."""
        return None

    def flange_b_flow(self, rel_pos, rel_speed):
        """The flow into flange_b [N, N.m] (flange_a gets the opposite)."""
        raise NotImplementedError

    def state_select(self):
        """MSL's stateSelect of the relative states (the option of the elements with
        relative states: prefer by default), or None (no such option): what a reinit of
        another component keeps (see PhysicsBuilder.reinit)."""
        return self.stateSelect if "stateSelect" in self.all_options() else None

    def loss_power(self, rel_pos, rel_speed, flow):
        """Dissipated power [W] (MSL's lossPower), or None for a lossless element."""
        return None

    def _law(self, e, rel_pos, rel_speed):
        """(flow into flange_b, lossPower or None); an element whose law needs the physics
        builder (modes, events) replaces this instead of ``flange_b_flow``."""
        flow = self.flange_b_flow(rel_pos, rel_speed)
        return flow, self.loss_power(rel_pos, rel_speed, flow)

    def physics(self, e):
        x = self.axis
        rel_pos = e.pos(self.flange_b) - e.pos(self.flange_a)
        rel_speed = e.vel(self.flange_b) - e.vel(self.flange_a)
        flow, loss = self._law(e, rel_pos, rel_speed)
        self._apply_opposite_flows(e, flow)
        e.variable(f"{x.s}_rel", rel_pos, x.s_unit,
                   f"relative {x.position} (= flange_b.{x.s} - flange_a.{x.s})",
                   nominal=self.rel_nominal(), stateSelect=self.state_select())
        e.variable(f"{x.v}_rel", rel_speed, x.v_unit, f"relative {x.speed} (= der({x.s}_rel))",
                   stateSelect=self.state_select())
        if self.records_a_rel:
            e.variable("a_rel", e.acc(self.flange_b) - e.acc(self.flange_a), x.a_unit,
                       f"relative {x.acceleration} (= der({x.v}_rel))")
        e.variable(x.f, flow, x.f_unit, f"{x.flow} between flanges (= flange_b.{x.f})")
        if loss is not None:
            self._loss_power(e, loss)


# =========================================================================================
# Support (useSupport)
# =========================================================================================
class _Support(Component):
    """MSL's optional ``support`` (housing): with ``useSupport=False`` (default) the component
    is implicitly fixed to the ground (support at 0); with True the domain's ``support``
    flange exists, must be connected, and takes the reactions.

    Motion relative to the support works on ports and internal nodes alike.
    """
    axis: Axis
    options = {"useSupport": False}

    def _rel_position(self, e, port):
        """port.s − support.s [m] (port.phi − support.phi [rad])."""
        return e.pos(port) - (e.pos(self.support) if self.useSupport else 0.0)

    def _rel_speed(self, e, port):
        """der(port.s − support.s) [m/s, rad/s]."""
        return e.vel(port) - (e.vel(self.support) if self.useSupport else 0.0)

    def _rel_acc(self, e, port):
        """der(der(port.s − support.s)) [m/s², rad/s²]."""
        return e.acc(port) - (e.acc(self.support) if self.useSupport else 0.0)

    def _relative_constraint(self, s, coeffs: dict, rhs, name: str) -> None:
        """Declare Σ a_i·(port_i − support) = rhs (the support dropped when grounded)."""
        coeffs = dict(coeffs)
        if self.useSupport:
            coeffs[self.support] = -sum(coeffs.values())
        s.linear(coeffs, rhs, name)


class PartialElementaryOneFlangeAndSupport2(_Support):
    """One ``flange`` and the optional ``support``; what acts on the flange reacts on the
    support: support.f = −flange.f (support.tau = −flange.tau)."""
    partial = True

    def _apply_flange_flow(self, e, flow_into_flange) -> None:
        """flange.f = flow_into_flange (or flange.tau) and support.f = −flow_into_flange."""
        e.flow(self.flange, flow_into_flange)
        if self.useSupport:
            e.flow(self.support, -flow_into_flange)

    def _prescribe(self, s, rhs) -> None:
        """flange − support = rhs: prescribed motion (the reaction goes to the flange and,
        opposite, to the support)."""
        self._relative_constraint(s, {self.flange: 1.0}, rhs, f"{self.path}: prescribed motion")

    def _record_relative(self, e, *which: str, **given) -> None:
        """Record the flange's motion relative to the support under the domain's names
        (s, v, a / phi, w, a): ``which`` of ``"s"`` (position), ``"v"`` (speed), ``"a"``
        (acceleration) as measured, ``given`` as the values given (``a=...``)."""
        x = self.axis
        rows = {"s": (x.s, self._rel_position, x.s_unit,
                      f"{x.position} of flange with respect to support "
                      f"(= flange.{x.s} - support.{x.s})"),
                "v": (x.v, self._rel_speed, x.v_unit,
                      f"{x.speed} of flange with respect to support (= der({x.s}))"),
                "a": ("a", self._rel_acc, x.a_unit,
                      f"{x.acceleration} of flange with respect to support (= der({x.v}))")}
        for key in which + tuple(given):
            name, value, unit, description = rows[key]
            e.variable(name, given[key] if key in given else value(e, self.flange), unit,
                       description)


class PartialElementaryTwoFlangesAndSupport2(_Support):
    """``flange_a``, ``flange_b`` and the optional ``support``."""
    partial = True


# =========================================================================================
# Speed-dependent laws (Linear/Quadratic/InverseSpeedDependentForce and -Torque, SignForce
# and SignTorque)
# =========================================================================================
def unit_direction(c: Component, name: str, example: str) -> ca.SX:
    """The unit vector v/|v| of ``c``'s direction parameter ``name`` (MSL's
    normalizeWithAssert), planar or 3-D: a zero vector gives no direction and is refused
    naming the parameter."""
    v0 = c._values[name]
    if all(x == 0.0 for x in v0):
        zero = "{" + ", ".join("0" for _ in v0) + "}"
        raise ParameterError(f"{who(c)}: {name} = {zero} gives no direction; give one, "
                             f"e.g. {type(c).__name__}({name}={example})")
    v = getattr(c, name)
    return v / ca.norm_2(v)


def drive_flanges(flange_cls: type, kind: str, option: str):
    """A joint's ``axis`` and ``support``: 1-D flanges of the joint's domain (``kind``,
    "rotational" or "translational"), present if the structural option ``option`` is True
    (PlanarMechanics' useFlange, MultiBody's useAxisFlange)."""
    return (ConditionalPort(flange_cls(f"1-dim. {kind} flange that drives the joint"), option),
            ConditionalPort(flange_cls(f"1-dim. {kind} flange of the drive support (assumed "
                                       f"to be fixed in the world frame, NOT in the joint)"),
                            option))


class PartialDrivenJoint(Component):
    """A joint (planar or 3-D) with an optional 1-D drive: ``axis`` follows the joint
    coordinate and ``support`` is fixed in the world (as in PlanarMechanics and MultiBody,
    the support is *not* fixed in the joint). Unconnected, the flanges are free (no drive
    force); connected to the 1-D libraries they drive or load the joint. Subclasses declare
    the two flanges with ``drive_flanges`` under the option named ``drive_option``."""
    partial = True
    drive_option = "useFlange"

    def _driven(self) -> bool:
        return bool(getattr(self, self.drive_option))

    def _link_flange(self, s, node):
        """axis follows the joint coordinate ``node``; support is fixed in the world."""
        if self._driven():
            s.linear({self.axis: 1.0, node: -1.0}, 0.0, f"{self.path}: axis")
            s.linear({self.support: 1.0}, 0.0, f"{self.path}: support")

    def _drive_force(self, e):
        """The drive force/torque: the axis' cut flow (0 without flange)."""
        return e.cut_flow(self.axis) if self._driven() else ca.SX(0)


def linear_law(x, same_direction: bool):
    """|x| (same direction both ways: ForceDirection/TorqueDirection) or x."""
    return ca.fabs(x) if same_direction else x


def quadratic_law(x, same_direction: bool):
    """x² (same direction both ways) or x·|x|."""
    return x ** 2 if same_direction else x * ca.fabs(x)


class Regularization(str, Enum):
    """Modelica.Blocks.Types.Regularization: how RollingResistance, SignForce and SignTorque
    cross v = 0, with x = v/v0: Exp 2/(1 + exp(−x/0.01)) − 1; Sine sin(π/2·x); Linear x;
    CoSine sign(x)·(1 − cos(π/2·x)), the last three inside |x| < 1 and sign(x) outside."""
    Exp = "Exp"
    Sine = "Sine"
    Linear = "Linear"
    CoSine = "CoSine"


def regularized_sign(e, v, v0, reg: Regularization, prefix: str = ""):
    """The regularized sign(v) of MSL's RollingResistance, SignForce and SignTorque (see
    Regularization), v and v0 [m/s or rad/s]. Sine, Linear and CoSine switch at |v| = v0 by
    state events on the mode ``<prefix>region`` (declare it with ``regularization_region``),
    as Modelica's ``if abs(v) >= v0``;
    in smooth form their corners at |v| = v0 are rounded over 0.01·v0 (the width of the Exp
    form)."""
    x = v / v0
    if reg is Regularization.Exp:
        return 2 / (1 + ca.exp(-x / 0.01)) - 1
    x = _limited(e, x, -1.0, 1.0, 0.01, True, prefix)
    if reg is Regularization.Sine:
        return ca.sin(math.pi / 2 * x)
    if reg is Regularization.Linear:
        return x
    return ca.sign(x) * (1 - ca.cos(math.pi / 2 * x))


def regularization_region(s, reg: Regularization, prefix: str = "") -> None:
    """Declare the mode of ``regularized_sign`` (none for Exp, which has no band)."""
    if reg is not Regularization.Exp:
        speed_band_region(s, prefix)


def speed_band_region(s, prefix: str = "") -> None:
    """Declare the mode ``<prefix>region`` of a law switching at |v| = v0 (``inverse_law``,
    ``regularized_sign``): −1, 0, 1 for v ≤ −v0, inside, v ≥ v0."""
    _limiter_region(s, True, prefix)


def inverse_law(e, x, x0, same_direction: bool, prefix: str = ""):
    """MSL's InverseSpeedDependentForce/-Torque over x = v/v_nominal and x0 = v0/v_nominal:
    1/max(|x|, x0) (same direction both ways) or x/x0 for |x| < x0, 1/x outside (as MSL:
    a jump of 1 − 1/x0 at |x| = x0 unless v0 = v_nominal). The switch at |x| = x0 is a
    state event on the mode ``<prefix>region`` (``speed_band_region``); in smooth form it is
    rounded over 0.01·x0, as ``regularized_sign``."""
    a = x / x0
    c = _limited(e, a, -1.0, 1.0, 0.01, True, prefix)     # a inside the band, sign(a) outside
    m = 1 + ca.fabs(a) - ca.fabs(c)                        # max(|a|, 1)
    if same_direction:
        return 1 / (x0 * m)
    outside = ca.tanh((m - 1) / 0.01) if e.smooth else e.mode(f"{prefix}region") != 0
    return c / m * (1 + (1 / x0 - 1) * outside)



# =========================================================================================
# Prescribed motion of the flange relative to the support (Sources)
# =========================================================================================
class _PrescribedMotion(PartialElementaryOneFlangeAndSupport2):
    """flange − support is prescribed; its speed and position states start at 0 (MSL:
    start=0, fixed=true)."""

    def _speed_state(self, s, der=None, note: str = ""):
        """The state v/w [m/s, rad/s]; its derivative ``der`` here or later in physics."""
        x = self.axis
        return s.state(x.v, 0.0, x.v_unit, f"{x.speed} of flange with respect to support{note}",
                       der=der)

    def _position_state(self, s, der, note: str = "") -> None:
        """The state s/phi [m, rad] with derivative ``der``; flange − support follows it."""
        x = self.axis
        self._prescribe(s, s.state(x.s, 0.0, x.s_unit, f"{x.position} of flange with respect "
                                                       f"to support{note}", der=der))


class Position(_PrescribedMotion):
    """flange − support follows the reference input ``s_ref``/``phi_ref`` [m, rad]: exactly
    (``exact=True``; a function of time, differentiated twice) or through MSL's 2nd-order
    Bessel filter with cut-off f_crit [Hz] (states s/phi and v/w, from 0)."""
    partial = True
    options = {"exact": False}
    f_crit = Parameter(50.0, "Hz", "if exact=False, critical frequency of filter to filter "
                                   "input signal", positive=True)
    af = 1.3617   # s coefficient of Bessel filter
    bf = 0.6180   # s*s coefficient of Bessel filter

    def _ref(self):
        return getattr(self, f"{self.axis.s}_ref")

    def structure(self, s):
        if self.exact:
            self._prescribe(s, s.input(self._ref()))
        else:
            self._position_state(s, self._speed_state(s, note=" (filter state)"),
                                 " (filter state)")

    def physics(self, e):
        if self.exact:
            self._record_relative(e, "s", "v", "a")
            return
        w_crit = 2 * math.pi * self.f_crit
        xs, xv = e.state(self.axis.s), e.state(self.axis.v)
        a = ((e.input(self._ref()) - xs) * w_crit - self.af * xv) * (w_crit / self.bf)
        e.derivative(xv, a)
        self._record_relative(e, a=a)


class Speed(_PrescribedMotion):
    """flange − support moves with the reference speed ``v_ref``/``w_ref`` [m/s, rad/s]:
    exactly (``exact=True``; a function of time, differentiated once) or through a
    first-order filter with cut-off f_crit [Hz] (state v/w, from 0). The position s/phi is a
    state from 0."""
    partial = True
    options = {"exact": False}
    f_crit = Parameter(50.0, "Hz", "if exact=False, critical frequency of filter to filter "
                                   "input signal", positive=True)

    def _ref(self):
        return getattr(self, f"{self.axis.v}_ref")

    def structure(self, s):
        v = s.input(self._ref()) if self.exact else self._speed_state(s, note=" (filter state)")
        self._position_state(s, v)

    def physics(self, e):
        if self.exact:
            self._record_relative(e, "v", "a")
            return
        xv = e.state(self.axis.v)
        a = (e.input(self._ref()) - xv) * (2 * math.pi * self.f_crit)
        e.derivative(xv, a)
        self._record_relative(e, a=a)


class Accelerate(_PrescribedMotion):
    """flange − support accelerates with the input ``a_ref`` [m/s², rad/s²]; position and
    speed are states integrated from 0."""
    partial = True

    def structure(self, s):
        self._position_state(s, self._speed_state(s, der=s.input(self.a_ref)))

    def physics(self, e):
        self._record_relative(e, a=e.input(self.a_ref))


class Move(PartialElementaryOneFlangeAndSupport2):
    """flange − support = u[1], its speed u[2] and its acceleration u[3] as given (MSL's
    position(u, time) with its derivative functions: ``StructureBuilder.with_rates``);
    u[2], u[3] are also recorded as ``v_u``/``w_u`` and ``a_u``."""
    partial = True

    def structure(self, s):
        self._prescribe(s, s.with_rates(self.axis.s, s.input(self.u[1]), s.input(self.u[2]),
                                        s.input(self.u[3])))

    def physics(self, e):
        x = self.axis
        self._record_relative(e, "s", "v", "a")
        e.variable(f"{x.v}_u", e.input(self.u[2]), x.v_unit, f"{x.speed} input u[2]")
        e.variable("a_u", e.input(self.u[3]), x.a_unit, f"{x.acceleration} input u[3]")


class ConstantSpeed(_PrescribedMotion):
    """flange − support moves with the constant speed ``v_fixed``/``w_fixed`` [m/s, rad/s],
    whatever the flow; the position is a state from 0. Records the speed."""
    partial = True

    def _fixed(self):
        return getattr(self, f"{self.axis.v}_fixed")

    def structure(self, s):
        self._position_state(s, self._fixed())

    def physics(self, e):
        self._record_relative(e, v=self._fixed())


# =========================================================================================
# Signal adaptors of a flange (MSL's Blocks.Interfaces.Adaptors, for FMUs)
# =========================================================================================
class FlowToPotentialAdaptor(Component):
    """MSL's FlowToPotentialAdaptor on a 1-D ``flange``: the input flow acts on the flange
    (flange.f = input, flange.tau for rotation), the outputs are the flange's position and,
    where the domain's connectors exist, its speed and acceleration (0 without the speed
    connector, as MSL's der(0)). ``connectors``: the domain's names of (position, speed,
    acceleration, flow)."""
    partial = True
    connectors: tuple[str, str, str, str]

    def physics(self, e):
        pos, speed, acc, flow = self.connectors
        ports = self.ports
        e.flow(self.flange, e.input(ports[flow]))
        e.output(ports[pos], e.pos(self.flange))
        if speed in ports:
            e.output(ports[speed], e.vel(self.flange))
        if acc in ports:
            e.output(ports[acc], e.acc(self.flange) if speed in ports else 0.0)


class PotentialToFlowAdaptor(Component):
    """MSL's PotentialToFlowAdaptor on a 1-D ``flange``: the flange is moved by the input
    position, with the input speed and acceleration (where the domain's connectors exist)
    as its derivatives, not derived from the position (``StructureBuilder.with_rates``);
    the output is the flow needed to move it, −flange.f (−flange.tau). Without the speed
    connector the rates are those of the position signal (derived where a mass needs
    them; a model input has none: then only force elements without mass may be attached,
    as in MSL). ``connectors``: the domain's names of (position, speed, acceleration,
    flow)."""
    partial = True
    connectors: tuple[str, str, str, str]

    def structure(self, s):
        pos, speed, acc, _ = self.connectors
        ports = self.ports
        rates = [s.input(ports[k]) for k in (speed, acc) if k in ports]
        s.linear({self.flange: 1.0}, s.with_rates(pos, s.input(ports[pos]), *rates),
                 f"{self.path}: motion from the signals")

    def physics(self, e):
        e.output(self.ports[self.connectors[3]], -e.cut_flow(self.flange))


class _GeneralAdaptorConnectors(Component):
    """The connectors of MSL's Blocks.Interfaces.Adaptors as they are, which the domains'
    General adaptors keep: p, pder, pder2, f; ``use_pder`` and ``use_pder2`` (pder2 only with
    use_pder, as in MSL). MSL's fder, fder2 are final off in those adaptors and not
    offered."""
    partial = True
    options = {"use_pder": True, "use_pder2": True}
    connectors = ("p", "pder", "pder2", "f")

    def __init__(self, name: str | None = None, **params):
        params["use_pder2"] = params.get("use_pder", True) and params.get("use_pder2", True)
        super().__init__(name, **params)


class GeneralFlowToPotentialAdaptor(_GeneralAdaptorConnectors, FlowToPotentialAdaptor):
    """FlowToPotentialAdaptor with MSL's generic connectors (input f; outputs p, pder,
    pder2): the base of Translational's GeneralForceToPositionAdaptor and Rotational's
    GeneralTorqueToAngleAdaptor, which declare the connectors with their units."""
    partial = True


class GeneralPotentialToFlowAdaptor(_GeneralAdaptorConnectors, PotentialToFlowAdaptor):
    """PotentialToFlowAdaptor with MSL's generic connectors (inputs p, pder, pder2; output
    f): the base of Translational's GeneralPositionToForceAdaptor and Rotational's
    GeneralAngleToTorqueAdaptor, which declare the connectors with their units."""
    partial = True

