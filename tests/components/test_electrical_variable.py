"""The variable and controlled elements, the coupled-inductor Transformer, the
Potentiometer and the sensors of Modelica.Electrical.Analog in small circuits, against
closed forms and MSL's equations integrated here by scipy."""
from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.components import electrical as el
from acausal.components import signals as sig
from acausal.errors import ParameterError, SimulationError
from wiring import model

TIGHT = {"rtol": 1e-11, "atol": 1e-12}
SCIPY = {"method": "DOP853", "rtol": 1e-12, "atol": 1e-13}


def scipy_solution(rhs, x0, t):
    return solve_ivp(rhs, (t[0], t[-1]), x0, t_eval=t, **SCIPY).y


def test_variable_inductor_follows_msl_flux_equation():
    """Source V·sin — R — VariableInductor with L(t) = L0 + a·t (a Ramp block): MSL's
    Psi = L·i, v = der(Psi), so der(Psi) = V·sin(ωt) − R·Psi/L(t) (not L·di/dt = v)."""
    V, w, R, L0, a = 3.0, 2 * np.pi * 2, 1.5, 0.2, 0.8
    m = model("rl", lambda m: [(m.src.p, m.r.p), (m.r.n, m.l.p), (m.l.n, m.src.n),
                               (m.src.n, m.ground.p), (m.Lt.y, m.l.L)],
              src=el.SineVoltage(V=V, f=2.0), r=el.Resistor(R=R), l=el.VariableInductor(),
              Lt=sig.Ramp(height=a, duration=1.0, offset=L0), ground=el.Ground())
    t = np.linspace(0.0, 1.0, 201)
    res = acausal.compile(m).simulate(1.0, t=t, **TIGHT)
    L = lambda s: L0 + a * s                                          # noqa: E731
    psi, = scipy_solution(lambda s, x: [V * np.sin(w * s) - R * x[0] / L(s)], [0.0], t)
    np.testing.assert_allclose(res["l.Psi"], psi, atol=1e-9)
    np.testing.assert_allclose(res["l.i"], psi / L(t), atol=1e-9)
    np.testing.assert_allclose(res["l.v"], V * np.sin(w * t) - R * psi / L(t), atol=1e-8)


def test_variable_capacitor_follows_msl_charge_equation_and_uic():
    """Source V — R — VariableCapacitor with C(t) = C0·(1 + 0.5·sin(2πt)): Q = C·v,
    i = der(Q), so der(Q) = (V − Q/C(t))/R; with UIC the start is v = IC, Q = C(0)·IC."""
    V, R, C0, IC = 2.0, 10.0, 0.05, 0.7
    m = model("rc", lambda m: [(m.src.p, m.r.p), (m.r.n, m.c.p), (m.c.n, m.src.n),
                               (m.src.n, m.ground.p), (m.Ct.y, m.c.C)],
              src=el.ConstantVoltage(V=V), r=el.Resistor(R=R),
              c=el.VariableCapacitor(IC=IC, UIC=True),
              Ct=sig.Sine(amplitude=0.5 * C0, f=1.0, offset=C0), ground=el.Ground())
    t = np.linspace(0.0, 2.0, 201)
    res = acausal.compile(m).simulate(2.0, t=t, **TIGHT)
    C = lambda s: C0 * (1 + 0.5 * np.sin(2 * np.pi * s))               # noqa: E731
    q, = scipy_solution(lambda s, x: [(V - x[0] / C(s)) / R], [C(0.0) * IC], t)
    np.testing.assert_allclose(res["c.Q"], q, atol=1e-10)
    np.testing.assert_allclose(res["c.v"], q / C(t), atol=1e-9)
    assert res["c.v"][0] == pytest.approx(IC, abs=1e-10)


def test_variable_capacitor_below_cmin_and_negative():
    """C below Cmin counts as Cmin (MSL's max(C, Cmin)); a negative C stops the run with
    MSL's assertion, naming the capacitor."""
    def circuit(C):
        return model("rc", lambda m: [(m.src.p, m.r.p), (m.r.n, m.c.p), (m.c.n, m.src.n),
                                      (m.src.n, m.ground.p), (m.Ct.y, m.c.C)],
                     src=el.ConstantVoltage(V=1.0), r=el.Resistor(R=1.0),
                     c=el.VariableCapacitor(Cmin=0.1), Ct=sig.Constant(k=C),
                     ground=el.Ground())
    t = np.linspace(0.0, 0.5, 11)
    res = acausal.compile(circuit(0.01)).simulate(0.5, t=t, **TIGHT)
    np.testing.assert_allclose(res["c.v"], 1 - np.exp(-t / 0.1), atol=1e-9)
    with pytest.raises(SimulationError, match="c.*Capacitance C has to be >= 0"):
        acausal.compile(circuit(-0.01)).simulate(0.5)


