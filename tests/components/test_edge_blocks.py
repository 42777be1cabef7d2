"""Edge detectors, Timer, RSFlipFlop and SampleTrigger (acausal.components.logical) against
closed-form switching times and values, and MSL's BooleanNetwork1 reference result.

Edges are true only within the event iteration at their instants, so they are observed
through what they latch: an RSFlipFlop set and reset by them switches at the instants of
the input's edges (BooleanPulse, BooleanTable, BooleanStep: known times), and the time it
spends set is the integral of its output, exact to the integrator's tolerance.
"""
from __future__ import annotations

import numpy as np
import pytest

import acausal
from acausal import Model
from acausal.components import logical as lg
from acausal.components import signals as sg

SIM = dict(rtol=1e-10, atol=1e-12)


def _after_events(res, name: str, times: np.ndarray) -> np.ndarray:
    """``name`` at ``times``, the value after an event where one is (the last column at
    that time)."""
    return np.array([res[name][np.flatnonzero(np.abs(res.t - tk) <= 1e-9)[-1]]
                     for tk in times])


def _with_time_set(m: Model, port) -> Model:
    """Adds ``set_time``: the integral of the Boolean ``port`` (its time true) [s]."""
    m.to_real, m.set_time = lg.BooleanToReal(), sg.Integrator()
    m.connect(port, m.to_real.u)
    m.connect(m.to_real.y, m.set_time.u)
    return m


def _pulse_and_table() -> Model:
    """Edges of a pulse (rising at 0.2 + k s) set a flip flop, rising edges of a table
    (true at 0.7, false at 1.6, true at 2.4 s) reset it."""
    m = Model("edges")
    m.pulse = lg.BooleanPulse(width=30.0, period=1.0, startTime=0.2)
    m.table = lg.BooleanTable(table=[0.7, 1.6, 2.4])
    m.rise_p, m.rise_t = lg.Edge(), lg.Edge()
    m.ff = lg.RSFlipFlop()
    for a, b in ((m.pulse.y, m.rise_p.u), (m.table.y, m.rise_t.u),
                 (m.rise_p.y, m.ff.S), (m.rise_t.y, m.ff.R)):
        m.connect(a, b)
    return _with_time_set(m, m.ff.Q)


def test_rising_edges_set_and_reset_a_flip_flop():
    t = np.linspace(0.0, 3.5, 351)
    res = acausal.compile(_pulse_and_table()).simulate(3.5, t=t, **SIM)
    set_ = ((t >= 0.2) & (t < 0.7)) | ((t >= 1.2) & (t < 2.4)) | (t >= 3.2)
    grid = np.round(t, 9)
    np.testing.assert_array_equal(_after_events(res, "ff.Q", grid), set_)
    np.testing.assert_array_equal(_after_events(res, "ff.QI", grid), ~set_)
    switches = [ev.time for ev in res.events if "ff.pre.y" in ev.modes]
    np.testing.assert_allclose(switches, [0.2, 0.7, 1.2, 2.4, 3.2], atol=1e-12)
    assert res["set_time.y"][-1] == pytest.approx(0.5 + 1.2 + 0.3, abs=1e-8)
    # the edge outputs are false after every event
    assert not np.any(_after_events(res, "rise_p.y", grid))


def test_falling_edge_and_change():
    """Falling edges of the pulse (at 0.5 + k s) set, its rising edges reset: Q = not pulse
    after the first falling edge. A Change of the pulse toggles nothing by itself; a
    flip flop set by Change and reset by the rising edge is set at every falling edge
    (at a rising edge S and R are both true: Q stays false)."""
    m = Model("falling")
    m.pulse = lg.BooleanPulse(width=30.0, period=1.0, startTime=0.2)
    m.fall, m.rise, m.change = lg.FallingEdge(), lg.Edge(), lg.Change()
    m.ff = lg.RSFlipFlop()
    for a, b in ((m.pulse.y, m.fall.u), (m.pulse.y, m.rise.u), (m.pulse.y, m.change.u),
                 (m.fall.y, m.ff.S), (m.rise.y, m.ff.R)):
        m.connect(a, b)
    _with_time_set(m, m.ff.Q)
    t = np.linspace(0.0, 3.0, 301)
    res = acausal.compile(m).simulate(3.0, t=t, **SIM)
    grid = np.round(t, 9)
    tp = np.round(np.mod(grid - 0.2, 1.0), 9)
    expected = (grid >= 0.5) & ~(tp < 0.3)
    np.testing.assert_array_equal(_after_events(res, "ff.Q", grid), expected)
    # set at 0.5, 1.5, 2.5, reset at 1.2, 2.2: 0.7 + 0.7 + 0.5 s set
    assert res["set_time.y"][-1] == pytest.approx(1.9, abs=1e-8)
    changes = [ev.time for ev in res.events if "change.pre_u" in ev.modes]
    np.testing.assert_allclose(changes, [0.2, 0.5, 1.2, 1.5, 2.2, 2.5], atol=1e-12)


@pytest.mark.parametrize("pre_u_start, qini, set_at_start", [
    (False, False, True), (True, False, False), (True, True, True)])
