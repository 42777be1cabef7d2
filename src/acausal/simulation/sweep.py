"""sweep(): many runs of one compiled model — variations of parameters, start values and
inputs — through one CasADi integrator mapped over the runs, on threads or on a
``dask.distributed`` cluster.

The integrator is built once with the parameters, the nominals (the state scaling) and the
varied inputs as its symbolic parameters, never folded per run; ``Function.map(n, "thread",
threads)`` integrates a chunk of runs in one call. A chunk that fails is integrated again
run by run to find which runs failed and why: those get NaN trajectories and an entry in
``SweepResult.failed``, never dropped. On a cluster the integrator travels once, serialized
(``casadi.Function.serialize``), to every worker; each task integrates a chunk of runs.

Models with state events or modes, closed loops, declared time events (a Step, a sampled
block), or per-run inputs other than numbers and arrays on the grid are run as a loop of
``simulate()`` instead (serial, in this process), with the same result.
"""
from __future__ import annotations

import itertools
import math
import os
from contextlib import nullcontext

import casadi as ca
import numpy as np

from ..errors import AcausalError, SimulationError
from ..numerics import event_times, first_failed_assertion
from . import assertions
from .diagnosis import failure_message, not_finite, quiet_stderr
from .events import ModeIteration
from .initialization import initial_state
from .inputs import Samples, input_signal
from .problem import (check_finite, check_inputs, check_settings, integrator_problem,
                      integrator_settings, output_grid, scaled)
from .simulate import simulate
from .stiffness import adams_step_budget, is_stiff, spectral_radius

KINDS = ("params", "x0", "inputs")


class SweepResult:
    """The runs of a sweep: ``dataset`` (an ``xarray.Dataset``, dims run × time, a variable
    per name asked for, the varied values as coordinates along run: parameters by name,
    start values as ``<name>(0)``, constant inputs by name; ``failed`` (boolean) and
    ``solver`` (the one that ran, as simulate()'s ``Result.solver``) coordinates too);
    ``res[name]``: a (runs × times) array; ``as_frame()``: a long pandas frame; ``runs``:
    each run's variation (list of dicts {name: value} by kind); ``failed``: the failed runs,
    index → error message (their values are NaN); ``method``: "map" (one mapped integrator)
    or "simulate" (a loop of simulate())."""

    def __init__(self, t, dataset, runs, failed, method):
        self.t, self.dataset, self.runs, self.failed, self.method = t, dataset, runs, failed, method

    def __getitem__(self, name: str) -> np.ndarray:
        if name not in self.dataset.data_vars:
            raise SimulationError(f"the sweep recorded no '{name}'; it recorded "
                                  f"{list(self.dataset.data_vars)} (give variables=[...])")
        return self.dataset[name].values

    def as_frame(self):
        """A long pandas DataFrame: one row per run and time, the varied values and the
        variables as columns."""
        return self.dataset.to_dataframe().reset_index()

    def __len__(self):
        return len(self.runs)

    def __repr__(self):
        return (f"<SweepResult: {len(self.runs)} runs ({len(self.failed)} failed) × "
                f"{self.t.size} times, {list(self.dataset.data_vars)}, by {self.method}>")


