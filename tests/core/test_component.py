"""Component and Model: parameters and structural options at construction, naming by
assignment, ports per instance; connect() and its errors, each naming the parts at fault.
The library's components serve as ordinary instances here."""
import numpy as np
import pytest

import acausal
from acausal.components import rotational as rot
from acausal.components import translational as tr
from acausal.components.translational import Force, Mass, Spring
from acausal.core import (Component, Input, Model, Output, Parameter, RealInput, RealOutput,
                          RotationalFlange, StateSelect, TranslationalFlange, Unavailable,
                          connect)
from acausal.errors import ParameterError, PortConnectionError


class Pulley(Component):
    """A rotational part with one flange (a test component)."""
    flange = RotationalFlange("axis")


class Slider(Component):
    """A test component with a parameter, a required one, an option and two flanges."""
    options = {"useBrake": False}
    required = ("f_max",)
    m = Parameter(1.0, "kg", "mass", positive=True)
    f_max = Parameter(0.0, "N", "largest force")
    flange_a = TranslationalFlange("left")
    flange_b = TranslationalFlange("right")


class BrakedSlider(Slider):
    options = {"useHeat": True}
    d = Parameter(0.5, "N.s/m", "brake damping")


# ---- construction: parameters and options ---------------------------------------------------
def test_unknown_parameter_at_construction():
    with pytest.raises(acausal.ParameterError) as err:
        Spring(s_rel_0=0.1)
    assert "s_rel_0" in str(err.value) and "s_rel0" in str(err.value)


@pytest.mark.parametrize("value", [-1e-9, -1.0])
def test_negative_mass_at_construction(value):
    """MSL's Mass.m has min = 0: a negative mass is refused, m = 0 (a massless flange) is
    legal (its compile: tests/components/test_translational.py)."""
    with pytest.raises(acausal.ParameterError, match=r"\bm\b.*>= 0"):
        Mass(m=value)
    mass = Mass()
    with pytest.raises(acausal.ParameterError, match=r"\bm\b.*>= 0"):
        mass.m = value
    assert Mass(m=0.0).m == 0.0


def test_non_number_parameter():
    with pytest.raises(acausal.ParameterError, match=r"\bc\b"):
        Spring(c="stiff")


def test_unknown_parameter_and_option_errors():
    with pytest.raises(ParameterError, match=r"Spring has no parameter 'k'.*\bc\b"):
        tr.Spring(k=3.0)
    with pytest.raises(ParameterError, match="useSupport"):
        tr.Force(useSupport="yes")
    with pytest.raises(ParameterError, match=r"'f_constant'.*no default.*ConstantForce"):
        tr.ConstantForce()
    with pytest.raises(ParameterError, match=r"'f_nominal', 'v_nominal'"):
        tr.QuadraticSpeedDependentForce()
    with pytest.raises(AttributeError, match="useSupport=True"):
        tr.Force().support
    with pytest.raises(ParameterError, match="structural"):
        tr.Position().exact = True


def test_parameters_options_and_required_parameters_of_a_component():
    s = BrakedSlider(f_max=10, useBrake=True)
    assert (s.m, s.f_max, s.d, s.useBrake, s.useHeat) == (1.0, 10.0, 0.5, True, True)
    assert list(BrakedSlider.parameters()) == ["m", "f_max", "d"]      # base class first
    assert BrakedSlider.all_options() == {"useBrake": False, "useHeat": True}
    with pytest.raises(ParameterError) as err:
        Slider(f_max=1.0, k=2.0)
    assert str(err.value) == ("Slider has no parameter 'k' (its parameters and options: m, "
                              "f_max, useBrake)")
    with pytest.raises(ParameterError) as err:
        Slider()
    assert str(err.value) == ("Slider: parameter(s) 'f_max' have no default (as in MSL); give "
                              "them: Slider(f_max=...)")
    with pytest.raises(ParameterError) as err:
        Slider(f_max=1.0, useBrake=1)
    assert str(err.value) == "Slider: option 'useBrake' must be True or False, got 1"
    model = Model("rig")
    model.slider = Slider(f_max=1.0)
    with pytest.raises(ParameterError) as err:
        model.slider.useBrake = True
    assert str(err.value) == ("Slider 'slider': option 'useBrake' is structural and fixed when "
                              "the component is created: Slider(useBrake=True)")


