"""Consistent initial values from values given by the dotted names of any variable.

The given values are hard equations v_i(x, z) = value_i; closed loops add Φ = 0 and Φ̇ = 0;
algebraic equations 0 = alg hold. Among the states that satisfy them, the ones chosen are
closest (least squares) to the states' start values, algebraic variables being free: each
iteration projects the start values onto the equations linearized at the current point
(exact in one step for 1-D kinematics). Guessed values (Modelica's start values of variables
that are not fixed) replace the start values first: a guessed state's start is the guess; a
guess on any other variable g(x, z) = value (a joint angle that is no coordinate, a port's
position) moves the start values the least that gives it that value, the given values held,
so that it pulls the projection towards it as a start value does, without being held.
At a simulation's start the components' initial equations (``PhysicsBuilder.initial``: a
motor started in steady state, der(C.v) = 0) are hard equations too, next to x0 (with the
modes at their start values). The cost grows with the number of equations k (a k × k system), not with the model
size.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..errors import InitializationError, warn_user
from ..numerics import ProjectionError, moved_note, project


def initial_state(model, x0: dict, p: np.ndarray, u0: np.ndarray, t0: float,
                  guess: dict | None = None, initial_equations: bool = False):
    """(x, z) consistent with ``x0`` (names → values, held exactly) at time t0 with
    parameters p, closest to the start values, moved first by ``guess`` (names of any
    variables → values, see the module's docstring); with ``initial_equations`` (a
    simulation's start) the components' initial equations held too (an operating point of
    the analyses is where its x puts it). Closed loops are assembled this way:
    fix the driving joint in x0, guess the other joints (or the joint that closes the loop)
    on the branch wanted. Warns, naming them, when loop assembly moved states off their
    guess or start value."""
    w = ca.vertcat(model.x, model.z)
    nx = model.x.numel()
    names = model.x_names + model.z_names
    x0, guess = by_angles(model, x0, p), by_angles(model, guess, p)
    more, more_labels = model_equations(model)
    if initial_equations and model.initial_equations.numel():
        more, more_labels = more + [model.initial_equations], more_labels + model.initial_labels
    start = np.array(model.start(p), dtype=float).ravel()
    guess = dict(guess or {})
    soft = {n: v for n, v in guess.items() if n not in names}
    for name, value in guess.items():
        if name in names:
            start[names.index(name)] = float(value)
    wk = start.copy()
    for name, value in x0.items():          # linearize where the fixed values put the states
        if name in names:
            wk[names.index(name)] = float(value)
    if not soft and not more and all(n in names[:nx] for n in x0):
        return wk[:nx], wk[nx:]                  # states given: nothing to solve
    given = _rows(model, "x0", x0, w)
    eqs = [h - v for h, v in zip(given, x0.values())]
    labels, targets = list(x0), [float(v) for v in x0.values()]
    if soft:                                # the start values that give the guessed values
        rows = eqs + [g - v for g, v in zip(_rows(model, "guess", soft, w), soft.values())]
        start = wk = _project(model, rows, labels + list(soft),
                              targets + [float(v) for v in soft.values()], start, wk, nx,
                              (t0, u0, p), "x0 and guess")
    if not eqs + more:
        return start[:nx], start[nx:]
    wk = _project(model, eqs + more, labels + more_labels, targets, start, wk, nx, (t0, u0, p),
                  "x0")
    note = moved_note(names[:nx], start, wk, held=x0) if model.has_loops else None
    if note:
        warn_user(note)
    return wk[:nx], wk[nx:]


def by_angles(model, values: dict | None, p: np.ndarray) -> dict:
    """``values`` (x0 or guess) with the three angles of a free rotation given by name (a
    Spherical joint's, a FreeMotion's or a free Body's phi[1..3]) replaced by its quaternion
    states, and the three rates (phi_d[1..3]) given with them by its angular velocity
    states (``charts.AngleStart``): exact for any angles, where a projection onto the
    recorded angles would be singular at gimbal lock and miss angles beyond their range.
    Angles given in part are completed by the start orientation's (the recorded angles at
    the states' start values)."""
    out = dict(values or {})
    for a in model.angle_starts:
        if not any(n in out for n in a.angles):
            continue
        if not all(n in out for n in a.angles):
            at_start = _start_values(model, a.angles, p)
            out.update({n: v for n, v in zip(a.angles, at_start) if n not in out})
        phi = [float(out.pop(n)) for n in a.angles]
        rates = [float(out.pop(n)) for n in a.rates] if all(n in out for n in a.rates) \
            else None
        Q, w = a.function(phi, rates or [0.0] * 3, p)
        out.update(zip(a.Q, np.array(Q, dtype=float).ravel()))
        if rates is not None:
            out.update(zip(a.w, np.array(w, dtype=float).ravel()))
    return out


def _start_values(model, names, p: np.ndarray) -> list[float]:
    """The variables ``names`` (of the states and parameters only) at the states' start
    values."""
    f = ca.Function("at_start", [model.x, model.p], [ca.vertcat(*[model.expression(n)
                                                                 for n in names])])
    x = np.array(model.start(p), dtype=float).ravel()[:model.x.numel()]
    return [float(v) for v in np.array(f(x, p)).ravel()]


def _rows(model, what: str, values: dict, w: ca.SX) -> list:
    """The expressions of the variables named in ``values`` (x0 or guess), each depending
    on the states; InitializationError naming the first that is unknown or fixed."""
    rows = []
    for name in values:
        try:
            ex = model.expression(name)
        except KeyError as e:
            raise InitializationError(f"{what}: {e.args[0]}") from None
        if not ca.depends_on(ex, w):
            raise InitializationError(f"{what}: '{name}' does not depend on any state (it is "
                                      f"fixed by the model); remove it from {what}")
        rows.append(ex)
    return rows


def _project(model, eqs, labels, targets, start, wk, nx, point, given):
    """``numerics.project`` of ``start`` onto eqs = 0 (its first len(targets) rows the given
    values), iterating from wk at point = (t0, u0, p)."""
    w = ca.vertcat(model.x, model.z)
    H = ca.vertcat(*[ca.vec(e) for e in eqs])
    f = ca.Function("init", [model.t, w, model.u, model.p], [H, ca.jacobian(H, w)])
    t0, u0, p = point

    def equations(wk):
        h, J = f(t0, wk, u0, p)
        return np.array(h, dtype=float).ravel(), np.array(J, dtype=float)

    try:
        return project(equations, start, wk, nx, labels, targets, given,
                       positions=model.position_states)
    except ProjectionError as e:
        raise InitializationError(str(e)) from None


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
