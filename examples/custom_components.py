"""Writing your own components: a few lines each.

Three components are defined here, each with the two optional methods every component has:
``structure(s)`` (kinematic relations, internal points and states) and ``physics(e)``
(energies, flows on ports, state derivatives, recorded variables).

- ``CubicSpring``: a hardening spring f = c·δ + c3·δ³ (δ = s_rel − s_rel0), reusing the
  translational ``PartialCompliant`` base (which supplies flanges, s_rel, v_rel and f);
- ``Flywheel``: a rotational inertia J [kg.m2] (the library has
  ``acausal.components.rotational.Inertia``; this shows how such a body is written);
- ``SimpleDCMotor``: a permanent-magnet DC motor with its armature current i as a state,
  L·di/dt = v − R·i − k·w, driving its flange with the torque k·i.

Run ``python examples/custom_components.py``: it simulates a mass on the cubic spring (the
period shrinks with the amplitude) and the motor spinning up a flywheel, prints a summary and
saves ``custom_components.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.core import Component, Parameter, RealInput, RotationalFlange
from acausal.core.ports import ROTATIONAL
from acausal.components.translational import Fixed, Mass, PartialCompliant


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
        self._rotor = s.node("phi", ROTATIONAL, velocity="w", acceleration="a")
        s.linear({self.flange_a: 1.0, self._rotor: -1.0})        # flange_a.phi = phi
        s.linear({self.flange_b: 1.0, self._rotor: -1.0})        # flange_b.phi = phi

    def physics(self, e):
        e.kinetic_energy(0.5 * self.J * e.vel(self._rotor) ** 2)


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
        self._i = s.state("i", start=0.0, unit="A", description="armature current")

    def physics(self, e):
        w = e.vel(self.flange)
        e.derivative(self._i, (e.input(self.v) - self.R * self._i - self.k * w) / self.L)
        e.flow(self.flange, -self.k * self._i)     # flow into the motor: −(torque it applies)
        e.variable("tau", self.k * self._i, "N.m")
        e.variable("w", w, "rad/s")


def duffing_model(m=1.0, c=4.0, c3=40.0) -> acausal.Model:
    """wall | CubicSpring | mass."""
    model = acausal.Model("duffing")
    model.wall, model.spring, model.mass = Fixed(), CubicSpring(c=c, c3=c3), Mass(m=m)
    model.connect(model.wall.flange, model.spring.flange_a)
    model.connect(model.spring.flange_b, model.mass.flange_a)
    return model


def motor_model(R=0.5, L=0.02, k=0.08, J=2e-3) -> acausal.Model:
    """Input voltage V -> SimpleDCMotor -> Flywheel."""
    model = acausal.Model("drive")
    model.V = acausal.Input(start=12.0, unit="V", description="supply voltage")
    model.motor = SimpleDCMotor(R=R, L=L, k=k)
    model.rotor = Flywheel(J=J)
    model.connect(model.V.y, model.motor.v)
    model.connect(model.motor.flange, model.rotor.flange_a)
    return model


def _period(t, x):
    up = t[1:][(x[:-1] < 0) & (x[1:] >= 0)]
    return float(np.mean(np.diff(up))) if len(up) > 1 else float("nan")


def main():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    duffing = acausal.compile(duffing_model())
    t = np.linspace(0, 10.0, 2001)
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 7))
    print("mass on a hardening spring (m = 1 kg, c = 4 N/m, c3 = 40 N/m3):")
    print(f"  linear period 2*pi/sqrt(c/m) = {2 * np.pi / 2.0:.4f} s")
    for amp in (0.05, 0.2, 0.5):
        res = duffing.simulate(10.0, t=t, x0={"mass.s": amp})
        print(f"  amplitude {amp:4.2f} m: period {_period(t, res['mass.s']):.4f} s")
        res.plot("mass.s", ax=ax1)
        ax1.lines[-1].set_label(f"mass.s, amplitude {amp} m")
    ax1.legend()

    drive = acausal.compile(motor_model())
    res = drive.simulate(1.0, t=np.linspace(0, 1.0, 1001))
    print("DC motor (R = 0.5 Ohm, L = 0.02 H, k = 0.08 N.m/A) spinning up J = 2e-3 kg.m2 at 12 V:")
    print(f"  peak current {res['motor.i'].max():.2f} A, speed after 1 s "
          f"{res['rotor.w'][-1]:.2f} rad/s (no-load speed V/k = {12 / 0.08:.1f} rad/s)")
    res.plot("rotor.w", "motor.i", ax=ax2)

    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "custom_components.png")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
