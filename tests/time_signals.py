"""Signals of time shared by the component tests: a source of any function of time, and the
references its integrals are checked against."""
from __future__ import annotations

import numpy as np
from scipy.integrate import quad

from acausal.core import Component, RealOutput


class TimeSignal(Component):
    """Test-local signal source: y = fn(time), fn a CasADi-compatible function of time (an
    explicit, differentiable one)."""
    y = RealOutput("fn(time)")

    def __init__(self, fn, name=None):
        super().__init__(name)
        self.__dict__["_fn"] = fn

    def physics(self, e):
        e.output(self.y, self._fn(e.time))


def cumulative_integral(f, t, breaks=()):
    """∫_0^t f for every grid time, by adaptive quadrature between grid points (``breaks``:
    the times where f jumps or kinks)."""
    out = np.zeros_like(t)
    for i in range(1, t.size):
        pts = [b for b in breaks if t[i - 1] < b < t[i]]
        out[i] = out[i - 1] + quad(f, t[i - 1], t[i], points=pts or None, limit=200,
                                   epsabs=1e-13, epsrel=1e-13)[0]
    return out


def after(t, t0, value):
    """``value`` from t0 on, 0 before."""
    return np.where(t < t0, 0.0, value)
