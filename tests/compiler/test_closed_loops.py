"""Closed kinematic loops (issue 3): a four-bar linkage and a slider-crank under gravity,
undamped: the linkages of acausal.models.linkages, built from planar components (World,
Fixed, FixedTranslation, Body, Revolute, Prismatic).

What is checked, against references that do not come from the code under test:
- loop closure: every joint relation evaluated here from the recorded frame poses (for the
  joint that closes the loop, e.g. rev4.frame_a.x − rev4.frame_b.x);
- energy: T + V computed here from the bodies' recorded positions, velocities, masses and
  inertias;
- the crank angle: an independent minimal-coordinate model in the crank angle θ, written here
  by hand — the loop solved in closed form (circle intersection, slider geometry), the
  dependent rates from the vector-loop equations, the crank's equation of motion by virtual
  power (CasADi only as a calculator) — integrated by scipy's DOP853 at tolerance 1e-12;
  the parallelograms against their one-line equation J θ̈ = −g cos θ Σ m·lever;
- initial assembly: the crank where the user put it, the other joints moved from far-off
  start values onto the loop (Φ = 0), velocities projected (Φ_q q̇ = 0), also from the
  singular start with every joint at 0;
- mobility and redundant constraints: degrees of freedom by the Gruebler count and by rank;
  a parallelogram four-bar has none redundant, a double parallelogram (a fifth link) has one,
  reported by name, and both move as their hand-written models.
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.models.linkages import FourBar, Parallelogram, SliderCrank

G = 9.81                                     # m/s², World default, along n = (0, -1)
T_END = 10.0                                 # s
GRID = np.linspace(0.0, T_END, 1001)
# simulate(): BDF's phase error grows over the swings; at rtol 1e-8 the four-bar's crank
# angle (swinging through 5.7 rad) is off by ~5e-4 rad after 10 s (the hand-written minimal
# ODE through cvodes: 2e-3), at 1e-12 by ~2e-7: the tolerance the comparison needs.
LONG = {"rtol": 1e-12, "atol": 1e-14}
SHORT = {"rtol": 1e-10, "atol": 1e-12}       # assembly checks: only t = 0 matters

# four-bar (Grashof crank-rocker: the crank turns fully, transmission angle in 44°..92°)
L0, L1, L2, L3 = 1.0, 0.3, 1.0, 0.8          # m: ground, crank, coupler, rocker
M1, M2, M3 = 0.5, 1.0, 0.8                   # kg
FB_THETA0, FB_W0 = 1.0, 2.0                  # rad, rad/s: the crank at t = 0

# slider-crank (slider axis a distance H below the crank pivot)
R_C, L_R, H = 0.2, 0.6, 0.05                 # m: crank, connecting rod, offset
MC, MR, MS = 0.4, 0.6, 1.0                   # kg: crank, rod, slider
SC_THETA0, SC_W0 = 0.5, 3.0


def inertia(m, L):
    """Slender rod about its centre [kg.m²]."""
    return m * L ** 2 / 12


# ---- the models under test: acausal.models.linkages ----------------------------------------
def four_bar(parallelogram=False, fifth_link=False, crank_flange=False):
    """acausal.models' FourBar: ground pivots A = (0, 0) and D = (L0, 0), crank A–B on
    rev1, coupler B–C on rev2, rocker D–C on rev3, rev4 closing the loop at C.
    ``parallelogram``: the rocker as long as the crank, the coupler as long as the ground.
    ``fifth_link`` (a parallelogram too): a fifth link, as long as the crank, from
    E = (L0/2, 0) (rev5) to the coupler's middle (rev6): a redundant second loop.
    ``crank_flange``: rev1 with its 1-D flange (to drive it)."""
    if parallelogram or fifth_link:
        return Parallelogram("four_bar", L0, L1, (M1, M2, M3), crank_flange, fifth_link)
    return FourBar("four_bar", (L0, L1, L2, L3), (M1, M2, M3), crank_flange)


def slider_crank():
    """acausal.models' SliderCrank: crank O–A on rev1 (O at the origin), rod A–B
    on rev2, slider (a Body) on a Prismatic along x from (0, −H), rev3 joining them."""
    return SliderCrank(lengths=(R_C, L_R, H), masses=(MC, MR, MS))


FB_BODIES = {"crank": (M1, inertia(M1, L1)), "coupler": (M2, inertia(M2, L2)),
             "rocker": (M3, inertia(M3, L3))}
SC_BODIES = {"crank": (MC, inertia(MC, R_C)), "rod": (MR, inertia(MR, L_R)),
             "slider": (MS, 0.01)}
FB_JOINTS = {"rev1": "revolute", "rev2": "revolute", "rev3": "revolute", "rev4": "revolute"}
SC_JOINTS = {"rev1": "revolute", "rev2": "revolute", "rev3": "revolute",
             "prismatic": (1.0, 0.0)}            # a prismatic joint: its direction e


@pytest.fixture(scope="module")
def fb_compiled():
    return ac.compile(four_bar())


@pytest.fixture(scope="module")
def sc_compiled():
    return ac.compile(slider_crank())


@pytest.fixture(scope="module")
def fb_run(fb_compiled):
    return fb_compiled.simulate(T_END, t=GRID, x0={"rev1.phi": FB_THETA0, "rev1.w": FB_W0},
                                **LONG)


@pytest.fixture(scope="module")
def sc_run(sc_compiled):
    return sc_compiled.simulate(T_END, t=GRID, x0={"rev1.phi": SC_THETA0, "rev1.w": SC_W0},
                                **LONG)


# ---- checks computed from a Result ---------------------------------------------------------
def joint_residual(res, joints) -> np.ndarray:
    """|residual| over time, the largest of every joint relation, from the recorded frame
    poses: revolute: frame_b = (frame_a.x, frame_a.y, frame_a.phi + phi); prismatic
    (``joints[name]`` its direction e): frame_b = frame_a + s·R(frame_a.phi)·e, same angle."""
    worst = np.zeros_like(res.t)
    for name, kind in joints.items():
        a = [res[f"{name}.frame_a.{c}"] for c in ("x", "y", "phi")]
        b = [res[f"{name}.frame_b.{c}"] for c in ("x", "y", "phi")]
        if kind == "revolute":
            rows = [b[0] - a[0], b[1] - a[1], b[2] - a[2] - res[f"{name}.phi"]]
        else:
            ex, ey = kind
            s, c, sn = res[f"{name}.s"], np.cos(a[2]), np.sin(a[2])
            rows = [b[0] - a[0] - s * (c * ex - sn * ey), b[1] - a[1] - s * (sn * ex + c * ey),
                    b[2] - a[2]]
        worst = np.maximum(worst, np.max(np.abs(rows), axis=0))
    return worst


def energy(res, bodies):
    """(T, V) [J] of the bodies from their recorded motion: T = ½ m v² + ½ I w², V = m g y."""
    T = sum(0.5 * m * (res[f"{b}.v[1]"] ** 2 + res[f"{b}.v[2]"] ** 2) + 0.5 * I * res[f"{b}.w"] ** 2
            for b, (m, I) in bodies.items())
    V = sum(m * G * res[f"{b}.r[2]"] for b, (m, _) in bodies.items())
    return T, V


def unwound(angle, expected, start=0.0, tol=1e-10):
    """``angle`` equals ``expected`` up to turns of 2π, and lies less than a turn from the
    start value: assembly must not wind a joint by whole turns."""
    d = angle - expected
    return abs(d - 2 * np.pi * round(d / (2 * np.pi))) < tol and abs(angle - start) < 2 * np.pi


def tip_velocity(res, body, half_length, k=0):
    """Velocity of the point at half_length along a body's x axis (rigid-body kinematics)."""
    phi, w = res[f"{body}.phi"][k], res[f"{body}.w"][k]
    rx, ry = half_length * math.cos(phi), half_length * math.sin(phi)
    return np.array([res[f"{body}.v[1]"][k] - w * ry, res[f"{body}.v[2]"][k] + w * rx])


