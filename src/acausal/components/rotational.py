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
Freewheel (not an MSL class) is its freewheel alone; LossyGear (mesh efficiency and bearing
friction, stuck or rolling), ElastoBacklash and ElastoBacklash2 switch on modes at state
events too, and each has a smooth form for optimal control (``compile(model, smooth=True)``).
Gearbox is MSL's composition of a LossyGear and an ElastoBacklash (a Model of the two);
SignTorque and InverseSpeedDependentTorque switch at |w| = w0 by state events.
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np

from ..core import (Component, ConditionalPort, HeatPort_a, Model, Parameter, RealInput,
                    RealOutput, RotationalFlange, StateSelect, TranslationalFlange, VectorPort)
from ..core.ports import ROTATIONAL
from ..errors import ParameterError
from . import friction, interfaces
from .interfaces import (ROTATIONAL_AXIS, Regularization, inverse_law, linear_law,
                         quadratic_law, regularization_region, regularized_sign,
                         speed_band_region)

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
    "OneWayClutch", "Freewheel", "LossyGear", "ElastoBacklash", "ElastoBacklash2", "Gearbox",
    "InitializeFlange", "TorqueToAngleAdaptor", "AngleToTorqueAdaptor",
    "GeneralTorqueToAngleAdaptor", "GeneralAngleToTorqueAdaptor",
    # sources
    "Torque", "Torque2", "ConstantTorque", "SignTorque", "QuadraticSpeedDependentTorque",
    "LinearSpeedDependentTorque", "InverseSpeedDependentTorque", "TorqueStep",
    "EddyCurrentTorque", "Position", "Speed",
    "Accelerate", "Move",
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
    partial = True
    axis = ROTATIONAL_AXIS
    flange_a = Flange("flange of left shaft")
    flange_b = Flange("flange of right shaft")


class PartialElementaryOneFlangeAndSupport2(interfaces.PartialElementaryOneFlangeAndSupport2):
    """One ``flange`` and, with ``useSupport=True``, a ``support`` (housing) flange.

    The reaction of what acts on ``flange`` goes to the support: support.tau = −flange.tau.
    """
    partial = True
    axis = ROTATIONAL_AXIS
    flange = Flange("flange of shaft")
    support = _support()


class PartialElementaryTwoFlangesAndSupport2(interfaces.PartialElementaryTwoFlangesAndSupport2):
    """``flange_a``, ``flange_b`` and, with ``useSupport=True``, a ``support`` flange."""
    partial = True
    axis = ROTATIONAL_AXIS
    flange_a = Flange("flange of left shaft")
    flange_b = Flange("flange of right shaft")
    support = _support()


class PartialElementaryRotationalToTranslational(Component):
    """Rotational ``flangeR`` and translational ``flangeT``; with ``useSupportR`` /
    ``useSupportT`` a rotational ``supportR`` / translational ``supportT`` housing flange."""
    partial = True
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
    partial = True
    axis = ROTATIONAL_AXIS
    flange_a = Flange("left flange of compliant 1-dim. rotational component")
    flange_b = Flange("right flange of compliant 1-dim. rotational component")

    def torque(self, phi_rel, w_rel):
        """The torque tau [N.m] on flange_b for phi_rel [rad] and w_rel [rad/s]."""
        raise NotImplementedError

    def flange_b_flow(self, rel_pos, rel_speed):
        return self.torque(rel_pos, rel_speed)


class PartialCompliantWithRelativeStates(PartialCompliant):
    """MSL's variant of PartialCompliant with phi_rel, w_rel as preferred states (the
    compiler chooses the coordinates; ``stateSelect``, default prefer, see StateSelect, says
    that w_rel keeps its value at another component's reinit); records also a_rel =
    der(w_rel) [rad/s²].

    phi_rel has MSL's nominal: phi_nominal [rad] (default 1e-4; 1 if below machine epsilon),
    the scale of the error control of the state phi_rel is (e.g. the housing's angle when
    flange_a is fixed; see ``CompiledModel.nominals``).
    """
    partial = True
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
    partial = True

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
    partial = True
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


class Damper(PartialCompliantWithRelativeStates,
             interfaces.PartialElementaryConditionalHeatPortWithoutT):
    """Linear 1-D rotational damper: tau = d·w_rel; lossPower = tau·w_rel.
    d [N.m.s/rad] ≥ 0 (default 0 = MSL start value).
    useHeatPort: heatPort.Q_flow = −lossPower."""
    batch_physics = True       # physics: port motion and parameters only
    d = Parameter(0.0, "N.m.s/rad", "damping constant", nonnegative=True)

    def torque(self, phi_rel, w_rel):
        return self.d * w_rel

    def loss_power(self, phi_rel, w_rel, tau):
        return tau * w_rel


