"""MSL's Blocks.Examples InverseModel, TotalHarmonicDistortion and ShowLogicalSources
(``acausal.models``), against closed forms.

1. InverseModel: the input of a first-order block (T = 0.3 s) computed so that its output
   follows a sine (2 Hz, from 0.2 s) filtered by a first-order CriticalDamping (100 Hz):

       sine --> criticalDamping --> inverseBlockConstraints.u1
       firstOrder1.y --> inverseBlockConstraints.u2,  inverseBlockConstraints.y2 --> firstOrder1.u
       inverseBlockConstraints.y1 --> firstOrder2 (the same block) --> feedback (− sine)

   u1 = u2 holds no unknown (firstOrder1 has no direct feedthrough): the model is compiled
   with ``index_reduction=True``, which makes firstOrder1.y an expression of the filter's
   state and solves the computed input from the constraint's rate. firstOrder2, driven by
   the computed input, follows the filtered sine; the input is T·y' + y.

2. TotalHarmonicDistortion: a 50 Hz voltage (100 V RMS) with its third harmonic (20 V RMS),
   from 0.02 s: THD = 0.2 with respect to the fundamental, 20/sqrt(100² + 20²) with respect
   to the total RMS, valid once a full period of the voltage has been sampled (0.04 s).

3. ShowLogicalSources: BooleanTable, BooleanConstant, BooleanStep, BooleanPulse,
   SampleTrigger and pulse.y and step.y (an And), switching where their definitions say.

Run ``python examples/msl_blocks_examples.py``: prints the comparisons and saves
``msl_blocks_examples.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np
from scipy.integrate import solve_ivp

import acausal
from acausal.models import InverseModel, ShowLogicalSources, TotalHarmonicDistortion

TOL = dict(rtol=1e-10, atol=1e-12)


def sine(t):
    """The InverseModel's sine: offset 1, 2 Hz from 0.2 s."""
    return 1 + np.where(t >= 0.2, np.sin(2 * np.pi * 2 * (t - 0.2)), 0.0)


def inverse_model():
    compiled = acausal.compile(InverseModel(), index_reduction=True)
    print(f"InverseModel: states {compiled.x_names}, algebraic {compiled.z_names}")
    t = np.linspace(0.0, 1.0, 1001)
    res = compiled.simulate(1.0, t=t, **TOL)
    w, T = 2 * np.pi * 100, 0.3
    filtered = solve_ivp(lambda tk, y: (sine(tk) - y) * w, (0.0, 1.0), [1.0], t_eval=t,
                         method="Radau", rtol=1e-12, atol=1e-14, first_step=1e-6).y[0]
    u = T * (sine(t) - filtered) * w + filtered
    print(f"  firstOrder2.y (driven by the computed input) vs the filtered sine: largest "
          f"difference {np.abs(res['firstOrder2.y'] - filtered).max():.1e}")
    print(f"  computed input vs T·y' + y: largest difference "
          f"{np.abs(res['inverseBlockConstraints.y1'] - u).max():.1e} (of "
          f"{np.abs(u).max():.2f})")
    return res


def total_harmonic_distortion():
    mid = np.linspace(0.005, 0.095, 10)             # between the sample instants k·20 ms
    res = acausal.compile(TotalHarmonicDistortion()).simulate(
        0.095, t=np.linspace(0.0, 0.095, 951), **TOL)
    at = np.searchsorted(res.t, mid, side="right") - 1
    for name, theory in (("thd1", 20 / 100), ("thdRMS", 20 / np.hypot(100, 20))):
        y, valid = res[f"{name}.y"][at], res[f"{name}.valid"][at].astype(bool)
        print(f"TotalHarmonicDistortion {name}: {np.round(y[valid], 7)} where valid (from "
              f"{mid[valid][0]:g} s), theory {theory:.7f}")
    return res


def show_logical_sources():
    res = acausal.compile(ShowLogicalSources()).simulate(10.0, t=np.linspace(0, 10, 1001))
    for name, expected in (("table.y", [2, 4, 6, 8]), ("step.y", [4]),
                           ("booleanExpression.y", [4.5, 5.25, 6, 6.75, 7.5, 8.25, 9, 9.75])):
        k = np.flatnonzero(np.diff(res[name]))
        print(f"ShowLogicalSources {name} switches at {np.round(res.t[k + 1], 9).tolist()} s "
              f"(expected {expected})")
    return res


def main():
    inv, thd, logic = inverse_model(), total_harmonic_distortion(), show_logical_sources()

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2, ax3) = plt.subplots(3, 1, figsize=(7, 8))
    ax1.plot(inv.t, sine(inv.t), "k--", label="sine")
    ax1.plot(inv.t, inv["firstOrder2.y"], label="firstOrder2.y (computed input applied)")
    ax1.plot(inv.t, inv["inverseBlockConstraints.y1"], label="computed input")
    ax1.set_title("InverseModel")
    ax1.legend(fontsize=8)
    ax2.plot(thd.t, thd["thd1.y"], label="thd1.y (w.r.t. fundamental)")
    ax2.plot(thd.t, thd["thdRMS.y"], label="thdRMS.y (w.r.t. total RMS)")
    ax2.set_title("TotalHarmonicDistortion")
    ax2.legend(fontsize=8)
    for k, name in enumerate(("table.y", "step.y", "pulse.y", "booleanExpression.y")):
        ax3.step(logic.t, logic[name] + 1.5 * k, where="post", label=name)
    ax3.set_title("ShowLogicalSources (offset by 1.5 each)")
    ax3.set_ylim(-0.3, 7.5)
    ax3.legend(fontsize=8, loc="upper left", ncol=4)
    for ax in (ax1, ax2, ax3):
        ax.set_xlabel("time [s]")
        ax.grid(True)
    fig.tight_layout()
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "msl_blocks_examples.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
