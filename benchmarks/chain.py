"""Scaling benchmark: a chain of N masses and springs, acausal vs hand-written CasADi and scipy.

    wall | spring1 | mass1 | spring2 | mass2 | ... | massN <- F(t) = sin(2t)

m = 1 kg, c = 100 N/m (s_rel0 = 0, L = 0), everything at rest at t = 0; the force on the
last mass is a model Input given as a function of time. 10 s, rtol 1e-8, atol 1e-10, a
101-point grid. The chain is not stiff (its highest frequency is 2·sqrt(c/m) = 20 rad/s):
the CasADi contenders use CVODES (BDF, as simulate() picks it here), scipy uses DOP853, the
right method for a non-stiff problem at tight tolerances. Contenders, run interleaved
(``--repeat`` rounds), each timed in the phases a user waits for:

- acausal end to end: build the Model in Python, compile it, the first ``simulate()`` after
  compile (integrator creation, initial values, the run) and reading every mass's position and
  velocity from the Result; and, apart from the total, the first read of a variable that is
  no state (a spring's force: every recorded variable is built and evaluated then);
- acausal's equations alone: a CVODES integrator on the compiled ODE with the parameters
  and the input substituted (as simulate() does): creation, run;
- CasADi by hand: the ODE as SX with numbers (build: expressions), integrator creation, the
  run and its trajectories as numpy arrays; and the same with every parameter symbolic (m, L,
  c, s_rel0 per element), the form acausal compiles to (run only);
- scipy: solve_ivp DOP853 with a vectorized numpy right-hand side (run).

Printed per N: median (min–max) of each phase, the end-to-end ratio acausal / CasADi by
hand (target ≤ 2), and every contender's max error of the final state against a tight
reference (scipy DOP853, rtol 1e-12, atol 1e-14). ``--scale N``: compile time and peak
memory of an N-mass chain in a fresh process (target at 100 000: < 15 s, < 1 GB).

    python benchmarks/chain.py                      # N = 1000, 10000 (~ 2 min)
    python benchmarks/chain.py --ns 100 1000 --repeat 5
    python benchmarks/chain.py --ns --scale 100000
"""
from __future__ import annotations

from timing import (Phases, fit_exponent, interleaved, maxrss_mb, median,  # first: pins
                    print_table, spread)                                 # BLAS threads

import argparse
import subprocess
import sys
import time

import casadi as ca
import numpy as np
from scipy.integrate import solve_ivp

import acausal
from acausal.components.translational import Fixed, Force, Mass, Spring

MASS, STIFF, T_FINAL, RTOL, ATOL = 1.0, 100.0, 10.0, 1e-8, 1e-10
GRID = np.linspace(0.0, T_FINAL, 101)
CVODES = {"abstol": ATOL, "reltol": RTOL, "max_num_steps": 100000}
TARGET_E2E, TARGET_SCALE = 2.0, (15.0, 1024.0)       # ratio; s, MB at 100 000 masses


def force(t):
    """F(t) [N]; works on floats, numpy arrays and CasADi symbols."""
    return np.sin(2.0 * t) if not isinstance(t, (ca.SX, ca.MX)) else ca.sin(2.0 * t)


# ---- acausal ------------------------------------------------------------------------------
def build_acausal(n: int) -> acausal.Model:
    m = acausal.Model(f"chain{n}")
    m.wall = Fixed()
    prev = m.wall.flange
    for i in range(1, n + 1):
        spring, mass = Spring(c=STIFF), Mass(m=MASS)
        setattr(m, f"spring{i}", spring)
        setattr(m, f"mass{i}", mass)
        m.connect(prev, spring.flange_a)
        m.connect(spring.flange_b, mass.flange_a)
        prev = mass.flange_b
    m.push, m.F = Force(), acausal.Input(unit="N")
    m.connect(m.F.y, m.push.f)
    m.connect(m.push.flange, prev)
    return m


def acausal_run(n: int, keep: dict) -> dict:
    """End to end: build, compile, first simulate() and reading every state; the compiled
    model is kept in ``keep``."""
    ph = Phases()
    model = build_acausal(n)
    ph.lap("build")
    compiled = acausal.compile(model)
    ph.lap("compile")
    res = compiled.simulate(T_FINAL, t=GRID, inputs={"F": force}, rtol=RTOL, atol=ATOL,
                            solver="cvodes")
    ph.lap("simulate")
    s = np.array([res[f"mass{i}.s"] for i in range(1, n + 1)])
    v = np.array([res[f"mass{i}.v"] for i in range(1, n + 1)])
    ph.lap("read")
    res["spring1.f"]             # a first variable that is no state: every one is evaluated
    ph.lap("force")
    ph["total"] = sum(ph[k] for k in ("build", "compile", "simulate", "read"))
    ph["xf"] = np.concatenate([s[:, -1], v[:, -1]])
    keep["compiled"] = compiled
    return ph


