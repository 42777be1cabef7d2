"""A model with electrical and thermal networks and heat ports as a native FMU (FMI 2.0 and
3.0, model exchange and co-simulation) and through the pythonfmu backend: fmpy and the
Reference FMUs' fmusim reproduce compiled.simulate to 1e-6 of each signal's peak, and the
FMU's own result closes the model's heat balance. A pulse-driven RC, whose source's edges
are periodic time events, is reproduced by fmpy likewise.

The model: a DC motor whose armature resistance (α = 0.004 1/K) and load damper give their
losses through their heat ports to a heat capacitor (the winding), which cools through a
thermal conductor to a fixed ambient; a voltage step at 0.01 s. The resistance follows the
winding's temperature: an algebraic loop of the electrical and the thermal network.
"""
from __future__ import annotations

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")

import acausal                                                     # noqa: E402
from acausal.components import electrical as el                    # noqa: E402
from acausal.components import rotational as rot                   # noqa: E402
from acausal.components import thermal as th                       # noqa: E402
from importers import fmusim                                       # noqa: E402
from test_native_events import RTOL, VERSIONS                      # noqa: E402

T_END, DT = 0.5, 0.005                  # s
C_WINDING, G_AMBIENT, T_AMBIENT = 2.0, 0.5, 293.15     # J/K, W/K, K
SIGNALS = ["rotor.w", "inductor.i", "winding.T", "resistor.R_actual"]


def heated_motor() -> acausal.Model:
    m = acausal.Model("heated_motor")
    m.source = el.StepVoltage(V=12.0, startTime=0.01)
    m.resistor = el.Resistor(R=0.5, alpha=0.004, T_ref=T_AMBIENT, useHeatPort=True)
    m.inductor, m.emf = el.Inductor(L=0.01), el.RotationalEMF(k=0.2)
    m.rotor, m.load = rot.Inertia(J=0.01), rot.Damper(d=0.05, useHeatPort=True)
    m.fixed, m.ground = rot.Fixed(), el.Ground()
    m.winding = th.HeatCapacitor(C=C_WINDING, T_start=T_AMBIENT)
    m.cooling, m.ambient = th.ThermalConductor(G=G_AMBIENT), th.FixedTemperature(T=T_AMBIENT)
    for a, b in [(m.source.p, m.resistor.p), (m.resistor.n, m.inductor.p),
                 (m.inductor.n, m.emf.p), (m.emf.n, m.source.n), (m.source.n, m.ground.p),
                 (m.emf.flange, m.rotor.flange_a), (m.rotor.flange_b, m.load.flange_a),
                 (m.load.flange_b, m.fixed.flange), (m.resistor.heatPort, m.winding.port),
                 (m.load.heatPort, m.winding.port), (m.winding.port, m.cooling.port_a),
                 (m.cooling.port_b, m.ambient.port)]:
        m.connect(a, b)
    return m


@pytest.fixture(scope="module")
def exported(fmu_dir):
    compiled = acausal.compile(heated_motor())
    grid = np.linspace(0.0, T_END, int(round(T_END / DT)) + 1)
    ref = compiled.simulate(T_END, t=grid, rtol=1e-12, atol=1e-12)
    fmus = {v: compiled.export_fmu(fmu_dir / f"heated_motor{v[0]}.fmu", fmi_version=v,
                                   stop_time=T_END) for v in VERSIONS}
    fmus["pythonfmu"] = compiled.export_fmu(fmu_dir / "heated_motor_py.fmu",
                                            backend="pythonfmu", fmu_type="cs")
    return compiled, ref, fmus


def check(ref, t, value):
    for n in SIGNALS:
        v = np.interp(ref.t, t, value(n))
        err = np.max(np.abs(v - ref[n])) / np.max(np.abs(ref[n]))
        assert err < RTOL, (n, err)


