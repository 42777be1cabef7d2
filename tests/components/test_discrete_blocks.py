"""FirstOrderHold, TransferFunction, StateSpace, TriggeredSampler and TriggeredMax
(acausal.components.discrete) against difference equations written by hand in numpy, scipy's
lfilter and dlsim, and closed forms of the sampled input.

The input is a sine, known in closed form, so its samples u(t_k) are exact; the sample
instants t_k = startTime + k·samplePeriod after the start (the start is initialization, where
MSL's ``when sampleTrigger`` is inactive). Every value is compared at the right limits of the
instants and on a grid between them (held values, or FirstOrderHold's line).
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy import signal

import acausal
from acausal import Model, ParameterError, SimulationError, StructureError
from acausal.components import discrete as dc
from acausal.components import logical as lg
from acausal.components import signals as sg

SIM = dict(rtol=1e-10, atol=1e-12)
TIGHT = dict(rtol=1e-12, atol=1e-14)          # an integrated plant: its samples to 1e-9
AMP, F_HZ, OFFSET = 1.3, 0.7, 0.3


def u_of(t):
    """The input: OFFSET + AMP·sin(2π F_HZ t)."""
    return OFFSET + AMP * np.sin(2 * np.pi * F_HZ * np.asarray(t, dtype=float))


def _driven(name: str, **blocks) -> Model:
    """``blocks`` (name → block with input u, or u[1]) fed by the sine."""
    m = Model(name)
    m.src = sg.Sine(amplitude=AMP, f=F_HZ, offset=OFFSET)
    for n, b in blocks.items():
        setattr(m, n, b)
        m.connect(m.src.y, b.u[1] if isinstance(b, dc.StateSpace) else b.u)
    return m


def _right_limits(res, times, tol=1e-9) -> np.ndarray:
    """Column indices of the values after the events at ``times`` (the last column there)."""
    return np.array([np.flatnonzero(np.abs(res.t - tk) <= tol)[-1] for tk in times])


def _instants(start, period, t_end, t0=0.0) -> np.ndarray:
    """The sample instants in (t0, t_end] (one at t_end is processed there, as a Modelica
    tool ends a simulation)."""
    k = np.arange(0, int((t_end - start) / period) + 2)
    tk = start + period * k
    return tk[(tk > t0 + 1e-12) & (tk < t_end + 1e-12)]


def _held(t, tk, values, before):
    """The piecewise constant signal: values[i] on [tk[i], tk[i+1]), ``before`` before tk[0]."""
    i = np.searchsorted(tk, np.asarray(t) + 1e-12, side="right") - 1
    return np.where(i < 0, before, np.asarray(values)[np.maximum(i, 0)])


# ---- FirstOrderHold --------------------------------------------------------------------------
@pytest.mark.parametrize("start", [0.0, 0.13])
def test_first_order_hold_extrapolates_through_the_last_two_samples(start):
    """MSL's y = pre_uSample + c·(time − tSample): on [t_k, t_k+1) the line from u(t_k−1) at
    t_k with slope (u(t_k) − u(t_k−1))/T (so it reaches u(t_k) at t_k+1); at the first
    instant (startTime, if after the start) c = 0; before it, and before the second,
    u(0), the initial equations' sample."""
    T, t_end = 0.1, 1.25
    res = acausal.compile(_driven("foh", foh=dc.FirstOrderHold(samplePeriod=T,
                                                              startTime=start))).simulate(
        t_end, t=np.linspace(0.0, t_end, 251), **SIM)
    tk = _instants(start, T, t_end)
    samples = np.concatenate([[u_of(0.0)], u_of(tk)])        # uSample after each instant
    prev, cur = samples[:-1], samples[1:]                     # pre_uSample, uSample at t_k
    slope = np.where(np.isclose(tk, start), 0.0, (cur - prev) / T)
    t = np.round(res.t, 12)
    k = np.searchsorted(tk, t + 1e-12, side="right") - 1
    # after each instant's event; a column at an instant before its event is the left limit
    after = np.ones(len(t), dtype=bool)
    for tj in tk:
        cols = np.flatnonzero(np.abs(t - tj) <= 1e-9)
        after[cols[:-1]] = False
    k = np.where(after, k, k - 1)
    expected = np.where(k < 0, u_of(0.0), prev[np.maximum(k, 0)]
                        + slope[np.maximum(k, 0)] * (t - tk[np.maximum(k, 0)]))
    np.testing.assert_allclose(res["foh.y"], expected, rtol=0, atol=1e-12)
    at = _right_limits(res, tk)
    np.testing.assert_allclose(res["foh.uSample"][at], cur, rtol=0, atol=1e-14)
    np.testing.assert_allclose(res["foh.pre_uSample"][at], prev, rtol=0, atol=1e-14)
    np.testing.assert_allclose(res["foh.tSample"][at], tk, rtol=0, atol=1e-12)
    assert np.all(res["foh.sampled"] == 0) and np.all(res["foh.initialTrigger"] == 0)


