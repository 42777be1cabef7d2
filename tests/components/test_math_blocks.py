"""MSL Math and Nonlinear blocks (acausal.components.signals) against closed forms.

References never come from the code under test: the scalar functions against numpy on
sine inputs, MatrixGain against numpy's matmul, Mean and RootMeanSquare against the closed
form integrals of a sine over each period, SlewRateLimiter against scipy's solve_ivp of
MSL's equation written out here, PadeDelay against the factorial formula of the Padé
approximant, scipy.interpolate.pade and scipy.signal's step response, and MSL's
SlewRateLimiter example against its reference result.
"""
from __future__ import annotations

import pickle
from math import factorial

import casadi as ca
import numpy as np
import pytest
import scipy.signal as sig
from scipy.integrate import solve_ivp
from scipy.interpolate import pade

import acausal
from acausal import Model, ParameterError, SimulationError, StructureError
from acausal.analysis import linearize
from acausal.components import signals as sg

SIM = dict(rtol=1e-10, atol=1e-12)
F, A0 = 0.7, 0.9                     # the sine feeding the blocks: A0·sin(2π·F·t) (+ offset)
T = np.linspace(0.0, 2.0, 401)


def _fed(blocks: dict, source) -> Model:
    """A model with ``source`` feeding each block of ``blocks`` (name -> block, SISO)."""
    m = Model("fed")
    m.src = source
    for name, block in blocks.items():
        setattr(m, name, block)
        m.connect(m.src.y, block.u)
    return m


def _sine(t, amplitude=A0, offset=0.0):
    return offset + amplitude * np.sin(2 * np.pi * F * t)


# ---- scalar functions of one input --------------------------------------------------------------
# block, input offset (the sine's amplitude A0 keeps the input in the block's domain), numpy
UNARY = {
    "abs1": (lambda: sg.Abs(), 0.0, np.abs),
    "abs_events": (lambda: sg.Abs(generateEvent=True), 0.0, np.abs),
    "sign1": (lambda: sg.Sign(), 0.2, np.sign),
    "sqrt1": (lambda: sg.Sqrt(), 1.0, np.sqrt),
    "sin1": (lambda: sg.Sin(), 0.3, np.sin),
    "cos1": (lambda: sg.Cos(), 0.3, np.cos),
    "tan1": (lambda: sg.Tan(), 0.3, np.tan),
    "asin1": (lambda: sg.Asin(), 0.0, np.arcsin),
    "acos1": (lambda: sg.Acos(), 0.0, np.arccos),
    "atan1": (lambda: sg.Atan(), 0.5, np.arctan),
    "sinh1": (lambda: sg.Sinh(), 0.5, np.sinh),
    "cosh1": (lambda: sg.Cosh(), 0.5, np.cosh),
    "tanh1": (lambda: sg.Tanh(), 0.5, np.tanh),
    "exp1": (lambda: sg.Exp(), 0.5, np.exp),
    "power1": (lambda: sg.Power(base=3.0), 0.5, lambda u: 3.0 ** u),
    "exponentiation1": (lambda: sg.Exponentiation(exponent=2.5), 1.0, lambda u: u ** 2.5),
    "log1": (lambda: sg.Log(), 1.0, np.log),
    "log_base2": (lambda: sg.Log(base=2.0), 1.0, np.log2),
    "log10": (lambda: sg.Log10(), 1.0, np.log10),
}


@pytest.fixture(scope="module")
def unary_result():
    """Every block of UNARY on its own sine, in one model and one run."""
    m = Model("unary")
    for name, (block, offset, _) in UNARY.items():
        src = sg.Sine(amplitude=A0, f=F, offset=offset)
        setattr(m, f"src_{name}", src)
        setattr(m, name, block())
        m.connect(src.y, getattr(m, name).u)
    return acausal.compile(m).simulate(T[-1], t=T, **SIM)


