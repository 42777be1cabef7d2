"""The rotational library against references that do not come from acausal: closed forms,
hand-reduced models integrated with scipy's solve_ivp (DOP853, rtol 1e-11), energy balances.

Every comparison is relative to the size of the reference, at 1e-6 unless stated.
"""
import math

import casadi as ca
import numpy as np
import pytest
from scipy.integrate import simpson, solve_ivp

import acausal
from acausal.components import rotational as rot
from acausal.components import signals as sig
from acausal.components import translational as tr
from time_signals import TimeSignal

TOL = 1e-6


def close(actual, expected, tol=TOL, what=""):
    """max |actual − expected| ≤ tol · max(1, max |expected|)."""
    actual, expected = np.asarray(actual, float), np.asarray(expected, float)
    scale = max(1.0, float(np.max(np.abs(expected))))
    err = float(np.max(np.abs(actual - expected)))
    assert err <= tol * scale, f"{what}: max error {err:.3e} > {tol:.1e} * {scale:.3g}"


def hand(rhs, y0, t):
    """Integrate the hand-written ODE y' = rhs(t, y) onto the grid t."""
    sol = solve_ivp(rhs, (t[0], t[-1]), y0, t_eval=t, method="DOP853", rtol=1e-11,
                    atol=1e-12)
    assert sol.success, sol.message
    return sol.y


def connect_all(m, *pairs):
    for a, b in pairs:
        m.connect(a, b)


# =========================================================================================
# Gears and converters vs hand-reduced models
# =========================================================================================
J1, J2, RATIO, C2, D2 = 0.5, 4.0, 3.0, 20.0, 0.8


def torque_in(t):
    return 2.0 + np.sin(3.0 * t)


def test_ideal_gear_two_inertias_vs_reduced_one_inertia_model():
    """j1 --gear(ratio)--> j2 with spring and damper to ground, torque on j1. Reduced to the
    load side: (J2 + ratio²·J1)·φ2'' = ratio·τ − c·φ2 − d·φ2'; φ1 = ratio·φ2."""
    m = acausal.Model("gear")
    m.T, m.torque = acausal.Input(unit="N.m"), rot.Torque()
    m.j1, m.gear, m.j2 = rot.Inertia(J=J1), rot.IdealGear(ratio=RATIO), rot.Inertia(J=J2)
    m.spring, m.damper, m.ground = rot.Spring(c=C2), rot.Damper(d=D2), rot.Fixed()
    connect_all(m, (m.T.y, m.torque.tau), (m.torque.flange, m.j1.flange_a),
                (m.j1.flange_b, m.gear.flange_a), (m.gear.flange_b, m.j2.flange_a),
                (m.ground.flange, m.spring.flange_a), (m.spring.flange_b, m.j2.flange_b),
                (m.ground.flange, m.damper.flange_a), (m.damper.flange_b, m.j2.flange_b))
    t = np.linspace(0.0, 2.0, 201)
    res = acausal.compile(m).simulate(2.0, t=t, inputs={"T": torque_in},
                                      x0={"j2.phi": 0.1, "j2.w": -0.2})

    J_eff = J2 + RATIO ** 2 * J1

    def rhs(tk, y):
        return [y[1], (RATIO * torque_in(tk) - C2 * y[0] - D2 * y[1]) / J_eff]

    phi2, w2 = hand(rhs, [0.1, -0.2], t)
    a2 = (RATIO * torque_in(t) - C2 * phi2 - D2 * w2) / J_eff
    close(res["j2.phi"], phi2, what="j2.phi")
    close(res["j2.w"], w2, what="j2.w")
    close(res["j1.phi"], RATIO * phi2, what="j1.phi = ratio*j2.phi")
    close(res["j1.w"], RATIO * w2, what="j1.w")
    close(res["j1.a"], RATIO * a2, what="j1.a")
    # torques: the gear drives the load with J2·a2 + c·φ2 + d·w2 (flange_b.tau is minus that)
    tau_b = -(J2 * a2 + C2 * phi2 + D2 * w2)
    close(res["gear.flange_b.tau"], tau_b, what="gear.flange_b.tau")
    close(res["gear.flange_a.tau"], -tau_b / RATIO, what="0 = ratio*flange_a.tau + flange_b.tau")
    close(res["torque.flange.tau"], -torque_in(t), what="torque source: flange.tau = -tau")
    close(res["gear.phi_a"], res["j1.phi"], what="phi_a")
    close(res["spring.tau"], C2 * phi2, what="spring torque")


def test_ideal_gear_with_support_on_elastic_housing_vs_hand_model():
    """Gear housing = inertia Jh on a spring ch to ground: the reaction torque turns it.
    Hand Lagrangian in (φ1, φh): φ2 = φh + (φ1 − φh)/ratio."""
    Jh, ch, tau1 = 2.0, 30.0, 1.5
    m = acausal.Model("housing")
    m.T, m.torque = acausal.Input(), rot.Torque()
    m.j1, m.gear, m.j2 = rot.Inertia(J=J1), rot.IdealGear(ratio=RATIO, useSupport=True), \
        rot.Inertia(J=J2)
    m.housing, m.mount, m.ground = rot.Inertia(J=Jh), rot.Spring(c=ch), rot.Fixed()
    connect_all(m, (m.T.y, m.torque.tau), (m.torque.flange, m.j1.flange_a),
                (m.j1.flange_b, m.gear.flange_a), (m.gear.flange_b, m.j2.flange_a),
                (m.gear.support, m.housing.flange_a), (m.housing.flange_b, m.mount.flange_b),
                (m.mount.flange_a, m.ground.flange))
    t = np.linspace(0.0, 1.5, 151)
    res = acausal.compile(m).simulate(1.5, t=t, inputs={"T": tau1})

    al = 1.0 / RATIO
    M = np.array([[J1 + J2 * al ** 2, J2 * al * (1 - al)],
                  [J2 * al * (1 - al), Jh + J2 * (1 - al) ** 2]])

    def rhs(tk, y):
        acc = np.linalg.solve(M, [tau1, -ch * y[1]])
        return [y[2], y[3], acc[0], acc[1]]

    phi1, phih, w1, wh = hand(rhs, [0.0, 0.0, 0.0, 0.0], t)
    close(res["j1.phi"], phi1, what="j1.phi")
    close(res["housing.phi"], phih, what="housing.phi")
    close(res["j2.phi"], phih + (phi1 - phih) * al, what="j2.phi")
    close(res["gear.phi_b"], (phi1 - phih) * al, what="gear.phi_b (relative to support)")
    close(res["gear.support.tau"], -(res["gear.flange_a.tau"] + res["gear.flange_b.tau"]),
          what="support.tau = -(flange_a.tau + flange_b.tau)")
    close(res["mount.tau"], ch * phih, what="mount spring torque = c·phi_rel")


