"""Model inputs given as a constant, a callable of time, (times, values) samples and an array
on the output grid, checked against closed forms of a forced oscillator
(m x'' + c x = F(t), x(0) = x'(0) = 0) and a scipy model."""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from forced_oscillator import forced_oscillator

MASS, STIFF = 0.5, 8.0
W = np.sqrt(STIFF / MASS)      # 4 rad/s
T_END = 3.0
GRID = np.linspace(0.0, T_END, 301)


@pytest.fixture(scope="module")
def compiled():
    return acausal.compile(forced_oscillator(MASS, STIFF, F_start=0.25))


def step_response(F0, t):
    return F0 / STIFF * (1 - np.cos(W * t))


def ramp_response(a, t):
    """F = a t."""
    return a / STIFF * (t - np.sin(W * t) / W)


def sine_response(A, Om, t):
    """F = A sin(Om t), Om != W."""
    return A / (MASS * (W ** 2 - Om ** 2)) * (np.sin(Om * t) - Om / W * np.sin(W * t))


def test_input_names(compiled):
    assert compiled.input_names == ["F"]


def test_constant(compiled):
    res = compiled.simulate(T_END, t=GRID, inputs={"F": 1.5})
    np.testing.assert_allclose(res["mass.s"], step_response(1.5, GRID), atol=1e-6)
    np.testing.assert_allclose(res["F"], 1.5)
    np.testing.assert_allclose(res["force.flange.f"], -1.5)


def test_start_value_when_not_given(compiled):
    res = compiled.simulate(T_END, t=GRID)
    np.testing.assert_allclose(res["mass.s"], step_response(0.25, GRID), atol=1e-6)


def test_symbolic_callable(compiled):
    """A callable that works on CasADi symbols (numpy ufuncs) becomes an exact expression."""
    res = compiled.simulate(T_END, t=GRID, inputs={"F": lambda t: 2.0 * np.sin(3.0 * t)})
    np.testing.assert_allclose(res["mass.s"], sine_response(2.0, 3.0, GRID), atol=1e-6)
    np.testing.assert_allclose(res["F"], 2.0 * np.sin(3.0 * GRID), atol=1e-12)


def test_numeric_callable(compiled):
    """A callable that only takes floats (math.sin, branches) is sampled finely (2001 points
    here) and interpolated linearly: the force error is below h²/8·max|F''| = 5e-6 N, which
    bounds the displacement error by ~5e-6 m over 3 s (1.8e-6 m observed)."""
    def force(t):
        return 2.0 * math.sin(3.0 * t) if t >= 0 else 0.0
    res = compiled.simulate(T_END, t=GRID, inputs={"F": force})
    np.testing.assert_allclose(res["mass.s"], sine_response(2.0, 3.0, GRID), atol=5e-6)


@pytest.mark.parametrize("force, response", [
    (lambda t: 2.0 * math.sin(3.0 * t), lambda t: sine_response(2.0, 3.0, t)),
    (lambda t: 1.5 * float(t >= 0.0), lambda t: step_response(1.5, t)),
])
def test_a_callable_that_makes_nan_of_symbols_is_sampled(compiled, force, response):
    """math.sin and float() accept a CasADi symbol and give NaN (no error): the expression is
    checked against the callable's values at numbers, and such a callable is sampled as one
    that rejects symbols (not a NaN input; the error bound of test_numeric_callable)."""
    with pytest.warns(UserWarning, match="does not accept CasADi symbols"):
        res = compiled.simulate(T_END, t=GRID, inputs={"F": force})
    np.testing.assert_allclose(res["mass.s"], response(GRID), atol=5e-6)


def test_samples(compiled):
    """(times, values) on a grid unrelated to the output grid; linear between samples."""
    ts = np.linspace(0.0, T_END, 7)
    res = compiled.simulate(T_END, t=GRID, inputs={"F": (ts, 0.8 * ts)})
    np.testing.assert_allclose(res["mass.s"], ramp_response(0.8, GRID), atol=1e-6)


