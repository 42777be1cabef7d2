"""The scalar variables an FMU of a compiled model exposes, in value-reference order.

One list serves every backend (native FMI 2.0 / 3.0 and pythonfmu), so that a model's FMUs
agree on names, causalities, units and start values:

- parameters (causality ``parameter``, variability ``tunable``, start = default; the
  switches ``loops.active[i]`` of closed-loop rows start as simulate() sets them: redundant
  rows at the configuration assembled from the default start values are off);
- inputs (``input``, ``continuous``, start = the Input's start);
- outputs (``output``, ``continuous``);
- continuous states (``local``, ``continuous``, initial ``exact``: settable start values);
- their derivatives ``der(<state>)`` (``local``, ``continuous``, initial ``calculated``);
- every other recorded variable (``local``, ``continuous``, initial ``calculated``): port
  positions, flows, sensor signals by their dotted names.
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from ..compiler.compiled import CompiledModel
from ..core.errors import AcausalError
from ..simulation.initialization import initial_state


@dataclass(frozen=True)
class FmuVariable:
    name: str
    value_reference: int
    kind: str            # parameter / input / output / state / derivative / recorded
    index: int           # position in p, u, y, x, ẋ, or recorded_names
    causality: str       # parameter / input / output / local
    variability: str     # tunable / continuous
    initial: str | None  # exact / calculated / None (inputs, as FMI requires)
    start: float | None
    unit: str
    description: str
    derivative_of: int | None = None   # value reference of the state (derivatives only)


def fmu_variables(compiled: CompiledModel) -> list[FmuVariable]:
    """The FMU's variables of ``compiled``, value references 1, 2, ... in the order above."""
    units = dict(zip(compiled.recorded_names, compiled.recorded_units))
    out: list[FmuVariable] = []

    def add(name, kind, index, causality, variability, initial, start, unit, desc, der=None):
        out.append(FmuVariable(name, len(out) + 1, kind, index, causality, variability,
                               initial, start, unit or "", desc or "", der))

    for i, ((name, _, unit, desc, _), start) in enumerate(zip(compiled.params,
                                                               parameter_starts(compiled))):
        add(name, "parameter", i, "parameter", "tunable", "exact", float(start), unit, desc)
    for i, (name, start, unit, desc) in enumerate(compiled.inputs):
        add(name, "input", i, "input", "continuous", None, float(start), unit, desc)
    for i, (name, unit, desc) in enumerate(compiled.outputs):
        add(name, "output", i, "output", "continuous", "calculated", None, unit, desc)
    x_start = compiled.start(compiled.param_vector())
    x_start = [float(v) for v in x_start.full().ravel()[:len(compiled.x_names)]]
    state_ref = {}
    for i, name in enumerate(compiled.x_names):
        add(name, "state", i, "local", "continuous", "exact", x_start[i], units.get(name, ""),
            f"state {name}")
        state_ref[i] = out[-1].value_reference
    for i, name in enumerate(compiled.x_names):
        unit = units.get(name, "")
        add(f"der({name})", "derivative", i, "local", "continuous", "calculated", None,
            f"{unit}/s" if unit else "", f"time derivative of {name}", state_ref[i])
    taken = {v.name for v in out}
    for i, name in enumerate(compiled.recorded_names):
        if name not in taken:
            add(name, "recorded", i, "local", "continuous", "calculated", None, units.get(name),
                "")
    return out


def parameter_starts(compiled: CompiledModel, tries: int = 4) -> np.ndarray:
    """Parameter defaults, with the loop-row switches set as simulate() sets them, judged at
    configurations assembled from randomly perturbed start values (a special configuration,
    e.g. every link of a parallelogram on one line, would show more redundancy than the
    motion has): the most rows found independent; all rows on if no assembly succeeds."""
    p = compiled.param_vector()
    if not compiled.loop_rows:
        return p
    u0 = np.array([i[1] for i in compiled.inputs], dtype=float)
    start = np.asarray(compiled.start(p), dtype=float).ravel()
    rng = np.random.default_rng(0)
    switches = [i for i, n in enumerate(compiled.param_names) if n.startswith("loops.active")]
    best = None
    for _ in range(tries):
        guess = {n: float(v) + rng.uniform(-0.5, 0.5) for n, v in zip(compiled.x_names, start)}
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                x, z = initial_state(compiled, {}, p, u0, 0.0, guess)
                active = np.asarray(compiled.mobility_at(x, z, p, 0.0)[0], dtype=float)
        except AcausalError:
            continue
        if best is None or active.sum() > best.sum():
            best = active
    if best is not None:
        p[switches] = best
    return p
