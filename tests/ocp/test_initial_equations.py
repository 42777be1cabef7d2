"""The model's initial equations hold at an OCP's first node.

An inertia (J = 2 kg·m²) on a damper to the ground (d = 0.5 N·m·s/rad), driven by the
control τ; an InitializeFlange gives it the start speed w_start = 0.7 rad/s by an initial
equation (MSL's der(flange.phi) = w_start), and the OCP fixes only the angle. Brought to
rest at T = 2 s with minimum ∫τ² dt. Without the initial equation the optimum is to start
at rest and do nothing (cost 0); with it, the control must brake.

Reference independent of acausal: with τ held on each of the N intervals (h = T/N) the
speed follows w_{k+1} = α w_k + β τ_k exactly, α = exp(−d h / J), β = (1 − α)/d; the
least-norm controls reaching w_N = 0 are τ_k ∝ α^{N−1−k}, with cost
h (α^N w_0)² / (β² Σ_k α^{2(N−1−k)}) and τ_0 = −α^N w_0 α^{N−1} / (β Σ_k α^{2(N−1−k)}).
"""
import numpy as np
import pytest

import acausal
from acausal.components import rotational as rot
from acausal.components import signals as sg
from acausal.ocp import OCP

J, D, W_START, N, T = 2.0, 0.5, 0.7, 20, 2.0


class SpinningDown(acausal.Model):
    def __init__(self, name="spinning_down"):
        super().__init__(name)
        self.fixed = rot.Fixed()
        self.inertia = rot.Inertia(J=J)
        self.damper = rot.Damper(d=D)
        self.torque = rot.Torque()
        self.tau = acausal.Input(unit="N.m")
        self.init = rot.InitializeFlange(use_phi_start=False, use_a_start=False)
        self.w_start = sg.Constant(k=W_START)
        self.connect(self.tau.y, self.torque.tau)
        self.connect(self.torque.flange, self.inertia.flange_a)
        self.connect(self.damper.flange_a, self.fixed.flange)
        self.connect(self.damper.flange_b, self.inertia.flange_b)
        self.connect(self.init.flange, self.inertia.flange_b)
        self.connect(self.w_start.y, self.init.w_start)


def least_norm():
    """(cost, first control) of the exact zero-order-hold problem, in closed form."""
    h = T / N
    alpha = np.exp(-D * h / J)
    beta = (1.0 - alpha) / D
    powers = alpha ** (2 * np.arange(N - 1, -1, -1))
    free_end = alpha ** N * W_START
    cost = h * free_end ** 2 / (beta ** 2 * powers.sum())
    tau0 = -free_end * alpha ** (N - 1) / (beta * powers.sum())
    return cost, tau0


@pytest.mark.parametrize("method", ["collocation", "shooting"])
def test_the_initial_equation_fixes_the_start_speed(method):
    compiled = acausal.compile(SpinningDown())
    ocp = OCP(compiled, N=N, T=T, method=method)
    ocp.minimize(ocp.integral(lambda v: v["tau"] ** 2))
    ocp.initial({"inertia.phi": 0.0})
    ocp.final({"inertia.w": 0.0})
    sol = ocp.solve()
    cost, tau0 = least_norm()
    assert abs(sol["inertia.w"][0] - W_START) < 1e-9
    assert abs(sol.cost - cost) < 1e-7 * cost
    assert abs(sol.control("tau")[0] - tau0) < 1e-6 * abs(tau0)
