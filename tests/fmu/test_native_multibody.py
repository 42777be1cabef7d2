"""Native FMUs (FMI 2.0 and 3.0, model exchange and co-simulation) of 3-D multibody models
reproduce compiled.simulate (rtol 1e-12) in two independent importers, fmpy and the
Reference FMUs' fmusim: every compared signal within 1e-6 of its peak, with a changed
parameter whose effect is large (so the parameter reaches the FMU).

The models: MSL's Elementary.FreeBody (a free BodyShape on two 3-D Springs: 13 states, the
quaternion kept on |Q| = 1 by the FMU's own right-hand side) and Loops.Engine1a (a 3-D
slider-crank loop closed by a RevolutePlanarLoopConstraint: the FMU assembles the loop from
the start values in its initialization and keeps Φ, Φ̇ at zero by projection). Engine1a's
inertia starts at 10 rad/s through its state bearing.w (MSL's inertia.w(start = 10),
inertia.phi = bearing.phi); the cylinder starts from its start value s = 0 in both, so
both assemble the same branch. Engine1a also with b2 a plain Revolute (MSL's
over-constrained planar loop: 6 rows, 3 of them redundant, switched off at the assembled
configuration; its FMU takes 45 s to compile, so FMI 2.0 only). FreeBody's w_a[1] is not compared: it stays at rounding
noise (1e-18 rad/s) in both. A loop through a Spherical joint (a bar on it, its tip held by
a SphericalSpherical rod): the FMU keeps the joint's quaternion on the loop (FMI 2.0 only).
"""
from __future__ import annotations

import warnings

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")

import acausal                                                     # noqa: E402
from acausal.components.multibody import (BodyShape, FixedTranslation, Spherical,  # noqa: E402
                                          SphericalSpherical, World)
from acausal.models.multibody_forces import FreeBody                # noqa: E402
from acausal.models.multibody_loops import MultiBodyEngine1a       # noqa: E402
from importers import fmusim                                       # noqa: E402
from test_native_events import RTOL, VERSIONS                      # noqa: E402

ENGINE_SIGNALS = ["bearing.phi", "bearing.w", "b1.phi", "cylinder.s", "cylinder.v"]

# name: (model, horizon [s], output interval [s], start values and parameters, signals,
# FMI versions)
CASES = {
    "free_body": (FreeBody, 3.0, 0.01, {"spring1.c": 30.0},
                  [f"body.frame_a.r_0[{k}]" for k in (1, 2, 3)]
                  + [f"body.v_0[{k}]" for k in (1, 2, 3)]
                  + [f"body.body.w_a[{k}]" for k in (2, 3)]
                  + [f"body.body.Q[{k}]" for k in (1, 2, 3, 4)], VERSIONS),
    "engine": (MultiBodyEngine1a, 1.0, 0.005, {"bearing.w": 10.0, "inertia.J": 0.5},
               ENGINE_SIGNALS, VERSIONS),
    "engine_6_rows": (lambda: MultiBodyEngine1a(planarLoopConstraint=False), 1.0, 0.005,
                      {"bearing.w": 10.0, "inertia.J": 0.5}, ENGINE_SIGNALS, ("2.0",)),
}
CASES_VERSIONS = [(n, v) for n, case in CASES.items() for v in case[5]]


def spherical_rod_loop() -> acausal.Model:
    """A bar on a Spherical joint at the origin (turning and spinning at the start), its tip
    tied to {1, 1, 0} by a SphericalSpherical rod of 1 m."""
    m = acausal.Model("sphericalRodLoop")
    m.world, m.fix = World(), FixedTranslation(r=(1.0, 1.0, 0))
    m.sph = Spherical(w_rel_a_start=(1.0 + 2.0 ** 0.5, 2.0 ** 0.5, 0.0))
    m.bar = BodyShape(r=(1.0, 0, 0), r_CM=(0.5, 0, 0), m=1.0, I_11=0.01, I_22=0.1, I_33=0.1)
    m.rod = SphericalSpherical(rodLength=1.0)
    for a, b in ((m.world.frame_b, m.sph.frame_a), (m.sph.frame_b, m.bar.frame_a),
                 (m.world.frame_b, m.fix.frame_a), (m.bar.frame_b, m.rod.frame_a),
                 (m.fix.frame_b, m.rod.frame_b)):
        m.connect(a, b)
    return m


CASES["spherical_loop"] = (spherical_rod_loop, 2.0, 0.01, {"bar.m": 3.0},
                           ["sph.Q[1]", "sph.Q[2]", "sph.Q[4]", "sph.w_rel[1]",
                            "bar.frame_b.r_0[3]"], ("2.0",))
CASES_VERSIONS.append(("spherical_loop", "2.0"))


@pytest.fixture(scope="module")
def exported(fmu_dir):
    """name -> (reference, reference with default parameters, {version: FMU path})."""
    out = {}
    for name, (make, T, dt, start, signals, versions) in CASES.items():
        compiled = acausal.compile(make())
        grid = np.linspace(0.0, T, int(round(T / dt)) + 1)
        params = {k: v for k, v in start.items() if k in compiled.param_names}
        x0 = {k: v for k, v in start.items() if k not in params}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")          # loop assembly moves the start values
            ref = compiled.simulate(T, t=grid, x0=x0, params=params, rtol=1e-12, atol=1e-14)
            base = compiled.simulate(T, t=grid, x0=x0, rtol=1e-12, atol=1e-14)
        fmus = {v: compiled.export_fmu(fmu_dir / f"{name}_{v[0]}.fmu", fmi_version=v,
                                       stop_time=T) for v in versions}
        out[name] = (ref, base, fmus)
    return out


def check(name, ref, t, value):
    for n in CASES[name][4]:
        v = np.interp(ref.t, t, value(n))
        err = np.max(np.abs(v - ref[n])) / np.max(np.abs(ref[n]))
        assert err < RTOL, (name, n, err)


@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
@pytest.mark.parametrize("name, version", CASES_VERSIONS)
def test_fmpy_reproduces_simulate(exported, name, version, kind):
    ref, base, fmus = exported[name]
    _, T, dt, start, signals, _ = CASES[name]
    res = fmpy.simulate_fmu(str(fmus[version]), stop_time=T, output_interval=dt,
                            fmi_type=kind, start_values=start, relative_tolerance=1e-10,
                            record_events=False, output=signals)
    check(name, ref, res["time"], lambda n: res[n])
    # the parameter change matters (agreement above is not agreement with the defaults)
    assert max(np.max(np.abs(ref[n] - base[n])) / np.max(np.abs(ref[n]))
               for n in signals) > 1e-3


@pytest.mark.parametrize("kind", ["me", "cs"])
@pytest.mark.parametrize("name, version", CASES_VERSIONS)
def test_fmusim_reproduces_simulate(exported, name, version, kind, tmp_path):
    ref, _, fmus = exported[name]
    _, T, dt, start, signals, _ = CASES[name]
    res = fmusim(fmus[version], kind, T, dt, start, signals, tmp_path)
    check(name, ref, res["time"], lambda n: res[n])
