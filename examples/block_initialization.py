"""MSL's ``initType`` of the continuous blocks: a control loop started at its operating point.

Block diagram:

    setpoint (Step) --> Feedback.u1    Feedback.y --> PI --> plant (FirstOrder) --> y
    plant.y ----------> Feedback.u2

The plant kp/(Tp·s + 1) runs under PI control at the set point r0; the set point steps to
r1 at t = 1 s. With ``initType="SteadyState"`` on the PI and the plant, der(PI.x) = 0 and
der(plant.y) = 0 at the start put the loop at its operating point (e = 0, plant.y = r0,
PI.x = r0/(k·kp), solved by hand below), so nothing moves until the step. With MSL's
defaults (NoInit for both) the states start at their start values (0): the loop first
settles from there. A SecondOrder filter on the output with ``initType="InitialOutput"``
(y = y_start, der(y) = yd_start) starts at the plant's steady output.

Run ``python examples/block_initialization.py``: prints both starts and saves
``block_initialization.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components.signals import PI, Feedback, FirstOrder, SecondOrder, Step

KP, TP, K, TI = 2.0, 0.5, 1.2, 0.4          # plant gain, time constant; PI gain, time constant
R0, R1, T_STEP, T_END = 0.8, 1.2, 1.0, 4.0


class Loop(acausal.Model):
    """PI control of a first-order plant, a second-order filter on its output."""

    def __init__(self, name=None, init: str = "NoInit"):
        super().__init__(name)
        self.setpoint = Step(height=R1 - R0, offset=R0, startTime=T_STEP)
        self.error = Feedback()
        self.pi = PI(k=K, T=TI, initType=init)
        self.plant = FirstOrder(k=KP, T=TP, initType=init)
        self.filter = SecondOrder(w=8.0, D=0.7, y_start=R0 if init == "SteadyState" else 0.0,
                                  initType="InitialOutput")
        for a, b in [(self.setpoint.y, self.error.u1), (self.plant.y, self.error.u2),
                     (self.error.y, self.pi.u), (self.pi.y, self.plant.u),
                     (self.plant.y, self.filter.u)]:
            self.connect(a, b)


def main():
    t = np.linspace(0.0, T_END, 401)
    runs = {init: acausal.compile(Loop("loop", init)).simulate(T_END, t=t, rtol=1e-10,
                                                               atol=1e-12)
            for init in ("SteadyState", "NoInit")}
    steady = runs["SteadyState"]
    before = t < T_STEP
    print(f"operating point by hand: plant.y = {R0}, PI.x = {R0 / (K * KP):.6f}, "
          f"PI.y = {R0 / KP:.6f}")
    print(f"SteadyState start:  plant.y = {steady['plant.y'][0]:.6f}, "
          f"PI.x = {steady['pi.x'][0]:.6f}, PI.y = {steady['pi.y'][0]:.6f}; largest change "
          f"before the step {np.ptp(steady['plant.y'][before]):.1e}")
    assert abs(steady["pi.x"][0] - R0 / (K * KP)) < 1e-9
    assert np.ptp(steady["plant.y"][before]) < 1e-9
    print(f"NoInit start:       plant.y = {runs['NoInit']['plant.y'][0]:.6f} (its start "
          f"value), y({T_STEP:g} s) = {runs['NoInit']['plant.y'][before][-1]:.4f}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(t, steady["setpoint.y"], "k--", label="setpoint")
    for init, res in runs.items():
        ax.plot(t, res["plant.y"], label=f"plant.y ({init})")
        ax.plot(t, res["filter.y"], ":", label=f"filter.y (InitialOutput, {init} loop)")
    ax.set_xlabel("time [s]")
    ax.legend()
    ax.grid(True)
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "block_initialization.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
