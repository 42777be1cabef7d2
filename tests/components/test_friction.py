"""Coulomb friction elements (MSL's PartialFriction mode machine on state events) against
closed forms (always) and MSL's published reference result of Rotational.Examples.Friction
(when the collection is at hand): a flywheel braked to rest (stop time, speed, friction work), a bearing below
its breakaway torque staying at rest, breaking away on a ramp at peak·tau0 and sliding on a
speed-dependent table (a linear ODE), a clutch locking two inertias (momentum and energy), a
block on a support friction at rest below breakaway and sliding to a stop, a translational
brake free without normal force and braking after a step of it."""
import numpy as np
import pytest
from scipy.optimize import brentq

import acausal
from acausal.components import rotational as rot
from acausal.components import translational as tr
from acausal.components.friction import table_value, check_table
from acausal.components.signals import Constant, Ramp, Sine, Step
from acausal.errors import ParameterError
from acausal.models import RotationalFriction
from acausal.models.friction import START

TOL = dict(rtol=1e-10, atol=1e-12)


# ---- the characteristic table ------------------------------------------------------------
def test_table_interpolates_and_extrapolates_through_the_last_two_rows():
    import casadi as ca
    tab = check_table([[0, 1.0], [1, 3.0], [3, 4.0]], "tau_pos", "bearing")
    x = ca.SX.sym("x")
    f = ca.Function("f", [x], [table_value(tab, x)])
    xs = np.array([-1.0, 0.0, 0.5, 1.0, 2.0, 3.0, 5.0])
    ref = np.interp(xs, tab[:, 0], tab[:, 1])
    ref[0], ref[-1] = 1.0 - 2.0, 4.0 + 0.5 * 2.0          # through the first / last two rows
    assert np.abs(np.array(f(xs)).ravel() - ref).max() < 1e-14


@pytest.mark.parametrize("table", [[[1.0, 2.0], [0.5, 3.0]], [[0, 1, 2]], [[-1.0, 1.0]],
                                   [["a", 1.0]]])
def test_bad_tables_are_refused(table):
    with pytest.raises(ParameterError, match=r"BearingFriction\.tau_pos"):
        rot.BearingFriction(tau_pos=table)


def test_peak_below_one_is_refused():
    with pytest.raises(ParameterError, match="peak.*>= 1"):
        tr.SupportFriction(peak=0.5)


# ---- rotational --------------------------------------------------------------------------
J, W0, FN, MU = 2.0, 3.0, 10.0, 0.5          # flywheel, its speed, brake's normal force, mu


def braked_flywheel():
    model = acausal.Model("flywheel")
    model.fly = rot.Inertia(J=J)
    model.brake = rot.Brake(fn_max=FN, cgeo=1.0, mu_pos=[[0.0, MU]])
    model.on = Constant(k=1.0)
    model.connect(model.fly.flange_b, model.brake.flange_a)
    model.connect(model.on.y, model.brake.f_normalized)
    return model


@pytest.fixture(scope="module")
def braked():
    return acausal.compile(braked_flywheel()).simulate(3.0, x0={"fly.w": W0}, **TOL)


def test_brake_stops_a_flywheel_at_the_analytic_time(braked):
    tau = MU * FN
    t_stop = J * W0 / tau
    start, stop = braked.events
    assert start.time == 0.0 and start.modes == {"brake.mode": (3.0, 1.0)}   # unknown -> fwd
    assert stop.time == pytest.approx(t_stop, abs=1e-9)
    assert (stop.indicator, stop.modes) == ("brake.sliding", {"brake.mode": (1.0, 0.0)})
    assert stop.reinit["fly.w"][1] == 0.0
    right = np.flatnonzero(braked.t == stop.time)[-1]          # the event's right limit
    after = np.arange(len(braked.t)) >= right
    assert np.abs(braked["fly.w"][after]).max() <= 1e-12
    before = np.arange(len(braked.t)) < right
    assert np.abs(braked["fly.w"][before] - (W0 - tau / J * braked.t[before])).max() < 1e-9
    phi_stop = W0 * t_stop - 0.5 * tau / J * t_stop ** 2
    assert np.abs(braked["fly.phi"][after] - phi_stop).max() < 1e-9
    assert np.all(braked["brake.tau"][before] == pytest.approx(tau, abs=1e-12))
    assert np.all(braked["brake.locked"][after] == 1)
    assert np.abs(braked["brake.tau"][after]).max() < 1e-12        # nothing to hold
    assert braked["brake.tau0"][0] == pytest.approx(tau) and braked["brake.free"][0] == 0


