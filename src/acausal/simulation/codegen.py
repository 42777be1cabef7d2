"""Generated code for simulate(..., codegen=True): the model's equations as C, built once by
the system C compiler, cached on disk, and run by the CasADi integrators.

The library holds the right-hand side of the model, ``ode(x, t, u, p)`` for an ODE or
``dae(x, z, t, u, p) -> (ode, alg)`` for a DAE, with the parameters and inputs as
arguments: changing a parameter or an input never rebuilds it. (Folding the parameter
values into the expressions, as the in-process simulate() does, takes a third of the
instructions off the N = 32 pendulum but only 5-7 % off the compiled right-hand side's
time, 42.0 against 44.4 us median of 21 interleaved mapped runs on a loaded machine: not
worth a build per parameter change.) For the solvers that iterate with
Newton's method (cvodes' BDF, idas) it also holds the Jacobian with respect to the states,
or its forward derivative when that Jacobian is too large to compile (``equations``); the
other arguments are declared not differentiable (the integrators need no derivative with
respect to t, u or p). Adams with functional iteration and the explicit DOP853 evaluate no
derivative, so their library has none.

The results equal those of a CasADi integrator on ``compiled.dae`` with the parameters as
its arguments (the same arithmetic); the in-process simulate() folds them, which rounds
otherwise in some models: the two then differ at the level of the integrator's error.

The shared library is named by a SHA-256 hash of its C source (and of the compiler and its
flags) in the cache directory, ``$ACAUSAL_CACHE`` or ``~/.cache/acausal`` (``$XDG_CACHE_HOME``
when set): a second run of the same model, in this process or another, loads it without
compiling. Within a process the loaded Functions are also kept on the model. Models with
events or modes are refused (their indicator and update functions are not generated).
"""
from __future__ import annotations

import hashlib
import os
import tempfile
from pathlib import Path

import casadi as ca

from .. import toolchain
from ..errors import SimulationError

WITHOUT_DERIVATIVES = ("adams", "dop853")      # the solvers that evaluate no Jacobian
NO_AD = {"enable_fd": True, "enable_forward": False, "enable_reverse": False,
         "enable_jacobian": False}


def cache_dir() -> Path:
    """Where built libraries are kept: $ACAUSAL_CACHE, else the user's cache directory."""
    root = os.environ.get("ACAUSAL_CACHE")
    if root:
        return Path(root).expanduser()
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "acausal"


def equations(model, derivatives: bool) -> ca.Function:
    """The model's right-hand side as a CasADi Function loaded from generated C (built on
    the first call, cached on disk and on the model): ``ode(x, t, u, p)`` for an ODE,
    ``dae(x, z, t, u, p) -> (ode, alg)`` for a DAE; ``derivatives``: with its Jacobian with
    respect to the states (x, z), for Newton's method — symbolic, with its sparsity, as the
    in-process integrator has it while its code is cheap to compile
    (``toolchain.jacobian_fits``); else CasADi's from the forward derivative, one column
    per call."""
    key = ("codegen", derivatives)
    if key not in model._cache:
        check_supported(model)
        f = _function(model)
        functions = [f]
        if derivatives:
            jac = f.jacobian()
            functions.append(jac if toolchain.jacobian_fits(jac, f) else f.forward(1))
        library = _library(functions, f.name())
        model._cache[key] = ca.external(f.name(), str(library),
                                        {"is_diff_in": _states(model)} if derivatives else NO_AD)
    return model._cache[key]


def _states(model) -> list[bool]:
    """Which arguments of the generated function are differentiated: the states only."""
    return [True, True, False, False, False] if model.z.numel() else [True, False, False, False]


def check_supported(model) -> None:
    """Refuse what the generated code does not cover: models with events or modes."""
    if model.has_events:
        raise SimulationError(
            f"model '{model.name}' has events or modes, which simulate(codegen=True) does not "
            f"support; simulate it without codegen, or export a native FMU "
            f"(compiled.export_fmu), whose generated code handles events")


def _function(model) -> ca.Function:
    args = [model.x, model.z, model.t, model.u, model.p]
    names = ["x", "z", "t", "u", "p"]
    if model.z.numel():
        return ca.Function("dae", args, [model.ode, model.alg], names, ["ode", "alg"],
                           {"is_diff_in": _states(model)})
    return ca.Function("ode", args[:1] + args[2:], [model.ode], names[:1] + names[2:], ["ode"],
                       {"is_diff_in": _states(model)})


def _library(functions: list[ca.Function], name: str) -> Path:
    """The shared library of the C of ``functions``: from the cache, or built into it."""
    cc = toolchain.find_compiler(SimulationError)
    with tempfile.TemporaryDirectory(prefix="acausal_codegen_") as tmp:
        gen = ca.CodeGenerator(f"{name}.c", {"with_header": False})
        for f in functions:
            gen.add(f)
        source = Path(tmp) / f"{name}.c"
        source.write_text(toolchain.plain_access(gen.dump(), functions, SimulationError))
        digest = hashlib.sha256(source.read_bytes())
        digest.update(" ".join((cc, ca.__version__) + toolchain.FLAGS).encode())
        target = cache_dir() / f"{name}_{digest.hexdigest()[:24]}.so"
        if target.is_file():
            return target
        try:
            target.parent.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise SimulationError(f"the cache directory of generated code {target.parent} "
                                  f"cannot be created ({e}); set ACAUSAL_CACHE to a writable "
                                  f"directory") from None
        # built beside its final name and renamed: a concurrent run never loads half a file
        partial = target.with_suffix(f".{os.getpid()}.tmp")
        toolchain.build_shared_library(cc, [source], partial, flags=toolchain.FLAGS,
                                       error=SimulationError,
                                       what=f"the generated code of '{name}'")
        os.replace(partial, target)
    return target


def dae_problem(model, solver: str, u_expr: ca.SX, p, scale) -> dict:
    """The integrator's DAE dict on the generated code: states [x; z] divided by ``scale``
    (as ``problem.scaled``), inputs the functions of time ``u_expr``, the parameter values
    ``p`` constants of the call (the integrator has no parameters)."""
    nx = model.x.numel()
    f = equations(model, derivatives=solver not in WITHOUT_DERIVATIVES)
    x, t = ca.MX.sym("x", nx), ca.MX.sym("t")
    u = ca.Function("u", [model.t], [u_expr])(t) if model.u.numel() else ca.MX(0, 1)
    Nx = ca.DM(scale[:nx])
    if not model.z.numel():
        return {"x": x, "t": t, "ode": f(Nx * x, t, u, ca.DM(p)) / Nx}
    z = ca.MX.sym("z", model.z.numel())
    ode, alg = f(Nx * x, ca.DM(scale[nx:]) * z, t, u, ca.DM(p))
    return {"x": x, "z": z, "t": t, "ode": ode / Nx, "alg": alg}
