"""A vehicle driven up a slope (Translational.Components.Vehicle): a 1200 kg car, wheel radius
0.3 m, started at rest and driven by a constant 450 N.m at the wheels on level road, a road
that rises at 8 % (inclination = tan α = 0.08) from 600 m on, against a 4 m/s head wind.

The inclination is a function of the distance travelled: a small block (``Road``) reads
the vehicle's position (PositionSensor) and gives the grade. Prints the speed where the
slope begins and the speed at the end, up the slope, next to the steady speed where τ/R =
fDrag.f + fRoll.f − fGrav.f (a root of that balance, by scipy), and saves ``vehicle.png`` (in $ACAUSAL_OUT, default the current
directory): speed and the three driving resistances over time.
"""
from __future__ import annotations

import math
import os

import casadi as ca
import numpy as np
from scipy.optimize import brentq

import acausal
from acausal.components import rotational as rot
from acausal.components import translational as tr
from acausal.components.signals import Constant
from acausal.core import Component, Parameter, RealInput, RealOutput

M, R, TAU = 1200.0, 0.3, 450.0          # kg, m, N.m
GRADE, START, WIDTH = 0.08, 600.0, 20.0  # tan α, where the slope begins [m], its ramp-in [m]
WIND = -4.0                              # m/s (negative: head wind)


class Road(Component):
    """The road's inclination at the distance s [m]: 0, rising smoothly (over ``width``) to
    ``grade`` from ``start`` on."""
    grade = Parameter(GRADE, "1", "inclination of the slope = tan(angle)")
    start = Parameter(START, "m", "where the slope begins")
    width = Parameter(WIDTH, "m", "length of the transition to the slope")
    s = RealInput("distance travelled [m]")
    inclination = RealOutput("inclination = tan(angle)")

    def physics(self, e):
        x = (e.input(self.s) - self.start) / self.width
        e.output(self.inclination, self.grade / 2 * (1 + ca.tanh(4 * x)))


def build() -> acausal.Model:
    m = acausal.Model("uphill")
    m.vehicle = tr.Vehicle(m=M, J=2.0, R=R, A=2.2, Cd=0.3, CrConstant=0.012,
                           vWindConstant=WIND, useInclinationInput=True)
    m.torque, m.drive = rot.Torque(), Constant(k=TAU)
    m.position, m.road = tr.PositionSensor(), Road()
    for a, b in [(m.drive.y, m.torque.tau), (m.torque.flange, m.vehicle.flangeR),
                 (m.vehicle.flangeT, m.position.flange), (m.position.s, m.road.s),
                 (m.road.inclination, m.vehicle.inclination)]:
        m.connect(a, b)
    return m


def steady_speed(grade: float) -> float:
    """v where τ/R = Cd·A·rho/2·(v − vWind)² + Cr·m·g·cos α + m·g·sin α (MSL's laws)."""
    alpha, g = math.atan(grade), 9.80665

    def excess(v):
        return TAU / R - 0.3 * 2.2 * 1.2 / 2 * (v - WIND) ** 2 \
            - 0.012 * M * g * math.cos(alpha) - M * g * math.sin(alpha)
    return brentq(excess, 0.0, 100.0)


def main():
    res = acausal.compile(build()).simulate(150.0, t=np.linspace(0, 150, 1501), rtol=1e-8,
                                            atol=1e-10)
    v, s = res["vehicle.v"], res["vehicle.s"]
    at_slope = np.argmax(s > START)
    print(f"slope reached at t = {res.t[at_slope]:.1f} s at {v[at_slope] * 3.6:.1f} km/h "
          f"(steady on the flat: {steady_speed(0.0) * 3.6:.1f} km/h)")
    print(f"speed up the slope at the end {v[-1] * 3.6:.2f} km/h, steady "
          f"{steady_speed(GRADE) * 3.6:.2f} km/h by the force balance")

    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "vehicle.png")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    ax1.plot(res.t, v * 3.6, label="vehicle.v")
    ax1.axhline(steady_speed(GRADE) * 3.6, ls=":", c="k", label="steady speed on the slope")
    ax1.set_ylabel("speed [km/h]")
    ax1.legend()
    ax2.plot(res.t, res["vehicle.fDrag.f"], label="air drag fDrag.f")
    ax2.plot(res.t, res["vehicle.fRoll.f"], label="rolling resistance fRoll.f")
    ax2.plot(res.t, -res["vehicle.fGrav.f"], label="slope resistance −fGrav.f")
    ax2.axhline(TAU / R, ls=":", c="k", label="driving force τ/R")
    ax2.set_ylabel("force [N]")
    ax2.set_xlabel("time [s]")
    ax2.legend(loc="center right")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    print(f"saved {out}")


if __name__ == "__main__":
    main()
