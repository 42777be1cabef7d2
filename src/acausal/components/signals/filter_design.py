"""The coefficients of MSL's analog filters (Modelica.Blocks.Continuous.Internal.Filter, MSL 4.1):
the base low pass filters with cut-off 1 rad/s, their transformation to low, high, band pass
and band stop filters, and the eigenvalue form the block Continuous.Filter integrates.

A base filter is a chain of first order sections cr/(s + cr) (real poles) and second order
sections c0/(s² + c1·s + c0) (conjugate complex pairs), each with gain 1 at s = 0. Normalized
(``normalized=True``) the amplitude at the cut-off frequency is -3 dB = 10^(-3/20) (MSL's
definition: CriticalDamping, Bessel, ChebyshevI); Butterworth is always at 1/sqrt(2) there.
Where MSL solves a nonlinear equation (Brent's method) these functions take the root of the
same equation written as a polynomial (numpy.roots), then polish it with Newton steps.
"""
from __future__ import annotations

import functools
import math
from enum import Enum
from typing import NamedTuple

import numpy as np

#: The amplitude MSL's normalized filters have at the cut-off frequency: -3 dB.
MINUS_3_DB = 10 ** (-3 / 20)
#: The highest order of MSL's Bessel filters (the orders its coefficient table holds).
BESSEL_MAX_ORDER = 41


class AnalogFilter(str, Enum):
    """Modelica.Blocks.Types.AnalogFilter: the characteristics of an analog filter."""
    CriticalDamping = "CriticalDamping"
    Bessel = "Bessel"
    Butterworth = "Butterworth"
    ChebyshevI = "ChebyshevI"


class FilterType(str, Enum):
    """Modelica.Blocks.Types.FilterType: which band a filter passes."""
    LowPass = "LowPass"
    HighPass = "HighPass"
    BandPass = "BandPass"
    BandStop = "BandStop"


class Base(NamedTuple):
    """A base low pass filter (cut-off 1 rad/s): real poles s + cr, pairs s² + c1·s + c0."""
    cr: np.ndarray
    c0: np.ndarray
    c1: np.ndarray


class Roots(NamedTuple):
    """A filter in MSL's eigenvalue form: real eigenvalues r (der(x) = r·(x − u)); pairs
    a ± j·b with input gain ku (der(x1) = a·x1 − b·x2 + ku·u, der(x2) = b·x1 + a·x2) and
    output gains k1, k2 (y = k1·x1 + k2·x2 [+ u]; unused by low pass filters: y = x2)."""
    r: np.ndarray
    a: np.ndarray
    b: np.ndarray
    ku: np.ndarray
    k1: np.ndarray
    k2: np.ndarray


def _to_highest_power_one(den1, den2) -> Base:
    """MSL's toHighestPowerOne: (den1·s + 1) → s + 1/den1, (d1·s² + d2·s + 1) →
    s² + (d2/d1)·s + 1/d1."""
    den1, den2 = np.asarray(den1, float), np.asarray(den2, float).reshape(-1, 2)
    return Base(1 / den1, 1 / den2[:, 0], den2[:, 1] / den2[:, 0])


def _scaled(den1, den2, alpha: float) -> tuple:
    """The denominators with p replaced by alpha·p."""
    den2 = np.asarray(den2, float).reshape(-1, 2) * [alpha ** 2, alpha]
    return np.asarray(den1, float) * alpha, den2


def _polished_root(poly: np.ndarray, lo: float, hi: float, residue) -> float:
    """The real root of the polynomial ``poly`` (highest power first) in (lo, hi), the
    smallest one if there are several, polished by Newton steps on ``residue(z)`` (the same
    function, evaluated without expanding it into a polynomial: more accurate)."""
    roots = np.roots(poly)
    real = sorted(z.real for z in roots if abs(z.imag) <= 1e-9 * max(1.0, abs(z)) and
                  lo < z.real < hi)
    if not real:
        raise ValueError("no real root in the interval")
    z, dpoly = real[0], np.polyder(poly)
    for _ in range(3):
        slope = np.polyval(dpoly, z)
        if slope == 0:
            break
        z -= residue(z) / slope
    return float(z)