def test_first_order_hold_starts_from_a_sample_settled_at_the_start():
    """A Sampler (samples at the start: when {sampleTrigger, initial()}) into a
    FirstOrderHold, the simulation started at t0 = 0.35 s: the hold's initial equations
    take the sampled u(t0), not the Sampler's start value 0; its first instant (0.4 s)
    then extrapolates from u(t0) to the sample u(0.4) (the first instant of the hold,
    startTime 0, was before the start: c ≠ 0)."""
    m = Model("foh_chain")
    m.src = sg.Sine(amplitude=AMP, f=F_HZ, offset=OFFSET)
    m.smp, m.foh = dc.Sampler(samplePeriod=0.1), dc.FirstOrderHold(samplePeriod=0.1)
    m.connect(m.src.y, m.smp.u)
    m.connect(m.smp.y, m.foh.u)
    t = np.linspace(0.35, 0.6, 26)
    res = acausal.compile(m).simulate(0.6, t=t, **SIM)
    u0, u4, u5 = u_of([0.35, 0.4, 0.5])
    assert res["foh.y"][0] == pytest.approx(u0, abs=1e-14)
    assert res["foh.uSample"][0] == pytest.approx(u0, abs=1e-14)
    on = (res.t > 0.4 + 1e-9) & (res.t < 0.5 - 1e-9)
    np.testing.assert_allclose(res["foh.y"][on], u0 + (u4 - u0) / 0.1 * (res.t[on] - 0.4),
                               rtol=0, atol=1e-12)
    at = _right_limits(res, [0.5])
    assert res["foh.y"][at][0] == pytest.approx(u4, abs=1e-14)
    assert res["foh.c"][at][0] == pytest.approx((u5 - u4) / 0.1, abs=1e-11)


# ---- TransferFunction ------------------------------------------------------------------------
def _tf_recursion(b, a, u, x_start=None):
    """MSL's controller canonical form by hand: x1 = (u − a[2:]·x)/a[1], y = bb·[x1; x],
    x ← [x1; x][:nx]; y after each sample."""
    na, nb = len(a), len(b)
    bb = np.concatenate([np.zeros(na - nb), b])
    x = np.zeros(na - 1) if x_start is None else np.array(x_start, dtype=float)
    ys, xs = [], []
    for uk in u:
        x1 = (uk - np.dot(a[1:], x)) / a[0]
        xext = np.concatenate([[x1], x])
        ys.append(np.dot(bb, xext))
        x = xext[:-1]
        xs.append(x.copy())
    return np.array(ys), np.array(xs)


@pytest.mark.parametrize("b, a", [([0.5, 0.2], [1.0, -0.6, 0.1]),       # no feedthrough
                                  ([2.0, 0.4, -0.3], [1.5, -0.9, 0.2]),   # nb = na, a[1] ≠ 1
                                  ([0.7], [1.0])])                        # a gain, nx = 0
def test_transfer_function_is_its_difference_equation(b, a):
    """y[k] against the recursion y[k] = (Σ bb[i] u[k−i] − Σ_{i≥1} a[i] y[k−i])/a[1] (scipy's
    lfilter, zero initial state; bb: b padded with leading zeros to na), u[k] the sine at the
    instants 0.05 + 0.1·k, held between; 0 before the first."""
    T, start, t_end = 0.1, 0.05, 2.02
    res = acausal.compile(_driven("tf", tf=dc.TransferFunction(
        b=b, a=a, samplePeriod=T, startTime=start))).simulate(
        t_end, t=np.linspace(0.0, t_end, 203), **SIM)
    tk = _instants(start, T, t_end)
    bb = np.concatenate([np.zeros(len(a) - len(b)), b])
    y = signal.lfilter(bb, a, u_of(tk))
    np.testing.assert_allclose(res["tf.y"][_right_limits(res, tk)], y, rtol=0, atol=1e-12)
    grid = np.linspace(0.0, t_end, 203)
    np.testing.assert_allclose(res["tf.y"][_right_limits(res, grid)], _held(grid, tk, y, 0.0),
                               rtol=0, atol=1e-12)
    _, xs = _tf_recursion(np.array(b), np.array(a), u_of(tk))
    for i in range(len(a) - 1):
        np.testing.assert_allclose(res[f"tf.x[{i + 1}]"][_right_limits(res, tk)], xs[:, i],
                                   rtol=0, atol=1e-12)


