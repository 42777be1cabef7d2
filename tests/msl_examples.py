"""What the comparisons of MSL examples with their published reference results share: the
model wired from port pairs, the simulation on the reference's time grid, our values at the
reference's times."""
from __future__ import annotations

import numpy as np
import pytest

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
