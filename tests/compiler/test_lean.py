"""The lean equations (acausal.compiler.lean): the cart-pole's ODE, compiled from PlanarMechanics
components with Lagrange's equations by AD and simplified, against its closed form written by
hand (M. Kelly, SIAM Review 2017, section 6; point mass m2 at the pole's tip):

    ẍ = (m2 l sinθ θ̇² + F + m2 g cosθ sinθ) / (m1 + m2 sin²θ)
    θ̈ = −(m2 l cosθ sinθ θ̇² + F cosθ + (m1 + m2) g sinθ) / (l (m1 + m2 sin²θ))

at random states and forces, to 1e-12; and the simplification on expressions whose simple
form is known (cancelling products, sin² + cos²)."""
import casadi as ca
import numpy as np
import pytest

import acausal
from acausal.compiler.lean import lean
from acausal.models.cartpole import CartPole

M1, M2, L, G = 1.2, 0.4, 0.7, 9.81


def closed_form(x, F):
    th, thd = x[1], x[3]
    s, c = np.sin(th), np.cos(th)
    den = M1 + M2 * s ** 2
    xdd = (M2 * L * s * thd ** 2 + F + M2 * G * c * s) / den
    thdd = -(M2 * L * c * s * thd ** 2 + F * c + (M1 + M2) * G * s) / (L * den)
    return np.array([x[2], x[3], xdd, thdd])


@pytest.fixture(scope="module")
def cartpole():
    return acausal.compile(CartPole(m1=M1, m2=M2, l=L))


def test_lean_cartpole_is_the_closed_form(cartpole):
    c = cartpole
    assert c.x_names == ["rail.s", "hinge.phi", "rail.v", "hinge.w"]
    folded = ca.substitute(c.ode, c.p, ca.DM(c.param_vector()))
    f = ca.Function("f", [c.x, c.u], lean([folded]))
    rng = np.random.default_rng(3)
    for _ in range(200):
        x = rng.uniform([-2, -np.pi, -3, -8], [2, np.pi, 3, 8])
        F = rng.uniform(-20, 20)
        want = closed_form(x, F)
        got = np.array(f(x, F)).ravel()
        assert np.abs(got - want).max() <= 1e-12 * (1 + np.abs(want).max())


def test_lean_cartpole_is_about_as_short_as_the_closed_form(cartpole):
    c = cartpole
    folded = ca.substitute(c.ode, c.p, ca.DM(c.param_vector()))
    x, F = ca.SX.sym("x", 4), ca.SX.sym("F")
    th, thd = x[1], x[3]
    s, co = ca.sin(th), ca.cos(th)
    den = M1 + M2 * s ** 2
    hand = ca.vertcat(x[2], x[3], (M2 * L * s * thd ** 2 + F + M2 * G * co * s) / den,
                      -(M2 * L * co * s * thd ** 2 + F * co + (M1 + M2) * G * s) / (L * den))
    n_hand = ca.Function("hand", [x, F], [hand]).n_instructions()
    n_lean = ca.Function("lean", [c.x, c.u], lean([folded])).n_instructions()
    n_raw = ca.Function("raw", [c.x, c.u], [folded]).n_instructions()
    assert n_lean < n_raw and n_lean <= 1.25 * n_hand


def test_cancelling_products_and_pythagoras():
    a, b, th = ca.SX.sym("a"), ca.SX.sym("b"), ca.SX.sym("th")
    s, c = ca.sin(th), ca.cos(th)
    e = ca.vertcat((a * s) * b - b * (s * a) + 2 * a,            # = 2a
                   0.3 * b * c * c + b * (0.3 * s ** 2),           # = 0.3 b
                   (a + b) * (a - b) - a ** 2)                      # = -b²
    out = lean([e])[0]
    for k, want in enumerate([2 * a, 0.3 * b, -b ** 2]):
        assert not ca.depends_on(out[k], th)
        f = ca.Function("f", [a, b, th], [out[k] - want])
        for v in np.random.default_rng(k).uniform(-3, 3, (20, 3)):
            assert abs(float(f(*v))) <= 1e-13
    assert ca.n_nodes(out[1]) <= ca.n_nodes(0.3 * b)
    assert not ca.depends_on(out[1], th) and not ca.depends_on(out[0], ca.vertcat(b, th))


@pytest.mark.parametrize("n", [1, 2, 3])
def test_small_solve_is_numpys_solve(n):
    from acausal.compiler.symbolic import small_solve
    A, b = ca.SX.sym("A", n, n), ca.SX.sym("b", n)
    f = ca.Function("f", [A, b], [small_solve(A, b)])
    rng = np.random.default_rng(n)
    for _ in range(20):
        An, bn = rng.normal(size=(n, n)) + n * np.eye(n), rng.normal(size=n)
        np.testing.assert_allclose(np.array(f(An, bn)).ravel(), np.linalg.solve(An, bn),
                                   rtol=1e-12, atol=1e-12)
