"""3-D multibody components against closed forms and hand-written formulas: energy
conservation of an undamped 3-D tree, MSL's Newton–Euler cut forces and torques at the
joints' frames, MSL's mass properties of BodyBox and BodyCylinder, point gravity, drives
through the axis flanges, and the errors of models the compiler cannot take yet."""
from __future__ import annotations

import numpy as np
import pytest

import acausal
from acausal.components import planar, rotational, translational
from acausal.components.multibody import (Body, BodyBox, BodyCylinder, BodyShape, Fixed,
                                          FixedRotation, FixedTranslation, GravityTypes,
                                          PointMass, Prismatic, Revolute, Spherical,
                                          World)
from acausal.core import Model
from acausal.errors import AcausalError, ParameterError, StructureError
from acausal.models import chain

TOL = dict(rtol=1e-10, atol=1e-12)
LINKS = [  # a tree: joint1 and joint2 both hang from joint0's frame_b
    dict(parent=-1, kind="R", r=(0.1, 0.2, -0.1), n=(1, 1, 0), angle=30.0, axis=(0, 0.6, 0.8),
         body=dict(m=1.5, r_CM=(0.3, -0.1, 0.2), I_11=0.05, I_22=0.08, I_33=0.04, I_21=0.01,
                   I_31=-0.005, I_32=0.002)),
    dict(parent=0, kind="P", r=(0.4, 0.0, 0.1), n=(0, 1, 1), angle=-50.0, axis=(1, 0, 0),
         body=dict(m=0.7, r_CM=(0.0, 0.2, 0.1), I_11=0.02, I_22=0.01, I_33=0.03, I_21=0.0,
                   I_31=0.004, I_32=-0.003)),
    dict(parent=0, kind="R", r=(0.0, -0.3, 0.2), n=(0, 0, 1), angle=70.0, axis=(0.6, 0, 0.8),
         body=dict(m=1.1, r_CM=(0.25, 0.05, -0.1), I_11=0.03, I_22=0.02, I_33=0.05,
                   I_21=-0.004, I_31=0.0, I_32=0.006)),
]
X0 = {"joint0.phi": 0.4, "joint1.s": 0.1, "joint2.phi": -0.8, "joint0.w": 1.0,
      "joint1.v": -0.5, "joint2.w": 2.0}


def _inertia(b):
    return np.array([[b["I_11"], b["I_21"], b["I_31"]], [b["I_21"], b["I_22"], b["I_32"]],
                     [b["I_31"], b["I_32"], b["I_33"]]])


def _vec(res, name, k=None):
    """The recorded 3-vector ``name`` (at sample k, or all) as an array of shape (n, 3)."""
    v = np.stack([res[f"{name}[{i}]"] for i in (1, 2, 3)], axis=-1)
    return v if k is None else v[k]


def _T(res, frame):
    return np.stack([np.stack([res[f"{frame}.R.T[{i},{j}]"] for j in (1, 2, 3)], -1)
                     for i in (1, 2, 3)], -2)


def test_undamped_3d_tree_conserves_energy():
    """E = Σ ½m|v_CM|² + ½wᵀIw − m g·r_CM from the recorded body variables (r_0, v_0, w_a,
    frame_a.R.T) stays at its start value to 1e-8 over 3 s of tumbling motion."""
    g_n = np.array([0.2, -1.0, 0.3])
    res = acausal.compile(chain(LINKS, g=9.81, n=tuple(g_n))).simulate(
        3.0, x0=X0, **TOL)
    g = 9.81 * g_n / np.linalg.norm(g_n)
    E = 0.0
    for i, link in enumerate(LINKS):
        b = link["body"]
        T = _T(res, f"body{i}.frame_a")
        w = _vec(res, f"body{i}.w_a")
        c = np.array(b["r_CM"])
        r_cm = _vec(res, f"body{i}.r_0") + np.einsum("nji,j->ni", T, c)
        v_cm = _vec(res, f"body{i}.v_0") + np.einsum("nji,nj->ni", T, np.cross(w, c))
        E = E + 0.5 * b["m"] * np.sum(v_cm ** 2, 1) + 0.5 * np.einsum(
            "ni,ij,nj->n", w, _inertia(b), w) - b["m"] * r_cm @ g
    assert np.ptp(E) < 1e-8 * np.max(np.abs(E))
    assert np.ptp(res["joint2.phi"]) > 1.0                       # it did move


