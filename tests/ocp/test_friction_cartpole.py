"""The friction cart-pole swing-up through acausal.ocp in smooth form
(acausal.models.cartpole.FrictionCartPole, examples/ocp_friction_cartpole.py).

Cart m1 = 1 kg on a rail with Coulomb friction f_c = 2 N (a translational SupportFriction:
MSL's stuck/sliding modes on state events in simulation), pole l = 1 m with m2 = 0.1 kg at
its tip; minimize ∫F² dt over T = 5 s, N = 30, |F| ≤ 30 N, from rest hanging down to rest
upright. The OCP transcribes the smooth form f = f_c·tanh(v/v_smooth), v_smooth = 1 cm/s.

Checks:
- the smooth form against a hand-written CasADi model of the cart-pole with tanh friction
  (Lagrange's equations eliminated for the accelerations), at random states: 1e-8;
- the OCP converges, reports the smooth form, and ends upright at rest (the tip l above
  the rail, from the planar model's recorded position);
- the optimal control replayed open loop on the EXACT model (events, stuck mode): the pole
  upright is unstable and the mesh (h = 0.17 s) is coarse, so over the whole 5 s the replay
  leaves the swing-up (on the smooth model itself as well: 2.4 rad off at T); over the first
  second it stays within the documented bound of the smooth form's error. Starting from
  rest under a net force |F(0)| − f_c, the smooth friction f_c·tanh(v/v_smooth) builds up
  while the speed rises through v_smooth and misses the impulse f_c·∫(1 − tanh(v/v_s)) dt
  = f_c·v_smooth·ln 2/(rate of speed per unit mass of net force), hence
  |Δv| ≤ ln 2·f_c/(|F(0)| − f_c)·v_smooth; passing through v = 0 while sliding adds
  nothing to first order (the deficit is odd in v); the error is first order in v_smooth
  (ten times smaller at a tenth of it).
"""
import casadi as ca
import numpy as np
import pytest

import acausal
from acausal.errors import SmoothFormWarning
from acausal.models.cartpole import FrictionCartPole
from acausal.ocp import OCP
from acausal.simulation import Samples

M1, M2, L, F_C, G = 1.0, 0.1, 1.0, 2.0, 9.81
T_FINAL, N, F_MAX, V_SMOOTH = 5.0, 30, 30.0, 0.01
START = {"rail.s": 0.0, "hinge.phi": 0.0, "rail.v": 0.0, "hinge.w": 0.0}
UPRIGHT = {"hinge.phi": np.pi, "rail.v": 0.0, "hinge.w": 0.0}
TOL = dict(rtol=1e-10, atol=1e-12)


def hand_written_ode(x, F, v_smooth):
    """[x, θ, ẋ, θ̇]' of the cart-pole with friction f = f_c·tanh(ẋ/v_smooth) on the cart
    (θ from hanging down): Lagrange's equations with the force F − f on the cart."""
    th, xd, thd = x[1], x[2], x[3]
    s, c = ca.sin(th), ca.cos(th)
    u = F - F_C * ca.tanh(xd / v_smooth)
    den = M1 + M2 * s ** 2
    xdd = (M2 * L * s * thd ** 2 + u + M2 * G * c * s) / den
    thdd = -(M2 * L * c * s * thd ** 2 + u * c + (M1 + M2) * G * s) / (L * den)
    return ca.vertcat(xd, thd, xdd, thdd)


@pytest.fixture(scope="module")
def exact():
    return acausal.compile(FrictionCartPole())


@pytest.fixture(scope="module")
def solved(exact):
    with pytest.warns(SmoothFormWarning, match=r"friction \(friction.v_smooth = 0.01 m/s\)"):
        ocp = OCP(exact, N=N, T=T_FINAL, params={"friction.v_smooth": V_SMOOTH})
    ocp.minimize(ocp.integral(lambda v: v["F"] ** 2))
    ocp.bounds("F", -F_MAX, F_MAX)
    ocp.initial(START)
    ocp.final(UPRIGHT)
    return ocp, ocp.solve({"tol": 1e-10})


