"""The exceptions of acausal: every user mistake is one of these, naming the part at fault."""
import difflib


def did_you_mean(name: str, options) -> str:
    """'; did you mean 'a', 'b'?' for the options closest to a mistyped ``name`` (or '')."""
    close = difflib.get_close_matches(name, list(options), n=3)
    return f"; did you mean {', '.join(repr(c) for c in close)}?" if close else ""


class AcausalError(Exception):
    """Base of every error acausal raises for a bad model or a bad request."""


class VariableNameError(AcausalError, KeyError):
    """A variable name the model (or a result) does not have."""

    def __str__(self):                      # the message, not KeyError's quoted repr
        return str(self.args[0]) if self.args else ""


class ParameterError(AcausalError, ValueError):
    """A parameter name that does not exist, or a value out of its range."""


class ConnectionError_(AcausalError):
    """Ports of different kinds connected, or a port connected wrongly."""


class StructureError(AcausalError):
    """The model cannot be compiled: unconnected ports, no dynamics, bad or redundant loops."""


class SingularModelError(StructureError):
    """The equations cannot be solved for the accelerations (a massless part with no law)."""


class InitializationError(AcausalError):
    """Initial values that conflict or cannot be met."""


class SimulationError(AcausalError):
    """The integrator failed, or simulate() was called with bad arguments."""


# Public name: Python's builtin ConnectionError means something else (sockets).
PortConnectionError = ConnectionError_
del ConnectionError_
