"""1-D translational mechanics, after Modelica.Mechanics.Translational (MSL 4.1).

Names, parameters, defaults and sign conventions are MSL's, so a model written against MSL
translates line by line: ``Mass(m=1, L=0.5)``, ``Force(useSupport=True)``,
``connect(force.flange, mass.flange_a)``.

Sign conventions (MSL): a flange's cut force ``f`` [N] is the force acting *on the component*
through that flange (positive in the positive s direction, Modelica's flow sign); a compliant
element's ``f`` is the force on flange_b (flange_a gets −f), ``s_rel`` = flange_b.s −
flange_a.s. A Mass's (or Rod's) ``s`` is the position of its centre: flange_a.s = s − L/2,
flange_b.s = s + L/2.

Parameters: where MSL gives a parameter only a ``start`` value (Mass.m, Spring.c, ...) that
value is the default; where MSL gives none at all (ConstantForce.f_constant, ...) the
parameter is required when the component is created (a ParameterError otherwise).

Structural (Boolean) parameters of MSL — ``useSupport``, ``exact``, ``ForceDirection`` — are
keyword arguments fixed at construction (they change the ports or the equations). With
``useSupport=False`` (the MSL default) the component is implicitly fixed to the ground at
s = 0; with ``True`` it gets a ``support`` flange (the housing) that must be connected and
receives the reaction force (support.f = −flange.f).

The equations shared with the rotational library are written once in ``interfaces``; the
classes here declare MSL's connectors and names on top of them.

Coulomb friction (SupportFriction, Brake, MassWithStopAndFriction) has MSL's mode machine
on state events (see ``friction``); MassWithStopAndFriction's stops, ElastoGap's contact and
HardStop (stops with a coefficient of restitution, not an MSL class) are state events too.
RollingResistance's regularization switches by state events too, and so does Vehicle's (a
component written with the equations of MSL's parts, see its docstring).
SignForce and InverseSpeedDependentForce switch at |v| = v0 by state events too. Not here
yet: the adaptors, InitializeFlange, RelativeStates. Differences from MSL are listed in each
docstring.
"""
from __future__ import annotations

import math

import casadi as ca

from ..core import (Component, ConditionalPort, Parameter, RealInput, RealOutput,
                    RotationalFlange, StateSelect, TranslationalFlange, VectorPort)
from ..core.ports import TRANSLATIONAL
from ..errors import ParameterError
from . import friction, interfaces, rotational
from .interfaces import (TRANSLATIONAL_AXIS, Regularization, inverse_law, linear_law,
                         quadratic_law, regularization_region, regularized_sign,
                         speed_band_region)

Flange = TranslationalFlange

__all__ = [
    # interfaces
    "PartialTwoFlanges", "PartialRigid", "PartialCompliant",
    "PartialCompliantWithRelativeStates", "PartialElementaryOneFlangeAndSupport2",
    "PartialElementaryTwoFlangesAndSupport2", "PartialFriction", "PartialForce",
    "PartialAbsoluteSensor", "PartialRelativeSensor",
    # components
    "Fixed", "Mass", "Rod", "Spring", "Damper", "SpringDamper", "SupportFriction", "Brake",
    "MassWithStopAndFriction", "ElastoGap", "HardStop", "contact_force", "RollingResistance",
    "Regularization", "IdealRollingWheel", "Vehicle", "GeneralForceToPositionAdaptor",
    "GeneralPositionToForceAdaptor",
    # sources
    "Force", "Force2", "ConstantForce", "ForceStep", "SignForce", "LinearSpeedDependentForce",
    "QuadraticSpeedDependentForce", "InverseSpeedDependentForce", "EddyCurrentForce",
    "Position", "Speed", "Accelerate", "Move",
    "ConstantSpeed",
    # sensors
    "PositionSensor", "SpeedSensor", "AccSensor", "ForceSensor", "PowerSensor",
    "MultiSensor", "RelPositionSensor", "RelSpeedSensor", "RelAccSensor",
]


# =========================================================================================
# Interfaces
# =========================================================================================
class PartialTwoFlanges(interfaces.PartialTwoFlanges):
    """Component with two translational 1-D flanges ``flange_a``, ``flange_b``."""
    partial = True
    axis = TRANSLATIONAL_AXIS
    flange_a = Flange("(left) driving flange (flange axis directed into cut plane, e. g. from "
                      "left to right)")
    flange_b = Flange("(right) driven flange (flange axis directed out of cut plane)")


class PartialRigid(PartialTwoFlanges):
    """Two rigidly connected flanges at distance ``L`` [m]; ``s`` [m] is the centre:
    flange_a.s = s − L/2, flange_b.s = s + L/2 (the forces at the flanges may differ)."""
    partial = True
    L = Parameter(0.0, "m", "length of component, from left flange to right flange "
                            "(= flange_b.s - flange_a.s)")

    def _centre(self, s):
        """The internal node ``s`` (the centre). Default: not a preferred coordinate."""
        return s.node("s", TRANSLATIONAL, preferred=False)

    def structure(self, s):
        centre = self._centre(s)
        s.linear({self.flange_a: 1.0, centre: -1.0}, (-0.5, self.L), f"{self.path}: flange_a")
        s.linear({self.flange_b: 1.0, centre: -1.0}, (0.5, self.L), f"{self.path}: flange_b")


class PartialCompliant(PartialTwoFlanges, interfaces.PartialCompliant):
    """Two flanges and a force f [N] = flange_b.f = −flange_a.f depending on s_rel and v_rel.

    Records s_rel = flange_b.s − flange_a.s [m], v_rel = der(s_rel) [m/s], f [N] and, when
    ``loss_power(s_rel, v_rel, f)`` gives one, lossPower [W]. Subclasses define
    ``force(s_rel, v_rel)``.
    """
    partial = True

    def force(self, s_rel, v_rel):
        """The force f [N] on flange_b for relative position s_rel [m] and speed v_rel [m/s]."""
        raise NotImplementedError

    def flange_b_flow(self, rel_pos, rel_speed):
        return self.force(rel_pos, rel_speed)


class PartialCompliantWithRelativeStates(PartialCompliant):
    """MSL's variant of PartialCompliant that prefers s_rel, v_rel as states. The compiler
    chooses the coordinates; ``stateSelect`` (default prefer, see StateSelect) says that
    v_rel keeps its value at another component's reinit (a stop's reinit(v, 0) takes the
    mass on the other side along). s_rel has MSL's nominal: s_nominal [m] (default
    1e-4), the scale of the error control of the state s_rel is (see
    ``CompiledModel.nominals``)."""
    partial = True
    options = {"stateSelect": StateSelect.prefer}
    s_nominal = Parameter(1e-4, "m", "nominal value of s_rel (used for scaling)")

    def rel_nominal(self):
        return self.s_nominal


class PartialElementaryOneFlangeAndSupport2(interfaces.PartialElementaryOneFlangeAndSupport2):
    """One ``flange`` and, with ``useSupport=True``, a ``support`` (housing) flange.

    What acts on the flange reacts on the support: support.f = −flange.f; s = flange.s −
    support.s [m] (support.s = 0 without support).
    """
    partial = True
    axis = TRANSLATIONAL_AXIS
    flange = Flange("flange of component")
    support = ConditionalPort(Flange("support/housing of component", required=True),
                              "useSupport")



