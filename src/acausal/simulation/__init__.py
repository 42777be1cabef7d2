"""Simulation: CasADi integrators, consistent initial values, Result."""
from .initialization import initial_state
from .result import Result
from .simulate import input_expression, simulate

__all__ = ["simulate", "Result", "initial_state", "input_expression"]
