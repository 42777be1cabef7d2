"""The stepping interface against the exact discretization of a linear oscillator
(matrix exponential), simulate() with held samples, a closed loop simulated by simulate()
and the closed form of a bouncing ball."""
import numpy as np
import pytest

import acausal
from acausal.errors import SimulationError
from acausal.simulation import Samples
from forced_oscillator import forced_oscillator, oscillator_system
from lti import held_input_flow

MASS, STIFF, DAMP = 0.5, 8.0, 0.3
DT = 0.05


@pytest.fixture(scope="module")
def compiled():
    return acausal.compile(forced_oscillator(MASS, STIFF, DAMP))


def exact_steps(x0, forces, dt, m=MASS):
    """States [s, v] after each held force: x_{k+1} = e^{A dt} x_k + ∫ e^{A τ} dτ B F_k (the
    augmented matrix exponential), the spring unstretched at s = 0."""
    Phi, Gam = held_input_flow(*oscillator_system(m, STIFF, DAMP), dt)
    x, out = np.asarray(x0, dtype=float), []
    for F in forces:
        x = Phi @ x + Gam * F
        out.append(x)
    return np.array(out)


FORCES = np.sin(0.7 * np.arange(60)) + 0.3


@pytest.mark.parametrize("solver, tol", [("dopri", 1e-9), ("cvodes", 1e-8),
                                         ("collocation", 1e-8)])
def test_steps_equal_the_exact_discretization(compiled, solver, tol):
    st = compiled.stepper(DT, x0={"mass.s": 0.1, "mass.v": -0.2}, rtol=1e-11, atol=1e-13,
                          solver=solver)
    got = np.array([[y["mass.s"], y["mass.v"]] for y in (st.step({"F": F}) for F in FORCES)])
    np.testing.assert_allclose(got, exact_steps([0.1, -0.2], FORCES, DT), rtol=0, atol=tol)
    assert st.t == pytest.approx(DT * FORCES.size, abs=1e-12)


def test_new_parameters_without_rebuilding(compiled):
    st = compiled.stepper(DT, rtol=1e-11, atol=1e-13)
    st.reset(x0={"mass.s": 0.1}, params={"mass.m": 2.0})
    got = np.array([st.step([F])["mass.s"] for F in FORCES[:20]])
    np.testing.assert_allclose(got, exact_steps([0.1, 0.0], FORCES[:20], DT, m=2.0)[:, 0],
                               atol=1e-9)


def test_steps_equal_simulate_with_held_samples(compiled):
    st = compiled.stepper(DT, x0={"mass.s": 0.1}, outputs=["mass.s", "spring.f"])
    got = np.array([list(st.step({"F": F}).values()) for F in FORCES])
    times = DT * np.arange(FORCES.size + 1)
    res = compiled.simulate(times[-1], t=times, x0={"mass.s": 0.1},
                            inputs={"F": Samples(times, np.append(FORCES, FORCES[-1]), "hold")})
    np.testing.assert_allclose(got[:, 0], res["mass.s"][1:], atol=1e-7)
    np.testing.assert_allclose(got[:, 1], res["spring.f"][1:], atol=1e-6)


def test_state_set_and_get_round_trip(compiled):
    st = compiled.stepper(DT)
    st.state = {"mass.v": 0.5}
    assert st.state == {"mass.s": 0.0, "mass.v": 0.5}
    st.x = [0.2, -0.1]
    assert st.state == {"mass.s": 0.2, "mass.v": -0.1}
    np.testing.assert_array_equal(st.x, [0.2, -0.1])
    a = st.step({"F": 1.0})
    st.x = [0.2, -0.1]
    st.reset(x0={"mass.s": 0.2, "mass.v": -0.1}, t0=0.0)
    assert st.step({"F": 1.0}) == a
    st.reset()
    assert st.t == 0.0 and st.state == {"mass.s": 0.0, "mass.v": 0.0}


def test_closed_loop_dae_steps_like_simulate():
    from acausal.models.linkages import FourBar
    model = acausal.compile(FourBar())
    ends = [f"rev4.frame_{f}.{c}" for f in "ab" for c in "xy"]
    with pytest.warns(UserWarning, match="close the kinematic loops"):
        st = model.stepper(0.02, outputs=ends)
    with pytest.warns(UserWarning, match="close the kinematic loops"):
        res = model.simulate(0.4, t=np.linspace(0.0, 0.4, 21), rtol=1e-10, atol=1e-12)
    for _ in range(20):
        y = st.step()
        # loop closure after every step: the coupler's end meets the rocker's (rev4's frames)
        assert max(abs(y[f"rev4.frame_a.{c}"] - y[f"rev4.frame_b.{c}"]) for c in "xy") < 1e-9
    np.testing.assert_allclose(st.x, [res[n][-1] for n in model.x_names], atol=1e-6)