@pytest.mark.parametrize("name", list(UNARY))
def test_scalar_function_against_numpy(unary_result, name):
    """(With events, the left limit at a located crossing is u·sign before it: −|u| with
    |u| within the event tolerance.)"""
    _, offset, f = UNARY[name]
    t = unary_result.t
    np.testing.assert_allclose(unary_result[f"{name}.y"], f(_sine(t, offset=offset)),
                               rtol=1e-13, atol=1e-11)


def test_abs_with_events_locates_the_zero_crossings(unary_result):
    """generateEvent=True: state events where u = A0·sin(2πFt) crosses 0, at k/(2F)."""
    crossings = _crossings(unary_result, "abs_events")
    np.testing.assert_allclose(crossings, [k / (2 * F) for k in range(1, 3)], atol=1e-9)


def _crossings(res, block):
    """The times (after the start) where ``block``'s indicators crossed zero (its two
    indicators at the limits [0, 0] cross together)."""
    return sorted({round(e.time, 9) for e in res.events
                   if e.component == block and e.indicator and e.time > 1e-6})


def test_sign_with_events_and_zero_input():
    """Sign(generateEvent=True) of a sine: ±1 between the crossings, located as events;
    Sign of a zero input is 0 (MSL's else branch)."""
    m = _fed({"s": sg.Sign(generateEvent=True)}, sg.Sine(amplitude=A0, f=F))
    m.zero, m.s0 = sg.Constant(k=0.0), sg.Sign(generateEvent=True)
    m.connect(m.zero.y, m.s0.u)
    res = acausal.compile(m).simulate(T[-1], t=T, **SIM)
    inside = np.abs(np.sin(2 * np.pi * F * res.t)) > 1e-9
    np.testing.assert_array_equal(res["s.y"][inside], np.sign(np.sin(2 * np.pi * F * res.t))[inside])
    assert np.all(res["s0.y"] == 0.0)
    crossings = _crossings(res, "s")
    np.testing.assert_allclose(crossings, [k / (2 * F) for k in range(1, 3)], atol=1e-9)


def test_power_with_a_negative_base_and_integer_input():
    """Power(useExp=False): base^u, a negative base with an integer u."""
    m = _fed({"p": sg.Power(base=-2.0, useExp=False)}, sg.Step(height=3.0, offset=2.0,
                                                              startTime=0.5))
    res = acausal.compile(m).simulate(1.0, **SIM)
    np.testing.assert_allclose(res["p.y"], np.where(res.t < 0.5, 4.0, -32.0))


def test_smooth_abs_and_sign_within_their_error_bounds():
    """compile(smooth=True): Abs = u²/sqrt(u² + w²), Sign = u/sqrt(u² + w²); Abs is below
    |u| by at most 0.3003·w, no events."""
    w = 0.05
    m = _fed({"a": sg.Abs(generateEvent=True, u_smooth=w), "s": sg.Sign(u_smooth=w)},
             sg.Sine(amplitude=A0, f=F))
    c = acausal.compile(m, smooth=True)
    assert not c.has_events
    res = c.simulate(T[-1], t=np.linspace(0, 2, 4001), **SIM)
    u = _sine(res.t)
    np.testing.assert_allclose(res["a.y"], u ** 2 / np.sqrt(u ** 2 + w ** 2), rtol=1e-12,
                               atol=1e-14)
    np.testing.assert_allclose(res["s.y"], u / np.sqrt(u ** 2 + w ** 2), rtol=1e-12, atol=1e-14)
    gap = np.abs(u) - res["a.y"]
    assert 0 <= gap.min() and 0.29 * w < gap.max() <= 0.3003 * w


@pytest.mark.parametrize("block, offset, outside, what", [
    (sg.Sqrt, 0.0, lambda u: u < 0, "Sqrt must be >= 0"),
    (sg.Log, 0.0, lambda u: u <= 0, "Log must be > 0"),
    (sg.Log10, 0.5, lambda u: u <= 0, "Log10 must be > 0"),
    (sg.Asin, 0.5, lambda u: np.abs(u) > 1, r"Asin must be within \[-1, 1\]"),
    (sg.Acos, -0.5, lambda u: np.abs(u) > 1, r"Acos must be within \[-1, 1\]")])
