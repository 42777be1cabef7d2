"""Closed kinematic loops of 3-D parts: MSL's Loops examples against their published
references, a spatial four-bar with parallel axes (over-constrained) against planar
kinematics and energy by hand, the loop-closing joints' rod forces against statics, and
the errors of loops that cannot close or become singular."""
from __future__ import annotations

import math
import warnings

import casadi as ca
import numpy as np
import pytest
from scipy.optimize import brentq

import acausal
from acausal.components.multibody import (Body, BodyShape, Fixed, FixedTranslation, JointRRR,
                                          JointSSP, JointSSR, Revolute, SphericalSpherical,
                                          UniversalSpherical, World)
from acausal.components.rotational import ConstantSpeed
from acausal.core import Model
from acausal.errors import InitializationError
from acausal.models.multibody_loops import (ENGINE_START, FOURBAR_START, EngineJointRRP,
                                            MultiBodyEngine1a, MultiBodyFourbar1,
                                            MultiBodyFourbar2, MultiBodyFourbarAnalytic,
                                            ParallelFourbar)

TOL = dict(rtol=1e-10, atol=1e-12)
G = 9.80665
LOOPS = "Modelica.Mechanics.MultiBody.Examples.Loops."
CASES = [  # model, MSL name, x0, guess, compared signals, (coordinates, loop rows, dof)
    (MultiBodyFourbar1, "Fourbar1", FOURBAR_START, {"j2.s": -0.2}, ("j1.phi", "j1.w"),
     (7, 6, 1)),
    (MultiBodyFourbar2, "Fourbar2", dict(FOURBAR_START, **{"j2.s": -0.2}), {},
     ("j1.phi", "j1.w"), (2, 1, 1)),
    (MultiBodyFourbarAnalytic, "Fourbar_analytic", FOURBAR_START, {}, ("j1.phi", "j1.w"),
     (1, 0, 1)),
    (MultiBodyEngine1a, "Engine1a", ENGINE_START, {"cylinder.s": 0.15},
     ("inertia.phi", "inertia.w"), (3, 2, 1)),
    (EngineJointRRP, "Engine1a", ENGINE_START, {}, ("inertia.phi", "inertia.w"), (1, 0, 1)),
]


@pytest.mark.parametrize("model, msl, x0, guess, signals, mobility", CASES,
                         ids=["Fourbar1", "Fourbar2", "Fourbar_analytic", "Engine1a",
                              "Engine1a_by_JointRRP"])
def test_msl_loop_examples_match_the_reference(reference_result, model, msl, x0, guess,
                                               signals, mobility):
    """Every compared signal within 2e-3 of its peak over the reference's 5 s; the loops
    close with the rows expected (Fourbar1: 7 joint coordinates, 6 rows at rev1; Fourbar2:
    1 row of the UniversalSpherical; Fourbar_analytic: none, JointSSP's closed form;
    Engine1a: RevolutePlanarLoopConstraint's 2 rows; the same engine closed by a JointRRP:
    none), 1 degree of freedom each."""
    ref = reference_result("MAP-LIB_ReferenceResults", LOOPS + msl)
    t = ref["time"]
    compiled = acausal.compile(model())
    nq, nc, dof = mobility
    assert (len(compiled.coordinates), len(compiled.loop_rows)) == (nq, nc)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")              # the start speeds moved onto the loop
        res = compiled.simulate(float(t[-1]), t=t, x0=x0, guess=guess, rtol=1e-9, atol=1e-11)
    if nc:
        assert (res.mobility.dof, res.mobility.redundant) == (dof, [])
    for name in signals:
        assert np.max(np.abs(res[name] - ref[name])) < 2e-3 * np.max(np.abs(ref[name])), name


def test_engine_with_a_plain_revolute_closing_its_planar_loop(reference_result):
    """Engine1a with b2 a Revolute instead of MSL's RevolutePlanarLoopConstraint: the loop
    closes at the cylinder's Prismatic with 6 rows, 3 of them redundant (found from the
    rank), and the engine still matches the Engine1a reference within 2e-3 of the peaks."""
    ref = reference_result("MAP-LIB_ReferenceResults", LOOPS + "Engine1a")
    compiled = acausal.compile(MultiBodyEngine1a(planarLoopConstraint=False))
    assert compiled.loop_rows[0].startswith("cylinder.")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = compiled.simulate(float(ref["time"][-1]), t=ref["time"], x0=ENGINE_START,
                                guess={"cylinder.s": 0.15}, rtol=1e-9, atol=1e-11)
    mob = res.mobility
    assert (mob.coordinates, mob.constraints, mob.gruebler, mob.dof) == (4, 6, -2, 1)
    assert len(mob.redundant) == 3
    for name in ("inertia.phi", "inertia.w"):
        assert np.max(np.abs(res[name] - ref[name])) < 2e-3 * np.max(np.abs(ref[name])), name