@pytest.mark.parametrize("kind, use_support", [("wheel", False), ("wheel", True),
                                               ("r2t", False), ("r2t", True)])
def test_rotational_to_translational_vs_reduced_model(kind, use_support):
    """Inertia J with torque τ(t) -> IdealRollingWheel(radius) / IdealGearR2T(ratio) -> Mass
    m (length L) -> translational spring to a wall. flangeT.s = sT0 + κ·φ, κ = radius or
    1/ratio. Reduced: (J + m κ²)·φ'' = τ + κ·c·(S0 − sT0 − κφ − L − s_rel0)."""
    J, mass, L, c, S0, s_rel0 = 0.2, 3.0, 0.2, 40.0, 2.0, 1.0
    kappa = 0.25 if kind == "wheel" else 1.0 / 8.0
    sT0 = 0.3 if use_support else 0.0
    m = acausal.Model(kind)
    m.T, m.torque, m.wheel = acausal.Input(), rot.Torque(), rot.Inertia(J=J)
    opts = dict(useSupportR=use_support, useSupportT=use_support)
    m.conv = (rot.IdealRollingWheel(radius=kappa, **opts) if kind == "wheel"
              else rot.IdealGearR2T(ratio=1.0 / kappa, **opts))
    m.mass, m.spring, m.wall = tr.Mass(m=mass, L=L), tr.Spring(c=c, s_rel0=s_rel0), \
        tr.Fixed(s0=S0)
    connect_all(m, (m.T.y, m.torque.tau), (m.torque.flange, m.wheel.flange_a),
                (m.wheel.flange_b, m.conv.flangeR), (m.conv.flangeT, m.mass.flange_a),
                (m.mass.flange_b, m.spring.flange_a), (m.spring.flange_b, m.wall.flange))
    if use_support:
        m.groundR, m.groundT = rot.Fixed(), tr.Fixed(s0=sT0)
        connect_all(m, (m.conv.supportR, m.groundR.flange), (m.conv.supportT, m.groundT.flange))
    t = np.linspace(0.0, 1.0, 101)
    res = acausal.compile(m).simulate(1.0, t=t, inputs={"T": torque_in},
                                      x0={"wheel.phi": 0.5, "wheel.w": 1.0})
    Jeff = J + mass * kappa ** 2

    def spring_force(phi):            # force of the stretched spring pulling the mass forward
        return c * (S0 - (sT0 + kappa * phi + L) - s_rel0)

    def rhs(tk, y):
        return [y[1], (torque_in(tk) + kappa * spring_force(y[0])) / Jeff]

    phi, w = hand(rhs, [0.5, 1.0], t)
    a = (torque_in(t) + kappa * spring_force(phi)) / Jeff
    close(res["wheel.phi"], phi, what="wheel.phi")
    close(res["mass.s"], sT0 + kappa * phi + L / 2, what="mass.s")
    close(res["mass.v"], kappa * w, what="mass.v")
    F = mass * kappa * a - spring_force(phi)          # force of the converter on the mass
    close(res["conv.flangeT.f"], -F, what="flangeT.f")
    close(res["conv.flangeR.tau"], kappa * F, what="flangeR.tau")
    if use_support:
        close(res["conv.supportR.tau"], -res["conv.flangeR.tau"], what="supportR.tau")
        close(res["conv.supportT.f"], -res["conv.flangeT.f"], what="supportT.f")


def test_ideal_planetary_willis_and_torque_balance_vs_hand_model():
    """Sun inertia driven by τ_s, ring inertia with a damper to ground, carrier inertia with
    a ConstantTorque. Hand model in (φs, φr): φc = (φs + r·φr)/(1 + r)."""
    r, Js, Jr, Jc, dr, tau_c = 2.5, 0.1, 0.8, 0.4, 0.3, -0.5
    m = acausal.Model("planetary")
    m.T, m.torque = acausal.Input(), rot.Torque()
    m.sun, m.ring, m.carrier = rot.Inertia(J=Js), rot.Inertia(J=Jr), rot.Inertia(J=Jc)
    m.gear, m.damper, m.ground = rot.IdealPlanetary(ratio=r), rot.Damper(d=dr), rot.Fixed()
    m.load = rot.ConstantTorque(tau_constant=tau_c)
    connect_all(m, (m.T.y, m.torque.tau), (m.torque.flange, m.sun.flange_a),
                (m.sun.flange_b, m.gear.sun), (m.gear.ring, m.ring.flange_a),
                (m.ring.flange_b, m.damper.flange_b), (m.damper.flange_a, m.ground.flange),
                (m.gear.carrier, m.carrier.flange_a), (m.load.flange, m.carrier.flange_b))
    t = np.linspace(0.0, 2.0, 101)
    res = acausal.compile(m).simulate(2.0, t=t, inputs={"T": torque_in})
    b = 1.0 / (1.0 + r)
    M = np.array([[Js + Jc * b * b, Jc * b * b * r], [Jc * b * b * r, Jr + Jc * b * b * r * r]])

    def acc(tk, wr):
        return np.linalg.solve(M, [torque_in(tk) + b * tau_c, -dr * wr + r * b * tau_c])

    def rhs(tk, y):
        return [y[2], y[3], *acc(tk, y[3])]

    phis, phir, ws, wr = hand(rhs, [0.0, 0.0, 0.0, 0.0], t)
    close(res["sun.phi"], phis, what="sun.phi")
    close(res["ring.phi"], phir, what="ring.phi")
    close(res["carrier.phi"], b * (phis + r * phir), what="carrier.phi")
    # Willis equation on speeds, from the simulated speeds
    close((1 + r) * res["carrier.w"], res["sun.w"] + r * res["ring.w"], tol=1e-9,
          what="Willis: (1+r)·w_carrier = w_sun + r·w_ring")
    a_s = np.array([acc(tk, wk)[0] for tk, wk in zip(t, wr)])
    sun_tau = torque_in(t) - Js * a_s               # what the sun inertia passes to the gear
    close(res["gear.sun.tau"], sun_tau, what="sun.tau")
    close(res["gear.ring.tau"], r * sun_tau, what="ring.tau = ratio·sun.tau")
    close(res["gear.carrier.tau"], -(1 + r) * sun_tau, what="carrier.tau = -(1+ratio)·sun.tau")
    power = sum(res[f"gear.{f}.tau"] * res[f"{f}.w"] for f in ("sun", "ring", "carrier"))
    close(power, 0 * power, tol=1e-9, what="ideal gear: no power lost")


