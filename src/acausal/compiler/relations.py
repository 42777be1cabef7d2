"""Kinematic relations components declare between their ports (and internal nodes).

A relation can determine any one of its nodes from the others (it *fires* in the tree) or,
when all its nodes are known already, close a loop (a constraint Φ = 0). Either way the flows
(forces, torques) it exerts at its ports follow from its reaction λ by virtual work:
flow_i = (∂Φ/∂pose_i)ᵀ λ, with Φ the relation written so that the fired node's relaxation ε
enters as Φ = ε.

- LinearRelation: Σ a_i·pos_i = b between 1-D ports: rigid offsets, gears, prescribed motion.
- RigidTransform, RevoluteJoint, PrismaticJoint: planar frames, frame_b = frame_a ⊕ a relative
  pose that is constant or given by a joint coordinate (a 1-D node).
- SpatialTransform, SpatialRevolute, SpatialPrismatic: the same for 3-D frames
  (``core.ports.MULTIBODY``).

One mechanism serves 2-D and 3-D. A node has a position ``pos`` (its potentials) and a
velocity ``vel`` conjugate to its flows. For 1-D and planar nodes ``vel`` = der(pos). A 3-D
frame's position is r_0 and R.T (12 numbers, ``frames.pose``) but its velocity is the
twist (v, w) resolved in the frame (6 numbers), conjugate to MSL's (f, t) resolved in the
frame; ``pose_rate`` maps the twist to der(pos) and ``twist`` maps der(pos) back. A relation
gives node j's position from the others'; its velocity follows by AD through these two maps
(or from the closed form a class may give, ``velocity_local``: the 3-D relations do, as the
AD route builds equations five times larger; tests compare the two), and its acceleration
and the Jacobian that maps reactions to flows (∂vel_j/∂vel_i) by AD from the velocity, for
planar and 3-D relations alike. The relaxation ε of a 3-D
node that a relation determines is a virtual twist: r_0 + R.Tᵀ·ε_r and (I − [ε_θ×])·R.T
(first order in ε, all the reactions need; ``relax_spatial``), whose conjugate reaction is
the cut force and torque at the frame.
"""
from __future__ import annotations

import casadi as ca

from ..errors import StructureError
from ..core.ports import PhysicalPort
from ..frames import FRAME_ROWS, equality_constraint, parts, planar_rotation, pose, skew, vee


class LinearRelation:
    """Σ a_i · pos(port_i) = b for 1-D ports: rigid offsets, gears, prescribed motion.

    The coefficients a_i are numbers or expressions of parameters; b may also depend on
    time, internal states and signals (prescribed motion). The flow at port i is a_i·λ, λ
    the reaction.
    """
    linear = True
    dim = 1

    def __init__(self, owner, ports: list[PhysicalPort], coeffs: list, rhs, name: str = ""):
        for p in ports:
            if p.domain.dim != 1:
                raise StructureError(f"{owner.path}: a linear relation joins 1-D ports; "
                                     f"'{p.path}' is {p.kind}")
        self.owner, self.ports = owner, list(ports)
        self.coeffs = [c if isinstance(c, ca.SX) else float(c) for c in coeffs]
        # a (factor, expression) pair stays a product in the linear forms (no SX operation)
        self.rhs = (float(rhs[0]), rhs[1]) if isinstance(rhs, tuple) else \
            rhs if isinstance(rhs, ca.SX) else float(rhs)
        self.name = name or f"{owner.path}: relation"
        self.nodes = []

    def can_solve(self, j: int) -> bool:
        return True

    def solve(self, j: int, atoms, eps: int) -> dict:
        """Linear form of node j's position from the other nodes', the rhs and the relaxation
        atom ``eps``: pos_j = (b + ε − Σ_{i≠j} a_i pos_i) / a_j."""
        form = {eps: 1.0}
        _axpy(form, 1.0, self._rhs(atoms))
        for i, (a, n) in enumerate(zip(self.coeffs, self.nodes)):
            if i != j:
                _axpy(form, -a, n.form)
        return _scale(form, self.coeffs[j])

    def residual(self, atoms) -> dict:
        """Linear form of Σ a_i pos_i − b (a loop-closing constraint)."""
        form = {}
        for a, n in zip(self.coeffs, self.nodes):
            _axpy(form, a, n.form)
        _axpy(form, -1.0, self._rhs(atoms))
        return form

    def _rhs(self, atoms) -> dict:
        if isinstance(self.rhs, tuple):
            return {k: self.rhs[0] * c for k, c in atoms.constant(self.rhs[1]).items()}
        return atoms.constant(self.rhs)

    def flows(self, lam: ca.SX) -> list[tuple[PhysicalPort, ca.SX]]:
        return list(zip(self.ports, ca.vertsplit(linear_flows([self], lam, [0]))))


