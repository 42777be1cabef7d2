"""Timing and reporting helpers shared by the benchmark scripts.

Import this module before numpy, scipy or casadi: it pins the BLAS / OpenMP thread pools to
one thread (unless the environment sets them), so that contenders do not differ by how many
threads a library happens to start on a shared machine.
"""
from __future__ import annotations

import os
import sys

THREAD_VARIABLES = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS",
                    "BLIS_NUM_THREADS", "VECLIB_MAXIMUM_THREADS", "NUMEXPR_NUM_THREADS")
for _v in THREAD_VARIABLES:
    os.environ.setdefault(_v, "1")
if "numpy" in sys.modules:
    print("timing.py: numpy was imported before the thread pools were pinned; import timing "
          "first", file=sys.stderr)

import gc  # noqa: E402
import time  # noqa: E402
from collections.abc import Callable  # noqa: E402

import numpy as np  # noqa: E402


def best_of(fn, repeat: int, budget: float = float("inf")):
    """(best wall time [s], result) of ``repeat`` runs of fn(); no repeat once a run takes
    more than ``budget`` seconds (a long run is timed well enough once)."""
    out = None
    for _ in range(repeat):
        gc.collect()
        t0 = time.perf_counter()
        r = fn()
        dt = time.perf_counter() - t0
        if out is None or dt < out[0]:
            out = (dt, r)
        if dt > budget:
            break
    return out


def fit_exponent(ns, ts) -> float:
    """Slope k of log t vs log N (least squares): t ~ N^k."""
    pts = [(a, b) for a, b in zip(ns, ts) if b > 0 and np.isfinite(b)]
    if len(pts) < 2:
        return float("nan")
    a, b = zip(*pts)
    return float(np.polyfit(np.log(a), np.log(b), 1)[0])


def print_table(head: list[str], rows: list, fmts) -> None:
    """Rows under a header, one format per column (or one for all but the first, an int N);
    NaN prints as '-'."""
    for row in rows:
        cols = fmts if isinstance(fmts, list) else ["{:>10d}"] + [fmts] * (len(row) - 1)
        break
    print(" | ".join(f"{h:>10s}" for h in head))
    for row in rows:
        cells = [f"{'-':>10s}" if isinstance(v, float) and np.isnan(v) else f.format(v)
                 for v, f in zip(row, cols)]
        print(" | ".join(cells))


def interleaved(contenders: dict[str, Callable[[], dict]], repeat: int) -> dict[str, list[dict]]:
    """Run each contender ``repeat`` times, in rounds (A, B, C, A, B, C, ...: a change of the
    machine's load hits all of them alike). A contender returns a dict of the phases it
    timed (name -> seconds) and anything else it wants kept (the last run's is kept);
    returns contender -> one dict per run."""
    runs: dict[str, list[dict]] = {name: [] for name in contenders}
    for _ in range(repeat):
        for name, fn in contenders.items():
            gc.collect()
            runs[name].append(fn())
    return runs


def timed(fn: Callable[[], object]) -> Callable[[], dict]:
    """A contender for ``interleaved`` that times one call of ``fn`` (phase 'run')."""
    def run():
        t0 = time.perf_counter()
        fn()
        return {"run": time.perf_counter() - t0}
    return run


def stats(runs: list[dict], phase: str) -> tuple[float, float, float]:
    """(median, min, max) of ``phase`` [s] over the runs."""
    v = np.array([r[phase] for r in runs], dtype=float)
    return float(np.median(v)), float(v.min()), float(v.max())


def median(runs: list[dict], phase: str) -> float:
    """The median of ``phase`` [s] over the runs."""
    return stats(runs, phase)[0]


def spread(runs: list[dict], phase: str) -> str:
    """'median (min–max)' of ``phase``, in milliseconds."""
    m, lo, hi = stats(runs, phase)
    return f"{1e3 * m:.1f} ({1e3 * lo:.1f}–{1e3 * hi:.1f})"


class Phases(dict):
    """Wall-clock times of consecutive phases of one run: ``ph = Phases()`` starts the
    clock, ``ph.lap("compile")`` records the time since the last lap under that name."""

    def __init__(self):
        super().__init__()
        self._t = time.perf_counter()

    def lap(self, name: str) -> float:
        now = time.perf_counter()
        self[name] = self.get(name, 0.0) + now - self._t
        self._t = now
        return self[name]


def maxrss_mb() -> float:
    """The process's peak resident memory so far [MB] (Linux ru_maxrss is in kB)."""
    import resource
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
