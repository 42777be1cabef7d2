"""Routing (Modelica.Blocks.Routing, MSL 4.1): blocks that pass Real signals on, copy,
select, combine and split them; every output is one of the inputs, exactly.

Sizes are structural (MSL's Integer parameters ``nout``, ``nin``, ``n``, ``n1`` .. ``n6``,
``extract``): constructor arguments that fix the block's vector connectors, numbered from 1
as in Modelica (``connect(mux.y[3], gain.u)``). The Boolean ones (BooleanPassThrough,
BooleanReplicator) are in ``acausal.components.logical``.

MSL differences: Extractor (its ``index`` is an IntegerInput) and the Integer blocks
(IntegerReplicator, IntegerPassThrough) are not available: acausal has no Integer
connectors; ExtractSignal selects by a fixed ``extract`` vector. Multiplex and DeMultiplex
take their size ``n`` at construction (≥ 1) instead of from connectorSizing.
"""
from __future__ import annotations

from ...core import Component, RealInput, RealOutput, VectorPort
from ...errors import ParameterError
from .interfaces import SISO, _size, _Sized

__all__ = ["RealPassThrough", "Replicator", "ExtractSignal", "Multiplex", "DeMultiplex",
           "Multiplex2", "Multiplex3", "Multiplex4", "Multiplex5", "Multiplex6",
           "DeMultiplex2", "DeMultiplex3", "DeMultiplex4", "DeMultiplex5", "DeMultiplex6"]


class RealPassThrough(SISO):
    """y = u (MSL Routing.RealPassThrough): a signal passed on under another name."""

    def physics(self, e):
        e.output(self.y, e.input(self.u))


def _route(e, sources, targets) -> None:
    """Each output of ``targets`` = the input of ``sources`` at the same place."""
    for src, dst in zip(sources, targets):
        e.output(dst, e.input(src))


class _Replicating(_Sized, Component):
    """y = fill(u, nout): the input ``u`` copied to the ``nout`` outputs ``y[1]`` ..
    ``y[nout]`` (constructor argument, default 1), on the ports of ``_signal`` (Real here,
    Boolean in ``logical.BooleanReplicator``)."""
    _signal = ("Real", RealInput, RealOutput)

    def __new__(cls, name=None, *, nout: int = 1, **params):
        return super().__new__(cls._variant(_size(nout, f"{cls.__name__}: nout (number of "
                                                        f"outputs)", 1)))

    @classmethod
    def _declare(cls, nout: int) -> dict:
        kind, port_in, port_out = cls._signal
        return {"u": port_in(f"connector of {kind} input signal"),
                "y": VectorPort(port_out, nout, f"connector of {kind} output signals")}

    def __init__(self, name: str | None = None, *, nout: int = 1, **params):
        super().__init__(name, **params)

    @property
    def nout(self) -> int:
        """Number of outputs."""
        return self._key[0]

    def physics(self, e):
        _route(e, [self.u] * self.nout, self.y)


class Replicator(_Replicating):
    """y = fill(u, nout) (MSL Routing.Replicator): the input ``u`` copied to the ``nout``
    outputs ``y[1]`` .. ``y[nout]`` (constructor argument, default 1)."""
    _classes: dict = {}


class ExtractSignal(_Sized, Component):
    """y[i] = u[extract[i]], i = 1..nout (MSL Routing.ExtractSignal): the inputs ``u[1]`` ..
    ``u[nin]`` picked in the order of ``extract`` (constructor arguments: ``nin``, default 1;
    ``extract``, nout indices in 1..nin, an index may repeat; default 1..nout with ``nout``,
    default 1), outputs ``y[1]`` .. ``y[nout]``."""
    _classes: dict = {}

    def __new__(cls, name=None, *, nin: int = 1, nout: int | None = None, extract=None,
                **params):
        return super().__new__(cls._variant(*cls._layout(nin, nout, extract)))

    @classmethod
    def _layout(cls, nin, nout, extract) -> tuple:
        """(nin, extract) checked: a ParameterError naming the block otherwise."""
        nin = _size(nin, f"{cls.__name__}: nin (number of inputs)", 1)
        if extract is None:
            n = _size(1 if nout is None else nout, f"{cls.__name__}: nout (number of outputs)",
                      1)
            extract = range(1, n + 1)
        extract = tuple(_size(i, f"{cls.__name__}: extract[{k}]", 1)
                        for k, i in enumerate(extract, start=1))
        if not extract or (nout is not None and len(extract) != nout):
            raise ParameterError(f"{cls.__name__}: extract must have nout (= {nout}) indices, "
                                 f"got {len(extract)}")
        if max(extract) > nin:
            raise ParameterError(f"{cls.__name__}: extract = {list(extract)} selects input "
                                 f"{max(extract)}, but nin = {nin}; give indices in 1..nin")
        return nin, extract

    @staticmethod
    def _declare(nin: int, extract: tuple) -> dict:
        return {"u": VectorPort(RealInput, nin, "connector of Real input signals"),
                "y": VectorPort(RealOutput, len(extract), "connector of Real output signals")}

    def __init__(self, name: str | None = None, *, nin: int = 1, nout: int | None = None,
                 extract=None, **params):
        super().__init__(name, **params)

    @property
    def nin(self) -> int:
        """Number of inputs."""
        return self._key[0]

    @property
    def extract(self) -> tuple:
        """The input each output is (1-based)."""
        return self._key[1]

    @property
    def nout(self) -> int:
        """Number of outputs."""
        return len(self._key[1])

    def physics(self, e):
        _route(e, [self.u[i] for i in self.extract], self.y)


