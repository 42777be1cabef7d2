"""Native FMUs (C, FMI 2.0 and 3.0, model exchange and co-simulation) of the worked models,
loaded and simulated by an independent importer (fmpy: CVode for model exchange, the FMU's
own RODAS4 solver for co-simulation) and compared with the in-process simulation
(compiled.simulate at rtol 1e-12) of the same model: equal to 1e-6 relative to each
variable's largest magnitude, at every output point, with a changed parameter and changed
start values — and the change itself is large, so the parameter demonstrably reaches the FMU.
Inputs are driven as steps at communication points (fmpy's model-exchange loop applies inputs
between solver calls and handles steps as input events; co-simulation holds an input over a
step); the in-process reference integrates the same steps piece by piece, restarted at every
jump.
"""
from __future__ import annotations

import warnings

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")
from fmpy import simulate_fmu                                    # noqa: E402
from fmpy.validation import validate_fmu                         # noqa: E402

import acausal                                                   # noqa: E402
from acausal.models import (DiskDriveHead, Drivetrain, FourBar, GantryCrane,  # noqa: E402
                            Parallelogram)

RTOL = 1e-6
VERSIONS = ("2.0", "3.0")
KINDS = ("ModelExchange", "CoSimulation")

# name: (model, horizon [s], changed parameters, start values, compared variables, nominals)
CASES = {
    "crane": (lambda: GantryCrane(), 3.0, {"load.m": 3.0, "railDamper.d": 2.0},
              {"hinge.phi": 0.3}, ["rail.s", "hinge.phi", "rail.v", "load.r[1]"], None),
    "disk": (lambda: DiskDriveHead(), 0.004, {"flexureSpring.c": 2.0e4},
             {"pivot.w": 10.0}, ["pivot.phi", "flexure.s", "flexure.v"],
             {"flexure.s": 1e-9, "flexure.v": 1e-5}),
    "four_bar": (lambda: FourBar(), 2.0, {"coupler.m": 1.5},
                 {"rev1.phi": 1.0, "rev1.w": 2.0}, ["rev1.phi", "rev2.phi", "rev3.phi", "rev3.w"],
                 None),
    "drivetrain": (lambda: Drivetrain(), 3.0, {"gear.ratio": 8.0}, {},
                   ["motor.w", "drum.w", "motor.i", "shaft.tau"], None),
}
INPUTS = {"crane": ("F", 0.25, lambda t: 5.0 * np.sin(2.0 * t + 0.3)),
          "disk": ("T", 2.5e-4, lambda t: 0.02 * np.sin(2 * np.pi * t / 2e-3) * (t < 2e-3))}


@pytest.fixture(scope="module")
def fmus(fmu_dir):
    """(compiled, {version: path}) per case, exported once."""
    out = {}
    for name, (make, _, _, _, _, nominals) in CASES.items():
        compiled = acausal.compile(make())
        out[name] = (compiled, {v: compiled.export_fmu(fmu_dir / f"{name}_{v[0]}.fmu",
                                                       fmi_version=v, nominals=nominals,
                                                       stop_time=CASES[name][1])
                                for v in VERSIONS})
    return out


def reference(compiled, T, grid, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")       # loop assembly moves the guessed joints
        atol = 1e-18 if compiled.name == "disk" else 1e-14
        return compiled.simulate(T, t=grid, rtol=1e-12, atol=atol, **kw)


def on_grid(res, grid, name):
    """Values of ``name`` at the grid times (the last row recorded at each; fmpy adds rows at
    input events)."""
    idx = np.searchsorted(res["time"], grid + 1e-9 * grid[-1], side="right") - 1
    assert np.allclose(res["time"][idx], grid, rtol=0, atol=1e-8 * grid[-1])
    return res[name][idx]


def relerr(a, b):
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b))) / np.max(np.abs(b)))


