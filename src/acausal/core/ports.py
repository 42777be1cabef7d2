"""Ports (connectors): what components are connected by.

Mechanical ports (flanges, frames) carry a pose; the compiler gives their connection sets
coordinates on a spanning tree. Network ports (``Domain.network``: electrical pins, heat
ports) carry one potential and one flow (Modelica's across and through variables, e.g.
v [V] and i [A]): a connection set has one potential, and its flows sum to zero
(Kirchhoff's current law); the compiler makes the potentials and the flows algebraic
variables of the DAE (``acausal.compiler.networks``).

A physical port carries potential variables (equal at a connection) and flow variables (summed
to zero at a connection; a flow is positive into the component, as in Modelica). A signal port
carries one causal value: a Real signal, or a Boolean one (``BooleanInput`` /
``BooleanOutput``, Modelica's Boolean connectors), carried as 0 / 1 (false / true) but a kind of
its own: a Boolean port connects to Boolean ports only, so a logical value never drives a Real
input by accident (Modelica.Blocks.Math.BooleanToReal / RealToBoolean convert between them).
"""
from __future__ import annotations

import operator
from dataclasses import dataclass


@dataclass(frozen=True)
class Domain:
    """A kind of physical port: names and units of its potentials and flows."""
    name: str
    potentials: tuple[str, ...]
    flows: tuple[str, ...]
    potential_units: tuple[str, ...]
    flow_units: tuple[str, ...]
    velocity_units: tuple[str, ...]
    #: a potential/flow network (electrical, thermal), not a mechanical pose
    network: bool = False
    #: start value of a network node's potential where nothing fixes it (Modelica's type
    #: start: SI.Temperature's 288.15 K, 0 V)
    potential_start: float = 0.0
    #: names under which the components of a port's velocity are recorded ("" not), for
    #: domains whose velocity is no potential's rate (the 3-D frame's R.w)
    velocity_names: tuple[str, ...] = ()

    @property
    def dim(self) -> int:
        """Number of potentials (the size of a node's position)."""
        return len(self.potentials)

    @property
    def dof(self) -> int:
        """Number of flows, which is the number of velocities (degrees of freedom) of a
        node. It equals ``dim`` except for the 3-D frame, whose position is r_0 and the
        nine entries of R.T, and whose velocity is the 6-vector (v, w) conjugate to (f, t)."""
        return len(self.flows)


TRANSLATIONAL = Domain("translational", ("s",), ("f",), ("m",), ("N",), ("m/s",))
ROTATIONAL = Domain("rotational", ("phi",), ("tau",), ("rad",), ("N.m",), ("rad/s",))
PLANAR = Domain("planar", ("x", "y", "phi"), ("fx", "fy", "t"), ("m", "m", "rad"),
                ("N", "N", "N.m"), ("m/s", "m/s", "rad/s"))
#: the 3-D frame (Modelica.Mechanics.MultiBody.Interfaces.Frame): r_0 [m] resolved in the
#: world, the orientation R.T (transformation matrix from the world to the frame, row by
#: row); cut force f [N] and torque t [N.m] resolved in the frame. Its velocity (the
#: compiler's node velocity) is (v, w) [m/s, rad/s] resolved in the frame: v = R.T·der(r_0),
#: w the angular velocity (MSL's R.w, recorded), so that f·v + t·w is the power into the
#: frame.
MULTIBODY = Domain(
    "multibody",
    ("r_0[1]", "r_0[2]", "r_0[3]") + tuple(f"R.T[{i},{j}]" for i in (1, 2, 3) for j in (1, 2, 3)),
    ("f[1]", "f[2]", "f[3]", "t[1]", "t[2]", "t[3]"),
    ("m",) * 3 + ("1",) * 9, ("N",) * 3 + ("N.m",) * 3, ("m/s",) * 3 + ("rad/s",) * 3,
    velocity_names=("", "", "", "R.w[1]", "R.w[2]", "R.w[3]"))
ELECTRICAL = Domain("electrical", ("v",), ("i",), ("V",), ("A",), ("V/s",), network=True)
THERMAL = Domain("thermal", ("T",), ("Q_flow",), ("K",), ("W",), ("K/s",), network=True,
                 potential_start=288.15)


class Port:
    """Base of all ports. Named by the attribute of the component it is assigned to."""
    kind = "port"
    #: Whether an unconnected port is an error (signal inputs, sensor flanges).
    required = False

    def __init__(self, description: str = "", *, required: bool | None = None):
        self.description = description
        self.owner = None
        self.name = ""
        if required is not None:
            self.required = required

    @property
    def path(self) -> str:
        """Dotted name, e.g. ``crane.cart.flange_a``."""
        owner = self.owner.path if self.owner is not None else ""
        return f"{owner}.{self.name}" if owner else self.name

    def __repr__(self):
        return f"<{type(self).__name__} {self.path}>"


