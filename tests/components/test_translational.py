"""The translational library (MSL names, defaults and signs) against independent references:
closed forms, Newton's law written by hand, hand-written scipy models and energy balances."""
import math

import casadi as ca
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.core import Component, RealInput, RealOutput
from acausal.errors import ParameterError, StructureError
from acausal.components import translational as tr
from time_signals import TimeSignal

T_END = 1.0
GRID = np.linspace(0.0, T_END, 101)
TOL = 1e-6


def close(a, b, tol=TOL):
    np.testing.assert_allclose(a, b, rtol=0, atol=tol)


# =========================================================================================
# Forces on a mass
# =========================================================================================
def test_constant_force_accelerates_mass():
    """s = s0 + v0 t + F t²/(2m); MSL: ConstantForce.f = flange.f = −f_constant."""
    F, m_, L = 2.5, 0.8, 0.4
    m = acausal.Model("cf")
    m.src = tr.ConstantForce(f_constant=F)
    m.mass = tr.Mass(m=m_, L=L)
    m.connect(m.src.flange, m.mass.flange_a)
    res = acausal.compile(m).simulate(T_END, t=GRID, x0={"mass.s": 0.1, "mass.v": 0.3})
    t = GRID
    s = 0.1 + 0.3 * t + F * t ** 2 / (2 * m_)
    close(res["mass.s"], s)
    close(res["mass.v"], 0.3 + F * t / m_)
    close(res["mass.a"], F / m_)
    close(res["mass.flange_a.s"], s - L / 2)
    close(res["mass.flange_b.s"], s + L / 2)
    close(res["src.s"], s - L / 2)                 # flange.s − support.s, support at 0
    close(res["src.f"], -F)
    close(res["src.flange.f"], -F)
    close(res["mass.flange_a.f"], F)               # the force acting on the mass
    close(res["mass.flange_b.f"], 0.0)


def test_force_support_takes_the_reaction():
    """Force(useSupport=True): support.f = −flange.f = f; the housing's Fixed gets −f."""
    F, m_, s0 = 1.5, 2.0, 0.25
    m = acausal.Model("sup")
    m.F = acausal.Input(start=F)
    m.force = tr.Force(useSupport=True)
    m.housing = tr.Fixed(s0=s0)
    m.mass = tr.Mass(m=m_)
    m.connect(m.F.y, m.force.f)
    m.connect(m.force.flange, m.mass.flange_a)
    m.connect(m.housing.flange, m.force.support)
    res = acausal.compile(m).simulate(T_END, t=GRID)
    s = F * GRID ** 2 / (2 * m_)
    close(res["mass.s"], s)
    close(res["force.s"], s - s0)
    close(res["force.flange.f"], -F)
    close(res["force.support.f"], F)
    close(res["housing.flange.f"], -F)


def test_sign_convention_example():
    """MSL Translational.Examples.SignConvention: a force of 1 N on a 1 kg mass — pushing at
    flange_a, pulling at flange_b, or mounted the other way round with its support on the
    ground — always gives a = 1, v(1) = 1 m/s, s(1) = 0.5 m."""
    m = acausal.Model("SignConvention")
    for k in (1, 2, 3):
        setattr(m, f"mass{k}", tr.Mass(m=1, L=1))
        setattr(m, f"constant{k}", acausal.Input(start=1.0))
    m.force1 = tr.Force()
    m.force2 = tr.Force()
    m.force3 = tr.Force(useSupport=True)
    m.fixed = tr.Fixed()
    for k in (1, 2, 3):
        m.connect(getattr(m, f"constant{k}").y, getattr(m, f"force{k}").f)
    m.connect(m.force1.flange, m.mass1.flange_a)
    m.connect(m.force2.flange, m.mass2.flange_b)
    m.connect(m.mass3.flange_b, m.force3.flange)
    m.connect(m.fixed.flange, m.force3.support)
    res = acausal.compile(m).simulate(1.0, t=GRID)
    for k in (1, 2, 3):
        close(res[f"mass{k}.a"], 1.0)
        close(res[f"mass{k}.v"][-1], 1.0)
        close(res[f"mass{k}.s"][-1], 0.5)


def test_force_step():
    """f = −offsetForce − (t ≥ startTime)·stepForce: piecewise-parabolic motion."""
    m_, off, step, t0 = 2.0, 0.5, 2.0, 0.3
    m = acausal.Model("fs")
    m.src = tr.ForceStep(stepForce=step, offsetForce=off, startTime=t0)
    m.mass = tr.Mass(m=m_)
    m.connect(m.src.flange, m.mass.flange_a)
    res = acausal.compile(m).simulate(T_END, t=GRID)
    t = GRID
    after = np.clip(t - t0, 0, None)
    close(res["mass.s"], off * t ** 2 / (2 * m_) + step * after ** 2 / (2 * m_))
    close(res["mass.v"], off * t / m_ + step * after / m_)
    close(res["src.f"], -off - step * (t >= t0))


