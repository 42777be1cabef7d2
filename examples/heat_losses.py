"""Mechanical losses as heat: ``useHeatPort=True`` on dissipating components.

    flywheel ── brake (heatPort ─ disc: HeatCapacitor) ── ground, braked from 0.5 s
    MSL's Rotational EddyCurrentBrake: inertia ── eddyCurrentTorque (heatPort ─ heatCapacitor)

The brake's heatPort takes its lossPower (heatPort.Q_flow = −lossPower): the disc warms by
exactly the kinetic energy the flywheel loses, also through the brake's stick event. The eddy
current brake's losses heat its capacitor, whose temperature shifts the speed of maximum
torque (alpha20 of copper). Prints both energy balances; plots the temperatures.
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components import rotational as rot
from acausal.components import signals as sig
from acausal.components import thermal as th
from acausal.models import RotationalEddyCurrentBrake
from acausal.models.eddy_current_brakes import START_ROTATIONAL

J, C, W0, T0 = 2.0, 5.0, 30.0, 293.15


def braked_flywheel():
    m = acausal.Model("braked_flywheel")
    m.flywheel, m.brake = rot.Inertia(J=J), rot.Brake(fn_max=100.0, useHeatPort=True)
    m.disc, m.step = th.HeatCapacitor(C=C), sig.Step(startTime=0.5)
    for a, b in [(m.flywheel.flange_b, m.brake.flange_a), (m.brake.heatPort, m.disc.port),
                 (m.step.y, m.brake.f_normalized)]:
        m.connect(a, b)
    return m


def main():
    t = np.linspace(0.0, 3.0, 301)
    res = acausal.compile(braked_flywheel()).simulate(3.0, t=t, x0={"flywheel.w": W0},
                                                      rtol=1e-10, atol=1e-12)
    stuck = [ev.time for ev in res.events if ev.modes.get("brake.mode", (0, 1))[1] == 0]
    heat = C * (res["disc.T"] - T0)
    lost = 0.5 * J * (W0 ** 2 - res["flywheel.w"] ** 2)
    print(f"brake sticks at t = {stuck[0]:.6f} s; disc +{res['disc.T'][-1] - T0:.3f} K, "
          f"heat - kinetic energy lost: {np.max(np.abs(heat - lost)):.1e} J")
    eddy = acausal.compile(RotationalEddyCurrentBrake()).simulate(
        1.0, t=np.linspace(0.0, 1.0, 1001), x0=START_ROTATIONAL, rtol=1e-10, atol=1e-12)
    balance = eddy["heatCapacitor.T"] - T0 - 0.5 * (400.0 - eddy["inertia.w"] ** 2)
    print(f"eddy current brake: {eddy['inertia.w'][-1]:.4f} rad/s left, heat capacitor "
          f"{eddy['heatCapacitor.T'][-1]:.3f} K, balance off by {np.max(np.abs(balance)):.1e} J")
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(2, 1, figsize=(7, 6))
    ax[0].plot(res.t, res["disc.T"] - 273.15); ax[0].set_ylabel("brake disc [degC]")
    ax[1].plot(eddy.t, eddy["heatCapacitor.T"] - 273.15)
    ax[1].set_ylabel("eddy current brake [degC]"); ax[1].set_xlabel("t [s]")
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "heat_losses.png"))


if __name__ == "__main__":
    main()