# =========================================================================================
# DC motor vs its two-state ODE
# =========================================================================================
V_STEP, JL, DL = 24.0, 0.35, 0.05


def dc_motor_model(use_support=False):
    m = acausal.Model("dc")
    m.v = acausal.Input(unit="V")
    m.motor, m.load = rot.DCMotor(useSupport=use_support), rot.Inertia(J=JL)
    m.friction, m.ground = rot.Damper(d=DL), rot.Fixed()
    connect_all(m, (m.v.y, m.motor.v), (m.motor.flange, m.load.flange_a),
                (m.load.flange_b, m.friction.flange_b), (m.friction.flange_a, m.ground.flange))
    return m


def test_dc_motor_voltage_step_vs_hand_ode():
    """L·i' = v − R·i − k·w,  (J + JL)·w' = k·i − d·w, with MSL's DC_PermanentMagnet data."""
    R, L, k, J = 0.05, 0.0015, 2.0 / math.pi, 0.15
    t = np.linspace(0.0, 0.3, 301)
    res = acausal.compile(dc_motor_model()).simulate(0.3, t=t, inputs={"v": V_STEP})

    def rhs(tk, y):
        i, w, _ = y
        return [(V_STEP - R * i - k * w) / L, (k * i - DL * w) / (J + JL), w]

    i, w, phi = hand(rhs, [0.0, 0.0, 0.0], t)
    close(res["motor.i"], i, what="motor.i")
    close(res["motor.w"], w, what="motor.w")
    close(res["load.phi"], phi, what="load.phi")
    close(res["motor.tau_el"], k * i, what="tau_el = k·i")
    # steady state (closed form) is approached: w_ss = k·V/(k² + R·d)
    w_ss = k * V_STEP / (k * k + R * DL)
    res_long = acausal.compile(dc_motor_model()).simulate(3.0, inputs={"v": V_STEP})
    close(res_long.final("motor.w"), w_ss, what="steady-state speed")
    close(res_long.final("motor.i"), DL * w_ss / k, what="steady-state current")


def test_dc_motor_energy_balance():
    """∫v·i dt = ½L·i² + ½(J+JL)·w² + ∫R·i² dt + ∫d·w² dt (Simpson quadrature)."""
    R, L, J = 0.05, 0.0015, 0.15
    t = np.linspace(0.0, 0.2, 4001)
    res = acausal.compile(dc_motor_model()).simulate(0.2, t=t, inputs={"v": V_STEP})
    i, w = res["motor.i"], res["motor.w"]
    supplied = simpson(V_STEP * i, x=t)
    stored = 0.5 * L * i[-1] ** 2 + 0.5 * (J + JL) * w[-1] ** 2
    lost = simpson(R * i ** 2, x=t) + simpson(DL * w ** 2, x=t)
    close(stored + lost, supplied, what="energy balance [J]")
    close(res["friction.lossPower"], DL * w ** 2, what="damper lossPower")


def test_dc_motor_with_support_on_elastic_housing_vs_hand_ode():
    """Housing inertia Jh on a spring-damper to ground takes the reaction −k·i; the back-emf
    uses the speed relative to the housing."""
    R, L, k, J = 0.05, 0.0015, 2.0 / math.pi, 0.15
    Jh, ch, dh = 1.0, 500.0, 2.0
    m = dc_motor_model(use_support=True)
    m.housing, m.mount, m.base = rot.Inertia(J=Jh), rot.SpringDamper(c=ch, d=dh), rot.Fixed()
    connect_all(m, (m.motor.support, m.housing.flange_a), (m.housing.flange_b, m.mount.flange_b),
                (m.mount.flange_a, m.base.flange))
    t = np.linspace(0.0, 0.3, 151)
    res = acausal.compile(m).simulate(0.3, t=t, inputs={"v": V_STEP})

    def rhs(tk, y):
        i, phir, wr, phih, wh = y
        return [(V_STEP - R * i - k * (wr - wh)) / L, wr, (k * i - DL * wr) / (J + JL),
                wh, (-k * i - ch * phih - dh * wh) / Jh]

    i, phir, wr, phih, wh = hand(rhs, [0.0] * 5, t)
    close(res["motor.i"], i, what="motor.i")
    close(res["motor.phi"], phir, what="rotor angle")
    close(res["housing.phi"], phih, what="housing angle")
    close(res["motor.support.tau"], k * i, what="support.tau = k·i (reaction)")
    close(res["motor.vi"], k * (wr - wh), what="back-emf on relative speed")


# =========================================================================================
# Sensors
# =========================================================================================
def test_torque_power_multi_sensor_vs_hand_computed_torque():
    """τ(t) on j1 -> TorqueSensor -> MultiSensor -> PowerSensor -> j2, spring to ground.
    (J1+J2)·φ'' = τ − c·φ; the shaft carries J2·φ'' + c·φ."""
    c = 15.0
    m = acausal.Model("sensors")
    m.T, m.torque, m.j1, m.j2 = acausal.Input(), rot.Torque(), rot.Inertia(J=J1), \
        rot.Inertia(J=J2)
    m.ts, m.ms, m.ps = rot.TorqueSensor(), rot.MultiSensor(), rot.PowerSensor()
    m.spring, m.ground = rot.Spring(c=c), rot.Fixed()
    connect_all(m, (m.T.y, m.torque.tau), (m.torque.flange, m.j1.flange_a),
                (m.j1.flange_b, m.ts.flange_a), (m.ts.flange_b, m.ms.flange_a),
                (m.ms.flange_b, m.ps.flange_a), (m.ps.flange_b, m.j2.flange_a),
                (m.j2.flange_b, m.spring.flange_b), (m.spring.flange_a, m.ground.flange))
    t = np.linspace(0.0, 2.0, 201)
    res = acausal.compile(m).simulate(2.0, t=t, inputs={"T": torque_in},
                                      x0={"j2.phi": -0.2})

    def rhs(tk, y):
        return [y[1], (torque_in(tk) - c * y[0]) / (J1 + J2)]

    phi, w = hand(rhs, [-0.2, 0.0], t)
    shaft = J2 * (torque_in(t) - c * phi) / (J1 + J2) + c * phi
    close(res["ts.tau"], shaft, what="TorqueSensor.tau")
    close(res["ms.tau"], shaft, what="MultiSensor.tau")
    close(res["ms.w"], w, what="MultiSensor.w")
    close(res["ms.power"], shaft * w, what="MultiSensor.power")
    close(res["ps.power"], shaft * w, what="PowerSensor.power")


