"""Where and under which name an FMU is written: its model identifier and its file, checked
before anything is built (a build is wasted on a destination that cannot be written)."""
from __future__ import annotations

import os
import re
from pathlib import Path

from ..errors import FmuPathError


def identifier(name: str) -> str:
    """The FMU's modelIdentifier: the model name as a C identifier."""
    ident = re.sub(r"\W", "_", name or "model")
    return ident if re.match(r"[A-Za-z_]", ident) else f"m_{ident}"


def fmu_path(path, model_name: str) -> Path:
    """The .fmu file to write for ``path``: ``path`` itself, or ``<identifier>.fmu`` inside
    it when it is a directory. Missing parent directories will be created; FmuPathError
    when the destination cannot be written (a read-only directory, a parent that is a file)."""
    path = Path(path)
    if path.is_dir():
        path = path / f"{identifier(model_name)}.fmu"
    if path.is_dir():
        raise FmuPathError(f"cannot write the FMU to '{path}': it is a directory")
    existing = path.parent
    while not existing.exists():
        existing = existing.parent
    if not existing.is_dir():
        raise FmuPathError(f"cannot write the FMU to '{path}': '{existing}' is a file, not a "
                           f"directory; choose another path")
    target = path if path.exists() else existing
    if not os.access(target, os.W_OK):
        raise FmuPathError(f"cannot write the FMU to '{path}': no permission to write "
                           f"'{target}'; choose a writable directory")
    return path
