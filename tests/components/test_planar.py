"""Planar multibody library (after PlanarMechanics) against independent references.

Every reference is written here by hand: closed forms (free fall, incline, constant force),
Lagrangian / Newton ODEs integrated with scipy (pendulum, double pendulum, spring elements,
driven joints), energy balances and Newton's law on the recorded trajectories (cut forces).
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal import Model
from acausal.components import planar as P
from acausal.components import rotational as Rot
from acausal.components import signals as S
from acausal.components import translational as Tr
from acausal.errors import ParameterError, PortConnectionError, StructureError

G = 9.81
TOL = 1e-6
SIM = dict(rtol=1e-10, atol=1e-12)


def ref_ode(f, y0, t):
    """A hand-written ODE integrated tightly on the grid t."""
    sol = solve_ivp(f, (t[0], t[-1]), y0, t_eval=t, method="DOP853", rtol=1e-12, atol=1e-12)
    assert sol.success
    return sol.y


def pendulum(L=1.0, m=1.0, I=0.1, use_flange=False, sensor=None):
    """Fixed -> [sensor] -> Revolute -> bar (L along x at phi = 0) -> body."""
    md = Model("pendulum")
    md.world = P.World()
    md.fixed = P.Fixed()
    md.rev = P.Revolute(useFlange=use_flange)
    md.bar = P.FixedTranslation(r=(L, 0.0))
    md.body = P.Body(m=m, I=I)
    if sensor is None:
        md.connect(md.fixed.frame, md.rev.frame_a)
    else:
        md.sensor = sensor
        md.connect(md.fixed.frame, md.sensor.frame_a)
        md.connect(md.sensor.frame_b, md.rev.frame_a)
    md.connect(md.rev.frame_b, md.bar.frame_a)
    md.connect(md.bar.frame_b, md.body.frame_a)
    return md


def pendulum_ref(t, phi0, w0, L=1.0, m=1.0, I=0.1, tau=lambda t: 0.0, d=0.0):
    """(I + m L²) φ̈ = −m g L cos φ + τ(t) − d φ̇: body at L(cos φ, sin φ), g along −y."""
    J = I + m * L ** 2
    return ref_ode(lambda tt, y: [y[1], (-m * G * L * math.cos(y[0]) + tau(tt) - d * y[1]) / J],
                   [phi0, w0], t)


# =========================================================================================
# Pendulums
# =========================================================================================
def test_simple_pendulum_matches_hand_ode():
    t = np.linspace(0, 3, 151)
    c = acausal.compile(pendulum(L=0.8, m=1.3, I=0.05))
    assert c.lagrange.q_names == ["rev.phi"]
    res = c.simulate(3.0, t=t, x0={"rev.phi": 0.3, "rev.w": -0.5}, **SIM)
    phi, w = pendulum_ref(t, 0.3, -0.5, L=0.8, m=1.3, I=0.05)
    assert np.max(np.abs(res["rev.phi"] - phi)) < TOL
    assert np.max(np.abs(res["rev.w"] - w)) < TOL
    # the body follows the bar: position and angle
    assert np.max(np.abs(res["body.r[1]"] - 0.8 * np.cos(phi))) < TOL
    assert np.max(np.abs(res["body.r[2]"] - 0.8 * np.sin(phi))) < TOL
    assert np.max(np.abs(res["body.phi"] - phi)) < TOL


def test_double_pendulum_matches_lagrangian():
    L1, L2, m1, m2, I1, I2 = 1.0, 0.7, 1.5, 0.8, 0.2, 0.05
    md = Model("double")
    md.world = P.World()
    md.fixed = P.Fixed()
    md.rev1 = P.Revolute()
    md.bar1 = P.FixedTranslation(r=(L1, 0.0))
    md.body1 = P.Body(m=m1, I=I1)
    md.rev2 = P.Revolute()
    md.bar2 = P.FixedTranslation(r=(L2, 0.0))
    md.body2 = P.Body(m=m2, I=I2)
    md.connect(md.fixed.frame, md.rev1.frame_a)
    md.connect(md.rev1.frame_b, md.bar1.frame_a)
    md.connect(md.bar1.frame_b, md.body1.frame_a)
    md.connect(md.bar1.frame_b, md.rev2.frame_a)
    md.connect(md.rev2.frame_b, md.bar2.frame_a)
    md.connect(md.bar2.frame_b, md.body2.frame_a)
    t = np.linspace(0, 2, 101)
    res = acausal.compile(md).simulate(2.0, t=t, x0={"rev1.phi": -0.4, "rev2.phi": 0.9,
                                                     "rev1.w": 0.5, "rev2.w": 0.0}, **SIM)

    def rhs(_, y):       # absolute angles θ1 = φ1, θ2 = φ1 + φ2 (hand-derived Lagrangian)
        th1, th2, w1, w2 = y
        c, s = math.cos(th1 - th2), math.sin(th1 - th2)
        M = np.array([[I1 + (m1 + m2) * L1 ** 2, m2 * L1 * L2 * c],
                      [m2 * L1 * L2 * c, I2 + m2 * L2 ** 2]])
        rhs = np.array([-m2 * L1 * L2 * s * w2 ** 2 - (m1 + m2) * G * L1 * math.cos(th1),
                        m2 * L1 * L2 * s * w1 ** 2 - m2 * G * L2 * math.cos(th2)])
        return [w1, w2, *np.linalg.solve(M, rhs)]

    th1, th2, w1, w2 = ref_ode(rhs, [-0.4, 0.5, 0.5, 0.5], t)
    assert np.max(np.abs(res["rev1.phi"] - th1)) < TOL
    assert np.max(np.abs(res["rev2.phi"] - (th2 - th1))) < TOL
    assert np.max(np.abs(res["rev2.w"] - (w2 - w1))) < TOL
    assert np.max(np.abs(res["body2.phi"] - th2)) < TOL


# =========================================================================================
# Free body, incline
# =========================================================================================
def test_free_body_parabola():
    md = Model("free")
    md.world = P.World()
    md.body = P.Body(m=2.0, I=0.3)
    c = acausal.compile(md)
    assert len(c.lagrange.q_names) == 3               # x, y, phi of the free body
    t = np.linspace(0, 1.5, 31)
    x0 = {"body.r[1]": 0.5, "body.r[2]": 2.0, "body.phi": 0.1,
          "body.v[1]": 1.2, "body.v[2]": 3.0, "body.w": -2.0}
    res = c.simulate(1.5, t=t, x0=x0, **SIM)
    assert np.max(np.abs(res["body.r[1]"] - (0.5 + 1.2 * t))) < TOL
    assert np.max(np.abs(res["body.r[2]"] - (2.0 + 3.0 * t - 0.5 * G * t ** 2))) < TOL
    assert np.max(np.abs(res["body.phi"] - (0.1 - 2.0 * t))) < TOL
    assert np.max(np.abs(res["body.a[2]"] + G)) < TOL
    assert np.max(np.abs(res["body.f[1]"])) < TOL and np.max(np.abs(res["body.f[2]"])) < TOL


def test_free_body_tilted_gravity():
    md = Model("free")
    md.world = P.World(g=5.0, n=(0.6, -0.8))
    md.body = P.Body(m=1.0, I=0.1)
    t = np.linspace(0, 1.0, 11)
    res = acausal.compile(md).simulate(1.0, t=t, **SIM)
    assert np.max(np.abs(res["body.r[1]"] - 0.5 * 3.0 * t ** 2)) < TOL
    assert np.max(np.abs(res["body.r[2]"] + 0.5 * 4.0 * t ** 2)) < TOL


@pytest.mark.parametrize("g, n", [(9.81, (0.0, -2.0)), (4.0, (3.0, 4.0))])
def test_world_gravity_is_g_along_n_over_its_length(g, n):
    """MultiBody's World: gravity = g·n/|n|, whatever the length of n. A free body falls by
    r = ½·g·n/|n|·t² (closed form)."""
    md = Model("fall")
    md.world = P.World(g=g, n=n)
    md.body = P.Body(m=2.0, I=0.1)
    t = np.linspace(0, 1.0, 11)
    res = acausal.compile(md).simulate(1.0, t=t, **SIM)
    e = np.array(n) / np.hypot(*n)
    assert np.max(np.abs(res["body.r[1]"] - 0.5 * g * e[0] * t ** 2)) < TOL
    assert np.max(np.abs(res["body.r[2]"] - 0.5 * g * e[1] * t ** 2)) < TOL
    assert np.max(np.abs(res["body.f[2]"])) < TOL                  # free fall: no force


def test_world_without_a_direction_is_refused():
    md = Model("fall")
    md.world = P.World(n=(0.0, 0.0))
    md.body = P.Body()
    with pytest.raises(ParameterError) as err:
        acausal.compile(md)
    assert str(err.value) == ("World 'world': n = {0, 0} gives no direction; give one, e.g. "
                              "World(n=(0, -1))")


def test_prismatic_incline_and_normal_force():
    alpha, m = 0.4, 2.5
    md = Model("incline")
    md.world = P.World()
    md.fixed = P.Fixed(r=(1.0, -2.0), phi=alpha)
    md.prism = P.Prismatic(r=(2.0, 0.0))              # not a unit vector: normalized
    md.cut = P.CutForceAndTorque()
    md.body = P.Body(m=m, I=0.2)
    md.connect(md.fixed.frame, md.prism.frame_a)
    md.connect(md.prism.frame_b, md.cut.frame_a)
    md.connect(md.cut.frame_b, md.body.frame_a)
    t = np.linspace(0, 1.2, 25)
    res = acausal.compile(md).simulate(1.2, t=t, x0={"prism.s": 0.3, "prism.v": 1.0}, **SIM)
    s = 0.3 + 1.0 * t - 0.5 * G * math.sin(alpha) * t ** 2
    assert np.max(np.abs(res["prism.s"] - s)) < TOL
    assert np.max(np.abs(res["body.r[1]"] - (1.0 + s * math.cos(alpha)))) < TOL
    assert np.max(np.abs(res["body.r[2]"] - (-2.0 + s * math.sin(alpha)))) < TOL
    assert np.max(np.abs(res["body.phi"] - alpha)) < TOL
    # the rail carries the normal force m g cos(alpha), perpendicular to the incline
    # (resolved in the sensor's frame_a, which is at angle alpha), and no torque
    assert np.max(np.abs(res["cut.force[1]"])) < TOL
    assert np.max(np.abs(res["cut.force[2]"] - m * G * math.cos(alpha))) < TOL
    assert np.max(np.abs(res["cut.torque"])) < TOL


# =========================================================================================
# Force elements
# =========================================================================================
def test_line_spring_damper_oscillation_matches_hand_ode():
    m, c, d, L0 = 0.7, 40.0, 0.9, 0.5
    md = Model("elastic")
    md.world = P.World()
    md.fixed = P.Fixed(r=(0.2, 0.1))
    md.sd = P.LineSpringDamper(c=c, d=d, s_rel0=L0)
    md.body = P.Body(m=m, I=0.1)
    md.connect(md.fixed.frame, md.sd.frame_a)
    md.connect(md.sd.frame_b, md.body.frame_a)
    t = np.linspace(0, 2, 101)
    res = acausal.compile(md).simulate(2.0, t=t, x0={
        "body.r[1]": 0.9, "body.r[2]": -0.3, "body.v[1]": 0.0, "body.v[2]": 1.0,
        "body.phi": 0.0, "body.w": 0.7}, **SIM)

    def rhs(_, y):
        x, yy, vx, vy = y
        dx, dy = x - 0.2, yy - 0.1
        length = math.hypot(dx, dy)
        ex, ey = dx / length, dy / length
        f = c * (length - L0) + d * (ex * vx + ey * vy)          # tension
        return [vx, vy, -f * ex / m, -f * ey / m - G]

    x, y, vx, vy = ref_ode(rhs, [0.9, -0.3, 0.0, 1.0], t)
    assert np.max(np.abs(res["body.r[1]"] - x)) < TOL
    assert np.max(np.abs(res["body.r[2]"] - y)) < TOL
    assert np.max(np.abs(res["body.v[2]"] - vy)) < TOL
    assert np.max(np.abs(res["body.w"] - 0.7)) < TOL        # no torque about the origins
    length = np.hypot(x - 0.2, y - 0.1)
    assert np.max(np.abs(res["sd.length"] - length)) < TOL
    vrel = ((x - 0.2) * vx + (y - 0.1) * vy) / length
    assert np.max(np.abs(res["sd.f"] - (c * (length - L0) + d * vrel))) < 1e-5
    assert np.max(np.abs(res["sd.lossPower"] - d * vrel ** 2)) < 1e-5


def test_xy_spring_damper_matches_hand_ode():
    """PlanarMechanics' SpringDamper (after its SpringDamperDemo, with c_phi, d_phi > 0)."""
    m, I = 0.5, 0.1
    cx, cy, cphi, dx_, dy_, dphi = 5.0, 7.0, 2.0, 1.0, 0.5, 0.3
    md = Model("sdd")
    md.world = P.World()
    md.fixed = P.Fixed()
    md.ft = P.FixedTranslation(r=(-1.0, 0.0))
    md.sd = P.SpringDamper(c_x=cx, c_y=cy, c_phi=cphi, d_x=dx_, d_y=dy_, d_phi=dphi,
                           s_relx0=0.2, s_rely0=-0.1, phi_rel0=0.25)
    md.body = P.Body(m=m, I=I)
    md.connect(md.fixed.frame, md.ft.frame_a)
    md.connect(md.ft.frame_b, md.sd.frame_a)
    md.connect(md.sd.frame_b, md.body.frame_a)
    t = np.linspace(0, 3, 61)
    y0 = [1.0, 1.0, 0.0, 0.3, -0.4, 0.0]
    res = acausal.compile(md).simulate(3.0, t=t, x0=dict(zip(
        ["body.r[1]", "body.r[2]", "body.phi", "body.v[1]", "body.v[2]", "body.w"], y0)), **SIM)

    def rhs(_, y):
        x, yy, ph, vx, vy, w = y
        return [vx, vy, w, (-cx * (x + 1.0 - 0.2) - dx_ * vx) / m,
                (-cy * (yy + 0.1) - dy_ * vy) / m - G, (-cphi * (ph - 0.25) - dphi * w) / I]

    ref = ref_ode(rhs, y0, t)
    for k, name in enumerate(["body.r[1]", "body.r[2]", "body.phi"]):
        assert np.max(np.abs(res[name] - ref[k])) < TOL, name
    assert np.max(np.abs(res["sd.lossPower"] - (dx_ * ref[3] ** 2 + dy_ * ref[4] ** 2
                                                + dphi * ref[5] ** 2))) < 1e-5


