"""MSL's Rotational.Examples.GenerationOfFMUs: rotational parts behind a pure signal interface,
exported as FMUs and connected again, signal to signal, outside acausal.

A model's own connectors are the inputs and outputs of its FMU, so the blocks of MSL's
Utilities export as they are:

    DirectInertia   inputs tauDrive, tau      outputs phi, w, a    (an inertia with states)
    InverseInertia  inputs phi, w, a          output  tau          (the torque it needs)
    Spring          inputs phi1, phi2         outputs tau1, tau2   (a force law, no states)

The script simulates the composed example in acausal, exports the three blocks as native
FMUs (model exchange, FMI 2.0), connects them in Python through fmpy's FMI calls — the
DirectInertia FMU carrying the InverseInertia FMU (an algebraic loop: the acceleration
needs the torque, the torque the acceleration; linear, solved from two trials), the Spring
FMU between two inertias whose states scipy integrates — and compares both with the
composed model. Saves ``generation_of_fmus.png`` (in $ACAUSAL_OUT, default the current
directory); the FMUs live in a temporary directory below the current one, removed at the end.
"""
from __future__ import annotations

import ctypes
import os
import tempfile

import numpy as np
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Model
from scipy.integrate import solve_ivp

import acausal
from acausal.models.rotational_fmus import (STOP_TIME, DirectInertia, GenerationOfFMUs,
                                            InverseInertia, Spring)


class Block:
    """A model-exchange FMU in continuous-time mode: outputs and state derivatives for the
    time, states and inputs given."""

    def __init__(self, path: str, workdir: str):
        md = read_model_description(path)
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        self.fmu = FMU2Model(guid=md.guid, unzipDirectory=extract(path, os.path.join(
            workdir, os.path.basename(path) + ".d")),
            modelIdentifier=md.modelExchange.modelIdentifier, instanceName="block")
        self.fmu.instantiate()
        self.fmu.setupExperiment(startTime=0.0)
        self.fmu.enterInitializationMode()
        self.fmu.exitInitializationMode()
        self.fmu.enterContinuousTimeMode()

    def __call__(self, t, x, inputs: dict, outputs: tuple):
        self.fmu.setTime(t)
        self.fmu.setReal([self.vr[n] for n in inputs], list(inputs.values()))
        dx = np.zeros(len(x))
        if len(x):
            self.fmu.setContinuousStates((ctypes.c_double * len(x))(*x), len(x))
            buf = (ctypes.c_double * len(x))()
            self.fmu.getDerivatives(buf, len(x))
            dx = np.array(buf)
        return np.array(self.fmu.getReal([self.vr[n] for n in outputs])), dx

    def close(self):
        self.fmu.terminate()
        self.fmu.freeInstance()


def drive(t):
    """The example's sine1 [N.m]."""
    return 10.0 * np.sin(4 * np.pi * t)


def main():
    t = np.linspace(0.0, STOP_TIME, 501)
    composed = acausal.compile(GenerationOfFMUs()).simulate(
        STOP_TIME, t=t, x0=GenerationOfFMUs.START, rtol=1e-10, atol=1e-12)

    with tempfile.TemporaryDirectory(dir=".", prefix="fmus_") as workdir:
        workdir = os.path.abspath(workdir)
        paths = {}
        for name, block in (("direct", DirectInertia(J=1.1)), ("inverse", InverseInertia(J=2.2)),
                            ("spring", Spring(c=1e4))):
            compiled = acausal.compile(block)
            paths[name] = str(compiled.export_fmu(os.path.join(workdir, f"{name}.fmu"),
                                                  fmu_type="me"))
            print(f"{type(block).__name__:15s} inputs {', '.join(compiled.input_names):18s} "
                  f"outputs {', '.join(compiled.output_names)}")
        direct, inverse, spring = (Block(paths[n], workdir) for n in ("direct", "inverse",
                                                                       "spring"))

        def tau_needed(tk, x, trial):
            (phi, w, a), _ = direct(tk, x, {"tauDrive": drive(tk), "tau": trial},
                                    ("phi", "w", "a"))
            return inverse(tk, [], {"phi": phi, "w": w, "a": a}, ("tau",))[0][0]

        def upper(tk, x):
            g0, g1 = tau_needed(tk, x, 0.0), tau_needed(tk, x, 1.0)
            tau = g0 / (1.0 - (g1 - g0))                  # tau = g0 + (g1 − g0)·tau
            return direct(tk, x, {"tauDrive": drive(tk), "tau": tau}, ())[1]

        def lower(tk, x):                                 # inertia3a, inertia3b: phi, w
            (tau1, tau2), _ = spring(tk, [], {"phi1": x[0], "phi2": x[1]}, ("tau1", "tau2"))
            return [x[2], x[3], (drive(tk) - tau1) / 1.1, -tau2 / 2.2]

        opts = dict(t_eval=t, rtol=1e-10, atol=1e-12)
        up = solve_ivp(upper, (0.0, STOP_TIME), [0.0, 0.0], **opts).y
        low = solve_ivp(lower, (0.0, STOP_TIME), [0.0] * 4, **opts).y
        for b in (direct, inverse, spring):
            b.close()

    for label, ours, name in (("DirectInertia + InverseInertia FMUs", up[0],
                               "directInertia.inertia.phi"),
                              ("Spring FMU: inertia3a", low[0], "inertia3a.phi"),
                              ("Spring FMU: inertia3b", low[1], "inertia3b.phi")):
        err = np.max(np.abs(ours - composed[name]))
        print(f"{label:37s} vs the composed model ({name}): max |difference| {err:.1e} rad")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    ax[0].plot(t, composed["directInertia.inertia.phi"], label="composed model")
    ax[0].plot(t[::20], up[0][::20], "o", label="DirectInertia FMU + InverseInertia FMU")
    ax[0].set_ylabel("phi [rad]")
    ax[1].plot(t, composed["inertia3a.w"] - composed["inertia3b.w"], label="composed model")
    ax[1].plot(t[::20], (low[2] - low[3])[::20], "o", label="Spring FMU between the inertias")
    ax[1].set_ylabel("w3a − w3b [rad/s]")
    ax[1].set_xlabel("time [s]")
    for a in ax:
        a.grid(True)
        a.legend(fontsize="small", loc="upper left")
    ax[0].set_title("MSL GenerationOfFMUs: blocks exported as FMUs, connected again")
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "generation_of_fmus.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
