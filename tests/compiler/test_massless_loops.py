"""Closed loops through massless links: PlanarMechanics' KinematicLoop and PistonEngine
(acausal.models.linkages), whose loops run through FixedTranslations without bodies, and a
four-bar whose crank and rocker have no mass.

What is checked, against references that do not come from the code under test:
- declaration order: each model compiles and simulates in PlanarMechanics' order, reversed
  and shuffled, with the same results (to solver tolerance); where a tree exists whose
  coordinates all carry mass, the compiler takes one (no zero row in the mass matrix);
- the motion: an independent minimal-coordinate model of each, written here by hand — the
  loop solved in closed form (the triangle's apex, the slider-crank's piston, the four-bar's
  circle intersection), T and V from the bodies' positions, Lagrange's equations with CasADi
  only as a calculator — integrated by scipy's DOP853 at tolerance 1e-12;
- the MSL reference results (PlanarMechanics_ReferenceResults, Dymola, tolerance 1e-6) within
  2e-3 of each signal's peak, when they are at hand: the CSVs are not part of this
  repository; the test reads them from $ACAUSAL_REFERENCE_RESULTS or from
  shared/PlanarMechanics_ReferenceResults beside the repository (laid out as that repository:
  PlanarMechanics/Examples/<Model>/<Model>.csv), and is skipped otherwise;
- where no tree gives every coordinate mass (the four-bar with a massless crank and rocker),
  the massless coordinate is a dependent coordinate of the loop and the motion still matches;
  a loop that can move without moving any mass is refused, naming its coordinates.
"""
from __future__ import annotations

import math
import random
import warnings

import casadi as ca
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.components import translational as tr
from acausal.components.planar import (Body, Fixed, FixedTranslation, Prismatic, Revolute,
                                       World)
from acausal.core import Model
from acausal.errors import StructureError
from acausal.models.linkages import KinematicLoop, PistonEngine

G = 9.81                                      # m/s², PlanarMechanics' constantGravity {0, -9.81}
TIGHT = {"rtol": 1e-10, "atol": 1e-12}


def orders(cls) -> list:
    """PlanarMechanics' declaration order, reversed, and one shuffled."""
    shuffled = list(cls.COMPONENTS)
    random.Random(7).shuffle(shuffled)
    return [None, "reversed", shuffled]


def simulate(compiled, cls, t, guess=None, **tol):
    """The example from PlanarMechanics' initial values (``cls.X0``, held exactly); ``guess``
    (joint angles by name) for those that are states of this compile."""
    states = set(compiled.x_names)
    guess = {k: v for k, v in (guess or {}).items() if k in states}
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", "initial values changed", UserWarning)
        return compiled.simulate(t[-1], t=t, x0=cls.X0, guess=guess, **(tol or TIGHT))


def massless_coordinates(compiled, res) -> list[str]:
    """The coordinates whose row of the mass matrix is zero at the start of ``res``."""
    L = compiled.lagrange
    q = [res[n][0] for n in compiled.coordinates]
    M = np.array(L.function("M")(0.0, q, np.zeros(len(q)), compiled.input_start,
                                 compiled.param_vector())).reshape(len(q), len(q))
    return [n for n, row in zip(compiled.coordinates, M) if not np.any(row)]


# ---- the independent references: minimal coordinates, closed-form loops --------------------
def minimal_model(q, bodies, V_extra=0, Q_extra=None):
    """Lagrange's equations in the minimal coordinates ``q`` (SX), written from the bodies:
    (m [kg], I [kg.m²], position (2-vector SX of q) [m], angle (SX of q) [rad]) each, gravity
    −G along y, ``V_extra(q)`` more potential energy [J], ``Q_extra(q, q̇)`` more generalized
    forces. M = Σ m J_pᵀJ_p + I J_aᵀJ_a; M q̈ = Q − ∂V/∂q − Ṁ q̇ + ∂T/∂q. CasADi only
    differentiates; returns f(q, q̇) -> q̈ and the Function of the positions and angles."""
    n = q.numel()
    qd = ca.SX.sym("qd", n)
    M, V = ca.SX.zeros(n, n), V_extra
    for m, I, pos, angle in bodies:
        Jp, Ja = ca.jacobian(pos, q), ca.jacobian(angle, q)
        M += m * ca.mtimes(Jp.T, Jp) + I * ca.mtimes(Ja.T, Ja)
        V += m * G * pos[1]
    T = 0.5 * ca.mtimes([qd.T, M, qd])
    Mdot_qd = ca.mtimes(ca.jacobian(ca.mtimes(M, qd), q), qd)
    Q = Q_extra(q, qd) if Q_extra is not None else ca.SX.zeros(n)
    rhs = Q - ca.gradient(V, q) - Mdot_qd + ca.gradient(T, q)
    return ca.Function("qdd", [q, qd], [ca.solve(M, rhs)])


