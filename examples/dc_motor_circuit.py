"""A DC motor built as a circuit: a step voltage source, armature resistance and inductance,
an EMF driving the rotor, and a resistor that heats up.

    StepVoltage --(PowerSensor)-- Resistor --- Inductor --- RotationalEMF --- Ground
                                      |heatPort                 |flange
                                 HeatCapacitor --G-- ambient    Inertia --- Damper

The electrical and thermal parts are potential/flow networks compiled next to the
rotor's Lagrange equation: the EMF's torque k·i is a generalized force on the rotor. The
script checks the energy balance (electrical input = resistive heat + magnetic and kinetic
energy + damper losses, all integrated by the model), prints the equations the compiler
kept, and saves ``dc_motor_circuit.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import math
import os

import numpy as np

import acausal
from acausal.components import electrical as el
from acausal.components import rotational as rot
from acausal.components import signals as sig
from acausal.components import thermal as th

R, L, K, J, D = 0.05, 0.0015, 2.0 / math.pi, 0.15, 0.05


class MotorCircuit(acausal.Model):
    def __init__(self, name=None):
        super().__init__(name)
        self.src = el.StepVoltage(V=100.0, startTime=0.05)
        self.power = el.PowerSensor()
        self.r = el.Resistor(R=R, useHeatPort=True)
        self.l = el.Inductor(L=L)
        self.emf = el.RotationalEMF(k=K)
        self.ground = el.Ground()
        self.rotor = rot.Inertia(J=J)
        self.damper = rot.Damper(d=D)
        self.fixed = rot.Fixed()
        self.winding = th.HeatCapacitor(C=500.0, T_start=300.15)
        self.cooling = th.ThermalConductor(G=2.0)
        self.ambient = th.FixedTemperature(T=300.15)
        self.energy_in = sig.Integrator()
        for a, b in [
                (self.src.p, self.power.pc), (self.power.nc, self.r.p),
                (self.power.pv, self.src.p), (self.power.nv, self.ground.p),
                (self.r.n, self.l.p), (self.l.n, self.emf.p), (self.emf.n, self.src.n),
                (self.src.n, self.ground.p), (self.emf.flange, self.rotor.flange_a),
                (self.rotor.flange_b, self.damper.flange_a),
                (self.damper.flange_b, self.fixed.flange),
                (self.r.heatPort, self.winding.port), (self.winding.port, self.cooling.port_a),
                (self.cooling.port_b, self.ambient.port),
                (self.power.power, self.energy_in.u)]:
            self.connect(a, b)


def main():
    compiled = acausal.compile(MotorCircuit("motor"))
    print("states:", compiled.x_names, " algebraic:", compiled.z_names)
    print("rotor:", compiled.lagrange.q_names, " Q_rest =", compiled.lagrange.Q_rest)
    t = np.linspace(0.0, 2.0, 4001)
    res = compiled.simulate(2.0, t=t, rtol=1e-10, atol=1e-12)
    # energy balance: heat into the winding (stored + conducted away) + magnetic + kinetic
    # + damper's heat, the last two integrated here by the trapezoid rule on a fine grid
    heat = 500.0 * (res["winding.T"] - 300.15)
    conducted = np.concatenate([[0.0], np.cumsum(np.diff(t) * 0.5 * (
        res["cooling.Q_flow"][1:] + res["cooling.Q_flow"][:-1]))])
    damper = np.concatenate([[0.0], np.cumsum(np.diff(t) * 0.5 * D * (
        res["rotor.w"][1:] ** 2 + res["rotor.w"][:-1] ** 2))])
    stored = 0.5 * L * res["l.i"] ** 2 + 0.5 * J * res["rotor.w"] ** 2
    balance = res["energy_in.y"] - (heat + conducted + stored + damper)
    print(f"speed {res['rotor.w'][-1]:.2f} rad/s, current {res['l.i'][-1]:.2f} A, winding "
          f"+{res['winding.T'][-1] - 300.15:.3f} K; energy in {res['energy_in.y'][-1]:.1f} J, "
          f"balance off by {np.max(np.abs(balance)):.2e} J (trapezoid rule)")
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(3, 1, sharex=True, figsize=(7, 7))
    ax[0].plot(t, res["rotor.w"]); ax[0].set_ylabel("w [rad/s]")
    ax[1].plot(t, res["l.i"]); ax[1].set_ylabel("i [A]")
    ax[2].plot(t, res["winding.T"] - 273.15); ax[2].set_ylabel("winding [degC]")
    ax[2].set_xlabel("t [s]")
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "dc_motor_circuit.png"))


if __name__ == "__main__":
    main()
