"""A mass positioned by a PID controller through a force actuator (Modelica.Blocks + Translational).

Block diagram, as one would draw it in Modelica:

    setpoint (TimeTable) --> Feedback.u1     Feedback.y --> PID --> Force --> Mass (carriage)
    PositionSensor.s ----->  Feedback.u2                      disturbance Step --> Force
                                                       Damper (rail friction) to the ground

The carriage (m = 2 kg, viscous rail friction d = 4 N.s/m) follows point-to-point moves of the
setpoint; at t = 5 s a constant 3 N load pushes it, and the PID's integral action removes the
resulting offset. The PID is MSL's ``Continuous.PID`` (k, Ti, Td, Nd); its gains are
parameters of the compiled model, so a second run with a softer tuning needs no recompiling.

Run ``python examples/pid_position_control.py``: prints a summary and saves
``pid_position_control.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os
import time

import numpy as np

import acausal
from acausal.components.signals import PID, Feedback, Step, TimeTable
from acausal.components.translational import Damper, Fixed, Force, Mass, PositionSensor


class PositionLoop(acausal.Model):
    """Carriage on a rail with a PID position loop and a step load disturbance."""

    def __init__(self, name=None):
        super().__init__(name)
        self.setpoint = TimeTable(table=[[0.0, 0.0], [0.5, 0.0], [1.5, 0.2], [3.0, 0.2],
                                         [3.5, -0.1], [7.0, -0.1]])   # [s, m]
        self.error = Feedback()
        self.pid = PID(k=400.0, Ti=0.5, Td=0.08, Nd=10.0)
        self.actuator = Force()
        self.load = Step(height=-3.0, startTime=5.0)        # [N] pushes towards −s
        self.push = Force()
        self.carriage = Mass(m=2.0)
        self.friction = Damper(d=4.0)
        self.ground = Fixed()
        self.sensor = PositionSensor()
        for a, b in [(self.setpoint.y, self.error.u1), (self.sensor.s, self.error.u2),
                     (self.error.y, self.pid.u), (self.pid.y, self.actuator.f),
                     (self.actuator.flange, self.carriage.flange_a),
                     (self.load.y, self.push.f), (self.push.flange, self.carriage.flange_a),
                     (self.ground.flange, self.friction.flange_a),
                     (self.friction.flange_b, self.carriage.flange_a),
                     (self.sensor.flange, self.carriage.flange_b)]:
            self.connect(a, b)


def main():
    t0 = time.perf_counter()
    model = acausal.compile(PositionLoop("loop"))
    t1 = time.perf_counter()
    grid = np.linspace(0.0, 7.0, 1401)
    res = model.simulate(7.0, t=grid, max_step=0.01)
    soft = model.simulate(7.0, t=grid, max_step=0.01,
                          params={"pid.k": 100.0, "pid.Ti": 1.0, "pid.Td": 0.15})
    t2 = time.perf_counter()
    print(model)
    print(f"states: {model.x_names}")
    print(f"compiled in {t1 - t0:.3f} s, two 7 s simulations in {t2 - t1:.3f} s")

    for label, r in (("k=400, Ti=0.5, Td=0.08", res), ("k=100, Ti=1.0, Td=0.15", soft)):
        err = r["setpoint.y"] - r["carriage.s"]
        move = (grid >= 0.5) & (grid < 3.0)
        after_load = (grid >= 5.0)
        print(f"PID {label}:")
        print(f"  tracking error during the first move: max {np.max(np.abs(err[move])) * 1e3:6.2f}"
              f" mm, at t = 3 s {abs(err[grid == 3.0][0]) * 1e3:6.3f} mm")
        print(f"  load step at 5 s: peak deviation {np.max(np.abs(err[after_load])) * 1e3:6.2f} mm,"
              f" at 7 s {abs(err[-1]) * 1e3:6.3f} mm (integral action)")
        print(f"  peak actuator force {np.max(np.abs(r['pid.y'])):6.1f} N, final "
              f"{r.final('pid.y'):5.2f} N (balances the 3 N load)")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    ax1.plot(grid, res["setpoint.y"] * 1e3, "k--", label="setpoint")
    ax1.plot(grid, res["carriage.s"] * 1e3, label="carriage (k=400)")
    ax1.plot(grid, soft["carriage.s"] * 1e3, label="carriage (k=100)")
    ax1.set_ylabel("position [mm]")
    ax1.legend()
    ax1.grid(True)
    ax2.plot(grid, res["pid.y"], label="actuator force (k=400)")
    ax2.plot(grid, soft["pid.y"], label="actuator force (k=100)")
    ax2.plot(grid, res["load.y"], "k:", label="load")
    ax2.set_ylabel("force [N]")
    ax2.set_xlabel("time [s]")
    ax2.legend()
    ax2.grid(True)
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "pid_position_control.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
