"""Consistent initial values where the projection must be well conditioned.

References: closed forms (a massless node between springs sits where their forces balance),
and loop closure evaluated here from the recorded frame poses of random linkages.
"""
from __future__ import annotations

import numpy as np
import pytest

import acausal as ac
from acausal.analysis import operating_point
from acausal.components import planar as pl
from acausal.components import rotational as rot
from acausal.components import translational as tr
from acausal.numerics import ProjectionError, project


def test_massless_node_between_stiff_springs_starts_where_the_forces_balance():
    """wall | spring c1 | node (no mass) | spring c2 | mass: with mass.s = 0.5 m held, the
    node sits at c2·s/(c1 + c2) (the springs' forces balance), whatever their stiffness."""
    c1, c2, s = 1e3, 3e3, 0.5
    m = ac.Model("node")
    m.wall, m.s1, m.s2, m.mass = tr.Fixed(), tr.Spring(c=c1), tr.Spring(c=c2), tr.Mass(m=1.0)
    m.connect(m.wall.flange, m.s1.flange_a)
    m.connect(m.s1.flange_b, m.s2.flange_a)
    m.connect(m.s2.flange_b, m.mass.flange_a)
    res = ac.compile(m).simulate(0.01, t=np.linspace(0, 0.01, 3), x0={"mass.s": s})
    assert abs(res["mass.s"][0] - s) < 1e-12
    assert abs(res["s1.flange_b.s"][0] - c2 * s / (c1 + c2)) < 1e-12
    assert abs(res["s1.f"][0] - res["s2.f"][0]) < 1e-9 * c1


def test_two_default_rotational_springs_in_series_start_from_x0():
    """Two Springs at their default c = 1e5 N.m/rad in series to an inertia: the node between
    them at phi/2."""
    m = ac.Model("series")
    m.fixed, m.s1, m.s2, m.inertia = rot.Fixed(), rot.Spring(), rot.Spring(), rot.Inertia()
    m.connect(m.fixed.flange, m.s1.flange_a)
    m.connect(m.s1.flange_b, m.s2.flange_a)
    m.connect(m.s2.flange_b, m.inertia.flange_a)
    res = ac.compile(m).simulate(1e-3, t=np.linspace(0, 1e-3, 3), x0={"inertia.phi": 0.5})
    assert abs(res["inertia.phi"][0] - 0.5) < 1e-12
    assert abs(res["s1.flange_b.phi"][0] - 0.25) < 1e-12


def _four_bar(lengths):
    """Four-bar of bars (ground, crank, coupler, rocker) [m], 1 kg bodies at the bars' ends."""
    l0, l1, l2, l3 = lengths
    m = ac.Model("random_four_bar")
    m.world, m.A, m.D = pl.World(), pl.Fixed(), pl.Fixed(r=(l0, 0.0))
    m.rev1, m.rev2, m.rev3, m.rev4 = pl.Revolute(), pl.Revolute(), pl.Revolute(), pl.Revolute()
    m.crank, m.coupler, m.rocker = (pl.FixedTranslation(r=(l, 0.0)) for l in (l1, l2, l3))
    m.b1, m.b2, m.b3 = pl.Body(m=1.0, I=0.1), pl.Body(m=1.0, I=0.1), pl.Body(m=1.0, I=0.1)
    for a, b in [(m.A.frame, m.rev1.frame_a), (m.rev1.frame_b, m.crank.frame_a),
                 (m.crank.frame_b, m.b1.frame_a), (m.crank.frame_b, m.rev2.frame_a),
                 (m.rev2.frame_b, m.coupler.frame_a), (m.coupler.frame_b, m.b2.frame_a),
                 (m.D.frame, m.rev3.frame_a), (m.rev3.frame_b, m.rocker.frame_a),
                 (m.rocker.frame_b, m.b3.frame_a), (m.coupler.frame_b, m.rev4.frame_a),
                 (m.rocker.frame_b, m.rev4.frame_b)]:
        m.connect(a, b)
    return m


@pytest.mark.parametrize("seed", range(12))
def test_random_closable_four_bars_assemble_without_a_guess(seed):
    """Random Grashof crank-rockers (the shortest bar the crank, s + l < p + q: every crank
    angle closes), the crank at a random angle, every other joint from its start value 0:
    assembly closes the loop, measured on the recorded frame positions."""
    rng = np.random.default_rng(seed)
    while True:
        l0, l2, l3 = rng.uniform(0.5, 2.0, 3)
        l1 = rng.uniform(0.05, 0.45) * min(l0, l2, l3)
        bars = sorted([l0, l1, l2, l3])
        if bars[0] + bars[3] < bars[1] + bars[2] - 0.05:
            break
    compiled = ac.compile(_four_bar((l0, l1, l2, l3)))
    theta = rng.uniform(-np.pi, np.pi)
    with pytest.warns(UserWarning, match="close the kinematic loops"):
        pt = operating_point(compiled, {"rev1.phi": theta})
    gap = [pt[f"rev4.frame_a.{c}"] - pt[f"rev4.frame_b.{c}"] for c in ("x", "y")]
    assert np.max(np.abs(gap)) < 1e-10
    assert abs(pt["rev1.phi"] - theta) < 1e-12
    assert abs(pt["crank.frame_b.x"] - l1 * np.cos(theta)) < 1e-12


