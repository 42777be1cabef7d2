"""MSL's initType of the continuous blocks (Integrator, Derivative, FirstOrder, SecondOrder,
PI, PID, LimPID) against the closed-form solutions of their ODEs from the initial values
that SteadyState (der(states) = 0) and InitialOutput (y = y_start) give, solved by hand;
steady operating points of controller loops against their equilibria solved by hand.
"""
from __future__ import annotations

import numpy as np
import pytest

import acausal
from acausal import InitializationError, Model
from acausal.components import signals as sg

SIM = dict(rtol=1e-10, atol=1e-12)
T = np.linspace(0.0, 2.0, 41)


def _simulate(src, block, t=T):
    m = Model("init_test")
    m.src, m.blk = src, block
    m.connect(m.src.y, m.blk.u)
    return acausal.compile(m).simulate(t[-1], t=t, **SIM)


def test_msl_defaults():
    """The defaults of Modelica.Blocks.Continuous (MSL 4.1.0)."""
    defaults = {sg.Integrator: "InitialState", sg.PID: "InitialState",
                sg.Derivative: "NoInit", sg.FirstOrder: "NoInit", sg.SecondOrder: "NoInit",
                sg.PI: "NoInit"}
    for cls, init in defaults.items():
        assert cls().initType is sg.Init(init), cls.__name__
    assert sg.LimPID(yMax=1.0).initType is sg.Init.InitialState


def test_first_order():
    """SteadyState: y = k·u from the start on; InitialOutput (and the default, NoInit):
    y = k·u + (y_start − k·u)·exp(−t/T)."""
    k, Tc, u, y0 = 1.5, 0.4, 0.8, -0.3
    res = _simulate(sg.Constant(k=u), sg.FirstOrder(k=k, T=Tc, y_start=y0,
                                                    initType="SteadyState"))
    np.testing.assert_allclose(res["blk.y"], k * u, rtol=0, atol=1e-12)
    for init in ("InitialOutput", "NoInit"):
        res = _simulate(sg.Constant(k=u), sg.FirstOrder(k=k, T=Tc, y_start=y0, initType=init))
        np.testing.assert_allclose(res["blk.y"], k * u + (y0 - k * u) * np.exp(-T / Tc),
                                   rtol=0, atol=1e-9)


def test_integrator_steady_state():
    """SteadyState needs k·u = 0 at the start: an input that starts at 0 leaves y at y_start
    (then y = y_start + k·h·(t − t0) after a step of height h at t0); a constant non-zero
    input makes the initial equation unsolvable (an InitializationError naming the block);
    in a loop u = r − y, it starts y at r."""
    k, h, t0, y0 = 2.0, 0.6, 0.5, 0.25
    res = _simulate(sg.Step(height=h, startTime=t0),
                    sg.Integrator(k=k, y_start=y0, initType="SteadyState"))
    np.testing.assert_allclose(res["blk.y"], y0 + k * h * np.maximum(T - t0, 0), rtol=0,
                               atol=1e-9)
    with pytest.raises(InitializationError, match=r"blk: der\(y\) = 0 \(initType=SteadyState"
                                                  r"\): no start value enters it"):
        _simulate(sg.Constant(k=h), sg.Integrator(initType="SteadyState"))
    m = Model("integrator_loop")
    m.r, m.fb = sg.Constant(k=0.7), sg.Feedback()
    m.integ = sg.Integrator(k=k, y_start=y0, initType="SteadyState")
    for a, b in [(m.r.y, m.fb.u1), (m.integ.y, m.fb.u2), (m.fb.y, m.integ.u)]:
        m.connect(a, b)
    res = acausal.compile(m).simulate(T[-1], t=T, **SIM)
    np.testing.assert_allclose(res["integ.y"], 0.7, rtol=0, atol=1e-12)


def test_integrator_initial_output():
    """InitialOutput: y = y_start, then y = y_start + k·u·t."""
    k, u, y0 = 2.0, -0.4, 0.9
    res = _simulate(sg.Constant(k=u), sg.Integrator(k=k, y_start=y0, initType="InitialOutput"))
    np.testing.assert_allclose(res["blk.y"], y0 + k * u * T, rtol=0, atol=1e-9)


