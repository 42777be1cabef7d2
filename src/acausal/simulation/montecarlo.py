"""Monte-Carlo studies on ``compiled.sweep`` (also ``acausal.montecarlo``): parameters
(start values, inputs) drawn from distributions, and statistics of the results over the
runs.

    runs = montecarlo.samples({"spring.c": montecarlo.uniform(0.8, 1.2),
                               "mass.m": montecarlo.normal(1.0, 0.05)}, n=500, seed=1)
    res = compiled.sweep(10.0, runs=runs)
    stats = montecarlo.statistics(res, ["mass.s"])     # mean, std, quantiles per time

A distribution is ``normal(mean, std)``, ``uniform(low, high)``, or any object with
scipy.stats' ``rvs(size=, random_state=)`` (a frozen distribution: ``scipy.stats.lognorm(
0.1, scale=2.0)``); a number holds for every run. A drawn value a parameter refuses (a
negative mass from a wide normal) makes that run fail, reported in the result's
``failed``, and the statistics leave it out.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ParameterError


@dataclass(frozen=True)
class Normal:
    """The normal distribution of mean ``mean`` and standard deviation ``std`` (> 0)."""
    mean: float
    std: float

    def draw(self, rng: np.random.Generator, n: int) -> np.ndarray:
        return rng.normal(self.mean, self.std, n)


@dataclass(frozen=True)
class Uniform:
    """The uniform distribution on [low, high)."""
    low: float
    high: float

    def draw(self, rng: np.random.Generator, n: int) -> np.ndarray:
        return rng.uniform(self.low, self.high, n)


def normal(mean: float, std: float) -> Normal:
    """A normal distribution (std > 0)."""
    if not (np.isfinite(mean) and np.isfinite(std) and std > 0):
        raise ParameterError(f"normal(mean, std) needs finite values and std > 0, got "
                             f"({mean!r}, {std!r})")
    return Normal(float(mean), float(std))


def uniform(low: float, high: float) -> Uniform:
    """A uniform distribution on [low, high) (low < high)."""
    if not (np.isfinite(low) and np.isfinite(high) and low < high):
        raise ParameterError(f"uniform(low, high) needs finite values and low < high, got "
                             f"({low!r}, {high!r})")
    return Uniform(float(low), float(high))


def samples(distributions: dict, n: int, seed: int | None = None):
    """A pandas DataFrame of ``n`` runs (for ``sweep(runs=...)``): a column per name of
    ``distributions`` (name → distribution or number, see the module), drawn in the
    order given from one generator seeded with ``seed`` (the same seed, the same runs)."""
    import pandas as pd
    if int(n) != n or n < 1:
        raise ParameterError(f"samples: n must be a whole number of runs >= 1, got {n!r}")
    rng = np.random.default_rng(seed)
    columns = {}
    for name, dist in distributions.items():
        if hasattr(dist, "draw"):
            values = dist.draw(rng, int(n))
        elif hasattr(dist, "rvs"):
            values = dist.rvs(size=int(n), random_state=rng)
        elif isinstance(dist, (int, float, np.number)) and np.isfinite(dist):
            values = np.full(int(n), float(dist))
        else:
            raise ParameterError(f"samples: '{name}' must be a distribution (normal, uniform, "
                                 f"a scipy.stats frozen distribution) or a number, got "
                                 f"{dist!r}")
        columns[name] = np.asarray(values, dtype=float)
    return pd.DataFrame(columns)


def statistics(result, names: list[str] | None = None,
               quantiles: tuple[float, ...] = (0.05, 0.5, 0.95)):
    """Statistics over the runs of a sweep's ``result`` (a SweepResult or its dataset),
    per time: an ``xarray.Dataset`` with a variable per name (default: all recorded), dims
    statistic × time, statistic "mean", "std" (the sample standard deviation, ddof = 1),
    "min", "max" and "q<percent>" per quantile ("q5", "q50", "q95"); the failed runs left
    out (attribute ``runs``: how many runs count)."""
    import xarray as xr
    ds = getattr(result, "dataset", result)
    if not all(0.0 <= q <= 1.0 for q in quantiles):
        raise ParameterError(f"statistics: quantiles must be in [0, 1], got {quantiles!r}")
    names = list(names) if names is not None else list(ds.data_vars)
    missing = [n for n in names if n not in ds.data_vars]
    if missing:
        raise ParameterError(f"statistics: the sweep recorded no {missing}; it recorded "
                             f"{list(ds.data_vars)}")
    good = ~ds["failed"].values if "failed" in ds.coords else np.ones(ds.sizes["run"], bool)
    labels = ["mean", "std", "min", "max"] + [f"q{100 * q:g}" for q in quantiles]
    data = {}
    for name in names:
        v = ds[name].values[good]
        rows = [v.mean(axis=0), v.std(axis=0, ddof=1) if len(v) > 1 else np.full(
            v.shape[1], np.nan), v.min(axis=0), v.max(axis=0)]
        rows += list(np.quantile(v, quantiles, axis=0))
        data[name] = (("statistic", "time"), np.vstack(rows))
    out = xr.Dataset(data, coords={"statistic": labels, "time": ds["time"].values})
    out.attrs["runs"] = int(good.sum())
    return out


__all__ = ["normal", "uniform", "samples", "statistics", "Normal", "Uniform"]
