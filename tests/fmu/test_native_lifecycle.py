"""Native FMUs give no silent wrong answer: they keep the FMI life cycle (instantiated,
initialization, event / continuous-time / step mode, terminated, error) and refuse, with
fmiError and a message through the logger, calls out of order, a NULL instance, non-finite
times, steps and values, communication points away from the FMU's time, value references
that do not exist, and parameter values their Parameter's flags forbid. Then two independent
importers, the FMU Compliance Checker (FMI 2.0) and the Reference FMUs' fmusim (FMI 3.0), run
the FMUs and agree with compiled.simulate.
"""
from __future__ import annotations

import ctypes
import math
import re
import warnings
from pathlib import Path

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")
from fmpy import read_model_description                           # noqa: E402
from fmpy.fmi1 import FMICallException                            # noqa: E402

import acausal                                                    # noqa: E402
from acausal.errors import ParameterError                          # noqa: E402
from acausal.fmu.export import find_fmi_headers, platform_dirs    # noqa: E402
from acausal.models import Drivetrain, FourBar, GantryCrane       # noqa: E402
from fmi_calls import derivatives, get_real, init, instance, set_real, unzipped  # noqa: E402
from importers import fmu_check, fmusim                            # noqa: E402

VERSIONS = ("2.0", "3.0")
RTOL = 1e-6            # test_native.py's agreement with compiled.simulate
# the independent importers: ../shared/fmi-tools/bin relative to the repository root


@pytest.fixture(scope="module")
def fmus(fmu_dir):
    out = {}
    for name, make in (("crane", GantryCrane), ("drivetrain", lambda: Drivetrain("drivetrain")),
                       ("four_bar", FourBar)):
        compiled = acausal.compile(make())
        out[name] = compiled
        for v in VERSIONS:
            out[name, v] = compiled.export_fmu(fmu_dir / f"{name}{v[0]}.fmu", fmi_version=v)
    return out


def refused(call, capsys, *words):
    """``call`` fails with fmiError and the logger says every one of ``words``."""
    with pytest.raises(FMICallException, match="status 3"):
        call()
    log = capsys.readouterr().out
    for w in words:
        assert w in log, (w, log)


def fmu_time(fmu, md):
    """The FMU's time: FMI 3 declares it (value reference 0), FMI 2 reports the last
    successful time of co-simulation."""
    if md.fmiVersion == "3.0":
        return get_real(fmu, md, [0])[0]
    return fmu.getRealStatus(fmpy.fmi2.fmi2LastSuccessfulTime)


@pytest.mark.parametrize("version", VERSIONS)
def test_do_step_refuses_non_finite_and_mismatched_times(fmus, version, capsys):
    """NaN / infinite step sizes and communication points, zero or negative steps and a
    communication point away from the FMU's time are refused (the Reference FMUs' rule:
    within 1e-5, absolute or relative); the FMU keeps its time and state and steps on."""
    fmu, vr, md = instance(fmus["crane", version], cs=True)
    init(fmu, md, {"hinge.phi": 0.3}, vr)
    fmu.doStep(0.0, 0.1)
    states = [vr[n] for n in ("rail.s", "hinge.phi", "rail.v", "hinge.w")]
    x = get_real(fmu, md, states)
    for t, h in ((0.1, math.nan), (0.1, math.inf), (math.nan, 0.1), (math.inf, 0.1),
                 (0.1, 0.0), (0.1, -0.1)):
        refused(lambda: fmu.doStep(t, h), capsys, "doStep", "finite and > 0")
    for t in (0.1 + 2e-5, 0.1 - 2e-5, 5.0, 0.0):
        refused(lambda: fmu.doStep(t, 0.1), capsys, "FMU is at t = 0.1")
    assert fmu_time(fmu, md) == 0.1 and np.array_equal(get_real(fmu, md, states), x)
    fmu.doStep(0.1 + 1e-9, 0.1)          # within the tolerance: steps to t0 + h
    assert fmu_time(fmu, md) == 0.1 + 1e-9 + 0.1
    fmu.terminate()
    fmu.freeInstance()


