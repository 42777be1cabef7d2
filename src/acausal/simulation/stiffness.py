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


def spectral_radius(f, x0: np.ndarray, t0: float, fx0: np.ndarray) -> float:
    """An estimate of ρ = max |λ(∂f/∂x)| at (x0, t0), ``f(x, t)`` the right-hand side and
    ``fx0`` its value there: the growth rate of ‖J^k v‖ over k power iterations (which also
    converges for a dominant complex pair, whose iterates rotate)."""
    n = x0.size
    v = np.cos(np.arange(1, n + 1) * 1.618)              # deterministic, not aligned with axes
    v /= np.linalg.norm(v)
    eps = 1e-7 * (1.0 + np.linalg.norm(x0))
    log_growth, counted = 0.0, 0
    for k in range(ITERATIONS):
        w = (np.asarray(f(x0 + eps * v, t0), dtype=float).ravel() - fx0) / eps
        norm = np.linalg.norm(w)
        if not np.isfinite(norm) or norm == 0.0:
            return 0.0 if norm == 0.0 else np.inf
        if k >= ITERATIONS // 3:                          # past the transient
            log_growth += np.log(norm)
            counted += 1
        v = w / norm
    return float(np.exp(log_growth / counted))


def is_stiff(rho: float, t0: float, t1: float) -> bool:
    """Whether an ODE with spectral radius ``rho`` [1/s] is stiff over [t0, t1]."""
    return rho * (t1 - t0) > STIFF


def adams_step_budget(rho: float, interval: float) -> int:
    """The steps Adams may take between two output times before the run is judged too slow
    for it (then BDF takes over): a generous multiple of what resolving the fastest mode
    needs."""
    return int(max(2000, min(1e7, 200 * rho * interval)))
