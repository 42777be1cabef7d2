"""Peer benchmark: 3-D robot arms and chains, acausal vs Pinocchio (ABA) + scipy DOP853.

Cases, each built by acausal from MultiBody components and by Pinocchio from the same data:
- ``ur5``: the 6-axis UR5 arm of example-robot-data, read from its URDF by
  ``acausal.multibody.from_urdf`` and by ``pinocchio.buildModelFromUrdf``;
- ``chain N`` (N = 6, 16, 32, 64 by default): N revolute joints in series whose axes cycle
  through z, y, x, each after a FixedRotation mount (0.25 m along x, 30° about an oblique
  axis), with a Body of full inertia tensor (``acausal.models.chain``; Pinocchio:
  RevoluteUnaligned joints with the same placements and inertias).
Gravity 9.81 m/s² along −z, no damping.

Measured in the same run, for each case:
1. compile time: ``acausal.compile`` (the Model built before), the first in the process
   ("cold": it also builds the cached CasADi Functions of the joint and frame relations,
   once per process) and the best of the repeats ("warm"); Pinocchio's model build;
2. one right-hand side [µs]: acausal's ODE with the parameter values folded in, as
   ``simulate()`` hands it to the integrator, per evaluation inside ``map(K)`` (CasADi's
   virtual machine, no Python overhead), its instruction count; with ``--jit`` the same
   compiled to C by CasADi's JIT (gcc -O2), the code an exported FMU runs; Pinocchio's
   ``pin.aba`` called from Python (its C++ time plus ~1 µs of binding overhead);
3. simulation of 1 s (long chains turn chaotic later), released at rest from q = 0.3 rad at every joint, 101-point grid:
   Pinocchio ABA + scipy DOP853 (rtol 1e-8, atol 1e-10) against ``compiled.simulate``
   (its default solver choice) with rtol tightened in half decades (atol = rtol/100) until
   its final-state error is no larger than DOP853's; the errors are against DOP853 + ABA at
   rtol 1e-12, atol 1e-14.
4. ``simulate(codegen=True)`` (unless --no-codegen, or without a C compiler): the first run
   with an empty cache (generating the C and gcc counted), the first run of a freshly
   compiled copy (library from the disk cache), the built library's rhs against ABA, and
   the run at equal accuracy interleaved with DOP853 + ABA and the in-process run; and
   ``simulate(codegen=True, solver="dop853")`` (scipy's DOP853 on the generated C, the
   reference's own method) at equal accuracy, interleaved with them.
Accelerations agree: max |q''(acausal) − q''(ABA)| / max(1, |q''|) at a random state.

Targets: compile of the 6-axis arm < 0.2 s, right-hand side <= 2x ABA, simulation <= 2x
Pinocchio. Where the time goes: the right-hand side has about as many operations as
Pinocchio's ABA (one spatial recursion plus the Coriolis and gravity terms of the Lagrangian
by AD), but CasADi's virtual machine runs them several times slower than compiled C++; the
same code compiled to C (--jit, what a native FMU runs) is on par with ABA.

    python benchmarks/multibody_3d.py                  # ur5 and N = 6, 16, 32, 64
    python benchmarks/multibody_3d.py --ns 6 16 --jit

Requires the ``bench`` extra (pin, scipy, example-robot-data).
"""
from __future__ import annotations

import argparse
import atexit
import shutil
import tempfile
import time
from importlib.metadata import distribution

from timing import best_of, fit_exponent, print_table  # first: pins BLAS threads
import casadi as ca
import numpy as np
from scipy.integrate import solve_ivp

import acausal
from acausal.models import chain
from acausal.multibody import from_urdf
from pendulum import codegen_runs, mapped_per_eval, per_call, report_codegen, use_codegen_cache

G = 9.81
Q0, T_FINAL, RTOL, ATOL = 0.3, 1.0, 1e-8, 1e-10
REF_RTOL, REF_ATOL = 1e-12, 1e-14
MATCH_RTOLS = tuple(10.0 ** -k for k in np.arange(8.0, 11.01, 0.5))
GRID = np.linspace(0.0, T_FINAL, 101)
TARGETS = {"compile_arm": 0.2, "rhs_ratio": 2.0, "sim_ratio": 2.0}
UR5 = "cmeel.prefix/share/example-robot-data/robots/ur_description/urdf/" \
      "ur5_joint_limited_robot.urdf"
MOUNT_AXIS = (1.0, 1.0, 1.0)


