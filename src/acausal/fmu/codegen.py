"""CasADi functions of a compiled model for the native FMU, generated as C.

Every function takes the same five dense arguments (t, x, z, u, p), the order of every
Function of the compiled model:

- ``x`` the FMU's continuous states (``compiled.x``);
- ``z`` the algebraic variables the FMU solves by Newton's method (massless nodes and the
  model's own algebraic variables: every entry of ``compiled.z`` but the loop multipliers);
- the loop multipliers μ, ν (``compiled.loop_multipliers``) of the stabilized (GGL) form are zero on
  the exact solution: they are replaced by 0 everywhere, and their residual rows become the
  constraint vector H = [Φ; Φ̇] that the C runtime keeps at zero by projection.

Functions (outputs dense, column-major):

    ac_ode  -> ẋ                      ac_out -> y           ac_rec -> recorded rows
    ac_alg  -> (g, ∂g/∂z)             Newton for z (if any)
    ac_jac  -> (∂F/∂w, ∂F/∂z, ∂g/∂w, ∂g/∂z),  F = [ẋ; y], w = [x; u; t]
    ac_con  -> (H, ∂H/∂x)             loop constraints (if any)
    ac_phiq -> Φ_q                    their Jacobian in the coordinates, every row enforced:
                                      the runtime picks the rows to enforce from it
    ac_start(p) -> start values of [x; z];  ac_events(p) -> [first times; periods]
    ac_clocks(p) -> [first times; periods] of the sample triggers (``clock_times``): their
                                      instants are among ac_events' (reported as time events
                                      there); this tells which trigger ticks at one
    ac_ind  -> g                      the state events' indicators (``indicator_function``)
    ac_upd  -> (modes, reinit)        the modes' new values from their present ones in p and
                                      the reinits' values (``event_update_function``)
    ac_init -> (E, ∂E/∂x, ∂E/∂z)      the components' initial equations E = 0
                                      (``initial_equations``), held at initialization with
                                      the loop constraints
    ac_term -> conditions             the termination conditions (``state_events.terminate``):
                                      > 0.5 ends the run at an event
    ac_assert -> held                 the components' assertions (``assertions``): < 0.5
                                      fails the run with the component's message, checked
                                      after initialization, events and every step

The event logic over these two (which indicator crossed, which reinits apply, the event
iteration) is the C runtime's events.c, after acausal.simulation.events; the tables it
needs (where the modes are in p, the reinits' states, indicators and directions, owners)
are ``event_tables``.
"""
from __future__ import annotations

from pathlib import Path

import casadi as ca
import numpy as np

from .. import toolchain
from ..errors import FmuExportError
from ..simulation.initialization import model_equations

SMALL = 2000       # instructions: a generated function below shares a C file with the others


