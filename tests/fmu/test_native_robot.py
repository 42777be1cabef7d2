"""The native FMU of a 6-axis arm (the UR5 read from example-robot-data's URDF by
``acausal.multibody.from_urdf``, joints damped through their axis flanges) in an
independent importer (fmpy: CVode for model exchange, the FMU's own solver for
co-simulation) equals the in-process simulation (rtol 1e-12) to 1e-6 of each joint angle's
and speed's largest magnitude over 1 s of swinging under gravity, with a changed link mass
and changed start angles."""
from __future__ import annotations

from importlib.metadata import PackageNotFoundError, distribution

import numpy as np
import pytest

pytest.importorskip("fmpy")
from fmpy import simulate_fmu                                    # noqa: E402

import acausal                                                   # noqa: E402
from acausal.components.rotational import Damper                 # noqa: E402
from acausal.multibody import from_urdf                          # noqa: E402

JOINTS = ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint",
          "wrist_2_joint", "wrist_3_joint"]


def ur5_model():
    try:
        path = distribution("example-robot-data").locate_file(
            "cmeel.prefix/share/example-robot-data/robots/ur_description/urdf/"
            "ur5_joint_limited_robot.urdf")
    except PackageNotFoundError:
        pytest.skip("example-robot-data is not installed (the robots extra)")
    model = from_urdf(path)
    for k, name in enumerate(JOINTS):
        damper = Damper(d=0.5)
        setattr(model, f"damper{k}", damper)
        model.connect(getattr(model, name).support, damper.flange_a)
        model.connect(damper.flange_b, getattr(model, name).axis)
    return model


T = 1.0


@pytest.fixture(scope="module")
def ur5_fmu(fmu_dir):
    """(compiled, FMU path), exported once (model exchange and co-simulation)."""
    compiled = acausal.compile(ur5_model())
    return compiled, compiled.export_fmu(fmu_dir / "ur5.fmu", stop_time=T)


@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
def test_ur5_fmu_equals_in_process(ur5_fmu, kind):
    compiled, path = ur5_fmu
    x0 = {"shoulder_lift_joint.phi": -1.0, "elbow_joint.phi": 1.2, "wrist_1_joint.phi": 0.4,
          "wrist_2_joint.phi": 0.7}
    params = {"forearm_link.m": 4.0}
    names = [f"{j}.{v}" for j in JOINTS for v in ("phi", "w")]
    grid = np.linspace(0.0, T, 101)
    ref = compiled.simulate(T, t=grid, rtol=1e-12, atol=1e-14, x0=x0, params=params)
    base = compiled.simulate(T, t=grid, rtol=1e-12, atol=1e-14, x0=x0)
    res = simulate_fmu(str(path), stop_time=T, output_interval=T / 100, fmi_type=kind,
                       start_values={**params, **x0}, relative_tolerance=1e-10,
                       record_events=False, output=names)
    assert np.allclose(res["time"], grid, rtol=0, atol=1e-12)
    for n in names:
        err = np.max(np.abs(res[n] - ref[n])) / np.max(np.abs(ref[n]))
        assert err < 1e-6, (n, err)
    change = max(np.max(np.abs(ref[n] - base[n])) / np.max(np.abs(ref[n])) for n in names)
    assert change > 1e-3                  # the changed mass reached the FMU
