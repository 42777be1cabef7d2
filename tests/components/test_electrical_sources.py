"""The electrical signal sources (Modelica.Electrical.Analog.Sources) against their closed
forms written here with numpy, and in circuits against the exact RC responses."""
from __future__ import annotations

import numpy as np
import pytest

import acausal
from acausal.components import electrical as el
from acausal.components.electrical.sources import _VoltageSource
from acausal.errors import ParameterError
from wiring import model

TIGHT = {"rtol": 1e-11, "atol": 1e-12}
R_LOAD = 2.0


def on_resistor(source):
    """``source`` across a resistor R_LOAD, n grounded, beside a discharging RC of its own
    (so that the model has a state)."""
    return model("src", lambda m: [
        (m.src.p, m.r.p), (m.r.n, m.src.n), (m.src.n, m.ground.p),
        (m.rc.p, m.c.p), (m.rc.n, m.c.n), (m.c.n, m.ground.p)],
        src=source, r=el.Resistor(R=R_LOAD), rc=el.Resistor(R=1.0),
        c=el.Capacitor(C=1.0, v_start=1.0), ground=el.Ground())


def pulse(t, amplitude, width, period, start, nperiod=-1):
    tau = t - start
    count = np.floor(tau / period)
    on = (tau >= 0) & ((tau - count * period) < width / 100 * period)
    return np.where(on & ((nperiod < 0) | (count < nperiod)), amplitude, 0.0)


def trapezoid(t, a, rising, width, falling, period, start, nperiod):
    tau = t - start
    count = np.floor(tau / period)
    tp = tau - count * period
    y = np.interp(tp, [0, rising, rising + width, rising + width + falling, period],
                  [0, a, a, 0, 0])
    return np.where((tau >= 0) & ((nperiod < 0) | (count < nperiod)), y, 0.0)


def exponentials(t, top, rise, rise_const, fall_const, start):
    tau = t - start
    reached = top * (1 - np.exp(-rise / rise_const))
    y = np.where(tau < rise, top * (1 - np.exp(-np.clip(tau, 0, None) / rise_const)),
                 reached * np.exp(-np.clip(tau - rise, 0, None) / fall_const))
    return np.where(tau < 0, 0.0, y)


def table_by_hand(tau, times, values, jump=None, after=None):
    """Linear interpolation through (times, values), extrapolated through the last two
    points; with ``jump``: from that time on the row (jump, after) replaces the value there
    (a repeated time in the table)."""
    times, values = list(times), list(values)
    if jump is not None:
        k = times.index(jump)
        before = np.interp(tau, times[:k + 1], values[:k + 1])
        tail_t, tail_v = [jump] + times[k + 1:], [after] + values[k + 1:]
        slope = (tail_v[-1] - tail_v[-2]) / (tail_t[-1] - tail_t[-2])
        later = np.where(tau > tail_t[-1], tail_v[-1] + slope * (tau - tail_t[-1]),
                         np.interp(tau, tail_t, tail_v))
        return np.where(tau < jump, before, later)
    slope = (values[-1] - values[-2]) / (times[-1] - times[-2])
    return np.where(tau > times[-1], values[-1] + slope * (tau - times[-1]),
                    np.interp(tau, times, values))


