"""Gantry crane transfer in minimum time: the load moved by D and at rest at the end.

The crane of acausal.models.crane (cart M on a damped rail, load m on a rope of length L
with a damped hinge; input F [N] pushes the cart). Minimize the final time T [s] (free) with
|F| ≤ F_max, from rest at x = 0 to rest at x = D with the rope vertical (the load at rest
above its target):

    minimize T  s.t.  dynamics,  |F| ≤ F_max,  x(0) = θ(0) = ẋ(0) = θ̇(0) = 0,
                      x(T) = D,  θ(T) = ẋ(T) = θ̇(T) = 0.

The optimal force is bang-bang (F = ±F_max with a few switches). Without the sway
constraint the rigid transfer takes 2·sqrt(D (M + m) / F_max) (accelerate, then brake): a
lower bound. The script solves by direct collocation (Radau) and by multiple shooting (RK4)
and saves ``ocp_crane_min_time.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os
import time

import numpy as np

import acausal
from acausal.ocp import OCP, FreeTime
from acausal.models.crane import CART_MASS, LOAD_MASS, GantryCrane

DISTANCE, F_MAX = 1.0, 10.0                  # m, N
REST = {"hinge.phi": 0.0, "rail.v": 0.0, "hinge.w": 0.0}


def min_time_transfer(compiled, N=40, method="collocation", **kw) -> OCP:
    """The minimum-time transfer through acausal.ocp (not yet solved)."""
    ocp = OCP(compiled, N=N, T=FreeTime(guess=3.0, lower=0.1, upper=20.0), method=method, **kw)
    ocp.minimize(ocp.T)
    ocp.bounds("F", -F_MAX, F_MAX)
    ocp.initial({"rail.s": 0.0, **REST})
    ocp.final({"rail.s": DISTANCE, **REST})
    return ocp


def rigid_bound() -> float:
    """Minimum time [s] of the transfer of a rigid cart-and-load (no sway) from rest to rest."""
    return 2.0 * np.sqrt(DISTANCE * (CART_MASS + LOAD_MASS) / F_MAX)


def main():
    compiled = acausal.compile(GantryCrane())
    sols = {}
    for method in ("collocation", "shooting"):
        t0 = time.perf_counter()
        sols[method] = sol = min_time_transfer(compiled, method=method).solve({"tol": 1e-10})
        F = sol.control("F")
        print(f"{method:11s}: T = {sol.T:.6f} s ({sol.iterations} iterations, "
              f"{time.perf_counter() - t0:.2f} s); |F| at its bound on "
              f"{np.sum(np.abs(np.abs(F) - F_MAX) < 1e-6)} of {F.size} intervals; load at "
              f"x = {sol['load.r[1]'][-1]:.6f} m, speed {sol['load.v[1]'][-1]:.1e} m/s")
    print(f"rigid transfer (no sway) lower bound: {rigid_bound():.4f} s")
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "ocp_crane_min_time.png")
    sols["collocation"].plot("rail.s", "load.r[1]", "hinge.phi", "F", path=out)
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
