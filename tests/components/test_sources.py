"""The sources after MSL 4.1 (ContinuousClock, Exponentials, SawTooth, Sinc,
Sine/CosineVariableFrequencyAndAmplitude, LogFrequencySweep, KinematicPTP) against their
MSL formulas written in numpy, their integrals by scipy quadrature of those formulas, the
variable-frequency waves against a scipy integration of their phase, and the published MSL
reference results (Blocks.Examples CompareSincExpSine, Modulation, PID_Controller).

Grids are binary fractions (exact in floating point) that contain every discontinuity: the
output there is its right limit (MSL's ``time < T`` relations: the new value from T on), and
the integrals, with no step limit, check that the solver never steps across one (time
events).
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal import DisabledPortError, Model, ParameterError
from acausal.components import signals as sg
from time_signals import after, cumulative_integral

SIM = dict(rtol=1e-10, atol=1e-12)
T_END = 3.0
GRID = np.arange(193) / 64.0                    # 0 .. 3 s by 1/64 s, exact binary fractions
TWO_PI = 2 * np.pi


def _source_model(src, *, inputs=()):
    """src -> Integrator; ``inputs``: (port name, source) pairs driving src's inputs."""
    m = Model("src_test")
    m.src = src
    m.integ = sg.Integrator()
    m.connect(m.src.y, m.integ.u)
    for k, (port, drive) in enumerate(inputs):
        setattr(m, f"in{k}", drive)
        m.connect(drive.y, getattr(m.src, port))
    return m


def _exponentials(t, outMax, riseTime, riseConst, fallConst, offset, t0):
    tau = np.maximum(t - t0, 0.0)
    y_rise = outMax * (1 - np.exp(-riseTime / riseConst))
    return offset + after(t, t0, np.where(tau < riseTime, outMax * (1 - np.exp(-tau / riseConst)),
                                           y_rise * np.exp(-(tau - riseTime) / fallConst)))


def _sawtooth(t, amplitude, period, nperiod, offset, t0):
    count = np.floor((t - t0) / period)
    on = (t >= t0) & ((nperiod < 0) | (count < nperiod))
    return offset + np.where(on, amplitude * (t - t0 - count * period) / period, 0.0)


def _log_sweep(t, wMin, wMax, t0, duration):
    x = np.clip((t - t0) / duration, 0.0, 1.0)
    return wMin * (wMax / wMin) ** x


# name: (block, numpy formula, discontinuities and kinks [s] on GRID)
SOURCES = {
    "ContinuousClock": (lambda: sg.ContinuousClock(offset=0.5, startTime=0.75),
                        lambda t: 0.5 + after(t, 0.75, t - 0.75), (0.75,)),
    "Exponentials": (lambda: sg.Exponentials(outMax=2.0, riseTime=0.5, riseTimeConst=0.25,
                                             offset=-0.5, startTime=0.25),
                     lambda t: _exponentials(t, 2.0, 0.5, 0.25, 0.25, -0.5, 0.25), (0.25, 0.75)),
    "Exponentials_fallTimeConst": (
        lambda: sg.Exponentials(outMax=1.5, riseTime=1.0, riseTimeConst=0.5, fallTimeConst=0.125,
                                startTime=0.5),
        lambda t: _exponentials(t, 1.5, 1.0, 0.5, 0.125, 0.0, 0.5), (0.5, 1.5)),
    # 3 periods of 0.5 s from 0.25 s: jumps at 0.25, 0.75, 1.25 and back to offset at 1.75
    "SawTooth": (lambda: sg.SawTooth(amplitude=2.0, period=0.5, nperiod=3, offset=0.25,
                                     startTime=0.25),
                 lambda t: _sawtooth(t, 2.0, 0.5, 3, 0.25, 0.25), (0.25, 0.75, 1.25, 1.75)),
    "SawTooth_endless": (lambda: sg.SawTooth(amplitude=-1.0, period=0.375),
                         lambda t: _sawtooth(t, -1.0, 0.375, -1, 0.0, 0.0),
                         tuple(0.375 * np.arange(1, 8))),
    "Sinc": (lambda: sg.Sinc(amplitude=1.5, f=2.0, offset=0.25, startTime=0.5),
             lambda t: 0.25 + after(t, 0.5, 1.5 * np.sinc(2 * 2.0 * (t - 0.5))), (0.5,)),
    "Sinc_continuous": (lambda: sg.Sinc(amplitude=1.5, f=2.0, startTime=0.5, continuous=True),
                        lambda t: 1.5 * np.where(t < 0.5, 1.0, np.sinc(2 * 2.0 * (t - 0.5))),
                        (0.5,)),
    "LogFrequencySweep": (lambda: sg.LogFrequencySweep(wMin=0.5, wMax=8.0, startTime=0.5,
                                                       duration=1.5),
                          lambda t: _log_sweep(t, 0.5, 8.0, 0.5, 1.5), (0.5, 2.0)),
}