@pytest.mark.parametrize("version", VERSIONS)
def test_set_time_refuses_non_finite(fmus, version, capsys):
    """Model exchange: setTime(NaN / ±inf) is refused; the drivetrain's sources (a ramp, a
    load step) keep answering at the time before."""
    fmu, vr, md = instance(fmus["drivetrain", version])
    init(fmu, md, {}, vr)
    fmu.enterContinuousTimeMode()
    nx = md.numberOfContinuousStates
    x = np.full(nx, 0.1)
    before = derivatives(fmu, md, x, t=0.3)
    for t in (math.nan, math.inf, -math.inf):
        refused(lambda: fmu.setTime(t), capsys, "time must be a finite number")
        assert np.array_equal(derivatives(fmu, md, x, t=0.3), before)
    assert not np.array_equal(derivatives(fmu, md, x, t=2.9), before)   # the time matters
    bad = x.copy()
    bad[0] = math.nan
    refused(lambda: fmu.setContinuousStates((ctypes.c_double * nx)(*bad), nx), capsys,
            "not finite")
    fmu.terminate()
    fmu.freeInstance()


@pytest.mark.parametrize("cs", [False, True])
@pytest.mark.parametrize("version", VERSIONS)
def test_calls_out_of_order_are_refused(fmus, version, cs, capsys):
    """Initialization again after steps, steps before initialization or after terminate,
    model-exchange calls in co-simulation or in the wrong mode: refused with a message naming
    the function and the mode; the FMU keeps its time and states and goes on."""
    v3 = version == "3.0"
    fmu, vr, md = instance(fmus["crane", version], cs=cs)
    refused(lambda: fmu.exitInitializationMode(), capsys, "ExitInitializationMode",
            "not allowed in the instantiated state")
    if cs:
        refused(lambda: fmu.doStep(0.0, 0.1), capsys, "DoStep", "instantiated")
    init(fmu, md, {"hinge.phi": 0.3}, vr)
    states = [vr[n] for n in ("rail.s", "hinge.phi", "rail.v", "hinge.w")]
    if cs:
        fmu.doStep(0.0, 0.1)
        mode = "step mode"
    else:
        fmu.enterContinuousTimeMode()
        fmu.setTime(0.1)
        mode = "continuous-time mode"
    x = get_real(fmu, md, states)
    again = (lambda: fmu.enterInitializationMode(startTime=0.0)) if v3 else \
        fmu.enterInitializationMode
    refused(again, capsys, "EnterInitializationMode", mode)
    refused(fmu.exitInitializationMode, capsys, "ExitInitializationMode", mode)
    if not v3:
        refused(lambda: fmu.setupExperiment(startTime=0.0), capsys, "SetupExperiment", mode)
    if cs:
        set_time = getattr(fmu.dll, f"fmi{version[0]}SetTime")    # not a slave's method
        set_time.argtypes = [ctypes.c_void_p, ctypes.c_double]
        assert set_time(fmu.component, 0.2) == 3
        assert "SetTime is not allowed in step mode" in capsys.readouterr().out
        fmu.doStep(0.1, 0.1)               # goes on from where it was
        assert fmu_time(fmu, md) == pytest.approx(0.2, abs=1e-15)
    else:
        update = fmu.updateDiscreteStates if v3 else fmu.newDiscreteStates
        refused(update, capsys, "DiscreteStates", mode)
        refused(fmu.enterContinuousTimeMode, capsys, "EnterContinuousTimeMode", mode)
        assert np.array_equal(get_real(fmu, md, states), x)
        fmu.enterEventMode()                # goes on
        update()
    fmu.terminate()
    refused(fmu.terminate, capsys, "Terminate", "the terminated state")
    if cs:
        refused(lambda: fmu.doStep(0.2, 0.1), capsys, "DoStep", "the terminated state")
    refused(lambda: set_real(fmu, md, [vr["load.m"]], [2.0]), capsys, "the terminated state")
    fmu.reset()                             # back to instantiated: a new run
    init(fmu, md, {}, vr)
    fmu.freeInstance()


def test_failed_computation_is_the_error_state(fmus, capsys):
    """A step that fails puts the instance in the error state: it refuses further steps, can
    be read (the states as before the step) and a saved FMU state brings it back."""
    fmu, vr, md = instance(fmus["four_bar", "2.0"], cs=True)
    init(fmu, md, {"rev1.phi": 1.0}, vr)
    state = fmu.getFMUstate()
    set_real(fmu, md, [vr["rocker_b.r[1]"]], [5.0])     # the loop can no longer close
    refused(lambda: fmu.doStep(0.0, 0.1), capsys, "loop constraints")
    refused(lambda: fmu.doStep(0.0, 0.1), capsys, "not allowed in the error state")
    assert fmu.getStatus(fmpy.fmi2.fmi2DoStepStatus) == fmpy.fmi2.fmi2Error
    assert get_real(fmu, md, [vr["rev1.phi"]])[0] == 1.0
    fmu.setFMUstate(state)
    fmu.doStep(0.0, 0.1)
    fmu.freeFMUstate(state)
    fmu.terminate()
    fmu.freeInstance()


