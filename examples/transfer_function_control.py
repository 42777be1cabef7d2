"""A plant given as a transfer function under PI control (Modelica.Blocks.Continuous),
checked against scipy.signal.

Block diagram:

    setpoint (Step) --> Feedback.u1    Feedback.y --> PI --> Add.u1 --> plant (TransferFunction) --> y
    plant.y ----------> Feedback.u2                load (Step) --> Add.u2

The plant G(s) = 2 / (s + 1)^3 is MSL's TransferFunction(b={2}, a={1, 3, 3, 1}) (states in
MSL's scaled controller canonical form); the controller is Continuous.PI(k=0.8, T=1.6 s,
its integral starting at 0). A constant load of 0.25 acts at the plant's input from the
start, and the plant starts in steady state (``initType=SteadyState``: der(x) = 0 solved
with the loop closed, the PI's integral held at 0, which then integrates the load's
output); the setpoint steps to 1 at t = 1 s. The same loop is written by hand
as one state-space model (scipy.signal.tf2ss of the plant plus the PI's integral) and
simulated with scipy.signal.lsim from the steady state solved with numpy: the responses
agree to the integrators' tolerance. The plant's A matrix, linearized from the compiled
model, is tf2ss's controller canonical form.

Run ``python examples/transfer_function_control.py``: prints the comparison and saves
``transfer_function_control.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np
import scipy.signal as sig

import acausal
from acausal.analysis import linearize
from acausal.components.signals import PI, Add, Feedback, Step, TransferFunction

B_PLANT, A_PLANT = [2.0], [1.0, 3.0, 3.0, 1.0]       # G(s) = 2 / (s + 1)^3
K, TI, LOAD, T_STEP, T_END = 0.8, 1.6, 0.25, 1.0, 25.0


class ControlLoop(acausal.Model):
    """PI control of a third-order plant given by its transfer function."""

    def __init__(self, name=None):
        super().__init__(name)
        self.setpoint = Step(height=1.0, startTime=T_STEP)
        self.error = Feedback()
        self.pi = PI(k=K, T=TI)
        self.load = Step(height=LOAD)
        self.sum = Add()
        self.plant = TransferFunction(b=B_PLANT, a=A_PLANT, initType="SteadyState")
        for a, b in [(self.setpoint.y, self.error.u1), (self.plant.y, self.error.u2),
                     (self.error.y, self.pi.u), (self.pi.y, self.sum.u1),
                     (self.load.y, self.sum.u2), (self.sum.y, self.plant.u)]:
            self.connect(a, b)


def scipy_loop(t: np.ndarray) -> np.ndarray:
    """y of the same loop: plant (Ap, Bp, Cp) = tf2ss(b, a), PI integral xi with
    der(xi) = e/T, plant input k·(xi + e) + d, e = r − Cp·x; the start: xi = 0, der(x) = 0
    under r = 0 (the PI then integrates the load's output until the step)."""
    Ap, Bp, Cp, _ = sig.tf2ss(B_PLANT, A_PLANT)
    A = np.block([[Ap - K * Bp @ Cp, K * Bp], [-Cp / TI, np.zeros((1, 1))]])
    B = np.block([[K * Bp, Bp], [np.full((1, 1), 1 / TI), np.zeros((1, 1))]])  # inputs r, d
    C = np.hstack([Cp, np.zeros((1, 1))])
    x0 = np.append(np.linalg.solve(Ap - K * Bp @ Cp, -Bp[:, 0] * LOAD), 0.0)
    system = (A, B, C, np.zeros((1, 2)))

    def piece(r, times, x_start):        # constant inputs (r, LOAD): lsim is exact
        _, y, x = sig.lsim(system, np.tile([r, LOAD], (times.size, 1)), times - times[0],
                           X0=x_start)
        return y, x[-1]

    y_before, x_step = piece(0.0, np.append(t[t < T_STEP], T_STEP), x0)
    y_after, _ = piece(1.0, np.insert(t[t > T_STEP], 0, T_STEP), x_step)
    return np.concatenate([y_before[:-1], y_after])       # T_STEP is on the grid t


def main():
    model = acausal.compile(ControlLoop("loop"))
    print(f"states: {model.x_names}")
    t = np.linspace(0.0, T_END, 2501)
    # the steady state is solved for the plant's states with the PI's integral held at 0
    # (without it, the start values of all states are only the closest point to start from)
    res = model.simulate(T_END, t=t, x0={"pi.x": 0.0}, rtol=1e-10, atol=1e-12)
    y_ref = scipy_loop(t)
    err = np.max(np.abs(res["plant.y"] - y_ref))
    print(f"y(0) = {res['plant.y'][0]:.6f} (steady state under the load: "
          f"{2 * LOAD / (1 + 2 * K):.6f}); max |y - scipy|: {err:.2e}")
    assert err < 1e-7
    peak = np.argmax(res["plant.y"])
    print(f"overshoot {100 * (res['plant.y'][peak] - 1):.1f} % at t = {t[peak]:.2f} s, "
          f"y({T_END:g} s) = {res['plant.y'][-1]:.5f}")

    m = acausal.Model("open_loop")
    m.u, m.plant, m.y = acausal.Input(), TransferFunction(b=B_PLANT, a=A_PLANT), acausal.Output()
    m.connect(m.u.y, m.plant.u)
    m.connect(m.plant.y, m.y.u)
    lin = linearize(acausal.compile(m), {})
    print("plant A (linearized):\n", lin.A, "\nscipy tf2ss A:\n", sig.tf2ss(B_PLANT, A_PLANT)[0])

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(t, res["setpoint.y"], "k--", label="setpoint")
    ax.plot(t, res["plant.y"], label="plant.y (acausal)")
    ax.plot(t[::50], y_ref[::50], "o", mfc="none", label="scipy.signal.lsim")
    ax.plot(t, res["pi.y"], label="PI output")
    ax.set_xlabel("time [s]")
    ax.legend()
    ax.grid(True)
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "transfer_function_control.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