class ModelFunctions:
    """The CasADi Functions above for ``compiled``, with their sizes and sparsity."""

    def __init__(self, compiled):
        c = self.compiled = compiled
        t, x, p, u = c.t, c.x, c.p, c.u
        zall = ca.vertsplit(c.z) if c.z.numel() else []
        loop = sorted(c.loop_multipliers)
        free = [i for i in range(len(zall)) if i not in loop]
        self.z_names = [c.z_names[i] for i in free]
        z = ca.vertcat(*[zall[i] for i in free]) if free else ca.SX(0, 1)
        zl = ca.vertcat(*[zall[i] for i in loop]) if loop else ca.SX(0, 1)
        alg = ca.vertsplit(c.alg) if c.alg.numel() else []

        def nol(ex):           # loop multipliers are 0 on the exact solution
            return ca.substitute(ex, zl, ca.SX.zeros(zl.numel())) if loop else ex

        ode = nol(c.ode)
        g = nol(ca.vertcat(*[alg[i] for i in free])) if free else ca.SX(0, 1)
        H = nol(ca.vertcat(*[alg[i] for i in loop])) if loop else ca.SX(0, 1)
        y = nol(c.y) if c.y.numel() else ca.SX(0, 1)
        rf = c.recorded_function
        rec = nol(rf(t, x, c.z, u, p)) if rf.size1_out(0) else ca.SX(0, 1)
        self.nx, self.nz, self.np, self.nu = x.numel(), z.numel(), p.numel(), u.numel()
        self.ny, self.nrec, self.nh = y.numel(), rec.numel(), H.numel()
        phi_q = nol(c.lagrange.phi_q) if loop else ca.SX(0, 1)
        self.nphi, self.nq = phi_q.shape if loop else (0, 0)
        # the rows of H (μ's then ν's: Φ then Φ̇), named as simulate() names them
        self.h_names = model_equations(c)[1][:self.nh]
        ev_t, ev_p = c.events(p)
        self.nev = ev_t.numel()
        se = c.state_events
        ind = nol(se.indicator) if se.indicator.numel() else ca.SX(0, 1)
        upd = [nol(v) if v.numel() else ca.SX(0, 1) for v in (se.mode_update, se.reinit_values)]
        self.ng, self.nmode, self.nreinit = ind.numel(), len(c.mode_params), len(se.reinits)
        self.nclock = len(se.clocks)
        clocks = ca.vertcat(*se.clock_times(p)) if self.nclock else ca.SX(0, 1)
        init = nol(c.initial_equations) if c.initial_equations.numel() else ca.SX(0, 1)
        term = nol(se.terminate) if se.terminate.numel() else ca.SX(0, 1)
        asserted = nol(c.assertions) if c.assertions.numel() else ca.SX(0, 1)
        self.nie, self.nterm, self.nassert = init.numel(), term.numel(), asserted.numel()

        s0 = ca.vertsplit(c.start(p))          # start values of [x; z]: x and the free z
        start = ca.vertcat(*(s0[:self.nx] + [s0[self.nx + i] for i in free]))
        args, names = [t, x, z, u, p], ["t", "x", "z", "u", "p"]
        d = ca.densify
        w = ca.vertcat(x, u, t)
        F = ca.vertcat(ode, y)
        fs = {
            "ac_ode": ca.Function("ac_ode", args, [d(ode)], names, ["xdot"]),
            "ac_out": ca.Function("ac_out", args, [d(y)], names, ["y"]),
            "ac_rec": ca.Function("ac_rec", args, [d(rec)], names, ["rec"]),
            "ac_jac": _jacobian(args, names, F, g, w, z),
            "ac_alg": ca.Function("ac_alg", args, [d(g), d(ca.jacobian(g, z))], names,
                                  ["g", "g_z"]),
            "ac_con": ca.Function("ac_con", args, [d(H), d(ca.jacobian(H, x))], names,
                                  ["H", "H_x"]),
            "ac_phiq": ca.Function("ac_phiq", args, [d(phi_q)], names, ["phi_q"]),
            "ac_start": ca.Function("ac_start", [p], [d(start)], ["p"], ["x0"]),
            "ac_events": ca.Function("ac_events", [p], [d(ca.vertcat(ev_t, ev_p))], ["p"],
                                     ["ev"]),
            "ac_clocks": ca.Function("ac_clocks", [p], [d(clocks)], ["p"], ["clocks"]),
            "ac_ind": ca.Function("ac_ind", args, [d(ind)], names, ["g"]),
            "ac_upd": ca.Function("ac_upd", args, [d(upd[0]), d(upd[1])], names,
                                  ["modes", "reinit"]),
            "ac_init": ca.Function("ac_init", args, [d(init), d(ca.jacobian(init, x)),
                                                     d(ca.jacobian(init, z))], names,
                                   ["E", "E_x", "E_z"]),
            "ac_term": ca.Function("ac_term", args, [d(term)], names, ["terminate"]),
            "ac_assert": ca.Function("ac_assert", args, [d(asserted)], names, ["held"]),
        }
        self.functions = fs
        # structural dependencies of F = [ẋ; y] on w = [x; u; t] (through z too), and on p
        Fw = np.array(ca.DM(ca.jacobian_sparsity(F, w), 1)) != 0 if F.numel() and w.numel() \
            else np.zeros((F.numel(), w.numel()), bool)
        Fp = np.array(ca.DM(ca.jacobian_sparsity(F, p), 1)) != 0 if F.numel() and p.numel() \
            else np.zeros((F.numel(), p.numel()), bool)
        if self.nz:
            Fz = np.array(ca.DM(ca.jacobian_sparsity(F, z), 1)) != 0
            gw = np.array(ca.DM(ca.jacobian_sparsity(g, w), 1)).any(axis=0) != 0
            gp = np.array(ca.DM(ca.jacobian_sparsity(g, p), 1)).any(axis=0) != 0 \
                if p.numel() else np.zeros(0, bool)
            via = Fz.any(axis=1)
            Fw = Fw | np.outer(via, gw)
            Fp = Fp | np.outer(via, gp)
        self.dep_w = Fw.reshape(F.numel(), w.numel())     # rows ẋ then y; cols x, u, t
        self.dep_p = Fp.reshape(F.numel(), p.numel())

    def event_tables(self) -> dict:
        """The state events' tables for the C runtime: positions in p of the modes, their
        names, owners and allowed values, whether each is an Integer/Boolean mode (rounded by
        the event iteration) or a discrete Real variable (not); the sample triggers' positions
        among the modes and whether each is true at the start too; each indicator's name and
        owner; each reinit's state (index in x), indicator and direction."""
        c = self.compiled
        real = set(c.state_events.real_modes)
        allowed = [c.state_events.mode_values.get(v.name) for v in c.modes]
        starts = np.cumsum([0] + [len(a or ()) for a in allowed]).tolist()
        return {"AC_MODE_P": ("int", c.mode_params),
                "AC_MODE_NAMES": ("char *", [v.name for v in c.modes]),
                "AC_MODE_OWNER": ("char *", [v.component for v in c.modes]),
                # the values each mode may take: AC_MODE_VALUES[AC_MODE_FIRST[k] ...
                # AC_MODE_FIRST[k + 1]) (none: any value)
                "AC_MODE_FIRST": ("int", starts),
                "AC_MODE_VALUES": ("int", [int(v) for a in allowed for v in (a or ())]),
                "AC_MODE_INT": ("int", [int(v.name not in real) for v in c.modes]),
                "AC_CLOCK_MODE": ("int", list(c.state_events.clocks)),
                "AC_CLOCK_INITIAL": ("int", [int(b) for b in c.state_events.clock_initial]),
                "AC_G_NAMES": ("char *", [v.name for v in c.state_events.indicators]),
                "AC_G_OWNER": ("char *", [v.component for v in c.state_events.indicators]),
                "AC_RE_STATE": ("int", [r.state for r in c.state_events.reinits]),
                "AC_RE_IND": ("int", [r.indicator for r in c.state_events.reinits]),
                "AC_RE_DIR": ("int", [r.direction for r in c.state_events.reinits]),
                "AC_IE_NAMES": ("char *", list(c.initial_labels)),
                "AC_TERM_OWNER": ("char *", [o for o, _ in c.state_events.terminations]),
                "AC_TERM_TEXT": ("char *", [t for _, t in c.state_events.terminations]),
                "AC_ASSERT_OWNER": ("char *", [o for o, _ in c.assertion_texts]),
                "AC_ASSERT_TEXT": ("char *", [t for _, t in c.assertion_texts])}

    def sizes(self) -> dict:
        """Work array sizes over all functions."""
        fs = self.functions.values()
        return {"arg": max(f.sz_arg() for f in fs), "res": max(f.sz_res() for f in fs),
                "iw": max(f.sz_iw() for f in fs), "w": max(toolchain.work_size(f) for f in fs)}

    def generate(self, directory) -> list[str]:
        """Write the C of the functions into ``directory``: each large one (``SMALL``
        instructions or more, or an MX Function) in a file of its own, so that the files
        compile side by side (``toolchain.build_shared_library``), the small ones together
        in ``ac_small.c`` (a compiler process costs ~50 ms); and the header
        ``model_functions.h`` the runtime includes. Returns the C files' names."""
        directory = Path(directory)
        small = [n for n, f in self.functions.items()
                 if f.is_a("SXFunction") and f.n_instructions() < SMALL]
        groups = [(n, [n]) for n in self.functions if n not in small]
        groups += [("ac_small", small)] if small else []
        for file, names in groups:
            gen = ca.CodeGenerator(f"{file}.c", {"with_header": True})
            for n in names:
                gen.add(self.functions[n])
            gen.generate(str(directory) + "/")
            path = directory / f"{file}.c"
            path.write_text(toolchain.plain_access(
                path.read_text(), [self.functions[n] for n in names], FmuExportError))
        (directory / "model_functions.h").write_text(
            "".join(f'#include "{file}.h"\n' for file, _ in groups))
        return [f"{file}.c" for file, _ in groups]


