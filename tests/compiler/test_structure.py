"""Structural checks of the compiler with clear errors, the choice of coordinates, and the
mass matrix of the equations of motion."""
import casadi as ca
import numpy as np
import pytest

import acausal
from acausal.core import Component, Parameter, TranslationalFlange
from acausal.components.translational import Fixed, Force, Mass, Spring


class Rod(Component):
    """A rigid massless rod: flange_b.s − flange_a.s = L (a test component)."""
    L = Parameter(0.5, "m", "length of the rod")
    flange_a = TranslationalFlange("left flange")
    flange_b = TranslationalFlange("right flange")

    def structure(self, s):
        s.linear({self.flange_b: 1.0, self.flange_a: -1.0}, self.L)


def oscillator():
    m = acausal.Model("osc")
    m.wall, m.spring, m.mass = Fixed(), Spring(c=4.0), Mass(m=1.0)
    m.connect(m.wall.flange, m.spring.flange_a)
    m.connect(m.spring.flange_b, m.mass.flange_a)
    return m


# ---- errors -----------------------------------------------------------------------------
def test_unconnected_real_input():
    m = acausal.Model("m")
    m.mass, m.push = Mass(), Force()
    m.connect(m.push.flange, m.mass.flange_b)
    with pytest.raises(acausal.StructureError, match=r"'push\.f'"):
        acausal.compile(m)


def test_unknown_parameter_at_simulation():
    c = acausal.compile(oscillator())
    with pytest.raises(acausal.ParameterError) as err:
        c.simulate(1.0, params={"spring.cc": 3.0})
    assert "spring.cc" in str(err.value) and "'spring.c'" in str(err.value)


@pytest.mark.parametrize("value", [0.0, -2.0])
def test_non_positive_mass_at_simulation(value):
    c = acausal.compile(oscillator())
    with pytest.raises(acausal.ParameterError, match=r"mass\.m.*> 0"):
        c.simulate(1.0, params={"mass.m": value})


def test_model_without_dynamics():
    m = acausal.Model("static")
    m.left, m.right, m.spring = Fixed(), Fixed(s0=1.0), Spring()
    m.connect(m.left.flange, m.spring.flange_a)
    m.connect(m.spring.flange_b, m.right.flange)
    with pytest.raises(acausal.StructureError, match="no dynamics"):
        acausal.compile(m)


def test_empty_model():
    with pytest.raises(acausal.StructureError, match="no dynamics"):
        acausal.compile(acausal.Model("empty"))


def _walls_joined_by_rod(rod_length, with_oscillator):
    m = acausal.Model("loop")
    m.left, m.right, m.rod = Fixed(s0=0.0), Fixed(s0=1.0), Rod(L=rod_length)
    m.connect(m.left.flange, m.rod.flange_a)
    m.connect(m.rod.flange_b, m.right.flange)
    if with_oscillator:
        m.spring, m.mass = Spring(c=4.0), Mass()
        m.connect(m.left.flange, m.spring.flange_a)
        m.connect(m.spring.flange_b, m.mass.flange_a)
    return m


@pytest.mark.parametrize("with_oscillator", [False, True])
def test_inconsistent_rigid_loop(with_oscillator):
    """Walls at 0 and 1 joined by a rod of length 0.5 (beside a moving part or alone): the
    error names the rod and the walls it joins."""
    with pytest.raises(acausal.StructureError) as err:
        acausal.compile(_walls_joined_by_rod(0.5, with_oscillator))
    msg = str(err.value)
    assert "'rod'" in msg and "left" in msg and "right" in msg


def test_redundant_rigid_loop():
    """Walls at 0 and 1 joined by a rod of length 1: consistent but redundant (the rod's force
    is statically indeterminate). Reported by name and handled: the constraint is dropped with
    a warning, and the oscillator beside it moves as its closed form says."""
    with pytest.warns(UserWarning, match=r"redundant.*rod"):
        c = acausal.compile(_walls_joined_by_rod(1.0, True))
    mob = c.mobility()
    assert mob.redundant == ["rod"] and mob.dof == 1
    t = np.linspace(0.0, 2.0, 41)
    res = c.simulate(2.0, t=t, x0={"mass.s": 0.1})
    np.testing.assert_allclose(res["mass.s"], 0.1 * np.cos(2.0 * t), atol=1e-6)
    np.testing.assert_allclose(res["right.flange.s"], 1.0, atol=1e-14)


def test_x0_conflict_between_rigidly_joined_masses():
    m = acausal.Model("pair")
    m.m1, m.m2 = Mass(m=1.0, L=0.2), Mass(m=2.0, L=0.4)
    m.connect(m.m1.flange_b, m.m2.flange_a)
    c = acausal.compile(m)
    with pytest.raises(acausal.InitializationError) as err:
        c.simulate(1.0, x0={"m1.s": 0.0, "m2.s": 1.0})
    assert "m1.s" in str(err.value) and "m2.s" in str(err.value)
    # consistent values are accepted: m2.s = m1.s + 0.1 + 0.2
    res = c.simulate(1.0, x0={"m1.s": 0.0, "m2.s": 0.3, "m2.v": 0.5})
    np.testing.assert_allclose(res["m1.s"], 0.5 * res.t, atol=1e-9)
    np.testing.assert_allclose(res["m2.s"], 0.3 + 0.5 * res.t, atol=1e-9)


