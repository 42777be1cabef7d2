"""Potential/flow networks (electrical, thermal): Kirchhoff's laws as DAE equations.

The connection sets of network ports (``Domain.network``: pins, heat ports) are not
mechanical: they get no coordinates, no kinetic energy. Each set is a node with one
potential (v [V], T [K]); the unknowns and equations the network adds to the DAE are

- unknowns: every node's potential; every port flow a component reads as an unknown
  (``PhysicsBuilder.flow_of``); the algebraic variables of components with network ports;
- equations: Kirchhoff's current law at every node (the flows of its ports, positive into
  the components, sum to zero); the residuals of components with network ports.

A component gives each of its network ports' flows either explicitly
(``PhysicsBuilder.flow``: an inductor's state current, a heat flow source) or as the unknown
``flow_of(port)`` with an equation of its own (a resistor's v = R·i). Capacitors, inductors
and heat capacitors declare states with derivatives (semi-explicit DAE). A network port
of a model made of parts (an outside connector, e.g. the heatPort of a composed motor) is a
junction: the connections inside and outside it form one node, where it adds no flow (its
potential is recorded). A node's potential starts at its domain's ``potential_start``
(0 V; 288.15 K, SI.Temperature's start) where nothing fixes it.

Structure. Before any elimination, the network's equations are matched to its unknowns
(maximum bipartite matching of the incidence). A network is accepted when the matching is
perfect: index 1, which IDAS integrates directly. Otherwise it is structurally singular, a
higher-index network, refused by default with a StructureError naming the parts:

- equations left over with no unknown of their own (Dulmage-Mendelsohn's over-determined
  part) are either a loop of potential-fixing elements (capacitors, voltage sources,
  grounds, heat capacitors and fixed temperatures joined directly: one voltage follows
  from the others, Kirchhoff's voltage law constrains states) or a cut set of flow-fixing
  elements (nodes whose flows are all given: inductors, current sources; Kirchhoff's
  current law constrains states). The error names the components and says what to change
  (a resistor in series, or across; or merging the elements into one);
- unknowns left over (the under-determined part) name the nodes.
A circuit without a reference (no Ground: every equation keeps its value when all the
potentials of a connected circuit are shifted together) is singular too, but not
structurally: it is found by that shift and refused, naming the circuit's components.
A loop or cut set the structure cannot see (a cut set through elements that give their
flows explicitly in both potentials: an inductor, a Conductor and a current source in
series) leaves the Jacobian of the equations in the unknowns singular: it is found
numerically, at random values of the states, and reported and reduced as above.

Index reduction (``compile(model, index_reduction=True)``, opt-in: a state of the loop
stops being one, so its start value is no longer used). A loop or cut set whose equations
are linear in the potentials and flows with numeric coefficients (ideal capacitors,
inductors, sources, grounds) gives a constraint h(x, t) = 0 on the states: the left null
vector of its equations' Jacobian combines them into it. The last declared state in h with
a constant coefficient becomes an expression of the others (recorded under its name), and
the equation it was in is replaced by dh/dt = 0 (its state derivative given by the others';
``compiler.index``, which also reduces the block equations that constrain states).
The states kept need not be those a Modelica tool keeps (in MSL's CauerLowPassAnalog C3 and
C5 become expressions where the MSL fixes their start values; all start at 0 there, so the
solution is the same). Loops through other elements, and constraints through model inputs
(whose rate is unknown), stay refused.

Elimination. Trivial equations are solved before the DAE is built, where cheap: an equation
affine in an unknown with a numeric coefficient is solved for it when the rest holds at most
one other unknown (a grounded potential, p.v = 0; an alias, n.i = −p.i; a potential fixed by
a state, v = C's voltage) or when the unknown appears in no other network equation (the
ground's current). The eliminated unknowns are substituted everywhere (equations of motion,
outputs, recorded variables) and recorded as expressions.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import casadi as ca
import numpy as np
from scipy.linalg import null_space
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import maximum_bipartite_matching

from ..core.component import Model
from ..errors import StructureError
from .index import demote_state

_vc = ca.vertcat


@dataclass
class NetNode:
    """A connection set of network ports: one potential (an unknown of the DAE)."""
    ports: list
    potential: ca.SX

    @property
    def domain(self):
        return self.ports[0].domain

    @property
    def name(self) -> str:
        return self.ports[0].path


def declare_nodes(ws, groups: list) -> None:
    """Give every network connection set of ``groups`` its node and potential symbol."""
    for g in groups:
        name = f"{g[0].path}.{g[0].domain.potentials[0]}"
        node = NetNode(list(g), ca.SX.sym(name))
        ws.der_table[name] = None
        ws.net_nodes.append(node)
        for p in g:
            ws.net_node_of[p] = node


def _is_junction(port) -> bool:
    """A port of a model made of parts (Modelica's outside connector of a sub-model): the
    connections inside and outside it are one set, where it carries no flow of its own."""
    return isinstance(port.owner, Model) and bool(port.owner.children)


def has_network_ports(component) -> bool:
    return any(getattr(p, "domain", None) is not None and p.domain.network
               for p in component.ports.values())


@dataclass
class Network:
    """The network's part of the DAE: remaining unknowns ``z`` (with units and start
    values), equations ``alg``, and ``substitute``, which replaces the eliminated unknowns
    in any expression; ``records`` are (name, expression, unit) of every port's potential
    and flow."""
    z: list = field(default_factory=list)            # (symbol, unit, start, description)
    alg: list = field(default_factory=list)
    eliminated: list = field(default_factory=list)   # symbols
    values: list = field(default_factory=list)       # their expressions
    records: list = field(default_factory=list)
    demoted: list = field(default_factory=list)      # (state symbol, expression of others)

    def substitute(self, exprs: list) -> list:
        if self.eliminated:
            exprs = ca.substitute(exprs, [_vc(*self.eliminated)], [_vc(*self.values)])
        if self.demoted:
            exprs = ca.substitute(exprs, [_vc(*[s for s, _ in self.demoted])],
                                  [_vc(*[v for _, v in self.demoted])])
        return exprs


def build_network(ws, resolve) -> Network:
    """Kirchhoff's laws and the residuals of the components with network ports, resolved
    (signals substituted), checked for structure and reduced (see the module's docstring)."""
    net = Network()
    if not ws.net_nodes:
        return net
    explicit: dict = {}
    for p, v in ws.net_flows:
        explicit[p] = explicit[p] + v if p in explicit else v
    unknowns, units, starts, what = [], [], [], []
    for n in ws.net_nodes:
        unknowns.append(n.potential)
        units.append(n.domain.potential_units[0])
        starts.append(n.domain.potential_start)
        what.append(("node", n))
    for p, s in ws.net_flow_sym.items():
        if p in explicit:
            raise StructureError(f"{type(p.owner).__name__} '{p.owner.path}' gives the flow of "
                                 f"'{p.path}' (e.flow) and also reads it as unknown "
                                 f"(e.flow_of); use one")
        unknowns.append(s)
        units.append(p.domain.flow_units[0])
        starts.append(0.0)
        what.append(("port", p))
    for a in ws.algebraics:
        if has_network_ports(a.owner):
            unknowns.append(a.sym)
            units.append(a.unit)
            starts.append(a.start)
            what.append(("component", a.owner))
    eqs, labels = [], []
    for n in ws.net_nodes:
        flows = []
        for p in n.ports:
            if _is_junction(p):
                continue
            if p in explicit:
                flows.append(explicit[p])
            elif p in ws.net_flow_sym:
                flows.append(ws.net_flow_sym[p])
            else:
                raise StructureError(f"{type(p.owner).__name__} '{p.owner.path}' sets no "
                                     f"{p.domain.flows[0]} of its port '{p.path}' (give it "
                                     f"with e.flow, or read it with e.flow_of and give an "
                                     f"equation for it)")
        eqs.append(ca.sum1(_vc(*flows)))
        labels.append(("node", n))
    for owner, r in ws.residuals:
        if has_network_ports(owner):
            eqs.append(r)
            labels.append(("component", owner))
    eqs = ca.vertsplit(resolve([_vc(*eqs)])[0])
    while True:
        over = _check_structure(eqs, unknowns, labels, what, explicit)
        if over is None:
            _check_reference(ws.net_nodes, eqs)
            over = _singular_rows(eqs, unknowns)
        if over is None:
            break
        message = _over_message([labels[r] for r in over], explicit)
        if not ws.index_reduction:
            raise StructureError(message + " (or compile with index_reduction=True)")
        _reduce_index(ws, resolve, eqs, unknowns, over, net.demoted, message)
    alive, solved = _eliminate(eqs, unknowns)
    net.alg = [eqs[k] for k in alive]
    net.z = [(unknowns[k], units[k], starts[k]) for k in range(len(unknowns))
             if k not in solved]
    net.eliminated = [unknowns[k] for k in solved]
    net.values = [solved[k] for k in solved]
    for sym, _ in net.demoted:
        info = next(i for i in ws.demoted_states if i.sym is sym)
        net.records.append((sym.name(), sym, info.unit))
    for n in ws.net_nodes:
        dom = n.domain
        for p in n.ports:
            flow = explicit.get(p, ws.net_flow_sym.get(p))
            net.records.append((f"{p.path}.{dom.potentials[0]}", n.potential,
                                dom.potential_units[0]))
            if not _is_junction(p):          # a junction's flow is its parts' (recorded)
                net.records.append((f"{p.path}.{dom.flows[0]}", flow, dom.flow_units[0]))
    return net


def _reduce_index(ws, resolve, eqs: list, unknowns: list, rows: list, demoted: list,
                  message: str) -> None:
    """Differentiate the constraint on the states that the over-determined equations
    ``rows`` give, demote one of its states (module's docstring); ``eqs``, ``demoted`` and
    ``ws.states`` are updated in place. Raises the StructureError ``message`` when the
    loop is not of that kind."""
    sub = _vc(*[eqs[r] for r in rows])
    cols = [k for k, u in enumerate(unknowns) if ca.depends_on(sub, u)]
    G = ca.jacobian(sub, _vc(*[unknowns[k] for k in cols]))
    if not G.is_constant():
        raise StructureError(message + " (index reduction needs a loop of elements linear "
                                       "in their potentials and flows)")
    N = null_space(np.array(ca.DM(G)).T)
    if N.shape[1] == 0:
        raise StructureError(message)
    c = np.round(N[:, 0] / N[np.argmax(np.abs(N[:, 0])), 0], 12)   # ±1 for ideal loops
    h = ca.substitute(ca.dot(ca.DM(c), sub), _vc(*[unknowns[k] for k in cols]),
                      ca.SX.zeros(len(cols)))
    rate = demote_state(ws, resolve, h, demoted, message)
    d, value = demoted[-1]
    r0 = next(r for r, ck in zip(rows, c) if ck != 0 and ca.depends_on(eqs[r], d))
    eqs[r0] = rate
    for k, e in enumerate(eqs):
        eqs[k] = ca.substitute(e, d, value)


def _eliminate(eqs: list, unknowns: list):
    """Solve trivial equations (see the module's docstring): the indices of the equations
    left and {unknown index: its expression in the remaining unknowns}. ``eqs`` is updated
    in place."""
    index = {u.name(): k for k, u in enumerate(unknowns)}
    vars_of = [{index[s.name()] for s in ca.symvar(e) if s.name() in index} for e in eqs]
    rows_of: dict = {k: set() for k in range(len(unknowns))}
    for r, vs in enumerate(vars_of):
        for k in vs:
            rows_of[k].add(r)
    alive = set(range(len(eqs)))
    solved: dict = {}
    progress = True
    while progress:
        progress = False
        for r in sorted(alive):
            hit = _solvable(eqs[r], vars_of[r], rows_of, unknowns)
            if hit is None:
                continue
            k, value = hit
            u = unknowns[k]
            for r2 in rows_of[k] - {r}:
                eqs[r2] = ca.substitute(eqs[r2], u, value)
                vars_of[r2] = (vars_of[r2] | vars_of[r]) - {k}
                for j in vars_of[r] - {k}:
                    rows_of[j].add(r2)
            for j in list(solved):
                if ca.depends_on(solved[j], u):
                    solved[j] = ca.substitute(solved[j], u, value)
            solved[k] = value
            for j in vars_of[r]:
                rows_of[j].discard(r)
            rows_of[k] = set()
            alive.discard(r)
            progress = True
    return sorted(alive), solved


def _solvable(eq, vs: set, rows_of: dict, unknowns: list):
    """(k, value) if eq is affine in unknown k with a numeric coefficient and is trivial for
    it (at most one other unknown in it, or k in no other equation), else None."""
    for k in sorted(vs):
        if len(vs) > 2 and len(rows_of[k]) > 1:
            continue
        a = ca.jacobian(eq, unknowns[k])
        if not a.is_constant():
            continue
        a = float(a)
        if a == 0.0:
            continue
        return k, -ca.substitute(eq, unknowns[k], 0) / a
    return None


def _check_structure(eqs, unknowns, labels, what, explicit):
    """None for a structurally regular network; the over-determined equations (a loop or
    cut set: module's docstring) if some are; refuses an under-determined one."""
    n_eq, n_un = len(eqs), len(unknowns)
    rows, cols = ca.jacobian_sparsity(_vc(*eqs), _vc(*unknowns)).get_triplet()
    incidence = csr_matrix((np.ones(len(rows)), (rows, cols)), shape=(n_eq, n_un))
    match = maximum_bipartite_matching(incidence, perm_type="column")   # row -> column
    col_match = -np.ones(n_un, dtype=int)
    for r, c in enumerate(match):
        if c >= 0:
            col_match[c] = r
    unmatched_rows = [r for r in range(n_eq) if match[r] < 0]
    unmatched_cols = [c for c in range(n_un) if col_match[c] < 0]
    if not unmatched_rows and not unmatched_cols:
        return None
    by_row = [[] for _ in range(n_eq)]
    by_col = [[] for _ in range(n_un)]
    for r, c in zip(rows, cols):
        by_row[r].append(c)
        by_col[c].append(r)
    if unmatched_rows:                  # over-determined: rows reachable by alternating paths
        return sorted(_alternating(unmatched_rows, by_row, col_match))
    seen = _alternating(unmatched_cols, by_col, match)
    nodes = sorted({w.name for kind, w in (what[c] for c in seen) if kind == "node"})
    others = sorted({w.path for kind, w in (what[c] for c in seen) if kind != "node"})
    raise StructureError(
        f"network not determined: the potentials of nodes {', '.join(nodes) or '-'}"
        f"{' and the unknowns of ' + ', '.join(others) if others else ''} follow from no "
        f"equation; give the circuit a reference potential (an electrical Ground, a "
        f"FixedTemperature or a HeatCapacitor on a thermal network)")


def _singular_rows(eqs: list, unknowns: list):
    """None when the network's Jacobian in its unknowns is regular; else the equations a
    left null vector combines into a relation free of unknowns (a loop or cut set the
    structure cannot see: through elements that give their flows in both potentials). The
    Jacobian is equilibrated and evaluated at two random points of the other symbols
    (states, time, modes); singular at both counts as singular."""
    J = ca.jacobian(_vc(*eqs), _vc(*unknowns))
    others = _vc(*ca.symvar(J))
    f = ca.Function("network_jacobian", [others], [J])
    rng = np.random.default_rng(1)
    for _ in range(2):
        Jn = np.array(f(rng.uniform(0.5, 2.0, others.numel())))
        Jn /= np.maximum(np.abs(Jn).max(axis=1, keepdims=True), 1e-300)
        Jn /= np.maximum(np.abs(Jn).max(axis=0, keepdims=True), 1e-300)
        N = null_space(Jn.T, rcond=1e-12)
        if N.shape[1] == 0:
            return None
    w = np.abs(N[:, 0])
    return [r for r in range(len(eqs)) if w[r] > 1e-9 * w.max()]


def _alternating(start: list, neighbours: list, partner) -> set:
    """The vertices of one side of the matching graph reachable from the unmatched ``start``
    by alternating paths: to a neighbour, then to its matched partner (Dulmage-Mendelsohn)."""
    seen, stack = set(start), list(start)
    while stack:
        for other in neighbours[stack.pop()]:
            nxt = partner[other]
            if nxt >= 0 and nxt not in seen:
                seen.add(nxt)
                stack.append(nxt)
    return seen


def _check_reference(nodes: list, eqs: list) -> None:
    """Refuse a connected circuit (nodes of one domain joined through components) whose
    potentials are not fixed: the equations do not change when they all shift by δ."""
    parent = list(range(len(nodes)))

    def find(k):
        while parent[k] != k:
            k = parent[k]
        return k

    first = {}
    for k, n in enumerate(nodes):
        for p in n.ports:
            key = (id(p.owner), n.domain.name)
            if key in first:
                parent[find(k)] = find(first[key])
            else:
                first[key] = k
    sets: dict = {}
    for k in range(len(nodes)):
        sets.setdefault(find(k), []).append(k)
    rng = np.random.default_rng(0)
    for members in sets.values():
        delta = ca.SX.sym("<shift>")
        pots = _vc(*[nodes[k].potential for k in members])
        shifted = ca.substitute(_vc(*eqs), pots, pots + delta)
        J = ca.jacobian(shifted, delta)
        free = [v for v in ca.symvar(J) if v.name() != "<shift>"]
        f = ca.Function("shift", [_vc(delta, *free)], [J])
        if np.any(np.asarray(f(rng.uniform(0.5, 2.0, 1 + len(free))))):
            continue
        parts = sorted({_part(p.owner) for k in members for p in nodes[k].ports})
        raise StructureError(f"{nodes[members[0]].domain.name} network without a reference "
                             f"potential: {', '.join(parts)} float (every potential may shift "
                             f"together); connect a Ground to it (electrical), or a "
                             f"FixedTemperature / HeatCapacitor (thermal)")


def _part(c) -> str:
    return f"{type(c).__name__} '{c.path}'"


def _over_message(labels, explicit) -> str:
    nodes = [w for kind, w in labels if kind == "node"]
    comps = []
    for kind, w in labels:
        if kind == "component" and w not in comps:
            comps.append(w)
    if nodes:                          # Kirchhoff's current law over given flows: a cut set
        givers = []
        for n in nodes:
            for p in n.ports:
                if p in explicit and p.owner not in givers:
                    givers.append(p.owner)
        dom = nodes[0].domain
        return (f"higher-index network: the {dom.flows[0]} into node(s) "
                f"{', '.join(n.name for n in nodes)} are all fixed by "
                f"{', '.join(_part(c) for c in givers) or 'no component'}"
                f"{' (through ' + ', '.join(_part(c) for c in comps) + ')' if comps else ''}: "
                f"a cut set of inductors / flow sources, where Kirchhoff's current law "
                f"constrains their states; put a resistor (or "
                f"capacitor) across one of them, from the node to the ground, or merge "
                f"inductors in series into one")
    return (f"higher-index network: {', '.join(_part(c) for c in comps)} fix the same "
            f"potentials in a loop (capacitors / voltage sources / grounds, or heat "
            f"capacitors / fixed temperatures, joined directly): one of their potential "
            f"differences follows from the others, Kirchhoff's voltage law constrains their "
            f"states; put a resistor (thermal conductor) in "
            f"series with one of them, or merge parallel capacitors into one")