def test_variable_resistor_and_conductor_in_an_rc():
    """Source V — VariableResistor R(t) — C ∥ VariableConductor G(t): C·v' = (V − v)/R(t)
    − G(t)·v; the losses are v·i of each."""
    V, C = 5.0, 0.1
    m = model("rc", lambda m: [(m.src.p, m.r.p), (m.r.n, m.c.p), (m.c.p, m.g.p),
                               (m.c.n, m.src.n), (m.g.n, m.src.n), (m.src.n, m.ground.p),
                               (m.Rt.y, m.r.R), (m.Gt.y, m.g.G)],
              src=el.ConstantVoltage(V=V), r=el.VariableResistor(), c=el.Capacitor(C=C),
              g=el.VariableConductor(), Rt=sig.Ramp(height=3.0, duration=1.0, offset=1.0),
              Gt=sig.Sine(amplitude=0.2, f=1.5, offset=0.5), ground=el.Ground())
    t = np.linspace(0.0, 1.5, 151)
    res = acausal.compile(m).simulate(1.5, t=t, **TIGHT)
    R = lambda s: 1.0 + 3.0 * np.clip(s, 0, 1)                        # noqa: E731
    G = lambda s: 0.5 + 0.2 * np.sin(2 * np.pi * 1.5 * s)             # noqa: E731
    v, = scipy_solution(lambda s, x: [((V - x[0]) / R(s) - G(s) * x[0]) / C], [0.0], t)
    np.testing.assert_allclose(res["c.v"], v, atol=1e-8)
    np.testing.assert_allclose(res["r.R_actual"], R(t), atol=1e-12)
    np.testing.assert_allclose(res["r.LossPower"], (V - v) ** 2 / R(t), atol=1e-7)
    np.testing.assert_allclose(res["g.LossPower"], G(t) * v ** 2, atol=1e-7)


R_SERIES, C_LOAD = 5.0, 0.02


def controlled(source, port1):
    """A constant source V = 2 feeding ``source``'s port 1 as ``port1`` wires it; port 2
    drives R_SERIES and C_LOAD (start 0) in series, n2 grounded."""
    return model("ctl", lambda m: [(m.src.n, m.ground.p), (m.x.n2, m.ground.p),
                                   (m.x.p2, m.r.p), (m.r.n, m.c.p),
                                   (m.c.n, m.ground.p)] + port1(m),
                 src=el.ConstantVoltage(V=2.0), x=source, c=el.Capacitor(C=C_LOAD),
                 r=el.Resistor(R=R_SERIES), ground=el.Ground(), r1=el.Resistor(R=4.0))


ACROSS = lambda m: [(m.src.p, m.x.p1), (m.x.n1, m.ground.p), (m.r1.p, m.src.p),  # noqa: E731
                    (m.r1.n, m.ground.p)]
IN_SERIES = lambda m: [(m.src.p, m.r1.p), (m.r1.n, m.x.p1),                      # noqa: E731
                       (m.x.n1, m.ground.p)]


@pytest.mark.parametrize("source, port1, v1, i1, v2, i2", [
    # VCV: v2 = gain·v1, i1 = 0
    (el.VCV(gain=3.0), ACROSS, 2.0, 0.0, 3.0 * 2.0, None),
    # VCC: i2 = gT·v1 (into p2), i1 = 0
    (el.VCC(transConductance=0.25), ACROSS, 2.0, 0.0, None, 0.25 * 2.0),
    # CCV: v1 = 0, i1 = 2 V/4 Ohm through R1; v2 = rT·i1
    (el.CCV(transResistance=6.0), IN_SERIES, 0.0, 0.5, 6.0 * 0.5, None),
    # CCC: i2 = gain·i1, v1 = 0
    (el.CCC(gain=1.5), IN_SERIES, 0.0, 0.5, None, 1.5 * 0.5)])
