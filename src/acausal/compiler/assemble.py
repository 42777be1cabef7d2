"""compile(): model → CompiledModel.

1. flatten; parameters become SX symbols; every component declares its structure;
2. kinematic graph and coordinates (kinematics.build_tree);
3. every component contributes its physics given the motion of its ports;
4. Lagrange's equations by algorithmic differentiation, for the coordinates q and the
   relaxations ε of the tree relations (whose reactions give the port flows):
       R = d/dt(∂T/∂q̇) − ∂T/∂q + ∂V/∂q − Q = 0,  Q = Σ J_portᵀ f_port;
5. signals, state derivatives and relaxations are substituted; the equations are solved for
   the accelerations (elementwise when the mass matrix is diagonal, else a symbolic solve),
   closed loops get multipliers (stabilized index-2 form: the constraints hold exactly),
   massless nodes become algebraic variables of a semi-explicit DAE.
"""
from __future__ import annotations

import gc

import casadi as ca

from ..core.component import Model
from ..core.parameter import Parameter
from ..errors import SingularModelError, StructureError
from .batch import run_physics
from .builders import StructureBuilder, Workspace
from .compiled import CompiledModel, Lagrange
from .flatten import flatten
from .kinematics import InternalNode, Node, build_tree
from .loops import analyse_loops
from .recursive import articulated_solve
from .symbolic import UnknownDerivative, der_with, substitute_all

_vc = ca.vertcat
_ACTIVE = Parameter(1.0, "1", "1: this loop constraint row is enforced; simulate() sets 0 for "
                              "rows redundant at the assembled configuration", nonnegative=True)


def compile(model: Model) -> CompiledModel:
    """Compile ``model`` into a CompiledModel."""
    gc_was_enabled = gc.isenabled()
    gc.disable()          # many small objects, no cycles worth collecting: 20 % of the time
    try:
        return _compile(model)
    finally:
        if gc_was_enabled:
            gc.enable()


def _compile(model: Model) -> CompiledModel:
    flat = flatten(model)
    ws = Workspace(t=ca.SX.sym("t"))
    ws.der_table["t"] = 1
    ws.source = flat.signal_source
    ws.components = flat.components
    params = []                                    # (name, default, Parameter, component)
    try:
        for c in flat.components:
            syms = {}
            for pname, par in c.parameters().items():
                value = c._values[pname]
                elements = []
                for k, ename in enumerate(par.element_names()):
                    s = ca.SX.sym(f"{c.path}.{ename}" if c.path else ename)
                    elements.append(s)
                    params.append((s, value if par.size is None else value[k], par, c))
                syms[pname] = elements[0] if par.size is None else _vc(*elements)
            c.__dict__["_symbols"] = syms
        for c in flat.components:
            c.structure(StructureBuilder(ws, c))
        nodes = [Node(i, list(g)) for i, g in enumerate(flat.groups)]
        for n in ws.internal_nodes:
            nodes.append(Node(len(nodes), [n]))
        for n in nodes:
            for p in n.ports:
                ws.node_of[p] = n
        for r in ws.relations:
            r.nodes = [ws.node_of[p] for p in r.ports]
        tree = build_tree(nodes, ws.relations, ws.der_table)
        run_physics(ws, flat.components)
    finally:
        for c in flat.components:
            c.__dict__.pop("_symbols", None)
    ws.p = _vc(*[s for s, *_ in params]) if params else ca.SX(0, 1)
    ws.p_default = [d for _, d, *_ in params]
    return _assemble(model, flat, ws, tree, params)


