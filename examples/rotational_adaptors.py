"""A drive shaft cut at a signal interface with MSL's GeneralTorqueToAngleAdaptor and
GeneralAngleToTorqueAdaptor (the form in which parts are exported as FMUs), against the same
parts connected by their flanges.

    tau(t) ─ motor J1 ─ toAngle ══(p, pder, pder2 → ← f)══ toTorque ─ load J2 ─ damper ─ fixed

toAngle outputs the motor's angle, speed and acceleration and takes the torque f on it;
toTorque moves the load with them and outputs the torque that needs, f = J2·a + d·w (an
algebraic loop through the signals, as when two FMUs are connected so). Prints the largest
differences from the model connected by flanges (the compiler reduces both to the same
equations of one shaft: round-off at most) and of f from J2·a + d·w; plots the speed and the
interface torque.
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components import rotational as rot
from acausal.components import signals as sig

J1, J2, D = 0.5, 1.5, 0.8          # kg.m2, kg.m2, N.m.s/rad


def shaft(cut: bool) -> acausal.Model:
    m = acausal.Model("cut_shaft" if cut else "shaft")
    m.sine, m.torque = sig.Sine(amplitude=4.0, f=0.5, offset=1.0), rot.Torque()
    m.motor, m.load = rot.Inertia(J=J1), rot.Inertia(J=J2)
    m.damper, m.fixed = rot.Damper(d=D), rot.Fixed()
    pairs = [(m.sine.y, m.torque.tau), (m.torque.flange, m.motor.flange_a),
             (m.load.flange_b, m.damper.flange_a), (m.damper.flange_b, m.fixed.flange)]
    if cut:
        m.toAngle, m.toTorque = rot.GeneralTorqueToAngleAdaptor(), \
            rot.GeneralAngleToTorqueAdaptor()
        pairs += [(m.motor.flange_b, m.toAngle.flange), (m.toTorque.flange, m.load.flange_a),
                  (m.toAngle.p, m.toTorque.p), (m.toAngle.pder, m.toTorque.pder),
                  (m.toAngle.pder2, m.toTorque.pder2), (m.toTorque.f, m.toAngle.f)]
    else:
        pairs += [(m.motor.flange_b, m.load.flange_a)]
    for a, b in pairs:
        m.connect(a, b)
    return m


def main():
    t = np.linspace(0.0, 10.0, 1001)
    opts = dict(t=t, rtol=1e-10, atol=1e-12)
    cut = acausal.compile(shaft(cut=True)).simulate(10.0, **opts)
    whole = acausal.compile(shaft(cut=False)).simulate(10.0, **opts)
    for name in ("motor.phi", "load.phi", "load.w"):
        print(f"{name:9s} max |cut − connected| {np.max(np.abs(cut[name] - whole[name])):.1e}")
    f, needed = cut["toTorque.f"], J2 * cut["toAngle.pder2"] + D * cut["toAngle.pder"]
    print(f"interface torque f: max |f − (J2·a + d·w)| {np.max(np.abs(f - needed)):.1e} N.m, "
          f"max |f| {np.max(np.abs(f)):.3f} N.m")
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(2, 1, figsize=(7, 5), sharex=True)
    ax[0].plot(t, whole["load.w"], label="connected by flanges")
    ax[0].plot(t[::40], cut["load.w"][::40], "o", label="cut by the General adaptors")
    ax[0].set_ylabel("w [rad/s]"); ax[0].legend(fontsize="small")
    ax[1].plot(t, cut["toTorque.f"]); ax[1].set_ylabel("f [N.m]"); ax[1].set_xlabel("t [s]")
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."), "rotational_adaptors.png"))


if __name__ == "__main__":
    main()
