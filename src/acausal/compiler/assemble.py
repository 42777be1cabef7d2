"""compile(): model → CompiledModel, in six steps.

1. flatten (``flatten``); parameters become SX symbols, held in the compile's own workspace
   (``Workspace.param_symbols``, read by the components through ``symbolic_parameters``);
2. every component declares its structure; kinematic graph and coordinates
   (``kinematics.choose_tree``: for a graph with loops, the tree whose coordinates carry
   mass, from a dry run of the physics with every node free, ``_massive_nodes``);
3. every component contributes its physics given the motion of its ports (``batch``);
4. Lagrange's residuals by algorithmic differentiation for the coordinates q and the
   relaxations ε of the tree relations (``lagrange.residuals``);
5. signals, state derivatives and relaxations are substituted (``resolve``); the loops are
   checked (``loops``) and the equations solved for the accelerations (``motion``);
   potential/flow networks (electrical, thermal: ``networks``) add their node potentials
   and unknown flows as algebraic variables, with Kirchhoff's laws, checked for structure
   and reduced by their trivial equations before the accelerations are solved (a flow on a
   mechanical flange, an EMF's torque, enters Lagrange's generalized forces); block
   equations that constrain states are reduced (``index``);
6. the DAE, its start values, nominals and time events, the recorded variables (``recorded``, built on
   first use) are put together into a CompiledModel.

Nothing is written into the components: a component may be compiled into two models, or
twice, and keeps no trace of it.
"""
from __future__ import annotations

from dataclasses import replace

import casadi as ca
import numpy as np

from ..core.component import Model
from ..core.parameter import Parameter, symbolic_parameters
from ..errors import StructureError, did_you_mean
from .batch import run_physics
from .builders import StructureBuilder, Workspace
from .charts import angle_starts, at_origin, check_inertia, quaternion_states
from .compiled import CompiledModel, Reinit, ScalarVariable, StateEvents, coinciding
from .flatten import RootSignal, flatten
from .index import reduce_signal_constraints
from .kinematics import Node, choose_tree, motion_symbols
from .lagrange import Lagrange, Residuals, residuals
from .loops import analyse_loops
from .motion import solve_motion
from .nonholonomic import solve_velocity_constrained
from .networks import build_network, declare_nodes, has_network_ports
from .recorded import port_flows, recorded_variables
from .resolve import make_resolver
from .symbolic import gc_paused

_vc = ca.vertcat
_ACTIVE = Parameter(1.0, "1", "1: this loop constraint row is enforced; simulate() sets 0 for "
                              "rows redundant at the assembled configuration", nonnegative=True)


def _stack(items) -> ca.SX:
    return _vc(*items) if items else ca.SX(0, 1)


def _column(values: list) -> ca.SX:
    """A column of numbers and scalar SX, the numbers converted in one piece (one SX per
    number costs ~10 µs each in bulk)."""
    expr = [i for i, x in enumerate(values) if isinstance(x, ca.SX)]
    if not expr:
        return ca.SX(ca.DM([float(x) for x in values])) if values else ca.SX(0, 1)
    num = [i for i, x in enumerate(values) if not isinstance(x, ca.SX)]
    joined = _vc(ca.DM([float(values[i]) for i in num]), *[values[i] for i in expr])
    order = np.argsort(num + expr)
    return joined[[int(k) for k in order]]


def compile(model: Model, smooth: bool = False, index_reduction: bool = False) -> CompiledModel:
    """Compile ``model`` into a CompiledModel; ``smooth``: every component with events in its
    smooth form (see ``PhysicsBuilder.smooth``); ``index_reduction``: reduce the loops of
    capacitors / voltage sources and the cut sets of inductors / current sources of
    networks, and the block equations that constrain states, instead of refusing them (see
    ``networks``, ``index``)."""
    with gc_paused():
        return _compile(model, smooth, index_reduction)


def recompile(compiled: CompiledModel, smooth: bool) -> CompiledModel:
    """``compiled``'s ``source`` model compiled again, in smooth form or not, with the same
    ``index_reduction``, as a record of ``compiled``'s class."""
    if compiled.source is None:
        raise StructureError(f"compiled model '{compiled.name}' does not know the Model it "
                             "was compiled from; compile the Model with "
                             f"acausal.compile(model, smooth={bool(smooth)})")
    return type(compiled).wrap(compile(compiled.source, smooth, compiled.index_reduction))


