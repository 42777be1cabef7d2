"""The exceptions of acausal, in one hierarchy; ``did_you_mean`` for their messages and
``warn_user`` for warnings that point at the user's line.

A base leaf: it imports nothing of acausal, and every layer may import it. Every user mistake
raises one of these, and its message names the part at fault and says what to do. Errors that
are also Python's own kind derive from both, so ``except KeyError`` / ``except AttributeError``
/ ``except FileNotFoundError`` in a user's code keep working:

    AcausalError
    ├── VariableNameError (KeyError)        a name the model or result does not have
    ├── ParameterError (ValueError)         a parameter or option that does not exist, a bad value
    ├── PortConnectionError                 ports connected wrongly
    ├── DisabledPortError (AttributeError)  a conditional port its component was built without
    ├── StructureError                      the model cannot be compiled
    │   └── SingularModelError              no solution for the accelerations
    ├── InitializationError                 initial values that conflict or cannot be met
    ├── SimulationError                     the integrator failed, or bad simulate() arguments
    ├── AnalysisError (ValueError)          an analysis that cannot be done as asked
    ├── OCPError (ValueError)               a bad optimal control problem
    │   └── SolveError                      IPOPT did not converge
    └── FmuExportError                      an FMU could not be built
        └── FmuPathError (FileNotFoundError) the FMU's destination cannot be written

and one warning, a note rather than a fault: SmoothFormWarning (UserWarning), a model's
components with events replaced by their smooth form (optimal control).
"""
from __future__ import annotations

import difflib
import sys
import warnings

__all__ = ["did_you_mean", "warn_user", "SmoothFormWarning", "AcausalError", "VariableNameError", "ParameterError",
           "PortConnectionError", "DisabledPortError", "StructureError", "SingularModelError",
           "InitializationError", "SimulationError", "AnalysisError", "OCPError", "SolveError",
           "FmuExportError", "FmuPathError"]


def did_you_mean(name: str, options) -> str:
    """'; did you mean 'a', 'b'?' for the options closest to a mistyped ``name`` (or '')."""
    close = difflib.get_close_matches(name, list(options), n=3)
    return f"; did you mean {', '.join(repr(c) for c in close)}?" if close else ""


def warn_user(message: str, category: type[Warning] = UserWarning) -> None:
    """Warn, pointing at the user's line: the first caller outside the acausal package."""
    level, frame = 2, sys._getframe(1)
    while frame is not None and frame.f_globals.get("__name__", "").startswith("acausal"):
        frame, level = frame.f_back, level + 1
    warnings.warn(message, category, stacklevel=level)


class SmoothFormWarning(UserWarning):
    """A note, not a fault: a model's components with events were replaced by their smooth
    form (optimal control transcribes that form; see ``compile(model, smooth=True)``).
    Silence it with ``warnings.simplefilter("ignore", SmoothFormWarning)``."""


class AcausalError(Exception):
    """Base of every error acausal raises for a bad model or a bad request."""


class VariableNameError(AcausalError, KeyError):
    """A variable name the model (or a result) does not have."""

    def __str__(self):                      # the message, not KeyError's quoted repr
        return str(self.args[0]) if self.args else ""


class ParameterError(AcausalError, ValueError):
    """A parameter or option name that does not exist, or a value out of its range."""


class PortConnectionError(AcausalError):
    """Ports of different kinds connected, or a port connected wrongly."""


class DisabledPortError(AcausalError, AttributeError):
    """A conditional port (MSL's ``... if useSupport``) of a component built without it."""


class StructureError(AcausalError):
    """The model cannot be compiled: unconnected ports, no dynamics, bad or redundant loops."""


class SingularModelError(StructureError):
    """The equations cannot be solved for the accelerations (a massless part with no law)."""


class InitializationError(AcausalError):
    """Initial values that conflict or cannot be met."""


class SimulationError(AcausalError):
    """The integrator failed, or simulate() was called with bad arguments."""


class AnalysisError(AcausalError, ValueError):
    """An analysis cannot be done as asked: an unknown name, no equilibrium found, a
    prescribed motion the mechanism cannot follow. The message names the part at fault."""


class OCPError(AcausalError, ValueError):
    """A bad optimal control problem: an unknown name, bad bounds, a malformed constraint."""


class SolveError(OCPError):
    """IPOPT did not converge. ``status`` is IPOPT's return status (e.g.
    'Infeasible_Problem_Detected'); ``solution`` the last iterate, for inspection."""

    def __init__(self, message: str, status: str, solution=None):
        super().__init__(message)
        self.status = status
        self.solution = solution


class FmuExportError(AcausalError):
    """The FMU could not be built (no C compiler, no FMI headers, a compiler error)."""


class FmuPathError(FmuExportError, FileNotFoundError):
    """The FMU's destination cannot be written (a missing or read-only directory)."""
