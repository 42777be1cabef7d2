"""Benchmark: a chain of N masses in stick-slip, exact friction on events vs what users do
without events (tanh friction) and vs an event-driven scipy model.

    drive (v_d) ── spring ── mass1 ── spring ── mass2 ── ... ── massN
                              │ SupportFriction        │ SupportFriction

m = 1 kg, c = 100 N/m (every spring, unstretched at rest), the first spring's end driven at
v_d = 0.1 m/s; mass i rubs on the ground with Coulomb friction F_i = 1 + 0.01·i N sliding and
peak·F_i = 1.5·F_i stuck (MSL's SupportFriction: f_pos = [[0, F_i]], peak = 1.5). All at
rest at t = 0; 10 s. The masses stick and slip one after another as the load travels down
the chain (hundreds of mode changes).

Measured in the same run, end to end (Model built, compiled, simulated, trajectories read):
- acausal, exact: SupportFriction on the state-event engine (rtol 1e-8);
- acausal smooth form, ``compile(model, smooth=True)`` (the regularization optimal control
  uses), when this version has it;
- CasADi by hand with tanh friction, what ModelingToolkit / hand-written models do:
  f = F_i·(1 + (peak − 1)·exp(−(v/v_s)²))·tanh(v/v_t), v_s = 10·v_t (so it holds up to
  about peak·F_i), cvodes BDF, for v_t = 1e-2,
  1e-3, 1e-4 m/s (the smaller v_t, the closer to Coulomb and the stiffer);
- scipy solve_ivp (DOP853, rtol 1e-10) with one event function per mass and the modes
  switched by hand between runs: the independent reference of the exact model.
Printed: wall time, ratio to acausal, and the max error of the final positions [m] against
the scipy event reference.

    python benchmarks/stick_slip.py           # N = 50
    python benchmarks/stick_slip.py --n 10
"""
from __future__ import annotations

import argparse
import time

from timing import print_table  # first: pins BLAS threads
import casadi as ca
import numpy as np
from scipy.integrate import solve_ivp

import acausal
from acausal.components.translational import ConstantSpeed, Mass, Spring, SupportFriction

MASS, STIFF, SPEED, PEAK, T_FINAL = 1.0, 100.0, 0.1, 1.5, 10.0


def coulomb(n: int) -> np.ndarray:
    """Sliding friction force F_i [N] of each mass."""
    return 1.0 + 0.01 * np.arange(1, n + 1)


# ---- acausal ------------------------------------------------------------------------------
def build(n: int) -> acausal.Model:
    model = acausal.Model(f"StickSlip{n}")
    model.drive = ConstantSpeed(v_fixed=SPEED)
    prev = model.drive.flange
    for i, f in enumerate(coulomb(n), start=1):
        spring, mass = Spring(c=STIFF), Mass(m=MASS)
        friction = SupportFriction(f_pos=[[0.0, f]], peak=PEAK)
        setattr(model, f"spring{i}", spring)
        setattr(model, f"mass{i}", mass)
        setattr(model, f"friction{i}", friction)
        model.connect(prev, spring.flange_a)
        model.connect(spring.flange_b, mass.flange_a)
        model.connect(mass.flange_b, friction.flange_a)
        prev = mass.flange_b
    return model


def run_acausal(n: int, smooth: bool = False):
    """(seconds end to end, final positions, number of events)."""
    t0 = time.perf_counter()
    compiled = acausal.compile(build(n), smooth=smooth)
    res = compiled.simulate(T_FINAL, t=np.linspace(0, T_FINAL, 101), rtol=1e-8, atol=1e-10)
    s = np.array([res[f"mass{i}.s"][-1] for i in range(1, n + 1)])
    return time.perf_counter() - t0, s, len(getattr(res, "events", []))


def has_smooth_form(n: int) -> bool:
    """Whether this version writes SupportFriction without events when compiled smooth."""
    try:
        return not acausal.compile(build(1), smooth=True).has_events
    except TypeError:
        return False