def test_brake_friction_work_and_kinetic_energy_keep_the_initial_energy(braked):
    """Friction work ∫ lossPower dt = ∫ tau dphi, tau piecewise constant (exact sums)."""
    tau, phi = braked["brake.tau"], braked["fly.phi"]
    work = np.concatenate([[0.0], np.cumsum(tau[:-1] * np.diff(phi))])
    energy = work + 0.5 * J * braked["fly.w"] ** 2
    assert np.abs(energy - 0.5 * J * W0 ** 2).max() < 1e-8
    loss = braked["brake.lossPower"]
    assert np.allclose(loss, tau * braked["fly.w"], atol=1e-12)



def test_brake_on_a_fixed_support_takes_the_reaction():
    """useSupport=True, the support fixed: the same stop time; support.tau = −tau (MSL)."""
    model = acausal.Model("supported")
    model.fly, model.fixed = rot.Inertia(J=J), rot.Fixed()
    model.brake = rot.Brake(fn_max=FN, mu_pos=[[0.0, MU]], useSupport=True)
    model.on = Constant(k=1.0)
    model.connect(model.fly.flange_b, model.brake.flange_a)
    model.connect(model.brake.support, model.fixed.flange)
    model.connect(model.on.y, model.brake.f_normalized)
    res = acausal.compile(model).simulate(2.0, x0={"fly.w": W0}, **TOL)
    assert res.events[-1].time == pytest.approx(J * W0 / (MU * FN), abs=1e-9)
    assert np.allclose(res["brake.support.tau"], -res["brake.tau"], atol=1e-12)
    assert res["brake.support.tau"][0] == pytest.approx(-MU * FN)

TAU0, PEAK = 1.0, 1.5


def bearing_flywheel(drive, **friction):
    model = acausal.Model("bearing")
    model.fly = rot.Inertia(J=J)
    model.bearing = rot.BearingFriction(**friction)
    model.drive = drive
    model.connect(model.fly.flange_b, model.bearing.flange_a)
    model.connect(model.fly.flange_a, model.drive.flange)
    return model


def test_bearing_friction_below_breakaway_stays_at_rest():
    model = bearing_flywheel(rot.ConstantTorque(tau_constant=-1.4), tau_pos=[[0, TAU0]],
                             peak=PEAK)
    res = acausal.compile(model).simulate(10.0)
    assert [ev.modes for ev in res.events] == [{"bearing.mode": (3.0, 0.0)}]
    assert np.abs(res["fly.w"]).max() <= 1e-12 and np.abs(res["fly.phi"]).max() <= 1e-12
    assert np.allclose(res["bearing.tau"], -1.4, atol=1e-12)        # holds the drive
    assert np.allclose(res["bearing.sa"], -1.4, atol=1e-12)


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_bearing_friction_breaks_away_at_peak_on_a_ramp(sign):
    """Drive k·t: stuck until k·t = peak·tau0, then J·w' = k·t − tau0 (both directions)."""
    model = bearing_flywheel(rot.Torque(), tau_pos=[[0, TAU0]], peak=PEAK)
    model.ramp = Ramp(height=sign * 4.0, duration=4.0)              # k = 1 N.m/s
    model.connect(model.ramp.y, model.drive.tau)
    res = acausal.compile(model).simulate(4.0, **TOL)
    start, breakaway, moving = res.events
    t_b = PEAK * TAU0
    mode, flag = (1.0, "bearing.startForward") if sign > 0 else (-1.0, "bearing.startBackward")
    assert breakaway.time == pytest.approx(t_b, abs=1e-9)
    assert breakaway.indicator == "bearing.breakaway"
    assert breakaway.modes == {"bearing.mode": (0.0, mode), flag: (0.0, 1.0)}
    assert breakaway.reinit["fly.w"][1] == 0.0                     # at rest exactly
    assert (moving.indicator, moving.modes) == ("bearing.start", {flag: (1.0, 0.0)})
    assert moving.time - breakaway.time < 1e-6
    t = res.t
    w = np.where(t > t_b, (0.5 * (t ** 2 - t_b ** 2) - TAU0 * (t - t_b)) / J, 0.0)
    assert np.abs(res["fly.w"] - sign * w).max() < 1e-9


