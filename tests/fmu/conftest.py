"""Shared by the FMU tests: the examples/ directory on sys.path (the worked models live there)
and a per-module directory for exported FMUs (each module exports its FMUs once)."""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
if str(EXAMPLES) not in sys.path:
    sys.path.insert(0, str(EXAMPLES))


@pytest.fixture(scope="module")
def fmu_dir(tmp_path_factory, request):
    """A temporary directory for the FMUs of one test module."""
    return tmp_path_factory.mktemp(request.module.__name__.rsplit(".", 1)[-1])
