"""What a component sees while being compiled: StructureBuilder, then PhysicsBuilder.

Both are thin views of the compiler's workspace for one component; every method documents
its units through the ports it takes (translational: m, m/s, N; rotational: rad, rad/s, N.m).

Network ports (electrical pins: v [V], i [A]; heat ports: T [K], Q_flow [W]) have no motion:
a component reads a port's potential with ``e.potential(port)`` and gives each of its ports'
flows (positive into the component) either explicitly, ``e.flow(port, value)`` (an
inductor's state current, a heat flow source, a sensor's 0), or as an unknown it pins down
with an equation of its own: ``i = e.flow_of(port)`` and ``e.residual(...)`` (a resistor's
v − R·i, a voltage source's p.v − n.v − V). Storage elements declare states with ``s.state``
and give their derivatives (a capacitor's der(v) = i/C; its residual p.v − n.v − v ties the
state to the potentials). Kirchhoff's laws, the structural check and the elimination of
trivial equations are the compiler's (``compiler.networks``). A component may mix domains:
an EMF reads its pins and puts k·i on its mechanical flange with ``e.flow``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import casadi as ca

from ..core.component import Component
from ..errors import StructureError
from ..frames import pose as frame_pose
from ..core.interface import Input, Output
from ..core.ports import MULTIBODY, Domain, PhysicalPort, Port, RealInput, RealOutput
from .charts import FreeFrame
from .kinematics import InternalNode
from .relations import (DeclaredRelation, LinearRelation, PrismaticJoint, RevoluteJoint,
                        RigidTransform, SpatialCompose, SpatialDistance, SpatialPrismatic,
                        SpatialRevolute, SpatialTransform, frame_residual)
from .symbolic import der_with, sx


@dataclass
class StateInfo:
    sym: ca.SX
    start: object            # float, or SX of parameters
    unit: str
    description: str
    owner: Component
    der: ca.SX | None = None
    placeholder: ca.SX | None = None


@dataclass
class ModeInfo:
    """A discrete variable, constant between events: Modelica's Integer or Boolean mode, a
    ``discrete Real`` (``real``, in ``unit``), or a sample trigger (``clock``: its first
    instant and period, expressions of parameters; ``initial``: also true at the start)."""
    sym: ca.SX
    start: float
    values: tuple | None
    description: str
    owner: Component
    update: ca.SX | None = None
    real: bool = False
    unit: str = "1"
    clock: tuple | None = None
    initial: bool = False


@dataclass
class Workspace:
    """Everything components declare, collected for the assembly."""
    t: ca.SX
    smooth: bool = False                                    # components in smooth form
    index_reduction: bool = False                           # of networks' loops, cut sets
    der_table: dict = field(default_factory=dict)
    relations: list = field(default_factory=list)
    internal_nodes: list = field(default_factory=list)
    states: list[StateInfo] = field(default_factory=list)
    algebraics: list[StateInfo] = field(default_factory=list)
    residuals: list = field(default_factory=list)           # (owner, expr)
    signal_sym: dict = field(default_factory=dict)          # RealOutput -> placeholder SX
    signal_expr: dict = field(default_factory=dict)         # RealOutput -> expression
    aliases: list = field(default_factory=list)             # (symbol, what it stands for)
    source: dict = field(default_factory=dict)              # RealInput -> RealOutput
    inputs: list = field(default_factory=list)              # (Input, SX)
    outputs: list = field(default_factory=list)             # (Output, expr)
    kinetic: list = field(default_factory=list)
    bodies: list = field(default_factory=list)              # rigid bodies, packed
    kinetic_other: list = field(default_factory=list)       # kinetic energy not of bodies
    potential: list = field(default_factory=list)
    # explicit flows: (ports, their flows stacked, port by port); a batch of components
    # adds one entry for all its members
    flows: list = field(default_factory=list)
    variables: list = field(default_factory=list)           # (name, expr, unit)
    nominals: dict = field(default_factory=dict)            # name -> nominal (number or SX)
    node_of: dict = field(default_factory=dict)             # port -> Node (after the tree)
    one_d: tuple = ()              # the tree's stacked 1-D node motion (Tree.one_d)
    state_names: dict = field(default_factory=dict)         # port -> its coordinates' names
    declared: dict = field(default_factory=dict)            # (component, name) -> node / state
    cut_flow_sym: dict = field(default_factory=dict)        # port -> placeholder of its flow
    events: list = field(default_factory=list)              # (time, period) of time events
    modes: list[ModeInfo] = field(default_factory=list)
    indicators: list = field(default_factory=list)          # (owner, name, expr, unit, descr.)
    reinits: list = field(default_factory=list)             # (owner, variable, expr, when, dir.)
    initials: list = field(default_factory=list)            # (owner, expr, name) at the start
    terminations: list = field(default_factory=list)        # (owner, condition, text)
    assertions: list = field(default_factory=list)          # (owner, condition, message)
    velocity_constraints: list = field(default_factory=list)  # (owner, name, expr, force)
    state_selects: list = field(default_factory=list)       # (owner, name, expr, rank) kept
    components: list = field(default_factory=list)          # all of them, flattened
    param_symbols: dict = field(default_factory=dict)       # component -> {name: SX}
    param_rows: dict = field(default_factory=dict)          # component -> {name: row of p}
    net_nodes: list = field(default_factory=list)           # networks.NetNode
    net_node_of: dict = field(default_factory=dict)         # network port -> NetNode
    net_flows: list = field(default_factory=list)           # (network port, explicit flow)
    net_flow_sym: dict = field(default_factory=dict)        # network port -> unknown flow
    demoted_states: list = field(default_factory=list)      # StateInfo of reduced loops
    p: object = None                                        # parameter symbols, stacked
    p_default: list = field(default_factory=list)           # their default values

    def signal(self, port: Port) -> ca.SX:
        """The placeholder standing for the value of a signal port."""
        src = self.source.get(port, port) if isinstance(port, RealInput) else port
        if src not in self.signal_sym:
            if isinstance(src, RealInput):       # unconnected, optional input (not the model's)
                raise StructureError(f"input '{port.path}' is not connected to any output")
            s = ca.SX.sym(f"sig:{src.path}")
            self.signal_sym[src] = s
            self.der_table[s.name()] = _lazy_signal_rate(self, s)
        return self.signal_sym[src]

    def model_input(self, record, port: Port | None = None) -> ca.SX:
        """A new input of the compiled model (``record``: its path, unit, description,
        start), of unknown rate; ``port``: the model's own input connector it drives."""
        u = ca.SX.sym(record.path)
        self.der_table[u.name()] = None
        self.inputs.append((record, u))
        if port is not None:
            s = ca.SX.sym(f"sig:{port.path}")
            self.signal_sym[port], self.signal_expr[port] = s, u
            self.der_table[s.name()] = _lazy_signal_rate(self, s)
        return u


