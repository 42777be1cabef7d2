"""Kinematic analysis, inverse and mixed dynamics (issue 4), against references that do not
come from the code under test:
- the four-bar driven by an exact Position source: the rocker and coupler angles, rates and
  accelerations against the loop solved here in closed form (circle intersection; CasADi's AD
  only as a calculator for the time derivatives of the hand-written geometry);
- inverse dynamics: the drive torque against the power balance T θ̇ = Σ (m a·v + I α ω) +
  Σ m g v_y of the hand-written motion; the reaction at the joint that closes the loop
  against the rocker's moment balance about its pivot, I_D α = r × F + r_G × m g;
- a 1-D inertia driven by an exact Speed source (a non-mechanical state integrated): angle
  and torque against φ = ∫w, τ = J ẇ;
- mixed dynamics: the four-bar simulated under a known crank torque T0 sin(ωt) through an
  Input; the simulated crank (or rocker) motion prescribed, the torque recovered to 1e-6
  relative;
- a mechanism with free coordinates, mismatched motions/unknowns and velocity-level motions
  are refused with errors naming the parts.
"""
from __future__ import annotations

import math
import warnings

import casadi as ca
import numpy as np
import pytest

import acausal as ac
from acausal.analysis import (AnalysisError, inverse_dynamics, kinematic_analysis,
                              mixed_dynamics)
from acausal.components import rotational as rot
from acausal.components import signals as sig
from acausal.models.linkages import FOUR_BAR_LENGTHS, FOUR_BAR_MASSES, DrivenFourBar, FourBar

L0, L1, L2, L3 = FOUR_BAR_LENGTHS            # m: ground, crank, coupler, rocker
M1, M2, M3 = FOUR_BAR_MASSES                 # kg
GUESS = {"rev2.phi": -0.5, "rev3.phi": 1.6}  # rad: the assembly branch (rocker up)
G = 9.81
T_GRID = np.linspace(0.0, 2.0, 81)


@pytest.fixture(scope="module")
def driven():
    return ac.compile(DrivenFourBar("position"))


@pytest.fixture(scope="module")
def torque_driven():
    return ac.compile(DrivenFourBar("torque"))


def hand_motion():
    """Hand-written four-bar driven as phi_ref(t): (t, list of (name, expression of t))."""
    t = ca.SX.sym("t")
    th = 1.0 + 2.0 * t + 0.3 * ca.sin(ca.pi * t)
    B = ca.vertcat(L1 * ca.cos(th), L1 * ca.sin(th))
    D = ca.DM([L0, 0.0])
    d = ca.norm_2(D - B)
    a = (L2 ** 2 - L3 ** 2 + d ** 2) / (2 * d)
    h = ca.sqrt(L2 ** 2 - a ** 2)
    e = (D - B) / d
    C = B + a * e + h * ca.vertcat(-e[1], e[0])          # the branch with the rocker up
    beta = ca.atan2(C[1] - B[1], C[0] - B[0])             # coupler angle
    psi = ca.atan2(C[1] - D[1], C[0] - D[0])              # rocker angle
    return t, th, B, C, beta, psi


def rates(ex, t):
    d1 = ca.jacobian(ex, t)
    return ca.Function("r", [t], [ex, d1, ca.jacobian(d1, t)])


def test_four_bar_kinematics_against_closed_form(driven):
    res = kinematic_analysis(driven, T_GRID, guess=GUESS)
    t, th, B, C, beta, psi = hand_motion()
    for name, ex in (("rev3", psi), ("coupler", beta)):
        f = rates(ex, t).map(T_GRID.size)
        ref = [np.array(v).ravel() for v in f(T_GRID.reshape(1, -1))]
        if name == "rev3":
            got = [res["rev3.phi"], res["rev3.w"], res["rev3.z"]]
        else:
            got = [res["coupler.phi"], res["coupler.w"], res["coupler.z"]]
        for g, r in zip(got, ref):
            np.testing.assert_allclose(g, r, rtol=1e-9, atol=1e-9)
    Cf = ca.Function("C", [t], [C]).map(T_GRID.size)(T_GRID.reshape(1, -1))
    np.testing.assert_allclose(res["rev4.frame_a.x"], np.array(Cf[0, :]).ravel(), atol=1e-11)
    np.testing.assert_allclose(res["rev4.frame_b.y"], np.array(Cf[1, :]).ravel(), atol=1e-11)


def hand_drive_torque(grid):
    """The crank torque of the hand-written motion by the power balance [N.m]."""
    t, th, B, C, beta, psi = hand_motion()
    D = ca.DM([L0, 0.0])
    bodies = [(M1, M1 * L1 ** 2 / 12, B / 2, th), (M2, M2 * L2 ** 2 / 12, (B + C) / 2, beta),
              (M3, M3 * L3 ** 2 / 12, (C + D) / 2, psi)]
    power = 0
    for m, I, r, ang in bodies:
        v, w = ca.jacobian(r, t), ca.jacobian(ang, t)
        acc, alpha = ca.jacobian(v, t), ca.jacobian(w, t)
        power += m * ca.dot(acc, v) + I * alpha * w + m * G * v[1]
    torque = ca.Function("T", [t], [power / ca.jacobian(th, t)]).map(grid.size)
    return np.array(torque(grid.reshape(1, -1))).ravel()


