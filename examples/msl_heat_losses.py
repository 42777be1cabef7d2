"""MSL's two HeatLosses examples: every dissipating element of a drive train sends its
lossPower through its heat port to one convection to the ambient.

    Rotational: torque → inertias joined by dampers, a spring damper, elastic backlash, a
    bearing, a lossy gear, a clutch, a one-way clutch and a brake (1 s)
    Translational: force → masses joined by dampers, an elastic gap, support friction, a
    brake and a mass with a hard stop and Stribeck friction (2 s)

Prints the heat each passed to the ambient, checks that the convection takes the sum of the
elements' losses, and shows the translational stop's reinit(v, 0): springDamper1's relative
velocity (a state MSL prefers) is kept, so mass3 jumps with the stopped mass. Plots the
temperature rise of the convection's solid side (Σ lossPower / 20 W/K).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.models import RotationalHeatLosses, TranslationalHeatLosses
from acausal.models.heat_losses import (INTERVAL, ROTATIONAL_INTERVAL, ROTATIONAL_STOP_TIME,
                                        STOP_TIME)

ROTATIONAL = ("damper", "springDamper", "elastoBacklash", "bearingFriction", "lossyGear",
              "clutch", "oneWayClutch", "brake")
TRANSLATIONAL = ("damper", "springDamper", "elastoGap", "supportFriction", "brake",
                 "massWithStopAndFriction", "springDamper1")


def run(model, stop, interval, start):
    t = np.linspace(0.0, stop, int(round(stop / interval)) + 1)
    return acausal.compile(model).simulate(stop, t=t, x0=start, rtol=1e-10, atol=1e-12)


def main():
    results = {}
    for label, model, stop, interval, elements in [
            ("Rotational", RotationalHeatLosses(), ROTATIONAL_STOP_TIME, ROTATIONAL_INTERVAL,
             ROTATIONAL),
            ("Translational", TranslationalHeatLosses(), STOP_TIME, INTERVAL, TRANSLATIONAL)]:
        res = run(model, stop, interval, type(model).START)
        losses = sum(res[f"{c}.lossPower"] for c in elements)
        T = np.unique(res.t)
        Q = np.interp(T, res.t, res["convection.Q_flow"])
        heat = float(np.sum(0.5 * (Q[1:] + Q[:-1]) * np.diff(T)))       # trapezoid
        off = np.max(np.abs(res["convection.Q_flow"] - losses))
        print(f"{label} HeatLosses: {len(res.events)} events, {heat:.4f} J to the ambient "
              f"(peak {losses.max():.3f} W); convection - sum of lossPower: {off:.1e} W")
        results[label] = res
    res = results["Translational"]
    for ev in res.events:
        if ev.indicator == "massWithStopAndFriction.gap_max" and ev.direction == -1:
            v, v3 = ev.reinit["massWithStopAndFriction.v"], ev.reinit["mass3.v"]
            print(f"  stop hit at t = {ev.time:.5f} s: v {v[0]:.4f} -> {v[1]:g} m/s, "
                  f"mass3.v {v3[0]:.4f} -> {v3[1]:.5f} m/s (springDamper1.v_rel kept)")
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(2, 1, figsize=(7, 6))
    for a, (label, res) in zip(ax, results.items()):
        a.plot(res.t, res["convection.solid.T"] - 298.15)
        a.set_ylabel(f"{label}: solid.T - T_amb [K]")
    ax[-1].set_xlabel("t [s]")
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "msl_heat_losses.png"))


if __name__ == "__main__":
    main()
