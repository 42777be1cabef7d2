"""Linearization and modes of models with quaternion states in the minimal tangent
coordinates θ (``linearize(..., tangent=True)``; ``modes`` always): a pendulum on a
Spherical joint against its closed form, a free body's rigid-body modes, and a loop through
a Spherical joint against the same mechanism built of revolute joints."""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import acausal
from acausal.analysis import linearize, modes
from acausal.components.multibody import (Body, BodyShape, FixedTranslation, Revolute,
                                          Spherical, SphericalSpherical, World)
from wiring import model

G = 9.80665
M_BOB, L, I = 2.0, 0.5, np.array([0.01, 0.02, 0.03])


def _spherical_pendulum():
    return model("sphericalPendulum", lambda m: (
        (m.world.frame_b, m.joint.frame_a), (m.joint.frame_b, m.body.frame_a)),
        world=World(), joint=Spherical(),
        body=Body(m=M_BOB, r_CM=(0, -L, 0), I_11=I[0], I_22=I[1], I_33=I[2]))


def test_spherical_pendulum_in_tangent_coordinates_is_the_textbook_model():
    """Hanging at rest (gravity −y), in (θ, w): θ̇ = w, I_O·ẇ = −m·g·L·(θx, 0, θz), I_O =
    I + m·L²·diag(1, 0, 1); the mass matrix is I_O."""
    lin = linearize(acausal.compile(_spherical_pendulum()), {}, tangent=True)
    assert lin.states == [f"joint.theta[{k}]" for k in (1, 2, 3)] \
        + [f"joint.w_rel[{k}]" for k in (1, 2, 3)]
    I_O = np.diag(I + M_BOB * L * L * np.array([1, 0, 1]))
    K = M_BOB * G * L * np.diag([1, 0, 1])
    A = np.block([[np.zeros((3, 3)), np.eye(3)], [-np.linalg.solve(I_O, K), np.zeros((3, 3))]])
    assert np.max(np.abs(lin.A - A)) < 1e-10 * np.max(np.abs(A))
    assert np.max(np.abs(lin.mass - I_O)) < 1e-12
    assert np.all(lin.x_op == 0)


def test_spherical_pendulum_modes_are_the_two_swings_and_the_free_turn():
    """modes(): √(m·g·L/I_O) about x and z (the two swings, closed form), 0 Hz about the
    vertical (the bob turns freely), each mode along one θ axis."""
    md = modes(acausal.compile(_spherical_pendulum()), {})
    assert md.coordinates == [f"joint.theta[{k}]" for k in (1, 2, 3)]
    I_O = I + M_BOB * L * L * np.array([1, 0, 1])
    swing = np.sqrt(M_BOB * G * L / I_O[[2, 0]]) / (2 * math.pi)     # ascending
    assert np.allclose(md.frequencies, [0.0, *swing], rtol=1e-10, atol=1e-12)
    for k, axis in enumerate((2, 3, 1)):
        assert abs(md.shape(k)[f"joint.theta[{axis}]"]) == 1.0
        assert sum(abs(v) for v in md.shape(k).values()) < 1 + 1e-9


def test_free_body_has_six_rigid_body_modes():
    """A free body in gravity: nothing holds it, so all six modes (3 translations, 3
    rotations) are at 0 Hz, and every eigenvalue of the 12-state tangent model is 0."""
    md = modes(acausal.compile(model("freeBody", lambda m: (), world=World(), body=Body(
        m=1.5, r_CM=(0.1, 0.2, 0), I_11=1, I_22=2, I_33=3))), {})
    assert len(md.coordinates) == 6 and np.all(md.frequencies == 0.0)
    assert np.max(np.abs(md.eigenvalues)) < 1e-9


BAR = dict(r=(0, -1.0, 0), r_CM=(0, -0.5, 0), m=1.0, I_11=0.1, I_22=0.01, I_33=0.1)


def test_loop_through_a_spherical_joint_has_the_modes_of_its_revolute_tree():
    """A bar hanging on a Spherical joint at the origin, its tip {0, −1, 0} tied to {1, −1, 0}
    by a SphericalSpherical rod of 1 m: it swings about the axis {1, −1, 0}/√2 (its tip on
    the circle the rod allows, lowest there) and spins about itself: the modes of the tree
    Revolute({1, −1, 0}/√2) + Revolute({0, 1, 0}) (one swing, one free spin at 0 Hz), to
    1e-9."""
    loop = model("sphericalRod", lambda m: (
        (m.world.frame_b, m.sph.frame_a), (m.sph.frame_b, m.bar.frame_a),
        (m.world.frame_b, m.fix.frame_a), (m.bar.frame_b, m.rod.frame_a),
        (m.fix.frame_b, m.rod.frame_b)),
        world=World(), sph=Spherical(), bar=BodyShape(**BAR),
        fix=FixedTranslation(r=(1.0, -1.0, 0)), rod=SphericalSpherical(rodLength=1.0))
    tree = model("tree", lambda m: (
        (m.world.frame_b, m.r1.frame_a), (m.r1.frame_b, m.r2.frame_a),
        (m.r2.frame_b, m.bar.frame_a)),
        world=World(), r1=Revolute(n=(1 / math.sqrt(2), -1 / math.sqrt(2), 0)),
        r2=Revolute(n=(0, 1, 0)), bar=BodyShape(**BAR))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        a = modes(acausal.compile(loop), {})
    b = modes(acausal.compile(tree), {})
    assert len(a.frequencies) == 2
    assert np.allclose(a.frequencies, b.frequencies, rtol=1e-9, atol=1e-12)
    assert a.frequencies[0] == 0.0 and a.frequencies[1] > 0.3
    # closed form: a physical pendulum about u = {1, −1, 0}/√2 through the pivot, its free
    # spin about the bar's axis e = {0, 1, 0} coupled through the inertia. About the pivot
    # I = I_cm + m·(|r|²·E − r·rᵀ), r = r_CM; stiffness m·g·|n⊥u|·|r⊥u| = m·g/4;
    # ω² = k / (uᵀIu − (uᵀIe)² / eᵀIe)
    r, u, e = np.array(BAR["r_CM"]), np.array([1.0, -1.0, 0]) / math.sqrt(2), np.array([0, 1.0, 0])
    inertia = np.diag([BAR["I_11"], BAR["I_22"], BAR["I_33"]]) \
        + BAR["m"] * (r @ r * np.eye(3) - np.outer(r, r))
    k = BAR["m"] * G * np.linalg.norm(r - (r @ u) * u) * np.linalg.norm(-e - (-e @ u) * u)
    omega2 = k / (u @ inertia @ u - (u @ inertia @ e) ** 2 / (e @ inertia @ e))
    assert a.frequencies[1] == pytest.approx(math.sqrt(omega2) / (2 * math.pi), rel=1e-9)