# ---- the independent reference: minimal coordinates, closed-form loop ----------------------
# Written by hand; CasADi serves only as a calculator (one compiled right-hand side) and
# scipy's DOP853 integrates it.
def e(a):
    """Unit vector at angle a."""
    return ca.vertcat(ca.cos(a), ca.sin(a))


def e_(a):
    """d e(a) / da."""
    return ca.vertcat(-ca.sin(a), ca.cos(a))


def solve2(J, b):
    """J x = b for a 2 × 2 J (Cramer's rule)."""
    det = J[0, 0] * J[1, 1] - J[0, 1] * J[1, 0]
    return ca.vertcat(b[0] * J[1, 1] - J[0, 1] * b[1], J[0, 0] * b[1] - b[0] * J[1, 0]) / det


class VectorLoop:
    """A one-degree-of-freedom mechanism in coordinates q = (θ, q1, q2), θ the crank angle.

    A point is ``(offset, terms)``, terms (c, k, u): c·e(q_k) (a bar of length c at angle q_k)
    when u is None, else q_k·u (a slide along the fixed unit vector u). The loop is a point
    that must be zero; ``dependent(θ)`` solves it for (q1, q2) in closed form. Bodies are
    (m, I, point of the centre of mass, index of the angle or None). The crank's equation of
    motion comes from virtual power along s = ∂q̇/∂θ̇:
        Σ m a·v_s + I α ω_s = Σ m g·v_s,  with q̈ = s θ̈ + q̈0 linear in θ̈."""

    def __init__(self, loop, bodies, dependent):
        self.loop, self.bodies = loop, bodies
        th, thd = ca.SX.sym("theta"), ca.SX.sym("thetad")
        q = ca.vertcat(th, *dependent(th))
        J = ca.horzcat(*[sum((c * e_(q[k]) if u is None else ca.DM(u)
                              for c, k, u in loop[1] if k == i), ca.SX.zeros(2))
                         for i in range(3)])
        s = ca.vertcat(1, solve2(J[:, 1:], -J[:, 0]))
        qd = s * thd
        _, _, quad = self.motion(loop, q, qd, ca.SX.zeros(3))
        qdd0 = ca.vertcat(0, solve2(J[:, 1:], -quad))
        num = den = 0
        for m, I, point, k in bodies:
            _, vs, _ = self.motion(point, q, s, ca.SX.zeros(3))
            _, _, a0 = self.motion(point, q, qd, qdd0)
            ws, alpha0 = (s[k], qdd0[k]) if k is not None else (0, 0)
            num += m * (-G * vs[1]) - m * ca.dot(a0, vs) - I * alpha0 * ws
            den += m * ca.dot(vs, vs) + I * ws ** 2
        self._rhs = ca.Function("rhs", [th, thd], [thd, num / den])
        self._state = ca.Function("state", [th, thd], [q, qd])

    @staticmethod
    def motion(point, q, qd, qdd):
        offset, terms = point
        p, v, a = ca.DM(offset), ca.SX.zeros(2), ca.SX.zeros(2)
        for c, k, u in terms:
            if u is None:
                p = p + c * e(q[k])
                v = v + c * e_(q[k]) * qd[k]
                a = a + c * (e_(q[k]) * qdd[k] - e(q[k]) * qd[k] ** 2)
            else:
                p, v, a = p + q[k] * ca.DM(u), v + qd[k] * ca.DM(u), a + qdd[k] * ca.DM(u)
        return p, v, a

    def state(self, theta, thetad=0.0):
        """(q, q̇) on the loop, as numpy arrays."""
        q, qd = self._state(theta, thetad)
        return np.array(q).ravel(), np.array(qd).ravel()

    def rhs(self, t, y):
        return [float(v) for v in self._rhs(y[0], y[1])]

    def simulate(self, theta0, thetad0, t):
        sol = solve_ivp(self.rhs, (t[0], t[-1]), [theta0, thetad0], method="DOP853", t_eval=t,
                        rtol=1e-12, atol=1e-12)
        assert sol.success
        return sol.y[0]


