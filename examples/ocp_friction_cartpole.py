"""Swing-up of a cart-pole whose cart has Coulomb friction on its rail, through acausal.ocp.

Cart m1 = 1 kg with Coulomb friction f_c = 2 N (a translational SupportFriction: stuck and
sliding modes on state events in simulation), pole l = 1 m with m2 = 0.1 kg at its tip
(``acausal.models.cartpole.FrictionCartPole``); minimize ∫F² dt over T = 5 s on N = 30
intervals, |F| ≤ 30 N, from rest hanging down to rest upright.

The OCP cannot transcribe events: it compiles the model again in smooth form, the friction
f = f_c·tanh(v/v_smooth) (a SmoothFormWarning says so; here v_smooth = 1 cm/s, as the 0.17 s
mesh cannot resolve the 1 mm/s default), and solves that with IPOPT. The optimal force is
then replayed open loop on the exact model (events) over the first second, where it stays
within the smooth form's error bound ln 2·f_c/(|F(0)| − f_c)·v_smooth on the cart's speed;
over the whole horizon an open-loop replay leaves the unstable upright position, as it does
on the smooth model itself. Saves ``ocp_friction_cartpole.png`` (in $ACAUSAL_OUT, default
the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.models.cartpole import FrictionCartPole
from acausal.ocp import OCP
from acausal.simulation import Samples

F_C, V_SMOOTH = 2.0, 0.01           # N, m/s


def main():
    exact = acausal.compile(FrictionCartPole())
    ocp = OCP(exact, N=30, T=5.0, params={"friction.v_smooth": V_SMOOTH})
    ocp.minimize(ocp.integral(lambda v: v["F"] ** 2))
    ocp.bounds("F", -30.0, 30.0)
    ocp.initial({"rail.s": 0.0, "hinge.phi": 0.0, "rail.v": 0.0, "hinge.w": 0.0})
    ocp.final({"hinge.phi": np.pi, "rail.v": 0.0, "hinge.w": 0.0})
    sol = ocp.solve({"tol": 1e-10})
    print(ocp)
    print(sol, "regularized:", sol.regularized)
    print(f"tip height at T: {sol['tip.r[2]'][-1]:.6f} m, peak force "
          f"{np.abs(sol.control('F')).max():.2f} N")

    t = np.linspace(0.0, 1.0, 201)
    force = Samples(sol.t[:-1], sol.control("F"), "hold")
    runs = {}
    for name, model in (("exact", exact), ("smooth", ocp.model)):
        res = model.simulate(1.0, t=t, inputs={"F": force}, rtol=1e-10, atol=1e-12,
                             params={"friction.v_smooth": V_SMOOTH})
        runs[name] = res["rail.v"][np.searchsorted(res.t, t, side="right") - 1]
        if name == "exact":
            print("events of the exact model:", *res.events[:4], sep="\n  ")
    bound = np.log(2) * F_C / (abs(sol.control("F")[0]) - F_C) * V_SMOOTH
    print(f"first second, exact vs smooth cart speed: max |dv| = "
          f"{np.abs(runs['exact'] - runs['smooth']).max():.2e} m/s (bound {bound:.2e})")

    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "ocp_friction_cartpole.png")
    fig = sol.plot("rail.s", "hinge.phi", "rail.v", "friction.f", "F")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
