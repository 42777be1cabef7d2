"""pythonfmu backend: FMI 2.0 co-simulation FMUs of compiled models, loaded and simulated by an
independent importer (fmpy) and compared with the in-process simulation of the same model.

Each model is exported once per module. Inputs are driven as steps at communication points
(co-simulation holds an input constant over a step), so the in-process reference with the
same step as a function of time is the same problem; both integrate to tight tolerances and
must agree to 1e-6 relative (to each variable's largest magnitude) at every communication
point.
"""
from __future__ import annotations

import subprocess
import sys
import warnings

import casadi as ca
import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")
pytest.importorskip("pythonfmu")
from fmpy import read_model_description, simulate_fmu            # noqa: E402
from fmpy.validation import validate_fmu                          # noqa: E402

import acausal                                                    # noqa: E402
from acausal.components import translational as tr                # noqa: E402
from acausal.fmu.pythonfmu_backend import export_pythonfmu        # noqa: E402
from acausal.fmu.variables import fmu_variables                   # noqa: E402
from acausal.models import (DiskDriveHead, Drivetrain, FourBar, GantryCrane,  # noqa: E402
                            Parallelogram)

RTOL = 1e-6


class Crane(GantryCrane):
    """The gantry crane with the cart position as a model output ``x`` [m]."""

    def __init__(self):
        super().__init__("crane")
        self.cartPosition = tr.PositionSensor()
        self.x = acausal.Output(unit="m", description="cart position")
        self.connect(self.rail.axis, self.cartPosition.flange)
        self.connect(self.cartPosition.s, self.x.u)


class Drive(Drivetrain):
    """The 1-D drivetrain with the drum speed as a model output ``speed`` [rad/s]."""

    def __init__(self):
        super().__init__("drivetrain")
        self.speed = acausal.Output(unit="rad/s", description="drum speed")
        self.connect(self.drumSpeed.w, self.speed.u)


MODELS = {"crane": Crane, "disk": lambda: DiskDriveHead(), "four_bar": lambda: FourBar(),
          "drivetrain": Drive}


@pytest.fixture(scope="module")
def fmus(tmp_path_factory):
    """name -> (compiled model, FMU path): each model compiled and exported once."""
    folder = tmp_path_factory.mktemp("pythonfmu")
    out = {}
    for name, make in MODELS.items():
        compiled = acausal.compile(make())
        out[name] = compiled, export_pythonfmu(compiled, folder / f"{name}.fmu")
    return out


def run_fmu(path, t_final, dt, names, start_values=None, steps=None):
    """Simulate the FMU in fmpy (co-simulation); ``steps``: {input: (t_switch, before,
    after)}, a step of the input at a communication point. Returns (result, log messages)."""
    logs = []
    signal = None
    if steps:
        times = sorted({0.0, t_final} | {s[0] for s in steps.values()})
        rows = []
        for t in times:
            before = [s[1] if t <= s[0] else s[2] for s in steps.values()]
            after = [s[1] if t < s[0] else s[2] for s in steps.values()]
            rows += [(t, *before)] + ([(t, *after)] if after != before else [])
        signal = np.array(rows, dtype=[("time", float)] + [(n, float) for n in steps])
    res = simulate_fmu(str(path), stop_time=t_final, output_interval=dt, output=names,
                       start_values=start_values or {}, input=signal, debug_logging=True,
                       logger=lambda env, inst, status, cat, msg: logs.append(msg.decode()))
    return res, logs


def run_in_process(compiled, t_final, n, steps=None, **kwargs):
    """compiled.simulate on the FMU's communication grid, the same input steps."""
    inputs = {name: (lambda t, s=s: ca.if_else(t < s[0], s[1], s[2]))
              for name, s in (steps or {}).items()}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")        # loop assembly notes
        return compiled.simulate(t_final, t=np.linspace(0.0, t_final, n + 1), inputs=inputs,
                                 rtol=1e-12, atol=1e-14, **kwargs)


def assert_agree(fmu_res, ref, names, rtol=RTOL):
    assert np.allclose(fmu_res["time"], ref.t, rtol=0, atol=1e-12)
    for name in names:
        scale = np.max(np.abs(ref[name]))
        err = np.max(np.abs(fmu_res[name] - ref[name]))
        assert err <= rtol * scale, \
            f"{name}: max |FMU − in-process| = {err:.3g} (scale {scale:.3g})"


def changed(a, b, name, by=1e-2):
    """The runs differ in ``name`` by more than ``by`` of its magnitude."""
    return np.max(np.abs(a[name] - b[name])) > by * np.max(np.abs(b[name]))


