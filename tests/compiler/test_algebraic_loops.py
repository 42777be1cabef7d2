"""Algebraic loops of blocks (signals that depend on each other without a state in between)
are torn into algebraic variables and solved with the model, as a Modelica tool does;
checked against closed forms, numpy's roots of the loop's cubic and a scipy model."""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.analysis import linearize
from acausal.components import signals as sg
from acausal.components.translational import Force, Mass
from signal_loops import speed_loop

T = np.linspace(0.0, 2.0, 201)


def gain_loop():
    """Constant 1 → Feedback → Gain(k = 2) → back to the Feedback, integrated: the loop
    holds g.y = 2·(1 − g.y), so g.y = 2/3 and i.y = 2/3·t."""
    m = acausal.Model("loop")
    m.c, m.fb, m.g = sg.Constant(), sg.Feedback(), sg.Gain(k=2.0)
    m.i = sg.Integrator()
    m.connect(m.c.y, m.fb.u1)
    m.connect(m.fb.y, m.g.u)
    m.connect(m.g.y, m.fb.u2)
    m.connect(m.g.y, m.i.u)
    return m


def test_a_loop_of_gains_is_solved():
    c = acausal.compile(gain_loop())
    assert len(c.z_names) == 1 and c.z_names[0] in ("fb.y", "g.y")   # one torn signal
    res = c.simulate(2.0, t=T)
    np.testing.assert_allclose(res["g.y"], 2 / 3, rtol=1e-12)
    np.testing.assert_allclose(res["fb.y"], 1 / 3, rtol=1e-12)
    np.testing.assert_allclose(res["i.y"], 2 / 3 * T, rtol=0, atol=1e-8)


def cubic_loop(a=0.7):
    """fb.y = 3·sin(2π·0.5·t) − a·fb.y³, driving a mass."""
    m = acausal.Model("cubic")
    m.u, m.fb = sg.Sine(amplitude=3.0, f=0.5), sg.Feedback()
    m.sq, m.cube, m.g = sg.Product(), sg.Product(), sg.Gain(k=a)
    m.connect(m.u.y, m.fb.u1)
    m.connect(m.fb.y, m.sq.u1)
    m.connect(m.fb.y, m.sq.u2)
    m.connect(m.sq.y, m.cube.u1)
    m.connect(m.fb.y, m.cube.u2)
    m.connect(m.cube.y, m.g.u)
    m.connect(m.g.y, m.fb.u2)
    m.mass, m.force = Mass(m=1.0), Force()           # something that moves with it
    m.connect(m.fb.y, m.force.f)
    m.connect(m.force.flange, m.mass.flange_a)
    return m


def cubic_root(a, u):
    """The one real root of a·y³ + y − u = 0 for each u (numpy)."""
    return np.array([next(r.real for r in np.roots([a, 0.0, 1.0, -uk]) if abs(r.imag) < 1e-9)
                     for uk in u])


def test_a_nonlinear_loop_follows_the_real_root():
    res = acausal.compile(cubic_loop(0.7)).simulate(2.0, t=T)
    np.testing.assert_allclose(res["fb.y"], cubic_root(0.7, 3.0 * np.sin(np.pi * T)), rtol=0,
                               atol=1e-7)


def test_a_loop_around_a_state_against_the_closed_form_and_scipy():
    m_, k, g, r = 2.0, 5.0, 0.5, 1.5
    c = acausal.compile(speed_loop(m_, k, g, r))
    res = c.simulate(2.0, t=T)
    tau = m_ * (1 + k * g) / k
    np.testing.assert_allclose(res["mass.v"], r * (1 - np.exp(-T / tau)), rtol=0, atol=1e-7)
    sol = solve_ivp(lambda t, v: [k * (r - v[0]) / (1 + k * g) / m_], (0, 2.0), [0.0],
                    t_eval=T, rtol=1e-11, atol=1e-13)
    np.testing.assert_allclose(res["force.f"], k * (r - sol.y[0]) / (1 + k * g), rtol=0,
                               atol=1e-6)


def test_linearized_loop_is_the_closed_loop():
    m_, k, g = 2.0, 5.0, 0.5
    lin = linearize(acausal.compile(speed_loop(m_, k, g)))
    iv = lin.states.index("mass.v")
    assert math.isclose(lin.A[iv, iv], -k / (m_ * (1 + k * g)), rel_tol=1e-12)


def test_a_loop_of_gain_one_is_named():
    """Feedback(1 − y) with y = 2·(0.5·…): y = 1 − y·… cancels: no solution."""
    m = acausal.Model("singular")
    m.c, m.add, m.g1, m.g2 = sg.Constant(), sg.Add(), sg.Gain(k=2.0), sg.Gain(k=0.5)
    m.connect(m.c.y, m.add.u1)
    m.connect(m.add.y, m.g1.u)
    m.connect(m.g1.y, m.g2.u)
    m.connect(m.g2.y, m.add.u2)
    m.i = sg.Integrator()
    m.connect(m.g1.y, m.i.u)
    with pytest.raises(acausal.InitializationError, match="loop of blocks whose gain is "
                                                          "exactly 1"):
        acausal.compile(m).simulate(1.0)


def test_a_sweep_of_the_cubic_loop_equals_simulate():
    """The runs of a sweep solve their algebraic variables again at the output times as
    simulate() does: each equals the real root of its cubic."""
    c = acausal.compile(cubic_loop())
    res = c.sweep(2.0, t=T, params={"g.k": [0.7, 2.0]}, variables=["fb.y"])
    u = 3.0 * np.sin(np.pi * T)
    for k, a in enumerate([0.7, 2.0]):
        np.testing.assert_allclose(res.dataset["fb.y"][k], cubic_root(a, u), rtol=0, atol=1e-7)
