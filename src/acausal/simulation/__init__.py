"""Simulation: CasADi integrators, consistent initial values, state events and modes
(``events``), Result. The dependency-free pieces it shares with the compiler and the
pythonfmu FMU (projection, event times) are in the base leaf ``acausal.numerics``."""
from .initialization import initial_state
from .result import Event, Result
from .inputs import Samples, input_signal
from .simulate import simulate
from .sweep import SweepResult, sweep
from .feedback import Controller
from .stepper import Stepper

__all__ = ["simulate", "sweep", "SweepResult", "Result", "Event", "Samples", "initial_state",
           "input_signal", "Controller", "Stepper"]
