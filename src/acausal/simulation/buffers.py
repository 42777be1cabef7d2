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
        self.name, self.buffer_call = f.name(), f.buffer()
        buffer = self.buffer_call[0]
        self.args = [np.zeros(f.nnz_in(name)) for name in inputs]
        self.inputs = inputs
        for name, a in zip(inputs, self.args):
            buffer.set_arg(f.index_in(name), memoryview(a))
        self.res = []
        for name in outputs:
            sp = f.sparsity_out(name)
            assert sp.is_dense(), f"output '{name}' of {f.name()} is not dense"
            out = np.zeros((sp.size2(), sp.size1()))      # CasADi's column-major storage
            self.res.append(out)
            if out.size:
                buffer.set_res(f.index_out(name), memoryview(out))

    def __call__(self, *values) -> list[np.ndarray]:
        """The outputs (new arrays) for the arguments ``values``, in the order of the
        input names."""
        for name, a, value in zip(self.inputs, self.args, values):
            v = np.asarray(value, dtype=float).ravel(order="F")
            if v.size != a.size:
                raise ValueError(f"argument '{name}' of {self.name}: {v.size} values, "
                                 f"{a.size} expected")
            a[:] = v
        self.buffer_call[1]()
        return [out.T.copy() for out in self.res]


class Buffered:
    """A CasADi Function called through its buffer: its arguments and results are numpy
    arrays (float, contiguous), changed in place and read in place (``args``, ``res``), no
    conversion per call: what a Function called once per step needs."""

    def __init__(self, f: ca.Function, args: Sequence[np.ndarray]):
        self.buffer, self.call = f.buffer()
        self.args = list(args)
        self.res = [np.zeros(f.nnz_out(i)) for i in range(f.n_out())]
        for i, a in enumerate(self.args):
            self.buffer.set_arg(i, memoryview(a))
        for i, r in enumerate(self.res):
            self.buffer.set_res(i, memoryview(r))