@pytest.mark.parametrize("name", list(SOURCES))
def test_source_and_its_integral(name):
    """The output on the grid (right limits at the jumps) and its integral, without a step
    limit: a solver that stepped across a jump or a kink would miss the quadrature."""
    make, f, breaks = SOURCES[name]
    assert set(breaks) <= set(GRID)
    res = acausal.compile(_source_model(make())).simulate(T_END, t=GRID, **SIM)
    assert np.array_equal(res.t, GRID)
    np.testing.assert_allclose(res["src.y"], f(GRID), rtol=0, atol=1e-13)
    np.testing.assert_allclose(res["integ.y"], cumulative_integral(f, GRID, breaks),
                               rtol=0, atol=1e-8)


def test_values_at_the_jumps_are_the_right_limits():
    """At a jump time the output is the new value, just before it the old one."""
    t0, period = 0.25, 0.5
    saw = acausal.compile(_source_model(sg.SawTooth(amplitude=2.0, period=period, nperiod=2,
                                                    startTime=t0)))
    jumps = np.array([t0, t0 + period, t0 + 2 * period])
    t = np.sort(np.concatenate([[0.0], jumps, jumps - 2 ** -20, [2.0]]))
    y = saw.simulate(2.0, t=t, **SIM)["src.y"]
    before, at = y[1::2][:3], y[2::2][:3]
    np.testing.assert_allclose(before, [0.0, 2.0, 2.0], atol=1e-5)     # left limits
    np.testing.assert_array_equal(at, [0.0, 0.0, 0.0])                  # right limits


def test_sawtooth_integral_on_a_coarse_grid_is_exact():
    """20 teeth of 0.1 s, 4 output times, no step limit: the integral is A·P/2 per tooth
    plus the part of the tooth under way; stepping across a jump would miss it."""
    A, P, t0 = 3.0, 0.1, 0.05
    c = acausal.compile(_source_model(sg.SawTooth(amplitude=A, period=P, nperiod=20,
                                                  startTime=t0)))
    t = np.array([0.0, 0.77, 1.5, 3.0])
    res = c.simulate(3.0, t=t)
    teeth = np.clip(np.floor((t - t0) / P), 0, 20)
    tp = np.where((t > t0) & (teeth < 20), t - t0 - teeth * P, 0.0)
    np.testing.assert_allclose(res["integ.y"], teeth * A * P / 2 + A * tp ** 2 / (2 * P),
                               atol=1e-9)


def test_sinc_at_zero_is_its_limit_and_smooth():
    """At x = 0 (time = startTime) the output is amplitude (sin(x)/x → 1), not NaN, and so
    just around it; the derivative (the Der block, exact) is −x·amplitude·(2πf)/3 there
    (sinc'(x) ≈ −x/3), with no cancellation."""
    m = Model("sinc")
    m.src = sg.Sinc(amplitude=2.0, f=3.0, offset=0.5, startTime=0.25)
    m.der = sg.Der()
    m.connect(m.src.y, m.der.u)
    m.integ = sg.Integrator()
    m.connect(m.src.y, m.integ.u)
    t = np.array([0.0, 0.25, 0.25 + 1e-9, 0.25 + 1e-6, 0.25 + 1e-4, 0.25 + 1e-2, 0.5])
    res = acausal.compile(m).simulate(0.5, t=t, **SIM)
    x = TWO_PI * 3.0 * (t - 0.25)
    assert np.isfinite(res["src.y"]).all() and np.isfinite(res["der.y"]).all()
    assert res["src.y"][1] == 2.5
    ref = 0.5 + after(t, 0.25, 2.0 * np.sinc(x / np.pi))
    np.testing.assert_allclose(res["src.y"], ref, rtol=1e-15, atol=0)
    dsinc = np.where(x == 0, 0.0, (x * np.cos(x) - np.sin(x)) / np.where(x == 0, 1, x) ** 2)
    small = np.abs(x) < 1e-2
    dsinc[small] = -x[small] / 3 + x[small] ** 3 / 30            # the series, no cancellation
    np.testing.assert_allclose(res["der.y"][1:], 2.0 * TWO_PI * 3.0 * dsinc[1:],
                               rtol=1e-12, atol=1e-12)


