"""Timing and reporting helpers shared by the benchmark scripts."""
from __future__ import annotations

import gc
import time

import numpy as np


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


def interleaved(contenders: dict, repeat: int) -> dict:
    """{name: (median, min, max) wall time [s]} of the callables ``contenders``, run in turn
    ``repeat`` times (one of each per round, so that the load of a shared machine falls on
    all alike)."""
    times = {name: [] for name in contenders}
    for _ in range(repeat):
        for name, fn in contenders.items():
            gc.collect()
            t0 = time.perf_counter()
            fn()
            times[name].append(time.perf_counter() - t0)
    return {name: (float(np.median(v)), min(v), max(v)) for name, v in times.items()}