def test_xy_spring_and_line_damper_on_prismatic():
    """PlanarMechanics' SpringDemo: an x/y Spring and the line Damper in parallel with a
    vertical Prismatic; the body passes the spring's zero length (the damper's too)."""
    m, cy, d = 0.5, 10.0, 1.0
    md = Model("springdemo")
    md.world = P.World()
    md.fixed = P.Fixed()
    md.ft = P.FixedTranslation()                       # r = {1, 0}
    md.spring = P.Spring(c_y=cy, s_rely0=-0.5, c_x=1.0, c_phi=1e5)
    md.damper = P.Damper(d=d)
    md.prism = P.Prismatic(r=(0.0, 1.0))
    md.body = P.Body(m=m, I=0.1)
    md.connect(md.fixed.frame, md.ft.frame_a)
    md.connect(md.spring.frame_a, md.ft.frame_b)
    md.connect(md.spring.frame_b, md.body.frame_a)
    md.connect(md.damper.frame_a, md.spring.frame_a)
    md.connect(md.damper.frame_b, md.spring.frame_b)
    md.connect(md.spring.frame_a, md.prism.frame_a)
    md.connect(md.prism.frame_b, md.spring.frame_b)
    t = np.linspace(0, 1.0, 51)
    res = acausal.compile(md).simulate(1.0, t=t, x0={"prism.s": 0.2, "prism.v": 0.0}, **SIM)
    # m s'' = -c_y (s - s_rely0) - d s' - m g (the line damper along ±y gives -d s')
    s, v = ref_ode(lambda _, y: [y[1], (-cy * (y[0] + 0.5) - d * y[1]) / m - G], [0.2, 0.0], t)
    assert np.min(s) < 0 < np.max(s)                    # crosses zero length
    assert np.max(np.abs(res["prism.s"] - s)) < 1e-5
    assert np.max(np.abs(res["spring.f_y"] - cy * (s + 0.5))) < 1e-4
    assert np.max(np.abs(res["damper.length"] - np.abs(s))) < 1e-5
    away = np.abs(s) > 1e-3                             # f = -d·der(length), PlanarMechanics' sign
    assert np.max(np.abs(res["damper.f"][away] + d * np.sign(s[away]) * v[away])) < 1e-5
    assert np.max(np.abs(res["damper.lossPower"][away] - d * v[away] ** 2)) < 1e-5


