"""Translational.Components.RollingResistance and Vehicle against references written here
from MSL's source (Modelica/Mechanics/Translational/Components/RollingResistance.mo and
Vehicle.mo), not from acausal: the rolling resistance's closed form at prescribed speeds
through its regularization band, the Vehicle's equation of motion integrated by scipy, and
the Vehicle's energy balance.

MSL's Vehicle computes its inclination force with Blocks.Math.Atan and Math.Sin; acausal's
Vehicle writes those inside its own equations, so no such block is needed here (nor in MSL's
Examples.Vehicle, in test_msl_examples_translational.py).
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid, solve_ivp

import acausal
from acausal.components import rotational as rot
from acausal.components import translational as tr
from time_signals import TimeSignal

G_N = 9.80665
TOL = dict(rtol=1e-10, atol=1e-12)


def msl_direction(v, v0, reg: str):
    """MSL's RollingResistance: the factor of −f_nominal for each Regularization."""
    x = np.asarray(v) / v0
    band = np.abs(x) < 1
    if reg == "Exp":
        return 2 / (1 + np.exp(-x / 0.01)) - 1
    inner = {"Sine": np.sin(np.pi / 2 * x), "Linear": x,
             "CoSine": np.sign(x) * (1 - np.cos(np.pi / 2 * x))}[reg]
    return np.where(band, inner, np.sign(x))


# =========================================================================================
# RollingResistance
# =========================================================================================
@pytest.mark.parametrize("reg", ["Exp", "Sine", "Linear", "CoSine"])
@pytest.mark.parametrize("inputs", [False, True], ids=["constants", "inputs"])
def test_rolling_resistance_is_its_closed_form(reg, inputs):
    """A flange moved at v(t) = 0.05·t − 0.25 m/s (through v0 = 0.1 m/s both ways) against
    f = flange.f = Cr·fWeight·cos(atan(inclination))·reg(v/v0) (MSL: f = −f_nominal·...,
    f_nominal = −Cr·fWeight·cos(atan(inclination))), with Cr, inclination constants or the
    inputs cr(t) = 0.01 + 0.002·t, inclination(t) = 0.2·sin(t)."""
    m = acausal.Model("roll")
    m.roll = tr.RollingResistance(fWeight=1500, CrConstant=0.012, inclinationConstant=0.15,
                                  v0=0.1, reg=reg, useCrInput=inputs,
                                  useInclinationInput=inputs)
    m.speed = tr.Speed(exact=True)
    m.v_ref = TimeSignal(fn=lambda t: 0.05 * t - 0.25)
    m.connect(m.v_ref.y, m.speed.v_ref)
    m.connect(m.speed.flange, m.roll.flange)
    if inputs:
        m.cr = TimeSignal(fn=lambda t: 0.01 + 0.002 * t)
        m.inclination = TimeSignal(fn=lambda t: 0.2 * ca.sin(t))
        m.connect(m.cr.y, m.roll.cr)
        m.connect(m.inclination.y, m.roll.inclination)
    t = np.linspace(0.0, 10.0, 401)
    res = acausal.compile(m).simulate(10.0, t=t, **TOL)
    t = res.t
    v = 0.05 * t - 0.25
    cr, inclination = (0.01 + 0.002 * t, 0.2 * np.sin(t)) if inputs else (0.012, 0.15)
    f_nominal = -cr * 1500 * np.cos(np.arctan(inclination))
    np.testing.assert_allclose(res["roll.v"], v, rtol=0, atol=1e-9)
    np.testing.assert_allclose(res["roll.f_nominal"], f_nominal * np.ones_like(t), rtol=1e-9)
    np.testing.assert_allclose(res["roll.f"], -f_nominal * msl_direction(v, 0.1, reg),
                               rtol=0, atol=1e-6)
    inside = np.abs(v) < 0.1
    assert inside.any() and (~inside).any()


