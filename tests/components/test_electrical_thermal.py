"""Temperature-dependent electrical components (Resistor's device temperature, MSL 3's
HeatingResistor, the exponential Diode) against closed forms and MSL's published reference
results of Electrical.Analog.Examples.Resistor and HeatingRectifier."""
from __future__ import annotations

import re

import numpy as np
import pytest

import acausal
from acausal.components import electrical as el
from acausal.components import thermal as th
from acausal.models import HeatingRectifier, ResistorExample
from hot_resistor import OUTSIDE, hot_part

TIGHT = {"rtol": 1e-11, "atol": 1e-12}
K_B, Q_E = 1.380649e-23, 1.602176634e-19        # Modelica.Constants.k, q


def on_sine(part, V=1.0, f=1.0, heat=None):
    """``part`` (a OnePort) across SineVoltage(V, f); ``heat``: a thermal component its
    heatPort is connected to."""
    m = acausal.Model("on_sine")
    m.src, m.part, m.ground = el.SineVoltage(V=V, f=f), part, el.Ground()
    m.connect(m.src.p, m.part.p)
    m.connect(m.part.n, m.src.n)
    m.connect(m.src.n, m.ground.p)
    if heat is not None:
        m.heat = heat
        m.connect(m.part.heatPort, heat.port)
    return m


def test_resistor_without_heat_port_sits_at_T_ref_unless_T_is_given():
    """MSL's Resistor(T=T_ref): R_actual = R whatever alpha, also with T_ref changed at
    simulation time; with T given, R_actual = R·(1 + alpha·(T − T_ref)); the Conductor
    likewise with G_actual = G/(1 + alpha·(T − T_ref))."""
    R, alpha, T_ref = 10.0, 4e-3, 293.15
    t = np.linspace(0.0, 0.5, 11)
    r = el.Resistor(R=R, alpha=alpha, T_ref=T_ref)
    assert r.T == T_ref and "T" not in r.parameters()
    compiled = acausal.compile(on_sine(r))
    assert "part.T" not in compiled.param_names
    res = compiled.simulate(0.5, t=t, params={"part.T_ref": 350.0}, **TIGHT)
    np.testing.assert_allclose(res["part.R_actual"], R, rtol=1e-14)
    np.testing.assert_allclose(res["part.T_heatPort"], 350.0, rtol=1e-14)
    np.testing.assert_allclose(res["part.i"], np.sin(2 * np.pi * t) / R, atol=1e-14)

    hot = el.Resistor(R=R, alpha=alpha, T_ref=T_ref, T=330.0)
    assert isinstance(hot, el.Resistor) and type(hot).__name__ == "Resistor"
    res = acausal.compile(on_sine(hot)).simulate(0.5, t=t, params={"part.T": 340.0}, **TIGHT)
    np.testing.assert_allclose(res["part.R_actual"], R * (1 + alpha * (340.0 - T_ref)),
                               rtol=1e-14)

    g = el.Conductor(G=0.5, alpha=alpha, T_ref=T_ref, T=380.0)
    res = acausal.compile(on_sine(g)).simulate(0.5, t=t, **TIGHT)
    np.testing.assert_allclose(res["part.G_actual"], 0.5 / (1 + alpha * (380.0 - T_ref)),
                               rtol=1e-14)
    assert el.Conductor(T_ref=310.0).T == 310.0


def test_ideal_switches_have_msl_final_device_temperature():
    """MSL's IdealSwitch declares final T = 293.15 K (no parameter); IdealDiode's T is one."""
    with pytest.raises(acausal.ParameterError, match="IdealOpeningSwitch has no parameter 'T'"):
        el.IdealOpeningSwitch(T=300.0)
    assert el.IdealClosingSwitch().T == 293.15
    assert el.IdealDiode(T=300.0).T == 300.0


