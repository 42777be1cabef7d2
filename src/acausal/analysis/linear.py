"""LinearModel: a linear state-space model with names, as numpy arrays, exportable to
python-control (optional dependency)."""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass
class LinearModel:
    """δẋ = A δx + B δu,  δy = C δx + D δu  about the operating point (x_op, u_op, y_op).

    ``states``, ``inputs``, ``outputs`` name the rows/columns (dotted names of the model).
    For a model with closed loops the states are the independent coordinates, their rates and
    the other states; ``expansion`` (full states × ``states``) gives the change of every state
    of the model (``full_states``) from a change of these: δx_full = expansion · δx.
    ``coordinates`` names the position states of the mechanical coordinates among ``states``
    (``rates`` their rate states), ``mass`` is their (reduced) mass matrix there [SI units]
    and δq = ``q_basis`` · δ(coordinates) gives the change of every coordinate of the model
    (``q_names``, dependent ones of closed loops included). ``mode``: the discrete modes
    the model was linearized in, by name (empty without modes).
    """
    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    states: list[str]
    inputs: list[str]
    outputs: list[str]
    x_op: np.ndarray
    u_op: np.ndarray
    y_op: np.ndarray
    full_states: list[str] = field(default_factory=list)
    expansion: np.ndarray | None = None
    coordinates: list[str] = field(default_factory=list)
    rates: list[str] = field(default_factory=list)
    mass: np.ndarray | None = None
    q_names: list[str] = field(default_factory=list)
    q_basis: np.ndarray | None = None
    mode: dict = field(default_factory=dict)

    def eigenvalues(self) -> np.ndarray:
        """Eigenvalues of A [1/s], sorted by imaginary part then real part."""
        ev = np.linalg.eigvals(self.A) if self.A.size else np.zeros(0, complex)
        return ev[np.lexsort((ev.real, ev.imag))]

    def to_control(self, name: str | None = None):
        """A ``control.StateSpace`` (needs the python-control package) with the signal names,
        '.' replaced by '_' (python-control reserves '.' for subsystems): ``m2.s`` -> ``m2_s``."""
        try:
            import control
        except ImportError:
            raise ImportError("LinearModel.to_control needs python-control: pip install "
                              "control (or use A, B, C, D directly)") from None
        def ok(names):
            return [n.replace(".", "_") for n in names]
        return control.ss(self.A, self.B, self.C, self.D, states=ok(self.states),
                          inputs=ok(self.inputs), outputs=ok(self.outputs), name=name)

    def __repr__(self):
        modes = f", in modes {self.mode}" if self.mode else ""
        return (f"<LinearModel: {len(self.states)} states, {len(self.inputs)} inputs "
                f"{self.inputs}, {len(self.outputs)} outputs {self.outputs}{modes}>")