def test_transfer_function_starts_from_x_start():
    """x_start (MSL's x(start=...)) as the state before the first instant: the hand
    recursion from it; y = 0 until the first instant."""
    b, a, x0, T = [1.0, -0.5], [1.0, 0.3, -0.2], [0.4, -1.1], 0.2
    res = acausal.compile(_driven("tf", tf=dc.TransferFunction(
        b=b, a=a, samplePeriod=T, x_start=x0))).simulate(1.9, **SIM)
    tk = _instants(0.0, T, 1.9)
    y, _ = _tf_recursion(np.array(b), np.array(a), u_of(tk), x0)
    np.testing.assert_allclose(res["tf.y"][_right_limits(res, tk)], y, rtol=0, atol=1e-12)
    assert res["tf.y"][0] == 0.0 and res["tf.x[1]"][0] == 0.4 and res["tf.x[2]"][0] == -1.1


def test_transfer_function_in_a_loop_with_a_sampled_plant_input():
    """A discrete integrator controller C(z) = 0.4 z/(z − 1) (feedthrough) closing a loop
    through a ZeroOrderHold onto a first order plant y' = −y + v: MSL's event iteration
    settles the error sampled at the instant; against the exact discretization of the plant
    (e^−T, 1 − e^−T) and the controller's recursion c[k] = c[k−1] + 0.4 e[k]."""
    T, r = 0.25, 1.0
    m = Model("pi_loop")
    m.ref, m.fb = sg.Constant(k=r), sg.Feedback()
    m.ctrl = dc.TransferFunction(b=[0.4, 0.0], a=[1.0, -1.0], samplePeriod=T)
    m.zoh, m.plant = dc.ZeroOrderHold(samplePeriod=T), sg.FirstOrder(k=1.0, T=1.0)
    for p, q in [(m.ref.y, m.fb.u1), (m.plant.y, m.fb.u2), (m.fb.y, m.ctrl.u),
                 (m.ctrl.y, m.zoh.u), (m.zoh.y, m.plant.u)]:
        m.connect(p, q)
    res = acausal.compile(m).simulate(3.1, **TIGHT)
    tk = _instants(0.0, T, 3.1)
    ad, bd = np.exp(-T), 1 - np.exp(-T)
    y, c, held, ys, cs = 0.0, 0.0, 0.0, [], []
    for _ in tk:
        y = ad * y + bd * held          # the plant over the last period
        c = c + 0.4 * (r - y)           # the controller at the instant
        held = c                        # the hold takes it (its y = pre(ySample))
        ys.append(y)
        cs.append(c)
    at = _right_limits(res, tk)
    np.testing.assert_allclose(res["plant.y"][at], ys, rtol=0, atol=1e-9)
    np.testing.assert_allclose(res["ctrl.y"][at], cs, rtol=0, atol=1e-9)


# ---- StateSpace ------------------------------------------------------------------------------
A = np.array([[0.5, 0.1, 0.0], [-0.2, 0.8, 0.3], [0.0, -0.1, 0.6]])
B = np.array([[1.0, 0.0], [0.5, -0.4], [0.0, 0.2]])
C = np.array([[1.0, -1.0, 0.5], [0.0, 0.3, 1.0]])
D = np.array([[0.3, 0.0], [0.1, -0.2]])