def test_input_outside_the_domain_stops_the_simulation(block, offset, outside, what):
    """u leaves the domain at a known time: a SimulationError naming the block and the first
    output time outside, also when the output feeds a state (the function is evaluated at
    the clipped input: no NaN reaches the integrator)."""
    m = _fed({"f": block()}, sg.Sine(amplitude=A0, f=F, offset=offset))
    m.integrator = sg.Integrator()
    m.connect(m.f.y, m.integrator.u)
    first = T[np.argmax(outside(_sine(T, offset=offset)))]
    with pytest.raises(SimulationError, match=rf"'f': the input of {what} \(assertion failed "
                                              rf"at t = {first:.6g} s\)"):
        acausal.compile(m).simulate(T[-1], t=T, **SIM)


# ---- two inputs, vectors of inputs --------------------------------------------------------------
def test_atan2_max_min_and_the_multi_input_blocks():
    m = Model("two")
    m.s1 = sg.Sine(amplitude=1.0, f=F)
    m.s2 = sg.Cosine(amplitude=0.8, f=0.3, offset=-0.1)
    m.s3 = sg.Ramp(height=2.0, duration=2.0, offset=-1.0)
    m.atan2, m.max1, m.min1 = sg.Atan2(), sg.Max(), sg.Min()
    for b in (m.atan2, m.max1, m.min1):
        m.connect(m.s1.y, b.u1)
        m.connect(m.s2.y, b.u2)
    m.sum1 = sg.MultiSum(nu=3, k=[2.0, -1.0, 0.5])
    m.prod = sg.MultiProduct(nu=3)
    m.minmax = sg.MinMax(nu=3)
    for b in (m.sum1, m.prod, m.minmax):
        for i, s in enumerate((m.s1, m.s2, m.s3), start=1):
            m.connect(s.y, b.u[i])
    res = acausal.compile(m).simulate(T[-1], t=T, params={"sum1.k[3]": 4.0}, **SIM)
    t = res.t
    u1, u2 = np.sin(2 * np.pi * F * t), -0.1 + 0.8 * np.cos(2 * np.pi * 0.3 * t)
    u3 = -1.0 + t
    u = np.vstack([u1, u2, u3])
    close = dict(rtol=1e-13, atol=1e-14)
    np.testing.assert_allclose(res["atan2.y"], np.arctan2(u1, u2), **close)
    np.testing.assert_allclose(res["max1.y"], np.maximum(u1, u2), **close)
    np.testing.assert_allclose(res["min1.y"], np.minimum(u1, u2), **close)
    np.testing.assert_allclose(res["sum1.y"], 2 * u1 - u2 + 4.0 * u3, **close)
    np.testing.assert_allclose(res["prod.y"], u1 * u2 * u3, **close)
    np.testing.assert_allclose(res["minmax.yMax"], u.max(axis=0), **close)
    np.testing.assert_allclose(res["minmax.yMin"], u.min(axis=0), **close)


def test_matrix_gain_against_numpy_matmul():
    """y = K·u; another K of the same shape at simulation time, without recompiling."""
    K = np.array([[0.12, 2.0], [3.0, 1.5], [-1.0, 0.25]])
    m = Model("mg")
    m.s1, m.s2 = sg.Sine(amplitude=1.0, f=F), sg.Ramp(height=1.0, duration=2.0)
    m.gain = sg.MatrixGain(K=K)
    m.connect(m.s1.y, m.gain.u[1])
    m.connect(m.s2.y, m.gain.u[2])
    c = acausal.compile(m)
    assert (m.gain.nout, m.gain.nin) == (3, 2)
    for k, params in ((K, {}), (K[::-1] - 1.0, {"gain.K": K[::-1] - 1.0})):
        res = c.simulate(T[-1], t=T, params=params, **SIM)
        u = np.vstack([np.sin(2 * np.pi * F * res.t), np.clip(res.t / 2.0, 0, 1)])
        y = np.vstack([res[f"gain.y[{i}]"] for i in range(1, 4)])
        np.testing.assert_allclose(y, k @ u, rtol=1e-13, atol=1e-14)


