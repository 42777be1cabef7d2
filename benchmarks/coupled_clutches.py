"""Benchmark: MSL's CoupledClutches (acausal.models.clutches) with exact clutches on state
events vs what users do without events (tanh friction) and vs an event-driven scipy model.

    torque ── J1 ── clutch1 ── J2 ── clutch2 ── J3 ── clutch3 ── J4

J1..J4 1 kg.m², torque 10·sin(2π·5·t) N.m on J1 (10 rad/s at the start, the others at
rest); clutch k (mu 0.5, peak 1.1) pressed by fn1 = 20·cos(2π·0.2·t) N while positive,
fn2 = 20 N from 0.4 s, fn3 = 20 N from 0.9 s; 1.5 s (MSL's experiment).

Measured in the same run, end to end (Model built, compiled, first simulation, results read):
- acausal, exact: Clutch on the state-event engine (rtol 1e-8, and 1e-5);
- acausal smooth form, ``compile(model, smooth=True)``, when this version has the clutch's;
- CasADi by hand with tanh friction, what ModelingToolkit / hand-written models do:
  tau = mu·fn·(1 + (peak − 1)·exp(−(w/w_s)²))·tanh(w/w_t), w_s = 10·w_t (so it holds up to
  about peak·mu·fn), cvodes BDF rtol 1e-8, for w_t = 1e-1 .. 1e-6 rad/s (the smaller, the
  closer to Coulomb and the stiffer);
- scipy solve_ivp (DOP853, rtol 1e-10) with an event function per clutch and the modes
  switched by hand between runs (a stuck clutch's torque from the linear system of the
  coupled inertias): an independent event-driven model.
Accuracy: the largest error of J1.phi, J1.w and each clutch's phi_rel, w_rel over the run
against MSL's reference result (MAP-LIB_ReferenceResults, Dymola; from the directory named
by ACAUSAL_REFERENCE_RESULTS or shared/ beside the repository), each relative to the
signal's peak; without the reference, against the scipy model. Printed: the best of
``--repeat`` runs of wall and CPU time (the CPU time of this process: the machine may be
shared), the ratio of CPU times to acausal exact, the error; then the cheapest tanh model as
accurate as acausal.

    python benchmarks/coupled_clutches.py [--repeat 3]
"""
from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

from timing import print_table  # first: pins BLAS threads
import casadi as ca
import numpy as np
from scipy.integrate import solve_ivp

import acausal
from acausal.models.clutches import START, STOP_TIME, CoupledClutches

J, MU, PEAK, FN, TAU_AMP, F_TAU = 1.0, 0.5, 1.1, 20.0, 10.0, 5.0
F2, T2, T3 = 0.2, 0.4, 0.9
T1 = 1 / (4 * F2)                 # clutch1 released: fn1 = 20·cos(2π·F2·t) falls through 0
SIGNALS = ["J1.phi", "J1.w"] + [f"clutch{k}.{v}" for k in (1, 2, 3) for v in ("phi_rel",
                                                                              "w_rel")]


def reference():
    """MSL's reference result (name -> values, event times kept once), or None."""
    parts = "Modelica/Mechanics/Rotational/Examples/CoupledClutches/CoupledClutches.csv"
    roots = [os.environ.get("ACAUSAL_REFERENCE_RESULTS", ""),
             Path(__file__).resolve().parents[2] / "shared"]
    for root in roots:
        path = Path(root) / "MAP-LIB_ReferenceResults" / parts
        if root and path.is_file():
            names = [n.strip().strip('"') for n in path.read_text().split("\n", 1)[0].split(",")]
            data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
            keep = np.append(data[1:, 0] != data[:-1, 0], True)
            return {n: data[keep, k] for k, n in enumerate(names)}
    return None


def signals(t, phi, w) -> dict:
    """The compared signals from the inertias' angles and speeds (rows J1..J4)."""
    out = {"time": t, "J1.phi": phi[0], "J1.w": w[0]}
    for k in (1, 2, 3):
        out[f"clutch{k}.phi_rel"] = phi[k] - phi[k - 1]
        out[f"clutch{k}.w_rel"] = w[k] - w[k - 1]
    return out


def error(result: dict, ref: dict) -> float:
    """The largest error of the compared signals relative to their peaks."""
    return max(np.max(np.abs(result[n] - ref[n])) / np.max(np.abs(ref[n])) for n in SIGNALS)


def normal_forces(t):
    """fn1, fn2, fn3 [N] at time t (numbers or CasADi expressions)."""
    if isinstance(t, ca.SX):
        return (FN * ca.fmax(ca.cos(2 * ca.pi * F2 * t), 0), FN * (t >= T2), FN * (t >= T3))
    return (FN * np.cos(2 * np.pi * F2 * t) * (t < T1), FN * (t >= T2), FN * (t >= T3))


