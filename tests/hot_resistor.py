"""A part whose temperature leaves the scope of MSL's model (shared by the tests of
assertions in simulate(), sweeps, the Stepper and the native FMU)."""
from __future__ import annotations

import acausal
from acausal.components import electrical as el
from acausal.components import signals as sg
from acausal.components import thermal as th


def hot_part(kind: str, alpha: float = -0.02) -> acausal.Model:
    """A current of 0.5 A through a Resistor or Conductor (R = 1/G = 1 Ohm) and a capacitor,
    its heat port at T_ref + 100 K·t: 1 + alpha·(T − T_ref) = 1 + 100·alpha·t (with the
    default alpha −0.02 1/K: 1 − 2·t, which reaches 0 at 0.5 s)."""
    T_ref = 300.15
    m = acausal.Model("hot")
    m.src, m.c, m.ground = el.ConstantCurrent(I=0.5), el.Capacitor(C=1.0), el.Ground()
    m.part = getattr(el, kind)(alpha=alpha, T_ref=T_ref, useHeatPort=True)
    m.ramp = sg.Ramp(height=100.0, duration=1.0, offset=T_ref)
    m.heat = th.PrescribedTemperature()
    for a, b in [(m.src.n, m.part.p), (m.part.n, m.c.p), (m.c.n, m.ground.p),
                 (m.src.p, m.ground.p), (m.ramp.y, m.heat.T), (m.heat.port, m.part.heatPort)]:
        m.connect(a, b)
    return m


OUTSIDE = r"'part': Temperature outside scope of model! \(assertion failed at t = 0\.5\d* s\)"
