"""The compiled model as an optimal control problem sees it: names, kinds and symbols."""
from __future__ import annotations

from collections.abc import Mapping

import casadi as ca
import numpy as np

from ..compiler import recompile
from ..compiler.lean import lean
from ..errors import OCPError, ParameterError, VariableNameError, did_you_mean
from ..numerics import has_nan_constant

#: the OCP's word for each kind of name the compiled model resolves
_KINDS = {"time": "time", "state": "state", "input": "control", "parameter": "parameter",
          "algebraic": "variable", "recorded": "variable"}


class ModelView:
    """Names of a compiled model sorted by kind, with their CasADi expressions.

    Kinds: 'state' (``x_names``), 'control' (the model's Inputs, ``input_names``),
    'parameter' (``param_names``), 'time', and 'variable' (any other recorded variable,
    ``compiled.expression``). Parameter values are the defaults with ``params`` overrides;
    those named in ``free`` become decision variables (their value is then the guess).
    """

    def __init__(self, compiled, params: dict | None = None, free=()):
        if compiled.has_events:
            raise OCPError(f"model '{compiled.name}' has state events or modes (of "
                           f"{', '.join(event_owners(compiled))}); the transcription would "
                           f"ignore their events: transcribe its smooth form "
                           f"(OCP(..., smooth=True), the default)")
        self.compiled = compiled
        self.p_values = compiled.param_vector(params)
        self.free = list(free)
        for name in self.free:
            if name not in compiled.param_names:
                raise ParameterError(f"model '{compiled.name}' has no parameter '{name}' to "
                                     f"estimate{did_you_mean(name, compiled.param_names)}")
        if len(set(self.free)) != len(self.free):
            raise OCPError(f"free parameters listed twice: {self.free}")
        self.free_index = [compiled.param_names.index(n) for n in self.free]
        # fixed parameters as numbers (folded into the arithmetic, as in simulate), free
        # ones as the symbols they are
        fold = [ca.SX(v) for v in self.p_values]
        for i in self.free_index:
            fold[i] = compiled.p[i]
        self._fold = ca.vertcat(*fold) if fold else ca.SX(0, 1)
        self.f = self.function([compiled.ode, compiled.alg], "f", ["xdot", "alg"])
        start = np.asarray(compiled.start(self.p_values), dtype=float).ravel()
        self.x_start, self.z_start = start[:self.nx], start[self.nx:]
        self.u_start = compiled.input_start
        self._split_algebraic()

    # ---- sizes and names --------------------------------------------------------------------
    @property
    def nx(self) -> int:
        return self.compiled.x.numel()

    @property
    def nz(self) -> int:
        return self.compiled.z.numel()

    @property
    def nu(self) -> int:
        return self.compiled.u.numel()

    def _resolve(self, name: str):
        if not isinstance(name, str):
            raise OCPError(f"variable names are strings, got {name!r}")
        try:
            return self.compiled.variable(name)
        except VariableNameError as e:
            raise OCPError(str(e)) from None

    def kind(self, name: str) -> str:
        """'state', 'control', 'parameter', 'time' or 'variable'; OCPError if unknown."""
        return _KINDS[self._resolve(name).kind]

    def index(self, name: str) -> int:
        """Row of a state, control or parameter in x, u or p."""
        return self._resolve(name).index

    # ---- symbols ------------------------------------------------------------------------------
    def sym(self, name: str) -> ca.SX:
        """The SX expression of ``name`` in the model's symbols t, x, z, u, p."""
        return self._resolve(name).expression

    def names(self) -> list[str]:
        """Every name the model resolves: time, parameters, and every recorded variable."""
        return ["time"] + self.compiled.param_names + self.compiled.recorded_names

    def expression(self, expr) -> ca.SX:
        """A scalar SX in the model's symbols from an SX, a name, or a callable receiving
        a mapping name -> SX (``lambda v: v["F"]**2``)."""
        if isinstance(expr, str):
            expr = self.sym(expr)
        elif callable(expr):
            expr = expr(Symbols(self))
        if isinstance(expr, (int, float)):
            expr = ca.SX(expr)
        if not isinstance(expr, ca.SX) or expr.numel() != 1:
            raise OCPError("an integrand must be a scalar CasADi SX expression of the model's "
                           "symbols, a variable name, or a callable v -> v['name'] ... "
                           f"(got {type(expr).__name__})")
        if has_nan_constant(expr):
            raise OCPError("an integrand turns the model's CasADi symbols into NaN (Python's "
                           "float() or the math module on a symbol); write it with casadi "
                           "operations or numpy ufuncs (np.sin, casadi.if_else)")
        return expr

    def function(self, exprs: list, name: str = "g", outputs=("g",)) -> ca.Function:
        """Function (t, x, z, u, p) -> ``exprs`` (stacked into one output unless ``outputs``
        names each), the argument order of every Function of the compiled model; the fixed
        parameters' values are folded in (only the free entries of p are read) and the
        result simplified (``compiler.lean``: like terms collected, cancelling ones dropped,
        subexpressions shared)."""
        c = self.compiled
        outs = [ca.vertcat(*exprs)] if len(outputs) == 1 else list(exprs)
        return c.function(name, lean(ca.substitute(outs, [c.p], [self._fold])), outputs)

    # ---- algebraic structure ------------------------------------------------------------------
    def _split_algebraic(self):
        """Which algebraic variables the algebraic equations determine (``z_alg``: index 1,
        e.g. massless nodes) and which rows hold on the states alone (``rows_x``: the
        loops' Φ = 0, Φ̇ = 0 of the stabilized index-2 form, whose multipliers μ, ν enter
        only the state equations and are 0 on the exact solution). Judged on the equations
        with the fixed parameters' values (the loop-row switches turn rows to index 1)."""
        c = self.compiled
        alg = ca.substitute(c.alg, c.p, ca.DM(self.p_values))
        J = ca.jacobian(alg, c.z).sparsity() if self.nz else ca.Sparsity(0, 0)
        rows, cols = J.get_triplet()
        self.z_alg = sorted(set(cols))
        self.rows_z = sorted(set(rows))
        self.rows_x = [r for r in range(c.alg.numel()) if r not in set(rows)]


