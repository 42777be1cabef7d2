"""Transcriptions of a compiled model's DAE on a mesh of N intervals into NLP constraints:
direct collocation and direct multiple shooting.

Both share one core (``Transcription.transcribe``): state continuity at the mesh nodes, the
integrals of the cost, and the algebraic equations at the nodes. A subclass only says how
one interval maps its start state and control to its end state and its integrals
(``intervals``), vectorized over all intervals with ``Function.map``.

Controls are piecewise constant (the model's Inputs hold their value on each interval).
Time on interval k is t_k + h·τ, τ ∈ [0, 1], h = T/N, so a free final time T is just another
decision variable.

Constrained (closed-loop) models: their DAE is the stabilized index-2 form of Gear, Gupta and
Leimkuhler (algebraic variables z = loops.mu, loops.nu; algebraic equations Φ = 0, Φ̇ = 0).
Collocation enforces the algebraic equations at every collocation point; with Radau points
(the default) the interval's end is one of them, so Φ = Φ̇ = 0 hold at every mesh node. With
Legendre points they hold at the collocation points only. Multiple shooting needs an
integrator that solves DAEs ('collocation', the default for DAEs, or 'idas' for consistent
index-1 models). Both also impose Φ = Φ̇ = 0 on the initial state: fix only independent
coordinates in ``ocp.initial`` (e.g. the crank angle), as for ``simulate(x0=...)``.

The model's initial equations (``PhysicsBuilder.initial``: a steady start, an
InitializeFlange) hold at the first node, next to the values ``ocp.initial`` fixes (which
must not contradict them), as at the start of a simulation.
"""
from __future__ import annotations

from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..errors import OCPError
from .model import ModelView
from .nlp import NLP

SCHEMES = ("radau", "legendre")


@dataclass
class Nodes:
    """The NLP's values at the mesh nodes: states X (nx × N+1), controls U (nu × N),
    algebraic variables Z (nz × N+1), parameters P (np × 1), times t (1 × N+1), step h; MX
    of the NLP's variables, or SX of their twins (``NLP.as_sx``)."""
    X: ca.MX
    U: ca.MX
    Z: ca.MX
    P: ca.MX
    t: ca.MX
    h: ca.MX

    @property
    def N(self) -> int:
        return self.U.shape[1]

    @property
    def U_nodes(self) -> ca.MX:
        """Controls at the nodes (nu × N+1): the last interval's value held at t_N."""
        return ca.horzcat(self.U, self.U[:, -1]) if self.U.numel() else \
            type(self.U)(0, self.N + 1)


class Transcription:
    """The shared core; subclasses implement ``intervals`` (and ``fill_guess`` if they add
    variables). ``in_sx``: whether the transcription can be written in SX (every Function
    it calls evaluates on SX), the fixed numbers then folded into its arithmetic."""

    in_sx = True

    def __init__(self, view: ModelView):
        self.view = view

    def transcribe(self, nlp: NLP, nodes: Nodes, integrands: list) -> ca.MX:
        """Add the dynamics to ``nlp``; return the integrals over [t_0, t_N] of
        ``integrands`` (SX in the model's symbols), stacked (MX or SX as ``nodes``)."""
        view, N, c = self.view, nodes.N, self.view.compiled
        # integrands of the controls and parameters alone are constant on each interval:
        # h·g is their exact integral; the others use the transcription's quadrature
        moving = ca.vertcat(c.x, c.z, c.t)
        held = [i for i, e in enumerate(integrands) if not ca.depends_on(e, moving)]
        other = [i for i in range(len(integrands)) if i not in held]
        g = view.function([integrands[i] for i in other], "integrands") if other else None
        X_end, Q_other = self.intervals(nlp, nodes, g)
        nlp.equal(nodes.X[:, 1:] - X_end)
        Q = type(nodes.X)(len(integrands), 1)
        if held:
            gh = view.function([integrands[i] for i in held], "held").map(N)
            Q[held] = nodes.h * ca.sum2(gh(nodes.t[:, :N], nodes.X[:, :N], nodes.Z[:, :N],
                                            nodes.U, nodes.P))
        if other:
            Q[other] = ca.sum2(Q_other)
        f, U = view.f, nodes.U_nodes
        if view.rows_z:             # index-1 algebraic equations at every node
            alg = f.map(N + 1)(nodes.t, nodes.X, nodes.Z, U, nodes.P)[1]
            nlp.equal(alg[view.rows_z, :])
        start = (nodes.t[0], nodes.X[:, 0], nodes.Z[:, 0], U[:, 0], nodes.P)
        if view.rows_x:             # the loops' Φ = 0, Φ̇ = 0 at the start
            nlp.equal(f(*start)[1][view.rows_x])
        if c.initial_equations.numel():     # the model's initial equations at the start
            nlp.equal(view.function([c.initial_equations], "initial")(*start))
        return Q

    def intervals(self, nlp: NLP, nodes: Nodes, g: ca.Function | None):
        """(end states nx × N, integrals of g per interval ng × N)."""
        raise NotImplementedError

    def fill_guess(self, nlp: NLP, X_guess: np.ndarray) -> None:
        """Set the guesses of the transcription's own variables from the node states'."""