def _assemble(model, flat, ws: Workspace, tree, params) -> CompiledModel:
    t = ws.t
    nq = tree.q.numel()
    eps = _vc(*[f[1] for f in tree.fired]) if tree.fired else ca.SX(0, 1)
    epsd = _vc(*[f[2] for f in tree.fired]) if tree.fired else ca.SX(0, 1)
    epsdd = _vc(*[f[3] for f in tree.fired]) if tree.fired else ca.SX(0, 1)
    qa, qda = _vc(tree.q, eps), _vc(tree.qd, epsd)

    for info in ws.states:
        if info.der is None:
            raise StructureError(f"{type(info.owner).__name__} '{info.owner.path}': state "
                                 f"'{info.sym.name()}' has no derivative (call e.derivative)")
    if len(ws.residuals) != len(ws.algebraics):
        raise StructureError(f"{len(ws.algebraics)} algebraic variables but "
                             f"{len(ws.residuals)} residual equations: "
                             f"{', '.join(a.sym.name() for a in ws.algebraics) or 'none'}")

    # ---- Lagrange's equations for [q; ε] ---------------------------------------------
    T = ca.sum1(_vc(*ws.kinetic)) if ws.kinetic else ca.SX(0)
    V = ca.sum1(_vc(*ws.potential)) if ws.potential else ca.SX(0)
    R_T = der_with(ca.gradient(T, qda), ws.der_table) - ca.gradient(T, qa)   # inertia
    R_V = ca.gradient(V, qa)                                                 # conservative
    R_Q = ca.SX.zeros(qa.numel())                                            # −Q of flows
    if ws.flows:
        v = _vc(*[ws.node_of[p].vel for p, _ in ws.flows])
        f = _vc(*[fl for _, fl in ws.flows])                 # flow into the component
        R_Q = ca.jtimes(v, qda, f, True)                     # node force is −flow
    phi = tree.loop_residual
    phi_eps = ca.jacobian(phi, eps)

    # ---- signals, state derivatives, relaxations: substituted -------------------------
    resolve = _resolver(ws, eps, epsd, epsdd)
    pieces = [R_T, R_V, R_Q, phi, phi_eps,
              _vc(*[i.der for i in ws.states]) if ws.states else ca.SX(0, 1),
              _vc(*[r for _, r in ws.residuals]) if ws.residuals else ca.SX(0, 1),
              _vc(*[e for _, e in ws.outputs]) if ws.outputs else ca.SX(0, 1),
              _vc(*[fl for _, fl in ws.flows]) if ws.flows else ca.SX(0, 1)]
    R_T, R_V, R_Q, phi, phi_eps, zdot, g_alg, y_out, explicit = resolve(pieces)
    R = R_T + R_V + R_Q
    R_q, R_eps = R[:nq], R[nq:]

    cut = _vc(*ws.cut_flow_sym.values()) if ws.cut_flow_sym else ca.SX(0, 1)
    if ca.depends_on(_vc(R_q, phi), cut):
        raise StructureError("a measured cut force/torque (force or torque sensor) feeds back "
                             "into the forces of the model; this implicit loop is not supported "
                             "yet: measure the force elsewhere (e.g. a spring's f)")
    keep, row_names = analyse_loops(tree, phi, ws)
    bodies, T_other = [], None
    if ws.bodies:                  # planar rigid bodies, for the articulated-body recursion
        flat_b = resolve([_vc(*[_vc(pos, vel, m, I) for pos, vel, m, I in ws.bodies])])[0]
        bodies = [(b[0:3], b[3:6], b[6], b[7]) for b in ca.vertsplit(flat_b, 8)]
        T_other = resolve([ca.sum1(_vc(*ws.kinetic_other)) if ws.kinetic_other
                           else ca.SX(0)])[0]
    eq = _solve_motion(tree, R_q, phi[keep], t, ws, (bodies, T_other), resolve)
    lam = ca.SX.zeros(phi.numel())               # dropped (redundant) rows carry nothing
    lam[keep] = eq.lam
    lam_tree = -(R_eps + ca.mtimes(phi_eps.T, lam)) if eps.numel() else ca.SX(0, 1)
    sub_from = [tree.qdd] + eq.extra_from
    sub_to = [eq.qdd] + eq.extra_to

    def flows():
        return _port_flows(ws, tree, explicit, lam_tree, lam)

    cut_values = ca.SX(0, 1)
    if ws.cut_flow_sym:
        _, flow_of = flows()
        cut_values = _vc(*[flow_of[p] for p in ws.cut_flow_sym])
        if ca.depends_on(cut_values, cut):
            raise StructureError("force sensors measure each other in a loop; not supported")
        zdot, g_alg, y_out = ca.substitute([zdot, g_alg, y_out], [cut], [cut_values])
    zdot, g_alg, y_out = ca.substitute([zdot, g_alg, y_out], sub_from, sub_to)

    def recorded():
        """Every potential, velocity, flow, state, variable and signal, by name (built on
        first use: large models need not pay for it to be simulated or exported)."""
        names, exprs, units = _recorded(flat, ws, tree)
        fl, _ = flows()
        names += [n for n, _ in fl]
        units += _flow_units(fl)
        exprs = resolve([_vc(exprs, *[e for _, e in fl])])[0]
        exprs = ca.substitute([ca.substitute(exprs, cut, cut_values)], sub_from, sub_to)[0]
        return names, exprs, units

    # ---- states, algebraic variables ----------------------------------------------------
    for k, s in enumerate(ca.vertsplit(eq.active)):      # switches of the loop rows
        params.append((s, 1.0, _ACTIVE, None))
    z_states = _vc(*[i.sym for i in ws.states]) if ws.states else ca.SX(0, 1)
    z_alg = _vc(*[a.sym for a in ws.algebraics]) if ws.algebraics else ca.SX(0, 1)
    u = _vc(*[s for _, s in ws.inputs]) if ws.inputs else ca.SX(0, 1)
    p = _vc(*[s for s, *_ in params]) if params else ca.SX(0, 1)
    x = _vc(eq.q_diff, eq.qd_diff, z_states)
    if x.numel() == 0 and not ca.depends_on(recorded()[1], _vc(t, u)):
        raise StructureError(f"model '{model.name or type(model).__name__}' has no dynamics: no "
                             f"part can move (every node is fixed or prescribed) and no component "
                             f"has states, and no motion is prescribed; add a mass or inertia "
                             f"that is free to move")
    ode = _vc(eq.q_diff_dot, eq.qdd_diff, zdot)
    alg_vars = _vc(eq.alg_vars, z_alg)
    alg = _vc(eq.alg_res, g_alg)
    resolve.check([ode, alg, y_out])
    check = ca.Function("check", [t, x, alg_vars, p, u], [ode, alg, y_out],
                        {"allow_free": True})
    if check.has_free():
        raise StructureError(f"internal: unresolved symbols {check.get_free()[:5]} "
                             f"(please report)")

    return CompiledModel(
        name=model.name or type(model).__name__, t=t, x=x, z=alg_vars, p=p, u=u,
        ode=ode, alg=alg,
        x_names=[s.name() for s in ca.vertsplit(x)], z_names=[s.name() for s in ca.vertsplit(alg_vars)],
        start=_start_values(eq.x_start + [i.start for i in ws.states]
                            + eq.z_start + [a.start for a in ws.algebraics], p),
        params=[(s.name(), d, par.unit, par.description, par) for s, d, par, _ in params],
        inputs=[(c.path, c.start, c.unit, c.description) for c, _ in ws.inputs],
        outputs=[(c.path, c.unit, c.description) for c, _ in ws.outputs], y=y_out,
        recorder=recorded, events=_events(ws.events, p),
        loop_rows=[row_names[i] for i in keep],
        loop_rows_dropped=[row_names[i] for i in range(phi.numel()) if i not in keep],
        lagrange=Lagrange(tree, R_T[:nq], R_V[:nq], R_Q[:nq], phi[keep], t, p, u,
                                [c.path for c, _ in ws.inputs], z_states),
        coordinates=tree.q_names,
        method=eq.method,
    )