def test_force2_equal_and_opposite():
    """Force2: flange_a.f = f, flange_b.f = −f: pushes the two bodies apart, momentum 0."""
    m1, m2, f = 1.0, 3.0, 1.5
    m = acausal.Model("f2")
    m.a = tr.Mass(m=m1)
    m.b = tr.Mass(m=m2)
    m.force = tr.Force2()
    m.f = acausal.Input(start=f)
    m.connect(m.f.y, m.force.f)
    m.connect(m.a.flange_b, m.force.flange_a)
    m.connect(m.force.flange_b, m.b.flange_a)
    res = acausal.compile(m).simulate(T_END, t=GRID, x0={"a.s": -1.0, "b.s": 1.0})
    close(res["a.s"], -1.0 - f * GRID ** 2 / (2 * m1))
    close(res["b.s"], 1.0 + f * GRID ** 2 / (2 * m2))
    close(m1 * res["a.v"] + m2 * res["b.v"], 0.0)
    close(res["force.flange_a.f"], f)
    close(res["force.flange_b.f"], -f)


@pytest.mark.parametrize("cls, direction, v0, law", [
    # force on the mass = −flange.f; f_nominal = −2 N (a load), v_nominal = 0.5 m/s, m = 1 kg
    (tr.LinearSpeedDependentForce, False, 1.0, lambda t: np.exp(-4 * t)),
    (tr.LinearSpeedDependentForce, True, -1.0, lambda t: -np.exp(4 * t)),
    (tr.QuadraticSpeedDependentForce, True, 1.0, lambda t: 1 / (1 + 8 * t)),
    (tr.QuadraticSpeedDependentForce, False, -1.0, lambda t: -1 / (1 + 8 * t)),
])
def test_speed_dependent_forces(cls, direction, v0, law):
    """Linear: m v' = f_nominal·|v|/v_nominal or f_nominal·v/v_nominal; quadratic:
    m v' = f_nominal·v²/v_nominal² or f_nominal·v·|v|/v_nominal² — closed forms."""
    m = acausal.Model("sdf")
    m.src = cls(f_nominal=-2.0, v_nominal=0.5, ForceDirection=direction)
    m.mass = tr.Mass(m=1.0)
    m.connect(m.src.flange, m.mass.flange_a)
    t = np.linspace(0, 0.5, 51)
    res = acausal.compile(m).simulate(0.5, t=t, x0={"mass.v": v0})
    v = law(t)
    close(res["mass.v"], v)
    close(res["src.v"], v)
    x = v / 0.5
    force_on_mass = -2.0 * ((np.abs(x) if direction else x) if cls is tr.LinearSpeedDependentForce
                            else (x ** 2 if direction else x * np.abs(x)))
    close(res["src.f"], -force_on_mass, 1e-5)


# =========================================================================================
# Springs, dampers, rods
# =========================================================================================
S0, S_REL0, LEN = 0.3, 0.5, 0.2      # wall position, unstretched length, mass length [m]


def damped(t, m, c, d, x0, v0):
    """x(t) of m x'' + d x' + c x = 0 (underdamped)."""
    w0, zeta = math.sqrt(c / m), d / (2 * math.sqrt(c * m))
    wd = w0 * math.sqrt(1 - zeta ** 2)
    return np.exp(-zeta * w0 * t) * (x0 * np.cos(wd * t) + (v0 + zeta * w0 * x0) / wd
                                     * np.sin(wd * t))


def test_spring_damper_vs_spring_and_damper_in_parallel():
    """Two oscillators — SpringDamper, and Spring ∥ Damper — against the damped closed form;
    forces, the wall's reaction and lossPower = d v² by hand."""
    m_, c, d = 0.5, 8.0, 0.6
    m = acausal.Model("sd")
    m.wall1 = tr.Fixed(s0=S0)
    m.sd = tr.SpringDamper(c=c, d=d, s_rel0=S_REL0)
    m.mass1 = tr.Mass(m=m_, L=LEN)
    m.connect(m.wall1.flange, m.sd.flange_a)
    m.connect(m.sd.flange_b, m.mass1.flange_a)
    m.wall2 = tr.Fixed(s0=S0)
    m.spring = tr.Spring(c=c, s_rel0=S_REL0)
    m.damper = tr.Damper(d=d)
    m.mass2 = tr.Mass(m=m_, L=LEN)
    m.connect(m.wall2.flange, m.spring.flange_a)
    m.connect(m.wall2.flange, m.damper.flange_a)
    m.connect(m.spring.flange_b, m.mass2.flange_a)
    m.connect(m.damper.flange_b, m.mass2.flange_a)
    s_eq = S0 + S_REL0 + LEN / 2
    x0 = {"mass1.s": s_eq + 0.1, "mass1.v": 0.2, "mass2.s": s_eq + 0.1, "mass2.v": 0.2}
    res = acausal.compile(m).simulate(3.0, t=np.linspace(0, 3, 301), x0=x0)
    t = res.t
    x = damped(t, m_, c, d, 0.1, 0.2)
    h = 1e-6
    v = (damped(t + h, m_, c, d, 0.1, 0.2) - damped(t - h, m_, c, d, 0.1, 0.2)) / (2 * h)
    for k in (1, 2):
        close(res[f"mass{k}.s"], s_eq + x)
        close(res[f"mass{k}.v"], v, 1e-5)
    f_spring, f_damper = c * x, d * v
    close(res["sd.f"], f_spring + f_damper, 1e-5)
    close(res["spring.f"], f_spring, 1e-5)
    close(res["damper.f"], f_damper, 1e-5)
    close(res["sd.s_rel"], x + S_REL0)
    close(res["sd.v_rel"], v, 1e-5)
    close(res["sd.lossPower"], d * v ** 2, 1e-5)
    close(res["damper.lossPower"], d * v ** 2, 1e-5)
    # the wall is pulled by the compressed/stretched element: flange.f = f of the element
    close(res["wall1.flange.f"], f_spring + f_damper, 1e-5)
    close(res["wall2.flange.f"], f_spring + f_damper, 1e-5)
    close(res["mass1.flange_a.f"], -(f_spring + f_damper), 1e-5)


