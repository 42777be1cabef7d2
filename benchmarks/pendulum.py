"""Peer benchmark: an N-link planar pendulum, acausal vs Pinocchio vs sympy.physics.mechanics.

A chain of N identical links hanging from a fixed pivot, gravity g = 9.81 m/s² along -y, no
damping. Link i: a revolute joint (relative angle q_i, 0 = hanging along the previous link),
a massless bar of length L = 0.5 m along -y of the joint frame, and a body (m = 1 kg,
I = 0.01 kg.m² about its centre of mass) at the bar's end, where the next joint sits.

- acausal: acausal.models.PendulumChain: planar World, Fixed, then N x (Revolute +
  FixedTranslation(r = {0, -L}) + Body);
- Pinocchio: a model built programmatically, N revolute joints about z (JointModelRZ), the
  same inertias, gravity along -y; forward dynamics by pin.aba;
- sympy.physics.mechanics: KanesMethod (relative angles, u = q'), mass matrix and forcing
  lambdified (cse=True), q'' = solve(M, F) in numpy. Its derivation grows steeply with N:
  an N is skipped when the derivation would take more than --sympy-cap seconds (predicted
  from the smaller N, and stopped by an alarm otherwise).

Measured in the same run, for each N:
1. compile / build time: acausal.compile (Model construction separately), Pinocchio model
   build, sympy derivation + lambdify;
2. one right-hand-side evaluation [µs]: acausal ``compiled.f`` (a casadi Function) called
   from Python with numpy arrays, and natively (``f.map(K)`` on K copies of the state:
   the Python-call overhead removed); also the ODE with the parameter values folded in as
   simulate() hands it to the integrator (mapped; its instructions per link and its sin, cos
   and divisions per link are printed); with --jit that ODE compiled to C by CasADi's JIT;
   Pinocchio pin.aba from Python; sympy's lambdified M, F plus numpy.linalg.solve;
3. a 10 s simulation, released at rest with the straight chain 0.1 rad from hanging (every
   link at 0.1 rad: q_1 = 0.1, the relative angles q_2..q_N = 0), rtol 1e-8, atol 1e-10,
   101-point output grid: acausal ``compiled.simulate`` with its default solver (which
   judges the pendulum non-stiff and takes cvodes' Adams method with functional iteration;
   initial values, integrator creation, the run) and with solver="cvodes" (BDF + Newton),
   and cvodes on ``compiled.dae`` alone (creation / run), vs Pinocchio ABA +
   scipy DOP853. The final states are checked against a reference (Pinocchio ABA + DOP853,
   rtol 1e-12, atol 1e-14; itself checked against rtol 1e-13). Equal accuracy: acausal's
   rtol is tightened in half decades (atol = rtol/100, down to 1e-11) until its error is no
   larger than DOP853's at rtol 1e-8; that run's time is compared. cvodes' own statistics
   show where the time goes (steps, Jacobians, time in the rhs and in its Jacobian).
   (Every *joint* at 0.1 rad would curl a long chain into a chaotic motion: from N = 32 on,
   both methods' errors at 10 s are O(10) rad/s and the reference itself differs from its
   rtol-1e-13 rerun by ~1e-3.)
4. ``simulate(codegen=True)`` (unless --no-codegen, or without a C compiler): the first run
   with an empty cache directory (generating the C, gcc, the run), the first run of a
   freshly compiled copy of the model (the library from the disk cache), the built
   library's rhs, and the run at equal accuracy, interleaved with DOP853 + ABA and the
   in-process simulate() (median and spread), and ``solver="dop853"`` on the generated C
   (scipy's DOP853, the reference's method) at equal accuracy, interleaved with them.
   Target: <= 0.5x Pinocchio + DOP853.
The models agree: max |acausal rhs - ABA| (and sympy - ABA) at a random state is printed.

    python benchmarks/pendulum.py                 # N = 2, 4, 8, 16, 32, 64 (~ 2 min)
    python benchmarks/pendulum.py --max-n 16
    python benchmarks/pendulum.py --jit --profile 64   # + JIT-compiled rhs, cProfile of compile

Requires the ``bench`` extra: pip install ".[bench]"  (pin = Pinocchio, sympy, scipy).
"""
from __future__ import annotations

import argparse
import cProfile
import gc
import io
import os
import pstats
import signal
import time

from timing import best_of, fit_exponent, interleaved, print_table, stats, timed
import casadi as ca
import numpy as np
from scipy.integrate import solve_ivp

import acausal
from acausal.models.pendulums import PendulumChain
from acausal.simulation import codegen as generated

