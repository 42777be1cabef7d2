"""Signals, state derivatives and relaxations, resolved once and substituted anywhere.

Components write their physics with placeholders: a signal input reads as ``sig:<output>``
(and its rates ``der(sig:...)`` where a prescribed motion differentiates it), a state's
derivative as ``der(<state>)`` until the component sets it, a value with given rates
(``StructureBuilder.with_rates``) as ``given:<component>.<name>``. Once every component has spoken,
the placeholders' values are known; a Resolver substitutes them (and the relaxations ε of the
tree relations by zero) in any expression.

Signals that depend on each other without a state in between (an algebraic loop of blocks,
y = k·(u + g·y)) are torn first, as a Modelica tool does: a few of the loop's signals, chosen
so that the rest follow from them in order, become algebraic variables of the model (named as
their output, e.g. ``add.y``), each with the equation "its value = its block's expression",
solved with the other algebraic equations (IDAS, the FMU's Newton iteration).
"""
from __future__ import annotations

import casadi as ca

from ..errors import StructureError
from .builders import StateInfo, Workspace
from .symbolic import UnknownDerivative, der_with, substitute_all

_vc = ca.vertcat


class Resolver:
    """Substitutes signal placeholders (and their rates), state-derivative placeholders and
    the relaxations ε (by zero) in any expression, with values resolved once."""

    def __init__(self, syms, vals, zeros_for, failed):
        self.failed = failed
        zeros = [ca.SX.zeros(v.numel()) for v in zeros_for]
        # the values with ε = 0 already, so that one substitution does both at once
        values = ca.substitute([_vc(*vals)], zeros_for, zeros)[0] if vals else ca.SX(0, 1)
        self.frm = [_vc(*syms) if syms else ca.SX(0, 1)] + list(zeros_for)
        self.to = [values] + zeros
        self._failed_syms = _vc(*[sym for sym, _ in failed]) if failed else None

    def __call__(self, pieces: list) -> list:
        """``pieces`` with the placeholders resolved (``check`` the expressions they end in
        for the rates that could not be derived)."""
        return ca.substitute(pieces, self.frm, self.to)

    def unknown_rows(self, column: ca.SX) -> list[int]:
        """The rows of a resolved ``column`` that need a rate that could not be derived."""
        if self._failed_syms is None or not ca.depends_on(column, self._failed_syms):
            return []
        return [k for k, x in enumerate(ca.vertsplit(column))
                if ca.depends_on(x, self._failed_syms)]

    def error(self, piece: ca.SX) -> StructureError:
        """The error of the first rate ``piece`` needs that could not be derived."""
        return next(err for sym, err in self.failed if ca.depends_on(piece, sym))

    def check(self, pieces):
        """Raise the error of a placeholder whose rate could not be derived, if any piece
        still needs it (one test for all of them first)."""
        if self._failed_syms is None or not pieces or \
                not ca.depends_on(ca.veccat(*pieces), self._failed_syms):
            return
        for sym, err in self.failed:
            if any(ca.depends_on(x, sym) for x in pieces):
                raise err


