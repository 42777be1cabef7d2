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
    VTM, IH, ITM, VGT, IGT = 1.7, 6e-3, 25.0, 0.7, 5e-3
    TON, TOFF, Vt, Nbv = 1e-6, 15e-6, 0.04, 0.74
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
    above −VRRM, where V < VRRM keeps it), the holding mode switched where iA crosses IH
    (an event of solve_ivp).
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


# ---- MOSFETs ------------------------------------------------------------------------------
def nmos_drain_current(vD, vG, vS, vB, W=20e-6, L=6e-6, Beta=0.041e-3, Vt=0.8, K2=1.144,
                       K5=0.7311, dW=-2.5e-6, dL=-1.5e-6, RDS=1e7):
    """D.i of MSL's Semiconductors.NMOS, its equations as written there."""
    gds = 1 / RDS
    v = Beta * (W + dW) / (L + dL)
    ud = vS if vD < vS else vD
    us = vD if vD < vS else vS
    uds = ud - us
    ubs = 0 if vB > us else vB - us
    ugst = (vG - us - Vt + K2 * ubs) * K5
    if ugst <= 0:
        i = uds * gds
    elif ugst > uds:
        i = v * uds * (ugst - uds / 2) + uds * gds
    else:
        i = v * ugst * ugst / 2 + uds * gds
    return -i if vD < vS else i


def pmos_drain_current(vD, vG, vS, vB, W=20e-6, L=6e-6, Beta=0.0105e-3, Vt=-1.0, K2=0.41,
                       K5=0.839, dW=-2.5e-6, dL=-2.1e-6, RDS=1e7):
    """D.i of MSL's Semiconductors.PMOS, its equations as written there."""
    gds = 1 / RDS
    v = Beta * (W + dW) / (L + dL)
    ud = vS if vD > vS else vD
    us = vD if vD > vS else vS
    uds = ud - us
    ubs = 0 if vB < us else vB - us
    ugst = (vG - us - Vt + K2 * ubs) * K5
    if ugst >= 0:
        i = uds * gds
    elif ugst < uds:
        i = -v * uds * (ugst - uds / 2) + uds * gds
    else:
        i = -v * ugst * ugst / 2 + uds * gds
    return -i if vD > vS else i


def test_cmos_inverter_transfer_curve_matches_msl_equations():
    """CMOS inverter (PMOS from Vdd = 5 V, NMOS to ground, gates on a ramp 0 → 5 V, drains
    the output, 1 MΩ load): the output solves NMOS.D.i + PMOS.D.i + vout/1 MΩ = 0 with
    MSL's equations (brentq); high for a low input, low for a high one, the switching
    threshold between; no gate current; the supply delivers what the transistors and the
    load dissipate."""
    from scipy.optimize import brentq
    Vdd, RL = 5.0, 1e6
    m = model("inverter", lambda m: [
        (m.vdd.p, m.pmos.S), (m.vdd.p, m.pmos.B), (m.pmos.D, m.out.p), (m.nmos.D, m.out.p),
        (m.nmos.S, m.ground.p), (m.nmos.B, m.ground.p), (m.vin.p, m.nmos.G),
        (m.vin.p, m.pmos.G), (m.out.n, m.ground.p), (m.vdd.n, m.ground.p),
        (m.vin.n, m.ground.p)],
        vdd=el.ConstantVoltage(V=Vdd), pmos=el.PMOS(), nmos=el.NMOS(), out=el.Resistor(R=RL),
        vin=el.RampVoltage(V=Vdd, duration=1.0), ground=el.Ground())
    t = np.linspace(0.0, 1.0, 201)
    res = acausal.compile(m).simulate(1.0, t=t, **TIGHT)
    vin = Vdd * t

    def vout(u):
        return brentq(lambda o: nmos_drain_current(o, u, 0.0, 0.0)
                      + pmos_drain_current(o, u, Vdd, Vdd) + o / RL, -1.0, Vdd + 1.0,
                      xtol=1e-14)
    ref = np.array([vout(u) for u in vin])
    np.testing.assert_allclose(res["out.v"], ref, atol=1e-8)
    assert ref[0] > 4.9 and ref[-1] < 0.1
    np.testing.assert_allclose(res["nmos.G.i"], 0.0, atol=0)
    supplied = -res["vdd.i"] * Vdd
    dissipated = res["nmos.LossPower"] + res["pmos.LossPower"] + res["out.v"] ** 2 / RL
    np.testing.assert_allclose(supplied, dissipated, atol=1e-12)


