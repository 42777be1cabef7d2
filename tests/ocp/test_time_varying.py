"""A time-varying model and a horizon not starting at 0: a mass pushed by a known force
2 sin(2π t) [N] (a signals.Sine) plus the control F, moved from rest at 0 to rest at 1 m on
[0.5, 2.5] s with minimum ∫F² dt. Reference independent of acausal: the optimal
piecewise-constant F replayed through scipy's solve_ivp of s̈ = F + 2 sin(2π t) reaches the
target (to 1e-6, the transcriptions' error); collocation and shooting agree (1e-6)."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.components import signals as sg
from acausal.components import translational as tr
from acausal.ocp import OCP

N, T0, T = 20, 0.5, 2.0


class ForcedMass(acausal.Model):
    def __init__(self, name="forced_mass"):
        super().__init__(name)
        self.mass = tr.Mass(m=1.0)
        self.F = acausal.Input(unit="N")
        self.sine = sg.Sine(amplitude=2.0, f=1.0)
        self.add = sg.Add()
        self.force = tr.Force()
        self.connect(self.sine.y, self.add.u1)
        self.connect(self.F.y, self.add.u2)
        self.connect(self.add.y, self.force.f)
        self.connect(self.force.flange, self.mass.flange_a)


@pytest.fixture(scope="module")
def solutions():
    compiled = acausal.compile(ForcedMass())
    out = {}
    for method in ("collocation", "shooting"):
        ocp = OCP(compiled, N=N, T=T, t0=T0, method=method)
        ocp.minimize(ocp.integral(lambda v: v["F"] ** 2))
        ocp.initial({"mass.s": 0.0, "mass.v": 0.0})
        ocp.final({"mass.s": 1.0, "mass.v": 0.0})
        out[method] = ocp.solve({"tol": 1e-12})
    return out


@pytest.mark.parametrize("method", ["collocation", "shooting"])
def test_replay_reaches_the_target(solutions, method):
    sol = solutions[method]
    np.testing.assert_allclose(sol.t, np.linspace(T0, T0 + T, N + 1), atol=1e-14)
    F, y = sol.control("F"), np.zeros(2)
    for k in range(N):
        y = solve_ivp(lambda t, s: [s[1], F[k] + 2.0 * np.sin(2 * np.pi * t)],
                      (sol.t[k], sol.t[k + 1]), y, rtol=1e-12, atol=1e-12).y[:, -1]
    np.testing.assert_allclose(y, [1.0, 0.0], atol=1e-6)


def test_methods_agree(solutions):
    assert solutions["shooting"].cost == pytest.approx(solutions["collocation"].cost, rel=1e-6)
