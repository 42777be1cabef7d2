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
    buffer, evaluate = f.buffer()
    held = []                       # the arrays the buffer points into, alive until it ran
    for name, value in args.items():
        a = np.ascontiguousarray(np.asarray(value, dtype=float).ravel(order="F"))
        if a.size != f.nnz_in(name):
            raise ValueError(f"argument '{name}' of {f.name()}: {a.size} values, "
                             f"{f.nnz_in(name)} expected")
        held.append(a)
        buffer.set_arg(f.index_in(name), memoryview(a))
    results = []
    for name in outputs:
        sp = f.sparsity_out(name)
        assert sp.is_dense(), f"output '{name}' of {f.name()} is not dense"
        out = np.zeros((sp.size2(), sp.size1()))          # CasADi's column-major storage
        results.append(out)
        if out.size:
            buffer.set_res(f.index_out(name), memoryview(out))
    evaluate()
    return [out.T for out in results]


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
