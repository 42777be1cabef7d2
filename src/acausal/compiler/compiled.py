"""CompiledModel: the seam between the compiler and everything downstream.

It holds, by name, the states, algebraic variables, parameters (with defaults), inputs and
outputs, as ``ScalarVariable`` records, and the CasADi objects: the semi-explicit DAE

    ẋ = ode(t, x, z, u, p),   0 = alg(t, x, z, u, p)

as a dict for ``casadi.integrator``, Functions for the right-hand side, the outputs and the
recorded variables, and the pieces of Lagrange's equations (``lagrange``): M(q), C, K,
gravity, Coriolis, input matrix, Φ(q) for loops.

Every Function of the seam takes its arguments in one order, **(t, x, z, u, p)**: time,
states, algebraic variables, inputs, parameters (``function`` builds more of them).

Discrete modes (``StructureBuilder.mode``: Integer / Boolean variables constant between
events; ``discrete``: discrete Real variables; ``sample``: sample triggers) are appended to
the parameters: p = [parameters of the components; loop switches;
modes d], ``mode_params`` their positions in p, so every Function sees the modes as
parameters and the argument order stays. ``state_events`` holds the zero-crossing
indicators, the modes' updates and the reinits, as expressions in (t, x, z, u, p);
``indicator_function`` and ``event_update_function`` are their Functions.
Names are resolved here once (``variable``, ``expression``): simulation, analysis, ocp and
fmu ask the seam what a name is.

The compiler builds this record and imports nothing downstream; what users call on it —
``simulate``, ``export_fmu``, ``mobility`` — comes from the facade above every layer
(``acausal.facade``), which wraps this record.
"""
from __future__ import annotations

from dataclasses import dataclass, field, fields

import casadi as ca
import numpy as np

from ..core.parameter import checked_value
from ..errors import ParameterError, SimulationError, VariableNameError, did_you_mean
from ..numerics import event_times
from .lagrange import Lagrange
from .loops import Mobility, mobility
from .symbolic import gc_paused

ARGS = ("t", "x", "z", "u", "p")        # the argument order of every Function of the seam


@dataclass(frozen=True, slots=True)          # slots: one per parameter, many of them
class ScalarVariable:
    """One scalar of a compiled model: a parameter, input, output, state or algebraic
    variable. ``start`` is a parameter's default or an input's start value (None where
    the model computes it); ``min`` / ``max`` its bounds (a parameter declared positive or
    nonnegative has min = 0); ``nominal`` a state's or algebraic variable's magnitude at the
    default parameters (``CompiledModel.nominal``; None for the others); ``declaration``
    the ``Parameter`` whose rule checks a parameter's values."""
    name: str
    unit: str = ""
    description: str = ""
    start: float | None = None
    min: float = -np.inf
    max: float = np.inf
    nominal: float | None = None
    declaration: object = field(default=None, compare=False, repr=False)
    component: str = ""      # the owning component's path (modes, indicators)

    def check(self, value) -> float:
        """A parameter value as float, checked by its declaration's rule (ParameterError
        naming this parameter otherwise)."""
        return checked_value(self.name, value, self.declaration.rule, self.description,
                             self.unit)


@dataclass(frozen=True)
class Resolved:
    """What a name stands for in a compiled model: ``kind`` (time / state / algebraic /
    input / parameter / recorded), ``index`` in x, z, u, p (recorded variables: in
    ``recorded_names``; time: None), ``expression`` in (t, x, z, u, p), ``unit``."""
    name: str
    kind: str
    index: int | None
    expression: ca.SX
    unit: str


@dataclass(frozen=True)
class Reinit:
    """``when`` indicator ``indicator`` crosses zero in ``direction`` (−1 falling, 1 rising,
    0 either): state ``state`` (its index in x) jumps to ``value`` (in (t, x, z, u, p), at the
    event's left limit)."""
    state: int
    indicator: int
    direction: int
    value: ca.SX


