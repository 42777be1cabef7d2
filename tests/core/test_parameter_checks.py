"""One rule for a parameter's value, Parameter.check_scalar: a finite number within its
range, wherever it is set (construction, assignment, simulate's params). NaN and ±inf are
refused with a ParameterError naming ``component.parameter``."""
import math

import numpy as np
import pytest

import acausal
from acausal.components import planar as P
from acausal.components import translational as tr
from acausal.errors import ParameterError

BAD = [math.nan, math.inf, -math.inf, np.float64("nan")]


def oscillator():
    m = acausal.Model("osc")
    m.fixed, m.spring, m.mass = tr.Fixed(), tr.Spring(c=4.0), tr.Mass(m=1.0)
    m.connect(m.fixed.flange, m.spring.flange_a)
    m.connect(m.spring.flange_b, m.mass.flange_a)
    return m


@pytest.mark.parametrize("value", BAD, ids=["nan", "inf", "-inf", "np.nan"])
def test_non_finite_values_are_refused_at_construction(value):
    with pytest.raises(ParameterError, match=r"'Spring\.c' must be a finite number"):
        tr.Spring(c=value)
    with pytest.raises(ParameterError, match=r"'Mass\.m' must be a finite number"):
        tr.Mass(m=value)                        # positive=True: +inf would pass "> 0"
    with pytest.raises(ParameterError, match=r"'Spring\.s_rel0' must be a finite number"):
        tr.Spring(s_rel0=value)                 # no range: only finiteness


@pytest.mark.parametrize("value", BAD, ids=["nan", "inf", "-inf", "np.nan"])
def test_non_finite_values_are_refused_when_assigned_and_at_simulation_time(value):
    m = oscillator()
    with pytest.raises(ParameterError, match=r"'mass\.m' must be a finite number.*finite "
                                             r"value \[kg\]"):
        m.mass.m = value
    compiled = acausal.compile(m)
    with pytest.raises(ParameterError, match=r"'spring\.c' must be a finite number"):
        compiled.simulate(0.1, params={"spring.c": value})
    with pytest.raises(ParameterError, match=r"'spring\.c' must be a finite number"):
        compiled.param_vector({"spring.c": value})


def test_vector_parameter_element_nan_is_refused():
    with pytest.raises(ParameterError, match=r"'Fixed\.r\[2\]' must be a finite number, "
                                             r"got nan"):
        P.Fixed(r=(0.0, math.nan))
    with pytest.raises(ParameterError, match=r"'World\.n\[1\]' must be a finite number, "
                                             r"got inf"):
        P.World(n=(math.inf, -1.0))
    m = acausal.Model("pend")
    m.world, m.fixed, m.rev, m.body = P.World(), P.Fixed(), P.Revolute(), P.Body()
    m.connect(m.fixed.frame, m.rev.frame_a)
    m.connect(m.rev.frame_b, m.body.frame_a)
    compiled = acausal.compile(m)
    with pytest.raises(ParameterError, match=r"'fixed\.r\b.*must be a finite number"):  # r[2]
        compiled.simulate(0.1, params={"fixed.r[2]": math.nan})


@pytest.mark.parametrize("value", [True, np.bool_(False), "2.0", b"2"],
                         ids=["True", "np.False_", "text", "bytes"])
def test_text_and_booleans_are_no_numbers(value):
    """float() would take them (True as 1, "2.0" as 2): a Real parameter does not."""
    with pytest.raises(ParameterError, match=r"'Mass\.m' must be a number"):
        tr.Mass(m=value)
    compiled = acausal.compile(oscillator())
    with pytest.raises(ParameterError, match=r"'spring\.c' must be a number"):
        compiled.simulate(0.1, params={"spring.c": value})


def test_finite_values_still_pass():
    assert tr.Spring(c=1e300).c == 1e300
    assert tr.Mass(m=np.float32(2.0)).m == 2.0 and tr.Mass(m=np.int64(3)).m == 3.0
    assert P.Fixed(r=(1, -2)).r == (1.0, -2.0)


def _buildable_public_classes():
    """Every public component class of acausal.components that builds with its defaults."""
    import warnings

    from acausal.errors import AcausalError
    from library_classes import library_classes
    found = {}
    for name, cls in library_classes().items():
        if cls.__name__.startswith("_"):
            continue
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                cls()
        except AcausalError:            # needs arguments (a table, a required value), partial
            continue
        found[name] = cls
    return found


LIBRARY = _buildable_public_classes()


def test_the_sweep_below_covers_the_library():
    assert len(LIBRARY) > 300


@pytest.mark.parametrize("name", sorted(LIBRARY))
def test_every_component_refuses_bad_values_and_unknown_names_clearly(name):
    """A NaN or a string for any scalar parameter, at construction: a ParameterError naming
    the class and the parameter, never a TypeError from arithmetic on it or a silent NaN;
    an unknown keyword: the package's error (a Model's own signature: Python's TypeError,
    which names it)."""
    import warnings
    from acausal.core import Model
    from acausal.errors import AcausalError
    cls = LIBRARY[name]
    for pname, par in cls.parameters().items():
        if par.size is not None:
            continue
        for value in (math.nan, "abc"):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                with pytest.raises(ParameterError, match=rf"{cls.__name__}\.{pname}'"):
                    cls(**{pname: value})
    refused = (AcausalError, TypeError) if issubclass(cls, Model) else AcausalError
    with pytest.raises(refused, match="no_such_parameter"):
        cls(no_such_parameter=1.0)
