"""OCP: an optimal control problem over a compiled model, written with the model's names."""
from __future__ import annotations

from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..errors import OCPError, SmoothFormWarning, SolveError, warn_user
from ..simulation.progress import IterationProgress, progress_bar
from .model import ModelView, smooth_form
from .nlp import DEFAULT_IPOPT, NLP, SUCCESS, canonical
from .solution import Solution
from .transcription import Collocation, MultipleShooting, Nodes

METHODS = ("collocation", "shooting")


@dataclass
class FreeTime:
    """A free final time T [s] (a decision variable): its guess and bounds. Give it as
    ``OCP(..., T=FreeTime(guess=3.0, lower=0.5, upper=20.0))`` and minimize ``ocp.T``."""
    guess: float = 1.0
    lower: float = 0.0
    upper: float = np.inf


class OCP:
    """An optimal control problem over a compiled model on [t0, t0 + T] [s].

    ``model``      an acausal.CompiledModel; its Inputs are the controls (piecewise constant
                   on N intervals), its states x, algebraic variables z and parameters p;
    ``N``          number of intervals of the mesh (N + 1 nodes t_0 .. t_N, step h = T/N);
    ``T``          horizon [s]: a number (fixed) or a ``FreeTime`` (free final time);
    ``method``     'collocation' (degree ``degree``, points ``scheme`` 'radau' or 'legendre')
                   or 'shooting' (a CasADi ``integrator`` plugin per interval, with
                   ``integrator_options``; see transcription.MultipleShooting);
    ``params``     fixed parameter values by dotted name (defaults otherwise);
    ``free``       parameters to estimate (decision variables; guess = their value);
    ``smooth``     True (default): a model with state events or modes (friction, impacts)
                   is transcribed in its smooth form, its Model compiled again with
                   ``compile(model, smooth=True)`` (each such component's law regularized
                   with a named parameter, e.g. ``friction.v_smooth``, which ``params``
                   sets; see the components' docstrings for the error against the exact
                   form), noted by a ``SmoothFormWarning``; ``ocp.smooth`` says whether the
                   transcribed model ``ocp.model`` is in smooth form, ``ocp.regularized``
                   names the regularized components and their parameters' values. False:
                   a model with events is refused (no complementarity form yet: a Coulomb
                   friction force as a bounded algebraic with complementarity constraints
                   needs the component to expose its force as a decision variable).
                   Check the optimum on the exact model: ``compiled.simulate(T, inputs=
                   {"F": Samples(sol.t[:-1], sol.control("F"), "hold")})``.

    Symbols, by name (CasADi MX column vectors, for costs and constraints; they combine
    with numpy arrays of the same length): ``ocp["cart.s"]`` a state at the nodes (N+1),
    ``ocp["F"]`` a control per interval (N), ``ocp["load.v[1]"]`` any recorded variable at
    the nodes (N+1), ``ocp["spring.c"]`` a parameter (scalar), ``ocp["time"]`` the node
    times [s], ``ocp.T`` the horizon [s]; ``ocp.integral(lambda v: v["F"] ** 2)`` the
    integral over the horizon of an expression of the model's variables (``v[name]`` are the
    model's SX symbols, as ``compiled.expression(name)``).

    Problem: ``minimize(cost)``, ``subject_to(ocp["cart.s"] <= 1, ...)`` (path constraints
    hold at the nodes), ``bounds(name, lower, upper)``, ``initial({...})``, ``final({...})``,
    ``guess({...})``; ``solve()`` returns a ``Solution``.
    """

    def __init__(self, model, N: int = 50, T: float | FreeTime = 1.0, *, t0: float = 0.0,
                 method: str = "collocation", degree: int = 3, scheme: str = "radau",
                 integrator: str | None = None, integrator_options: dict | None = None,
                 params: dict | None = None, free=(), smooth: bool = True):
        if not isinstance(N, (int, np.integer)) or N < 1:
            raise OCPError(f"N must be a positive integer (number of intervals), not {N!r}")
        if method not in METHODS:
            raise OCPError(f"method '{method}' is not one of {METHODS}")
        regularized = {}
        if smooth:
            model, regularized = smooth_form(model)
        self.view = view = ModelView(model, params, free)
        self.smooth = bool(model.smooth)
        self.regularized = {owner: {n: float(view.p_values[model.param_names.index(n)])
                                    for n in names} for owner, names in regularized.items()}
        if self.regularized:
            warn_user(f"optimal control of '{model.name}' in smooth form: "
                      f"{_regularization(self.regularized, model)} instead of events; the "
                      f"optimum is the smooth model's (OCP.regularized; check it on the exact "
                      f"model with simulate)", SmoothFormWarning)
        self.model, self.N, self.t0 = model, int(N), float(t0)
        self._nlp = nlp = NLP()
        X = nlp.variable("X", view.nx, N + 1)
        U = nlp.variable("U", view.nu, N)
        self._z_alg = nlp.variable("Z", len(view.z_alg), N + 1)
        Z = _rows_of(view.nz, view.z_alg) @ self._z_alg if view.nz else ca.MX(0, N + 1)
        self._p_free = nlp.variable("p_free", len(view.free))
        fixed = view.p_values.copy()
        fixed[view.free_index] = 0.0
        P = ca.MX(ca.DM(fixed)) + _rows_of(fixed.size, view.free_index) @ self._p_free
        if isinstance(T, FreeTime):
            self.free_time = T
            self.T = nlp.variable("T", 1)
        else:
            if not np.isfinite(T) or T <= 0:
                raise OCPError(f"horizon T must be a positive number of seconds, not {T!r}; "
                               "give acausal.ocp.FreeTime(...) for a free final time")
            self.free_time, self.T = None, ca.MX(float(T))
        h = self.T / N
        t = self.t0 + h * ca.DM(np.arange(N + 1)).T
        self.nodes = Nodes(X, U, Z, P, t, h)
        self.transcription = (Collocation(view, degree, scheme) if method == "collocation"
                              else MultipleShooting(view, integrator, integrator_options))
        self.method = method
        self._integrands, self._integrals = [], []
        self._objective, self._constraints = ca.MX(0), []
        self._bounds, self._initial, self._final, self._guess = {}, {}, {}, {}
        self._variables, self._built = {}, None

    # ---- symbols ------------------------------------------------------------------------------
    def __getitem__(self, name: str) -> ca.MX:
        kind, n = self.view.kind(name), self.nodes
        if kind == "state":
            return n.X[self.view.index(name), :].T
        if kind == "control":
            return n.U[self.view.index(name), :].T
        if kind == "parameter":
            return n.P[self.view.index(name)]
        if kind == "time":
            return n.t.T
        if name not in self._variables:
            f = self.view.function([self.view.sym(name)], "variable").map(self.N + 1)
            self._variables[name] = f(n.t, n.X, n.Z, n.U_nodes, n.P).T
        return self._variables[name]

    def integral(self, integrand) -> ca.MX:
        """∫ integrand dt over the horizon, an MX scalar for costs and constraints.
        ``integrand``: a callable receiving the model's symbols by name (``lambda v:
        v["F"] ** 2``), a variable name, or an SX of the model's symbols. It is integrated
        with the transcription's quadrature (collocation points, or the integrator)."""
        self._integrands.append(self.view.expression(integrand))
        self._integrals.append(ca.MX.sym(f"integral_{len(self._integrals)}"))
        self._built = None
        return self._integrals[-1]

    # ---- the problem --------------------------------------------------------------------------
    def minimize(self, cost) -> None:
        """Set the cost (an MX scalar of the problem's symbols; replaces an earlier one)."""
        cost = ca.MX(cost) if isinstance(cost, (int, float, ca.MX)) else None
        if cost is None or cost.numel() != 1:
            raise OCPError("the cost must be a scalar expression of the problem's symbols, "
                           "e.g. ocp.integral(lambda v: v['F'] ** 2) or ocp.T")
        self._objective, self._built = cost, None

    def subject_to(self, *constraints) -> None:
        """Add constraints: relations (<=, >=, ==) of the problem's symbols, elementwise."""
        for c in constraints:
            self._constraints.append(canonical(c))
        self._built = None

    def bounds(self, name: str, lower: float | None = None, upper: float | None = None) -> None:
        """lower ≤ name ≤ upper (None: unbounded) at every node (states, variables), on every
        interval (controls), or for a free parameter."""
        kind = self.view.kind(name)
        if kind == "time" or (kind == "parameter" and name not in self.view.free):
            raise OCPError(f"'{name}' is a fixed {kind}: only states, controls, recorded "
                           "variables and free parameters (OCP(..., free=[...])) take bounds")
        lo = -np.inf if lower is None else _number(lower, f"lower bound of '{name}'")
        hi = np.inf if upper is None else _number(upper, f"upper bound of '{name}'")
        if lo > hi:
            raise OCPError(f"bounds of '{name}': lower {lo:g} > upper {hi:g}")
        self._bounds[name] = (lo, hi)
        if kind == "variable":
            self._built = None

    def initial(self, values: dict) -> None:
        """Values at t_0 by name (states, controls, recorded variables)."""
        self._boundary(values, self._initial, "initial")

    def final(self, values: dict) -> None:
        """Values at t_N by name (states, controls, recorded variables)."""
        self._boundary(values, self._final, "final")

    def _boundary(self, values, store, which):
        for name, v in dict(values).items():
            kind = self.view.kind(name)
            if kind in ("time", "parameter"):
                raise OCPError(f"'{name}' is a {kind}: it takes no {which} value (fix a "
                               "parameter with OCP(..., params={...}))")
            store[name] = _number(v, f"{which} value of '{name}'")
            if kind == "variable":
                self._built = None

    def guess(self, values: dict) -> None:
        """Initial guesses by name: states (a number, N+1 node values, or a callable of
        time [s]), controls (a number, N values, or a callable of time), free parameters (a
        number). Unset states are guessed from their initial and final values (linear),
        else their start values; controls from the Inputs' start values."""
        for name, v in dict(values).items():
            kind = self.view.kind(name)
            if kind not in ("state", "control") and name not in self.view.free:
                raise OCPError(f"'{name}' is not a decision variable; guess states, controls "
                               f"and free parameters")
            size = {"state": self.N + 1, "control": self.N}.get(kind, 1)
            if not callable(v):
                arr = np.asarray(v, dtype=float).ravel()
                if arr.size not in (1, size) or not np.all(np.isfinite(arr)):
                    raise OCPError(f"guess of '{name}': give a finite number or {size} values, "
                                   f"not {arr.size}")
            self._guess[name] = v

    # ---- solving ------------------------------------------------------------------------------
    def solve(self, ipopt: dict | None = None, options: dict | None = None,
              progress: bool = False) -> Solution:
        """Solve with IPOPT. ``ipopt``: IPOPT options (default quiet: print_level 0);
        ``options``: nlpsol options (e.g. {'expand': True}); ``progress``: a progress bar
        of IPOPT's iterations (tqdm, shown once the solve takes 2 s;
        ``acausal.simulation.progress``). Raises SolveError with IPOPT's return status if
        it does not converge."""
        opts = {"print_time": False, **(options or {}),
                "ipopt": {**DEFAULT_IPOPT, **(ipopt or {})}}
        key = repr(opts) + repr(progress)
        if self._built is None or self._built[0] != key:
            self._built = (key, *self._build(opts, progress))
        _, nlp, solver, resolve, iterations = self._built
        self._fill(nlp)
        lbw, ubw, w0, lbg, ubg = nlp.bounds_and_guess()
        if iterations is not None:
            iterations.bar = progress_bar(None, f"IPOPT {self.model.name}", True, unit="it")
        try:
            out = solver(x0=w0, lbx=lbw, ubx=ubw, lbg=lbg, ubg=ubg)
        finally:
            if iterations is not None:
                iterations.bar.close()
        stats = solver.stats()
        sol = Solution(self, nlp, np.array(out["x"]).ravel(), float(out["f"]), stats, resolve)
        if stats["return_status"] not in SUCCESS:
            raise SolveError(f"IPOPT did not solve the problem on '{self.model.name}': "
                             f"{stats['return_status']} after {stats['iter_count']} "
                             "iterations; check bounds and constraints for conflicts, the "
                             "horizon, and the guess (the last iterate is error.solution)",
                             stats["return_status"], sol)
        return sol

    def _build(self, opts, progress: bool = False):
        nlp = self._nlp.copy()
        nodes = self.nodes
        if self.transcription.in_sx:        # the dynamics in SX, the fixed numbers folded in
            nodes = Nodes(*nlp.as_sx([nodes.X, nodes.U, nodes.Z, nodes.P, nodes.t, nodes.h]))
        Q = self.transcription.transcribe(nlp, nodes, self._integrands)
        syms = ca.vertcat(*self._integrals)
        in_sx = isinstance(Q, ca.SX)
        if in_sx:       # the integrals in SX for the solver, in MX for the solution's values
            if syms.numel():
                nlp.define(syms, Q)
            Q = nlp.lift([Q])[0]

        def resolve(e):     # the integrals' placeholders -> their quadratures
            return ca.substitute(ca.MX(e), syms, Q) if syms.numel() else ca.MX(e)

        inner = ca.MX if in_sx else resolve     # what the solver is given
        for g, lb, ub in self._constraints:
            nlp.bound(inner(g), lb, ub)
        for name, (lo, hi) in self._bounds.items():
            if self.view.kind(name) == "variable":
                nlp.bound(self[name], lo, hi)
        for store, k in ((self._initial, 0), (self._final, -1)):
            for name, v in store.items():
                if self.view.kind(name) == "variable":
                    nlp.equal(self[name][k], v)
        iterations = None
        if progress:
            iterations = IterationProgress(nlp.w.numel(), sum(g.numel() for g in nlp.g), 0)
            opts = dict(opts, iteration_callback=iterations)
        try:
            solver = nlp.solver(inner(self._objective), opts)
        except RuntimeError as e:
            raise OCPError(f"cannot make the IPOPT solver: {str(e).strip().splitlines()[-1]}") \
                from None
        return nlp, solver, resolve, iterations

    def _fill(self, nlp: NLP) -> None:
        """Bounds and guesses of the node variables, from bounds/initial/final/guess."""
        view, n, t = self.view, self.nodes, self._time_guess()
        X_guess = self._state_guess(t)
        nlp.set(n.X, *self._box("state", n.X.shape, self.N), guess=X_guess)
        U_guess = np.tile(view.u_start.reshape(-1, 1), (1, self.N))
        for name, v in self._guess.items():
            if view.kind(name) == "control":
                U_guess[view.index(name)] = v(t[:-1]) if callable(v) else v
        nlp.set(n.U, *self._box("control", n.U.shape, self.N - 1), guess=U_guess)
        declared = view.compiled.params          # a free parameter keeps its declared range
        box = [self._bounds.get(name, (declared[i].min, declared[i].max))
               for name, i in zip(view.free, view.free_index)]
        guess = [self._guess.get(name, view.p_values[i])
                 for name, i in zip(view.free, view.free_index)]
        column = lambda values: np.reshape(values, (-1, 1))
        nlp.set(self._p_free, column([b[0] for b in box]), column([b[1] for b in box]),
                column(guess))
        nlp.set(self._z_alg, guess=view.z_start[view.z_alg].reshape(-1, 1))
        if self.free_time is not None:
            ft = self.free_time
            if not 0 <= ft.lower <= ft.guess <= ft.upper:
                raise OCPError(f"free final time: need 0 ≤ lower ≤ guess ≤ upper, got "
                               f"{ft.lower:g} ≤ {ft.guess:g} ≤ {ft.upper:g}")
            nlp.set(self.T, ft.lower, ft.upper, ft.guess)
        self.transcription.fill_guess(nlp, X_guess)

    def _box(self, kind: str, shape, last: int):
        """(lower, upper) arrays of the states or controls: bounds, then the initial (column
        0) and final (column ``last``) values, which must lie within them."""
        lb, ub = np.full(shape, -np.inf), np.full(shape, np.inf)
        named = lambda store: [(n, v) for n, v in store.items() if self.view.kind(n) == kind]
        for name, (lo, hi) in named(self._bounds):
            lb[self.view.index(name)], ub[self.view.index(name)] = lo, hi
        for which, store, k in (("initial", self._initial, 0), ("final", self._final, last)):
            for name, v in named(store):
                i = self.view.index(name)
                if not lb[i, k] <= v <= ub[i, k]:
                    raise OCPError(f"{which} value {v:g} of '{name}' is outside its bounds "
                                   f"[{lb[i, k]:g}, {ub[i, k]:g}]")
                lb[i, k] = ub[i, k] = v
        return lb, ub

    def _time_guess(self) -> np.ndarray:
        """Node times [s] with the horizon's guess."""
        T = self.free_time.guess if self.free_time is not None else float(ca.evalf(self.T))
        return self.t0 + T * np.arange(self.N + 1) / self.N

    def _state_guess(self, t: np.ndarray) -> np.ndarray:
        X = np.tile(self.view.x_start.reshape(-1, 1), (1, self.N + 1))
        for i, name in enumerate(self.view.compiled.x_names):
            a, b = self._initial.get(name), self._final.get(name)
            if name in self._guess:
                v = self._guess[name]
                X[i] = v(t) if callable(v) else v
            elif a is not None and b is not None:
                X[i] = np.linspace(a, b, self.N + 1)
            elif a is not None or b is not None:
                X[i] = a if a is not None else b
        return X

    def __repr__(self):
        T = "free" if self.free_time is not None else f"{float(ca.evalf(self.T)):g} s"
        form = f", smooth form of {', '.join(self.regularized)}" if self.regularized else (
            ", smooth form" if self.smooth else "")
        return (f"<OCP on '{self.model.name}': {self.method}, N = {self.N}, T = {T}, "
                f"{self.view.nx} states, {self.view.nu} controls, {len(self.view.free)} free "
                f"parameters{form}>")


def _regularization(regularized: dict, model) -> str:
    """'friction (friction.v_smooth = 0.001 m/s), ...'."""
    units = {v.name: v.unit for v in model.params}
    return ", ".join(owner + " (" + ", ".join(f"{n} = {v:g} {units[n]}".rstrip()
                                              for n, v in values.items()) + ")"
                     for owner, values in regularized.items())


def _rows_of(n: int, rows: list) -> ca.DM:
    """The n × len(rows) matrix placing a vector's entries at ``rows``."""
    S = ca.DM.zeros(n, len(rows))
    for j, r in enumerate(rows):
        S[r, j] = 1.0
    return S


def _number(v, what: str) -> float:
    try:
        out = float(v)
    except (TypeError, ValueError):
        raise OCPError(f"{what} must be a number, not {v!r}") from None
    if np.isnan(out):
        raise OCPError(f"{what} is NaN")
    return out
