"""A 3-D pendulum from MSL MultiBody components: a steel BodyCylinder on two Revolutes
with perpendicular axes (a Cardan joint at the pivot: first about the world's y axis,
then about x): a conical pendulum under gravity (-y), line by line as in Modelica:

    World world; Revolute rev1(n={0,1,0}); Revolute rev2(n={1,0,0});
    BodyCylinder rod(r={0,-0.6,0}, diameter=0.05);

It starts tilted (rev2.phi = 0.6 rad) and turning about the vertical (rev1.w = 3 rad/s).
Prints Lagrange's mass matrix M(q) (``compiled.lagrange``), checks that the energy
½q̇ᵀM(q)q̇ + m·g·y_CM (m and the centre of mass by hand: ρπL(d/2)², r/2) stays constant, and
saves ``pendulum_3d.png`` (in $ACAUSAL_OUT, default the current directory). Last, the modes
hanging at rest next to those of the same rod on a Spherical joint (quaternion states,
analysed in their tangent coordinates θ: the two swings and a free turn about the rod).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.analysis import modes
from acausal.components.multibody import BodyCylinder, Revolute, Spherical, World

R_ROD, D_ROD = np.array([0.0, -0.6, 0.0]), 0.05


class Pendulum3D(acausal.Model):
    """World, two Revolutes (y, then x) and a BodyCylinder hanging from them."""

    def __init__(self, name=None):
        super().__init__(name)
        self.world = World()
        self.rev1, self.rev2 = Revolute(n=(0, 1, 0)), Revolute(n=(1, 0, 0))
        self.rod = BodyCylinder(r=tuple(R_ROD), diameter=D_ROD)
        self.connect(self.world.frame_b, self.rev1.frame_a)
        self.connect(self.rev1.frame_b, self.rev2.frame_a)
        self.connect(self.rev2.frame_b, self.rod.frame_a)


def main():
    model = acausal.compile(Pendulum3D("pendulum3d"))
    p = model.param_vector()
    M = model.lagrange.function("M")
    print(f"q = {model.coordinates}\nM(q) at q = (0, 0.6):\n"
          f"{np.array(M(0, [0, 0.6], [0, 0], [], p)).round(5)}")
    t = np.linspace(0, 5, 1001)
    res = model.simulate(5.0, t=t, x0={"rev2.phi": 0.6, "rev1.w": 3.0}, rtol=1e-10,
                         atol=1e-12)
    q = np.stack([res["rev1.phi"], res["rev2.phi"]], 1)
    qd = np.stack([res["rev1.w"], res["rev2.w"]], 1)
    T = np.stack([np.stack([res[f"rod.frame_a.R.T[{i},{j}]"] for j in (1, 2, 3)], -1)
                  for i in (1, 2, 3)], -2)                  # world -> rod, per sample
    m = 7700 * np.pi * np.linalg.norm(R_ROD) * (D_ROD / 2) ** 2
    y_cm = np.einsum("nji,j->n", T[:, :, 1:2], R_ROD / 2)
    E = np.array([0.5 * v @ np.array(M(0, x, v, [], p)) @ v for x, v in zip(q, qd)]) \
        + m * 9.80665 * y_cm
    print(f"rod mass {m:.4f} kg; energy {E[0]:.6f} J, drift over 5 s {np.ptp(E):.1e} J")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    tip = np.einsum("nji,j->ni", T, R_ROD)                   # rod end in the world frame
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].plot(t, q[:, 0], label="rev1.phi [rad]")
    ax[0].plot(t, q[:, 1], label="rev2.phi [rad]")
    ax[0].set_xlabel("t [s]")
    ax[0].legend()
    ax[1].plot(tip[:, 0], tip[:, 2])
    ax[1].set_aspect("equal")
    ax[1].set_title("rod end seen from above: x, z [m]")
    fig.tight_layout()
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "pendulum_3d.png")
    fig.savefig(out, dpi=100)
    print(f"plot saved to {out}")

    spherical = acausal.Model("spherical")
    spherical.world, spherical.joint = World(), Spherical()
    spherical.rod = BodyCylinder(r=tuple(R_ROD), diameter=D_ROD)
    spherical.connect(spherical.world.frame_b, spherical.joint.frame_a)
    spherical.connect(spherical.joint.frame_b, spherical.rod.frame_a)
    print("modes hanging at rest [Hz]: Cardan joint", modes(model, {}).frequencies.round(4),
          "; Spherical joint", modes(acausal.compile(spherical), {}).frequencies.round(4))


if __name__ == "__main__":
    main()
