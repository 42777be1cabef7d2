"""MSL's Translational.Examples.GenerationOfFMUs and the blocks of its Utilities: the
translational twin of ``rotational_fmus`` (see there): masses and force laws behind a pure
signal interface, to be exported as FMUs and connected again, signal to signal.

    sine1 ─ directMass ═(s, v, a → ← f)═ inverseMass                (one mass 1.1 + 2.2)
    sine1 ─ force2 ─ mass2a ─ forceToPosition2a ═ springDamper ═ forceToPosition2b ─ mass2b
    sine1 ─ force3 ─ mass3a ─ forceToPosition3a ═ spring ═ forceToPosition3b ─ mass3b

The experiment: StopTime 1 s, Interval 0.001 s, every mass (L = 0) at rest at 0
(``START``).
"""
from __future__ import annotations

from ..components import interfaces
from ..components.signals import Sine
from ..components.translational import (Force, GeneralForceToPositionAdaptor,
                                        GeneralPositionToForceAdaptor, Mass, PartialCompliant,
                                        Spring as SpringComponent,
                                        SpringDamper as SpringDamperComponent)
from ..core import Model, Parameter, RealInput, RealOutput

STOP_TIME, INTERVAL = 1.0, 0.001            # s, the MSL experiment


class SpringDamperNoRelativeStates(PartialCompliant,
                                   interfaces.PartialElementaryConditionalHeatPortWithoutT):
    """Linear 1-D translational spring and damper in parallel whose relative position and
    velocity are not states (MSL Examples.Utilities.SpringDamperNoRelativeStates): the law
    of SpringDamper, f = c·(s_rel − s_rel0) + d·v_rel, lossPower = d·v_rel²; none of the
    relative states' options. Defaults c = 1e5 N/m, d = 0 N.s/m (MSL's start values)."""
    batch_physics = True       # physics: port motion and parameters only
    c = Parameter(1.0e5, "N/m", "spring constant", nonnegative=True)
    d = Parameter(0.0, "N.s/m", "damping constant", nonnegative=True)
    s_rel0 = Parameter(0.0, "m", "unstretched spring length")
    force = SpringDamperComponent.force
    loss_power = SpringDamperComponent.loss_power


class DirectMass(Model):
    """Input/output block of a direct mass model (MSL Examples.Utilities.DirectMass): the
    force fDrive [N] accelerates a mass m [kg] (default 1, L = 0; start at rest at 0) on one
    side, the force f [N] drives it on the other (a GeneralForceToPositionAdaptor); outputs
    its position s [m], speed v [m/s] and acceleration a [m/s²]. Its states are
    ``mass.s``, ``mass.v``; the output a depends on the inputs directly."""
    fDrive = RealInput("accelerating force acting at flange (= -flange.f) [N]")
    s = RealOutput("mass moves with position s due to force f [m]")
    v = RealOutput("mass moves with speed v due to force f [m/s]")
    a = RealOutput("mass moves with acceleration a due to force f [m/s2]")
    f = RealInput("force to drive the mass [N]")

    def __init__(self, name: str | None = None, *, m: float = 1.0):
        super().__init__(name)
        self.mass = Mass(m=m, L=0.0)
        self.forceSource = Force()
        self.forceToPosition = GeneralForceToPositionAdaptor()
        for a, b in [(self.forceToPosition.f, self.f), (self.forceToPosition.p, self.s),
                     (self.forceToPosition.pder, self.v), (self.forceToPosition.pder2, self.a),
                     (self.fDrive, self.forceSource.f),
                     (self.forceSource.flange, self.mass.flange_a),
                     (self.mass.flange_b, self.forceToPosition.flange)]:
            self.connect(a, b)


class InverseMass(Model):
    """Input/output block of an inverse mass model (MSL Examples.Utilities.InverseMass): a
    mass m [kg] (default 1, L = 0) moved by the position s [m], speed v [m/s] and
    acceleration a [m/s²] (a GeneralPositionToForceAdaptor; the three consistent is the
    user's to keep, as in MSL); output the force f = m·a [N] needed to move it so. No
    states: f depends on the input a directly."""
    s = RealInput("position to drive the mass [m]")
    v = RealInput("speed to drive the mass [m/s]")
    a = RealInput("acceleration to drive the mass [m/s2]")
    f = RealOutput("force needed to drive the flange according to s, v, a [N]")

    def __init__(self, name: str | None = None, *, m: float = 1.0):
        super().__init__(name)
        self.mass = Mass(m=m, L=0.0)
        self.positionToForce = GeneralPositionToForceAdaptor()
        for a, b in [(self.positionToForce.f, self.f),
                     (self.positionToForce.flange, self.mass.flange_a),
                     (self.positionToForce.p, self.s), (self.positionToForce.pder, self.v),
                     (self.positionToForce.pder2, self.a)]:
            self.connect(a, b)


class Spring(Model):
    """Input/output block of a spring model (MSL Examples.Utilities.Spring): a linear spring
    (c [N/m], default 1e4; s_rel0 [m], default 0) between two flanges moved by the
    positions s1, s2 [m] (GeneralPositionToForceAdaptors without speed and acceleration);
    outputs the forces f1, f2 [N] needed to move them so: f1 = −f2 = −c·(s2 − s1 −
    s_rel0). No states."""
    s1 = RealInput("position of left flange of force element [m]")
    f1 = RealOutput("force generated by the force element [N]")
    s2 = RealInput("position of right flange of force element [m]")
    f2 = RealOutput("force generated by the force element [N]")

    def __init__(self, name: str | None = None, *, c: float = 1.0e4, s_rel0: float = 0.0):
        super().__init__(name)
        self.positionToForce1 = GeneralPositionToForceAdaptor(use_pder=False, use_pder2=False)
        self.spring = SpringComponent(c=c, s_rel0=s_rel0)
        self.positionToForce2 = GeneralPositionToForceAdaptor(use_pder=False, use_pder2=False)
        for a, b in [(self.f1, self.positionToForce1.f), (self.positionToForce2.f, self.f2),
                     (self.positionToForce1.flange, self.spring.flange_a),
                     (self.spring.flange_b, self.positionToForce2.flange),
                     (self.positionToForce1.p, self.s1), (self.positionToForce2.p, self.s2)]:
            self.connect(a, b)


