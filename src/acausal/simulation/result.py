"""Result: the simulated trajectories of every variable, by dotted name."""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..errors import SimulationError, VariableNameError
from .buffers import Buffered


@dataclass(frozen=True)
class Event:
    """One entry of a Result's event log: at ``time`` [s], ``component``'s ``indicator``
    crossed zero in ``direction`` (−1 falling, 1 rising; for a time event or the start,
    indicator "" and direction 0); ``modes``: every mode that changed, name -> (before,
    after); ``reinit``: every state reinitialized, name -> (before, after)."""
    time: float
    component: str
    indicator: str
    direction: int
    modes: dict = field(default_factory=dict)
    reinit: dict = field(default_factory=dict)

    def __str__(self):
        what = f"{self.indicator} {'falls' if self.direction < 0 else 'rises'} through 0" \
            if self.indicator else "modes updated (start or time event)"
        changes = [f"{n}: {a:g} -> {b:g}" for n, (a, b) in {**self.modes, **self.reinit}.items()]
        return f"t = {self.time:.12g} s: {what}" + (f"; {', '.join(changes)}" if changes else "")


@dataclass(frozen=True)
class Termination:
    """Why a simulation ended before its final time: at ``time`` [s] the condition of
    ``component`` (Modelica's ``terminate(message)``, ``PhysicsBuilder.terminate``) held
    after an event."""
    time: float
    component: str
    message: str

    def __str__(self):
        return f"terminated at t = {self.time:.12g} s by '{self.component}': {self.message}"