class PartialElementaryTwoFlangesAndSupport2(PartialTwoFlanges,
                                             interfaces.PartialElementaryTwoFlangesAndSupport2):
    """``flange_a``, ``flange_b`` and, with ``useSupport=True``, a ``support`` flange."""
    partial = True
    support = ConditionalPort(Flange("support/housing of component", required=True),
                              "useSupport")


class PartialFriction(friction.PartialFriction):
    """Coulomb friction with MSL's mode machine (Translational.Interfaces.PartialFriction;
    see ``acausal.components.friction``): v_relfric [m/s], a_relfric [m/s²], f0, f0_max [N],
    mode (3 unknown, 2 free, 1 forward, 0 stuck, −1 backward), the friction force f [N] an
    algebraic variable; in smooth form f = F(|v_relfric|)·tanh(v_relfric/v_smooth)."""
    partial = True
    axis = TRANSLATIONAL_AXIS
    v_small = Parameter(1e-3, "m/s", "relative velocity near to zero", positive=True)
    v_smooth = Parameter(1e-3, "m/s", "smooth form only: f = f_pos(|v_relfric|)*"
                         "tanh(v_relfric/v_smooth) (a held block creeps at about "
                         "v_smooth*|f|/f0)", positive=True)

class PartialForce(PartialElementaryOneFlangeAndSupport2):
    """A force law on ``flange`` (relative to the support). MSL's variable ``f`` = flange.f
    [N] is recorded: a force f_constant > 0 pushing the flange's body forward has
    f = −f_constant. Subclasses define ``flange_force(e)`` (the value of flange.f)."""
    partial = True
    flange = Flange("flange of component", required=True)

    def flange_force(self, e):
        """flange.f [N] (the force on the connected body is −flange.f)."""
        raise NotImplementedError

    def physics(self, e):
        f = self.flange_force(e)
        self._apply_flange_flow(e, f)
        self._record_relative(e, "s")
        e.variable("f", f, "N", "accelerating force acting at flange (= flange.f)")


# =========================================================================================
# Components
# =========================================================================================
class Fixed(Component):
    """Flange fixed in the housing at position ``s0`` [m]."""
    s0 = Parameter(0.0, "m", "fixed offset position of housing")
    flange = Flange("flange fixed in housing at a given position")

    def structure(self, s):
        s.linear({self.flange: 1.0}, self.s0, f"{self.path}: fixed")


class Mass(PartialRigid):
    """Sliding mass with inertia ``m`` [kg] and length ``L`` [m], without friction.

    States s [m] (centre: flange_a.s = s − L/2, flange_b.s = s + L/2) and v [m/s];
    a [m/s²] recorded; m·a = flange_a.f + flange_b.f. ``stateSelect`` is a hint
    (StateSelect).

    m = 0 is allowed (MSL: min = 0), a massless flange where something else carries the
    inertia: its position is then an algebraic variable of the DAE, fixed by the forces on
    it (0 = flange_a.f + flange_b.f), and m is fixed at 0 in the compiled model (compile a
    Mass built with m > 0 to change it); a node on which nothing but given forces act is
    singular and refused at compile time.
    """
    options = {"stateSelect": StateSelect.default}
    m = Parameter(1.0, "kg", "mass of the sliding mass", nonnegative=True,
                  structural_zero=True)
    batch_physics = True

    def _centre(self, s):
        return s.node("s", TRANSLATIONAL, velocity="v", acceleration="a")

    def physics(self, e):
        e.kinetic_energy(0.5 * self.m * e.vel(e.node("s")) ** 2)


class Rod(PartialRigid):
    """Massless rod of length ``L`` [m]: flange_b.s = flange_a.s + L, 0 = flange_a.f +
    flange_b.f; ``s`` [m] is its centre."""


class Spring(PartialCompliant):
    """Linear spring: f = c·(s_rel − s_rel0); c [N/m] ≥ 0 (default 1 = MSL start value),
    s_rel0 [m] unstretched length."""
    batch_physics = True       # physics: port motion and parameters only
    c = Parameter(1.0, "N/m", "spring constant", nonnegative=True)
    s_rel0 = Parameter(0.0, "m", "unstretched spring length")

    def force(self, s_rel, v_rel):
        return self.c * (s_rel - self.s_rel0)


class Damper(PartialCompliantWithRelativeStates,
             interfaces.PartialElementaryConditionalHeatPortWithoutT):
    """Linear damper: f = d·v_rel; d [N.s/m] ≥ 0 (default 0 = MSL start value).
    lossPower = f·v_rel [W]. useHeatPort: heatPort.Q_flow = −lossPower."""
    batch_physics = True       # physics: port motion and parameters only
    d = Parameter(0.0, "N.s/m", "damping constant", nonnegative=True)

    def force(self, s_rel, v_rel):
        return self.d * v_rel

    def loss_power(self, s_rel, v_rel, f):
        return f * v_rel


class SpringDamper(PartialCompliantWithRelativeStates,
                   interfaces.PartialElementaryConditionalHeatPortWithoutT):
    """Linear spring and damper in parallel: f = c·(s_rel − s_rel0) + d·v_rel;
    c [N/m], d [N.s/m] ≥ 0 (defaults 1 = MSL start values). lossPower = d·v_rel² [W].
    useHeatPort: heatPort.Q_flow = −lossPower."""
    batch_physics = True       # physics: port motion and parameters only
    c = Parameter(1.0, "N/m", "spring constant", nonnegative=True)
    d = Parameter(1.0, "N.s/m", "damping constant", nonnegative=True)
    s_rel0 = Parameter(0.0, "m", "unstretched spring length")

    def force(self, s_rel, v_rel):
        return self.c * (s_rel - self.s_rel0) + self.d * v_rel

    def loss_power(self, s_rel, v_rel, f):
        return self.d * v_rel ** 2



class SupportFriction(PartialElementaryTwoFlangesAndSupport2, friction.SupportedFriction,
                      friction.TableFriction, PartialFriction):
    """Coulomb friction in the support: flange_b.s = flange_a.s, the friction force f [N]
    against the support, f_pos(v) [N] when sliding forward (v ≥ 0, a table constructor
    keyword of rows [v, f], default [[0, 1]]), up to f0_max = peak·f_pos(0) when stuck.
    Records s, v, a relative to the support. useHeatPort: heatPort.Q_flow = −lossPower."""
    options = {"useSupport": False}
    table_name = "f_pos"
    table_default = ((0.0, 1.0),)


class Brake(PartialElementaryTwoFlangesAndSupport2, friction.SupportedFriction,
            friction.NormalForceFriction, PartialFriction):
    """Brake based on Coulomb friction: flange_b.s = flange_a.s, the brake force f [N]
    against the support, mu·cgeo·fn when sliding, fn = fn_max·f_normalized [N]; ``mu_pos``
    (constructor keyword, rows [v, mu], default [[0, 0.5]]); free (mode 2, f = 0) when
    fn ≤ 0. fn_max defaults to 1 N (MSL's start value).
    useHeatPort: heatPort.Q_flow = −lossPower."""
    options = {"useSupport": False}
    f_normalized = RealInput("normalized force signal 0..1 (normal force = "
                             "fn_max*f_normalized; brake is active if > 0)")


