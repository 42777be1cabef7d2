"""The system C compiler and the C that CasADi generates for it: found on the PATH, called to
build shared libraries (the native FMUs, the generated code of ``simulate(...,
codegen=True)``), and given code it compiles in reasonable time.

gcc's time on CasADi's straight-line code grows steeply with the size of a function (its
register allocation works on the whole of it), so what is generated is kept cheap to
compile: ``-O1`` (``FLAGS``: as fast to run as -O2, 1.5-2x faster to build), no
null-pointer branch per element where they are dense (``plain_access``), a dense Jacobian
only while it is small (``jacobian_fits``: else the forward derivative, one column per
call), and the sources of a library compiled side by side on the available cores.

A base leaf: it imports nothing of acausal. The caller passes the error class its own layer
raises (``FmuExportError``, ``SimulationError``).
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
from pathlib import Path

import casadi as ca

# CasADi's straight-line code runs as fast at -O1 as at -O2 (a 3-D chain of 16 links:
# 16.6 vs 16.4 us per right-hand side; -O0 43 us) and compiles 1.5x faster (8 s vs 13 s)
FLAGS = ("-O1",)
JACOBIAN_LIMIT = 20000      # instructions: gcc -O1 takes ~1 s per 3000
JACOBIAN_RATIO = 5          # a sparse Jacobian (a chain of masses) is kept however large
BRANCHY = 0.1               # null-pointer branches per instruction worth removing


def find_compiler(error: type[Exception]) -> str:
    """The path of the C compiler: $CC, else cc, gcc or clang on the PATH."""
    for cand in [os.environ.get("CC"), "cc", "gcc", "clang"]:
        if cand and shutil.which(cand):
            return shutil.which(cand)
    raise error("no C compiler found (tried $CC, cc, gcc, clang); install one, e.g. "
                "apt-get install gcc, or set CC")


def build_shared_library(cc: str, sources: list, out: Path, *,
                         include: tuple[Path, ...] = (), flags: tuple[str, ...] = ("-O2",),
                         error: type[Exception],
                         what: str = "the shared library") -> None:
    """Compile and link C ``sources`` into the shared library ``out`` (C99, position
    independent, linked with libm); a source is a Path (compiled with ``flags``) or a
    (Path, its own flags) pair. Several sources are compiled side by side, as many at a
    time as this process may use cores, then linked. A failure raises ``error`` with the
    compiler's last lines."""
    sources = [s if isinstance(s, tuple) else (s, flags) for s in sources]
    common = ["-fPIC", "-std=c99", "-w"] + [f"-I{d}" for d in include]
    if len(sources) == 1:
        (src, own), = sources
        _run([[cc, *own, "-shared", *common, str(src), "-o", str(out), "-lm"]], error, what)
        return
    with tempfile.TemporaryDirectory(prefix="acausal_objects_") as tmp:
        objects = [Path(tmp) / f"{k}_{Path(src).stem}.o" for k, (src, _) in enumerate(sources)]
        jobs = sorted(zip(sources, objects), key=lambda j: -Path(j[0][0]).stat().st_size)
        _run([[cc, *own, "-c", *common, str(src), "-o", str(o)] for (src, own), o in jobs],
             error, what)                    # the largest first: the cores finish together
        _run([[cc, "-shared", *map(str, objects), "-o", str(out), "-lm"]], error, what)


def _run(commands: list[list[str]], error: type[Exception], what: str) -> None:
    """Run the compiler commands, as many at a time as there are cores to use; the first
    failure raises ``error``."""
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else \
        (os.cpu_count() or 1)
    pending, running = list(commands), []
    try:
        while pending or running:
            while pending and len(running) < cores:
                cmd = pending.pop(0)
                running.append((cmd, subprocess.Popen(cmd, stdout=subprocess.PIPE,
                                                      stderr=subprocess.STDOUT, text=True)))
            cmd, proc = running.pop(0)
            output = proc.communicate()[0]
            if proc.returncode != 0:
                tail = "\n".join(output.strip().splitlines()[-25:])
                raise error(f"compiling {what} failed ({' '.join(cmd[:2])} ...):\n{tail}")
    finally:
        for _, proc in running:
            proc.kill()
            proc.wait()


