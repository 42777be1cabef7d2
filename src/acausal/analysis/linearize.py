"""Linearization of a compiled model about an operating point: A, B, C, D by name.

ODE models: A = ∂f/∂x, B = ∂f/∂u, C = ∂y/∂x, D = ∂y/∂u by algorithmic differentiation.
Algebraic variables that are not loop multipliers (massless nodes, components' algebraic
variables) are eliminated by the implicit function theorem: δz = −g_z⁻¹ (g_x δx + g_u δu).

Closed loops (reduction to independent coordinates): the compiled model's states hold all
coordinates q and rates v, tied by Φ(q, t) = 0 and Φ̇ = Φ_q v + Φ_t = 0 (its GGL multipliers
μ, ν vanish on these). At the point, the rank-revealing QR factorization (column pivoting)
of Φ_q picks r = rank Φ_q dependent coordinates q_D (the best-conditioned block Φ_D; or the
complement of ``independent``, if given); the others q_I are independent. A change of the
independent states δx_I = (δq_I, δv_I, δ other) fixes the dependent ones through the
linearized constraints:

    δq_D = −Φ_D⁺ (Φ_I δq_I + Φ_o δo),  δv_D = −Φ_D⁺ (Φ_I δv_I + ∂Φ̇/∂q δq + ∂Φ̇/∂o δo),

i.e. δq lies in the null space of Φ_q (velocities likewise, plus the curvature term that
vanishes at rest). With δx_full = T δx_I: A = S (∂f/∂x) T, B = S ∂f/∂u, C = (∂y/∂x) T,
D = ∂y/∂u, where S picks the independent rows: the reduced model is exact to first order on
the constraint manifold and has no spurious (constraint) eigenvalues.

Quaternion states (free bodies, Spherical and FreeMotion joints: ``compiler.charts``): by
default the linear model is in the model's own states (Q[1..4] with its norm-keeping
eigenvalue). With ``tangent`` (and always with closed loops) each Q is replaced by the
minimal tangent coordinates θ[1..3] of its chart, the small rotation resolved in the frame
(θ̇ = w at the point): δQ = ½·G(Q)·δθ (G of MSL's quaternion rate, orthonormal columns at
|Q| = 1, so δθ = 2·G(Q)ᵀ·δQ and the norm direction Q drops out); then the coordinates are
(θ, the joints'), their rates (w, ...), and the mass matrix is Lagrange's M in them, as
``modes`` needs.
"""
from __future__ import annotations

import casadi as ca
import numpy as np
import scipy.linalg

from ..errors import AnalysisError
from ..frames import Q_rate
from .linear import LinearModel
from .point import index_of, operating_point


def linearize(model, x=None, *, u: dict | None = None, params: dict | None = None,
              t: float = 0.0, guess: dict | None = None, inputs: list[str] | None = None,
              outputs: list[str] | None = None,
              independent: list[str] | None = None, mode: dict | None = None,
              tangent: bool = False) -> LinearModel:
    """The linear model of ``model`` about the point x (an OperatingPoint, e.g. from
    ``equilibrium``, or values by the name of any variable, assembled as simulate's x0),
    with inputs u and parameters ``params`` by name at time t [s].

    mode        a model with discrete modes is linearized in one set of them: these (name
                -> value, e.g. {"friction.mode": 0}: stuck, the friction a rigid lock;
                1: sliding forward, the friction force F(w)), the others as the event
                iteration finds them at the point (as simulate at its start); the
                LinearModel's ``mode`` says which were used;

    inputs      names of the model's Inputs to keep as columns of B, D (default: all);
    outputs     names of any recorded variables (default: the model's Outputs);
    independent coordinates to keep as states of a model with closed loops (default: chosen
                by QR with column pivoting of Φ_q; see the module docstring);
    tangent     quaternion states replaced by their charts' tangent coordinates θ (see the
                module docstring; always so with closed loops).
    """
    pt = operating_point(model, x, u=u, params=params, t=t, guess=guess, mode=mode)
    inputs = model.input_names if inputs is None else list(inputs)
    outputs = model.output_names if outputs is None else list(outputs)
    iu = index_of(model.input_names, inputs, "input", model.name)
    Y = ca.vertcat(*[_expression(model, n) for n in outputs]) if outputs else ca.SX(0, 1)
    f = model.function("jacobians", [
        ca.jacobian(e, v) for e in (model.ode, model.alg, Y) for v in (model.x, model.z, model.u)
    ] + [Y])
    J = [np.array(m, dtype=float).reshape(m.shape) for m in f(pt.t, pt.x, pt.z, pt.u, pt.p)]
    (fx, fz, fu, gx, gz, gu, yx, yz, yu), y0 = J[:9], np.array(J[9]).ravel()
    fu, gu, yu = fu[:, iu], gu[:, iu], yu[:, iu]
    nx = len(model.x_names)

    # algebraic variables other than the loops' μ, ν: implicit function theorem
    zn = model.z_names
    loop = model.loop_multipliers                         # μ rows, then ν rows
    other = [k for k in range(len(zn)) if k not in set(loop)]
    dz_x, dz_u = np.zeros((len(zn), nx)), np.zeros((len(zn), len(iu)))
    if other:
        G = gz[np.ix_(other, other)]
        if np.linalg.matrix_rank(G) < len(other):
            raise AnalysisError(f"linearize '{model.name}': the algebraic equations are "
                                f"singular for {', '.join(zn[k] for k in other)} here")
        dz_x[other] = -np.linalg.solve(G, gx[other])
        dz_u[other] = -np.linalg.solve(G, gu[other])
    Ax, Bx = fx + fz @ dz_x, fu + fz @ dz_u
    Cx, Dx = yx + yz @ dz_x, yu + yz @ dz_u
    L = model.lagrange
    names, x_op, loop_x = list(model.x_names), pt.x, gx[loop] + gz[loop] @ dz_x
    if L.chart_names and (tangent or loop):
        P, S, names, x_op = _tangent(model, pt.x)
        Ax, Bx, Cx, dz_x, loop_x = S @ Ax @ P, S @ Bx, Cx @ P, dz_x @ P, loop_x @ P
    nx = len(names)

    T, keep = np.eye(nx), list(range(nx))
    if loop:
        T, keep = _loop_basis(model, names, loop_x, gu[loop] + gz[loop] @ dz_u, independent)
    states = [names[k] for k in keep]
    full = T if not other else np.vstack([T, dz_x[other] @ T])
    full_names = names + [zn[k] for k in other]
    coords = [n for n, r in zip(L.q_names, L.qd_names) if n in states and r in states]
    rates = [L.qd_names[L.q_names.index(n)] for n in coords]
    mass, V = None, None
    if coords and all(n in full_names for n in L.q_names):   # (charts: tangent only)
        M = np.array(model.function("M", [L.M])(pt.t, pt.x, pt.z, pt.u, pt.p), dtype=float)
        V = full[[full_names.index(n) for n in L.q_names]][:, [states.index(c) for c in coords]]
        mass = V.T @ M @ V
    return LinearModel(A=Ax[keep] @ T, B=Bx[keep], C=Cx @ T, D=Dx, states=states,
                       inputs=inputs, outputs=outputs, x_op=x_op[keep], u_op=pt.u[iu],
                       y_op=y0, full_states=full_names, expansion=full, coordinates=coords,
                       rates=rates, mass=mass, q_names=list(L.q_names), q_basis=V,
                       mode=dict(pt.mode))


