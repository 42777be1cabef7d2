"""Parameter: declared on a component class, checked when set (at construction and on
assignment), read as the value; vector parameters numbered from 1 as in Modelica."""
import pytest

from acausal.core import Component, Model, Parameter
from acausal.errors import ParameterError


class Probe(Component):
    """A test component with one parameter of each kind."""
    m = Parameter(1, "kg", "mass", positive=True)
    d = Parameter(0.0, "N.s/m", "damping", nonnegative=True)
    ratio = Parameter(2.0, "", "gear ratio", nonzero=True)
    r = Parameter((0, 1.5), "m", "position")


def test_declaration_records_default_unit_and_description():
    m = Probe.parameters()["m"]
    assert (m.name, m.default, m.unit, m.description, m.size) == ("m", 1.0, "kg", "mass", None)
    assert isinstance(m.default, float)
    r = Probe.parameters()["r"]
    assert (r.default, r.size) == ((0.0, 1.5), 2)
    assert r.element_names() == ["r[1]", "r[2]"] and m.element_names() == ["m"]
    assert list(Probe.parameters()) == ["m", "d", "ratio", "r"]


def test_instance_reads_defaults_and_given_values_as_floats():
    p = Probe(m=3, r=[1, 2])
    assert (p.m, p.d, p.ratio, p.r) == (3.0, 0.0, 2.0, (1.0, 2.0))
    assert isinstance(p.m, float)
    p.d = 0.5
    assert p.d == 0.5
    assert Probe.m.default == 1.0                  # the class attribute is the declaration


@pytest.mark.parametrize("kw, message", [
    ({"m": 0.0}, "parameter 'Probe.m' must be > 0 (mass), got 0.0"),
    ({"m": -1.0}, "parameter 'Probe.m' must be > 0 (mass), got -1.0"),
    ({"d": -0.1}, "parameter 'Probe.d' must be >= 0 (damping), got -0.1"),
    ({"ratio": 0.0}, "parameter 'Probe.ratio' must not be 0 (gear ratio)"),
    ({"m": "heavy"}, "parameter 'Probe.m' must be a number, got 'heavy'"),
    ({"r": (1.0, 2.0, 3.0)}, "parameter 'Probe.r' takes 2 values, got (1.0, 2.0, 3.0)"),
    ({"r": 1.0}, "parameter 'Probe.r' takes 2 values, got 1.0"),
    ({"r": "ab"}, "parameter 'Probe.r' takes 2 values, got 'ab'"),
    ({"r": (1.0, "x")}, "parameter 'Probe.r[2]' must be a number, got 'x'"),
])
def test_bad_values_at_construction_name_the_parameter(kw, message):
    with pytest.raises(ParameterError) as err:
        Probe(**kw)
    assert str(err.value) == message


def test_assignment_is_checked_and_names_the_instance_path():
    model = Model("rig")
    model.probe = Probe()
    with pytest.raises(ParameterError) as err:
        model.probe.m = 0.0
    assert str(err.value) == "parameter 'probe.m' must be > 0 (mass), got 0.0"
    assert model.probe.m == 1.0                    # the bad value was not stored
