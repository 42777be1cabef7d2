"""Semiconductors of Modelica.Electrical.Analog (Thyristor, SimpleTriac, Ideal.IdealTriac,
NMOS, PMOS, NPN, PNP, Diode2) against hand-written scipy models of small circuits with MSL's
equations written out here from the .mo files, closed forms and power balances.

The gate pulses have edges at times exact in binary (a 64 Hz mains, 1/1024 s steps): the
pulses' time events then fall exactly on their edges."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.components import electrical as el
from acausal.components import logical as lg
from acausal.errors import ParameterError
from wiring import model

TIGHT = {"rtol": 1e-9, "atol": 1e-11}
V, F, R = 80.0, 64.0, 10.0                    # mains amplitude [V], frequency [Hz], load [Ohm]
W = 2 * math.pi * F
START = 3 / 1024                               # firing instant [s]: 3π/8 after the zero
WIDTH = 1 / 1024                               # gate pulse [s]
IG = 0.01                                      # gate current [A]


# ---- Thyristor -----------------------------------------------------------------------------
class MSLThyristor:
    """MSL's Semiconductors.Thyristor with its default parameters, written out by hand."""
    VDRM = VRRM = 100.0
    VTM, IH, ITM, VGT, IGT, TON, TOFF, Vt, Nbv = 1.7, 6e-3, 25.0, 0.7, 5e-3, 1e-6, 15e-6, 0.04, 0.74
    Von, Voff = 5.0, 1.5
    Ron = (VTM - 0.7) / ITM
    Roff = VDRM ** 2 / VTM / IH

    def anode_current(self, vAK, vc):
        if vAK < -self.VRRM:
            return -self.VRRM / self.Roff * math.exp(-(vAK + self.VRRM) / (self.Nbv * self.Vt))
        if vc < self.Voff:
            return vAK / self.Roff
        if vc < self.Von:
            x = (2 * vc - self.Von - self.Voff) / (2 * (self.Von - self.Voff))
            return vAK / (math.sqrt(self.Ron * self.Roff)
                          * (self.Ron / self.Roff) ** ((3 * x - 4 * x ** 3) / 2))
        return vAK / self.Ron

    def control_rate(self, vc, vAK, iG, main):
        trigger = 0.95 * self.IGT
        gate = 0.0 if iG < trigger else (10000 * (iG - trigger) * vAK if iG < trigger + 1e-3
                                         else 10 * vAK)
        rise = self.Von * main + gate - vc
        return rise / (1.87 * self.TON if rise > 0 else 0.638 * self.TOFF)


def phase_control_by_hand(t_out, periods):
    """SineVoltage (V, F) → Anode; Cathode → R → ground; a gate current IG into the Gate
    during [START, START + WIDTH] of every period: the state vControl integrated by LSODA,
    the anode voltage from Kirchhoff's law vAK = vs − R·(iA + iG) (iA = vAK·G(vControl)
    above −VRRM, where V < VRRM keeps it), the holding mode switched where iA crosses IH (an event of solve_ivp).
    Returns (load current at t_out, the switching times of the mode)."""
    th = MSLThyristor()
    edges = sorted({0.0, periods / F} | {START + k / F for k in range(periods)}
                   | {START + WIDTH + k / F for k in range(periods)})

    def solve(t, vc, iG):
        vAK = (V * math.sin(W * t) - R * iG) / (1 + R * th.anode_current(1.0, vc))
        return vAK, th.anode_current(vAK, vc)

    main, vc, switches, pieces = 0, 0.0, [], []
    for a, b in zip(edges[:-1], edges[1:]):
        iG = IG if any(START + k / F <= a < START + WIDTH + k / F for k in range(periods)) \
            else 0.0
        t0 = a
        while t0 < b:
            def rhs(t, x, iG=iG, main=main):
                return [th.control_rate(x[0], solve(t, x[0], iG)[0], iG, main)]

            def holding(t, x, iG=iG):
                return solve(t, x[0], iG)[1] - th.IH
            holding.terminal = True
            holding.direction = -1 if main else 1
            sol = solve_ivp(rhs, (t0, b), [vc], method="LSODA", events=holding,
                            dense_output=True, rtol=1e-11, atol=1e-12, first_step=1e-12,
                            max_step=2e-4)
            pieces.append((t0, sol.t[-1], sol.sol, iG))
            vc, t0 = sol.y[0, -1], sol.t[-1]
            if sol.status == 1:
                switches.append(t0)
                main = 1 - main
    current = np.empty_like(t_out)
    for k, t in enumerate(t_out):
        a, b, s, iG = next(p for p in reversed(pieces) if p[0] <= t <= p[1])   # right limit
        current[k] = solve(t, s(t)[0], iG)[1] + iG            # the cathode's current
    return current, np.array(switches)


