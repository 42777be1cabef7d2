"""Limiter, VariableLimiter, DeadZone and LimPID (acausal.components.signals) against the
same laws written out in numpy and hand-written scipy models.

The nonlinear blocks drive a mass on a spring (m x'' + c x = F); the reference integrates
the same ODE with scipy, F written with numpy from the MSL equations, restarting at the
kinks (found by root finding on the numpy law); the blocks' state events must fall on these
kinks. LimPID positions a mass through a saturating force; its reference is the LimPID
equations (P, I with anti-windup feedback through Ni, approximated D, set-point weights,
feed-forward, limiter) written by hand. The smooth forms stay within half their named width
of the exact laws.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

import acausal
from acausal import DisabledPortError, Model, ParameterError
from acausal.components import signals as sg
from acausal.components.translational import Fixed, Force, Mass, PositionSensor, Spring

SIM = dict(rtol=1e-10, atol=1e-12)
MASS, STIFF = 0.5, 8.0
T_END = 3.0
T = np.linspace(0.0, T_END, 151)


def _roots(g, t_end, n=3001):
    """Times in (0, t_end) where g changes sign (brentq on a fine grid)."""
    s = np.linspace(0.0, t_end, n)
    v = np.array([g(x) for x in s])
    return [brentq(g, a, b, xtol=1e-15) for a, b, va, vb in
            zip(s[:-1], s[1:], v[:-1], v[1:]) if va * vb < 0]


def _spring_mass_reference(force, breaks):
    """x(t) of m x'' + c x = force(t), x(0) = x'(0) = 0, restarted at every break."""
    bounds = [0.0] + sorted(b for b in breaks if 0 < b < T_END) + [T_END]
    rhs = lambda t, z: [z[1], (force(t) - STIFF * z[0]) / MASS]          # noqa: E731
    out, z = np.full(T.shape, np.nan), [0.0, 0.0]
    for a, b in zip(bounds[:-1], bounds[1:]):
        sol = solve_ivp(rhs, (a, b), z, method="DOP853", rtol=1e-12, atol=1e-14,
                        dense_output=True)
        sel = (T >= a) & (T <= b)
        out[sel] = sol.sol(T[sel])[0]
        z = sol.y[:, -1]
    return out


def _on_grid(res, name):
    """``res[name]`` at the output grid T (a result with events also holds the event
    instants)."""
    return res[name][np.isin(res.t, T)]


def _driven(block, sources: dict):
    """sources (input name -> source block) -> block -> Force on a mass on a spring."""
    m = Model("driven")
    m.blk, m.force = block, Force()
    m.mass, m.spring, m.fixed = Mass(m=MASS), Spring(c=STIFF), Fixed()
    for name, src in sources.items():
        setattr(m, f"src_{name}", src)
        m.connect(src.y, getattr(block, name))
    for a, b in [(block.y, m.force.f), (m.force.flange, m.mass.flange_a),
                 (m.mass.flange_b, m.spring.flange_b), (m.spring.flange_a, m.fixed.flange)]:
        m.connect(a, b)
    return m


A, F_HZ = 2.0, 0.7
W = 2 * np.pi * F_HZ


def _u(t):
    return A * np.sin(W * t)


def limiter_law(u, lo, hi):
    return np.where(u > hi, hi, np.where(u < lo, lo, u))


def deadzone_law(u, lo, hi):
    return np.where(u > hi, u - hi, np.where(u < lo, u - lo, 0.0))


@pytest.mark.parametrize("kind, kwargs, params, lo, hi", [
    ("Limiter", {"uMax": 1.2}, {}, -1.2, 1.2),
    ("Limiter", {"uMax": 1.5, "uMin": -0.4}, {}, -0.4, 1.5),
    # uMin = -uMax is MSL's binding: it follows uMax changed at simulation time
    ("Limiter", {"uMax": 1.2}, {"blk.uMax": 0.8}, -0.8, 0.8),
    ("DeadZone", {"uMax": 0.6}, {}, -0.6, 0.6),
    ("DeadZone", {"uMax": 1.0, "uMin": -0.3}, {"blk.uMin": -0.5}, -0.5, 1.0)])
def test_static_nonlinearity_drives_a_mass_on_a_spring(kind, kwargs, params, lo, hi):
    law = limiter_law if kind == "Limiter" else deadzone_law
    c = acausal.compile(_driven(getattr(sg, kind)(**kwargs), {"u": sg.Sine(amplitude=A,
                                                                           f=F_HZ)}))
    # state events at the kinks: no step limit, even while at rest inside the dead zone
    res = c.simulate(T_END, t=T, params=params, **SIM)
    np.testing.assert_allclose(_on_grid(res, "blk.y"), law(_u(T), lo, hi), rtol=0, atol=1e-12)
    breaks = _roots(lambda t: _u(t) - hi, T_END) + _roots(lambda t: _u(t) - lo, T_END)
    ref = _spring_mass_reference(lambda t: float(law(_u(t), lo, hi)), breaks)
    np.testing.assert_allclose(_on_grid(res, "mass.s"), ref, rtol=0, atol=1e-7)
    assert c.event_times(c.param_vector(params), 0.0, T_END) == []      # no time events
    events = sorted(ev.time for ev in res.events if ev.component == "blk")
    np.testing.assert_allclose(events, sorted(breaks), rtol=0, atol=1e-9)   # at the kinks


