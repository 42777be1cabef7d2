"""What the comparisons of MSL examples with their published reference results share: the
model wired from port pairs, the simulation on the reference's time grid, our values at the
reference's times."""
from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal


def connect_all(model, pairs) -> None:
    for a, b in pairs:
        model.connect(a, b)


def simulate_like_reference(build, example: str, reference_result, *,
                            index_reduction: bool = False, **tol):
    """(result, reference) of the MSL example ``example`` (its full Modelica name): the model
    ``build()`` gives (model, stop time [s], start values), compiled (with
    ``index_reduction``), simulated on the reference's time grid with the solver options
    ``tol``."""
    ref = reference_result("MAP-LIB_ReferenceResults", example)
    model, stop_time, start = build()
    res = acausal.compile(model, index_reduction=index_reduction).simulate(
        stop_time, t=ref["time"], x0=start, **tol)
    assert ref["time"][-1] == pytest.approx(stop_time)
    return res, ref


def at_reference_times(res, t: np.ndarray, name: str) -> np.ndarray:
    """``name`` of ``res`` at the times t (simulated on that grid, events added): the value
    after an event, as the reference keeps it."""
    at = np.searchsorted(res.t, t, side="right") - 1
    assert np.allclose(res.t[at], t, rtol=0, atol=1e-12)
    return res[name][at]


def generation_of_fmus_motion(t: np.ndarray) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """MSL's GenerationOfFMUs (Rotational and Translational alike: 10·sin(4πt) on bodies of
    1.1 and 2.2, at rest at 0), part → (position, speed) at the times t: "direct", the
    direct body that carries the inverse one, (1.1 + 2.2)·a = 10·sin(4πt) in closed form;
    "2a", "2b" the bodies joined by c = 1e4, d = 100 and "3a", "3b" by c = 1e4 alone, a
    hand-written model integrated by scipy (DOP853, rtol 1e-12)."""
    w = 4 * np.pi
    k = 10 / (3.3 * w)
    out = {"direct": (k * (t - np.sin(w * t) / w), k * (1 - np.cos(w * t)))}
    for part, d in (("2", 100.0), ("3", 0.0)):
        def rhs(tk, y, d=d):
            f = 1e4 * (y[1] - y[0]) + d * (y[3] - y[2])
            return [y[2], y[3], (10 * np.sin(w * tk) + f) / 1.1, -f / 2.2]
        y = solve_ivp(rhs, (0.0, t[-1]), [0.0] * 4, t_eval=t, method="DOP853", rtol=1e-12,
                      atol=1e-14).y
        out[f"{part}a"], out[f"{part}b"] = (y[0], y[2]), (y[1], y[3])
    return out