def test_exponentials_fall_time_constant_follows_rise_time_constant():
    """Not given, fallTimeConst is riseTimeConst (MSL's binding), also when riseTimeConst
    is changed at simulation time; given, it is a parameter of its own."""
    c = acausal.compile(_source_model(sg.Exponentials(riseTime=0.5)))
    res = c.simulate(T_END, t=GRID, params={"src.riseTimeConst": 0.375}, **SIM)
    np.testing.assert_allclose(res["src.y"], _exponentials(GRID, 1.0, 0.5, 0.375, 0.375, 0, 0),
                               atol=1e-13)
    assert "src.fallTimeConst" not in c.param_names
    own = acausal.compile(_source_model(sg.Exponentials(riseTime=0.5, fallTimeConst=0.25)))
    res = own.simulate(T_END, t=GRID, params={"src.fallTimeConst": 0.5}, **SIM)
    np.testing.assert_allclose(res["src.y"], _exponentials(GRID, 1.0, 0.5, 0.1, 0.5, 0, 0),
                               atol=1e-13)


# ---- variable frequency and amplitude ----------------------------------------------------------
def _am(t):
    return 1.0 + 0.5 * np.sin(TWO_PI * 2.0 * t)


def _fm(t):
    return 3.0 + 2.0 * np.sin(TWO_PI * 0.5 * t)


@pytest.mark.parametrize("cls, wave", [(sg.SineVariableFrequencyAndAmplitude, np.sin),
                                       (sg.CosineVariableFrequencyAndAmplitude, np.cos)],
                         ids=["sine", "cosine"])
def test_variable_frequency_and_amplitude_against_scipy(cls, wave):
    """y = offset + a(t)·wave(phi), phi' = 2π·f(t), phi(0) = phi_start: phi by solve_ivp."""
    inputs = [("amplitude", sg.Sine(amplitude=0.5, f=2.0, offset=1.0)),
              ("f", sg.Sine(amplitude=2.0, f=0.5, offset=3.0))]
    src = cls(offset=0.25, phi_start=0.3)
    res = acausal.compile(_source_model(src, inputs=inputs)).simulate(T_END, t=GRID, **SIM)
    phi = solve_ivp(lambda t, p: [TWO_PI * _fm(t)], (0, T_END), [0.3], t_eval=GRID,
                    rtol=1e-12, atol=1e-12).y[0]
    np.testing.assert_allclose(res["src.phi"], phi, atol=1e-8)
    np.testing.assert_allclose(res["src.y"], 0.25 + _am(GRID) * wave(phi), atol=1e-8)


def test_constant_amplitude_and_frequency_options():
    """With both options the parameters replace the inputs, which are then absent."""
    src = sg.CosineVariableFrequencyAndAmplitude(useConstantAmplitude=True, constantAmplitude=2.0,
                                                 useConstantFrequency=True,
                                                 constantFrequency=1.5)
    with pytest.raises(DisabledPortError, match="amplitude"):
        src.amplitude
    with pytest.raises(DisabledPortError, match="'f'"):
        src.f
    res = acausal.compile(_source_model(src)).simulate(T_END, t=GRID, **SIM)
    np.testing.assert_allclose(res["src.y"], 2.0 * np.cos(TWO_PI * 1.5 * GRID), atol=1e-8)


