"""Calls into an FMU through fmpy's low-level classes, for the FMU tests: instantiate,
initialize, get and set reals, state derivatives — the same for FMI 2.0 and 3.0."""
from __future__ import annotations

import ctypes
import tempfile
from pathlib import Path

import numpy as np
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Model, FMU2Slave
from fmpy.fmi3 import FMU3Model, FMU3Slave


def unzipped(path) -> str:
    """The FMU at ``path`` extracted next to it (inside the test's temporary directory, which
    pytest cleans up; fmpy's default would leave a directory in /tmp per call)."""
    return extract(str(path), unzipdir=tempfile.mkdtemp(dir=Path(path).parent))


def instance(path, cs=False, **kw):
    md = read_model_description(str(path))
    cls = {("2.0", False): FMU2Model, ("2.0", True): FMU2Slave, ("3.0", False): FMU3Model,
           ("3.0", True): FMU3Slave}[(md.fmiVersion, cs)]
    ident = (md.coSimulation if cs else md.modelExchange).modelIdentifier
    fmu = cls(guid=md.guid, unzipDirectory=unzipped(path), modelIdentifier=ident,
              instanceName="test")
    fmu.instantiate(**kw)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    return fmu, vr, md


def init(fmu, md, start=None, vr=None):
    v3 = md.fmiVersion == "3.0"
    if not v3:
        fmu.setupExperiment(startTime=0.0)
    fmu.enterInitializationMode() if not v3 else fmu.enterInitializationMode(startTime=0.0)
    for n, val in (start or {}).items():
        set_real(fmu, md, [vr[n]], [val])
    fmu.exitInitializationMode()


def get_real(fmu, md, vrs):
    return np.array(fmu.getFloat64(vrs) if md.fmiVersion == "3.0" else fmu.getReal(vrs))


def set_real(fmu, md, vrs, vals):
    fmu.setFloat64(vrs, vals) if md.fmiVersion == "3.0" else fmu.setReal(vrs, vals)


def derivatives(fmu, md, x, t=0.0):
    n = len(x)
    fmu.setTime(t)
    fmu.setContinuousStates((ctypes.c_double * n)(*x), n)
    dx = (ctypes.c_double * n)()
    (fmu.getContinuousStateDerivatives if md.fmiVersion == "3.0" else fmu.getDerivatives)(dx, n)
    return np.array(dx)