def linear_flows(relations: list[LinearRelation], lam: ca.SX, rows: list[int]) -> ca.SX:
    """The flows a_i·λ at the ports of linear ``relations`` (``LinearRelation.flows``),
    stacked relation by relation; the reaction λ of relation k is ``lam[rows[k]]``. One
    product of two vectors (an SX operation per port from Python costs ~3 µs)."""
    coeffs = [a for r in relations for a in r.coeffs]
    if not coeffs:
        return ca.SX(0, 1)
    a = ca.DM(coeffs) if not any(isinstance(c, ca.SX) for c in coeffs) else \
        ca.vertcat(*[c if isinstance(c, ca.SX) else ca.SX(c) for c in coeffs])
    return a * lam[[k for r, k in zip(relations, rows) for _ in r.ports], 0]


def _axpy(form: dict, a, other: dict) -> None:
    """form += a · other (linear forms: atom index -> coefficient)."""
    for k, c in other.items():
        v = c if (isinstance(a, float) and a == 1.0) else a * c
        form[k] = form[k] + v if k in form else v


def _scale(form: dict, a) -> dict:
    if isinstance(a, float) and a == 1.0:
        return form
    return {k: c / a for k, c in form.items()}


# ---- planar frames ------------------------------------------------------------------------
def _vec(v) -> ca.SX:
    """A vector given as an SX or as a sequence of numbers / SX."""
    return v if isinstance(v, ca.SX) else ca.vertcat(*[ca.SX(x) for x in v])


def _rot(phi, v):
    """R(phi)·v for a 2-vector v."""
    c, s = ca.cos(phi), ca.sin(phi)
    return ca.vertcat(c * v[0] - s * v[1], s * v[0] + c * v[1])


_KIND = {1: "a 1-D flange", 3: "a planar frame", 12: "a 3-D frame"}


def pose_rate(pos, vel):
    """der(pos) of a node from its velocity: vel itself, except for a 3-D frame, whose
    twist (v, w) resolved in the frame gives der(r_0) = Tᵀv and der(T) = −[w×]T."""
    if pos.numel() == vel.numel():
        return vel
    _, T = parts(pos)
    return pose(ca.mtimes(T.T, vel[:3]), -ca.mtimes(skew(vel[3:6]), T))


def twist(pos, rate):
    """A node's velocity from der(pos) (inverse of ``pose_rate``): for a 3-D frame
    v = T·der(r_0) and [w×] = T·der(T)ᵀ (its skew part, exact for orthogonal T)."""
    if pos.numel() != 12:
        return rate
    _, T = parts(pos)
    rd, Td = parts(rate)
    return ca.vertcat(ca.mtimes(T, rd), vee(ca.mtimes(T, Td.T)))


def _relax_spatial() -> ca.Function:
    pos, vel, acc = ca.SX.sym("pos", 12), ca.SX.sym("vel", 6), ca.SX.sym("acc", 6)
    e, ed, edd = ca.SX.sym("e", 6), ca.SX.sym("ed", 6), ca.SX.sym("edd", 6)
    r, T = parts(pos)
    relaxed = pose(r + ca.mtimes(T.T, e[:3]), T - ca.mtimes(skew(e[3:6]), T))
    rate = pose_rate(pos, vel)
    # the twist of ``relaxed`` to first order in ε (= twist(relaxed, der(relaxed)) there)
    v, w, er, et = vel[:3], vel[3:], e[:3], e[3:]
    v = ca.vertcat(v + ed[:3] + ca.cross(w, er) - ca.cross(et, v), w + ed[3:] - ca.cross(et, w))
    a = ca.jtimes(v, ca.vertcat(pos, vel, e, ed), ca.vertcat(rate, acc, ed, edd))
    return ca.Function("relax_spatial", [pos, vel, acc, e, ed, edd], [relaxed, v, a])


