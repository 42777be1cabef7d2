"""Loop assembly in the native FMU's initialization (fmu/c/loops.c) is numerics.project's
algorithm in C: from the same start values the FMU reaches the configuration acausal reaches in
process (operating_point and simulate's first point, numpy's SVD-based steps), in FMI 2.0 and
3.0, model exchange and co-simulation. The loop's closure is measured independently of both:
the loop's joint C from the crank's side, A + L1 e(φ1) + L2 e(φ1 + φ2), and from the rocker's,
D + L3 e(φ3) (e(a) = (cos a, sin a), A = (0, 0), D = (L0, 0)), in position and velocity, and on
the recorded frames of rev4. Where no assembly exists, exitInitializationMode fails with a
message naming the constraints not satisfied and the part at fault.
"""
from __future__ import annotations

import warnings

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")
from fmpy.fmi1 import FMICallException                            # noqa: E402

import acausal                                                    # noqa: E402
from acausal.analysis import operating_point                      # noqa: E402
from acausal.models import FourBar                                # noqa: E402
from acausal.models.linkages import FOUR_BAR_LENGTHS              # noqa: E402
from fmi_calls import get_real, init, instance                    # noqa: E402

VERSIONS = ("2.0", "3.0")
REV4 = ["rev4.frame_a.x", "rev4.frame_b.x", "rev4.frame_a.y", "rev4.frame_b.y"]
FAST = {"rev1.phi": 1.0, "rev1.w": 45.0}          # the crank's start: 45 rad/s


