"""The motion solve: Lagrange's residuals R(q, q̇, q̈) = 0 turned into the states' equations.

The accelerations are solved elementwise when the mass matrix is diagonal (1-D chains), by
the O(N) articulated-body recursion for planar trees of rigid bodies, and by a symbolic solve
otherwise. Closed loops get multipliers in the stabilized index-2 form of Gear, Gupta and
Leimkuhler; coordinates without mass become algebraic variables of a semi-explicit DAE.

A coordinate without mass that a loop constraint depends on (a joint between two massless
links of a loop, where no choice of the tree gives it mass: ``kinematics.choose_tree``) is
a dependent coordinate of the loop: the constraint rows determine it, not a law of its own.
It stays with the loop's coordinates: its acceleration comes from the constrained solve
(its row of the mass matrix is zero, the row Φ̈ = 0 fixes it; the multipliers λ make its
force balance hold), its position and velocity are held on Φ = 0 and Φ̇ = 0 by the same
stabilizing multipliers as the others. The constrained solve is regular when every motion
the loops allow moves some mass; structurally, when the massless coordinates of the loops
can each be matched to a loop row of its own. A loop whose motion moves no mass along some
coordinate (a massless mechanism held only by springs and dampers) is refused, naming the
coordinates.
"""
from __future__ import annotations

from dataclasses import dataclass

import casadi as ca

from ..errors import SingularModelError, StructureError
from .charts import at_origin
from .recursive import articulated_solve
from .symbolic import der_with, small_solve

_vc = ca.vertcat


@dataclass(frozen=True)
class GGL:
    """The stabilized index-2 form of the loop constraints (Gear–Gupta–Leimkuhler):
    q̇ = q̇_state + Φ_qᵀμ, v̇ = q̈ + Φ_qᵀν, 0 = Φ, 0 = Φ̇, with μ = ν = 0 on the exact
    solution; a row switched off (``active`` 0) reads μ_i = 0, ν_i = 0 instead."""
    mu: ca.SX            # multipliers of the position constraints Φ = 0
    nu: ca.SX            # multipliers of the velocity constraints Φ̇ = 0
    dq: ca.SX            # Φ_qᵀ μ, added to the coordinates' rates
    dv: ca.SX            # Φ_qᵀ ν, added to the accelerations
    phi: ca.SX           # the position rows (or μ for switched-off rows)
    phid: ca.SX          # the velocity rows (or ν for switched-off rows)


@dataclass(frozen=True)
class Motion:
    """The mechanical part of the DAE, after the accelerations are solved.

    States: ``q_diff`` (coordinates with mass and the massless ones the loops determine, then
    massless ones a damper holds) with rates ``q_diff_dot``, and ``qd_diff`` (rates of the
    former) with derivatives ``qdd_diff``; algebraic variables ``alg_vars`` (massless nodes'
    rates or positions, then the loop multipliers μ, ν) with residuals ``alg_res``. ``qdd``
    are all accelerations, ``lam`` the loop multipliers λ (the constraint reactions),
    ``active`` the switches of the loop rows; ``substitute_from`` → ``substitute_to``
    replaces what the solve eliminated (the rates of spring-only massless nodes) in other
    expressions."""
    method: str
    q_diff: ca.SX
    q_diff_dot: ca.SX
    qd_diff: ca.SX
    qdd_diff: ca.SX
    alg_vars: ca.SX
    alg_res: ca.SX
    qdd: ca.SX
    lam: ca.SX
    active: ca.SX
    loop_mu: list[int]        # positions of μ in alg_vars
    loop_nu: list[int]        # positions of ν in alg_vars
    substitute_from: list
    substitute_to: list

    @property
    def n_x(self) -> int:
        return self.q_diff.numel() + self.qd_diff.numel()

    @property
    def n_z(self) -> int:
        return self.alg_vars.numel()


def _rows(v, ks):
    return v[ks] if ks else ca.SX(0, 1)


def _check_massless(tree, R0, vel_alg: list[int], pos_alg: list[int]) -> None:
    """The massless coordinates' equations (forces in balance) must fix them: a node whose
    forces depend on neither its position nor its speed (a massless Mass with only a given
    force on it) is singular, named in a SingularModelError."""
    order = vel_alg + pos_alg
    if not order:
        return
    J = ca.jacobian(_vc(_rows(R0, vel_alg), _rows(R0, pos_alg)),
                    _vc(_rows(tree.qd, vel_alg), _rows(tree.q, pos_alg)))
    if ca.sprank(J) == len(order):
        return
    free = [order[i] for i in range(len(order)) if J[i, :].nnz() == 0] or order
    raise SingularModelError(
        f"the massless node(s) {', '.join(tree.q_names[k] for k in free)}: the forces on it "
        f"depend neither on its position nor on its speed (no mass, spring or damper holds "
        f"it), so nothing fixes its motion; give it a mass, or connect a spring or damper")


