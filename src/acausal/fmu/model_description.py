"""modelDescription.xml (FMI 2.0 and 3.0) and buildDescription.xml of a native FMU.

Variables come from ``variables.fmu_variables`` (one list for every backend), plus, after
them, the co-simulation solver's tunable tolerances ``solver.rtol`` and ``solver.atol`` and,
in FMI 3.0, the independent variable ``time`` (value reference 0). Units are declared in
UnitDefinitions with their SI base-unit exponents (``N.m/rad`` -> kg·m²·s⁻²·rad⁻¹).
"""
from __future__ import annotations

import math
import re
import time
from xml.sax.saxutils import quoteattr

from .variables import FmuVariable

SOLVER_VARIABLES = (
    ("solver.rtol", 1e-6, "1",
     "relative tolerance of the co-simulation solver (Rosenbrock RODAS4); an importer's "
     "tolerance (fmi2SetupExperiment / fmi3EnterInitializationMode) replaces the default"),
    ("solver.atol", 1e-8, "",
     "absolute tolerance of the co-simulation solver (in the states' units); default "
     "rtol/100 when the importer gives a tolerance"),
)

# ---- units ------------------------------------------------------------------------------
BASE_UNITS = ("kg", "m", "s", "A", "K", "mol", "cd", "rad")
_SI = {  # name -> (exponents of kg, m, s, A, K, mol, cd, rad; factor)
    "kg": ((1, 0, 0, 0, 0, 0, 0, 0), 1.0), "m": ((0, 1, 0, 0, 0, 0, 0, 0), 1.0),
    "s": ((0, 0, 1, 0, 0, 0, 0, 0), 1.0), "A": ((0, 0, 0, 1, 0, 0, 0, 0), 1.0),
    "K": ((0, 0, 0, 0, 1, 0, 0, 0), 1.0), "mol": ((0, 0, 0, 0, 0, 1, 0, 0), 1.0),
    "cd": ((0, 0, 0, 0, 0, 0, 1, 0), 1.0), "rad": ((0, 0, 0, 0, 0, 0, 0, 1), 1.0),
    "g": ((1, 0, 0, 0, 0, 0, 0, 0), 1e-3), "N": ((1, 1, -2, 0, 0, 0, 0, 0), 1.0),
    "J": ((1, 2, -2, 0, 0, 0, 0, 0), 1.0), "W": ((1, 2, -3, 0, 0, 0, 0, 0), 1.0),
    "Pa": ((1, -1, -2, 0, 0, 0, 0, 0), 1.0), "Hz": ((0, 0, -1, 0, 0, 0, 0, 0), 1.0),
    "C": ((0, 0, 1, 1, 0, 0, 0, 0), 1.0), "V": ((1, 2, -3, -1, 0, 0, 0, 0), 1.0),
    "Ohm": ((1, 2, -3, -2, 0, 0, 0, 0), 1.0), "S": ((-1, -2, 3, 2, 0, 0, 0, 0), 1.0),
    "F": ((-1, -2, 4, 2, 0, 0, 0, 0), 1.0), "H": ((1, 2, -2, -2, 0, 0, 0, 0), 1.0),
    "Wb": ((1, 2, -2, -1, 0, 0, 0, 0), 1.0), "T": ((1, 0, -2, -1, 0, 0, 0, 0), 1.0),
    "deg": ((0, 0, 0, 0, 0, 0, 0, 1), math.pi / 180), "min": ((0, 0, 1, 0, 0, 0, 0, 0), 60.0),
    "h": ((0, 0, 1, 0, 0, 0, 0, 0), 3600.0), "rpm": ((0, 0, -1, 0, 0, 0, 0, 1), math.pi / 30),
    "1": ((0,) * 8, 1.0), "%": ((0,) * 8, 0.01),
}
_PREFIX = {"k": 1e3, "M": 1e6, "G": 1e9, "m": 1e-3, "u": 1e-6, "n": 1e-9, "c": 1e-2}


def _factor(tok: str):
    m = re.fullmatch(r"([A-Za-z%]+|1)(-?\d+)?", tok)
    if not m:
        return None
    name, exp = m.group(1), int(m.group(2) or 1)
    if name in _SI:
        e, f = _SI[name]
    elif len(name) > 1 and name[0] in _PREFIX and name[1:] in _SI and name[1:] not in ("1", "%"):
        e, f = _SI[name[1:]]
        f = f * _PREFIX[name[0]]
    else:
        return None
    return [x * exp for x in e], f ** exp


def parse_unit(unit: str):
    """(exponents of kg, m, s, A, K, mol, cd, rad; factor) of a Modelica unit string
    (``N.m/rad``, ``m/s2``, ``rad/s/s``), or None if it is not understood."""
    parts = unit.split("/")
    exps, factor = [0] * 8, 1.0
    for k, part in enumerate(parts):
        if not part:
            return None
        for tok in part.split("."):
            r = _factor(tok)
            if r is None:
                return None
            sign = 1 if k == 0 else -1
            exps = [a + sign * b for a, b in zip(exps, r[0])]
            factor = factor * (r[1] if sign > 0 else 1.0 / r[1])
    return exps, factor


