"""The recorded variables of a compiled model: every port's potentials and flows (cut forces
and torques, recovered from the relations' reactions), internal nodes' motion, states,
algebraic variables, components' variables and signals, by dotted name."""
from __future__ import annotations

import casadi as ca

from .kinematics import InternalNode

_vc = ca.vertcat


def port_flows(ws, tree, explicit, lam_tree, lam_loop):
    """Flow of every port of every component, explicit ones plus relation reactions:
    ([(dotted name, expression, unit)] of the ports' flows, {port: flow} of the ports force
    sensors measure)."""
    total: dict = {}
    order = []

    def add(p, v):
        if p not in total:
            total[p] = v
            order.append(p)
        else:
            total[p] = total[p] + v

    ports = [p for block, _ in ws.flows for p in block]
    for p, v in zip(ports, _split(explicit, [p.domain.dof for p in ports])):
        add(p, v)
    extra = {}
    for block, lam in zip(tree.loops, _split(lam_loop, [b.rows for b in tree.loops])):
        if block.flows is None:
            extra[id(block.relation)] = lam    # extra rows of a relation that also fired
            continue
        for p, v in block.flows(lam):
            add(p, v)
    for f, lam in zip(tree.fired, _split(lam_tree, [f.dim for f in tree.fired])):
        r = f.relation
        for p, v in (r.flows(lam) if r.linear else r.flows_fired(lam, extra.get(id(r)))):
            add(p, v)
    out = []
    for p in order:
        if isinstance(p, InternalNode):
            continue
        for j, fname in enumerate(p.domain.flows):
            out.append((f"{p.path}.{fname}", total[p][j] if p.domain.dof > 1 else total[p],
                        p.domain.flow_units[j]))
    flow_of = {p: total.get(p, ca.SX.zeros(p.domain.dof)) for p in ws.cut_flow_sym}
    return out, flow_of


def _split(v: ca.SX, dims: list[int]) -> list[ca.SX]:
    """Consecutive pieces of v with the given sizes (one call: slicing costs per piece)."""
    if all(d == 1 for d in dims):
        return ca.vertsplit(v) if dims else []
    offsets = [0]
    for d in dims:
        offsets.append(offsets[-1] + d)
    return ca.vertsplit(v, offsets)


def _scalars(v: ca.SX) -> list[ca.SX]:
    """The elements of v (v itself if it is one: indexing an SX costs ~10 µs per call)."""
    return [v] if v.is_scalar() else ca.vertsplit(ca.vec(v))


def recorded_variables(ws, tree):
    """Names, expressions and units of every potential, velocity, state and signal; and
    the rows that are kept only where they can be computed (the velocities of ports and
    internal points, the variables components record): a flange moved by a model input
    with no speed given has none."""
    names, exprs, units = [], [], []
    optional = set()
    seen = set()

    def rec(name, ex, unit="", may_drop=False):
        if name not in seen:
            seen.add(name)
            if may_drop:
                optional.add(len(names))
            names.append(name)
            exprs.append(ex)
            units.append(unit)

    for n in tree.nodes:
        pos = vel = None                 # the node's potentials and velocities, as scalars
        for p in n.ports:
            dom = p.domain
            if isinstance(p, InternalNode) and dom.dim == 1:   # else by potential, as ports
                rec(p.path, n.pos, dom.potential_units[0])
                base = p.owner.path
                if p.velocity:
                    rec(f"{base}.{p.velocity}" if base else p.velocity, n.vel,
                        dom.velocity_units[0], True)
                if p.acceleration:
                    rec(f"{base}.{p.acceleration}" if base else p.acceleration, n.acc,
                        dom.velocity_units[0] + "2", True)
                continue
            if pos is None:
                pos, vel = _scalars(n.pos), _scalars(n.vel)
            for j, pot in enumerate(dom.potentials):
                rec(f"{p.path}.{pot}", pos[j], dom.potential_units[j])
            for j, name in enumerate(dom.velocity_names):
                if name:
                    rec(f"{p.path}.{name}", vel[j], dom.velocity_units[j], True)
    for info in ws.states:
        rec(info.sym.name(), info.sym, info.unit)
    for a in ws.algebraics:
        rec(a.sym.name(), a.sym, a.unit)
    for name, ex, unit, _ in ws.variables:
        rec(name, ex, unit, True)
    for c, s in ws.inputs:
        rec(c.path, s, c.unit)
    for c, e in ws.outputs:
        rec(c.path, e, c.unit)
    unit_of = {id(c): c.unit for c, _ in ws.inputs}      # a model Input's signal: its unit
    for o, s in ws.signal_sym.items():
        rec(o.path, s, unit_of.get(id(o.owner), ""))
    for i, o in ws.source.items():
        if o in ws.signal_sym:
            rec(i.path, ws.signal_sym[o], unit_of.get(id(o.owner), ""))
    return names, (_vc(*[e if e.size2() == 1 else ca.vec(e) for e in exprs]) if exprs
                   else ca.SX(0, 1)), units, optional
