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
    form: dict | None = None                     # linear form of pos over the tree's atoms

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

    The coefficients a_i are numbers or expressions of parameters; b may also depend on
    time, internal states and signals (prescribed motion). The flow at port i is a_i·λ, λ
    the reaction.
    """
    dim = 1

    def __init__(self, owner, ports: list[PhysicalPort], coeffs: list, rhs, name: str = ""):
        for p in ports:
            if p.domain.dim != 1:
                raise StructureError(f"{owner.path}: a linear relation joins 1-D ports; "
                                     f"'{p.path}' is {p.kind}")
        self.owner, self.ports = owner, list(ports)
        self.coeffs = [c if isinstance(c, ca.SX) else float(c) for c in coeffs]
        self.rhs = rhs if isinstance(rhs, ca.SX) else float(rhs)
        self.name = name or f"{owner.path}: relation"
        self.nodes: list[Node] = []

    def solve(self, j: int, atoms: "Atoms", eps: int) -> dict:
        """Linear form of node j's position from the other nodes', the rhs and the relaxation
        atom ``eps``: pos_j = (b + ε − Σ_{i≠j} a_i pos_i) / a_j."""
        form = {eps: 1.0}
        _axpy(form, 1.0, atoms.constant(self.rhs))
        for i, (a, n) in enumerate(zip(self.coeffs, self.nodes)):
            if i != j:
                _axpy(form, -a, n.form)
        return _scale(form, self.coeffs[j])

    def residual(self, atoms: "Atoms") -> dict:
        """Linear form of Σ a_i pos_i − b (a loop-closing constraint)."""
        form = {}
        for a, n in zip(self.coeffs, self.nodes):
            _axpy(form, a, n.form)
        _axpy(form, -1.0, atoms.constant(self.rhs))
        return form

    def flows(self, lam: ca.SX) -> list[tuple[PhysicalPort, ca.SX]]:
        return [(p, combine(0, [(a, lam)])) for p, a in zip(self.ports, self.coeffs)]


def _axpy(form: dict, a, other: dict) -> None:
    """form += a · other (linear forms: atom index -> coefficient)."""
    for k, c in other.items():
        v = c if (isinstance(a, float) and a == 1.0) else a * c
        form[k] = form[k] + v if k in form else v


def _scale(form: dict, a) -> dict:
    if isinstance(a, float) and a == 1.0:
        return form
    return {k: c / a for k, c in form.items()}


class Atoms:
    """The independent quantities node positions are linear in: coordinates, relaxations ε,
    and right-hand sides of relations (constants and prescribed motions). Each has a position,
    velocity and acceleration expression."""

    def __init__(self):
        self.pos, self.vel, self.acc = [], [], []
        self.rhs = []                  # indices of atoms whose rates are derived in bulk
        self._const = {}

    def add(self, pos, vel, acc) -> int:
        self.pos.append(pos); self.vel.append(vel); self.acc.append(acc)
        return len(self.pos) - 1

    def constant(self, b) -> dict:
        """Linear form of a relation's rhs b: nothing for 0, an atom otherwise."""
        if isinstance(b, float):
            if b == 0.0:
                return {}
            key = ("num", b)
            if key not in self._const:
                self._const[key] = self.add(ca.SX(b), ca.SX(0), ca.SX(0))
            return {self._const[key]: 1.0}
        k = self.add(b, None, None)
        self.rhs.append(k)
        return {k: 1.0}

    def materialize(self, der) -> tuple[ca.SX, ca.SX, ca.SX]:
        """Stacked position, velocity and acceleration of all atoms (rates of the rhs atoms
        by one total-derivative call on all of them)."""
        if self.rhs:
            b = ca.vertcat(*[self.pos[k] for k in self.rhs])
            bd = der(b)
            bds, bdds = ca.vertsplit(bd), ca.vertsplit(der(bd))
            for i, k in enumerate(self.rhs):
                self.vel[k], self.acc[k] = bds[i], bdds[i]
        return (ca.vertcat(*self.pos), ca.vertcat(*self.vel), ca.vertcat(*self.acc))