# ---- model description ----------------------------------------------------------------------
@pytest.mark.parametrize("name", list(MODELS))
def test_validates(fmus, name):
    assert validate_fmu(str(fmus[name][1])) == []


def test_variables_are_the_shared_list(fmus):
    """Names, value references, causalities, variability, initial, starts and units are those
    of acausal.fmu.variables (the list the native backend uses too); derivatives point at
    their states; outputs are in the model structure."""
    compiled, path = fmus["crane"]
    md = read_model_description(str(path))
    assert md.fmiVersion == "2.0" and md.coSimulation is not None
    by_name = {v.name: v for v in md.modelVariables}
    expected = fmu_variables(compiled)
    assert len(md.modelVariables) == len(expected)
    for v in expected:
        got = by_name[v.name]
        assert (got.valueReference, got.causality, got.variability) == \
            (v.value_reference, v.causality, v.variability)
        if v.initial is not None:           # (inputs have none; fmpy fills in a default)
            assert got.initial == v.initial
        assert got.unit == (v.unit or None)
        if v.start is not None:
            assert float(got.start) == pytest.approx(v.start, rel=1e-15, abs=0)
        if v.derivative_of is not None:
            assert got.derivative.valueReference == v.derivative_of
    assert by_name["cart.m"].causality == "parameter" and by_name["F"].causality == "input"
    assert [u.variable.name for u in md.outputs] == ["x"]
    assert by_name["x"].unit == "m" and by_name["F"].unit == "N"


# ---- the four models against the in-process simulation -------------------------------------
def test_crane(fmus):
    """Rope angle started at 0.3 rad, force step 0 -> 2 N at 0.5 s; then a heavier load and a
    force step 3 -> -1 N at 0.3 s, through the FMU's parameter and input."""
    compiled, path = fmus["crane"]
    names = ["rail.s", "hinge.phi", "rail.v", "hinge.w", "x", "load.r[1]", "load.r[2]"]
    base = {"F": (0.5, 0.0, 2.0)}
    res, _ = run_fmu(path, 1.0, 0.01, names, {"hinge.phi": 0.3}, base)
    ref = run_in_process(compiled, 1.0, 100, base, x0={"hinge.phi": 0.3})
    assert_agree(res, ref, names)
    assert np.allclose(ref["x"], ref["rail.s"], atol=1e-12)       # the output is the cart
    alt = {"F": (0.3, 3.0, -1.0)}
    res2, _ = run_fmu(path, 1.0, 0.01, names, {"hinge.phi": 0.3, "load.m": 3.5}, alt)
    ref2 = run_in_process(compiled, 1.0, 100, alt, x0={"hinge.phi": 0.3},
                          params={"load.m": 3.5})
    assert_agree(res2, ref2, names)
    assert changed(res2, res, "rail.s") and changed(res2, res, "hinge.phi")


def test_disk_drive_head(fmus):
    """Bang-bang voice-coil torque (switch at 1 ms) over 3 ms, 120 communication steps;
    then a stiffer flexure and a weaker torque. The flexure's deflection (µm) is under the
    FMU's error control through its nominal: FMU and in-process agree to 1e-7 (without
    nominals the FMU's absolute tolerance 1e-12 m let flexure.v drift by 1.6e-7)."""
    compiled, path = fmus["disk"]
    names = ["pivot.phi", "flexure.s", "pivot.w", "flexure.v", "head.r[2]"]
    base = {"T": (1e-3, 0.02, -0.02)}
    res, _ = run_fmu(path, 3e-3, 2.5e-5, names, steps=base)
    ref = run_in_process(compiled, 3e-3, 120, base)
    assert_agree(res, ref, names, rtol=1e-7)
    alt = {"T": (1e-3, 0.01, -0.01)}
    res2, _ = run_fmu(path, 3e-3, 2.5e-5, names, {"flexureSpring.c": 4e4}, alt)
    ref2 = run_in_process(compiled, 3e-3, 120, alt, params={"flexureSpring.c": 4e4})
    assert_agree(res2, ref2, names, rtol=1e-7)
    assert changed(res2, res, "pivot.phi") and changed(res2, res, "flexure.s")


