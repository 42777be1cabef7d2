"""Calls of CasADi Functions that read their arguments from and write their results into
numpy arrays directly (``Function.buffer``): no conversion through DM, which costs more
than the integration itself for the trajectories of a large model (2000 states on 100
output times: 45 ms, the cvodes run 12 ms)."""
from __future__ import annotations

from collections.abc import Sequence

import casadi as ca
import numpy as np


def call(f: ca.Function, args: dict, outputs: list[str]) -> list[np.ndarray]:
    """The dense ``outputs`` of ``f`` by name, as numpy arrays (shape of the output), for
    the arguments ``args`` by name (the others zero). A failure raises RuntimeError as
    calling ``f`` does."""
    return Caller(f, list(args), outputs)(*args.values())


class Caller:
    """``call`` of one Function with the same argument and output names, again and again:
    the buffer, the arguments' arrays and the results' arrays made once (a call then costs
    a few microseconds more than the evaluation, not tens)."""

    def __init__(self, f: ca.Function, inputs: list[str], outputs: list[str]):
        self.name, self.inputs = f.name(), inputs
        self.shapes = []
        for name in outputs:
            sp = f.sparsity_out(name)
            assert sp.is_dense(), f"output '{name}' of {f.name()} is not dense"
            self.shapes.append((sp.size2(), sp.size1()))      # CasADi's column-major storage
        self.buffered = Buffered(f, {name: np.zeros(f.nnz_in(name)) for name in inputs},
                                 outputs)

    def __call__(self, *values) -> list[np.ndarray]:
        """The outputs (new arrays) for the arguments ``values``, in the order of the
        input names."""
        for name, a, value in zip(self.inputs, self.buffered.args, values):
            v = np.asarray(value, dtype=float).ravel(order="F")
            if v.size != a.size:
                raise ValueError(f"argument '{name}' of {self.name}: {v.size} values, "
                                 f"{a.size} expected")
            a[:] = v
        self.buffered.call()
        return [out.reshape(shape).T.copy() for out, shape in zip(self.buffered.res,
                                                                   self.shapes)]


class Buffered:
    """A CasADi Function called through its buffer: its arguments and results are numpy
    arrays (float, contiguous), changed in place and read in place (``args``, ``res``), no
    conversion per call: what a Function called once per step needs. ``args``: every
    argument in order, or some by name (the others zero); ``outputs``: the names of the
    results computed (default: all)."""

    def __init__(self, f: ca.Function, args: Sequence[np.ndarray] | dict[str, np.ndarray],
                 outputs: Sequence[str] | None = None):
        self.buffer, self.call = f.buffer()
        named = args if isinstance(args, dict) else dict(zip(f.name_in(), args))
        self.args = list(named.values())
        for name, a in named.items():
            self.buffer.set_arg(f.index_in(name), memoryview(a))
        names = f.name_out() if outputs is None else list(outputs)
        self.res = [np.zeros(f.nnz_out(name)) for name in names]
        for name, r in zip(names, self.res):
            if r.size:
                self.buffer.set_res(f.index_out(name), memoryview(r))
