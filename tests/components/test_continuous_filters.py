"""LimIntegrator, Der, CriticalDamping, LowpassButterworth and Filter (MSL Continuous) against
references that do not come from the code under test.

Filters: the frequency response of the compiled block (acausal.analysis.linearize) at the
cut-off frequency (-3 dB = 10^(-3/20) for MSL's normalized CriticalDamping, Bessel and
ChebyshevI, 1/sqrt(2) for Butterworth), at zero and high frequency; the poles against
scipy.signal.butter / cheby1 / bessel (analog, where the normalizations coincide: Butterworth
always, ChebyshevI and Bessel non-normalized: scipy's pass band edge and norm='delay'), band
filters against scipy.signal.lp2bp / lp2bs of scipy's Butterworth; step responses against
scipy.signal.lti of the same transfer function; MSL's examples Filter, FilterWithRiseTime
and FilterWithDifferentiation against the MSL reference results (within 1e-5: the
accuracy of the reference's own integration). LimIntegrator against its
closed form for a sine input; Der against the derivatives of the filter's step response
(its impulse response and the rates of it, from scipy's state space).
"""
from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.signal as sig
from scipy.linalg import expm

import acausal
from acausal import Model, ParameterError
from acausal.analysis import linearize
from acausal.components import signals as sg
from acausal.errors import AcausalError

SIM = dict(rtol=1e-10, atol=1e-12)
MINUS_3_DB = 10 ** (-3 / 20)
BLOCKS = "Modelica.Blocks.Examples."


def _linear(block) -> tuple:
    """A, B, C, D of ``block`` (one input u, output y) from the compiled model."""
    m = Model("lin")
    m.u = acausal.Input()
    m.f = block
    m.y = acausal.Output()
    m.connect(m.u.y, m.f.u)
    m.connect(m.f.y, m.y.u)
    lin = linearize(acausal.compile(m), {})
    return lin.A, lin.B, lin.C, lin.D


def _response(block, f) -> np.ndarray:
    """|H(j·2π·f)| of the compiled block at the frequencies f [Hz]."""
    return _magnitude(_linear(block), f)


def _magnitude(system, f) -> np.ndarray:
    """|C·(j·2π·f·I − A)⁻¹·B + D| of system = (A, B, C, D) at the frequencies f [Hz]."""
    A, B, C, D = system
    n = A.shape[0]
    return np.array([abs((C @ np.linalg.solve(2j * math.pi * fi * np.eye(n) - A, B) + D)[0, 0])
                     for fi in np.atleast_1d(f)])


def _poles(block) -> np.ndarray:
    return np.sort_complex(np.linalg.eigvals(_linear(block)[0]))


@pytest.mark.parametrize("kind", list(sg.AnalogFilter))
@pytest.mark.parametrize("order", [1, 2, 3, 4, 5, 8])
def test_normalized_low_and_high_pass_are_minus_3_db_at_f_cut(kind, order):
    cut = 1 / math.sqrt(2) if kind is sg.AnalogFilter.Butterworth else MINUS_3_DB
    for ftype, ends in (("LowPass", (1e-6, 1e6)), ("HighPass", (1e6, 1e-6))):
        f = sg.Filter(analogFilter=kind, filterType=ftype, order=order, f_cut=3.0, gain=2.0,
                      init="NoInit")
        at_cut, passed, stopped = _response(f, [3.0, *ends])
        assert at_cut == pytest.approx(2 * cut, rel=1e-10)
        assert passed == pytest.approx(2.0, rel=1e-6)
        assert stopped < 1e-5


def _scipy_poles(z_p_k) -> np.ndarray:
    return np.sort_complex(z_p_k[1])


@pytest.mark.parametrize("order", [1, 2, 3, 6])
def test_poles_against_scipy(order):
    w = 2 * math.pi * 1.5
    cases = [
        (dict(analogFilter="Butterworth"), sig.butter(order, w, analog=True, output="zpk")),
        (dict(analogFilter="ChebyshevI", A_ripple=0.7, normalized=False),
         sig.cheby1(order, 0.7, w, analog=True, output="zpk")),
        (dict(analogFilter="Bessel", normalized=False),
         sig.bessel(order, w, analog=True, output="zpk", norm="delay")),
        (dict(analogFilter="CriticalDamping", normalized=False),
         ([], [-w] * order, 1.0)),
    ]
    for kw, ref in cases:
        ours = _poles(sg.Filter(order=order, f_cut=1.5, init="NoInit", **kw))
        np.testing.assert_allclose(ours, _scipy_poles(ref), rtol=1e-9, atol=1e-9)


