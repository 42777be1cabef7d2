"""Many runs of one model: a parameter sweep and a Monte-Carlo study of a quarter car.

The quarter car (``acausal.models.QuarterCar``: body 250 kg and wheel 35 kg on a
suspension spring-damper and a tyre spring) drives over the two-wave road of
examples/road_profile.py at 10 m/s for 2 s.

1) Sweep: suspension stiffness × damping on a grid (5 × 8 runs) in one call,
   ``compiled.sweep(params={...: [...], ...: [...]})``: one CasADi integrator mapped over the
   runs on threads. The RMS body acceleration (ride comfort) and the largest suspension
   travel of every run, from the xarray Dataset the sweep returns; the most comfortable
   setting that stays within 40 mm of travel.
2) Monte-Carlo: body mass (payload) and damper (wear) uncertain,
   ``montecarlo.samples({...: uniform(...), ...: normal(...)}, n=300, seed=1)``, run by the same
   sweep; the mean, standard deviation and 5 / 95 % quantiles of the body acceleration per
   time (``montecarlo.statistics``).

The same sweep runs on a dask cluster with ``client=Client("tcp://scheduler:8786")`` (or
``cluster="local"`` for processes on this machine); see ``acausal.simulation.sweep``.

Run ``python examples/sweep_montecarlo.py``: prints both studies and saves
``sweep_montecarlo.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os
import time

import numpy as np

import acausal
from acausal import models, montecarlo

T_END = 2.0
TRAVEL = 0.04            # suspension travel available [m]


def road(t):
    """Road height [m] at time t [s]: 0.02 m at 0.9 /m and 0.006 m at 4.1 /m, at 10 m/s."""
    return 0.02 * np.sin(9.0 * t) + 0.006 * np.sin(41.0 * t + 0.4)


def main():
    car = acausal.compile(models.QuarterCar())
    t = np.linspace(0.0, T_END, 401)

    # 1) a grid of suspension settings
    stiffness = [10e3, 14e3, 18e3, 22e3, 26e3]                 # N/m
    damping = list(np.linspace(0.4e3, 3.2e3, 8))               # N.s/m
    start = time.perf_counter()
    grid = car.sweep(T_END, t=t, params={"suspension.c": stiffness, "suspension.d": damping},
                     inputs={"road": road})
    elapsed = time.perf_counter() - start
    ds = grid.dataset
    rms = np.sqrt((ds["a_body"] ** 2).mean("time"))             # per run
    travel = np.abs(ds["travel"]).max("time")
    print(f"sweep: {len(grid)} runs in {elapsed:.2f} s ({grid.method}), "
          f"{len(grid.failed)} failed")
    within = np.flatnonzero(travel.values <= TRAVEL)           # room in the wheel arch
    best = within[np.argmin(rms.values[within])]
    print(f"  most comfortable with at most {1e3 * TRAVEL:.0f} mm of travel: "
          f"c = {float(ds['suspension.c'][best]):.0f} N/m, "
          f"d = {float(ds['suspension.d'][best]):.0f} N.s/m: RMS body acceleration "
          f"{float(rms[best]):.3f} m/s², largest travel {1e3 * float(travel[best]):.1f} mm")

    # 2) uncertain payload and damper wear
    runs = montecarlo.samples({"body.m": montecarlo.uniform(220.0, 400.0),
                               "suspension.d": montecarlo.normal(1.0e3, 0.1e3)}, n=300, seed=1)
    start = time.perf_counter()
    mc = car.sweep(T_END, t=t, runs=runs, inputs={"road": road}, variables=["a_body", "travel"])
    elapsed = time.perf_counter() - start
    summary = montecarlo.statistics(mc, ["a_body"])
    stats = summary["a_body"]
    peak = np.abs(mc["a_body"]).max(axis=1)
    print(f"Monte-Carlo: {len(mc)} runs in {elapsed:.2f} s, {len(mc.failed)} failed; peak "
          f"body acceleration {peak.mean():.2f} ± {peak.std(ddof=1):.2f} m/s² "
          f"(5 % .. 95 %: {np.quantile(peak, 0.05):.2f} .. {np.quantile(peak, 0.95):.2f})")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    table = rms.values.reshape(len(stiffness), len(damping))
    for c, row in zip(stiffness, table):
        ax[0].plot(damping, row, "o-", ms=3, label=f"c = {c / 1e3:.0f} kN/m")
    ax[0].set_xlabel("suspension damping d [N.s/m]")
    ax[0].set_ylabel("RMS body acceleration [m/s²]")
    ax[0].set_title("parameter sweep")
    ax[0].legend(fontsize=7)
    ax[1].fill_between(t, stats.sel(statistic="q5"), stats.sel(statistic="q95"), alpha=0.3,
                       label="5 % .. 95 %")
    mean, std = stats.sel(statistic="mean"), stats.sel(statistic="std")
    ax[1].plot(t, mean, "k", lw=1, label="mean")
    ax[1].plot(t, mean + std, "k--", lw=0.6, label="mean ± std")
    ax[1].plot(t, mean - std, "k--", lw=0.6)
    ax[1].set_xlabel("time [s]")
    ax[1].set_ylabel("body acceleration [m/s²]")
    ax[1].set_title(f"Monte-Carlo, {summary.attrs['runs']} runs")
    ax[1].legend(fontsize=7)
    for a in ax:
        a.grid(True)
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "sweep_montecarlo.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"saved {out}")


if __name__ == "__main__":
    main()
