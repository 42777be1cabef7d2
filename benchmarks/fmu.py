"""Benchmark: simulation time of native FMUs (C, FMI 2.0) in fmpy vs in-process simulation.

For the gantry crane (ODE, 4 states, input F as steps), the drivetrain (5 states, stiff
shaft, time events) and the four-bar linkage (closed loop: projection in the FMU, IDAS with
the index-2 GGL form in process), each over its horizon with a 201-point output grid,
measured in the same run (best of --repeat):

- in process: ``compiled.simulate(...)`` (integrator creation + run), rtol 1e-8, atol 1e-10;
- FMU model exchange: ``fmpy.simulate_fmu(fmi_type="ModelExchange")`` (CVode, BDF, dense
  difference-quotient Jacobian; fmpy's atol = rtol · nominal), relative_tolerance 1e-8;
- FMU co-simulation: ``fmpy.simulate_fmu(fmi_type="CoSimulation")``, the FMU's RODAS4 with
  the importer's tolerance 1e-8 (atol 1e-10).

The FMU is unzipped and its modelDescription.xml read once, before timing (like an importer
that simulates a loaded FMU repeatedly); the FMU timings include loading the binary,
instantiation, initialization and fmpy's Python loop (every CVode right-hand side is three
ctypes calls; outputs are recorded in Python). The accuracy of each run against a tight in-process
reference (rtol 1e-12) is printed next to the times, so the ratios compare like with like.
Target: FMU within 2× of in-process. Run: ``python benchmarks/fmu.py [--repeat 3]``.

In the Reference FMUs' C importer ``fmusim`` (``$FMUSIM``, on the PATH, or the shared
fmi-tools; skipped when absent), so that the FMU and not fmpy's Python loop is timed: model
exchange (its CVODE, ``--solver cvode``) and co-simulation (the FMU's solver), tolerance
1e-8, interleaved with the in-process run (median CPU times of --repeat rounds, at least 5: the
shared machine's load falls on wall times far more). fmusim unzips and loads the FMU on
every run: "net" subtracts a run of one output interval (its start-up). At equal accuracy:
the in-process rtol is the loosest of 1e-5 … 1e-12 (atol = rtol/100) whose error is no
larger than the FMU's, for ME and CS each. Targets: ME <= 1.5x and
CS <= 1x in-process.

Where model-exchange time goes: the number of right-hand sides fmpy's CVode asks for is counted,
and the FMU's own cost of one (fmi2SetTime + fmi2SetContinuousStates + fmi2GetDerivatives) is
timed in C by ``fmu_rhs.c``, built here with the system compiler; "FMU share" is their product
over the ME time. The rest is the importer: its Python callbacks, loading and output recording.
"""
from __future__ import annotations

import argparse
import os
import shutil
import resource
import subprocess
import time
import tempfile
import warnings
from pathlib import Path

from timing import best_of, print_table  # first: pins BLAS threads
import numpy as np
from fmpy import extract, instantiate_fmu, read_model_description, simulate_fmu

import acausal
from acausal.fmu.export import find_compiler, find_fmi_headers, platform_dirs
from acausal.models import Drivetrain, FourBar, GantryCrane

CASES = {   # name: (model, horizon [s], start values, compared variable)
    "crane": (GantryCrane, 10.0, {"hinge.phi": 0.3, "F": 2.0}, "hinge.phi"),
    "drivetrain": (Drivetrain, 4.0, {}, "drum.w"),
    "four_bar": (FourBar, 5.0, {"rev1.phi": 1.0, "rev1.w": 2.0}, "rev3.phi"),
}


def build_rhs_timer(tmp: Path) -> Path:
    """fmu_rhs.c compiled against fmpy's FMI 2 headers."""
    exe = tmp / "fmu_rhs"
    subprocess.run([find_compiler(), "-O2", f"-I{find_fmi_headers('2.0')}",
                    str(Path(__file__).with_name("fmu_rhs.c")), "-o", str(exe), "-ldl"],
                   check=True)
    return exe


def fmu_rhs_seconds(exe: Path, unzipped: Path, md, start: dict, calls: int = 200_000) -> float:
    """The FMU's own time per right-hand side [s], measured in C from the start values."""
    vr = {v.name: v.valueReference for v in md.modelVariables}
    platform, _, ext = platform_dirs()
    binary = Path(unzipped) / "binaries" / platform / f"{md.modelExchange.modelIdentifier}{ext}"
    out = subprocess.run([str(exe), str(binary), md.guid, (Path(unzipped) / "resources").as_uri(),
                          str(md.numberOfContinuousStates), str(calls),
                          *(f"{vr[k]}={v}" for k, v in start.items())],
                         check=True, capture_output=True, text=True)
    return float(out.stdout)