def test_static_equilibrium_reactions():
    """wall | spring | mass <- F (ConstantForce at flange_b), started at rest in equilibrium:
    nothing moves; the spring is stretched by F/c; the wall is pulled in +s with F
    (Fixed.flange.f = +F); the force source's housing (useSupport) is pushed back with −F."""
    F, c, s0, L = 5.0, 50.0, 1.0, 0.4
    m = acausal.Model("static")
    m.wall = tr.Fixed(s0=s0)
    m.spring = tr.Spring(c=c, s_rel0=0.2)
    m.mass = tr.Mass(m=2.0, L=L)
    m.src = tr.ConstantForce(f_constant=F, useSupport=True)
    m.ground = tr.Fixed(s0=3.0)
    m.connect(m.wall.flange, m.spring.flange_a)
    m.connect(m.spring.flange_b, m.mass.flange_a)
    m.connect(m.mass.flange_b, m.src.flange)
    m.connect(m.src.support, m.ground.flange)
    s_eq = s0 + 0.2 + F / c + L / 2
    res = acausal.compile(m).simulate(T_END, t=GRID, x0={"mass.s": s_eq, "mass.v": 0.0})
    close(res["mass.s"], s_eq)
    close(res["spring.s_rel"], 0.2 + F / c)
    close(res["spring.f"], F)
    close(res["wall.flange.f"], F)
    close(res["spring.flange_a.f"], -F)
    close(res["spring.flange_b.f"], F)
    close(res["mass.flange_a.f"], -F)
    close(res["mass.flange_b.f"], F)
    close(res["src.flange.f"], -F)
    close(res["src.f"], -F)
    close(res["src.s"], s_eq + L / 2 - 3.0)
    close(res["ground.flange.f"], -F)
    close(res["wall.flange.f"] + res["ground.flange.f"], 0.0)   # no net force on the ground


def test_rod_shifts_positions_and_passes_the_force():
    """wall(s0) | rod(L) | spring | mass: positions shift by L, rod.flange_a.f = −flange_b.f
    and the oscillation is the wall's, moved by L."""
    s0, Lr, c, m_, Lm = 0.2, 0.7, 4.0, 1.0, 0.2
    m = acausal.Model("rod")
    m.wall = tr.Fixed(s0=s0)
    m.rod = tr.Rod(L=Lr)
    m.spring = tr.Spring(c=c, s_rel0=0.1)
    m.mass = tr.Mass(m=m_, L=Lm)
    m.connect(m.wall.flange, m.rod.flange_a)
    m.connect(m.rod.flange_b, m.spring.flange_a)
    m.connect(m.spring.flange_b, m.mass.flange_a)
    s_eq = s0 + Lr + 0.1 + Lm / 2
    res = acausal.compile(m).simulate(T_END, t=GRID, x0={"mass.s": s_eq + 0.05})
    x = 0.05 * np.cos(2.0 * GRID)
    close(res["mass.s"], s_eq + x)
    close(res["rod.s"], s0 + Lr / 2)
    close(res["rod.flange_b.s"], s0 + Lr)
    close(res["rod.flange_b.f"], c * x)
    close(res["rod.flange_a.f"], -c * x)
    close(res["wall.flange.f"], c * x)


def test_energy_of_an_undamped_chain_is_constant():
    """wall | spring | mass | spring | mass ... (8 of each, free end): T + V constant to
    1e-7 (relative), T and V computed here from the masses and spring constants."""
    n = 8
    ms = [1.0 + 0.25 * k for k in range(n)]
    cs = [20.0 + 5.0 * k for k in range(n)]
    Ls = [0.1 * (k % 3) for k in range(n)]
    r0 = [0.3 + 0.05 * k for k in range(n)]
    m = acausal.Model("chain")
    m.wall = tr.Fixed(s0=-0.4)
    prev = m.wall.flange
    for k in range(n):
        setattr(m, f"spring{k}", tr.Spring(c=cs[k], s_rel0=r0[k]))
        setattr(m, f"mass{k}", tr.Mass(m=ms[k], L=Ls[k]))
        sp, ma = getattr(m, f"spring{k}"), getattr(m, f"mass{k}")
        m.connect(prev, sp.flange_a)
        m.connect(sp.flange_b, ma.flange_a)
        prev = ma.flange_b
    x0 = {f"mass{k}.s": 0.5 * k + 0.03 * (-1) ** k for k in range(n)}
    x0["mass0.v"] = 0.4
    t = np.linspace(0, 2.0, 201)
    res = acausal.compile(m).simulate(2.0, t=t, x0=x0, rtol=1e-10, atol=1e-12)
    T = sum(0.5 * ms[k] * res[f"mass{k}.v"] ** 2 for k in range(n))
    left = -0.4
    V = 0.0
    for k in range(n):
        s = res[f"mass{k}.s"]
        V = V + 0.5 * cs[k] * ((s - Ls[k] / 2 - left) - r0[k]) ** 2
        left = s + Ls[k] / 2
    E = T + V
    assert np.ptp(T) > 0.1 * E[0]                     # energy really moves between T and V
    assert np.max(np.abs(E - E[0])) / E[0] < 1e-7