def jacobian_fits(jacobian: ca.Function, function: ca.Function) -> bool:
    """Whether the generated code of ``jacobian`` (of ``function``) compiles in reasonable
    time: at most JACOBIAN_LIMIT instructions or JACOBIAN_RATIO times the function's. The
    dense Jacobian of a recursion (O(N²) code) does not: its columns from the forward
    derivative (code linear in the model's size) take its place."""
    limit = max(JACOBIAN_LIMIT, JACOBIAN_RATIO * function.n_instructions())
    return jacobian.n_instructions() <= limit


def work_size(f: ca.Function) -> int:
    """Work vector length of ``f`` as ``plain_access`` leaves it: CasADi's, plus room for
    the largest result a caller does not want."""
    return f.sz_w() + max([f.nnz_out(i) for i in range(f.n_out())] + [1])


def plain_access(code: str, functions: list[ca.Function], error: type[Exception]) -> str:
    """CasADi's C reads every argument element as ``arg[i]? arg[i][k] : 0`` and writes every
    result element under ``if (res[i]!=0)`` (a null pointer: zeros in, not wanted out): a
    branch per element, which makes gcc's time grow steeply with the size of the function
    (the 1000-mass chain's ODE and Jacobian: 7 s and 17 s at -O1, 2.7 s and 1.6 s without).
    Reads and writes become plain; each exported function passes a block of zeros for a
    null argument (derivative seeds CasADi leaves out) and, for a null result, space it
    adds to the work vector (per call: thread-safe; ``work_size``). Only where the branches
    are dense (a tenth of the instructions or more, ``BRANCHY``): in long stretches of
    arithmetic between few reads (a 3-D recursion) they cut the block that gcc's register
    allocation works on, and it takes longer without them (a 16-link 3-D chain: 4.8 s, 7 s
    without). Only for SX functions: an MX function calls others with null pointers."""
    if not all(f.is_a("SXFunction") for f in functions):
        return code
    reads = re.compile(r"arg\[(\d+)\]\? (arg\[\1\]\[\d+\]) : 0")
    writes = re.compile(r"if \(res\[\d+\]!=0\) (res\[\d+\]\[\d+\]=)")
    branches = len(reads.findall(code)) + len(writes.findall(code))
    if branches < BRANCHY * sum(f.n_instructions() for f in functions):
        return code
    largest = max(f.nnz_in(i) for f in functions for i in range(f.n_in()))
    code = reads.sub(r"\2", code)
    code = writes.sub(r"\1", code)
    for f in functions:
        name = re.escape(f.name())
        work = re.compile(rf"(CASADI_SYMBOL_EXPORT int {name}_work\({_SIZES}\) \{{\n(?:.*\n)"
                          rf"{{3}}  if \(sz_w\) \*sz_w = )(\d+);")
        entry = re.compile(rf"(CASADI_SYMBOL_EXPORT int {name}{_ENTRY}\{{\n)"
                           rf"  return (casadi_f\d+)\(arg, res, iw, w, mem\);")
        found = [int(m.group(2)) for m in work.finditer(code)]
        code, n_work = work.subn(lambda m: f"{m.group(1)}{work_size(f)};", code)
        guard = (f"  const casadi_real* a[{max(f.n_in(), 1)}];\n"
                 f"  casadi_real* r[{max(f.n_out(), 1)}];\n  int i;\n"
                 f"  for (i = 0; i < {f.n_in()}; ++i) a[i] = arg[i] ? arg[i] : acausal_zeros;\n"
                 f"  for (i = 0; i < {f.n_out()}; ++i) r[i] = res[i] ? res[i] : "
                 f"w + {f.sz_w()};\n")
        code, n_entry = entry.subn(lambda m: f"{m.group(1)}{guard}  return {m.group(2)}"
                                             f"(a, r, iw, w, mem);", code)
        if n_work != 1 or n_entry != 1 or found[0] > f.sz_w():
            raise error(f"the generated code of '{f.name()}' has not the entry points "
                        f"expected (CasADi {ca.__version__}): generate it with another "
                        f"CasADi version")
    zeros = f"static const casadi_real acausal_zeros[{max(largest, 1)}] = {{0}};\n"
    head = code.index("static int casadi_f")             # before the first function
    return code[:head] + zeros + code[head:]


_ENTRY = (r"\(const casadi_real\*\* arg, casadi_real\*\* res, casadi_int\* iw, "
          r"casadi_real\* w, int mem\)")
_SIZES = (r"casadi_int \*sz_arg, casadi_int\* sz_res, casadi_int \*sz_iw, "
          r"casadi_int \*sz_w")
