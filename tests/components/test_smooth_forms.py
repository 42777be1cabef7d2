"""The smooth forms (``compile(model, smooth=True)``) of the components with events, against
closed forms and the exact (event) form, within the error bounds their docstrings give.

- Friction, tau = F(|w|)·tanh(w/w_smooth): a block held by |f| < f0 creeps at exactly
  v_smooth·artanh(|f|/f0) (its steady state); a braked flywheel follows the closed form
  sinh(w/w_s) = sinh(W0/w_s)·exp(−tau·t/(J·w_s)) and stays within w_smooth·ln 2 of the
  exact stop (the torque it misses, ∫(1 − tanh(w/w_s)) dw ≤ w_s·ln 2); a clutch (a
  normal-force element, free without normal force) keeps the two inertias' momentum and
  brings them to the common speed; no modes, indicators, reinits or algebraic variables.
- The bouncing ball's floor, a quadratic contact stiffer in than out: the contact time
  1.4022·(δ_max/v_in)·(1 + 1/e), the penetration δ_max = (3·m·v_in²/(2c))^(1/3), the
  rebound e·v_in (gravity during the contact neglected: within 1 %).
"""
import numpy as np
import pytest

import acausal
from acausal.components import rotational as rot
from acausal.components import translational as tr
from acausal.components.signals import Constant, Step
from acausal.models.bouncing_ball import G, BouncingBall

TOL = dict(rtol=1e-10, atol=1e-12)


def block(push, **friction):
    model = acausal.Model("block")
    model.mass = tr.Mass(m=1.0)
    model.friction = tr.SupportFriction(**friction)
    model.push = push
    model.connect(model.mass.flange_b, model.friction.flange_a)
    model.connect(model.push.flange, model.mass.flange_a)
    return model


def test_smooth_friction_has_no_events_and_records_the_exact_forms_names():
    exact = acausal.compile(block(tr.ConstantForce(f_constant=1.0)))
    smooth = acausal.compile(block(tr.ConstantForce(f_constant=1.0)), smooth=True)
    assert exact.has_events and not smooth.has_events and smooth.smooth
    assert smooth.z_names == [] and exact.z_names == ["friction.f"]
    for name in ("friction.f", "friction.v_relfric", "friction.a_relfric", "friction.f0",
                 "friction.f0_max", "friction.free", "friction.lossPower", "friction.v"):
        assert name in smooth.recorded_names
    assert "friction.v_smooth" in smooth.param_names


@pytest.mark.parametrize("push", [1.0, -1.5])
def test_held_block_creeps_at_v_smooth_artanh_of_its_load(push):
    f0, v_smooth = 2.0, 1e-3
    model = block(tr.ConstantForce(f_constant=push), f_pos=[[0.0, f0]])
    res = acausal.compile(model, smooth=True).simulate(1.0, **TOL)
    creep = v_smooth * np.arctanh(push / f0)
    assert res["mass.v"][-1] == pytest.approx(creep, rel=1e-8)
    assert res["friction.f"][-1] == pytest.approx(push, rel=1e-8)    # it holds the push
    assert res["friction.lossPower"][-1] == pytest.approx(push * creep, rel=1e-8)


J, W0, FN, MU = 2.0, 3.0, 10.0, 0.5


def braked_flywheel():
    model = acausal.Model("flywheel")
    model.fly = rot.Inertia(J=J)
    model.brake = rot.Brake(fn_max=FN, mu_pos=[[0.0, MU]])
    model.on = Constant(k=1.0)
    model.connect(model.fly.flange_b, model.brake.flange_a)
    model.connect(model.on.y, model.brake.f_normalized)
    return model


def smooth_stop(t, w_smooth):
    """The smooth brake's closed form: J·ẇ = −tau·tanh(w/w_s) gives
    sinh(w/w_s) = sinh(W0/w_s)·exp(−tau·t/(J·w_s)), written with L = ln of the right side
    (W0/w_s is large) and asinh(e^L) = L + ln(1 + √(1 + e^(−2L)))."""
    tau = MU * FN
    L = W0 / w_smooth + np.log1p(-np.exp(-2 * W0 / w_smooth)) - np.log(2) \
        - tau * t / (J * w_smooth)
    big = L > 0
    out = np.arcsinh(np.exp(np.where(big, 0.0, L)))
    out[big] = L[big] + np.log1p(np.sqrt(1 + np.exp(-2 * L[big])))
    return w_smooth * out