@pytest.mark.parametrize("cls, kw", [(el.NMOS, {}), (el.PMOS, {})], ids=["NMOS", "PMOS"])
def test_mosfet_drain_characteristic_in_every_region_and_direction(cls, kw):
    """Drain voltage swept through ±6 V at three gate voltages, the bulk below the source
    (NMOS) or above it (PMOS), the source at 1 V: D.i against MSL's equations, reverse
    operation (D below S for the NMOS) included; the temperature dependence at T_heatPort
    = 350 K from a FixedTemperature against the same equations with MSL's beta_t, vt_t,
    k2_t."""
    from acausal.components import thermal as th
    sign = 1 if cls is el.NMOS else -1
    law = nmos_drain_current if cls is el.NMOS else pmos_drain_current
    defaults = {k: p.default for k, p in cls.parameters().items()}
    for temperature in (None, 350.0):
        for vg in (0.5, 2.5, 4.0):
            params = dict(useTemperatureDependency=True) if temperature else {}
            dev = cls(**params)
            m = model("sweep", lambda m: [
                (m.vd.p, m.dev.D), (m.vg.p, m.dev.G), (m.vs.p, m.dev.S), (m.vb.p, m.dev.B)]
                + [(s.n, m.ground.p) for s in (m.vd, m.vg, m.vs, m.vb)]
                + ([(m.dev.heatPort, m.fixed.port)] if temperature else []),
                vd=el.RampVoltage(V=12.0, offset=-6.0, duration=1.0),
                vg=el.ConstantVoltage(V=1.0 + sign * vg), vs=el.ConstantVoltage(V=1.0),
                vb=el.ConstantVoltage(V=1.0 - sign * 0.5), dev=dev, ground=el.Ground(),
                **({"fixed": th.FixedTemperature(T=temperature)} if temperature else {}))
            t = np.linspace(0.0, 1.0, 121)
            res = acausal.compile(m).simulate(1.0, t=t, **TIGHT)
            scaled = {}
            if temperature:
                dT = temperature - defaults["Tnom"]
                scaled = dict(Beta=defaults["Beta"] * (temperature / defaults["Tnom"]) ** -1.5,
                              Vt=defaults["Vt"] * (1 + dT * defaults["kvt"]),
                              K2=defaults["K2"] * (1 + dT * defaults["kk2"]))
            ref = [law(-6.0 + 12.0 * tt, 1.0 + sign * vg, 1.0, 1.0 - sign * 0.5, **scaled)
                   for tt in t]
            np.testing.assert_allclose(res["dev.D.i"], ref, rtol=1e-10, atol=1e-15)
            np.testing.assert_allclose(res["dev.S.i"], -np.array(ref), rtol=1e-10,
                                       atol=1e-15)


def test_mosfet_refuses_a_non_positive_effective_size():
    with pytest.raises(ParameterError, match="NMOS 'q'.*effective length"):
        el.NMOS("q", L=1e-6)
    with pytest.raises(ParameterError, match="PMOS.*effective width"):
        el.PMOS(W=2e-6)


# ---- Diode2 -------------------------------------------------------------------------------
def diode2_current(v, Vt, Vf=0.7, Ids=1e-13, Rs=16.0, N=1.0, Bv=100.0, Gp=1e-6):
    """i of MSL's Semiconductors.Diode2 at the voltage v: vd from v = vd + id(vd)·Rs
    (brentq), then i = id + v·Gp, its equations as written there."""
    from scipy.optimize import brentq
    VdMax = Vf + N * Vt
    iVdMax = Ids * (math.exp(VdMax / (N * Vt)) - 1)
    diVdMax = Ids * math.exp(VdMax / (N * Vt)) / (N * Vt)

    def i_d(vd):
        if vd < -Bv / 2:
            return -Ids * (math.exp(-(vd + Bv) / (N * Vt)) + 1 - 2 * math.exp(-Bv / (2 * N * Vt)))
        if vd < VdMax:
            return Ids * (math.exp(vd / (N * Vt)) - 1)
        return iVdMax + (vd - VdMax) * diVdMax
    vd = brentq(lambda u: u + i_d(u) * Rs - v, min(v, -Bv), max(v, 1.0), xtol=1e-15)
    return i_d(vd) + v * Gp


