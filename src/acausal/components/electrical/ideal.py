"""Ideal electrical elements (after Modelica.Electrical.Analog.Ideal): the ideal switching
elements (parametric characteristics, see the package's docstring), Short, Idle, the
IdealTransformer and the ideal operational amplifiers."""
from __future__ import annotations

import casadi as ca

from ...core import BooleanInput, Component, NegativePin, Parameter, Pin, PositivePin
from ..logical import refuse_smooth
from ..signals.interfaces import _start
from .interfaces import OnePort, TwoPort, _ConditionalHeatPort


class _IdealSwitching(_ConditionalHeatPort, OnePort):
    """MSL's IdealSemiconductor / IdealSwitch: a point s [1] (an algebraic unknown) on a
    two-segment characteristic, v = s·(1 if off else Ron) + Vknee [V], i = s·(Goff if off
    else 1) + Goff·Vknee [A]: a resistance Ron when on, a conductance Goff when off, both
    segments through the knee (Vknee, Goff·Vknee). Records v, i, s, off, LossPower = v·i,
    T_heatPort."""
    Ron = Parameter(1e-5, "Ohm", "forward state-on differential resistance (closed "
                                 "resistance)", nonnegative=True)
    Goff = Parameter(1e-5, "S", "backward state-off conductance (opened conductance)",
                     nonnegative=True)
    #: fixed device temperature if useHeatPort = false [K]: MSL's IdealSwitch has final
    #: T = 293.15 (IdealDiode declares it a parameter)
    T = 293.15
    _Vknee = 0.0

    def structure(self, s):
        s.algebraic("s", 0.0, "1", "auxiliary variable for actual position on the ideal "
                                   "characteristic (s < 0: blocking, s > 0: conducting)")

    def _off(self, e):
        raise NotImplementedError

    def physics(self, e):
        sa, off, v, i = e.state("s"), self._off(e), self._v(e), self._current(e)
        e.residual(v - (sa * ca.if_else(off, 1.0, self.Ron) + self._Vknee))
        e.residual(i - (sa * ca.if_else(off, self.Goff, 1.0) + self.Goff * self._Vknee))
        self._record(e, v, i)
        e.variable("s", sa, "1", "auxiliary variable (s < 0: blocking, s > 0: conducting)")
        e.variable("off", off, "", "switching state (1: off)")
        self._losses(e, v * i, self._T_heatPort(e))


#: how far past the knee [1: A when conducting, V when blocking] the event of an ideal
#: semiconductor is located, so that s < 0 is unambiguous at the event (at s = 0 itself
#: both states hold)
S_NOISE = 1e-10


class _IdealSemiconductor(_IdealSwitching):
    """MSL Interfaces.IdealSemiconductor: the characteristic of ``_IdealSwitching`` through
    the knee (Vknee [V], Goff·Vknee [A]), its Boolean mode off (start true, MSL's) switched
    at events to ``_next_off`` (of the present mode, MSL's pre(off)), and a state event
    where s crosses 0: its indicator ``s`` is located past the knee by ``S_NOISE`` (1e-10:
    a current of 1e-10 A, a voltage of 1e-10 V; the switching instant is late by
    S_NOISE/|ds/dt|, 3e-12 s in the rectifier of the tests), so that s < 0 is unambiguous
    at the event. No smooth form (refused when compiled with smooth=True)."""
    Vknee = Parameter(0.0, "V", "forward threshold voltage", nonnegative=True)
    T = Parameter(293.15, "K", "fixed device temperature if useHeatPort = false",
                  positive=True)

    @property
    def _Vknee(self):
        return self.Vknee

    def structure(self, s):
        refuse_smooth(self, s)
        super().structure(s)
        s.mode("off", 1, values=(0, 1), description="switching state (1: blocking)")

    def _next_off(self, e, off, blocking):
        """The mode off after an event, from the present one and ``blocking`` (s < 0)."""
        raise NotImplementedError

    def _off(self, e):
        off, sa = e.mode("off"), e.state("s")
        e.mode_update(off, self._next_off(e, off, sa < 0))
        e.indicator("s", ca.if_else(off, sa - S_NOISE, sa + S_NOISE), "1",
                    "position on the characteristic past the knee by S_NOISE: the element "
                    "switches where it crosses 0")
        return off


