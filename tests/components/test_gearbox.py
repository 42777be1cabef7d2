"""Rotational.Components.Gearbox (a LossyGear in series with an ElastoBacklash, composed of
its parts) against hand-written scipy models of the two inertias it couples."""
from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.components import rotational as rot
from acausal.components import thermal as th
from wiring import model

TIGHT = {"rtol": 1e-10, "atol": 1e-12}
J1, J2, RATIO, TAU = 0.2, 1.5, 2.0, 1.0


def drivetrain(gearbox):
    """A constant torque TAU on J1 —gearbox— J2."""
    return model("drivetrain", lambda m: [
        (m.drive.flange, m.j1.flange_a), (m.j1.flange_b, m.gearbox.flange_a),
        (m.gearbox.flange_b, m.j2.flange_a)],
        drive=rot.ConstantTorque(tau_constant=TAU), j1=rot.Inertia(J=J1), gearbox=gearbox,
        j2=rot.Inertia(J=J2))


def reference(spring, eta, y0, t):
    """J1·φ1'' = TAU + τ_s/ratio·(1/eta if J1 drives (τ_s < 0) else eta), J2·φ2'' = −τ_s,
    τ_s = spring(φ2 − φ1/ratio, ω2 − ω1/ratio): the torque of the elasticity on flange_b,
    valid while the gear rolls forward (ω1 > 0)."""
    def rhs(_, y):
        p1, w1, p2, w2 = y
        tau_s = spring(p2 - p1 / RATIO, w2 - w1 / RATIO)
        k = 1 / eta if tau_s < 0 else eta
        return [w1, (TAU + tau_s / RATIO * k) / J1, w2, -tau_s / J2]
    return solve_ivp(rhs, (t[0], t[-1]), y0, dense_output=True, rtol=1e-11, atol=1e-12,
                     method="DOP853", max_step=1e-3).sol(t)


@pytest.mark.parametrize("eta", [1.0, 0.8])
def test_elastic_gearbox_without_backlash(eta):
    """b = 0: a spring-damper c, d behind the gear; ideal or with the mesh efficiency eta
    both ways (lossTable [[0, eta, eta, 0, 0]]), the gear rolling forward from ω1 = 1 rad/s."""
    c, d = 200.0, 2.0
    table = [[0.0, eta, eta, 0.0, 0.0]]
    m = drivetrain(rot.Gearbox(ratio=RATIO, lossTable=table, c=c, d=d))
    t = np.linspace(0.0, 2.0, 201)
    res = acausal.compile(m).simulate(2.0, t=t, x0={"j1.w": 1.0, "j2.w": 0.5}, **TIGHT)
    t = res.t
    p1, w1, p2, w2 = reference(lambda x, v: c * x + d * v, eta, [0.0, 1.0, 0.0, 0.5], t)
    assert np.all(w1 > 0)
    np.testing.assert_allclose(res["j1.w"], w1, atol=1e-6)
    np.testing.assert_allclose(res["j2.w"], w2, atol=1e-6)
    np.testing.assert_allclose(res["gearbox.elastoBacklash.phi_rel"], p2 - p1 / RATIO,
                               atol=1e-8)


def test_gearbox_with_backlash_against_scipy():
    """b = 0.2 rad, d = 0, ideal gear: no torque while |phi_rel| ≤ b/2, c·(phi_rel ∓ b/2)
    in contact; J2 starts at rest in the middle of the backlash, J1 at 2 rad/s."""
    c, b = 500.0, 0.2

    def spring(x, v):
        return c * (x - np.sign(x) * b / 2) if abs(x) > b / 2 else 0.0

    m = drivetrain(rot.Gearbox(ratio=RATIO, c=c, b=b))
    t = np.linspace(0.0, 1.5, 151)
    res = acausal.compile(m).simulate(1.5, t=t, x0={"j1.w": 2.0}, **TIGHT)
    t = res.t
    p1, w1, p2, w2 = reference(spring, 1.0, [0.0, 2.0, 0.0, 0.0], t)
    np.testing.assert_allclose(res["j1.w"], w1, atol=1e-5)
    np.testing.assert_allclose(res["j2.w"], w2, atol=1e-5)
    assert set(np.unique(res["gearbox.elastoBacklash.contact"])) >= {0, 1}


def test_gearbox_losses_leave_through_the_heat_port():
    """useHeatPort: the heat flow into a HeatCapacitor at the gearbox's heatPort is the
    mechanical power lost, TAU·ω1 − d/dt(kinetic and spring energy)."""
    c, d, eta = 200.0, 2.0, 0.8
    m = drivetrain(rot.Gearbox(ratio=RATIO, lossTable=[[0.0, eta, eta, 0.0, 0.0]], c=c, d=d,
                               useHeatPort=True))
    m.heat = th.HeatCapacitor(C=1.0, T_start=293.15)
    m.connect(m.gearbox.heatPort, m.heat.port)
    t = np.linspace(0.0, 2.0, 401)
    res = acausal.compile(m).simulate(2.0, t=t, x0={"j1.w": 1.0, "j2.w": 0.5}, **TIGHT)
    p1, w1, p2, w2 = reference(lambda x, v: c * x + d * v, eta, [0.0, 1.0, 0.0, 0.5], t)
    energy = 0.5 * J1 * w1 ** 2 + 0.5 * J2 * w2 ** 2 + 0.5 * c * (p2 - p1 / RATIO) ** 2
    heat = (res["heat.T"] - 293.15) * 1.0
    work = TAU * p1
    np.testing.assert_allclose(heat, work - (energy - energy[0]), atol=1e-5)


def test_gearbox_needs_a_positive_spring_constant():
    with pytest.raises(acausal.ParameterError, match="c"):
        rot.Gearbox(c=0.0)
