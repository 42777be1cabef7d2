"""Inputs of a simulation as expressions of time, with the time events their jumps need.

An input is given as a number (constant), a callable of time, samples, or values on the
output grid:

- a callable that accepts CasADi symbols (numpy ufuncs do, ``casadi.if_else`` too) becomes
  an exact expression; one that does not, or that turns them into NaN (``math.sin``,
  ``float()``: checked against its values at numbers), is sampled on a fine grid and
  interpolated linearly, and a warning says so (give ``Samples(..., interpolation="hold")``
  for a piecewise-constant signal such as a sampled controller's output);
- ``Samples(times, values, interpolation)`` or a pair ``(times, values)`` (linear): between
  samples linear, or held (zero-order hold: each value holds until the next sample time);
  a time given twice is a step (the value jumps there). Like MSL's CombiTimeTable, linear
  samples extrapolate the first and last two points; held ones hold the end values (both
  on CasADi interpolants: a binary search per evaluation, not a branch per sample).
  Integration restarts at every jump (a time event), never stepping across it;
- an array with one value per output time: linear between them.
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..errors import SimulationError, warn_user

FINE = 2001         # samples of a callable that rejects CasADi symbols (at least 4 per output)


@dataclass(frozen=True)
class Samples:
    """Input samples: ``times`` [s] (non-decreasing; a time given twice is a step),
    ``values`` at those times, ``interpolation`` "linear" or "hold" (zero-order hold)."""
    times: object
    values: object
    interpolation: str = "linear"


@dataclass(frozen=True)
class InputSignal:
    """An input as an expression of time, and the times where it jumps."""
    expression: ca.SX
    events: tuple[float, ...] = ()


def input_signal(name: str, value, t: ca.SX, grid: np.ndarray) -> InputSignal:
    """The input ``name`` given as ``value`` (see the module docstring), on the output grid."""
    if isinstance(value, Samples):
        return _samples(name, value, t)
    if isinstance(value, tuple) and len(value) == 2:
        return _samples(name, Samples(*value), t)
    if callable(value):
        return _callable(name, value, t, grid)
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise SimulationError(f"input '{name}': give a number, an array of values on the output "
                              f"grid, Samples(times, values) or a function of time; got "
                              f"{value!r}") from None
    if not np.all(np.isfinite(arr)):
        raise SimulationError(f"input '{name}': values must be finite numbers, got {value!r}")
    if arr.ndim == 0:
        return InputSignal(ca.SX(float(arr)))
    if arr.size != len(grid):
        raise SimulationError(f"input '{name}': {arr.size} samples but the output grid has "
                              f"{len(grid)} points; give Samples(times, values) instead")
    return InputSignal(_linear(t, grid, arr.ravel()))


def _callable(name, f, t, grid) -> InputSignal:
    ex = _expression(f, t, grid)
    if ex is not None:
        return InputSignal(ex)
    fine = np.linspace(grid[0], grid[-1], max(FINE, 4 * len(grid)))
    try:
        vals = np.array([float(f(tk)) for tk in fine])
    except Exception as e:
        raise SimulationError(f"input '{name}': calling it with a time failed: {e}") from None
    if not np.all(np.isfinite(vals)):
        bad = fine[~np.isfinite(vals)][0]
        raise SimulationError(f"input '{name}' is not finite at t = {bad:g} s")
    warn_user(f"input '{name}': the function does not accept CasADi symbols, so it was sampled "
              f"at {fine.size} points and interpolated linearly (a jump or a held value becomes "
              f"a ramp {fine[1] - fine[0]:.3g} s wide); for exact results write it with casadi "
              f"operations (casadi.if_else, numpy ufuncs) or give "
              f"Samples(times, values, interpolation='hold' or 'linear')")
    return InputSignal(_linear(t, fine, vals))


def _expression(f, t, grid) -> ca.SX | None:
    """``f(t)`` as a scalar expression of the time symbol ``t``, or None where ``f`` does not
    give one that agrees with its finite values at numbers (at the grid's first, middle and
    last time): a function that rejects CasADi symbols, or one that turns them into NaN
    without complaint (``math.sin(t)``, ``float(t >= 1)``: Python's float() of a symbol is
    NaN). Where the function has no finite value the expression's own (inf) stands."""
    try:
        with warnings.catch_warnings():      # numpy ufuncs on SX: the casadi result is wanted
            warnings.simplefilter("ignore", FutureWarning)
            ex = f(t)
        ex = ca.SX(ex) if not isinstance(ex, ca.SX) else ex
        if ex.numel() != 1:
            return None
        at = ca.Function("input", [t], [ex])
        for tk in (grid[0], grid[len(grid) // 2], grid[-1]):
            symbolic = float(at(tk))
            try:
                numeric = float(f(float(tk)))
            except (ArithmeticError, ValueError):     # no value there (1/(1 - t) at 1)
                continue
            if np.isfinite(numeric) and not abs(symbolic - numeric) <= 1e-12 * (1 + abs(numeric)):
                return None
    except Exception:
        return None
    return ex


def _linear(t, times: np.ndarray, values: np.ndarray) -> ca.SX:
    """Linear interpolation through (times, values), strictly increasing times, extrapolated
    through the first and last two: a CasADi interpolant (a binary search per evaluation,
    not one branch per sample)."""
    return ca.interpolant("samples", "linear", [np.asarray(times, dtype=float)],
                          np.asarray(values, dtype=float))(t)


def _held(t, times: np.ndarray, values: np.ndarray) -> ca.SX:
    """values[k] from times[k] (strictly increasing) until the next time; values[0] before,
    the last value after: the sample's index by a linear interpolant of the times, rounded
    down, then its value (two binary searches per evaluation, not a branch per sample)."""
    n = times.size
    index = ca.interpolant("index", "linear", [times], np.arange(n, dtype=float))(t)
    k = ca.fmin(ca.fmax(ca.floor(index), 0), n - 1)
    return ca.interpolant("held", "linear", [np.arange(n, dtype=float)],
                          np.asarray(values, dtype=float))(k)


def _samples(name, s: Samples, t) -> InputSignal:
    tt, vv = (np.asarray(a, dtype=float).ravel() for a in (s.times, s.values))
    if s.interpolation not in ("linear", "hold"):
        raise SimulationError(f"input '{name}': interpolation must be 'linear' or 'hold', got "
                              f"{s.interpolation!r}")
    if tt.size != vv.size or tt.size < 2:
        raise SimulationError(f"input '{name}': samples need at least two times and as many "
                              f"values ({tt.size} times, {vv.size} values given)")
    if not (np.all(np.isfinite(tt)) and np.all(np.isfinite(vv))):
        raise SimulationError(f"input '{name}': sample times and values must be finite")
    if np.any(np.diff(tt) < 0) or np.any((tt[2:] == tt[1:-1]) & (tt[1:-1] == tt[:-2])):
        raise SimulationError(f"input '{name}': sample times must not decrease, and a time may "
                              f"be given at most twice (a step)")
    steps = tuple(float(a) for a, b in zip(tt[:-1], tt[1:]) if a == b)
    if s.interpolation == "hold":
        keep = np.append(tt[1:] != tt[:-1], True)       # a step: the value after it holds
        tt, vv = tt[keep], vv[keep]
        jumps = tuple(float(a) for a, dv in zip(tt[1:], np.diff(vv)) if dv != 0)
        return InputSignal(_held(t, tt, vv), jumps)
    if not steps:
        return InputSignal(_linear(t, tt, vv))
    # linear pieces between the steps, each chosen on its interval
    cuts = [0] + [i + 1 for i in range(tt.size - 1) if tt[i] == tt[i + 1]] + [tt.size]
    pieces = [(tt[a:b], vv[a:b]) for a, b in zip(cuts, cuts[1:])]
    expr = ca.SX(0)
    for k, (tk, vk) in enumerate(pieces):
        if tk.size == 1:                     # a lone sample between two steps: constant
            line = ca.SX(vk[0])
        else:
            line = _linear(t, tk, vk)
        onehot = np.zeros(len(pieces))
        onehot[k] = 1.0
        expr = expr + ca.pw_const(t, ca.DM(list(steps)), ca.DM(onehot)) * line
    return InputSignal(expr, steps)