def test_xy_spring_has_no_torque_and_conserves_energy():
    """PlanarMechanics' Spring: c_phi exerts no torque; world-axis springs are conservative."""
    m, I, cx, cy = 1.2, 0.2, 30.0, 12.0
    md = Model("xy")
    md.world = P.World()
    md.fixed = P.Fixed(r=(0.0, 1.0))
    md.spring = P.Spring(c_x=cx, c_y=cy, s_relx0=0.1, s_rely0=-0.4)
    md.body = P.Body(m=m, I=I)
    md.connect(md.fixed.frame, md.spring.frame_a)
    md.connect(md.spring.frame_b, md.body.frame_a)
    t = np.linspace(0, 3, 301)
    res = acausal.compile(md).simulate(3.0, t=t, x0={
        "body.r[1]": 0.4, "body.r[2]": 0.2, "body.v[1]": 0.3, "body.v[2]": -1.0, "body.phi": 0,
        "body.w": 1.5}, **SIM)
    assert np.max(np.abs(res["body.w"] - 1.5)) < TOL
    x, y = res["body.r[1]"], res["body.r[2]"]
    E = (0.5 * m * (res["body.v[1]"] ** 2 + res["body.v[2]"] ** 2)
         + 0.5 * I * res["body.w"] ** 2 + 0.5 * cx * (x - 0.1) ** 2
         + 0.5 * cy * (y - 1.0 + 0.4) ** 2 + m * G * y)
    assert np.max(np.abs(E - E[0])) / abs(E[0]) < TOL


