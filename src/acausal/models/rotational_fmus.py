"""MSL's Rotational.Examples.GenerationOfFMUs and the blocks of its Utilities: rotational
parts behind a pure signal interface, to be exported as FMUs (``compile(DirectInertia())
.export_fmu(...)``: a model's own connectors are the inputs and outputs of its FMU) and
connected again, signal to signal, in another tool.

Before export one must know how a part is used on the other side: an inertia "with states"
(``DirectInertia``: torques in, angle, speed and acceleration out) drives an inertia moved
by them (``InverseInertia``: the torque it needs out); a force law between two inertias
gets their angles (``Spring``) or angles and speeds (``SpringDamper``) and returns the
torques on both. Composed, the example must give what the same parts connected by flanges
give (MSL's check of a tool's FMU export and import):

    sine1 ─ directInertia ═(phi, w, a → ← tau)═ inverseInertia   (one inertia 1.1 + 2.2)
    sine1 ─ torque2 ─ inertia2a ─ torqueToAngle2a ═ springDamper ═ torqueToAngle2b ─ inertia2b
    sine1 ─ force3 ─ inertia3a ─ torqueToAngle3a ═ spring ═ torqueToAngle3b ─ inertia3b

The experiment: StopTime 1 s, Interval 0.001 s, every inertia at rest at 0 (``START``).
"""
from __future__ import annotations

from ..components import interfaces
from ..components.rotational import (AngleToTorqueAdaptor, Inertia, PartialCompliant, Spring
                                     as SpringComponent, SpringDamper as SpringDamperComponent,
                                     Torque, TorqueToAngleAdaptor)
from ..components.signals import Sine
from ..core import Model, Parameter, RealInput, RealOutput

STOP_TIME, INTERVAL = 1.0, 0.001            # s, the MSL experiment


class SpringDamperNoRelativeStates(PartialCompliant,
                                   interfaces.PartialElementaryConditionalHeatPortWithoutT):
    """Linear 1-D rotational spring and damper in parallel whose relative angle and speed
    are not states (MSL Examples.Utilities.SpringDamperNoRelativeStates): the law of
    SpringDamper, tau = c·(phi_rel − phi_rel0) + d·w_rel, lossPower = d·w_rel², without
    its a_rel = der(w_rel), which would need the flanges' accelerations (inputs of an FMU
    that moves them by angle and speed only). Defaults c = 1e5 N.m/rad, d = 0 N.m.s/rad
    (MSL's start values)."""
    batch_physics = True       # physics: port motion and parameters only
    c = Parameter(1.0e5, "N.m/rad", "spring constant", nonnegative=True)
    d = Parameter(0.0, "N.m.s/rad", "damping constant", nonnegative=True)
    phi_rel0 = Parameter(0.0, "rad", "unstretched spring angle")
    torque = SpringDamperComponent.torque
    loss_power = SpringDamperComponent.loss_power


class DirectInertia(Model):
    """Input/output block of a direct inertia model (MSL Examples.Utilities.DirectInertia):
    the torque tauDrive [N.m] accelerates an inertia J [kg.m²] (default 1; start at rest at
    0) on one side, the torque tau [N.m] drives it on the other (a TorqueToAngleAdaptor);
    outputs its angle phi [rad], speed w [rad/s] and acceleration a [rad/s²]. Its states
    are ``inertia.phi``, ``inertia.w``; the output a depends on the inputs directly."""
    tauDrive = RealInput("accelerating torque acting at flange (= -flange.tau) [N.m]")
    phi = RealOutput("inertia moves with angle phi due to torque tau [rad]")
    w = RealOutput("inertia moves with speed w due to torque tau [rad/s]")
    a = RealOutput("inertia moves with acceleration a due to torque tau [rad/s2]")
    tau = RealInput("torque to drive the inertia [N.m]")

    def __init__(self, name: str | None = None, *, J: float = 1.0):
        super().__init__(name)
        self.inertia = Inertia(J=J)
        self.torqueSource = Torque()
        self.torqueToAngle = TorqueToAngleAdaptor()
        for a, b in [(self.tauDrive, self.torqueSource.tau),
                     (self.torqueSource.flange, self.inertia.flange_a),
                     (self.inertia.flange_b, self.torqueToAngle.flange),
                     (self.torqueToAngle.phi, self.phi), (self.torqueToAngle.w, self.w),
                     (self.torqueToAngle.a, self.a), (self.tau, self.torqueToAngle.tau)]:
            self.connect(a, b)


