"""A compiled model stepped sample by sample, for controllers written in Python.

``Stepper(model, dt, ...)`` (``compiled.stepper(dt, ...)``) holds the state of a simulation;
``step(u)`` integrates it over one sample period dt [s] with the inputs u held (zero-order
hold) and returns the chosen variables at the end of the step, by name. The integrator is
built once, with the inputs u and the parameters p as its arguments, and called per step
through a CasADi buffer (no conversion of arguments: a few microseconds per call):

- ODEs (solver 'dopri', the default): Dormand–Prince 5(4) steps inside the sample period,
  written out as one CasADi Function; the error of every step is estimated and held below
  ``atol·nominal + rtol·|x|`` per state: a step whose error exceeds it is taken again with
  twice as many substeps, and the number of substeps shrinks again when the error is far
  below (it is carried from sample to sample, as a variable-step solver carries its step).
  Stiff models need many substeps with an explicit method: give solver='cvodes' (BDF,
  restarted at every sample) then;
- DAEs (closed loops, massless nodes; solver 'collocation', the default for them): CasADi's
  fixed-step Radau IIA collocation (order 5 in x) with ``substeps`` finite elements per
  sample (a Newton solve per call: milliseconds per step); 'cvodes' / 'idas' (not for closed
  loops): CasADi's variable-step integrators to the tolerances, restarted at every sample;
- models with state events or modes (friction, impacts, sampled blocks): every step runs
  the event engine of ``simulate()`` (``acausal.simulation.events``: crossings located,
  modes iterated, reinits applied) over the sample period, its indicators checked
  ``EVENT_CHECKS`` times per step, the modes carried from step to step (milliseconds per
  step: its integrators are built per step); ``events`` is the log.
"""
from __future__ import annotations

from typing import Mapping, Sequence

import casadi as ca
import numpy as np

from ..errors import SimulationError
from . import assertions
from .buffers import Buffered
from .events import EventSimulation
from .initialization import initial_state
from .problem import check_finite, folded, integrator_settings, scaled

SOLVERS = ("dopri", "collocation", "cvodes", "idas")
MAX_SUBSTEPS = 2 ** 16      # a sample period split further than this: the model is stiff
EVENT_CHECKS = 16           # indicator checks per step of a model with events (two
#                             crossings closer than dt / EVENT_CHECKS are not seen)

# Dormand–Prince 5(4): nodes, stages, 5th-order weights (taken), 4th-order weights (error)
_C = (0.0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1.0, 1.0)
_A = ((), (1 / 5,), (3 / 40, 9 / 40), (44 / 45, -56 / 15, 32 / 9),
      (19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729),
      (9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656),
      (35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84))
_B5 = (35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84, 0.0)
_B4 = (5179 / 57600, 0.0, 7571 / 16695, 393 / 640, -92097 / 339200, 187 / 2100, 1 / 40)


def dopri_step(model, p: np.ndarray) -> ca.Function:
    """One Dormand–Prince 5(4) step of the ODE of ``model`` with the parameter values ``p``
    folded in (``problem.folded``), as a CasADi Function (x, u, t, h, tol_abs, rtol) ->
    (x after the step h [s] from t with inputs u held, the estimated error over its
    tolerance atol_i + rtol·|x_i|, max over the states: ≤ 1 to accept)."""
    x, u, t = model.x, model.u, model.t
    h, tol_abs, rtol = ca.SX.sym("h"), ca.SX.sym("tol_abs", x.numel()), ca.SX.sym("rtol")
    f = ca.Function("ode", [t, x, u], [folded(model, p)[0]])
    k = []
    for c, a in zip(_C, _A):
        xi = x
        for aj, kj in zip(a, k):
            if aj:
                xi = xi + (h * aj) * kj
        k.append(f(t + c * h, xi, u))
    x5 = x + h * sum((b * kj for b, kj in zip(_B5, k) if b), ca.SX.zeros(x.numel()))
    err = h * sum(((b5 - b4) * kj for b5, b4, kj in zip(_B5, _B4, k) if b5 != b4),
                  ca.SX.zeros(x.numel()))
    weight = tol_abs + rtol * ca.fmax(ca.fabs(x), ca.fabs(x5))
    return ca.Function("dopri_step", [x, u, t, h, tol_abs, rtol],
                       [x5, ca.mmax(ca.vertcat(0, ca.fabs(err) / weight))],
                       ["x", "u", "t", "h", "tol_abs", "rtol"], ["xf", "err"])