def test_cut_forces_at_the_joints_are_msl_newton_euler():
    """The reactions recorded at the leaf joints' frame_b equal minus MSL's Body equations
    (frame_a.f = m(R(a_0 − g_0) + z×r_CM + w×(w×r_CM)), frame_a.t = Iz + w×Iw + r_CM×f),
    and frame_a carries them back as MSL's Revolute (−R_relᵀ) and Prismatic (t_a = −t_b −
    (e s)×f_b) do; a joint's tau is −frame_b.t·e with no flange torque: 0."""
    res = acausal.compile(chain(LINKS, g=9.81)).simulate(1.0, x0=X0, **TOL)
    for i in (1, 2):
        b = LINKS[i]["body"]
        m, c, I = b["m"], np.array(b["r_CM"]), _inertia(b)
        T = _T(res, f"body{i}.frame_a")
        w, z = _vec(res, f"body{i}.w_a"), _vec(res, f"body{i}.z_a")
        a = np.einsum("nij,nj->ni", T, _vec(res, f"body{i}.a_0") - _vec(res, f"body{i}.g_0"))
        f = m * (a + np.cross(z, c) + np.cross(w, np.cross(w, c)))
        t = z @ I + np.cross(w, w @ I) + np.cross(c, f)
        fb, tb = _vec(res, f"joint{i}.frame_b.f"), _vec(res, f"joint{i}.frame_b.t")
        assert np.max(np.abs(_vec(res, f"joint{i}.frame_b.R.w") - w)) == 0.0    # MSL's R.w
        assert np.max(np.abs(fb + f)) < 1e-7 * np.max(np.abs(f))
        assert np.max(np.abs(tb + t)) < 1e-7 * np.max(np.abs(t))
        fa, ta = _vec(res, f"joint{i}.frame_a.f"), _vec(res, f"joint{i}.frame_a.t")
        e = np.array(LINKS[i]["axis"]) / np.linalg.norm(LINKS[i]["axis"])
        if LINKS[i]["kind"] == "R":
            R_rel = np.einsum("nij,nkj->nik", T, _T(res, f"joint{i}.frame_a"))  # T_b T_aᵀ
            back = lambda x: np.einsum("nji,nj->ni", R_rel, x)              # noqa: E731
            assert np.max(np.abs(fa + back(fb))) < 1e-9 * np.max(np.abs(f))
            assert np.max(np.abs(ta + back(tb))) < 1e-9 * np.max(np.abs(t))
        else:
            es = np.outer(res[f"joint{i}.s"], e)
            assert np.max(np.abs(fa + fb)) < 1e-9 * np.max(np.abs(f))
            assert np.max(np.abs(ta + tb + np.cross(es, fb))) < 1e-9 * np.max(np.abs(t))
        assert np.max(np.abs(res[f"joint{i}.{'tau' if i == 2 else 'f'}"])) == 0.0
        if i == 2:
            assert np.max(np.abs(tb @ e)) < 1e-9 * np.max(np.abs(t))


def _from_nxy(n_x, n_y):
    e_x = np.asarray(n_x) / np.linalg.norm(n_x)
    e_z = np.cross(e_x, n_y)
    e_z = e_z / np.linalg.norm(e_z)
    return np.array([e_x, np.cross(e_z, e_x), e_z])


def _about_joint(shape, axis=(0.0, 0.0, 1.0)):
    """M of a Revolute about ``axis`` at frame_a of ``shape``: its moment of inertia there."""
    m = Model("spin")
    m.world, m.rev, m.shape = World(), Revolute(n=axis), shape
    m.connect(m.world.frame_b, m.rev.frame_a)
    m.connect(m.rev.frame_b, m.shape.frame_a)
    c = acausal.compile(m)
    return float(c.lagrange.function("M")(0.0, [0.3], [0.0], [], c.param_vector())), c


