"""Potential/flow networks in the compiler: the DAE they give, its size after elimination,
mixed electro-mechanical models, linearization and FMU export, and the errors for ports
used the wrong way."""
from __future__ import annotations

import math

import numpy as np
import pytest

import acausal
from acausal.analysis import linearize
from acausal.components import electrical as el
from acausal.components import rotational as rot
from acausal.core import Component, Pin
from wiring import model

TIGHT = {"rtol": 1e-11, "atol": 1e-12}
R, L, K, J = 0.05, 0.0015, 2.0 / math.pi, 0.15


def rc(R=10.0, C=0.01):
    return model("rc", lambda m: [(m.src.p, m.r.p), (m.r.n, m.c.p), (m.c.n, m.src.n),
                                  (m.src.n, m.ground.p)],
                 src=el.ConstantVoltage(V=2.0), r=el.Resistor(R=R), c=el.Capacitor(C=C),
                 ground=el.Ground())


def dc_circuit(source):
    return model("dc_circuit", lambda m: [
        (m.src.p, m.r.p), (m.r.n, m.l.p), (m.l.n, m.emf.p), (m.emf.n, m.src.n),
        (m.src.n, m.ground.p), (m.emf.flange, m.rotor.flange_a)] + (
        [(m.v.y, m.src.v)] if isinstance(source, el.SignalVoltage) else []),
        src=source, r=el.Resistor(R=R), l=el.Inductor(L=L), emf=el.RotationalEMF(k=K),
        rotor=rot.Inertia(J=J), ground=el.Ground(),
        **({"v": acausal.Input(unit="V")} if isinstance(source, el.SignalVoltage) else {}))


def test_trivial_equations_are_eliminated():
    """RC: of 4 potentials, 4 currents and 8 equations one unknown current and the
    resistor's equation remain (the capacitor's voltage is the state); the DC motor circuit
    becomes an ODE (its current is the inductor's state). Every pin still records v and i."""
    compiled = acausal.compile(rc())
    assert compiled.x_names == ["c.v"]
    assert len(compiled.z_names) == 1 and compiled.alg.numel() == 1
    res = compiled.simulate(0.1, t=np.linspace(0, 0.1, 3))
    for name in ("src.p.v", "src.n.v", "r.n.v", "ground.p.i", "c.n.i", "src.p.i"):
        assert name in res.names
    np.testing.assert_allclose(res["r.n.v"], res["c.v"], atol=1e-12)
    np.testing.assert_allclose(res["src.p.i"], -res["r.p.i"], atol=1e-12)
    motor = acausal.compile(dc_circuit(el.ConstantVoltage(V=10.0)))
    assert motor.z_names == [] and motor.x_names == ["rotor.phi", "rotor.w", "l.i"]


