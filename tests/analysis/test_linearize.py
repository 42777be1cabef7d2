"""Linearization and modes (issue 4), against references that do not come from the code
under test:
- a 2-mass chain (springs k1, k2, damper d, force input): A, B, C, D equal to the matrices
  written here by hand, undamped eigenvalues to the closed-form roots of the characteristic
  quadratic, the static gain of python-control's export to 1/k1 + 1/k2;
- a planar pendulum with a hinge damper: eigenvalues to the closed form
  λ = (−d ± √(d² − 4 J m g l)) / (2J), J = I + m l²;
- A, B equal to central finite differences of the nonlinear model's Function ``f`` at a
  moving, non-equilibrium state (pendulum; four-bar reduced to an independent coordinate,
  the perturbed states put back on the loop by the simulation's assembly);
- a parallelogram four-bar (closed loop) hanging at rest: its frequency to the closed form
  ω² = g l Σ m·lever / J_red, and the mode shape in all three joint angles (1, −1, 1);
- modes of a 3-mass chain against scipy.linalg.eigh of K φ = ω² M φ with M, K built here,
  damped eigenvalues and damping ratios against numpy's eig of the hand-built state matrix.
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
import scipy.linalg

import acausal as ac
from acausal.analysis import AnalysisError, LinearModel, linearize, modes
from acausal.components import rotational as rot
from acausal.components import translational as tr
from acausal.components.planar import Body, Fixed, FixedTranslation, Revolute, World
from acausal.models.linkages import FourBar, Parallelogram
from acausal.simulation.initialization import initial_state

G = 9.81


def chain(masses, springs, damper=None, force_input=False):
    """Ground — k1 — m1 — k2 — m2 ... (translational); optional damper from the last mass to
    the ground and a force Input F on the last mass."""
    md = ac.Model("chain")
    md.fixed = tr.Fixed()
    prev = md.fixed.flange
    for i, (m, k) in enumerate(zip(masses, springs), 1):
        s, ms = tr.Spring(c=k), tr.Mass(m=m)
        setattr(md, f"s{i}", s)
        setattr(md, f"m{i}", ms)
        md.connect(prev, s.flange_a)
        md.connect(s.flange_b, ms.flange_a)
        prev = ms.flange_b
    last = getattr(md, f"m{len(masses)}")
    if damper is not None:
        md.d = tr.Damper(d=damper)
        md.connect(md.fixed.flange, md.d.flange_a)
        md.connect(md.d.flange_b, last.flange_a)
    if force_input:
        md.F, md.force = ac.Input(unit="N"), tr.Force()
        md.connect(md.F.y, md.force.f)
        md.connect(md.force.flange, last.flange_b)
    return ac.compile(md)


def hand_chain(masses, springs, damper=0.0):
    """M, K, C of the chain written by hand."""
    n = len(masses)
    M, K, C = np.diag(masses), np.zeros((n, n)), np.zeros((n, n))
    for i, k in enumerate(springs):
        K[i, i] += k
        if i > 0:
            K[i - 1, i - 1] += k
            K[i - 1, i] -= k
            K[i, i - 1] -= k
    C[-1, -1] = damper
    return M, K, C


M1, M2, K1, K2, D = 1.0, 2.0, 100.0, 50.0, 0.5


def test_two_mass_chain_matrices_and_closed_form():
    c = chain([M1, M2], [K1, K2], damper=D, force_input=True)
    lin = linearize(c, outputs=["m2.s", "s2.f"])
    M, K, C = hand_chain([M1, M2], [K1, K2], D)
    Mi = np.linalg.inv(M)
    assert lin.states == ["m1.s", "m2.s", "m1.v", "m2.v"] and lin.inputs == ["F"]
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-Mi @ K, -Mi @ C]])
    np.testing.assert_allclose(lin.A, A, atol=1e-12)
    np.testing.assert_allclose(lin.B, [[0], [0], [0], [1 / M2]], atol=1e-12)
    np.testing.assert_allclose(lin.C, [[0, 1, 0, 0], [-K2, K2, 0, 0]], atol=1e-12)
    np.testing.assert_allclose(lin.D, [[0], [0]], atol=1e-12)
    # undamped: m1 m2 ω⁴ − (m1 k2 + m2 (k1 + k2)) ω² + k1 k2 = 0
    c0 = chain([M1, M2], [K1, K2])
    a, b, cc = M1 * M2, -(M1 * K2 + M2 * (K1 + K2)), K1 * K2
    w2 = np.sort([(-b - math.sqrt(b * b - 4 * a * cc)) / (2 * a),
                  (-b + math.sqrt(b * b - 4 * a * cc)) / (2 * a)])
    ev = linearize(c0).eigenvalues()
    np.testing.assert_allclose(np.sort(ev.imag[ev.imag > 0]), np.sqrt(w2), rtol=1e-12)
    np.testing.assert_allclose(ev.real, 0.0, atol=1e-12)
    np.testing.assert_allclose(modes(c0).frequencies, np.sqrt(w2) / (2 * np.pi), rtol=1e-12)


def test_export_to_python_control():
    control = pytest.importorskip("control")
    c = chain([M1, M2], [K1, K2], damper=D, force_input=True)
    sys_ = linearize(c, outputs=["m2.s"]).to_control()
    assert isinstance(sys_, control.StateSpace)
    assert sys_.state_labels == ["m1_s", "m2_s", "m1_v", "m2_v"]
    # a static force F stretches both springs: m2.s = F (1/k1 + 1/k2)
    np.testing.assert_allclose(control.dcgain(sys_), 1 / K1 + 1 / K2, rtol=1e-12)


# ---- pendulum: a Body on a bar hinged at a fixed point, damper and torque in the hinge ----
PM, PL, PI, PD = 0.7, 0.4, 0.02, 0.15            # kg, m, kg.m², N.m.s/rad


def pendulum():
    md = ac.Model("pendulum")
    md.world, md.fixed = World(), Fixed()
    md.rev = Revolute(useFlange=True)
    md.bar, md.body = FixedTranslation(r=(PL, 0.0)), Body(m=PM, I=PI)
    md.damper, md.ground = rot.Damper(d=PD), rot.Fixed()
    md.T, md.torque = ac.Input(unit="N.m"), rot.Torque()
    md.connect(md.fixed.frame, md.rev.frame_a)
    md.connect(md.rev.frame_b, md.bar.frame_a)
    md.connect(md.bar.frame_b, md.body.frame_a)
    md.connect(md.rev.axis, md.damper.flange_b)
    md.connect(md.ground.flange, md.damper.flange_a)
    md.connect(md.T.y, md.torque.tau)
    md.connect(md.torque.flange, md.rev.axis)
    return ac.compile(md)


def test_pendulum_eigenvalues_closed_form():
    c = pendulum()
    lin = linearize(c, {"rev.phi": -math.pi / 2, "rev.w": 0.0}, outputs=["body.r[1]"])
    J = PI + PM * PL ** 2
    disc = np.sqrt(complex(PD ** 2 - 4 * J * PM * G * PL))
    ref = np.array([(-PD - disc) / (2 * J), (-PD + disc) / (2 * J)])
    np.testing.assert_allclose(np.sort_complex(lin.eigenvalues()), np.sort_complex(ref),
                               rtol=1e-12)
    np.testing.assert_allclose(lin.B, [[0], [1 / J]], rtol=1e-12)
    np.testing.assert_allclose(lin.C, [[PL, 0]], atol=1e-12)     # x = l cos φ at φ = −π/2
    m = modes(c, {"rev.phi": -math.pi / 2, "rev.w": 0.0})
    np.testing.assert_allclose(m.frequencies, [math.sqrt(PM * G * PL / J) / (2 * math.pi)],
                               rtol=1e-12)
    zeta = PD / (2 * math.sqrt(J * PM * G * PL))
    np.testing.assert_allclose(m.damping, [zeta], rtol=1e-12)


def fd_jacobians(c, x, u, p, z=None, t=0.0, h=1e-6):
    """Central differences of the model's f(x, u, p, z, t) -> xdot in x and u."""
    z = np.zeros(len(c.z_names)) if z is None else z

    def f(xx, uu):
        return np.array(c.f(x=xx, u=uu, p=p, z=z, t=t)["xdot"], dtype=float).ravel()
    A = np.column_stack([(f(x + h * e, u) - f(x - h * e, u)) / (2 * h) for e in np.eye(len(x))])
    B = np.column_stack([(f(x, u + h * e) - f(x, u - h * e)) / (2 * h) for e in np.eye(len(u))])
    return A, B