def test_variable_limiter_drives_a_mass_on_a_spring():
    """limit1 = 0.5 + 0.8 t (a ramp of the maximum), limit2 = −1 + 0.3 sin(3t)."""
    blk = sg.VariableLimiter()
    src = {"u": sg.Sine(amplitude=A, f=F_HZ),
           "limit1": sg.Ramp(height=0.8 * 10, duration=10.0, offset=0.5),
           "limit2": sg.Sine(amplitude=0.3, f=3 / (2 * np.pi), offset=-1.0)}
    res = acausal.compile(_driven(blk, src)).simulate(T_END, t=T, **SIM)
    hi = lambda t: 0.5 + 0.8 * t                                        # noqa: E731
    lo = lambda t: -1.0 + 0.3 * np.sin(3 * t)                           # noqa: E731
    np.testing.assert_allclose(_on_grid(res, "blk.y"), limiter_law(_u(T), lo(T), hi(T)),
                               atol=1e-12)
    breaks = _roots(lambda t: _u(t) - hi(t), T_END) + _roots(lambda t: _u(t) - lo(t), T_END)
    ref = _spring_mass_reference(lambda t: float(limiter_law(_u(t), lo(t), hi(t))), breaks)
    np.testing.assert_allclose(_on_grid(res, "mass.s"), ref, rtol=0, atol=1e-8)
    events = sorted(ev.time for ev in res.events if ev.component == "blk")
    np.testing.assert_allclose(events, sorted(breaks), rtol=0, atol=1e-9)


def test_limits_are_checked_and_required():
    with pytest.raises(ParameterError, match="uMax"):
        sg.Limiter()
    with pytest.raises(ParameterError, match="consistent"):
        sg.DeadZone(uMax=0.0, uMin=0.5)
    with pytest.raises(ParameterError, match="yMax"):
        sg.LimPID()
    with pytest.raises(ParameterError, match="y_start"):
        sg.LimPID(yMax=1.0, initType="InitialOutput", y_start=1.5)
    with pytest.raises(DisabledPortError, match="withFeedForward"):
        sg.LimPID(yMax=1.0).u_ff
    assert sg.Limiter(uMax=2.0).uMin == -2.0 and type(sg.Limiter(uMax=1, uMin=0)).__name__ \
        == "Limiter"


# ---- LimPID -------------------------------------------------------------------------------
T_STEP, R0, R1 = 0.2, 0.0, 1.0        # set point: R0, then R1 from T_STEP
MASS_PID = 1.0


def _ff(t):
    return 0.5 * np.sin(2.0 * t)


def _limpid_reference(t, p, kind, feed_forward, x0):
    """Mass under a LimPID position loop, the LimPID equations written by hand."""
    with_i, with_d = kind in ("PI", "PID"), kind in ("PD", "PID")
    tf = max(p["Td"] / p["Nd"], 1e-14)

    def force(time, s, xi, xd):
        r = R0 if time < T_STEP else R1
        d = p["Td"] / tf * (p["wd"] * r - s - xd) if with_d else 0.0
        lim_u = p["k"] * ((p["wp"] * r - s) + (xi if with_i else 0.0) + d) \
            + (p["kFF"] * _ff(time) if feed_forward else 0.0)
        return min(max(lim_u, p["yMin"]), p["yMax"]), lim_u, r

    def rhs(time, z):
        s, v, xi, xd = z
        y, lim_u, r = force(time, s, xi, xd)
        dxi = (r - s + (y - lim_u) / (p["k"] * p["Ni"])) / p["Ti"] if with_i else 0.0
        dxd = (p["wd"] * r - s - xd) / tf if with_d else 0.0
        return [v, y / MASS_PID, dxi, dxd]

    out, z = [], x0
    for a, b in [(0.0, T_STEP), (T_STEP, t[-1])]:
        sol = solve_ivp(rhs, (a, b), z, method="DOP853", rtol=1e-13, atol=1e-14,
                        dense_output=True, max_step=0.01)
        sel = t[(t >= a) & (t < b)] if b < t[-1] else t[t >= a]
        out.append(sol.sol(sel))
        z = sol.y[:, -1]
    z = np.hstack(out)
    y = np.array([force(ti, *zi[[0, 2, 3]])[0] for ti, zi in zip(t, z.T)])
    return z, y


BASE = {"k": 20.0, "Ti": 0.5, "Td": 0.1, "wp": 1.0, "wd": 0.0, "Ni": 0.9, "Nd": 10.0,
        "kFF": 1.0}


