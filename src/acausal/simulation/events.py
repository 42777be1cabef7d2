"""State events and discrete modes: integration from event to event.

CasADi's own event support (3.8: a ``zero`` expression with a ``transition`` Function) fires
in one direction only with CVODES and not at all with IDAS (casadi/casadi#4393), so events
are located here, over CasADi's integrators, for ODEs (CVODES) and DAEs (IDAS) alike:

1. between events the model is integrated with the modes d as the integrator's parameters,
   its outputs at the output grid and at checks between (``CHECKS`` per output interval, at
   least ``CHECKS_PER_RUN`` in all), where every indicator's sign is checked (a pair of
   crossings closer than that is not seen); after an event over a window of checks (twice
   the last gap between events, at least ``FIRST_WINDOW``), integrated again from the
   event over twice as many while none happens (up to ``MAX_WINDOW``, then continued from
   the window's end): little is integrated past the next event and thrown away, and the
   integrator is seldom restarted between events (a restart costs accuracy);
2. a sign change between two checks is located by re-integrating from the earlier check
   (one integrator on the normalized time τ ∈ [0, 1], the duration a parameter, built once),
   secant steps (Illinois: an end kept twice in a row has its value halved, so that both
   ends close in) safeguarded by bisection, until the bracket is shorter than
   ``EVENT_TOL``·max(1, |t|); every indicator that changed sign over that last bracket crossed
   at the event (simultaneous events), the bracket's end is the event's left limit;
3. at the event instant: the reinits of the crossed indicators (in their direction, their
   values at the left limit; a reinit of a velocity comes with the reinits of the
   velocities that follow it, so that the states a Modelica tool keeps keep their values:
   ``PhysicsBuilder.reinit``), then the event iteration on the reinitialized states: all
   modes updated together from the present ones, the algebraic variables solved in between,
   until no mode changes (``MAX_ITERATIONS``; MSL's friction mode machine); in closed loops
   the states are projected onto the loop constraints and their rates (the reinitialized
   ones held); the integrator restarts from there, the right limit; where the algebraic
   equations are singular but consistent there (statically indeterminate: two friction
   elements stuck on one shaft), the indeterminate combinations of the algebraic variables
   are held at the least-norm values the iteration found until the next event;
4. time events (declared, input jumps) are restarts as without modes; the event iteration
   runs there and at the start too, so that the modes start consistent. At the instants of
   a sample trigger (``StructureBuilder.sample``, Modelica's ``sample(start, period)``) the
   trigger is true through the event iteration, so sampled values (discrete Real
   variables, never rounded) take their new values and a chain of them settles; then the
   iteration runs once more with the trigger false. Time events closer than the event
   tolerance are one instant (sample instants of two rates, 3·0.1 and 0.3).

A component's termination condition (``PhysicsBuilder.terminate``, MSL's
TerminateSimulation) is checked at the right limit of every event (not the start): once it
holds, the run ends there (``terminated``: when, whose, why), the output grid after it left
out.

A crossing that can change nothing (a model without modes, no reinit of that indicator in
that direction: a ball leaving the floor) is no event: not located, not logged.
``CHATTER_EVENTS`` state events within ``CHATTER_SPAN`` of the simulated time is chattering:
a SimulationError naming the component whose indicators fired the most. Every event is
logged (``Result.events``), and the left and right limits at an event are both kept in the
Result (its time appears twice).
"""
from __future__ import annotations

from collections import deque
from contextlib import nullcontext

import casadi as ca
import numpy as np

from ..compiler.compiled import ARGS
from ..errors import SimulationError
from ..numerics import event_times, just_before, short_error
from . import buffers
from .diagnosis import blow_up, quiet_stderr, solver_account
from .initialization import model_equations
from .result import Event, Termination

CHECKS = 4                 # indicator checks per output interval, and at least
CHECKS_PER_RUN = 2000      # this many over the simulated time (coarse output grids)
EVENT_TOL = 1e-12          # event location: the bracket's width over max(1, |t|) [s]
SINGULAR = 1e-10           # relative singular value below which a Jacobian is singular
MAX_ITERATIONS = 50        # event iteration: rounds of mode updates at one instant
FIRST_WINDOW = 2 * CHECKS  # checks integrated at once after an event (at least) ...
MAX_WINDOW = 512           # ... doubled while none happens, up to this many
CHATTER_EVENTS = 100       # this many state events ...
CHATTER_SPAN = 1e-6        # ... within this fraction of the simulated time: chattering


def instant(t: float) -> float:
    """How close two time events are to be one instant: the event location's tolerance
    (sample instants k·period of two sample rates differ by rounding: 3·0.1 vs 0.3)."""
    return EVENT_TOL * max(1.0, abs(t))