class _Resolver:
    """Substitutes signal placeholders (and their rates), state-derivative placeholders and
    the relaxations ε (by zero) in any expression, with values resolved once."""

    def __init__(self, syms, vals, zeros_for, failed):
        self.syms, self.failed = syms, failed
        self.sv = _vc(*syms) if syms else ca.SX(0, 1)
        self.vals = _vc(*vals) if vals else ca.SX(0, 1)
        self.zeros_for = zeros_for

    def __call__(self, pieces: list) -> list:
        if self.syms:
            pieces = ca.substitute(pieces, [self.sv], [self.vals])
        z = [ca.SX.zeros(v.numel()) for v in self.zeros_for]
        pieces = ca.substitute(pieces, self.zeros_for, z)
        self.check(pieces)
        return pieces

    def check(self, pieces):
        for sym, err in self.failed:
            if any(ca.depends_on(x, sym) for x in pieces):
                raise err


def _resolver(ws: Workspace, eps, epsd, epsdd) -> _Resolver:
    missing = [o for o in ws.signal_sym if o not in ws.signal_expr]
    if missing:
        o = missing[0]
        raise StructureError(f"{type(o.owner).__name__} '{o.owner.path}' never sets its output "
                             f"'{o.path}' (call e.output in physics)")
    syms, vals = [], []
    for o, s in ws.signal_sym.items():
        syms.append(s)
        vals.append(ws.signal_expr[o])
    for info in ws.states:
        if info.placeholder is not None:
            syms.append(info.placeholder)
            vals.append(info.der)
    vals = substitute_all(vals, syms, vals) if syms else vals
    # rates of signals (prescribed motion): d/dt of the resolved signal expressions
    failed = []
    by_name = {s.name(): v for s, v in zip(syms, vals)}
    for name in list(ws.der_table):
        if not name.startswith("sig:"):
            continue
        level, value = ws.der_table[name], by_name[name]
        while level is not None and level.name().startswith("der("):
            try:
                value = resolve_once(der_with(value, ws.der_table), syms, vals)
            except UnknownDerivative as e:
                failed.append((level, e))
                break
            syms.append(level)
            vals.append(value)
            level = ws.der_table.get(level.name())
    return _Resolver(syms, vals, [eps, epsd, epsdd], failed)


