"""simulate(..., codegen=True): the integrator on the model's equations generated as C.

A chain of 24 pendulum links (acausal.models.PendulumChain) swings for 10 s, released with
the first link 0.5 rad from hanging. The first run with ``codegen=True`` generates the C of
the right-hand side, builds it with the system C compiler and keeps the shared library in
the cache directory, named by a hash of the code; the second run — here of a copy of the
model compiled afresh, as a new Python process would — loads it without compiling. Changing
a parameter does not rebuild it: parameters (and inputs) are arguments of the generated
code. The last run takes ``solver="dop853"`` (scipy's explicit Runge–Kutta method of order
8, on the same generated C). scipy takes its steps in Python, some 20-30 us per stage besides
the right-hand side: on a light right-hand side like this planar chain's (a few us) Adams,
stepping in C, is faster; DOP853 pays off where the right-hand side is heavy and the motion
smooth (3-D chains, robot arms: ``benchmarks/multibody_3d.py``).

Checks printed: the final angles of the generated-code runs equal the in-process
``simulate()``'s (the same arithmetic, the same steps), DOP853's agree with them to the
tolerances, and the energy of the undamped chain stays constant to the integrator's tolerance
in both methods.

The cache is ``$ACAUSAL_CACHE`` (this example: ``acausal_cache`` in the current directory
unless set), else ``~/.cache/acausal``. Needs a C compiler (gcc, clang or $CC). Run
``python examples/simulate_codegen.py``; a second run of the script finds the library built.
"""
from __future__ import annotations

import os
import time

import numpy as np

os.environ.setdefault("ACAUSAL_CACHE", "acausal_cache")

import acausal                                          # noqa: E402
from acausal.models.pendulums import PendulumChain     # noqa: E402

N, T = 24, 10.0
X0 = {"rev1.phi": 0.5}


def timed(fn):
    t0 = time.perf_counter()
    out = fn()
    return out, time.perf_counter() - t0


def main():
    compiled = acausal.compile(PendulumChain(N))
    angles = [f"rev{i}.phi" for i in range(1, N + 1)]
    final = lambda res: np.array([res[a][-1] for a in angles])      # noqa: E731

    ref, t_ref = timed(lambda: compiled.simulate(T, x0=X0))
    first, t_first = timed(lambda: compiled.simulate(T, x0=X0, codegen=True))
    again = acausal.compile(PendulumChain(N))            # a fresh copy: loads from the cache
    second, t_second = timed(lambda: again.simulate(T, x0=X0, codegen=True))
    third, t_third = timed(lambda: again.simulate(T, x0=X0, codegen=True,
                                                  params={"body3.m": 2.0}))
    changed = compiled.simulate(T, x0=X0, params={"body3.m": 2.0})
    dop, t_dop = timed(lambda: again.simulate(T, x0=X0, codegen=True, solver="dop853"))

    print(f"{N}-link pendulum, {T:g} s (solver: {first.solver}); cache: "
          f"{os.environ['ACAUSAL_CACHE']}")
    print(f"  in-process simulate()                  {t_ref:8.3f} s")
    print(f"  codegen, first run (generate + build)  {t_first:8.3f} s")
    print(f"  codegen, fresh compile, cached library {t_second:8.3f} s")
    print(f"  codegen, body3.m = 2 kg (no rebuild)   {t_third:8.3f} s")
    print(f"  codegen, solver='dop853'               {t_dop:8.3f} s")
    print(f"  max |final angles, codegen - in-process|: "
          f"{np.max(np.abs(final(first) - final(ref))):.1e} rad (first), "
          f"{np.max(np.abs(final(second) - final(ref))):.1e} rad (cached), "
          f"{np.max(np.abs(final(third) - final(changed))):.1e} rad (changed mass), "
          f"{np.max(np.abs(final(dop) - final(ref))):.1e} rad (dop853)")
    print(f"  energy drift over the run (relative): {drift(first):.1e} (Adams), "
          f"{drift(dop):.1e} (dop853)")


def drift(res) -> float:
    """The relative change of the potential + kinetic energy of the bodies (m = 1 kg)."""
    energy = 0.0
    for i in range(1, N + 1):
        b = f"body{i}"
        energy = energy + 9.81 * res[f"{b}.r[2]"] + 0.5 * (
            res[f"{b}.v[1]"] ** 2 + res[f"{b}.v[2]"] ** 2) + 0.5 * 0.01 * res[f"{b}.w"] ** 2
    return float(np.ptp(energy) / np.max(np.abs(energy)))


if __name__ == "__main__":
    main()