def integrate(qdd, q0, qd0, t):
    """q(t), q̇(t) of the minimal model by DOP853 at tolerance 1e-12."""
    n = len(q0)

    def rhs(_, y):
        return np.concatenate([y[n:], np.array(qdd(y[:n], y[n:])).ravel()])

    sol = solve_ivp(rhs, (t[0], t[-1]), list(q0) + list(qd0), method="DOP853", t_eval=t,
                    rtol=1e-12, atol=1e-12)
    assert sol.success
    return sol.y[:n], sol.y[n:]


def kinematic_loop_reference(t):
    """KinematicLoop in q = (s, β): s the prismatic base [m], β the pendulum's absolute angle.
    The links (0.5 m each) meet at the apex A = (s/2, −√(0.25 − s²/4)), below the base;
    revolute1.phi = asin(s) (its link from the origin to A), the pendulum's body at
    A + 0.6·(sin β, −cos β), revolute4.phi = β − revolute1.phi. The spring-damper on s:
    V = ½·20·(s − 0.4)², Q_s = −4·ṡ. Returns the four reference signals."""
    q = ca.SX.sym("q", 2)
    s, beta = q[0], q[1]
    apex = ca.vertcat(s / 2, -ca.sqrt(0.25 - s ** 2 / 4))
    body = apex + 0.6 * ca.vertcat(ca.sin(beta), -ca.cos(beta))
    qdd = minimal_model(q, [(1.0, 0.1, body, beta)], V_extra=0.5 * 20.0 * (s - 0.4) ** 2,
                        Q_extra=lambda q, qd: ca.vertcat(-4.0 * qd[0], 0))
    x0 = KinematicLoop.X0
    phi1 = math.asin(x0["prismatic1.s"])
    (s, beta), (sd, betad) = integrate(qdd, [x0["prismatic1.s"], phi1 + x0["revolute4.phi"]],
                                       [0.0, 0.0], t)
    phi1, w1 = np.arcsin(s), sd / np.sqrt(1 - s ** 2)
    return {"revolute1.phi": phi1, "revolute1.w": w1, "revolute4.phi": beta - phi1,
            "revolute4.w": betad - w1}


def piston_x(theta):
    """The piston's x [m] for the crank angle θ: the rod (0.8 m) from the pin
    0.3·(cos θ, sin θ) to the x axis, the piston right of the pin."""
    return 0.3 * ca.cos(theta) + ca.sqrt(0.64 - (0.3 * ca.sin(theta)) ** 2)


def piston_engine_reference(t):
    """PistonEngine in the crank angle θ: bodyDrive turns on the crank's axis (I = 0.1),
    bodyPiston (m = 3) slides at (piston_x(θ), 0) without turning; gravity does no work."""
    theta = ca.SX.sym("theta")
    qdd = minimal_model(theta, [(1.0, 0.1, ca.vertcat(0, 0), theta),
                                (3.0, 0.1, ca.vertcat(piston_x(theta), 0), ca.SX(0))])
    x0 = PistonEngine.X0
    (th,), (thd,) = integrate(qdd, [x0["revoluteDrive.phi"]], [x0["revoluteDrive.w"]], t)
    return {"revoluteDrive.phi": th, "revoluteDrive.w": thd}


REFERENCES = {KinematicLoop: kinematic_loop_reference, PistonEngine: piston_engine_reference}
# joint angles on the branch PlanarMechanics starts from, for trees that have them as states
GUESS = {KinematicLoop: {"revolute1.phi": math.asin(0.4), "revolute3.phi": -math.asin(0.4),
                         "revolute2.phi": -2 * math.asin(0.4)},
         PistonEngine: {"prismatic.s": -1.1}}


@pytest.fixture(scope="module", params=[KinematicLoop, PistonEngine],
                ids=["KinematicLoop", "PistonEngine"])
def runs(request):
    """The example compiled and simulated in each declaration order: (class, [(compiled,
    Result)])."""
    cls = request.param
    t = np.linspace(0.0, cls.STOP_TIME, 1201)
    out = []
    for order in orders(cls):
        compiled = ac.compile(cls(order=order))
        out.append((compiled, simulate(compiled, cls, t, GUESS[cls])))
    return cls, out