def event_owners(compiled) -> list[str]:
    """The components of ``compiled`` that declare state events or modes."""
    return sorted({v.component for v in compiled.state_events.indicators + compiled.modes})


def smooth_form(compiled):
    """(the smooth form of ``compiled``, the components regularized in it with their
    regularization parameters: {component: [parameter names]}). A model with events is
    compiled again from its Model in smooth form (``compile(model, smooth=True)``); one
    compiled smooth is kept (its exact form compiled to name what is regularized); one
    without events and not smooth is its own smooth form, nothing regularized. The
    regularization parameters of a component are its parameters that the smooth form's
    equations use and the exact form's do not (``v_smooth``, a contact stiffness)."""
    if compiled.has_events:
        smooth = recompile(compiled, smooth=True)
        return smooth, _regularized(compiled, smooth)
    if compiled.smooth and compiled.source is not None:
        return compiled, _regularized(recompile(compiled, smooth=False), compiled)
    return compiled, {}


def _regularized(exact, smooth) -> dict[str, list[str]]:
    ev = exact.state_events
    e_all = ca.vertcat(exact.ode, exact.alg, ev.indicator, ev.mode_update, ev.reinit_values)
    s_all = ca.vertcat(smooth.ode, smooth.alg)
    out = {}
    for owner in event_owners(exact):
        names = [n for i, n in enumerate(smooth.param_names)
                 if n.startswith(owner + ".") and ca.depends_on(s_all, smooth.p[i])
                 and not (n in exact.param_names and ca.depends_on(
                     e_all, exact.p[exact.param_names.index(n)]))]
        out[owner] = names
    return out


class Symbols(Mapping):
    """Read-only mapping name -> SX of a model (what integrand callables receive)."""

    def __init__(self, view: ModelView):
        self._view = view

    def __getitem__(self, name):
        return self._view.sym(name)

    def __iter__(self):
        return iter(self._view.names())

    def __len__(self):
        return len(self._view.names())
