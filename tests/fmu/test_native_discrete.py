"""Native FMUs of models with sample triggers, discrete Real variables and relations reproduce
compiled.simulate (acausal.simulation.events) in two independent importers, fmpy and the
Reference FMUs' fmusim, FMI 2.0 and 3.0, model exchange and co-simulation: every signal
within 1e-6 of its peak at every output point (the right limits at events), the discrete
values equal, and the event instants within 1e-6 s (model exchange: from the importer's rows
at the events). The sample instants are time events (nextEventTime; co-simulation stops at
them); at each the FMU's event iteration runs with the trigger true, then once more false,
and rounds only the Integer/Boolean modes.

The models: a ramp 0.5 + 0.2·t through a ZeroOrderHold (every 0.25 s from 0.105 s) and a
Sampler into a UnitDelay (every 0.2 s) — the hold is also checked against the exact
staircase and the delay against the ramp one instant late; the sampled P controller on a
mass (models/event_blocks.py; its exact discretization is checked in
tests/components/test_event_blocks.py); the thermostat with a Hysteresis and with an
OnOffController (a relation's state events; its switching times are logarithms); edges of
a Boolean pulse latched by an RSFlipFlop into a TransferFunction, and a Timer; MSL's
CoupledClutches (models/clutches.py; three clutches sticking and slipping, 1.5 s); a
discrete TransferFunction controlling a first-order plant through a ZeroOrderHold, with a
discrete StateSpace, a FirstOrderHold, a TriggeredSampler and a TriggeredMax on a sine (their
numbers against numpy recursions, lfilter and dlsim in
tests/components/test_discrete_blocks.py).
"""
from __future__ import annotations

import re

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")
from fmpy.fmi1 import FMICallException                                   # noqa: E402

import acausal                                                            # noqa: E402
from acausal.components import discrete as dc                            # noqa: E402
from acausal.components import logical as lg                             # noqa: E402
from acausal.components import signals as sg                             # noqa: E402
from acausal.errors import FmuExportError                                # noqa: E402
from acausal.models import CoupledClutches, SampledPController, Thermostat  # noqa: E402
from acausal.models.clutches import START as CLUTCHES_START              # noqa: E402
from fmi_calls import init, instance                                     # noqa: E402
from importers import fmu_check, fmusim                                   # noqa: E402
from test_native_events import EVENT_TOL, RTOL, VERSIONS, at, mode_changes  # noqa: E402

RAMP = (0.5, 0.2)              # offset, slope [1/s]
HOLD = (0.105, 0.25)           # the ZeroOrderHold's first instant and period [s]
DELAY = 0.2                    # the UnitDelay's period [s]


def hold() -> acausal.Model:
    m = acausal.Model("hold")
    m.ramp = sg.Ramp(height=RAMP[1] * 10.0, duration=10.0, offset=RAMP[0])
    m.zoh = dc.ZeroOrderHold(startTime=HOLD[0], samplePeriod=HOLD[1])
    m.smp, m.dly = dc.Sampler(samplePeriod=DELAY), dc.UnitDelay(samplePeriod=DELAY)
    for a, b in [(m.ramp.y, m.zoh.u), (m.ramp.y, m.smp.u), (m.smp.y, m.dly.u)]:
        m.connect(a, b)
    return m


def edges() -> acausal.Model:
    """Edges of a pulse set and reset a flip flop whose output drives a TransferFunction;
    a Timer measures the pulse."""
    m = acausal.Model("edges")
    m.pulse = lg.BooleanPulse(width=30.0, period=0.7, startTime=0.15)
    m.rise, m.fall, m.ff = lg.Edge(), lg.FallingEdge(), lg.RSFlipFlop()
    m.to_real, m.timer = lg.BooleanToReal(), lg.Timer()
    m.tf = sg.TransferFunction(b=[1.0, 2.0], a=[0.5, 1.0, 3.0], x_start=[0.2, -0.1])
    for a, b in [(m.pulse.y, m.rise.u), (m.pulse.y, m.fall.u), (m.fall.y, m.ff.S),
                 (m.rise.y, m.ff.R), (m.ff.Q, m.to_real.u), (m.to_real.y, m.tf.u),
                 (m.pulse.y, m.timer.u)]:
        m.connect(a, b)
    return m


