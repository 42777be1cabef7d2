"""simulate(): a compiled model through a CasADi integrator onto a time grid."""
from __future__ import annotations

import warnings

import casadi as ca
import numpy as np

from ..errors import SimulationError
from .initialization import initial_state
from ..numerics import just_before, short_error
from .result import Result

SOLVERS = ("cvodes", "adams", "idas", "rk", "collocation")


def input_expression(name: str, value, t: ca.SX, grid: np.ndarray) -> ca.SX:
    """An input as an SX expression of time t.

    ``value`` is a number (constant), a callable of time (called with the symbol t when it
    accepts one — numpy ufuncs do — otherwise sampled on a fine grid and linearly
    interpolated), or samples: a pair (times, values), or an array of values on ``grid``
    (linear interpolation).
    """
    if callable(value):
        try:
            with warnings.catch_warnings():      # numpy ufuncs on SX: the casadi result is wanted
                warnings.simplefilter("ignore", FutureWarning)
                ex = value(t)
            ex = ca.SX(ex) if not isinstance(ex, ca.SX) else ex
            if ex.numel() == 1:
                return ex
        except Exception:
            pass
        fine = np.linspace(grid[0], grid[-1], max(2001, 4 * len(grid)))
        try:
            vals = np.array([float(value(tk)) for tk in fine])
        except Exception as e:
            raise SimulationError(f"input '{name}': calling it with a time failed: {e}") from None
        return ca.pw_lin(t, ca.DM(fine), ca.DM(vals))
    if isinstance(value, tuple) and len(value) == 2:
        tt, vv = (np.asarray(a, dtype=float).ravel() for a in value)
        if tt.size != vv.size or tt.size < 2 or np.any(np.diff(tt) <= 0):
            raise SimulationError(f"input '{name}': samples need ≥ 2 increasing times and as many "
                                  f"values")
        return ca.pw_lin(t, ca.DM(tt), ca.DM(vv))
    arr = np.asarray(value, dtype=float)
    if arr.ndim == 0:
        return ca.SX(float(arr))
    if arr.size != len(grid):
        raise SimulationError(f"input '{name}': {arr.size} samples but the output grid has "
                              f"{len(grid)} points; give (times, values) instead")
    return ca.pw_lin(t, ca.DM(grid), ca.DM(arr.ravel()))