def contact_force(depth, rate, c, d):
    """The pushing-only force [N] (≥ 0, pushing the bodies apart) of a contact of stiffness c
    [N/m] and damping d [N.s/m] at penetration depth [m] (> 0 in contact) closing at rate
    [m/s] (= der(depth)): MSL ElastoGap's law with n = 1, c·depth plus the damping force
    d·rate limited to ±c·depth, so that the total never pulls (0 out of contact)."""
    spring = c * ca.fmax(depth, 0.0)
    return spring + ca.fmin(ca.fmax(d * rate, -spring), spring)


def _softplus(x, width):
    """width·log(1 + exp(x/width)) [m], written so that it never overflows."""
    return ca.fmax(x, 0.0) + width * ca.log1p(ca.exp(-ca.fabs(x) / width))


class MassWithStopAndFriction(PartialRigid, PartialFriction):
    """Sliding mass with hard stops and Stribeck friction (MSL's MassWithStopAndFriction).

    A mass m [kg] of length L [m] (centre ``s``: flange_a.s = s − L/2, flange_b.s = s + L/2;
    states s [m], v [m/s]; a [m/s²] recorded) sliding on a fixed surface between the stops
    smin and smax [m] (its flange_a at ≥ smin, its flange_b at ≤ smax): m·a = flange_a.f +
    flange_b.f − f. The friction force f [N] (against v) has MSL's mode machine
    (``acausal.components.friction``); sliding forward f = F_prop·v + F_Coulomb +
    F_Stribeck·exp(−fexp·v), backward the mirror image; stuck up to f0_max = peak·f0,
    f0 = F_Coulomb + F_Stribeck. Parameters (MSL's start values as defaults): m = 1,
    F_prop = 1 [N.s/m], F_Coulomb = 5 [N], F_Stribeck = 10 [N], fexp = 2 [s/m], smax = 25,
    smin = −25 [m], v_small = 1e-3 [m/s]; ``peak`` = 1.001 is MSL's fixed factor
    f0_max = 1.001·f0 (a parameter here). free (no friction at all: f0 ≤ 0 and F_prop ≤ 0,
    between the stops) is mode 2.

    Stops (MSL's ``when stopped <> 0 then reinit(v, 0)``): when s − L/2 falls to smin or
    s + L/2 rises to smax (indicators ``gap_min``, ``gap_max`` [m], the distances to the
    stops) the velocity is set to 0; the mass is then stuck, the stop's reaction in f, and
    it stays there until f passes f0_max away from the stop (it neither breaks away nor
    slides into the stop). Records ``stopped`` (−1 at smin, +1 at smax, 0 between), mode,
    locked, sa, f, f0, f0_max, v_relfric = v, a_relfric = a, lossPower = f·v [W].
    Difference from MSL: the position is not reinitialized onto the stop; it stays where the
    impact was located, past the stop by the event location's tolerance (~1e-12·|v| m).

    Smooth form (``compile(model, smooth=True)``): the friction of PartialFriction's smooth
    form (``v_smooth``) and each stop a penalty contact of stiffness ``c_smooth`` [N/m],
    critically damped (d = 2·√(c_smooth·m), the damping force limited so that it never
    pulls, ``contact_force``): at a stop hit at speed v the mass goes past it by about
    |v|·√(m/(2·c_smooth)) (while it goes in, the limited damping force equals the spring's)
    and comes back nearly at rest; pressed by a force F it stays past it by F/c_smooth.
    useHeatPort: heatPort.Q_flow = −lossPower.
    """
    smax = Parameter(25.0, "m", "right stop for (right end of) sliding mass")
    smin = Parameter(-25.0, "m", "left stop for (left end of) sliding mass")
    m = Parameter(1.0, "kg", "mass", positive=True)
    F_prop = Parameter(1.0, "N.s/m", "velocity dependent friction", nonnegative=True)
    F_Coulomb = Parameter(5.0, "N", "constant friction: Coulomb force")
    F_Stribeck = Parameter(10.0, "N", "Stribeck effect")
    fexp = Parameter(2.0, "s/m", "exponential decay", nonnegative=True)
    peak = Parameter(1.001, "1", "f0_max = peak*f0 (MSL: fixed 1.001)")
    c_smooth = Parameter(1e7, "N/m", "smooth form only: stiffness of the stops",
                         positive=True)

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        check_stops(self, *self._limits(), "(smax - L/2) must be >= (smin + L/2), L = "
                                            f"{self.L}")

    def _centre(self, s):
        return s.node("s", TRANSLATIONAL, velocity="v", acceleration="a")

    def structure(self, s):
        PartialRigid.structure(self, s)
        PartialFriction.structure(self, s)

    def _limits(self):
        return self.smin + self.L / 2, self.smax - self.L / 2

    def _relfric(self, e):
        node = e.node("s")
        return e.vel(node), e.acc(node)

    def _sliding(self, e, v):
        # |v| as MSL: bounded where the mode's law is continued past v = 0 before the event
        return self.F_prop * v + self.F_Coulomb + self.F_Stribeck * ca.exp(
            -self.fexp * ca.fabs(v))

    def _free(self, e):
        lower, upper = self._limits()
        s = e.pos(e.node("s"))
        return ca.logic_and(ca.logic_and(self.F_Coulomb + self.F_Stribeck <= 0,
                                         self.F_prop <= 0), ca.logic_and(s > lower, s < upper))

    def _apply(self, e, f) -> None:
        e.flow(e.node("s"), f)

    def _stop(self, e):
        return e.vel(e.node("s")), 0.0

    def _can_slide(self, e):
        lower, upper = self._limits()
        s = e.pos(e.node("s"))
        return s < upper, s > lower

    def physics(self, e):
        node = e.node("s")
        s, v = e.pos(node), e.vel(node)
        e.kinetic_energy(0.5 * self.m * v ** 2)
        super().physics(e)
        lower, upper = self._limits()
        if e.smooth:
            d = 2 * ca.sqrt(self.c_smooth * self.m)
            e.flow(node, contact_force(s - upper, v, self.c_smooth, d)
                   - contact_force(lower - s, -v, self.c_smooth, d))
        else:
            e.indicator("gap_max", upper - s, "m", "distance to the stop smax")
            e.indicator("gap_min", s - lower, "m", "distance to the stop smin")
            e.reinit(v, 0.0, when="gap_max", direction=-1)
            e.reinit(v, 0.0, when="gap_min", direction=-1)
        e.variable("stopped", ca.if_else(s <= lower, -1, ca.if_else(s >= upper, 1, 0)), "",
                   "mode of stop (-1: hard stop at flange_a, 0: no stop, +1: hard stop at "
                   "flange_b)")