def test_heat_balance_of_the_reference():
    """The winding's heat: C·(T − T0) = ∫ (i²R(T) + d·w² − G·(T − T_amb)) dt, to 1e-8 of
    the heat taken up, from the recorded currents and speeds (trapezoids on a fine grid)."""
    compiled = acausal.compile(heated_motor())
    t = np.linspace(0.0, T_END, 20001)
    r = compiled.simulate(T_END, t=t, rtol=1e-12, atol=1e-12)
    R = 0.5 * (1 + 0.004 * (r["winding.T"] - T_AMBIENT))
    np.testing.assert_allclose(r["resistor.R_actual"], R, rtol=1e-12)
    power = r["inductor.i"] ** 2 * R + 0.05 * r["rotor.w"] ** 2 \
        - G_AMBIENT * (r["winding.T"] - T_AMBIENT)
    heat = np.concatenate([[0.0], np.cumsum(np.diff(t) * (power[1:] + power[:-1]) / 2)])
    stored = C_WINDING * (r["winding.T"] - T_AMBIENT)
    assert np.max(np.abs(heat - stored)) < 1e-8 * np.max(np.abs(stored))


@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
@pytest.mark.parametrize("version", VERSIONS)
def test_fmpy_reproduces_simulate(exported, version, kind):
    _, ref, fmus = exported
    res = fmpy.simulate_fmu(str(fmus[version]), stop_time=T_END, output_interval=DT,
                            fmi_type=kind, relative_tolerance=1e-10, output=SIGNALS)
    check(ref, res["time"], lambda n: res[n])


@pytest.mark.parametrize("kind", ["me", "cs"])
@pytest.mark.parametrize("version", VERSIONS)
def test_fmusim_reproduces_simulate(exported, version, kind, tmp_path):
    _, ref, fmus = exported
    res = fmusim(fmus[version], kind, T_END, DT, {}, SIGNALS, tmp_path)
    check(ref, res["time"], lambda n: res[n])


def test_pythonfmu_backend_reproduces_simulate(exported):
    _, ref, fmus = exported
    res = fmpy.simulate_fmu(str(fmus["pythonfmu"]), stop_time=T_END, output_interval=DT,
                            output=SIGNALS)
    check(ref, res["time"], lambda n: res[n])


PULSE_END, PULSE_DT = 0.3, 0.004        # s


@pytest.fixture(scope="module")
def pulsed_rc(fmu_dir):
    """A PulseVoltage (5 V, 30 % of 0.1 s from 0.02 s) charging C = 2 mF through 10 Ohm."""
    m = acausal.Model("pulsed_rc")
    m.source = el.PulseVoltage(V=5.0, width=30.0, period=0.1, startTime=0.02)
    m.resistor, m.capacitor, m.ground = el.Resistor(R=10.0), el.Capacitor(C=2e-3), el.Ground()
    for a, b in [(m.source.p, m.resistor.p), (m.resistor.n, m.capacitor.p),
                 (m.capacitor.n, m.source.n), (m.source.n, m.ground.p)]:
        m.connect(a, b)
    compiled = acausal.compile(m)
    grid = np.arange(0.0, PULSE_END + PULSE_DT / 2, PULSE_DT)
    ref = compiled.simulate(PULSE_END, t=grid, rtol=1e-12, atol=1e-12)
    return ref, {v: compiled.export_fmu(fmu_dir / f"pulsed_rc{v[0]}.fmu", fmi_version=v,
                                        stop_time=PULSE_END) for v in VERSIONS}


@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
@pytest.mark.parametrize("version", VERSIONS)
def test_fmpy_reproduces_a_pulse_source(pulsed_rc, version, kind):
    ref, fmus = pulsed_rc
    res = fmpy.simulate_fmu(str(fmus[version]), stop_time=PULSE_END,
                            output_interval=PULSE_DT, fmi_type=kind,
                            relative_tolerance=1e-10, output=["capacitor.v", "source.v"])
    for n in ("capacitor.v", "source.v"):
        v = np.interp(ref.t, res["time"], res[n])
        assert np.max(np.abs(v - ref[n])) < RTOL * np.max(np.abs(ref[n])), n