def test_sized_blocks_pickle_with_their_layout():
    for block in (sg.MatrixGain(K=[[1.0, 2.0, 3.0]]), sg.MultiSum(nu=2, k=[1.0, 3.0]),
                  sg.MinMax(nu=4), sg.PadeDelay(n=3, m=2, balance=True, delayTime=0.2)):
        back = pickle.loads(pickle.dumps(block))
        assert type(back)._key == type(block)._key
        assert back.parameters().keys() == block.parameters().keys()
    assert pickle.loads(pickle.dumps(sg.MultiSum(nu=2, k=[1.0, 3.0]))).k == (1.0, 3.0)


# ---- Mean, RootMeanSquare ----------------------------------------------------------------------
def _period_means(f_mean, k, amplitude, offset, f_sine, x0=0.0):
    """Mean of offset + amplitude·sin(2π f_sine t) and of its square over [(k−1)/f, k/f]."""
    a, b, w = (k - 1) / f_mean, k / f_mean, 2 * np.pi * f_sine
    cos_int = (np.cos(w * a) - np.cos(w * b)) / w                  # ∫ sin
    sin2_int = (b - a) / 2 - (np.sin(2 * w * b) - np.sin(2 * w * a)) / (4 * w)   # ∫ sin²
    mean = f_mean * (offset * (b - a) + amplitude * cos_int + (x0 if k == 1 else 0.0))
    square = f_mean * (offset ** 2 * (b - a) + 2 * offset * amplitude * cos_int
                       + amplitude ** 2 * sin2_int + (x0 if k == 1 else 0.0))
    return mean, square


def test_mean_and_root_mean_square_of_a_sine_at_the_sample_instants():
    """Held between the instants k/f: the mean and the RMS over the last period; y0 before
    the first; x0 adds f·x0 to the first period's value."""
    f_mean, amp, off, f_sine, x0, y0 = 2.5, 1.3, 0.4, 1.1, 0.2, -0.7
    m = _fed({"mean": sg.Mean(f=f_mean, x0=x0, y0=y0), "rms": sg.RootMeanSquare(f=f_mean, x0=x0,
                                                                                 y0=0.3)},
             sg.Sine(amplitude=amp, f=f_sine, offset=off))
    t = (np.arange(0, 10) + 0.5) / f_mean                   # mid-periods: held values
    res = acausal.compile(m).simulate(t[-1], t=np.concatenate([[0.0], t]), **SIM)
    mean_y, rms_y = (np.interp(t, res.t, res[n]) for n in ("mean.y", "rms.y"))
    assert mean_y[0] == y0 and rms_y[0] == pytest.approx(0.3)
    for k in range(1, 10):
        mean, square = _period_means(f_mean, k, amp, off, f_sine, x0)
        assert mean_y[k] == pytest.approx(mean, abs=5e-8)          # the integrator's error
        assert rms_y[k] == pytest.approx(np.sqrt(square), abs=5e-8)
    # MSL's x: the integral since the last instant
    tk = t[-1]
    assert res["mean.x"][-1] == pytest.approx(
        off * 0.5 / f_mean + amp * (np.cos(2 * np.pi * f_sine * (tk - 0.5 / f_mean))
                                   - np.cos(2 * np.pi * f_sine * tk)) / (2 * np.pi * f_sine),
        abs=5e-8)


def test_mean_of_a_sine_over_its_period_is_its_offset():
    m = _fed({"mean": sg.Mean(f=F), "rms": sg.RootMeanSquare(f=F)},
             sg.Sine(amplitude=A0, f=F, offset=0.3))
    t = np.array([1.5, 2.5, 3.5]) / F
    res = acausal.compile(m).simulate(t[-1], t=np.concatenate([[0.0], t]), **SIM)
    np.testing.assert_allclose(np.interp(t, res.t, res["mean.y"]), 0.3, atol=5e-8)
    np.testing.assert_allclose(np.interp(t, res.t, res["rms.y"]), np.sqrt(0.3 ** 2 + A0 ** 2 / 2),
                               atol=5e-8)