def test_body_box_and_cylinder_mass_properties_are_msl_s():
    """MSL's formulas: a hollow box and a hollow cylinder along a skew r: m = ρ·L·(w·h −
    wi·hi), ρπL(r² − ri²), inertia from the principal values rotated by from_nxy(r, ·),
    moment of inertia about a joint axis e through frame_a = eᵀ(I + m(|c|²1 − ccᵀ))e."""
    r, wd, e = np.array([0.1, 0.3, 0.4]), np.array([1.0, 0.0, 0.5]), np.array([0.6, 0.0, 0.8])
    L = np.linalg.norm(r)
    w, h, wi, hi, rho = 0.05, 0.04, 0.02, 0.01, 2700.0
    mo, mi = rho * L * w * h, rho * L * wi * hi
    D = np.diag([mo * (w * w + h * h) - mi * (wi * wi + hi * hi),
                 mo * (L * L + h * h) - mi * (L * L + hi * hi),
                 mo * (L * L + w * w) - mi * (L * L + wi * wi)]) / 12
    R = _from_nxy(r, wd)
    box = BodyBox(r=tuple(r), widthDirection=tuple(wd), width=w, height=h, innerWidth=wi,
                  innerHeight=hi, density=rho)
    d, di = 0.06, 0.04
    mco, mci = 7700 * np.pi * L * (d / 2) ** 2, 7700 * np.pi * L * (di / 2) ** 2
    I22 = (mco * (L * L + 3 * (d / 2) ** 2) - mci * (L * L + 3 * (di / 2) ** 2)) / 12
    Dc = np.diag([(mco * (d / 2) ** 2 - mci * (di / 2) ** 2) / 2, I22, I22])
    cyl = BodyCylinder(r=tuple(r), diameter=d, innerDiameter=di)
    Rc = _from_nxy(r, (0, 1, 0))
    for shape, mass, I in ((box, mo - mi, R.T @ D @ R), (cyl, mco - mci, Rc.T @ Dc @ Rc)):
        c = r / 2
        expected = e @ (I + mass * (c @ c * np.eye(3) - np.outer(c, c))) @ e
        got, _ = _about_joint(shape, tuple(e))
        assert abs(got - expected) < 1e-12 * expected
    assert box.width == 0.05 and BodyBox(r=(0.5, 0, 0)).width == 0.5 / 20     # MSL defaults
    assert BodyCylinder(r=(0, 0.4, 0)).diameter == 0.4 / 20


def test_point_gravity_and_a_drive_through_the_axis_flange():
    """A PointMass on a Prismatic along the world's x axis in MSL's point gravity field
    accelerates by −mu/x² (x at an earth radius); a Prismatic along y carrying a BodyShape
    of 2 kg and a Body of 1.5 kg on a Revolute, pushed through its axis flange by a
    ConstantForce of (2 + 1.5)·g, the Revolute driven by
    a ConstantTorque of m g (r_CM x) through its axis flange, stay at rest."""
    m = Model("orbit")
    m.world = World(gravityType=GravityTypes.PointGravity)
    m.fixed = Fixed(r=(6.371e6, 0, 0))
    m.prism, m.mass = Prismatic(n=(1, 0, 0)), PointMass(m=3.0)
    m.connect(m.fixed.frame_b, m.prism.frame_a)
    m.connect(m.prism.frame_b, m.mass.frame_a)
    c = acausal.compile(m)
    x = np.array([0.0, 0.0])
    a = float(c.f(x=x, p=c.param_vector())["xdot"][1])
    assert abs(a + 3.986004418e14 / 6.371e6 ** 2) < 1e-12 * 9.8

    m = Model("held")
    m.world = World()
    m.prism = Prismatic(n=(0, 1, 0), useAxisFlange=True)
    m.body = BodyShape(r=(0, 0.2, 0), r_CM=(0.1, 0, 0), m=2.0)
    m.push = translational.ConstantForce(f_constant=3.5 * 9.80665, useSupport=True)
    m.rev = Revolute(n=(0, 0, 1), useAxisFlange=True)
    m.arm = Body(r_CM=(0.5, 0, 0), m=1.5)
    m.turn = rotational.ConstantTorque(tau_constant=1.5 * 9.80665 * 0.5, useSupport=True)
    m.connect(m.world.frame_b, m.prism.frame_a)
    m.connect(m.prism.frame_b, m.body.frame_a)
    m.connect(m.push.flange, m.prism.axis)
    m.connect(m.push.support, m.prism.support)
    m.connect(m.body.frame_b, m.rev.frame_a)
    m.connect(m.rev.frame_b, m.arm.frame_a)
    m.connect(m.turn.flange, m.rev.axis)
    m.connect(m.turn.support, m.rev.support)
    c = acausal.compile(m)
    xdot = np.array(c.f(x=np.zeros(4), p=c.param_vector())["xdot"]).ravel()
    assert np.max(np.abs(xdot)) < 1e-12
    res = c.simulate(0.5)
    assert abs(res["prism.f"][-1] - 3.5 * 9.80665) < 1e-9
    assert abs(res["rev.tau"][-1] - 1.5 * 9.80665 * 0.5) < 1e-9