def instants(times) -> list[float]:
    """The distinct instants of ``times``, sorted: times closer than ``instant`` merged (the
    first kept)."""
    out: list[float] = []
    for t in sorted(set(times)):
        if not out or t - out[-1] > instant(t):
            out.append(float(t))
    return out


def null_space(J: np.ndarray) -> np.ndarray:
    """The rows spanning the null space of J (none at full column rank); singular values
    below SINGULAR of the largest (at least 1) count as 0. The singular values alone tell a
    full column rank (the common case, at every event), at a fraction of the full SVD."""
    def rank(sv):
        return int(np.sum(sv > SINGULAR * max(sv.max(initial=0.0), 1.0)))
    if rank(np.linalg.svd(J, compute_uv=False)) == J.shape[1]:
        return np.zeros((0, J.shape[1]))
    sv, vt = np.linalg.svd(J)[1:]
    return vt[rank(sv):]


def solved(r: np.ndarray, rows: np.ndarray, z: np.ndarray) -> bool:
    """Whether the residuals ``r`` of the algebraic equations are 0 to round-off on
    ``rows`` (a mask of r's shape, or of its rows), for the algebraic variables ``z``."""
    return np.max(np.abs(r[rows]), initial=0.0) <= 1e-12 * (1 + np.abs(z).max(initial=0.0))


def side(g: np.ndarray, before: np.ndarray) -> np.ndarray:
    """The sign of each indicator; where it is exactly 0, the side it was on ``before``."""
    s = np.sign(g)
    return np.where(s == 0, before, s)


