"""Benchmark: a controller written in Python in the loop of the gantry crane, 1 kHz for 10 s.

The controller (a PD on the cart position towards 1 m with damping of the sway, computed in
Python from the cart position and speed and the rope angle and rate) runs every millisecond;
the plant (``acausal.models.crane``, 4 states, input F) is integrated between samples with F
held. Contenders, measured in the same run, interleaved, ``--repeat`` times (median and
spread min..max of the 10 000-step loop):

- stepper: ``compiled.stepper(1e-3, rtol=...)``, ``step({"F": F})`` per sample (Dormand–Prince
  substeps with error control, called through a CasADi buffer);
- stepper (cvodes): the same with ``solver='cvodes'``: one CasADi CVODES integrator built
  once (u, p, the step's start as its parameters) and called per sample. CVODES cannot carry
  its state across calls of a CasADi Function: every call re-initializes it (order 1, a
  fresh first step), which is what this line measures;
- FMU: the native co-simulation FMU of the same model (``compiled.export_fmu(...,
  fmu_type='cs')``), driven from Python by fmpy's FMU2Slave: getReal of the states, setReal
  of F, doStep per sample (the FMU's RODAS4, which carries its step size from sample to
  sample), tolerance set by setupExperiment.

Both at the same relative tolerance; their error against a tight reference (scipy DOP853,
rtol 1e-12, atol 1e-14, per sample on the compiled model's right-hand side, the same
controller) is printed, as max |Δ| over the trajectory of the states. Set-up costs (building
the stepper; exporting, unzipping and instantiating the FMU) are printed apart. Target: the
stepper's loop within 1.5× the FMU's. The machine is shared: ratios measured in one run are
what count. Run: ``python benchmarks/stepper.py [--repeat 5] [--rtol 1e-8]``.
"""
from __future__ import annotations

import argparse
import os
import tempfile
import time
from pathlib import Path

for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import numpy as np  # noqa: E402
from fmpy import extract, read_model_description  # noqa: E402
from fmpy.fmi2 import FMU2Slave  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402

import acausal  # noqa: E402
from acausal.models import GantryCrane  # noqa: E402

DT, STEPS = 1e-3, 10_000
STATES = ["rail.s", "hinge.phi", "rail.v", "hinge.w"]


def controller(s, phi, v, w):
    """F [N] from the cart position s [m], rope angle phi [rad] and their rates."""
    return 20.0 * (1.0 - s) - 12.0 * v + 30.0 * phi + 5.0 * w


def run_stepper(compiled, rtol, solver=None):
    st = compiled.stepper(DT, rtol=rtol, atol=rtol * 1e-2, outputs=STATES, solver=solver)
    y = st.outputs()
    out = np.empty((STEPS, 4))
    t0 = time.perf_counter()
    for k in range(STEPS):
        y = st.step({"F": controller(y["rail.s"], y["hinge.phi"], y["rail.v"], y["hinge.w"])})
        out[k] = y["rail.s"], y["hinge.phi"], y["rail.v"], y["hinge.w"]
    return time.perf_counter() - t0, out


def run_fmu(unzipped, md, rtol):
    vr = {v.name: v.valueReference for v in md.modelVariables}
    xs, F = [vr[n] for n in STATES], [vr["F"]]
    fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipped,
                    modelIdentifier=md.coSimulation.modelIdentifier, instanceName="crane")
    fmu.instantiate()
    fmu.setupExperiment(tolerance=rtol, startTime=0.0)
    fmu.enterInitializationMode()
    fmu.exitInitializationMode()
    out = np.empty((STEPS, 4))
    t = 0.0
    t0 = time.perf_counter()
    y = fmu.getReal(xs)
    for k in range(STEPS):
        fmu.setReal(F, [controller(*y)])
        fmu.doStep(t, DT)
        t += DT
        y = fmu.getReal(xs)
        out[k] = y
    elapsed = time.perf_counter() - t0
    fmu.terminate()
    fmu.freeInstance()
    return elapsed, out


def reference(compiled):
    """The closed loop by scipy DOP853 per sample (rtol 1e-12, atol 1e-14)."""
    f, p = compiled.f, compiled.param_vector()
    x, out = np.zeros(4), np.empty((STEPS, 4))
    for k in range(STEPS):
        F = controller(*x)
        sol = solve_ivp(lambda t, xx: np.array(f(x=xx, u=F, p=p)["xdot"]).ravel(),
                        (0.0, DT), x, method="DOP853", rtol=1e-12, atol=1e-14)
        x = sol.y[:, -1]
        out[k] = x
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--rtol", type=float, default=1e-8)
    args = ap.parse_args()
    compiled = acausal.compile(GantryCrane())
    assert compiled.x_names == STATES
    t0 = time.perf_counter()
    compiled.stepper(DT, rtol=args.rtol)
    build_stepper = time.perf_counter() - t0
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        path = compiled.export_fmu(Path(tmp) / "crane.fmu", fmu_type="cs")
        md = read_model_description(str(path))
        unzipped = extract(str(path), str(Path(tmp) / "unzipped"))
        build_fmu = time.perf_counter() - t0
        ref = reference(compiled)
        times = {"stepper": [], "FMU (fmpy)": [], "stepper (cvodes)": []}
        errors = {}
        for _ in range(args.repeat):                       # interleaved
            for name, run in (("stepper", lambda: run_stepper(compiled, args.rtol)),
                              ("FMU (fmpy)", lambda: run_fmu(unzipped, md, args.rtol)),
                              ("stepper (cvodes)",
                               lambda: run_stepper(compiled, args.rtol, "cvodes"))):
                dt, out = run()
                times[name].append(dt)
                errors[name] = float(np.max(np.abs(out - ref)))
    print(f"gantry crane, {STEPS} steps of {DT * 1e3:g} ms, rtol {args.rtol:g}, "
          f"{args.repeat} interleaved repeats")
    print(f"set-up: stepper {build_stepper * 1e3:.1f} ms; FMU export + unzip "
          f"{build_fmu * 1e3:.0f} ms")
    print(f"{'':>16s} | {'median [s]':>10s} | {'min..max [s]':>15s} | {'per step':>9s} | "
          f"{'max error':>9s}")
    for name, ts in times.items():
        med = float(np.median(ts))
        print(f"{name:>16s} | {med:10.4f} | {min(ts):6.4f}..{max(ts):6.4f} | "
              f"{med / STEPS * 1e6:6.1f} µs | {errors[name]:9.2e}")
    ratio = np.median(times["stepper"]) / np.median(times["FMU (fmpy)"])
    print(f"stepper / FMU: {ratio:.2f}× (target ≤ 1.5×)")


if __name__ == "__main__":
    main()