def measure(run, repeat: int):
    """(best wall time [s], best CPU time [s], result of the last run) of ``repeat`` runs."""
    walls, cpus = [], []
    for _ in range(repeat):
        w0, c0 = time.perf_counter(), time.process_time()
        out = run()
        walls.append(time.perf_counter() - w0)
        cpus.append(time.process_time() - c0)
    return min(walls), min(cpus), out


# ---- acausal ------------------------------------------------------------------------------
def run_acausal(grid, smooth=False, rtol=1e-8):
    """(the compared signals, the number of events): built, compiled, simulated."""
    compiled = acausal.compile(CoupledClutches(), smooth=smooth)
    res = compiled.simulate(STOP_TIME, t=grid, x0=START, rtol=rtol, atol=rtol * 1e-2)
    at = np.searchsorted(res.t, grid, side="right") - 1             # right limits
    return {n: np.asarray(res[n])[at] for n in SIGNALS}, len(getattr(res, "events", []))


def has_smooth_form() -> bool:
    """Whether this version writes the Clutch without events when compiled smooth."""
    try:
        return not acausal.compile(CoupledClutches(), smooth=True).has_events
    except TypeError:
        return False


# ---- CasADi by hand, tanh friction --------------------------------------------------------
def run_tanh(grid, w_t: float):
    """The compared signals: CasADi expressions built, integrator created and run."""
    phi, w, t = ca.SX.sym("phi", 4), ca.SX.sym("w", 4), ca.SX.sym("t")
    w_rel = w[1:] - w[:-1]
    fn = ca.vertcat(*normal_forces(t))
    tau = MU * fn * (1 + (PEAK - 1) * ca.exp(-(w_rel / (10 * w_t)) ** 2)) * ca.tanh(w_rel / w_t)
    drive = ca.vertcat(TAU_AMP * ca.sin(2 * ca.pi * F_TAU * t), 0, 0, 0)
    acc = (drive + ca.vertcat(tau, 0) - ca.vertcat(0, tau)) / J
    integ = ca.integrator("tanh", "cvodes", {"x": ca.vertcat(phi, w), "t": t,
                                             "ode": ca.vertcat(w, acc)}, 0.0, list(grid[1:]),
                          {"abstol": 1e-10, "reltol": 1e-8, "max_num_steps": 10 ** 6})
    x0 = np.array([0, 0, 0, 0, 10.0, 0, 0, 0])
    X = np.column_stack([x0, np.array(integ(x0=x0)["xf"])])
    return signals(grid, X[:4], X[4:])


# ---- scipy, event-driven ------------------------------------------------------------------
def accelerations(t, w, mode):
    """(a [rad/s²] of J1..J4, tau [N.m] of the clutches) for the modes (−1 backward, 0 stuck,
    1 forward, 2 free): J·a_k = drive_k + tau_k − tau_(k−1), a stuck clutch's a_rel = 0."""
    fn = normal_forces(t)
    stuck = [k for k in range(3) if mode[k] == 0]
    n = 4 + len(stuck)
    A, b = np.zeros((n, n)), np.zeros(n)
    A[:4, :4] = np.eye(4) * J
    b[0] = TAU_AMP * np.sin(2 * np.pi * F_TAU * t)
    tau = np.array([0.0 if mode[k] == 2 else mode[k] * MU * fn[k] for k in range(3)])
    for k in range(3):
        if k not in stuck:
            b[k] += tau[k]
            b[k + 1] -= tau[k]
    for j, k in enumerate(stuck):          # unknown tau_k: column 4 + j, row a_rel = 0
        A[k, 4 + j], A[k + 1, 4 + j] = -1.0, 1.0
        A[4 + j, k + 1], A[4 + j, k] = 1.0, -1.0
    sol = np.linalg.solve(A, b)
    for j, k in enumerate(stuck):
        tau[k] = sol[4 + j]
    return sol[:4], tau


def settle(t, x, mode):
    """The event iteration: a free clutch is engaged (stuck at w_rel = 0, else sliding its
    way) when fn > 0; a stuck one breaks away beyond peak·tau0 (its w_rel is 0); a sliding
    one at w_rel = 0 sticks unless its acceleration keeps its direction."""
    fn = normal_forces(t)
    for _ in range(20):
        new = mode.copy()
        a, tau = accelerations(t, x[4:], mode)
        for k in range(3):
            w_rel, a_rel = x[5 + k] - x[4 + k], a[k + 1] - a[k]
            if fn[k] <= 0:
                new[k] = 2
            elif mode[k] == 2:
                new[k] = np.sign(w_rel)
            elif mode[k] == 0 and abs(tau[k]) > PEAK * MU * fn[k]:
                new[k] = np.sign(tau[k])
            elif mode[k] in (-1, 1) and w_rel == 0 and mode[k] * a_rel <= 0:
                new[k] = 0
        if np.array_equal(new, mode):
            return mode
        mode = new
    raise RuntimeError(f"the clutches' modes do not settle at t = {t}")


