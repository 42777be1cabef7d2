"""Result: the simulated trajectories of every variable, by dotted name."""
from __future__ import annotations

import numpy as np

from ..errors import VariableNameError, did_you_mean


class Result:
    """Trajectories on the output grid: ``res.t`` [s], ``res["mass.s"]`` (numpy arrays)."""

    def __init__(self, t: np.ndarray, names: list[str], layout: list[tuple[str, int]],
                 units: list[str], sources: dict, model_name: str = ""):
        """``layout[i]`` = (source key, row) of ``names[i]``; ``sources`` maps a key to an
        array of trajectories (rows × len(t)) or to a callable giving one on first use."""
        self.t = t
        self.names = list(names)
        self._index = dict(zip(names, layout))
        self._sources = dict(sources)
        self.units = dict(zip(names, units))
        self.model_name = model_name

    def _row(self, where: tuple[str, int]) -> np.ndarray:
        key, r = where
        if callable(self._sources[key]):
            self._sources[key] = self._sources[key]()
        return self._sources[key][r]

    def __getitem__(self, name: str) -> np.ndarray:
        if name == "time" or name == "t":
            return self.t
        try:
            return self._row(self._index[name])
        except KeyError:
            raise VariableNameError(f"no variable '{name}' in the result of '{self.model_name}'"
                           f"{did_you_mean(name, self.names)}") from None

    def __contains__(self, name: str) -> bool:
        return name in self._index

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