#: (pos, vel, acc, ε, ε̇, ε̈) of a 3-D frame -> its relaxed (pos, vel, acc): ε = (ε_r, ε_θ)
#: a virtual displacement and rotation resolved in the frame, to first order
relax_spatial = _relax_spatial()


class FrameRelation:
    """A nonlinear relation among nodes of given dimensions, with parameters.

    Subclasses give ``dims`` (one per node: 1 for a 1-D node, 3 for a planar frame, 12 for a
    3-D frame), ``solve_local(j, vals, par)`` -> (position of node j, extra constraint rows
    or None) from the others' positions, and ``residual_local(vals, par)`` (all nodes
    known). From these, velocities (through ``pose_rate`` and ``twist``), accelerations and
    the Jacobians for the flows are derived once per class and direction by AD on local
    symbols (casadi Functions), so firing a relation costs one Function call.
    """
    linear = False
    dims: tuple[int, ...] = ()
    _cache: dict = {}

    def __init__(self, owner, ports: list, params: list, name: str = ""):
        self.owner, self.ports = owner, list(ports)
        self.params = [p if isinstance(p, ca.SX) else ca.SX(p) for p in params]
        self.name = name or f"{owner.path}"
        self.nodes = []
        for p, d in zip(self.ports, self.dims):
            if p.domain.dim != d:
                raise StructureError(f"{owner.path}: port '{p.path}' should be {_KIND[d]}")

    # to be given by subclasses
    def solve_local(self, j, vals, par):
        raise NotImplementedError

    def residual_local(self, vals, par):
        raise NotImplementedError

    def velocity_local(self, j, vals, vels, par):
        """Node j's velocity in closed form from the others' positions and velocities, or
        None: derived by AD from ``solve_local`` (the same expression, numerically; a closed
        form is smaller, which the 3-D relations give)."""
        return None

    def can_solve(self, j: int) -> bool:
        return True

    def row_names(self, extra: bool) -> tuple[str, ...]:
        """Names of the constraint rows: all of the residual, or the extra rows left when
        the joint's coordinate was solved from its frames."""
        return ("x", "y", "phi")

    # derived, cached per class
    @property
    def kind(self):
        """What the derived Functions are cached by (with dims and parameter sizes)."""
        return type(self)

    @property
    def dofs(self) -> tuple[int, ...]:
        """Size of each node's velocity (6 for a 3-D frame, else its dimension)."""
        return tuple(6 if d == 12 else d for d in self.dims)

    def _locals(self):
        vals = [ca.SX.sym(f"n{i}", d) for i, d in enumerate(self.dims)]
        vels = [ca.SX.sym(f"v{i}", d) for i, d in enumerate(self.dofs)]
        accs = [ca.SX.sym(f"a{i}", d) for i, d in enumerate(self.dofs)]
        par = [ca.SX.sym(f"p{k}", p.numel()) for k, p in enumerate(self.params)]
        return vals, vels, accs, par

    def _solver(self, j: int) -> ca.Function:
        key = (self.kind, self.dims, "solve", j, tuple(p.numel() for p in self.params))
        if key not in FrameRelation._cache:
            vals, vels, accs, par = self._locals()
            others = [i for i in range(len(self.dims)) if i != j]
            value, extra = self.solve_local(j, {i: vals[i] for i in others}, par)
            X = ca.vertcat(*[vals[i] for i in others])
            Xd = ca.vertcat(*[vels[i] for i in others])
            Xdd = ca.vertcat(*[accs[i] for i in others])
            rate = ca.vertcat(*[pose_rate(vals[i], vels[i]) for i in others])
            vel = self.velocity_local(j, {i: vals[i] for i in others},
                                      {i: vels[i] for i in others}, par)
            if vel is None:
                vel = twist(value, ca.jtimes(value, X, rate))
            acc = ca.jtimes(vel, ca.vertcat(X, Xd), ca.vertcat(rate, Xdd))
            J = ca.jacobian(vel, Xd)                # reactions to flows: ∂vel_j/∂vel_i
            extra = extra if extra is not None else ca.SX(0, 1)
            Je = ca.jacobian(ca.jtimes(extra, X, rate), Xd)
            Jej = ca.SX(extra.numel(), self.dofs[j])
            ins = [vals[i] for i in others] + [vels[i] for i in others] + \
                  [accs[i] for i in others] + par
            FrameRelation._cache[key] = ca.Function(
                f"{type(self).__name__}_solve{j}", ins, [value, vel, acc, J, extra, Je, Jej])
        return FrameRelation._cache[key]

    def _residual(self) -> ca.Function:
        """Φ of the relation closing a loop and its Jacobian with respect to the nodes'
        velocities (twists of 3-D frames): the map of its multipliers to the flows."""
        key = (self.kind, self.dims, "residual", tuple(p.numel() for p in self.params))
        if key not in FrameRelation._cache:
            vals, vels, _, par = self._locals()
            phi = self.residual_local({i: v for i, v in enumerate(vals)}, par)
            X, V = ca.vertcat(*vals), ca.vertcat(*vels)
            rate = ca.vertcat(*[pose_rate(x, v) for x, v in zip(vals, vels)])
            FrameRelation._cache[key] = ca.Function(
                f"{type(self).__name__}_residual", vals + par,
                [phi, ca.jacobian(ca.jtimes(phi, X, rate), V)])
        return FrameRelation._cache[key]

    def fire(self, j: int, node_values) -> tuple:
        """Node j from the others: (pos, vel, acc), and the rows of extra constraints (or
        None). ``node_values(n)`` gives (pos, vel, acc) of a known node. Keeps what the
        flows need."""
        others = [i for i in range(len(self.dims)) if i != j]
        known = [node_values(self.nodes[i]) for i in others]
        args = [k[0] for k in known] + [k[1] for k in known] + [k[2] for k in known]
        pos, vel, acc, J, extra, Je, _ = self._solver(j)(*args, *self.params)
        self._fired = (j, others, J, Je)
        return (pos, vel, acc), (extra if extra.numel() else None)

    def flows_fired(self, lam: ca.SX, lam_extra: ca.SX | None):
        """Flows at the ports when this relation fired: λ at node j (relaxation ε added to
        it), −Jᵢᵀλ at the others; extra constraint rows add Jeᵢᵀ λ_extra."""
        j, others, J, Je = self._fired
        out = {j: lam}
        col = 0
        for i in others:
            d = self.dofs[i]
            f = -ca.mtimes(J[:, col:col + d].T, lam)
            if lam_extra is not None and lam_extra.numel():
                f = f + ca.mtimes(Je[:, col:col + d].T, lam_extra)
            out[i] = f
            col += d
        return [(self.ports[i], out[i]) for i in range(len(self.dims))]

    def loop_residual(self, node_values):
        vals = [node_values(n)[0] for n in self.nodes]
        phi, J = self._residual()(*vals, *self.params)
        self._loop = J
        return phi

    def flows_loop(self, lam: ca.SX):
        out, col = [], 0
        for p, d in zip(self.ports, self.dofs):
            out.append((p, ca.mtimes(self._loop[:, col:col + d].T, lam)))
            col += d
        return out