class IdealDiode(_IdealSemiconductor):
    """Ideal diode (MSL Ideal.IdealDiode): the characteristic of ``_IdealSwitching`` with
    off = s < 0, switched at the state event where s crosses 0 (``_IdealSemiconductor``).
    Ron [Ohm] 1e-5, Goff [S] 1e-5, Vknee [V] 0. No smooth form (refused when compiled with
    smooth=True)."""

    def _next_off(self, e, off, blocking):
        return blocking


class IdealThyristor(_IdealSemiconductor):
    """Ideal thyristor (MSL Ideal.IdealThyristor): off = s < 0 or (pre(off) and not fire):
    a blocking thyristor conducts once v > Vknee while the Boolean input ``fire`` is true
    (switched at the event of ``fire``'s rise or of s crossing 0), and keeps conducting
    after ``fire`` falls until its current falls below Goff·Vknee (s < 0). Ron [Ohm] 1e-5,
    Goff [S] 1e-5, Vknee [V] 0; no smooth form."""
    fire = BooleanInput("true => the thyristor may conduct (it turns on if v > Vknee)")

    def _next_off(self, e, off, blocking):
        return ca.logic_or(blocking, ca.logic_and(off, ca.logic_not(e.input(self.fire))))


class IdealGTOThyristor(_IdealSemiconductor):
    """Ideal GTO thyristor or switching transistor (MSL Ideal.IdealGTOThyristor): off = s < 0
    or not fire: conducting while v > Vknee and the Boolean input ``fire`` is true, blocking
    as soon as ``fire`` falls (at its event). Ron [Ohm] 1e-5, Goff [S] 1e-5, Vknee [V] 0;
    no smooth form."""
    fire = BooleanInput("true => conducting if v > Vknee, false => blocking")

    def _next_off(self, e, off, blocking):
        return ca.logic_or(blocking, ca.logic_not(e.input(self.fire)))


class IdealOpeningSwitch(_IdealSwitching):
    """Ideal electrical opener (MSL Ideal.IdealOpeningSwitch): off = control (Boolean
    input ``control``: true opens p—n); Ron [Ohm] 1e-5, Goff [S] 1e-5. The switching
    instants are the events of the block driving ``control``; with smooth=True the law is
    unchanged (smooth between the control's jumps)."""
    control = BooleanInput("true => switch open, false => p--n connected")

    def _off(self, e):
        return e.input(self.control)


class IdealClosingSwitch(_IdealSwitching):
    """Ideal electrical closer (MSL Ideal.IdealClosingSwitch): off = not control (Boolean
    input ``control``: true connects p—n); Ron [Ohm] 1e-5, Goff [S] 1e-5."""
    control = BooleanInput("true => p--n connected, false => switch open")

    def _off(self, e):
        return 1 - e.input(self.control)


class _ControlPin(Component):
    """The control pin of MSL's Controlled* switches: no current (control.i = 0); the
    switch state follows control.v > level [V], a Boolean mode ``above`` switched at the
    state event where control.v − level crosses 0 (indicator ``control``). No smooth form
    (refused when compiled with smooth=True)."""
    level = Parameter(0.5, "V", "switch level")

    def structure(self, s):
        refuse_smooth(self, s)
        super().structure(s)
        s.mode("above", 0, values=(0, 1), description="control.v > level")

    def _above(self, e):
        """The mode control.v > level (1: true)."""
        above, vc = e.mode("above"), e.potential(self.control)
        e.flow(self.control, 0.0)
        e.mode_update(above, vc > self.level)
        e.indicator("control", vc - self.level, "V", "control.v - level: the switch "
                                                      "switches where it crosses 0")
        return above


class ControlledIdealOpeningSwitch(_ControlPin, _IdealSwitching):
    """Controlled ideal electrical opener (MSL Ideal.ControlledIdealOpeningSwitch): off =
    control.v > level [V] (0.5), the pin ``control`` carrying no current; Ron [Ohm] 1e-5,
    Goff [S] 1e-5."""
    control = Pin("control pin: control.v > level switch open, otherwise p--n connected")

    def _off(self, e):
        return self._above(e)


