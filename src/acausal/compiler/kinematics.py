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

A node's velocity is conjugate to its flows: der(pos) for 1-D and planar nodes, the twist
(v, w) resolved in the frame for a 3-D frame, whose position is r_0 and R.T
(``Domain.dof`` ≠ ``Domain.dim``; ``relations.pose_rate``). A 3-D node's relaxation ε is a
virtual twist (``relations.relax_spatial``). A 3-D frame the relations cannot reach (a
free body, the relative frame of a FreeMotion or Spherical joint) becomes a free root with
orientation states: a quaternion and the angular velocity, Lagrange's equations written in
a local chart about the current orientation (``charts``).

Where the graph has closed loops, the tree is a choice: the relation that closes a loop
decides which joints' coordinates the tree keeps. Taking relations in declaration order
would let that order decide whether the coordinates carry mass (PlanarMechanics'
KinematicLoop and PistonEngine, whose loops run through massless links, compiled in one
order and not in another). ``choose_tree`` decides by mass instead:

- which nodes have mass is known from the components' physics, not their structure (a
  Body's frame, an Inertia's centre, a custom component's kinetic energy), and physics
  needs the nodes' motion, i.e. a tree. So for a graph with loops the compiler runs the
  components' physics once more with every node free (``assemble._massive_nodes``: each
  node its own position, velocity and acceleration symbols) and takes the nodes whose
  velocity enters the kinetic energy (a non-zero block of ∂²T/∂v²). Models without loops
  skip this dry run.
- a coordinate carries mass when some node with mass moves with it (depends on it in the
  tree). The tree in declaration order is kept when all its coordinates do. Otherwise the
  coordinates that share a loop row with a massless one are candidates: a candidate is
  deferred (``build_tree``'s ``defer``: it becomes a free root only after the other nodes of
  its rank), which moves the loop's cut to its joint; a deferral that lowers the number of
  massless coordinates is kept, and the search goes on from there (each candidate tried
  once, the last declared first: where mass leaves a choice, the joints declared first
  keep their coordinates).

In KinematicLoop (a pendulum hangs from the end of the first of two massless links) this
cuts the loop at that link's ground joint, so that the path to the pendulum runs through
every other joint of the loop; in PistonEngine (a slider-crank with a massless rod) at the
crank's or the slider's ground joint, where both ends of the rod move a mass. Where no tree
gives every coordinate mass (a massless link between two joints of a loop whose masses sit
elsewhere), the massless coordinates that remain are dependent coordinates of the loop:
``motion.solve_motion`` takes their accelerations from the loop constraints instead of from a
mass. Either way the motion is the same; the choice only decides which joints are states.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import casadi as ca

from ..core.ports import Domain, PhysicalPort
from .charts import FreeFrame, free_root
from .relations import pose_rate, relax_spatial
from .symbolic import Row, combine, der_with, stack, sx


class InternalNode(PhysicalPort):
    """A point of a component that is not a port (a Mass's centre): relations may use it."""

    def __init__(self, domain: Domain, velocity: str = "", acceleration: str = "",
                 preferred: bool = True):
        super().__init__()
        self.domain = domain
        self.velocity, self.acceleration, self.preferred = velocity, acceleration, preferred


def motion_symbols(prefix: str, domain: Domain, der_table: dict) -> tuple[ca.SX, ca.SX, ca.SX]:
    """Free position, velocity and acceleration symbols ``<prefix>.pos`` / ``.vel`` /
    ``.acc`` of a node of ``domain`` (not on any tree: the dry run for masses, batched
    physics), their rates entered in ``der_table`` (a 3-D frame's position rate from its
    twist: ``relations.pose_rate``)."""
    pos, vel, acc = (ca.SX.sym(f"{prefix}.{k}", d) for k, d in (
        ("pos", domain.dim), ("vel", domain.dof), ("acc", domain.dof)))
    for a, b in ((pos, pose_rate(pos, vel)), (vel, acc), (acc, None)):
        for k in range(a.numel()):
            der_table[a[k].name()] = b[k] if b is not None else None
    return pos, vel, acc


