"""Parameter estimation (acausal.models.oscillators, examples/ocp_parameter_estimation.py): a
spring stiffness c, a damping d and the release position s0 of a 1-D oscillator from noisy
positions (fixed seed).

References: scipy's least_squares on scipy's solve_ivp of the hand-written ODE m s̈ = −c s − d ṡ
(independent of acausal). acausal.ocp's estimates equal scipy's to 1e-3 of their standard
deviation (observed |Δ| ~ 1e-7, the transcription's error),
and both lie within 3 standard deviations of the truth. The least-squares residual rms is
the noise level σ (to 20 %).
"""
import casadi as ca
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import least_squares

import acausal
from acausal.models.oscillators import Oscillator
from acausal.ocp import OCP

MASS, STIFFNESS, DAMPING, S0 = 1.0, 4.0, 0.4, 0.5     # kg, N/m, N.s/m, m (the truth)
SIGMA, DT, DURATION, SEED = 0.01, 0.1, 10.0, 0         # m, s, s
GUESS = {"spring.c": 3.0, "damper.d": 0.2}             # N/m, N.s/m


def hand_positions(t, c, d, s0, m=MASS):
    """s(t) [m] of m s̈ = −c s − d ṡ from rest at s0 (scipy, rtol 1e-11)."""
    r = solve_ivp(lambda _, y: [y[1], -(c * y[0] + d * y[1]) / m], (t[0], t[-1]), [s0, 0.0],
                  t_eval=t, rtol=1e-11, atol=1e-13, method="DOP853")
    return r.y[0]


def measurements():
    """(times [s], noisy positions [m]) of the true oscillator."""
    t = np.linspace(0.0, DURATION, int(round(DURATION / DT)) + 1)
    noise = SIGMA * np.random.default_rng(SEED).standard_normal(t.size)
    return t, hand_positions(t, STIFFNESS, DAMPING, S0) + noise


def estimate(compiled, t, y, method="collocation", **kw):
    """c, d and s0 by acausal.ocp: the Solution (free parameters in sol.parameters)."""
    ocp = OCP(compiled, N=t.size - 1, T=t[-1] - t[0], t0=t[0], method=method,
              free=["spring.c", "damper.d"], **kw)
    ocp.minimize(ca.sumsqr(ocp["mass.s"] - y))
    ocp.initial({"mass.v": 0.0})
    ocp.bounds("spring.c", 0.0, None)
    ocp.bounds("damper.d", 0.0, None)
    ocp.guess({**GUESS, "mass.s": y})
    return ocp.solve({"tol": 1e-12})


def reference_fit(t, y):
    """(estimates [c, d, s0], standard deviations) by scipy on the hand ODE."""
    fit = least_squares(lambda th: hand_positions(t, *th) - y,
                        [GUESS["spring.c"], GUESS["damper.d"], y[0]], xtol=1e-14, ftol=1e-14,
                        gtol=1e-14)
    cov = SIGMA ** 2 * np.linalg.inv(fit.jac.T @ fit.jac)
    return fit.x, np.sqrt(np.diag(cov))


@pytest.fixture(scope="module")
def data():
    t, y = measurements()
    ref, std = reference_fit(t, y)
    return t, y, ref, std


@pytest.fixture(scope="module")
def compiled():
    return acausal.compile(Oscillator(m=MASS))


@pytest.mark.parametrize("method", ["collocation", "shooting"])
def test_estimates_match_scipy_and_the_truth(compiled, data, method):
    t, y, ref, std = data
    sol = estimate(compiled, t, y, method=method)
    got = np.array([sol.parameters["spring.c"], sol.parameters["damper.d"], sol["mass.s"][0]])
    np.testing.assert_allclose(got, ref, atol=1e-3 * std.min())
    truth = np.array([STIFFNESS, DAMPING, S0])
    assert np.all(np.abs(got - truth) < 3 * std)
    assert np.sqrt(np.mean((sol["mass.s"] - y) ** 2)) == pytest.approx(SIGMA, rel=0.2)
    # the estimated model's motion is the hand ODE's with the estimates
    np.testing.assert_allclose(sol["mass.s"], hand_positions(t, *got), atol=1e-6)
    # the spring force recorded by the model is c·s_rel at the estimate (Hooke; MSL's f is
    # the tension, s_rel = flange_b.s − flange_a.s = mass.s − 0)
    np.testing.assert_allclose(sol["spring.f"], got[0] * sol["mass.s"], atol=1e-12)