def test_mean_refuses_smooth_form():
    with pytest.raises(StructureError, match="Mean 'mean' has no smooth form"):
        acausal.compile(_fed({"mean": sg.Mean(f=F)}, sg.Sine()), smooth=True)


# ---- SlewRateLimiter ---------------------------------------------------------------------------
def _slew_reference(u, rising, falling, Td, y0, t):
    """MSL's der(y) = clamp((u − y)/Td, Falling, Rising) by solve_ivp (the kinks resolved
    by a step limit)."""
    def rhs(tt, y):
        return [np.clip((u(tt) - y[0]) / Td, falling, rising)]
    return solve_ivp(rhs, (t[0], t[-1]), [y0], t_eval=t, method="LSODA", rtol=1e-11,
                     atol=1e-13, max_step=1e-3).y[0]


@pytest.mark.parametrize("strict", [False, True])
def test_slew_rate_limiter_against_scipy(strict):
    rising, falling, Td = 3.0, -5.0, 0.02
    m = _fed({"slew": sg.SlewRateLimiter(Rising=rising, Falling=falling, Td=Td, strict=strict)},
             sg.Sine(amplitude=2.0, f=F, offset=0.5))
    res = acausal.compile(m).simulate(T[-1], t=T, **SIM)
    ref = _slew_reference(lambda t: 0.5 + 2.0 * np.sin(2 * np.pi * F * t), rising, falling, Td,
                          0.5, T)                          # SteadyState: y(0) = u(0)
    y = np.interp(T, res.t, res["slew.y"])
    np.testing.assert_allclose(y, ref, atol=2e-7)
    rate = np.diff(y) / np.diff(T)
    assert rate.max() == pytest.approx(rising, rel=1e-9)
    assert rate.min() == pytest.approx(falling, rel=1e-9)
    crossings = {e.indicator for e in res.events if e.component == "slew" and e.indicator}
    assert crossings == (set() if strict else {"slew.upper", "slew.lower"})


def test_slew_rate_limiter_falling_follows_rising_and_initial_output():
    """Falling = −Rising (MSL's binding) also when Rising changes at simulation time;
    initType=InitialOutput starts at y_start."""
    m = _fed({"slew": sg.SlewRateLimiter(Rising=1.0, Td=0.01, initType="InitialOutput",
                                         y_start=2.0)}, sg.Constant(k=-1.0))
    res = acausal.compile(m).simulate(2.0, t=np.linspace(0, 2, 201),
                                      params={"slew.Rising": 4.0}, **SIM)
    t = np.linspace(0, 2, 201)
    ref = _slew_reference(lambda t: -1.0, 4.0, -4.0, 0.01, 2.0, t)
    y = np.interp(t, res.t, res["slew.y"])
    np.testing.assert_allclose(y, ref, atol=2e-7)
    assert y[10] == pytest.approx(2.0 - 4.0 * 0.1, rel=1e-10)


def test_slew_rate_limiter_smooth_form_has_no_events():
    m = _fed({"slew": sg.SlewRateLimiter(Rising=3.0, Td=0.02, u_smooth=1e-3)},
             sg.Sine(amplitude=2.0, f=F))
    c = acausal.compile(m, smooth=True)
    assert not c.has_events
    res = c.simulate(T[-1], t=T, **SIM)
    ref = _slew_reference(lambda t: 2.0 * np.sin(2 * np.pi * F * t), 3.0, -3.0, 0.02, 0.0, T)
    assert res.t.size == T.size
    np.testing.assert_allclose(res["slew.y"], ref, atol=2e-3 * T[-1])   # rate off <= 5e-4