def side_by_side(nodes: list, one_d: tuple, kind: str) -> ca.SX:
    """The ``kind`` ('pos', 'vel' or 'acc') of ``nodes``, one column each: a slice of the
    tree's stacked 1-D motion ``one_d`` (``Tree.one_d``) where every node is a row of it,
    else joined node by node."""
    rows = [n.row for n in nodes]
    if one_d and None not in rows:
        return one_d[("pos", "vel", "acc").index(kind)][rows, :].T
    return ca.horzcat(*[getattr(n, kind) for n in nodes])


class StackedRows:
    """Stacked (pos, vel, acc) vectors whose rows are read one by one: a few rows are
    indexed (what compiling reads), and a vector read more often is split into all its
    rows once (indexing a long SX costs ~11 µs a read, splitting it ~2 µs a row: what
    recording every variable reads)."""
    __slots__ = ("vectors", "_rows", "_reads")
    SPLIT_AFTER = 64                # reads of one vector

    def __init__(self, vectors: tuple):
        self.vectors, self._rows = vectors, [None] * len(vectors)
        self._reads = [0] * len(vectors)

    def row(self, k: int, i: int) -> ca.SX:
        if self._rows[k] is None:
            self._reads[k] += 1
            if self._reads[k] <= self.SPLIT_AFTER:
                return self.vectors[k][i]
            self._rows[k] = ca.vertsplit(self.vectors[k])
        return self._rows[k][i]


class Node:
    """A group of connected ports: one pose (potentials) shared by all of them.

    ``pos``, ``vel`` and ``acc`` are its motion; a 1-D node of the tree (``row`` set by
    ``stack``) takes them from the tree's stacked motion on first use: most nodes are
    only ever read in slices of it (``side_by_side``)."""
    __slots__ = ("index", "ports", "coordinate", "form", "row", "_motion", "_stacked")

    def __init__(self, index: int, ports: list[PhysicalPort]):
        self.index, self.ports = index, ports
        self.coordinate: list[int] | None = None     # indices of q if this node is a free root
        self.form: dict | None = None                # linear form of pos over the tree's atoms
        self.row: int | None = None                  # of a 1-D node: its row in Tree.one_d
        self._motion, self._stacked = [None, None, None], None

    def _get(self, k: int):
        if self._motion[k] is None and self.row is not None:
            self._motion[k] = self._stacked.row(k, self.row)
        return self._motion[k]

    def _set(self, k: int, value) -> None:
        self._motion[k] = value

    pos = property(lambda self: self._get(0), lambda self, v: self._set(0, v))
    vel = property(lambda self: self._get(1), lambda self, v: self._set(1, v))
    acc = property(lambda self: self._get(2), lambda self, v: self._set(2, v))

    def stack(self, stacked: "StackedRows", row: int) -> None:
        """Make this node row ``row`` of the stacked (pos, vel, acc) ``stacked``."""
        self._motion, self._stacked, self.row = [None, None, None], stacked, row

    @property
    def domain(self) -> Domain:
        return self.ports[0].domain

    @property
    def name(self) -> str:
        return self.ports[0].path

    def preferred(self, state_names: dict) -> bool:
        """Whether a component marked one of its ports (or internal points) as a natural
        coordinate: a preferred internal node, or a port that names its coordinates."""
        return any(getattr(p, "preferred", False) or p in state_names for p in self.ports)