@pytest.mark.parametrize("version", VERSIONS)
def test_unknown_value_references_are_errors(fmus, version, capsys):
    """A value reference no variable has is an error naming it (FMI 3 declares time as 0,
    FMI 2 has no variable 0)."""
    fmu, vr, md = instance(fmus["crane", version], cs=True)
    last = max(v.valueReference for v in md.modelVariables)
    missing = [last + 1, 2**32 - 1] + ([0] if version == "2.0" else [])
    for r in missing:
        refused(lambda: get_real(fmu, md, [r]), capsys, f"no variable with value reference {r}")
        refused(lambda: set_real(fmu, md, [r], [1.0]), capsys,
                f"no variable with value reference {r}")
    if version == "3.0":
        assert get_real(fmu, md, [0])[0] == 0.0
    fmu.freeInstance()


def fmi_functions(version: str) -> list[str]:
    """The FMI functions that take an instance, from the standard's header."""
    header = find_fmi_headers(version) / ("fmi2Functions.h" if version == "2.0"
                                          else "fmi3Functions.h")
    prefix = "fmi2" if version == "2.0" else "fmi3"
    names = set(re.findall(rf"\b({prefix}[A-Z]\w*)TYPE\s+{prefix}\w+;", header.read_text()))
    free = {"GetTypesPlatform", "GetVersion", "Instantiate", "InstantiateModelExchange",
            "InstantiateCoSimulation", "InstantiateScheduledExecution", "FreeInstance"}
    return sorted(n for n in names if n[4:] not in free)


@pytest.mark.parametrize("version", VERSIONS)
def test_null_instance_is_an_error(fmus, version):
    """Every FMI function that takes an instance answers a NULL one with fmiError (x86-64:
    the instance is the first integer argument; the others are zeros, never reached)."""
    d = Path(unzipped(fmus["crane", version]))
    md = read_model_description(str(d))
    plat = platform_dirs()[0 if version == "2.0" else 1]
    lib = ctypes.CDLL(str(d / "binaries" / plat / (md.coSimulation.modelIdentifier
                                                   + platform_dirs()[2])))
    names = fmi_functions(version)
    assert len(names) > (30 if version == "2.0" else 60)
    for name in names:
        fn = getattr(lib, name)
        fn.restype = ctypes.c_int
        assert fn(None, *([0] * 10)) == 3, name
    lib[f"fmi{version[0]}FreeInstance"](None)       # frees nothing, does not crash


PARAM_VALUES = (math.nan, math.inf, -math.inf, -1.0, 0.0, 1e-300, 2.0)


@pytest.mark.parametrize("version", VERSIONS)
def test_parameters_follow_their_flags(fmus, version, capsys):
    """For every parameter with a flag (positive, nonnegative, nonzero) and for one without,
    and for every value above: the FMU refuses exactly what Parameter.check_scalar refuses,
    and non-finite values, with a message naming the parameter; a refused value is not
    taken, an accepted one is."""
    compiled = fmus["drivetrain"]
    fmu, vr, md = instance(fmus["drivetrain", version], cs=True)
    params = [(v.name, v.declaration) for v in compiled.params if v.name in vr]
    flagged = [(n, p) for n, p in params if p.positive or p.nonnegative or p.nonzero]
    plain = [(n, p) for n, p in params if not (p.positive or p.nonnegative or p.nonzero)]
    assert {f for _, p in flagged for f in ("positive", "nonnegative", "nonzero")
            if getattr(p, f)} == {"positive", "nonnegative", "nonzero"}
    for name, par in flagged + plain[:1]:
        for v in PARAM_VALUES:
            try:
                par.check_scalar(v, name)
                ok = math.isfinite(v)
            except ParameterError:
                ok = False
            before = get_real(fmu, md, [vr[name]])[0]
            if ok:
                set_real(fmu, md, [vr[name]], [v])
                assert get_real(fmu, md, [vr[name]])[0] == v
                set_real(fmu, md, [vr[name]], [before])
            else:
                refused(lambda: set_real(fmu, md, [vr[name]], [v]), capsys,
                        f"parameter '{name}'")
                assert get_real(fmu, md, [vr[name]])[0] == before
    init(fmu, md, {}, vr)
    name = flagged[0][0]
    refused(lambda: set_real(fmu, md, [vr[name]], [math.nan]), capsys, f"parameter '{name}'")
    fmu.doStep(0.0, 0.01)                   # the refusal left the FMU running
    fmu.terminate()
    fmu.freeInstance()


