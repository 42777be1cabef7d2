"""3-D forces, sensors and a Rotor1D (after Modelica.Mechanics.MultiBody).

A bead slides on a rod that turns freely about the vertical z axis, pulled to the axis by a
3-D SpringDamperParallel; sensors measure its distance, its velocity seen from the rod and
the power flowing into it. Then MSL's GyroscopicEffects: a spinning cylinder on a body hung
from a spherical joint, modelled once with 3-D bodies and once with a Rotor1D, moves the
same. Saves multibody_forces.png.
"""
import matplotlib.pyplot as plt
import numpy as np

import acausal
from acausal.components.multibody import Body, Prismatic, Revolute, World, forces, sensors
from acausal.core import Model
from acausal.models.multibody_forces import GyroscopicEffects

m = Model("bead")
m.world = World(g=0)
m.rev, m.rod = Revolute(n=(0, 0, 1)), Body(m=0, r_CM=(0, 0, 0), I_33=0.5)
m.slide, m.bead = Prismatic(n=(1, 0, 0)), Body(m=2.0, r_CM=(0, 0, 0))
m.spring = forces.SpringDamperParallel(c=40.0, d=1.0, s_unstretched=0.2)
m.power, m.dist = sensors.Power(), sensors.Distance()
m.v_rod = sensors.RelativeVelocity()            # resolved in frame_a: the rod's
m.connect(m.world.frame_b, m.rev.frame_a)
m.connect(m.rev.frame_b, m.rod.frame_a)
m.connect(m.rev.frame_b, m.slide.frame_a)
m.connect(m.slide.frame_b, m.power.frame_a)
m.connect(m.power.frame_b, m.bead.frame_a)
for a, b in ((m.world.frame_b, m.spring), (m.world.frame_b, m.dist),
             (m.rev.frame_b, m.v_rod)):
    m.connect(a, b.frame_a)
    m.connect(b.frame_b, m.bead.frame_a)
res = acausal.compile(m).simulate(4.0, x0={"slide.s": 0.5, "rev.w": 2.0})
print(f"bead: distance {res['dist.distance'][-1]:.4f} m, rod speed {res['rev.w'][-1]:.4f} "
      f"rad/s, heat {np.trapezoid(res['spring.lossPower'], res.t):.4f} J")

gyro = acausal.compile(GyroscopicEffects()).simulate(5.0, x0=GyroscopicEffects.START)
print("housing w_a[3], spinning 3-D cylinder vs Rotor1D:",
      f"{gyro['bodyCylinder1.body.w_a[3]'][-1]:.6f}",
      f"{gyro['bodyCylinder3.body.w_a[3]'][-1]:.6f} rad/s")

fig, ax = plt.subplots(1, 2, figsize=(10, 4))
ax[0].plot(res.t, res["dist.distance"], label="distance [m]")
ax[0].plot(res.t, res["v_rod.v_rel[1]"], label="speed along the rod [m/s]")
ax[0].plot(res.t, res["power.power"], label="power into the bead [W]")
ax[0].set_xlabel("t [s]")
ax[0].legend()
for k in (1, 2, 3):
    ax[1].plot(gyro.t, gyro[f"bodyCylinder1.body.w_a[{k}]"], label=f"3-D bodies w_a[{k}]")
    ax[1].plot(gyro.t, gyro[f"bodyCylinder3.body.w_a[{k}]"], "--", label=f"Rotor1D w_a[{k}]")
ax[1].set_xlabel("t [s]")
ax[1].legend(fontsize=7)
fig.tight_layout()
fig.savefig("multibody_forces.png")
