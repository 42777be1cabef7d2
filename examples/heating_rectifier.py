"""Electrical losses as heat: MSL's HeatingRectifier and Resistor examples.

    SineVoltage1 (1 V, 1 Hz) --|>|-- Capacitor1 (1 F) || R (1 Ohm)      HeatingRectifier
                      HeatingDiode1 --heatPort-- ThermalConductor1 -- HeatCapacitor1

    SineVoltage1 (220 V, 1 Hz) -- resistor (100 Ohm, alpha 1e-3 1/K)    Resistor
                      resistor --heatPort-- thermalConductor (50 W/K) -- 20 degC

The rectifier's Diode is MSL's exponential one with temperature dependency: its losses
v·i heat HeatCapacitor1, whose temperature changes the diode's characteristic. The
resistor example has no states: its current and temperature solve R_actual·i = v,
T = 293.15 K + v·i/G at each instant; it is built here also from MSL 3's HeatingResistor
(R_ref), which MSL 4 converts to Resistor(useHeatPort=true). Saves heating_rectifier.png
(in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components import electrical as el
from acausal.models import HeatingRectifier, ResistorExample


def main():
    t = np.linspace(0.0, 5.0, 2501)
    rect = acausal.compile(HeatingRectifier()).simulate(5.0, t=t, rtol=1e-10, atol=1e-12)
    print(f"rectifier: Capacitor1.v {rect['Capacitor1.v'][-1]:.4f} V, HeatCapacitor1 "
          f"+{(rect['HeatCapacitor1.T'][-1] - 293.15) * 1e3:.2f} mK after 5 s")
    res = acausal.compile(ResistorExample()).simulate(5.0, t=t, rtol=1e-10, atol=1e-12)
    print(f"resistor: peak current {res['resistor.i'].max():.4f} A (cold: 2.2 A), "
          f"hottest {res['resistor.heatPort.T'].max() - 273.15:.2f} degC, "
          f"R_actual up to {res['resistor.R_actual'].max():.3f} Ohm")
    print("MSL 3's HeatingResistor(R_ref=100, alpha=1e-3, T_ref=293.15) parameters:",
          list(el.HeatingResistor(R_ref=100.0, alpha=1e-3, T_ref=293.15).parameters()))

    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, sharex=True, figsize=(7, 7))
    ax[0].plot(t, rect["Capacitor1.v"]); ax[0].set_ylabel("Capacitor1.v [V]")
    ax[1].plot(t, rect["HeatCapacitor1.T"] - 293.15); ax[1].set_ylabel("HeatCapacitor1 +K")
    ax[2].plot(t, res["resistor.LossPower"]); ax[2].set_ylabel("resistor loss [W]")
    ax[2].set_xlabel("t [s]")
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "heating_rectifier.png"))


if __name__ == "__main__":
    main()
