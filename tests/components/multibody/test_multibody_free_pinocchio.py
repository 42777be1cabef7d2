"""Joints with several degrees of freedom and free-floating bases against Pinocchio (an
independent rigid-body dynamics library), at random states:

- trees on a fixed base with Spherical (quaternion states), Universal, Cylindrical and
  Planar joints next to Revolute and Prismatic ones: M of ``compiled.lagrange`` (in the
  joints' velocities; a spherical joint's relative angular velocity resolved in frame_b, as
  Pinocchio's) equals Pinocchio's mass matrix to 1e-10 (its columns from RNEA at zero
  velocity: Pinocchio 4.1's CRBA leaves out the couplings of a composite joint's later
  degrees of freedom with its descendants in branched trees, which its RNEA and ABA have),
  the right-hand side's accelerations its ABA to 1e-9;
- chains on a free-floating base (a Body with no joint to the world, the implicit free
  joint, or a FreeMotion from the World), one with a FreeMotion inside the chain too:
  accelerations equal ABA with free-flyer joints to 1e-9.

Pinocchio's joints are its own: JointModelSpherical (quaternion), JointModelFreeFlyer, and
composites of its unaligned revolute/prismatic joints for Universal, Cylindrical, Planar.
MSL's quaternion Q = {n·sin(φ/2), cos(φ/2)} of T = planarRotation(n, φ) (world/frame_a to
the frame) has the components of Eigen's quaternion (x, y, z, w) of Pinocchio's rotation
R = Tᵀ. Pinocchio's free-flyer velocity is (T·v_0, w_a) (a FreeMotion's: (T_rel·v_rel_a,
w_rel_b)) and its acceleration the rate of those components: der(v_0) = Tᵀ(a_lin + w_a ×
T·v_0)."""
from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

import acausal
from acausal import frames
from acausal.components.multibody import (Body, Cylindrical, FixedRotation, FreeMotion,
                                          Planar, Prismatic, Revolute, Spherical, Universal,
                                          World)
from acausal.core import Model

pin = pytest.importorskip("pinocchio")


def _unit(v):
    return v / np.linalg.norm(v)


def _T(n, angle):
    """T of MSL's planarRotation(n, angle): v_b = T v_a."""
    return np.array(ca.evalf(frames.planar_rotation(_unit(np.asarray(n)), angle)))


def _T_of_Q(Q):
    return np.array(ca.evalf(frames.from_Q(Q)))


def _random_links(rng, kinds):
    links = []
    for i, kind in enumerate(kinds):
        A = rng.normal(size=(3, 3)) * 0.3
        I = A @ A.T + 0.05 * np.eye(3)
        links.append(dict(
            parent=int(rng.integers(-1, i)) if i else -1, kind=kind,
            r=rng.uniform(-0.5, 0.5, 3), n=_unit(rng.normal(size=3)),
            angle=float(rng.uniform(-180, 180)), axis=_unit(rng.normal(size=3)),
            axis2=_unit(rng.normal(size=3)),
            body=dict(m=float(rng.uniform(0.5, 2.0)), r_CM=tuple(rng.uniform(-0.3, 0.3, 3)),
                      I_11=I[0, 0], I_22=I[1, 1], I_33=I[2, 2], I_21=I[1, 0], I_31=I[2, 0],
                      I_32=I[2, 1])))
    return links


def _joint(link):
    kind, a, b = link["kind"], tuple(link["axis"]), tuple(link["axis2"])
    return {"R": lambda: Revolute(n=a), "P": lambda: Prismatic(n=a),
            "S": lambda: Spherical(), "F": lambda: FreeMotion(),
            "U": lambda: Universal(n_a=a, n_b=b),
            "C": lambda: Cylindrical(n=a), "L": lambda: Planar(n=a, n_x=b)}[kind]()


#: our position and velocity state names of each joint kind (after "joint{i}.")
_STATES = {"R": (["phi"], ["w"]), "P": (["s"], ["v"]),
           "S": ([f"Q[{k}]" for k in (1, 2, 3, 4)], [f"w_rel[{k}]" for k in (1, 2, 3)]),
           "F": ([f"r_rel_a[{k}]" for k in (1, 2, 3)] + [f"Q[{k}]" for k in (1, 2, 3, 4)],
                 [f"v_rel_a[{k}]" for k in (1, 2, 3)] + [f"w_rel_b[{k}]" for k in (1, 2, 3)]),
           "U": (["phi_a", "phi_b"], ["w_a", "w_b"]), "C": (["s", "phi"], ["v", "w"]),
           "L": (["s_x", "s_y", "phi"], ["v_x", "v_y", "w"])}


def _planar_axes(link):
    n, nx = link["axis"], link["axis2"]
    return _unit(np.cross(np.cross(n, nx), n)), _unit(np.cross(n, nx)), n


