"""A mug of coffee cooling in a room given in degree Fahrenheit: MSL's Thermal.HeatTransfer
Fahrenheit, Rankine and Celsius packages (heat ports in K, signals and parameters in the
package's unit).

    coffee (HeatCapacitor, 185 degF) ── ThermalConductor ── room (FixedTemperature, 70 degF)
      └── thermometers: Fahrenheit / Celsius / Rankine.TemperatureSensor

The coffee cools exponentially, T = T_room + (T0 − T_room)·exp(−G·t/C). Prints the three
readings at the end against that closed form and the time the coffee is at 140 degF,
simulated (the first grid time it is below) and exact, t = C/G·ln((T0 − T_room)/(T − T_room));
plots the readings.
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components import celsius, fahrenheit, rankine
from acausal.components import thermal as th

C, G = 1200.0, 0.5                 # J/K (about 0.3 kg of water), W/K
T0_F, ROOM_F, DRINKABLE_F = 185.0, 70.0, 140.0


def kelvin(degF: float) -> float:
    return (degF - 32.0) * 5.0 / 9.0 + 273.15


def mug() -> acausal.Model:
    m = acausal.Model("coffee")
    m.coffee = th.HeatCapacitor(C=C, T_start=kelvin(T0_F))
    m.wall = th.ThermalConductor(G=G)
    m.room = fahrenheit.FixedTemperature(T=ROOM_F)
    m.degF, m.degC, m.degRk = (fahrenheit.TemperatureSensor(), celsius.TemperatureSensor(),
                               rankine.TemperatureSensor())
    for a, b in [(m.coffee.port, m.wall.port_a), (m.wall.port_b, m.room.port),
                 (m.degF.port, m.coffee.port), (m.degC.port, m.coffee.port),
                 (m.degRk.port, m.coffee.port)]:
        m.connect(a, b)
    return m


def main():
    t = np.linspace(0.0, 3600.0, 3601)
    res = acausal.compile(mug()).simulate(3600.0, t=t, rtol=1e-10, atol=1e-10)
    T = kelvin(ROOM_F) + (kelvin(T0_F) - kelvin(ROOM_F)) * np.exp(-G * t / C)
    for name, unit, exact in (("degF", "degF", T * 9 / 5 - 459.67),
                              ("degC", "degC", T - 273.15), ("degRk", "degRk", T * 9 / 5)):
        print(f"after 1 h: {res[name + '.T'][-1]:8.3f} {unit:5s} (closed form {exact[-1]:.3f}, "
              f"max |difference| {np.max(np.abs(res[name + '.T'] - exact)):.1e})")
    when = t[np.argmax(res["degF.T"] <= DRINKABLE_F)]
    exact = C / G * np.log((T0_F - ROOM_F) / (DRINKABLE_F - ROOM_F))
    print(f"at {DRINKABLE_F:.0f} degF after {when:.0f} s (closed form {exact:.1f} s)")
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(7, 4))
    for name in ("degF", "degC", "degRk"):
        ax.plot(t / 60, res[name + ".T"], label=name)
    ax.axhline(DRINKABLE_F, color="gray", lw=0.8)
    ax.set_xlabel("t [min]"); ax.set_ylabel("coffee temperature"); ax.legend()
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "temperature_scales.png"))


if __name__ == "__main__":
    main()
