"""TransferFunction and StateSpace (acausal.components.signals) against scipy.signal.

Responses to steps (which scipy.signal.lsim integrates exactly, by the matrix exponential)
from non-zero x_start; the initializations SteadyState and InitialOutput against their
conditions solved by hand with numpy (InitialOutput of StateSpace: MSL's
equalityLeastSquares as the KKT system of the constrained least squares); the compiled
model's A matrix (acausal.analysis.linearize) against scipy.signal.tf2ss's controller
canonical form.
"""
from __future__ import annotations

import pickle

import numpy as np
import pytest
import scipy.signal as sig

import acausal
from acausal import Model, ParameterError
from acausal.analysis import linearize
from acausal.components import signals as sg

SIM = dict(rtol=1e-11, atol=1e-13)
T = np.linspace(0.0, 4.0, 81)


def _tf_model(height=1.5, **kw) -> Model:
    m = Model("tf_test")
    m.step = sg.Step(height=height)
    m.tf = sg.TransferFunction(**kw)
    m.connect(m.step.y, m.tf.u)
    return m


def _tf_step(b, a, height, x0=None):
    """y and x of b/a under u = height from x0 (MSL's x: scipy's tf2ss states / a[1])."""
    A, B, C, D = sig.tf2ss(b, a)
    x0 = None if x0 is None else np.asarray(x0) * a[0]
    _, y, x = sig.lsim((A, B, C, D), height * np.ones_like(T), T, X0=x0)
    return y, np.reshape(x, (T.size, -1)) / a[0]


@pytest.mark.parametrize("b, a, x_start", [
    ([2.0, 4.0], [1.0, 3.0, 2.0], [0.3, -0.2]),              # strictly proper, monic
    ([0.5, -1.0, 3.0], [2.0, 1.0, 4.0], [0.1, 0.4]),         # biproper, a[1] != 1 (d != 0)
    ([1.0], [0.5, 1.2, 0.8, 0.3], [0.2, -0.1, 0.5]),         # third order
    ([3.0, 1.0], [1.0, 2.0, 0.0], [0.4, 0.7]),               # a[end] = 0: unscaled states
])
def test_transfer_function_step_from_x_start(b, a, x_start):
    c = acausal.compile(_tf_model(b=b, a=a, x_start=x_start))
    res = c.simulate(T[-1], t=T, **SIM)
    y, x = _tf_step(b, a, 1.5, x_start)
    assert np.abs(res["tf.y"] - y).max() < 1e-8
    for i in range(len(a) - 1):
        assert np.abs(res[f"tf.x[{i + 1}]"] - x[:, i]).max() < 1e-8


def test_transfer_function_states_are_msl_scaled():
    c = acausal.compile(_tf_model(b=[2.0, 4.0], a=[1.0, 3.0, 2.0], x_start=[0.3, -0.2]))
    assert c.x_names == ["tf.x_scaled[1]", "tf.x_scaled[2]"]
    res = c.simulate(1.0, t=np.linspace(0, 1, 3), **SIM)
    # x_scaled = x * a_end, a_end = a[3] = 2
    assert res["tf.x_scaled[1]"][0] == pytest.approx(0.6, abs=1e-12)
    assert res["tf.x_scaled[2]"][0] == pytest.approx(-0.4, abs=1e-12)


def test_transfer_function_static_gain():
    c = acausal.compile(_tf_model(b=[3.0], a=[2.0]))
    res = c.simulate(1.0, t=np.linspace(0, 1, 3), **SIM)
    np.testing.assert_allclose(res["tf.y"], 1.5 * 1.5, atol=1e-14)


def test_transfer_function_steady_state():
    b, a = [0.5, -1.0, 3.0], [2.0, 1.0, 4.0]
    c = acausal.compile(_tf_model(b=b, a=a, initType="SteadyState"))
    res = c.simulate(T[-1], t=T, **SIM)
    np.testing.assert_allclose(res["tf.y"], 1.5 * b[-1] / a[-1], atol=1e-10)