def _planar(angle, v):
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * v[0] - s * v[1], s * v[0] + c * v[1]], -1)


def test_spatial_fourbar_moves_with_one_degree_of_freedom_and_stays_closed():
    """A four-bar of 3-D parts with parallel revolute axes: Gruebler 3·6 − 4·5 = −2, yet 1
    degree of freedom; the 3 out-of-plane rows of the loop-closing joint are found
    redundant. Over 10 s of full crank turns the loop stays closed to 1e-9 (the chain
    j1–j2–j3 by planar kinematics of the recorded angles ends at j4's pivot, turned by
    j4's angle), and the energy by hand formulas (recorded r_0, v_0, body.w_a) stays at
    its start value to 1e-7 (3e-8 is the integrator's round-off plateau over these 10 s;
    1e-7 at rtol 1e-8)."""
    compiled = acausal.compile(ParallelFourbar())
    x0 = {"j1.phi": 0.0, "j1.w": 3.0}
    with pytest.warns(UserWarning) as caught:
        mob = compiled.mobility(x0=x0)
    assert any("redundant loop constraints" in str(w.message) for w in caught)
    assert (mob.coordinates, mob.constraints, mob.gruebler, mob.dof) == (4, 6, -2, 1)
    assert mob.redundant == ["j4.r_rel[3]", "j4.residue[1]", "j4.residue[2]"]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = compiled.simulate(10.0, x0=x0, **TOL)
    p1, p2, p3, p4 = (res[f"j{i}.phi"] for i in (1, 2, 3, 4))
    tip = _planar(p1, (0, 0.5)) + _planar(p1 + p2, (1.2, 0.2)) + _planar(p1 + p2 + p3,
                                                                          (0, -0.7))
    assert np.max(np.abs(tip - [1.2, 0.0])) < 1e-9
    assert np.max(np.abs(np.angle(np.exp(1j * (p1 + p2 + p3 - p4))))) < 1e-9
    assert np.ptp(p1) > 6 * 2 * math.pi                          # the crank turns round
    # Lagrange's Φ and Φ_q along the motion: 0, rank 3, the speeds in their null space
    f = compiled.lagrange.function("phi", "phi_q")
    p = compiled.param_vector()
    for k in range(0, len(res.t), 50):
        q = [res[n][k] for n in compiled.coordinates]
        qd = [res[n][k] for n in compiled.lagrange.qd_names]
        phi, J = (np.array(v, dtype=float) for v in f(res.t[k], q, qd, [], p))
        assert np.max(np.abs(phi)) < 1e-9 and np.linalg.matrix_rank(J, 1e-9) == 3
        assert np.max(np.abs(J @ qd)) < 1e-8
    E = 0.0
    for link, (r, m, I) in ParallelFourbar.LINKS.items():
        c = np.array(r) / 2
        r0 = np.stack([res[f"{link}.r_0[{i}]"] for i in (1, 2, 3)], -1)
        v0 = np.stack([res[f"{link}.v_0[{i}]"] for i in (1, 2, 3)], -1)
        w = res[f"{link}.body.w_a[3]"]
        ang = p1 + (p2 if link != "crank" else 0) + (p3 if link == "rocker" else 0)
        r_cm = r0[:, :2] + _planar(ang, c)
        v_cm = v0[:, :2] + w[:, None] * _planar(ang + math.pi / 2, c)
        E = E + 0.5 * m * np.sum(v_cm ** 2, 1) + 0.5 * I * w ** 2 + m * G * r_cm[:, 1]
    assert np.ptp(E) < 1e-7 * np.max(np.abs(E))