def test_array_on_grid(compiled):
    res = compiled.simulate(T_END, t=GRID, inputs={"F": 0.8 * GRID})
    np.testing.assert_allclose(res["mass.s"], ramp_response(0.8, GRID), atol=1e-6)
    np.testing.assert_allclose(res["F"], 0.8 * GRID, atol=1e-12)


def test_piecewise_linear_samples_against_scipy(compiled):
    """Ramp up, hold, ramp down: compared with scipy (np.interp), integrated piece by piece."""
    ts = np.array([0.0, 0.5, 1.5, 2.0, 3.0])
    fs = np.array([0.0, 1.0, 1.0, -0.5, -0.5])
    res = compiled.simulate(T_END, t=GRID, inputs={"F": (ts, fs)})

    def rhs(t, y):
        return [y[1], (np.interp(t, ts, fs) - STIFF * y[0]) / MASS]
    y, ref = np.zeros(2), []
    for a, b in zip(ts[:-1], ts[1:]):
        pts = GRID[(GRID >= a) & (GRID < b)]
        sol = solve_ivp(rhs, (a, b), y, t_eval=pts, rtol=1e-12, atol=1e-14, method="DOP853")
        ref.append(sol.y[0])
        y = solve_ivp(rhs, (a, b), y, rtol=1e-12, atol=1e-14, method="DOP853").y[:, -1]
    ref = np.concatenate(ref + [[y[0]]])
    np.testing.assert_allclose(res["mass.s"], ref, atol=1e-6)


def test_bad_inputs(compiled):
    with pytest.raises(acausal.SimulationError, match="FF"):
        compiled.simulate(T_END, t=GRID, inputs={"FF": 1.0})
    with pytest.raises(acausal.SimulationError, match="'F'"):
        compiled.simulate(T_END, t=GRID, inputs={"F": np.zeros(7)})      # not on the grid


def _piecewise_reference(ts, fs, hold):
    """scipy DOP853 of the forced oscillator, integrated piece by piece between the sample
    times, with the force as numpy gives it: held (zero-order) or interpolated linearly."""
    def force(t, a):
        if hold:
            return fs[np.searchsorted(ts, a, side="right") - 1]
        return np.interp(t, ts, fs)

    y, out = np.zeros(2), np.zeros(GRID.size)
    bounds = np.unique(np.concatenate([ts, [T_END]]))
    for a, b in zip(bounds[:-1], bounds[1:]):
        rhs = lambda t, y: [y[1], (force(t, a) - STIFF * y[0]) / MASS]   # noqa: E731
        pts = (GRID >= a) & (GRID < b)
        sol = solve_ivp(rhs, (a, b), y, t_eval=GRID[pts], rtol=1e-12, atol=1e-14,
                        method="DOP853")
        out[pts] = sol.y[0]
        y = solve_ivp(rhs, (a, b), y, rtol=1e-12, atol=1e-14, method="DOP853").y[:, -1]
    out[-1] = y[0]
    return out


def test_held_samples_are_a_zero_order_hold(compiled):
    """Samples(..., 'hold'): each value holds until the next sample time (a sampled
    controller's output), integrated with a restart at every jump."""
    ts = np.array([0.0, 0.35, 0.8, 1.7, 2.45])
    fs = np.array([1.0, -0.5, 2.0, 0.0, 0.7])
    res = compiled.simulate(T_END, t=GRID, inputs={"F": acausal.simulation.Samples(ts, fs,
                                                                                  "hold")})
    np.testing.assert_allclose(res["mass.s"], _piecewise_reference(ts, fs, hold=True),
                               atol=1e-7)
    held = fs[np.searchsorted(ts, GRID, side="right") - 1]
    np.testing.assert_allclose(res["F"], held, atol=1e-12)


