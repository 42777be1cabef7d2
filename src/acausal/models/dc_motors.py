"""The DC motor of ``acausal.components.rotational.DCMotor`` composed of its parts, as one
draws it in Modelica: armature circuit (SignalVoltage, Resistor, Inductor), air gap
(RotationalEMF) and rotor (Inertia).

    v ─> signalVoltage ── resistor ── inductor ── emf ──┐      emf.flange ── inertia ── flange
              └─────────────── ground ─────────────────┘      (emf.support ── support)
                   (resistor.heatPort ── heatPort)
"""
from __future__ import annotations

from ..components import electrical as el
from ..components import rotational as rot
from ..core import ConditionalPort, HeatPort_a, Model, RealInput, RotationalFlange

_COMPACT = rot.DCMotor


class DCMotorCircuit(Model):
    """Permanent-magnet DC motor from Modelica parts, equal to the compact
    ``rotational.DCMotor`` (same ports ``v`` [V] (RealInput), ``flange``, ``support`` with
    ``useSupport``; same defaults, MSL's DC_PermanentMagnet data):

        signalVoltage.v = v;  resistor: R [Ohm];  inductor: L [H], state ``inductor.i``;
        emf: k [N.m/A] = [V.s/rad], k·w_rel = emf.v, torque −k·i on its flange;
        inertia: J [kg.m2], states ``inertia.phi``, ``inertia.w`` (absolute).

    Constructor keywords R, L, k, J (defaults the compact motor's) set the parts' parameters
    ``resistor.R``, ``inductor.L``, ``emf.k``, ``inertia.J``, by which they are changed at
    simulation time. The compact DCMotor's records map to ``emf.tauElectrical`` (tau_el),
    ``emf.v`` (vi) and ``signalVoltage.i`` (−i: pin = −v·signalVoltage.i). With
    ``useHeatPort`` the armature's losses leave through ``heatPort`` (the resistor's, at
    whose temperature R_actual = R·(1 + alpha·(T − T_ref)), keywords alpha [1/K] (0) and
    T_ref [K] (300.15)); the compact motor has no heat port."""
    options = {"useSupport": False, "useHeatPort": False}
    v = RealInput("armature voltage [V]")
    flange = RotationalFlange("flange of shaft")
    support = ConditionalPort(RotationalFlange("support/housing of component", required=True),
                              "useSupport")
    heatPort = ConditionalPort(HeatPort_a("heat port of the armature resistance",
                                          required=True), "useHeatPort")

    def __init__(self, name: str | None = None, *, R: float = _COMPACT.R.default,
                 L: float = _COMPACT.L.default, k: float = _COMPACT.k.default,
                 J: float = _COMPACT.J.default, alpha: float = 0.0, T_ref: float = 300.15,
                 useSupport: bool = False, useHeatPort: bool = False):
        super().__init__(name, useSupport=useSupport, useHeatPort=useHeatPort)
        self.signalVoltage = el.SignalVoltage()
        self.resistor = el.Resistor(R=R, alpha=alpha, T_ref=T_ref, useHeatPort=useHeatPort)
        self.inductor = el.Inductor(L=L)
        self.emf = el.RotationalEMF(k=k, useSupport=useSupport)
        self.inertia = rot.Inertia(J=J)
        self.ground = el.Ground()
        for a, b in [(self.v, self.signalVoltage.v),
                     (self.signalVoltage.p, self.resistor.p), (self.resistor.n, self.inductor.p),
                     (self.inductor.n, self.emf.p), (self.emf.n, self.signalVoltage.n),
                     (self.signalVoltage.n, self.ground.p),
                     (self.emf.flange, self.inertia.flange_a),
                     (self.inertia.flange_b, self.flange)]:
            self.connect(a, b)
        if useSupport:
            self.connect(self.emf.support, self.support)
        if useHeatPort:
            self.connect(self.resistor.heatPort, self.heatPort)
