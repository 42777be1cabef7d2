"""CasADi SX expressions as sympy expressions: the equations of a compiled model in the form
a hand derivation has (``Lagrange.to_sympy``), with every CasADi symbol a sympy Symbol of the
same name (``hinge.phi``, ``cart.m``).

The conversion walks the algorithm of an SX Function (its instructions: inputs, constants,
operations, outputs), so shared subexpressions are converted once; constants that are short
decimals become exact rationals (0.5 → 1/2). Needs sympy (the ``symbolic`` extra).
"""
from __future__ import annotations

from fractions import Fraction

import casadi as ca


def _sympy():
    try:
        import sympy
    except ImportError:
        raise ImportError("the sympy form of the equations needs sympy: "
                          "pip install 'acausal[symbolic]'") from None
    return sympy


def _operations(sp) -> dict:
    """CasADi operation code -> sympy function of the operands. Comparisons and logic are
    numbers in CasADi (1 or 0, used in arithmetic): here Piecewise expressions of 1 and 0."""
    def truth(condition):
        return sp.Piecewise((1, condition), (0, True))

    unary = {ca.OP_NEG: lambda a: -a, ca.OP_SQ: lambda a: a ** 2, ca.OP_SQRT: sp.sqrt,
             ca.OP_SIN: sp.sin, ca.OP_COS: sp.cos, ca.OP_TAN: sp.tan, ca.OP_EXP: sp.exp,
             ca.OP_LOG: sp.log, ca.OP_ASIN: sp.asin, ca.OP_ACOS: sp.acos,
             ca.OP_ATAN: sp.atan, ca.OP_SINH: sp.sinh, ca.OP_COSH: sp.cosh,
             ca.OP_TANH: sp.tanh, ca.OP_FABS: sp.Abs, ca.OP_SIGN: sp.sign,
             ca.OP_INV: lambda a: 1 / a, ca.OP_TWICE: lambda a: 2 * a,
             ca.OP_FLOOR: sp.floor, ca.OP_CEIL: sp.ceiling, ca.OP_ERF: sp.erf,
             ca.OP_ASSIGN: lambda a: a, ca.OP_NOT: lambda a: truth(sp.Eq(a, 0)),
             ca.OP_LOG1P: lambda a: sp.log(1 + a), ca.OP_EXPM1: lambda a: sp.exp(a) - 1}
    binary = {ca.OP_ADD: lambda a, b: a + b, ca.OP_SUB: lambda a, b: a - b,
              ca.OP_MUL: lambda a, b: a * b, ca.OP_DIV: lambda a, b: a / b,
              ca.OP_POW: lambda a, b: a ** b, ca.OP_CONSTPOW: lambda a, b: a ** b,
              ca.OP_ATAN2: sp.atan2, ca.OP_FMIN: sp.Min, ca.OP_FMAX: sp.Max,
              ca.OP_HYPOT: lambda a, b: sp.sqrt(a ** 2 + b ** 2),
              ca.OP_COPYSIGN: lambda a, b: sp.Abs(a) * sp.sign(b),
              ca.OP_FMOD: sp.Mod,
              ca.OP_LT: lambda a, b: truth(sp.StrictLessThan(a, b)),
              ca.OP_LE: lambda a, b: truth(sp.LessThan(a, b)),
              ca.OP_EQ: lambda a, b: truth(sp.Eq(a, b)),
              ca.OP_NE: lambda a, b: truth(sp.Ne(a, b)),
              ca.OP_AND: lambda a, b: truth(sp.And(sp.Ne(a, 0), sp.Ne(b, 0))),
              ca.OP_OR: lambda a, b: truth(sp.Or(sp.Ne(a, 0), sp.Ne(b, 0))),
              ca.OP_IF_ELSE_ZERO: lambda c, a: sp.Piecewise((a, sp.Ne(c, 0)), (0, True))}
    return unary, binary


def _constant(sp, c: float):
    """An exact rational for a short decimal or a ratio of small integers, else a Float."""
    if c == int(c) and abs(c) < 2 ** 53:
        return sp.Integer(int(c))
    r = Fraction(c).limit_denominator(10 ** 6)
    return sp.Rational(r.numerator, r.denominator) if float(r) == c else sp.Float(c)