@pytest.mark.parametrize("temperature", [None, 330.0], ids=["Vt", "heatPort"])
def test_diode2_characteristic_from_breakdown_to_the_linear_continuation(temperature):
    """The voltage across Diode2 ramped from −104 V (past the breakdown Bv = 100 V) to
    1.4 V (past VdMax): i against MSL's equations (vd by brentq); Vt = k·T/q at T = 293.15
    K by MSL's binding, or k·T_heatPort/q with a heat port at 330 K."""
    from acausal.components import thermal as th
    params = {"useHeatPort": True} if temperature else {}
    m = model("d2", lambda m: [(m.src.p, m.d.p), (m.d.n, m.src.n), (m.src.n, m.ground.p)]
              + ([(m.d.heatPort, m.fixed.port)] if temperature else []),
              src=el.RampVoltage(V=105.4, offset=-104.0, duration=1.0), d=el.Diode2(**params),
              ground=el.Ground(),
              **({"fixed": th.FixedTemperature(T=temperature)} if temperature else {}))
    t = np.linspace(0.0, 1.0, 301)
    res = acausal.compile(m).simulate(1.0, t=t, **TIGHT)
    Vt = 1.380649e-23 * (temperature or 293.15) / 1.602176634e-19
    ref = np.array([diode2_current(v, Vt) for v in -104.0 + 105.4 * t])
    np.testing.assert_allclose(res["d.i"], ref, rtol=1e-8, atol=1e-15)
    assert ref[0] < -1e-3 and ref[-1] > 0.03                  # breakdown, conducting
    np.testing.assert_allclose(res["d.LossPower"], res["d.v"] * res["d.i"], rtol=1e-12)
    if not temperature:
        assert el.Diode2().Vt == pytest.approx(Vt, rel=1e-15)
        assert el.Diode2(Vt=0.03).Vt == 0.03


# ---- bipolar transistors ------------------------------------------------------------------
def exlin2(x, lo=-100.0, hi=40.0):
    """MSL's Semiconductors.exlin2 (as written there)."""
    if x < lo:
        return math.exp(lo) * (1 + x - lo)
    return math.exp(hi) * (1 + x - hi) if x > hi else math.exp(x)


def powlin(x, y):
    """MSL's Semiconductors.powlin (as written there)."""
    return 1 + y * x if x > 0 else (1 - x) ** (-y)


BJT = dict(Bf=50.0, Br=0.1, Is=1e-16, Vak=0.02, Tauf=0.12e-9, Taur=5e-9, Ccs=1e-12,
           Cje=0.4e-12, Cjc=0.5e-12, Phie=0.8, Me=0.4, Phic=0.8, Mc=0.333, Gbc=1e-15,
           Gbe=1e-15, Vt=0.02585, NF=1.0, NR=1.0)               # MSL's NPN and PNP defaults
VCC, RC, RB, RE = 10.0, 1e3, 1e4, 10.0


def vin(t):
    return 1.0 + np.sin(2 * np.pi * 100.0 * t)


def stage_by_hand(kind, t_out):
    """A common-emitter stage (Vcc = 10 V through Rc = 1 kΩ to the collector, vin = 1 +
    sin(2π·100·t) V through Rb = 10 kΩ to the base, the emitter through Re = 10 Ω to
    ground, the substrate grounded) — for the PNP every potential negated — integrated in
    MSL's states (vbc, vbe, vcs; vcb, veb, vcs) by LSODA, with MSL's equations of the NPN
    or the PNP as written in the .mo files, the three capacitive currents solved from the
    pin currents the resistors give. Returns the collector potential at t_out."""
    p = BJT
    s = 1.0 if kind == "NPN" else -1.0

    def rhs(t, x):
        vj_c, vj_e, vcs = x                      # NPN: vbc, vbe; PNP: vcb, veb
        vC = vcs                                  # vS = 0
        vB = vC + s * vj_c
        vE = vB - s * vj_e
        iC = (s * VCC - vC) / RC                  # the pin currents from the resistors
        iB = (s * vin(t) - vB) / RB
        iE = -vE / RE
        ic = p["Is"] * (exlin2(vj_c / (p["NR"] * p["Vt"])) - 1) + vj_c * p["Gbc"]
        ie = p["Is"] * (exlin2(vj_e / (p["NF"] * p["Vt"])) - 1) + vj_e * p["Gbe"]
        cc = (p["Taur"] * p["Is"] / (p["NR"] * p["Vt"]) * exlin2(vj_c / (p["NR"] * p["Vt"]))
              + p["Cjc"] * powlin(vj_c / p["Phic"], p["Mc"]))
        ce = (p["Tauf"] * p["Is"] / (p["NF"] * p["Vt"]) * exlin2(vj_e / (p["NF"] * p["Vt"]))
              + p["Cje"] * powlin(vj_e / p["Phie"], p["Me"]))
        qbk = 1 - vj_c * p["Vak"]
        iS = -iB - iC - iE                        # E.i = −B.i − C.i − iS
        dvcs = -iS / p["Ccs"]                     # iS = −Ccs·der(vcs)
        if kind == "NPN":
            # C.i = (ibe − ibc)·qbk − ibc/Br − cbc·der(vbc) − iS
            dc = ((ie - ic) * qbk - ic / p["Br"] - iS - iC) / cc
            # B.i = ibe/Bf + ibc/Br + cbc·der(vbc) + cbe·der(vbe)
            de = (iB - ie / p["Bf"] - ic / p["Br"] - cc * dc) / ce
        else:
            # C.i = icb/Br + ccb·der(vcb) + (icb − ieb)·qbk − iS
            dc = (iC - ic / p["Br"] - (ic - ie) * qbk + iS) / cc
            # B.i = −ieb/Bf − icb/Br − ceb·der(veb) − ccb·der(vcb)
            de = (-iB - ie / p["Bf"] - ic / p["Br"] - cc * dc) / ce
        return [dc, de, dvcs]
    sol = solve_ivp(rhs, (0.0, t_out[-1]), [0.0, 0.0, 0.0], method="LSODA", t_eval=t_out,
                    rtol=1e-10, atol=1e-12, first_step=1e-15)
    return sol.y[2]


