"""A component's assertion in the native FMU: MSL's Resistor with its heat port driven out
of the model's scope (1 + alpha·(T − T_ref) = 1 − 2·t, ``hot_resistor``). Over [0, 0.4] s
the FMU runs and its voltage is the closed form v = 0.5·(1 − 2·t); over [0, 0.6] s the
run fails with an error status, and the log names the part, MSL's message and a time
within one step after 0.5 s, in fmpy (model exchange: CVode's completed steps;
co-simulation: the FMU's own steps), FMI 2.0 and 3.0; the pythonfmu backend's FMU checks
them at its communication points (the step that ends after the failure returns fmi2Discard,
as a failed solve does)."""
from __future__ import annotations

import re

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")
from fmpy import simulate_fmu                                      # noqa: E402
from fmpy.fmi1 import FMICallException                             # noqa: E402

import acausal                                                     # noqa: E402
from fmi_calls import unzipped                                     # noqa: E402
from hot_resistor import hot_part                                  # noqa: E402


@pytest.fixture(scope="module")
def hot_fmus(fmu_dir):
    compiled = acausal.compile(hot_part("Resistor"))
    fmus = {v: compiled.export_fmu(fmu_dir / f"hot{v[0]}.fmu", fmi_version=v)
            for v in ("2.0", "3.0")}
    fmus["pythonfmu"] = compiled.export_fmu(fmu_dir / "hot_py.fmu", backend="pythonfmu")
    return fmus


@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
@pytest.mark.parametrize("version", ["2.0", "3.0"])
def test_assertion_fails_the_fmu_run(hot_fmus, kind, version, capfd):
    settings = dict(fmi_type=kind, output=["part.v"], relative_tolerance=1e-10,
                    output_interval=0.01)
    path = unzipped(hot_fmus[version])      # (fmpy's own would stay in /tmp after an error)
    res = simulate_fmu(path, stop_time=0.4, **settings)
    np.testing.assert_allclose(res["part.v"], 0.5 * (1 - 2 * res["time"]), rtol=1e-7)
    capfd.readouterr()
    with pytest.raises(FMICallException):
        simulate_fmu(path, stop_time=0.6, debug_logging=True, **settings)
    found = re.search(r"'part': Temperature outside scope of model! \(assertion failed at "
                      r"t = ([0-9.e-]+) s\)", capfd.readouterr().out)
    assert found, "the FMU's log names the part and MSL's message"
    assert 0.5 <= float(found.group(1)) <= 0.52


def test_assertion_fails_the_pythonfmu_run(hot_fmus, capfd):
    settings = dict(output=["part.v"], output_interval=0.01)
    path = unzipped(hot_fmus["pythonfmu"])
    res = simulate_fmu(path, stop_time=0.4, **settings)
    np.testing.assert_allclose(res["part.v"], 0.5 * (1 - 2 * res["time"]), rtol=1e-6)
    capfd.readouterr()                       # the step to 0.5 s ends it with fmi2Discard
    res = simulate_fmu(path, stop_time=0.6, debug_logging=True, **settings)
    assert res["time"][-1] == pytest.approx(0.49)
    found = re.search(r"'part': Temperature outside scope of model! \(assertion failed at "
                      r"t = ([0-9.e-]+) s\)", capfd.readouterr().out)
    assert found, "the FMU's log names the part and MSL's message"
    assert 0.5 <= float(found.group(1)) <= 0.51