#: Modelica's stateSelect values of the variables a reinit keeps, by rank (first kept first)
KEPT = {"always": 0, "prefer": 1}


def _lazy_signal_rate(ws: Workspace, s: ca.SX) -> ca.SX:
    """A placeholder for ds/dt, resolved once the signal's expression is known."""
    d = ca.SX.sym(f"der({s.name()})")
    ws.der_table[d.name()] = _lazy_signal_rate(ws, d) if s.name().count("der(") < 2 else None
    return d


def _start(value):
    """A start value: a number, or an SX expression of parameters (evaluated at simulation)."""
    return value if isinstance(value, ca.SX) else float(value)


class _Base:
    def __init__(self, ws: Workspace, owner: Component):
        self._ws, self._owner = ws, owner

    @property
    def smooth(self) -> bool:
        """Whether the model is compiled in smooth form (``compile(model, smooth=True)``, what
        gradient-based optimal control needs): a component with events or modes then
        declares none and writes its nonsmooth law as a regularization with a named
        parameter (e.g. friction tau0·tanh(w/w_smooth)), documenting its error against the
        exact form."""
        return self._ws.smooth

    @property
    def time(self) -> ca.SX:
        """Simulation time t [s]."""
        return self._ws.t

    def der(self, expr) -> ca.SX:
        """Total time derivative of an expression of the motion, states and time."""
        return der_with(expr, self._ws.der_table)

    def input(self, port: RealInput) -> ca.SX:
        """The value of a signal input (or output) port."""
        self._mine(port)
        return self._ws.signal(port)

    def _mine(self, port: Port):
        if port.owner is not self._owner:
            raise StructureError(f"{self._owner.path}: port '{port.path}' belongs to another "
                                 f"component")

    def _name(self, name: str) -> str:
        return f"{self._owner.path}.{name}" if self._owner.path else name


