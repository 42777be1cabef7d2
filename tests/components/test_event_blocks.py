"""Blocks with events or discrete time (acausal.components.logical, .discrete) against closed
forms, hand-written numpy/scipy models and MSL's published reference result.

Relations switch where their inputs cross (arcsin solutions, brentq roots; located to 1e-9
s); Hysteresis and OnOffController run a bang-bang loop on a first-order plant whose switching
times are logarithms; a ZeroOrderHold of a ramp is an exact staircase; a sampled P
controller on a mass-spring-damper follows the exact discretization (matrix exponential);
UnitDelay makes the difference equation x[k+1] = a x[k] + b u[k]; MSL's LogicalNetwork1
(tables, Not, And, Or, Pre in a loop) against its reference and a hand evaluation.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

import acausal
from acausal import Model, ParameterError, PortConnectionError, StructureError
from acausal.components import discrete as dc
from acausal.components import logical as lg
from acausal.components import signals as sg
from acausal.models.event_blocks import SampledPController, Thermostat
from forced_oscillator import oscillator_system
from lti import held_input_flow

SIM = dict(rtol=1e-10, atol=1e-12)
TIGHT = dict(rtol=1e-12, atol=1e-14)          # integrated plants: event times to 1e-9 s


def _wire(m: Model, pairs) -> Model:
    for a, b in pairs:
        m.connect(a, b)
    return m


def _switch_times(res, component: str) -> list[float]:
    """Times after the start of the events of ``component`` where a mode changed."""
    return [ev.time for ev in res.events
            if ev.component == component and ev.modes and ev.time > res.t[0]]


def _right_limits(res, times, tol=1e-9) -> np.ndarray:
    """Column indices of the right limits at ``times`` (the last column within ``tol``)."""
    at = np.array([np.flatnonzero(np.abs(res.t - tk) <= tol)[-1] for tk in times])
    return at


def _roots(g, t_end, n=4001):
    """Times in (0, t_end) where g changes sign (brentq on a fine grid)."""
    s = np.linspace(0.0, t_end, n)
    v = np.array([g(x) for x in s])
    return [brentq(g, a, b, xtol=1e-15) for a, b, va, vb in
            zip(s[:-1], s[1:], v[:-1], v[1:]) if va * vb < 0]


# ---- relations -------------------------------------------------------------------------------
A, F_HZ, PHASE, THRESHOLD = 1.5, 0.8, 0.4, 0.6
W = 2 * np.pi * F_HZ
T_REL = 3.0
GRID = np.linspace(0.0, T_REL, 301)


def _sine(t):
    return A * np.sin(W * t + PHASE)


def _sine_crossings(level, t_end):
    """The closed form: A sin(W t + PHASE) = level at W t + PHASE = asin(level/A) + 2πk and
    π − asin(level/A) + 2πk."""
    a = np.arcsin(level / A)
    k = np.arange(-1, int(W * t_end / (2 * np.pi)) + 2)
    t = np.concatenate([(a + 2 * np.pi * k - PHASE) / W, (np.pi - a + 2 * np.pi * k - PHASE) / W])
    return np.sort(t[(t > 0) & (t < t_end)])


@pytest.mark.parametrize("kind, law", [
    ("GreaterThreshold", lambda u: u > THRESHOLD),
    ("GreaterEqualThreshold", lambda u: u >= THRESHOLD),
    ("LessThreshold", lambda u: u < THRESHOLD),
    ("LessEqualThreshold", lambda u: u <= THRESHOLD),
    ("RealToBoolean", lambda u: u >= THRESHOLD)])
def test_a_sine_into_a_threshold_switches_at_the_arcsin_solutions(kind, law):
    m = Model("threshold")
    m.src = sg.Sine(amplitude=A, f=F_HZ, phase=PHASE)
    m.blk = getattr(lg, kind)(threshold=THRESHOLD)
    res = acausal.compile(_wire(m, [(m.src.y, m.blk.u)])).simulate(T_REL, t=GRID, **SIM)
    expected = _sine_crossings(THRESHOLD, T_REL)
    assert len(expected) == 6
    np.testing.assert_allclose(_switch_times(res, "blk"), expected, rtol=0, atol=1e-9)
    on_grid = np.isin(res.t, GRID)
    np.testing.assert_array_equal(res["blk.y"][on_grid], law(_sine(GRID)).astype(float))
    at = _right_limits(res, expected)                  # the new value from the crossing on
    np.testing.assert_array_equal(res["blk.y"][at], law(_sine(expected + 1e-6)))


@pytest.mark.parametrize("kind, law", [
    ("Greater", np.greater), ("GreaterEqual", np.greater_equal),
    ("Less", np.less), ("LessEqual", np.less_equal)])
def test_two_signals_compared_switch_where_they_cross(kind, law):
    """u1 a sine, u2 a ramp 0.6 t − 0.9: crossings by brentq."""
    m = Model("compare")
    m.s1 = sg.Sine(amplitude=A, f=F_HZ, phase=PHASE)
    m.s2 = sg.Ramp(height=6.0, duration=10.0, offset=-0.9)
    m.blk = getattr(lg, kind)()
    res = acausal.compile(_wire(m, [(m.s1.y, m.blk.u1), (m.s2.y, m.blk.u2)])).simulate(
        T_REL, t=GRID, **SIM)
    ramp = lambda t: 0.6 * t - 0.9                                      # noqa: E731
    expected = _roots(lambda t: _sine(t) - ramp(t), T_REL)
    assert len(expected) == 5
    np.testing.assert_allclose(_switch_times(res, "blk"), expected, rtol=0, atol=1e-9)
    on_grid = np.isin(res.t, GRID)
    np.testing.assert_array_equal(res["blk.y"][on_grid], law(_sine(GRID), ramp(GRID)))


def test_switch_selects_between_two_signals():
    """y = if sin > 0.6 then cos else 0.25, the Boolean from a relation."""
    m = Model("switch")
    m.src = sg.Sine(amplitude=A, f=F_HZ, phase=PHASE)
    m.cos = sg.Cosine(amplitude=2.0, f=0.3)
    m.low = sg.Constant(k=0.25)
    m.gt, m.sw = lg.GreaterThreshold(threshold=THRESHOLD), lg.Switch()
    res = acausal.compile(_wire(m, [(m.src.y, m.gt.u), (m.gt.y, m.sw.u2), (m.cos.y, m.sw.u1),
                                    (m.low.y, m.sw.u3)])).simulate(T_REL, t=GRID, **SIM)
    on_grid = np.isin(res.t, GRID)
    np.testing.assert_allclose(res["sw.y"][on_grid], np.where(
        _sine(GRID) > THRESHOLD, 2.0 * np.cos(2 * np.pi * 0.3 * GRID), 0.25), rtol=0,
        atol=1e-13)


@pytest.mark.parametrize("pre_y_start", [False, True])
def test_hysteresis_on_a_sine_switches_at_uhigh_rising_and_ulow_falling(pre_y_start):
    """u = sin(π t): y becomes true where u rises through uHigh = 0.6 (π t = asin 0.6 +
    2πk), false where it falls through uLow = −0.3 (π t = π + asin 0.3 + 2πk); started true,
    y holds until the first fall through uLow."""
    m = Model("hysteresis")
    m.src = sg.Sine(f=0.5)
    m.hyst = lg.Hysteresis(uLow=-0.3, uHigh=0.6, pre_y_start=pre_y_start)
    t = np.linspace(0.0, 5.0, 501)
    res = acausal.compile(_wire(m, [(m.src.y, m.hyst.u)])).simulate(5.0, t=t, **SIM)
    rise = np.arcsin(0.6) / np.pi + 2 * np.arange(3)
    fall = (np.pi + np.arcsin(0.3)) / np.pi + 2 * np.arange(3)
    rise, fall = rise[rise < 5.0], fall[fall < 5.0]
    expected = np.sort(np.concatenate([fall, rise if not pre_y_start else rise[1:]]))
    np.testing.assert_allclose(_switch_times(res, "hyst"), expected, rtol=0, atol=1e-9)
    phase = np.mod(t, 2.0)
    y = (phase >= rise[0]) & (phase < fall[0])
    if pre_y_start:
        y |= t < fall[0]
    np.testing.assert_array_equal(res["hyst.y"][np.isin(res.t, t)], y)


def test_hysteresis_limits_are_checked():
    with pytest.raises(ParameterError, match="uHigh"):
        lg.Hysteresis(uLow=1.0, uHigh=0.5)
    with pytest.raises(ParameterError, match="uLow"):
        lg.Hysteresis(uHigh=0.5)


# ---- bang-bang on a first-order plant --------------------------------------------------------
TAU, POWER, LOWER, UPPER = 2.0, 10.0, 4.0, 6.0


def _bang_bang_times(t_end: float) -> np.ndarray:
    """A first-order plant τ y' = P·on − y from 0, heated (on) until y = UPPER, cooled
    until y = LOWER, and so on: the switching times before t_end are logarithms."""
    heat_first = -TAU * np.log(1 - UPPER / POWER)
    cool = TAU * np.log(UPPER / LOWER)
    heat = TAU * np.log((POWER - LOWER) / (POWER - UPPER))
    out = [heat_first]
    while out[-1] + cool < t_end:
        out.append(out[-1] + (cool if len(out) % 2 else heat))
    return np.array(out[:-1] if out[-1] >= t_end else out)


@pytest.mark.parametrize("kind", ["OnOffController", "Hysteresis"])
def test_bang_bang_of_a_first_order_plant_switches_at_the_closed_form_times(kind):
    model = Thermostat(kind=kind, tau=TAU, power=POWER, lower=LOWER, upper=UPPER)
    res = acausal.compile(model).simulate(12.0, **TIGHT)
    expected = _bang_bang_times(12.0)
    assert len(expected) == 13
    np.testing.assert_allclose(_switch_times(res, "ctrl"), expected, rtol=0, atol=1e-9)
    at = _right_limits(res, expected)
    np.testing.assert_allclose(res["plant.y"][at], [UPPER, LOWER] * 6 + [UPPER], rtol=0,
                               atol=1e-8)


# ---- logical blocks and Boolean sources ---------------------------------------------------------
def test_logical_blocks_follow_their_truth_tables():
    """Pulses (period 1 s and 0.7 s, from 0.1 s) and a step into every logical block."""
    m = Model("logic")
    m.a = lg.BooleanPulse(width=50.0, period=1.0, startTime=0.1)
    m.b = lg.BooleanPulse(width=30.0, period=0.7)
    m.c = lg.BooleanStep(startTime=1.55, startValue=True)
    m.k = lg.BooleanConstant(k=False)
    pairs = []
    for name in ("And", "Or", "Xor", "Nand", "Nor"):
        setattr(m, name.lower(), getattr(lg, name)())
        blk = getattr(m, name.lower())
        pairs += [(m.a.y, blk.u1), (m.b.y, blk.u2)]
    m.no, m.ls, m.real = lg.Not(), lg.LogicalSwitch(), lg.BooleanToReal(realTrue=2.5,
                                                                        realFalse=-1.0)
    pairs += [(m.c.y, m.no.u), (m.a.y, m.ls.u1), (m.c.y, m.ls.u2), (m.k.y, m.ls.u3),
              (m.b.y, m.real.u)]
    t = np.linspace(0.0, 3.0, 301) + 0.0005          # off the sources' edges
    res = acausal.compile(_wire(m, pairs)).simulate(t[-1], t=t)
    a = (t >= 0.1) & (np.mod(t - 0.1, 1.0) < 0.5)
    b = np.mod(t, 0.7) < 0.21
    c = t < 1.55
    truth = {"and": a & b, "or": a | b, "xor": a ^ b, "nand": ~(a & b), "nor": ~(a | b),
             "no": ~c, "ls": np.where(c, a, False), "a": a, "b": b, "c": c,
             "k": np.zeros_like(a)}
    for name, expected in truth.items():
        np.testing.assert_array_equal(res[f"{name}.y"], expected, err_msg=name)
    np.testing.assert_array_equal(res["real.y"], np.where(b, 2.5, -1.0))


def _logical_network1() -> Model:
    """MSL Blocks.Examples.LogicalNetwork1: Pre1.u = table1 or (not table2 and pre(Pre1.u))."""
    m = Model("LogicalNetwork1")
    m.table2 = lg.BooleanTable(table=[1, 3, 5, 7])
    m.table1 = lg.BooleanTable(table=[2, 4, 6, 8])
    m.Not1, m.And1, m.Or1, m.Pre1 = lg.Not(), lg.And(), lg.Or(), lg.Pre()
    return _wire(m, [(m.table2.y, m.Not1.u), (m.And1.y, m.Or1.u2), (m.table1.y, m.Or1.u1),
                     (m.Not1.y, m.And1.u1), (m.Pre1.y, m.And1.u2), (m.Or1.y, m.Pre1.u)])


def _flip_flop(t):
    """LogicalNetwork1 by hand: the tables toggle at their times; the loop through Pre
    holds its value while table2 is false."""
    t1 = np.searchsorted([2, 4, 6, 8], t, side="right") % 2 == 1
    t2 = np.searchsorted([1, 3, 5, 7], t, side="right") % 2 == 1
    out, held = [], False
    for a, b in zip(t1, t2):
        held = a or (not b and held)
        out.append(held)
    return np.array(out), t1, t2


def test_logical_network_with_pre_in_a_loop_against_a_hand_evaluation():
    t = np.linspace(0.0, 10.0, 201) + 0.01
    res = acausal.compile(_logical_network1()).simulate(t[-1], t=t)
    expected, t1, t2 = _flip_flop(t)
    on_grid = np.isin(res.t, t)
    np.testing.assert_array_equal(res["Pre1.u"][on_grid], expected)
    np.testing.assert_array_equal(res["table1.y"][on_grid], t1)
    np.testing.assert_array_equal(res["table2.y"][on_grid], t2)
    assert _switch_times(res, "Pre1") == [2.0, 5.0, 6.0]


def test_logical_network1_matches_the_msl_reference(reference_result):
    ref = reference_result("MAP-LIB_ReferenceResults",
                           "Modelica.Blocks.Examples.LogicalNetwork1")
    t = ref["time"]
    res = acausal.compile(_logical_network1()).simulate(float(t[-1]), t=t)
    at = _right_limits(res, t)
    for name in ("Pre1.u", "table1.y", "table2.y"):
        np.testing.assert_array_equal(res[name][at], ref[name], err_msg=name)


def test_boolean_expression_is_the_value_given():
    """MSL's default false; y=True is true: a switch selects u1 (a sine) by it."""
    m = Model("boolean_expression")
    m.off, m.on = lg.BooleanExpression(), lg.BooleanExpression(y=True)
    m.a, m.b = sg.Sine(amplitude=1.5), sg.Constant(k=-2.0)
    m.switch = lg.Switch()
    for a, b in ((m.a.y, m.switch.u1), (m.on.y, m.switch.u2), (m.b.y, m.switch.u3)):
        m.connect(a, b)
    res = acausal.compile(m).simulate(1.0, **SIM)
    assert np.all(res["off.y"] == 0) and np.all(res["on.y"] == 1)
    np.testing.assert_allclose(res["switch.y"], 1.5 * np.sin(2 * np.pi * res.t), atol=1e-12)


