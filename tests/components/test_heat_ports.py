"""Mechanical losses through MSL's conditional heatPort (useHeatPort=True): the heat absorbed
by heat capacitors equals the drop of the mechanical energy, through events too; the eddy
current brakes and MSL's examples against their published reference results."""
from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.components import rotational as rot
from acausal.components import signals as sig
from acausal.components import thermal as th
from acausal.components import translational as tr
from acausal.models import (RotationalEddyCurrentBrake, RotationalHeatLosses,
                            TranslationalEddyCurrentBrake, TranslationalHeatLosses)
from acausal.models.eddy_current_brakes import START_ROTATIONAL, START_TRANSLATIONAL

TIGHT = dict(rtol=1e-10, atol=1e-12)
T0 = 293.15


def test_a_damper_heats_its_capacitor_by_the_kinetic_energy_it_takes():
    """A translational Damper between a sliding mass (10 m/s) and the ground, its heatPort on
    a HeatCapacitor: C·(T − T0) = ½ m (v0² − v²) = ∫ lossPower dt, to 1e-8 of the total."""
    m, C = 2.0, 3.0
    model = acausal.Model("damped")
    model.mass, model.damper, model.fixed = tr.Mass(m=m), tr.Damper(d=0.5, useHeatPort=True), \
        tr.Fixed()
    model.cap = th.HeatCapacitor(C=C)
    for a, b in [(model.mass.flange_b, model.damper.flange_a),
                 (model.damper.flange_b, model.fixed.flange),
                 (model.damper.heatPort, model.cap.port)]:
        model.connect(a, b)
    res = acausal.compile(model).simulate(10.0, t=np.linspace(0, 10, 51),
                                          x0={"mass.v": 10.0}, **TIGHT)
    heat = C * (res["cap.T"] - T0)
    taken = 0.5 * m * (100.0 - res["mass.v"] ** 2)
    assert heat[-1] > 0.9 * 100.0
    np.testing.assert_allclose(heat, taken, atol=1e-8 * heat[-1], rtol=0)
    np.testing.assert_allclose(res["damper.lossPower"], 0.5 * res["mass.v"] ** 2, rtol=1e-12)


def test_a_braked_flywheel_heats_its_brake_until_it_sticks():
    """A flywheel (J = 2 kg.m², 30 rad/s) braked from t = 0.5 s (a Step on f_normalized, a
    time event) until it sticks (a state event): the brake's heat capacitor takes ½ J (w0² −
    w²) to 1e-8 of the total, and nothing after the flywheel has stopped."""
    J, C, w0 = 2.0, 5.0, 30.0
    model = acausal.Model("braked")
    model.flywheel, model.brake = rot.Inertia(J=J), rot.Brake(fn_max=100.0, useHeatPort=True)
    model.cap, model.step = th.HeatCapacitor(C=C), sig.Step(startTime=0.5)
    for a, b in [(model.flywheel.flange_b, model.brake.flange_a),
                 (model.brake.heatPort, model.cap.port), (model.step.y, model.brake.f_normalized)]:
        model.connect(a, b)
    res = acausal.compile(model).simulate(3.0, t=np.linspace(0, 3, 61),
                                          x0={"flywheel.w": w0}, **TIGHT)
    stops = [ev.time for ev in res.events if ev.modes.get("brake.mode", (None, None))[1] == 0]
    assert len(stops) == 1 and 0.5 < stops[0] < 3.0
    heat = C * (res["cap.T"] - T0)
    total = 0.5 * J * w0 ** 2
    np.testing.assert_allclose(heat, 0.5 * J * (w0 ** 2 - res["flywheel.w"] ** 2),
                               atol=1e-8 * total, rtol=0)
    assert abs(heat[-1] - total) < 1e-8 * total


