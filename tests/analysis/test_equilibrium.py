"""Static equilibrium (issue 4), against references that do not come from the code under
test:
- a pendulum on a torsion spring with a torque input: the angle solves
  c φ + m g l cos φ = T (scipy's brentq), and the linearization there has the closed-form
  frequency ω² = (c − m g l sin φ) / J;
- a 3-mass spring chain under a force: the deflections solve K s = F e_3 (numpy);
- a four-bar hanging under gravity: the crank angle minimizes the potential energy computed
  here from the loop geometry (circle intersection, scipy's minimize_scalar), and the loop
  multipliers satisfy the rocker's moment balance about its ground pivot;
- no equilibrium (a torque above m g l, a pushed free mass): an AnalysisError naming the
  rate equation that does not vanish.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq, minimize_scalar

import acausal as ac
from acausal.analysis import AnalysisError, equilibrium, linearize
from acausal.components import rotational as rot
from acausal.components import translational as tr
from acausal.components.planar import Body, Fixed, FixedTranslation, Revolute, World
from acausal.models.linkages import FOUR_BAR_LENGTHS, FOUR_BAR_MASSES, FourBar

L0, L1, L2, L3 = FOUR_BAR_LENGTHS            # m: ground, crank, coupler, rocker
M1, M2, M3 = FOUR_BAR_MASSES                 # kg
G = 9.81
PM, PL, PI, PC = 0.7, 0.4, 0.02, 2.0            # kg, m, kg.m², N.m/rad


def spring_pendulum(c=PC, with_spring=True):
    md = ac.Model("spring_pendulum")
    md.world, md.fixed = World(), Fixed()
    md.rev = Revolute(useFlange=True)
    md.bar, md.body = FixedTranslation(r=(PL, 0.0)), Body(m=PM, I=PI)
    md.ground = rot.Fixed()
    md.T, md.torque = ac.Input(unit="N.m"), rot.Torque()
    md.connect(md.fixed.frame, md.rev.frame_a)
    md.connect(md.rev.frame_b, md.bar.frame_a)
    md.connect(md.bar.frame_b, md.body.frame_a)
    if with_spring:
        md.spring = rot.Spring(c=c)
        md.connect(md.ground.flange, md.spring.flange_a)
        md.connect(md.spring.flange_b, md.rev.axis)
    md.connect(md.T.y, md.torque.tau)
    md.connect(md.torque.flange, md.rev.axis)
    return ac.compile(md)


def test_spring_pendulum_angle_and_frequency():
    c = spring_pendulum()
    T = 0.5
    eq = equilibrium(c, u={"T": T}, guess={"rev.phi": -1.0})
    ref = brentq(lambda f: PC * f + PM * G * PL * math.cos(f) - T, -2.0, 0.0)
    assert abs(eq["rev.phi"] - ref) < 1e-10
    assert abs(eq["rev.w"]) < 1e-12 and eq.residual < 1e-10
    J = PI + PM * PL ** 2
    w2 = (PC - PM * G * PL * math.sin(ref)) / J
    ev = linearize(c, eq).eigenvalues()
    np.testing.assert_allclose(ev, [-1j * math.sqrt(w2), 1j * math.sqrt(w2)], rtol=1e-10)


def test_three_mass_chain_static_deflection():
    md = ac.Model("chain3")
    md.fixed = tr.Fixed()
    ks, prev = [300.0, 100.0, 200.0], None
    prev = md.fixed.flange
    for i, k in enumerate(ks, 1):
        s, m = tr.Spring(c=k), tr.Mass(m=1.0)
        setattr(md, f"s{i}", s)
        setattr(md, f"m{i}", m)
        md.connect(prev, s.flange_a)
        md.connect(s.flange_b, m.flange_a)
        prev = m.flange_b
    md.F, md.force = ac.Input(), tr.Force()
    md.connect(md.F.y, md.force.f)
    md.connect(md.force.flange, prev)
    c = ac.compile(md)
    eq = equilibrium(c, u={"F": 12.0})
    K = np.array([[400.0, -100.0, 0.0], [-100.0, 300.0, -200.0], [0.0, -200.0, 200.0]])
    ref = np.linalg.solve(K, [0.0, 0.0, 12.0])
    np.testing.assert_allclose([eq[f"m{i}.s"] for i in (1, 2, 3)], ref, rtol=1e-12)


def four_bar_geometry(theta):
    """Hand-written loop closure: B on the crank, C where the coupler (from B) meets the
    rocker (from D), on the branch below the ground line."""
    B = L1 * np.array([math.cos(theta), math.sin(theta)])
    D = np.array([L0, 0.0])
    d = np.linalg.norm(D - B)
    a = (L2 ** 2 - L3 ** 2 + d ** 2) / (2 * d)
    h = math.sqrt(L2 ** 2 - a ** 2)
    e = (D - B) / d
    C = B + a * e + h * np.array([e[1], -e[0]])
    return B, C


def four_bar_potential(theta):
    B, C = four_bar_geometry(theta)
    return G * (M1 * B[1] / 2 + M2 * (B[1] + C[1]) / 2 + M3 * C[1] / 2)


def test_four_bar_hanging_minimizes_potential_and_balances_moments():
    c = ac.compile(FourBar())
    eq = equilibrium(c, guess={"rev1.phi": -1.5, "rev2.phi": 1.0, "rev3.phi": -1.5})
    ref = minimize_scalar(four_bar_potential, bounds=(-2.0, -1.0), method="bounded",
                          options={"xatol": 1e-12}).x
    assert abs(eq["rev1.phi"] - ref) < 1e-7          # (a minimum: V is flat to 2nd order)
    _, C = four_bar_geometry(eq["rev1.phi"])
    np.testing.assert_allclose([eq["rev4.frame_b.x"], eq["rev4.frame_b.y"]], C, atol=1e-12)
    # rocker D–C at rest: the force of the coupler at C (−λ, λ the loop multiplier of
    # Φ = C_rocker − C_coupler) and its weight at mid-length have no moment about D
    lam = np.array([eq.multipliers["rev4.x"], eq.multipliers["rev4.y"]])
    r = C - np.array([L0, 0.0])
    moment = r[0] * (-lam[1]) - r[1] * (-lam[0]) + (r[0] / 2) * (-M3 * G)
    assert abs(moment) < 1e-10
    # the same force as the recorded reaction at the joint that closes the loop
    np.testing.assert_allclose([eq["rev4.frame_b.fx"], eq["rev4.frame_b.fy"]], lam, atol=1e-10)


def test_no_equilibrium_names_the_residual():
    c = spring_pendulum(with_spring=False)
    with pytest.raises(AnalysisError, match=r"d\(rev.w\)/dt"):
        equilibrium(c, u={"T": 1.2 * PM * G * PL})
    md = ac.Model("pushed")
    md.mass, md.F, md.force = tr.Mass(m=2.0), ac.Input(start=1.0), tr.Force()
    md.connect(md.F.y, md.force.f)
    md.connect(md.force.flange, md.mass.flange_a)
    with pytest.raises(AnalysisError, match=r"d\(mass.v\)/dt = 0.5"):
        equilibrium(ac.compile(md))


def test_solver_settings_are_checked():
    c = spring_pendulum(with_spring=True)
    with pytest.raises(AnalysisError, match="tol must be a finite number > 0"):
        equilibrium(c, tol=-1.0)
    with pytest.raises(AnalysisError, match="max_iter must be a whole number >= 1"):
        equilibrium(c, max_iter=0)


def test_stiff_chain_equilibrium_is_found():
    """wall | c1 = 1e9 N/m | m1 = 1 mg | c2 = 1 N/m | m2 = 1 kg | constant force F = 1 N:
    s1 = F/c1, s2 = s1 + F/c2. The accelerations' residual scales with c/m = 1e12, so an
    absolute tolerance on them could not be met; the scaled one is."""
    m = ac.Model("stiff_chain")
    m.wall, m.s1, m.m1 = tr.Fixed(), tr.Spring(c=1e9), tr.Mass(m=1e-6)
    m.s2, m.m2, m.push = tr.Spring(c=1.0), tr.Mass(m=1.0), tr.ConstantForce(f_constant=1.0)
    for a, b in [(m.wall.flange, m.s1.flange_a), (m.s1.flange_b, m.m1.flange_a),
                 (m.m1.flange_b, m.s2.flange_a), (m.s2.flange_b, m.m2.flange_a),
                 (m.m2.flange_b, m.push.flange)]:
        m.connect(a, b)
    eq = equilibrium(ac.compile(m))
    assert abs(eq["m1.s"] - 1e-9) < 1e-18
    assert abs(eq["m2.s"] - (1.0 + 1e-9)) < 1e-12
