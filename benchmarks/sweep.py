"""Many runs of one model: 1000 quarter cars (``acausal.models.QuarterCar``) with sampled
suspension stiffness, damping and body mass, over the two-wave road of
examples/road_profile.py (at 10 m/s), 1 s on 101 output times.

Contenders, interleaved and repeated (median and spread of the wall times, everything the
user waits for counted: building the integrator, the runs, reading the states):
  loop     a Python loop of ``compiled.simulate()``, one run per parameter set;
  sweep    ``compiled.sweep(runs=...)`` on 2 threads (one mapped integrator);
  hand     the same ODE written by hand in CasADi: ``integrator(...).map(N, "thread", 2)``
           with the same method (Adams, functional iteration, as simulate() chooses for this
           non-stiff model) and tolerances;
  cluster  ``compiled.sweep(..., client=)`` on a 2-process ``LocalCluster`` (started once,
           its start-up printed apart), checked equal to the local sweep bit for bit.
Every contender's error against a tight reference (the hand-written ODE at rtol 1e-12) is
printed: they are compared at equal accuracy.

    python benchmarks/sweep.py [--runs 1000] [--repeat 3] [--no-cluster]

The machine's 2 cores are shared: only the ratios within one run mean something.
"""
from __future__ import annotations

import os

for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")               # BLAS single-threaded: the runs are parallel

import argparse          # noqa: E402
import gc                # noqa: E402
import time              # noqa: E402

import casadi as ca      # noqa: E402
import numpy as np       # noqa: E402

import acausal           # noqa: E402
from acausal import models, montecarlo     # noqa: E402

T_END, POINTS = 1.0, 101
RTOL, ATOL = 1e-6, 1e-8
THREADS = 2
STATES = ["wheel.s", "body.s", "wheel.v", "body.v"]


def road(t, sin=np.sin):
    """Road height [m] under the tyre at time t [s]: examples/road_profile.py's two waves
    (0.02 m at 0.9 /m, 0.006 m at 4.1 /m) at 10 m/s (numpy's sin: exact on CasADi symbols
    in simulate(); casadi's for the hand-written ODE)."""
    return 0.02 * sin(9.0 * t) + 0.006 * sin(41.0 * t + 0.4)


def parameter_sets(n: int):
    return montecarlo.samples({"suspension.c": montecarlo.uniform(10e3, 25e3),
                               "suspension.d": montecarlo.uniform(0.5e3, 2e3),
                               "body.m": montecarlo.uniform(200.0, 400.0)}, n=n, seed=0)


def hand_integrator(grid, rtol, atol, adams=True):
    """The quarter car's ODE by hand: x = (wheel.s, body.s, wheel.v, body.v), parameters
    (c_s, d_s, m_s) per run; tyre 160 kN/m, wheel 35 kg."""
    x, p, t = ca.SX.sym("x", 4), ca.SX.sym("p", 3), ca.SX.sym("t")
    zu, zs, vu, vs = ca.vertsplit(x)
    c, d, ms = ca.vertsplit(p)
    f = c * (zs - zu) + d * (vs - vu)
    ode = ca.vertcat(vu, vs, (f + models.quarter_car.TYRE_C * (road(t, ca.sin) - zu))
                     / models.quarter_car.WHEEL, -f / ms)
    opts = {"abstol": atol, "reltol": rtol, "max_num_steps": 100000}
    if adams:
        opts.update(linear_multistep_method="adams", nonlinear_solver_iteration="functional")
    return ca.integrator("hand", "cvodes", {"x": x, "p": p, "t": t, "ode": ode}, 0.0,
                         list(grid[1:]), opts)


def hand(grid, P, rtol=RTOL, atol=ATOL, adams=True):
    """(runs × 4 × times) of the hand-written integrator mapped on threads."""
    n = P.shape[1]
    F = hand_integrator(grid, rtol, atol, adams)
    xf = np.array(F.map(n, "thread", THREADS)(x0=np.zeros((4, n)), p=P)["xf"])
    X = np.concatenate([np.zeros((4, n, 1)), xf.reshape(4, n, grid.size - 1)], axis=2)
    return X.transpose(1, 0, 2)


