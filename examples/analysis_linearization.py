"""Equilibrium, linearization and modes (acausal.analysis) of the gantry crane
(acausal.models.crane, as in gantry_crane.py): the load hanging at rest is an equilibrium;
about it, the linear model from the force F [N] on the cart to the cart position and the rope
angle, its damped eigenvalues, the undamped natural frequency and mode shape, and (if
python-control is installed) its export as a control.StateSpace with the frequency response.

Prints a summary and saves ``analysis_linearization.png`` (in $ACAUSAL_OUT, default the
current directory): the Bode magnitude from F to the rope angle.
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.analysis import equilibrium, linearize, modes
from acausal.models.crane import CART_MASS, LOAD_MASS, ROPE, GantryCrane


def main():
    crane = acausal.compile(GantryCrane())
    eq = equilibrium(crane, u={"F": 0.0})
    print(f"equilibrium of {crane.name}: cart at {eq['rail.s']:.3g} m, rope angle "
          f"{eq['hinge.phi']:.3g} rad (residual {eq.residual:.1e})")
    lin = linearize(crane, eq, inputs=["F"], outputs=["rail.s", "hinge.phi"])
    print(lin)
    print("A =\n", np.array2string(lin.A, precision=4))
    print("B =", lin.B.ravel())
    m = modes(lin)
    print(m)
    g = 9.81
    w_ref = np.sqrt(g / ROPE * (1 + LOAD_MASS / CART_MASS))   # cart and load swing against each other
    print(f"closed form (undamped, free cart): {w_ref / (2 * np.pi):.4f} Hz")

    w = np.logspace(-1, 2, 400)
    s = 1j * w
    I = np.eye(lin.A.shape[0])
    H = np.array([(lin.C @ np.linalg.solve(sk * I - lin.A, lin.B) + lin.D)[1, 0] for sk in s])
    try:
        import control
        sys_ = lin.to_control("crane")
        mag = control.frequency_response(sys_, w).magnitude[1, 0]
        print(f"python-control: {sys_.nstates} states, inputs {sys_.input_labels}, outputs "
              f"{sys_.output_labels}; |H| agrees to {np.max(np.abs(mag - np.abs(H))):.1e}")
    except ImportError:
        print("python-control not installed: the LinearModel's numpy arrays are used")

    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "analysis_linearization.png")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.loglog(w / (2 * np.pi), np.abs(H), label="F -> hinge.phi [rad/N]")
    for f in m.frequencies:
        ax.axvline(f, color="k", ls=":", label=f"undamped mode {f:.3f} Hz")
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("|H|")
    ax.grid(True, which="both")
    ax.legend()
    ax.set_title("Gantry crane linearized about the hanging load")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