# ---- naming and ports -----------------------------------------------------------------------
def test_assignment_names_components_and_ports_by_their_dotted_path():
    outer, inner = Model("plant"), Model("inner")
    inner.slider = Slider(f_max=1.0)
    outer.stage = inner
    assert (outer.path, inner.path, inner.slider.path) == ("", "stage", "stage.slider")
    assert inner.slider.name == "slider" and inner.slider.owner is inner
    assert inner.slider.flange_a.path == "stage.slider.flange_a"
    assert inner.slider.flange_a.owner is inner.slider
    assert outer.children == {"stage": inner} and inner.children == {"slider": inner.slider}
    assert list(inner.slider.ports) == ["flange_a", "flange_b"]
    assert repr(inner.slider) == "Slider(m=1.0, f_max=1.0) at 'stage.slider'"


def test_every_instance_has_its_own_ports():
    a, b = Slider(f_max=1.0), Slider(f_max=1.0)
    assert a.flange_a is not b.flange_a and a.flange_a is not Slider.flange_a
    assert isinstance(a.flange_a, TranslationalFlange) and a.flange_a.kind == "translational"


def test_a_component_belongs_to_one_model():
    first, second = Model("first"), Model("second")
    first.mass = Mass()
    with pytest.raises(PortConnectionError) as err:
        second.mass = first.mass
    assert str(err.value) == ("component 'mass' already belongs to a model; create a new one "
                              "for 'mass'")


def test_an_option_not_available_yet_accepts_only_its_off_value():
    """MSL options acausal does not implement yet (``Unavailable``) take their "off" value
    and refuse the other naming what is missing; stateSelect is accepted as a hint."""
    class Heated(Component):
        options = {"useHeatPort": Unavailable(False, "the heatPort")}

    assert Heated().useHeatPort is False and Heated.all_options() == {"useHeatPort": False}
    with pytest.raises(ParameterError) as err:
        Heated(useHeatPort=True)
    assert str(err.value) == ("Heated: useHeatPort=True is not available yet (the heatPort); "
                              "leave useHeatPort=False, the default")
    with pytest.raises(ParameterError, match="must be True or False"):
        Heated(useHeatPort="no")
    for cls in (tr.Damper, tr.SpringDamper, rot.Damper, rot.SpringDamper):
        assert "heatPort" not in cls(useHeatPort=False).ports
        assert "heatPort" in cls(useHeatPort=True).ports        # MSL's conditional heatPort
    assert rot.Inertia(stateSelect="always").stateSelect is StateSelect.always
    assert tr.Mass(stateSelect=StateSelect.never).stateSelect is StateSelect.never
    assert tr.Damper().stateSelect is StateSelect.prefer              # MSL's default there


def test_a_component_has_one_name_in_its_model():
    """Assigning a part a second name would put it in the model twice (its parameters
    listed twice, an oscillator moving like twice the mass): refused, naming both names.
    The model is left with the one mass: its period is 2π·sqrt(m/c) (closed form)."""
    m = Model("osc")
    m.fixed, m.spring, m.mass = tr.Fixed(), Spring(c=4.0), Mass(m=1.0)
    with pytest.raises(PortConnectionError) as err:
        m.other = m.mass
    assert str(err.value) == ("component 'mass' is already part of this model; assigning it "
                              "to 'other' too would put it in the model twice: use 'mass' "
                              "itself, or create a new component for 'other'")
    m.mass = m.mass                                   # the same name again: nothing changes
    assert list(m.children) == ["fixed", "spring", "mass"]
    connect(m.fixed.flange, m.spring.flange_a)
    connect(m.spring.flange_b, m.mass.flange_a)
    compiled = acausal.compile(m)
    assert compiled.param_names.count("mass.m") == 1
    t = np.linspace(0.0, 2.0, 201)
    res = compiled.simulate(2.0, t=t, x0={"mass.s": 0.1})
    np.testing.assert_allclose(res["mass.s"], 0.1 * np.cos(2.0 * t), atol=1e-6,
                               err_msg="s = s0·cos(√(c/m)·t) with one mass m = 1, c = 4")


