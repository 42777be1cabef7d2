"""Native FMU through fmpy's low-level API: the derivatives against the crane's closed form
(the textbook's), a massless node solved inside the FMU (algebraic variable) with a model
output and its ModelStructure, FMU state get/set/serialize round trips, directional derivatives
against finite differences, errors as FMI statuses with logged messages, the sources in the
FMU rebuilding the binary, and a clear error without a C compiler.
"""
from __future__ import annotations

import ctypes
import os
import subprocess

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")
from fmpy import extract, read_model_description, simulate_fmu    # noqa: E402
from fmpy.fmi1 import FMICallException                            # noqa: E402
from fmpy.validation import validate_fmu                          # noqa: E402

import acausal                                                    # noqa: E402
from acausal import toolchain                                     # noqa: E402
from acausal.components import translational as tr               # noqa: E402
from acausal.core import RealOutput                               # noqa: E402
from acausal.fmu import FmuExportError                            # noqa: E402
from acausal.models import FourBar, GantryCrane                   # noqa: E402
from fmi_calls import derivatives, get_real, init, instance, set_real   # noqa: E402


def crane_closed_form(q, qd, M, m, L, c, c_T, g):
    """The textbook's gantry crane for q = [x, θ]: M, C, gravity, coriolis, B (numpy)."""
    th, thd = q[1], qd[1]
    return {"M": np.array([[M + m, m * L * np.cos(th)], [m * L * np.cos(th), m * L ** 2]]),
            "C": np.diag([c, c_T]), "gravity": np.array([0.0, -m * g * L * np.sin(th)]),
            "coriolis": np.array([m * L * np.sin(th) * thd ** 2, 0.0]),
            "B": np.array([1.0, 0.0])}


class Isolator(acausal.Model):
    """wall ─ spring c1 ─ node (massless) ─ damper d ─ mass m ─ spring c2 ─ wall; force F on
    the mass; output ``pos`` = mass position. The node's speed is an algebraic variable."""

    def __init__(self, name="iso"):
        super().__init__(name)
        self.wall = tr.Fixed()
        self.s1 = tr.Spring(c=100.0)
        self.d = tr.Damper(d=5.0)
        self.mass = tr.Mass(m=2.0)
        self.s2 = tr.Spring(c=50.0)
        self.F = acausal.Input(unit="N", description="force on the mass")
        self.force = tr.Force()
        self.sensor = tr.PositionSensor()
        self.pos = acausal.Output(unit="m", description="mass position")
        for a, b in [(self.wall.flange, self.s1.flange_a), (self.s1.flange_b, self.d.flange_a),
                     (self.d.flange_b, self.mass.flange_a), (self.mass.flange_b, self.s2.flange_a),
                     (self.s2.flange_b, self.wall.flange), (self.F.y, self.force.f),
                     (self.force.flange, self.mass.flange_b),
                     (self.sensor.flange, self.mass.flange_b), (self.sensor.s, self.pos.u)]:
            self.connect(a, b)


@pytest.fixture(scope="module")
def fmus(fmu_dir):
    """The crane and the isolator, compiled and exported (FMI 2 and 3); "<model> by columns":
    exported with the Jacobian assembled from the forward derivative (``ac_jac`` as for a
    model whose symbolic Jacobian is too large to compile)."""
    crane, iso = acausal.compile(GantryCrane()), acausal.compile(Isolator())
    out = {"crane": crane, "iso": iso}
    for name, compiled in (("crane", crane), ("iso", iso)):
        for v in ("2.0", "3.0"):
            out[(name, v)] = compiled.export_fmu(fmu_dir / f"{name}{v[0]}.fmu", fmi_version=v)
            with pytest.MonkeyPatch.context() as mp:
                mp.setattr(toolchain, "JACOBIAN_LIMIT", 0)
                mp.setattr(toolchain, "JACOBIAN_RATIO", 0)
                out[(f"{name} by columns", v)] = compiled.export_fmu(
                    fmu_dir / f"{name}{v[0]}_columns.fmu", fmi_version=v)
    return out


