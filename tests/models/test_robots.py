"""Robot arms built by ``acausal.multibody``: from Denavit–Hartenberg tables (standard and
modified conventions) and from URDF files.

- DH: the PUMA 560 (both conventions) and the Stanford arm (a prismatic joint): the pose of
  every link frame, at random joint values, equals the product of the DH matrices written
  here by hand in numpy (to 1e-12).
- URDF: the UR5 of the ``example-robot-data`` package, read by acausal and by Pinocchio
  (its own URDF parser and algorithms): M(q) equals Pinocchio's CRBA to 1e-10, the
  accelerations Pinocchio's ABA to 1e-9 (both relative to their largest entry), at random
  states; the drive torques of acausal's inverse dynamics along a trajectory equal
  Pinocchio's RNEA to 1e-9; the joints' limits and axes are recorded. The Panda (fixed
  joints, prismatic fingers, a mimic joint) likewise, with and without its mimic joint.
"""
from __future__ import annotations

from importlib.metadata import PackageNotFoundError, distribution

import numpy as np
import pytest

import acausal
from acausal.multibody import dh_chain, from_urdf

# PUMA 560: Corke's standard table, Craig's modified one [m, rad]
PUMA_STANDARD = [(0.0, 0.0, 0.0, np.pi / 2), (0.0, 0.0, 0.4318, 0.0),
                 (0.0, 0.15005, 0.0203, -np.pi / 2), (0.0, 0.4318, 0.0, np.pi / 2),
                 (0.0, 0.0, 0.0, -np.pi / 2), (0.0, 0.0, 0.0, 0.0)]
PUMA_MODIFIED = [(0.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, -np.pi / 2),
                 (0.0, 0.15005, 0.4318, 0.0), (0.0, 0.4318, 0.0203, -np.pi / 2),
                 (0.0, 0.0, 0.0, np.pi / 2), (0.0, 0.0, 0.0, -np.pi / 2)]
# Stanford arm (standard), joint 3 prismatic
STANFORD = [(0.0, 0.412, 0.0, -np.pi / 2, "R"), (0.0, 0.154, 0.0, np.pi / 2, "R"),
            (-np.pi / 2, 0.0, 0.0203, 0.0, "P"), (0.0, 0.0, 0.0, -np.pi / 2, "R"),
            (0.0, 0.0, 0.0, np.pi / 2, "R"), (0.0, 0.263, 0.0, 0.0, "R")]


def rot_z(t):
    c, s = np.cos(t), np.sin(t)
    return np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])


def rot_x(t):
    c, s = np.cos(t), np.sin(t)
    return np.array([[1, 0, 0, 0], [0, c, -s, 0], [0, s, c, 0], [0, 0, 0, 1]])


def trans(x, y, z):
    A = np.eye(4)
    A[:3, 3] = x, y, z
    return A


def dh_frames(rows, q, convention):
    """The 4x4 poses of link frames 1..n in frame 0 by the DH product."""
    A, out = np.eye(4), []
    for (theta, d, a, alpha, *kind), qi in zip(rows, q):
        if (kind or ["R"])[0] == "R":
            theta = theta + qi
        else:
            d = d + qi
        if convention == "standard":
            A = A @ rot_z(theta) @ trans(0, 0, d) @ trans(a, 0, 0) @ rot_x(alpha)
        else:
            A = A @ rot_x(alpha) @ trans(a, 0, 0) @ rot_z(theta) @ trans(0, 0, d)
        out.append(A)
    return out


def table(rows):
    return [dict(theta=r[0], d=r[1], a=r[2], alpha=r[3], joint=(r[4] if len(r) > 4 else "R"),
                 body=dict(m=1.0 + 0.1 * i, r_CM=(0.01 * i, -0.02, 0.05)))
            for i, r in enumerate(rows)]


@pytest.mark.parametrize("rows, convention", [(PUMA_STANDARD, "standard"),
                                              (PUMA_MODIFIED, "modified"),
                                              (STANFORD, "standard")])