def _compile(model: Model, smooth: bool, index_reduction: bool) -> CompiledModel:
    flat = flatten(model)
    ws = Workspace(t=ca.SX.sym("t"), smooth=bool(smooth), index_reduction=bool(index_reduction))
    ws.der_table["t"] = 1
    ws.source = flat.signal_source
    ws.components = flat.components
    _declare_root_inputs(ws, flat)
    params, fixed = _declare_parameters(ws, flat.components)
    ws.p = _stack([s for s, _ in params])
    ws.p_default = [v.start for _, v in params]
    with symbolic_parameters(ws.param_symbols):
        for c in flat.components:
            c.structure(StructureBuilder(ws, c))
        mech, net = _split_groups(flat.groups)
        declare_nodes(ws, net)
        nodes = [Node(i, list(g)) for i, g in enumerate(mech)]
        for n in ws.internal_nodes:
            nodes.append(Node(len(nodes), [n]))
        for n in nodes:
            for p in n.ports:
                ws.node_of[p] = n
        for r in ws.relations:
            r.nodes = [ws.node_of[p] for p in r.ports]
        tree = choose_tree(nodes, ws.relations, ws.der_table, ws.state_names,
                           lambda: _massive_nodes(flat, ws, len(nodes)))
        ws.one_d = tree.one_d
        run_physics(ws, flat.components)
    for port, source in flat.root_outputs:
        if source is None:
            raise StructureError(f"output '{port.path}' of model "
                                 f"'{model.name or type(model).__name__}' is not connected "
                                 f"inside it; connect it to the output of one of its components")
        ws.outputs.append((RootSignal(port), ws.signal(source)))
    return _assemble(model, ws, tree, params, fixed)


def _declare_root_inputs(ws: Workspace, flat) -> None:
    """The model's own input connectors (Modelica's top-level inputs) as inputs of the
    compiled model, by their names."""
    for port in flat.root_inputs:
        ws.model_input(RootSignal(port), port)


def _split_groups(groups):
    """Mechanical connection sets, then network ones (``Domain.network``)."""
    return ([g for g in groups if not g[0].domain.network],
            [g for g in groups if g[0].domain.network])


def _massive_nodes(flat, ws: Workspace, n_nodes: int) -> set[int]:
    """Indices of the nodes with mass: those whose velocity enters the kinetic energy.

    A dry run in a workspace of its own: every component declares its structure again
    (the same nodes, in the same order, as deterministic as the first time), every node gets
    position, velocity and acceleration symbols of its own, free of any tree, and every
    component contributes its physics; a node has mass when the kinetic energy is not
    linear in its velocity. The components keep nothing of it (as of any compile)."""
    probe = Workspace(t=ws.t, smooth=ws.smooth)
    probe.der_table["t"] = 1
    probe.source, probe.components = ws.source, ws.components
    _declare_root_inputs(probe, flat)
    probe.param_symbols = dict(ws.param_symbols)
    for c in flat.components:
        c.structure(StructureBuilder(probe, c))
    mech, net = _split_groups(flat.groups)
    declare_nodes(probe, net)
    groups = [list(g) for g in mech] + [[n] for n in probe.internal_nodes]
    if len(groups) != n_nodes:
        raise StructureError("internal: a component declared different nodes when asked "
                             "twice (please report)")
    vels = []
    for i, ports in enumerate(groups):
        node = Node(i, ports)
        node.pos, node.vel, node.acc = motion_symbols(f"probe{i}", node.domain,
                                                      probe.der_table)
        for p in ports:
            probe.node_of[p] = node
        vels.append(node.vel)
    run_physics(probe, flat.components)
    if not probe.kinetic:
        return set()
    v = ca.vertcat(*vels)
    T = ca.sum1(ca.vertcat(*probe.kinetic))
    hessian = ca.jacobian_sparsity(ca.gradient(T, v), v)
    owner = [i for i, vel in enumerate(vels) for _ in range(vel.numel())]
    return {owner[k] for k in hessian.get_triplet()[0]}


