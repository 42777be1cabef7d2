"""The components' assertions (``PhysicsBuilder.assertion``, Modelica's ``assert``) checked
at the points a run computed: simulate() and the Stepper raise a SimulationError at the
first point where one fails, a sweep reports the run as failed with the same message
(``numerics.first_failed_assertion``, which the pythonfmu FMU's slave shares). They are
checked at those points only, not located between them (they add no event)."""
from __future__ import annotations

import numpy as np

from ..errors import SimulationError
from ..numerics import first_failed_assertion


def held(model, T, X, Z, U, P) -> np.ndarray | None:
    """The assertions of ``model`` at the points (columns of T, X, Z, U, P; P may be one
    column for all): one row each, > 0.5 where it holds; None for a model without any."""
    if not model.assertions.numel():
        return None
    if "assertions" not in model._cache:        # built once: the Stepper checks every step
        model._cache["assertions"] = model.function("assertions", [model.assertions])
    f, n = model._cache["assertions"], np.size(T)
    return np.array((f if n == 1 else f.map(n))(np.reshape(T, (1, -1)), X, Z, U, P),
                    dtype=float)


def first_failure(model, T, X, Z, U, P) -> tuple[int, str] | None:
    """(column, message) of the first point where an assertion of ``model`` fails; None
    where all hold."""
    H = held(model, T, X, Z, U, P)
    return None if H is None else first_failed_assertion(H, T, model.assertion_texts)


def check(model, T, X, Z, U, P) -> None:
    """A SimulationError at the first point where an assertion fails."""
    failure = first_failure(model, T, X, Z, U, P)
    if failure is not None:
        raise SimulationError(failure[1])