def test_bearing_friction_slides_on_its_table():
    """tau_pos = 1 + 0.2·w (two rows, extrapolated above): J·w' = T − 1 − 0.2·w from rest,
    w = (T − 1)/0.2·(1 − exp(−0.2·t/J))."""
    T = 3.0
    model = bearing_flywheel(rot.ConstantTorque(tau_constant=T),
                             tau_pos=[[0, 1.0], [1.0, 1.2]])
    res = acausal.compile(model).simulate(5.0, **TOL)
    w = (T - 1.0) / 0.2 * (1.0 - np.exp(-0.2 * res.t / J))
    assert np.abs(res["fly.w"] - w).max() < 1e-8
    assert np.abs(res["bearing.tau"] - (1.0 + 0.2 * w)).max() < 1e-8
    assert np.all(res["bearing.mode"][1:] == 1)


JA, JB = 1.0, 2.0


def test_clutch_locks_two_inertias_with_momentum_kept_and_energy_lost():
    model = acausal.Model("clutch")
    model.a, model.b = rot.Inertia(J=JA), rot.Inertia(J=JB)
    model.clutch = rot.Clutch(fn_max=FN, mu_pos=[[0.0, MU]])
    model.on = Constant(k=1.0)
    model.connect(model.a.flange_b, model.clutch.flange_a)
    model.connect(model.clutch.flange_b, model.b.flange_a)
    model.connect(model.on.y, model.clutch.f_normalized)
    res = acausal.compile(model).simulate(3.0, x0={"a.w": 10.0, "b.w": 0.0}, **TOL)
    tau = MU * FN
    t_lock = 10.0 / (tau / JA + tau / JB)
    start, lock = res.events
    assert start.modes == {"clutch.mode": (3.0, -1.0)}              # w_rel < 0: backward
    assert lock.time == pytest.approx(t_lock, abs=1e-9)
    assert lock.modes == {"clutch.mode": (-1.0, 0.0)}
    w_common = JA * 10.0 / (JA + JB)
    after = res.t >= t_lock
    assert np.abs(res["clutch.w_rel"][after][1:]).max() <= 1e-12
    assert np.abs(res["b.w"][after] - w_common).max() < 1e-9
    before = ~after
    assert np.abs(res["b.w"][before] - tau / JB * res.t[before]).max() < 1e-9
    assert np.allclose(res["clutch.tau"][before], -tau, atol=1e-12)
    energy = 0.5 * (JA * res.final("a.w") ** 2 + JB * res.final("b.w") ** 2)
    lost = 0.5 * JA * JB / (JA + JB) * 10.0 ** 2
    assert energy == pytest.approx(0.5 * JA * 10.0 ** 2 - lost, abs=1e-8)


def test_clutch_is_free_without_normal_force():
    model = acausal.Model("open")
    model.a, model.b = rot.Inertia(J=JA), rot.Inertia(J=JB)
    model.clutch = rot.Clutch(fn_max=FN)
    model.off = Constant(k=0.0)
    model.connect(model.a.flange_b, model.clutch.flange_a)
    model.connect(model.clutch.flange_b, model.b.flange_a)
    model.connect(model.off.y, model.clutch.f_normalized)
    res = acausal.compile(model).simulate(1.0, x0={"a.w": 10.0, "b.w": 0.0})
    assert np.all(res["clutch.mode"] == 2) and np.all(res["clutch.free"] == 1)
    assert np.abs(res["a.w"] - 10.0).max() < 1e-9 and np.abs(res["b.w"]).max() < 1e-12
    assert np.abs(res["clutch.tau"]).max() == 0.0


# ---- translational -----------------------------------------------------------------------
M, F0 = 2.0, 1.0


def block(push, friction):
    model = acausal.Model("block")
    model.mass = tr.Mass(m=M)
    model.friction = friction
    model.push = push
    model.connect(model.mass.flange_b, model.friction.flange_a)
    model.connect(model.push.flange, model.mass.flange_a)
    return model


def test_support_friction_below_breakaway_stays_at_rest():
    model = block(tr.ConstantForce(f_constant=1.4), tr.SupportFriction(f_pos=[[0, F0]],
                                                                       peak=PEAK))
    res = acausal.compile(model).simulate(10.0)
    assert [ev.modes for ev in res.events] == [{"friction.mode": (3.0, 0.0)}]
    assert np.abs(res["mass.v"]).max() <= 1e-12 and np.abs(res["mass.s"]).max() <= 1e-12
    assert np.allclose(res["friction.f"], 1.4, atol=1e-12)
    assert np.all(res["friction.f0_max"] == PEAK * F0)