def four_bar_reference(branch):
    """q = (θ, β, γ): crank, coupler and rocker angles (absolute); C the intersection of the
    circles about B (radius L2) and D (radius L3), on the side ``branch`` (±1) of B→D."""
    D = ca.DM([L0, 0.0])

    def dependent(theta):
        B = L1 * e(theta)
        d = D - B
        dist = ca.norm_2(d)
        a = (L2 ** 2 - L3 ** 2 + dist ** 2) / (2 * dist)
        h = ca.sqrt(L2 ** 2 - a ** 2)
        u = d / dist
        C = B + a * u + branch * h * ca.vertcat(-u[1], u[0])
        return ca.atan2(C[1] - B[1], C[0] - B[0]), ca.atan2(C[1] - D[1], C[0] - D[0])

    loop = ((-L0, 0.0), [(L1, 0, None), (L2, 1, None), (-L3, 2, None)])
    bodies = [(M1, inertia(M1, L1), ((0, 0), [(L1 / 2, 0, None)]), 0),
              (M2, inertia(M2, L2), ((0, 0), [(L1, 0, None), (L2 / 2, 1, None)]), 1),
              (M3, inertia(M3, L3), ((L0, 0), [(L3 / 2, 2, None)]), 2)]
    return VectorLoop(loop, bodies, dependent)


