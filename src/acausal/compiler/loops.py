"""Closed loops: which constraint rows are consistent, redundant or independent, and the
mobility of the mechanism (Gruebler's count against the rank of Φ_q).

A loop row that no coordinate enters is checked at the parameters' defaults: non-zero is an
inconsistent loop (an error naming the parts), zero a redundant one. The other rows are
examined at an assembled configuration (Φ(q) = 0 solved by Gauss–Newton from the start
values, defaults for the parameters): rows that add nothing to the rank of Φ_q are redundant.
Redundant rows are dropped from the equations with a warning that names them: the motion is
unaffected, and the reactions they would share are statically indeterminate (the remaining
constraints carry them).
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import casadi as ca
import numpy as np

from ..core.errors import StructureError


@dataclass
class Mobility:
    """Degrees of freedom of the mechanism: ``gruebler`` = coordinates − constraint rows;
    ``dof`` = coordinates − rank Φ_q at the assembled configuration (None if it could not
    be assembled at the defaults); ``redundant`` names the rows dropped."""
    coordinates: int
    constraints: int
    gruebler: int
    dof: int | None
    redundant: list[str] = field(default_factory=list)

    def __str__(self):
        dof = "unknown (no assembled configuration at the defaults)" if self.dof is None \
            else self.dof
        red = f"; redundant constraints: {', '.join(self.redundant)}" if self.redundant else ""
        return (f"{self.coordinates} coordinates, {self.constraints} constraints: Gruebler "
                f"count {self.gruebler}, degrees of freedom {dof}{red}")


def analyse_loops(tree, phi: ca.SX, ws) -> tuple[list[int], Mobility]:
    """The rows of Φ to keep, and the mobility. Raises for inconsistent loops."""
    q = tree.q
    nq, nc = q.numel(), phi.numel()
    names = tree.loop_rows
    J = ca.jacobian(phi, q)
    with_q = set(J.sparsity().get_triplet()[0])
    redundant = []
    for i in range(nc):
        if i not in with_q:
            _constant_row(tree, phi, i, ws)
            redundant.append(i)
    moving = [i for i in range(nc) if i in with_q]
    dof = None
    qa = _assemble(phi, J, q, ws)
    if qa is not None and moving:
        Jn = np.array(ca.Function("J", [q, ws.p], [J], {"allow_free": True})(qa, ws.p_default))
        kept, basis = [], np.zeros((0, nq))
        for i in moving:
            row = Jn[i]
            trial = np.vstack([basis, row])
            if np.linalg.matrix_rank(trial, tol=1e-9 * max(1.0, np.abs(Jn).max())) > len(kept):
                kept.append(i)
                basis = trial
            else:
                redundant.append(i)
        dof = nq - len(kept)
    elif qa is not None:
        dof = nq
    redundant.sort()
    if redundant:
        warnings.warn(
            "redundant loop constraints dropped (the motion is unaffected; the reactions they "
            "would share are statically indeterminate and carried by the other constraints): "
            + ", ".join(names[i] for i in redundant), stacklevel=4)
    keep = [i for i in range(nc) if i not in redundant]
    return keep, Mobility(nq, nc, nq - nc, dof, [names[i] for i in redundant])


def _constant_row(tree, phi, i, ws) -> None:
    """A row no coordinate enters: error unless it holds (then it is redundant)."""
    r, k = _relation_of_row(tree, i)
    parts = sorted({p.owner.path for n in r.nodes for p in n.ports} - {r.owner.path})
    val = ca.Function("phi", [ws.p], [phi[i]], {"allow_free": True})
    if not val.has_free() and abs(float(val(ws.p_default))) <= 1e-10:
        return
    raise StructureError(
        f"the rigid loop through '{r.owner.path}' ({type(r.owner).__name__}) cannot close: the "
        f"parts it joins are fixed with a different offset"
        f"{' (or move in time)' if val.has_free() else ''}; parts in the loop: "
        f"{', '.join(parts)}. Remove the component or fix its parameters")


def _relation_of_row(tree, i):
    k = 0
    for r, dim, _ in tree.loops:
        if i < k + dim:
            return r, i - k
        k += dim
    raise IndexError(i)


def _assemble(phi, J, q, ws):
    """A configuration with Φ(q) = 0 near the start values (zeros), or None."""
    f = ca.Function("phiJ", [q, ws.p, ws.t], [phi, J], {"allow_free": True})
    if f.has_free():             # prescribed motion: depends on states, cannot assemble here
        return None
    rng = np.random.default_rng(0)
    starts = [np.zeros(q.numel())] + [rng.uniform(-1.0, 1.0, q.numel()) for _ in range(4)]
    for x in starts:                # Levenberg–Marquardt from the start values, then others
        lam = 1e-3
        for _ in range(100):
            r, Jn = (np.array(v, dtype=float) for v in f(x, ws.p_default, 0.0))
            r = r.ravel()
            if np.max(np.abs(r), initial=0.0) < 1e-12:
                return x
            step = np.linalg.solve(Jn.T @ Jn + lam * np.eye(x.size), -Jn.T @ r)
            r_new = np.array(f(x + step, ws.p_default, 0.0)[0], dtype=float).ravel()
            if r_new @ r_new < r @ r:
                x, lam = x + step, lam / 3
            else:
                lam *= 10
    return None