# =========================================================================================
# Prescribed motion: Position, Speed, Accelerate, Move, ConstantSpeed
# =========================================================================================
def test_position_exact_drives_spring_damper_mass():
    """Position(exact=True, useSupport) on a housing at s0 moves a rigid mass m0, which drives
    mass m1 through a spring-damper; against a hand-written scipy ODE. Reaction:
    position.flange.f = f_sd − m0·a0 (Newton on m0), and the housing gets the same."""
    A, w, s0, m0, m1, c, d, r0 = 0.2, 3.0, 0.1, 0.5, 1.0, 30.0, 0.8, 0.4
    m = acausal.Model("pos")
    m.ref = TimeSignal(fn=lambda t: A * ca.sin(w * t))
    m.position = tr.Position(exact=True, useSupport=True)
    m.housing = tr.Fixed(s0=s0)
    m.m0 = tr.Mass(m=m0)
    m.sd = tr.SpringDamper(c=c, d=d, s_rel0=r0)
    m.m1 = tr.Mass(m=m1)
    m.connect(m.ref.y, m.position.s_ref)
    m.connect(m.housing.flange, m.position.support)
    m.connect(m.position.flange, m.m0.flange_a)
    m.connect(m.m0.flange_b, m.sd.flange_a)
    m.connect(m.sd.flange_b, m.m1.flange_a)
    res = acausal.compile(m).simulate(T_END, t=GRID, x0={"m1.s": s0 + r0, "m1.v": A * w})

    xp = lambda t: s0 + A * np.sin(w * t)
    vp = lambda t: A * w * np.cos(w * t)
    ap = lambda t: -A * w ** 2 * np.sin(w * t)

    def rhs(t, y):
        x, v = y
        return [v, (-c * (x - xp(t) - r0) - d * (v - vp(t))) / m1]

    ref = solve_ivp(rhs, (0, T_END), [s0 + r0, A * w], t_eval=GRID, rtol=1e-11, atol=1e-12)
    x, v = ref.y
    close(res["m1.s"], x)
    close(res["m1.v"], v)
    close(res["m0.s"], xp(GRID))
    close(res["position.s"], xp(GRID) - s0)
    close(res["position.v"], vp(GRID))
    close(res["position.a"], ap(GRID))
    f_sd = c * (x - xp(GRID) - r0) + d * (v - vp(GRID))
    close(res["sd.f"], f_sd, 1e-5)
    close(res["position.flange.f"], f_sd - m0 * ap(GRID), 1e-5)
    close(res["housing.flange.f"], f_sd - m0 * ap(GRID), 1e-5)


def bessel_reference(t, r, f_crit, m_, c, r0, x0):
    """MSL Position filter (af = 1.3617, bf = 0.6180) driving a spring-mass, by scipy."""
    wc = 2 * math.pi * f_crit

    def rhs(t, y):
        sf, vf, x, v = y
        af = ((r(t) - sf) * wc - 1.3617 * vf) * (wc / 0.6180)
        return [vf, af, v, -c * (x - sf - r0) / m_]

    sol = solve_ivp(rhs, (t[0], t[-1]), x0, t_eval=t, rtol=1e-11, atol=1e-12)
    sf, vf, x, v = sol.y
    af = ((r(t) - sf) * wc - 1.3617 * vf) * (wc / 0.6180)
    return sf, vf, af, x


@pytest.mark.parametrize("offset", [0.0, 0.4])
def test_position_filter_against_hand_filter(offset):
    """Position(exact=False) filters s_ref (here a model Input, not differentiable by the
    compiler) with MSL's Bessel filter; it drives a spring-mass. With s_ref(0) ≠ 0 the filter
    is initialized as MSL does (s = s_ref(0)) through x0."""
    f_crit, m_, c, r0 = 3.0, 1.0, 40.0, 0.3
    m = acausal.Model("filt")
    m.sref = acausal.Input()
    m.position = tr.Position(f_crit=f_crit)
    m.spring = tr.Spring(c=c, s_rel0=r0)
    m.mass = tr.Mass(m=m_)
    m.connect(m.sref.y, m.position.s_ref)
    m.connect(m.position.flange, m.spring.flange_a)
    m.connect(m.spring.flange_b, m.mass.flange_a)
    r = lambda t: offset + 0.5 * np.sin(2 * t)
    x0 = {"mass.s": offset + r0}
    if offset:
        x0["position.s"] = offset
    res = acausal.compile(m).simulate(T_END, t=GRID, x0=x0,
                                      inputs={"sref": lambda t: offset + 0.5 * ca.sin(2 * t)})
    sf, vf, af, x = bessel_reference(GRID, r, f_crit, m_, c, r0, [offset, 0, offset + r0, 0])
    close(res["position.s"], sf)
    close(res["position.v"], vf)
    close(res["position.a"], af, 1e-5)
    close(res["mass.s"], x)
    close(res["position.flange.s"], sf)
    close(res["position.flange.f"], c * (x - sf - r0), 1e-5)