class ModeIteration:
    """The event iteration of ``model`` at a point, with parameters p (modes last, as
    ``mode_params`` places them) and inputs ``u`` (a callable of time; a CasADi Function of
    time where values along many times are needed, ``consistent_along``): what simulate runs
    at the start and at every event, what the analyses run to find the modes at an operating
    point, and how simulate and sweep solve the algebraic variables at the output times."""

    def __init__(self, model, p, u):
        self.model, self.p, self.u = model, np.asarray(p, dtype=float), u
        self._maps = {}       # Functions mapped over n points, by (kind, n)
        self.nx, self.has_alg = model.x.numel(), model.z.numel() > 0
        self.loops = model.has_loops
        if self.loops:
            rows = model_equations(model)[0][1]                  # Φ̇ along the motion
            self.speeds = model.function("speeds", [rows, ca.jacobian(rows, model.x)])
        self.update = model.event_update_function
        self.mode_names = [v.name for v in model.modes]
        self.mode_owner = [v.component for v in model.modes]
        self.allowed = model.state_events.mode_values
        real = set(model.state_events.real_modes)
        self.integer = np.array([n not in real for n in self.mode_names], dtype=bool)
        if self.has_alg:
            if "newton" not in model._cache:         # once per model (a sweep makes many)
                z, alg_full = model.z, model.alg
                model._cache["newton"] = (
                    model.function("newton", [alg_full, ca.jacobian(alg_full, z)]),
                    model.function("residual", [alg_full], ["r"]))
            self.newton, self.alg_function = model._cache["newton"]
            self.residual = buffers.Caller(self.alg_function, ARGS, ["r"])
            # the rows some algebraic variable may enter (a superset of those it enters)
            self.z_rows = np.diff(self.newton.sparsity_out(1).T.colind()) > 0

    # ---- evaluation at a point -----------------------------------------------------------
    def params(self, d) -> np.ndarray:
        p = self.p.copy()
        p[self.model.mode_params] = d
        return p

    def point(self, t, x, z, d):
        """The arguments (t, x, z, u, p) of the seam's Functions."""
        u = np.array(self.u(t), dtype=float).ravel() if self.model.u.numel() else np.zeros(0)
        return t, x, z, u, self.params(d)

    def consistent(self, t, x, z, d, held: dict):
        """(x, z) consistent at t with modes d: in closed loops the speeds moved the least
        onto the loop velocity constraints Φ̇ = 0, the positions and the ``held`` states
        (reinitialized ones, name -> value) kept, and the loops' multipliers 0 (their value
        on the exact solution); the algebraic variables solving alg = 0 (Newton from z)."""
        if self.loops:
            x = np.array(x, dtype=float)
            keep = set(self.model.position_states) | {self.model.x_names.index(n) for n in held}
            free = [k for k in range(self.nx) if k not in keep]
            r, J = (np.array(v, dtype=float) for v in self.speeds(*self.point(t, x, z, d)))
            x[free] -= np.linalg.lstsq(J[:, free], r.ravel(), rcond=None)[0]
            z = np.array(z, dtype=float)
            z[self.model.loop_multipliers] = 0.0
        return x, self.consistent_z(t, x, z, d)

    def consistent_z(self, t, x, z, d) -> np.ndarray:
        """The algebraic variables solving alg = 0 at (t, x) with modes d (Newton from z;
        the rows no algebraic variable enters, a closed loop's Φ = 0 and Φ̇ = 0, are the
        states' business; the residuals checked alone first, as ``consistent_along``)."""
        if not self.has_alg:
            return z
        z = np.array(z, dtype=float)
        for _ in range(50):
            point = self.point(t, x, z, d)
            if solved(self.residual(*point)[0].ravel(), self.z_rows, z):
                return z
            r, J = self.newton(*point)
            r, J = np.array(r, dtype=float).ravel(), np.array(J, dtype=float)
            rows = np.any(J != 0, axis=1)
            if solved(r, rows, z):
                return z
            z = z - np.linalg.lstsq(J[rows], r[rows], rcond=None)[0]
        raise SimulationError(f"the algebraic equations of '{self.model.name}' have no "
                              f"solution at t = {t:g} s with the modes "
                              f"{self._modes(d)}: check the equations the "
                              f"components give for these modes")

    def consistent_along(self, times, X, Z, d) -> np.ndarray:
        """``consistent_z`` at each of ``times`` (columns of X, Z), all at once (one mapped
        Newton step per round; a row no algebraic variable enters left out, a singular
        system by least squares). Each round first checks the residuals alone (cheaper than
        with the Jacobian): small on every row an algebraic variable may enter, converged."""
        n, nz = len(times), Z.shape[0]
        if ("newton", n) not in self._maps:
            F = self.newton.map(n)
            i, j = F.sparsity_out(1).get_triplet()                   # J: nz x (n·nz)
            self._maps["newton", n] = F, (np.array(j) // nz, np.array(i), np.array(j) % nz)
            self._maps["residual", n] = buffers.Caller(self.alg_function.map(n), ARGS, ["r"])
        F, at = self._maps["newton", n]
        T = np.asarray(times, dtype=float).reshape(1, -1)
        U, P = self.inputs_along(T), self.params(d)
        Ps = np.tile(P[:, None], (1, n))
        Z = np.array(Z, dtype=float)
        for _ in range(50):
            if solved(self._maps["residual", n](T, X, Z, U, Ps)[0], self.z_rows, Z):
                return Z
            r, Jv = F(T, X, Z, U, P)
            r = r.full()
            J = np.zeros((n, nz, nz))                                 # one per column
            J[at] = np.array(Jv.nonzeros())
            rows = np.any(J != 0, axis=2).T                           # (nz, n)
            if solved(r, rows, Z):
                return Z
            R = np.where(rows, r, 0.0).T[..., None]                   # (n, nz, 1)
            try:
                step = np.linalg.solve(J + ~rows.T[..., None] * np.eye(nz), R)
            except np.linalg.LinAlgError:                             # indeterminate
                step = np.linalg.pinv(J) @ R
            Z = Z - step[..., 0].T
        for k in range(n):          # one by one: what converges slowly, or the error
            Z[:, k] = self.consistent_z(times[k], X[:, k], Z[:, k], d)
        return Z

    def inputs_along(self, T: np.ndarray) -> np.ndarray:
        """The inputs at each of the times T (a row), one column each."""
        n = T.shape[1]
        if not self.model.u.numel():
            return np.zeros((0, n))
        if ("u", n) not in self._maps:
            self._maps["u", n] = self.u.map(n)
        return np.array(self._maps["u", n](T), dtype=float)

    def iterate(self, t, x, z, d, held: dict, keep=()):
        """The event iteration at (t, x): every mode updated from the present ones, the
        algebraic variables solved for them (``consistent``, ``held`` states kept), until no
        mode changes: (x, z, d). ``keep``: positions in d of modes held at their value."""
        keep = list(keep)
        seen = [tuple(d)]
        for _ in range(MAX_ITERATIONS):
            x, z = self.consistent(t, x, z, d, held)
            nxt = np.array(self.update(*self.point(t, x, z, d))[0], dtype=float).ravel()
            nxt[self.integer] = np.round(nxt[self.integer])
            nxt[keep] = d[keep]
            if np.array_equal(nxt, d):
                self._check_values(t, d)
                return x, z, d
            d = nxt
            seen.append(tuple(d))
        moving = {self.mode_owner[k] for k in range(len(d)) if len({s[k] for s in seen}) > 1}
        raise SimulationError(
            f"event iteration at t = {t:g} s does not settle: the modes of "
            f"{', '.join(sorted(moving))} keep changing ({MAX_ITERATIONS} rounds: "
            f"{' -> '.join(str(s) for s in seen[-4:])}); check their mode_update for a cycle")

    def _modes(self, d) -> dict:
        return {n: float(v) for n, v in zip(self.mode_names, d)}

    def _check_values(self, t, d):
        for name, v, owner in zip(self.mode_names, d, self.mode_owner):
            allowed = self.allowed.get(name)
            if allowed is not None and int(v) not in allowed:
                raise SimulationError(f"at t = {t:g} s the mode_update of '{owner}' gives "
                                      f"{name} = {v:g}, not one of its values {allowed}")


class EventSimulation(ModeIteration):
    """Integration of ``model`` (an ODE/DAE whose ``ode``/``alg`` are scaled by ``scale``
    and have the modes as free symbols, every other parameter a number) with its events."""

    def __init__(self, model, ode, alg, p, u_expr, scale, plugin, opts):
        super().__init__(model, p, ca.Function("u", [model.t], [u_expr]))
        self.plugin, self.opts = plugin, dict(opts)
        if self.has_alg:
            # the integrator restarts at every event with z consistent but not its rate:
            # the algebraic variables (index 1: functions of x) stay out of the error test;
            # the start is consistent (``consistent``), so IDAS's own initial-value search
            # is replaced by the known derivatives (it fails on a start that is consistent
            # already, e.g. every friction element stuck: IDA_LINESEARCH_FAIL)
            self.opts.setdefault("suppress_algebraic", True)
            self.opts["calc_ic"] = False
        self.Nx, self.Nz = scale[:self.nx], scale[self.nx:]
        d = model.p[model.mode_params] if model.mode_params else ca.SX(0, 1)
        self.ode, self.alg, self.d = ode, alg, d
        # no states (signals only, or algebraic variables of time: a diode among resistors):
        # nothing to integrate, the algebraic variables solved by Newton's method at each time
        self.static = self.nx == 0
        if self.has_alg:    # IDAS is given consistent derivatives at each start
            self.xdot = ca.Function("xdot", [model.x, model.z, model.t, d], [ode])
            self.alg_jacobian = ca.Function("alg_jacobian", [model.x, model.z, model.t, d],
                                            [ca.jacobian(alg, model.z),
                                             ca.jacobian(ode, model.z)])
        self.regular = self._integrators(alg)
        self.dae, self.step = self.regular
        self.g = model.indicator_function
        self.g_call = buffers.Caller(self.g, ARGS, ["g"])
        self.reinits = model.state_events.reinits
        self.owner = [v.component for v in model.state_events.indicators]
        self.names = [v.name for v in model.state_events.indicators]
        self.clocks = list(model.state_events.clocks)
        self.terminations = model.state_events.terminations
        if self.terminations:
            self.terminate = model.function("terminate", [model.state_events.terminate])
        self.terminated: Termination | None = None
        self.ticks: list[np.ndarray] = []     # the instants of each sample trigger (run)
        self.log: list[Event] = []
        self.cols: list = []                  # the columns of ``run`` so far
        self.checks_per_run = CHECKS_PER_RUN  # indicator checks over a run, at least
        self.reached = lambda t: None         # called with the time integrated to

    def _integrators(self, alg):
        """(the DAE with algebraic equations ``alg``, a Function (t, x, z, p, u) -> (ode,
        alg, quad, zero) that every integrator between events is built on: its derivatives
        built once, not per integrator; the integrator over a normalized interval
        [t0, t0 + h] built on it once: what locating an event re-integrates)."""
        model, d, none = self.model, self.d, ca.SX(0, 1)
        dae = ca.Function("dae", [model.t, model.x, model.z, d, none],
                          [self.ode, alg if self.has_alg else none, none, none],
                          ca.dyn_in(), ca.dyn_out())
        if self.loops or self.static:
            return dae, None
        t0, h, tau = ca.SX.sym("t0"), ca.SX.sym("h"), ca.SX.sym("tau")
        at = model.t, t0 + h * tau
        scaled = {"x": model.x, "t": tau, "p": ca.vertcat(t0, h, d),
                  "ode": h * ca.substitute(self.ode, *at)}
        if self.has_alg:
            scaled.update(z=model.z, alg=ca.substitute(alg, *at))
        local = {k: v for k, v in self.opts.items() if k not in ("max_step_size", "calc_ic")}
        step = ca.integrator("locate", self.plugin, scaled, 0.0, [1.0], local)
        return dae, buffers.Caller(step, ["x0", "z0", "p"], ["xf", "zf"])

    def _prepare(self, t, x, z, d):
        """The DAE of the stretch that starts at (t, x, z) with modes d: the model's, or,
        where its algebraic equations are singular there (statically indeterminate: two
        friction elements stuck on one rigid shaft share its holding torque in any
        proportion, MSL's LossyGearDemo2; a Modelica tool picks a split by pivoting), their
        independent rows and the indeterminate combinations of the algebraic variables held
        at their values there (the least-norm split the event iteration solved). Where such a
        combination drives the states (the model has no unique solution in these modes: an
        ideal diode with Goff = 0 blocking an inductor's current), a SimulationError."""
        self.dae, self.step = self.regular
        if not self.has_alg or self.loops:
            return
        xs, zs = x / self.Nx, z / self.Nz
        J, J_ode = (np.array(v, dtype=float) for v in self.alg_jacobian(xs, zs, t, d))
        held = null_space(J)                        # the indeterminate combinations
        if not len(held):
            return
        if np.abs(J_ode @ held.T).max() > SINGULAR * max(np.abs(J_ode).max(), 1.0):
            free = np.flatnonzero(np.abs(held).max(axis=0) > 1e-8)
            raise SimulationError(
                f"at t = {t:g} s, in the modes entered there, the algebraic equations do not "
                f"determine {', '.join(self.model.z_names[k] for k in free)}, and the states' "
                f"derivatives depend on it: the model has no unique solution in these modes "
                f"(e.g. an ideal diode or switch with Goff = 0 that blocks an inductor's "
                f"current); give the blocking element a conductance (Goff > 0, MSL's default "
                f"1e-5 S) or a resistor in parallel")
        rows, tol = [], SINGULAR * max(np.linalg.norm(J, 2), 1.0)
        for k in range(J.shape[0]):                 # the first independent rows
            if np.linalg.matrix_rank(J[rows + [k]], tol=tol) > len(rows):
                rows.append(k)
        alg = ca.vertcat(self.alg[rows, :], ca.mtimes(ca.DM(held), self.model.z - ca.DM(zs)))
        self.dae, self.step = self._integrators(alg)

    def indicators(self, t, x, z, d) -> np.ndarray:
        return self.g_call(*self.point(t, x, z, d))[0].ravel()

    def indicators_along(self, times, X, Z, d) -> np.ndarray:
        """The indicators at each of ``times`` (columns of X, Z), in one call."""
        n = len(times)
        if ("g", n) not in self._maps:
            self._maps["g", n] = buffers.Caller(self.g.map(n), ARGS, ["g"])
        T = np.asarray(times, dtype=float).reshape(1, -1)
        U = self.inputs_along(T)
        return self._maps["g", n](T, X, Z, U, np.tile(self.params(d)[:, None], (1, n)))[0]

    # ---- integration ---------------------------------------------------------------------
    def integrate(self, t0, times, x, z, d):
        """(x, z) at each of ``times`` (> t0) from (t0, x, z) with modes d, unscaled."""
        if self.static:
            X = np.zeros((0, len(times)))
            if not self.has_alg:
                return X, np.zeros((0, len(times)))
            return X, self.consistent_along(times, X, np.tile(np.reshape(z, (-1, 1)),
                                                              (1, len(times))), d)
        try:
            with solver_account():
                F = ca.integrator("segment", self.plugin, self.dae, float(t0), list(times),
                                  self._start_options(t0, x, z, d, times[-1]))
                xf, zf = buffers.call(F, {"x0": x / self.Nx, "z0": z / self.Nz, "p": d},
                                      ["xf", "zf"])
        except RuntimeError as e:
            why = blow_up(str(e))
            raise SimulationError(f"integration of '{self.model.name}' failed after "
                                  f"t = {t0:g} s with the modes "
                                  f"{self._modes(d)}: {short_error(e)}"
                                  f"{'. ' + why if why else ''}"
                                  f"{self._undetermined(t0, x, z, d)}") from None
        X = xf * self.Nx[:, None]
        if not self.has_alg:
            return X, np.zeros((0, len(times)))
        # out of the error test, z at an output time is IDAS's interpolant, far off where
        # the states stand still (a stuck friction element: long steps); solved at x instead
        Z = zf * self.Nz[:, None]
        return X, self.consistent_along(times, X, Z, d)

    def _start_options(self, t0, x, z, d, t1) -> dict:
        """The integrator's options; DAEs: with the derivatives at the start and a first
        step, as simulate() gives them for closed loops (IDAS's own initialization is off)."""
        if not self.has_alg:
            return self.opts
        xdot = np.array(self.xdot(x / self.Nx, z / self.Nz, t0, d), dtype=float).ravel()
        step0 = max(1e-6 * (t1 - t0), 1e-13 * max(1.0, abs(t0)))    # resolvable at t0
        return dict(self.opts, init_xdot=list(xdot), step0=step0)

    def state_at(self, t0, x, z, d, t):
        """(x, z) at t from (t0, x, z), by the normalized integrator (t − t0 may be tiny);
        closed loops, or where IDAS's own initial-value search fails on the consistent start
        (IDA_LINESEARCH_FAIL: the normalized integrator, built once, cannot be given the
        start's derivatives), by an integrator from t0 to t with them."""
        if self.loops or self.static:
            X, Z = self.integrate(t0, [t], x, z, d)
            return X[:, 0], Z[:, 0]
        args = (x / self.Nx, z / self.Nz, np.concatenate([[t0, t - t0], d]))
        try:
            with quiet_stderr() if self.has_alg else nullcontext():   # (IDAS prints why its
                xf, zf = self.step(*args)                             # initial search failed)
        except RuntimeError:
            if not self.has_alg:
                raise
            X, Z = self.integrate(t0, [t], x, z, d)
            return X[:, 0], Z[:, 0]
        return xf[:, 0] * self.Nx, zf[:, 0] * self.Nz if self.has_alg else z

    # ---- events --------------------------------------------------------------------------
    def locate(self, t0, x0, z0, d, sides, t1, x1, z1):
        """The first crossing in (t0, t1] (some indicator off its ``sides`` at t1, where the
        integration gave x1, z1): (t, x, z, indicators) at the bracket's end after it, the
        event's left limit."""
        lo_t, lo_g = t0, self.indicators(t0, x0, z0, d)
        hi_t, hi_x, hi_z = t1, x1, z1      # (the far end as the integration gave it)
        hi_g = self.indicators(t1, hi_x, hi_z, d)
        tol = EVENT_TOL * max(1.0, abs(t1))
        widths = [hi_t - lo_t]
        weight = {"lo": 1.0, "hi": 1.0}    # Illinois: the end kept twice counts half as much
        moved = None
        while hi_t - lo_t > tol:
            crossed = side(hi_g, sides) != sides
            slow = len(widths) > 3 and widths[-1] > 0.5 * widths[-4]
            if slow:
                t = 0.5 * (lo_t + hi_t)
            else:                          # the earliest secant estimate among the crossed
                a, b = weight["lo"] * lo_g[crossed], weight["hi"] * hi_g[crossed]
                frac = np.min(np.clip(a / np.where(a == b, 1.0, a - b), 0.0, 1.0))
                t = lo_t + frac * (hi_t - lo_t)
            t = min(max(t, lo_t + 0.25 * tol), hi_t - 0.25 * tol)
            x, z = self.state_at(t0, x0, z0, d, t)
            g = self.indicators(t, x, z, d)
            end = "hi" if np.any(side(g, sides) != sides) else "lo"
            if end == "hi":
                hi_t, hi_x, hi_z, hi_g = t, x, z, g
            else:
                lo_t, lo_g = t, g
            kept = "lo" if end == "hi" else "hi"
            weight[end] = 1.0
            weight[kept] *= 0.5 if moved == end else 1.0
            moved = end
            widths.append(hi_t - lo_t)
        return hi_t, hi_x, hi_z, hi_g

    def event(self, t, x, z, d, crossed: dict):
        """The event at t from the left limit (x, z, d): the reinits of the ``crossed``
        indicators (index -> direction), their values at the left limit, then the event
        iteration on the reinitialized states (a friction element's velocity, set to 0 when
        it sticks, is 0 for its mode machine). Returns the right limit (x, z, d) and logs the
        event."""
        values = np.array(self.update(*self.point(t, x, z, d))[1], dtype=float).ravel()
        x_new = np.array(x, dtype=float)
        reinit = {}
        for j, r in enumerate(self.reinits):
            if r.indicator in crossed and r.direction in (0, crossed[r.indicator]):
                reinit[self.model.x_names[r.state]] = (float(x_new[r.state]), float(values[j]))
                x_new[r.state] = values[j]
        held = {name: after for name, (_, after) in reinit.items()}
        d = np.array(d, dtype=float)
        ticking = [c for c, ticks in zip(self.clocks, self.ticks)
                   if np.any(np.abs(ticks - t) <= instant(t))]
        d_new = d.copy()
        d_new[ticking] = 1.0
        x_new, z, d_new = self.iterate(t, x_new, z, d_new, held)
        if ticking:         # once more without the triggers: what follows them settles back
            d_new[ticking] = 0.0
            x_new, z, d_new = self.iterate(t, x_new, z, d_new, held)
        changed = {n: (float(a), float(b)) for n, a, b in zip(self.mode_names, d, d_new)
                   if a != b}
        for k, direction in crossed.items():
            self.log.append(Event(float(t), self.owner[k], self.names[k], direction, changed,
                                  reinit))
        if not crossed and (changed or reinit):
            owners = sorted({self.mode_owner[self.mode_names.index(n)] for n in changed})
            self.log.append(Event(float(t), ", ".join(owners), "", 0, changed, reinit))
        self._prepare(t, x_new, z, d_new)
        return x_new, z, d_new

    def _first_event(self, G, sides):
        """(the first column of the indicators G off ``sides`` that is an event, or None;
        the sides just before it, inert crossings taken)."""
        first = 0
        while first < G.shape[1]:
            S = side(G[:, first:], sides[:, None])
            off = np.flatnonzero(np.any(S != sides[:, None], axis=0))
            if not off.size:
                break
            i, new = first + off[0], S[:, off[0]]
            if not self._inert(new, sides):
                return i, sides
            sides, first = new, i + 1
        return None, sides

    def _inert(self, new, sides) -> bool:
        """Whether crossings from ``sides`` to ``new`` change nothing, and so are no event: no
        modes in the model, no condition that may end the run, and no reinit of these
        indicators in these directions (a ball leaving the floor)."""
        if self.mode_names or self.terminations:
            return False
        crossed = {k: new[k] for k in np.flatnonzero(new != sides)}
        return not any(r.indicator in crossed and r.direction in (0, crossed[r.indicator])
                       for r in self.reinits)

    def _undetermined(self, t, x, z, d) -> str:
        """Why the algebraic equations may be singular at (t, x, z): the algebraic variables
        they leave free (their Jacobian's null space), or '' if none."""
        if not self.has_alg:
            return ""
        J = np.array(self.newton(*self.point(t, x, z, d))[1], dtype=float)
        free = np.abs(null_space(J[np.any(J != 0, axis=1)])).max(axis=0, initial=0.0) > 1e-8
        names = [self.model.z_names[k] for k in np.flatnonzero(free)]
        if not names:
            return ""
        return (f"; the equations leave {', '.join(names)} undetermined there and are not "
                f"consistent (check the equations the components give for these modes)")

    def run(self, grid, x, z, time_events, start: bool = True):
        """Integrate over ``grid`` from (x, z) at grid[0]: (T, X, Z, D) with the left and right
        limits at events (T repeats their time), D the modes per column. A time event or
        sample instant at the last time is processed there (its right limit the last
        column, as a Modelica tool ends). ``start``: grid[0] is the simulation's start,
        where a sample trigger true initially ticks (a run that continues one, a stepper's
        next step, has processed the events at its start already)."""
        t, t1 = float(grid[0]), float(grid[-1])
        d = self.p[self.model.mode_params]
        self.ticks = self._clock_instants(t, t1, start)
        x, z, d = self.event(t, x, z, d, {})
        self.cols = cols = [(t, x, z, d)]
        sides = side(self.indicators(t, x, z, d), np.ones(len(self.names)))
        recent = deque(maxlen=CHATTER_EVENTS)
        span = CHATTER_SPAN * (grid[-1] - grid[0])
        stops = [s for s in instants(time_events) if t1 - s > instant(t1)]
        stops.append(t1)
        at_end = bool(self.model.event_times(self.p, t1 - instant(t1), t1 + instant(t1))) \
            or any(np.any(np.abs(ticks - t1) <= instant(t1)) for ticks in self.ticks)
        window = FIRST_WINDOW
        for stop in stops:
            end = stop if stop == t1 else just_before(stop)
            while t < end:
                times, output = _checks(grid, t, end, window, self.checks_per_run)
                X, Z = self.integrate(t, times, x, z, d)
                self.reached(times[-1])
                i, after = self._first_event(self.indicators_along(times, X, Z, d), sides)
                if i is None and times[-1] != end and window < MAX_WINDOW:
                    window *= 2         # again from t, further (no restart mid-way)
                    continue
                cols += [(times[k], X[:, k], Z[:, k], d)
                         for k in np.flatnonzero(output[:len(times) if i is None else i])]
                sides = after
                if i is None:
                    t, x, z = times[-1], X[:, -1], Z[:, -1]
                    continue
                window = max(FIRST_WINDOW, 2 * (i + 1))
                prev = (times[i - 1], X[:, i - 1], Z[:, i - 1]) if i else (t, x, z)
                te, xe, ze, ge = self.locate(*prev, d, sides, times[i], X[:, i], Z[:, i])
                new = side(ge, sides)
                crossed = {k: int(new[k]) for k in np.flatnonzero(new != sides)}
                cols.append((te, xe, ze, d))
                x, z, d = self.event(te, xe, ze, d, crossed)
                cols.append((te, x, z, d))
                t = te
                if self._ends(t, x, z, d):
                    return self._columns(cols)
                sides = side(self.indicators(t, x, z, d), new)
                recent.extend((te, k) for k in crossed)
                self._chattering(recent, span)
            if stop != t1 or at_end:           # a time event: restart at it
                t = stop
                g = self.indicators(t, x, z, d)
                new = side(g, sides)
                crossed = {k: int(new[k]) for k in np.flatnonzero(new != sides)}
                n_log = len(self.log)
                x1, z1, d1 = self.event(t, x, z, d, crossed)
                if len(self.log) > n_log and stop != t1:   # (at t1: the column integrated to)
                    cols.append((t, x, z, d))
                x, z, d = x1, z1, d1
                ends = self._ends(t, x, z, d)
                # an output time at the event, or just before it (to rounding, where the
                # integration towards the event stops short of it): the right limit there
                # (at t1, only if the event changed something: else the column integrated to
                # is the right limit already)
                on_grid = np.any((grid > t - instant(t)) & (grid <= t)) and stop != t1
                if on_grid or len(self.log) > n_log or ends:
                    cols.append((t, x, z, d))
                if ends:
                    return self._columns(cols)
                sides = side(self.indicators(t, x, z, d), new)
        return self._columns(cols)

    @staticmethod
    def _columns(cols):
        """(T, X, Z, D) of the columns (t, x, z, d) collected by ``run``."""
        T = np.array([c[0] for c in cols])
        return (T, *(np.column_stack([np.asarray(c[k], dtype=float).reshape(-1) for c in cols])
                     .reshape(-1, len(cols)) for k in (1, 2, 3)))

    def _ends(self, t, x, z, d) -> bool:
        """Whether a termination condition holds at the right limit of the event at t
        (then recorded in ``terminated``: the first such condition)."""
        if not self.terminations:
            return False
        held = np.array(self.terminate(*self.point(t, x, z, d)), dtype=float).ravel()
        hit = np.flatnonzero(held > 0.5)
        if hit.size:
            component, text = self.terminations[hit[0]]
            self.terminated = Termination(float(t), component, text)
        return bool(hit.size)

    def _clock_instants(self, t0: float, t1: float, start: bool) -> list[np.ndarray]:
        """The instants of each sample trigger: its time events in (t0, t1] (the same
        numbers as ``CompiledModel.event_times``), and t0 if ``start`` is the simulation's
        start and the trigger is true there (``initial``; otherwise the start is
        initialization, where Modelica's when-clauses are inactive, even at a sample
        instant)."""
        ev = self.model.state_events
        if not self.clocks:
            return []
        starts, periods = (np.array(v, dtype=float).ravel() for v in ev.clock_times(self.p))
        out = []
        for c, first, period, initial in zip(self.clocks, starts, periods, ev.clock_initial):
            if not period > 0:
                raise SimulationError(f"the sample period of '{self.mode_owner[c]}' must be "
                                      f"> 0 s, got {period:g}")
            ticks = event_times([first], [period], t0, t1 + instant(t1))
            out.append(np.array(ticks + [t0] if initial and start else ticks))
        return out

    def _chattering(self, recent: deque, span: float):
        if len(recent) < CHATTER_EVENTS or recent[-1][0] - recent[0][0] > span:
            return
        counts = {}
        for _, k in recent:
            counts[self.owner[k]] = counts.get(self.owner[k], 0) + 1
        worst = max(counts, key=counts.get)
        names = sorted({self.names[k] for _, k in recent if self.owner[k] == worst})
        raise SimulationError(
            f"chattering: {len(recent)} events within {recent[-1][0] - recent[0][0]:.3g} s "
            f"after t = {recent[0][0]:.9g} s, {counts[worst]} of them of component '{worst}' "
            f"(indicators {', '.join(names)}): its modes switch back and forth without end "
            f"(an ideal relay, a sliding mode, a Zeno accumulation of impacts); give it a mode "
            f"that holds at the switching surface (a stuck mode) or end the simulation before")


def _checks(grid, t, end, limit: int, per_run: int = CHECKS_PER_RUN):
    """The output times in (t, end], end itself, and checks between them: CHECKS per output
    interval, none further apart than 1/``per_run`` of the simulated time; the first
    ``limit`` of them, and whether each is an output time."""
    spacing = (grid[-1] - grid[0]) / per_run
    stops = grid[(grid > t) & (grid <= end)][:limit]
    output = np.ones(len(stops), dtype=bool)
    if not len(stops) or stops[-1] != end:
        stops, output = np.append(stops, end), np.append(output, False)
    starts = np.concatenate([[t], stops[:-1]])
    counts = np.maximum(CHECKS, np.ceil((stops - starts) / spacing).astype(int))
    rows = [None] * len(stops)
    for n in np.unique(counts):                  # the intervals of n checks, together
        k = np.flatnonzero(counts == n)
        block = starts[k, None] + (stops - starts)[k, None] * (np.arange(1, n + 1) / n)
        block[:, -1] = stops[k]
        for r, row in zip(k, block):
            rows[r] = row
    flags = np.zeros(int(counts.sum()), dtype=bool)
    flags[np.cumsum(counts) - 1] = output
    return np.concatenate(rows)[:limit], flags[:limit]