def _declare_parameters(ws: Workspace, components):
    """A symbol and a record for every scalar parameter (vector parameters by element,
    ``r[1]``, ``r[2]``); the components' symbols go into ``ws.param_symbols`` (the rows of
    the scalar ones in the stacked parameters into ``ws.param_rows``). A
    ``structural_zero`` parameter built with 0 is the constant 0 instead, listed in the
    second list returned (by name)."""
    params, fixed = [], []
    layouts, declarations = {}, {}       # by class; by (parameter, built with 0)
    for c in components:
        syms, rows, path, values = {}, {}, c.path, c._values
        prefix = f"{path}." if path else ""
        layout = layouts.get(type(c))
        if layout is None:
            layout = layouts[type(c)] = [(pname, par, par.element_names())
                                         for pname, par in c.parameters().items()]
        for pname, par, enames in layout:
            value = values[pname]
            key = (id(par), par.size is None and value == 0.0)
            if key not in declarations:
                declarations[key] = par.compiled(value)
            declaration = declarations[key]
            if declaration is None:                       # fixed at 0: a massless part
                syms[pname] = ca.SX(0.0)
                fixed.append(prefix + pname)
                continue
            elements = []
            if par.size is None:
                rows[pname] = len(params)
            for k, ename in enumerate(enames):
                full = prefix + ename
                s = ca.SX.sym(full)
                elements.append(s)
                params.append((s, _parameter_record(full, declaration,
                                                    value if par.size is None else value[k])))
            syms[pname] = elements[0] if par.size is None else _vc(*elements)
        ws.param_symbols[c] = syms
        ws.param_rows[c] = rows
    return params, fixed


def _parameter_record(name: str, par: Parameter, default: float) -> ScalarVariable:
    lower = 0.0 if par.positive or par.nonnegative else -float("inf")
    return ScalarVariable(name, par.unit, par.description, default, min=lower, declaration=par)


