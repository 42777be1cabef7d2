"""1-D rotational mechanics, after Modelica.Mechanics.Rotational (MSL 4.1), plus a DC motor.

Sign conventions as in MSL: a flange's cut torque ``tau`` is positive into the component
(Modelica's flow sign); a compliant element's ``tau`` is the torque on flange_b (flange_a gets
−tau); ``phi_rel`` = flange_b.phi − flange_a.phi. An ``Inertia``'s states are ``phi`` [rad] and
``w`` [rad/s], with flange_a.phi = flange_b.phi = phi. A torque source's ``tau`` is the
accelerating torque = −flange.tau.

Structural (Boolean) parameters of MSL — ``useSupport``, ``useSupportR``/``useSupportT``,
``exact``, ``TorqueDirection`` — are keyword arguments fixed at construction (they change the
ports or the equations): ``IdealGear(ratio=3, useSupport=True)``. With ``useSupport=False``
(the MSL default) the component is implicitly fixed to the ground; with ``True`` it gets a
``support`` flange (the housing) that must be connected and receives the reaction torque.

Parameters: where MSL gives a parameter only a ``start`` value (Inertia.J, Spring.c,
IdealGear.ratio, ...) that value is the default; where MSL gives none at all
(ConstantTorque.tau_constant, ConstantSpeed.w_fixed, ...) the parameter is required when the
component is created (a ParameterError otherwise).

The equations shared with the translational library are written once in ``interfaces``; the
classes here declare MSL's connectors and names on top of them.

Differences from MSL, by necessity of a Python library, are listed in each docstring.
Coulomb friction (BearingFriction, Brake, Clutch) has MSL's mode machine on state events
(see ``friction``); OneWayClutch has MSL's own (a freewheel in parallel with a clutch), and
Freewheel (not an MSL class) is its freewheel alone; backlash and stops are not here yet.
"""
from __future__ import annotations

import math

import casadi as ca

from ..core import (Component, ConditionalPort, Parameter, RealInput, RealOutput,
                    RotationalFlange, StateSelect, TranslationalFlange, VectorPort)
from ..core.ports import ROTATIONAL
from ..errors import ParameterError
from . import friction, interfaces
from .interfaces import ROTATIONAL_AXIS, USE_HEAT_PORT, linear_law, quadratic_law

Flange = RotationalFlange
_EPS = 2.220446049250313e-16      # Modelica.Constants.eps
_EPS0 = 1.0e-4                     # OneWayClutch.eps0, relative hysteresis epsilon

__all__ = [
    # interfaces
    "PartialTwoFlanges", "PartialElementaryOneFlangeAndSupport2",
    "PartialElementaryTwoFlangesAndSupport2", "PartialElementaryRotationalToTranslational",
    "PartialCompliant", "PartialCompliantWithRelativeStates", "PartialTorque",
    "PartialAbsoluteSensor", "PartialRelativeSensor", "PartialFriction",
    # components
    "Fixed", "Inertia", "Disc", "Spring", "Damper", "SpringDamper", "IdealGear",
    "IdealPlanetary", "IdealRollingWheel", "IdealGearR2T", "BearingFriction", "Brake", "Clutch",
    "OneWayClutch", "Freewheel",
    # sources
    "Torque", "Torque2", "ConstantTorque", "QuadraticSpeedDependentTorque",
    "LinearSpeedDependentTorque", "TorqueStep", "Position", "Speed", "Accelerate", "Move",
    "ConstantSpeed",
    # sensors
    "AngleSensor", "SpeedSensor", "AccSensor", "TorqueSensor", "PowerSensor", "MultiSensor",
    "RelAngleSensor", "RelSpeedSensor", "RelAccSensor",
    # actuators
    "DCMotor",
]


# =========================================================================================
# Interfaces
# =========================================================================================
def _support(option: str = "useSupport", description: str = "support/housing of component",
             flange_cls: type = Flange) -> ConditionalPort:
    """MSL's ``Support support if useSupport``."""
    return ConditionalPort(flange_cls(description, required=True), option)


class PartialTwoFlanges(interfaces.PartialTwoFlanges):
    """Component with two rotational 1-D shaft flanges ``flange_a``, ``flange_b``."""
    axis = ROTATIONAL_AXIS
    flange_a = Flange("flange of left shaft")
    flange_b = Flange("flange of right shaft")


class PartialElementaryOneFlangeAndSupport2(interfaces.PartialElementaryOneFlangeAndSupport2):
    """One ``flange`` and, with ``useSupport=True``, a ``support`` (housing) flange.

    The reaction of what acts on ``flange`` goes to the support: support.tau = −flange.tau.
    """
    axis = ROTATIONAL_AXIS
    flange = Flange("flange of shaft")
    support = _support()


class PartialElementaryTwoFlangesAndSupport2(interfaces.PartialElementaryTwoFlangesAndSupport2):
    """``flange_a``, ``flange_b`` and, with ``useSupport=True``, a ``support`` flange."""
    axis = ROTATIONAL_AXIS
    flange_a = Flange("flange of left shaft")
    flange_b = Flange("flange of right shaft")
    support = _support()


class PartialElementaryRotationalToTranslational(Component):
    """Rotational ``flangeR`` and translational ``flangeT``; with ``useSupportR`` /
    ``useSupportT`` a rotational ``supportR`` / translational ``supportT`` housing flange."""
    options = {"useSupportR": False, "useSupportT": False}
    flangeR = Flange("flange of rotational shaft")
    flangeT = TranslationalFlange("flange of translational rod")
    supportR = _support("useSupportR", "rotational support/housing of component")
    supportT = _support("useSupportT", "translational support/housing of component",
                        TranslationalFlange)

    def _declare(self, s, aR, aT, name: str) -> None:
        """aR·(flangeR.phi − supportR.phi) + aT·(flangeT.s − supportT.s) = 0."""
        coeffs = {self.flangeR: aR, self.flangeT: aT}
        if self.useSupportR:
            coeffs[self.supportR] = -aR
        if self.useSupportT:
            coeffs[self.supportT] = -aT
        s.linear(coeffs, 0.0, name)