def test_dh_chain_frames_equal_the_dh_product(rows, convention):
    model = dh_chain(table(rows), convention=convention, n=(0, 0, -1))
    compiled = acausal.compile(model)
    n = len(rows)
    coords = [f"joint{i + 1}.{'s' if len(r) > 4 and r[4] == 'P' else 'phi'}"
              for i, r in enumerate(rows)]
    frames = [f.path for f in model.frames]
    names = [f"{f}.{k}" for f in frames
             for k in [f"r_0[{i}]" for i in (1, 2, 3)]
             + [f"R.T[{i},{j}]" for i in (1, 2, 3) for j in (1, 2, 3)]]
    fk = compiled.function("fk", [acausal_expr for acausal_expr in
                                  map(compiled.expression, names)])
    rng = np.random.default_rng(5)
    for _ in range(5):
        q = rng.uniform(-np.pi, np.pi, n)
        x = np.zeros(len(compiled.x_names))
        x[[compiled.x_names.index(c) for c in coords]] = q
        got = np.array([float(v) for v in fk(0.0, x, [], [], compiled.param_vector())])
        got = got.reshape(n, 12)
        for k, A in enumerate(dh_frames(rows, q, convention)):
            assert np.max(np.abs(got[k, :3] - A[:3, 3])) < 1e-12
            assert np.max(np.abs(got[k, 3:].reshape(3, 3) - A[:3, :3].T)) < 1e-12


def test_dh_chain_refuses_a_bad_row():
    with pytest.raises(acausal.ParameterError, match="row 2.*'X'"):
        dh_chain([dict(theta=0, d=0, a=0, alpha=0), dict(theta=0, d=0, a=0, alpha=0,
                                                         joint="X")])
    with pytest.raises(acausal.ParameterError, match="row 1 lacks alpha"):
        dh_chain([dict(theta=0, d=0, a=0)])
    with pytest.raises(acausal.ParameterError, match="convention"):
        dh_chain(table(STANFORD), convention="craig")


# ---- URDF -----------------------------------------------------------------------------------
def robot_file(relative: str) -> str:
    try:
        path = distribution("example-robot-data").locate_file(
            f"cmeel.prefix/share/example-robot-data/robots/{relative}")
    except PackageNotFoundError:
        pytest.skip("example-robot-data is not installed (the robots extra)")
    return str(path)


UR5 = "ur_description/urdf/ur5_joint_limited_robot.urdf"
G = (0.0, 0.0, -9.81)


@pytest.fixture(scope="module")
def ur5():
    pin = pytest.importorskip("pinocchio")
    path = robot_file(UR5)
    pmodel = pin.buildModelFromUrdf(path)
    pmodel.gravity.linear = np.array(G)
    return path, pmodel


def equal_pinocchio(model, pmodel, states=5, seed=7):
    """M(q) against Pinocchio's CRBA (1e-10) and the accelerations against Pinocchio's
    (1e-9, relative to their largest entry): ABA, or for mimic joints (which Pinocchio's
    ABA refuses) CRBA⁻¹(τ − nonLinearEffects), at random states."""
    import pinocchio as pin
    data = pmodel.createData()
    compiled = acausal.compile(model)
    n = pmodel.nv
    coords = [f"{nm}.{'s' if model.limits[nm]['type'] == 'prismatic' else 'phi'}"
              for nm, joint in zip(list(pmodel.names)[1:], list(pmodel.joints)[1:])
              if joint.shortname() != "JointModelMimic"]
    assert sorted(coords) == sorted(compiled.coordinates)
    order = [compiled.coordinates.index(c) for c in coords]
    M_fun = compiled.lagrange.function("M")
    p = compiled.param_vector()
    x_index = [compiled.x_names.index(nm) for nm in compiled.coordinates] + \
              [compiled.x_names.index(nm) for nm in compiled.lagrange.qd_names]
    mimic = any(j.shortname() == "JointModelMimic" for j in pmodel.joints)
    rng = np.random.default_rng(seed)
    for _ in range(states):
        q = rng.uniform(np.maximum(pmodel.lowerPositionLimit, -np.pi),
                        np.minimum(pmodel.upperPositionLimit, np.pi))
        v = rng.normal(size=n)
        qa, va = np.empty(n), np.empty(n)
        qa[order], va[order] = q, v
        M = np.array(M_fun(0.0, qa, va, [], p))[np.ix_(order, order)]
        M_pin = pin.crba(pmodel, data, q)
        M_pin = np.triu(M_pin) + np.triu(M_pin, 1).T
        assert np.max(np.abs(M - M_pin)) < 1e-10 * np.max(np.abs(M_pin))
        x = np.empty(2 * n)
        x[x_index] = np.concatenate([qa, va])
        a = np.array(compiled.f(x=x, p=p)["xdot"]).ravel()[x_index][n:][order]
        a_pin = np.linalg.solve(M_pin, -pin.nonLinearEffects(pmodel, data, q, v)) if mimic \
            else pin.aba(pmodel, data, q, v, np.zeros(n))
        assert np.max(np.abs(a - a_pin)) < 1e-9 * np.max(np.abs(a_pin))
    return compiled


