"""Routing blocks (acausal.components.signals.routing, after Modelica.Blocks.Routing): every
output is one of the inputs, so the recorded outputs must equal, bit for bit, the signals
fed in (three sources of time, their values computed by the sources themselves), in the
order MSL's equations give: y = fill(u, nout), y[i] = u[extract[i]], [y] = [u1; u2; ...],
[u] = [y1; y2; ...]."""
from __future__ import annotations

import pickle

import numpy as np
import pytest

import acausal
from acausal import Model, ParameterError
from acausal.components import logical as lg
from acausal.components import signals as sg

T = np.linspace(0.0, 2.0, 41)


def _sources(m: Model, n: int) -> list:
    """n distinct signals of time: sines of frequencies 0.3·(k+1) Hz, amplitude k+1."""
    ports = []
    for k in range(n):
        src = sg.Sine(amplitude=k + 1.0, f=0.3 * (k + 1), phase=0.1 * k)
        setattr(m, f"s{k + 1}", src)
        ports.append(src.y)
    return ports


def _closed_form(n: int) -> list:
    """The sources' values on T (numpy)."""
    return [(k + 1.0) * np.sin(2 * np.pi * 0.3 * (k + 1) * T + 0.1 * k) for k in range(n)]


def _run(m: Model):
    return acausal.compile(m).simulate(T[-1], t=T)


@pytest.mark.parametrize("parts", [2, 3, 4, 5, 6])
def test_multiplex_then_demultiplex_route_every_element_exactly(parts):
    """Multiplex<parts> of inputs sized 1, 2, 1, 2, ... concatenated, then
    DeMultiplex<parts> with the sizes reversed: each output is the input at the same place
    of the concatenation."""
    sizes = [1 + k % 2 for k in range(parts)]
    total = sum(sizes)
    m = Model("mux")
    src = _sources(m, total)
    m.mux = getattr(sg, f"Multiplex{parts}")(**{f"n{k + 1}": n for k, n in enumerate(sizes)})
    back = sizes[::-1]
    m.demux = getattr(sg, f"DeMultiplex{parts}")(**{f"n{k + 1}": n for k, n in enumerate(back)})
    flat = [getattr(m.mux, f"u{k + 1}")[i + 1] for k, n in enumerate(sizes) for i in range(n)]
    for s, u in zip(src, flat):
        m.connect(s, u)
    assert len(m.mux.y) == total == len(m.demux.u)
    for i in range(1, total + 1):
        m.connect(m.mux.y[i], m.demux.u[i])
    res = _run(m)
    expected = _closed_form(total)
    np.testing.assert_allclose(res["mux.y[1]"], expected[0], atol=1e-12)
    outs = [f"demux.y{k + 1}[{i + 1}]" for k, n in enumerate(back) for i in range(n)]
    for j, name in enumerate(outs):
        assert np.array_equal(res[name], res[f"s{j + 1}.y"]), name
        assert np.array_equal(res[f"mux.y[{j + 1}]"], res[f"s{j + 1}.y"])


def test_replicator_extract_signal_and_the_n_forms():
    m = Model("routing")
    src = _sources(m, 3)
    m.mux = sg.Multiplex(n=3)
    for k, s in enumerate(src, start=1):
        m.connect(s, m.mux.u[k])
    m.demux = sg.DeMultiplex(n=3)
    m.ex = sg.ExtractSignal(nin=3, nout=4, extract=[3, 1, 1, 2])
    for i in range(1, 4):
        m.connect(m.mux.y[i], m.demux.u[i])
        m.connect(m.mux.y[i], m.ex.u[i])
    m.rep = sg.Replicator(nout=3)
    m.connect(m.s2.y, m.rep.u)
    m.through = sg.RealPassThrough()
    m.connect(m.s3.y, m.through.u)
    res = _run(m)
    np.testing.assert_allclose(res["s3.y"], _closed_form(3)[2], atol=1e-12)
    for i in range(1, 4):
        assert np.array_equal(res[f"demux.y[{i}]"], res[f"s{i}.y"])
        assert np.array_equal(res[f"rep.y[{i}]"], res["s2.y"])
    for i, k in enumerate([3, 1, 1, 2], start=1):
        assert np.array_equal(res[f"ex.y[{i}]"], res[f"s{k}.y"])
    assert np.array_equal(res["through.y"], res["s3.y"])
    assert (m.ex.nin, m.ex.nout, m.ex.extract) == (3, 4, (3, 1, 1, 2))


def test_extract_signal_default_is_the_first_nout_inputs():
    ex = sg.ExtractSignal(nin=4, nout=2)
    assert ex.extract == (1, 2) and len(ex.y) == 2 and len(ex.u) == 4


def test_boolean_replicator_copies_a_pulse():
    m = Model("brep")
    m.pulse = lg.BooleanPulse(width=30.0, period=0.5)
    m.rep = lg.BooleanReplicator(nout=2)
    m.connect(m.pulse.y, m.rep.u)
    res = _run(m)
    tp = np.mod(res.t, 0.5)
    for i in (1, 2):
        assert np.array_equal(res[f"rep.y[{i}]"], res["pulse.y"])
    inside = np.abs(tp - 0.15) > 1e-9
    np.testing.assert_array_equal(res["rep.y[1]"][inside], (tp < 0.15)[inside])


@pytest.mark.parametrize("make, text", [
    (lambda: sg.Replicator(nout=0), "Replicator: nout"),
    (lambda: sg.Multiplex2(n1=2, n2=0), "Multiplex2: n2"),
    (lambda: sg.DeMultiplex4(n3=1.5), "DeMultiplex4: n3"),
    (lambda: sg.Multiplex(n=-1), "Multiplex: n"),
    (lambda: sg.ExtractSignal(nin=2, extract=[1, 3]), "ExtractSignal: extract"),
    (lambda: sg.ExtractSignal(nin=3, nout=3, extract=[1, 2]), "ExtractSignal: extract"),
    (lambda: sg.ExtractSignal(nin=3, extract=[0]), "ExtractSignal: extract[1]"),
    (lambda: lg.BooleanReplicator(nout=0), "BooleanReplicator: nout"),
])
def test_bad_sizes_are_parameter_errors_naming_the_block(make, text):
    with pytest.raises(ParameterError, match=text.replace("[", r"\[").replace("]", r"\]")):
        make()


def test_sized_routing_blocks_pickle_by_their_sizes():
    mux = pickle.loads(pickle.dumps(sg.Multiplex3(n1=2, n2=1, n3=3)))
    assert type(mux).__name__ == "Multiplex3" and len(mux.y) == 6 and len(mux.u3) == 3
    ex = pickle.loads(pickle.dumps(sg.ExtractSignal(nin=3, extract=[2, 2])))
    assert ex.extract == (2, 2)