class PartialCompliant(interfaces.PartialCompliant):
    """Two flanges and a torque tau [N.m] = flange_b.tau = −flange_a.tau, a function of
    phi_rel = flange_b.phi − flange_a.phi [rad] and w_rel = der(phi_rel) [rad/s].

    Records phi_rel, w_rel, tau (and lossPower [W] when ``loss_power(phi_rel, w_rel, tau)``
    gives one). Subclasses define ``torque(phi_rel, w_rel)``.
    """
    axis = ROTATIONAL_AXIS
    flange_a = Flange("left flange of compliant 1-dim. rotational component")
    flange_b = Flange("right flange of compliant 1-dim. rotational component")

    def torque(self, phi_rel, w_rel):
        """The torque tau [N.m] on flange_b for phi_rel [rad] and w_rel [rad/s]."""
        raise NotImplementedError

    def flange_b_flow(self, rel_pos, rel_speed):
        return self.torque(rel_pos, rel_speed)


class PartialCompliantWithRelativeStates(PartialCompliant):
    """MSL's variant of PartialCompliant with phi_rel, w_rel as preferred states (here the
    compiler chooses the coordinates: ``stateSelect``, default prefer, is a hint, see
    StateSelect); records also a_rel = der(w_rel) [rad/s²].

    phi_rel has MSL's nominal: phi_nominal [rad] (default 1e-4; 1 if below machine epsilon),
    the scale of the error control of the state phi_rel is (e.g. the housing's angle when
    flange_a is fixed; see ``CompiledModel.nominals``).
    """
    options = {"stateSelect": StateSelect.prefer}
    records_a_rel = True
    phi_nominal = Parameter(1e-4, "rad", "nominal value of phi_rel (used for scaling)",
                            nonnegative=True)

    def rel_nominal(self):
        return ca.if_else(self.phi_nominal >= _EPS, self.phi_nominal, 1.0)


class PartialTorque(PartialElementaryOneFlangeAndSupport2):
    """A torque source depending on time and on the flange's motion relative to the support.

    Records phi = flange.phi − phi_support [rad], w = der(phi) [rad/s] and the accelerating
    torque tau = −flange.tau [N.m]. Subclasses define ``torque(e, phi, w)``.
    """

    def torque(self, e, phi, w):
        """The accelerating torque [N.m] (acting on flange, positive direction)."""
        raise NotImplementedError

    def physics(self, e):
        tau = self.torque(e, self._rel_position(e, self.flange),
                          self._rel_speed(e, self.flange))
        self._apply_flange_flow(e, -tau)
        self._record_relative(e, "s", "v")
        e.variable("tau", tau, "N.m", "accelerating torque acting at flange (= -flange.tau)")



class PartialFriction(friction.PartialFriction):
    """Coulomb friction with MSL's mode machine (Rotational.Interfaces.PartialFriction; see
    ``acausal.components.friction``): w_relfric [rad/s], a_relfric [rad/s²], tau0, tau0_max
    [N.m], mode (3 unknown, 2 free, 1 forward, 0 stuck, −1 backward), the friction torque tau
    [N.m] an algebraic variable; in smooth form tau = F(|w_relfric|)·tanh(w_relfric/w_smooth)."""
    axis = ROTATIONAL_AXIS
    w_small = Parameter(1.0e10, "rad/s", "relative angular velocity near to zero if jumps due "
                                         "to a reinit(..) of the velocity can occur",
                        positive=True)
    w_smooth = Parameter(1e-3, "rad/s", "smooth form only: tau = tau_pos(|w_relfric|)*"
                         "tanh(w_relfric/w_smooth) (a held element creeps at about "
                         "w_smooth*|tau|/tau0)", positive=True)

# =========================================================================================
# Components
# =========================================================================================
class Fixed(Component):
    """Flange fixed in the housing at a given angle phi0 [rad]."""
    phi0 = Parameter(0.0, "rad", "fixed offset angle of housing")
    flange = Flange("flange fixed in housing at angle phi0")

    def structure(self, s):
        s.linear({self.flange: 1.0}, self.phi0)


class Inertia(Component):
    """1-D rotational component with inertia J [kg.m²]; states phi [rad] and w [rad/s];
    a [rad/s²] recorded. flange_a.phi = flange_b.phi = phi. ``stateSelect`` is a hint
    (StateSelect).

    J = 0 is allowed (MSL: min = 0), a massless shaft where something else carries the
    inertia: as Translational.Mass with m = 0 (J fixed at 0 in the compiled model, its angle
    algebraic where nothing with inertia is rigidly attached).
    """
    options = {"stateSelect": StateSelect.default}
    J = Parameter(1.0, "kg.m2", "moment of inertia", nonnegative=True, structural_zero=True)
    flange_a = Flange("left flange of shaft")
    flange_b = Flange("right flange of shaft")
    batch_physics = True

    def structure(self, s):
        body = s.node("phi", ROTATIONAL, velocity="w", acceleration="a")
        s.linear({self.flange_a: 1.0, body: -1.0}, 0.0)
        s.linear({self.flange_b: 1.0, body: -1.0}, 0.0)

    def physics(self, e):
        e.kinetic_energy(0.5 * self.J * e.vel(e.node("phi")) ** 2)


class Disc(Component):
    """Rigid massless disc: flange_b is rotated by deltaPhi [rad] with respect to flange_a.

    flange_a.phi = phi − deltaPhi/2, flange_b.phi = phi + deltaPhi/2 (phi recorded).
    """
    deltaPhi = Parameter(0.0, "rad", "fixed rotation of left flange with respect to right "
                                     "flange (= flange_b.phi - flange_a.phi)")
    flange_a = Flange("left flange of shaft")
    flange_b = Flange("right flange of shaft")

    def structure(self, s):
        s.linear({self.flange_b: 1.0, self.flange_a: -1.0}, self.deltaPhi)

    def physics(self, e):
        e.variable("phi", e.pos(self.flange_a) + self.deltaPhi / 2, "rad",
                   "absolute rotation angle of component")