L, MASS, INERTIA, G = 0.5, 1.0, 0.01, 9.81
Q0, T_FINAL, RTOL, ATOL = 0.1, 10.0, 1e-8, 1e-10
REF_RTOL, REF_ATOL = 1e-12, 1e-14
MATCH_RTOLS = tuple(10.0 ** -k for k in np.arange(8.0, 11.01, 0.5))   # 1e-8 ... 1e-11
# equal accuracy of the generated code's runs: an error no larger than DOP853's to 1 % (DOP853
# on acausal's right-hand side takes the reference's steps: its error differs by rounding,
# the UR5 at rtol 1e-8: 5.608e-9 against 5.595e-9)
SAME_ERROR = 1.01
ADAMS = {"linear_multistep_method": "adams", "nonlinear_solver_iteration": "functional"}
GRID = np.linspace(0.0, T_FINAL, 101)
TARGETS = {"compile_32": 0.1, "rhs_ratio": 2.0, "sim_ratio": 2.0, "codegen_ratio": 0.5}


# ---- models ---------------------------------------------------------------------------------
def build_acausal(n: int) -> acausal.Model:
    return PendulumChain(n, L=L, m=MASS, I=INERTIA, g=G)


def acausal_state_order(compiled, n: int) -> np.ndarray:
    """Permutation p with x_acausal[p] = [q_1..q_N, w_1..w_N] (the order Pinocchio uses)."""
    names = [f"rev{i}.phi" for i in range(1, n + 1)] + [f"rev{i}.w" for i in range(1, n + 1)]
    return np.array([compiled.x_names.index(k) for k in names])


def build_pinocchio(n: int):
    import pinocchio as pin
    model = pin.Model()
    model.gravity.linear = np.array([0.0, -G, 0.0])
    parent = 0
    inertia = pin.Inertia(MASS, np.array([0.0, -L, 0.0]), np.diag([INERTIA] * 3))
    for i in range(1, n + 1):
        place = pin.SE3(np.eye(3), np.array([0.0, 0.0 if i == 1 else -L, 0.0]))
        parent = model.addJoint(parent, pin.JointModelRZ(), place, f"rev{i}")
        model.appendBodyToJoint(parent, inertia, pin.SE3.Identity())
    return model, model.createData()


def pinocchio_ode(model, data):
    import pinocchio as pin
    n, tau = model.nq, np.zeros(model.nv)

    def f(t, y):
        return np.concatenate([y[n:], pin.aba(model, data, y[:n], y[n:], tau)])
    return f


class _Timeout(Exception):
    pass


def derive_sympy(n: int, limit: float):
    """KanesMethod for the same chain; (q'' = f(q, u) in numpy) or raises _Timeout."""
    import sympy as sm
    import sympy.physics.mechanics as me

    def alarm(*_):
        raise _Timeout

    old = signal.signal(signal.SIGALRM, alarm)
    signal.setitimer(signal.ITIMER_REAL, limit)
    try:
        q, u = me.dynamicsymbols(f"q1:{n + 1}"), me.dynamicsymbols(f"u1:{n + 1}")
        N = me.ReferenceFrame("N")
        O = me.Point("O")
        O.set_vel(N, 0)
        bodies, loads, kde = [], [], []
        parent, P = N, O
        for i in range(n):
            A = parent.orientnew(f"A{i + 1}", "Axis", (q[i], N.z))
            A.set_ang_vel(parent, u[i] * N.z)
            Pi = P.locatenew(f"P{i + 1}", -L * A.y)
            Pi.v2pt_theory(P, N, A)
            bodies.append(me.RigidBody(f"B{i + 1}", Pi, A, MASS,
                                       (me.inertia(A, 0, 0, INERTIA), Pi)))
            loads.append((Pi, -MASS * G * N.y))
            kde.append(q[i].diff() - u[i])
            parent, P = A, Pi
        km = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kde)
        km.kanes_equations(bodies, loads)
        fMF = sm.lambdify([q, u], [km.mass_matrix, km.forcing], cse=True)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)

    def qdd(qv, uv):
        Mv, Fv = fMF(qv, uv)
        return np.linalg.solve(np.asarray(Mv, dtype=float), np.asarray(Fv, dtype=float).ravel())
    return qdd


# ---- timing helpers -------------------------------------------------------------------------
def per_call(fn, min_time=0.05, repeat=5) -> float:
    """Seconds per call of fn(): calls batched to last >= min_time, best of ``repeat``."""
    fn()
    k = 1
    while True:
        t0 = time.perf_counter()
        for _ in range(k):
            fn()
        dt = time.perf_counter() - t0
        if dt >= min_time or k >= 1 << 20:
            break
        k *= max(2, min(10, int(min_time / max(dt, 1e-9)) + 1))
    best = dt / k
    for _ in range(repeat - 1):
        t0 = time.perf_counter()
        for _ in range(k):
            fn()
        best = min(best, (time.perf_counter() - t0) / k)
    return best


