"""Lagrange's equations: the residuals by algorithmic differentiation, and the record of a
compiled model's equations (M, C, K, gravity, Coriolis, B, Φ) by name.

For coordinates q (and the relaxations ε of the tree relations, whose reactions give the
port flows):

    R = d/dt(∂T/∂q̇) − ∂T/∂q + ∂V/∂q − Q = 0,   Q = Σ J_portᵀ f_port,

J_port = ∂vel_port/∂q̇, vel the port's velocity conjugate to its flow (for a 3-D frame its
twist (v, w) resolved in the frame, conjugate to MSL's f, t resolved in the frame).
"""
from __future__ import annotations

from dataclasses import dataclass

import casadi as ca

from . import sympy_form
from .charts import state_positions
from .kinematics import side_by_side
from .symbolic import der_with

_vc = ca.vertcat


@dataclass(frozen=True)
class Residuals:
    """Lagrange's residuals R = inertia + conservative + flows (each a column over the
    coordinates): ``inertia`` = d/dt(∂T/∂q̇) − ∂T/∂q, ``conservative`` = ∂V/∂q, ``flows`` = −Q
    of the forces and torques components put on their ports."""
    inertia: ca.SX
    conservative: ca.SX
    flows: ca.SX

    @property
    def total(self) -> ca.SX:
        return self.inertia + self.conservative + self.flows


def residuals(ws, q: ca.SX, qd: ca.SX) -> Residuals:
    """Lagrange's residuals for the coordinates ``q`` (rates ``qd``) from the energies and
    flows the components of workspace ``ws`` contributed."""
    T = ca.sum1(_vc(*ws.kinetic)) if ws.kinetic else ca.SX(0)
    V = ca.sum1(_vc(*ws.potential)) if ws.potential else ca.SX(0)
    R_T = der_with(ca.gradient(T, qd), ws.der_table) - ca.gradient(T, q)
    R_V = ca.gradient(V, q)
    R_Q = ca.SX.zeros(q.numel())
    if ws.flows:
        v = _vc(*[ca.vec(side_by_side([ws.node_of[p] for p in ports], ws.one_d, "vel"))
                  for ports, _ in ws.flows])
        f = _vc(*[fl for _, fl in ws.flows])                 # flow into the component
        R_Q = ca.jtimes(v, qd, f, True)                      # node force is −flow
    return Residuals(R_T, R_V, R_Q)