class Spring(PartialCompliant):
    """Linear 1-D rotational spring: tau = c·(phi_rel − phi_rel0).

    Default c = 1e5 N.m/rad: MSL's start value (MSL declares no default).
    """
    batch_physics = True       # physics: port motion and parameters only
    c = Parameter(1.0e5, "N.m/rad", "spring constant", nonnegative=True)
    phi_rel0 = Parameter(0.0, "rad", "unstretched spring angle")

    def torque(self, phi_rel, w_rel):
        return self.c * (phi_rel - self.phi_rel0)


class Damper(PartialCompliantWithRelativeStates):
    """Linear 1-D rotational damper: tau = d·w_rel; lossPower = tau·w_rel.
    d [N.m.s/rad] ≥ 0 (default 0 = MSL start value). useHeatPort only False."""
    options = {"useHeatPort": USE_HEAT_PORT}
    batch_physics = True       # physics: port motion and parameters only
    d = Parameter(0.0, "N.m.s/rad", "damping constant", nonnegative=True)

    def torque(self, phi_rel, w_rel):
        return self.d * w_rel

    def loss_power(self, phi_rel, w_rel, tau):
        return tau * w_rel


class SpringDamper(PartialCompliantWithRelativeStates):
    """Linear spring and damper in parallel: tau = c·(phi_rel − phi_rel0) + d·w_rel;
    lossPower = d·w_rel². Defaults c = 1e5 N.m/rad, d = 0 N.m.s/rad (MSL's start values).
    useHeatPort only False."""
    options = {"useHeatPort": USE_HEAT_PORT}
    batch_physics = True       # physics: port motion and parameters only
    c = Parameter(1.0e5, "N.m/rad", "spring constant", nonnegative=True)
    d = Parameter(0.0, "N.m.s/rad", "damping constant", nonnegative=True)
    phi_rel0 = Parameter(0.0, "rad", "unstretched spring angle")

    def torque(self, phi_rel, w_rel):
        return self.c * (phi_rel - self.phi_rel0) + self.d * w_rel

    def loss_power(self, phi_rel, w_rel, tau):
        return self.d * w_rel ** 2


class IdealGear(PartialElementaryTwoFlangesAndSupport2):
    """Ideal gear without inertia: phi_a = ratio·phi_b, 0 = ratio·flange_a.tau + flange_b.tau,
    with phi_a = flange_a.phi − phi_support, phi_b = flange_b.phi − phi_support (recorded).

    ``ratio`` (flange_a.phi/flange_b.phi, default 1 = MSL start value) must not be 0; the
    support (useSupport=True) takes −(flange_a.tau + flange_b.tau).
    """
    ratio = Parameter(1.0, "1", "transmission ratio (flange_a.phi/flange_b.phi)", nonzero=True)

    def structure(self, s):
        self._relative_constraint(s, {self.flange_a: 1.0, self.flange_b: -self.ratio}, 0.0,
                                  f"{self.path}: phi_a = ratio*phi_b")

    def physics(self, e):
        e.variable("phi_a", self._rel_position(e, self.flange_a), "rad",
                   "angle between left shaft flange and support")
        e.variable("phi_b", self._rel_position(e, self.flange_b), "rad",
                   "angle between right shaft flange and support")


class IdealPlanetary(Component):
    """Ideal planetary gear box (Willis): (1 + ratio)·carrier.phi = sun.phi + ratio·ring.phi;
    ring.tau = ratio·sun.tau, carrier.tau = −(1 + ratio)·sun.tau.

    ``ratio`` = ring teeth / sun teeth (default 100/50 = MSL start value), > 0.
    """
    ratio = Parameter(2.0, "1", "number of ring_teeth/sun_teeth (e.g. ratio=100/50)",
                      positive=True)
    sun = Flange("flange of sun shaft")
    carrier = Flange("flange of carrier shaft")
    ring = Flange("flange of ring shaft")

    def structure(self, s):
        s.linear({self.carrier: 1.0 + self.ratio, self.sun: -1.0, self.ring: -self.ratio},
                 0.0, f"{self.path}: (1 + ratio)*carrier.phi = sun.phi + ratio*ring.phi")


class IdealRollingWheel(PartialElementaryRotationalToTranslational):
    """Ideal rolling wheel without inertia: (flangeR.phi − supportR.phi)·radius =
    flangeT.s − supportT.s; 0 = radius·flangeT.f + flangeR.tau.

    ``radius`` [m] > 0 (default 0.3 = MSL start value).
    """
    radius = Parameter(0.3, "m", "wheel radius", positive=True)

    def structure(self, s):
        self._declare(s, self.radius, -1.0, f"{self.path}: radius*phi = s")


class IdealGearR2T(PartialElementaryRotationalToTranslational):
    """Gearbox rotational → translational: (flangeR.phi − supportR.phi) =
    ratio·(flangeT.s − supportT.s); 0 = ratio·flangeR.tau + flangeT.f.

    ``ratio`` [rad/m] ≠ 0 (default 1 = MSL start value).
    """
    ratio = Parameter(1.0, "rad/m", "transmission ratio (flangeR.phi/flangeT.s)",
                      nonzero=True)

    def structure(self, s):
        self._declare(s, 1.0, -self.ratio, f"{self.path}: phi = ratio*s")



class BearingFriction(PartialElementaryTwoFlangesAndSupport2, friction.SupportedFriction,
                      friction.TableFriction, PartialFriction):
    """Coulomb friction in bearings: flange_b.phi = flange_a.phi, the friction torque tau
    [N.m] against the support, tau_pos(w) [N.m] when sliding forward (w ≥ 0, a table
    constructor keyword of rows [w, tau], default [[0, 1]]), up to tau0_max = peak·tau_pos(0)
    when stuck. Records phi, w, a relative to the support. useHeatPort only False."""
    options = {"useSupport": False, "useHeatPort": USE_HEAT_PORT}
    table_name = "tau_pos"
    table_default = ((0.0, 1.0),)


