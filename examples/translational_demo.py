"""MSL's Modelica.Mechanics.Translational.Examples.Damper, line by line.

Three sliding masses (m = 1 kg, L = 1 m) start at s = 3 m with v = 10 m/s towards a wall at
s0 = 4.5 m:

    1) mass1 | damper1 (d = 25 N.s/m)                              | fixed1
    2) mass2 | damper2 (d = 25) in parallel with spring2 (c = 1 N/m, s_rel0 = 1 m) | fixed2
    3) mass3 | springDamper3 (c = 1, d = 25, s_rel0 = 1)           | fixed3

Systems 2) and 3) are the same physics built two ways and must coincide. The energy lost by
each system equals the time integral of its dampers' ``lossPower`` (checked here).

Run ``python examples/translational_demo.py``: prints a summary and saves
``translational_demo.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os
import time

import numpy as np

import acausal
from acausal.components.translational import Damper, Fixed, Mass, Spring, SpringDamper


class DamperExample(acausal.Model):
    """Modelica.Mechanics.Translational.Examples.Damper (MSL 4.0)."""

    def __init__(self, name=None):
        super().__init__(name)
        self.mass1 = Mass(L=1, m=1)
        self.damper1 = Damper(d=25)
        self.fixed1 = Fixed(s0=4.5)
        self.mass2 = Mass(L=1, m=1)
        self.damper2 = Damper(d=25)
        self.fixed2 = Fixed(s0=4.5)
        self.mass3 = Mass(L=1, m=1)
        self.fixed3 = Fixed(s0=4.5)
        self.spring2 = Spring(s_rel0=1, c=1)
        self.springDamper3 = SpringDamper(s_rel0=1, d=25, c=1)
        c = self.connect
        c(self.mass1.flange_b, self.damper1.flange_a)
        c(self.mass2.flange_b, self.damper2.flange_a)
        c(self.damper2.flange_b, self.spring2.flange_b)
        c(self.damper2.flange_a, self.spring2.flange_a)
        c(self.mass3.flange_b, self.springDamper3.flange_a)
        c(self.damper1.flange_b, self.fixed1.flange)
        c(self.damper2.flange_b, self.fixed2.flange)
        c(self.springDamper3.flange_b, self.fixed3.flange)


def main():
    t0 = time.perf_counter()
    model = acausal.compile(DamperExample("Damper"))
    t1 = time.perf_counter()
    grid = np.linspace(0.0, 1.0, 1001)                 # experiment(StopTime=1, Interval=0.001)
    x0 = {}
    for k in (1, 2, 3):                                # s(start=3, fixed=true), v(start=10, ...)
        x0[f"mass{k}.s"], x0[f"mass{k}.v"] = 3.0, 10.0
    res = model.simulate(1.0, t=grid, x0=x0)
    t2 = time.perf_counter()
    print(model)
    print(f"states: {model.x_names}")
    print(f"compiled in {t1 - t0:.3f} s, simulated 1 s in {t2 - t1:.3f} s")

    def integral(y):
        """Composite Simpson rule on the (uniform, even) output grid."""
        h = grid[1] - grid[0]
        return float(h / 3 * (y[0] + y[-1] + 4 * np.sum(y[1:-1:2]) + 2 * np.sum(y[2:-1:2])))

    springs = {1: None, 2: "spring2", 3: "springDamper3"}
    losses = {1: ["damper1"], 2: ["damper2"], 3: ["springDamper3"]}
    for k in (1, 2, 3):
        s, v = res[f"mass{k}.s"], res[f"mass{k}.v"]
        E = 0.5 * 1.0 * v ** 2
        if springs[k]:
            E = E + 0.5 * 1.0 * (res[f"{springs[k]}.s_rel"] - 1.0) ** 2
        lost = sum(integral(res[f"{d}.lossPower"]) for d in losses[k])
        print(f"system {k}: s(1) = {s[-1]:.6f} m, v(1) = {v[-1]: .6f} m/s, energy "
              f"{E[0]:.3f} -> {E[-1]:.6f} J; dissipated (integral of lossPower) {lost:.6f} J, "
              f"balance error {abs(E[0] - E[-1] - lost):.1e} J")
    diff = np.max(np.abs(res["mass2.s"] - res["mass3.s"]))
    print(f"systems 2) and 3) coincide: max |mass2.s - mass3.s| = {diff:.1e} m")
    print(f"wall reaction of system 1 at t = 0: fixed1.flange.f = {res['fixed1.flange.f'][0]:.1f} N"
          f" (the damper pushes the wall forward with d*v = 250 N)")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    for k, label in ((1, "1) damper"), (2, "2) damper || spring"), (3, "3) SpringDamper")):
        style = "--" if k == 3 else "-"
        ax1.plot(grid, res[f"mass{k}.s"], style, label=label)
        ax2.plot(grid, res[f"mass{k}.v"], style, label=label)
    ax1.set_ylabel("mass.s [m]")
    ax1.grid(True)
    ax1.legend()
    ax2.set_ylabel("mass.v [m/s]")
    ax2.set_xlabel("time [s]")
    ax2.grid(True)
    fig.suptitle("Modelica.Mechanics.Translational.Examples.Damper")
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "translational_demo.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
