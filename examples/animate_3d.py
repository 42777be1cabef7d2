"""Animate 3-D multibody results: MSL's RollingWheelSetDriving (a wheel set driven by two
sine torques, with a small body on a rod ahead of its axle) and the rolling wheel of MSL's
Elementary.RollingWheel, each drawn from its parts' shapes (wheels as discs, the rod as a
cylinder, a Body as a sphere and a cylinder) and saved as

- an interactive view in the browser, ``<name>.html`` (self-contained: open it, drag to
  turn, wheel to zoom, the slider and play button for time), and
- a GIF, ``<name>.gif``,

in $ACAUSAL_OUT (default the current directory). Prints where the wheel set ends and that
its wheels did not slip (the contact points' velocities along the wheels, by hand).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.analysis.animation import Animation
from acausal.models.rolling import (ROLLING_WHEEL_START, WHEEL_SET_START, RollingWheelExample,
                                    RollingWheelSetDriving)


def main():
    out = os.environ.get("ACAUSAL_OUT", ".")
    t = np.linspace(0, 3, 91)
    model = RollingWheelSetDriving()
    res = acausal.compile(model).simulate(3.0, x0=WHEEL_SET_START, t=t)
    # no slip: wheel 1's centre moves along its heading (no lateral velocity)
    phi = res["wheelSet.phi"]
    v = np.column_stack([res[f"wheelSet.body1.v_0[{k}]"] for k in (1, 2)])
    heading = np.column_stack([np.cos(phi), np.sin(phi)])
    print(f"wheel set at t = 3 s: x = {res.final('wheelSet.x'):.4f} m, "
          f"y = {res.final('wheelSet.y'):.4f} m, phi = {res.final('wheelSet.phi'):.4f} rad")
    print(f"lateral velocity of wheel 1 (no slip): "
          f"{np.max(np.abs(heading[:, 0] * v[:, 1] - heading[:, 1] * v[:, 0])):.1e} m/s")
    anim = Animation(model, res)
    anim.save_html(os.path.join(out, "wheel_set.html"), "RollingWheelSetDriving")
    anim.save_gif(os.path.join(out, "wheel_set.gif"), frames=30)

    wheel = RollingWheelExample()
    res = acausal.compile(wheel).simulate(4.0, x0=ROLLING_WHEEL_START,
                                          t=np.linspace(0, 4, 121))
    anim = Animation(wheel, res)
    anim.save_html(os.path.join(out, "rolling_wheel.html"), "RollingWheel")
    anim.save_gif(os.path.join(out, "rolling_wheel.gif"), frames=30)
    print(f"saved wheel_set.html/.gif and rolling_wheel.html/.gif in {out}")


if __name__ == "__main__":
    main()
