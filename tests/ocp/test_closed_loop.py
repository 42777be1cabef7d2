"""A closed kinematic loop in an OCP: a slider-crank (acausal.models.linkages) whose crank
is driven by an input torque tau [N.m] moves the crank from rest at 0.5 rad to rest at 2 rad
in 1 s with minimum ∫tau² dt.

The compiled DAE is the stabilized index-2 form (z = loops.mu, loops.nu; Φ = 0, Φ̇ = 0).
References independent of acausal:
- the loop closes at every mesh node, by hand geometry of the joint angles: the rod's end B
  (crank R at φ1, rod L at φ1 + φ2) is on the slider's track y = −H, the slider does not turn
  (φ1 + φ2 + φ3 = 0), and the same at velocity level: residuals < 1e-8;
- energy balance: the work of the piecewise-constant torque, Σ tau_k (φ1(t_k+1) − φ1(t_k)),
  equals the change of T + V of the bodies (from their recorded motion), to the
  transcription's accuracy (observed 1.4e-6 relative with Radau collocation of degree 3 on
  20 intervals, falling as h⁵; 1e-9 with shooting);
- collocation and multiple shooting (CasADi's fixed-step Radau integrator) reach the same
  cost (1e-5 relative).
"""
import numpy as np
import pytest

import acausal
from acausal.models.linkages import SliderCrank
from acausal.ocp import OCP

PHI_START, PHI_END, T_FINAL = 0.5, 2.0, 1.0     # rad, rad, s
R, L, H = 0.2, 0.6, 0.05                        # m: crank, rod, offset of the slider's track
M_CRANK, M_ROD, M_SLIDER, I_SLIDER = 0.4, 0.6, 1.0, 0.01     # kg, kg, kg, kg.m²
BODIES = {"crank": (M_CRANK, M_CRANK * R ** 2 / 12), "rod": (M_ROD, M_ROD * L ** 2 / 12),
          "slider": (M_SLIDER, I_SLIDER)}      # (m [kg], I [kg.m²]); slender rods
G = 9.81                                        # m/s², the World's default


def energy(res, bodies):
    """(T, V) [J] of the bodies from their recorded motion: T = ½ m v² + ½ I w², V = m g y."""
    T = sum(0.5 * m * (res[f"{b}.v[1]"] ** 2 + res[f"{b}.v[2]"] ** 2) + 0.5 * I * res[f"{b}.w"] ** 2
            for b, (m, I) in bodies.items())
    V = sum(m * G * res[f"{b}.r[2]"] for b, (m, _) in bodies.items())
    return T, V


@pytest.fixture(scope="module")
def compiled():
    c = acausal.compile(SliderCrank("driven_slider_crank", driven=True, lengths=(R, L, H),
                                    masses=(M_CRANK, M_ROD, M_SLIDER)))
    assert c.z_names and c.loop_rows          # a constrained model: GGL multipliers
    return c


def move_crank(compiled, method, N=20, **kw):
    ocp = OCP(compiled, N=N, T=T_FINAL, method=method, **kw)
    ocp.minimize(ocp.integral(lambda v: v["tau"] ** 2))
    ocp.initial({"rev1.phi": PHI_START, "rev1.w": 0.0})     # the independent coordinate only
    ocp.final({"rev1.phi": PHI_END, "rev1.w": 0.0})
    ocp.guess({"rev2.phi": -0.7, "rev3.phi": 0.2})           # the assembly branch
    return ocp.solve({"tol": 1e-10})


@pytest.fixture(scope="module")
def solutions(compiled):
    return {"collocation": move_crank(compiled, "collocation"),
            "shooting": move_crank(compiled, "shooting",
                                   integrator_options={"number_of_finite_elements": 2})}


@pytest.mark.parametrize("method", ["collocation", "shooting"])
def test_loop_constraints_hold_at_every_node(solutions, method):
    sol = solutions[method]
    q1, q2, q3 = sol["rev1.phi"], sol["rev2.phi"], sol["rev3.phi"]
    w1, w2, w3 = sol["rev1.w"], sol["rev2.w"], sol["rev3.w"]
    on_track = R * np.sin(q1) + L * np.sin(q1 + q2) + H
    on_track_rate = R * np.cos(q1) * w1 + L * np.cos(q1 + q2) * (w1 + w2)
    assert np.max(np.abs(on_track)) < 1e-8
    assert np.max(np.abs(q1 + q2 + q3)) < 1e-8
    assert np.max(np.abs(on_track_rate)) < 1e-8
    assert np.max(np.abs(w1 + w2 + w3)) < 1e-8
    # the planar model's own records agree: the slider on its track, not turned
    assert np.max(np.abs(sol["slider.r[2]"] + H)) < 1e-8
    assert sol["rev1.phi"][-1] == pytest.approx(PHI_END, abs=1e-12)


@pytest.mark.parametrize("method, rel", [("collocation", 1e-5), ("shooting", 1e-7)])
def test_work_of_the_torque_is_the_change_of_energy(solutions, method, rel):
    sol = solutions[method]
    work = np.sum(sol.control("tau") * np.diff(sol["rev1.phi"]))
    T, V = energy(sol, BODIES)
    dE = (T[-1] + V[-1]) - (T[0] + V[0])
    assert T[0] == pytest.approx(0.0, abs=1e-12) and T[-1] == pytest.approx(0.0, abs=1e-12)
    assert work == pytest.approx(dE, rel=rel)


def test_collocation_and_shooting_agree(solutions):
    assert solutions["shooting"].cost == pytest.approx(solutions["collocation"].cost, rel=1e-5)
