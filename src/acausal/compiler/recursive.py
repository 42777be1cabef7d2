"""O(N) accelerations for planar trees: the articulated-body recursion on M q̈ = τ.

For a mechanism whose joint graph is a tree, whose inertia is planar rigid bodies
(PhysicsBuilder.rigid_body) plus 1-D inertias that each move with a single coordinate
(armature), the mass matrix need not be formed and factorized (O(N³) as a symbolic solve):
Featherstone's articulated-body algorithm, run with zero velocity and zero external force,
applies M⁻¹ to a vector in O(N). The velocity-dependent, gravity and applied terms are
already in τ (from the Lagrangian by AD, also O(N)).

Spatial vectors are planar (ω, v_Ox, v_Oy): velocities of the body point at the world origin,
and forces (moment about the origin, fx, fy), all in world coordinates, so no coordinate
transforms appear. Each coordinate is a 1-dof joint with motion vector S_i = ∂V/∂q̇_i of the
bodies it moves; its parent is the closest coordinate that moves all of them (a free body's
x, y, phi are a chain of three such joints).

Before it is used, the recursion is checked against the Lagrangian mass matrix at a random
state; a model outside its assumptions falls back to the dense solve.
"""
from __future__ import annotations

import casadi as ca
import numpy as np


def _spatial() -> ca.Function:
    """(pose, rates, m, I) of a body's centre of mass -> its spatial velocity (ω, v_O) and its
    spatial inertia about the world origin (m [kg], I [kg.m²] about the centre of mass)."""
    pos, vel, m, I = ca.SX.sym("pos", 3), ca.SX.sym("vel", 3), ca.SX.sym("m"), ca.SX.sym("I")
    x, y = pos[0], pos[1]
    V = ca.vertcat(vel[2], vel[0] + vel[2] * y, vel[1] - vel[2] * x)
    mx, my = m * x, m * y
    Ib = ca.reshape(ca.vertcat(I + mx * x + my * y, -my, mx, -my, m, 0, mx, 0, m), 3, 3)
    return ca.Function("spatial", [pos, vel, m, I], [V, Ib])


def _backward() -> ca.Function:
    """One leaves-to-root step of the recursion for coordinate i: from its articulated
    inertia IA, motion vector S, force τ, bias pA and armature J to U = IA S, D = 1/(Sᵀ U + J),
    u = τ − Sᵀ pA and what it passes to its parent: IA − U D Uᵀ, pA + U D u."""
    IA, S, tau = ca.SX.sym("IA", 3, 3), ca.SX.sym("S", 3), ca.SX.sym("tau")
    pA, J = ca.SX.sym("pA", 3), ca.SX.sym("J")
    U = ca.mtimes(IA, S)
    D = 1 / (ca.dot(S, U) + J)
    u = tau - ca.dot(S, pA)
    UD = U * D
    return ca.Function("aba_back", [IA, S, tau, pA, J],
                       [U, D, u, IA - ca.mtimes(UD, U.T), pA + UD * u])


def _forward() -> ca.Function:
    """One root-to-leaves step: q̈_i = D (u − Uᵀ a_parent), a_i = a_parent + S q̈_i."""
    U, S, ap = ca.SX.sym("U", 3), ca.SX.sym("S", 3), ca.SX.sym("ap", 3)
    D, u = ca.SX.sym("D"), ca.SX.sym("u")
    qdd = (u - ca.dot(U, ap)) * D
    return ca.Function("aba_fwd", [U, D, u, S, ap], [qdd, ap + S * qdd])


SPATIAL, BACKWARD, FORWARD = _spatial(), _backward(), _forward()


def articulated_solve(q: ca.SX, qd: ca.SX, bodies: list, T_other, tau: ca.SX, M_times: ca.SX,
                      probe: ca.SX, p: ca.SX, p_default: list):
    """q̈ = M⁻¹ τ by the articulated-body recursion, or None when the model is outside its
    assumptions (checked numerically against ``M_times`` = M·probe, the Lagrangian mass
    matrix applied to the symbol ``probe``).

    ``bodies``: (pos, vel, m, I) of each rigid body's centre of mass frame; ``T_other``: the
    rest of the kinetic energy (1-D inertias), which must be Σ ½ J_i q̇_i² (armature).
    """
    n = q.numel()
    if n < 2 or not bodies:
        return None
    spatial = [SPATIAL(pos, vel, m, I) for pos, vel, m, I in bodies]
    V = ca.vertcat(*[v for v, _ in spatial])
    Jall = ca.jacobian(V, qd)                       # one sweep: 3 rows per body
    rows, cols = Jall.sparsity().get_triplet()
    deps = [set() for _ in bodies]
    for r, c in zip(rows, cols):
        deps[r // 3].add(c)
    deps = [frozenset(d) for d in deps]
    moved = [frozenset(b for b, d in enumerate(deps) if i in d) for i in range(n)]
    if any(not s for s in moved):
        return None                                  # a coordinate moves no body
    parent = []
    for i in range(n):
        anc = [j for j in range(n) if j != i and moved[j] >= moved[i]
               and (moved[j] != moved[i] or j < i)]
        parent.append(min(anc, key=lambda j: (len(moved[j]), -j)) if anc else None)
    S = [Jall[3 * min(moved[i]):3 * min(moved[i]) + 3, i] for i in range(n)]
    own = [[] for _ in range(n)]                     # bodies whose deepest coordinate is i
    for b, d in enumerate(deps):
        if d:
            own[max(d, key=lambda j: (-len(moved[j]), j))].append(b)
    order = _topological(parent)
    tau_value, tau = tau, ca.SX.sym("tau", n)
    Ib = [ib for _, ib in spatial]                    # about the world origin
    IA = [sum((Ib[b] for b in own[i]), ca.SX.zeros(3, 3)) for i in range(n)]
    H = ca.hessian(T_other, qd)[0] if T_other is not None else ca.SX(n, n)
    r, c = H.sparsity().get_triplet()
    if any(i != j for i, j in zip(r, c)) or ca.depends_on(H, ca.vertcat(q, qd)):
        return None                       # 1-D inertia coupling coordinates: not armature
    pA = [ca.SX.zeros(3) for _ in range(n)]
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
        ap = a[parent[i]] if parent[i] is not None else ca.SX.zeros(3)
        qdd[i], a[i] = FORWARD(U[i], D[i], u[i], S[i], ap)
    qdd = ca.vertcat(*qdd)
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
    x = rng.standard_normal(q.numel())
    Mx = ca.Function("Mx", [q, probe, p], [M_times], {"allow_free": True})
    f = ca.Function("aba", [q, tau, p], [qdd], {"allow_free": True})
    if Mx.has_free() or f.has_free():
        return False
    qn = rng.uniform(-1, 1, q.numel())
    got = np.array(f(qn, Mx(qn, x, p_default), p_default)).ravel()
    return bool(np.allclose(got, x, rtol=1e-8, atol=1e-10 * np.abs(x).max()))
