"""Ideal electrical elements (after Modelica.Electrical.Analog.Ideal): the ideal switching
elements (parametric characteristics, see the package's docstring), Short, Idle, the
IdealTransformer and the ideal operational amplifiers."""
from __future__ import annotations

from enum import Enum

import casadi as ca

from ...core import (BooleanInput, Component, ConditionalPort, Model, NegativePin, Parameter,
                     Pin, PositivePin)
from ...core.component import who
from ...errors import ParameterError
from ..signals.interfaces import _start, refuse_smooth
from ..signals.nonlinear import LimiterHomotopy, _limited, _limiter_region
from .basic import Capacitor, Resistor
from .interfaces import (OnePort, TwoPort, _ConditionalHeatPort, _LimitedOpAmp, _nullator,
                         _ThreePinOpAmp)


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


class IdealTriac(Model):
    """Ideal triac (MSL Ideal.IdealTriac), made of MSL's parts: two IdealThyristors in
    antiparallel between the anode ``p`` and the cathode ``n`` (``idealThyristor1`` from p
    to n, ``idealThyristor`` from n to p), both fired by the Boolean input ``fire1``, and
    the disturbance elimination (snubber) ``resistor`` Rdis in series with ``capacitor``
    Cdis across them::

        p ── idealThyristor1 ── n,   n ── idealThyristor ── p,   p ── Cdis ── Rdis ── n

    So each half-wave is conducted from the instant fire1 is true while the voltage across
    the thyristor of that direction exceeds Vknee until its current falls below
    Goff·Vknee (IdealThyristor). Constructor keywords (MSL's parameters, set on the parts,
    by whose names they are changed at simulation time): Ron [Ohm] (1e-5), Goff [S]
    (1e-5), Vknee [V] (0.8) of both thyristors, Rdis [Ohm] (100, ``resistor.R``), Cdis [F]
    (0.005, ``capacitor.C``; its voltage a state starting at 0)."""
    p = PositivePin("anode")
    n = NegativePin("cathode")
    fire1 = BooleanInput("gate")

    def __init__(self, name: str | None = None, *, Ron: float = 1e-5, Goff: float = 1e-5,
                 Vknee: float = 0.8, Rdis: float = 100.0, Cdis: float = 0.005):
        super().__init__(name)
        self.idealThyristor = IdealThyristor(Ron=Ron, Goff=Goff, Vknee=Vknee)
        self.idealThyristor1 = IdealThyristor(Ron=Ron, Goff=Goff, Vknee=Vknee)
        self.resistor = Resistor(R=Rdis)
        self.capacitor = Capacitor(C=Cdis)
        for a, b in [(self.idealThyristor.n, self.capacitor.n),
                     (self.capacitor.n, self.idealThyristor1.p),
                     (self.idealThyristor1.n, self.resistor.p),
                     (self.resistor.p, self.idealThyristor.p),
                     (self.resistor.n, self.capacitor.p),
                     (self.idealThyristor1.fire, self.fire1),
                     (self.idealThyristor.fire, self.fire1), (self.n, self.idealThyristor.p),
                     (self.idealThyristor1.p, self.p)]:
            self.connect(a, b)


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


class IdealOpAmp3Pin(_ThreePinOpAmp):
    """Ideal operational amplifier with three pins (MSL Ideal.IdealOpAmp3Pin): the
    IdealOpAmp with its negative output pin left out: in_p.v = in_n.v and no input current
    (a nullator); the output pin's voltage and current are whatever the circuit needs.
    Records vin = in_p.v − in_n.v [V] (0)."""

    def physics(self, e):
        vin, _ = self._input_and_output(e)
        e.residual(vin)
        e.variable("vin", vin, "V", "input voltage")


