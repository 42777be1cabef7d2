"""State feedback in simulate(): an input computed by a controller from the model's variables.

``simulate(..., inputs={"F": controller})`` where the controller is

- a ``Controller(fn, of=names, period=None)``;
- a CasADi Function of (t, y) — y the vector of the variables named in ``of`` (default: the
  model's Outputs, then its states, in ``output_names`` + ``x_names`` order) — or a Python
  callable of two arguments (t, y), y a dict of those variables by name. (A callable of one
  argument stays an input given as a function of time.)

Continuous (period None): the controller's expression in the model's symbols replaces the
input in the equations and the event functions (exact: no sampling). A CasADi Function always has one; a Python
callable must accept CasADi symbols (arithmetic, numpy ufuncs, ``casadi.if_else``) — one
that does not (an ``if`` on a value, a neural network in another framework) is refused:
give it a ``period``.

Sampled (``period`` [s]): the controller is called once per sample instant k·period with
the values of ``of`` there, and its result held until the next (zero-order hold, a digital
controller); the plant is integrated exactly between the samples
(``acausal.simulation.stepper``), the other inputs as expressions of time. Ctrl-C during a
sampled run returns the Result up to the last sample (``Result.partial``).
"""
from __future__ import annotations

import inspect
import warnings
from dataclasses import dataclass, replace
from typing import Callable, Sequence

import casadi as ca
import numpy as np

from ..errors import SimulationError
from ..numerics import has_nan_constant
from .inputs import input_signal
from .progress import progress_bar, warn_interrupted
from .result import Result
from .stepper import Stepper


@dataclass(frozen=True)
class Controller:
    """A controller of one input: ``fn(t, y)`` (see the module docstring), ``of`` the dotted
    names of the variables in y (default: the model's Outputs, then its states), ``period``
    [s] for a sampled controller (None: continuous)."""
    fn: Callable
    of: Sequence[str] | None = None
    period: float | None = None


def feedback_inputs(inputs: dict | None) -> dict[str, Controller]:
    """The inputs given as controllers, by input name."""
    out = {}
    for name, value in (inputs or {}).items():
        if isinstance(value, Controller):
            out[name] = value
        elif isinstance(value, ca.Function) or (callable(value) and _arguments(value) == 2):
            out[name] = Controller(value)
    return out


def _arguments(f) -> int | None:
    """The number of positional arguments f takes (None: unknown, e.g. a numpy ufunc)."""
    try:
        params = inspect.signature(f).parameters.values()
    except (TypeError, ValueError):
        return None
    return sum(p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD) and p.default is p.empty
               for p in params)


def simulate_feedback(simulate, model, t_final, grid, inputs, feedback, *, params=None,
                      x0=None, guess=None, rtol=1e-8, atol=1e-10, progress=None, **kwargs):
    """simulate() of ``model`` with the ``feedback`` inputs (by name) closed: continuous ones
    substituted into the equations and run by ``simulate``, sampled ones by a stepper."""
    for name, fb in feedback.items():
        model.locate(name)
        if fb.period is not None and not (np.isfinite(fb.period) and fb.period > 0):
            raise SimulationError(f"input '{name}': the controller's period must be a finite "
                                  f"number > 0 s, got {fb.period!r}")
    sampled = {n: fb for n, fb in feedback.items() if fb.period is not None}
    if len({fb.period for fb in sampled.values()}) > 1:
        raise SimulationError(f"the sampled controllers of {sorted(sampled)} have different "
                              f"periods; give them one period")
    continuous = {n: _expression(model, n, fb) for n, fb in feedback.items()
                  if fb.period is None}
    others = {n: v for n, v in inputs.items() if n not in feedback}
    if not sampled:
        closed = _closed(model, continuous)
        res = simulate(closed, t_final, t=grid, params=params, inputs=others, x0=x0,
                       guess=guess, rtol=rtol, atol=atol, progress=progress, **kwargs)
        return _on_model(model, closed, res, continuous)
    if kwargs.get("solver") not in (None, "cvodes", "idas"):
        raise SimulationError(f"a sampled controller runs with the stepper's solvers; "
                              f"solver={kwargs['solver']!r} is not one of them")
    unused = [k for k in ("max_step", "nominal", "options") if kwargs.get(k) is not None] \
        + (["codegen"] if kwargs.get("codegen") else [])
    if unused:
        raise SimulationError(f"{', '.join(unused)} are not taken by a run with a sampled "
                              f"controller (it steps with acausal.simulation.stepper); leave "
                              f"them out")
    # the other inputs as expressions of time: the inputs left are the sampled controllers'
    subs = dict(continuous, **{n: input_signal(n, v, model.t, grid).expression
                               for n, v in others.items()})
    return _sampled(model, _closed(model, subs), subs, sampled, grid, params=params, x0=x0,
                    guess=guess, rtol=rtol, atol=atol, progress=progress,
                    solver=kwargs.get("solver"))


