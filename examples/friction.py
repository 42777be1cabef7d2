"""Coulomb friction on state events: MSL's drive train with a clutch and a brake
(acausal.models.friction, Rotational.Examples.Friction), and a flywheel braked to rest
checked against its closed form.

The drive train: a sine torque drives inertia3, the clutch (always engaged) slips and sticks
between inertia3 and inertia2; at 0.5 s the torque stops and the brake holds inertia1 behind
the spring. Prints the event log (modes: 1 forward, 0 stuck, -1 backward, 2 free) and saves
``friction.png`` (in $ACAUSAL_OUT, default the current directory): speeds, the clutch's and the
brake's friction torques and modes.
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components import rotational as rot
from acausal.components.signals import Constant
from acausal.models.friction import INTERVAL, START, STOP_TIME, RotationalFriction

J, W0, FN, MU = 2.0, 3.0, 10.0, 0.5       # flywheel [kg.m²], [rad/s]; brake [N], [1]


def braked_flywheel():
    """The brake's torque mu·fn stops the flywheel at t = J·w0/(mu·fn)."""
    m = acausal.Model("flywheel")
    m.fly = rot.Inertia(J=J)
    m.brake = rot.Brake(fn_max=FN, mu_pos=[[0.0, MU]])
    m.on = Constant(k=1.0)
    m.connect(m.fly.flange_b, m.brake.flange_a)
    m.connect(m.on.y, m.brake.f_normalized)
    res = acausal.compile(m).simulate(2.0, x0={"fly.w": W0}, rtol=1e-10, atol=1e-12)
    stop = res.events[-1].time
    print(f"flywheel stops at {stop:.12f} s, closed form {J * W0 / (MU * FN):.12f} s; "
          f"afterwards |w| <= {np.abs(res['fly.w'][res.t > stop]).max():.1e} rad/s")


def main():
    braked_flywheel()
    model = acausal.compile(RotationalFriction())
    res = model.simulate(STOP_TIME, x0=START, t=np.arange(0.0, STOP_TIME + INTERVAL / 2,
                                                          INTERVAL), rtol=1e-8, atol=1e-10)
    for event in res.events:
        print(event)

    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "friction.png")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2, ax3) = plt.subplots(3, 1, sharex=True, figsize=(7, 7))
    for name in ("inertia3.w", "inertia2.w", "inertia1.w"):
        ax1.plot(res.t, res[name], label=name)
    ax1.set_ylabel("speed [rad/s]")
    for name in ("clutch.tau", "brake.tau"):
        ax2.plot(res.t, res[name], label=name)
    ax2.set_ylabel("friction torque [N.m]")
    for name in ("clutch.mode", "brake.mode"):
        ax3.step(res.t, res[name], where="post", label=name)
    ax3.set_ylabel("mode")
    ax3.set_xlabel("time [s]")
    for ax in (ax1, ax2, ax3):
        ax.grid(True)
        ax.legend(loc="upper right")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"saved {out}")


if __name__ == "__main__":
    main()