def test_support_friction_slides_to_a_stop_with_constant_deceleration():
    """From v0 = 1 m/s backward, no push: v = −v0 + F0/M·t until t = M·v0/F0, then stuck."""
    model = block(tr.ConstantForce(f_constant=0.0), tr.SupportFriction(f_pos=[[0, F0]],
                                                                       peak=PEAK))
    res = acausal.compile(model).simulate(4.0, x0={"mass.v": -1.0}, **TOL)
    start, stop = res.events
    assert start.modes == {"friction.mode": (3.0, -1.0)}
    t_stop = M * 1.0 / F0
    assert stop.time == pytest.approx(t_stop, abs=1e-9)
    assert stop.modes == {"friction.mode": (-1.0, 0.0)}
    right = np.flatnonzero(res.t == stop.time)[-1]
    assert np.abs(res["mass.v"][right:]).max() <= 1e-12
    t = res.t[:right]
    assert np.abs(res["mass.v"][:right] - (-1.0 + F0 / M * t)).max() < 1e-9
    s_stop = -t_stop + 0.5 * F0 / M * t_stop ** 2
    assert np.abs(res["mass.s"][right:] - s_stop).max() < 1e-9
    assert np.allclose(res["friction.f"][:right], -F0, atol=1e-12)   # backward: f = -f_pos(0)
    assert np.allclose(res["friction.v"], res["mass.v"], atol=0)


def test_translational_brake_is_free_then_brakes_after_a_step_of_the_normal_force():
    """Coasting at v0 with f_normalized = 0 (free, f = 0) until t1, then fn = fn_max:
    v = v0 − mu·fn/M·(t − t1) until it stops at t1 + M·v0/(mu·fn)."""
    v0, t1 = 2.0, 1.0
    model = block(tr.ConstantForce(f_constant=0.0), tr.Brake(fn_max=FN, mu_pos=[[0, MU]]))
    model.step = Step(height=1.0, startTime=t1)
    model.connect(model.step.y, model.friction.f_normalized)
    res = acausal.compile(model).simulate(3.0, x0={"mass.v": v0}, **TOL)
    free, engaged, stop = res.events
    assert free.modes == {"friction.mode": (3.0, 2.0)}
    assert engaged.time == t1 and engaged.modes == {"friction.mode": (2.0, 1.0)}
    t_stop = t1 + M * v0 / (MU * FN)
    assert stop.time == pytest.approx(t_stop, abs=1e-9)
    t, v = res.t, res["mass.v"]
    ref = np.where(t < t1, v0, np.maximum(v0 - MU * FN / M * (t - t1), 0.0))
    right = np.flatnonzero(t == stop.time)[-1]
    assert np.abs(v[right:]).max() <= 1e-12
    assert np.abs(v - ref).max() < 1e-9
    coasting = t < t1
    assert np.all(res["friction.free"][coasting] == 1) and \
        np.all(res["friction.f"][coasting] == 0.0)
    assert np.all(res["friction.mode"][coasting] == 2)


# ---- MSL's Rotational.Examples.Friction --------------------------------------------------
def test_drive_train_with_clutch_and_brake_matches_the_msl_reference(reference_result):
    """The Modelica Association's reference result (Dymola): every continuous signal within
    2e-3 of its peak at the reference's times (the right limit at an event)."""
    ref = reference_result("MAP-LIB_ReferenceResults",
                           "Modelica.Mechanics.Rotational.Examples.Friction")
    t = ref["time"]
    res = acausal.compile(RotationalFriction()).simulate(float(t[-1]), t=t, x0=START,
                                                          rtol=1e-8, atol=1e-10)
    at = np.searchsorted(res.t, t, side="right") - 1
    assert np.array_equal(res.t[at], t)
    for name in ("clutch.phi_rel", "clutch.w_rel", "inertia3.phi", "inertia3.w",
                 "spring.phi_rel", "spring.w_rel"):
        values = ref[name]
        assert np.max(np.abs(res[name][at] - values)) < 2e-3 * np.max(np.abs(values)), name



