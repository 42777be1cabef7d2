"""MSL's JointUPS (universal - prismatic - spherical assembly) in MSL's example
LineForceWithTwoMasses (two point masses on a damped line force between a pendulum and the
world) against the same mechanism's Lagrangian written by hand, and in a spatial version
against the universal joint's geometry and the energy balance."""
from __future__ import annotations

import casadi as ca
import numpy as np
from scipy.integrate import solve_ivp

import acausal
from acausal.components.multibody import (Body, BodyShape, FixedTranslation, JointUPS,
                                          Revolute, World)
from acausal.components.translational import Damper
from acausal.core import Model
from body_energy import G, body_energy, orientation, vector

TOL = dict(rtol=1e-10, atol=1e-12)
N_AXIS = np.array([0.7, 1.2, 0.0])
E_AXIS = N_AXIS / np.linalg.norm(N_AXIS)
BOX = dict(m=2.0, I_33=0.1, I_11=0.05, I_22=0.07)         # the pendulum, CM at its middle


def _line_force_with_two_masses(d=3.0, n=(0, 0, 1), inertia=0.0):
    """MSL's Examples.Elementary.LineForceWithTwoMasses, its JointUPS half: a pendulum
    (revolute1 about n at {0, 0.3, 0}, a bar {0.7, 0, 0} m) whose tip is frame_b of a
    JointUPS from {0, −0.9, 0}; point masses of 1 kg (bodies with ``inertia`` [kg.m²], 0 in
    MSL) 0.2 m along the line from either end, on frame_ia and frame_ib; a damper d [N.s/m]
    between axis and bearing."""
    m = Model("lineForceWithTwoMasses")
    m.world = World()
    m.rod2, m.rod1 = FixedTranslation(r=(0, 0.3, 0)), FixedTranslation(r=(0, -0.9, 0))
    m.revolute1 = Revolute(n=n)
    m.bodyBox1 = BodyShape(r=(0.7, 0, 0), r_CM=(0.35, 0, 0), **BOX)
    m.jointUPS = JointUPS(nAxis_ia=tuple(N_AXIS))
    J = dict(I_11=inertia, I_22=2 * inertia, I_33=3 * inertia)
    m.body1 = Body(m=1.0, r_CM=tuple(0.2 * E_AXIS), **J)
    m.body2 = Body(m=1.0, r_CM=tuple(-0.2 * E_AXIS), **J)
    m.damper1 = Damper(d=d)
    for a, b in ((m.world.frame_b, m.rod2.frame_a), (m.world.frame_b, m.rod1.frame_a),
                 (m.rod2.frame_b, m.revolute1.frame_a), (m.revolute1.frame_b, m.bodyBox1.frame_a),
                 (m.bodyBox1.frame_b, m.jointUPS.frame_b), (m.rod1.frame_b, m.jointUPS.frame_a),
                 (m.jointUPS.frame_ia, m.body1.frame_a), (m.jointUPS.frame_ib, m.body2.frame_a),
                 (m.jointUPS.bearing, m.damper1.flange_a), (m.jointUPS.axis, m.damper1.flange_b)):
        m.connect(a, b)
    return m


def _by_hand(d):
    """The planar mechanism's equation of motion from its Lagrangian by hand: the tip P(φ)
    = {0, 0.3, 0} + Rz(φ)·{0.7, 0, 0}, the line from A = {0, −0.9, 0}, e = (P − A)/ℓ, point
    masses at A + 0.2e and P − 0.2e; the damper's force d·ℓ̇ against ℓ's growth."""
    q, qd = ca.SX.sym("q"), ca.SX.sym("qd")
    rot = ca.vertcat(ca.cos(q), ca.sin(q), 0)
    P = ca.vertcat(0, 0.3, 0) + 0.7 * rot
    A = ca.DM([0, -0.9, 0])
    ell = ca.norm_2(P - A)
    e = (P - A) / ell
    points = (A + 0.2 * e, P - 0.2 * e)
    vel = [ca.jacobian(p, q) * qd for p in points]
    I_o = BOX["I_33"] + BOX["m"] * 0.35 ** 2
    T = 0.5 * I_o * qd ** 2 + sum(0.5 * ca.dot(v, v) for v in vel)
    V = G * (BOX["m"] * 0.35 * ca.sin(q) + sum(p[1] for p in points))
    ell_dot = ca.jacobian(ell, q) * qd
    Q = -d * ell_dot * ca.jacobian(ell, q)
    L = T - V
    M = ca.jacobian(ca.jacobian(L, qd), qd)
    rhs = Q + ca.jacobian(L, q).T - ca.jacobian(ca.jacobian(L, qd), q) * qd
    f = ca.Function("f", [q, qd], [rhs / M])
    return lambda t, x: [x[1], float(f(x[0], x[1]))]


