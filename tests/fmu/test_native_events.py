"""Native FMUs of models with state events and discrete modes reproduce compiled.simulate
(acausal.simulation.events, the in-process engine) in two independent importers, fmpy and the
Reference FMUs' fmusim, FMI 2.0 and 3.0, model exchange (the importer's CVODE locates the
crossings of the FMU's event indicators; the FMU runs the reinits and the event iteration of
the modes in its event update) and co-simulation (the FMU locates the events inside its
steps): every signal within 1e-6 of its peak, and the event instants — the ball's impacts,
the clutch's, the brake's and the belt friction's mode changes (stick, slip) — within 1e-6 s.
The FMU Compliance Checker passes them (FMI 2.0), and an event iteration that never settles
fails with fmiError and a logged message naming the component.

The models: the bouncing ball (models/bouncing_ball.py), MSL's Rotational.Examples.Friction
(a clutch and a brake; models/friction.py, its START values) and a Coulomb stick-slip
oscillator: a mass on a spring to the wall, riding a belt at constant speed through a
SupportFriction whose breakaway force is 1.5 times the sliding force.
"""
from __future__ import annotations

import re

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")
from fmpy.fmi1 import FMICallException                             # noqa: E402

import acausal                                                     # noqa: E402
from acausal.components import translational as tr                 # noqa: E402
from acausal.core import Component, TranslationalFlange             # noqa: E402
from acausal.errors import FmuExportError                          # noqa: E402
from acausal.models.bouncing_ball import G, BouncingBall           # noqa: E402
from acausal.models.friction import START, RotationalFriction      # noqa: E402
from faulty_components import Relay, Toggle, on_a_mass             # noqa: E402
from fmi_calls import unzipped                                      # noqa: E402
from importers import fmu_check, fmusim                             # noqa: E402

VERSIONS = ("2.0", "3.0")
RTOL = 1e-6           # of each signal's peak
EVENT_TOL = 1e-6      # [s], event instants


def stick_slip() -> acausal.Model:
    """A mass (1 kg) on a spring (4 N/m) to the wall, carried by a belt at 0.12 m/s through
    Coulomb friction (1 N sliding, 1.5 N breakaway): stuck to the belt until the spring pulls
    1.5 N, then slipping back until it moves with the belt again, and again."""
    m = acausal.Model("stick_slip")
    m.wall, m.spring, m.mass = tr.Fixed(), tr.Spring(c=4.0), tr.Mass(m=1.0)
    m.belt = tr.ConstantSpeed(v_fixed=0.12)
    m.friction = tr.SupportFriction(useSupport=True, peak=1.5)
    for a, b in [(m.wall.flange, m.spring.flange_a), (m.spring.flange_b, m.mass.flange_a),
                 (m.mass.flange_b, m.friction.flange_a), (m.belt.flange, m.friction.support)]:
        m.connect(a, b)
    return m


# name: (model, stop time [s], output interval [s], start values, signals, modes)
CASES = {
    "ball": (BouncingBall, 3.0, 0.01, {"ball.s": 1.0, "ball.v": 0.0},
             ["ball.s", "ball.v"], []),
    "friction": (RotationalFriction, 3.0, 0.001, START,
                 ["inertia1.w", "inertia2.w", "inertia3.w", "inertia1.phi", "inertia3.phi",
                  "clutch.tau", "brake.tau"], ["clutch.mode", "brake.mode"]),
    "stick_slip": (stick_slip, 12.0, 0.01, {"mass.v": 0.12},
                   ["mass.s", "mass.v", "friction.f"], ["friction.mode"]),
}


@pytest.fixture(scope="module")
def fmus(fmu_dir):
    out = {}
    for name, (make, T, dt, x0, _, _) in CASES.items():
        compiled = acausal.compile(make())
        grid = np.linspace(0.0, T, int(round(T / dt)) + 1)
        out[name] = compiled, compiled.simulate(T, t=grid, x0=x0, rtol=1e-12, atol=1e-14)
        for v in VERSIONS:
            out[name, v] = compiled.export_fmu(fmu_dir / f"{name}{v[0]}.fmu", fmi_version=v,
                                               stop_time=T)
    return out


# ---- comparisons ----------------------------------------------------------------------------
def at(t, values, grid):
    """values at each grid time: the last row at that time (an event's right limit)."""
    idx = np.searchsorted(t, grid + 1e-9, side="right") - 1
    assert np.allclose(t[idx], grid, rtol=0, atol=1e-9)
    return np.asarray(values)[idx]