def test_models_the_compiler_cannot_take_yet_are_refused_naming_the_part():
    """A free rotation that carries no inertia (a spherical joint holding a point mass at
    its centre), a rigid 3-D loop that cannot close, a zero axis, a planar frame connected
    to a 3-D one, and a Body without m: clear errors naming the part."""
    m = Model("free")
    m.world, m.joint, m.mass = World(), Spherical(), PointMass(m=1.0)
    m.connect(m.world.frame_b, m.joint.frame_a)
    m.connect(m.joint.frame_b, m.mass.frame_a)
    with pytest.raises(StructureError, match="joint.Q.*no inertia"):
        acausal.compile(m)
    m = Model("loop")
    m.world, m.a, m.b = World(), FixedTranslation(r=(1, 0, 0)), Fixed(r=(2, 0, 0))
    m.rev, m.body = Revolute(), Body(m=1.0, r_CM=(0.2, 0, 0))
    m.connect(m.world.frame_b, m.a.frame_a)
    m.connect(m.a.frame_b, m.b.frame_b)
    m.connect(m.a.frame_b, m.rev.frame_a)
    m.connect(m.rev.frame_b, m.body.frame_a)
    with pytest.raises(StructureError, match="loop through 'a'.*cannot close.*parts in the loop: b"):
        acausal.compile(m)
    with pytest.raises(ParameterError, match="n = {0, 0, 0}"):
        m = Model("zero")
        m.world, m.rev = World(), Revolute(n=(0, 0, 0))
        m.body = Body(m=1.0, r_CM=(1, 0, 0))
        m.connect(m.world.frame_b, m.rev.frame_a)
        m.connect(m.rev.frame_b, m.body.frame_a)
        acausal.compile(m)
    m = Model("mixed")
    m.world, m.fixed = World(), planar.Fixed()
    with pytest.raises(AcausalError, match="world.frame_b.*fixed.frame|fixed.frame.*world.frame_b"):
        m.connect(m.world.frame_b, m.fixed.frame)
    with pytest.raises(ParameterError, match="'m'"):
        Body(r_CM=(1, 0, 0))
    with pytest.raises(ParameterError, match="sequence"):
        FixedRotation(rotationType="PlanarRotationSequence", sequence=(1, 1, 2))


@pytest.mark.parametrize("backwards", [False, True])
def test_parts_and_joints_used_from_frame_b_work_as_from_frame_a(backwards):
    """A FixedRotation, a Revolute and a Prismatic between the world and a Body, connected
    frame_a to the world or (``backwards``) frame_b to the world: the reaction recorded at
    the frame that carries the body equals minus MSL's Newton–Euler of the body (its motion
    is then right), and the energy is conserved."""
    I = np.array([[0.05, 0.01, 0.0], [0.01, 0.03, 0.0], [0.0, 0.0, 0.04]])
    c = np.array([0.3, -0.2, 0.1])
    m = Model("backwards")
    m.world = World(n=(0.3, -1, 0.2))
    m.rot = FixedRotation(r=(0.1, 0.2, 0.3), n=(1, 2, 3), angle=40)
    m.rev, m.prism = Revolute(n=(0.2, 0.5, 1)), Prismatic(n=(1, 1, 0))
    m.body = Body(m=1.3, r_CM=tuple(c), I_11=0.05, I_22=0.03, I_33=0.04, I_21=0.01)
    a, b = ("frame_b", "frame_a") if backwards else ("frame_a", "frame_b")
    m.connect(m.world.frame_b, getattr(m.rot, a))
    m.connect(getattr(m.rot, b), getattr(m.rev, a))
    m.connect(getattr(m.rev, b), getattr(m.prism, a))
    m.connect(getattr(m.prism, b), m.body.frame_a)
    res = acausal.compile(m).simulate(2.0, x0={"rev.w": 1.0, "prism.v": 0.3}, **TOL)
    T = _T(res, "body.frame_a")
    w, z = _vec(res, "body.w_a"), _vec(res, "body.z_a")
    acc = np.einsum("nij,nj->ni", T, _vec(res, "body.a_0") - _vec(res, "body.g_0"))
    f = 1.3 * (acc + np.cross(z, c) + np.cross(w, np.cross(w, c)))
    t = z @ I + np.cross(w, w @ I) + np.cross(c, f)
    assert np.max(np.abs(_vec(res, f"prism.{b}.f") + f)) < 1e-9 * np.max(np.abs(f))
    assert np.max(np.abs(_vec(res, f"prism.{b}.t") + t)) < 1e-9 * np.max(np.abs(t))
    g = 9.80665 * np.array([0.3, -1, 0.2]) / np.linalg.norm([0.3, -1, 0.2])
    r_cm = _vec(res, "body.r_0") + np.einsum("nji,j->ni", T, c)
    v_cm = _vec(res, "body.v_0") + np.einsum("nji,nj->ni", T, np.cross(w, c))
    kinetic = 0.5 * 1.3 * np.sum(v_cm ** 2, 1) + 0.5 * np.einsum("ni,ij,nj->n", w, I, w)
    potential = -1.3 * r_cm @ g
    assert np.ptp(kinetic + potential) < 1e-8 * np.max(np.abs(kinetic) + np.abs(potential))