def test_spring_pendulum_energy_is_conserved():
    """Revolute + Prismatic (a rod with a sliding mass held by a LineSpring) and gravity."""
    m, I, c, L0 = 1.0, 0.05, 60.0, 0.6
    md = Model("springpendulum")
    md.world = P.World()
    md.fixed = P.Fixed()
    md.rev = P.Revolute()
    md.prism = P.Prismatic(r=(1.0, 0.0))
    md.body = P.Body(m=m, I=I)
    md.spring = P.LineSpring(c=c, s_rel0=L0)
    md.connect(md.fixed.frame, md.rev.frame_a)
    md.connect(md.rev.frame_b, md.prism.frame_a)
    md.connect(md.prism.frame_b, md.body.frame_a)
    md.connect(md.fixed.frame, md.spring.frame_a)
    md.connect(md.spring.frame_b, md.body.frame_a)
    t = np.linspace(0, 4, 401)
    res = acausal.compile(md).simulate(4.0, t=t, x0={"rev.phi": -0.3, "rev.w": 1.0,
                                                     "prism.s": 0.8, "prism.v": 0.0}, **SIM)
    x, y, ph = res["body.r[1]"], res["body.r[2]"], res["body.phi"]
    T = 0.5 * m * (res["body.v[1]"] ** 2 + res["body.v[2]"] ** 2) + 0.5 * I * res["body.w"] ** 2
    V = 0.5 * c * (np.hypot(x, y) - L0) ** 2 + m * G * y
    E = T + V
    assert np.ptp(res["prism.s"]) > 0.05 and np.ptp(ph) > 0.5        # both move
    assert np.max(np.abs(E - E[0])) / np.max(np.abs(T)) < TOL
    assert np.max(np.abs(res["spring.f"] - c * (np.hypot(x, y) - L0))) < 1e-5


