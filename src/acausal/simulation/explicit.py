"""simulate(..., solver='dop853'): an explicit Runge–Kutta method of order 8 for non-stiff ODEs.

scipy's ``DOP853`` (Dormand–Prince 8(5,3), Hairer's DOP853: the method of
``scipy.integrate.solve_ivp(method='DOP853')``, with its step-size control and its dense
output of order 7 onto the output grid) steps the model's right-hand side ẋ = f(x, t): the
generated C with ``codegen=True`` (``acausal.simulation.codegen``), else the in-process
CasADi Function with the parameter values folded in, as the other solvers see it. It is
called from Python through ``Function.buffer()``: about a microsecond per call besides the
arithmetic, against tens of microseconds for a plain call.

On smooth non-stiff motion (pendulums, robot arms, chains without stiff springs) an
order-8 method takes large steps: at equal accuracy it needs a fraction of the right-hand
sides that cvodes' Adams method needs at the tighter tolerance it takes to get there (a
3-D chain of 64 links, 1 s: Adams needs rtol 1e-10 to match DOP853's error at 1e-8).
scipy takes the steps in Python, some 20-30 us per stage besides the right-hand side: it
pays where the right-hand side is heavy (a 3-D chain of tens of links, generated C of tens
of us); on a light one Adams, stepping in C, is faster (the planar 24-link pendulum, 10 s:
8789 right-hand sides in 0.32 s, Adams on the same generated C 0.04 s).
It has no Newton iteration and no Jacobian, so a stiff model (a stiff spring, a fast
electrical time constant) makes it take tiny steps: the run then stops after
``MAX_STEPS`` steps and says so. The automatic choice of simulate() never picks it: the
spectral radius that tells stiff from non-stiff does not tell whether the motion is smooth
and the right-hand side heavy enough for order 8 in Python to pay off over Adams in C, and
scipy is an optional dependency; ask for it.

Only ODEs without events: algebraic variables (closed loops, massless nodes) need IDAS,
state events and modes need the event engine (``acausal.simulation.events``). Time events
and jumps of the inputs are handled as by the other solvers: the run restarts at each one.
"""
from __future__ import annotations

from bisect import bisect_right

import casadi as ca
import numpy as np

from ..errors import SimulationError
from .buffers import Buffered

NAME = "dop853"
MAX_STEPS = 100000          # steps per segment between time events (as cvodes' default here)
OPTIONS = ("first_step", "max_num_steps")


def check_supported(model) -> None:
    """Refuse what an explicit ODE solver cannot integrate: DAEs and models with events."""
    if model.z.numel():
        what = "closed kinematic loops" if model.has_loops else "algebraic variables"
        raise SimulationError(
            f"model '{model.name}' has {what} ({', '.join(model.z_names[:3])}, ...): "
            f"solver='dop853' integrates ODEs only; use solver='idas' (or the default)")
    if model.has_events:
        raise SimulationError(
            f"model '{model.name}' has state events or modes, which solver='dop853' does not "
            f"handle; use the default solver (cvodes with event location)")


class Dop853:
    """DOP853 runs of a model's ODE over the segments between time events.

    ``dae``: the integrator problem {'x', 't', 'ode'} in the scaled states (as the CasADi
    integrators get it); rtol, atol: tolerances on the scaled states; ``options``: the
    keys OPTIONS ('first_step' [s], 'max_num_steps' per segment); ``reached(t)`` is told
    the time integrated to after every step (progress)."""

    def __init__(self, model, dae: dict, rtol: float, atol: float,
                 max_step: float | None, options: dict, reached=lambda t: None):
        try:
            from scipy.integrate import DOP853
        except ImportError:
            raise SimulationError("solver='dop853' needs scipy: pip install "
                                  "'acausal[analysis]'") from None
        unknown = sorted(set(options) - set(OPTIONS))
        if unknown:
            raise SimulationError(f"solver='dop853' takes the options {list(OPTIONS)}, not "
                                  f"{unknown}")
        first, most = options.get("first_step"), options.get("max_num_steps", MAX_STEPS)
        if first is not None and not (isinstance(first, (int, float)) and 0 < first < np.inf):
            raise SimulationError(f"options['first_step'] must be a number > 0 [s], got "
                                  f"{first!r}")
        if not (isinstance(most, (int, np.integer)) and most >= 1):
            raise SimulationError(f"options['max_num_steps'] must be an integer >= 1, got "
                                  f"{most!r}")
        self.model, self.method, self.reached = model, DOP853, reached
        self.settings = dict(rtol=rtol, atol=atol, max_step=np.inf if max_step is None
                             else max_step, first_step=first)
        self.max_steps = int(most)
        f = ca.Function("rhs", [dae["x"], dae["t"]], [dae["ode"]])
        self._f = Buffered(f, [np.zeros(f.nnz_in(0)), np.zeros(1)])

    def rhs(self, t: float, x: np.ndarray) -> np.ndarray:
        """ẋ at (t, x), a new array (the solver keeps it)."""
        self._f.args[0][:] = x
        self._f.args[1][0] = t
        self._f.call()
        return self._f.res[0].copy()

    def run(self, a: float, end: float, x: np.ndarray, pts: list[float], X: list) -> np.ndarray:
        """Integrate from x at a to end, the states at the output times ``pts`` (in (a,
        end], ascending) appended to X column by column as the steps pass them; the state at
        end."""
        if end <= a:
            return x
        solver = self.method(self.rhs, a, x, end, **self.settings)
        k, steps = 0, 0
        while solver.status == "running":
            said = solver.step()
            if solver.status == "failed":
                raise SimulationError(self._failure(a, end, solver.t, said))
            j = bisect_right(pts, solver.t)
            if j > k:
                X.append(solver.dense_output()(pts[k:j]))
                k = j
            self.reached(solver.t)
            steps += 1
            if steps >= self.max_steps and solver.status == "running":
                raise SimulationError(self._failure(a, end, solver.t, None))
        return solver.y

    def _failure(self, a, end, t, said) -> str:
        head = f"simulation of '{self.model.name}' with solver='dop853' failed between " \
               f"t = {a:g} and {end:g} s, at t = {t:g} s"
        if said is None:
            return (f"{head}: {self.max_steps} steps did not reach the end (max_num_steps): the "
                    f"model is stiff there (an explicit method needs tiny steps); use "
                    f"solver='cvodes', or raise the limit with options={{'max_num_steps': n}}")
        return (f"{head}: {said.rstrip('.')} (the step size the error test asks for is "
                f"below rounding): the equations are not finite or change abruptly there, or "
                f"the model is stiff; check the parameters and initial values, or use "
                f"solver='cvodes'")
