"""The independent FMI importers the FMU tests run: the Reference FMUs' ``fmusim`` and the
FMU Compliance Checker ``fmuCheck`` (``shared/fmi-tools/bin`` beside the repository; a test
that needs one is skipped, with the reason, where it is absent), their results by column."""
from __future__ import annotations

import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

TOOLS = Path(__file__).resolve().parents[2].parent / "shared" / "fmi-tools" / "bin"


def tool(name: str) -> Path:
    exe = TOOLS / name
    if not exe.is_file():
        pytest.skip(f"{name} not found in {TOOLS} (the shared FMI importers)")
    return exe


def csv(path: Path) -> np.ndarray:
    return np.genfromtxt(path, delimiter=",", names=True, deletechars="")


def fmusim(fmu: Path, kind: str, T: float, dt: float, start: dict, outputs: list,
           tmp_path: Path, early_return: bool = False) -> np.ndarray:
    """fmusim on ``fmu`` ("me" with CVODE, or "cs"; ``early_return``: co-simulation steps may
    end early), tolerance 1e-10, with ``start`` values by name: its result, by column."""
    out = tmp_path / f"fmusim_{kind}.csv"
    cmd = [str(tool("fmusim")), "--interface-type", kind, "--tolerance", "1e-10",
           "--stop-time", repr(T), "--output-interval", repr(dt), "--output-file", str(out)]
    for n, v in start.items():
        cmd += ["--start-value", n, repr(v)]
    for n in outputs:
        cmd += ["--output-variable", n]
    if kind == "me":
        cmd += ["--solver", "cvode"]
    elif early_return:
        cmd += ["--early-return-allowed"]
    r = subprocess.run(cmd + [str(fmu)], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr
    return csv(out)


def fmu_check(fmu: Path, kind: str, T: float, h: float, n: int, out: Path) -> np.ndarray:
    """fmuCheck (FMI 2.0) on ``fmu`` ("me" or "cs") to T with step h and n output points:
    asserts that neither the FMU nor the checker reports a warning or error; its result."""
    r = subprocess.run([str(tool("fmuCheck")), "-k", kind, "-s", repr(T), "-h", repr(h),
                        "-n", str(n), "-f", "-l", "3", "-o", str(out), str(fmu)],
                       capture_output=True, text=True, timeout=600)
    report = r.stdout + r.stderr
    assert r.returncode == 0, report
    assert re.search(r"FMU reported:\s+0 warning\(s\) and error\(s\)", report), report
    assert re.search(r"Checker reported:\s+0 Warning\(s\)\s+0 Error\(s\)", report), report
    return csv(out)