class DeclaredRelation(FrameRelation):
    """A relation a component writes itself (``StructureBuilder.relation``): ``solve`` maps
    the index j of a node it can determine to ``f(vals, par) -> (pos_j, extra rows or
    None)``, ``residual(vals, par)`` gives its rows when it closes a loop (None: it never
    does), ``rows`` names them (``extra_rows`` the extra rows of a firing). ``vals`` maps
    node indices to positions, ``par`` lists the local symbols of ``params``. The derived
    Functions are cached per component class and ``name``: the callables must depend on
    nothing but their arguments."""

    def __init__(self, owner, ports, params, solve, residual, rows, extra_rows, name):
        self.dims = tuple(p.domain.dim for p in ports)
        self._solve, self._residual_of = dict(solve or {}), residual
        self._rows, self._extra_rows = tuple(rows), tuple(extra_rows)
        super().__init__(owner, ports, params)
        self._key = (type(owner), name)

    @property
    def kind(self):
        return self._key

    def can_solve(self, j: int) -> bool:
        return j in self._solve

    def solve_local(self, j, vals, par):
        return self._solve[j](vals, par)

    def residual_local(self, vals, par):
        return self._residual_of(vals, par)

    def loop_residual(self, node_values):
        if self._residual_of is None:
            raise StructureError(
                f"{type(self.owner).__name__} '{self.owner.path}' closes a kinematic loop in "
                f"a way it cannot (all its frames are fixed by other paths); open the loop "
                f"at another joint")
        return super().loop_residual(node_values)

    def row_names(self, extra):
        return self._extra_rows if extra else self._rows


