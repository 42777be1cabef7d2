"""simulate(): a compiled model through a CasADi integrator onto a time grid."""
from __future__ import annotations

from contextlib import nullcontext

import casadi as ca
import numpy as np

from ..errors import SimulationError
from ..numerics import just_before
from . import assertions, buffers, codegen as generated, explicit
from .diagnosis import failure_message, not_finite, quiet_stderr, solver_account
from .events import EventSimulation, ModeIteration
from .initialization import initial_state
from .problem import (check_finite, check_inputs, check_settings, folded,
                      integrator_problem, integrator_settings, output_grid, scaled)
from .inputs import input_signal
from .result import Result
from .progress import progress_bar, time_reporter, warn_interrupted
from .stiffness import adams_step_budget, is_stiff, spectral_radius

PROGRESS_POINTS = 100       # restarts of the integrator to report progress at


def simulate(model, t_final: float, *, t=None, params: dict | None = None,
             inputs: dict | None = None, x0: dict | None = None, guess: dict | None = None,
             solver: str | None = None,
             rtol: float = 1e-8, atol: float = 1e-10, max_step: float | None = None,
             nominal: dict | None = None, options: dict | None = None,
             progress: bool = False, codegen: bool = False) -> Result:
    """Simulate ``model`` from t = 0 (or t[0]) to ``t_final`` [s].

    t        output grid (default: 501 points); params: overrides by dotted name;
    inputs   per input name: a number, a callable of time, ``Samples(times, values,
             interpolation='linear' | 'hold')``, (times, values) or values on t (see
             ``acausal.simulation.inputs``), or a controller: a CasADi Function or callable
             of (t, y), a ``Controller(fn, of=..., period=...)``, continuous or sampled
             (``acausal.simulation.feedback``);
    x0       initial values by the dotted name of any variable (``mass.s``, ``inertia.w``),
             held exactly, as the components' initial equations (``PhysicsBuilder.initial``)
             are;
    guess    start values by the dotted name of any variable, used where x0 and the
             constraints leave freedom (closed loops: fix the driver in x0, guess the other
             joints, or a joint angle that is no coordinate, e.g. the loop-closing one);
    solver   'cvodes' (BDF with Newton iterations, for stiff mechanics), 'adams' (cvodes'
             Adams method with functional iteration: no Jacobians, faster for non-stiff models
             such as pendulums and linkages without stiff springs), 'idas' (DAEs: closed loops,
             massless nodes), CasADi's fixed-step 'rk' / 'collocation'
             (``options={'number_of_finite_elements': n}``), or 'dop853': scipy's explicit
             Runge–Kutta method of order 8 (``acausal.simulation.explicit``; ODEs without
             state events only; ``options`` 'first_step', 'max_num_steps'), fewest steps at
             equal accuracy on smooth non-stiff motion (robot arms, chains; with
             ``codegen=True``: about Pinocchio + DOP853's time). Default (never 'dop853'):
             'idas' for DAEs; for ODEs 'adams' when the spectral radius at the initial state
             is small against the time span (``acausal.simulation.stiffness``), else
             'cvodes' — and 'cvodes' again should Adams fail or work too hard.
             ``Result.solver`` says which ran;
    rtol, atol, max_step: integrator tolerances and step limit; the absolute tolerance
             of a state (or algebraic variable) is atol·nominal (Modelica's nominal: the
             error control of a state of size 1e-4 needs atol 1e-4 times smaller);
    nominal  nominal magnitudes by the dotted name of a state or of a variable that
             coincides with one (``springDamper.w_rel``), replacing the model's
             (``CompiledModel.nominals``: 1 unless a component declares one, e.g.
             MSL's phi_nominal of a SpringDamper, or ``nominal={...}`` on a component);
    progress a progress bar (tqdm, ``acausal.simulation.progress``) over the simulated time,
             shown once the run takes more than 2 s: the integrator then restarts at 100
             points of the grid to report (results equal to the tolerances).
    codegen  True: the integrator runs on the model's equations generated as C and built by
             the system C compiler once, cached on disk by a hash of the code
             (``acausal.simulation.codegen``: parameters and inputs stay arguments, so
             changing them does not rebuild); faster on large models, the same results to
             rounding (which the integrator may carry up to its tolerance); models with
             events are refused.

    Ctrl-C (KeyboardInterrupt) between two calls of the integrator (time events, the
    progress points, sample instants of a sampled controller, the windows between state
    events) ends the run there: the Result holds the output times reached,
    ``Result.partial`` is True and a warning says so.

    A model with state events or discrete modes (components' ``indicator``, ``mode``,
    ``reinit``) is integrated from event to event (``acausal.simulation.events``: CVODES for
    ODEs, IDAS for DAEs); the Result then has the event log ``events`` and both limits at
    every event (its time twice in ``t``); the modes' start values are read from ``params``.
    A model without states whose equations depend on time (a resistive circuit on a source)
    is solved by Newton's method at each output time. A component's termination condition
    (MSL's TerminateSimulation) ends the run at the event where it holds:
    ``Result.terminated`` says when and why, ``t`` ends there.
    """
    grid = output_grid(t_final, t)
    check_settings(rtol=rtol, atol=atol, max_step=max_step)
    from .feedback import feedback_inputs, simulate_feedback   # (they step with simulate's
    controllers = feedback_inputs(inputs)                      # integrator settings)
    if controllers:
        return simulate_feedback(simulate, model, t_final, grid, dict(inputs), controllers,
                                 params=params, x0=x0, guess=guess, solver=solver, rtol=rtol,
                                 atol=atol, max_step=max_step, nominal=nominal,
                                 options=options, progress=progress, codegen=codegen)
    if codegen:
        generated.check_supported(model)
    if solver == explicit.NAME:
        explicit.check_supported(model)
    p = model.param_vector(params)
    inputs = dict(inputs or {})
    check_inputs(model, inputs)
    signals = [input_signal(v.name, inputs.get(v.name, v.start), model.t, grid)
               for v in model.inputs]
    u_expr = ca.vertcat(*[s.expression for s in signals]) if signals else ca.SX(0, 1)
    u0 = np.array(ca.evalf(ca.substitute(u_expr, model.t, grid[0]))).ravel()
    for name, values in (("x0", x0), ("guess", guess)):
        check_finite(name, values)
    xs, zs = initial_state(model, dict(x0 or {}), p, u0, grid[0], guess,
                           initial_equations=True)
    scale = model.nominals(p, nominal)           # the integrator works on [x; z] / scale
    nx = model.x.numel()
    mobility = None
    if model.has_loops:                  # enforce the loop rows independent at this assembly
        active, mobility = model.mobility_at(grid[0], xs, zs, u0, p)
        p[model.loop_switches] = active

    has_alg = model.z.numel() > 0
    auto = solver is None
    rho = None if has_alg or not model.x.numel() else _check_start(
        model, p, u0, xs, grid[0], estimate=auto)
    # inputs become expressions of time, parameters their values: the integrator sees the
    # same folded arithmetic as a hand-written model with numbers (changing a parameter
    # rebuilds only the integrator, never the model); modes stay symbols, the integrator's
    # parameters, changed at events. The generated code takes them as arguments: folded
    # only for a closed loop's initial rates and a model without states (a large model's
    # folding costs a fair part of a short run: 0.06 s for a 3-D chain of 64 links)
    ode = alg = None
    if not codegen or model.has_loops or not model.x.numel():
        ode, alg = scaled(model, *folded(model, p, u_expr), scale)
    if auto:
        solver = "idas" if has_alg else (
            "cvodes" if rho is not None and (model.has_events or is_stiff(rho, grid[0], grid[-1]))
            else "adams")
    plugin, opts, loops = (solver, {}, False) if solver == explicit.NAME else \
        integrator_settings(model, solver, rtol, atol, max_step)
    if auto and solver == "adams" and rho is not None:   # too much work: BDF takes over
        opts["max_num_steps"] = adams_step_budget(rho, float(np.max(np.diff(grid))))
    # IDAS's own initial-value computation starts from the rates given (0 by default):
    # the states' rates at the start of each segment, which a fast state (a pF junction
    # capacitance charged through kΩ: 1e10 V/s) needs for its Newton iteration to converge
    # (with events, EventSimulation gives them)
    rates = loops or (plugin == "idas" and ode is not None and not model.has_events)
    if rates:
        xdot = ca.Function("xdot", [model.x, model.z, model.t], [ode])
    opts.update(options or {})

    def integrate(plugin, opts):
        nonlocal interrupted
        dae = generated.dae_problem(model, solver, u_expr, p, scale) if codegen else \
            integrator_problem(model, solver, ode, alg)
        X = [np.asarray(xs, dtype=float).reshape(-1, 1) / scale[:nx, None]]
        Z = [np.asarray(zs, dtype=float).reshape(-1, 1) / scale[nx:, None]]
        if not model.x.numel() and not has_alg:   # every motion prescribed: nothing to solve
            return np.zeros((0, grid.size)), np.zeros((0, grid.size))
        x, z = X[0][:, 0], Z[0][:, 0]
        if not model.x.numel():     # algebraic only (a resistive circuit on a source):
            return np.zeros((0, grid.size)), _algebraic_only(model, alg, grid, z) * scale[
                nx:, None]
        bar = progress_bar(grid[-1] - grid[0], f"simulate {model.name}", progress)
        reached = time_reporter(bar, grid[0])
        advance = step if solver != explicit.NAME else explicit_step(
            explicit.Dop853(model, dae, rtol, atol, max_step, opts, reached))
        restarts = progress and solver != explicit.NAME    # (DOP853 reports each step)
        events = sorted(set(time_events).union(
            grid[1:-1:max(1, grid.size // PROGRESS_POINTS)] if restarts else ()))
        try:
            for a, b, pts in _segments(grid, events):
                x, z = advance(dae, a, b, pts, x, z, X, Z)
                reached(b)
        except KeyboardInterrupt:
            interrupted = True
        finally:
            bar.close()
        X = np.hstack(X) * scale[:nx, None]
        return X, np.hstack(Z) * scale[nx:, None] if has_alg else np.zeros((0, X.shape[1]))

    def segment(a, b, pts, x, z, X, Z):
        """Where the integration from a towards b stops, (b, or just before an event at b:
        it restarts there, never steps over a jump) and the output times pts clipped to
        it; an output time exactly at the event a gets the state there."""
        if a != grid[0] and a in grid:
            X.append(x.reshape(-1, 1))
            Z.append(z.reshape(-1, 1))
        end = b if b == grid[-1] else just_before(b)
        return end, [min(tt, end) for tt in pts]

    def explicit_step(method):
        """``step`` by the explicit ODE solver ``method`` (``explicit.Dop853``)."""
        def advance(dae, a, b, pts, x, z, X, Z):
            end, tout = segment(a, b, pts, x, z, X, Z)
            return method.run(a, end, x, tout, X), z
        return advance

    def step(dae, a, b, pts, x, z, X, Z):
        """Integrate ``dae`` from (x, z) at a to b, the output times pts appended to X, Z:
        (x, z) at b."""
        end, tout = segment(a, b, pts, x, z, X, Z)
        tout = tout + ([] if pts and pts[-1] == b else [end])
        if loops:
            opts["step0"] = (options or {}).get("step0", 1e-6 * (b - a))
        if rates:
            opts["init_xdot"] = list(np.array(xdot(x, z, a), dtype=float).ravel())
        try:
            with solver_account():
                F = ca.integrator("sim", plugin, dae, float(a), tout, opts)
                xf, *zf = buffers.call(F, {"x0": x, "z0": z}, ["xf", "zf"][:1 + has_alg])
        except RuntimeError as e:
            def state_near(t_fail, a=a, x=x, z=z):
                """(x, z) shortly before the failure, by a second run; None if it fails."""
                try:
                    probe = ca.integrator("probe", plugin, dae, float(a),
                                          [a + (t_fail - a) * (1 - 1e-6)], opts)
                    sol = probe(x0=x, z0=z)
                except RuntimeError:
                    return None
                return np.array(sol["xf"]).ravel(), np.array(sol["zf"]).ravel()
            raise SimulationError(failure_message(
                model, e, a, b, rtol, atol, state_near if loops else None, p,
                lambda tt: np.array(ca.evalf(ca.substitute(u_expr, model.t, tt))).ravel(),
                start=(np.ravel(x) * scale[:nx], np.ravel(z) * scale[nx:]))
            ) from None
        zf = zf[0] if has_alg else np.zeros((0, len(tout)))
        X.append(xf[:, :len(pts)])
        Z.append(zf[:, :len(pts)])
        return xf[:, -1], (zf[:, -1] if has_alg else z)

    # the declared time events and the inputs' jumps inside the grid: restarts, sorted
    time_events = sorted(set(model.event_times(p, grid[0], grid[-1])).union(
        e for s in signals for e in s.events if grid[0] < e < grid[-1]))
    interrupted = False          # Ctrl-C: the Result holds the output times reached
    if model.has_events:
        return _with_events(model, ode, alg, grid, xs, zs, p, u_expr, scale, plugin, opts,
                            time_events, solver, mobility, progress)
    retry = plugin == "idas" and "suppress_algebraic" not in opts
    try:
        with quiet_stderr() if retry else nullcontext():
            X, Z = integrate(plugin, opts)
    except SimulationError:
        if auto and solver == "adams":
            solver = "cvodes"            # misjudged as non-stiff: BDF with Newton iterations
            plugin, opts, _ = integrator_settings(model, solver, rtol, atol, max_step)
            opts.update(options or {})
        elif retry:
            # IDAS starts the algebraic variables with a zero rate (CasADi takes initial
            # rates of x only): a fast one fails the error test at every step size. Out of
            # it, they follow x (index 1) to the accuracy of x.
            opts["suppress_algebraic"] = True
        else:
            raise
        X, Z = integrate(plugin, opts)
    if opts.get("suppress_algebraic") and has_alg and not loops and X.size:
        # out of IDAS's error test, z at an output time is its interpolant between steps;
        # z of an index-1 DAE follows the states: solved at them instead
        Z = ModeIteration(model, p, ca.Function("u", [model.t], [u_expr])).consistent_along(
            grid[:X.shape[1]], X, Z, np.zeros(0))
    if interrupted:
        grid = grid[:X.shape[1]]
        warn_interrupted(model.name, grid[-1])
    U = np.array(ca.Function("u", [model.t], [u_expr]).map(grid.size)(grid.reshape(1, -1))) \
        if model.u.numel() else np.zeros((0, grid.size))
    res = Result(model, grid, X, Z, U, p)
    assertions.check(model, res.t, res._states, res._algebraics, res._inputs, res._params)
    res.partial = interrupted
    res.mobility = mobility             # degrees of freedom and redundant loop rows, if loops
    res.solver = solver
    return res


def _with_events(model, ode, alg, grid, xs, zs, p, u_expr, scale, plugin, opts,
                 time_events, solver, mobility, progress) -> Result:
    """simulate() of a model with state events or modes (``events``), restarted at the
    sorted ``time_events``."""
    run = EventSimulation(model, ode, alg, p, u_expr, scale, plugin, opts)
    bar = progress_bar(grid[-1] - grid[0], f"simulate {model.name}", progress)
    run.reached = time_reporter(bar, grid[0])
    try:
        T, X, Z, D = run.run(grid, np.asarray(xs, dtype=float).ravel(),
                             np.asarray(zs, dtype=float).ravel(), time_events)
        partial = False
    except KeyboardInterrupt:
        T, X, Z, D = run._columns(run.cols)
        partial = True
        warn_interrupted(model.name, T[-1])
    finally:
        bar.close()
    U = np.array(ca.Function("u", [model.t], [u_expr]).map(T.size)(T.reshape(1, -1))) \
        if model.u.numel() else np.zeros((0, T.size))
    P = np.tile(p.reshape(-1, 1), (1, T.size))
    P[model.mode_params] = D
    res = Result(model, T, X, Z, U, P)
    assertions.check(model, res.t, res._states, res._algebraics, res._inputs, res._params)
    res.partial = partial
    res.events = run.log
    res.terminated = run.terminated
    res.mobility = mobility
    res.solver = solver
    return res


def _algebraic_only(model, alg, grid, z0) -> np.ndarray:
    """The algebraic variables (scaled, one column per output time) of a model without
    states: 0 = alg(t, z) solved by Newton's method at each output time from the solution
    at the previous one (``z0`` at the first)."""
    solve = ca.rootfinder("alg", "newton", {"x": model.z, "p": model.t, "g": alg},
                          {"abstol": 1e-14, "max_iter": 100, "error_on_fail": True})
    Z, z = [np.asarray(z0, dtype=float)], np.asarray(z0, dtype=float)
    for tk in grid[1:]:
        try:
            z = np.array(solve(z, tk), dtype=float).ravel()
        except RuntimeError:
            raise SimulationError(f"the algebraic equations of '{model.name}' have no solution "
                                  f"near the one at the previous output time, at t = {tk:g} s: "
                                  f"check the parameters or give a finer grid t") from None
        Z.append(z)
    return np.column_stack(Z)


def _check_start(model, p, u0, xs, t0, estimate: bool) -> float | None:
    """The ODE's equations at its initial state (parameters p, inputs u0), checked finite
    (diagnosed, not integrated, otherwise); with ``estimate``, its spectral radius ρ there
    (for the solver's choice), once per model and operating point."""
    key = ("rho", p.tobytes(), u0.tobytes(), np.asarray(xs, float).tobytes(), float(t0))
    cache = model._cache.setdefault("stiffness", {})
    if key in cache:
        return cache[key]

    def f(x, t):
        return model.f(t, x, np.zeros(0), u0, p)[0]
    x0 = np.asarray(xs, dtype=float).ravel()
    fx0 = np.asarray(f(x0, t0), dtype=float).ravel()
    if not np.all(np.isfinite(fx0)):
        raise SimulationError(not_finite(model, x0, fx0, p, u0, t0))
    if not estimate:
        return None
    cache[key] = spectral_radius(f, x0, t0, fx0)
    return cache[key]


def _segments(grid: np.ndarray, events: list[float]):
    """(start, end, output times in (start, end]) of the pieces between time events."""
    bounds = [grid[0]] + [e for e in events] + [grid[-1]]
    for a, b in zip(bounds, bounds[1:]):
        last = b == grid[-1]
        pts = [float(tt) for tt in grid[1:] if a < tt < b or (tt == b and last)]
        yield float(a), float(b), pts
