"""The components' assertions (``PhysicsBuilder.assertion``, Modelica's ``assert``) checked
at the points a run computed: simulate() and the Stepper raise a SimulationError at the
first point where one fails, a sweep reports the run as failed with the same message. They
are checked at those points only, not located between them (they add no event)."""
from __future__ import annotations

import numpy as np

from ..errors import SimulationError


def failures(model, T, X, Z, U, P) -> np.ndarray:
    """At each point (a column of T, X, Z, U, P; P may be one column for all): the index of
    the first of ``model.assertion_texts`` that fails there, or -1."""
    n = np.size(T)
    if not model.assertions.numel():
        return np.full(n, -1)
    held = np.array(model.function("assertions", [model.assertions]).map(n)(
        np.reshape(T, (1, -1)), X, Z, U, P), dtype=float).reshape(-1, n) > 0.5
    return np.where(held.all(axis=0), -1, np.argmin(held, axis=0))


def message(model, index: int, t: float) -> str:
    """What failed: the component, its message and the time."""
    component, text = model.assertion_texts[index]
    return f"'{component}': {text} (assertion failed at t = {t:.6g} s)"


def check(model, T, X, Z, U, P) -> None:
    """A SimulationError at the first point where an assertion fails."""
    failed = failures(model, T, X, Z, U, P)
    k = np.flatnonzero(failed >= 0)
    if k.size:
        raise SimulationError(message(model, int(failed[k[0]]), float(np.ravel(T)[k[0]])))
