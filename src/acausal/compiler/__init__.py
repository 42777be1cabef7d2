"""The compiler: model → CompiledModel (flatten, kinematic graph, coordinates, Lagrange's
equations by algorithmic differentiation, constraints, DAE assembly, structural checks)."""
from .assemble import compile, recompile
from .compiled import CompiledModel, Resolved, ScalarVariable
from .lagrange import Lagrange

__all__ = ["compile", "recompile", "CompiledModel", "Lagrange", "ScalarVariable", "Resolved"]