def test_inverse_dynamics_drive_torque_and_reaction(driven):
    res = inverse_dynamics(driven, T_GRID, guess=GUESS)
    assert set(res.drivers) == {"rev1.axis.tau", "drive.flange.tau"}
    np.testing.assert_allclose(res.drivers["rev1.axis.tau"], res["rev1.t"], atol=1e-14)
    ref = hand_drive_torque(T_GRID)
    t, th, B, C, beta, psi = hand_motion()
    np.testing.assert_allclose(res["rev1.t"], ref, rtol=1e-9, atol=1e-9 * np.abs(ref).max())
    # rocker about D: I_D α = (C − D) × F_C + (C − D)/2 × (0, −m g), F_C = −rev4.frame_b.f
    alpha = np.array(rates(psi, t).map(T_GRID.size)(T_GRID.reshape(1, -1))[2]).ravel()
    rx, ry = res["rev4.frame_b.x"] - L0, res["rev4.frame_b.y"]
    Fx, Fy = -res["rev4.frame_b.fx"], -res["rev4.frame_b.fy"]
    moment = rx * Fy - ry * Fx - rx / 2 * M3 * G
    np.testing.assert_allclose(moment, M3 * L3 ** 2 / 3 * alpha, atol=1e-9)


def test_speed_driven_inertia_integrates_the_source_angle():
    md = ac.Model("spin")
    md.inertia, md.drive = rot.Inertia(J=2.0), rot.Speed(exact=True)
    md.ref = sig.Sine(amplitude=1.0, f=1 / math.pi, offset=3.0)     # w = 3 + sin(2t)
    md.connect(md.ref.y, md.drive.w_ref)
    md.connect(md.drive.flange, md.inertia.flange_a)
    t = np.linspace(0.0, 1.0, 11)
    res = inverse_dynamics(ac.compile(md), t)
    np.testing.assert_allclose(res["inertia.phi"], 3 * t - np.cos(2 * t) / 2 + 0.5, atol=1e-9)
    np.testing.assert_allclose(res["inertia.w"], 3 + np.sin(2 * t), atol=1e-12)
    # the source's flange carries the reaction of J ẇ (flow into the source: −J ẇ)
    np.testing.assert_allclose(res.drivers["drive.flange.tau"], -2.0 * 2 * np.cos(2 * t),
                               atol=1e-12)


T0, OMEGA = 2.0, 3.0


@pytest.fixture(scope="module")
def forward_run(torque_driven):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return torque_driven.simulate(2.0, t=T_GRID, inputs={"T": lambda s: T0 * np.sin(OMEGA * s)},
                                      x0={"rev1.phi": 1.0, "rev1.w": 2.0}, guess=GUESS,
                                      rtol=1e-11, atol=1e-12)


@pytest.mark.parametrize("joint", ["rev1", "rev3"])
def test_mixed_dynamics_recovers_the_applied_torque(torque_driven, forward_run, joint):
    sim = forward_run
    motion = {f"{joint}.phi": (T_GRID, sim[f"{joint}.phi"], sim[f"{joint}.w"], sim[f"{joint}.z"])}
    res = mixed_dynamics(torque_driven, T_GRID, motion, ["T"], guess={"rev1.phi": 1.0, **GUESS})
    applied = T0 * np.sin(OMEGA * T_GRID)
    assert np.max(np.abs(res.drivers["T"] - applied)) / T0 < 1e-6
    # the whole motion is the simulated one: a coordinate that was not prescribed
    other = "rev3.phi" if joint == "rev1" else "rev1.phi"
    np.testing.assert_allclose(res[other], sim[other], atol=1e-8)


def test_mixed_dynamics_with_a_function_of_time(torque_driven):
    """The crank angle given as a function of time (rates by AD): the torque Input T is the
    power-balance torque of the hand-written motion."""
    res = mixed_dynamics(torque_driven, T_GRID,
                         {"rev1.phi": lambda s: 1.0 + 2.0 * s + 0.3 * np.sin(np.pi * s)},
                         ["T"], guess=GUESS)
    ref = hand_drive_torque(T_GRID)
    np.testing.assert_allclose(res.drivers["T"], ref, rtol=1e-9, atol=1e-9 * np.abs(ref).max())


def test_refusals_name_the_parts(torque_driven):
    with pytest.raises(ac.StructureError, match="not fully driven"):
        kinematic_analysis(ac.compile(FourBar()), T_GRID[:3])
    with pytest.raises(AnalysisError, match="as many of each"):
        mixed_dynamics(torque_driven, T_GRID[:3], {"rev1.phi": 1.0}, [])
    with pytest.raises(AnalysisError, match="velocities"):
        mixed_dynamics(torque_driven, T_GRID[:3], {"rev1.w": 1.0}, ["T"])
    with pytest.raises(AnalysisError, match="no input 'F'"):
        mixed_dynamics(torque_driven, T_GRID[:3], {"rev1.phi": 1.0}, ["F"])