class Atoms:
    """The independent quantities node positions are linear in: coordinates, relaxations ε,
    and right-hand sides of relations (constants and prescribed motions). Each has a position,
    velocity and acceleration expression. Relaxations made in blocks (``block``) keep their
    stacked vectors, so that ``materialize`` joins whole blocks instead of their scalars."""

    def __init__(self, der_table: dict):
        self.pos, self.vel, self.acc = [], [], []
        self.rhs = []                  # indices of atoms whose rates are derived in bulk
        self.fixed = []                # indices of atoms that are parameters (rates 0)
        self.blocks = []               # (atom indices, (pos, vel, acc) stacked vectors)
        self._const = {}
        self._der_table = der_table

    def add(self, pos, vel, acc) -> int:
        self.pos.append(pos); self.vel.append(vel); self.acc.append(acc)
        return len(self.pos) - 1

    def block(self, pos: ca.SX, vel: ca.SX, acc: ca.SX) -> range:
        """Atoms for the rows of stacked vectors (their motion as ``Row``s); their indices."""
        first, size = len(self.pos), pos.numel()
        self.blocks.append((range(first, first + size), (pos, vel, acc)))
        for x, out in zip((pos, vel, acc), (self.pos, self.vel, self.acc)):
            out.extend(Row(x, i) for i in range(size))
        return range(first, first + size)

    def constant(self, b) -> dict:
        """Linear form of a relation's rhs b: nothing for 0, an atom otherwise."""
        if isinstance(b, float):
            if b == 0.0:
                return {}
            key = ("num", b)
            if key not in self._const:
                self._const[key] = self.add(ca.SX(b), ca.SX(0), ca.SX(0))
            return {self._const[key]: 1.0}
        key = ("expr", id(b))          # one atom for an expression several relations share
        if key not in self._const:     # (a Mass's length at both flanges)
            self._const[key] = k = self.add(b, None, None)
            fixed = b.is_symbolic() and b.name() not in self._der_table
            (self.fixed if fixed else self.rhs).append(k)
        return {self._const[key]: 1.0}

    def motion(self, k: int, der) -> tuple:
        """(pos, vel, acc) of atom k, deriving the rates of a rhs atom now if needed."""
        if self.vel[k] is None:
            self.vel[k] = der(self.pos[k])
            self.acc[k] = der(self.vel[k])
        return sx(self.pos[k]), sx(self.vel[k]), sx(self.acc[k])

    def materialize(self, der) -> tuple[list[int], tuple[ca.SX, ca.SX, ca.SX]]:
        """Stacked position, velocity and acceleration of all atoms, the atoms outside
        blocks first, then the blocks whole; and the row of each atom in them. The rhs atoms
        whose rates are not known yet become one more block, their rates by one
        total-derivative call on all of them, and the parameters one more, rates 0."""
        pending = [k for k in self.rhs if self.vel[k] is None]
        if pending:
            b = ca.vertcat(*[self.pos[k] for k in pending])
            bd = der(b)
            self.blocks.append((pending, (b, bd, der(bd))))
        fixed = [k for k in self.fixed if self.vel[k] is None]
        if fixed:
            zeros = ca.SX.zeros(len(fixed))
            self.blocks.append((fixed, (ca.vertcat(*[self.pos[k] for k in fixed]), zeros,
                                        zeros)))
        in_blocks = {k for indices, _ in self.blocks for k in indices}
        loose = [k for k in range(len(self.pos)) if k not in in_blocks]
        order = loose + [k for indices, _ in self.blocks for k in indices]
        row = [0] * len(order)
        for r, k in enumerate(order):
            row[k] = r
        stacked = tuple(ca.vertcat(ca.vertcat(*[xs[k] for k in loose]),
                                   *[vectors[i] for _, vectors in self.blocks])
                        for i, xs in enumerate((self.pos, self.vel, self.acc)))
        return row, stacked


def _forms_to_matrix(forms: list[dict], column: list[int]):
    """Sparse matrix S with S[i, column[k]] = forms[i][k] (DM when every coefficient is a
    number)."""
    rows, cols, vals = [], [], []
    for i, f in enumerate(forms):
        for k, c in f.items():
            rows.append(i); cols.append(column[k]); vals.append(c)
    n_atoms = len(column)
    if all(isinstance(v, float) for v in vals):
        return ca.DM.triplet(rows, cols, ca.DM(vals), len(forms), n_atoms)
    return ca.SX.triplet(rows, cols, ca.vertcat(*[ca.SX(v) for v in vals]), len(forms), n_atoms)


@dataclass(frozen=True)
class FiredRelation:
    """A relation that determined a node: its relaxation ε (and ε̇, ε̈; SX, or ``Row``s of
    a block of scalar ones), whose conjugate generalized force is the relation's reaction."""
    relation: object
    eps: ca.SX | Row
    epsd: ca.SX | Row
    epsdd: ca.SX | Row

    @property
    def dim(self) -> int:
        return 1 if isinstance(self.eps, Row) else self.eps.numel()


@dataclass(frozen=True)
class LoopBlock:
    """Consecutive rows of Φ from one relation that closes a loop: ``flows(λ)`` gives the
    flows at its ports for its multipliers, or is None for the extra rows of a relation that
    also fired (their flows come with the fired relation's)."""
    relation: object
    rows: int
    flows: object


