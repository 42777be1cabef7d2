"""Result: the simulated trajectories of every variable, by dotted name."""
from __future__ import annotations

import numpy as np

from ..errors import VariableNameError


class Result:
    """Trajectories on the output grid: ``res.t`` [s], ``res["mass.s"]`` (numpy arrays) for
    any variable of the model by its dotted name.

    Made from the model and its trajectories on the grid t: states X, algebraic variables Z,
    inputs U and parameters P (columns per time; P may have one column). States and the
    other symbols are read directly; the recorded variables (port positions and flows,
    sensor signals, components' variables) are built and evaluated on first use, so that a
    run whose states alone are read pays nothing for them.
    """

    def __init__(self, model, t, X, Z, U, P):
        self.t = np.asarray(t, dtype=float)
        self.model_name = model.name
        self._model = model
        n = self.t.size
        self._states, self._algebraics, self._inputs = (np.asarray(a, dtype=float).reshape(-1, n)
                                     for a in (X, Z, U))
        self._params = np.asarray(P, dtype=float).reshape(len(model.params), -1)
        self._values = None
        self._units = None

    @property
    def names(self) -> list[str]:
        """Every variable's dotted name."""
        return self._model.recorded_names

    @property
    def units(self) -> dict[str, str]:
        """Units by variable name."""
        if self._units is None:
            self._units = dict(zip(self.names, self._model.recorded_units))
            self._units.update((v.name, v.unit) for v in self._model.inputs if v.unit)
        return self._units

    def _recorded(self) -> np.ndarray:
        """The recorded expressions that are not states, on the grid (evaluated once)."""
        if self._values is None:
            n, P = self.t.size, self._params
            P = P if P.shape[1] == n else np.tile(P[:, :1], (1, n))
            V = self._model.recorded_function.map(n)(self.t.reshape(1, -1), self._states,
                                                     self._algebraics, self._inputs, P)
            self._values = np.asarray(V.full(), dtype=float)
        return self._values

    def __getitem__(self, name: str) -> np.ndarray:
        try:
            kind, index = self._model.locate(name)
        except VariableNameError as e:
            raise VariableNameError(f"{e} (in the result of '{self.model_name}')") from None
        if kind == "time":
            return self.t
        if kind == "parameter":
            return np.full(self.t.size, self._params[index, 0])
        source = {"state": self._states, "algebraic": self._algebraics,
                  "input": self._inputs}.get(kind)
        if source is not None:
            return source[index]
        where, row = self._model.recorded_layout[index]
        return self._states[row] if where == "x" else self._recorded()[row]

    def __contains__(self, name: str) -> bool:
        try:
            self._model.locate(name)
        except VariableNameError:
            return False
        return True

    def final(self, name: str) -> float:
        """The value of ``name`` at the last time point."""
        return float(self[name][-1])

    def to_pandas(self):
        """A pandas DataFrame indexed by time (needs pandas)."""
        import pandas as pd
        return pd.DataFrame({n: self[n] for n in self.names},
                            index=pd.Index(self.t, name="time"))

    def to_csv(self, path, names: list[str] | None = None) -> None:
        """Write time and the chosen (default: all) variables as CSV with a header line."""
        names = names or self.names
        data = np.column_stack([self.t] + [self[n] for n in names])
        header = ",".join(["time"] + names)
        np.savetxt(path, data, delimiter=",", header=header, comments="")

    def plot(self, *names: str, ax=None, path=None):
        """Plot variables against time (needs matplotlib); save to ``path`` if given."""
        import matplotlib
        if path is not None:
            matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        if ax is None:
            _, ax = plt.subplots()
        for n in names:
            unit = self.units.get(n, "")
            ax.plot(self.t, self[n], label=f"{n} [{unit}]" if unit else n)
        ax.set_xlabel("time [s]")
        ax.grid(True)
        ax.legend()
        if path is not None:
            ax.figure.savefig(path, dpi=120, bbox_inches="tight")
        return ax

    def __repr__(self):
        return (f"<Result of '{self.model_name}': {len(self.t)} time points, "
                f"{len(self.names)} variables>")