def test_transfer_function_initial_output():
    """y(0) = y_start and der(x_scaled[2:nx]) = 0: x[1:nx-1] = 0, the last state gives y;
    then the step response from that state."""
    b, a, y_start = [1.0, 2.0, 3.0], [1.0, 1.2, 0.8, 0.3], 0.7
    c = acausal.compile(_tf_model(b=b, a=a, initType="InitialOutput", y_start=y_start))
    res = c.simulate(T[-1], t=T, **SIM)
    # x = [0, 0, x3]: y = (bb - d a)[4] x3 + d u with d = 0  ->  x3 = y_start / b[3]
    x_start = [0.0, 0.0, y_start / b[2]]
    y, _ = _tf_step(b, a, 1.5, x_start)
    assert res["tf.y"][0] == pytest.approx(y_start, abs=1e-12)
    assert np.abs(res["tf.y"] - y).max() < 1e-8


def test_transfer_function_a_matrix_is_controller_canonical_form():
    b, a = [1.0, 2.0, 3.0], [2.0, 1.2, 0.8, 0.3]
    m = Model("tf_lin")
    m.u = acausal.Input()
    m.tf = sg.TransferFunction(b=b, a=a)
    m.y = acausal.Output()
    m.connect(m.u.y, m.tf.u)
    m.connect(m.tf.y, m.y.u)
    lin = linearize(acausal.compile(m), {})
    A, B, C, D = sig.tf2ss(b, a)
    np.testing.assert_allclose(lin.A, A, atol=1e-14)
    # the same transfer function: C (sI - A)^-1 B + D at a few frequencies
    for s in (0.3j, 1.0 + 2.0j, 5.0j):
        g = lin.C @ np.linalg.solve(s * np.eye(3) - lin.A, lin.B) + lin.D
        assert g[0, 0] == pytest.approx(np.polyval(b, s) / np.polyval(a, s), rel=1e-12)


def test_transfer_function_coefficients_are_parameters():
    """b and a change at simulation time without recompiling."""
    c = acausal.compile(_tf_model(b=[1.0], a=[1.0, 1.0]))
    res = c.simulate(T[-1], t=T, params={"tf.b": [2.0], "tf.a[2]": 4.0}, **SIM)
    y, _ = _tf_step([2.0], [1.0, 4.0], 1.5)
    assert np.abs(res["tf.y"] - y).max() < 1e-8


def test_transfer_function_errors_and_pickle():
    with pytest.raises(ParameterError, match="not proper"):
        sg.TransferFunction(b=[1.0, 2.0, 3.0], a=[1.0, 2.0])
    with pytest.raises(ParameterError, match=r"a\[1\] must be non-zero"):
        sg.TransferFunction(b=[1.0], a=[0.0, 2.0])
    with pytest.raises(ParameterError, match="x_start must have 2 values"):
        sg.TransferFunction(b=[1.0], a=[1.0, 2.0, 3.0], x_start=[1.0, 2.0, 3.0])
    tf = sg.TransferFunction("g", b=[2.0, 4.0], a=[1.0, 3.0], x_start=[0.5])
    back = pickle.loads(pickle.dumps(tf))
    assert type(back) is type(tf) and back.b == (2.0, 4.0) and back.x_start == (0.5,)


# ---- StateSpace --------------------------------------------------------------------------------
A = np.array([[-1.0, 2.0, 0.0], [-2.0, -1.0, 1.0], [0.0, 0.5, -3.0]])
B = np.array([[1.0, 0.0], [0.0, 2.0], [1.0, -1.0]])
C = np.array([[1.0, 0.0, 1.0], [0.0, 1.0, 0.0]])
D = np.array([[0.0, 0.5], [0.1, 0.0]])
U = np.array([1.5, -0.5])


def _ss_model(**kw) -> Model:
    m = Model("ss_test")
    m.s1, m.s2 = sg.Step(height=U[0]), sg.Step(height=U[1])
    m.ss = sg.StateSpace(**kw)
    m.connect(m.s1.y, m.ss.u[1])
    m.connect(m.s2.y, m.ss.u[2])
    return m


def _ss_response(res):
    return (np.column_stack([res[f"ss.y[{i}]"] for i in (1, 2)]),
            np.column_stack([res[f"ss.x[{i}]"] for i in (1, 2, 3)]))


