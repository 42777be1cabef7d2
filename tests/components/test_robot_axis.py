"""MSL's RobotR3 OneAxis against its reference result, and the blocks it brought, each against
a closed form: KinematicPTP2's trapezoidal and bang-bang profiles, IdealOpAmp amplifiers,
InitializeFlange's start values, steady-state initial equations, TerminateSimulation's
stop time."""
from __future__ import annotations

import math

import numpy as np
import pytest

import acausal
from acausal.components import electrical as el
from acausal.components import rotational as rot
from acausal.components import signals as sig
from acausal.errors import InitializationError, ParameterError, StructureError
from acausal.models.robot_axis import STOP_TIME, GearType2, Motor, OneAxis
from fast_spin import fast_enough
from wiring import model

ONE_AXIS = "Modelica.Mechanics.MultiBody.Examples.Systems.RobotR3.OneAxis"
FRICTION = "axis.gear.bearingFriction."


def changes(t, values):
    """(time, new value) wherever ``values`` changes."""
    k = np.flatnonzero(np.diff(values) != 0) + 1
    return list(zip(t[k], values[k]))


# ---- MSL's OneAxis -----------------------------------------------------------------------
def test_one_axis_matches_the_msl_reference(reference_result):
    """Every comparison signal within 2e-3 of its peak (the worst is 5e-4, w_rel); the run
    terminates where the reference ends, path.endTime + swingTime = 1.4981317 s; the
    bearing friction's mode changes in the reference's order, to its values, within 1e-4 s
    (the largest difference is 3.7e-5 s); every change of startForward / startBackward of
    the reference is matched within 1e-4 s. Ours sets startForward / startBackward also at
    the other breakaways (0.00065 s, 0.998 s, 1.354 s), for the instant until the speed
    leaves 0 (< 1e-6 s: the friction element's W_NOISE), where the reference clears them
    within the event iteration, so its output never shows them."""
    ref = reference_result("MAP-LIB_ReferenceResults", ONE_AXIS)
    t = ref["time"]
    res = acausal.compile(OneAxis()).simulate(STOP_TIME, t=np.append(t, STOP_TIME),
                                              rtol=1e-8, atol=1e-10)
    assert res.terminated is not None
    assert res.terminated.component == "pathPlanning.terminateSimulation"
    assert res.terminated.time == pytest.approx(t[-1], abs=1e-12)
    assert res.t[-1] == res.terminated.time
    # right limits at the reference's times (its phase changes of the path, time events,
    # are ours to rounding)
    at = np.searchsorted(res.t, t + 1e-12, side="right") - 1
    assert np.abs(res.t[at] - t).max() < 1e-12
    for name in ["axis.controller.PI.x", "axis.gear.spring.phi_rel", "axis.gear.spring.w_rel",
                 "axis.initializeFlange.phi_flange", "axis.initializeFlange.w_flange",
                 "axis.motor.C.v", "axis.motor.La.i"]:
        err = np.max(np.abs(res[name][at] - ref[name]))
        assert err < 2e-3 * np.max(np.abs(ref[name])), (name, err)
    ours, theirs = changes(res.t, res[FRICTION + "mode"]), changes(t, ref[FRICTION + "mode"])
    assert [v for _, v in ours] == [v for _, v in theirs] == [1, -1, 0, -1, 0, 1]
    assert np.abs(np.subtract([a for a, _ in ours], [a for a, _ in theirs])).max() < 1e-4
    for flag in ("startForward", "startBackward"):
        ours = changes(res.t, res[FRICTION + flag])
        for when, value in changes(t, ref[FRICTION + flag]):
            assert any(abs(a - when) < 1e-4 and v == value for a, v in ours), (flag, when)
        ons = [a for a, v in ours if v == 1]
        offs = [a for a, v in ours if v == 0]
        assert len(ons) == len(offs) and np.all(np.subtract(offs, ons) < 1e-6), flag