def to_sympy(expressions: list[ca.SX]) -> list:
    """``expressions`` (SX matrices) as sympy Matrices, each CasADi symbol in them a sympy
    Symbol of its name."""
    sp = _sympy()
    unary, binary = _operations(sp)
    outs = [ca.SX(e) for e in expressions]
    symbols = ca.symvar(ca.veccat(*outs)) if outs else []
    names = [sp.Symbol(s.name()) for s in symbols]
    f = ca.Function("f", [ca.vertcat(*symbols)] if symbols else [], outs)
    work: dict[int, object] = {}
    values = [[sp.Integer(0)] * o.nnz() for o in outs]
    for k in range(f.n_instructions()):
        op, out, ins = f.instruction_id(k), f.instruction_output(k), f.instruction_input(k)
        if op == ca.OP_INPUT:
            work[out[0]] = names[ins[1]]
        elif op == ca.OP_OUTPUT:
            values[out[0]][out[1]] = work[ins[0]]
        elif op == ca.OP_CONST:
            work[out[0]] = _constant(sp, f.instruction_constant(k))
        elif op in unary:
            work[out[0]] = unary[op](work[ins[0]])
        elif op in binary:
            work[out[0]] = binary[op](work[ins[0]], work[ins[1]])
        else:
            raise NotImplementedError(f"no sympy form of CasADi operation code {op}")
    mats = []
    for o, nz in zip(outs, values):
        m = sp.zeros(o.size1(), o.size2())
        for v, r, c in zip(nz, o.sparsity().row(), o.sparsity().get_col()):
            m[r, c] = v
        mats.append(m)
    return mats


#: Lagrange's pieces in the order they print: M q'' + C q' + K q = gravity + coriolis + B u
#: + Q_rest, then the loop constraints.
PIECES = ("M", "C", "K", "gravity", "coriolis", "B", "Q_rest", "phi", "phi_q")


def simplified(e):
    """A sympy expression collected as a hand derivation writes it: expanded, products of
    sines and cosines of sums folded (trigsimp), common factors taken out."""
    sp = _sympy()
    return sp.factor_terms(sp.trigsimp(sp.expand(e)))


class SympyEquations:
    """Lagrange's equations of a compiled model as sympy Matrices (``Lagrange.to_sympy``):
    ``q``, ``qd``, ``u`` the coordinates, their rates and the inputs as Symbols of their
    dotted names; ``M``, ``C``, ``K``, ``gravity``, ``coriolis``, ``B``, ``Q_rest`` and, with
    loops, ``phi`` and ``phi_q`` (None where ``Lagrange`` has None: K and C when the forces
    are not linear), parameters as Symbols of their dotted names."""

    def __init__(self, lagrange, simplify: bool = True):
        sp = _sympy()
        pieces = [p for p in PIECES if p[:3] != "phi" or lagrange.phi.numel()]
        values = {p: getattr(lagrange, p) for p in pieces}
        given = [p for p in pieces if values[p] is not None]
        mats = to_sympy([values[p] for p in given] + [lagrange.q, lagrange.qd, lagrange.u])
        *mats, self.q, self.qd, self.u = mats
        for p in pieces:
            setattr(self, p, None)
        for p, m in zip(given, mats):
            setattr(self, p, m.applyfunc(simplified) if simplify else m)
        self.pieces = pieces
        self._sp = sp

    def latex(self) -> str:
        """The equations in LaTeX (an ``align*`` body, one piece per line)."""
        sp = self._sp
        given = [p for p in self.pieces if getattr(self, p) is not None]
        symbols = set().union(*(getattr(self, p).free_symbols for p in given))
        names = {s: r"\mathrm{" + s.name.replace("_", r"\_") + "}" for s in symbols}
        rows = [r"M \ddot q + C \dot q + K q &= g + c + B u + Q"]
        rows += [f"{_tex_name(p)} &= {sp.latex(getattr(self, p), symbol_names=names)}"
                 for p in given]
        return " \\\\\n".join(rows)

    def __str__(self):
        lines = [f"q = {list(self.q)}", f"u = {list(self.u)}",
                 "M q'' + C q' + K q = gravity + coriolis + B u + Q_rest"]
        for p in self.pieces:
            m = getattr(self, p)
            lines.append(f"{p}: not linear" if m is None else f"{p} = {m.tolist()}")
        return "\n".join(lines)


def _tex_name(piece: str) -> str:
    return {"gravity": "g", "coriolis": "c", "Q_rest": "Q", "phi": r"\Phi",
            "phi_q": r"\Phi_q"}.get(piece, piece)
