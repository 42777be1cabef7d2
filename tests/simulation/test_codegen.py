"""simulate(..., codegen=True): the integrators on the model's equations generated as C.

References: a hand-written CasADi integrator on ``compiled.dae`` with the parameters as its
arguments (the arithmetic of the generated code: equal to 1e-12); the in-process simulate(),
whose parameters are folded into the expressions (equal to 1e-12 where the folding rounds
alike, else to the integrator's error); closed forms (the heavy top's precession, the
four-bar's loop closure)."""
from __future__ import annotations

import os
import subprocess
import sys
import warnings
from pathlib import Path

import casadi as ca
import numpy as np
import pytest

import acausal
import acausal.toolchain as toolchain
from acausal.core import Model
from acausal.errors import SimulationError
from acausal.models import FourBar, GantryCrane
from acausal.models.bouncing_ball import BouncingBall
from acausal.models.pendulums import PendulumChain
from heavy_top import OMEGA, heavy_top

pytestmark = pytest.mark.skipif(
    not any(toolchain.shutil.which(c) for c in ("cc", "gcc", "clang")), reason="no C compiler")


@pytest.fixture(scope="module", autouse=True)
def cache(codegen_cache):
    """This module's cache of generated code."""
    return codegen_cache


@pytest.fixture(scope="module")
def pendulum():
    return acausal.compile(PendulumChain(3))


def states(res, names):
    return np.array([res[n] for n in names])


def hand_written(compiled, grid, x0, adams: bool, **params) -> np.ndarray:
    """The states on ``grid`` by cvodes on ``compiled.dae`` (p = [u; p] its arguments: the
    arithmetic of the generated code) from the state vector ``x0``, rtol 1e-8, atol 1e-10."""
    opts = {"abstol": 1e-10, "reltol": 1e-8, "max_num_steps": 100000}
    if adams:
        opts.update(linear_multistep_method="adams", nonlinear_solver_iteration="functional")
    F = ca.integrator("hand", "cvodes", compiled.dae, grid[0], grid[1:], opts)
    X = np.array(F(x0=x0, p=compiled.param_vector(params or None))["xf"])
    return np.column_stack([x0, X])


def test_ode_equals_in_process_simulate(pendulum):
    kw = dict(x0={"rev1.phi": 0.8, "rev2.w": 1.0}, params={"body2.m": 1.7})
    ref = pendulum.simulate(4.0, **kw)
    res = pendulum.simulate(4.0, codegen=True, **kw)
    assert ref.solver == res.solver == "adams"
    X = states(res, pendulum.x_names)
    assert np.max(np.abs(X - hand_written(pendulum, res.t, X[:, 0], True, **kw["params"]))) \
        < 1e-12
    # the pendulum's parameters fold into the same rounding: simulate() takes the same steps
    assert np.max(np.abs(X - states(ref, pendulum.x_names))) < 1e-12


def test_bdf_equals_hand_written_integrator_with_symbolic_parameters(pendulum):
    """BDF's Newton iterations use the Jacobian of the generated equations, whose parameters
    are arguments: the hand-written cvodes on compiled.dae (p = [u; p] its arguments) takes
    the same steps."""
    grid = np.linspace(0, 3.0, 61)
    res = pendulum.simulate(3.0, t=grid, x0={"rev1.phi": 0.8}, solver="cvodes", codegen=True)
    X = states(res, pendulum.x_names)
    assert np.max(np.abs(X - hand_written(pendulum, grid, X[:, 0], False))) < 1e-12
    # and the in-process simulate() (parameters folded: other rounding) to its tolerance
    ref = pendulum.simulate(3.0, t=grid, x0={"rev1.phi": 0.8}, solver="cvodes")
    assert np.max(np.abs(states(res, pendulum.x_names) - states(ref, pendulum.x_names))) < 1e-5