def test_torsional_oscillator_closed_form_and_absolute_relative_sensors():
    """Fixed(phi0) - Spring(c, phi_rel0) - Inertia J: φ(t) = φe + (φ0 − φe)cos ωt + (w0/ω) sin ωt
    with φe = phi0 + phi_rel0, ω = √(c/J); every sensor against the closed form."""
    J, c, phi0, phi_rel0, x0, w0 = 0.3, 12.0, 0.2, 0.1, 0.7, -1.0
    m = acausal.Model("osc")
    m.ground, m.spring, m.j = rot.Fixed(phi0=phi0), rot.Spring(c=c, phi_rel0=phi_rel0), \
        rot.Inertia(J=J)
    m.angle, m.speed, m.acc = rot.AngleSensor(), rot.SpeedSensor(), rot.AccSensor()
    m.rel_angle, m.rel_speed, m.rel_acc = rot.RelAngleSensor(), rot.RelSpeedSensor(), \
        rot.RelAccSensor()
    connect_all(m, (m.ground.flange, m.spring.flange_a), (m.spring.flange_b, m.j.flange_a),
                (m.j.flange_b, m.angle.flange), (m.j.flange_b, m.speed.flange),
                (m.j.flange_b, m.acc.flange))
    for s in (m.rel_angle, m.rel_speed, m.rel_acc):
        connect_all(m, (m.ground.flange, s.flange_a), (m.j.flange_a, s.flange_b))
    t = np.linspace(0.0, 3.0, 301)
    res = acausal.compile(m).simulate(3.0, t=t, x0={"j.phi": x0, "j.w": w0})
    om, pe = math.sqrt(c / J), phi0 + phi_rel0
    phi = pe + (x0 - pe) * np.cos(om * t) + w0 / om * np.sin(om * t)
    w = -(x0 - pe) * om * np.sin(om * t) + w0 * np.cos(om * t)
    a = -om ** 2 * (phi - pe)
    close(res["j.phi"], phi, what="j.phi")
    close(res["angle.phi"], phi, what="AngleSensor")
    close(res["speed.w"], w, what="SpeedSensor")
    close(res["acc.a"], a, what="AccSensor")
    close(res["rel_angle.phi_rel"], phi - phi0, what="RelAngleSensor")
    close(res["rel_speed.w_rel"], w, what="RelSpeedSensor")
    close(res["rel_acc.a_rel"], a, what="RelAccSensor")
    close(res["spring.tau"], c * (phi - pe), what="spring torque")


def test_spring_damper_free_decay_closed_form():
    """Fixed - SpringDamper(c, d) - Inertia: φ = e^{−ζωt}(φ0 cos ωd t + (w0 + ζωφ0)/ωd sin ωd t)."""
    J, c, d, p0, w0 = 0.5, 50.0, 0.8, 0.3, 0.0
    m = acausal.Model("decay")
    m.ground, m.sd, m.j = rot.Fixed(), rot.SpringDamper(c=c, d=d), rot.Inertia(J=J)
    connect_all(m, (m.ground.flange, m.sd.flange_a), (m.sd.flange_b, m.j.flange_a))
    t = np.linspace(0.0, 2.0, 201)
    res = acausal.compile(m).simulate(2.0, t=t, x0={"j.phi": p0, "j.w": w0})
    om = math.sqrt(c / J)
    z = d / (2 * math.sqrt(c * J))
    wd = om * math.sqrt(1 - z * z)
    phi = np.exp(-z * om * t) * (p0 * np.cos(wd * t) + (w0 + z * om * p0) / wd * np.sin(wd * t))
    close(res["j.phi"], phi, what="j.phi")
    close(res["sd.lossPower"], d * res["j.w"] ** 2, what="lossPower = d·w_rel²")


# =========================================================================================
# Energy conservation of an undamped drivetrain
# =========================================================================================
def test_undamped_drivetrain_conserves_energy():
    """j1 -gear- spring1 - j2 - disc - planetary sun; ring on spring2 to ground; carrier j3.
    T + V computed here from the simulated speeds and spring angles stays constant."""
    Ja, Jb, Jc, c1, c2, ratio, pr = 0.2, 1.5, 0.7, 50.0, 30.0, 4.0, 2.0
    m = acausal.Model("drivetrain")
    m.j1, m.gear, m.s1, m.j2 = rot.Inertia(J=Ja), rot.IdealGear(ratio=ratio), \
        rot.Spring(c=c1), rot.Inertia(J=Jb)
    m.disc, m.pg, m.s2, m.ground, m.j3 = rot.Disc(deltaPhi=0.3), rot.IdealPlanetary(ratio=pr), \
        rot.Spring(c=c2, phi_rel0=0.05), rot.Fixed(), rot.Inertia(J=Jc)
    connect_all(m, (m.j1.flange_b, m.gear.flange_a), (m.gear.flange_b, m.s1.flange_a),
                (m.s1.flange_b, m.j2.flange_a), (m.j2.flange_b, m.disc.flange_a),
                (m.disc.flange_b, m.pg.sun), (m.pg.ring, m.s2.flange_b),
                (m.s2.flange_a, m.ground.flange), (m.pg.carrier, m.j3.flange_a))
    t = np.linspace(0.0, 3.0, 301)
    res = acausal.compile(m).simulate(3.0, t=t, x0={"j1.w": 5.0, "j2.phi": 0.1, "j3.w": -1.0},
                                      rtol=1e-11, atol=1e-12)
    close(res["disc.flange_b.phi"] - res["disc.flange_a.phi"], 0.3 + 0 * t, tol=1e-12,
          what="disc deltaPhi")
    energy = (0.5 * Ja * res["j1.w"] ** 2 + 0.5 * Jb * res["j2.w"] ** 2
              + 0.5 * Jc * res["j3.w"] ** 2 + 0.5 * c1 * res["s1.phi_rel"] ** 2
              + 0.5 * c2 * (res["s2.phi_rel"] - 0.05) ** 2)
    assert np.ptp(res["s1.phi_rel"]) > 0.1, "the test must exercise the springs"
    close(energy, np.full_like(t, energy[0]), tol=1e-7, what="T + V")


