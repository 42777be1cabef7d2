"""Ideal switching elements and two-ports of Modelica.Electrical.Analog against a hand-written
event-driven scipy model, closed forms, power balances and MSL's ChuaCircuit."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.components import electrical as el
from acausal.components import logical as lg
from acausal.errors import SimulationError
from wiring import model

TIGHT = {"rtol": 1e-11, "atol": 1e-12}


def rectifier(V=10.0, f=50.0, R=100.0, C=1e-4):
    """SineVoltage → IdealDiode → node c (Resistor R and Capacitor C to ground)."""
    return model("rectifier", lambda m: [
        (m.src.p, m.diode.p), (m.diode.n, m.r.p), (m.r.p, m.c.p), (m.r.n, m.ground.p),
        (m.c.n, m.ground.p), (m.src.n, m.ground.p)],
        src=el.SineVoltage(V=V, f=f), diode=el.IdealDiode(), r=el.Resistor(R=R),
        c=el.Capacitor(C=C), ground=el.Ground())


def rectifier_by_hand(V, f, R, C, Ron, Goff, t_end, t):
    """The same circuit as an event-driven scipy model in the diode voltage u = vs − vc
    (tiny while conducting, so written as the state): u' = vs' − ic/C with the capacitor's
    current ic = u/Ron − vc/R conducting, Goff·u − vc/R blocking; the diode switches where u
    crosses 0 (its current u/Ron falls through 0, or the source rises above the capacitor).
    Returns (vc at t, switch times)."""
    w = 2 * math.pi * f
    g = {False: 1 / Ron, True: Goff}

    def rhs(off):
        return lambda tt, x: [V * w * math.cos(w * tt)
                              - (g[off] * x[0] - (V * math.sin(w * tt) - x[0]) / R) / C]

    def edge(tt, x):
        return x[0]
    edge.terminal = True
    off, t0, x0, times, pieces = False, 0.0, [0.0], [], []     # conducting at t = 0 (s = 0)
    while t0 < t_end:
        edge.direction = 1 if off else -1
        sol = solve_ivp(rhs(off), (t0, t_end), x0, method="Radau", events=edge,
                        dense_output=True, rtol=1e-12, atol=1e-20 if not off else 1e-13)
        pieces.append((t0, sol.t[-1], sol.sol))
        if sol.status == 1:
            times.append(sol.t[-1])
            off = not off
        t0, x0 = sol.t[-1], [0.0]
    u = np.empty_like(t)
    for a, b, s in pieces:
        k = (t >= a) & (t <= b)
        if k.any():
            u[k] = s(t[k])[0]
    return V * np.sin(w * t) - u, np.array(times)


def test_half_wave_rectifier_matches_an_event_driven_scipy_model():
    """Conduction ends where the diode current crosses 0 and starts again where the source
    rises above the capacitor: both instants within 1e-8 s of the scipy model's, the
    capacitor voltage within 1e-7 V over three periods."""
    V, f, R, C, t_end = 10.0, 50.0, 100.0, 1e-4, 0.06
    t = np.linspace(0.0, t_end, 601)
    res = acausal.compile(rectifier(V, f, R, C)).simulate(t_end, t=t, **TIGHT)
    switches = [ev.time for ev in res.events if "diode.off" in ev.modes and ev.time > 0]
    vc_ref, times_ref = rectifier_by_hand(V, f, R, C, 1e-5, 1e-5, t_end, t)
    assert len(switches) == len(times_ref) == 5
    np.testing.assert_allclose(switches, times_ref, atol=1e-8)
    at = np.searchsorted(res.t, t, side="right") - 1
    np.testing.assert_allclose(res["c.v"][at], vc_ref, atol=1e-7)
    # MSL's characteristic: the diode's v and i from s, and the loss v·i
    np.testing.assert_allclose(res["diode.LossPower"], res["diode.v"] * res["diode.i"],
                               atol=1e-12)


def test_opening_switch_in_an_rl_circuit_decays_through_goff():
    """V — R — L — IdealOpeningSwitch, opened at t0 by a BooleanStep: before, i = V/(R+Ron)
    ·(1 − exp(−t(R+Ron)/L)); after, the open switch leaks Goff (MSL), so i decays from I0
    to V/(R + 1/Goff) with the time constant L/(R + 1/Goff)."""
    V, R, L, t0, Ron, Goff = 5.0, 10.0, 1.0, 0.3, 1e-5, 1e-5
    m = model("rl_switch", lambda m: [
        (m.src.p, m.r.p), (m.r.n, m.l.p), (m.l.n, m.switch.p), (m.switch.n, m.src.n),
        (m.src.n, m.ground.p), (m.step.y, m.switch.control)],
        src=el.ConstantVoltage(V=V), r=el.Resistor(R=R), l=el.Inductor(L=L),
        switch=el.IdealOpeningSwitch(), step=lg.BooleanStep(startTime=t0), ground=el.Ground())
    t = np.concatenate([np.linspace(0.0, t0, 31)[:-1], t0 + np.linspace(0.0, 1e-4, 51)])
    res = acausal.compile(m).simulate(float(t[-1]), t=t, **TIGHT)
    at = np.searchsorted(res.t, t, side="right") - 1
    R1, R2 = R + Ron, R + 1 / Goff
    I0 = V / R1 * (1 - math.exp(-t0 * R1 / L))
    i = np.where(t < t0, V / R1 * (1 - np.exp(-t * R1 / L)),
                 V / R2 + (I0 - V / R2) * np.exp(-np.clip(t - t0, 0, None) * R2 / L))
    np.testing.assert_allclose(res["l.i"][at], i, atol=1e-9 * I0)
    k = t != t0         # at the time event itself the output shows s's left limit
    np.testing.assert_allclose(res["switch.v"][at][k], np.where(t < t0, Ron, 1 / Goff)[k] *
                               i[k], rtol=1e-8, atol=1e-12)


def test_a_blocking_diode_without_leakage_in_series_with_an_inductor_is_refused():
    """An IdealDiode with Goff = 0 blocks an R-L branch at its current's zero: then the
    diode's voltage (its curve parameter s) is determined by no equation while the
    inductor's derivative depends on it (in a Modelica tool: a singular system). The
    simulation stops there with an error naming s and what to do, instead of holding s and
    missing the next turn-on (the conduction interval before it is the closed form's: the
    current's zero beta)."""
    from scipy.optimize import brentq
    V, F, R, L = 10.0, 50.0, 10.0, 0.01
    w = 2 * math.pi * F
    m = model("rl_rectifier", lambda m: [
        (m.src.p, m.d.p), (m.d.n, m.r.p), (m.r.n, m.l.p), (m.l.n, m.src.n),
        (m.src.n, m.ground.p)],
        src=el.SineVoltage(V=V, f=F), d=el.IdealDiode(Goff=0.0), r=el.Resistor(R=R),
        l=el.Inductor(L=L), ground=el.Ground())
    phi = math.atan2(w * L, R + 1e-5)
    beta = brentq(lambda th: math.sin(th - phi) + math.sin(phi) * math.exp(-th / math.tan(phi)),
                  math.pi, 2 * math.pi, xtol=1e-14)
    with pytest.raises(SimulationError, match=r"do not determine d\.s.*Goff > 0") as err:
        acausal.compile(m).simulate(2 / F, **TIGHT)
    stopped = float(re.search(r"at t = (\S+) s", str(err.value)).group(1))
    assert abs(stopped - beta / w) < 1e-6          # at the turn-off, the message's 6 digits


def test_closing_switch_charges_a_capacitor_through_goff_then_ron():
    """V — R — IdealClosingSwitch — C, closed at t0 by a BooleanStep: before, C charges
    through R + 1/Goff (MSL's leakage), after through R + Ron: two exponentials."""
    V, R, C, t0, Ron, Goff = 5.0, 10.0, 1e-3, 0.02, 1e-5, 1e-5
    m = model("rc_switch", lambda m: [
        (m.src.p, m.r.p), (m.r.n, m.switch.p), (m.switch.n, m.c.p), (m.c.n, m.src.n),
        (m.src.n, m.ground.p), (m.step.y, m.switch.control)],
        src=el.ConstantVoltage(V=V), r=el.Resistor(R=R), c=el.Capacitor(C=C),
        switch=el.IdealClosingSwitch(), step=lg.BooleanStep(startTime=t0), ground=el.Ground())
    t = np.linspace(0.0, 0.1, 101)
    res = acausal.compile(m).simulate(0.1, t=t, **TIGHT)
    at = np.searchsorted(res.t, t, side="right") - 1
    v0 = V * (1 - math.exp(-t0 / ((R + 1 / Goff) * C)))
    vc = np.where(t < t0, V * (1 - np.exp(-t / ((R + 1 / Goff) * C))),
                  V - (V - v0) * np.exp(-np.clip(t - t0, 0, None) / ((R + Ron) * C)))
    np.testing.assert_allclose(res["c.v"][at], vc, atol=1e-9)
    np.testing.assert_allclose(res["switch.off"][at], t < t0)


def test_ideal_transformer_is_power_conserving():
    """SineVoltage (V, ω) on the primary, an R-L load on the secondary: v2 = v1/n, so the
    load current is the sinusoidal RL response i = V/n/(R² + ω²L²)·(R sin ωt − ωL cos ωt +
    ωL e^(−Rt/L)), i2 = −i, i1 = −i2/n and v1·i1 + v2·i2 = 0 exactly; with a magnetizing
    inductance Lm1 the primary draws the extra current im1, Lm1·im1' = v1."""
    V, f, n, R, L, Lm1 = 230.0, 50.0, 4.0, 8.0, 0.02, 2.0
    w = 2 * np.pi * f
    for magnetize in (False, True):
        m = model("transformer", lambda m: [
            (m.src.p, m.tr.p1), (m.src.n, m.tr.n1), (m.tr.p2, m.r.p), (m.r.n, m.l.p),
            (m.l.n, m.tr.n2), (m.src.n, m.ground.p), (m.tr.n2, m.ground2.p)],
            src=el.SineVoltage(V=V, f=f), r=el.Resistor(R=R), l=el.Inductor(L=L),
            tr=el.IdealTransformer(n=n, Lm1=Lm1, considerMagnetization=magnetize),
            ground=el.Ground(), ground2=el.Ground())
        t = np.linspace(0.0, 0.04, 81)
        res = acausal.compile(m).simulate(0.04, t=t, rtol=1e-10, atol=1e-12)
        v1 = V * np.sin(w * t)
        i = V / n / (R ** 2 + (w * L) ** 2) * (R * np.sin(w * t) - w * L * np.cos(w * t)
                                               + w * L * np.exp(-R * t / L))
        np.testing.assert_allclose(res["tr.v2"], v1 / n, atol=1e-8)
        np.testing.assert_allclose(res["tr.i2"], -i, atol=1e-8)
        im1 = V / (w * Lm1) * (1 - np.cos(w * t)) if magnetize else 0.0
        np.testing.assert_allclose(res["tr.i1"], i / n + im1, atol=1e-8)
        np.testing.assert_allclose(res["tr.im1"], im1, atol=1e-8)
        if not magnetize:
            p2 = res["tr.v2"] * res["tr.i2"]       # zero to the algebraic solve's round-off
            np.testing.assert_allclose(res["tr.v1"] * res["tr.i1"] + p2, 0.0,
                                       atol=1e-10 * np.max(np.abs(p2)))


def test_gyrator_turns_a_capacitor_into_an_inductor():
    """A gyrator (G1 = G2 = G) loaded by a capacitor C is an inductor L = C/G² at its
    primary port: a step V through R charges it as i1 = V/R·(1 − exp(−t·R/L))."""
    V, R, C, G = 2.0, 4.0, 0.5, 2.0
    m = model("gyrator", lambda m: [
        (m.src.p, m.r.p), (m.r.n, m.gy.p1), (m.gy.n1, m.src.n), (m.gy.p2, m.c.p),
        (m.gy.n2, m.c.n), (m.src.n, m.ground.p), (m.c.n, m.ground.p)],
        src=el.ConstantVoltage(V=V), r=el.Resistor(R=R), gy=el.Gyrator(G1=G, G2=G),
        c=el.Capacitor(C=C), ground=el.Ground())
    t = np.linspace(0.0, 1.0, 51)
    res = acausal.compile(m).simulate(1.0, t=t, **TIGHT)
    L = C / G ** 2
    np.testing.assert_allclose(res["gy.i1"], V / R * (1 - np.exp(-t * R / L)), atol=1e-9)
    np.testing.assert_allclose(res["gy.v1"] * res["gy.i1"] + res["gy.v2"] * res["gy.i2"],
                               0.0, atol=1e-9)


def chua_by_hand(t):
    """MSL's ChuaCircuit as scipy ODEs: C1·v1' = G·(v2 − v1) − Nr(v1), C2·v2' = G·(v1 − v2)
    − iL, L·iL' = v2 − Ro·iL, with its parameters and starts (v1 = 4 V)."""
    L, Ro, G, C1, C2, Ga, Gb, Ve = 18.0, 12.5e-3, 0.565, 10.0, 100.0, -0.757576, -0.409091, 1

    def nr(v):
        return Gb * (v + Ve) - Ga * Ve if v < -Ve else Gb * (v - Ve) + Ga * Ve if v > Ve \
            else Ga * v

    def rhs(_, x):
        v1, v2, i = x
        return [(G * (v2 - v1) - nr(v1)) / C1, (G * (v1 - v2) - i) / C2, (v2 - Ro * i) / L]
    sol = solve_ivp(rhs, (t[0], t[-1]), [4.0, 0.0, 0.0], t_eval=t, method="DOP853",
                    rtol=1e-12, atol=1e-12)
    return dict(zip(("C1.v", "C2.v", "L.i"), sol.y))


def test_chua_circuit_matches_a_scipy_model():
    """The first 2000 s of MSL's ChuaCircuit (the double scroll forming) against the same
    equations in scipy: C1.v, C2.v, L.i within 2e-3 of each signal's peak (6e-8 found;
    the two part beyond 2e-3 after 8785 s, chaos amplifying the integration errors)."""
    from acausal.models import ChuaCircuit
    t = np.linspace(0.0, 2000.0, 2001)
    res = acausal.compile(ChuaCircuit()).simulate(2000.0, t=t, rtol=1e-10, atol=1e-12)
    at = np.searchsorted(res.t, t, side="right") - 1
    ref = chua_by_hand(t)
    for name, y in ref.items():
        err = np.max(np.abs(res[name][at] - y)) / np.max(np.abs(y))
        assert err < 2e-3, (name, err)


def test_chua_circuit_matches_the_msl_reference(reference_result):
    """MSL's ChuaCircuit against the Modelica Association's reference (its comparisonSignals
    C1.v, C2.v, L.i), within 2e-3 of each signal's peak, over the first T_AGREE = 2000 s of
    the reference's 50000 s only: the circuit is chaotic, and two correct solutions part
    once their integration errors have grown. The reference was computed with DASSL at a
    tolerance of 1e-6: scipy's BDF and LSODA at 1e-6 leave the 2e-3 band around a 1e-12
    solution after 3650 s and 3720 s (acausal at 1e-10 after 8785 s), so 2000 s is where
    agreement can be asked for. Not run against the data yet (its file was not available
    when this test was written)."""
    from acausal.models import ChuaCircuit
    ref = reference_result("MAP-LIB_ReferenceResults",
                           "Modelica.Electrical.Analog.Examples.ChuaCircuit")
    t = ref["time"][ref["time"] <= T_AGREE]
    res = acausal.compile(ChuaCircuit()).simulate(float(t[-1]), t=t, rtol=1e-10, atol=1e-12)
    at = np.searchsorted(res.t, t, side="right") - 1
    for name in ("C1.v", "C2.v", "L.i"):
        y = ref[name][:len(t)]
        err = np.max(np.abs(res[name][at] - y)) / np.max(np.abs(y))
        assert err < 2e-3, (name, err)


T_AGREE = 2000.0      # [s] see test_chua_circuit_matches_the_msl_reference


def test_switching_elements_refuse_smooth_compilation():
    with pytest.raises(acausal.StructureError, match="IdealDiode.*no smooth form"):
        acausal.compile(rectifier(), smooth=True)


def test_limited_op_amp_inverts_and_clips_at_its_supply():
    """Inverting amplifier (gain −Rf/Rin) on a sine, supplied with ±Vs, driving an RC load:
    out = clip(−Rf/Rin·vs, −Vs, Vs), and C·vc' = (out − vc)/RL against scipy."""
    A, f, Rin, Rf, Vs, RL, C = 2.0, 5.0, 1e3, 5e3, 6.0, 1e3, 2e-5
    m = model("amplifier", lambda m: [
        (m.src.p, m.rin.p), (m.rin.n, m.op.in_n), (m.op.in_n, m.rf.p), (m.rf.n, m.op.out),
        (m.op.in_p, m.ground.p), (m.op.VMax, m.vmax.p), (m.op.VMin, m.vmin.n),
        (m.vmax.n, m.ground.p), (m.vmin.p, m.ground.p), (m.src.n, m.ground.p),
        (m.op.out, m.rl.p), (m.rl.n, m.c.p), (m.c.n, m.ground.p)],
        src=el.SineVoltage(V=A, f=f), rin=el.Resistor(R=Rin), rf=el.Resistor(R=Rf),
        op=el.IdealOpAmpLimited(), vmax=el.ConstantVoltage(V=Vs), vmin=el.ConstantVoltage(V=Vs),
        rl=el.Resistor(R=RL), c=el.Capacitor(C=C), ground=el.Ground())
    t = np.linspace(0.0, 0.4, 401)
    res = acausal.compile(m).simulate(0.4, t=t, rtol=1e-10, atol=1e-12)
    out = np.clip(-Rf / Rin * A * np.sin(2 * np.pi * f * t), -Vs, Vs)
    np.testing.assert_allclose(res["op.out.v"], out, atol=1e-8)
    assert np.max(np.abs(res["op.vin"][np.abs(out) < Vs - 1e-3])) < 1e-9   # nullor
    assert np.isclose(np.max(res["op.out.v"]), Vs) and np.isclose(np.min(res["op.out.v"]), -Vs)

    def rhs(tt, x):
        o = np.clip(-Rf / Rin * A * np.sin(2 * np.pi * f * tt), -Vs, Vs)
        return [(o - x[0]) / (RL * C)]
    vc = solve_ivp(rhs, (0.0, 0.4), [0.0], t_eval=t, rtol=1e-12, atol=1e-13,
                   method="DOP853", max_step=1e-4).y[0]
    np.testing.assert_allclose(res["c.v"], vc, atol=1e-7)