# =========================================================================================
# Reactions, sensors
# =========================================================================================
def test_pivot_cut_force_is_m_times_acceleration_minus_gravity():
    L, m, I = 0.9, 1.4, 0.07
    md = Model("p2")
    md.world = P.World()
    md.fixed = P.Fixed()
    md.pivot = P.CutForce()
    md.pivot_world = P.CutForceAndTorque(resolveInFrame="world", positiveSign=False)
    md.rev = P.Revolute()
    md.bar = P.FixedTranslation(r=(L, 0.0))
    md.tip = P.CutForceAndTorque()
    md.tip_torque = P.CutTorque(positiveSign=False)
    md.body = P.Body(m=m, I=I)
    md.connect(md.fixed.frame, md.pivot.frame_a)
    md.connect(md.pivot.frame_b, md.pivot_world.frame_a)
    md.connect(md.pivot_world.frame_b, md.rev.frame_a)
    md.connect(md.rev.frame_b, md.bar.frame_a)
    md.connect(md.bar.frame_b, md.tip.frame_a)
    md.connect(md.tip.frame_b, md.tip_torque.frame_a)
    md.connect(md.tip_torque.frame_b, md.body.frame_a)
    t = np.linspace(0, 2, 81)
    res = acausal.compile(md).simulate(2.0, t=t, x0={"rev.phi": 0.2, "rev.w": 1.0}, **SIM)
    phi, w = pendulum_ref(t, 0.2, 1.0, L=L, m=m, I=I)
    z = -m * G * L * np.cos(phi) / (I + m * L ** 2)
    ax = L * (-np.sin(phi) * z - np.cos(phi) * w ** 2)      # centripetal + tangential
    ay = L * (np.cos(phi) * z - np.sin(phi) * w ** 2)
    Fx, Fy = m * ax, m * (ay + G)                           # force of the pivot on the pendulum
    # pivot sensor: frame_a at the fixed frame (angle 0): force = frame_a.f = pivot's push
    assert np.max(np.abs(res["pivot.force[1]"] - Fx)) < TOL
    assert np.max(np.abs(res["pivot.force[2]"] - Fy)) < TOL
    assert np.max(np.abs(res["pivot_world.force[1]"] + Fx)) < TOL     # positiveSign=False
    assert np.max(np.abs(res["pivot_world.torque"])) < TOL            # free revolute
    # tip sensor resolved in its frame_a (turning with the bar): radial and tangential
    fr = np.cos(phi) * Fx + np.sin(phi) * Fy
    ft = -np.sin(phi) * Fx + np.cos(phi) * Fy
    assert np.max(np.abs(res["tip.force[1]"] - fr)) < TOL
    assert np.max(np.abs(res["tip.force[2]"] - ft)) < TOL
    assert np.max(np.abs(res["tip.torque"] - I * z)) < TOL           # I·φ̈ through the tip
    assert np.max(np.abs(res["tip_torque.torque"] + I * z)) < TOL    # positiveSign=False
    # the same as the revolute's own cut force at frame_a (flow into the joint)
    assert np.max(np.abs(res["rev.frame_a.fx"] - Fx)) < TOL


def test_kinematic_sensors_on_a_pendulum():
    L = 0.8
    md = pendulum(L=L)
    md.apos = P.AbsolutePosition()
    md.apos_w = P.AbsolutePosition(resolveInFrame=P.ResolveInFrameA.world)
    md.avel = P.AbsoluteVelocity()
    md.avel_w = P.AbsoluteVelocity(resolveInFrame="world")
    md.aacc = P.AbsoluteAcceleration()
    md.rpos = P.RelativePosition(resolveInFrame="frame_b")
    md.rvel = P.RelativeVelocity()                      # fixed observer: = absolute velocity
    md.rvel_b = P.RelativeVelocity(resolveInFrame="frame_b")
    md.racc = P.RelativeAcceleration()
    md.turning = P.RelativeVelocity()                   # observer turning with the body
    md.turning_acc = P.RelativeAcceleration()
    md.dist = P.Distance()
    md.ref = P.Fixed(phi=0.6)                           # a frame to resolve in
    md.apos_r = P.AbsolutePosition(resolveInFrame="frame_resolve")
    md.connect(md.apos_r.frame_resolve, md.ref.frame)
    for s in (md.apos, md.apos_w, md.avel, md.avel_w, md.aacc, md.apos_r):
        md.connect(s.frame_a, md.body.frame_a)
    for s in (md.rpos, md.rvel, md.rvel_b, md.racc, md.dist):
        md.connect(s.frame_a, md.fixed.frame)
        md.connect(s.frame_b, md.body.frame_a)
    for s in (md.turning, md.turning_acc):
        md.connect(s.frame_a, md.body.frame_a)
        md.connect(s.frame_b, md.fixed.frame)
    t = np.linspace(0, 1.5, 61)
    res = acausal.compile(md).simulate(1.5, t=t, x0={"rev.phi": -0.5, "rev.w": 0.0}, **SIM)
    phi, w = pendulum_ref(t, -0.5, 0.0, L=L)
    z = -G * L * np.cos(phi) / (0.1 + L ** 2)
    x, y = L * np.cos(phi), L * np.sin(phi)
    vx, vy = -L * np.sin(phi) * w, L * np.cos(phi) * w
    zero = np.zeros_like(t)
    expect = {
        "apos.r[1]": L + zero, "apos.r[2]": zero, "apos.r[3]": zero,
        "apos_w.r[1]": x, "apos_w.r[2]": y, "apos_w.r[3]": phi,
        "avel.v[1]": zero, "avel.v[2]": L * w, "avel.v[3]": w,
        "avel_w.v[1]": vx, "avel_w.v[2]": vy, "avel_w.v[3]": w,
        "aacc.a[1]": -L * w ** 2, "aacc.a[2]": L * z, "aacc.a[3]": z,
        "rpos.r_rel[1]": L + zero, "rpos.r_rel[2]": zero, "rpos.r_rel[3]": phi,
        "rvel.v_rel[1]": vx, "rvel.v_rel[2]": vy, "rvel.v_rel[3]": w,
        "rvel_b.v_rel[1]": zero, "rvel_b.v_rel[2]": L * w,
        "racc.a_rel[1]": L * (-np.sin(phi) * z - np.cos(phi) * w ** 2),
        "racc.a_rel[2]": L * (np.cos(phi) * z - np.sin(phi) * w ** 2),
        "turning.v_rel[1]": zero, "turning.v_rel[2]": zero, "turning.v_rel[3]": -w,
        "turning_acc.a_rel[1]": zero, "turning_acc.a_rel[2]": zero,
        "turning_acc.a_rel[3]": -z,
        "dist.distance": L + zero,
        "apos_r.r[1]": math.cos(0.6) * x + math.sin(0.6) * y,
        "apos_r.r[2]": -math.sin(0.6) * x + math.cos(0.6) * y, "apos_r.r[3]": phi - 0.6,
    }
    for name, ref in expect.items():
        assert np.max(np.abs(res[name] - ref)) < TOL, name


