"""Progress bars on long work (a simulation, a sweep, an optimization's iterations).

``progress_bar(total, description, progress)`` is a ``tqdm`` bar (the optional dependency
of the 'progress' extra) when ``progress`` is True, and an object that does nothing
otherwise (False or None, or tqdm not installed: a warning then says how to get it). The
bar appears only once the work has taken ``DELAY`` seconds, so short runs stay quiet even
with ``progress=True``. Every caller takes ``progress`` as a flag, default off.
"""
from __future__ import annotations

from ..errors import warn_user

DELAY = 2.0         # s of work before a bar is shown


class _Silent:
    """No progress bar: update and close do nothing."""

    def update(self, n: float = 1) -> None:
        pass

    def close(self) -> None:
        pass


def progress_bar(total: float, description: str, progress: bool | None, unit: str = "s"):
    """A progress bar over ``total`` (seconds of simulated time, runs, iterations: ``unit``)
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
                if unit == "s" else None)
