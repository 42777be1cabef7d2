"""PlanarMechanics' SpringDemo and SpringDamperDemo, line by line, and a line-spring pendulum.

1. SpringDemo: a body (m = 0.5 kg, I = 0.1 kg.m²) held by PlanarMechanics' x/y ``Spring``
   (c_y = 10 N/m, s_rely0 = -0.5 m) and the line ``Damper`` (d = 1 N.s/m) in parallel with a
   vertical ``Prismatic`` (r = {0, 1}, s(start = 0.2)), under gravity; the body passes the
   point of zero spring length. Along the prismatic it is a damped oscillator
   m s'' = -c_y (s - s_rely0) - d s' - m g, solved in closed form here.
2. SpringDamperDemo: a free body (start r = {1, 1}) on an x/y ``SpringDamper`` (c_x = c_y = 5,
   d_x = d_y = 1, c_phi = d_phi = 0) from a frame at {-1, 0}: two independent damped
   oscillators in x and y, also in closed form.
3. A body on a ``LineSpring`` (force along the line between the frame origins; not in
   PlanarMechanics, whose Spring is the x/y one): an elastic pendulum whose energy
   T + V (computed here from the recorded motion) stays constant.

Run ``python examples/planar_spring_demo.py``: prints a summary and saves
``planar_spring_demo.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import math
import os
import time

import numpy as np

import acausal
from acausal.components.planar import (Body, Damper, Fixed, FixedTranslation, LineSpring,
                                       Prismatic, Spring, SpringDamper, World)

G = 9.81


class SpringDemo(acausal.Model):
    """PlanarMechanics.Examples.SpringDemo."""

    def __init__(self, name=None):
        super().__init__(name)
        self.body = Body(I=0.1, m=0.5)
        self.fixed = Fixed()
        self.planarWorld = World()
        self.fixedTranslation = FixedTranslation()              # r = {1, 0}
        self.spring1 = Spring(c_y=10, s_rely0=-0.5, c_x=1, c_phi=1e5)
        self.damper = Damper(d=1)
        self.prismatic = Prismatic(r=(0, 1))
        c = self.connect
        c(self.fixed.frame, self.fixedTranslation.frame_a)
        c(self.spring1.frame_a, self.fixedTranslation.frame_b)
        c(self.spring1.frame_b, self.body.frame_a)
        c(self.damper.frame_a, self.spring1.frame_a)
        c(self.damper.frame_b, self.spring1.frame_b)
        c(self.spring1.frame_a, self.prismatic.frame_a)
        c(self.prismatic.frame_b, self.spring1.frame_b)


class SpringDamperDemo(acausal.Model):
    """PlanarMechanics.Examples.SpringDamperDemo."""

    def __init__(self, name=None):
        super().__init__(name)
        self.springDamper = SpringDamper(s_relx0=0, d_y=1, s_rely0=0, d_phi=0, c_y=5, c_x=5,
                                         d_x=1, c_phi=0)
        self.body = Body(I=0.1, m=0.5)
        self.fixed = Fixed()
        self.planarWorld = World()
        self.fixedTranslation = FixedTranslation(r=(-1, 0))
        c = self.connect
        c(self.fixed.frame, self.fixedTranslation.frame_a)
        c(self.fixedTranslation.frame_b, self.springDamper.frame_a)
        c(self.springDamper.frame_b, self.body.frame_a)


class LineSpringPendulum(acausal.Model):
    """A body on a LineSpring (c = 40 N/m, unstretched 0.5 m) from a fixed point."""

    def __init__(self, name=None):
        super().__init__(name)
        self.planarWorld = World()
        self.fixed = Fixed()
        self.spring = LineSpring(c=40, s_rel0=0.5)
        self.body = Body(m=1, I=0.1)
        self.connect(self.fixed.frame, self.spring.frame_a)
        self.connect(self.spring.frame_b, self.body.frame_a)


def damped(t, m, c, d, x_eq, x0, v0):
    """Closed-form motion of m x'' + d x' + c (x - x_eq) = 0 (underdamped)."""
    sigma = d / (2 * m)
    wd = math.sqrt(c / m - sigma ** 2)
    A = x0 - x_eq
    B = (v0 + sigma * A) / wd
    return x_eq + np.exp(-sigma * t) * (A * np.cos(wd * t) + B * np.sin(wd * t))