def _names(model, fb: Controller) -> list[str]:
    names = list(fb.of) if fb.of is not None else model.output_names + model.x_names
    for n in names:
        model.locate(n)
    return names


def _expression(model, name, fb: Controller) -> ca.SX:
    """The continuous controller's output as an expression in (t, x, z, u, p)."""
    names = _names(model, fb)
    y = [model.expression(n) for n in names]
    try:
        if isinstance(fb.fn, ca.Function):
            out = fb.fn(model.t, ca.vertcat(*y))
        else:
            with warnings.catch_warnings():     # numpy ufuncs on SX: the casadi result
                warnings.simplefilter("ignore", FutureWarning)
                out = fb.fn(model.t, dict(zip(names, y)))
        out = ca.SX(out) if not isinstance(out, ca.SX) else out
    except Exception as e:
        raise SimulationError(
            f"input '{name}': the controller does not accept CasADi symbols ({e}), so it "
            f"cannot enter the equations; write it with casadi operations (casadi.if_else, "
            f"numpy ufuncs) or sample it: Controller(fn, period=...)") from None
    if out.numel() != 1:
        raise SimulationError(f"input '{name}': the controller returns {out.numel()} values; "
                              f"one is needed")
    if has_nan_constant(out):
        raise SimulationError(f"input '{name}': the controller turns CasADi symbols into NaN "
                              f"(Python's float() or the math module on a symbol); write it "
                              f"with casadi operations (casadi.if_else, numpy ufuncs) or "
                              f"sample it: Controller(fn, period=...)")
    if ca.depends_on(out, model.u):
        raise SimulationError(f"input '{name}': the controller reads a variable that depends "
                              f"on an input (an algebraic loop through {names}); feed it "
                              f"states or outputs that do not")
    return out


def _closed(model, exprs: dict):
    """``model`` with the inputs ``exprs`` (by name) replaced by those expressions in its
    equations; the others stay inputs. Only the integration uses it: its recorded
    variables are read on ``model`` (``_on_model``)."""
    if not exprs:
        return model
    keep = [k for k, n in enumerate(model.input_names) if n not in exprs]
    drop = [model.input_names.index(n) for n in exprs]
    old = [model.u[k] for k in drop]
    new = list(exprs.values())
    ode, alg, y, init, asserted = ca.substitute(
        [model.ode, model.alg, model.y, model.initial_equations, model.assertions], old, new)
    ev = model.state_events
    g, update, values, end = ca.substitute(
        [ev.indicator, ev.mode_update, ev.reinit_values, ev.terminate], old, new)
    events = replace(ev, indicator=g, mode_update=update, reinit_values=values, terminate=end,
                     reinits=[replace(r, value=ca.substitute([ca.SX(r.value)], old, new)[0])
                              for r in ev.reinits])
    return replace(model, u=ca.vertcat(*[model.u[k] for k in keep]) if keep else ca.SX(0, 1),
                   inputs=[model.inputs[k] for k in keep], ode=ode, alg=alg, y=y,
                   initial_equations=init, assertions=asserted, state_events=events,
                   _cache={})


