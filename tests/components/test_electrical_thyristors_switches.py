"""Thyristors and the two-way, intermediate and controlled switches of
Modelica.Electrical.Analog.Ideal against closed forms: a phase-controlled rectifier's
conduction angle and current, Ohm's law in each switch position, power balances."""
from __future__ import annotations

import math

import numpy as np
import pytest

import acausal
from acausal.components import electrical as el
from acausal.components import logical as lg
from acausal.errors import StructureError
from wiring import model

TIGHT = {"rtol": 1e-10, "atol": 1e-12}
V, F, R = 100.0, 50.0, 10.0
W = 2 * math.pi * F


def thyristor_rectifier(kind, alpha, width=10.0):
    """SineVoltage (V, F) → thyristor → Resistor R to ground, fired by a BooleanPulse at the
    firing angle alpha [rad] of every period, true for ``width`` percent of it."""
    return model("thyristor_rectifier", lambda m: [
        (m.src.p, m.th.p), (m.th.n, m.r.p), (m.r.n, m.ground.p), (m.src.n, m.ground.p),
        (m.pulse.y, m.th.fire)],
        src=el.SineVoltage(V=V, f=F), th=kind(), r=el.Resistor(R=R),
        pulse=lg.BooleanPulse(period=1 / F, width=width, startTime=alpha / W),
        ground=el.Ground())


def on_off(res, name):
    """The instants [s] where ``name``.off switched to 0 (on) and to 1 (off)."""
    on, off = [], []
    for ev in res.events:
        if f"{name}.off" in ev.modes and ev.time > 0:
            (off if ev.modes[f"{name}.off"][1] else on).append(ev.time)
    return np.array(on), np.array(off)


def test_thyristor_conducts_from_the_firing_angle_to_the_current_zero():
    """Resistive load: the thyristor turns on at the firing angle alpha (fire rises, v > 0)
    and off where the current V·sin(ωt)/(R + Ron) falls through 0 (ωt = π), although fire
    fell long before: conduction angle π − alpha each period; the current follows Ohm's law
    while conducting and the leakage Goff·v while blocking."""
    alpha = math.pi / 3
    t_end = 2 / F
    t = np.linspace(0.0, t_end, 801)
    res = acausal.compile(thyristor_rectifier(el.IdealThyristor, alpha)).simulate(
        t_end, t=t, **TIGHT)
    on, off = on_off(res, "th")
    np.testing.assert_allclose(on, (alpha + 2 * math.pi * np.arange(2)) / W, atol=1e-9)
    np.testing.assert_allclose(off, (math.pi + 2 * math.pi * np.arange(2)) / W, atol=1e-8)
    np.testing.assert_allclose((off - on) * W, math.pi - alpha, atol=1e-6)
    phase = np.mod(W * res.t, 2 * math.pi)
    conducting = (phase > alpha + 1e-6) & (phase < math.pi - 1e-6)
    vs = V * np.sin(W * res.t)
    Ron, Goff = 1e-5, 1e-5
    i_ref = np.where(conducting, vs / (R + Ron), vs * Goff / (1 + Goff * R))
    blocking = ~conducting & (np.abs(phase - alpha) > 1e-6) & (np.abs(phase - math.pi) > 1e-6)
    k = conducting | blocking
    np.testing.assert_allclose(res["r.i"][k], i_ref[k], atol=1e-9)
    # the mean current over a period: V/(2πR)·(1 + cos alpha) (Ohm's law integrated)
    tt = np.linspace(1 / F, 2 / F, 20001)
    i_tt = np.interp(tt, res.t, res["r.i"])
    mean = np.trapezoid(i_tt, tt) * F
    assert mean == pytest.approx(V / (2 * math.pi * R) * (1 + math.cos(alpha)), rel=1e-3)
    np.testing.assert_allclose(res["th.LossPower"], res["th.v"] * res["th.i"], atol=1e-12)