def loop(compiled, grid, runs):
    out = []
    for row in runs.to_dict("records"):
        res = compiled.simulate(T_END, t=grid, params=row, inputs={"road": road}, rtol=RTOL,
                                atol=ATOL)
        out.append([res[n] for n in STATES])
    return np.array(out)


def swept(compiled, grid, runs, **kw):
    res = compiled.sweep(T_END, t=grid, runs=runs, inputs={"road": road}, rtol=RTOL,
                         atol=ATOL, threads=THREADS, variables=STATES, **kw)
    assert not res.failed, res.failed
    return np.stack([res[n] for n in STATES], axis=1)


def timed(fn):
    gc.collect()
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=1000)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--no-cluster", action="store_true")
    args = ap.parse_args()
    grid = np.linspace(0.0, T_END, POINTS)
    runs = parameter_sets(args.runs)
    P = runs[["suspension.c", "suspension.d", "body.m"]].to_numpy().T
    t0 = time.perf_counter()
    compiled = acausal.compile(models.QuarterCar())
    print(f"quarter car: {args.runs} runs, {T_END:g} s on {POINTS} times, rtol {RTOL:g}, "
          f"atol {ATOL:g}, {THREADS} threads; compile {time.perf_counter() - t0:.2f} s "
          f"(once, not counted)")
    swept(compiled, grid, runs.iloc[:4])           # imports (xarray) and caches warm
    client = cluster = None
    contenders = {"loop": lambda: loop(compiled, grid, runs),
                  "sweep": lambda: swept(compiled, grid, runs),
                  "hand": lambda: hand(grid, P)}
    if not args.no_cluster:
        from distributed import Client, LocalCluster
        t0 = time.perf_counter()
        cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                               dashboard_address=":0")
        client = Client(cluster)
        print(f"LocalCluster of 2 processes started in {time.perf_counter() - t0:.2f} s "
              f"(once, not counted)")
        contenders["cluster"] = lambda: swept(compiled, grid, runs, client=client)
    times = {name: [] for name in contenders}
    results = {}
    try:
        for _ in range(args.repeat):
            for name, fn in contenders.items():          # interleaved
                dt, results[name] = timed(fn)
                times[name].append(dt)
    finally:
        if client is not None:
            client.close()
            cluster.close()
    tight = hand(grid, P, rtol=1e-12, atol=1e-14, adams=False)
    print(f"\n{'contender':>10s} | {'median [s]':>10s} | {'min..max [s]':>15s} | "
          f"{'per run [ms]':>12s} | {'max error body.s [m]':>20s}")
    for name, ts in times.items():
        err = np.max(np.abs(results[name][:, 1] - tight[:, 1]))
        print(f"{name:>10s} | {np.median(ts):10.3f} | {min(ts):6.3f}..{max(ts):6.3f} | "
              f"{1e3 * np.median(ts) / args.runs:12.3f} | {err:20.2e}")
    med = {name: float(np.median(ts)) for name, ts in times.items()}
    print(f"\nloop / sweep  = {med['loop'] / med['sweep']:.1f}x   (sweep faster than a loop "
          f"of simulate())")
    print(f"sweep / hand  = {med['sweep'] / med['hand']:.2f}x  (sweep against a hand-written "
          f"integrator.map)")
    print(f"loop / hand   = {med['loop'] / med['hand']:.1f}x   (the most any mapped integrator "
          f"can gain over the loop here: the integration itself)")
    if "cluster" in med:
        same = np.array_equal(results["cluster"], results["sweep"])
        print(f"cluster / sweep = {med['cluster'] / med['sweep']:.2f}x; cluster results equal "
              f"the local ones bit for bit: {same}")


if __name__ == "__main__":
    main()
