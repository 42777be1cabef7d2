"""Components written outside the component library, as a user writes them (a few lines
each), and the models built from them.

Each has the two optional methods every component has: ``structure(s)`` (kinematic relations,
internal points and states) and ``physics(e)`` (energies, flows on ports, state derivatives,
recorded variables).

- ``CubicSpring``: a hardening spring f = c·δ + c3·δ³ (δ = s_rel − s_rel0), reusing the
  translational ``PartialCompliant`` base (which supplies flanges, s_rel, v_rel and f);
- ``Flywheel``: a rotational inertia J [kg.m2] (the library has
  ``acausal.components.rotational.Inertia``; this shows how such a body is written);
- ``SimpleDCMotor``: a permanent-magnet DC motor with its armature current i as a state,
  L·di/dt = v − R·i − k·w, driving its flange with the torque k·i.

``duffing_model``: a mass on the cubic spring (coordinate ``mass.s``); ``motor_model``: the
motor, fed by the model Input ``V``, spinning up a flywheel (states ``rotor.phi``,
``rotor.w``, ``motor.i``).
"""
from __future__ import annotations

from ..components.translational import Fixed, Mass, PartialCompliant
from ..core import Component, Input, Model, Parameter, RealInput, RotationalFlange
from ..core.ports import ROTATIONAL


class CubicSpring(PartialCompliant):
    """Hardening spring: f = c·δ + c3·δ³ with δ = s_rel − s_rel0 [m]; f [N] on flange_b."""
    c = Parameter(1.0, "N/m", "linear stiffness", nonnegative=True)
    c3 = Parameter(0.0, "N/m3", "cubic stiffness (> 0: hardening)")
    s_rel0 = Parameter(0.0, "m", "unstretched spring length")

    def force(self, s_rel, v_rel):
        d = s_rel - self.s_rel0
        return self.c * d + self.c3 * d ** 3


class Flywheel(Component):
    """Rigid rotor of inertia J [kg.m2]; states phi [rad] and w [rad/s]; a [rad/s2]."""
    J = Parameter(1.0, "kg.m2", "moment of inertia", positive=True)
    flange_a = RotationalFlange("left flange of shaft")
    flange_b = RotationalFlange("right flange of shaft")

    def structure(self, s):
        rotor = s.node("phi", ROTATIONAL, velocity="w", acceleration="a")
        s.linear({self.flange_a: 1.0, rotor: -1.0})        # flange_a.phi = phi
        s.linear({self.flange_b: 1.0, rotor: -1.0})        # flange_b.phi = phi

    def physics(self, e):
        e.kinetic_energy(0.5 * self.J * e.vel(e.node("phi")) ** 2)   # the node of structure()


class SimpleDCMotor(Component):
    """DC motor (housing fixed): L·di/dt = v − R·i − k·w, torque k·i on ``flange``.

    v [V] is the RealInput ``v``; w [rad/s] the flange speed. Records i [A], tau [N.m] (the
    torque the motor applies to the shaft) and w [rad/s].
    """
    R = Parameter(1.0, "Ohm", "armature resistance", positive=True)
    L = Parameter(1e-3, "H", "armature inductance", positive=True)
    k = Parameter(0.1, "N.m/A", "torque (and back-EMF, V.s/rad) constant", positive=True)
    v = RealInput("armature voltage [V]")
    flange = RotationalFlange("shaft")

    def structure(self, s):
        s.state("i", start=0.0, unit="A", description="armature current")

    def physics(self, e):
        w, i = e.vel(self.flange), e.state("i")      # the state declared in structure()
        e.derivative(i, (e.input(self.v) - self.R * i - self.k * w) / self.L)
        e.flow(self.flange, -self.k * i)         # flow into the motor: −(torque it applies)
        e.variable("tau", self.k * i, "N.m")
        e.variable("w", w, "rad/s")


def duffing_model(m=1.0, c=4.0, c3=40.0) -> Model:
    """wall | CubicSpring | mass. m: mass [kg]; c: linear stiffness [N/m]; c3: cubic
    stiffness [N/m3]."""
    model = Model("duffing")
    model.wall, model.spring, model.mass = Fixed(), CubicSpring(c=c, c3=c3), Mass(m=m)
    model.connect(model.wall.flange, model.spring.flange_a)
    model.connect(model.spring.flange_b, model.mass.flange_a)
    return model


def motor_model(R=0.5, L=0.02, k=0.08, J=2e-3) -> Model:
    """Input voltage V [V] (start 12 V) -> SimpleDCMotor -> Flywheel. R: armature resistance
    [Ohm]; L: armature inductance [H]; k: motor constant [N.m/A]; J: flywheel inertia
    [kg.m2]."""
    model = Model("drive")
    model.V = Input(start=12.0, unit="V", description="supply voltage")
    model.motor = SimpleDCMotor(R=R, L=L, k=k)
    model.rotor = Flywheel(J=J)
    model.connect(model.V.y, model.motor.v)
    model.connect(model.motor.flange, model.rotor.flange_a)
    return model