def test_a_brake_engaged_by_a_normal_force_rising_from_zero_slides_at_once():
    """f_normalized = sin(2π t) from t = 0 (MSL's HeatLosses drives its brake so): fn = 0 is
    free (MSL's relation fn <= 0, which changes at events only), fn > 0 an event right after
    0; the flywheel (J = 1 kg.m², 10 rad/s) slides against tau = mu·fn_max·sin(2π t) while
    fn > 0: w(t) = 10 − 5(1 − cos 2πt)/(2π), free again from 0.5 s; heat = kinetic energy lost."""
    model = acausal.Model("sine_brake")
    model.flywheel, model.brake = rot.Inertia(J=1.0), rot.Brake(fn_max=10.0, useHeatPort=True)
    model.cap, model.sine = th.HeatCapacitor(C=1.0), sig.Sine(f=1.0)
    for a, b in [(model.flywheel.flange_b, model.brake.flange_a),
                 (model.brake.heatPort, model.cap.port), (model.sine.y, model.brake.f_normalized)]:
        model.connect(a, b)
    t = np.linspace(0.0, 0.75, 16)
    res = acausal.compile(model).simulate(0.75, t=t, x0={"flywheel.w": 10.0}, **TIGHT)
    at = np.searchsorted(res.t, t, side="right") - 1
    w = 10.0 - 5.0 * (1 - np.cos(2 * np.pi * np.minimum(t, 0.5))) / (2 * np.pi)
    np.testing.assert_allclose(res["flywheel.w"][at], w, atol=1e-8)
    np.testing.assert_allclose(res["cap.T"] - T0, 0.5 * (100.0 - res["flywheel.w"] ** 2),
                               atol=1e-8 * 50.0)
    modes = [(ev.time, ev.modes["brake.mode"][1]) for ev in res.events if "brake.mode" in ev.modes]
    assert [m for _, m in modes] == [2.0, 1.0, 2.0] and modes[1][0] < 1e-9
    assert abs(modes[2][0] - 0.5) < 1e-9


def test_a_clutch_heats_its_capacitor_by_the_energy_lost_while_it_slips():
    """Two inertias (1 and 3 kg.m², 40 and 0 rad/s) joined by a Clutch engaged from t = 0.2 s
    until they lock: the heat equals the kinetic energy lost, ½ J1 w1² + ½ J2 w2² below its
    start, to 1e-8; after locking (common speed 10 rad/s) the loss is J1 J2/(J1 + J2)·w0²/2."""
    J1, J2, w0, C = 1.0, 3.0, 40.0, 2.0
    model = acausal.Model("clutched")
    model.a, model.b = rot.Inertia(J=J1), rot.Inertia(J=J2)
    model.clutch = rot.Clutch(fn_max=50.0, useHeatPort=True)
    model.cap, model.step = th.HeatCapacitor(C=C), sig.Step(startTime=0.2)
    for a, b in [(model.a.flange_b, model.clutch.flange_a), (model.clutch.flange_b, model.b.flange_a),
                 (model.clutch.heatPort, model.cap.port), (model.step.y, model.clutch.f_normalized)]:
        model.connect(a, b)
    res = acausal.compile(model).simulate(3.0, t=np.linspace(0, 3, 61),
                                          x0={"a.w": w0, "b.w": 0.0}, **TIGHT)
    heat = C * (res["cap.T"] - T0)
    lost = 0.5 * J1 * w0 ** 2 - 0.5 * J1 * res["a.w"] ** 2 - 0.5 * J2 * res["b.w"] ** 2
    final = J1 * J2 / (J1 + J2) * w0 ** 2 / 2
    np.testing.assert_allclose(heat, lost, atol=1e-8 * final, rtol=0)
    assert abs(res["b.w"][-1] - 10.0) < 1e-9 and abs(heat[-1] - final) < 1e-8 * final


@pytest.mark.parametrize("build, start, dotted, signals", [
    (RotationalEddyCurrentBrake, START_ROTATIONAL, "Rotational.Examples.EddyCurrentBrake",
     ("inertia.phi", "heatCapacitor.T", "eddyCurrentTorque.lossPower")),
    (TranslationalEddyCurrentBrake, START_TRANSLATIONAL, "Translational.Examples.EddyCurrentBrake",
     ("mass.s", "heatCapacitor.T", "eddyCurrentForce.lossPower"))])