@pytest.mark.parametrize("version", ["2.0", "3.0"])
def test_derivatives_are_the_closed_form(fmus, version):
    """ẋ of the crane FMU = [q̇; M⁻¹(B F − C q̇ + gravity + coriolis)] from the textbook's M(q)."""
    fmu, vr, md = instance(fmus[("crane", version)])
    init(fmu, md, {"load.m": 3.0}, vr)
    fmu.enterContinuousTimeMode()
    rng = np.random.default_rng(1)
    for _ in range(5):
        x, F = rng.normal(size=4), rng.normal()
        set_real(fmu, md, [vr["F"]], [F])
        dx = derivatives(fmu, md, x)
        ref = crane_closed_form(x[:2], x[2:], 5.0, 3.0, 1.0, 0.5, 0.05, 9.81)
        rhs = ref["B"] * F - ref["C"] @ x[2:] + ref["gravity"] + ref["coriolis"]
        assert np.allclose(dx, np.r_[x[2:], np.linalg.solve(ref["M"], rhs)], rtol=1e-12,
                           atol=1e-12)
        # the recorded variables follow the state that was set
        assert get_real(fmu, md, [vr["load.r[1]"]])[0] == pytest.approx(x[0] + np.sin(x[1]),
                                                                         abs=1e-12)
    fmu.terminate()
    fmu.freeInstance()


@pytest.mark.parametrize("version", ["2.0", "3.0"])
def test_massless_node_and_output(fmus, version):
    """The node's speed is solved inside (Newton); results equal the in-process DAE to 1e-6;
    the output depends on the mass position only, the mass acceleration on the input."""
    iso, path = fmus["iso"], fmus[("iso", version)]
    assert iso.z_names and iso.output_names == ["pos"]
    assert validate_fmu(str(path)) == []
    T, grid = 2.0, np.linspace(0.0, 2.0, 201)
    ref = iso.simulate(T, t=grid, inputs={"F": 3.0}, params={"d.d": 8.0}, x0={"mass.s": 0.1},
                       rtol=1e-12, atol=1e-14)
    names = ["pos", "mass.v", "d.v_rel", "s1.f"]
    for kind in ("ModelExchange", "CoSimulation"):
        res = simulate_fmu(str(path), stop_time=T, output_interval=T / 200, fmi_type=kind,
                           start_values={"F": 3.0, "d.d": 8.0, "mass.s": 0.1},
                           relative_tolerance=1e-10, output=names)
        for n in names:
            err = np.max(np.abs(res[n] - ref[n])) / np.max(np.abs(ref[n]))
            assert err < 1e-6, (kind, n, err)
    md = read_model_description(str(path))
    (out,) = md.outputs
    assert out.variable.name == "pos" and [d.name for d in out.dependencies] == ["mass.s"]
    ders = {d.variable.name: sorted(x.name for x in d.dependencies) for d in md.derivatives}
    assert ders["der(mass.s)"] == ["mass.v"]
    assert "F" in ders["der(mass.v)"] and "F" not in ders["der(mass.s)"]


@pytest.mark.parametrize("version", ["2.0", "3.0"])
def test_fmu_state_round_trip(fmus, version):
    """Co-simulation: save the state at t1 (also serialized and back), run on, restore, run
    again: the same trajectory to the last bit; a parameter change after the save is undone."""
    fmu, vr, md = instance(fmus[("crane", version)], cs=True)
    init(fmu, md, {"hinge.phi": 0.4}, vr)
    v3 = md.fmiVersion == "3.0"
    step = fmu.doStep
    names = [vr[n] for n in ("rail.s", "hinge.phi", "rail.v", "hinge.w")]
    t = 0.0
    for _ in range(10):
        step(t, 0.05)
        t += 0.05
    state = fmu.getFMUState() if v3 else fmu.getFMUstate()
    blob = fmu.serializeFMUState(state) if v3 else fmu.serializeFMUstate(state)

    def run():
        out, tt = [], t
        for _ in range(10):
            step(tt, 0.05)
            tt += 0.05
            out.append(get_real(fmu, md, names))
        return np.array(out)

    first = run()
    set_real(fmu, md, [vr["load.m"]], [7.0])
    (fmu.setFMUState if v3 else fmu.setFMUstate)(state)
    again = run()
    copy = fmu.deserializeFMUState(blob) if v3 else fmu.deSerializeFMUstate(blob)
    (fmu.setFMUState if v3 else fmu.setFMUstate)(copy)
    third = run()
    assert np.array_equal(first, again) and np.array_equal(first, third)
    assert np.max(np.abs(first)) > 0.1
    fmu.terminate()
    fmu.freeInstance()