def mode_changes(t, mode):
    """The instants where ``mode`` changes between consecutive rows (an importer records the
    event's left limit at its time)."""
    return t[:-1][np.diff(mode) != 0]


def impacts(t, v):
    """The ball's impacts in rows that keep both limits: where v jumps up at one time."""
    return t[:-1][(np.diff(t) == 0) & (np.diff(v) > 0)]


def impacts_from_samples(t, s, v):
    """The ball's impacts from samples between them: from the first sample (s, v) after each,
    back along the free flight s = v₊τ − gτ²/2 that started at the floor τ earlier."""
    after = np.flatnonzero((v[:-1] < 0) & (v[1:] > 0)) + 1
    s, v = s[after], v[after]
    return t[after] - (-v + np.sqrt(v * v + 2 * G * s)) / G


def check(name, ref, t, get, grid, events=None):
    _, _, _, _, signals, modes = CASES[name]
    for n in signals:
        e = np.max(np.abs(at(t, get(n), grid) - at(ref.t, ref[n], grid))) / np.max(np.abs(ref[n]))
        assert e < RTOL, (name, n, e)
    for m in modes:        # the modes at the output points (right limits) too
        assert np.array_equal(at(t, get(m), grid), at(ref.t, ref[m], grid)), (name, m)
    for key, got in (events or {}).items():
        want = model_events(name, ref.t, lambda n: ref[n])[key]
        assert len(want) > 0, key
        assert len(got) == len(want), (name, key, got, want)
        assert np.max(np.abs(got - want)) < EVENT_TOL, (name, key, got - want)


def model_events(name, t, get):
    """Event instants in rows that keep both limits of events (simulate()'s, an importer's in
    model exchange)."""
    modes = CASES[name][5]
    if not modes:
        return {"impacts": impacts(t, get("ball.v"))}
    return {m: mode_changes(t, get(m)) for m in modes}


# ---- fmpy --------------------------------------------------------------------------------------
@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("name", list(CASES))
def test_fmpy_reproduces_simulate_with_its_events(fmus, name, version, kind):
    """fmpy (CVODE for model exchange, the FMU's RODAS4 in co-simulation), tolerance 1e-10:
    the signals within 1e-6 of their peaks, the modes at every output point, and the event
    instants within 1e-6 s: in model exchange from fmpy's rows at the events, in
    co-simulation the ball's impacts extrapolated back from the samples after them."""
    ref = fmus[name][1]
    _, T, dt, x0, signals, modes = CASES[name]
    r = fmpy.simulate_fmu(str(fmus[name, version]), fmi_type=kind, stop_time=T,
                          output_interval=dt, start_values=x0, relative_tolerance=1e-10,
                          output=signals + modes)
    check_importer(name, ref, r, kind == "ModelExchange")


def test_the_event_instants_are_those_of_the_closed_form():
    """The reference itself: the ball's impacts from 1 m with restitution 0.8 at
    t₁ = √(2/g), then every 2·e^k·√(2/g) later."""
    compiled = acausal.compile(BouncingBall())
    res = compiled.simulate(3.0, x0={"ball.s": 1.0, "ball.v": 0.0}, rtol=1e-12, atol=1e-14)
    t1 = np.sqrt(2.0 / G)
    closed = t1 + np.concatenate([[0.0], np.cumsum(2 * t1 * 0.8 ** np.arange(1, 20))])
    got = np.array([e.time for e in res.events])
    assert np.max(np.abs(got - closed[:got.size])) < 1e-9


# ---- the Reference FMUs' fmusim ---------------------------------------------------------------
@pytest.mark.parametrize("kind", ["me", "cs"])
@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("name", list(CASES))
def test_fmusim_reproduces_simulate_with_its_events(fmus, name, version, kind, tmp_path):
    """The Reference FMUs' fmusim (CVODE for model exchange), tolerance 1e-10: as fmpy."""
    ref = fmus[name][1]
    _, T, dt, x0, signals, modes = CASES[name]
    res = fmusim(fmus[name, version], kind, T, dt, x0, signals + modes, tmp_path)
    check_importer(name, ref, res, kind == "me")


def check_importer(name, ref, res, model_exchange: bool):
    """``check`` of an importer's result ``res`` (columns by name, "time"): event instants
    from its rows in model exchange; in co-simulation the ball's impacts extrapolated back
    from the samples after them, the modes' changes bracketed by the output points."""
    _, T, dt, _, _, modes = CASES[name]
    t = res["time"]
    grid = np.linspace(0.0, T, int(round(T / dt)) + 1)
    if model_exchange:
        events = model_events(name, t, lambda n: res[n])
    elif not modes:
        events = {"impacts": impacts_from_samples(t, res["ball.s"], res["ball.v"])}
    else:
        events = None
    check(name, ref, t, lambda n: res[n], grid, events)


