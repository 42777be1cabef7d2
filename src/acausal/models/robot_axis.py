"""One axis of MSL's r3 robot (Modelica.Mechanics.MultiBody.Examples.Systems.RobotR3):
``OneAxis`` and the parts of its Utilities package it uses, built from acausal components
with MSL's names, parameters and defaults.

    pathPlanning ──(angle_ref, speed_ref)──→ axis ── load
    (KinematicPTP2)                           │
                controller (P-PI cascade) ─→ motor (current-controlled: op-amp circuit,
                                                    EMF, rotor Jmotor)
                                               └─→ gear (bearing friction, elasticity, ratio)

MSL routes the signals through the expandable connectors ControlBus / AxisControlBus. Here
the bus is plain named signal connections: each part has the bus signals it reads as
inputs and the ones it writes as outputs, under the bus's names (``angle_ref``,
``speed_ref``, ``acceleration_ref``, ``motion_ref``, ``angle``, ``speed``,
``acceleration``, ``current_ref``, ``current``, ``motorAngle``, ``motorSpeed``), and the
model that holds them connects the names (PathToAxisControlBus's pass-throughs kept). The
parameters of a part are constructor arguments (MSL's modifiers), e.g.
``AxisType1(ratio=210, kp=5)``.

Initialization is MSL's: the motor in steady state (initial equations der(C.v) = 0,
der(La.i) = 0), the gear's spring at rest (w_rel = 0, a_rel = 0), the axis flange at the
reference's angle, speed and acceleration 0 (InitializeFlange): ``PhysicsBuilder.initial``.
The simulation ends at pathPlanning.path.endTime + swingTime (TerminateSimulation), before
MSL's StopTime of 1.6 s (``STOP_TIME``).
"""
from __future__ import annotations

import math


from ..components import electrical as el
from ..components import logical as lg
from ..components import rotational as rot
from ..components import signals as sig
from ..core import (BooleanInput, BooleanOutput, Model, Parameter, PortVector, RealInput,
                    RealOutput, RotationalFlange, StateSelect)

STOP_TIME = 1.6            # s, the MSL experiment (the run terminates before, at ~1.498 s)


class Motor(Model):
    """Motor with its current controller (MSL RobotR3.Utilities.Motor): the reference
    current ``current_ref`` [A] drives an analog circuit of three ideal op-amps (difference
    amplifier ``diff``, PI current controller ``OpI`` with Ri, C, power stage ``power``)
    that feeds the armature (Ra, La) of ``emf`` (k [N.m/A]) on the rotor ``Jmotor`` (J
    [kg.m²]); the current is measured by ``hall1`` (fed back through ``hall2``). La =
    250/(2·D·w) [H], C = 0.004·D/w [F] from the motor's gain k, time constant w and damping
    D. Outputs motorAngle [rad], motorSpeed [rad/s], current [A]. Starts in steady state:
    initial equations der(C.v) = 0, der(La.i) = 0. (w_max, i_max are MSL's data, unused by
    its equations too.)"""
    current_ref = RealInput("reference current of motor [A]")
    motorAngle = RealOutput("angle of motor flange [rad]")
    motorSpeed = RealOutput("speed of motor flange [rad/s]")
    current = RealOutput("current of motor [A]")
    flange_motor = RotationalFlange("motor flange")

    def __init__(self, name: str | None = None, *, J=0.0013, k=1.1616, w=4590.0, D=0.6,
                 w_max=315.0, i_max=9.0):
        super().__init__(name)
        self.Vs, self.hall2 = el.SignalVoltage(), el.SignalVoltage()
        self.power, self.diff, self.OpI = el.IdealOpAmp(), el.IdealOpAmp(), el.IdealOpAmp()
        self.emf = el.RotationalEMF(k=k)
        self.La = el.Inductor(L=250 / (2 * D * w))
        self.Ra = el.Resistor(R=250.0)
        self.C = el.Capacitor(C=0.004 * D / w)
        for n, R in (("Rd1", 100.0), ("Rd2", 100.0), ("Rd3", 100.0), ("Rd4", 100.0),
                     ("Ri", 10.0), ("Rp1", 200.0), ("Rp2", 50.0)):
            setattr(self, n, el.Resistor(R=R))
        for n in ("g1", "g2", "g3", "g4", "g5"):
            setattr(self, n, el.Ground())
        self.hall1 = el.CurrentSensor()
        self.phi, self.speed = rot.AngleSensor(), rot.SpeedSensor()
        self.Jmotor = rot.Inertia(J=J)
        self.convert1, self.convert2 = sig.Gain(k=1.0), sig.Gain(k=1.0)
        for a, b in [
                ("La.n", "emf.p"), ("Ra.n", "La.p"), ("Rd2.n", "diff.n1"), ("C.n", "OpI.p2"),
                ("OpI.p2", "power.p1"), ("Vs.p", "Rd2.p"), ("diff.n1", "Rd1.p"),
                ("Rd1.n", "diff.p2"), ("diff.p2", "Ri.p"), ("Ri.n", "OpI.n1"),
                ("OpI.n1", "C.p"), ("power.n1", "Rp1.p"), ("power.p2", "Rp1.n"),
                ("Rp1.p", "Rp2.p"), ("power.p2", "Ra.p"), ("Rd3.p", "hall2.p"),
                ("Rd3.n", "diff.p1"), ("Rd3.n", "Rd4.p"), ("Vs.n", "g1.p"), ("g2.p", "hall2.n"),
                ("Rd4.n", "g3.p"), ("g3.p", "OpI.p1"), ("g5.p", "Rp2.n"), ("emf.n", "hall1.p"),
                ("hall1.n", "g4.p"), ("emf.flange", "phi.flange"),
                ("emf.flange", "speed.flange"), ("OpI.n2", "power.n2"), ("OpI.p1", "OpI.n2"),
                ("OpI.p1", "diff.n2"), ("Jmotor.flange_b", "flange_motor"),
                ("phi.phi", "motorAngle"), ("speed.w", "motorSpeed"), ("hall1.i", "current"),
                ("hall1.i", "convert1.u"), ("convert1.y", "hall2.v"),
                ("current_ref", "convert2.u"), ("convert2.y", "Vs.v"),
                ("emf.flange", "Jmotor.flange_a")]:
            self.connect(self._port(a), self._port(b))

    def _port(self, dotted: str):
        part, _, port = dotted.rpartition(".")
        return getattr(getattr(self, part) if part else self, port)

    def physics(self, e):
        e.initial(e.der(e.part(self.C).state("v")), "der(C.v) = 0 (steady state)")
        e.initial(e.der(e.part(self.La).state("i")), "der(La.i) = 0 (steady state)")


