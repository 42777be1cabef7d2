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
import re
import tempfile
from pathlib import Path

import casadi as ca

from .. import toolchain
from ..errors import SimulationError

# CasADi's straight-line code runs as fast at -O1 as at -O2 (a 3-D chain of 16 links:
# 16.6 vs 16.4 us per right-hand side; -O0 43 us) and compiles 1.5x faster (8 s vs 13 s)
FLAGS = ("-O1",)
JACOBIAN_LIMIT = 20000      # instructions: gcc -O1 takes ~1 s per 3000
JACOBIAN_RATIO = 5          # a sparse Jacobian (a chain of masses) is kept however large
BRANCHY = 0.1              # null-pointer branches per instruction worth removing
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
    in-process integrator has it while it is at most JACOBIAN_LIMIT instructions or
    JACOBIAN_RATIO times the right-hand side's; else (the dense Jacobian of a recursion,
    O(N²) code) CasADi's from the forward derivative, one column per call (code linear in
    the model's size)."""
    key = ("codegen", derivatives)
    if key not in model._cache:
        check_supported(model)
        f = _function(model)
        functions = [f]
        if derivatives:
            jac = f.jacobian()
            limit = max(JACOBIAN_LIMIT, JACOBIAN_RATIO * f.n_instructions())
            functions.append(jac if jac.n_instructions() <= limit else f.forward(1))
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
        source.write_text(_without_null_checks(gen.dump(), functions))
        digest = hashlib.sha256(source.read_bytes())
        digest.update(" ".join((cc, ca.__version__) + FLAGS).encode())
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
        toolchain.build_shared_library(cc, [source], partial, flags=FLAGS,
                                       error=SimulationError,
                                       what=f"the generated code of '{name}'")
        os.replace(partial, target)
    return target


def _without_null_checks(code: str, functions: list[ca.Function]) -> str:
    """CasADi's C reads every argument element as ``arg[i]? arg[i][k] : 0`` and writes every
    result element under ``if (res[i]!=0)`` (a null pointer: zeros in, not wanted out): a
    branch per element, which makes gcc's time grow steeply with the size of the function
    (the 1000-mass chain's ODE and Jacobian: 7 s and 17 s at -O1, 2.7 s and 1.6 s without).
    Reads and writes become plain; each exported function passes a block of zeros for a
    null argument (derivative seeds CasADi leaves out) and, for a null result, space it
    adds to the work vector (per call: thread-safe). Only where the branches are dense (a
    tenth of the instructions or more, ``BRANCHY``): in long stretches of arithmetic
    between few reads (a 3-D recursion) they cut the block that gcc's register allocation
    works on, and it takes longer without them (a 16-link 3-D chain: 4.8 s, 7 s without)."""
    reads = re.compile(r"arg\[(\d+)\]\? (arg\[\1\]\[\d+\]) : 0")
    writes = re.compile(r"if \(res\[\d+\]!=0\) (res\[\d+\]\[\d+\]=)")
    branches = len(reads.findall(code)) + len(writes.findall(code))
    if branches < BRANCHY * sum(f.n_instructions() for f in functions):
        return code
    largest = max(f.nnz_in(i) for f in functions for i in range(f.n_in()))
    code = re.sub(r"arg\[(\d+)\]\? (arg\[\1\]\[\d+\]) : 0", r"\2", code)
    code = re.sub(r"if \(res\[\d+\]!=0\) (res\[\d+\]\[\d+\]=)", r"\1", code)
    for f in functions:
        name = re.escape(f.name())
        sink = max([f.nnz_out(i) for i in range(f.n_out())] + [1])
        work = re.compile(rf"(CASADI_SYMBOL_EXPORT int {name}_work\({_SIZES}\) \{{\n(?:.*\n)"
                          rf"{{3}}  if \(sz_w\) \*sz_w = )(\d+);")
        entry = re.compile(rf"(CASADI_SYMBOL_EXPORT int {name}{_ENTRY}\{{\n)"
                           rf"  return (casadi_f\d+)\(arg, res, iw, w, mem\);")
        found = []

        def more_work(m):
            found.append(int(m.group(2)))
            return f"{m.group(1)}{found[0] + sink};"
        code, n_work = work.subn(more_work, code)
        guard = (f"  const casadi_real* a[{max(f.n_in(), 1)}];\n"
                 f"  casadi_real* r[{max(f.n_out(), 1)}];\n  int i;\n"
                 f"  for (i = 0; i < {f.n_in()}; ++i) a[i] = arg[i] ? arg[i] : acausal_zeros;\n"
                 f"  for (i = 0; i < {f.n_out()}; ++i) r[i] = res[i] ? res[i] : "
                 f"w + {found[0] if found else 0};\n")
        code, n_entry = entry.subn(lambda m: f"{m.group(1)}{guard}  return {m.group(2)}"
                                             f"(a, r, iw, w, mem);", code)
        if n_work != 1 or n_entry != 1:
            raise SimulationError(f"the generated code of '{f.name()}' has not the entry points "
                                  f"expected (CasADi {ca.__version__}); simulate without codegen")
    zeros = f"static const casadi_real acausal_zeros[{max(largest, 1)}] = {{0}};\n"
    head = code.index("static int casadi_f")             # before the first function
    return code[:head] + zeros + code[head:]


_ENTRY = (r"\(const casadi_real\*\* arg, casadi_real\*\* res, casadi_int\* iw, "
          r"casadi_real\* w, int mem\)")
_SIZES = (r"casadi_int \*sz_arg, casadi_int\* sz_res, casadi_int \*sz_iw, "
          r"casadi_int \*sz_w")


def dae_problem(model, solver: str, u_expr: ca.SX, p, scale) -> dict:
    """The integrator's DAE dict on the generated code: states [x; z] divided by ``scale``
    (as ``simulate.scaled``), inputs the functions of time ``u_expr``, the parameter values
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
