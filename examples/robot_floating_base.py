"""A legged robot with a floating base from its URDF file: Solo12 of the
``example-robot-data`` package (the ``robots`` extra), read by
``acausal.multibody.from_urdf(..., floating_base=True)``: the base link moves freely on a
FreeMotion ``root_joint`` from the World (quaternion states, 18 degrees of freedom), as
Pinocchio's JointModelFreeFlyer root. Weightless (no gravity, no ground), the robot swings
its legs to a new pose through series-elastic drives (Position source behind a
SpringDamper on each joint's axis flange): with no external force or torque, its momentum
stays zero, so the base turns and shifts to make up for the legs. The base starts turned
by angles given by name (``root_joint.phi``, the quaternion set from them).

Prints the compile time and the method of the accelerations, the base's position and
angles before and after; saves ``robot_floating_base.png`` (in $ACAUSAL_OUT, default the
current directory).
"""
from __future__ import annotations

import os
import sys
import time
from importlib.metadata import PackageNotFoundError, distribution

import numpy as np

import acausal
from acausal.components import rotational, signals
from acausal.multibody import from_urdf

SOLO12 = "cmeel.prefix/share/example-robot-data/robots/solo_description/robots/solo12.urdf"


def main():
    try:
        path = distribution("example-robot-data").locate_file(SOLO12)
    except PackageNotFoundError:
        print("example-robot-data not installed (pip install example-robot-data)")
        sys.exit(0)
    model = from_urdf(path, gravity=(0.0, 0.0, 0.0), floating_base=True)
    legs = [j for j in model.joints if j is not model.root_joint]
    for k, joint in enumerate(legs):
        target = (0.3, 0.9, -1.6)[k % 3] * (1 if k < 6 else -1)      # a crouch, per leg
        drive = rotational.Position(f_crit=2.0, useSupport=True)
        pd = rotational.SpringDamper(c=20.0, d=0.5)
        ref = signals.Constant(k=target)
        for part, c in (("ref", ref), ("drive", drive), ("pd", pd)):
            setattr(model, f"{part}{k}", c)
        model.connect(ref.y, drive.phi_ref)
        model.connect(drive.support, joint.support)
        model.connect(drive.flange, pd.flange_a)
        model.connect(pd.flange_b, joint.axis)
    t0 = time.perf_counter()
    compiled = acausal.compile(model)
    print(f"compiled in {time.perf_counter() - t0:.2f} s; accelerations by the "
          f"{compiled.method}")
    start = {"root_joint.phi[1]": 0.2, "root_joint.phi[2]": -0.1, "root_joint.phi[3]": 0.5}
    t = np.linspace(0.0, 2.0, 401)
    res = compiled.simulate(2.0, t=t, x0=start)
    for label, k in (("start", 0), ("end", -1)):
        r = [res[f"root_joint.r_rel_a[{i}]"][k] for i in (1, 2, 3)]
        phi = [res[f"root_joint.phi[{i}]"][k] for i in (1, 2, 3)]
        print(f"base at {label}: position {np.round(r, 4)} m, angles {np.round(phi, 4)} rad")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    for i in (1, 2, 3):
        a1.plot(t, res[f"root_joint.phi[{i}]"], label=f"base phi[{i}]")
    for joint in legs[:3]:
        a2.plot(t, res[f"{joint.path}.phi"], label=joint.path)
    a1.set_ylabel("base angles [rad]")
    a1.legend(fontsize=7)
    a2.set_ylabel("joint angle [rad]")
    a2.legend(fontsize=7)
    a2.set_xlabel("time [s]")
    fig.tight_layout()
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "robot_floating_base.png"))


if __name__ == "__main__":
    main()