def make_resolver(ws: Workspace, relaxations: list[ca.SX]) -> Resolver:
    """The Resolver of a workspace whose components have all contributed their physics;
    ``relaxations`` (ε, ε̇, ε̈ of the tree) are substituted by zero."""
    missing = [o for o in ws.signal_sym if o not in ws.signal_expr]
    if missing:
        o = missing[0]
        raise StructureError(f"{type(o.owner).__name__} '{o.owner.path}' never sets its output "
                             f"'{o.path}' (call e.output in physics)")
    syms, vals = [], []
    for o, s in ws.signal_sym.items():
        syms.append(s)
        vals.append(ws.signal_expr[o])
    for info in ws.states:
        if info.placeholder is not None:
            syms.append(info.placeholder)
            vals.append(info.der)
    for sym, value in ws.aliases:
        syms.append(sym)
        vals.append(value)
    _tear_loops(ws, syms, vals)
    vals = substitute_all(vals, syms, vals) if syms else vals
    # rates of signals (prescribed motion): d/dt of the resolved signal expressions
    failed = []
    by_name = {s.name(): v for s, v in zip(syms, vals)}
    for name in list(ws.der_table):
        if not name.startswith("sig:"):
            continue
        level, value = ws.der_table[name], by_name[name]
        while level is not None and level.name().startswith("der("):
            try:
                value = _resolve_once(der_with(value, ws.der_table), syms, vals)
            except UnknownDerivative as e:
                failed.append((level, e))
                break
            syms.append(level)
            vals.append(value)
            level = ws.der_table.get(level.name())
    # a signal may be the rate of another (a Der block's output): resolve those rates in it
    rates = _vc(*syms[len(by_name):]) if len(syms) > len(by_name) else None
    if rates is not None and any(ca.depends_on(v, rates) for v in vals[:len(by_name)]):
        vals = substitute_all(vals, syms, vals)
    return Resolver(syms, vals, relaxations, failed)


def _resolve_once(ex, syms, vals):
    return ca.substitute([ex], [_vc(*syms)], [_vc(*vals)])[0] if syms else ex


def _tear_loops(ws: Workspace, syms: list, vals: list) -> None:
    """Tear the algebraic loops among the placeholders ``syms`` (values ``vals``, changed in
    place): while the graph "value i uses placeholder j" has a cycle, the signal of the
    cycle's component used most (in and out) becomes an algebraic variable z named as its
    output, its placeholder's value z, its block's expression an equation of ws (z − value
    = 0). Only block outputs are torn; a loop without one is left to substitute_all's error."""
    index = {s.name(): i for i, s in enumerate(syms)}
    uses = [sorted({index[n] for n in (v.name() for v in ca.symvar(ca.SX(x))) if n in index})
            for x in vals]
    outputs = {s.name(): o for o, s in ws.signal_sym.items()}
    torn = set()
    while True:
        loops = [c for c in _strong_components(uses, torn)
                 if len(c) > 1 or c[0] in uses[c[0]]]
        if not loops:
            break
        for cycle in loops:
            members = set(cycle)
            tearable = [i for i in cycle if syms[i].name() in outputs]
            if not tearable:
                return
            degree = {i: sum(j in members for j in uses[i]) +
                      sum(i in uses[j] for j in members) for i in tearable}
            torn.add(max(tearable, key=lambda i: (degree[i], -i)))
    for i in sorted(torn):
        port = outputs[syms[i].name()]
        z = ca.SX.sym(port.path)
        ws.der_table[z.name()] = None
        ws.algebraics.append(StateInfo(z, 0.0, "", f"{port.path} (torn algebraic loop)",
                                       port.owner))
        ws.residuals.append((port.owner, z - vals[i]))
        vals[i] = z


def _strong_components(uses: list[list[int]], removed: set) -> list[list[int]]:
    """The strongly connected components of the graph i → uses[i] without the vertices
    ``removed`` (Tarjan's algorithm, iterative)."""
    order, low, on_stack, stack, out, counter = {}, {}, set(), [], [], [0]
    for root in range(len(uses)):
        if root in removed or root in order:
            continue
        work = [(root, 0)]
        while work:
            v, k = work.pop()
            if k == 0:
                order[v] = low[v] = counter[0]
                counter[0] += 1
                stack.append(v)
                on_stack.add(v)
            edges = [w for w in uses[v] if w not in removed]
            for j in range(k, len(edges)):
                w = edges[j]
                if w not in order:
                    work.append((v, j + 1))
                    work.append((w, 0))
                    break
                if w in on_stack:
                    low[v] = min(low[v], order[w])
            else:
                if low[v] == order[v]:
                    component = []
                    while True:
                        w = stack.pop()
                        on_stack.discard(w)
                        component.append(w)
                        if w == v:
                            break
                    out.append(component)
                if work:
                    parent = work[-1][0]
                    low[parent] = min(low[parent], low[v])
    return out