class Brake(PartialElementaryTwoFlangesAndSupport2, friction.SupportedFriction,
            friction.NormalForceFriction, PartialFriction):
    """Brake based on Coulomb friction: flange_b.phi = flange_a.phi, the brake torque tau
    [N.m] against the support, mu·cgeo·fn when sliding, fn = fn_max·f_normalized [N];
    ``mu_pos`` (constructor keyword, rows [w, mu], default [[0, 0.5]]); free (mode 2, tau = 0)
    when fn ≤ 0. fn_max defaults to 1 N (MSL's start value). useHeatPort only False."""
    options = {"useSupport": False, "useHeatPort": USE_HEAT_PORT}
    f_normalized = RealInput("normalized force signal 0..1 (normal force = "
                             "fn_max*f_normalized; brake is active if > 0)")


class Clutch(PartialCompliantWithRelativeStates, friction.NormalForceFriction,
             PartialFriction):
    """Clutch based on Coulomb friction between flange_a and flange_b: w_relfric = w_rel =
    der(flange_b.phi − flange_a.phi), tau = flange_b.tau = −flange_a.tau [N.m], mu·cgeo·fn
    when sliding, fn = fn_max·f_normalized [N]; ``mu_pos`` (constructor keyword, rows
    [w_rel, mu], default [[0, 0.5]]); free (disengaged, mode 2) when fn ≤ 0. Records phi_rel,
    w_rel, a_rel. When it sticks, flange_b's speed is set to flange_a's: flange_b's speed must
    be a state. useHeatPort only False."""
    options = {"stateSelect": StateSelect.prefer, "useHeatPort": USE_HEAT_PORT}
    f_normalized = RealInput("normalized force signal 0..1 (normal force = "
                             "fn_max*f_normalized; clutch is engaged if > 0)")

    def _relfric(self, e):
        return (e.vel(self.flange_b) - e.vel(self.flange_a),
                e.acc(self.flange_b) - e.acc(self.flange_a))

    def _apply(self, e, tau) -> None:
        self._apply_opposite_flows(e, tau)

    def _stop(self, e):
        return e.vel(self.flange_b), e.vel(self.flange_a)

    def physics(self, e):
        friction.NormalForceFriction.physics(self, e)
        w_rel, a_rel = self._relfric(e)
        e.variable("phi_rel", e.pos(self.flange_b) - e.pos(self.flange_a), "rad",
                   "relative rotation angle (= flange_b.phi - flange_a.phi)",
                   nominal=self.rel_nominal())
        e.variable("w_rel", w_rel, "rad/s", "relative angular velocity (= der(phi_rel))")
        e.variable("a_rel", a_rel, "rad/s2", "relative angular acceleration (= der(w_rel))")


class _Overrunning(PartialCompliantWithRelativeStates):
    """The mode machine of MSL's OneWayClutch, shared by OneWayClutch and Freewheel (see
    OneWayClutch). A subclass gives ``_engagement(e, w)``: (free, tau0, tau0_max, tau_slide)
    with tau_slide the friction torque [N.m] when sliding forward at w_rel = w."""
    options = {"stateSelect": StateSelect.prefer, "useHeatPort": USE_HEAT_PORT}
    w_small = Parameter(1.0e10, "rad/s", "relative angular velocity near to zero if jumps due "
                                         "to a reinit(..) of the velocity can occur",
                        positive=True)
    w_smooth = Parameter(1e-3, "rad/s", "smooth form only: speed scale of the regularization "
                                        "(tanh of the friction, softplus of the lock)",
                         positive=True)
    d_smooth = Parameter(1e3, "N.m.s/rad", "smooth form only: one-sided damping that holds "
                                           "the lock (a held torque T creeps at about "
                                           "-|T|/d_smooth)", positive=True)

    def _engagement(self, e, w):
        raise NotImplementedError

    def structure(self, s):
        if s.smooth:                     # no modes, no algebraic: tau is the regularized law
            return
        s.mode("startForward", 0, values=(0, 1),
               description="= true, if w_rel=0 and start of forward sliding or "
                           "w_rel > w_small")
        s.mode("stuck", 0, values=(0, 1),
               description="w_rel=0 (locked or start forward sliding)")
        s.algebraic("sa", unit="1",
                    description="path parameter of tau = f(a_rel) friction characteristic")

    def physics(self, e):
        w_rel = e.vel(self.flange_b) - e.vel(self.flange_a)
        a_rel = e.acc(self.flange_b) - e.acc(self.flange_a)
        if e.smooth:
            free, tau0, tau0_max, slide = self._engagement(e, ca.fabs(w_rel))
            x = -w_rel / self.w_smooth                     # softplus(x) = ln(1 + exp(x))
            lock = self.d_smooth * self.w_smooth * (ca.fmax(x, 0.0)
                                                    + ca.log1p(ca.exp(-ca.fabs(x))))
            tau = ca.if_else(free, 0.0, slide * ca.tanh(w_rel / self.w_smooth)) - lock
            loss = tau * w_rel
        else:
            free, tau0, tau0_max, slide = self._engagement(e, w_rel)
            stuck, start, sa = e.mode("stuck"), e.mode("startForward"), e.state("sa")
            locked = ca.logic_and(stuck, ca.logic_not(start))
            tau = ca.if_else(locked, sa, ca.if_else(free, 0.0, slide))
            e.residual(a_rel - ca.if_else(locked, 0.0, sa - tau0))
            # MSL: startForward = pre(stuck) and (sa > tau0_max or pre(startForward) and
            # sa > tau0 or w_rel > w_small); locked = pre(stuck) and not startForward;
            # stuck = locked or w_rel <= 0
            starts = ca.logic_and(stuck, ca.logic_or(
                ca.logic_or(sa > tau0_max, ca.logic_and(start, sa > tau0)),
                w_rel > self.w_small))
            e.mode_update(start, starts)
            e.mode_update(stuck, ca.logic_or(ca.logic_and(stuck, ca.logic_not(starts)),
                                             w_rel <= 0))
            e.indicator("sliding", ca.if_else(locked, -1.0, w_rel), "rad/s",
                        "w_rel while not locked (falls through 0: stuck; rises: sliding)")
            e.indicator("breakaway", ca.if_else(locked, tau0_max - sa, ca.if_else(
                ca.logic_and(stuck, start), sa - tau0, 1.0)), "1",
                "tau0_max - sa while locked, sa - tau0 while starting to slide forward")
            for when in ("sliding", "breakaway"):          # w_rel = 0 exactly at either
                e.reinit(e.vel(self.flange_b), e.vel(self.flange_a), when=when,
                         direction=-1)
            e.variable("locked", locked, "", "= true, if w_rel=0 and not sliding")
            e.variable("sa", sa, "1", "path parameter of tau = f(a_rel) friction "
                                      "characteristic")
            loss = ca.if_else(stuck, 0.0, tau * w_rel)
        self._apply_opposite_flows(e, tau)
        e.variable("phi_rel", e.pos(self.flange_b) - e.pos(self.flange_a), "rad",
                   "relative rotation angle (= flange_b.phi - flange_a.phi)",
                   nominal=self.rel_nominal())
        e.variable("w_rel", w_rel, "rad/s", "relative angular velocity (= der(phi_rel))")
        e.variable("a_rel", a_rel, "rad/s2", "relative angular acceleration (= der(w_rel))")
        e.variable("tau", tau, "N.m", "torque between flanges (= flange_b.tau)")
        e.variable("free", free, "", "= true, if frictional element is not active")
        e.variable("tau0", tau0, "N.m", "friction torque for w=0 and sliding")
        e.variable("tau0_max", tau0_max, "N.m", "maximum friction torque for w=0 and locked")
        e.variable("lossPower", loss, "W", "loss power leaving component via heatPort")