def slider_crank_branch(res, k=0):
    """+1 when the slider is right of the crank pin A in the result, else −1."""
    return 1.0 if res["slider.r[1]"][k] > res["rev2.frame_a.x"][k] else -1.0


def four_bar_branch(res, k=0):
    """Side of B→D the joint C is on in the result (cross product sign)."""
    B = np.array([res["rev2.frame_a.x"][k], res["rev2.frame_a.y"][k]])
    C = np.array([res["rev4.frame_a.x"][k], res["rev4.frame_a.y"][k]])
    d, c = np.array([L0, 0.0]) - B, C - B
    return 1.0 if d[0] * c[1] - d[1] * c[0] > 0 else -1.0


def slider_crank_reference(branch=1.0):
    """q = (θ, ψ, x): crank angle, rod angle, slider position; the slider right of the crank
    pin (cos ψ > 0) for ``branch`` +1, left of it for −1."""
    def dependent(theta):
        s = ca.asin((-H - R_C * ca.sin(theta)) / L_R)
        psi = s if branch > 0 else np.pi - s
        return psi, R_C * ca.cos(theta) + L_R * ca.cos(psi)

    loop = ((0.0, H), [(R_C, 0, None), (L_R, 1, None), (None, 2, (-1.0, 0.0))])
    bodies = [(MC, inertia(MC, R_C), ((0, 0), [(R_C / 2, 0, None)]), 0),
              (MR, inertia(MR, L_R), ((0, 0), [(R_C, 0, None), (L_R / 2, 1, None)]), 1),
              (MS, 0.01, ((0.0, -H), [(None, 2, (1.0, 0.0))]), None)]
    return VectorLoop(loop, bodies, dependent)


# ---- four-bar ------------------------------------------------------------------------------
def test_four_bar_loop_stays_closed(fb_run):
    res = fb_run
    gap = np.hypot(res["rev4.frame_a.x"] - res["rev4.frame_b.x"],
                   res["rev4.frame_a.y"] - res["rev4.frame_b.y"])
    assert np.max(gap) < 1e-8
    assert np.max(joint_residual(res, FB_JOINTS)) < 1e-8
    assert np.ptp(res["rev3.phi"]) > 0.3          # the mechanism really moves


def test_four_bar_energy_is_conserved(fb_run):
    T, V = energy(fb_run, FB_BODIES)
    E = T + V
    assert np.max(T) > 0.5
    assert np.max(np.abs(E - E[0])) / np.max(T) < 1e-6


def test_four_bar_crank_angle_matches_minimal_coordinate_model(fb_run):
    res = fb_run
    ref = four_bar_reference(four_bar_branch(res))
    theta = ref.simulate(FB_THETA0, FB_W0, res.t)
    assert np.ptp(theta) > 1.0
    assert np.max(np.abs(res["rev1.phi"] - theta)) < 1e-6
    # the other bodies follow the same loop: rocker angle γ = rev3.phi
    gamma = np.array([ref.state(th)[0][2] for th in res["rev1.phi"]])
    assert np.max(np.abs(np.angle(np.exp(1j * (res["rev3.phi"] - gamma))))) < 1e-8