class IdealOpAmpLimited(_LimitedOpAmp):
    """Ideal operational amplifier with limitation (MSL Ideal.IdealOpAmpLimited): no input
    or supply currents; an auxiliary s [1] (algebraic unknown) with vin = in_p.v − in_n.v =
    (s + 1 if s < −1, s − 1 if s > 1, else 0) [V] and out.v = VMin.v if s < −1, VMax.v if
    s > 1, else (VMax.v − VMin.v)·s/2 + (VMax.v + VMin.v)/2: a nullor (vin = 0) while the
    output lies between the supply pins, the output at a supply pin (vin ≠ 0) otherwise.
    Both laws are continuous in s; their kinks are integrated across. Records vin, s."""

    def structure(self, s):
        s.algebraic("s", 0.0, "1", "auxiliary variable")

    def physics(self, e):
        sa = e.state("s")
        vin, _ = self._input_and_output(e)
        vmax, vmin = self._limits(e)
        e.residual(vin - ca.if_else(sa < -1, sa + 1, ca.if_else(sa > 1, sa - 1, 0.0)))
        e.residual(e.potential(self.out) - ca.if_else(
            sa < -1, vmin, ca.if_else(sa > 1, vmax, (vmax - vmin) * sa / 2 + (vmax + vmin) / 2)))
        e.variable("vin", vin, "V", "input voltage")
        e.variable("s", sa, "1", "auxiliary variable")


class InitOpAmp(str, Enum):
    """Modelica.Electrical.Analog.Types.InitOpAmp: the initial intermediate voltage v_int of
    OpAmpLimited with useFirstOrder: V0·v_in limited to the supply (Linear), the positive
    supply (UpperLimit) or the negative one (LowerLimit)."""
    Linear = "Linear"
    UpperLimit = "UpperLimit"
    LowerLimit = "LowerLimit"


class _SuppliedOpAmp(_ThreePinOpAmp):
    """MSL's OpAmpLimited and IdealizedOpAmpLimited: no input current; the output voltage
    v_out = out.v is the intermediate voltage v_int (``_intermediate``: V0·v_in, or its
    first-order lag) limited to the supply [vns, vps] [V]. The supply is the parameters Vps,
    Vns, or with the option ``useSupply`` the potentials of the pins s_p, s_n, which then
    take the supply current i_s = p_s/(vps − vns) [A] (into s_p, out of s_n): the amplifier
    stores and dissipates nothing, p_in + p_out + p_s = 0 with the input power p_in =
    in_p.v·in_p.i + in_n.v·in_n.i (0), the output power p_out = out.v·out.i and the supply
    power p_s [W] (without the pins it comes from an implicit internal supply). vps > vns
    is asserted. Compiled with ``smooth=True`` the limitation's corners are rounded over
    v_smooth [V] (the Limiter's smooth form, error ≤ v_smooth/2). Records vps, vns, v_in,
    v_int, v_out, i_out, p_in, p_out, p_s, i_s."""
    options = {"useSupply": False}
    V0 = Parameter(15000.0, "1", "no-load amplification")
    Vps = Parameter(15.0, "V", "positive supply voltage")
    Vns = Parameter(-15.0, "V", "negative supply voltage")
    v_smooth = Parameter(1e-3, "V", "smooth form only: width over which the corners at the "
                                    "supply limits are rounded (error <= v_smooth/2)",
                         positive=True)
    s_p = ConditionalPort(PositivePin("optional positive supply pin", required=True),
                          "useSupply")
    s_n = ConditionalPort(NegativePin("optional negative supply pin", required=True),
                          "useSupply")

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        if not self.useSupply and not self.Vps > self.Vns:
            raise ParameterError(f"{who(self)}: the supply voltages are not consistent: Vps (= "
                                 f"{self.Vps:g} V) must exceed Vns (= {self.Vns:g} V)")

    #: whether v_int lags V0·v_in (a state) rather than equals it
    _first_order = False

    def _events(self) -> bool:
        """Whether the limitation generates state events (the mode ``region``)."""
        raise NotImplementedError

    def _intermediate(self, e, v_in, vps, vns):
        """The intermediate voltage v_int [V] before the limitation."""
        return self.V0 * v_in

    def structure(self, s):
        _limiter_region(s, self._events())

    def physics(self, e):
        v_in, i_out = self._input_and_output(e)
        if self.useSupply:
            vps, vns = e.potential(self.s_p), e.potential(self.s_n)
        else:
            vps, vns = self.Vps, self.Vns
        e.assertion(vps > vns, "OpAmp supply voltages are not consistent.")
        v_int = self._intermediate(e, v_in, vps, vns)
        v_out = _limited(e, v_int, vns, vps, self.v_smooth, self._events())
        # with v_int = V0·v_in the output's equation is divided by the gain between the
        # limits, so that its residual is the input voltage's error, not that error
        # amplified beyond round-off; at a limit (out.v = the supply) it is not
        gain = 1 if self._first_order else ca.fmax(1, ca.fabs(self.V0))
        if self._events() and not e.smooth:
            gain = ca.if_else(e.mode("region") == 0, gain, 1)
        e.residual((e.potential(self.out) - v_out) / gain)
        p_out = v_out * i_out
        p_s = -p_out                                         # p_in = 0: no input current
        i_s = p_s / (vps - vns)
        if self.useSupply:
            e.flow(self.s_p, i_s)
            e.flow(self.s_n, -i_s)
        for name, value, unit, text in (
                ("vps", vps, "V", "positive supply voltage"),
                ("vns", vns, "V", "negative supply voltage"),
                ("v_in", v_in, "V", "input voltage difference"),
                ("v_int", v_int, "V", "intermediate voltage"),
                ("v_out", v_out, "V", "output voltage to ground"),
                ("i_out", i_out, "A", "output current into OpAmp"),
                ("p_in", 0.0, "W", "input power"), ("p_out", p_out, "W", "output power"),
                ("p_s", p_s, "W", "supply power"), ("i_s", i_s, "A", "supply current")):
            e.variable(name, value, unit, text)


