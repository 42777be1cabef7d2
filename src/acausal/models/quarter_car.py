"""A quarter car on a road: body and wheel on springs, the tyre a linear spring between the
road and the wheel; the road height a model input, or a measured table of it.

    body: Mass (m_s) ── suspension: SpringDamper (c_s, d_s) ── wheel: Mass (m_u)
    wheel ← tyreForce: Force (f = tyre.k·(road − wheel.s)) ← tyre: Gain ← deflection:
    Feedback(road, wheelPosition: PositionSensor); road: Input ``road`` or
    roadTable: CombiTimeTable

The tyre's force is built from signal blocks (as MSL's examples wire a force law) so that
the road may be any model input, sampled or varied per run, without its derivative.
Coordinates ``wheel.s``, ``body.s`` [m] (0 at rest on a flat road: the suspension's
unstretched length 0 and no gravity, i.e. displacements from the static equilibrium);
outputs ``a_body`` (the body's acceleration [m/s²], ride comfort) and ``travel``
(suspension deflection body.s − wheel.s [m]).
"""
from __future__ import annotations

from ..components import signals as sg
from ..components.translational import (AccSensor, Force, Mass, PositionSensor,
                                        RelPositionSensor, SpringDamper)
from ..core import Input, Model, Output

BODY, WHEEL = 250.0, 35.0                 # kg
SUSPENSION_C, SUSPENSION_D = 16e3, 1e3    # N/m, N.s/m
TYRE_C = 160e3                            # N/m


class QuarterCar(Model):
    """m_s: body (sprung) mass [kg]; m_u: wheel (unsprung) mass [kg]; c_s, d_s: suspension
    stiffness [N/m] and damping [N.s/m] (``suspension.c``, ``suspension.d``); c_t: tyre
    stiffness [N/m] (``tyre.k``). ``road``: None for an input ``road``, the road height
    under the tyre [m]; or a table of rows [time [s], height [m]] (a ``CombiTimeTable``
    ``roadTable``, linear between rows: a road measured along its length, driven at a
    speed)."""

    def __init__(self, name="quarter_car", m_s=BODY, m_u=WHEEL, c_s=SUSPENSION_C,
                 d_s=SUSPENSION_D, c_t=TYRE_C, road=None):
        super().__init__(name)
        if road is None:
            self.road = Input(unit="m", description="road height under the tyre")
            height = self.road.y
        else:
            self.roadTable = sg.CombiTimeTable(table=road)
            height = self.roadTable.y[1]
        self.wheelPosition = PositionSensor()
        self.tyreDeflection = sg.Feedback()
        self.tyre = sg.Gain(k=c_t)
        self.tyreForce = Force()
        self.wheel = Mass(m=m_u)
        self.suspension = SpringDamper(c=c_s, d=d_s)
        self.body = Mass(m=m_s)
        self.accelerometer = AccSensor()
        self.deflection = RelPositionSensor()
        self.a_body = Output(unit="m/s2", description="body acceleration")
        self.travel = Output(unit="m", description="suspension travel body.s - wheel.s")
        for a, b in [(height, self.tyreDeflection.u1),
                     (self.wheelPosition.s, self.tyreDeflection.u2),
                     (self.tyreDeflection.y, self.tyre.u), (self.tyre.y, self.tyreForce.f),
                     (self.tyreForce.flange, self.wheel.flange_a),
                     (self.wheel.flange_a, self.wheelPosition.flange),
                     (self.wheel.flange_b, self.suspension.flange_a),
                     (self.suspension.flange_b, self.body.flange_a),
                     (self.body.flange_b, self.accelerometer.flange),
                     (self.wheel.flange_b, self.deflection.flange_a),
                     (self.body.flange_a, self.deflection.flange_b),
                     (self.accelerometer.a, self.a_body.u),
                     (self.deflection.s_rel, self.travel.u)]:
            self.connect(a, b)
