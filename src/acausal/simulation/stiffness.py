"""Which integrator suits an ODE: its spectral radius against the time to be simulated.

An explicit (Adams, functional iteration) method must take steps shorter than about 1/ρ,
ρ = max |λ| over the eigenvalues of the Jacobian ∂f/∂x, however slow the motion that matters:
an undamped 1 MHz mode next to a 1 Hz one, or a 1e4/s decay, makes it crawl. An implicit BDF
method with Newton iterations steps over such modes. So an ODE is taken as stiff when
ρ·(t1 − t0) > STIFF, ρ estimated by power iteration on Jacobian-vector products (finite
differences of f: O(n) each, one thread, no matrix built), and judged once per model and
operating point (cached on the model).
"""
from __future__ import annotations

import numpy as np

STIFF = 1e4          # ρ·(t1 − t0) above which BDF is chosen
ITERATIONS = 30      # power iterations: ρ to within some 25 %, enough for the choice


def spectral_radius(f, x0: np.ndarray, t0: float, fx0: np.ndarray):
    """An estimate of ρ = max |λ(∂f/∂x)| at (x0, t0), ``f(x, t)`` the right-hand side and
    ``fx0`` its value there: the growth rate of ‖J^k v‖ over k power iterations (which also
    converges for a dominant complex pair, whose iterates rotate). Many points at once:
    x0 and fx0 with one column per point, f taking and giving such columns; then an array
    of ρ, one per column."""
    x0 = np.asarray(x0, dtype=float)
    X = x0.reshape(x0.shape[0], -1)
    FX = np.asarray(fx0, dtype=float).reshape(X.shape)
    n, m = X.shape
    v = np.tile(np.cos(np.arange(1, n + 1) * 1.618)[:, None], (1, m))   # deterministic,
    v /= np.linalg.norm(v, axis=0)                                       # not along axes
    eps = 1e-7 * (1.0 + np.linalg.norm(X, axis=0))
    log_growth, counted = np.zeros(m), 0
    rho = np.full(m, np.nan)                  # set early where J v vanishes or blows up
    for k in range(ITERATIONS):
        W = (np.asarray(f(X + eps * v, t0), dtype=float).reshape(n, m) - FX) / eps
        norm = np.linalg.norm(W, axis=0)
        stop = np.isnan(rho) & (~np.isfinite(norm) | (norm == 0.0))
        rho[stop] = np.where(norm[stop] == 0.0, 0.0, np.inf)
        norm = np.where(np.isnan(rho), norm, 1.0)
        if k >= ITERATIONS // 3:                          # past the transient
            log_growth += np.log(norm)
            counted += 1
        v = np.where(np.isnan(rho), W, v) / norm
    rho = np.where(np.isnan(rho), np.exp(log_growth / counted), rho)
    return float(rho[0]) if x0.ndim == 1 else rho


def is_stiff(rho: float, t0: float, t1: float) -> bool:
    """Whether an ODE with spectral radius ``rho`` [1/s] is stiff over [t0, t1]."""
    return rho * (t1 - t0) > STIFF


def adams_step_budget(rho: float, interval: float) -> int:
    """The steps Adams may take between two output times before the run is judged too slow
    for it (then BDF takes over): a generous multiple of what resolving the fastest mode
    needs."""
    return int(max(2000, min(1e7, 200 * rho * interval)))