def base_unit_attributes(unit: str) -> dict[str, str] | None:
    """The BaseUnit attributes of ``unit`` (SI exponents, factor), None if not understood."""
    parsed = parse_unit(unit)
    if parsed is None:
        return None
    exps, factor = parsed
    attrs = {n: str(e) for n, e in zip(BASE_UNITS, exps) if e}
    if factor != 1.0:
        attrs["factor"] = repr(factor)
    return attrs


def unit_definitions(units) -> str:
    out = []
    for u in sorted(set(units)):
        base = base_unit_attributes(u)
        if base is None:
            out.append(f"    <Unit name={quoteattr(u)}/>")
            continue
        attrs = "".join(f' {n}="{e}"' for n, e in base.items())
        out.append(f"    <Unit name={quoteattr(u)}><BaseUnit{attrs}/></Unit>")
    return "  <UnitDefinitions>\n" + "\n".join(out) + "\n  </UnitDefinitions>\n" if out else ""


# ---- names --------------------------------------------------------------------------------
_IDENT = r"(?:[A-Za-z_][A-Za-z0-9_]*(?:\[\d+(?:,\d+)*\])?)"
_STRUCTURED = re.compile(rf"{_IDENT}(?:\.{_IDENT})*|der\({_IDENT}(?:\.{_IDENT})*(?:,\d+)?\)")


def naming_convention(names) -> str:
    """'structured' if every name fits FMI's structured grammar, otherwise 'flat'."""
    return "structured" if all(_STRUCTURED.fullmatch(n) for n in names) else "flat"


def _num(v: float) -> str:
    return repr(float(v))


def _deps(deps, label) -> str:
    """The dependencies attribute of value references ``deps`` written as ``label(vr)``; none
    for None (FMI: depends on all knowns)."""
    return "" if deps is None else f' dependencies="{" ".join(label(r) for r in deps)}"'


def _a(name, value) -> str:
    return f" {name}={quoteattr(str(value))}" if value not in (None, "") else ""


def needs_step(info: dict) -> bool:
    """Whether the importer must call completedIntegratorStep: to keep closed loops closed;
    with state events, where the FMU keeps the indicators' signs at the accepted steps
    (a crossing that changes nothing updates them there; any other asks for an event); and
    to check the components' assertions."""
    return bool(info["loops"] or info["events"] or info["assertions"])


# ---- FMI 2.0 ------------------------------------------------------------------------------
def _attributes(v, info: dict, derivative) -> tuple[str, str]:
    """The XML attributes of a variable: (those of the variable itself, those of its real
    type: unit, start, derivative — the state's index in FMI 2, its value reference in FMI 3
    — and nominal)."""
    attrs = (f'{_a("name", v.name)} valueReference="{v.value_reference}"'
             f'{_a("description", v.description)} causality="{v.causality}"'
             f' variability="{v.variability}"{_a("initial", v.initial)}')
    real = _a("unit", v.unit)
    if v.start is not None:
        real += f' start="{_num(v.start)}"'
    if derivative is not None:
        real += f' derivative="{derivative}"'
    if v.kind == "state" and v.name in info.get("nominal", {}):
        real += f' nominal="{_num(info["nominal"][v.name])}"'
    return attrs, real


def fmi2_xml(info: dict) -> str:
    """info: model_name, identifier, guid, description, variables (FmuVariable list incl. the
    solver ones), me, cs, sources, deps (see export), loops, events (state events: the
    importer must call completedIntegratorStep), stop_time."""
    vs: list[FmuVariable] = info["variables"]
    index = {v.value_reference: k + 1 for k, v in enumerate(vs)}   # 1-based list position
    names = [v.name for v in vs]
    caps = ('canGetAndSetFMUstate="true" canSerializeFMUstate="true" '
            'providesDirectionalDerivative="true" canNotUseMemoryManagementFunctions="true"')
    src = "".join(f'      <File name="{f}"/>\n' for f in info["sources"])
    src = f"    <SourceFiles>\n{src}    </SourceFiles>\n"
    head = [f'<?xml version="1.0" encoding="UTF-8"?>\n<fmiModelDescription fmiVersion="2.0"'
            f'{_a("modelName", info["model_name"])}{_a("guid", info["guid"])}'
            f'{_a("description", info["description"])} generationTool="acausal (native)"'
            f' generationDateAndTime="{time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}"'
            f' variableNamingConvention="{naming_convention(names)}"'
            f' numberOfEventIndicators="{sum(v.kind == "indicator" for v in vs)}">\n']
    if info["me"]:
        head.append(f'  <ModelExchange modelIdentifier="{info["identifier"]}" {caps}'
                    f' completedIntegratorStepNotNeeded="{str(not needs_step(info)).lower()}">\n'
                    f'{src}  </ModelExchange>\n')
    if info["cs"]:
        head.append(f'  <CoSimulation modelIdentifier="{info["identifier"]}" {caps}'
                    f' canHandleVariableCommunicationStepSize="true" canInterpolateInputs="false"'
                    f' maxOutputDerivativeOrder="0">\n{src}  </CoSimulation>\n')
    head.append(unit_definitions(v.unit for v in vs if v.unit))
    head.append('  <LogCategories>\n    <Category name="logStatusError"/>\n'
                '    <Category name="logStatusWarning"/>\n    <Category name="logEvents"/>\n'
                '    <Category name="logAll"/>\n  </LogCategories>\n')
    head.append(f'  <DefaultExperiment startTime="0" stopTime="{_num(info["stop_time"])}"'
                f' tolerance="1e-06"/>\n')
    body = ["  <ModelVariables>\n"]
    for v in vs:
        attrs, real = _attributes(v, info, index.get(v.derivative_of))
        body.append(f"    <ScalarVariable{attrs}>\n      <Real{real}/>\n    </ScalarVariable>\n")
    body.append("  </ModelVariables>\n  <ModelStructure>\n")

    def unknowns(tag, items):
        if not items:
            return
        body.append(f"    <{tag}>\n")
        for vr, deps in items:
            attr = _deps(deps, lambda r: str(index[r]))
            body.append(f'      <Unknown index="{index[vr]}"{attr}/>\n')
        body.append(f"    </{tag}>\n")

    unknowns("Outputs", info["deps"]["outputs"])
    unknowns("Derivatives", info["deps"]["derivatives"])
    unknowns("InitialUnknowns", sorted(info["deps"]["initial"], key=lambda it: index[it[0]]))
    body.append("  </ModelStructure>\n</fmiModelDescription>\n")
    return "".join(head + body)


