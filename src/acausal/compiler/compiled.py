"""CompiledModel: the seam between the compiler and everything downstream.

It holds, by name, the states, algebraic variables, parameters (with defaults), inputs and
outputs, and the CasADi objects: the semi-explicit DAE

    ẋ = ode(t, x, z, p, u),   0 = alg(t, x, z, p, u)

as a dict for ``casadi.integrator`` (its ``p`` is [parameters; inputs]), Functions for the
right-hand side and the recorded variables, and the pieces of Lagrange's equations
(``lagrange``): M(q), C, K, gravity, Coriolis, input matrix, Φ(q) for loops.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import casadi as ca
import numpy as np

from ..errors import ParameterError, VariableNameError, did_you_mean


class Lagrange:
    """Lagrange's equations of a compiled model, as CasADi expressions of the coordinates q,
    their rates q̇ (``qd``), the inputs u, time t, parameters p (and internal states z):

        M(q) q̈ + C q̇ + K q = gravity(q) + coriolis(q, q̇) + B u + Q_rest  (− Φ_qᵀ λ)

    - ``M`` the mass matrix; ``coriolis`` = −(Ṁ q̇ − ∂T/∂q), the centrifugal and Coriolis
      terms; ``gravity`` = −∂V/∂q from potential energies;
    - the generalized forces Q of all port forces and torques (springs, dampers, sources,
      actuators) are split as Q = −K q − C q̇ + B u + Q_rest when their stiffness and damping
      are linear (``K``, ``C`` constant); otherwise ``K`` and ``C`` are None and Q_rest = Q − B u;
    - ``B`` = ∂Q/∂u, the input matrix of the model's Inputs (``u_names``);
    - ``phi`` the loop constraints Φ(q, t) = 0 and ``phi_q`` their Jacobian.
    ``R0`` = −(gravity + coriolis + Q) is everything but the inertia term: M q̈ + R0 = 0.
    Each piece is derived (by AD) on first access.
    """

    def __init__(self, tree, R_T, R_V, R_Q, phi, t, p, u, u_names, z):
        self.q, self.qd, self.qdd = tree.q, tree.qd, tree.qdd
        self.q_names, self.qd_names = tree.q_names, tree.qd_names
        self.phi, self.t, self.p, self.u, self.u_names, self.z = phi, t, p, u, list(u_names), z
        self._R = (R_T, R_V, R_Q)
        self._cache = {}

    def _lazy(self, key, make):
        if key not in self._cache:
            self._cache[key] = make()
        return self._cache[key]

    @property
    def M(self) -> ca.SX:
        return self._lazy("M", lambda: ca.jacobian(self._R[0], self.qdd))

    @property
    def coriolis(self) -> ca.SX:
        return self._lazy("cor", lambda: -ca.substitute(self._R[0], self.qdd, self._zero()))

    @property
    def gravity(self) -> ca.SX:
        return -self._R[1]

    @property
    def B(self) -> ca.SX:
        return self._lazy("B", lambda: ca.jacobian(-self._R[2], self.u))

    def _split_Q(self):
        Q = -self._R[2]
        Qnu = ca.substitute(Q, self.u, ca.SX.zeros(self.u.numel()))
        K, C = -ca.jacobian(Qnu, self.q), -ca.jacobian(Qnu, self.qd)
        if ca.depends_on(ca.vertcat(ca.vec(K), ca.vec(C)), ca.vertcat(self.q, self.qd, self.qdd)):
            return None, None, Qnu
        return K, C, ca.simplify(Qnu + ca.mtimes(K, self.q) + ca.mtimes(C, self.qd))

    @property
    def K(self) -> ca.SX | None:
        return self._lazy("Q", self._split_Q)[0]

    @property
    def C(self) -> ca.SX | None:
        return self._lazy("Q", self._split_Q)[1]

    @property
    def Q_rest(self) -> ca.SX:
        return self._lazy("Q", self._split_Q)[2]

    @property
    def phi_q(self) -> ca.SX:
        return self._lazy("phi_q", lambda: ca.jacobian(self.phi, self.q))

    @property
    def R0(self) -> ca.SX:
        return self._lazy("R0", lambda: ca.substitute(sum(self._R, ca.SX(0)), self.qdd,
                                                      self._zero()))

    def _zero(self):
        return ca.SX.zeros(self.qdd.numel())

    def with_values(self, values: dict, keep: tuple = ()) -> "Lagrange":
        """The same equations with the parameters in ``values`` (dotted name -> number, e.g.
        ``compiled.param_defaults``) replaced by numbers, except those named in ``keep``:
        printing then reads like a hand derivation (``M = [[m1+m2, ...``)."""
        names = [s.name() for s in ca.vertsplit(self.p)]
        subs = [(s, v) for s, n in zip(ca.vertsplit(self.p), names)
                if n in values and n not in keep for v in [values[n]]]
        if not subs:
            return self
        sym, val = ca.vertcat(*[a for a, _ in subs]), ca.vertcat(*[b for _, b in subs])
        R = ca.substitute(list(self._R) + [self.phi], [sym], [val])
        out = Lagrange.__new__(Lagrange)
        out.__dict__.update(self.__dict__)
        out._R, out.phi, out._cache = tuple(ca.simplify(r) for r in R[:3]), R[3], {}
        return out

    def function(self, *names: str) -> ca.Function:
        """A casadi Function (q, qd, u, t, p) -> the named pieces ('M', 'gravity', ...)."""
        outs = [getattr(self, n) for n in names]
        if any(o is None for o in outs):
            raise ValueError(f"{[n for n, o in zip(names, outs) if o is None]} not linear here")
        return ca.Function("lagrange", [self.q, self.qd, self.u, self.t, self.p], outs,
                           ["q", "qd", "u", "t", "p"], list(names), {"allow_free": True})

    def __str__(self):
        def show(name, ex):
            return f"{name} =\n{ex}" if ex is not None else f"{name}: not linear"
        lines = [f"q = [{', '.join(self.q_names)}]", f"u = [{', '.join(self.u_names)}]",
                 "M q'' + C q' + K q = gravity + coriolis + B u + Q_rest",
                 show("M", self.M), show("C", self.C), show("K", self.K),
                 show("gravity", self.gravity), show("coriolis", self.coriolis),
                 show("B", self.B), show("Q_rest", self.Q_rest)]
        if self.phi.numel():
            lines += [show("Phi", self.phi), show("Phi_q", self.phi_q)]
        return "\n".join(lines)


@dataclass
class CompiledModel:
    name: str
    t: ca.SX
    x: ca.SX
    z: ca.SX
    p: ca.SX
    u: ca.SX
    ode: ca.SX
    alg: ca.SX
    x_names: list
    z_names: list
    start: ca.Function      # p -> start values of [x; z]
    events: ca.Function     # p -> (times, periods) of time events
    params: list            # (name, default, unit, description, Parameter)
    inputs: list            # (name, start, unit, description)
    outputs: list           # (name, unit, description)
    y: ca.SX
    recorder: object        # () -> (names, expressions, units) of every recorded variable
    lagrange: Lagrange
    coordinates: list
    method: str = ""        # how accelerations are solved: diagonal / recursion / dense / KKT
    loop_rows: list = field(default_factory=list)          # names of the rows of Φ
    loop_rows_dropped: list = field(default_factory=list)  # constant, redundant rows removed
    _cache: dict = field(default_factory=dict, repr=False)

    # ---- names ----------------------------------------------------------------------------
    @property
    def param_names(self) -> list[str]:
        return [p[0] for p in self.params]

    @property
    def param_defaults(self) -> dict[str, float]:
        return {p[0]: p[1] for p in self.params}

    @property
    def input_names(self) -> list[str]:
        return [i[0] for i in self.inputs]

    @property
    def output_names(self) -> list[str]:
        return [o[0] for o in self.outputs]

    @property
    def loop_switches(self) -> list[int]:
        """Positions in p of the loop-row switches ``loops.active_i`` (row order): 1 enforces
        row i of Φ, 0 drops it (redundant). simulate() and the FMUs set them at the assembled
        initial configuration (``mobility_at``)."""
        return [i for i, n in enumerate(self.param_names) if n.startswith("loops.active")]

    def param_vector(self, overrides: dict | None = None) -> np.ndarray:
        """Parameter values [defaults with ``overrides`` by dotted name], checked."""
        values = self.param_defaults
        for name, v in (overrides or {}).items():
            if name not in values:
                raise ParameterError(f"model '{self.name}' has no parameter '{name}'"
                                     f"{did_you_mean(name, values)}")
            par = self.params[self.param_names.index(name)][4]
            values[name] = par.check_scalar(v, name.rsplit(".", 1)[0])
        return np.array([values[n] for n in self.param_names], dtype=float)

    def event_times(self, p: np.ndarray, t0: float, t1: float) -> list[float]:
        """Times of the declared time events strictly inside (t0, t1), sorted."""
        from ..simulation.kernels import event_times
        return event_times(*self.events(p), t0, t1)

    # ---- recorded variables (built on first use) -------------------------------------------
    def _recorded(self):
        if "recorded" not in self._cache:
            self._cache["recorded"] = self.recorder()
        return self._cache["recorded"]

    @property
    def recorded_names(self) -> list[str]:
        """Dotted names of every variable a Result holds."""
        return self._recorded()[0]

    @property
    def recorded(self) -> ca.SX:
        """Expressions (in t, x, z, p, u) of the recorded variables, stacked."""
        return self._recorded()[1]

    @property
    def recorded_units(self) -> list[str]:
        return self._recorded()[2]

    # ---- CasADi objects ---------------------------------------------------------------------
    @property
    def dae(self) -> dict:
        """The DAE as a dict for ``casadi.integrator``: x, z, p = [params; inputs], t, ode, alg."""
        d = {"x": self.x, "p": ca.vertcat(self.p, self.u), "t": self.t, "ode": self.ode}
        if self.z.numel():
            d.update(z=self.z, alg=self.alg)
        return d

    @property
    def f(self) -> ca.Function:
        """The model as a CasADi Function f(x, u, p, z, t) -> (xdot, alg): state derivatives
        and the algebraic residual (empty for ODE models). Call it with keywords, e.g.
        ``f(x=x, u=u, p=p)["xdot"]``; omitted arguments are 0 (time-invariant ODE models need
        only x, u, p). Symbols: ``x, u, p, z, t``; names: ``x_names``, ``input_names``,
        ``param_names``, ``z_names``."""
        if "f" not in self._cache:
            self._cache["f"] = ca.Function("f", [self.x, self.u, self.p, self.z, self.t],
                                           [self.ode, self.alg], ["x", "u", "p", "z", "t"],
                                           ["xdot", "alg"])
        return self._cache["f"]

    @property
    def output_function(self) -> ca.Function:
        """Function (x, u, p, z, t) -> y, the model's Outputs (``output_names``)."""
        if "y" not in self._cache:
            self._cache["y"] = ca.Function("outputs", [self.x, self.u, self.p, self.z, self.t],
                                           [self.y], ["x", "u", "p", "z", "t"], ["y"])
        return self._cache["y"]

    @property
    def recorded_layout(self) -> list[tuple[str, int]]:
        """Where each recorded name's values come from: ("x", i) for a name that is state i,
        ("r", j) for row j of ``recorded_function``'s output (names that are one expression,
        e.g. the positions of connected ports, share a row)."""
        return self._recorded_unique()[1]

    def _recorded_unique(self):
        if "unique" not in self._cache:
            states = {e.element_hash(): i for i, e in enumerate(ca.vertsplit(self.x))}
            layout, unique, seen = [], [], {}
            for e in ca.vertsplit(self.recorded):
                key = e.element_hash()
                if key in states:
                    layout.append(("x", states[key]))
                    continue
                if key not in seen:
                    seen[key] = len(unique)
                    unique.append(e)
                layout.append(("r", seen[key]))
            self._cache["unique"] = (ca.vertcat(*unique) if unique else ca.SX(0, 1), layout)
        return self._cache["unique"]

    @property
    def recorded_function(self) -> ca.Function:
        """Function (t, x, z, p, u) -> the distinct recorded expressions that are not states
        (see ``recorded_layout``)."""
        if "rec" not in self._cache:
            self._cache["rec"] = ca.Function("recorded", [self.t, self.x, self.z, self.p, self.u],
                                             [self._recorded_unique()[0]],
                                             ["t", "x", "z", "p", "u"], ["v"])
        return self._cache["rec"]

    def expression(self, name: str) -> ca.SX:
        """The symbolic expression of a recorded variable, in t, x, z, p, u."""
        try:
            return self.recorded[self.recorded_names.index(name)]
        except ValueError:
            raise VariableNameError(f"no variable '{name}' in model '{self.name}'"
                           f"{did_you_mean(name, self.recorded_names)}") from None

    def mobility(self, params: dict | None = None, x0: dict | None = None,
                 guess: dict | None = None, t0: float = 0.0):
        """Degrees of freedom at the configuration assembled from x0 / guess (Gruebler count
        vs the rank of Φ_q there) and the redundant constraint rows: a loops.Mobility."""
        from ..simulation.initialization import initial_state
        p = self.param_vector(params)
        u0 = np.array([i[1] for i in self.inputs], dtype=float)
        x, z = initial_state(self, dict(x0 or {}), p, u0, t0, guess)
        return self.mobility_at(x, z, p, t0)[1]

    @property
    def phi_q_function(self) -> ca.Function:
        """Φ_q, the loop constraints' Jacobian in the coordinates, as a Function (x, z, t, p)
        (built on first use): where the loop rows to enforce are chosen."""
        if "phi_q" not in self._cache:
            self._cache["phi_q"] = ca.Function("phi_q", [self.x, self.z, self.t, self.p],
                                               [self.lagrange.phi_q], ["x", "z", "t", "p"],
                                               ["phi_q"], {"allow_free": True})
        return self._cache["phi_q"]

    def mobility_at(self, x, z, p, t=0.0):
        """(enforced-row switches, Mobility) at the state x, z: see ``mobility``."""
        from .loops import mobility
        return mobility(np.array(self.phi_q_function(x, z, t, p), dtype=float), self.loop_rows,
                        self.loop_rows_dropped)

    def simulate(self, t_final: float, **kwargs):
        """Simulate; see acausal.simulation.simulate for the arguments."""
        from ..simulation import simulate
        return simulate(self, t_final, **kwargs)

    def export_fmu(self, path, **kwargs):
        """Export as an FMU; see acausal.fmu.export_fmu for the arguments."""
        from ..fmu import export_fmu
        return export_fmu(self, path, **kwargs)

    def __repr__(self):
        return (f"<CompiledModel '{self.name}': {len(self.x_names)} states, "
                f"{len(self.z_names)} algebraic, {len(self.params)} parameters, "
                f"{len(self.inputs)} inputs, {len(self.outputs)} outputs>")
