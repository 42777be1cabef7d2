"""A run that ends itself: an inertia (2 kg.m²) under 3 N.m from rest, terminated when its
speed exceeds 4.5 rad/s, at t = 4.5·2/3 = 3 s (shared by the tests of TerminateSimulation
in simulate() and in the native FMU)."""
from __future__ import annotations

import acausal
from acausal.components import logical as lg
from acausal.components import rotational as rot
from acausal.components import signals as sig
from wiring import model


def fast_enough() -> acausal.Model:
    return model("fast_enough", lambda m: [(m.torque.flange, m.inertia.flange_a),
                                           (m.tau.y, m.torque.tau),
                                           (m.speed.flange, m.inertia.flange_b),
                                           (m.speed.w, m.fast.u), (m.fast.y, m.stop.condition)],
                 torque=rot.Torque(), inertia=rot.Inertia(J=2.0), tau=sig.Constant(k=3.0),
                 speed=rot.SpeedSensor(), fast=lg.GreaterThreshold(threshold=4.5),
                 stop=lg.TerminateSimulation(terminationText="fast enough"))
