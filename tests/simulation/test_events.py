"""State events and discrete modes (acausal.simulation.events) against closed forms: a ball
bouncing on a floor (an ODE, CVODES: impact times, velocities and heights), a block on
Coulomb friction with MSL's mode encoding (a DAE, IDAS: sticking below the breakaway force,
breaking away on a ramp, sliding to a stop, breaking away at a time event), chattering and a
mode machine that never settles (errors naming the component)."""
import casadi as ca
import numpy as np
import pytest

import acausal
from acausal.components.signals import Ramp
from acausal.components.translational import ConstantForce, Force, ForceStep, Mass
from acausal.core import Component, Parameter, RotationalFlange, TranslationalFlange
from acausal.errors import SimulationError, StructureError
from acausal.models import BouncingBall, Floor, FourBar
from faulty_components import Relay, Toggle, on_a_mass

G, E, H0 = 9.81, 0.8, 1.0


def impacts(n):
    """Closed form of the ball dropped from H0 at rest: impact times t_k and the speed just
    before each impact |v_k| (after it: E·|v_k|)."""
    t, v = [np.sqrt(2 * H0 / G)], [np.sqrt(2 * G * H0)]
    for _ in range(n - 1):
        t.append(t[-1] + 2 * E * v[-1] / G)
        v.append(E * v[-1])
    return np.array(t), np.array(v)


def height(t):
    """Closed form of the ball's height at times t."""
    tk, vk = impacts(40)
    k = np.searchsorted(tk, t, side="left")          # impacts at or after t: k before it
    start = np.where(k == 0, 0.0, tk[np.maximum(k - 1, 0)])
    v0 = np.where(k == 0, 0.0, E * vk[np.maximum(k - 1, 0)])
    h0 = np.where(k == 0, H0, 0.0)
    tau = t - start
    return h0 + v0 * tau - 0.5 * G * tau ** 2


@pytest.fixture(scope="module")
def ball():
    model = acausal.compile(BouncingBall(e=E))
    return model.simulate(3.0, x0={"ball.s": H0, "ball.v": 0.0}, rtol=1e-10, atol=1e-12)


def test_bouncing_ball_impact_times_and_speeds(ball):
    falls = [ev for ev in ball.events if ev.direction < 0]
    tk, vk = impacts(len(falls))
    assert len(falls) == 6                              # t_6 = 2.88 s, t_7 = 3.12 s
    assert np.abs(np.array([ev.time for ev in falls]) - tk).max() < 1e-9
    for ev, v in zip(falls, vk):
        assert (ev.component, ev.indicator) == ("floor", "floor.h")
        before, after = ev.reinit["ball.v"]
        assert before == pytest.approx(-v, rel=1e-8) and after == pytest.approx(E * v, rel=1e-8)


def test_bouncing_ball_left_and_right_limits_and_heights(ball):
    for ev in (ev for ev in ball.events if ev.direction < 0):
        i = np.flatnonzero(ball.t == ev.time)
        assert len(i) == 2                              # left limit, then right limit
        v_left, v_right = ball["ball.v"][i]
        assert v_right == pytest.approx(-E * v_left, rel=1e-12)
        assert abs(ball["ball.s"][i]).max() < 1e-11     # at the floor, on both sides
    assert np.abs(ball["ball.s"] - height(ball.t)).max() < 1e-8
    _, vk = impacts(6)                                  # apexes after each impact
    tk = impacts(6)[0]
    apex_t = tk + E * vk / G
    assert np.abs(height(apex_t[:5]) - (E * vk[:5]) ** 2 / (2 * G)).max() < 1e-12
    for k in range(5):                                  # the result's highest point between
        inside = (ball.t > tk[k]) & (ball.t < tk[k + 1])
        assert ball["ball.s"][inside].max() <= (E * vk[k]) ** 2 / (2 * G) + 1e-8


