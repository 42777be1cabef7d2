"""ConvectiveResistor, ThermalCollector, RelTemperatureSensor, ConditionalFixedHeatFlowSensor
and the Celsius package against closed forms and hand-written scipy models."""
from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.components import celsius
from acausal.components import signals as sig
from acausal.components import thermal as th
from wiring import model

TIGHT = {"rtol": 1e-11, "atol": 1e-12}


def test_body_cools_through_a_time_varying_convective_resistance():
    """C·T' = −(T − T_f)/Rc(t), Rc(t) = 0.5 + 0.25·sin(2π·0.1·t) [K/W] from a Sine, the fluid
    a Celsius.PrescribedTemperature at 15 degC, against scipy; dT = Rc·Q_flow."""
    C, T0, Tf = 40.0, 360.0, 15.0 + 273.15
    m = model("cooling", lambda m: [
        (m.body.port, m.conv.solid), (m.conv.fluid, m.fluid.port), (m.rc.y, m.conv.Rc),
        (m.tf.y, m.fluid.T)],
        body=th.HeatCapacitor(C=C, T_start=T0), conv=th.ConvectiveResistor(),
        fluid=celsius.PrescribedTemperature(), tf=sig.Constant(k=15.0),
        rc=sig.Sine(amplitude=0.25, f=0.1, offset=0.5))
    t = np.linspace(0.0, 40.0, 81)
    res = acausal.compile(m).simulate(40.0, t=t, **TIGHT)

    def rc(t):
        return 0.5 + 0.25 * np.sin(2 * np.pi * 0.1 * t)

    ref = solve_ivp(lambda t, x: [-(x[0] - Tf) / rc(t) / C], (0, 40.0), [T0], t_eval=t,
                    rtol=1e-11, atol=1e-10)
    T = ref.y[0]
    np.testing.assert_allclose(res["body.T"], T, atol=1e-6)
    np.testing.assert_allclose(res["conv.Q_flow"], (T - Tf) / rc(t), atol=1e-5)
    np.testing.assert_allclose(res["conv.dT"], T - Tf, atol=1e-6)
    np.testing.assert_allclose(res["fluid.port.Q_flow"], (T - Tf) / rc(t), atol=1e-5)


def test_thermal_collector_sums_the_heat_flows_at_one_temperature():
    """Three capacitors through G_i into port_a[i] of a ThermalCollector(m=3), port_b through
    G0 to a FixedTemperature: the collector's node at T_c = (Σ G_i·T_i + G0·T_amb)/(Σ G_i +
    G0), C_i·T_i' = −G_i·(T_i − T_c), port_b.Q_flow = −Σ port_a[i].Q_flow (scipy)."""
    C, G, T0 = [5.0, 10.0, 20.0], [1.0, 2.0, 3.0], [400.0, 350.0, 300.0]
    G0, T_amb = 4.0, 280.0
    parts = {f"c{i}": th.HeatCapacitor(C=C[i], T_start=T0[i]) for i in range(3)}
    parts.update({f"g{i}": th.ThermalConductor(G=G[i]) for i in range(3)})
    parts.update(col=th.ThermalCollector(m=3), gb=th.ThermalConductor(G=G0),
                 amb=th.FixedTemperature(T=T_amb), rel=th.RelTemperatureSensor())
    m = model("collector", lambda m: [
        *[(getattr(m, f"c{i}").port, getattr(m, f"g{i}").port_a) for i in range(3)],
        *[(getattr(m, f"g{i}").port_b, m.col.port_a[i + 1]) for i in range(3)],
        (m.col.port_b, m.gb.port_a), (m.gb.port_b, m.amb.port),
        (m.rel.port_a, m.c0.port), (m.rel.port_b, m.col.port_b)], **parts)
    t = np.linspace(0.0, 20.0, 41)
    res = acausal.compile(m).simulate(20.0, t=t, **TIGHT)
    Cv, Gv = np.array(C), np.array(G)

    def node(x):
        return (Gv @ x + G0 * T_amb) / (Gv.sum() + G0)

    ref = solve_ivp(lambda t, x: -Gv * (x - node(x)) / Cv, (0, 20.0), T0, t_eval=t,
                    rtol=1e-12, atol=1e-10)
    x = ref.y
    Tc = node(x)
    for i in range(3):
        np.testing.assert_allclose(res[f"c{i}.T"], x[i], atol=1e-7)
        np.testing.assert_allclose(res[f"col.port_a[{i + 1}].Q_flow"], G[i] * (x[i] - Tc),
                                   atol=1e-7)
    np.testing.assert_allclose(res["col.port_b.Q_flow"], -(Gv @ (x - Tc)), atol=1e-7)
    np.testing.assert_allclose(res["gb.Q_flow"], G0 * (Tc - T_amb), atol=1e-7)
    np.testing.assert_allclose(res["rel.T_rel"], x[0] - Tc, atol=1e-7)