class ElastoGap(PartialCompliantWithRelativeStates,
                interfaces.PartialElementaryConditionalHeatPortWithoutT):
    """Spring and damper in parallel with a gap (MSL's ElastoGap): they act only in contact,
    s_rel < s_rel0, and only push.

    With the compression δ = s_rel0 − s_rel [m]: contact (δ > 0) f_c = −f_ref·|δ/s_ref|^n,
    f_ref = c·s_ref (MSL's binding; not a parameter of its own here), the damping force
    d·v_rel limited to |f_d| ≤ |f_c| (so f = f_c + f_d never pulls), f = 0 out of contact;
    lossPower = f_d·v_rel [W]. Parameters: c [N/m], d [N.s/m] ≥ 0 (defaults 1 = MSL's start
    values), s_rel0 [m] (0), s_ref [m] (1), n ≥ 1 (1). Records s_rel, v_rel, f, lossPower and
    ``contact``, a Boolean mode changed at the state event of indicator ``compression``
    (δ crossing 0, MSL's event of ``contact = s_rel < s_rel0``), so that the integrator
    restarts at the kink instead of stepping across it. The law itself is written in δ (as
    MSL's noEvent expressions), not switched on the mode: while the integrator runs ahead
    of a crossing not located yet, the bodies keep touching as they should (switched off,
    two plates preloaded by a spring would ring undamped for the rest of the run). The
    limit of f_d has no events (MSL: noEvent). useHeatPort: heatPort.Q_flow = −lossPower.

    Smooth form (``compile(model, smooth=True)``): no mode and no event; the compression
    is δ⁺ = s_smooth·log(1 + exp(δ/s_smooth)) (named parameter s_smooth [m], default 1e-6)
    in f_c, and the damping force |f_c|·tanh(d·v_rel/(|f_c| + f_s)), f_s = f_ref·(s_smooth/
    s_ref)^n the spring force at δ = s_smooth (so that out of contact it fades smoothly
    instead of becoming a step in v_rel). Error against the exact law: δ⁺ exceeds max(δ, 0)
    by at most s_smooth·ln 2 (at δ = 0) and by less than s_smooth·exp(−|δ|/s_smooth)
    elsewhere, so f_c by at most f_ref·(s_smooth·ln 2/s_ref)^n (n = 1: c·s_smooth·ln 2); in
    contact (|f_c| ≫ f_s) the damping force differs from the limited d·v_rel by at most
    0.24·|f_c| (where d·|v_rel| ≈ |f_c|), and by less than |d·v_rel|³/(3·|f_c|²) +
    |d·v_rel|·f_s/|f_c| below it.
    """
    c = Parameter(1.0, "N/m", "spring constant", nonnegative=True)
    d = Parameter(1.0, "N.s/m", "damping constant", nonnegative=True)
    s_rel0 = Parameter(0.0, "m", "unstretched spring length")
    s_ref = Parameter(1.0, "m", "reference relative compression at which f_c = f_ref "
                                "(= c*s_ref)", positive=True)
    n = Parameter(1.0, "1", "exponent of spring force ( f_c = -f_ref*|(s_rel-s_rel0)/s_ref|^n )",
                  positive=True)
    s_smooth = Parameter(1e-6, "m", "smooth form only: width of the contact's regularization",
                         positive=True)

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        if self.n < 1:
            raise ParameterError(f"parameter '{type(self).__name__}.n' must be >= 1 (MSL: "
                                 f"min = 1), got {self.n}")

    def structure(self, s):
        if not s.smooth:
            s.mode("contact", 0, values=(0, 1),
                   description="= true, if contact, otherwise no contact")

    def _law(self, e, s_rel, v_rel):
        depth = self.s_rel0 - s_rel
        f_ref = self.c * self.s_ref
        if e.smooth:
            f_c = -f_ref * (_softplus(depth, self.s_smooth) / self.s_ref) ** self.n
            f_s = f_ref * (self.s_smooth / self.s_ref) ** self.n
            f_d = -f_c * ca.tanh(self.d * v_rel / (f_s - f_c))
            e.variable("contact", depth > 0, "", "= true, if contact, otherwise no contact")
        else:
            e.indicator("compression", depth, "m", "compression s_rel0 - s_rel")
            e.mode_update(e.mode("contact"), depth > 0)
            f_c = -f_ref * (ca.fmax(depth, 0.0) / self.s_ref) ** self.n
            f_d = ca.fmin(ca.fmax(self.d * v_rel, f_c), -f_c)
        return f_c + f_d, f_d * v_rel


class HardStop(PartialElementaryOneFlangeAndSupport2):
    """Hard stops with a coefficient of restitution: the position s = flange.s − support.s
    [m] of the body connected to ``flange`` stays in [smin, smax]. Not an MSL class (MSL's
    stops are MassWithStopAndFriction's, which end every impact at rest, and ElastoGap, a
    compliant contact); written after MSL's conventions.

    Between impacts it exerts no force. An impact (indicator ``gap_max`` = smax − s while
    approaching smax, v > 0; ``gap_min`` = s − smin while approaching smin) sets the
    velocity v = der(s) [m/s] to −e·v (Modelica's ``reinit(v, -e*pre(v))``), or to 0 when
    the impact speed |v| is below v_small [m/s]: the body then rests at the stop (mode
    ``stopped`` = +1 at smax, −1 at smin, 0 free), held by the force f [N] = flange.f
    (an algebraic variable: the relative acceleration is 0), until that force would pull
    (indicator ``release``). So a body bouncing under a constant force comes to rest after
    about log(v_small/v1)/log(e) impacts instead of an endless (Zeno) accumulation.
    Parameters: smax = 25, smin = −25 [m] (MSL's MassWithStopAndFriction), e = 0.8 [1]
    (0 ≤ e ≤ 1), v_small = 1e-3 [m/s]. Records s, v, f, contact (= true, if resting at a
    stop), stopped. The position is not reinitialized onto the stop: it is where the impact
    was located (past the stop by ~1e-12·|v| m).

    Smooth form (``compile(model, smooth=True)``): each stop a penalty contact of stiffness
    ``c_smooth`` [N/m] and damping ``d_smooth`` [N.s/m], the damping force limited so that
    it never pulls (``contact_force``); no modes, no events, e not used. For a body of mass
    m hitting a stop at speed v with d_smooth = 0 it goes past the stop by |v|·√(m/c_smooth)
    and leaves it after π·√(m/c_smooth) s at the same speed (restitution 1); with damping
    the restitution falls (about exp(−ζπ/√(1 − ζ²)), ζ = d_smooth/(2·√(c_smooth·m)), for a
    linear damper; the limit keeps it higher) and the penetration towards
    |v|·√(m/(2·c_smooth)) (the damping force saturates at the spring's while it goes in).
    """
    flange = Flange("flange of the body the stops hold", required=True)
    smax = Parameter(25.0, "m", "upper stop of s = flange.s - support.s")
    smin = Parameter(-25.0, "m", "lower stop of s = flange.s - support.s")
    e = Parameter(0.8, "1", "coefficient of restitution (speed after / speed before impact)",
                  nonnegative=True)
    v_small = Parameter(1e-3, "m/s", "impact speed below which the body rests at the stop",
                        positive=True)
    c_smooth = Parameter(1e7, "N/m", "smooth form only: stiffness of the stops", positive=True)
    d_smooth = Parameter(1e3, "N.s/m", "smooth form only: damping of the stops",
                         nonnegative=True)

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        if self.e > 1:
            raise ParameterError(f"parameter '{type(self).__name__}.e' (coefficient of "
                                 f"restitution) must be in [0, 1], got {self.e}")
        check_stops(self, self.smin, self.smax, "smax must be >= smin")

    def structure(self, s):
        if not s.smooth:
            s.mode("stopped", 0, values=(-1, 0, 1),
                   description="-1: resting at smin, 0: free, +1: resting at smax")
            s.algebraic("f", unit="N", description="force of the stops on the flange "
                                                   "(= flange.f)")

    def physics(self, e):
        s, v = self._rel_position(e, self.flange), self._rel_speed(e, self.flange)
        self._record_relative(e, "s", "v")
        if e.smooth:
            f = contact_force(s - self.smax, v, self.c_smooth, self.d_smooth) \
                - contact_force(self.smin - s, -v, self.c_smooth, self.d_smooth)
            self._apply_flange_flow(e, f)
            e.variable("f", f, "N", "force of the stops on the flange (= flange.f)")
            e.variable("contact", ca.logic_or(s > self.smax, s < self.smin), "",
                       "= true, if in contact with a stop")
            return
        stopped, f = e.mode("stopped"), e.state("f")
        a = self._rel_acc(e, self.flange)
        e.residual(ca.if_else(stopped == 0, f, a))
        self._apply_flange_flow(e, f)
        e.indicator("gap_max", ca.if_else(v > 0, self.smax - s, 1.0), "m",
                    "distance to smax while approaching it")
        e.indicator("gap_min", ca.if_else(v < 0, s - self.smin, 1.0), "m",
                    "distance to smin while approaching it")
        e.indicator("release", ca.if_else(stopped == 1, f, ca.if_else(stopped == -1, -f, 1.0)),
                    "N", "force pushing the flange into the stop it rests at")
        after = ca.if_else(ca.fabs(v) < self.v_small, 0.0, -self.e * v)
        for when in ("gap_max", "gap_min"):
            e.reinit(e.vel(self.flange), e.vel(self.flange) - v + after, when=when,
                     direction=-1)
        at_max = ca.logic_and(s >= self.smax, v == 0)
        at_min = ca.logic_and(s <= self.smin, v == 0)
        e.mode_update(stopped, ca.if_else(
            stopped == 1, f >= 0, ca.if_else(stopped == -1, -(f <= 0), ca.if_else(
                ca.logic_and(at_max, a > 0), 1, ca.if_else(ca.logic_and(at_min, a < 0),
                                                           -1, 0)))))
        e.variable("contact", stopped != 0, "", "= true, if resting at a stop")


