"""TimeTable and CombiTimeTable (acausal.components.signals) against numpy and closed forms.

References never come from the code under test: table values against numpy's ``interp`` of
the same rows (each MSL extrapolation mode written out in numpy), a mass on a spring driven
by a table against the closed-form solution piece by piece (m x'' + c x = a + b t between
rows: particular solution (a + b t)/c plus the free oscillation that continues x, x'), and
the number of time events against the table's jumps.
"""
from __future__ import annotations

import pickle

import numpy as np
import pytest

import acausal
from acausal import Model, ParameterError
from acausal.components import signals as sg
from acausal.components.translational import Fixed, Force, Mass, Spring

SIM = dict(rtol=1e-10, atol=1e-12)
MASS, STIFF = 0.5, 8.0
W = np.sqrt(STIFF / MASS)


def _probe(src, port=None):
    """src (one output connected, or all if port is None) -> Integrators (dynamics)."""
    m = Model("table_test")
    m.src = src
    ports = [port] if port is not None else (list(src.y) if hasattr(src, "nout") else [src.y])
    for i, p in enumerate(ports, start=1):
        setattr(m, f"i{i}", sg.Integrator())
        m.connect(p, getattr(m, f"i{i}").u)
    return m


def _driven_mass(src, port):
    """Force = table on a mass tied to the ground by a spring: m x'' + c x = F(t)."""
    m = Model("driven")
    m.src, m.force = src, Force()
    m.mass, m.spring, m.fixed = Mass(m=MASS), Spring(c=STIFF), Fixed()
    for a, b in [(port, m.force.f), (m.force.flange, m.mass.flange_a),
                 (m.mass.flange_b, m.spring.flange_b), (m.spring.flange_a, m.fixed.flange)]:
        m.connect(a, b)
    return m


def _oscillator(t, pieces):
    """x(t) of m x'' + c x = a + b·t, x(0) = x'(0) = 0, for pieces [(t0, t1, a, b)] covering
    [0, t_end]: closed form on every piece, continuing x and x' across the boundaries."""
    x = np.full(t.shape, np.nan)
    x0 = v0 = 0.0
    for t0, t1, a, b in pieces:
        A = x0 - (a + b * t0) / STIFF
        B = (v0 - b / STIFF) / W

        def pos(s):
            return (a + b * s) / STIFF + A * np.cos(W * (s - t0)) + B * np.sin(W * (s - t0))

        sel = (t >= t0) & (t <= t1)
        x[sel] = pos(t[sel])
        x0 = pos(t1)
        v0 = b / STIFF - A * W * np.sin(W * (t1 - t0)) + B * W * np.cos(W * (t1 - t0))
    return x


def _linear_pieces(tab, t_end):
    """(t0, t1, a, b) of the linear pieces of a table (jumps at repeated times), the last one
    extrapolated to t_end."""
    out = []
    for (t0, y0), (t1, y1) in zip(tab[:-1], tab[1:]):
        if t1 > t0:
            b = (y1 - y0) / (t1 - t0)
            out.append([t0, t1, y0 - b * t0, b])
    out[-1][1] = t_end
    return out


JUMPY = np.array([[0.0, 0.0], [0.4, 1.0], [0.4, -0.5], [1.1, 0.3], [1.6, 0.3], [1.6, 1.2],
                  [2.2, 0.0], [2.5, 0.4]])


def test_mass_on_spring_driven_by_a_table_with_jumps():
    """Linear segments with two jumps, extrapolated beyond the last row (LastTwoPoints)."""
    t = np.linspace(0.0, 3.0, 151)
    src = sg.CombiTimeTable(table=JUMPY)
    c = acausal.compile(_driven_mass(src, src.y[1]))
    res = c.simulate(3.0, t=t, **SIM)
    ref = _oscillator(t, _linear_pieces(JUMPY, 3.0))
    np.testing.assert_allclose(res["mass.s"], ref, rtol=0, atol=1e-8)
    assert c.event_times(c.param_vector(), 0.0, 3.0) == pytest.approx([0.4, 1.6])