def main():
    tol = dict(rtol=1e-10, atol=1e-12)
    grid = np.linspace(0.0, 5.0, 2001)                           # experiment(StopTime=5)

    t0 = time.perf_counter()
    demo1 = acausal.compile(SpringDemo("SpringDemo"))
    r1 = demo1.simulate(5.0, t=grid, x0={"prismatic.s": 0.2, "prismatic.v": 0.0}, **tol)
    t1 = time.perf_counter()
    s_ref = damped(grid, 0.5, 10.0, 1.0, -0.5 - 0.5 * G / 10.0, 0.2, 0.0)
    err1 = np.max(np.abs(r1["prismatic.s"] - s_ref))
    print(f"SpringDemo ({t1 - t0:.3f} s, coordinates {demo1.lagrange.q_names}): "
          f"s from 0.2 m to {r1['prismatic.s'][-1]:.4f} m (rest at {-0.5 - 0.5 * G / 10:.4f} m), "
          f"passes zero spring length; max |s - closed form| = {err1:.1e} m")

    t0 = time.perf_counter()
    demo2 = acausal.compile(SpringDamperDemo("SpringDamperDemo"))
    x0 = {"body.r[1]": 1.0, "body.r[2]": 1.0, "body.v[1]": 0.0, "body.v[2]": 0.0,
          "body.phi": 0.0, "body.w": 0.0}
    r2 = demo2.simulate(5.0, t=grid, x0=x0, **tol)
    t1 = time.perf_counter()
    x_ref = damped(grid, 0.5, 5.0, 1.0, -1.0, 1.0, 0.0)
    y_ref = damped(grid, 0.5, 5.0, 1.0, -0.5 * G / 5.0, 1.0, 0.0)
    err2 = max(np.max(np.abs(r2["body.r[1]"] - x_ref)), np.max(np.abs(r2["body.r[2]"] - y_ref)))
    p = r2["springDamper.lossPower"]
    loss = float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(grid)))        # trapezoidal rule
    m = 0.5

    def energy(k):
        return (0.5 * m * (r2["body.v[1]"][k] ** 2 + r2["body.v[2]"][k] ** 2)
                + 0.5 * 5.0 * ((r2["body.r[1]"][k] + 1.0) ** 2 + r2["body.r[2]"][k] ** 2)
                + m * G * r2["body.r[2]"][k])

    print(f"SpringDamperDemo ({t1 - t0:.3f} s, {len(demo2.lagrange.q_names)} coordinates of the "
          f"free body): max |r - closed form| = {err2:.1e} m; energy lost "
          f"{energy(0) - energy(-1):.6f} J = integral of lossPower {loss:.6f} J")

    t0 = time.perf_counter()
    demo3 = acausal.compile(LineSpringPendulum("LineSpringPendulum"))
    r3 = demo3.simulate(5.0, t=grid, x0={"body.r[1]": 0.6, "body.r[2]": -0.5,
                                         "body.v[1]": 0.0, "body.v[2]": 0.0}, **tol)
    t1 = time.perf_counter()
    x, y = r3["body.r[1]"], r3["body.r[2]"]
    E3 = (0.5 * (r3["body.v[1]"] ** 2 + r3["body.v[2]"] ** 2)
          + 0.5 * 40 * (np.hypot(x, y) - 0.5) ** 2 + G * y)
    print(f"LineSpring pendulum ({t1 - t0:.3f} s): spring length {r3['spring.length'].min():.3f}"
          f" .. {r3['spring.length'].max():.3f} m, relative energy drift "
          f"{np.ptp(E3) / np.max(np.abs(E3)):.1e}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 3, figsize=(13, 3.8))
    ax[0].plot(grid, r1["prismatic.s"], label="prismatic.s")
    ax[0].plot(grid, s_ref, "k:", label="closed form")
    ax[0].axhline(0, color="grey", lw=0.5)
    ax[0].set_xlabel("t [s]")
    ax[0].set_ylabel("s [m]")
    ax[0].legend()
    ax[0].set_title("SpringDemo")
    ax[1].plot(grid, r2["body.r[1]"], label="body.r[1]")
    ax[1].plot(grid, r2["body.r[2]"], label="body.r[2]")
    ax[1].plot(grid, x_ref, "k:", label="closed form")
    ax[1].plot(grid, y_ref, "k:")
    ax[1].set_xlabel("t [s]")
    ax[1].set_ylabel("[m]")
    ax[1].legend()
    ax[1].set_title("SpringDamperDemo")
    ax[2].plot(x, y)
    ax[2].plot([0], [0], "ko")
    ax[2].set_aspect("equal")
    ax[2].set_title("LineSpring pendulum")
    fig.tight_layout()
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "planar_spring_demo.png")
    fig.savefig(out, dpi=110)
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
