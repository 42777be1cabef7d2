"""Orientation states of free 3-D frames: quaternions, with Lagrange's equations written in a
local chart about the current orientation.

A 3-D frame with no path through joints to the world (a free Body, the relative frame of a
FreeMotion or Spherical joint) becomes a free root of the tree. Its orientation state is a
quaternion Q (4 numbers, MSL's order and convention, ``frames.from_Q``), its velocity
state the angular velocity w resolved in the frame (a quasi-velocity: not the rate of any
coordinate), and, for a free frame, its position r [m] with rate v = der(r) [m/s]: 13
states for a free body (7 for a spherical joint's relative rotation: Q and w).

Why quaternions and not minimal angles with a chart switch: a quaternion covers every
orientation with one smooth state (no event, no reinit, no switching logic inside the
integrator), its rate ½·G(Q)·w is polynomial, and the orientation is taken from Q/|Q|
(``frames.from_Q``), so a drift of the norm changes no orientation and no physics. The rate
½·G(Q)·w is tangent to |Q| = const, so the norm moves only by the integration error; a
radial term keeps it: der(Q) = ½·G(Q)·w + k·(1 − |Q|²)·Q with k = √(|w|² + 1) [1/s]
(``norm_gain``), which pulls |Q| back to 1 on the time scale of the rotation itself
without touching the orientation (Q/|Q|) or stiffening the equations (its eigenvalue −2k
is of the size of the rotation's frequency |w| the steps resolve anyway); it vanishes on
|Q| = 1 and adds that one stable eigenvalue to a linearization.

How Lagrange's equations get to quasi-velocities: at every instant the orientation is
written as T = E(θ)·T(Q), E(θ) = exp(−[θ×]) (to second order), with Q held constant (its
entry in ``der_table`` is 0) and θ = 0 at that instant. θ is a generalized coordinate like
any other: its rate θ̇ is the state w (the frame's angular velocity θ̇ − ½·θ × θ̇ + O(θ²)
equals it at θ = 0, and so does its rate), so the compiler's machinery (AD of T and V,
virtual work of the port flows, reactions, recorded accelerations) runs unchanged in the
chart, and every expression is then evaluated at θ = 0 (``at_origin``). Lagrange's
equations need the kinematics to first order in θ only (∂T/∂θ and d/dt ∂T/∂θ̇ at θ = 0),
which the chart gives exactly. The result are the Newton–Euler equations in (v, w):
M(Q)·[v̇; ẇ] + ... = Q_gen, the gyroscopic w × I·w coming from the first-order term
−½·θ × θ̇. ``compiled.lagrange`` holds them so: its coordinates of a chart are θ (named
``<...>.theta[i]``), its rates w, and M, gravity, coriolis, K, C, B are evaluated at
θ = 0 (expressions of Q; gravity and K are the generalized forces and stiffness about
the frame's axes); ``lagrange.function`` takes the positions in the states' layout (Q in
place of θ: ``lagrange.q_state``).

Closed loops through such a frame (a Spherical joint or a free body in the spanning tree
of a loop): the loop constraints Φ are expressions of θ like any others, so Φ_θ at θ = 0
is their Jacobian in the quasi-velocities w and Φ̈ comes out right (θ̈ = ẇ at θ = 0);
``compiled.lagrange.phi`` is Φ at θ = 0 (a function of Q, what the initialization projects
onto), and the stabilized index-2 form's correction Φ_θᵀμ of θ's rate enters Q's rate
(``_layout``), so the quaternion is held on Φ = 0 as the other coordinates are.

Why not minimal angles with a chart switch: that needs an event and a reinit of three
states each time the angles near their singularity, and the equations of motion in angles
are long (the inverse of the angles' velocity map); the local chart here is that idea
taken to the limit (a new chart at every instant, centred on the current orientation),
with the quaternion carrying the chart's centre.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import casadi as ca

from ..errors import StructureError
from ..frames import Q_rate, axes_rotations, axes_rotations_Q, from_Q, pose, skew

_vc = ca.vertcat


@dataclass
class FreeFrame:
    """What a component declares for a 3-D frame that may need free states
    (``StructureBuilder.free_frame``): the names of the states, ``translation`` False for a
    rotation only (the frame's origin fixed at r = 0), and their start values (numbers or
    expressions of parameters): r, v [m, m/s], Q, w [rad/s]."""
    r: tuple = ("r[1]", "r[2]", "r[3]")
    v: tuple = ("v[1]", "v[2]", "v[3]")
    Q: tuple = ("Q[1]", "Q[2]", "Q[3]", "Q[4]")
    w: tuple = ("w[1]", "w[2]", "w[3]")
    translation: bool = True
    rotation: bool = True
    start: dict = field(default_factory=dict)       # 'r', 'v', 'Q', 'w' -> 3- or 4-vector
    base: str = ""                                  # prefix of the names (owner's path)
    angles: tuple = ()                              # names of the recorded angles
    angle_rates: tuple = ()                         # names of their rates
    sequence: object = (1, 2, 3)                    # the angles' axes (numbers, parameters)


@dataclass
class AngleStart:
    """The orientation of a free frame given by three angles about the axes of a sequence
    (MSL's phi[3], e.g. of a Spherical joint's sequence_angleStates, and phi_d = der(phi)),
    as its states: ``function`` (angles [rad], their rates [rad/s], p) -> (Q, w), Q =
    axes_rotations_Q(sequence, angles) and w the angular velocity resolved in the frame
    (MSL's Frames.angularVelocity2 of axesRotations). ``angles``, ``rates``, ``Q``, ``w``:
    the names."""
    angles: tuple
    rates: tuple
    Q: tuple
    w: tuple
    function: ca.Function | None = None

    def build(self, a: ca.SX, ad: ca.SX, sequence, p: ca.SX) -> "AngleStart":
        """With ``function`` made for the symbols a, ad (3 each) and the parameters p."""
        T = axes_rotations(sequence, a)
        dT = ca.reshape(ca.jtimes(ca.vec(T), a, ad), 3, 3)
        w = _vc(ca.mtimes(T[2, :], dT[1, :].T), -ca.mtimes(T[2, :], dT[0, :].T),
                ca.mtimes(T[1, :], dT[0, :].T))
        self.function = ca.Function("angle_start", [a, ad, p],
                                    [axes_rotations_Q(sequence, a), w])
        return self


@dataclass
class Chart:
    """A free 3-D frame's states: the chart coordinates θ (0 at every instant), the
    quaternion Q, the angular velocity w; start values by state name."""
    theta: ca.SX
    Q: ca.SX
    w: ca.SX
    start: dict
    units: dict
    angles: tuple = ()          # (names of the angles, of their rates, sequence) if recorded


def free_root(node, spec: FreeFrame | None, der_table: dict):
    """Give the free 3-D ``node`` its states: (chart, [(q, qd, qdd, q_name, qd_name)]), its
    pos, vel and acc set. ``spec`` None: the names of the node's first port
    (``<port>.r_0[i]``, ``.v_0[i]``, ``.Q[i]``, ``.w[i]``), starting at rest at the
    world's origin and orientation."""
    if spec is None:
        spec = FreeFrame(r=tuple(f"r_0[{i}]" for i in (1, 2, 3)),
                         v=tuple(f"v_0[{i}]" for i in (1, 2, 3)), base=node.name)
    name = (lambda s: f"{spec.base}.{s}") if spec.base else (lambda s: s)     # noqa: E731
    coords = []

    def coordinate(qname, vname):
        s, v, a = ca.SX.sym(qname), ca.SX.sym(vname), ca.SX.sym(f"der({vname})")
        der_table[s.name()], der_table[v.name()], der_table[a.name()] = v, a, None
        coords.append((s, v, a, qname, vname))
        return s, v, a

    start = {}
    if spec.translation:
        r, v, a = (ca.vertcat(*x) for x in zip(*[coordinate(name(q), name(u))
                                                  for q, u in zip(spec.r, spec.v)]))
        for key, sym in (("r", r), ("v", v)):
            start.update(_starts(sym, spec.start.get(key)))
    else:
        r, v, a = ca.SX.zeros(3), ca.SX(0, 1), ca.SX(0, 1)
    if spec.rotation:
        base = name(spec.Q[0]).rsplit(".", 1)[0] + "." if "." in name(spec.Q[0]) else ""
        th, w, wd = (ca.vertcat(*x) for x in zip(*[coordinate(f"{base}theta[{i}]", name(u))
                                                    for i, u in zip((1, 2, 3), spec.w)]))
        Q = ca.vertcat(*[ca.SX.sym(name(q)) for q in spec.Q])
        for q in ca.vertsplit(Q):
            der_table[q.name()] = 0                  # the chart's base: constant in it
        start.update(_starts(Q, spec.start.get("Q", (0.0, 0.0, 0.0, 1.0))))
        start.update(_starts(w, spec.start.get("w")))
        S = skew(th)
        T = ca.mtimes(ca.SX.eye(3) - S + 0.5 * ca.mtimes(S, S), from_Q(Q))   # exp(−[θ×])
    else:                                            # a point: the world's orientation
        th = w = wd = Q = ca.SX(0, 1)
        T = ca.SX.eye(3)
    node.pos = pose(r, T)
    X, Xd, Xdd = _vc(r if v.numel() else v, th), _vc(v, w), _vc(a, wd)
    # the twist: T·der(r) and the angular velocity of exp(−[θ×])·T(Q) resolved in the
    # frame, θ̇ − ½·θ × θ̇ (exact to first order in θ, all the equations at θ = 0 need)
    node.vel = _vc(ca.mtimes(T, v) if v.numel() else ca.SX.zeros(3),
                   w - 0.5 * ca.cross(th, w) if w.numel() else ca.SX.zeros(3))
    node.acc = ca.jtimes(node.vel, _vc(X, Xd), _vc(Xd, Xdd))
    units = {x[3]: "m" for x in coords[:3 if spec.translation else 0]}
    units.update({x[4]: "m/s" for x in coords[:3 if spec.translation else 0]})
    units.update({q.name(): "1" for q in ca.vertsplit(Q)})
    units.update({s.name(): "rad/s" for s in ca.vertsplit(w)})
    angles = (tuple(name(a) for a in spec.angles), tuple(name(a) for a in spec.angle_rates),
              spec.sequence) if spec.rotation and spec.angles else ()
    return Chart(th, Q, w, start, units, angles), coords


def angle_starts(charts: list[Chart], p: ca.SX) -> list[AngleStart]:
    """The AngleStart of every chart whose component records angles for it."""
    a, ad = ca.SX.sym("angles", 3), ca.SX.sym("der_angles", 3)
    return [AngleStart(c.angles[0], c.angles[1], tuple(q.name() for q in ca.vertsplit(c.Q)),
                       tuple(s.name() for s in ca.vertsplit(c.w))).build(a, ad, c.angles[2], p)
            for c in charts if c.angles]


def _starts(sym: ca.SX, values) -> dict:
    if values is None:
        return {}
    return {s.name(): v for s, v in zip(ca.vertsplit(sym), ca.vertsplit(ca.vertcat(values)))}


def check_inertia(charts: list[Chart], inertia: ca.SX, qdd: ca.SX) -> None:
    """Refuse a free orientation that carries no inertia (its rows of the mass matrix, the
    Jacobian of Lagrange's ``inertia`` residuals by ``qdd``, are empty): nothing would fix
    its rotation."""
    rows = set(ca.jacobian_sparsity(inertia, qdd).get_triplet()[0])
    index = {s.name(): k for k, s in enumerate(ca.vertsplit(qdd))}
    for c in charts:
        if c.Q.numel() and any(index[f"der({s.name()})"] not in rows
                               for s in ca.vertsplit(c.w)):
            raise StructureError(
                f"the free 3-D frame with states {c.Q[0].name()[:-3]}: its rotation carries "
                f"no inertia, so nothing fixes it; give the body there an inertia tensor "
                f"(I_11, I_22, I_33 > 0) or connect it to the world through joints")


def at_origin(charts: list[Chart]) -> tuple[list, list]:
    """(from, to) for ``ca.substitute``: every chart coordinate θ at 0."""
    if not charts:
        return [], []
    th = _vc(*[c.theta for c in charts])
    return [th], [ca.SX.zeros(th.numel())]


def norm_gain(w) -> ca.SX:
    """k [1/s] of the norm-keeping term k·(1 − |Q|²)·Q: √(|w|² + 1) (smooth at rest)."""
    return ca.sqrt(ca.dot(w, w) + 1)


def _layout(charts: list[Chart], q: ca.SX, rates: ca.SX):
    """(position, rate) pairs of q in the states' layout: each chart's θ (3 entries)
    replaced by its Q (4 entries) with Q's rate ½·G(Q)·θ̇ + k·(1 − |Q|²)·Q, θ̇ the rates
    given for θ (w, and in a closed loop w + Φ_θᵀμ, the stabilized index-2 form's
    correction, which moves the orientation back onto Φ = 0 as it moves the other
    coordinates)."""
    first = {c.theta[0].name(): c for c in charts if c.Q.numel()}
    rest = {c.theta[i].name() for c in charts if c.Q.numel() for i in (1, 2)}
    rate_of = {s.name(): r for s, r in zip(ca.vertsplit(q), ca.vertsplit(rates))}
    out = []
    for s in ca.vertsplit(q):
        c = first.get(s.name())
        if c is not None:
            # θ's rate: w, plus the loops' stabilizing correction Φ_θᵀμ where there is one
            theta_rate = _vc(*[rate_of[th.name()] for th in ca.vertsplit(c.theta)])
            out.append((c.Q, Q_rate(c.Q, theta_rate)
                        + norm_gain(c.w) * (1 - ca.dot(c.Q, c.Q)) * c.Q))
        elif s.name() not in rest:
            out.append((s, rate_of[s.name()]))
    return out


def quaternion_states(charts: list[Chart], q_diff: ca.SX, q_diff_dot: ca.SX):
    """The states q_diff and their rates with each chart's θ replaced by its quaternion Q
    and Q's rate."""
    pairs = _layout(charts, q_diff, q_diff_dot)
    return _vc(*[a for a, _ in pairs]), _vc(*[b for _, b in pairs])


def state_positions(charts: list[Chart], q: ca.SX) -> ca.SX:
    """The coordinates q with each chart's θ replaced by its Q (the states' layout)."""
    if not charts:
        return q
    pairs = _layout(charts, q, q)
    return _vc(*[a for a, _ in pairs]) if pairs else ca.SX(0, 1)