@pytest.mark.parametrize("version", VERSIONS)
def test_non_finite_inputs_and_tolerances_are_refused(fmus, version, capsys):
    fmu, vr, md = instance(fmus["crane", version], cs=True)
    for v in (math.nan, math.inf):
        refused(lambda: set_real(fmu, md, [vr["F"]], [v]), capsys, "not finite")
        refused(lambda: set_real(fmu, md, [vr["hinge.phi"]], [v]), capsys, "not finite")
    if version == "2.0":
        refused(lambda: fmu.setupExperiment(tolerance=math.nan, startTime=0.0), capsys,
                "tolerance")
        refused(lambda: fmu.setupExperiment(startTime=math.nan), capsys, "start time")
    else:
        refused(lambda: fmu.enterInitializationMode(startTime=math.inf), capsys, "start time")
    fmu.freeInstance()


# ---- independent importers ---------------------------------------------------------------
def reference(compiled, T, grid, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")       # loop assembly moves the guessed joints
        return compiled.simulate(T, t=grid, rtol=1e-12, atol=1e-14, **kw)


def relerr(a, b):
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b))) / np.max(np.abs(b)))


NAMES = ["rev1.phi", "rev2.phi", "rev3.phi", "rev3.w"]


def test_fmu_compliance_checker(fmus, tmp_path):
    """FMI 2.0, the four-bar falling from its default start (assembled by the FMU): the
    checker finds no error in model exchange or co-simulation. Co-simulation (the FMU's
    RODAS4) equals compiled.simulate to 1e-6; model exchange is integrated by the checker's
    forward Euler, first order in its step h: halving h halves the error, and the Richardson
    extrapolation of the error, 2·e(h/2) − e(h), is below 1e-6 (the checker outputs at the
    Euler step nearest each output point: each run is compared at its own times)."""
    compiled, path = fmus["four_bar"], fmus["four_bar", "2.0"]
    cs = fmu_check(path, "cs", 1.0, 0.02, 50, tmp_path / "cs.csv")
    ref = reference(compiled, 1.0, cs["time"])
    for n in NAMES:
        assert relerr(cs[n], ref[n]) < RTOL, (n, relerr(cs[n], ref[n]))
    coarse = fmu_check(path, "me", 1.0, 2e-5, 50, tmp_path / "me1.csv")
    fine = fmu_check(path, "me", 1.0, 1e-5, 50, tmp_path / "me2.csv")
    assert np.allclose(coarse["time"], fine["time"], rtol=0, atol=3e-5)
    ref_c = reference(compiled, 1.0, coarse["time"])
    ref_f = reference(compiled, 1.0, fine["time"])
    for n in NAMES:
        e_c, e_f = coarse[n] - ref_c[n], fine[n] - ref_f[n]
        scale = np.max(np.abs(ref_f[n]))
        assert 1.8 < np.max(np.abs(e_c)) / np.max(np.abs(e_f)) < 2.2, n
        assert np.max(np.abs(2 * e_f - e_c)) / scale < RTOL, n


@pytest.mark.parametrize("kind", ["me", "cs"])
def test_fmusim_fmi3(fmus, kind, tmp_path):
    """FMI 3.0 through the Reference FMUs' fmusim (CVODE for model exchange, the FMU's RODAS4
    for co-simulation), with a changed parameter and start values: equal to compiled.simulate
    to 1e-6."""
    compiled, path = fmus["four_bar"], fmus["four_bar", "3.0"]
    params, x0 = {"coupler.m": 1.5}, {"rev1.phi": 1.0, "rev1.w": 2.0}
    res = fmusim(path, kind, 1.0, 0.01, {**params, **x0}, NAMES, tmp_path)
    grid = np.linspace(0.0, 1.0, 101)
    idx = np.searchsorted(res["time"], grid + 1e-9, side="right") - 1   # the last row at each
    assert np.allclose(res["time"][idx], grid, rtol=0, atol=1e-12)     # (and events' rows)
    ref = reference(compiled, 1.0, grid, params=params, x0=x0)
    for n in NAMES:
        assert relerr(res[n][idx], ref[n]) < RTOL, (n, relerr(res[n][idx], ref[n]))