@pytest.mark.parametrize("name", list(CASES))
def test_fmu_compliance_checker(fmus, name, tmp_path):
    """FMI 2.0: the checker finds nothing in model exchange (its forward Euler, events at its
    steps' ends) nor in co-simulation, whose results equal compiled.simulate to 1e-6 of each
    signal's peak, from the models' default starts (the checker sets none). The ball starts
    at rest on the floor, a start without a defined motion (simulate() lets it sink, the
    FMU's hysteresis lets it bounce ever so slightly): only checked."""
    make, T, dt, _, signals, modes = CASES[name]
    compiled = fmus[name][0]
    cs = fmu_check(fmus[name, "2.0"], "cs", T, dt, int(round(T / dt)), tmp_path / "cs.csv")
    if name == "ball":
        signals = []
    ref = compiled.simulate(T, t=cs["time"], rtol=1e-12, atol=1e-14)
    for n in signals:
        e = np.max(np.abs(at(cs["time"], cs[n], cs["time"]) - at(ref.t, ref[n], cs["time"])))
        assert e / max(np.max(np.abs(ref[n])), 1e-300) < RTOL, (name, n, e)
    fmu_check(fmus[name, "2.0"], "me", T, 1e-4, int(round(T / 1e-4)), tmp_path / "me.csv")


# ---- errors -------------------------------------------------------------------------------------
@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
def test_an_event_iteration_that_never_settles_names_the_component(fmu_dir, version, kind,
                                                                    capsys):
    path = acausal.compile(on_a_mass("toggle", Toggle())).export_fmu(
        fmu_dir / f"toggle{version[0]}.fmu", fmi_version=version)
    with pytest.raises(FMICallException, match="status 3"):
        fmpy.simulate_fmu(unzipped(path), fmi_type=kind, stop_time=1.0)
    log = capsys.readouterr().out
    assert re.search(r"event iteration at t = 0 s does not settle: the modes of toggle keep "
                     r"changing \(50 rounds\)", log), log


@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
def test_chattering_names_the_component(fmu_dir, version, kind, capsys):
    """A relay stops the mass at t = 1 s and then switches without end: fmiError, the log
    naming it, as simulate() does, not an importer stepping forever."""
    path = acausal.compile(on_a_mass("relay", Relay())).export_fmu(
        fmu_dir / f"relay{version[0]}.fmu", fmi_version=version)
    with pytest.raises(FMICallException, match="status 3"):
        fmpy.simulate_fmu(unzipped(path), fmi_type=kind, stop_time=2.0,
                          start_values={"mass.v": 1.0})
    log = capsys.readouterr().out
    assert re.search(r"chattering: 100 events within .* after t = 1(\.0+\d*)? s, 100 of them "
                     r"of component 'relay'", log), log


class Jump(Component):
    """A mode declared with values (0, 1) whose update gives 2."""
    flange = TranslationalFlange("any flange")

    def structure(self, s):
        s.mode("gear", 0, values=(0, 1))

    def physics(self, e):
        e.mode_update(e.mode("gear"), 2)


@pytest.mark.parametrize("version", VERSIONS)
def test_a_mode_off_its_values_names_the_component(fmu_dir, version, capsys):
    model = acausal.Model("jump")
    model.mass = tr.Mass(m=1.0)
    model.jump = Jump()
    model.connect(model.mass.flange_a, model.jump.flange)
    path = acausal.compile(model).export_fmu(fmu_dir / f"jump{version[0]}.fmu",
                                             fmi_version=version)
    with pytest.raises(FMICallException, match="status 3"):
        fmpy.simulate_fmu(unzipped(path), fmi_type="ModelExchange", stop_time=1.0)
    log = capsys.readouterr().out
    assert "the mode_update of 'jump' gives jump.gear = 2, not one of its values" in log, log


def test_pythonfmu_refuses_models_with_events_and_points_at_the_native_backend(fmu_dir):
    compiled = acausal.compile(BouncingBall())
    with pytest.raises(FmuExportError, match=r"floor.*pythonfmu.*backend='native'"):
        compiled.export_fmu(fmu_dir / "ball_py.fmu", backend="pythonfmu")