def _assemble(model, ws: Workspace, tree, params, fixed: list[str]) -> CompiledModel:
    t = ws.t
    nq = tree.q.numel()
    eps, epsd, epsdd = tree.relaxations()
    _check_declarations(ws)

    # ---- Lagrange's residuals for [q; ε]; signals, derivatives, relaxations resolved ----
    R = residuals(ws, _vc(tree.q, eps), _vc(tree.qd, epsd))
    phi = tree.loop_residual
    phi_eps = ca.jacobian(phi, eps)
    resolve = make_resolver(ws, [eps, epsd, epsdd])
    network = build_network(ws, resolve)
    _reduce_signal_constraints(ws, tree, resolve, network)
    # (the rigid bodies, for the articulated-body recursion, in the same substitution, so
    # that their kinematics is the residuals' and not a copy of it)
    R_T, R_V, R_Q, phi, phi_eps, zdot, g_alg, y_out, explicit, nh, flat_bodies, T_other = \
        network.substitute(resolve([
            R.inertia, R.conservative, R.flows, phi, phi_eps,
            _stack([i.der for i in ws.states]),
            _stack([r for o, r in ws.residuals if not has_network_ports(o)]),
            _stack([e for _, e in ws.outputs]), _stack([fl for _, fl in ws.flows]),
            _stack([r for _, _, r, _ in ws.velocity_constraints]),
            _stack(ws.bodies), ca.sum1(_stack(ws.kinetic_other))]))
    cut = _stack(list(ws.cut_flow_sym.values()))
    if ca.depends_on(_vc((R_T + R_V + R_Q)[:nq], phi), cut):
        R_T, R_Q = _measured_into_forces(ws, tree, cut, R_T, R_V, R_Q, explicit, phi, nq)
    R_all = R_T + R_V + R_Q
    R_q, R_eps = R_all[:nq], R_all[nq:]

    # ---- loops, accelerations ------------------------------------------------------------
    keep, row_names = analyse_loops(tree, phi, ws)
    bodies = ca.vertsplit(flat_bodies, [int(k) for k in np.cumsum([0] + [b.numel() for b in
                                                                      ws.bodies])])
    check_inertia(tree.charts, R_T[:nq], tree.qdd)
    if ws.velocity_constraints:
        if keep or tree.charts:
            raise StructureError("closed kinematic loops or free bodies together with velocity "
                                 "constraints (rolling contacts) are not supported yet")
        motion = solve_velocity_constrained(
            tree, R_q, nh, _stack([f for *_, f in ws.velocity_constraints]),
            [f"{o.path}.{n}" for o, n, _, _ in ws.velocity_constraints], ws, resolve)
    else:
        motion = _on_charts(solve_motion(tree, R_q, phi[keep, :], ws, (bodies, T_other), resolve),
                            tree)
    lam = ca.SX.zeros(phi.numel())               # dropped (redundant) rows carry nothing
    lam[keep] = motion.lam
    lam_tree = -(R_eps + ca.mtimes(phi_eps.T, lam)) if eps.numel() else ca.SX(0, 1)
    sub_from = [tree.qdd] + motion.substitute_from
    sub_to = [motion.qdd] + motion.substitute_to

    def flows():
        return port_flows(ws, tree, explicit, lam_tree, lam)

    cut_values = ca.SX(0, 1)
    net_alg = _stack(network.alg)       # a heat flow may carry accelerations (friction losses)
    if ws.cut_flow_sym:
        _, flow_of = flows()
        cut_values = ca.densify(resolve([_stack([flow_of[p] for p in ws.cut_flow_sym])])[0])
        if ca.depends_on(cut_values, cut):
            raise StructureError("force sensors measure each other in a loop; not supported")
        zdot, g_alg, y_out, net_alg = ca.substitute([zdot, g_alg, y_out, net_alg], [cut],
                                                    [cut_values])
    zdot, g_alg, y_out, net_alg = ca.substitute([zdot, g_alg, y_out, net_alg], sub_from, sub_to)

    def resolved(exprs: ca.SX) -> ca.SX:
        return network.substitute(resolve([exprs]))[0]

    def finish(exprs: ca.SX) -> ca.SX:
        """Resolved expressions of the motion in (t, x, z, u, p)."""
        return ca.substitute([ca.substitute(exprs, cut, cut_values)], sub_from, sub_to)[0]

    def final(exprs: ca.SX) -> ca.SX:
        """Expressions of the motion as recorded: in (t, x, z, u, p)."""
        exprs = resolved(exprs)
        resolve.check([exprs])
        return finish(exprs)

    def recorder():
        """Every potential, velocity, flow, state, variable and signal, by name (built on
        first use: large models need not pay for it to be simulated or exported); the
        velocities and component variables that need a rate nobody knows (the speed of a
        flange that a model input moves with no speed given: an FMU's force law) kept
        apart with the error that reading them raises, an error for any other such row
        (a Der block's output)."""
        names, exprs, units, optional = recorded_variables(ws, tree)
        (flow_names, flow_exprs, flow_units), _ = flows()
        names += flow_names + [n for n, _, _ in network.records]
        units += flow_units + [u for _, _, u in network.records]
        exprs = resolved(_vc(exprs, flow_exprs, *[e for _, e, _ in network.records]))
        unknown = set(resolve.unknown_rows(exprs))
        resolve.check([exprs[sorted(unknown - optional)]] if unknown - optional else [])
        unavailable = {names[k]: resolve.error(exprs[k]) for k in sorted(unknown)}
        if unknown:
            kept = [k for k in range(len(names)) if k not in unknown]
            names, units = [names[k] for k in kept], [units[k] for k in kept]
            exprs = exprs[kept] if kept else ca.SX(0, 1)
        return names, finish(exprs), units, unavailable

    # ---- the DAE -------------------------------------------------------------------------
    n_model_params = len(params)
    params = params + [(s, ScalarVariable(s.name(), _ACTIVE.unit, _ACTIVE.description, 1.0,
                                          min=0.0, declaration=_ACTIVE))
                       for s in ca.vertsplit(motion.active)]
    n_before_modes = len(params)
    params = params + [(m.sym, _mode_record(m)) for m in ws.modes]
    z_states = _stack([i.sym for i in ws.states])
    u = _stack([s for _, s in ws.inputs])
    p = _vc(ws.p, motion.active, _stack([m.sym for m in ws.modes]))   # the model's, stacked once
    x = _vc(motion.q_diff, motion.qd_diff, z_states)
    if x.numel() == 0 and not ca.depends_on(recorder()[1], _vc(t, u)):
        raise StructureError(f"model '{model.name or type(model).__name__}' has no dynamics: no "
                             f"part can move (every node is fixed or prescribed) and no component "
                             f"has states, and no motion is prescribed; add a mass or inertia "
                             f"that is free to move")
    ode = _vc(motion.q_diff_dot, motion.qdd_diff, zdot)
    algebraics = [a for a in ws.algebraics if not has_network_ports(a.owner)]
    z = _vc(motion.alg_vars, _stack([a.sym for a in algebraics]),
            _stack([s for s, _, _ in network.z]))
    alg = _vc(motion.alg_res, g_alg, net_alg)
    events = _state_events(ws, final, x, _vc(t, x, z, u), p,
                           range(motion.q_diff.numel(), motion.n_x), [v.start for _, v in params])
    initial = final(_stack([ex for _, ex, _ in ws.initials]))
    asserted = final(_stack([c for _, c, _ in ws.assertions]))
    resolve.check([ode, alg, y_out, events.indicator, events.mode_update,
                   events.reinit_values, events.terminate, initial, asserted])
    check = ca.Function("check", [t, x, z, u, p], [ode, alg, y_out, events.indicator,
                                                    events.mode_update, events.reinit_values,
                                                    events.terminate, initial, asserted],
                        {"allow_free": True})
    if check.has_free():
        raise StructureError(f"internal: unresolved symbols {check.get_free()[:5]} "
                             f"(please report)")
    chart_starts = {k: v for c in tree.charts for k, v in c.start.items()}
    x_names = [s.name() for s in ca.vertsplit(x)[:motion.n_x]]     # q_diff, qd_diff
    starts = [chart_starts.get(name, 0.0) for name in x_names] \
        + [i.start for i in ws.states] \
        + [0.0] * motion.n_z + [a.start for a in algebraics] + [v for _, _, v in network.z]
    nominal = _parameter_function("nominal", _nominals(model, ws, tree, final, _vc(x, z),
                                                       _vc(t, x, z, u)), p, "nominals")
    n0 = nominal([v.start for _, v in params]).full().ravel()
    n_x, n_z = iter(n0[:x.numel()]), iter(n0[x.numel():])        # at the defaults
    units = _coordinate_units(tree)
    return CompiledModel(
        name=model.name or type(model).__name__, t=t, x=x, z=z, p=p, u=u,
        ode=ode, alg=alg, y=y_out,
        states=[ScalarVariable(name, units.get(name, ""), nominal=float(next(n_x)))
                for name in x_names]
        + [ScalarVariable(i.sym.name(), i.unit, i.description, nominal=float(next(n_x)))
           for i in ws.states],
        algebraics=[ScalarVariable(s.name(), units.get(s.name(), ""), nominal=float(next(n_z)))
                    for s in ca.vertsplit(motion.alg_vars)]
        + [ScalarVariable(a.sym.name(), a.unit, a.description, nominal=float(next(n_z)))
           for a in algebraics]
        + [ScalarVariable(s.name(), unit, nominal=float(next(n_z))) for s, unit, _ in network.z],
        params=[v for _, v in params],
        inputs=[ScalarVariable(c.path, c.unit, c.description, c.start) for c, _ in ws.inputs],
        outputs=[ScalarVariable(c.path, c.unit, c.description) for c, _ in ws.outputs],
        start=_parameter_function("start", starts, p, "start values"),
        nominal=nominal,
        events=_events(ws.events, p),
        recorder=recorder,
        lagrange=Lagrange(tree, Residuals(R_T[:nq], R_V[:nq], R_Q[:nq]), phi[keep, :], t, p, u,
                          [c.path for c, _ in ws.inputs], z_states),
        coordinates=tree.q_names,
        method=motion.method,
        loop_rows=[row_names[i] for i in keep],
        loop_rows_dropped=[row_names[i] for i in range(phi.numel()) if i not in keep],
        loop_switches=list(range(n_model_params, len(params))),
        loop_mu=motion.loop_mu, loop_nu=motion.loop_nu,
        fixed_params=fixed,
        mode_params=list(range(n_before_modes, len(params))),
        state_events=events,
        initial_equations=initial,
        initial_labels=[f"{o.path or model.name or type(model).__name__}: {n}"
                        for o, _, n in ws.initials],
        assertions=asserted,
        assertion_texts=[(o.path, text) for o, _, text in ws.assertions],
        smooth=ws.smooth,
        index_reduction=ws.index_reduction,
        angle_starts=angle_starts(tree.charts, p),
        source=model,
    )