def test_four_bar(fmus):
    """The closed loop assembled around the crank's start values (the FMU's states), falling
    under gravity for 1 s; then on a lighter planet with a heavier coupler. The loop stays
    closed in the FMU."""
    compiled, path = fmus["four_bar"]
    names = ["rev1.phi", "rev2.phi", "rev3.phi", "rev1.w", "rev3.w", "coupler.r[1]"]
    gap = ["rev4.frame_a.x", "rev4.frame_b.x", "rev4.frame_a.y", "rev4.frame_b.y"]
    x0 = {"rev1.phi": 1.0, "rev1.w": 2.0}
    res, logs = run_fmu(path, 1.0, 0.01, names + gap, x0)
    ref = run_in_process(compiled, 1.0, 100, x0=x0)
    assert_agree(res, ref, names)
    assert any("close the kinematic loops" in m for m in logs)
    closure = np.hypot(res["rev4.frame_a.x"] - res["rev4.frame_b.x"],
                       res["rev4.frame_a.y"] - res["rev4.frame_b.y"])
    assert np.max(closure) < 1e-8
    params = {"world.g": 3.7, "coupler.m": 2.0}
    res2, _ = run_fmu(path, 1.0, 0.01, names, {**x0, **params})
    ref2 = run_in_process(compiled, 1.0, 100, x0=x0, params=params)
    assert_agree(res2, ref2, names)
    assert changed(res2, res, "rev1.phi")


def test_drivetrain(fmus):
    """Supply ramp (ends at 0.5 s) and load step (2.5 s): time events inside the FMU; then
    another gear ratio and the load step moved to 1.2 s (events follow the parameters)."""
    compiled, path = fmus["drivetrain"]
    names = ["motor.phi", "drum.w", "motor.i", "speed", "shaftTorque.tau"]
    res, _ = run_fmu(path, 3.0, 0.02, names)
    ref = run_in_process(compiled, 3.0, 150)
    assert_agree(res, ref, names)
    params = {"gear.ratio": 8.0, "extraLoad.startTime": 1.2}
    res2, _ = run_fmu(path, 3.0, 0.02, names, params)
    ref2 = run_in_process(compiled, 3.0, 150, params=params)
    assert_agree(res2, ref2, names)
    assert changed(res2, res, "drum.w") and changed(res2, res, "motor.i")
    # the output is the drum speed; der(drum.phi) is the drum speed too
    d, _ = run_fmu(path, 0.2, 0.02, ["speed", "drum.w", "der(drum.phi)"])
    assert np.allclose(d["speed"], d["drum.w"], rtol=0, atol=1e-12)
    assert np.allclose(d["der(drum.phi)"], d["drum.w"], rtol=0, atol=1e-12)


# ---- errors, FMU state, termination ---------------------------------------------------------
def test_errors_are_statuses_with_messages(fmus):
    """A failed solve (a NaN input), a bad parameter value (a negative mass) and a linkage
    that cannot be assembled end the simulation with fmi2Discard at the first step and a
    logged message (pythonfmu has no fmi2Error for Python code: an exception would be
    fmi2Fatal); the importer lives on and the FMU simulates normally afterwards."""
    _, path = fmus["crane"]
    res, logs = run_fmu(path, 0.1, 0.01, ["rail.s"], {"F": float("nan")})
    assert res["time"][-1] == 0.0
    assert any("solver failed in the step from t = 0" in m for m in logs)
    res, logs = run_fmu(path, 0.1, 0.01, ["rail.s"], {"cart.m": -1.0})
    assert res["time"][-1] == 0.0
    assert any("parameter 'cart.m' must be > 0" in m for m in logs)
    # a linkage that cannot be assembled (coupler and rocker 0.1 m long cannot span the
    # ≥ 0.7 m from the crank tip to the rocker pivot): the in-process simulation raises
    # InitializationError
    short = {f"{link}_{end}.r[1]": 0.05 for link in ("coupler", "rocker") for end in "ab"}
    res, logs = run_fmu(fmus["four_bar"][1], 0.1, 0.01, ["rev1.phi"], short)
    assert res["time"][-1] == 0.0
    with pytest.raises(acausal.InitializationError) as err:
        fmus["four_bar"][0].simulate(0.1, params=short)
    message = str(err.value)            # the in-process message, naming the open loop rows
    assert message.startswith("cannot find initial values satisfying loop constraint rev4.")
    assert any(m == f"initialization failed: {message.replace('x0', 'start')}" for m in logs)
    res, _ = run_fmu(path, 0.1, 0.01, ["rail.s"], {"F": 1.0})
    assert res["time"][-1] == pytest.approx(0.1)
    # at rest with the load hanging straight the load pulls on the cart only once the rope
    # swings: the cart starts with acceleration F/M, s ≈ F t²/(2M) (M = 5 kg)
    assert res["rail.s"][1] == pytest.approx(1.0 * 0.01 ** 2 / (2 * 5.0), rel=1e-3)


