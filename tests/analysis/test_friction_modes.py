"""Analyses of a model with discrete modes, at a given mode (stuck or sliding friction),
against hand-derived linear systems and equilibria.

Two masses on springs, the first on Coulomb friction (a translational SupportFriction,
sliding force f0, peak 1.5):

    wall ──k1── m1 (friction) ──k2── m2

- stuck (friction.mode = 0): the friction is a rigid lock, m1 stays put (two zero
  eigenvalues: its position and speed do not move) and m2 oscillates on k2 alone,
  λ = ±i·√(k2/m2);
- sliding (friction.mode = 1): the friction force is the constant f0 (its table is flat, so
  it adds nothing to the linear model): the free two-mass system, λ = ±i·ω with ω² the
  eigenvalues of M⁻¹K, M = diag(m1, m2), K = [[k1 + k2, −k2], [−k2, k2]].
The default mode is what simulate's event iteration finds at the point: at rest with the
springs relaxed, nothing loads the friction, so it is stuck.

A block pushed by F through nothing but a spring to the wall and friction: stuck, it rests
wherever it is put (the friction holds F − k·s, below peak·f0), nearest the guess; sliding
forward at v = 0, it rests where k·s = F − f0; backward where k·s = F + f0.
"""
import numpy as np
import pytest

import acausal
from acausal.analysis import equilibrium, linearize, modes
from acausal.components import translational as tr
from acausal.errors import AnalysisError

M1, M2, K1, K2, F0, PEAK = 2.0, 0.5, 300.0, 50.0, 3.0, 1.5
STUCK = {"friction.mode": 0, "friction.startForward": 0, "friction.startBackward": 0}


@pytest.fixture(scope="module")
def two_masses():
    m = acausal.Model("two_masses")
    m.wall = tr.Fixed()
    m.k1, m.k2 = tr.Spring(c=K1), tr.Spring(c=K2)
    m.m1, m.m2 = tr.Mass(m=M1), tr.Mass(m=M2)
    m.friction = tr.SupportFriction(f_pos=[[0.0, F0]], peak=PEAK)
    for a, b in [(m.wall.flange, m.k1.flange_a), (m.k1.flange_b, m.m1.flange_a),
                 (m.m1.flange_b, m.k2.flange_a), (m.k2.flange_b, m.m2.flange_a),
                 (m.m1.flange_a, m.friction.flange_a)]:
        m.connect(a, b)
    return acausal.compile(m)


def sorted_eigenvalues(values):
    values = np.asarray(values, dtype=complex)
    return values[np.lexsort((values.real.round(9), values.imag.round(9)))]


def test_stuck_friction_linearizes_as_a_rigid_lock(two_masses):
    x = {"m1.s": 0.0, "m1.v": 0.0, "m2.s": 0.0, "m2.v": 0.0}
    lin = linearize(two_masses, x, mode={"friction.mode": 0})
    assert lin.mode == STUCK and "in modes" in repr(lin) and "'friction.mode': 0" in repr(lin)
    w = np.sqrt(K2 / M2)
    want = sorted_eigenvalues([0, 0, 1j * w, -1j * w])
    np.testing.assert_allclose(sorted_eigenvalues(lin.eigenvalues()), want, atol=1e-9)
    i = lin.states.index("m1.v")
    assert np.abs(lin.A[i]).max() == 0.0                 # m1 does not accelerate
    # the default: the event iteration at the point, as simulate's start, finds it stuck
    default = linearize(two_masses, x)
    assert default.mode == STUCK
    np.testing.assert_allclose(default.A, lin.A, atol=0)


def test_sliding_friction_linearizes_as_the_free_system(two_masses):
    x = {"m1.s": 0.0, "m1.v": 0.0, "m2.s": 0.0, "m2.v": 0.0}
    lin = linearize(two_masses, x, mode={"friction.mode": 1})
    assert lin.mode["friction.mode"] == 1
    M = np.diag([M1, M2])
    K = np.array([[K1 + K2, -K2], [-K2, K2]])
    w = np.sqrt(np.linalg.eigvals(np.linalg.solve(M, K)).real)
    want = sorted_eigenvalues(np.concatenate([1j * w, -1j * w]))
    np.testing.assert_allclose(sorted_eigenvalues(lin.eigenvalues()), want, rtol=1e-10)
    # modes(): the undamped frequencies [Hz] of the free system, and which mode they are of
    m = modes(two_masses, x, mode={"friction.mode": 1})
    np.testing.assert_allclose(m.frequencies, np.sort(w) / (2 * np.pi), rtol=1e-10)
    assert m.mode["friction.mode"] == 1 and "friction.mode" in str(m)
    stuck = modes(two_masses, x, mode={"friction.mode": 0})
    np.testing.assert_allclose(stuck.frequencies, [0.0, np.sqrt(K2 / M2) / (2 * np.pi)],
                               atol=1e-9)


def test_bad_modes_are_refused(two_masses):
    with pytest.raises(AnalysisError, match="no mode 'friction.mod'.*did you mean"):
        linearize(two_masses, {}, mode={"friction.mod": 0})
    with pytest.raises(AnalysisError, match=r"friction.mode' takes the values \(-1, 0, 1, 2, 3\)"):
        linearize(two_masses, {}, mode={"friction.mode": 7})


F_PUSH, K = 2.0, 100.0              # N (below peak·f0 = 4.5 N), N/m


@pytest.fixture(scope="module")
def pushed_block():
    m = acausal.Model("pushed_block")
    m.wall, m.spring, m.mass = tr.Fixed(), tr.Spring(c=K), tr.Mass(m=1.0)
    m.friction = tr.SupportFriction(f_pos=[[0.0, F0]], peak=PEAK)
    m.push = tr.ConstantForce(f_constant=F_PUSH)
    for a, b in [(m.wall.flange, m.spring.flange_a), (m.spring.flange_b, m.mass.flange_a),
                 (m.mass.flange_b, m.friction.flange_a), (m.push.flange, m.mass.flange_b)]:
        m.connect(a, b)
    return acausal.compile(m)


def test_equilibrium_stuck_holds_wherever_the_block_is_put(pushed_block):
    eq = equilibrium(pushed_block, guess={"mass.s": 0.03})
    assert eq.mode == STUCK
    assert eq["mass.s"] == pytest.approx(0.03, abs=1e-12)        # nearest the guess
    assert eq["friction.f"] == pytest.approx(F_PUSH - K * 0.03, abs=1e-9)   # what it holds


@pytest.mark.parametrize("mode, s_rest", [(1, (F_PUSH - F0) / K), (-1, (F_PUSH + F0) / K)])
def test_equilibrium_sliding_rests_where_the_spring_balances_the_push_and_friction(
        pushed_block, mode, s_rest):
    eq = equilibrium(pushed_block, mode={"friction.mode": mode})
    assert eq.mode["friction.mode"] == mode
    assert eq["mass.s"] == pytest.approx(s_rest, abs=1e-12)
    assert eq["friction.f"] == pytest.approx(mode * F0, abs=1e-12)