class RigidTransform(FrameRelation):
    """frame_b = frame_a ⊕ (r resolved in frame_a [m], phi [rad]); without frame_a, frame_b is
    fixed in the world at (r, phi)."""
    dims = (3, 3)

    def __init__(self, owner, frame_a, frame_b, r, phi, name=""):
        if frame_a is None:
            self.dims = (3,)
            super().__init__(owner, [frame_b], [_vec(r), phi], name)
        else:
            super().__init__(owner, [frame_a, frame_b], [_vec(r), phi], name)

    def solve_local(self, j, vals, par):
        r, phi = par
        if len(self.dims) == 1:
            return ca.vertcat(r, phi), None
        if j == 1:
            a = vals[0]
            return ca.vertcat(a[:2] + _rot(a[2], r), a[2] + phi), None
        b = vals[1]
        pa = b[2] - phi
        return ca.vertcat(b[:2] - _rot(pa, r), pa), None

    def residual_local(self, vals, par):
        r, phi = par
        if len(self.dims) == 1:
            return vals[0] - ca.vertcat(r, phi)
        a, b = vals[0], vals[1]
        return b - ca.vertcat(a[:2] + _rot(a[2], r), a[2] + phi)


class RevoluteJoint(FrameRelation):
    """frame_b = frame_a rotated by the joint angle (a 1-D node) about their common origin."""
    dims = (3, 3, 1)

    def __init__(self, owner, frame_a, frame_b, angle, name=""):
        super().__init__(owner, [frame_a, frame_b, angle], [], name)

    def solve_local(self, j, vals, par):
        if j == 1:
            a, q = vals[0], vals[2]
            return ca.vertcat(a[:2], a[2] + q), None
        if j == 0:
            b, q = vals[1], vals[2]
            return ca.vertcat(b[:2], b[2] - q), None
        a, b = vals[0], vals[1]
        return b[2] - a[2], b[:2] - a[:2]

    def residual_local(self, vals, par):
        a, b, q = vals[0], vals[1], vals[2]
        return b - ca.vertcat(a[:2], a[2] + q)

    def row_names(self, extra):
        return ("x", "y") if extra else ("x", "y", "phi")


class PrismaticJoint(FrameRelation):
    """frame_b = frame_a translated by s·e (s the joint coordinate, a 1-D node; e a unit
    vector resolved in frame_a); no relative rotation."""
    dims = (3, 3, 1)

    def __init__(self, owner, frame_a, frame_b, s, e, name=""):
        super().__init__(owner, [frame_a, frame_b, s], [_vec(e)], name)

    def solve_local(self, j, vals, par):
        (e,) = par
        if j == 1:
            a, s = vals[0], vals[2]
            return ca.vertcat(a[:2] + s * _rot(a[2], e), a[2]), None
        if j == 0:
            b, s = vals[1], vals[2]
            return ca.vertcat(b[:2] - s * _rot(b[2], e), b[2]), None
        a, b = vals[0], vals[1]
        d = b[:2] - a[:2]
        ea = _rot(a[2], e)
        n = ca.vertcat(-ea[1], ea[0])
        return ca.dot(ea, d) / ca.dot(e, e), ca.vertcat(ca.dot(n, d), b[2] - a[2])

    def residual_local(self, vals, par):
        (e,) = par
        a, b, s = vals[0], vals[1], vals[2]
        return b - ca.vertcat(a[:2] + s * _rot(a[2], e), a[2])

    def row_names(self, extra):
        return ("normal", "phi") if extra else ("x", "y", "phi")


