"""The analyses on 3-D models with quaternion orientation states (free bodies, Spherical
joints), against linear models and statics derived by hand here.

What the linearization's states are: the model's own, so for a Spherical joint the
quaternion Q[1..4] and w_rel[1..3] (resolved in frame_b), for a free body r_0, Q, v_0, w_a:
A is the Jacobian of the right-hand side as integrated, der(Q) = ½·B(Q)ᵀ·w + k·(1 − |Q|²)·Q
(MSL's quaternion rate, B(Q) the 3 × 4 matrix of MSL's Quaternions.angularVelocity2, and the
norm-keeping term of ``acausal.compiler.charts`` with k = √(|w|² + 1) 1/s). Near
Q0 = (0, 0, 0, 1) a small rotation θ (T ≈ I − [θ×]) is δQ[1..3] = θ/2: the linear model is
the textbook one in θ with θ̇ = w, plus one eigenvalue −2k along Q0 (the norm direction,
which leaves the orientation Q/|Q| unchanged). ``modes`` needs coordinates with rates (q̇ =
v), which quaternion states are not: it refuses such a model.

(The 3-D double pendulum's modes against the closed form and the inverse dynamics of 3-D
chains against Pinocchio's RNEA are in tests/components/multibody.)
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import fsolve

import acausal
from acausal.analysis import equilibrium, linearize, modes
from acausal.components.multibody import Body, GravityTypes, Spherical, World
from acausal.core import Model
from acausal.errors import AnalysisError
from acausal.models.multibody_forces import ThreeSprings

G = 9.80665


def B(Q):
    """MSL's Frames.Quaternions: w = 2·B(Q)·der(Q)."""
    q1, q2, q3, q4 = Q
    return np.array([[q4, q3, -q2, -q1], [-q3, q4, q1, -q2], [q2, -q1, q4, -q3]])


def quaternion_block(Q0, w0):
    """∂/∂Q and ∂/∂w of der(Q) = ½·B(Q)ᵀ·w + k·(1 − |Q|²)·Q at |Q0| = 1."""
    k = np.sqrt(w0 @ w0 + 1)
    A_QQ = 0.5 * np.column_stack([B(e).T @ w0 for e in np.eye(4)]) - 2 * k * np.outer(Q0, Q0)
    return A_QQ, 0.5 * B(Q0).T


def spherical_pendulum(m, L, I):
    model = Model("spherical_pendulum")
    model.world = World()
    model.joint = Spherical()
    model.body = Body(m=m, r_CM=(0, -L, 0), I_11=I[0], I_22=I[1], I_33=I[2])
    model.connect(model.world.frame_b, model.joint.frame_a)
    model.connect(model.joint.frame_b, model.body.frame_a)
    return model


def test_spherical_pendulum_hanging_at_rest_linearizes_to_the_hand_model():
    """A Body (m, centre of mass L below the joint, inertia I about it) on a Spherical joint,
    hanging at rest (Q0 = (0, 0, 0, 1), w = 0; gravity −y): torque −m·g·L·(θx, 0, θz) about
    the pivot (rotation about the vertical neutral), I_O = I + m·L²·diag(1, 0, 1); with θ =
    2·δQ[1..3]: δQ̇ = ½·B(Q0)ᵀ·δw − 2·Q0·Q0ᵀ·δQ, δẇ = −I_O⁻¹·K·2·δQ[1..3]. Eigenvalues
    ±i·√(m·g·L/I_O) for the two swings, 0 twice (rotation about the vertical), −2 (the
    norm). ``modes`` refuses it (no coordinates with rates)."""
    m, L, I = 2.0, 0.5, np.array([0.01, 0.02, 0.03])
    lin = linearize(acausal.compile(spherical_pendulum(m, L, I)), {})
    assert lin.states == [f"joint.Q[{k}]" for k in (1, 2, 3, 4)] \
        + [f"joint.w_rel[{k}]" for k in (1, 2, 3)]
    Q0, w0 = np.array([0, 0, 0, 1.0]), np.zeros(3)
    I_O = np.diag(I) + m * L * L * np.diag([1, 0, 1])
    K = m * G * L * np.diag([1, 0, 1])
    A = np.zeros((7, 7))
    A[:4, :4], A[:4, 4:] = quaternion_block(Q0, w0)
    A[4:, :3] = -np.linalg.solve(I_O, K) * 2               # θ = 2·δQ[1..3]
    assert np.max(np.abs(lin.A - A)) < 1e-9 * np.max(np.abs(A))
    ev = np.sort_complex(np.linalg.eigvals(lin.A))
    swing = np.sqrt(m * G * L / I_O[[0, 2], [0, 2]])
    assert np.allclose(np.sort(ev.imag[ev.imag > 0]), np.sort(swing), rtol=1e-10)
    assert np.sum(np.abs(ev) < 1e-9) == 2 and np.min(ev.real) == pytest.approx(-2.0, 1e-12)
    with pytest.raises(AnalysisError, match="coordinates"):
        modes(lin)


