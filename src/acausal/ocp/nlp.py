"""A nonlinear program in CasADi MX: decision variables with bounds and guesses, constraints
lb ≤ g ≤ ub, solved by IPOPT through ``casadi.nlpsol``.

Each MX variable has an SX twin of its shape: the transcription writes the dynamics in SX of
the twins (``as_sx``), where the fixed numbers fold into the arithmetic; the problem is then
solved in SX (the MX costs and constraints of the user expanded to SX of the twins), so
that IPOPT's function and derivative evaluations run at SX speed."""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..errors import OCPError

DEFAULT_IPOPT = {"print_level": 0, "sb": "yes"}
SUCCESS = ("Solve_Succeeded", "Solved_To_Acceptable_Level")


class NLP:
    """Decision variables (MX matrices, each with arrays of bounds and a guess) and
    constraints; ``solve`` stacks them into w and g for ``nlpsol``."""

    def __init__(self):
        self.vars, self.twins, self.lb, self.ub, self.guess = [], [], [], [], []
        self.g, self.lbg, self.ubg = [], [], []
        self.defined, self.definitions = [], []     # MX symbols standing for SX of the twins

    def copy(self) -> "NLP":
        """A new NLP with the same variables (the same symbols and arrays) and constraints,
        to which more can be added without changing this one."""
        out = NLP()
        for key, value in self.__dict__.items():
            setattr(out, key, list(value))
        return out

    def variable(self, name: str, rows: int, cols: int = 1, guess=0.0) -> ca.MX:
        v = ca.MX.sym(name, rows, cols)
        self.vars.append(v)
        self.twins.append(ca.SX.sym(name, rows, cols))
        self.lb.append(np.full((rows, cols), -np.inf))
        self.ub.append(np.full((rows, cols), np.inf))
        self.guess.append(np.broadcast_to(np.asarray(guess, dtype=float), (rows, cols)).copy())
        return v

    def set(self, v: ca.MX, lower=None, upper=None, guess=None) -> None:
        """Bounds and guess of variable ``v`` (each broadcast to its shape; None: unchanged)."""
        k = next(i for i, w in enumerate(self.vars) if w is v)
        for store, value in ((self.lb, lower), (self.ub, upper), (self.guess, guess)):
            if value is not None:
                store[k] = np.broadcast_to(np.asarray(value, dtype=float), v.shape).copy()

    def equal(self, g, value=0.0) -> None:
        """Constraint g = value (elementwise)."""
        self.bound(g, value, value)

    def bound(self, g, lower, upper) -> None:
        """Constraint lower ≤ g ≤ upper (elementwise; bounds broadcast to g's shape); g an
        MX of the variables, or an SX of their twins."""
        g = ca.vec(g if isinstance(g, ca.SX) else ca.MX(g))
        if g.numel():
            self.g.append(g)
            self.lbg.append(np.broadcast_to(np.asarray(lower, dtype=float).ravel(), g.shape[:1]))
            self.ubg.append(np.broadcast_to(np.asarray(upper, dtype=float).ravel(), g.shape[:1]))

    @property
    def w(self) -> ca.MX:
        return ca.veccat(*self.vars)

    def twin(self, v: ca.MX) -> ca.SX:
        """The SX twin of variable ``v``."""
        return self.twins[next(i for i, w in enumerate(self.vars) if w is v)]

    def define(self, symbol: ca.MX, value: ca.SX) -> None:
        """Let the MX ``symbol`` (a placeholder in costs and constraints) stand for ``value``,
        an SX expression of the twins."""
        self.defined.append(symbol)
        self.definitions.append(value)

    def as_sx(self, exprs: list) -> list:
        """MX expressions of the variables (and the defined symbols) as SX expressions of
        their twins."""
        out = ca.Function("as_sx", self.vars + self.defined, list(exprs)).expand()(
            *self.twins, *self.definitions)
        return [out] if isinstance(out, ca.SX) else list(out)

    def lift(self, exprs: list) -> list:
        """SX expressions of the twins as MX expressions of the variables (one call of one
        SX Function computing them all)."""
        if not exprs:
            return []
        out = ca.Function("transcription", self.twins, list(exprs))(*self.vars)
        return [out] if isinstance(out, ca.MX) else list(out)

    def solver(self, f: ca.MX, options: dict) -> ca.Function:
        """IPOPT on the problem: in SX when the transcription wrote its constraints in SX
        (the MX cost and constraints then expanded to SX of the twins), else in MX."""
        g = list(self.g)
        sx = [i for i, e in enumerate(g) if isinstance(e, ca.SX)]
        if sx:
            mx = [i for i, e in enumerate(g) if not isinstance(e, ca.SX)]
            try:
                f_sx, *rest = self.as_sx([f] + [g[i] for i in mx])
            except RuntimeError:        # an MX-only Function among the user's: solve in MX
                pass
            else:
                for i, e in zip(mx, rest):
                    g[i] = e
                return ca.nlpsol("ocp", "ipopt", {"x": ca.veccat(*self.twins), "f": f_sx,
                                                  "g": ca.vertcat(*g)}, options)
            for i, e in zip(sx, self.lift([g[i] for i in sx])):
                g[i] = e
            if self.defined:
                f, *g = ca.substitute([f] + g, self.defined, self.lift(self.definitions))
        return ca.nlpsol("ocp", "ipopt", {"x": self.w, "f": f, "g": ca.vertcat(*g)}, options)

    def bounds_and_guess(self):
        """(lbw, ubw, w0, lbg, ubg) as flat arrays (column-major, as ``w``)."""
        flat = lambda arrs: (np.concatenate([a.ravel(order="F") for a in arrs])
                             if arrs else np.zeros(0))
        return (flat(self.lb), flat(self.ub), flat(self.guess),
                np.concatenate(self.lbg) if self.lbg else np.zeros(0),
                np.concatenate(self.ubg) if self.ubg else np.zeros(0))


def canonical(constraint) -> tuple[ca.MX, np.ndarray, np.ndarray]:
    """(g, lb, ub) of an MX relation ``a <= b``, ``a >= b`` or ``a == b`` (elementwise);
    a numeric side becomes the bound, so ``x <= 1`` is g = x with ub = 1."""
    if not isinstance(constraint, ca.MX) or not any(
            constraint.is_op(op) for op in (ca.OP_LE, ca.OP_LT, ca.OP_EQ)):
        raise OCPError(f"a constraint must be a relation of the problem's symbols such as "
                       f"ocp['cart.s'] <= 1 or ocp['F'][0] == 0 (got {constraint!r}); "
                       "Python cannot chain 'a <= x <= b': give two constraints")
    a, b = constraint.dep(0), constraint.dep(1)
    shape = a.shape if a.numel() >= b.numel() else b.shape
    equal = constraint.is_op(ca.OP_EQ)
    if b.is_constant():
        g, bound = a, np.array(ca.evalf(b)).ravel(order="F")
        lb, ub = (bound, bound) if equal else (-np.inf, bound)
    elif a.is_constant():
        g, bound = b, np.array(ca.evalf(a)).ravel(order="F")
        lb, ub = (bound, bound) if equal else (bound, np.inf)
    else:
        g, lb, ub = a - b, (0.0 if equal else -np.inf), 0.0
    g = ca.vec(g + ca.MX.zeros(*shape)) if g.shape != shape else ca.vec(g)
    n = g.numel()
    return g, np.broadcast_to(lb, (n,)).astype(float), np.broadcast_to(ub, (n,)).astype(float)