class ControlledIdealClosingSwitch(_ControlPin, _IdealSwitching):
    """Controlled ideal electrical closer (MSL Ideal.ControlledIdealClosingSwitch): off =
    control.v < level [V] (0.5; at control.v = level exactly it is open here, closed in MSL:
    the instant of the crossing), the pin ``control`` carrying no current; Ron [Ohm] 1e-5,
    Goff [S] 1e-5."""
    control = Pin("control pin: control.v > level switch closed, otherwise switch open")

    def _off(self, e):
        return 1 - self._above(e)


class _TwoWaySwitching(_ConditionalHeatPort):
    """MSL's IdealTwoWaySwitch and its controlled twin: the pin p connected to n1 (a
    resistance Ron [Ohm] 1e-5) and not to n2 (a conductance Goff [S] 1e-5) while the
    switch state ``_to_n2`` is false, the other way round while it is true; each path k
    (p–n1, p–n2) a point s_k [1] (an algebraic unknown) on its two-segment characteristic,
    p.v − nk.v = s_k·(Ron if closed else 1), nk.i = −s_k·(1 if closed else Goff),
    p.i = −(n1.i + n2.i). T [K] 293.15 without heat port (MSL's final T); LossPower =
    p.i·p.v + n1.i·n1.v + n2.i·n2.v [W]."""
    Ron = Parameter(1e-5, "Ohm", "closed switch resistance", nonnegative=True)
    Goff = Parameter(1e-5, "S", "opened switch conductance", nonnegative=True)
    T = 293.15
    p = PositivePin("positive pin")
    n1 = NegativePin("negative pin, connected to p while the switch is in its first position")
    n2 = NegativePin("negative pin, connected to p while the switch is in its second position")

    def structure(self, s):
        super().structure(s)
        for k in (1, 2):
            s.algebraic(f"s{k}", 0.0, "1", "auxiliary variable")

    def _to_n2(self, e):
        raise NotImplementedError

    def physics(self, e):
        to_n2 = self._to_n2(e)
        vp, currents, loss = e.potential(self.p), [], 0
        for k, pin, closed in ((1, self.n1, 1 - to_n2), (2, self.n2, to_n2)):
            sk = e.state(f"s{k}")
            e.residual(vp - e.potential(pin) - sk * ca.if_else(closed, self.Ron, 1.0))
            ik = -sk * ca.if_else(closed, 1.0, self.Goff)
            e.flow(pin, ik)
            currents.append(ik)
            loss += ik * e.potential(pin)
        ip = -(currents[0] + currents[1])
        e.flow(self.p, ip)
        self._losses(e, loss + ip * vp, self._T_heatPort(e))


class IdealTwoWaySwitch(_TwoWaySwitching):
    """Ideal two-way switch (MSL Ideal.IdealTwoWaySwitch, MSL 3's IdealCommutingSwitch):
    the Boolean input ``control`` connects p–n2 when true, p–n1 when false (see
    ``_TwoWaySwitching``: Ron [Ohm] 1e-5 closed, Goff [S] 1e-5 open)."""
    control = BooleanInput("true => p--n2 connected, false => p--n1 connected")

    def _to_n2(self, e):
        return e.input(self.control)


class ControlledIdealTwoWaySwitch(_ControlPin, _TwoWaySwitching):
    """Controlled ideal two-way switch (MSL Ideal.ControlledIdealTwoWaySwitch, MSL 3's
    ControlledIdealCommutingSwitch): p–n2 connected while control.v > level [V] (0.5),
    p–n1 otherwise; the pin ``control`` carries no current; Ron [Ohm] 1e-5, Goff [S] 1e-5."""
    control = Pin("control pin: if control.v > level p--n2 connected, otherwise p--n1 "
                  "connected")

    def _to_n2(self, e):
        return self._above(e)