class Collocation(Transcription):
    """Direct collocation: on each interval the states are the polynomial of degree
    ``degree`` through the start state and ``degree`` collocation points ('radau' or
    'legendre' roots), on which the state equations and the algebraic equations hold.
    Integrals use the collocation points' quadrature (exact to degree 2d−2 for Radau,
    2d−1 for Legendre)."""

    def __init__(self, view: ModelView, degree: int = 3, scheme: str = "radau"):
        super().__init__(view)
        if scheme not in SCHEMES:
            raise OCPError(f"collocation scheme '{scheme}' is not one of {SCHEMES}")
        if not isinstance(degree, (int, np.integer)) or not 1 <= degree <= 9:
            raise OCPError(f"collocation degree must be an integer from 1 to 9, not {degree!r}")
        self.degree, self.scheme = int(degree), scheme
        self.tau = np.array(ca.collocation_points(self.degree, scheme))
        C, D, _ = ca.collocation_coeff(list(self.tau))
        self.C, self.D = ca.DM(C), ca.DM(D)
        # quadrature weights of the collocation points: ∫₀¹ of their Lagrange basis
        V = np.vander(self.tau, increasing=True).T
        self.B = ca.DM(np.linalg.solve(V, 1.0 / np.arange(1, self.degree + 1)))

    def intervals(self, nlp, nodes, g):
        view, N, d = self.view, nodes.N, self.degree
        E = ca.DM.eye(N)
        Xc = self._Xc = nlp.variable("X_colloc", view.nx, N * d)
        Zc = nlp.variable("Z_colloc", view.nz, N * d, view.z_start.reshape(-1, 1))
        if isinstance(nodes.X, ca.SX):
            Xc, Zc = nlp.twin(Xc), nlp.twin(Zc)
        spread = ca.kron(E, ca.DM.ones(1, d))                   # interval -> its points
        Tc = nodes.t[:, :N] @ spread + nodes.h * ca.DM(np.tile(self.tau, N)).T
        Uc = nodes.U @ spread
        xdot, alg = view.f.map(N * d)(Tc, Xc, Zc, Uc, nodes.P)
        Xs = nodes.X[:, :N]
        slope = Xs @ ca.kron(E, self.C[0, :]) + Xc @ ca.kron(E, self.C[1:, :])
        nlp.equal(nodes.h * xdot - slope)
        nlp.equal(alg)
        X_end = Xs @ ca.kron(E, self.D[0]) + Xc @ ca.kron(E, self.D[1:])
        Q = None
        if g is not None:
            G = g.map(N * d)(Tc, Xc, Zc, Uc, nodes.P)
            Q = nodes.h * (G @ ca.kron(E, self.B))
        return X_end, Q

    def fill_guess(self, nlp, X_guess):
        d = self.degree
        start = np.repeat(X_guess[:, :-1], d, axis=1)
        step = np.repeat(np.diff(X_guess, axis=1), d, axis=1)
        nlp.set(self._Xc, guess=start + step * np.tile(self.tau, X_guess.shape[1] - 1))


