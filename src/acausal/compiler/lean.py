"""Exact simplification of small SX expressions: the equations as short as a hand derivation.

Lagrange's equations by algorithmic differentiation carry terms a hand derivation cancels:
d/dt(∂T/∂q̇) and ∂T/∂q share products that cancel exactly (v·ω·sin θ from either side),
and a rotated lever's squared length reads l²(cos²θ + sin²θ). CasADi keeps both (it does
not reorder products). ``lean`` expands each expression into a polynomial of its atoms
(symbols and the non-polynomial nodes: sin, cos, quotients by non-constants, ...), with
the atoms' arguments simplified in turn and identified by their polynomial: like terms are
collected, terms that cancel dropped, and m·sin²a + m·cos²a replaced by m. An expression
is replaced only if its polynomial form takes fewer operations; every output keeps its
value (up to the rounding of reordered arithmetic). Meant for small models: the expansion
is capped (a product of more than ``MAX_TERMS`` terms stays a product).
"""
from __future__ import annotations

import casadi as ca

MAX_TERMS = 48
MAX_NODES = 4000       # larger expressions are left as they are (the walk is in Python)
MAX_WORK = 20_000     # term operations; beyond, the expressions are left as they are
_ZERO = 1e-14          # a collected coefficient below this fraction of its parts is zero


class _TooLarge(Exception):
    pass