@pytest.mark.parametrize("y", [1, "pulse.y and step.y", None])
def test_boolean_expression_takes_true_or_false(y):
    with pytest.raises(ParameterError, match="BooleanExpression: y must be True or False.*And"):
        lg.BooleanExpression(y=y)


def test_a_boolean_signal_cannot_drive_a_real_input():
    m = Model("mixed")
    m.step, m.gain, m.sine, m.no = lg.BooleanStep(), sg.Gain(), sg.Sine(), lg.Not()
    with pytest.raises(PortConnectionError, match=r"step\.y.*Boolean signal.*gain\.u"):
        m.connect(m.step.y, m.gain.u)
    with pytest.raises(PortConnectionError, match=r"sine\.y.*no\.u.*BooleanToReal"):
        m.connect(m.sine.y, m.no.u)


# ---- sampled data ----------------------------------------------------------------------------
def test_zero_order_hold_of_a_ramp_is_an_exact_staircase():
    """Ramp 0.5 + 0.2 t: ZeroOrderHold (T = 0.25 s from 0.105 s) holds ramp(t_k) from each
    instant t_k to the next, 0 before the first; a Sampler from 0 samples at the start."""
    m = Model("hold")
    m.ramp = sg.Ramp(height=2.0, duration=10.0, offset=0.5)
    m.zoh = dc.ZeroOrderHold(samplePeriod=0.25, startTime=0.105)
    m.smp = dc.Sampler(samplePeriod=0.3)
    t = np.linspace(0.0, 3.0, 301)
    res = acausal.compile(_wire(m, [(m.ramp.y, m.zoh.u), (m.ramp.y, m.smp.u)])).simulate(
        3.0, t=t, **SIM)
    ramp = lambda s: 0.5 + 0.2 * s                                      # noqa: E731
    tk = 0.105 + 0.25 * np.arange(12)
    held = np.where(t < 0.105, 0.0, ramp(0.105 + 0.25 * np.floor((t - 0.105) / 0.25)))
    on_grid = _right_limits(res, t, tol=0.0)       # the Sampler's instants are on the grid
    np.testing.assert_allclose(res["zoh.y"][on_grid], held, rtol=0, atol=1e-14)
    at = _right_limits(res, tk)
    np.testing.assert_allclose(res["zoh.y"][at], ramp(tk), rtol=0, atol=1e-14)
    np.testing.assert_allclose(res["zoh.y"][at[1:] - 1], ramp(tk[:-1]), rtol=0, atol=1e-14)
    np.testing.assert_allclose(res["zoh.ySample"], res["zoh.y"], rtol=0, atol=0)
    ts = 0.3 * np.floor(t / 0.3 + 1e-9)            # the instant at the final time included
    np.testing.assert_allclose(res["smp.y"][on_grid], ramp(ts), rtol=0, atol=1e-14)
    assert res["smp.y"][0] == 0.5                      # sampled at the start (initial())
    assert np.all(res["zoh.sampleTrigger"] == 0)