# ---- slider-crank --------------------------------------------------------------------------
def test_slider_crank_loop_stays_closed(sc_run):
    """Whichever joint closes the loop (rev3, or the prismatic when the tree reaches the
    slider through the rod), every joint relation holds."""
    res = sc_run
    gap = np.hypot(res["rev3.frame_a.x"] - res["rev3.frame_b.x"],
                   res["rev3.frame_a.y"] - res["rev3.frame_b.y"])
    assert np.max(gap) < 1e-8
    assert np.max(joint_residual(res, SC_JOINTS)) < 1e-8
    assert np.max(np.abs(res["slider.r[2]"] + H)) < 1e-8      # the slider stays on its track
    assert np.max(np.abs(res["slider.phi"])) < 1e-8
    assert np.ptp(res["prismatic.s"]) > 0.2


def test_slider_crank_energy_is_conserved(sc_run):
    T, V = energy(sc_run, SC_BODIES)
    E = T + V
    assert np.max(T) > 0.5
    assert np.max(np.abs(E - E[0])) / np.max(T) < 1e-6


def test_slider_crank_matches_minimal_coordinate_model(sc_run):
    res = sc_run
    ref = slider_crank_reference(slider_crank_branch(res))
    theta = ref.simulate(SC_THETA0, SC_W0, res.t)
    assert np.ptp(theta) > 1.0
    assert np.max(np.abs(res["rev1.phi"] - theta)) < 1e-6
    x = np.array([ref.state(th)[0][2] for th in res["rev1.phi"]])
    assert np.max(np.abs(res["slider.r[1]"] - x)) < 1e-8


@pytest.mark.parametrize("case", ["slider_crank", "four_bar"])
def test_tight_tolerances(sc_compiled, fb_compiled, case):
    """rtol 1e-12, atol 1e-14 — what a user asks for when 1e-6 over 10 s matters — must
    start and run from other initial states too (IDAS once failed at t = 0 here)."""
    t = np.linspace(0.0, 2.0, 201)
    if case == "slider_crank":
        x0 = (2.0, -4.0)
        res = sc_compiled.simulate(2.0, t=t, x0={"rev1.phi": x0[0], "rev1.w": x0[1]}, **LONG)
        ref = slider_crank_reference(slider_crank_branch(res))
    else:
        x0 = (-2.0, 0.5)
        res = fb_compiled.simulate(2.0, t=t, x0={"rev1.phi": x0[0], "rev1.w": x0[1]}, **LONG)
        ref = four_bar_reference(four_bar_branch(res))
    assert np.max(np.abs(res["rev1.phi"] - ref.simulate(*x0, t))) < 1e-8


# ---- initial assembly ------------------------------------------------------------------------
@pytest.mark.parametrize("theta0, w0", [(1.0, 2.0), (2.6, -1.0), (-2.0, 0.5), (4.0, 0.0)])
def test_four_bar_assembles_from_far_start_values(fb_compiled, theta0, w0):
    """Only the crank is given; the other joints start from their start values (0): coupler
    folded back along the crank, rocker along +x, ends ≥ 0.3 m apart. Assembly must close the
    loop, keep the crank where the user put it and project the velocities."""
    start_gap = math.hypot((L1 + L2) * math.cos(theta0) - (L0 + L3), (L1 + L2) * math.sin(theta0))
    assert start_gap > 0.3
    res = fb_compiled.simulate(0.01, t=np.linspace(0, 0.01, 3),
                               x0={"rev1.phi": theta0, "rev1.w": w0}, **SHORT)
    assert abs(res["rev1.phi"][0] - theta0) < 1e-12
    assert abs(res["rev1.w"][0] - w0) < 1e-12
    assert joint_residual(res, FB_JOINTS)[0] < 1e-10
    # positions on the loop: the closed-form solution on the branch reached, the joint angles
    # not wound by whole turns away from their start values
    ref = four_bar_reference(four_bar_branch(res))
    q, qd = ref.state(theta0, w0)
    assert unwound(res["rev2.phi"][0], q[1] - theta0)
    assert unwound(res["rev3.phi"][0], q[2])
    # velocities projected: Φ_q q̇ = 0 — the ends of coupler and rocker move together
    v_c = tip_velocity(res, "coupler", L2 / 2)
    v_r = tip_velocity(res, "rocker", L3 / 2)
    assert np.max(np.abs(v_c - v_r)) < 1e-10
    assert abs(res["coupler.w"][0] - qd[1]) < 1e-9
    assert abs(res["rocker.w"][0] - qd[2]) < 1e-9


