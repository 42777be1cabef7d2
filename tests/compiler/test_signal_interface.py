"""A model's own signal connectors as the inputs and outputs of the compiled model, and a
measured cut force fed back into the forces of a tree, against closed forms."""
from __future__ import annotations

import numpy as np
import pytest

import acausal
from acausal.components import translational as tr
from acausal.components.signals import Constant, Gain, Sine
from acausal.core import Model, RealInput, RealOutput
from acausal.errors import StructureError

T = np.linspace(0.0, 1.0, 51)
TOL = dict(rtol=1e-10, atol=1e-12)


class PushedMass(Model):
    """A mass m [kg] pushed by the force F [N]; outputs its position s [m] and the force."""
    F = RealInput("force pushing the mass [N]")
    s = RealOutput("position of the mass [m]")
    echo = RealOutput("the force, passed through")

    def __init__(self, name=None, *, m=2.0, connect_s=True):
        super().__init__(name)
        self.mass, self.force, self.sensor = tr.Mass(m=m), tr.Force(), tr.PositionSensor()
        pairs = [(self.F, self.force.f), (self.force.flange, self.mass.flange_a),
                 (self.mass.flange_a, self.sensor.flange), (self.F, self.echo)]
        if connect_s:
            pairs.append((self.sensor.s, self.s))
        for a, b in pairs:
            self.connect(a, b)


def test_root_connectors_are_the_compiled_models_inputs_and_outputs():
    """Compiled alone, a model's RealInput F is an input and its RealOutputs s, echo are
    outputs, by the connectors' names, with the units ending their descriptions: F = 3 N
    moves the mass (2 kg) to s = 3/4·t²; inside a bigger model the same block is driven
    by a connection."""
    compiled = acausal.compile(PushedMass())
    assert compiled.input_names == ["F"] and compiled.output_names == ["s", "echo"]
    assert [v.unit for v in compiled.inputs + compiled.outputs] == ["N", "m", ""]
    res = compiled.simulate(1.0, t=T, inputs={"F": 3.0}, **TOL)
    assert np.allclose(res["s"], 0.75 * T ** 2, rtol=0, atol=1e-10)
    assert np.allclose(res["echo"], 3.0, rtol=0, atol=1e-14)
    y = compiled.output_function(0.5, [0.1, 0.2], [], [3.0], compiled.param_vector())
    assert np.allclose(y.full().ravel(), [0.1, 3.0])
    outer = Model("outer")
    outer.block, outer.push = PushedMass(), Constant(k=3.0)
    outer.connect(outer.push.y, outer.block.F)
    inner = acausal.compile(outer)
    assert inner.input_names == [] and inner.output_names == []
    assert np.allclose(inner.simulate(1.0, t=T, **TOL)["block.s"], 0.75 * T ** 2, atol=1e-10)


def test_a_component_compiled_alone_outputs_its_outputs():
    """A block compiled by itself: its RealOutput is the compiled model's output."""
    compiled = acausal.compile(Sine(amplitude=2.0, f=1.0))
    assert compiled.output_names == ["y"]
    res = compiled.simulate(1.0, t=T, **TOL)
    assert np.allclose(res["y"], 2.0 * np.sin(2 * np.pi * T), rtol=0, atol=1e-12)


def test_an_unconnected_root_output_is_named():
    with pytest.raises(StructureError, match="output 's' of model 'PushedMass'"):
        acausal.compile(PushedMass("PushedMass", connect_s=False))


def test_measured_force_feeding_a_force_adds_to_the_inertia():
    """mass1 (m1) pushed by F0 drives mass2 (m2) through a ForceSensor, which measures
    f = m2·a; k·f pushes mass1 too: (m1 + m2)·a = F0 + k·m2·a, so a = F0/(m1 + m2 − k·m2),
    and the mass matrix of the compiled equations is m1 + m2 − k·m2 (the measured
    reaction is an inertia term)."""
    m1, m2, k, F0 = 1.0, 2.0, 0.5, 3.0
    m = Model("feedback")
    m.push, m.force, m.mass1 = Constant(k=F0), tr.Force(), tr.Mass(m=m1)
    m.sensor, m.mass2 = tr.ForceSensor(), tr.Mass(m=m2)
    m.gain, m.force2 = Gain(k=k), tr.Force()
    for a, b in [(m.push.y, m.force.f), (m.force.flange, m.mass1.flange_a),
                 (m.mass1.flange_b, m.sensor.flange_a), (m.sensor.flange_b, m.mass2.flange_a),
                 (m.sensor.f, m.gain.u), (m.gain.y, m.force2.f),
                 (m.force2.flange, m.mass1.flange_a)]:
        m.connect(a, b)
    compiled = acausal.compile(m)
    a = F0 / (m1 + m2 - k * m2)
    res = compiled.simulate(1.0, t=T, **TOL)
    assert np.allclose(res["mass1.a"], a, rtol=1e-12)
    assert np.allclose(res["sensor.f"], m2 * a, rtol=1e-12)
    assert np.allclose(res["mass2.v"], a * T, rtol=0, atol=1e-10)
    M = compiled.lagrange.function("M")(0.0, [0.0], [0.0], [], compiled.param_vector())
    assert float(M) == pytest.approx(m1 + m2 - k * m2, rel=1e-14)
