"""The exceptions of acausal.ocp (both are acausal.AcausalError)."""
from __future__ import annotations

from ..core.errors import AcausalError


class OCPError(AcausalError, ValueError):
    """A bad optimal control problem: an unknown name, bad bounds, a malformed constraint."""


class SolveError(OCPError):
    """IPOPT did not converge. ``status`` is IPOPT's return status (e.g.
    'Infeasible_Problem_Detected'); ``solution`` the last iterate, for inspection."""

    def __init__(self, message: str, status: str, solution=None):
        super().__init__(message)
        self.status = status
        self.solution = solution
