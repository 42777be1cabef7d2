"""Kinematic analysis: the motion of a mechanism whose every degree of freedom is prescribed.

At each time of the grid, with G(q, t) = [Φ(q, t); y(q, t) − f(t)] the loop constraints of the
compiled model (prescribed motions inside the model — Position/Speed sources with
``exact=True`` on joint or 1-D flanges — make Φ depend on t) and, for mixed dynamics, the
motions prescribed by name (y: any recorded variable of the positions, f(t) its motion):

1. positions: G(q, t) = 0 by Newton–Raphson (Gauss–Newton steps by least squares, from the
   previous time's solution extrapolated);
2. velocities: the linear problem G_q q̇ = −G_t (+ ḟ);
3. accelerations: from the model's own equations at (q, q̇): with all coordinates driven, its
   constrained solve [M Φ_qᵀ; Φ_q 0] gives q̈ = −Φ_q⁻¹ γ and the multipliers λ, i.e. the
   driving forces and joint reactions (inverse dynamics). With motions prescribed by name,
   the unknown inputs u_x are found with them: ÿ(q, q̇, u_x, t) = f̈(t) (as many equations as
   unknowns, Newton in u_x; one step when the forces enter linearly) — the unknown forces
   play the part of the multipliers of the prescribed motions (partitioning method).

States that are not mechanical coordinates (e.g. a Speed source's angle) must depend on time
and known inputs only: they are integrated first (cvodes). Every recorded variable is then
evaluated on the grid: a Result like simulate's.
"""
from __future__ import annotations

import casadi as ca
import numpy as np
from scipy.interpolate import CubicSpline

from ..errors import StructureError
from ..simulation.result import Result
from ..simulation.inputs import input_signal
from ..errors import AnalysisError
from .point import index_of, set_loop_switches

_vc = ca.vertcat


def kinematic_analysis(model, t, *, params: dict | None = None, inputs: dict | None = None,
                       guess: dict | None = None, tol: float = 1e-12) -> Result:
    """Positions, velocities and accelerations of a mechanism fully driven by prescribed
    motions inside the model (as many exact Position/Speed sources as degrees of freedom),
    on the time grid t [s]; every recorded variable by name (a Result, like simulate's),
    including the driving forces and joint reactions (port flows).

    params, inputs: as for simulate; guess: start values of the coordinates by name at t[0]
    (the branch of the assembly); tol: Newton tolerance on the constraints [m, rad].
    """
    return MotionSolver(model, t, params, inputs, {}, [], guess, tol).run()