# ---- 3-D frames ---------------------------------------------------------------------------
class SpatialRelation(FrameRelation):
    """A relation among 3-D frames (and a joint's 1-D coordinate). Subclasses give the
    velocity map in closed form (``velocity_local``, what the AD route gives, smaller;
    tests compare the two).

    Closing a loop (all its nodes known), it compares the frame it would determine (its
    last frame: frame_b, or the one frame of a frame fixed in the world) with where the
    rest of the loop puts it: ``frame_residual``, 6 rows (3 of position, 3 of
    orientation) whose multipliers are the cut force and torque at that frame resolved in
    it. Where the loop is planar or otherwise over-constrained, the rows that add nothing
    to the rank of Φ_q are found at the assembled configuration (``compiler.loops``)."""

    def can_solve(self, j: int) -> bool:
        return self.dims[j] == 12          # a joint's coordinate is never solved from frames

    def residual_local(self, vals, par):
        j = 1 if len(self.dims) > 1 else 0
        pred, _ = self.solve_local(j, {i: v for i, v in vals.items() if i != j}, par)
        return frame_residual(pred, vals[j])

    def row_names(self, extra):
        return FRAME_ROWS


def frame_residual(expected, actual) -> ca.SX:
    """The 6 rows that vanish when the 3-D frame ``actual`` is at ``expected`` (both
    ``pose``): the position error resolved in ``actual`` [m], then MSL's
    ``Frames.Orientation.equalityConstraint`` [rad]. Their Jacobian with respect to
    ``actual``'s twist is the identity where they vanish, so their multipliers are the cut
    force [N] and torque [N.m] at ``actual``, resolved in it."""
    re, Te = parts(expected)
    r, T = parts(actual)
    return ca.vertcat(ca.mtimes(T, r - re), equality_constraint(Te, T))


class SpatialTransform(SpatialRelation):
    """frame_b = frame_a translated by r [m] (resolved in frame_a) and rotated by T_rel
    (frame_b's axes resolved in frame_a's: v_b = T_rel·v_a); without frame_a, frame_b is
    fixed in the world at r with orientation T_rel."""
    dims = (12, 12)

    def __init__(self, owner, frame_a, frame_b, r, T, name=""):
        if frame_a is None:
            self.dims = (12,)
            super().__init__(owner, [frame_b], [_vec(r), ca.vec(T)], name)
        else:
            super().__init__(owner, [frame_a, frame_b], [_vec(r), ca.vec(T)], name)

    def solve_local(self, j, vals, par):
        r, T = par[0], ca.reshape(par[1], 3, 3)
        if len(self.dims) == 1:
            return pose(r, T), None
        return _composed(j, vals, r, T), None

    def velocity_local(self, j, vals, vels, par):
        r, T = par[0], ca.reshape(par[1], 3, 3)
        if len(self.dims) == 1:
            return ca.SX.zeros(6)
        return _composed_twist(j, vels, r, T, ca.SX.zeros(6))


def _composed(j, vals, r, T):
    """Frame j (1: frame_b, 0: frame_a) of frame_b = frame_a followed by (r [m] resolved in
    frame_a, T from frame_a to frame_b), from the other frame in ``vals``."""
    if j == 1:
        ra, Ta = parts(vals[0])
        return pose(ra + ca.mtimes(Ta.T, r), ca.mtimes(T, Ta))
    rb, Tb = parts(vals[1])
    Ta = ca.mtimes(T.T, Tb)
    return pose(rb - ca.mtimes(Ta.T, r), Ta)


def _composed_twist(j, vels, r, T, rel):
    """The twist of frame j of ``_composed`` from the other's, ``rel`` = (v_rel, w_rel) the
    relative motion resolved in frame_b: v_b = T(v_a + w_a × r) + v_rel, w_b = T w_a + w_rel."""
    vr, wr = rel[:3], rel[3:]
    if j == 1:
        v, w = vels[0][:3], vels[0][3:]
        return ca.vertcat(ca.mtimes(T, v + ca.cross(w, r)) + vr, ca.mtimes(T, w) + wr)
    v, w = vels[1][:3], vels[1][3:]
    wa = ca.mtimes(T.T, w - wr)
    return ca.vertcat(ca.mtimes(T.T, v - vr) - ca.cross(wa, r), wa)


