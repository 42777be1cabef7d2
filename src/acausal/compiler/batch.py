"""Batched physics: many instances of one component class in one CasADi call.

Each SX operation issued from Python costs ~20 µs, so a chain of 10 000 springs spends most of
its compile time inside the springs' physics(). For classes that declare
``batch_physics = True`` in their own class body (their physics reads only port motion,
parameters and time, and writes flows, energies and variables with their nominals), physics()
runs once on stand-in symbols; the result becomes a casadi Function, mapped over all
instances in one call. The expressions are the same as instance by instance. Classes that do
anything else fall back to the plain path.
"""
from __future__ import annotations

import casadi as ca

from .builders import KEPT, PhysicsBuilder, Workspace
from .kinematics import motion_symbols, side_by_side

#: fewer instances than this are not worth a batch
MIN_BATCH = 8


class _NotBatchable(Exception):
    pass


class _TraceBuilder(PhysicsBuilder):
    """PhysicsBuilder for the representative instance: motion as stand-in symbols, results
    recorded instead of added to the workspace."""

    def __init__(self, ws, owner, slots: dict, table: dict):
        super().__init__(ws, owner)
        self.slots, self.table, self.out = slots, table, []

    def _slot(self, port, k):
        self._mine(port)
        return self.slots[port.name][k]

    def pos(self, port):
        return self._slot(port, 0)

    def vel(self, port):
        return self._slot(port, 1)

    def acc(self, port):
        return self._slot(port, 2)

    def der(self, expr):
        from .symbolic import der_with
        return der_with(expr, self.table)

    def flow(self, port, value):
        self._mine(port)
        if port.domain.network:         # a heat port's flow goes to the network equations
            raise _NotBatchable
        self.out.append(("flow", port.name, ca.vec(ca.SX(value))))

    def kinetic_energy(self, T):
        self.out.append(("T", None, ca.SX(T)))

    def potential_energy(self, V):
        self.out.append(("V", None, ca.SX(V)))

    def variable(self, name, expr, unit="", description="", nominal=None, stateSelect=None):
        self.out.append(("var", (name, unit, description), ca.vec(ca.SX(expr))))
        if nominal is not None:
            self.out.append(("nominal", name, ca.SX(nominal)))
        rank = KEPT.get(getattr(stateSelect, "value", stateSelect))
        if rank is not None:
            self.out.append(("kept", (name, rank), ca.vec(ca.SX(expr))))

    def _refuse(self, *args, **kwargs):
        raise _NotBatchable

    input = output = cut_flow = derivative = residual = model_input = model_output = _refuse
    state = _refuse
    time_event = outer = rigid_body = _refuse


def run_physics(ws: Workspace, components: list) -> None:
    """Call every component's physics, batching the classes that allow it."""
    points = {}
    for n in ws.internal_nodes:
        points.setdefault(id(n.owner), []).append(n)
    groups: dict = {}
    for c in components:
        if vars(type(c)).get("batch_physics", False):      # not inherited: a subclass may differ
            ports = tuple(sorted(c.ports)) + tuple(sorted(n.name for n in points.get(id(c), [])))
            groups.setdefault((type(c), ports), []).append(c)
        else:
            c.physics(PhysicsBuilder(ws, c))
    for members in groups.values():
        if len(members) < MIN_BATCH or not _batched(ws, members, points):
            for c in members:
                c.physics(PhysicsBuilder(ws, c))


def _ports_of(c, points) -> dict:
    out = dict(c.ports)
    for n in points.get(id(c), []):
        out[n.name] = n
    return out


def _batched(ws: Workspace, members: list, points: dict) -> bool:
    rep = members[0]
    rep_ports = _ports_of(rep, points)
    slots, table, inputs, names = {}, {}, [], sorted(rep_ports)
    for name in names:
        trio = list(motion_symbols(name, rep_ports[name].domain, table))
        slots[name] = trio
        inputs += trio
    saved = ws.param_symbols[rep]
    pnames = list(saved)
    stand = {p: ca.SX.sym(p, saved[p].numel()) for p in pnames}
    table["t"] = 1
    ws.param_symbols[rep] = stand
    try:
        tb = _TraceBuilder(ws, rep, slots, table)
        rep.physics(tb)
    except _NotBatchable:
        return False
    finally:
        ws.param_symbols[rep] = saved
    if not tb.out:
        return True
    F = ca.Function("batch", inputs + [stand[p] for p in pnames] + [ws.t],
                    [ca.vertcat(*[ex for *_, ex in tb.out])])
    args = []
    all_ports = [_ports_of(c, points) for c in members]
    for name in names:
        nodes = [ws.node_of[ports[name]] for ports in all_ports]
        args += [side_by_side(nodes, ws.one_d, k) for k in ("pos", "vel", "acc")]
    args += [_parameter_row(ws, members, p) for p in pnames]
    args.append(ws.t)
    Y = F.map(len(members))(*args)
    prefixes = [f"{c.path}." if c.path else "" for c in members]
    row = 0
    for kind, what, ex in tb.out:
        k = ex.numel()
        block = Y[row:row + k, :]
        row += k
        if kind in ("T", "V"):
            (ws.kinetic if kind == "T" else ws.potential).append(ca.sum2(block))
            if kind == "T":
                ws.kinetic_other.append(ca.sum2(block))
            continue
        if kind == "flow":
            ws.flows.append(([ports[what] for ports in all_ports], ca.vec(block)))
            continue
        cols = ca.horzsplit(block)
        if kind == "nominal":
            for prefix, col in zip(prefixes, cols):
                ws.nominals[prefix + what] = col
        elif kind == "kept":
            name, rank = what
            for c, prefix, col in zip(members, prefixes, cols):
                ws.state_selects.append((c, prefix + name, col, rank))
        else:
            name, unit, desc = what
            for prefix, col in zip(prefixes, cols):
                ws.variables.append((prefix + name, col, unit, desc))
    return True


def _parameter_row(ws: Workspace, members: list, name: str) -> ca.SX:
    """The members' parameter ``name`` side by side: one slice of the stacked parameters
    where each is a row of them, else their symbols joined one by one."""
    rows = [ws.param_rows.get(c, {}).get(name) for c in members]
    if ws.p is not None and None not in rows:
        return ws.p[rows].T
    return ca.horzcat(*[ws.param_symbols[c][name] for c in members])