def test_thyristor_with_an_rl_load_turns_off_at_the_extinction_angle():
    """R-L load: after firing at alpha the current is V/Z·(sin(θ − φ) − sin(alpha − φ)·
    exp(−(θ − alpha)/tan φ)), Z = |R + jωL|, φ = atan(ωL/R) (R including Ron); the thyristor
    turns off at its zero beta > π (scipy's brentq), conduction angle beta − alpha. Before
    the firing the blocking thyristor (1/Goff) leaks the steady current V/Zb·sin(θ − φb)
    (its transient decays with L/(R + 1/Goff) = 0.2 µs), the start of the conducting
    current's own decaying term."""
    from scipy.optimize import brentq
    alpha, L = math.pi / 4, 0.02
    m = model("thyristor_rl", lambda m: [
        (m.src.p, m.th.p), (m.th.n, m.r.p), (m.r.n, m.l.p), (m.l.n, m.ground.p),
        (m.src.n, m.ground.p), (m.pulse.y, m.th.fire)],
        src=el.SineVoltage(V=V, f=F), th=el.IdealThyristor(), r=el.Resistor(R=R),
        l=el.Inductor(L=L), pulse=lg.BooleanPulse(period=1 / F, width=5.0, startTime=alpha / W),
        ground=el.Ground())
    t = np.linspace(0.0, 1 / F, 401)
    res = acausal.compile(m).simulate(1 / F, t=t, **TIGHT)
    Rs = R + 1e-5
    Z, phi = math.hypot(Rs, W * L), math.atan2(W * L, Rs)
    Rb = R + 1 / 1e-5
    Zb, phib = math.hypot(Rb, W * L), math.atan2(W * L, Rb)
    leak = V / Zb * math.sin(alpha - phib)

    def current(theta):
        return V / Z * np.sin(theta - phi) + (leak - V / Z * math.sin(alpha - phi)) * np.exp(
            -(theta - alpha) / math.tan(phi))
    beta = brentq(current, math.pi, 2 * math.pi, xtol=1e-14)
    on, off = on_off(res, "th")
    np.testing.assert_allclose(on, [alpha / W], atol=1e-9)
    np.testing.assert_allclose(off, [beta / W], atol=1e-8)
    theta = W * res.t
    k = (theta > alpha + 1e-6) & (theta < beta - 1e-6)
    np.testing.assert_allclose(res["l.i"][k], current(theta[k]), atol=1e-6)


def test_gto_thyristor_turns_off_when_fire_falls():
    """The GTO conducts only while fire is true and v > 0: fired at alpha for a quarter of
    the period it turns off at alpha + T/4 (before the current zero): conduction angle
    π/2."""
    alpha = math.pi / 6
    t_end = 1 / F
    t = np.linspace(0.0, t_end, 401)
    res = acausal.compile(thyristor_rectifier(el.IdealGTOThyristor, alpha, 25.0)).simulate(
        t_end, t=t, **TIGHT)
    on, off = on_off(res, "th")
    np.testing.assert_allclose(on, [alpha / W], atol=1e-9)
    np.testing.assert_allclose(off, [(alpha + math.pi / 2) / W], atol=1e-9)
    phase = W * res.t
    k = (phase > alpha + 1e-6) & (phase < alpha + math.pi / 2 - 1e-6)
    np.testing.assert_allclose(res["r.i"][k], V * np.sin(phase[k]) / (R + 1e-5), rtol=1e-9)


def test_thyristor_with_a_knee_voltage_is_not_fired_below_it():
    """Fired while v < Vknee, a thyristor stays blocked: its blocking segment through the
    knee (Vknee, Goff·Vknee) is the leakage i = Goff·v."""
    Vknee, alpha = 150.0, math.pi / 2                  # above the source's amplitude V
    m = thyristor_rectifier(lambda: el.IdealThyristor(Vknee=Vknee), alpha)
    res = acausal.compile(m).simulate(1 / F, t=np.linspace(0, 1 / F, 101), **TIGHT)
    assert np.all(res["th.off"] == 1)
    vs = V * np.sin(W * res.t)
    # blocking: i = Goff·v through R: v + R·Goff·v = vs
    np.testing.assert_allclose(res["r.i"], 1e-5 * vs / (1 + 1e-5 * R), atol=1e-9)


