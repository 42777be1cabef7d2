"""Simulation: CasADi integrators, consistent initial values, Result; ``kernels`` holds the
dependency-free pieces (projection, event times) that the pythonfmu FMU ships and runs too."""
from .initialization import initial_state
from .result import Result
from .simulate import input_expression, simulate

__all__ = ["simulate", "Result", "initial_state", "input_expression"]