def test_rolling_resistance_brakes_a_coasting_mass():
    """A mass (10 kg) coasting from 1 m/s against Linear rolling resistance Cr·fWeight = 2 N
    (v0 = 1e-3 m/s): v = 1 − 0.2·t until the band, then v ∝ exp(−(2/v0)/m·t) inside it."""
    m = acausal.Model("coast")
    m.mass = tr.Mass(m=10)
    m.roll = tr.RollingResistance(fWeight=200, CrConstant=0.01, v0=1e-3, reg="Linear")
    m.connect(m.mass.flange_b, m.roll.flange)
    t = np.linspace(0.0, 5.5, 1101)
    res = acausal.compile(m).simulate(5.5, t=t, x0={"mass.v": 1.0}, **TOL)
    t_band = (1 - 1e-3) / 0.2
    before = res.t <= t_band
    np.testing.assert_allclose(res["mass.v"][before], 1 - 0.2 * res.t[before], atol=1e-9)
    after = res.t > t_band
    expected = 1e-3 * np.exp(-(2 / 1e-3) / 10 * (res.t[after] - t_band))
    np.testing.assert_allclose(res["mass.v"][after], expected, rtol=0, atol=1e-9)


# =========================================================================================
# Vehicle
# =========================================================================================
VEHICLE = dict(m=1200.0, J=3.0, R=0.3, A=2.2, Cd=0.3, rho=1.2, CrConstant=0.012, vReg=1e-3,
               vWindConstant=-2.0)


def drive_torque(t):
    """τ(t) [N.m]: forward, then backward through standstill."""
    return 400 * np.cos(0.25 * t) if isinstance(t, (float, np.ndarray)) \
        else 400 * ca.cos(0.25 * t)


def inclination_of(t):
    return 0.08 * np.sin(0.2 * t) if isinstance(t, (float, np.ndarray)) \
        else 0.08 * ca.sin(0.2 * t)


def wind_of(t):
    return -2.0 + 1.5 * np.sin(t) if isinstance(t, (float, np.ndarray)) \
        else -2.0 + 1.5 * ca.sin(t)


def cr_of(t):
    return 0.012 + 0.001 * t


def scipy_vehicle(t_eval, inputs: bool, load: float):
    """MSL's Vehicle by hand: (m + J/R²)·a = τ/R + load − fDrag − fRoll + fGrav, fDrag =
    Cd·A·rho/2·(v − vw)·|v − vw|, fRoll = Cr·m·g·cos(α)·clip(v/vReg, −1, 1), fGrav =
    −m·g·sin(α), α = atan(inclination); with inputs, the wind vw passes windSpeed's filter
    der(vw) = (vWind − vw)·2π·50 from vw(0) = vWind(0). Integrated between the crossings of
    |v| = vReg (where the law has corners), as Modelica's events."""
    p = VEHICLE
    m_eff = p["m"] + p["J"] / p["R"] ** 2

    def rhs(t, y):
        s, v, vw = y
        alpha = math.atan(inclination_of(t))
        cr = cr_of(t) if inputs else p["CrConstant"]
        wind = vw if inputs else p["vWindConstant"]
        f_drag = p["Cd"] * p["A"] * p["rho"] / 2 * (v - wind) * abs(v - wind)
        f_roll = cr * p["m"] * G_N * math.cos(alpha) * min(max(v / p["vReg"], -1.0), 1.0)
        f_grav = -p["m"] * G_N * math.sin(alpha)
        a = (drive_torque(t) / p["R"] + load - f_drag - f_roll + f_grav) / m_eff
        dvw = (wind_of(t) - vw) * 2 * math.pi * 50 if inputs else 0.0
        return [v, a, dvw]

    events = [lambda t, y: y[1] - p["vReg"], lambda t, y: y[1] + p["vReg"]]
    for ev in events:
        ev.terminal = True
    t0, y0, ts, ys = 0.0, [0.0, 0.0, wind_of(0.0) if inputs else 0.0], [], []
    while True:
        sol = solve_ivp(rhs, (t0, t_eval[-1]), y0, method="Radau", rtol=1e-11, atol=1e-12,
                        dense_output=True, events=events)
        ts.append(sol.t)
        ys.append(sol.sol)
        if sol.status == 0:
            break
        t0, y0 = sol.t[-1], sol.y[:, -1]
        y0[1] += 1e-12 * np.sign(rhs(t0, y0)[1])
    out = np.empty((3, len(t_eval)))
    for k, t in enumerate(t_eval):
        piece = next(i for i, tt in enumerate(ts) if t <= tt[-1] + 1e-12)
        out[:, k] = ys[piece](t)
    return out