INTEGRATOR_DEFAULTS = {"rk": {"number_of_finite_elements": 4, "simplify": True},
                       "collocation": {"number_of_finite_elements": 4},
                       "cvodes": {"abstol": 1e-10, "reltol": 1e-10},
                       "idas": {"abstol": 1e-10, "reltol": 1e-10}}


class MultipleShooting(Transcription):
    """Direct multiple shooting: a CasADi integrator (``casadi.integrator`` plugin name:
    'rk' fixed-step RK4, the default for ODEs; 'collocation' fixed-step Radau, the default
    for DAEs; 'cvodes'; 'idas') carries each interval's start state to its end; the cost
    integrals are its quadratures. ``options`` go to the integrator (defaults: 4 steps per
    interval for the fixed-step ones, tolerances 1e-10 for the variable-step ones)."""

    def __init__(self, view: ModelView, integrator: str | None = None,
                 options: dict | None = None):
        super().__init__(view)
        self.plugin = integrator or ("collocation" if view.nz else "rk")
        if view.nz and self.plugin in ("rk", "cvodes"):
            raise OCPError(f"integrator '{self.plugin}' does not solve DAEs, and model "
                           f"'{view.compiled.name}' has algebraic variables "
                           f"{view.compiled.z_names[:4]}; use 'collocation' or 'idas'")
        self.options = {**INTEGRATOR_DEFAULTS.get(self.plugin, {}), **(options or {})}
        self.in_sx = self.plugin == "rk"        # explicit steps: one SX Function
    def intervals(self, nlp, nodes, g):
        view, c, N = self.view, self.view.compiled, nodes.N
        s, tk, h = ca.SX.sym("s"), ca.SX.sym("t_k"), ca.SX.sym("h")
        # a fixed step: the integrator runs in time over [0, h], t = t_k + s; a free final
        # time: in τ ∈ [0, 1], t = t_k + h·τ, the rates scaled by the step h (a parameter)
        fixed = nodes.h.is_constant()
        local = tk + s if fixed else tk + h * s

        def scaled(rates):
            rates = ca.substitute(rates, c.t, local)
            return rates if fixed else h * rates

        xdot, alg = view.f(c.t, c.x, c.z, c.u, c.p)
        dae = {"x": c.x, "p": ca.vertcat(c.p, c.u, tk, *([] if fixed else [h])), "t": s,
               "ode": scaled(xdot)}
        if view.nz:
            dae.update(z=c.z, alg=ca.substitute(alg, c.t, local))
        if g is not None:
            dae["quad"] = scaled(g(c.t, c.x, c.z, c.u, c.p))
        span = float(ca.evalf(nodes.h)) if fixed else 1.0
        try:
            F = ca.integrator("interval", self.plugin, dae, 0.0, span, self.options)
            if self.plugin == "rk" and F.is_a("MXFunction"):
                F = F.expand()          # explicit steps as one SX Function: fast derivatives
        except RuntimeError as e:
            raise OCPError(f"cannot make a '{self.plugin}' integrator for model "
                           f"'{c.name}': {str(e).strip().splitlines()[-1]}") from None
        p = ca.vertcat(ca.repmat(nodes.P, 1, N), nodes.U, nodes.t[:, :N],
                       *([] if fixed else [ca.repmat(nodes.h, 1, N)]))
        out = F.map(N)(x0=nodes.X[:, :N], z0=ca.DM(view.z_start), p=p)
        return out["xf"], (out["qf"] if g is not None else None)