def test_speed_filter_closed_form():
    """Speed(exact=False): v = V(1 − e^(−w t)), s = V(t − (1 − e^(−w t))/w), w = 2π f_crit;
    the reaction on a rigidly attached mass is −m·a."""
    V, f_crit, m_ = 1.5, 2.0, 0.7
    w = 2 * math.pi * f_crit
    m = acausal.Model("spd")
    m.vref = acausal.Input(start=V)
    m.speed = tr.Speed(f_crit=f_crit)
    m.mass = tr.Mass(m=m_)
    m.connect(m.vref.y, m.speed.v_ref)
    m.connect(m.speed.flange, m.mass.flange_a)
    res = acausal.compile(m).simulate(T_END, t=GRID)
    t = GRID
    close(res["speed.v"], V * (1 - np.exp(-w * t)))
    close(res["speed.s"], V * (t - (1 - np.exp(-w * t)) / w))
    close(res["speed.a"], V * w * np.exp(-w * t), 1e-5)
    close(res["mass.s"], V * (t - (1 - np.exp(-w * t)) / w))
    close(res["speed.flange.f"], -m_ * V * w * np.exp(-w * t), 1e-5)


def test_speed_exact_closed_form():
    """Speed(exact=True), v_ref = A cos(w t): s = A sin(w t)/w; flange.f = −m·a."""
    A, w, m_ = 0.8, 2.5, 1.2
    m = acausal.Model("spdx")
    m.ref = TimeSignal(fn=lambda t: A * ca.cos(w * t))
    m.speed = tr.Speed(exact=True)
    m.mass = tr.Mass(m=m_)
    m.connect(m.ref.y, m.speed.v_ref)
    m.connect(m.speed.flange, m.mass.flange_a)
    res = acausal.compile(m).simulate(T_END, t=GRID)
    t = GRID
    close(res["mass.s"], A * np.sin(w * t) / w)
    close(res["speed.v"], A * np.cos(w * t))
    close(res["speed.a"], -A * w * np.sin(w * t))
    close(res["speed.flange.f"], m_ * A * w * np.sin(w * t))


def test_accelerate_closed_form():
    """Accelerate: s = a t²/2, v = a t from rest; the driven mass pushes back with −m·a."""
    a, m_ = 0.9, 3.0
    m = acausal.Model("acc")
    m.aref = acausal.Input(start=a)
    m.acc = tr.Accelerate(useSupport=True)
    m.ground = tr.Fixed(s0=-0.5)
    m.mass = tr.Mass(m=m_, L=0.2)
    m.connect(m.aref.y, m.acc.a_ref)
    m.connect(m.ground.flange, m.acc.support)
    m.connect(m.acc.flange, m.mass.flange_a)
    res = acausal.compile(m).simulate(T_END, t=GRID)
    t = GRID
    close(res["acc.s"], a * t ** 2 / 2)
    close(res["acc.v"], a * t)
    close(res["acc.a"], a)
    close(res["mass.s"], -0.5 + 0.1 + a * t ** 2 / 2)
    close(res["acc.flange.f"], -m_ * a)
    close(res["ground.flange.f"], -m_ * a)        # support.f = −flange.f; ground = −support


def test_constant_speed_against_a_damper():
    """ConstantSpeed(v_fixed) pulls a damper anchored to the wall: s = v t, the damper force
    is d·v and MSL's f = flange.f = −d·v."""
    v, d = 0.7, 4.0
    m = acausal.Model("cs")
    m.src = tr.ConstantSpeed(v_fixed=v)
    m.wall = tr.Fixed()
    m.damper = tr.Damper(d=d)
    m.connect(m.wall.flange, m.damper.flange_a)
    m.connect(m.damper.flange_b, m.src.flange)
    res = acausal.compile(m).simulate(T_END, t=GRID)
    close(res["src.s"], v * GRID)
    close(res["src.v"], v)
    close(res["damper.f"], d * v)
    close(res["src.f"], -d * v)
    close(res["src.flange.f"], -d * v)
    close(res["wall.flange.f"], d * v)


def test_move_with_consistent_signals():
    """Move: u[1] = A sin(w t), u[2] = its derivative, u[3] the second: the rigidly driven
    mass follows u[1]; through a spring it drives a free mass (scipy reference); Newton on the
    driven mass gives the reaction move.flange.f = f_spring − m·u[3]."""
    A, w, m_, m2, c = 0.3, 2.0, 1.5, 0.5, 12.0
    m = acausal.Model("move")
    m.p = TimeSignal(fn=lambda t: A * ca.sin(w * t))
    m.v = TimeSignal(fn=lambda t: A * w * ca.cos(w * t))
    m.a = TimeSignal(fn=lambda t: -A * w ** 2 * ca.sin(w * t))
    m.move = tr.Move()
    m.mass = tr.Mass(m=m_)
    m.spring = tr.Spring(c=c, s_rel0=0.5)
    m.mass2 = tr.Mass(m=m2)
    m.connect(m.p.y, m.move.u[1])
    m.connect(m.v.y, m.move.u[2])
    m.connect(m.a.y, m.move.u[3])
    m.connect(m.move.flange, m.mass.flange_a)
    m.connect(m.mass.flange_b, m.spring.flange_a)
    m.connect(m.spring.flange_b, m.mass2.flange_a)
    res = acausal.compile(m).simulate(T_END, t=GRID, x0={"mass2.s": 0.5})
    t = GRID
    xp, ap = A * np.sin(w * t), -A * w ** 2 * np.sin(w * t)
    ref = solve_ivp(lambda t, y: [y[1], -c * (y[0] - A * np.sin(w * t) - 0.5) / m2],
                    (0, T_END), [0.5, 0.0], t_eval=t, rtol=1e-11, atol=1e-12)
    close(res["mass2.s"], ref.y[0])
    close(res["mass.s"], xp)
    close(res["move.v"], A * w * np.cos(w * t))
    close(res["move.v_u"], A * w * np.cos(w * t))
    close(res["move.a"], ap)
    f_spring = c * (ref.y[0] - xp - 0.5)
    close(res["move.flange.f"], f_spring - m_ * ap, 1e-5)


