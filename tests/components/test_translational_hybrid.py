"""Translational friction with stops, gaps and hard stops on state events against closed forms,
a stick-slip reference written with scipy's solve_ivp and its events, energy balances, and
(where the collection is at hand) MSL's published reference results of Translational.Examples
Brake, Friction and PreLoad."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.components import translational as tr
from acausal.errors import ParameterError
from acausal.models.translational_friction import PreLoad, TranslationalBrake, \
    TranslationalFriction

TOL = dict(rtol=1e-10, atol=1e-12)
G = 9.81


# ---- MSL's examples against the MAP-LIB reference results --------------------------------
def mode_changes(t, values, merge=1e-4):
    """[(time, value after)] of a piecewise constant signal, the changes closer than
    ``merge`` [s] taken as one (the event iteration's steps) and those that undo themselves
    dropped."""
    out, k = [], 0
    idx = np.flatnonzero(np.diff(values) != 0)
    while k < len(idx):
        first, last = idx[k], idx[k]
        while k + 1 < len(idx) and t[idx[k + 1] + 1] - t[first + 1] < merge:
            k += 1
            last = idx[k]
        if values[last + 1] != values[first]:
            out.append((t[first + 1], values[last + 1]))
        k += 1
    return out


def compare(res, ref, signals, modes):
    """Every continuous signal within 2e-3 of its peak at the reference's times (those more
    than 1e-4 s from an event), every mode's changes at the same times within 1e-4 s."""
    t = ref["time"]
    at = np.searchsorted(res.t, t, side="right") - 1
    assert np.array_equal(res.t[at], t)
    events = np.array([ev.time for ev in res.events])
    away = np.array([np.min(np.abs(events - x), initial=np.inf) > 1e-4 for x in t])
    assert away.sum() > 0.9 * len(t)
    for name in signals:
        values = ref[name]
        err = np.max(np.abs(res[name][at][away] - values[away]))
        assert err < 2e-3 * np.max(np.abs(values)), (name, err)
    for name in modes:
        mine, theirs = mode_changes(res.t, res[name]), mode_changes(t, ref[name])
        assert [v for _, v in mine] == [v for _, v in theirs], name
        assert np.allclose([x for x, _ in mine], [x for x, _ in theirs], rtol=0, atol=1e-4), \
            name


def test_brake_example_matches_the_msl_reference(reference_result):
    """Two masses at 1 m/s braked from 0.1 s lock at 1.1 s (mode 2 → 1 → 0)."""
    ref = reference_result("MAP-LIB_ReferenceResults",
                           "Modelica.Mechanics.Translational.Examples.Brake")
    res = acausal.compile(TranslationalBrake()).simulate(
        TranslationalBrake.STOP_TIME, t=ref["time"], x0=TranslationalBrake.START, **TOL)
    compare(res, ref, ["mass1.s", "mass1.v", "mass2.s", "mass2.v"],
            [f"{b}.{m}" for b in ("brake", "brake1")
             for m in ("mode", "startForward", "startBackward")])
    assert [ev.time for ev in res.events if ev.indicator.endswith(".fn")] == [0.1, 0.1]
    assert [ev.time for ev in res.events if ev.indicator and not ev.indicator.endswith(".fn")] \
        == pytest.approx([1.1, 1.1], abs=1e-9)


def test_friction_example_matches_the_msl_reference(reference_result):
    """MassWithStopAndFriction driven by a sine and against its stops, and a Mass on a
    SupportFriction with the same Stribeck table: positions, speeds, breakaway, reversal,
    impact and locking times."""
    ref = reference_result("MAP-LIB_ReferenceResults",
                           "Modelica.Mechanics.Translational.Examples.Friction")
    res = acausal.compile(TranslationalFriction()).simulate(
        TranslationalFriction.STOP_TIME, t=ref["time"], x0=TranslationalFriction.START,
        rtol=1e-8, atol=1e-10)
    compare(res, ref, ["mass.s", "mass.v", "stop1.s", "stop1.v", "stop2.s", "stop2.v"],
            [f"{c}.{m}" for c in ("stop1", "stop2", "supportFriction")
             for m in ("mode", "startForward", "startBackward")])


