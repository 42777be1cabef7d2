"""Index reduction by demoting states (the dummy-derivative method, for constraints linear in
a state).

A constraint h(x, t) = 0 on the states (a loop of capacitors in a network; a block equation
that fixes states only, MSL's InverseBlockConstraints) holds no unknown of the DAE: the
unknowns it fixes act through the states' rates, so the DAE has index 2 or more. One state
d of h with a constant coefficient c (a number, or an expression of parameters that is
nonzero at their defaults: a parameter changed to make it 0 at simulation time makes the
equations divide by 0) stops being a state and becomes an expression of the others,
d = −(h − c·d)/c (recorded under its name; its start value is no longer used), and its
derivative equation der(d) = f_d becomes the algebraic equation d/dt(−(h − c·d)/c) = f_d,
the rate of the constraint. Where that equation still holds no unknown (an inverted block
of higher order) it is a constraint again, reduced the same way. Every signal the
constraint holds must have a known rate (not a model input's), as often as it is
differentiated.

Signal constraints (``reduce_signal_constraints``): a residual of a component without
network ports (``PhysicsBuilder.residual``) that depends on states, time, parameters,
inputs and modes only. The state demoted is, among those of h, one whose rate depends on
the algebraic variables, directly or through other states (a state of the block being
inverted: its input is the unknown), else any; the last declared of them. So the states of
the blocks that give the constraint its values (a filter of the reference signal) are kept
with their start values and initial equations.
"""
from __future__ import annotations

import casadi as ca

from ..core.component import who
from ..errors import StructureError
from .symbolic import UnknownDerivative, der_with

_vc = ca.vertcat


def demote_state(ws, resolve, h: ca.SX, demoted: list, message: str, prefer=()) -> ca.SX:
    """Demote a state of the constraint ``h`` = 0 (module's docstring), preferring the
    states ``prefer`` (StateInfo), the last declared: ``demoted`` (state symbol, its
    expression) and ``ws.states`` updated in place. Returns the rate equation that replaces
    the constraint (in which the demoted state is still a symbol: the caller substitutes
    it, as in its other equations). Raises the StructureError ``message`` (with the
    reason) when no state can be demoted."""
    parameters = {s.name() for s in ca.vertsplit(ws.p)}
    candidates = [i for i in ws.states if ca.depends_on(h, i.sym)
                  and _constant(ca.jacobian(h, i.sym), ws, parameters)]
    if not candidates:
        raise StructureError(message + " (its constraint involves no state with a constant "
                                       "coefficient to demote)")
    preferred = [i for i in candidates if any(i is p for p in prefer)]
    d = (preferred or candidates)[-1]
    value = -ca.substitute(h, d.sym, 0) / ca.jacobian(h, d.sym)
    try:
        rate = resolve([der_with(value, ws.der_table) - d.der])[0]
    except UnknownDerivative as e:
        raise StructureError(f"{message}; index reduction: {e}") from None
    if demoted:           # the rates of the states may hold states demoted before this one
        rate = ca.substitute(rate, _vc(*[sym for sym, _ in demoted]),
                             _vc(*[v for _, v in demoted]))
    for k, (sym, v) in enumerate(demoted):
        demoted[k] = (sym, ca.substitute(v, d.sym, value))
    demoted.append((d.sym, value))
    ws.states[:] = [i for i in ws.states if i is not d]
    ws.demoted_states.append(d)
    return rate


def _constant(c: ca.SX, ws, parameters: set) -> bool:
    """Whether the coefficient ``c`` is a number or an expression of parameters, nonzero at
    the parameters' defaults."""
    if not all(s.name() in parameters for s in ca.symvar(c)):
        return False
    at_defaults = ca.substitute(c, ws.p, ca.DM(ws.p_default)) if ws.p.numel() else c
    return float(ca.evalf(at_defaults)) != 0


def reduce_signal_constraints(ws, resolve, network, rows: list, known: ca.SX,
                              unknowns: ca.SX) -> None:
    """Reduce the residuals ``rows`` (indices into ``ws.residuals``: those of components
    without network ports) that constrain states only (module's docstring): each is
    replaced by its rate, the demoted states go into ``network.demoted`` (substituted
    everywhere by ``network.substitute``) and are recorded in ``network.records`` (unless
    a signal of that name records them: a FirstOrder's state y is its output y).
    ``known``: the symbols a constraint on states may hold (time, coordinates and their
    rates, states, parameters, inputs, modes); ``unknowns``: the algebraic variables of
    those components. Without ``ws.index_reduction`` a StructureError names the
    component."""
    names = {s.name() for s in ca.vertsplit(known)}

    def constrains_states(row) -> bool:
        free = ca.symvar(row)
        return bool(free) and all(s.name() in names for s in free)

    resolved = ca.vertsplit(network.substitute(resolve([_vc(*[ws.residuals[k][1]
                                                              for k in rows])]))[0])
    pending = [k for k, row in zip(rows, resolved) if constrains_states(row)]
    while pending:
        k = pending.pop(0)
        owner, row = ws.residuals[k]
        row = network.substitute(resolve([row]))[0]
        if not constrains_states(row):
            continue
        states = ", ".join(i.sym.name() for i in ws.states if ca.depends_on(row, i.sym))
        message = (f"{who(owner)}: an equation of it holds no unknown, only states "
                   f"({states or 'none'}): the DAE has a higher index (its unknown follows "
                   f"from the rate of the constraint)")
        if not ws.index_reduction:
            raise StructureError(message + "; compile with index_reduction=True to reduce it "
                                           "(a state of the constraint then becomes an "
                                           "expression of the others)")
        rate = demote_state(ws, resolve, row, network.demoted, message,
                            _driven(ws, resolve, network, unknowns))
        d = ws.demoted_states[-1]
        value = network.demoted[-1][1]
        ws.residuals[k] = (owner, ca.substitute(rate, d.sym, value))
        if network.alg:
            network.alg = ca.vertsplit(ca.substitute(_vc(*network.alg), d.sym, value))
        if not any(o.path == d.sym.name() for o in ws.signal_sym):   # a block's output
            network.records.append((d.sym.name(), d.sym, d.unit))      # state: recorded
        pending.insert(0, k)                    # its rate may constrain states again


def _driven(ws, resolve, network, unknowns: ca.SX) -> list:
    """The states whose rate depends on ``unknowns``, directly or through other such
    states."""
    if not ws.states:
        return []
    rates = ca.vertsplit(network.substitute(resolve([_vc(*[i.der for i in ws.states])]))[0])
    driven, reached = [], unknowns
    while True:
        more = [i for i, r in zip(ws.states, rates)
                if not any(i is d for d in driven) and ca.depends_on(r, reached)]
        if not more:
            return driven
        driven += more
        reached = _vc(reached, *[i.sym for i in more])
