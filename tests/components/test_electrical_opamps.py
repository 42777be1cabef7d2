"""Operational amplifiers (Modelica.Electrical.Analog.Basic.OpAmp, Ideal.IdealOpAmp3Pin,
OpAmpLimited, IdealizedOpAmpLimited), the SupplyVoltage and the sources with variable
frequency and amplitude, against closed forms (amplifier gains, saturation at the supply,
an integrator, a follower's first-order rise), root-finding of MSL's characteristics written
here, solve_ivp of the phase, and energy balances."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

import acausal
from acausal.components import electrical as el
from acausal.components import signals as sg
from acausal.errors import ParameterError, SimulationError
from wiring import model

TIGHT = {"rtol": 1e-10, "atol": 1e-12}
A, F, RIN, RF, RL = 2.0, 5.0, 1e3, 5e3, 2e3
W = 2 * math.pi * F


def inverting(op, Vps=6.0, Vns=-5.0):
    """Inverting amplifier: SineVoltage (A, F) → Rin → in_n, Rf from in_n to out, in_p
    grounded, load RL from out to ground; the amplifier supplied by a SupplyVoltage
    (Vps, Vns) through its pins VMax/VMin or s_p/s_n, whichever it has."""
    def pairs(m):
        out = [(m.src.p, m.rin.p), (m.rin.n, m.op.in_n), (m.op.in_n, m.rf.p),
               (m.rf.n, m.op.out), (m.op.in_p, m.ground.p), (m.src.n, m.ground.p),
               (m.op.out, m.rl.p), (m.rl.n, m.ground.p), (m.supply.ground, m.ground.p)]
        if isinstance(op, (el.OpAmp, el.IdealOpAmpLimited)):
            out += [(m.op.VMax, m.supply.pin_p), (m.op.VMin, m.supply.pin_n)]
        elif getattr(op, "useSupply", False):
            out += [(m.op.s_p, m.supply.pin_p), (m.op.s_n, m.supply.pin_n)]
        return out
    return model("inverting", pairs, src=el.SineVoltage(V=A, f=F), rin=el.Resistor(R=RIN),
                 rf=el.Resistor(R=RF), op=op, rl=el.Resistor(R=RL),
                 supply=el.SupplyVoltage(Vps=Vps, Vns=Vns), ground=el.Ground())


def finite_gain(V0):
    """The inverting amplifier's gain with an amplifier of gain V0: −(Rf/Rin)/(1 + (1 +
    Rf/Rin)/V0) (vin = −(vs·Rf + out·Rin)/(Rin + Rf), out = V0·vin)."""
    return -(RF / RIN) / (1 + (1 + RF / RIN) / V0)


@pytest.mark.parametrize("make", [
    lambda: el.OpAmpLimited(Vps=6.0, Vns=-5.0),
    lambda: el.OpAmpLimited(useSupply=True),
    lambda: el.IdealizedOpAmpLimited(Vps=6.0, Vns=-5.0),
    lambda: el.IdealizedOpAmpLimited(useSupply=True, strict=False)],
    ids=["OpAmpLimited", "OpAmpLimited-supply", "Idealized", "Idealized-events"])
def test_inverting_amplifier_has_its_finite_gain_and_saturates_at_the_supply(make):
    """out = clip(g·vs, Vns, Vps), g the finite-gain closed form; with events the
    saturation starts where g·vs reaches a limit (arcsin); the amplifier is lossless: the
    sine and the supply deliver what the three resistors dissipate."""
    op = make()
    t = np.linspace(0.0, 0.4, 401)
    res = acausal.compile(inverting(op)).simulate(0.4, t=t, **TIGHT)
    g = finite_gain(15000.0)
    vs = A * np.sin(W * res.t)
    np.testing.assert_allclose(res["op.out.v"], np.clip(g * vs, -5.0, 6.0), atol=1e-9)
    assert res["op.v_out"].max() == pytest.approx(6.0, abs=1e-9)
    assert res["op.v_out"].min() == pytest.approx(-5.0, abs=1e-9)
    if op._events():
        first = [ev.time for ev in res.events if "op.region" in ev.modes][:2]
        theta = math.asin(5.0 / (A * abs(g)))                # g < 0: the lower limit first
        np.testing.assert_allclose(first, [theta / W, (math.pi - theta) / W], atol=1e-9)
    supplied = (res["supply.pin_p.v"] * -res["supply.pin_p.i"]
                + res["supply.pin_n.v"] * -res["supply.pin_n.i"])
    delivered = res["src.v"] * -res["src.i"] + (supplied if op.useSupply else -res["op.p_out"])
    heat = sum(res[f"{r}.v"] * res[f"{r}.i"] for r in ("rin", "rf", "rl"))
    np.testing.assert_allclose(delivered, heat, atol=1e-9)
    np.testing.assert_allclose(res["op.p_s"], -res["op.p_out"], atol=1e-12)


def test_opamp_limited_in_smooth_form_rounds_the_saturation_within_v_smooth():
    """compile(smooth=True): no modes; within v_smooth/2 of the clipped closed form (the
    feedback hides the rounding below the limits: the error is largest in saturation)."""
    op = el.OpAmpLimited(Vps=6.0, Vns=-5.0, v_smooth=1e-2)
    t = np.linspace(0.0, 0.4, 401)
    compiled = acausal.compile(inverting(op), smooth=True)
    assert not compiled.has_events
    res = compiled.simulate(0.4, t=t, **TIGHT)
    err = res["op.out.v"] - np.clip(finite_gain(15000.0) * A * np.sin(W * t), -5.0, 6.0)
    assert np.abs(err).max() <= 0.5e-2


def test_basic_opamp_follows_msl_characteristic_in_a_non_inverting_amplifier():
    """Non-inverting amplifier (vs on in_p, divider R1 = 1 kΩ, R2 = 9 kΩ from out to in_n,
    VMax/VMin from a ±12 V supply): out.v solves out = (VMax + VMin)/2 + S·vin/(1 +
    S·|f·vin|), vin = vs − out·R1/(R1 + R2), f = 2/(VMax − VMin) (brentq); for a large
    input it approaches the supply without reaching it."""
    S, R1, R2, Vp, Vn = 2000.0, 1e3, 9e3, 12.0, -12.0
    m = model("noninverting", lambda m: [
        (m.src.p, m.op.in_p), (m.op.in_n, m.r1.p), (m.r1.n, m.ground.p), (m.op.in_n, m.r2.p),
        (m.r2.n, m.op.out), (m.op.VMax, m.supply.pin_p), (m.op.VMin, m.supply.pin_n),
        (m.supply.ground, m.ground.p), (m.src.n, m.ground.p)],
        src=el.SineVoltage(V=3.0, f=F), op=el.OpAmp(Slope=S), r1=el.Resistor(R=R1),
        r2=el.Resistor(R=R2), supply=el.SupplyVoltage(Vps=Vp, Vns=Vn), ground=el.Ground())
    t = np.linspace(0.0, 0.2, 201)
    res = acausal.compile(m).simulate(0.2, t=t, **TIGHT)
    beta, f = R1 / (R1 + R2), 2 / (Vp - Vn)

    def out(vs):
        law = lambda o: (Vp + Vn) / 2 + S * (vs - beta * o) / (1 + S * abs(f * (vs - beta * o)))
        return brentq(lambda o: o - law(o), 2 * Vn, 2 * Vp, xtol=1e-14)
    ref = np.array([out(v) for v in 3.0 * np.sin(W * t)])
    np.testing.assert_allclose(res["op.out.v"], ref, atol=1e-9)
    assert 11.0 < ref.max() < Vp and Vn < ref.min() < -11.0
    np.testing.assert_allclose(res["supply.pin_p.i"], 0.0, atol=1e-15)   # no supply current


@pytest.mark.parametrize("op, gain", [
    (el.IdealOpAmp3Pin(), 10.0), (el.OpAmpLimited(V0=500.0), 10.0 / (1 + 10.0 / 500.0))],
    ids=["IdealOpAmp3Pin", "OpAmpLimited"])
def test_non_inverting_amplifier_gain(op, gain):
    """vs on in_p, divider R1 = 1 kΩ (in_n to ground), R2 = 9 kΩ (out to in_n): out = (1 +
    R2/R1)·vs, with gain V0: (1 + R2/R1)/(1 + (1 + R2/R1)/V0); below the ±15 V supply."""
    m = model("noninverting", lambda m: [
        (m.src.p, m.op.in_p), (m.op.in_n, m.r1.p), (m.r1.n, m.ground.p), (m.op.in_n, m.r2.p),
        (m.r2.n, m.op.out), (m.src.n, m.ground.p)],
        src=el.SineVoltage(V=1.2, f=F), op=op, r1=el.Resistor(R=1e3), r2=el.Resistor(R=9e3),
        ground=el.Ground())
    t = np.linspace(0.0, 0.2, 201)
    res = acausal.compile(m).simulate(0.2, t=t, **TIGHT)
    np.testing.assert_allclose(res["op.out.v"], gain * 1.2 * np.sin(W * t), atol=1e-10)


def test_ideal_opamp_3pin_integrator_is_the_closed_form():
    """Inverting integrator: vs → R → in_n, C from in_n to out: out = −∫vs/(R·C) =
    A/(R·C·ω)·(cos ωt − 1); the input pins carry no current, in_n is a virtual ground."""
    R, C = 1e3, 1e-5
    m = model("integrator", lambda m: [
        (m.src.p, m.r.p), (m.r.n, m.op.in_n), (m.op.in_n, m.c.p), (m.c.n, m.op.out),
        (m.op.in_p, m.ground.p), (m.src.n, m.ground.p)],
        src=el.SineVoltage(V=A, f=F), r=el.Resistor(R=R), c=el.Capacitor(C=C),
        op=el.IdealOpAmp3Pin(), ground=el.Ground())
    t = np.linspace(0.0, 0.4, 401)
    res = acausal.compile(m).simulate(0.4, t=t, **TIGHT)
    np.testing.assert_allclose(res["op.out.v"], A / (R * C * W) * (np.cos(W * t) - 1),
                               atol=1e-8)
    np.testing.assert_allclose(res["op.in_n.v"], 0.0, atol=1e-12)
    np.testing.assert_allclose(res["op.in_n.i"], 0.0, atol=0)
    np.testing.assert_allclose(res["r.i"], A * np.sin(W * t) / R, atol=1e-12)


def follower(op, vs=2.0, start=1e-4):
    """Voltage follower: StepVoltage (vs at ``start``) on in_p, out joined to in_n, a load."""
    return model("follower", lambda m: [
        (m.src.p, m.op.in_p), (m.op.out, m.op.in_n), (m.op.out, m.rl.p), (m.rl.n, m.ground.p),
        (m.src.n, m.ground.p)],
        src=el.StepVoltage(V=vs, startTime=start), op=op, rl=el.Resistor(R=RL),
        ground=el.Ground())


def test_opamp_limited_first_order_rise_of_a_follower():
    """useFirstOrder: Tau·v_int' = V0·(vs − v_int) − v_int for the follower: from 0 (Linear
    initialization at vs = 0) to V0/(V0 + 1)·vs with the time constant Tau/(V0 + 1)."""
    V0, Tau, vs, t0 = 100.0, 1e-3, 2.0, 1e-4
    t = np.linspace(0.0, 1e-4 + 5e-5, 301)
    res = acausal.compile(follower(el.OpAmpLimited(V0=V0, Tau=Tau, useFirstOrder=True),
                                   vs, t0)).simulate(t[-1], t=t, **TIGHT)
    tau = Tau / (V0 + 1)
    ref = np.where(res.t < t0, 0.0, V0 / (V0 + 1) * vs * (1 - np.exp(-(res.t - t0) / tau)))
    np.testing.assert_allclose(res["op.v_out"], ref, atol=1e-9)


def test_opamp_limited_first_order_starts_at_the_upper_limit():
    """initOpAmp = UpperLimit: v_int(0) = Vps = 15 V, then v_int' = −(V0 + 1)·v_int/Tau
    while vs = 0 (out = v_int below the limit): v_int = 15·exp(−(V0 + 1)·t/Tau)."""
    V0, Tau = 100.0, 1e-3
    op = el.OpAmpLimited(V0=V0, Tau=Tau, useFirstOrder=True,
                         initOpAmp=el.InitOpAmp.UpperLimit)
    t = np.linspace(0.0, 5e-5, 101)
    res = acausal.compile(follower(op, start=1.0)).simulate(t[-1], t=t, **TIGHT)
    np.testing.assert_allclose(res["op.v_int"], 15.0 * np.exp(-(V0 + 1) * res.t / Tau),
                               atol=1e-8)


def test_opamp_supply_errors_name_the_amplifier():
    with pytest.raises(ParameterError, match="OpAmpLimited 'amp'.*Vps.*Vns"):
        el.OpAmpLimited("amp", Vps=-1.0, Vns=1.0)
    with pytest.raises(ParameterError, match="IdealizedOpAmpLimited.*Vps"):
        el.IdealizedOpAmpLimited(Vps=0.0, Vns=0.0)
    with pytest.raises(ParameterError, match="InitOpAmp"):
        el.OpAmpLimited(initOpAmp="Middle")
    # supplied through its pins, the supply is checked while simulating
    with pytest.raises(SimulationError, match="op.*supply voltages are not consistent"):
        acausal.compile(inverting(el.OpAmpLimited(useSupply=True), Vps=-1.0, Vns=1.0)
                        ).simulate(0.01)


# ---- sources with variable frequency and amplitude, SupplyVoltage -------------------------
def _fm(t):
    return 30.0 + 10.0 * t                                      # f = 30 Hz + 10 Hz/s·t


def _am(t):
    return 1.0 + 0.5 * t                                        # amplitude ramp


@pytest.mark.parametrize("cls, wave", [
    (el.SineVoltageVariableFrequencyAndAmplitude, np.sin),
    (el.CosineVoltageVariableFrequencyAndAmplitude, np.cos),
    (el.SineCurrentVariableFrequencyAndAmplitude, np.sin),
    (el.CosineCurrentVariableFrequencyAndAmplitude, np.cos)],
    ids=["sine-voltage", "cosine-voltage", "sine-current", "cosine-current"])
def test_variable_frequency_and_amplitude_sources(cls, wave):
    """value = offset + a(t)·wave(phi), phi = phi_start + 2π·∫f: a chirp on a resistor
    (phi by its closed form 2π·(30·t + 5·t²)); a voltage source sets v, a current source
    sends i from p through itself to n."""
    current = "Current" in cls.__name__
    amplitude = "I" if current else "V"
    m = model("chirp", lambda m: [
        (m.src.p, m.r.p), (m.r.n, m.src.n), (m.src.n, m.ground.p),
        (m.fr.y, m.src.f), (m.am.y, getattr(m.src, amplitude))],
        src=cls(offset=0.5, phi_start=0.2), r=el.Resistor(R=2.0),
        fr=sg.Ramp(height=10.0, duration=1.0, offset=30.0),
        am=sg.Ramp(height=0.5, duration=1.0, offset=1.0), ground=el.Ground())
    t = np.linspace(0.0, 1.0, 1001)
    res = acausal.compile(m).simulate(1.0, t=t, **TIGHT)
    phi = 0.2 + 2 * math.pi * (30.0 * t + 5.0 * t ** 2)
    np.testing.assert_allclose(res["src.phi"], phi, atol=1e-7)
    value = 0.5 + _am(t) * wave(phi)
    np.testing.assert_allclose(res["src.i" if current else "src.v"], value, atol=1e-7)
    np.testing.assert_allclose(res["r.i"], -value if current else value / 2.0,
                               atol=1e-7)


def test_variable_frequency_source_with_constant_options_against_scipy():
    """useConstantAmplitude and useConstantFrequency: the inputs are absent and the
    parameters act; through an RL load the current solves L·i' = v − R·i (solve_ivp)."""
    src = el.CosineVoltageVariableFrequencyAndAmplitude(
        useConstantAmplitude=True, constantAmplitude=3.0, useConstantFrequency=True,
        constantFrequency=50.0)
    assert "V" not in src.ports and "f" not in src.ports
    R, L = 5.0, 0.02
    m = model("rl", lambda m: [(m.src.p, m.r.p), (m.r.n, m.l.p), (m.l.n, m.src.n),
                               (m.src.n, m.ground.p)],
              src=src, r=el.Resistor(R=R), l=el.Inductor(L=L), ground=el.Ground())
    t = np.linspace(0.0, 0.1, 501)
    res = acausal.compile(m).simulate(0.1, t=t, **TIGHT)
    ref = solve_ivp(lambda tt, x: [(3.0 * math.cos(2 * math.pi * 50 * tt) - R * x[0]) / L],
                    (0, 0.1), [0.0], t_eval=t, rtol=1e-12, atol=1e-14, method="DOP853").y[0]
    np.testing.assert_allclose(res["l.i"], ref, atol=1e-8)