def test_preload_example_matches_the_msl_reference(reference_result):
    """The spool held by one preloaded spring through four ElastoGaps: contact and speeds."""
    ref = reference_result("MAP-LIB_ReferenceResults",
                           "Modelica.Mechanics.Translational.Examples.PreLoad")
    res = acausal.compile(PreLoad()).simulate(PreLoad.STOP_TIME, t=ref["time"],
                                              x0=PreLoad.START, rtol=1e-8, atol=1e-10)
    compare(res, ref, ["friction.v_rel", "innerContactA.s_rel", "innerContactB.s_rel",
                       "outerContactA.v_rel", "outerContactB.s_rel", "outerContactB.v_rel"], [])


# ---- MassWithStopAndFriction: closed forms -----------------------------------------------
def sliding_block(push, **params):
    model = acausal.Model("block")
    model.block = tr.MassWithStopAndFriction(**params)
    model.push = push
    model.connect(model.push.flange, model.block.flange_a)
    return model


def test_block_pushed_below_breakaway_stays_at_rest_exactly():
    """f0_max = 1.001·(F_Coulomb + F_Stribeck) = 15.015 N; a push of 15 N holds for 10 s."""
    res = acausal.compile(sliding_block(tr.ConstantForce(f_constant=15.0))).simulate(10.0)
    assert [ev.modes for ev in res.events] == [{"block.mode": (3.0, 0.0)}]
    assert np.abs(res["block.v"]).max() <= 1e-12 and np.abs(res["block.s"]).max() <= 1e-12
    assert np.allclose(res["block.f"], 15.0, atol=1e-12)
    assert np.all(res["block.locked"] == 1) and np.all(res["block.stopped"] == 0)
    assert res["block.f0_max"][0] == pytest.approx(15.015, abs=1e-12)


def test_braked_block_locks_at_the_analytic_time():
    """m·v' = −(F_prop·v + F_Coulomb) from v0: v = (v0 + Fc/Fp)·exp(−Fp·t/m) − Fc/Fp, at
    rest from t = (m/Fp)·ln(1 + Fp·v0/Fc)."""
    m, Fp, Fc, v0 = 2.0, 0.5, 3.0, 4.0
    model = sliding_block(tr.ConstantForce(f_constant=0.0), m=m, F_prop=Fp, F_Coulomb=Fc,
                          F_Stribeck=0.0)
    res = acausal.compile(model).simulate(8.0, x0={"block.v": v0}, **TOL)
    start, stop = res.events
    t_stop = m / Fp * np.log(1 + Fp * v0 / Fc)
    assert stop.time == pytest.approx(t_stop, abs=1e-9)
    assert stop.modes == {"block.mode": (1.0, 0.0)}
    right = np.flatnonzero(res.t == stop.time)[-1]
    t = res.t[:right]
    v = (v0 + Fc / Fp) * np.exp(-Fp * t / m) - Fc / Fp
    assert np.abs(res["block.v"][:right] - v).max() < 1e-9
    assert np.abs(res["block.v"][right:]).max() <= 1e-12
    s_stop = (m / Fp) * (v0 + Fc / Fp) * (1 - np.exp(-Fp * t_stop / m)) - Fc / Fp * t_stop
    assert np.abs(res["block.s"][right:] - s_stop).max() < 1e-9 * s_stop


def test_coulomb_friction_work_and_kinetic_energy_keep_the_initial_energy():
    """F_prop = F_Stribeck = 0: friction work F_Coulomb·(distance) + ½mv² = ½mv0²."""
    m, Fc, v0 = 2.0, 3.0, 4.0
    model = sliding_block(tr.ConstantForce(f_constant=0.0), m=m, F_prop=0.0, F_Coulomb=Fc,
                          F_Stribeck=0.0)
    res = acausal.compile(model).simulate(4.0, x0={"block.v": v0}, **TOL)
    f, s = res["block.f"], res["block.s"]
    work = np.concatenate([[0.0], np.cumsum(f[:-1] * np.diff(s))])
    energy = work + 0.5 * m * res["block.v"] ** 2
    assert np.abs(energy / (0.5 * m * v0 ** 2) - 1).max() < 1e-8
    assert res.events[-1].time == pytest.approx(m * v0 / Fc, abs=1e-9)