class SpringDamper(PartialCompliantWithRelativeStates,
                   interfaces.PartialElementaryConditionalHeatPortWithoutT):
    """Linear spring and damper in parallel: tau = c·(phi_rel − phi_rel0) + d·w_rel;
    lossPower = d·w_rel². Defaults c = 1e5 N.m/rad, d = 0 N.m.s/rad (MSL's start values).
    useHeatPort: heatPort.Q_flow = −lossPower."""
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
    when stuck. Records phi, w, a relative to the support.
    useHeatPort: heatPort.Q_flow = −lossPower."""
    options = {"useSupport": False}
    table_name = "tau_pos"
    table_default = ((0.0, 1.0),)


class Brake(PartialElementaryTwoFlangesAndSupport2, friction.SupportedFriction,
            friction.NormalForceFriction, PartialFriction):
    """Brake based on Coulomb friction: flange_b.phi = flange_a.phi, the brake torque tau
    [N.m] against the support, mu·cgeo·fn when sliding, fn = fn_max·f_normalized [N];
    ``mu_pos`` (constructor keyword, rows [w, mu], default [[0, 0.5]]); free (mode 2, tau = 0)
    when fn ≤ 0. fn_max defaults to 1 N (MSL's start value).
    useHeatPort: heatPort.Q_flow = −lossPower."""
    options = {"useSupport": False}
    f_normalized = RealInput("normalized force signal 0..1 (normal force = "
                             "fn_max*f_normalized; brake is active if > 0)")


class Clutch(PartialCompliantWithRelativeStates, friction.NormalForceFriction,
             PartialFriction):
    """Clutch based on Coulomb friction between flange_a and flange_b: w_relfric = w_rel =
    der(flange_b.phi − flange_a.phi), tau = flange_b.tau = −flange_a.tau [N.m], mu·cgeo·fn
    when sliding, fn = fn_max·f_normalized [N]; ``mu_pos`` (constructor keyword, rows
    [w_rel, mu], default [[0, 0.5]]); free (disengaged, mode 2) when fn ≤ 0. Records phi_rel,
    w_rel, a_rel. When it sticks, flange_b's speed is set to flange_a's: flange_b's speed must
    be a state. useHeatPort: heatPort.Q_flow = −lossPower."""
    options = {"stateSelect": StateSelect.prefer}
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
                   nominal=self.rel_nominal(), stateSelect=self.state_select())
        e.variable("w_rel", w_rel, "rad/s", "relative angular velocity (= der(phi_rel))",
                   stateSelect=self.state_select())
        e.variable("a_rel", a_rel, "rad/s2", "relative angular acceleration (= der(w_rel))")


class _Overrunning(PartialCompliantWithRelativeStates,
                   interfaces.PartialElementaryConditionalHeatPortWithoutT):
    """The mode machine of MSL's OneWayClutch, shared by OneWayClutch and Freewheel (see
    OneWayClutch). A subclass gives ``_engagement(e, w)``: (free, tau0, tau0_max, tau_slide)
    with tau_slide the friction torque [N.m] when sliding forward at w_rel = w."""
    options = {"stateSelect": StateSelect.prefer}
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
                   nominal=self.rel_nominal(), stateSelect=self.state_select())
        e.variable("w_rel", w_rel, "rad/s", "relative angular velocity (= der(phi_rel))",
                   stateSelect=self.state_select())
        e.variable("a_rel", a_rel, "rad/s2", "relative angular acceleration (= der(w_rel))")
        e.variable("tau", tau, "N.m", "torque between flanges (= flange_b.tau)")
        e.variable("free", free, "", "= true, if frictional element is not active")
        e.variable("tau0", tau0, "N.m", "friction torque for w=0 and sliding")
        e.variable("tau0_max", tau0_max, "N.m", "maximum friction torque for w=0 and locked")
        self._loss_power(e, loss)


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
    fn_max defaults to 1 N (MSL's start value). useHeatPort: heatPort.Q_flow = −lossPower.

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


class EddyCurrentTorque(PartialElementaryOneFlangeAndSupport2,
                        interfaces.PartialEddyCurrent):
    """MSL's simple rotational eddy current brake: the braking torque tau = flange.tau =
    2·tau_nominal·excitation²·w_normalized/(1 + w_normalized²) [N.m], w_normalized =
    w/(w_nominal·(1 + alphaRef·(TheatPort − TRef))) (see interfaces.PartialEddyCurrent);
    lossPower = tau·w [W], to the heatPort with useHeatPort. Required: tau_nominal [N.m],
    w_nominal [rad/s] > 0 (MSL gives no defaults); TRef 293.15 K, alpha20 0 1/K, T 293.15 K.
    Records phi, w (relative to the support), tau, w_normalized, lossPower, TheatPort."""
    required = ("tau_nominal", "w_nominal")
    tau_nominal = Parameter(0.0, "N.m", "maximum torque (always braking)")
    w_nominal = Parameter(1.0, "rad/s", "nominal speed (leads to maximum torque) at "
                                        "reference temperature", positive=True)

    def physics(self, e):
        tau, x = self._braking(e, self.tau_nominal, self._rel_speed(e, self.flange),
                               self.w_nominal)
        self._apply_flange_flow(e, tau)
        self._record_relative(e, "s", "v")
        e.variable("tau", tau, "N.m", "accelerating torque acting at flange (= flange.tau)")
        e.variable("w_normalized", x, "1", "relative speed w/w_nominal")


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
        return self.tau_nominal * self.law(e, w / self.w_nominal)


class QuadraticSpeedDependentTorque(_SpeedDependentTorque):
    """tau = tau_nominal·(w/w_nominal)² (TorqueDirection=True: same direction both ways), or
    tau_nominal·(w/w_nominal)·|w/w_nominal| (TorqueDirection=False)."""

    def law(self, e, x):
        return quadratic_law(x, self.TorqueDirection)


class LinearSpeedDependentTorque(_SpeedDependentTorque):
    """tau = tau_nominal·|w/w_nominal| (TorqueDirection=True) or tau_nominal·w/w_nominal
    (TorqueDirection=False)."""

    def law(self, e, x):
        return linear_law(x, self.TorqueDirection)


class InverseSpeedDependentTorque(_SpeedDependentTorque):
    """tau = tau_nominal·w_nominal/max(|w|, w0) (TorqueDirection=True: same direction both
    ways) or tau_nominal·w/w0 for |w| < w0 and tau_nominal·w_nominal/w outside
    (TorqueDirection=False; as MSL, a jump at |w| = w0 unless w0 = w_nominal). The switch at
    |w| = w0 is a state event (mode ``region``; rounded over 0.01·w0 in smooth form).
    w0 [rad/s] > 0 (default 0.1 = MSL start value)."""
    w0 = Parameter(0.1, "rad/s", "regularization below w0", positive=True)

    def structure(self, s):
        speed_band_region(s)

    def law(self, e, x):
        return inverse_law(e, x, self.w0 / self.w_nominal, self.TorqueDirection)


class SignTorque(PartialTorque):
    """Constant torque changing sign with speed: tau = tau_nominal·sign(w) [N.m], regularized
    within [−w0, w0] by ``reg`` (default Exp, see interfaces.Regularization: Exp, Sine,
    Linear, CoSine). Required: tau_nominal [N.m] (MSL gives no default; negative: a load);
    w0 [rad/s] > 0 (default 0.1 = MSL start value)."""
    options = {"reg": Regularization.Exp}
    tau_nominal = Parameter(0.0, "N.m", "nominal torque (if negative, torque is acting as "
                                        "load)")
    w0 = Parameter(0.1, "rad/s", "regularization below w0", positive=True)
    required = ("tau_nominal",)

    def structure(self, s):
        regularization_region(s, self.reg)

    def torque(self, e, phi, w):
        return self.tau_nominal * regularized_sign(e, w, self.w0, self.reg)


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
    [rad/s²]), numbered from 1 as in MSL: ``connect(src.y, move.u[1])``. As in MSL, u[2]
    and u[3] are taken as the derivatives of u[1], not derived from it: consistent signals
    are the user's to give (MSL's deliberately inconsistent u[2] = u[3] = 0 moves the flange
    without the reactions of its speed and acceleration). Records u[2], u[3] as ``w_u``,
    ``a_u`` (equal to ``w``, ``a``).
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


class InitializeFlange(Component):
    """Initializes ``flange`` from the inputs at the start (MSL
    Components.InitializeFlange): initial equations flange.phi = phi_start [rad] (option
    ``use_phi_start``), der(flange.phi) = w_start [rad/s] (``use_w_start``) and
    der(der(flange.phi)) = a_start [rad/s²] (``use_a_start``), each input existing only with
    its option (all True, MSL's defaults); no torque on the flange (flange.tau = 0). Records
    phi_flange and w_flange. ``stateSelect`` is accepted as a hint (the compiler chooses
    the coordinates). The initial equations hold with the modes at their start values
    (``PhysicsBuilder.initial``)."""
    options = {"use_phi_start": True, "use_w_start": True, "use_a_start": True,
               "stateSelect": StateSelect.default}
    phi_start = ConditionalPort(RealInput("initial angle of flange [rad]"), "use_phi_start")
    w_start = ConditionalPort(RealInput("initial speed of flange [rad/s]"), "use_w_start")
    a_start = ConditionalPort(RealInput("initial angular acceleration of flange [rad/s2]"),
                              "use_a_start")
    flange = Flange("flange that is initialized")

    def physics(self, e):
        e.flow(self.flange, 0.0)
        phi, w, a = e.pos(self.flange), e.vel(self.flange), e.acc(self.flange)
        for use, port, value, what in (
                (self.use_phi_start, "phi_start", phi, "flange.phi = phi_start"),
                (self.use_w_start, "w_start", w, "der(flange.phi) = w_start"),
                (self.use_a_start, "a_start", a, "der(w) = a_start")):
            if use:
                e.initial(value - e.input(getattr(self, port)), what)
        e.variable("phi_flange", phi, "rad", "flange angle")
        e.variable("w_flange", w, "rad/s", "= der(phi_flange)")


class TorqueToAngleAdaptor(interfaces.FlowToPotentialAdaptor):
    """Signal adaptor of a flange with the angle, speed and acceleration as outputs and the
    torque as input (MSL Components.TorqueToAngleAdaptor, for FMUs): flange.tau = tau
    [N.m]; phi = flange.phi [rad], w = der(phi) [rad/s] (option ``use_w``), a = der(w)
    [rad/s²] (option ``use_a``; 0 without ``use_w``, as MSL's der(0)). The block with an
    inertia behind it is what an FMU of a flange "with states" exposes (see
    models.rotational_fmus.DirectInertia)."""
    options = {"use_w": True, "use_a": True}
    connectors = ("phi", "w", "a", "tau")
    flange = Flange("flange", required=True)
    phi = RealOutput("flange moves with angle phi due to torque tau [rad]")
    w = ConditionalPort(RealOutput("flange moves with speed w due to torque tau [rad/s]"),
                        "use_w")
    a = ConditionalPort(RealOutput("flange moves with angular acceleration a due to torque "
                                   "tau [rad/s2]"), "use_a")
    tau = RealInput("torque to drive the flange [N.m]")


class AngleToTorqueAdaptor(interfaces.PotentialToFlowAdaptor):
    """Signal adaptor of a flange with the torque as output and the angle, speed and
    acceleration as inputs (MSL Components.AngleToTorqueAdaptor, for FMUs): the flange
    moves with the angle phi [rad], its speed w [rad/s] (option ``use_w``) and
    acceleration a [rad/s²] (option ``use_a``) as given (w = der(phi), a = der(w) are the
    user's to keep, as in MSL); tau = −flange.tau [N.m], the torque needed to move it so.
    As in MSL the input w exists if use_w or use_a (``use_a`` implies ``use_w``)."""
    options = {"use_w": True, "use_a": True}
    connectors = ("phi", "w", "a", "tau")
    flange = Flange("flange", required=True)
    phi = RealInput("angle to drive the flange [rad]")
    w = ConditionalPort(RealInput("speed to drive the flange (w = der(phi) required) "
                                  "[rad/s]"), "use_w")
    a = ConditionalPort(RealInput("angular acceleration to drive the flange (a = der(w) "
                                  "required) [rad/s2]"), "use_a")
    tau = RealOutput("torque needed to drive the flange according to phi, w, a [N.m]")

    def __init__(self, name: str | None = None, **params):
        params["use_w"] = params.get("use_w", True) or params.get("use_a", True)
        super().__init__(name, **params)


class GeneralTorqueToAngleAdaptor(interfaces.GeneralFlowToPotentialAdaptor):
    """Signal adaptor of a flange with the angle, speed and acceleration as outputs and the
    torque as input, with MSL's generic connector names (MSL
    Components.GeneralTorqueToAngleAdaptor, for FMUs): flange.tau = f [N.m]; p = flange.phi
    [rad], pder = der(p) [rad/s] (option ``use_pder``), pder2 = der(pder) [rad/s²] (option
    ``use_pder2``, only with ``use_pder`` as in MSL). MSL's inputs of the torque's
    derivatives are final off there and not offered."""
    flange = Flange("flange", required=True)
    p = RealOutput("output for potential: angle phi [rad]")
    pder = ConditionalPort(RealOutput("optional output for der(potential): angular velocity "
                                      "w [rad/s]"), "use_pder")
    pder2 = ConditionalPort(RealOutput("optional output for der2(potential): angular "
                                       "acceleration a [rad/s2]"), "use_pder2")
    f = RealInput("input for flow: torque tau [N.m]")


class GeneralAngleToTorqueAdaptor(interfaces.GeneralPotentialToFlowAdaptor):
    """Signal adaptor of a flange with the torque as output and the angle, speed and
    acceleration as inputs, with MSL's generic connector names (MSL
    Components.GeneralAngleToTorqueAdaptor, for FMUs): the flange moves with the angle p
    [rad], its speed pder [rad/s] (option ``use_pder``) and acceleration pder2 [rad/s²]
    (option ``use_pder2``, only with ``use_pder`` as in MSL) as given (the user's to keep
    consistent, as in MSL); f = −flange.tau [N.m], the torque needed to move it so. MSL's
    outputs of the torque's derivatives are final off there and not offered."""
    flange = Flange("flange", required=True)
    p = RealInput("input for potential: angle phi [rad]")
    pder = ConditionalPort(RealInput("optional input for der(potential): angular velocity w "
                                     "[rad/s]"), "use_pder")
    pder2 = ConditionalPort(RealInput("optional input for der2(potential): angular "
                                      "acceleration a [rad/s2]"), "use_pder2")
    f = RealOutput("output for flow: torque tau [N.m] needed to move the flange so")


# =========================================================================================
# Sensors
# =========================================================================================
class PartialAbsoluteSensor(Component):
    """Measures an absolute quantity of ``flange`` (no torque: flange.tau = 0)."""
    partial = True
    flange = Flange("flange to be measured", required=True)


class PartialRelativeSensor(Component):
    """Measures between ``flange_a`` and ``flange_b``."""
    partial = True
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

    ``acausal.models.DCMotorCircuit`` is the same motor composed of Modelica parts
    (SignalVoltage, Resistor, Inductor, RotationalEMF, Inertia; equal to 1e-10 in the
    tests). This compact form is kept because it is faster: it compiles in ~0.6 of the time
    (about 8 vs 13 ms), simulates in the same time, ~1.2–1.4x less CPU end to end
    (benchmarks/dc_motor.py); the composed one has the resistor's heat port.
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


# =========================================================================================
# Gears with losses, backlash
# =========================================================================================
class LossyGear(PartialElementaryTwoFlangesAndSupport2,
                interfaces.PartialElementaryConditionalHeatPortWithoutT):
    """Gear with mesh efficiency and bearing friction, stuck or rolling (MSL 4.1's
    LossyGear): phi_a = ratio·phi_b (relative to the support), 0 = flange_b.tau +
    ratio·(flange_a.tau − tauLoss), support.tau = −(flange_a.tau + flange_b.tau).

    ``lossTable`` (constructor keyword, rows [|w_a|, eta_mf1, eta_mf2, tau_bf1, tau_bf2],
    default [[0, 1, 1, 0, 0]], the ideal gear) gives the mesh efficiencies [1] when flange_a
    (eta_mf1) or flange_b (eta_mf2) drives and the resultant bearing friction [N.m] w.r.t.
    flange_a, interpolated in |w_a| as MSL's Smoothness.LinearSegments (the only smoothness
    here) with Extrapolation.LastTwoPoints. ``ratio`` [1] ≠ 0 (default 1 = MSL start value).

    Smooth form (``e.smooth``, for optimal control): no modes nor events; tauLoss =
    σ·max(quadrant1, quadrant2) + (1 − σ)·min(quadrant3, quadrant4), σ = ½(1 +
    tanh(w_a/w_smooth)), the table read at √(w_a² + w_smooth²/4) (≥ |w_a|, by at most
    w_smooth/2). For efficiencies with eta_mf1·eta_mf2 ≤ 1 the max and min are MSL's choice
    of quadrant by the sign of tau_eta (quadrant1 − quadrant2 = (1/eta_mf2 − eta_mf1)·tau_eta),
    so rolling at |w_a| ≫ w_smooth the loss is exact up to |tauLossMax − tauLossMin|·
    exp(−2|w_a|/w_smooth) (plus the table's slope·w_smooth/2); there is no stuck mode: where
    the exact gear sticks, the smooth one creeps with |w_a| of the order of w_smooth.

    The loss torque tauLoss [N.m] (on flange_a's side) is an algebraic variable switched on
    MSL's mode (2: ideal, 1: forward rolling w_a > 0, 0: stuck, −1: backward) and on
    tau_etaPos, MSL's relation tau_eta ≥ 0 (which side drives): rolling forward,
    tauLoss = quadrant1 (tau_etaPos) or quadrant2; backward, quadrant4 or quadrant3; stuck,
    a_a = 0 and tauLoss is the torque that holds the gear, between tauLossMin_m and
    tauLossMax_p. MSL writes its own mode machine for LossyGear (it does not extend
    PartialFriction); here it runs on the state-event engine as PartialFriction's does
    (``acausal.components.friction``): events ``rolling`` (w_a falling through 0 while
    rolling, setting w_a to 0 exactly), ``breakaway`` (the holding torque leaving
    [tauLossMin_m, tauLossMax_p] while stuck), ``start`` (w_a leaving the round-off
    band friction.W_NOISE around 0 after breaking away: startForward/startBackward, Boolean
    modes set at breakaway, are cleared then; rolling on forward out of it, stuck again the
    other way, see ``friction.start_indicator``) and ``tau_eta`` (the driving side changing: the kink
    between quadrants, past a band of round-off; a mode only of a gear with losses). Two
    elements stuck on one shaft (a LossyGear and a BearingFriction) leave the split of their
    holding torque undetermined: the simulator keeps the split they stuck with (see
    ``acausal.simulation.events``). A rolling gear
    that reaches w_a = 0 keeps rolling only if its acceleration there keeps its direction.
    The mode starts at Free (MSL: start = Free, fixed = true); at the start, as MSL's
    initial(), it takes the direction of w_a, or Stuck.

    Records MSL's variables: phi_a, phi_b, w_a, a_a, sa, eta_mf1, eta_mf2, tau_bf1,
    tau_bf2, tau_bf_a, tau_eta, tau_eta_p, tau_eta_m, quadrant1..4, quadrant1_p,
    quadrant2_p, quadrant3_m, quadrant4_m, tauLoss, tauLossMax, tauLossMin, tauLossMax_p,
    tauLossMin_m, tau_aPos, tau_etaPos, startForward, startBackward, locked, ideal, mode,
    lossPower [W] (MSL's interpolation_result matrix is not recorded: its columns are
    eta_mf1, eta_mf2, tau_bf1, tau_bf2). The ideal table gives an IdealGear without events
    (mode 2, tauLoss 0). useHeatPort: heatPort.Q_flow = −lossPower.
    """
    options = {"useSupport": False}
    ratio = Parameter(1.0, "1", "transmission ratio (flange_a.phi/flange_b.phi)", nonzero=True)
    w_smooth = Parameter(1.0e-3, "rad/s", "smooth form (compile(smooth=True)): speed over "
                                          "which the loss changes from rolling backward to "
                                          "forward", positive=True)
    IDEAL = ((0.0, 1.0, 1.0, 0.0, 0.0),)

    def __init__(self, name: str | None = None, **params):
        table = params.pop("lossTable", self.IDEAL)
        super().__init__(name, **params)
        try:
            tab = np.array(table, dtype=float)
        except (TypeError, ValueError):
            tab = np.zeros((0, 0))
        if tab.ndim != 2 or tab.shape[1] != 5 or tab.shape[0] < 1:
            raise ParameterError(f"parameter 'LossyGear.lossTable' must be a table of rows "
                                 f"[w, eta_mf1, eta_mf2, tau_bf1, tau_bf2], got {table!r}")
        for k in range(1, 5):                     # speeds increasing from >= 0, finite values
            friction.check_table(tab[:, [0, k]], "lossTable", "LossyGear")
        if np.any(tab[:, 1:3] <= 0):
            raise ParameterError(f"parameter 'LossyGear.lossTable': the efficiencies eta_mf1, "
                                 f"eta_mf2 (columns 2 and 3) must be > 0, got "
                                 f"{tab[:, 1:3].tolist()}")
        self.__dict__["lossTable"] = tab
        self.__dict__["ideal"] = tab.shape == (1, 5) and np.allclose(
            tab, self.IDEAL, rtol=0.0, atol=_EPS)

    def _losses(self, w):
        """(eta_mf1, eta_mf2, tau_bf1, tau_bf2, tau_bf_a) at |w_a| = w: the table's columns
        and MSL's split tau_bf_a [N.m] of the bearing friction to flange_a's side."""
        eta1, eta2, bf1, bf2 = (friction.table_value(self.lossTable[:, [0, k]], w)
                                for k in range(1, 5))
        bf1, bf2 = ca.fabs(bf1), ca.fabs(bf2)
        unit = ca.logic_and(ca.fabs(eta1 - 1.0) <= _EPS, ca.fabs(eta2 - 1.0) <= _EPS)
        tau_bf_a = ca.if_else(unit, bf1 / 2, (bf1 - bf2) / ca.if_else(unit, 1.0,
                                                                       eta1 - 1.0 / eta2))
        return eta1, eta2, bf1, bf2, tau_bf_a

    def structure(self, s):
        self._relative_constraint(s, {self.flange_a: 1.0, self.flange_b: -self.ratio}, 0.0,
                                  f"{self.path}: phi_a = ratio*phi_b")
        if self.ideal:
            return
        s.algebraic("tauLoss", unit="N.m", description="torque loss due to friction in the "
                                                       "gear teeth and in the bearings")
        if s.smooth:
            return
        s.mode("mode", friction.FREE, values=friction.MODES[:-1],
               description="mode of friction element (-1: backward rolling, 0: stuck, "
                           "1: forward rolling, 2: not active)")
        s.mode("startForward", 0, values=(0, 1), description="= true, if starting to roll "
                                                             "forward")
        s.mode("startBackward", 0, values=(0, 1), description="= true, if starting to roll "
                                                              "backward")
        s.mode("tau_etaPos", 1, values=(0, 1), description="= true, if torque tau_eta is "
                                                           "not negative")

    def physics(self, e):
        phi_a, phi_b = (self._rel_position(e, f) for f in (self.flange_a, self.flange_b))
        w, a = self._rel_speed(e, self.flange_a), self._rel_acc(e, self.flange_a)
        e.variable("phi_a", phi_a, "rad", "angle between left shaft flange and support")
        e.variable("phi_b", phi_b, "rad", "angle between right shaft flange and support")
        e.variable("w_a", w, "rad/s", "angular velocity of flange_a with respect to support")
        e.variable("a_a", a, "rad/s2", "angular acceleration of flange_a with respect to "
                                       "support")
        e.variable("ideal", float(self.ideal), "", "= true, if losses are neglected (that is "
                                                   "lossTable = [0, 1, 1, 0, 0])")
        if self.ideal:
            e.variable("mode", friction.FREE, "", "mode of friction element")
            e.variable("tauLoss", 0.0, "N.m", "torque loss")
            self._loss_power(e, 0.0)
            return
        tau_loss = e.state("tauLoss")
        e.flow(self.flange_a, tau_loss)
        if self.useSupport:
            e.flow(self.support, -tau_loss)
        tau_a = e.cut_flow(self.flange_a)                      # flange_a.tau
        self._loss_power(e, tau_loss * w)
        if e.smooth:
            self._smooth(e, tau_loss, tau_a, w, a)
        else:
            self._modes(e, tau_loss, tau_a, w, a)

    def _quadrants(self, tau_a, w):
        """MSL's quadrant1..4 [N.m] at |w_a| = w, and eta_mf1, eta_mf2, tau_bf1, tau_bf2,
        tau_bf_a there."""
        eta1, eta2, bf1, bf2, tau_bf_a = self._losses(w)
        return ((1 - eta1) * tau_a + bf1, (1 - 1 / eta2) * tau_a + bf2,
                (1 - eta1) * tau_a - bf1, (1 - 1 / eta2) * tau_a - bf2,
                (eta1, eta2, bf1, bf2, tau_bf_a))

    def _smooth(self, e, tau_loss, tau_a, w, a):
        """The smooth form: tauLoss = σ·max(q1, q2) + (1 − σ)·min(q3, q4), σ = ½(1 +
        tanh(w_a/w_smooth)), the table at the rounded |w_a| (see the class)."""
        q1, q2, q3, q4, _ = self._quadrants(tau_a, _smax(w, -w, self.w_smooth))
        up = 0.5 * (1 + ca.tanh(w / self.w_smooth))
        e.residual(tau_loss - (up * ca.fmax(q1, q2) + (1 - up) * ca.fmin(q3, q4)))

    def _modes(self, e, tau_loss, tau_a, w, a):
        """The exact form: MSL's modes on state events (see the class)."""
        FORWARD, STUCK, BACKWARD = friction.FORWARD, friction.STUCK, friction.BACKWARD
        mode = e.mode("mode")
        start_fwd, start_bwd, pos = (e.mode(n) for n in ("startForward", "startBackward",
                                                         "tau_etaPos"))
        q1, q2, q3, q4, (eta1, eta2, bf1, bf2, tau_bf_a) = self._quadrants(tau_a, ca.fabs(w))
        q1_p, q2_p, q3_m, q4_m, (*_, tau_bf_a_0) = self._quadrants(tau_a, 0.0)   # w_a = 0±
        tau_eta_p, tau_eta_m = tau_a - tau_bf_a_0, tau_a + tau_bf_a_0
        loss_max_p = ca.if_else(tau_eta_p > 0, q1_p, q2_p)
        loss_min_m = ca.if_else(tau_eta_m > 0, q4_m, q3_m)
        loss_max = ca.if_else(pos, q1, q2)
        loss_min = ca.if_else(pos, q4, q3)

        fwd = ca.logic_or(mode == FORWARD, start_fwd)
        bwd = ca.logic_or(mode == BACKWARD, start_bwd)
        locked = ca.logic_not(ca.logic_or(fwd, bwd))
        by_sign = ca.if_else(w > 0, tau_loss - loss_max,         # mode Free: at the start
                             ca.if_else(w < 0, tau_loss - loss_min, a))
        e.residual(ca.if_else(fwd, tau_loss - loss_max, ca.if_else(
            bwd, tau_loss - loss_min, ca.if_else(mode == STUCK, a, by_sign))))
        tau_eta = ca.if_else(locked, tau_a, ca.if_else(fwd, tau_a - tau_bf_a, tau_a + tau_bf_a))

        stuck = ca.logic_and(locked, mode == STUCK)
        starting = ca.logic_or(start_fwd, start_bwd)
        e.indicator("rolling", ca.if_else(starting, 1.0, ca.if_else(fwd, w, ca.if_else(
            bwd, -w, 1.0))), "rad/s", "w_a while rolling (not starting), in its direction")
        e.indicator("breakaway", ca.if_else(stuck, ca.fmin(loss_max_p - tau_loss,
                                                           tau_loss - loss_min_m), 1.0),
                    "N.m", "distance of the holding torque to its bounds while stuck")
        friction.start_indicator(e, w, starting, "rad/s", "angular velocity w_a")
        # MSL's relation tau_eta >= 0 with a hysteresis of its round-off (as a simulator's
        # crossing functions): in LossyGearDemo3 tau_eta is 0 while rolling, up to noise
        band = 1e-10 * (ca.fabs(tau_a) + ca.fabs(tau_bf_a) + 1.0)
        e.indicator("tau_eta", ca.if_else(pos, tau_eta + band, tau_eta - band), "N.m",
                    "torque that determines the driving side (tau_eta), past a band of "
                    "round-off on the side of tau_etaPos")
        stop = e.vel(self.support) if self.useSupport else 0.0
        e.reinit(e.vel(self.flange_a), stop, when="rolling", direction=-1)
        e.reinit(e.vel(self.flange_a), stop, when="breakaway", direction=-1)

        breaks_fwd = ca.logic_and(stuck, tau_loss > loss_max_p)
        breaks_bwd = ca.logic_and(stuck, tau_loss < loss_min_m)
        e.mode_update(start_fwd, ca.logic_or(breaks_fwd, ca.logic_and(
            mode == FORWARD, friction.still_starting(start_fwd, w))))
        e.mode_update(start_bwd, ca.logic_or(breaks_bwd, ca.logic_and(
            mode == BACKWARD, friction.still_starting(start_bwd, w))))
        e.mode_update(pos, ca.if_else(pos, tau_eta + band >= 0, tau_eta - band > 0))
        keeps_fwd = ca.logic_or(w > 0, ca.logic_and(w == 0, ca.logic_or(a > 0, start_fwd)))
        keeps_bwd = ca.logic_or(w < 0, ca.logic_and(w == 0, ca.logic_or(a < 0, start_bwd)))
        sign_w = friction.direction(w)
        e.mode_update(mode, ca.if_else(
            mode == STUCK, ca.if_else(breaks_fwd, FORWARD, ca.if_else(breaks_bwd, BACKWARD,
                                                                        STUCK)),
            ca.if_else(mode == FORWARD, ca.if_else(keeps_fwd, FORWARD, STUCK),
                       ca.if_else(mode == BACKWARD, ca.if_else(keeps_bwd, BACKWARD, STUCK),
                                  sign_w))))

        for name, value, descr in [
                ("sa", ca.if_else(locked, tau_loss, a + tau_loss),
                 "path parameter for acceleration and torque loss"),
                ("eta_mf1", eta1, "mesh efficiency in case that flange_a is driving"),
                ("eta_mf2", eta2, "mesh efficiency in case that flange_b is driving")]:
            e.variable(name, value, "1", descr)
        for name, value, descr in [
                ("tau_bf1", bf1, "absolute resultant bearing friction torque with respect "
                                 "to flange_a in case that flange_a is driving"),
                ("tau_bf2", bf2, "absolute resultant bearing friction torque with respect "
                                 "to flange_a in case that flange_b is driving"),
                ("tau_bf_a", tau_bf_a, "bearing friction torque on flange_a side"),
                ("tau_eta", tau_eta, "torque that determines the driving side"),
                ("tau_eta_p", tau_eta_p, "tau_eta assuming positive omega"),
                ("tau_eta_m", tau_eta_m, "tau_eta assuming negative omega"),
                ("quadrant1", q1, "torque loss if w_a > 0 and flange_a.tau >= 0"),
                ("quadrant2", q2, "torque loss if w_a > 0 and flange_a.tau < 0"),
                ("quadrant3", q3, "torque loss if w_a < 0 and flange_a.tau >= 0"),
                ("quadrant4", q4, "torque loss if w_a < 0 and flange_a.tau < 0"),
                ("quadrant1_p", q1_p, "torque loss at w_a = 0+ (flange_a.tau >= 0)"),
                ("quadrant2_p", q2_p, "torque loss at w_a = 0+ (flange_a.tau < 0)"),
                ("quadrant3_m", q3_m, "torque loss at w_a = 0- (flange_a.tau >= 0)"),
                ("quadrant4_m", q4_m, "torque loss at w_a = 0- (flange_a.tau < 0)"),
                ("tauLossMax", loss_max, "torque loss for positive speed"),
                ("tauLossMin", loss_min, "torque loss for negative speed"),
                ("tauLossMax_p", loss_max_p, "torque loss for positive speed (at w_a = 0+)"),
                ("tauLossMin_m", loss_min_m, "torque loss for negative speed (at w_a = 0-)")]:
            e.variable(name, value, "N.m", descr)
        e.variable("tau_aPos", pos, "", "only for backwards compatibility (= tau_etaPos)")
        e.variable("locked", locked, "", "= true, if gear is locked")


def _smax(x, y, eps):
    """max(x, y) rounded over a width eps: ½(x + y + √((x − y)² + eps²)), above the max by
    at most eps/2 (where x = y), by less than eps²/(4|x − y|) away from it."""
    return 0.5 * (x + y + ca.sqrt((x - y) ** 2 + eps ** 2))


def _smin(x, y, eps):
    """min(x, y) rounded over a width eps, below it by at most eps/2 (see _smax)."""
    return -_smax(-x, -y, eps)


class _ElastoBacklash(PartialCompliantWithRelativeStates,
                      interfaces.PartialElementaryConditionalHeatPortWithoutT):
    """Backlash b [rad] in series with a linear spring c [N.m/rad] and damper d [N.m.s/rad]
    (MSL's ElastoBacklash and ElastoBacklash2): no torque while bMin ≤ phi_diff ≤ bMax
    (phi_diff = phi_rel − phi_rel0 [rad], bMax = b/2 = −bMin); in contact the spring torque
    tau_c = c·(phi_diff ∓ b/2) and the damper torque tau_d = d·w_rel, never pulling; a
    plain spring-damper when b ≤ bEps = 1e-10 rad.

    Events (MSL's relations phi_diff > bMax, phi_diff < bMin): the mode ``contact`` (1:
    contact at bMax, 0: in the backlash, −1: contact at bMin) changes at the indicators
    ``bMax`` (phi_diff − bMax) and ``bMin`` (phi_diff − bMin), the Boolean mode ``pushing``
    (tau_c + tau_d pushes, in the contact's direction) at the indicator ``pushing``; the
    torque is written for the modes, so the integrator never steps across a kink. During
    initialization MSL replaces the characteristic by a monotone one (for solving initial
    equations); here the start values are given (x0) and that form is not needed.

    Smooth form (``e.smooth``): the contacts' kinks rounded over ``phi_smooth`` [rad] (and
    the torques' over c·phi_smooth [N.m]) by √(x² + ε²) maxima, no modes nor events (the
    subclasses give the error). Records tau_c, tau_d, phi_diff (MSL's protected variables),
    contact, pushing, tau, lossPower [W]. useHeatPort: heatPort.Q_flow = −lossPower.
    """
    options = {"stateSelect": StateSelect.prefer}
    c = Parameter(1.0e5, "N.m/rad", "spring constant (c > 0 required)", positive=True)
    d = Parameter(0.0, "N.m.s/rad", "damping constant", nonnegative=True)
    b = Parameter(0.0, "rad", "total backlash", nonnegative=True)
    phi_rel0 = Parameter(0.0, "rad", "unstretched spring angle")
    phi_smooth = Parameter(1.0e-5, "rad", "smooth form (compile(smooth=True)): width of the "
                                          "rounded contact kinks", positive=True)
    bEps = 1e-10                 # rad, MSL's minimum backlash

    def structure(self, s):
        if s.smooth:
            return
        s.mode("contact", 0, values=(-1, 0, 1),
               description="1: contact at phi_diff = b/2, 0: in the backlash, -1: contact at "
                           "phi_diff = -b/2")
        s.mode("pushing", 0, values=(0, 1), description="= true, if in contact and tau_c + "
                                                        "tau_d pushes")
        self._structure_modes(s)

    def _structure_modes(self, s):
        """Further modes of a subclass."""

    def _law(self, e, phi_rel, w_rel):
        phi_diff, b_max = phi_rel - self.phi_rel0, self.b / 2
        plain = self.b <= self.bEps
        tau_d = self.d * w_rel
        if e.smooth:
            eps = self.phi_smooth
            tau_c = self.c * (_smax(phi_diff - b_max, 0.0, eps)
                              + _smin(phi_diff + b_max, 0.0, eps))
            tau, loss = self._smooth_law(phi_diff, b_max, tau_d, w_rel)
        else:
            contact, pushing = e.mode("contact"), e.mode("pushing")
            tau_c = self.c * (phi_diff - contact * b_max)        # in contact
            tc, td = contact * tau_c, contact * tau_d            # in its direction
            tau, loss = self._contact_law(e, contact, tc, td)
            tau = ca.if_else(pushing, contact * tau, 0.0)
            loss = ca.if_else(pushing, contact * loss * w_rel, 0.0)    # back from the
            # contact's direction: at bMin (contact −1) the loss torque is −loss
            tau_c = ca.if_else(contact == 0, 0.0, tau_c)
            touching = ca.logic_and(contact != 0, ca.logic_not(plain))
            e.indicator("bMax", ca.if_else(plain, 1.0, phi_diff - b_max), "rad",
                        "phi_diff - b/2")
            e.indicator("bMin", ca.if_else(plain, 1.0, phi_diff + b_max), "rad",
                        "phi_diff + b/2")
            e.indicator("pushing", ca.if_else(touching, tc + td, 1.0), "N.m",
                        "tau_c + tau_d in the contact's direction, in contact")
            e.mode_update(contact, ca.if_else(phi_diff > b_max, 1, ca.if_else(
                phi_diff < -b_max, -1, 0)))
            e.mode_update(pushing, ca.logic_and(contact != 0, tc + td > 0))
        e.variable("phi_diff", phi_diff, "rad", "phi_rel - phi_rel0")
        e.variable("tau_c", ca.if_else(plain, self.c * phi_diff, tau_c), "N.m",
                   "spring torque")
        e.variable("tau_d", tau_d, "N.m", "damper torque")
        return (ca.if_else(plain, self.c * phi_diff + tau_d, tau),
                ca.if_else(plain, tau_d * w_rel, loss))

    def _contact_law(self, e, contact, tc, td):
        """(torque, loss torque) in contact and pushing, in the contact's direction, from the
        spring and damper torques tc, td in that direction; the loss torque times w_rel is
        lossPower."""
        raise NotImplementedError

    def _smooth_law(self, phi_diff, b_max, tau_d, w_rel):
        """(tau, lossPower) of the smooth form."""
        raise NotImplementedError


class ElastoBacklash(_ElastoBacklash):
    """Backlash in series with a spring and damper (MSL's ElastoBacklash): in contact and
    pushing, flange_b.tau = tau_c + min(tau_c, tau_d) in the contact's direction (the damper
    torque limited by the spring torque: no jump at the start of contact, no pulling),
    lossPower = min(tau_c, tau_d)·w_rel. See _ElastoBacklash for the rest.

    Besides MSL's events (contact), the mode ``limited`` (tau_d ≥ tau_c in the contact's
    direction, the damping limited) changes at the indicator ``limited`` (tau_d − tau_c), so
    that every kink of the law is an event (MSL writes it under noEvent).

    Smooth form: |tau − exact| ≤ 4·c·phi_smooth [N.m] (each of the four rounded maxima
    adds at most half its width, and a rounded contact deflection c·phi_smooth/2).
    """
    def _structure_modes(self, s):
        s.mode("limited", 0, values=(0, 1), description="= true, if in contact and the "
                                                        "damper torque is limited by tau_c")

    def _contact_law(self, e, contact, tc, td):
        limited = e.mode("limited")
        e.indicator("limited", ca.if_else(contact != 0, td - tc, -1.0), "N.m",
                    "tau_d - tau_c in the contact's direction, in contact")
        e.mode_update(limited, ca.logic_and(contact != 0, td > tc))
        e.variable("limited", limited, "", "= true, if the damper torque is limited")
        damper = ca.if_else(limited, tc, td)
        return tc + damper, damper

    def _smooth_law(self, phi_diff, b_max, tau_d, w_rel):
        eps, tau_eps = self.phi_smooth, self.c * self.phi_smooth
        tc_pos = self.c * _smax(phi_diff - b_max, 0.0, eps)
        tc_neg = self.c * _smin(phi_diff + b_max, 0.0, eps)
        d_pos, d_neg = _smin(tc_pos, tau_d, tau_eps), _smax(tc_neg, tau_d, tau_eps)
        tau_pos = _smax(tc_pos + d_pos, 0.0, tau_eps)
        tau_neg = _smin(tc_neg + d_neg, 0.0, tau_eps)
        return tau_pos + tau_neg, (d_pos + d_neg) * w_rel


class ElastoBacklash2(_ElastoBacklash):
    """Backlash in series with a spring and damper (MSL 4.x's ElastoBacklash2): in contact
    and pushing, flange_b.tau = tau_c + tau_d (it jumps by tau_d when contact starts: an
    event), zero when it would pull; lossPower = tau_d·w_rel. See _ElastoBacklash for the
    rest.

    Smooth form: tau_d switched on by ½(1 ± tanh((phi_diff ∓ b/2)/phi_smooth)) and the
    no-pull limit rounded over c·phi_smooth: |tau − exact| ≤ 1.5·c·phi_smooth +
    d·|w_rel|·exp(−2·|phi_diff ∓ b/2|/phi_smooth) [N.m] (the torque's jump at contact spread
    over a few phi_smooth).
    """

    def _contact_law(self, e, contact, tc, td):
        return tc + td, td

    def _smooth_law(self, phi_diff, b_max, tau_d, w_rel):
        eps, tau_eps = self.phi_smooth, self.c * self.phi_smooth
        on_pos = 0.5 * (1 + ca.tanh((phi_diff - b_max) / eps))
        on_neg = 0.5 * (1 - ca.tanh((phi_diff + b_max) / eps))
        tau_pos = _smax(self.c * _smax(phi_diff - b_max, 0.0, eps) + on_pos * tau_d, 0.0,
                        tau_eps)
        tau_neg = _smin(self.c * _smin(phi_diff + b_max, 0.0, eps) + on_neg * tau_d, 0.0,
                        tau_eps)
        return tau_pos + tau_neg, tau_d * w_rel * (on_pos + on_neg)


class Gearbox(Model):
    """Realistic model of a gearbox (MSL's Components.Gearbox): a LossyGear (mesh efficiency
    and bearing friction) in series with an ElastoBacklash (gear elasticity, damping and
    backlash), composed of these parts as in MSL::

        flange_a ── lossyGear ── elastoBacklash ── flange_b
                    (lossyGear.support ── support, or fixed with useSupport=False)

    Constructor keywords (MSL's parameters): ratio [1] (1 = MSL start value; flange_a.phi /
    lossyGear.flange_b.phi), lossTable (rows [|w_a|, eta_mf1, eta_mf2, tau_bf1, tau_bf2],
    default [[0, 1, 1, 0, 0]], see LossyGear), c [N.m/rad] > 0 (1e5), d [N.m.s/rad] ≥ 0 (0),
    b [rad] ≥ 0 (0, total backlash), stateSelect (prefer); options useSupport and
    useHeatPort (the losses of both parts leave through ``heatPort``). The elasticity's
    relative angle phi_rel = flange_b.phi − lossyGear.flange_b.phi [rad] and w_rel [rad/s]
    are ``elastoBacklash.phi_rel``, ``elastoBacklash.w_rel`` (states).

    Differences from MSL: the keywords set the parts' parameters (``lossyGear.ratio``,
    ``elastoBacklash.c``, ...), by which they are changed at simulation time (an acausal
    Model has no parameters of its own to bind its parts' to); phi_rel, w_rel, a_rel are
    recorded under ``elastoBacklash`` only.
    """
    options = {"useSupport": False, "useHeatPort": False}
    flange_a = Flange("flange of left shaft")
    flange_b = Flange("flange of right shaft")
    support = _support()
    heatPort = ConditionalPort(HeatPort_a("optional port to which dissipated losses are "
                                          "transported in form of heat", required=True),
                               "useHeatPort")

    def __init__(self, name: str | None = None, *, ratio: float = 1.0,
                 lossTable=LossyGear.IDEAL, c: float = 1.0e5, d: float = 0.0, b: float = 0.0,
                 stateSelect: StateSelect = StateSelect.prefer, useSupport: bool = False,
                 useHeatPort: bool = False):
        super().__init__(name, useSupport=useSupport, useHeatPort=useHeatPort)
        self.lossyGear = LossyGear(ratio=ratio, lossTable=lossTable, useSupport=True,
                                   useHeatPort=useHeatPort)
        self.elastoBacklash = ElastoBacklash(b=b, c=c, d=d, phi_rel0=0.0,
                                             stateSelect=stateSelect, useHeatPort=useHeatPort)
        self.connect(self.flange_a, self.lossyGear.flange_a)
        self.connect(self.lossyGear.flange_b, self.elastoBacklash.flange_a)
        self.connect(self.elastoBacklash.flange_b, self.flange_b)
        if useSupport:
            self.connect(self.lossyGear.support, self.support)
        else:
            self.fixed = Fixed()
            self.connect(self.lossyGear.support, self.fixed.flange)
        if useHeatPort:
            self.connect(self.lossyGear.heatPort, self.heatPort)
            self.connect(self.elastoBacklash.heatPort, self.heatPort)