def test_motor_starts_in_steady_state_and_stays_there():
    """MSL's Motor with its rotor held and a constant reference current of 2 A: the initial
    equations der(C.v) = 0, der(La.i) = 0 give the steady state of the current loop, the
    armature current equal to the reference (the PI op-amp integrates any difference) and
    the capacitor at the voltage that drives it through Ra; nothing moves after."""
    m = model("held_motor", lambda m: [(m.ref.y, m.motor.current_ref),
                                        (m.motor.flange_motor, m.fixed.flange)],
              ref=sig.Constant(k=2.0), motor=Motor(), fixed=rot.Fixed())
    res = acausal.compile(m).simulate(0.01)
    i, v = res["motor.La.i"], res["motor.C.v"]
    assert i[0] == pytest.approx(2.0, abs=1e-9)
    # OpI's output is C.n (C.p held at ground by the nullator: C.v = −v(C.n)); the power
    # stage is non-inverting, 1 + Rp1/Rp2 = 5, and drives Ra = 250 Ω (La, the EMF at rest
    # and hall1 drop nothing): Ra·i = 5·(−C.v)
    assert v[0] == pytest.approx(-250 * 2.0 / 5, rel=1e-9)
    assert np.ptp(i) < 1e-9 and np.ptp(v) < 1e-6


@pytest.mark.parametrize("tau", [0.2, 0.3])
def test_gear_type2_holds_below_its_peak_and_slides_above(tau):
    """GearType2 (ratio −99, bearing friction Rv0 = 21.8 N.m, Rv1 = 9.8 N.m.s/rad, peak
    26.7/21.8 on the driven side) between a motor inertia J1 = 1e-3 kg.m² under tau and a
    load J2 = 1 kg.m²: the driven side sees i·tau, 19.8 N.m (above Rv0, below the peak
    26.7 N.m: held) or 29.7 N.m (breaks away at once and slides backward); sliding,
    (J1·i² + J2)·dw/dt = i·tau + Rv0 − Rv1·w, so w = w_end·(1 − exp(−Rv1·t/(J1·i² + J2)))
    with w_end = (i·tau + Rv0)/Rv1."""
    m = model("gear2", lambda m: [(m.src.y, m.torque.tau), (m.torque.flange, m.J1.flange_a),
                                  (m.J1.flange_b, m.gear.flange_a),
                                  (m.gear.flange_b, m.J2.flange_a)],
              src=sig.Constant(k=tau), torque=rot.Torque(), J1=rot.Inertia(J=1e-3),
              gear=GearType2(), J2=rot.Inertia(J=1.0))
    res = acausal.compile(m).simulate(2.0, rtol=1e-10, atol=1e-12)
    w = res["J2.w"]
    if tau * 99 < 26.7:
        assert np.abs(w).max() < 1e-12
        assert set(res["gear.bearingFriction.mode"][1:]) == {0}
        return
    J, w_end = 1e-3 * 99 ** 2 + 1.0, (-99 * tau + 21.8) / 9.8
    assert np.abs(w - w_end * (1 - np.exp(-9.8 * res.t / J))).max() < 1e-8
    assert np.abs(res["J1.w"] + 99 * w).max() < 1e-9


# ---- KinematicPTP2 -----------------------------------------------------------------------
def ptp_by_hand(t, dq, qd_max, qdd_max, t0=0.0):
    """The fastest rest-to-rest motion by dq within qd_max, qdd_max (one axis): (q, qd, qdd)
    at times t, written from the textbook profile (trapezoid, or triangle when qd_max is
    not reached)."""
    a, v = qdd_max, qd_max
    ta = v / a
    if a * ta ** 2 >= abs(dq):               # triangle: accelerate half way, brake
        ta = math.sqrt(abs(dq) / a)
        v, tc = a * ta, 0.0
    else:
        tc = (abs(dq) - a * ta ** 2) / v
    sgn = math.copysign(1.0, dq)
    q, qd, qdd = (np.zeros_like(t) for _ in range(3))
    for k, tk in enumerate(t - t0):
        if tk < 0:
            continue
        if tk < ta:
            q[k], qd[k], qdd[k] = a * tk ** 2 / 2, a * tk, a
        elif tk < ta + tc:
            q[k], qd[k] = a * ta ** 2 / 2 + v * (tk - ta), v
        elif tk < 2 * ta + tc:
            tb = 2 * ta + tc - tk
            q[k], qd[k], qdd[k] = abs(dq) - a * tb ** 2 / 2, a * tb, -a
        else:
            q[k] = abs(dq)
    return sgn * q, sgn * qd, sgn * qdd, t0 + 2 * ta + tc


