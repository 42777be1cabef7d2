"""Pendulum on a spring-mounted cart, the worked case of DESIGN.md, from planar and 1-D components.

A cart (mass m1) on a horizontal rail is tied by a spring k to a point whose position u(t) is
prescribed; a pendulum (mass m2, inertia J_S about its centre of mass at distance l from the
hinge) hangs from the cart; gravity g. With x the cart position and φ the pendulum angle from
the downward vertical (counter-clockwise):

    (m1+m2) ẍ + m2 l cosφ φ̈ − m2 l sinφ φ̇² + k x = k u(t)
    (J_S + m2 l²) φ̈ + m2 l cosφ ẍ + m2 g l sinφ = 0

Components (PlanarMechanics and MSL names):

    World  base: Fixed.frame ── rail: Prismatic(useFlange) ── cart: Body (m1, I=0)
              rail.flange_a ── spring (c = k) ── shaker.flange
                                                 shaker: Position(exact=True, useSupport=True),
                                                 support on rail.support, s_ref ← u: Sine
              rail.frame_b ── hinge: Revolute ── arm: FixedTranslation r = (0, −l)
                                                  ── pendulum: Body (m2, I = J_S)

How u(t) enters: the spring's far end is moved by a translational Position source with
exact=True, which makes the end follow u(t) exactly (its speed and acceleration by algorithmic
differentiation). exact=True needs u to be a function of time only, so u is a signal source
(``u``: Sine, u = U sin(2π f t)), not a model Input: the generalized force k·u(t) then sits in
``lagrange.Q_rest`` and the spring's k·x in K. ``drive="input"`` builds the equivalent with a
model Input ``u`` instead: the spring ties the cart to the ground (rail.support) and a Force
k·u (``gain``: Gain with k, which must be kept equal to ``spring.c``) pushes the cart, so
that B = [k, 0]ᵀ — the form a controller or an optimal-control problem wants.

Compiled coordinates: x = ``rail.s``, φ = ``hinge.phi``.

The script shows the pendulum working as a vibration absorber: at Ω_a = sqrt(m2 g l/(J_S +
m2 l²)) the linearized cart amplitude is zero. It starts both runs on the linear steady
state (x = 0, φ = 0 and the harmonic solution's speeds), one excited at Ω_a and one at
1.3·Ω_a, prints the cart's amplitude next to the linear prediction and saves
``pendulum_on_cart.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os
import time

import numpy as np

import acausal
from acausal.components import translational as tr
from acausal.components.planar import Body, Fixed, FixedTranslation, Prismatic, Revolute, World
from acausal.components.signals import Gain, Sine

CART_MASS, PENDULUM_MASS = 2.0, 0.5     # kg
ARM, J_S = 0.3, 0.015                   # m (hinge to centre of mass), kg.m² (about the centre)
STIFFNESS = 200.0                       # N/m
AMPLITUDE, FREQUENCY = 2.0e-3, 0.5      # m, Hz: u(t) = AMPLITUDE sin(2π FREQUENCY t)


class PendulumOnCart(acausal.Model):
    """Cart on a spring whose far end moves by u(t), with a pendulum hanging from the cart.

    drive="position": u is the Sine source ``u`` (amplitude U [m], frequency f [Hz]) moving
    the spring's end through Position(exact=True). drive="input": u [m] is a model Input, the
    spring is tied to the ground and the force k·u acts on the cart.
    """

    def __init__(self, name="pendulumOnCart", m1=CART_MASS, m2=PENDULUM_MASS, l=ARM, J_S=J_S,
                 k=STIFFNESS, U=AMPLITUDE, f=FREQUENCY, drive="position"):
        super().__init__(name)
        if drive not in ("position", "input"):
            raise ValueError(f"drive must be 'position' or 'input', got {drive!r}")
        self.world = World()
        self.base = Fixed()
        self.rail = Prismatic(r=(1.0, 0.0), useFlange=True)
        self.cart = Body(m=m1, I=0.0)
        self.hinge = Revolute()
        self.arm = FixedTranslation(r=(0.0, -l))
        self.pendulum = Body(m=m2, I=J_S)
        self.spring = tr.Spring(c=k)
        links = [(self.base.frame, self.rail.frame_a), (self.rail.frame_b, self.cart.frame_a),
                 (self.rail.frame_b, self.hinge.frame_a), (self.hinge.frame_b, self.arm.frame_a),
                 (self.arm.frame_b, self.pendulum.frame_a),
                 (self.spring.flange_b, self.rail.flange_a)]
        if drive == "position":
            self.u = Sine(amplitude=U, f=f)
            self.shaker = tr.Position(exact=True, useSupport=True)
            links += [(self.u.y, self.shaker.s_ref), (self.shaker.support, self.rail.support),
                      (self.shaker.flange, self.spring.flange_a)]
        else:
            self.u = acausal.Input(unit="m", description="position of the spring's far end")
            self.gain = Gain(k=k)
            self.force = tr.Force()
            links += [(self.rail.support, self.spring.flange_a), (self.u.y, self.gain.u),
                      (self.gain.y, self.force.f), (self.force.flange, self.rail.flange_a)]
        for a, b in links:
            self.connect(a, b)


def harmonic(Omega, m1, m2, l, J_S, k, U, g=9.81):
    """Amplitudes (X, Φ) of the linearized steady state x = X sin Ωt, φ = Φ sin Ωt."""
    A = np.array([[k - (m1 + m2) * Omega ** 2, -m2 * l * Omega ** 2],
                  [-m2 * l * Omega ** 2, m2 * g * l - (J_S + m2 * l ** 2) * Omega ** 2]])
    return np.linalg.solve(A, [k * U, 0.0])


def main():
    t0 = time.perf_counter()
    model = acausal.compile(PendulumOnCart())
    t1 = time.perf_counter()
    lag = model.lagrange
    print(model)
    print(f"coordinates {lag.q_names} (x = rail.s, φ = hinge.phi); compiled in {t1 - t0:.3f} s")

    m1, m2, l, J, k, g = CART_MASS, PENDULUM_MASS, ARM, J_S, STIFFNESS, 9.81
    M0 = np.array([[m1 + m2, m2 * l], [m2 * l, J + m2 * l ** 2]])
    K0 = np.diag([k, m2 * g * l])
    w_modes = np.sqrt(np.sort(np.linalg.eigvals(np.linalg.solve(M0, K0)).real))
    Omega_a = np.sqrt(m2 * g * l / (J + m2 * l ** 2))
    print(f"linearized natural frequencies {np.round(w_modes / (2 * np.pi), 4).tolist()} Hz, "
          f"absorber frequency sqrt(m2 g l/(J_S + m2 l²)) = {Omega_a / (2 * np.pi):.4f} Hz")

    t_final = 10.0
    grid = np.linspace(0.0, t_final, 2001)
    runs = {}
    for label, Omega in (("tuned, Ω = Ω_a", Omega_a), ("detuned, Ω = 1.3 Ω_a", 1.3 * Omega_a)):
        X, Phi = harmonic(Omega, m1, m2, l, J, k, AMPLITUDE)
        t2 = time.perf_counter()
        res = model.simulate(t_final, t=grid, params={"u.f": Omega / (2 * np.pi)},
                             x0={"rail.v": X * Omega, "hinge.w": Phi * Omega})
        t3 = time.perf_counter()
        print(f"{label:22s} (simulated {t_final:.0f} s in {t3 - t2:.3f} s): cart amplitude "
              f"{np.max(np.abs(res['rail.s'])) * 1e3:7.3f} mm (linear {abs(X) * 1e3:7.3f} mm), "
              f"pendulum {np.degrees(np.max(np.abs(res['hinge.phi']))):6.2f} deg "
              f"(linear {np.degrees(abs(Phi)):6.2f} deg), spring end {AMPLITUDE * 1e3:.1f} mm")
        runs[label] = res

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(3, 1, sharex=True, figsize=(7, 7))
    for i, (label, res) in enumerate(runs.items()):
        col = f"C{i}"
        axes[0].plot(grid, res["u.y"] * 1e3, col, label=label)
        axes[1].plot(grid, res["rail.s"] * 1e3, col, label=label)
        axes[2].plot(grid, np.degrees(res["hinge.phi"]), col, label=label)
    axes[0].set_ylabel("spring end u [mm]")
    axes[1].set_ylabel("cart x [mm]")
    axes[2].set_ylabel("pendulum φ [deg]")
    axes[2].set_xlabel("time [s]")
    for ax in axes:
        ax.grid(True)
        ax.legend(fontsize=8, loc="upper right")
    axes[0].set_title("Pendulum on a spring-mounted cart: the pendulum as vibration absorber")
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "pendulum_on_cart.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
