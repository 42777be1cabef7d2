"""FMI 2.0 co-simulation FMUs through pythonfmu: the compiled model runs in Python on the
importer's side, with a CasADi integrator.

``export_pythonfmu(compiled, path)`` writes an FMU whose ``resources`` hold

- the slave module (the template ``acausal/fmu/pythonfmu_slave.py``), the numerics it shares with
  acausal (``acausal/numerics.py``, as the module ``<slave>_kernels``) and pythonfmu's
  own Python files (pythonfmu's builder embeds them);
- ``acausal_model/model.json``: the FMU variables of ``acausal.fmu.variables.fmu_variables``
  (the same names, value references, causalities, units and start values as the native FMU),
  the parameters' range checks, the recorded variables' layout and the solver settings;
- ``acausal_model/*.casadi``: the model as serialized CasADi Functions — the integrator
  (built here, once: the DAE in scaled time with parameters, inputs, step start and length as
  its parameters), the start values, time events, right-hand side, outputs, recorded
  variables and (closed loops / algebraic equations) the initialization equations;
- ``requirements.txt``: what the importing Python needs (``pythonfmu deploy -f x.fmu`` installs it).

What the importing machine needs
--------------------------------
- Linux x86-64 or Windows x86-64 (the platforms pythonfmu ships its FMI wrapper binary for);
- a CPython 3 interpreter in the importing process: Python importers (fmpy, PyFMI, …) have it;
  a non-Python importer must be able to resolve the Python C API (on Linux, start it with the
  interpreter's ``libpython3.X.so`` preloaded, e.g. ``LD_PRELOAD=/usr/lib/x86_64-linux-gnu/
  libpython3.11.so``; on Windows, ``python3X.dll`` on the PATH);
- in that interpreter: ``numpy`` and ``casadi`` — the same casadi version as the exporter (it is
  in ``requirements.txt`` and ``model.json``; the slave logs a warning on a mismatch: CasADi's
  serialization format may change between releases). Not acausal, not pythonfmu.
For an FMU that needs nothing on the importer's side use the native backend.

Models with state events or modes are refused (``acausal.fmu.export_fmu``: FmuExportError):
the slave's integrator would step across their events; the native backend handles them.

The FMU: every parameter tunable (a change during the simulation takes effect from the next
step), inputs held constant over each communication step, states settable before
initialization (a value different from the declared start is held exactly; closed loops are
assembled around it), outputs, state derivatives and every recorded variable readable;
get/set/serialize FMU state. The tolerances (``rtol``, ``atol``) are fixed at export: pythonfmu
does not pass the importer's tolerance to the slave. So are the nominals (the model's at the
default parameters, ``compiled.nominals``, or ``nominals`` given at export): the integrator
works on the states divided by them, so that a state's absolute tolerance is atol·nominal,
as in acausal.simulate. CasADi re-initializes its integrator at
every call, so every communication step restarts the multistep method from the state reached:
the defaults (1e-10, 1e-12) are tighter than acausal.simulate's so that a hundred restarts stay
well inside 1e-6 of the in-process result.

Errors: a failed solve, a failed initialization (e.g. a linkage that cannot be assembled) or an
invalid parameter value makes fmi2DoStep return fmi2Discard (fmpy then ends the simulation at
the last good time) with the reason logged at status error; pythonfmu maps a Python exception
to fmi2Fatal and has no fmi2Error, so the slave never raises. Messages reach the importer's
logger when logging is on (fmi2Instantiate's loggingOn; fmpy: ``debug_logging=True``).
"""
from __future__ import annotations

import hashlib
import json
import shutil
import sys
import tempfile
from importlib.metadata import version
from pathlib import Path

import casadi as ca

from ..errors import AcausalError, FmuExportError, SimulationError
from .. import numerics
from ..simulation.initialization import model_equations
from ..simulation.problem import integrator_settings
from .destination import fmu_path, identifier
from .model_description import base_unit_attributes, naming_convention
from .variables import fmu_variables

TEMPLATE = Path(__file__).with_name("pythonfmu_slave.py")
DATA = "acausal_model"
SOLVERS = ("cvodes", "adams", "idas")