@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("name", list(CASES))
def test_validates(fmus, name, version):
    assert validate_fmu(str(fmus[name][1][version])) == []


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("name", list(CASES))
def test_equals_in_process(fmus, name, version, kind):
    compiled, paths = fmus[name]
    _, T, params, x0, names, _ = CASES[name]
    grid = np.linspace(0.0, T, 201)
    ref = reference(compiled, T, grid, params=params, x0=x0)
    base = reference(compiled, T, grid, x0=x0)
    res = simulate_fmu(str(paths[version]), stop_time=T, output_interval=T / 200, fmi_type=kind,
                       start_values={**params, **x0}, relative_tolerance=1e-10,
                       record_events=False, output=names)
    assert np.allclose(res["time"], grid, rtol=0, atol=1e-12 * T)
    for n in names:
        assert relerr(res[n], ref[n]) < RTOL, (n, relerr(res[n], ref[n]))
    # the parameter change matters (so agreement above is not agreement with the defaults)
    assert max(relerr(ref[n], base[n]) for n in names) > 1e-3


def steps(name, T):
    """A step input on a regular grid: the fmpy signal (repeated times = jumps) and the
    (times, values) of its pieces."""
    inp, dt, f = INPUTS[name]
    tk = np.arange(0.0, T - 1e-12, dt)
    vk = f(tk)
    ts = np.append(np.repeat(tk, 2)[1:], T)
    vs = np.append(np.repeat(vk, 2)[:-1], vk[-1])
    return inp, np.array(list(zip(ts, vs)), dtype=[("time", float), (inp, float)]), tk, vk


def reference_pieces(compiled, T, grid, inp, tk, vk, params):
    """compiled.simulate piece by piece, restarted at every jump of the input from the end
    state of the previous piece (the integrator never steps over a jump)."""
    bounds = list(tk) + [T]
    x = {}
    out = {n: [] for n in compiled.x_names + compiled.recorded_names}
    for a, b, v in zip(bounds, bounds[1:], vk):
        pts = grid[(grid > a + 1e-12 * T) & (grid <= b + 1e-12 * T)]
        tt = np.unique(np.r_[a, pts, b])
        r = reference(compiled, b, tt, params=params, inputs={inp: float(v)}, x0=x)
        keep = np.isin(tt, grid) & ((tt > a) | (a == 0.0))
        for n in out:
            out[n].append(r[n][keep])
        x = {n: float(r[n][-1]) for n in compiled.x_names}
    return {n: np.concatenate(v) for n, v in out.items()}


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("name", list(INPUTS))
def test_input_drives_the_fmu(fmus, name, version, kind):
    compiled, paths = fmus[name]
    _, T, params, _, names, _ = CASES[name]
    grid = np.linspace(0.0, T, 201)
    inp, signal, tk, vk = steps(name, T)
    ref = reference_pieces(compiled, T, grid, inp, tk, vk, params)
    res = simulate_fmu(str(paths[version]), stop_time=T, output_interval=T / 200, fmi_type=kind,
                       start_values=params, input=signal, relative_tolerance=1e-10,
                       record_events=False, output=names)
    assert np.max(np.abs(ref[names[0]])) > 1e-3     # the input moved the model
    for n in names:
        got = on_grid(res, grid, n)
        assert relerr(got, ref[n]) < RTOL, (n, relerr(got, ref[n]))


@pytest.mark.parametrize("kind", KINDS)
def test_four_bar_loop_stays_closed(fmus, kind):
    """The FMU presents an ODE; its projection keeps the loop joint rev4 closed."""
    compiled, paths = fmus["four_bar"]
    res = simulate_fmu(str(paths["2.0"]), stop_time=2.0, output_interval=0.01, fmi_type=kind,
                       start_values={"rev1.phi": 1.0, "rev1.w": 2.0}, relative_tolerance=1e-10,
                       output=["rev4.frame_a.x", "rev4.frame_b.x", "rev4.frame_a.y",
                               "rev4.frame_b.y", "rev1.phi", "rev1.w"])
    gap = np.hypot(res["rev4.frame_a.x"] - res["rev4.frame_b.x"],
                   res["rev4.frame_a.y"] - res["rev4.frame_b.y"])
    assert gap.max() < 1e-8
    # the importer's start values of the driving joint are held by the assembly
    assert res["rev1.phi"][0] == pytest.approx(1.0, abs=1e-14)
    assert res["rev1.w"][0] == pytest.approx(2.0, abs=1e-14)


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("version", VERSIONS)
def test_four_bar_assembles_from_its_default_start_values(fmus, version, kind):
    """With no start values at all every joint is at 0, a singular configuration (the loop
    residual's gradient vanishes): the FMU still assembles the loop, to the configuration
    simulate() finds from the same start, and closes it to 1e-10 m."""
    compiled, paths = fmus["four_bar"]
    ref = reference(compiled, 0.01, np.linspace(0.0, 0.01, 2))
    res = simulate_fmu(str(paths[version]), stop_time=0.01, output_interval=0.01,
                       fmi_type=kind, relative_tolerance=1e-10,
                       output=["rev1.phi", "rev2.phi", "rev3.phi", "rev4.frame_a.x",
                               "rev4.frame_b.x", "rev4.frame_a.y", "rev4.frame_b.y"])
    for n in ("rev1.phi", "rev2.phi", "rev3.phi"):
        assert res[n][0] == pytest.approx(ref[n][0], abs=1e-9), n
    assert abs(ref["rev1.phi"][0]) > 0.1          # the crank moved: a real assembly step
    assert np.hypot(res["rev4.frame_a.x"][0] - res["rev4.frame_b.x"][0],
                    res["rev4.frame_a.y"][0] - res["rev4.frame_b.y"][0]) < 1e-10