class _IntermediateSwitching(_ConditionalHeatPort):
    """MSL's IdealIntermediateSwitch and its controlled twin: p1–n1 and p2–n2 connected
    while the switch state ``_crossed`` is false, p1–n2 and p2–n1 while it is true; each of
    the four paths a point s_k [1] (an algebraic unknown) on its two-segment
    characteristic, the voltage s_k·(Ron if closed else 1) [V], the currents at the pins
    the sums of the two paths meeting there, s·1 for a closed path and s·Goff for an open
    one [A] (MSL's equations). Ron [Ohm] 1e-5, Goff [S] 1e-5; T [K] 293.15 without heat
    port (MSL's final T); LossPower = Σ pin.i·pin.v [W]."""
    Ron = Parameter(1e-5, "Ohm", "closed switch resistance", nonnegative=True)
    Goff = Parameter(1e-5, "S", "opened switch conductance", nonnegative=True)
    T = 293.15
    p1 = PositivePin("positive pin 1")
    p2 = PositivePin("positive pin 2")
    n1 = NegativePin("negative pin 1")
    n2 = NegativePin("negative pin 2")

    def structure(self, s):
        super().structure(s)
        for k in (1, 2, 3, 4):
            s.algebraic(f"s{k}", 0.0, "1", "auxiliary variable")

    def _crossed(self, e):
        raise NotImplementedError

    def physics(self, e):
        crossed = self._crossed(e)
        # the paths: (k, from, to, closed while crossed)
        paths = ((1, self.p1, self.n1, False), (2, self.p2, self.n2, False),
                 (3, self.p1, self.n2, True), (4, self.p2, self.n1, True))
        current = {}
        for k, a, b, when in paths:
            sk = e.state(f"s{k}")
            closed = crossed if when else 1 - crossed
            e.residual(e.potential(a) - e.potential(b)
                       - sk * ca.if_else(closed, self.Ron, 1.0))
            current[k] = sk * ca.if_else(closed, 1.0, self.Goff)
        flows = ((self.p1, current[1] + current[3]), (self.p2, current[2] + current[4]),
                 (self.n1, -(current[1] + current[4])), (self.n2, -(current[2] + current[3])))
        loss = 0
        for pin, i in flows:
            e.flow(pin, i)
            loss += i * e.potential(pin)
        self._losses(e, loss, self._T_heatPort(e))


class IdealIntermediateSwitch(_IntermediateSwitching):
    """Ideal intermediate switch (MSL Ideal.IdealIntermediateSwitch): the Boolean input
    ``control`` connects p1–n2 and p2–n1 when true, p1–n1 and p2–n2 when false (see
    ``_IntermediateSwitching``: Ron [Ohm] 1e-5, Goff [S] 1e-5)."""
    control = BooleanInput("true => p1--n2, p2--n1 connected, otherwise p1--n1, p2--n2 "
                           "connected")

    def _crossed(self, e):
        return e.input(self.control)


class ControlledIdealIntermediateSwitch(_ControlPin, _IntermediateSwitching):
    """Controlled ideal intermediate switch (MSL Ideal.ControlledIdealIntermediateSwitch):
    p1–n2 and p2–n1 connected while control.v > level [V] (0.5), p1–n1 and p2–n2
    otherwise; the pin ``control`` carries no current; Ron [Ohm] 1e-5, Goff [S] 1e-5."""
    control = Pin("control pin: if control.v > level p1--n2, p2--n1 connected, otherwise "
                  "p1--n1, p2--n2 connected")

    def _crossed(self, e):
        return self._above(e)


#: MSL 3's names of the two-way switches
IdealCommutingSwitch = IdealTwoWaySwitch
ControlledIdealCommutingSwitch = ControlledIdealTwoWaySwitch


class Short(OnePort):
    """Short cut branch (MSL Ideal.Short): v = 0 [V]; its current i [A] is what the circuit
    sends through it."""

    def physics(self, e):
        e.residual(self._v(e))
        self._record(e, i=self._current(e))


class Idle(OnePort):
    """Idle branch (MSL Ideal.Idle): i = 0 [A]; its voltage v [V] is what the circuit
    sets."""

    def physics(self, e):
        self._current(e, 0.0)
        self._record(e, v=self._v(e))