def sweep(model, t_final: float, *, runs=None, params: dict | None = None,
          x0: dict | None = None, inputs: dict | None = None, t=None,
          variables: list[str] | None = None, guess: dict | None = None,
          solver: str | None = None, rtol: float = 1e-8, atol: float = 1e-10,
          max_step: float | None = None, nominal: dict | None = None,
          options: dict | None = None, threads: int | None = None, chunk: int | None = None,
          client=None, cluster: str | None = None, workers: int = 2) -> SweepResult:
    """Simulate ``model`` once per variation, from t = 0 (or t[0]) to ``t_final`` [s].

    Variations, by dotted name:
    params, x0, inputs   dicts name → value; a list (or 1-D array) of values varies it, one
             run per value, and several lists make a grid (their Cartesian product); any
             other value holds for every run. An input's value per run is a number or an
             array on the grid t (a list of such, or a 2-D array with one row per run); a
             fixed input may be anything ``simulate`` takes (a 1-D array: one signal on
             the grid t for every run);
    runs     a list of dicts, or a pandas DataFrame (a column per name), one run per row:
             names of parameters, inputs or any variable's start value (x0); combined with
             the lists of params / x0 / inputs as a grid (every row with every grid point).

    The other arguments are simulate()'s (``acausal.simulation.simulate``: the solver is
    chosen per run as simulate() chooses it, and a run Adams fails is run again with
    'cvodes'; runs with Adams equal simulate()'s to round-off, runs with BDF, whose Newton
    iterations round differently with the parameters as symbols, to the integration
    error), and:
    variables  the dotted names recorded (default: the states and the outputs);
    threads    threads of the mapped integrator (default: the machine's cores);
    chunk      runs per call of the mapped integrator (per task on a cluster; default: the
               runs split into two calls per thread or worker);
    client     a ``dask.distributed.Client``: the chunks run on its cluster, the integrator
               shipped once to every worker, serialized (no recompilation per task);
    cluster    "local": start a ``LocalCluster`` of ``workers`` processes (one thread
               each) for this call, and close it after. To use a cluster of machines, start
               a scheduler and workers there (``dask scheduler``; ``dask worker
               tcp://host:8786`` on each machine, with acausal and casadi installed) and
               pass ``client=Client("tcp://host:8786")``. Processes start by importing
               the script: call sweep under ``if __name__ == "__main__":`` there.

    Models with state events or modes, closed loops or declared time events (a Step, a
    sampled block), and per-run inputs that are not numbers or arrays on the grid, run as a
    serial loop of simulate() in this process (``method`` "simulate"; client and cluster
    unused), with the values on the grid t (at an event on a grid time: the value after it;
    after a termination: NaN).

    A run that cannot start (a parameter out of its range, inconsistent start values) or
    whose integration fails is reported in ``failed`` (index → message) with NaN values.
    """
    grid = output_grid(t_final, t)
    check_settings(rtol=rtol, atol=atol, max_step=max_step)
    check_finite("guess", guess)
    table = variations(model, runs, params, x0, inputs)
    variables = list(variables) if variables is not None else \
        model.x_names + model.output_names
    for name in set(variables).union(*[run["x0"] for run in table]):
        model.locate(name)                   # VariableNameError naming it, before any run
    settings = dict(guess=guess, solver=solver, rtol=rtol, atol=atol, max_step=max_step,
                    nominal=nominal, options=options)
    P, refused = _parameter_columns(model, table)
    if _needs_loop(model, table, grid, P):
        values, failed, solvers = _simulate_loop(model, grid, table, variables, settings)
        method = "simulate"
    else:
        with _cluster(client, cluster, workers) as dask_client:
            engine = _Engine(model, grid, table, P, refused, settings, threads, chunk,
                             dask_client)
            values, failed, solvers = engine.run(variables)
        method = "map"
    return SweepResult(grid, _dataset(grid, table, variables, values, failed, solvers), table,
                       failed, method)


# ---- variations ---------------------------------------------------------------------------
def _alternatives(kind: str, value):
    """The values a sweep argument takes over the runs (a list), or None when it is fixed
    (an input's 1-D array is one signal on the grid, as simulate() takes it)."""
    if isinstance(value, (list, range)) or type(value).__name__ == "Series":
        return list(value)
    if isinstance(value, np.ndarray) and value.ndim >= (2 if kind == "inputs" else 1):
        return [np.asarray(v) if np.ndim(v) else float(v) for v in value]
    return None


def variations(model, runs=None, params=None, x0=None, inputs=None) -> list[dict]:
    """The runs of a sweep (see ``sweep``), each a dict kind → {name: value} for kind in
    params, x0, inputs, in the order: rows of ``runs``, each with every point of the grid."""
    fixed = {kind: {} for kind in KINDS}
    axes = []
    for kind, given in zip(KINDS, (params, x0, inputs)):
        for name, value in (given or {}).items():
            alt = _alternatives(kind, value)
            if alt is None:
                fixed[kind][name] = value
            elif not alt:
                raise SimulationError(f"{kind}['{name}']: an empty list of values (no runs)")
            else:
                axes.append((kind, name, alt))
    rows = [{}] if runs is None else _rows(model, runs)
    table = []
    for row in rows:
        for point in itertools.product(*[alt for _, _, alt in axes]):
            run = {kind: dict(values) for kind, values in fixed.items()}
            for name, value in row.items():
                run[_kind(model, name)][name] = value
            for (kind, name, _), value in zip(axes, point):
                run[kind][name] = value
            table.append(run)
    return table


