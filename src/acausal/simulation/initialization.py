"""Consistent initial values from values given by the dotted names of any variable.

The given values are hard equations v_i(x, z) = value_i; closed loops add Φ = 0 and Φ̇ = 0;
algebraic equations 0 = alg hold. Among the states that satisfy them, the ones chosen are
closest (least squares) to the states' start values, algebraic variables being free: each
iteration projects the start values onto the equations linearized at the current point (exact in one step for 1-D kinematics).
The cost grows with the number of equations k (a k × k system), not with the model size.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..errors import InitializationError, warn_user
from ..numerics import ProjectionError, moved_note, project


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
    for name, value in x0.items():
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
    more, more_labels = model_equations(model)
    eqs += more
    labels += more_labels
    start = np.array(model.start(p), dtype=float).ravel()
    for name, value in (guess or {}).items():
        if name not in names:
            raise InitializationError(f"guess: '{name}' is not a state of '{model.name}' (its "
                                      f"states: {', '.join(names[:8])}...)")
        start[names.index(name)] = float(value)
    if not eqs:
        return start[:nx], start[nx:]
    H = ca.vertcat(*[ca.vec(e) for e in eqs])
    f = ca.Function("init", [model.t, w, model.u, model.p], [H, ca.jacobian(H, w)])

    def equations(wk):
        h, J = f(t0, wk, u0, p)
        return np.array(h, dtype=float).ravel(), np.array(J, dtype=float)

    wk = start.copy()
    for name, value in x0.items():          # linearize where the fixed values put the states
        if name in names:
            wk[names.index(name)] = float(value)
    try:
        wk = project(equations, start, wk, nx, labels, targets, positions=model.position_states)
    except ProjectionError as e:
        raise InitializationError(str(e)) from None
    note = moved_note(names[:nx], start, wk, held=x0) if model.has_loops else None
    if note:
        warn_user(note)
    return wk[:nx], wk[nx:]


def model_equations(model):
    """The equations every initial state satisfies besides the given values, as a list of SX
    in (t, x, z, u, p), and a label per row: closed loops' Φ = 0 and Φ̇ = 0 ("loop constraint
    <row>", "loop velocity constraint <row>"), then the algebraic equations."""
    eqs, labels = [], []
    phi = model.lagrange.phi
    if model.has_loops:
        # Φ̇ along the model's own motion (states other than q, e.g. a Speed source's angle,
        # may enter Φ), with the stabilizing multipliers at their consistent value 0
        xdot = ca.substitute(model.ode, model.z, ca.SX.zeros(model.z.numel()))
        eqs += [phi, ca.jtimes(phi, model.x, xdot) + ca.jacobian(phi, model.t)]
        labels += [f"loop constraint {n}" for n in model.loop_rows]
        labels += [f"loop velocity constraint {n}" for n in model.loop_rows]
    if model.z.numel():
        eqs.append(model.alg)
        labels += [f"algebraic equation for {n}" for n in model.z_names]
    return eqs, labels
