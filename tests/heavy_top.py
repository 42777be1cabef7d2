"""The heavy symmetric top in steady precession (Goldstein), a closed form for 3-D bodies on a
Spherical joint: mass m at l on its axis, inertias A transverse and C axial about the centre
of mass, gravity −z, started with the tilt θ and the angular velocity Ω·z + ψ̇·e3 of a
steady precession (m·g·l = Ω·(C·ω3 − A'·Ω·cos θ), A' = A + m·l², ω3 = Ω·cos θ + ψ̇): its
axis e3 turns about z at the rate Ω with constant tilt."""
from __future__ import annotations

import casadi as ca
import numpy as np

from acausal import frames
from acausal.components.multibody import Body, Spherical, World
from acausal.core import Model

M, L, A, C, G = 0.5, 0.1, 2e-3, 4e-3, 9.81
THETA, OMEGA = 0.5, 1.5


def heavy_top() -> tuple[Model, callable]:
    """The top's Model (world, joint, top) and its axis e3 over time (the closed form):
    ``axis(t)`` of shape (3, len(t)), to compare with the rows top.frame_a.R.T[3, j]."""
    omega3 = (M * G * L / OMEGA + (A + M * L * L) * OMEGA * np.cos(THETA)) / C
    e3 = np.array(ca.evalf(frames.planar_rotation((1, 0, 0), THETA)))[2]
    w0 = OMEGA * np.array([0, 0, 1.0]) + (omega3 - OMEGA * np.cos(THETA)) * e3
    m = Model("top")
    m.world = World(g=G, n=(0, 0, -1))
    m.joint = Spherical(angles_start=(THETA, 0.0, 0.0), w_rel_a_start=tuple(w0))
    m.top = Body(m=M, r_CM=(0, 0, L), I_11=A, I_22=A, I_33=C)
    m.connect(m.world.frame_b, m.joint.frame_a)
    m.connect(m.joint.frame_b, m.top.frame_a)

    def axis(t):
        c, s = np.cos(OMEGA * t), np.sin(OMEGA * t)
        return np.array([c * e3[0] - s * e3[1], s * e3[0] + c * e3[1],
                         np.full_like(t, e3[2])])
    return m, axis