@pytest.mark.parametrize("w_smooth", [1e-2, 1e-3])
def test_braked_flywheel_in_smooth_form_stays_within_w_smooth_ln2_of_the_exact_stop(w_smooth):
    """The smooth form against its closed form, and that against the exact form's closed
    form (w = W0 − tau/J·t until it sticks at J·W0/tau, then 0; checked against the event
    simulation in test_friction.py): the gap is at most w_smooth·ln 2."""
    tau = MU * FN
    t_stop = J * W0 / tau
    t = np.union1d(np.linspace(0.0, 3.0, 301), [t_stop])
    smooth = acausal.compile(braked_flywheel(), smooth=True).simulate(
        3.0, t=t, x0={"fly.w": W0}, params={"brake.w_smooth": w_smooth}, **TOL)
    assert np.abs(smooth["fly.w"] - smooth_stop(t, w_smooth)).max() < 1e-8
    gap = smooth["fly.w"] - np.maximum(W0 - tau / J * t, 0.0)
    assert gap.min() >= -1e-9 and gap.max() <= w_smooth * np.log(2)
    # at the exact stop the smooth flywheel still turns at w_s·asinh(1/2) (0.48·w_s)
    at_stop = smooth["fly.w"][t == t_stop][0]
    assert at_stop == pytest.approx(w_smooth * np.arcsinh(0.5), rel=1e-6)
    assert np.allclose(smooth["brake.mu"], MU * np.tanh(smooth["fly.w"] / w_smooth),
                       atol=1e-12)


def test_smooth_clutch_keeps_momentum_and_brings_the_inertias_to_one_speed():
    J1, J2, w1, w2 = 1.0, 3.0, 10.0, 0.0
    model = acausal.Model("clutched")
    model.a, model.b = rot.Inertia(J=J1), rot.Inertia(J=J2)
    model.clutch = rot.Clutch(fn_max=20.0)
    model.engage = Step(height=1.0, startTime=0.5)
    model.connect(model.a.flange_b, model.clutch.flange_a)
    model.connect(model.clutch.flange_b, model.b.flange_a)
    model.connect(model.engage.y, model.clutch.f_normalized)
    res = acausal.compile(model, smooth=True).simulate(
        4.0, x0={"a.w": w1, "b.w": w2}, **TOL)
    momentum = J1 * res["a.w"] + J2 * res["b.w"]
    assert np.abs(momentum - (J1 * w1 + J2 * w2)).max() < 1e-8
    free = res.t < 0.5                                    # disengaged: free, no torque
    assert np.all(res["clutch.tau"][free] == 0.0) and np.all(res["a.w"][free] == w1)
    common = (J1 * w1 + J2 * w2) / (J1 + J2)
    assert res["a.w"][-1] == pytest.approx(common, abs=1e-6)
    assert res["b.w"][-1] == pytest.approx(common, abs=1e-6)


def test_smooth_floor_contact_time_penetration_and_rebound():
    e, c, h0 = 0.8, 1e7, 1.0
    t = np.linspace(0.0, 0.6, 60001)
    res = acausal.compile(BouncingBall(e=e), smooth=True).simulate(
        0.6, t=t, x0={"ball.s": h0}, **TOL)
    inside = np.flatnonzero(res["ball.s"] < 0)
    v_in = np.sqrt(2 * G * h0)
    depth = (3 * 1.0 * v_in ** 2 / (2 * c)) ** (1 / 3)
    assert t[inside[0]] == pytest.approx(np.sqrt(2 * h0 / G), abs=2e-5)
    assert t[inside[-1]] - t[inside[0]] == pytest.approx(
        1.4022 * depth / v_in * (1 + 1 / e), rel=0.01)
    assert -res["ball.s"].min() == pytest.approx(depth, rel=0.01)
    assert res["ball.v"][inside[-1] + 1] == pytest.approx(e * v_in, rel=0.01)
    assert np.all(res["floor.f"][res["ball.s"] > 0] == 0.0)       # no force off the floor
