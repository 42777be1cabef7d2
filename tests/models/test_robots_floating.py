"""Robots with a floating base from URDF files (``from_urdf(..., floating_base=True)``:
the root link on a FreeMotion from the World) against Pinocchio with a JointModelFreeFlyer
root: Solo12 and Talos (a quadruped and a humanoid of example-robot-data): M(q) equals
CRBA to 1e-10 and the accelerations ABA to 1e-9, at random states. Pinocchio's free-flyer velocity is in the
root link's frame, the FreeMotion's linear velocity v_rel_a in the world's: M and the
accelerations are compared through that map. A ``planar`` URDF joint against Pinocchio's
JointModelPlanar and a ``floating`` joint in the middle of a tree likewise; a
``continuous`` joint records no position limits."""
from __future__ import annotations

import numpy as np
import pytest

import acausal
from acausal.multibody import from_urdf

G = (0.0, 0.0, -9.81)


def _pinocchio():
    return pytest.importorskip("pinocchio")


def _robot_file(relative: str) -> str:
    from importlib.metadata import PackageNotFoundError, distribution
    try:
        return str(distribution("example-robot-data").locate_file(
            f"cmeel.prefix/share/example-robot-data/robots/{relative}"))
    except PackageNotFoundError:
        pytest.skip("example-robot-data is not installed (the robots extra)")


def _skew(w):
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def _equal_pinocchio(model, pmodel, blocks, states=4, seed=11):
    """M and the accelerations of ``model`` against Pinocchio's CRBA and ABA at random
    states. ``blocks``: per Pinocchio joint (in its order) a function (q_pin_i, v_pin_i) ->
    (our positions in the states' layout, our rates, G_i, g_i) with our rates = G_i·v_pin_i
    and our accelerations = G_i·v̇_pin_i + g_i; the sampler of q_pin_i is its first
    argument's shape."""
    pin = _pinocchio()
    data = pmodel.createData()
    compiled = acausal.compile(model)
    L = compiled.lagrange
    M_fun = L.function("M")
    p = compiled.param_vector()
    rng = np.random.default_rng(seed)
    for _ in range(states):
        q = pin.randomConfiguration(pmodel, np.maximum(pmodel.lowerPositionLimit, -3),
                                    np.minimum(pmodel.upperPositionLimit, 3))
        v = rng.normal(size=pmodel.nv)
        qs, rates, Gs, gs = {}, {}, [], []
        for j, (name, joint) in enumerate(zip(pmodel.names, pmodel.joints)):
            if j == 0:
                continue
            qi = q[joint.idx_q:joint.idx_q + joint.nq]
            vi = v[joint.idx_v:joint.idx_v + joint.nv]
            pos, rate, Gi, gi = blocks[name](qi, vi)
            qs.update(pos)
            rates.update(rate)
            Gs.append(Gi)
            gs.append(gi)
        qa = np.array([qs[n] for n in L.q_state_names])
        va = np.array([rates[n] for n in L.qd_names])
        order = [L.qd_names.index(n) for n in _rate_order(blocks, pmodel, q, v)]
        Gm = _block_diag(Gs)
        M = np.array(M_fun(0.0, qa, va, [], p))[np.ix_(order, order)]
        M_pin = pin.crba(pmodel, data, q)
        M_pin = np.triu(M_pin) + np.triu(M_pin, 1).T
        assert np.max(np.abs(Gm.T @ M @ Gm - M_pin)) < 1e-10 * np.max(np.abs(M_pin))
        x = np.empty(compiled.x.numel())
        names = compiled.x_names
        for n, val in list(zip(L.q_state_names, qa)) + list(zip(L.qd_names, va)):
            x[names.index(n)] = val
        xdot = np.array(compiled.f(x=x, p=p)["xdot"]).ravel()
        acc = np.array([xdot[names.index(L.qd_names[k])] for k in order])
        a_pin = pin.aba(pmodel, data, q, v, np.zeros(pmodel.nv))
        expected = Gm @ a_pin + np.concatenate(gs)
        assert np.max(np.abs(acc - expected)) < 1e-9 * np.max(np.abs(expected))
    return compiled


def _rate_order(blocks, pmodel, q, v):
    """Our rate names in Pinocchio's velocity order."""
    out = []
    for j, (name, joint) in enumerate(zip(pmodel.names, pmodel.joints)):
        if j:
            qi = q[joint.idx_q:joint.idx_q + joint.nq]
            vi = v[joint.idx_v:joint.idx_v + joint.nv]
            out += list(blocks[name](qi, vi)[1])
    return out


def _block_diag(blocks):
    n = sum(b.shape[0] for b in blocks)
    out, k = np.zeros((n, n)), 0
    for b in blocks:
        out[k:k + b.shape[0], k:k + b.shape[0]] = b
        k += b.shape[0]
    return out