def test_repeated_sample_times_are_steps(compiled):
    """(times, values) with a time given twice: linear pieces with a jump there."""
    ts = np.array([0.0, 1.0, 1.0, 3.0])
    fs = np.array([0.0, 1.0, -1.0, 0.0])
    res = compiled.simulate(T_END, t=GRID, inputs={"F": (ts, fs)})
    ref_force = np.where(GRID < 1.0, GRID, -1.0 + (GRID - 1.0) / 2.0)
    np.testing.assert_allclose(res["F"], ref_force, atol=1e-12)

    def rhs(t, y):
        return [y[1], ((t if t < 1.0 else -1.0 + (t - 1.0) / 2.0) - STIFF * y[0]) / MASS]
    first = GRID < 1.0
    a = solve_ivp(rhs, (0.0, 1.0), [0.0, 0.0], t_eval=GRID[first], rtol=1e-12, atol=1e-14,
                  method="DOP853")
    y1 = solve_ivp(rhs, (0.0, 1.0), [0.0, 0.0], rtol=1e-12, atol=1e-14,
                   method="DOP853").y[:, -1]
    b = solve_ivp(rhs, (1.0, T_END), y1, t_eval=GRID[~first], rtol=1e-12, atol=1e-14,
                  method="DOP853")
    np.testing.assert_allclose(res["mass.s"], np.concatenate([a.y[0], b.y[0]]), atol=1e-7)


def test_a_sampled_callable_is_announced(compiled):
    """A callable that rejects CasADi symbols is sampled: the user is told, at their line."""
    with pytest.warns(UserWarning, match="does not accept CasADi symbols") as record:
        compiled.simulate(T_END, t=GRID, inputs={"F": lambda t: 1.0 if t > 1 else 0.0})
    assert record[0].filename == __file__


@pytest.mark.parametrize("kwargs, message", [
    ({"t_final": float("nan")}, "t_final must be a finite number"),
    ({"t_final": 0.0}, "t_final must be > 0"),
    ({"t_final": -1.0}, "t_final must be > 0"),
    ({"t_final": 1.0, "rtol": float("nan")}, "rtol must be a finite number > 0"),
    ({"t_final": 1.0, "atol": 0.0}, "atol must be a finite number > 0"),
    ({"t_final": 1.0, "max_step": float("inf")}, "max_step must be a finite number > 0"),
    ({"t_final": 1.0, "t": [0.0, float("nan"), 1.0]}, "increasing grid of at least two finite"),
    ({"t_final": 1.0, "x0": {"mass.s": float("nan")}}, r"x0\['mass.s'\] must be a finite"),
    ({"t_final": 1.0, "inputs": {"F": float("nan")}}, "input 'F': values must be finite"),
    ({"t_final": 1.0, "inputs": {"F": ([0.0, 2.0, 1.0], [0, 1, 2])}}, "must not decrease"),
    ({"t_final": 1.0, "inputs": {"F": "abc"}}, "input 'F': give a number, an array"),
    ({"t_final": 1.0, "options": {"max_num_step": 10}}, "no option 'max_num_step'"),
])
def test_non_finite_or_bad_settings_are_refused(compiled, kwargs, message):
    """Every time, grid, tolerance and value is checked before integrating (a NaN t_final
    used to hang inside the integrator)."""
    with pytest.raises(acausal.SimulationError, match=message):
        compiled.simulate(**kwargs)


def test_many_held_and_linear_samples_read_exactly(compiled):
    """300 samples: the input on a grid between and at the sample times equals numpy's
    lookup (hold) and interpolation (linear) of them."""
    rng = np.random.default_rng(3)
    times = np.cumsum(rng.uniform(0.005, 0.015, 300))
    values = rng.normal(size=300)
    grid = np.unique(np.concatenate([np.linspace(0.0, 3.0, 301), times[times < 3.0]]))
    held = compiled.simulate(3.0, t=grid, inputs={"F": acausal.simulation.Samples(
        times, values, "hold")})
    index = np.clip(np.searchsorted(times, grid, side="right") - 1, 0, times.size - 1)
    np.testing.assert_array_equal(held["F"], values[index])
    linear = compiled.simulate(3.0, t=grid,
                               inputs={"F": acausal.simulation.Samples(times, values)})
    inside = (grid >= times[0]) & (grid <= times[-1])
    np.testing.assert_allclose(linear["F"][inside], np.interp(grid[inside], times, values),
                               rtol=0, atol=1e-14)