@dataclass
class StateEvents:
    """What happens at state events: the indicators (records named
    ``<component>.<indicator>``, ``component`` their owner) and their expressions
    ``indicator``; the new value of every mode (``mode_update``, in mode order: the mode
    itself where the component gives no update); the reinits and their values stacked
    (``reinit_values``); ``mode_values``: the values each mode may take, by name (modes
    declared with ``values``); ``real_modes``: the names of the discrete Real variables
    (sampled values, never rounded); ``clocks``: positions among the modes of the sample
    triggers (``StructureBuilder.sample``), ``clock_times`` the Function p -> (first
    instants, periods) of them, ``clock_initial`` whether each is true at the start too;
    ``terminate``: the Boolean conditions that end the simulation at an event
    (``PhysicsBuilder.terminate``), ``terminations`` their (component, text)."""
    indicators: list = field(default_factory=list)
    indicator: ca.SX = field(default_factory=lambda: ca.SX(0, 1))
    mode_update: ca.SX = field(default_factory=lambda: ca.SX(0, 1))
    reinits: list = field(default_factory=list)
    reinit_values: ca.SX = field(default_factory=lambda: ca.SX(0, 1))
    mode_values: dict = field(default_factory=dict)
    real_modes: tuple = ()
    clocks: list = field(default_factory=list)
    clock_initial: list = field(default_factory=list)
    clock_times: ca.Function | None = None
    terminate: ca.SX = field(default_factory=lambda: ca.SX(0, 1))
    terminations: list = field(default_factory=list)