def test_eddy_current_brake_matches_the_msl_reference(reference_result, build, start, dotted,
                                                      signals):
    """MSL's EddyCurrentBrake (the reference's version: full excitation from t = 0): the
    comparison signals within 2e-3 of their peaks; the heat capacitor takes the kinetic energy
    to 1e-8 (C = 1 J/K, J = 1 kg.m² or m = 1 kg)."""
    ref = reference_result("MAP-LIB_ReferenceResults", f"Modelica.Mechanics.{dotted}")
    t = ref["time"]
    res = acausal.compile(build()).simulate(float(t[-1]), t=t, x0=start, **TIGHT)
    for name in signals:
        err = np.max(np.abs(res[name] - ref[name]))
        assert err < 2e-3 * np.max(np.abs(ref[name])), (name, err)
    speed = res["inertia.w"] if "inertia.w" in res.names else res["mass.v"]
    np.testing.assert_allclose(res["heatCapacitor.T"] - T0, 0.5 * (400.0 - speed ** 2),
                               atol=1e-8 * 200.0, rtol=0)


def test_eddy_current_brake_with_the_ramped_excitation_of_the_later_msl():
    """ramp=True (the later MSL version): no braking before 0.1 s, then the heat capacitor
    takes the kinetic energy to 1e-8; the nominal speed rises with the temperature:
    w_normalized = w/(10·(1 + alpha20·(T − 293.15)))."""
    res = acausal.compile(RotationalEddyCurrentBrake(ramp=True)).simulate(
        1.0, t=np.linspace(0, 1, 101), x0=START_ROTATIONAL, **TIGHT)
    early = res.t <= 0.1
    assert np.all(res["inertia.w"][early] == 20.0) and res["inertia.w"][-1] < 5.0
    np.testing.assert_allclose(res["heatCapacitor.T"] - T0,
                               0.5 * (400.0 - res["inertia.w"] ** 2), atol=2e-6, rtol=0)
    T = res["heatCapacitor.T"]
    np.testing.assert_allclose(res["eddyCurrentTorque.w_normalized"],
                               res["inertia.w"] / (10.0 * (1 + 3.92e-3 * (T - T0))), rtol=1e-12)


HEAT_LOSSES_SIGNALS = ("damper.s_rel", "damper.v_rel", "massWithStopAndFriction.s",
                       "massWithStopAndFriction.v", "springDamper.s_rel", "springDamper.v_rel",
                       "springDamper1.s_rel", "springDamper1.v_rel")
HEAT_LOSSES_MODES = ("brake.mode", "massWithStopAndFriction.mode", "supportFriction.mode")


def _clusters(times):
    """The first time of each run of mode changes closer than 1e-4 s to the previous one (a
    start from rest settles in a few changes: the reference's 2 → 1 → 0, acausal's 2 → −1 → 0
    within 1e-6 s)."""
    times = list(times)
    return [x for k, x in enumerate(times) if k == 0 or x - times[k - 1] > 1e-4]


def test_translational_heat_losses_matches_the_msl_reference(reference_result):
    """MSL's Translational.Examples.HeatLosses over its 2 s: every compared signal within
    2e-3 of its peak and every mode change within 1e-4 s of the reference's, through the
    stop's impacts (0.4285 s, 1.4992 s: reinit(v, 0) keeps springDamper1's relative states,
    so mass3 jumps by −v of the stopped mass, as in the reference); the convection takes the
    sum of the seven elements' lossPower: solid.T = 298.15 K + Σ lossPower/20 W/K."""
    ref = reference_result("MAP-LIB_ReferenceResults",
                           "Modelica.Mechanics.Translational.Examples.HeatLosses")
    t = ref["time"]
    res = acausal.compile(TranslationalHeatLosses()).simulate(
        float(t[-1]), t=t, x0=TranslationalHeatLosses.START, rtol=1e-10, atol=1e-12)
    at = np.searchsorted(res.t, t, side="right") - 1
    # the reference's rows at its event instants, which may fall a nanosecond before ours
    # (a jump there compares a left limit with a right one), are left out
    away = np.min(np.abs(t[:, None] - np.array([ev.time for ev in res.events])[None, :]),
                  axis=1) > 1e-6
    for name in HEAT_LOSSES_SIGNALS:
        err = np.max(np.abs(res[name][at] - ref[name])[away])
        assert err < 2e-3 * np.max(np.abs(ref[name])), (name, err)
    for name in HEAT_LOSSES_MODES:
        ref_changes = t[1:][np.diff(ref[name]) != 0]
        ours = [ev.time for ev in res.events
                if name in ev.modes and ev.modes[name][0] != ev.modes[name][1] and ev.time > 0]
        ours, theirs = _clusters(ours), _clusters(ref_changes)
        assert len(ours) == len(theirs), (name, ours, theirs)
        assert np.max(np.abs(np.array(ours) - theirs), initial=0) < 1e-4, name
    impacts = [ev for ev in res.events
               if ev.indicator == "massWithStopAndFriction.gap_max" and ev.direction == -1]
    assert len(impacts) == 2
    for ev in impacts:           # mass3 jumps with the stopped mass: v_rel kept
        (v_before, v_after), (v3_before, v3_after) = (
            ev.reinit["massWithStopAndFriction.v"], ev.reinit["mass3.v"])
        assert v_after == 0 and abs(v3_after - (v3_before - v_before)) < 1e-12
    losses = sum(res[f"{c}.lossPower"] for c in (
        "damper", "springDamper", "elastoGap", "supportFriction", "brake",
        "massWithStopAndFriction", "springDamper1"))
    np.testing.assert_allclose(res["convection.Q_flow"], losses, atol=1e-9)
    np.testing.assert_allclose(res["convection.solid.T"], 298.15 + losses / 20.0, atol=1e-10)


