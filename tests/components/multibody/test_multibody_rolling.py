"""Rolling wheels (constraints on velocities): MSL's rolling examples against their
published references, a leaning disk's steady turn against Newton–Euler by hand, energy
conservation and the no-slip rows held to round-off."""
import numpy as np
import pytest

import acausal
from acausal.core import Model
from acausal.components.multibody import RollingWheel, World
from acausal.errors import StructureError
from acausal.models.rolling import (ROLLING_WHEEL_START, WHEEL_SET_START, RollingWheelExample,
                                    RollingWheelSetDriving, RollingWheelSetPulling)

MSL = "Modelica.Mechanics.MultiBody.Examples.Elementary."
CASES = [(RollingWheelExample, "RollingWheel", ROLLING_WHEEL_START),
         (RollingWheelSetDriving, "RollingWheelSetDriving", WHEEL_SET_START),
         (RollingWheelSetPulling, "RollingWheelSetPulling", WHEEL_SET_START)]


@pytest.mark.parametrize("model, msl, x0", CASES, ids=[c[1] for c in CASES])
def test_rolling_examples_match_the_msl_reference(reference_result, model, msl, x0):
    ref = reference_result("MAP-LIB_ReferenceResults", MSL + msl)
    t = ref["time"]
    res = acausal.compile(model()).simulate(float(t[-1]), x0=x0, t=t, rtol=1e-10, atol=1e-10)
    for name, values in ref.items():
        if name != "time":
            assert np.max(np.abs(res[name] - values)) < 2e-3 * np.max(np.abs(values)), name


def test_the_wheel_keeps_msl_states_and_its_rates_of_x_and_y_follow_from_no_slip():
    c = acausal.compile(RollingWheelExample())
    assert c.x_names == ["wheel1.x", "wheel1.y"] + [f"wheel1.angles[{k}]" for k in (1, 2, 3)] \
        + [f"wheel1.der_angles[{k}]" for k in (1, 2, 3)]


def _rotation(res, name, k):
    return np.array([[res[f"{name}.frame_a.R.T[{i},{j}]"][k] for j in (1, 2, 3)]
                     for i in (1, 2, 3)])


def _vec(res, name):
    return np.column_stack([res[f"{name}[{k}]"] for k in (1, 2, 3)])


def _energy_and_slip(res, name, m, I_axis, I_long, g=9.80665):
    """T + V of the wheel and its contact point's velocity (world frame), by hand from the
    recorded motion (v_0, w_a, R.T, r_road_0)."""
    v0, w_a = _vec(res, f"{name}.v_0"), _vec(res, f"{name}.body.w_a")
    r0, road = _vec(res, f"{name}.r_0"), _vec(res, f"{name}.r_road_0")
    I = np.diag([I_long, I_axis, I_long])
    E, slip = [], []
    for k in range(len(res["time"])):
        T = _rotation(res, name, k)
        w0 = T.T @ w_a[k]
        E.append(0.5 * m * v0[k] @ v0[k] + 0.5 * w_a[k] @ I @ w_a[k] + m * g * r0[k, 2])
        slip.append(v0[k] + np.cross(w0, road[k] - r0[k]))
    return np.array(E), np.array(slip)


def test_the_rolling_wheel_conserves_energy_and_does_not_slip():
    t = np.linspace(0, 4, 201)
    res = acausal.compile(RollingWheelExample()).simulate(4.0, x0=ROLLING_WHEEL_START, t=t,
                                                         rtol=1e-12, atol=1e-12)
    E, slip = _energy_and_slip(res, "wheel1", 2.0, 0.06, 0.12)
    assert np.max(np.abs(E - E[0])) < 1e-9 * abs(E[0])
    assert np.max(np.abs(slip)) < 1e-9
    assert np.max(np.abs(slip[:, 2])) < 1e-12          # the contact point stays on z = 0
    assert np.max(np.abs(res["wheel1.err"])) < 1e-12
    assert np.max(np.abs(res["wheel1.r_road_0[3]"])) < 1e-12


def _steady_spin(a, m, A, C, beta, Omega, g=9.80665):
    """Spin rate s of a disk (radius a, mass m, transverse / axial inertia A, C) rolling in
    a steady turn at yaw rate Omega with its axis u = (0, cos beta, sin beta) at the start:
    Newton–Euler about the centre, Ω e_z × H = −a d × F, H = Aω + (C − A)(u·ω)u,
    ω = Ω e_z + s u, F = m(a_G + g e_z), d = (0, −sin beta, cos beta) from the contact
    point to the centre, v = a(Ω sin beta + s) the centre's speed."""
    sb, cb = np.sin(beta), np.cos(beta)
    return -(a * m * g * sb + Omega ** 2 * sb * cb * (m * a * a + C - A)) / (
        Omega * cb * (C + m * a * a))


def test_a_leaning_disk_turns_steadily_at_the_rate_newton_euler_gives():
    a, m, A, C = 0.3, 2.0, 0.045, 0.09              # a uniform disk
    beta, Omega = 0.3, 6.0
    s = _steady_spin(a, m, A, C, beta, Omega)
    u = np.array([0.0, np.cos(beta), np.sin(beta)])
    w0 = np.array([0.0, 0.0, Omega]) + s * u
    T0 = np.array([[1, 0, 0], [0, np.cos(beta), np.sin(beta)],
                   [0, -np.sin(beta), np.cos(beta)]])          # angles = (0, 0, beta)
    w_a = T0 @ w0
    model = Model("disk")
    model.world = World(n=(0, 0, -1))
    model.wheel = RollingWheel(radius=a, m=m, I_axis=C, I_long=A)
    x0 = {"wheel.x": 0.0, "wheel.y": 0.0, "wheel.angles[1]": 0.0, "wheel.angles[2]": 0.0,
          "wheel.angles[3]": beta}
    x0.update({f"wheel.body.w_a[{k + 1}]": w_a[k] for k in range(3)})
    t = np.linspace(0, 1.0, 51)
    res = acausal.compile(model).simulate(1.0, x0=x0, t=t, rtol=1e-11, atol=1e-11)
    v = a * (Omega * np.sin(beta) + s)
    rho = v / Omega                               # the centre's circle, centre C
    centre = np.array([0.0, rho, a * np.cos(beta)])
    expected = centre + np.column_stack([rho * np.sin(Omega * t), -rho * np.cos(Omega * t),
                                         0 * t])
    r0 = _vec(res, "wheel.r_0")
    assert np.max(np.abs(r0 - expected)) < 1e-6 * abs(rho)
    # the axis keeps its lean: u_z = T[2, 3] = sin(beta)
    assert np.max(np.abs(res["wheel.frame_a.R.T[2,3]"] - np.sin(beta))) < 1e-7


def test_a_wheel_also_held_by_another_path_to_the_world_is_refused():
    from acausal.components.multibody import FixedTranslation
    model = Model("loop")
    model.world = World(n=(0, 0, -1))
    model.wheel = RollingWheel(radius=0.3, m=2, I_axis=0.06, I_long=0.12)
    model.rod = FixedTranslation(r=(0, 0, 0.3))
    model.connect(model.world.frame_b, model.rod.frame_a)
    model.connect(model.rod.frame_b, model.wheel.frame_a)
    with pytest.raises(StructureError):
        acausal.compile(model)
