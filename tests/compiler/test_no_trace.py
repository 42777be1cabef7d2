"""Compiling leaves no trace on the components: the compiler keeps its per-compile state in
its own workspace. A model compiled twice gives the same equations, and every component's and
port's attributes are as they were."""
from __future__ import annotations

import copy

import casadi as ca
import numpy as np

import acausal as ac
from acausal.components import rotational as rot
from acausal.components import signals as sig
from acausal.models import GantryCrane


def _attributes(model):
    """Every component's and port's attributes (values copied), by path."""
    out = {}

    def walk(c):
        out[c.path] = {k: copy.copy(v) for k, v in vars(c).items()}
        for name, port in c.ports.items():
            out[f"{c.path}.{name}"] = dict(vars(port))
        for child in c.children.values():
            walk(child)
    walk(model)
    return out


def _motor_model():
    m = ac.Model("motor")
    m.motor, m.load, m.pid = rot.DCMotor(), rot.Inertia(J=0.5), sig.PID()
    m.ref, m.sensor = sig.Constant(k=1.0), rot.SpeedSensor()
    m.connect(m.motor.flange, m.load.flange_a)
    m.connect(m.load.flange_b, m.sensor.flange)
    m.connect(m.ref.y, m.pid.u)
    m.connect(m.pid.y, m.motor.v)
    return m


def test_compiling_twice_leaves_the_components_as_they_were():
    for model in (GantryCrane(), _motor_model()):
        before = _attributes(model)
        first, second = ac.compile(model), ac.compile(model)
        after = _attributes(model)
        assert before.keys() == after.keys()
        for path in before:
            assert before[path].keys() == after[path].keys(), path
        assert first.x_names == second.x_names and first.param_names == second.param_names
        x = np.linspace(0.1, 0.9, first.x.numel())
        p = first.param_vector()
        u = first.input_start
        a = first.f(t=0.3, x=x, u=u, p=p)["xdot"]
        b = second.f(t=0.3, x=x, u=u, p=p)["xdot"]
        np.testing.assert_array_equal(np.array(a), np.array(b))
        # parameters read as numbers again, not as the compile's symbols
        for c in model.children.values():
            for name in c.parameters():
                assert not isinstance(getattr(c, name), (ca.SX, ca.MX)), f"{c.path}.{name}"