def resolve_once(ex, syms, vals):
    return ca.substitute([ex], [_vc(*syms)], [_vc(*vals)])[0] if syms else ex


class _Motion:
    """Accelerations solved: the differential/algebraic split of the mechanical states."""


def _solve_motion(tree, R_q, phi, t, ws, bodies, resolve) -> _Motion:
    nq = tree.q.numel()
    q, qd, qdd = tree.q, tree.qd, tree.qdd
    R0 = ca.substitute(R_q, qdd, ca.SX.zeros(nq))
    out = _Motion()
    out.R0 = R0
    out.method = "diagonal mass matrix"
    out.extra_from, out.extra_to = [], []
    sp = ca.jacobian_sparsity(R_q, qdd)           # the mass matrix's pattern, without it
    row_nnz = [0] * nq
    for r in sp.get_triplet()[0]:
        row_nnz[r] += 1
    massive = [k for k in range(nq) if row_nnz[k] > 0]
    massless = [k for k in range(nq) if row_nnz[k] == 0]
    nc = phi.numel()
    probe = ca.SX.sym("probe", nq)
    M_times = ca.jtimes(R_q, qdd, probe)           # M·probe in O(N)
    if ca.depends_on(M_times, qdd):
        raise SingularModelError("the equations of motion are not linear in the accelerations "
                                 "(a force depends nonlinearly on an acceleration)")
    idx = lambda v, ks: v[ks] if ks else ca.SX(0, 1)
    qdM = idx(qd, massive)
    diagonal = all(i == j for i, j in zip(*sp.get_triplet()))
    qdd_M = None
    if not nc and not massless and not diagonal and nq > 2:
        # a planar tree: the O(N) articulated-body recursion, if the model fits it
        qdd_M = articulated_solve(q, qd, *bodies, -R0, M_times, probe, ws.p, ws.p_default)
    A = None if qdd_M is not None else ca.jacobian(R_q, qdd)
    A_MM = A[massive, massive] if A is not None and massive else ca.SX(0, 0)
    if nc:
        if massless:
            raise StructureError(
                "a closed kinematic loop together with massless nodes "
                f"({', '.join(tree.q_names[k] for k in massless)}) is not supported yet; give "
                "those nodes a mass")
        # accelerations and multipliers from [M Φ_qᵀ; Φ_q 0][q̈; λ] = [−R0; −γ], γ = Φ̈ at
        # q̈ = 0; the positions and velocities are then held on Φ = 0 and Φ̇ = 0 exactly (to
        # the solver's Newton tolerance) by the stabilized index-2 form of Gear, Gupta and
        # Leimkuhler: q̇ = q̇_state + Φ_qᵀμ, v̇ = q̈ + Φ_qᵀν, 0 = Φ, 0 = Φ̇, with μ = ν = 0 on the
        # exact solution. Unlike Baumgarte's method this leaves no drift to tune away, and
        # unlike coordinate partitioning it needs no choice of independent coordinates.
        # Rows found redundant at the assembled initial configuration are switched off by
        # their entry of ``active`` (0): then λ, μ, ν of that row are 0 and its equation drops.
        phi_q = ca.jacobian(phi, q)
        # (the rates of prescribed motion in Φ bring back signal placeholders: resolved)
        phid = der_with(phi, ws.der_table)
        gamma = ca.substitute(der_with(phid, ws.der_table), qdd, ca.SX.zeros(nq))
        phid, gamma = resolve([phid, gamma])
        act = ca.SX.sym("loops.active", nc)
        on, off = ca.diag(act), ca.diag(1 - act)
        KKT = ca.blockcat([[A_MM, ca.mtimes(phi_q.T, on)], [ca.mtimes(on, phi_q), off]])
        sol = ca.solve(KKT, _vc(-R0, -act * gamma))
        qdd_sol, out.lam = sol[:nq], sol[nq:]
        mu, nu = ca.SX.sym("loops.mu", nc), ca.SX.sym("loops.nu", nc)
        out.ggl = (mu, nu, ca.mtimes(phi_q.T, act * mu), ca.mtimes(phi_q.T, act * nu),
                   act * phi + (1 - act) * mu, act * phid + (1 - act) * nu)
        out.active = act
        out.method = "constrained (KKT) solve"
    else:
        out.lam = ca.SX(0, 1)
        out.active = ca.SX(0, 1)
        R0M = idx(R0, massive)
        if qdd_M is not None:
            out.method = "articulated-body recursion"
        elif diagonal:
            qdd_M = -R0M / ca.diag(A_MM)
        else:
            out.method = "dense solve"
            qdd_M = ca.solve(A_MM, -R0M)
        qdd_sol = ca.SX.zeros(nq)
        qdd_sol[massive] = qdd_M
    # massless coordinates: algebraic velocity (a damper holds them) or position (springs only)
    vel_alg = [k for k in massless if ca.depends_on(R0[k], qd[k])]
    pos_alg = [k for k in massless if k not in vel_alg]
    out.q_diff = _vc(idx(q, massive), idx(q, vel_alg)) if nq else ca.SX(0, 1)
    out.q_diff_dot = _vc(idx(qd, massive), idx(qd, vel_alg)) if nq else ca.SX(0, 1)
    out.qd_diff = qdM
    out.qdd_diff = idx(qdd_sol, massive) if massive else ca.SX(0, 1)
    out.alg_vars = _vc(idx(qd, vel_alg), idx(q, pos_alg))
    out.alg_res = _vc(idx(R0, vel_alg), idx(R0, pos_alg))
    if nc:
        mu, nu, dq, dv, phi_, phid_ = out.ggl
        out.q_diff_dot = out.q_diff_dot + dq
        out.qdd_diff = out.qdd_diff + dv
        out.alg_vars = _vc(out.alg_vars, mu, nu)
        out.alg_res = _vc(out.alg_res, phi_, phid_)
    if massless:
        out.alg_res = ca.substitute(out.alg_res, qdd, qdd_sol)
    if pos_alg:
        # velocities (and accelerations) of spring-only massless nodes follow from d/dt R = 0
        qdP, qddP = idx(qd, pos_alg), idx(qdd, pos_alg)
        RP = idx(R0, pos_alg)
        dR = der_with(RP, ws.der_table)
        J = ca.jacobian(dR, qdP)
        qdP_sol = ca.solve(J, -ca.substitute(dR, qdP, ca.SX.zeros(len(pos_alg))))
        ddR = der_with(dR, ws.der_table)
        J2 = ca.jacobian(ddR, qddP)
        qddP_sol = ca.solve(J2, -ca.substitute(ddR, qddP, ca.SX.zeros(len(pos_alg))))
        out.extra_from, out.extra_to = [qdP], [qdP_sol]
        qdd_sol[pos_alg] = qddP_sol
        if ca.depends_on(_vc(out.qdd_diff, out.alg_res), qdP):
            out.qdd_diff, out.alg_res = ca.substitute([out.qdd_diff, out.alg_res], [qdP], [qdP_sol])
    out.qdd = qdd_sol
    out.x_start = [0.0] * (len(massive) + len(vel_alg)) + [0.0] * len(massive)
    out.z_start = [0.0] * (len(vel_alg) + len(pos_alg) + 2 * nc)
    out.massless = [tree.q_names[k] for k in massless]
    return out


