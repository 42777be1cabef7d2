"""Component, Model and connect(): the modelling language.

A Component declares parameters (class attributes of type Parameter) and ports (class
attributes of a Port type; each instance gets its own copies). It describes itself to the
compiler in two phases, both optional:

``structure(self, s)``
    kinematic relations between its ports (rigid, gear-like, prescribed in time), internal
    nodes, internal states and algebraic variables (``s`` is the compiler's StructureBuilder);
``physics(self, e)``
    given the symbolic motion of its ports, its kinetic and potential energy, the flows
    (forces, torques) on its ports, state derivatives, residual equations, outputs and
    recorded variables (``e`` is the compiler's PhysicsBuilder).

Ports are declared as class attributes; a port that exists only for some structural options
(MSL's ``Support support if useSupport``) is declared once with ``ConditionalPort``, a vector
connector (``RealInput u[3]``) with ``VectorPort``.

A Model is a component made of components: assigning a component or port to an attribute of
a model names it; ``connect(a, b)`` joins two ports acausally.
"""
from __future__ import annotations

import functools
from enum import Enum

from ..errors import DisabledPortError, ParameterError, PortConnectionError, StructureError
from . import documentation
from .parameter import Parameter
from .ports import PhysicalPort, Port, PortVector, RealOutput, VectorPort


def who(c: "Component") -> str:
    """``Force 'drive.force'``: a component's type and path (only the type outside a model)."""
    where = c.path or c.name
    return f"{type(c).__name__} '{where}'" if where else type(c).__name__


def _shown(value) -> str:
    """An option value as written in a call: True, 'frame_resolve'."""
    return repr(value.value if isinstance(value, Enum) else value)


@functools.cache
def _class_options(cls) -> dict:
    """``Component._option_specs``, once per class."""
    out: dict = {}
    for klass in reversed(cls.__mro__):
        out.update(vars(klass).get("options", {}))
    return out


@functools.cache
def _class_declarations(cls, types) -> dict:
    """``Component._declared``, once per class (a model has many instances of a class)."""
    out = {}
    for klass in reversed(cls.__mro__):
        for n, v in vars(klass).items():
            if isinstance(v, types):
                out[n] = v
    return out


@functools.cache
def _class_defaults(cls) -> dict:
    """The default values of a class's parameters, by name (each instance copies them)."""
    return {name: par.default for name, par in _class_declarations(cls, Parameter).items()}


@functools.cache
def _class_ports(cls) -> tuple[list, list, list]:
    """A class's declared ports as (name, template) pairs: plain ports, ConditionalPorts,
    VectorPorts, each in declaration order."""
    ports = _class_declarations(cls, (Port, ConditionalPort, VectorPort)).items()
    return ([(n, t) for n, t in ports if isinstance(t, Port)],
            [(n, t) for n, t in ports if isinstance(t, ConditionalPort)],
            [(n, t) for n, t in ports if isinstance(t, VectorPort)])


class StateSelect(str, Enum):
    """Modelica's StateSelect, the priority of a variable as a state, accepted as the option
    ``stateSelect`` where MSL / PlanarMechanics declare it. The compiler chooses the
    coordinates itself (joint coordinates where the joint graph is a tree, one node per
    rigid cluster); stateSelect matters only where the choice of states changes the results
    in Modelica, at a reinit: a velocity a component records with stateSelect prefer or
    always (MSL's relative states v_rel, w_rel) keeps its value at another component's
    reinit, as a Modelica tool's state would (``PhysicsBuilder.reinit``)."""
    never = "never"
    avoid = "avoid"
    default = "default"
    prefer = "prefer"
    always = "always"


class Unavailable:
    """An MSL structural option whose other values acausal does not implement yet, declared
    in ``options`` as ``{"useHeatPort": Unavailable(False, "the heat port (the thermal
    domain)")}``: its value ``off`` (MSL's default, which changes nothing) is accepted, any
    other is refused with a ParameterError saying ``what`` is not available yet."""

    def __init__(self, off, what: str):
        self.off, self.what = off, what