def _forms_to_matrix(forms: list[dict], n_atoms: int):
    """Sparse matrix S with S[i, k] = forms[i][k] (DM when every coefficient is a number)."""
    rows, cols, vals = [], [], []
    for i, f in enumerate(forms):
        for k, c in f.items():
            rows.append(i); cols.append(k); vals.append(c)
    if all(isinstance(v, float) for v in vals):
        return ca.DM.triplet(rows, cols, ca.DM(vals), len(forms), n_atoms)
    return ca.SX.triplet(rows, cols, ca.vertcat(*[ca.SX(v) for v in vals]), len(forms), n_atoms)


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
    loop_residual: ca.SX = None                    # Φ of the loop relations, stacked


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
    atoms = Atoms()
    q, qd, qdd, q_names, qd_names = [], [], [], [], []
    fired, loops = [], []
    for n in nodes:
        n.form = None

    def visit(r):
        unknown = [i for i, n in enumerate(r.nodes) if n.form is None]
        if len(unknown) > 1:
            return None
        used.add(id(r))
        if not unknown:
            loops.append(r)
            return None
        j = unknown[0]
        k = len(fired)
        e, ed, edd = (ca.SX.sym(f"eps{k}"), ca.SX.sym(f"epsd{k}"), ca.SX.sym(f"epsdd{k}"))
        der_table[e.name()], der_table[ed.name()], der_table[edd.name()] = ed, edd, None
        node = r.nodes[j]
        node.form = r.solve(j, atoms, atoms.add(e, ed, edd))
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

    grounded = []                     # relations that fix a node by themselves fire first
    for r in relations:
        if len(r.nodes) == 1 and id(r) not in used:
            new = visit(r)
            if new is not None:
                grounded.append(new)
    propagate(grounded)
    order = [n for n in nodes if n.preferred] + [n for n in nodes if not n.preferred]
    for n in order:
        if n.form is not None:
            continue
        if n.domain.dim != 1:
            raise StructureError(f"'{n.name}': {n.domain.name} frames are not supported yet")
        qname = n.name if _is_named_state(n) else f"{n.name}.{n.domain.potentials[0]}"
        vname = _velocity_name(n, qname)
        s, v, a = ca.SX.sym(qname), ca.SX.sym(vname), ca.SX.sym(f"der({vname})")
        der_table[s.name()], der_table[v.name()], der_table[a.name()] = v, a, None
        n.coordinate = [len(q)]
        q.append(s); qd.append(v); qdd.append(a)
        q_names.append(qname); qd_names.append(vname)
        n.form = {atoms.add(s, v, a): 1.0}
        propagate([n])
    for r in relations:               # relations among nodes that were all known already
        if id(r) not in used:
            visit(r)

    # materialize: every node's motion is a sparse linear map of the atoms' motion
    forms = [n.form for n in nodes] + [r.residual(atoms) for r in loops]
    S = _forms_to_matrix(forms, len(atoms.pos))
    P, Vv, A = atoms.materialize(lambda ex: der_with(ex, der_table))
    pos, vel, acc = (ca.vertsplit(ca.mtimes(S, X)) for X in (P, Vv, A))
    for i, n in enumerate(nodes):
        n.pos, n.vel, n.acc = pos[i], vel[i], acc[i]
    nn = len(nodes)
    residual = ca.vertcat(*pos[nn:]) if loops else ca.SX(0, 1)
    vec = lambda xs: ca.vertcat(*xs) if xs else ca.SX(0, 1)
    return Tree(nodes, vec(q), vec(qd), vec(qdd), q_names, qd_names, fired, loops, residual)


def _is_named_state(n: Node) -> bool:
    return any(isinstance(p, InternalNode) for p in n.ports)


def _velocity_name(n: Node, qname: str) -> str:
    for p in n.ports:
        if isinstance(p, InternalNode) and p.velocity:
            return f"{p.owner.path}.{p.velocity}" if p.owner.path else p.velocity
    return f"der({qname})"