class Lagrange:
    """Lagrange's equations of a compiled model, as CasADi expressions of the coordinates q,
    their rates q̇ (``qd``), the inputs u, time t, parameters p (and internal states z):

        M(q) q̈ + C q̇ + K q = gravity(q) + coriolis(q, q̇) + B u + Q_rest  (− Φ_qᵀ λ)

    - ``M`` the mass matrix; ``coriolis`` = −(Ṁ q̇ − ∂T/∂q), the centrifugal and Coriolis
      terms; ``gravity`` = −∂V/∂q from potential energies;
    - the generalized forces Q of all port forces and torques (springs, dampers, sources,
      actuators) are split as Q = −K q − C q̇ + B u + Q_rest when their stiffness and damping
      are linear (``K``, ``C`` constant); otherwise ``K`` and ``C`` are None and Q_rest = Q − B u;
    - ``B`` = ∂Q/∂u, the input matrix of the model's Inputs (``u_names``);
    - ``phi`` the loop constraints Φ(q, t) = 0 and ``phi_q`` their Jacobian.
    ``R0`` = −(gravity + coriolis + Q) is everything but the inertia term: M q̈ + R0 = 0.
    Each piece is derived (by AD) on first access.

    A free 3-D frame (free Body, FreeMotion, Spherical: ``charts``) has the chart
    coordinates θ[1..3] among ``q`` (named ``<...>.theta[i]``), its angular velocity w
    resolved in the frame among ``qd`` (quasi-velocities) and ẇ among ``qdd``: every piece
    is given at θ = 0, an expression of the frame's quaternion Q (M(Q) the mass matrix in
    (v, w), coriolis with the gyroscopic w × I·w, gravity and K the generalized forces and
    stiffness about the frame's axes); ``function`` takes q in the states' layout, Q in
    place of θ (``q_state``, ``q_state_names``; ``chart_names`` pairs each chart's θ
    names with its Q names).
    """

    def __init__(self, tree, R: Residuals, phi, t, p, u, u_names, z):
        self.q, self.qd, self.qdd = tree.q, tree.qd, tree.qdd
        self.q_names, self.qd_names = tree.q_names, tree.qd_names
        self._phi, self.t, self.p, self.u, self.u_names, self.z = phi, t, p, u, list(u_names), z
        self._R = R
        self._cache = {}
        charts = tree.charts
        self._theta = _vc(*[c.theta for c in charts]) if charts else ca.SX(0, 1)
        self.q_state = state_positions(charts, self.q)
        self.q_state_names = [s.name() for s in ca.vertsplit(self.q_state)] if charts \
            else list(self.q_names)
        #: (names of θ[1..3], names of Q[1..4]) of each free frame's chart
        self.chart_names = [(tuple(s.name() for s in ca.vertsplit(c.theta)),
                             tuple(s.name() for s in ca.vertsplit(c.Q)))
                            for c in charts if c.Q.numel()]

    def _lazy(self, key, make):
        if key not in self._cache:
            value = make()
            if self._theta.numel() and value is not None:
                at0 = ca.SX.zeros(self._theta.numel())
                value = ca.substitute(value, self._theta, at0) if isinstance(value, ca.SX) \
                    else tuple(None if v is None else ca.substitute(v, self._theta, at0)
                               for v in value)
            self._cache[key] = value
        return self._cache[key]

    @property
    def M(self) -> ca.SX:
        return self._lazy("M", lambda: ca.jacobian(self._R.inertia, self.qdd))

    @property
    def coriolis(self) -> ca.SX:
        return self._lazy("cor", lambda: -ca.substitute(self._R.inertia, self.qdd, self._zero()))

    @property
    def gravity(self) -> ca.SX:
        return self._lazy("gravity", lambda: -self._R.conservative)

    @property
    def B(self) -> ca.SX:
        return self._lazy("B", lambda: ca.jacobian(-self._R.flows, self.u))

    def _split_Q(self):
        Q = -self._R.flows
        Qnu = ca.substitute(Q, self.u, ca.SX.zeros(self.u.numel()))
        K, C = -ca.jacobian(Qnu, self.q), -ca.jacobian(Qnu, self.qd)
        if ca.depends_on(ca.vertcat(ca.vec(K), ca.vec(C)), ca.vertcat(self.q, self.qd, self.qdd)):
            return None, None, Qnu
        return K, C, ca.simplify(Qnu + ca.mtimes(K, self.q) + ca.mtimes(C, self.qd))

    @property
    def K(self) -> ca.SX | None:
        return self._lazy("Q", self._split_Q)[0]

    @property
    def C(self) -> ca.SX | None:
        return self._lazy("Q", self._split_Q)[1]

    @property
    def Q_rest(self) -> ca.SX:
        return self._lazy("Q", self._split_Q)[2]

    @property
    def phi(self) -> ca.SX:
        return self._lazy("phi", lambda: self._phi)

    @property
    def phi_q(self) -> ca.SX:
        return self._lazy("phi_q", lambda: ca.jacobian(self._phi, self.q))

    @property
    def R0(self) -> ca.SX:
        return self._lazy("R0", lambda: ca.substitute(self._R.total, self.qdd,
                                                      self._zero()))

    def _zero(self):
        return ca.SX.zeros(self.qdd.numel())

    def with_values(self, values: dict, keep: tuple = ()) -> "Lagrange":
        """The same equations with the parameters in ``values`` (dotted name -> number, e.g.
        ``compiled.param_defaults``) replaced by numbers, except those named in ``keep``:
        printing then reads like a hand derivation (``M = [[m1+m2, ...``)."""
        names = [s.name() for s in ca.vertsplit(self.p)]
        subs = [(s, v) for s, n in zip(ca.vertsplit(self.p), names)
                if n in values and n not in keep for v in [values[n]]]
        if not subs:
            return self
        sym, val = ca.vertcat(*[a for a, _ in subs]), ca.vertcat(*[b for _, b in subs])
        R = ca.substitute([self._R.inertia, self._R.conservative, self._R.flows, self._phi],
                          [sym], [val])
        out = Lagrange.__new__(Lagrange)
        out.__dict__.update(self.__dict__)
        out._R, out._phi, out._cache = Residuals(*(ca.simplify(r) for r in R[:3])), R[3], {}
        return out

    def function(self, *names: str) -> ca.Function:
        """A casadi Function (t, q, qd, u, p) -> the named pieces ('M', 'gravity', ...), in
        the argument order of every Function of the compiled model (t, states, inputs,
        parameters; q in the states' layout, ``q_state``); the internal states of
        components (a motor current), where a piece depends on them, are free symbols of
        the Function."""
        outs = [getattr(self, n) for n in names]
        if any(o is None for o in outs):
            raise ValueError(f"{[n for n, o in zip(names, outs) if o is None]} not linear here")
        return ca.Function("lagrange", [self.t, self.q_state, self.qd, self.u, self.p], outs,
                           ["t", "q", "qd", "u", "p"], list(names), {"allow_free": True})

    def to_sympy(self, simplify: bool = True):
        """The equations as sympy Matrices with the coordinates, rates, inputs and
        parameters as Symbols of their dotted names (``sympy_form.SympyEquations``: M, C, K,
        gravity, coriolis, B, Q_rest, phi, phi_q; ``latex()``); ``simplify``: collected as
        a hand derivation writes them (seconds for a two-link arm with every length
        symbolic; ``with_values`` first fixes what need not stay a symbol). Needs sympy."""
        return sympy_form.SympyEquations(self, simplify)

    def __str__(self):
        """The simplified sympy form (``to_sympy``) for up to 4 coordinates when sympy is
        installed; else CasADi's, whose shared subexpressions (@1 = …) keep the text of
        larger models short (a sympy expression tree repeats them)."""
        if self.q.numel() <= 4:
            try:
                return str(self.to_sympy())
            except ImportError:
                pass
        return self._casadi_str()

    def _casadi_str(self):
        def show(name, ex):
            return f"{name} =\n{ex}" if ex is not None else f"{name}: not linear"
        lines = [f"q = [{', '.join(self.q_names)}]", f"u = [{', '.join(self.u_names)}]",
                 "M q'' + C q' + K q = gravity + coriolis + B u + Q_rest",
                 show("M", self.M), show("C", self.C), show("K", self.K),
                 show("gravity", self.gravity), show("coriolis", self.coriolis),
                 show("B", self.B), show("Q_rest", self.Q_rest)]
        if self.phi.numel():
            lines += [show("Phi", self.phi), show("Phi_q", self.phi_q)]
        return "\n".join(lines)