# =========================================================================================
# Sources
# =========================================================================================
def _free_body(md, name="body", m=2.0, I=0.5):
    setattr(md, name, P.Body(m=m, I=I))
    return getattr(md, name)


def _constants(md, values, prefix="k"):
    out = []
    for i, v in enumerate(values, start=1):
        setattr(md, f"{prefix}{i}", S.Constant(k=v))
        out.append(getattr(md, f"{prefix}{i}"))
    return out


def test_world_force_in_world_frame_and_world_torque():
    m, I, F = 2.0, 0.5, (3.0, -1.0, 0.4)
    md = Model("wf")
    md.world = P.World(g=0.0)
    body = _free_body(md, m=m, I=I)
    md.wf = P.WorldForce(resolveInFrame="world")
    md.wt = P.WorldTorque()
    for k, src in zip([*md.wf.force, md.wf.torque], _constants(md, F)):
        md.connect(src.y, k)
    md.kt = S.Constant(k=0.6)
    md.connect(md.kt.y, md.wt.torque)
    md.connect(md.wf.frame_b, body.frame_a)
    md.connect(md.wt.frame_b, body.frame_a)
    t = np.linspace(0, 1, 11)
    res = acausal.compile(md).simulate(1.0, t=t, **SIM)
    assert np.max(np.abs(res["body.r[1]"] - 0.5 * F[0] / m * t ** 2)) < TOL
    assert np.max(np.abs(res["body.r[2]"] - 0.5 * F[1] / m * t ** 2)) < TOL
    assert np.max(np.abs(res["body.w"] - (F[2] + 0.6) / I * t)) < TOL
    assert np.max(np.abs(res["wf.frame_b.fx"] + F[0])) < TOL        # flow into the source


def test_world_force_resolved_in_turning_frame_b():
    m, w0, phi0, F = 1.5, 2.0, 0.3, (1.0, 0.5)
    md = Model("wfb")
    md.world = P.World(g=0.0)
    body = _free_body(md, m=m)
    md.wf = P.WorldForce()                                # default: frame_b
    for k, src in zip([*md.wf.force, md.wf.torque], _constants(md, (*F, 0.0))):
        md.connect(src.y, k)
    md.connect(md.wf.frame_b, body.frame_a)
    t = np.linspace(0, 1.2, 13)
    res = acausal.compile(md).simulate(1.2, t=t, x0={"body.phi": phi0, "body.w": w0}, **SIM)
    ph = phi0 + w0 * t
    # v(t) = (1/m) ∫ R(φ0 + w0 s) F ds, closed form
    ic, is_ = (np.sin(ph) - math.sin(phi0)) / w0, (math.cos(phi0) - np.cos(ph)) / w0
    vx = (ic * F[0] - is_ * F[1]) / m
    vy = (is_ * F[0] + ic * F[1]) / m
    assert np.max(np.abs(res["body.v[1]"] - vx)) < TOL
    assert np.max(np.abs(res["body.v[2]"] - vy)) < TOL


def test_world_force_resolved_in_frame_resolve():
    beta, m, F = 0.7, 1.0, (2.0, 0.0)
    md = Model("wfr")
    md.world = P.World(g=0.0)
    body = _free_body(md, m=m)
    md.ref = P.Fixed(phi=beta)
    md.wf = P.WorldForce(resolveInFrame=P.ResolveInFrameB.frame_resolve)
    for k, src in zip([*md.wf.force, md.wf.torque], _constants(md, (*F, 0.0))):
        md.connect(src.y, k)
    md.connect(md.wf.frame_b, body.frame_a)
    md.connect(md.wf.frame_resolve, md.ref.frame)
    t = np.linspace(0, 1, 11)
    res = acausal.compile(md).simulate(1.0, t=t, **SIM)
    assert np.max(np.abs(res["body.r[1]"] - 0.5 * F[0] * math.cos(beta) / m * t ** 2)) < TOL
    assert np.max(np.abs(res["body.r[2]"] - 0.5 * F[0] * math.sin(beta) / m * t ** 2)) < TOL