@pytest.mark.parametrize("kind, given, feed_forward", [
    ("PID", {"yMax": 5.0}, False),
    ("PID", {"yMax": 4.0, "yMin": -2.0, "wp": 0.7, "wd": 0.4, "Ni": 0.3, "kFF": 2.0}, True),
    ("PI", {"yMax": 5.0, "k": 10.0, "Ti": 0.8}, False),
    ("PD", {"yMax": 3.0, "wd": 1.0}, False),
    ("P", {"yMax": 5.0, "k": 8.0}, True)])
def test_limpid_positions_a_mass_through_saturation(kind, given, feed_forward):
    """Step of the set point 0 -> 1 m at 0.2 s: the force saturates at yMax (anti-windup
    through Ni), then the loop settles; every internal variable against the hand model."""
    given = dict(BASE, **given)
    p = dict(given, yMin=given.get("yMin", -given["yMax"]))      # MSL: yMin = -yMax
    m = Model("limpid_loop")
    m.ref = sg.Step(height=R1 - R0, offset=R0, startTime=T_STEP)
    m.pid = sg.LimPID(controllerType=kind, withFeedForward=feed_forward, xi_start=0.1,
                      xd_start=-0.05, **given)
    m.force, m.mass, m.probe = Force(), Mass(m=MASS_PID), PositionSensor()
    for a, b in [(m.ref.y, m.pid.u_s), (m.probe.s, m.pid.u_m), (m.pid.y, m.force.f),
                 (m.force.flange, m.mass.flange_a), (m.probe.flange, m.mass.flange_b)]:
        m.connect(a, b)
    if feed_forward:
        m.ff = sg.Sine(amplitude=0.5, f=1 / np.pi)           # 0.5 sin(2 t)
        m.connect(m.ff.y, m.pid.u_ff)
    t = np.linspace(0.0, 4.0, 201)
    res = acausal.compile(m).simulate(4.0, t=t, x0={"mass.v": 0.3}, **SIM)
    x0 = [0.0, 0.3, 0.1 if kind in ("PI", "PID") else 0.0,
          -0.05 if kind in ("PD", "PID") else 0.0]
    z, y = _limpid_reference(t, p, kind, feed_forward, x0)
    at = np.searchsorted(res.t, t, side="right") - 1      # the grid (right limits at events)
    assert np.array_equal(res.t[at], t)
    np.testing.assert_allclose(res["mass.s"][at], z[0], rtol=0, atol=1e-6)
    np.testing.assert_allclose(res["mass.v"][at], z[1], rtol=0, atol=1e-6)
    if kind in ("PI", "PID"):
        np.testing.assert_allclose(res["pid.I.y"][at], z[2], rtol=0, atol=1e-6)
    if kind in ("PD", "PID"):
        np.testing.assert_allclose(res["pid.D.x"][at], z[3], rtol=0, atol=1e-6)
    np.testing.assert_allclose(res["pid.y"][at], y, rtol=0, atol=1e-5)
    np.testing.assert_allclose(res["pid.controlError"][at], np.where(t < T_STEP, R0, R1)
                               - res["mass.s"][at], atol=1e-12)
    assert np.max(res["pid.y"][at]) == pytest.approx(p["yMax"], abs=1e-12)   # it saturates
    limiting = [ev.time for ev in res.events                    # state events: at the limits
                if ev.indicator and ev.time != T_STEP]
    lim_u = res["pid.limiter.u"]
    for tk in limiting:
        k = np.flatnonzero(res.t == tk)[0]
        assert min(abs(lim_u[k] - p["yMax"]), abs(lim_u[k] - p["yMin"])) < 1e-9
    assert limiting or kind == "P"


def test_limpid_smooth_form_rounds_the_limiter_within_half_its_width():
    """compile(smooth=True): no events; y within y_smooth/2 of limiter.u clamped to
    [yMin, yMax] (numpy), the bound reached where the output leaves the limit."""
    m = Model("limpid_smooth")
    m.ref = sg.Step(height=1.0, startTime=T_STEP)
    m.pid = sg.LimPID(controllerType="PI", k=20.0, yMax=5.0)
    m.force, m.mass, m.probe = Force(), Mass(m=MASS_PID), PositionSensor()
    for a, b in [(m.ref.y, m.pid.u_s), (m.probe.s, m.pid.u_m), (m.pid.y, m.force.f),
                 (m.force.flange, m.mass.flange_a), (m.probe.flange, m.mass.flange_b)]:
        m.connect(a, b)
    c = acausal.compile(m, smooth=True)
    assert not c.has_events
    res = c.simulate(4.0, t=np.linspace(0.0, 4.0, 4001), params={"pid.y_smooth": 0.1}, **SIM)
    error = np.abs(res["pid.y"] - np.clip(res["pid.limiter.u"], -5.0, 5.0))
    assert error.max() <= 0.05 + 1e-12 and error.max() > 0.04
