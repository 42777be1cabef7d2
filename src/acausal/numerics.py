"""Numerical kernels shared by every layer of acausal and by the pythonfmu FMU's slave.

A base leaf: it imports only the standard library, numpy and casadi (no acausal, no relative
imports), so the compiler, the simulator and the analyses may all use it, and the pythonfmu
backend copies it into every FMU, where the slave runs without acausal. It holds the pieces
they share: the loop rows' independence rule, the projection onto the initial-value equations, the time
events' rule, the restart time before an event, the readable line of a CasADi error and
the message of a failed assertion.
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np

__all__ = ["parameter_problem", "row_scales", "ProjectionError", "project", "independent_rows", "moved_note", "event_times",
           "just_before", "short_error", "first_failed_assertion", "has_nan_constant"]


ASSEMBLY_RETRIES = 4     # restarts of a stalled projection from perturbed start values,
ASSEMBLY_JITTER = 0.1    # moved by up to ±ASSEMBLY_JITTER/2 · (1 + |value|)


class ProjectionError(ValueError):
    """The initial-value equations have no solution near the start values (message says why)."""


def project(equations, start, w0, nx: int, labels, targets, given: str = "x0",
            positions=None):
    """The point w = [x; z] whose states x are closest to ``start`` (least squares) and that
    satisfies H(w) = 0; the algebraic variables z are free.

    equations  w -> (H, ∂H/∂w) as numpy arrays; its first len(targets) rows are the given
               values (row i: v_i(w) − targets[i]), the others the model's equations;
    start      the start values of [x; z];
    w0         where the iteration starts (start with the given values put in);
    labels     a name per row of H, for the error message; ``given`` names the given values
               in it ("x0", "start");
    positions  indices of the states that are positions (angles: where a large step could
               jump to another assembly branch), default all states; speeds enter the
               equations linearly and are never held back.
    Each iteration projects the start values onto the equations linearized at the current
    point (exact in one step when they are linear), eliminating z by an orthogonal basis of
    the range of ∂H/∂z rather than by weights, so that stiff elements (a massless node between
    springs of 1e3 N/m) keep it well conditioned; far from the solution a step moves no state
    by more than 0.3 (``positions`` only), so that a guess keeps a linkage on its branch. Should that stall (a
    start at a singular configuration, a linkage with every joint at 0, where the residual's
    gradient vanishes), a Levenberg–Marquardt descent on the scaled residual takes over and
    the projection resumes from where it ends; as a last resort the iteration restarts from a
    few deterministic perturbations of the states (up to ±ASSEMBLY_JITTER/2 · (1 + |w0|), the
    sequence of the native FMU's runtime). Converged when every row of H, divided by its
    gradient's size, is below 1e-10 · (1 + max |w|): a distance in the variables' own units.
    Raises ProjectionError naming the equations that fail, or two given values that conflict.
    """
    start = np.asarray(start, dtype=float)
    w0 = np.asarray(w0, dtype=float)
    not_finite = _not_finite(*equations(w0)[::-1], labels)
    if not_finite:
        raise ProjectionError(not_finite)
    limited = np.arange(nx) if positions is None else np.asarray(positions, dtype=int)
    scale = 1 + max(np.abs(start).max(initial=0.0), np.abs(w0).max(initial=0.0))
    seed = 12345
    for attempt in range(ASSEMBLY_RETRIES + 1):
        wk = w0.copy()
        for k in range(nx if attempt else 0):
            seed = (seed * 1103515245 + 12345) % 2**32         # C's unsigned arithmetic
            wk[k] += ASSEMBLY_JITTER * (1 + abs(w0[k])) * (((seed >> 8) & 0xFFFF) / 65535 - 0.5)
        wk = _iterate(equations, start, wk, nx, limited)
        if not _solved(*equations(wk), scale):
            wk = _iterate(equations, start, _descend(equations, wk, limited, scale), nx,
                          limited)
        h, J = equations(wk)
        if _solved(h, J, scale):
            return wk
        if attempt == 0:
            h0, J0 = h, J
    raise ProjectionError(_conflict(J0, h0, labels, targets, given))


def row_scales(J) -> np.ndarray:
    """The size of each row's gradient (1 for a row with none)."""
    s = np.abs(J).max(axis=1, initial=0.0) if J.size else np.ones(J.shape[0])
    return np.where(s > 0, s, 1.0)


def _solved(h, J, scale: float) -> bool:
    """Every row of H, over its gradient's size, below 1e-10 · scale."""
    return bool(np.all(np.abs(h) / row_scales(J) <= 1e-10 * scale))


def _limit(step, limited, most: float = 0.3):
    """``step`` scaled down so that no entry of ``limited`` moves by more than ``most``."""
    big = np.max(np.abs(step[limited]), initial=0.0)
    return step * (most / big) if big > most else step


def _iterate(equations, start, wk, nx: int, limited):
    """The projection of ``project`` from wk, until its step vanishes (≤ 200 iterations)."""
    for _ in range(200):
        h, J = equations(wk)
        step = _limit(_projection_step(J, -h, start - wk, nx), limited)
        wk = wk + step
        if np.linalg.norm(step) < 1e-13 * (1 + np.linalg.norm(wk)):
            break
    return wk


def _projection_step(J, b, r, nx: int):
    """The step d with J d = b (least squares where inconsistent) whose state part is closest
    to r[:nx]; the algebraic part is free. With J = [Jx Jz] and P the projector onto the
    complement of range(Jz): P Jx dx = P b, dx = r_x + (P Jx)⁺ (P b − P Jx r_x), then
    dz = Jz⁺ (b − Jx dx). Orthogonal factorizations only: no normal equations."""
    s = row_scales(J)
    J, b = J / s[:, None], b / s                  # rows scaled: each in its own unit
    Jx, Jz = J[:, :nx], J[:, nx:]
    if Jz.shape[1]:
        U, sv, _ = np.linalg.svd(Jz, full_matrices=False)
        U = U[:, sv > 1e-12 * max(1.0, sv.max(initial=0.0))]
        P = np.eye(J.shape[0]) - U @ U.T
    else:
        P = np.eye(J.shape[0])
    PJx = P @ Jx
    rx = r[:nx]
    dx = rx + _lstsq(PJx, P @ b - PJx @ rx)
    dz = _lstsq(Jz, b - Jx @ dx) if Jz.shape[1] else np.zeros(0)
    return np.concatenate([dx, dz])


def _lstsq(A, b):
    """The minimum-norm least-squares solution of A x = b, singular values of A below
    1e-12 · max(1, σ_max) taken as 0. The cut is absolute for rows of unit size (as the
    scaled rows here): when z takes up every equation, P·Jx is rounding noise (1e-16) that a
    cut relative to its own σ_max would invert into a step of the states."""
    U, sv, Vt = np.linalg.svd(A, full_matrices=False)
    keep = sv > 1e-12 * max(1.0, sv.max(initial=0.0))
    return Vt[keep].T @ ((U[:, keep].T @ b) / sv[keep])


def _descend(equations, wk, limited, scale: float, iterations: int = 100):
    """Levenberg–Marquardt on the row-scaled residual from wk: minimum-norm damped steps
    d = −Jᵀ (J Jᵀ + μ I)⁻¹ h, μ adapted to the progress (a singular Jacobian is no
    obstacle), no position moved by more than 0.3 a step. Returns the best point reached."""
    h, J = equations(wk)
    s = row_scales(J)
    cost, mu = float(np.sum((h / s) ** 2)), 1e-3
    for _ in range(iterations):
        Js, hs = J / s[:, None], h / s
        d = -Js.T @ np.linalg.lstsq(Js @ Js.T + mu * np.eye(len(hs)), hs, rcond=None)[0]
        d = _limit(d, limited)
        h_new, J_new = equations(wk + d)
        cost_new = float(np.sum((h_new / s) ** 2))
        if cost_new < cost:
            wk, h, J, cost, mu = wk + d, h_new, J_new, cost_new, max(mu / 10, 1e-12)
            if _solved(h, J, scale):
                break
        else:
            mu *= 10
            if mu > 1e12:
                break
    return wk


def _not_finite(J, h, labels) -> str | None:
    """The error for rows of H (or of its Jacobian) that are NaN or inf, or None."""
    rows = np.flatnonzero(~(np.isfinite(h) & np.all(np.isfinite(J), axis=1)))
    if not rows.size:
        return None
    one = rows.size == 1
    return (f"cannot find initial values: {', '.join(labels[i] for i in rows)} "
            f"{'is' if one else 'are'} not finite (NaN or inf) at the start; check the inputs "
            f"and parameters {'it uses' if one else 'they use'} (an input that is NaN, a "
            f"division by a parameter that is 0)")


def _conflict(J, h, labels, targets, given) -> str:
    not_finite = _not_finite(J, h, labels)
    if not_finite:
        return not_finite
    bad = [labels[i] for i in np.flatnonzero(np.abs(h) / row_scales(J) > 1e-10)]
    for i in range(len(targets)):
        for j in range(i + 1, len(targets)):
            if np.linalg.matrix_rank(J[[i, j]], 1e-9) < 2:
                return (f"{given} values conflict: '{labels[i]}' = {targets[i]} and "
                        f"'{labels[j]}' = {targets[j]} cannot both hold (the parts are rigidly "
                        f"joined); give only one of them")
    fixed = [labels[i] for i in np.flatnonzero(np.abs(h) / row_scales(J) > 1e-10)
             if i >= len(targets) and not np.any(J[i])]
    if fixed:                    # no start value moves these: time, inputs, parameters do
        which = "no start value enters it" if fixed == bad else \
            f"no start value enters {', '.join(fixed)}"
        return (f"cannot find initial values satisfying {', '.join(bad)}: {which} (it holds "
                f"or fails with the time, inputs and parameters at the start alone, e.g. a "
                f"steady start under an input that keeps the state moving, or a loop of blocks "
                f"whose gain is exactly 1); change those, the component's initialization "
                f"(initType), or the loop's gains")
    return (f"cannot find initial values satisfying {', '.join(bad)}; check {given} values "
            f"against the model's constraints")


def parameter_problem(name: str, value: float, description: str = "", unit: str = "", *,
                      positive: bool = False, nonnegative: bool = False,
                      nonzero: bool = False) -> str | None:
    """What is wrong with ``value`` for the parameter ``name`` under its declared rule
    (finite; > 0, >= 0, != 0 as declared), as the message to show, or None: the one rule
    for a parameter's value, wherever it is set (construction, simulate, the FMUs)."""
    what = description or name.rsplit(".", 1)[-1]
    if not math.isfinite(value):
        unit = f" [{unit}]" if unit else ""
        return f"parameter '{name}' must be a finite number, got {value}: give it a finite " \
               f"value{unit}"
    if positive and not value > 0:
        return f"parameter '{name}' must be > 0 ({what}), got {value}"
    if nonnegative and not value >= 0:
        return f"parameter '{name}' must be >= 0 ({what}), got {value}"
    if nonzero and value == 0:
        return f"parameter '{name}' must not be 0 ({what})"
    return None


def has_nan_constant(ex: ca.SX) -> bool:
    """Whether the expression holds a NaN constant: what Python's float() (and the math
    module) make of a CasADi symbol, without complaint."""
    f = ca.Function("f", ca.symvar(ex), [ex])
    return any(f.instruction_id(k) == ca.OP_CONST and math.isnan(f.instruction_constant(k))
               for k in range(f.n_instructions()))


def independent_rows(J) -> np.ndarray:
    """1 for each row of the constraint Jacobian J that adds to the rank of the rows on before
    it, 0 for the others: the loop rows to enforce at a configuration. In row order, a row is
    on when its Gram–Schmidt residual against the rows on before it exceeds
    1e-9 · max(1, max |J|); the native FMU's runtime applies the same rule
    (``select_loop_rows`` in fmu/c/loops.c)."""
    J = np.asarray(J, dtype=float)
    tol = 1e-9 * max(1.0, np.abs(J).max(initial=0.0))
    active, basis = np.zeros(J.shape[0]), []
    for i, row in enumerate(J):
        r = row.copy()
        for _ in range(2):                       # twice: orthogonal to rounding
            for b in basis:
                r -= (b @ r) * b
        norm = np.linalg.norm(r)
        if norm > tol:
            active[i] = 1.0
            basis.append(r / norm)
    return active


def moved_note(names, before, after, held=()) -> str | None:
    """The note that closing the kinematic loops moved the states ``names`` (other than the
    ``held`` ones) from ``before`` to ``after``; None if none moved."""
    moved = [f"{n}: {a:.6g} -> {b:.6g}" for n, a, b in zip(names, before, after)
             if n not in held and abs(a - b) > 1e-9 * (1 + abs(a))]
    if not moved:
        return None
    return "initial values changed to close the kinematic loops: " + "; ".join(moved)


def event_times(times, periods, t0: float, t1: float) -> list[float]:
    """The time events strictly inside (t0, t1), sorted: event i at ``times[i]``, repeated
    every ``periods[i]`` when that is > 0."""
    out = set()
    times, periods = (np.array(v, dtype=float).ravel() for v in (times, periods))
    for first, period in zip(times, periods):
        if period > 0:
            k0 = max(0, int(np.ceil((t0 - first) / period)))
            ts = first + period * np.arange(k0, k0 + int((t1 - first) / period) + 2)
        else:
            ts = [first]
        out.update(float(x) for x in ts if t0 < x < t1)
    return sorted(out)


def just_before(t: float) -> float:
    """Where integration towards an event at t stops (it restarts at t: never step over a
    jump)."""
    return t - 1e-12 * max(1.0, abs(t))


def short_error(e: Exception) -> str:
    """The informative line of a CasADi error (what the solver returned), not its call chain."""
    lines = [ln.strip() for ln in str(e).splitlines() if ln.strip()]
    for key in ("returned", "At t =", "failed", "Error"):
        hits = [ln for ln in lines if key in ln]
        if hits:
            return hits[-1].split(": ", 1)[-1][:300]
    return (lines[-1] if lines else str(e))[:300]


def first_failed_assertion(held, times, texts) -> tuple[int, str] | None:
    """Of the components' assertions evaluated at points (``held``: one row per assertion,
    one column per point, > 0.5 where it holds; ``times`` of the points; ``texts``: the
    (component, message) of each row): the first point where one fails and what failed
    (the component, its message and the time), or None."""
    held = np.asarray(held, dtype=float).reshape(len(texts), -1) > 0.5
    failed = np.flatnonzero(~held.all(axis=0))
    if not failed.size:
        return None
    k = int(failed[0])
    component, text = texts[int(np.argmin(held[:, k]))]
    return k, (f"'{component}': {text} (assertion failed at t = "
               f"{float(np.ravel(times)[k]):.6g} s)")