def test_every_declaration_order_compiles_to_coordinates_with_mass(runs):
    """The tree cuts each loop where its coordinates keep mass, whatever the order: no row
    of the mass matrix is zero."""
    cls, out = runs
    for compiled, res in out:
        assert compiled.method == "constrained (KKT) solve"
        assert massless_coordinates(compiled, res) == [], compiled.coordinates


def test_declaration_orders_give_the_same_motion(runs):
    cls, out = runs
    first = out[0][1]
    for compiled, res in out[1:]:
        for name in REFERENCES[cls](first.t[:2]):        # the signals MSL records
            scale = np.max(np.abs(first[name]))
            assert np.max(np.abs(res[name] - first[name])) < 1e-7 * scale, name


def test_matches_the_minimal_coordinate_model(runs):
    cls, out = runs
    ref = REFERENCES[cls](out[0][1].t)
    for compiled, res in out:
        for name, y in ref.items():
            assert np.max(np.abs(res[name] - y)) < 1e-6 * np.max(np.abs(y)), name
    assert min(np.ptp(y) for y in ref.values()) > 0.1           # it really moves


def test_loops_stay_closed(runs):
    """Every joint relation from the recorded frame poses (the loop's closing joint among
    them, whichever it is)."""
    cls, out = runs
    joints = [n for n in cls.COMPONENTS if n.startswith(("revolute", "prismatic"))]
    for compiled, res in out:
        for j in joints:
            a = [res[f"{j}.frame_a.{c}"] for c in ("x", "y", "phi")]
            b = [res[f"{j}.frame_b.{c}"] for c in ("x", "y", "phi")]
            if j.startswith("revolute"):
                rows = [b[0] - a[0], b[1] - a[1], b[2] - a[2] - res[f"{j}.phi"]]
            else:                                      # both prismatic joints run along x
                rows = [b[0] - a[0] - res[f"{j}.s"] * np.cos(a[2]),
                        b[1] - a[1] - res[f"{j}.s"] * np.sin(a[2]), b[2] - a[2]]
            assert np.max(np.abs(rows)) < 1e-8, j


@pytest.mark.parametrize("cls", [KinematicLoop, PistonEngine],
                         ids=["KinematicLoop", "PistonEngine"])
def test_matches_the_msl_reference_results(cls, reference_result):
    """PlanarMechanics' reference results (DLR, Dymola at tolerance 1e-6): within 2e-3 of
    each signal's peak, on the reference's own grid, in two declaration orders
    (PlanarMechanics' and reversed)."""
    ref = reference_result("PlanarMechanics_ReferenceResults",
                           f"PlanarMechanics.Examples.{cls.__name__}")
    t = ref["time"] if "time" in ref else ref["Time"]
    for order in (None, "reversed"):
        res = simulate(ac.compile(cls(order=order)), cls, t, GUESS[cls], rtol=1e-8, atol=1e-10)
        for col, y in ref.items():
            if col.lower() != "time":
                assert np.max(np.abs(res[col] - y)) < 2e-3 * np.max(np.abs(y)), (order, col)


# ---- no choice: a four-bar with a massless crank and rocker ---------------------------------
L0, L1, L2, L3 = 1.0, 0.3, 1.0, 0.8             # m: ground, crank, coupler, rocker
M2, I2 = 1.0, 1.0 / 12                          # kg, kg.m²: the coupler, a slender rod


def light_four_bar(reverse=False):
    """Ground pivots A = (0, 0), D = (L0, 0); massless bars crank A–B (rev1) and rocker D–C
    (rev3); the coupler B–C (rev2) a bar with a Body at its middle; rev4 joins C. Every tree
    leaves one coordinate without mass: the one that turns the crank or the rocker alone."""
    m = Model("light_four_bar")
    parts = dict(world=World(), A=Fixed(), D=Fixed(r=(L0, 0.0)), rev1=Revolute(),
                 crank=FixedTranslation(r=(L1, 0.0)), rev2=Revolute(),
                 coupler_a=FixedTranslation(r=(L2 / 2, 0.0)), coupler=Body(m=M2, I=I2),
                 coupler_b=FixedTranslation(r=(L2 / 2, 0.0)), rev3=Revolute(),
                 rocker=FixedTranslation(r=(L3, 0.0)), rev4=Revolute())
    for name in (list(parts)[::-1] if reverse else parts):
        setattr(m, name, parts[name])
    c = m.connect
    c(m.A.frame, m.rev1.frame_a)
    c(m.rev1.frame_b, m.crank.frame_a)
    c(m.crank.frame_b, m.rev2.frame_a)
    c(m.rev2.frame_b, m.coupler_a.frame_a)
    c(m.coupler_a.frame_b, m.coupler.frame_a)
    c(m.coupler.frame_a, m.coupler_b.frame_a)
    c(m.D.frame, m.rev3.frame_a)
    c(m.rev3.frame_b, m.rocker.frame_a)
    c(m.coupler_b.frame_b, m.rev4.frame_a)
    c(m.rocker.frame_b, m.rev4.frame_b)
    return m


