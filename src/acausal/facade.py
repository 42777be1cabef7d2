"""The facade: ``acausal.compile`` and what users call on its result.

A top module, above every package (core → components → compiler → simulation →
analysis | fmu | ocp): it may import any of them and none imports it. The compiler's record
(``acausal.compiler.CompiledModel``, the seam) knows nothing of simulation or FMUs; the
``CompiledModel`` returned here is that record with the calls users write on it —
``simulate``, ``sweep``, ``export_fmu``, ``mobility``, ``animation`` (behind
``Result.animate``) — each delegating to the layer that does the work.
"""
from __future__ import annotations

from pathlib import Path

from . import compiler
from .compiler.loops import Mobility
from .core.component import Model
from .simulation import Result, SweepResult, initial_state, simulate, sweep
from .simulation.stepper import Stepper


class CompiledModel(compiler.CompiledModel):
    """A compiled model (see ``acausal.compiler.CompiledModel`` for what it holds) with the
    calls users write on it."""

    def simulate(self, t_final: float, **kwargs) -> Result:
        """Simulate; see ``acausal.simulation.simulate`` for the arguments."""
        return simulate(self, t_final, **kwargs)

    def sweep(self, t_final: float, **kwargs) -> SweepResult:
        """Many runs (parameter, start-value and input variations) in one mapped integrator,
        on threads or a dask cluster; see ``acausal.simulation.sweep`` for the arguments."""
        return sweep(self, t_final, **kwargs)

    def stepper(self, dt: float, **kwargs) -> Stepper:
        """A simulation stepped by ``step(u)`` every ``dt`` [s] with the inputs held; see
        ``acausal.simulation.stepper.Stepper`` for the arguments."""
        return Stepper(self, dt, **kwargs)

    def recompiled(self, smooth: bool) -> "CompiledModel":
        """The Model this was compiled from, compiled again in smooth form or not (see
        ``compile``)."""
        return compiler.recompile(self, smooth)

    def export_fmu(self, path, **kwargs) -> Path:
        """Export as an FMU; see ``acausal.fmu.export_fmu`` for the arguments."""
        from .fmu import export_fmu          # needs the 'fmu' extra only when used
        return export_fmu(self, path, **kwargs)

    def animation(self, result: Result, **kwargs):
        """The parts of the model moving as in ``result`` (what ``result.animate()`` gives);
        see ``acausal.analysis.animation.Animation`` for the arguments."""
        from .analysis.animation import Animation
        return Animation(self, result, **kwargs)

    def mobility(self, params: dict | None = None, x0: dict | None = None,
                 guess: dict | None = None, t0: float = 0.0) -> Mobility:
        """Degrees of freedom at the configuration assembled from x0 / guess (Gruebler count
        vs the rank of Φ_q there) and the redundant constraint rows."""
        p = self.param_vector(params)
        u0 = self.input_start
        x, z = initial_state(self, dict(x0 or {}), p, u0, t0, guess)
        return self.mobility_at(t0, x, z, u0, p)[1]


def compile(model: Model, smooth: bool = False, index_reduction: bool = False) -> CompiledModel:
    """Compile ``model`` into a CompiledModel: the CasADi equations of motion by name.
    ``smooth=True``: every component with events in its smooth form (a regularization with
    a named parameter instead of modes and events; what gradient-based optimal control
    needs). The result keeps a reference to ``model`` (``source``): acausal.ocp compiles
    it again in smooth form when given the exact one (``recompiled``). ``index_reduction``:
    loops of capacitors and voltage sources, cut sets of inductors and current sources
    (higher-index networks, refused by default) are reduced by demoting one state each
    (``acausal.compiler.networks``), and so are block equations that constrain states
    (an inverse model's InverseBlockConstraints; ``acausal.compiler.index``)."""
    return CompiledModel.wrap(compiler.compile(model, smooth, index_reduction))


__all__ = ["compile", "CompiledModel"]
