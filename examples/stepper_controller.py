"""A controller written in Python in the loop of the gantry crane, and an environment for
reinforcement-learning style use, both on ``compiled.stepper``.

The crane (``acausal.models.crane``: cart on a damped rail, load on a rope, input force F)
is stepped at 100 Hz: ``stepper.step({"F": F})`` holds F over 10 ms, integrates the plant
exactly over the step (to the tolerances) and returns the states by name. The controller is
plain Python with branches and a saturation — no CasADi needed: it moves the cart to 2 m
while damping the sway, with the force limited to ±15 N.

``CraneEnv`` wraps the same stepper in the reset/step interface of reinforcement-learning
libraries (observation, reward, done), without depending on any of them: its state can be
set for a randomized start (``stepper.state = {...}``), its parameters changed per episode
without recompiling (``stepper.reset(params=...)``). A heuristic policy runs one episode.

Run ``python examples/stepper_controller.py``: prints a summary and saves
``stepper_controller.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os
import time

import numpy as np

import acausal
from acausal.models.crane import GantryCrane

TARGET, F_MAX, DT = 2.0, 15.0, 0.01          # m, N, s


def controller(y: dict) -> float:
    """Cart to TARGET with sway damping, saturated at ±F_MAX [N]."""
    F = 6.0 * (TARGET - y["rail.s"]) - 8.0 * y["rail.v"] + 25.0 * y["hinge.phi"] \
        + 4.0 * y["hinge.w"]
    return float(np.clip(F, -F_MAX, F_MAX))


class CraneEnv:
    """Move the load to TARGET: observation [s, phi, v, w], action F [N] (clipped),
    reward −(distance² + sway²), done after ``horizon`` [s] or once settled."""

    def __init__(self, compiled, horizon: float = 15.0, seed: int = 0):
        self.stepper = compiled.stepper(DT, outputs=["rail.s", "hinge.phi", "rail.v",
                                                     "hinge.w"])
        self.horizon, self.rng = horizon, np.random.default_rng(seed)

    def reset(self) -> np.ndarray:
        st = self.stepper
        st.reset(params={"load.m": self.rng.uniform(0.5, 2.0)})   # a new load, no recompile
        st.state = {"hinge.phi": self.rng.uniform(-0.1, 0.1)}      # a swinging start
        return np.array(list(st.outputs().values()))

    def step(self, action: float):
        y = self.stepper.step({"F": float(np.clip(action, -F_MAX, F_MAX))})
        obs = np.array(list(y.values()))
        reward = -((obs[0] - TARGET) ** 2 + obs[1] ** 2)
        settled = abs(obs[0] - TARGET) < 1e-3 and abs(obs[2]) < 1e-3 and abs(obs[1]) < 1e-3
        return obs, reward, settled or self.stepper.t >= self.horizon - 1e-9


def main():
    compiled = acausal.compile(GantryCrane())
    stepper = compiled.stepper(DT)
    y, rows = stepper.outputs(), []
    t0 = time.perf_counter()
    while stepper.t < 15.0 - 1e-9:
        F = controller(y)
        y = stepper.step({"F": F})
        rows.append([stepper.t, y["rail.s"], y["hinge.phi"], F])
    wall = time.perf_counter() - t0
    t, s, phi, F = np.array(rows).T
    print(f"{len(rows)} steps of {DT * 1e3:g} ms in {wall * 1e3:.0f} ms "
          f"({wall / len(rows) * 1e6:.0f} µs per step, controller included)")
    print(f"cart at {s[-1]:.4f} m (target {TARGET} m), sway {np.degrees(phi[-1]):.3f} deg, "
          f"largest sway {np.degrees(np.abs(phi).max()):.2f} deg")

    env = CraneEnv(compiled)
    obs, total, done = env.reset(), 0.0, False
    while not done:
        obs, reward, done = env.step(controller(dict(zip(
            ["rail.s", "hinge.phi", "rail.v", "hinge.w"], obs))))
        total += reward
    print(f"episode: load {env.stepper.p[compiled.param_names.index('load.m')]:.2f} kg, "
          f"return {total:.1f}, ended at t = {env.stepper.t:.2f} s")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, sharex=True, figsize=(7, 6))
    ax[0].plot(t, s)
    ax[0].axhline(TARGET, ls="--", c="gray")
    ax[0].set_ylabel("cart s [m]")
    ax[1].plot(t, np.degrees(phi))
    ax[1].set_ylabel("sway [deg]")
    ax[2].step(t, F, where="pre")
    ax[2].set_ylabel("F [N]")
    ax[2].set_xlabel("time [s]")
    for a in ax:
        a.grid(True)
    path = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "stepper_controller.png")
    fig.savefig(path, dpi=110, bbox_inches="tight")
    print(f"saved {path}")


if __name__ == "__main__":
    main()