def light_four_bar_geometry(theta):
    """(B, C, coupler angle β, rocker angle γ) for the crank angle θ, C above the line B→D."""
    e = lambda a: ca.vertcat(ca.cos(a), ca.sin(a))          # noqa: E731
    B = L1 * e(theta)
    d = ca.vertcat(L0, 0) - B
    dist = ca.norm_2(d)
    a = (L2 ** 2 - L3 ** 2 + dist ** 2) / (2 * dist)
    u = d / dist
    C = B + a * u + ca.sqrt(L2 ** 2 - a ** 2) * ca.vertcat(-u[1], u[0])
    return B, C, ca.atan2(C[1] - B[1], C[0] - B[0]), ca.atan2(C[1], C[0] - L0)


def test_four_bar_without_a_choice_moves_its_massless_coordinate_with_the_loop():
    theta = ca.SX.sym("theta")
    B, C, beta, gamma = light_four_bar_geometry(theta)
    qdd = minimal_model(theta, [(M2, I2, (B + C) / 2, beta)])
    theta0, w0 = 1.0, 1.5
    t = np.linspace(0.0, 3.0, 301)
    (th,), _ = integrate(qdd, [theta0], [w0], t)
    assert np.ptp(th) > 1.0
    angles = ca.Function("angles", [theta], [beta - theta, gamma])
    b0, g0 = (float(v) for v in angles(theta0))
    guess = {"rev2.phi": b0, "rev3.phi": g0, "rev4.phi": g0 - b0 - theta0}
    first = None
    for reverse in (False, True):
        compiled = ac.compile(light_four_bar(reverse))
        with warnings.catch_warnings():
            warnings.filterwarnings("ignore", "initial values changed", UserWarning)
            res = compiled.simulate(3.0, t=t, x0={"rev1.phi": theta0, "rev1.w": w0},
                                    guess={k: v for k, v in guess.items()
                                           if k in compiled.x_names}, **TIGHT)
        assert len(massless_coordinates(compiled, res)) == 1      # no tree avoids it
        assert np.max(np.abs(res["rev1.phi"] - th)) < 1e-6
        gap = np.hypot(res["rev4.frame_a.x"] - res["rev4.frame_b.x"],
                       res["rev4.frame_a.y"] - res["rev4.frame_b.y"])
        assert np.max(gap) < 1e-8
        if first is not None:
            assert np.max(np.abs(res["rev3.phi"] - first["rev3.phi"])) < 1e-6
        first = res


def test_a_loop_that_moves_no_mass_is_refused():
    """KinematicLoop without its pendulum: the triangle moves (its spring-damper holds it)
    without moving any mass; the constraints cannot give its accelerations. Refused, naming
    the loop's coordinates, rather than solved wrong."""
    m = Model("triangle")
    m.world, m.fixed = World(), Fixed()
    m.rev1, m.rev2, m.rev3 = Revolute(), Revolute(), Revolute()
    m.bar1, m.bar2 = FixedTranslation(r=(0.0, -0.5)), FixedTranslation(r=(0.0, -0.5))
    m.prismatic = Prismatic(r=(1.0, 0.0), useFlange=True)
    m.spring, m.fixed1D = tr.SpringDamper(c=20.0, d=4.0, s_rel0=0.4), tr.Fixed()
    c = m.connect
    c(m.fixed.frame, m.rev1.frame_a)
    c(m.rev1.frame_b, m.bar1.frame_a)
    c(m.bar1.frame_b, m.rev2.frame_a)
    c(m.rev2.frame_b, m.bar2.frame_b)
    c(m.bar2.frame_a, m.rev3.frame_b)
    c(m.rev3.frame_a, m.prismatic.frame_b)
    c(m.prismatic.frame_a, m.fixed.frame)
    c(m.fixed1D.flange, m.spring.flange_a)
    c(m.spring.flange_b, m.prismatic.axis)
    with pytest.raises(StructureError, match=r"without moving any mass.*rev\d\.phi.*mass or "
                                             r"inertia"):
        ac.compile(m)