def _events(events: list, p: ca.SX) -> ca.Function:
    """Function p -> (first times, periods) of the declared time events (period 0: once)."""
    times = _vc(*[e[0] for e in events]) if events else ca.SX(0, 1)
    periods = _vc(*[e[1] for e in events]) if events else ca.SX(0, 1)
    f = ca.Function("events", [p], [times, periods], ["p"], ["times", "periods"],
                    {"allow_free": True})
    if f.has_free():
        raise StructureError(f"event times may depend on parameters only; these depend on "
                             f"other symbols: {f.get_free()[:5]}")
    return f


def _start_values(values: list, p: ca.SX) -> ca.Function:
    """Function p -> start values of [x; z] (numbers, or expressions of parameters)."""
    v = _vc(*[ca.SX(x) for x in values]) if values else ca.SX(0, 1)
    f = ca.Function("start", [p], [v], ["p"], ["start"], {"allow_free": True})
    if f.has_free():
        raise StructureError(f"start values may depend on parameters only; these depend on "
                             f"other symbols: {f.get_free()[:5]}")
    return f


def _port_flows(ws, tree, explicit, lam_tree, lam_loop):
    """Flow of every port of every component: explicit ones plus relation reactions."""
    total: dict = {}
    order = []

    def add(p, v):
        if p not in total:
            total[p] = v
            order.append(p)
        else:
            total[p] = total[p] + v

    for (p, _), v in zip(ws.flows, _split(explicit, [p.domain.dim for p, _ in ws.flows])):
        add(p, v)
    extra = {}
    for (r, dim, flows), lam in zip(tree.loops, _split(lam_loop, [b[1] for b in tree.loops])):
        if flows is None:
            extra[id(r)] = lam                 # extra rows of a relation that also fired
            continue
        for p, v in flows(lam):
            add(p, v)
    for (r, e, *_), lam in zip(tree.fired, _split(lam_tree, [f[1].numel() for f in tree.fired])):
        for p, v in (r.flows(lam) if r.linear else r.flows_fired(lam, extra.get(id(r)))):
            add(p, v)
    out = []
    for p in order:
        if isinstance(p, InternalNode):
            continue
        for j, fname in enumerate(p.domain.flows):
            out.append((f"{p.path}.{fname}", total[p][j] if p.domain.dim > 1 else total[p]))
    flow_of = {p: total.get(p, ca.SX.zeros(p.domain.dim)) for p in ws.cut_flow_sym}
    return out, flow_of