@dataclass
class CompiledModel:
    """A model compiled into CasADi symbols and expressions (see the module docstring):
    symbols t, x, z, p, u; the DAE ``ode``, ``alg``; outputs ``y``; the variables as
    ``ScalarVariable`` records; Functions of parameters for start values, nominals and time
    events; the recorded variables (built on first use); ``lagrange``.

    ``loop_switches``: positions in p of the switches of the loop rows (row order): 1
    enforces row i of Φ, 0 drops it (redundant); simulate() and the FMUs set them at the
    assembled initial configuration (``mobility_at``). ``loop_mu`` / ``loop_nu``: positions
    in z of the multipliers of the stabilized index-2 form that hold Φ = 0 and Φ̇ = 0 (zero
    on the exact solution). ``fixed_params``: parameters fixed at 0 when compiled (a
    component built with a ``structural_zero`` parameter at 0, e.g. a massless Mass), not
    parameters of this model. ``mode_params``: positions in p of the discrete modes (last in
    p; their records in ``params`` hold their start values, ``component`` their owner).
    ``state_events``: indicators, mode updates and reinits (see ``StateEvents``).
    ``initial_equations``: the components' initial equations (= 0 at the start, in (t, x,
    z, u, p); ``PhysicsBuilder.initial``), ``initial_labels`` one label each.
    ``assertions``: the components' conditions that must hold (1 = true, in (t, x, z, u,
    p); ``PhysicsBuilder.assertion``), ``assertion_texts`` their (component, message).
    ``smooth``: compiled in smooth form (``compile(model, smooth=True)``);
    ``index_reduction``: networks' loops and cut sets reduced (``compile(model,
    index_reduction=True)``, kept by ``recompile``). ``angle_starts``: the free rotations
    whose angles (and rates) given by name set their quaternion (and angular velocity)
    states (``charts.AngleStart``). ``source``: the
    Model compiled (a reference, nothing of it copied: ``recompile`` compiles it as it is
    then)."""
    name: str
    t: ca.SX
    x: ca.SX
    z: ca.SX
    p: ca.SX
    u: ca.SX
    ode: ca.SX
    alg: ca.SX
    y: ca.SX
    states: list[ScalarVariable]
    algebraics: list[ScalarVariable]
    params: list[ScalarVariable]
    inputs: list[ScalarVariable]
    outputs: list[ScalarVariable]
    start: ca.Function      # p -> start values of [x; z]
    nominal: ca.Function    # p -> nominals of [x; z] (see ``nominals``)
    events: ca.Function     # p -> (times, periods) of time events
    recorder: object        # () -> (names, expressions, units) of every recorded variable,
    #                         and {name: error} of those that cannot be computed
    lagrange: Lagrange
    coordinates: list[str]
    method: str = ""        # how accelerations are solved: diagonal / recursion / dense / KKT
    loop_rows: list[str] = field(default_factory=list)          # names of the rows of Φ
    loop_rows_dropped: list[str] = field(default_factory=list)  # constant, redundant rows
    loop_switches: list[int] = field(default_factory=list)
    loop_mu: list[int] = field(default_factory=list)
    loop_nu: list[int] = field(default_factory=list)
    fixed_params: list[str] = field(default_factory=list)
    mode_params: list[int] = field(default_factory=list)
    state_events: StateEvents = field(default_factory=StateEvents)
    initial_equations: ca.SX = field(default_factory=lambda: ca.SX(0, 1))
    initial_labels: list[str] = field(default_factory=list)
    assertions: ca.SX = field(default_factory=lambda: ca.SX(0, 1))
    assertion_texts: list = field(default_factory=list)
    smooth: bool = False    # compiled in smooth form (no events; see PhysicsBuilder.smooth)
    index_reduction: bool = False   # networks' loops and cut sets reduced (compiler.networks)
    angle_starts: list = field(default_factory=list)    # charts.AngleStart of free rotations
    source: object = field(default=None, repr=False, compare=False)     # the Model compiled
    _cache: dict = field(default_factory=dict, repr=False)

    @classmethod
    def wrap(cls, record: "CompiledModel") -> "CompiledModel":
        """A record of this class with the fields of ``record`` (sharing its symbols and
        caches): how a subclass (the facade's) dresses the compiler's record."""
        return cls(**{f.name: getattr(record, f.name) for f in fields(record)})

    # ---- names ----------------------------------------------------------------------------
    @property
    def x_names(self) -> list[str]:
        return [v.name for v in self.states]

    @property
    def z_names(self) -> list[str]:
        return [v.name for v in self.algebraics]

    @property
    def param_names(self) -> list[str]:
        return [v.name for v in self.params]

    @property
    def param_defaults(self) -> dict[str, float]:
        return {v.name: v.start for v in self.params}

    @property
    def input_names(self) -> list[str]:
        return [v.name for v in self.inputs]

    @property
    def input_start(self) -> np.ndarray:
        """The inputs' start values, in input order."""
        return np.array([v.start for v in self.inputs], dtype=float)

    @property
    def output_names(self) -> list[str]:
        return [v.name for v in self.outputs]

    @property
    def has_loops(self) -> bool:
        """Whether closed kinematic loops add constraints Φ(q, t) = 0 (a DAE with
        multipliers)."""
        return bool(self.loop_rows)

    @property
    def position_states(self) -> list[int]:
        """Positions in x of the generalized coordinates (the states that are positions or
        angles, not rates or internal states)."""
        index = self._index("states")
        return [index[n] for n in self.lagrange.q_names if n in index]

    @property
    def modes(self) -> list[ScalarVariable]:
        """The discrete modes, in the order of ``mode_params`` (their start values: ``start``)."""
        return [self.params[i] for i in self.mode_params]

    @property
    def has_events(self) -> bool:
        """Whether the model has state events (indicators), modes to update or conditions
        that end the simulation."""
        return bool(self.state_events.indicators or self.mode_params
                    or self.state_events.terminations)

    @property
    def indicator_function(self) -> ca.Function:
        """Function (t, x, z, u, p) -> g, the indicators (``state_events.indicators``)."""
        if "g" not in self._cache:
            self._cache["g"] = self.function("indicators", [self.state_events.indicator], ["g"])
        return self._cache["g"]

    @property
    def event_update_function(self) -> ca.Function:
        """Function (t, x, z, u, p) -> (modes, reinit): the modes' new values given their
        present ones in p, and the value of every reinit (``state_events.reinits``)."""
        if "update" not in self._cache:
            ev = self.state_events
            self._cache["update"] = self.function("event_update",
                                                  [ev.mode_update, ev.reinit_values],
                                                  ["modes", "reinit"])
        return self._cache["update"]

    @property
    def loop_multipliers(self) -> list[int]:
        """Positions in z of every loop multiplier (μ then ν)."""
        return self.loop_mu + self.loop_nu

    def param_vector(self, overrides: dict | None = None) -> np.ndarray:
        """Parameter values [defaults with ``overrides`` by dotted name], checked; a vector
        parameter by its name takes all its elements (``{"table.table": values}``, an array
        flattened row by row, for ``table[1]``, ``table[2]``, ...)."""
        values = self.param_defaults
        index = self._index("params")
        for name, v in _elements(overrides or {}, index).items():
            if name in self.fixed_params:
                raise ParameterError(
                    f"parameter '{name}' of model '{self.name}' was fixed at 0 when it was "
                    f"compiled: its component was built with 0, which changes the equations "
                    f"(a massless part); build it with a value > 0 and compile again")
            if name not in index:
                raise ParameterError(f"model '{self.name}' has no parameter '{name}'"
                                     f"{did_you_mean(name, values)}")
            values[name] = self.params[index[name]].check(v)
        return np.array(list(values.values()), dtype=float)

    def event_times(self, p: np.ndarray, t0: float, t1: float) -> list[float]:
        """Times of the declared time events strictly inside (t0, t1), sorted."""
        return event_times(*self.events(p), t0, t1)

    def nominals(self, p: np.ndarray, overrides: dict | None = None) -> np.ndarray:
        """The nominal magnitude of every state and algebraic variable ([x; z]) at
        parameters p: the scale of the integrator's absolute error control, atol·nominal_i
        (Modelica's ``nominal``; 1 unless declared).

        A variable declared with a nominal n (``e.variable(..., nominal=)``,
        ``s.state(..., nominal=)``, a component's ``nominal={...}``) gives it to the state
        or algebraic variable w_k it coincides with: when the variable is a·w_k + b, a and b
        depending on parameters only (``coinciding``), w_k gets n/|a| — a compliant
        element's phi_rel is its housing's angle when the other flange is fixed; several
        such variables on one w_k: the smallest. A variable that is no such function of one
        state (a spring between two moving inertias: phi_rel = phi_2 − phi_1) leaves the
        states' nominals as they are. ``overrides`` (name -> value, simulate's ``nominal``)
        replace the nominal of the state the named variable is or coincides with; a name
        that coincides with none is an error."""
        n = np.array(self.nominal(p), dtype=float).ravel()
        w = ca.vertcat(self.x, self.z)
        for name, value in (overrides or {}).items():
            hit = coinciding(self.expression(name), w, self._free())
            try:
                value = float(value)
            except (TypeError, ValueError):
                value = float("nan")
            if not 0 < value < np.inf:
                raise SimulationError(f"nominal['{name}'] must be a finite number > 0, got "
                                      f"{value!r}")
            if hit is None:
                raise SimulationError(
                    f"nominal: '{name}' is not a state of '{self.name}' nor one state "
                    f"scaled and offset by parameters, so no state takes its nominal; give "
                    f"the nominal of a state ({', '.join(self.x_names[:6])}...)")
            k, a = hit
            scale = abs(float(ca.Function("a", [self.p], [a])(p)))
            n[k] = value / scale
        bad = [f"{name} = {v:g}" for name, v in zip(self.x_names + self.z_names, n)
               if not 0 < v < np.inf]
        if bad:
            raise SimulationError(f"nominals must be finite numbers > 0; at these parameters "
                                  f"{', '.join(bad[:4])}: check the parameters that set them "
                                  f"(e.g. phi_nominal, s_nominal)")
        return n

    def _free(self) -> ca.SX:
        """The symbols that are not parameters: t, x, z, u."""
        return ca.vertcat(self.t, self.x, self.z, self.u)

    # ---- name resolution -------------------------------------------------------------------
    def _index(self, kind: str) -> dict[str, int]:
        key = f"index:{kind}"
        if key not in self._cache:
            self._cache[key] = {v.name: i for i, v in enumerate(getattr(self, kind))}
        return self._cache[key]

    _KINDS = (("state", "states", "x"), ("algebraic", "algebraics", "z"),
              ("input", "inputs", "u"), ("parameter", "params", "p"))

    def locate(self, name: str) -> tuple[str, int | None]:
        """(kind, index) of ``name`` — see ``variable`` — without building its expression:
        states, algebraics, inputs and parameters cost a dictionary look-up."""
        if not isinstance(name, str):
            raise VariableNameError(f"variables of model '{self.name}' are named by text "
                                    f"(e.g. '{self.x_names[0] if self.x_names else 'time'}'), "
                                    f"got {name!r}")
        if name in ("time", "t"):
            return "time", None
        for kind, attr, _ in self._KINDS:
            i = self._index(attr).get(name)
            if i is not None:
                return kind, i
        i = self._recorded_index().get(name)
        if i is None and name in self._recorded()[3]:
            error = self._recorded()[3][name]          # a rate nobody knows: why it is missing
            raise type(error)(f"'{name}': {error}")
        if i is None:
            raise VariableNameError(
                f"no variable '{name}' in model '{self.name}'"
                f"{did_you_mean(name, self.recorded_names + self.param_names)}")
        return "recorded", i

    def variable(self, name: str) -> Resolved:
        """What ``name`` is: time ('time'), a state, an algebraic variable, an input, a
        parameter, or any other recorded variable (a port's potential or flow, a sensor
        signal, a component's variable). VariableNameError, with the closest names,
        otherwise."""
        kind, i = self.locate(name)
        if kind == "time":
            return Resolved(name, kind, None, self.t, "s")
        if kind == "recorded":
            return Resolved(name, kind, i, self.recorded[i], self.recorded_units[i])
        attr, sym = next((a, getattr(self, s)) for k, a, s in self._KINDS if k == kind)
        return Resolved(name, kind, i, sym[i], getattr(self, attr)[i].unit)

    def expression(self, name: str) -> ca.SX:
        """The symbolic expression of any variable by name, in (t, x, z, u, p)."""
        return self.variable(name).expression

    def function(self, name: str, outputs: list, output_names=None) -> ca.Function:
        """A casadi Function (t, x, z, u, p) -> ``outputs`` (expressions in the model's
        symbols), the argument order of every Function of the seam."""
        names = list(output_names) if output_names is not None else \
            [f"o{i}" for i in range(len(outputs))]
        return ca.Function(name, [self.t, self.x, self.z, self.u, self.p], list(outputs),
                           list(ARGS), names)

    # ---- recorded variables (built on first use) -------------------------------------------
    def _recorded(self):
        if "recorded" not in self._cache:
            with gc_paused():           # millions of small objects, no cycles
                self._cache["recorded"] = self.recorder()
        return self._cache["recorded"]

    def _recorded_index(self) -> dict[str, int]:
        if "index:recorded" not in self._cache:
            self._cache["index:recorded"] = {n: i for i, n in enumerate(self.recorded_names)}
        return self._cache["index:recorded"]

    @property
    def recorded_names(self) -> list[str]:
        """Dotted names of every variable a Result holds."""
        return self._recorded()[0]

    @property
    def recorded(self) -> ca.SX:
        """Expressions (in t, x, z, u, p) of the recorded variables, stacked."""
        return self._recorded()[1]

    @property
    def recorded_units(self) -> list[str]:
        return self._recorded()[2]

    # ---- CasADi objects ---------------------------------------------------------------------
    @property
    def dae(self) -> dict:
        """The DAE as a dict for ``casadi.integrator``: x, z, p = [inputs; parameters] (the
        seam's order: u before p), t, ode, alg."""
        d = {"x": self.x, "p": ca.vertcat(self.u, self.p), "t": self.t, "ode": self.ode}
        if self.z.numel():
            d.update(z=self.z, alg=self.alg)
        return d

    @property
    def f(self) -> ca.Function:
        """The model as a CasADi Function f(t, x, z, u, p) -> (xdot, alg): state derivatives
        and the algebraic residual (empty for ODE models). Call it with keywords, e.g.
        ``f(x=x, u=u, p=p)["xdot"]``; omitted arguments are 0 (time-invariant ODE models need
        only x, u, p). Names: ``x_names``, ``z_names``, ``input_names``, ``param_names``."""
        if "f" not in self._cache:
            self._cache["f"] = self.function("f", [self.ode, self.alg], ["xdot", "alg"])
        return self._cache["f"]

    @property
    def output_function(self) -> ca.Function:
        """Function (t, x, z, u, p) -> y, the model's Outputs (``output_names``)."""
        if "y" not in self._cache:
            self._cache["y"] = self.function("outputs", [self.y], ["y"])
        return self._cache["y"]

    @property
    def recorded_layout(self) -> list[tuple[str, int]]:
        """Where each recorded name's values come from: ("x", i) for a name that is state i,
        ("r", j) for row j of ``recorded_function``'s output (names that are one expression,
        e.g. the positions of connected ports, share a row)."""
        return self._recorded_unique()[1]

    def _recorded_unique(self):
        if "unique" not in self._cache:
            with gc_paused():
                self._cache["unique"] = self._unique_rows()
        return self._cache["unique"]

    def _unique_rows(self):
        """(the distinct recorded expressions that are not states, stacked; the layout): a
        row is identified by its expression's node (``element_hash``), the distinct rows
        taken out of ``recorded`` in one index (stacking them one by one costs ~2 µs each)."""
        states = {e.element_hash(): i for i, e in enumerate(ca.vertsplit(self.x))}
        layout, first, seen = [], [], {}
        for k, e in enumerate(ca.vertsplit(self.recorded)):
            key = e.element_hash()
            i = states.get(key)
            if i is not None:
                layout.append(("x", i))
                continue
            j = seen.get(key)
            if j is None:
                j = seen[key] = len(first)
                first.append(k)
            layout.append(("r", j))
        return self.recorded[first, 0] if first else ca.SX(0, 1), layout

    @property
    def recorded_function(self) -> ca.Function:
        """Function (t, x, z, u, p) -> the distinct recorded expressions that are not states
        (see ``recorded_layout``)."""
        if "rec" not in self._cache:
            with gc_paused():
                self._cache["rec"] = self.function("recorded", [self._recorded_unique()[0]],
                                                   ["v"])
        return self._cache["rec"]

    @property
    def phi_q_function(self) -> ca.Function:
        """Φ_q, the loop constraints' Jacobian in the coordinates, as a Function
        (t, x, z, u, p) (built on first use): where the loop rows to enforce are chosen."""
        if "phi_q" not in self._cache:
            self._cache["phi_q"] = self.function("phi_q", [self.lagrange.phi_q], ["phi_q"])
        return self._cache["phi_q"]

    def mobility_at(self, t, x, z, u, p) -> tuple[list[int], Mobility]:
        """(enforced-row switches, Mobility) at the point (t, x, z, u, p): degrees of freedom
        (Gruebler count vs the rank of Φ_q there) and the redundant constraint rows."""
        return mobility(np.array(self.phi_q_function(t, x, z, u, p), dtype=float),
                        self.loop_rows, self.loop_rows_dropped)

    def __repr__(self):
        """A summary: the counts, then coordinates, states, algebraic variables, loops,
        events, inputs, outputs and parameters by name (long lists cut)."""
        def listed(items, limit=8):
            items = list(items)
            more = f", … ({len(items) - limit} more)" if len(items) > limit else ""
            return ", ".join(items[:limit]) + more if items else "none"

        def unit(v):
            return f" [{v.unit}]" if v.unit else ""

        modes = set(self.mode_params)
        rows = [("coordinates", listed(self.coordinates)),
                ("states", listed(self.x_names)),
                ("algebraic", listed(self.z_names)),
                ("loops", f"{len(self.loop_rows)} constraint rows ({self.method})"
                 if self.loop_rows else "none"),
                ("events", f"{len(self.state_events.indicators)} indicators, "
                 f"{len(self.mode_params)} modes" if self.has_events else "none"),
                ("inputs", listed(v.name + unit(v) for v in self.inputs)),
                ("outputs", listed(v.name + unit(v) for v in self.outputs)),
                ("parameters", listed(f"{v.name} = {v.start:g}{unit(v)}"
                                      for i, v in enumerate(self.params) if i not in modes))]
        head = (f"CompiledModel '{self.name}': {len(self.states)} states, "
                f"{len(self.algebraics)} algebraic, {len(self.params)} parameters, "
                f"{len(self.inputs)} inputs, {len(self.outputs)} outputs")
        return "\n".join([head] + [f"  {k:<13}{v}" for k, v in rows])


