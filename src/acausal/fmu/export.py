"""Native FMU export: CasADi C code generation + this package's FMI wrapper in C, compiled with
the system C compiler. No Python is needed where the FMU runs.

What the FMU contains
---------------------
- ``binaries/linux64/<id>.so`` (FMI 2.0) or ``binaries/x86_64-linux/<id>.so`` (FMI 3.0), built
  from ``sources/``: the generated model functions (``ac_ode.c``, ``ac_jac.c``, … a file
  each for the large ones, ``ac_small.c`` for the others, declared together by
  ``model_functions.h``; every source compiled at -O1, side by side, ``toolchain``), the
  model's sizes
  and tables (``model.h``, ``model_data.c``), the shared runtime (``c/`` in this package:
  ``instance.c`` the instance, its variables and life cycle; ``equations.c`` evaluation and
  Newton for algebraic variables; ``events.c`` state events, modes and terminations;
  ``loops.c`` the consistent start (loops, initial equations) and the loops' projection;
  ``solver.c`` the RODAS4 co-simulation solver; ``linalg.c`` dense LU, Householder QR and
  minimum-norm least squares) and the FMI adapter (``fmi2.c`` or ``fmi3.c``). FMI 2 lists the sources in modelDescription.xml, FMI 3 in
  ``sources/buildDescription.xml``; to rebuild elsewhere compile them with the standard FMI
  headers on the include path and link with ``-lm``.
- Variables: ``variables.fmu_variables`` (parameters tunable, inputs, outputs, states with
  settable start values, derivatives, the modes and event indicators of a model with state
  events, every recorded variable) plus ``solver.rtol`` and
  ``solver.atol``, the co-simulation solver's tolerances (tunable parameters; they exist in
  model exchange too but are used there only for the loop-drift threshold below).

Model exchange
--------------
The FMU presents the ODE ẋ = f(t, x, z(x), p, u): algebraic variables z of massless nodes are
solved inside by Newton's method (generated Jacobian, warm-started from the last solution).
Closed loops (the compiler's stabilized GGL form, multipliers μ = ν = 0 on the exact solution)
are presented with μ = ν = 0, i.e. the accelerations of the KKT solve; the constraints
Φ = 0, Φ̇ = 0 are kept by projection: ``completedIntegratorStep`` asks for an event when
max(|Φ|, |Φ̇|) exceeds 1e-3·``solver.rtol`` and the event update projects the states onto
the constraints (the closest point in the Euclidean norm of the states, by the assembly's
projection steps below, reporting ``valuesOfContinuousStatesChanged``). Time events (steps, ramps, pulses) are reported as
``nextEventTime``.

State events and modes (``compiled.state_events``; the runtime's ``events.c``, after
acausal.simulation.events): the indicators are the FMU's event indicators
(``numberOfEventIndicators`` / FMI 3's ``EventIndicator``s, also variables by their names
``<component>.<indicator>``), read by ``fmi2GetEventIndicators`` / ``fmi3GetEventIndicators``;
the importer locates their sign changes. The modes are internal discrete states (variables
``local``, ``discrete``, read-only). The FMU keeps each indicator's side (its sign, a zero
staying on the side it was on, as events.py's ``side``) at the last accepted step
(``completedIntegratorStep``, which the FMU then needs, asks for an event when a step
crossed) and event, and reports each indicator with a hysteresis of 1e-10 (in its units)
on that side (g + 1e-10·side), as Modelica tools shift their crossing functions: at the
crossing the importer locates, the relations the mode updates test (a torque beyond its
breakaway value) are past their thresholds by more than round-off, however tightly it is
located; the event instants differ from simulate()'s by 1e-10/|dg/dt|. The
event update (``fmi2NewDiscreteStates`` / ``fmi3UpdateDiscreteStates``) runs the event as
``simulate()`` does: the reinits of the indicators that crossed (in their directions, values
at the left limit), then the event iteration: all modes updated from the present ones, the
algebraic variables solved in between, until no mode changes (50 rounds, events.py's
``MAX_ITERATIONS``; otherwise fmiError with a message naming the components whose modes
keep changing), reporting ``valuesOfContinuousStatesChanged`` when states were reinitialized
or modes changed (the importer restarts its solver). Initialization ends with the same
iteration, so that the modes start consistent. Termination conditions
(``PhysicsBuilder.terminate``: TerminateSimulation) are checked after every event update
past the start time, as events.py's ``_ends``: when one holds, its component and text are
logged (status OK, category ``logEvents``, whatever the logging setting) and the event
update reports ``terminateSimulation`` (the conditions change at events only, so
``completedIntegratorStep`` never does). A crossing that can change nothing (no
modes, no reinit of it in that direction: a ball leaving the floor) updates the sides
only. Integer and Boolean modes are rounded in the iteration, discrete Real variables
(sampled values, ``StructureBuilder.discrete``) are not. The instants of sample triggers
(``StructureBuilder.sample``: the discrete blocks) are time events (``nextEventTime``); at
one (within 1e-12·max(1, |t|) s, events.py's ``instant``) the trigger is true through the
event iteration, then the iteration runs once more with it false, as in ``simulate()``;
at the start only the triggers declared ``initial`` are true.

Co-simulation
-------------
An embedded linearly implicit Rosenbrock solver, RODAS4 (Hairer & Wanner; stiffly accurate,
L-stable, order 4 with an embedded order-3 error estimate), with the exact Jacobian from CasADi
and step-size control: error ≤ ``solver.atol`` + ``solver.rtol``·|x| (RMS norm); the step size
is carried over from one communication step to the next. Inputs are held constant over a
communication step (``canInterpolateInputs=false``). The solver stops just before every time
event and restarts at it. Loops: the states are projected onto Φ = 0, Φ̇ = 0 after every
accepted step. An importer's tolerance (fmi2SetupExperiment / fmi3EnterInitializationMode)
replaces the default ``solver.rtol`` (and sets ``solver.atol`` to 1/100 of it) unless they
were set explicitly.
State events: after every accepted step the indicators' sides are checked; a crossing is
located inside the step as ``simulate()`` locates it (secant steps on the crossed
indicators, bisection when the bracket shrinks slowly, to 1e-12·max(1, |t|) s), each trial
point one RODAS4 step from the step's start; the event (reinits, event iteration) runs at
the bracket's end and the step goes on from there. Time events run the event iteration
too. A termination condition that holds after an event inside a step ends the step there,
the FMU at the event's right limit: FMI 2's fmi2DoStep returns fmi2Discard, then
``fmi2GetBooleanStatus(fmi2Terminated)`` is true and
``fmi2GetRealStatus(fmi2LastSuccessfulTime)`` the event's time; FMI 3's fmi3DoStep returns
fmi3OK with ``terminateSimulation`` true, ``lastSuccessfulTime`` the event's time and
``earlyReturn`` true if the importer allowed it (``earlyReturnAllowed``;
``mightReturnEarlyFromDoStep`` is declared for a model with termination conditions). A
further doStep is refused (fmiError).

Chattering (simulate()'s rule: 100 state events within 1e-6 of the time, here of
max(1, |t|) s, the FMU not knowing the importer's stop time) is an error naming the
component whose indicators fired the most (a relay without a stuck mode).

What it cannot do: with closed loops, a
reinit is followed by the drift projection, which does not hold the reinitialized states as
simulate() does; the Jacobian is dense and re-evaluated every step and
the linear algebra is dense LU, O(n³) per step (fine for tens to a few hundred states, slow
for thousands); the Newton iteration for z has no globalization beyond the warm start (it
fails with fmi2Error and a logged message if it does not converge in 50 iterations; with
initial equations it runs at every point of the initialization's projection, where
simulate() has z among the projection's unknowns); the
solver does not detect the loops' singular positions (a dead point of a linkage stops it
with an error). A sample instant at the stop time is taken by the co-simulation FMU (its
last doStep ends at the instant's right limit), not by simulate(), which ends there; a
model-exchange importer that steps over a sample instant (its event update comes later)
gets fmiError naming the block instead of a lost sample.

Initialization
--------------
Start values of the states follow the parameters (``compiled.start(p)``) unless the importer
set them. Closed loops are assembled and the components' initial equations
(``PhysicsBuilder.initial``: InitializeFlange, a steady start) satisfied in
exitInitializationMode by ``simulate()``'s algorithm (acausal.numerics.project on the same
equations as ``initial_state(..., initial_equations=True)``, in C in loops.c), so both reach
the same start: the states the importer set are held (as simulate()'s x0), the others move
the least from their start values (projections onto Φ = 0, Φ̇ = 0 and the initial equations
linearized, the algebraic variables solved at every point, rows scaled by their gradients,
minimum-norm steps from orthogonal factorizations; steps limited to 0.3 on the coordinates only, speeds never held back; a
Levenberg–Marquardt descent when the projection stalls at a singular configuration, such as
a linkage with every joint at 0; then the same deterministic restarts). A failure names the
constraints not satisfied and whether the positions or the speeds set are at fault, or the
initial equations not satisfied (by their labels) and the start values set. Then the
loop-row switches ``loops.active_i``
(calculatedParameters) are set at the assembled configuration as ``simulate()`` sets them:
rows that add nothing to the rank of Φ_q there are off (a redundant link).

Errors and the life cycle
-------------------------
The FMU keeps the FMI life cycle (instantiated, initialization mode, event / continuous-time
mode or step mode, terminated, and an error state after a failed initialization, step or
event update) with the Reference FMUs' rules of which call is allowed when. Refused, with
fmi2Error / fmi3Error and a message through the logger callback, and without changing the
instance: a NULL instance (no message), a call out of order, a value reference no variable has
(0 in FMI 2; time in FMI 3), a non-finite time, tolerance, input or state, a parameter value
that is not finite or violates its Parameter's positive / nonnegative / nonzero flag (the
flags are generated into model_data.c), a doStep whose step size is not finite and > 0 or
whose communication point is not the FMU's time (the Reference FMUs' tolerance: 1e-5,
absolute or relative; the step then ends at communication point + step size). A failed
Newton, projection or step returns the same statuses and puts the instance in the error
state, from which it can be read, reset, restored from an FMU state or freed.

Directional derivatives (``providesDirectionalDerivative(s)``) of state derivatives and
outputs w.r.t. states and inputs come from CasADi's AD (total derivatives through z).
"""
from __future__ import annotations