class ConditionalPort:
    """A port that exists only when the structural option ``option`` equals ``value``
    (MSL's ``Flange_b support if useSupport``), declared as a class attribute::

        support = ConditionalPort(Flange("support/housing of component", required=True),
                                  "useSupport")
        frame_resolve = ConditionalPort(Frame("..."), "resolveInFrame", "frame_resolve")

    A component built with another value has no such port: it is not in ``ports`` and
    reading it raises a DisabledPortError that says how to enable it.
    """

    def __init__(self, port: Port, option: str, value=True):
        self.port, self.option, self.value = port, option, value
        self.name = ""

    def __set_name__(self, owner, name):
        self.name = name

    def exists(self, component: "Component") -> bool:
        if self.option not in component.all_options():
            raise TypeError(f"{type(component).__name__}.{self.name} depends on option "
                            f"'{self.option}', which the class does not declare")
        return getattr(component, self.option) == self.value

    def __get__(self, instance, owner=None):
        if instance is None:
            return self
        kind = type(instance).__name__
        raise DisabledPortError(
            f"{who(instance)} has no port '{self.name}' ({self.port.description}): it was "
            f"built with {self.option}={_shown(getattr(instance, self.option))}; create it "
            f"with {kind}({self.option}={_shown(self.value)}) to have it")


def _refuse_partial(cls: type) -> None:
    """The StructureError for building the partial class ``cls``, naming its subclasses."""
    concrete, todo = [], list(cls.__subclasses__())
    while todo:
        sub = todo.pop(0)
        if sub.__dict__.get("partial"):
            todo += sub.__subclasses__()
        elif not sub.__name__.startswith("_") and sub.__name__ not in concrete:
            concrete.append(sub.__name__)
    use = f"use one of its subclasses ({', '.join(concrete[:8])}" \
        f"{', ...' if len(concrete) > 8 else ''}), or " if concrete else ""
    raise StructureError(f"{cls.__name__} is a partial class (MSL's 'partial'): it declares what "
                         f"its subclasses share and is not a component by itself; {use}extend "
                         f"it with the equations it leaves open")


