"""Signal blocks (acausal.components.signals) against closed forms and hand-written ODEs.

References never come from the code under test: sources are compared with their MSL formulas
written in numpy (and their integrals with scipy quadrature of those formulas), the
continuous blocks with the analytic solutions of their ODEs, and a PID position loop with a
scipy model of mass + PID written out by hand.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal import Model, ParameterError, StructureError
from acausal.components import signals as sg
from acausal.components.translational import Force, Mass, PositionSensor
from time_signals import after, cumulative_integral

SIM = dict(rtol=1e-10, atol=1e-12)   # quadratures over 2-3 s: rtol 1e-8 leaves ~1e-6 errors


def _source_model(src):
    """src -> Integrator (a state, so the model has dynamics)."""
    m = Model("src_test")
    m.src = src
    m.integ = sg.Integrator()
    m.connect(m.src.y, m.integ.u)
    return m


# ---- sources: output and integral vs the MSL formulas ----------------------------------------
TWO_PI = 2 * np.pi

SOURCES = {
    "Constant": (lambda: sg.Constant(k=2.5), lambda t: 2.5 + 0 * t, ()),
    "Step": (lambda: sg.Step(height=3.0, offset=-1.0, startTime=0.7),
             lambda t: -1.0 + after(t, 0.7, 3.0), (0.7,)),
    "Ramp": (lambda: sg.Ramp(height=2.0, duration=1.2, offset=0.5, startTime=0.3),
             lambda t: 0.5 + after(t, 0.3, np.clip((t - 0.3) / 1.2, 0, 1) * 2.0), (0.3, 1.5)),
    "Sine": (lambda: sg.Sine(amplitude=1.5, f=0.8, phase=0.4, offset=0.2, startTime=0.5),
             lambda t: 0.2 + after(t, 0.5, 1.5 * np.sin(TWO_PI * 0.8 * (t - 0.5) + 0.4)),
             (0.5,)),
    "Cosine": (lambda: sg.Cosine(amplitude=0.7, f=1.3, phase=-0.2, offset=1.0, startTime=0.25),
               lambda t: 1.0 + after(t, 0.25, 0.7 * np.cos(TWO_PI * 1.3 * (t - 0.25) - 0.2)),
               (0.25,)),
    # MSL's continuous = true: before startTime the value the sine starts from, no jump
    "Sine_continuous": (lambda: sg.Sine(amplitude=1.5, f=0.8, phase=0.4, offset=0.2,
                                        startTime=0.5, continuous=True),
                        lambda t: 0.2 + 1.5 * np.where(
                            t < 0.5, np.sin(0.4), np.sin(TWO_PI * 0.8 * (t - 0.5) + 0.4)),
                        (0.5,)),
    "Cosine_continuous": (lambda: sg.Cosine(amplitude=0.7, f=1.3, phase=-0.2, offset=1.0,
                                            startTime=0.25, continuous=True),
                          lambda t: 1.0 + 0.7 * np.where(
                              t < 0.25, np.cos(-0.2), np.cos(TWO_PI * 1.3 * (t - 0.25) - 0.2)),
                          (0.25,)),
    "ExpSine": (lambda: sg.ExpSine(amplitude=2.0, f=1.5, phase=0.3, damping=0.8, offset=-0.3,
                                   startTime=0.4),
                lambda t: -0.3 + after(t, 0.4, 2.0 * np.exp(-0.8 * (t - 0.4))
                                        * np.sin(TWO_PI * 1.5 * (t - 0.4) + 0.3)), (0.4,)),
    "ExpSine_defaults": (lambda: sg.ExpSine(),      # MSL defaults: f = 2 Hz, damping = 1/s
                         lambda t: np.exp(-t) * np.sin(TWO_PI * 2.0 * t), ()),
    # period 0.8 s, 30 % width, 3 periods from t = 0.2 s
    "Pulse": (lambda: sg.Pulse(amplitude=2.0, width=30.0, period=0.8, nperiod=3, offset=0.1,
                               startTime=0.2),
              lambda t: 0.1 + np.where((t >= 0.2) & (t < 0.2 + 3 * 0.8)
                                       & (np.mod(t - 0.2, 0.8) < 0.24), 2.0, 0.0),
              (0.2, 0.44, 1.0, 1.24, 1.8, 2.04)),
    # rise 0.2 s, hold 0.3 s, fall 0.1 s, period 1 s, infinitely many periods
    "Trapezoid": (lambda: sg.Trapezoid(amplitude=1.5, rising=0.2, width=0.3, falling=0.1,
                                       period=1.0, offset=-0.5, startTime=0.1),
                  lambda t: -0.5 + after(t, 0.1, np.interp(np.mod(t - 0.1, 1.0),
                                                            [0, 0.2, 0.5, 0.6, 1.0],
                                                            [0, 1.5, 1.5, 0, 0])),
                  (0.1, 0.3, 0.6, 0.7, 1.1, 1.3, 1.6, 1.7, 2.1, 2.3, 2.6, 2.7)),
}


@pytest.mark.parametrize("name", list(SOURCES))
def test_source_and_its_integral(name):
    make, f, breaks = SOURCES[name]
    t = np.linspace(0.0, 3.0, 61)
    # periodic sources jump without solver events: a step limit lets the solver see every pulse
    max_step = 0.05 if name in ("Pulse", "Trapezoid") else None
    res = acausal.compile(_source_model(make())).simulate(3.0, t=t, max_step=max_step, **SIM)
    np.testing.assert_allclose(res["src.y"], f(t), rtol=0, atol=1e-12)
    np.testing.assert_allclose(res["integ.u"], f(t), rtol=0, atol=1e-12)
    np.testing.assert_allclose(res["integ.y"], cumulative_integral(f, t, breaks),
                               rtol=0, atol=1e-7)


def test_source_parameters_change_at_simulation_time():
    """Sine parameters are symbols of the compiled model: changed without recompiling."""
    c = acausal.compile(_source_model(sg.Sine()))
    t = np.linspace(0.0, 2.0, 41)
    res = c.simulate(2.0, t=t, params={"src.amplitude": 3.0, "src.f": 0.25,
                                       "src.startTime": 0.5, "src.offset": 1.0}, **SIM)
    ref = 1.0 + after(t, 0.5, 3.0 * np.sin(TWO_PI * 0.25 * (t - 0.5)))
    np.testing.assert_allclose(res["src.y"], ref, atol=1e-12)
    np.testing.assert_allclose(res["integ.y"], cumulative_integral(
        lambda s: 1.0 + after(s, 0.5, 3.0 * np.sin(TWO_PI * 0.25 * (s - 0.5))), t, (0.5,)),
        atol=1e-7)


def test_ramp_with_zero_duration_is_a_step():
    t = np.linspace(0.0, 1.0, 11)
    res = acausal.compile(_source_model(sg.Ramp(height=2.0, duration=0.0, startTime=0.45))) \
        .simulate(1.0, t=t, **SIM)
    np.testing.assert_allclose(res["src.y"], after(t, 0.45, 2.0), atol=0)


# ---- TimeTable --------------------------------------------------------------------------------
MSL_TABLE = [[0, 0], [1, 0], [1, 1], [2, 4], [3, 9], [4, 16]]


def test_timetable_msl_documentation_example():
    """The values listed in the MSL TimeTable documentation, extrapolation included."""
    t = np.array([0.0, 0.5, 1.0, 1.5, 2.0, 4.0, 5.0])
    res = acausal.compile(_source_model(sg.TimeTable(table=MSL_TABLE))).simulate(5.0, t=t, **SIM)
    np.testing.assert_allclose(res["src.y"], [0.0, 0.0, 1.0, 2.5, 4.0, 16.0, 23.0], atol=1e-12)
    # the integral: 0 up to t = 1, then piecewise-linear areas (trapezoids)
    areas = {1.5: 0.5 * (1 + 2.5) * 0.5, 2.0: 0.5 * (1 + 4),
             4.0: 0.5 * (1 + 4) + 0.5 * (4 + 9) + 0.5 * (9 + 16),
             5.0: 0.5 * (1 + 4) + 0.5 * (4 + 9) + 0.5 * (9 + 16) + 0.5 * (16 + 23)}
    for tk, area in areas.items():
        assert res["integ.y"][np.flatnonzero(t == tk)[0]] == pytest.approx(area, abs=1e-7)


def test_timetable_vs_numpy_interp_with_offset_starttime_timescale():
    table = np.array([[0.0, 1.0], [0.5, 3.0], [1.2, -1.0], [2.0, 0.5], [3.0, 0.5]])
    offset, start, scale = 0.25, 0.4, 0.5        # table times in units of 0.5 s
    t = np.linspace(0.0, 1.8, 73)                # stays inside the table: (t - 0.4)/0.5 <= 2.8
    src = sg.TimeTable(table=table, offset=offset, startTime=start, timeScale=scale)
    res = acausal.compile(_source_model(src)).simulate(t[-1], t=t, **SIM)
    ref = offset + after(t, start, np.interp((t - start) / scale, table[:, 0], table[:, 1]))
    np.testing.assert_allclose(res["src.y"], ref, atol=1e-12)
    f = lambda s: offset + (0.0 if s < start else np.interp((s - start) / scale, *table.T))
    breaks = [start] + list(start + scale * table[1:, 0])
    np.testing.assert_allclose(res["integ.y"], cumulative_integral(f, t, breaks), atol=1e-7)


def test_timetable_shifttime_and_extrapolation():
    """shiftTime moves the table; before it (but after startTime) the first two rows are
    extrapolated; after the end the last two; a one-row table is constant."""
    table = [[0.0, 1.0], [1.0, 3.0], [2.0, 2.0]]
    m = Model("tt")
    m.a = sg.TimeTable(table=table, startTime=0.2, shiftTime=0.5)
    m.b = sg.TimeTable(table=[[0.0, 4.0]], offset=1.0, startTime=0.3)
    m.s = sg.Add()
    m.i = sg.Integrator()
    m.connect(m.a.y, m.s.u1)
    m.connect(m.b.y, m.s.u2)
    m.connect(m.s.y, m.i.u)
    c = acausal.compile(m)
    assert "a.shiftTime" in c.param_names and "b.shiftTime" not in c.param_names
    t = np.linspace(0.0, 4.0, 41)
    res = c.simulate(4.0, t=t, **SIM)
    tau = t - 0.5
    line = np.where(tau < 1.0, 1.0 + 2.0 * tau, 3.0 - (tau - 1.0))     # rows 1-2, rows 2-3
    np.testing.assert_allclose(res["a.y"], after(t, 0.2, line), atol=1e-12)
    np.testing.assert_allclose(res["b.y"], 1.0 + after(t, 0.3, 4.0), atol=1e-12)
    # changing startTime at simulation time also moves a table whose shiftTime follows it
    c2 = acausal.compile(_source_model(sg.TimeTable(table=table)))
    res2 = c2.simulate(4.0, t=t, params={"src.startTime": 1.0}, **SIM)
    tau = t - 1.0
    np.testing.assert_allclose(
        res2["src.y"], after(t, 1.0, np.where(tau < 1.0, 1 + 2 * tau, 3 - (tau - 1))),
        atol=1e-12)


@pytest.mark.parametrize("table, match", [
    (None, "no table"), ([[0.5, 1.0], [1.0, 2.0]], "has to be 0"),
    ([[0.0, 1.0], [2.0, 2.0], [1.0, 3.0]], "non-decreasing"), ([[0, 1, 2]], "rows"),
    ([[0.0, np.nan], [1.0, 0.0]], "non-finite")])
def test_timetable_rejects_bad_tables(table, match):
    with pytest.raises(ParameterError, match=match):
        sg.TimeTable(table=table)


# ---- math blocks ------------------------------------------------------------------------------
def test_math_blocks_arithmetic():
    m = Model("math")
    m.a = sg.Sine(amplitude=2.0, f=0.5, offset=0.3)
    m.b = sg.Ramp(height=3.0, duration=1.0, offset=1.0, startTime=0.2)
    m.c = sg.Cosine(amplitude=0.5, f=1.0, offset=-0.2)
    m.gain = sg.Gain(k=-1.7)
    m.add = sg.Add(k1=0.5, k2=-2.0)
    m.add3 = sg.Add3(k1=1.0, k2=2.0, k3=-3.0)
    m.fb = sg.Feedback()
    m.prod = sg.Product()
    m.div = sg.Division()
    m.sum = sg.Sum(nin=3, k=[1.0, -0.5, 2.0])
    m.integ = sg.Integrator(k=2.0, y_start=1.0)
    for x, y in [(m.a.y, m.gain.u), (m.a.y, m.add.u1), (m.b.y, m.add.u2),
                 (m.a.y, m.add3.u1), (m.b.y, m.add3.u2), (m.c.y, m.add3.u3),
                 (m.b.y, m.fb.u1), (m.c.y, m.fb.u2), (m.a.y, m.prod.u1), (m.c.y, m.prod.u2),
                 (m.a.y, m.div.u1), (m.b.y, m.div.u2), (m.a.y, m.sum.u[1]),
                 (m.b.y, m.sum.u[2]), (m.c.y, m.sum.u[3]), (m.fb.y, m.integ.u)]:
        m.connect(x, y)
    t = np.linspace(0.0, 2.0, 41)
    res = acausal.compile(m).simulate(2.0, t=t, **SIM)
    a = 0.3 + 2.0 * np.sin(np.pi * t)
    b = 1.0 + after(t, 0.2, 3.0 * np.clip(t - 0.2, 0, 1))
    c = -0.2 + 0.5 * np.cos(TWO_PI * t)
    for name, ref in [("gain.y", -1.7 * a), ("add.y", 0.5 * a - 2.0 * b),
                      ("add3.y", a + 2 * b - 3 * c), ("fb.y", b - c), ("prod.y", a * c),
                      ("div.y", a / b), ("sum.y", a - 0.5 * b + 2.0 * c),
                      ("sum.u[2]", b)]:
        np.testing.assert_allclose(res[name], ref, rtol=0, atol=1e-12, err_msg=name)
    integral = cumulative_integral(
        lambda s: (1.0 + (0.0 if s < 0.2 else 3.0 * min(s - 0.2, 1.0)))
        - (-0.2 + 0.5 * np.cos(TWO_PI * s)), t, (0.2, 1.2))
    np.testing.assert_allclose(res["integ.y"], 1.0 + 2.0 * integral, atol=1e-7)


def test_sum_gains_are_parameters_and_inputs_are_numbered_from_one():
    s = sg.Sum(nin=2)
    assert isinstance(s, sg.Sum) and s.nin == 2 and len(s.u) == 2
    assert s.u[1].name == "u[1]" and s.u[2].name == "u[2]"
    with pytest.raises(IndexError, match="numbered 1..2"):
        s.u[0]
    with pytest.raises(ParameterError, match="k has 3 elements"):
        sg.Sum(nin=2, k=[1, 2, 3])
    with pytest.raises(ParameterError, match="nin"):
        sg.Sum(nin=0)
    m = Model("sum")
    m.one, m.two = sg.Constant(k=1.0), sg.Constant(k=10.0)
    m.sum, m.integ = s, sg.Integrator()
    m.connect(m.one.y, s.u[1])
    m.connect(m.two.y, s.u[2])
    m.connect(s.y, m.integ.u)
    c = acausal.compile(m)
    assert {"sum.k[1]", "sum.k[2]"} <= set(c.param_names)
    res = c.simulate(1.0, t=np.linspace(0, 1, 3), params={"sum.k[2]": -0.5}, **SIM)
    np.testing.assert_allclose(res["sum.y"], 1.0 - 5.0, atol=1e-14)
    np.testing.assert_allclose(res["integ.y"], -4.0 * res.t, atol=1e-9)


# ---- continuous blocks ------------------------------------------------------------------------
def _siso_model(src, block):
    m = Model("siso")
    m.src, m.blk = src, block
    m.connect(m.src.y, m.blk.u)
    return m


def test_integrator_gain_and_start_value():
    t = np.linspace(0.0, 2.0, 21)
    res = acausal.compile(_siso_model(sg.Constant(k=0.8), sg.Integrator(k=2.5, y_start=1.0))) \
        .simulate(2.0, t=t, **SIM)
    np.testing.assert_allclose(res["blk.y"], 1.0 + 2.5 * 0.8 * t, atol=1e-9)


def test_firstorder_step_response():
    k, T, h, t0, y0 = 2.0, 0.5, 1.5, 0.3, 0.4
    t = np.linspace(0.0, 3.0, 61)
    c = acausal.compile(_siso_model(sg.Step(height=h, startTime=t0),
                                    sg.FirstOrder(k=k, T=T, y_start=y0)))
    res = c.simulate(3.0, t=t, **SIM)
    ref = np.where(t < t0, y0 * np.exp(-t / T),
                   k * h + (y0 * np.exp(-t0 / T) - k * h) * np.exp(-(t - t0) / T))
    np.testing.assert_allclose(res["blk.y"], ref, atol=1e-7)
    # the textbook unit step response 1 − exp(−t/T), with parameters changed at simulation time
    res = c.simulate(3.0, t=t, params={"blk.k": 1.0, "blk.T": 0.7, "src.height": 1.0,
                                       "src.startTime": 0.0}, x0={"blk.y": 0.0}, **SIM)
    np.testing.assert_allclose(res["blk.y"], 1 - np.exp(-t / 0.7), atol=1e-7)


def test_secondorder_step_response():
    k, w, D = 1.5, 4.0, 0.3
    wd = w * np.sqrt(1 - D ** 2)
    t = np.linspace(0.0, 3.0, 61)
    res = acausal.compile(_siso_model(sg.Step(), sg.SecondOrder(k=k, w=w, D=D))) \
        .simulate(3.0, t=t, **SIM)
    decay = np.exp(-D * w * t)
    ref = k * (1 - decay * (np.cos(wd * t) + D / np.sqrt(1 - D ** 2) * np.sin(wd * t)))
    np.testing.assert_allclose(res["blk.y"], ref, atol=1e-7)
    np.testing.assert_allclose(res["blk.yd"], k * w / np.sqrt(1 - D ** 2) * decay
                               * np.sin(wd * t), atol=1e-6)


def test_derivative_of_a_sine():
    """x' = (u − x)/T with u = sin ωt, x(0) = 0, solved by hand; y = (k/T)(u − x)."""
    k, T, f = 1.5, 0.05, 0.7
    om = TWO_PI * f
    t = np.linspace(0.0, 2.0, 41)
    res = acausal.compile(_siso_model(sg.Sine(f=f), sg.Derivative(k=k, T=T))) \
        .simulate(2.0, t=t, **SIM)
    x = (np.sin(om * t) - om * T * np.cos(om * t) + om * T * np.exp(-t / T)) / (1 + (om * T) ** 2)
    np.testing.assert_allclose(res["blk.x"], x, atol=1e-7)
    np.testing.assert_allclose(res["blk.y"], k / T * (np.sin(om * t) - x), atol=1e-5)
    zero = acausal.compile(_siso_model(sg.Sine(f=f), sg.Derivative(k=0.0, T=T))) \
        .simulate(2.0, t=t, **SIM)
    assert np.all(zero["blk.y"] == 0) and np.all(zero["blk.x"] == 0)   # MSL: k = 0 -> y = 0


