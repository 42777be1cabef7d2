"""An OCP over a model with an index-1 algebraic variable: a mass pushed by a force F and
tied to the ground through a Maxwell element (spring c in series with a damper d; the
massless node between them has its velocity as an algebraic variable z).

Move the mass from rest at 0 to 1 m in 2 s with minimum ∫F² dt, by collocation and by
shooting (CasADi's Radau integrator). Reference independent of acausal: the optimal
piecewise-constant F replayed through scipy's solve_ivp of the hand ODE
    ẋ = v,  m v̇ = F − c (x − y),  d ẏ = c (x − y)
gives the optimized nodes (to 1e-6), and the recorded damper force at the nodes (which reads
the algebraic variable) equals c (x − y) there (1e-9).
"""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal
from acausal.components import translational as tr
from acausal.ocp import OCP, OCPError

M, C, D, T_FINAL, N = 1.0, 4.0, 0.5, 2.0, 20


class Maxwell(acausal.Model):
    def __init__(self, name="maxwell"):
        super().__init__(name)
        self.fixed = tr.Fixed()
        self.damper = tr.Damper(d=D)
        self.spring = tr.Spring(c=C)
        self.mass = tr.Mass(m=M)
        self.F = acausal.Input(unit="N")
        self.force = tr.Force()
        self.connect(self.fixed.flange, self.damper.flange_a)
        self.connect(self.damper.flange_b, self.spring.flange_a)
        self.connect(self.spring.flange_b, self.mass.flange_a)
        self.connect(self.F.y, self.force.f)
        self.connect(self.force.flange, self.mass.flange_b)


@pytest.fixture(scope="module")
def compiled():
    c = acausal.compile(Maxwell())
    assert c.z_names                       # the node's velocity is algebraic
    return c


@pytest.mark.parametrize("method", ["collocation", "shooting"])
def test_optimum_replays_through_the_hand_ode(compiled, method):
    ocp = OCP(compiled, N=N, T=T_FINAL, method=method)
    ocp.minimize(ocp.integral(lambda v: v["F"] ** 2))
    ocp.initial({"mass.s": 0.0, "mass.v": 0.0, "damper.flange_b.s": 0.0})
    ocp.final({"mass.s": 1.0, "mass.v": 0.0})
    sol = ocp.solve({"tol": 1e-10})
    x, y, v = sol["mass.s"], sol["damper.flange_b.s"], sol["mass.v"]
    F, t = sol.control("F"), sol.t
    state, replay = np.zeros(3), [np.zeros(3)]
    for k in range(N):
        r = solve_ivp(lambda _, s: [s[1], (F[k] - C * (s[0] - s[2])) / M, C * (s[0] - s[2]) / D],
                      (t[k], t[k + 1]), state, rtol=1e-12, atol=1e-12, method="DOP853")
        state = r.y[:, -1]
        replay.append(state)
    replay = np.array(replay).T
    np.testing.assert_allclose(x, replay[0], atol=1e-6)
    np.testing.assert_allclose(v, replay[1], atol=1e-6)
    np.testing.assert_allclose(y, replay[2], atol=1e-6)
    np.testing.assert_allclose(sol["damper.f"], C * (x - y), atol=1e-9)
    assert sol.cost == pytest.approx(T_FINAL / N * np.sum(F ** 2), rel=1e-10)


def test_dae_needs_a_dae_integrator():
    with pytest.raises(OCPError, match="integrator 'rk' does not solve DAEs.*'collocation'"):
        OCP(acausal.compile(Maxwell()), N=5, method="shooting", integrator="rk")
