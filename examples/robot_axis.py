"""One axis of MSL's r3 robot (RobotR3.OneAxis): path planning, P-PI cascade controller, a
current-controlled motor (a circuit of ideal op-amps), an elastic gear with bearing friction.

    pathPlanning (KinematicPTP2: 0 -> 120 deg, 3 rad/s, 10 rad/s2)
        -> axis: controller -> motor (op-amp current loop, EMF, Jmotor) -> gear -> load

The motor starts in steady state (initial equations der(C.v) = 0, der(La.i) = 0) and the
run ends 0.5 s after the reference motion (TerminateSimulation). Prints the tracking error,
the bearing friction's mode changes and why the run ended; plots angle, current, spring.
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.models.robot_axis import STOP_TIME, OneAxis


def main():
    res = acausal.compile(OneAxis()).simulate(STOP_TIME, t=np.linspace(0.0, STOP_TIME, 801))
    print(res.terminated)
    error = res["axis.angle_ref"] - res["axis.initializeFlange.phi_flange"]
    print(f"largest tracking error {np.degrees(np.abs(error).max()):.3f} deg, at the end "
          f"{np.degrees(error[-1]):.2e} deg; peak motor current "
          f"{np.abs(res['axis.motor.La.i']).max():.2f} A")
    for ev in res.events:
        if "axis.gear.bearingFriction.mode" in ev.modes:
            before, after = ev.modes["axis.gear.bearingFriction.mode"]
            print(f"  t = {ev.time:.6f} s: bearing friction mode {before:g} -> {after:g}")
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(3, 1, figsize=(7, 7), sharex=True)
    ax[0].plot(res.t, np.degrees(res["axis.angle_ref"]), "--", label="reference")
    ax[0].plot(res.t, np.degrees(res["axis.initializeFlange.phi_flange"]), label="load")
    ax[0].set_ylabel("angle [deg]"); ax[0].legend()
    ax[1].plot(res.t, res["axis.motor.La.i"]); ax[1].set_ylabel("motor current [A]")
    ax[2].plot(res.t, res["axis.gear.spring.phi_rel"])
    ax[2].set_ylabel("gear spring phi_rel [rad]"); ax[2].set_xlabel("t [s]")
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "robot_axis.png"))


if __name__ == "__main__":
    main()
