"""Flatten a model: every component and port by dotted name, connection groups, signal wiring."""
from __future__ import annotations

import re
from dataclasses import dataclass

from ..core.component import Component, Model
from ..errors import PortConnectionError, StructureError
from ..core.ports import PhysicalPort, Port, RealInput, RealOutput


@dataclass
class Flat:
    """The flattened model: components in declaration order, connection groups of ports;
    the root's own signal connectors (Modelica's top-level inputs and outputs), which
    become inputs and outputs of the compiled model."""
    root: Model
    components: list[Component]
    groups: list[list[PhysicalPort]]           # physical ports joined by connections
    signal_source: dict[RealInput, RealOutput]  # where each input gets its value
    root_inputs: list[RealInput]
    root_outputs: list[tuple[RealOutput, RealOutput | RealInput | None]]   # and their driver


@dataclass(frozen=True)
class RootSignal:
    """A signal connector of the compiled model itself as an input or output of the
    compiled model (and of its FMU): named by the connector, with its description; its
    unit is the bracketed one that ends the description ("torque to drive the flange
    [N.m]"), if any; an input starts at 0."""
    port: Port
    start: float = 0.0

    @property
    def path(self) -> str:
        return self.port.path

    @property
    def description(self) -> str:
        return self.port.description

    @property
    def unit(self) -> str:
        found = re.search(r"\[([^\[\]]+)\]\s*$", self.port.description)
        return found.group(1) if found else ""


class _UnionFind:
    def __init__(self):
        self.parent = {}

    def find(self, x):
        p = self.parent.setdefault(x, x)
        while p is not self.parent.get(p, p):
            self.parent[p] = self.parent[self.parent[p]]
            p = self.parent[p]
        return p

    def union(self, a, b):
        ra, rb = self.find(a), self.find(b)
        if ra is not rb:
            self.parent[rb] = ra


def _walk(c: Component, out: list[Component]):
    out.append(c)
    for child in c.children.values():
        _walk(child, out)


def flatten(root: Model) -> Flat:
    if not isinstance(root, Component):
        raise StructureError(f"compile() takes a Model, got {root!r}")
    comps: list[Component] = []
    _walk(root, comps)
    in_model = set(map(id, comps))
    phys: list[PhysicalPort] = []
    signals: list[Port] = []
    for c in comps:
        for p in c.ports.values():
            (phys if isinstance(p, PhysicalPort) else signals).append(p)

    uf = _UnionFind()
    for c in comps:
        for a, b in getattr(c, "_connections", ()):
            for p in (a, b):
                if id(p.owner) not in in_model:
                    raise PortConnectionError(
                        f"port '{p.path}' is connected in '{c.path or c.name}' but its component "
                        f"is not part of the model being compiled")
            uf.union(a, b)

    connected = set()
    for c in comps:
        for a, b in getattr(c, "_connections", ()):
            connected.update((a, b))

    # physical groups, in port declaration order
    index: dict[int, int] = {}
    groups: list[list[PhysicalPort]] = []
    for p in phys:
        r = id(uf.find(p))
        if r not in index:
            index[r] = len(groups)
            groups.append([])
        groups[index[r]].append(p)
    for p in phys:
        if p.required and p not in connected:
            raise StructureError(
                f"port '{p.path}' of {type(p.owner).__name__} is not connected; connect it "
                f"(a sensor or source must be attached to what it measures or drives)")

    # signal wiring: every group of signal ports has exactly one driver
    sig_groups: dict[int, list[Port]] = {}
    for p in signals:
        sig_groups.setdefault(id(uf.find(p)), []).append(p)
    source: dict[RealInput, RealOutput] = {}
    for members in sig_groups.values():
        outs = [p for p in members if _drives(p, root)]
        ins = [p for p in members if p not in outs]
        if len(outs) > 1:
            raise PortConnectionError(
                f"signals {', '.join(repr(o.path) for o in outs)} are connected together; an "
                f"input can be driven by one output only")
        for p in ins:
            if not outs:
                if isinstance(p, RealInput) and p.required:
                    raise StructureError(
                        f"input '{p.path}' of {type(p.owner).__name__} is not connected to any "
                        f"output: connect it to a signal source (e.g. Constant, Step) or to an "
                        f"Input of the model")
                continue
            source[p] = outs[0]
    own = [p for p in root.ports.values() if not isinstance(p, PhysicalPort)]
    return Flat(root, comps, groups, source, [p for p in own if isinstance(p, RealInput)],
                [(p, source.get(p, p if _drives(p, root) else None)) for p in own
                 if isinstance(p, RealOutput)])


def _drives(p: Port, root: Model) -> bool:
    """Whether a signal port is the driver of its group: a component's RealOutput, or an
    input of the compiled model itself (given from outside)."""
    if isinstance(p, RealOutput):
        return not (isinstance(p.owner, Model) and p.owner.children)
    return p.owner is root