import hashlib
import platform
import tempfile
import uuid
import zipfile
from importlib import resources
from pathlib import Path

import numpy as np

from .. import toolchain
from ..errors import AcausalError, FmuExportError
from ..simulation.events import CHATTER_EVENTS, CHATTER_SPAN, EVENT_TOL, MAX_ITERATIONS
from .codegen import ModelFunctions
from .destination import fmu_path, identifier
from .model_description import (SOLVER_VARIABLES, build_description, fmi2_xml, fmi3_xml)
from .variables import FmuVariable, fmu_variables

KINDS = {"parameter": 0, "input": 1, "output": 2, "state": 3, "derivative": 4, "recorded": 5,
         "solver": 6, "time": 7, "switch": 9, "mode": 10, "indicator": 11}
# (instance.h's AC_K_*; 8: no variable)
# the runtime shared by every native FMU (c/): headers, then the C files compiled
RUNTIME_HEADERS = ("instance.h", "equations.h", "events.h", "loops.h", "solver.h", "linalg.h")
RUNTIME_SOURCES = ("instance.c", "equations.c", "events.c", "loops.c", "solver.c", "linalg.c")


# ---- the toolchain ---------------------------------------------------------------------
def find_fmi_headers(version: str) -> Path:
    """The directory holding fmi2Functions.h / fmi3Functions.h, from the installed fmpy."""
    header = "fmi2Functions.h" if version == "2.0" else "fmi3Functions.h"
    try:
        import importlib.util
        spec = importlib.util.find_spec("fmpy")
    except (ImportError, ValueError):
        spec = None
    if spec is None or not spec.origin:
        raise FmuExportError(f"the FMI {version} headers ({header}) are taken from the fmpy "
                             f"package, which is not installed: pip install fmpy")
    root = Path(spec.origin).parent
    hits = sorted(root.rglob(header))
    for h in hits:          # the directory with the complete set of headers
        d = h.parent
        need = (["fmi2TypesPlatform.h", "fmi2FunctionTypes.h"] if version == "2.0"
                else ["fmi3PlatformTypes.h", "fmi3FunctionTypes.h"])
        if all((d / n).is_file() for n in need):
            return d
    raise FmuExportError(f"no {header} (with its companion headers) under {root}; reinstall "
                         f"fmpy (pip install --force-reinstall fmpy)")