def test_block_hits_its_stop_rests_there_and_leaves_when_pulled_back():
    """Pushed by 10 N against F_Coulomb = 4 N from rest 1 m before smax: a = 3 m/s², the stop
    at t = √(2/3) s sets v = 0; it rests there (the stop's reaction in f) however hard it
    is pushed, until the push becomes a pull of 10 N at t = 3 s, when it breaks away."""
    m, Fc, t1 = 2.0, 4.0, 3.0
    model = sliding_block(tr.ForceStep(offsetForce=10.0, stepForce=-20.0, startTime=t1),
                          m=m, F_prop=0.0, F_Coulomb=Fc, F_Stribeck=0.0, L=0.5, smax=1.25,
                          smin=-5.0)
    res = acausal.compile(model).simulate(4.0, **TOL)
    hit = next(ev for ev in res.events if ev.indicator == "block.gap_max")
    assert hit.time == pytest.approx(np.sqrt(2 * 1.0 / ((10.0 - Fc) / m)), abs=1e-9)
    assert hit.reinit["block.v"][1] == 0.0 and hit.modes["block.mode"] == (1.0, 0.0)
    resting = (res.t > hit.time) & (res.t < t1)
    assert np.abs(res["block.v"][resting]).max() <= 1e-12
    assert np.all(res["block.stopped"][resting] == 1)
    assert np.allclose(res["block.f"][resting], 10.0, atol=1e-9)     # push held by the stop
    leave = next(ev for ev in res.events if ev.time == t1)
    assert leave.modes["block.mode"] == (0.0, -1.0)
    after = res.t > t1 + 1e-6
    a = -(10.0 - Fc) / m
    assert np.allclose(res["block.v"][after], a * (res.t[after] - t1), atol=1e-9)


def test_block_smooth_form_stops_on_a_penalty_stop():
    """compile(smooth=True) (PartialFriction's smooth friction, the stop a critically damped
    penalty of c_smooth = 1e7 N/m): no modes; the stop reached at the exact time to within
    the contact's time scale, past it by about v·√(m/(2·c_smooth)) at most, resting past it
    by the push over c_smooth (the smooth friction holds nothing at v = 0)."""
    m, c = 2.0, 1e7
    model = sliding_block(tr.ConstantForce(f_constant=10.0), m=m, F_prop=0.0, F_Coulomb=4.0,
                          F_Stribeck=0.0, L=0.5, smax=1.25, smin=-5.0, c_smooth=c)
    compiled = acausal.compile(model, smooth=True)
    if compiled.mode_params:
        pytest.skip("PartialFriction has no smooth form in this tree")
    res = compiled.simulate(3.0, t=np.linspace(0, 3, 3001))
    t_hit, v_hit = np.sqrt(2 / 3), 3 * np.sqrt(2 / 3)
    assert res.t[np.argmax(res["block.s"] > 1.0)] == pytest.approx(t_hit, abs=2e-3)
    assert res["block.s"].max() - 1.0 == pytest.approx(v_hit * np.sqrt(m / (2 * c)), rel=0.05)
    assert res["block.s"][-1] - 1.0 == pytest.approx(10.0 / c, rel=1e-3)
    assert res["block.stopped"][-1] == 1


# ---- stick-slip of a mass on a moving belt against scipy ---------------------------------
M, K, V_BELT, F_C, PEAK = 1.0, 10.0, 0.5, 2.0, 1.5


