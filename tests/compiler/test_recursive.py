"""The O(N) articulated-body recursion against the Lagrangian mass matrix of the same model
(q̈ = M⁻¹ τ by numpy), for chains with revolute and prismatic joints, a free body and 1-D
inertia on a joint flange (armature)."""
import casadi as ca
import numpy as np

import acausal as ac
from acausal.components import planar as P
from acausal.components import rotational as rot


def chain(n, prismatic_every=3, free_body=True, armature=True):
    m = ac.Model("chain")
    m.world, m.fix = P.World(), P.Fixed()
    prev = m.fix.frame
    for i in range(n):
        if i % prismatic_every == 2:
            j = P.Prismatic(r=(0.3, 1.0))
        else:
            j = P.Revolute(useFlange=armature and i == 0)
        bar = P.FixedTranslation(r=(0.4 + 0.1 * i, -0.05 * i))
        body = P.Body(m=1.0 + 0.2 * i, I=0.05 + 0.01 * i)
        for name, c in ((f"j{i}", j), (f"bar{i}", bar), (f"b{i}", body)):
            setattr(m, name, c)
        m.connect(prev, j.frame_a)
        m.connect(j.frame_b, bar.frame_a)
        m.connect(bar.frame_b, body.frame_a)
        prev = bar.frame_b
    if armature:
        m.rotor = rot.Inertia(J=0.3)
        m.connect(m.j0.axis, m.rotor.flange_a)
    if free_body:
        m.puck = P.Body(m=0.7, I=0.02)
    return m


def test_recursion_matches_the_mass_matrix():
    c = ac.compile(chain(7))
    assert c.method == "articulated-body recursion"
    L = c.lagrange
    n = L.q.numel()
    rhs = ca.Function("rhs", [c.x, c.p], [c.ode])
    parts = ca.Function("parts", [L.q, L.qd, L.p], [L.M, L.R0], {"allow_free": True})
    rng = np.random.default_rng(3)
    p = c.param_vector()
    for _ in range(10):
        q, qd = rng.uniform(-1, 1, n), rng.uniform(-1, 1, n)
        names = c.x_names
        x = np.zeros(len(names))
        x[[names.index(k) for k in L.q_names]] = q
        x[[names.index(k) for k in L.qd_names]] = qd
        M, R0 = (np.array(v) for v in parts(q, qd, p))
        qdd_ref = np.linalg.solve(M, -R0).ravel()
        out = np.array(rhs(x, p)).ravel()
        qdd = out[[names.index(k) for k in L.qd_names]]
        np.testing.assert_allclose(qdd, qdd_ref, rtol=1e-9, atol=1e-9)


def test_recursion_is_linear_in_chain_length():
    """The right-hand side grows linearly with the chain (a dense solve grows cubically)."""
    sizes = {}
    for n in (8, 16, 32):
        c = ac.compile(chain(n, free_body=False, armature=False))
        sizes[n] = ca.Function("f", [c.x, c.p], [c.ode]).n_instructions()
    assert sizes[32] / sizes[16] < 2.3 and sizes[16] / sizes[8] < 2.3