class OneWayClutch(_Overrunning):
    """Parallel connection of freewheel and clutch (MSL's OneWayClutch): w_rel = der(phi_rel),
    phi_rel = flange_b.phi − flange_a.phi, tau = flange_b.tau = −flange_a.tau [N.m].

    The freewheel locks when w_rel would become negative and holds any negative tau (it
    drives flange_b with flange_a); the clutch, pressed by fn = fn_max·f_normalized [N]
    (free when f_normalized ≤ 0, fn = 0), brakes the overrunning flange_b with tau =
    mu(w_rel)·cgeo·fn when w_rel > 0 and, locked, holds tau up to tau0_max = peak2·tau0,
    tau0 = mu0·cgeo·fn, mu0 = mu_pos(0), peak2 = max(peak, 1 + 1e-4) (free: up to
    tau0_max_low = 1e-4·mu0·cgeo·fn_max). ``mu_pos``: constructor keyword, rows [w_rel, mu]
    (w_rel ≥ 0), default [[0, 0.5]], linear with extrapolation through the last two rows.
    fn_max defaults to 1 N (MSL's start value). useHeatPort only False.

    MSL's equations, on state events: the Boolean modes ``stuck`` and ``startForward`` (both
    start false, as MSL's start values) and the algebraic path parameter ``sa``:
    locked = stuck and not startForward; a_rel = 0 if locked else sa − tau0; tau = sa if
    locked, else 0 if free, else mu·cgeo·fn. At every event (iterated until they settle):
    startForward = stuck and (sa > tau0_max or startForward and sa > tau0 or w_rel > w_small),
    stuck = (stuck and not startForward) or w_rel ≤ 0, as MSL updates them from their pre
    values. Indicators: ``sliding`` (w_rel while not locked), ``breakaway`` (tau0_max − sa
    while locked; sa − tau0 while starting to slide), ``u`` (f_normalized); when it locks or
    breaks away, flange_b's speed is set to flange_a's (w_rel = 0 exactly): flange_b's speed
    must be a state. Records u, fn, mu, free, tau0, tau0_max, sa, locked, stuck,
    startForward, phi_rel, w_rel, a_rel, tau and lossPower = 0 if stuck else tau·w_rel [W]
    (MSL's OneWayClutch has no ``mode``: stuck, startForward and locked say it).
    Not here: MSL's ``initial() and w_rel > 0`` term, which only sets startForward at the
    initial instant (nothing else depends on it there). As in MSL, the relative speed must
    start ≥ 0.

    Smooth form (``compile(model, smooth=True)``): no modes, indicators or algebraic;
    tau = mu(|w_rel|)·cgeo·fn·tanh(w_rel/w_smooth) (0 when free)
    − d_smooth·w_smooth·ln(1 + exp(−w_rel/w_smooth)), the clutch as PartialFriction's smooth
    form and the freewheel a one-sided damper d_smooth [N.m.s/rad] smoothed over w_smooth
    [rad/s]. Its error against the exact form: (1) where the exact form holds a torque T < 0
    locked, the smooth form slips backward at w_rel = −w_smooth·ln(exp(|T|/(d_smooth·w_smooth))
    − 1) ≈ −|T|/d_smooth (|T| ≫ d_smooth·w_smooth) plus the clutch's share; (2) overrunning
    at w_rel ≫ w_smooth, the lock drags with d_smooth·w_smooth·exp(−w_rel/w_smooth) (< 1e-3 of
    d_smooth·w_smooth beyond w_rel > 6.9·w_smooth) and the friction is low by at most
    2·mu·cgeo·fn·exp(−2·w_rel/w_smooth); (3) a positive held torque T < tau0 creeps forward at
    about w_smooth·artanh(T/tau0), and there is no stiction peak (it breaks away at tau0);
    (4) with nothing to hold, an engaged clutch settles not at w_rel = 0 but where
    tau0·tanh(w_rel/w_smooth) = d_smooth·w_smooth·ln(1 + exp(−w_rel/w_smooth)) (the lock
    pulls with d_smooth·w_smooth·ln 2 at w_rel = 0): 1.3e-4 rad/s for tau0 = 5 N.m and the
    defaults. A stiffer lock (larger d_smooth) creeps less and makes the equations stiffer:
    the time constant of the lock is about J/d_smooth. Recorded in the smooth form: u, fn, mu
    (at |w_rel|), free, tau0, tau0_max, phi_rel, w_rel, a_rel, tau, lossPower = tau·w_rel.
    """
    peak = Parameter(1.0, "1", "peak for maximum value of mu at w==0 (mu0_max = "
                               "peak*mu_pos[1,2])")
    cgeo = Parameter(1.0, "1", "geometry constant containing friction distribution "
                               "assumption", nonnegative=True)
    fn_max = Parameter(1.0, "N", "maximum normal force", nonnegative=True)
    f_normalized = RealInput("normalized force signal 0..1 (normal force = "
                             "fn_max*f_normalized; clutch is engaged if > 0)")

    def __init__(self, name: str | None = None, **params):
        table = params.pop("mu_pos", ((0.0, 0.5),))
        super().__init__(name, **params)
        if self.peak < 1:
            raise ParameterError(f"parameter 'OneWayClutch.peak' must be >= 1 (MSL: min = 1), "
                                 f"got {self.peak}")
        self.__dict__["table"] = friction.check_table(table, "mu_pos", "OneWayClutch")

    def _engagement(self, e, w):
        u = e.input(self.f_normalized)
        free = u <= 0
        fn = ca.if_else(free, 0.0, self.fn_max * u)
        mu0 = friction.table_value(self.table, 0.0)
        mu = friction.table_value(self.table, w)
        tau0 = mu0 * self.cgeo * fn
        tau0_max = ca.if_else(free, _EPS0 * mu0 * self.cgeo * self.fn_max,
                              ca.fmax(self.peak, 1 + _EPS0) * tau0)
        if not e.smooth:
            e.indicator("u", u, "1", "normalized force input (free when <= 0)")
        e.variable("u", u, "1", "normalized force input signal (0..1)")
        e.variable("fn", fn, "N", "normal force (fn=fn_max*inPort.signal)")
        e.variable("mu", mu, "1", "friction coefficient")
        return free, tau0, tau0_max, mu * self.cgeo * fn