def belt_model():
    """Mass on a spring to the ground and on a belt at constant speed (SupportFriction with
    its support on the belt, Coulomb F_C, stiction PEAK·F_C)."""
    model = acausal.Model("belt")
    model.ground, model.spring = tr.Fixed(), tr.Spring(c=K)
    model.mass = tr.Mass(m=M)
    model.friction = tr.SupportFriction(f_pos=[[0.0, F_C]], peak=PEAK, useSupport=True)
    model.belt = tr.ConstantSpeed(v_fixed=V_BELT)
    for a, b in [(model.ground.flange, model.spring.flange_a),
                 (model.spring.flange_b, model.mass.flange_a),
                 (model.mass.flange_b, model.friction.flange_a),
                 (model.friction.support, model.belt.flange)]:
        model.connect(a, b)
    return model


def scipy_stick_slip(t_end):
    """The same system in plain scipy: sticking (v = V_BELT) until the spring force exceeds
    PEAK·F_C, then sliding with the friction F_C against the relative speed until it is 0
    again, where it sticks if the spring force is at most PEAK·F_C. Returns the switching
    times and a dense solution (t -> x, v)."""
    t, y, stuck, switches, pieces = 0.0, np.array([0.0, V_BELT]), True, [], []
    while t < t_end:
        if stuck:
            def rhs(_, y):
                return [V_BELT, 0.0]

            def event(_, y):
                return K * abs(y[0]) - PEAK * F_C
        else:
            direction = -np.sign(K * y[0])       # the spring pulls the mass off the belt

            def rhs(_, y, d=direction):
                return [y[1], (-K * y[0] - F_C * d) / M]

            def event(_, y):
                return y[1] - V_BELT
            event.direction = np.sign(-direction)
        event.terminal = True
        sol = solve_ivp(rhs, (t, t_end), y, events=event, dense_output=True, rtol=1e-12,
                        atol=1e-14, method="DOP853")
        pieces.append((t, sol.t[-1], sol.sol))
        if sol.status != 1:
            break
        t, y = sol.t_events[0][0], sol.y_events[0][0]
        y[1] = V_BELT if not stuck else y[1]
        # MSL's rule at v_rel = 0: sliding goes on only if it still accelerates that way
        stuck = not stuck if stuck else np.sign(-K * y[0] - F_C * direction) != direction
        switches.append(t)

    def at(times):
        out = np.empty((2, len(times)))
        for i, tt in enumerate(times):
            a, b, f = next(p for p in pieces if p[0] <= tt <= p[1] + 1e-15)
            out[:, i] = f(tt)
        return out
    return switches, at


def test_stick_slip_on_a_belt_matches_an_event_driven_scipy_reference():
    t_end = 6.0
    switches, at = scipy_stick_slip(t_end)
    assert len(switches) >= 5                          # stick, slip, stick, slip, stick
    grid = np.linspace(0.0, t_end, 601)
    res = acausal.compile(belt_model()).simulate(t_end, t=grid, x0={"mass.v": V_BELT}, **TOL)
    changes = [ev.time for ev in res.events
               if any(k == "friction.mode" and a in (0.0, -1.0) and b in (0.0, -1.0) and a != b
                      for k, (a, b) in ev.modes.items())]
    assert np.allclose(changes, switches[:len(changes)], rtol=0, atol=1e-8)
    assert len(changes) == len(switches)
    ref = at(grid)
    res_at = res.t.searchsorted(grid, side="right") - 1
    assert np.abs(res["mass.s"][res_at] - ref[0]).max() < 1e-7
    far = np.array([np.min(np.abs(np.array(switches) - x)) > 1e-6 for x in grid])
    assert np.abs(res["mass.v"][res_at][far] - ref[1][far]).max() < 1e-7
    stuck = res["friction.mode"] == 0
    assert np.abs(res["mass.v"][stuck] - V_BELT).max() <= 1e-12    # exactly on the belt


# ---- HardStop: impacts with restitution, rest, release -----------------------------------
def ball(stop: tr.HardStop, m=1.0, lift=None):
    model = acausal.Model("ball")
    model.body = tr.Mass(m=m)
    model.gravity = tr.ConstantForce(f_constant=-m * G) if lift is None else lift
    model.stop = stop
    model.connect(model.gravity.flange, model.body.flange_a)
    model.connect(model.stop.flange, model.body.flange_a)
    return model


