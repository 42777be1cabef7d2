"""Algebraic loops of blocks, solved as a Modelica tool solves them: the compiler tears the
loop (one of its signals becomes an algebraic variable, named as its output) and the
integrator solves it with the states.

A speed controller whose output is fed back through a static gain, with no state in the
loop:

    r ─(+)─ err ─(+)─ fb ─ k ─┬─ force → mass ─ speed sensor ─┐
        ↑-                ↑-  │                                │
        └─────────────────┼───┼────────── v ───────────────────┘
                          └─ g ┘

y = k·(r − v − g·y), so y = k·(r − v)/(1 + k·g): the mass reaches r with the time constant
τ = m·(1 + k·g)/k. Prints the torn signal, the largest difference from that closed form,
and plots the speed and the force.
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components import signals as sg
from acausal.components.translational import Force, Mass, SpeedSensor

M, K, G, R = 2.0, 5.0, 0.5, 1.5          # kg, N.s/m, m/(N.s), m/s


def speed_loop() -> acausal.Model:
    m = acausal.Model("speed_loop")
    m.ref, m.err, m.fb = sg.Constant(k=R), sg.Feedback(), sg.Feedback()
    m.k, m.g = sg.Gain(k=K), sg.Gain(k=G)
    m.mass, m.force, m.speed = Mass(m=M), Force(), SpeedSensor()
    for a, b in [(m.ref.y, m.err.u1), (m.speed.v, m.err.u2), (m.err.y, m.fb.u1),
                 (m.fb.y, m.k.u), (m.k.y, m.g.u), (m.g.y, m.fb.u2), (m.k.y, m.force.f),
                 (m.force.flange, m.mass.flange_a), (m.speed.flange, m.mass.flange_b)]:
        m.connect(a, b)
    return m


def main():
    compiled = acausal.compile(speed_loop())
    print(f"torn signal(s), solved as algebraic variables: {compiled.z_names}")
    t = np.linspace(0.0, 5.0, 501)
    res = compiled.simulate(5.0, t=t)
    tau = M * (1 + K * G) / K
    v = R * (1 - np.exp(-t / tau))
    print(f"max |v − closed form| {np.max(np.abs(res['mass.v'] - v)):.1e} m/s, "
          f"max |force − k·(r − v)/(1 + k·g)| "
          f"{np.max(np.abs(res['force.f'] - K * (R - v) / (1 + K * G))):.1e} N")
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(2, 1, figsize=(7, 5), sharex=True)
    ax[0].plot(t, res["mass.v"], label="simulated")
    ax[0].plot(t[::25], v[::25], "o", label="closed form")
    ax[0].set_ylabel("v [m/s]"); ax[0].legend(fontsize="small")
    ax[1].plot(t, res["force.f"]); ax[1].set_ylabel("force [N]"); ax[1].set_xlabel("t [s]")
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "algebraic_loop.png"))


if __name__ == "__main__":
    main()