# (class, parameters, closed form of the source's value as a function of t); sample times
# avoid the discontinuities (a value there is either side's)
T_SAMPLE = np.linspace(0.0, 1.0, 101)[:-1] + 0.0037
WAVES = [
    (el.StepVoltage, dict(V=2.5, offset=0.3, startTime=0.42),
     lambda t: 0.3 + np.where(t < 0.42, 0.0, 2.5)),
    (el.RampVoltage, dict(V=3.0, duration=0.4, offset=-1.0, startTime=0.2),
     lambda t: -1.0 + 3.0 * np.clip((t - 0.2) / 0.4, 0.0, 1.0)),
    (el.SineVoltage, dict(V=1.5, f=3.0, phase=0.4, offset=0.1, startTime=0.25),
     lambda t: 0.1 + np.where(t < 0.25, 0.0, 1.5 * np.sin(2 * np.pi * 3 * (t - 0.25) + 0.4))),
    (el.CosineVoltage, dict(V=2.0, f=2.0, phase=0.3, startTime=0.1),
     lambda t: np.where(t < 0.1, 0.0, 2.0 * np.cos(2 * np.pi * 2 * (t - 0.1) + 0.3))),
    (el.ExpSineVoltage, dict(V=4.0, f=3.0, phase=0.2, damping=2.5, offset=0.5),
     lambda t: 0.5 + 4.0 * np.exp(-2.5 * t) * np.sin(2 * np.pi * 3 * t + 0.2)),
    (el.PulseVoltage, dict(V=2.0, width=30.0, period=0.2, offset=0.5, startTime=0.1),
     lambda t: 0.5 + pulse(t, 2.0, 30.0, 0.2, 0.1)),
    (el.TrapezoidVoltage, dict(V=2.0, rising=0.05, width=0.1, falling=0.02, period=0.3,
                               nperiod=2, offset=0.1, startTime=0.05),
     lambda t: 0.1 + trapezoid(t, 2.0, 0.05, 0.1, 0.02, 0.3, 0.05, 2)),
    (el.StepCurrent, dict(I=2.5, offset=0.3, startTime=0.42),
     lambda t: 0.3 + np.where(t < 0.42, 0.0, 2.5)),
    (el.RampCurrent, dict(I=3.0, duration=0.4, offset=-1.0, startTime=0.2),
     lambda t: -1.0 + 3.0 * np.clip((t - 0.2) / 0.4, 0.0, 1.0)),
    (el.SineCurrent, dict(I=1.5, f=3.0, phase=0.4, offset=0.1, startTime=0.25),
     lambda t: 0.1 + np.where(t < 0.25, 0.0, 1.5 * np.sin(2 * np.pi * 3 * (t - 0.25) + 0.4))),
    (el.CosineCurrent, dict(I=2.0, f=2.0, phase=0.3),
     lambda t: 2.0 * np.cos(2 * np.pi * 2 * t + 0.3)),
    (el.ExpSineCurrent, dict(I=4.0, f=3.0, phase=0.2, damping=2.5, startTime=0.3),
     lambda t: np.where(t < 0.3, 0.0, 4.0 * np.exp(-2.5 * (t - 0.3))
                        * np.sin(2 * np.pi * 3 * (t - 0.3) + 0.2))),
    (el.PulseCurrent, dict(I=-1.5, width=60.0, period=0.25, offset=0.2),
     lambda t: 0.2 + pulse(t, -1.5, 60.0, 0.25, 0.0)),
    (el.TrapezoidCurrent, dict(I=1.0, rising=0.1, width=0.05, falling=0.1, period=0.4),
     lambda t: trapezoid(t, 1.0, 0.1, 0.05, 0.1, 0.4, 0.0, -1)),
    (el.SawToothVoltage, dict(V=3.0, period=0.3, offset=-0.5, startTime=0.1),
     lambda t: -0.5 + np.where(t < 0.1, 0.0, 3.0 * np.mod(t - 0.1, 0.3) / 0.3)),
    (el.SawToothCurrent, dict(I=-2.0, period=0.15),
     lambda t: -2.0 * np.mod(t, 0.15) / 0.15),
    (el.ExponentialsVoltage, dict(vMax=2.0, riseTime=0.3, riseTimeConst=0.05, offset=0.2,
                                  startTime=0.1),
     lambda t: 0.2 + exponentials(t, 2.0, 0.3, 0.05, 0.05, 0.1)),
    (el.TableVoltage, dict(table=[[0, 0], [0.2, 1.0], [0.4, 1.0], [0.4, -2.0], [0.6, 0.5]],
                           offset=0.1, startTime=0.15),
     lambda t: 0.1 + np.where(t < 0.15, 0.0, table_by_hand(
         t - 0.15, [0, 0.2, 0.4, 0.6], [0, 1.0, 1.0, 0.5], 0.4, -2.0))),
    (el.TableCurrent, dict(), lambda t: table_by_hand(t, [0, 1, 2], [0, 1, 4])),
    (el.ExponentialsCurrent, dict(iMax=-1.5, riseTime=0.4, riseTimeConst=0.2,
                                  fallTimeConst=0.07),
     lambda t: exponentials(t, -1.5, 0.4, 0.2, 0.07, 0.0)),
]


@pytest.mark.parametrize("cls, params, closed_form", WAVES, ids=[w[0].__name__ for w in WAVES])
def test_source_waveform_matches_its_closed_form(cls, params, closed_form):
    """A voltage source sets v = p.v − n.v (the resistor draws −i = v/R through it); a
    current source sends i from p through itself to n (the resistor sees v = −R·i)."""
    res = acausal.compile(on_resistor(cls(**params))).simulate(
        T_SAMPLE[-1], t=T_SAMPLE, **TIGHT)
    expected = closed_form(T_SAMPLE)
    if issubclass(cls, _VoltageSource):
        np.testing.assert_allclose(res["src.v"], expected, atol=1e-12)
        np.testing.assert_allclose(res["r.i"], expected / R_LOAD, atol=1e-12)
    else:
        np.testing.assert_allclose(res["src.i"], expected, atol=1e-12)
        np.testing.assert_allclose(res["r.v"], -R_LOAD * expected, atol=1e-12)


def test_pulse_voltage_keeps_msl_parameters():
    """MSL's PulseVoltage has no nperiod (its Pulse block keeps the default −1: infinitely
    many periods); its TrapezoidVoltage has one."""
    assert "nperiod" not in el.PulseVoltage.parameters()
    assert el.TrapezoidVoltage.parameters()["nperiod"].default == -1
    assert el.PulseVoltage.parameters()["width"].unit == "%"
    assert el.RampCurrent.parameters()["offset"].unit == "A"


