"""acausal: Modelica-like acausal mechanics in Python on CasADi.

Build models from components (``acausal.components``), compile them into CasADi equations of
motion (``acausal.compile``), simulate (``compiled.simulate``).

The package's layers; imports flow one way, downwards in this list (``tests/test_layers.py``
holds every import to it):

    facade.py       acausal.compile and the calls on its result (simulate, export_fmu,
                    mobility): the top, importing any layer, imported by none
    analysis/ fmu/ ocp/   what is asked of a compiled model (siblings: none imports another)
    simulation/     CasADi integrators, inputs, initial values, solver choice, state events
                    (events.py: location, event iteration of the modes, reinit), Result
    compiler/       model -> CompiledModel, the seam every layer above uses (compiled.py:
                    records of the variables, name resolution, Functions in the order
                    (t, x, z, u, p))
    models/         the models examples, tests and benchmarks share (MSL keeps its Examples
                    inside the library too)
    components/     the component library (translational, rotational, planar, friction,
                    signals; logical and discrete: Boolean and sampled-data blocks)
    core/           the modelling language: Parameter, ports, Component, Model, connect
    errors.py, numerics.py   base leaves every layer may use: the exception hierarchy; the
                    dependency-free numerics shared with the pythonfmu FMU
"""
from importlib.metadata import version

from .core import Component, Input, Model, Output, Parameter, connect
from .errors import (AcausalError, AnalysisError, DisabledPortError, FmuExportError, FmuPathError,
                     InitializationError, OCPError, ParameterError, PortConnectionError,
                     SimulationError, SingularModelError, SolveError, StructureError,
                     VariableNameError)
from .facade import CompiledModel, compile
from .simulation import Result, simulate
from .simulation import montecarlo

__version__ = version("acausal")
__all__ = ["Model", "Component", "Parameter", "Input", "Output", "connect", "compile",
           "CompiledModel", "simulate", "Result", "montecarlo", "AcausalError", "ParameterError",
           "PortConnectionError", "StructureError", "SingularModelError",
           "InitializationError", "SimulationError", "VariableNameError", "DisabledPortError",
           "AnalysisError", "OCPError", "SolveError", "FmuExportError", "FmuPathError"]