def test_thyristor_phase_control_matches_a_scipy_model_of_msl_equations():
    """Fired by a 10 mA gate pulse at 3π/8 of each period the thyristor conducts until its
    current falls below IH near the current zero; the load current and the instants the
    holding mode switches (on within ns of the pulse, off where iA = IH) against the scipy
    model; while fully on i = vs/(R + Ron), while blocking vs/(R + Roff)."""
    m = model("phase_control", lambda m: [
        (m.src.p, m.th.Anode), (m.th.Cathode, m.r.p), (m.r.n, m.ground.p),
        (m.src.n, m.ground.p), (m.gate.p, m.ground.p), (m.gate.n, m.th.Gate)],
        src=el.SineVoltage(V=V, f=F), th=el.Thyristor(), r=el.Resistor(R=R),
        gate=el.PulseCurrent(I=IG, width=100 * WIDTH * F, period=1 / F, startTime=START),
        ground=el.Ground())
    t = np.linspace(0.0, 2 / F, 513)
    res = acausal.compile(m).simulate(t[-1], t=t, **TIGHT)
    ref, switches = phase_control_by_hand(t, 2)
    mains = [ev.time for ev in res.events if "th.main" in ev.modes]
    np.testing.assert_allclose(mains, switches, atol=1e-9)
    at = np.searchsorted(res.t, t, side="right") - 1
    np.testing.assert_allclose(res["r.i"][at], ref, atol=1e-7)
    th = MSLThyristor()
    phase = np.mod(W * t, 2 * math.pi)
    on = (phase > W * (START + WIDTH) + 0.05) & (phase < math.pi - 0.05)
    vs = V * np.sin(W * t)
    np.testing.assert_allclose(res["r.i"][at][on], vs[on] / (R + th.Ron), rtol=1e-9)
    off = (phase > math.pi + 0.05) | (phase < W * START - 0.05)
    np.testing.assert_allclose(res["r.i"][at][off], vs[off] / (R + th.Roff), rtol=1e-6)
    np.testing.assert_allclose(
        res["th.LossPower"], res["th.vAK"] * res["th.Anode.i"] + res["th.vGK"] * res["th.iGK"],
        atol=1e-9)


def test_thyristor_refuses_inconsistent_parameters():
    with pytest.raises(ParameterError, match="Thyristor 'th'.*VTM"):
        el.Thyristor("th", VTM=0.5)
    with pytest.raises(ParameterError, match="Thyristor.*VGT.*vRef"):
        el.Thyristor(VGT=0.6)
    with pytest.raises(ParameterError, match="IH"):
        el.Thyristor(IH=0.0)
    with pytest.raises(acausal.StructureError, match="Thyristor.*smooth"):
        acausal.compile(model("t", lambda m: [
            (m.src.p, m.th.Anode), (m.th.Cathode, m.src.n), (m.th.Gate, m.th.Cathode),
            (m.src.n, m.ground.p)], src=el.SineVoltage(), th=el.Thyristor(),
            ground=el.Ground()), smooth=True)


