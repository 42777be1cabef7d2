"""Fixtures of the simulation tests."""
import os

import pytest


@pytest.fixture(scope="module")
def codegen_cache(tmp_path_factory):
    """A cache directory of generated code (``ACAUSAL_CACHE``) for one test module."""
    path = tmp_path_factory.mktemp("codegen_cache")
    old = os.environ.get("ACAUSAL_CACHE")
    os.environ["ACAUSAL_CACHE"] = str(path)
    yield path
    if old is None:
        del os.environ["ACAUSAL_CACHE"]
    else:
        os.environ["ACAUSAL_CACHE"] = old


@pytest.fixture
def dask_scratch(tmp_path):
    """dask's scratch directory (the workers' files) in this test's temporary directory
    instead of the system's."""
    dask = pytest.importorskip("dask")
    with dask.config.set({"temporary-directory": str(tmp_path)}):
        yield tmp_path
