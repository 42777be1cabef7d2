"""Exact references of linear time-invariant systems x' = A x + B u: the matrix exponential
of the system augmented by its input, the input held constant over each interval."""
import numpy as np
from scipy.linalg import expm


def held_input_flow(A, B, dt: float):
    """(Φ, Γ) with x(t + dt) = Φ x(t) + Γ u for x' = A x + B u, u held over dt [s]: the
    blocks of expm([[A, B], [0, 0]] dt) (exact, A singular or not); Γ has B's shape."""
    A = np.atleast_2d(np.asarray(A, dtype=float))
    n, B = A.shape[0], np.asarray(B, dtype=float)
    columns = B.reshape(n, -1)
    M = np.zeros((n + columns.shape[1],) * 2)
    M[:n, :n], M[:n, n:] = A, columns
    E = expm(M * dt)
    return E[:n, :n], E[:n, n:].reshape(B.shape)


def constant_input_response(A, b, x0, t) -> np.ndarray:
    """The states (a row per time of t [s]) of x' = A x + b, b constant, from x(0) = x0."""
    x0 = np.asarray(x0, dtype=float)
    return np.array([Phi @ x0 + Gam for Phi, Gam in (held_input_flow(A, b, tk) for tk in t)])
