"""Harmonic and TotalHarmonicDistortion (MSL Math) on a signal made of known harmonics,
against numpy's FFT and RMS of its samples over one period (exact for a band-limited
signal), at the middle of the sample periods (held values)."""
from __future__ import annotations

import numpy as np
import pytest

import acausal
from acausal import Model, ParameterError
from acausal.components import signals as sg

SIM = dict(rtol=1e-10, atol=1e-12)
F = 5.0                                  # base frequency [Hz]
OFFSET = 0.3
WAVES = {1: (2.0, 0.4), 2: (0.5, -1.1), 5: (0.8, 2.5)}     # k: (RMS, phase [rad])


def _signal_model(blocks: dict) -> Model:
    """OFFSET + Σ √2·U_k·cos(2π·k·F·t − φ_k) (Cosine sources summed) into each block's u."""
    m = Model("harmonics")
    m.sum = sg.MultiSum(nu=len(WAVES) + 1)
    m.offset = sg.Constant(k=OFFSET)
    m.connect(m.offset.y, m.sum.u[1])
    for i, (k, (rms, phase)) in enumerate(WAVES.items(), start=2):
        wave = sg.Cosine(amplitude=np.sqrt(2) * rms, f=k * F, phase=-phase)
        setattr(m, f"wave{k}", wave)
        m.connect(wave.y, m.sum.u[i])
    for name, block in blocks.items():
        setattr(m, name, block)
        m.connect(m.sum.y, block.u)
    return m


def _samples(n: int = 1024) -> np.ndarray:
    t = np.arange(n) / (n * F)
    return OFFSET + sum(np.sqrt(2) * rms * np.cos(2 * np.pi * k * F * t - phase)
                        for k, (rms, phase) in WAVES.items())


def _fft_harmonic(k: int) -> tuple[float, float]:
    """(RMS, phase) of harmonic k from numpy's FFT of one period."""
    c = 2 * np.fft.rfft(_samples())[k] / len(_samples())
    return abs(c) / np.sqrt(2), -np.angle(c)


def _held(res, names, periods: int = 4):
    """Values at the middle of the periods 1 .. periods (after the instants k/F)."""
    t = (np.arange(periods) + 1.5) / F
    at = np.searchsorted(res.t, t, side="right") - 1
    return {n: res[n][at] for n in names}


def _simulate(m: Model, periods: int = 4):
    t_end = (periods + 1.5) / F
    return acausal.compile(m).simulate(t_end, t=np.linspace(0.0, t_end, 2 * periods + 4),
                                       **SIM)


@pytest.mark.parametrize("k", [1, 2, 3, 5])
def test_harmonic_is_the_fft_coefficient(k):
    m = _signal_model({"h": sg.Harmonic(f=F, k=k), "hc": sg.Harmonic(
        f=F, k=k, useConjugateComplex=True)})
    held = _held(_simulate(m), ["h.y_rms", "h.y_arg", "hc.y_rms", "hc.y_arg"])
    rms, phase = _fft_harmonic(k)
    np.testing.assert_allclose(held["h.y_rms"], rms, atol=1e-8)
    np.testing.assert_allclose(held["hc.y_rms"], rms, atol=1e-8)
    if rms > 1e-6:
        np.testing.assert_allclose(held["h.y_arg"], phase, atol=1e-8)
        np.testing.assert_allclose(held["hc.y_arg"], -phase, atol=1e-8)
    if k in WAVES:
        assert rms == pytest.approx(WAVES[k][0], abs=1e-12)


def test_harmonic_start_values():
    """Before 1/F the outputs come from y0Cos, y0Sin; x0Cos, x0Sin add F·x0 to the first
    means (MSL's Mean start values)."""
    x0c, x0s, y0c, y0s = 0.1, -0.2, 0.6, 0.8
    m = _signal_model({"h": sg.Harmonic(f=F, x0Cos=x0c, x0Sin=x0s, y0Cos=y0c, y0Sin=y0s)})
    t = np.array([0.5, 1.5]) / F
    res = acausal.compile(m).simulate(t[-1], t=np.append(0.0, t), **SIM)
    at = np.searchsorted(res.t, t, side="right") - 1
    rms, arg = res["h.y_rms"][at], res["h.y_arg"][at]
    assert rms[0] == pytest.approx(1.0) and arg[0] == pytest.approx(np.arctan2(y0s, y0c))
    U1, phi = WAVES[1]
    re, im = U1 * np.cos(phi) + F * x0c, U1 * np.sin(phi) + F * x0s
    assert rms[1] == pytest.approx(np.hypot(re, im), abs=1e-8)
    assert arg[1] == pytest.approx(np.arctan2(im, re), abs=1e-8)


def test_total_harmonic_distortion_against_fft_and_rms():
    """THD with respect to the first harmonic and to the total RMS (the offset counts as
    distortion: it is in the RMS, not in the first harmonic); valid from the first
    instant."""
    m = _signal_model({"thd1": sg.TotalHarmonicDistortion(f=F),
                       "thdRMS": sg.TotalHarmonicDistortion(f=F, useFirstHarmonic=False)})
    res = _simulate(m)
    held = _held(res, ["thd1.y", "thdRMS.y", "thd1.valid", "thdRMS.valid"])
    U, U1 = np.sqrt(np.mean(_samples() ** 2)), _fft_harmonic(1)[0]
    rest = np.sqrt(U ** 2 - U1 ** 2)
    np.testing.assert_allclose(held["thd1.y"], rest / U1, rtol=1e-7)
    np.testing.assert_allclose(held["thdRMS.y"], rest / U, rtol=1e-7)
    assert held["thd1.valid"].all() and held["thdRMS.valid"].all()
    before = res.t < 1 / F
    assert not res["thd1.valid"][before].any() and np.all(res["thd1.y"][before] == 0)


def test_total_harmonic_distortion_of_zero_is_not_valid():
    m = Model("thd_of_zero")
    m.zero, m.thd = sg.Constant(k=0.0), sg.TotalHarmonicDistortion(f=F)
    m.connect(m.zero.y, m.thd.u)
    res = acausal.compile(m).simulate(3 / F, **SIM)
    assert not res["thd.valid"].any() and np.all(res["thd.y"] == 0)


@pytest.mark.parametrize("k", [0, -1, 1.5, True, "2"])
def test_harmonic_order_must_be_a_positive_integer(k):
    with pytest.raises(ParameterError, match=r"Harmonic: k \(order of the harmonic\)"):
        sg.Harmonic(k=k)


@pytest.mark.parametrize("make", [lambda: sg.Harmonic(f=0.0),
                                  lambda: sg.TotalHarmonicDistortion(f=-1.0)])
def test_base_frequency_must_be_positive(make):
    with pytest.raises(ParameterError, match=r"\.f"):
        make()
