"""A ball dropped from 1 m onto a floor with restitution e = 0.8 (acausal.models.bouncing_ball):
state events located in time, the ball's velocity reinitialized at each impact.

Prints the event log and each impact time against its closed form
t_1 = √(2h/g), t_(k+1) = t_k + 2·e^k·v_1/g, and saves ``bouncing_ball.png`` (in $ACAUSAL_OUT,
default the current directory): height and velocity, with both limits at every impact.
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.models.bouncing_ball import G, BouncingBall

H0, E = 1.0, 0.8


def main():
    model = acausal.compile(BouncingBall(e=E))
    res = model.simulate(3.0, x0={"ball.s": H0, "ball.v": 0.0}, rtol=1e-10, atol=1e-12)
    for event in res.events:
        print(event)
    v1 = np.sqrt(2 * G * H0)
    t_ref = np.sqrt(2 * H0 / G)
    impacts = [ev.time for ev in res.events if ev.direction < 0]
    for k, t in enumerate(impacts):
        print(f"impact {k + 1}: t = {t:.12f} s, closed form {t_ref:.12f} s "
              f"(error {t - t_ref:.1e} s)")
        t_ref += 2 * E ** (k + 1) * v1 / G

    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "bouncing_ball.png")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
    ax1.plot(res.t, res["ball.s"])
    ax1.set_ylabel("height ball.s [m]")
    ax2.plot(res.t, res["ball.v"])
    ax2.set_ylabel("velocity ball.v [m/s]")
    ax2.set_xlabel("time [s]")
    for ax in (ax1, ax2):
        ax.grid(True)
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"saved {out}")


if __name__ == "__main__":
    main()