class Component:
    """Base of every component.

    Keyword arguments set parameters by name, and structural options: ``options`` (a class
    attribute, name -> default) are MSL's structural parameters, a Boolean such as
    ``useSupport`` or an enumeration such as ``resolveInFrame`` (the default is then a member
    of the Enum, and a value is given as a member or its name). They read as
    ``self.<name>``, are fixed once the component is built, and decide which
    ``ConditionalPort`` exist. ``required`` names parameters that have no default (MSL
    declares them without a value): they must be given.

    A class that declares ``partial = True`` in its own body is MSL's ``partial`` class:
    what its subclasses share (interfaces, PartialCompliant, PartialFriction); building it
    raises a StructureError naming the subclasses to use instead.

    ``nominal={"w_rel": 1e-4}`` sets the nominal magnitude (the scale of the integrator's
    absolute error control, Modelica's ``w_rel(nominal=1e-4)``) of variables of this
    component by their names relative to it (``"frame_a.x"``, ``"phi"``); it replaces the
    nominal the component declares for them (see ``acausal.compiler.CompiledModel.nominal``
    for how a variable's nominal reaches the states).
    """
    options: dict[str, bool | Enum] = {}
    required: tuple[str, ...] = ()

    def __init_subclass__(cls, **kwargs):
        """Write the class's parameters, options and ports into its docstring and call
        signature (``acausal.core.documentation``): what ``help()`` shows."""
        super().__init_subclass__(**kwargs)
        parameters, options = cls.parameters(), cls.all_options()
        cls.__doc__ = documentation.reference(cls.__doc__, parameters, cls.required, options,
                                              port_rows(cls))
        cls.__signature__ = documentation.signature(cls.__init__, parameters, cls.required,
                                                    options)

    def __init__(self, name: str | None = None, **params):
        d = self.__dict__
        cls = type(self)
        if cls.__dict__.get("partial"):
            _refuse_partial(cls)
        d["_owner"] = None
        d["_name"] = name or ""
        d["_children"] = {}
        d["_ports"] = {}
        kind = cls.__name__
        opts = {key: _option(kind, key, spec, params.pop(key, _default(spec)))
                for key, spec in _class_options(cls).items()}
        d["_nominal"] = _nominals(kind, params.pop("nominal", None))
        declared = _class_declarations(cls, Parameter)
        d["_values"] = values = dict(_class_defaults(cls))
        for pname, value in params.items():
            par = declared.get(pname)
            if par is None:
                known = ", ".join(list(declared) + list(opts)) or "none"
                raise ParameterError(
                    f"{kind} has no parameter '{pname}' (its parameters and options: {known})")
            values[pname] = par.check(value, kind)
        missing = [p for p in self.required if p not in params]
        if missing:
            given = ", ".join(f"{p}=..." for p in missing)
            raise ParameterError(f"{kind}: parameter(s) {', '.join(repr(p) for p in missing)} "
                                 f"have no default (as in MSL); give them: {kind}({given})")
        d.update(opts)
        plain, conditional, vectors = _class_ports(cls)
        for pname, template in plain:                  # plain ports first, as declared
            self._own_port(pname, template)
        for pname, template in conditional:
            if template.exists(self):
                self._own_port(pname, template.port)
        for pname, template in vectors:
            items = []
            for i, text in enumerate(template.descriptions, start=1):
                setattr(self, f"{pname}[{i}]", template.port_cls(text))
                items.append(self._ports[f"{pname}[{i}]"])
            d[pname] = PortVector(kind, pname, items)

    def _own_port(self, name: str, template: Port) -> None:
        """Give this new component its own copy of a declared port (what assigning the copy
        does, without the checks a port made elsewhere needs)."""
        port = _port_copy(template)
        port.owner, port.name = self, name
        self._ports[name] = self.__dict__[name] = port

    @classmethod
    def _option_specs(cls) -> dict:
        """The ``options`` of this class and its bases, as declared (a subclass's replace its
        base's)."""
        return dict(_class_options(cls))

    @classmethod
    def all_options(cls) -> dict[str, bool | Enum]:
        """The structural options of this class and its bases, with their defaults."""
        return {key: _default(spec) for key, spec in cls._option_specs().items()}

    @classmethod
    def _declared(cls, types) -> dict:
        """Class attributes that are instances of ``types``, by name, in declaration order
        (base classes first; a subclass's declaration replaces its base's)."""
        return dict(_class_declarations(cls, types))

    # ---- naming ------------------------------------------------------------------------
    @classmethod
    def parameters(cls) -> dict[str, Parameter]:
        """The declared parameters, by name, in declaration order (base classes first)."""
        return cls._declared(Parameter)

    @property
    def name(self) -> str:
        return self._name

    @property
    def owner(self) -> "Component | None":
        return self._owner

    @property
    def path(self) -> str:
        """Dotted name relative to the outermost model (which itself has no prefix)."""
        if self._owner is None:
            return ""
        parent = self._owner.path
        return f"{parent}.{self._name}" if parent else self._name

    @property
    def ports(self) -> dict[str, Port]:
        return dict(self._ports)

    @property
    def children(self) -> dict[str, "Component"]:
        return dict(self._children)

    def __setattr__(self, key, value):
        if key in _class_options(type(self)):
            raise ParameterError(f"{who(self)}: option '{key}' is structural and fixed when "
                                 f"the component is created: "
                                 f"{type(self).__name__}({key}={_shown(value)})")
        if isinstance(value, Port) and not key.startswith("_"):
            if value.owner is not None and (value.owner is not self or value.name != key):
                raise PortConnectionError(
                    f"port '{value.path}' already belongs to {who(value.owner)}; assigning it "
                    f"to '{_attribute(self, key)}' too would give one port two names: use "
                    f"'{value.path}' itself (connect it), or create a new port for '{key}'")
            value.owner, value.name = self, key
            self._ports[key] = value
        elif isinstance(value, Component) and not key.startswith("_"):
            if value._owner is self and value._name != key:
                raise PortConnectionError(
                    f"component '{value.path}' is already part of this model; assigning it to "
                    f"'{_attribute(self, key)}' too would put it in the model twice: use "
                    f"'{value.path}' itself, or create a new component for '{key}'")
            if value._owner is not None and value._owner is not self:
                raise PortConnectionError(
                    f"component '{value.path}' already belongs to a model; create a new one "
                    f"for '{key}'")
            value.__dict__["_owner"], value.__dict__["_name"] = self, key
            self._children[key] = value
        object.__setattr__(self, key, value)

    def __repr__(self):
        vals = ", ".join(f"{k}={v}" for k, v in self._values.items())
        where = self.path or self._name
        return f"{type(self).__name__}({vals})" + (f" at '{where}'" if where else "")

    # ---- the two phases (defaults: nothing) ----------------------------------------------
    def structure(self, s) -> None:
        """Declare kinematic relations, internal nodes and states. Default: none."""

    def physics(self, e) -> None:
        """Contribute energies, flows, state derivatives, outputs. Default: none."""