class OpAmpLimited(_SuppliedOpAmp):
    """Operational amplifier with saturation (MSL Ideal.OpAmpLimited, which MSL adds after
    4.1.0 as the improved IdealizedOpAmpLimited): no input current, the no-load
    amplification V0 [1] (high, not infinite), the output limited to the supply:
    v_out = min(vps, max(vns, v_int)) [V], v_int = V0·v_in, or with the option
    ``useFirstOrder`` the first-order rise Tau·der(v_int) = V0·v_in − v_int (Tau [s]; v_int
    a state, its initial value by ``initOpAmp``: InitOpAmp.Linear v_int = min(vps,
    max(vns, V0·v_in)), UpperLimit vps, LowerLimit vns). Saturation (MSL's satPos: v_int ≥
    vps, satNeg: v_int ≤ vns) is located by state events (the mode ``region``: 1 positive,
    −1 negative saturation, 0 between; recorded as satPos, satNeg). Supply, power balance
    and smooth form: see ``_SuppliedOpAmp``."""
    options = {"useFirstOrder": False, "initOpAmp": InitOpAmp.Linear}
    Tau = Parameter(1e-5, "s", "time constant of firstOrder rise of output voltage",
                    positive=True)

    def _events(self) -> bool:
        return True

    @property
    def _first_order(self) -> bool:
        return self.useFirstOrder

    def structure(self, s):
        super().structure(s)
        if self.useFirstOrder:
            s.state("v_int", 0.0, "V", "intermediate voltage")

    def _intermediate(self, e, v_in, vps, vns):
        if not self.useFirstOrder:
            return super()._intermediate(e, v_in, vps, vns)
        v_int = e.state("v_int")
        e.derivative(v_int, (self.V0 * v_in - v_int) / self.Tau)
        start = {InitOpAmp.Linear: ca.fmin(vps, ca.fmax(vns, self.V0 * v_in)),
                 InitOpAmp.UpperLimit: vps, InitOpAmp.LowerLimit: vns}[self.initOpAmp]
        e.initial(v_int - start, f"v_int = {self.initOpAmp.value} (initOpAmp)")
        return v_int

    def physics(self, e):
        super().physics(e)
        if not e.smooth:
            region = e.mode("region")
            e.variable("satPos", region == 1, "", "positive saturation")
            e.variable("satNeg", region == -1, "", "negative saturation")


class IdealizedOpAmpLimited(_SuppliedOpAmp):
    """Idealized operational amplifier with saturation (MSL Ideal.IdealizedOpAmpLimited): no
    input current, v_out = V0·v_in limited to the supply [vns, vps] [V] (V0 [1] the
    no-load amplification). With ``strict`` (MSL's default: noEvent) the limitation is the
    plain expression, its kinks integrated across; with strict=False state events locate
    them (the mode ``region``, as the Limiter's). ``homotopyType`` is accepted and changes
    nothing (the initialization solves the actual model). Supply, power balance and smooth
    form: see ``_SuppliedOpAmp``."""
    options = {"strict": True, "homotopyType": LimiterHomotopy.NoHomotopy}

    def _events(self) -> bool:
        return not self.strict
