"""Native FMUs carry the model's initial equations and termination conditions.

Initial equations (``PhysicsBuilder.initial``: InitializeFlange's start angle, speed and
acceleration; MSL's Motor started in steady state, der(C.v) = 0, der(La.i) = 0) hold at
exitInitializationMode as in-process (``initial_state(..., initial_equations=True)``, the
start of compiled.simulate): the start state equals simulate()'s to 1e-10, a start value the
importer sets is held as simulate()'s x0, and the trajectory equals simulate()'s and the
closed form, in fmpy and the Reference FMUs' fmusim, FMI 2.0 and 3.0, model exchange and
co-simulation. Initial equations that cannot hold are fmiError naming them.

Termination (Modelica.Blocks.Logical.TerminateSimulation): an inertia (2 kg·m²) under 3 N·m
from rest, to end when its speed exceeds 4.5 rad/s: at t = 4.5·2/3 = 3 s. Model exchange
ends there (terminateSimulation from the event update), co-simulation's doStep stops at it
(FMI 2: fmi2Discard, fmi2Terminated, fmi2LastSuccessfulTime; FMI 3: terminateSimulation,
earlyReturn, lastSuccessfulTime), the component's text logged. MSL's RobotR3.OneAxis, whose
motor starts in steady state, ends at a time event: path end time + swingTime =
2·0.3 + (2π/3 − 0.9)/3 + 0.5 s (KinematicPTP2 to 120° at 3 rad/s, 10 rad/s²). The FMU
Compliance Checker passes the FMUs (FMI 2.0).

The models:
- spin: an inertia J = 2 kg·m² on a damper d = 0.5 N·m·s/rad to the ground, started at
  0.3 rad and 0.7 rad/s: w = 0.7·e^(−t/4), φ = 0.3 + 2.8·(1 − e^(−t/4));
- wound: the inertia on a spring c = 100 N·m/rad to the ground, started with the
  acceleration −5 rad/s² (the angle follows: φ0 = J·5/c = 0.1 rad) at the speed the
  importer sets, w0 = 0.5 rad/s: φ = 0.1·cos(ωt) + (w0/ω)·sin(ωt), ω = √(c/J);
- held_motor: MSL's Motor (RobotR3) with its rotor held and a reference current of 2 A,
  algebraic variables (its op-amps' currents) in its initial equations: La.i = 2 A and
  C.v = −250·2/5 = −100 V throughout (tests/components/test_robot_axis.py);
- four_bar: the four-bar linkage (models/linkages.py) whose crank InitializeFlange starts at
  1 rad and 2 rad/s: the initial equations and the loop constraints in one projection (no
  closed form; simulate() is the reference).
"""
from __future__ import annotations

import math
import re
import warnings

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")
from fmpy.fmi1 import FMICallException                             # noqa: E402
from fmpy.fmi2 import fmi2Discard, fmi2LastSuccessfulTime, fmi2Terminated  # noqa: E402

import acausal                                                     # noqa: E402
from acausal.components import rotational as rot                   # noqa: E402
from acausal.components import signals as sig                      # noqa: E402
from acausal.errors import FmuExportError                          # noqa: E402
from acausal.models import FourBar                                 # noqa: E402
from acausal.models.robot_axis import STOP_TIME, Motor, OneAxis    # noqa: E402
from fast_spin import fast_enough                                  # noqa: E402
from fmi_calls import init, instance                               # noqa: E402
from importers import fmu_check, fmusim                             # noqa: E402
from wiring import model                                           # noqa: E402

VERSIONS = ("2.0", "3.0")
START_TOL = 1e-10     # the start state against simulate()'s, relative to max(1, |value|)
RTOL = 1e-6           # trajectories, of each signal's peak, as test_native.py (tolerance 1e-10)
CLOSED_TOL = 1e-8     # simulate() (tolerance 1e-12) against the closed forms, of the peak
END_TOL = 1e-9        # [s], the termination's time against its closed form
OMEGA = math.sqrt(50.0)


def spin():
    return model("spin", lambda m: [(m.damper.flange_a, m.fixed.flange),
                                    (m.damper.flange_b, m.inertia.flange_b),
                                    (m.init.flange, m.inertia.flange_b),
                                    (m.phi0.y, m.init.phi_start), (m.w0.y, m.init.w_start)],
                 fixed=rot.Fixed(), inertia=rot.Inertia(J=2.0), damper=rot.Damper(d=0.5),
                 init=rot.InitializeFlange(use_a_start=False), phi0=sig.Constant(k=0.3),
                 w0=sig.Constant(k=0.7))