class BoundParameters:
    """Mixin of a component with MSL's bound parameters (``uMin = -uMax``, ``T = T_ref``):
    such a parameter is a property of the class reading its binding (so it follows the
    other parameter, also when that one is changed at simulation time) unless it is given
    at construction, which builds the class's twin declaring it as a parameter of its own
    (``bound_twin``)."""

    def __new__(cls, name=None, **params):
        for key in params:
            twin = vars(cls).get(f"_twin_{key}")
            if twin is not None:
                return super().__new__(twin)
        return super().__new__(cls)


def bound_twin(cls: type, name: str, parameter: Parameter) -> type:
    """Register on ``cls`` (a BoundParameters) its twin declaring ``name`` as ``parameter``,
    the class ``cls(name=...)`` builds; it shows cls's name in messages. Returns ``cls``
    (usable as a decorator)."""
    attribute = f"_twin_{name}"
    setattr(cls, attribute, type(cls.__name__, (cls,), {
        "__module__": cls.__module__, "__qualname__": f"{cls.__qualname__}.{attribute}",
        "__doc__": cls.__doc__, name: parameter}))
    return cls


def port_rows(cls) -> list[tuple[str, str, str, str]]:
    """(name, type, description, condition) of the ports a component class declares."""
    rows = []
    for name, t in cls._declared((Port, ConditionalPort, VectorPort)).items():
        if isinstance(t, Port):
            rows.append((name, type(t).__name__, t.description, ""))
        elif isinstance(t, ConditionalPort):
            rows.append((name, type(t.port).__name__, t.port.description,
                         f"{t.option} = {documentation.shown(t.value)}"))
        else:
            rows.append((f"{name}[{len(t.descriptions)}]", t.port_cls.__name__,
                         t.descriptions[0].removesuffix(" [1]"), ""))
    return rows


def _attribute(owner: Component, key: str) -> str:
    """The dotted name an attribute ``key`` of ``owner`` would have."""
    return f"{owner.path}.{key}" if owner.path else key


def _port_copy(template: Port) -> Port:
    """A component's own port from its class's template: what ``copy.copy`` gives (ports are
    plain objects), without its generic machinery (a third of building a large model)."""
    port = object.__new__(type(template))
    port.__dict__.update(template.__dict__)
    return port


def _default(spec):
    """An option's default, from its declaration in ``options``."""
    return spec.off if isinstance(spec, Unavailable) else spec


def _option(kind: str, key: str, spec, value):
    """An option's value, checked against the type of its default (bool or an Enum) and,
    for an Unavailable option, refused unless it is the value that changes nothing."""
    default = _default(spec)
    value = _typed_option(kind, key, default, value)
    if isinstance(spec, Unavailable) and value != spec.off:
        raise ParameterError(f"{kind}: {key}={_shown(value)} is not available yet "
                             f"({spec.what}); leave {key}={_shown(spec.off)}, the default")
    return value