def export_pythonfmu(compiled, path, *, fmi_version: str = "2.0", fmu_type: str = "cs",
                     rtol: float = 1e-10, atol: float = 1e-12, solver: str | None = None,
                     nominals: dict | None = None, **options) -> Path:
    """Write ``compiled`` as an FMI 2.0 co-simulation FMU at ``path`` (a file name, or an
    existing directory: then ``<model>.fmu`` inside it); returns the FMU's path.

    rtol, atol  the integrator's tolerances (fixed in the FMU);
    solver      'cvodes' (ODE default: BDF), 'adams' (non-stiff ODE models) or 'idas' (DAE
                default), as in acausal.simulate;
    nominals    nominal magnitudes by state name (or a variable that coincides with one),
                replacing the model's, as simulate's ``nominal``.
    """
    if str(fmi_version) != "2.0":
        raise FmuExportError(f"the pythonfmu backend makes FMI 2.0 FMUs only, not "
                           f"fmi_version={fmi_version!r}; use backend='native' for FMI 3.0")
    if fmu_type != "cs":
        raise FmuExportError(f"the pythonfmu backend makes co-simulation FMUs only, not "
                           f"fmu_type={fmu_type!r}: pass fmu_type='cs', or use "
                           f"backend='native' for model exchange")
    if options:
        raise FmuExportError(f"unknown option(s) {sorted(options)} for the pythonfmu backend; "
                           f"it takes rtol, atol, solver and nominals")
    try:
        from pythonfmu.builder import FmuBuilder
    except ImportError:
        raise FmuExportError("the pythonfmu backend needs the 'pythonfmu' package: "
                           "pip install pythonfmu (or acausal[fmu])") from None
    path = fmu_path(path, compiled.name)
    ident = identifier(compiled.name)
    functions, meta = _contents(compiled, ident, rtol, atol, solver, nominals)
    source = TEMPLATE.read_text(encoding="utf-8")
    shared = Path(numerics.__file__).read_text(encoding="utf-8")
    digest = hashlib.sha1((source + shared).encode()).hexdigest()[:10]
    module = f"acausal_slave_{digest}"
    with tempfile.TemporaryDirectory(prefix="acausal_fmu_") as tmp:
        tmp = Path(tmp)
        data = tmp / DATA
        data.mkdir()
        for name, f in functions.items():
            f.save(str(data / f"{name}.casadi"))
        (data / "model.json").write_text(json.dumps(meta, indent=1), encoding="utf-8")
        requirements = tmp / "requirements.txt"
        requirements.write_text(f"numpy\ncasadi=={ca.__version__}\n", encoding="utf-8")
        script = tmp / "src" / f"{module}.py"
        script.parent.mkdir()
        script.write_text(source, encoding="utf-8")
        shared_module = script.with_name(f"{module}_kernels.py")    # the slave imports it
        shared_module.write_text(shared, encoding="utf-8")
        built = tmp / f"{ident}.fmu"
        try:
            FmuBuilder.build_FMU(script, dest=built,
                                 project_files=[data, requirements, shared_module],
                                 canGetAndSetFMUstate=True, canSerializeFMUstate=True)
        finally:    # the builder imports the script: leave no trace in this process
            sys.modules.pop(module, None)
            sys.modules.pop(f"{module}_kernels", None)
            while str(script.parent) in sys.path:
                sys.path.remove(str(script.parent))
        path.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, path)
    return path


def _contents(compiled, ident, rtol, atol, solver, nominals):
    """The serialized Functions and the JSON metadata of the FMU."""
    c = compiled
    variables = fmu_variables(c)
    has_alg = c.z.numel() > 0
    loops = c.has_loops
    try:
        scale = c.nominals(c.param_vector(), nominals)
    except AcausalError as e:
        raise FmuExportError(f"nominals: {e}") from None
    integrator, deviation = _integrator(c, solver, rtol, atol, scale)
    rec = c.recorded_function
    functions = {
        "integrator": integrator,
        "start": c.start,
        "events": c.events,
        "f": c.f,
        "outputs": c.output_function,
        "recorded": rec,
    }
    init_labels = []
    if loops or has_alg:
        functions["init"], init_labels = _init_function(c)
    if loops:
        functions["phi_q"] = c.phi_q_function
    if c.assertions.numel():
        functions["assertions"] = c.function("assertions", [c.assertions])
    checks = []
    for v in c.params:
        checks.append(dict(v.declaration.rule, description=v.description, unit=v.unit))
    layout = c.recorded_layout
    meta = {
        "identifier": ident,
        "description": (f"acausal model '{c.name}': {len(c.x_names)} states, "
                        f"{len(c.params)} parameters, {len(c.inputs)} inputs, "
                        f"{len(c.outputs)} outputs (pythonfmu co-simulation)"),
        "acausal_version": version("acausal"),
        "casadi_version": ca.__version__,
        "functions": sorted(functions),
        "x_names": list(c.x_names),
        "z_names": list(c.z_names),
        "param_names": list(c.param_names),
        "param_defaults": [float(v) for v in c.param_vector()],
        "loop_switches": c.loop_switches,
        "positions": c.position_states,
        "parameter_checks": checks,
        "variables": [_plain(v) for v in variables],
        "units": [_unit(u) for u in sorted({v.unit for v in variables if v.unit})],
        "naming_convention": naming_convention([v.name for v in variables]),
        # recorded variables: the FMU variable's index is its position in recorded_names
        "recorded_layout": [list(layout[i]) for i in range(len(layout))],
        "deviation_form": deviation,
        "init_labels": init_labels,
        "assertion_texts": [list(a) for a in c.assertion_texts],
        "rtol": rtol, "atol": atol,
        "nominal": [float(v) for v in scale],
    }
    return functions, meta


