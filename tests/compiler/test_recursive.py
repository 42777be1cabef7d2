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


# ---- 3-D ------------------------------------------------------------------------------------
def tree_3d():
    """A 3-D tree of MultiBody parts: a revolute base with a rotor on its axis flange
    (armature), a prismatic arm, a gimbal (three revolutes about x, y, z through one point,
    massless frames in between: a spherical joint as three coordinates) carrying a body, and
    a second branch from the base."""
    from acausal.components import multibody as mb
    m = ac.Model("tree3d")
    m.world = mb.World(n=(0.2, -1.0, 0.1))
    m.base = mb.Revolute(n=(0, 1, 0), useAxisFlange=True)
    m.rotor = rot.Inertia(J=0.2)
    m.connect(m.base.axis, m.rotor.flange_a)
    m.link0 = mb.BodyShape(r=(0.4, 0.1, 0.0), r_CM=(0.2, 0.0, 0.05), m=2.0, I_11=0.02,
                           I_22=0.05, I_33=0.04, I_21=0.003)
    m.slide = mb.Prismatic(n=(0.6, 0.0, 0.8))
    m.link1 = mb.BodyShape(r=(0.0, 0.3, 0.0), r_CM=(0.0, 0.15, 0.02), m=1.2, I_11=0.01,
                           I_22=0.004, I_33=0.012, I_31=-0.001)
    m.gx, m.gy, m.gz = (mb.Revolute(n=n) for n in ((1, 0, 0), (0, 1, 0), (0, 0, 1)))
    m.ball = mb.Body(m=0.8, r_CM=(0.1, 0.05, -0.1), I_11=0.003, I_22=0.002, I_33=0.004,
                     I_32=0.0005)
    m.elbow = mb.Revolute(n=(0.0, 0.6, 0.8))
    m.link2 = mb.Body(m=0.9, r_CM=(0.25, 0.0, 0.0), I_11=0.001, I_22=0.01, I_33=0.01)
    m.connect(m.world.frame_b, m.base.frame_a)
    m.connect(m.base.frame_b, m.link0.frame_a)
    m.connect(m.link0.frame_b, m.slide.frame_a)
    m.connect(m.slide.frame_b, m.link1.frame_a)
    m.connect(m.link1.frame_b, m.gx.frame_a)
    m.connect(m.gx.frame_b, m.gy.frame_a)
    m.connect(m.gy.frame_b, m.gz.frame_a)
    m.connect(m.gz.frame_b, m.ball.frame_a)
    m.connect(m.link0.frame_b, m.elbow.frame_a)
    m.connect(m.elbow.frame_b, m.link2.frame_a)
    return m


def test_3d_recursion_matches_the_mass_matrix():
    """The recursion in 6-D spatial vectors (3-D bodies, a rotor as armature, a gimbal's
    three coordinates as one 3-DOF joint) gives q̈ = M⁻¹(−R0) of the Lagrangian (numpy) to
    1e-9 at random states."""
    c = ac.compile(tree_3d())
    assert c.method == "articulated-body recursion"
    L = c.lagrange
    n = L.q.numel()
    assert n == 6
    rhs = ca.Function("rhs", [c.x, c.p], [c.ode])
    parts = ca.Function("parts", [L.q, L.qd, L.p], [L.M, L.R0], {"allow_free": True})
    rng = np.random.default_rng(4)
    p = c.param_vector()
    names = c.x_names
    for _ in range(10):
        q, qd = rng.uniform(-1.5, 1.5, n), rng.uniform(-2, 2, n)
        x = np.zeros(len(names))
        x[[names.index(k) for k in L.q_names]] = q
        x[[names.index(k) for k in L.qd_names]] = qd
        M, R0 = (np.array(v) for v in parts(q, qd, p))
        qdd_ref = np.linalg.solve(M, -R0).ravel()
        qdd = np.array(rhs(x, p)).ravel()[[names.index(k) for k in L.qd_names]]
        np.testing.assert_allclose(qdd, qdd_ref, rtol=1e-9, atol=1e-9)


def test_3d_recursion_is_linear_in_chain_length():
    from acausal.models import chain as chain3d
    links = lambda n: [dict(parent=i - 1, kind="RP"[i % 4 == 3], r=(0.3, 0.0, 0.1),  # noqa
                            n=(1, 1, 0), angle=40.0, axis=((0, 0, 1), (0, 1, 0))[i % 2],
                            body=dict(m=1.0, r_CM=(0.1, 0.02, 0.0))) for i in range(n)]
    sizes = {}
    for n in (8, 16, 32):
        c = ac.compile(chain3d(links(n)))
        assert c.method == "articulated-body recursion"
        sizes[n] = ca.Function("f", [c.x, c.p], [c.ode]).n_instructions()
    assert sizes[32] / sizes[16] < 2.3 and sizes[16] / sizes[8] < 2.3
