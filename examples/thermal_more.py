"""A geared drive whose losses warm its housing: MSL's Gearbox, SignTorque,
InverseSpeedDependentTorque, ThermalCollector, ConvectiveResistor and the Celsius package.

    drive: InverseSpeedDependentTorque ── j1 ── gearbox (heatPort) ── j2 ── load: SignTorque
    gearbox.heatPort ─ collector.port_a[1]      electronics (FixedHeatFlow) ─ port_a[2]
    collector.port_b ── housing (HeatCapacitor) ── ConvectiveResistor (Rc: a fan from 60 s)
                                                   └── air: Celsius.FixedTemperature 20 degC

The drive delivers constant power tau_nominal·w_nominal above w0 (a motor at its power limit),
the load is a Coulomb-like torque (SignTorque, Exp regularization); the lossy gear (mesh
efficiency 0.9 both ways) and the gear's damping turn power into heat that the collector sums
with the electronics' 5 W into the housing, cooled through a convective resistance that drops
when the fan starts. Prints the steady speed against its closed form (drive power = load
power / efficiency) and the energy balance (work in = kinetic energy + load work + heat, the
powers integrated by the trapezoidal rule on the output grid);
plots speeds and the housing's temperature in degC.
"""
from __future__ import annotations

import os

import numpy as np
from scipy.integrate import cumulative_trapezoid

import acausal
from acausal.components import celsius
from acausal.components import rotational as rot
from acausal.components import signals as sig
from acausal.components import thermal as th

TAU_N, W_N, RATIO, ETA, LOAD, C_HOUSING = 2.0, 10.0, 4.0, 0.9, 6.0, 500.0


def drive() -> acausal.Model:
    m = acausal.Model("geared_drive")
    m.drive = rot.InverseSpeedDependentTorque(tau_nominal=TAU_N, w_nominal=W_N, w0=1.0)
    m.j1, m.j2 = rot.Inertia(J=0.01), rot.Inertia(J=0.5)
    m.gearbox = rot.Gearbox(ratio=RATIO, lossTable=[[0.0, ETA, ETA, 0.0, 0.0]], c=1e4, d=5.0,
                            useHeatPort=True)
    m.load = rot.SignTorque(tau_nominal=-LOAD, w0=0.1)
    m.collector = th.ThermalCollector(m=2)
    m.electronics = th.FixedHeatFlow(Q_flow=5.0)
    m.housing = th.HeatCapacitor(C=C_HOUSING, T_start=293.15)
    m.cooling, m.air = th.ConvectiveResistor(), celsius.FixedTemperature(T=20.0)
    m.fan = sig.Step(height=-0.3, offset=0.5, startTime=60.0)        # Rc [K/W]
    m.thermometer = celsius.TemperatureSensor()
    for a, b in [(m.drive.flange, m.j1.flange_a), (m.j1.flange_b, m.gearbox.flange_a),
                 (m.gearbox.flange_b, m.j2.flange_a), (m.j2.flange_b, m.load.flange),
                 (m.gearbox.heatPort, m.collector.port_a[1]),
                 (m.electronics.port, m.collector.port_a[2]),
                 (m.collector.port_b, m.housing.port), (m.housing.port, m.cooling.solid),
                 (m.cooling.fluid, m.air.port), (m.fan.y, m.cooling.Rc),
                 (m.thermometer.port, m.housing.port)]:
        m.connect(a, b)
    return m


def main():
    t = np.linspace(0.0, 120.0, 24001)
    res = acausal.compile(drive()).simulate(120.0, t=t, rtol=1e-9, atol=1e-10)
    # steady state: TAU_N·W_N = LOAD·w2/ETA (the drive at its power limit, w1 > w0)
    w2 = ETA * TAU_N * W_N / LOAD
    print(f"output speed {res['j2.w'][-1]:.6f} rad/s (closed form {w2:.6f}), input "
          f"{res['j1.w'][-1]:.6f} rad/s")
    work = cumulative_trapezoid(res["drive.tau"] * res["j1.w"], res.t, initial=0.0)
    load = cumulative_trapezoid(-res["load.tau"] * res["j2.w"], res.t, initial=0.0)
    gear_heat = cumulative_trapezoid(res["collector.port_a[1].Q_flow"], res.t, initial=0.0)
    kinetic = 0.5 * 0.01 * res["j1.w"] ** 2 + 0.5 * 0.5 * res["j2.w"] ** 2 + 0.5 * 1e4 * \
        res["gearbox.elastoBacklash.phi_rel"] ** 2
    print(f"energy balance: work {work[-1]:.2f} J = kinetic {kinetic[-1]:.2f} J + load "
          f"{load[-1]:.2f} J + gear heat {gear_heat[-1]:.2f} J (off by "
          f"{abs(work[-1] - kinetic[-1] - load[-1] - gear_heat[-1]):.1e} J)")
    print(f"housing {res['thermometer.T'][-1]:.3f} degC after 120 s (fan from 60 s)")
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    ax[0].plot(res.t, res["j1.w"], label="input (j1)")
    ax[0].plot(res.t, res["j2.w"], label="output (j2)")
    ax[0].set_ylabel("speed [rad/s]"); ax[0].legend()
    ax[1].plot(res.t, res["thermometer.T"]); ax[1].set_ylabel("housing [degC]")
    ax[1].set_xlabel("t [s]")
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "thermal_more.png"))


if __name__ == "__main__":
    main()