def test_two_sample_rates_tick_together_at_common_instants():
    """Sampler every 0.1 s into a ZeroOrderHold every 0.3 s: at 0.3·k (3·0.1 s in floating
    point differs from 0.3 s) both sample at one instant, so the hold takes ramp(0.3 k)."""
    m = Model("two_rates")
    m.ramp = sg.Ramp(height=1.0, duration=10.0)
    m.fast, m.slow = dc.Sampler(samplePeriod=0.1), dc.ZeroOrderHold(samplePeriod=0.3)
    res = acausal.compile(_wire(m, [(m.ramp.y, m.fast.u), (m.fast.y, m.slow.u)])).simulate(
        2.0, **SIM)
    tk = 0.3 * np.arange(7)
    np.testing.assert_allclose(res["slow.y"][_right_limits(res, tk, tol=1e-12)], 0.1 * tk,
                               rtol=0, atol=1e-14)
    slow = [ev.time for ev in res.events if "slow" in ev.component]
    assert len(slow) == 6 and all("fast" in ev.component for ev in res.events if ev.time > 0
                                  and "slow" in ev.component)


M, C, D, K, R, TS = 1.0, 4.0, 0.5, 12.0, 1.0, 0.1


def _discrete_loop(n: int) -> tuple[np.ndarray, np.ndarray]:
    """The sampled P loop written by hand: on [t_k, t_k+1) the force F_k = K (R − x_k)
    is constant, so [x, v] steps by the exact discretization of m x'' + d x' + c x = F
    (matrix exponential of the augmented system)."""
    Ad, Bd = held_input_flow(*oscillator_system(M, C, D), TS)
    s, xs, fs = np.array([0.2, 0.0]), [], []
    for _ in range(n):
        f = K * (R - s[0])
        xs.append(s[0])
        fs.append(f)
        s = Ad @ s + Bd * f
    return np.array(xs), np.array(fs)