@pytest.mark.parametrize("beta", [0.0, 0.004], ids=["Spring", "SpringDamper"])
def test_torsional_chain_vs_modal_solution(beta):
    """Ground - spring - J1 - spring - J2 ... - J10 (ten of each, so the compiler's batched
    physics path is used), with stiffness-proportional damping d = β·c (SpringDamper) or none
    (Spring): x(t) from the eigen-decomposition of K φ = ω² M φ (scipy), each mode a damped
    oscillator with ζω = β·ω²/2."""
    from scipy.linalg import eigh
    n = 10
    Js = np.linspace(0.5, 1.4, n)
    cs = np.linspace(80.0, 35.0, n)
    m = acausal.Model("chain")
    m.ground = rot.Fixed()
    left = m.ground.flange
    for i in range(n):
        spring = rot.SpringDamper(c=cs[i], d=beta * cs[i]) if beta else rot.Spring(c=cs[i])
        body = rot.Inertia(J=Js[i])
        setattr(m, f"s{i}", spring)
        setattr(m, f"j{i}", body)
        connect_all(m, (left, spring.flange_a), (spring.flange_b, body.flange_a))
        left = body.flange_b
    x0 = 0.1 * np.sin(np.arange(1, n + 1))
    t = np.linspace(0.0, 2.0, 101)
    res = acausal.compile(m).simulate(2.0, t=t, x0={f"j{i}.phi": x0[i] for i in range(n)},
                                      rtol=1e-10, atol=1e-12)
    K = np.zeros((n, n))
    for i in range(n):              # spring i joins body i-1 (ground for i = 0) and body i
        K[i, i] += cs[i]
        if i:
            K[i - 1, i - 1] += cs[i]
            K[i, i - 1] -= cs[i]
            K[i - 1, i] -= cs[i]
    om2, V = eigh(K, np.diag(Js))        # V is M-orthonormal
    a0 = (V.T @ np.diag(Js) @ x0)[:, None]
    om = np.sqrt(om2)[:, None]
    zo = beta * om ** 2 / 2                          # ζ·ω of each mode
    wd = np.sqrt(om ** 2 - zo ** 2)
    x = V @ (a0 * np.exp(-zo * t) * (np.cos(wd * t) + zo / wd * np.sin(wd * t)))
    for i in range(n):
        close(res[f"j{i}.phi"], x[i], what=f"j{i}.phi")
        if not beta:
            close(res[f"s{i}.tau"], cs[i] * (x[i] - (x[i - 1] if i else 0.0)),
                  what=f"s{i}.tau")
    if beta:                                         # all dissipated power is in the dampers
        loss = sum(res[f"s{i}.lossPower"] for i in range(n))
        rel_w = [res[f"j{i}.w"] - (res[f"j{i - 1}.w"] if i else 0.0) for i in range(n)]
        close(loss, sum(beta * cs[i] * rel_w[i] ** 2 for i in range(n)), what="lossPower")


# =========================================================================================
# Prescribed motion
# =========================================================================================
A_REF, OM_REF = 0.4, 3.0

def base_excited(source, ref_port_of, ref_signal):
    """source -> j1 (driven) -> spring c -> j2 (free)."""
    m = acausal.Model("prescribed")
    m.ref, m.src = ref_signal, source
    m.j1, m.spring, m.j2 = rot.Inertia(J=J1), rot.Spring(c=C2), rot.Inertia(J=J2)
    connect_all(m, (m.ref.y, ref_port_of(m.src)), (m.src.flange, m.j1.flange_a),
                (m.j1.flange_b, m.spring.flange_a), (m.spring.flange_b, m.j2.flange_a))
    return m


def test_position_exact_vs_hand_model():
    """phi_ref = A sin(Ωt) exactly: J2·φ2'' = c·(φref − φ2); the source delivers
    J1·φref'' + c·(φref − φ2)."""
    m = base_excited(rot.Position(exact=True), lambda s: s.phi_ref,
                     TimeSignal(lambda t: A_REF * ca.sin(OM_REF * t)))
    t = np.linspace(0.0, 2.0, 201)
    res = acausal.compile(m).simulate(2.0, t=t)
    ref = A_REF * np.sin(OM_REF * t)
    phi2, w2 = hand(lambda tk, y: [y[1], C2 * (A_REF * np.sin(OM_REF * tk) - y[0]) / J2],
                    [0.0, 0.0], t)
    close(res["j1.phi"], ref, what="j1.phi = phi_ref")
    close(res["j1.w"], A_REF * OM_REF * np.cos(OM_REF * t), what="j1.w = der(phi_ref)")
    close(res["j1.a"], -OM_REF ** 2 * ref, what="j1.a")
    close(res["j2.phi"], phi2, what="j2.phi")
    delivered = J1 * (-OM_REF ** 2 * ref) + C2 * (ref - phi2)
    close(res["src.flange.tau"], -delivered, what="source torque")


def test_position_filtered_vs_hand_model():
    """MSL's Bessel filter with a model input (step 1 rad): states φf, wf;
    wf' = ((φref − φf)·wc − af·wf)·wc/bf."""
    f_crit = 4.0
    m = base_excited(rot.Position(f_crit=f_crit), lambda s: s.phi_ref, acausal.Input())
    t = np.linspace(0.0, 1.5, 151)
    res = acausal.compile(m).simulate(1.5, t=t, inputs={"ref": 1.0})
    wc, af, bf = 2 * math.pi * f_crit, 1.3617, 0.6180

    def rhs(tk, y):
        pf, wf, p2, w2 = y
        return [wf, ((1.0 - pf) * wc - af * wf) * wc / bf, w2, C2 * (pf - p2) / J2]

    pf, wf, p2, w2 = hand(rhs, [0.0] * 4, t)
    close(res["j1.phi"], pf, what="filtered angle")
    close(res["src.w"], wf, what="filtered speed")
    close(res["j2.phi"], p2, what="j2.phi")


def test_speed_filtered_vs_hand_model():
    """Speed(exact=False): w' = (w_ref − w)·2π f_crit, w_ref a model input."""
    f_crit = 3.0
    m = base_excited(rot.Speed(f_crit=f_crit), lambda s: s.w_ref, acausal.Input())
    t = np.linspace(0.0, 1.5, 151)
    res = acausal.compile(m).simulate(1.5, t=t, inputs={"ref": 2.0})
    wc = 2 * math.pi * f_crit

    def rhs(tk, y):
        p, w, p2, w2 = y
        return [w, (2.0 - w) * wc, w2, C2 * (p - p2) / J2]

    p, w, p2, w2 = hand(rhs, [0.0] * 4, t)
    close(res["j1.phi"], p, what="Speed filtered: angle")
    close(res["j1.w"], w, what="Speed filtered: speed")
    close(res["j2.phi"], p2, what="j2.phi")


