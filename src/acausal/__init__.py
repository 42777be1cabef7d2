"""acausal: Modelica-like acausal mechanics in Python on CasADi.

Build models from components (``acausal.components``), compile them into CasADi equations of
motion (``acausal.compile``), simulate (``compiled.simulate``).
"""
from importlib.metadata import version

from .core import Component, Input, Model, Output, Parameter, connect
from .errors import (AcausalError, AnalysisError, DisabledPortError, FmuExportError, FmuPathError,
                     InitializationError, OCPError, ParameterError, PortConnectionError,
                     SimulationError, SingularModelError, SolveError, StructureError,
                     VariableNameError)
from .facade import CompiledModel, compile
from .simulation import Result, simulate

__version__ = version("acausal")
__all__ = ["Model", "Component", "Parameter", "Input", "Output", "connect", "compile",
           "CompiledModel", "simulate", "Result", "AcausalError", "ParameterError",
           "PortConnectionError", "StructureError", "SingularModelError",
           "InitializationError", "SimulationError", "VariableNameError", "DisabledPortError",
           "AnalysisError", "OCPError", "SolveError", "FmuExportError", "FmuPathError"]
