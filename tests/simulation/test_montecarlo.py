"""Monte-Carlo helpers: sampled parameters through sweep(), and the statistics over the
runs, against the closed form of an undamped oscillator x(t) = x0·cos(√(c/m)·t)."""
import numpy as np
import pytest
import scipy.stats

import acausal
from acausal import models, montecarlo

pytest.importorskip("xarray")

T = np.linspace(0.0, 5.0, 51)
C_LOW, C_HIGH = 1.0, 4.0           # spring stiffness range [N/m], mass 1 kg
N, SEED = 400, 7


@pytest.fixture(scope="module")
def oscillator():
    return acausal.compile(models.Oscillator(m=1.0, d=0.0))


def mean_response(t):
    """E[cos(√c·t)] for c uniform on [C_LOW, C_HIGH]: with w = √c (dc = 2w·dw),
    2/(C_HIGH − C_LOW)·[(cos wt + wt·sin wt)/t²] from √C_LOW to √C_HIGH."""
    t = np.asarray(t, dtype=float)
    out = np.ones_like(t)
    tt = t[t > 0]
    def F(w):
        return (np.cos(w * tt) + w * tt * np.sin(w * tt)) / tt ** 2
    out[t > 0] = 2.0 / (C_HIGH - C_LOW) * (F(np.sqrt(C_HIGH)) - F(np.sqrt(C_LOW)))
    return out


def test_uniform_stiffness_statistics_against_the_closed_form(oscillator):
    runs = montecarlo.samples({"spring.c": montecarlo.uniform(C_LOW, C_HIGH)}, n=N, seed=SEED)
    res = oscillator.sweep(T[-1], t=T, runs=runs, x0={"mass.s": 1.0})
    assert not res.failed and len(res) == N
    c = runs["spring.c"].to_numpy()
    exact = np.cos(np.sqrt(c)[:, None] * T[None, :])          # each run's closed form
    np.testing.assert_allclose(res["mass.s"], exact, atol=1e-6)
    stats = montecarlo.statistics(res, ["mass.s"], quantiles=(0.1, 0.5, 0.9))
    assert list(stats["statistic"].values) == ["mean", "std", "min", "max", "q10", "q50",
                                               "q90"]
    s = stats["mass.s"]
    np.testing.assert_allclose(s.sel(statistic="mean"), exact.mean(axis=0), atol=1e-6)
    np.testing.assert_allclose(s.sel(statistic="std"), exact.std(axis=0, ddof=1), atol=1e-6)
    for q in (0.1, 0.5, 0.9):
        np.testing.assert_allclose(s.sel(statistic=f"q{100 * q:g}"),
                                   np.quantile(exact, q, axis=0), atol=1e-6)
    # the sample mean against the expectation: within 4 standard errors at every time
    se = exact.std(axis=0, ddof=1) / np.sqrt(N)
    assert np.all(np.abs(s.sel(statistic="mean") - mean_response(T)) <= 4 * se + 1e-6)


def test_samples_are_seeded_and_take_scipy_distributions():
    a = montecarlo.samples({"spring.c": montecarlo.normal(4.0, 0.2),
                            "mass.m": scipy.stats.uniform(1.0, 0.5), "damper.d": 0.3},
                           n=5, seed=11)
    b = montecarlo.samples({"spring.c": montecarlo.normal(4.0, 0.2),
                            "mass.m": scipy.stats.uniform(1.0, 0.5), "damper.d": 0.3},
                           n=5, seed=11)
    assert a.equals(b)
    rng = np.random.default_rng(11)                     # drawn in the order given
    np.testing.assert_array_equal(a["spring.c"], rng.normal(4.0, 0.2, 5))
    np.testing.assert_array_equal(a["mass.m"], 1.0 + 0.5 * rng.uniform(size=5))
    np.testing.assert_array_equal(a["damper.d"], np.full(5, 0.3))
    with pytest.raises(acausal.ParameterError):
        montecarlo.normal(1.0, -0.1)
    with pytest.raises(acausal.ParameterError):
        montecarlo.samples({"spring.c": "wide"}, n=3)


def test_statistics_leave_out_failed_runs(oscillator):
    """A normal wide enough to draw negative stiffnesses: those runs fail (a spring
    constant must be >= 0) and the statistics count the others only."""
    runs = montecarlo.samples({"spring.c": montecarlo.normal(0.5, 1.0)}, n=40, seed=2)
    res = oscillator.sweep(T[-1], t=T, runs=runs, x0={"mass.s": 1.0})
    bad = np.flatnonzero(runs["spring.c"].to_numpy() < 0)
    assert bad.size and sorted(res.failed) == list(bad)
    stats = montecarlo.statistics(res)
    good = np.setdiff1d(np.arange(40), bad)
    exact = np.cos(np.sqrt(runs["spring.c"].to_numpy()[good])[:, None] * T[None, :])
    assert stats.attrs["runs"] == good.size
    np.testing.assert_allclose(stats["mass.s"].sel(statistic="mean"), exact.mean(axis=0),
                               atol=1e-6)