def test_speed_exact_closed_form():
    """Speed(exact=True), w_ref = A sin(Ωt): φ = A(1 − cos Ωt)/Ω, a = AΩ cos Ωt."""
    m = base_excited(rot.Speed(exact=True), lambda s: s.w_ref,
                     TimeSignal(lambda tt: A_REF * ca.sin(OM_REF * tt)))
    t = np.linspace(0.0, 1.5, 151)
    res = acausal.compile(m).simulate(1.5, t=t)
    close(res["j1.phi"], A_REF * (1 - np.cos(OM_REF * t)) / OM_REF, what="Speed exact: angle")
    close(res["j1.a"], A_REF * OM_REF * np.cos(OM_REF * t), what="Speed exact: acceleration")


def test_accelerate_and_constant_speed_closed_forms():
    """Accelerate(useSupport) on a support at phi0: φ = phi0 + a t²/2; ConstantSpeed against
    a damper needs τ = d·w_fixed."""
    t = np.linspace(0.0, 1.0, 101)
    # Accelerate with support
    m = base_excited(rot.Accelerate(useSupport=True), lambda s: s.a_ref, acausal.Input())
    m.housing = rot.Fixed(phi0=0.5)
    m.connect(m.src.support, m.housing.flange)
    res = acausal.compile(m).simulate(1.0, t=t, inputs={"ref": 3.0})
    close(res["j1.phi"], 0.5 + 1.5 * t ** 2, what="Accelerate: angle")
    close(res["src.w"], 3.0 * t, what="Accelerate: relative speed")
    close(res["src.support.tau"], -res["src.flange.tau"], what="support reaction")
    # ConstantSpeed
    d = 0.7
    m = acausal.Model("cs")
    m.cs, m.j, m.damper, m.ground = rot.ConstantSpeed(w_fixed=3.0), rot.Inertia(J=2.0), \
        rot.Damper(d=d), rot.Fixed()
    connect_all(m, (m.cs.flange, m.j.flange_a), (m.j.flange_b, m.damper.flange_b),
                (m.damper.flange_a, m.ground.flange))
    res = acausal.compile(m).simulate(1.0, t=t)
    close(res["j.phi"], 3.0 * t, what="ConstantSpeed: angle")
    close(res["cs.tau"], d * 3.0 + 0 * t, what="ConstantSpeed: torque against the damper")


def test_move_follows_u1_with_rates_u2_u3():
    """Move with u = (A sin Ωt, AΩ cos Ωt, −AΩ² sin Ωt)."""
    t = np.linspace(0.0, 1.0, 101)
    m = acausal.Model("move")
    m.u1 = TimeSignal(lambda tt: A_REF * ca.sin(OM_REF * tt))
    m.u2 = TimeSignal(lambda tt: A_REF * OM_REF * ca.cos(OM_REF * tt))
    m.u3 = TimeSignal(lambda tt: -A_REF * OM_REF ** 2 * ca.sin(OM_REF * tt))
    m.move, m.j1, m.spring, m.j2 = rot.Move(), rot.Inertia(J=J1), rot.Spring(c=C2), \
        rot.Inertia(J=J2)
    connect_all(m, (m.u1.y, m.move.u[1]), (m.u2.y, m.move.u[2]), (m.u3.y, m.move.u[3]),
                (m.move.flange, m.j1.flange_a), (m.j1.flange_b, m.spring.flange_a),
                (m.spring.flange_b, m.j2.flange_a))
    res = acausal.compile(m).simulate(1.0, t=t)
    close(res["j1.phi"], A_REF * np.sin(OM_REF * t), what="Move: angle")
    close(res["j1.w"], res["move.w_u"], what="Move: speed = u[2]")
    close(res["j1.a"], res["move.a_u"], what="Move: acceleration = u[3]")
    phi2, _ = hand(lambda tk, y: [y[1], C2 * (A_REF * np.sin(OM_REF * tk) - y[0]) / J2],
                   [0.0, 0.0], t)
    close(res["j2.phi"], phi2, what="j2.phi")


def test_angle_and_torque_adaptors_follow_msl():
    """AngleToTorqueAdaptor(use_w=False) keeps its input w (MSL: w exists if use_w or
    use_a) and moves an inertia by model inputs: tau = J·a, the input acceleration (here
    inconsistent with phi on purpose: it is taken as given). TorqueToAngleAdaptor on an
    inertia: flange.tau = tau loads it (J·der(w) = −tau), outputs phi, w and, without
    use_w, a = 0 (MSL's der(0))."""
    J = 0.7
    m = acausal.Model("adaptors")
    m.phi, m.w, m.a, m.load = acausal.Input(), acausal.Input(), acausal.Input(), acausal.Input()
    m.moved, m.j1 = rot.AngleToTorqueAdaptor(use_w=False), rot.Inertia(J=J)
    m.driven, m.j2 = rot.TorqueToAngleAdaptor(use_w=False), rot.Inertia(J=J)
    connect_all(m, (m.phi.y, m.moved.phi), (m.w.y, m.moved.w), (m.a.y, m.moved.a),
                (m.moved.flange, m.j1.flange_a), (m.load.y, m.driven.tau),
                (m.driven.flange, m.j2.flange_b))
    assert sorted(m.moved.ports) == ["a", "flange", "phi", "tau", "w"]
    assert sorted(m.driven.ports) == ["a", "flange", "phi", "tau"]
    t = np.linspace(0.0, 1.0, 101)
    res = acausal.compile(m).simulate(1.0, t=t, inputs={
        "phi": np.sin, "w": np.cos, "a": lambda x: 0 * x + 2.0, "load": lambda x: 0 * x + 1.4})
    close(res["moved.tau"], J * 2.0, what="tau = J·a as given")
    close(res["j1.phi"], np.sin(t), what="angle as given")
    close(res["j1.w"], np.cos(t), what="speed as given")
    close(res["driven.phi"], -t ** 2, what="J·der(w) = −tau: phi = −(1.4/0.7)·t²/2")
    close(res["driven.a"], 0.0, what="a without use_w")


