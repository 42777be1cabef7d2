"""MSL's partial classes (interfaces such as SISO, PartialCompliant, PartialFriction): what
their subclasses share, not components by themselves. Building one is refused with a
StructureError that names the subclasses to use; a subclass, the library's or a user's,
builds and works."""
import pytest

import acausal
from acausal.components import translational as tr
from acausal.errors import StructureError
from library_classes import library_classes


CLASSES = library_classes()
PARTIAL = {name: cls for name, cls in CLASSES.items() if cls.__dict__.get("partial")}


def test_every_class_named_partial_is_declared_partial():
    named = {name for name, cls in CLASSES.items() if cls.__name__.lower().startswith("partial")}
    assert named and named <= set(PARTIAL)


@pytest.mark.parametrize("name", sorted(PARTIAL))
def test_a_partial_class_is_refused_naming_what_to_use(name):
    cls = PARTIAL[name]
    with pytest.raises(StructureError, match=rf"{cls.__name__} is a partial class"):
        cls()


def test_the_message_names_the_concrete_subclasses():
    with pytest.raises(StructureError, match=r"use one of its subclasses \(.*\bSpring\b"):
        tr.PartialCompliant()


class LinearSpring(tr.PartialCompliant):
    """A user's element on MSL's PartialCompliant: f = c·s_rel."""
    c = acausal.Parameter(1.0, "N/m", "spring constant", positive=True)

    def force(self, s_rel, v_rel):
        return self.c * s_rel


def test_a_users_subclass_builds_and_oscillates_at_the_closed_form_frequency():
    """m = 2 kg on c = 8 N/m from s = 0.1 m at rest: s(t) = 0.1·cos(2t)."""
    import numpy as np
    m = acausal.Model("osc")
    m.fixed, m.spring, m.mass = tr.Fixed(), LinearSpring(c=8.0), tr.Mass(m=2.0)
    m.connect(m.fixed.flange, m.spring.flange_a)
    m.connect(m.spring.flange_b, m.mass.flange_a)
    t = np.linspace(0.0, 3.0, 61)
    res = acausal.compile(m).simulate(3.0, t=t, x0={"mass.s": 0.1})
    assert np.allclose(res["mass.s"], 0.1 * np.cos(2.0 * t), atol=1e-6)