class SpringDamper(Model):
    """Input/output block of a spring/damper model (MSL Examples.Utilities.SpringDamper): a
    linear spring and damper in parallel (SpringDamperNoRelativeStates: c [N/m], default
    1e4; d [N.s/m], default 1; s_rel0 [m], default 0) between two flanges moved by the
    positions s1, s2 [m] and speeds v1, v2 [m/s] (GeneralPositionToForceAdaptors without
    acceleration); outputs the forces f1, f2 [N] needed to move them so: f1 = −f2 =
    −(c·(s2 − s1 − s_rel0) + d·(v2 − v1)). No states."""
    s1 = RealInput("position of left flange of force element [m]")
    v1 = RealInput("speed to left flange of force element [m/s]")
    f1 = RealOutput("force generated by the force element [N]")
    s2 = RealInput("position of right flange of force element [m]")
    v2 = RealInput("speed to right flange of force element [m/s]")
    f2 = RealOutput("force generated by the force element [N]")

    def __init__(self, name: str | None = None, *, c: float = 1.0e4, d: float = 1.0,
                 s_rel0: float = 0.0):
        super().__init__(name)
        self.positionToForce1 = GeneralPositionToForceAdaptor(use_pder2=False)
        self.springDamper = SpringDamperNoRelativeStates(c=c, d=d, s_rel0=s_rel0)
        self.positionToForce2 = GeneralPositionToForceAdaptor(use_pder2=False)
        for a, b in [(self.f1, self.positionToForce1.f), (self.positionToForce2.f, self.f2),
                     (self.positionToForce1.flange, self.springDamper.flange_a),
                     (self.springDamper.flange_b, self.positionToForce2.flange),
                     (self.positionToForce1.p, self.s1), (self.positionToForce1.pder, self.v1),
                     (self.positionToForce2.p, self.s2), (self.positionToForce2.pder, self.v2)]:
            self.connect(a, b)


class GenerationOfFMUs(Model):
    """MSL's Translational.Examples.GenerationOfFMUs: a sine force (10 N, 2 Hz) drives (1) a
    DirectMass (m = 1.1 kg) connected by signals to an InverseMass (m = 2.2 kg), (2) mass2a
    (1.1 kg) connected to mass2b (2.2 kg) through a SpringDamper block (c = 1e4 N/m,
    d = 100 N.s/m) and GeneralForceToPositionAdaptors without acceleration, (3) mass3a to
    mass3b likewise through a Spring block (c = 1e4 N/m) and adaptors with the position
    only. All masses L = 0, at rest at 0 (``START``)."""
    START = {f"{name}.{v}": 0.0 for name in ("directMass.mass", "mass2a", "mass2b", "mass3a",
                                             "mass3b") for v in ("s", "v")}

    def __init__(self, name: str = "GenerationOfFMUs"):
        super().__init__(name)
        self.sine1 = Sine(f=2.0, amplitude=10.0)
        self.directMass = DirectMass(m=1.1)
        self.inverseMass = InverseMass(m=2.2)
        self.springDamper = SpringDamper(c=1e4, d=100.0)
        self.mass2a = Mass(m=1.1, L=0.0)
        self.force2 = Force()
        self.forceToPosition2a = GeneralForceToPositionAdaptor(use_pder2=False)
        self.mass2b = Mass(m=2.2, L=0.0)
        self.forceToPosition2b = GeneralForceToPositionAdaptor(use_pder2=False)
        self.spring = Spring(c=1e4)
        self.mass3a = Mass(m=1.1, L=0.0)
        self.force3 = Force()
        self.forceToPosition3a = GeneralForceToPositionAdaptor(use_pder=False, use_pder2=False)
        self.mass3b = Mass(m=2.2, L=0.0)
        self.forceToPosition3b = GeneralForceToPositionAdaptor(use_pder=False, use_pder2=False)
        d, i, sd, s = self.directMass, self.inverseMass, self.springDamper, self.spring
        f2a, f2b, f3a, f3b = (self.forceToPosition2a, self.forceToPosition2b,
                              self.forceToPosition3a, self.forceToPosition3b)
        for a, b in [(self.sine1.y, d.fDrive), (d.s, i.s), (d.v, i.v), (d.a, i.a),
                     (i.f, d.f), (self.force2.flange, self.mass2a.flange_a),
                     (self.mass2a.flange_b, f2a.flange), (f2b.flange, self.mass2b.flange_a),
                     (self.force3.flange, self.mass3a.flange_a),
                     (self.mass3a.flange_b, f3a.flange), (f3b.flange, self.mass3b.flange_a),
                     (f2a.f, sd.f1), (sd.f2, f2b.f), (f3a.f, s.f1), (s.f2, f3b.f),
                     (f3a.p, s.s1), (s.s2, f3b.p), (f2a.p, sd.s1), (sd.s2, f2b.p),
                     (f2a.pder, sd.v1), (sd.v2, f2b.pder), (self.sine1.y, self.force2.f),
                     (self.sine1.y, self.force3.f)]:
            self.connect(a, b)