def test_critical_damping_normalization_closed_form():
    """Filter's normalized CriticalDamping: n poles at -w_cut/alpha, alpha =
    sqrt(10^(3/(10n)) - 1); the block CriticalDamping: alpha = sqrt(2^(1/n) - 1)."""
    for n in (1, 2, 5):
        w = 2 * math.pi * 2.0
        ours = _poles(sg.Filter(order=n, f_cut=2.0, init="NoInit"))
        np.testing.assert_allclose(ours, [-w / math.sqrt(10 ** (0.3 / n) - 1)] * n, rtol=1e-9)
        np.testing.assert_allclose(_poles(sg.CriticalDamping(n=n, f=2.0)),
                                   [-w / math.sqrt(2 ** (1 / n) - 1)] * n, rtol=1e-9)
        assert _response(sg.CriticalDamping(n=n, f=2.0), 2.0)[0] == pytest.approx(1 / math.sqrt(2), rel=1e-10)


@pytest.mark.parametrize("ftype", ["BandPass", "BandStop"])
@pytest.mark.parametrize("order", [1, 2, 3])
def test_butterworth_band_filters_against_scipy(ftype, order):
    """The poles of scipy.signal.lp2bp / lp2bs of scipy's Butterworth; the amplitudes too,
    but for band stop filters of order >= 2, whose sections MSL 4.1 gives the zeros s² +
    c0 of their own c0 (see Filter's docstring)."""
    f_min, f_cut = 2.0, 5.0
    wo, bw = 2 * math.pi * math.sqrt(f_min * f_cut), 2 * math.pi * (f_cut - f_min)
    b, a = sig.butter(order, 1.0, analog=True)
    b, a = (sig.lp2bp if ftype == "BandPass" else sig.lp2bs)(b, a, wo=wo, bw=bw)
    block = sg.Filter(analogFilter="Butterworth", filterType=ftype, order=order, f_cut=f_cut,
                      f_min=f_min, init="NoInit")
    system = _linear(block)
    np.testing.assert_allclose(np.sort_complex(np.linalg.eigvals(system[0])),
                               np.sort_complex(np.roots(a)), rtol=1e-8)
    f = np.array([0.3, 1.0, f_min, 3.0, f_cut, 9.0])
    _, h = sig.freqs(b, a, worN=2 * math.pi * f)
    if ftype == "BandPass" or order == 1:
        np.testing.assert_allclose(_magnitude(system, f), np.abs(h), rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize("kind", list(sg.AnalogFilter))
def test_band_filters_are_symmetric_and_stop_at_the_center(kind):
    """Band pass: equal amplitudes at f_min and f_cut (both map to the low pass's cut-off),
    0 at zero and high frequency; band stop: 1 there, 0 at the center sqrt(f_min·f_cut)."""
    f_min, f_cut = 3.0, 4.0
    lo, hi, zero, high = _response(sg.Filter(analogFilter=kind, filterType="BandPass",
                                             order=3, f_cut=f_cut, f_min=f_min,
                                             init="NoInit"), [f_min, f_cut, 1e-6, 1e6])
    assert lo == pytest.approx(hi, rel=1e-9) and zero < 1e-10 and high < 1e-10
    center, zero, high = _response(sg.Filter(analogFilter=kind, filterType="BandStop",
                                             order=3, f_cut=f_cut, f_min=f_min,
                                             init="NoInit"), [math.sqrt(f_min * f_cut),
                                                              1e-6, 1e6])
    assert center < 1e-8
    assert zero == pytest.approx(1.0, rel=1e-9) and high == pytest.approx(1.0, rel=1e-6)


def test_band_pass_of_real_poles_too_wide_is_refused():
    """MSL's assert: the band transformation of CriticalDamping's real poles over a wide
    band gives real poles, which the realization cannot take."""
    with pytest.raises(ParameterError, match="another analog filter"):
        sg.Filter(filterType="BandPass", order=3, f_cut=4.0, f_min=1.0)


def _step_model(block, offset=0.1, height=1.0, start=0.1) -> Model:
    m = Model("step_test")
    m.step = sg.Step(height=height, offset=offset, startTime=start)
    m.f = block
    m.connect(m.step.y, m.f.u)
    return m


def _lti_step(b, a, t, offset=0.1, height=1.0, start=0.1) -> np.ndarray:
    """The response of b/a (DC gain b[-1]/a[-1]) from steady state at u = offset to the step
    of ``height`` at ``start``."""
    dc = b[-1] / a[-1]
    after = t >= start
    y = np.full_like(t, offset * dc)
    _, ys = sig.step(sig.lti(b, a), T=t[after] - start)
    y[after] += height * ys
    return y


T = np.linspace(0.0, 1.5, 151)


@pytest.mark.parametrize("ftype", ["LowPass", "HighPass"])
def test_step_responses_against_scipy_lti(ftype):
    """Butterworth and non-normalized ChebyshevI (scipy's) and CriticalDamping (closed
    form), order 3, steady state at the start."""
    w = 2 * math.pi * 2.0
    refs = {"Butterworth": sig.butter(3, w, btype=ftype.lower(), analog=True),
            "CriticalDamping": (np.poly([-w] * 3)[-1:], np.poly([-w] * 3))}
    cheb = sig.cheby1(3, 0.5, w, btype=ftype.lower(), analog=True)
    refs["ChebyshevI"] = cheb
    for kind, (b, a) in refs.items():
        if kind == "CriticalDamping" and ftype == "HighPass":
            b = [1.0, 0.0, 0.0, 0.0]                 # s³/(s + w)³
        block = sg.Filter(analogFilter=kind, filterType=ftype, order=3, f_cut=2.0,
                          normalized=False, A_ripple=0.5)
        res = acausal.compile(_step_model(block)).simulate(T[-1], t=T, **SIM)
        ref = _lti_step(b, a, T)
        y = np.interp(T, res.t, res["f.y"])
        assert np.abs(y - ref).max() < 1e-7, kind


def test_msl_filter_example(reference_result):
    """MSL Blocks.Examples.Filter: step 0.1 -> 1.1 at 0.1 s into low pass filters of order 3,
    f_cut = 2 Hz, normalized, steady state at the start: every state."""
    ref = reference_result("MAP-LIB_ReferenceResults", BLOCKS + "Filter")
    m = Model("Filter")
    m.step = sg.Step(startTime=0.1, offset=0.1)
    for kind in sg.AnalogFilter:
        setattr(m, kind.value, sg.Filter(analogFilter=kind, order=3, f_cut=2.0, f_min=1.6))
        m.connect(m.step.y, getattr(m, kind.value).u)
    t = ref["time"]
    res = acausal.compile(m).simulate(float(t[-1]), t=np.unique(t), **SIM)
    for name in (n for n in ref if n != "time"):
        ours = np.interp(t, res.t, res[name])
        assert np.abs(ours - ref[name]).max() < 1e-5, name


def test_msl_filter_with_rise_time_example(reference_result):
    """MSL Blocks.Examples.FilterWithRiseTime: CriticalDamping low pass filters of order 2
    with f_cut = fac/(2π·riseTime), fac = 3, 4, 5, riseTime = 2 s, step at 1 s."""
    ref = reference_result("MAP-LIB_ReferenceResults", BLOCKS + "FilterWithRiseTime")
    m = Model("FilterWithRiseTime")
    m.step = sg.Step(startTime=1.0)
    for fac in (3, 4, 5):
        setattr(m, f"filter_fac{fac}", sg.Filter(f_cut=fac / (2 * math.pi * 2.0), order=2))
        m.connect(m.step.y, getattr(m, f"filter_fac{fac}").u)
    t = ref["time"]
    res = acausal.compile(m).simulate(float(t[-1]), t=np.unique(t), **SIM)
    for name in (n for n in ref if n != "time"):
        assert np.abs(np.interp(t, res.t, res[name]) - ref[name]).max() < 1e-5, name


def _differentiation_model() -> Model:
    m = Model("FilterWithDifferentiation")
    m.step = sg.Step(startTime=0.1, offset=0.1)
    m.Bessel = sg.Filter(f_cut=2.0, order=3, analogFilter="Bessel")
    m.der1, m.der2, m.der3 = sg.Der(), sg.Der(), sg.Der()
    m.connect(m.step.y, m.Bessel.u)
    m.connect(m.Bessel.y, m.der1.u)
    m.connect(m.der1.y, m.der2.u)
    m.connect(m.der2.y, m.der3.u)
    return m


def test_msl_filter_with_differentiation_example(reference_result):
    """MSL Blocks.Examples.FilterWithDifferentiation: the Bessel filter's states."""
    ref = reference_result("MAP-LIB_ReferenceResults", BLOCKS + "FilterWithDifferentiation")
    t = ref["time"]
    res = acausal.compile(_differentiation_model()).simulate(float(t[-1]), t=np.unique(t),
                                                              **SIM)
    for name in (n for n in ref if n != "time"):
        assert np.abs(np.interp(t, res.t, res[name]) - ref[name]).max() < 1e-5, name


def test_der_gives_the_exact_derivatives_of_the_filter_output():
    """der1..der3 of the Bessel filter's step response: the impulse response h and its rates
    h', h'' of the filter's linearization: C·A^(k−1)·e^(A·t)·B, by scipy's expm)."""
    A, B, C, _ = _linear(sg.Filter(f_cut=2.0, order=3, analogFilter="Bessel", init="NoInit"))
    res = acausal.compile(_differentiation_model()).simulate(T[-1], t=T, **SIM)
    after = T >= 0.1
    for k in (1, 2, 3):
        ref = np.zeros_like(T)
        ref[after] = [(C @ np.linalg.matrix_power(A, k - 1) @ expm(A * (t - 0.1)) @ B)[0, 0]
                      for t in T[after]]
        y = res[f"der{k}.y"][np.searchsorted(res.t, T, side="right") - 1]
        scale = np.abs(ref).max()
        assert np.abs(y - ref).max() < 1e-6 * scale, k


def test_der_of_a_model_input_is_refused():
    m = Model("der_input")
    m.u = acausal.Input()
    m.d = sg.Der()
    m.connect(m.u.y, m.d.u)
    with pytest.raises(AcausalError, match=r"time derivative of 'u' is needed but unknown.*"
                                           r"a Der block.*Derivative block"):
        acausal.compile(m).simulate(1.0)


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_lowpass_butterworth_against_scipy(n):
    block = sg.LowpassButterworth(n=n, f=2.0, initType="SteadyState")
    res = acausal.compile(_step_model(block)).simulate(T[-1], t=T, **SIM)
    b, a = sig.butter(n, 2 * math.pi * 2.0, analog=True)
    assert np.abs(np.interp(T, res.t, res["f.y"]) - _lti_step(b, a, T)).max() < 1e-7
    assert _response(sg.LowpassButterworth(n=n, f=2.0), 2.0)[0] == pytest.approx(
        1 / math.sqrt(2), rel=1e-10)


@pytest.mark.parametrize("n", [1, 3])
@pytest.mark.parametrize("normalized", [True, False])
def test_critical_damping_against_closed_form(n, normalized):
    w = 2 * math.pi * 2.0 / (math.sqrt(2 ** (1 / n) - 1) if normalized else 1.0)
    block = sg.CriticalDamping(n=n, f=2.0, normalized=normalized, initType="SteadyState")
    res = acausal.compile(_step_model(block)).simulate(T[-1], t=T, **SIM)
    den = np.poly([-w] * n)
    ref = _lti_step(den[-1:], den, T)
    assert np.abs(np.interp(T, res.t, res["f.y"]) - ref).max() < 1e-7


@pytest.mark.parametrize("block", [
    lambda init: sg.CriticalDamping(n=3, f=2.0, initType=init, y_start=0.4),
    lambda init: sg.LowpassButterworth(n=3, f=2.0, initType=init, y_start=0.4),
    lambda init: sg.LowpassButterworth(n=4, f=2.0, initType=init, y_start=0.4),
    lambda init: sg.Filter(order=3, f_cut=2.0, analogFilter="Bessel", init=init, y_start=0.4),
    lambda init: sg.Filter(order=2, f_cut=2.0, filterType="HighPass", init=init, y_start=0.4),
], ids=["CriticalDamping", "Butterworth3", "Butterworth4", "FilterBessel", "FilterHighPass"])
def test_initialization(block):
    """SteadyState: y = u (high pass: 0) at the start, no transient before the step;
    InitialOutput: y = y_start."""
    t = np.linspace(0.0, 0.09, 10)
    for init in ("SteadyState", "InitialOutput"):
        b = block(init)
        high = getattr(b, "filterType", None) is sg.FilterType.HighPass
        res = acausal.compile(_step_model(b, offset=0.3)).simulate(t[-1], t=t, **SIM)
        if init == "SteadyState":
            np.testing.assert_allclose(res["f.y"], 0.0 if high else 0.3, atol=1e-9)
        else:
            assert res["f.y"][0] == pytest.approx(0.4, abs=1e-10)


def _lim_integrator_reference(t, out=0.1) -> np.ndarray:
    """y of der(y) = sin(2πt) halted at ±out, y(0) = 0, in closed form by pieces: rising
    (from 0, later from -out) up to out, held until 0.5 s into the period, falling to -out,
    held until the period ends."""
    F = lambda s: (1 - np.cos(2 * math.pi * s)) / (2 * math.pi)    # noqa: E731  ∫0^s sin
    fall = 1 - math.acos(1 - 2 * math.pi * (F(0.5) - 2 * out)) / (2 * math.pi)
    y = np.empty_like(t)
    for i, s in enumerate(t):
        n, p = divmod(s, 1.0)
        if p < 0.5:
            y[i] = min(out, (0.0 if n == 0 else -out) + F(p))
        elif p < fall:
            y[i] = out + F(p) - F(0.5)
        else:
            y[i] = -out
    return y


@pytest.mark.parametrize("strict", [False, True])
def test_lim_integrator_against_closed_form(strict):
    t = np.linspace(0.0, 2.0, 401)
    m = Model("lim")
    m.sine = sg.Sine(f=1.0)
    m.li = sg.LimIntegrator(outMax=0.1, strict=strict)
    m.connect(m.sine.y, m.li.u)
    # strict (no events): resting at a limit der(y) = 0 exactly, so the integrator's steps
    # grow past the input's sign change unless max_step bounds them (see the docstring)
    res = acausal.compile(m).simulate(t[-1], t=t, **SIM, **({"max_step": 0.01} if strict
                                                               else {}))
    y = np.interp(t, res.t, res["li.y"])
    assert np.abs(y - _lim_integrator_reference(t)).max() < (1e-7 if not strict else 1e-5)


def test_lim_integrator_smooth_form_stays_within_the_limits():
    t = np.linspace(0.0, 2.0, 401)
    m = Model("lim")
    m.sine = sg.Sine(f=1.0)
    m.li = sg.LimIntegrator(outMax=0.1, outMin=-0.08, y_smooth=1e-3)
    m.connect(m.sine.y, m.li.u)
    res = acausal.compile(m, smooth=True).simulate(t[-1], t=t, **SIM)
    y = res["li.y"]
    assert y.max() <= 0.1 + 1e-12 and y.min() >= -0.08 - 1e-12
    assert y.max() > 0.1 - 1e-3 and y.min() < -0.08 + 1e-3


@pytest.mark.parametrize("make, says", [
    (lambda: sg.Filter(order=0, f_cut=1.0), "order"),
    (lambda: sg.Filter(order=2.5, f_cut=1.0), "order"),
    (lambda: sg.Filter(order=2), "f_cut"),
    (lambda: sg.Filter(order=2, f_cut=0.0), "f_cut"),
    (lambda: sg.Filter(order=2, f_cut=1.0, filterType="BandPass", f_min=1.0), "f_min"),
    (lambda: sg.Filter(order=2, f_cut=1.0, filterType="BandStop"), "f_min"),
    (lambda: sg.Filter(order=2, f_cut=1.0, analogFilter="ChebyshevI", A_ripple=0.0),
     "A_ripple"),
    (lambda: sg.Filter(order=42, f_cut=1.0, analogFilter="Bessel"), "between 1 and 41"),
    (lambda: sg.CriticalDamping(n=0, f=1.0), "n "),
    (lambda: sg.LowpassButterworth(n=-1, f=1.0), "n "),
    (lambda: sg.CriticalDamping(n=2, f=-1.0), "f"),
    (lambda: sg.LimIntegrator(outMax=-1.0, outMin=1.0), "outMax"),
])
def test_bad_input_is_a_parameter_error(make, says):
    with pytest.raises(ParameterError, match=says) as err:
        make()
    assert any(name in str(err.value) for name in ("Filter", "CriticalDamping",
                                                   "LowpassButterworth", "LimIntegrator",
                                                   "parameter"))