@pytest.mark.parametrize("use_pder, use_pder2", [(True, True), (True, False), (False, True)])
def test_general_angle_to_torque_adaptor_moves_an_inertia_against_a_spring(use_pder, use_pder2):
    """GeneralAngleToTorqueAdaptor moves an inertia J, tied to the ground by a spring c, by
    the angle p = A·sin(ωt) from model inputs (with its rates pder, pder2 where they exist):
    f = −flange.tau = J·phi'' + c·phi, the torque needed to move it so. A model input has
    no rates to derive: without pder2 only the spring is attached, f = c·phi. The option
    pder2 exists only with pder (use_pder=False, use_pder2=True: no pder2), as in MSL."""
    J, c, A, om = 0.7, 5.0, 0.3, 2.0
    m = acausal.Model("general_angle")
    m.p, m.w, m.a = acausal.Input(), acausal.Input(), acausal.Input()
    m.moved = rot.GeneralAngleToTorqueAdaptor(use_pder=use_pder, use_pder2=use_pder2)
    m.spring, m.fixed = rot.Spring(c=c), rot.Fixed()
    pairs = [(m.p.y, m.moved.p), (m.spring.flange_b, m.fixed.flange)]
    has_pder2 = use_pder and use_pder2
    if has_pder2:
        m.j = rot.Inertia(J=J)
        pairs += [(m.moved.flange, m.j.flange_b), (m.j.flange_a, m.spring.flange_a),
                  (m.w.y, m.moved.pder), (m.a.y, m.moved.pder2)]
    else:
        pairs += [(m.moved.flange, m.spring.flange_a)]
        if use_pder:
            pairs += [(m.w.y, m.moved.pder)]
    connect_all(m, *pairs)
    expected_ports = {"flange", "p", "f"} | ({"pder"} if use_pder else set()) \
        | ({"pder2"} if has_pder2 else set())
    assert set(m.moved.ports) == expected_ports
    t = np.linspace(0.0, 3.0, 61)
    res = acausal.compile(m).simulate(3.0, t=t, rtol=1e-10, atol=1e-12, inputs={
        "p": lambda x: A * np.sin(om * x), "w": lambda x: A * om * np.cos(om * x),
        "a": lambda x: -A * om ** 2 * np.sin(om * x)})
    phi = A * np.sin(om * t)
    close(res["spring.phi_rel"], -phi, what="the spring turned by phi (flange_b fixed)")
    close(res["moved.f"], (-J * A * om ** 2 * np.sin(om * t) if has_pder2 else 0.0) + c * phi,
          what="f = J·phi'' + c·phi")


def test_general_angle_to_torque_adaptor_derives_the_rates_of_a_signal_source():
    """Without pder the flange's rates are those of the angle signal: a Sine p = A·sin(ωt)
    moving an inertia J needs f = J·phi'' = −J·A·ω²·sin(ωt)."""
    J, A, f = 0.7, 0.3, 0.5
    om = 2 * np.pi * f
    m = acausal.Model("general_angle_source")
    m.sine = sig.Sine(amplitude=A, f=f)
    m.moved, m.j = rot.GeneralAngleToTorqueAdaptor(use_pder=False), rot.Inertia(J=J)
    connect_all(m, (m.sine.y, m.moved.p), (m.moved.flange, m.j.flange_a))
    t = np.linspace(0.0, 2.0, 41)
    res = acausal.compile(m).simulate(2.0, t=t, rtol=1e-10, atol=1e-12)
    close(res["j.phi"], A * np.sin(om * t), what="angle as given")
    close(res["moved.f"], -J * A * om ** 2 * np.sin(om * t), what="f = J·phi''")


@pytest.mark.parametrize("use_pder, use_pder2", [(True, True), (False, True)])
def test_general_torque_to_angle_adaptor_on_an_inertia(use_pder, use_pder2):
    """GeneralTorqueToAngleAdaptor on an inertia J at rest: flange.tau = f loads it, J·phi''
    = −f (MSL's u = flange.tau); outputs p = phi = −f·t²/(2J), pder = −f·t/J, pder2 = −f/J.
    Without use_pder there is no pder2 either (MSL's pder2 if use_pder and use_pder2)."""
    J, load = 0.7, 1.4
    m = acausal.Model("general_torque")
    m.load = acausal.Input()
    m.driven = rot.GeneralTorqueToAngleAdaptor(use_pder=use_pder, use_pder2=use_pder2)
    m.j = rot.Inertia(J=J)
    connect_all(m, (m.load.y, m.driven.f), (m.driven.flange, m.j.flange_b))
    assert set(m.driven.ports) == {"flange", "p", "f"} | (
        {"pder", "pder2"} if use_pder else set())
    t = np.linspace(0.0, 1.0, 101)
    res = acausal.compile(m).simulate(1.0, t=t, inputs={"load": lambda x: 0 * x + load})
    close(res["driven.p"], -load * t ** 2 / (2 * J), what="p = phi")
    close(res["j.phi"], res["driven.p"], what="p = flange.phi")
    if use_pder:
        close(res["driven.pder"], -load * t / J, what="pder = w")
        close(res["driven.pder2"], -load / J, what="pder2 = a")


def test_general_adaptors_back_to_back_are_one_inertia():
    """MSL's use of the pair (GenerationOfFMUs): an inertia J1 driven by tau(t) = sin(t)
    through a GeneralTorqueToAngleAdaptor whose p, pder, pder2 move a second inertia J2
    through a GeneralAngleToTorqueAdaptor, whose torque f is fed back: as one inertia
    J1 + J2, phi = (t − sin t)/(J1 + J2), and f = J2·phi''."""
    J1, J2 = 1.1, 2.2
    m = acausal.Model("back_to_back")
    m.tau, m.torque = acausal.Input(), rot.Torque()
    m.j1, m.j2 = rot.Inertia(J=J1), rot.Inertia(J=J2)
    m.toAngle, m.toTorque = rot.GeneralTorqueToAngleAdaptor(), rot.GeneralAngleToTorqueAdaptor()
    connect_all(m, (m.tau.y, m.torque.tau), (m.torque.flange, m.j1.flange_a),
                (m.j1.flange_b, m.toAngle.flange), (m.toAngle.p, m.toTorque.p),
                (m.toAngle.pder, m.toTorque.pder), (m.toAngle.pder2, m.toTorque.pder2),
                (m.toTorque.flange, m.j2.flange_a), (m.toTorque.f, m.toAngle.f))
    t = np.linspace(0.0, 2.0, 41)
    res = acausal.compile(m).simulate(2.0, t=t, rtol=1e-10, atol=1e-12,
                                      inputs={"tau": np.sin})
    Jt = J1 + J2
    close(res["j1.phi"], (t - np.sin(t)) / Jt, what="phi of J1")
    close(res["j2.phi"], (t - np.sin(t)) / Jt, what="phi of J2")
    close(res["toTorque.f"], J2 * np.sin(t) / Jt, what="f = J2·phi''")


# =========================================================================================
# Torque sources: closed forms on a single inertia
# =========================================================================================
JS = 2.0