def test_fast_crank_starts_without_a_guess():
    """A four-bar whose crank starts at 45 rad/s: the loop's velocity constraints are linear
    in the speeds, so the other joints' speeds come out exactly however large (the start-up
    solver used to limit speed steps like angle steps, and gave up). Reference: the rates of
    the loop-closing point, evaluated here from the recorded frame velocities, vanish."""
    compiled = ac.compile(_four_bar((1.0, 0.3, 1.0, 0.8)))
    with pytest.warns(UserWarning, match="close the kinematic loops"):
        pt = operating_point(compiled, {"rev1.phi": 1.0, "rev1.w": 45.0})
    assert abs(pt["rev1.w"] - 45.0) < 1e-12
    gap = [pt[f"rev4.frame_a.{c}"] - pt[f"rev4.frame_b.{c}"] for c in ("x", "y")]
    assert np.max(np.abs(gap)) < 1e-10
    # the loop's end C moves the same seen from the coupler (body b2) and the rocker (b3);
    # the crank's tip (b1) as the closed form says
    for k in (1, 2):
        assert abs(pt[f"b2.v[{k}]"] - pt[f"b3.v[{k}]"]) < 1e-9 * 45.0
    assert abs(pt["b1.v[1]"] + 0.3 * 45.0 * np.sin(1.0)) < 1e-10
    assert abs(pt["b1.v[2]"] - 0.3 * 45.0 * np.cos(1.0)) < 1e-10


def _mass_on_spring():
    """wall at 0.3 m | spring | mass of length 0.2 m: spring.s_rel = mass.s − 0.1 − 0.3."""
    model = ac.Model("osc")
    model.wall = tr.Fixed(s0=0.3)
    model.spring = tr.Spring(c=8.0)
    model.mass = tr.Mass(m=0.5, L=0.2)
    model.connect(model.wall.flange, model.spring.flange_a)
    model.connect(model.spring.flange_b, model.mass.flange_a)
    return ac.compile(model)


def test_a_guess_on_any_variable_moves_the_start_values():
    """Without constraints the guess on a variable that is no state is met exactly by the
    state it depends on: spring.s_rel = 0.7 m puts the mass's centre at 0.7 + 0.1 + 0.3."""
    compiled = _mass_on_spring()
    res = compiled.simulate(0.01, t=[0.0, 0.01], guess={"spring.s_rel": 0.7},
                            rtol=1e-10, atol=1e-12)
    assert abs(res["mass.s"][0] - 1.1) < 1e-12
    assert abs(res["spring.s_rel"][0] - 0.7) < 1e-12


def test_guess_errors_name_the_variable():
    compiled = _mass_on_spring()
    with pytest.raises(ac.errors.InitializationError, match="guess: .*spring.s_rell"):
        compiled.simulate(0.01, guess={"spring.s_rell": 0.7})
    with pytest.raises(ac.errors.InitializationError, match="guess: 'wall.flange.s' does not"):
        compiled.simulate(0.01, guess={"wall.flange.s": 0.7})
    with pytest.raises(ac.errors.InitializationError, match="x0 and guess values conflict"):
        compiled.simulate(0.01, x0={"mass.s": 1.0}, guess={"spring.s_rel": 0.7})


def test_states_stay_at_their_start_when_the_algebraic_variables_solve_the_equations():
    """H(x, z) = A·z − B·x (3 equations, A invertible): the algebraic variables z can meet
    every equation, so the projection keeps the states x at their start values exactly and
    gives z = A⁻¹·B·x (the start values of a body hung from massless junctions between
    3-D springs, MSL's ThreeSprings)."""
    rng = np.random.default_rng(7)
    A, B = rng.normal(size=(3, 3)) + 3 * np.eye(3), rng.normal(size=(3, 3))
    x_start = rng.normal(size=4)
    B4 = np.c_[B, np.zeros(3)]

    def equations(w):
        x, z = w[:4], w[4:]
        return A @ z - B4 @ x, np.c_[-B4, A]

    start = np.r_[x_start, 0.1, -0.2, 0.2]
    w = project(equations, start, start, 4, ["row"] * 3, [])
    assert np.array_equal(w[:4], x_start)
    assert np.allclose(w[4:], np.linalg.solve(A, B4 @ x_start), rtol=0, atol=1e-13)


def test_equations_not_finite_at_the_start_are_named():
    """An equation that is NaN at the start (an input NaN there) cannot be met: the error
    names it and says it is not finite, instead of listing no equation at all."""
    def equations(w):
        return np.array([w[0] - 1.0, np.nan]), np.array([[1.0], [1.0]])
    with pytest.raises(ProjectionError, match=r"initial values: x\[n\] = u is not finite "
                                              r"\(NaN or inf\) at the start"):
        project(equations, np.zeros(1), np.zeros(1), 1, ["x0 row", "x[n] = u"], [1.0])