def test_move_takes_u2_u3_as_given_not_derived():
    """MSL's Move takes u[2], u[3] as the speed and acceleration of u[1], not derived from
    it: with u[2] = u[3] = 0 (MSL's use for position-dependent forces only) the mass follows
    u[1] = A sin(wt), its speed and acceleration read 0, and the source's force is the
    spring's alone (no m·a), while the free mass behind the spring feels the position."""
    A, w, m_, m2, c = 0.3, 2.0, 1.5, 0.5, 12.0
    m = acausal.Model("move0")
    m.p = TimeSignal(fn=lambda t: A * ca.sin(w * t))
    m.zero = TimeSignal(fn=lambda t: 0 * t)
    m.move, m.mass, m.spring, m.mass2 = tr.Move(), tr.Mass(m=m_), tr.Spring(c=c, s_rel0=0.5), \
        tr.Mass(m=m2)
    for a, b in [(m.p.y, m.move.u[1]), (m.zero.y, m.move.u[2]), (m.zero.y, m.move.u[3]),
                 (m.move.flange, m.mass.flange_a), (m.mass.flange_b, m.spring.flange_a),
                 (m.spring.flange_b, m.mass2.flange_a)]:
        m.connect(a, b)
    res = acausal.compile(m).simulate(T_END, t=GRID, x0={"mass2.s": 0.5}, rtol=1e-10,
                                      atol=1e-12)
    ref = solve_ivp(lambda t, y: [y[1], -c * (y[0] - A * np.sin(w * t) - 0.5) / m2],
                    (0, T_END), [0.5, 0.0], t_eval=GRID, rtol=1e-11, atol=1e-12)
    close(res["mass2.s"], ref.y[0])
    close(res["mass.s"], A * np.sin(w * GRID))
    close(res["mass.v"], 0.0)
    close(res["mass.a"], 0.0)
    close(res["move.flange.f"], c * (ref.y[0] - A * np.sin(w * GRID) - 0.5))


@pytest.mark.parametrize("use_pder, use_pder2", [(True, True), (True, False), (False, False)])
def test_position_to_force_adaptor_moved_by_model_inputs(use_pder, use_pder2):
    """GeneralPositionToForceAdaptor driven by model inputs (no rates derivable): with
    the speed and acceleration given, a mass behind it needs f = m·pder2 + the spring's
    pull; with the position only, a spring alone to a wall (no mass: no rate needed) needs
    f = c·(p − wall − s_rel0) pulling back. GeneralForceToPositionAdaptor on a mass: the
    input force is its flange's cut force (flange.f = f: it loads the mass, which is
    accelerated by −f), the outputs are the mass's position, speed and acceleration."""
    m_, c, wall, s_rel0 = 1.5, 12.0, 2.0, 0.5
    m = acausal.Model("adaptors")
    m.p, m.v, m.a = acausal.Input(), acausal.Input(), acausal.Input()
    m.moved = tr.GeneralPositionToForceAdaptor(use_pder=use_pder, use_pder2=use_pder2)
    m.spring, m.wall = tr.Spring(c=c, s_rel0=s_rel0), tr.Fixed(s0=wall)
    pairs = [(m.p.y, m.moved.p), (m.spring.flange_b, m.wall.flange)]
    if use_pder2:
        m.mass = tr.Mass(m=m_)
        pairs += [(m.moved.flange, m.mass.flange_a), (m.mass.flange_b, m.spring.flange_a)]
    else:
        pairs += [(m.moved.flange, m.spring.flange_a)]
    if use_pder:
        pairs += [(m.v.y, m.moved.pder)]
    if use_pder2:
        pairs += [(m.a.y, m.moved.pder2)]
    m.drive = acausal.Input()
    m.driven, m.mass3 = tr.GeneralForceToPositionAdaptor(), tr.Mass(m=m_)
    pairs += [(m.drive.y, m.driven.f), (m.driven.flange, m.mass3.flange_b)]
    for a, b in pairs:
        m.connect(a, b)
    signals = {"p": np.sin, "v": np.cos, "a": lambda t: -np.sin(t), "drive": lambda t: 0 * t + 3.0}
    res = acausal.compile(m).simulate(T_END, t=GRID, inputs=signals, rtol=1e-10, atol=1e-12)
    p, a = np.sin(GRID), -np.sin(GRID)
    stretch = wall - p - s_rel0
    close(res["moved.f"], (m_ * a if use_pder2 else 0.0) - c * stretch)
    close(res["driven.p"], res["mass3.s"])
    close(res["mass3.s"], -3.0 * GRID ** 2 / (2 * m_))
    close(res["driven.pder"], -3.0 * GRID / m_)
    close(res["driven.pder2"], -3.0 / m_)