def ptp_model(**kw):
    return model("ptp", lambda m: [], ptp=sig.KinematicPTP2(**kw))


@pytest.mark.parametrize("dq, qd_max, qdd_max", [(2.0, 1.0, 2.0), (-0.5, 2.0, 2.0)],
                         ids=["trapezoid", "bang-bang"])
def test_kinematic_ptp2_follows_the_closed_form_profile(dq, qd_max, qdd_max):
    """q, qd, qdd and moving against the textbook profile (start 0.2 s, from q = 0.3),
    endTime its end; the phase changes are time events (the output is exact there)."""
    t = np.linspace(0.0, 3.5, 701)
    res = acausal.compile(ptp_model(q_begin=0.3, q_end=0.3 + dq, qd_max=qd_max,
                                    qdd_max=qdd_max, startTime=0.2)).simulate(3.5, t=t)
    q, qd, qdd, end = ptp_by_hand(res.t, dq, qd_max, qdd_max, t0=0.2)
    assert np.abs(res["ptp.q[1]"] - 0.3 - q).max() < 1e-12
    assert np.abs(res["ptp.qd[1]"] - qd).max() < 1e-12
    assert np.abs(res["ptp.qdd[1]"] - qdd).max() < 1e-12
    assert res["ptp.endTime"][0] == pytest.approx(end, abs=1e-12)
    assert np.array_equal(res["ptp.moving[1]"], (res.t < end).astype(float))


def test_kinematic_ptp2_synchronizes_the_axes():
    """Two axes (nout from the longest vector, q_begin given once for both): the slower
    one (axis 2: 3 rad at 1 rad/s) sets the profile, axis 1 moves on the same normalized
    path, so both arrive together; an axis that does not move is never ``moving``."""
    t = np.linspace(0.0, 4.0, 401)
    m = model("ptp", lambda m: [], ptp=sig.KinematicPTP2(q_begin=[0.0], q_end=[1.0, 3.0, 0.0],
                                                         qd_max=[5.0, 1.0, 1.0],
                                                         qdd_max=[10.0, 2.0, 1.0]))
    res = acausal.compile(m).simulate(4.0, t=t)
    q2, qd2, _, end = ptp_by_hand(res.t, 3.0, 1.0, 2.0)
    assert np.abs(res["ptp.q[2]"] - q2).max() < 1e-12
    assert np.abs(res["ptp.q[1]"] - q2 / 3).max() < 1e-12
    assert np.abs(res["ptp.qd[1]"] - qd2 / 3).max() < 1e-12
    assert res["ptp.endTime"][0] == pytest.approx(end)
    assert not res["ptp.moving[3]"].any() and not res["ptp.q[3]"].any()


def test_kinematic_ptp2_refuses_bad_limits():
    with pytest.raises(ParameterError, match=r"KinematicPTP2\.qd_max\[1\].*> 0"):
        sig.KinematicPTP2(qd_max=0.0)
    with pytest.raises(ParameterError, match=r"KinematicPTP2\.qdd_max\[2\].*> 0"):
        sig.KinematicPTP2(q_end=[1.0, 2.0], qdd_max=[1.0, -1.0])
    with pytest.raises(ParameterError, match="qd_max has 2 elements.*nout = 3"):
        sig.KinematicPTP2(q_end=[1.0, 2.0, 3.0], qd_max=[1.0, 2.0])
    compiled = acausal.compile(ptp_model())
    with pytest.raises(Exception, match=r"ptp\.qd_max\[1\].*> 0"):
        compiled.simulate(1.0, params={"ptp.qd_max[1]": -2.0})


