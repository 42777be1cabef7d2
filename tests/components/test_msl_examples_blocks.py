"""MSL's Blocks.Examples InverseModel, ShowLogicalSources and TotalHarmonicDistortion
(acausal.models, built with MSL's names and parameters) against MSL's published reference
results (when the collection is at hand) and against closed forms."""
from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

import acausal
from acausal import models
from msl_examples import at_reference_times, simulate_like_reference

EXAMPLES = "Modelica.Blocks.Examples"
TOL = dict(rtol=1e-10, atol=1e-12)


def _inverse_model():
    return models.InverseModel(), 1.0, {}


def test_inverse_model_matches_the_msl_reference(reference_result):
    """firstOrder1's output (held at the filtered sine) and firstOrder2's (driven by the
    computed input) against the reference, within 1e-6 of the peak."""
    res, ref = simulate_like_reference(_inverse_model, f"{EXAMPLES}.InverseModel",
                                       reference_result, index_reduction=True, **TOL)
    for name in ("firstOrder1.y", "firstOrder2.y"):
        ours = at_reference_times(res, ref["time"], name)
        np.testing.assert_allclose(ours, ref[name], atol=1e-6 * np.max(np.abs(ref[name])),
                                   err_msg=name)


def test_inverse_model_against_the_filtered_sine():
    """firstOrder1.y = firstOrder2.y = the sine through 1/(s/w + 1), w = 2π·100 rad/s,
    steady at 1 until 0.2 s (scipy); the computed input is T·y' + y."""
    compiled = acausal.compile(models.InverseModel(), index_reduction=True)
    assert compiled.x_names == ["firstOrder2.y", "criticalDamping.x[1]"]
    assert compiled.z_names == ["inverseBlockConstraints.y1"]
    t = np.linspace(0.0, 1.0, 201)
    res = compiled.simulate(1.0, t=t, **TOL)
    w, T = 2 * np.pi * 100, 0.3

    def sine(tk):
        return 1 + (np.sin(2 * np.pi * 2 * (tk - 0.2)) if tk >= 0.2 else 0.0)

    sol = solve_ivp(lambda tk, y: [(sine(tk) - y[0]) * w], (0.0, 1.0), [1.0], t_eval=t,
                    method="Radau", rtol=1e-12, atol=1e-14, first_step=1e-6)
    y = sol.y[0]
    for name in ("firstOrder1.y", "firstOrder2.y"):
        np.testing.assert_allclose(res[name], y, atol=1e-7, err_msg=name)
    u = T * (np.array([sine(tk) for tk in t]) - y) * w + y
    np.testing.assert_allclose(res["inverseBlockConstraints.y1"], u, atol=1e-5)
    np.testing.assert_allclose(res["feedback.y"], y - [sine(tk) for tk in t], atol=1e-7)


def test_show_logical_sources_matches_the_msl_reference(reference_result):
    """table.y (the reference's one column) exactly; the other sources against their
    closed forms on the same grid."""
    res, ref = simulate_like_reference(lambda: (models.ShowLogicalSources(), 10.0, {}),
                                       f"{EXAMPLES}.ShowLogicalSources", reference_result, **TOL)
    t = ref["time"]
    table = at_reference_times(res, t, "table.y")
    np.testing.assert_array_equal(table, ref["table.y"])
    k = np.flatnonzero(np.diff(ref["table.y"]))
    assert [(t[i + 1], ref["table.y"][i + 1]) for i in k] == [(2, 1), (4, 0), (6, 1), (8, 0)]
    step = t >= 4
    pulse = np.mod(t + 1e-12, 1.5) < 0.75
    np.testing.assert_array_equal(at_reference_times(res, t, "step.y"), step)
    np.testing.assert_array_equal(at_reference_times(res, t, "pulse.y"), pulse)
    np.testing.assert_array_equal(at_reference_times(res, t, "booleanExpression.y"),
                                  pulse & step)
    np.testing.assert_array_equal(at_reference_times(res, t, "const.y"), np.ones_like(t))
    np.testing.assert_array_equal(res["sample.y"], 0)          # true only within events


def _total_harmonic_distortion():
    return models.TotalHarmonicDistortion(), 0.1, {}


def test_total_harmonic_distortion_matches_the_msl_reference(reference_result):
    """The six integrator states of the reference (thd1's and thdRMS's harmonic.mean1.x,
    harmonic.mean2.x, rootMeanSquare.mean.x, reset every 20 ms) within 1e-6 of their peaks,
    the last point after the reset at the stop time, as the reference has it."""
    res, ref = simulate_like_reference(_total_harmonic_distortion,
                                       f"{EXAMPLES}.TotalHarmonicDistortion",
                                       reference_result, **TOL)
    for name in [n for n in ref if n != "time"]:
        ours = at_reference_times(res, ref["time"], name)
        np.testing.assert_allclose(ours, ref[name], atol=1e-6 * np.max(np.abs(ref[name])),
                                   err_msg=name)


def test_total_harmonic_distortion_against_its_theoretical_values():
    """From the first full period of the voltage (0.04 s) on, thd1.y = V3/V1 and
    thdRMS.y = V3/sqrt(V1² + V3²), both valid; 0 and not valid before."""
    V1, V3 = 100.0, 20.0
    t = np.linspace(0.005, 0.095, 10)            # between the sample instants k·20 ms
    res = acausal.compile(models.TotalHarmonicDistortion()).simulate(
        0.095, t=np.append(0.0, t), **TOL)
    at = np.searchsorted(res.t, t, side="right") - 1
    late = t > 0.04
    for name, theory in (("thd1", V3 / V1), ("thdRMS", V3 / np.hypot(V1, V3))):
        y, valid = res[f"{name}.y"][at], res[f"{name}.valid"][at]
        np.testing.assert_allclose(y[late], theory, atol=1e-6)
        np.testing.assert_array_equal(y[~late], 0)
        np.testing.assert_array_equal(valid, late)
        np.testing.assert_allclose(res[f"{name}.harmonic.y_rms"][at][late], V1, rtol=1e-7)
        np.testing.assert_allclose(res[f"{name}.rootMeanSquare.y"][at][late],
                                   np.hypot(V1, V3), rtol=1e-7)