def _pin_joint(link):
    kind, a, b = link["kind"], link["axis"], link["axis2"]
    if kind == "R":
        return pin.JointModelRevoluteUnaligned(a)
    if kind == "P":
        return pin.JointModelPrismaticUnaligned(a)
    if kind == "S":
        return pin.JointModelSpherical()
    if kind == "F":
        return pin.JointModelFreeFlyer()
    parts = {"U": [pin.JointModelRevoluteUnaligned(a), pin.JointModelRevoluteUnaligned(b)],
             "C": [pin.JointModelPrismaticUnaligned(a), pin.JointModelRevoluteUnaligned(a)]}
    if kind == "L":
        ex, ey, n = _planar_axes(link)
        parts["L"] = [pin.JointModelPrismaticUnaligned(ex), pin.JointModelPrismaticUnaligned(ey),
                      pin.JointModelRevoluteUnaligned(n)]
    composite = pin.JointModelComposite()
    for j in parts[kind]:
        composite.addJoint(j)
    return composite


def _inertia(b):
    I = np.array([[b["I_11"], b["I_21"], b["I_31"]], [b["I_21"], b["I_22"], b["I_32"]],
                  [b["I_31"], b["I_32"], b["I_33"]]])
    return pin.Inertia(b["m"], np.array(b["r_CM"]), I)


def build(links, g_dir, base=None, base_body=None):
    """(acausal model, Pinocchio model): the links hang from the world, or from a free base
    body ``base_body`` ("Body": no joint, "FreeMotion": a FreeMotion from the World)."""
    m = Model("tree")
    m.world = World(g=9.81, n=tuple(g_dir))
    pmodel = pin.Model()
    ends, ids = [], []
    root, root_id = m.world.frame_b, 0
    if base is not None:
        m.base = Body(**base_body)
        if base == "FreeMotion":
            m.free = FreeMotion()
            m.connect(m.world.frame_b, m.free.frame_a)
            m.connect(m.free.frame_b, m.base.frame_a)
        root = m.base.frame_a
        root_id = pmodel.addJoint(0, pin.JointModelFreeFlyer(), pin.SE3.Identity(), "base")
        pmodel.appendBodyToJoint(root_id, _inertia(base_body), pin.SE3.Identity())
    for i, link in enumerate(links):
        mount = FixedRotation(r=tuple(link["r"]), n=tuple(link["n"]), angle=link["angle"])
        joint, body = _joint(link), Body(**link["body"])
        setattr(m, f"mount{i}", mount)
        setattr(m, f"joint{i}", joint)
        setattr(m, f"body{i}", body)
        m.connect(root if link["parent"] < 0 else ends[link["parent"]], mount.frame_a)
        m.connect(mount.frame_b, joint.frame_a)
        m.connect(joint.frame_b, body.frame_a)
        ends.append(joint.frame_b)
        placement = pin.SE3(_T(link["n"], np.radians(link["angle"])).T, np.array(link["r"]))
        parent = root_id if link["parent"] < 0 else ids[link["parent"]]
        jid = pmodel.addJoint(parent, _pin_joint(link), placement, f"joint{i}")
        pmodel.appendBodyToJoint(jid, _inertia(link["body"]), pin.SE3.Identity())
        ids.append(jid)
    pmodel.gravity.linear = 9.81 * np.asarray(g_dir)
    return m, pmodel


def _random_state(rng, links, base):
    """Pinocchio's (q, v) at random, and our x by name."""
    q, v, x = [], [], {}
    if base is not None:
        Q, r, vl, w = _unit(rng.normal(size=4)), rng.normal(size=3), rng.normal(size=3), \
            rng.normal(size=3)
        q += list(r) + list(Q)
        v += list(vl) + list(w)
        pre = "free.r_rel_a", "free.v_rel_a", "free.Q", "free.w_rel_b"
        if base == "Body":
            pre = "base.frame_a.r_0", "base.v_0", "base.Q", "base.w_a"
        v0 = _T_of_Q(Q).T @ vl
        for k in range(3):
            x[f"{pre[0]}[{k + 1}]"], x[f"{pre[1]}[{k + 1}]"] = r[k], v0[k]
            x[f"{pre[3]}[{k + 1}]"] = w[k]
        for k in range(4):
            x[f"{pre[2]}[{k + 1}]"] = Q[k]
    for i, link in enumerate(links):
        pos, vel = _STATES[link["kind"]]
        qi = list(_unit(rng.normal(size=4))) if link["kind"] == "S" else \
            list(rng.uniform(-np.pi, np.pi, len(pos)))
        vi = list(rng.normal(size=len(vel)))
        q += qi
        v += vi
        if link["kind"] == "F":          # a quaternion; v_rel_a = der(r_rel_a) = Tᵀ·v_lin
            qi[3:] = _unit(rng.normal(size=4))
            q[-4:] = qi[3:]
            vi = list(_T_of_Q(qi[3:]).T @ vi[:3]) + vi[3:]
        x.update({f"joint{i}.{n}": val for n, val in zip(pos, qi)})
        x.update({f"joint{i}.{n}": val for n, val in zip(vel, vi)})
    return np.array(q), np.array(v), x