# ---- IdealOpAmp ---------------------------------------------------------------------------
def amplifier(inverting: bool, R1=1e3, R2=4.7e3, V=2.0, f=3.0):
    """An IdealOpAmp with feedback R2 from its output p2 to the input n1 (p1 grounded, the
    input through R1 into n1: inverting; or R1 from n1 to ground, the source at p1:
    non-inverting), the output port's n2 grounded. An RL branch across the source gives
    the network a state (a network without one is not integrated)."""
    def pairs(m):
        common = [(m.rf.p, m.amp.n1), (m.rf.n, m.amp.p2), (m.amp.n2, m.g.p),
                  (m.src.n, m.g.p), (m.load.p, m.amp.p2), (m.load.n, m.g.p),
                  (m.src.p, m.l.p), (m.l.n, m.rl.p), (m.rl.n, m.g.p)]
        if inverting:
            return common + [(m.src.p, m.r1.p), (m.r1.n, m.amp.n1), (m.amp.p1, m.g.p)]
        return common + [(m.src.p, m.amp.p1), (m.r1.p, m.amp.n1), (m.r1.n, m.g.p)]
    return model("amplifier", pairs, src=el.SineVoltage(V=V, f=f), amp=el.IdealOpAmp(),
                 r1=el.Resistor(R=R1), rf=el.Resistor(R=R2), load=el.Resistor(R=100.0),
                 l=el.Inductor(L=0.1), rl=el.Resistor(R=10.0), g=el.Ground())


@pytest.mark.parametrize("inverting, gain", [(True, -4.7), (False, 5.7)],
                         ids=["inverting", "non-inverting"])
def test_ideal_op_amp_amplifiers_have_their_closed_form_gain(inverting, gain):
    """v_out = −R2/R1·v_in (inverting), (1 + R2/R1)·v_in (non-inverting); the nullator
    takes no current and holds v1 = 0; the norator supplies the load and the feedback."""
    t = np.linspace(0.0, 0.5, 101)
    res = acausal.compile(amplifier(inverting)).simulate(0.5, t=t)
    vin = 2.0 * np.sin(2 * np.pi * 3.0 * t)
    vout = res["amp.v2"]
    # the potentials are algebraic variables, IDAS's interpolation at the output times
    assert np.abs(vout - gain * vin).max() < 1e-8 * np.abs(gain * 2.0)
    assert np.abs(res["amp.v1"]).max() < 1e-12 and np.abs(res["amp.i1"]).max() == 0
    i_feedback = (vout - (0 if inverting else vin)) / 4.7e3
    assert np.abs(res["amp.i2"] + vout / 100.0 + i_feedback).max() < 1e-8 * 0.1


def test_ideal_op_amp_integrator_ramps():
    """An inverting integrator (R into n1, C from n1 to the output) on a constant 1.5 V:
    v_out = −V·t/(R·C), the capacitor a state of the network."""
    R, C, V = 1e3, 1e-4, 1.5
    m = model("integrator", lambda m: [
        (m.src.p, m.r.p), (m.r.n, m.amp.n1), (m.c.p, m.amp.n1), (m.c.n, m.amp.p2),
        (m.amp.p1, m.g.p), (m.amp.n2, m.g.p), (m.src.n, m.g.p)],
        src=el.ConstantVoltage(V=V), r=el.Resistor(R=R), c=el.Capacitor(C=C),
        amp=el.IdealOpAmp(), g=el.Ground())
    res = acausal.compile(m).simulate(0.2)
    assert np.abs(res["amp.v2"] + V * res.t / (R * C)).max() < 1e-9


def test_ideal_op_amp_without_feedback_is_refused():
    """Open loop, nothing fixes the norator's output (the nullator's v1 = 0 contradicts the
    source through R): the structural check names the amplifier."""
    m = model("open_loop", lambda m: [
        (m.src.p, m.r.p), (m.r.n, m.amp.p1), (m.amp.n1, m.g.p), (m.src.n, m.g.p),
        (m.amp.p2, m.load.p), (m.load.n, m.g.p), (m.amp.n2, m.g.p)],
        src=el.ConstantVoltage(V=1.0), r=el.Resistor(R=1.0), amp=el.IdealOpAmp(),
        load=el.Resistor(R=1.0), g=el.Ground())
    with pytest.raises(StructureError, match="IdealOpAmp 'amp'"):
        acausal.compile(m)