def test_mass_on_spring_driven_by_constant_segments():
    """ConstantSegments: the row at or before the time; an event at every row."""
    tab = np.array([[0.0, 1.0], [0.5, -1.0], [1.2, 0.5], [2.0, 0.0]])
    t = np.linspace(0.0, 3.0, 151)
    src = sg.CombiTimeTable(table=tab, smoothness="ConstantSegments")
    c = acausal.compile(_driven_mass(src, src.y[1]))
    res = c.simulate(3.0, t=t, **SIM)
    ends = list(tab[1:, 0]) + [3.0]
    ref = _oscillator(t, [(a, b, y, 0.0) for a, b, y in zip(tab[:, 0], ends, tab[:, 1])])
    np.testing.assert_allclose(res["mass.s"], ref, rtol=0, atol=1e-8)
    assert c.event_times(c.param_vector(), 0.0, 3.0) == pytest.approx([0.5, 1.2, 2.0])


def test_timetable_drives_the_oscillator_with_shift_and_scale():
    """TimeTable (MSL Sources.TimeTable) with startTime, timeScale and offset: the force is
    offset before startTime, then the table in units of timeScale."""
    tab = np.array([[0.0, 0.5], [1.0, 2.0], [1.0, 0.0], [3.0, 1.0]])
    start, scale, offset = 0.3, 0.5, 0.2
    src = sg.TimeTable(table=tab, startTime=start, timeScale=scale, offset=offset)
    t = np.linspace(0.0, 3.0, 151)
    c = acausal.compile(_driven_mass(src, src.y))
    res = c.simulate(3.0, t=t, **SIM)
    scaled = tab * [scale, 1.0] + [start, offset]
    pieces = [(0.0, start, offset, 0.0)] + _linear_pieces(scaled, 3.0)
    np.testing.assert_allclose(res["mass.s"], _oscillator(t, pieces), rtol=0, atol=1e-8)
    assert c.event_times(c.param_vector(), 0.0, 3.0) == pytest.approx([start, start + scale])


def _road(n=300, length=6.0):
    s = np.linspace(0.0, length, n)
    return np.column_stack([s, 0.05 * np.sin(2.1 * s) + 0.02 * np.sin(7.3 * s + 0.4)])


def test_event_count_smooth_table_none_repeated_times_one_each():
    """A 300-row table without repeated times restarts the integrator nowhere; three
    repeated times restart it three times; timeEvents=Always at every inner row (MSL's
    default)."""
    road = _road()
    c = acausal.compile(_probe(sg.CombiTimeTable(table=road)))
    assert c.event_times(c.param_vector(), 0.0, 10.0) == []
    jumps = road.tolist()
    for k in (250, 150, 50):                               # repeat a row: a jump there
        jumps.insert(k, [road[k, 0], road[k, 1] + 0.1])
    c = acausal.compile(_probe(sg.CombiTimeTable(table=jumps)))
    assert c.event_times(c.param_vector(), 0.0, 10.0) == pytest.approx(road[[50, 150, 250], 0])
    c = acausal.compile(_probe(sg.CombiTimeTable(table=road, timeEvents="Always")))
    assert len(c.event_times(c.param_vector(), 0.0, 10.0)) == 298
    c = acausal.compile(_probe(sg.TimeTable(table=road)))
    assert c.event_times(c.param_vector(), 0.0, 10.0) == []


TAB = np.array([[0.5, 1.0, -2.0], [1.0, 3.0, 0.0], [1.5, 2.0, 1.0], [2.5, -1.0, 1.0]])


def _numpy_table(tau, column, mode):
    """MSL's extrapolation modes written out in numpy for the linear segments of TAB."""
    x, y = TAB[:, 0], TAB[:, column - 1]
    if mode == "HoldLastPoint":
        return np.interp(tau, x, y)
    if mode == "Periodic":
        return np.interp(x[0] + np.mod(tau - x[0], x[-1] - x[0]), x, y)
    inner = np.interp(tau, x, y)
    if mode == "NoExtrapolation":
        return np.where((tau < x[0]) | (tau > x[-1]), np.nan, inner)
    left = y[0] + (y[1] - y[0]) / (x[1] - x[0]) * (tau - x[0])
    right = y[-1] + (y[-1] - y[-2]) / (x[-1] - x[-2]) * (tau - x[-1])
    return np.where(tau < x[0], left, np.where(tau > x[-1], right, inner))