def _typed_option(kind: str, key: str, default, value):
    """An option's value, checked against the type of its default (bool or an Enum)."""
    if isinstance(default, Enum):
        try:
            return type(default)(value)
        except ValueError:
            allowed = ", ".join(m.value for m in type(default))
            raise ParameterError(f"{kind}: {key}={_shown(value)} is not one of "
                                 f"{type(default).__name__} ({allowed})") from None
    if not isinstance(value, bool):
        raise ParameterError(f"{kind}: option '{key}' must be True or False, got {value!r}")
    return value


def _nominals(kind: str, given) -> dict[str, float]:
    """The ``nominal`` keyword: variable name -> a finite number > 0."""
    if given is None:
        return {}
    if not isinstance(given, dict):
        raise ParameterError(f"{kind}: nominal must be a dict of variable name -> nominal "
                             f"magnitude, e.g. nominal={{'w_rel': 1e-4}}; got {given!r}")
    out = {}
    for name, value in given.items():
        try:
            v = float(value)
        except (TypeError, ValueError):
            v = float("nan")
        if not (isinstance(name, str) and v > 0 and v < float("inf")):
            raise ParameterError(f"{kind}: nominal of '{name}' must be a finite number > 0, "
                                 f"got {value!r}")
        out[name] = v
    return out


class Model(Component):
    """A component made of components, connected by ``connect``.

    Subclass it and build the parts in ``__init__``, or build one ad hoc::

        m = Model("osc")
        m.fixed = Fixed(); m.spring = Spring(c=10); m.mass = Mass(m=1)
        m.connect(m.fixed.flange, m.spring.flange_a)
    """

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        self.__dict__["_connections"] = []

    @property
    def connections(self) -> list[tuple[Port, Port]]:
        return list(self._connections)

    def connect(self, a: Port, b: Port) -> None:
        """Join ports ``a`` and ``b``: potentials equal, flows sum to zero (signals: b = a)."""
        _check_connectable(a, b)
        self._connections.append((a, b))


def connect(a: Port, b: Port) -> None:
    """Join two ports; the connection belongs to the innermost model that holds both."""
    _check_connectable(a, b)
    holder = _common_model(a, b)
    holder._connections.append((a, b))


def _check_connectable(a, b) -> None:
    for p in (a, b):
        if not isinstance(p, Port):
            raise PortConnectionError(f"connect() takes ports, got {p!r}")
        if p.owner is None:
            raise PortConnectionError(f"port {p!r} is not part of a component")
    if a is b:
        raise PortConnectionError(f"cannot connect port '{a.path}' to itself")
    if isinstance(a, PhysicalPort) != isinstance(b, PhysicalPort) or (
            isinstance(a, PhysicalPort) and a.domain != b.domain):
        raise PortConnectionError(
            f"cannot connect '{a.path}' ({a.kind}) to '{b.path}' ({b.kind}): ports of "
            f"different kinds; use a component that converts between them "
            f"(e.g. IdealRollingWheel or IdealGearR2T for rotational <-> translational)")
    if a.kind != b.kind:
        raise PortConnectionError(
            f"cannot connect '{a.path}' ({a.kind}) to '{b.path}' ({b.kind}): a Boolean signal "
            f"connects to Boolean ports only; convert it with a BooleanToReal or RealToBoolean "
            f"block")
    if isinstance(a, RealOutput) and isinstance(b, RealOutput) and not (
            _exports(a, b) or _exports(b, a)):
        raise PortConnectionError(
            f"cannot connect two outputs '{a.path}' and '{b.path}': an output drives inputs")


def _exports(outer: Port, inner: Port) -> bool:
    """Whether ``outer`` is an output of a model that holds ``inner``'s component: the
    model's output, driven from inside by ``inner``."""
    return isinstance(outer.owner, Model) and outer.owner in _ancestors(inner.owner)[1:]


def _ancestors(c):
    out = []
    while c is not None:
        out.append(c)
        c = c.owner
    return out


def _common_model(a: Port, b: Port) -> Model:
    up_a = _ancestors(a.owner)
    for c in _ancestors(b.owner):
        if c in up_a and isinstance(c, Model):
            return c
    raise PortConnectionError(
        f"'{a.path}' and '{b.path}' are not in one model: assign both components to "
        f"attributes of the same Model before connecting them")