def _reduce_signal_constraints(ws: Workspace, tree, resolve, network) -> None:
    """``index.reduce_signal_constraints`` of the residuals of the components without
    network ports."""
    rows = [k for k, (o, _) in enumerate(ws.residuals) if not has_network_ports(o)]
    if not rows:                    # (most models: no block equation to look at)
        return
    known = _vc(ws.t, tree.q, tree.qd, _stack([i.sym for i in ws.states]), ws.p,
                _stack([s for _, s in ws.inputs]), _stack([m.sym for m in ws.modes]))
    unknowns = _stack([a.sym for a in ws.algebraics if not has_network_ports(a.owner)])
    reduce_signal_constraints(ws, resolve, network, rows, known, unknowns)


def _measured_into_forces(ws: Workspace, tree, cut, R_T, R_V, R_Q, explicit, phi, nq: int):
    """(R_T, R_Q) with the cut flows that sensors measure (``PhysicsBuilder.cut_flow``)
    replaced where they drive forces: in a tree each is the reaction of relations that
    fired, −R_ε, linear in the accelerations; its terms in q̈ join the inertia terms (an
    inverse inertia moved by the acceleration of a direct one, which it drives with the
    torque it needs: MSL's GenerationOfFMUs), the rest the generalized forces. Refused in
    loops and with rolling contacts (the reactions there come out of the constrained solve)
    and where the measured flows measure each other."""
    if phi.numel() or ws.velocity_constraints:
        raise StructureError("a measured cut force/torque (force or torque sensor, FMU adaptor) "
                             "feeds back into the forces of a model with closed kinematic loops "
                             "or rolling contacts; this implicit loop is not supported there: "
                             "measure the force elsewhere (e.g. a spring's f)")
    lam_tree = -(R_T + R_V + R_Q)[nq:]
    _, flow_of = port_flows(ws, tree, explicit, lam_tree, ca.SX(0, 1))
    values = _stack([flow_of[p] for p in ws.cut_flow_sym])
    if ca.depends_on(values, cut):
        raise StructureError("force sensors measure each other in a loop; not supported")
    R_T, R_Q = ca.substitute([R_T, R_Q], [cut], [values])
    forces = ca.substitute(R_Q, tree.qdd, ca.SX.zeros(tree.qdd.numel()))
    return R_T + (R_Q - forces), forces