def check_stops(component, lower, upper, what: str) -> None:
    """A ParameterError naming the component's smax unless upper ≥ lower."""
    if upper < lower:
        raise ParameterError(f"parameter '{type(component).__name__}.smax' = "
                             f"{component.smax} with smin = {component.smin}: {what}")


def _signal_or(e, component, port: str, option: str, constant):
    """The input ``port`` of ``component`` if its option ``option`` is on, else ``constant``."""
    return e.input(getattr(component, port)) if getattr(component, option) else constant


class RollingResistance(PartialForce):
    """Resistance of a rolling wheel (MSL's Components.RollingResistance): the wheel load
    fWeight [N] (default 0 = MSL start value) on a road of inclination tan(α) gives the
    nominal resistance f_nominal = −Cr·fWeight·cos(atan(inclination)) [N] (recorded), and
    f = flange.f = −f_nominal·sign(v) regularized within [−v0, v0] (``reg``, default Exp,
    see Regularization; v0 [m/s] default 0.1), v = der(s) [m/s] recorded relative to the
    support: it brakes the body on the flange in either direction.

    Cr is CrConstant (default 0.01) or, with ``useCrInput``, the input ``cr``; the
    inclination is inclinationConstant (default 0) or, with ``useInclinationInput``, the
    input ``inclination`` (positive uphill for positive v)."""
    options = {"useCrInput": False, "useInclinationInput": False,
               "reg": Regularization.Exp}
    fWeight = Parameter(0.0, "N", "wheel load due to gravity")
    CrConstant = Parameter(0.01, "1", "constant rolling resistance coefficient")
    inclinationConstant = Parameter(0.0, "1", "constant inclination = tan(angle)")
    v0 = Parameter(0.1, "m/s", "regularization below v0", positive=True)
    inclination = ConditionalPort(RealInput("inclination=tan(angle)"), "useInclinationInput")
    cr = ConditionalPort(RealInput("rolling resistance coefficient"), "useCrInput")

    def structure(self, s):
        regularization_region(s, self.reg)

    def flange_force(self, e):
        cr = _signal_or(e, self, "cr", "useCrInput", self.CrConstant)
        inclination = _signal_or(e, self, "inclination", "useInclinationInput",
                                 self.inclinationConstant)
        v = self._rel_speed(e, self.flange)
        self._record_relative(e, "v")
        f_nominal = -cr * self.fWeight * ca.cos(ca.atan(inclination))
        e.variable("f_nominal", f_nominal, "N",
                   "nominal rolling resistance without regularization")
        return -f_nominal * regularized_sign(e, v, self.v0, self.reg)


#: Translational.Components.IdealRollingWheel is MSL's Rotational one.
IdealRollingWheel = rotational.IdealRollingWheel

_V_REF = 1.0               # m/s, Vehicle's reference velocity of the air drag (MSL's vRef)
_WIND_F_CRIT = 50.0        # Hz, cut-off of Vehicle's wind filter (windSpeed's default f_crit)