@pytest.mark.parametrize("kind", ["NPN", "PNP"])
def test_common_emitter_stage_matches_a_scipy_model_of_msl_equations(kind):
    """The collector potential of the stage over two periods of the input against the
    scipy model (including the start, where the pF junction capacitances charge within
    ns); the PNP's circuit is the NPN's with every potential negated, and so is its
    collector potential (MSL's PNP is the NPN with voltages and currents reversed); the
    stage inverts and amplifies: the collector falls as the input rises."""
    cls, s = (el.NPN, 1.0) if kind == "NPN" else (el.PNP, -1.0)
    m = model("stage", lambda m: [
        (m.vcc.p, m.rc.p), (m.rc.n, m.q.C), (m.q.E, m.re.p), (m.re.n, m.ground.p),
        (m.vcc.n, m.ground.p), (m.vin.p, m.rb.p), (m.rb.n, m.q.B), (m.vin.n, m.ground.p)],
        vcc=el.ConstantVoltage(V=s * VCC), rc=el.Resistor(R=RC), rb=el.Resistor(R=RB),
        re=el.Resistor(R=RE), q=cls(),
        vin=el.SineVoltage(V=s * 1.0, f=100.0, offset=s * 1.0), ground=el.Ground())
    t = np.linspace(0.0, 0.02, 401)
    res = acausal.compile(m).simulate(0.02, t=t, **TIGHT)
    ref = stage_by_hand(kind, t)
    np.testing.assert_allclose(res["q.C.v"], ref, atol=1e-6)
    vc = s * ref
    assert vc[np.argmax(vin(t))] < 6.0 and vc[np.argmin(vin(t[1:])) + 1] > 9.9
    if kind == "NPN":          # the active region: the collector current Bf·qbk times the base's
        k = (np.abs(vin(t) - 1.0) < 0.2) & (t > 1e-3)
        ratio = res["q.C.i"][k] / res["q.B.i"][k]
        np.testing.assert_allclose(ratio, BJT["Bf"] * res["q.qbk"][k], rtol=2e-3)


def test_grounded_emitter_closes_a_capacitor_loop_reduced_on_request():
    """With the emitter grounded (and the substrate implicitly so) the three junction
    capacitances close a loop: refused naming the transistor, and with index_reduction the
    same stage as with the emitter resistor gone (scipy: Re → 0 Ω is the limit, here
    checked against Re = 1 mΩ)."""
    def stage(re):
        return model("stage", lambda m: [
            (m.vcc.p, m.rc.p), (m.rc.n, m.q.C), (m.vcc.n, m.ground.p), (m.vin.p, m.rb.p),
            (m.rb.n, m.q.B), (m.vin.n, m.ground.p)]
            + ([(m.q.E, m.re.p), (m.re.n, m.ground.p)] if re else [(m.q.E, m.ground.p)]),
            vcc=el.ConstantVoltage(V=VCC), rc=el.Resistor(R=RC), rb=el.Resistor(R=RB),
            q=el.NPN(), vin=el.SineVoltage(V=1.0, f=100.0, offset=1.0), ground=el.Ground(),
            **({"re": el.Resistor(R=re)} if re else {}))
    with pytest.raises(acausal.StructureError, match="NPN 'q'.*index_reduction=True"):
        acausal.compile(stage(None))
    t = np.linspace(0.0, 0.01, 101)
    reduced = acausal.compile(stage(None), index_reduction=True).simulate(0.01, t=t, **TIGHT)
    near = acausal.compile(stage(1e-3)).simulate(0.01, t=t, **TIGHT)
    np.testing.assert_allclose(reduced["q.C.v"], near["q.C.v"], atol=1e-3)