# ---- triacs -------------------------------------------------------------------------------
def test_simple_triac_conducts_both_half_waves_from_the_firing_angle():
    """Gate pulses every half period: each thyristor of the triac fires at 3π/8 of its
    half-wave (within ns) and holds until its current falls below IH; fully on the load
    sees vs/(R + Ron), blocked vs/(R + Roff) (MSL's thyristor resistances); the mean of
    the load current over a period is 0, its rms that of the phase-controlled wave."""
    m = model("triac", lambda m: [
        (m.src.p, m.tr.p), (m.tr.n, m.r.p), (m.r.n, m.ground.p), (m.src.n, m.ground.p),
        (m.gate.p, m.ground.p), (m.gate.n, m.tr.g)],
        src=el.SineVoltage(V=V, f=F), tr=el.SimpleTriac(), r=el.Resistor(R=R),
        gate=el.PulseCurrent(I=0.02, width=100 * WIDTH * 2 * F, period=0.5 / F,
                             startTime=START), ground=el.Ground())
    t = np.linspace(0.0, 1 / F, 1025)
    res = acausal.compile(m).simulate(t[-1], t=t, **TIGHT)
    th = MSLThyristor()
    on_at = {name: [ev.time for ev in res.events
                    if ev.modes.get(f"tr.{name}.main", (0, 0)) == (0.0, 1.0)]
             for name in ("thyristor", "thyristor1")}
    np.testing.assert_allclose(on_at["thyristor1"], [START], atol=2e-8)     # p → n
    np.testing.assert_allclose(on_at["thyristor"], [START + 0.5 / F], atol=2e-8)
    at = np.searchsorted(res.t, t, side="right") - 1
    i, vs = res["r.i"][at], V * np.sin(W * t)
    phase = np.mod(W * t, math.pi)
    on = (phase > W * (START + WIDTH) + 0.05) & (phase < math.pi - 0.05)
    np.testing.assert_allclose(i[on], vs[on] / (R + th.Ron), rtol=1e-6)
    assert np.abs(i[phase < W * START - 0.05]).max() < 1e-3        # blocking: leakage only
    assert abs(np.trapezoid(i, t) * F) < 1e-3
    a = W * START                                        # rms of the phase-cut sine
    rms = V / (R + th.Ron) * math.sqrt((math.pi - a + math.sin(2 * a) / 2) / (2 * math.pi))
    assert math.sqrt(np.trapezoid(i ** 2, t) * F) == pytest.approx(rms, rel=2e-3)