# ---- CasADi by hand, tanh friction --------------------------------------------------------
def run_tanh(n: int, v_t: float):
    """(seconds: build, integrator creation and run; final positions)."""
    t0 = time.perf_counter()
    s, v, t = ca.SX.sym("s", n), ca.SX.sym("v", n), ca.SX.sym("t")
    f = coulomb(n)
    left = ca.vertcat(SPEED * t, s[:-1])
    right = ca.vertcat(s[1:], s[-1])
    spring = STIFF * (left - s) + STIFF * (right - s)
    friction = f * (1 + (PEAK - 1) * ca.exp(-(v / (10 * v_t)) ** 2)) * ca.tanh(v / v_t)
    ode = ca.vertcat(v, (spring - friction) / MASS)
    grid = np.linspace(0, T_FINAL, 101)
    integ = ca.integrator("tanh", "cvodes", {"x": ca.vertcat(s, v), "t": t, "ode": ode},
                          0.0, grid, {"abstol": 1e-10, "reltol": 1e-8, "max_num_steps": 10**6})
    xf = np.array(integ(x0=np.zeros(2 * n))["xf"])
    return time.perf_counter() - t0, xf[:n, -1]


# ---- scipy, event-driven ------------------------------------------------------------------
def run_scipy(n: int, rtol: float = 1e-10):
    """(seconds, final positions, number of mode changes): each mass stuck (0) or sliding
    (±1); a sliding mass whose speed reaches 0 sticks if the spring force is within
    peak·F_i, else slides the other way; a stuck mass breaks away when the spring force
    exceeds peak·F_i. Stuck masses are held (v = 0, a = 0); the integration restarts at
    every mode change."""
    t_start = time.perf_counter()
    f = coulomb(n)

    def spring(t, s):
        left = np.concatenate(([SPEED * t], s[:-1]))
        right = np.concatenate((s[1:], [s[-1]]))
        return STIFF * (left - s) + STIFF * (right - s)

    def rhs(t, x, mode):
        s, v = x[:n], x[n:]
        a = (spring(t, s) - mode * f) / MASS
        return np.concatenate((np.where(mode == 0, 0.0, v), np.where(mode == 0, 0.0, a)))

    def indicators(mode):
        def event(i):
            def g(t, x, _mode):
                if mode[i] == 0:
                    return PEAK * f[i] - abs(spring(t, x[:n])[i])
                return mode[i] * x[n + i]
            g.terminal, g.direction = True, -1
            return g
        return [event(i) for i in range(n)]

    t, x, mode, changes = 0.0, np.zeros(2 * n), np.zeros(n), 0
    while t < T_FINAL:
        sol = solve_ivp(rhs, (t, T_FINAL), x, method="DOP853", rtol=rtol, atol=1e-12,
                        args=(mode,), events=indicators(mode))
        t, x = sol.t[-1], sol.y[:, -1].copy()
        if sol.status != 1:
            break
        for i in [i for i, te in enumerate(sol.t_events) if len(te)]:
            force = spring(t, x[:n])[i]
            if mode[i] == 0:
                mode[i] = np.sign(force)
            else:
                x[n + i] = 0.0
                mode[i] = 0 if abs(force) <= PEAK * f[i] else np.sign(force)
            changes += 1
    return time.perf_counter() - t_start, x[:n], changes


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=50)
    n = ap.parse_args().n

    t_ref, s_ref, changes = run_scipy(n)
    t_ac, s_ac, events = run_acausal(n)
    print(f"stick-slip chain, N = {n}: {changes} mode changes in the scipy reference, "
          f"{events} events in acausal\n")
    rows = [("acausal exact", t_ac, 1.0, np.max(np.abs(s_ac - s_ref)))]
    if has_smooth_form(n):
        t_sm, s_sm, _ = run_acausal(n, smooth=True)
        rows.append(("acausal smooth", t_sm, t_sm / t_ac, np.max(np.abs(s_sm - s_ref))))
    for v_t in (1e-2, 1e-3, 1e-4):
        t_h, s_h = run_tanh(n, v_t)
        rows.append((f"tanh {v_t:g}", t_h, t_h / t_ac, np.max(np.abs(s_h - s_ref))))
    rows.append(("scipy events", t_ref, t_ref / t_ac, 0.0))
    print_table(["method", "time [s]", "/ acausal", "max err [m]"], rows,
                ["{:>10s}", "{:>10.3f}", "{:>10.2f}", "{:>10.2e}"])


if __name__ == "__main__":
    main()