def test_controlled_sources_follow_their_gains(source, port1, v1, i1, v2, i2):
    """A controlled voltage charges the R-C in series as v_C = v2·(1 − e^(−t/RC)) and
    sends i2 = −(v2 − v_C)/R back into p2; a controlled current i2 into p2 drains the
    capacitor linearly, v_C = −i2·t/C."""
    t = np.linspace(0.0, 0.3, 31)
    res = acausal.compile(controlled(source, port1)).simulate(0.3, t=t, **TIGHT)
    np.testing.assert_allclose(res["x.v1"], v1, atol=1e-12)
    np.testing.assert_allclose(res["x.i1"], i1, atol=1e-12)
    if v2 is not None:
        vc = v2 * (1 - np.exp(-t / (R_SERIES * C_LOAD)))
        np.testing.assert_allclose(res["x.v2"], v2, atol=1e-12)
        np.testing.assert_allclose(res["x.i2"], -(v2 - vc) / R_SERIES, atol=1e-9)
    else:
        vc = -i2 * t / C_LOAD
        np.testing.assert_allclose(res["x.i2"], i2, atol=1e-12)
    np.testing.assert_allclose(res["c.v"], vc, atol=1e-8)


def test_transformer_matches_the_coupled_inductor_ode_and_balances_energy():
    """Primary: V·sin(ωt) — R1 — (p1, n1); secondary: R2 across (p2, n2). With
    v1 = V·sin − R1·i1, v2 = −R2·i2: [[L1, M], [M, L2]]·d[i1, i2]/dt = [v1, v2]. The
    source's energy is the losses plus the magnetic ½·iᵀ·L·i."""
    V, f, R1, R2, L1, L2, M = 5.0, 3.0, 1.0, 2.0, 0.4, 0.3, 0.25
    m = model("tr", lambda m: [(m.src.p, m.r1.p), (m.r1.n, m.t.p1), (m.t.n1, m.src.n),
                               (m.src.n, m.ground.p), (m.t.p2, m.r2.p), (m.r2.n, m.t.n2),
                               (m.t.n2, m.ground.p)],
              src=el.SineVoltage(V=V, f=f), r1=el.Resistor(R=R1),
              t=el.Transformer(L1=L1, L2=L2, M=M), r2=el.Resistor(R=R2), ground=el.Ground())
    t = np.linspace(0.0, 1.0, 2001)
    res = acausal.compile(m).simulate(1.0, t=t, **TIGHT)
    Lm = np.array([[L1, M], [M, L2]])

    def rhs(s, x):
        return np.linalg.solve(Lm, [V * np.sin(2 * np.pi * f * s) - R1 * x[0], -R2 * x[1]])
    i1, i2 = scipy_solution(rhs, [0.0, 0.0], t)
    np.testing.assert_allclose(res["t.i1"], i1, atol=1e-9)
    np.testing.assert_allclose(res["t.i2"], i2, atol=1e-9)
    np.testing.assert_allclose(res["t.v2"], -R2 * i2, atol=1e-8)
    np.testing.assert_allclose(res["t.dv"], res["t.v1"] - res["t.v2"], atol=1e-8)
    supplied = np.trapezoid(-res["src.v"] * res["src.i"], t)
    lost = np.trapezoid(res["r1.LossPower"] + res["r2.LossPower"], t)
    stored = 0.5 * (L1 * i1[-1] ** 2 + 2 * M * i1[-1] * i2[-1] + L2 * i2[-1] ** 2)
    assert supplied == pytest.approx(lost + stored, rel=1e-6)


def test_transformer_refuses_perfect_or_missing_coupling():
    with pytest.raises(ParameterError, match="Transformer.*M\\^2"):
        el.Transformer(L1=1.0, L2=1.0, M=1.0)
    with pytest.raises(ParameterError, match="Transformer.*'M'"):
        el.Transformer(L1=1.0, L2=1.0)
    with pytest.raises(ParameterError, match="Transformer.L1"):
        el.Transformer(L1=0.0, L2=1.0, M=0.1)