def _split(v: ca.SX, dims: list[int]) -> list[ca.SX]:
    """Consecutive pieces of v with the given sizes (one call: slicing costs per piece)."""
    if all(d == 1 for d in dims):
        return ca.vertsplit(v) if dims else []
    offsets = [0]
    for d in dims:
        offsets.append(offsets[-1] + d)
    return ca.vertsplit(v, offsets)


def _flow_units(flows):
    units = {"f": "N", "tau": "N.m", "fx": "N", "fy": "N", "t": "N.m"}
    return [units.get(n.rsplit(".", 1)[1], "") for n, _ in flows]


def _recorded(flat, ws, tree):
    """Names and expressions of every potential, velocity, state and signal."""
    names, exprs, units = [], [], []
    seen = set()

    def rec(name, ex, unit=""):
        if name not in seen:
            seen.add(name)
            names.append(name)
            exprs.append(ex)
            units.append(unit)

    for n in tree.nodes:
        for p in n.ports:
            dom = p.domain
            if isinstance(p, InternalNode):
                rec(p.path, n.pos, dom.potential_units[0])
                base = p.owner.path
                if p.velocity:
                    rec(f"{base}.{p.velocity}" if base else p.velocity, n.vel, dom.velocity_units[0])
                if p.acceleration:
                    rec(f"{base}.{p.acceleration}" if base else p.acceleration, n.acc,
                        dom.velocity_units[0] + "2")
                continue
            for j, pot in enumerate(dom.potentials):
                rec(f"{p.path}.{pot}", n.pos[j], dom.potential_units[j])
    for info in ws.states:
        rec(info.sym.name(), info.sym, info.unit)
    for a in ws.algebraics:
        rec(a.sym.name(), a.sym, a.unit)
    for name, ex, unit, _ in ws.variables:
        rec(name, ex, unit)
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
                   else ca.SX(0, 1)), units