def test_simultaneous_impacts_are_one_event():
    """Two balls dropped together from H0 onto floors of their own (one with e, the other
    with e/2) hit at the same instant: one event, both indicators crossed, both speeds
    reinitialized; the second ball's next impact follows the closed form with e/2."""
    model = acausal.Model("two_balls")
    for k, e in ((1, E), (2, E / 2)):
        setattr(model, f"ball{k}", Mass(m=1.0))
        setattr(model, f"gravity{k}", ConstantForce(f_constant=-G))
        setattr(model, f"floor{k}", Floor(e=e))
        ball = getattr(model, f"ball{k}")
        model.connect(getattr(model, f"gravity{k}").flange, ball.flange_a)
        model.connect(getattr(model, f"floor{k}").flange, ball.flange_a)
    res = acausal.compile(model).simulate(
        1.0, x0={"ball1.s": H0, "ball1.v": 0.0, "ball2.s": H0, "ball2.v": 0.0},
        rtol=1e-10, atol=1e-12)
    falls = [ev for ev in res.events if ev.direction < 0]
    t_1, v_1 = np.sqrt(2 * H0 / G), np.sqrt(2 * G * H0)
    first = [ev for ev in falls if abs(ev.time - t_1) < 1e-9]
    assert {ev.component for ev in first} == {"floor1", "floor2"}
    assert len({ev.time for ev in first}) == 1                 # one instant, one restart
    assert first[0].reinit == {"ball1.v": pytest.approx((-v_1, E * v_1), rel=1e-8),
                               "ball2.v": pytest.approx((-v_1, E / 2 * v_1), rel=1e-8)}
    second = next(ev for ev in falls if ev.component == "floor2" and ev.time > t_1 + 1e-6)
    assert second.time == pytest.approx(t_1 + 2 * (E / 2) * v_1 / G, abs=1e-9)


class CoulombFriction(Component):
    """Coulomb friction of a body on the ground with MSL's mode encoding (PartialFriction:
    −1 backward, 0 stuck, 1 forward): sliding force F_c [N] against the motion, breakaway
    force F_0 [N]; the friction force on the body f [N] is an algebraic variable (stuck: the
    force that holds the body). Its speed is set to 0 when it sticks and when it breaks
    away (it rests up to the integrator's roundoff, whose sign must not decide)."""
    F_c = Parameter(1.0, "N", "sliding friction force")
    F_0 = Parameter(1.5, "N", "breakaway force")
    flange = TranslationalFlange("the sliding body")

    def structure(self, s):
        s.mode("mode", 0, values=(-1, 0, 1), description="-1 backward, 0 stuck, 1 forward")
        s.algebraic("f", unit="N", description="friction force on the body")

    def physics(self, e):
        v, a = e.vel(self.flange), e.acc(self.flange)
        mode, f = e.mode("mode"), e.state("f")
        e.flow(self.flange, -f)
        e.residual(ca.if_else(mode == 0, a, f + self.F_c * mode))
        e.indicator("v", ca.if_else(mode == 0, 1, mode * v), "m/s")
        e.indicator("breakaway", ca.if_else(mode == 0, self.F_0 - ca.fabs(f), 1), "N")
        stuck = ca.if_else(v > 0, 1, ca.if_else(v < 0, -1, ca.if_else(
            -f > self.F_0, 1, ca.if_else(f > self.F_0, -1, 0))))
        keeps = ca.logic_or(mode * v > 0, ca.logic_and(v == 0, mode * a > 0))
        e.mode_update(mode, ca.if_else(mode == 0, stuck, ca.if_else(keeps, mode, 0)))
        e.reinit(v, 0, when="v", direction=-1)
        e.reinit(v, 0, when="breakaway", direction=-1)    # at rest exactly (not roundoff)


M, F_C, F_0 = 2.0, 1.0, 1.5


def block(push):
    model = acausal.Model("block")
    model.mass = Mass(m=M)
    model.friction = CoulombFriction(F_c=F_C, F_0=F_0)
    model.push = push
    model.connect(model.mass.flange_a, model.friction.flange)
    model.connect(model.mass.flange_a, model.push.flange)
    return model


def test_friction_below_breakaway_stays_at_rest():
    res = acausal.compile(block(ConstantForce(f_constant=-1.4))).simulate(10.0)
    assert res.solver == "idas" and res.events == []
    assert np.abs(res["mass.v"]).max() <= 1e-12 and np.abs(res["mass.s"]).max() <= 1e-12
    assert np.all(res["friction.mode"] == 0)
    assert np.allclose(res["friction.f"], 1.4, atol=1e-12)   # holds the push, f_constant