def test_heating_resistor_is_the_resistor_with_its_heat_port():
    """MSL 3's HeatingResistor(R_ref, T_ref, alpha) in MSL's Resistor example gives exactly
    the results of MSL 4's Resistor(R, useHeatPort=true); it has no option without its port."""
    ref_model = ResistorExample()
    model = acausal.Model("heating_resistor")      # MSL 3's Examples.HeatingResistor
    model.resistor = el.HeatingResistor(R_ref=100.0, alpha=1e-3, T_ref=293.15)
    model.SineVoltage1, model.G = el.SineVoltage(V=220.0, f=1.0), el.Ground()
    model.thermalConductor = th.ThermalConductor(G=50.0)
    model.fixedTemperature = th.FixedTemperature(T=293.15)
    for a, b in [(model.SineVoltage1.n, model.G.p),
                 (model.resistor.heatPort, model.thermalConductor.port_a),
                 (model.SineVoltage1.p, model.resistor.p), (model.G.p, model.resistor.n),
                 (model.thermalConductor.port_b, model.fixedTemperature.port)]:
        model.connect(a, b)
    assert set(model.resistor.ports) == {"p", "n", "heatPort"}
    assert "R_ref" in model.resistor.parameters() and "R" not in model.resistor.parameters()
    t = np.linspace(0.0, 2.0, 401)
    a = acausal.compile(ref_model).simulate(2.0, t=t, **TIGHT)
    b = acausal.compile(model).simulate(2.0, t=t, **TIGHT)
    for name in ("resistor.i", "resistor.LossPower", "resistor.R_actual",
                 "resistor.T_heatPort"):
        np.testing.assert_array_equal(a[name], b[name])
    with pytest.raises(acausal.ParameterError, match="always has its heatPort"):
        el.HeatingResistor(useHeatPort=False)
    with pytest.raises(acausal.ParameterError, match="no parameter 'R'"):
        el.HeatingResistor(R=1.0)


def test_resistor_example_is_the_closed_form_and_matches_the_msl_reference(reference_result):
    """MSL's Examples.Resistor has no states: P = v²/R_act, T = 293.15 + P/G and R_act =
    R·(1 + alpha·(T − 293.15)) give R_act² − R·R_act − R·alpha·v²/G = 0, so R_act =
    (R + √(R² + 4·R·alpha·v²/G))/2; then against the Modelica Association's reference,
    resistor.i and resistor.LossPower within 2e-3 of their peaks."""
    R, alpha, G, V = 100.0, 1e-3, 50.0, 220.0
    compiled = acausal.compile(ResistorExample())
    assert compiled.x_names == []
    t = np.linspace(0.0, 5.0, 1001)
    res = compiled.simulate(5.0, t=t, **TIGHT)
    v = V * np.sin(2 * np.pi * t)
    R_act = (R + np.sqrt(R * R + 4 * R * alpha * v * v / G)) / 2
    np.testing.assert_allclose(res["resistor.R_actual"], R_act, rtol=1e-13)
    np.testing.assert_allclose(res["resistor.i"], v / R_act, atol=1e-13)
    np.testing.assert_allclose(res["resistor.heatPort.T"], 293.15 + v * v / R_act / G,
                               rtol=1e-14)

    ref = reference_result("MAP-LIB_ReferenceResults",
                           "Modelica.Electrical.Analog.Examples.Resistor")
    res = compiled.simulate(float(ref["time"][-1]), t=ref["time"], **TIGHT)
    for name in ("resistor.i", "resistor.LossPower"):
        err = np.max(np.abs(res[name] - ref[name])) / np.max(np.abs(ref[name]))
        assert err < 2e-3, (name, err)


def exlin(x, maxexp):
    return np.where(x > maxexp, np.exp(maxexp) * (1 + x - maxexp),
                    np.exp(np.minimum(x, maxexp)))


def test_diode_characteristic_with_and_without_temperature_dependency():
    """Diode across a 1 V sine (v/Vt up to 25, past Maxexp = 15: both branches of exlin)
    against MSL's formulas written with numpy: without temperature dependency i =
    Ids·(exlin(v/Vt) − 1) + v/R; with it, at a FixedTemperature T on its heatPort,
    i = Ids·(exlin(v/(N·vt)) − 1)·(T/TNOM)^(XTI/N)·exp((T/TNOM − 1)·EG/(N·vt)) + v/R,
    vt = k·T/q; LossPower = v·i flows out of the heatPort."""
    t = np.linspace(0.0, 1.0, 201)
    v = np.sin(2 * np.pi * t)
    Ids, Vt, R = 1e-6, 0.04, 1e8
    res = acausal.compile(on_sine(el.Diode())).simulate(1.0, t=t, **TIGHT)
    i = Ids * (exlin(v / Vt, 15.0) - 1) + v / R
    np.testing.assert_allclose(res["part.i"], i, rtol=1e-12, atol=1e-20)
    assert np.max(v / Vt) > 15.0 and np.max(res["part.i"]) > 0.5
    np.testing.assert_allclose(res["part.T_heatPort"], 293.15)

    T, N, EG, TNOM, XTI = 320.0, 1.2, 1.11, 300.15, 3.0
    diode = el.Diode(useTemperatureDependency=True, N=N)
    assert diode.useHeatPort                          # MSL: useHeatPort = useTemperatureDep.
    m = on_sine(diode, heat=th.FixedTemperature(T=T))
    res = acausal.compile(m).simulate(1.0, t=t, **TIGHT)
    vt = K_B * T / Q_E
    i = (Ids * (exlin(v / (N * vt), 15.0) - 1) * (T / TNOM) ** (XTI / N)
         * np.exp((T / TNOM - 1) * EG / (N * vt)) + v / R)
    np.testing.assert_allclose(res["part.i"], i, rtol=1e-12, atol=1e-20)
    np.testing.assert_allclose(res["part.vt_t"], vt, rtol=1e-14)
    np.testing.assert_allclose(res["part.heatPort.Q_flow"], -v * i, rtol=1e-12, atol=1e-20)
    np.testing.assert_allclose(res["heat.port.Q_flow"], v * i, rtol=1e-12, atol=1e-20)