def test_stuck_cart_breaks_away_at_a_force_step_whatever_the_roundoff_of_its_speed():
    """The friction cart-pole's cart is stuck (peak 1, f_c = 2 N) while its pole swings from
    0.3 rad, its speed off 0 by the integrator's roundoff only; the push stepped to 3 N at
    t1 (a time event, no reinit) starts forward sliding there, once (MSL keeps startForward
    until the speed leaves 0), and the cart sticks no more before t1 + 0.1 s."""
    from acausal.models import FrictionCartPole
    from acausal.simulation.inputs import Samples
    t1 = 1.0
    compiled = acausal.compile(FrictionCartPole())
    res = compiled.simulate(t1 + 0.1, x0={"hinge.phi": 0.3}, **TOL,
                            inputs={"F": Samples([0.0, t1, 2.0], [0.0, 3.0, 3.0], "hold")})
    before = res.t < t1
    assert 0 < np.abs(res["rail.v"][before]).max() <= 1e-12       # stuck, up to roundoff
    modes = [(ev.time, ev.modes["friction.mode"]) for ev in res.events
             if "friction.mode" in ev.modes]
    assert modes == [(0.0, (3.0, 0.0)), (t1, (0.0, 1.0))]
    assert np.all(res["rail.v"][res.t > t1] > 0)


def _grazing_bearing(eps):
    """A flywheel (J = 1 kg.m², at rest) on a BearingFriction (tau0 = tau0_max = 1 N.m),
    driven by T = (1 + eps)·sin(π t) N.m: T exceeds tau0 for |t − 0.5| < arccos(1/(1 + eps))/π."""
    model = acausal.Model("grazing")
    model.flywheel, model.bearing = rot.Inertia(J=1.0), rot.BearingFriction()
    model.torque = rot.Torque()
    model.sine = Sine(f=0.5, amplitude=1.0 + eps)
    for a, b in [(model.sine.y, model.torque.tau), (model.torque.flange, model.flywheel.flange_a),
                 (model.flywheel.flange_b, model.bearing.flange_a)]:
        model.connect(a, b)
    return model


@pytest.mark.parametrize("eps", [1e-7, 1e-3])
def test_a_start_that_turns_back_at_once_sticks_again_instead_of_chattering(eps):
    """T = (1 + eps)·sin(π t) just exceeds the breakaway torque 1 N.m around t = 0.5 s: the
    flywheel breaks away at t_a = 0.5 − arccos(1/(1 + eps))/π, slides with
    w = (1 + eps)(cos π t_a − cos π t)/π − (t − t_a) while w > 0 and sticks again at the
    root t_r of w (closed form). eps = 1e-7: the slide peaks at 1.9e-11 rad/s, within the
    round-off band friction.W_NOISE: its acceleration reverses while the element is still
    starting (startForward). The mode machine used to read w falling through 0 then as a
    sliding element reaching w = 0, set w to 0 and, startForward being set, kept it sliding
    forward: the friction then drove the flywheel backward (w = −0.18 rad/s at t = 1 s,
    energy from nowhere), or, where w stayed at 0 within round-off, the same event came
    again and again (MSL's Rotational HeatLosses: chattering, a SimulationError). It sticks
    again now, its speed within W_NOISE of 0. eps = 1e-3: a visible slide
    (2e-5 rad/s) that sticks again at t_r to 1e-9 s."""
    A = 1.0 + eps
    t_a = 0.5 - np.arccos(1.0 / A) / np.pi

    def w(t):
        return A * (np.cos(np.pi * t_a) - np.cos(np.pi * t)) / np.pi - (t - t_a)
    t_r = brentq(w, 0.5 + 1e-9, 0.5 + 10 * (0.5 - t_a))
    t = np.linspace(0.0, 1.0, 2001)
    res = acausal.compile(_grazing_bearing(eps)).simulate(1.0, t=t, **TOL)
    at = np.searchsorted(res.t, t, side="right") - 1
    ref = np.where((t > t_a) & (t < t_r), w(t), 0.0)
    np.testing.assert_allclose(res["flywheel.w"][at], ref, atol=2e-10 + 1e-6 * ref.max(),
                               rtol=0)
    modes = [(ev.time, ev.modes["bearing.mode"][1]) for ev in res.events
             if "bearing.mode" in ev.modes]
    assert [m for _, m in modes] == [0.0, 1.0, 0.0], modes       # stuck, slides, stuck
    assert abs(modes[1][0] - t_a) < 1e-9
    if eps > 1e-6:
        assert abs(modes[2][0] - t_r) < 1e-9
    else:           # stuck again where w leaves the band: w ≈ −3·eps·(t − t_r)
        assert t_r < modes[2][0] < t_r + 2 * 1e-10 / (3 * eps)
    assert res["bearing.mode"][-1] == 0 and abs(res["flywheel.w"][-1]) <= 1.01e-10
