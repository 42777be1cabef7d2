"""A failed integration is explained in the model's terms (the exact advice expected)."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import acausal as ac
from acausal.models import Parallelogram
from acausal.simulation.diagnosis import failure_message


@pytest.fixture(scope="module")
def parallelogram():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return ac.compile(Parallelogram())


def test_tight_tolerances_are_blamed_not_praised(parallelogram):
    """At rtol 1e-12 / atol 1e-14 IDAS's corrector fails on the parallelogram: the advice is
    to loosen the tolerances (it used to be to tighten them)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(ac.SimulationError, match=r"rtol = 1e-12, atol = 1e-14 are tighter "
                                                     r"than .* loosen them"):
            parallelogram.simulate(3.0, x0={"rev1.phi": 0.5, "rev1.w": 0.0},
                                   guess={"rev2.phi": -0.5, "rev3.phi": 0.5},
                                   rtol=1e-12, atol=1e-14)


def test_singular_loop_configuration_is_named(parallelogram):
    """At the collinear position of a parallelogram (crank, coupler, rocker all along x:
    rev1.phi = rev3.phi = 0) its loop constraints' Jacobian loses a rank; a failure there is
    explained as a dead point, naming the loop's rows and the coordinates."""
    c = parallelogram
    x = np.zeros(c.x.numel())                       # every joint at 0: the collinear position
    z = np.zeros(c.z.numel())
    p = c.param_vector()
    error = RuntimeError('IDASolve returned "IDA_CONV_FAIL"\nAt t = 0.7 and h = 1e-20, the '
                         'corrector convergence failed')
    text = failure_message(c, error, 0.0, 3.0, 1e-8, 1e-10, lambda t: (x, z), p,
                           lambda t: c.input_start)
    assert "Near t = 0.7 s the closed loop reaches a singular configuration" in text
    assert "rev4" in text and "rev1.phi = 0" in text
    assert "loosen" not in text


def test_massless_parts_that_nothing_holds_are_named():
    """A spring-damper connected to nothing: both flanges massless, the damper fixes only
    their relative speed, so their common motion is free (the algebraic equations' Jacobian
    d·[[1, −1], [−1, 1]] is singular). The failure names both flanges' unknowns and says to
    fix or give mass; a grounded one runs: s_rel decays as e^(−c·t/d) from 0.1 m."""
    from acausal.components import translational as tr
    m = ac.Model("floating")
    m.part = tr.SpringDamper(c=2.0, d=1.0)
    with pytest.raises(ac.SimulationError, match=r"do not determine der\(part\.flange_a\.s\), "
                                                 r"der\(part\.flange_b\.s\) .*connect them to "
                                                 r"a fixed point"):
        ac.compile(m).simulate(0.1)
    m.fixed = tr.Fixed()
    m.connect(m.fixed.flange, m.part.flange_a)
    t = np.linspace(0.0, 1.0, 11)
    res = ac.compile(m).simulate(1.0, t=t, x0={"part.flange_b.s": 0.1})
    assert np.allclose(res["part.s_rel"], 0.1 * np.exp(-2.0 * t), atol=1e-7)


def test_a_finite_time_blow_up_is_named_where_and_stderr_stays_quiet(capfd):
    """m·v' = v² with v(0) = 1 m/s, m = 1 kg: v = 1/(1 − t) grows without bound at t = 1 s.
    The error says so, with the time; what SUNDIALS and CasADi wrote (tens of thousands of
    lines: steps too small, Inf detected) is not poured onto the user's terminal."""
    from acausal.components import signals as sg
    from acausal.components.translational import Force, Mass, SpeedSensor
    m = ac.Model("blow_up")
    m.mass, m.force, m.speed, m.sq = Mass(m=1.0), Force(), SpeedSensor(), sg.Product()
    for a, b in [(m.speed.v, m.sq.u1), (m.speed.v, m.sq.u2), (m.sq.y, m.force.f),
                 (m.force.flange, m.mass.flange_a), (m.speed.flange, m.mass.flange_b)]:
        m.connect(a, b)
    compiled = ac.compile(m)
    capfd.readouterr()
    with pytest.raises(ac.SimulationError, match=r"became infinite or NaN near t = 1 s: the "
                                                 r"states grow without bound"):
        compiled.simulate(2.0, x0={"mass.v": 1.0})
    assert capfd.readouterr().err == ""