@dataclass
class Tree:
    """Result of the coordinate choice."""
    nodes: list[Node]
    q: ca.SX
    qd: ca.SX
    qdd: ca.SX
    q_names: list[str]
    qd_names: list[str]
    fired: list[FiredRelation] = field(default_factory=list)
    loops: list[LoopBlock] = field(default_factory=list)
    loop_residual: ca.SX = None                    # Φ of the loops, stacked in that order
    loop_rows: list = field(default_factory=list)  # a name for each row of Φ
    charts: list = field(default_factory=list)     # charts.Chart of the free 3-D frames
    one_d: tuple = ()            # stacked (pos, vel, acc) of the 1-D nodes, by Node.row

    def relaxations(self) -> tuple[ca.SX, ca.SX, ca.SX]:
        """ε, ε̇ and ε̈ of the fired relations, stacked in their order."""
        return tuple(stack([getattr(f, k) for f in self.fired])
                     for k in ("eps", "epsd", "epsdd"))


def choose_tree(nodes: list[Node], relations: list, der_table: dict, state_names: dict,
                massive_nodes) -> Tree:
    """The tree of ``build_tree`` whose coordinates carry mass, where the loops leave a choice.

    ``massive_nodes()`` gives the indices of the nodes with mass (their velocity enters the
    kinetic energy); it is called only if the graph has loops. The tree in declaration order
    is kept when all its coordinates carry mass. Otherwise each coordinate that shares a loop
    row with a massless one is a candidate: deferring it (``build_tree``'s ``defer``) moves
    the loop's cut to it. Candidates are tried each once, from the last declared back (where
    mass leaves a choice, the joints declared first keep their coordinates, as in the tree of
    declaration order); one that lowers the count of massless coordinates is kept, and the
    search goes on from that tree until the count is 0 or no candidate is left. The
    relations keep what the chosen tree fired (it is built last), and ``der_table`` holds
    its symbols.
    """
    base = dict(der_table)
    tree = build_tree(nodes, relations, der_table, state_names)
    if not tree.loops:
        return tree
    massive = massive_nodes()
    count, candidates = _assess(tree, nodes, massive)
    defer, tried = frozenset(), set()
    while count:
        todo = [c for c in reversed(candidates) if c not in tried and c not in defer]
        if not todo:
            break
        for c in todo:
            tried.add(c)
            trial = build_tree(nodes, relations, dict(base), state_names, defer | {c})
            trial_count, trial_candidates = _assess(trial, nodes, massive)
            if trial_count < count:
                count, candidates, defer = trial_count, trial_candidates, defer | {c}
                break
    if tried:                 # the trials left their state in the relations: build the choice
        der_table.clear()
        der_table.update(base)
        tree = build_tree(nodes, relations, der_table, state_names, defer)
    return tree


def _assess(tree: Tree, nodes: list[Node], massive: set[int]) -> tuple[int, list[int]]:
    """How many of the tree's coordinates move no node with mass, and the free-root nodes
    (indices, in node order) whose coordinates share a loop row with such a coordinate: the
    candidates for cutting those loops elsewhere."""
    nq = tree.q.numel()
    pos = [n.pos for n in nodes if n.index in massive]
    moved = set(ca.jacobian_sparsity(ca.vertcat(*pos), tree.q).get_triplet()[1]) \
        if pos and nq else set()
    massless = set(range(nq)) - moved
    if not massless or not tree.loop_residual.numel():
        return len(massless), []
    rows, cols = ca.jacobian_sparsity(tree.loop_residual, tree.q).get_triplet()
    loops = {r for r, k in zip(rows, cols) if k in massless}
    near = {k for r, k in zip(rows, cols) if r in loops}
    return len(massless), [n.index for n in nodes
                           if n.coordinate and any(k in near for k in n.coordinate)]