# =========================================================================================
# Sensors
# =========================================================================================
def test_sensors_against_newton():
    """wall | spring | m1 | ForceSensor | MultiSensor | PowerSensor | m2 <- F: the sensors
    are rigid, so m1, m2 move together: (m1+m2) x'' = −c (x − x_eq) (closed form). Newton on
    m2 gives the cut force f = m2·a − F; power = f·v; absolute and relative sensors read the
    hand-computed positions, speeds and accelerations."""
    m1, m2, L1, L2, c, F, s0, r0 = 1.0, 2.0, 0.1, 0.2, 20.0, 3.0, 0.1, 0.2
    m = acausal.Model("sens")
    m.wall = tr.Fixed(s0=s0)
    m.spring = tr.Spring(c=c, s_rel0=r0)
    m.mass1 = tr.Mass(m=m1, L=L1)
    m.forceSensor = tr.ForceSensor()
    m.multiSensor = tr.MultiSensor()
    m.powerSensor = tr.PowerSensor()
    m.mass2 = tr.Mass(m=m2, L=L2)
    m.force = tr.Force()
    m.F = acausal.Input(start=F)
    m.positionSensor = tr.PositionSensor()
    m.speedSensor = tr.SpeedSensor()
    m.accSensor = tr.AccSensor()
    m.relPositionSensor = tr.RelPositionSensor()
    m.relSpeedSensor = tr.RelSpeedSensor()
    m.relAccSensor = tr.RelAccSensor()
    C = m.connect
    C(m.wall.flange, m.spring.flange_a)
    C(m.spring.flange_b, m.mass1.flange_a)
    C(m.mass1.flange_b, m.forceSensor.flange_a)
    C(m.forceSensor.flange_b, m.multiSensor.flange_a)
    C(m.multiSensor.flange_b, m.powerSensor.flange_a)
    C(m.powerSensor.flange_b, m.mass2.flange_a)
    C(m.mass2.flange_b, m.force.flange)
    C(m.F.y, m.force.f)
    for sensor in (m.positionSensor, m.speedSensor, m.accSensor):
        C(sensor.flange, m.mass2.flange_b)
    for sensor in (m.relPositionSensor, m.relSpeedSensor, m.relAccSensor):
        C(sensor.flange_a, m.spring.flange_a)
        C(sensor.flange_b, m.spring.flange_b)
    res = acausal.compile(m).simulate(T_END, t=GRID, x0={"mass1.s": 0.6})
    w = math.sqrt(c / (m1 + m2))
    x_eq = s0 + r0 + F / c + L1 / 2
    x = x_eq + (0.6 - x_eq) * np.cos(w * GRID)
    v = -(0.6 - x_eq) * w * np.sin(w * GRID)
    a = -w ** 2 * (x - x_eq)
    f = m2 * a - F
    close(res["mass1.s"], x)
    close(res["forceSensor.f"], f, 1e-5)
    close(res["multiSensor.f"], f, 1e-5)
    close(res["multiSensor.v"], v)
    close(res["multiSensor.power"], f * v, 1e-5)
    close(res["powerSensor.power"], f * v, 1e-5)
    close(res["forceSensor.flange_b.f"], -f, 1e-5)
    close(res["mass1.flange_b.f"], -f, 1e-5)
    # Newton on m1: m1 a = flange_a.f + flange_b.f, spring force c(s_rel − s_rel0) by hand
    f_spring = c * (x - L1 / 2 - s0 - r0)
    close(res["mass1.flange_a.f"], -f_spring, 1e-5)
    close(m1 * a, -f_spring - f, 1e-5)
    close(res["positionSensor.s"], x + L1 / 2 + L2)
    close(res["speedSensor.v"], v)
    close(res["accSensor.a"], a, 1e-5)
    close(res["accSensor.v"], v)
    close(res["relPositionSensor.s_rel"], x - L1 / 2 - s0)
    close(res["relSpeedSensor.v_rel"], v)
    close(res["relSpeedSensor.s_rel"], x - L1 / 2 - s0)
    close(res["relAccSensor.a_rel"], a, 1e-5)
    close(res["relAccSensor.v_rel"], v)


def test_speed_sensor_feedback_is_a_damper():
    """A SpeedSensor feeding a Force (f = −d·v through a test-local gain) acts as a damper:
    the mass on a spring follows the damped closed form."""
    m_, c, d = 0.5, 8.0, 0.6

    class NegGain(Component):
        u = RealInput("input")
        y = RealOutput("output")

        def physics(self, e):
            e.output(self.y, -d * e.input(self.u))

    m = acausal.Model("fb")
    m.wall = tr.Fixed()
    m.spring = tr.Spring(c=c)
    m.mass = tr.Mass(m=m_)
    m.speedSensor = tr.SpeedSensor()
    m.gain = NegGain()
    m.force = tr.Force()
    m.connect(m.wall.flange, m.spring.flange_a)
    m.connect(m.spring.flange_b, m.mass.flange_a)
    m.connect(m.speedSensor.flange, m.mass.flange_b)
    m.connect(m.speedSensor.v, m.gain.u)
    m.connect(m.gain.y, m.force.f)
    m.connect(m.force.flange, m.mass.flange_b)
    res = acausal.compile(m).simulate(T_END, t=GRID, x0={"mass.s": 0.1})
    close(res["mass.s"], damped(GRID, m_, c, d, 0.1, 0.0))


# =========================================================================================
# Errors
# =========================================================================================
def _series_chain(masses, c=(10.0, 30.0), m_end=2.0):
    """wall ── spring c[0] ── Mass masses[0] ── spring c[1] ── ... ── Mass m_end."""
    m = acausal.Model("chain")
    m.wall = tr.Fixed()
    prev = m.wall.flange
    for i, (ci, mi) in enumerate(zip(c, list(masses) + [m_end])):
        spring, mass = tr.Spring(c=ci), tr.Mass(m=mi)
        setattr(m, f"s{i}", spring)
        setattr(m, f"m{i}", mass)
        m.connect(prev, spring.flange_a)
        m.connect(spring.flange_b, mass.flange_a)
        prev = mass.flange_b
    return m