def test_double_pendulum_hanging_modes_equal_the_compound_pendulum_closed_form():
    """MSL's DoublePendulum (two steel boxes 0.5 × 0.06 × 0.06 m) hanging at rest: the
    equilibrium is phi1 = −π/2, phi2 = 0, and its undamped natural frequencies (acausal's
    analysis: linearize, modes) are those of two compound pendulums in series,
    det(K − ω²M) = 0 with M = [[J + m l²/4 + m l², m l²/2], [m l²/2, J + m l²/4]],
    K = g·diag(3 m l/2, m l/2), J = m(l² + w²)/12 about the box's centre."""
    from acausal.analysis import equilibrium, linearize, modes
    from acausal.models import MultiBodyDoublePendulum
    compiled = acausal.compile(MultiBodyDoublePendulum())
    eq = equilibrium(compiled, guess={"revolute1.phi": -1.4, "revolute2.phi": 0.1})
    assert abs(eq["revolute1.phi"] + np.pi / 2) < 1e-12 and abs(eq["revolute2.phi"]) < 1e-12
    l, w, g = 0.5, 0.06, 9.80665
    m = 7700 * l * w * w
    J = m * (l * l + w * w) / 12
    M = np.array([[J + m * l * l / 4 + m * l * l, m * l * l / 2],
                  [m * l * l / 2, J + m * l * l / 4]])
    K = g * np.diag([1.5 * m * l, 0.5 * m * l])
    f_exact = np.sqrt(np.sort(np.linalg.eigvals(np.linalg.solve(M, K)).real)) / (2 * np.pi)
    f = np.sort(modes(linearize(compiled, eq)).frequencies)
    assert np.max(np.abs(f - f_exact)) < 1e-9 * f_exact.max()


def _rot(axis, deg):
    e = np.eye(3)[axis - 1] if isinstance(axis, int) else np.asarray(axis) / np.linalg.norm(axis)
    K = np.array([[0, -e[2], e[1]], [e[2], 0, -e[0]], [-e[1], e[0], 0]])
    a = np.radians(deg)
    return np.outer(e, e) + (np.eye(3) - np.outer(e, e)) * np.cos(a) - K * np.sin(a)


@pytest.mark.parametrize("kw, T_rel", [
    (dict(n=(1, 2, 2), angle=75.0), _rot((1, 2, 2), 75.0)),
    (dict(rotationType="TwoAxesVectors", n_x=(1, 1, 0), n_y=(0, 1, 1)),
     _from_nxy((1, 1, 0), (0, 1, 1))),
    (dict(rotationType="PlanarRotationSequence", sequence=(3, 1, 3), angles=(20, -40, 65)),
     _rot(3, 65) @ _rot(1, -40) @ _rot(3, 20)),
])
def test_fixed_rotation_forms_are_msl_s(kw, T_rel):
    """FixedRotation's three rotation types give MSL's R_rel (planarRotation for an axis and
    an angle in degrees, from_nxy for two axes, axesRotations for a sequence): frame_b.r_0 =
    r_0a + R_aᵀ r and frame_b.R.T = T_rel·R_a.T, behind a tilted FixedRotation."""
    m = Model("rotations")
    m.world = World()
    m.tilt = FixedRotation(n=(0, 0, 1), angle=30.0)
    m.rot = FixedRotation(r=(0.2, -0.1, 0.4), **kw)
    m.rev, m.body = Revolute(), Body(m=1.0, r_CM=(0.3, 0, 0))
    m.connect(m.world.frame_b, m.tilt.frame_a)
    m.connect(m.tilt.frame_b, m.rot.frame_a)
    m.connect(m.rot.frame_b, m.rev.frame_a)
    m.connect(m.rev.frame_b, m.body.frame_a)
    res = acausal.compile(m).simulate(0.1)
    Ta = _rot(3, 30.0)
    assert np.max(np.abs(_T(res, "rot.frame_b")[0] - T_rel @ Ta)) < 1e-14
    assert np.max(np.abs(_vec(res, "rot.frame_b.r_0", 0) - Ta.T @ [0.2, -0.1, 0.4])) < 1e-14