def _friction_table(Rv0, Rv1):
    """MSL's bearing friction of the r3 gears: tau = Rv0 + Rv1·|w| [N.m] (rows [w, tau])."""
    return [[0.0, Rv0], [1.0, Rv0 + Rv1]]


class GearType2(Model):
    """Gearbox of r3 joints 4, 5, 6 (MSL RobotR3.Utilities.GearType2): an IdealGear of ratio
    i, then BearingFriction of tau_pos = [0, Rv0; 1, Rv0 + Rv1] (Rv0 [N.m], Rv1
    [N.m.s/rad]) with ``peak``, on the driven side; flange_a the motor side."""
    flange_a = RotationalFlange("flange of left shaft")
    flange_b = RotationalFlange("flange of right shaft")

    def __init__(self, name: str | None = None, *, i=-99.0, Rv0=21.8, Rv1=9.8,
                 peak=26.7 / 21.8):
        super().__init__(name)
        self.gear = rot.IdealGear(ratio=i)
        self.bearingFriction = rot.BearingFriction(tau_pos=_friction_table(Rv0, Rv1),
                                                   peak=peak)
        self.connect(self.gear.flange_b, self.bearingFriction.flange_a)
        self.connect(self.bearingFriction.flange_b, self.flange_b)
        self.connect(self.gear.flange_a, self.flange_a)


class GearType1(Model):
    """Gearbox of r3 joints 1, 2, 3 (MSL RobotR3.Utilities.GearType1): BearingFriction
    (tau_pos = [0, Rv0; 1, Rv0 + Rv1], peak 1: MSL passes no peak to it) on the motor side,
    the gear elasticity SpringDamper (c [N.m/rad], d [N.m.s/rad]), then the IdealGear of
    ratio i. Records a_rel = der(spring.w_rel) [rad/s²]; initial equations spring.w_rel =
    0 and a_rel = 0. ``peak`` is MSL's parameter, unused by its equations too."""
    flange_a = RotationalFlange("flange of left shaft")
    flange_b = RotationalFlange("flange of right shaft")

    def __init__(self, name: str | None = None, *, i=-105.0, c=43.0, d=0.005, Rv0=0.4,
                 Rv1=0.13 / 160, peak=1.0):
        super().__init__(name)
        self.gear = rot.IdealGear(ratio=i)
        self.spring = rot.SpringDamper(c=c, d=d)
        self.bearingFriction = rot.BearingFriction(tau_pos=_friction_table(Rv0, Rv1))
        self.connect(self.spring.flange_b, self.gear.flange_a)
        self.connect(self.bearingFriction.flange_b, self.spring.flange_a)
        self.connect(self.gear.flange_b, self.flange_b)
        self.connect(self.bearingFriction.flange_a, self.flange_a)

    def physics(self, e):
        spring, a, b = e.part(self.spring), self.spring.flange_a, self.spring.flange_b
        a_rel = spring.acc(b) - spring.acc(a)
        e.variable("a_rel", a_rel, "rad/s2", "relative angular acceleration of spring")
        e.initial(spring.vel(b) - spring.vel(a), "spring.w_rel = 0")
        e.initial(a_rel, "a_rel = 0")


