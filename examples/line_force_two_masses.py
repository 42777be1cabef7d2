"""A line force with mass: MSL's Examples.Elementary.LineForceWithTwoMasses, its JointUPS half.

A pendulum swings from the world; a damped hydraulic-cylinder-like line force runs from a
fixed point to its tip: a JointUPS (universal joint at frame_a, prismatic joint along the
line, spherical joint at frame_b) with a point mass on each part (frame_ia, frame_ib) and a
1-D Translational damper between its axis and bearing. The assembly adds no coordinate and
no constraint: the pendulum's angle is the only state. Saves line_force_two_masses.png.
"""
import matplotlib.pyplot as plt
import numpy as np

import acausal
from acausal.components.multibody import (Body, BodyBox, FixedTranslation, JointUPS,
                                          Revolute, World)
from acausal.components.translational import Damper
from acausal.core import Model

m = Model("lineForceWithTwoMasses")
m.world = World()
m.rod1, m.rod2 = FixedTranslation(r=(0, -0.9, 0)), FixedTranslation(r=(0, 0.3, 0))
m.revolute1, m.bodyBox1 = Revolute(), BodyBox(r=(0.7, 0, 0))
m.jointUPS = JointUPS(nAxis_ia=(0.7, 1.2, 0))
e_axis = np.array(m.jointUPS.eAxis_ia)
m.body1 = Body(m=1.0, r_CM=tuple(0.2 * e_axis), I_11=0, I_22=0, I_33=0)
m.body2 = Body(m=1.0, r_CM=tuple(-0.2 * e_axis), I_11=0, I_22=0, I_33=0)
m.damper1 = Damper(d=3)
m.connect(m.world.frame_b, m.rod2.frame_a)
m.connect(m.world.frame_b, m.rod1.frame_a)
m.connect(m.rod2.frame_b, m.revolute1.frame_a)
m.connect(m.revolute1.frame_b, m.bodyBox1.frame_a)
m.connect(m.bodyBox1.frame_b, m.jointUPS.frame_b)
m.connect(m.rod1.frame_b, m.jointUPS.frame_a)
m.connect(m.jointUPS.frame_ia, m.body1.frame_a)
m.connect(m.jointUPS.frame_ib, m.body2.frame_a)
m.connect(m.jointUPS.bearing, m.damper1.flange_a)
m.connect(m.jointUPS.axis, m.damper1.flange_b)

compiled = acausal.compile(m)
print("coordinates:", compiled.coordinates, "loop rows:", compiled.loop_rows)
res = compiled.simulate(3.0, t=np.linspace(0, 3, 301))
print(f"pendulum angle at 3 s {res['revolute1.phi'][-1]:.4f} rad, cylinder length "
      f"{res['jointUPS.s'][-1]:.4f} m, damper force {res['jointUPS.f'][-1]:.4f} N")

fig, ax = plt.subplots(2, 1, sharex=True)
ax[0].plot(res.t, res["revolute1.phi"])
ax[0].set_ylabel("revolute1.phi [rad]")
ax[1].plot(res.t, res["jointUPS.f"])
ax[1].set_ylabel("jointUPS.f [N]")
ax[1].set_xlabel("t [s]")
fig.savefig("line_force_two_masses.png")