def test_supply_voltage_sets_both_rails_and_returns_the_currents_through_ground():
    """Loads from each rail to ground: pin_p.v − ground.v = Vps, pin_n.v − ground.v = Vns;
    ground returns the sum; i_p, i_n are the two supplies' currents (MSL's sign)."""
    m = model("rails", lambda m: [
        (m.supply.pin_p, m.rp.p), (m.rp.n, m.ground.p), (m.supply.pin_n, m.rn.n),
        (m.rn.p, m.ground.p), (m.supply.ground, m.ground.p), (m.ground.p, m.c.p),
        (m.c.n, m.rc.p), (m.rc.n, m.supply.pin_p)],
        supply=el.SupplyVoltage(Vps=12.0, Vns=-5.0), rp=el.Resistor(R=4.0),
        rn=el.Resistor(R=10.0), c=el.Capacitor(C=1e-3), rc=el.Resistor(R=1e3),
        ground=el.Ground())
    res = acausal.compile(m).simulate(1.0, t=[0.0, 1.0], **TIGHT)
    np.testing.assert_allclose(res["supply.pin_p.v"], 12.0, atol=1e-12)
    np.testing.assert_allclose(res["supply.pin_n.v"], -5.0, atol=1e-12)
    np.testing.assert_allclose(res["rp.i"], 3.0, atol=1e-12)
    np.testing.assert_allclose(res["rn.i"], 0.5, atol=1e-12)
    ic = 12.0 / 1e3 * np.exp(-res.t)                  # the RC between ground and the rail
    np.testing.assert_allclose(res["supply.i_p"], 3.0 + ic, atol=1e-9)
    np.testing.assert_allclose(res["supply.i_n"], 0.5, atol=1e-12)
    np.testing.assert_allclose(res["supply.ground.i"], -(res["supply.pin_p.i"]
                                                         + res["supply.pin_n.i"]), atol=1e-15)