def test_revolute_planar_loop_constraint_cut_forces_are_msl_s():
    """Engine1a's RevolutePlanarLoopConstraint b2: MSL's cut forces: no torques at either
    frame, no force along the axis n = {1, 0, 0}, frame_b.f = −R_rel·frame_a.f (the frames
    turn about n by the angle between them); the force in the plane carries the engine
    (non-zero)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = acausal.compile(MultiBodyEngine1a()).simulate(
            0.5, x0=ENGINE_START, guess={"cylinder.s": 0.15}, **TOL)
    fa, fb = _vec(res, "b2.frame_a.f"), _vec(res, "b2.frame_b.f")
    for frame in ("frame_a", "frame_b"):
        assert np.max(np.abs(_vec(res, f"b2.{frame}.t"))) < 1e-9
    assert np.max(np.abs(fa[:, 0])) < 1e-9 * np.max(np.abs(fa))
    T = {k: np.stack([np.stack([res[f"b2.{k}.R.T[{i},{j}]"] for j in (1, 2, 3)], -1)
                      for i in (1, 2, 3)], -2) for k in ("frame_a", "frame_b")}
    R_rel = np.einsum("nij,nkj->nik", T["frame_b"], T["frame_a"])
    assert np.max(np.abs(fb + np.einsum("nij,nj->ni", R_rel, fa))) < 1e-9 * np.max(np.abs(fa))
    assert np.max(np.abs(fa)) > 10.0


def test_fixed_frame_on_the_world_frame_is_a_harmless_redundant_loop():
    """A Fixed at the origin connected to world.frame_b (rows no coordinate enters, and
    0 there): dropped with a warning, the pendulum on it moves as without it."""
    def pendulum(with_fixed):
        m = Model("pendulum")
        m.world, m.rev, m.body = World(), Revolute(), Body(m=1.0, r_CM=(0.5, 0, 0))
        m.connect(m.world.frame_b, m.rev.frame_a)
        m.connect(m.rev.frame_b, m.body.frame_a)
        if with_fixed:
            m.fixed = Fixed()
            m.connect(m.fixed.frame_b, m.world.frame_b)
        return m
    with pytest.warns(UserWarning, match="redundant loop constraints dropped.*fixed"):
        compiled = acausal.compile(pendulum(True))
    assert compiled.loop_rows == [] and len(compiled.loop_rows_dropped) == 6
    a = compiled.simulate(1.0, x0={"rev.phi": 0.3}, **TOL)
    b = acausal.compile(pendulum(False)).simulate(1.0, x0={"rev.phi": 0.3}, **TOL)
    assert np.max(np.abs(a["rev.phi"] - b["rev.phi"])) < 1e-12


def _held_bar(rod, rod_frame_at_tip):
    """A bar (Body m = 2 kg at 0.5 m, BodyShape to its tip at {1, 0, 0}) on a Revolute about
    z at the origin, held level by ``rod`` from its tip to a Fixed at {1, 1, 0}."""
    m = Model("held")
    m.world, m.rev = World(), Revolute()
    m.bar = BodyShape(r=(1, 0, 0), r_CM=(0.5, 0, 0), m=2.0)
    m.top, m.rod = Fixed(r=(1, 1, 0)), rod
    m.connect(m.world.frame_b, m.rev.frame_a)
    m.connect(m.rev.frame_b, m.bar.frame_a)
    tip, top = (rod.frame_a, rod.frame_b) if rod_frame_at_tip else (rod.frame_b, rod.frame_a)
    m.connect(m.bar.frame_b, tip)
    m.connect(m.top.frame_b, top)
    return m


@pytest.mark.parametrize("rod, at_tip, sign", [
    (SphericalSpherical(rodLength=1.0), True, -1.0),
    (SphericalSpherical(rodLength=1.0, m=0.8), True, -1.0),
    (UniversalSpherical(n1_a=(0, 0, 1), rRod_ia=(0, -1, 0)), False, -1.0),
], ids=["SphericalSpherical", "SphericalSpherical_mass", "UniversalSpherical"])
def test_loop_joint_rod_forces_are_the_statics(rod, at_tip, sign):
    """The bar held level stays at rest (it starts in equilibrium), and the rod carries
    half its weight, m·g/2 in tension whatever the rod's own mass (moments about the
    hinge): SphericalSpherical's f_rod (positive on frame_a, from frame_a to frame_b) and
    UniversalSpherical's (positive if pressed) are −m·g/2; the hinge's cut force carries the
    other half (whatever the rod's mass, which its top carries)."""
    m = _held_bar(rod, at_tip)
    res = acausal.compile(m).simulate(1.0, **TOL)
    assert np.max(np.abs(res["rev.phi"])) < 1e-10
    assert np.max(np.abs(res["rod.f_rod"] - sign * 2.0 * G / 2)) < 1e-8
    # the world holds the hinge up with the other half of the bar's weight
    assert np.max(np.abs(res["rev.frame_a.f[2]"] - 2.0 * G / 2)) < 1e-8


def test_rod_length_computed_at_initialization():
    """Fourbar2's UniversalSpherical has computeRodLength = true: the length comes from the
    configuration x0 fixes (j1.phi = 0, j2.s = −0.2 m: |{−1, 0.3, 0.1}| m) whatever the
    guess (rRod_ia twice as long, only its direction counts), and stays constant."""
    compiled = acausal.compile(MultiBodyFourbar2())
    params = {f"universalSpherical.rRod_ia[{k + 1}]": 2 * v
              for k, v in enumerate((-1, 0.3, 0.1))}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = compiled.simulate(1.0, x0=dict(FOURBAR_START, **{"j2.s": -0.2}), params=params,
                                **TOL)
    assert np.max(np.abs(res["universalSpherical.rodLength"] - math.sqrt(1.1))) < 1e-10


@pytest.mark.parametrize("rod", [SphericalSpherical(kinematicConstraint=False),
                                 UniversalSpherical(kinematicConstraint=False,
                                                    rRod_ia=(0, -1, 0))],
                         ids=["SphericalSpherical", "UniversalSpherical"])
def test_rod_without_kinematic_constraint_holds_nothing(rod):
    """kinematicConstraint = false (MSL's, for assemblies that hold the length otherwise):
    no constraint row, the bar falls as a compound pendulum, m·g·0.5·cos(φ) = (I + m·0.25)·φ̈
    at the start (I = 0.001 kg.m², Body's default about its centre)."""
    compiled = acausal.compile(_held_bar(rod, isinstance(rod, SphericalSpherical)))
    assert compiled.loop_rows == []
    res = compiled.simulate(0.01, t=np.linspace(0, 0.01, 3), **TOL)
    phi_dd = -2.0 * G * 0.5 / (0.001 + 2.0 * 0.25)
    assert abs(res["rev.phi"][-1] - phi_dd * 0.01 ** 2 / 2) < 1e-3 * abs(phi_dd) * 1e-4


def test_joint_ssp_equals_the_universal_spherical_four_bar():
    """Fourbar_analytic (JointSSP, closed form) and Fourbar2 (UniversalSpherical, one
    constraint row) are the same mechanism with a massless rod: the slider's distance and
    the rod force (JointSSP's f_rod, positive on frame_a from frame_a to frame_im, is the
    UniversalSpherical's, positive if pressed) agree over 2 s."""
    t = np.linspace(0.0, 2.0, 201)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        a = acausal.compile(MultiBodyFourbar2()).simulate(
            2.0, t=t, x0=dict(FOURBAR_START, **{"j2.s": -0.2}), **TOL)
    b = acausal.compile(MultiBodyFourbarAnalytic()).simulate(2.0, t=t, x0=FOURBAR_START, **TOL)
    assert np.max(np.abs(a["j2.s"] - b["jointSSP.prismatic.distance"])) < 1e-7
    f = a["universalSpherical.f_rod"]
    assert np.max(np.abs(f - b["jointSSP.f_rod"])) < 1e-6 * np.max(np.abs(f))
    assert np.max(np.abs(f)) > 10.0


def test_a_loop_that_cannot_close_names_its_joint():
    """The four-bar with its ground pivot out of reach (3 m > 0.5 + 1.22 + 0.7): the
    initialization fails naming the loop rows of the joint that closes the loop."""
    m = ParallelFourbar()
    m.ground.r = (3.0, 0.0, 0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        compiled = acausal.compile(m)
        with pytest.raises(InitializationError, match=r"loop constraint j4\.r_rel\[1\]"):
            compiled.simulate(1.0, x0={"j1.phi": 0.0})


def test_joint_ssp_stops_at_the_singular_position_of_its_loop():
    """A JointSSP whose rod (0.6 m) cannot reach the slider's axis beyond some crank angle,
    the crank driven at 1 rad/s: the run ends where the two roots of the closed form meet
    (rod perpendicular distance to the axis = rod length: 0.5cosφ − 0.1sinφ = −0.15),
    with MSL's message naming the joint."""
    m = Model("driven")
    m.world, m.j1 = World(), Revolute(n=(1, 0, 0), useAxisFlange=True)
    m.b1, m.b3 = FixedTranslation(r=(0, 0.5, 0.1)), FixedTranslation(r=(1.2, 0, 0))
    m.ssp = JointSSP(rod1Length=0.6, n_b=(1, 0, 0), rRod2_ib=(0, 0.2, 0))
    m.drive = ConstantSpeed(w_fixed=1.0, useSupport=True)
    for a, b in ((m.world.frame_b, m.j1.frame_a), (m.j1.frame_b, m.b1.frame_a),
                 (m.b1.frame_b, m.ssp.frame_a), (m.world.frame_b, m.b3.frame_a),
                 (m.b3.frame_b, m.ssp.frame_b), (m.drive.flange, m.j1.axis),
                 (m.drive.support, m.j1.support)):
        m.connect(a, b)
    res = acausal.compile(m).simulate(5.0, **TOL)
    phi = brentq(lambda p: 0.5 * math.cos(p) - 0.1 * math.sin(p) + 0.15, 0.5, 2.5)
    assert res.terminated is not None and "ssp: singular position of loop" in \
        res.terminated.message
    assert abs(res.t[-1] - phi) < 1e-6


def _vec(res, name):
    return np.stack([res[f"{name}[{i}]"] for i in (1, 2, 3)], -1)


def test_cut_forces_at_the_loop_closing_joint_are_newton_euler():
    """In Fourbar1 the loop closes at rev1, whose cut force and torque come from the loop's
    multipliers (mapped through the twist Jacobian of its 6 rows). With j5's (a tree
    joint's reaction) they move the rod b3 as MSL's BodyShape equations say: f_a + f_b =
    m(R(a_0 − g_0) + z×r_CM + w×(w×r_CM)), t_a + t_b + r×f_b = I·z + w×I·w + r_CM×(f_a +
    f_b), everything resolved in b3's frames (parallel), f_a = −rev1.frame_b.f, f_b =
    −j5.frame_b.f."""
    model = MultiBodyFourbar1()
    m, c, I = model.b3.mass_properties()             # MSL's formulas: tested elsewhere
    m, c, I = float(m), np.array(c, dtype=float).ravel(), np.array(ca.evalf(I), dtype=float)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = acausal.compile(model).simulate(1.0, x0=FOURBAR_START, guess={"j2.s": -0.2},
                                              **TOL)
    T = np.stack([np.stack([res[f"b3.frame_a.R.T[{i},{j}]"] for j in (1, 2, 3)], -1)
                  for i in (1, 2, 3)], -2)
    w, z = _vec(res, "b3.body.w_a"), _vec(res, "b3.body.z_a")
    a = np.einsum("nij,nj->ni", T, _vec(res, "b3.a_0") - _vec(res, "b3.body.g_0"))
    f = m * (a + np.cross(z, c) + np.cross(w, np.cross(w, c)))
    t = z @ I + np.cross(w, w @ I) + np.cross(c, f)
    fa, ta = -_vec(res, "rev1.frame_b.f"), -_vec(res, "rev1.frame_b.t")
    fb, tb = -_vec(res, "j5.frame_b.f"), -_vec(res, "j5.frame_b.t")
    assert np.max(np.abs(fa + fb - f)) < 1e-6 * np.max(np.abs(f))
    r = np.array([-1.0, 0.3, 0.1])
    assert np.max(np.abs(ta + tb + np.cross(r, fb) - t)) < 1e-6 * np.max(np.abs(t))
    assert np.max(np.abs(fa)) > 1.0                  # the loop's reaction carries load


def _crank_rocker(closing):
    """A crank (j1 about z, BodyShape to {0, 0.5, 0} m) and a rocker (BodyShape {0, 0.7, 0}
    m from the pivot at {1.2, 0, 0} m) joined by a rod of |{1.2, 0.2}| m with a 2 kg point
    mass in its middle: by a JointSSR (``closing`` "SSR", closed form) or by a Revolute j4
    at the pivot and a SphericalSpherical (one constraint row)."""
    L = math.hypot(1.2, 0.2)
    m = Model("crank_rocker")
    m.world, m.j1, m.ground = World(), Revolute(), FixedTranslation(r=(1.2, 0, 0))
    m.crank = BodyShape(r=(0, 0.5, 0), r_CM=(0, 0.25, 0), m=1.0, I_11=0.03, I_22=0.03,
                        I_33=0.03)
    m.rocker = BodyShape(r=(0, 0.7, 0), r_CM=(0, 0.35, 0), m=1.5, I_11=0.07, I_22=0.07,
                         I_33=0.07)
    m.connect(m.world.frame_b, m.j1.frame_a)
    m.connect(m.j1.frame_b, m.crank.frame_a)
    m.connect(m.world.frame_b, m.ground.frame_a)
    if closing == "SSR":
        m.rod = JointSSR(rod1Length=L, rod1Mass=2.0, rRod2_ib=(0, 0.7, 0),
                         positiveBranch=False)
        m.connect(m.crank.frame_b, m.rod.frame_a)
        m.connect(m.ground.frame_b, m.rod.frame_b)
        m.connect(m.rod.frame_ib, m.rocker.frame_a)
    else:
        m.j4, m.rod = Revolute(), SphericalSpherical(rodLength=L, m=2.0)
        m.connect(m.ground.frame_b, m.j4.frame_a)
        m.connect(m.j4.frame_b, m.rocker.frame_a)
        m.connect(m.crank.frame_b, m.rod.frame_a)
        m.connect(m.rocker.frame_b, m.rod.frame_b)
    return m


def test_joint_ssr_equals_the_loop_closed_by_a_spherical_spherical_rod():
    """The crank-rocker with a massive rod closed in closed form by JointSSR (1 coordinate,
    no row) moves as when closed by a SphericalSpherical (2 coordinates, 1 row): crank and
    rocker angles to 1e-6 rad, rod forces (both MSL's f_rod sign) to 1e-5 of their peak,
    over 3 s of full crank turns."""
    t = np.linspace(0.0, 3.0, 301)
    x0 = {"j1.phi": 0.0, "j1.w": 3.0}
    analytic = acausal.compile(_crank_rocker("SSR"))
    assert (analytic.coordinates, analytic.loop_rows) == (["j1.phi"], [])
    a = analytic.simulate(3.0, t=t, x0=x0, **TOL)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        b = acausal.compile(_crank_rocker("SS")).simulate(3.0, t=t, x0=x0, **TOL)
    assert np.max(np.abs(a["j1.phi"] - b["j1.phi"])) < 1e-6
    assert np.max(np.abs(a["rod.revolute.phi"] - b["j4.phi"])) < 1e-6
    f = b["rod.f_rod"]
    assert np.max(np.abs(a["rod.f_rod"] - f)) < 1e-5 * np.max(np.abs(f))
    assert np.ptp(a["j1.phi"]) > 2 * math.pi


def test_joint_rrr_equals_the_four_bar_closed_by_revolutes():
    """ParallelFourbar rebuilt with a JointRRR (rRod1_ia = the coupler, rRod2_ib = the
    rocker from its pivot; coupler and rocker bodies on frame_ia and frame_ib): 1
    coordinate and no row instead of 4 coordinates and 6 rows (3 redundant), the same
    motion: crank and rocker angles to 1e-6 rad, the coupler's angular velocity (its
    frame_ia orientation, MSL's universal-joint rod frame) to 1e-5 rad/s, over 3 s."""
    m = Model("rrr")
    m.world, m.j1, m.ground = World(), Revolute(), FixedTranslation(r=(1.2, 0, 0))
    for link, (r, mass, I) in ParallelFourbar.LINKS.items():
        r = (0, 0.7, 0) if link == "rocker" else r            # from the pivot, up
        setattr(m, link, BodyShape(r=r, r_CM=tuple(x / 2 for x in r), m=mass, I_11=I, I_22=I,
                                   I_33=I))
    m.rrr = JointRRR(rRod1_ia=(1.2, 0.2, 0), rRod2_ib=(0, 0.7, 0), positiveBranch=False)
    for a, b in ((m.world.frame_b, m.j1.frame_a), (m.j1.frame_b, m.crank.frame_a),
                 (m.world.frame_b, m.ground.frame_a), (m.crank.frame_b, m.rrr.frame_a),
                 (m.ground.frame_b, m.rrr.frame_b), (m.rrr.frame_ia, m.coupler.frame_a),
                 (m.rrr.frame_ib, m.rocker.frame_a)):
        m.connect(a, b)
    t = np.linspace(0.0, 3.0, 301)
    x0 = {"j1.phi": 0.0, "j1.w": 3.0}
    analytic = acausal.compile(m)
    assert (analytic.coordinates, analytic.loop_rows) == (["j1.phi"], [])
    a = analytic.simulate(3.0, t=t, x0=x0, **TOL)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        b = acausal.compile(ParallelFourbar()).simulate(3.0, t=t, x0=x0, **TOL)
    assert np.max(np.abs(a["j1.phi"] - b["j1.phi"])) < 1e-6
    assert np.max(np.abs(a["rrr.revolute.phi"] - b["j4.phi"])) < 1e-6
    assert np.max(np.abs(a["coupler.body.w_a[3]"] - b["coupler.body.w_a[3]"])) < 1e-5
    assert np.ptp(a["j1.phi"]) > 2 * math.pi