class Vehicle(Component):
    """Simple vehicle model (MSL's Components.Vehicle): mass, drive-train inertia, wheel,
    air drag, rolling resistance and inclination resistance.

    Driven at the rotational ``flangeR`` (the drive-train inertia J [kg.m²] and a wheel of
    radius R [m]: R·flangeR.phi = s), coupled to other vehicles at the translational
    ``flangeT`` (flangeT.s = s); either may be left unconnected. Records s [m] (state,
    start 0), v [m/s] (state, start 0), a [m/s²]. With α = atan(inclination)::

        (m + J/R²)·a = flangeR.tau/R + flangeT.f − fDrag.f − fRoll.f + fGrav.f
        fDrag.f = Cd·A·rho/2·(v − vWind)·|v − vWind|     (air drag, recorded)
        fRoll.f = Cr·m·g·cos(α)·reg(v/vReg)              (rolling, recorded)
        fGrav.f = −m·g·sin(α)                            (inclination, recorded)

    with flangeR.tau, flangeT.f the torque and force the connected parts exert, reg MSL's
    Linear regularization (v/vReg inside |v| < vReg, sign(v) outside: state events at |v|
    = vReg, mode ``fRoll.region``; see RollingResistance). The signs are MSL's parts':
    fDrag.f, fRoll.f are the flange forces of its QuadraticSpeedDependentForce and
    RollingResistance (positive when they brake forward motion), fGrav.f the input of its
    Force (positive pushing forward).

    Parameters: m [kg] > 0, J [kg.m²] ≥ 0, R [m] > 0 (required: MSL gives no defaults),
    g [m/s²] (9.80665), A [m²] (1), Cd (0.5), rho [kg/m³] (1.2), vWindConstant [m/s] (0),
    CrConstant (0.015), vReg [m/s] (1e-3), inclinationConstant (0, = tan(α), positive
    uphill). Options useWindInput, useCrInput, useInclinationInput give the inputs
    ``vWind`` [m/s], ``cr`` and ``inclination`` in place of the constants. As MSL's
    windSpeed (Sources.Speed, 50 Hz filter), an input wind passes a first-order filter
    of cut-off 50 Hz, its output the state ``vWindFiltered`` [m/s] starting at vWind(0).

    Differences from MSL: MSL composes Vehicle of Mass, Inertia, IdealRollingWheel,
    QuadraticSpeedDependentForce, RollingResistance, Force, Speed and Blocks.Math blocks
    (Atan, Sin, Gain); here its equations are written directly, with the laws of those
    parts (``quadratic_law``, ``regularized_sign``): a composed acausal Model cannot bind
    its parts' parameters to its own (m enters mass.m, fRoll.fWeight = m·g and
    gravForceGain.k = −m·g), so m, g, Cd, ... would not be parameters of the compiled model
    that can be changed at simulation time. The parts' variables other than the forces
    (mass.*, inertia.*, fDrag.v, ...) are not recorded; s, v, a are the mass's.
    """
    options = {"useWindInput": False, "useCrInput": False, "useInclinationInput": False}
    m = Parameter(1.0, "kg", "total mass of vehicle", positive=True)
    g = Parameter(9.80665, "m/s2", "constant gravity acceleration")
    J = Parameter(0.0, "kg.m2", "total rotational inertia of drive train", nonnegative=True)
    R = Parameter(1.0, "m", "wheel radius", positive=True)
    A = Parameter(1.0, "m2", "cross section of vehicle")
    Cd = Parameter(0.5, "1", "drag resistance coefficient")
    rho = Parameter(1.2, "kg/m3", "density of air")
    vWindConstant = Parameter(0.0, "m/s", "constant wind velocity")
    CrConstant = Parameter(0.015, "1", "constant rolling resistance coefficient")
    vReg = Parameter(1e-3, "m/s", "velocity for regularization around 0", positive=True)
    inclinationConstant = Parameter(0.0, "1", "constant inclination = tan(angle)")
    required = ("m", "J", "R")
    flangeT = Flange("translational flange")
    flangeR = RotationalFlange("rotational flange")
    inclination = ConditionalPort(RealInput("inclination=tan(angle)"), "useInclinationInput")
    cr = ConditionalPort(RealInput("rolling resistance coefficient"), "useCrInput")
    vWind = ConditionalPort(RealInput("wind velocity [m/s]"), "useWindInput")

    def structure(self, s):
        body = s.node("s", TRANSLATIONAL, velocity="v", acceleration="a")
        s.linear({self.flangeT: 1.0, body: -1.0}, 0.0, f"{self.path}: flangeT")
        s.linear({self.flangeR: self.R, body: -1.0}, 0.0, f"{self.path}: R*flangeR.phi = s")
        regularization_region(s, Regularization.Linear, "fRoll.")
        if self.useWindInput:
            s.state("vWindFiltered", 0.0, "m/s", "wind velocity, filtered (MSL's windSpeed.v)")

    def physics(self, e):
        body = e.node("s")
        v = e.vel(body)
        e.kinetic_energy(0.5 * (self.m + self.J / self.R ** 2) * v ** 2)
        inclination = _signal_or(e, self, "inclination", "useInclinationInput",
                                 self.inclinationConstant)
        cr = _signal_or(e, self, "cr", "useCrInput", self.CrConstant)
        alpha = ca.atan(inclination)
        f_drag = self.Cd * self.A * self.rho * _V_REF ** 2 / 2 * quadratic_law(
            (v - self._wind(e)) / _V_REF, False)
        f_roll = cr * self.m * self.g * ca.cos(alpha) * regularized_sign(
            e, v, self.vReg, Regularization.Linear, "fRoll.")
        f_grav = -self.m * self.g * ca.sin(alpha)
        e.flow(body, f_drag + f_roll - f_grav)
        e.variable("fDrag.f", f_drag, "N", "air drag (flange force of fDrag)")
        e.variable("fRoll.f", f_roll, "N", "rolling resistance (flange force of fRoll)")
        e.variable("fGrav.f", f_grav, "N", "inclination force on the vehicle (input of fGrav)")

    def _wind(self, e):
        """The wind velocity [m/s]: vWindConstant, or the input vWind through the filter."""
        if not self.useWindInput:
            return self.vWindConstant
        filtered, wind = e.state("vWindFiltered"), e.input(self.vWind)
        e.derivative(filtered, (wind - filtered) * 2 * math.pi * _WIND_F_CRIT)
        e.initial(filtered - wind, "vWindFiltered = vWind")
        return filtered


class GeneralForceToPositionAdaptor(interfaces.GeneralFlowToPotentialAdaptor):
    """Signal adaptor of a flange with the position, speed and acceleration as outputs and
    the force as input (MSL Components.GeneralForceToPositionAdaptor, for FMUs): flange.f
    = f [N]; p = flange.s [m], pder = der(p) [m/s] (option ``use_pder``), pder2 = der(pder)
    [m/s²] (option ``use_pder2``, only with ``use_pder`` as in MSL). MSL's inputs of the
    force's derivatives are final off there and not offered. The block with a mass behind
    it is what an FMU of a flange "with states" exposes (see
    models.translational_fmus.DirectMass)."""
    flange = Flange("flange", required=True)
    p = RealOutput("output for potential: position s [m]")
    pder = ConditionalPort(RealOutput("optional output for der(potential): velocity v "
                                      "[m/s]"), "use_pder")
    pder2 = ConditionalPort(RealOutput("optional output for der2(potential): acceleration "
                                       "a [m/s2]"), "use_pder2")
    f = RealInput("input for flow: force f [N]")


class GeneralPositionToForceAdaptor(interfaces.GeneralPotentialToFlowAdaptor):
    """Signal adaptor of a flange with the force as output and the position, speed and
    acceleration as inputs (MSL Components.GeneralPositionToForceAdaptor, for FMUs): the
    flange moves with the position p [m], its speed pder [m/s] (option ``use_pder``) and
    acceleration pder2 [m/s²] (option ``use_pder2``, only with ``use_pder`` as in MSL) as
    given (the user's to keep consistent, as in MSL); f = −flange.f [N], the force needed
    to move it so. MSL's outputs of the force's derivatives are final off there and not
    offered."""
    flange = Flange("flange", required=True)
    p = RealInput("input for potential: position s [m]")
    pder = ConditionalPort(RealInput("optional input for der(potential): velocity v [m/s]"),
                           "use_pder")
    pder2 = ConditionalPort(RealInput("optional input for der2(potential): acceleration a "
                                      "[m/s2]"), "use_pder2")
    f = RealOutput("output for flow: force f [N] needed to move the flange so")


# =========================================================================================
# Sources
# =========================================================================================
class Force(PartialElementaryOneFlangeAndSupport2):
    """External force: the input signal ``f`` [N] drives the body connected to ``flange`` in
    the positive direction (flange.f = −f; support.f = f with useSupport)."""
    f = RealInput("driving force as input signal [N]")
    flange = Flange("flange of component", required=True)

    def physics(self, e):
        self._apply_flange_flow(e, -e.input(self.f))
        self._record_relative(e, "s")