def discrete_blocks() -> acausal.Model:
    """A discrete PI, C(z) = (0.6 z − 0.4)/(z − 1) every 0.1 s, holds the input of a plant
    1/(s + 1) tracking 1; a discrete StateSpace and a FirstOrderHold (every 0.25 s from
    0.02 s) sample a sine, a TriggeredSampler and a TriggeredMax take it at the rising edges
    of a pulse."""
    m = acausal.Model("discrete_blocks")
    m.ref, m.fb = sg.Constant(k=1.0), sg.Feedback()
    m.ctrl = dc.TransferFunction(b=[0.6, -0.4], a=[1.0, -1.0], samplePeriod=0.1)
    m.zoh, m.plant = dc.ZeroOrderHold(samplePeriod=0.1), sg.FirstOrder(k=1.0, T=1.0)
    m.sine = sg.Sine(amplitude=1.3, f=0.7, offset=0.3)
    m.ss = dc.StateSpace(A=[[0.5, 0.1], [-0.2, 0.8]], B=[[1.0], [0.5]], C=[[1.0, -1.0]],
                         D=[[0.3]], samplePeriod=0.1, x_start=[0.2, -0.1])
    m.foh = dc.FirstOrderHold(samplePeriod=0.25, startTime=0.02)
    m.pulse = lg.BooleanPulse(width=40.0, period=0.3, startTime=0.1)
    m.ts, m.tm = dc.TriggeredSampler(y_start=2.0), dc.TriggeredMax()
    for a, b in [(m.ref.y, m.fb.u1), (m.plant.y, m.fb.u2), (m.fb.y, m.ctrl.u),
                 (m.ctrl.y, m.zoh.u), (m.zoh.y, m.plant.u), (m.sine.y, m.ss.u[1]),
                 (m.sine.y, m.foh.u), (m.sine.y, m.ts.u), (m.sine.y, m.tm.u),
                 (m.pulse.y, m.ts.trigger), (m.pulse.y, m.tm.trigger)]:
        m.connect(a, b)
    return m


CLUTCHES = ["J1.w", "J2.w", "J3.w", "J4.w", "J1.phi", "J4.phi", "clutch1.tau", "clutch2.tau",
            "clutch3.tau"]
# name: (model, stop time [s] (no sample instant there), output interval [s], start values,
#        signals, discrete values whose changes are the events)
CASES = {
    "hold": (hold, 2.9, 0.01, {}, ["ramp.y"], ["zoh.y", "smp.y", "dly.y"]),
    "sampled": (SampledPController, 2.05, 0.01, {"mass.s": 0.2}, ["mass.s", "mass.v"],
                ["smp.y", "zoh.ySample"]),
    "thermostat": (lambda: Thermostat(kind="Hysteresis"), 12.0, 0.01, {},
                   ["plant.y", "heater.y"], ["ctrl.y"]),
    "on_off": (Thermostat, 12.0, 0.01, {}, ["plant.y", "heater.y"], ["ctrl.y"]),
    "edges": (edges, 2.9, 0.01, {}, ["tf.y", "tf.x[1]", "timer.y"], ["ff.pre.y"]),
    "clutches": (CoupledClutches, 1.5, 0.001, CLUTCHES_START, CLUTCHES,
                 ["clutch1.mode", "clutch2.mode", "clutch3.mode"]),
    "discrete_blocks": (discrete_blocks, 2.05, 0.01, {}, ["plant.y", "foh.y"],
                        ["ctrl.y", "ctrl.x[1]", "ss.y[1]", "ss.x[2]", "ts.y", "tm.y"]),
}


def grid_of(name) -> np.ndarray:
    _, T, dt, *_ = CASES[name]
    return np.linspace(0.0, T, int(round(T / dt)) + 1)


@pytest.fixture(scope="module")
def fmus(fmu_dir):
    out = {}
    for name, (make, T, _, x0, _, _) in CASES.items():
        compiled = acausal.compile(make())
        out[name] = compiled.simulate(T, t=grid_of(name), x0=x0, rtol=1e-12, atol=1e-14)
        for v in VERSIONS:
            out[name, v] = compiled.export_fmu(fmu_dir / f"{name}{v[0]}.fmu", fmi_version=v,
                                               stop_time=T)
    return out


def check(name, ref, t, get, model_exchange, grid=None):
    """Every signal within RTOL of its peak and every discrete value within RTOL of its peak
    at the output points (right limits; at an output point within EVENT_TOL of a state
    event of simulate(), such as clutch1's release at 1.25 s or the clutches' mode changes
    just after a time event, any of simulate()'s rows within EVENT_TOL: the FMU's
    hysteresis puts a crossing 1e-10/|dg/dt| s later, on the other side of the point); in
    model exchange the instants where the discrete values change within EVENT_TOL of
    simulate()'s."""
    *_, signals, discrete = CASES[name]
    grid = grid_of(name) if grid is None else grid
    crossings = np.array([ev.time for ev in ref.events if ev.indicator])
    near = [np.flatnonzero(np.abs(ref.t - g) < EVENT_TOL)
            if np.any(np.abs(crossings - g) < EVENT_TOL) else [] for g in grid]
    for n in signals + discrete:
        got, want = at(t, get(n), grid), np.asarray(ref[n])
        e = np.abs(got - at(ref.t, want, grid))
        for k, rows in enumerate(near):
            if len(rows):
                e[k] = min(e[k], np.min(np.abs(got[k] - want[rows])))
        assert np.max(e) <= RTOL * np.max(np.abs(want)), (name, n, np.max(e))
    if model_exchange:
        for n in discrete:
            got, want = mode_changes(t, get(n)), mode_changes(ref.t, ref[n])
            assert len(want) > 0 and len(got) == len(want), (name, n, got, want)
            assert np.max(np.abs(got - want)) < EVENT_TOL, (name, n, got - want)


