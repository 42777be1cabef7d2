"""Interfaces of the analog electrical components (after Modelica.Electrical.Analog.Interfaces):
the two-pin OnePort, the four-pin TwoPort, MSL's ConditionalHeatPort, and the pins the
operational amplifiers share."""
from __future__ import annotations

from ...core import Component, ConditionalPort, HeatPort_a, NegativePin, PositivePin


class OnePort(Component):
    """Two pins p, n with v = p.v − n.v [V] and i = p.i = −n.i [A] (MSL Interfaces.OnePort)."""
    p = PositivePin("positive electrical pin")
    n = NegativePin("negative electrical pin")

    def _v(self, e):
        return e.potential(self.p) - e.potential(self.n)

    def _current(self, e, value=None):
        """The current i from p to n: ``value`` if given (an explicit current), otherwise
        an unknown this component gives an equation for; n.i = −i."""
        i = e.flow_of(self.p) if value is None else value
        if value is not None:
            e.flow(self.p, i)
        e.flow(self.n, -i)
        return i

    def _record(self, e, v=None, i=None):
        if v is not None:
            e.variable("v", v, "V", "voltage drop of the two pins (= p.v - n.v)")
        if i is not None:
            e.variable("i", i, "A", "current flowing from pin p to pin n")


class _ConditionalHeatPort(Component):
    """MSL's ConditionalHeatPort: with ``useHeatPort`` the ``heatPort`` (HeatPort_a) takes
    the loss power LossPower [W] (heatPort.Q_flow = −LossPower) and sets the device
    temperature T_heatPort = heatPort.T; without it T_heatPort = T, the fixed device
    temperature [K] each subclass declares as MSL binds it."""
    options = {"useHeatPort": False}
    heatPort = ConditionalPort(HeatPort_a("conditional heat port", required=True),
                               "useHeatPort")

    def _T_heatPort(self, e):
        return e.potential(self.heatPort) if self.useHeatPort else self.T

    def _losses(self, e, loss, T_heatPort):
        if self.useHeatPort:
            e.flow(self.heatPort, -loss)
        e.variable("LossPower", loss, "W", "loss power leaving component via heatPort")
        e.variable("T_heatPort", T_heatPort, "K", "temperature of heatPort")


class TwoPort(Component):
    """Two pin pairs (MSL Interfaces.TwoPort): v1 = p1.v − n1.v, i1 = p1.i = −n1.i [V, A]
    on the primary side, v2, i2 likewise on the secondary side."""
    p1 = PositivePin("positive pin of the left port")
    n1 = NegativePin("negative pin of the left port")
    p2 = PositivePin("positive pin of the right port")
    n2 = NegativePin("negative pin of the right port")

    def _port(self, e, k, i=None):
        """(v_k, i_k) of port k = 1, 2: i_k is ``i`` if given, else an unknown."""
        p, n = (self.p1, self.n1) if k == 1 else (self.p2, self.n2)
        if i is None:
            i = e.flow_of(p)
        else:
            e.flow(p, i)
        e.flow(n, -i)
        return e.potential(p) - e.potential(n), i

    def _record(self, e, v1, i1, v2, i2):
        for name, value, unit in (("v1", v1, "V"), ("i1", i1, "A"), ("v2", v2, "V"),
                                  ("i2", i2, "A")):
            e.variable(name, value, unit, f"{'voltage drop' if unit == 'V' else 'current'} "
                                          f"of port {name[1]}")


def _nullator(e, p, n):
    """The input port of an operational amplifier: no current into the pins p, n; its
    voltage p.v − n.v [V] (0 for the nullator: the amplifier's equations fix it)."""
    e.flow(p, 0.0)
    e.flow(n, 0.0)
    return e.potential(p) - e.potential(n)


class _ThreePinOpAmp(Component):
    """The pins of MSL's operational amplifiers with one output pin: the input port in_p,
    in_n (no current) and the output pin ``out``, whose current is what the circuit
    draws."""
    in_p = PositivePin("positive pin of the input port")
    in_n = NegativePin("negative pin of the input port")
    out = PositivePin("output pin")

    def _input_and_output(self, e):
        """(vin = in_p.v − in_n.v [V], the current out.i into the output pin [A])."""
        return _nullator(e, self.in_p, self.in_n), e.flow_of(self.out)


class _LimitedOpAmp(_ThreePinOpAmp):
    """The pins of MSL's operational amplifiers limited by the potentials of the pins VMax
    and VMin (which carry no current; the output's power comes from nowhere)."""
    VMax = PositivePin("positive output voltage limitation")
    VMin = NegativePin("negative output voltage limitation")

    def _limits(self, e):
        """(VMax.v, VMin.v) [V]."""
        for pin in (self.VMax, self.VMin):
            e.flow(pin, 0.0)
        return e.potential(self.VMax), e.potential(self.VMin)