class Rate(sg.SI2SO):
    """der(limit_v.y) of the example written out: MSL's SlewRateLimiter law for limit_v
    (u1 = its input, u2 = its output), the value of the example's Der block v."""

    def __init__(self, name=None, *, rising, Td):
        super().__init__(name)
        self.__dict__.update(rising=rising, Td=Td)

    def physics(self, e):
        val = (e.input(self.u1) - e.input(self.u2)) / self.Td
        e.output(self.y, ca.fmin(ca.fmax(val, -self.rising), self.rising))


def test_msl_slew_rate_limiter_example(reference_result):
    """Modelica.Blocks.Examples.SlewRateLimiter: a position step limited in velocity
    (limit_v) and acceleration (limit_a, the rate of v = der(limit_v.y)), integrated back
    to positionSmoothed. The example's Der block v (y = der(u)) is written out as ``Rate``:
    a signal's derivative as a block output is not available."""
    ref = reference_result("MAP-LIB_ReferenceResults", "Modelica.Blocks.Examples.SlewRateLimiter")
    m = Model("SlewRateLimiter")
    m.positionStep = sg.Step(startTime=0.1)
    m.limit_v = sg.SlewRateLimiter(initType="InitialOutput", Rising=2.0, y_start=0.0, Td=1e-4)
    m.v = Rate(rising=2.0, Td=1e-4)
    m.limit_a = sg.SlewRateLimiter(initType="InitialOutput", y_start=0.0, Rising=20.0, Td=1e-4)
    m.positionSmoothed = sg.Integrator(k=1.0, initType="InitialOutput", y_start=0.0)
    m.connect(m.positionStep.y, m.limit_v.u)
    m.connect(m.positionStep.y, m.v.u1)
    m.connect(m.limit_v.y, m.v.u2)
    m.connect(m.v.y, m.limit_a.u)
    m.connect(m.limit_a.y, m.positionSmoothed.u)
    t = ref["time"]
    res = acausal.compile(m).simulate(t[-1], t=t, rtol=1e-8, atol=1e-10)
    for name in ("limit_a.y", "limit_v.y", "positionSmoothed.y"):
        np.testing.assert_allclose(np.interp(t, res.t, res[name]), ref[name], atol=1e-5)


# ---- PadeDelay ---------------------------------------------------------------------------------
def _pade_closed_form(T_d, n, m):
    """Numerator and denominator of the [m/n] Padé approximant of exp(−T_d·s), highest
    power first: b_k = (n+m−k)!·m!/((n+m)!·k!·(m−k)!)·(−T_d)^k, a_k likewise with T_d, n."""
    num = [factorial(n + m - k) * factorial(m) / (factorial(n + m) * factorial(k)
                                                   * factorial(m - k)) * (-T_d) ** k
           for k in range(m + 1)]
    den = [factorial(n + m - k) * factorial(n) / (factorial(n + m) * factorial(k)
                                                   * factorial(n - k)) * T_d ** k
           for k in range(n + 1)]
    return num[::-1], den[::-1]


@pytest.mark.parametrize("n, m", [(1, 1), (2, 1), (3, 3), (4, 3), (5, 5)])
def test_pade_polynomials_against_the_closed_form_and_scipy(n, m):
    T_d = 0.37
    b, a = sg.pade_polynomials(T_d, n, m)
    nb, na = _pade_closed_form(T_d, n, m)
    np.testing.assert_allclose(b, nb, rtol=1e-13)
    np.testing.assert_allclose(a, na, rtol=1e-13)
    taylor = [(-T_d) ** k / factorial(k) for k in range(n + m + 1)]
    p, q = pade(taylor, n, m)                      # p/q, q of order n, normalized q(0) = 1
    np.testing.assert_allclose(b, p.coeffs, rtol=1e-10)
    np.testing.assert_allclose(a, q.coeffs, rtol=1e-10)


