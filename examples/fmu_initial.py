"""FMUs that carry initial equations and a termination condition, against compiled.simulate.

1. A spring-mounted inertia started by InitializeFlange with the acceleration -5 rad/s²
   (J = 2 kg.m², c = 100 N.m/rad): the FMU's initialization solves the initial equation
   for the angle, φ0 = J·5/c = 0.1 rad, as simulate() does, the speed 0.5 rad/s set by the
   importer held; then φ = 0.1·cos(ωt) + (0.5/ω)·sin(ωt), ω = √(c/J).
2. MSL's RobotR3.OneAxis: the motor starts in steady state (der(C.v) = 0, der(La.i) = 0),
   InitializeFlange sets the load, and TerminateSimulation ends the run 0.5 s after the
   reference motion. Model exchange ends where the event update reports
   terminateSimulation; co-simulation's doStep stops at the event (FMI 2.0: fmi2Discard,
   fmi2Terminated; FMI 3.0: terminateSimulation, earlyReturn).

Native FMUs (C), run by fmpy; prints the start states, the largest differences and the end
times.
"""
from __future__ import annotations

import math
import os
import tempfile

import numpy as np
from fmpy import simulate_fmu

import acausal
from acausal.components import rotational as rot
from acausal.components import signals as sig
from acausal.models.robot_axis import STOP_TIME, OneAxis


class Wound(acausal.Model):
    """An inertia on a spring to the ground, started with a given acceleration."""

    def __init__(self, name="wound"):
        super().__init__(name)
        self.fixed, self.spring = rot.Fixed(), rot.Spring(c=100.0)
        self.inertia = rot.Inertia(J=2.0)
        self.init = rot.InitializeFlange(use_phi_start=False, use_w_start=False)
        self.a0 = sig.Constant(k=-5.0)
        self.connect(self.fixed.flange, self.spring.flange_a)
        self.connect(self.spring.flange_b, self.inertia.flange_a)
        self.connect(self.init.flange, self.inertia.flange_b)
        self.connect(self.a0.y, self.init.a_start)


def run(path, kind, stop_time, interval, start, outputs):
    return simulate_fmu(str(path), fmi_type=kind, stop_time=stop_time, output_interval=interval,
                        start_values=start, relative_tolerance=1e-10, output=outputs,
                        early_return_allowed=True)


def main():
    with tempfile.TemporaryDirectory() as tmp:
        # 1. the start from an initial equation, a speed set by the importer held
        wound = acausal.compile(Wound())
        start, grid = {"inertia.w": 0.5}, np.linspace(0.0, 1.0, 101)
        ref = wound.simulate(1.0, t=grid, x0=start, rtol=1e-12, atol=1e-14)
        omega = math.sqrt(50.0)
        closed = 0.1 * np.cos(omega * grid) + 0.5 / omega * np.sin(omega * grid)
        print(f"wound: simulate() starts at phi = {ref['inertia.phi'][0]:.12f} rad, "
              f"w = {ref['inertia.w'][0]:.12f} rad/s (closed form 0.1, 0.5); largest "
              f"difference to the closed form {np.abs(ref['inertia.phi'] - closed).max():.1e}")
        for version in ("2.0", "3.0"):
            path = wound.export_fmu(os.path.join(tmp, f"wound{version[0]}.fmu"),
                                    fmi_version=version, stop_time=1.0)
            for kind in ("ModelExchange", "CoSimulation"):
                r = run(path, kind, 1.0, 0.01, start, ["inertia.phi", "inertia.w"])
                print(f"  FMI {version} {kind:14s} starts at phi = {r['inertia.phi'][0]:.12f}"
                      f" rad; largest difference to simulate() "
                      f"{np.abs(r['inertia.phi'] - ref['inertia.phi']).max():.1e} rad")

        # 2. a steady start and a termination
        axis = acausal.compile(OneAxis())
        signals = ["load.phi", "axis.motor.La.i", "axis.motor.C.v"]
        grid = np.linspace(0.0, STOP_TIME, 1601)
        ref = axis.simulate(STOP_TIME, t=grid, rtol=1e-10, atol=1e-12)
        grid = grid[grid < ref.terminated.time]         # the output points before the end
        print(f"OneAxis: simulate() {ref.terminated}")
        for version in ("2.0", "3.0"):
            path = axis.export_fmu(os.path.join(tmp, f"one_axis{version[0]}.fmu"),
                                   fmi_version=version, stop_time=STOP_TIME)
            for kind in ("ModelExchange", "CoSimulation"):
                r = run(path, kind, STOP_TIME, 1e-3, {}, signals)
                t = r["time"]
                idx = np.searchsorted(t, grid + 1e-9, side="right") - 1     # right limits
                ridx = np.searchsorted(ref.t, grid + 1e-9, side="right") - 1
                err = max(np.abs(r[n][idx] - ref[n][ridx]).max() / np.abs(ref[n]).max()
                          for n in signals)
                print(f"  FMI {version} {kind:14s} ends at t = {t[-1]:.10f} s (simulate(): "
                      f"{ref.terminated.time:.10f} s); largest difference {err:.1e} of the "
                      f"peaks")


if __name__ == "__main__":
    main()