def normalization_factor(den1, den2) -> float:
    """MSL's normalizationFactor: alpha such that the filter with p replaced by alpha·p has
    the amplitude 10^(-3/20) at 1 rad/s: the root of Π|den(j·alpha)|² = 10^(3/10), a
    polynomial in z = alpha² (|a·p + 1|² = 1 + a²z, |b2·p² + b1·p + 1|² = 1 + (b1² − 2·b2)·z
    + b2²·z²)."""
    factors = [[a * a, 1.0] for a in np.ravel(den1)] + \
        [[b2 * b2, b1 * b1 - 2 * b2, 1.0] for b2, b1 in np.asarray(den2, float).reshape(-1, 2)]
    poly = np.array([1.0])
    for f in factors:
        poly = np.polymul(poly, f)
    target = MINUS_3_DB ** -2
    poly = np.polysub(poly, [target])
    return math.sqrt(_polished_root(
        poly, 0.0, np.inf, lambda z: math.prod(np.polyval(f, z) for f in factors) - target))


@functools.cache
def bessel_sections(order: int) -> tuple[list, list]:
    """The Bessel filter of ``order`` not normalized (group delay 1 s at low frequency), in
    MSL's form: den1 the [p] coefficient a of the real pole's a·p + 1 (odd orders), den2 the
    [p², p] coefficients of the pairs' b2·p² + b1·p + 1, the most damped first. Its poles
    are the roots of the reverse Bessel polynomial Σ (2n−k)!/(2^(n−k)·k!·(n−k)!)·p^k
    (n = order), found by the Aberth–Ehrlich iteration from numpy.roots' estimates with the
    polynomial evaluated in 256-bit fixed point: its integer coefficients span 60 decades at
    order 41, where numpy.roots alone is wrong from order ~15 on."""
    n = order
    c = [math.factorial(2 * n - k) // (2 ** (n - k) * math.factorial(k) * math.factorial(n - k))
         for k in range(n + 1)]
    r = float(c[0]) ** (1.0 / n)                  # p = r·x: the roots of moderate coefficients
    poles = list(np.roots([float(ck) * r ** k / float(c[0]) for k, ck in enumerate(c)][::-1])
                 * r)
    for _ in range(100):
        largest = 0.0
        for k, z in enumerate(poles):
            q = _newton_step(c, z)
            w = q / (1 - q * sum(1 / (z - zj) for j, zj in enumerate(poles) if j != k))
            poles[k] = z - w
            largest = max(largest, abs(w) / abs(z))
        if largest < 1e-17:
            break
    den1 = [-1 / z.real for z in poles if abs(z.imag) <= 1e-9 * abs(z)]
    den2 = sorted(([1 / abs(z) ** 2, -2 * z.real / abs(z) ** 2] for z in poles
                   if z.imag > 1e-9 * abs(z)), key=lambda d: -d[1])
    return den1, den2


def _newton_step(coeffs: list[int], z: complex, bits: int = 256) -> complex:
    """p(z)/p'(z) of the polynomial with integer ``coeffs`` (lowest power first), evaluated
    by Horner's scheme in fixed point with ``bits`` fraction bits."""
    one = 1 << bits
    x, y = int(round(z.real * one)), int(round(z.imag * one))
    pr, pi, dr, di = coeffs[-1] * one, 0, 0, 0
    for c in reversed(coeffs[:-1]):
        dr, di = ((dr * x - di * y) >> bits) + pr, ((dr * y + di * x) >> bits) + pi
        pr, pi = ((pr * x - pi * y) >> bits) + c * one, (pr * y + pi * x) >> bits
    return complex(pr / one, pi / one) / complex(dr / one, di / one)


