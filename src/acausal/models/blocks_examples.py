"""MSL's Blocks.Examples InverseModel, ShowLogicalSources and TotalHarmonicDistortion rebuilt
from acausal.components.signals, .logical and .electrical, with MSL's names."""
from __future__ import annotations

import math

from ..components import electrical as el
from ..components import logical as lg
from ..components import signals as sg
from ..core import Model

_Init = sg.Init


class InverseModel(Model):
    """MSL's Blocks.Examples.InverseModel: the input of ``firstOrder1`` (k = 1, T = 0.3 s,
    steady state) computed so that its output follows ``sine`` (f = 2 Hz, offset 1, from
    0.2 s) filtered by ``criticalDamping`` (n = 1, f = 100 Hz), through
    ``inverseBlockConstraints``; the computed input drives ``firstOrder2`` (identical), and
    ``feedback`` gives firstOrder2.y − sine.y. StopTime 1 s. Compile it with
    ``index_reduction=True``: firstOrder1.y becomes criticalDamping's state; the states are
    criticalDamping.x[1] and firstOrder2.y, the unknown inverseBlockConstraints.y1."""

    def __init__(self, name=None):
        super().__init__(name)
        self.firstOrder1 = sg.FirstOrder(k=1, T=0.3, initType=_Init.SteadyState)
        self.sine = sg.Sine(f=2, offset=1, startTime=0.2)
        self.inverseBlockConstraints = ib = sg.InverseBlockConstraints()
        self.firstOrder2 = sg.FirstOrder(k=1, T=0.3, initType=_Init.SteadyState)
        self.feedback = sg.Feedback()
        self.criticalDamping = sg.CriticalDamping(n=1, f=50 * 2)
        for a, b in [(self.firstOrder1.y, ib.u2), (ib.y2, self.firstOrder1.u),
                     (self.firstOrder2.y, self.feedback.u1),
                     (self.sine.y, self.criticalDamping.u), (self.criticalDamping.y, ib.u1),
                     (self.sine.y, self.feedback.u2), (ib.y1, self.firstOrder2.u)]:
            self.connect(a, b)


class ShowLogicalSources(Model):
    """MSL's Blocks.Examples.ShowLogicalSources: the Boolean sources ``table`` (BooleanTable,
    switching at 2, 4, 6, 8 s), ``const`` (true), ``step`` (at 4 s), ``pulse`` (period
    1.5 s, width 50 %), ``sample`` (SampleTrigger, period 0.5 s) and ``booleanExpression``
    (pulse.y and step.y). StopTime 10 s.

    MSL difference: booleanExpression is an And of pulse.y and step.y (MSL's
    BooleanExpression takes an expression of the model's variables; acausal's, a constant)."""

    def __init__(self, name=None):
        super().__init__(name)
        self.table = lg.BooleanTable(table=[2, 4, 6, 8])
        self.const = lg.BooleanConstant()
        self.step = lg.BooleanStep(startTime=4)
        self.pulse = lg.BooleanPulse(period=1.5)
        self.sample = lg.SampleTrigger(period=0.5)
        self.booleanExpression = lg.And()
        self.connect(self.pulse.y, self.booleanExpression.u1)
        self.connect(self.step.y, self.booleanExpression.u2)


class TotalHarmonicDistortion(Model):
    """MSL's Blocks.Examples.TotalHarmonicDistortion: a voltage of a fundamental wave (RMS V1
    [V], f1 [Hz]) and its third harmonic (RMS V3 [V]), both from 0.02 s (SineVoltages in
    series, measured by ``voltageSensor``), into ``thd1`` (TotalHarmonicDistortion with
    respect to the fundamental: V3/V1 in theory) and ``thdRMS`` (with respect to the total
    RMS: V3/sqrt(V1² + V3²)). StopTime 0.1 s, Interval 1e-4 s, Tolerance 1e-6."""

    def __init__(self, name=None, f1: float = 50.0, V1: float = 100.0, V3: float = 20.0):
        super().__init__(name)
        self.ground = el.Ground()
        self.sineVoltage3 = el.SineVoltage(V=math.sqrt(2) * V3, f=3 * f1, startTime=0.02)
        self.sineVoltage1 = el.SineVoltage(V=math.sqrt(2) * V1, f=f1, startTime=0.02)
        self.voltageSensor = el.VoltageSensor()
        self.thd1 = sg.TotalHarmonicDistortion(f=f1)
        self.thdRMS = sg.TotalHarmonicDistortion(f=f1, useFirstHarmonic=False)
        for a, b in [(self.voltageSensor.p, self.sineVoltage3.p),
                     (self.sineVoltage3.n, self.sineVoltage1.p),
                     (self.sineVoltage1.n, self.ground.p), (self.ground.p, self.voltageSensor.n),
                     (self.thd1.u, self.voltageSensor.v), (self.voltageSensor.v, self.thdRMS.u)]:
            self.connect(a, b)