class Freewheel(_Overrunning):
    """Ideal freewheel (overrunning clutch) between flange_a and flange_b. Not an MSL class
    (MSL 4.1 has none): OneWayClutch without its clutch, f_normalized ≡ 0 with a zero
    threshold. w_rel = der(flange_b.phi − flange_a.phi) ≥ 0, tau = flange_b.tau =
    −flange_a.tau [N.m]: locked (w_rel = 0) it holds any tau ≤ 0, flange_a driving flange_b;
    it frees as soon as the torque that holds it turns positive (flange_b would overrun) and
    runs free (tau = 0) while w_rel > 0, until w_rel falls back to 0.

    The mode machine, indicators, reinits and records are OneWayClutch's with free = true,
    tau0 = tau0_max = 0 (OneWayClutch holds up to tau0_max_low = 1e-4·mu0·cgeo·fn_max when
    free); its smooth form is OneWayClutch's lock alone: tau = −d_smooth·w_smooth·
    ln(1 + exp(−w_rel/w_smooth)), with OneWayClutch's errors (1) and (2)."""

    def _engagement(self, e, w):
        return ca.SX(1), ca.SX(0), ca.SX(0), ca.SX(0)


# =========================================================================================
# Sources
# =========================================================================================
class Torque(PartialElementaryOneFlangeAndSupport2):
    """Input signal ``tau`` [N.m] acting as external torque on ``flange``: flange.tau = −tau
    (a positive tau accelerates the flange); support.tau = tau with useSupport."""
    tau = RealInput("accelerating torque acting at flange (= -flange.tau)")

    def physics(self, e):
        self._apply_flange_flow(e, -e.input(self.tau))


class Torque2(PartialTwoFlanges):
    """Input signal ``tau`` [N.m] acting on two flanges: flange_a.tau = tau,
    flange_b.tau = −tau."""
    tau = RealInput("torque driving the two flanges")

    def physics(self, e):
        self._apply_opposite_flows(e, -e.input(self.tau))


class ConstantTorque(PartialTorque):
    """Constant torque tau = tau_constant [N.m], not dependent on speed (positive: accelerates
    in positive direction). Required: tau_constant (MSL gives no default)."""
    tau_constant = Parameter(0.0, "N.m", "constant torque (if negative, torque is acting as "
                                         "load in positive direction of rotation)")
    required = ("tau_constant",)

    def torque(self, e, phi, w):
        return self.tau_constant


class _SpeedDependentTorque(PartialTorque):
    """tau = tau_nominal·law(w/w_nominal); ``TorqueDirection`` picks the law.
    Required: tau_nominal [N.m], w_nominal [rad/s] > 0 (MSL gives no defaults)."""
    options = {"TorqueDirection": True}
    tau_nominal = Parameter(0.0, "N.m", "nominal torque (if negative, torque is acting as "
                                        "load in positive direction of rotation)")
    w_nominal = Parameter(1.0, "rad/s", "nominal speed", positive=True)
    required = ("tau_nominal", "w_nominal")

    def torque(self, e, phi, w):
        return self.tau_nominal * self.law(w / self.w_nominal)


class QuadraticSpeedDependentTorque(_SpeedDependentTorque):
    """tau = tau_nominal·(w/w_nominal)² (TorqueDirection=True: same direction both ways), or
    tau_nominal·(w/w_nominal)·|w/w_nominal| (TorqueDirection=False)."""

    def law(self, x):
        return quadratic_law(x, self.TorqueDirection)


class LinearSpeedDependentTorque(_SpeedDependentTorque):
    """tau = tau_nominal·|w/w_nominal| (TorqueDirection=True) or tau_nominal·w/w_nominal
    (TorqueDirection=False)."""

    def law(self, x):
        return linear_law(x, self.TorqueDirection)


