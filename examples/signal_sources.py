"""The sources of Modelica.Blocks.Sources that MSL 4.1 adds to the classic ones, each printed
against its closed form:

    ContinuousClock     y = time − startTime
    Exponentials        a rise to outMax·(1 − exp(−τ/riseTimeConst)), then an exponential fall
    SawTooth            amplitude·(time − T_start)/period, 3 teeth: jumps (time events)
    Sinc                amplitude·sin(x)/x, x = 2π·f·(time − startTime): 1 at x = 0
    LogFrequencySweep   from wMin to wMax, linear in log10
    SineVariableFrequencyAndAmplitude   a chirp: f from a Ramp, phi = ∫2π·f dt
    KinematicPTP        the acceleration of the fastest point-to-point motion; integrated
                        twice it is the position (two Integrators)

Run ``python examples/signal_sources.py``: prints values against the closed forms and saves
``signal_sources.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components.signals import (ContinuousClock, Exponentials, Integrator, KinematicPTP,
                                        LogFrequencySweep, Ramp, SawTooth, Sinc,
                                        SineVariableFrequencyAndAmplitude)

T_END = 3.0


class Sources(acausal.Model):
    """The new sources side by side; the saw tooth and the PTP acceleration integrated."""

    def __init__(self, name=None):
        super().__init__(name)
        self.clock = ContinuousClock(startTime=0.5)
        self.exponentials = Exponentials(outMax=1.0, riseTime=1.0, riseTimeConst=0.25,
                                         fallTimeConst=0.5, startTime=0.25)
        self.sawTooth = SawTooth(amplitude=1.0, period=0.5, nperiod=3, startTime=0.5)
        self.sawArea = Integrator()
        self.sinc = Sinc(f=2.0, startTime=0.5)
        self.sweep = LogFrequencySweep(wMin=0.1, wMax=10.0, startTime=0.5, duration=2.0)
        self.frequency = Ramp(height=4.0, duration=T_END, offset=0.5)
        self.chirp = SineVariableFrequencyAndAmplitude(useConstantAmplitude=True)
        self.ptp = KinematicPTP(deltaq=[1.0], qd_max=[1.0], qdd_max=[2.0], startTime=0.5)
        self.speed, self.position = Integrator(), Integrator()
        for a, b in [(self.sawTooth.y, self.sawArea.u), (self.frequency.y, self.chirp.f),
                     (self.ptp.y[1], self.speed.u), (self.speed.y, self.position.u)]:
            self.connect(a, b)


def main():
    t = np.arange(int(T_END * 128) + 1) / 128.0            # exact binary fractions
    res = acausal.compile(Sources("sources")).simulate(T_END, t=t, rtol=1e-10, atol=1e-12)

    def report(name, closed_form):
        print(f"{name:<28s} largest difference from the closed form "
              f"{np.abs(res[name] - closed_form).max():.1e}")

    tau = t - 0.5
    report("clock.y", np.where(tau < 0, 0.0, tau))
    te = t - 0.25
    rise = 1 - np.exp(-np.maximum(te, 0) / 0.25)
    report("exponentials.y", np.where(te < 0, 0.0, np.where(
        te < 1.0, rise, (1 - np.exp(-4.0)) * np.exp(-(te - 1.0) / 0.5))))
    teeth = np.floor(tau / 0.5)
    report("sawTooth.y", np.where((tau >= 0) & (teeth < 3), (tau - 0.5 * teeth) / 0.5, 0.0))
    full = np.clip(teeth, 0, 3)
    part = np.where((tau >= 0) & (teeth < 3), tau - 0.5 * teeth, 0.0)
    report("sawArea.y", full * 0.5 / 2 + part ** 2 / (2 * 0.5))
    report("sinc.y", np.where(tau < 0, 0.0, np.sinc(2 * 2.0 * tau)))
    print(f"{'sinc.y at x = 0':<28s} {res['sinc.y'][t == 0.5][0]:.17g} (sin(x)/x → 1)")
    report("sweep.y", 0.1 * 100.0 ** np.clip(tau / 2.0, 0, 1))
    report("chirp.phi", 2 * np.pi * (0.5 * t + 4.0 / T_END * t ** 2 / 2))
    # KinematicPTP: 1 rad at 1 rad/s, 2 rad/s²: accelerate 0.5 s, cruise 0.5 s, brake 0.5 s
    print(f"{'position.y at the end':<28s} {res['position.y'][-1]:.12f} (deltaq = 1)")
    print(f"{'speed.y, largest':<28s} {res['speed.y'].max():.12f} (qd_max = 1)")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(4, 2, figsize=(9, 8), sharex=True)
    for ax, names in zip(axes.flat, [("clock.y",), ("exponentials.y",),
                                     ("sawTooth.y", "sawArea.y"), ("sinc.y",), ("sweep.y",),
                                     ("chirp.y",), ("ptp.y[1]", "speed.y", "position.y"),
                                     ("frequency.y",)]):
        for name in names:
            ax.plot(res.t, res[name], label=name)
        ax.legend(fontsize=7)
        ax.grid(True)
    axes[-1, 0].set_xlabel("time [s]")
    axes[-1, 1].set_xlabel("time [s]")
    fig.tight_layout()
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "signal_sources.png")
    fig.savefig(out, dpi=110, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
