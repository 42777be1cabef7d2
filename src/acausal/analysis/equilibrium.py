"""Static equilibrium: q̇ = q̈ = 0 (and every other state at rest) for given inputs and
parameters.

The unknowns are all states x and algebraic variables z; the equations are the model's own,
ẋ = f(x, z, u, p, t) = 0 and 0 = g(x, z, u, p, t): for a mechanism, v = 0, the net
generalized forces vanish and, with closed loops, Φ(q) = 0 (their GGL multipliers μ, ν then
vanish too). They are solved by Gauss–Newton from the start values (``guess`` by state name),
the loops assembled first, with steps limited so the solution stays on the branch of the
guess; a singular Jacobian (a free rigid-body motion, a neutral direction) gives the
equilibrium closest to the guess. The loop multipliers λ [N or N.m, per constraint row] come
from Φ_qᵀ λ = −R0(q, 0) (R0: everything but inertia in M q̈ + R0 + Φ_qᵀ λ = 0); the joint
reactions are the recorded port flows, e.g. ``eq["rev4.frame_a.fx"]``.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import casadi as ca
import numpy as np

from ..errors import AnalysisError
from ..numerics import row_scales
from .point import OperatingPoint, in_modes, modes_of, operating_point

MODE_ROUNDS = 5           # solves with the modes found at the last equilibrium, at most


@dataclass
class Equilibrium(OperatingPoint):
    """An equilibrium point (an OperatingPoint: ``eq["name"]`` is any variable there);
    ``multipliers``: the loop constraints' λ by row name; ``residual``: max |ẋ|, |g| there."""
    multipliers: dict = field(default_factory=dict)
    residual: float = 0.0


def equilibrium(model, *, u: dict | None = None, params: dict | None = None, t: float = 0.0,
                guess: dict | None = None, tol: float = 1e-10, max_iter: int = 100,
                mode: dict | None = None) -> Equilibrium:
    """The equilibrium of ``model`` at time t [s] with inputs ``u`` and parameters ``params``
    (by name), nearest to ``guess`` (state names -> values; default the start values).
    Converged when every equation, divided by the size of its gradient (a distance in the
    variables' own units, whatever the stiffness: 1e9 N/m on 1 mg as well as 1 N/m on 1 kg),
    is below ``tol`` · (1 + max |x, z|). Raises AnalysisError naming the equations that do
    not vanish when none is found.

    A model with discrete modes is solved in the modes ``mode`` (name -> value, held) and,
    for the others, those the event iteration finds at the guess, then again at the
    equilibrium found until they agree (a block on friction at rest under a load below
    breakaway: stuck, anywhere; a stuck friction element holds a whole range of positions,
    and the one nearest the guess is returned). ``Equilibrium.mode`` says which."""
    if not (isinstance(tol, (int, float)) and math.isfinite(tol) and tol > 0):
        raise AnalysisError(f"tol must be a finite number > 0, got {tol!r}")
    if not (isinstance(max_iter, int) and max_iter >= 1):
        raise AnalysisError(f"max_iter must be a whole number >= 1, got {max_iter!r}")
    with warnings.catch_warnings():          # the guess is moved onto the loops: expected
        warnings.filterwarnings("ignore", message="initial values changed")
        start = operating_point(model, {}, u=u, params=params, t=t, guess=guess, mode=mode)
    p, uv = start.p, start.u
    w_sym = ca.vertcat(model.x, model.z)
    H = ca.vertcat(model.ode, model.alg)
    F = ca.Function("equilibrium", [model.t, w_sym, model.u, model.p],
                    [H, ca.jacobian(H, w_sym)])
    nx = len(model.x_names)
    w = np.concatenate([start.x, start.z])
    for _ in range(MODE_ROUNDS):
        w = _solve(model, F, t, w, uv, p, tol, max_iter)
        x, z, p_new = in_modes(model, float(t), w[:nx], w[nx:], uv, p, mode)
        if np.array_equal(p_new, p):
            break
        p, w = p_new, np.concatenate([x, z])
    else:
        raise AnalysisError(f"equilibrium of '{model.name}': the discrete modes do not settle "
                            f"(last {modes_of(model, p)}); give them with mode=")
    h = _eval(F, t, w, uv, p)[0]
    x, z = w[:nx], w[nx:]
    return Equilibrium(model, float(t), x, z, p, uv, modes_of(model, p),
                       _multipliers(model, x, z, p, uv, t), float(np.max(np.abs(h), initial=0.0)))


def _solve(model, F, t, w, uv, p, tol, max_iter) -> np.ndarray:
    """Gauss–Newton on the scaled equations from w (see ``equilibrium``)."""
    nx = len(model.x_names)

    def converged(h, J, w):
        return np.all(np.abs(h) / row_scales(J) <= tol * (1 + np.abs(w).max(initial=0.0)))

    for _ in range(max_iter):
        h, J = _eval(F, t, w, uv, p)
        if converged(h, J, w):
            break
        scale = row_scales(J)              # rows in their own units: well conditioned
        step = -np.linalg.lstsq(J / scale[:, None], h / scale, rcond=1e-13)[0]
        big = np.max(np.abs(step[:nx]), initial=0.0)
        if big > 0.5:                      # stay on the guess's branch
            step *= 0.5 / big
        norm0 = np.linalg.norm(h / scale)
        for _ in range(30):                # backtrack while the residual grows
            h_new = _eval(F, t, w + step, uv, p)[0]
            if np.linalg.norm(h_new / scale) < norm0 or np.linalg.norm(step) < 1e-14:
                break
            step = step / 2
        w = w + step
        if np.linalg.norm(step) < 1e-15 * (1 + np.linalg.norm(w)):
            break
    h, J = _eval(F, t, w, uv, p)
    if not converged(h, J, w):
        given = dict(zip(model.input_names, map(float, uv)))
        modes = f" in modes {modes_of(model, p)}" if model.mode_params else ""
        raise AnalysisError(f"no equilibrium of '{model.name}' found near the guess (inputs "
                            f"{given}{modes}): these do not vanish: "
                            f"{_name_residuals(model, h / row_scales(J), tol)}; "
                            f"change the inputs, parameters or guess")
    return w


def _eval(F, t, w, u, p):
    h, J = F(t, w, u, p)
    return np.array(h, dtype=float).ravel(), np.array(J, dtype=float)


def _name_residuals(model, h, tol) -> str:
    rows = model.loop_rows
    names = [f"d({n})/dt" for n in model.x_names]
    names += [f"algebraic equation of {n}" for n in model.z_names]
    for row, k in enumerate(model.loop_mu):
        names[len(model.x_names) + k] = f"loop constraint {rows[row]}"
    for row, k in enumerate(model.loop_nu):
        names[len(model.x_names) + k] = f"rate of loop constraint {rows[row]}"
    order = np.argsort(-np.abs(h))
    return ", ".join(f"{names[k]} = {h[k]:.3g}" for k in order if abs(h[k]) > tol)


def _multipliers(model, x, z, p, u, t) -> dict:
    L = model.lagrange
    if not model.has_loops:
        return {}
    f = model.function("loops", [L.R0, L.phi_q])
    R0, Pq = (np.array(v, dtype=float) for v in f(t, x, z, u, p))
    lam = np.linalg.lstsq(Pq.T, -R0.ravel(), rcond=None)[0]
    return dict(zip(model.loop_rows, map(float, lam)))
