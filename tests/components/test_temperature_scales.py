"""MSL's Thermal.HeatTransfer.Fahrenheit and .Rankine packages (and Celsius, which shares
their equations) against the defining fixed points of the scales and closed forms."""
from __future__ import annotations

import numpy as np
import pytest

import acausal
from acausal.components import celsius, fahrenheit, rankine
from acausal.components import signals as sig
from acausal.components import thermal as th
from wiring import model

TIGHT = {"rtol": 1e-11, "atol": 1e-12}
SCALES = {"Celsius": (celsius, "degC"), "Fahrenheit": (fahrenheit, "degF"),
          "Rankine": (rankine, "degRk")}


def conversions(scale: str, value: float) -> dict[str, float]:
    """ToKelvin of ``value`` (in ``scale``, a model input) and FromKelvin of that back, and
    of 373.15 K (a Constant)."""
    module = SCALES[scale][0]
    m = model("conversions", lambda m: [
        (m.k.y, getattr(m.to, scale)), (m.to.Kelvin, m.back.Kelvin),
        (m.boiling.y, m.fromK.Kelvin)],
        k=acausal.Input(), to=module.ToKelvin(), back=module.FromKelvin(),
        boiling=sig.Constant(k=373.15), fromK=module.FromKelvin())
    res = acausal.compile(m).simulate(1.0, t=[0.0, 1.0], inputs={"k": value})
    return {"K": res["to.Kelvin"][-1], "back": res[f"back.{scale}"][-1],
            "boiling": res[f"fromK.{scale}"][-1]}


@pytest.mark.parametrize("scale, value, kelvin, boiling", [
    ("Fahrenheit", 32.0, 273.15, 212.0),            # water freezes and boils
    ("Fahrenheit", 212.0, 373.15, 212.0),
    ("Fahrenheit", -40.0, 233.15, 212.0),           # −40 degF = −40 degC
    ("Fahrenheit", -459.67, 0.0, 212.0),            # absolute zero
    ("Rankine", 491.67, 273.15, 671.67),
    ("Rankine", 0.0, 0.0, 671.67),
    ("Celsius", 100.0, 373.15, 100.0),
])
def test_conversions_at_the_fixed_points_of_the_scales(scale, value, kelvin, boiling):
    got = conversions(scale, value)
    assert got["K"] == pytest.approx(kelvin, abs=1e-12)
    assert got["back"] == pytest.approx(value, abs=1e-12)
    assert got["boiling"] == pytest.approx(boiling, abs=1e-12)


def test_capacitor_cooling_to_a_fahrenheit_fixed_temperature():
    """C = 10 J/K from 350 K through G = 2 W/K to Fahrenheit.FixedTemperature(T = 50 degF
    = 283.15 K): T = 283.15 + (350 − 283.15)·exp(−G·t/C); the Fahrenheit, Rankine and
    Celsius sensors read T·9/5 − 459.67, T·9/5 and T − 273.15; the source takes the heat:
    port.Q_flow = G·(T − 283.15) into it."""
    C, G, T0, Ta = 10.0, 2.0, 350.0, 283.15
    m = model("cooling", lambda m: [
        (m.cap.port, m.g.port_a), (m.g.port_b, m.amb.port), (m.degF.port, m.cap.port),
        (m.degRk.port, m.cap.port), (m.degC.port, m.cap.port)],
        cap=th.HeatCapacitor(C=C, T_start=T0), g=th.ThermalConductor(G=G),
        amb=fahrenheit.FixedTemperature(T=50.0), degF=fahrenheit.TemperatureSensor(),
        degRk=rankine.TemperatureSensor(), degC=celsius.TemperatureSensor())
    t = np.linspace(0.0, 10.0, 21)
    res = acausal.compile(m).simulate(10.0, t=t, **TIGHT)
    T = Ta + (T0 - Ta) * np.exp(-G * t / C)
    np.testing.assert_allclose(res["cap.T"], T, atol=1e-8)
    np.testing.assert_allclose(res["amb.port.T"], Ta, atol=1e-12)
    np.testing.assert_allclose(res["amb.port.Q_flow"], G * (T - Ta), atol=1e-7)
    np.testing.assert_allclose(res["degF.T"], T * 9 / 5 - 459.67, atol=1e-8)
    np.testing.assert_allclose(res["degRk.T"], T * 9 / 5, atol=1e-8)
    np.testing.assert_allclose(res["degC.T"], T - 273.15, atol=1e-8)
    np.testing.assert_allclose(res["degF.port.Q_flow"], 0.0, atol=1e-12)


@pytest.mark.parametrize("scale, ramp_from, ramp_to", [
    ("Fahrenheit", 32.0, 212.0), ("Rankine", 491.67, 671.67)])
def test_capacitor_following_a_prescribed_temperature_ramp(scale, ramp_from, ramp_to):
    """<scale>.PrescribedTemperature from a Ramp 273.15 → 373.15 K over 10 s (in the
    scale's unit), through G to C from 273.15 K: C·T' = G·(T_p − T), T_p = 273.15 + 10·t,
    T = T_p − 10·τ·(1 − exp(−t/τ)) with τ = C/G."""
    C, G = 10.0, 2.0
    tau = C / G
    m = model("following", lambda m: [
        (m.ramp.y, m.src.T), (m.src.port, m.g.port_a), (m.g.port_b, m.cap.port)],
        ramp=sig.Ramp(height=ramp_to - ramp_from, duration=10.0, offset=ramp_from),
        src=SCALES[scale][0].PrescribedTemperature(), g=th.ThermalConductor(G=G),
        cap=th.HeatCapacitor(C=C, T_start=273.15))
    t = np.linspace(0.0, 10.0, 21)
    res = acausal.compile(m).simulate(10.0, t=t, **TIGHT)
    Tp = 273.15 + 10.0 * t
    np.testing.assert_allclose(res["src.port.T"], Tp, atol=1e-9)
    np.testing.assert_allclose(res["cap.T"], Tp - 10.0 * tau * (1 - np.exp(-t / tau)),
                               atol=1e-8)


@pytest.mark.parametrize("scale", ["Fahrenheit", "Rankine"])
def test_units_are_msls_nonsi_units(scale):
    """Temperature_degF / Temperature_degRk (Modelica.Units.NonSI) on the parameter and the
    signals; the conversion blocks' signals as the inputs and outputs of a compiled block."""
    module, unit = SCALES[scale]
    assert module.FixedTemperature.parameters()["T"].unit == unit
    to_k, from_k = acausal.compile(module.ToKelvin()), acausal.compile(module.FromKelvin())
    assert [(v.name, v.unit) for v in to_k.inputs] == [(scale, unit)]
    assert [(v.name, v.unit) for v in to_k.outputs] == [("Kelvin", "K")]
    assert [(v.name, v.unit) for v in from_k.inputs] == [("Kelvin", "K")]
    assert [(v.name, v.unit) for v in from_k.outputs] == [(scale, unit)]
    source = acausal.compile(module.PrescribedTemperature())
    assert [(v.name, v.unit) for v in source.inputs] == [("T", unit)]
    assert module.TemperatureSensor.T.description.endswith(f"[{unit}]")


@pytest.mark.parametrize("module", [fahrenheit, rankine], ids=["Fahrenheit", "Rankine"])
def test_fixed_temperature_needs_its_temperature(module):
    with pytest.raises(acausal.ParameterError, match="FixedTemperature.*'T'"):
        module.FixedTemperature()