def _second_order_step(k, w, D, u, y0, yd0, t):
    """y of y'' + 2·D·w·y' + w²·y = w²·k·u (D < 1) from y(0) = y0, y'(0) = yd0."""
    wd, e0 = w * np.sqrt(1 - D ** 2), y0 - k * u
    return k * u + np.exp(-D * w * t) * (e0 * np.cos(wd * t)
                                         + (yd0 + D * w * e0) / wd * np.sin(wd * t))


def test_second_order():
    """InitialOutput: y = y_start, der(y) = yd_start, then the damped step response;
    SteadyState: y = k·u, yd = 0 throughout, whatever the start values."""
    k, w, D, u, y0, yd0 = 1.5, 3.0, 0.3, 0.8, -0.2, 1.1
    res = _simulate(sg.Constant(k=u), sg.SecondOrder(k=k, w=w, D=D, y_start=y0, yd_start=yd0,
                                                     initType="InitialOutput"))
    np.testing.assert_allclose(res["blk.y"], _second_order_step(k, w, D, u, y0, yd0, T),
                               rtol=0, atol=1e-8)
    res = _simulate(sg.Constant(k=u), sg.SecondOrder(k=k, w=w, D=D, y_start=y0, yd_start=yd0,
                                                     initType="SteadyState"))
    np.testing.assert_allclose(res["blk.y"], k * u, rtol=0, atol=1e-12)
    np.testing.assert_allclose(res["blk.yd"], 0, rtol=0, atol=1e-12)


def test_derivative():
    """SteadyState: x = u, y = 0 under a constant input; InitialOutput: y(0) = y_start, so
    x(0) = u − y_start·T/k and y = y_start·exp(−t/T); with k = 0, x = u."""
    k, Tc, u, y0 = 0.5, 0.2, 0.7, 1.3
    res = _simulate(sg.Constant(k=u), sg.Derivative(k=k, T=Tc, x_start=-1.0,
                                                    initType="SteadyState"))
    np.testing.assert_allclose(res["blk.x"], u, rtol=0, atol=1e-12)
    np.testing.assert_allclose(res["blk.y"], 0, rtol=0, atol=1e-12)
    res = _simulate(sg.Constant(k=u), sg.Derivative(k=k, T=Tc, y_start=y0,
                                                    initType="InitialOutput"))
    np.testing.assert_allclose(res["blk.y"], y0 * np.exp(-T / Tc), rtol=0, atol=1e-8)
    assert res["blk.x"][0] == pytest.approx(u - y0 * Tc / k, abs=1e-12)
    res = _simulate(sg.Constant(k=u), sg.Derivative(k=0.0, T=Tc, x_start=-1.0, y_start=y0,
                                                    initType="InitialOutput"))
    np.testing.assert_allclose(res["blk.x"], u, rtol=0, atol=1e-12)


def test_pi_initial_output():
    """InitialOutput: y = k·(x + u) = y_start, so x(0) = y_start/k − u;
    y = y_start + k·u·t/T."""
    k, Tc, u, y0 = 2.0, 0.5, 0.6, 1.0
    res = _simulate(sg.Constant(k=u), sg.PI(k=k, T=Tc, x_start=5.0, y_start=y0,
                                            initType="InitialOutput"))
    np.testing.assert_allclose(res["blk.y"], y0 + k * u / Tc * T, rtol=0, atol=1e-9)


def test_pid_initial_output():
    """InitialOutput: der(D.x) = 0 (D.x = u, D.y = 0) and y = k·(u + I.y) = y_start;
    then y = y_start + k·u·t/Ti, D.x = u."""
    k, Ti, u, y0 = 2.0, 0.5, 0.6, 1.0
    res = _simulate(sg.Constant(k=u), sg.PID(k=k, Ti=Ti, Td=0.1, xi_start=3.0, xd_start=-2.0,
                                             y_start=y0, initType="InitialOutput"))
    np.testing.assert_allclose(res["blk.y"], y0 + k * u / Ti * T, rtol=0, atol=1e-9)
    assert res["blk.D.x"][0] == pytest.approx(u, abs=1e-12)
    np.testing.assert_allclose(res["blk.D.x"], u, rtol=0, atol=1e-9)