def test_relative_force_acts_equal_and_opposite():
    mA, mB, IA, IB, phiA, F = 1.0, 3.0, 0.2, 0.4, 0.5, (1.2, -0.6, 0.0)
    md = Model("rf")
    md.world = P.World(g=0.0)
    a = _free_body(md, "a", m=mA, I=IA)
    b = _free_body(md, "b", m=mB, I=IB)
    md.rf = P.RelativeForce()                             # default: resolved in frame_a
    for k, src in zip([*md.rf.force, md.rf.torque], _constants(md, F)):
        md.connect(src.y, k)
    md.connect(md.rf.frame_a, a.frame_a)
    md.connect(md.rf.frame_b, b.frame_a)
    t = np.linspace(0, 1, 11)
    res = acausal.compile(md).simulate(1.0, t=t, x0={"a.phi": phiA, "b.r[1]": 1.0}, **SIM)
    fx = math.cos(phiA) * F[0] - math.sin(phiA) * F[1]     # force on b, world frame
    fy = math.sin(phiA) * F[0] + math.cos(phiA) * F[1]
    assert np.max(np.abs(res["b.r[1]"] - (1.0 + 0.5 * fx / mB * t ** 2))) < TOL
    assert np.max(np.abs(res["b.r[2]"] - 0.5 * fy / mB * t ** 2)) < TOL
    assert np.max(np.abs(res["a.r[1]"] + 0.5 * fx / mA * t ** 2)) < TOL
    assert np.max(np.abs(res["a.r[2]"] + 0.5 * fy / mA * t ** 2)) < TOL


def test_relative_force_torque_in_world_frame():
    IA, IB, tau = 0.2, 0.4, 0.3
    md = Model("rft")
    md.world = P.World(g=0.0)
    a = _free_body(md, "a", I=IA)
    b = _free_body(md, "b", I=IB)
    md.rf = P.RelativeForce(resolveInFrame="world")
    for k, src in zip([*md.rf.force, md.rf.torque], _constants(md, (0.0, 0.0, tau))):
        md.connect(src.y, k)
    md.connect(md.rf.frame_a, a.frame_a)
    md.connect(md.rf.frame_b, b.frame_a)
    t = np.linspace(0, 1, 11)
    res = acausal.compile(md).simulate(1.0, t=t, **SIM)
    assert np.max(np.abs(res["b.w"] - tau / IB * t)) < TOL
    assert np.max(np.abs(res["a.w"] + tau / IA * t)) < TOL


def test_power_sensor_measures_the_power_into_frame_b():
    """PlanarMechanics.Sensors.Power between a WorldForce (world frame, force F, torque τ)
    and a free body starting at rest: power = F·v + τ·w = (|F|²/m + τ²/I)·t (closed
    form); frame_a and frame_b move together."""
    m, I, F, tau = 2.0, 0.5, (3.0, -1.0), 0.4
    md = Model("power")
    md.world = P.World(g=0.0)
    body = _free_body(md, m=m, I=I)
    md.wf = P.WorldForce(resolveInFrame="world")
    md.power = P.Power()
    for k, src in zip([*md.wf.force, md.wf.torque], _constants(md, (*F, tau))):
        md.connect(src.y, k)
    md.connect(md.wf.frame_b, md.power.frame_a)
    md.connect(md.power.frame_b, body.frame_a)
    t = np.linspace(0, 1, 11)
    res = acausal.compile(md).simulate(1.0, t=t, x0={"body.r[1]": 0.3}, **SIM)
    expected = ((F[0] ** 2 + F[1] ** 2) / m + tau ** 2 / I) * t
    assert np.max(np.abs(res["power.power"] - expected)) < TOL
    assert np.max(np.abs(res["power.frame_a.x"] - res["body.r[1]"])) < TOL


def test_body_without_gravity_keeps_still_while_another_falls():
    """Body.enableGravity = false (PlanarMechanics): f = m·a, gravity does not act on it;
    a body with the default falls by ½·g·t² (closed forms)."""
    md = Model("gravity")
    md.world = P.World()
    md.floating = P.Body(m=2.0, enableGravity=False)
    md.falling = P.Body(m=2.0)
    t = np.linspace(0, 1, 11)
    res = acausal.compile(md).simulate(1.0, t=t, x0={"floating.v[1]": 0.5}, **SIM)
    assert np.max(np.abs(res["floating.r[1]"] - 0.5 * t)) < TOL
    assert np.max(np.abs(res["floating.r[2]"])) < TOL
    assert np.max(np.abs(res["floating.f[2]"])) < TOL              # f = m·a = 0
    assert np.max(np.abs(res["falling.r[2]"] + 0.5 * G * t ** 2)) < TOL


def test_state_select_is_a_hint_that_changes_nothing():
    """stateSelect (Revolute, Prismatic, Body as PlanarMechanics) is accepted with every
    value of Modelica's StateSelect; the pendulum still matches the hand ODE."""
    t = np.linspace(0, 1, 21)
    phi, _ = pendulum_ref(t, 0.3, 0.0)
    for choice in ("never", "avoid", "default", "prefer", "always"):
        md = Model("pendulum")
        md.world, md.fixed = P.World(), P.Fixed()
        md.rev = P.Revolute(stateSelect=choice)
        assert md.rev.stateSelect is P.StateSelect(choice)
        md.bar = P.FixedTranslation(r=(1.0, 0.0))
        md.body = P.Body(m=1.0, I=0.1, stateSelect=choice)
        for a, b in [(md.fixed.frame, md.rev.frame_a), (md.rev.frame_b, md.bar.frame_a),
                     (md.bar.frame_b, md.body.frame_a)]:
            md.connect(a, b)
        res = acausal.compile(md).simulate(1.0, t=t, x0={"rev.phi": 0.3}, **SIM)
        assert np.max(np.abs(res["rev.phi"] - phi)) < TOL
    assert P.Prismatic(stateSelect=P.StateSelect.always).stateSelect == "always"