class Controller(Model):
    """P-PI cascade controller of one axis (MSL RobotR3.Utilities.Controller): the
    references angle_ref [rad], speed_ref [rad/s] of the gear output, times ``ratio``, are
    the motor's; P (gain kp) on the motor angle error, PI (gain ks, time constant Ts [s])
    on kp·error + speed reference − motorSpeed; output current_ref [A]."""
    angle_ref = RealInput("reference angle of axis flange [rad]")
    speed_ref = RealInput("reference speed of axis flange [rad/s]")
    motorAngle = RealInput("angle of motor flange [rad]")
    motorSpeed = RealInput("speed of motor flange [rad/s]")
    current_ref = RealOutput("reference current of motor [A]")

    def __init__(self, name: str | None = None, *, kp=10.0, ks=1.0, Ts=0.01, ratio=1.0):
        super().__init__(name)
        self.gain1 = sig.Gain(k=ratio)
        self.PI = sig.PI(k=ks, T=Ts)
        self.feedback1 = sig.Feedback()
        self.P = sig.Gain(k=kp)
        self.add3 = sig.Add3(k3=-1.0)
        self.gain2 = sig.Gain(k=ratio)
        for a, b in [(self.gain1.y, self.feedback1.u1), (self.feedback1.y, self.P.u),
                     (self.P.y, self.add3.u2), (self.gain2.y, self.add3.u1),
                     (self.add3.y, self.PI.u), (self.speed_ref, self.gain2.u),
                     (self.angle_ref, self.gain1.u), (self.motorAngle, self.feedback1.u2),
                     (self.motorSpeed, self.add3.u3), (self.PI.y, self.current_ref)]:
            self.connect(a, b)


class AxisType2(Model):
    """Axis of r3 joints 4, 5, 6 (MSL RobotR3.Utilities.AxisType2): controller, motor and
    gear (GearType2) on ``flange``; sensors of the flange's angle, speed and acceleration;
    InitializeFlange starting the flange at angle_ref and speed_ref with acceleration 0.
    Inputs angle_ref [rad], speed_ref [rad/s]; outputs angle, speed, acceleration,
    motorAngle, motorSpeed, current, current_ref (the AxisControlBus signals). Parameters
    (MSL's defaults): kp, ks, Ts [s] of the controller; k, w, D, J [kg.m²] of the motor;
    ratio, Rv0 [N.m], Rv1 [N.m.s/rad], peak of the gear."""
    angle_ref = RealInput("reference angle of axis flange [rad]")
    speed_ref = RealInput("reference speed of axis flange [rad/s]")
    angle = RealOutput("angle of axis flange [rad]")
    speed = RealOutput("speed of axis flange [rad/s]")
    acceleration = RealOutput("acceleration of axis flange [rad/s2]")
    motorAngle = RealOutput("angle of motor flange [rad]")
    motorSpeed = RealOutput("speed of motor flange [rad/s]")
    current = RealOutput("current of motor [A]")
    current_ref = RealOutput("reference current of motor [A]")
    flange = RotationalFlange("axis flange")

    def __init__(self, name: str | None = None, *, kp=10.0, ks=1.0, Ts=0.01, k=1.1616,
                 w=4590.0, D=0.6, J=0.0013, ratio=-105.0, Rv0=0.4, Rv1=0.13 / 160, peak=1.0,
                 **gear):
        super().__init__(name)
        self.gear = self._gear(i=ratio, Rv0=Rv0, Rv1=Rv1, peak=peak, **gear)
        self.motor = Motor(J=J, k=k, w=w, D=D)
        self.controller = Controller(kp=kp, ks=ks, Ts=Ts, ratio=ratio)
        self.angleSensor, self.speedSensor = rot.AngleSensor(), rot.SpeedSensor()
        self.accSensor = rot.AccSensor()
        self.initializeFlange = rot.InitializeFlange(stateSelect=StateSelect.prefer)
        self.const = sig.Constant(k=0.0)
        m, c = self.motor, self.controller
        for a, b in [(self.gear.flange_b, self.flange),
                     (self.gear.flange_b, self.angleSensor.flange),
                     (self.gear.flange_b, self.speedSensor.flange),
                     (m.flange_motor, self.gear.flange_a),
                     (self.gear.flange_b, self.accSensor.flange),
                     (self.angleSensor.phi, self.angle), (self.speedSensor.w, self.speed),
                     (self.accSensor.a, self.acceleration),
                     (self.angle_ref, self.initializeFlange.phi_start),
                     (self.speed_ref, self.initializeFlange.w_start),
                     (self.initializeFlange.flange, self.flange),
                     (self.const.y, self.initializeFlange.a_start),
                     # the AxisControlBus between controller and motor
                     (self.angle_ref, c.angle_ref), (self.speed_ref, c.speed_ref),
                     (m.motorAngle, c.motorAngle), (m.motorSpeed, c.motorSpeed),
                     (c.current_ref, m.current_ref), (m.motorAngle, self.motorAngle),
                     (m.motorSpeed, self.motorSpeed), (m.current, self.current),
                     (c.current_ref, self.current_ref)]:
            self.connect(a, b)

    def _gear(self, **data):
        """MSL's ``replaceable GearType2 gear``."""
        return GearType2(**data)


