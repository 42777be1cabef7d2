"""Timed Boolean blocks after MSL 4.1 (OnDelay, TriggeredTrapezoid, LogicalDelay,
ZeroCrossing, AssertCondition) against their closed-form switching times and values: the
inputs switch at known instants (BooleanTable, BooleanStep), the outputs must switch at
those instants plus the delays (state events located to the event tolerance) and, for the
trapezoid, follow the straight ramps between, written here independently of the block's
discrete variables (a value moving towards its target at a constant slope)."""
from __future__ import annotations

import numpy as np
import pytest

import acausal
from acausal import Model, ParameterError, SimulationError
from acausal.components import logical as lg
from acausal.components import signals as sg

SIM = dict(rtol=1e-10, atol=1e-12)
EDGES = [2.0, 4.0, 6.0, 6.5, 7.0, 9.0, 11.0]          # MSL BooleanNetwork1's booleanTable
T_END = 12.5


def _after_events(res, name: str, times) -> np.ndarray:
    """``name`` at ``times``, the value after an event where one is."""
    return np.array([res[name][np.flatnonzero(np.abs(res.t - tk) <= 1e-9)[-1]]
                     for tk in times])


def _switch_times(res, name: str) -> np.ndarray:
    """The first recorded instants of each new value of the Boolean ``name`` (an event's
    time, where the Result holds its limits)."""
    return res.t[np.flatnonzero(np.diff(res[name]) != 0) + 1]


def _u(t) -> np.ndarray:
    """The table's signal: false before 2 s, then toggled at every edge."""
    return np.searchsorted(EDGES, np.asarray(t), side="right") % 2 == 1


def _simulate(m: Model, grid):
    return acausal.compile(m).simulate(grid[-1], t=grid, **SIM)


def _table_into(m: Model, *ports) -> None:
    m.table = lg.BooleanTable(table=EDGES)
    for p in ports:
        m.connect(m.table.y, p)


GRID = np.round(np.linspace(0.0, T_END, 251), 9)


def test_on_delay_delays_rising_edges_only():
    """delayTime 1 s: y true on [3, 4), [8, 9), [12, ...): the pulse [6, 6.5) is shorter
    than the delay and gives nothing."""
    m = Model("on_delay")
    m.on = lg.MathBoolean.OnDelay(delayTime=1.0)
    _table_into(m, m.on.u)
    res = _simulate(m, GRID)
    expected = ((GRID >= 3) & (GRID < 4)) | ((GRID >= 8) & (GRID < 9)) | (GRID >= 12)
    np.testing.assert_array_equal(_after_events(res, "on.y", GRID), expected)
    np.testing.assert_allclose(_switch_times(res, "on.y"), [3, 4, 8, 9, 12], atol=1e-9)


def test_on_delay_with_u_true_at_the_start_is_true_at_once():
    """MSL's ``when initial()`` branch: a u true at the start is no rising edge, y = u."""
    m = Model("on_delay_start")
    m.table = lg.BooleanTable(table=[0.0, 1.0, 1.5])
    m.on = lg.MathBoolean.OnDelay(delayTime=0.3)
    m.connect(m.table.y, m.on.u)
    grid = np.round(np.linspace(0.0, 2.5, 101), 9)
    res = _simulate(m, grid)
    expected = (grid < 1.0) | (grid >= 1.8)
    np.testing.assert_array_equal(_after_events(res, "on.y", grid), expected)


def _trapezoid(t, amplitude, rising, falling, offset):
    """The trapezoid's closed form: from ``offset`` at the start, at every edge a straight
    ramp towards offset + amplitude (u true, slope amplitude/rising) or offset (u false,
    slope amplitude/falling), from the value reached."""
    t = np.asarray(t, dtype=float)
    y = np.full_like(t, offset)
    value, edge, u = offset, 0.0, False
    for tk in EDGES + [np.inf]:
        target = offset + amplitude if u else offset
        duration = rising if u else falling
        def moved(dt):                # how far the ramp has come after dt
            if duration == 0:
                return abs(target - value) + 0 * dt
            return np.minimum(abs(target - value), abs(amplitude) / duration * dt)
        seg = (t >= edge) & (t < tk)
        y[seg] = value + np.sign(target - value) * moved(t[seg] - edge)
        if np.isfinite(tk):
            value = value + np.sign(target - value) * moved(tk - edge)
        edge, u = tk, not u
    return y


@pytest.mark.parametrize("amplitude, rising, falling, offset", [
    (2.0, 1.5, 0.5, 0.5),      # the pulse [6, 6.5) turns mid-ramp
    (-1.0, 0.8, None, 0.2),    # falling = rising, negative amplitude
    (1.0, 0.0, 0.4, 0.0),      # jumps up, ramps down
])
def test_triggered_trapezoid_follows_its_ramps(amplitude, rising, falling, offset):
    m = Model("trapezoid")
    kw = dict(amplitude=amplitude, rising=rising, offset=offset)
    if falling is not None:
        kw["falling"] = falling
    m.tt = lg.TriggeredTrapezoid(**kw)
    _table_into(m, m.tt.u)
    res = _simulate(m, GRID)
    expected = _trapezoid(GRID, amplitude, rising, rising if falling is None else falling,
                          offset)
    np.testing.assert_allclose(_after_events(res, "tt.y", GRID), expected, atol=1e-9)