def _rows(model, runs) -> list[dict]:
    if hasattr(runs, "to_dict") and hasattr(runs, "columns"):      # a pandas DataFrame
        rows = runs.to_dict("records")
    else:
        rows = [dict(r) for r in runs]
    if not rows:
        raise SimulationError("runs is empty: give at least one run")
    return rows


def _kind(model, name: str) -> str:
    if name in model.param_defaults:
        return "params"
    return "inputs" if name in model.input_names else "x0"


def _varied(table) -> dict[str, list]:
    """The values that differ between runs, by (kind, name)."""
    names = {(kind, n) for run in table for kind in KINDS for n in run[kind]}
    out = {}
    for kind, name in sorted(names):
        values = [run[kind].get(name) for run in table]
        if any(not _same(v, values[0]) for v in values):
            out[(kind, name)] = values
    return out


def _same(a, b) -> bool:
    try:
        return bool(np.array_equal(np.asarray(a, dtype=float), np.asarray(b, dtype=float)))
    except (TypeError, ValueError):
        return a is b


def _parameter_columns(model, table) -> tuple[np.ndarray, dict[int, str]]:
    """The parameters of every run of ``table`` (a column each, ``param_names`` order) and
    the runs whose values a parameter refuses (index → message; the value left at its
    default: that run fails). Names that are no parameter of the model are left out
    (the mapped integrator refuses them, a loop of simulate() fails those runs)."""
    index = {name: i for i, name in enumerate(model.param_names)}
    P = np.tile(model.param_vector()[:, None], (1, len(table)))
    refused: dict[int, str] = {}
    for k, run in enumerate(table):
        for name, value in run["params"].items():
            if name in index and name not in model.fixed_params:
                try:
                    P[index[name], k] = model.params[index[name]].check(value)
                except AcausalError as e:
                    refused.setdefault(k, str(e))
    return P, refused


def _needs_loop(model, table, grid, P) -> bool:
    """Whether the runs need simulate() one by one (see ``sweep``); P: their parameters."""
    if model.has_events or model.has_loops or not model.x.numel():
        return True
    for (kind, name), values in _varied(table).items():
        if kind == "inputs" and any(callable(v) or isinstance(v, (Samples, tuple))
                                    for v in values):
            return True
    if _time_events(model, P, grid):
        return True
    run = table[0]["inputs"]
    return any(input_signal(v.name, run.get(v.name, v.start), model.t, grid).events
               for v in model.inputs)


def _time_events(model, P, grid) -> bool:
    """Whether a run (a column of the parameters P) has a declared time event (a Step, a
    sampled block) inside the grid."""
    if not model.events.numel_out(0):
        return False
    n = P.shape[1]
    times, periods = (np.array(v, dtype=float).reshape(-1, n) for v in model.events.map(n)(P))
    return any(event_times(times[:, k], periods[:, k], grid[0], grid[-1]) for k in range(n))