class Stepper:
    """A simulation of ``model`` advanced by ``step(u)``, one sample period ``dt`` [s] at a
    time, the inputs held over each step (see the module docstring).

    params   parameter overrides by dotted name (``reset(params=...)`` changes them: no
             recompiling, the integrator rebuilt in milliseconds); x0, guess: initial values
             as in ``simulate()``; t0: the start time [s];
    outputs  dotted names of the variables ``step`` returns (default: the model's Outputs,
             or its states if it has none);
    solver   'dopri' (ODEs), 'collocation' (DAEs), 'cvodes', 'idas' (see the module
             docstring); rtol, atol: tolerances (atol scaled by the states' nominals);
    substeps finite elements per sample period of 'collocation' (default 4), and the
             number of Dormand–Prince substeps to start with.

    ``t`` [s], ``state`` (the states by name; set it with a dict of some of them),
    ``x`` (the state vector in ``x_names`` order, settable), ``z`` (the algebraic
    variables), ``u`` (the held inputs; ``hold(u)`` sets them, ``advance(h)`` integrates
    over h [s]), ``p`` (the parameter vector), ``input_names``, ``output_names``,
    ``reset(x0=..., t0=..., params=...)``.
    """

    def __init__(self, model, dt: float, *, params: dict | None = None,
                 x0: dict | None = None, guess: dict | None = None,
                 outputs: Sequence[str] | None = None, solver: str | None = None,
                 rtol: float = 1e-8, atol: float = 1e-10, substeps: int | None = None,
                 t0: float = 0.0):
        if not (isinstance(dt, (int, float, np.floating)) and np.isfinite(dt) and dt > 0):
            raise SimulationError(f"the sample period dt must be a finite number > 0 s, "
                                  f"got {dt!r}")
        for name, v in (("rtol", rtol), ("atol", atol)):
            if not (np.isfinite(v) and v > 0):
                raise SimulationError(f"{name} must be a finite number > 0, got {v!r}")
        self.model, self.dt = model, float(dt)
        self.rtol, self.atol = float(rtol), float(atol)
        self.has_alg = model.z.numel() > 0
        solver = solver or ("collocation" if self.has_alg else "dopri")
        if solver not in SOLVERS:
            raise SimulationError(f"unknown stepper solver '{solver}'; choose one of {SOLVERS}")
        if solver in ("dopri", "cvodes") and self.has_alg:
            raise SimulationError(f"model '{model.name}' has algebraic variables "
                                  f"({', '.join(model.z_names[:3])}, ...): step it with "
                                  f"solver='collocation' or 'idas'")
        if solver == "idas" and model.has_loops:
            raise SimulationError(f"model '{model.name}' has closed kinematic loops, whose "
                                  f"restarts IDAS cannot initialize at every sample: step it "
                                  f"with solver='collocation'")
        self.solver = solver
        self.substeps = int(substeps or (1 if solver == "dopri" else 4))
        if self.substeps < 1:
            raise SimulationError(f"substeps must be an integer >= 1, got {substeps!r}")
        self.output_names = list(outputs) if outputs is not None else (
            model.output_names or model.x_names)
        for name in self.output_names:
            model.locate(name)                       # VariableNameError with suggestions
        self.input_names = list(model.input_names)
        self._input_index = {n: i for i, n in enumerate(self.input_names)}
        self.events = []
        self._x0, self._guess = dict(x0 or {}), guess
        # the state, inputs and parameters live in these arrays, changed in place only: the
        # buffers of the Functions read them
        self._x, self._z = np.zeros(model.x.numel()), np.zeros(model.z.numel())
        self.u, self._t = np.zeros(model.u.numel()), np.zeros(1)
        self._params = dict(params or {})
        self.p = model.param_vector(self._params)
        self._outputs = Buffered(model.function(
            "outputs", [ca.vertcat(*[model.expression(n) for n in self.output_names])]),
            [self._t, self._x, self._z, self.u, self.p])
        self._integrator, self._built_for = None, None
        self._t0 = float(t0)
        self.reset()

    @property
    def t(self) -> float:
        """The present time [s]."""
        return float(self._t[0])

    # ---- state ----------------------------------------------------------------------------
    def reset(self, x0: dict | None = None, t0: float | None = None,
              params: dict | None = None,
              u: Mapping[str, float] | Sequence[float] | None = None) -> dict:
        """Start again at t0 [s] from x0 (default: the t0 and x0 given when made), with new
        parameter overrides if ``params`` is given (kept for later resets; default: the
        last ones), and inputs ``u`` (default: their start values); returns the outputs
        there."""
        model = self.model
        if params is not None:
            self._params = dict(params)
        self.p[:] = model.param_vector(self._params)      # (modes and loop rows: at start)
        self.scale = model.nominals(self.p)
        self.u[:] = np.array(model.input_start, dtype=float).ravel()
        if u is not None:
            self.hold(u)
        self._t[0] = self._t0 if t0 is None else float(t0)
        x0 = dict(x0) if x0 is not None else self._x0
        x, z = initial_state(model, x0, self.p, self.u, self.t, self._guess,
                             initial_equations=True)
        self._x[:], self._z[:] = np.ravel(x), np.ravel(z)
        if model.has_loops:
            active = model.mobility_at(self.t, self._x, self._z, self.u, self.p)[0]
            self.p[model.loop_switches] = active
        self.events = []
        self._started = False            # no step yet: the next one starts the simulation
        self._build()
        return self.outputs()

    @property
    def x(self) -> np.ndarray:
        """The states [x_names order] (a copy); settable."""
        return self._x.copy()

    @x.setter
    def x(self, values) -> None:
        values = np.asarray(values, dtype=float).ravel()
        if values.size != self._x.size:
            raise SimulationError(f"the state of '{self.model.name}' is {self._x.size} numbers "
                                  f"({', '.join(self.model.x_names)}), got {values.size}")
        self.state = dict(zip(self.model.x_names, values))

    @property
    def z(self) -> np.ndarray:
        """The algebraic variables [z_names order] (a copy)."""
        return self._z.copy()

    @property
    def state(self) -> dict[str, float]:
        """The states by dotted name; set some or all of them with a dict (the others kept;
        a DAE's algebraic variables and a closed loop's dependent states made consistent)."""
        return dict(zip(self.model.x_names, self._x.tolist()))

    @state.setter
    def state(self, values: Mapping[str, float]) -> None:
        names = self.model.x_names
        unknown = [n for n in values if n not in names]
        if unknown:
            raise SimulationError(f"'{self.model.name}' has no state {unknown}; its states: "
                                  f"{names}")
        x = self._x.copy()
        for n, v in values.items():
            x[names.index(n)] = float(v)
        if not np.all(np.isfinite(x)):
            raise SimulationError(f"the states of '{self.model.name}' must be finite numbers")
        if self.has_alg:                   # consistent algebraic variables (and loops)
            x, z = initial_state(self.model, dict(values), self.p, self.u, self.t,
                                 guess=dict(zip(names, x)))
            self._z[:] = np.ravel(z)
        self._x[:] = np.ravel(x)

    # ---- stepping -------------------------------------------------------------------------
    def step(self, u: Mapping[str, float] | Sequence[float] | float | None = None) -> dict:
        """Hold the inputs ``u`` (a dict by input name, the others keeping their value, or
        values in ``input_names`` order; None: all kept) over [t, t + dt] and integrate:
        the outputs at t + dt by name."""
        if u is not None:
            self.hold(u)
        self.advance(self.dt)
        return self.outputs()

    def advance(self, h: float) -> None:
        """Integrate over [t, t + h] with the held inputs (``step`` without outputs); a
        SimulationError if a component's assertion fails at t + h (``assertions``)."""
        self._over(h)
        self._t[0] += h
        if self.model.assertions.numel():
            assertions.check(self.model, self._t, self._x, self._z, self.u, self.p)

    def outputs(self) -> dict[str, float]:
        """The chosen outputs at the present time, by name."""
        self._outputs.call()
        return dict(zip(self.output_names, self._outputs.res[0].tolist()))

    def hold(self, u: Mapping[str, float] | Sequence[float]) -> None:
        """Hold the inputs ``u`` from now on (as ``step`` takes them)."""
        if type(u) is dict or isinstance(u, Mapping):
            check_finite("u", u)
            for n, v in u.items():
                i = self._input_index.get(n)
                if i is None:
                    raise SimulationError(f"'{self.model.name}' has no input '{n}'; its "
                                          f"inputs: {self.input_names or 'none'}")
                self.u[i] = v
            return
        try:
            values = np.asarray(u, dtype=float).ravel()
        except (TypeError, ValueError):                   # text: no numbers at all
            values = None
        if values is None or values.size != self.u.size or not np.all(np.isfinite(values)):
            raise SimulationError(f"'{self.model.name}' has {self.u.size} inputs "
                                  f"{self.input_names}: give as many finite numbers, got {u!r}")
        self.u[:] = values

    def _build(self) -> None:
        """The integrator for the present parameters (kept while they are the same)."""
        if self._built_for == self.p.tobytes():
            return
        self._built_for = self.p.tobytes()
        model = self.model
        if model.has_events:
            # the parameters folded in once (the modes left symbols, the event engine's
            # parameters): each step substitutes only the held inputs
            equations = scaled(model, *folded(model, self.p), self.scale)
            self._integrator = (equations, integrator_settings(
                model, "idas" if self.has_alg else "cvodes", self.rtol, self.atol)[:2])
            self._over = self._events_over
            return
        if not self._x.size and self.has_alg:    # algebraic only: Newton at each step's end
            self._integrator = ca.rootfinder("step", "newton", {
                "x": model.z, "p": ca.vertcat(model.t, model.u, model.p), "g": model.alg},
                {"abstol": 1e-14, "max_iter": 100, "error_on_fail": True})
            self._over = self._algebraic_over
            return
        if self.solver == "dopri":
            self._over = self._dopri_over
            self._integrator = Buffered(dopri_step(model, self.p), [
                self._x.copy(), self.u, np.zeros(1), np.zeros(1),         # x, u, t, h
                self.atol * self.scale[:self._x.size], np.array([self.rtol])])
            return
        # τ ∈ [0, 1] over the step [t0, t0 + h]: the step's start and length are parameters
        t0, h, tau = ca.SX.sym("t0"), ca.SX.sym("h"), ca.SX.sym("tau")
        ode, alg = scaled(model, model.ode, model.alg, self.scale)
        ode, alg = ca.substitute([h * ode, alg], [model.t], [t0 + h * tau])
        dae = {"x": model.x, "t": tau, "p": ca.vertcat(model.u, model.p, t0, h), "ode": ode}
        if self.has_alg:
            dae.update(z=model.z, alg=alg)
        if self.solver == "collocation":
            plugin, opts = "collocation", {"number_of_finite_elements": self.substeps,
                                           "collocation_scheme": "radau",
                                           "interpolation_order": 3}
        else:
            plugin, opts, _ = integrator_settings(model, self.solver, self.rtol, self.atol)
        self._integrator = ca.integrator("step", plugin, dae, 0.0, [1.0], opts)
        self._over = self._integrate_over

    def _dopri_over(self, h: float) -> None:
        """Dormand–Prince substeps over [t, t + h], as many as the error needs."""
        f = self._integrator
        x, t, hh = f.args[0], f.args[2], f.args[3]
        xf, err = f.res
        n = self.substeps
        while True:
            x[:], hh[0], worst, t0 = self._x, h / n, 0.0, self._t[0]
            for k in range(n):
                t[0] = t0 + k * hh[0]
                f.call()
                e = err[0]
                if not e <= 1.0:                       # too large (or not a number)
                    break
                if e > worst:
                    worst = e
                x[:] = xf
            else:
                break
            n *= 2
            if n > MAX_SUBSTEPS:
                raise SimulationError(
                    f"stepping '{self.model.name}' from t = {t0:g} s: {MAX_SUBSTEPS} "
                    f"Dormand-Prince substeps per sample period do not reach the tolerance "
                    f"(rtol {self.rtol:g}, atol {self.atol:g}): the model is stiff there or its "
                    f"state not finite; step it with solver='cvodes'")
        if worst < 1 / 64 and n > 1:     # 5th order: half as many substeps, 32× the error
            n //= 2
        self.substeps = n
        self._x[:] = x

    def _algebraic_over(self, h: float) -> None:
        """The algebraic variables at t + h, by Newton's method from those at t."""
        try:
            z = self._integrator(self._z, np.concatenate([[self.t + h], self.u, self.p]))
        except RuntimeError:
            raise SimulationError(f"the algebraic equations of '{self.model.name}' have no "
                                  f"solution near the previous one at t = {self.t + h:g} s: "
                                  f"check the inputs and parameters") from None
        self._z[:] = np.array(z, dtype=float).ravel()

    def _integrate_over(self, h: float) -> None:
        """One call of the CasADi integrator over [t, t + h]."""
        Nx, Nz = self.scale[:self._x.size], self.scale[self._x.size:]
        try:
            sol = self._integrator(x0=self._x / Nx, z0=self._z / Nz,
                                   p=np.concatenate([self.u, self.p, [self.t, h]]))
        except RuntimeError as e:
            raise SimulationError(f"stepping '{self.model.name}' from t = {self.t:g} s over "
                                  f"{h:g} s failed ({self.solver}): {str(e).splitlines()[-1]}; "
                                  f"check the inputs and state, or try another solver"
                                  ) from None
        self._x[:] = np.array(sol["xf"], dtype=float).ravel() * Nx
        if self.has_alg:
            self._z[:] = np.array(sol["zf"], dtype=float).ravel() * Nz

    def _events_over(self, h: float) -> None:
        """The event engine of simulate() over [t, t + h], the modes carried in p."""
        model = self.model
        equations, (plugin, opts) = self._integrator
        ode, alg = ca.substitute(list(equations), [model.u], [ca.SX(ca.DM(self.u))])
        run = EventSimulation(model, ode, alg, self.p, ca.SX(ca.DM(self.u)), self.scale,
                              plugin, opts)
        run.checks_per_run = EVENT_CHECKS
        grid = np.array([self.t, self.t + h])
        T, X, Z, D = run.run(grid, self._x, self._z, model.event_times(self.p, *grid),
                             start=not self._started)
        self._started = True
        self._x[:], self._z[:] = X[:, -1], Z[:, -1]
        self.p[model.mode_params] = D[:, -1]
        self.events += run.log
        if run.terminated is not None:
            raise SimulationError(f"'{model.name}' {run.terminated}: reset it to go on")
