"""Massless nodes the model's equations do not determine are named at compile time, not
left to a singular Jacobian inside the solver (exact errors expected)."""
from __future__ import annotations

import pytest

import acausal as ac
from acausal.components import translational as tr


def _oscillator(m):
    m.wall, m.spring, m.mass = tr.Fixed(), tr.Spring(c=10.0), tr.Mass()
    m.connect(m.wall.flange, m.spring.flange_a)
    m.connect(m.spring.flange_b, m.mass.flange_a)


def test_rod_connected_to_nothing_is_named():
    m = ac.Model("loose_rod")
    _oscillator(m)
    m.rod = tr.Rod(L=1.0)
    with pytest.raises(ac.SingularModelError, match=r"massless node\(s\) rod\.flange_a\.s: "
                                                    r"the forces on it depend neither"):
        ac.compile(m)


def test_force_on_a_massless_rod_blames_the_node_not_the_input():
    """A force pushes a rod that nothing balances: the rod's node is named (the error used to
    be about the input's time derivative)."""
    m = ac.Model("pushed_rod")
    _oscillator(m)
    m.rod, m.push, m.F = tr.Rod(L=1.0), tr.Force(), ac.Input(start=1.0)
    m.connect(m.push.flange, m.rod.flange_a)
    m.connect(m.F.y, m.push.f)
    with pytest.raises(ac.SingularModelError, match=r"massless node\(s\) rod\.flange_a\.s: "
                                                    r"the forces on it depend neither"):
        ac.compile(m)