class PhysicalPort(Port):
    """A port with potentials and flows of a Domain."""
    domain: Domain

    @property
    def kind(self) -> str:
        return self.domain.name


class TranslationalFlange(PhysicalPort):
    """1-D translational flange: position s [m], cut force f [N] (positive into the component)."""
    domain = TRANSLATIONAL


class RotationalFlange(PhysicalPort):
    """1-D rotational flange: angle phi [rad], cut torque tau [N.m] (positive into the component)."""
    domain = ROTATIONAL


class Frame(PhysicalPort):
    """Planar frame (PlanarMechanics): x, y [m], phi [rad]; cut force fx, fy [N] and torque
    t [N.m] about the frame's origin, resolved in the world frame, positive into the
    component (t counter-clockwise, like phi)."""
    domain = PLANAR


class MultiBodyFrame(PhysicalPort):
    """3-D frame (Modelica.Mechanics.MultiBody.Interfaces.Frame): position r_0[3] [m] of its
    origin resolved in the world frame, orientation R (R.T[3,3]: transformation matrix from
    the world frame to this frame, v_frame = R.T·v_world; R.w [rad/s] its angular velocity
    resolved in the frame); cut force f[3] [N] and cut torque t[3] [N.m] about its origin,
    resolved in this frame, positive into the component."""
    domain = MULTIBODY


class Pin(PhysicalPort):
    """Electrical pin (Modelica.Electrical.Analog.Interfaces.Pin): potential v [V], current
    i [A] flowing into the pin (into the component)."""
    domain = ELECTRICAL


class PositivePin(Pin):
    """Positive pin of an electrical component (same connector as Pin)."""


class NegativePin(Pin):
    """Negative pin of an electrical component (same connector as Pin)."""


class HeatPort(PhysicalPort):
    """Thermal port (Modelica.Thermal.HeatTransfer.Interfaces.HeatPort): temperature T [K],
    heat flow rate Q_flow [W] into the component."""
    domain = THERMAL


class HeatPort_a(HeatPort):
    """Thermal port, drawn filled (same connector as HeatPort)."""


class HeatPort_b(HeatPort):
    """Thermal port, drawn empty (same connector as HeatPort)."""


class RealInput(Port):
    """A causal real input signal; must be connected to exactly one RealOutput."""
    kind = "signal"
    required = True


class RealOutput(Port):
    """A causal real output signal."""
    kind = "signal"


class BooleanInput(RealInput):
    """A causal Boolean input signal (0: false, 1: true); must be connected to exactly one
    BooleanOutput."""
    kind = "Boolean signal"


class BooleanOutput(RealOutput):
    """A causal Boolean output signal (0: false, 1: true)."""
    kind = "Boolean signal"


class VectorPort:
    """Declares a vector connector on a component class (Modelica's ``RealInput u[3]``):
    ``u = VectorPort(RealInput, 3, "input signals")`` gives each instance the ports
    ``u[1]`` .. ``u[3]`` and the PortVector ``u``. ``description`` is one text (the element
    number is appended) or one text per element."""

    def __init__(self, port_cls: type, n: int, description: str | tuple[str, ...] = ""):
        if isinstance(description, str):
            description = tuple(f"{description} [{i}]" for i in range(1, n + 1))
        if len(description) != n:
            raise TypeError(f"VectorPort of {n} elements given {len(description)} descriptions")
        self.port_cls, self.descriptions = port_cls, tuple(description)


class PortVector:
    """Ports of a vector connector (``Sum.u``), numbered from 1 as in Modelica: ``u[1]``."""

    def __init__(self, owner_type: str, name: str, items: list):
        self._owner_type, self._name, self._items = owner_type, name, list(items)

    def __getitem__(self, i: int):
        try:
            i = operator.index(i)
        except TypeError:
            i = None
        if i is None or not 1 <= i <= len(self._items):
            raise IndexError(f"{self._owner_type}.{self._name}[{i}]: index out of range; the "
                             f"elements are numbered 1..{len(self._items)} as in Modelica")
        return self._items[i - 1]

    def __len__(self):
        return len(self._items)

    def __iter__(self):
        return iter(self._items)

    def __repr__(self):
        return f"[{', '.join(p.path for p in self._items)}]"
