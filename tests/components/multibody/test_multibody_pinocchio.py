"""3-D chains and trees of revolute and prismatic joints against Pinocchio (an independent
rigid-body dynamics library): the mass matrix M(q) of ``compiled.lagrange`` equals
Pinocchio's CRBA to 1e-10 (its gravity and Coriolis terms Pinocchio's generalized gravity
and nonlinear effects), and the accelerations of the compiled model's right-hand side
(gravity, Coriolis and centrifugal terms included) equal Pinocchio's ABA to 1e-9, at random
states; the drive torques of inverse dynamics equal its RNEA. The models are built from
acausal's MultiBody components (``acausal.models.chain``: FixedRotation mounts,
Revolute/Prismatic joints, Bodies with full inertia tensors) and the same data are given
to Pinocchio directly (joint placements, unaligned axes, inertias)."""
from __future__ import annotations

import numpy as np
import pytest

import acausal
from acausal.models import chain

pin = pytest.importorskip("pinocchio")


def _unit(v):
    return v / np.linalg.norm(v)


def _rotation(n, angle):
    """T of MSL's planarRotation(n, angle): v_b = T v_a."""
    n = _unit(np.asarray(n))
    K = np.array([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
    return np.outer(n, n) + (np.eye(3) - np.outer(n, n)) * np.cos(angle) - K * np.sin(angle)


def random_links(rng, n: int, tree: bool) -> list[dict]:
    links = []
    for i in range(n):
        A = rng.normal(size=(3, 3)) * 0.3
        I = A @ A.T + 0.05 * np.eye(3)
        links.append(dict(
            parent=int(rng.integers(-1, i)) if tree else i - 1,
            kind="R" if rng.random() < 0.7 else "P",
            r=tuple(rng.uniform(-0.5, 0.5, 3)), n=tuple(_unit(rng.normal(size=3))),
            angle=float(rng.uniform(-180, 180)), axis=tuple(_unit(rng.normal(size=3))),
            body=dict(m=float(rng.uniform(0.5, 2.0)), r_CM=tuple(rng.uniform(-0.3, 0.3, 3)),
                      I_11=I[0, 0], I_22=I[1, 1], I_33=I[2, 2], I_21=I[1, 0], I_31=I[2, 0],
                      I_32=I[2, 1])))
    return links


def pinocchio_model(links, gravity):
    model = pin.Model()
    ids = []
    for i, link in enumerate(links):
        T = _rotation(link["n"], np.radians(link["angle"]))
        placement = pin.SE3(T.T, np.array(link["r"]))
        joint = (pin.JointModelRevoluteUnaligned if link["kind"] == "R"
                 else pin.JointModelPrismaticUnaligned)(np.array(link["axis"]))
        parent = 0 if link["parent"] < 0 else ids[link["parent"]]
        jid = model.addJoint(parent, joint, placement, f"joint{i}")
        b = link["body"]
        I = np.array([[b["I_11"], b["I_21"], b["I_31"]], [b["I_21"], b["I_22"], b["I_32"]],
                      [b["I_31"], b["I_32"], b["I_33"]]])
        model.appendBodyToJoint(jid, pin.Inertia(b["m"], np.array(b["r_CM"]), I),
                                pin.SE3.Identity())
        ids.append(jid)
    model.gravity.linear = np.asarray(gravity)
    return model


@pytest.mark.parametrize("n, tree, seed", [(3, False, 1), (6, False, 2), (7, True, 3),
                                           (5, True, 4)])
def test_mass_matrix_and_accelerations_equal_pinocchio(n, tree, seed):
    rng = np.random.default_rng(seed)
    links = random_links(rng, n, tree)
    g_dir = _unit(rng.normal(size=3))
    compiled = acausal.compile(chain(links, g=9.81, n=tuple(g_dir)))
    pmodel = pinocchio_model(links, 9.81 * g_dir)
    data = pmodel.createData()
    names = [f"joint{i}.{'phi' if link['kind'] == 'R' else 's'}" for i, link in enumerate(links)]
    order = [compiled.coordinates.index(nm) for nm in names]       # ours -> Pinocchio's order
    M_fun = compiled.lagrange.function("M", "gravity", "coriolis")
    p = compiled.param_vector()
    qd_names = compiled.lagrange.qd_names
    x_index = [compiled.x_names.index(nm) for nm in compiled.coordinates] + \
              [compiled.x_names.index(nm) for nm in qd_names]
    for _ in range(5):
        q, v = rng.uniform(-np.pi, np.pi, n), rng.normal(size=n)
        qa, va = np.empty(n), np.empty(n)             # in acausal's coordinate order
        qa[order], va[order] = q, v
        M, grav, cor = (np.array(x) for x in M_fun(0.0, qa, va, [], p))
        M_pin = pin.crba(pmodel, data, q)
        M_pin = np.triu(M_pin) + np.triu(M_pin, 1).T
        assert np.max(np.abs(M[np.ix_(order, order)] - M_pin)) < 1e-10 * max(
            1.0, np.max(np.abs(M_pin)))
        g_pin = pin.computeGeneralizedGravity(pmodel, data, q)       # torques holding it
        c_pin = pin.nonLinearEffects(pmodel, data, q, v) - g_pin       # C(q, q̇) q̇
        for ours, theirs in ((grav, g_pin), (cor, c_pin)):
            assert np.max(np.abs(ours.ravel()[order] + theirs)) < 1e-10 * max(
                1.0, np.max(np.abs(theirs)))
        x = np.empty(2 * n)
        x[x_index] = np.concatenate([qa, va])
        xdot = np.array(compiled.f(x=x, p=p)["xdot"]).ravel()[x_index]
        a = xdot[n:][order]
        a_pin = pin.aba(pmodel, data, q, v, np.zeros(n))
        assert np.max(np.abs(a - a_pin)) < 1e-9 * max(1.0, np.max(np.abs(a_pin)))


def test_joints_driven_through_axis_flanges_need_pinocchio_s_rnea_torques():
    """A 3-D chain whose joints follow sines exactly through 1-D Position sources on their
    axis flanges (rotational for revolutes, translational for prismatic joints): the drive
    torques and forces of acausal's inverse dynamics (the joints' tau / f) equal Pinocchio's
    RNEA at the same q, q̇, q̈ to 1e-9."""
    from acausal.analysis import inverse_dynamics
    from acausal.components import rotational, signals, translational
    rng = np.random.default_rng(11)
    n = 4
    links = random_links(rng, n, False)
    model = chain(links, useAxisFlange=True, g=9.81, n=(0, -1, 0))
    A, F, P = rng.uniform(0.2, 1.0, n), rng.uniform(0.2, 1.0, n), rng.uniform(0, 6, n)
    for i, link in enumerate(links):
        revolute = link["kind"] == "R"
        drive = (rotational if revolute else translational).Position(exact=True,
                                                                      useSupport=True)
        ref = signals.Sine(amplitude=A[i], f=F[i], phase=P[i])
        setattr(model, f"drive{i}", drive)
        setattr(model, f"ref{i}", ref)
        joint = getattr(model, f"joint{i}")
        model.connect(drive.flange, joint.axis)
        model.connect(drive.support, joint.support)
        model.connect(ref.y, drive.phi_ref if revolute else drive.s_ref)
    t = np.linspace(0, 2, 21)
    res = inverse_dynamics(acausal.compile(model), t)
    pmodel = pinocchio_model(links, [0, -9.81, 0])
    data = pmodel.createData()
    w = 2 * np.pi * F
    for k, tk in enumerate(t):
        q, qd = A * np.sin(w * tk + P), A * w * np.cos(w * tk + P)
        tau = pin.rnea(pmodel, data, q, qd, -w * w * q)
        ours = [res[f"joint{i}.{'tau' if link['kind'] == 'R' else 'f'}"][k]
                for i, link in enumerate(links)]
        assert np.max(np.abs(ours - tau)) < 1e-9 * max(1.0, np.max(np.abs(tau)))
