"""Slider-crank under gravity, undamped: a closed loop with a prismatic joint.

The crank O–A turns about O = (0, 0) (rev1), the connecting rod A–B hangs on the crank (rev2)
and its end B is pinned (rev3) to a slider that runs on a horizontal Prismatic along x, a
distance H below O. Crank and rod are bars (FixedTranslation) with a Body at their middle.
Mobility (Gruebler): 3 moving bodies · 3 − 4 joints · 2 = 1 degree of freedom.

    World   O: Fixed ── rev1 ── crank ── rev2 ── rod ── rev3 ──┐
            track: Fixed(0, −H) ── prismatic ───────── slider: Body

The compiler reaches the slider through the crank and rod first, so the tree coordinates are
rev1.phi, rev2.phi, rev3.phi and the prismatic joint closes the loop: its constraint rows are
the slider's distance from the track and its angle. The script fixes the crank angle and speed
at t = 0, lets assembly find the rod and slider, simulates 10 s and reports the constraint
residual (every joint relation, from the recorded frame poses) and the energy T + V computed
from the bodies' motion. It saves ``slider_crank.png`` (in
$ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components.planar import Body, Fixed, Prismatic, Revolute, World
from acausal.components.rotational import Torque
from four_bar import add_link, energy, simulate_assembled      # the shared linkage pieces

R, L, H = 0.2, 0.6, 0.05                     # m: crank, rod, offset of the slider's track
M_CRANK, M_ROD, M_SLIDER = 0.4, 0.6, 1.0     # kg
I_SLIDER = 0.01                              # kg.m² (the slider does not turn)


class SliderCrank(acausal.Model):
    """Crank, connecting rod (slender rods, I = m L²/12) and a slider on a horizontal track;
    ``driven``: a Torque source on the crank's flange from the model Input ``tau`` [N.m]."""

    def __init__(self, name="slider_crank", driven: bool = False):
        super().__init__(name)
        self.world = World()
        self.O, self.track = Fixed(), Fixed(r=(0.0, -H))
        self.rev1, self.rev2, self.rev3 = Revolute(useFlange=driven), Revolute(), Revolute()
        if driven:
            self.tau = acausal.Input(unit="N.m", description="torque driving the crank")
            self.motor = Torque()
            self.connect(self.tau.y, self.motor.tau)
            self.connect(self.motor.flange, self.rev1.flange_a)
        self.prismatic = Prismatic(r=(1.0, 0.0))
        self.slider = Body(m=M_SLIDER, I=I_SLIDER)
        self.connect(self.O.frame, self.rev1.frame_a)
        A = add_link(self, "crank", R, M_CRANK, self.rev1.frame_b)
        self.connect(A, self.rev2.frame_a)
        B = add_link(self, "rod", L, M_ROD, self.rev2.frame_b)
        self.connect(B, self.rev3.frame_a)
        self.connect(self.track.frame, self.prismatic.frame_a)
        self.connect(self.prismatic.frame_b, self.slider.frame_a)
        self.connect(self.rev3.frame_b, self.slider.frame_a)


BODIES = {"crank": (M_CRANK, M_CRANK * R ** 2 / 12), "rod": (M_ROD, M_ROD * L ** 2 / 12),
          "slider": (M_SLIDER, I_SLIDER)}


def main():
    res, seconds = simulate_assembled(SliderCrank(), {"rev1.phi": 0.5, "rev1.w": 3.0})
    gap = np.hypot(res["rev3.frame_a.x"] - res["rev3.frame_b.x"],
                   res["rev3.frame_a.y"] - res["rev3.frame_b.y"])
    off_track = np.abs(res["slider.r[2]"] + H)          # the prismatic's rows: off the track,
    turned = np.abs(res["slider.phi"])                  # and turned
    T, V = energy(res, BODIES)
    E = T + V
    print(f"simulated 10 s in {seconds:.3f} s; mobility at t = 0: {res.mobility}")
    print(f"crank: {res['rev1.phi'][0]:.3f} rad -> {res['rev1.phi'][-1]:.3f} rad; slider "
          f"stroke {res['prismatic.s'].min():.3f}..{res['prismatic.s'].max():.3f} m")
    print(f"constraints: max |B_rod - B_slider| {gap.max():.1e} m, slider off its track "
          f"{off_track.max():.1e} m, turned {turned.max():.1e} rad")
    drift = np.max(np.abs(E - E[0])) / T.max()
    print(f"energy: E0 = {E[0]:.6f} J, max |E - E0| / max T = {drift:.1e}")

    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "slider_crank.png")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    ax[0].plot(res.t, res["rev1.phi"], label="crank rev1.phi [rad]")
    ax[0].plot(res.t, res["prismatic.s"], label="slider prismatic.s [m]")
    ax[0].set_ylabel("crank angle, slider position")
    ax[1].semilogy(res.t, np.maximum(off_track, 1e-17), label="slider off its track [m]")
    ax[1].semilogy(res.t, np.maximum(turned, 1e-17), label="slider turned [rad]")
    ax[1].set_ylabel("constraint residual")
    ax[1].legend()
    ax[2].plot(res.t, E - E[0])
    ax[2].set_ylabel("energy drift E − E0 [J]")
    ax[2].set_xlabel("time [s]")
    for a in ax:
        a.grid(True)
    ax[0].legend()
    fig.suptitle("Slider-crank under gravity (undamped)")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
