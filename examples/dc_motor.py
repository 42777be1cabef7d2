"""A permanent-magnet DC motor started by a voltage step, against its closed-form response.

    v (model input) --> DCMotor --flange--> Inertia (load) --> Damper to the ground

The motor is ``acausal.components.rotational.DCMotor`` with MSL's DC_PermanentMagnet data
(R = 0.05 Ω, L = 1.5 mH, k = 2/π N.m/A, rotor J = 0.15 kg.m²). Its equations

    L·di/dt = v − R·i − k·w,     (J + J_load)·dw/dt = k·i − d·w

are linear: the speed's step response is second order with poles p1, p2, the roots of
L·Jt·s² + (R·Jt + L·d)·s + (R·d + k²), Jt = J + J_load, and

    w(t) = w_ss·[1 + (p2·e^{p1 t} − p1·e^{p2 t})/(p1 − p2)],   w_ss = k·V/(R·d + k²).

The script simulates two supply voltages (the voltage is a model input: no recompiling),
prints the steady state and the largest deviation from the closed form, and saves
``dc_motor.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import math
import os
import time

import numpy as np

import acausal
from acausal.components.rotational import DCMotor, Damper, Fixed, Inertia

J_LOAD = 0.35      # kg.m², load inertia on the motor shaft
D_LOAD = 0.05      # N.m.s/rad, viscous load (bearing and windage)


class MotorOnLoad(acausal.Model):
    """DC motor, supply voltage ``v`` as a model input, driving a damped inertia."""

    def __init__(self, name=None):
        super().__init__(name)
        self.v = acausal.Input(unit="V", description="armature voltage")
        self.motor = DCMotor()
        self.load = Inertia(J=J_LOAD)
        self.friction = Damper(d=D_LOAD)
        self.ground = Fixed()
        for a, b in [(self.v.y, self.motor.v), (self.motor.flange, self.load.flange_a),
                     (self.load.flange_b, self.friction.flange_b),
                     (self.friction.flange_a, self.ground.flange)]:
            self.connect(a, b)


def closed_form(t, V, R, L, k, Jt, d):
    """Speed and current of the linear motor model for a voltage step V at t = 0."""
    p1, p2 = np.roots([L * Jt, R * Jt + L * d, R * d + k * k]).astype(complex)
    w_ss = k * V / (R * d + k * k)
    w = w_ss * (1 + (p2 * np.exp(p1 * t) - p1 * np.exp(p2 * t)) / (p1 - p2))
    dw = w_ss * p1 * p2 * (np.exp(p1 * t) - np.exp(p2 * t)) / (p1 - p2)
    i = (Jt * dw + d * w) / k
    return w.real, i.real, (p1, p2)


def main():
    t0 = time.perf_counter()
    model = acausal.compile(MotorOnLoad("dc"))
    t1 = time.perf_counter()
    grid = np.linspace(0.0, 0.5, 1001)
    runs = {V: model.simulate(0.5, t=grid, inputs={"v": V}) for V in (50.0, 100.0)}
    t2 = time.perf_counter()
    print(model)
    print(f"states: {model.x_names}")
    print(f"compiled in {t1 - t0:.3f} s, two simulations in {t2 - t1:.3f} s")

    p = model.param_defaults
    R, L, k, J = (p[f"motor.{n}"] for n in ("R", "L", "k", "J"))
    Jt = J + J_LOAD
    print(f"motor: R = {R} Ohm, L = {L * 1e3} mH, k = {k:.4f} N.m/A, J = {J} kg.m2")
    ref = {}
    for V, res in runs.items():
        w_ref, i_ref, (p1, p2) = closed_form(grid, V, R, L, k, Jt, D_LOAD)
        ref[V] = (w_ref, i_ref)
        w_ss = k * V / (R * D_LOAD + k * k)
        print(f"V = {V:5.1f} V: speed at 0.5 s {res.final('motor.w'):8.3f} rad/s "
              f"({res.final('motor.w') * 30 / math.pi:7.1f} rpm), steady state "
              f"{w_ss:8.3f} rad/s; peak current {np.max(res['motor.i']):7.1f} A")
        print(f"    closed form vs simulation: max |dw| = "
              f"{np.max(np.abs(res['motor.w'] - w_ref)):.2e} rad/s, max |di| = "
              f"{np.max(np.abs(res['motor.i'] - i_ref)):.2e} A")
    wn = math.sqrt(abs(p1 * p2))
    print(f"poles {p1:.2f}, {p2:.2f} 1/s: natural frequency {wn:.2f} rad/s, damping ratio "
          f"{-(p1 + p2).real / (2 * wn):.3f}")
    print(f"direct-on-line start at 100 V: the current peaks at "
          f"{np.max(runs[100.0]['motor.i']) / 100.0:.1f} x the nominal 100 A")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    for V, res in runs.items():
        ax1.plot(grid, res["motor.w"], label=f"simulated, V = {V:g} V")
        ax1.plot(grid, ref[V][0], "k--", lw=0.8)
        ax2.plot(grid, res["motor.i"], label=f"V = {V:g} V")
    ax1.plot([], [], "k--", lw=0.8, label="closed form")
    ax1.set_ylabel("speed w [rad/s]")
    ax1.legend()
    ax1.grid(True)
    ax2.set_ylabel("armature current i [A]")
    ax2.set_xlabel("time [s]")
    ax2.legend()
    ax2.grid(True)
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "dc_motor.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
