"""A nonlinear program in CasADi MX: decision variables with bounds and guesses, constraints
lb ≤ g ≤ ub, solved by IPOPT through ``casadi.nlpsol``."""
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
        self.vars, self.lb, self.ub, self.guess = [], [], [], []
        self.g, self.lbg, self.ubg = [], [], []

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
        """Constraint lower ≤ g ≤ upper (elementwise; bounds broadcast to g's shape)."""
        g = ca.vec(ca.MX(g))
        if g.numel():
            self.g.append(g)
            self.lbg.append(np.broadcast_to(np.asarray(lower, dtype=float).ravel(), g.shape[:1]))
            self.ubg.append(np.broadcast_to(np.asarray(upper, dtype=float).ravel(), g.shape[:1]))

    @property
    def w(self) -> ca.MX:
        return ca.veccat(*self.vars)

    def solver(self, f: ca.MX, options: dict) -> ca.Function:
        return ca.nlpsol("ocp", "ipopt", {"x": self.w, "f": f, "g": ca.vertcat(*self.g)},
                         options)

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
