"""Numerical kernels shared by acausal and the pythonfmu FMU's slave.

This module imports only the standard library, numpy and casadi (no acausal, no relative
imports): the pythonfmu backend copies it into every FMU, where the slave runs without acausal.
It holds the pieces both sides run: the projection onto the initial-value equations, the time
events' rule, the restart time before an event and the readable line of a CasADi error.
"""
from __future__ import annotations

import numpy as np

__all__ = ["ProjectionError", "project", "independent_rows", "moved_note", "event_times",
           "just_before", "short_error"]


ASSEMBLY_RETRIES = 4     # restarts of a stalled projection from perturbed start values,
ASSEMBLY_JITTER = 0.1    # moved by up to ±ASSEMBLY_JITTER/2 · (1 + |value|)


class ProjectionError(ValueError):
    """The initial-value equations have no solution near the start values (message says why)."""


def project(equations, start, w0, nx: int, labels, targets, given: str = "x0"):
    """The point w = [x; z] closest to ``start`` that satisfies H(w) = 0.

    equations  w -> (H, ∂H/∂w) as numpy arrays; its first len(targets) rows are the given
               values (row i: v_i(w) − targets[i]), the others the model's equations;
    start      the start values (states 1, algebraic variables (nearly) free: metric D with
               1 for the nx states and 1e8 for the rest);
    w0         where the iteration starts (start with the given values put in);
    labels     a name per row of H, for the error message; ``given`` names the given values
               in it ("x0", "start").
    Each iteration projects the start values onto the equations linearized at the current
    point (exact in one step when they are linear); far from the solution a step moves no
    state by more than 0.3, so that a guess keeps a linkage on its branch. A start at a
    singular configuration (a linkage with every joint at 0: the residual's gradient vanishes)
    stalls the iteration; it is then restarted from a few deterministic perturbations of the
    states (up to ±ASSEMBLY_JITTER/2 · (1 + |w0|), the sequence of the native FMU's runtime, so
    that both find the same assembly). Raises ProjectionError naming the equations
    that fail, or two given values that conflict.
    """
    start = np.asarray(start, dtype=float)
    w0 = np.asarray(w0, dtype=float)
    scale = 1 + max(abs(float(v)) for v in targets) if len(targets) else 1.0
    seed = 12345
    for attempt in range(ASSEMBLY_RETRIES + 1):
        wk = w0.copy()
        for k in range(nx if attempt else 0):
            seed = (seed * 1103515245 + 12345) % 2**32         # C's unsigned arithmetic
            wk[k] += ASSEMBLY_JITTER * (1 + abs(w0[k])) * (((seed >> 8) & 0xFFFF) / 65535 - 0.5)
        wk = _iterate(equations, start, wk, nx)
        h, J = equations(wk)
        if np.max(np.abs(h), initial=0.0) <= 1e-8 * scale:
            return wk
        if attempt == 0:
            h0, J0 = h, J
    raise ProjectionError(_conflict(J0, h0, labels, targets, given))


def _iterate(equations, start, wk, nx: int):
    """The iteration of ``project`` from wk, until its step vanishes (≤ 200 iterations)."""
    D = np.ones(start.size)
    D[nx:] = 1e8
    for _ in range(200):
        h, J = equations(wk)
        # closest point to the start values (metric D⁻¹) on the linearized equations:
        #   w = start + D Jᵀ (J D Jᵀ)⁺ (J (wk − start) − h)    (J is k × n with k small)
        JD = J * D
        lam = np.linalg.lstsq(JD @ J.T, J @ (wk - start) - h, rcond=1e-14)[0]
        step = start + JD.T @ lam - wk
        big = np.max(np.abs(step[:nx]), initial=0.0)
        if big > 0.3:
            step *= 0.3 / big
        wk = wk + step
        if np.linalg.norm(step) < 1e-13 * (1 + np.linalg.norm(wk)):
            break
    return wk


def _conflict(J, h, labels, targets, given) -> str:
    bad = [labels[i] for i in np.flatnonzero(np.abs(h) > 1e-8)]
    for i in range(len(targets)):
        for j in range(i + 1, len(targets)):
            if np.linalg.matrix_rank(J[[i, j]], 1e-9) < 2:
                return (f"{given} values conflict: '{labels[i]}' = {targets[i]} and "
                        f"'{labels[j]}' = {targets[j]} cannot both hold (the parts are rigidly "
                        f"joined); give only one of them")
    return (f"cannot find initial values satisfying {', '.join(bad)}; check {given} values "
            f"against the model's constraints")


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
