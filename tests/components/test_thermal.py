"""Thermal components (Modelica.Thermal.HeatTransfer) against closed forms and hand-written
ODEs."""
from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.components import signals as sig
from acausal.components import thermal as th
from lti import constant_input_response
from wiring import model

TIGHT = {"rtol": 1e-11, "atol": 1e-12}


@pytest.mark.parametrize("element", ["ThermalConductor", "ThermalResistor"])
def test_thermal_rc_cools_to_the_fixed_temperature(element):
    """HeatCapacitor C through G (or R = 1/G) to a FixedTemperature T_amb:
    T = T_amb + (T0 − T_amb)·exp(−G t / C); the heat flow Q = G·(T − T_amb) leaves the
    capacitor; sensors read T and Q."""
    C, G, T0, T_amb = 20.0, 4.0, 400.0, 300.0
    link = th.ThermalConductor(G=G) if element == "ThermalConductor" \
        else th.ThermalResistor(R=1 / G)
    m = model("thermal_rc", lambda m: [
        (m.cap.port, m.flow.port_a), (m.flow.port_b, m.link.port_a),
        (m.link.port_b, m.amb.port), (m.sensor.port, m.cap.port)],
        cap=th.HeatCapacitor(C=C, T_start=T0), link=link, amb=th.FixedTemperature(T=T_amb),
        flow=th.HeatFlowSensor(), sensor=th.TemperatureSensor())
    t = np.linspace(0.0, 15.0, 31)
    res = acausal.compile(m).simulate(15.0, t=t, **TIGHT)
    T = T_amb + (T0 - T_amb) * np.exp(-G * t / C)
    np.testing.assert_allclose(res["cap.T"], T, atol=1e-8)
    np.testing.assert_allclose(res["sensor.T"], T, atol=1e-8)
    np.testing.assert_allclose(res["flow.Q_flow"], G * (T - T_amb), atol=1e-8)
    np.testing.assert_allclose(res["link.Q_flow"], G * (T - T_amb), atol=1e-8)
    np.testing.assert_allclose(res["cap.der_T"], -G / C * (T - T_amb), atol=1e-8)
    np.testing.assert_allclose(res["amb.port.Q_flow"], G * (T - T_amb), atol=1e-8)


def test_two_capacitors_heated_and_convecting_match_the_linear_ode():
    """FixedHeatFlow P into C1; C1 —G— C2; C2 convects (Gc from a Constant) to a
    PrescribedTemperature T_f (a Constant): x = [T1, T2],
    C1 T1' = P − G(T1 − T2), C2 T2' = G(T1 − T2) − Gc(T2 − T_f), solved exactly."""
    P, C1, C2, G, Gc, Tf = 50.0, 10.0, 30.0, 2.0, 1.5, 290.0
    m = model("two_caps", lambda m: [
        (m.heater.port, m.c1.port), (m.c1.port, m.g.port_a), (m.g.port_b, m.c2.port),
        (m.c2.port, m.conv.solid), (m.conv.fluid, m.fluid.port), (m.gc.y, m.conv.Gc),
        (m.tf.y, m.fluid.T)],
        heater=th.FixedHeatFlow(Q_flow=P), c1=th.HeatCapacitor(C=C1, T_start=300.0),
        c2=th.HeatCapacitor(C=C2, T_start=290.0), g=th.ThermalConductor(G=G),
        conv=th.Convection(), fluid=th.PrescribedTemperature(), gc=sig.Constant(k=Gc),
        tf=sig.Constant(k=Tf))
    t = np.linspace(0.0, 60.0, 61)
    res = acausal.compile(m).simulate(60.0, t=t, **TIGHT)
    A = np.array([[-G / C1, G / C1], [G / C2, -(G + Gc) / C2]])
    b = np.array([P / C1, Gc * Tf / C2])
    x0 = np.array([300.0, 290.0])
    xs = constant_input_response(A, b, x0, t)
    np.testing.assert_allclose(res["c1.T"], xs[:, 0], atol=1e-7)
    np.testing.assert_allclose(res["c2.T"], xs[:, 1], atol=1e-7)
    np.testing.assert_allclose(res["conv.Q_flow"], Gc * (xs[:, 1] - Tf), atol=1e-7)


def test_body_radiation_and_temperature_dependent_heat_flow_match_scipy():
    """C T' = −Gr·σ·(T⁴ − T_amb⁴) + P·(1 + alpha·(T − T_ref)) (a PrescribedHeatFlow with
    alpha), against scipy's solve_ivp."""
    C, Gr, T_amb, P, alpha, T_ref = 5.0, 0.02, 280.0, 30.0, 0.01, 300.0
    m = model("radiation", lambda m: [
        (m.cap.port, m.rad.port_a), (m.rad.port_b, m.amb.port), (m.heater.port, m.cap.port),
        (m.p.y, m.heater.Q_flow)],
        cap=th.HeatCapacitor(C=C, T_start=600.0), rad=th.BodyRadiation(Gr=Gr),
        amb=th.FixedTemperature(T=T_amb), heater=th.PrescribedHeatFlow(alpha=alpha,
                                                                       T_ref=T_ref),
        p=sig.Constant(k=P))
    t = np.linspace(0.0, 100.0, 51)
    res = acausal.compile(m).simulate(100.0, t=t, **TIGHT)

    def rhs(_, T):
        return [(-Gr * th.SIGMA * (T[0] ** 4 - T_amb ** 4)
                 + P * (1 + alpha * (T[0] - T_ref))) / C]

    ref = solve_ivp(rhs, (0, 100.0), [600.0], t_eval=t, rtol=1e-12, atol=1e-10,
                    method="DOP853").y[0]
    np.testing.assert_allclose(res["cap.T"], ref, atol=1e-7)


def test_heat_capacitors_joined_directly_are_refused():
    m = model("joined", lambda m: [(m.c1.port, m.c2.port)], c1=th.HeatCapacitor(C=1.0),
              c2=th.HeatCapacitor(C=2.0))
    with pytest.raises(acausal.StructureError,
                       match=r"HeatCapacitor 'c1', HeatCapacitor 'c2'.*thermal conductor"):
        acausal.compile(m)


def test_msl_required_parameters():
    for cls, name in ((th.HeatCapacitor, "C"), (th.ThermalConductor, "G"),
                      (th.FixedTemperature, "T"), (th.FixedHeatFlow, "Q_flow"),
                      (th.BodyRadiation, "Gr")):
        with pytest.raises(acausal.ParameterError, match=name):
            cls()