def _rotational_heat_losses_with_meters():
    """MSL's Rotational HeatLosses with meters that change nothing: the torque's work
    W = ∫ sine.y·inertia1.w dt and the heat through the convection
    Q = ∫ Gc·(solid.T − 298.15 K) dt (Gc = 20 W/K), both integrator states."""
    m = RotationalHeatLosses()
    m.speed, m.power, m.work = rot.SpeedSensor(), sig.Product(), sig.Integrator()
    m.temperature, m.ambient = th.TemperatureSensor(), sig.Constant(k=298.15)
    m.dT, m.heat = sig.Add(k1=20.0, k2=-20.0), sig.Integrator()
    for a, b in [(m.inertia1.flange_b, m.speed.flange), (m.sine.y, m.power.u1),
                 (m.speed.w, m.power.u2), (m.power.y, m.work.u),
                 (m.convection.solid, m.temperature.port), (m.temperature.T, m.dT.u1),
                 (m.ambient.y, m.dT.u2), (m.dT.y, m.heat.u)]:
        m.connect(a, b)
    return m


ROTATIONAL_LOSSES = ("damper", "springDamper", "elastoBacklash", "bearingFriction", "lossyGear",
                     "clutch", "oneWayClutch", "brake")


@pytest.fixture(scope="module")
def rotational_heat_losses():
    t = np.linspace(0.0, 1.0, 10001)                     # MSL's experiment: 1 s, 1e-4 s
    return acausal.compile(_rotational_heat_losses_with_meters()).simulate(
        1.0, t=t, x0=RotationalHeatLosses.START, rtol=1e-10, atol=1e-12)


def test_rotational_heat_losses_sends_every_loss_to_the_convection(rotational_heat_losses):
    """MSL's Rotational.Examples.HeatLosses (its published reference result is not at hand):
    the convection takes the sum of the eight elements' lossPower at every instant
    (convection.Q_flow = Σ lossPower, solid.T = 298.15 K + Σ lossPower/20 W/K), so the heat
    it passes, integrated by a meter from Gc·(solid.T − T_ambient), equals ∫ Σ lossPower dt
    to 1e-8 of the total; every loss is ≥ 0."""
    res = rotational_heat_losses
    losses = sum(res[f"{c}.lossPower"] for c in ROTATIONAL_LOSSES)
    peak = np.max(np.abs(losses))
    assert peak > 1.0 and res["heat.y"][-1] > 0.1
    for c in ROTATIONAL_LOSSES:
        assert np.min(res[f"{c}.lossPower"]) >= -1e-9 * peak, c
    np.testing.assert_allclose(res["convection.Q_flow"], losses, atol=1e-9 * peak, rtol=0)
    np.testing.assert_allclose(res["convection.solid.T"], 298.15 + losses / 20.0,
                               atol=1e-10 * peak, rtol=0)
    # the meter integrates Gc·dT, equal to Σ lossPower at every instant: their integrals agree
    np.testing.assert_allclose(res["dT.y"], losses, atol=1e-9 * peak, rtol=0)


