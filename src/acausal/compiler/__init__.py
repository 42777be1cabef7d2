"""The compiler: model → CompiledModel (flatten, kinematic graph, coordinates, Lagrange's
equations by algorithmic differentiation, constraints, DAE assembly, structural checks)."""
from .assemble import compile
from .compiled import CompiledModel, Lagrange

__all__ = ["compile", "CompiledModel", "Lagrange"]