def wound():
    return model("wound", lambda m: [(m.fixed.flange, m.spring.flange_a),
                                     (m.spring.flange_b, m.inertia.flange_a),
                                     (m.init.flange, m.inertia.flange_b),
                                     (m.a0.y, m.init.a_start)],
                 fixed=rot.Fixed(), spring=rot.Spring(c=100.0), inertia=rot.Inertia(J=2.0),
                 init=rot.InitializeFlange(use_phi_start=False, use_w_start=False),
                 a0=sig.Constant(k=-5.0))


def held_motor():
    return model("held_motor", lambda m: [(m.ref.y, m.motor.current_ref),
                                          (m.motor.flange_motor, m.fixed.flange)],
                 ref=sig.Constant(k=2.0), motor=Motor(), fixed=rot.Fixed())


class StartedFourBar(FourBar):
    def __init__(self):
        super().__init__("four_bar", crank_flange=True)
        self.init = rot.InitializeFlange(use_a_start=False)
        self.phi0, self.w0 = sig.Constant(k=1.0), sig.Constant(k=2.0)
        self.connect(self.init.flange, self.rev1.axis)
        self.connect(self.phi0.y, self.init.phi_start)
        self.connect(self.w0.y, self.init.w_start)


# name: (model, stop time [s], output interval [s], start values set, closed form t -> {name:
# values})
CASES = {
    "spin": (spin, 3.0, 0.01, {},
             lambda t: {"inertia.w": 0.7 * np.exp(-t / 4),
                        "inertia.phi": 0.3 + 2.8 * (1 - np.exp(-t / 4))}),
    "wound": (wound, 1.0, 0.01, {"inertia.w": 0.5},
              lambda t: {"inertia.phi": 0.1 * np.cos(OMEGA * t) + 0.5 / OMEGA * np.sin(OMEGA * t),
                         "inertia.w": -0.1 * OMEGA * np.sin(OMEGA * t) + 0.5 * np.cos(OMEGA * t)}),
    "held_motor": (held_motor, 0.01, 1e-4, {},
                   lambda t: {"motor.La.i": np.full_like(t, 2.0),
                              "motor.C.v": np.full_like(t, -100.0)}),
    "four_bar": (StartedFourBar, 1.0, 0.01, {}, lambda t: {}),
}
T_END = 3.0           # fast_enough's termination [s]


@pytest.fixture(scope="module")
def fmus(fmu_dir):
    out = {}
    for name, (make, T, dt, x0, _) in CASES.items():
        compiled = acausal.compile(make())
        grid = np.linspace(0.0, T, int(round(T / dt)) + 1)
        with warnings.catch_warnings():     # the four-bar's states moved to close the loop
            warnings.simplefilter("ignore")
            out[name] = compiled, compiled.simulate(T, t=grid, x0=x0, rtol=1e-12, atol=1e-14)
        for v in VERSIONS:
            out[name, v] = compiled.export_fmu(fmu_dir / f"{name}{v[0]}.fmu", fmi_version=v,
                                               stop_time=T)
    compiled = acausal.compile(fast_enough())
    out["fast_enough"] = compiled
    for v in VERSIONS:
        out["fast_enough", v] = compiled.export_fmu(fmu_dir / f"fast_enough{v[0]}.fmu",
                                                    fmi_version=v, stop_time=10.0)
    return out


def check(name, fmus, t, get):
    """The start state against simulate()'s (START_TOL), every state's trajectory against
    simulate()'s (RTOL of its peak), simulate()'s against the closed form (CLOSED_TOL)."""
    compiled, ref = fmus[name]
    _, T, dt, _, closed = CASES[name]
    grid = np.linspace(0.0, T, int(round(T / dt)) + 1)
    idx = np.searchsorted(t, grid + 1e-9 * T, side="right") - 1
    assert np.allclose(t[idx], grid, rtol=0, atol=1e-9 * T)
    for n in compiled.x_names:
        got, want = np.asarray(get(n)), ref[n]
        assert abs(got[0] - want[0]) <= START_TOL * max(1.0, abs(want[0])), (name, n, got[0],
                                                                             want[0])
        peak = max(np.max(np.abs(want)), 1e-300)
        assert np.max(np.abs(got[idx] - want)) < RTOL * peak, (name, n)
    for n, values in closed(grid).items():
        assert np.max(np.abs(ref[n] - values)) < CLOSED_TOL * np.max(np.abs(values)), (name, n)