def test_pi_and_pid_without_derivative_part():
    """PI: x' = u/T, y = k(x + u); PID with Td = 0 is the same controller (I.y = x)."""
    k, T, f, x0 = 2.0, 0.4, 0.5, 0.3
    om = TWO_PI * f
    t = np.linspace(0.0, 2.0, 41)
    x = x0 + (1 - np.cos(om * t)) / (om * T)
    y = k * (x + np.sin(om * t))
    res = acausal.compile(_siso_model(sg.Sine(f=f), sg.PI(k=k, T=T, x_start=x0))) \
        .simulate(2.0, t=t, **SIM)
    np.testing.assert_allclose(res["blk.x"], x, atol=1e-8)
    np.testing.assert_allclose(res["blk.y"], y, atol=1e-7)
    res = acausal.compile(_siso_model(sg.Sine(f=f), sg.PID(k=k, Ti=T, Td=0.0, xi_start=x0))) \
        .simulate(2.0, t=t, **SIM)
    np.testing.assert_allclose(res["blk.I.y"], x, atol=1e-8)
    np.testing.assert_allclose(res["blk.y"], y, atol=1e-7)
    assert np.all(res["blk.D.y"] == 0)


def test_pi_initial_output_by_x0():
    """MSL's initType=InitialOutput: x0 on the output fixes the state, x(0) = y0/k − u(0)."""
    k, T, u, y0 = 2.0, 0.5, 0.6, 1.0
    t = np.linspace(0.0, 1.0, 11)
    res = acausal.compile(_siso_model(sg.Constant(k=u), sg.PI(k=k, T=T))) \
        .simulate(1.0, t=t, x0={"blk.y": y0}, **SIM)
    np.testing.assert_allclose(res["blk.y"], y0 + k * u / T * t, atol=1e-8)