def test_sampled_p_controller_on_a_mass_matches_the_exact_discretization():
    m = SampledPController(m=M, c=C, d=D, K=K, reference=R, samplePeriod=TS)
    res = acausal.compile(m).simulate(2.05, x0={"mass.s": 0.2}, **TIGHT)
    xs, fs = _discrete_loop(21)
    tk = TS * np.arange(21)
    at = _right_limits(res, tk)
    np.testing.assert_allclose(res["mass.s"][at], xs, rtol=0, atol=1e-9)
    np.testing.assert_allclose(res["smp.y"][at], xs, rtol=0, atol=1e-9)
    np.testing.assert_allclose(res["zoh.ySample"][at], fs, rtol=0, atol=1e-8)
    assert sorted({ev.time for ev in res.events}) == pytest.approx(tk, abs=1e-12)


def test_unit_delay_makes_a_difference_equation():
    """x[k] = UnitDelay(a x + b s), s the Sampler of u = sin(t) at the same instants:
    x[k] = a x[k−1] + b u(t[k−1]), x[0] = y_start (kept at the start, MSL's initialization)."""
    a, b, ts = 0.8, 0.5, 0.2
    m = Model("difference")
    m.u = sg.Sine(f=1 / (2 * np.pi))
    m.smp = dc.Sampler(samplePeriod=ts)
    m.delay = dc.UnitDelay(samplePeriod=ts, y_start=1.5)
    m.add = sg.Add(k1=a, k2=b)
    res = acausal.compile(_wire(m, [(m.u.y, m.smp.u), (m.delay.y, m.add.u1),
                                    (m.smp.y, m.add.u2), (m.add.y, m.delay.u)])).simulate(
        3.05, **SIM)
    tk = ts * np.arange(16)
    x = [1.5]
    for k in range(1, 16):
        x.append(a * x[-1] + b * np.sin(tk[k - 1]))
    at = _right_limits(res, tk)
    np.testing.assert_allclose(res["delay.y"][at], x, rtol=0, atol=1e-14)
    assert np.all(res["delay.sampled"] == 0)


