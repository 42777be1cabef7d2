"""The integrator simulate() chooses, judged on the spectral radius against the time span,
and the start checked before integrating. References: modal closed forms (numpy eigen-
decomposition of a linear system written here), and the exact error expected."""
from __future__ import annotations

import numpy as np
import pytest

import acausal as ac
from acausal.components import planar as pl
from acausal.components import translational as tr


def chain(masses, stiffnesses):
    """wall | spring c1 | mass m1 | spring c2 | mass m2 ..."""
    m = ac.Model("chain")
    m.wall = tr.Fixed()
    prev = m.wall.flange
    for i, (mi, ci) in enumerate(zip(masses, stiffnesses), 1):
        setattr(m, f"spring{i}", tr.Spring(c=ci))
        setattr(m, f"mass{i}", tr.Mass(m=mi))
        m.connect(prev, getattr(m, f"spring{i}").flange_a)
        m.connect(getattr(m, f"spring{i}").flange_b, getattr(m, f"mass{i}").flange_a)
        prev = getattr(m, f"mass{i}").flange_b
    return m


def modal(masses, stiffnesses, s0, t):
    """Positions of the undamped chain released from rest at s0: s(t) = Σ modes cos(ω t)."""
    n = len(masses)
    K = np.zeros((n, n))
    for i, c in enumerate(stiffnesses):
        K[i, i] += c
        if i > 0:
            K[i - 1, i - 1] += c
            K[i - 1, i] -= c
            K[i, i - 1] -= c
    Mh = np.diag(1 / np.sqrt(masses))
    w2, V = np.linalg.eigh(Mh @ K @ Mh)
    modes = Mh @ V
    a = np.linalg.solve(modes, s0)
    return (modes * a) @ np.cos(np.outer(np.sqrt(w2), t))


def test_undamped_stiff_chain_gets_bdf():
    """c = 1e9 N/m on m = 1e-3 kg (ω = 1e6 rad/s) next to c = 1, m = 1: no damping, yet far
    too stiff for Adams over 10 s (it took 73 s): BDF is chosen, and matches the modes."""
    masses, cs = [1e-3, 1.0], [1e9, 1.0]
    t = np.linspace(0.0, 10.0, 101)
    s0 = np.array([0.5 * cs[1] / (cs[0] + cs[1]), 0.5])     # mass1 balanced: fast mode at rest
    res = ac.compile(chain(masses, cs)).simulate(
        10.0, t=t, x0={"mass1.s": s0[0], "mass2.s": s0[1], "mass1.v": 0.0, "mass2.v": 0.0})
    assert res.solver == "cvodes"
    np.testing.assert_allclose(res["mass2.s"], modal(masses, cs, s0, t)[1], atol=1e-6)


def test_long_soft_chain_keeps_adams():
    """500 masses of 1 kg on springs of 100 N/m: ρ ≈ 20 rad/s, not stiff over 10 s, whatever
    the size (models above 400 states used to be taken as stiff)."""
    n = 500
    res = ac.compile(chain([1.0] * n, [100.0] * n)).simulate(
        10.0, t=np.linspace(0, 10, 11), x0={f"mass{n}.s": 0.01})
    assert res.solver == "adams"
    s0 = np.zeros(n)
    s0[-1] = 0.01
    np.testing.assert_allclose(res[f"mass{n}.s"], modal([1.0] * n, [100.0] * n, s0,
                                                       np.linspace(0, 10, 11))[-1], atol=1e-7)


def test_singular_mass_matrix_is_named():
    """A free Body with zero inertia, pulled off its centre: its rotation has no inertia. The
    error names the coordinate, not a LinAlgError."""
    m = ac.Model("spinning")
    m.world = pl.World(g=0.0)
    m.body = pl.Body(m=1.0, I=0.0)
    m.arm = pl.FixedTranslation(r=(0.5, 0.0))
    m.push = pl.WorldForce()
    m.F = ac.Output()
    m.fy = ac.Input(start=1.0)
    m.fx = ac.Input(start=0.0)
    m.torque = ac.Input(start=0.0)
    m.connect(m.body.frame_a, m.arm.frame_a)
    m.connect(m.arm.frame_b, m.push.frame_b)
    for i, src in enumerate((m.fx, m.fy), 1):
        m.connect(src.y, m.push.force[i])
    m.connect(m.torque.y, m.push.torque)
    m.connect(m.fy.y, m.F.u)
    with pytest.raises(ac.SimulationError, match=r"mass matrix is singular.*body\.phi"):
        ac.compile(m).simulate(1.0)
