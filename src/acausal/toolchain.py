"""The system C compiler: found on the PATH and called to build shared libraries (the native
FMUs, the generated code of ``simulate(..., codegen=True)``).

A base leaf: it imports nothing of acausal. The caller passes the error class its own layer
raises (``FmuExportError``, ``SimulationError``).
"""
from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path


def find_compiler(error: type[Exception]) -> str:
    """The path of the C compiler: $CC, else cc, gcc or clang on the PATH."""
    for cand in [os.environ.get("CC"), "cc", "gcc", "clang"]:
        if cand and shutil.which(cand):
            return shutil.which(cand)
    raise error("no C compiler found (tried $CC, cc, gcc, clang); install one, e.g. "
                "apt-get install gcc, or set CC")


def build_shared_library(cc: str, sources: list[Path], out: Path, *,
                         include: tuple[Path, ...] = (), flags: tuple[str, ...] = ("-O2",),
                         error: type[Exception],
                         what: str = "the shared library") -> None:
    """Compile and link C ``sources`` into the shared library ``out`` (C99, position
    independent, linked with libm); a failure raises ``error`` with the compiler's last
    lines."""
    cmd = [cc, *flags, "-shared", "-fPIC", "-std=c99", "-w"]
    cmd += [f"-I{d}" for d in include] + [str(s) for s in sources] + ["-o", str(out), "-lm"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        tail = "\n".join((r.stderr or r.stdout).strip().splitlines()[-25:])
        raise error(f"compiling {what} failed ({' '.join(cmd[:2])} ...):\n{tail}")