# ---- smooth form -------------------------------------------------------------------------------
@pytest.mark.parametrize("make", [lambda: lg.GreaterThreshold(), lambda: dc.Sampler(
    samplePeriod=0.1), lambda: lg.Hysteresis(uLow=0.0, uHigh=1.0), sg.Harmonic,
    sg.TotalHarmonicDistortion])
def test_blocks_with_discrete_outputs_refuse_the_smooth_form(make):
    m = Model("no_smooth")
    m.src, m.blk = sg.Sine(), make()
    m.connect(m.src.y, m.blk.u)
    with pytest.raises(StructureError, match=rf"{type(m.blk).__name__} 'blk'.*smooth"):
        acausal.compile(m, smooth=True)


@pytest.mark.parametrize("kind, law", [
    ("Limiter", lambda u: np.clip(u, -1.0, 1.0)),
    ("DeadZone", lambda u: u - np.clip(u, -1.0, 1.0))])
def test_smooth_limiter_and_dead_zone_are_within_half_the_smoothing_width(kind, law):
    """compile(smooth=True): no events, and |y − y_exact| ≤ u_smooth/2, the bound reached
    at the limits (sin(t)·1.5 = ±1 at asin(2/3))."""
    m = Model("smooth")
    m.src, m.blk = sg.Sine(amplitude=1.5, f=1 / (2 * np.pi)), getattr(sg, kind)(uMax=1.0)
    m.connect(m.src.y, m.blk.u)
    c = acausal.compile(m, smooth=True)
    assert not c.has_events
    kink = np.arcsin(1 / 1.5)
    t = np.sort(np.concatenate([np.linspace(0.0, 6.0, 601), [kink, np.pi - kink]]))
    res = c.simulate(6.0, t=t, params={"blk.u_smooth": 0.05})
    error = np.abs(res["blk.y"] - law(1.5 * np.sin(t)))
    assert error.max() <= 0.025 + 1e-12
    assert error[np.isin(t, [kink])][0] == pytest.approx(0.025, rel=1e-2)
    exact = acausal.compile(m)
    assert exact.has_events and [v.name for v in exact.modes] == ["blk.region"]