def find_compiler() -> str:
    """The system C compiler (see ``acausal.toolchain``)."""
    return toolchain.find_compiler(FmuExportError)


def platform_dirs() -> tuple[str, str, str]:
    """(FMI 2 platform, FMI 3 platform tuple, shared library extension) of this machine."""
    system, machine = platform.system(), platform.machine().lower()
    arch = {"amd64": "x86_64", "x86_64": "x86_64", "arm64": "aarch64", "aarch64": "aarch64"}.get(
        machine, machine)
    if system == "Linux":
        return ("linux64" if arch == "x86_64" else f"linux-{arch}"), f"{arch}-linux", ".so"
    if system == "Darwin":
        return "darwin64", f"{arch}-darwin", ".dylib"
    raise FmuExportError(f"native FMU export supports Linux and macOS, not {system}; use "
                         f"backend='pythonfmu'")


# ---- tables ------------------------------------------------------------------------------
def _c_str(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _c_arr(ctype: str, name: str, values, fmt=repr) -> tuple[str, str]:
    """(declaration for model.h, definition for model_data.c) of a constant table."""
    vals = list(values) or ["" if fmt is _c_str else 0]
    body = ", ".join(fmt(v) for v in vals)
    head = f"const {ctype} {name}[{len(vals)}]"
    return f"extern {head};\n", f"{head} = {{{body}}};\n"


def solver_variables(first_vr: int) -> list[FmuVariable]:
    return [FmuVariable(name, first_vr + i, "solver", i, "parameter", "tunable", "exact",
                        float(start), unit, desc)
            for i, (name, start, unit, desc) in enumerate(SOLVER_VARIABLES)]


def vr_table(compiled, variables: list[FmuVariable], fmi_version: str):
    """(kind, index) by value reference; value reference 0 is time in FMI 3.0 (declared
    there as the independent variable) and no variable in FMI 2.0."""
    layout = compiled.recorded_layout
    n = max(v.value_reference for v in variables) + 1
    kind, index = [8] * n, [0] * n
    if fmi_version == "3.0":
        kind[0] = KINDS["time"]
    for v in variables:
        k, i = KINDS[v.kind], v.index
        if v.kind == "recorded":
            src, j = layout[v.index]
            k, i = (KINDS["state"], j) if src == "x" else (KINDS["recorded"], j)
        kind[v.value_reference], index[v.value_reference] = k, i
    return kind, index


def model_sources(compiled, mf: ModelFunctions, variables, guid: str, nominal: list[float],
                  fmi_version: str) -> dict[str, str]:
    """model.h (the sizes of the model and its tables' declarations) and model_data.c (the
    tables: value references, defaults, parameter flags, the loop-row switches, the
    coordinates' positions in x, names)."""
    sz = mf.sizes()
    kind, index = vr_table(compiled, variables, fmi_version)
    sizes = [("NX", mf.nx), ("NZ", mf.nz), ("NP", mf.np), ("NU", mf.nu), ("NY", mf.ny),
             ("NREC", mf.nrec), ("NH", mf.nh), ("NPHI", mf.nphi), ("NQ", mf.nq),
             ("NPOS", len(compiled.position_states)), ("NEV", mf.nev), ("NVR", len(kind)),
             ("NG", mf.ng), ("NMODE", mf.nmode), ("NREINIT", mf.nreinit),
             ("NCLOCK", mf.nclock), ("NIE", mf.nie), ("NTERM", mf.nterm),
             ("NASSERT", mf.nassert),
             ("SZ_ARG", sz["arg"]), ("SZ_RES", sz["res"]), ("SZ_IW", sz["iw"]),
             ("SZ_W", sz["w"])]
    # the Parameter's flags, checked by the runtime as Parameter.check_scalar does
    rules = [v.declaration.rule for v in compiled.params]
    flags = [(1 if r["positive"] else 0) | (2 if r["nonnegative"] else 0)
             | (4 if r["nonzero"] else 0) for r in rules]
    tables = [("char *", "ac_model_name", _c_str(compiled.name)),
              ("char *", "ac_guid", _c_str(guid))]
    arrays = [_c_arr("int", "AC_VR_KIND", kind, str), _c_arr("int", "AC_VR_INDEX", index, str),
              _c_arr("double", "AC_P_DEFAULT", compiled.param_vector(),
                     lambda v: repr(float(v))),
              _c_arr("int", "AC_SWITCH", compiled.loop_switches, str),
              _c_arr("int", "AC_POSITIONS", compiled.position_states, str),
              _c_arr("char *", "AC_H_NAMES", mf.h_names, _c_str),
              _c_arr("unsigned char", "AC_P_FLAGS", flags, str),
              _c_arr("char *", "AC_P_NAMES", compiled.param_names, _c_str),
              _c_arr("double", "AC_U_START", [float(v) for v in compiled.input_start]),
              _c_arr("char *", "AC_X_NAMES", compiled.x_names, _c_str),
              _c_arr("double", "AC_X_NOMINAL", nominal),
              _c_arr("char *", "AC_Z_NAMES", mf.z_names, _c_str),
              _c_arr("double", "AC_SOLVER_DEFAULT", [float(s[1]) for s in SOLVER_VARIABLES])]
    arrays += [_c_arr(ctype, name, values, _c_str if ctype == "char *" else str)
               for name, (ctype, values) in mf.event_tables().items()]
    model_h = ["/* generated by acausal: sizes and tables of the model */\n#ifndef AC_MODEL_H\n"
               "#define AC_MODEL_H\n"]
    model_h += [f"#define AC_{k} {v}\n" for k, v in sizes]
    # simulate()'s event engine's settings (acausal.simulation.events), for events.c
    model_h.append(f"#define AC_EVENT_ITERATIONS {MAX_ITERATIONS}\n"
                   f"#define AC_EVENT_TOL {EVENT_TOL!r}\n"
                   f"#define AC_CHATTER_EVENTS {CHATTER_EVENTS}\n"
                   f"#define AC_CHATTER_SPAN {CHATTER_SPAN!r}\n")
    model_h.append("#define AC_D(n) ((n) > 0 ? (n) : 1)   /* array length: C has no empty "
                   "arrays */\n")
    model_h += [f"extern const {t} {n};\n" for t, n, _ in tables] + [d for d, _ in arrays]
    model_h.append("#endif\n")
    data = ['/* generated by acausal: tables of the model */\n#include "model.h"\n']
    data += [f"const {t} {n} = {v};\n" for t, n, v in tables] + [d for _, d in arrays]
    return {"model.h": "".join(model_h), "model_data.c": "".join(data)}


def dependencies(compiled, mf: ModelFunctions, variables: list[FmuVariable]) -> dict:
    """ModelStructure: (value reference, [value references it depends on] or None for all) of
    the outputs, derivatives and initial unknowns, from the sparsity of the Jacobians."""
    by_kind = {}
    for v in variables:
        by_kind.setdefault(v.kind, {})[v.index] = v.value_reference
    xs, us, ps = by_kind.get("state", {}), by_kind.get("input", {}), by_kind.get("parameter", {})
    nx, nu = mf.nx, mf.nu

    def deps(row, with_params):
        cols = np.flatnonzero(mf.dep_w[row])
        out = [xs[c] for c in cols if c < nx] + [us[c - nx] for c in cols if nx <= c < nx + nu]
        if with_params:
            out += [ps[c] for c in np.flatnonzero(mf.dep_p[row]) if c in ps]   # not switches
        return sorted(out)

    ders = [(by_kind["derivative"][i], deps(i, False)) for i in range(nx)]
    outs = [(by_kind["output"][i], deps(nx + i, False)) for i in range(mf.ny)]
    init = ([(by_kind["output"][i], deps(nx + i, True)) for i in range(mf.ny)]
            + [(by_kind["derivative"][i], deps(i, True)) for i in range(nx)]
            # the loop-row switches follow from the assembly: from every start value (None:
            # no dependencies attribute, i.e. on all knowns)
            + [(vr, None) for vr in by_kind.get("switch", {}).values()])
    return {"outputs": outs, "derivatives": ders, "initial": init}


# ---- build -----------------------------------------------------------------------------------
def export_native(compiled, path, *, fmi_version: str = "2.0", fmu_type: str = "both",
                  stop_time: float = 1.0, description: str | None = None,
                  nominals: dict | None = None) -> Path:
    """Write a native FMU of ``compiled`` to ``path`` (a directory gets ``<model>.fmu``).
    ``nominals``: state name (or a variable that coincides with one) -> nominal magnitude,
    replacing the model's (``compiled.nominals`` at the default parameters: 1 unless
    declared): the scale of its absolute tolerance, in the importer's solver (``nominal``
    attribute) and in the FMU's own."""
    if fmi_version not in ("2.0", "3.0"):
        raise FmuExportError(f"fmi_version must be '2.0' or '3.0', got {fmi_version!r}")
    if fmu_type not in ("me", "cs", "both"):
        raise FmuExportError(f"fmu_type must be 'me', 'cs' or 'both', got {fmu_type!r}")
    path = fmu_path(path, compiled.name)
    ident = identifier(compiled.name)
    headers = find_fmi_headers(fmi_version)
    cc = find_compiler()
    plat2, plat3, ext = platform_dirs()
    try:
        nominal = [float(v) for v in compiled.nominals(compiled.param_vector(), nominals)
                   [:len(compiled.x_names)]]
    except AcausalError as e:
        raise FmuExportError(f"nominals: {e}") from None
    mf = ModelFunctions(compiled)
    variables = fmu_variables(compiled)
    variables += solver_variables(variables[-1].value_reference + 1 if variables else 1)
    with tempfile.TemporaryDirectory(prefix="acausal_fmu_") as tmp:
        tmp = Path(tmp)
        src = tmp / "sources"
        src.mkdir()
        generated = mf.generate(src)
        digest = hashlib.sha256(b"".join((src / f).read_bytes() for f in generated))
        digest.update(repr([(v.name, v.value_reference, v.start) for v in variables]
                           + nominal).encode())
        guid = "{" + str(uuid.UUID(digest.hexdigest()[:32])) + "}"
        for name, text in model_sources(compiled, mf, variables, guid, nominal,
                                       fmi_version).items():
            (src / name).write_text(text)
        wrapper = "fmi2.c" if fmi_version == "2.0" else "fmi3.c"
        pkg = resources.files("acausal.fmu") / "c"
        for name in RUNTIME_HEADERS + RUNTIME_SOURCES + (wrapper,):
            (src / name).write_text((pkg / name).read_text())
        c_files = [*generated, "model_data.c", *RUNTIME_SOURCES, wrapper]
        plat = plat2 if fmi_version == "2.0" else plat3
        binary = tmp / "binaries" / plat / f"{ident}{ext}"
        binary.parent.mkdir(parents=True)
        hidden = ("-fvisibility=hidden",)
        toolchain.build_shared_library(cc, [src / f for f in c_files], binary,
                                       include=(src, headers), flags=toolchain.FLAGS + hidden,
                                       error=FmuExportError, what="the FMU")
        info = {"model_name": compiled.name, "identifier": ident, "guid": guid,
                "description": description or f"{compiled.name} (acausal, native)",
                "variables": variables, "me": fmu_type in ("me", "both"),
                "cs": fmu_type in ("cs", "both"), "sources": c_files,
                "deps": dependencies(compiled, mf, variables),
                "loops": mf.nh > 0, "events": compiled.has_events, "assertions": mf.nassert > 0, "stop_time": stop_time,
                "terminations": mf.nterm > 0,
                "nominal": {n: v for n, v in zip(compiled.x_names, nominal) if v != 1.0}}
        if fmi_version == "2.0":
            (tmp / "modelDescription.xml").write_text(fmi2_xml(info))
        else:
            (tmp / "modelDescription.xml").write_text(fmi3_xml(info))
            (src / "buildDescription.xml").write_text(build_description(ident, c_files))
        path.parent.mkdir(parents=True, exist_ok=True)
        with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as zf:
            for f in sorted(tmp.rglob("*")):
                if f.is_file():
                    zf.write(f, f.relative_to(tmp).as_posix())
    return path