def _on_charts(motion, tree):
    """The motion with the free 3-D frames' chart coordinates θ turned into quaternion
    states and every expression at θ = 0 (``charts``)."""
    if not tree.charts:
        return motion
    states = quaternion_states(tree.charts, motion.q_diff, motion.q_diff_dot)
    frm, to = at_origin(tree.charts)
    rates, qdd_diff, alg_res, qdd, lam = ca.substitute(
        [states[1], motion.qdd_diff, motion.alg_res, motion.qdd, motion.lam], frm, to)
    return replace(motion, q_diff=states[0], q_diff_dot=rates, qdd_diff=qdd_diff,
                   alg_res=alg_res, qdd=qdd, lam=lam,
                   substitute_from=motion.substitute_from + frm,
                   substitute_to=motion.substitute_to + to)


def _mode_record(m) -> ScalarVariable:
    what = m.description or ("discrete variable" if m.real else "discrete mode")
    declaration = Parameter(float(m.start), m.unit, f"{what}; its start value here, changed "
                                                    f"only at events")
    return ScalarVariable(m.sym.name(), m.unit, declaration.description, float(m.start),
                          declaration=declaration, component=m.owner.path)


def _state_events(ws: Workspace, final, x: ca.SX, free: ca.SX, p: ca.SX, velocities: range,
                  p0: list) -> StateEvents:
    """The indicators, mode updates (a mode without one keeps its value), reinits and
    termination conditions of the components, in (t, x, z, u, p); a reinit's variable
    resolved to the state it is, a reinit of a generalized velocity (x[velocities]) followed
    by the reinits of the velocities that follow it (``_followers``, chosen at the
    parameters' start values p0); the sample triggers' instants as a Function of p."""
    indicators = [ScalarVariable(f"{o.path}.{n}" if o.path else n, unit, descr, component=o.path)
                  for o, n, _, unit, descr in ws.indicators]
    index = {(o, n): i for i, (o, n, *_) in enumerate(ws.indicators)}
    g, upd, values = (final(_stack(v)) if v else ca.SX(0, 1) for v in (
        [e for *_, e, _, _ in ws.indicators],
        [m.update if m.update is not None else m.sym for m in ws.modes],
        [ex for _, _, ex, _, _ in ws.reinits]))
    rows = []
    for (owner, variable, _, when, direction), value in zip(ws.reinits, ca.vertsplit(values)):
        where = f"{type(owner).__name__} '{owner.path}'"
        if (owner, when) not in index:
            mine = [n for o, n, *_ in ws.indicators if o is owner]
            raise StructureError(f"{where}: reinit when '{when}', which is no indicator of it "
                                 f"(its indicators: {', '.join(mine) or 'none'}); declare it "
                                 f"with e.indicator")
        v = final(variable)
        hit = coinciding(v, x, free)
        if hit is None:
            jumps = _combination_jumps(ws, final, owner, v, x, free, p, velocities, p0)
            if jumps is None:
                raise StructureError(f"{where}: reinit of '{variable}', which is not a state "
                                     f"(nor one state scaled and offset by parameters, nor a "
                                     f"velocity linear in the generalized velocities); reinit "
                                     f"a state or the velocity of a flange")
            rows += [Reinit(j, index[(owner, when)], direction, x[j] + dj * (value - v))
                     for j, dj in jumps]
            continue
        k, a = hit
        new = (value - ca.substitute(v, x[k], 0)) / a
        rows.append(Reinit(k, index[(owner, when)], direction, new))
        rows += [Reinit(j, index[(owner, when)], direction, x[j] + dj * (new - x[k]))
                 for j, dj in _followers(ws, final, owner, k, x, free, p, velocities, p0)]
    reinit_values = _stack([r.value for r in rows])
    values = {m.sym.name(): m.values for m in ws.modes if m.values is not None}
    clocks = [k for k, m in enumerate(ws.modes) if m.clock is not None]
    clock_times = _events([ws.modes[k].clock for k in clocks], p)
    terminate = final(_stack([c for _, c, _ in ws.terminations]))
    return StateEvents(indicators, g, upd, rows, reinit_values, values,
                       real_modes=tuple(m.sym.name() for m in ws.modes if m.real),
                       clocks=clocks, clock_initial=[ws.modes[k].initial for k in clocks],
                       clock_times=clock_times, terminate=terminate,
                       terminations=[(o.path, text) for o, _, text in ws.terminations])