@pytest.mark.parametrize("use_input, r", [(False, 0.3), (True, 0.8)])
def test_potentiometer_divides_like_its_thevenin_equivalent(use_input, r):
    """V across pin_p—pin_n (grounded); C in series with Rs from the contact to ground
    charges to V·r through Rs + Rp ∥ Rn = Rs + R·r·(1 − r)."""
    V, R, Rs, C = 4.0, 100.0, 10.0, 1e-3
    parts = dict(src=el.ConstantVoltage(V=V), c=el.Capacitor(C=C), rs=el.Resistor(R=Rs),
                 ground=el.Ground())
    if use_input:
        parts.update(pot=el.Potentiometer(R=R, useRinput=True), rin=sig.Constant(k=r))
    else:
        parts.update(pot=el.Potentiometer(R=R, rConstant=r))
    m = model("pot", lambda m: [(m.src.p, m.pot.pin_p), (m.pot.pin_n, m.ground.p),
                                (m.src.n, m.ground.p), (m.pot.contact, m.rs.p),
                                (m.rs.n, m.c.p),
                                (m.c.n, m.ground.p)] + ([(m.rin.y, m.pot.r)] if use_input
                                                         else []), **parts)
    t = np.linspace(0.0, 0.2, 41)
    res = acausal.compile(m).simulate(0.2, t=t, **TIGHT)
    vc = V * r * (1 - np.exp(-t / ((Rs + R * r * (1 - r)) * C)))
    np.testing.assert_allclose(res["c.v"], vc, atol=1e-9)
    np.testing.assert_allclose(res["pot.Rp"], R * (1 - r), atol=1e-12)
    v_contact = vc + Rs * (V * r - vc) / (Rs + R * r * (1 - r))
    ip, i_n = (V - v_contact) / (R * (1 - r)), -v_contact / (R * r)
    np.testing.assert_allclose(res["pot.pin_p.i"], ip, atol=1e-9)
    np.testing.assert_allclose(res["pot.LossPower"], (V - v_contact) * ip - v_contact * i_n,
                               atol=1e-8)


def test_sensors_short_and_idle():
    """MultiSensor in series with R (current path) and across it (voltage path): i, v and
    power = v·i of the resistor; PotentialSensor reads the node; a Short carries the loop
    current at v = 0, an Idle branch none."""
    V, R, C = 3.0, 2.0, 0.05
    m = model("sense", lambda m: [
        (m.src.p, m.ms.pc), (m.ms.nc, m.sh.p), (m.sh.n, m.r.p), (m.r.n, m.c.p),
        (m.c.n, m.ground.p), (m.src.n, m.ground.p), (m.ms.pv, m.r.p), (m.ms.nv, m.r.n),
        (m.ps.p, m.r.n), (m.idle.p, m.r.p), (m.idle.n, m.ground.p)],
        src=el.StepVoltage(V=V, startTime=0.1), ms=el.MultiSensor(), sh=el.Short(),
        r=el.Resistor(R=R), c=el.Capacitor(C=C), ps=el.PotentialSensor(), idle=el.Idle(),
        ground=el.Ground())
    t = np.linspace(0.0, 0.5, 50)                     # not at the step, 0.1 s
    res = acausal.compile(m).simulate(0.5, t=t, **TIGHT)
    tau = np.clip(t - 0.1, 0.0, None)
    vc = V * (1 - np.exp(-tau / (R * C)))
    np.testing.assert_allclose(res["ps.phi"], vc, atol=1e-9)
    np.testing.assert_allclose(res["ms.i"], (np.where(t < 0.1, 0, V) - vc) / R, atol=1e-9)
    np.testing.assert_allclose(res["ms.v"], res["r.v"], atol=1e-12)
    np.testing.assert_allclose(res["ms.power"], res["r.LossPower"], atol=1e-12)
    np.testing.assert_allclose(res["sh.i"], res["ms.i"], atol=1e-12)
    np.testing.assert_allclose(res["idle.v"], res["r.p.v"], atol=1e-12)


@pytest.mark.parametrize("make, name", [
    (lambda: el.VariableCapacitor(Cmin=0.0), "VariableCapacitor.Cmin"),
    (lambda: el.VariableInductor(Lmin=-1e-3), "VariableInductor.Lmin"),
    (lambda: el.Potentiometer(rConstant=-0.1), "Potentiometer.rConstant"),
    (lambda: el.Potentiometer(rConstant=1.5), "Potentiometer.rConstant")])
def test_bad_bounds_are_refused_naming_the_component(make, name):
    with pytest.raises(ParameterError, match=name):
        make()