def ideal_triac_by_hand(t_out, Ron=1e-5, Goff=1e-5, Vknee=0.8, Rdis=100.0, Cdis=0.005):
    """MSL's IdealTriac on the load R, written out: the snubber's capacitor voltage vc
    (C·vc' = (vT − vc)/Rdis) the state; vT (anode − cathode) from Kirchhoff's law, linear
    in each combination of the thyristors' modes; each IdealThyristor's characteristic
    (conducting: v = s·Ron + Vknee, i = s + Goff·Vknee; blocking: v = s + Vknee, i =
    Goff·s + Goff·Vknee), turned on where s > 0 while fired, off where s < 0 (events of
    solve_ivp); fire1 true during [START, START + WIDTH] of every half period."""
    fire_edges = sorted({START + k * 0.5 / F for k in range(4)}
                        | {START + WIDTH + k * 0.5 / F for k in range(4)})
    edges = [0.0] + [e for e in fire_edges if e < t_out[-1]] + [t_out[-1]]

    def fired(t):
        return any(START + k * 0.5 / F <= t < START + WIDTH + k * 0.5 / F for k in range(4))

    def thyristor(v, off):                   # current (from its p to n) = g·v + h
        return (Goff, 0.0) if off else (1 / Ron, Goff * Vknee - Vknee / Ron)

    def solve(t, vc, off):                    # off: (thyristor1 p→n, thyristor n→p)
        vs = V * math.sin(W * t)
        g1, h1 = thyristor(None, off[0])
        g2, h2 = thyristor(None, off[1])
        # (vs − vT)/R = g1·vT + h1 − (g2·(−vT) + h2) + (vT − vc)/Rdis
        vT = (vs / R - h1 + h2 + vc / Rdis) / (1 / R + g1 + g2 + 1 / Rdis)
        s = [(vT - Vknee) if off[0] else (g1 * vT + h1 - Goff * Vknee),
             (-vT - Vknee) if off[1] else (g2 * -vT + h2 - Goff * Vknee)]
        return vT, s

    off, vc, pieces, switches = [True, True], 0.0, [], []
    for a, b in zip(edges[:-1], edges[1:]):
        t0, fire = a, fired(a)
        _, s = solve(t0, vc, off)            # the event iteration at an edge of fire1
        new = [s[k] < 0 or (off[k] and not fire) for k in range(2)]
        switches += [(t0, k) for k in range(2) if new[k] != off[k]]
        off = new
        while t0 < b:
            def rhs(t, x, off=tuple(off)):
                return [(solve(t, x[0], off)[0] - x[0]) / (Rdis * Cdis)]
            events, which = [], []           # the crossings that switch: on while fired,
            for k in range(2):               # off while conducting
                if off[k] and not fire:
                    continue

                def ev(t, x, k=k, off=tuple(off)):
                    return solve(t, x[0], off)[1][k]
                ev.terminal, ev.direction = True, 1 if off[k] else -1
                events.append(ev)
                which.append(k)
            sol = solve_ivp(rhs, (t0, b), [vc], method="DOP853", events=events,
                            dense_output=True, rtol=1e-12, atol=1e-12)
            pieces.append((t0, sol.t[-1], sol.sol, tuple(off)))
            vc, t0 = sol.y[0, -1], sol.t[-1]
            for j, k in enumerate(which):
                if sol.status == 1 and len(sol.t_events[j]):
                    off[k] = not off[k]
                    switches.append((t0, k))
    current = np.empty_like(t_out)
    for k, t in enumerate(t_out):
        a, b, s, o = next(p for p in reversed(pieces) if p[0] <= t <= p[1])
        current[k] = (V * math.sin(W * t) - solve(t, s(t)[0], o)[0]) / R
    return current, switches


def test_ideal_triac_phase_control_matches_a_scipy_model_with_its_snubber():
    """IdealTriac fired every half period at 3π/8: the load current (through the
    thyristors and the Rdis–Cdis snubber) and the switching instants against the scipy
    model of MSL's composition; the triac turns off where its current falls below
    Goff·Vknee, before the voltage zero (the snubber takes over)."""
    m = model("ideal_triac", lambda m: [
        (m.src.p, m.tr.p), (m.tr.n, m.r.p), (m.r.n, m.ground.p), (m.src.n, m.ground.p),
        (m.pulse.y, m.tr.fire1)],
        src=el.SineVoltage(V=V, f=F), tr=el.IdealTriac(), r=el.Resistor(R=R),
        pulse=lg.BooleanPulse(width=100 * WIDTH * 2 * F, period=0.5 / F, startTime=START),
        ground=el.Ground())
    t = np.linspace(0.0, 1.5 / F, 769)
    res = acausal.compile(m).simulate(t[-1], t=t, **TIGHT)
    ref, switches = ideal_triac_by_hand(t)
    names = {0: "tr.idealThyristor1.off", 1: "tr.idealThyristor.off"}
    got = sorted((ev.time, k) for ev in res.events for k, n in names.items() if n in ev.modes)
    assert [k for _, k in got] == [k for _, k in switches]
    np.testing.assert_allclose([tt for tt, _ in got], [tt for tt, _ in switches], atol=1e-8)
    at = np.searchsorted(res.t, t, side="right") - 1
    np.testing.assert_allclose(res["r.i"][at], ref, atol=1e-6)