def _on_model(model, closed, res: Result, subs: dict) -> Result:
    """The Result of ``closed`` as one of ``model``: every input's values on the grid (the
    substituted ones, ``subs``, evaluated on the trajectories)."""
    n = res.t.size
    U = np.zeros((model.u.numel(), n))
    kept = [v.name for v in closed.inputs]
    for k, v in enumerate(model.inputs):
        if v.name in kept:
            U[k] = res._inputs[kept.index(v.name)]
        else:
            f = closed.function("u", [subs[v.name]]).map(n)
            U[k] = np.array(f(res.t.reshape(1, -1), res._states, res._algebraics,
                              res._inputs, res._param_columns())).ravel()
    out = Result(model, res.t, res._states, res._algebraics, U, res._params)
    for attr in ("events", "terminated", "mobility", "solver", "partial"):
        if hasattr(res, attr):
            setattr(out, attr, getattr(res, attr))
    return out


def _sampled(model, held, subs, sampled, grid, *, params, x0, guess, rtol, atol, progress,
             solver):
    """The run with sampled controllers on ``held`` (the model with every other input
    substituted, ``subs``): a stepper over each sample period, the controllers called at its
    start with the variables they read; the states on the grid."""
    period = next(iter(sampled.values())).period
    names = {n: _names(model, fb) for n, fb in sampled.items()}
    of = list(dict.fromkeys(v for ns in names.values() for v in ns))
    if any(model.locate(n)[0] == "input" for n in of):
        raise SimulationError(f"the sampled controllers of {sorted(sampled)} read inputs; "
                              f"give them states or outputs")
    exprs = ca.substitute([ca.vertcat(*[model.expression(n) for n in of])],
                          [model.u[model.input_names.index(n)] for n in subs],
                          list(subs.values()))
    read = held.function("of", exprs)
    st = Stepper(held, period, params=params, x0=x0, guess=guess, rtol=rtol, atol=atol,
                 solver=solver, t0=float(grid[0]), outputs=[])
    cols, k, t0, t_end = [], 0, float(grid[0]), float(grid[-1])
    on_grid = 1e-12 * max(1.0, abs(t_end))
    bar = progress_bar(t_end - t0, f"simulate {model.name}", progress)
    try:
        while True:
            t_k = t0 + k * period
            y = np.array(read(st.t, st.x, st.z, st.u, st.p), dtype=float).ravel()
            y = dict(zip(of, y.tolist()))
            st.hold({name: _call(fb, name, st.t, {n: y[n] for n in names[name]})
                            for name, fb in sampled.items()})
            t_next = min(t_k + period, t_end)
            lo, hi = np.searchsorted(grid, [t_k - on_grid, t_next - on_grid])
            for tg in grid[lo:hi]:             # the output times in [t_k, t_next)
                if tg > st.t:
                    st.advance(float(tg) - st.t)
                cols.append((float(tg), st.x, st.z, st.u.copy()))
            st.advance(t_next - st.t)
            bar.update(t_next - t_k)
            if t_next >= t_end - on_grid:
                cols.append((t_end, st.x, st.z, st.u.copy()))
                break
            k += 1
        partial = False
    except KeyboardInterrupt:
        partial = True
        warn_interrupted(model.name, cols[-1][0] if cols else st.t)
    finally:
        bar.close()
    if not cols:
        raise SimulationError(f"simulation of '{model.name}' interrupted before its first "
                              f"output time")
    T = np.array([c[0] for c in cols])
    X, Z, U = (np.column_stack([c[i] for c in cols]).reshape(-1, T.size) for i in (1, 2, 3))
    res = Result(held, T, X, Z, U, st.p)
    res.events, res.partial, res.solver = st.events, partial, st.solver
    return _on_model(model, held, res, subs)


def _call(fb: Controller, name: str, t: float, y: dict) -> float:
    """The sampled controller's value at t from the values y of the variables it reads."""
    if isinstance(fb.fn, ca.Function):
        out = np.array(fb.fn(t, list(y.values())), dtype=float).ravel()
    else:
        out = np.asarray(fb.fn(t, y), dtype=float).ravel()
    if out.size != 1 or not np.isfinite(out[0]):
        raise SimulationError(f"input '{name}': the controller returned {out.tolist()} at "
                              f"t = {t:g} s; one finite number is needed")
    return float(out[0])