def simulate(model, t_final: float, *, t=None, params: dict | None = None,
             inputs: dict | None = None, x0: dict | None = None, guess: dict | None = None,
             solver: str | None = None,
             rtol: float = 1e-8, atol: float = 1e-10, max_step: float | None = None,
             options: dict | None = None) -> Result:
    """Simulate ``model`` from t = 0 (or t[0]) to ``t_final`` [s].

    t        output grid (default: 501 points); params: overrides by dotted name;
    inputs   per input name: a number, a callable of time, (times, values) or values on t;
    x0       initial values by the dotted name of any variable (``mass.s``, ``inertia.w``),
             held exactly;
    guess    start values by state name, used where x0 and the constraints leave freedom
             (closed loops: fix the driver in x0, guess the other joints);
    solver   'cvodes' (BDF with Newton iterations, for stiff mechanics), 'adams' (cvodes'
             Adams method with functional iteration: no Jacobians, faster for non-stiff models
             such as pendulums and linkages without stiff springs), 'idas' (DAEs: closed loops,
             massless nodes), or CasADi's fixed-step 'rk' / 'collocation'
             (``options={'number_of_finite_elements': n}``). Default: 'idas' for DAEs; for
             ODEs 'adams' when the linearization at the initial state is not stiff (see
             ``is_stiff``), else 'cvodes' — and 'cvodes' again should Adams fail.
             ``Result.solver`` says which ran;
    rtol, atol, max_step: integrator tolerances and step limit.
    """
    grid = np.linspace(0.0, float(t_final), 501) if t is None else np.asarray(t, dtype=float)
    if grid.ndim != 1 or grid.size < 2 or np.any(np.diff(grid) <= 0):
        raise SimulationError("t must be an increasing grid of at least two times")
    if t is not None and abs(grid[-1] - t_final) > 1e-12 * max(1.0, abs(t_final)):
        raise SimulationError(f"the grid ends at {grid[-1]} but t_final is {t_final}")
    p = model.param_vector(params)
    inputs = dict(inputs or {})
    unknown = set(inputs) - set(model.input_names)
    if unknown:
        raise SimulationError(f"model '{model.name}' has no input {sorted(unknown)}; its inputs: "
                              f"{model.input_names or 'none'}")
    u_ex = [input_expression(v.name, inputs.get(v.name, v.start), model.t, grid)
            for v in model.inputs]
    u_expr = ca.vertcat(*u_ex) if u_ex else ca.SX(0, 1)
    u0 = np.array(ca.evalf(ca.substitute(u_expr, model.t, grid[0]))).ravel()
    xs, zs = initial_state(model, dict(x0 or {}), p, u0, grid[0], guess)
    mobility = None
    if model.has_loops:                  # enforce the loop rows independent at this assembly
        active, mobility = model.mobility_at(grid[0], xs, zs, u0, p)
        p[model.loop_switches] = active

    has_alg = model.z.numel() > 0
    # inputs become expressions of time, parameters their values: the integrator sees the
    # same folded arithmetic as a hand-written model with numbers (changing a parameter
    # rebuilds only the integrator, never the model)
    ode, alg = ca.substitute([model.ode, model.alg], [model.u, model.p], [u_expr, ca.SX(p)])
    auto = solver is None
    if auto:
        solver = "idas" if has_alg else (
            "cvodes" if is_stiff(model.x, model.t, ode, xs, grid[0], grid[-1]) else "adams")
    plugin, opts, loops = integrator_settings(model, solver, rtol, atol, max_step)
    if loops:
        xdot = ca.Function("xdot", [model.x, model.z, model.t], [ode])
    opts.update(options or {})

    def problem(solver):
        """The DAE for the integrator. Adams with functional iteration never evaluates a
        Jacobian, so the ODE goes in as a call whose derivatives would be finite
        differences: CasADi then builds no symbolic Jacobian (O(N²) for the recursion)."""
        if solver == "adams":
            f = ca.Function("ode", [model.x, model.t], [ode], _NO_AD)
            x, t = ca.MX.sym("x", model.x.numel()), ca.MX.sym("t")
            return {"x": x, "t": t, "ode": f(x, t)}
        dae = {"x": model.x, "t": model.t, "ode": ode}
        if has_alg:
            dae.update(z=model.z, alg=alg)
        return dae

    def integrate(plugin, opts):
        dae = problem(solver)
        X = [np.asarray(xs, dtype=float).reshape(-1, 1)]
        Z = [np.asarray(zs, dtype=float).reshape(-1, 1)]
        if not model.x.numel() and not has_alg:   # every motion prescribed: nothing to solve
            return np.zeros((0, grid.size)), np.zeros((0, grid.size))
        x, z = X[0][:, 0], Z[0][:, 0]
        for a, b, pts in _segments(grid, model.event_times(p, grid[0], grid[-1])):
            # integrate up to just before an event, restart at it (never step over a jump)
            if a != grid[0] and a in grid:           # an output time exactly at the event
                X.append(x.reshape(-1, 1))
                Z.append(z.reshape(-1, 1))
            end = b if b == grid[-1] else just_before(b)
            tout = list(pts) + ([] if pts and pts[-1] == b else [end])
            tout = [min(tt, end) for tt in tout]
            if loops:
                opts["step0"] = (options or {}).get("step0", 1e-6 * (b - a))
                opts["init_xdot"] = list(np.array(xdot(x, z, a), dtype=float).ravel())
            try:
                F = ca.integrator("sim", plugin, dae, float(a), tout, opts)
                sol = F(x0=x, z0=z)
            except RuntimeError as e:
                raise SimulationError(
                    f"simulation of '{model.name}' failed between t = {a:g} and {b:g} s: "
                    f"{short_error(e)}; check the parameters and initial values, or try a "
                    f"smaller rtol/atol or another solver") from None
            xf = np.array(sol["xf"])
            zf = np.array(sol["zf"]) if has_alg else np.zeros((0, len(tout)))
            X.append(xf[:, :len(pts)])
            Z.append(zf[:, :len(pts)])
            x, z = xf[:, -1], (zf[:, -1] if has_alg else z)
        return np.hstack(X), np.hstack(Z)

    try:
        X, Z = integrate(plugin, opts)
    except SimulationError:
        if not (auto and solver == "adams"):
            raise
        solver = "cvodes"                # misjudged as non-stiff: BDF with Newton iterations
        for k in ("linear_multistep_method", "nonlinear_solver_iteration"):
            opts.pop(k)
        X, Z = integrate("cvodes", opts)
    U = np.array(ca.Function("u", [model.t], [u_expr]).map(grid.size)(grid.reshape(1, -1))) \
        if model.u.numel() else np.zeros((0, grid.size))
    P = np.tile(p.reshape(-1, 1), (1, grid.size))

    def evaluate():            # the recorded variables that are not states, on first access
        V = model.recorded_function.map(grid.size)(grid.reshape(1, -1), X, Z, U, P)
        return np.asarray(V.full(), dtype=float)

    res = Result(grid, model.recorded_names, model.recorded_layout, model.recorded_units,
                 {"x": X, "r": evaluate}, model.name)
    res.mobility = mobility             # degrees of freedom and redundant loop rows, if loops
    res.solver = solver
    return res