# ---- cases ----------------------------------------------------------------------------------
def chain_links(n: int) -> list[dict]:
    """Link data of the N-link chain (``acausal.models.chain``'s format)."""
    axes = [(0.0, 0.0, 1.0), (0.0, 1.0, 0.0), (1.0, 0.0, 0.0)]
    return [dict(parent=i - 1, kind="R", r=(0.25, 0.0, 0.0), n=MOUNT_AXIS, angle=30.0,
                 axis=axes[i % 3],
                 body=dict(m=1.0, r_CM=(0.12, 0.01, 0.0), I_11=0.002, I_22=0.01, I_33=0.011,
                           I_21=0.0005, I_31=0.0002, I_32=-0.0003))
            for i in range(n)]


def pinocchio_chain(links):
    import pinocchio as pin
    model = pin.Model()
    e = np.asarray(MOUNT_AXIS) / np.linalg.norm(MOUNT_AXIS)
    parent = 0
    for i, link in enumerate(links):
        a = np.radians(link["angle"])     # MSL's planarRotation(e, a).T is R(e, a)ᵀ
        K = np.array([[0, -e[2], e[1]], [e[2], 0, -e[0]], [-e[1], e[0], 0]])
        R = np.eye(3) + np.sin(a) * K + (1 - np.cos(a)) * K @ K
        parent = model.addJoint(parent, pin.JointModelRevoluteUnaligned(np.array(link["axis"])),
                                pin.SE3(R, np.array(link["r"])), f"joint{i}")
        b = link["body"]
        I = np.array([[b["I_11"], b["I_21"], b["I_31"]], [b["I_21"], b["I_22"], b["I_32"]],
                      [b["I_31"], b["I_32"], b["I_33"]]])
        model.appendBodyToJoint(parent, pin.Inertia(b["m"], np.array(b["r_CM"]), I),
                                pin.SE3.Identity())
    model.gravity.linear = np.array([0.0, 0.0, -G])
    return model


def case(name: str, n: int | None):
    """(build acausal Model, build Pinocchio model, joint names in Pinocchio's order)."""
    if name == "ur5":
        import pinocchio as pin
        path = str(distribution("example-robot-data").locate_file(UR5))

        def pin_model():
            m = pin.buildModelFromUrdf(path)
            m.gravity.linear = np.array([0.0, 0.0, -G])
            return m
        return (lambda: from_urdf(path, gravity=(0.0, 0.0, -G))), pin_model, None
    links = chain_links(n)
    return ((lambda: chain(links, g=G, n=(0.0, 0.0, -1.0))), (lambda: pinocchio_chain(links)),
            [f"joint{i}" for i in range(n)])