@pytest.mark.parametrize("source, w0, expected", [
    (lambda: rot.ConstantTorque(tau_constant=3.0), 0.5,
     lambda t: 0.5 + 3.0 * t / JS),
    (lambda: rot.TorqueStep(stepTorque=4.0, offsetTorque=-1.0, startTime=0.4), 0.0,
     lambda t: -t / JS + 4.0 * np.maximum(t - 0.4, 0.0) / JS),
    (lambda: rot.LinearSpeedDependentTorque(tau_nominal=-1.2, w_nominal=2.0,
                                            TorqueDirection=False), 3.0,
     lambda t: 3.0 * np.exp(-0.6 * t / JS)),
    (lambda: rot.LinearSpeedDependentTorque(tau_nominal=-1.2, w_nominal=2.0), -3.0,
     lambda t: -3.0 * np.exp(0.6 * t / JS)),          # |w|: the load drives when w < 0
    (lambda: rot.QuadraticSpeedDependentTorque(tau_nominal=-0.5, w_nominal=1.0,
                                               TorqueDirection=False), -2.0,
     lambda t: -2.0 / (1 + 0.5 * 2.0 * t / JS)),
    (lambda: rot.QuadraticSpeedDependentTorque(tau_nominal=-0.5, w_nominal=1.0), -1.0,
     lambda t: -1.0 / (1 - 0.5 * 1.0 * t / JS)),
], ids=["ConstantTorque", "TorqueStep", "LinearSpeedDependent", "LinearSpeedDependentAbs",
        "QuadraticSpeedDependent", "QuadraticSpeedDependentSameDirection"])
def test_torque_sources_closed_form(source, w0, expected):
    m = acausal.Model("src")
    m.src, m.j = source(), rot.Inertia(J=JS)
    m.connect(m.src.flange, m.j.flange_a)
    t = np.linspace(0.0, 1.0, 101)
    res = acausal.compile(m).simulate(1.0, t=t, x0={"j.w": w0}, max_step=0.01)
    close(res["j.w"], expected(t), what="j.w")
    close(res["src.tau"], -res["src.flange.tau"], tol=1e-12, what="tau = -flange.tau")


def test_torque2_acts_on_two_inertias():
    """Torque2: flange_a.tau = τ, flange_b.tau = −τ: J1·a1 = −τ, J2·a2 = τ."""
    m = acausal.Model("t2")
    m.T, m.t2, m.j1, m.j2 = acausal.Input(), rot.Torque2(), rot.Inertia(J=J1), rot.Inertia(J=J2)
    connect_all(m, (m.T.y, m.t2.tau), (m.t2.flange_a, m.j1.flange_b),
                (m.t2.flange_b, m.j2.flange_a))
    t = np.linspace(0.0, 1.0, 11)
    res = acausal.compile(m).simulate(1.0, t=t, inputs={"T": 2.0})
    close(res["j1.w"], -2.0 * t / J1, what="j1.w")
    close(res["j2.w"], 2.0 * t / J2, what="j2.w")


# =========================================================================================
# Errors name the parameter / port at fault
# =========================================================================================
def test_bad_parameters_and_options_are_named():
    with pytest.raises(acausal.ParameterError, match=r"\bJ\b"):
        rot.Inertia(J=-1.0)
    with pytest.raises(acausal.ParameterError, match="ratio"):
        rot.IdealGear(ratio=0.0)
    with pytest.raises(acausal.ParameterError, match="radius"):
        rot.IdealRollingWheel(radius=0.0)
    with pytest.raises(acausal.ParameterError, match="useSupport"):
        rot.Torque(useSupport=1)
    with pytest.raises(acausal.ParameterError, match="usesupport.*useSupport"):
        rot.IdealGear(usesupport=True)
    with pytest.raises(acausal.ParameterError, match="tau_constant"):
        rot.ConstantTorque()
    with pytest.raises(acausal.ParameterError, match="L"):
        rot.DCMotor(L=0.0)
    with pytest.raises(AttributeError, match="useSupport=True"):
        rot.IdealGear().support


def test_bad_values_at_simulation_time_and_structure_errors_are_named():
    m = acausal.Model("g")
    m.j1, m.gear, m.j2 = rot.Inertia(), rot.IdealGear(ratio=2.0), rot.Inertia()
    connect_all(m, (m.j1.flange_b, m.gear.flange_a), (m.gear.flange_b, m.j2.flange_a))
    compiled = acausal.compile(m)
    with pytest.raises(acausal.ParameterError, match="gear.ratio"):
        compiled.simulate(1.0, params={"gear.ratio": 0.0})
    with pytest.raises(acausal.ParameterError, match="j2.J"):
        compiled.simulate(1.0, params={"j2.J": -3.0})
    # an enabled support must be connected
    m = acausal.Model("s")
    m.j1, m.gear, m.j2 = rot.Inertia(), rot.IdealGear(useSupport=True), rot.Inertia()
    connect_all(m, (m.j1.flange_b, m.gear.flange_a), (m.gear.flange_b, m.j2.flange_a))
    with pytest.raises(acausal.StructureError, match="gear.support"):
        acausal.compile(m)
    # exact=True needs a function of time, not a model input (raised when compiling or, for
    # a rate needed only by recorded variables, when they are first built: here j1.w, the
    # input's rate, when it is read)
    m = base_excited(rot.Position(exact=True), lambda s: s.phi_ref, acausal.Input())
    with pytest.raises(acausal.StructureError, match="exact=False"):
        acausal.compile(m).simulate(0.1, inputs={"ref": np.sin})["j1.w"]


@pytest.mark.parametrize("J_motor", [0.0, 0.2])
def test_massless_inertia_in_a_gear_train_is_the_reduced_inertia(J_motor):
    """MSL allows Inertia.J = 0: torque τ on motor (J_motor) ── IdealGear(ratio i) ── load
    (J_load). Reduced to the load: (J_load + i²·J_motor)·φ̈_load = i·τ (closed form), so
    J_motor = 0 leaves J_load alone; the motor turns i times the load."""
    tau, i, J_load = 1.5, 3.0, 0.8
    m = acausal.Model("train")
    m.T = TimeSignal(fn=lambda t: tau + 0 * t)
    m.torque, m.motor = rot.Torque(), rot.Inertia(J=J_motor)
    m.gear, m.load = rot.IdealGear(ratio=i), rot.Inertia(J=J_load)
    connect_all(m, (m.T.y, m.torque.tau), (m.torque.flange, m.motor.flange_a),
                (m.motor.flange_b, m.gear.flange_a), (m.gear.flange_b, m.load.flange_a))
    compiled = acausal.compile(m)
    assert compiled.fixed_params == (["motor.J"] if J_motor == 0 else [])
    t = np.linspace(0.0, 1.0, 11)
    res = compiled.simulate(1.0, t=t)
    a = i * tau / (J_load + i ** 2 * J_motor)
    close(res["load.phi"], 0.5 * a * t ** 2, what="φ_load = ½·iτ/(J_load + i²J_motor)·t²")
    close(res["motor.phi"], i * res["load.phi"], what="φ_motor = i·φ_load")