class _Lean:
    def __init__(self):
        self.work = 0                           # term operations so far (MAX_WORK)
        self.memo: dict[int, dict] = {}         # node hash -> polynomial
        self.atoms: dict[tuple, int] = {}       # atom key -> id
        self.exprs: list[ca.SX] = []            # id -> SX
        self.trig: dict[int, tuple] = {}        # id -> ('sin' | 'cos', argument key)
        self.cos_of: dict = {}                  # argument key -> id of its cosine
        self.monomials: dict[tuple, ca.SX] = {}  # built products of atoms

    # ---- polynomials: {monomial: coefficient}, monomial = ((atom id, power), ...) ------------
    def atom(self, key: tuple, make) -> dict:
        if key not in self.atoms:
            self.atoms[key] = len(self.exprs)
            self.exprs.append(make())
            if key[0] in (ca.OP_SIN, ca.OP_COS):
                self.trig[self.atoms[key]] = ("sin" if key[0] == ca.OP_SIN else "cos", key[1])
                if key[0] == ca.OP_COS:
                    self.cos_of[key[1]] = self.atoms[key]
        return {((self.atoms[key], 1),): 1.0}

    @staticmethod
    def key(p: dict) -> tuple:
        return tuple(sorted(p.items()))

    @staticmethod
    def scale(p: dict, c: float) -> dict:
        return {m: c * v for m, v in p.items()} if c else {}

    def spend(self, n: int) -> None:
        self.work += n
        if self.work > MAX_WORK:
            raise _TooLarge

    def add(self, a: dict, b: dict) -> dict:
        self.spend(len(a) + len(b))
        out = dict(a)
        for m, v in b.items():
            if m in out:
                s = out[m] + v
                if abs(s) <= _ZERO * max(abs(out[m]), abs(v)):
                    del out[m]
                else:
                    out[m] = s
            else:
                out[m] = v
        return self.pythagoras(out)

    def mul(self, a: dict, b: dict) -> dict:
        self.spend(len(a) * len(b))
        out: dict = {}
        for ma, va in a.items():
            for mb, vb in b.items():
                powers = dict(ma)
                for k, n in mb:
                    powers[k] = powers.get(k, 0) + n
                m = tuple(sorted(powers.items()))
                out[m] = out.get(m, 0.0) + va * vb
        return {m: v for m, v in out.items() if v != 0.0}

    def pythagoras(self, p: dict) -> dict:
        """m·sin²a + m·cos²a → m, for every such pair with equal coefficients."""
        if not self.cos_of:
            return p
        cos_of = self.cos_of
        changed = True
        while changed:
            changed = False
            for m in list(p):
                if m not in p:
                    continue
                v = p[m]
                for i, n in m:
                    kind, arg = self.trig.get(i, (None, None))
                    j = cos_of.get(arg)
                    if kind != "sin" or n < 2 or j is None:
                        continue
                    rest = dict(m)
                    rest[i] -= 2
                    other = dict(rest)
                    other[j] = other.get(j, 0) + 2
                    mo = tuple(sorted((k, e) for k, e in other.items() if e))
                    self.spend(1)
                    if mo in p and abs(p[mo] - v) <= _ZERO * abs(v):
                        del p[m], p[mo]
                        merged = tuple(sorted((k, e) for k, e in rest.items() if e))
                        p[merged] = p.get(merged, 0.0) + v
                        if p[merged] == 0.0:
                            del p[merged]
                        changed = True
                        break
        return p

    # ---- from and to SX ---------------------------------------------------------------------
    def poly(self, e: ca.SX) -> dict:
        h = e.element_hash()
        if h not in self.memo:
            self.memo[h] = self._poly(e, h)
        return self.memo[h]

    def _poly(self, e: ca.SX, h: int) -> dict:
        if e.is_constant():
            v = float(e)
            return {(): v} if v else {}
        if e.is_symbolic():
            return self.atom(("symbol", h), lambda: e)
        op, n = e.op(), e.n_dep()
        deps = [self.poly(e.dep(i)) for i in range(n)] if n in (1, 2) else []
        if op == ca.OP_ADD:
            return self.add(*deps)
        if op == ca.OP_SUB:
            return self.add(deps[0], self.scale(deps[1], -1.0))
        if op == ca.OP_NEG:
            return self.scale(deps[0], -1.0)
        if op == ca.OP_TWICE:
            return self.scale(deps[0], 2.0)
        if op in (ca.OP_MUL, ca.OP_SQ):
            a, b = (deps[0], deps[0]) if op == ca.OP_SQ else deps
            if len(a) * len(b) <= MAX_TERMS:
                return self.pythagoras(self.mul(a, b))
        if op == ca.OP_DIV and set(deps[1]) == {()}:
            return self.scale(deps[0], 1.0 / deps[1][()])
        if n == 1 and deps:
            return self.atom((op, self.key(deps[0])),
                             lambda: ca.SX.unary(op, self.build(deps[0])))
        if n == 2 and deps:
            return self.atom((op, self.key(deps[0]), self.key(deps[1])),
                             lambda: ca.SX.binary(op, self.build(deps[0]), self.build(deps[1])))
        return self.atom(("node", h), lambda: e)

    def monomial(self, m: tuple) -> ca.SX:
        """The product of the atoms' powers ``m`` (products shared by their prefixes)."""
        if m not in self.monomials:
            self.spend(1)
            i, n = m[-1]
            prefix = m[:-1] + (((i, n - 1),) if n > 1 else ())
            f = self.exprs[i]
            self.monomials[m] = _binary(ca.OP_MUL, self.monomial(prefix), f) if prefix else f
        return self.monomials[m]

    def build(self, p: dict) -> ca.SX:
        out = None
        for m, v in sorted(p.items()):
            if not m:
                term = ca.SX(v)
            elif v == 1.0:
                term = self.monomial(m)
            elif v == -1.0:
                term = ca.SX.unary(ca.OP_NEG, self.monomial(m))
            else:
                term = _binary(ca.OP_MUL, ca.SX(v), self.monomial(m))
            out = term if out is None else _binary(ca.OP_ADD, out, term)
        return ca.SX(0) if out is None else out


#: SX operations by opcode (several times cheaper from Python than the operators)
_binary = ca.SX.binary


def lean(exprs: list[ca.SX]) -> list[ca.SX]:
    """``exprs`` (SX matrices) simplified exactly, each element replaced by its polynomial
    form where that has fewer nodes, their repeated subexpressions shared (``ca.cse``);
    the simplified set is returned only if it takes fewer operations than the given one
    (shared alike), and the given one as it is if it is larger than ``MAX_NODES`` nodes or
    its expansion than ``MAX_WORK`` term operations."""
    exprs = list(exprs)
    if sum(ca.n_nodes(e) for e in exprs) > MAX_NODES:
        return exprs
    simplifier = _Lean()
    out = []
    try:
        for e in exprs:
            y = ca.SX(e.sparsity())
            for k in range(e.nnz()):
                x = e.nz[k]
                s = simplifier.build(simplifier.poly(x))
                y.nz[k] = s if ca.n_nodes(s) < ca.n_nodes(x) else x
            out.append(y)
    except _TooLarge:
        return exprs
    given, short = ca.cse(exprs), ca.cse(out)
    count = lambda es: ca.Function("count", ca.symvar(ca.veccat(*[ca.vec(e) for e in es])),
                                   es).n_instructions()
    return short if count(short) < count(given) else given
