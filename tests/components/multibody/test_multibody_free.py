"""Free bodies and spherical joints (quaternion orientation states) against MSL's FreeBody
reference and closed forms: a heavy symmetric top's steady precession, a torque-free
asymmetric body turning about its intermediate axis (Dzhanibekov) conserving energy and
angular momentum through many flips, and Lagrange's equations of a free body in its
quasi-velocities (Newton–Euler by hand)."""
from __future__ import annotations

import casadi as ca
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal import frames
from acausal.components.multibody import Body, FreeMotion, GravityTypes, Spherical, World
from acausal.core import Model
from acausal.models.multibody_forces import FreeBody
from heavy_top import OMEGA, heavy_top


def test_free_body_matches_the_msl_reference(reference_result):
    ref = reference_result("MAP-LIB_ReferenceResults",
                           "Modelica.Mechanics.MultiBody.Examples.Elementary.FreeBody")
    compiled = acausal.compile(FreeBody())
    assert len(compiled.x_names) == 13                  # r_0, Q, v_0, w_a
    t = ref["time"]
    res = compiled.simulate(float(t[-1]), t=t, rtol=1e-9, atol=1e-11)
    for name, values in ref.items():
        if name == "time":
            continue
        ours = res[name.replace("body.body.frame_a.", "body.frame_a.")]
        assert np.max(np.abs(ours - values)) <= 2e-3 * np.max(np.abs(values)) + 1e-12, name


def test_heavy_symmetric_top_precesses_steadily_at_the_closed_form_rate():
    """The heavy symmetric top in steady precession (tests/heavy_top.py): its axis turns
    about z at the rate Ω with constant tilt."""
    m, expected = heavy_top()
    t = np.linspace(0, 3 * 2 * np.pi / OMEGA, 601)
    res = acausal.compile(m).simulate(t[-1], t=t, rtol=1e-11, atol=1e-13)
    axis = np.array([res[f"top.frame_a.R.T[3,{j}]"] for j in (1, 2, 3)])
    assert np.max(np.abs(axis - expected(t))) < 1e-7
    # a spherical joint transmits no torque: MSL's frame_b.t = 0
    assert max(np.max(np.abs(res[f"joint.frame_b.t[{k}]"])) for k in (1, 2, 3)) < 1e-10


@pytest.mark.parametrize("angles_start", [(0.0, 0.0, 0.0), (0.3, np.pi / 2, -0.4)],
                         ids=["upright", "gimbal-lock-of-1-2-3"])
def test_torque_free_body_about_its_intermediate_axis_conserves_energy_and_momentum(
        angles_start):
    """Dzhanibekov's effect: a free body (no joint, no gravity) with inertias 1, 2, 3 kg.m²
    spun about its intermediate axis flips over and over (29 times in 200 s). Energy
    ½wᵀIw and the angular momentum in the world Tᵀ·I·w stay constant to 1e-9 (relative),
    the quaternion's norm at 1, and w equals the solution of Euler's equations
    I·ẇ + w × I·w = 0 (scipy DOP853); the same when the start orientation is the gimbal
    lock of the 1-2-3 angle sequence (no state is singular there)."""
    I = np.diag([1.0, 2.0, 3.0])
    w_a0 = np.array([0.01, 3.0, 0.02])
    T0 = np.array(ca.evalf(frames.axes_rotations((1, 2, 3), angles_start)))
    m = Model("dzhanibekov")
    m.world = World(gravityType=GravityTypes.NoGravity)
    m.body = Body(m=1.0, r_CM=(0, 0, 0), I_11=1, I_22=2, I_33=3, v_0_start=(0.1, 0, 0),
                  angles_start=angles_start, w_0_start=tuple(T0.T @ w_a0))
    t = np.linspace(0, 200.0, 4001)
    res = acausal.compile(m).simulate(t[-1], t=t, rtol=1e-12, atol=1e-14)
    w = np.array([res[f"body.w_a[{i}]"] for i in (1, 2, 3)])
    T = np.array([[res[f"body.frame_a.R.T[{i},{j}]"] for j in (1, 2, 3)] for i in (1, 2, 3)])
    E = 0.5 * np.einsum("it,ij,jt->t", w, I, w)
    L = np.einsum("jit,jk,kt->it", T, I, w)
    Q = np.array([res[f"body.Q[{i}]"] for i in (1, 2, 3, 4)])
    assert np.sum(np.diff(np.sign(w[1])) != 0) >= 20
    assert np.max(np.abs(E / E[0] - 1)) < 1e-9
    assert np.max(np.abs(L - L[:, :1])) < 1e-9 * np.linalg.norm(L[:, 0])
    assert np.max(np.abs(np.linalg.norm(Q, axis=0) - 1)) < 1e-9
    def euler_equations(_, x):                  # I·ẇ = (I·w) × w, I diagonal
        return [(2 - 3) * x[1] * x[2] / 1, (3 - 1) * x[2] * x[0] / 2, (1 - 2) * x[0] * x[1] / 3]

    euler = solve_ivp(euler_equations, (0, t[-1]), w_a0,
                      method="DOP853", rtol=1e-12, atol=1e-14, t_eval=t)
    assert np.max(np.abs(euler.y - w)) < 1e-7
    assert np.max(np.abs(res["body.v_0[1]"] - 0.1)) < 1e-12