def mapped_per_eval(f: ca.Function, args: list, target=0.05) -> float:
    """Seconds per evaluation of f inside f.map(K) (one Python call for K evaluations)."""
    one = per_call(lambda: f(*args), min_time=0.01, repeat=2)
    K = int(min(20000, max(10, target / max(one, 1e-7))))
    F = f.map(K)
    big = [np.tile(np.asarray(a, dtype=float).reshape(-1, 1), (1, K)) for a in args]
    return per_call(lambda: F(*big), min_time=target, repeat=3) / K




# ---- one N ----------------------------------------------------------------------------------
def bench(n: int, repeat: int, sympy_state: dict, sympy_cap: float,
          jit: bool = False, codegen: bool = False) -> dict:
    import pinocchio as pin
    r = {"N": n}
    rng = np.random.default_rng(n)

    # (1) build / compile
    gc.collect()
    t0 = time.perf_counter()
    model = build_acausal(n)
    r["ac_model"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    compiled = acausal.compile(model)
    r["ac_compile"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    rhs = compiled.f
    r["ac_rhs_fn"] = time.perf_counter() - t0
    r["ac_instr"] = rhs.n_instructions()
    r["pin_build"], (pmodel, pdata) = best_of(lambda: build_pinocchio(n), repeat, budget=2.0)

    # (2) one right-hand side
    perm = acausal_state_order(compiled, n)
    inv = np.argsort(perm)
    y = np.concatenate([rng.uniform(-1, 1, n), rng.uniform(-2, 2, n)])     # [q; w]
    x = y[inv]                                                           # acausal's order
    p = compiled.param_vector()
    t, z, u = 0.0, np.zeros(0), np.zeros(0)
    qdd_ac = np.asarray(rhs(t, x, z, u, p)[0], dtype=float).ravel()[perm][n:]
    tau = np.zeros(n)
    qdd_pin = pin.aba(pmodel, pdata, y[:n], y[n:], tau)
    r["dev_ac"] = np.max(np.abs(qdd_ac - qdd_pin)) / max(1.0, np.max(np.abs(qdd_pin)))
    r["ac_rhs_py"] = per_call(lambda: rhs(t, x, z, u, p))
    r["ac_rhs_native"] = mapped_per_eval(rhs, [t, x, z, u, p])
    folded = ca.Function("folded", [compiled.x],
                         [ca.substitute(compiled.ode, compiled.p, ca.SX(p))])
    r["ac_folded_instr"] = folded.n_instructions()
    ops = [folded.instruction_id(k) for k in range(folded.n_instructions())]
    r["ac_ops"] = {name: ops.count(getattr(ca, f"OP_{name.upper()}"))
                   for name in ("sin", "cos", "div", "mul", "add", "sub")}
    r["ac_rhs_folded"] = mapped_per_eval(folded, [x])
    r["ac_rhs_jit"] = float("nan")
    if jit:            # the same, compiled to C by CasADi's JIT (not what simulate() does)
        t0 = time.perf_counter()
        fj = ca.Function("folded_jit", [compiled.x], [folded(compiled.x)],
                         {"jit": True, "compiler": "shell", "jit_options": {"flags": ["-O2"]}})
        fj(x)
        r["ac_jit_build"] = time.perf_counter() - t0
        r["ac_rhs_jit"] = mapped_per_eval(fj, [x])
    r["pin_aba"] = per_call(lambda: pin.aba(pmodel, pdata, y[:n], y[n:], tau))

    r["sy_build"] = r["sy_rhs"] = r["dev_sy"] = float("nan")
    r["sy_note"] = ""
    predicted = sympy_state.get("predict", lambda n: 0.0)(n)
    if sympy_state.get("stopped") or predicted > sympy_cap:
        r["sy_note"] = (f"skipped (derivation predicted ~{predicted:.0f} s > {sympy_cap:g} s)"
                        if not sympy_state.get("stopped") else "skipped (a smaller N hit the cap)")
        sympy_state["stopped"] = True
    else:
        t0 = time.perf_counter()
        try:
            qdd_sy = derive_sympy(n, sympy_cap)
            r["sy_build"] = time.perf_counter() - t0
        except _Timeout:
            r["sy_note"] = f"stopped after {sympy_cap:g} s"
            sympy_state["stopped"] = True
        if not r["sy_note"]:
            r["dev_sy"] = (np.max(np.abs(qdd_sy(y[:n], y[n:]) - qdd_pin))
                           / max(1.0, np.max(np.abs(qdd_pin))))
            r["sy_rhs"] = per_call(lambda: qdd_sy(y[:n], y[n:]))
            hist = sympy_state.setdefault("hist", [])
            hist.append((n, r["sy_build"]))
            # t ~ a N^k through the last two points (one point: k = 4, as measured here)
            k = 4.0 if len(hist) < 2 else max(1.0, np.log(hist[-1][1] / hist[-2][1])
                                              / np.log(hist[-1][0] / hist[-2][0]))
            n2, t2 = hist[-1]
            sympy_state["predict"] = lambda m, k=k, n2=n2, t2=t2: t2 * (m / n2) ** k

    # (3) simulation, 10 s, the straight chain released at rest Q0 from hanging
    q0 = np.zeros(n)
    q0[0] = Q0
    y0 = np.concatenate([q0, np.zeros(n)])
    x0 = {f"rev{i}.phi": q0[i - 1] for i in range(1, n + 1)}

    def run_acausal(solver=None, rtol=RTOL, atol=ATOL, codegen=False, on=compiled):
        res = on.simulate(T_FINAL, t=GRID, x0=x0, rtol=rtol, atol=atol, solver=solver,
                          codegen=codegen)
        r["auto_solver"] = res.solver if solver is None else r.get("auto_solver")
        return np.array([res[f"rev{i}.phi"][-1] for i in range(1, n + 1)]
                        + [res[f"rev{i}.w"][-1] for i in range(1, n + 1)])

    f_pin = pinocchio_ode(pmodel, pdata)

    def run_pin(rtol=RTOL, atol=ATOL):
        sol = solve_ivp(f_pin, (0.0, T_FINAL), y0, method="DOP853", t_eval=GRID,
                        rtol=rtol, atol=atol)
        if not sol.success:
            raise RuntimeError(f"DOP853 failed at N={n}: {sol.message}")
        return sol
    t0 = time.perf_counter()
    y_ref = run_pin(REF_RTOL, REF_ATOL).y[:, -1]
    r["ref_time"] = time.perf_counter() - t0
    r["ref_check"] = np.max(np.abs(run_pin(REF_RTOL / 10, REF_ATOL / 10).y[:, -1] - y_ref))
    r["scale"] = np.max(np.abs(y_ref))
    err = lambda y_: float(np.max(np.abs(y_ - y_ref)))

    r["pin_sim"], sol = best_of(run_pin, repeat, budget=2.0)
    r["err_pin"], r["pin_nfev"] = err(sol.y[:, -1]), sol.nfev

    for key, solver in (("bdf", "cvodes"), ("adams", None)):
        # at the same tolerances, then tightened until as accurate as DOP853
        for k, rtol in enumerate(MATCH_RTOLS):
            dt, y_ = best_of(lambda: run_acausal(solver, rtol, rtol / 100), repeat, budget=2.0)
            e = err(y_)
            if k == 0:
                r[f"ac_{key}"], r[f"err_{key}"] = dt, e
            if e <= r["err_pin"] or rtol == MATCH_RTOLS[-1]:
                r[f"ac_{key}_eq"], r[f"err_{key}_eq"], r[f"rtol_{key}_eq"] = dt, e, rtol
                r[f"ok_{key}_eq"] = e <= r["err_pin"]
                break

    if codegen:
        codegen_runs(r, compiled, acausal.compile(build_acausal(n)),
                     lambda rtol, cg, on, solver=None: run_acausal(solver, rtol, rtol / 100, cg,
                                                                   on), run_pin,
                     err, [x, t, u, p], r["rtol_adams_eq"], repeat)

    dae = dict(compiled.dae)
    pu = np.concatenate([np.zeros(compiled.u.numel()), p])      # dae p = [u; p]
    creates, runs = [], []
    for _ in range(repeat):
        t0 = time.perf_counter()
        F = ca.integrator("pendulum", "cvodes", dae, GRID[0], GRID[1:],
                          {"abstol": ATOL, "reltol": RTOL, "max_num_steps": 100000})
        t1 = time.perf_counter()
        sol = F(x0=y0[inv], p=pu)
        creates.append(t1 - t0)
        runs.append(time.perf_counter() - t1)
        if runs[-1] > 2.0:
            break
    r["ac_int_create"], r["ac_int_run"] = min(creates), min(runs)
    r["err_int"] = err(np.asarray(sol["xf"], dtype=float)[:, -1][perm])
    stats = F.stats()
    r["ac_steps"] = stats.get("nsteps", -1)
    r["ac_nfevals"] = stats.get("nfevals", -1)
    r["ac_njac"] = stats.get("n_call_jacF", -1)
    r["ac_t_rhs"] = stats.get("t_wall_daeF", float("nan"))    # time in the rhs
    r["ac_t_jac"] = stats.get("t_wall_jacF", float("nan"))    # time in its Jacobian
    # the Adams run at its equal-accuracy tolerance, on compiled.dae: evaluations and time
    rt = r["rtol_adams_eq"]
    F = ca.integrator("pendulum", "cvodes", dae, GRID[0], GRID[1:],
                      dict(ADAMS, abstol=rt / 100, reltol=rt, max_num_steps=1000000))
    F(x0=y0[inv], p=pu)
    stats = F.stats()
    r["adams_nfev"] = stats.get("nfevals", -1)
    r["adams_t_rhs"] = stats.get("t_wall_daeF", float("nan"))
    return r


def codegen_runs(r, compiled, again, run, run_pin, err, rhs_args, rtol_in_process,
                 repeat) -> None:
    """simulate(codegen=True) (the default solver): the first run, which generates and
    builds the C (gcc; the cache directory is empty), the first run of ``again`` (a freshly
    compiled copy of the model: the library loaded from the disk cache, what a new process
    pays, compile aside), the right-hand side of the built library at ``rhs_args`` = (x, t,
    u, p) (mapped over x), and the run at
    equal accuracy against DOP853 and the in-process run at ``rtol_in_process``,
    interleaved; also simulate(codegen=True, solver="dop853") at equal accuracy (the
    same method as the reference's, on the generated C). ``run(rtol, codegen, on,
    solver=None)`` simulates ``on`` and returns the final state."""
    t0 = time.perf_counter()
    run(RTOL, True, compiled)
    r["cg_first"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    run(RTOL, True, again)
    r["cg_cached_first"] = time.perf_counter() - t0
    # the built library's right-hand side at the state x (t, u, p fixed: as the folded rhs
    # above, so that no conversion of mapped parameter copies is timed)
    x, t, u, p = rhs_args
    xs = ca.MX.sym("x", len(x))
    f = generated.equations(compiled, derivatives=False)
    r["cg_rhs"] = mapped_per_eval(ca.Function("cg_rhs", [xs], [f(xs, t, u, p)]), [x])
    for key, solver in (("cg", None), ("dop", "dop853")):
        for rtol in MATCH_RTOLS:
            e = err(run(rtol, True, compiled, solver))
            if e <= SAME_ERROR * r["err_pin"] or rtol == MATCH_RTOLS[-1]:
                r[f"err_{key}_eq"], r[f"rtol_{key}_eq"], r[f"ok_{key}_eq"] = \
                    e, rtol, e <= SAME_ERROR * r["err_pin"]
                break
    runs = interleaved({
        "pin": timed(run_pin),
        "in-process": timed(lambda: run(rtol_in_process, False, compiled)),
        "codegen": timed(lambda: run(r["rtol_cg_eq"], True, compiled)),
        "dop853": timed(lambda: run(r["rtol_dop_eq"], True, compiled, "dop853"))},
        max(repeat, 5))
    r["cg_times"] = {k: stats(v, "run") for k, v in runs.items()}


# ---- report ---------------------------------------------------------------------------------




def profile_compile(n: int, top: int = 20):
    """cProfile of acausal.compile: acausal's own functions by cumulative time, then the
    CasADi calls by own time."""
    model = build_acausal(n)
    pr = cProfile.Profile()
    pr.enable()
    acausal.compile(model)
    pr.disable()
    for order, filt, label in (("cumulative", "acausal", "acausal functions, cumulative"),
                               ("tottime", "casadi", "CasADi calls, own time")):
        s = io.StringIO()
        st = pstats.Stats(pr, stream=s)
        st.sort_stats(order).print_stats(filt, top)
        lines = [ln.replace(acausal.__path__[0] + "/", "") for ln in s.getvalue().splitlines()
                 if ln.strip()]
        k = next(i for i, ln in enumerate(lines) if ln.lstrip().startswith("ncalls"))
        print(f"\ncProfile of acausal.compile, N = {n} ({label}):")
        print("\n".join(lines[k:]))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ns", type=int, nargs="*", default=[2, 4, 8, 16, 32, 64],
                    help="chain lengths (default 2 4 8 16 32 64)")
    ap.add_argument("--max-n", type=int, default=64, help="largest N to run (default 64)")
    ap.add_argument("--repeat", type=int, default=3, help="runs per build/simulation (best)")
    ap.add_argument("--sympy-cap", type=float, default=60.0,
                    help="longest sympy derivation allowed [s] (default 60)")
    ap.add_argument("--jit", action="store_true",
                    help="also time the folded rhs compiled to C (CasADi JIT; needs a C compiler)")
    ap.add_argument("--no-codegen", action="store_true",
                    help="skip simulate(codegen=True) (generated C; needs a C compiler)")
    ap.add_argument("--profile", type=int, default=0, metavar="N",
                    help="also cProfile acausal.compile at this N")
    args = ap.parse_args(argv)
    ns = [n for n in args.ns if n <= args.max_n]
    codegen = not args.no_codegen and use_codegen_cache()
    import pinocchio as pin
    import sympy
    print(f"acausal {acausal.__version__}, casadi {ca.__version__}, pinocchio {pin.__version__}, "
          f"sympy {sympy.__version__}", flush=True)

    rows, sympy_state = [], {}
    for n in ns:
        t0 = time.perf_counter()
        r = bench(n, args.repeat, sympy_state, args.sympy_cap, args.jit, codegen)
        rows.append(r)
        print(f"N={n:3d} done in {time.perf_counter() - t0:.1f} s: compile {r['ac_compile']:.4f} s,"
              f" rhs {r['ac_rhs_native'] * 1e6:.1f} us (ABA {r['pin_aba'] * 1e6:.1f} us), "
              f"simulate {r['ac_bdf']:.3f} s, Adams {r['ac_adams']:.3f} s (DOP853 "
              f"{r['pin_sim']:.3f} s)", flush=True)

    print(f"\nN-link planar pendulum (L = {L} m, m = {MASS} kg, I = {INERTIA} kg.m2), "
          f"wall-clock, best of {args.repeat}")
    print("\n(1) build / compile [s]")
    print_table(["N", "ac model", "ac compile", "ac rhs fn", "pin build", "sympy", "compile/pin"],
           [[r["N"], r["ac_model"], r["ac_compile"], r["ac_rhs_fn"], r["pin_build"],
             r["sy_build"], r["ac_compile"] / r["pin_build"]] for r in rows],
           ["{:10d}"] + ["{:10.4g}"] * 6)
    print("  ac model: building the acausal Model in Python; ac compile: acausal.compile; "
          "ac rhs fn:"
          "\n  first access of compiled.f; pin build: the Pinocchio model; sympy: KanesMethod + "
          "lambdify")
    for r in rows:
        if r["sy_note"]:
            print(f"  sympy N={r['N']}: {r['sy_note']}")

    print("\n(2) one right-hand side [us]")
    print_table(["N", "ac python", "ac native", "ac folded", "pin.aba", "sympy", "native/pin",
            "python/pin", "instr", "dev ac", "dev sympy"],
           [[r["N"], r["ac_rhs_py"] * 1e6, r["ac_rhs_native"] * 1e6, r["ac_rhs_folded"] * 1e6,
             r["pin_aba"] * 1e6, r["sy_rhs"] * 1e6, r["ac_rhs_native"] / r["pin_aba"],
             r["ac_rhs_py"] / r["pin_aba"], r["ac_instr"], r["dev_ac"], r["dev_sy"]]
            for r in rows],
           ["{:10d}"] + ["{:10.4g}"] * 7 + ["{:10d}", "{:10.1e}", "{:10.1e}"])
    if any(np.isfinite(r["ac_rhs_jit"]) for r in rows):
        print_table(["N", "ac jit", "jit/pin", "gcc time"],
               [[r["N"], r["ac_rhs_jit"] * 1e6, r["ac_rhs_jit"] / r["pin_aba"],
                 r.get("ac_jit_build", float("nan"))] for r in rows],
               ["{:10d}"] + ["{:10.4g}"] * 3)
        print("  ac jit: the folded rhs compiled to C by CasADi's JIT (gcc -O2), mapped; "
              "gcc time [s]")
    print("  per link, in the folded rhs: " + "; ".join(
        f"N={r['N']}: {r['ac_folded_instr'] / r['N']:.0f} instr, "
        + ", ".join(f"{v / r['N']:.1f} {k}" for k, v in r["ac_ops"].items()
                    if k in ("sin", "cos", "div")) for r in rows if r["N"] >= 8))
    print("  ac python: compiled.f(t, x, z, u, p) called from Python on numpy arrays; ac native: "
          "per\n  evaluation inside compiled.f.map(K) (no Python overhead); ac folded: the ODE "
          "with the\n  parameter values substituted, as simulate() gives it to cvodes (mapped); "
          "instr: SX\n  instructions of compiled.f; dev: max |q''(model) - q''(ABA)| / max(1, "
          "|q''|) at a random state")

    print(f"\n(3) simulation of {T_FINAL:g} s, the straight chain released {Q0} rad from hanging, "
          f"rtol {RTOL:g}, atol {ATOL:g},\n    {len(GRID)}-point grid [s]")
    print_table(["N", "DOP853+ABA", "sim BDF", "sim Adams", "BDF/DOP", "Adams/DOP", "int.create",
            "int.run", "t in rhs", "t in jac", "cv steps", "cv jacs", "DOP f-evals"],
           [[r["N"], r["pin_sim"], r["ac_bdf"], r["ac_adams"], r["ac_bdf"] / r["pin_sim"],
             r["ac_adams"] / r["pin_sim"], r["ac_int_create"], r["ac_int_run"], r["ac_t_rhs"],
             r["ac_t_jac"], int(r["ac_steps"]), int(r["ac_njac"]), int(r["pin_nfev"])]
            for r in rows],
           ["{:10d}"] + ["{:10.4g}"] * 9 + ["{:10d}"] * 3)
    print("  DOP853+ABA: scipy solve_ivp DOP853 on pin.aba; sim BDF: compiled.simulate(solver="
          "'cvodes') (BDF +\n  Newton; initial values, integrator creation, run, reading "
          "the angles); sim Adams: simulate()'s default,\n  which judges the model non-stiff "
          "and takes cvodes' Adams method with functional iteration; int.create / int.run: cvodes BDF on compiled.dae\n  alone; t in rhs / t in "
          "jac: cvodes' own wall time in the rhs and in its Jacobian during int.run")
    print(f"\n    max |final state - reference| (angles [rad], rates [rad/s]); reference: "
          f"DOP853+ABA at rtol {REF_RTOL:g}, atol {REF_ATOL:g}")
    print_table(["N", "max|x_ref|", "ref check", "DOP853+ABA", "sim BDF", "sim Adams", "cvodes dae"],
           [[r["N"], r["scale"], r["ref_check"], r["err_pin"], r["err_bdf"], r["err_adams"],
             r["err_int"]] for r in rows], ["{:10d}"] + ["{:10.3e}"] * 6)
    print(f"  ref check: |reference - the same at rtol {REF_RTOL / 10:g}|")
    print("\n    at equal accuracy: acausal's rtol tightened (atol = rtol/100) until its error <= "
          "DOP853's at rtol 1e-8")
    print_table(["N", "DOP853+ABA", "BDF rtol", "BDF time", "BDF error", "BDF/DOP", "Adams rtol",
            "Adams time", "Adams err", "Adams/DOP", "Ad. f-evals", "Ad. t rhs"],
           [[r["N"], r["pin_sim"], r["rtol_bdf_eq"], r["ac_bdf_eq"], r["err_bdf_eq"],
             r["ac_bdf_eq"] / r["pin_sim"], r["rtol_adams_eq"], r["ac_adams_eq"],
             r["err_adams_eq"], r["ac_adams_eq"] / r["pin_sim"], int(r["adams_nfev"]),
             r["adams_t_rhs"]] for r in rows],
           ["{:10d}", "{:10.4g}", "{:10.1e}", "{:10.4g}", "{:10.2e}", "{:10.4g}", "{:10.1e}",
            "{:10.4g}", "{:10.2e}", "{:10.4g}", "{:10d}", "{:10.4g}"])
    print("  Ad. f-evals / Ad. t rhs: cvodes Adams on compiled.dae at that rtol: rhs evaluations "
          "and the\n  time spent in them [s] (compare DOP f-evals above)")
    for r in rows:
        for key in ("bdf", "adams"):
            if not r[f"ok_{key}_eq"]:
                print(f"  N={r['N']}: {key} did not reach DOP853's error even at rtol "
                      f"{MATCH_RTOLS[-1]:g}")

    ns_fit = [r["N"] for r in rows]
    print("\nfitted exponents (t ~ N^k, least squares on log-log; N >= 8 in brackets)")
    for label, key in (("acausal compile", "ac_compile"), ("acausal rhs native", "ac_rhs_native"),
                       ("acausal rhs folded", "ac_rhs_folded"), ("acausal rhs instructions",
                                                                 "ac_instr"),
                       ("Pinocchio build", "pin_build"), ("Pinocchio ABA", "pin_aba"),
                       ("sympy derivation", "sy_build"), ("sympy rhs", "sy_rhs"),
                       ("acausal simulate() BDF", "ac_bdf"),
                       ("acausal simulate() Adams", "ac_adams"), ("DOP853 + ABA", "pin_sim")):
        ts = [r[key] for r in rows]
        big = [(n, t) for n, t in zip(ns_fit, ts) if n >= 8]
        k_all = fit_exponent(ns_fit, ts)
        k_big = fit_exponent(*zip(*big)) if len(big) >= 2 else float("nan")
        print(f"  {label:26s} k = {k_all:5.2f}   [{k_big:5.2f}]")

    print("\ntargets:")
    by_n = {r["N"]: r for r in rows}
    if 32 in by_n:
        tc = by_n[32]["ac_compile"]
        print(f"  compile N=32: {tc:.4f} s (target < {TARGETS['compile_32']:g} s) -> "
              f"{'met' if tc < TARGETS['compile_32'] else 'NOT met'}")
    else:
        print(f"  compile N=32: not run (target < {TARGETS['compile_32']:g} s)")
    for r in rows:
        native = r["ac_rhs_native"] / r["pin_aba"]
        ratio = r["ac_rhs_folded"] / r["pin_aba"]
        ok = lambda v, lim: "met" if v <= lim else "NOT met"
        print(f"  N={r['N']:3d}: rhs/ABA = {ratio:5.2f} (parameters folded, as simulated; "
              f"symbolic {native:4.2f}, numpy call "
              f"{r['ac_rhs_py'] / r['pin_aba']:5.1f}; target <= {TARGETS['rhs_ratio']:g}) -> "
              f"{ok(ratio, TARGETS['rhs_ratio'])}")
        for key, label in (("bdf", "simulate(solver='cvodes')"),
                           ("adams", f"simulate() (auto: {r['auto_solver']})")):
            sim = r[f"ac_{key}_eq"] / r["pin_sim"]
            print(f"         {label:26s} / DOP853 at equal accuracy = {sim:6.2f} (rtol "
                  f"{r[f'rtol_{key}_eq']:.1e}, error {r[f'err_{key}_eq']:.1e} vs "
                  f"{r['err_pin']:.1e}; target <= {TARGETS['sim_ratio']:g}) -> "
                  f"{ok(sim, TARGETS['sim_ratio']) if r[f'ok_{key}_eq'] else 'NOT met'}")
    if codegen:
        report_codegen(rows)
    if args.profile:
        profile_compile(args.profile)


def use_codegen_cache() -> bool:
    """A C compiler is there: generated code goes to an empty temporary cache directory
    (removed at exit), so that the first run's build is measured."""
    import atexit
    import shutil
    import tempfile
    from acausal import toolchain
    try:
        toolchain.find_compiler(acausal.errors.SimulationError)
    except acausal.errors.SimulationError as e:
        print(f"simulate(codegen=True) skipped: {e}")
        return False
    cache = tempfile.mkdtemp(prefix="acausal_bench_cache_")
    atexit.register(shutil.rmtree, cache, ignore_errors=True)
    os.environ["ACAUSAL_CACHE"] = cache
    return True


def report_codegen(rows, case: str = "N", case_format: str = "{:10d}",
                   aba: str = "pin_aba") -> None:
    """The tables of simulate(codegen=True) (Adams, then dop853) against DOP853 + ABA, one
    row per ``rows`` entry named by its ``case`` key (``aba``: its ABA time's key)."""
    print("\n(4) simulate(codegen=True): generated C of the right-hand side (gcc -O1), Adams")
    rows_out = []
    for r in rows:
        pin_, inp, cg = (r["cg_times"][k][0] for k in ("pin", "in-process", "codegen"))
        rows_out.append([r[case], r["cg_first"], r["cg_cached_first"], r["cg_rhs"] * 1e6,
                         r["cg_rhs"] / r[aba], r["rtol_cg_eq"], r["err_cg_eq"], pin_, inp,
                         cg, cg / pin_, cg / inp])
    print_table([case, "first run", "cached 1st", "rhs [us]", "rhs/ABA", "rtol eq", "error",
                 "DOP853+ABA", "in-process", "codegen", "cg/DOP", "cg/in-proc"], rows_out,
                [case_format, "{:10.4g}", "{:10.4g}", "{:10.4g}", "{:10.3g}", "{:10.1e}",
                 "{:10.2e}", "{:10.4g}", "{:10.4g}", "{:10.4g}", "{:10.3g}", "{:10.3g}"])
    print("  first run: generating the C, gcc, loading, and the run (empty cache); cached 1st: "
          "the first run\n  of a freshly compiled copy of the model (library from the disk "
          "cache); rhs: the built library's, mapped;\n  times at equal accuracy: median of "
          "interleaved runs (spread below); in-process: simulate() without codegen")
    report_dop853(rows, case, case_format)
    for r in rows:
        print(f"  {case} {r[case]} spread [min, max] s: " + "; ".join(
            f"{k} [{lo:.4g}, {hi:.4g}]" for k, (_, lo, hi) in r["cg_times"].items()))


def report_dop853(rows, case: str, case_format: str) -> None:
    """The table of simulate(codegen=True, solver="dop853") against DOP853 + ABA."""
    print('\n  simulate(codegen=True, solver="dop853") at equal accuracy (interleaved with the '
          'above):')
    print_table([case, "DOP853+ABA", "error", "dop853", "rtol eq", "error", "dop/DOP",
                 "dop/Adams"],
                [[r[case], r["cg_times"]["pin"][0], r["err_pin"], r["cg_times"]["dop853"][0],
                  r["rtol_dop_eq"], r["err_dop_eq"],
                  r["cg_times"]["dop853"][0] / r["cg_times"]["pin"][0],
                  r["cg_times"]["dop853"][0] / r["cg_times"]["codegen"][0]] for r in rows],
                [case_format, "{:10.4g}", "{:10.2e}", "{:10.4g}", "{:10.1e}", "{:10.2e}",
                 "{:10.3g}", "{:10.3g}"])


if __name__ == "__main__":
    main()