def _pade_model(**kwargs) -> Model:
    m = Model("pade")
    m.u = acausal.Input()
    m.delay = sg.PadeDelay(**kwargs)
    m.y = acausal.Output()
    m.connect(m.u.y, m.delay.u)
    m.connect(m.delay.y, m.y.u)
    return m


@pytest.mark.parametrize("balance", [False, True])
@pytest.mark.parametrize("n, m", [(1, 1), (3, 2), (4, 4)])
def test_pade_delay_transfer_function_is_the_pade_approximant(n, m, balance):
    T_d = 0.05 if balance else 0.8
    lin = linearize(acausal.compile(_pade_model(delayTime=T_d, n=n, m=m, balance=balance)), {})
    b, a = _pade_closed_form(T_d, n, m)
    for s in (0.1j, 1.0 + 2.0j, 7.0j, 30.0):
        g = lin.C @ np.linalg.solve(s * np.eye(n) - lin.A, lin.B) + lin.D
        assert g[0, 0] == pytest.approx(np.polyval(b, s) / np.polyval(a, s), rel=1e-10)
        if abs(s) * T_d < 0.5:                 # close to the delay itself at low frequency
            assert abs(g[0, 0] - np.exp(-s * T_d)) < 1e-2
    if balance:                                 # balanced: far smaller spread of A's entries
        b_ss = sig.tf2ss(b, a)[0]
        assert np.abs(lin.A).max() <= np.abs(b_ss).max()


@pytest.mark.parametrize("balance", [False, True])
def test_pade_delay_step_against_scipy(balance):
    T_d, n, m, t0 = 0.4, 4, 3, 0.5
    model = _fed({"delay": sg.PadeDelay(delayTime=T_d, n=n, m=m, balance=balance)},
                 sg.Step(startTime=t0))
    t = np.linspace(0, 3.0, 601)
    res = acausal.compile(model).simulate(t[-1], t=t, **SIM)
    b, a = _pade_closed_form(T_d, n, m)
    after = t >= t0
    _, step = sig.step(sig.lti(b, a), T=t[after] - t0)
    np.testing.assert_allclose(res["delay.y"][after], step, atol=1e-7)
    np.testing.assert_allclose(res["delay.y"][~after], 0.0, atol=1e-12)
    assert res["delay.y"][-1] == pytest.approx(1.0, abs=1e-3)      # unit DC gain


def test_pade_delay_time_is_a_parameter():
    c = acausal.compile(_pade_model(delayTime=1.0, n=2, m=2))
    lin = linearize(c, {}, params={"delay.delayTime": 0.25})
    b, a = _pade_closed_form(0.25, 2, 2)
    s = 3.0j
    g = lin.C @ np.linalg.solve(s * np.eye(2) - lin.A, lin.B) + lin.D
    assert g[0, 0] == pytest.approx(np.polyval(b, s) / np.polyval(a, s), rel=1e-12)


def test_balance_abc_is_msl_example():
    """Modelica.Math.Matrices.balanceABC's documented example: scale = {16, 1, 0.0625}."""
    A = [[1, -10, 1000], [0.01, 0, 10], [0.005, -0.01, 10]]
    B = [[100, 10], [1, 0], [-0.003, 1]]
    C = [[-0.5, 1, 100]]
    np.testing.assert_array_equal(sg.balance_abc(np.array(A), np.array(B), np.array(C)),
                                  [16, 1, 0.0625])