# ---- one case -------------------------------------------------------------------------------
def bench(name: str, n: int | None, repeat: int, jit: bool, codegen: bool = False) -> dict:
    import pinocchio as pin
    build, build_pin, _ = case(name, n)
    r = {"case": name if n is None else f"chain {n}"}
    model = build()
    t0 = time.perf_counter()
    compiled = acausal.compile(model)
    r["compile_cold"] = time.perf_counter() - t0
    fresh = [build() for _ in range(repeat)]
    r["compile"], compiled = best_of(lambda: acausal.compile(fresh.pop()), repeat, budget=5.0)
    r["method"] = compiled.method
    r["pin_build"], pmodel = best_of(build_pin, repeat, budget=2.0)
    pdata = pmodel.createData()
    nq = pmodel.nq
    joints = list(pmodel.names)[1:]
    coords = [f"{j}.phi" for j in joints] + [f"{j}.w" for j in joints]
    perm = np.array([compiled.x_names.index(k) for k in coords])     # x[perm] = [q; w]
    inv = np.argsort(perm)

    # (2) one right-hand side
    rng = np.random.default_rng(1)
    y = np.concatenate([rng.uniform(-1, 1, nq), rng.uniform(-2, 2, nq)])
    p = compiled.param_vector()
    folded = ca.Function("folded", [compiled.x],
                         [ca.substitute(compiled.ode, compiled.p, ca.SX(p))])
    a_ac = np.asarray(folded(y[inv]), dtype=float).ravel()[perm][nq:]
    tau = np.zeros(nq)
    a_pin = pin.aba(pmodel, pdata, y[:nq], y[nq:], tau)
    r["dev"] = np.max(np.abs(a_ac - a_pin)) / max(1.0, np.max(np.abs(a_pin)))
    r["instr"] = folded.n_instructions()
    r["rhs"] = mapped_per_eval(folded, [y[inv]])
    r["rhs_jit"] = float("nan")
    if jit:                   # gcc's files in a temporary directory, removed at exit
        tmp = tempfile.mkdtemp(prefix="acausal_jit_")
        atexit.register(shutil.rmtree, tmp, ignore_errors=True)
        fj = ca.Function("folded_jit", [compiled.x], [folded(compiled.x)],
                         {"jit": True, "compiler": "shell",
                          "jit_options": {"flags": ["-O2"], "directory": tmp + "/"}})
        r["rhs_jit"] = mapped_per_eval(fj, [y[inv]])
    r["aba"] = per_call(lambda: pin.aba(pmodel, pdata, y[:nq], y[nq:], tau))

    # (3) simulation at equal accuracy
    y0 = np.concatenate([np.full(nq, Q0), np.zeros(nq)])
    x0 = {f"{j}.phi": Q0 for j in joints}

    def f_pin(t, yy):
        return np.concatenate([yy[nq:], pin.aba(pmodel, pdata, yy[:nq], yy[nq:], tau)])

    def run_pin(rtol=RTOL, atol=ATOL):
        sol = solve_ivp(f_pin, (0.0, T_FINAL), y0, method="DOP853", t_eval=GRID, rtol=rtol,
                        atol=atol)
        if not sol.success:
            raise RuntimeError(f"DOP853 failed on {r['case']}: {sol.message}")
        return sol.y[:, -1]
    y_ref = run_pin(REF_RTOL, REF_ATOL)
    r["ref_check"] = np.max(np.abs(run_pin(REF_RTOL / 10, REF_ATOL / 10) - y_ref))
    err = lambda yy: float(np.max(np.abs(yy - y_ref)))        # noqa: E731
    r["pin_sim"], y_pin = best_of(run_pin, repeat, budget=2.0)
    r["err_pin"] = err(y_pin)

    def run_acausal(rtol, codegen=False, on=compiled, solver=None):
        res = on.simulate(T_FINAL, t=GRID, x0=x0, rtol=rtol, atol=rtol / 100, codegen=codegen,
                          solver=solver)
        r["solver"] = res.solver if solver is None else r["solver"]
        return np.array([res[k][-1] for k in coords])
    for rtol in MATCH_RTOLS:
        dt, yy = best_of(lambda: run_acausal(rtol), repeat, budget=2.0)
        e = err(yy)
        if e <= r["err_pin"] or rtol == MATCH_RTOLS[-1]:
            r["sim"], r["err_sim"], r["rtol_sim"], r["ok_sim"] = dt, e, rtol, e <= r["err_pin"]
            break
    if codegen:
        codegen_runs(r, compiled, acausal.compile(build()), run_acausal, run_pin, err,
                     [y[inv], 0.0, np.zeros(0), p], r["rtol_sim"], repeat)
    return r


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ns", type=int, nargs="*", default=[6, 16, 32, 64],
                    help="chain lengths (default 6 16 32 64)")
    ap.add_argument("--no-arm", action="store_true", help="skip the UR5 arm")
    ap.add_argument("--repeat", type=int, default=3, help="runs per timing (best)")
    ap.add_argument("--jit", action="store_true",
                    help="also time the rhs compiled to C (CasADi JIT; needs a C compiler)")
    ap.add_argument("--no-codegen", action="store_true",
                    help="skip simulate(codegen=True) (generated C; needs a C compiler)")
    args = ap.parse_args(argv)
    codegen = not args.no_codegen and use_codegen_cache()
    import pinocchio as pin
    print(f"acausal {acausal.__version__}, casadi {ca.__version__}, pinocchio {pin.__version__}",
          flush=True)
    cases = ([] if args.no_arm else [("ur5", None)]) + [("chain", n) for n in args.ns]
    rows = []
    for name, n in cases:
        t0 = time.perf_counter()
        r = bench(name, n, args.repeat, args.jit, codegen)
        rows.append(r)
        print(f"{r['case']:>9s} done in {time.perf_counter() - t0:.1f} s", flush=True)

    print(f"\n(1) compile [s], (2) one right-hand side [us], wall-clock, best of {args.repeat}")
    print_table(["case", "cold", "compile", "pin build", "rhs", "rhs jit", "pin.aba", "rhs/ABA",
                 "jit/ABA", "instr", "dev"],
                [[r["case"], r["compile_cold"], r["compile"], r["pin_build"], r["rhs"] * 1e6,
                  r["rhs_jit"] * 1e6,
                  r["aba"] * 1e6, r["rhs"] / r["aba"], r["rhs_jit"] / r["aba"], r["instr"],
                  r["dev"]] for r in rows],
                ["{:>10s}"] + ["{:10.4g}"] * 9 + ["{:10.1e}"])
    print("  cold: the first compile of the case in the process (the first case also builds the "
          "relations'\n  cached Functions); compile: best of the repeats (model built before, "
          "as in cold);\n  rhs: acausal's ODE (parameters folded, as simulated) in CasADi's virtual machine, "
          "mapped;\n  rhs jit: the same compiled to C (--jit); pin.aba: from Python; instr: "
          "SX instructions\n  of the rhs; dev: max |q''(acausal) - q''(ABA)| / max(1, |q''|)")
    print(f"\n(3) simulation of {T_FINAL:g} s from q = {Q0} rad at rest, at equal accuracy [s]")
    print_table(["case", "DOP853+ABA", "error", "simulate", "rtol", "error", "sim/DOP",
                 "solver"],
                [[r["case"], r["pin_sim"], r["err_pin"], r["sim"], r["rtol_sim"], r["err_sim"],
                  r["sim"] / r["pin_sim"], r["solver"]] for r in rows],
                ["{:>10s}", "{:10.4g}", "{:10.2e}", "{:10.4g}", "{:10.1e}", "{:10.2e}",
                 "{:10.4g}", "{:>10s}"])
    print(f"  errors: max |final state - DOP853+ABA at rtol {REF_RTOL:g}|; simulate: "
          f"compiled.simulate (initial values,\n  integrator creation, run, reading the "
          f"states), rtol tightened until its error <= DOP853's at rtol {RTOL:g}")
    chains = [r for r in rows if r["case"].startswith("chain")]
    if len(chains) >= 2:
        ns = [int(r["case"].split()[1]) for r in chains]
        print("\nfitted exponents (t ~ N^k) over the chains: " + ", ".join(
            f"{label} {fit_exponent(ns, [r[k] for r in chains]):.2f}"
            for label, k in (("compile", "compile"), ("rhs", "rhs"), ("ABA", "aba"),
                             ("simulate", "sim"), ("DOP853+ABA", "pin_sim"))))
    if codegen:
        report_codegen(rows, "case", "{:>10s}", "aba")
    print("\ntargets:")
    ok = lambda v, lim: "met" if v <= lim else "NOT met"     # noqa: E731
    for r in rows:
        line = f"  {r['case']:>9s}:"
        if r["case"] == "ur5":
            line += f" compile {r['compile']:.3f} s, first {r['compile_cold']:.3f} s (< " \
                    f"{TARGETS['compile_arm']:g} s) -> {ok(r['compile'], TARGETS['compile_arm'])};"
        rhs = r["rhs"] / r["aba"]
        line += f" rhs/ABA {rhs:.2f} -> {ok(rhs, TARGETS['rhs_ratio'])}"
        if np.isfinite(r["rhs_jit"]):
            jit = r["rhs_jit"] / r["aba"]
            line += f" (C: {jit:.2f} -> {ok(jit, TARGETS['rhs_ratio'])})"
        sim = r["sim"] / r["pin_sim"]
        line += f"; sim/DOP853 {sim:.2f} -> " \
                f"{ok(sim, TARGETS['sim_ratio']) if r['ok_sim'] else 'NOT met (accuracy)'}"
        if codegen:
            rhs = r["cg_rhs"] / r["aba"]
            sim = r["cg_times"]["codegen"][0] / r["cg_times"]["pin"][0]
            line += f"; codegen: rhs/ABA {rhs:.2f} -> {ok(rhs, TARGETS['rhs_ratio'])}, " \
                    f"sim/DOP853 {sim:.2f} -> " \
                    f"{ok(sim, TARGETS['sim_ratio']) if r['ok_cg_eq'] else 'NOT met (accuracy)'}"
            sim = r["cg_times"]["dop853"][0] / r["cg_times"]["pin"][0]
            line += f"; codegen + dop853: sim/DOP853 {sim:.2f} -> " \
                    f"{ok(sim, TARGETS['sim_ratio']) if r['ok_dop_eq'] else 'NOT met (accuracy)'}"
        print(line)


if __name__ == "__main__":
    main()