def _our_rates(links, base, Q_base, v_base):
    """Names of our states whose rates are Pinocchio's accelerations, in its order."""
    names = []
    if base is not None:
        names += [f"{'free.v_rel_a' if base == 'FreeMotion' else 'base.v_0'}[{k}]"
                  for k in (1, 2, 3)]
        names += [f"{'free.w_rel_b' if base == 'FreeMotion' else 'base.w_a'}[{k}]"
                  for k in (1, 2, 3)]
    for i, link in enumerate(links):
        names += [f"joint{i}.{n}" for n in _STATES[link["kind"]][1]]
    return names


def _to_rates(links, base, q, v, a):
    """Pinocchio's accelerations as our states' rates: a free-flyer's linear part becomes
    der(v_0) / der(v_rel_a) = Tᵀ(a_lin + ω × v_lin), resolved in the parent."""
    a, iq, iv = a.copy(), 0, 0
    kinds = (["F"] if base is not None else []) + [link["kind"] for link in links]
    for kind in kinds:
        nq = {"R": 1, "P": 1, "S": 4, "F": 7, "U": 2, "C": 2, "L": 3}[kind]
        nv = {"S": 3, "F": 6}.get(kind, nq)
        if kind == "F":
            T = _T_of_Q(q[iq + 3:iq + 7])
            a[iv:iv + 3] = T.T @ (a[iv:iv + 3] + np.cross(v[iv + 3:iv + 6], v[iv:iv + 3]))
        iq, iv = iq + nq, iv + nv
    return a


def _accelerations(compiled, x_by_name, names):
    p = compiled.param_vector()
    x = np.array([x_by_name[n] for n in compiled.x_names])
    xdot = np.array(compiled.f(x=x, p=p)["xdot"]).ravel()
    return np.array([xdot[compiled.x_names.index(n)] for n in names])


@pytest.mark.parametrize("kinds, seed", [("SRS", 1), ("UCLRP", 2), ("SUSCL", 3),
                                         ("RSPSU", 4)])
def test_trees_with_spherical_universal_cylindrical_planar_joints_equal_pinocchio(kinds,
                                                                                  seed):
    rng = np.random.default_rng(seed)
    links = _random_links(rng, kinds)
    g_dir = _unit(rng.normal(size=3))
    model, pmodel = build(links, g_dir)
    compiled = acausal.compile(model)
    data = pmodel.createData()
    L = compiled.lagrange
    M_fun = L.function("M")
    names = _our_rates(links, None, None, None)
    order = [L.qd_names.index(n) for n in names]         # Pinocchio's order in ours
    p = compiled.param_vector()
    for _ in range(4):
        q, v, x = _random_state(rng, links, None)
        M = np.array(M_fun(0.0, [x[n] for n in L.q_state_names], [x[n] for n in L.qd_names],
                           [], p))
        b = pin.rnea(pmodel, data, q, np.zeros(pmodel.nv), np.zeros(pmodel.nv))
        M_pin = np.column_stack([pin.rnea(pmodel, data, q, np.zeros(pmodel.nv), e) - b
                                 for e in np.eye(pmodel.nv)])
        assert np.max(np.abs(M[np.ix_(order, order)] - M_pin)) < 1e-10 * max(
            1.0, np.max(np.abs(M_pin)))
        a_pin = _to_rates(links, None, q, v, pin.aba(pmodel, data, q, v, np.zeros(pmodel.nv)))
        a = _accelerations(compiled, x, names)
        assert np.max(np.abs(a - a_pin)) < 1e-9 * max(1.0, np.max(np.abs(a_pin)))


@pytest.mark.parametrize("base, kinds, seed", [("Body", "RRSP", 5), ("FreeMotion", "RSR", 6),
                                               ("Body", "SPRU", 7), ("FreeMotion", "RFSR", 8)])
def test_free_floating_chains_equal_pinocchio_aba_with_a_free_flyer(base, kinds, seed):
    rng = np.random.default_rng(seed)
    links = _random_links(rng, kinds)
    links[1]["parent"] = 0                      # a chain
    for i in range(2, len(links)):
        links[i]["parent"] = i - 1
    A = rng.normal(size=(3, 3)) * 0.4
    I = A @ A.T + 0.1 * np.eye(3)
    base_body = dict(m=2.0, r_CM=tuple(rng.uniform(-0.2, 0.2, 3)), I_11=I[0, 0],
                     I_22=I[1, 1], I_33=I[2, 2], I_21=I[1, 0], I_31=I[2, 0], I_32=I[2, 1])
    g_dir = _unit(rng.normal(size=3))
    model, pmodel = build(links, g_dir, base, base_body)
    compiled = acausal.compile(model)
    assert len(compiled.x_names) == 13 + sum(
        len(_STATES[k][0]) + len(_STATES[k][1]) for k in kinds)
    data = pmodel.createData()
    names = _our_rates(links, base, None, None)
    for _ in range(4):
        q, v, x = _random_state(rng, links, base)
        a_pin = _to_rates(links, base, q, v, pin.aba(pmodel, data, q, v, np.zeros(pmodel.nv)))
        a = _accelerations(compiled, x, names)
        assert np.max(np.abs(a - a_pin)) < 1e-9 * max(1.0, np.max(np.abs(a_pin)))