def test_options_not_available_yet_accept_only_their_off_value():
    assert P.Damper(enableAssert=False, useHeatPort=False).enableAssert is False
    assert P.Spring(enableAssert=False).enableAssert is False     # a warning: no effect
    with pytest.raises(ParameterError, match=r"Damper: enableAssert=True is not available "
                                             r"yet .*run-time assertions"):
        P.Damper(enableAssert=True)


# =========================================================================================
# Joints driven through their 1-D flanges
# =========================================================================================
def test_revolute_flange_driven_by_torque_and_damped():
    L, m, I, d = 1.0, 1.0, 0.1, 0.8
    md = pendulum(L=L, m=m, I=I, use_flange=True)
    md.torque = Rot.Torque()
    md.sine = S.Sine(amplitude=3.0, f=0.7)
    md.damper = Rot.Damper(d=d)
    md.connect(md.sine.y, md.torque.tau)
    md.connect(md.torque.flange, md.rev.axis)
    md.connect(md.damper.flange_a, md.rev.axis)
    md.connect(md.damper.flange_b, md.rev.support)
    t = np.linspace(0, 3, 121)
    res = acausal.compile(md).simulate(3.0, t=t, x0={"rev.phi": -1.2}, **SIM)
    tau = lambda tt: 3.0 * math.sin(2 * math.pi * 0.7 * tt)           # noqa: E731
    phi, w = pendulum_ref(t, -1.2, 0.0, L=L, m=m, I=I, tau=tau, d=d)
    assert np.max(np.abs(res["rev.phi"] - phi)) < TOL
    assert np.max(np.abs(res["rev.w"] - w)) < TOL
    # the drive torque t = flange_a.tau: the source's torque minus the damper's
    assert np.max(np.abs(res["rev.t"] - (3.0 * np.sin(2 * np.pi * 0.7 * t) - d * w))) < TOL


def test_revolute_flange_unconnected_is_free():
    md = pendulum(use_flange=True)
    t = np.linspace(0, 1, 11)
    res = acausal.compile(md).simulate(1.0, t=t, x0={"rev.phi": 0.1}, **SIM)
    phi, _ = pendulum_ref(t, 0.1, 0.0)
    assert np.max(np.abs(res["rev.phi"] - phi)) < TOL


def test_prismatic_flange_driven_by_force():
    m, F = 2.0, 5.0
    md = Model("slide")
    md.world = P.World()
    md.fixed = P.Fixed()
    md.prism = P.Prismatic(r=(1.0, 0.0), useFlange=True)
    md.body = P.Body(m=m)
    md.force = Tr.Force()
    md.k = S.Constant(k=F)
    md.connect(md.fixed.frame, md.prism.frame_a)
    md.connect(md.prism.frame_b, md.body.frame_a)
    md.connect(md.k.y, md.force.f)
    md.connect(md.force.flange, md.prism.axis)
    t = np.linspace(0, 1, 11)
    res = acausal.compile(md).simulate(1.0, t=t, **SIM)
    assert np.max(np.abs(res["prism.s"] - 0.5 * F / m * t ** 2)) < TOL
    assert np.max(np.abs(res["prism.f"] - F)) < TOL


# =========================================================================================
# Errors
# =========================================================================================
def test_negative_mass_and_inertia_are_refused():
    with pytest.raises(ParameterError, match=r"Body\.m.*> 0"):
        P.Body(m=-1.0)
    with pytest.raises(ParameterError, match=r"Body\.I.*>= 0"):
        P.Body(I=-0.1)
    md = pendulum()
    with pytest.raises(ParameterError, match=r"body\.m"):
        md.body.m = 0.0


def test_frame_to_flange_connection_names_both_ports():
    md = pendulum()
    md.inertia = Rot.Inertia()
    with pytest.raises(PortConnectionError, match=r"body\.frame_a.*inertia\.flange_a"):
        md.connect(md.body.frame_a, md.inertia.flange_a)


def test_structural_mistakes_name_the_part():
    with pytest.raises(ParameterError, match="resolveInFrame"):
        P.WorldForce(resolveInFrame="frame_a")
    with pytest.raises(AttributeError, match="useFlange"):
        P.Revolute().axis                                       # noqa: B018
    with pytest.raises(AttributeError, match="frame_resolve"):
        P.CutForce().frame_resolve                              # noqa: B018
    md = pendulum()
    md.prism = P.Prismatic(r=(0.0, 0.0))
    md.body2 = P.Body()
    md.connect(md.body.frame_a, md.prism.frame_a)
    md.connect(md.prism.frame_b, md.body2.frame_a)
    with pytest.raises(ParameterError, match="prism"):
        acausal.compile(md)
    md = Model("noworld")
    md.body = P.Body()
    with pytest.raises(StructureError, match=r"body.*World"):
        acausal.compile(md)
    md = pendulum()
    md.wf = P.WorldForce()
    with pytest.raises(StructureError, match=r"wf\.frame_b"):
        acausal.compile(md)