def test_hard_stop_impact_times_and_rest_match_the_bouncing_ball_closed_form():
    """Dropped from h under gravity onto smin = 0 with restitution e: impacts at
    t1 = √(2h/g), t_(k+1) = t_k + 2·e^k·v1/g (v1 = √(2gh)); the first impact slower than
    v_small ends at rest on the stop (stopped = −1, f = −m·g), no Zeno accumulation."""
    h, e, v_small, m = 1.0, 0.8, 0.05, 2.0
    res = acausal.compile(ball(tr.HardStop(smin=0.0, smax=10.0, e=e, v_small=v_small),
                               m=m)).simulate(5.0, x0={"body.s": h}, **TOL)
    impacts = [ev for ev in res.events if ev.indicator == "stop.gap_min"]
    v1 = np.sqrt(2 * G * h)
    n = next(k for k in range(1, 100) if v1 * e ** (k - 1) < v_small)
    times = np.sqrt(2 * h / G) + np.concatenate([[0.0], np.cumsum(
        [2 * e ** k * v1 / G for k in range(1, n)])])
    assert len(impacts) == n
    assert np.allclose([ev.time for ev in impacts], times, rtol=0, atol=1e-8)
    for k, ev in enumerate(impacts[:-1]):
        before, after = ev.reinit["body.v"]
        assert before == pytest.approx(-v1 * e ** k, abs=1e-8)
        assert after == pytest.approx(-e * before, abs=1e-12)
    assert impacts[-1].reinit["body.v"][1] == 0.0
    assert impacts[-1].modes == {"stop.stopped": (0.0, -1.0)}
    rest = res.t > impacts[-1].time
    assert np.abs(res["body.v"][rest]).max() <= 1e-12
    assert np.abs(res["body.s"][rest]).max() < 1e-9
    assert np.allclose(res["stop.f"][rest], -m * G, atol=1e-9)
    assert np.all(res["stop.contact"][rest] == 1)
    flying = res.t < impacts[0].time
    assert np.abs(res["stop.f"][flying]).max() <= 1e-30                # 0 up to roundoff
    assert np.all(res["stop.stopped"][flying] == 0)


def test_hard_stop_releases_the_body_when_the_force_pulls_it_away():
    """Resting on smax under a push of 3 N; from t = 1 s a pull of 5 N: released at 1 s,
    s = smax − ½·(5/m)·(t − 1)²."""
    m, smax = 2.0, 0.5
    push = tr.ForceStep(offsetForce=3.0, stepForce=-8.0, startTime=1.0)
    res = acausal.compile(ball(tr.HardStop(smin=-1.0, smax=smax), m=m, lift=push)).simulate(
        2.0, x0={"body.s": smax}, **TOL)
    assert res.events[0].modes == {"stop.stopped": (0.0, 1.0)}
    held = res.t < 1.0
    assert np.allclose(res["stop.f"][held], 3.0, atol=1e-12)
    assert np.abs(res["body.v"][held]).max() <= 1e-12
    release = next(ev for ev in res.events if "stop.stopped" in ev.modes and ev.time > 0)
    assert release.time == 1.0 and release.modes == {"stop.stopped": (1.0, 0.0)}
    after = res.t > 1.0
    assert np.allclose(res["body.s"][after], smax - 0.5 * 5.0 / m * (res.t[after] - 1) ** 2,
                       atol=1e-9)


def test_hard_stop_smooth_form_is_a_stiff_penalty_without_events():
    """compile(smooth=True): no modes; the first impact within the contact time
    π·√(m/c_smooth) of the exact one, the penetration about v1·√(m/c_smooth)."""
    h, m, c = 1.0, 1.0, 1e6
    model = ball(tr.HardStop(smin=0.0, smax=10.0, c_smooth=c, d_smooth=0.0), m=m)
    compiled = acausal.compile(model, smooth=True)
    assert not compiled.mode_params
    res = compiled.simulate(0.6, x0={"body.s": h}, t=np.linspace(0, 0.6, 6001))
    v1, t1 = np.sqrt(2 * G * h), np.sqrt(2 * h / G)
    depth = -res["body.s"].min()
    assert depth == pytest.approx(v1 * np.sqrt(m / c), rel=0.02)
    t_contact = res.t[res["body.s"] < 0]
    assert abs(t_contact[0] - t1) < 1e-3 and t_contact[-1] - t_contact[0] == pytest.approx(
        np.pi * np.sqrt(m / c), abs=2e-4)
    energy = 0.5 * res["body.v"] ** 2 + G * res["body.s"]        # per kg, d_smooth = 0
    after = res.t > t_contact[-1] + 1e-3
    assert np.abs(energy[after] / (G * h) - 1).max() < 1e-5