class StructureBuilder(_Base):
    """Phase 1: kinematic relations, internal nodes, states, algebraic variables."""

    def with_rates(self, name: str, value, *rates) -> ca.SX:
        """``value`` whose time derivatives are the given ``rates`` (first, second, ...)
        rather than derived from it: Modelica's function with a derivative annotation, by
        which MSL's Move and the FMU adaptors prescribe a motion from a position, speed and
        acceleration given as separate signals (model inputs, whose rates are unknown, or
        deliberately inconsistent ones). Returns a symbol ``given:<component>.<name>``
        standing for ``value`` (``value`` itself without rates); the derivative of the last rate is
        derived from it as usual."""
        if not rates:
            return sx(value)
        chain = [ca.SX.sym(f"given:{self._name(name)}" + (f":der{k}" if k else ""))
                 for k in range(len(rates))]
        for k, (sym, stands_for) in enumerate(zip(chain, (value,) + rates)):
            self._ws.aliases.append((sym, sx(stands_for)))
            self._ws.der_table[sym.name()] = chain[k + 1] if k + 1 < len(chain) \
                else sx(rates[-1])
        return chain[0]

    def linear(self, coeffs: dict, rhs=0.0, name: str = "") -> None:
        """Declare Σ coeff·pos(port) = rhs between 1-D ports (or internal nodes).

        Coefficients may depend on parameters; ``rhs`` also on time, states and signals
        (prescribed motion); ``rhs`` given as a pair (number a, expression b) is a·b, kept
        as a product of the relation's linear form (cheaper to compile than the SX a·b).
        The flow at each port is coeff·λ, λ the reaction.
        """
        for p in coeffs:
            self._mine(p)
        self._ws.relations.append(LinearRelation(self._owner, list(coeffs), list(coeffs.values()),
                                                 rhs, name or f"{self._owner.path}"))

    def transform(self, frame_a, frame_b, r=(0.0, 0.0), phi=0.0, name: str = "", *,
                  T=None) -> None:
        """Frames rigidly joined: frame_b = frame_a translated by r [m] (resolved in frame_a)
        and rotated, by phi [rad] for planar frames, by the 3×3 matrix ``T`` for 3-D frames
        (MSL's R_rel.T: v_b = T·v_a; default the identity; r then has 3 elements). With
        frame_a None, frame_b is fixed in the world at position r and that rotation."""
        for p in (frame_a, frame_b):
            if p is not None:
                self._mine(p)
        if frame_b.domain is MULTIBODY:
            T = ca.SX.eye(3) if T is None else sx(T)
            rel = SpatialTransform(self._owner, frame_a, frame_b, r, T, name)
        else:
            rel = RigidTransform(self._owner, frame_a, frame_b, r, phi, name)
        self._ws.relations.append(rel)

    def revolute(self, frame_a, frame_b, angle, name: str = "", *, n=None) -> None:
        """frame_b = frame_a rotated by the 1-D node ``angle`` [rad] about their common
        origin; for 3-D frames about the unit axis ``n`` (resolved in frame_a)."""
        for p in (frame_a, frame_b, angle):
            self._mine(p)
        if frame_b.domain is MULTIBODY:
            rel = SpatialRevolute(self._owner, frame_a, frame_b, angle, n, name)
        else:
            rel = RevoluteJoint(self._owner, frame_a, frame_b, angle, name)
        self._ws.relations.append(rel)

    def prismatic(self, frame_a, frame_b, s, e=(1.0, 0.0), name: str = "") -> None:
        """frame_b = frame_a translated by s·e: ``s`` a 1-D node [m], ``e`` a unit axis
        resolved in frame_a (3 elements for 3-D frames); no relative rotation."""
        for p in (frame_a, frame_b, s):
            self._mine(p)
        cls = SpatialPrismatic if frame_b.domain is MULTIBODY else PrismaticJoint
        self._ws.relations.append(cls(self._owner, frame_a, frame_b, s, e, name))

    def pose(self, frame, coordinates: list, fn, params=(), name: str = "") -> None:
        """The 3-D ``frame`` placed by the 1-D nodes ``coordinates`` (e.g. a wheel's x, y,
        angles): r_0 [m], R.T = ``fn``(coordinate symbols, ``params``), a function of
        CasADi scalars; a ``relation`` that fires like a joint (the frame from its
        coordinates), its twist and reactions by AD."""
        n = len(coordinates)

        def place(vals, par):
            r, T = fn([vals[i] for i in range(1, n + 1)], par)
            return frame_pose(r, T), None

        self.relation([frame, *coordinates], list(params), solve={0: place},
                      name=name or fn.__name__)

    def distance(self, frame_a, frame_b, node, name: str = "") -> None:
        """The 1-D (translational) ``node`` at the distance [m] between the origins of the
        3-D frames frame_a and frame_b; a force on it acts along the line between them."""
        for p in (frame_a, frame_b, node):
            self._mine(p)
        self._ws.relations.append(SpatialDistance(self._owner, frame_a, frame_b, node, name))

    def relation(self, ports: list, params: list, *, solve: dict | None = None,
                 residual=None, rows=(), extra_rows=(), name: str) -> None:
        """A kinematic relation among ``ports`` (frames, 1-D internal nodes) written by the
        component, for joints that close loops (MSL's SphericalSpherical,
        UniversalSpherical, RevolutePlanarLoopConstraint, the Joints.Assemblies).

        ``solve``: {j: f(vals, par) -> (pos_j, extra)}: node j's position from the others'
        (``vals``: index -> position; a 3-D frame's ``acausal.frames.pose``), and extra
        constraint rows (or None) the others must meet, analytic loop closure. ``residual
        (vals, par)``: the constraint rows when every node is known already (the relation
        closes a loop), or None. ``par``: local symbols of ``params`` (the component's
        parameters or expressions of them, in order); ``rows`` / ``extra_rows`` name the
        rows. Velocities, accelerations and the flows (cut forces and torques, by virtual
        work from the multipliers) are derived by the compiler; the callables are traced
        once per component class and ``name`` (they may use nothing but their arguments).
        ``frame_residual(expected, actual)`` gives the 6 rows of two coinciding 3-D
        frames."""
        for p in ports:
            self._mine(p)
        self._ws.relations.append(DeclaredRelation(self._owner, ports, params, solve, residual,
                                                   rows, extra_rows, name))

    frame_residual = staticmethod(frame_residual)

    def states(self, port: PhysicalPort, positions: tuple, velocities: tuple) -> None:
        """Name the coordinates a port gets if its connection group needs free coordinates
        (a Body not connected to the ground: ``r[1], r[2], phi`` and ``v[1], v[2], w``); such
        ports are preferred when choosing free coordinates."""
        self._mine(port)
        self._ws.state_names[port] = (tuple(positions), tuple(velocities))

    def compose(self, frame_a, frame_b, rel) -> None:
        """frame_b = frame_a followed by the relative pose of the 3-D node ``rel`` (an
        internal node with ``free_frame`` states: FreeMotion, Spherical)."""
        for p in (frame_a, frame_b, rel):
            self._mine(p)
        self._ws.relations.append(SpatialCompose(self._owner, frame_a, frame_b, rel))

    def free_frame(self, frame, *, r=("r[1]", "r[2]", "r[3]"), v=("v[1]", "v[2]", "v[3]"),
                   Q=("Q[1]", "Q[2]", "Q[3]", "Q[4]"), w=("w[1]", "w[2]", "w[3]"),
                   translation: bool = True, rotation: bool = True,
                   start: dict | None = None, angles: tuple = (), angle_rates: tuple = (),
                   sequence=(1, 2, 3)) -> None:
        """Name the states a 3-D ``frame`` (a port or internal node) gets if it has no path
        through joints to the world (``compiler.charts``): position r [m] and its rate v
        (unless ``translation`` is False: a rotation only), quaternion Q and angular
        velocity w [rad/s] resolved in the frame (unless ``rotation`` is False: a point
        mass, the frame keeps the world's orientation); ``start`` their start values by
        'r', 'v', 'Q', 'w' (numbers or expressions of parameters). Such frames are
        preferred when choosing free coordinates. ``angles`` / ``angle_rates``: the names of
        the three angles [rad] about the axes ``sequence`` (numbers or parameters) the
        component records for the orientation, and of their rates [rad/s]: values given
        for them by name (x0, guess) set Q and w (``charts.AngleStart``)."""
        self._mine(frame)
        self._ws.state_names[frame] = FreeFrame(tuple(r), tuple(v), tuple(Q), tuple(w),
                                                translation, rotation, dict(start or {}),
                                                self._owner.path, tuple(angles),
                                                tuple(angle_rates), sequence)

    def node(self, name: str, domain: Domain, *, velocity: str = "", acceleration: str = "",
             preferred: bool = True) -> InternalNode:
        """An internal point (e.g. a centre of mass) named ``name``; its velocity and
        acceleration are recorded as ``velocity`` / ``acceleration`` when given. A preferred
        node becomes the coordinate of its rigid cluster when it needs one."""
        n = InternalNode(domain, velocity, acceleration, preferred)
        n.owner, n.name = self._owner, name
        self._ws.internal_nodes.append(n)
        self._declare(name, n)
        return n

    def _declare(self, name: str, handle) -> None:
        key = (self._owner, name)
        if key in self._ws.declared:
            raise StructureError(f"{type(self._owner).__name__} '{self._owner.path}' declares "
                                 f"'{name}' twice; give each node and state its own name")
        self._ws.declared[key] = handle

    def state(self, name: str, start=0.0, unit: str = "", description: str = "",
              der=None, nominal=None) -> ca.SX:
        """An internal state (a motor current, a controller integral), starting at ``start``
        (a number or an expression of parameters) unless x0 says otherwise. Its derivative is set
        here (required when the state is used in a relation) or later by
        PhysicsBuilder.derivative. ``nominal``: its magnitude (a number or an expression of
        parameters; default 1), the scale of its absolute error control."""
        s = ca.SX.sym(self._name(name))
        info = StateInfo(s, _start(start), unit, description, self._owner)
        self._ws.states.append(info)
        self._declare(name, s)
        if nominal is not None:
            self._ws.nominals[s.name()] = _start(nominal)
        if der is not None:
            info.der = sx(der)
            self._ws.der_table[s.name()] = info.der
        else:
            d = ca.SX.sym(f"der({s.name()})")
            self._ws.der_table[s.name()] = d
            info.placeholder = d
        return s

    def mode(self, name: str, start: int = 0, values=None, description: str = "") -> ca.SX:
        """A discrete variable (Modelica's Integer or Boolean ``mode``; Booleans are 0 / 1),
        starting at ``start``, constant between events: the equations may switch on it
        (``casadi.if_else``). It changes only at events, to the value its
        ``PhysicsBuilder.mode_update`` gives; ``values``: the values it may take (checked),
        e.g. MSL's friction modes (-1, 0, 1): backward, stuck, forward. Compiled, it is
        appended to the parameters (``CompiledModel.mode_params``)."""
        start = int(start)
        if values is not None:
            values = tuple(int(v) for v in values)
            if start not in values:
                raise StructureError(f"{type(self._owner).__name__} '{self._owner.path}': mode "
                                     f"'{name}' starts at {start}, not one of its values "
                                     f"{values}")
        return self._discrete(name, ModeInfo(None, start, values, description, self._owner))

    def discrete(self, name: str, start: float = 0.0, unit: str = "",
                 description: str = "") -> ca.SX:
        """A discrete Real variable (Modelica's ``discrete Real``: a sampled value), starting
        at ``start`` [unit], constant between events; it changes only at events, to the value
        its ``PhysicsBuilder.mode_update`` gives (typically guarded by a ``sample`` trigger,
        Modelica's ``when sample(...) then``). Compiled, it is appended to the parameters
        like a mode (``CompiledModel.mode_params``), not rounded."""
        start = float(start)
        if not math.isfinite(start):
            raise StructureError(f"{type(self._owner).__name__} '{self._owner.path}': discrete "
                                 f"variable '{name}' starts at {start}; give a finite start")
        return self._discrete(name, ModeInfo(None, start, None, description, self._owner,
                                             real=True, unit=unit))

    def sample(self, name: str, start, period, initial: bool = False,
               description: str = "") -> ca.SX:
        """Modelica's ``sample(start, period)``: a Boolean that is true (1) during the event
        iteration at the instants start + k·period [s] (k = 0, 1, ...; both numbers or
        expressions of parameters; period > 0) after the start of a simulation, and false
        (0) everywhere else. The start itself is initialization, where Modelica's
        when-clauses are inactive, even at a sample instant; with ``initial`` the trigger is
        true there too (Modelica's ``when {sample(...), initial()}``). The instants are time
        events. Use it in ``mode_update``s: it stays true
        through every round of the event iteration at its instant, so a chain of sampled
        values (a Sampler feeding a gain feeding a ZeroOrderHold) settles on the values of
        that instant; after it the iteration runs once more with the trigger false. Recorded
        (as 0 everywhere: it is true only within events) under ``name``."""
        start, period = sx(start), sx(period)
        self._ws.events.append((start, period))
        return self._discrete(name, ModeInfo(None, 0, (0, 1), description, self._owner,
                                             clock=(start, period), initial=bool(initial)))

    def _discrete(self, name: str, info: ModeInfo) -> ca.SX:
        info.sym = ca.SX.sym(self._name(name))
        self._ws.modes.append(info)
        self._declare(name, info.sym)
        return info.sym

    def algebraic(self, name: str, start=0.0, unit: str = "",
                  description: str = "") -> ca.SX:
        """An algebraic variable, fixed by a residual equation given in physics."""
        s = ca.SX.sym(self._name(name))
        self._ws.algebraics.append(StateInfo(s, _start(start), unit, description, self._owner))
        self._declare(name, s)
        self._ws.der_table[s.name()] = None
        return s