def in_process(compiled, x0):
    """operating_point's states and rev4's frames (warning that assembly moved the guess)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        pt = operating_point(compiled, x0)
    return {n: pt[n] for n in compiled.x_names + REV4}


def assembled(path, compiled, start, cs):
    """The FMU's states and rev4's frames after exitInitializationMode."""
    fmu, vr, md = instance(path, cs=cs)
    init(fmu, md, start, vr)
    names = compiled.x_names + REV4
    values = dict(zip(names, get_real(fmu, md, [vr[n] for n in names])))
    fmu.terminate()
    fmu.freeInstance()
    return values


def loop_gap(lengths, v):
    """C from the crank's side minus C from the rocker's, and its rate (closed form)."""
    l0, l1, l2, l3 = lengths
    a1, a12, a3 = v["rev1.phi"], v["rev1.phi"] + v["rev2.phi"], v["rev3.phi"]
    w1, w12, w3 = v["rev1.w"], v["rev1.w"] + v["rev2.w"], v["rev3.w"]
    gap = [l1 * np.cos(a1) + l2 * np.cos(a12) - l0 - l3 * np.cos(a3),
           l1 * np.sin(a1) + l2 * np.sin(a12) - l3 * np.sin(a3)]
    rate = [-l1 * w1 * np.sin(a1) - l2 * w12 * np.sin(a12) + l3 * w3 * np.sin(a3),
            l1 * w1 * np.cos(a1) + l2 * w12 * np.cos(a12) - l3 * w3 * np.cos(a3)]
    return np.abs(gap).max(), np.abs(rate).max()


def assert_assembled_as_in_process(fmu, ref, lengths, held):
    for n, value in ref.items():
        assert fmu[n] == pytest.approx(value, abs=1e-9), (n, fmu[n], value)
    for n, value in held.items():                  # the importer's start values are held
        assert fmu[n] == value, n
    gap, rate = loop_gap(lengths, fmu)
    assert gap < 1e-10 and rate < 1e-10 * (1 + abs(fmu["rev1.w"])), (gap, rate)
    assert abs(fmu["rev4.frame_a.x"] - fmu["rev4.frame_b.x"]) < 1e-10
    assert abs(fmu["rev4.frame_a.y"] - fmu["rev4.frame_b.y"]) < 1e-10


@pytest.fixture(scope="module")
def four_bar(fmu_dir):
    compiled = acausal.compile(FourBar())
    return compiled, {v: compiled.export_fmu(fmu_dir / f"four_bar_{v[0]}.fmu", fmi_version=v)
                      for v in VERSIONS}


@pytest.mark.parametrize("cs", [False, True], ids=["ME", "CS"])
@pytest.mark.parametrize("version", VERSIONS)
def test_fast_crank_assembles_as_in_process(four_bar, version, cs):
    """The crank at 1 rad and 45 rad/s, the other joints from 0: the velocity constraints are
    linear in the speeds, which the FMU's steps never hold back (it used to give up and blame
    the angles); it reaches operating_point's state and simulate's first point."""
    compiled, paths = four_bar
    ref = in_process(compiled, FAST)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        first = compiled.simulate(1e-3, x0=FAST, t=[0.0, 1e-3])
    for n in compiled.x_names:
        assert first[n][0] == pytest.approx(ref[n], abs=1e-12), n
    fmu = assembled(paths[version], compiled, FAST, cs)
    assert_assembled_as_in_process(fmu, ref, FOUR_BAR_LENGTHS, FAST)
    assert abs(fmu["rev2.w"]) > 10                 # the loop's speeds really moved


def grashof_crank_rocker(seed):
    """As tests/simulation/test_initialization.py draws them: bars (ground, crank, coupler,
    rocker), the crank the shortest and s + l < p + q (every crank angle closes); a crank
    angle."""
    rng = np.random.default_rng(seed)
    while True:
        l0, l2, l3 = rng.uniform(0.5, 2.0, 3)
        l1 = rng.uniform(0.05, 0.45) * min(l0, l2, l3)
        bars = sorted([l0, l1, l2, l3])
        if bars[0] + bars[3] < bars[1] + bars[2] - 0.05:
            return (l0, l1, l2, l3), rng.uniform(-np.pi, np.pi)


@pytest.mark.parametrize("seed", range(4))
def test_random_closable_four_bars_assemble_as_in_process(fmu_dir, seed):
    """Random Grashof crank-rockers, the crank at a random angle, every other joint from its
    start value 0 (no guess): the FMU closes the loop where acausal does (FMI 2.0 for even
    seeds, 3.0 for odd; model exchange and co-simulation)."""
    lengths, theta = grashof_crank_rocker(seed)
    compiled = acausal.compile(FourBar(f"grashof_{seed}", lengths=lengths))
    version = VERSIONS[seed % 2]
    path = compiled.export_fmu(fmu_dir / f"grashof_{seed}.fmu", fmi_version=version)
    ref = in_process(compiled, {"rev1.phi": theta})
    for cs in (False, True):
        fmu = assembled(path, compiled, {"rev1.phi": theta}, cs)
        assert_assembled_as_in_process(fmu, ref, lengths, {"rev1.phi": theta})


def refused_initialization(path, start, capsys):
    fmu, vr, md = instance(path)
    with pytest.raises(FMICallException, match="status 3"):
        init(fmu, md, start, vr)
    return capsys.readouterr().out


@pytest.mark.parametrize("version", VERSIONS)
def test_speeds_that_contradict_the_loop_are_named(four_bar, version, capsys):
    """Every joint's speed set: the loop leaves one free, so its velocity constraints fail
    while its positions close; the message names the velocity constraints and the speeds,
    not the angles."""
    compiled, paths = four_bar
    start = {"rev1.phi": 1.0, "rev1.w": 1.0, "rev2.w": 1.0, "rev3.w": 1.0}
    log = refused_initialization(paths[version], start, capsys)
    assert "positions close but the speeds cannot satisfy loop velocity constraint rev4.x" in log
    assert "rev2.w = 1, rev3.w = 1" in log
    assert "loop constraint rev4" not in log, log


def test_unclosable_four_bar_names_the_position_constraints(fmu_dir, capsys):
    """A crank longer than the other three bars together: no crank angle closes the loop; the
    message names the position constraints, the parameters and the angle set."""
    compiled = acausal.compile(FourBar("unclosable", lengths=(1.0, 3.0, 0.5, 0.5)))
    path = compiled.export_fmu(fmu_dir / "unclosable.fmu")
    log = refused_initialization(path, {"rev1.phi": 1.0}, capsys)
    assert "not satisfied: loop constraint rev4.x, loop constraint rev4.y" in log
    assert "check the parameters and the start values set (rev1.phi = 1)" in log