@pytest.mark.parametrize("kind", KINDS)
def test_redundant_loop_rows_are_switched_off(fmu_dir, kind):
    """The FMU sets its loop-row switches (calculated parameters) in initialization as
    simulate() sets them (one redundant row off), so the constrained solve is regular and the motion equals the in-process one (started
    from the in-process assembly of crank angle 1 rad, rate 1 rad/s, for 0.25 s: before the
    crank falls to the collinear configuration at 0.33 s, where the rows left on lose rank)."""
    compiled = acausal.compile(Parallelogram("double_parallelogram", fifth_link=True))
    path = compiled.export_fmu(fmu_dir / f"double_parallelogram_{kind}.fmu", stop_time=0.25)
    assert validate_fmu(str(path)) == []
    grid = np.linspace(0.0, 0.25, 101)
    ref = reference(compiled, 0.25, grid, x0={"rev1.phi": 1.0, "rev1.w": 1.0},
                    guess={"rev2.phi": -1.0, "rev3.phi": 1.0, "rev5.phi": 1.0})
    assert len(ref.mobility.redundant) == 1
    start = {n: float(ref[n][0]) for n in compiled.x_names}
    switches = [f"loops.active_{i}" for i in range(len(compiled.loop_rows))]
    res = simulate_fmu(str(path), stop_time=0.25, output_interval=0.0025, fmi_type=kind,
                       start_values=start, relative_tolerance=1e-10,
                       output=["rev1.phi", "rev5.phi", *switches])
    for n in ("rev1.phi", "rev5.phi"):
        assert relerr(res[n], ref[n]) < RTOL, (n, relerr(res[n], ref[n]))
    # the FMU switched off the row simulate() names redundant, and only that one
    off = compiled.loop_rows.index(ref.mobility.redundant[0])
    assert [res[n][0] for n in switches] == [float(i != off) for i in range(len(switches))]


def test_nominals_default_to_the_models(fmu_dir):
    """Without ``nominals`` the FMU's states carry the model's nominals (the disk head's
    flexure magnitudes, the pivot damper's phi_nominal on the arm's angle); ``nominals``
    replaces them by name, also through a variable that coincides with a state."""
    from fmpy import read_model_description
    compiled = acausal.compile(DiskDriveHead())

    def nominals(path):
        md = read_model_description(str(path))
        return {v.name: float(v.nominal) if v.nominal is not None else 1.0
                for v in md.modelVariables if v.name in compiled.x_names}

    default = compiled.export_fmu(fmu_dir / "disk_nominal.fmu", fmu_type="me")
    assert nominals(default) == {"pivot.phi": 1e-4, "flexure.s": 1e-6, "pivot.w": 1.0,
                                 "flexure.v": 1e-2}
    given = compiled.export_fmu(fmu_dir / "disk_given.fmu", fmu_type="me",
                                nominals={"pivotDamper.phi_rel": 1e-3, "flexure.v": 1e-3})
    assert nominals(given) == {"pivot.phi": 1e-3, "flexure.s": 1e-6, "pivot.w": 1.0,
                               "flexure.v": 1e-3}
    with pytest.raises(acausal.errors.FmuExportError, match="nominals"):
        compiled.export_fmu(fmu_dir / "disk_bad.fmu", nominals={"flexure.s": -1.0})