def test_friction_breaks_away_on_a_ramp():
    model = block(Force())
    model.ramp = Ramp(height=3.0, duration=3.0)                 # push k·t, k = 1 N/s
    model.connect(model.ramp.y, model.push.f)
    res = acausal.compile(model).simulate(3.0, rtol=1e-10, atol=1e-12)
    (ev,) = res.events
    t_b = F_0 / 1.0
    assert ev.time == pytest.approx(t_b, abs=1e-9)
    assert (ev.component, ev.indicator, ev.modes) == ("friction", "friction.breakaway",
                                                      {"friction.mode": (0.0, 1.0)})
    t = res.t
    v = np.where(t > t_b, (0.5 * (t ** 2 - t_b ** 2) - F_C * (t - t_b)) / M, 0.0)
    assert np.abs(res["mass.v"] - v).max() < 1e-9


def test_friction_slides_to_a_stop_and_sticks():
    res = acausal.compile(block(ConstantForce(f_constant=0.0))).simulate(
        5.0, x0={"mass.v": 1.0}, rtol=1e-10, atol=1e-12)
    start, stop = res.events
    assert start.modes == {"friction.mode": (0.0, 1.0)}          # moving at t = 0: forward
    t_stop = M * 1.0 / F_C
    assert stop.time == pytest.approx(t_stop, abs=1e-9)
    assert stop.modes == {"friction.mode": (1.0, 0.0)} and stop.reinit["mass.v"][1] == 0.0
    after = res.t >= t_stop
    assert np.abs(res["mass.v"][after][1:]).max() <= 1e-12
    s_stop = 1.0 * t_stop - 0.5 * F_C / M * t_stop ** 2
    assert np.abs(res["mass.s"][after] - s_stop).max() < 1e-9
    before = ~after
    assert np.abs(res["mass.v"][before] - (1.0 - F_C / M * res.t[before])).max() < 1e-9


def test_time_event_with_state_events():
    res = acausal.compile(block(ForceStep(stepForce=2.0, startTime=1.0))).simulate(3.0)
    (ev,) = res.events
    assert ev.time == 1.0 and ev.indicator == "" and ev.modes == {"friction.mode": (0.0, 1.0)}
    t = res.t
    v = np.where(t >= 1.0, (2.0 - F_C) / M * (t - 1.0), 0.0)
    assert np.abs(res["mass.v"] - v).max() < 1e-8
    assert np.sum(t == 1.0) == 2                              # both limits kept


def test_chattering_names_the_component():
    model = on_a_mass("relay", Relay())
    with pytest.raises(SimulationError, match=r"chattering.*'relay'.*relay\.v"):
        acausal.compile(model).simulate(3.0, x0={"mass.v": 1.0})


def test_event_iteration_that_never_settles_names_the_component():
    model = on_a_mass("toggle", Toggle())
    with pytest.raises(SimulationError, match="does not settle.*toggle"):
        acausal.compile(model).simulate(1.0)


class BadReinit(Component):
    flange = TranslationalFlange("any flange")

    def physics(self, e):
        e.indicator("h", e.pos(self.flange))
        e.reinit(e.pos(self.flange) ** 2, 0.0, when="height")


def test_reinit_of_an_unknown_indicator_is_refused():
    model = acausal.Model("bad")
    model.mass = Mass(m=1.0)
    model.bad = BadReinit()
    model.connect(model.mass.flange_a, model.bad.flange)
    with pytest.raises(StructureError, match="'bad'.*'height'.*its indicators: h"):
        acausal.compile(model)



class Stop(Component):
    """A rigid stop at phi_stop [rad] for a rotational flange coming from above: the speed
    is reversed with restitution e when the angle falls through phi_stop."""
    phi_stop = Parameter(0.0, "rad", "angle of the stop")
    e = Parameter(1.0, "1", "coefficient of restitution")
    flange = RotationalFlange("flange that hits the stop")

    def physics(self, e):
        w = e.vel(self.flange)
        e.indicator("gap", e.pos(self.flange) - self.phi_stop, "rad")
        e.reinit(w, -self.e * w, when="gap", direction=-1)