def test_a_port_has_one_owner():
    m = Model("m")
    m.mass = Mass()
    with pytest.raises(PortConnectionError) as err:
        m.end = m.mass.flange_b
    assert str(err.value) == ("port 'mass.flange_b' already belongs to Mass 'mass'; assigning "
                              "it to 'end' too would give one port two names: use "
                              "'mass.flange_b' itself (connect it), or create a new port for "
                              "'end'")
    assert m.mass.flange_b.path == "mass.flange_b" and "end" not in m.ports


# ---- connect --------------------------------------------------------------------------------
def test_mismatched_port_kinds():
    m = acausal.Model("m")
    m.mass, m.pulley = Mass(), Pulley()
    with pytest.raises(acausal.PortConnectionError) as err:
        m.connect(m.mass.flange_a, m.pulley.flange)
    msg = str(err.value)
    assert "mass.flange_a" in msg and "pulley.flange" in msg
    assert "translational" in msg and "rotational" in msg


def test_translational_to_rotational_connection_names_both_ports():
    class Shaft(Component):
        flange = RotationalFlange("a rotational flange")

    m = acausal.Model("mix")
    m.mass = tr.Mass()
    m.shaft = Shaft()
    with pytest.raises(PortConnectionError) as err:
        m.connect(m.mass.flange_a, m.shaft.flange)
    assert "mass.flange_a" in str(err.value) and "shaft.flange" in str(err.value)


def test_signal_to_flange_is_rejected():
    m = acausal.Model("m")
    m.mass, m.push = Mass(), Force()
    with pytest.raises(acausal.PortConnectionError, match=r"push\.f.*mass\.flange_a"):
        m.connect(m.push.f, m.mass.flange_a)


def test_connect_refuses_what_is_not_a_port_of_a_component():
    m = Model("m")
    m.mass, m.pulley = Mass(), Pulley()
    with pytest.raises(PortConnectionError, match=r"^connect\(\) takes ports, got "):
        m.connect(m.mass, m.mass.flange_a)
    loose = TranslationalFlange("not assigned to a component")
    with pytest.raises(PortConnectionError, match=r"is not part of a component$"):
        m.connect(loose, m.mass.flange_a)
    with pytest.raises(PortConnectionError) as err:
        m.connect(m.mass.flange_a, m.mass.flange_a)
    assert str(err.value) == "cannot connect port 'mass.flange_a' to itself"
    assert m.connections == []


def test_two_outputs_cannot_be_connected():
    m = Model("m")
    m.a, m.b = Input(), Input()
    with pytest.raises(PortConnectionError) as err:
        m.connect(m.a.y, m.b.y)
    assert str(err.value) == "cannot connect two outputs 'a.y' and 'b.y': an output drives inputs"


def test_connect_records_the_connection_in_the_innermost_common_model():
    plant, stage = Model("plant"), Model("stage")
    stage.a, stage.b = Mass(), Mass()
    plant.stage, plant.c = stage, Mass()
    connect(stage.a.flange_b, stage.b.flange_a)
    connect(stage.b.flange_b, plant.c.flange_a)
    assert stage.connections == [(stage.a.flange_b, stage.b.flange_a)]
    assert plant.connections == [(stage.b.flange_b, plant.c.flange_a)]
    plant.connect(plant.c.flange_b, stage.a.flange_a)         # the method: this model
    assert plant.connections[-1] == (plant.c.flange_b, stage.a.flange_a)
    other = Model("other")
    other.d = Mass()
    with pytest.raises(PortConnectionError) as err:
        connect(plant.c.flange_b, other.d.flange_a)
    assert str(err.value) == ("'c.flange_b' and 'd.flange_a' are not in one model: assign both "
                              "components to attributes of the same Model before connecting "
                              "them")


# ---- Input and Output -----------------------------------------------------------------------
def test_input_and_output_are_the_models_signal_interface():
    m = Model("m")
    m.F = Input(start=2, unit="N", description="push")
    m.x = Output(unit="m", description="position")
    assert (m.F.start, m.F.unit, m.F.description) == (2.0, "N", "push")
    assert isinstance(m.F.start, float)
    assert (m.x.unit, m.x.description) == ("m", "position")
    assert isinstance(m.F.y, RealOutput) and isinstance(m.x.u, RealInput)
    assert (m.F.y.path, m.x.u.path) == ("F.y", "x.u")
    assert Input().start == 0.0 and Input().unit == "" and Output().description == ""
    m.connect(m.F.y, m.x.u)
    assert m.connections == [(m.F.y, m.x.u)]
