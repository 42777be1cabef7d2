"""Index reduction of block equations that constrain states only (``compiler.index``): inverse
models built with InverseBlockConstraints, against closed forms and scipy's simulation of
the inverse transfer function."""
from __future__ import annotations

import numpy as np
import pytest
from scipy import signal
from scipy.integrate import solve_ivp

import acausal
from acausal import Model, StructureError
from acausal.components import electrical as el
from acausal.components import signals as sg
from acausal.core import Input

TIGHT = dict(rtol=1e-10, atol=1e-12)
A, F, OFFSET = 0.7, 1.5, 0.4          # the reference r(t) = OFFSET + A·sin(2π·F·t)
W = 2 * np.pi * F


def inverse_first_order(m: Model, k: float, T: float, reference) -> None:
    """firstOrder (k, T) inverted: its output held at ``reference``'s, its input computed."""
    m.firstOrder = sg.FirstOrder(k=k, T=T, y_start=5.0)      # a start that cannot hold
    m.inverse = sg.InverseBlockConstraints()
    for a, b in ((reference, m.inverse.u1), (m.firstOrder.y, m.inverse.u2),
                 (m.inverse.y2, m.firstOrder.u)):
        m.connect(a, b)


def test_inverse_of_a_gain_is_an_algebraic_equation():
    """Gain k (direct feedthrough) inverted: u1 = u2 holds the unknown, nothing to reduce;
    u = r/k."""
    m = Model("inverse_gain")
    m.sine = sg.Sine(amplitude=A, f=F, offset=OFFSET)
    m.gain = sg.Gain(k=4.0)
    m.inverse = sg.InverseBlockConstraints()
    for a, b in ((m.sine.y, m.inverse.u1), (m.gain.y, m.inverse.u2), (m.inverse.y2, m.gain.u)):
        m.connect(a, b)
    compiled = acausal.compile(m)
    assert compiled.x_names == [] and compiled.z_names == ["inverse.y1"]
    t = np.linspace(0.0, 1.0, 11)
    res = compiled.simulate(1.0, t=t, **TIGHT)
    np.testing.assert_allclose(res["inverse.y1"], (OFFSET + A * np.sin(W * t)) / 4.0,
                               atol=1e-12)


def test_inverse_of_a_first_order_is_its_input_in_closed_form():
    """FirstOrder T·y' + y = k·u held at y = r(t): u = (T·r' + r)/k; its state becomes r."""
    k, T = 2.0, 0.3
    m = Model("inverse_first_order")
    m.sine = sg.Sine(amplitude=A, f=F, offset=OFFSET)
    inverse_first_order(m, k, T, m.sine.y)
    compiled = acausal.compile(m, index_reduction=True)
    assert compiled.x_names == [] and compiled.z_names == ["inverse.y1"]
    names = compiled.recorded_names                  # the demoted state once (an FMU's too)
    assert names.count("firstOrder.y") == 1 and len(set(names)) == len(names)
    t = np.linspace(0.0, 2.0, 81)
    res = compiled.simulate(2.0, t=t, **TIGHT)
    r, rd = OFFSET + A * np.sin(W * t), A * W * np.cos(W * t)
    np.testing.assert_allclose(res["firstOrder.y"], r, atol=1e-12)
    np.testing.assert_allclose(res["inverse.y1"], (T * rd + r) / k, atol=1e-9)
    np.testing.assert_allclose(res["inverse.y2"], res["inverse.y1"], atol=0)


def test_the_computed_input_drives_a_twin_to_the_reference():
    """The inverse's input fed to an identical FirstOrder started at r(0) (MSL's
    InverseModel check): the twin follows r(t)."""
    k, T = 1.0, 0.2
    m = Model("inverse_and_twin")
    m.sine = sg.Sine(amplitude=A, f=F, offset=OFFSET)
    inverse_first_order(m, k, T, m.sine.y)
    m.twin = sg.FirstOrder(k=k, T=T, y_start=OFFSET)
    m.connect(m.inverse.y1, m.twin.u)
    compiled = acausal.compile(m, index_reduction=True)
    assert compiled.x_names == ["twin.y"]
    t = np.linspace(0.0, 2.0, 81)
    res = compiled.simulate(2.0, t=t, **TIGHT)
    np.testing.assert_allclose(res["twin.y"], OFFSET + A * np.sin(W * t), atol=1e-8)


