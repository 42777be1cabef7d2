"""The kinematic graph: relations between port groups, the spanning tree, the coordinates.

Nodes are groups of connected ports (plus components' internal nodes, e.g. a Mass's centre).
Relations are the kinematic equations components declare between their ports. Starting from
the ground (relations that fix a node), every relation with one unknown node determines that
node; when none can, an unknown node becomes a free root and gets generalized coordinates
(preferring the internal nodes components mark as natural states, so that a Mass's
coordinate is its centre ``mass.s``). A relation whose nodes are all known when it is reached
closes a loop and becomes a constraint Φ = 0.

Every relation that determines a node is relaxed by a virtual coordinate ε (zero in the
model); the generalized force conjugate to ε is the relation's reaction, from which the flows
(cut forces, torques) at its ports are recovered.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import casadi as ca

from ..core.errors import StructureError
from ..core.ports import Domain, PhysicalPort
from .symbolic import combine, der_with


class InternalNode(PhysicalPort):
    """A point of a component that is not a port (a Mass's centre): relations may use it."""

    def __init__(self, domain: Domain, velocity: str = "", acceleration: str = "",
                 preferred: bool = True):
        super().__init__()
        self.domain = domain
        self.velocity, self.acceleration, self.preferred = velocity, acceleration, preferred


@dataclass
class Node:
    """A group of connected ports: one pose (potentials) shared by all of them."""
    index: int
    ports: list[PhysicalPort]
    pos: ca.SX | None = None
    vel: ca.SX | None = None
    acc: ca.SX | None = None
    coordinate: list[int] | None = None          # indices of q if this node is a free root

    @property
    def domain(self) -> Domain:
        return self.ports[0].domain

    @property
    def name(self) -> str:
        return self.ports[0].path

    @property
    def preferred(self) -> bool:
        return any(getattr(p, "preferred", False) for p in self.ports)


class LinearRelation:
    """Σ a_i · pos(port_i) = b for 1-D ports: rigid offsets, gears, prescribed motion.

    The coefficients a_i may depend on parameters only; b on parameters, time, internal
    states and signals (prescribed motion: ``varying``). The flow at port i is a_i·λ, λ the
    reaction.
    """
    dim = 1

    def __init__(self, owner, ports: list[PhysicalPort], coeffs: list, rhs, name: str = "",
                 varying: bool = True):
        for p in ports:
            if p.domain.dim != 1:
                raise StructureError(f"{owner.path}: a linear relation joins 1-D ports; "
                                     f"'{p.path}' is {p.kind}")
        self.owner, self.ports = owner, list(ports)
        self.coeffs = [c if isinstance(c, ca.SX) else float(c) for c in coeffs]
        self.rhs = rhs if isinstance(rhs, ca.SX) else float(rhs)
        self.varying = varying
        self.name = name or f"{owner.path}: relation"
        self.nodes: list[Node] = []

    def solve(self, j: int, der, eps: ca.SX) -> tuple[ca.SX, ca.SX, ca.SX]:
        """Position, velocity, acceleration of node j from the others and the relaxation eps."""
        a = self.coeffs
        b = self.rhs
        bd = der(b) if self.varying else 0.0
        bdd = der(bd) if self.varying else 0.0
        e, ed, edd = eps
        others = [i for i in range(len(a)) if i != j]
        neg = [(-a[i] if isinstance(a[i], float) else -a[i], i) for i in others]
        pos = combine(b, [(1, e)] + [(c, self.nodes[i].pos) for c, i in neg], a[j])
        vel = combine(bd, [(1, ed)] + [(c, self.nodes[i].vel) for c, i in neg], a[j])
        acc = combine(bdd, [(1, edd)] + [(c, self.nodes[i].acc) for c, i in neg], a[j])
        return pos, vel, acc

    def residual(self) -> ca.SX:
        return combine(-self.rhs, [(a, n.pos) for a, n in zip(self.coeffs, self.nodes)])

    def flows(self, lam: ca.SX) -> list[tuple[PhysicalPort, ca.SX]]:
        return [(p, combine(0, [(a, lam)])) for p, a in zip(self.ports, self.coeffs)]


@dataclass
class Tree:
    """Result of the coordinate choice."""
    nodes: list[Node]
    q: ca.SX
    qd: ca.SX
    qdd: ca.SX
    q_names: list[str]
    qd_names: list[str]
    fired: list = field(default_factory=list)      # (relation, eps, epsd, epsdd)
    loops: list = field(default_factory=list)      # relations that close loops


def build_tree(nodes: list[Node], relations: list, der_table: dict) -> Tree:
    """Choose coordinates, give every node its position, velocity and acceleration.

    ``der_table`` maps symbol names to their time derivatives; it is extended with the
    coordinates and relaxations created here.
    """
    by_node: dict[int, list] = {n.index: [] for n in nodes}
    for r in relations:
        for n in r.nodes:
            by_node[n.index].append(r)
    used = set()
    q, qd, qdd, q_names, qd_names = [], [], [], [], []
    fired, loops = [], []
    def der(ex):
        return der_with(ex, der_table)

    def visit(r):
        unknown = [i for i, n in enumerate(r.nodes) if n.pos is None]
        if len(unknown) > 1:
            return None
        used.add(id(r))
        if not unknown:
            loops.append(r)
            return None
        j = unknown[0]
        k = len(fired)
        e, ed, edd = (ca.SX.sym(f"eps{k}"), ca.SX.sym(f"epsd{k}"), ca.SX.sym(f"epsdd{k}"))
        der_table[e.name()], der_table[ed.name()] = ed, edd
        node = r.nodes[j]
        node.pos, node.vel, node.acc = r.solve(j, der, (e, ed, edd))
        fired.append((r, e, ed, edd))
        return node

    def propagate(start: list[Node]):
        stack = list(start)
        while stack:
            n = stack.pop()
            for r in by_node[n.index]:
                if id(r) not in used:
                    new = visit(r)
                    if new is not None:
                        stack.append(new)

    # ground: relations with no unknown besides one node fire first
    propagate_roots = []
    for r in relations:
        if id(r) not in used and len({n.index for n in r.nodes}) == 1 and len(r.nodes) == 1:
            new = visit(r)
            if new is not None:
                propagate_roots.append(new)
    propagate(propagate_roots)
    order = [n for n in nodes if n.preferred] + [n for n in nodes if not n.preferred]
    for n in order:
        if n.pos is not None:
            continue
        idx = []
        for k, pname in enumerate(n.domain.potentials):
            qname = n.name if _is_named_state(n) and n.domain.dim == 1 else f"{n.name}.{pname}"
            vname = _velocity_name(n, qname)
            s, v, a = ca.SX.sym(qname), ca.SX.sym(vname), ca.SX.sym(f"der({vname})")
            der_table[s.name()], der_table[v.name()] = v, a
            idx.append(len(q))
            q.append(s); qd.append(v); qdd.append(a)
            q_names.append(qname); qd_names.append(vname)
        n.coordinate = idx
        if len(idx) == 1:
            n.pos, n.vel, n.acc = q[idx[0]], qd[idx[0]], qdd[idx[0]]
        else:
            n.pos, n.vel, n.acc = (ca.vertcat(*[q[i] for i in idx]),
                                   ca.vertcat(*[qd[i] for i in idx]),
                                   ca.vertcat(*[qdd[i] for i in idx]))
        propagate([n])
    for r in relations:               # relations among nodes that were all known already
        if id(r) not in used:
            visit(r)
    return Tree(nodes, ca.vertcat(*q) if q else ca.SX(0, 1), ca.vertcat(*qd) if qd else ca.SX(0, 1),
                ca.vertcat(*qdd) if qdd else ca.SX(0, 1), q_names, qd_names, fired, loops)


def _is_named_state(n: Node) -> bool:
    return any(isinstance(p, InternalNode) for p in n.ports)


def _velocity_name(n: Node, qname: str) -> str:
    for p in n.ports:
        if isinstance(p, InternalNode) and p.velocity:
            return f"{p.owner.path}.{p.velocity}" if p.owner.path else p.velocity
    return f"der({qname})"