@pytest.mark.parametrize("inputs", [False, True], ids=["constants", "inputs"])
def test_vehicle_matches_the_msl_equations_by_scipy(inputs):
    """A vehicle driven at flangeR by τ(t) through standstill, on the inclination(t) input,
    loaded at flangeT by a constant −150 N; with ``inputs`` also wind and Cr as inputs
    (vWind(t), cr(t)), else the constants vWindConstant = −2 m/s, CrConstant."""
    m = acausal.Model("drive")
    options = dict(useInclinationInput=True, useWindInput=inputs, useCrInput=inputs)
    m.vehicle = tr.Vehicle(**VEHICLE, **options)
    m.torque, m.tau = rot.Torque(), TimeSignal(fn=drive_torque)
    m.load, m.f = tr.Force(), TimeSignal(fn=lambda t: -150.0 + 0 * t)
    m.inclination = TimeSignal(fn=inclination_of)
    for a, b in [(m.tau.y, m.torque.tau), (m.torque.flange, m.vehicle.flangeR),
                 (m.f.y, m.load.f), (m.load.flange, m.vehicle.flangeT),
                 (m.inclination.y, m.vehicle.inclination)]:
        m.connect(a, b)
    if inputs:
        m.wind, m.cr = TimeSignal(fn=wind_of), TimeSignal(fn=cr_of)
        m.connect(m.wind.y, m.vehicle.vWind)
        m.connect(m.cr.y, m.vehicle.cr)
    t = np.linspace(0.0, 30.0, 601)
    res = acausal.compile(m).simulate(30.0, t=t, **TOL)
    ref = scipy_vehicle(res.t, inputs, -150.0)
    assert np.min(res["vehicle.v"]) < -1.0 < 1.0 < np.max(res["vehicle.v"])
    np.testing.assert_allclose(res["vehicle.s"], ref[0], rtol=0, atol=1e-6)
    np.testing.assert_allclose(res["vehicle.v"], ref[1], rtol=0, atol=1e-6)
    if inputs:
        np.testing.assert_allclose(res["vehicle.vWindFiltered"], ref[2], rtol=0, atol=1e-6)
    alpha = np.arctan(inclination_of(res.t))
    np.testing.assert_allclose(res["vehicle.fGrav.f"], -1200 * G_N * np.sin(alpha),
                               rtol=1e-9)


def test_vehicle_energy_balance():
    """Driven by τ = 200 N.m up a constant 6 % grade against a 3 m/s tail wind: the work of
    τ (τ·w, w measured at flangeR) equals the kinetic energy ½(m + J/R²)·v², the potential
    energy m·g·sin(α)·s and the work dissipated by drag and rolling resistance, (fDrag.f +
    fRoll.f)·v, integrated."""
    m = acausal.Model("energy")
    m.vehicle = tr.Vehicle(m=900, J=1.5, R=0.28, inclinationConstant=0.06, vWindConstant=3)
    m.torque, m.tau = rot.Torque(), TimeSignal(fn=lambda t: 200.0 + 0 * t)
    m.w = rot.SpeedSensor()
    for a, b in [(m.tau.y, m.torque.tau), (m.torque.flange, m.vehicle.flangeR),
                 (m.w.flange, m.vehicle.flangeR)]:
        m.connect(a, b)
    t = np.linspace(0.0, 20.0, 40001)
    res = acausal.compile(m).simulate(20.0, t=t, **TOL)
    v, s = res["vehicle.v"], res["vehicle.s"]
    np.testing.assert_allclose(res["w.w"], v / 0.28, rtol=1e-12, atol=1e-12)
    work = cumulative_trapezoid(200.0 * res["w.w"], res.t, initial=0)
    lost = cumulative_trapezoid((res["vehicle.fDrag.f"] + res["vehicle.fRoll.f"]) * v, res.t,
                                initial=0)
    stored = 0.5 * (900 + 1.5 / 0.28 ** 2) * v ** 2 \
        + 900 * G_N * math.sin(math.atan(0.06)) * s
    assert v[-1] > 1.0
    np.testing.assert_allclose(work, stored + lost, rtol=0, atol=1e-6 * work[-1])


def test_vehicle_required_parameters_and_ports():
    """m, J, R have no default (MSL); the inputs exist only with their options."""
    with pytest.raises(acausal.errors.ParameterError, match="'m' have no default"):
        tr.Vehicle(J=0, R=0.3)
    vehicle = tr.Vehicle(m=1, J=0, R=0.3)
    assert {"flangeT", "flangeR"} <= set(vehicle.ports)
    assert not {"inclination", "cr", "vWind"} & set(vehicle.ports)
    vehicle = tr.Vehicle(m=1, J=0, R=0.3, useInclinationInput=True, useCrInput=True,
                         useWindInput=True)
    assert {"inclination", "cr", "vWind"} <= set(vehicle.ports)