class _Concatenation(_Sized, Component):
    """Vector connectors of sizes ``n1`` .. ``n<parts>`` (constructor arguments, default 1;
    ``n`` for one part) on one side and their concatenation on the other: ``_split`` names
    the single connector (``u``: its parts are ``y1``, ``y2``, ... ; ``y``: the parts are
    ``u1``, ``u2``, ...)."""
    _parts = 1
    _split = "y"

    @classmethod
    def _names(cls) -> list[str]:
        return ["n"] if cls._parts == 1 else [f"n{k}" for k in range(1, cls._parts + 1)]

    def __new__(cls, name=None, **params):
        sizes = tuple(_size(params.get(n, 1), f"{cls.__name__}: {n} (dimension of signal "
                                                f"connector)", 1) for n in cls._names())
        return super().__new__(cls._variant(*sizes))

    @classmethod
    def _declare(cls, *sizes) -> dict:
        whole, part = ((RealOutput, RealInput) if cls._split == "y" else (RealInput, RealOutput))
        side = "u" if cls._split == "y" else "y"
        kind = "input" if side == "u" else "output"
        names = [side] if cls._parts == 1 else [f"{side}{k}" for k in range(1, cls._parts + 1)]
        ports = {name: VectorPort(part, n, f"connector of Real {kind} signals"
                                  + ("" if cls._parts == 1 else f" {k}"))
                 for k, (name, n) in enumerate(zip(names, sizes), start=1)}
        ports[cls._split] = VectorPort(whole, sum(sizes), "connector of Real "
                                       f"{'output' if side == 'u' else 'input'} signals")
        return {**ports, "_part_names": tuple(names)}

    def __init__(self, name: str | None = None, **params):
        for n in self._names():
            params.pop(n, None)
        super().__init__(name, **params)

    def _pieces(self) -> list:
        """The ports of the parts, in order."""
        return [p for name in self._part_names for p in getattr(self, name)]

    def physics(self, e):
        whole = getattr(self, self._split)
        if self._split == "y":
            _route(e, self._pieces(), whole)
        else:
            _route(e, whole, self._pieces())


class Multiplex(_Concatenation):
    """y = u (MSL Routing.Multiplex): the ``n`` inputs ``u[1]`` .. ``u[n]`` (constructor
    argument ``n``, default 1) as the outputs ``y[1]`` .. ``y[n]``."""
    _classes: dict = {}


class DeMultiplex(_Concatenation):
    """y = u (MSL Routing.DeMultiplex): the ``n`` inputs ``u[1]`` .. ``u[n]`` (constructor
    argument ``n``, default 1) as the outputs ``y[1]`` .. ``y[n]``."""
    _classes: dict = {}
    _split = "u"


class Multiplex2(_Concatenation):
    """[y] = [u1; u2] (MSL Routing.Multiplex2): the output ``y`` (n1 + n2 elements) is the
    concatenation of the inputs ``u1[n1]``, ``u2[n2]``; the sizes ``n1``, ``n2`` are
    constructor arguments (default 1)."""
    _classes: dict = {}
    _parts = 2


class Multiplex3(_Concatenation):
    """[y] = [u1; u2; u3] (MSL Routing.Multiplex3); sizes ``n1`` .. ``n3`` (constructor
    arguments, default 1)."""
    _classes: dict = {}
    _parts = 3


class Multiplex4(_Concatenation):
    """[y] = [u1; u2; u3; u4] (MSL Routing.Multiplex4); sizes ``n1`` .. ``n4`` (constructor
    arguments, default 1)."""
    _classes: dict = {}
    _parts = 4


class Multiplex5(_Concatenation):
    """[y] = [u1; ...; u5] (MSL Routing.Multiplex5); sizes ``n1`` .. ``n5`` (constructor
    arguments, default 1)."""
    _classes: dict = {}
    _parts = 5


class Multiplex6(_Concatenation):
    """[y] = [u1; ...; u6] (MSL Routing.Multiplex6); sizes ``n1`` .. ``n6`` (constructor
    arguments, default 1)."""
    _classes: dict = {}
    _parts = 6


class DeMultiplex2(_Concatenation):
    """[u] = [y1; y2] (MSL Routing.DeMultiplex2): the input ``u`` (n1 + n2 elements) split
    into the outputs ``y1[n1]``, ``y2[n2]``; the sizes ``n1``, ``n2`` are constructor
    arguments (default 1)."""
    _classes: dict = {}
    _parts, _split = 2, "u"


class DeMultiplex3(_Concatenation):
    """[u] = [y1; y2; y3] (MSL Routing.DeMultiplex3); sizes ``n1`` .. ``n3`` (constructor
    arguments, default 1)."""
    _classes: dict = {}
    _parts, _split = 3, "u"


class DeMultiplex4(_Concatenation):
    """[u] = [y1; y2; y3; y4] (MSL Routing.DeMultiplex4); sizes ``n1`` .. ``n4`` (constructor
    arguments, default 1)."""
    _classes: dict = {}
    _parts, _split = 4, "u"


class DeMultiplex5(_Concatenation):
    """[u] = [y1; ...; y5] (MSL Routing.DeMultiplex5); sizes ``n1`` .. ``n5`` (constructor
    arguments, default 1)."""
    _classes: dict = {}
    _parts, _split = 5, "u"


class DeMultiplex6(_Concatenation):
    """[u] = [y1; ...; y6] (MSL Routing.DeMultiplex6); sizes ``n1`` .. ``n6`` (constructor
    arguments, default 1)."""
    _classes: dict = {}
    _parts, _split = 6, "u"
