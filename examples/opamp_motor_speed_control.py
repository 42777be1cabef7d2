"""An analog speed controller for a DC motor: an op-amp PI controller drives a complementary
MOSFET output stage (NMOS and PMOS source followers) that feeds the armature; a
tachogenerator closes the loop.

    setpoint −kt·w_ref ─ R1 ─┐         ┌─ Rf ─ Cf ─┐
    tacho     +kt·w   ─ R1 ─┴─ in_n ─(OpAmpLimited)─ out ─┬─ NMOS gate (drain at +Vs) ─┐
                               in_p = 0      ±Vs supply    └─ PMOS gate (drain at −Vs) ─┤
                                                   sources: motor, 1 kΩ to ground ──────┘

The op amp (Electrical.Analog.Ideal.OpAmpLimited: gain V0, output limited to its supply,
supplied through its pins by a SupplyVoltage) is an inverting PI stage: out = (Rf/R1)·kt·
(w_ref − w) + kt/(R1·Cf)·∫(w_ref − w) dt. The output stage (Semiconductors.NMOS, PMOS:
MSL's Shichman–Hodges transistors, made wide enough for amperes) follows the op amp's
output less the gate thresholds, a dead band the loop's integral action works through. The
motor (armature R, L, RotationalEMF, rotor inertia) speeds up along a ramped setpoint, then
takes a load torque step; the integral action brings the speed back to the setpoint, the
current and the op amp's output rise to carry the load (a 1 kΩ bleeder holds the output
node while both transistors are off). Prints the speed against the setpoint, the torque
balance under load and the supply's power balance; saves ``opamp_motor_speed_control.png`` (in
$ACAUSAL_OUT, default the current directory).
"""
from __future__ import annotations

import os

import numpy as np

import acausal
from acausal.components import electrical as el
from acausal.components import rotational as rot
from acausal.components import signals as sig

VS = 15.0                          # supply [V]
KT = 0.02                          # tachogenerator [V/(rad/s)]
R1, RF, CF = 1e3, 47e3, 1e-6       # PI: Kp = Rf/R1·kt, Ki = kt/(R1·Cf)
R, L, K, J = 1.0, 2e-3, 0.05, 2e-5     # armature [Ohm], [H], motor constant [N.m/A], [kg.m2]
W_REF, LOAD = 150.0, 0.05          # speed setpoint [rad/s], load torque step [N.m]


class SpeedControl(acausal.Model):
    def __init__(self, name=None):
        super().__init__(name)
        self.supply = el.SupplyVoltage(Vps=VS, Vns=-VS)
        self.ground = el.Ground()
        self.setpoint = el.RampVoltage(V=-KT * W_REF, duration=0.05, startTime=0.01)
        self.r_set = el.Resistor(R=R1)
        self.speed = rot.SpeedSensor()
        self.tacho_gain = sig.Gain(k=KT)
        self.tacho = el.SignalVoltage()
        self.r_tacho = el.Resistor(R=R1)
        self.opamp = el.OpAmpLimited(useSupply=True)
        self.rf = el.Resistor(R=RF)
        self.cf = el.Capacitor(C=CF)
        self.nmos = el.NMOS(W=0.05)
        self.pmos = el.PMOS(W=0.2)
        self.bleeder = el.Resistor(R=1e3)    # holds the output node while both are off
        self.armature = el.Resistor(R=R)
        self.inductance = el.Inductor(L=L)
        self.emf = el.RotationalEMF(k=K)
        self.rotor = rot.Inertia(J=J)
        self.load = rot.TorqueStep(stepTorque=-LOAD, startTime=0.25)
        g = self.ground.p
        for a, b in [
                (self.supply.ground, g), (self.opamp.s_p, self.supply.pin_p),
                (self.opamp.s_n, self.supply.pin_n), (self.opamp.in_p, g),
                (self.setpoint.p, self.r_set.p), (self.setpoint.n, g),
                (self.r_set.n, self.opamp.in_n), (self.tacho.p, self.r_tacho.p),
                (self.tacho.n, g), (self.r_tacho.n, self.opamp.in_n),
                (self.opamp.in_n, self.rf.p), (self.rf.n, self.cf.p),
                (self.cf.n, self.opamp.out), (self.opamp.out, self.nmos.G),
                (self.opamp.out, self.pmos.G), (self.nmos.D, self.supply.pin_p),
                (self.pmos.D, self.supply.pin_n), (self.nmos.S, self.armature.p),
                (self.pmos.S, self.armature.p), (self.nmos.B, self.nmos.S),
                (self.pmos.B, self.pmos.S), (self.bleeder.p, self.armature.p),
                (self.bleeder.n, g), (self.armature.n, self.inductance.p),
                (self.inductance.n, self.emf.p), (self.emf.n, g),
                (self.emf.flange, self.rotor.flange_a), (self.rotor.flange_b, self.load.flange),
                (self.rotor.flange_b, self.speed.flange), (self.speed.w, self.tacho_gain.u),
                (self.tacho_gain.y, self.tacho.v)]:
            self.connect(a, b)


def main():
    compiled = acausal.compile(SpeedControl("speed_control"))
    t = np.linspace(0.0, 0.5, 1001)
    res = compiled.simulate(0.5, t=t, rtol=1e-8, atol=1e-10)
    w = res["rotor.w"]
    for when in (0.2, 0.26, 0.5):
        k = np.searchsorted(res.t, when)
        print(f"t = {when:.2f} s: speed {w[k]:7.2f} rad/s (setpoint {W_REF:.0f}), armature "
              f"{res['inductance.i'][k]:6.3f} A, op amp out {res['opamp.v_out'][k]:6.2f} V")
    # in steady state under load the integral action leaves no speed error, and the motor
    # carries the load: k·i = LOAD
    print(f"final speed error {W_REF - w[-1]:.2e} rad/s, "
          f"k·i - load {K * res['inductance.i'][-1] - LOAD:.2e} N.m")
    # the supply delivers what the op amp's output and the transistors' drains take
    supplied = -(res["supply.pin_p.v"] * res["supply.pin_p.i"]
                 + res["supply.pin_n.v"] * res["supply.pin_n.i"])
    taken = -res["opamp.p_out"] + VS * res["nmos.D.i"] - VS * res["pmos.D.i"]
    print(f"supply power balance off by {np.max(np.abs(supplied - taken)):.1e} W "
          f"(peak {np.max(np.abs(supplied)):.1f} W)")
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(3, 1, sharex=True, figsize=(7, 7))
    ax[0].plot(res.t, w, label="speed")
    ax[0].plot(res.t, np.clip((res.t - 0.01) / 0.05, 0, 1) * W_REF, "--", label="setpoint")
    ax[0].set_ylabel("w [rad/s]")
    ax[0].legend()
    ax[1].plot(res.t, res["inductance.i"])
    ax[1].set_ylabel("armature [A]")
    ax[2].plot(res.t, res["opamp.v_out"], label="op amp out")
    ax[2].plot(res.t, res["armature.p.v"], label="motor terminal")
    ax[2].set_ylabel("[V]")
    ax[2].set_xlabel("t [s]")
    ax[2].legend()
    fig.savefig(os.path.join(os.environ.get("ACAUSAL_OUT", "."),
                             "opamp_motor_speed_control.png"))


if __name__ == "__main__":
    main()
