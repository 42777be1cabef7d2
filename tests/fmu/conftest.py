"""Shared by the FMU tests: a per-module directory for exported FMUs (each module exports its
FMUs once)."""
from __future__ import annotations

import pytest


@pytest.fixture(scope="module")
def fmu_dir(tmp_path_factory, request):
    """A temporary directory for the FMUs of one test module."""
    return tmp_path_factory.mktemp(request.module.__name__.rsplit(".", 1)[-1])