def test_pendulum_A_B_equal_finite_differences_off_equilibrium():
    c = pendulum()
    x = {"rev.phi": 0.3, "rev.w": -1.2}
    lin = linearize(c, x, u={"T": 0.4})
    p = c.param_vector()
    A, B = fd_jacobians(c, np.array([0.3, -1.2]), np.array([0.4]), p)
    np.testing.assert_allclose(lin.A, A, rtol=1e-8, atol=1e-8)
    np.testing.assert_allclose(lin.B, B, rtol=1e-8, atol=1e-8)


def test_four_bar_reduced_A_equals_finite_differences_on_the_loop():
    """A moving four-bar (crank 1 rad, 2 rad/s): the reduced A against differences of f with
    each perturbed independent state put back on the loop (positions and velocities) by the
    simulation's assembly, the others re-solved there."""
    c = ac.compile(FourBar())
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        lin = linearize(c, {"rev1.phi": 1.0, "rev1.w": 2.0}, independent=["rev1.phi"])
        assert lin.states == ["rev1.phi", "rev1.w"]
        p, u = c.param_vector(), np.zeros(0)
        x_op, _ = initial_state(c, {"rev1.phi": 1.0, "rev1.w": 2.0}, p, u, 0.0)
        guess = dict(zip(c.x_names, x_op))
        h = 1e-6

        def xdot(phi, w):
            x, z = initial_state(c, {"rev1.phi": phi, "rev1.w": w}, p, u, 0.0, guess)
            xd = np.array(c.f(x=x, u=u, p=p, z=z, t=0.0)["xdot"], dtype=float).ravel()
            return xd[[c.x_names.index("rev1.phi"), c.x_names.index("rev1.w")]]
        A = np.column_stack([(xdot(1.0 + h, 2.0) - xdot(1.0 - h, 2.0)) / (2 * h),
                             (xdot(1.0, 2.0 + h) - xdot(1.0, 2.0 - h)) / (2 * h)])
    np.testing.assert_allclose(lin.A, A, rtol=1e-7, atol=1e-7)
    # the dependent coordinates follow the null space of Φ_q: Φ_q · q_basis = 0
    assert lin.q_names == ["rev1.phi", "rev2.phi", "rev3.phi"]
    q = x_op[[c.x_names.index(n) for n in lin.q_names]]
    phi_q = np.array(c.lagrange.function("phi_q")(0.0, q, 0, u, p), dtype=float)
    np.testing.assert_allclose(phi_q @ lin.q_basis, 0.0, atol=1e-12)
    assert lin.q_basis[0, 0] == 1.0


