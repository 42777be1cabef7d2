"""Consistent initial values from values given by the dotted names of any variable.

The given values are hard equations v_i(x, z) = value_i; closed loops add Φ = 0 and Φ̇ = 0;
algebraic equations 0 = alg hold. Among the states that satisfy them, the ones chosen are
closest (least squares) to the states' start values. Solved by Gauss–Newton on the hard
equations with the soft ones projected onto their null space; exact in one step for linear
(1-D) kinematics.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..core.errors import InitializationError


def initial_state(model, x0: dict, p: np.ndarray, u0: np.ndarray, t0: float):
    """(x, z) consistent with ``x0`` (names → values) at time t0 with parameters p."""
    w = ca.vertcat(model.x, model.z)
    nx = model.x.numel()
    hard, labels, targets = [], [], []
    for name, value in x0.items():
        if name in model.x_names:
            ex = model.x[model.x_names.index(name)]
        elif name in model.z_names:
            ex = model.z[model.z_names.index(name)]
        else:
            try:
                ex = model.expression(name)
            except KeyError as e:
                raise InitializationError(f"x0: {e.args[0]}") from None
        if not ca.depends_on(ex, w):
            raise InitializationError(f"x0: '{name}' does not depend on any state (it is fixed "
                                      f"by the model); remove it from x0")
        hard.append(ex)
        labels.append(name)
        targets.append(float(value))
    eqs = [h - v for h, v in zip(hard, targets)]
    phi = model.equations.phi
    if phi.numel():
        eqs += [phi, ca.jtimes(phi, model.equations.q, model.equations.qd)
                + ca.jacobian(phi, model.t)]
        labels += [f"loop constraint {i}" for i in range(phi.numel())] * 2
    if model.z.numel():
        eqs.append(model.alg)
        labels += [f"algebraic equation for {n}" for n in model.z_names]
    H = ca.vertcat(*[ca.vec(e) for e in eqs]) if eqs else ca.SX(0, 1)
    f = ca.Function("init", [w, model.t, model.p, model.u], [H, ca.jacobian(H, w)])
    start = np.array(list(model.x_start) + list(model.z_start), dtype=float)
    wk = start.copy()
    ngiven = len(hard)
    for _ in range(50):
        h, J = (np.array(a, dtype=float) for a in f(wk, t0, p, u0))
        h = h.ravel()
        if h.size == 0:
            break
        # step: satisfy hard equations (min-norm), then move towards starts in the null space
        Jp = np.linalg.pinv(J, rcond=1e-10)
        step = -Jp @ h
        N = np.eye(w.numel()) - Jp @ J
        step += N @ (start - wk - step)
        wk = wk + step
        if np.linalg.norm(step) < 1e-13 * (1 + np.linalg.norm(wk)):
            break
    h, J = (np.array(a, dtype=float) for a in f(wk, t0, p, u0))
    h = h.ravel()
    if h.size and np.max(np.abs(h)) > 1e-8 * (1 + np.max(np.abs(targets or [0]))):
        raise InitializationError(_conflict(f, wk, t0, p, u0, labels, targets, ngiven, h))
    return wk[:nx], wk[nx:]


def _conflict(f, wk, t0, p, u0, labels, targets, ngiven, h) -> str:
    bad = [labels[i] for i in np.flatnonzero(np.abs(h) > 1e-8)]
    _, J = (np.array(a, dtype=float) for a in f(wk, t0, p, u0))
    given = list(range(ngiven))
    for i in given:
        for j in given:
            if j <= i:
                continue
            sub = J[[i, j]]
            if np.linalg.matrix_rank(sub, 1e-9) < 2:
                return (f"x0 values conflict: '{labels[i]}' = {targets[i]} and '{labels[j]}' = "
                        f"{targets[j]} cannot both hold (the parts are rigidly joined); give "
                        f"only one of them")
    return (f"cannot find initial values satisfying {', '.join(bad)}; check x0 against the "
            f"model's constraints")