def test_modulation_against_msl_reference(reference_result):
    """Blocks.Examples.Modulation: AM and FM of 100 Hz carriers by 2 Hz sines. The FM phase
    is also checked against its closed form 2π·(100·t + 50·(1 − cos(4πt))/(4π)): the
    reference's phase drifts by ~1e-3 rad over its 628 rad (its solver's tolerance), hence
    the looser comparison of the FM columns with it."""
    ref = reference_result("MAP-LIB_ReferenceResults", "Modelica.Blocks.Examples.Modulation")
    m = Model("Modulation")
    m.amplitude = sg.Sine(amplitude=0.5, f=2.0, offset=1.0)
    m.frequency = sg.Sine(amplitude=50.0, f=2.0, offset=100.0)
    const = dict(useConstantAmplitude=True, useConstantFrequency=True, constantFrequency=100.0)
    m.sine = sg.SineVariableFrequencyAndAmplitude(**const)
    am = dict(useConstantFrequency=True, constantFrequency=100.0)
    m.sinAM = sg.SineVariableFrequencyAndAmplitude(**am)
    m.cosAM = sg.CosineVariableFrequencyAndAmplitude(**am)
    m.sinFM = sg.SineVariableFrequencyAndAmplitude(useConstantAmplitude=True)
    m.cosFM = sg.CosineVariableFrequencyAndAmplitude(useConstantAmplitude=True)
    for block in (m.sinAM, m.cosAM):
        m.connect(m.amplitude.y, block.amplitude)
    for block in (m.sinFM, m.cosFM):
        m.connect(m.frequency.y, block.f)
    t = ref["time"][::20]
    res = acausal.compile(m).simulate(1.0, t=t, **SIM)
    phi = TWO_PI * (100 * t + 50 * (1 - np.cos(4 * np.pi * t)) / (4 * np.pi))
    np.testing.assert_allclose(res["sinFM.phi"], phi, rtol=0, atol=1e-6)
    np.testing.assert_allclose(res["cosFM.y"], np.cos(phi), atol=1e-6)
    for name, tol in (("sine", 2e-6), ("sinAM", 2e-6), ("cosAM", 2e-6), ("sinFM", 2e-3),
                      ("cosFM", 2e-3)):
        np.testing.assert_allclose(res[f"{name}.y"], ref[f"{name}.y"][::20], atol=tol,
                                   err_msg=name)


def test_sinc_against_msl_reference(reference_result):
    """Blocks.Examples.CompareSincExpSine: Sinc(f = 5) and two ExpSines."""
    ref = reference_result("MAP-LIB_ReferenceResults",
                           "Modelica.Blocks.Examples.CompareSincExpSine")
    m = Model("CompareSincExpSine")
    m.sinc = sg.Sinc(f=5.0)
    m.expSine1 = sg.ExpSine(f=5.0, damping=5.0)
    m.expSine2 = sg.ExpSine(f=5.0, phase=np.pi / 2, damping=5.0)
    m.integ = sg.Integrator()
    m.connect(m.sinc.y, m.integ.u)
    res = acausal.compile(m).simulate(1.0, t=ref["time"], **SIM)
    for name in ("sinc", "expSine1", "expSine2"):
        np.testing.assert_allclose(res[f"{name}.y"], ref[f"{name}.y"], atol=1e-9, err_msg=name)


# ---- KinematicPTP ------------------------------------------------------------------------------
def _ptp_acceleration(t, dq, qd_max, qdd_max, t0):
    """The acceleration of the fastest rest-to-rest motion by dq (one axis, the textbook
    profile: trapezoid, or triangle when qd_max is not reached) and its end time."""
    a, v = qdd_max, qd_max
    ta = v / a
    if a * ta ** 2 >= abs(dq):
        ta, tc = np.sqrt(abs(dq) / a), 0.0
    else:
        tc = (abs(dq) - a * ta ** 2) / v
    tau = t - t0
    acc = np.where(tau < 0, 0.0, np.where(tau < ta, a, np.where(
        tau < ta + tc, 0.0, np.where(tau < 2 * ta + tc, -a, 0.0))))
    return np.sign(dq) * acc, (t0, t0 + ta, t0 + ta + tc, t0 + 2 * ta + tc)


