"""Scaling benchmark: a chain of N masses and springs, acausal vs hand-written CasADi and scipy.

    wall | spring1 | mass1 | spring2 | mass2 | ... | massN <- F(t) = sin(2t)

m = 1 kg, c = 100 N/m (s_rel0 = 0, L = 0), everything at rest at t = 0; the force on the
last mass is a model Input given as a function of time. For each N:

- acausal: time to build the Model in Python, to compile it, and of ``simulate()`` (10 s,
  rtol 1e-8, atol 1e-10, cvodes BDF as the hand model, 101-point grid; integrator creation, initial values and
  reading every mass's trajectory from the Result included), plus the integrator run alone
  on acausal's equations (parameters folded in, as simulate() does);
- CasADi by hand: the same ODE as SX (build: expressions + integrator creation) and the
  integrator run (cvodes, same tolerances and grid); also its run with every parameter kept
  symbolic (m, L, c, s_rel0 per element), the form acausal compiles to;
- numpy + scipy: solve_ivp BDF with the (constant, sparse) Jacobian, and DOP853 / RK45;
- a tight-tolerance reference (scipy DOP853, rtol 1e-12, atol 1e-14): max error of every
  method's final state.

Prints two tables (times and ratios; errors) and the fitted exponent of compile time vs N.
Timings are wall-clock, best of ``--repeat`` runs for the simulations (compile: one run).

    python benchmarks/chain.py                 # N = 10, 100, 1000, 10000
    python benchmarks/chain.py --max-n 1000
"""
from __future__ import annotations

import argparse
import gc
import time

import casadi as ca
import numpy as np
import scipy.sparse as sps
from scipy.integrate import solve_ivp

import acausal
from timing import best_of, fit_exponent, print_table
from acausal.components.translational import Fixed, Force, Mass, Spring

MASS, STIFF, T_FINAL, RTOL, ATOL = 1.0, 100.0, 10.0, 1e-8, 1e-10
GRID = np.linspace(0.0, T_FINAL, 101)
TARGETS = {"compile_1000": 0.5, "compile_10000": 5.0, "sim_ratio": 1.3}


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


def acausal_final_state(res, n):
    return np.array([res[f"mass{i}.s"][-1] for i in range(1, n + 1)]
                    + [res[f"mass{i}.v"][-1] for i in range(1, n + 1)])


def acausal_integrator_only(compiled):
    """What simulate() does minus initialization and recorded variables: the integrator on
    the compiled DAE with the input and the parameter values substituted (creation, run)."""
    ode = ca.substitute([compiled.ode], [compiled.u, compiled.p],
                        [force(compiled.t), ca.SX(compiled.param_vector())])[0]
    dae = {"x": compiled.x, "t": compiled.t, "ode": ode}
    t0 = time.perf_counter()
    F = ca.integrator("acausal", "cvodes", dae, GRID[0], GRID[1:],
                      {"abstol": ATOL, "reltol": RTOL, "max_num_steps": 100000})
    t1 = time.perf_counter()
    _run_and_read(F, x0=np.zeros(compiled.x.numel()))
    t2 = time.perf_counter()
    return t1 - t0, t2 - t1


# ---- CasADi by hand -----------------------------------------------------------------------
def build_casadi(n: int, symbolic: bool = False):
    """The chain's ODE in x = [s; v] (centre positions, velocities). ``symbolic``: with every
    component's parameters as symbols (m, L, c, s_rel0 per element, wall s0), as acausal
    keeps them so that they can change without recompiling; else numbers folded in."""
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
    dae = {"x": ca.vertcat(s, v), "p": p, "t": t, "ode": ca.vertcat(v, acc)}
    F = ca.integrator("hand", "cvodes", dae, GRID[0], GRID[1:],
                      {"abstol": ATOL, "reltol": RTOL, "max_num_steps": 100000})
    p_val = np.concatenate([np.full(n, MASS), np.zeros(n), np.full(n, STIFF), np.zeros(n),
                            [0.0]]) if symbolic else np.zeros(0)
    return F, p_val


# ---- numpy + scipy ------------------------------------------------------------------------
def scipy_system(n: int):
    def rhs(t, y):
        s, v = y[:n], y[n:]
        f = STIFF * np.diff(s, prepend=0.0)
        fn = np.empty(n)
        fn[:-1] = f[1:]
        fn[-1] = np.sin(2.0 * t)
        return np.concatenate([v, (fn - f) / MASS])
    main = np.full(n, -2 * STIFF / MASS)
    main[-1] = -STIFF / MASS
    off = np.full(n - 1, STIFF / MASS)
    K = sps.diags([off, main, off], [-1, 0, 1])
    jac = sps.bmat([[None, sps.identity(n)], [K, None]], format="csc")
    return rhs, jac