def test_lagrange_of_a_free_body_is_newton_euler_in_its_quasi_velocities():
    """compiled.lagrange of a free Body, in (v_0 world, w_a): M = [[m·1, −m·Tᵀ[r_CM×]],
    [m·[r_CM×]·T, I + m·[r_CM×]ᵀ[r_CM×]]], gravity = (m·g, r_CM × T·m·g), coriolis =
    (−m·Tᵀ(w × (w × r_CM)), −w × I_O·w) with I_O the inertia about frame_a, at a random
    orientation Q and angular velocity (hand-written Newton–Euler)."""
    rng = np.random.default_rng(3)
    mass, r_CM = 1.7, rng.uniform(-0.3, 0.3, 3)
    A = rng.normal(size=(3, 3))
    I = A @ A.T + 0.1 * np.eye(3)
    m = Model("free")
    m.world = World(n=(0, 0, -1), g=9.81)
    m.body = Body(m=mass, r_CM=tuple(r_CM), I_11=I[0, 0], I_22=I[1, 1], I_33=I[2, 2],
                  I_21=I[1, 0], I_31=I[2, 0], I_32=I[2, 1])
    compiled = acausal.compile(m)
    L = compiled.lagrange
    assert L.q_names[3:] == ["body.theta[1]", "body.theta[2]", "body.theta[3]"]
    assert L.q_state_names[3:] == ["body.Q[1]", "body.Q[2]", "body.Q[3]", "body.Q[4]"]
    Q = rng.normal(size=4)
    Q /= np.linalg.norm(Q)
    v0, w = rng.normal(size=3), rng.normal(size=3)
    M, grav, cor = (np.array(x) for x in L.function("M", "gravity", "coriolis")(
        0.0, np.concatenate([rng.normal(size=3), Q]), np.concatenate([v0, w]), [],
        compiled.param_vector()))
    T = np.array(ca.evalf(frames.from_Q(Q)))
    S = np.array(ca.evalf(frames.skew(r_CM)))
    I_O = I + mass * S.T @ S
    M_hand = np.block([[mass * np.eye(3), -mass * T.T @ S], [mass * S @ T, I_O]])
    g = np.array([0, 0, -9.81])
    grav_hand = np.concatenate([mass * g, np.cross(r_CM, T @ (mass * g))])
    cor_hand = np.concatenate([-mass * T.T @ np.cross(w, np.cross(w, r_CM)),
                               -np.cross(w, I_O @ w)])
    assert np.max(np.abs(M - M_hand)) < 1e-12
    assert np.max(np.abs(grav.ravel() - grav_hand)) < 1e-12
    assert np.max(np.abs(cor.ravel() - cor_hand)) < 1e-12


