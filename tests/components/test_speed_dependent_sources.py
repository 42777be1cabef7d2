"""SignTorque / SignForce and InverseSpeedDependentTorque / -Force (MSL's Sources) against
their formulas written in numpy, and a flywheel spun up by an InverseSpeedDependentTorque
against its closed form and a hand-written scipy model."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.components import rotational as rot
from acausal.components import signals as sig
from acausal.components import translational as tr
from wiring import model

T_END = 4.0
TIGHT = {"rtol": 1e-10, "atol": 1e-12}


def sign_law(x, reg):
    """MSL's SignTorque: the factor of tau_nominal at x = w/w0."""
    if reg == "Exp":
        return 2 / (1 + np.exp(-x / 0.01)) - 1
    inside = {"Sine": np.sin(math.pi / 2 * x), "Linear": x,
              "CoSine": np.sign(x) * (1 - np.cos(math.pi / 2 * x))}[reg]
    return np.where(np.abs(x) >= 1, np.sign(x), inside)


def inverse_law(w, tau_nominal, w_nominal, w0, same):
    """MSL's InverseSpeedDependentTorque, as its equations read."""
    w_out = np.where(np.abs(w) < w0, w0, w)           # no division by 0 in the unused branch
    if same:
        return np.where(np.abs(w) < w0, tau_nominal * w_nominal / w0,
                        tau_nominal * w_nominal / np.abs(w_out))
    return np.where(np.abs(w) < w0, tau_nominal * w / w0, tau_nominal * w_nominal / w_out)


def swept(source, rotational: bool):
    """The source's flange moved at the speed −3·v0 → +3·v0 (a ramp over T_END, v0 = 0.2)
    by an exact Speed source; returns (speed, result)."""
    lib = rot if rotational else tr
    m = model("sweep", lambda m: [(m.ramp.y, m.drive.w_ref if rotational else m.drive.v_ref),
                                  (m.drive.flange, m.src.flange)],
              ramp=sig.Ramp(height=1.2, duration=T_END, offset=-0.6),
              drive=lib.Speed(exact=True), src=source)
    t = np.linspace(0.0, T_END, 161)
    res = acausal.compile(m).simulate(T_END, t=t, **TIGHT)
    return -0.6 + 1.2 * res.t / T_END, res     # res.t: the grid and the events' instants


@pytest.mark.parametrize("reg", ["Exp", "Sine", "Linear", "CoSine"])
def test_sign_torque_and_force_follow_the_regularized_sign(reg):
    """tau = tau_nominal·reg(w/w0) inside |w| < w0 and ±tau_nominal outside; the force's
    flange.f = −f_nominal·reg(v/v0)."""
    w, res = swept(rot.SignTorque(tau_nominal=3.0, w0=0.2, reg=reg), True)
    np.testing.assert_allclose(res["src.w"], w, atol=1e-9)
    np.testing.assert_allclose(res["src.tau"], 3.0 * sign_law(w / 0.2, reg), atol=1e-6)
    v, res = swept(tr.SignForce(f_nominal=-2.0, v0=0.2, reg=reg), False)
    np.testing.assert_allclose(res["src.f"], 2.0 * sign_law(v / 0.2, reg), atol=1e-6)
    np.testing.assert_allclose(res["src.v"], v, atol=1e-9)


@pytest.mark.parametrize("same", [True, False])
def test_inverse_speed_dependent_torque_and_force_follow_msl_s_law(same):
    """Inside and outside |w| < w0, with w0 ≠ w_nominal (TorqueDirection=False jumps at
    |w| = w0: the two rows at each switching instant, before and after, are left out)."""
    w, res = swept(rot.InverseSpeedDependentTorque(tau_nominal=2.0, w_nominal=0.5, w0=0.2,
                                                   TorqueDirection=same), True)
    off = np.abs(np.abs(w) - 0.2) > 1e-9
    assert (~off).sum() == 4                      # two switches, each recorded twice
    np.testing.assert_allclose(res["src.tau"][off], inverse_law(w[off], 2.0, 0.5, 0.2, same),
                               atol=1e-6)
    v, res = swept(tr.InverseSpeedDependentForce(f_nominal=2.0, v_nominal=0.5, v0=0.2,
                                                 ForceDirection=same), False)
    off = np.abs(np.abs(v) - 0.2) > 1e-9
    np.testing.assert_allclose(res["src.f"][off], -inverse_law(v[off], 2.0, 0.5, 0.2, same),
                               atol=1e-6)