def run_scipy(n, method, rtol=RTOL, atol=ATOL):
    rhs, jac = scipy_system(n)
    kw = {"jac": jac} if method in ("BDF", "Radau", "LSODA") else {}
    t0 = time.perf_counter()
    sol = solve_ivp(rhs, (0.0, T_FINAL), np.zeros(2 * n), method=method, t_eval=GRID,
                    rtol=rtol, atol=atol, **kw)
    dt = time.perf_counter() - t0
    if not sol.success:
        raise RuntimeError(f"scipy {method} failed: {sol.message}")
    return dt, sol.y[:, -1]




def _simulate_and_read(compiled, n):
    res = compiled.simulate(T_FINAL, t=GRID, inputs={"F": force}, rtol=RTOL, atol=ATOL,
                            solver="cvodes")     # the hand model's method (small N: not Adams)
    return res, acausal_final_state(res, n)


def _run_and_read(F, **args) -> dict:
    sol = F(**args)
    sol["xf"] = sol["xf"].full()
    return sol


def bench(n: int, repeat: int, explicit: bool) -> dict:
    r = {"N": n}
    gc.collect()
    t0 = time.perf_counter()
    model = build_acausal(n)
    r["ac_build"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    compiled = acausal.compile(model)
    r["ac_compile"] = time.perf_counter() - t0
    # simulate() and reading the trajectories of every mass (states are read directly; other
    # recorded variables would be built on first access): the first call after compile, what
    # a user waits for, and the best of the repeats
    t0 = time.perf_counter()
    _simulate_and_read(compiled, n)
    r["ac_first"] = time.perf_counter() - t0
    r["ac_sim"], (res, x_ac) = best_of(lambda: _simulate_and_read(compiled, n), repeat)
    create, run = zip(*[acausal_integrator_only(compiled) for _ in range(repeat)])
    r["ac_int_create"], r["ac_int_run"] = min(create), min(run)

    t0 = time.perf_counter()
    F, _ = build_casadi(n)
    r["ca_build"] = time.perf_counter() - t0
    # the run and its trajectories as numpy arrays (what simulate() hands the user)
    r["ca_sim"], sol = best_of(lambda: _run_and_read(F, x0=np.zeros(2 * n)), repeat)
    x_ca = sol["xf"][:, -1]
    Fp, p_val = build_casadi(n, symbolic=True)
    r["cap_sim"], sol = best_of(lambda: _run_and_read(Fp, x0=np.zeros(2 * n), p=p_val), repeat)
    r["ac_vs_cap"] = np.max(np.abs(sol["xf"][:, -1] - x_ca))

    r["bdf"], x_bdf = min((run_scipy(n, "BDF") for _ in range(repeat)), key=lambda a: a[0])
    if explicit:
        r["dop853"], x_dop = min((run_scipy(n, "DOP853") for _ in range(repeat)),
                                 key=lambda a: a[0])
        r["rk45"], x_rk = run_scipy(n, "RK45")
    _, x_ref = run_scipy(n, "DOP853", rtol=1e-12, atol=1e-14)
    scale = np.max(np.abs(x_ref))
    r["scale"] = scale
    r["err_ac"] = np.max(np.abs(x_ac - x_ref))
    r["err_ca"] = np.max(np.abs(x_ca - x_ref))
    r["err_bdf"] = np.max(np.abs(x_bdf - x_ref))
    if explicit:
        r["err_dop853"] = np.max(np.abs(x_dop - x_ref))
        r["err_rk45"] = np.max(np.abs(x_rk - x_ref))
    r["ac_vs_ca"] = np.max(np.abs(x_ac - x_ca))
    return r






def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--max-n", type=int, default=10000, help="largest N to run (default 10000)")
    ap.add_argument("--ns", type=int, nargs="*", default=[10, 100, 1000, 10000],
                    help="chain lengths (default 10 100 1000 10000)")
    ap.add_argument("--repeat", type=int, default=3, help="runs per simulation timing (best)")
    ap.add_argument("--no-explicit", action="store_true", help="skip scipy RK45 / DOP853")
    args = ap.parse_args(argv)
    ns = [n for n in args.ns if n <= args.max_n]

    rows = []
    for n in ns:
        r = bench(n, args.repeat, not args.no_explicit)
        rows.append(r)
        print(f"N={n:6d} done: compile {r['ac_compile']:.3f} s, simulate {r['ac_sim']:.3f} s, "
              f"CasADi {r['ca_build']:.3f} + {r['ca_sim']:.3f} s", flush=True)
    explicit = not args.no_explicit

    print(f"\nchain of N masses and springs, {T_FINAL:g} s, rtol {RTOL:g}, atol {ATOL:g}, "
          f"{len(GRID)}-point grid; wall-clock times [s] (simulations: best of {args.repeat})")
    print_table(["N", "build", "compile", "1st sim()", "simulate()", "int.create", "int.run",
                 "CasADi bld", "CasADi run", "1st ratio", "sim ratio", "run ratio", "CasADi(p)",
                 "run/(p)"],
                [[r["N"], r["ac_build"], r["ac_compile"], r["ac_first"], r["ac_sim"],
                  r["ac_int_create"], r["ac_int_run"], r["ca_build"], r["ca_sim"],
                  r["ac_first"] / (r["ca_build"] + r["ca_sim"]),
                  r["ac_sim"] / (r["ca_build"] + r["ca_sim"]), r["ac_int_run"] / r["ca_sim"],
                  r["cap_sim"], r["ac_int_run"] / r["cap_sim"]]
                 for r in rows], "{:10.4g}")
    print("  build, compile, simulate(): acausal (simulate() creates its integrator, computes "
          "initial values\n  and reads every mass's trajectory); 1st sim(): the first call "
          "after compile; int.create / int.run:\n  a cvodes integrator on acausal's DAE alone; "
          "CasADi bld / run: the hand-written SX model\n  (expressions + integrator creation / "
          "the run). 1st ratio, sim ratio = 1st sim(), simulate() / (CasADi\n  bld + run); run "
          "ratio = int.run / CasADi run. CasADi(p): run of the hand-written "
          "model with every parameter symbolic, as acausal keeps them;\n  run/(p) = int.run / "
          "CasADi(p)")
    head = ["N", "scipy BDF", "BDF/CasADi"]
    if explicit:
        head += ["DOP853", "DOP/CasADi", "RK45", "RK45/CasADi"]
    print_table(head, [[r["N"], r["bdf"], r["bdf"] / r["ca_sim"]]
                  + ([r["dop853"], r["dop853"] / r["ca_sim"], r["rk45"], r["rk45"] / r["ca_sim"]]
                     if explicit else []) for r in rows], "{:10.4g}")
    print("  numpy + scipy solve_ivp (BDF with the sparse Jacobian); ratios against the CasADi run")

    print("\nmax |final state - reference|  (reference: scipy DOP853, rtol 1e-12, atol 1e-14)")
    head = ["N", "max|x_ref|", "acausal", "CasADi", "ac-CasADi", "CasADi(p)-", "scipy BDF"]
    if explicit:
        head += ["DOP853", "RK45"]
    print_table(head, [[r["N"], r["scale"], r["err_ac"], r["err_ca"], r["ac_vs_ca"], r["ac_vs_cap"],
                   r["err_bdf"]]
                  + ([r["err_dop853"], r["err_rk45"]] if explicit else []) for r in rows],
           "{:10.3e}")
    print("  ac-CasADi: |acausal - hand-written CasADi|; CasADi(p)-: |CasADi(p) - CasADi|")

    ns_fit = [r["N"] for r in rows]
    print()
    for label, key in (("compile", "ac_compile"), ("build + compile", None)):
        ts = [r["ac_compile"] + (r["ac_build"] if key is None else 0) for r in rows]
        big = [(n, t) for n, t in zip(ns_fit, ts) if n >= 100]
        msg = f"fitted exponent of {label} time (t ~ N^k): k = {fit_exponent(ns_fit, ts):.2f}"
        if len(big) >= 2:
            msg += f" (N >= 100: k = {fit_exponent(*zip(*big)):.2f})"
        print(msg)

    print("\ntargets:")
    by_n = {r["N"]: r for r in rows}
    for n, key in ((1000, "compile_1000"), (10000, "compile_10000")):
        if n in by_n:
            t = by_n[n]["ac_compile"]
            ok = "met" if t < TARGETS[key] else "NOT met"
            print(f"  compile N={n}: {t:.3f} s (target < {TARGETS[key]:g} s) -> {ok}")
        else:
            print(f"  compile N={n}: not run (target < {TARGETS[key]:g} s)")
    for r in rows:
        if r["N"] not in (1000, 10000):
            continue
        first = r["ac_first"] / (r["ca_build"] + r["ca_sim"])
        ratio = r["ac_sim"] / (r["ca_build"] + r["ca_sim"])
        ok = "met" if first <= TARGETS["sim_ratio"] else "NOT met"
        print(f"  simulation N={r['N']}: first simulate()/CasADi = {first:.2f} (best "
              f"{ratio:.2f}, run alone {r['ac_int_run'] / r['ca_sim']:.2f}; target <= "
              f"{TARGETS['sim_ratio']}x) -> {ok}")


if __name__ == "__main__":
    main()