def test_heating_rectifier_matches_the_msl_reference(reference_result):
    """MSL's HeatingRectifier (a temperature-dependent Diode heating a HeatCapacitor through
    a ThermalConductor) against the Modelica Association's reference: Capacitor1.v and
    HeatCapacitor1.T within 2e-3 of their peaks (measured: 3e-5 and 4e-8)."""
    ref = reference_result("MAP-LIB_ReferenceResults",
                           "Modelica.Electrical.Analog.Examples.HeatingRectifier")
    t = ref["time"]
    res = acausal.compile(HeatingRectifier()).simulate(float(t[-1]), t=t, rtol=1e-10,
                                                       atol=1e-12)
    for name in ("Capacitor1.v", "HeatCapacitor1.T"):
        err = np.max(np.abs(res[name] - ref[name])) / np.max(np.abs(ref[name]))
        assert err < 2e-3, (name, err)
    # the temperature rise alone (1.04 K) against the reference's
    rise = ref["HeatCapacitor1.T"] - 293.15
    assert np.max(np.abs(res["HeatCapacitor1.T"] - 293.15 - rise)) < 2e-3 * np.max(rise)


@pytest.mark.parametrize("kind", ["Resistor", "Conductor"])
def test_temperature_outside_scope_stops_the_simulation(kind):
    """MSL's assert(1 + alpha·(T_heatPort − T_ref) >= eps, "Temperature outside scope of
    model!") with 1 + alpha·(T − T_ref) = 1 − 2·t (``hot_part``): up to 0.4 s the run holds
    the closed form; to 0.6 s it stops with the package's error naming the part, at the
    first output time from 0.5 s on."""
    from acausal.errors import SimulationError

    compiled = acausal.compile(hot_part(kind))
    t = np.linspace(0.0, 0.4, 41)
    res = compiled.simulate(0.4, t=t, **TIGHT)
    np.testing.assert_allclose(res["part.v"], 0.5 * (1 - 2 * t), rtol=1e-10)
    with pytest.raises(SimulationError, match=OUTSIDE):
        compiled.simulate(0.6, t=np.linspace(0.0, 0.6, 61), **TIGHT)


def test_temperature_outside_scope_in_a_sweep_and_a_stepper():
    """The same assertion in a sweep (alpha −0.005 1/K: holds to 0.6 s, the closed form
    v = 0.5·(1 + 100·alpha·t); alpha −0.02: the run is reported failed with the message
    and NaN values) and in a Stepper (the step that ends at 0.5 s raises it)."""
    from acausal.errors import SimulationError

    compiled = acausal.compile(hot_part("Resistor"))
    grid = np.linspace(0.0, 0.6, 61)
    out = compiled.sweep(0.6, t=grid, params={"part.alpha": [-0.005, -0.02]},
                         variables=["part.v"], **TIGHT)
    assert list(out.failed) == [1]
    assert re.fullmatch(OUTSIDE, out.failed[1])
    np.testing.assert_allclose(out["part.v"][0], 0.5 * (1 - 0.5 * grid), rtol=1e-8)
    assert np.all(np.isnan(out["part.v"][1]))
    stepper = compiled.stepper(0.1, **TIGHT)
    for _ in range(4):
        stepper.step()
    with pytest.raises(SimulationError, match=OUTSIDE):
        stepper.step()
