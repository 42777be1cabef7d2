"""A robot arm from its URDF file: the UR5 of the ``example-robot-data`` package (pip install
example-robot-data; the ``robots`` extra), read by ``acausal.multibody.from_urdf`` into
MultiBody parts (links as Bodies, joints as Revolutes with their axis flanges), under gravity
along −z. Each joint is driven through its flange by a series-elastic drive: a Position
source (MSL's Rotational.Sources.Position, its reference a 1 Hz Bessel-filtered step to the
target pose) behind a SpringDamper (a PD law: τ = c·(φ_ref − φ) + d·(ω_ref − ω)), so the
arm's joints stay free coordinates and its accelerations come from the dynamics.

Prints the joints with their URDF limits, the compile time and the method the accelerations
are computed by (the O(N) articulated-body recursion), each joint's final angle (the PD
law's sag under gravity), its largest drive torque next to its effort limit, and the tool
flange's final position; saves ``robot_urdf.png``
(in $ACAUSAL_OUT, default the current directory). Without example-robot-data, the PUMA 560
from its Denavit–Hartenberg table (``acausal.multibody.dh_chain``) stands in.
"""
from __future__ import annotations

import os
import time
from importlib.metadata import PackageNotFoundError, distribution

import numpy as np

import acausal
from acausal.components import rotational, signals
from acausal.multibody import dh_chain, from_urdf

UR5 = "cmeel.prefix/share/example-robot-data/robots/ur_description/urdf/" \
      "ur5_joint_limited_robot.urdf"
TARGET = (0.8, -1.2, 1.5, -0.6, 1.0, 0.5)          # [rad], one per joint
STIFFNESS = (2000.0, 2000.0, 1000.0, 100.0, 100.0, 30.0)     # c [N.m/rad]
DAMPING = (200.0, 200.0, 80.0, 8.0, 8.0, 3.0)                # d [N.m.s/rad]


def robot() -> acausal.Model:
    try:
        return from_urdf(distribution("example-robot-data").locate_file(UR5))
    except PackageNotFoundError:
        print("example-robot-data not installed: the PUMA 560 from its DH table instead")
        puma = [(0, 0, 0, np.pi / 2, 0), (0, 0, 0.4318, 0, 17.4), (0, 0.15005, 0.0203,
                -np.pi / 2, 4.8), (0, 0.4318, 0, np.pi / 2, 0.82), (0, 0, 0, -np.pi / 2, 0.34),
                (0, 0, 0, 0, 0.09)]
        return dh_chain([dict(theta=t, d=d, a=a, alpha=al, body=dict(m=m) if m else None)
                         for t, d, a, al, m in puma], n=(0, 0, -1))


def main():
    model = robot()
    names = [j.path for j in model.joints]
    for name in names:
        lim = getattr(model, "limits", {}).get(name, {})
        print(f"{name:22s} axis {lim.get('axis', (0, 0, 1))}  limits "
              f"[{lim.get('lower', -np.inf):.3f}, {lim.get('upper', np.inf):.3f}] rad, "
              f"effort {lim.get('effort', np.inf):g} N.m")
    for k, joint in enumerate(model.joints):
        drive = rotational.Position(f_crit=0.8, useSupport=True)
        pd = rotational.SpringDamper(c=STIFFNESS[k], d=DAMPING[k])
        ref = signals.Constant(k=TARGET[k])
        for part, c in (("ref", ref), ("drive", drive), ("pd", pd)):
            setattr(model, f"{part}{k}", c)
        model.connect(ref.y, drive.phi_ref)
        model.connect(drive.support, joint.support)
        model.connect(drive.flange, pd.flange_a)
        model.connect(pd.flange_b, joint.axis)
    t0 = time.perf_counter()
    compiled = acausal.compile(model)
    print(f"compiled in {time.perf_counter() - t0:.3f} s; accelerations by the "
          f"{compiled.method}")
    t = np.linspace(0.0, 3.0, 601)
    res = compiled.simulate(3.0, t=t)
    tool = model.frames[-1] if hasattr(model, "frames") else model.ee_fixed_joint_origin.frame_b
    r_tool = [res[f"{tool.path}.r_0[{i}]"][-1] for i in (1, 2, 3)]
    for k, name in enumerate(names):
        tau = np.abs(res[f"{name}.tau"]).max()
        effort = getattr(model, "limits", {}).get(name, {}).get("effort", np.inf)
        print(f"{name:22s} final {res[f'{name}.phi'][-1]:+.4f} rad (target {TARGET[k]:+.1f}), "
              f"peak drive torque "
              f"{tau:7.2f} N.m ({'within' if tau <= effort else 'BEYOND'} the effort limit)")
    print(f"tool flange at {np.round(r_tool, 4)} m")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    for name in names:
        a1.plot(t, res[f"{name}.phi"], label=name)
        a2.plot(t, res[f"{name}.tau"])
    a1.set_ylabel("joint angle [rad]")
    a1.legend(fontsize=7)
    a2.set_ylabel("drive torque [N.m]")
    a2.set_xlabel("time [s]")
    fig.tight_layout()
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "robot_urdf.png"))


if __name__ == "__main__":
    main()