class TorqueStep(PartialTorque):
    """tau = offsetTorque + (0 if time < startTime else stepTorque) [N.m]."""
    stepTorque = Parameter(1.0, "N.m", "height of torque step (if negative, torque is acting "
                                       "as load)")
    offsetTorque = Parameter(0.0, "N.m", "offset of torque")
    startTime = Parameter(0.0, "s", "torque = offset for time < startTime")

    def torque(self, e, phi, w):
        e.time_event(self.startTime)
        return self.offsetTorque + ca.if_else(e.time < self.startTime, 0.0, self.stepTorque)


class Position(PartialElementaryOneFlangeAndSupport2, interfaces.Position):
    """Forced movement of ``flange`` (relative to support) by the reference angle ``phi_ref``.

    exact=False (default, as MSL): phi_ref passes a critically damped 2nd-order Bessel filter
    with cut-off f_crit [Hz] (default 50): a = ((phi_ref − phi)·w_crit − af·w)·(w_crit/bf),
    w_crit = 2π·f_crit, af = 1.3617, bf = 0.6180; states phi [rad], w [rad/s] (any signal
    works, model inputs included).
    exact=True: flange.phi − phi_support = phi_ref exactly; phi_ref must be a function of time
    (its first two derivatives are taken by algorithmic differentiation).

    Differences from MSL: the filter starts at phi = 0, w = 0 (MSL: phi = phi_ref(0) by an
    initial equation): when phi_ref(0) ≠ 0 give ``x0={"<name>.phi": phi_ref(0)}``. With
    exact=True, w and a are the actual relative speed and acceleration (MSL: dummies 0).
    """
    phi_ref = RealInput("reference angle of flange with respect to support [rad]")


class Speed(PartialElementaryOneFlangeAndSupport2, interfaces.Speed):
    """Forced movement of ``flange`` (relative to support) by the reference speed ``w_ref``.

    phi = ∫w is a state (start 0, as MSL's phi(start=0, fixed=true)).
    exact=False (default): w follows w_ref through a first-order filter with cut-off f_crit
    [Hz]: a = (w_ref − w)·2π·f_crit; w is a state (any signal works).
    exact=True: w = w_ref exactly; w_ref must be a function of time (differentiated once).

    Difference from MSL: the filter starts at w = 0 (MSL: w = w_ref(0) by an initial
    equation): give ``x0={"<name>.w": w_ref(0)}`` when it differs.
    """
    w_ref = RealInput("reference angular velocity of flange with respect to support [rad/s]")


class Accelerate(PartialElementaryOneFlangeAndSupport2, interfaces.Accelerate):
    """Forced movement of ``flange`` (relative to support) by the acceleration ``a_ref``
    [rad/s²]; phi and w are states integrated from 0 (MSL: start=0, fixed=true)."""
    a_ref = RealInput("absolute angular acceleration of flange with respect to support")


class Move(PartialElementaryOneFlangeAndSupport2, interfaces.Move):
    """Forced movement of ``flange`` (relative to the support) by the signals ``u[1]``
    (angle [rad]), ``u[2]`` (angular velocity [rad/s]), ``u[3]`` (angular acceleration
    [rad/s²]), numbered from 1 as in MSL: ``connect(src.y, move.u[1])``.

    Difference from MSL (same as translational.Move): the compiler cannot yet be told that
    u[2], u[3] are the derivatives of u[1]; the motion is phi = u[1], with its velocity and
    acceleration taken from u[1] by algorithmic differentiation (u[1] must be a function of
    time, as for Position(exact=True)). For consistent signals (MSL's requirement) this is
    the same motion; MSL's deliberately inconsistent use (u[2] = u[3] = 0) is not
    reproduced. u[2], u[3] must be connected; they are recorded as ``w_u``, ``a_u`` next to
    the actual ``w``, ``a`` so that the two can be compared.
    """
    u = VectorPort(RealInput, 3, tuple(f"{what} of flange with respect to support as input "
                                       f"signal" for what in
                                       ("angle", "angular velocity", "angular acceleration")))


class ConstantSpeed(PartialElementaryOneFlangeAndSupport2, interfaces.ConstantSpeed):
    """Constant speed w = w_fixed [rad/s] of flange relative to support, not dependent on
    torque; phi is a state (start 0). Records w and also tau = −flange.tau [N.m], the torque
    the source delivers (not an MSL variable). Required: w_fixed (MSL gives no default)."""
    w_fixed = Parameter(0.0, "rad/s", "fixed speed")
    required = ("w_fixed",)

    def physics(self, e):
        super().physics(e)
        e.variable("tau", -e.cut_flow(self.flange), "N.m",
                   "torque the source applies to the flange (= -flange.tau)")


# =========================================================================================
# Sensors
# =========================================================================================
class PartialAbsoluteSensor(Component):
    """Measures an absolute quantity of ``flange`` (no torque: flange.tau = 0)."""
    flange = Flange("flange to be measured", required=True)


class PartialRelativeSensor(Component):
    """Measures between ``flange_a`` and ``flange_b``."""
    flange_a = Flange("left flange of shaft", required=True)
    flange_b = Flange("right flange of shaft", required=True)


class AngleSensor(PartialAbsoluteSensor):
    """Output ``phi`` [rad]: absolute angle of flange."""
    phi = RealOutput("absolute angle of flange [rad]")

    def physics(self, e):
        e.output(self.phi, e.pos(self.flange))


class SpeedSensor(PartialAbsoluteSensor):
    """Output ``w`` [rad/s]: absolute angular velocity of flange."""
    w = RealOutput("absolute angular velocity of flange [rad/s]")

    def physics(self, e):
        e.output(self.w, e.vel(self.flange))


class AccSensor(PartialAbsoluteSensor):
    """Output ``a`` [rad/s²]: absolute angular acceleration of flange."""
    a = RealOutput("absolute angular acceleration of flange [rad/s2]")

    def physics(self, e):
        e.output(self.a, e.acc(self.flange))