# ---- the mapped integrator ----------------------------------------------------------------
class _Engine:
    """The runs of a sweep through one integrator with symbolic parameters
    q = [model parameters p; nominals; varied inputs], mapped over chunks of runs."""

    def __init__(self, model, grid, table, P, refused, settings, threads, chunk, client):
        self.model, self.grid, self.table, self.settings = model, grid, table, settings
        self.threads = threads or os.cpu_count() or 1
        self.chunk, self.client = chunk, client
        self.P, self.failed = P, dict(refused)     # (``_parameter_columns``)
        self.solvers = np.array([""] * len(table), dtype=object)     # the solver of each run
        self._inputs(table)
        self._starts(table)
        self.q = ca.vertcat(model.p, self.nominal, self.u_sym)
        self.Q = np.vstack([self.P, self.N, self.U])
        ode = ca.substitute(model.ode, model.u, self.u_expr)
        alg = ca.substitute(model.alg, model.u, self.u_expr)
        self.ode, self.alg = scaled(model, ode, alg, self.nominal)

    def _inputs(self, table):
        """The inputs as expressions of time and of the symbols of the varied ones: a
        constant per run is one symbol, an array on the grid per run a linear interpolant
        with the values as symbols (the interpolation simulate() gives such an input,
        ``inputs._linear``)."""
        model, grid = self.model, self.grid
        varied = {name: values for (kind, name), values in _varied(table).items()
                  if kind == "inputs"}
        check_inputs(model, {n for run in table for n in run["inputs"]})
        exprs, syms, rows = [], [], []
        for v in model.inputs:
            if v.name not in varied:
                value = table[0]["inputs"].get(v.name, v.start)
                exprs.append(input_signal(v.name, value, model.t, grid).expression)
                continue
            values = [np.asarray(x if x is not None else v.start, dtype=float)
                      for x in varied[v.name]]
            for x in values:
                if x.ndim and x.size != grid.size or not np.all(np.isfinite(x)):
                    raise SimulationError(
                        f"input '{v.name}': a run's value must be a finite number or an array "
                        f"of {grid.size} values on the grid t, got {x!r}")
            if all(x.ndim == 0 for x in values):
                s = ca.SX.sym(v.name)
                exprs.append(s)
                rows.append(np.array([float(x) for x in values])[None, :])
            else:
                s = ca.SX.sym(v.name, grid.size)
                exprs.append(ca.interpolant(v.name, "linear", [grid])(model.t, s))
                rows.append(np.column_stack([np.broadcast_to(x, grid.shape) for x in values]))
            syms.append(s)
        self.u_expr = ca.vertcat(*exprs) if exprs else ca.SX(0, 1)
        self.u_sym = ca.vertcat(*syms) if syms else ca.SX(0, 1)
        self.U = np.vstack(rows) if rows else np.zeros((0, len(table)))
        self.u_of = ca.Function("u", [model.t, self.u_sym], [self.u_expr])
        self.nominal = ca.SX.sym("nominal", model.x.numel() + model.z.numel())

    def _starts(self, table):
        """Nominals N and consistent start values W0 of every run (a column each), or the
        run's failure: a name that is no parameter is an error for all runs; the start
        values and nominals of runs that need no projection (no x0, guess, initial
        equations, algebraic variables or loops) by one mapped call each, the others run
        by run."""
        model, s, t0, n = self.model, self.settings, self.grid[0], len(table)
        known = set(model.param_names) - set(model.fixed_params)
        for run in table:
            for name in run["params"]:
                if name not in known:
                    model.param_vector({name: 0.0})       # the error naming it, for all runs
        ok = np.array([k for k in range(n) if k not in self.failed], dtype=int)
        self.N = np.ones((model.x.numel() + model.z.numel(), n))
        self.W0 = np.full(self.N.shape, np.nan)
        if not ok.size:
            return
        if s["nominal"] is None:
            self.N[:, ok] = np.array(model.nominal.map(ok.size)(self.P[:, ok]), dtype=float)
        U0 = np.array(self.u_of.map(n)(t0, self.U), dtype=float).reshape(-1, n)
        mapped = not (s["guess"] or model.initial_equations.numel() or model.z.numel()
                      or model.has_loops)
        self.W0[:, ok] = np.array(model.start.map(ok.size)(self.P[:, ok]), dtype=float)
        for k in ok:
            run = table[k]
            try:
                if s["nominal"] is not None or not np.all((self.N[:, k] > 0)
                                                           & (self.N[:, k] < np.inf)):
                    self.N[:, k] = model.nominals(self.P[:, k], s["nominal"])   # or its error
                if run["x0"] or not mapped:
                    check_finite("x0", run["x0"])
                    x, z = initial_state(model, dict(run["x0"]), self.P[:, k], U0[:, k], t0,
                                         s["guess"], initial_equations=True)
                    self.W0[:, k] = np.concatenate([np.ravel(x), np.ravel(z)])
            except AcausalError as e:
                self.failed[k] = str(e)
        self.W0[:, list(self.failed)] = np.nan

    def _solvers(self, ok: np.ndarray) -> tuple[dict[str, list[int]], np.ndarray]:
        """The runs by solver (simulate()'s choice per run, or the one given), with the
        spectral radii (for Adams' step budget); the runs whose equations are not finite
        at the start fail."""
        model, grid, given = self.model, self.grid, self.settings["solver"]
        nx = model.x.numel()
        rho = np.zeros(len(self.table))
        if model.z.numel():
            return {given or "idas": list(ok)}, rho
        f = ca.Function("ode", [model.x, model.t, self.q], [self.ode])
        fm = f.map(ok.size)
        Q, X0 = self.Q[:, ok], self.W0[:nx, ok] / self.N[:nx, ok]
        fx0 = np.array(fm(X0, grid[0], Q), dtype=float)
        good = np.all(np.isfinite(fx0), axis=0)
        for j in np.flatnonzero(~good):
            k = ok[j]
            self.failed[k] = not_finite(model, self.W0[:nx, k], fx0[:, j] * self.N[:nx, k],
                                         self.P[:, k], self.U[:, k], grid[0])
        ok, X0, Q, fx0 = ok[good], X0[:, good], Q[:, good], fx0[:, good]
        if given:
            return {given: list(ok)}, rho
        rho[ok] = spectral_radius(lambda x, t: fm(x, t, Q), X0, grid[0], fx0)
        stiff = [is_stiff(r, grid[0], grid[-1]) for r in rho[ok]]
        return {"cvodes": [k for k, s in zip(ok, stiff) if s],
                "adams": [k for k, s in zip(ok, stiff) if not s]}, rho

    def integrator(self, solver: str, extra: dict | None = None) -> ca.Function:
        s = self.settings
        plugin, opts, _ = integrator_settings(self.model, solver, s["rtol"], s["atol"],
                                              s["max_step"])
        opts.update(extra or {})
        opts.update(s["options"] or {})
        dae = integrator_problem(self.model, solver, self.ode, self.alg, self.q)
        try:
            return ca.integrator("sweep", plugin, dae, float(self.grid[0]),
                                 [float(tt) for tt in self.grid[1:]], opts)
        except RuntimeError as e:                    # an option the plugin does not know
            raise SimulationError(failure_message(self.model, e, self.grid[0], self.grid[-1],
                                                  s["rtol"], s["atol"])) from None

    def run(self, variables):
        model, grid = self.model, self.grid
        n, nt, nx = len(self.table), grid.size, model.x.numel()
        nw = self.W0.shape[0]
        W = np.full((nw, n, nt), np.nan)
        ok = np.array([k for k in range(n) if k not in self.failed], dtype=int)
        groups, rho = self._solvers(ok) if ok.size else ({}, None)
        auto = self.settings["solver"] is None
        errors, suppressed = {}, []      # runs whose algebraic variables IDAS did not test
        for solver, runs in groups.items():
            if not runs:
                continue
            extra = {}
            if auto and solver == "adams":   # too much work: BDF takes over, as in simulate
                extra["max_num_steps"] = max(adams_step_budget(r, float(np.max(np.diff(grid))))
                                             for r in rho[runs])
            failed = self._integrate(self.integrator(solver, extra), runs, W)
            self.solvers[runs] = solver
            if solver == "idas" and (self.settings["options"] or {}).get("suppress_algebraic"):
                suppressed += [k for k in runs if k not in failed]
            retry = self._retry(solver, auto)
            if failed and retry:
                self.solvers[sorted(failed)] = retry[0]
                again = self._integrate(self.integrator(*retry), sorted(failed), W)
                if retry[1].get("suppress_algebraic"):
                    suppressed += [k for k in failed if k not in again]
                failed = again
            errors.update(failed)
        if suppressed and nw > nx and not model.has_loops:
            self._algebraics_again(W, np.array(sorted(suppressed)))
        s = self.settings
        for k, text in errors.items():
            self.failed[k] = failure_message(model, RuntimeError(text), grid[0], grid[-1],
                                             s["rtol"], s["atol"])
        X, Z = W[:nx].reshape(nx, n * nt), W[nx:].reshape(nw - nx, n * nt)
        T = np.tile(grid, n)                        # every run side by side
        U = np.array(self.u_of.map(n * nt)(T[None, :], np.repeat(self.U, nt, axis=1)),
                     dtype=float) if model.u.numel() else np.zeros((0, n * nt))
        P = np.repeat(self.P, nt, axis=1)
        H = assertions.held(model, T, X, Z, U, P)
        for k in ok if H is not None else ():     # a run whose assertion fails: failed too
            failure = None if k in self.failed else first_failed_assertion(
                H[:, k * nt:(k + 1) * nt], grid, model.assertion_texts)
            if failure is not None:
                self.failed[k] = failure[1]
        failed = sorted(self.failed)
        values = _values(model, variables, T, X, Z, U, P)
        values = {name: v.reshape(n, nt).copy() for name, v in values.items()}
        for v in values.values():
            v[failed] = np.nan
        self.solvers[failed] = ""
        return values, {k: self.failed[k] for k in failed}, list(self.solvers)

    def _algebraics_again(self, W: np.ndarray, runs: np.ndarray) -> None:
        """The algebraic variables of ``runs`` in W solved again from their states at every
        output time, as simulate() does (``ModeIteration.consistent_along``)."""
        model, nx = self.model, self.model.x.numel()
        for k in runs:
            u = ca.Function("u", [model.t], [self.u_of(model.t, self.U[:, k])])
            W[nx:, k, :] = ModeIteration(model, self.P[:, k], u).consistent_along(
                self.grid, W[:nx, k, :], W[nx:, k, :], np.zeros(0))

    def _retry(self, solver: str, auto: bool):
        """(solver, options) for the runs that failed, as simulate() retries them: Adams
        chosen automatically → 'cvodes'; IDAS → with suppress_algebraic; or None."""
        if auto and solver == "adams":
            return "cvodes", {}
        if solver == "idas" and "suppress_algebraic" not in (self.settings["options"] or {}):
            return "idas", {"suppress_algebraic": True}
        return None

    def _integrate(self, F: ca.Function, runs: list[int], W: np.ndarray) -> dict[int, str]:
        """Runs ``runs`` through integrator F in chunks, their trajectories into W
        (scaled back); the errors of the runs that failed, by run index."""
        nx, nw, nt = self.model.x.numel(), self.W0.shape[0], self.grid.size
        runs = np.asarray(runs, dtype=int)
        W0 = self.W0[:, runs] / self.N[:, runs]
        X0, Z0, Q = W0[:nx], W0[nx:], self.Q[:, runs]
        workers = sum(self.client.nthreads().values()) if self.client else self.threads
        count = math.ceil(runs.size / self.chunk) if self.chunk else min(runs.size,
                                                                           2 * workers)
        bounds = np.linspace(0, runs.size, count + 1).round().astype(int)   # equal sizes
        pieces = [slice(a, b) for a, b in zip(bounds, bounds[1:])]
        if self.client is None:
            out = [integrate_chunk(F, X0[:, c], Z0[:, c], Q[:, c], self.threads)
                   for c in pieces]
        else:
            shipped = self.client.scatter(F.serialize(), broadcast=True)  # once per worker
            futures = [self.client.submit(integrate_chunk, shipped, X0[:, c], Z0[:, c],
                                          Q[:, c], 1, False, pure=False) for c in pieces]
            out = self.client.gather(futures)
        errors = {}
        for c, (XF, ZF, failed) in zip(pieces, out):
            ks = runs[c]
            m = ks.size
            W[:, ks, 0] = W0[:, c]
            W[:nx, ks, 1:] = XF.reshape(nx, m, nt - 1)
            W[nx:, ks, 1:] = ZF.reshape(nw - nx, m, nt - 1)
            W[:, ks, :] *= self.N[:, ks][:, :, None]
            errors.update((int(ks[j]), text) for j, text in failed.items())
        return errors


