"""Benchmark: cart-pole swing-up (examples/ocp_cartpole.py, on acausal.models.CartPole) through
acausal.ocp vs the same problem hand-written in casadi.Opti from the closed-form equations, in
the same run.

Both use the same transcription (Radau collocation of degree 3, or multiple shooting with 4
RK4 steps per interval), the same mesh, guess and IPOPT options (tol 1e-10, quiet). The
reference is written as a competent user would (``ocp_cartpole.hand_written``): SX dynamics
mapped over the mesh, the NLP expanded to SX, bounds and boundary values as variable bounds.
The contenders run interleaved (acausal, Opti, acausal, ...), ``--repeat`` times each; the
tables give the median and the spread (min–max) of:
- "total": from the problem statement to the solution (acausal: OCP(...) on the compiled
  model and ``ocp.solve()``; Opti: the variables, constraints and ``opti.solve()``); the
  model is compiled once, outside the timing, as the closed-form equations are written once;
- "IPOPT": the solver call alone (nlpsol's t_wall_total), and of it the time in the NLP's
  function evaluations (t_wall of nlp_f, nlp_g, nlp_grad_f, nlp_jac_g, nlp_hess_l);
- "build" = total − IPOPT: formulating the NLP and creating the solver.
Both solve the same NLP: the difference of their costs and their largest state difference
is printed with IPOPT's iteration counts. Targets: total ≤ 1.0×, IPOPT ≤ 1.2× the Opti.

    python benchmarks/ocp.py                # N = 50 (~ 30 s)
    python benchmarks/ocp.py --n 25 50 100 --repeat 7
"""
from __future__ import annotations

from timing import interleaved, median, print_table, spread  # first: pins BLAS threads

import argparse
import sys
import time
from pathlib import Path

import casadi as ca
import numpy as np

import acausal
from acausal.compiler.lean import lean
from acausal.models import CartPole

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "examples"))
import ocp_cartpole as ex  # noqa: E402   (the problem and its hand-written reference)

IPOPT = {"tol": 1e-10}
RECORD = {"record_time": True}      # nlpsol's timings in its stats (both contenders)
TARGET_TOTAL, TARGET_IPOPT = 1.0, 1.2
EVALUATIONS = ("nlp_f", "nlp_g", "nlp_grad_f", "nlp_jac_g", "nlp_hess_l")


def _phases(t0: float, stats: dict) -> dict:
    total = time.perf_counter() - t0
    ipopt = stats["t_wall_total"]
    return {"total": total, "ipopt": ipopt, "build": total - ipopt,
            "eval": sum(stats.get(f"t_wall_{k}", 0.0) for k in EVALUATIONS),
            "iter": stats["iter_count"]}


def acausal_run(compiled, n, method) -> dict:
    t0 = time.perf_counter()
    ocp = ex.swing_up(compiled, N=n, method=method)
    sol = ocp.solve(IPOPT, RECORD)
    out = _phases(t0, sol.stats)
    out.update(cost=sol.cost, X=np.array([sol[k] for k in compiled.x_names]))
    return out


def opti_run(n, method) -> dict:
    t0 = time.perf_counter()
    opti, X, _ = ex.hand_written(N=n, method=method)
    opti.solver("ipopt", {**ex.OPTIONS, **RECORD, "ipopt": {"print_level": 0, "sb": "yes", **IPOPT}})
    sol = opti.solve()
    out = _phases(t0, sol.stats())
    out.update(cost=float(sol.value(opti.f)), X=np.array(sol.value(X)))
    return out


def instruction_counts(compiled) -> list:
    """CasADi instructions of the cart-pole's ODE: acausal's compiled form (parameters
    symbolic), with the parameters folded in, folded and simplified (``compiler.lean``, as
    the OCP uses it), and the closed form of the reference."""
    x, F = ca.SX.sym("x", 4), ca.SX.sym("F")
    ode = ca.substitute(compiled.ode, compiled.p, ca.DM(compiled.param_vector()))
    count = lambda e, *a: ca.Function("f", [*a], [e]).n_instructions()
    return [count(compiled.ode, compiled.x, compiled.u, compiled.p),
            count(ode, compiled.x, compiled.u), count(lean([ode])[0], compiled.x, compiled.u),
            count(ex.cartpole_ode(x, F), x, F)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="*", default=[50])
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    compiled = acausal.compile(CartPole())
    sym, folded, short, closed = instruction_counts(compiled)
    print(f"cart-pole ODE, CasADi instructions: compiled {sym} (parameters symbolic), "
          f"{folded} (parameters folded in), {short} (folded and lean: what the OCP "
          f"transcribes); closed form {closed}")
    rows, worst = [], {"total": 0.0, "ipopt": 0.0}
    for method in ("collocation", "shooting"):
        for n in args.n:
            acausal_run(compiled, n, method)            # warm-up: first-call costs of both
            opti_run(n, method)
            runs = interleaved({"acausal": lambda: acausal_run(compiled, n, method),
                                "Opti": lambda: opti_run(n, method)}, args.repeat)
            a, o = runs["acausal"], runs["Opti"]
            ratio = {k: median(a, k) / median(o, k) for k in ("total", "build", "ipopt", "eval")}
            for k in worst:
                worst[k] = max(worst[k], ratio[k])
            ra, ro = a[-1], o[-1]
            rows.append([method, n, spread(a, "total"), spread(o, "total"), ratio["total"],
                         spread(a, "build"), spread(o, "build"), ratio["build"],
                         spread(a, "ipopt"), spread(o, "ipopt"), ratio["ipopt"],
                         spread(a, "eval"), spread(o, "eval"), ratio["eval"],
                         abs(ra["cost"] - ro["cost"]) / ro["cost"],
                         float(np.max(np.abs(ra["X"] - ro["X"]))), int(ra["iter"]),
                         int(ro["iter"])])
    print(f"\ncart-pole swing-up, min ∫F² dt, T = 2 s: acausal.ocp vs hand-written casadi.Opti; "
          f"times in ms, median (min–max) of {args.repeat} interleaved runs")
    s, r = "{:>22s}", "{:>6.2f}"
    print_table(["method", "N", "total ac", "total Opti", "ratio", "build ac", "build Opti",
                 "ratio", "IPOPT ac", "IPOPT Opti", "ratio", "eval ac", "eval Opti", "ratio",
                 "cost rdiff", "max|ΔX|", "it ac", "it Opti"], rows,
                ["{:>11s}", "{:>4d}", s, s, r, s, s, r, s, s, r, s, s, r, "{:>10.1e}",
                 "{:>8.1e}", "{:>5d}", "{:>7d}"])
    for k, target in (("total", TARGET_TOTAL), ("ipopt", TARGET_IPOPT)):
        verdict = "within" if worst[k] <= target else "NOT within"
        print(f"worst {k} ratio {worst[k]:.2f}: {verdict} the {target}x target")


if __name__ == "__main__":
    main()