def test_four_bar_assembles_from_the_singular_all_zero_start(fb_compiled):
    """Every joint at its start value 0 lays the links along x: the residual's gradient with
    respect to the free joints vanishes there (a stationary point, not a solution), which
    stalls a Gauss–Newton iteration. Assembly still closes the loop: with the crank held at 0
    (x0), and with nothing given (the crank free to move too); the result lies on the
    closed-form loop of its branch."""
    for x0 in ({"rev1.phi": 0.0}, {}):
        with pytest.warns(UserWarning, match="close the kinematic loops"):
            res = fb_compiled.simulate(0.01, t=np.linspace(0, 0.01, 3), x0=x0, **SHORT)
        theta = res["rev1.phi"][0]
        if x0:
            assert abs(theta) < 1e-12
        assert joint_residual(res, FB_JOINTS)[0] < 1e-10
        q, _ = four_bar_reference(four_bar_branch(res)).state(theta)
        assert unwound(res["rev2.phi"][0], q[1] - theta)
        assert unwound(res["rev3.phi"][0], q[2])


def test_slider_crank_assembles_from_far_start_values(sc_compiled):
    res = sc_compiled.simulate(0.01, t=np.linspace(0, 0.01, 3),
                               x0={"rev1.phi": 2.0, "rev1.w": -4.0}, **SHORT)
    assert abs(res["rev1.phi"][0] - 2.0) < 1e-12
    assert joint_residual(res, SC_JOINTS)[0] < 1e-10
    ref = slider_crank_reference(slider_crank_branch(res))
    q, qd = ref.state(2.0, -4.0)
    assert unwound(res["rev2.phi"][0], q[1] - 2.0)
    assert abs(res["slider.r[1]"][0] - q[2]) < 1e-10
    assert abs(res["slider.v[1]"][0] - qd[2]) < 1e-9
    v_rod = tip_velocity(res, "rod", L_R / 2)
    assert np.max(np.abs(v_rod - [res["slider.v[1]"][0], res["slider.v[2]"][0]])) < 1e-10


def test_four_bar_guess_selects_the_assembly_branch(fb_compiled):
    """The user fixes the crank (x0) and guesses the other joints (guess) on either side of
    B→D, 0.4 rad off: assembly lands on the guessed branch, and the warning names the
    values it changed."""
    theta0 = 1.0
    for branch in (1.0, -1.0):
        ref = four_bar_reference(branch)
        q, _ = ref.state(theta0)
        guess = {"rev2.phi": q[1] - theta0 + 0.4 * branch, "rev3.phi": q[2] + 0.4 * branch}
        with pytest.warns(UserWarning, match=r"rev2\.phi.*rev3\.phi"):
            res = fb_compiled.simulate(0.01, t=np.linspace(0, 0.01, 3),
                                       x0={"rev1.phi": theta0}, guess=guess, **SHORT)
        assert joint_residual(res, FB_JOINTS)[0] < 1e-10
        assert four_bar_branch(res) == branch
        assert abs(res["rev1.phi"][0] - theta0) < 1e-12
        assert abs(res["rocker.phi"][0] - q[2]) < 1e-10