def _pid_loop():
    m = Model("pid_loop")
    m.ref = sg.Step(height=0.5, offset=0.1, startTime=0.4)
    m.fb, m.pid = sg.Feedback(), sg.PID(k=30.0, Ti=0.8, Td=0.25, Nd=8.0)
    m.force, m.mass, m.probe = Force(), Mass(m=2.0), PositionSensor()
    for a, b in [(m.ref.y, m.fb.u1), (m.probe.s, m.fb.u2), (m.fb.y, m.pid.u),
                 (m.pid.y, m.force.f), (m.force.flange, m.mass.flange_a),
                 (m.probe.flange, m.mass.flange_b)]:
        m.connect(a, b)
    return m


def _pid_mass_reference(t, mass, k, Ti, Td, Nd, ref, t_step, x0):
    """m s'' = F, F = k (e + xi + Nd (e − xd)), xi' = e/Ti, xd' = (e − xd) Nd/Td, e = r − s."""
    def rhs(_, z, r):
        s, v, xi, xd = z
        e = r - s
        return [v, k * (e + xi + Nd * (e - xd)) / mass, e / Ti, (e - xd) * Nd / Td]

    sols = []
    for (a, b), r in [((0.0, t_step), ref[0]), ((t_step, t[-1]), ref[1])]:
        sel = t[(t >= a) & (t < b)] if b < t[-1] else t[t >= a]
        sol = solve_ivp(rhs, (a, b), x0, method="DOP853", args=(r,), rtol=1e-12, atol=1e-13,
                        dense_output=True)
        sols.append(sol.sol(sel))
        x0 = sol.y[:, -1]
    return np.hstack(sols)