def test_rc_on_a_ramp_matches_the_closed_form_and_balances_energy():
    """RC on a RampVoltage (a = V/d from t0): with τ = t − t0 ≤ d, v_C = a·(τ − RC·(1 −
    e^(−τ/RC))); after the ramp v_C relaxes to V from v_C(d). The source's energy is the
    resistor's loss plus ½·C·v_C²."""
    V, d, t0, R, C = 2.0, 0.3, 0.1, 5.0, 0.02
    tau_rc = R * C
    m = model("rc", lambda m: [(m.src.p, m.r.p), (m.r.n, m.c.p), (m.c.n, m.src.n),
                               (m.src.n, m.ground.p)],
              src=el.RampVoltage(V=V, duration=d, startTime=t0), r=el.Resistor(R=R),
              c=el.Capacitor(C=C), ground=el.Ground())
    t = np.linspace(0.0, 1.0, 2001)
    res = acausal.compile(m).simulate(1.0, t=t, **TIGHT)
    a = V / d
    tau = np.clip(t - t0, 0.0, d)
    on_ramp = a * (tau - tau_rc * (1 - np.exp(-tau / tau_rc)))
    v_end = a * (d - tau_rc * (1 - np.exp(-d / tau_rc)))
    after = V + (v_end - V) * np.exp(-np.clip(t - t0 - d, 0.0, None) / tau_rc)
    vc = np.where(t - t0 <= d, on_ramp, after)
    np.testing.assert_allclose(res["c.v"], vc, atol=1e-9)
    supplied = -res["src.v"] * res["src.i"]
    e_in = np.trapezoid(supplied, t)
    e_out = np.trapezoid(res["r.LossPower"], t) + 0.5 * C * vc[-1] ** 2
    assert e_in == pytest.approx(e_out, rel=1e-6)


def test_rc_on_a_pulse_current_matches_the_exact_piecewise_response():
    """A PulseCurrent into C ∥ R: on each plateau v relaxes exponentially to R·i; the
    simulation restarts at the pulse's edges (its time events), so it stays exact over
    many edges."""
    I, width, period, R, C = 0.5, 25.0, 0.1, 4.0, 0.01
    m = model("pulse", lambda m: [(m.src.n, m.c.p), (m.c.p, m.r.p), (m.src.p, m.ground.p),
                                  (m.c.n, m.ground.p), (m.r.n, m.ground.p)],
              src=el.PulseCurrent(I=I, width=width, period=period), c=el.Capacitor(C=C),
              r=el.Resistor(R=R), ground=el.Ground())
    t = np.linspace(0.0, 1.0, 1001)
    res = acausal.compile(m).simulate(1.0, t=t, **TIGHT)
    edges = [k * period + offset for k in range(10) for offset in (0, width / 100 * period)]
    expected, v, last = [], 0.0, 0.0
    for point in sorted(set(edges[1:]) | set(t)):  # exact exponential from edge to edge
        if point > last:
            on = ((last + point) / 2) % period < width / 100 * period
            level = R * I * on
            v = level + (v - level) * np.exp(-(point - last) / (R * C))
            last = point
        if point in t:
            expected.append(v)
    np.testing.assert_allclose(res["c.v"], expected, atol=1e-9)


def test_exponentials_fall_time_constant_follows_the_rise_time_constant():
    """MSL's binding fallTimeConst = riseTimeConst holds at simulation time too (changing
    riseTimeConst changes the fall); given at construction fallTimeConst is a parameter of
    its own."""
    assert "fallTimeConst" not in el.ExponentialsVoltage.parameters()
    assert "fallTimeConst" in type(el.ExponentialsVoltage(fallTimeConst=0.2)).parameters()
    compiled = acausal.compile(on_resistor(el.ExponentialsVoltage(vMax=1.0, riseTime=0.2)))
    res = compiled.simulate(T_SAMPLE[-1], t=T_SAMPLE, params={"src.riseTimeConst": 0.08},
                            **TIGHT)
    np.testing.assert_allclose(res["src.v"], exponentials(T_SAMPLE, 1.0, 0.2, 0.08, 0.08, 0.0),
                               atol=1e-12)


@pytest.mark.parametrize("make", [
    lambda: el.SawToothVoltage(period=0.0), lambda: el.ExponentialsCurrent(riseTimeConst=0.0),
    lambda: el.TableVoltage(table=[[0, 1, 2], [1, 2, 3]]),
    lambda: el.TableCurrent(table=[[0.5, 1], [1, 2]]),
    lambda: el.ExponentialsVoltage(fallTimeConst=-1.0),
    lambda: el.PulseVoltage(period=0.0), lambda: el.PulseCurrent(width=0.0),
    lambda: el.PulseVoltage(width=-5.0), lambda: el.TrapezoidCurrent(period=-1.0),
    lambda: el.TrapezoidVoltage(rising=-0.1), lambda: el.RampVoltage(duration=0.0),
    lambda: el.RampCurrent(duration=-1.0)])
def test_bad_source_parameters_are_refused_naming_the_component(make):
    with pytest.raises(ParameterError,
                       match=r"(Pulse|Trapezoid|Ramp|SawTooth|Exponentials|Table)(Voltage|Current)"
                             r"(\.| *:)"):
        make()