# ---- coordinates ---------------------------------------------------------------------------
def test_coordinate_is_mass_centre():
    c = acausal.compile(oscillator())
    assert c.coordinates == ["mass.s"]
    assert c.x_names == ["mass.s", "mass.v"]


def test_rigidly_joined_masses_share_a_coordinate():
    m = acausal.Model("pair")
    m.wall, m.spring = Fixed(), Spring(c=9.0)
    m.m1, m.m2 = Mass(m=1.0, L=0.2), Mass(m=2.0, L=0.4)
    m.connect(m.wall.flange, m.spring.flange_a)
    m.connect(m.spring.flange_b, m.m1.flange_a)
    m.connect(m.m1.flange_b, m.m2.flange_a)
    c = acausal.compile(m)
    assert len(c.coordinates) == 1 and c.coordinates[0] in ("m1.s", "m2.s")
    assert len(c.x_names) == 2
    # they move as one body of 3 kg on a 9 N/m spring: omega = sqrt(3)
    t = np.linspace(0, 2.0, 101)
    res = c.simulate(2.0, t=t, x0={"m1.s": 0.2})       # spring stretched by 0.1
    np.testing.assert_allclose(res["m1.s"], 0.1 + 0.1 * np.cos(np.sqrt(3.0) * t), atol=1e-6)
    np.testing.assert_allclose(res["m2.s"], res["m1.s"] + 0.3, atol=1e-12)


def test_chain_coordinates_in_order():
    m = acausal.Model("chain")
    m.wall = Fixed()
    prev = m.wall.flange
    for i in range(3):
        setattr(m, f"spring{i}", Spring())
        setattr(m, f"mass{i}", Mass())
        m.connect(prev, getattr(m, f"spring{i}").flange_a)
        m.connect(getattr(m, f"spring{i}").flange_b, getattr(m, f"mass{i}").flange_a)
        prev = getattr(m, f"mass{i}").flange_b
    c = acausal.compile(m)
    assert c.coordinates == ["mass0.s", "mass1.s", "mass2.s"]


# ---- equations -----------------------------------------------------------------------------
def test_mass_matrix_of_two_mass_chain():
    m = acausal.Model("two")
    m.wall, m.s1, m.m1, m.s2, m.m2 = Fixed(), Spring(c=3.0), Mass(m=1.5), Spring(c=5.0), Mass(m=4.0)
    m.connect(m.wall.flange, m.s1.flange_a)
    m.connect(m.s1.flange_b, m.m1.flange_a)
    m.connect(m.m1.flange_b, m.s2.flange_a)
    m.connect(m.s2.flange_b, m.m2.flange_a)
    c = acausal.compile(m)
    eq = c.lagrange
    assert eq.q_names == ["m1.s", "m2.s"]
    Mfun = ca.Function("M", [eq.q, eq.p], [eq.M])
    R0fun = ca.Function("R0", [eq.q, eq.qd, eq.p], [eq.R0])
    p = c.param_vector()
    q, qd = np.array([0.3, -0.2]), np.array([1.0, 2.0])
    np.testing.assert_allclose(np.array(Mfun(q, p)), np.diag([1.5, 4.0]), atol=1e-14)
    p2 = c.param_vector({"m1.m": 2.5, "m2.m": 0.5})
    np.testing.assert_allclose(np.array(Mfun(q, p2)), np.diag([2.5, 0.5]), atol=1e-14)
    # R0 = K q for this linear chain (no offsets): K = [[c1 + c2, −c2], [−c2, c2]]
    K = np.array([[8.0, -5.0], [-5.0, 5.0]])
    np.testing.assert_allclose(np.array(R0fun(q, qd, p)).ravel(), K @ q, atol=1e-14)


def test_fully_driven_pendulum_has_no_states_but_its_drive_torque():
    """Every coordinate prescribed (Position on the hinge): no states; "simulating" evaluates
    the motion, and the drive torque is m L² φ̈ + m g L cos φ (bar along x at φ = 0)."""
    from acausal.components import planar as pl, rotational as rot, signals as sig
    m = acausal.Model("driven")
    m.world, m.fixed = pl.World(), pl.Fixed()
    m.rev, m.bar = pl.Revolute(useFlange=True), pl.FixedTranslation(r=(1.5, 0.0))
    m.body, m.pos = pl.Body(m=2.0, I=0.0), rot.Position(exact=True)
    m.ref = sig.Sine(amplitude=0.5, f=1.0)
    for a, b in [(m.fixed.frame, m.rev.frame_a), (m.rev.frame_b, m.bar.frame_a),
                 (m.bar.frame_b, m.body.frame_a), (m.ref.y, m.pos.phi_ref),
                 (m.pos.flange, m.rev.axis)]:
        m.connect(a, b)
    c = acausal.compile(m)
    assert c.x_names == [] and c.z_names == []
    t = np.linspace(0.0, 1.0, 21)
    res = c.simulate(1.0, t=t)
    w = 2 * np.pi
    phi, acc = 0.5 * np.sin(w * t), -0.5 * w * w * np.sin(w * t)
    tau = 2.0 * 1.5 ** 2 * acc + 2.0 * 9.81 * 1.5 * np.cos(phi)
    np.testing.assert_allclose(-res["pos.flange.tau"], tau, atol=1e-10)
    np.testing.assert_allclose(res["body.frame_a.y"], 1.5 * np.sin(phi), atol=1e-12)
