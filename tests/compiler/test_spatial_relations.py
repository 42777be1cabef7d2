"""The 3-D relations' closed-form velocity maps equal what the generic route derives by AD
from their positions (``twist(pos, der(pos))``, the route planar relations take), in both
directions, at random states; the relaxation of a 3-D frame (a virtual twist) likewise to
first order in ε, all the reactions need."""
from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

from acausal.compiler.relations import (SpatialCompose, SpatialPrismatic, SpatialRevolute,
                                        SpatialTransform, pose_rate, relax_spatial, twist)
from acausal.core import MultiBodyFrame, RotationalFlange
from acausal.frames import parts, planar_rotation, pose

RNG = np.random.default_rng(7)


class _Owner:
    path = "part"


def _random_pose():
    q, _ = np.linalg.qr(RNG.normal(size=(3, 3)))
    return np.concatenate([RNG.normal(size=3), (q * np.sign(np.linalg.det(q))).ravel()])


def _unit():
    v = RNG.normal(size=3)
    return v / np.linalg.norm(v)


def _relation(cls):
    a, b, q = MultiBodyFrame(), MultiBodyFrame(), RotationalFlange()
    if cls is SpatialTransform:
        T = ca.evalf(planar_rotation(ca.SX(_unit()), 0.7))
        return cls(_Owner(), a, b, ca.SX(RNG.normal(size=3)), ca.SX(T))
    if cls is SpatialCompose:
        return cls(_Owner(), a, b, MultiBodyFrame())
    return cls(_Owner(), a, b, q, ca.SX(_unit()))


@pytest.mark.parametrize("cls", [SpatialTransform, SpatialRevolute, SpatialPrismatic,
                                 SpatialCompose])
@pytest.mark.parametrize("j", [0, 1])
def test_closed_form_twist_equals_the_ad_derivation(cls, j):
    rel = _relation(cls)
    vals, vels, accs, par = rel._locals()
    others = [i for i in range(len(rel.dims)) if i != j]
    value, _ = rel.solve_local(j, {i: vals[i] for i in others}, par)
    X = ca.vertcat(*[vals[i] for i in others])
    rate = ca.vertcat(*[pose_rate(vals[i], vels[i]) for i in others])
    generic = ca.Function("g", [*[vals[i] for i in others], *[vels[i] for i in others], *par],
                          [twist(value, ca.jtimes(value, X, rate))])
    solver = rel._solver(j)
    for _ in range(5):
        pos = [_random_pose() if rel.dims[i] == 12 else RNG.normal(size=1) for i in others]
        vel = [RNG.normal(size=rel.dofs[i]) for i in others]
        acc = [RNG.normal(size=rel.dofs[i]) for i in others]
        p = [np.array(ca.evalf(x)).ravel() for x in rel.params]
        want = np.array(generic(*pos, *vel, *p)).ravel()
        got = np.array(solver(*pos, *vel, *acc, *p)[1]).ravel()
        assert np.max(np.abs(got - want)) < 1e-12 * max(1.0, np.max(np.abs(want)))


def test_relaxed_frame_twist_is_the_derivative_of_the_relaxed_pose_to_first_order():
    pos, vel, acc = ca.SX.sym("pos", 12), ca.SX.sym("vel", 6), ca.SX.sym("acc", 6)
    e, ed, edd = ca.SX.sym("e", 6), ca.SX.sym("ed", 6), ca.SX.sym("edd", 6)
    relaxed, v, _ = relax_spatial(pos, vel, acc, e, ed, edd)
    r, T = parts(pos)
    generic = twist(relaxed, ca.jtimes(relaxed, ca.vertcat(pos, e),
                                       ca.vertcat(pose_rate(pos, vel), ed)))
    eps = ca.vertcat(e, ed)
    f = ca.Function("f", [pos, vel, eps], [v - generic, ca.jacobian(v - generic, eps)])
    assert ca.depends_on(relaxed, e) and np.allclose(
        np.array(ca.Function("p", [pos, e], [relaxed - pose(r, T)])(_random_pose(), 0)), 0)
    for _ in range(5):
        d, J = f(_random_pose(), RNG.normal(size=6), np.zeros(12))
        assert np.max(np.abs(np.array(d))) < 1e-12 and np.max(np.abs(np.array(J))) < 1e-12
