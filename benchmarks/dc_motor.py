"""Benchmark: the DC motor as one compact component (rotational.DCMotor) vs composed of
Modelica parts (models.DCMotorCircuit: SignalVoltage, Resistor, Inductor, RotationalEMF,
Inertia) vs a hand-written CasADi model of the same ODE.

    v = 100 V ─> motor (MSL's DC_PermanentMagnet data) ── load: Inertia J_L ── Damper d

x = [phi, w, i]: phi' = w, (J + J_L)·w' = k·i − d·w, L·i' = v − R·i − k·w; 2 s on a grid
of 2001 points, rtol 1e-8, atol 1e-10, each with its own default integrator (acausal picks
from the spectral radius, the hand-written one is CVODES BDF, and also with acausal forced
to CVODES for a like-for-like run).

Measured in the same run, end to end: the model built, compiled, simulated, the speed read
(acausal), or the CasADi expressions built, the integrator created and run (by hand).
Printed: the best of ``--repeat`` runs (wall time, CPU time of this process: the machine may
be shared), compile and simulate separately for acausal, the ratio of CPU times to the
compact motor, and the largest difference of the speed from the hand-written model.

    python benchmarks/dc_motor.py [--repeat 5]
"""
from __future__ import annotations

import argparse
import time

from timing import print_table  # first: pins BLAS threads
import casadi as ca
import numpy as np

import acausal
from acausal.components import rotational as rot
from acausal.models import DCMotorCircuit

V, J_L, D, T_END = 100.0, 0.5, 0.05, 2.0
M = rot.DCMotor
R, L, K, J = M.R.default, M.L.default, M.k.default, M.J.default
GRID = np.linspace(0.0, T_END, 2001)
TOL = {"rtol": 1e-8, "atol": 1e-10}


def drive(motor) -> acausal.Model:
    m = acausal.Model("drive")
    m.v, m.motor = acausal.Input(unit="V", start=V), motor
    m.load, m.damper, m.fixed = rot.Inertia(J=J_L), rot.Damper(d=D), rot.Fixed()
    for a, b in [(m.v.y, m.motor.v), (m.motor.flange, m.load.flange_a),
                 (m.load.flange_b, m.damper.flange_a), (m.damper.flange_b, m.fixed.flange)]:
        m.connect(a, b)
    return m


def run_acausal(make, speed: str, solver=None):
    """(compile wall, compile CPU, simulate wall, simulate CPU, speed [rad/s], solver)."""
    w0, c0 = time.perf_counter(), time.process_time()
    compiled = acausal.compile(drive(make()))
    w1, c1 = time.perf_counter(), time.process_time()
    res = compiled.simulate(T_END, t=GRID, solver=solver, **TOL)
    w = np.asarray(res[speed])
    w2, c2 = time.perf_counter(), time.process_time()
    return w1 - w0, c1 - c0, w2 - w1, c2 - c1, w, res.solver


def run_hand():
    """(wall, CPU, speed [rad/s]): the ODE as CasADi expressions, CVODES on the grid."""
    w0, c0 = time.perf_counter(), time.process_time()
    x = ca.SX.sym("x", 3)
    w, i = x[1], x[2]                      # x = [phi, w, i]
    ode = ca.vertcat(w, (K * i - D * w) / (J + J_L), (V - R * i - K * w) / L)
    F = ca.integrator("motor", "cvodes", {"x": x, "ode": ode}, 0.0, GRID[1:],
                      {"abstol": TOL["atol"], "reltol": TOL["rtol"]})
    xs = np.array(F(x0=[0.0, 0.0, 0.0])["xf"])
    speed = np.concatenate([[0.0], xs[1]])
    return time.perf_counter() - w0, time.process_time() - c0, speed


def best(run, repeat: int):
    """The run with the least total CPU time of ``repeat`` runs."""
    return min((run() for _ in range(repeat)), key=lambda r: r[1] + (r[3] if len(r) > 3
                                                                       else 0.0))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=5)
    repeat = ap.parse_args().repeat
    hand = best(run_hand, repeat)
    rows, base, solvers = [], None, []
    for label, make, speed, solver in (
            ("compact", rot.DCMotor, "motor.w", None),
            ("composed", DCMotorCircuit, "motor.inertia.w", None),
            ("compact*", rot.DCMotor, "motor.w", "cvodes"),
            ("composed*", DCMotorCircuit, "motor.inertia.w", "cvodes")):
        cw, cc, sw, sc, w, used = best(lambda: run_acausal(make, speed, solver), repeat)
        base = base or cc + sc
        solvers.append(f"{label} {used}")
        rows.append((label, cc, sc, cw + sw, cc + sc, (cc + sc) / base,
                     float(np.max(np.abs(w - hand[2])))))
    rows.append(("by hand", float("nan"), float("nan"), hand[0], hand[1], hand[1] / base, 0.0))
    print(f"DC motor on a load, {T_END:g} s, {GRID.size} points; best of {repeat} runs; "
          f"speed at the end {hand[2][-1]:.4f} rad/s; integrators: {', '.join(solvers)}, "
          f"by hand cvodes (* forced to CVODES BDF)\n")
    print_table(["model", "compile", "simulate", "wall [s]", "CPU [s]", "CPU/compct",
                 "max |dw|"], rows,
                ["{:>10s}", "{:>10.4f}", "{:>10.4f}", "{:>10.4f}", "{:>10.4f}", "{:>10.2f}",
                 "{:>10.2e}"])
    print("compile, simulate: CPU [s] of acausal.compile and of simulate + reading the speed")

if __name__ == "__main__":
    main()
