"""The modelling language: Parameter, ports, Component, Model, connect(), Input, Output.

Nothing here knows the component library or the compiler; its errors are those of
``acausal.errors``.
"""
from .component import Component, ConditionalPort, Model, StateSelect, Unavailable, connect
from .interface import Input, Output
from .parameter import Parameter
from .ports import (ELECTRICAL, MULTIBODY, PLANAR, ROTATIONAL, THERMAL, TRANSLATIONAL,
                    BooleanInput, BooleanOutput, Domain, Frame, HeatPort, HeatPort_a,
                    HeatPort_b, MultiBodyFrame, NegativePin, PhysicalPort, Pin, Port,
                    PortVector, PositivePin, RealInput, RealOutput, RotationalFlange,
                    TranslationalFlange, VectorPort)

__all__ = [
    "Component", "ConditionalPort", "Model", "StateSelect", "Unavailable", "connect", "Input",
    "Output", "Parameter",
    "Port", "PhysicalPort", "PortVector", "VectorPort", "Domain", "TranslationalFlange",
    "RotationalFlange", "Frame", "RealInput", "RealOutput", "BooleanInput", "BooleanOutput",
    "TRANSLATIONAL", "ROTATIONAL", "PLANAR", "MULTIBODY", "MultiBodyFrame", "ELECTRICAL",
    "THERMAL", "Pin", "PositivePin",
    "NegativePin", "HeatPort", "HeatPort_a", "HeatPort_b",
]