def test_second_order_inverse_through_a_critical_damping_filter_matches_scipy():
    """Two FirstOrders (T1, T2) in series inverted through a CriticalDamping filter of order
    2 (f_c) of a sine: two reductions (the first constraint's rate holds a state again). The
    computed input is the sine through (T1·s + 1)(T2·s + 1)/(s/w + 1)², that transfer
    function's state space simulated by scipy from rest. The filter is declared last: the states kept are still its own (those of the
    inverted blocks are driven by the unknown input)."""
    T1, T2, fc = 0.3, 0.1, 20.0
    m = Model("inverse_second_order")
    m.sine = sg.Sine(amplitude=A, f=F)
    m.first = sg.FirstOrder(T=T1)
    m.second = sg.FirstOrder(T=T2)
    m.inverse = sg.InverseBlockConstraints()
    m.filter = sg.CriticalDamping(n=2, f=fc, normalized=False)
    for a, b in ((m.sine.y, m.filter.u), (m.filter.y, m.inverse.u1),
                 (m.second.y, m.inverse.u2), (m.inverse.y2, m.first.u),
                 (m.first.y, m.second.u)):
        m.connect(a, b)
    compiled = acausal.compile(m, index_reduction=True)
    assert compiled.x_names == ["filter.x[1]", "filter.x[2]"]
    t = np.linspace(0.0, 1.0, 201)
    res = compiled.simulate(1.0, t=t, **TIGHT)
    w = 2 * np.pi * fc
    num = np.polymul([T1, 1.0], [T2, 1.0])
    den = np.polymul([1 / w, 1.0], [1 / w, 1.0])
    a, b, c, d = signal.tf2ss(num, den)
    sol = solve_ivp(lambda tk, x: a @ x + b[:, 0] * A * np.sin(W * tk), (0.0, 1.0), [0.0, 0.0],
                    t_eval=t, method="DOP853", rtol=1e-12, atol=1e-14)
    u_ref = (c @ sol.y)[0] + d[0, 0] * A * np.sin(W * t)
    np.testing.assert_allclose(res["inverse.y1"], u_ref, atol=1e-7 * np.max(np.abs(u_ref)))
    np.testing.assert_allclose(res["second.y"], res["filter.y"], atol=1e-12)


def test_a_demoted_state_in_a_network_equation():
    """The inverted block's output drives a SignalVoltage across a resistor: the network's
    equations hold the demoted state, so its current is r(t)/R."""
    R = 4.0
    m = Model("inverse_drives_circuit")
    m.sine = sg.Sine(amplitude=A, f=F, offset=OFFSET)
    inverse_first_order(m, 1.0, 0.5, m.sine.y)
    m.source, m.resistor, m.ground = el.SignalVoltage(), el.Resistor(R=R), el.Ground()
    for a, b in ((m.firstOrder.y, m.source.v), (m.source.p, m.resistor.p),
                 (m.resistor.n, m.source.n), (m.source.n, m.ground.p)):
        m.connect(a, b)
    t = np.linspace(0.0, 1.0, 21)
    res = acausal.compile(m, index_reduction=True).simulate(1.0, t=t, **TIGHT)
    np.testing.assert_allclose(res["resistor.i"], (OFFSET + A * np.sin(W * t)) / R,
                               atol=1e-12)


def test_without_index_reduction_the_constraint_is_named():
    m = Model("inverse_refused")
    m.sine = sg.Sine(amplitude=A, f=F)
    inverse_first_order(m, 1.0, 0.3, m.sine.y)
    with pytest.raises(StructureError, match=r"InverseBlockConstraints 'inverse'.*holds no "
                                             r"unknown, only states \(firstOrder\.y\).*"
                                             r"index_reduction=True"):
        acausal.compile(m)


def test_a_constraint_through_a_model_input_needs_its_rate():
    """u1 from a model input: the reduction needs the input's rate, which is unknown."""
    m = Model("inverse_of_input")
    m.command = Input()
    inverse_first_order(m, 1.0, 0.3, m.command.y)
    with pytest.raises(StructureError, match=r"InverseBlockConstraints 'inverse'.*index "
                                             r"reduction:.*time derivative of 'command'"):
        acausal.compile(m, index_reduction=True)


def test_a_constraint_on_given_signals_only_has_no_state_to_demote():
    """u1 and u2 both from sources: the equation fixes no unknown and no state."""
    m = Model("inverse_of_nothing")
    m.a, m.b = sg.Sine(amplitude=A, f=F), sg.Constant(k=1.0)
    m.inverse = sg.InverseBlockConstraints()
    m.sink = sg.Gain()
    for a, b in ((m.a.y, m.inverse.u1), (m.b.y, m.inverse.u2), (m.inverse.y1, m.sink.u)):
        m.connect(a, b)
    with pytest.raises(StructureError, match=r"InverseBlockConstraints 'inverse'.*no state"):
        acausal.compile(m, index_reduction=True)
