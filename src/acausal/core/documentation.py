"""The reference of a component class from its declarations: parameters (default, unit,
description), structural options and ports, as the "Parameters", "Options" and "Ports"
sections of its docstring and as its call signature, so that ``help(Mass)`` and the API
reference list them and they cannot drift from the code."""
from __future__ import annotations

import inspect
from enum import Enum

#: The sections this module appends; a docstring holding the first already has them.
SECTIONS = ("Parameters", "Options", "Ports")


def shown(value) -> str:
    """A default as a user writes it: 1.0, (0.0, 0.0, 1.0), True, 'frame_a'."""
    if isinstance(value, Enum):
        return repr(value.value)
    if isinstance(value, float):
        return f"{value:g}"
    if isinstance(value, tuple):
        return "(" + ", ".join(shown(v) for v in value) + ")"
    return repr(value)


def parameter_rows(parameters: dict, required: tuple) -> list[tuple[str, str, str, str]]:
    """(name, default, unit, description) of each Parameter; default 'required' for one
    in ``required`` (MSL declares it without a value)."""
    return [(name, "required" if name in required else shown(par.default), par.unit,
             par.description) for name, par in parameters.items()]


def reference(doc: str | None, parameters: dict, required: tuple, options: dict,
              ports: list[tuple[str, str, str, str]]) -> str:
    """``doc`` with the sections of the class's declarations appended (numpydoc form):
    ``parameters`` name -> Parameter, ``required`` the names without a default, ``options``
    name -> default, ``ports`` (name, type, description, condition)."""
    doc = inspect.cleandoc(doc or "")
    if f"\n{SECTIONS[0]}\n---" in doc:
        return doc
    parts = [doc] if doc else []
    if parameters:
        lines = []
        for name, default, unit, description in parameter_rows(parameters, required):
            value = default if default == "required" else f"default {default}"
            kind = "float" if parameters[name].size is None else "tuple of float"
            lines.append(f"{name} : {kind}, {value}" + (f" [{unit}]" if unit else ""))
            lines.append(f"    {description or name}")
        parts.append(_section("Parameters", lines))
    if options:
        lines = []
        for name, default in options.items():
            kind = type(default).__name__
            lines.append(f"{name} : {kind}, default {shown(default)}")
            if isinstance(default, Enum):
                lines.append("    one of " + ", ".join(repr(m.value) for m in type(default)))
            else:
                lines.append("    structural option (fixed when the component is built)")
        parts.append(_section("Options", lines))
    if ports:
        lines = []
        for name, kind, description, condition in ports:
            lines.append(f"{name} : {kind}" + (f" (if {condition})" if condition else ""))
            lines.append(f"    {description or name}")
        parts.append(_section("Ports", lines))
    return "\n\n".join(parts) + "\n"


def _section(title: str, lines: list[str]) -> str:
    return "\n".join([title, "-" * len(title)] + lines)


def signature(init, parameters: dict, required: tuple, options: dict) -> inspect.Signature:
    """The call signature of a component class whose ``__init__`` takes ``**params``: its
    own arguments, then every parameter (those in ``required`` without a default) and
    option as a keyword with its default, then ``nominal``; parameters made per element
    (``q_begin[1]``) are given through their vector's name and are left out."""
    own = list(inspect.signature(init).parameters.values())[1:]        # without self
    if not any(p.kind is p.VAR_KEYWORD for p in own):
        return inspect.Signature(own)
    taken = {p.name for p in own}
    none = inspect.Parameter.empty
    keywords = [inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY,
                                  default=default.value if isinstance(default, Enum) else default)
                for name, default in [*((n, none if n in required else p.default)
                                        for n, p in parameters.items()),
                                      *options.items(), ("nominal", None)]
                if name not in taken and name.isidentifier()]
    positional = [p for p in own if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    rest = [p for p in own if p.kind is p.KEYWORD_ONLY]
    return inspect.Signature(positional + rest + keywords)
