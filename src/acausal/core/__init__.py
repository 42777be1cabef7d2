"""The modelling language: Parameter, ports, Component, Model, connect(), Input, Output.

Nothing here knows the component library or the compiler.
"""
from .component import Component, Model, connect
from .errors import (AcausalError, InitializationError, ParameterError, PortConnectionError,
                     SimulationError, SingularModelError, StructureError, VariableNameError)
from .interface import Input, Output
from .parameter import Parameter
from .ports import (PLANAR, ROTATIONAL, TRANSLATIONAL, Domain, Frame, PhysicalPort, Port,
                    PortVector, RealInput, RealOutput, RotationalFlange, TranslationalFlange)

__all__ = [
    "Component", "Model", "connect", "Input", "Output", "Parameter",
    "Port", "PhysicalPort", "PortVector", "Domain", "TranslationalFlange", "RotationalFlange", "Frame",
    "RealInput", "RealOutput", "TRANSLATIONAL", "ROTATIONAL", "PLANAR",
    "AcausalError", "ParameterError", "PortConnectionError", "StructureError",
    "SingularModelError", "InitializationError", "SimulationError", "VariableNameError",
]