FMUSIM = Path(os.environ.get("FMUSIM") or shutil.which("fmusim") or
              Path(__file__).resolve().parents[1].parent / "shared" / "fmi-tools" / "bin" /
              "fmusim")
IN_PROCESS_RTOLS = tuple(10.0 ** -k for k in np.arange(5.0, 12.01, 0.5))


def fmusim(fmu: Path, kind: str, T: float, dt: float, start: dict, var: str, out: Path):
    """(values of ``var`` on the output grid, CPU seconds of the fmusim process) for
    fmusim ("me": CVODE, "cs") at tolerance 1e-8 up to ``T``; of the rows fmusim adds at
    events, the last one at each output time."""
    cmd = [str(FMUSIM), "--interface-type", kind, "--tolerance", "1e-8", "--stop-time",
           repr(T), "--output-interval", repr(dt), "--output-variable", var,
           "--output-file", str(out)] + (["--solver", "cvode"] if kind == "me" else [])
    for k, v in start.items():
        cmd += ["--start-value", k, repr(v)]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run(cmd + [str(fmu)], capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        raise RuntimeError(f"fmusim {kind} failed on {fmu.name}: {r.stdout}{r.stderr}")
    rows = np.genfromtxt(out, delimiter=",", names=True, deletechars="")
    grid = np.linspace(0.0, T, int(round(T / dt)) + 1)
    last = np.searchsorted(rows["time"], grid * (1 + 1e-12), side="right") - 1
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    return rows[var][last], cpu


def fmusim_row(name, path, T, start, var, in_process, ref, scale, repeat, tmp) -> list:
    """[model, FMU error ME, CS, in-process rtol at equal accuracy (ME, CS) and its errors,
    median CPU times [ms] of in-process (ME, CS rtol), fmusim ME, CS, start-up; ratios ME/in,
    CS/in (fmusim net of its start-up)]."""
    dt = T / 200
    err = lambda v: float(np.max(np.abs(np.asarray(v) - ref)) / scale)  # noqa: E731
    run = {"me": lambda: fmusim(path, "me", T, dt, start, var, tmp / "me.csv"),
           "cs": lambda: fmusim(path, "cs", T, dt, start, var, tmp / "cs.csv"),
           "startup": lambda: fmusim(path, "cs", dt, dt, start, var, tmp / "up.csv")}
    e = {k: err(run[k]()[0]) for k in ("me", "cs")}
    rtol = {k: next((rt for rt in IN_PROCESS_RTOLS
                     if err(in_process(rt, rt / 100)[var]) <= e[k]), IN_PROCESS_RTOLS[-1])
            for k in ("me", "cs")}
    e_in = {k: err(in_process(rtol[k], rtol[k] / 100)[var]) for k in ("me", "cs")}

    def in_cpu(k):
        t0 = time.process_time()
        in_process(rtol[k], rtol[k] / 100)
        return None, time.process_time() - t0
    run.update(in_me=lambda: in_cpu("me"), in_cs=lambda: in_cpu("cs"))
    cpu = {k: [] for k in run}
    for _ in range(max(repeat, 5)):
        for k, fn in run.items():
            cpu[k].append(fn()[1])
    c = {k: float(np.median(v)) for k, v in cpu.items()}
    return [name, e["me"], e["cs"], rtol["me"], rtol["cs"], e_in["me"], e_in["cs"],
            c["in_me"] * 1e3, c["in_cs"] * 1e3, c["me"] * 1e3, c["cs"] * 1e3,
            c["startup"] * 1e3, (c["me"] - c["startup"]) / c["in_me"],
            (c["cs"] - c["startup"]) / c["in_cs"]]


def count_me_rhs(unzipped: Path, md, **kw) -> int:
    """Right-hand sides fmpy's CVode asks for in one model-exchange run."""
    fmu = instantiate_fmu(str(unzipped), md, "ModelExchange")
    calls = 0
    get_derivatives = fmu.getDerivatives

    def counted(*args):
        nonlocal calls
        calls += 1
        return get_derivatives(*args)

    fmu.getDerivatives = counted
    simulate_fmu(str(unzipped), model_description=md, fmu_instance=fmu, **kw)
    fmu.freeInstance()
    return calls


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    rows, shares, native = [], [], []
    with tempfile.TemporaryDirectory() as tmp:
        rhs_timer = build_rhs_timer(Path(tmp))
        for name, (make, T, start, var) in CASES.items():
            compiled = acausal.compile(make())
            path = compiled.export_fmu(Path(tmp) / f"{name}.fmu", stop_time=T)
            unzipped = extract(str(path), unzipdir=str(Path(tmp) / name))
            md = read_model_description(unzipped)
            grid = np.linspace(0.0, T, 201)
            inputs = {k: v for k, v in start.items() if k in compiled.input_names}
            x0 = {k: v for k, v in start.items() if k not in inputs}

            def in_process(rtol=1e-8, atol=1e-10):
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    return compiled.simulate(T, t=grid, inputs=inputs, x0=x0, rtol=rtol,
                                             atol=atol)

            settings = dict(validate=False, stop_time=T, output_interval=T / 200,
                            start_values=dict(start), relative_tolerance=1e-8,
                            record_events=False, output=[var])

            def fmu(kind):
                return simulate_fmu(unzipped, model_description=md, fmi_type=kind, **settings)

            ref = in_process(1e-12, 1e-14)[var]
            scale = np.max(np.abs(ref))
            t_in, r_in = best_of(in_process, args.repeat)
            t_me, r_me = best_of(lambda: fmu("ModelExchange"), args.repeat)
            t_cs, r_cs = best_of(lambda: fmu("CoSimulation"), args.repeat)
            err = [np.max(np.abs(np.asarray(r[var]) - ref)) / scale for r in (r_in, r_me, r_cs)]
            rows.append([name, t_in * 1e3, t_me * 1e3, t_cs * 1e3, t_me / t_in, t_cs / t_in,
                         *err])
            if FMUSIM.is_file():
                native.append(fmusim_row(name, Path(path), T, start, var, in_process, ref,
                                         scale, args.repeat, Path(tmp)))
            n_rhs = count_me_rhs(unzipped, md, **settings)
            t_rhs = fmu_rhs_seconds(rhs_timer, unzipped, md, start)
            shares.append([name, n_rhs, t_rhs * 1e6, (t_me - n_rhs * t_rhs) / n_rhs * 1e6,
                           100 * n_rhs * t_rhs / t_me])
    print_table(["model", "in-proc ms", "FMU ME ms", "FMU CS ms", "ME/in", "CS/in",
                 "err in", "err ME", "err CS"], rows,
                ["{:>10s}"] + ["{:>10.1f}"] * 3 + ["{:>10.2f}"] * 2 + ["{:>10.1e}"] * 3)
    print("\nmodel exchange in fmpy: right-hand sides, the FMU's own time per rhs (C), fmpy's "
          "time per rhs (the rest of the ME time over the rhs count), FMU share of ME time")
    print_table(["model", "rhs calls", "FMU us/rhs", "fmpy us/rhs", "FMU share%"], shares,
                ["{:>10s}", "{:>10d}", "{:>10.3f}", "{:>10.2f}", "{:>10.2f}"])
    worst = max(max(r[4], r[5]) for r in rows)
    print(f"worst FMU/in-process ratio: {worst:.2f} (target <= 2)")
    if not native:
        print(f"\nfmusim not found ({FMUSIM}): the C importer's timings skipped")
        return
    print("\nin fmusim (C importer), tolerance 1e-8, against in-process at equal accuracy: "
          "medians of CPU times\nof interleaved runs [ms]")
    print_table(["model", "err ME", "err CS", "rtol ME", "rtol CS", "err in ME", "err in CS",
                 "in (ME)", "in (CS)", "fmusim ME", "fmusim CS", "start-up", "ME net/in",
                 "CS net/in"], native,
                ["{:>10s}"] + ["{:>10.1e}"] * 6 + ["{:>10.2f}"] * 5 + ["{:>10.2f}"] * 2)
    print("  err: max |signal - in-process at rtol 1e-12| / its peak; rtol ME / CS: the "
          "in-process rtol whose\n  error is no larger than fmusim's ME / CS (err in); in "
          "(ME), in (CS): in-process CPU time at those;\n  start-up: fmusim over one output "
          "interval (unzip, load, instantiate, initialize); net: minus it.\n  CPU times "
          "(user + system; fmusim's from the child process): the shared machine's load\n  "
          "falls on wall times far more")
    for r in native:
        print(f"  {r[0]:>10s}: ME {r[12]:.2f} (target <= 1.5) -> "
              f"{'met' if r[12] <= 1.5 else 'NOT met'}; CS {r[13]:.2f} (target <= 1) -> "
              f"{'met' if r[13] <= 1.0 else 'NOT met'}")


if __name__ == "__main__":
    main()