class InverseInertia(Model):
    """Input/output block of an inverse inertia model (MSL Examples.Utilities.InverseInertia):
    an inertia J [kg.m²] (default 1) moved by the angle phi [rad], speed w [rad/s] and
    acceleration a [rad/s²] (an AngleToTorqueAdaptor; the three consistent is the user's
    to keep, as in MSL); output the torque tau = J·a [N.m] needed to move it so. No
    states: tau depends on the input a directly."""
    phi = RealInput("angle to drive the inertia [rad]")
    w = RealInput("speed to drive the inertia [rad/s]")
    a = RealInput("acceleration to drive the inertia [rad/s2]")
    tau = RealOutput("torque needed to drive the flange according to phi, w, a [N.m]")

    def __init__(self, name: str | None = None, *, J: float = 1.0):
        super().__init__(name)
        self.inertia = Inertia(J=J)
        self.angleToTorque = AngleToTorqueAdaptor()
        for a, b in [(self.angleToTorque.flange, self.inertia.flange_a),
                     (self.phi, self.angleToTorque.phi), (self.w, self.angleToTorque.w),
                     (self.a, self.angleToTorque.a), (self.angleToTorque.tau, self.tau)]:
            self.connect(a, b)


class Spring(Model):
    """Input/output block of a spring model (MSL Examples.Utilities.Spring): a linear
    spring (c [N.m/rad], default 1e4; phi_rel0 [rad], default 0) between two flanges moved
    by the angles phi1, phi2 [rad] (AngleToTorqueAdaptors without speed and acceleration);
    outputs the torques tau1, tau2 [N.m] needed to move them so: tau1 = −tau2 =
    −c·(phi2 − phi1 − phi_rel0). No states."""
    phi1 = RealInput("angle of left flange of force element [rad]")
    tau1 = RealOutput("torque generated by the force element [N.m]")
    phi2 = RealInput("angle of right flange of force element [rad]")
    tau2 = RealOutput("torque generated by the force element [N.m]")

    def __init__(self, name: str | None = None, *, c: float = 1.0e4, phi_rel0: float = 0.0):
        super().__init__(name)
        self.angleToTorque1 = AngleToTorqueAdaptor(use_w=False, use_a=False)
        self.spring = SpringComponent(c=c, phi_rel0=phi_rel0)
        self.angleToTorque2 = AngleToTorqueAdaptor(use_w=False, use_a=False)
        for a, b in [(self.angleToTorque1.flange, self.spring.flange_a),
                     (self.spring.flange_b, self.angleToTorque2.flange),
                     (self.phi1, self.angleToTorque1.phi), (self.angleToTorque1.tau, self.tau1),
                     (self.angleToTorque2.phi, self.phi2), (self.angleToTorque2.tau, self.tau2)]:
            self.connect(a, b)


class SpringDamper(Model):
    """Input/output block of a spring/damper model (MSL Examples.Utilities.SpringDamper): a
    linear spring and damper in parallel (SpringDamperNoRelativeStates: c [N.m/rad],
    default 1e4; d [N.m.s/rad], default 1; phi_rel0 [rad], default 0) between two flanges
    moved by the angles phi1, phi2 [rad] and speeds w1, w2 [rad/s] (AngleToTorqueAdaptors
    without acceleration); outputs the torques tau1, tau2 [N.m] needed to move them so:
    tau1 = −tau2 = −(c·(phi2 − phi1 − phi_rel0) + d·(w2 − w1)). No states."""
    phi1 = RealInput("angle of left flange of force element [rad]")
    w1 = RealInput("speed to left flange of force element [rad/s]")
    tau1 = RealOutput("torque generated by the force element [N.m]")
    phi2 = RealInput("angle of right flange of force element [rad]")
    w2 = RealInput("speed to right flange of force element [rad/s]")
    tau2 = RealOutput("torque generated by the force element [N.m]")

    def __init__(self, name: str | None = None, *, c: float = 1.0e4, d: float = 1.0,
                 phi_rel0: float = 0.0):
        super().__init__(name)
        self.angleToTorque1 = AngleToTorqueAdaptor(use_a=False)
        self.springDamper = SpringDamperNoRelativeStates(c=c, d=d, phi_rel0=phi_rel0)
        self.angleToTorque2 = AngleToTorqueAdaptor(use_a=False)
        for a, b in [(self.springDamper.flange_b, self.angleToTorque2.flange),
                     (self.angleToTorque1.flange, self.springDamper.flange_a),
                     (self.phi1, self.angleToTorque1.phi), (self.w1, self.angleToTorque1.w),
                     (self.angleToTorque1.tau, self.tau1), (self.angleToTorque2.phi, self.phi2),
                     (self.w2, self.angleToTorque2.w), (self.angleToTorque2.tau, self.tau2)]:
            self.connect(a, b)