def _expression(model, name):
    try:
        return model.expression(name)
    except KeyError as e:
        raise AnalysisError(f"linearize: {e.args[0]}") from None


def _tangent(model, x: np.ndarray):
    """(P, S, names, x_op): δx = P·δx_t from the tangent states (each chart's θ[1..3] in
    place of its Q[1..4]: δQ = ½·G(Q)·δθ) and δx_t = S·δx (S = P⁺: δθ = 2·G(Q)ᵀ·δQ), the
    tangent states' names and values at x (θ = 0)."""
    xn = model.x_names
    charts = {Q[0]: (theta, Q) for theta, Q in model.lagrange.chart_names}
    skip = {n for _, Q in charts.values() for n in Q}
    cols, names, x_op = [], [], []
    for k, n in enumerate(xn):
        if n in charts:
            theta, Q = charts[n]
            iq = [xn.index(m) for m in Q]
            half_G = np.array(ca.evalf(Q_rate(x[iq] / np.linalg.norm(x[iq]), ca.DM.eye(3))))
            for i in range(3):
                col = np.zeros(len(xn))
                col[iq] = half_G[:, i]
                cols.append(col)
            names += list(theta)
            x_op += [0.0, 0.0, 0.0]
        elif n not in skip:
            col = np.zeros(len(xn))
            col[k] = 1.0
            cols.append(col)
            names.append(n)
            x_op.append(x[k])
    P = np.column_stack(cols)
    return P, np.linalg.pinv(P), names, np.array(x_op)


def _loop_basis(model, xn: list[str], Cx: np.ndarray, Cu: np.ndarray, independent):
    """(T, independent states): δx = T δx_I on the linearized constraints Cx δx = 0 (states
    ``xn``), the dependent states being the coordinates picked from Φ_q (and their
    rates)."""
    L = model.lagrange
    if np.abs(Cu).max(initial=0.0) > 1e-12 * max(1.0, np.abs(Cx).max(initial=0.0)):
        raise AnalysisError(f"linearize '{model.name}': the loop constraints depend on the "
                            f"inputs here; not supported")
    pos_rows = list(range(len(model.loop_mu)))           # the μ rows: Φ = 0
    iq = [xn.index(n) for n in L.q_names]
    iv = [xn.index(n) for n in L.qd_names]
    Pq = Cx[np.ix_(pos_rows, iq)]
    tol = 1e-9 * max(1.0, np.abs(Pq).max(initial=0.0))
    rank = np.linalg.matrix_rank(Pq, tol)
    if independent is None:
        piv = scipy.linalg.qr(Pq, pivoting=True, mode="r")[1]
        dep = sorted(piv[:rank])
    else:
        ind = index_of(L.q_names, independent, "coordinate", model.name)
        dep = [k for k in range(len(iq)) if k not in ind]
        if len(dep) != rank or np.linalg.matrix_rank(Pq[:, dep], tol) < rank:
            raise AnalysisError(
                f"linearize '{model.name}': independent coordinates {independent} do not "
                f"fix the others through the loop constraints (Φ_q has rank {rank} over "
                f"{len(iq)} coordinates: choose {len(iq) - rank} coordinates whose "
                f"complement's columns of Φ_q are independent)")
    dep_x = [iq[k] for k in dep] + [iv[k] for k in dep]
    keep = [k for k in range(len(xn)) if k not in dep_x]
    T = np.zeros((len(xn), len(keep)))
    T[keep, range(len(keep))] = 1.0
    T[dep_x] = -np.linalg.lstsq(Cx[:, dep_x], Cx[:, keep], rcond=None)[0]
    return T, keep