class SpatialRevolute(SpatialRelation):
    """frame_b = frame_a rotated by the joint angle (a 1-D node) about the unit axis e
    (resolved in frame_a and frame_b) through their common origin (MSL's Revolute)."""
    dims = (12, 12, 1)

    def __init__(self, owner, frame_a, frame_b, angle, e, name=""):
        super().__init__(owner, [frame_a, frame_b, angle], [_vec(e)], name)

    def solve_local(self, j, vals, par):
        (e,) = par
        R = planar_rotation(e, vals[2])
        if j == 1:
            ra, Ta = parts(vals[0])
            return pose(ra, ca.mtimes(R, Ta)), None
        rb, Tb = parts(vals[1])
        return pose(rb, ca.mtimes(R.T, Tb)), None

    def velocity_local(self, j, vals, vels, par):
        (e,) = par
        R = planar_rotation(e, vals[2])
        if j == 1:            # v_b = R v_a, w_b = R w_a + e·w
            v, w = vels[0][:3], vels[0][3:]
            return ca.vertcat(ca.mtimes(R, v), ca.mtimes(R, w) + e * vels[2])
        v, w = vels[1][:3], vels[1][3:]
        return ca.vertcat(ca.mtimes(R.T, v), ca.mtimes(R.T, w - e * vels[2]))


class SpatialPrismatic(SpatialRelation):
    """frame_b = frame_a translated by s·e (s the joint coordinate, a 1-D node; e a unit
    vector resolved in frame_a); no relative rotation (MSL's Prismatic)."""
    dims = (12, 12, 1)

    def __init__(self, owner, frame_a, frame_b, s, e, name=""):
        super().__init__(owner, [frame_a, frame_b, s], [_vec(e)], name)

    def solve_local(self, j, vals, par):
        (e,) = par
        if j == 1:
            ra, Ta = parts(vals[0])
            return pose(ra + ca.mtimes(Ta.T, e * vals[2]), Ta), None
        rb, Tb = parts(vals[1])
        return pose(rb - ca.mtimes(Tb.T, e * vals[2]), Tb), None

    def velocity_local(self, j, vals, vels, par):
        (e,) = par
        if j == 1:            # v_b = v_a + w_a × (e s) + e·v, w_b = w_a
            v, w = vels[0][:3], vels[0][3:]
            return ca.vertcat(v + ca.cross(w, e * vals[2]) + e * vels[2], w)
        v, w = vels[1][:3], vels[1][3:]
        return ca.vertcat(v - ca.cross(w, e * vals[2]) - e * vels[2], w)


class SpatialDistance(SpatialRelation):
    """A 1-D node at the distance |r_b − r_a| [m] between the origins of two 3-D frames
    (MSL's LineForceWithMass: flange_b.s = length): the node's force acts along the line,
    on frame_b away from frame_a, by virtual work. Only the node is solved from the frames."""
    dims = (12, 12, 1)

    def __init__(self, owner, frame_a, frame_b, node, name=""):
        super().__init__(owner, [frame_a, frame_b, node], [], name)

    def can_solve(self, j: int) -> bool:
        return j == 2

    def solve_local(self, j, vals, par):
        return ca.norm_2(parts(vals[1])[0] - parts(vals[0])[0]), None


class SpatialCompose(SpatialRelation):
    """frame_b = frame_a followed by the relative pose of the 3-D node ``rel`` (r_rel
    resolved in frame_a, T_rel from frame_a to frame_b): a joint whose relative motion has
    several degrees of freedom held by a free node of its own (FreeMotion, Spherical; the
    node's states in ``compiler.charts``). rel's twist is the relative motion resolved in
    frame_b: (T_rel·der(r_rel), w_rel)."""
    dims = (12, 12, 12)

    def __init__(self, owner, frame_a, frame_b, rel, name=""):
        super().__init__(owner, [frame_a, frame_b, rel], [], name)

    def can_solve(self, j: int) -> bool:
        return j != 2                      # the relative pose is never solved from frames

    def solve_local(self, j, vals, par):
        return _composed(j, vals, *parts(vals[2])), None

    def velocity_local(self, j, vals, vels, par):
        return _composed_twist(j, vels, *parts(vals[2]), vels[2])