def _elements(overrides: dict, index: dict) -> dict:
    """``overrides`` with every vector parameter given by its name (``r``, not ``r[1]``)
    split into its elements."""
    out = {}
    for name, v in overrides.items():
        n = 0
        while name not in index and f"{name}[{n + 1}]" in index:
            n += 1
        if not n:
            out[name] = v
            continue
        try:
            flat = np.asarray(v, dtype=float).ravel()
        except (TypeError, ValueError):
            flat = None
        if flat is None or flat.size != n:
            raise ParameterError(f"parameter '{name}' has {n} elements ({name}[1] .. "
                                 f"{name}[{n}]); got {v!r}")
        out.update((f"{name}[{k + 1}]", float(x)) for k, x in enumerate(flat))
    return out


def coinciding(v: ca.SX, w: ca.SX, free: ca.SX) -> tuple[int, ca.SX] | None:
    """(k, a) when the scalar expression v is a·w[k] + b with a, b free of the symbols
    ``free`` (time, states, algebraic variables, inputs: a and b depend on parameters only),
    i.e. v coincides with w[k] up to a fixed scale and offset; None otherwise."""
    J = ca.jacobian(v, w)
    cols = J.sparsity().get_col()
    if len(cols) != 1:
        return None
    k = cols[0]
    a = J[0, k]
    if ca.depends_on(a, free) or ca.depends_on(ca.substitute(v, w[k], 0), free):
        return None
    return k, a