def test_fmu_state_get_set(fmus, tmp_path):
    """fmi2GetFMUstate / SetFMUstate / serialization: stepping again from a saved state gives
    the same result."""
    from fmpy import extract
    from fmpy.fmi2 import FMU2Slave
    compiled, path = fmus["crane"]
    md = read_model_description(str(path))
    assert md.coSimulation.canGetAndSetFMUstate and md.coSimulation.canSerializeFMUstate
    vr = {v.name: v.valueReference for v in md.modelVariables}
    unzipped = extract(str(path), unzipdir=str(tmp_path / "unzipped"))
    fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipped,
                    modelIdentifier=md.coSimulation.modelIdentifier, instanceName="crane")
    fmu.instantiate()
    fmu.setupExperiment(startTime=0.0)
    fmu.enterInitializationMode()
    fmu.setReal([vr["hinge.phi"], vr["F"]], [0.2, 1.0])
    fmu.exitInitializationMode()
    t = 0.0
    for _ in range(10):
        fmu.doStep(t, 0.01)
        t += 0.01
    saved, t_saved = fmu.serializeFMUstate(fmu.getFMUstate()), t
    for _ in range(10):
        fmu.doStep(t, 0.01)
        t += 0.01
    first = fmu.getReal([vr["rail.s"], vr["hinge.phi"]])
    fmu.setFMUstate(fmu.deSerializeFMUstate(saved))
    t = t_saved
    for _ in range(10):
        fmu.doStep(t, 0.01)
        t += 0.01
    again = fmu.getReal([vr["rail.s"], vr["hinge.phi"]])
    fmu.terminate()
    fmu.freeInstance()
    assert again == first
    ref = run_in_process(compiled, 0.2, 20, {"F": (1.0, 1.0, 1.0)}, x0={"hinge.phi": 0.2})
    assert first[1] == pytest.approx(ref["hinge.phi"][-1], rel=RTOL)


def test_importer_exits_cleanly(fmus):
    """A fresh Python process without acausal (importing it fails there) loads, simulates
    and releases the FMU, then exits with 0."""
    _, path = fmus["four_bar"]
    code = ("import sys\n"
            "sys.modules['acausal'] = None\n"
            "from fmpy import simulate_fmu\n"
            f"r = simulate_fmu({str(path)!r}, stop_time=0.05, output_interval=0.01,"
            " output=['rev1.phi'], start_values={'rev1.phi': 1.0})\n"
            "print(len(r))\n")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == "6"


def test_only_fmi2_cosimulation(fmus, tmp_path):
    compiled, _ = fmus["drivetrain"]
    with pytest.raises(acausal.AcausalError, match="FMI 2.0"):
        export_pythonfmu(compiled, tmp_path / "x.fmu", fmi_version="3.0")
    with pytest.raises(acausal.AcausalError, match="co-simulation"):
        export_pythonfmu(compiled, tmp_path / "x.fmu", fmu_type="me")


def test_through_export_fmu(fmus, tmp_path):
    """compiled.export_fmu(..., backend='pythonfmu') goes through the dispatcher to this
    backend."""
    compiled, _ = fmus["drivetrain"]
    path = compiled.export_fmu(tmp_path / "drive.fmu", backend="pythonfmu", fmu_type="cs")
    assert validate_fmu(str(path)) == []
    md = read_model_description(str(path))
    assert md.generationTool.startswith("PythonFMU") and md.modelExchange is None
    res, _ = run_fmu(path, 1.0, 0.05, ["drum.w"])
    ref = run_in_process(compiled, 1.0, 20)
    assert_agree(res, ref, ["drum.w"])


def test_redundant_loop_rows_are_switched_off(tmp_path):
    """A double parallelogram (a redundant fifth link): the FMU sets its loop-row switches
    (calculated parameters) in initialization as simulate() does, one redundant row off, and
    moves as the in-process simulation from the same assembly (0.25 s, before the collinear
    configuration where the rows left on lose rank)."""
    compiled = acausal.compile(Parallelogram("double_parallelogram", fifth_link=True))
    path = export_pythonfmu(compiled, tmp_path / "double_parallelogram.fmu")
    assert validate_fmu(str(path)) == []
    ref = run_in_process(compiled, 0.25, 100, x0={"rev1.phi": 1.0, "rev1.w": 1.0},
                         guess={"rev2.phi": -1.0, "rev3.phi": 1.0, "rev5.phi": 1.0})
    assert len(ref.mobility.redundant) == 1
    switches = [f"loops.active_{i}" for i in range(len(compiled.loop_rows))]
    res, _ = run_fmu(path, 0.25, 0.0025, ["rev1.phi", "rev5.phi", *switches],
                     {n: float(ref[n][0]) for n in compiled.x_names})
    for n in ("rev1.phi", "rev5.phi"):
        assert np.max(np.abs(res[n] - ref[n])) < RTOL * np.max(np.abs(ref[n])), n
    off = compiled.loop_rows.index(ref.mobility.redundant[0])
    assert [res[n][0] for n in switches] == [float(i != off) for i in range(len(switches))]
