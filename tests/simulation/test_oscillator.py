"""Harmonic oscillator (wall | spring | mass, and with a damper) against its closed form."""
import numpy as np
import pytest

import acausal
from acausal.components.translational import Damper, Fixed, Mass, Spring

S0_WALL, S_REL0, LEN = 0.3, 0.5, 0.2     # wall position, unstretched length, mass length [m]


def oscillator(m=0.5, c=8.0, d=None):
    """wall (at S0_WALL) | spring (c, s_rel0) [|| damper d] | mass (m, L)."""
    model = acausal.Model("osc")
    model.wall = Fixed(s0=S0_WALL)
    model.spring = Spring(c=c, s_rel0=S_REL0)
    model.mass = Mass(m=m, L=LEN)
    model.connect(model.wall.flange, model.spring.flange_a)
    model.connect(model.spring.flange_b, model.mass.flange_a)
    if d is not None:
        model.damper = Damper(d=d)
        model.connect(model.wall.flange, model.damper.flange_a)
        model.connect(model.damper.flange_b, model.mass.flange_a)
    return model


S_EQ = S0_WALL + S_REL0 + LEN / 2        # centre of the mass at rest


def closed_form(t, m, c, s0, v0, d=0.0):
    """Centre position of the (under)damped oscillator m x'' + d x' + c x = 0, x = s − S_EQ."""
    w0 = np.sqrt(c / m)
    zeta = d / (2 * np.sqrt(c * m))
    wd = w0 * np.sqrt(1 - zeta ** 2)
    x0 = s0 - S_EQ
    return S_EQ + np.exp(-zeta * w0 * t) * (x0 * np.cos(wd * t)
                                            + (v0 + zeta * w0 * x0) / wd * np.sin(wd * t))


@pytest.fixture(scope="module")
def compiled():
    return acausal.compile(oscillator())


def test_free_oscillation(compiled):
    t = np.linspace(0, 3.0, 301)
    res = compiled.simulate(3.0, t=t, x0={"mass.s": S_EQ + 0.1, "mass.v": 0.2})
    ref = closed_form(t, 0.5, 8.0, S_EQ + 0.1, 0.2)
    np.testing.assert_allclose(res["mass.s"], ref, rtol=0, atol=1e-6)
    w = 4.0
    v_ref = -0.1 * w * np.sin(w * t) + 0.2 * np.cos(w * t)
    np.testing.assert_allclose(res["mass.v"], v_ref, rtol=0, atol=1e-6)
    np.testing.assert_allclose(res["mass.a"], -w ** 2 * (ref - S_EQ), rtol=0, atol=1e-5)
    # flange positions follow the centre; the spring force is c (s_rel − s_rel0)
    np.testing.assert_allclose(res["mass.flange_a.s"], ref - LEN / 2, atol=1e-6)
    np.testing.assert_allclose(res["mass.flange_b.s"], ref + LEN / 2, atol=1e-6)
    np.testing.assert_allclose(res["spring.f"], 8.0 * (ref - S_EQ), atol=1e-5)


def test_initial_values_by_any_name(compiled):
    """x0 may name a flange position instead of the centre."""
    t = np.linspace(0, 1.0, 101)
    res = compiled.simulate(1.0, t=t, x0={"mass.flange_b.s": S_EQ + LEN / 2 - 0.05})
    np.testing.assert_allclose(res["mass.s"], closed_form(t, 0.5, 8.0, S_EQ - 0.05, 0.0),
                               atol=1e-6)


@pytest.mark.parametrize("m, c", [(0.5, 8.0), (2.0, 8.0), (0.5, 50.0), (0.125, 2.0)])
def test_parameters_changed_at_simulation_time(compiled, m, c):
    """The same compiled model, new m and c: the frequency is sqrt(c/m) each time."""
    t = np.linspace(0, 3.0, 301)
    res = compiled.simulate(3.0, t=t, params={"mass.m": m, "spring.c": c},
                            x0={"mass.s": S_EQ + 0.1})
    np.testing.assert_allclose(res["mass.s"], closed_form(t, m, c, S_EQ + 0.1, 0.0), atol=1e-6)
    # measured frequency: zero crossings of the displacement
    x = res["mass.s"] - S_EQ
    crossings = t[:-1][np.sign(x[:-1]) != np.sign(x[1:])]
    if len(crossings) >= 3:
        period = 2 * np.mean(np.diff(crossings))
        assert period == pytest.approx(2 * np.pi / np.sqrt(c / m), rel=0.02)


def test_geometry_parameters_changed_at_simulation_time(compiled):
    """Offsets (wall position, unstretched length, mass length) are parameters too."""
    t = np.linspace(0, 2.0, 201)
    res = compiled.simulate(2.0, t=t, params={"wall.s0": -1.0, "spring.s_rel0": 0.25,
                                              "mass.L": 0.5}, x0={"mass.s": 0.0})
    s_eq = -1.0 + 0.25 + 0.25
    np.testing.assert_allclose(res["mass.s"], s_eq + (0.0 - s_eq) * np.cos(4.0 * t), atol=1e-6)


def test_defaults_unchanged_after_override(compiled):
    t = np.linspace(0, 1.0, 101)
    compiled.simulate(1.0, t=t, params={"spring.c": 100.0}, x0={"mass.s": S_EQ + 0.1})
    res = compiled.simulate(1.0, t=t, x0={"mass.s": S_EQ + 0.1})
    np.testing.assert_allclose(res["mass.s"], closed_form(t, 0.5, 8.0, S_EQ + 0.1, 0.0),
                               atol=1e-6)


@pytest.mark.parametrize("d", [0.4, 1.5])
def test_damped_oscillator(d):
    compiled = acausal.compile(oscillator(m=0.5, c=8.0, d=d))
    t = np.linspace(0, 3.0, 301)
    res = compiled.simulate(3.0, t=t, x0={"mass.s": S_EQ + 0.1, "mass.v": -0.3})
    np.testing.assert_allclose(res["mass.s"], closed_form(t, 0.5, 8.0, S_EQ + 0.1, -0.3, d),
                               rtol=0, atol=1e-6)
    # damping can be changed at simulation time as well
    res2 = compiled.simulate(3.0, t=t, params={"damper.d": 2 * d},
                             x0={"mass.s": S_EQ + 0.1, "mass.v": -0.3})
    np.testing.assert_allclose(res2["mass.s"],
                               closed_form(t, 0.5, 8.0, S_EQ + 0.1, -0.3, 2 * d), atol=1e-6)