def _jacobian(args: list, names: list[str], F: ca.SX, g: ca.SX, w: ca.SX, z: ca.SX):
    """``ac_jac``: the dense Jacobians (∂F/∂w, ∂F/∂z, ∂g/∂w, ∂g/∂z), symbolic while their
    code is cheap to compile (``toolchain.jacobian_fits``); else column by column from the
    forward derivative of (F, g), mapped over the unit seeds (a 6-axis arm's 3-D
    recursion: 53 000 instructions and 20-30 s of gcc for the symbolic ones)."""
    outs = ["F_w", "F_z", "g_w", "g_z"]
    jac = ca.Function("ac_jac", args, [ca.densify(ca.jacobian(e, v))
                                       for e, v in ((F, w), (F, z), (g, w), (g, z))],
                      names, outs)
    h = ca.Function("F_g", args, [F, g], names, ["F", "g"])
    if toolchain.jacobian_fits(jac, h):
        return jac
    forward = h.forward(1)
    mx = [ca.MX.sym(n, a.sparsity()) for n, a in zip(names, args)]
    value = h(*mx)

    def columns(v: ca.SX) -> list:
        """(∂F/∂v, ∂g/∂v): the forward derivative at the unit seeds of v, a vector of the
        arguments (the seed of each argument: the constant ∂v/∂argᵀ)."""
        if not v.numel():
            return [ca.MX(F.numel(), 0), ca.MX(g.numel(), 0)]
        seeds = [ca.DM(ca.evalf(ca.jacobian(v, a))).T for a in args]
        return forward.map(v.numel())(*mx, *value, *seeds)

    (F_w, g_w), (F_z, g_z) = columns(w), columns(z)
    return ca.Function("ac_jac", mx, [F_w, F_z, g_w, g_z], names, outs)