class _RigidRelativeSensor(PartialRelativeSensor):
    """flange_a.phi = flange_b.phi; the cut torque tau = flange_a.tau = −flange_b.tau."""

    def structure(self, s):
        s.linear({self.flange_a: 1.0, self.flange_b: -1.0}, 0.0, f"{self.path}: rigid")


class TorqueSensor(_RigidRelativeSensor):
    """Output ``tau`` [N.m] = flange_a.tau: the cut torque transmitted from flange_a to
    flange_b (rigid: flange_a.phi = flange_b.phi)."""
    tau = RealOutput("torque in flange flange_a and flange_b (tau = flange_a.tau = "
                     "-flange_b.tau) [N.m]")

    def physics(self, e):
        e.output(self.tau, e.cut_flow(self.flange_a))


class PowerSensor(_RigidRelativeSensor):
    """Output ``power`` [W] = flange_a.tau·der(flange_a.phi) (rigid)."""
    power = RealOutput("power in flange flange_a [W]")

    def physics(self, e):
        e.output(self.power, e.cut_flow(self.flange_a) * e.vel(self.flange_a))


class MultiSensor(_RigidRelativeSensor):
    """Outputs ``w`` [rad/s] of flange_a, ``tau`` = flange_a.tau [N.m] and
    ``power`` = tau·w [W] (rigid)."""
    power = RealOutput("power in flange flange_a [W]")
    w = RealOutput("absolute angular velocity of flange_a [rad/s]")
    tau = RealOutput("torque in flange flange_a and flange_b (tau = flange_a.tau = "
                     "-flange_b.tau) [N.m]")

    def physics(self, e):
        w, tau = e.vel(self.flange_a), e.cut_flow(self.flange_a)
        e.output(self.w, w)
        e.output(self.tau, tau)
        e.output(self.power, tau * w)


class RelAngleSensor(PartialRelativeSensor):
    """Output ``phi_rel`` = flange_b.phi − flange_a.phi [rad]."""
    phi_rel = RealOutput("relative angle between two flanges (= flange_b.phi - "
                         "flange_a.phi) [rad]")

    def physics(self, e):
        e.output(self.phi_rel, e.pos(self.flange_b) - e.pos(self.flange_a))


class RelSpeedSensor(PartialRelativeSensor):
    """Output ``w_rel`` = der(flange_b.phi − flange_a.phi) [rad/s]; phi_rel recorded."""
    w_rel = RealOutput("relative angular velocity between two flanges [rad/s]")

    def physics(self, e):
        e.variable("phi_rel", e.pos(self.flange_b) - e.pos(self.flange_a), "rad")
        e.output(self.w_rel, e.vel(self.flange_b) - e.vel(self.flange_a))


class RelAccSensor(PartialRelativeSensor):
    """Output ``a_rel`` [rad/s²], second derivative of flange_b.phi − flange_a.phi;
    phi_rel and w_rel recorded."""
    a_rel = RealOutput("relative angular acceleration between two flanges [rad/s2]")

    def physics(self, e):
        e.variable("phi_rel", e.pos(self.flange_b) - e.pos(self.flange_a), "rad")
        e.variable("w_rel", e.vel(self.flange_b) - e.vel(self.flange_a), "rad/s")
        e.output(self.a_rel, e.acc(self.flange_b) - e.acc(self.flange_a))


# =========================================================================================
# Actuators
# =========================================================================================
class DCMotor(PartialElementaryOneFlangeAndSupport2):
    """Permanent-magnet DC motor driven by the armature voltage ``v`` [V] (RealInput).

    Armature:  L·di/dt = v − R·i − k·w_rel    (state ``i`` [A], start 0)
    Air gap:   tau_el = k·i on ``flange`` (reaction −k·i on ``support`` with useSupport)
    Rotor:     inertia J on ``flange``; states ``phi`` [rad], ``w`` [rad/s] (absolute)

    w_rel = w − support speed. k [N.m/A] is both the torque and the back-emf constant
    [V.s/rad]. Defaults follow MSL's DC_PermanentMagnet data record
    (Electrical.Machines.Utilities.ParameterRecords.DcPermanentMagnetData): R = Ra = 0.05 Ω,
    L = La = 1.5 mH, J = Jr = 0.15 kg.m², and k = (VaNominal − Ra·IaNominal)/wNominal =
    (100 V − 5 V)/(1425 rpm) = 2/π ≈ 0.6366 N.m/A. Records tau_el [N.m], vi = k·w_rel [V]
    (induced voltage) and the electrical input power pin = v·i [W].
    """
    R = Parameter(0.05, "Ohm", "armature resistance", nonnegative=True)
    L = Parameter(0.0015, "H", "armature inductance", positive=True)
    k = Parameter(2.0 / math.pi, "N.m/A", "motor constant (torque per current = back-emf per "
                                          "speed)")
    J = Parameter(0.15, "kg.m2", "rotor's moment of inertia", positive=True)
    v = RealInput("armature voltage [V]")

    def structure(self, s):
        rotor = s.node("phi", ROTATIONAL, velocity="w", acceleration="a")
        s.linear({self.flange: 1.0, rotor: -1.0}, 0.0)
        s.state("i", 0.0, "A", "armature current")

    def physics(self, e):
        rotor, i = e.node("phi"), e.state("i")
        w_rel = self._rel_speed(e, rotor)
        v = e.input(self.v)
        tau_el = self.k * i
        e.kinetic_energy(0.5 * self.J * e.vel(rotor) ** 2)
        self._apply_flange_flow(e, -tau_el)
        e.derivative(i, (v - self.R * i - self.k * w_rel) / self.L)
        e.variable("tau_el", tau_el, "N.m", "electrical (air gap) torque")
        e.variable("vi", self.k * w_rel, "V", "induced (back-emf) voltage")
        e.variable("pin", v * i, "W", "electrical input power")