def acausal_equations_run(compiled) -> dict:
    """A CVODES integrator on acausal's ODE, parameters and input substituted."""
    ph = Phases()
    ode = ca.substitute([compiled.ode], [compiled.u, compiled.p],
                        [force(compiled.t), ca.SX(compiled.param_vector())])[0]
    F = ca.integrator("acausal", "cvodes", {"x": compiled.x, "t": compiled.t, "ode": ode},
                      GRID[0], GRID[1:], CVODES)
    ph.lap("create")
    xf = F(x0=np.zeros(compiled.x.numel()))["xf"].full()
    ph.lap("run")
    ph["xf"] = _ordered(compiled, xf[:, -1])
    return ph


def _ordered(compiled, x):
    """A final state of acausal's x as [s_1..s_N, v_1..v_N]."""
    n = compiled.x.numel() // 2
    where = {name: i for i, name in enumerate(compiled.x_names)}
    return np.array([x[where[f"mass{i}.{k}"]] for k in ("s", "v") for i in range(1, n + 1)])


# ---- CasADi by hand -----------------------------------------------------------------------
def casadi_ode(n: int, symbolic: bool = False):
    """(x, p, t, ode) of the chain in x = [s; v] (positions, velocities). ``symbolic``: with
    every component's parameters as symbols (m, L, c, s_rel0 per element, wall s0), as
    acausal keeps them so that they can change without recompiling; else numbers."""
    s, v, t = ca.SX.sym("s", n), ca.SX.sym("v", n), ca.SX.sym("t")
    if symbolic:
        m, L, c, s_rel0 = (ca.SX.sym(k, n) for k in ("m", "L", "c", "s_rel0"))
        s0 = ca.SX.sym("s0")
        right_end = ca.vertcat(s0, s[:n - 1] + L[:n - 1] / 2)       # flange_b of body i-1
        f = c * ((s - L / 2 - right_end) - s_rel0)
        acc = (ca.vertcat(f[1:], ca.sin(2 * t)) - f) / m
        p = ca.vertcat(m, L, c, s_rel0, s0)
    else:
        f = STIFF * (s - ca.vertcat(0, s[:n - 1]))            # spring i's tension
        acc = (ca.vertcat(f[1:], ca.sin(2 * t)) - f) / MASS
        p = ca.SX(0, 1)
    return ca.vertcat(s, v), p, t, ca.vertcat(v, acc)


def casadi_run(n: int) -> dict:
    ph = Phases()
    x, p, t, ode = casadi_ode(n)
    ph.lap("build")
    F = ca.integrator("hand", "cvodes", {"x": x, "t": t, "ode": ode}, GRID[0], GRID[1:],
                      CVODES)
    ph.lap("create")
    X = F(x0=np.zeros(2 * n))["xf"].full()
    ph.lap("run")
    ph["total"] = ph["build"] + ph["create"] + ph["run"]
    ph["xf"] = X[:, -1]
    return ph


def casadi_symbolic_run(n: int) -> dict:
    x, p, t, ode = casadi_ode(n, symbolic=True)
    F = ca.integrator("hand_p", "cvodes", {"x": x, "p": p, "t": t, "ode": ode}, GRID[0],
                      GRID[1:], CVODES)
    p_val = np.concatenate([np.full(n, MASS), np.zeros(n), np.full(n, STIFF), np.zeros(n),
                            [0.0]])
    ph = Phases()
    X = F(x0=np.zeros(2 * n), p=p_val)["xf"].full()
    ph.lap("run")
    ph["xf"] = X[:, -1]
    return ph


# ---- numpy + scipy ------------------------------------------------------------------------
def scipy_rhs(n: int):
    def rhs(t, y):
        s, v = y[:n], y[n:]
        f = STIFF * np.diff(s, prepend=0.0)
        fn = np.empty(n)
        fn[:-1] = f[1:]
        fn[-1] = np.sin(2.0 * t)
        return np.concatenate([v, (fn - f) / MASS])
    return rhs


def scipy_run(n: int, rtol=RTOL, atol=ATOL) -> dict:
    ph = Phases()
    sol = solve_ivp(scipy_rhs(n), (0.0, T_FINAL), np.zeros(2 * n), method="DOP853",
                    t_eval=GRID, rtol=rtol, atol=atol)
    ph.lap("run")
    if not sol.success:
        raise RuntimeError(f"scipy DOP853 failed: {sol.message}")
    ph["xf"] = sol.y[:, -1]
    return ph


# ---- compile scale in a fresh process -----------------------------------------------------
def scale_child(n: int) -> None:
    t0 = time.perf_counter()
    model = build_acausal(n)
    t1 = time.perf_counter()
    acausal.compile(model)
    t2 = time.perf_counter()
    print(f"{t1 - t0} {t2 - t1} {maxrss_mb()}")


