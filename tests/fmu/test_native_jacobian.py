"""The native FMU's Jacobian function ``ac_jac`` assembled column by column from the forward
derivative (as for a model whose symbolic Jacobian is too large to compile, e.g. a 3-D
robot's recursion) equals CasADi's symbolic Jacobian of the same equations at random points,
for a model with an input, an output and an algebraic variable and for a closed loop; and a
6-axis arm takes the column route by itself, with far smaller code than its symbolic
Jacobian."""
from __future__ import annotations

import sys
from pathlib import Path

import casadi as ca
import numpy as np
import pytest

import acausal
from acausal import toolchain
from acausal.fmu.codegen import ModelFunctions
from acausal.models import FourBar

sys.path.insert(0, str(Path(__file__).parent))
from test_native_api import Isolator                              # noqa: E402


@pytest.mark.parametrize("make", [Isolator, FourBar])
def test_columns_equal_the_symbolic_jacobian(make, monkeypatch):
    compiled = acausal.compile(make())
    symbolic = ModelFunctions(compiled).functions["ac_jac"]
    monkeypatch.setattr(toolchain, "JACOBIAN_LIMIT", 0)
    monkeypatch.setattr(toolchain, "JACOBIAN_RATIO", 0)
    columns = ModelFunctions(compiled).functions["ac_jac"]
    assert columns.is_a("MXFunction") and symbolic.is_a("SXFunction")
    rng = np.random.default_rng(3)
    p = compiled.param_vector()
    for _ in range(5):
        args = [rng.normal(size=symbolic.size_in(i)) for i in range(4)] + [p]
        for a, b in zip(symbolic(*args), columns(*args)):
            a, b = np.array(a), np.array(b)
            assert a.shape == b.shape
            assert np.allclose(a, b, rtol=1e-12, atol=1e-12 * max(1.0, np.max(np.abs(a),
                                                                               initial=0)))
    assert np.max(np.abs(np.array(symbolic(*args)[0]))) > 0.1


def test_a_robot_takes_the_columns(monkeypatch):
    """The UR5's symbolic Jacobian is too large to compile in reasonable time: its columns
    from the forward derivative are generated instead, in a fraction of the C."""
    ur5 = pytest.importorskip("test_native_robot").ur5_model
    compiled = acausal.compile(ur5())
    columns = ModelFunctions(compiled).functions["ac_jac"]
    monkeypatch.setattr(toolchain, "JACOBIAN_LIMIT", 10 ** 9)
    symbolic = ModelFunctions(compiled).functions["ac_jac"]
    assert columns.is_a("MXFunction") and symbolic.is_a("SXFunction")

    def c_size(f):
        gen = ca.CodeGenerator("f.c")
        gen.add(f)
        return len(gen.dump())
    assert 2 * c_size(columns) < c_size(symbolic)