# ---- InitializeFlange, initial equations ---------------------------------------------------
def test_initialize_flange_sets_angle_and_speed():
    """An inertia (2 kg.m²) under 4 N.m, started by InitializeFlange at the inputs'
    0.3 rad and 2 rad/s: phi = 0.3 + 2·t + t² (no acceleration start: use_a_start=False,
    which has no a_start input)."""
    init = rot.InitializeFlange(use_a_start=False)
    assert "a_start" not in init.ports
    m = model("init", lambda m: [(m.torque.flange, m.inertia.flange_a),
                                 (m.init.flange, m.inertia.flange_b),
                                 (m.tau.y, m.torque.tau), (m.phi0.y, m.init.phi_start),
                                 (m.w0.y, m.init.w_start)],
              torque=rot.Torque(), inertia=rot.Inertia(J=2.0), init=init,
              tau=sig.Constant(k=4.0), phi0=sig.Constant(k=0.3), w0=sig.Constant(k=2.0))
    res = acausal.compile(m).simulate(1.0)
    assert np.abs(res["init.phi_flange"] - (0.3 + 2 * res.t + res.t ** 2)).max() < 1e-8
    assert np.abs(res["init.w_flange"] - (2 + 2 * res.t)).max() < 1e-8


def test_initialize_flange_acceleration_places_a_spring():
    """A 2 kg.m² inertia on a 100 N.m/rad spring to the ground, started at rest with the
    acceleration −5 rad/s² (use_phi_start=False): the spring must be wound to
    phi0 = J·5/c = 0.1 rad, and the inertia oscillates as 0.1·cos(ω·t), ω = √(c/J)."""
    m = model("wound", lambda m: [(m.fixed.flange, m.spring.flange_a),
                                  (m.spring.flange_b, m.inertia.flange_a),
                                  (m.init.flange, m.inertia.flange_b),
                                  (m.w0.y, m.init.w_start), (m.a0.y, m.init.a_start)],
              fixed=rot.Fixed(), spring=rot.Spring(c=100.0), inertia=rot.Inertia(J=2.0),
              init=rot.InitializeFlange(use_phi_start=False), w0=sig.Constant(k=0.0),
              a0=sig.Constant(k=-5.0))
    res = acausal.compile(m).simulate(1.0, rtol=1e-10, atol=1e-12)
    assert np.abs(res["inertia.phi"] - 0.1 * np.cos(math.sqrt(50.0) * res.t)).max() < 1e-8


def test_initial_equations_that_contradict_x0_are_named():
    m = model("init", lambda m: [(m.init.flange, m.inertia.flange_a),
                                 (m.phi0.y, m.init.phi_start), (m.w0.y, m.init.w_start)],
              inertia=rot.Inertia(J=1.0), init=rot.InitializeFlange(use_a_start=False),
              phi0=sig.Constant(k=0.3), w0=sig.Constant(k=0.0))
    compiled = acausal.compile(m)
    with pytest.raises(InitializationError, match="inertia.phi"):
        compiled.simulate(1.0, x0={"inertia.phi": 1.0})


def test_part_must_be_a_part():
    class Outsider(acausal.Model):
        def physics(self, e):
            e.part(lonely)

    lonely = rot.Inertia()
    m = Outsider("outsider")
    m.inertia = rot.Inertia()
    with pytest.raises(StructureError, match="is not a part of it"):
        acausal.compile(m)


# ---- TerminateSimulation -------------------------------------------------------------------
def test_terminate_simulation_stops_at_the_condition():
    """An inertia (2 kg.m²) under 3 N.m from rest, the run to end when its speed exceeds
    4.5 rad/s (GreaterThreshold, a state event): at t = 4.5·2/3 = 3 s, located to the event
    tolerance; the Result ends there and says why; the grid after it is left out."""
    m = fast_enough()
    res = acausal.compile(m).simulate(10.0)
    assert res.terminated.time == pytest.approx(3.0, abs=1e-11)
    assert res.terminated.component == "stop" and res.terminated.message == "fast enough"
    assert "fast enough" in str(res.terminated)
    assert res.t[-1] == res.terminated.time and res.t[-2] < 3.0 + 1e-11
    assert res["inertia.w"][-1] == pytest.approx(4.5, abs=1e-9)
    untouched = acausal.compile(model("free", lambda m: [(m.tau.y, m.torque.tau),
                                                         (m.torque.flange, m.inertia.flange_a)],
                                      torque=rot.Torque(), inertia=rot.Inertia(),
                                      tau=sig.Constant(k=1.0))).simulate(1.0)
    assert untouched.terminated is None
