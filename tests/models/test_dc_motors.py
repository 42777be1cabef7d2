"""models.DCMotorCircuit (the DC motor composed of Resistor, Inductor, RotationalEMF and
Inertia) against the closed-form steady state, the compact rotational.DCMotor, and an energy
balance of a mixed electrical / mechanical / thermal model measured by quadrature."""
from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import simpson

import acausal
from acausal.components import rotational as rot
from acausal.components import thermal as th
from acausal.models import DCMotorCircuit

TIGHT = {"rtol": 1e-12, "atol": 1e-12, "solver": "cvodes"}
M = rot.DCMotor
R, L, K, J = M.R.default, M.L.default, M.k.default, M.J.default


def drive(motor, d=0.05, J_L=0.5, useSupport=False):
    """Input v -> motor -> load Inertia J_L -> Damper d to the ground (and, with
    useSupport, the motor's housing an Inertia 2 kg.m2 on a spring to the ground)."""
    m = acausal.Model("drive")
    m.v, m.motor = acausal.Input(unit="V"), motor
    m.load, m.damper, m.fixed = rot.Inertia(J=J_L), rot.Damper(d=d), rot.Fixed()
    for a, b in [(m.v.y, m.motor.v), (m.motor.flange, m.load.flange_a),
                 (m.load.flange_b, m.damper.flange_a), (m.damper.flange_b, m.fixed.flange)]:
        m.connect(a, b)
    if useSupport:
        m.housing, m.mount = rot.Inertia(J=2.0), rot.Spring(c=500.0)
        m.connect(m.motor.support, m.housing.flange_a)
        m.connect(m.housing.flange_b, m.mount.flange_a)
        m.connect(m.mount.flange_b, m.fixed.flange)
    return m


def test_composed_motor_has_the_compact_motors_interface_and_defaults():
    motor = DCMotorCircuit()
    assert {"v", "flange"} <= set(motor.ports) and "support" not in motor.ports
    assert (motor.resistor.R, motor.inductor.L, motor.emf.k, motor.inertia.J) == (R, L, K, J)
    assert "support" in DCMotorCircuit(useSupport=True).ports
    compiled = acausal.compile(drive(DCMotorCircuit()))
    assert compiled.x_names == ["motor.inertia.phi", "motor.inertia.w", "motor.inductor.i"]
    assert compiled.z_names == []                 # the network is eliminated: a pure ODE


def test_composed_motor_reaches_the_closed_form_steady_state():
    """On a damper d (with the load inertia): k·i = d·w and V = R·i + k·w, so
    w = V·k/(k² + R·d), i = d·w/k; the transient decays as exp(−17 t)."""
    V, d = 100.0, 0.05
    res = acausal.compile(drive(DCMotorCircuit(), d=d)).simulate(
        4.0, t=np.linspace(0, 4.0, 5), inputs={"v": V}, **TIGHT)
    w = V * K / (K * K + R * d)
    np.testing.assert_allclose(res["motor.inertia.w"][-1], w, rtol=1e-10)
    np.testing.assert_allclose(res["motor.inductor.i"][-1], d * w / K, rtol=1e-9)
    np.testing.assert_allclose(res["motor.emf.v"][-1], K * w, rtol=1e-10)


@pytest.mark.parametrize("useSupport", [False, True])
def test_composed_motor_step_response_equals_the_compact_motor(useSupport):
    """A 100 V step from rest (and a sinusoidal voltage on a motor whose housing is mounted
    elastically): speed, angle, current and air-gap torque of the two forms equal to 1e-10
    of their peaks."""
    t = np.linspace(0.0, 0.5, 501)
    v = 100.0 if not useSupport else (lambda tt: 100.0 * np.sin(2 * np.pi * 3 * tt))
    runs = [acausal.compile(drive(motor, useSupport=useSupport)).simulate(
        0.5, t=t, inputs={"v": v}, **TIGHT)
        for motor in (DCMotorCircuit(useSupport=useSupport), M(useSupport=useSupport))]
    pairs = [("motor.inertia.w", "motor.w"), ("motor.inertia.phi", "motor.phi"),
             ("motor.inductor.i", "motor.i"), ("motor.emf.tauElectrical", "motor.tau_el"),
             ("motor.emf.v", "motor.vi"), ("load.w", "load.w")]
    if useSupport:
        pairs.append(("housing.w", "housing.w"))
    for composed, compact in pairs:
        peak = np.max(np.abs(runs[1][compact]))
        assert peak > 0.1, compact
        np.testing.assert_allclose(runs[0][composed], runs[1][compact], atol=1e-10 * peak,
                                   rtol=0, err_msg=composed)


def test_electrical_energy_goes_to_motion_heat_and_the_magnetic_field():
    """A voltage-driven composed motor (resistor with alpha = 3.93e-3 1/K and heat port)
    turns a load inertia against a Damper with heat port; each heat port feeds its own
    HeatCapacitor. The electrical input ∫ v·i dt, integrated here from the recorded current
    (Simpson's rule on 40001 points), equals ½(J + J_L)w² + ½L·i² + C_R·ΔT_R + C_D·ΔT_D
    (the heat capacitors' states) to 1e-8 of the input energy."""
    C_R, C_D, T0, J_L, d = 40.0, 25.0, 300.15, 0.5, 0.05
    m = acausal.Model("mixed")
    m.v = acausal.Input(unit="V")
    m.motor = DCMotorCircuit(alpha=3.93e-3, useHeatPort=True)
    m.load, m.damper, m.fixed = rot.Inertia(J=J_L), rot.Damper(d=d, useHeatPort=True), \
        rot.Fixed()
    m.winding = th.HeatCapacitor(C=C_R, T_start=T0)
    m.brake = th.HeatCapacitor(C=C_D, T_start=T0)
    for a, b in [(m.v.y, m.motor.v), (m.motor.flange, m.load.flange_a),
                 (m.load.flange_b, m.damper.flange_a), (m.damper.flange_b, m.fixed.flange),
                 (m.motor.heatPort, m.winding.port), (m.damper.heatPort, m.brake.port)]:
        m.connect(a, b)
    t = np.linspace(0.0, 2.0, 40001)

    def voltage(tt):
        return 60.0 + 40.0 * np.sin(2 * np.pi * 2 * tt)
    res = acausal.compile(m).simulate(2.0, t=t, inputs={"v": voltage}, **TIGHT)
    i, w = res["motor.inductor.i"], res["load.w"]
    e_in = simpson(voltage(t) * i, x=t)
    stored = 0.5 * (J + J_L) * w[-1] ** 2 + 0.5 * L * i[-1] ** 2
    heat = C_R * (res["winding.T"][-1] - T0) + C_D * (res["brake.T"][-1] - T0)
    assert e_in > 1e3 and C_R * (res["winding.T"][-1] - T0) > 10.0
    assert res["motor.resistor.R_actual"][-1] > 1.01 * R          # the winding heated up
    assert abs(e_in - (stored + heat)) < 1e-8 * e_in, (e_in, stored + heat)
