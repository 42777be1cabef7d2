"""An FMU with state events: MSL's Rotational.Examples.Friction (a drive train with a clutch
and a brake, Coulomb friction with stuck and sliding modes) exported as a native FMU (C,
FMI 2.0, model exchange and co-simulation) and run by fmpy, against compiled.simulate.

In model exchange fmpy's CVODE locates the crossings of the FMU's event indicators and the
FMU runs the event (reinits, the event iteration of the friction modes) in
fmi2NewDiscreteStates; in co-simulation the FMU locates the events inside its own steps.
The script prints the largest differences and the brake's lock time in each, and saves
``fmu_events.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os
import tempfile

import numpy as np
from fmpy import simulate_fmu

import acausal
from acausal.models.friction import INTERVAL, START, STOP_TIME, RotationalFriction

SIGNALS = ["inertia1.w", "inertia2.w", "inertia3.w", "brake.mode"]


def lock_time(t, mode):
    """The instant the brake sticks (its mode becomes 0)."""
    return t[1:][(mode[1:] == 0) & (mode[:-1] != 0)][0]


def main():
    model = acausal.compile(RotationalFriction())
    grid = np.arange(0.0, STOP_TIME + INTERVAL / 2, INTERVAL)
    ref = model.simulate(STOP_TIME, t=grid, x0=START, rtol=1e-10, atol=1e-12)
    with tempfile.TemporaryDirectory() as tmp:
        path = model.export_fmu(os.path.join(tmp, "friction.fmu"), stop_time=STOP_TIME)
        runs = {kind: simulate_fmu(str(path), fmi_type=kind, stop_time=STOP_TIME,
                                   output_interval=INTERVAL, start_values=START,
                                   relative_tolerance=1e-8, output=SIGNALS)
                for kind in ("ModelExchange", "CoSimulation")}
    print(f"brake locks at t = {lock_time(ref.t, ref['brake.mode']):.9f} s (simulate)")
    for kind, r in runs.items():
        idx = np.searchsorted(r["time"], grid + 1e-9, side="right") - 1   # right limits
        ridx = np.searchsorted(ref.t, grid + 1e-9, side="right") - 1
        err = max(np.max(np.abs(r[n][idx] - ref[n][ridx])) for n in SIGNALS[:3])
        print(f"{kind:14s} largest speed difference {err:.2e} rad/s; brake locks at "
              f"t = {lock_time(r['time'], r['brake.mode']):.9f} s"
              + (" (to the output interval)" if kind == "CoSimulation" else ""))
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(8, 4))
    for n in SIGNALS[:3]:
        ax.plot(ref.t, ref[n], lw=2.5, alpha=0.4, label=f"{n} (simulate)")
        ax.plot(runs["ModelExchange"]["time"], runs["ModelExchange"][n], "--", lw=1,
                label=f"{n} (FMU, fmpy)")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("w [rad/s]")
    ax.legend(fontsize=7)
    ax.set_title("Rotational.Examples.Friction: native FMU (model exchange) vs simulate()")
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "fmu_events.png")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"saved {out}")


if __name__ == "__main__":
    main()