def test_flywheel_spun_up_by_an_inverse_speed_dependent_torque():
    """J·w' = tau_n·w_n/max(|w|, w0) from rest: w = c·t/w0 up to t1 = w0²/c (c = tau_n·w_n/J),
    then w² = w0² + 2c·(t − t1); the source switches at w = w0 by a state event."""
    J, tau_n, w_n, w0 = 0.5, 2.0, 3.0, 0.4
    m = model("flywheel", lambda m: [(m.src.flange, m.fly.flange_a)],
              src=rot.InverseSpeedDependentTorque(tau_nominal=tau_n, w_nominal=w_n, w0=w0),
              fly=rot.Inertia(J=J))
    res = acausal.compile(m).simulate(2.0, t=np.linspace(0.0, 2.0, 101), **TIGHT)
    t = res.t
    c = tau_n * w_n / J
    t1 = w0 ** 2 / c
    w = np.where(t < t1, c * t / w0, np.sqrt(w0 ** 2 + 2 * c * np.clip(t - t1, 0, None)))
    np.testing.assert_allclose(res["fly.w"], w, atol=1e-8)
    np.testing.assert_allclose(res["src.tau"], J * c / np.maximum(w, w0), atol=1e-6)


def test_vehicle_braked_by_an_inverse_force_against_scipy():
    """A mass pushed back by InverseSpeedDependentForce(ForceDirection=False) from v = 2:
    m·v' = −f_n·v_n/v outside v0, −f_n·v/v0 inside (scipy, with the switch as an event)."""
    mass, f_n, v_n, v0 = 2.0, 1.0, 0.3, 0.3
    m = model("brake", lambda m: [(m.src.flange, m.body.flange_a)],
              src=tr.InverseSpeedDependentForce(f_nominal=-f_n, v_nominal=v_n, v0=v0,
                                                ForceDirection=False),
              body=tr.Mass(m=mass))
    t = np.linspace(0.0, 6.0, 121)
    res = acausal.compile(m).simulate(6.0, t=t, x0={"body.v": 2.0}, **TIGHT)
    t = res.t

    def rhs(t, y):
        v = y[1]
        f = -f_n * v / v0 if abs(v) < v0 else -f_n * v_n / v
        return [v, f / mass]

    ref = solve_ivp(rhs, (0, 6.0), [0.0, 2.0], t_eval=t, rtol=1e-11, atol=1e-12,
                    method="DOP853", first_step=1e-4, max_step=1e-2)
    np.testing.assert_allclose(res["body.v"], ref.y[1], atol=1e-6)
    np.testing.assert_allclose(res["body.s"], ref.y[0], atol=1e-6)


@pytest.mark.parametrize("make, what", [
    (lambda: rot.SignTorque(tau_nominal=1.0, w0=0.0), "w0"),
    (lambda: rot.SignTorque(tau_nominal=1.0, w0=-1.0), "w0"),
    (lambda: tr.SignForce(f_nominal=1.0, v0=0.0), "v0"),
    (lambda: rot.InverseSpeedDependentTorque(tau_nominal=1.0, w_nominal=1.0, w0=0.0), "w0"),
    (lambda: tr.InverseSpeedDependentForce(f_nominal=1.0, v_nominal=0.0), "v_nominal"),
    (lambda: rot.SignTorque(w0=0.1), "tau_nominal"),
    (lambda: tr.InverseSpeedDependentForce(f_nominal=1.0), "v_nominal"),
])
def test_bad_parameters_are_refused_naming_the_parameter(make, what):
    with pytest.raises(acausal.ParameterError, match=what) as err:
        make()
    print(err.value)


def test_smooth_forms_have_no_events_and_stay_close():
    """compile(smooth=True): the switch at |w| = w0 rounded over 0.01·w0, no events; the
    flywheel's speed (from 0.05 rad/s: w = 0 is SignTorque's unstable equilibrium) within
    1e-3 of the exact form's, SignTorque(Linear) too."""
    J, tau_n, w_n, w0 = 0.5, 2.0, 3.0, 0.4
    for src in (rot.InverseSpeedDependentTorque(tau_nominal=tau_n, w_nominal=w_n, w0=w0),
                rot.SignTorque(tau_nominal=tau_n, w0=w0, reg="Linear")):
        m = model("flywheel", lambda m: [(m.src.flange, m.fly.flange_a)], src=src,
                  fly=rot.Inertia(J=J))
        exact, smooth = acausal.compile(m), acausal.compile(m, smooth=True)
        assert exact.has_events and not smooth.has_events
        t = np.linspace(0.0, 2.0, 41)
        a = exact.simulate(2.0, t=t, x0={"fly.w": 0.05}, **TIGHT)
        b = smooth.simulate(2.0, t=t, x0={"fly.w": 0.05}, **TIGHT)
        np.testing.assert_allclose(np.interp(t, a.t, a["fly.w"]), b["fly.w"], atol=1e-3)