def test_free_motion_records_msl_s_variables_and_transmits_nothing():
    """A FreeMotion from the World to a Body under gravity: the body falls freely with the
    start values given (r_rel_a, v_rel_a, angles, w_rel_a resolved in frame_a: MSL's
    w_rel_b start = R_rel_start·w_rel_a_start); frame_a.f = frame_a.t = 0 (MSL); a_rel_a =
    der(v_rel_a) and the centre of mass falls with g (hand formula); phi are the angles of
    the sequence sequence_angleStates: axesRotations(sequence, phi) equals frame_b's R.T all
    along, and phi equals angles_start at the start when the sequences agree."""
    angles, w_a = (0.1, 0.2, 0.3), np.array([1.0, 2.0, 0.5])
    r_CM = np.array([0.1, 0.2, 0.0])
    m = Model("fm")
    m.world = World()
    m.free = FreeMotion(r_rel_a_start=(1, 2, 3), v_rel_a_start=(0.5, 0, 0),
                        angles_start=angles, w_rel_a_start=tuple(w_a),
                        sequence_angleStates=(3, 1, 3))
    m.body = Body(m=1.0, r_CM=tuple(r_CM), I_11=0.1, I_22=0.2, I_33=0.3,
                  sequence_angleStates=(1, 2, 3))
    m.connect(m.world.frame_b, m.free.frame_a)
    m.connect(m.free.frame_b, m.body.frame_a)
    t = np.linspace(0, 1, 1001)
    res = acausal.compile(m).simulate(1.0, t=t, rtol=1e-11, atol=1e-13)
    T0 = np.array(ca.evalf(frames.axes_rotations((1, 2, 3), angles)))
    assert np.allclose([res[f"free.w_rel_b[{k}]"][0] for k in (1, 2, 3)], T0 @ w_a,
                       atol=1e-12)
    assert np.allclose([res[f"body.phi[{k}]"][0] for k in (1, 2, 3)], angles, atol=1e-12)
    for k in (1, 2, 3):
        assert np.max(np.abs(res[f"free.frame_a.f[{k}]"])) < 1e-10
        assert np.max(np.abs(res[f"free.frame_a.t[{k}]"])) < 1e-10
        v = res[f"free.v_rel_a[{k}]"]
        assert np.max(np.abs(np.gradient(v, t)[2:-2] - res[f"free.a_rel_a[{k}]"][2:-2])) < 1e-4
    T = np.array([[res[f"body.frame_a.R.T[{i},{j}]"] for j in (1, 2, 3)] for i in (1, 2, 3)])
    r0 = np.array([res[f"body.frame_a.r_0[{k}]"] for k in (1, 2, 3)])
    r_cm = r0 + np.einsum("jit,j->it", T, r_CM)
    v_cm0 = np.array([0.5, 0, 0]) + T0.T @ np.cross(T0 @ w_a, r_CM)
    expected = r_cm[:, :1] + np.outer(v_cm0, t) + np.outer([0, -9.80665 / 2, 0], t * t)
    assert np.max(np.abs(r_cm - expected)) < 1e-9
    phi = np.array([res[f"free.phi[{k}]"] for k in (1, 2, 3)])
    for k in range(0, len(t), 100):
        R = np.array(ca.evalf(frames.axes_rotations((3, 1, 3), phi[:, k])))
        assert np.max(np.abs(R - T[:, :, k])) < 1e-12


def test_bad_rotation_sequences_are_refused_naming_the_parameter():
    from acausal.errors import ParameterError
    with pytest.raises(ParameterError, match="sequence_start = \\(1.0, 1.0, 2.0\\)"):
        Spherical(sequence_start=(1, 1, 2))
    with pytest.raises(ParameterError, match="sequence_angleStates"):
        Body(m=1.0, r_CM=(0, 0, 0), sequence_angleStates=(1, 2, 4))