def test_bdf_on_the_forward_derivative_of_a_large_jacobian(monkeypatch):
    """A Jacobian too large to generate (the dense one of a recursion) is assembled by CasADi
    from the generated forward derivative, column by column: the same solution as the
    hand-written integrator to the integrator's tolerance (other rounding, other steps)."""
    from acausal import toolchain
    monkeypatch.setattr(toolchain, "JACOBIAN_LIMIT", 0)
    monkeypatch.setattr(toolchain, "JACOBIAN_RATIO", 0)
    compiled = acausal.compile(PendulumChain(4))
    grid = np.linspace(0, 2.0, 41)
    res = compiled.simulate(2.0, t=grid, x0={"rev1.phi": 0.8}, solver="cvodes", codegen=True)
    X = states(res, compiled.x_names)
    assert np.max(np.abs(X - hand_written(compiled, grid, X[:, 0], False))) < 1e-6


def test_chain_of_masses_with_branch_free_code_equals_in_process(monkeypatch):
    """A chain of masses and springs driven at its end: code with a read or write in every
    other instruction, generated without CasADi's null-pointer branches (BDF, with its
    sparse Jacobian); equal to the in-process simulate() and to the closed form of the
    static deflection under a constant force (each spring carries F: s_i = i·F/c)."""
    from acausal.components.translational import Fixed, Force, Mass, Spring
    from acausal import toolchain
    n, c, F = 30, 100.0, 2.0
    m = Model("masses")
    m.wall = Fixed()
    prev = m.wall.flange
    for i in range(1, n + 1):
        setattr(m, f"spring{i}", Spring(c=c))
        setattr(m, f"mass{i}", Mass(m=1.0, L=0.0))
        m.connect(prev, getattr(m, f"spring{i}").flange_a)
        m.connect(getattr(m, f"spring{i}").flange_b, getattr(m, f"mass{i}").flange_a)
        prev = getattr(m, f"mass{i}").flange_b
    m.push, m.F = Force(), acausal.Input(unit="N")
    m.connect(m.F.y, m.push.f)
    m.connect(m.push.flange, prev)
    compiled = acausal.compile(m)
    stripped = []
    plain = toolchain.plain_access

    def spy(code, functions, error):
        out = plain(code, functions, error)
        stripped.append(out != code)
        return out
    monkeypatch.setattr(toolchain, "plain_access", spy)
    x0 = {f"mass{i}.s": i * F / c for i in range(1, n + 1)}       # the static deflection
    kw = dict(x0=x0, inputs={"F": F}, solver="cvodes")
    res = compiled.simulate(5.0, codegen=True, **kw)
    assert stripped == [True]
    ref = compiled.simulate(5.0, **kw)
    assert np.max(np.abs(states(res, compiled.x_names) - states(ref, compiled.x_names))) < 1e-12
    assert max(np.max(np.abs(res[f"mass{i}.s"] - i * F / c)) for i in range(1, n + 1)) < 1e-8


def test_four_bar_dae_closes_its_loop_as_accurately_as_in_process():
    """IDAS's Newton iterations on the generated Jacobian (parameters as arguments) round
    otherwise than on the folded one in process: the runs differ at the level of the
    integrator's error, which is no larger than in process (against a run at rtol 1e-12)."""
    compiled = acausal.compile(FourBar())
    kw = dict(x0={"rev1.phi": 1.0, "rev1.w": 2.0}, atol=1e-12)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")        # the assembly moves the guessed joints
        tight = compiled.simulate(2.0, rtol=1e-12, **kw)
        ref = compiled.simulate(2.0, rtol=1e-9, **kw)
        res = compiled.simulate(2.0, rtol=1e-9, codegen=True, **kw)
    assert res.solver == "idas"
    names = ["rev1.phi", "rev2.phi", "rev3.phi", "rev1.w"]
    error = np.max(np.abs(states(res, names) - states(tight, names)))
    assert error <= 2 * np.max(np.abs(states(ref, names) - states(tight, names))) + 1e-9
    # loop closure: the coupler's end meets the rocker's end (rev4's frames coincide)
    gap = [res[f"rev4.frame_a.{c}"] - res[f"rev4.frame_b.{c}"] for c in ("x", "y")]
    assert np.max(np.abs(gap)) < 1e-9


