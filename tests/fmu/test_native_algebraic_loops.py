"""A model whose blocks close an algebraic loop, as a native FMU (model exchange): the
Reference FMUs' fmusim reproduces the loop's closed form, y = k·(r − v)/(1 + k·g) with
v(t) = r·(1 − exp(−t/τ)), τ = m·(1 + k·g)/k, the FMU solving the torn signal by Newton."""
from __future__ import annotations

import numpy as np

import acausal
from importers import fmusim
from signal_loops import speed_loop

M, K, G, R = 2.0, 5.0, 0.5, 1.5
T_END, DT = 2.0, 0.01


def test_fmusim_runs_the_loop_to_its_closed_form(tmp_path):
    compiled = acausal.compile(speed_loop(M, K, G, R))
    assert compiled.z_names                                   # the torn signal
    fmu = compiled.export_fmu(tmp_path / "speed_loop.fmu", fmi_version="2.0")
    out = fmusim(fmu, "me", T_END, DT, {}, ["mass.v", "k.y"], tmp_path)
    tau = M * (1 + K * G) / K
    v = R * (1 - np.exp(-out["time"] / tau))
    np.testing.assert_allclose(out["mass.v"], v, rtol=0, atol=1e-7)
    np.testing.assert_allclose(out["k.y"], K * (R - v) / (1 + K * G), rtol=0, atol=1e-6)