@pytest.mark.parametrize("axis", [0, 1, 2])
def test_free_body_spinning_about_a_principal_axis_linearizes_to_euler_s_equations(axis):
    """A free Body (no gravity, inertias 1, 2, 3 kg.m², r_CM = 0) spinning at ω = 2 rad/s
    about principal axis ``axis``, orientation Q0 = (0, 0, 0, 1), moving at v_0: the 13×13
    A is ṙ = v, v̇ = 0, the quaternion block of MSL's rate with the norm term, and Euler's
    equations linearized, I·δẇ = (I·δw) × w0 + (I·w0) × δw. Spun about the intermediate
    axis, one eigenvalue is real and positive, ω·√((I3 − I2)(I2 − I1)/(I1·I3)) (the flip of
    Dzhanibekov's effect); about the others the spin is stable (no positive real part)."""
    I, omega = np.array([1.0, 2.0, 3.0]), 2.0
    w0 = omega * np.eye(3)[axis]
    model = Model("spinning")
    model.world = World(gravityType=GravityTypes.NoGravity)
    model.body = Body(m=1.5, r_CM=(0, 0, 0), I_11=I[0], I_22=I[1], I_33=I[2],
                      v_0_start=(0.3, 0, 0), w_0_start=tuple(w0))
    lin = linearize(acausal.compile(model), {})
    names = [f"body.frame_a.r_0[{k}]" for k in (1, 2, 3)] + \
        [f"body.Q[{k}]" for k in (1, 2, 3, 4)] + [f"body.v_0[{k}]" for k in (1, 2, 3)] + \
        [f"body.w_a[{k}]" for k in (1, 2, 3)]
    order = [lin.states.index(n) for n in names]
    A_ours = lin.A[np.ix_(order, order)]
    A = np.zeros((13, 13))
    A[0:3, 7:10] = np.eye(3)
    A[3:7, 3:7], A[3:7, 10:13] = quaternion_block(np.array([0, 0, 0, 1.0]), w0)
    Iw0 = I * w0
    A[10:13, 10:13] = np.column_stack([(np.cross(I * e, w0) + np.cross(Iw0, e)) / I
                                       for e in np.eye(3)])
    assert np.max(np.abs(A_ours - A)) < 1e-9 * np.max(np.abs(A))
    ev = np.linalg.eigvals(lin.A)
    if axis == 1:
        rate = omega * np.sqrt((I[2] - I[1]) * (I[1] - I[0]) / (I[0] * I[2]))
        assert np.max(ev.real) == pytest.approx(rate, rel=1e-10)
    else:
        assert np.max(ev.real) < 1e-9


def test_three_springs_equilibrium_is_the_statics_of_the_hanging_body():
    """MSL's ThreeSprings at rest: ``equilibrium`` from the start values against the statics
    solved here by scipy: spring2 hangs vertical, stretched by m·g/c2, the body's centre of
    mass below its frame_a (r_CM = (0, −0.2, 0): the body upright), the massless junction
    J where spring1 and spring3 carry m·g: Σ c_i·(|A_i − J| − s0)·(A_i − J)/|A_i − J| =
    (0, m·g, 0), A1 = (0.3, 0, 0), A3 = (0, 0, 0.3)."""
    m, s0, c1, c2, c3 = 0.8, 0.1, 20.0, 40.0, 20.0
    anchors, c = np.array([[0.3, 0, 0], [0, 0, 0.3]]), np.array([c1, c3])

    def balance(J):
        d = anchors - J
        length = np.linalg.norm(d, axis=1)
        return (c * (length - s0) / length) @ d - np.array([0, m * G, 0])

    J = fsolve(balance, [0.1, -0.2, 0.1], xtol=1e-14)
    r_body = J - np.array([0, s0 + m * G / c2, 0])
    compiled = acausal.compile(ThreeSprings())
    eq = equilibrium(compiled, guess=ThreeSprings.GUESS)
    for k in (1, 2, 3):
        assert eq[f"spring3.r_b_0[{k}]"] == pytest.approx(J[k - 1], abs=1e-10)
        assert eq[f"body1.frame_a.r_0[{k}]"] == pytest.approx(r_body[k - 1], abs=1e-10)
        assert abs(eq[f"body1.v_0[{k}]"]) < 1e-12 and abs(eq[f"body1.w_a[{k}]"]) < 1e-12
    # the centre of mass straight below frame_a: T·(0, −1, 0) = (0, −1, 0) resolved in body1
    T = np.array([[eq[f"body1.frame_a.R.T[{i},{j}]"] for j in (1, 2, 3)] for i in (1, 2, 3)])
    assert np.max(np.abs(T.T @ np.array([0, -0.2, 0]) - [0, -0.2, 0])) < 1e-10
    assert eq["spring2.f"] == pytest.approx(m * G, rel=1e-10)