def _kept_rows(ws: Workspace, final, owner, w: ca.SX) -> list:
    """The velocities other components than ``owner`` declare stateSelect always, then
    prefer (``ws.state_selects``), that are linear in the generalized velocities w: their
    rows d(velocity)/dw, in that order (see PhysicsBuilder.reinit)."""
    rows = []
    for other, _, expr, rank in sorted(ws.state_selects, key=lambda r: r[3]):
        if other is owner:
            continue
        J = ca.jacobian(final(expr), w)
        if J.nnz() and not ca.depends_on(J, w):         # a velocity: linear in them
            rows.append(J)
    return rows


def _jump(first: ca.SX, kept: list, free: ca.SX, p: ca.SX, p0: list):
    """(d, d0, chosen): the change d of the generalized velocities w per unit change of the
    reinitialized velocity first·w (a 1×n row), with the ``kept`` velocities (rows) unchanged
    and then the generalized velocities themselves as far as they are independent of those
    before (rank at p0 and a generic point); d0 its value there, ``chosen`` the rows of
    [first; kept; unit rows] it keeps (0: the reinitialized velocity)."""
    n = first.size2()
    unit = ca.DM.eye(n)
    rows = [first] + kept + [ca.SX(unit[j, :]) for j in range(n)]
    probe = ca.Function("kept", [free, p], [ca.vertcat(*rows)], {"allow_free": True})
    rng = np.random.default_rng(0)
    A = np.array(probe(rng.uniform(0.5, 1.5, free.numel()), p0), dtype=float)
    chosen = []
    for r in range(A.shape[0]):
        if np.linalg.matrix_rank(A[chosen + [r]]) > len(chosen):
            chosen.append(r)
    rhs = ca.DM.zeros(n, 1)
    rhs[0] = 1.0
    d = ca.solve(ca.vertcat(*[rows[r] for r in chosen]), rhs)
    d0 = np.array(ca.Function("d", [free, p], [d], {"allow_free": True})(
        rng.uniform(0.5, 1.5, free.numel()), p0), dtype=float).ravel()
    return d, d0, chosen


def _followers(ws: Workspace, final, owner, k: int, x: ca.SX, free: ca.SX, p: ca.SX,
               velocities: range, p0: list) -> list:
    """[(j, d_j)]: the generalized velocities x[j] that a reinit of x[k] by ``owner`` moves,
    by d_j times its jump, so that the states a Modelica tool keeps keep their values (see
    PhysicsBuilder.reinit): the velocities other components declare stateSelect always,
    then prefer (``ws.state_selects``: expressions linear in x[velocities]), then the
    generalized velocities themselves, each kept where independent of those before (rank
    at p0 and a generic point). None when x[k] is no generalized velocity or nothing
    declared is kept."""
    if k not in velocities or not ws.state_selects:
        return []
    w = x[list(velocities), :]
    kept = _kept_rows(ws, final, owner, w)
    if not kept:
        return []
    n, at = w.numel(), k - velocities.start
    d, d0, chosen = _jump(ca.SX(ca.DM.eye(n)[at, :]), kept, free, p, p0)
    if all(r == 0 or r > len(kept) for r in chosen):      # only coordinates: no change
        return []
    return [(velocities.start + j, d[j]) for j in range(n)
            if j != at and (abs(d0[j]) > 1e-12 or ca.depends_on(d[j], ca.vertcat(free, p)))]


