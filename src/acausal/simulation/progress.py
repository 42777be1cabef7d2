"""Progress bars on long work (a simulation, a sweep, an optimization's iterations), and
the warning of a run interrupted by Ctrl-C.

``progress_bar(total, description, progress)`` is a ``tqdm`` bar (the optional dependency
of the 'progress' extra) when ``progress`` is True, and an object that does nothing
otherwise (False or None, or tqdm not installed: a warning then says how to get it). The
bar appears only once the work has taken ``DELAY`` seconds, so short runs stay quiet even
with ``progress=True``. Every caller takes ``progress`` as a flag, default off.
"""
from __future__ import annotations

import casadi as ca

from ..errors import warn_user

DELAY = 2.0         # s of work before a bar is shown


class _Silent:
    """No progress bar: update and close do nothing."""

    def update(self, n: float = 1) -> None:
        pass

    def close(self) -> None:
        pass


def progress_bar(total: float | None, description: str, progress: bool | None,
                 unit: str = "s"):
    """A progress bar over ``total`` (seconds of simulated time, runs, iterations: ``unit``;
    None: a counter without an end)
    if ``progress`` is True (see the module docstring); ``update(n)`` advances it by n,
    ``close()`` ends it."""
    if not progress:
        return _Silent()
    try:
        from tqdm.auto import tqdm
    except ImportError:
        warn_user("progress=True needs the tqdm package: pip install 'acausal[progress]'")
        return _Silent()
    return tqdm(total=total, desc=description, unit=unit, delay=DELAY, leave=False,
                bar_format="{l_bar}{bar}| {n:.4g}/{total:.4g} {unit} [{elapsed}<{remaining}]"
                if unit == "s" and total else None)


def time_reporter(bar, t0: float):
    """A callable of the time integrated to that advances ``bar`` (over simulated time from
    t0) to it."""
    done = [t0]

    def reached(t: float) -> None:
        if t > done[0]:
            bar.update(t - done[0])
            done[0] = t
    return reached


def warn_interrupted(name: str, t: float) -> None:
    """The warning of a simulation of ``name`` interrupted (Ctrl-C), its Result kept up to
    t [s]."""
    warn_user(f"simulation of '{name}' interrupted: the Result holds the output times up to "
              f"t = {t:g} s (Result.partial is True)")


class IterationProgress(ca.Callback):
    """An ``iteration_callback`` for a CasADi nlpsol with nx variables, ng constraints and np
    parameters: advances ``bar`` (a ``progress_bar``, set before each solve) by one per
    iteration and never stops the solver."""

    def __init__(self, nx: int, ng: int, np_: int):
        ca.Callback.__init__(self)
        self.sizes = {"x": nx, "lam_x": nx, "g": ng, "lam_g": ng, "lam_p": np_, "f": 1}
        self.bar = _Silent()
        self.construct("iterations", {})

    def get_n_in(self):
        return ca.nlpsol_n_out()

    def get_n_out(self):
        return 1

    def get_name_in(self, i):
        return ca.nlpsol_out(i)

    def get_name_out(self, i):
        return "ret"

    def get_sparsity_in(self, i):
        return ca.Sparsity.dense(self.sizes.get(ca.nlpsol_out(i), 0), 1)

    def eval(self, arg):
        self.bar.update(1)
        return [0]