def test_pre_u_start_and_qini(pre_u_start, qini, set_at_start):
    """A constant true input is a rising edge at the start unless pre_u_start = true;
    Qini is Q's value before anything sets it."""
    m = Model("start")
    m.on, m.off = lg.BooleanConstant(k=True), lg.BooleanConstant(k=False)
    m.rise = lg.Edge(pre_u_start=pre_u_start)
    m.ff = lg.RSFlipFlop(Qini=qini)
    m.connect(m.on.y, m.rise.u)
    m.connect(m.rise.y, m.ff.S)
    m.connect(m.off.y, m.ff.R)
    _with_time_set(m, m.ff.Q)
    res = acausal.compile(m).simulate(1.0, t=np.linspace(0.0, 1.0, 11), **SIM)
    np.testing.assert_array_equal(res["ff.Q"], set_at_start)
    np.testing.assert_array_equal(res["ff.QI"], not set_at_start)
    assert res["set_time.y"][-1] == pytest.approx(float(set_at_start), abs=1e-9)


def test_timer_measures_the_time_since_u_became_true():
    m = Model("timer")
    m.pulse = lg.BooleanPulse(width=40.0, period=0.8, startTime=0.3)
    m.step = lg.BooleanStep(startTime=0.7)
    m.t_pulse, m.t_step = lg.Timer(), lg.Timer()
    m.connect(m.pulse.y, m.t_pulse.u)
    m.connect(m.step.y, m.t_step.u)
    t = np.linspace(0.0, 3.0, 301)
    res = acausal.compile(m).simulate(3.0, t=t, **SIM)
    grid = np.round(t, 9)
    tau = grid - 0.3
    tp = tau - np.floor(tau / 0.8 + 1e-12) * 0.8
    on = (tau >= 0) & (tp < 0.32 - 1e-12)
    np.testing.assert_allclose(_after_events(res, "t_pulse.y", grid), np.where(on, tp, 0.0),
                               atol=1e-9)
    np.testing.assert_allclose(_after_events(res, "t_step.y", grid),
                               np.maximum(grid - 0.7, 0.0), atol=1e-9)
    np.testing.assert_allclose(_after_events(res, "t_pulse.entryTime", [3.0]), 2.7, atol=1e-12)


def test_timer_started_late_with_u_true_measures_from_time_zero():
    """A simulation started at t0 = 0.5 s with u already true: MSL's ``when u`` is inactive
    at initialization, so entryTime keeps its start 0 and y = time (not time − t0) until u
    falls at 1.3 s; u true again from 1.6 s gives y = time − 1.6 (BooleanTable: true on
    [0, 1.3) and from 1.6 s). A u false at the start (a step at 0.9 s) gives time − 0.9."""
    m = Model("late_timer")
    m.table = lg.BooleanTable(table=[0.0, 1.3, 1.6])
    m.step = lg.BooleanStep(startTime=0.9)
    m.t_table, m.t_step = lg.Timer(), lg.Timer()
    m.connect(m.table.y, m.t_table.u)
    m.connect(m.step.y, m.t_step.u)
    t = np.linspace(0.5, 2.5, 201)
    res = acausal.compile(m).simulate(2.5, t=t, **SIM)
    grid = np.round(t, 9)
    expected = np.where(grid < 1.3, grid, np.where(grid < 1.6, 0.0, grid - 1.6))
    np.testing.assert_allclose(_after_events(res, "t_table.y", grid), expected, atol=1e-9)
    np.testing.assert_allclose(_after_events(res, "t_step.y", grid),
                               np.maximum(grid - 0.9, 0.0), atol=1e-9)
    assert res["t_table.y"][0] == pytest.approx(0.5, abs=1e-12)
    assert res["t_table.entryTime"][0] == 0.0


def test_flip_flop_of_msl_boolean_network1(reference_result):
    """MSL Blocks.Examples.BooleanNetwork1: rSFlipFlop set by SampleTrigger(period=0.5),
    reset by SampleTrigger(period=0.5, startTime=0.3); its pre.u (= QI after each event)
    against the reference result."""
    ref = reference_result("MAP-LIB_ReferenceResults", "Modelica.Blocks.Examples.BooleanNetwork1")
    m = Model("BooleanNetwork1")
    m.sampleTriggerSet = lg.SampleTrigger(period=0.5, startTime=0.0)
    m.sampleTriggerReset = lg.SampleTrigger(period=0.5, startTime=0.3)
    m.rSFlipFlop = lg.RSFlipFlop()
    m.connect(m.sampleTriggerSet.y, m.rSFlipFlop.S)
    m.connect(m.sampleTriggerReset.y, m.rSFlipFlop.R)
    t = ref["time"]
    res = acausal.compile(m).simulate(t[-1], t=t, **SIM)
    # all but the final time, a sample instant the simulation does not take (the reference
    # does: set there)
    np.testing.assert_array_equal(_after_events(res, "rSFlipFlop.QI", t[:-1]),
                                  ref["rSFlipFlop.pre.u"][:-1])
    assert np.count_nonzero(np.diff(ref["rSFlipFlop.pre.u"][:-1])) == 39   # 19 sets after the start, 20 resets
