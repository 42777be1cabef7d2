"""The DC motor composed of Modelica parts next to the compact one, and where its energy
goes.

    v --> DCMotorCircuit: SignalVoltage -- Resistor -- Inductor -- RotationalEMF --> load
                                              |heatPort                   (Inertia, Damper)
                                         HeatCapacitor (winding)   Damper heatPort -> brake

``acausal.models.DCMotorCircuit`` has the ports and defaults of the compact
``rotational.DCMotor`` (MSL's DC_PermanentMagnet data); the script drives both with the
same voltage and prints their largest difference, then heats the composed motor's
winding (alpha of copper) and the damper's heat capacitor and checks that the electrical
input (integrated here from the current, Simpson's rule) equals kinetic + magnetic energy
+ heat. Saves dc_motor_composed.png (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np
from scipy.integrate import simpson

import acausal
from acausal.components import rotational as rot
from acausal.components import thermal as th
from acausal.models import DCMotorCircuit

J_L, D, T0 = 0.5, 0.05, 300.15


def drive(motor, heat=False):
    m = acausal.Model("drive")
    m.v, m.motor = acausal.Input(unit="V"), motor
    m.load, m.damper, m.fixed = rot.Inertia(J=J_L), rot.Damper(d=D, useHeatPort=heat), \
        rot.Fixed()
    for a, b in [(m.v.y, m.motor.v), (m.motor.flange, m.load.flange_a),
                 (m.load.flange_b, m.damper.flange_a), (m.damper.flange_b, m.fixed.flange)]:
        m.connect(a, b)
    if heat:
        m.winding, m.brake = th.HeatCapacitor(C=40.0, T_start=T0), th.HeatCapacitor(
            C=25.0, T_start=T0)
        m.connect(m.motor.heatPort, m.winding.port)
        m.connect(m.damper.heatPort, m.brake.port)
    return m


def main():
    t = np.linspace(0.0, 2.0, 4001)
    tight = {"rtol": 1e-11, "atol": 1e-12}
    composed = acausal.compile(drive(DCMotorCircuit())).simulate(2.0, t=t, inputs={"v": 100.0},
                                                                 **tight)
    compact = acausal.compile(drive(rot.DCMotor())).simulate(2.0, t=t, inputs={"v": 100.0},
                                                             **tight)
    print(f"100 V step: speed {compact['motor.w'][-1]:.3f} rad/s; composed - compact: "
          f"speed {np.max(np.abs(composed['motor.inertia.w'] - compact['motor.w'])):.1e} "
          f"rad/s, current "
          f"{np.max(np.abs(composed['motor.inductor.i'] - compact['motor.i'])):.1e} A")

    motor = DCMotorCircuit(alpha=3.93e-3, useHeatPort=True)
    J, L = motor.inertia.J, motor.inductor.L

    def v(tt):
        return 60.0 + 40.0 * np.sin(4 * np.pi * tt)
    res = acausal.compile(drive(motor, heat=True)).simulate(2.0, t=t, inputs={"v": v}, **tight)
    e_in = simpson(v(t) * res["motor.inductor.i"], x=t)
    kinetic = 0.5 * (J + J_L) * res["load.w"][-1] ** 2
    magnetic = 0.5 * L * res["motor.inductor.i"][-1] ** 2
    winding = 40.0 * (res["winding.T"][-1] - T0)
    brake = 25.0 * (res["brake.T"][-1] - T0)
    print(f"energy in {e_in:.3f} J = kinetic {kinetic:.3f} + magnetic {magnetic:.3f} + "
          f"winding heat {winding:.3f} + damper heat {brake:.3f} J "
          f"(off by {abs(e_in - kinetic - magnetic - winding - brake) / e_in:.1e})")

    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
    ax[0].plot(t, compact["motor.w"], label="compact")
    ax[0].plot(t, composed["motor.inertia.w"], "--", label="composed")
    ax[0].set_ylabel("w [rad/s]"); ax[0].legend()
    ax[1].plot(t, res["winding.T"] - T0, label="winding")
    ax[1].plot(t, res["brake.T"] - T0, label="damper")
    ax[1].set_ylabel("temperature rise [K]"); ax[1].set_xlabel("t [s]"); ax[1].legend()
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "dc_motor_composed.png"))


if __name__ == "__main__":
    main()