@pytest.mark.parametrize("make, match", [
    (lambda: el.NPN("q", Cje=0.0), r"NPN.*Cje.*> 0"),
    (lambda: el.PNP(Ccs=-1e-12), r"PNP.*Ccs.*> 0"),
    (lambda: el.Diode2(Bv=0.0), r"Diode2.*Bv.*> 0"),
    (lambda: el.SimpleTriac("tr", VDRM=50.0, VGT=0.5), r"Thyristor.*VGT.*vRef"),
    (lambda: el.SimpleTriac("tr", Ron=1.0), r"SimpleTriac 'tr' has no parameter 'Ron'"),
    (lambda: el.IdealTriac(Goff=-1.0), r"IdealThyristor.*Goff")])
def test_bad_semiconductor_parameters_are_refused_naming_the_component(make, match):
    with pytest.raises(ParameterError, match=match):
        make()


def test_push_pull_follower_reduces_interlocking_capacitor_loops():
    """An NPN/PNP push-pull emitter follower (collectors on ±10 V, bases together through
    Rb = 1 kΩ from a 2 V, 50 Hz sine, emitters together into RL = 100 Ω): the junction
    capacitances close several loops that share states; with index_reduction each demoted
    state's rate holds the ones demoted before it (this compile ended in unresolved
    symbols). At the input's peaks (quasi-static: ns time constants at 50 Hz) the load
    voltage solves the static MSL equations of both transistors (scipy), the conducting
    one ~0.7 V below the input."""
    from scipy.optimize import brentq
    p, RL, RB_ = BJT, 100.0, 1e3
    m = model("push_pull", lambda m: [
        (m.vcc.n, m.ground.p), (m.vcc.p, m.npn.C), (m.vee.p, m.ground.p), (m.vee.n, m.pnp.C),
        (m.vin.n, m.ground.p), (m.vin.p, m.rb.p), (m.rb.n, m.npn.B), (m.rb.n, m.pnp.B),
        (m.npn.E, m.pnp.E), (m.npn.E, m.rl.p), (m.rl.n, m.ground.p)],
        vcc=el.ConstantVoltage(V=VCC), vee=el.ConstantVoltage(V=VCC), ground=el.Ground(),
        vin=el.SineVoltage(V=2.0, f=50.0), npn=el.NPN(), pnp=el.PNP(),
        rb=el.Resistor(R=RB_), rl=el.Resistor(R=RL))
    t = np.array([0.0, 0.005, 0.01, 0.015, 0.02])
    res = acausal.compile(m, index_reduction=True).simulate(0.02, t=t, **TIGHT)

    def junction(v, n):
        return p["Is"] * (exlin2(v / (n * p["Vt"])) - 1) + v * p["Gbe"]

    def pins(vB, vE):
        """(B.i, E.i) of both transistors together, static (MSL's equations)."""
        vbe, vbc = vB - vE, vB - VCC                 # NPN
        ie, ic = junction(vbe, p["NF"]), junction(vbc, p["NR"])
        nB = ie / p["Bf"] + ic / p["Br"]
        nC = (ie - ic) * (1 - vbc * p["Vak"]) - ic / p["Br"]
        veb, vcb = vE - vB, -VCC - vB                # PNP
        je, jc = junction(veb, p["NF"]), junction(vcb, p["NR"])
        pB = -je / p["Bf"] - jc / p["Br"]
        pC = jc / p["Br"] + (jc - je) * (1 - vcb * p["Vak"])
        return nB + pB, -(nB + nC) - (pB + pC)

    def base(vE, u):                                 # KCL at the bases: vB for a given vE
        return brentq(lambda vB: (u - vB) / RB_ - pins(vB, vE)[0], -5.0, 5.0, xtol=1e-15)

    for k, u in ((1, 2.0), (3, -2.0)):               # KCL at the emitters
        vE = brentq(lambda vE: pins(base(vE, u), vE)[1] + vE / RL, -3.0, 3.0, xtol=1e-15)
        assert res["rl.v"][k] == pytest.approx(vE, abs=1e-6)
        assert 0.5 < abs(u - vE) < 1.2
