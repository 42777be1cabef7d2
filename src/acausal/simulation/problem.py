"""How a compiled model becomes a CasADi integrator's problem, shared by simulate(), sweep(),
the stepper and the pythonfmu FMU: the DAE in the model's symbols, the parameters folded in as
numbers, the states scaled by their nominals, the integrator's plugin and options per solver,
and the checks of the arguments every run takes (the output grid, tolerances, finite values,
input names)."""
from __future__ import annotations

import math

import casadi as ca
import numpy as np

from ..errors import SimulationError
from . import explicit

SOLVERS = ("cvodes", "adams", "idas", "rk", "collocation")


def integrator_problem(model, solver: str, ode, alg, params: ca.SX | None = None) -> dict:
    """The DAE ẋ = ode, 0 = alg for ``casadi.integrator`` with ``solver``: in the model's
    x, z, t and ``params`` (symbols, the integrator's parameters ``p``; None: no parameters).
    Adams with functional iteration never evaluates a Jacobian, yet CasADi builds one for
    an SX right-hand side, at a cost that grows as states × instructions (43 ms for the
    16-link pendulum, 0.44 s for the 64-link one). Beyond ``ADAMS_SX_WORK`` of that product
    the ODE goes in as a call whose derivatives would be finite differences, so that none
    is built; below it, as it is: its Jacobian costs about a millisecond once, and each
    evaluation is 10–15 % cheaper than through a call (a quarter car's run: 2.6 against
    2.9 ms)."""
    params = ca.SX(0, 1) if params is None else params
    if solver == "adams":
        f = ca.Function("ode", [model.x, model.t, params], [ode], _NO_AD)
        if model.x.numel() * f.n_instructions() > ADAMS_SX_WORK:
            x, t = ca.MX.sym("x", model.x.numel()), ca.MX.sym("t")
            q = ca.MX.sym("p", params.numel())
            dae = {"x": x, "t": t, "ode": f(x, t, q)}
            return dict(dae, p=q) if params.numel() else dae
    dae = {"x": model.x, "t": model.t, "ode": ode}
    if params.numel():
        dae["p"] = params
    if model.z.numel():
        dae.update(z=model.z, alg=alg)
    return dae


def folded(model, p: np.ndarray, u: ca.SX | None = None) -> tuple[ca.SX, ca.SX]:
    """The equations (ode, alg) of ``model`` with the parameter values ``p`` folded in as
    numbers, the discrete modes left symbols (the event engine's parameters, changed at
    events), and the inputs replaced by the expressions ``u`` (None: they stay symbols):
    the numeric right-hand side simulate()'s and the stepper's integrators see."""
    values = ca.SX(p)
    if model.mode_params:               # (an empty index of a 1x1 p has no definite shape)
        values[model.mode_params] = model.p[model.mode_params]
    old, new = ([model.p], [values]) if u is None else ([model.u, model.p], [u, values])
    return tuple(ca.substitute([model.ode, model.alg], old, new))


def scaled(model, ode, alg, nominal):
    """The DAE ẋ = ode, 0 = alg in [x; z] divided by their nominals (x = N_x·x̃,
    z = N_z·z̃): dx̃/dt = ode/N_x, 0 = alg, with the model's symbols x, z standing for x̃,
    z̃. The integrator's absolute tolerance atol on x̃_i is atol·nominal_i on x_i (CVODES
    takes one absolute tolerance only); its relative error test is unchanged. ``nominal``:
    numbers, or symbols (parameters of the integrator, one value per run of a sweep)."""
    nx = model.x.numel()
    if isinstance(nominal, ca.SX):
        Nx, Nz = nominal[:nx, :], nominal[nx:, :]       # (a 1 x 1 SX sliced [1:] is 1 x 0)
    elif np.all(nominal == 1.0):
        return ode, alg
    else:
        Nx, Nz = ca.DM(nominal[:nx]), ca.DM(nominal[nx:])
    ode, alg = ca.substitute([ode, alg], [model.x, model.z], [Nx * model.x, Nz * model.z])
    return ode / Nx, alg


def integrator_settings(model, solver: str, rtol: float, atol: float,
                        max_step: float | None = None):
    """(plugin, options, loops) of the CasADi integrator for ``model`` with ``solver`` (one of
    SOLVERS): 'adams' is cvodes with Adams steps and functional iteration; cvodes and idas get
    the tolerances, max_num_steps and max_step; ``loops`` is True for IDAS on closed loops,
    whose options keep the index-2 multipliers out of the error test and skip IDAS's own
    initial-value computation (the caller gives consistent values, step0 and init_xdot)."""
    if solver == explicit.NAME:
        raise SimulationError(f"solver '{solver}' (scipy's) runs in simulate() only, not with "
                              f"a CasADi integrator; choose one of {SOLVERS} here")
    if solver not in SOLVERS:
        raise SimulationError(f"unknown solver '{solver}'; choose one of "
                              f"{SOLVERS + (explicit.NAME,)}")
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


ADAMS_SX_WORK = 4096        # states × instructions of the ODE
_NO_AD = {"enable_fd": True, "enable_forward": False, "enable_reverse": False,
          "enable_jacobian": False}


def check_inputs(model, names) -> None:
    """A SimulationError naming the ``names`` that are not inputs of ``model``."""
    unknown = set(names) - set(model.input_names)
    if unknown:
        raise SimulationError(f"model '{model.name}' has no input {sorted(unknown)}; its inputs: "
                              f"{model.input_names or 'none'}")


def output_grid(t_final, t) -> np.ndarray:
    """The output grid: ``t`` as given, or 501 points on [0, t_final]; checked."""
    try:
        t_final = float(t_final)
    except (TypeError, ValueError):
        raise SimulationError(f"t_final must be a number [s], got {t_final!r}") from None
    if not np.isfinite(t_final):
        raise SimulationError(f"t_final must be a finite number [s], got {t_final}")
    if t is None:
        if t_final <= 0:
            raise SimulationError(f"t_final must be > 0 s (the simulation starts at t = 0), got "
                                  f"{t_final:g}; give a grid t to start elsewhere")
        return np.linspace(0.0, t_final, 501)
    grid = np.asarray(t, dtype=float)
    if grid.ndim != 1 or grid.size < 2 or not np.all(np.isfinite(grid)) \
            or np.any(np.diff(grid) <= 0):
        raise SimulationError("t must be an increasing grid of at least two finite times [s]")
    if abs(grid[-1] - t_final) > 1e-12 * max(1.0, abs(t_final)):
        raise SimulationError(f"the grid t ends at {grid[-1]:g} s but t_final is {t_final:g} s")
    return grid


def check_settings(**values) -> None:
    """Tolerances and step limits: finite and > 0 (None: not set)."""
    for name, v in values.items():
        if v is not None and not (isinstance(v, (int, float, np.floating)) and np.isfinite(v)
                                  and v > 0):
            raise SimulationError(f"{name} must be a finite number > 0, got {v!r}")


def check_finite(what: str, values: dict | None, error=SimulationError) -> None:
    """An ``error`` naming the first of ``values`` (name -> value) that is no finite number
    (``what``: the argument that gave them, e.g. x0)."""
    for name, v in (values or {}).items():
        try:
            ok = math.isfinite(float(v))
        except (TypeError, ValueError):
            ok = False
        if not ok:
            raise error(f"{what}['{name}'] must be a finite number, got {v!r}")