@pytest.mark.parametrize("params", [{}, {"pid.k": 12.0, "pid.Td": 0.1, "mass.m": 0.5}])
def test_pid_positions_a_mass(params):
    """PID + Force + Mass vs the closed loop written by hand (parameters changed at
    simulation time for the second case)."""
    p = {"k": 30.0, "Ti": 0.8, "Td": 0.25, "Nd": 8.0, "m": 2.0}
    p.update({n.split(".")[1]: v for n, v in params.items()})
    t = np.linspace(0.0, 3.0, 61)
    res = acausal.compile(_pid_loop()).simulate(3.0, t=t, params=params,
                                                x0={"mass.s": 0.05, "mass.v": -0.2}, **SIM)
    z = _pid_mass_reference(t, p["m"], p["k"], p["Ti"], p["Td"], p["Nd"], (0.1, 0.6), 0.4,
                            [0.05, -0.2, 0.0, 0.0])
    for name, ref in zip(["mass.s", "mass.v", "pid.I.y", "pid.D.x"], z):
        np.testing.assert_allclose(res[name], ref, rtol=0, atol=1e-6, err_msg=name)
    e = np.where(t < 0.4, 0.1, 0.6) - z[0]
    force = p["k"] * (e + z[2] + p["Nd"] * (e - z[3]))
    np.testing.assert_allclose(res["pid.y"], force, rtol=0, atol=1e-6 * p["k"] * p["Nd"])
    np.testing.assert_allclose(res["force.f"], force, rtol=0, atol=1e-6 * p["k"] * p["Nd"])