@pytest.mark.filterwarnings("ignore:initial values changed to close")
def test_closed_loop_elastic_stop_retraces_its_path():
    """The four-bar (a closed loop, IDAS) released at rest with its crank at 1.2 rad swings
    down onto an elastic stop at 0.5 rad. Reference: the same four-bar without the stop,
    simulated without events, crosses 0.5 rad at t_1; conservative mechanics is reversible,
    so after the speeds are reversed (the loop's speeds projected onto Φ̇ = 0) the linkage
    retraces its path: at rest at 1.2 rad again at 2 t_1, impacts at (2k − 1) t_1."""
    phi0, stop = 1.2, 0.5
    start = dict(x0={"rev1.phi": phi0, "rev1.w": 0.0}, guess={"rev2.phi": -2.354,
                                                              "rev3.phi": -2.225})
    free = acausal.compile(FourBar())
    grid = np.concatenate([np.linspace(0.0, 0.27, 28), np.linspace(0.27, 0.28, 10001)[1:]])
    ref = free.simulate(0.28, t=grid, rtol=1e-10, atol=1e-12, **start)
    k = np.flatnonzero(ref["rev1.phi"] < stop)[0]
    a, b = ref["rev1.phi"][k - 1] - stop, ref["rev1.phi"][k] - stop
    t_1 = ref.t[k - 1] + a / (a - b) * (ref.t[k] - ref.t[k - 1])

    model = FourBar(crank_flange=True)
    model.stop = Stop(phi_stop=stop, e=1.0)
    model.connect(model.stop.flange, model.rev1.axis)
    compiled = acausal.compile(model)
    assert compiled.has_loops
    res = compiled.simulate(1.2, rtol=1e-10, atol=1e-12, **start)
    falls = [ev for ev in res.events if ev.direction < 0]
    assert [ev.time for ev in falls] == pytest.approx([t_1, 3 * t_1], abs=1e-8)
    for ev in falls:
        before, after = ev.reinit["rev1.w"]
        assert after == pytest.approx(-before, rel=1e-12)
        i = np.flatnonzero(res.t == ev.time)
        assert len(i) == 2
        w = np.array([res[f"rev{j}.w"][i] for j in (1, 2, 3)])
        assert np.allclose(w[:, 1], -w[:, 0], rtol=1e-6)       # every speed reversed
    back = compiled.simulate(2 * t_1, rtol=1e-10, atol=1e-12, **start)
    assert back.final("rev1.phi") == pytest.approx(phi0, abs=1e-7)
    assert abs(back.final("rev1.w")) < 1e-6


def test_a_crossing_the_re_integration_misses_at_its_check_is_still_located(monkeypatch):
    """A crossing the integration saw at a check, where the re-integration up to that check
    ends on the near side (the indicator within the integrators' error of 0 there, as on an
    output grid holding the event times of a reference result): located between the two
    checks all the same. Here the re-integration is made to land on the near side."""
    from acausal.simulation import events
    locate, state_at = events.EventSimulation.locate, events.EventSimulation.state_at

    def near_side_first(self, t0, x0, z0, d, sides, t1, x1, z1):
        calls = []

        def misses(sim, a, x, z, d_, t):        # the first call: the state at t0, not t1
            calls.append(t)
            return state_at(sim, a, x, z, d_, a if len(calls) == 1 else t)
        monkeypatch.setattr(events.EventSimulation, "state_at", misses)
        try:
            return locate(self, t0, x0, z0, d, sides, t1, x1, z1)
        finally:
            monkeypatch.setattr(events.EventSimulation, "state_at", state_at)

    monkeypatch.setattr(events.EventSimulation, "locate", near_side_first)
    res = acausal.compile(block(ConstantForce(f_constant=0.0))).simulate(
        5.0, x0={"mass.v": 1.0}, rtol=1e-10, atol=1e-12)
    start, stop = res.events
    assert stop.time == pytest.approx(M * 1.0 / F_C, abs=1e-9)
    assert stop.modes == {"friction.mode": (1.0, 0.0)}
