"""The 6 rows that close a loop of 3-D frames (``frame_residual``): zero where the frames
coincide, their Jacobian with respect to the actual frame's virtual twist the identity
there (so their multipliers are the cut force and torque resolved in that frame), and
MSL's equalityConstraint residues equal to a small rotation vector, at random poses."""
from __future__ import annotations

import casadi as ca
import numpy as np

from acausal.compiler.relations import frame_residual, relax_spatial
from acausal.frames import equality_constraint, parts, planar_rotation

RNG = np.random.default_rng(11)


def _random_pose():
    q, _ = np.linalg.qr(RNG.normal(size=(3, 3)))
    return np.concatenate([RNG.normal(size=3), (q * np.sign(np.linalg.det(q))).ravel()])


def test_frame_residual_vanishes_with_the_twist_jacobian_the_identity():
    eps = ca.SX.sym("eps", 6)
    zero = ca.SX.zeros(6)
    for _ in range(5):
        p = ca.DM(_random_pose())
        relaxed, _, _ = relax_spatial(p, zero, zero, eps, zero, zero)
        rows = frame_residual(p, relaxed)
        f = ca.Function("f", [eps], [rows, ca.jacobian(rows, eps)])
        value, J = (np.array(v, dtype=float) for v in f(np.zeros(6)))
        assert np.max(np.abs(value)) < 1e-14
        assert np.max(np.abs(J - np.eye(6))) < 1e-12


def test_equality_constraint_is_the_rotation_between_the_frames():
    """T2 = planarRotation(e, θ)·T1 (frame 2 turned by θ about e, resolved in frame 1):
    the residues are θ·e for small θ (to θ²), 0 for θ = 0."""
    for _ in range(5):
        _, T1 = parts(ca.DM(_random_pose()))
        e = RNG.normal(size=3)
        e /= np.linalg.norm(e)
        for theta in (0.0, 1e-4):
            T2 = ca.mtimes(planar_rotation(ca.DM(e), theta), T1)
            res = np.array(ca.evalf(equality_constraint(ca.SX(T1), ca.SX(T2))),
                           dtype=float).ravel()
            assert np.max(np.abs(res - theta * e)) <= 10 * theta ** 2 + 1e-15