# ---- ElastoGap ---------------------------------------------------------------------------
def gap_model(**params):
    """A mass at 0.5 m moving at −1 m/s toward an ElastoGap (s_rel0 = 0.2 m) on a wall."""
    model = acausal.Model("gap")
    model.wall, model.gap, model.mass = tr.Fixed(), tr.ElastoGap(**params), tr.Mass(m=1.0)
    model.connect(model.wall.flange, model.gap.flange_a)
    model.connect(model.gap.flange_b, model.mass.flange_a)
    return model


def test_elasto_gap_contact_is_half_an_oscillation_with_events_at_its_ends():
    """c = 100 N/m, d = 0: contact from t = 0.3 s for π/ω = π/10 s, leaving at +1 m/s."""
    res = acausal.compile(gap_model(c=100.0, d=0.0, s_rel0=0.2)).simulate(
        1.0, x0={"mass.s": 0.5, "mass.v": -1.0}, **TOL)
    enter, leave = res.events
    assert enter.time == pytest.approx(0.3, abs=1e-9) and \
        enter.modes == {"gap.contact": (0.0, 1.0)}
    assert leave.time == pytest.approx(0.3 + np.pi / 10, abs=1e-9) and \
        leave.modes == {"gap.contact": (1.0, 0.0)}
    inside = (res.t > 0.3) & (res.t < leave.time)
    tau = res.t[inside] - 0.3
    assert np.allclose(res["mass.s"][inside], 0.2 - 0.1 * np.sin(10 * tau), atol=1e-9)
    assert np.allclose(res["gap.f"][inside], -100.0 * 0.1 * np.sin(10 * tau), atol=1e-7)
    assert np.all(res["gap.f"][res.t > leave.time] == 0.0)
    assert res["mass.v"][-1] == pytest.approx(1.0, abs=1e-8)


def test_elasto_gap_damping_never_pulls_and_loses_the_energy_it_dissipates():
    """With heavy damping (ζ = 2.5) the limited damping force keeps f ≤ 0 (pushing only) and
    the mass still leaves; the kinetic energy lost equals ∫ lossPower dt (trapezoids)."""
    res = acausal.compile(gap_model(c=100.0, d=50.0, s_rel0=0.2)).simulate(
        1.5, x0={"mass.s": 0.5, "mass.v": -1.0}, t=np.linspace(0, 1.5, 6001), **TOL)
    assert [ev.modes["gap.contact"] for ev in res.events] == [(0.0, 1.0), (1.0, 0.0)]
    assert res["gap.f"].max() <= 0.0
    lost = np.trapezoid(res["gap.lossPower"], res.t)
    depth = np.maximum(0.2 - res["mass.s"][-1], 0.0)
    assert lost + 0.5 * res["mass.v"][-1] ** 2 + 0.5 * 100.0 * depth ** 2 == pytest.approx(
        0.5, rel=1e-5)


def test_elasto_gap_smooth_form_is_within_its_documented_error():
    """s_smooth = 1e-6 m: no modes; the motion within a few s_smooth of the exact one."""
    exact = acausal.compile(gap_model(c=100.0, d=0.0, s_rel0=0.2)).simulate(
        1.0, x0={"mass.s": 0.5, "mass.v": -1.0}, t=np.linspace(0, 1, 101), **TOL)
    smooth_model = acausal.compile(gap_model(c=100.0, d=0.0, s_rel0=0.2), smooth=True)
    assert not smooth_model.mode_params
    smooth = smooth_model.simulate(1.0, x0={"mass.s": 0.5, "mass.v": -1.0},
                                   t=np.linspace(0, 1, 101), **TOL)
    at = np.searchsorted(exact.t, smooth.t, side="right") - 1
    assert np.abs(smooth["mass.s"] - exact["mass.s"][at]).max() < 1e-5


