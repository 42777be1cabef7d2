"""The exception of the analyses (a request that cannot be answered)."""
from __future__ import annotations

from ..core.errors import AcausalError


class AnalysisError(AcausalError, ValueError):
    """An analysis cannot be done as asked: an unknown name, no equilibrium found, a
    prescribed motion the mechanism cannot follow. The message names the part at fault."""