def test_rotational_heat_losses_keeps_the_energy_balance(rotational_heat_losses):
    """The torque's work W = kinetic energy Σ ½ J w² + spring energy (springDamper,
    spring3: ½ c phi_rel²; elastoBacklash ½ c (phi_diff ∓ b/2)² while it pushes) + the heat
    the convection passed + the energy MSL's ElastoBacklash drops without reporting it as
    lossPower (when tau_c + tau_d stops pushing while the spring is still deflected, tau
    and lossPower are 0: its spring energy then is lost, the jump of the pushing energy at
    those events), to 1e-8 of W at every output time."""
    res = rotational_heat_losses
    kinetic = sum(0.5 * 2.0 * res[f"inertia{k}.w"] ** 2 for k in range(1, 7))
    springs = 0.5 * 1e4 * (res["springDamper.phi_rel"] ** 2 + res["spring3.phi_rel"] ** 2)
    pushing = 0.5 * 1e5 * (res["elastoBacklash.phi_diff"] - res["elastoBacklash.contact"]
                           * 0.0005) ** 2 * res["elastoBacklash.pushing"]
    jumps = np.flatnonzero(np.diff(res.t) == 0)                 # left, right limits
    dropped = np.zeros_like(res.t)
    for k in jumps:
        dropped[k + 1:] += pushing[k] - pushing[k + 1]
    work = res["work.y"]
    assert work[-1] > 0.1 and np.max(dropped) > 0
    residual = work - kinetic - springs - pushing - dropped - res["heat.y"]
    assert np.max(np.abs(residual)) < 1e-8 * work[-1], np.max(np.abs(residual))


def test_rotational_heat_losses_first_contact_and_breakaway_as_a_scipy_model(
        rotational_heat_losses):
    """Until the bearing breaks away everything behind the elastoBacklash is at rest (held
    by the stuck bearing, gear, clutches and brake): inertia1 (torque 20 sin 10πt, damper
    d = 10 to the ground) and inertia2 joined by the springDamper, and from phi2 = b/2 =
    0.0005 rad the elastoBacklash's lower contact on inertia2 (tau = tau_c + max(tau_c,
    tau_d), tau_c = c (−phi2 + b/2), tau_d = −d w2, while tau_c + tau_d < 0). A hand-written
    scipy model of this gives the contact time, the bearing's breakaway (|tau| = 1 N.m) and
    the motion to 1e-8."""
    J, b = 2.0, 0.001

    def tau_backlash(phi2, w2):
        tc, td = 1e5 * (-phi2 + b / 2), -100.0 * w2
        return np.where((phi2 > b / 2) & (tc + td < 0), tc + np.maximum(tc, td), 0.0)

    def rhs(t, y):
        phi1, w1, phi2, w2 = y
        sd = 1e4 * (phi2 - phi1) + 20.0 * (w2 - w1)
        return [w1, (20 * np.sin(10 * np.pi * t) - 10.0 * w1 + sd) / J, w2,
                (-sd + tau_backlash(phi2, w2)) / J]

    def contact(t, y):
        return y[2] - b / 2
    contact.terminal, contact.direction = True, 1

    def breakaway(t, y):
        return -tau_backlash(y[2], y[3]) - 1.0
    breakaway.terminal, breakaway.direction = True, 1

    opts = dict(method="LSODA", rtol=1e-12, atol=1e-14)
    first = solve_ivp(rhs, (0, 0.1), [0, 0, 0, 0], events=contact, dense_output=True, **opts)
    t_contact = first.t_events[0][0]
    second = solve_ivp(rhs, (t_contact, 0.1), first.y[:, -1], events=breakaway,
                       dense_output=True, **opts)
    t_break = second.t_events[0][0]
    res = rotational_heat_losses

    def when(indicator, direction):
        return [ev.time for ev in res.events if ev.indicator == indicator
                and ev.direction == direction]
    assert abs(when("elastoBacklash.bMin", -1)[0] - t_contact) < 1e-8
    assert abs(when("bearingFriction.breakaway", -1)[0] - t_break) < 1e-8
    t = np.unique(res.t[res.t < t_break])
    at = np.searchsorted(res.t, t)
    ref = np.where(t < t_contact, first.sol(t), second.sol(t))
    assert len(t) > 300
    np.testing.assert_allclose(res["inertia1.w"][at], ref[1], atol=1e-8)
    np.testing.assert_allclose(res["inertia2.phi"][at], ref[2], atol=1e-10)
    assert np.max(np.abs(res["inertia3.w"][res.t < t_break])) < 1e-15