def base_filter(kind: AnalogFilter, order: int, normalized: bool = True,
                A_ripple: float = 0.5) -> Base:
    """MSL's Internal.Filter.base: the base low pass filter of ``kind`` and ``order``
    (``A_ripple`` [dB]: the pass band ripple of ChebyshevI)."""
    m, odd = order // 2, order % 2
    if kind is AnalogFilter.CriticalDamping:
        alpha = math.sqrt(10 ** (3 / 10 / order) - 1) if normalized else 1.0
        return _to_highest_power_one([alpha] * order, np.zeros((0, 2)))
    if kind is AnalogFilter.Bessel:
        den1, den2 = bessel_sections(order)
        if normalized:
            den1, den2 = _scaled(den1, den2, normalization_factor(den1, den2))
        return _to_highest_power_one(den1, den2)
    if kind is AnalogFilter.Butterworth:
        den2 = [(1.0, -2 * math.cos(math.pi * (0.5 + (i - 0.5) / order)))
                for i in range(1, m + 1)]
        return _to_highest_power_one([1.0] * odd, den2)
    epsilon = math.sqrt(10 ** (A_ripple / 10) - 1)
    fac = math.asinh(1 / epsilon) / order
    den1 = [1 / math.sinh(fac)] * odd
    angles = [(i if odd else i - 0.5) * math.pi / order for i in range(1, m + 1)]
    den2 = [(d, 2 * d * math.sinh(fac) * math.cos(th))
            for th in angles for d in [1 / (math.cosh(fac) ** 2 - math.cos(th) ** 2)]]
    if normalized:
        den1, den2 = _scaled(den1, den2, normalization_factor(den1, den2))
    return _to_highest_power_one(den1, den2)


def band_pass_alpha(a: float, b: float, w: float) -> float:
    """MSL's bandPassAlpha: alpha = sqrt(z), z ∈ (0, 1) the root of z² + (a·w·z/(1 + z))²
    − (2 + b·w²)·z + 1 = 0, i.e. of (z² − (2 + b·w²)·z + 1)·(1 + z)² + a²w²z²."""
    poly = np.polyadd(np.polymul([1.0, -(2 + b * w * w), 1.0], [1.0, 2.0, 1.0]),
                      [a * a * w * w, 0.0, 0.0])
    return math.sqrt(_polished_root(
        poly, 0.0, 1.0, lambda z: z * z + (a * w * z / (1 + z)) ** 2 - (2 + b * w * w) * z + 1))


def _band(base: Base, w_band: float, stop: bool) -> tuple:
    """MSL's coefficients.bandPass / bandStop before the scaling by w_cut (w_cut = 1):
    c0, c1 of the second order sections."""
    c0, c1 = [], []
    for cr in base.cr:
        c1.append(w_band / cr if stop else cr * w_band)
        c0.append(1.0)
    for k0, k1 in zip(base.c0, base.c1):
        w = w_band / k0 if stop else w_band
        alpha = band_pass_alpha(k1, k0, w)
        c = k1 * w / (alpha + 1 / alpha)
        c1 += [c / alpha, c * alpha]
        c0 += [1 / alpha ** 2, alpha ** 2]
    return np.array(c0), np.array(c1)


def filter_roots(base: Base, filter_type: FilterType, f_cut: float,
                 f_min: float = 0.0) -> Roots:
    """MSL's Internal.Filter.roots: the eigenvalue form of the base filter transformed to
    ``filter_type`` with cut-off frequency ``f_cut`` [Hz] (band filters: the band f_min ..
    f_cut [Hz])."""
    none = np.zeros(0)
    if filter_type in (FilterType.LowPass, FilterType.HighPass):
        w = 2 * math.pi * f_cut
        if filter_type is FilterType.LowPass:
            cr, c0, c1 = w * base.cr, w * w * base.c0, w * base.c1
        else:
            cr, c0, c1 = w / base.cr, w * w / base.c0, w * base.c1 / base.c0
        a = -c1 / 2
        b = np.sqrt(c0 - a * a)
        ku = c0 / b
        if filter_type is FilterType.LowPass:
            return Roots(-cr, a, b, ku, none, none)
        ba2 = (b / a) ** 2
        return Roots(-cr, a, b, ku, 2 * a / ku, (1 - ba2) / (1 + ba2))
    f0 = math.sqrt(f_min * f_cut)
    w = 2 * math.pi * f0
    stop = filter_type is FilterType.BandStop
    c0, c1 = _band(base, (f_cut - f_min) / f0, stop)
    c0, c1 = w * w * c0, w * c1
    a = -c1 / 2
    bb = c0 - a * a
    if np.any(bb < 0):
        raise ValueError("the band transformation gives real poles: use another analog filter")
    b = np.sqrt(bb)
    ku = c0 / b
    if stop:
        return Roots(none, a, b, ku, 2 * a / ku, (c0 + a * a - b * b) / (b * ku))
    cn = (f_cut - f_min) / f0 * w
    return Roots(none, a, b, ku, cn / ku, cn * a / (b * ku))