def test_state_space_mimo_step_from_x_start():
    x_start = [0.3, -0.2, 1.0]
    c = acausal.compile(_ss_model(A=A, B=B, C=C, D=D, x_start=x_start))
    y, x = _ss_response(c.simulate(T[-1], t=T, **SIM))
    _, y_ref, x_ref = sig.lsim((A, B, C, D), np.tile(U, (T.size, 1)), T, X0=x_start)
    assert np.abs(y - y_ref).max() < 1e-8 and np.abs(x - x_ref).max() < 1e-8


def test_state_space_steady_state():
    c = acausal.compile(_ss_model(A=A, B=B, C=C, D=D, initType="SteadyState"))
    y, x = _ss_response(c.simulate(T[-1], t=T, **SIM))
    x_ss = np.linalg.solve(A, -B @ U)
    np.testing.assert_allclose(x, np.tile(x_ss, (T.size, 1)), atol=1e-10)
    np.testing.assert_allclose(y[0], C @ x_ss + D @ U, atol=1e-12)


def test_state_space_initial_output_is_equality_least_squares():
    """x(0) = argmin |A x + B u| subject to C x = y_start − D u (KKT system by numpy)."""
    y_start = np.array([0.7, 0.2])
    c = acausal.compile(_ss_model(A=A, B=B, C=C, D=D, initType="InitialOutput",
                                  y_start=y_start))
    y, x = _ss_response(c.simulate(T[-1], t=T, **SIM))
    kkt = np.block([[A.T @ A, C.T], [C, np.zeros((2, 2))]])
    x0 = np.linalg.solve(kkt, np.r_[-A.T @ B @ U, y_start - D @ U])[:3]
    np.testing.assert_allclose(x[0], x0, atol=1e-10)
    np.testing.assert_allclose(y[0], y_start, atol=1e-10)
    _, y_ref, _ = sig.lsim((A, B, C, D), np.tile(U, (T.size, 1)), T, X0=x0)
    assert np.abs(y - y_ref).max() < 1e-8


def test_state_space_msl_defaults_and_parameters():
    """MSL's defaults A = I, B = [1; 1], C = [1, 1], D = 0 (one input, one output); the
    matrices are parameters, changed at simulation time by name (row by row)."""
    ss = sg.StateSpace()
    assert (ss.nx, ss.nin, ss.nout) == (2, 1, 1) and ss.A == (1.0, 0.0, 0.0, 1.0)
    m = Model("ss_default")
    m.step, m.ss = sg.Step(height=1.0), sg.StateSpace()
    m.connect(m.step.y, m.ss.u[1])
    c = acausal.compile(m)
    A2 = np.array([[-1.0, 0.5], [0.0, -2.0]])
    res = c.simulate(T[-1], t=T, params={"ss.A": A2}, **SIM)
    _, y_ref, _ = sig.lsim((A2, [[1.0], [1.0]], [[1.0, 1.0]], [[0.0]]), np.ones_like(T), T)
    assert np.abs(res["ss.y[1]"] - y_ref).max() < 1e-8


def test_state_space_shapes_are_checked():
    with pytest.raises(ParameterError, match="A must be square"):
        sg.StateSpace(A=[[1.0, 2.0]], B=[[1.0]], C=[[1.0]])
    with pytest.raises(ParameterError, match=r"B must have shape \(2, m\)"):
        sg.StateSpace(A=np.eye(2), B=[[1.0], [1.0], [1.0]], C=[[1.0, 1.0]])
    with pytest.raises(ParameterError, match=r"D must have shape \(1, 1\)"):
        sg.StateSpace(A=np.eye(2), B=[[1.0], [1.0]], C=[[1.0, 1.0]], D=[[1.0, 2.0]])
    with pytest.raises(ParameterError, match="InitialOutput needs C of full row rank"):
        sg.StateSpace(A=np.eye(2), B=[[1.0], [1.0]], C=[[1.0, 1.0], [2.0, 2.0]],
                      initType="InitialOutput")
    ss = sg.StateSpace("s", A=A, B=B, C=C, D=D, x_start=[1.0, 2.0, 3.0])
    back = pickle.loads(pickle.dumps(ss))
    assert type(back) is type(ss) and back.D == tuple(D.ravel()) and back.nin == 2