class MotionSolver:
    """The solve described in the module docstring, for one model, grid and set of motions."""

    def __init__(self, model, t, params, inputs, motion: dict, unknown: list, guess, tol):
        self.model, self.tol = model, tol
        self.grid = np.asarray(t, dtype=float).ravel()
        if self.grid.size < 1 or np.any(np.diff(self.grid) <= 0):
            raise AnalysisError("t must be an increasing grid of times [s]")
        self.p = model.param_vector(params)
        L = model.lagrange
        xn = model.x_names
        missing = [n for n in L.q_names + L.qd_names if n not in xn]
        if missing:
            raise AnalysisError(f"model '{model.name}': coordinates without mass "
                                f"({', '.join(missing)}) cannot be prescribed kinematically")
        multipliers = set(model.loop_multipliers)
        other_z = [n for k, n in enumerate(model.z_names) if k not in multipliers]
        if other_z:
            raise AnalysisError(f"model '{model.name}': algebraic variables "
                                f"({', '.join(other_z)}) are not supported in kinematic "
                                f"analysis")
        self.iq = [xn.index(n) for n in L.q_names]
        self.iv = [xn.index(n) for n in L.qd_names]
        self.io = [k for k in range(len(xn)) if k not in self.iq + self.iv]
        q, v = L.q, L.qd
        o = model.x[self.io] if self.io else ca.SX(0, 1)
        self.motion_names = list(motion)
        self.iu = index_of(model.input_names, unknown, "input", model.name)
        if len(self.iu) != len(motion):
            raise AnalysisError(f"{len(motion)} prescribed motions "
                                f"({', '.join(motion) or 'none'}) but {len(self.iu)} unknown "
                                f"inputs ({', '.join(unknown) or 'none'}): give as many of each")
        known = dict(inputs or {})
        for name in unknown:
            if name in known:
                raise AnalysisError(f"input '{name}' is unknown and given in inputs")
        index_of(model.input_names, list(known), "input", model.name)
        self.U = self._inputs(known)
        self.F = self._motions(motion)

        # positions: G = [Φ; y − f] in q (others, t, p given)
        Y = _vc(*[self._position_expression(n) for n in motion]) if motion else ca.SX(0, 1)
        fv = ca.SX.sym("f", len(motion))
        G = _vc(L.phi, Y - fv)
        u_sym = model.u
        ode = ca.substitute(model.ode, model.z, ca.SX.zeros(model.z.numel()))
        od = ode[self.io] if self.io else ca.SX(0, 1)
        G_q = ca.jacobian(G, q)
        G_rate = ca.jacobian(G, model.t) + (ca.mtimes(ca.jacobian(G, o), od) if self.io else 0)
        args = [model.t, q, o, u_sym, model.p, fv]
        self.f_pos = ca.Function("positions", args, [G, G_q])
        self.f_vel = ca.Function("velocities", args, [G_q, -G_rate])
        # accelerations of the prescribed variables, as functions of the unknown inputs
        Ydot = ca.jtimes(Y, q, v) + ca.jacobian(Y, model.t) + (
            ca.jtimes(Y, o, od) if self.io else 0)
        Yddot = ca.jtimes(Ydot, model.x, ode) + ca.jacobian(Ydot, model.t)
        self.f_acc = ca.Function("accelerations", [model.t, model.x, u_sym, model.p],
                                 [Yddot, ca.jacobian(Yddot, u_sym)])
        self.guess = guess or {}
        self.other_ode = od

    # ---- inputs and motions as numbers on the grid -------------------------------------
    def _inputs(self, known: dict) -> np.ndarray:
        m, grid = self.model, self.grid
        ex = [input_signal(n, known.get(n, start), m.t, _grid2(grid)).expression
              for n, start in zip(m.input_names, m.input_start)]
        self.u_expr = _vc(*ex) if ex else ca.SX(0, 1)
        if not ex:
            return np.zeros((0, grid.size))
        f = ca.Function("u", [m.t], [self.u_expr])
        return np.array(f.map(grid.size)(grid.reshape(1, -1)), dtype=float)

    def _motions(self, motion: dict) -> np.ndarray:
        """(3, n_motion, n_t): f, ḟ, f̈ on the grid."""
        grid, t = self.grid, self.model.t
        out = np.zeros((3, len(motion), grid.size))
        for i, (name, spec) in enumerate(motion.items()):
            if isinstance(spec, tuple) and len(spec) in (2, 4):
                tt = np.asarray(spec[0], dtype=float).ravel()
                vals = [np.asarray(a, dtype=float).ravel() for a in spec[1:]]
                if any(a.size != tt.size for a in vals) or tt.size < 4:
                    raise AnalysisError(f"motion of '{name}': samples need ≥ 4 times and as "
                                        f"many values (times, positions[, rates, "
                                        f"accelerations])")
                if len(vals) == 3:             # given rates and accelerations: interpolated
                    out[:, i] = [np.interp(grid, tt, a) for a in vals]
                else:                          # positions only: a cubic spline's derivatives
                    s = CubicSpline(tt, vals[0])
                    out[:, i] = [s(grid), s(grid, 1), s(grid, 2)]
                continue
            ex = input_signal(f"motion of {name}", spec, t, _grid2(grid)).expression
            d1 = ca.jacobian(ex, t)
            f = ca.Function("motion", [t], [_vc(ex, d1, ca.jacobian(d1, t))])
            out[:, i] = np.array(f.map(grid.size)(grid.reshape(1, -1)), dtype=float)
        return out

    def _position_expression(self, name):
        m = self.model
        try:
            ex = m.expression(name)
        except KeyError as e:
            raise AnalysisError(f"motion: {e.args[0]}") from None
        L = m.lagrange
        if ca.depends_on(ex, _vc(L.qd, m.u, m.z)):
            raise AnalysisError(f"motion: '{name}' depends on velocities, inputs or algebraic "
                                f"variables; prescribe a position (a coordinate or any "
                                f"recorded variable of the positions)")
        return ex

    # ---- the solve ---------------------------------------------------------------------
    def run(self) -> Result:
        m, grid = self.model, self.grid
        n, nx = grid.size, len(m.x_names)
        X = np.zeros((nx, n))
        X[self.io] = self._integrate_other()
        q = np.array(m.start(self.p), dtype=float).ravel()[self.iq]
        for name, value in self.guess.items():
            q[index_of(m.lagrange.q_names, [name], "coordinate", m.name)[0]] = float(value)
        U = self.U.copy()
        v = a = np.zeros(len(self.iq))
        for k, tk in enumerate(grid):
            if k > 0:                               # predictor from the previous time
                dt = tk - grid[k - 1]
                q = q + v * dt + 0.5 * a * dt ** 2
            o = X[self.io, k]
            q = self._positions(q, tk, o, U[:, k], self.F[0, :, k], first=k == 0)
            v = self._velocities(q, tk, o, U[:, k], self.F[1, :, k])
            X[self.iq, k], X[self.iv, k] = q, v
            if k == 0:
                self.p = set_loop_switches(m, tk, X[:, 0], np.zeros(len(m.z_names)), U[:, 0],
                                           self.p)
            if self.iu:
                U[self.iu, k] = self._unknown_inputs(tk, X[:, k], U[:, k], self.F[2, :, k])
            a = np.array(m.f(x=X[:, k], u=U[:, k], p=self.p, t=tk)["xdot"],
                         dtype=float).ravel()[self.iv]
        Z = np.zeros((len(m.z_names), n))
        return Result(m, grid, X, Z, U, self.p)

    def _positions(self, q, t, o, u, f, first):
        m = self.model
        if first and len(m.loop_rows) + len(f) < len(q):
            self._check_driven(np.eye(len(m.loop_rows) + len(f), len(q)))
        for _ in range(100 if first else 30):
            G, J = (np.array(a, dtype=float) for a in self.f_pos(t, q, o, u, self.p, f))
            G = G.ravel()
            if np.max(np.abs(G), initial=0.0) <= self.tol:
                if first:
                    self._check_driven(J)
                return q
            step = -np.linalg.lstsq(J, G, rcond=1e-13)[0]
            big = np.max(np.abs(step), initial=0.0)
            if first and big > 0.3:      # stay on the branch of the guess
                step *= 0.3 / big
            q = q + step
        names = m.loop_rows + [f"motion of {n}" for n in self.motion_names]
        bad = ", ".join(f"{names[i]} = {G[i]:.3g}" for i in np.flatnonzero(np.abs(G) > self.tol))
        raise AnalysisError(f"'{m.name}' at t = {t:g} s: the positions cannot satisfy the "
                            f"constraints and prescribed motions ({bad}): the mechanism "
                            f"cannot reach this configuration (or passes a dead point)")

    def _check_driven(self, J):
        m = self.model
        nq = J.shape[1]
        rank = np.linalg.matrix_rank(J, 1e-9 * max(1.0, np.abs(J).max(initial=0.0)))
        if rank < nq:
            raise StructureError(
                f"'{m.name}' is not fully driven: {nq - rank} of its {nq} coordinates "
                f"({', '.join(m.lagrange.q_names)}) are free; prescribe as many more motions "
                f"(Position/Speed sources with exact=True on joint or 1-D flanges, or motions "
                f"by name in mixed_dynamics) as degrees of freedom")

    def _velocities(self, q, t, o, u, fd):
        J, rhs = (np.array(a, dtype=float) for a in self.f_vel(t, q, o, u, self.p, np.zeros(
            len(self.motion_names))))
        rhs = rhs.ravel()
        rhs[len(rhs) - len(fd):] += fd
        return np.linalg.lstsq(J, rhs, rcond=None)[0]

    def _unknown_inputs(self, t, x, u, fdd):
        u = u.copy()
        for _ in range(20):
            r, Ju = (np.array(a, dtype=float) for a in self.f_acc(t, x, u, self.p))
            r = r.ravel() - fdd
            Ju = Ju[:, self.iu]
            if np.linalg.matrix_rank(Ju) < len(self.iu):
                raise AnalysisError(
                    f"'{self.model.name}' at t = {t:g} s: the unknown inputs "
                    f"{[self.model.input_names[i] for i in self.iu]} do not act on the "
                    f"prescribed motions {self.motion_names} independently")
            du = -np.linalg.solve(Ju, r)
            u[self.iu] += du
            if np.max(np.abs(du)) <= 1e-13 * (1 + np.max(np.abs(u[self.iu]))):
                break
        return u[self.iu]

    def _integrate_other(self) -> np.ndarray:
        """Trajectories of the states that are not coordinates (functions of time only)."""
        m = self.model
        if not self.io:
            return np.zeros((0, self.grid.size))
        L = m.lagrange
        free = [m.input_names[i] for i in self.iu]
        names = [m.x_names[k] for k in self.io]
        if ca.depends_on(self.other_ode, _vc(L.q, L.qd)) or (
                free and ca.depends_on(self.other_ode, m.u[self.iu])):
            raise AnalysisError(f"'{m.name}': the states {names} change with the motion or "
                                f"the unknown inputs; kinematic analysis needs states that "
                                f"depend on time and known inputs only (use simulate)")
        o = m.x[self.io]
        x0 = np.array(m.start(self.p), dtype=float).ravel()[self.io]
        if self.grid.size == 1:
            return x0.reshape(-1, 1)
        ex = ca.substitute([self.other_ode], [m.p, m.u], [ca.DM(self.p), self.u_expr])[0]
        F = ca.integrator("other", "cvodes", {"x": o, "t": m.t, "ode": ex}, self.grid[0],
                          list(self.grid[1:]), {"abstol": 1e-12, "reltol": 1e-12})
        xf = np.array(F(x0=x0)["xf"], dtype=float)
        return np.hstack([x0.reshape(-1, 1), xf])


def _grid2(grid):
    return grid if grid.size > 1 else np.array([grid[0], grid[0] + 1.0])