def test_state_space_is_dlsim_with_pre_x():
    """MSL's x = A·pre(x) + B·u, y = C·pre(x) + D·u at each instant: scipy's dlsim
    (y[k] = C x[k] + D u[k], x[k+1] = A x[k] + B u[k], x[0] = x_start) on u[k] at the
    instants; two inputs (the sine and a ramp), two outputs, three states."""
    T, t_end, x0 = 0.1, 1.55, [0.2, -0.4, 1.0]
    m = Model("ss")
    m.src = sg.Sine(amplitude=AMP, f=F_HZ, offset=OFFSET)
    m.ramp = sg.Ramp(height=2.0, duration=2.0)
    m.ss = dc.StateSpace(A=A, B=B, C=C, D=D, samplePeriod=T, x_start=x0)
    m.connect(m.src.y, m.ss.u[1])
    m.connect(m.ramp.y, m.ss.u[2])
    res = acausal.compile(m).simulate(t_end, **SIM)
    tk = _instants(0.0, T, t_end)
    u = np.column_stack([u_of(tk), tk])
    _, y, x = signal.dlsim((A, B, C, D, T), u, t=np.arange(len(tk)) * T, x0=x0)
    at = _right_limits(res, tk)
    for i in range(2):
        np.testing.assert_allclose(res[f"ss.y[{i + 1}]"][at], y[:, i], rtol=0, atol=1e-12)
        assert res[f"ss.y[{i + 1}]"][0] == 0.0
    x_after = np.vstack([x[1:], A @ x[-1] + B @ u[-1]])
    for i in range(3):
        np.testing.assert_allclose(res[f"ss.x[{i + 1}]"][at], x_after[:, i], rtol=0,
                                   atol=1e-12)
        assert res[f"ss.x[{i + 1}]"][0] == x0[i]


def test_state_space_defaults_are_msl_s():
    """MSL's A = [1, 0; 0, 1], B = [1; 1], C = [1, 1], D = 0: two summers of u, y = their
    sum before the instant: y[k] = 2·Σ_{j<k} u[j]."""
    res = acausal.compile(_driven("ss", ss=dc.StateSpace(samplePeriod=0.1))).simulate(
        1.05, **SIM)
    tk = _instants(0.0, 0.1, 1.05)
    y = 2 * np.concatenate([[0.0], np.cumsum(u_of(tk))[:-1]])
    np.testing.assert_allclose(res["ss.y[1]"][_right_limits(res, tk)], y, rtol=0, atol=1e-12)


# ---- triggered blocks ------------------------------------------------------------------------
def _pulse_edges(start, period, t_end):
    k = np.arange(0, int((t_end - start) / period) + 2)
    tk = start + period * k
    return tk[(tk > 1e-12) & (tk < t_end + 1e-12)]       # (an edge at t_end too)


@pytest.mark.parametrize("start", [0.0, 0.1])
def test_triggered_sampler_and_max_take_u_at_rising_edges(start):
    """A BooleanPulse (period 0.3 s, width 40 %, from ``start``) triggers both: y = u at
    each rising edge (y_start = 2 before the first), the running max of |u| at the edges
    (0 before); a trigger true at the start (start 0) is no edge, as MSL's when at
    initialization."""
    t_end = 2.5
    m = _driven("trig", ts=dc.TriggeredSampler(y_start=2.0), tm=dc.TriggeredMax())
    m.pulse = lg.BooleanPulse(width=40.0, period=0.3, startTime=start)
    m.connect(m.pulse.y, m.ts.trigger)
    m.connect(m.pulse.y, m.tm.trigger)
    t = np.linspace(0.0, t_end, 251)
    res = acausal.compile(m).simulate(t_end, t=t, **SIM)
    tk = _pulse_edges(start, 0.3, t_end)
    samples = u_of(tk)
    running = np.maximum.accumulate(np.abs(samples))
    at = _right_limits(res, tk)
    np.testing.assert_allclose(res["ts.y"][at], samples, rtol=0, atol=1e-14)
    np.testing.assert_allclose(res["tm.y"][at], running, rtol=0, atol=1e-14)
    on_grid = _right_limits(res, t)
    np.testing.assert_allclose(res["ts.y"][on_grid], _held(t, tk, samples, 2.0), atol=1e-14)
    np.testing.assert_allclose(res["tm.y"][on_grid], _held(t, tk, running, 0.0), atol=1e-14)