class AxisType1(AxisType2):
    """Axis of r3 joints 1, 2, 3 (MSL RobotR3.Utilities.AxisType1): AxisType2 with the
    elastic GearType1 (spring c = 43 N.m/rad, damper cd = 0.005 N.m.s/rad by default)."""

    def __init__(self, name: str | None = None, *, c=43.0, cd=0.005, **params):
        super().__init__(name, c=c, d=cd, **params)

    def _gear(self, **data):
        return GearType1(**data)


class PathToAxisControlBus(Model):
    """Puts the path planning of axis ``axisUsed`` (1-based) of ``nAxis`` on one axis's
    signals (MSL RobotR3.Utilities.PathToAxisControlBus): inputs q[i], qd[i], qdd[i],
    moving[i], i = 1..nAxis; RealPassThrough / BooleanPassThrough blocks to the outputs
    angle_ref [rad], speed_ref [rad/s], acceleration_ref [rad/s²], motion_ref."""
    angle_ref = RealOutput("reference angle of axis flange [rad]")
    speed_ref = RealOutput("reference speed of axis flange [rad/s]")
    acceleration_ref = RealOutput("reference acceleration of axis flange [rad/s2]")
    motion_ref = BooleanOutput("= true, if reference motion is not in rest")

    def __init__(self, name: str | None = None, *, nAxis=6, axisUsed=1):
        super().__init__(name)
        for key, cls, text in (("q", RealInput, "reference position"),
                               ("qd", RealInput, "reference speed"),
                               ("qdd", RealInput, "reference acceleration"),
                               ("moving", BooleanInput, "= true, if moving")):
            items = []
            for i in range(1, nAxis + 1):
                setattr(self, f"{key}[{i}]", cls(f"{text} of axis {i}"))
                items.append(self.ports[f"{key}[{i}]"])
            self.__dict__[key] = PortVector(type(self).__name__, key, items)
        self.q_axisUsed, self.qd_axisUsed = sig.RealPassThrough(), sig.RealPassThrough()
        self.qdd_axisUsed = sig.RealPassThrough()
        self.motion_ref_axisUsed = lg.BooleanPassThrough()
        for src, block, out in ((self.q, self.q_axisUsed, self.angle_ref),
                                (self.qd, self.qd_axisUsed, self.speed_ref),
                                (self.qdd, self.qdd_axisUsed, self.acceleration_ref),
                                (self.moving, self.motion_ref_axisUsed, self.motion_ref)):
            self.connect(src[axisUsed], block.u)
            self.connect(block.y, out)


class _SwingOver(lg.partialBooleanSO):
    """y = time >= ptp.endTime + swingTime (``ptp`` a KinematicPTP2), a time event there:
    the condition MSL's PathPlanning1 binds to terminateSimulation.condition."""
    swingTime = Parameter(0.5, "s", "additional time after reference motion is in rest "
                                    "before simulation is stopped", nonnegative=True)

    def __init__(self, name: str | None = None, *, ptp, **params):
        super().__init__(name, **params)
        self.__dict__["ptp"] = ptp

    def physics(self, e):
        end = self.ptp.end_time() + self.swingTime
        e.time_event(end)
        e.output(self.y, e.time >= end)