@pytest.mark.parametrize("mode", ["LastTwoPoints", "HoldLastPoint", "Periodic",
                                  "NoExtrapolation"])
def test_extrapolation_modes_against_numpy(mode):
    """Two columns selected in reverse order, offsets per output, shiftTime and timeScale."""
    shift, scale = 0.2, 0.8
    src = sg.CombiTimeTable(table=TAB, columns=[3, 2], extrapolation=mode, offset=[0.1, -0.3],
                            shiftTime=shift, timeScale=scale)
    m = Model("extrap")
    m.src, m.c, m.i = src, sg.Constant(), sg.Integrator()
    m.connect(m.c.y, m.i.u)
    t = np.linspace(0.0, 6.0, 241)
    c = acausal.compile(m)
    res = c.simulate(6.0, t=t, **SIM)
    tau = (t - shift) / scale
    np.testing.assert_allclose(res["src.y[1]"], 0.1 + _numpy_table(tau, 3, mode), atol=1e-12)
    np.testing.assert_allclose(res["src.y[2]"], -0.3 + _numpy_table(tau, 2, mode), atol=1e-12)
    if mode == "Periodic":                   # the wrap jumps: an event every period
        period = scale * (TAB[-1, 0] - TAB[0, 0])
        first = shift + scale * TAB[-1, 0]
        assert c.event_times(c.param_vector(), 0.0, 6.0) == pytest.approx(
            np.arange(first, 6.0, period))


def test_constant_segments_extrapolation_and_periodic_rows():
    tab = np.array([[0.0, 1.0], [1.0, 2.0], [1.5, -1.0]])
    t = np.linspace(0.0, 4.0, 161)
    for mode, tau in [("HoldLastPoint", t), ("LastTwoPoints", t),
                      ("Periodic", np.mod(t, 1.5))]:
        src = sg.CombiTimeTable(table=tab, smoothness="ConstantSegments", extrapolation=mode)
        res = acausal.compile(_probe(src)).simulate(4.0, t=t, **SIM)
        idx = np.searchsorted(tab[:, 0], tau, side="right") - 1
        np.testing.assert_allclose(res["src.y[1]"], tab[idx, 1], atol=0, err_msg=mode)


def test_parameters_change_without_recompiling_and_pickle():
    src = sg.CombiTimeTable(table=TAB, offset=0.5)
    c = acausal.compile(_probe(src))
    assert {"src.offset[1]", "src.offset[2]", "src.startTime", "src.timeScale"} <= set(
        c.param_names) and "src.shiftTime" not in c.param_names
    t = np.linspace(0.0, 3.0, 61)
    res = c.simulate(3.0, t=t, params={"src.startTime": 1.0, "src.offset[2]": 2.0}, **SIM)
    after = t >= 1.0                       # shiftTime follows startTime (MSL's binding)
    ref = np.where(after, _numpy_table(t - 1.0, 3, "LastTwoPoints"), 0.0) + 2.0
    np.testing.assert_allclose(res["src.y[2]"], ref, atol=1e-12)
    copy = pickle.loads(pickle.dumps(src))
    assert copy.nout == 2 and np.array_equal(copy.table, src.table)


@pytest.mark.parametrize("kwargs, match", [
    (dict(table=TAB, columns=[1]), "columns"), (dict(table=TAB, columns=[4]), "columns"),
    (dict(table=TAB, offset=[1, 2, 3]), "offset has 3"),
    (dict(table=TAB, smoothness="ContinuousDerivative"), "not available"),
    (dict(table=TAB, extrapolation="Linear"), "Extrapolation"),
    (dict(table=TAB, tableOnFile=True), "files"),
    (dict(table=[[0, 1], [1, 2], [1, 3], [1, 4]]), "more than twice"),
    (dict(table=[[1, 2], [1, 3]]), "spans no time"),
    (dict(table=[[0, 1], [2, 2], [1, 3]]), "non-decreasing")])
def test_bad_tables_and_options_are_refused(kwargs, match):
    with pytest.raises(ParameterError, match=match):
        sg.CombiTimeTable(**kwargs)


ROWS = np.array([[0.0, 1.0, -1.0], [1.0, 2.0, 0.5], [1.0, 0.0, 0.0], [2.0, 3.0, 2.0],
                 [3.0, 1.0, 1.0]])                       # a jump at t = 1
