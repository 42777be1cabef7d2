"""The sympy form of Lagrange's equations against a hand derivation of the two-link arm,
and the SX → sympy conversion against CasADi's own evaluation."""
import casadi as ca
import numpy as np
import pytest

import acausal as ac
from acausal.compiler.sympy_form import to_sympy
from acausal.models.pendulums import PendulumChain

sp = pytest.importorskip("sympy")


def two_link():
    """The planar two-link arm (PendulumChain(2): bodies at the ends of bars r = (0, a),
    (0, b) [m], a, b < 0 hanging down), geometry along the bars kept symbolic."""
    c = ac.compile(PendulumChain(2))
    fixed = {k: v for k, v in c.param_defaults.items()
             if k in ("fixed.phi", "bar1.r[1]", "bar2.r[1]", "world.n[1]", "world.n[2]")}
    return c, c.lagrange.with_values(fixed).to_sympy()


def test_two_link_arm_equals_the_hand_derivation():
    c, eq = two_link()
    q1, q2 = sp.symbols("rev1.phi rev2.phi")
    w1, w2 = sp.symbols("rev1.w rev2.w")
    m1, m2, I1, I2, a, b, g = sp.symbols("body1.m body2.m body1.I body2.I bar1.r[2] "
                                         "bar2.r[2] world.g")
    # hand derivation: p1 = a·(−sin q1, cos q1), p2 = p1 + b·(−sin(q1+q2), cos(q1+q2)),
    # T = ½ Σ m |ṗ|² + ½ I1 q̇1² + ½ I2 (q̇1 + q̇2)², V = g Σ m y
    M = sp.Matrix([[m1 * a**2 + m2 * (a**2 + b**2 + 2 * a * b * sp.cos(q2)) + I1 + I2,
                    m2 * (b**2 + a * b * sp.cos(q2)) + I2],
                   [m2 * (b**2 + a * b * sp.cos(q2)) + I2, m2 * b**2 + I2]])
    V = g * (m1 * a * sp.cos(q1) + m2 * (a * sp.cos(q1) + b * sp.cos(q1 + q2)))
    gravity = -sp.Matrix([V]).jacobian([q1, q2]).T
    h = m2 * a * b * sp.sin(q2)                  # Christoffel form of the Coriolis terms
    coriolis = sp.Matrix([h * (2 * w1 * w2 + w2**2), -h * w1**2])
    assert list(eq.q) == [q1, q2] and list(eq.qd) == [w1, w2]
    for ours, hand in ((eq.M, M), (eq.gravity, gravity), (eq.coriolis, coriolis)):
        assert sp.simplify(ours - hand) == sp.zeros(*hand.shape)
    # printed as a hand derivation writes it: no CasADi temporaries, sums of angles folded
    assert str(eq.M[1, 1]) == "bar2.r[2]**2*body2.m + body2.I"
    assert "@" not in str(c.lagrange) and "cos(rev2.phi)" in str(eq.M[0, 1])
    assert (r"M &= \left[\begin{matrix}\mathrm{bar1.r[2]}^{2} \mathrm{body1.m}"
            in eq.latex())
    assert r"\cos{\left(\mathrm{rev2.phi} \right)}" in eq.latex()


def test_conversion_equals_casadi_evaluation():
    x, y = ca.SX.sym("x"), ca.SX.sym("y")
    e = ca.vertcat(ca.sin(x) * y + 0.5 * x**2, ca.atan2(x, y), ca.sqrt(x**2 + 1) / ca.exp(y),
                   ca.fmax(x, y) * ca.tanh(x), ca.if_else(x > y, x, 0))
    J = ca.jacobian(e, ca.vertcat(x, y))
    f = ca.Function("f", [x, y], [e, J])
    sx, sy = sp.symbols("x y")
    E, JJ = to_sympy([e, J])
    for xv, yv in [(0.3, -1.2), (2.0, 0.7), (-0.4, 0.1)]:
        ref_e, ref_J = (np.array(v, dtype=float) for v in f(xv, yv))
        got_e = np.array(E.subs({sx: xv, sy: yv}).evalf(), dtype=float)
        got_J = np.array(JJ.subs({sx: xv, sy: yv}).evalf(), dtype=float)
        np.testing.assert_allclose(got_e, ref_e, rtol=1e-14, atol=1e-14)
        np.testing.assert_allclose(got_J, ref_J, rtol=1e-14, atol=1e-14)
    assert E[0] == sx**2 / 2 + sy * sp.sin(sx)      # 0.5 became exactly 1/2