class IdealTransformer(TwoPort):
    """Ideal transformer core (MSL Ideal.IdealTransformer): v1 = n·v2 and the magnetization
    current im1 = i1 + i2/n [A]; without magnetization (option ``considerMagnetization``
    False, MSL's default) im1 = 0, so i1 = −i2/n and the power v1·i1 + v2·i2 = 0 exactly;
    with it, v1 = Lm1·der(im1), im1 a state (start ``im1_start``, 0). n [1] turns ratio
    primary:secondary voltage, Lm1 [H] magnetization inductance w.r.t. the primary side."""
    options = {"considerMagnetization": False}
    n = Parameter(1.0, "1", "turns ratio primary:secondary voltage")
    Lm1 = Parameter(1.0, "H", "magnetization inductance w.r.t. primary side", positive=True)

    def __init__(self, name: str | None = None, *, im1_start=0.0, **params):
        super().__init__(name, **params)
        self.__dict__["im1_start"] = _start(im1_start, f"{type(self).__name__}: im1_start")

    def structure(self, s):
        if self.considerMagnetization:
            s.state("im1", self.im1_start, "A", "magnetization current w.r.t. primary side")

    def physics(self, e):
        v2, i2 = self._port(e, 2)
        im1 = e.state("im1") if self.considerMagnetization else 0.0
        v1, i1 = self._port(e, 1, im1 - i2 / self.n)
        e.residual(v1 - self.n * v2)
        if self.considerMagnetization:
            e.derivative(im1, v1 / self.Lm1)
        self._record(e, v1, i1, v2, i2)
        e.variable("im1", im1, "A", "magnetization current w.r.t. primary side")
        e.variable("psim1", self.Lm1 * im1, "Wb", "magnetic flux w.r.t. primary side")


def _nullator(e, p, n):
    """The input port of an ideal operational amplifier: no current into the pins p, n;
    its voltage p.v − n.v [V] (0 for the nullator: the amplifier's equations fix it)."""
    e.flow(p, 0.0)
    e.flow(n, 0.0)
    return e.potential(p) - e.potential(n)


class IdealOpAmp(TwoPort):
    """Ideal operational amplifier (MSL Ideal.IdealOpAmp), a norator–nullator pair: the
    left port p1, n1 a nullator, v1 = 0 [V] and i1 = 0 [A]; the right port p2, n2 a
    norator, v2 [V] and i2 [A] (i2 = p2.i = −n2.i) whatever the circuit needs. Records
    v1, i1, v2, i2."""

    def physics(self, e):
        v1 = _nullator(e, self.p1, self.n1)
        v2, i2 = self._port(e, 2)
        e.residual(v1)
        self._record(e, v1, 0.0, v2, i2)


class IdealOpAmpLimited(Component):
    """Ideal operational amplifier with limitation (MSL Ideal.IdealOpAmpLimited): no input
    or supply currents; an auxiliary s [1] (algebraic unknown) with vin = in_p.v − in_n.v =
    (s + 1 if s < −1, s − 1 if s > 1, else 0) [V] and out.v = VMin.v if s < −1, VMax.v if
    s > 1, else (VMax.v − VMin.v)·s/2 + (VMax.v + VMin.v)/2: a nullor (vin = 0) while the
    output lies between the supply pins, the output at a supply pin (vin ≠ 0) otherwise.
    Both laws are continuous in s; their kinks are integrated across. Records vin, s."""
    in_p = PositivePin("positive pin of the input port")
    in_n = NegativePin("negative pin of the input port")
    out = PositivePin("output pin")
    VMax = PositivePin("positive output voltage limitation")
    VMin = NegativePin("negative output voltage limitation")

    def structure(self, s):
        s.algebraic("s", 0.0, "1", "auxiliary variable")

    def physics(self, e):
        sa = e.state("s")
        vin = _nullator(e, self.in_p, self.in_n)
        for pin in (self.VMax, self.VMin):
            e.flow(pin, 0.0)
        e.flow_of(self.out)
        vmax, vmin = e.potential(self.VMax), e.potential(self.VMin)
        e.residual(vin - ca.if_else(sa < -1, sa + 1, ca.if_else(sa > 1, sa - 1, 0.0)))
        e.residual(e.potential(self.out) - ca.if_else(
            sa < -1, vmin, ca.if_else(sa > 1, vmax, (vmax - vmin) * sa / 2 + (vmax + vmin) / 2)))
        e.variable("vin", vin, "V", "input voltage")
        e.variable("s", sa, "1", "auxiliary variable")