@pytest.mark.parametrize("m", [0, 2.5, True])
def test_thermal_collector_needs_a_whole_number_of_ports(m):
    with pytest.raises(acausal.ParameterError, match="ThermalCollector: m"):
        th.ThermalCollector(m=m)


@pytest.mark.parametrize("fixed", [False, True])
def test_conditional_fixed_heat_flow_sensor(fixed):
    """A capacitor (T0 = 350 K) through G to port_b of the sensor; port_a to a
    FixedTemperature at 300 K. Without the fixed temperature the sensor passes the heat flow
    to 300 K; with it port_a is held at 293.15 K (a second source there is refused, as two
    FixedTemperatures at one node): T → 293.15 K, Q_flow = G·(293.15 − T), and the open
    port_a carries no heat flow (the inner fixed temperature supplies it)."""
    C, G, T0, T_amb = 10.0, 2.0, 350.0, 300.0
    m = model("cfs", lambda m: [
        (m.amb.port, m.sensor.port_a), (m.sensor.port_b, m.g.port_a), (m.g.port_b, m.cap.port)],
        amb=th.FixedTemperature(T=T_amb), sensor=th.ConditionalFixedHeatFlowSensor(
            useFixedTemperature=fixed), g=th.ThermalConductor(G=G),
        cap=th.HeatCapacitor(C=C, T_start=T0))
    if fixed:
        # port_a is held twice (by amb and by the sensor): a higher-index network
        with pytest.raises(acausal.AcausalError):
            acausal.compile(m)
        m = model("cfs", lambda m: [(m.sensor.port_b, m.g.port_a), (m.g.port_b, m.cap.port)],
                  sensor=th.ConditionalFixedHeatFlowSensor(useFixedTemperature=True),
                  g=th.ThermalConductor(G=G), cap=th.HeatCapacitor(C=C, T_start=T0))
    t = np.linspace(0.0, 10.0, 21)
    res = acausal.compile(m).simulate(10.0, t=t, **TIGHT)
    Ts = 293.15 if fixed else T_amb
    T = Ts + (T0 - Ts) * np.exp(-G * t / C)
    np.testing.assert_allclose(res["cap.T"], T, atol=1e-8)
    np.testing.assert_allclose(res["sensor.Q_flow"], G * (Ts - T), atol=1e-7)
    if fixed:
        np.testing.assert_allclose(res["sensor.port_a.Q_flow"], 0.0, atol=1e-9)


def test_celsius_blocks_and_sources():
    """ToKelvin(20 degC) = 293.15 K and FromKelvin back; a capacitor cooling to a
    Celsius.FixedTemperature of 20 degC read by a Celsius.TemperatureSensor in degC."""
    C, G, T0 = 10.0, 2.0, 350.0
    m = model("celsius", lambda m: [
        (m.k.y, m.to.Celsius), (m.to.Kelvin, m.back.Kelvin), (m.cap.port, m.g.port_a),
        (m.g.port_b, m.amb.port), (m.sensor.port, m.cap.port)],
        k=sig.Constant(k=20.0), to=celsius.ToKelvin(), back=celsius.FromKelvin(),
        cap=th.HeatCapacitor(C=C, T_start=T0), g=th.ThermalConductor(G=G),
        amb=celsius.FixedTemperature(T=20.0), sensor=celsius.TemperatureSensor())
    t = np.linspace(0.0, 10.0, 21)
    res = acausal.compile(m).simulate(10.0, t=t, **TIGHT)
    np.testing.assert_allclose(res["to.Kelvin"], 293.15, atol=1e-12)
    np.testing.assert_allclose(res["back.Celsius"], 20.0, atol=1e-12)
    T = 293.15 + (T0 - 293.15) * np.exp(-G * t / C)
    np.testing.assert_allclose(res["cap.T"], T, atol=1e-8)
    np.testing.assert_allclose(res["sensor.T"], T - 273.15, atol=1e-8)