def _values(model, names, T, X, Z, U, P) -> dict[str, np.ndarray]:
    """The variables ``names`` at the points (columns) T, X, Z, U, P: states, algebraic
    variables, inputs and parameters as they are, the others by one Function of just
    them."""
    rows = {"state": X, "algebraic": Z, "input": U, "parameter": P}
    out, built = {}, []
    for name in names:
        kind, i = model.locate(name)
        if kind == "time":
            out[name] = T
        elif kind in rows:
            out[name] = rows[kind][i]
        else:
            built.append(name)
    if built:
        f = model.function("values", [ca.vertcat(*[model.expression(n) for n in built])])
        V = np.array(f.map(T.size)(T[None, :], X, Z, U, P), dtype=float)
        out.update(zip(built, V.reshape(len(built), T.size)))
    return out


_DESERIALIZED: dict[int, ca.Function] = {}     # a worker's integrators, by serialization
_MAPS: dict[tuple, tuple] = {}                 # mapped integrators by (id, runs, threads)


def _mapped(F: ca.Function, n: int, threads: int) -> ca.Function:
    """F mapped over n runs on threads (its construction grows with n: kept for the next
    chunk of that size, the last few only)."""
    key = (id(F), n, threads)
    if key not in _MAPS:
        if len(_MAPS) >= 8:
            _MAPS.pop(next(iter(_MAPS)))
        _MAPS[key] = (F, F.map(n, "thread", threads))    # F held: its id stays its own
    return _MAPS[key][1]


