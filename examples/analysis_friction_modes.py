"""Linearization and modes of a model with friction, in a given discrete mode.

    wall ──k1── m1 (Coulomb friction: SupportFriction) ──k2── m2

A model with modes is analysed in one set of them: ``mode={"friction.mode": 0}`` (stuck:
the friction is a rigid lock, only m2 vibrates, on k2) or ``{"friction.mode": 1}``
(sliding: the friction force is constant, the free two-mass system); by default the modes
simulate's event iteration finds at the point (at rest, unloaded: stuck). The results say
which modes they are of. Prints both, with the closed forms; also the equilibria of the
block pushed against a spring, stuck and sliding.
"""
from __future__ import annotations

import numpy as np

import acausal
from acausal.analysis import equilibrium, linearize, modes
from acausal.components import translational as tr

M1, M2, K1, K2, F0 = 2.0, 0.5, 300.0, 50.0, 3.0


def main():
    m = acausal.Model("two_masses")
    m.wall = tr.Fixed()
    m.k1, m.k2 = tr.Spring(c=K1), tr.Spring(c=K2)
    m.m1, m.m2 = tr.Mass(m=M1), tr.Mass(m=M2)
    m.friction = tr.SupportFriction(f_pos=[[0.0, F0]], peak=1.5)
    for a, b in [(m.wall.flange, m.k1.flange_a), (m.k1.flange_b, m.m1.flange_a),
                 (m.m1.flange_b, m.k2.flange_a), (m.k2.flange_b, m.m2.flange_a),
                 (m.m1.flange_a, m.friction.flange_a)]:
        m.connect(a, b)
    model = acausal.compile(m)
    rest = {"m1.s": 0.0, "m1.v": 0.0, "m2.s": 0.0, "m2.v": 0.0}

    print(linearize(model, rest))                          # default: stuck, said in repr
    for mode in (0, 1):
        print(modes(model, rest, mode={"friction.mode": mode}))
    M, K = np.diag([M1, M2]), np.array([[K1 + K2, -K2], [-K2, K2]])
    free = np.sqrt(np.linalg.eigvals(np.linalg.solve(M, K)).real) / (2 * np.pi)
    print(f"closed forms: stuck {np.sqrt(K2 / M2) / (2 * np.pi):.4f} Hz; "
          f"sliding {np.sort(free).round(4)} Hz")

    eq = equilibrium(model, guess={"m1.s": 0.005})
    print(f"equilibrium near m1.s = 5 mm (stuck: a range of positions holds, the one "
          f"nearest the guess): {eq.mode}, m1.s = {eq['m1.s']:.4g} m, friction "
          f"holds {eq['friction.f']:.3g} N")
    eq = equilibrium(model, mode={"friction.mode": 1})
    print(f"sliding forward at rest: {eq.mode}, m1.s = {eq['m1.s']:.4g} m "
          f"(closed form -f0/k1 = {-F0 / K1:.4g} m)")


if __name__ == "__main__":
    main()
