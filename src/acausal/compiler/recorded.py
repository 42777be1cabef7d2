"""The recorded variables of a compiled model: every port's potentials and flows (cut forces
and torques, recovered from the relations' reactions), internal nodes' motion, states,
algebraic variables, components' variables and signals, by dotted name."""
from __future__ import annotations

import itertools

import casadi as ca

from .kinematics import InternalNode
from .relations import linear_flows

_vc = ca.vertcat


class _Column:
    """A column of scalars, each a row of some vector, stacked by reference: every vector
    kept once, the column made by one vertcat of them and one index (taking scalars out of
    vectors and stacking them one by one costs ~3 µs each; the index ~0.1 µs a row)."""
    __slots__ = ("vectors", "rows", "_start", "_size")

    def __init__(self):
        self.vectors, self.rows, self._start, self._size = [], [], {}, 0

    def add(self, v: ca.SX, row: int) -> None:
        """Row ``row`` of the column ``v`` (held here: its id stays its own)."""
        start = self._start.get(id(v))
        if start is None:
            start = self._start[id(v)] = self._size
            self.vectors.append(v)
            self._size += v.numel()
        self.rows.append(start + row)

    def scalar(self, v: ca.SX) -> None:
        """The scalar ``v``."""
        self.vectors.append(v)
        self.rows.append(self._size)
        self._size += 1

    def stacked(self) -> ca.SX:
        return _vc(*self.vectors)[self.rows, 0] if self.rows else ca.SX(0, 1)


def port_flows(ws, tree, explicit, lam_tree, lam_loop):
    """Flow of every port of every component, explicit ones plus relation reactions:
    ((dotted names, expressions stacked, units) of the ports' flows, {port: flow} of the
    ports force sensors measure)."""
    terms: dict = {}     # port -> the terms of its flow, in order: (vector, first row), or
    #                      (expression, None) (taken out of the vector only if summed)

    def add(p, v, row=None):
        terms.setdefault(p, []).append((v, row))

    def reactions(relations: list, lam: ca.SX, dims: list[int], nonlinear) -> None:
        """Add the flows of ``relations`` for their reactions ``lam`` (``dims`` rows each):
        the linear ones' at once (``linear_flows``), the others' by nonlinear(k, λ_k)."""
        first = [0, *itertools.accumulate(dims)]
        linear = [k for k, r in enumerate(relations) if r.linear]
        at, row = linear_flows([relations[k] for k in linear], lam,
                               [first[k] for k in linear]), 0
        for k, piece in enumerate(_split(lam, dims)):
            if not relations[k].linear:
                nonlinear(k, piece)
                continue
            for p in relations[k].ports:
                add(p, at, row)
                row += 1

    def loop(k: int, lam: ca.SX) -> None:
        block = tree.loops[k]
        if block.flows is None:
            extra[id(block.relation)] = lam    # extra rows of a relation that also fired
            return
        for p, v in block.flows(lam):
            add(p, v)

    def fired(k: int, lam: ca.SX) -> None:
        r = tree.fired[k].relation
        for p, v in r.flows_fired(lam, extra.get(id(r))):
            add(p, v)

    row = 0
    for block, _ in ws.flows:
        for p in block:
            add(p, explicit, row)
            row += p.domain.dof
    extra = {}
    reactions([b.relation for b in tree.loops], lam_loop, [b.rows for b in tree.loops], loop)
    reactions([f.relation for f in tree.fired], lam_tree, [f.dim for f in tree.fired], fired)
    names, units, column, total = [], [], _Column(), {}
    measured = ws.cut_flow_sym
    for p, ((v, row), *more) in terms.items():
        internal = isinstance(p, InternalNode)
        if internal and p not in measured:        # an internal node's flow: never read
            continue
        dom = p.domain
        if more or p in measured:
            v = _term(v, row, dom.dof)
            for w, i in more:
                v = v + _term(w, i, dom.dof)
            total[p], row = v, None
        if internal:
            continue
        path = p.path
        names += [f"{path}.{fname}" for fname in dom.flows]
        units += dom.flow_units
        if row is None and dom.dof == 1:
            column.scalar(v)
            continue
        if row is None:
            v, row = ca.vec(v), 0
        for j in range(dom.dof):
            column.add(v, row + j)
    flow_of = {p: total.get(p, ca.SX.zeros(p.domain.dof)) for p in measured}
    return (names, column.stacked(), units), flow_of


