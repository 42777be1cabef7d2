"""Shared by every test: the published reference results (the Modelica Association's
MAP-LIB_ReferenceResults, DLR's PlanarMechanics_ReferenceResults), as the fixture
``reference_result``.

They are not part of this repository: a test reads them from the directory named by the
environment variable ACAUSAL_REFERENCE_RESULTS or from ``shared/`` beside the repository
(``shared/MAP-LIB_ReferenceResults/...``, ``shared/PlanarMechanics_ReferenceResults/...``,
each laid out as its public repository), and is skipped with a reason without them.
"""
from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

SHARED = Path(__file__).resolve().parents[1].parent / "shared"


def load_reference_result(collection: str, model: str) -> dict[str, np.ndarray]:
    """The reference result of ``model`` (a dotted Modelica class name, e.g.
    'Modelica.Mechanics.Rotational.Examples.ElasticBearing') in ``collection``
    ('MAP-LIB_ReferenceResults', 'PlanarMechanics_ReferenceResults'): column -> values, the
    repeated times of events kept once (the value after the event). Skips the test when the
    collection is not at hand."""
    roots = [Path(os.environ["ACAUSAL_REFERENCE_RESULTS"]) / collection] \
        if os.environ.get("ACAUSAL_REFERENCE_RESULTS") else []
    roots.append(SHARED / collection)
    parts = model.split(".")
    for root in roots:
        path = root.joinpath(*parts) / f"{parts[-1]}.csv"
        if path.is_file():
            break
    else:
        pytest.skip(f"{collection} not at hand (put it in shared/ beside the repository or "
                    f"name its parent directory in ACAUSAL_REFERENCE_RESULTS)")
    with open(path, encoding="utf-8") as f:
        names = [n.strip().strip('"') for n in f.readline().split(",")]
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    keep = np.append(data[1:, 0] != data[:-1, 0], True)
    return {n: data[keep, k] for k, n in enumerate(names)}


@pytest.fixture
def reference_result():
    """``reference_result(collection, model)``: see ``load_reference_result``."""
    return load_reference_result