# ---- FMI 3.0 ------------------------------------------------------------------------------
def fmi3_xml(info: dict) -> str:
    vs: list[FmuVariable] = info["variables"]
    names = ["time"] + [v.name for v in vs]
    caps = ('canGetAndSetFMUState="true" canSerializeFMUState="true" '
            'providesDirectionalDerivatives="true"')
    head = [f'<?xml version="1.0" encoding="UTF-8"?>\n<fmiModelDescription fmiVersion="3.0"'
            f'{_a("modelName", info["model_name"])}'
            f'{_a("instantiationToken", info["guid"])}'
            f'{_a("description", info["description"])} generationTool="acausal (native)"'
            f' generationDateAndTime="{time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}"'
            f' variableNamingConvention="{naming_convention(names)}">\n']
    if info["me"]:
        head.append(f'  <ModelExchange modelIdentifier="{info["identifier"]}" {caps}'
                    f' needsCompletedIntegratorStep="{str(needs_step(info)).lower()}"/>\n')
    if info["cs"]:
        head.append(f'  <CoSimulation modelIdentifier="{info["identifier"]}" {caps}'
                    f' canHandleVariableCommunicationStepSize="true" hasEventMode="false"'
                    f' mightReturnEarlyFromDoStep="{str(info["terminations"]).lower()}"'
                    f' maxOutputDerivativeOrder="0"/>\n')
    head.append(unit_definitions({"s"} | {v.unit for v in vs if v.unit}))
    head.append('  <LogCategories>\n    <Category name="logStatusError"/>\n'
                '    <Category name="logStatusWarning"/>\n    <Category name="logEvents"/>\n'
                '    <Category name="logAll"/>\n  </LogCategories>\n')
    head.append(f'  <DefaultExperiment startTime="0" stopTime="{_num(info["stop_time"])}"'
                f' tolerance="1e-06"/>\n')
    body = ['  <ModelVariables>\n    <Float64 name="time" valueReference="0"'
            ' causality="independent" variability="continuous" description="simulation time"'
            ' unit="s"/>\n']
    for v in vs:
        attrs, real = _attributes(v, info, v.derivative_of)
        body.append(f"    <Float64{attrs}{real}/>\n")
    body.append("  </ModelVariables>\n  <ModelStructure>\n")
    for tag, key in (("Output", "outputs"), ("ContinuousStateDerivative", "derivatives"),
                     ("InitialUnknown", "initial")):
        for vr, deps in info["deps"][key]:
            body.append(f'    <{tag} valueReference="{vr}"{_deps(deps, str)}/>\n')
    body += [f'    <EventIndicator valueReference="{v.value_reference}"/>\n' for v in vs
             if v.kind == "indicator"]
    body.append("  </ModelStructure>\n</fmiModelDescription>\n")
    return "".join(head + body)


def build_description(identifier: str, sources: list[str]) -> str:
    files = "".join(f'      <SourceFile name="{f}"/>\n' for f in sources)
    return (f'<?xml version="1.0" encoding="UTF-8"?>\n<fmiBuildDescription fmiVersion="3.0">\n'
            f'  <BuildConfiguration modelIdentifier="{identifier}">\n'
            f'    <SourceFileSet language="C99">\n{files}'
            f'    </SourceFileSet>\n    <Library name="m"/>\n  </BuildConfiguration>\n'
            f'</fmiBuildDescription>\n')
