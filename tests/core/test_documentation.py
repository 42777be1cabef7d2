"""help() of components: parameters, options and ports from their declarations, as MSL has
them; reprs of parameters, components and compiled models."""
import inspect
import pydoc

import pytest

import acausal as ac
from acausal.components.multibody.joints import Revolute
from acausal.components.multibody.parts import Body
from acausal.components.translational import Fixed, Mass, Spring


def test_help_lists_msl_parameters_with_default_unit_and_description():
    text = pydoc.render_doc(Mass, renderer=pydoc.plaintext)
    # MSL Translational.Components.Mass: parameter SI.Mass m(min=0, start=1) "Mass of the
    # sliding mass"; SI.Length L = 0 "Length of component, from left flange to right flange"
    assert "m : float, default 1 [kg]" in text and "mass of the sliding mass" in text
    assert "L : float, default 0 [m]" in text
    assert "flange_a : TranslationalFlange" in text and "flange_b : TranslationalFlange" in text
    assert "Mass(name: 'str | None' = None, *, L=0.0, m=1.0, stateSelect='default'" in text


def test_signature_has_msl_defaults_required_parameters_and_options():
    sig = inspect.signature(Body)
    # MSL Parts.Body: m and r_CM have no default; I_11 = 0.001; animation = true
    assert sig.parameters["m"].default is inspect.Parameter.empty
    assert sig.parameters["r_CM"].default is inspect.Parameter.empty
    assert sig.parameters["I_11"].default == 0.001
    assert sig.parameters["angles_fixed"].default is False
    rev = inspect.signature(Revolute)
    assert rev.parameters["n"].default == (0.0, 0.0, 1.0)
    assert rev.parameters["useAxisFlange"].default is False
    assert rev.parameters["stateSelect"].default == "prefer"
    rev.bind(n=(1.0, 0.0, 0.0), useAxisFlange=True)      # what the constructor accepts
    with pytest.raises(TypeError):
        rev.bind(nn=1.0)


def test_conditional_ports_say_when_they_exist():
    doc = Revolute.__doc__
    assert "axis : RotationalFlange (if useAxisFlange = True)" in doc
    assert "stateSelect : StateSelect, default 'prefer'" in doc


def test_parameter_and_component_reprs():
    assert repr(Mass.m) == "<Parameter Mass.m = 1.0 [kg] (>= 0): mass of the sliding mass>"
    assert repr(Mass(m=2.0)) == "Mass(L=0.0, m=2.0)"


def test_compiled_model_prints_a_summary():
    m = ac.Model("osc")
    m.wall, m.spring, m.mass = Fixed(), Spring(c=40.0), Mass(m=2.0)
    m.connect(m.wall.flange, m.spring.flange_a)
    m.connect(m.spring.flange_b, m.mass.flange_a)
    text = repr(ac.compile(m))
    assert text.splitlines()[0] == ("CompiledModel 'osc': 2 states, 0 algebraic, "
                                    "5 parameters, 0 inputs, 0 outputs")
    assert "  coordinates  mass.s" in text
    assert "  states       mass.s, mass.v" in text
    assert "spring.c = 40 [N/m]" in text and "mass.m = 2 [kg]" in text
