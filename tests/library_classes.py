"""The component classes of the library, for tests that hold for every one of them."""
from __future__ import annotations

import importlib
import inspect
import pkgutil

import acausal.components as library
from acausal.core import Component


def library_classes() -> dict[str, type]:
    """Every Component class defined in a module of acausal.components, by its dotted name
    relative to the package (``translational.Spring``, ``signals.interfaces.SISO``)."""
    found = {}
    for info in pkgutil.walk_packages(library.__path__, library.__name__ + "."):
        module = importlib.import_module(info.name)
        prefix = module.__name__.removeprefix(library.__name__ + ".")
        for name, obj in vars(module).items():
            if inspect.isclass(obj) and issubclass(obj, Component) \
                    and obj.__module__ == module.__name__:
                found[f"{prefix}.{name}"] = obj
    return found
