"""A 3-mass chain with springs, dampers and a force F(t) = sin(2t) on mass 3, compared with
the same system written by hand as a CasADi SX ODE and integrated with cvodes."""
import casadi as ca
import numpy as np
import pytest

import acausal
from acausal.components.translational import Damper, Fixed, Force, Mass, Spring

M = [1.0, 2.0, 0.5]          # kg
L = [0.1, 0.2, 0.3]          # m, mass lengths
C = [40.0, 25.0, 10.0]       # N/m
S0 = [0.5, 0.4, 0.6]         # m, unstretched lengths
D = [0.3, 0.1, 0.2]          # N.s/m
X0 = {"mass1.s": 0.62, "mass2.s": 1.25, "mass3.s": 2.1, "mass1.v": 0.0, "mass2.v": 0.3,
      "mass3.v": -0.2}


def chain_model():
    """wall | spring1 || damper1 | mass1 | spring2 || damper2 | mass2 | ... | mass3 <- F."""
    m = acausal.Model("chain3")
    m.wall = Fixed()
    left = m.wall.flange
    for i in range(3):
        spring = Spring(c=C[i], s_rel0=S0[i])
        damper = Damper(d=D[i])
        mass = Mass(m=M[i], L=L[i])
        setattr(m, f"spring{i + 1}", spring)
        setattr(m, f"damper{i + 1}", damper)
        setattr(m, f"mass{i + 1}", mass)
        m.connect(left, spring.flange_a)
        m.connect(left, damper.flange_a)
        m.connect(spring.flange_b, mass.flange_a)
        m.connect(damper.flange_b, mass.flange_a)
        left = mass.flange_b
    m.force = Force()
    m.F = acausal.Input()
    m.connect(m.F.y, m.force.f)
    m.connect(m.force.flange, m.mass3.flange_b)
    return m


def hand_model(grid, x0, rtol=1e-12, atol=1e-14):
    """Centre positions s_i, velocities v_i; spring/damper i joins flange_b of body i-1
    (the wall at 0 for i = 1) to flange_a of mass i; f_i is the force on its right end."""
    s = ca.SX.sym("s", 3)
    v = ca.SX.sym("v", 3)
    t = ca.SX.sym("t")
    left_pos = [0.0, s[0] + L[0] / 2, s[1] + L[1] / 2]
    left_vel = [0.0, v[0], v[1]]
    f = [C[i] * ((s[i] - L[i] / 2 - left_pos[i]) - S0[i]) + D[i] * (v[i] - left_vel[i])
         for i in range(3)]
    acc = [(-f[0] + f[1]) / M[0], (-f[1] + f[2]) / M[1], (-f[2] + ca.sin(2 * t)) / M[2]]
    dae = {"x": ca.vertcat(s, v), "t": t, "ode": ca.vertcat(v, *acc)}
    F = ca.integrator("hand", "cvodes", dae, grid[0], grid[1:], {"abstol": atol, "reltol": rtol})
    xf = np.array(F(x0=x0)["xf"])
    return np.hstack([np.reshape(x0, (-1, 1)), xf])


@pytest.fixture(scope="module")
def compiled():
    return acausal.compile(chain_model())


def test_chain_matches_hand_written_casadi(compiled):
    grid = np.linspace(0.0, 5.0, 251)
    res = compiled.simulate(5.0, t=grid, x0=X0, inputs={"F": lambda t: np.sin(2 * t)},
                            rtol=1e-10, atol=1e-12)
    x0 = [X0[f"mass{i}.s"] for i in (1, 2, 3)] + [X0[f"mass{i}.v"] for i in (1, 2, 3)]
    ref = hand_model(grid, x0)
    for i in range(3):
        np.testing.assert_allclose(res[f"mass{i + 1}.s"], ref[i], rtol=0, atol=1e-7)
        np.testing.assert_allclose(res[f"mass{i + 1}.v"], ref[3 + i], rtol=0, atol=1e-7)
    # the motion is not trivial: every mass moves by centimetres
    assert np.all(np.ptp(ref[:3], axis=1) > 1e-2)
    # spring forces and the wall's reaction from the hand model's positions and velocities
    s1, v1 = ref[0], ref[3]
    f_spring1 = C[0] * (s1 - L[0] / 2 - S0[0])
    f_damper1 = D[0] * v1
    np.testing.assert_allclose(res["spring1.f"], f_spring1, rtol=0, atol=1e-5)
    np.testing.assert_allclose(res["damper1.f"], f_damper1, rtol=0, atol=1e-6)
    # the wall holds spring1 and damper1: its cut force balances theirs (flows sum to zero)
    np.testing.assert_allclose(res["wall.flange.f"], f_spring1 + f_damper1, rtol=0, atol=1e-5)
    np.testing.assert_allclose(res["force.flange.f"], -np.sin(2 * grid), rtol=0, atol=1e-12)
