"""SaturatingInductor, M_Transformer and ZDiode of Modelica.Electrical.Analog against numpy
(MSL's laws written out), scipy (an RL step with the saturating inductance, three coupled
inductors) and energy balances."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

import acausal
from acausal.components import electrical as el
from acausal.errors import ParameterError
from wiring import model

TIGHT = {"rtol": 1e-10, "atol": 1e-12}


def ipar(Inom, Lnom, Lzer, Linf):
    """MSL's initial equation for Ipar, solved by scipy's brentq."""
    r = (Lnom - Linf) / (Lzer - Linf)
    return Inom * brentq(lambda x: x * (math.pi / 2 - math.atan(x)) - r, 1e-12, 1e8,
                         xtol=1e-15, rtol=1e-15)


def rl_saturating(V, R, **params):
    return model("rl_saturating", lambda m: [
        (m.src.p, m.r.p), (m.r.n, m.l.p), (m.l.n, m.ground.p), (m.src.n, m.ground.p)],
        src=el.ConstantVoltage(V=V), r=el.Resistor(R=R), l=el.SaturatingInductor(**params),
        ground=el.Ground())


def test_saturating_inductor_step_matches_scipy_and_msl_flux_law():
    """V — R — SaturatingInductor from i = 0: scipy integrates der(i) = (V − R·i)/(dPsi/di);
    the recorded Psi and Lact follow MSL's law (numpy), Lact(Inom) = Lnom by construction of
    Ipar, and the energy V·∫i dt − ∫R·i² dt put into the inductor equals ∫i dPsi =
    Linf·i²/2 + (Lzer − Linf)·Ipar²/2·ln(1 + (i/Ipar)²)."""
    V, R, Inom, Lnom, Lzer, Linf = 10.0, 2.0, 2.0, 0.4, 1.0, 0.1
    Ip = ipar(Inom, Lnom, Lzer, Linf)
    lact = lambda i: Linf + (Lzer - Linf) * np.arctan(i / Ip) / (i / Ip)   # noqa: E731
    assert lact(Inom) == pytest.approx(Lnom, rel=1e-12)
    t_end = 1.5
    t = np.linspace(0.0, t_end, 3001)
    res = acausal.compile(rl_saturating(V, R, Inom=Inom, Lnom=Lnom, Lzer=Lzer,
                                        Linf=Linf)).simulate(t_end, t=t, **TIGHT)
    assert res["l.Ipar"][0] == pytest.approx(Ip, rel=1e-12)
    ref = solve_ivp(lambda tt, x: [(V - R * x[0]) / (Linf + (Lzer - Linf)
                                                      / (1 + (x[0] / Ip) ** 2))],
                    (0, t_end), [0.0], t_eval=t, method="Radau", rtol=1e-12, atol=1e-14)
    i = ref.y[0]
    np.testing.assert_allclose(res["l.i"], i, atol=1e-8)
    assert i[-1] > 2 * Inom                              # driven deep into saturation
    np.testing.assert_allclose(res["l.Psi"], Linf * i + (Lzer - Linf) * Ip * np.arctan(i / Ip),
                               atol=1e-8)
    k = i > 1e-6
    np.testing.assert_allclose(res["l.Lact"][k], lact(i[k]), rtol=1e-7)
    assert res["l.Lact"][0] == pytest.approx(Lzer)
    energy = np.concatenate([[0.0], np.cumsum(np.diff(t) * 0.5 * (
        (res["l.v"] * res["l.i"])[1:] + (res["l.v"] * res["l.i"])[:-1]))])
    stored = Linf * i ** 2 / 2 + (Lzer - Linf) * Ip ** 2 / 2 * np.log1p((i / Ip) ** 2)
    np.testing.assert_allclose(energy, stored, atol=1e-5 * stored[-1])


def test_saturating_inductor_follows_its_parameters_at_simulation_time():
    """Ipar is an expression of the parameters: changed by params=..., the current still
    follows scipy's solution for the new values."""
    V, R = 10.0, 2.0
    compiled = acausal.compile(rl_saturating(V, R))
    Inom, Lnom, Lzer, Linf = 1.5, 0.3, 0.9, 0.05
    t = np.linspace(0.0, 1.0, 101)
    res = compiled.simulate(1.0, t=t, params={"l.Inom": Inom, "l.Lnom": Lnom, "l.Lzer": Lzer,
                                              "l.Linf": Linf}, **TIGHT)
    Ip = ipar(Inom, Lnom, Lzer, Linf)
    ref = solve_ivp(lambda tt, x: [(V - R * x[0]) / (Linf + (Lzer - Linf)
                                                      / (1 + (x[0] / Ip) ** 2))],
                    (0, 1.0), [0.0], t_eval=t, method="Radau", rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(res["l.i"], ref.y[0], atol=1e-8)


@pytest.mark.parametrize("bad, what", [({"Lzer": 0.9}, "Lzer"), ({"Linf": 1.2}, "Linf")])
def test_saturating_inductor_refuses_inconsistent_inductances(bad, what):
    with pytest.raises(ParameterError, match=f"SaturatingInductor 'l': {what} .* has to be"):
        el.SaturatingInductor("l", **bad)


def zdiode_msl(v, Ids=1e-6, Vt=0.04, Maxexp=30.0, R=1e8, Bv=5.1, Ibv=0.7, Nbv=0.74):
    """MSL's ZDiode law, written out as in ZDiode.mo (numpy)."""
    with np.errstate(over="ignore"):
        return np.where(
            v > Maxexp * Vt,
            Ids * (math.exp(Maxexp) * (1 + v / Vt - Maxexp) - 1) + v / R,
            np.where((v + Bv) < -Maxexp * (Nbv * Vt),
                     -Ids - Ibv * math.exp(Maxexp) * (1 - (v + Bv) / (Nbv * Vt) - Maxexp) + v / R,
                     Ids * (np.exp(v / Vt) - 1) - Ibv * np.exp(-(v + Bv) / (Nbv * Vt)) + v / R))


def test_zdiode_characteristic_in_forward_reverse_and_breakdown():
    """A RampVoltage sweeps the ZDiode from −6 V (past the breakdown's linear continuation,
    which starts at −Bv − Maxexp·Nbv·Vt = −5.988 V) to +1.5 V (past the forward
    continuation at Maxexp·Vt = 1.2 V); its current against MSL's law at every output point,
    points in all five pieces (breakdown linear, breakdown exponential, reverse blocking,
    forward exponential, forward linear); LossPower = v·i."""
    v0, v1 = -6.0, 1.5
    m = model("zdiode", lambda m: [
        (m.src.p, m.d.p), (m.d.n, m.ground.p), (m.src.n, m.ground.p)],
        src=el.RampVoltage(V=v1 - v0, offset=v0, duration=1.0), d=el.ZDiode(),
        ground=el.Ground())
    t = np.linspace(0.0, 1.0, 3001)
    res = acausal.compile(m).simulate(1.0, t=t, **TIGHT)
    v = v0 + (v1 - v0) * t
    np.testing.assert_allclose(res["d.v"], v, atol=1e-12)
    i_ref = zdiode_msl(v)
    np.testing.assert_allclose(res["d.i"], i_ref, rtol=1e-9, atol=1e-18)
    for lo, hi in ((-6.0, -5.988), (-5.98, -5.0), (-4.0, -0.1), (0.1, 1.2), (1.2, 1.5)):
        assert np.any((v > lo) & (v < hi))
    # the regions: breakdown conducts kA-scale reverse currents, forward likewise
    assert res["d.i"][0] < -1e3 and res["d.i"][-1] > 1e3
    k = np.argmin(np.abs(v + 2.0))                      # blocking: −Ids + v/R at −2 V
    assert res["d.i"][k] == pytest.approx(-1e-6 + v[k] / 1e8, rel=1e-9)
    np.testing.assert_allclose(res["d.LossPower"], res["d.v"] * res["d.i"], rtol=1e-12)


def test_m_transformer_matches_scipy_and_balances_energy():
    """M_Transformer, N = 3 with MSL's default L: a SineVoltage on inductor 1, resistors on
    2 and 3 (v_j = −R_j·i_j): scipy integrates Lm·der(i) = v; the energy the source puts in
    is the resistors' losses plus ½·iᵀ·Lm·i."""
    Vs, f, R2, R3 = 5.0, 2.0, 3.0, 7.0
    m = model("m_transformer", lambda m: [
        (m.src.p, m.tr.p[1]), (m.src.n, m.tr.n[1]), (m.r2.p, m.tr.p[2]), (m.r2.n, m.tr.n[2]),
        (m.r3.p, m.tr.p[3]), (m.r3.n, m.tr.n[3]), (m.src.n, m.ground.p),
        (m.r2.n, m.ground2.p), (m.r3.n, m.ground3.p)],
        src=el.SineVoltage(V=Vs, f=f), tr=el.M_Transformer(), r2=el.Resistor(R=R2),
        r3=el.Resistor(R=R3), ground=el.Ground(), ground2=el.Ground(), ground3=el.Ground())
    t = np.linspace(0.0, 1.0, 2001)
    res = acausal.compile(m).simulate(1.0, t=t, **TIGHT)
    Lm = np.array([[1.0, 0.1, 0.2], [0.1, 2.0, 0.3], [0.2, 0.3, 3.0]])
    w = 2 * math.pi * f
    ref = solve_ivp(lambda tt, x: np.linalg.solve(
        Lm, [Vs * math.sin(w * tt), -R2 * x[1], -R3 * x[2]]), (0, 1.0), [0.0, 0.0, 0.0],
        t_eval=t, method="Radau", rtol=1e-12, atol=1e-14)
    for j in range(3):
        np.testing.assert_allclose(res[f"tr.i[{j + 1}]"], ref.y[j], atol=1e-9)
    np.testing.assert_allclose(res["tr.v[2]"], -R2 * ref.y[1], atol=1e-9)
    power_in = res["tr.v[1]"] * res["tr.i[1]"]
    loss = R2 * res["tr.i[2]"] ** 2 + R3 * res["tr.i[3]"] ** 2
    i_end = ref.y[:, -1]
    assert np.trapezoid(power_in - loss, t) == pytest.approx(0.5 * i_end @ Lm @ i_end,
                                                              rel=1e-5, abs=1e-9)


def test_m_transformer_refuses_bad_inductances():
    with pytest.raises(ParameterError, match="give the 3 inductances L"):
        el.M_Transformer(N=2)
    with pytest.raises(ParameterError, match="M_Transformer 'tr'.*not positive definite"):
        el.M_Transformer("tr", N=2, L=(1.0, 2.0, 1.0))
    with pytest.raises(ParameterError, match="N .* must be an integer >= 1"):
        el.M_Transformer(N=0)
