"""Operating points: a consistent (t, x, z, p, u) of a compiled model, by name.

Every analysis works at such points. Inputs and parameters are given by dotted name (as to
``simulate``); states by the dotted name of any variable (as ``x0``, held exactly; closed loops
are assembled around them). Where closed loops have rows that are redundant at the point, the
model's loop-row switches (``loop_switches``) are set as ``simulate`` sets them.

A model with discrete modes (friction's stuck / sliding, ``StructureBuilder.mode``) is
analysed in one set of modes, the point's ``mode`` (name -> value): the ones given by name
(``mode={"friction.mode": 0}``) held, the others found by the event iteration at the point
from their start values, as ``simulate`` finds them at its start (a body at rest under a
load below breakaway: stuck). The algebraic variables are solved in those modes.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Mapping

import numpy as np

from ..errors import AnalysisError, SimulationError, did_you_mean
from ..simulation.events import ModeIteration
from ..simulation.initialization import initial_state
from ..simulation.problem import check_finite


@dataclass
class OperatingPoint:
    """A point of ``model``: time t [s], states x, algebraic variables z, parameters p and
    inputs u, as vectors in the model's order (``x_names``, ``z_names``, ``param_names``,
    ``input_names``). ``point["name"]`` is any recorded variable there. ``mode``: the
    discrete modes it is in, by name (their values are also in p; empty without modes)."""
    model: object
    t: float
    x: np.ndarray
    z: np.ndarray
    p: np.ndarray
    u: np.ndarray
    mode: dict = field(default_factory=dict)

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
    check_finite("u", values, AnalysisError)
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
                    t: float = 0.0, guess: dict | None = None,
                    mode: dict | None = None) -> OperatingPoint:
    """The point of ``model`` at time t [s] with inputs ``u`` and parameters ``params`` (by
    name; defaults otherwise) where the variables named in ``x`` have the given values
    (closed loops assembled, ``guess`` as for simulate), in the discrete modes ``mode``
    (name -> value; the others as the event iteration finds them there, see the module).
    ``x`` may also be an OperatingPoint (returned as is; then u, params, t, mode must not be
    given)."""
    if isinstance(x, OperatingPoint):
        if u is not None or params is not None or guess is not None or mode is not None:
            raise AnalysisError("give either an OperatingPoint or u/params/guess/mode, not "
                                "both")
        return x
    if x is not None and not isinstance(x, Mapping):
        raise AnalysisError(f"x must be values by variable name (a dict) or an "
                            f"OperatingPoint, got {x!r}")
    check_finite("x", x, AnalysisError)
    if not isinstance(t, (int, float, np.floating)) or not math.isfinite(t):
        raise AnalysisError(f"t must be a finite time [s], got {t!r}")
    p = model.param_vector(params)
    uv = input_vector(model, u)
    xs, zs = initial_state(model, dict(x or {}), p, uv, float(t), guess)
    p = set_loop_switches(model, t, xs, zs, uv, p)
    xs, zs, p = in_modes(model, float(t), np.asarray(xs, float), np.asarray(zs, float), uv, p,
                         mode)
    return OperatingPoint(model, float(t), xs, zs, p, uv, modes_of(model, p))


def modes_of(model, p) -> dict:
    """The discrete modes in p, by name (int values)."""
    return {v.name: int(round(p[i])) for v, i in zip(model.modes, model.mode_params)}


def in_modes(model, t, x, z, u, p, mode: dict | None):
    """(x, z, p) at (t, x) in the modes ``mode`` (name -> value, held) and, for the others,
    the event iteration's from their values in p; z solved in them."""
    given = dict(mode or {})
    names = [v.name for v in model.modes]
    if given and not names:
        raise AnalysisError(f"model '{model.name}' has no discrete modes; remove mode=")
    keep = index_of(names, list(given), "mode", model.name)
    if not names:
        return x, z, p
    p = p.copy()
    for k, (name, value) in zip(keep, given.items()):
        allowed = model.state_events.mode_values.get(name)
        if allowed is not None and value not in allowed:
            raise AnalysisError(f"mode '{name}' takes the values {allowed}, not {value!r}")
        p[model.mode_params[k]] = value
    run = ModeIteration(model, p, lambda _: u)
    try:
        x, z, d = run.iterate(t, x, z, p[model.mode_params], {}, keep)
    except SimulationError as e:
        raise AnalysisError(f"the modes of '{model.name}' at this point: {e}") from None
    p[model.mode_params] = d
    return x, z, p
