"""Constraints on velocities (PhysicsBuilder.velocity_constraint): a vertical disk on
ordinary joints held by MSL's RollingConstraintVerticalWheel rolls on a circle at constant
speeds (closed form), the dependent rates are eliminated from the states, bad rows are
refused with the component named."""
import numpy as np
import pytest

import acausal
from acausal.components.multibody import (Body, FixedTranslation, Prismatic, Revolute,
                                          RollingConstraintVerticalWheel, World)
from acausal.components.multibody.interfaces import Animated, Frame_a
from acausal.core import Model
from acausal.errors import StructureError

R, M, I_AXIS, I_LONG = 0.25, 1.5, 0.04, 0.03


def _vertical_disk(constraint=None):
    """World → prismatic x → prismatic y → revolute z (heading psi) → up by R → revolute
    y (spin theta) → the disk, with no slip at its contact point."""
    m = Model("disk")
    m.world = World(n=(0, 0, -1))
    m.px, m.py = Prismatic(n=(1, 0, 0)), Prismatic(n=(0, 1, 0))
    m.heading, m.spin = Revolute(n=(0, 0, 1)), Revolute(n=(0, 1, 0))
    m.up = FixedTranslation(r=(0, 0, R))
    m.disk = Body(m=M, r_CM=(0, 0, 0), I_11=I_LONG, I_22=I_AXIS, I_33=I_LONG)
    m.rolling = constraint or RollingConstraintVerticalWheel(radius=R)
    chain = [(m.world.frame_b, m.px.frame_a), (m.px.frame_b, m.py.frame_a),
             (m.py.frame_b, m.heading.frame_a), (m.heading.frame_b, m.up.frame_a),
             (m.up.frame_b, m.spin.frame_a), (m.spin.frame_b, m.disk.frame_a),
             (m.spin.frame_b, m.rolling.frame_a)]
    for a, b in chain:
        m.connect(a, b)
    return m


def test_a_vertical_disk_rolls_on_a_circle_at_constant_speeds():
    c = acausal.compile(_vertical_disk())
    # two rows: the rates of x and y follow from the heading's and the spin's
    assert c.x_names == ["px.s", "py.s", "heading.phi", "spin.phi", "heading.w", "spin.w"]
    w_psi, w_theta = 1.3, -4.0
    t = np.linspace(0, 5, 101)
    res = c.simulate(5.0, x0={"heading.w": w_psi, "spin.w": w_theta}, t=t, rtol=1e-11,
                     atol=1e-11)
    # the disk's axis is y turned by psi; no slip at the contact point −R e_z gives the
    # centre v = −ω × (−R e_z) = R·θ̇ along the heading (cos psi, sin psi): a circle of
    # radius R·θ̇/ψ̇
    v = R * w_theta
    psi = w_psi * t
    x = v / w_psi * np.sin(psi)
    y = v / w_psi * (1 - np.cos(psi))
    np.testing.assert_allclose(res["heading.w"], w_psi, atol=1e-9)
    np.testing.assert_allclose(res["spin.w"], w_theta, atol=1e-9)
    np.testing.assert_allclose(res["px.s"], x, atol=1e-8)
    np.testing.assert_allclose(res["py.s"], y, atol=1e-8)
    # the lateral force keeps the centre on its circle: m v²/ρ = m v ψ̇; no longitudinal one
    np.testing.assert_allclose(np.abs(res["rolling.f_lat"]), abs(M * v * w_psi), rtol=1e-8)
    np.testing.assert_allclose(res["rolling.f_long"], 0, atol=1e-8)


class _Squared(Animated):
    """A wrong row: the square of a velocity."""
    frame_a = Frame_a("")

    def physics(self, e):
        v = e.vel(self.frame_a)
        f = e.velocity_constraint("f", v[0] ** 2)
        e.flow(self.frame_a, f * np.array([1.0, 0, 0, 0, 0, 0]))


def test_a_row_not_linear_in_the_velocities_is_refused():
    with pytest.raises(StructureError, match="not linear in the velocities"):
        acausal.compile(_vertical_disk(_Squared()))
