"""Analyses of a compiled model: linearization, modes, static equilibrium, kinematic
analysis, inverse and mixed dynamics — every question asked of the same equations

    M(q) q̈ + Φ_qᵀ λ = Q(q, q̇, u, t),   Φ(q, t) = 0.
"""
from .equilibrium import Equilibrium, equilibrium
from ..errors import AnalysisError
from .inverse import inverse_dynamics, mixed_dynamics
from .kinematics import kinematic_analysis
from .linear import LinearModel
from .linearize import linearize
from .modes import Modes, modes
from .point import OperatingPoint, operating_point

__all__ = ["AnalysisError", "Equilibrium", "equilibrium", "kinematic_analysis", "inverse_dynamics",
           "mixed_dynamics", "LinearModel", "linearize", "Modes", "modes", "OperatingPoint",
           "operating_point"]