def test_heavy_top_with_quaternions_precesses_at_the_closed_form_rate():
    """As tests/components/multibody/test_multibody_free.py: a symmetric top in steady
    precession (Goldstein), its orientation in quaternion states."""
    m, expected = heavy_top()
    compiled = acausal.compile(m)
    t = np.linspace(0, 3 * 2 * np.pi / OMEGA, 601)
    res = compiled.simulate(t[-1], t=t, codegen=True)
    X = states(res, compiled.x_names)
    assert res.solver == "adams"
    assert np.max(np.abs(X - hand_written(compiled, t, X[:, 0], True))) < 1e-12
    res = compiled.simulate(t[-1], t=t, rtol=1e-11, atol=1e-13, codegen=True)
    axis = np.array([res[f"top.frame_a.R.T[3,{j}]"] for j in (1, 2, 3)])
    assert np.max(np.abs(axis - expected(t))) < 1e-7


def test_inputs_and_parameters_are_arguments_of_the_generated_code(monkeypatch):
    """The crane driven by F(t): equal to in-process; then other inputs, parameters and a
    freshly compiled copy of the model run on the built library — building again fails."""
    compiled = acausal.compile(GantryCrane())
    x0 = {"hinge.phi": 0.3}

    def both(**kw):
        return (compiled.simulate(3.0, x0=x0, **kw),
                compiled.simulate(3.0, x0=x0, codegen=True, **kw))
    ref, res = both(inputs={"F": lambda t: 5.0 * np.sin(2.0 * t)})
    assert np.max(np.abs(states(res, compiled.x_names) - states(ref, compiled.x_names))) < 1e-12
    assert np.max(np.abs(res["F"] - 5.0 * np.sin(2.0 * res.t))) < 1e-12

    def no_build(*args, **kwargs):
        raise AssertionError("the generated code was built again")
    monkeypatch.setattr(toolchain, "build_shared_library", no_build)
    ref, res = both(inputs={"F": lambda t: 2.0 * np.cos(t)}, params={"load.m": 3.0})
    assert np.max(np.abs(states(res, compiled.x_names) - states(ref, compiled.x_names))) < 1e-12
    again = acausal.compile(GantryCrane())          # same equations: loaded from the cache
    res2 = again.simulate(3.0, x0=x0, inputs={"F": lambda t: 2.0 * np.cos(t)},
                          params={"load.m": 3.0}, codegen=True)
    assert np.max(np.abs(states(res2, compiled.x_names) - states(res, compiled.x_names))) == 0


def test_a_new_process_loads_the_cached_library(pendulum, cache):
    pendulum.simulate(1.0, codegen=True)
    libraries = sorted(Path(cache).glob("*.so"))
    stamps = [p.stat().st_mtime_ns for p in libraries]
    script = ("import acausal, acausal.toolchain as tc\n"
              "from acausal.models.pendulums import PendulumChain\n"
              "def no_build(*a, **k): raise SystemExit('built again')\n"
              "tc.build_shared_library = no_build\n"
              "acausal.compile(PendulumChain(3)).simulate(1.0, codegen=True)\n")
    env = dict(os.environ, ACAUSAL_CACHE=str(cache))
    r = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr + r.stdout
    assert sorted(Path(cache).glob("*.so")) == libraries
    assert [p.stat().st_mtime_ns for p in libraries] == stamps


def test_no_compiler_is_a_clear_error(monkeypatch, tmp_path):
    monkeypatch.setenv("ACAUSAL_CACHE", str(tmp_path))
    monkeypatch.setattr(toolchain.shutil, "which", lambda name: None)
    monkeypatch.delenv("CC", raising=False)
    compiled = acausal.compile(PendulumChain(2))
    with pytest.raises(SimulationError, match="no C compiler"):
        compiled.simulate(1.0, codegen=True)


def test_events_are_refused_with_a_clear_message():
    compiled = acausal.compile(BouncingBall())
    with pytest.raises(SimulationError, match="events or modes.*without codegen"):
        compiled.simulate(1.0, codegen=True)
