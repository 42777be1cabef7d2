"""Conditional ports and structural options, declared once in core (ConditionalPort,
``options``): the port exists exactly when its option says so, is listed in ``ports`` only
then, and reading it otherwise raises a DisabledPortError that says how to enable it."""
import inspect
from enum import Enum

import pytest

import acausal
from acausal.components import planar as P
from acausal.components import rotational as rot
from acausal.components import signals, translational as tr
from acausal.core import Component, ConditionalPort, Frame, RealOutput, VectorPort
from acausal.errors import DisabledPortError, ParameterError

# (class, port, option, value enabling it, another value)
CASES = [
    (tr.Force, "support", "useSupport", True, False),
    (tr.Position, "support", "useSupport", True, False),
    (rot.Torque, "support", "useSupport", True, False),
    (rot.IdealGear, "support", "useSupport", True, False),
    (rot.DCMotor, "support", "useSupport", True, False),
    (rot.IdealRollingWheel, "supportR", "useSupportR", True, False),
    (rot.IdealGearR2T, "supportT", "useSupportT", True, False),
    (P.Revolute, "axis", "useFlange", True, False),
    (P.Prismatic, "support", "useFlange", True, False),
    (P.CutForce, "frame_resolve", "resolveInFrame", "frame_resolve", "world"),
    (P.WorldForce, "frame_resolve", "resolveInFrame", "frame_resolve", "frame_b"),
    (P.RelativeVelocity, "frame_resolve", "resolveInFrame", "frame_resolve", "frame_b"),
]


@pytest.mark.parametrize("cls, port, option, on, off", CASES,
                         ids=[f"{c[0].__module__.rsplit('.', 1)[1]}.{c[0].__name__}.{c[1]}"
                              for c in CASES])
def test_port_exists_exactly_when_its_option_holds(cls, port, option, on, off):
    enabled = cls(**{option: on})
    assert port in enabled.ports
    assert getattr(enabled, port) is enabled.ports[port]
    assert getattr(enabled, port).owner is enabled
    for disabled in (cls(), cls(**{option: off})):      # the default disables it, too
        assert port not in disabled.ports
        assert not hasattr(disabled, port)
    m = acausal.Model("m")
    m.part = cls(**{option: off})
    with pytest.raises(DisabledPortError) as err:
        getattr(m.part, port)
    assert isinstance(err.value, AttributeError)
    text = str(err.value)
    for needed in (f"{cls.__name__} 'part'", f"'{port}'", f"{option}={off!r}",
                   f"{cls.__name__}({option}={on!r})"):
        assert needed in text, (needed, text)


def test_enabled_support_is_required_and_takes_the_reaction():
    m = acausal.Model("m")
    m.gear, m.j1, m.j2 = rot.IdealGear(useSupport=True), rot.Inertia(), rot.Inertia()
    m.connect(m.j1.flange_b, m.gear.flange_a)
    m.connect(m.gear.flange_b, m.j2.flange_a)
    with pytest.raises(acausal.StructureError, match=r"gear\.support"):
        acausal.compile(m)


def test_options_are_validated_and_fixed():
    with pytest.raises(ParameterError, match="useSupport.*True or False"):
        tr.Force(useSupport=1)
    with pytest.raises(ParameterError, match=r"resolveInFrame='frame_a'.*ResolveInFrameB"):
        P.WorldForce(resolveInFrame="frame_a")
    assert P.WorldForce(resolveInFrame="world").resolveInFrame is P.ResolveInFrameB.world
    assert P.CutForce(resolveInFrame=P.ResolveInFrameA.frame_resolve).resolveInFrame \
        is P.ResolveInFrameA.frame_resolve
    assert P.CutForce().resolveInFrame is P.ResolveInFrameA.frame_a          # the default
    force = tr.Force()
    with pytest.raises(ParameterError, match=r"structural.*Force\(useSupport=True\)"):
        force.useSupport = True
    with pytest.raises(ParameterError, match="structural"):
        P.CutForce().resolveInFrame = "world"


class Mode(str, Enum):
    plain = "plain"
    measured = "measured"


class Probe(Component):
    """A user component: a Boolean and an enumeration option, each with a conditional port."""
    options = {"useExtra": False, "mode": Mode.plain}
    frame = Frame("always there")
    extra = ConditionalPort(Frame("with useExtra"), "useExtra")
    reading = ConditionalPort(RealOutput("with mode=measured"), "mode", Mode.measured)
    y = VectorPort(RealOutput, 2, "two outputs")


def test_user_components_declare_conditional_ports_the_same_way():
    assert list(Probe().ports) == ["frame", "y[1]", "y[2]"]
    assert list(Probe(useExtra=True, mode="measured").ports) == \
        ["frame", "extra", "reading", "y[1]", "y[2]"]
    with pytest.raises(DisabledPortError, match=r"mode='plain'.*Probe\(mode='measured'\)"):
        Probe().reading                                             # noqa: B018
    p = Probe()
    assert [q.name for q in p.y] == ["y[1]", "y[2]"] and p.y[2] is p.ports["y[2]"]
    assert Probe.extra.port.description == "with useExtra"         # the class declaration


def test_no_component_writes_its_own_attribute_hook():
    """One mechanism: no library component has __getattr__ or a port-creating hook."""
    for module in (tr, rot, P, signals):
        for _, cls in inspect.getmembers(module, inspect.isclass):
            if issubclass(cls, Component) and cls.__module__ == module.__name__:
                assert "__getattr__" not in vars(cls), cls
                assert "_conditional_ports" not in vars(cls), cls