@pytest.mark.parametrize("model", ["crane", "iso", "crane by columns", "iso by columns"])
@pytest.mark.parametrize("version", ["2.0", "3.0"])
def test_directional_derivatives(fmus, model, version):
    """∂ẋ/∂x·v and ∂ẋ/∂u·w from the FMU (CasADi AD, symbolic or by columns of the forward
    derivative; through the algebraic node for iso) against central finite differences of
    the FMU's derivatives."""
    compiled = fmus[model.split()[0]]
    fmu, vr, md = instance(fmus[(model, version)])
    init(fmu, md, {}, vr)
    fmu.enterContinuousTimeMode()
    nx = len(compiled.x_names)
    rng = np.random.default_rng(2)
    x = rng.normal(size=nx) * 0.5
    u = 1.3
    set_real(fmu, md, [vr["F"]], [u])
    states = [vr[n] for n in compiled.x_names]
    ders = [vr[f"der({n})"] for n in compiled.x_names]
    seed = rng.normal(size=nx)
    derivatives(fmu, md, x)
    got = np.array(fmu.getDirectionalDerivative(ders, states, list(seed)))
    got_u = np.array(fmu.getDirectionalDerivative(ders, [vr["F"]], [1.0]))
    eps = 1e-6
    fd = (derivatives(fmu, md, x + eps * seed) - derivatives(fmu, md, x - eps * seed)) / (2 * eps)
    derivatives(fmu, md, x)
    set_real(fmu, md, [vr["F"]], [u + eps])
    up = derivatives(fmu, md, x)
    set_real(fmu, md, [vr["F"]], [u - eps])
    fd_u = (up - derivatives(fmu, md, x)) / (2 * eps)
    assert np.allclose(got, fd, rtol=1e-6, atol=1e-7 * np.max(np.abs(fd)))
    assert np.allclose(got_u, fd_u, rtol=1e-6, atol=1e-8)
    assert np.max(np.abs(got_u)) > 0.1
    fmu.terminate()
    fmu.freeInstance()


@pytest.mark.parametrize("version", ["2.0", "3.0"])
def test_errors_are_statuses_with_messages(fmus, version, capsys):
    """A negative mass is rejected with fmiError and a logged message naming the parameter;
    the FMU keeps its value and works on."""
    fmu, vr, md = instance(fmus[("crane", version)], cs=True)
    with pytest.raises(FMICallException, match="status 3"):
        set_real(fmu, md, [vr["cart.m"]], [-1.0])
    assert "parameter 'cart.m' must be > 0" in capsys.readouterr().out
    with pytest.raises(FMICallException):
        set_real(fmu, md, [vr["world.g"]], [float("nan")])
    assert "world.g" in capsys.readouterr().out
    assert get_real(fmu, md, [vr["cart.m"]])[0] == 5.0
    with pytest.raises(FMICallException):
        set_real(fmu, md, [vr["der(rail.s)"]], [1.0])
    assert "cannot be set" in capsys.readouterr().out
    init(fmu, md, {}, vr)
    fmu.doStep(0.0, 0.1)
    with pytest.raises(FMICallException):     # a step from the wrong time
        fmu.doStep(5.0, 0.1)
    assert "FMU is at t = 0.1" in capsys.readouterr().out
    fmu.freeInstance()


class Lag(acausal.Component):
    """A first-order lag whose state starts at a parameter: der(x) = −x/T, x(0) = x0."""
    T = acausal.Parameter(0.5, "s", "time constant", positive=True)
    x0 = acausal.Parameter(0.3, "1", "start value of x")
    y = RealOutput("x")

    def structure(self, s):
        s.state("x", self.x0, "1", "lag state")

    def physics(self, e):
        x = e.state("x")
        e.derivative(x, -x / self.T)
        e.output(self.y, x)


