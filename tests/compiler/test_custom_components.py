"""User-written components (acausal.models.custom_components, shown by
examples/custom_components.py, and one defined here) against hand-written ODEs integrated with
scipy at tight tolerances."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.core import Component, Parameter, RotationalFlange
from acausal.models.custom_components import duffing_model, motor_model

TIGHT = dict(rtol=1e-12, atol=1e-14, method="DOP853")


class ViscousLoad(Component):
    """Viscous friction to the ground: torque −b·w on the shaft (a component in 6 lines)."""
    b = Parameter(0.0, "N.m.s/rad", "friction coefficient", nonnegative=True)
    flange = RotationalFlange("shaft")

    def physics(self, e):
        e.flow(self.flange, self.b * e.vel(self.flange))


# ---- cubic (hardening) spring -------------------------------------------------------------
M, C, C3 = 1.0, 4.0, 40.0


@pytest.fixture(scope="module")
def duffing():
    return acausal.compile(duffing_model(m=M, c=C, c3=C3))


def duffing_ref(t, x0, v0, c3=C3):
    sol = solve_ivp(lambda _, y: [y[1], -(C * y[0] + c3 * y[0] ** 3) / M], (t[0], t[-1]),
                    [x0, v0], t_eval=t, **TIGHT)
    return sol.y


@pytest.mark.parametrize("amp", [0.05, 0.5])
def test_cubic_spring_against_scipy(duffing, amp):
    t = np.linspace(0, 5.0, 501)
    res = duffing.simulate(5.0, t=t, x0={"mass.s": amp, "mass.v": 0.3}, rtol=1e-10, atol=1e-12)
    x, v = duffing_ref(t, amp, 0.3)
    np.testing.assert_allclose(res["mass.s"], x, rtol=0, atol=1e-6)
    np.testing.assert_allclose(res["mass.v"], v, rtol=0, atol=1e-6)
    np.testing.assert_allclose(res["spring.f"], C * x + C3 * x ** 3, rtol=0, atol=1e-5)
    # conservative: ½mv² + ½cδ² + ¼c3δ⁴ stays constant
    E = 0.5 * M * res["mass.v"] ** 2 + 0.5 * C * res["mass.s"] ** 2 + 0.25 * C3 * res["mass.s"] ** 4
    assert np.ptp(E) / E[0] < 1e-6


def test_cubic_spring_parameter_at_simulation_time(duffing):
    """The nonlinearity matters (period changes with amplitude) and c3 can be changed."""
    t = np.linspace(0, 5.0, 501)
    res = duffing.simulate(5.0, t=t, params={"spring.c3": 0.0}, x0={"mass.s": 0.5})
    np.testing.assert_allclose(res["mass.s"], 0.5 * np.cos(2.0 * t), atol=1e-6)
    res = duffing.simulate(5.0, t=t, params={"spring.c3": 100.0}, x0={"mass.s": 0.5},
                           rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(res["mass.s"], duffing_ref(t, 0.5, 0.0, c3=100.0)[0], atol=1e-6)
    assert np.max(np.abs(res["mass.s"] - 0.5 * np.cos(2.0 * t))) > 0.1


# ---- DC motor with the armature current as a state -----------------------------------------
R, L, K, J, B = 0.5, 0.02, 0.08, 2e-3, 1e-3


@pytest.fixture(scope="module")
def drive():
    model = motor_model(R=R, L=L, k=K, J=J)
    model.load = ViscousLoad(b=B)
    model.connect(model.load.flange, model.rotor.flange_b)
    return acausal.compile(model)


def motor_ref(t, v, i0=0.0, w0=0.0):
    def rhs(tt, y):
        i, w = y
        return [(v(tt) - R * i - K * w) / L, (K * i - B * w) / J]
    return solve_ivp(rhs, (t[0], t[-1]), [i0, w0], t_eval=t, **TIGHT).y


def test_motor_states(drive):
    assert "motor.i" in drive.x_names
    assert drive.coordinates == ["rotor.phi"]


def test_motor_step_against_scipy(drive):
    t = np.linspace(0, 4.0, 801)                 # 4 s: ~27 mechanical time constants
    res = drive.simulate(4.0, t=t, rtol=1e-10, atol=1e-12)          # V starts at 12 V
    i, w = motor_ref(t, lambda _: 12.0)
    np.testing.assert_allclose(res["motor.i"], i, rtol=0, atol=1e-6)
    np.testing.assert_allclose(res["rotor.w"], w, rtol=0, atol=1e-6)
    np.testing.assert_allclose(res["motor.tau"], K * i, rtol=0, atol=1e-7)
    # the shaft carries the motor torque: flows at the motor's flange
    np.testing.assert_allclose(res["motor.flange.tau"], -K * i, rtol=0, atol=1e-7)
    np.testing.assert_allclose(res["load.flange.tau"], B * w, rtol=0, atol=1e-7)
    # steady state: w = k v / (k² + R b), i = b w / k
    w_ss = K * 12.0 / (K ** 2 + R * B)
    assert res["rotor.w"][-1] == pytest.approx(w_ss, rel=1e-6)
    assert res["motor.i"][-1] == pytest.approx(B * w_ss / K, rel=1e-5)


def test_motor_sine_voltage_and_initial_current(drive):
    t = np.linspace(0, 0.5, 251)
    res = drive.simulate(0.5, t=t, inputs={"V": lambda tt: 6.0 * np.sin(20.0 * tt)},
                         x0={"motor.i": 2.0, "rotor.w": 10.0}, rtol=1e-10, atol=1e-12)
    i, w = motor_ref(t, lambda tt: 6.0 * np.sin(20.0 * tt), i0=2.0, w0=10.0)
    np.testing.assert_allclose(res["motor.i"], i, rtol=0, atol=1e-6)
    np.testing.assert_allclose(res["rotor.w"], w, rtol=0, atol=1e-6)


def test_motor_parameters_at_simulation_time(drive):
    """J and R changed at simulation time, checked against the hand ODE with the new values."""
    t = np.linspace(0, 0.5, 251)
    res = drive.simulate(0.5, t=t, params={"rotor.J": 2 * J, "motor.R": 1.0}, rtol=1e-10,
                         atol=1e-12)

    def rhs(tt, y):
        i, w = y
        return [(12.0 - 1.0 * i - K * w) / L, (K * i - B * w) / (2 * J)]
    i, w = solve_ivp(rhs, (0, 0.5), [0, 0], t_eval=t, **TIGHT).y
    np.testing.assert_allclose(res["motor.i"], i, rtol=0, atol=1e-6)
    np.testing.assert_allclose(res["rotor.w"], w, rtol=0, atol=1e-6)
