"""The mechanical energy of rigid bodies from a simulation's recorded motion alone (each
body's frame_a position, orientation, velocity and angular velocity), for energy balances
that do not trust the equations of motion under test."""
from __future__ import annotations

import numpy as np

G = 9.80665


def vector(res, name: str) -> np.ndarray:
    """name[1..3] over time, shape (n, 3)."""
    return np.stack([res[f"{name}[{k + 1}]"] for k in range(3)], axis=-1)


def orientation(res, frame: str) -> np.ndarray:
    """frame.R.T over time, shape (n, 3, 3) (from the world to the frame)."""
    return np.stack([[res[f"{frame}.R.T[{i},{j}]"] for j in (1, 2, 3)] for i in (1, 2, 3)]
                    ).transpose(2, 0, 1)


def body_energy(res, name: str, m: float, r_CM, inertia, w_a: str | None = None):
    """(kinetic, potential) [J] over time of the body ``name`` (mass m [kg], centre of mass
    r_CM [m] and inertia tensor about it [kg.m²] in frame_a; ``w_a`` the name of its
    recorded angular velocity, default ``<name>.w_a``) in gravity g along −y."""
    T, w = orientation(res, f"{name}.frame_a"), vector(res, w_a or f"{name}.w_a")
    r_CM = np.asarray(r_CM, dtype=float)
    v_cm = vector(res, f"{name}.v_0") + np.einsum("kji,kj->ki", T, np.cross(w, r_CM))
    y_cm = vector(res, f"{name}.r_0")[:, 1] + np.einsum("kj,j->k", T[:, :, 1], r_CM)
    kinetic = 0.5 * m * np.sum(v_cm ** 2, axis=1) \
        + 0.5 * np.einsum("ki,ij,kj->k", w, np.asarray(inertia, dtype=float), w)
    return kinetic, m * G * y_cm