def test_triggered_trapezoid_ramp_ends_are_state_events_at_the_closed_form_times():
    """amplitude 2, rising 1.5, falling 0.5: ramps end at 3.5, 4.5, 6.5 + (2/1.5·0.5)/4,
    8.5, 9.5 s; the block's T (the instant the ramp ends) is that after each edge."""
    m = Model("trapezoid_events")
    m.tt = lg.TriggeredTrapezoid(amplitude=2.0, rising=1.5, falling=0.5, offset=0.5)
    _table_into(m, m.tt.u)
    res = _simulate(m, GRID)
    ends = [3.5, 4.5, 6.5 + (2.0 * 0.5 / 1.5) / 4.0, 8.5, 9.5, 12.5]
    after = [2.0, 4.0, 6.5, 7.0, 9.0, 11.0]
    np.testing.assert_allclose(_after_events(res, "tt.T", after), ends, atol=1e-12)
    located = [ev for ev in res.events if "tt.ramp_end" in str(ev)]
    assert len(located) == 5


def test_logical_delay_delays_the_other_edge_of_each_output():
    m = Model("logical_delay")
    m.ld = lg.LogicalDelay(delayTime=0.8)
    _table_into(m, m.ld.u)
    res = _simulate(m, GRID)
    u = _u(GRID)
    k = np.searchsorted(EDGES, GRID, side="right")
    last_change = np.where(k > 0, np.array([-np.inf] + EDGES)[k], -np.inf)
    late = GRID - last_change >= 0.8 - 1e-12       # the event at the instant itself
    np.testing.assert_array_equal(_after_events(res, "ld.y1", GRID), u | ~late)
    np.testing.assert_array_equal(_after_events(res, "ld.y2", GRID), u & late)
    np.testing.assert_allclose(_switch_times(res, "ld.y2"), [2.8, 4, 7.8, 9, 11.8], atol=1e-9)


def test_zero_crossing_triggers_at_the_crossings_while_enabled():
    """u = sin(2π·0.3·t + 0.2), enabled on [1, 4): a Timer fed by y records in entryTime the
    last crossing, (kπ − 0.2)/(2π·0.3) for k = 1, 2; the enabling edge (u > 0 there) and
    the disabling one (u > 0) trigger nothing, nor the crossing at 4.89 s (disabled)."""
    m = Model("zero_crossing")
    m.sine = sg.Sine(f=0.3, phase=0.2)
    m.enable = lg.BooleanTable(table=[1.0, 4.0])
    m.zc, m.timer = lg.ZeroCrossing(), lg.Timer()
    m.connect(m.sine.y, m.zc.u)
    m.connect(m.enable.y, m.zc.enable)
    m.connect(m.zc.y, m.timer.u)
    grid = np.round(np.linspace(0.0, 6.0, 121), 9)
    res = _simulate(m, grid)
    crossings = (np.array([1, 2]) * np.pi - 0.2) / (2 * np.pi * 0.3)
    expected = np.where(grid < crossings[0], 0.0, np.where(grid < crossings[1], crossings[0],
                                                           crossings[1]))
    np.testing.assert_allclose(_after_events(res, "timer.entryTime", grid), expected,
                               atol=1e-9)


def test_assert_condition_stops_where_its_input_falls():
    m = Model("assert")
    m.step = lg.BooleanStep(startTime=0.7, startValue=True)
    m.check = lg.AssertCondition(message="the step must stay true")
    m.connect(m.step.y, m.check.u)
    with pytest.raises(SimulationError, match=r"(?s)check.*the step must stay true.*0\.7"):
        acausal.compile(m).simulate(1.0)


@pytest.mark.parametrize("make, text", [
    (lambda: lg.MathBoolean.OnDelay(delayTime=0.0), "delayTime"),
    (lambda: lg.MathBoolean.OnDelay(delayTime=-1.0), "delayTime"),
    (lambda: lg.MathBoolean.OnDelay(), "delayTime"),
    (lambda: lg.TriggeredTrapezoid(rising=-0.1), "rising"),
    (lambda: lg.LogicalDelay(delayTime=-1.0), "delayTime"),
])
def test_bad_parameters_are_parameter_errors_naming_the_block(make, text):
    with pytest.raises(ParameterError, match=text) as info:
        make()
    name = str(info.value)
    assert any(b in name for b in ("OnDelay", "TriggeredTrapezoid", "LogicalDelay")), name