def _free_flyer(prefix):
    """Pinocchio's free flyer q = (r, quaternion x, y, z, w), v = (v, ω) in the child's
    frame; ours r_rel_a, Q (MSL's order: vector first), v_rel_a = R·v (R: child to parent),
    w_rel_b = ω; der(v_rel_a) = R·(v̇ + ω × v)."""
    def block(qi, vi):
        pin = _pinocchio()
        R = pin.Quaternion(qi[6], *qi[3:6]).toRotationMatrix()
        v_a = R @ vi[:3]
        pos = {f"{prefix}.r_rel_a[{k + 1}]": qi[k] for k in range(3)}
        pos.update({f"{prefix}.Q[{k + 1}]": qi[3 + k] for k in range(4)})
        rate = {f"{prefix}.v_rel_a[{k + 1}]": v_a[k] for k in range(3)}
        rate.update({f"{prefix}.w_rel_b[{k + 1}]": vi[3 + k] for k in range(3)})
        G = np.eye(6)
        G[:3, :3] = R
        g = np.concatenate([R @ np.cross(vi[3:], vi[:3]), np.zeros(3)])
        return pos, rate, G, g
    return block


def _revolute(name):
    def block(qi, vi):
        return {f"{name}.phi": qi[0]}, {f"{name}.w": vi[0]}, np.eye(1), np.zeros(1)
    return block


@pytest.mark.parametrize("robot, dof", [("solo_description/robots/solo12.urdf", 18),
                                        ("talos_data/robots/talos_reduced.urdf", 38)],
                         ids=["solo12", "talos_reduced"])
def test_legged_robot_on_a_floating_base_equals_pinocchio_free_flyer(robot, dof):
    """Solo12 (a quadruped: 12 revolute joints, fixed ones with rotated origins) and Talos
    (a humanoid, reduced: 32 revolute joints; its grippers' mimic joints read as joints of
    their own, as Pinocchio reads them by default) with floating_base: a FreeMotion
    ``root_joint`` (13 states) from the World, the accelerations by the articulated-body
    recursion."""
    pin = _pinocchio()
    path = _robot_file(robot)
    pmodel = pin.buildModelFromUrdf(path, pin.JointModelFreeFlyer())
    pmodel.gravity.linear = np.array(G)
    model = from_urdf(path, gravity=G, floating_base=True, mimic=False)
    blocks = {n: _revolute(n) for n in list(pmodel.names)[2:]}
    blocks["root_joint"] = _free_flyer("root_joint")
    compiled = _equal_pinocchio(model, pmodel, blocks)
    assert len(compiled.lagrange.qd_names) == dof == pmodel.nv
    assert compiled.method == "articulated-body recursion"


URDF_PLANAR = """<robot name="r">
  <link name="base"/>
  <link name="slider"><inertial><origin xyz="0.1 -0.05 0.2" rpy="0.3 0 0.2"/>
    <mass value="2.0"/><inertia ixx="0.1" ixy="0.01" ixz="0" iyy="0.2" iyz="0.02" izz="0.3"/>
  </inertial></link>
  <link name="arm"><inertial><origin xyz="0.3 0 0"/><mass value="1.0"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.05" iyz="0" izz="0.05"/></inertial></link>
  <link name="pod"><inertial><origin xyz="0 0.1 0"/><mass value="0.5"/>
    <inertia ixx="0.02" ixy="0" ixz="0.001" iyy="0.03" iyz="0" izz="0.04"/></inertial></link>
  <joint name="plane" type="planar"><parent link="base"/><child link="slider"/>
    <origin xyz="0 0 0.5" rpy="0.2 -0.1 0"/><axis xyz="0 0 1"/></joint>
  <joint name="elbow" type="continuous"><parent link="slider"/><child link="arm"/>
    <origin xyz="0.2 0 0"/><axis xyz="0 1 0"/><limit lower="-1" upper="1" effort="5" velocity="2"/></joint>
  <joint name="hover" type="floating"><parent link="arm"/><child link="pod"/>
    <origin xyz="0.6 0 0" rpy="0 0.4 0"/></joint>
</robot>"""


def test_planar_continuous_and_floating_joints_equal_pinocchio(tmp_path):
    """A planar joint (Pinocchio's JointModelPlanar: q = x, y, cos θ, sin θ; v = the
    velocity in the child's frame), a continuous joint (JointModelRUBY: cos, sin) and a
    floating joint (a free flyer in mid-tree) from one URDF: M and accelerations as above;
    the continuous joint's limits hold effort and velocity, not lower and upper."""
    pin = _pinocchio()
    path = tmp_path / "planar.urdf"
    path.write_text(URDF_PLANAR)
    pmodel = pin.buildModelFromUrdf(str(path))
    pmodel.gravity.linear = np.array(G)
    model = from_urdf(path, gravity=G)
    assert dict(model.limits["elbow"]) == {"effort": 5.0, "velocity": 2.0, "type": "continuous",
                                           "axis": (0.0, 1.0, 0.0)}

    def planar(qi, vi):
        c, s = qi[2], qi[3]
        R = np.array([[c, -s], [s, c]])
        xy_dot = R @ vi[:2]
        pos = {"plane.s_x": qi[0], "plane.s_y": qi[1], "plane.phi": np.arctan2(s, c)}
        rate = {"plane.v_x": xy_dot[0], "plane.v_y": xy_dot[1], "plane.w": vi[2]}
        G = np.eye(3)
        G[:2, :2] = R
        g = np.concatenate([vi[2] * R @ np.array([-vi[1], vi[0]]), [0.0]])
        return pos, rate, G, g

    def continuous(qi, vi):
        return {"elbow.phi": np.arctan2(qi[1], qi[0])}, {"elbow.w": vi[0]}, np.eye(1), \
            np.zeros(1)

    _equal_pinocchio(model, pmodel, {"plane": planar, "elbow": continuous,
                                     "hover": _free_flyer("hover")})
