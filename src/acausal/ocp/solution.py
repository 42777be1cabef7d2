"""Solution: an OCP's optimum, with every variable of the model by name along it."""
from __future__ import annotations

import os

import casadi as ca
import numpy as np

from ..errors import VariableNameError
from ..simulation.result import Result, by_unit
from ..errors import OCPError


class Solution(Result):
    """The optimum of an OCP on its mesh nodes ``t`` [s] (N + 1 times).

    ``sol["cart.s"]``: any state, control or recorded variable at the nodes (a control's
    value on [t_k, t_k+1) is given at t_k and held at t_N); ``sol.control(name)``: a control's
    N interval values; ``sol.parameters``: the free parameters' values; ``sol.cost``,
    ``sol.T`` [s], ``sol.status`` (IPOPT's return status), ``sol.iterations``, ``sol.stats``;
    ``sol.value(expr)``: any MX expression of the problem's symbols (``ocp["x"]``,
    ``ocp.integral(...)``, ``ocp.T``) at the optimum; ``sol.smooth``, ``sol.regularized``:
    whether the model was in smooth form, which components were regularized with which
    parameter values (as the OCP's).
    """

    def __init__(self, ocp, nlp, w: np.ndarray, cost: float, stats: dict, resolve):
        self._w, self._nlp_w, self._resolve = w, nlp.w, resolve
        n, view, c = ocp.nodes, ocp.view, ocp.view.compiled
        t, X, U, Z, P = (self.value(e) for e in (n.t, n.X, n.U_nodes, n.Z, n.P))
        t, P = np.atleast_1d(t).ravel(), np.atleast_1d(P).reshape(-1, 1)
        X, U, Z = (np.asarray(a, dtype=float).reshape(-1, t.size) for a in (X, U, Z))

        super().__init__(c, t, X, Z, U, P)
        self._U, self._view = U[:, :-1], view
        self.cost, self.T = cost, float(t[-1] - t[0])
        self.stats, self.status = stats, stats["return_status"]
        self.iterations = stats["iter_count"]
        self.parameters = {name: float(P[i, 0]) for name, i in zip(view.free, view.free_index)}
        self.method = ocp.method
        self.smooth, self.regularized = ocp.smooth, ocp.regularized

    def value(self, expr):
        """The value of an MX expression of the problem's symbols at the optimum: a float
        for a scalar, a 1-D array for a vector, else a 2-D array."""
        try:
            f = ca.Function("value", [self._nlp_w], [self._resolve(expr)])
        except RuntimeError:
            raise OCPError("the expression depends on symbols this solution does not know (of "
                           "another OCP, or an integral made after the solve)") from None
        v = np.array(f(self._w), dtype=float)
        return float(v[0, 0]) if v.size == 1 else (v.ravel() if 1 in v.shape else v)

    def control(self, name: str) -> np.ndarray:
        """A control's N values, one per interval [t_k, t_k+1)."""
        if self._view.kind(name) != "control":
            raise VariableNameError(f"'{name}' is not a control; controls: "
                           f"{self._view.compiled.input_names}")
        return self._U[self._view.index(name)]

    def plot(self, *names: str, ax=None, path=None, title: str | None = None):
        """One panel per name (default: the states, one panel per unit, then the controls,
        as steps); ``ax``: one Axes (everything on it) or one per panel; saved to ``path``
        if given (a directory: ``ocp_<model>.png`` in it). Returns the figure."""
        if path is not None and os.path.isdir(path):
            path = os.path.join(path, f"ocp_{self._view.compiled.name}.png")
        axes = super().plot(*names, ax=ax, path=path, title=title)
        return np.atleast_1d(axes)[0].figure

    def _panels(self, names) -> list[list[str]]:
        c = self._view.compiled
        return [[n] for n in names] if names else (by_unit(c.x_names, self.units)
                                                   + by_unit(c.input_names, self.units))

    def _steps(self) -> set[str]:
        return set(self._view.compiled.input_names)

    def _title(self) -> str:
        return (f"{self._view.compiled.name}: cost {self.cost:.6g}, T = {self.T:.4g} s "
                f"({self.status})")

    def __repr__(self):
        form = f", smooth form of {', '.join(self.regularized)}" if self.regularized else (
            ", smooth form" if self.smooth else "")
        return (f"<Solution of '{self.model_name}': cost {self.cost:.6g}, T = {self.T:g} s, "
                f"{self.status} in {self.iterations} iterations{form}>")