def test_massless_mass_between_springs_is_the_springs_in_series():
    """MSL allows Mass.m = 0: wall ── c1 ── Mass(m=0) ── c2 ── Mass(m) is one mass on the
    series spring c = c1·c2/(c1 + c2): s = s0·cos(√(c/m)·t) (closed form, the hand model
    without the massless mass), and the massless node sits where c1·s_mid = c2·(s − s_mid).
    Its position is an algebraic variable; m is fixed at 0 in the compiled model."""
    c1, c2, m_end, s0 = 10.0, 30.0, 2.0, 0.1
    compiled = acausal.compile(_series_chain([0.0], (c1, c2), m_end))
    assert compiled.x_names == ["m1.s", "m1.v"] and compiled.z_names == ["m0.s"]
    assert compiled.fixed_params == ["m0.m"] and "m0.m" not in compiled.param_names
    t = np.linspace(0.0, 3.0, 151)
    res = compiled.simulate(3.0, t=t, x0={"m1.s": s0})
    s = s0 * np.cos(math.sqrt(c1 * c2 / (c1 + c2) / m_end) * t)
    close(res["m1.s"], s)
    close(res["m0.s"], c2 / (c1 + c2) * s)
    close(res["s0.f"], res["s1.f"])                       # no mass: the forces balance
    with pytest.raises(ParameterError, match=r"'m0\.m' of model 'chain' was fixed at 0 .* "
                                             r"build it with a value > 0 and compile again"):
        compiled.simulate(1.0, params={"m0.m": 1.0})
    massive = acausal.compile(_series_chain([1.0], (c1, c2), m_end))
    with pytest.raises(ParameterError, match=r"'m0\.m' must be > 0"):
        massive.simulate(1.0, params={"m0.m": 0.0})       # would need other equations


def test_many_massless_masses_batched_are_one_series_spring():
    """Nine massless masses between ten springs (compiled as one batch of the Mass class):
    one mass on c/10, s = s0·cos(√(c/(10·m))·t) (closed form)."""
    c, m_end, s0 = 50.0, 0.5, 0.2
    compiled = acausal.compile(_series_chain([0.0] * 9, (c,) * 10, m_end))
    assert compiled.x_names == ["m9.s", "m9.v"] and len(compiled.z_names) == 9
    t = np.linspace(0.0, 2.0, 101)
    res = compiled.simulate(2.0, t=t, x0={"m9.s": s0})
    close(res["m9.s"], s0 * np.cos(math.sqrt(c / 10 / m_end) * t))
    close(res["m4.s"], 0.5 * s0 * np.cos(math.sqrt(c / 10 / m_end) * t))


def test_massless_mass_with_only_a_force_is_singular():
    """A massless Mass on which only a given force acts has no equation for its motion:
    the compile names its node."""
    m = _series_chain([], (1.0,), 1.0)
    m.tip, m.push, m.k = tr.Mass(m=0.0), tr.Force(), TimeSignal(fn=lambda t: 1.0 + 0 * t)
    m.connect(m.k.y, m.push.f)
    m.connect(m.push.flange, m.tip.flange_a)
    with pytest.raises(acausal.SingularModelError) as err:
        acausal.compile(m)
    assert str(err.value).startswith("the massless node(s) tip.s: the forces on it depend "
                                     "neither on its position nor on its speed")


def test_negative_mass_is_a_parameter_error():
    with pytest.raises(ParameterError, match=r"Mass\.m.*>= 0"):
        tr.Mass(m=-1.0)
    m = acausal.Model("neg")
    m.src = tr.ConstantForce(f_constant=1.0)
    m.mass = tr.Mass()
    m.connect(m.src.flange, m.mass.flange_a)
    compiled = acausal.compile(m)
    with pytest.raises(ParameterError, match=r"mass\.m"):
        compiled.simulate(0.1, params={"mass.m": -2.0})


def test_unconnected_sensor_flange_and_support_are_errors():
    m = acausal.Model("loose")
    m.src = tr.ConstantForce(f_constant=1.0)
    m.mass = tr.Mass()
    m.sensor = tr.ForceSensor()
    m.connect(m.src.flange, m.mass.flange_a)
    m.connect(m.sensor.flange_a, m.mass.flange_b)
    with pytest.raises(StructureError, match=r"sensor\.flange_b"):
        acausal.compile(m)
    m = acausal.Model("nosupport")
    m.src = tr.ConstantForce(f_constant=1.0, useSupport=True)
    m.mass = tr.Mass()
    m.connect(m.src.flange, m.mass.flange_a)
    with pytest.raises(StructureError, match=r"src\.support"):
        acausal.compile(m)


def test_exact_position_from_a_model_input_is_refused():
    """exact=True needs the signal's derivatives; a model input has none: a clear error."""
    m = acausal.Model("inexact")
    m.sref = acausal.Input()
    m.position = tr.Position(exact=True)
    m.damper = tr.Damper(d=1.0)
    m.mass = tr.Mass()
    m.connect(m.sref.y, m.position.s_ref)
    m.connect(m.position.flange, m.damper.flange_a)
    m.connect(m.damper.flange_b, m.mass.flange_a)
    with pytest.raises(StructureError, match="exact=False"):
        acausal.compile(m)