def test_ur5_mass_matrix_and_accelerations_equal_pinocchio(ur5):
    path, pmodel = ur5
    model = from_urdf(path, gravity=G)
    assert equal_pinocchio(model, pmodel).method == "articulated-body recursion"
    limits = model.limits["shoulder_lift_joint"]
    assert limits["lower"] == pytest.approx(-3.14159265359) and limits["effort"] == 150.0
    assert limits["axis"] == (0.0, 1.0, 0.0) and limits["type"] == "revolute"


@pytest.mark.parametrize("mimic", [False, True])
def test_panda_equals_pinocchio(mimic):
    """The Panda (fixed joints with rotated origins, a hand, two prismatic fingers, the
    second mimicking the first): read as Pinocchio reads it with and without mimic joints;
    tied (one coordinate for both fingers) it is solved densely, since the fingers' one
    coordinate moves them in opposite directions."""
    pin = pytest.importorskip("pinocchio")
    path = robot_file("panda_description/urdf/panda.urdf")
    pmodel = pin.buildModelFromUrdf(path, mimic)
    pmodel.gravity.linear = np.array(G)
    model = from_urdf(path, gravity=G, mimic=mimic)
    compiled = equal_pinocchio(model, pmodel)
    assert compiled.lagrange.q.numel() == (8 if mimic else 9)
    assert model.limits["panda_finger_joint1"]["damping"] == 0.3


def test_ur5_inverse_dynamics_equals_pinocchio_rnea(ur5):
    """The UR5's joints follow sines exactly through Position sources on their axis
    flanges: acausal's inverse dynamics gives the drive torques (each joint's tau), which
    equal Pinocchio's RNEA at the same q, q̇, q̈ along 2 s."""
    import pinocchio as pin
    from acausal.analysis import inverse_dynamics
    from acausal.components import rotational, signals
    path, pmodel = ur5
    data = pmodel.createData()
    model = from_urdf(path, gravity=G)
    names = list(pmodel.names)[1:]
    rng = np.random.default_rng(3)
    A, F, P = rng.uniform(0.3, 1.2, 6), rng.uniform(0.2, 0.8, 6), rng.uniform(0, 6, 6)
    for i, nm in enumerate(names):
        drive = rotational.Position(exact=True, useSupport=True)
        ref = signals.Sine(amplitude=A[i], f=F[i], phase=P[i])
        setattr(model, f"drive{i}", drive)
        setattr(model, f"ref{i}", ref)
        joint = getattr(model, nm)
        model.connect(drive.flange, joint.axis)
        model.connect(drive.support, joint.support)
        model.connect(ref.y, drive.phi_ref)
    t = np.linspace(0, 2, 21)
    res = inverse_dynamics(acausal.compile(model), t)
    w = 2 * np.pi * F
    for k, tk in enumerate(t):
        q, qd = A * np.sin(w * tk + P), A * w * np.cos(w * tk + P)
        tau = pin.rnea(pmodel, data, q, qd, -w * w * q)
        ours = np.array([res[f"{nm}.tau"][k] for nm in names])
        assert np.max(np.abs(ours - tau)) < 1e-9 * max(1.0, np.max(np.abs(tau)))


def test_from_urdf_refuses_what_it_cannot_build(tmp_path):
    bad = tmp_path / "ball.urdf"
    bad.write_text('<robot name="r"><link name="a"/><link name="b"/>'
                   '<joint name="j" type="ball"><parent link="a"/><child link="b"/>'
                   '</joint></robot>')
    with pytest.raises(acausal.StructureError, match="joint 'j' is of type 'ball'"):
        from_urdf(bad)
    two = tmp_path / "two.urdf"
    two.write_text('<robot name="r"><link name="a"/><link name="b"/></robot>')
    with pytest.raises(acausal.StructureError, match="2 root links"):
        from_urdf(two)
    with pytest.raises(acausal.ParameterError, match="cannot read"):
        from_urdf(tmp_path / "missing.urdf")
    offset = tmp_path / "offset.urdf"
    offset.write_text('<robot name="r"><link name="a"/><link name="b"/><link name="c"/>'
                      '<joint name="j1" type="revolute"><parent link="a"/><child link="b"/>'
                      '</joint><joint name="j2" type="revolute"><parent link="b"/>'
                      '<child link="c"/><mimic joint="j1" offset="0.1"/></joint></robot>')
    with pytest.raises(acausal.StructureError, match="'j2' mimics 'j1' with multiplier 1 "
                                                     "and offset 0.1"):
        from_urdf(offset)