# ---- errors -----------------------------------------------------------------------------------
def test_unconnected_input_is_an_error():
    m = Model("open")
    m.i = sg.Integrator()
    with pytest.raises(StructureError, match="i.u"):
        acausal.compile(m)


def test_parameter_checks():
    with pytest.raises(ParameterError, match="T"):
        sg.PI(T=0.0)
    with pytest.raises(ParameterError, match="Ti"):
        sg.PID(Ti=-1.0)
    with pytest.raises(ParameterError, match="duration"):
        sg.Ramp(duration=-1.0)
    with pytest.raises(ParameterError, match="y_start"):
        sg.Integrator(y_start="a")
    with pytest.raises(ParameterError, match="no parameter 'kk'"):
        sg.Gain(kk=1.0)
    c = acausal.compile(_siso_model(sg.Constant(), sg.FirstOrder()))
    with pytest.raises(ParameterError, match="blk.T"):
        c.simulate(1.0, params={"blk.T": 0.0})


def test_narrow_pulses_are_not_stepped_over():
    """Time events: 1 % pulses on a coarse grid, no max_step. The integral is the pulse area
    (amplitude·width·period per period), which fails if the solver steps across pulses."""
    c = acausal.compile(_source_model(sg.Pulse(amplitude=2.0, width=1.0, period=0.5,
                                               startTime=0.05)))
    t = np.linspace(0.0, 3.0, 4)
    res = c.simulate(3.0, t=t)
    periods_done = np.floor((t - 0.05) / 0.5 + 1e-12) + 1
    partial = np.clip(((t - 0.05) % 0.5) / (0.5 * 0.01), 0, 1)      # inside a pulse?
    area = 2.0 * 0.005 * np.where(t >= 0.05, periods_done - 1 + partial, 0)
    np.testing.assert_allclose(res["integ.y"], area, atol=1e-9)