def integrate_chunk(integrator, X0: np.ndarray, Z0: np.ndarray, Q: np.ndarray,
                    threads: int = 1, quiet: bool = True):
    """(XF, ZF, errors) of the runs in the columns of X0, Z0, Q through ``integrator`` (a
    CasADi integrator on an output grid, or its serialization, deserialized once per
    process), mapped on ``threads`` threads: XF, ZF with the runs' output grids side by
    side (NaN for a run that failed), ``errors`` {column: the integrator's message}. The
    task of a sweep on a cluster."""
    if isinstance(integrator, str):
        key = hash(integrator)
        if key not in _DESERIALIZED:
            if len(_DESERIALIZED) >= 4:                  # the last few sweeps' only
                _DESERIALIZED.pop(next(iter(_DESERIALIZED)))
            _DESERIALIZED[key] = ca.Function.deserialize(integrator)
        integrator = _DESERIALIZED[key]
    n = X0.shape[1]
    args = dict(x0=X0, p=Q)
    if Z0.size:
        args["z0"] = Z0
    with quiet_stderr() if quiet else nullcontext():
        try:
            sol = _mapped(integrator, n, threads)(**args)
            return sol["xf"].full(), sol["zf"].full(), {}
        except RuntimeError:
            pass                                   # which run failed, and why: one by one
        XF, ZF, errors = [], [], {}
        for k in range(n):
            try:
                sol = integrator(**{a: v[:, k] for a, v in args.items()})
                XF.append(np.array(sol["xf"]))
                ZF.append(np.array(sol["zf"]))
            except RuntimeError as e:
                errors[k] = str(e)
                XF.append(np.full(integrator.size_out("xf"), np.nan))
                ZF.append(np.full(integrator.size_out("zf"), np.nan))
    return np.hstack(XF), np.hstack(ZF), errors