def _term(v: ca.SX, row: int | None, dof: int) -> ca.SX:
    """A term of a port's flow as an expression: rows row.. of v, or v itself (row None)."""
    return v if row is None else v[row:row + dof]


def _split(v: ca.SX, dims: list[int]) -> list[ca.SX]:
    """Consecutive pieces of v with the given sizes (one call: slicing costs per piece)."""
    if all(d == 1 for d in dims):
        return ca.vertsplit(v) if dims else []
    offsets = [0]
    for d in dims:
        offsets.append(offsets[-1] + d)
    return ca.vertsplit(v, offsets)


def _motion(node, one_d: tuple) -> list:
    """A node's position, velocity and acceleration, each as (column, row of its first
    element): rows of the tree's stacked 1-D motion (``Tree.one_d``) for a node of it (no
    scalar taken out), else its own vectors."""
    if node.row is not None and one_d:
        return [(x, node.row) for x in one_d]
    return [(None if x is None else ca.vec(x), 0) for x in (node.pos, node.vel, node.acc)]


def recorded_variables(ws, tree):
    """Names, expressions (stacked) and units of every potential, velocity, state and
    signal; and the rows that are kept only where they can be computed (the velocities of
    ports and internal points, the variables components record): a flange moved by a model
    input with no speed given has none."""
    names, units, column = [], [], _Column()
    optional = set()
    seen = set()

    def rec(name, v, row, unit, may_drop=False):
        """Record ``name``: row ``row`` of the column ``v``, or the scalar ``v`` (row None)."""
        if name not in seen:
            seen.add(name)
            if may_drop:
                optional.add(len(names))
            names.append(name)
            units.append(unit)
            if row is None:
                column.scalar(v)
            else:
                column.add(v, row)

    for n in tree.nodes:
        motion = None                     # the node's (pos, vel, acc), as (column, row)
        for p in n.ports:
            dom = p.domain
            if motion is None:
                motion = _motion(n, tree.one_d)
            (pos, i), (vel, k), acc = motion
            if isinstance(p, InternalNode) and dom.dim == 1:   # else by potential, as ports
                rec(p.path, pos, i, dom.potential_units[0])
                base = p.owner.path
                if p.velocity:
                    rec(f"{base}.{p.velocity}" if base else p.velocity, vel, k,
                        dom.velocity_units[0], True)
                if p.acceleration:
                    rec(f"{base}.{p.acceleration}" if base else p.acceleration, *acc,
                        dom.velocity_units[0] + "2", True)
                continue
            path = p.path
            for j, pot in enumerate(dom.potentials):
                rec(f"{path}.{pot}", pos, i + j, dom.potential_units[j])
            for j, name in enumerate(dom.velocity_names):
                if name:
                    rec(f"{path}.{name}", vel, k + j, dom.velocity_units[j], True)
    for info in ws.states:
        rec(info.sym.name(), info.sym, None, info.unit)
    for a in ws.algebraics:
        rec(a.sym.name(), a.sym, None, a.unit)
    for name, ex, unit, _ in ws.variables:
        rec(name, ex, None, unit, True)
    for c, s in ws.inputs:
        rec(c.path, s, None, c.unit)
    for c, e in ws.outputs:
        rec(c.path, e, None, c.unit)
    unit_of = {id(c): c.unit for c, _ in ws.inputs}      # a model Input's signal: its unit
    for o, s in ws.signal_sym.items():
        rec(o.path, s, None, unit_of.get(id(o.owner), ""))
    for i, o in ws.source.items():
        if o in ws.signal_sym:
            rec(i.path, ws.signal_sym[o], None, unit_of.get(id(o.owner), ""))
    return names, column.stacked(), units, optional