def parallelogram(m1=1.0, m2=2.0, m3=1.5, l1=0.5, l0=1.0):
    return ac.compile(Parallelogram(ground=l0, crank=l1, masses=(m1, m2, m3)))


def test_parallelogram_hanging_frequency_closed_form():
    m1, m2, m3, l1 = 1.0, 2.0, 1.5, 0.5
    c = parallelogram(m1, m2, m3, l1)
    at = {"rev1.phi": -math.pi / 2, "rev1.w": 0.0}
    guess = {"rev2.phi": math.pi / 2, "rev3.phi": -math.pi / 2}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        m = modes(c, at, guess=guess)
    # crank and rocker turn about their pivots (J = m l²/3), the coupler translates
    J = (m1 + m3) * l1 ** 2 / 3 + m2 * l1 ** 2
    w = math.sqrt(G * l1 * (m1 / 2 + m3 / 2 + m2) / J)
    np.testing.assert_allclose(m.frequencies, [w / (2 * math.pi)], rtol=1e-12)
    np.testing.assert_allclose(m.shapes[:, 0], [1.0, -1.0, 1.0], atol=1e-12)
    np.testing.assert_allclose(m.eigenvalues, [1j * w], rtol=1e-12, atol=1e-12)


def test_three_mass_chain_modes_against_eigh():
    masses, springs, d = [1.0, 2.0, 0.5], [300.0, 100.0, 200.0], 0.8
    c = chain(masses, springs, damper=d)
    m = modes(c)
    M, K, C = hand_chain(masses, springs, d)
    w2, phi = scipy.linalg.eigh(K, M)
    np.testing.assert_allclose(m.frequencies, np.sqrt(w2) / (2 * np.pi), rtol=1e-12)
    assert m.coordinates == ["m1.s", "m2.s", "m3.s"]
    phi = phi / phi[np.argmax(np.abs(phi), axis=0), range(3)]
    np.testing.assert_allclose(m.shapes, phi, atol=1e-10)
    A = np.block([[np.zeros((3, 3)), np.eye(3)],
                  [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
    ev = np.linalg.eigvals(A)
    ev = ev[ev.imag > 0]
    ev = ev[np.argsort(np.abs(ev))]
    np.testing.assert_allclose(m.eigenvalues, ev, rtol=1e-10)
    np.testing.assert_allclose(m.damping, -ev.real / np.abs(ev), rtol=1e-10)
    np.testing.assert_allclose(m.damped_frequencies, ev.imag / (2 * np.pi), rtol=1e-10)


def test_linearize_names_unknown_input_and_output():
    c = chain([M1, M2], [K1, K2], force_input=True)
    with pytest.raises(AnalysisError, match="no input 'G'"):
        linearize(c, inputs=["G"])
    with pytest.raises(AnalysisError, match="m2.ss"):
        linearize(c, outputs=["m2.ss"])
    assert isinstance(linearize(c, inputs=[]), LinearModel)


def test_linearize_refuses_values_that_are_no_finite_numbers():
    c = chain([M1, M2], [K1, K2], force_input=True)
    u = c.input_names[0]
    with pytest.raises(AnalysisError, match=r"x\['m1.s'\] must be a finite number"):
        linearize(c, {"m1.s": "a"})
    with pytest.raises(AnalysisError, match="x must be values by variable name"):
        linearize(c, [0.0, 0.0])
    with pytest.raises(AnalysisError, match=rf"u\['{u}'\] must be a finite number"):
        linearize(c, u={u: math.nan})
    with pytest.raises(AnalysisError, match="t must be a finite time"):
        linearize(c, t=math.nan)