def test_the_references_are_the_closed_forms(fmus):
    """simulate() itself: the hold is the exact staircase ramp(t_k) (0 before 0.105 s), the
    delayed samples the ramp at the previous instant 0.2·(k − 1) (0 until 0.2 s), the thermostat
    switches at the logarithms of its first-order plant, heated from 0 to 6, cooled to 4."""
    ref, grid = fmus["hold"], grid_of("hold")
    ramp = lambda s: RAMP[0] + RAMP[1] * s                                # noqa: E731
    k = np.floor((grid - HOLD[0]) / HOLD[1] + 1e-9)
    staircase = np.where(k < 0, 0.0, ramp(HOLD[0] + HOLD[1] * k))
    np.testing.assert_allclose(at(ref.t, ref["zoh.y"], grid), staircase, rtol=0, atol=1e-14)
    k = np.floor(grid / DELAY + 1e-9)
    delayed = np.where(k < 1, 0.0, ramp(DELAY * (k - 1)))
    np.testing.assert_allclose(at(ref.t, ref["dly.y"], grid), delayed, rtol=0, atol=1e-14)
    heat, cool = 2.0 * np.log((10.0 - 4.0) / (10.0 - 6.0)), 2.0 * np.log(6.0 / 4.0)
    first = -2.0 * np.log(1 - 6.0 / 10.0)
    for name in ("thermostat", "on_off"):
        switches = mode_changes(fmus[name].t, fmus[name]["ctrl.y"])
        assert len(switches) == 13
        expected = first + np.cumsum([0.0] + [cool, heat] * 6)[:13]
        np.testing.assert_allclose(switches, expected, rtol=0, atol=1e-9)


@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("name", list(CASES))
def test_fmpy_reproduces_simulate_with_its_samples(fmus, name, version, kind):
    """fmpy (CVODE for model exchange, the FMU's RODAS4 in co-simulation), tolerance 1e-10."""
    _, T, dt, x0, signals, discrete = CASES[name]
    r = fmpy.simulate_fmu(str(fmus[name, version]), fmi_type=kind, stop_time=T,
                          output_interval=dt, start_values=x0, relative_tolerance=1e-10,
                          output=signals + discrete)
    check(name, fmus[name], r["time"], lambda n: r[n], kind == "ModelExchange")


@pytest.mark.parametrize("kind", ["me", "cs"])
@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("name", list(CASES))
def test_fmusim_reproduces_simulate_with_its_samples(fmus, name, version, kind, tmp_path):
    """The Reference FMUs' fmusim (CVODE for model exchange), tolerance 1e-10: as fmpy."""
    _, T, dt, x0, signals, discrete = CASES[name]
    res = fmusim(fmus[name, version], kind, T, dt, x0, signals + discrete, tmp_path)
    check(name, fmus[name], res["time"], lambda n: res[n], kind == "me")


@pytest.mark.parametrize("name", list(CASES))
def test_fmu_compliance_checker(fmus, name, tmp_path):
    """FMI 2.0: the checker finds nothing in co-simulation, whose results are simulate()'s
    to 1e-6 of each signal's peak at its points (sums of the output interval, the sample
    instants to round-off: the FMU takes an instant within 1e-10 s of a communication point
    in the step ending there, its right limit), nor in model exchange (forward Euler,
    stopping at the time events), from the models' default starts (the checker sets
    none)."""
    make, T, dt, *_ = CASES[name]
    cs = fmu_check(fmus[name, "2.0"], "cs", T, dt, int(round(T / dt)), tmp_path / "cs.csv")
    grid = np.round(cs["time"], 9)              # the checker's points (it may skip one)
    ref = acausal.compile(make()).simulate(T, t=grid, rtol=1e-12, atol=1e-14)
    check(name, ref, cs["time"], lambda n: cs[n], False, grid)
    fmu_check(fmus[name, "2.0"], "me", T, 1e-3, int(round(T / 1e-3)), tmp_path / "me.csv")


# ---- errors -----------------------------------------------------------------------------------
def test_an_importer_stepping_over_a_sample_instant_gets_an_error_not_a_lost_sample(fmus,
                                                                                     capsys):
    """Model exchange, FMI 2.0: an event update at 0.3 s, past the hold's instant 0.105 s
    (and 0.2 s of the Sampler) that the importer did not stop at: fmiError naming the
    block, rather than a sample silently lost."""
    fmu, vr, md = instance(fmus["hold", "2.0"])
    init(fmu, md)
    fmu.newDiscreteStates()
    fmu.enterContinuousTimeMode()
    fmu.setTime(0.3)
    fmu.enterEventMode()
    with pytest.raises(FMICallException, match="status 3"):
        fmu.newDiscreteStates()
    log = capsys.readouterr().out
    assert re.search(r"the sample instant t = 0\.10\d* s of 'zoh' was passed without an "
                     r"event at it .*nextEventTime", log), log


def test_pythonfmu_refuses_sampled_models_and_points_at_the_native_backend(fmu_dir):
    compiled = acausal.compile(hold())
    with pytest.raises(FmuExportError, match=r"dly, smp, zoh.*backend='native'"):
        compiled.export_fmu(fmu_dir / "hold_py.fmu", backend="pythonfmu")
