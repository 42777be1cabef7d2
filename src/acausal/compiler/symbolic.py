"""Symbolic helpers on CasADi SX: the total time derivative, repeated substitution, the
closed-form solve of small linear systems, and a pause of Python's garbage collector for
the passes that build large expressions."""
from __future__ import annotations

import gc
from contextlib import contextmanager
from typing import NamedTuple

import casadi as ca

from ..errors import StructureError


class UnknownDerivative(StructureError):
    """An expression was differentiated in time through a symbol whose rate is unknown."""


class Row(NamedTuple):
    """Row ``row`` of the column ``vector``: a scalar of a block of symbols made at once,
    taken out of it only where it is used alone (``sx``) and in slices where rows of one
    block are stacked (``stack``): each scalar SX held in Python costs time and ~300 B."""
    vector: ca.SX
    row: int


@contextmanager
def gc_paused():
    """Python's cyclic garbage collector off for the block: symbolic passes allocate
    millions of small objects without cycles, and the collections they trigger traverse
    every live one (20–40 % of a large model's compile or first read)."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()


def sx(v) -> ca.SX:
    """``v`` as SX, without the cost of converting what already is one."""
    if isinstance(v, ca.SX):
        return v
    return v.vector[v.row] if isinstance(v, Row) else ca.SX(v)


def stack(items: list) -> ca.SX:
    """``items`` (SX, numbers or Rows) stacked in a column; consecutive rows of one vector
    are taken as one slice of it."""
    pieces = []                            # SX, or a run of rows: [vector, first, end]
    for x in items:
        last = pieces[-1] if pieces else None
        if isinstance(x, Row) and isinstance(last, list) and last[0] is x.vector \
                and last[2] == x.row:
            last[2] += 1
        else:
            pieces.append([x.vector, x.row, x.row + 1] if isinstance(x, Row) else sx(x))
    return ca.vertcat(*[p[0][p[1]:p[2], :] if isinstance(p, list) else p
                        for p in pieces]) if pieces else ca.SX(0, 1)


def combine(const, terms, div=1.0):
    """(const + Σ c·x) / div for (c, x) in terms, skipping unit and zero factors.

    Coefficients and ``const`` may be Python numbers or SX; numbers are folded without
    building SX nodes (each SX operation from Python costs ~20 µs, which dominates compile
    time for large models)."""
    out = None if (isinstance(const, (int, float)) and const == 0) else const
    for c, x in terms:
        if isinstance(c, (int, float)):
            if c == 0:
                continue
            if c == 1:
                out = x if out is None else out + x
                continue
            if c == -1:
                out = -x if out is None else out - x
                continue
        out = c * x if out is None else out + c * x
    if out is None:
        return ca.SX(0)
    if isinstance(div, (int, float)) and div == 1:
        return sx(out)
    return sx(out / div)


def der_with(ex, table: dict) -> ca.SX:
    """Total time derivative of ``ex``: Σ ∂ex/∂s · ṡ over the symbols s it depends on.

    ``table`` maps symbol names to their derivative (an SX; None when it is unknown, as for
    a model input). Symbols missing from the table are constants (derivative 0). Cost is
    proportional to the size of ``ex`` only.
    """
    if isinstance(ex, (int, float)):
        return ca.SX(0)
    if ex.is_constant():
        return ca.SX.zeros(ex.shape)
    syms = ca.symvar(ex)
    args, rates = [], []
    for s in syms:
        d = table.get(s.name(), 0)
        if d is None:
            raise UnknownDerivative(
                f"the time derivative of '{s.name()}' is needed but unknown (it is a model "
                f"input or an algebraic variable): a component differentiates it (a Der block, "
                f"an exact Position, Speed or Accelerate source); use a filtered source "
                f"(exact=False) or a Derivative block (k·s/(T·s + 1)), or give the signal as a "
                f"function of time")
        if isinstance(d, (int, float)) and d == 0:
            continue
        args.append(s)
        rates.append(d)
    if not args:
        return ca.SX.zeros(ex.shape)
    return ca.jtimes(ex, ca.vertcat(*args), stack(rates))


def substitute_all(exprs: list, syms: list, values: list, what: str = "signals") -> list:
    """Substitute ``syms`` by ``values`` in ``exprs`` until none is left (values may refer to
    other symbols of the list). A cycle raises a StructureError naming the symbols in it."""
    if not syms:
        return exprs
    v = ca.vertcat(*syms)
    vals = [ca.SX(x) for x in values]
    for _ in range(len(syms) + 1):
        pending = [i for i, x in enumerate(vals) if ca.depends_on(x, v)]
        if not pending:
            break
        vals = ca.substitute(vals, [v], [ca.vertcat(*vals)])
    else:
        names = [syms[i].name() for i in pending]
        raise StructureError(f"algebraic loop among {what}: {', '.join(names)} depend on each "
                             f"other without a state in between; break the loop with a state "
                             f"(e.g. a first-order block) or a mass")
    return ca.substitute([ca.SX(e) for e in exprs], [v], [ca.vertcat(*vals)])


def small_solve(A: ca.SX, b: ca.SX) -> ca.SX:
    """A⁻¹ b for a dense square A of size 1 to 3 in closed form: the adjugate's rows times b,
    scaled by one reciprocal of det A (CasADi's symbolic solve divides every entry of the
    inverse by the determinant: n² divisions instead of one)."""
    n = A.shape[0]
    a = [[A[i, j] for j in range(n)] for i in range(n)]
    if n == 1:
        return b / a[0][0]
    if n == 2:
        adj = [[a[1][1], -a[0][1]], [-a[1][0], a[0][0]]]
    elif n == 3:
        def cof(i, j):          # cofactor of a[j][i]: the adjugate's entry (i, j)
            r = [k for k in range(3) if k != j]
            c = [k for k in range(3) if k != i]
            return (a[r[0]][c[0]] * a[r[1]][c[1]] - a[r[0]][c[1]] * a[r[1]][c[0]]) \
                * (1 if (i + j) % 2 == 0 else -1)
        adj = [[cof(i, j) for j in range(n)] for i in range(n)]
    else:
        raise ValueError(f"small_solve: size {n} > 3")
    det = sum((a[0][j] * adj[j][0] for j in range(1, n)), a[0][0] * adj[0][0])
    inv_det = 1 / det
    return ca.vertcat(*[sum((adj[i][j] * b[j] for j in range(1, n)), adj[i][0] * b[0])
                        for i in range(n)]) * inv_det
