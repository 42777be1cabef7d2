"""Simulation: CasADi integrators, consistent initial values, Result. The dependency-free
pieces it shares with the compiler and the pythonfmu FMU (projection, event times) are in the
base leaf ``acausal.numerics``."""
from .initialization import initial_state
from .result import Result
from .inputs import Samples, input_signal
from .simulate import simulate

__all__ = ["simulate", "Result", "Samples", "initial_state", "input_signal"]