def _plain(v):
    return {"name": v.name, "value_reference": v.value_reference, "kind": v.kind,
            "index": v.index, "causality": v.causality, "variability": v.variability,
            "initial": v.initial, "start": v.start, "unit": v.unit or "",
            "description": v.description or "", "derivative_of": v.derivative_of}


def _unit(name):
    """A unit with its SI base-unit exponents (BaseUnit attributes), as the native FMU
    declares it; base None when the unit string is not understood."""
    return {"name": name, "base": base_unit_attributes(name)}


def _integrator(c, solver, rtol, atol, scale):
    """The model's integrator over one step, in scaled time τ ∈ [0, 1] (t = t0 + h·τ), with
    parameters P = [p; u; t0; h] (closed loops: also [x0; ẋ0], integrating the deviation
    δ = x − x0 − h·τ·ẋ0, consistent at τ = 0 with ẋ(δ) = 0), in the states (or δ) and the
    algebraic variables divided by their nominals ``scale``. Options as in
    acausal.simulate."""
    has_alg = c.z.numel() > 0
    solver = solver or ("idas" if has_alg else "cvodes")
    if solver not in SOLVERS:
        raise FmuExportError(f"unknown solver '{solver}' for the pythonfmu backend; choose "
                             f"one of {SOLVERS}")
    try:
        plugin, opts, loops = integrator_settings(c, solver, rtol, atol)
    except SimulationError as e:
        raise FmuExportError(str(e)) from None
    nx = c.x.numel()
    tau = ca.SX.sym("tau")
    t0, h = ca.SX.sym("t0"), ca.SX.sym("h")
    P = [c.p, c.u, t0, h]
    t = t0 + h * tau
    Nx, Nz = ca.DM(scale[:nx]), ca.DM(scale[nx:])
    if loops:
        d, x0, f0 = ca.SX.sym("delta", nx), ca.SX.sym("x0", nx), ca.SX.sym("f0", nx)
        P += [x0, f0]
        ode, alg = c.f(t, x0 + h * tau * f0 + Nx * d, Nz * c.z, c.u, c.p)
        dae = {"x": d, "ode": (h * ode - h * f0) / Nx}
    else:
        ode, alg = c.f(t, Nx * c.x, Nz * c.z, c.u, c.p)
        dae = {"x": c.x, "ode": h * ode / Nx}
    dae.update(t=tau, p=ca.vertcat(*P))
    if has_alg:
        dae.update(z=c.z, alg=alg)
    if loops:      # the step in τ that acausal.simulate takes in t: 1e-6 of the segment
        opts["step0"] = 1e-6
    return ca.integrator("step", plugin, dae, 0.0, 1.0, opts), loops


def _init_function(c):
    """(t, w = [x; z], u, p) -> (H, ∂H/∂w): loop constraints Φ, Φ̇ and algebraic equations,
    the equations acausal.simulation.initialization.initial_state holds; and their labels."""
    w = ca.vertcat(c.x, c.z)
    eqs, labels = model_equations(c)
    H = ca.vertcat(*[ca.vec(e) for e in eqs])
    f = ca.Function("init", [c.t, w, c.u, c.p], [H, ca.jacobian(H, w)],
                    ["t", "w", "u", "p"], ["H", "J"])
    return f, labels
