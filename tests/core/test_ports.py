"""Ports: the physical domains (potentials, flows and their units), the signal ports, and port
vectors numbered from 1 as in Modelica."""
import pytest

from acausal.core import (PLANAR, ROTATIONAL, TRANSLATIONAL, Frame, PortVector, RealInput,
                          RealOutput, RotationalFlange, TranslationalFlange)


def test_domains_name_their_potentials_flows_and_units():
    assert (TRANSLATIONAL.potentials, TRANSLATIONAL.flows, TRANSLATIONAL.dim) == \
        (("s",), ("f",), 1)
    assert (TRANSLATIONAL.potential_units, TRANSLATIONAL.flow_units,
            TRANSLATIONAL.velocity_units) == (("m",), ("N",), ("m/s",))
    assert (ROTATIONAL.potentials, ROTATIONAL.flows, ROTATIONAL.flow_units) == \
        (("phi",), ("tau",), ("N.m",))
    assert (PLANAR.potentials, PLANAR.flows, PLANAR.dim) == \
        (("x", "y", "phi"), ("fx", "fy", "t"), 3)
    assert PLANAR.potential_units == ("m", "m", "rad")


def test_port_kinds_and_which_must_be_connected():
    kinds = [(p.kind, p.required) for p in (TranslationalFlange(), RotationalFlange(), Frame(),
                                            RealInput(), RealOutput())]
    assert kinds == [("translational", False), ("rotational", False), ("planar", False),
                     ("signal", True), ("signal", False)]
    assert TranslationalFlange(required=True).required
    port = RealInput("the set point")
    assert (port.description, port.path, repr(port)) == ("the set point", "", "<RealInput >")


def test_port_vector_is_numbered_from_one():
    items = [RealInput(), RealInput(), RealInput()]
    u = PortVector("Sum", "u", items)
    assert (u[1], u[3], len(u), list(u)) == (items[0], items[2], 3, items)
    for bad in (0, 4, "1"):
        with pytest.raises(IndexError) as err:
            u[bad]
        index = bad if isinstance(bad, int) else None
        assert str(err.value) == (f"Sum.u[{index}]: index out of range; the elements are "
                                  f"numbered 1..3 as in Modelica")