KP, TP, R = 2.0, 0.3, 0.8          # plant kp/(Tp·s + 1), set point r


def _siso_loop(controller):
    m = Model("siso_loop")
    m.r, m.fb, m.ctrl = sg.Constant(k=R), sg.Feedback(), controller
    m.plant = sg.FirstOrder(k=KP, T=TP, y_start=-0.5, initType="SteadyState")
    for a, b in [(m.r.y, m.fb.u1), (m.plant.y, m.fb.u2), (m.fb.y, m.ctrl.u),
                 (m.ctrl.y, m.plant.u)]:
        m.connect(a, b)
    return acausal.compile(m).simulate(T[-1], t=T, **SIM)


def test_pi_and_pid_steady_state_in_a_loop():
    """Controller and plant in SteadyState: e = 0, plant.y = r, controller output r/kp, the
    integral state r/(k·kp) (PID: D.x = e = 0), held for all time."""
    k = 1.5
    for ctrl, state in [(sg.PI(k=k, T=0.4, x_start=3.0, initType="SteadyState"), "ctrl.x"),
                        (sg.PID(k=k, Ti=0.4, Td=0.1, xi_start=3.0, xd_start=1.0,
                                initType="SteadyState"), "ctrl.I.y")]:
        res = _siso_loop(ctrl)
        np.testing.assert_allclose(res["plant.y"], R, rtol=0, atol=1e-10)
        np.testing.assert_allclose(res["ctrl.y"], R / KP, rtol=0, atol=1e-10)
        np.testing.assert_allclose(res[state], R / (k * KP), rtol=0, atol=1e-10)


def test_limpid_steady_state_in_a_loop():
    """LimPID (PID, wp = 1, wd = 0) and plant in SteadyState: u_m = u_s = r, D.x = −r,
    I.y = r/(k·kp), y = r/kp inside the limits, held for all time."""
    k = 1.5
    m = Model("limpid_loop")
    m.r, m.ctrl = sg.Constant(k=R), sg.LimPID(k=k, Ti=0.4, Td=0.1, yMax=1.0, xi_start=3.0,
                                              initType="SteadyState")
    m.plant = sg.FirstOrder(k=KP, T=TP, y_start=-0.5, initType="SteadyState")
    for a, b in [(m.r.y, m.ctrl.u_s), (m.plant.y, m.ctrl.u_m), (m.ctrl.y, m.plant.u)]:
        m.connect(a, b)
    res = acausal.compile(m).simulate(T[-1], t=T, **SIM)
    np.testing.assert_allclose(res["plant.y"], R, rtol=0, atol=1e-10)
    np.testing.assert_allclose(res["ctrl.y"], R / KP, rtol=0, atol=1e-10)
    np.testing.assert_allclose(res["ctrl.I.y"], R / (k * KP), rtol=0, atol=1e-10)
    np.testing.assert_allclose(res["ctrl.D.x"], -R, rtol=0, atol=1e-10)


def test_limpid_initial_output():
    """InitialOutput: k·(P.y + I.y + D.y) = y_start with D in steady state (D.y = 0), then,
    unsaturated, y = y_start + k·(u_s − u_m)·t/Ti; y_start outside the limits is refused."""
    k, Ti, us, um, y0 = 2.0, 1.0, 0.5, 0.2, 0.5
    m = Model("limpid_open")
    m.s, m.meas = sg.Constant(k=us), sg.Constant(k=um)
    m.ctrl = sg.LimPID(k=k, Ti=Ti, Td=0.1, yMax=10.0, xi_start=3.0, xd_start=1.0, y_start=y0,
                       initType="InitialOutput")
    m.connect(m.s.y, m.ctrl.u_s)
    m.connect(m.meas.y, m.ctrl.u_m)
    res = acausal.compile(m).simulate(T[-1], t=T, **SIM)
    np.testing.assert_allclose(res["ctrl.y"], y0 + k * (us - um) * T / Ti, rtol=0, atol=1e-9)
    np.testing.assert_allclose(res["ctrl.D.y"], 0, rtol=0, atol=1e-12)
    with pytest.raises(acausal.ParameterError, match="y_start"):
        sg.LimPID(yMax=1.0, yMin=0.0, y_start=-0.1, initType="InitialOutput")