# ---- bad input ---------------------------------------------------------------------------
@pytest.mark.parametrize("make, match", [
    (lambda: tr.ElastoGap(c=-1.0), r"ElastoGap\.c"),
    (lambda: tr.ElastoGap(d=-1.0), r"ElastoGap\.d"),
    (lambda: tr.ElastoGap(n=0.5), r"ElastoGap\.n"),
    (lambda: tr.MassWithStopAndFriction(smax=-1.0, smin=1.0), r"MassWithStopAndFriction\.smax"),
    (lambda: tr.MassWithStopAndFriction(smax=1.0, smin=0.0, L=2.0),
     r"MassWithStopAndFriction\.smax"),
    (lambda: tr.MassWithStopAndFriction(F_prop=-1.0), r"MassWithStopAndFriction\.F_prop"),
    (lambda: tr.HardStop(smax=0.0, smin=1.0), r"HardStop\.smax"),
    (lambda: tr.HardStop(e=1.5), r"HardStop\.e"),
    (lambda: tr.HardStop(e=-0.1), r"HardStop\.e"),
])
def test_bad_parameters_are_refused_naming_component_and_parameter(make, match):
    with pytest.raises(ParameterError, match=match):
        make()


@pytest.mark.parametrize("joint", ["SpringDamper", "Spring"])
def test_a_reinit_keeps_the_relative_states_a_modelica_tool_keeps(joint):
    """Two masses (1 kg, 2 kg) at 1 m/s side by side, joined by a SpringDamper (c = 100 N/m,
    d = 1 N.s/m: MSL's relative states s_rel, v_rel, stateSelect prefer) or by a Spring
    (PartialCompliant: no relative states); mass1 hits a HardStop (e = 0.5) at s = 0.5 m,
    t = 0.5 s: reinit(v, −e·v). With the SpringDamper, v_rel is a state Modelica keeps:
    mass2 jumps by the same −1.5 m/s (to −0.5 m/s); with the Spring, only mass1's v changes
    (mass2 keeps 1 m/s). Only the reinit'd variable and the velocities that are no kept
    state change: positions, and v_rel with the SpringDamper, are continuous."""
    model = acausal.Model("pair")
    model.mass1, model.mass2 = tr.Mass(m=1.0), tr.Mass(m=2.0)
    model.joint = tr.SpringDamper(c=100.0, d=1.0) if joint == "SpringDamper" \
        else tr.Spring(c=100.0)
    model.stop = tr.HardStop(smax=0.5, e=0.5)
    for a, b in [(model.mass1.flange_b, model.joint.flange_a),
                 (model.joint.flange_b, model.mass2.flange_a),
                 (model.mass1.flange_a, model.stop.flange)]:
        model.connect(a, b)
    res = acausal.compile(model).simulate(
        0.6, t=np.linspace(0, 0.6, 61), x0={"mass1.s": 0.0, "mass1.v": 1.0, "mass2.s": 0.0,
                                            "mass2.v": 1.0}, rtol=1e-10, atol=1e-12)
    impact = res.events[0]
    assert impact.indicator == "stop.gap_max" and abs(impact.time - 0.5) < 1e-9
    k = np.flatnonzero(res.t == impact.time)
    assert len(k) == 2
    before, after = k
    np.testing.assert_allclose(res["mass1.v"][[before, after]], [1.0, -0.5], atol=1e-9)
    expected = -0.5 if joint == "SpringDamper" else 1.0
    np.testing.assert_allclose(res["mass2.v"][[before, after]], [1.0, expected], atol=1e-9)
    assert res["mass2.s"][after] == res["mass2.s"][before]
    if joint == "SpringDamper":
        assert abs(res["joint.v_rel"][after] - res["joint.v_rel"][before]) < 1e-12
