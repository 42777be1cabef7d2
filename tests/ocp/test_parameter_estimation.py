"""Parameter estimation (examples/ocp_parameter_estimation.py): a spring stiffness c, a
damping d and the release position s0 of a 1-D oscillator from noisy positions (fixed seed).

References: scipy's least_squares on scipy's solve_ivp of the hand-written ODE m s̈ = −c s − d ṡ
(independent of acausal). acausal.ocp's estimates equal scipy's to 1e-3 of their standard
deviation (observed |Δ| ~ 1e-7, the transcription's error),
and both lie within 3 standard deviations of the truth. The least-squares residual rms is
the noise level σ (to 20 %).
"""
import sys
from pathlib import Path

import numpy as np
import pytest

import acausal

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "examples"))
import ocp_parameter_estimation as ex  # noqa: E402


@pytest.fixture(scope="module")
def data():
    t, y = ex.measurements()
    ref, std = ex.reference_fit(t, y)
    return t, y, ref, std


@pytest.fixture(scope="module")
def compiled():
    return acausal.compile(ex.Oscillator())


@pytest.mark.parametrize("method", ["collocation", "shooting"])
def test_estimates_match_scipy_and_the_truth(compiled, data, method):
    t, y, ref, std = data
    sol = ex.estimate(compiled, t, y, method=method)
    got = np.array([sol.parameters["spring.c"], sol.parameters["damper.d"], sol["mass.s"][0]])
    np.testing.assert_allclose(got, ref, atol=1e-3 * std.min())
    truth = np.array([ex.STIFFNESS, ex.DAMPING, ex.S0])
    assert np.all(np.abs(got - truth) < 3 * std)
    assert np.sqrt(np.mean((sol["mass.s"] - y) ** 2)) == pytest.approx(ex.SIGMA, rel=0.2)
    # the estimated model's motion is the hand ODE's with the estimates
    np.testing.assert_allclose(sol["mass.s"], ex.hand_positions(t, *got), atol=1e-6)
    # the spring force recorded by the model is c·s_rel at the estimate (Hooke; MSL's f is
    # the tension, s_rel = flange_b.s − flange_a.s = mass.s − 0)
    np.testing.assert_allclose(sol["spring.f"], got[0] * sol["mass.s"], atol=1e-12)