def test_dc_circuit_linearizes_to_the_hand_matrices():
    """x = [phi, w, i]: phi' = w, J w' = k i, L i' = v − R i − k w."""
    lm = linearize(acausal.compile(dc_circuit(el.SignalVoltage())), {"rotor.w": 0.0},
                   u={"v": 0.0})
    assert lm.states == ["rotor.phi", "rotor.w", "l.i"]
    A = [[0, 1, 0], [0, 0, K / J], [0, -K / L, -R / L]]
    np.testing.assert_allclose(lm.A, A, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(lm.B.ravel(), [0, 0, 1 / L], rtol=1e-12)


def test_motor_driven_arm_linearizes_to_the_hand_matrices():
    """The circuit's rotor drives a planar arm (a Revolute's axis; a body m, I at l from
    the pivot; the revolute's support is its frame_a) hanging under gravity: x = [phi, w, i]
    about phi = −π/2,
    (J + I + m l²)·w' = k·i − m·g·l·δphi, L·i' = v − R·i − k·w."""
    from acausal.components import planar as pl
    m_arm, I_arm, l_arm, g = 2.0, 0.05, 0.4, 9.81
    arm = dc_circuit(el.SignalVoltage())
    arm.world, arm.base = pl.World(), pl.Fixed()
    arm.revolute, arm.rod = pl.Revolute(useFlange=True), pl.FixedTranslation(r=(l_arm, 0))
    arm.body = pl.Body(m=m_arm, I=I_arm)
    for a, b in [(arm.base.frame, arm.revolute.frame_a),
                 (arm.revolute.frame_b, arm.rod.frame_a), (arm.rod.frame_b, arm.body.frame_a),
                 (arm.rotor.flange_b, arm.revolute.axis)]:
        arm.connect(a, b)
    lm = linearize(acausal.compile(arm), {"rotor.phi": -math.pi / 2, "rotor.w": 0.0},
                   u={"v": 0.0})
    assert lm.states == ["rotor.phi", "rotor.w", "l.i"]
    Jt = J + I_arm + m_arm * l_arm ** 2
    A = [[0, 1, 0], [-m_arm * g * l_arm / Jt, 0, K / Jt], [0, -K / L, -R / L]]
    np.testing.assert_allclose(lm.A, A, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(lm.B.ravel(), [0, 0, 1 / L], rtol=1e-12)


def test_rc_with_an_algebraic_current_linearizes():
    lm = linearize(acausal.compile(rc()), {"c.v": 1.0}, outputs=["r.i"])
    np.testing.assert_allclose(lm.A, [[-1 / (10.0 * 0.01)]], rtol=1e-12)
    np.testing.assert_allclose(lm.C, [[-1 / 10.0]], rtol=1e-12)


@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
def test_network_models_export_as_fmus(tmp_path, kind):
    """The RC (a DAE with one algebraic current) and the DC motor circuit (an ODE with the
    EMF's torque) as native FMUs, simulated by fmpy, equal the in-process simulation."""
    fmpy = pytest.importorskip("fmpy")
    cases = ((rc(), ["c.v", "r.i"], 0.3),
             (dc_circuit(el.StepVoltage(V=10.0, startTime=0.01)), ["rotor.w", "l.i"], 0.3))
    for m, names, T in cases:
        compiled = acausal.compile(m)
        path = compiled.export_fmu(tmp_path / f"{compiled.name}.fmu", stop_time=T)
        res = fmpy.simulate_fmu(str(path), stop_time=T, output_interval=T / 100,
                                fmi_type=kind, relative_tolerance=1e-10, output=names,
                                record_events=False)
        ref = compiled.simulate(T, t=np.linspace(0, T, 101), **TIGHT)
        idx = np.searchsorted(res["time"], ref.t + 1e-9, side="right") - 1
        for n in names:
            err = np.max(np.abs(res[n][idx] - ref[n])) / np.max(np.abs(ref[n]))
            assert err < 1e-6, (compiled.name, n, err)


class _Floating(Component):
    """A pin whose flow nobody sets."""
    p = Pin("pin")


class _Moving(Component):
    p = Pin("pin")

    def physics(self, e):
        e.vel(self.p)


def test_ports_used_the_wrong_way_are_named():
    m = model("unset", lambda m: [(m.x.p, m.r.p), (m.r.n, m.ground.p)], x=_Floating(),
              r=el.Resistor(), ground=el.Ground())
    with pytest.raises(acausal.StructureError, match=r"_Floating 'x' sets no i.*'x.p'"):
        acausal.compile(m)
    m = model("moving", lambda m: [(m.x.p, m.ground.p)], x=_Moving(), ground=el.Ground())
    with pytest.raises(acausal.StructureError,
                       match=r"'x.p' \(electrical\) has no motion.*potential"):
        acausal.compile(m)
    m = acausal.Model("mixed")
    m.r, m.j = el.Resistor(), rot.Inertia()
    with pytest.raises(acausal.PortConnectionError):
        m.connect(m.r.p, m.j.flange_a)


def test_minimum_energy_positioning_with_a_bounded_current_equals_the_compact_motor():
    """acausal.ocp on the circuit (ODE after elimination): quarter turn in 0.5 s with
    |i| ≤ 30 A minimizing the electrical energy ∫ v·i dt; the optimum equals that of the
    same problem on rotational.DCMotor."""
    pytest.importorskip("casadi")
    from acausal.ocp import OCP

    def solve(compiled, current, angle, speed):
        ocp = OCP(compiled, N=20, T=0.5, method="collocation")
        ocp.minimize(ocp.integral(lambda v: v["v"] * v[current]))
        ocp.bounds(current, -30.0, 30.0)
        ocp.bounds("v", -50.0, 50.0)
        ocp.initial({angle: 0.0, speed: 0.0, current: 0.0})
        ocp.final({angle: math.pi / 2, speed: 0.0})
        return ocp.solve({"print_level": 0, "tol": 1e-10})

    circuit = solve(acausal.compile(dc_circuit(el.SignalVoltage())), "l.i", "rotor.phi",
                    "rotor.w")
    compact = acausal.Model("dc")
    compact.v, compact.motor = acausal.Input(unit="V"), rot.DCMotor()
    compact.connect(compact.v.y, compact.motor.v)
    ref = solve(acausal.compile(compact), "motor.i", "motor.phi", "motor.w")
    assert circuit.cost > 0.1
    assert abs(circuit.cost - ref.cost) < 1e-8 * ref.cost
    np.testing.assert_allclose(circuit.control("v"), ref.control("v"), atol=1e-6)


def test_rc_equilibrium_is_the_charged_capacitor():
    from acausal.analysis import equilibrium
    op = equilibrium(acausal.compile(rc()))
    np.testing.assert_allclose(op.x, [2.0], atol=1e-12)           # v = V, no current
    np.testing.assert_allclose(op.z, [0.0], atol=1e-12)


def test_stiff_motor_circuit_gets_bdf_and_equals_the_compact_motor():
    """L = 1 µH (electrical time constant L/R = 20 µs) next to a 1 Hz torsional mode: the
    circuit compiles to an ODE for which BDF (cvodes) is chosen automatically, equal to the
    compact DCMotor with the same data."""
    Ls, c = 1e-6, J * (2 * math.pi) ** 2 / 2           # spring: 1 Hz with rotor and load

    def with_load(m, flange):
        m.spring, m.load, m.fixed = rot.Spring(c=c), rot.Inertia(J=J), rot.Fixed()
        m.connect(flange, m.spring.flange_a)
        m.connect(m.spring.flange_b, m.load.flange_a)
        return m

    circuit = dc_circuit(el.StepVoltage(V=1.0, startTime=0.0))
    circuit.l.L = Ls
    circuit = with_load(circuit, circuit.rotor.flange_b)
    compact = acausal.Model("compact")
    compact.v, compact.motor = acausal.Input(unit="V"), rot.DCMotor(L=Ls)
    compact.connect(compact.v.y, compact.motor.v)
    compact = with_load(compact, compact.motor.flange)
    t = np.linspace(0.0, 2.0, 201)
    res = acausal.compile(circuit).simulate(2.0, t=t, rtol=1e-10, atol=1e-12)
    ref = acausal.compile(compact).simulate(2.0, t=t, inputs={"v": 1.0}, rtol=1e-10,
                                             atol=1e-12)
    assert res.solver == "cvodes" and ref.solver == "cvodes"
    assert np.max(np.abs(ref["load.w"])) > 0.1
    np.testing.assert_allclose(res["load.w"], ref["load.w"], atol=1e-7)
    np.testing.assert_allclose(res["l.i"], ref["motor.i"], atol=1e-6)
