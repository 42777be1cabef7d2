"""A model's own signal connectors as the inputs and outputs of the compiled model, against
closed forms."""
from __future__ import annotations

import numpy as np
import pytest

import acausal
from acausal.components import translational as tr
from acausal.components.signals import Constant
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


def test_an_unconnected_root_output_is_named():
    with pytest.raises(StructureError, match="output 's' of model 'PushedMass'"):
        acausal.compile(PushedMass("PushedMass", connect_s=False))

