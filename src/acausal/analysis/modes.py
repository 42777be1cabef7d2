"""Modes: undamped natural frequencies and mode shapes, damped eigenvalues and damping ratios.

From a LinearModel of a mechanical model (see ``linearize``): with the coordinates q_I, their
rates v_I and the reduced mass matrix M (Vᵀ M V for closed loops), the rows of A for v̇_I give
the stiffness and damping as seen by the coordinates, K = −M ∂v̇/∂q, C = −M ∂v̇/∂v (at an
equilibrium these are the Hessian of the potential, including gravity and the loops'
constraint forces, and the damping matrix). The undamped modes solve K φ = ω² M φ
(scipy.linalg.eigh when K is symmetric); the damped eigenvalues are those of the whole A.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.linalg

from ..errors import AnalysisError
from .linear import LinearModel
from .linearize import linearize


@dataclass
class Modes:
    """``frequencies`` [Hz]: undamped natural frequencies, ascending (an unstable direction,
    ω² < 0, shows as a negative value −√|ω²|/2π); ``shapes`` (len(coordinates) × modes): mode
    shapes in the named coordinates (all coordinates, dependent ones of closed loops included),
    each scaled to a largest entry of +1; ``eigenvalues`` [1/s]: damped eigenvalues of the
    linear model, one per complex-conjugate pair (Im ≥ 0) and the real ones, by magnitude;
    ``damping``: their damping ratios ζ = −Re λ/|λ| (nan for λ = 0); ``damped_frequencies`` [Hz] = Im λ/2π;
    ``mode``: the discrete modes of the model they are of (friction stuck or sliding), by
    name (empty without modes)."""
    frequencies: np.ndarray
    shapes: np.ndarray
    coordinates: list[str]
    eigenvalues: np.ndarray
    damping: np.ndarray
    damped_frequencies: np.ndarray
    mode: dict = field(default_factory=dict)

    def shape(self, k: int) -> dict[str, float]:
        """Mode shape k by coordinate name."""
        return dict(zip(self.coordinates, map(float, self.shapes[:, k])))

    def __str__(self):
        lines = [f"in discrete modes {self.mode}"] if self.mode else []
        lines.append(f"undamped modes ({', '.join(self.coordinates)}):")
        for k, fk in enumerate(self.frequencies):
            shape = ", ".join(f"{v:+.3f}" for v in self.shapes[:, k])
            lines.append(f"  {fk:10.4f} Hz  [{shape}]")
        lines.append("damped eigenvalues:")
        for lam, z in zip(self.eigenvalues, self.damping):
            lines.append(f"  {lam.real:+.5g} {lam.imag:+.5g}j  (zeta = {z:.4f}, "
                         f"{lam.imag / (2 * np.pi):.4f} Hz)")
        return "\n".join(lines)


def modes(model, x=None, **kwargs) -> Modes:
    """Modes of ``model`` (a CompiledModel, linearized at x with ``kwargs`` as for
    ``linearize``, ``mode=`` the discrete modes included, or a LinearModel). Quaternion
    states (free bodies, Spherical, FreeMotion) are taken in their tangent coordinates θ
    (``linearize(..., tangent=True)``): the mode shapes name θ[1..3], the rotation resolved
    in the frame; a free body has six rigid-body modes at 0 Hz."""
    lin = model if isinstance(model, LinearModel) else linearize(
        model, x, inputs=[], outputs=[], **{"tangent": True, **kwargs})
    if not lin.coordinates:
        raise AnalysisError("modes: the linear model has no mechanical coordinates (with "
                            "mass) among its states (orientations as quaternion states: "
                            "linearize with tangent=True, or give modes() the compiled "
                            "model)")
    if lin.mass is None:
        raise AnalysisError("modes: the linear model has quaternion states; linearize with "
                            "tangent=True (or give modes() the compiled model)")
    iq = [lin.states.index(n) for n in lin.coordinates]
    iv = [lin.states.index(n) for n in lin.rates]
    M = lin.mass
    K = -M @ lin.A[np.ix_(iv, iq)]
    if np.allclose(K, K.T, rtol=1e-8, atol=1e-10 * max(1.0, np.abs(K).max())):
        w2, phi = scipy.linalg.eigh((K + K.T) / 2, M)
    else:                                       # non-conservative stiffness (not at rest)
        w2, phi = scipy.linalg.eig(K, M)
        order = np.argsort(w2.real)
        w2, phi = w2.real[order], phi.real[:, order]
    w2 = np.where(np.abs(w2) <= 1e-12 * max(1.0, np.abs(w2).max()), 0.0, w2)   # rigid modes
    freq = np.sign(w2) * np.sqrt(np.abs(w2)) / (2 * np.pi)
    shapes = lin.q_basis @ phi
    big = shapes[np.argmax(np.abs(shapes), axis=0), range(shapes.shape[1])]
    shapes = shapes / big

    ev = np.linalg.eigvals(lin.A)
    ev = ev[ev.imag >= -1e-12 * np.maximum(1.0, np.abs(ev))]
    ev = ev[np.argsort(np.abs(ev))]
    mag = np.abs(ev)
    zeta = np.where(mag > 0, -ev.real / np.where(mag > 0, mag, 1.0), np.nan)
    return Modes(freq, shapes, list(lin.q_names), ev, zeta, ev.imag / (2 * np.pi),
                 dict(lin.mode))