def test_simulate_starts_on_the_closed_forms(fmus):
    """The reference itself: simulate()'s start state and trajectory are the closed forms'."""
    for name, (_, T, dt, _, closed) in CASES.items():
        ref = fmus[name][1]
        for n, values in closed(ref.t).items():
            assert abs(ref[n][0] - values[0]) <= START_TOL * max(1.0, abs(values[0])), (name, n)
            assert np.max(np.abs(ref[n] - values)) < CLOSED_TOL * np.max(np.abs(values)), \
                (name, n)


@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("name", list(CASES))
def test_fmpy_starts_where_simulate_starts(fmus, name, version, kind):
    _, T, dt, x0, _ = CASES[name]
    r = fmpy.simulate_fmu(str(fmus[name, version]), fmi_type=kind, stop_time=T,
                          output_interval=dt, start_values=x0, relative_tolerance=1e-10,
                          output=fmus[name][0].x_names)
    check(name, fmus, r["time"], lambda n: r[n])


@pytest.mark.parametrize("kind", ["me", "cs"])
@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("name", list(CASES))
def test_fmusim_starts_where_simulate_starts(fmus, name, version, kind, tmp_path):
    _, T, dt, x0, _ = CASES[name]
    res = fmusim(fmus[name, version], kind, T, dt, x0, fmus[name][0].x_names, tmp_path,
                 early_return=True)
    check(name, fmus, res["time"], lambda n: res[n])


@pytest.mark.parametrize("version", VERSIONS)
def test_initial_equations_that_cannot_hold_are_named(fmus, version, capsys):
    """The importer sets the angle that InitializeFlange's phi_start fixes otherwise: as
    simulate(x0=...) refuses it, the FMU's initialization fails naming the equation and the
    start value set."""
    fmu, vr, md = instance(fmus["spin", version])
    with pytest.raises(FMICallException, match="status 3"):
        init(fmu, md, {"inertia.phi": 1.0}, vr)
    log = capsys.readouterr().out
    assert re.search(r"initialization: the initial equations cannot be satisfied \(not "
                     r"satisfied: init: flange.phi = phi_start\).*\(inertia.phi = 1\)", log), log


# ---- termination ------------------------------------------------------------------------------
@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
@pytest.mark.parametrize("version", VERSIONS)
def test_fmpy_ends_at_the_termination(fmus, version, kind, capsys):
    """fmpy stops where the termination condition holds, at the closed form's 3 s with the
    speed at its threshold 4.5 rad/s; the FMU logs the block's text."""
    r = fmpy.simulate_fmu(str(fmus["fast_enough", version]), fmi_type=kind, stop_time=10.0,
                          output_interval=0.1, relative_tolerance=1e-10,
                          output=["inertia.w"], early_return_allowed=True)
    assert abs(r["time"][-1] - T_END) < END_TOL, r["time"][-1]
    assert abs(r["inertia.w"][-1] - 4.5) < 1e-8
    assert np.max(np.abs(r["inertia.w"] - 1.5 * r["time"])) < 1e-8
    log = capsys.readouterr().out
    assert re.search(r"terminated at t = 3(\.0+\d*)? s by 'stop': fast enough", log), log


@pytest.mark.parametrize("version", VERSIONS)
def test_do_step_reports_the_termination(fmus, version):
    """One doStep over [0, 10] s ends at the event, 3 s: FMI 2 returns fmi2Discard, then
    fmi2Terminated is true and fmi2LastSuccessfulTime is 3 s; FMI 3 returns
    terminateSimulation and earlyReturn with lastSuccessfulTime 3 s. Another doStep is
    refused."""
    path = fmus["fast_enough", version]
    if version == "2.0":
        fmu, vr, md = instance(path, cs=True)
        init(fmu, md)
        with pytest.raises(FMICallException) as e:
            fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=10.0)
        assert e.value.status == fmi2Discard
        assert fmu.getBooleanStatus(fmi2Terminated)
        end = fmu.getRealStatus(fmi2LastSuccessfulTime)
        w = fmu.getReal([vr["inertia.w"]])[0]
    else:
        fmu, vr, md = instance(path, cs=True, earlyReturnAllowed=True)
        init(fmu, md)
        _, terminate, early, end = fmu.doStep(currentCommunicationPoint=0.0,
                                              communicationStepSize=10.0)
        assert terminate and early
        w = fmu.getFloat64([vr["inertia.w"]])[0]
    assert abs(end - T_END) < END_TOL and abs(w - 4.5) < 1e-8
    with pytest.raises(FMICallException, match="status 3"):
        fmu.doStep(currentCommunicationPoint=end, communicationStepSize=1.0)
    fmu.terminate()
    fmu.freeInstance()


