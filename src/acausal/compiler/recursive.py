"""O(N) accelerations for trees: the articulated-body recursion on M q̈ = τ, planar and 3-D.

For a mechanism whose joint graph is a tree, whose inertia is rigid bodies
(PhysicsBuilder.rigid_body: planar or 3-D) plus 1-D inertias that each move with a single
coordinate (armature), the mass matrix need not be formed and factorized (O(N³) as a
symbolic solve): Featherstone's articulated-body algorithm, run with zero velocity and zero
external force, applies M⁻¹ to a vector in O(N). The velocity-dependent, gravity and applied
terms are already in τ (from the Lagrangian by AD, also O(N)).

Spatial vectors are resolved in the world and taken at the world origin, so no coordinate
transforms appear: motion vectors V = (ω, v_O), v_O the velocity of the body point at the
world origin, and force vectors (moment about the origin, force). Planar ones have 3
components (ω, v_Ox, v_Oy), 3-D ones 6; one recursion serves both (``STEPS[d]``), and a
model whose bodies are all planar or all 3-D uses it. A body's spatial inertia about the
origin is [[Ī_c + m c×c×ᵀ, m c×], [m c×ᵀ, m 1]] (c its centre of mass, Ī_c its rotational
inertia resolved in the world).

Each generalized velocity v_i is a 1-dof joint with motion vector S_i = ∂V/∂v_i of the
bodies it moves; its parent is the closest velocity that moves all of them. A joint of k
degrees of freedom (a spherical joint's 3 angular velocities, a free body's 6) plugs in as
k such steps with the same bodies, one the parent of the next: the recursion takes only
V = (∂V/∂v)·v, whatever the joint's positions (angles, quaternions) are, and k successive
1-dof steps eliminate the joint's k×k block D = (SᵀI^A S)⁻¹ pivot by pivot, which is
regular whenever the block is (positive definite: every pivot is positive).

Before it is used, the recursion is checked against the Lagrangian mass matrix at a random
state; a model outside its assumptions falls back to the dense solve.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..frames import parts, skew


def _spatial_planar() -> ca.Function:
    """(pose, rates, m, I) of a body's centre of mass -> its spatial velocity (ω, v_O) and its
    spatial inertia about the world origin (m [kg], I [kg.m²] about the centre of mass)."""
    pos, vel, m, I = ca.SX.sym("pos", 3), ca.SX.sym("vel", 3), ca.SX.sym("m"), ca.SX.sym("I")
    x, y = pos[0], pos[1]
    V = ca.vertcat(vel[2], vel[0] + vel[2] * y, vel[1] - vel[2] * x)
    mx, my = m * x, m * y
    Ib = ca.reshape(ca.vertcat(I + mx * x + my * y, -my, mx, -my, m, 0, mx, 0, m), 3, 3)
    return ca.Function("spatial", [ca.vertcat(pos, vel, m, I)], [V, Ib])


def _spatial_3d() -> ca.Function:
    """(pose (r_0, R.T), twist (v, w) resolved in the frame, m, r_CM, I) of a body's frame
    -> its spatial velocity (ω, v_O) and spatial inertia about the world origin, both
    resolved in the world (m [kg], r_CM [m] resolved in the frame, I [kg.m²] about the centre
    of mass, parallel to the frame)."""
    pos, vel, m = ca.SX.sym("pos", 12), ca.SX.sym("vel", 6), ca.SX.sym("m")
    r_CM, I = ca.SX.sym("r_CM", 3), ca.SX.sym("I", 3, 3)
    r0, T = parts(pos)
    w0 = ca.mtimes(T.T, vel[3:6])
    V = ca.vertcat(w0, ca.mtimes(T.T, vel[:3]) - ca.cross(w0, r0))
    c = r0 + ca.mtimes(T.T, r_CM)
    cx = skew(c)
    mcx = m * cx
    Ib = ca.blockcat([[ca.mtimes([T.T, I, T]) - ca.mtimes(mcx, cx), mcx],
                      [mcx.T, m * ca.SX.eye(3)]])
    return ca.Function("spatial3", [ca.vertcat(pos, vel, m, r_CM, ca.vec(I))], [V, Ib])


#: packed body (what PhysicsBuilder.rigid_body registers) -> (V, I_O), by its length
SPATIAL = {8: _spatial_planar(), 31: _spatial_3d()}


def _backward(d: int) -> ca.Function:
    """One leaves-to-root step of the recursion for coordinate i: from its articulated
    inertia IA, motion vector S, force τ, bias pA and armature J to U = IA S, D = 1/(Sᵀ U + J),
    u = τ − Sᵀ pA and what it passes to its parent: IA − U D Uᵀ, pA + U D u."""
    IA, S, tau = ca.SX.sym("IA", d, d), ca.SX.sym("S", d), ca.SX.sym("tau")
    pA, J = ca.SX.sym("pA", d), ca.SX.sym("J")
    U = ca.mtimes(IA, S)
    D = 1 / (ca.dot(S, U) + J)
    u = tau - ca.dot(S, pA)
    UD = U * D
    return ca.Function("aba_back", [IA, S, tau, pA, J],
                       [U, D, u, IA - ca.mtimes(UD, U.T), pA + UD * u])


def _forward(d: int) -> ca.Function:
    """One root-to-leaves step: q̈_i = D (u − Uᵀ a_parent), a_i = a_parent + S q̈_i."""
    U, S, ap = ca.SX.sym("U", d), ca.SX.sym("S", d), ca.SX.sym("ap", d)
    D, u = ca.SX.sym("D"), ca.SX.sym("u")
    qdd = (u - ca.dot(U, ap)) * D
    return ca.Function("aba_fwd", [U, D, u, S, ap], [qdd, ap + S * qdd])


#: the two steps in spatial vectors of dimension d (3 planar, 6 in space)
STEPS = {d: (_backward(d), _forward(d)) for d in (3, 6)}


def articulated_solve(q: ca.SX, qd: ca.SX, bodies: list, T_other, tau: ca.SX, M_times: ca.SX,
                      probe: ca.SX, p: ca.SX, p_default: list, origin=((), ())):
    """q̈ = M⁻¹ τ by the articulated-body recursion, or None when the model is outside its
    assumptions (checked numerically against ``M_times`` = M·probe, the Lagrangian mass
    matrix applied to the symbol ``probe``).

    ``q``, ``qd``: positions (every symbol of the configuration: the coordinates and the
    quaternions of free frames) and velocities (``qd`` the velocities the accelerations are
    of); ``bodies``: each rigid body packed as ``PhysicsBuilder.rigid_body`` registers it
    (planar: pose and rates of the centre of mass, m, I; 3-D: pose and twist of its frame,
    m, r_CM, I); ``T_other``: the rest of the kinetic energy (1-D inertias), which must be
    Σ ½ J_i q̇_i² (armature). ``origin``: (from, to) substitutions of the point where the
    result is used and checked (free frames' chart coordinates θ at 0: ``charts``; away
    from it the chart's rotation is not orthogonal, and the recursion's spatial inertias
    assume it is).
    """
    n = qd.numel()
    kinds = {b.numel() for b in bodies}
    if n < 2 or len(kinds) != 1:
        return None                                  # no bodies, or planar and 3-D mixed
    spatial = SPATIAL[kinds.pop()]
    d = spatial.size1_out(0)
    BACKWARD, FORWARD = STEPS[d]
    spatial = [spatial(b) for b in bodies]
    V = ca.vertcat(*[v for v, _ in spatial])
    Jall = ca.jacobian(V, qd)                       # one sweep: d rows per body
    rows, cols = Jall.sparsity().get_triplet()
    deps = [set() for _ in bodies]
    for r, c in zip(rows, cols):
        deps[r // d].add(c)
    deps = [frozenset(dep) for dep in deps]
    moved = [frozenset(b for b, dep in enumerate(deps) if i in dep) for i in range(n)]
    if any(not s for s in moved):
        return None                                  # a coordinate moves no body
    parent = []
    for i in range(n):
        anc = [j for j in range(n) if j != i and moved[j] >= moved[i]
               and (moved[j] != moved[i] or j < i)]
        parent.append(min(anc, key=lambda j: (len(moved[j]), -j)) if anc else None)
    S = [Jall[d * min(moved[i]):d * min(moved[i]) + d, i] for i in range(n)]
    own = [[] for _ in range(n)]                     # bodies whose deepest coordinate is i
    for b, dep in enumerate(deps):
        if dep:
            own[max(dep, key=lambda j: (-len(moved[j]), j))].append(b)
    order = _topological(parent)
    tau_value, tau = tau, ca.SX.sym("tau", n)
    Ib = [ib for _, ib in spatial]                    # about the world origin
    IA = [sum((Ib[b] for b in own[i]), ca.SX.zeros(d, d)) for i in range(n)]
    H = ca.hessian(T_other, qd)[0] if T_other is not None else ca.SX(n, n)
    r, c = H.sparsity().get_triplet()
    if any(i != j for i, j in zip(r, c)) or ca.depends_on(H, ca.vertcat(q, qd)):
        return None                       # 1-D inertia coupling coordinates: not armature
    pA = [ca.SX.zeros(d) for _ in range(n)]
    U, D, u = [None] * n, [None] * n, [None] * n
    for i in reversed(order):                       # leaves to root
        IA_i = ca.tril2symm(ca.tril(IA[i]))        # sums: the lower triangle suffices
        U[i], D[i], u[i], IA_up, pA_up = BACKWARD(IA_i, S[i], tau[i], pA[i], H[i, i])
        j = parent[i]
        if j is not None:
            IA[j], pA[j] = IA[j] + IA_up, pA[j] + pA_up
    a = [None] * n
    qdd = [None] * n
    for i in order:                                 # root to leaves
        ap = a[parent[i]] if parent[i] is not None else ca.SX.zeros(d)
        qdd[i], a[i] = FORWARD(U[i], D[i], u[i], S[i], ap)
    qdd = ca.vertcat(*qdd)
    frm, to = origin
    if frm:
        qdd, M_times = ca.substitute([qdd, M_times], list(frm), list(to))
    if not _agrees(q, tau, qdd, M_times, probe, p, p_default):
        return None
    return ca.substitute(qdd, tau, tau_value)


def _topological(parent: list) -> list[int]:
    """Coordinates ordered so that every parent comes before its children."""
    depth = {}

    def d(i):
        if i not in depth:
            depth[i] = 0 if parent[i] is None else d(parent[i]) + 1
        return depth[i]
    return sorted(range(len(parent)), key=lambda i: (d(i), i))


def _agrees(q, tau, qdd, M_times, probe, p, p_default) -> bool:
    """ABA(M x) == x at a random state: the recursion matches the Lagrangian inertia."""
    rng = np.random.default_rng(1)
    x = rng.standard_normal(tau.numel())
    Mx = ca.Function("Mx", [q, probe, p], [M_times], {"allow_free": True})
    f = ca.Function("aba", [q, tau, p], [qdd], {"allow_free": True})
    if Mx.has_free() or f.has_free():
        return False
    qn = rng.uniform(-1, 1, q.numel())
    got = np.array(f(qn, Mx(qn, x, p_default), p_default)).ravel()
    return bool(np.allclose(got, x, rtol=1e-8, atol=1e-10 * np.abs(x).max()))