def build_tree(nodes: list[Node], relations: list, der_table: dict,
               state_names: dict, defer=frozenset()) -> Tree:
    """Choose coordinates, give every node its position, velocity and acceleration.

    ``der_table`` maps symbol names to their time derivatives; it is extended with the
    coordinates and relaxations created here. ``state_names`` maps ports to the names of the
    coordinates they get if they need free ones (StructureBuilder.states). ``defer``: indices
    of nodes that become free roots only after the other candidates of their rank (so that
    a relation at such a node closes a loop rather than starting a branch).
    """
    by_node: dict[int, list] = {n.index: [] for n in nodes}
    for r in relations:
        for n in r.nodes:
            by_node[n.index].append(r)
    used = set()
    atoms = Atoms(der_table)
    der = lambda ex: der_with(ex, der_table)                       # noqa: E731
    q, qd, qdd, q_names, qd_names = [], [], [], [], []
    fired, lin_loops, nl_loops = [], [], []       # nl_loops: (relation, Φ rows, flows)
    charts = []                                   # orientation states of free 3-D frames
    for n in nodes:
        n.form = n.coordinate = n.row = None
        n.pos = n.vel = n.acc = None

    def known(n: Node) -> bool:
        return n.form is not None or n.pos is not None

    def values(n: Node):
        """(pos, vel, acc) of a known node; 1-D nodes are materialized from their form."""
        if n.pos is None:
            parts = [(c, atoms.motion(k, der)) for k, c in n.form.items()]
            n.pos, n.vel, n.acc = (combine(0, [(c, m[i]) for c, m in parts]) for i in range(3))
        return n.pos, n.vel, n.acc

    scalar_relaxations = []             # unused (ε, ε̇, ε̈) of 1-D relations, made in blocks
    # at most one per relation that may determine a 1-D node: the first block's size
    scalar_bound = sum(1 for r in relations
                       if r.linear or any(n.domain.dof == 1 for n in r.nodes))

    def relax(dim: int):
        k = len(fired)
        if dim == 1:
            if not scalar_relaxations:
                size = max(8, k if k else scalar_bound)
                scalar_relaxations.extend(reversed(_relaxation_block(k, size, der_table,
                                                                     atoms)))
            return scalar_relaxations.pop()
        e, ed, edd = (ca.SX.sym(f"eps{k}", dim), ca.SX.sym(f"epsd{k}", dim),
                      ca.SX.sym(f"epsdd{k}", dim))
        for a, b, c in zip(*(ca.vertsplit(x) for x in (e, ed, edd))):
            der_table[a.name()], der_table[b.name()], der_table[c.name()] = b, c, None
        return e, ed, edd, None

    def visit(r):
        unknown = [i for i, n in enumerate(r.nodes) if not known(n)]
        if len(unknown) > 1 or (unknown and not r.can_solve(unknown[0])):
            return None
        used.add(id(r))
        if not unknown:
            if r.linear:
                lin_loops.append(r)
            else:
                nl_loops.append((r, r.loop_residual(values), r.flows_loop))
            return None
        j = unknown[0]
        node = r.nodes[j]
        e, ed, edd, atom = relax(node.domain.dof if not r.linear else 1)
        if r.linear:
            node.form = r.solve(j, atoms, atom)
        else:
            (pos, vel, acc), extra = r.fire(j, values)
            if node.domain.dim == 1:
                node.form = {atoms.add(pos + sx(e), vel + sx(ed), acc + sx(edd)): 1.0}
            elif node.domain.dof != node.domain.dim:          # a 3-D frame: a virtual twist
                node.pos, node.vel, node.acc = relax_spatial(pos, vel, acc, e, ed, edd)
            else:
                node.pos, node.vel, node.acc = pos + e, vel + ed, acc + edd
            if extra is not None:
                nl_loops.append((r, extra, None))        # its flows: with the fired ones
        fired.append(FiredRelation(r, e, ed, edd))
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
    # free coordinates: joints' and masses' own (internal nodes) first, then ports that name
    # their coordinates (a free Body), then anything; deferred nodes last within their rank
    def rank(n: Node) -> tuple:
        kind = 0 if any(isinstance(p, InternalNode) and p.preferred for p in n.ports) \
            else 1 if n.preferred(state_names) else 2
        return kind, n.index in defer

    order = sorted(nodes, key=rank)
    for n in order:
        if known(n):
            continue
        if n.domain.dof != n.domain.dim:              # a free 3-D frame: a chart
            chart, coords = free_root(n, _free_frame(n, state_names), der_table)
            charts.append(chart)
            for s, v, a, qname, vname in coords:
                q.append(s); qd.append(v); qdd.append(a)
                q_names.append(qname); qd_names.append(vname)
            propagate([n])
            continue
        dim = n.domain.dim
        syms = []
        for pot in n.domain.potentials:
            qname, vname = _state_names(n, len(syms), pot, state_names)
            s, v, a = ca.SX.sym(qname), ca.SX.sym(vname), ca.SX.sym(f"der({vname})")
            der_table[qname], der_table[vname], der_table[f"der({vname})"] = v, a, None
            q.append(s); qd.append(v); qdd.append(a)
            q_names.append(qname); qd_names.append(vname)
            syms.append((s, v, a))
        n.coordinate = list(range(len(q) - dim, len(q)))
        if dim == 1:
            n.form = {atoms.add(*syms[0]): 1.0}
        else:
            n.pos, n.vel, n.acc = (ca.vertcat(*[x[i] for x in syms]) for i in range(3))
        propagate([n])
    for r in relations:               # relations among nodes that were all known already
        if id(r) not in used:
            visit(r)

    # materialize 1-D nodes: their motion is a sparse linear map of the atoms' motion
    one_d = [n for n in nodes if n.domain.dim == 1]
    forms = [n.form for n in one_d] + [r.residual(atoms) for r in lin_loops]
    column, atom_motion = atoms.materialize(der)
    S = _forms_to_matrix(forms, column)
    stacked = tuple(ca.mtimes(S, X) for X in atom_motion)
    rows_of = StackedRows(stacked)
    for i, n in enumerate(one_d):
        n.stack(rows_of, i)
    rows = [stacked[0][len(one_d):, :]]       # Φ: the linear loops' rows, then the others
    loops = [LoopBlock(r, 1, r.flows) for r in lin_loops]
    names = [r.owner.path for r in lin_loops]
    for r, phi, flows in nl_loops:
        rows.append(phi)
        loops.append(LoopBlock(r, phi.numel(), flows))
        names += [f"{r.owner.path}.{c}" for c in r.row_names(flows is None)]
    vec = lambda xs: ca.vertcat(*xs) if xs else ca.SX(0, 1)      # noqa: E731
    return Tree(nodes, vec(q), vec(qd), vec(qdd), q_names, qd_names, fired, loops, vec(rows),
                names, charts, tuple(x[:len(one_d), :] for x in stacked))