def test_celsius_fixed_temperature_needs_its_temperature():
    with pytest.raises(acausal.ParameterError, match="T"):
        celsius.FixedTemperature()


def test_msl_two_masses():
    """MSL's Examples.TwoMasses: C1 = C2 = 15 J/K at 373.15 K and 273.15 K joined by G = 10
    W/K: T1, T2 → T_final = 323.15 K with T1 − T2 = 100·exp(−G·(1/C1 + 1/C2)·t); the
    Celsius sensors read degC."""
    m = model("TwoMasses", lambda m: [
        (m.mass1.port, m.conduction.port_a), (m.conduction.port_b, m.mass2.port),
        (m.Tsensor1.port, m.mass1.port), (m.Tsensor2.port, m.mass2.port)],
        mass1=th.HeatCapacitor(C=15, T_start=373.15), mass2=th.HeatCapacitor(C=15,
                                                                            T_start=273.15),
        conduction=th.ThermalConductor(G=10), Tsensor1=celsius.TemperatureSensor(),
        Tsensor2=celsius.TemperatureSensor())
    t = np.linspace(0.0, 1.0, 51)
    res = acausal.compile(m).simulate(1.0, t=t, **TIGHT)
    d = 100.0 * np.exp(-10 * (2 / 15) * t)
    np.testing.assert_allclose(res["Tsensor1.T"], 50.0 + d / 2, atol=1e-8)
    np.testing.assert_allclose(res["Tsensor2.T"], 50.0 - d / 2, atol=1e-8)


def test_msl_motor():
    """MSL's Examples.Motor over its 7200 s: winding losses from a periodic table of
    constant segments (100 W for 0..360 s, 1000 W for 360..600 s), scaled by 1 + 3.03e-3·(T_w
    − 368.15) (PrescribedHeatFlow), core losses 500 W, winding C = 2500 J/K —G = 10 W/K— core
    C = 25000 J/K convecting with Gc = 25 W/K to 293.15 K: against scipy integrating the two
    temperatures segment by segment."""
    T_amb = 293.15
    m = model("Motor", lambda m: [
        (m.lossTable.y[1], m.windingLosses.Q_flow), (m.lossTable.y[2], m.coreLosses.Q_flow),
        (m.windingLosses.port, m.winding.port), (m.coreLosses.port, m.core.port),
        (m.winding.port, m.winding2core.port_a), (m.winding2core.port_b, m.core.port),
        (m.winding2core.port_b, m.convection.solid), (m.convectionConstant.y, m.convection.Gc),
        (m.convection.fluid, m.environment.port)],
        lossTable=sig.CombiTimeTable(table=[[0, 100, 500], [360, 1000, 500], [600, 100, 500]],
                                     extrapolation="Periodic", smoothness="ConstantSegments"),
        windingLosses=th.PrescribedHeatFlow(T_ref=368.15, alpha=3.03e-3),
        winding=th.HeatCapacitor(C=2500, T_start=T_amb), winding2core=th.ThermalConductor(G=10),
        core=th.HeatCapacitor(C=25000, T_start=T_amb), coreLosses=th.PrescribedHeatFlow(),
        convectionConstant=sig.Constant(k=25), convection=th.Convection(),
        environment=th.FixedTemperature(T=T_amb))
    t = np.linspace(0.0, 7200.0, 121)
    res = acausal.compile(m).simulate(7200.0, t=t, **TIGHT)

    def rhs(_, x, P):
        Tw, Tc = x
        Qw = P * (1 + 3.03e-3 * (Tw - 368.15))
        return [(Qw - 10 * (Tw - Tc)) / 2500, (500 + 10 * (Tw - Tc) - 25 * (Tc - T_amb)) / 25000]

    x, ts, xs = [T_amb, T_amb], [], []
    for k in range(12):
        for a, b, P in ((600 * k, 600 * k + 360, 100.0), (600 * k + 360, 600 * k + 600, 1000.0)):
            sol = solve_ivp(rhs, (a, b), x, args=(P,), dense_output=True, rtol=1e-12,
                            atol=1e-10)
            x = sol.y[:, -1]
            inside = t[(t >= a) & (t < b)]
            ts.append(inside)
            xs.append(sol.sol(inside))
    ref, ts = np.concatenate(xs, axis=1), np.concatenate(ts)
    rows = np.searchsorted(res.t, ts, side="right") - 1     # res.t has the events' instants
    assert ts.size == t.size - 1 and np.allclose(res.t[rows], ts)
    np.testing.assert_allclose(res["winding.T"][rows], ref[0], atol=1e-6)
    np.testing.assert_allclose(res["core.T"][rows], ref[1], atol=1e-6)