def test_impacts_inside_steps_follow_the_closed_form():
    from acausal.models.bouncing_ball import BouncingBall
    e, g, h = 0.8, 9.81, 1.0
    model = acausal.compile(BouncingBall(e=e, g=g))
    st = model.stepper(0.1, x0={"ball.s": h}, outputs=["ball.s"], rtol=1e-10, atol=1e-12)
    hit = np.sqrt(2 * h / g)                         # first impact, inside a step
    s = [st.step()["ball.s"] for _ in range(6)]
    t = 0.1 * np.arange(1, 7)
    v_up = e * g * hit
    exact = np.where(t < hit, h - g * t ** 2 / 2, v_up * (t - hit) - g * (t - hit) ** 2 / 2)
    np.testing.assert_allclose(s, exact, atol=1e-7)
    assert len(st.events) == 1 and st.events[0].time == pytest.approx(hit, abs=1e-9)


def test_wrong_inputs_are_refused(compiled):
    st = compiled.stepper(DT)
    with pytest.raises(SimulationError, match="no input 'G'"):
        st.step({"G": 1.0})
    with pytest.raises(SimulationError, match="1 inputs"):
        st.step([1.0, 2.0])
    with pytest.raises(SimulationError, match="1 inputs"):
        st.step("x")
    with pytest.raises(SimulationError, match=r"u\['F'\] must be a finite number"):
        st.step({"F": "x"})
    with pytest.raises(SimulationError, match="dt must be"):
        compiled.stepper(-1.0)


def test_models_without_states():
    """Signals only (2 sin(2πt), the closed form) and an algebraic circuit (simulate())."""
    from acausal.components import signals as sg
    from acausal.models.circuits import ResistorExample
    m = acausal.Model("sig")
    m.s, m.g = sg.Sine(amplitude=1.0, f=1.0), sg.Gain(k=2.0)
    m.connect(m.s.y, m.g.u)
    st = acausal.compile(m).stepper(0.1, outputs=["g.y"])
    np.testing.assert_allclose([st.step()["g.y"] for _ in range(5)],
                               2 * np.sin(2 * np.pi * 0.1 * np.arange(1, 6)), atol=1e-12)
    circuit = acausal.compile(ResistorExample())
    st = circuit.stepper(0.01, outputs=circuit.z_names)
    got = [list(st.step().values()) for _ in range(10)]
    res = circuit.simulate(0.1, t=np.linspace(0.0, 0.1, 11))
    np.testing.assert_allclose(got, np.column_stack([res[n][1:] for n in circuit.z_names]),
                               rtol=1e-10)


def test_reset_starts_the_modes_again():
    """After an impact and a reset, the ball falls and bounces as the first time."""
    from acausal.models.bouncing_ball import BouncingBall
    st = acausal.compile(BouncingBall()).stepper(0.1, x0={"ball.s": 1.0}, outputs=["ball.s"])
    first = [st.step()["ball.s"] for _ in range(8)]
    st.reset()
    assert [st.step()["ball.s"] for _ in range(8)] == first and len(st.events) == 1


@pytest.mark.parametrize("dt", [0.1, 0.05, 0.025])
def test_a_sampled_block_samples_at_its_own_instants_whatever_the_step(dt):
    """A Sampler (period 0.1 s) of the ramp u = t: at the end of every step y = u at the
    last sample instant k·0.1 s up to and including that time (an instant at the step's end
    is processed in that step, as at a simulation's stop time), never at the steps'
    starts in between."""
    from acausal.components import discrete, signals
    m = acausal.Model("sampled_ramp")
    m.ramp = signals.Ramp(height=1.0, duration=1.0)
    m.sampler = discrete.Sampler(samplePeriod=0.1)
    m.y = acausal.Output()
    m.connect(m.ramp.y, m.sampler.u)
    m.connect(m.sampler.y, m.y.u)
    stepper = acausal.compile(m).stepper(dt)
    for _ in range(int(round(0.5 / dt))):
        y = stepper.step()["y"]
        assert y == pytest.approx(0.1 * np.floor(stepper.t / 0.1 + 1e-9), abs=1e-12)