def scale(n: int) -> tuple[float, float, float]:
    """(build [s], compile [s], peak memory [MB]) of an n-mass chain in a fresh process."""
    out = subprocess.run([sys.executable, __file__, "--scale-child", str(n)], check=True,
                         capture_output=True, text=True).stdout.split()
    return tuple(float(v) for v in out[-3:])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ns", type=int, nargs="*", default=[1000, 10000],
                    help="chain lengths (default 1000 10000)")
    ap.add_argument("--repeat", type=int, default=3, help="interleaved rounds (default 3)")
    ap.add_argument("--scale", type=int, nargs="*", default=[],
                    help="chain lengths to compile in a fresh process (time, memory)")
    ap.add_argument("--scale-child", type=int, help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.scale_child:
        return scale_child(args.scale_child)

    rows, errors, e2e, compile_time = [], [], {}, {}
    for n in args.ns:
        keep = {}
        runs = interleaved({"acausal": lambda: acausal_run(n, keep), "CasADi": lambda: casadi_run(n),
                            "CasADi(p)": lambda: casadi_symbolic_run(n),
                            "scipy": lambda: scipy_run(n)}, args.repeat)
        compiled = keep.pop("compiled")
        runs["equations"] = interleaved({"eq": lambda: acausal_equations_run(compiled)},
                                        args.repeat)["eq"]
        ac, hand = runs["acausal"], runs["CasADi"]
        e2e[n] = median(ac, "total") / median(hand, "total")
        compile_time[n] = median(ac, "compile")
        rows.append([n, spread(ac, "build"), spread(ac, "compile"), spread(ac, "simulate"),
                     spread(ac, "read"), spread(ac, "total"), spread(ac, "force"),
                     spread(hand, "build"),
                     spread(hand, "create"), spread(hand, "run"), spread(hand, "total"), e2e[n],
                     spread(runs["equations"], "create"), spread(runs["equations"], "run"),
                     spread(runs["CasADi(p)"], "run"), spread(runs["scipy"], "run")])
        x_ref = scipy_run(n, rtol=1e-12, atol=1e-14)["xf"]
        errors.append([n, float(np.max(np.abs(x_ref)))] + [
            float(np.max(np.abs(runs[k][-1]["xf"] - x_ref)))
            for k in ("acausal", "equations", "CasADi", "CasADi(p)", "scipy")])
        print(f"N = {n} done", flush=True)

    if rows:
        print(f"\nchain of N masses and springs, {T_FINAL:g} s, rtol {RTOL:g}, atol {ATOL:g}, "
              f"{len(GRID)}-point grid; times in ms, median (min–max) of {args.repeat} "
              "interleaved rounds")
        s = "{:>24s}"
        print_table(["N", "ac build", "ac compile", "ac 1st sim", "ac read", "ac total",
                     "ac 1st force", "CasADi bld", "CasADi crt", "CasADi run", "CasADi tot",
                     "e2e ratio", "eq create", "eq run", "CasADi(p)", "scipy DOP"], rows,
                    ["{:>10d}"] + [s] * 10 + ["{:>10.2f}"] + [s] * 4)
        print("  ac: acausal end to end (build, compile, first simulate(), reading every "
              "state; 1st force: then reading a spring's force, not in the total);\n  CasADi: the hand-written SX model (build expressions, create the "
              "integrator, run); e2e ratio = ac total / CasADi total (target <= "
              f"{TARGET_E2E:g});\n  eq: CVODES on acausal's compiled ODE alone; CasADi(p): "
              "the hand model with every parameter symbolic; scipy DOP853")
        print("\nmax |final state - reference|  (reference: scipy DOP853, rtol 1e-12, "
              "atol 1e-14)")
        print_table(["N", "max|x_ref|", "acausal", "ac eq", "CasADi", "CasADi(p)", "scipy DOP"],
                    errors, "{:10.3e}")
        if len(rows) > 1:
            ns = list(e2e)
            print(f"fitted exponent of the median compile time (t ~ N^k): k = "
                  f"{fit_exponent(ns, [compile_time[n] for n in ns]):.2f}")
        for n, r in e2e.items():
            verdict = "met" if r <= TARGET_E2E else "NOT met"
            print(f"end to end N = {n}: {r:.2f}x hand-written CasADi (target <= "
                  f"{TARGET_E2E:g}x) -> {verdict}")
    for n in args.scale:
        build, comp, mem = scale(n)
        ok = comp < TARGET_SCALE[0] and mem < TARGET_SCALE[1]
        print(f"compile N = {n} in a fresh process: build {build:.2f} s, compile {comp:.2f} s, "
              f"peak memory {mem:.0f} MB (target at 100000: < {TARGET_SCALE[0]:g} s, < "
              f"{TARGET_SCALE[1]:g} MB) -> {'met' if ok else 'NOT met'}")


if __name__ == "__main__":
    main()