def test_triggered_blocks_take_a_value_sampled_at_the_same_instant():
    """Trigger: a SampleTrigger every 0.2 s from 0.2 s; u: a Sampler every 0.2 s of the
    sine: at each edge the blocks take the sample of that instant, settled in the event
    iteration (MSL's sorted when-equations), not the one before. The sine's |u| falls
    after its peaks, so the running max differs from max(|u| of any round)."""
    m = Model("same_instant")
    m.src = sg.Sine(amplitude=AMP, f=F_HZ, offset=OFFSET)
    m.smp = dc.Sampler(samplePeriod=0.2)
    m.trig = lg.SampleTrigger(period=0.2, startTime=0.2)
    m.ts, m.tm = dc.TriggeredSampler(), dc.TriggeredMax()
    for p, q in [(m.src.y, m.smp.u), (m.smp.y, m.ts.u), (m.smp.y, m.tm.u),
                 (m.trig.y, m.ts.trigger), (m.trig.y, m.tm.trigger)]:
        m.connect(p, q)
    res = acausal.compile(m).simulate(2.1, **SIM)
    tk = _instants(0.2, 0.2, 2.1)
    at = _right_limits(res, tk)
    np.testing.assert_allclose(res["ts.y"][at], u_of(tk), rtol=0, atol=1e-14)
    np.testing.assert_allclose(res["tm.y"][at], np.maximum.accumulate(np.abs(u_of(tk))),
                               rtol=0, atol=1e-14)


# ---- errors ----------------------------------------------------------------------------------
@pytest.mark.parametrize("make, message", [
    (lambda: dc.TransferFunction(b=[1, 2, 3], a=[1, 2], samplePeriod=0.1),
     r"TransferFunction: transfer function is not proper: b has 3 coefficients, a 2.*give b"),
    (lambda: dc.TransferFunction("ctrl", b=[1], a=[0, 1], samplePeriod=0.1),
     r"TransferFunction 'ctrl': a\[1\] must be non-zero"),
    (lambda: dc.TransferFunction(a=[1, 0.5], samplePeriod=0.1, x_start=[1, 2]),
     r"TransferFunction: x_start must have 1 values, got 2"),
    (lambda: dc.StateSpace(A=[[1, 2]], samplePeriod=0.1),
     r"StateSpace: A must be square"),
    (lambda: dc.StateSpace(A=np.eye(2), B=[[1], [1], [1]], samplePeriod=0.1),
     r"StateSpace: B must have shape \(2, m\), got shape \(3, 1\)"),
    (lambda: dc.StateSpace(A=np.eye(2), C=[[1, 1, 1]], samplePeriod=0.1),
     r"StateSpace: C must have shape \(n, 2\), got shape \(1, 3\)"),
    (lambda: dc.StateSpace(A=np.eye(2), D=[[1, 1]], samplePeriod=0.1),
     r"StateSpace: D must have shape \(1, 1\), got shape \(1, 2\)"),
    (lambda: dc.FirstOrderHold(samplePeriod=0.0),
     r"FirstOrderHold\.samplePeriod' must be > 0"),
    (lambda: dc.StateSpace(samplePeriod=-0.1),
     r"StateSpace\.samplePeriod' must be > 0"),
    (lambda: dc.TransferFunction(),
     r"TransferFunction: parameter\(s\) 'samplePeriod' have no default.*samplePeriod=\.\.\."),
    (lambda: dc.TriggeredSampler(y_start="high"),
     r"TriggeredSampler: y_start must be a number"),
])
def test_bad_parameters_are_refused_with_the_block_named(make, message):
    with pytest.raises(ParameterError, match=message):
        make()


def test_a_non_positive_sample_period_at_simulation_time_is_refused():
    c = acausal.compile(_driven("tf", tf=dc.TransferFunction(samplePeriod=0.1)))
    with pytest.raises((ParameterError, SimulationError), match=r"tf.*samplePeriod|tf.*> 0"):
        c.simulate(1.0, params={"tf.samplePeriod": 0.0})


@pytest.mark.parametrize("make", [
    lambda: dc.FirstOrderHold(samplePeriod=0.1), lambda: dc.TransferFunction(samplePeriod=0.1),
    lambda: dc.StateSpace(A=[[0.5]], B=[[1.0]], C=[[1.0]], samplePeriod=0.1),
    lambda: dc.TriggeredSampler(), lambda: dc.TriggeredMax()])
def test_the_new_blocks_refuse_the_smooth_form(make):
    m = Model("no_smooth")
    m.src, m.blk = sg.Sine(), make()
    m.connect(m.src.y, m.blk.u[1] if isinstance(m.blk, dc.StateSpace) else m.blk.u)
    if isinstance(m.blk, (dc.TriggeredSampler, dc.TriggeredMax)):
        m.trig = lg.BooleanPulse(period=0.2)
        m.connect(m.trig.y, m.blk.trigger)
    with pytest.raises(StructureError, match=rf"{type(m.blk).__name__} 'blk'.*smooth"):
        acausal.compile(m, smooth=True)