def run_scipy(grid, rtol=1e-10):
    """(the compared signals, the number of mode changes)."""

    def rhs(t, x, mode):
        return np.concatenate([x[4:], accelerations(t, x[4:], mode)[0]])

    def events(mode):
        """Per clutch: its w_rel falling through 0 in its direction while sliding, the
        margin to its breakaway torque falling through 0 while stuck."""
        def event(k):
            def g(t, x, _mode):
                if mode[k] == 0:
                    return PEAK * MU * normal_forces(t)[k] - abs(accelerations(t, x[4:],
                                                                                mode)[1][k])
                if mode[k] == 2:
                    return 1.0
                return mode[k] * (x[5 + k] - x[4 + k])
            g.terminal, g.direction = True, -1
            return g
        return [event(k) for k in range(3)]

    t, x = 0.0, np.array([0, 0, 0, 0, 10.0, 0, 0, 0])
    mode = settle(t, x, np.array([2, 2, 2]))
    T, X, changes = [], [], 0
    for stop in (T2, T3, T1, STOP_TIME):      # the time events: a clutch engaged, released
        while t < stop:
            out = grid[(grid > t) & (grid <= stop)]
            sol = solve_ivp(rhs, (t, stop), x, method="DOP853", rtol=rtol, atol=1e-12,
                            args=(mode,), events=events(mode), dense_output=True)
            t_end = sol.t[-1]
            keep = out[out <= t_end]
            T.append(keep)
            X.append(sol.sol(keep) if len(keep) else np.zeros((8, 0)))
            t, x = t_end, sol.y[:, -1].copy()
            if sol.status == 1:
                new = mode.copy()
                for k in range(3):
                    if len(sol.t_events[k]) and mode[k] in (-1, 1):
                        x[5 + k] = x[4 + k]         # stuck exactly, if it stays
                    elif len(sol.t_events[k]):      # breaks away the way it is pulled
                        new[k] = np.sign(accelerations(t, x[4:], mode)[1][k])
                new = settle(t, x, new)
                changes += int(np.sum(new != mode))
                mode = new
        new = settle(t, x, mode)                    # at the time event
        changes += int(np.sum(new != mode))
        mode = new
    T = np.concatenate([[0.0]] + T)
    X = np.column_stack([np.array([0, 0, 0, 0, 10.0, 0, 0, 0])[:, None]] + X)
    _, idx = np.unique(T, return_index=True)
    return signals(T[idx], X[:4, idx], X[4:, idx]), changes


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    repeat = ap.parse_args().repeat
    ref = reference()
    grid = ref["time"] if ref is not None else np.linspace(0.0, STOP_TIME, 1501)
    w_sp, c_sp, (sp, changes) = measure(lambda: run_scipy(grid), 1)
    if ref is None:
        ref = sp
        print("MSL reference result not at hand: errors against the scipy event model")
    w_ac, c_ac, (ac, events) = measure(lambda: run_acausal(grid), repeat)
    print(f"CoupledClutches: {events} events in acausal, {changes} mode changes in scipy\n")
    rows = [("acausal exact", w_ac, c_ac, 1.0, error(ac, ref))]
    w, c, (lo, _) = measure(lambda: run_acausal(grid, rtol=1e-5), repeat)
    rows.append(("exact 1e-5", w, c, c / c_ac, error(lo, ref)))
    if has_smooth_form():
        w, c, (sm, _) = measure(lambda: run_acausal(grid, smooth=True), repeat)
        rows.append(("acausal smooth", w, c, c / c_ac, error(sm, ref)))
    tanh = []
    for w_t in (1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6):
        w, c, h = measure(lambda: run_tanh(grid, w_t), repeat)
        tanh.append((c, w_t, error(h, ref)))
        rows.append((f"tanh {w_t:g}", w, c, c / c_ac, tanh[-1][2]))
    rows.append(("scipy events", w_sp, c_sp, c_sp / c_ac, error(sp, ref)))
    print_table(["method", "wall [s]", "CPU [s]", "CPU/acausal", "max err/peak"], rows,
                ["{:>14s}", "{:>10.3f}", "{:>10.3f}", "{:>10.2f}", "{:>12.2e}"])
    for name, target in (("acausal exact", rows[0][4]), ("acausal at rtol 1e-5", rows[1][4]),
                         ("MSL's acceptance", 2e-3)):
        ok = [(c, w_t) for c, w_t, err in tanh if err <= target]
        print(f"as accurate as {name} ({target:.1e} of the peaks): "
              + (f"tanh w_t = {min(ok)[1]:g}, {min(ok)[0]:.3f} s CPU, "
                 f"{min(ok)[0] / c_ac:.2f} x acausal exact" if ok else
                 "no tanh model of the sweep"))


if __name__ == "__main__":
    main()