def test_a_guess_on_the_loop_closing_joint_selects_the_branch(fb_compiled):
    """The crank fixed (x0), one guess on what is no coordinate: the angle of rev4, the joint
    that closes the loop (rev3.phi − rev1.phi − rev2.phi). From the start values alone
    assembly lands on the branch −1; the guess, 0.4 rad either side of the closed-form
    value of either branch, selects that branch."""
    theta0 = 1.0
    res = fb_compiled.simulate(0.01, t=np.linspace(0, 0.01, 3), x0={"rev1.phi": theta0},
                               **SHORT)
    assert four_bar_branch(res) == -1.0
    for branch in (1.0, -1.0):
        q, _ = four_bar_reference(branch).state(theta0)      # absolute θ, β, γ
        exact = q[2] - q[1]
        for off in (0.4, -0.4):
            with pytest.warns(UserWarning, match="close the kinematic loops"):
                res = fb_compiled.simulate(0.01, t=np.linspace(0, 0.01, 3),
                                           x0={"rev1.phi": theta0},
                                           guess={"rev4.phi": exact + off}, **SHORT)
            assert four_bar_branch(res) == branch
            assert joint_residual(res, FB_JOINTS)[0] < 1e-10
            assert abs(res["rev1.phi"][0] - theta0) < 1e-12
            assert abs(res["rocker.phi"][0] - q[2]) < 1e-10
            assert abs(res["rev4.phi"][0] - exact) < 1e-10


def test_assembly_reports_changed_start_values(fb_compiled):
    """The user is told which values assembly changed (not the ones fixed in x0)."""
    with pytest.warns(UserWarning) as record:
        fb_compiled.simulate(0.01, t=np.linspace(0, 0.01, 3),
                             x0={"rev1.phi": 1.0, "rev1.w": 2.0}, **SHORT)
    text = " ".join(str(w.message) for w in record)
    for name in ("rev2.phi", "rev3.phi", "rev2.w", "rev3.w"):
        assert name in text
    assert "rev1.phi" not in text and "rev1.w" not in text


# ---- degrees of freedom, redundant constraints ---------------------------------------------
def gruebler(bodies, joints):
    """Planar mobility count: 3 per moving body, −2 per revolute or prismatic joint."""
    return 3 * bodies - 2 * joints


def test_degrees_of_freedom(fb_compiled, sc_compiled, fb_run, sc_run):
    """Gruebler: 3·3 − 4·2 = 1; the rank of Φ_q at the assembled configuration agrees."""
    for compiled, res in ((fb_compiled, fb_run), (sc_compiled, sc_run)):
        mob = compiled.mobility(x0={"rev1.phi": 0.7})
        assert (mob.gruebler, mob.dof, list(mob.redundant)) == (gruebler(3, 4), 1, [])
        assert (res.mobility.gruebler, res.mobility.dof, list(res.mobility.redundant)) == \
            (1, 1, [])


def parallelogram_reference(t, theta0, thetad0, side_masses):
    """Parallelogram: the links of length L1 pivoting on the ground (masses ``side_masses``,
    slender rods) all at angle θ, the coupler (M2) translating with their ends; from T and V
    written by hand: J θ̈ = −g cos θ · Σ m·lever."""
    J = sum(inertia(m, L1) + m * (L1 / 2) ** 2 for m in side_masses) + M2 * L1 ** 2
    lever = sum(m * L1 / 2 for m in side_masses) + M2 * L1
    sol = solve_ivp(lambda _, y: [y[1], -G * lever * math.cos(y[0]) / J], (t[0], t[-1]),
                    [theta0, thetad0], method="DOP853", t_eval=t, rtol=1e-12, atol=1e-12)
    # swinging about θ = −π/2, away from the collinear (singular) configurations θ = 0, −π
    assert np.min(sol.y[0]) > -math.pi + 0.5 and np.max(sol.y[0]) < -0.5
    return sol.y[0]


P_THETA0, P_W0 = -0.8, -0.5                   # rad, rad/s: parallelogram start


