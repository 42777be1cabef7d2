"""MSL's Rotational.Examples.EddyCurrentBrake and Translational.Examples.EddyCurrentBrake: an
eddy current brake slows an inertia (a mass) from 20 rad/s (20 m/s); its losses heat an
adiabatic heat capacitor (C = 1 J/K from 293.15 K) whose temperature shifts the brake's
nominal speed (alpha20 of copper).

    (ramp ─→) eddyCurrentTorque ── inertia          (eddyCurrentForce ── mass)
                   │ heatPort
              heatCapacitor

By default the brake is fully excited from t = 0 (constant excitation 1), as in MSL 4.0.0,
from which the published reference results come; ``ramp=True`` builds the later MSL version,
whose excitation input ramps from 0 to 1 between 0.1 s and 0.2 s.

The experiment: StopTime 1 s, Interval 0.001 s; ``START`` holds the start values (``x0``).
"""
from __future__ import annotations

from ..components import rotational as rot
from ..components import signals as sig
from ..components import thermal as th
from ..components import translational as tr
from ..core import Model

STOP_TIME, INTERVAL = 1.0, 0.001            # s, the MSL experiment
#: Modelica.Electrical.Machines.Thermal.Constants.alpha20Copper [1/K]
ALPHA20_COPPER = 3.920e-3
START_ROTATIONAL = {"inertia.phi": 0.0, "inertia.w": 20.0}
START_TRANSLATIONAL = {"mass.s": 0.0, "mass.v": 20.0}


class RotationalEddyCurrentBrake(Model):
    """MSL's Rotational.Examples.EddyCurrentBrake: tau_nominal = 100 N.m, w_nominal = 10 rad/s,
    TRef = 293.15 K, alpha20 of copper; inertia J = 1 kg.m²; heatCapacitor C = 1 J/K;
    ``ramp``: the excitation input ramped (see the module)."""

    def __init__(self, name="EddyCurrentBrake", ramp=False):
        super().__init__(name)
        self.eddyCurrentTorque = rot.EddyCurrentTorque(
            useExcitationInput=ramp, tau_nominal=100.0, w_nominal=10.0,
            alpha20=ALPHA20_COPPER, TRef=293.15, useHeatPort=True)
        self.inertia = rot.Inertia(J=1.0)
        self.heatCapacitor = th.HeatCapacitor(C=1.0)
        self.connect(self.eddyCurrentTorque.flange, self.inertia.flange_a)
        if ramp:
            self.ramp = sig.Ramp(height=1.0, duration=0.1, offset=0.0, startTime=0.1)
            self.connect(self.ramp.y, self.eddyCurrentTorque.excitation)
        self.connect(self.eddyCurrentTorque.heatPort, self.heatCapacitor.port)


class TranslationalEddyCurrentBrake(Model):
    """MSL's Translational.Examples.EddyCurrentBrake: f_nominal = 100 N, v_nominal = 10 m/s,
    TRef = 293.15 K, alpha20 of copper; mass m = 1 kg; heatCapacitor C = 1 J/K;
    ``ramp``: the excitation input ramped (see the module)."""

    def __init__(self, name="EddyCurrentBrake", ramp=False):
        super().__init__(name)
        self.eddyCurrentForce = tr.EddyCurrentForce(
            useExcitationInput=ramp, f_nominal=100.0, v_nominal=10.0, useHeatPort=True,
            TRef=293.15, alpha20=ALPHA20_COPPER)
        self.mass = tr.Mass(m=1.0)
        self.heatCapacitor = th.HeatCapacitor(C=1.0)
        self.connect(self.eddyCurrentForce.flange, self.mass.flange_a)
        if ramp:
            self.ramp = sig.Ramp(height=1.0, duration=0.1, offset=0.0, startTime=0.1)
            self.connect(self.ramp.y, self.eddyCurrentForce.excitation)
        self.connect(self.eddyCurrentForce.heatPort, self.heatCapacitor.port)