def _loop_determined(phi_q: ca.SX, massless: list[int], names: list[str]) -> list[int]:
    """The massless coordinates that the loop rows enter, each matched (structurally) to a
    row of its own: the constrained solve determines them. A massless coordinate in a loop
    that no row is left for moves no mass along a motion the loops allow: refused."""
    rows_of: dict[int, list[int]] = {}
    for r, c in zip(*phi_q.sparsity().get_triplet()):
        rows_of.setdefault(c, []).append(r)
    entered = [k for k in massless if k in rows_of]
    owner: dict[int, int] = {}                    # row -> coordinate (augmenting paths)

    def augment(k, seen):
        for r in rows_of[k]:
            if r not in seen:
                seen.add(r)
                if r not in owner or augment(owner[r], seen):
                    owner[r] = k
                    return True
        return False

    free = [k for k in entered if not augment(k, set())]
    if free:
        raise StructureError(
            f"a closed kinematic loop can move without moving any mass: its coordinates "
            f"{', '.join(names[k] for k in entered)} carry none, and the loop constraints "
            f"leave {len(free)} of them free (a massless mechanism held only by springs or "
            f"dampers is not supported); give a part of the loop mass or inertia")
    return entered


def solve_motion(tree, R_q, phi, ws, bodies, resolve) -> Motion:
    """The Motion of the residuals ``R_q`` (in q, q̇, q̈ of ``tree``) with loop constraints
    ``phi``; ``bodies`` = (rigid bodies, other kinetic energy) for the recursion."""
    nq = tree.q.numel()
    q, qd, qdd = tree.q, tree.qd, tree.qdd
    R0 = ca.substitute(R_q, qdd, ca.SX.zeros(nq))
    method = "diagonal mass matrix"
    sub_from, sub_to = [], []
    sp = ca.jacobian_sparsity(R_q, qdd)           # the mass matrix's pattern, without it
    row_nnz = [0] * nq
    for r in sp.get_triplet()[0]:
        row_nnz[r] += 1
    massive = [k for k in range(nq) if row_nnz[k] > 0]
    massless = [k for k in range(nq) if row_nnz[k] == 0]
    nc = phi.numel()
    probe = ca.SX.sym("probe", nq)
    M_times = ca.jtimes(R_q, qdd, probe)           # M·probe in O(N)
    if ca.depends_on(M_times, qdd):
        raise SingularModelError("the equations of motion are not linear in the accelerations "
                                 "(a force depends nonlinearly on an acceleration)")
    qdM = _rows(qd, massive)
    diagonal = all(i == j for i, j in zip(*sp.get_triplet()))
    qdd_M = None
    if not nc and not massless and not diagonal and nq > 2:
        # a tree: the O(N) articulated-body recursion, if the model fits it
        # (the positions include the quaternions of free frames, the charts' bases; the
        # charts' coordinates θ are 0 where the result is used)
        positions = _vc(q, *[c.Q for c in tree.charts])
        qdd_M = articulated_solve(positions, qd, *bodies, -R0, M_times, probe, ws.p,
                                  ws.p_default, at_origin(tree.charts))
    A = None if qdd_M is not None else ca.jacobian(R_q, qdd)
    A_MM = A[massive, massive] if A is not None and massive else ca.SX(0, 0)
    ggl = None
    if nc:
        # the coordinates the constrained solve covers: those with mass, and the massless ones
        # that the loop rows determine (the others are held by their own forces, below)
        phi_q = ca.jacobian(phi, q)
        in_loop = _loop_determined(phi_q, massless, tree.q_names)
        massless = [k for k in massless if k not in in_loop]
        solved = sorted(massive + in_loop)
        qdM = _rows(qd, solved)
        A_MM = A[solved, solved]
        # accelerations and multipliers from [M Φ_qᵀ; Φ_q 0][q̈; λ] = [−R0; −γ], γ = Φ̈ at
        # q̈ = 0; the positions and velocities are then held on Φ = 0 and Φ̇ = 0 exactly (to
        # the solver's Newton tolerance) by the stabilized index-2 form (GGL). Unlike
        # Baumgarte's method this leaves no drift to tune away, and unlike coordinate
        # partitioning it needs no choice of independent coordinates. Rows found redundant
        # at the assembled initial configuration are switched off by their entry of
        # ``active`` (0): then λ, μ, ν of that row are 0 and its equation drops.
        phi_s = phi_q[:, solved]
        # (the rates of prescribed motion in Φ bring back signal placeholders: resolved)
        phid = der_with(phi, ws.der_table)
        gamma = ca.substitute(der_with(phid, ws.der_table), qdd, ca.SX.zeros(nq))
        phid, gamma = resolve([phid, gamma])
        active = ca.SX.sym("loops.active", nc)
        on, off = ca.diag(active), ca.diag(1 - active)
        KKT = ca.blockcat([[A_MM, ca.mtimes(phi_s.T, on)], [ca.mtimes(on, phi_s), off]])
        sol = ca.solve(KKT, _vc(-_rows(R0, solved), -active * gamma))
        ns = len(solved)
        qdd_sol = ca.SX.zeros(nq)
        qdd_sol[solved] = sol[:ns]
        lam = sol[ns:]
        mu, nu = ca.SX.sym("loops.mu", nc), ca.SX.sym("loops.nu", nc)
        ggl = GGL(mu, nu, ca.mtimes(phi_s.T, active * mu), ca.mtimes(phi_s.T, active * nu),
                  active * phi + (1 - active) * mu, active * phid + (1 - active) * nu)
        massive = solved
        method = "constrained (KKT) solve"
    else:
        lam = active = ca.SX(0, 1)
        R0M = _rows(R0, massive)
        if qdd_M is not None:
            method = "articulated-body recursion"
        elif diagonal:
            qdd_M = -R0M / ca.diag(A_MM)
        else:
            method = "dense solve"
            qdd_M = small_solve(A_MM, -R0M) if len(massive) <= 3 else ca.solve(A_MM, -R0M)
        qdd_sol = ca.SX.zeros(nq)
        qdd_sol[massive] = qdd_M
    # massless coordinates: algebraic velocity (a damper holds them) or position (springs only)
    vel_alg = [k for k in massless if ca.depends_on(R0[k], qd[k])]
    pos_alg = [k for k in massless if k not in vel_alg]
    _check_massless(tree, R0, vel_alg, pos_alg)
    q_diff = _vc(_rows(q, massive), _rows(q, vel_alg)) if nq else ca.SX(0, 1)
    q_diff_dot = _vc(_rows(qd, massive), _rows(qd, vel_alg)) if nq else ca.SX(0, 1)
    qdd_diff = _rows(qdd_sol, massive) if massive else ca.SX(0, 1)
    alg_vars = _vc(_rows(qd, vel_alg), _rows(q, pos_alg))
    alg_res = _vc(_rows(R0, vel_alg), _rows(R0, pos_alg))
    n_node = alg_vars.numel()
    if ggl is not None:
        q_diff_dot = q_diff_dot + _vc(ggl.dq, ca.SX.zeros(len(vel_alg)))
        qdd_diff = qdd_diff + ggl.dv
        alg_vars = _vc(alg_vars, ggl.mu, ggl.nu)
        alg_res = _vc(alg_res, ggl.phi, ggl.phid)
    if massless:
        alg_res = ca.substitute(alg_res, qdd, qdd_sol)
    if pos_alg:
        # velocities (and accelerations) of spring-only massless nodes follow from d/dt R = 0
        qdP, qddP = _rows(qd, pos_alg), _rows(qdd, pos_alg)
        RP = _rows(R0, pos_alg)
        dR = der_with(RP, ws.der_table)
        J = ca.jacobian(dR, qdP)
        qdP_sol = ca.solve(J, -ca.substitute(dR, qdP, ca.SX.zeros(len(pos_alg))))
        ddR = der_with(dR, ws.der_table)
        J2 = ca.jacobian(ddR, qddP)
        qddP_sol = ca.solve(J2, -ca.substitute(ddR, qddP, ca.SX.zeros(len(pos_alg))))
        # in terms of the states (a massless Mass records its acceleration): the other
        # nodes' accelerations and these nodes' rates replaced by their solutions
        qddP_sol = ca.substitute([qddP_sol], [qdd, qdP], [qdd_sol, qdP_sol])[0]
        sub_from, sub_to = [qdP], [qdP_sol]
        qdd_sol[pos_alg] = qddP_sol
        if ca.depends_on(_vc(qdd_diff, alg_res), qdP):
            qdd_diff, alg_res = ca.substitute([qdd_diff, alg_res], [qdP], [qdP_sol])
    return Motion(method=method, q_diff=q_diff, q_diff_dot=q_diff_dot, qd_diff=qdM,
                  qdd_diff=qdd_diff, alg_vars=alg_vars, alg_res=alg_res, qdd=qdd_sol, lam=lam,
                  active=active, loop_mu=list(range(n_node, n_node + nc)),
                  loop_nu=list(range(n_node + nc, n_node + 2 * nc)),
                  substitute_from=sub_from, substitute_to=sub_to)