def two_way(controlled, position):
    """RampVoltage (0 to V) at p; R1 from n1, R2 from n2 to ground; the switch set by a
    BooleanConstant (or a ConstantVoltage on the control pin, 1 V or 0 V)."""
    R1, R2 = 5.0, 20.0
    parts = dict(src=el.RampVoltage(V=V, duration=1e-3), r1=el.Resistor(R=R1), r2=el.Resistor(R=R2),
                 ground=el.Ground())
    pairs = [("src.p", "sw.p"), ("sw.n1", "r1.p"), ("sw.n2", "r2.p"), ("r1.n", "ground.p"),
             ("r2.n", "ground.p"), ("src.n", "ground.p")]
    if controlled:
        parts.update(sw=el.ControlledIdealTwoWaySwitch(), c=el.ConstantVoltage(V=float(position)))
        pairs += [("c.p", "sw.control"), ("c.n", "ground.p")]
    else:
        parts.update(sw=el.IdealTwoWaySwitch(), c=lg.BooleanConstant(k=bool(position)))
        pairs += [("c.y", "sw.control")]
    return model("two_way", lambda m: [(port(m, a), port(m, b)) for a, b in pairs],
                 **parts), R1, R2


def port(m, dotted):
    part, pin = dotted.split(".")
    return getattr(getattr(m, part), pin)


