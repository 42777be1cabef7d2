"""Operating points: a consistent (t, x, z, p, u) of a compiled model, by name.

Every analysis works at such points. Inputs and parameters are given by dotted name (as to
``simulate``); states by the dotted name of any variable (as ``x0``, held exactly; closed loops
are assembled around them). Where closed loops have rows that are redundant at the point, the
model's loop-row switches (``loop_switches``) are set as ``simulate`` sets them.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import AnalysisError, did_you_mean
from ..simulation.initialization import initial_state


@dataclass
class OperatingPoint:
    """A point of ``model``: time t [s], states x, algebraic variables z, parameters p and
    inputs u, as vectors in the model's order (``x_names``, ``z_names``, ``param_names``,
    ``input_names``). ``point["name"]`` is any recorded variable there."""
    model: object
    t: float
    x: np.ndarray
    z: np.ndarray
    p: np.ndarray
    u: np.ndarray

    def __getitem__(self, name: str) -> float:
        f = self.model.function("value", [self.model.expression(name)])
        return float(f(self.t, self.x, self.z, self.u, self.p))

    @property
    def state(self) -> dict[str, float]:
        """States by name."""
        return dict(zip(self.model.x_names, map(float, self.x)))


def index_of(names: list[str], wanted, what: str, model_name: str) -> list[int]:
    """Positions of ``wanted`` in ``names``; an AnalysisError names an unknown one."""
    out = []
    for w in wanted:
        if w not in names:
            raise AnalysisError(f"model '{model_name}' has no {what} '{w}'{did_you_mean(w, names)}"
                                f" (its {what}s: {', '.join(names[:10]) or 'none'})")
        out.append(names.index(w))
    return out


def input_vector(model, values: dict | None) -> np.ndarray:
    """Input values [start values, with ``values`` by name]."""
    u = model.input_start
    for k, v in zip(index_of(model.input_names, list(values or {}), "input", model.name),
                    (values or {}).values()):
        u[k] = float(v)
    return u


def set_loop_switches(model, t, x, z, u, p) -> np.ndarray:
    """p with the switches of the loop rows redundant at (t, x, z, u) set to 0."""
    if model.has_loops:
        active, _ = model.mobility_at(t, x, z, u, p)
        p = p.copy()
        p[model.loop_switches] = active
    return p


def operating_point(model, x=None, *, u: dict | None = None, params: dict | None = None,
                    t: float = 0.0, guess: dict | None = None) -> OperatingPoint:
    """The point of ``model`` at time t [s] with inputs ``u`` and parameters ``params`` (by
    name; defaults otherwise) where the variables named in ``x`` have the given values
    (closed loops assembled, ``guess`` as for simulate). ``x`` may also be an
    OperatingPoint (returned as is; then u, params, t must not be given)."""
    if isinstance(x, OperatingPoint):
        if u is not None or params is not None or guess is not None:
            raise AnalysisError("give either an OperatingPoint or u/params/guess, not both")
        return x
    p = model.param_vector(params)
    uv = input_vector(model, u)
    xs, zs = initial_state(model, dict(x or {}), p, uv, float(t), guess)
    p = set_loop_switches(model, t, xs, zs, uv, p)
    return OperatingPoint(model, float(t), np.asarray(xs, float), np.asarray(zs, float), p, uv)