class Result:
    """Trajectories on the output grid: ``res.t`` [s], ``res["mass.s"]`` (numpy arrays) for
    any variable of the model by its dotted name.

    Made from the model and its trajectories on the grid t: states X, algebraic variables Z,
    inputs U and parameters P (columns per time; P may have one column). States and the
    other symbols are read directly; the recorded variables (port positions and flows,
    sensor signals, components' variables) are built and evaluated on first use, so that a
    run whose states alone are read pays nothing for them.

    A model with events: ``events`` is the event log (``Event``s in time order), the modes
    are read like any variable (``res["block.mode"]``), and at each event the time appears
    twice in ``t``: the left limit, then the right limit. ``terminated``: a ``Termination``
    when a component's condition ended the simulation early (``t`` then ends at its
    instant, the right limit there last), else None.
    """

    def __init__(self, model, t, X, Z, U, P):
        self.t = np.asarray(t, dtype=float)
        self.model_name = model.name
        self._model = model
        n = self.t.size
        self._states, self._algebraics, self._inputs = (np.asarray(a, dtype=float).reshape(-1, n)
                                     for a in (X, Z, U))
        P = np.asarray(P, dtype=float)
        self._params = P.reshape(len(model.params), -1) if P.size else np.zeros((0, 1))
        self._values = None
        self._units = None
        self.events: list[Event] = []
        self.terminated: Termination | None = None
        self.partial = False         # the run was interrupted (Ctrl-C): t ends early

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
        """The recorded expressions that are not states, on the grid (evaluated once, time
        by time into one array: a mapped call's result converted from a DM costs more than
        the evaluation for a large model, 90 000 values on 101 times: 2.8 s against 0.7)."""
        if self._values is None:
            f = self._model.recorded_function
            columns = (self.t.reshape(1, -1), self._states, self._algebraics, self._inputs,
                       self._params)                # (parameters: one column, or one per time)
            buffered = Buffered(f, [np.zeros(f.nnz_in(i)) for i in range(f.n_in())])
            # column by column (Fortran order: a time's values contiguous, written at once)
            self._values = np.empty((f.nnz_out(0), self.t.size), order="F")
            for k in range(self.t.size):
                for arg, values in zip(buffered.args, columns):
                    arg[:] = values[:, k if values.shape[1] == self.t.size else 0]
                buffered.call()
                self._values[:, k] = buffered.res[0]
        return self._values

    def _param_columns(self) -> np.ndarray:
        """The parameters, a column per output time (a run without modes holds one)."""
        P, n = self._params, self.t.size
        return P if P.shape[1] == n else np.tile(P[:, :1], (1, n))

    def __getitem__(self, name: str) -> np.ndarray:
        try:
            kind, index = self._model.locate(name)
        except VariableNameError as e:
            raise VariableNameError(f"{e} (in the result of '{self.model_name}')") from None
        if kind == "time":
            return self.t
        if kind == "parameter":
            row = self._params[index]
            return row.copy() if row.size == self.t.size else np.full(self.t.size, row[0])
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

    def plot(self, *names: str, ax=None, path=None, title: str | None = None):
        """Plot against time (needs matplotlib): the ``names`` on one Axes, or with no
        names every state, one panel per unit (positions [m], angles [rad], …). ``ax``: an
        Axes to draw on (everything on it) or one Axes per panel; ``path``: save the figure
        there; ``title`` above the first panel (default: the model's name). Returns the
        Axes, or the list of them for several panels."""
        import matplotlib
        if path is not None and ax is None:
            matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        panels = self._panels(names)
        if ax is None:
            _, grid = plt.subplots(len(panels), 1, sharex=True, squeeze=False,
                                   figsize=(7, 1.8 * len(panels) + 1.2))
            axes = list(grid[:, 0])
        else:
            axes = list(np.atleast_1d(ax))
            if len(axes) == 1:
                panels = [[n for p in panels for n in p]]
            elif len(axes) != len(panels):
                raise ValueError(f"plot: {len(panels)} panels ({panels}) need 1 or "
                                 f"{len(panels)} Axes, got {len(axes)}")
        steps = self._steps()
        for a, group in zip(axes, panels):
            units = {self.units.get(n, "") for n in group}
            for n in group:
                unit = self.units.get(n, "")
                label = n if len(units) == 1 else (f"{n} [{unit}]" if unit else n)
                if n in steps:
                    a.step(self.t, self[n], where="post", label=label)
                else:
                    a.plot(self.t, self[n], label=label)
            if len(units) == 1 and units != {""}:
                a.set_ylabel(f"[{units.pop()}]")
            a.grid(True)
            a.legend(fontsize=8)
        axes[-1].set_xlabel("time [s]")
        axes[0].set_title(self._title() if title is None else title, fontsize=9)
        if path is not None:
            axes[0].figure.savefig(path, dpi=120, bbox_inches="tight")
        return axes[0] if len(axes) == 1 else axes

    def animate(self, **kwargs):
        """The model's parts moving as in this result (``acausal.analysis.animation``):
        ``.save("run.gif" | "run.mp4" | "run.html")``, shown by itself in a notebook;
        keywords ``shapes``, ``azimuth``, ``elevation`` [deg]."""
        animation = getattr(self._model, "animation", None)
        if animation is None:
            raise SimulationError(f"the result of '{self.model_name}' was made from the "
                                  f"compiler's record alone; animate the result of a model "
                                  f"compiled with acausal.compile")
        return animation(self, **kwargs)

    def _panels(self, names) -> list[list[str]]:
        """What ``plot`` draws: the names on one panel, else the states by unit."""
        return [list(names)] if names else by_unit(self._model.x_names, self.units)

    def _steps(self) -> set[str]:
        """Names drawn as steps (held values)."""
        return set()

    def _title(self) -> str:
        return f"{self.model_name}"

    def __repr__(self):
        return (f"<Result of '{self.model_name}': {len(self.t)} time points, "
                f"{len(self.names)} variables>")


def by_unit(names, units: dict) -> list[list[str]]:
    """The names grouped by their unit, groups in order of first appearance."""
    groups: dict[str, list[str]] = {}
    for n in names:
        groups.setdefault(units.get(n, ""), []).append(n)
    return list(groups.values())
