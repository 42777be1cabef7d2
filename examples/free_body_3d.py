"""A free body in 3-D (Dzhanibekov's tumbling wing nut) next to a spinning top on a
Spherical joint, from MSL MultiBody components, line by line as in Modelica:

    World world(gravityType=NoGravity);
    Body nut(m=0.1, r_CM={0,0,0}, I_11=1e-4, I_22=2e-4, I_33=3e-4, w_0_start={0.01,20,0.02});

A Body with no joint is a free body (13 states: frame_a.r_0, v_0, the quaternion Q, w_a);
spun about its intermediate axis it flips over and over, its energy and angular momentum
constant. The top (second model) precesses under gravity on a spherical joint. Prints
the states, Lagrange's M of the free body (in its velocities v_0, w_a), the energy and
momentum drift, the top's precession rate against the gyroscopic estimate m·g·l/(C·ω3),
and saves ``free_body_3d.png`` (in $ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components.multibody import Body, GravityTypes, Spherical, World

I_NUT = np.array([1e-4, 2e-4, 3e-4])


def wing_nut() -> acausal.Model:
    m = acausal.Model("wing_nut")
    m.world = World(gravityType=GravityTypes.NoGravity)
    m.nut = Body(m=0.1, r_CM=(0, 0, 0), I_11=I_NUT[0], I_22=I_NUT[1], I_33=I_NUT[2],
                 w_0_start=(0.01, 20.0, 0.02))
    return m


def top(spin: float) -> acausal.Model:
    m = acausal.Model("top")
    m.world = World(n=(0, 0, -1))
    m.joint = Spherical(angles_start=(0.4, 0, 0), w_rel_a_start=(0, -spin * np.sin(0.4),
                                                                 spin * np.cos(0.4)))
    m.top = Body(m=0.5, r_CM=(0, 0, 0.05), I_11=1e-3, I_22=1e-3, I_33=2e-3)
    m.connect(m.world.frame_b, m.joint.frame_a)
    m.connect(m.joint.frame_b, m.top.frame_a)
    return m


def main():
    nut = acausal.compile(wing_nut())
    print(f"states: {nut.x_names}")
    M = nut.lagrange.function("M")(0, [0, 0, 0, 0, 0, 0, 1], np.zeros(6), [],
                                   nut.param_vector())
    print(f"M in (v_0, w_a):\n{np.array(M)}")
    t = np.linspace(0, 10, 2001)
    res = nut.simulate(10.0, t=t, rtol=1e-11, atol=1e-13)
    w = np.array([res[f"nut.w_a[{i}]"] for i in (1, 2, 3)])
    T = np.array([[res[f"nut.frame_a.R.T[{i},{j}]"] for j in (1, 2, 3)] for i in (1, 2, 3)])
    E = 0.5 * np.einsum("i,it->t", I_NUT, w * w)
    L = np.einsum("jit,jt->it", T, I_NUT[:, None] * w)              # in the world
    print(f"flips: {np.sum(np.diff(np.sign(w[1])) != 0)}, relative drift of energy "
          f"{np.ptp(E) / E[0]:.1e}, of angular momentum "
          f"{np.ptp(L, axis=1).max() / np.linalg.norm(L[:, 0]):.1e}")

    spin = 200.0
    tt = np.linspace(0, 10.5, 4001)                 # one turn of the precession
    rt = acausal.compile(top(spin)).simulate(tt[-1], t=tt, rtol=1e-10, atol=1e-12)
    axis = np.array([rt[f"top.frame_a.R.T[3,{j}]"] for j in (1, 2, 3)])
    azimuth = np.unwrap(np.arctan2(axis[1], axis[0]))
    rate = np.polyfit(tt, azimuth, 1)[0]
    print(f"top: precession {rate:.4f} rad/s, gyroscopic estimate "
          f"{0.5 * 9.80665 * 0.05 / (2e-3 * spin):.4f} rad/s")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for i in range(3):
        ax[0].plot(t, w[i], label=f"nut.w_a[{i + 1}] [rad/s]")
    ax[0].set_xlabel("t [s]")
    ax[0].legend(loc="lower left")
    ax[0].set_title("free wing nut: flips about its intermediate axis")
    ax[1].plot(axis[0], axis[1])
    ax[1].set_aspect("equal")
    ax[1].set_title("top's axis seen from above (x, y)")
    fig.tight_layout()
    out = os.path.join(os.environ.get("ACAUSAL_OUT", "."), "free_body_3d.png")
    fig.savefig(out, dpi=100)
    print(f"plot saved to {out}")


if __name__ == "__main__":
    main()