class Force2(PartialTwoFlanges):
    """Input signal ``f`` [N] acting on two flanges: flange_a.f = f, flange_b.f = −f
    (a positive f pushes the two connected bodies apart)."""
    f = RealInput("driving force as input signal [N]")
    flange_a = Flange("left flange of component", required=True)
    flange_b = Flange("right flange of component", required=True)

    def physics(self, e):
        self._apply_opposite_flows(e, -e.input(self.f))


class ConstantForce(PartialForce):
    """Constant force f_constant [N] on the flange's body, not dependent on speed
    (f = flange.f = −f_constant). Required: f_constant (MSL gives no default)."""
    f_constant = Parameter(0.0, "N", "nominal force (if negative, force is acting as load in "
                                     "positive direction of motion)")
    required = ("f_constant",)

    def flange_force(self, e):
        return -self.f_constant


class ForceStep(PartialForce):
    """Force step: f = −offsetForce − (0 if time < startTime else stepForce) [N].

    The jump at startTime is a time event: the integrator restarts there.
    """
    stepForce = Parameter(1.0, "N", "height of force step (if negative, force is acting as "
                                    "load)")
    offsetForce = Parameter(0.0, "N", "offset of force")
    startTime = Parameter(0.0, "s", "force = offset for time < startTime")

    def flange_force(self, e):
        e.time_event(self.startTime)
        return -self.offsetForce - ca.if_else(e.time < self.startTime, 0.0, self.stepForce)


class _SpeedDependentForce(PartialForce):
    """f = −f_nominal·law(v/v_nominal), v = der(s) [m/s] (recorded); ``ForceDirection`` picks
    the law. Required: f_nominal [N], v_nominal [m/s] > 0 (MSL gives no defaults)."""
    options = {"ForceDirection": True}
    f_nominal = Parameter(0.0, "N", "nominal force (if negative, force is acting as load in "
                                    "positive direction of motion)")
    v_nominal = Parameter(1.0, "m/s", "nominal speed", positive=True)
    required = ("f_nominal", "v_nominal")

    def flange_force(self, e):
        self._record_relative(e, "v")
        return -self.f_nominal * self.law(e, self._rel_speed(e, self.flange) / self.v_nominal)


class EddyCurrentForce(PartialForce, interfaces.PartialEddyCurrent):
    """MSL's simple translational eddy current brake: the braking force f = flange.f =
    2·f_nominal·excitation²·v_normalized/(1 + v_normalized²) [N], v_normalized =
    v/(v_nominal·(1 + alphaRef·(TheatPort − TRef))) (see interfaces.PartialEddyCurrent);
    lossPower = f·v [W], to the heatPort with useHeatPort. Required: f_nominal [N],
    v_nominal [m/s] > 0 (MSL gives no defaults); TRef 293.15 K, alpha20 0 1/K, T 293.15 K.
    Records s, v (relative to the support), f, v_normalized, lossPower, TheatPort."""
    required = ("f_nominal", "v_nominal")
    f_nominal = Parameter(0.0, "N", "constant maximum force (always braking)")
    v_nominal = Parameter(1.0, "m/s", "nominal speed (leads to maximum force) at reference "
                                      "temperature", positive=True)

    def flange_force(self, e):
        self._record_relative(e, "v")
        f, x = self._braking(e, self.f_nominal, self._rel_speed(e, self.flange), self.v_nominal)
        e.variable("v_normalized", x, "1", "relative speed v/v_nominal")
        return f


class LinearSpeedDependentForce(_SpeedDependentForce):
    """f = −f_nominal·|v/v_nominal| (ForceDirection=True: same direction both ways) or
    −f_nominal·v/v_nominal (ForceDirection=False)."""

    def law(self, e, x):
        return linear_law(x, self.ForceDirection)


class QuadraticSpeedDependentForce(_SpeedDependentForce):
    """f = −f_nominal·(v/v_nominal)² (ForceDirection=True: same direction both ways) or
    −f_nominal·(v/v_nominal)·|v/v_nominal| (ForceDirection=False)."""

    def law(self, e, x):
        return quadratic_law(x, self.ForceDirection)


class InverseSpeedDependentForce(_SpeedDependentForce):
    """f = −f_nominal·v_nominal/max(|v|, v0) (ForceDirection=True: same direction both ways)
    or −f_nominal·v/v0 for |v| < v0 and −f_nominal·v_nominal/v outside (ForceDirection=False;
    as MSL, a jump at |v| = v0 unless v0 = v_nominal). The switch at |v| = v0 is a state
    event (mode ``region``; rounded over 0.01·v0 in smooth form). v0 [m/s] > 0 (default 0.1
    = MSL start value)."""
    v0 = Parameter(0.1, "m/s", "regularization below v0", positive=True)

    def structure(self, s):
        speed_band_region(s)

    def law(self, e, x):
        return inverse_law(e, x, self.v0 / self.v_nominal, self.ForceDirection)


class SignForce(PartialForce):
    """Constant force changing sign with speed: f = −f_nominal·sign(v), v = der(s) [m/s]
    (recorded), regularized within [−v0, v0] by ``reg`` (default Exp, see
    Regularization). Required: f_nominal [N] (MSL gives no default; negative: a load);
    v0 [m/s] > 0 (default 0.1 = MSL start value)."""
    options = {"reg": Regularization.Exp}
    f_nominal = Parameter(0.0, "N", "nominal force (if negative, force is acting as load)")
    v0 = Parameter(0.1, "m/s", "regularization below v0", positive=True)
    required = ("f_nominal",)

    def structure(self, s):
        regularization_region(s, self.reg)

    def flange_force(self, e):
        self._record_relative(e, "v")
        return -self.f_nominal * regularized_sign(e, self._rel_speed(e, self.flange), self.v0,
                                                  self.reg)


class Position(PartialElementaryOneFlangeAndSupport2, interfaces.Position):
    """Forced movement of ``flange`` (relative to the support) by the reference position
    ``s_ref`` [m].

    exact=False (default, as MSL): s_ref passes MSL's 2nd-order (Bessel) filter with cut-off
    f_crit [Hz] (default 50): a = ((s_ref − s)·w_crit − af·v)·(w_crit/bf), w_crit = 2π·f_crit,
    af = 1.3617, bf = 0.6180; states s [m], v [m/s] (any signal works, model inputs too).
    exact=True: flange.s − support.s = s_ref exactly; s_ref must be a function of time (its
    first two derivatives are taken by algorithmic differentiation).

    Differences from MSL: the filter starts at s = 0, v = 0 (MSL: s = s_ref(0) by an initial
    equation): when s_ref(0) ≠ 0 give ``x0={"<name>.s": s_ref(0)}``. With exact=True, v and a
    are the actual relative speed and acceleration (MSL: dummies 0).
    """
    s_ref = RealInput("reference position of flange as input signal [m]")


