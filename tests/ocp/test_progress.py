"""A progress bar of IPOPT's iterations: one update per iteration, the solution unchanged
(the first passage of a damped oscillator through 0, against its closed form)."""
import importlib

import numpy as np
import pytest

import acausal
from acausal.models.oscillators import Oscillator
from acausal.ocp import OCP, FreeTime

problem = importlib.import_module("acausal.ocp.problem")


class _Counter:
    def __init__(self):
        self.n, self.closed = 0, False

    def update(self, n=1):
        self.n += n

    def close(self):
        self.closed = True


def test_one_update_per_ipopt_iteration(monkeypatch):
    bars = []

    def bar(*args, **kwargs):
        bars.append(_Counter())
        return bars[-1]
    monkeypatch.setattr(problem, "progress_bar", bar)
    ocp = OCP(acausal.compile(Oscillator()), N=40, T=FreeTime(guess=1.0, lower=0.1, upper=2.5),
              params={"spring.c": 1.0, "damper.d": 0.1})
    ocp.minimize(ocp.T)
    ocp.initial({"mass.s": 1.0, "mass.v": 0.0})
    ocp.final({"mass.s": 0.0})
    sol = ocp.solve({"tol": 1e-12}, progress=True)
    zeta = 0.05
    wd = np.sqrt(1 - zeta ** 2)
    assert sol.T == pytest.approx((np.pi / 2 + np.arctan(zeta / wd)) / wd, rel=1e-8)
    assert len(bars) == 1 and bars[0].closed
    assert bars[0].n == sol.stats["iter_count"] + 1          # iteration 0 included