def test_parallelogram_four_bar_is_not_redundant():
    """A parallelogram four-bar is an ordinary 1-degree-of-freedom loop away from its
    collinear configurations (θ = 0, π): nothing is redundant, and the coupler translates."""
    compiled = ac.compile(four_bar(parallelogram=True))
    t = np.linspace(0, 3.0, 301)
    x0 = {"rev1.phi": P_THETA0, "rev1.w": P_W0}
    guess = {"rev2.phi": -P_THETA0, "rev3.phi": P_THETA0}       # the parallelogram branch
    mob = compiled.mobility(x0=x0, guess=guess)
    assert (mob.gruebler, mob.dof, list(mob.redundant)) == (1, 1, [])
    # assembled on the guessed branch (the anti-parallelogram would cross a singular point)
    start = compiled.simulate(0.01, t=np.linspace(0, 0.01, 3), x0=x0, guess=guess, **SHORT)
    assert abs(start["rev3.phi"][0] - P_THETA0) < 1e-10
    res = compiled.simulate(3.0, t=t, x0=x0, guess=guess, **LONG)
    assert (res.mobility.dof, list(res.mobility.redundant)) == (1, [])
    assert np.max(joint_residual(res, FB_JOINTS)) < 1e-8
    assert np.max(np.abs(res["coupler.phi"])) < 1e-8
    ref = parallelogram_reference(t, P_THETA0, P_W0, [M1, M3])
    assert np.max(np.abs(res["rev1.phi"] - ref)) < 1e-6


def test_redundant_fifth_link_is_reported_and_handled():
    """Gruebler counts 3·4 − 2·6 = 0, yet the double parallelogram moves (1 degree of
    freedom): one of the four loop rows is redundant. It must be reported by name, and the
    motion must come out right (reactions of the redundant rows are not unique)."""
    compiled = ac.compile(four_bar(fifth_link=True))
    t = np.linspace(0, 3.0, 301)
    x0 = {"rev1.phi": P_THETA0, "rev1.w": P_W0}
    guess = {"rev2.phi": -P_THETA0, "rev3.phi": P_THETA0, "rev5.phi": P_THETA0}
    with pytest.warns(UserWarning, match="redundant") as record:
        res = compiled.simulate(3.0, t=t, x0=x0, guess=guess, **LONG)
    mob = res.mobility
    assert mob.gruebler == gruebler(4, 6) == 0
    assert mob.dof == 1
    assert len(mob.redundant) == 1 and mob.redundant[0].split(".")[0] in ("rev4", "rev6")
    assert mob.redundant[0] in " ".join(str(w.message) for w in record
                                        if "redundant" in str(w.message))
    joints = dict(FB_JOINTS, rev5="revolute", rev6="revolute")
    assert np.max(joint_residual(res, joints)) < 1e-8
    assert np.max(np.abs(res["coupler.phi"])) < 1e-8
    ref = parallelogram_reference(t, P_THETA0, P_W0, [M1, M3, M3])
    assert np.max(np.abs(res["rev1.phi"] - ref)) < 1e-6


def test_four_bar_driven_at_constant_speed():
    """A Speed source (exact) turns the crank of a four-bar at 2 rad/s: the crank angle is
    1 + 2t, the loop stays closed, and the work of the drive torque equals the change of
    T + V (energy balance, computed here from the recorded motion)."""
    from acausal.components import rotational as rot, signals as sig
    m = four_bar(crank_flange=True)
    m.drive, m.ref = rot.Speed(exact=True), sig.Constant(k=2.0)
    m.connect(m.ref.y, m.drive.w_ref)
    m.connect(m.drive.flange, m.rev1.axis)
    c = ac.compile(m)
    t = np.linspace(0.0, 2.0, 201)
    with pytest.warns(UserWarning, match="initial values changed"):
        res = c.simulate(2.0, t=t, x0={"drive.phi": 1.0}, guess={"rev2.phi": 1.0, "rev3.phi": 2.0},
                         rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(res["rev1.phi"], 1.0 + 2.0 * t, atol=1e-9)
    for k in ("x", "y"):
        gap = res[f"rev4.frame_a.{k}"] - res[f"rev4.frame_b.{k}"]
        assert np.max(np.abs(gap)) < 1e-9
    T, V = energy(res, FB_BODIES)
    power = res["rev1.axis.tau"] * 2.0              # torque into the joint's flange
    work = np.concatenate([[0.0], np.cumsum(0.5 * (power[1:] + power[:-1]) * np.diff(t))])
    E = T + V
    np.testing.assert_allclose(work, E - E[0], atol=1e-4 * np.ptp(E))   # trapezoid: 3e-5