class Speed(PartialElementaryOneFlangeAndSupport2, interfaces.Speed):
    """Forced movement of ``flange`` (relative to the support) by the reference speed
    ``v_ref`` [m/s]. s = ∫v is a state (start 0, as MSL's s(start=0, fixed=true)).

    exact=False (default): v follows v_ref through a first-order filter with cut-off f_crit
    [Hz]: a = (v_ref − v)·2π·f_crit; v is a state (any signal works).
    exact=True: v = v_ref exactly; v_ref must be a function of time (differentiated once).

    Differences from MSL: the filter starts at v = 0 (MSL: v = v_ref(0) by an initial
    equation): give ``x0={"<name>.v": v_ref(0)}`` when it differs. With exact=True, a is the
    actual acceleration (MSL: dummy 0).
    """
    v_ref = RealInput("reference speed of flange as input signal [m/s]")


class Accelerate(PartialElementaryOneFlangeAndSupport2, interfaces.Accelerate):
    """Forced movement of ``flange`` (relative to the support) by the acceleration signal
    ``a_ref`` [m/s²]; s [m] and v [m/s] are states integrated from 0 (MSL: start=0,
    fixed=true)."""
    a_ref = RealInput("absolute acceleration of flange as input signal [m/s2]")


class Move(PartialElementaryOneFlangeAndSupport2, interfaces.Move):
    """Forced movement of ``flange`` (relative to the support) by the signals ``u[1]``
    (position [m]), ``u[2]`` (velocity [m/s]), ``u[3]`` (acceleration [m/s²]), numbered from 1
    as in MSL: ``connect(src.y, move.u[1])``. As in MSL, u[2] and u[3] are taken as the
    derivatives of u[1], not derived from it: consistent signals are the user's to give
    (MSL's deliberately inconsistent u[2] = u[3] = 0 gives position-dependent forces only).
    Records u[2], u[3] as ``v_u``, ``a_u`` (equal to ``v``, ``a``).
    """
    u = VectorPort(RealInput, 3, tuple(f"{what} of flange as input signal" for what in
                                       ("position", "velocity", "acceleration")))


class ConstantSpeed(PartialElementaryOneFlangeAndSupport2, interfaces.ConstantSpeed):
    """Constant speed v = v_fixed [m/s] of flange relative to support, not dependent on
    force; s [m] is a state (start 0). Records v and f = flange.f [N] (the reaction, as
    MSL's PartialForce). Required: v_fixed (MSL gives no default)."""
    v_fixed = Parameter(0.0, "m/s", "fixed speed (if negative, force is acting as load)")
    required = ("v_fixed",)
    flange = Flange("flange of component", required=True)

    def physics(self, e):
        super().physics(e)
        e.variable("f", e.cut_flow(self.flange), "N", "accelerating force acting at flange "
                                                      "(= flange.f)")


# =========================================================================================
# Sensors
# =========================================================================================
class PartialAbsoluteSensor(Component):
    """Measures an absolute quantity of ``flange`` (no force: flange.f = 0)."""
    partial = True
    flange = Flange("flange to be measured", required=True)


class PartialRelativeSensor(Component):
    """Measures between ``flange_a`` and ``flange_b`` (0 = flange_a.f + flange_b.f)."""
    partial = True
    flange_a = Flange("left flange of sensor", required=True)
    flange_b = Flange("right flange of sensor", required=True)


class _RigidRelativeSensor(PartialRelativeSensor):
    """flange_a.s = flange_b.s; the cut force flange_a.f = −flange_b.f passes through."""

    def structure(self, s):
        s.linear({self.flange_a: 1.0, self.flange_b: -1.0}, 0.0, f"{self.path}: rigid")


class PositionSensor(PartialAbsoluteSensor):
    """Output ``s`` [m]: absolute position of flange."""
    s = RealOutput("absolute position of flange as output signal [m]")

    def physics(self, e):
        e.output(self.s, e.pos(self.flange))


class SpeedSensor(PartialAbsoluteSensor):
    """Output ``v`` [m/s]: absolute velocity of flange."""
    v = RealOutput("absolute velocity of flange as output signal [m/s]")

    def physics(self, e):
        e.output(self.v, e.vel(self.flange))


class AccSensor(PartialAbsoluteSensor):
    """Output ``a`` [m/s²]: absolute acceleration of flange; v [m/s] recorded."""
    a = RealOutput("absolute acceleration of flange as output signal [m/s2]")

    def physics(self, e):
        e.variable("v", e.vel(self.flange), "m/s", "absolute velocity of flange")
        e.output(self.a, e.acc(self.flange))


class ForceSensor(_RigidRelativeSensor):
    """Output ``f`` [N] = flange_a.f = −flange_b.f: the cut force between the two flanges
    (rigid: flange_a.s = flange_b.s). It may feed outputs and state derivatives (a
    controller with a state), not directly a force of the same model."""
    f = RealOutput("force in flange_a and flange_b (f = flange_a.f = -flange_b.f) [N]")

    def physics(self, e):
        e.output(self.f, e.cut_flow(self.flange_a))


class PowerSensor(_RigidRelativeSensor):
    """Output ``power`` [W] = flange_a.f·der(flange_a.s) (rigid)."""
    power = RealOutput("power in flange flange_a as output signal [W]")

    def physics(self, e):
        e.output(self.power, e.cut_flow(self.flange_a) * e.vel(self.flange_a))


class MultiSensor(_RigidRelativeSensor):
    """Outputs ``f`` = flange_a.f [N], ``v`` = der(flange_a.s) [m/s] and ``power`` = f·v [W]
    (rigid)."""
    power = RealOutput("power in flange flange_a as output signal [W]")
    f = RealOutput("force in flange_a and flange_b (f = flange_a.f = -flange_b.f) [N]")
    v = RealOutput("absolute velocity of flange as output signal [m/s]")

    def physics(self, e):
        f, v = e.cut_flow(self.flange_a), e.vel(self.flange_a)
        e.output(self.f, f)
        e.output(self.v, v)
        e.output(self.power, f * v)


class RelPositionSensor(PartialRelativeSensor):
    """Output ``s_rel`` = flange_b.s − flange_a.s [m]."""
    s_rel = RealOutput("distance between two flanges (= flange_b.s - flange_a.s) [m]")

    def physics(self, e):
        e.output(self.s_rel, e.pos(self.flange_b) - e.pos(self.flange_a))


class RelSpeedSensor(PartialRelativeSensor):
    """Output ``v_rel`` = der(flange_b.s − flange_a.s) [m/s]; s_rel recorded."""
    v_rel = RealOutput("relative velocity between two flanges (= der(flange_b.s) - "
                       "der(flange_a.s)) [m/s]")

    def physics(self, e):
        e.variable("s_rel", e.pos(self.flange_b) - e.pos(self.flange_a), "m")
        e.output(self.v_rel, e.vel(self.flange_b) - e.vel(self.flange_a))


class RelAccSensor(PartialRelativeSensor):
    """Output ``a_rel`` [m/s²], second derivative of flange_b.s − flange_a.s; s_rel and
    v_rel recorded."""
    a_rel = RealOutput("relative acceleration between two flanges (= der(v_rel)) [m/s2]")

    def physics(self, e):
        e.variable("s_rel", e.pos(self.flange_b) - e.pos(self.flange_a), "m")
        e.variable("v_rel", e.vel(self.flange_b) - e.vel(self.flange_a), "m/s")
        e.output(self.a_rel, e.acc(self.flange_b) - e.acc(self.flange_a))