class _cluster:
    """The dask Client to run on: ``client``; a LocalCluster of ``workers`` processes for
    ``cluster="local"`` (closed on exit); None (this process)."""

    def __init__(self, client, cluster, workers):
        if cluster not in (None, "local"):
            raise SimulationError(f"cluster must be None or 'local', got {cluster!r}; for "
                                  f"another cluster pass client=Client(<scheduler address>)")
        self.client, self.local, self.workers, self.own = client, cluster == "local", \
            workers, None

    def __enter__(self):
        if self.client is not None or not self.local:
            return self.client
        try:
            from distributed import Client, LocalCluster
        except ImportError:
            raise SimulationError("cluster='local' needs dask.distributed: pip install "
                                  "'acausal[sweep]'") from None
        cluster = LocalCluster(n_workers=self.workers, threads_per_worker=1, processes=True,
                               dashboard_address=":0")
        self.own = (Client(cluster), cluster)
        return self.own[0]

    def __exit__(self, *exc):
        if self.own:
            self.own[0].close()
            self.own[1].close()


# ---- the loop of simulate() ---------------------------------------------------------------
def _simulate_loop(model, grid, table, variables, settings):
    """Each run through simulate(), the values on the grid (see ``sweep``)."""
    values = {name: np.full((len(table), grid.size), np.nan) for name in variables}
    failed, solvers = {}, [""] * len(table)
    for k, run in enumerate(table):
        try:
            res = simulate(model, grid[-1], t=grid, params=run["params"], x0=run["x0"],
                           inputs=run["inputs"], **settings)
        except AcausalError as e:
            failed[k] = str(e)
            continue
        at = np.searchsorted(res.t, grid, side="right") - 1   # after an event at a grid time
        inside = grid <= res.t[-1]
        for name in variables:
            values[name][k, inside] = res[name][at[inside]]
        solvers[k] = res.solver
    return values, failed, solvers


# ---- the result -----------------------------------------------------------------------------
def _dataset(grid, table, variables, values, failed, solvers):
    try:
        import xarray as xr
    except ImportError:
        raise SimulationError("sweep() returns an xarray Dataset: pip install "
                              "'acausal[sweep]'") from None
    n = len(table)
    coords = {"run": np.arange(n), "time": grid,
              "failed": ("run", np.array([k in failed for k in range(n)])),
              "solver": ("run", np.array(solvers, dtype=str))}
    for (kind, name), vals in _varied(table).items():
        label = f"{name}(0)" if kind == "x0" else name
        if label in variables or any(np.ndim(v) for v in vals):
            continue          # recorded anyway, or an array per run: in the runs' table
        coords[label] = ("run", np.array([np.nan if v is None else float(v) for v in vals]))
    data = {name: (("run", "time"), values[name]) for name in variables}
    ds = xr.Dataset(data, coords=coords)
    ds.attrs["failed_runs"] = list(failed)
    return ds
