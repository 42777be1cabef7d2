"""MSL Math and Nonlinear blocks in two small signal-processing chains, against closed forms.

1. Mains measurement (50 Hz, amplitude 325 V):

       va, vb, vc (Sine, phases 0, −2π/3, 2π/3) --> MatrixGain (Clarke) --> alpha, beta
       alpha, beta --> MultiProduct (squares) --> MultiSum --> Sqrt: |v| = 325 V
       beta, alpha --> Atan2: the voltage's angle, 2π·50·t wrapped to [−π, π]
       va --> RootMeanSquare(f=50): 325/√2 V;   va --> Abs --> Mean(f=50): 2·325/π V

   Mean and RootMeanSquare update at the end of every period (sampled), held in between.

2. A set point step, rate-limited and delayed:

       Step --> SlewRateLimiter(Rising=2/s) --> PadeDelay(delayTime=0.1 s, n=4, balance)

   The limited step is a ramp of slope 2/s; the Padé delay follows the ramp delayed by
   0.1 s, within a small error where the ramp kinks.

Run ``python examples/math_blocks.py``: prints the values against their closed forms and
saves ``math_blocks.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components.signals import (Abs, Atan2, MatrixGain, Mean, MultiProduct, MultiSum,
                                        PadeDelay, RootMeanSquare, Sine, SlewRateLimiter,
                                        Sqrt, Step)

V, F = 325.0, 50.0                           # mains amplitude [V], frequency [Hz]
CLARKE = (2 / 3) * np.array([[1.0, -0.5, -0.5], [0.0, np.sqrt(3) / 2, -np.sqrt(3) / 2]])
RISING, TD, DELAY = 2.0, 1e-3, 0.1          # slew rate [1/s], its Td [s], delay [s]


class Mains(acausal.Model):
    """Three-phase voltages, their space vector's magnitude and angle, RMS and rectified
    mean of one phase."""

    def __init__(self, name=None):
        super().__init__(name)
        self.va = Sine(amplitude=V, f=F)
        self.vb = Sine(amplitude=V, f=F, phase=-2 * np.pi / 3)
        self.vc = Sine(amplitude=V, f=F, phase=2 * np.pi / 3)
        self.clarke = MatrixGain(K=CLARKE)
        self.alpha2, self.beta2 = MultiProduct(nu=2), MultiProduct(nu=2)
        self.sum2 = MultiSum(nu=2)
        self.magnitude = Sqrt()
        self.angle = Atan2()
        self.rms = RootMeanSquare(f=F)
        self.rectified = Abs()
        self.mean = Mean(f=F)
        alpha, beta = self.clarke.y[1], self.clarke.y[2]
        for k, phase in enumerate((self.va, self.vb, self.vc), start=1):
            self.connect(phase.y, self.clarke.u[k])
        for square, signal in ((self.alpha2, alpha), (self.beta2, beta)):
            self.connect(signal, square.u[1])
            self.connect(signal, square.u[2])
        for k, square in enumerate((self.alpha2, self.beta2), start=1):
            self.connect(square.y, self.sum2.u[k])
        for a, b in [(self.sum2.y, self.magnitude.u), (beta, self.angle.u1),
                     (alpha, self.angle.u2), (self.va.y, self.rms.u),
                     (self.va.y, self.rectified.u), (self.rectified.y, self.mean.u)]:
            self.connect(a, b)


class SetPoint(acausal.Model):
    """A unit step, rate-limited, then delayed by a Padé approximation."""

    def __init__(self, name=None):
        super().__init__(name)
        self.step = Step(startTime=0.2)
        self.slew = SlewRateLimiter(Rising=RISING, Td=TD)
        self.delay = PadeDelay(delayTime=DELAY, n=4, balance=True)
        self.connect(self.step.y, self.slew.u)
        self.connect(self.slew.y, self.delay.u)


def main():
    tol = dict(rtol=1e-10, atol=1e-8)
    t1 = np.linspace(0.0, 0.1, 2001)
    mains = acausal.compile(Mains("mains")).simulate(t1[-1], t=t1, **tol)
    mid = np.array([1.5, 2.5, 3.5]) / F       # mid-periods: the values of the last period
    at = {n: np.interp(mid, mains.t, mains[n]) for n in ("rms.y", "mean.y")}
    print(f"|v| = sqrt(alpha² + beta²): {mains['magnitude.y'].min():.6f} .. "
          f"{mains['magnitude.y'].max():.6f} V (closed form {V:g} V)")
    angle = np.angle(np.exp(1j * (2 * np.pi * F * mains.t - np.pi / 2)))
    print(f"Atan2(beta, alpha) - (2π·50·t − π/2) wrapped: largest difference "
          f"{np.abs(np.angle(np.exp(1j * (mains['angle.y'] - angle)))).max():.1e} rad")
    print(f"RootMeanSquare over each period: {at['rms.y']} V (closed form "
          f"{V / np.sqrt(2):.6f} V)")
    print(f"Mean of Abs over each period:    {at['mean.y']} V (closed form "
          f"{2 * V / np.pi:.6f} V)")

    t2 = np.linspace(0.0, 1.5, 1501)
    sp = acausal.compile(SetPoint("setpoint")).simulate(t2[-1], t=t2, **tol)
    ramp = lambda t: np.clip(RISING * (t - 0.2), 0.0, 1.0)       # noqa: E731
    slew, delayed = np.interp(t2, sp.t, sp["slew.y"]), np.interp(t2, sp.t, sp["delay.y"])
    print(f"SlewRateLimiter vs the ramp of slope {RISING:g}/s: largest difference "
          f"{np.abs(slew - ramp(t2)).max():.2e} (closed form Td·Rising/e = "
          f"{TD * RISING / np.e:.2e}: where the ramp ends, y approaches u as exp(−t/Td))")
    print(f"PadeDelay(n=4) vs the ramp delayed by {DELAY:g} s: largest difference "
          f"{np.abs(delayed - ramp(t2 - DELAY)).max():.1e}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 6))
    ax1.plot(mains.t, mains["va.y"], label="va")
    ax1.plot(mains.t, mains["magnitude.y"], label="|v| (Clarke, Sqrt)")
    ax1.plot(mains.t, mains["rms.y"], label="RootMeanSquare(va)")
    ax1.plot(mains.t, mains["mean.y"], label="Mean(Abs(va))")
    ax1.set_xlabel("time [s]")
    ax1.set_ylabel("[V]")
    ax1.legend(fontsize=8)
    ax1.grid(True)
    ax2.plot(sp.t, sp["step.y"], "k--", label="step")
    ax2.plot(t2, slew, label="SlewRateLimiter")
    ax2.plot(t2, delayed, label=f"PadeDelay ({DELAY:g} s, n = 4)")
    ax2.plot(t2, ramp(t2 - DELAY), ":", label="ramp delayed exactly")
    ax2.set_xlabel("time [s]")
    ax2.legend(fontsize=8)
    ax2.grid(True)
    fig.tight_layout()
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "math_blocks.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