class PathPlanning1(Model):
    """Fastest motion of one axis within speed and acceleration limits (MSL
    RobotR3.Utilities.PathPlanning1): KinematicPTP2 ``kinematicPTP`` (MSL's ``path``, a
    name every component has here: its dotted name) from angleBegDeg to
    angleEndDeg [deg] with speedMax [rad/s], accMax [rad/s²] from startTime [s];
    PathToAxisControlBus ``pathToAxis1`` gives the outputs angle_ref, speed_ref,
    acceleration_ref, motion_ref; ``terminateSimulation`` ends the run swingTime [s] after
    the motion (its condition computed by ``swingOver``, the expression MSL binds)."""
    angle_ref = RealOutput("reference angle of axis flange [rad]")
    speed_ref = RealOutput("reference speed of axis flange [rad/s]")
    acceleration_ref = RealOutput("reference acceleration of axis flange [rad/s2]")
    motion_ref = BooleanOutput("= true, if reference motion is not in rest")

    def __init__(self, name: str | None = None, *, angleBegDeg=0.0, angleEndDeg=1.0,
                 speedMax=3.0, accMax=2.5, startTime=0.0, swingTime=0.5):
        super().__init__(name)
        self.kinematicPTP = sig.KinematicPTP2(q_begin=[math.radians(angleBegDeg)],
                                      q_end=[math.radians(angleEndDeg)], qd_max=[speedMax],
                                      qdd_max=[accMax], startTime=startTime)
        self.pathToAxis1 = PathToAxisControlBus(nAxis=1, axisUsed=1)
        self.swingOver = _SwingOver(ptp=self.kinematicPTP, swingTime=swingTime)
        self.terminateSimulation = lg.TerminateSimulation(
            terminationText="... End condition reached (reference motion at rest for "
                            "swingTime)")
        p, bus = self.kinematicPTP, self.pathToAxis1
        for a, b in [(p.q[1], bus.q[1]), (p.qd[1], bus.qd[1]), (p.qdd[1], bus.qdd[1]),
                     (p.moving[1], bus.moving[1]), (bus.angle_ref, self.angle_ref),
                     (bus.speed_ref, self.speed_ref),
                     (bus.acceleration_ref, self.acceleration_ref),
                     (bus.motion_ref, self.motion_ref),
                     (self.swingOver.y, self.terminateSimulation.condition)]:
            self.connect(a, b)


class OneAxis(Model):
    """MSL's RobotR3.OneAxis: one axis of the r3 robot (AxisType1: w = 5500, ratio = 210,
    c = 8 N.m/rad, cd = 0.01 N.m.s/rad, Rv0 = 0.5 N.m, Rv1 = 0.1/130 N.m.s/rad, controller
    gains kp, ks, Ts [s]) driving a load inertia J = rg²·mLoad (mLoad [kg], rg [m]) along
    PathPlanning1 from startAngle to endAngle [deg] (refSpeedMax [rad/s], refAccMax
    [rad/s²]); the run ends swingTime [s] after the reference motion (at 1.498 s with the
    defaults; ``STOP_TIME`` 1.6 s is MSL's StopTime)."""

    def __init__(self, name: str | None = "OneAxis", *, mLoad=15.0, rg=1.14, kp=5.0, ks=0.5,
                 Ts=0.05, startAngle=0.0, endAngle=120.0, swingTime=0.5, refSpeedMax=3.0,
                 refAccMax=10.0):
        super().__init__(name)
        self.axis = AxisType1(w=5500.0, ratio=210.0, c=8.0, cd=0.01, Rv0=0.5, Rv1=0.1 / 130,
                              kp=kp, ks=ks, Ts=Ts)
        self.load = rot.Inertia(J=rg ** 2 * mLoad)
        self.pathPlanning = PathPlanning1(swingTime=swingTime, angleBegDeg=startAngle,
                                          angleEndDeg=endAngle, speedMax=refSpeedMax,
                                          accMax=refAccMax)
        self.connect(self.axis.flange, self.load.flange_a)
        # the controlBus: the reference motion to the axis
        self.connect(self.pathPlanning.angle_ref, self.axis.angle_ref)
        self.connect(self.pathPlanning.speed_ref, self.axis.speed_ref)