class GenerationOfFMUs(Model):
    """MSL's Rotational.Examples.GenerationOfFMUs: a sine torque (10 N.m, 2 Hz) drives
    (1) a DirectInertia (J = 1.1 kg.m²) connected by signals to an InverseInertia (J = 2.2
    kg.m²), (2) inertia2a (1.1 kg.m²) connected to inertia2b (2.2 kg.m²) through a
    SpringDamper block (c = 1e4 N.m/rad, d = 100 N.m.s/rad) and TorqueToAngleAdaptors
    without acceleration, (3) inertia3a to inertia3b likewise through a Spring block
    (c = 1e4 N.m/rad) and adaptors with the angle only. All at rest at 0 (``START``)."""
    START = {f"{name}.{v}": 0.0 for name in ("directInertia.inertia", "inertia2a", "inertia2b",
                                             "inertia3a", "inertia3b") for v in ("phi", "w")}

    def __init__(self, name: str = "GenerationOfFMUs"):
        super().__init__(name)
        self.sine1 = Sine(f=2.0, amplitude=10.0)
        self.directInertia = DirectInertia(J=1.1)
        self.inverseInertia = InverseInertia(J=2.2)
        self.springDamper = SpringDamper(c=1e4, d=100.0)
        self.inertia2a = Inertia(J=1.1)
        self.torque2 = Torque()
        self.torqueToAngle2a = TorqueToAngleAdaptor(use_a=False)
        self.inertia2b = Inertia(J=2.2)
        self.torqueToAngle2b = TorqueToAngleAdaptor(use_a=False)
        self.spring = Spring(c=1e4)
        self.inertia3a = Inertia(J=1.1)
        self.force3 = Torque()
        self.torqueToAngle3a = TorqueToAngleAdaptor(use_w=False, use_a=False)
        self.inertia3b = Inertia(J=2.2)
        self.torqueToAngle3b = TorqueToAngleAdaptor(use_w=False, use_a=False)
        d, i, sd, s = self.directInertia, self.inverseInertia, self.springDamper, self.spring
        t2a, t2b, t3a, t3b = (self.torqueToAngle2a, self.torqueToAngle2b, self.torqueToAngle3a,
                              self.torqueToAngle3b)
        for a, b in [(self.sine1.y, d.tauDrive), (d.phi, i.phi), (d.w, i.w), (d.a, i.a),
                     (i.tau, d.tau), (self.sine1.y, self.torque2.tau),
                     (self.sine1.y, self.force3.tau), (t2b.flange, self.inertia2b.flange_a),
                     (self.inertia2a.flange_b, t2a.flange),
                     (self.torque2.flange, self.inertia2a.flange_a),
                     (self.inertia3a.flange_b, t3a.flange),
                     (self.force3.flange, self.inertia3a.flange_a),
                     (t3b.flange, self.inertia3b.flange_a), (t2a.phi, sd.phi1), (t2a.w, sd.w1),
                     (t2a.tau, sd.tau1), (sd.tau2, t2b.tau), (sd.phi2, t2b.phi),
                     (sd.w2, t2b.w), (t3a.phi, s.phi1), (t3a.tau, s.tau1), (s.phi2, t3b.phi),
                     (s.tau2, t3b.tau)]:
            self.connect(a, b)