# ---- bad input ---------------------------------------------------------------------------------
@pytest.mark.parametrize("make, match", [
    (lambda: sg.MultiSum(nu=0), r"MultiSum: nu \(number of inputs\) must be an integer >= 1"),
    (lambda: sg.MultiProduct(nu=2.5), "MultiProduct: nu"),
    (lambda: sg.MinMax(nu=-1), "MinMax: nu"),
    (lambda: sg.MultiSum(nu=3, k=[1.0, 2.0]), r"MultiSum.k' takes 3 values"),
    (lambda: sg.MatrixGain(K=[[1.0, 2.0], [3.0]]), "MatrixGain: K must be a matrix"),
    (lambda: sg.MatrixGain(K=[[1.0, np.nan]]), "MatrixGain: K contains non-finite"),
    (lambda: sg.Mean(f=0.0), r"Mean.f"),
    (lambda: sg.RootMeanSquare(f=-50.0), r"RootMeanSquare.f"),
    (lambda: sg.RootMeanSquare(y0=-1.0), "RootMeanSquare: y0 .* must be >= 0"),
    (lambda: sg.PadeDelay(delayTime=0.0), r"PadeDelay.delayTime"),
    (lambda: sg.PadeDelay(n=2, m=3), r"PadeDelay: m \(order of the numerator, 3\) must be <= n"),
    (lambda: sg.PadeDelay(n=0), r"PadeDelay: n \(order of the denominator\) must be an integer"),
    (lambda: sg.SlewRateLimiter(Falling=1.0), "SlewRateLimiter: Falling .* must be < 0"),
    (lambda: sg.SlewRateLimiter(Rising=0.0), r"SlewRateLimiter.Rising"),
    (lambda: sg.SlewRateLimiter(Td=-1.0), r"SlewRateLimiter.Td"),
    (lambda: sg.Log(base=1.0), "Log: base must be > 0 and != 1"),
    (lambda: sg.Power(base=-2.0), "Power: base must be > 0 with useExp=True"),
])
def test_bad_input_is_a_parameter_error(make, match):
    with pytest.raises(ParameterError, match=match):
        make()


def test_parameters_refused_at_simulation_time():
    c = acausal.compile(_fed({"mean": sg.Mean(f=F)}, sg.Sine()))
    with pytest.raises(ParameterError, match="mean.f"):
        c.simulate(1.0, params={"mean.f": -1.0})


def test_pade_delay_in_steady_state_passes_a_constant_input():
    """balance=True starts in steady state: a constant input passes at the DC gain 1 (a
    model whose only parameter is delayTime, fed by a model Input)."""
    res = acausal.compile(_pade_model(delayTime=0.3, n=3, m=2, balance=True)).simulate(
        1.0, inputs={"u": 2.5}, **SIM)
    np.testing.assert_allclose(res["delay.y"], 2.5, rtol=1e-12)


def test_native_fmu_of_the_new_blocks_matches_simulate(tmp_path):
    """A native FMU (fmpy as the importer) of Abs with events under Sqrt, Mean, PadeDelay and
    SlewRateLimiter gives simulate()'s outputs (away from the sample instants, where the
    two sides of the event differ)."""
    fmpy = pytest.importorskip("fmpy")
    m = Model("mb")
    m.s = sg.Sine(amplitude=0.9, f=1.3, offset=0.2)
    m.a, m.q = sg.Abs(generateEvent=True), sg.Sqrt()
    m.me = sg.Mean(f=2.0)
    m.p = sg.PadeDelay(delayTime=0.2, n=3, balance=True)
    m.sl = sg.SlewRateLimiter(Rising=2.0, Td=0.01)
    for b in (m.a, m.me, m.p, m.sl):
        m.connect(m.s.y, b.u)
    m.connect(m.a.y, m.q.u)
    names = {"y1": "q.y", "y2": "me.y", "y3": "p.y", "y4": "sl.y"}
    for out, signal in names.items():
        setattr(m, out, acausal.Output())
        block, port = signal.split(".")
        m.connect(getattr(getattr(m, block), port), getattr(m, out).u)
    c = acausal.compile(m)
    res = c.simulate(2.0, t=np.linspace(0, 2, 201), **SIM)
    fmu = fmpy.simulate_fmu(str(c.export_fmu(str(tmp_path / "mb.fmu"))), stop_time=2.0,
                            output_interval=0.01, output=list(names))
    t = fmu["time"]
    away = np.abs(t * 2.0 - np.round(t * 2.0)) > 1e-6
    for out, signal in names.items():
        np.testing.assert_allclose(fmu[out][away], np.interp(t[away], res.t, res[signal]),
                                   atol=1e-6)
