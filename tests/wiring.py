"""A model written in one call, shared by the tests that build many small circuits."""
from __future__ import annotations

import acausal


def model(name, pairs, **parts) -> acausal.Model:
    """Model ``name`` with ``parts`` (attribute name: component), connected by the port pairs
    ``pairs(model)`` returns."""
    m = acausal.Model(name)
    for k, v in parts.items():
        setattr(m, k, v)
    for a, b in pairs(m):
        m.connect(a, b)
    return m