@pytest.fixture(scope="module")
def one_axis(fmu_dir):
    compiled = acausal.compile(OneAxis())
    grid = np.linspace(0.0, STOP_TIME, 1601)
    ref = compiled.simulate(STOP_TIME, t=grid, rtol=1e-12, atol=1e-14)
    return compiled, ref, {v: compiled.export_fmu(fmu_dir / f"one_axis{v[0]}.fmu",
                                                  fmi_version=v, stop_time=STOP_TIME)
                           for v in VERSIONS}


@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
@pytest.mark.parametrize("version", VERSIONS)
def test_one_axis_ends_at_its_time_event(one_axis, version, kind):
    """OneAxis in fmpy ends at the closed form's end time, the start state and the states at
    the output points before it (right limits) as simulate()'s."""
    compiled, ref, paths = one_axis
    end = 0.6 + (2 * math.pi / 3 - 0.9) / 3 + 0.5
    assert abs(ref.terminated.time - end) < END_TOL
    r = fmpy.simulate_fmu(str(paths[version]), fmi_type=kind, stop_time=STOP_TIME,
                          output_interval=1e-3, relative_tolerance=1e-10,
                          output=compiled.x_names, early_return_allowed=True)
    assert abs(r["time"][-1] - end) < END_TOL, r["time"][-1]
    grid = np.linspace(0.0, STOP_TIME, 1601)
    grid = grid[grid < end]
    idx = np.searchsorted(r["time"], grid + 1e-9, side="right") - 1
    ridx = np.searchsorted(ref.t, grid + 1e-9, side="right") - 1
    for n in compiled.x_names:
        assert abs(r[n][0] - ref[n][0]) <= START_TOL, n
        peak = max(np.max(np.abs(ref[n])), 1e-300)
        assert np.max(np.abs(r[n][idx] - ref[n][ridx])) < RTOL * peak, n


@pytest.mark.parametrize("kind", ["me", "cs"])
@pytest.mark.parametrize("version", VERSIONS)
def test_fmusim_ends_at_the_termination(fmus, version, kind, tmp_path):
    res = fmusim(fmus["fast_enough", version], kind, 10.0, 0.1, {}, ["inertia.w"], tmp_path,
                 early_return=True)
    assert abs(res["time"][-1] - T_END) < END_TOL, res["time"][-1]
    assert abs(res["inertia.w"][-1] - 4.5) < 1e-8


def test_pythonfmu_refuses_them_and_points_at_the_native_backend(fmus, fmu_dir):
    with pytest.raises(FmuExportError, match=r"init: flange.phi.*backend='native'"):
        fmus["spin"][0].export_fmu(fmu_dir / "spin_py.fmu", backend="pythonfmu")


# ---- the independent importers ----------------------------------------------------------------
@pytest.mark.parametrize("name", ["spin", "held_motor", "fast_enough"])
@pytest.mark.parametrize("kind", ["me", "cs"])
def test_fmu_compliance_checker(fmus, name, kind, tmp_path):
    """FMI 2.0: the checker finds nothing, and its results start where simulate() starts
    (spin, held_motor) or end at the termination (fast_enough; the checker writes its last
    row at the output point after it, in co-simulation with the values at the termination)."""
    T, dt = (10.0, 0.1) if name == "fast_enough" else CASES[name][1:3]
    h = dt if kind == "cs" else dt / 10
    res = fmu_check(fmus[name, "2.0"], kind, T, h, int(round(T / dt)), tmp_path / "out.csv")
    if name == "fast_enough":     # its last row is the output point after the termination
        assert T_END - END_TOL < res["time"][-1] <= T_END + dt + END_TOL, res["time"][-1]
        if kind == "cs":          # the values at the termination
            assert abs(res["inertia.w"][-1] - 4.5) < 1e-8
        return
    compiled, ref = fmus[name]
    for n in compiled.x_names:
        assert abs(res[n][0] - ref[n][0]) <= START_TOL * max(1.0, abs(ref[n][0])), (name, n)