def test_states_follow_parameters_unless_set(fmu_dir):
    """Start values of states follow the parameters (compiled.start(p)) unless the importer
    set them; the trajectory is x0·exp(−t/T)."""
    m = acausal.Model("lag")
    m.lag = Lag()
    m.out = acausal.Output()
    m.connect(m.lag.y, m.out.u)
    c = acausal.compile(m)
    path = c.export_fmu(fmu_dir / "lag.fmu")
    for start, x0 in (({"lag.x0": 2.0}, 2.0), ({"lag.x0": 2.0, "lag.x": 0.7}, 0.7), ({}, 0.3)):
        for kind in ("ModelExchange", "CoSimulation"):
            res = simulate_fmu(str(path), stop_time=1.0, output_interval=0.1, fmi_type=kind,
                               start_values=dict(start), relative_tolerance=1e-10,
                               output=["out"])
            assert np.allclose(res["out"], x0 * np.exp(-res["time"] / 0.5), rtol=1e-7), start


def test_sources_rebuild_the_binary(fmus, tmp_path):
    """The FMU's sources/ compile on their own (with the FMI headers) into a library that
    exports the FMI functions; FMI 2 lists them in modelDescription.xml, FMI 3 in
    sources/buildDescription.xml."""
    from acausal.fmu.export import find_compiler, find_fmi_headers
    for version in ("2.0", "3.0"):
        d = extract(str(fmus[("iso", version)]), unzipdir=str(tmp_path / version))
        md = read_model_description(d)
        files = md.buildConfigurations[0].sourceFileSets[0].sourceFiles   # FMI 2: SourceFiles
        out = tmp_path / f"rebuilt{version[0]}.so"
        cmd = [find_compiler(), "-O0", "-shared", "-fPIC", f"-I{find_fmi_headers(version)}",
               f"-I{d}/sources"] + [f"{d}/sources/{f}" for f in files] + ["-o", str(out), "-lm"]
        subprocess.run(cmd, check=True, capture_output=True)
        lib = ctypes.CDLL(str(out))
        prefix = "fmi2" if version == "2.0" else "fmi3"
        for fn in ("GetVersion", "DoStep", "GetDirectionalDerivative", "SetContinuousStates"):
            assert hasattr(lib, prefix + fn)


def test_no_compiler_is_a_clear_error(fmus, tmp_path, monkeypatch):
    import acausal.toolchain as tc
    monkeypatch.setattr(tc.shutil, "which", lambda name: None)
    with pytest.raises(FmuExportError, match="no C compiler"):
        fmus["crane"].export_fmu(tmp_path / "x.fmu")
    with pytest.raises(FmuExportError, match="fmi_version"):
        fmus["crane"].export_fmu(tmp_path / "x.fmu", fmi_version="1.0")



def test_unclosable_loop_is_an_error(fmu_dir, capsys):
    """A four-bar whose rocker cannot reach the coupler fails in exitInitializationMode with
    fmi2Error and a logged message, not a crash."""
    path = acausal.compile(FourBar()).export_fmu(fmu_dir / "four_bar.fmu")
    unzipped = extract(str(path), unzipdir=str(fmu_dir / "four_bar"))   # fmpy leaves its own
    with pytest.raises(FMICallException, match="ExitInitializationMode"):  # copy on errors
        simulate_fmu(unzipped, stop_time=1.0, start_values={"rev1.phi": 1.0,
                                                            "rocker_b.r[1]": 5.0})
    assert "kinematic loops cannot be closed" in capsys.readouterr().out


@pytest.mark.parametrize("backend", ["native", "pythonfmu"])
def test_unwritable_destination_is_refused_before_building(tmp_path, backend):
    """A destination under a file: FmuPathError (also a FileNotFoundError) naming the path,
    raised before any build."""
    blocker = tmp_path / "file"
    blocker.write_text("")
    with pytest.raises(acausal.FmuPathError, match="is a file, not a directory"):
        _lag_model().export_fmu(blocker / "sub" / "lag.fmu", backend=backend)


@pytest.mark.skipif(os.geteuid() == 0, reason="root may write into a read-only directory")
def test_read_only_directory_is_refused(tmp_path):
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o500)
    try:
        with pytest.raises(FileNotFoundError, match="no permission"):
            _lag_model().export_fmu(locked / "lag.fmu")
    finally:
        locked.chmod(0o700)


def _lag_model():
    m = acausal.Model("lag")
    m.lag = Lag()
    return acausal.compile(m)