@pytest.mark.parametrize("controlled", [False, True])
@pytest.mark.parametrize("position", [0, 1])
def test_two_way_switch_obeys_ohms_law_in_both_positions(controlled, position):
    """Position false (control.v < level): p–n1 through Ron, p–n2 through 1/Goff;
    true: the other way round. Each branch current is V over its series resistance; the
    switch's loss is the sum of the two paths' i²·R."""
    m, R1, R2 = two_way(controlled, position)
    t = np.linspace(0, 1e-3, 5)
    res = acausal.compile(m).simulate(1e-3, t=t, **TIGHT)
    Ron, Goff = 1e-5, 1e-5
    r_1, r_2 = (Ron, 1 / Goff) if position == 0 else (1 / Goff, Ron)
    vs = V * t / 1e-3
    i1, i2 = vs / (R1 + r_1), vs / (R2 + r_2)
    np.testing.assert_allclose(res["r1.i"], i1, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(res["r2.i"], i2, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(res["src.i"], -(i1 + i2), rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(res["sw.LossPower"], i1 ** 2 * r_1 + i2 ** 2 * r_2, rtol=1e-8,
                               atol=1e-12)


def test_controlled_switches_switch_where_the_control_voltage_crosses_the_level():
    """A SineVoltage (1 V, 50 Hz) on the control pins, level 0.5: control.v > 0.5 from
    ωt = π/6 to 5π/6. The opening switch is open there, the closing switch closed; each
    switches a resistor R on V: the currents V/(R + Ron) or V/(R + 1/Goff)."""
    m = model("controlled", lambda m: [
        (m.src.p, m.op.p), (m.op.n, m.r1.p), (m.src.p, m.cl.p), (m.cl.n, m.r2.p),
        (m.r1.n, m.ground.p), (m.r2.n, m.ground.p), (m.src.n, m.ground.p),
        (m.ctl.p, m.op.control), (m.ctl.p, m.cl.control), (m.ctl.n, m.ground.p)],
        src=el.ConstantVoltage(V=V), op=el.ControlledIdealOpeningSwitch(),
        cl=el.ControlledIdealClosingSwitch(), r1=el.Resistor(R=R), r2=el.Resistor(R=R),
        ctl=el.SineVoltage(V=1.0, f=F), ground=el.Ground())
    t = np.linspace(0.0, 1 / F, 201)
    res = acausal.compile(m).simulate(1 / F, t=t, **TIGHT)
    switched = sorted({ev.time for ev in res.events if "op.above" in ev.modes})
    np.testing.assert_allclose(switched, [1 / (12 * F), 5 / (12 * F)], atol=1e-9)
    phase = W * res.t
    k = np.abs(np.sin(phase) - 0.5) > 1e-6
    high = np.sin(phase) > 0.5
    on, leak = V / (R + 1e-5), V / (R + 1e5)
    np.testing.assert_allclose(res["r1.i"][k], np.where(high, leak, on)[k], rtol=1e-9)
    np.testing.assert_allclose(res["r2.i"][k], np.where(high, on, leak)[k], rtol=1e-9)
    assert np.all(res["ctl.i"] == 0)            # the control pins draw no current


@pytest.mark.parametrize("controlled", [False, True])
@pytest.mark.parametrize("crossed", [0, 1])
def test_intermediate_switch_routes_two_sources_straight_or_crossed(controlled, crossed):
    """Sources V1 at p1 and V2 at p2, loads R1 from n1 and R2 from n2 to ground: straight
    (p1–n1, p2–n2 through Ron) each load sees its own source, crossed the other one; the
    open paths leak Goff: each load node a conductance divider."""
    V1, V2, R1, R2, Ron, Goff = 10.0, 3.0, 5.0, 7.0, 1e-5, 1e-5
    parts = dict(s1=el.ConstantVoltage(V=V1), s2=el.SineVoltage(V=V2, f=F, phase=math.pi / 2),
                 r1=el.Resistor(R=R1), r2=el.Resistor(R=R2), ground=el.Ground())
    pairs = [("s1.p", "sw.p1"), ("s2.p", "sw.p2"), ("sw.n1", "r1.p"), ("sw.n2", "r2.p"),
             ("r1.n", "ground.p"), ("r2.n", "ground.p"), ("s1.n", "ground.p"),
             ("s2.n", "ground.p")]
    if controlled:
        parts.update(sw=el.ControlledIdealIntermediateSwitch(),
                     c=el.ConstantVoltage(V=float(crossed)))
        pairs += [("c.p", "sw.control"), ("c.n", "ground.p")]
    else:
        parts.update(sw=el.IdealIntermediateSwitch(), c=lg.BooleanConstant(k=bool(crossed)))
        pairs += [("c.y", "sw.control")]
    m = acausal.Model("intermediate")
    for k, v in parts.items():
        setattr(m, k, v)
    for a, b in pairs:
        m.connect(port(m, a), port(m, b))
    t = np.linspace(0, 1e-3, 3)
    res = acausal.compile(m).simulate(1e-3, t=t, **TIGHT)
    V2 = V2 * np.cos(W * t)                     # the second source, a cosine
    g_on, g_off = 1 / Ron, Goff
    g11, g22 = (g_on, g_on) if not crossed else (g_off, g_off)     # p1–n1, p2–n2
    g12, g21 = (g_off, g_off) if not crossed else (g_on, g_on)     # p1–n2, p2–n1
    # the nodes n1, n2 are decoupled: each a conductance divider
    u1 = (g11 * V1 + g21 * V2) / (g11 + g21 + 1 / R1)
    u2 = (g22 * V2 + g12 * V1) / (g22 + g12 + 1 / R2)
    np.testing.assert_allclose(res["r1.v"], u1, rtol=1e-9)
    np.testing.assert_allclose(res["r2.v"], u2, rtol=1e-9)
    loss = (g11 * (V1 - u1) ** 2 + g22 * (V2 - u2) ** 2 + g12 * (V1 - u2) ** 2
            + g21 * (V2 - u1) ** 2)
    np.testing.assert_allclose(res["sw.LossPower"], loss, rtol=1e-7)


def test_msl3_names_of_the_two_way_switches():
    assert el.IdealCommutingSwitch is el.IdealTwoWaySwitch
    assert el.ControlledIdealCommutingSwitch is el.ControlledIdealTwoWaySwitch


def test_event_switched_elements_have_no_smooth_form():
    for m in (thyristor_rectifier(el.IdealThyristor, 1.0), two_way(True, 1)[0]):
        with pytest.raises(StructureError, match="no smooth form"):
            acausal.compile(m, smooth=True)
