"""Constraints on velocities that are not the derivative of constraints on positions
(nonholonomic: a rolling contact's no-slip), A(q, t)·q̇ + b(q, t) = 0, and the forces f
that hold them (``PhysicsBuilder.velocity_constraint``).

The rows do not reduce the positions: all coordinates q stay states. They reduce the
velocities: one rate per row, the *dependent* rates q̇_D, follows from the others,
q̇_D = −A_D⁻¹(A_I q̇_I + b), so the states are q and the independent rates q̇_I (Maggi's
form; MSL's RollingWheel keeps the same states: x, y, angles and der_angles). The
constraint holds exactly at every instant (no drift, nothing to project at the start:
given q̇_I, q̇_D follows). The accelerations and the constraint forces solve, as one linear
system, Lagrange's equations R(q, q̇, q̈, f) = 0 (the forces enter through the ports the
component puts them on) and the rows' time derivatives Ȧq̇ + Aq̈ + ḃ = 0.

The dependent rates are chosen by a structural matching of rows to the coordinates that
enter them (rows in declaration order, coordinates in tree order: a wheel's x and y rates
for its two rows), checked to be regular at a random configuration. Closed kinematic
loops (position constraints) together with velocity constraints are not supported yet.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..errors import SingularModelError, StructureError
from .motion import Motion
from .symbolic import der_with

_vc = ca.vertcat


def _dependent(A: ca.SX, rows: list[str], q_names: list[str]) -> list[int]:
    """One coordinate per row whose rate enters it (augmenting paths), in row order."""
    cols_of: dict[int, list[int]] = {}
    for r, c in zip(*A.sparsity().get_triplet()):
        cols_of.setdefault(r, []).append(c)
    owner: dict[int, int] = {}                     # coordinate -> row

    def augment(r, seen):
        for c in sorted(cols_of.get(r, [])):
            if c not in seen:
                seen.add(c)
                if c not in owner or augment(owner[c], seen):
                    owner[c] = r
                    return True
        return False

    for r in range(A.shape[0]):
        if not augment(r, set()):
            raise StructureError(f"the velocity constraint {rows[r]} cannot be given a rate "
                                 f"of its own to determine (the velocity constraints "
                                 f"{', '.join(rows)} share too few coordinates: "
                                 f"{', '.join(q_names[c] for c in sorted(owner))}); they "
                                 f"are redundant or contradict each other")
    by_row = {r: c for c, r in owner.items()}
    return [by_row[r] for r in range(A.shape[0])]


def _check_regular(A_D: ca.SX, q: ca.SX, ws, rows: list[str], names: list[str]) -> None:
    """A_D must be invertible: checked at a random configuration, the parameters' defaults."""
    f = ca.Function("A_D", [q, ws.p], [A_D], {"allow_free": True})
    if f.has_free():
        return
    rng = np.random.default_rng(1)
    a = np.array(f(rng.uniform(-1, 1, q.numel()), ws.p_default), dtype=float)
    if np.linalg.matrix_rank(a) < a.shape[0]:
        raise SingularModelError(f"the velocity constraints {', '.join(rows)} do not fix the "
                                 f"rates {', '.join(names)} (singular at a random "
                                 f"configuration): redundant velocity constraints")


def solve_velocity_constrained(tree, R_q: ca.SX, rows: ca.SX, forces: ca.SX,
                               row_names: list[str], ws, resolve) -> Motion:
    """The Motion of Lagrange's residuals ``R_q`` (in q, q̇, q̈ and the forces) under the
    velocity constraints 0 = ``rows`` held by ``forces``."""
    q, qd, qdd = tree.q, tree.qd, tree.qdd
    nq, nc = q.numel(), rows.numel()
    A = ca.jacobian(rows, qd)
    if ca.depends_on(A, qd):
        raise StructureError(f"the velocity constraints {', '.join(row_names)} are not linear "
                             f"in the velocities")
    dep = _dependent(A, row_names, tree.q_names)
    ind = [k for k in range(nq) if k not in dep]
    _check_regular(A[:, dep], q, ws, row_names, [tree.qd_names[k] for k in dep])
    qd_D = qd[dep]
    qd_D_sol = ca.solve(A[:, dep], -ca.substitute(rows, qd_D, ca.SX.zeros(nc)))
    # accelerations and forces: R = 0 and d/dt(rows) = 0, linear in (q̈, f)
    rows_dot = resolve([der_with(rows, ws.der_table)])[0]
    F, w = _vc(R_q, rows_dot), _vc(qdd, forces)
    J = ca.jacobian(F, w)
    if ca.depends_on(J, w):
        raise SingularModelError("the equations of motion are not linear in the accelerations "
                                 "and the constraint forces")
    if ca.sprank(J) < nq + nc:
        raise SingularModelError(f"the accelerations and the forces of the velocity "
                                 f"constraints {', '.join(row_names)} are not determined: a "
                                 f"coordinate without mass, or a constraint force that acts "
                                 f"on nothing (put the force on the ports with e.flow)")
    sol = ca.solve(J, -ca.substitute(F, w, ca.SX.zeros(nq + nc)))
    sol = ca.substitute(sol, qd_D, qd_D_sol)
    qd_all = ca.substitute(qd, qd_D, qd_D_sol)
    return Motion(method="velocity constraints (dependent rates eliminated), dense solve",
                  q_diff=q, q_diff_dot=qd_all, qd_diff=qd[ind], qdd_diff=sol[ind],
                  alg_vars=ca.SX(0, 1), alg_res=ca.SX(0, 1), qdd=sol[:nq], lam=ca.SX(0, 1),
                  active=ca.SX(0, 1), loop_mu=[], loop_nu=[],
                  substitute_from=[qd_D, forces], substitute_to=[qd_D_sol, sol[nq:]])
