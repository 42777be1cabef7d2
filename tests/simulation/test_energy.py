"""Energy conservation of an undamped chain of masses between two fixed walls."""
import numpy as np

import acausal
from acausal.components.translational import Fixed, Mass, Spring

N = 4
M = [1.0, 0.5, 2.0, 1.5]               # kg
L = [0.1, 0.2, 0.0, 0.3]               # m
C = [30.0, 10.0, 50.0, 20.0, 15.0]     # N/m, N + 1 springs
S0 = [0.4, 0.6, 0.5, 0.3, 0.7]         # m
WALL = 3.2                             # m, position of the right wall


def chain_between_walls():
    m = acausal.Model("walls")
    m.left = Fixed()
    m.right = Fixed(s0=WALL)
    prev = m.left.flange
    for i in range(N):
        spring, mass = Spring(c=C[i], s_rel0=S0[i]), Mass(m=M[i], L=L[i])
        setattr(m, f"spring{i}", spring)
        setattr(m, f"mass{i}", mass)
        m.connect(prev, spring.flange_a)
        m.connect(spring.flange_b, mass.flange_a)
        prev = mass.flange_b
    m.spring_end = Spring(c=C[N], s_rel0=S0[N])
    m.connect(prev, m.spring_end.flange_a)
    m.connect(m.spring_end.flange_b, m.right.flange)
    return m


def energy(res):
    """T + V [J] from the centre positions and velocities only (walls at 0 and WALL)."""
    s = [res[f"mass{i}.s"] for i in range(N)]
    v = [res[f"mass{i}.v"] for i in range(N)]
    ends = [0.0] + [s[i] + L[i] / 2 for i in range(N)]          # right end of the left body
    starts = [s[i] - L[i] / 2 for i in range(N)] + [WALL]        # left end of the right body
    T = sum(0.5 * M[i] * v[i] ** 2 for i in range(N))
    V = sum(0.5 * C[k] * (starts[k] - ends[k] - S0[k]) ** 2 for k in range(N + 1))
    return T + V


def test_energy_is_conserved():
    compiled = acausal.compile(chain_between_walls())
    x0 = {"mass0.s": 0.55, "mass1.s": 1.3, "mass2.s": 1.7, "mass3.s": 2.5, "mass1.v": 0.4,
          "mass3.v": -0.3}
    # BDF is slightly dissipative: the drift shrinks with the tolerance (2e-9 at rtol 1e-12)
    res = compiled.simulate(5.0, t=np.linspace(0, 5.0, 501), x0=x0, rtol=1e-12, atol=1e-14)
    E = energy(res)
    assert E[0] > 1.0                                    # a real amount of energy moves around
    kinetic = sum(0.5 * M[i] * res[f"mass{i}.v"] ** 2 for i in range(N))
    assert np.ptp(kinetic) > 0.5 * E[0]                  # ...between kinetic and potential
    assert np.max(np.abs(E - E[0])) / E[0] < 1e-7


def test_spring_forces_match_positions():
    """The recorded spring forces are c·(s_rel − s_rel0) of the recorded positions."""
    compiled = acausal.compile(chain_between_walls())
    res = compiled.simulate(1.0, x0={"mass0.s": 0.5, "mass2.v": 1.0})
    for i in range(N):
        left = 0.0 if i == 0 else res[f"mass{i - 1}.s"] + L[i - 1] / 2
        s_rel = res[f"mass{i}.s"] - L[i] / 2 - left
        np.testing.assert_allclose(res[f"spring{i}.s_rel"], s_rel, atol=1e-12)
        np.testing.assert_allclose(res[f"spring{i}.f"], C[i] * (s_rel - S0[i]), atol=1e-10)