def test_smooth_form_is_the_hand_written_tanh_friction_model(exact):
    smooth = exact.recompiled(smooth=True)
    assert smooth.smooth and not smooth.has_events and smooth.z_names == []
    names = ["rail.s", "hinge.phi", "rail.v", "hinge.w"]
    order = [smooth.x_names.index(n) for n in names]
    rng = np.random.default_rng(1)
    x, F = ca.SX.sym("x", 4), ca.SX.sym("F")
    ref = ca.Function("ref", [x, F], [hand_written_ode(x, F, V_SMOOTH)])
    p = smooth.param_vector({"friction.v_smooth": V_SMOOTH})
    for _ in range(20):
        xs = rng.uniform([-1, -4, -0.05, -5], [1, 4, 0.05, 5])   # |ẋ| ~ v_smooth and beyond
        xs[2] *= rng.choice([1.0, 30.0])
        Fs = rng.uniform(-F_MAX, F_MAX)
        state = np.zeros(4)
        state[order] = xs
        xdot = np.array(smooth.f(0.0, state, [], [Fs], p)[0]).ravel()[order]
        want = np.array(ref(xs, Fs)).ravel()
        assert np.abs(xdot - want).max() <= 1e-8 * (1 + np.abs(want).max())


def test_swing_up_converges_to_upright_in_smooth_form(solved):
    ocp, sol = solved
    assert sol.status == "Solve_Succeeded"
    assert ocp.smooth and sol.smooth
    assert sol.regularized == {"friction": {"friction.v_smooth": V_SMOOTH}}
    assert sol["hinge.phi"][-1] == pytest.approx(np.pi, abs=1e-9)
    assert sol["tip.r[2]"][-1] == pytest.approx(L, abs=1e-9)       # straight above the cart
    assert abs(sol["tip.v[1]"][-1]) < 1e-9 and abs(sol["tip.v[2]"][-1]) < 1e-9
    assert np.max(np.abs(sol.control("F"))) <= F_MAX + 1e-6
    # the friction force the OCP saw is the smooth law of the cart's speed
    np.testing.assert_allclose(sol["friction.f"], F_C * np.tanh(sol["rail.v"] / V_SMOOTH),
                               atol=1e-12)
    # the cost is the quadrature of piecewise-constant F: h·ΣF²
    assert sol.cost == pytest.approx(T_FINAL / N * np.sum(sol.control("F") ** 2), rel=1e-12)


def replay(model, sol, horizon, **params):
    t = np.linspace(0.0, horizon, int(200 * horizon) + 1)
    F = Samples(sol.t[:-1], sol.control("F"), "hold")
    res = model.simulate(horizon, t=t, inputs={"F": F}, params=params or None, **TOL)
    at = np.searchsorted(res.t, t, side="right") - 1          # right limits at events
    return {n: res[n][at] for n in ("rail.s", "hinge.phi", "rail.v", "hinge.w")}, res


def test_optimal_control_on_the_exact_model_within_the_smooth_forms_bound(exact, solved):
    ocp, sol = solved
    F0 = abs(sol.control("F")[0])
    assert F0 > F_C                                   # it breaks away at once
    exact_run, res = replay(exact, sol, 1.0)
    assert res.events[0].modes["friction.mode"][1] in (-1.0, 1.0)      # sliding from t = 0
    bound = np.log(2) * F_C / (F0 - F_C)
    errors = {}
    for vs in (V_SMOOTH, V_SMOOTH / 10):
        smooth_run, _ = replay(ocp.model, sol, 1.0, **{"friction.v_smooth": vs})
        errors[vs] = {n: np.abs(smooth_run[n] - exact_run[n]).max() for n in exact_run}
        assert errors[vs]["rail.v"] <= bound * vs
        assert errors[vs]["rail.s"] <= bound * vs * 1.0            # over 1 s
    assert errors[V_SMOOTH]["rail.v"] >= 0.5 * bound * V_SMOOTH     # the bound is tight
    for n in exact_run:                                             # first order in v_smooth
        assert errors[V_SMOOTH / 10][n] == pytest.approx(errors[V_SMOOTH][n] / 10, rel=0.05)

