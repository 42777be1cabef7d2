"""Consistent initial values from values given by the dotted names of any variable.

The given values are hard equations v_i(x, z) = value_i; closed loops add Φ = 0 and Φ̇ = 0;
algebraic equations 0 = alg hold. Among the states that satisfy them, the ones chosen are
closest (least squares) to the states' start values, algebraic variables being free: each
iteration projects the start values onto the equations linearized at the current point (exact in one step for 1-D kinematics).
The cost grows with the number of equations k (a k × k system), not with the model size.
"""
from __future__ import annotations

import warnings

import casadi as ca
import numpy as np

from ..core.errors import InitializationError


def initial_state(model, x0: dict, p: np.ndarray, u0: np.ndarray, t0: float,
                  guess: dict | None = None):
    """(x, z) consistent with ``x0`` (names → values, held exactly) at time t0 with
    parameters p, closest to the start values, where ``guess`` (state names → values)
    replaces them. Closed loops are assembled this way: fix the driving joint in x0, guess
    the others. Warns, naming them, when loop assembly moved states off their guess or start
    value."""
    w = ca.vertcat(model.x, model.z)
    nx = model.x.numel()
    hard, labels, targets = [], [], []
    names = model.x_names + model.z_names
    direct = dict(zip(names, ca.vertsplit(w)))
    for name, value in x0.items():
        if name in direct:
            ex = direct[name]
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
    phi = model.lagrange.phi
    if phi.numel():
        # Φ̇ along the model's own motion (states other than q, e.g. a Speed source's angle,
        # may enter Φ), with the stabilizing multipliers at their consistent value 0
        xdot = ca.substitute(model.ode, model.z, ca.SX.zeros(model.z.numel()))
        eqs += [phi, ca.jtimes(phi, model.x, xdot) + ca.jacobian(phi, model.t)]
        labels += [f"loop constraint {n}" for n in model.loop_rows]
        labels += [f"loop velocity constraint {n}" for n in model.loop_rows]
    if model.z.numel():
        eqs.append(model.alg)
        labels += [f"algebraic equation for {n}" for n in model.z_names]
    start = np.array(model.start(p), dtype=float).ravel()
    for name, value in (guess or {}).items():
        if name not in direct:
            raise InitializationError(f"guess: '{name}' is not a state of '{model.name}' (its "
                                      f"states: {', '.join(names[:8])}...)")
        start[names.index(name)] = float(value)
    if not eqs:
        return start[:nx], start[nx:]
    H = ca.vertcat(*[ca.vec(e) for e in eqs])
    f = ca.Function("init", [w, model.t, model.p, model.u], [H, ca.jacobian(H, w)])
    wk = start.copy()
    for name, value in x0.items():          # linearize where the fixed values put the states
        if name in names:
            wk[names.index(name)] = float(value)
    scale = 1 + max(abs(v) for v in targets) if targets else 1.0
    # states keep their start values where they can; algebraic variables are (nearly) free
    D = np.ones(w.numel())
    D[nx:] = 1e8
    for _ in range(200):
        h, J = _eval(f, wk, t0, p, u0)
        # closest point to the start values (metric D⁻¹) on the linearized equations:
        #   w = start + D Jᵀ (J D Jᵀ)⁺ (J (wk − start) − h)    (J is k × n with k small);
        # far from the solution the step is limited (0.3 per state), so that a guess keeps
        # the assembly on its branch instead of winding joints by whole turns
        JD = J * D
        lam = np.linalg.lstsq(JD @ J.T, J @ (wk - start) - h, rcond=1e-14)[0]
        step = start + JD.T @ lam - wk
        big = np.max(np.abs(step[:nx]), initial=0.0)
        if big > 0.3:
            step *= 0.3 / big
        wk = wk + step
        if np.linalg.norm(step) < 1e-13 * (1 + np.linalg.norm(wk)):
            break
    h, J = _eval(f, wk, t0, p, u0)
    if np.max(np.abs(h)) > 1e-8 * scale:
        raise InitializationError(_conflict(J, labels, targets, len(hard), h))
    if phi.numel():
        moved = [f"{n}: {a:.6g} -> {b:.6g}" for n, a, b in zip(names[:nx], start, wk)
                 if n not in x0 and abs(a - b) > 1e-9 * (1 + abs(a))]
        if moved:
            warnings.warn("initial values changed to close the kinematic loops: "
                          + "; ".join(moved), stacklevel=3)
    return wk[:nx], wk[nx:]


def _eval(f, w, t0, p, u0):
    h, J = f(w, t0, p, u0)
    return np.array(h, dtype=float).ravel(), np.array(J, dtype=float)


def _conflict(J, labels, targets, ngiven, h) -> str:
    bad = [labels[i] for i in np.flatnonzero(np.abs(h) > 1e-8)]
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