def test_kinematic_ptp_acceleration_and_its_integrals():
    """Two axes: axis 2 (2 rad at 1 rad/s, 1 rad/s²: trapezoid) sets the phases, axis 1
    (−0.5) follows scaled; the speed ∫y and position ∫∫y reach rest at deltaq."""
    m = Model("ptp")
    m.ptp = sg.KinematicPTP(deltaq=[-0.5, 2.0], qd_max=[4.0, 1.0], qdd_max=[4.0, 1.0],
                            startTime=0.25)
    m.qd = sg.Integrator()
    m.q = sg.Integrator()
    m.connect(m.ptp.y[2], m.qd.u)
    m.connect(m.qd.y, m.q.u)
    t = np.arange(4 * 64 + 1) / 64.0
    res = acausal.compile(m).simulate(4.0, t=t, **SIM)
    acc, phases = _ptp_acceleration(t, 2.0, 1.0, 1.0, 0.25)
    assert phases == (0.25, 1.25, 2.25, 3.25)                     # on the grid
    np.testing.assert_array_equal(res["ptp.y[2]"], acc)
    np.testing.assert_array_equal(res["ptp.y[1]"], -0.25 * acc)
    f = lambda s: _ptp_acceleration(np.array([s]), 2.0, 1.0, 1.0, 0.25)[0][0]  # noqa: E731
    qd = cumulative_integral(f, t, phases)
    np.testing.assert_allclose(res["qd.y"], qd, atol=1e-9)
    np.testing.assert_allclose(res["q.y"][-1], 2.0, atol=1e-9)


def test_kinematic_ptp_against_msl_reference(reference_result):
    """Blocks.Examples.PID_Controller: the reference speed, ∫KinematicPTP.y (deltaq = π/2,
    qd_max = qdd_max = 1, startTime 0.5 s)."""
    ref = reference_result("MAP-LIB_ReferenceResults", "Modelica.Blocks.Examples.PID_Controller")
    m = Model("PID_Controller")
    m.kinematicPTP = sg.KinematicPTP(startTime=0.5, deltaq=[1.570796326794897], qd_max=[1.0],
                                     qdd_max=[1.0])
    m.integrator = sg.Integrator()
    m.connect(m.kinematicPTP.y[1], m.integrator.u)
    res = acausal.compile(m).simulate(4.0, t=ref["time"], **SIM)
    np.testing.assert_allclose(res["integrator.y"], ref["integrator.y"], atol=1e-6)


# ---- bad input ---------------------------------------------------------------------------------
@pytest.mark.parametrize("make, match", [
    (lambda: sg.SawTooth(period=0.0), r"SawTooth\.period.*> 0"),
    (lambda: sg.Exponentials(riseTime=-1.0), r"Exponentials\.riseTime.*>= 0"),
    (lambda: sg.Exponentials(riseTimeConst=0.0), r"Exponentials\.riseTimeConst.*> 0"),
    (lambda: sg.Exponentials(fallTimeConst=-0.1), r"Exponentials\.fallTimeConst.*> 0"),
    (lambda: sg.LogFrequencySweep(wMin=0.0, wMax=1.0), r"LogFrequencySweep\.wMin.*> 0"),
    (lambda: sg.LogFrequencySweep(wMin=1.0), r"LogFrequencySweep.*wMax.*give"),
    (lambda: sg.LogFrequencySweep(wMin=1.0, wMax=2.0, duration=-1.0), r"duration.*>= 0"),
    (lambda: sg.KinematicPTP(qd_max=0.0), r"KinematicPTP\.qd_max\[1\].*> 0"),
    (lambda: sg.KinematicPTP(deltaq=[1.0, 2.0, 3.0], qdd_max=[1.0, 2.0]),
     r"KinematicPTP: qdd_max has 2 elements.*nout = 3"),
    (lambda: sg.KinematicPTP(deltaq="a"), r"KinematicPTP: deltaq must be a number"),
    (lambda: sg.SineVariableFrequencyAndAmplitude(phi_start="a"),
     r"SineVariableFrequencyAndAmplitude: phi_start must be a number"),
])
def test_bad_parameters_are_refused_by_name(make, match):
    with pytest.raises(ParameterError, match=match):
        make()


def test_bad_parameters_at_simulation_time_are_refused_by_name():
    c = acausal.compile(_source_model(sg.SawTooth()))
    with pytest.raises(ParameterError, match=r"src\.period.*> 0"):
        c.simulate(1.0, params={"src.period": -1.0})