def test_joint_ups_line_force_with_two_masses_equals_the_lagrangian_by_hand():
    """MSL's example (JointUPS, 1 coordinate, no loop row) against the hand-written
    Lagrangian: the pendulum's angle to 1e-8 rad over MSL's 3 s; s = ℓ − s_offset and the
    damper's force f = −d·ṡ (MSL's axis.f) from the same run."""
    model = _line_force_with_two_masses()
    assert np.allclose(model.jointUPS.eAxis_ia, E_AXIS, rtol=0, atol=1e-15)
    compiled = acausal.compile(model)
    assert (compiled.coordinates, compiled.loop_rows) == (["revolute1.phi"], [])
    t = np.linspace(0.0, 3.0, 61)
    res = compiled.simulate(3.0, t=t, **TOL)
    ref = solve_ivp(_by_hand(3.0), (0, 3), [0.0, 0.0], t_eval=t, rtol=1e-12, atol=1e-12,
                    method="DOP853")
    assert np.max(np.abs(res["revolute1.phi"] - ref.y[0])) < 1e-8
    assert np.ptp(res["revolute1.phi"]) > 1.0
    P = np.stack([0.7 * np.cos(ref.y[0]), 0.3 + 0.7 * np.sin(ref.y[0])])
    ell = np.hypot(P[0], P[1] + 0.9)
    assert np.max(np.abs(res["jointUPS.s"] - ell)) < 1e-8
    ell_dot = (P[0] * -0.7 * np.sin(ref.y[0]) + (P[1] + 0.9) * 0.7 * np.cos(ref.y[0])) \
        * ref.y[1] / ell
    assert np.max(np.abs(res["jointUPS.f"] + 3.0 * ell_dot)) < 1e-6


def test_joint_ups_in_space_keeps_the_universal_joint_and_the_energy():
    """The pendulum turning about {0, 1, 1} swings frame_b out of the plane; the bodies on
    frame_ia and frame_ib have inertia. frame_ia is MSL's universal-joint frame: its axis
    nAxis_ia lies on the line from frame_a to frame_b, its axis 2 (n1_a × nAxis_ia) stays
    orthogonal to axis 1 (n1_a = {0, 0, 1} of the fixed frame_a), frame_ib is parallel to it
    at frame_b; without damper the energy (from the recorded motion of each body) is
    conserved to 1e-9 of its swing (at rtol 1e-12)."""
    res = acausal.compile(_line_force_with_two_masses(d=0.0, n=(0, 1, 1), inertia=0.01)
                          ).simulate(2.0, t=np.linspace(0, 2, 81), rtol=1e-12, atol=1e-14)

    T_ia, T_ib = orientation(res, "jointUPS.frame_ia"), orientation(res, "jointUPS.frame_ib")
    line = vector(res, "jointUPS.frame_b.r_0") - vector(res, "jointUPS.frame_a.r_0")
    assert np.ptp(line[:, 2]) > 0.3
    line /= np.linalg.norm(line, axis=1, keepdims=True)
    assert np.max(np.abs(np.einsum("kji,j->ki", T_ia, E_AXIS) - line)) < 1e-12
    e2_ia = np.cross([0, 0, 1], E_AXIS)
    assert np.max(np.abs(np.einsum("kji,j->ki", T_ia, e2_ia)[:, 2])) < 1e-12
    assert np.max(np.abs(T_ia - T_ib)) < 1e-12
    assert np.max(np.abs(vector(res, "jointUPS.frame_ib.r_0")
                         - vector(res, "jointUPS.frame_b.r_0"))) < 1e-12

    J = np.diag([0.01, 0.02, 0.03])
    parts = [body_energy(res, "bodyBox1", BOX["m"], (0.35, 0, 0),
                         np.diag([BOX["I_11"], BOX["I_22"], BOX["I_33"]]), "bodyBox1.body.w_a"),
             body_energy(res, "body1", 1.0, 0.2 * E_AXIS, J),
             body_energy(res, "body2", 1.0, -0.2 * E_AXIS, J)]
    kinetic, potential = (sum(p[i] for p in parts) for i in (0, 1))
    energy = kinetic + potential
    assert np.ptp(kinetic) > 1.0
    assert np.max(np.abs(energy - energy[0])) < 1e-9 * np.ptp(kinetic)
