"""The scalar variables an FMU of a compiled model exposes, in value-reference order.

One list serves every backend (native FMI 2.0 / 3.0 and pythonfmu), so that a model's FMUs
agree on names, causalities, units and start values:

- parameters (causality ``parameter``, variability ``tunable``, start = default);
- the switches of closed-loop rows, ``loops.active_i`` (``calculatedParameter``, ``fixed``,
  initial ``calculated``): the FMU sets them in initialization as simulate() does, at the
  assembled configuration (rows that add nothing to the rank of Φ_q there are off);
- inputs (``input``, ``continuous``, start = the Input's start);
- outputs (``output``, ``continuous``);
- continuous states (``local``, ``continuous``, initial ``exact``: settable start values);
- their derivatives ``der(<state>)`` (``local``, ``continuous``, initial ``calculated``);
- the discrete modes of a model with state events (``local``, ``discrete``, initial
  ``calculated``: the event iteration at the end of initialization sets them from their
  declared start values and the start of the states, as simulate() does);
- the event indicators (``local``, ``continuous``, initial ``calculated``), by their names
  (``<component>.<indicator>``); FMI 3.0 lists them as its EventIndicators;
- every other recorded variable (``local``, ``continuous``, initial ``calculated``): port
  positions, flows, sensor signals by their dotted names.
"""
from __future__ import annotations

from dataclasses import dataclass

from ..compiler import CompiledModel


@dataclass(frozen=True)
class FmuVariable:
    name: str
    value_reference: int
    kind: str            # parameter / switch / input / output / state / derivative / mode /
                         # indicator / recorded
    index: int           # position in p (parameters, switches, modes), u, y, x, ẋ, the
                         # indicators, or recorded_names
    causality: str       # parameter / calculatedParameter / input / output / local
    variability: str     # tunable / fixed / continuous
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

    switches, modes = set(compiled.loop_switches), set(compiled.mode_params)
    for i, v in enumerate(compiled.params):
        if i in modes:
            continue
        if i in switches:
            add(v.name, "switch", i, "calculatedParameter", "fixed", "calculated", None, v.unit,
                v.description)
        else:
            add(v.name, "parameter", i, "parameter", "tunable", "exact", float(v.start), v.unit,
                v.description)
    for i, v in enumerate(compiled.inputs):
        add(v.name, "input", i, "input", "continuous", None, float(v.start), v.unit,
            v.description)
    for i, v in enumerate(compiled.outputs):
        add(v.name, "output", i, "output", "continuous", "calculated", None, v.unit,
            v.description)
    x_start = compiled.start(compiled.param_vector())
    x_start = [float(v) for v in x_start.full().ravel()[:len(compiled.x_names)]]
    state_ref = {}
    for i, v in enumerate(compiled.states):
        add(v.name, "state", i, "local", "continuous", "exact", x_start[i],
            v.unit or units.get(v.name, ""), v.description or f"state {v.name}")
        state_ref[i] = out[-1].value_reference
    for i, name in enumerate(compiled.x_names):
        unit = units.get(name, "")
        add(f"der({name})", "derivative", i, "local", "continuous", "calculated", None,
            f"{unit}/s" if unit else "", f"time derivative of {name}", state_ref[i])
    for i in compiled.mode_params:
        v = compiled.params[i]
        add(v.name, "mode", i, "local", "discrete", "calculated", None, v.unit,
            v.description or f"mode of {v.component}")
    for i, v in enumerate(compiled.state_events.indicators):
        add(v.name, "indicator", i, "local", "continuous", "calculated", None,
            v.unit or units.get(v.name), v.description or f"event indicator of {v.component}")
    taken = {v.name for v in out}
    for i, name in enumerate(compiled.recorded_names):
        if name not in taken:
            add(name, "recorded", i, "local", "continuous", "calculated", None, units.get(name),
                "")
    return out