NEW = np.array([[0.5, 2.0], [-1.0, 1.0], [4.0, -2.0], [1.0, 0.0], [2.0, 2.0]])
T_TAB = np.linspace(0.0, 3.0, 121)


@pytest.mark.parametrize("smoothness", ["LinearSegments", "ConstantSegments"])
def test_new_table_values_without_recompiling(smoothness):
    """The values of a compiled CombiTimeTable changed by params equal a model compiled with
    those values, and numpy's interpolation of them (the jump at t = 1 kept)."""
    old = acausal.compile(_probe(sg.CombiTimeTable(table=ROWS, smoothness=smoothness,
                                                   table_parameter=True)))
    new_tab = np.column_stack([ROWS[:, 0], NEW])
    fresh = acausal.compile(_probe(sg.CombiTimeTable(table=new_tab, smoothness=smoothness)))
    changed = old.simulate(3.0, t=T_TAB, params={"src.table": NEW}, **SIM)
    ref = fresh.simulate(3.0, t=T_TAB, **SIM)
    for name in ("src.y[1]", "src.y[2]", "i1.y", "i2.y"):
        np.testing.assert_allclose(changed[name], ref[name], rtol=0, atol=1e-12)
    if smoothness == "LinearSegments":              # after the jump: the rows from t = 1 on
        after = T_TAB > 1.0
        np.testing.assert_allclose(changed["src.y[2]"][after],
                                   np.interp(T_TAB[after], ROWS[2:, 0], NEW[2:, 1]), atol=1e-12)
    assert old.event_times(old.param_vector({"src.table": NEW}), 0.0, 3.0) == \
        fresh.event_times(fresh.param_vector(), 0.0, 3.0)


def test_new_time_table_values_follow_numpy():
    tab = [[0.0, 0.0], [1.0, 2.0], [2.5, -1.0]]
    c = acausal.compile(_probe(sg.TimeTable(table=tab, table_parameter=True)))
    assert [n for n in c.param_names if n.startswith("src.table")] == \
        ["src.table[1]", "src.table[2]", "src.table[3]"]
    res = c.simulate(2.5, t=T_TAB[T_TAB <= 2.5], params={"src.table": [1.0, -1.0, 3.0]}, **SIM)
    np.testing.assert_allclose(res["src.y"], np.interp(res.t, [0.0, 1.0, 2.5], [1.0, -1.0, 3.0]),
                               atol=1e-12)
    with pytest.raises(ParameterError, match="3 elements"):
        c.param_vector({"src.table": [1.0, 2.0]})
    fixed = acausal.compile(_probe(sg.TimeTable(table=tab, shiftTime=0.5)))
    assert not any(n.startswith("src.table") for n in fixed.param_names)
    for src in (sg.TimeTable(table=tab), sg.TimeTable(table=tab, shiftTime=0.5),
                sg.TimeTable(table=tab, table_parameter=True, shiftTime=0.5),
                sg.CombiTimeTable(table=ROWS, table_parameter=True)):
        copy = pickle.loads(pickle.dumps(src))
        assert type(copy) is type(src) and copy.table == src.table


def test_unpickled_time_table_follows_numpy():
    """A TimeTable made back from its pickle interpolates its rows as numpy does."""
    tab = np.array([[0.0, 0.0], [1.0, 2.0], [1.0, -1.0], [2.5, 3.0]])
    copy = pickle.loads(pickle.dumps(sg.TimeTable(table=tab, startTime=0.5)))
    res = acausal.compile(_probe(copy)).simulate(3.0, t=T_TAB, **SIM)
    after = T_TAB >= 1.5                         # past the jump: its later row holds
    np.testing.assert_allclose(res["src.y"][after],
                               np.interp(T_TAB[after] - 0.5, tab[2:, 0], tab[2:, 1]),
                               atol=1e-12)
    before = (T_TAB >= 0.5) & (T_TAB < 1.5)
    np.testing.assert_allclose(res["src.y"][before],
                               np.interp(T_TAB[before] - 0.5, tab[:2, 0], tab[:2, 1]),
                               atol=1e-12)
    np.testing.assert_array_equal(res["src.y"][T_TAB < 0.5], 0.0)