def test_zero_order_hold_breaks_an_algebraic_loop():
    """u = r − 0.5·y through the hold, no state in between: MSL's y = pre(ySample) makes it
    the difference equation y_k+1 = r − 0.5·y_k (y = r after the start, where ySample
    takes u with y = pre(ySample) = 0): y_k = r·(1 − (−0.5)^(k+1))/1.5; its integral is
    0.1·Σ y_k."""
    m = Model("zoh_loop")
    m.r, m.fb, m.g = sg.Constant(k=2.0), sg.Feedback(), sg.Gain(k=0.5)
    m.zoh, m.integ = dc.ZeroOrderHold(samplePeriod=0.1), sg.Integrator()
    _wire(m, [(m.r.y, m.fb.u1), (m.g.y, m.fb.u2), (m.fb.y, m.zoh.u), (m.zoh.y, m.g.u),
              (m.zoh.y, m.integ.u)])
    t = np.round(np.linspace(0.0, 1.05, 22), 12)
    res = acausal.compile(m).simulate(1.05, t=t, **SIM)
    k = np.floor(t / 0.1 + 1e-9)
    y_ref = 2.0 * (1 - (-0.5) ** (k + 1)) / 1.5
    at = _right_limits(res, t)
    np.testing.assert_allclose(res["zoh.y"][at], y_ref, atol=1e-12)
    steps = 2.0 * (1 - (-0.5) ** (np.arange(11) + 1)) / 1.5
    assert res["integ.y"][-1] == pytest.approx(0.1 * steps[:10].sum() + 0.05 * steps[10],
                                               abs=1e-9)