def _combination_jumps(ws: Workspace, final, owner, v: ca.SX, x: ca.SX, free: ca.SX,
                       p: ca.SX, velocities: range, p0: list) -> list | None:
    """[(j, d_j)] for a reinit of a velocity v that is no state but linear in the
    generalized velocities w = x[velocities] (coefficients and offset of parameters: a
    clutch's flange on the ring of a planetary gear whose sun and carrier carry the
    coordinates): each x[j] jumps by d_j times the jump of v, the states a Modelica tool
    keeps kept as for a reinit of a state (``_followers``), v being the one that changes.
    None when v is not such a velocity."""
    w = x[list(velocities), :]
    if w.numel() == 0:
        return None
    J = ca.jacobian(v, w)
    if not J.nnz() or ca.depends_on(J, free) \
            or ca.depends_on(ca.substitute(v, w, ca.SX.zeros(w.shape)), free):
        return None
    d, d0, _ = _jump(J, _kept_rows(ws, final, owner, w), free, p, p0)
    return [(velocities.start + j, d[j]) for j in range(w.numel())
            if abs(d0[j]) > 1e-12 or ca.depends_on(d[j], ca.vertcat(free, p))]


def _check_declarations(ws: Workspace) -> None:
    """Every state has a derivative, every algebraic variable an equation."""
    for info in ws.states:
        if info.der is None:
            raise StructureError(f"{type(info.owner).__name__} '{info.owner.path}': state "
                                 f"'{info.sym.name()}' has no derivative (call e.derivative)")
    algebraics = [a for a in ws.algebraics if not has_network_ports(a.owner)]
    residuals = [r for o, r in ws.residuals if not has_network_ports(o)]
    if len(residuals) != len(algebraics):        # networks: checked by build_network
        raise StructureError(f"{len(algebraics)} algebraic variables but "
                             f"{len(residuals)} residual equations: "
                             f"{', '.join(a.sym.name() for a in algebraics) or 'none'}")


def _nominals(model, ws: Workspace, tree, final, w: ca.SX, free: ca.SX) -> list:
    """The nominal of each of w = [x; z] (numbers or expressions of parameters): 1, or the
    smallest n/|a| of the variables with a declared nominal n that are a·w_k + b (a, b of
    parameters: ``coinciding``); the nominals the components declare, replaced by the ones
    given with their ``nominal={...}`` keyword. See ``CompiledModel.nominals``."""
    declared = dict(ws.nominals)
    for c in ws.components:
        for name, value in c._nominal.items():
            declared[f"{c.path}.{name}" if c.path else name] = value
    if not declared:
        return [1.0] * w.numel()
    names, exprs, *_ = recorded_variables(ws, tree)
    where = {n: i for i, n in enumerate(names)}
    unknown = [n for n in declared if n not in where]
    if unknown:
        raise StructureError(f"nominal given for '{unknown[0]}', which is no variable of "
                             f"'{model.name or type(model).__name__}'"
                             f"{did_you_mean(unknown[0], names)}")
    rows = final(exprs[[where[n] for n in declared], 0])
    out = [None] * w.numel()
    for v, n in zip(ca.vertsplit(rows), declared.values()):
        hit = coinciding(v, w, free)
        if hit is not None:
            k, a = hit
            n = n / ca.fabs(a)
            out[k] = n if out[k] is None else ca.fmin(out[k], n)
    return [1.0 if v is None else v for v in out]


def _coordinate_units(tree) -> dict[str, str]:
    """Units of the coordinates and their rates, from their nodes' domains."""
    units = {k: u for c in tree.charts for k, u in c.units.items()}
    for n in tree.nodes:
        for k, i in enumerate(n.coordinate or []):
            units[tree.q_names[i]] = n.domain.potential_units[k]
            units[tree.qd_names[i]] = n.domain.velocity_units[k]
    return units


def _events(events: list, p: ca.SX) -> ca.Function:
    """Function p -> (first times, periods) of the declared time events (period 0: once)."""
    times = _stack([e[0] for e in events])
    periods = _stack([e[1] for e in events])
    f = ca.Function("events", [p], [times, periods], ["p"], ["times", "periods"],
                    {"allow_free": True})
    if f.has_free():
        raise StructureError(f"event times may depend on parameters only; these depend on "
                             f"other symbols: {f.get_free()[:5]}")
    return f


def _parameter_function(name: str, values: list, p: ca.SX, what: str) -> ca.Function:
    """Function p -> values (numbers, or expressions of parameters)."""
    v = _column(values)
    f = ca.Function(name, [p], [v], ["p"], [name], {"allow_free": True})
    if f.has_free():
        raise StructureError(f"{what} may depend on parameters only; these depend on "
                             f"other symbols: {f.get_free()[:5]}")
    return f
