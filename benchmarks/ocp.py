"""Benchmark: cart-pole swing-up (examples/ocp_cartpole.py, on acausal.models.CartPole) through
acausal.ocp vs the same problem hand-written in casadi.Opti from the closed-form equations, in
the same run.

Both use the same transcription (Radau collocation of degree 3, or multiple shooting with 4
RK4 steps per interval), the same mesh, guess and IPOPT options (tol 1e-10, quiet). For each
N, best of --repeat runs:
- "solve": formulate the NLP and solve it, from the problem statement to the solution object
  (acausal: OCP(...) on the compiled model, ``ocp.solve()``; Opti: the variables and
  constraints, ``opti.solve()``); the model is compiled once, outside the timing, as the
  closed-form equations are written once;
- "re-solve": a second solve of the same, already built problem.
The ratio acausal / Opti is printed (target: within 1.2x), with both costs' relative
difference and IPOPT's iteration counts.

    python benchmarks/ocp.py                # N = 25, 50, 100 (~ 30 s)
    python benchmarks/ocp.py --n 50 --repeat 5
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import acausal
from acausal.models import CartPole
from timing import best_of, print_table

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "examples"))
import ocp_cartpole as ex  # noqa: E402   (the problem and its hand-written reference)

IPOPT = {"tol": 1e-10}
OPTIONS = {"print_time": False, "ipopt": {"print_level": 0, "sb": "yes", **IPOPT}}
TARGET = 1.2


def acausal_run(compiled, n, method):
    ocp = ex.swing_up(compiled, N=n, method=method)
    return ocp, ocp.solve(IPOPT)


def opti_run(n, method):
    opti, _, _ = ex.hand_written(N=n, method=method)
    opti.solver("ipopt", OPTIONS)
    return opti, opti.solve()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="*", default=[25, 50, 100])
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    compiled = acausal.compile(CartPole())
    rows, worst = [], 0.0
    for method in ("collocation", "shooting"):
        for n in args.n:
            t_a, (ocp, sol) = best_of(lambda: acausal_run(compiled, n, method), args.repeat)
            t_o, (opti, ref) = best_of(lambda: opti_run(n, method), args.repeat)
            r_a, _ = best_of(lambda: ocp.solve(IPOPT), args.repeat)
            r_o, _ = best_of(lambda: opti.solve(), args.repeat)
            cost = ref.value(opti.f)
            rows.append([method, n, t_a, t_o, t_a / t_o, r_a, r_o, r_a / r_o,
                         abs(sol.cost - cost) / cost, sol.iterations,
                         ref.stats()["iter_count"]])
            worst = max(worst, t_a / t_o)
    print("cart-pole swing-up, min ∫F² dt, T = 2 s: acausal.ocp vs hand-written casadi.Opti "
          "(times in s)")
    print_table(["method", "N", "acausal", "Opti", "ratio", "re-acausal", "re-Opti", "re-ratio",
                 "cost rdiff", "it acausal", "it Opti"], rows,
                ["{:>10s}", "{:>10d}", "{:>10.4f}", "{:>10.4f}", "{:>10.2f}", "{:>10.4f}",
                 "{:>10.4f}", "{:>10.2f}", "{:>10.1e}", "{:>10d}", "{:>10d}"])
    verdict = "within" if worst <= TARGET else "NOT within"
    print(f"worst solve-time ratio {worst:.2f}: {verdict} the {TARGET}x target")


if __name__ == "__main__":
    main()