def integrator_settings(model, solver: str, rtol: float, atol: float,
                        max_step: float | None = None):
    """(plugin, options, loops) of the CasADi integrator for ``model`` with ``solver`` (one of
    SOLVERS): 'adams' is cvodes with Adams steps and functional iteration; cvodes and idas get
    the tolerances, max_num_steps and max_step; ``loops`` is True for IDAS on closed loops,
    whose options keep the index-2 multipliers out of the error test and skip IDAS's own
    initial-value computation (the caller gives consistent values, step0 and init_xdot)."""
    if solver not in SOLVERS:
        raise SimulationError(f"unknown solver '{solver}'; choose one of {SOLVERS}")
    plugin = "cvodes" if solver == "adams" else solver
    if plugin == "cvodes" and model.z.numel():
        raise SimulationError(f"model '{model.name}' has algebraic variables "
                              f"{model.z_names[:3]}...; use solver='idas'")
    opts = {}
    if solver == "adams":        # non-stiff models: no Jacobians, no Newton iterations
        opts.update(linear_multistep_method="adams", nonlinear_solver_iteration="functional")
    if plugin in ("cvodes", "idas"):
        opts.update(abstol=atol, reltol=rtol, max_num_steps=100000)
        if max_step is not None:
            opts["max_step_size"] = max_step
    loops = solver == "idas" and model.has_loops
    if loops:
        # the loops' index-2 multipliers (zero on the exact solution) take no part in the
        # error test and get a loose tolerance in the Newton test; the initial values are
        # consistent already, so IDAS's own initialization (whose Newton iteration is
        # ill-conditioned for index 2 at tiny steps) is replaced by the known derivatives
        opts["suppress_algebraic"] = True
        multipliers = set(model.loop_multipliers)
        opts["abstolv"] = [atol] * model.x.numel() + [
            1.0 if k in multipliers else atol for k in range(model.z.numel())]
        opts["calc_ic"] = False
    return plugin, opts, loops


_NO_AD = {"enable_fd": True, "enable_forward": False, "enable_reverse": False,
          "enable_jacobian": False}


def is_stiff(x: ca.SX, t: ca.SX, ode: ca.SX, x0, t0: float, t1: float,
             max_states: int = 400) -> bool:
    """Whether the ODE ẋ = ode(x, t) is stiff at (x0, t0), judged on the eigenvalues λ of its
    Jacobian (finite differences, one mapped evaluation): stiff when some mode decays more
    than ten times faster than both the fastest oscillation and 1/(t1 − t0) — an explicit
    method would be held to steps far shorter than accuracy needs. Models with more than
    ``max_states`` states are taken as stiff (BDF is the safe choice, the test too costly)."""
    n = x.numel()
    if n == 0 or n > max_states:
        return n > 0
    f = ca.Function("f", [x, t], [ode])
    x0 = np.asarray(x0, dtype=float).ravel()
    h = 1e-7 * np.maximum(1.0, np.abs(x0))
    X = np.hstack([x0.reshape(-1, 1), x0.reshape(-1, 1) + np.diag(h)])
    F = np.asarray(f.map(n + 1)(X, t0), dtype=float)
    lam = np.linalg.eigvals((F[:, 1:] - F[:, :1]) / h)
    if not np.all(np.isfinite(lam)):
        return True
    decay = max(0.0, float(np.max(-lam.real)))
    return decay > 10.0 * max(float(np.max(np.abs(lam.imag))), 1.0 / max(t1 - t0, 1e-12))


def _segments(grid: np.ndarray, events: list[float]):
    """(start, end, output times in (start, end]) of the pieces between time events."""
    bounds = [grid[0]] + [e for e in events] + [grid[-1]]
    for a, b in zip(bounds, bounds[1:]):
        last = b == grid[-1]
        pts = [float(tt) for tt in grid[1:] if a < tt < b or (tt == b and last)]
        yield float(a), float(b), pts
