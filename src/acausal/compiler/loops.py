"""Closed loops: which constraint rows are consistent, redundant or independent, and the
mobility of the mechanism (Gruebler's count against the rank of Φ_q).

A loop row that no coordinate enters is checked at compile time at the parameters' defaults:
non-zero is an inconsistent loop (an error naming the parts), zero a redundant one (dropped).
The other rows are examined where the mechanism is assembled for a simulation (redundancy
can depend on the configuration, e.g. a parallelogram with a fifth parallel link): rows that
add nothing to the rank of Φ_q there are switched off (the model's ``loops.active``
parameters) with a warning that names them: the motion is unaffected, and the reactions they
would share are statically indeterminate (the remaining constraints carry them).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import casadi as ca
import numpy as np

from ..errors import StructureError, warn_user
from ..numerics import independent_rows


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


def analyse_loops(tree, phi: ca.SX, ws) -> tuple[list[int], list[str]]:
    """The rows of Φ to keep (rows no coordinate enters are checked here: inconsistent is an
    error, consistent ones are redundant and dropped), and the names of all rows."""
    J = ca.jacobian(phi, tree.q)
    with_q = set(J.sparsity().get_triplet()[0])
    keep = []
    for i in range(phi.numel()):
        if i in with_q:
            keep.append(i)
        else:
            _constant_row(tree, phi, i, ws)
    if len(keep) < phi.numel():
        warn_user("redundant loop constraints dropped (they join parts that are fixed "
                  "already; their reactions are statically indeterminate): "
                  + ", ".join(tree.loop_rows[i] for i in range(phi.numel()) if i not in keep))
    return keep, tree.loop_rows


def mobility(J: np.ndarray, names: list[str], dropped: list[str]) -> tuple[np.ndarray, Mobility]:
    """At an assembled configuration with constraint Jacobian ``J`` (rows named ``names``):
    which rows to enforce (1) and which are redundant (0), and the mobility. ``dropped``:
    rows removed already at compile time (constant and redundant)."""
    nc, nq = J.shape
    active = independent_rows(J)
    redundant = list(dropped) + [names[i] for i in range(nc) if not active[i]]
    total = nc + len(dropped)
    mob = Mobility(nq, total, nq - total, nq - int(active.sum()), redundant)
    if redundant:
        warn_user(
            "redundant loop constraints (not enforced: the motion is unaffected; the reactions "
            "they would share are statically indeterminate and carried by the other "
            "constraints): " + ", ".join(redundant))
    return active, mob


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
    for block in tree.loops:
        if i < k + block.rows:
            return block.relation, i - k
        k += block.rows
    raise IndexError(i)