class PhysicsBuilder(_Base):
    """Phase 2: energies, flows, state derivatives, residuals, outputs, recorded variables."""

    def node(self, name: str) -> InternalNode:
        """The internal node this component declared as ``name`` in structure()."""
        return self._declared(name, "node")

    def state(self, name: str) -> ca.SX:
        """The symbol of the state (or algebraic variable) this component declared as
        ``name`` in structure()."""
        return self._declared(name, "state")

    def mode(self, name: str) -> ca.SX:
        """The symbol of the mode this component declared as ``name`` in structure()."""
        return self._declared(name, "mode")

    def _declared(self, name: str, what: str):
        try:
            return self._ws.declared[(self._owner, name)]
        except KeyError:
            mine = [n for c, n in self._ws.declared if c is self._owner]
            raise StructureError(f"{type(self._owner).__name__} '{self._owner.path}' declared "
                                 f"no {what} '{name}' in structure() (it declared: "
                                 f"{', '.join(mine) or 'none'})") from None

    def _node(self, port: PhysicalPort):
        self._mine(port)
        if port.domain.network:
            raise StructureError(f"{self._owner.path}: port '{port.path}' ({port.domain.name}) "
                                 f"has no motion; read its potential with e.potential")
        return self._ws.node_of[port]

    def _net_port(self, port: PhysicalPort):
        self._mine(port)
        if not port.domain.network:
            raise StructureError(f"{self._owner.path}: port '{port.path}' is mechanical; use "
                                 f"e.pos / e.vel and e.flow")

    def potential(self, port: PhysicalPort) -> ca.SX:
        """The potential of a network port: v [V] of a pin, T [K] of a heat port."""
        self._net_port(port)
        return self._ws.net_node_of[port].potential

    def flow_of(self, port: PhysicalPort) -> ca.SX:
        """The flow through a network port (i [A], Q_flow [W]; positive into the component)
        as an unknown of the DAE: this component gives one equation (``residual``) for it.
        A port's flow is given either this way or by ``flow``, not both."""
        self._net_port(port)
        ws = self._ws
        if port not in ws.net_flow_sym:
            name = f"{port.path}.{port.domain.flows[0]}"
            ws.net_flow_sym[port] = ca.SX.sym(name)
            ws.der_table[name] = None
        return ws.net_flow_sym[port]

    def pos(self, port: PhysicalPort) -> ca.SX:
        """Potential of a port: s [m], phi [rad], (x, y, phi) for a planar frame, (r_0, R.T
        row by row) for a 3-D frame (``acausal.frames.parts`` splits it)."""
        return self._node(port).pos

    def vel(self, port: PhysicalPort) -> ca.SX:
        """Time derivative of the port's potential [m/s, rad/s]; for a 3-D frame its twist
        (v, w) resolved in the frame (v = R.T·der(r_0), w the angular velocity)."""
        return self._node(port).vel

    def acc(self, port: PhysicalPort) -> ca.SX:
        """Time derivative of ``vel`` [m/s², rad/s²]."""
        return self._node(port).acc

    def flow(self, port: PhysicalPort, value) -> None:
        """Set the flow (force [N] or torque [N.m]) acting on this component through
        ``port``, positive into the component (Modelica's sign): the component pushes the
        connection with −value. On a network port: its current [A] or heat flow [W],
        given explicitly."""
        self._mine(port)
        if port.domain.network:
            self._ws.net_flows.append((port, sx(value)))
        else:
            self._ws.flows.append(([port], sx(value)))

    def cut_flow(self, port: PhysicalPort) -> ca.SX:
        """The total flow through one of this component's ports (force [N] / torque [N.m],
        positive into the component), reactions included: what a force or torque sensor
        measures. It may feed outputs, state derivatives and the residuals of algebraic
        variables (a LossyGear's loss depends on flange_a.tau: an implicit equation the DAE
        solver closes), not forces of the model directly."""
        self._mine(port)
        if port.domain.network:
            raise StructureError(f"{self._owner.path}: cut_flow of the {port.domain.name} port "
                                 f"'{port.path}'; read a network port's flow with e.flow_of")
        if port not in self._ws.cut_flow_sym:
            self._ws.cut_flow_sym[port] = ca.SX.sym(f"flow:{port.path}", port.domain.dof)
        return self._ws.cut_flow_sym[port]

    def kinetic_energy(self, T) -> None:
        """Add kinetic energy [J], a function of port velocities and positions."""
        self._ws.kinetic.append(sx(T))
        self._ws.kinetic_other.append(sx(T))

    def rigid_body(self, frame: PhysicalPort, m, I, r_CM=None) -> None:
        """A rigid body fixed to ``frame``: adds its kinetic energy and lets the compiler use
        the O(N) articulated-body recursion for trees (``compiler.recursive``).

        Planar frame: mass m [kg] and inertia I [kg.m²] about the centre of mass, which is
        the frame's origin: ½m|v|² + ½Iω². 3-D frame: mass m [kg] at r_CM [m] (resolved in
        the frame; default its origin), inertia tensor I [kg.m²] (3×3) about the centre of
        mass, parallel to the frame: ½m|v + w×r_CM|² + ½wᵀIw, (v, w) the frame's twist."""
        self._mine(frame)
        n = self._ws.node_of[frame]
        v = n.vel
        if frame.domain is MULTIBODY:
            r_CM = ca.SX.zeros(3) if r_CM is None else sx(r_CM)
            I = sx(I)
            v_cm = v[:3] + ca.cross(v[3:6], r_CM)
            T = 0.5 * m * ca.dot(v_cm, v_cm) + 0.5 * ca.dot(v[3:6], ca.mtimes(I, v[3:6]))
            packed = ca.vertcat(n.pos, v, sx(m), r_CM, ca.vec(I))
        else:
            T = 0.5 * m * ca.sumsqr(v[:2]) + 0.5 * I * v[2] ** 2
            packed = ca.vertcat(n.pos, v, sx(m), sx(I))
        self._ws.kinetic.append(sx(T))
        self._ws.bodies.append(packed)

    def velocity_constraint(self, name: str, expr, unit: str = "N",
                            description: str = "") -> ca.SX:
        """A constraint on velocities, 0 = ``expr`` (linear in the port velocities, not the
        time derivative of a position constraint: a rolling contact's no-slip condition),
        and the unknown force [``unit``] that holds it, returned as a symbol recorded under
        ``name``: the component puts it on its ports with ``flow`` (ideal when its power
        is force·expr). The compiler eliminates one velocity per row (``compiler.
        nonholonomic``) and solves the forces with the accelerations."""
        f = ca.SX.sym(self._name(name))
        self._ws.der_table[f.name()] = None
        self._ws.velocity_constraints.append((self._owner, name, sx(expr), f))
        self._ws.variables.append((self._name(name), f, unit, description))
        return f

    def potential_energy(self, V) -> None:
        """Add potential energy [J] (conservative forces: generalized force −∂V/∂q)."""
        self._ws.potential.append(sx(V))

    def derivative(self, state: ca.SX, expr) -> None:
        """Set the time derivative of an internal state declared in structure()."""
        for info in self._ws.states:
            if info.sym is state:
                break
        else:
            raise StructureError(f"{self._owner.path}: derivative() of a symbol that is not a "
                                 f"state declared in structure()")
        if info.der is not None:
            raise StructureError(f"{self._owner.path}: derivative of '{state.name()}' given twice")
        info.der = sx(expr)

    def time_event(self, time, period=None) -> None:
        """Declare a discontinuity in time at ``time`` [s] (and every ``period`` [s] after it),
        both numbers or expressions of parameters: the integrator is restarted there instead
        of stepping across the jump."""
        self._ws.events.append((sx(time), sx(period) if period is not None else ca.SX(0)))

    def indicator(self, name: str, expr, unit: str = "", description: str = "") -> None:
        """A zero-crossing function ``<component>.<name>`` [unit]: a state event happens
        wherever ``expr`` (of time, motion, states, algebraic variables, inputs, parameters and
        modes) changes sign, in either direction. The simulator locates the crossing in time,
        stops there and runs the event iteration: every ``mode_update`` and the ``reinit`` of
        this indicator. Write it continuous between events (switch it with the modes: an
        indicator that means nothing in a mode may be a constant there)."""
        if any(o is self._owner and n == name for o, n, *_ in self._ws.indicators):
            raise StructureError(f"{type(self._owner).__name__} '{self._owner.path}' declares "
                                 f"indicator '{name}' twice")
        self._ws.indicators.append((self._owner, name, sx(expr), unit, description))

    def mode_update(self, mode: ca.SX, expr) -> None:
        """The value ``mode`` (or a discrete Real variable) takes at every event (state or time
        event): ``expr``, of the motion, states, algebraic variables, inputs, parameters and
        the modes. In ``expr`` the modes are their values before the update (Modelica's
        ``pre(mode)``). At an event all modes are updated together, again and again, until
        none changes (the event iteration, as MSL's friction elements; the algebraic variables
        solved in between). A sampled value changes at its instants only:
        ``if_else(trigger, value, mode)`` with a ``StructureBuilder.sample`` trigger."""
        info = next((m for m in self._ws.modes if m.sym is mode and m.owner is self._owner),
                    None)
        if info is None:
            raise StructureError(f"{self._owner.path}: mode_update() of a symbol that is not a "
                                 f"mode this component declared in structure()")
        if info.update is not None:
            raise StructureError(f"{self._owner.path}: mode_update of '{mode.name()}' given "
                                 f"twice")
        info.update = sx(expr)

    def reinit(self, variable, expr, when: str, direction: int = 0) -> None:
        """Modelica's ``when ... then reinit(variable, expr)``: when this component's
        indicator ``when`` crosses zero in ``direction`` (−1: from positive to negative, 1:
        from negative to positive, 0: either), the state ``variable`` (a state, a variable
        that is one state scaled and offset by parameters: ``e.vel(flange)``, or a velocity
        linear in the generalized velocities, whose jump the states below share) jumps
        to ``expr``, evaluated at the event's left limit (every value in it is its ``pre``),
        in the variable's units.

        What else a reinit of a velocity changes follows Modelica: a reinit changes only the
        reinitialized variable and keeps every other state, where the states are those a
        Modelica tool selects. Here the generalized velocities are the states; the velocities
        other components declare ``stateSelect`` prefer or always (``variable``: MSL's
        relative states v_rel / w_rel of its compliant elements with relative states,
        clutches) are kept first (always before prefer, then in declaration order, each
        where it is independent of the ones before), then the generalized velocities, as
        far as they are independent; the velocities that are no such state follow. E.g. a
        mass stopped by reinit(v, 0) that a SpringDamper (relative states) joins to another
        mass takes that mass along: the spring damper's v_rel is kept (MSL's
        Translational HeatLosses). The compiler writes this as reinits of the velocities
        that follow (``CompiledModel.state_events.reinits``, logged with the event);
        simultaneous reinits that move the same velocity are applied one after the other,
        each from the left limit."""
        if direction not in (-1, 0, 1):
            raise StructureError(f"{self._owner.path}: reinit direction must be -1, 0 or 1, "
                                 f"got {direction!r}")
        self._ws.reinits.append((self._owner, sx(variable), sx(expr), when, direction))

    def residual(self, expr) -> None:
        """Add an equation expr = 0 (for algebraic variables)."""
        self._ws.residuals.append((self._owner, sx(expr)))

    def initial(self, expr, name: str = "") -> None:
        """Modelica's ``initial equation expr = 0``: an equation held at the start of a
        simulation only, next to the values given in x0 (it must not contradict them), the
        states otherwise closest to their start values (``simulation.initialization``).
        ``expr`` may use time, the motion (``pos``/``vel``/``acc`` of ports), states,
        algebraic variables, inputs, parameters and derivatives: ``e.der(state)`` (so
        ``e.initial(e.der(C_v))`` starts a capacitor in steady state). A model writes its
        initial equations over its parts with ``part`` (MSL's RobotR3 motor: der(C.v) = 0,
        der(La.i) = 0). Solved with the modes at their start values, before the event
        iteration at the start; ``name`` labels it in errors (``<component>: <name>``).
        A simulation's start, an optimal control problem's first node and a native FMU's
        initialization hold them (not the operating points of the analyses)."""
        self._ws.initials.append((self._owner, sx(expr), name or "initial equation"))

    def terminate(self, condition, text: str) -> None:
        """Modelica's ``when condition then terminate(text)``: the simulation ends at the
        first event (state or time event, not the start) after which the Boolean
        ``condition`` (of time, motion, states, inputs, parameters and modes) is true; the
        Result says so (``Result.terminated``). The condition changes at events only when
        it is built from modes and time-evented signals (a relation block's output, a
        time event of this component at the instant it becomes true)."""
        self._ws.terminations.append((self._owner, sx(condition), str(text)))

    def assertion(self, condition, message: str) -> None:
        """Modelica's ``assert(condition, message)``: the Boolean ``condition`` (of time,
        motion, states, algebraic variables, inputs, parameters and modes) must hold;
        simulate() raises a SimulationError naming this component, ``message`` and the
        first time where it fails, checked at every point of the Result (output times and
        both sides of events), so a violation that begins and ends between two of them
        passes unseen. It adds no event (the model keeps its solvers and code generation);
        a sweep reports the run failed, the Stepper raises after the step, an FMU returns
        an error status with the message (native: checked after initialization, events and
        every integrator step; pythonfmu: after initialization and every doStep). A condition that is true by construction (constant) is not
        kept."""
        condition = sx(condition)
        if not (condition.is_constant() and float(condition) != 0):
            self._ws.assertions.append((self._owner, condition, str(message)))

    def part(self, component: Component) -> "PhysicsBuilder":
        """A builder for reading the variables of ``component``, a part of this one (a
        model's parts, at any depth): its ports' motion and potentials, its states, its
        inputs, in this component's equations (a model's ``initial`` equations)."""
        c = component
        while c is not None and c is not self._owner:
            c = c.owner
        if c is None or component is self._owner:
            raise StructureError(f"{self._owner.path or type(self._owner).__name__}: "
                                 f"part({getattr(component, 'path', component)!r}) is not a "
                                 f"part of it")
        return PhysicsBuilder(self._ws, component)

    def output(self, port: RealOutput, expr) -> None:
        """Set the value of a signal output."""
        self._mine(port)
        self._ws.signal(port)
        self._ws.signal_expr[port] = sx(expr)

    def variable(self, name: str, expr, unit: str = "", description: str = "",
                 nominal=None, stateSelect=None) -> None:
        """Record ``expr`` as ``<component>.<name>`` in results. ``nominal``: its magnitude (a
        number or an expression of parameters), Modelica's ``nominal`` attribute: the scale
        of the error control of the state it is (``CompiledModel.nominal``).
        ``stateSelect``: Modelica's attribute (a ``StateSelect``); a velocity (an expression
        linear in the generalized velocities) declared ``prefer`` or ``always`` is one a
        Modelica tool keeps as a state, and so keeps its value at another component's
        reinit (see ``reinit``)."""
        self._ws.variables.append((self._name(name), sx(expr), unit, description))
        if nominal is not None:
            self._ws.nominals[self._name(name)] = _start(nominal)
        rank = KEPT.get(getattr(stateSelect, "value", stateSelect))
        if rank is not None:
            self._ws.state_selects.append((self._owner, self._name(name), sx(expr), rank))

    def outer(self, cls) -> Component:
        """The one component of class ``cls`` in the model (Modelica's inner/outer), e.g. the
        planar World whose gravity every Body uses; while compiling, its parameters read as
        symbols."""
        found = [c for c in self._ws.components if isinstance(c, cls)]
        if len(found) != 1:
            raise StructureError(
                f"{type(self._owner).__name__} '{self._owner.path}' needs exactly one "
                f"{cls.__name__} in the model, found {len(found)}"
                f"{': ' + ', '.join(c.path for c in found) if found else ''}; "
                f"{'add one' if not found else 'keep one'}")
        return found[0]

    def model_input(self, comp: Input) -> ca.SX:
        return self._ws.model_input(comp)

    def model_output(self, comp: Output, expr) -> None:
        self._ws.outputs.append((comp, sx(expr)))
