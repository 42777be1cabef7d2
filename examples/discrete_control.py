"""A discrete PI controller (Modelica.Blocks.Discrete.TransferFunction) sampling a continuous
plant through a ZeroOrderHold, compared with its continuous counterpart and checked against
the plant's exact discretization (scipy.signal.cont2discrete).

Block diagram (sampled loop):

    setpoint (Step) --> Feedback.u1    Feedback.y --> ctrl (Discrete.TransferFunction)
    plant.y ----------> Feedback.u2    ctrl.y --> zoh (ZeroOrderHold) --> plant --> y

The plant G(s) = 1/((s + 1)(s + 0.5)) is a continuous TransferFunction; the continuous loop
has Continuous.PI(k, T) in place of ctrl and zoh. The discrete controller is the PI
discretized by Tustin's rule with sample period Ts:

    C(z) = (k·(1 + Ts/(2T))·z − k·(1 − Ts/(2T))) / (z − 1)

At each instant t_k = k·Ts the controller takes the error sampled there and the hold puts
its output on the plant until the next instant; written by hand with the plant's exact
(zero order hold) discretization, x[k+1] = Ad x[k] + Bd c[k], the sampled loop's plant
output at the instants is reproduced to the integrator's tolerance. The sampled loop
approaches the continuous one as Ts shrinks (Tustin's PI plus the hold's delay of Ts/2).

Run ``python examples/discrete_control.py``: prints the comparison and saves
``discrete_control.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np
import scipy.signal as sig

import acausal
from acausal.components import discrete as dc
from acausal.components import signals as sg

B_PLANT, A_PLANT = [1.0], [1.0, 1.5, 0.5]        # G(s) = 1/((s + 1)(s + 0.5))
K, TI, T_STEP, T_END = 1.2, 0.8, 0.12, 12.0
PERIODS = (0.05, 0.3)                             # sample periods Ts [s]


def tustin_pi(ts: float) -> tuple[list, list]:
    """b, a of the PI k·(1 + 1/(TI·s)) discretized by Tustin's rule with period ts."""
    return [K * (1 + ts / (2 * TI)), -K * (1 - ts / (2 * TI))], [1.0, -1.0]


class Loop(acausal.Model):
    """The plant under PI control: continuous (``ts`` None) or sampled every ``ts`` [s]."""

    def __init__(self, name=None, ts: float | None = None):
        super().__init__(name)
        self.setpoint, self.error = sg.Step(startTime=T_STEP), sg.Feedback()
        self.plant = sg.TransferFunction(b=B_PLANT, a=A_PLANT)
        if ts is None:
            self.ctrl = sg.PI(k=K, T=TI)
            chain = [(self.error.y, self.ctrl.u), (self.ctrl.y, self.plant.u)]
        else:
            b, a = tustin_pi(ts)
            self.ctrl = dc.TransferFunction(b=b, a=a, samplePeriod=ts)
            self.zoh = dc.ZeroOrderHold(samplePeriod=ts)
            chain = [(self.error.y, self.ctrl.u), (self.ctrl.y, self.zoh.u),
                     (self.zoh.y, self.plant.u)]
        for a_, b_ in [(self.setpoint.y, self.error.u1), (self.plant.y, self.error.u2)] + chain:
            self.connect(a_, b_)


def sampled_by_hand(ts: float, n: int) -> tuple[np.ndarray, np.ndarray]:
    """The sampled loop at t_k = k·ts, k = 1..n: the plant's exact discretization
    (cont2discrete, zero order hold) and the controller's difference equation
    c[k] = c[k−1] + b0·e[k] + b1·e[k−1]; the hold puts 0 on the plant until the first
    instant (the controller's output starts at 0, the hold samples it at the start)."""
    Ad, Bd, Cd, _, _ = sig.cont2discrete(sig.tf2ss(B_PLANT, A_PLANT), ts, method="zoh")
    (b0, b1), _ = tustin_pi(ts)
    x, c, e_prev, held, ys, cs = np.zeros(2), 0.0, 0.0, 0.0, [], []
    for k in range(1, n + 1):
        x = Ad @ x + Bd[:, 0] * held
        y = (Cd @ x).item()
        e = (1.0 if k * ts >= T_STEP else 0.0) - y
        c, e_prev = c + b0 * e + b1 * e_prev, e
        held = c
        ys.append(y)
        cs.append(c)
    return np.array(ys), np.array(cs)


def main():
    t = np.linspace(0.0, T_END, 2401)
    cont = acausal.compile(Loop("continuous")).simulate(T_END, t=t, rtol=1e-10, atol=1e-12)
    runs = {}
    for ts in PERIODS:
        res = acausal.compile(Loop("sampled", ts)).simulate(T_END, t=t, rtol=1e-10,
                                                            atol=1e-12)
        n = int(np.floor(T_END / ts - 1e-9))
        tk = ts * np.arange(1, n + 1)
        after = np.array([np.flatnonzero(np.abs(res.t - x) <= 1e-9)[-1] for x in tk])
        ys, cs = sampled_by_hand(ts, n)
        err = max(np.max(np.abs(res["plant.y"][after] - ys)),
                  np.max(np.abs(res["ctrl.y"][after] - cs)))
        gap = np.max(np.abs(np.interp(t, res.t, res["plant.y"]) - cont["plant.y"]))
        print(f"Ts = {ts:g} s: {len(tk)} instants, max |sampled loop - exact discretization| "
              f"= {err:.1e}; max |sampled - continuous| = {gap:.3f}")
        assert err < 1e-7
        runs[ts] = res
    gaps = [np.max(np.abs(np.interp(t, runs[ts].t, runs[ts]["plant.y"]) - cont["plant.y"]))
            for ts in PERIODS]
    assert gaps[0] < gaps[1]                 # the faster sampling is closer to continuous

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    top.plot(t, cont["setpoint.y"], "k--", label="setpoint")
    top.plot(t, cont["plant.y"], "k", label="continuous PI")
    bottom.plot(t, cont["ctrl.y"], "k", label="continuous PI")
    for ts, res in runs.items():
        top.plot(res.t, res["plant.y"], label=f"discrete PI, Ts = {ts:g} s")
        bottom.plot(res.t, res["zoh.y"], label=f"held controller output, Ts = {ts:g} s")
    top.set_ylabel("plant.y")
    bottom.set_ylabel("plant input")
    bottom.set_xlabel("time [s]")
    for ax in (top, bottom):
        ax.legend()
        ax.grid(True)
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "discrete_control.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
