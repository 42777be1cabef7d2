"""MathBoolean's vector blocks (And, Or, Xor, Nand, Nor with inputs u[1] .. u[nu]) against
numpy's truth tables over every combination of their inputs, and MSL's
Blocks.Examples.BooleanNetwork1 (the network of MathBoolean blocks) against its reference
result."""
from __future__ import annotations

import pickle

import numpy as np
import pytest

import acausal
from acausal import Model, ParameterError
from acausal.components import logical as lg

MB = lg.MathBoolean
SIM = dict(rtol=1e-10, atol=1e-12)


def _after_events(res, name: str, times) -> np.ndarray:
    """``name`` at ``times``, the value after an event where one is."""
    return np.array([res[name][np.flatnonzero(np.abs(res.t - tk) <= 1e-9)[-1]]
                     for tk in times])


LAWS = {"And": lambda u: u.all(axis=0), "Or": lambda u: u.any(axis=0),
        "Xor": lambda u: u.sum(axis=0) == 1, "Nand": lambda u: ~u.all(axis=0),
        "Nor": lambda u: ~u.any(axis=0)}


@pytest.mark.parametrize("nu", [1, 2, 3])
def test_vector_blocks_follow_their_truth_tables(nu):
    """Input k (1-based) toggles every 2**(k-1) s from 1 s on, so the middle of second j
    (j = 0 .. 2**nu − 1) shows the bits of j."""
    m = Model("math_boolean")
    n = 2 ** nu
    for k in range(1, nu + 1):
        step = 2 ** (k - 1)
        setattr(m, f"u{k}", lg.BooleanTable(table=list(np.arange(step, n, step, dtype=float))))
    for name in LAWS:
        block = getattr(MB, name)(nu=nu)
        setattr(m, name.lower(), block)
        for k in range(1, nu + 1):
            m.connect(getattr(m, f"u{k}").y, block.u[k])
    mid = np.arange(n) + 0.5
    res = acausal.compile(m).simulate(mid[-1], t=np.concatenate([[0.0], mid]), **SIM)
    bits = np.array([(np.arange(n) >> (k - 1)) & 1 for k in range(1, nu + 1)], dtype=bool)
    for name, law in LAWS.items():
        np.testing.assert_array_equal(_after_events(res, f"{name.lower()}.y", mid), law(bits),
                                      err_msg=name)


def test_math_boolean_names_and_the_shared_blocks():
    """The namespace holds MSL's names; Not and the edges are Logical's classes."""
    assert MB.Not is lg.Not and MB.RisingEdge is lg.RisingEdge
    assert MB.FallingEdge is lg.FallingEdge and MB.ChangingEdge is lg.ChangingEdge
    assert len(MB.And(nu=4).u) == 4 and MB.Or().nu == 1
    block = pickle.loads(pickle.dumps(MB.Xor(nu=3)))
    assert isinstance(block, MB.Xor) and len(block.u) == 3


@pytest.mark.parametrize("nu", [0, -2, 1.5, True])
def test_bad_nu_is_a_parameter_error_naming_the_block(nu):
    with pytest.raises(ParameterError, match=r"MathBoolean\.Nand: nu"):
        MB.Nand(nu=nu)


def test_boolean_network1_matches_the_msl_reference(reference_result):
    """MSL Blocks.Examples.BooleanNetwork1's MathBoolean chain: and1 (3 inputs) → or1 → xor1
    → nand1 → or2 (Nor) → nor1 (Not); the reference records each block's output as the
    next block's input (or1.u[1] = and1.y, ...), and onDelay.u = booleanTable.y. OnDelay's
    output is not in it: its timing is tested against closed forms elsewhere."""
    ref = reference_result("MAP-LIB_ReferenceResults", "Modelica.Blocks.Examples.BooleanNetwork1")
    m = Model("BooleanNetwork1")
    m.booleanPulse1 = lg.BooleanPulse(width=20, period=1)
    m.booleanPulse2 = lg.BooleanPulse(period=1, width=80)
    m.booleanStep = lg.BooleanStep(startTime=1.5)
    m.and1, m.or1, m.xor1 = MB.And(nu=3), MB.Or(nu=2), MB.Xor(nu=2)
    m.nand1, m.or2, m.nor1 = MB.Nand(nu=2), MB.Nor(nu=2), MB.Not()
    m.booleanTable = lg.BooleanTable(table=[2, 4, 6, 6.5, 7, 9, 11])
    m.onDelay = MB.OnDelay(delayTime=1)
    p2 = m.booleanPulse2.y
    for a, b in ((m.booleanPulse1.y, m.and1.u[1]), (m.booleanStep.y, m.and1.u[2]),
                 (p2, m.and1.u[3]), (m.and1.y, m.or1.u[1]), (p2, m.or1.u[2]),
                 (m.or1.y, m.xor1.u[1]), (p2, m.xor1.u[2]), (m.xor1.y, m.nand1.u[1]),
                 (p2, m.nand1.u[2]), (m.nand1.y, m.or2.u[1]), (p2, m.or2.u[2]),
                 (m.or2.y, m.nor1.u), (m.booleanTable.y, m.onDelay.u)):
        m.connect(a, b)
    t = ref["time"]
    res = acausal.compile(m).simulate(t[-1], t=t, **SIM)
    names = {"and1.y": "or1.u[1]", "or1.y": "xor1.u[1]", "xor1.y": "nand1.u[1]",
             "nand1.y": "or2.u[1]", "booleanTable.y": "onDelay.u"}
    for ours, theirs in names.items():
        np.testing.assert_array_equal(_after_events(res, ours, t), ref[theirs], err_msg=ours)
    # and1 switches 17 times, or1 (= booleanPulse2) 20, the table 6; xor1 is false
    # throughout (or1 = booleanPulse2), so nand1 is true
    assert [np.count_nonzero(np.diff(ref[n])) for n in ("or1.u[1]", "xor1.u[1]", "onDelay.u")] \
        == [17, 20, 6]
    np.testing.assert_array_equal(_after_events(res, "nor1.y", t),
                                  np.logical_or(ref["or2.u[1]"], ref["or2.u[2]"]))
