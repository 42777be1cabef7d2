"""A quarter car driving over a measured road profile given as a 300-row table.

The road height under the tyre, z_r [m], is sampled every 0.2 m over 60 m of road (a table
of [time, height] at 10 m/s) and prescribed to the tyre's lower end; the tyre is a spring,
the suspension a spring-damper between wheel and body:

    body (m_s = 250 kg) | SpringDamper (c = 16 kN/m, d = 1 kN.s/m) | wheel (m_u = 35 kg)
    | tyre Spring (c = 160 kN/m) | Position(exact) <- road table

The same drive is simulated three ways, timed in the same run:
  1) CombiTimeTable (LinearSegments, the default timeEvents=AtDiscontinuities): the table is a
     CasADi interpolant, the integrator never restarts;
  2) the same table with timeEvents=Always (MSL's default, and what TimeTable did before):
     a restart at each of the 298 inner rows;
  3) the road as a formula (two Sine blocks): no table at all.
Then a road twice as rough, with the table's values a parameter (``table_parameter=True``):
changed by ``params={"road.table": ...}`` without recompiling, against a model compiled with
the new table.

Run ``python examples/road_profile.py``: prints the event counts, times and the body's
peak acceleration, and saves ``road_profile.png`` (in $ACAUSAL_OUT, default the current
directory).
"""
from __future__ import annotations

import os
import time

import numpy as np

import acausal
from acausal.components import signals as sg
from acausal.components.translational import Mass, Position, Spring, SpringDamper

SPEED, LENGTH, ROWS = 10.0, 60.0, 300        # m/s, m, table rows
A1, K1, A2, K2, PHASE2 = 0.02, 0.9, 0.006, 4.1, 0.4     # road: heights [m], wavenumbers [1/m]


def road(x):
    """Road height [m] at distance x [m]."""
    return A1 * np.sin(K1 * x) + A2 * np.sin(K2 * x + PHASE2)


class QuarterCar(acausal.Model):
    """Body and wheel on springs, the tyre's lower end following ``source``'s output
    ``height`` (a port of source) [m]."""

    def __init__(self, source, height, name=None):
        super().__init__(name)
        self.road = source
        self.lift = Position(exact=True)
        self.tyre = Spring(c=160e3)
        self.wheel = Mass(m=35.0)
        self.suspension = SpringDamper(c=16e3, d=1e3)
        self.body = Mass(m=250.0)
        self.connect(height, self.lift.s_ref)
        for a, b in [(self.lift.flange, self.tyre.flange_a),
                     (self.tyre.flange_b, self.wheel.flange_a),
                     (self.wheel.flange_b, self.suspension.flange_a),
                     (self.suspension.flange_b, self.body.flange_a)]:
            self.connect(a, b)


class Formula(acausal.Model):
    """The road as a formula of time: two Sine blocks added."""

    def __init__(self, name=None):
        super().__init__(name)
        self.s1 = sg.Sine(amplitude=A1, f=K1 * SPEED / (2 * np.pi))
        self.s2 = sg.Sine(amplitude=A2, f=K2 * SPEED / (2 * np.pi), phase=PHASE2)
        self.add = sg.Add()
        self.connect(self.s1.y, self.add.u1)
        self.connect(self.s2.y, self.add.u2)


def main():
    x = np.linspace(0.0, LENGTH, ROWS)
    table = np.column_stack([x / SPEED, road(x)])
    t_end = LENGTH / SPEED
    t = np.linspace(0.0, t_end, 601)
    smooth = sg.CombiTimeTable(table=table)
    every_row = sg.CombiTimeTable(table=table, timeEvents="Always")
    formula = Formula()
    cases = {"table, events at jumps": QuarterCar(smooth, smooth.y[1]),
             "table, timeEvents=Always": QuarterCar(every_row, every_row.y[1]),
             "formula (two Sines)": QuarterCar(formula, formula.add.y)}
    results = {}
    print(f"quarter car over {LENGTH:.0f} m of road at {SPEED:.0f} m/s ({ROWS}-row table)")
    for label, model in cases.items():
        compiled = acausal.compile(model)
        events = len(compiled.event_times(compiled.param_vector(), 0.0, t_end))
        start = time.perf_counter()
        res = compiled.simulate(t_end, t=t, rtol=1e-8, atol=1e-10)
        elapsed = time.perf_counter() - start
        results[label] = res
        print(f"  {label:26s} {events:4d} time events  {elapsed:7.3f} s   "
              f"peak body acceleration {np.max(np.abs(res['body.a'])):.3f} m/s²")
    diff = np.max(np.abs(results["table, events at jumps"]["body.s"]
                         - results["table, timeEvents=Always"]["body.s"]))
    print(f"  body position, table without vs with per-row events: max difference "
          f"{diff:.1e} m")
    tunable = sg.CombiTimeTable(table=table, table_parameter=True)
    rough = acausal.compile(QuarterCar(tunable, tunable.y[1])).simulate(
        t_end, t=t, params={"road.table": 2 * table[:, 1:]}, rtol=1e-8, atol=1e-10)
    twice = sg.CombiTimeTable(table=np.column_stack([table[:, 0], 2 * table[:, 1]]))
    again = acausal.compile(QuarterCar(twice, twice.y[1])).simulate(t_end, t=t, rtol=1e-8,
                                                                    atol=1e-10)
    print(f"  road twice as rough by params (no recompiling): peak body acceleration "
          f"{np.max(np.abs(rough['body.a'])):.3f} m/s², vs compiled with it: max difference "
          f"{np.max(np.abs(rough['body.s'] - again['body.s'])):.1e} m")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 1, figsize=(8, 5), sharex=True)
    ax[0].plot(t * SPEED, road(t * SPEED) * 1e3, "k", lw=0.8, label="road")
    for label, res in results.items():
        ax[0].plot(t * SPEED, res["body.s"] * 1e3, lw=0.8, label=f"body: {label}")
        ax[1].plot(t * SPEED, res["body.a"], lw=0.8, label=label)
    ax[0].set_ylabel("height [mm]")
    ax[1].set_ylabel("body acceleration [m/s²]")
    ax[1].set_xlabel("distance [m]")
    ax[0].legend(fontsize=7)
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "road_profile.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"saved {out}")


if __name__ == "__main__":
    main()