def test_msl_controlled_temperature():
    """MSL's Examples.ControlledTemperature over its 10 s: a resistor (R = 10 Ω, alpha =
    1/255 1/K at 293.15 K) on 10 V through an IdealOpeningSwitch (Ron = 1e-5 Ω, Goff = 1e-5
    S) heats a capacitor C = 1 J/K losing G = 0.1 W/K to 20 degC; an OnOffController
    (bandwidth 2 K) keeps its Celsius temperature at a ramp 25 → 50 degC (2..8 s): against
    scipy with the hysteresis's switches as events."""
    from acausal.components import electrical as el
    from acausal.components import logical as lg
    T_amb = 293.15
    m = model("ControlledTemperature", lambda m: [
        (m.constantVoltage.n, m.resistor.n), (m.constantVoltage.n, m.ground.p),
        (m.resistor.heatPort, m.thermalConductor.port_a),
        (m.thermalConductor.port_b, m.fixedTemperature.port),
        (m.resistor.heatPort, m.temperatureSensor.port),
        (m.resistor.heatPort, m.heatCapacitor.port),
        (m.constantVoltage.p, m.idealSwitch.p), (m.idealSwitch.n, m.resistor.p),
        (m.ramp.y, m.onOffController.reference), (m.temperatureSensor.T, m.onOffController.u),
        (m.onOffController.y, m.logicalNot.u), (m.logicalNot.y, m.idealSwitch.control)],
        ground=el.Ground(), constantVoltage=el.ConstantVoltage(V=10),
        heatCapacitor=th.HeatCapacitor(C=1, T_start=T_amb),
        resistor=el.Resistor(R=10, T_ref=293.15, alpha=1 / 255, useHeatPort=True),
        fixedTemperature=th.FixedTemperature(T=T_amb),
        temperatureSensor=celsius.TemperatureSensor(),
        thermalConductor=th.ThermalConductor(G=0.1), idealSwitch=el.IdealOpeningSwitch(),
        ramp=sig.Ramp(height=25, duration=6, offset=25, startTime=2),
        onOffController=lg.OnOffController(bandwidth=2), logicalNot=lg.Not())
    t = np.linspace(0.0, 10.0, 201)
    res = acausal.compile(m).simulate(10.0, t=t, **TIGHT)

    def reference(tk):
        return 25 + 25 * np.clip((tk - 2) / 6, 0, 1)

    def rhs(tk, x, on):
        R = 10 * (1 + (x[0] - 293.15) / 255)
        i = 10 / (R + (1e-5 if on else 1 / 1e-5))
        return [R * i ** 2 - 0.1 * (x[0] - T_amb)]

    def switch(tk, x, on):            # heating stops at ref + 1, starts below ref − 1 (degC)
        return x[0] - 273.15 - reference(tk) - (1 if on else -1)

    switch.terminal = True
    tk, x, on, ts, xs = 0.0, [T_amb], True, [], []
    while tk < 10.0:
        sol = solve_ivp(rhs, (tk, 10.0), x, args=(on,), events=switch, dense_output=True,
                        rtol=1e-12, atol=1e-12, max_step=0.05)
        end = sol.t[-1]
        inside = t[(t >= tk) & (t < end)] if end < 10.0 else t[t >= tk]
        ts.append(inside)
        xs.append(sol.sol(inside)[0])
        tk, x, on = end, sol.y[:, -1], not on
    ts, ref = np.concatenate(ts), np.concatenate(xs)
    assert len(xs) > 4                                      # it switches several times
    rows = np.searchsorted(res.t, ts, side="right") - 1
    np.testing.assert_allclose(res["heatCapacitor.T"][rows], ref, atol=1e-6)
    np.testing.assert_allclose(res["temperatureSensor.T"][rows], ref - 273.15, atol=1e-6)
