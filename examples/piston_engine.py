"""PlanarMechanics' PistonEngine: a slider-crank whose connecting rod has no mass.

The model is acausal.models.linkages.PistonEngine, PlanarMechanics.Examples.PistonEngine line
by line: a crank (bodyDrive, I = 0.1 kg.m², on the crank's axis) turns on revoluteDrive, a
massless bar of 0.3 m (fixedTranslationDisc) carries revoluteDisc, the massless rod (pistonRod,
0.8 m) pushes the piston (bodyPiston, 3 kg) through revolutePiston along a Prismatic on x.

    fixed ── revoluteDrive ── disc (0.3 m) ── revoluteDisc ── pistonRod (0.8 m, massless)
             bodyDrive                                                │
    fixed1 ── prismatic ── bodyPiston ────────── revolutePiston ──────┘

The loop has four joints: the tree keeps three of them and one closes the loop. Which one
used to depend on the order in which the components were declared: a tree that reaches the
piston through the crank and the slider at once leaves the rod's joint angle without mass.
The compiler now cuts the loop where the tree's coordinates all carry mass (at the crank's
or the slider's ground joint), whatever the order: the script compiles the model in
PlanarMechanics' order and reversed, prints the coordinates each got, simulates 10 s from
PlanarMechanics' initial values (revoluteDrive.phi = 0, w = −2.5 rad/s), and reports the
crank's motion, the energy (gravity does no work here, so ½·I·w² + ½·m·v² stays constant)
and the difference between the two orders. With $ACAUSAL_REFERENCE_RESULTS naming the
directory that holds a copy of PlanarMechanics_ReferenceResults (as the tests take it) it
compares with Dymola's result too. It saves
``piston_engine.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os
import warnings

import numpy as np

import acausal
from acausal.models.linkages import PistonEngine

T_END = PistonEngine.STOP_TIME              # s, PlanarMechanics' experiment
GRID = np.linspace(0.0, T_END, 5001)        # the reference results' grid (0.002 s)


def run(order):
    """Compile the engine with its components declared in ``order`` and simulate it."""
    compiled = acausal.compile(PistonEngine(order=order))
    with warnings.catch_warnings(record=True) as notes:
        warnings.simplefilter("always")
        res = compiled.simulate(T_END, t=GRID, x0=PistonEngine.X0, rtol=1e-10, atol=1e-12)
    label = "PlanarMechanics' order" if order is None else f"{order} order"
    print(f"{label}: coordinates {compiled.coordinates} ({compiled.method})")
    for w in notes:
        print(f"  assembly: {w.message}")
    return res


def reference():
    """Dymola's result (time, revoluteDrive.phi, revoluteDrive.w), if at hand."""
    root = os.environ.get("ACAUSAL_REFERENCE_RESULTS")
    path = os.path.join(root or "", "PlanarMechanics_ReferenceResults", "PlanarMechanics",
                        "Examples", "PistonEngine", "PistonEngine.csv")
    if not root or not os.path.isfile(path):
        return None
    data = np.genfromtxt(path, delimiter=",", names=True)
    return data["Time"], data["revoluteDrivephi"], data["revoluteDrivew"]


def main():
    res = run(None)
    other = run("reversed")
    w = res["revoluteDrive.w"]
    v_piston = res["bodyPiston.v[1]"]
    E = 0.5 * 0.1 * w ** 2 + 0.5 * 3.0 * v_piston ** 2          # J: bodyDrive, bodyPiston
    print(f"crank: {res['revoluteDrive.phi'][-1]:.4f} rad after {T_END:g} s "
          f"({abs(res['revoluteDrive.phi'][-1]) / (2 * np.pi):.2f} turns), speed "
          f"{w.min():.3f}..{w.max():.3f} rad/s")
    print(f"piston: prismatic.s {res['prismatic.s'].min():.3f}..{res['prismatic.s'].max():.3f} "
          f"m (stroke {np.ptp(res['prismatic.s']):.3f} m = 2 x crank)")
    print(f"energy: E0 = {E[0]:.6f} J, max |E - E0| / E0 = {np.max(np.abs(E - E[0])) / E[0]:.1e}")
    for name in ("revoluteDrive.phi", "revoluteDrive.w"):
        print(f"declaration orders: max |{name} difference| = "
              f"{np.max(np.abs(res[name] - other[name])):.1e}")
    ref = reference()
    if ref is not None:
        t, phi, wr = ref
        keep = np.concatenate([np.diff(t) > 0, [True]])         # events repeat a time
        for name, y in (("revoluteDrive.phi", phi[keep]), ("revoluteDrive.w", wr[keep])):
            err = np.max(np.abs(np.interp(t[keep], res.t, res[name]) - y)) / np.max(np.abs(y))
            print(f"MSL reference: max |{name} error| / peak = {err:.1e}")

    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "piston_engine.png")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    ax[0].plot(res.t, res["revoluteDrive.phi"], label="crank revoluteDrive.phi [rad]")
    ax[0].plot(res.t, w, label="crank revoluteDrive.w [rad/s]")
    if ref is not None:
        ax[0].plot(ref[0], ref[2], "k:", label="Dymola (MSL reference) w")
    ax[0].legend()
    ax[1].plot(res.t, res["prismatic.s"], label="piston prismatic.s [m]")
    ax[1].plot(res.t, res["revoluteDisc.phi"], label="rod revoluteDisc.phi [rad]")
    ax[1].legend()
    ax[2].plot(res.t, E - E[0])
    ax[2].set_ylabel("energy drift E − E0 [J]")
    ax[2].set_xlabel("time [s]")
    for a in ax:
        a.grid(True)
    fig.suptitle("PlanarMechanics PistonEngine (massless connecting rod)")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