def _relaxation_block(k: int, size: int, der_table: dict, atoms: Atoms) -> list[tuple]:
    """``size`` scalar relaxations (ε, ε̇, ε̈ as ``Row``s of three vectors, atom index)
    named eps<k>_<i>, epsd<k>_<i>, epsdd<k>_<i>, their rates entered in ``der_table``, one
    block of ``atoms``: symbols made in blocks cost a third of one by one (the first block as
    large as the relations that may need one, any further one as large as the relaxations
    made so far)."""
    e, ed, edd = (ca.SX.sym(f"{base}{k}", size) for base in ("eps", "epsd", "epsdd"))
    out = []
    for i, atom in enumerate(atoms.block(e, ed, edd)):
        rates = Row(ed, i), Row(edd, i)
        der_table[f"eps{k}_{i}"], der_table[f"epsd{k}_{i}"], der_table[f"epsdd{k}_{i}"] = \
            rates[0], rates[1], None
        out.append((Row(e, i), rates[0], rates[1], atom))
    return out


def _free_frame(n: Node, state_names: dict):
    """The FreeFrame a component declared for a port (or internal node) of the free 3-D
    node ``n``, or None."""
    for p in n.ports:
        spec = state_names.get(p)
        if isinstance(spec, FreeFrame):
            return spec
    return None


def _state_names(n: Node, k: int, potential: str, state_names: dict) -> tuple[str, str]:
    """Names of the k-th coordinate of a free node and of its rate: those a component gave
    (StructureBuilder.states, a Mass's centre ``mass.s``/``mass.v``), else the first port's
    ``<port>.<potential>`` and ``der(...)``."""
    for p in n.ports:
        names = state_names.get(p)
        if names:
            base = f"{p.owner.path}." if p.owner.path else ""
            return base + names[0][k], base + names[1][k]
    for p in n.ports:
        if isinstance(p, InternalNode) and n.domain.dim == 1:
            base = f"{p.owner.path}." if p.owner.path else ""
            return p.path, (base + p.velocity if p.velocity else f"der({p.path})")
    qname = f"{n.name}.{potential}"
    return qname, f"der({qname})"
