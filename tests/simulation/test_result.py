"""Result: time grid, variables by dotted name, CSV / pandas export, plotting, port flows
(reactions at fixed flanges against static equilibrium), helpful KeyErrors."""
import numpy as np
import pytest

import acausal
from acausal.components.translational import Fixed, Force, Mass, Spring

C1, C2, S01, S02, LEN, WALL = 30.0, 20.0, 0.4, 0.5, 0.2, 1.5


def two_walls():
    """left wall (0) | spring1 | mass | spring2 | right wall (WALL)."""
    m = acausal.Model("walls")
    m.left, m.right = Fixed(), Fixed(s0=WALL)
    m.spring1, m.spring2 = Spring(c=C1, s_rel0=S01), Spring(c=C2, s_rel0=S02)
    m.mass = Mass(m=2.0, L=LEN)
    m.connect(m.left.flange, m.spring1.flange_a)
    m.connect(m.spring1.flange_b, m.mass.flange_a)
    m.connect(m.mass.flange_b, m.spring2.flange_a)
    m.connect(m.spring2.flange_b, m.right.flange)
    return m


# static equilibrium: C1 (s − L/2 − S01) = C2 (WALL − s − L/2 − S02)
S_EQ = (C1 * (LEN / 2 + S01) + C2 * (WALL - LEN / 2 - S02)) / (C1 + C2)
F_EQ = C1 * (S_EQ - LEN / 2 - S01)        # tension of both springs at rest [N]
OMEGA = np.sqrt((C1 + C2) / 2.0)


@pytest.fixture(scope="module")
def compiled():
    return acausal.compile(two_walls())


@pytest.fixture(scope="module")
def res(compiled):
    return compiled.simulate(2.0, t=np.linspace(0, 2.0, 81), x0={"mass.s": S_EQ + 0.05})


def test_time_and_names(res):
    np.testing.assert_array_equal(res.t, np.linspace(0, 2.0, 81))
    np.testing.assert_array_equal(res["time"], res.t)
    ref = S_EQ + 0.05 * np.cos(OMEGA * res.t)
    np.testing.assert_allclose(res["mass.s"], ref, atol=1e-6)
    np.testing.assert_allclose(res["mass.flange_b.s"], ref + LEN / 2, atol=1e-6)
    np.testing.assert_allclose(res["spring2.flange_a.s"], ref + LEN / 2, atol=1e-6)
    np.testing.assert_allclose(res["right.flange.s"], WALL)
    assert res.final("mass.s") == pytest.approx(ref[-1], abs=1e-6)
    assert "mass.v" in res and "mass.w" not in res
    assert res.units["mass.s"] == "m" and res.units["spring1.f"] == "N"


def test_unknown_name_suggests(res, compiled):
    with pytest.raises(KeyError, match=r"mass\.ss.*mass\.s"):
        res["mass.ss"]
    with pytest.raises(KeyError, match=r"spring1\.f"):
        res["spring1.ff"]
    with pytest.raises(KeyError, match=r"mass\.v"):
        compiled.expression("mass.vv")
    with pytest.raises(acausal.InitializationError, match=r"mass\.s"):
        compiled.simulate(1.0, x0={"mass.ss": 0.1})


def test_csv_round_trip(res, tmp_path):
    path = tmp_path / "out.csv"
    res.to_csv(path)
    with open(path) as fh:
        header = fh.readline().strip().split(",")
    assert header == ["time"] + res.names
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    assert data.shape == (len(res.t), len(res.names) + 1)
    np.testing.assert_array_equal(data[:, 0], res.t)
    for k, name in enumerate(res.names):
        np.testing.assert_allclose(data[:, k + 1], res[name], rtol=1e-15, atol=0)
    # a chosen subset of columns
    res.to_csv(path, names=["mass.s", "spring1.f"])
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    np.testing.assert_allclose(data[:, 1:].T, [res["mass.s"], res["spring1.f"]], rtol=1e-15)


def test_pandas(res):
    pytest.importorskip("pandas")
    df = res.to_pandas()
    assert df.index.name == "time"
    np.testing.assert_array_equal(df.index.to_numpy(), res.t)
    assert list(df.columns) == res.names
    np.testing.assert_array_equal(df["mass.s"].to_numpy(), res["mass.s"])


def test_plot_writes_png(res, tmp_path):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    path = tmp_path / "plot.png"
    ax = res.plot("mass.s", "spring1.f", path=path)
    assert path.stat().st_size > 1000
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(ax.get_lines()) == 2
    np.testing.assert_array_equal(ax.get_lines()[0].get_ydata(), res["mass.s"])
    import matplotlib.pyplot as plt
    plt.close("all")


def test_plot_without_names_draws_the_states_by_unit(res):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    axes = res.plot()
    assert [a.get_ylabel() for a in axes] == ["[m]", "[m/s]"]
    (s,), (v,) = (a.get_lines() for a in axes)
    assert (s.get_label(), v.get_label()) == ("mass.s", "mass.v")
    # the oscillation about the equilibrium: s − S_EQ = 0.05 cos(ωt), v = −0.05 ω sin(ωt)
    np.testing.assert_allclose(s.get_ydata(), S_EQ + 0.05 * np.cos(OMEGA * res.t), atol=1e-6)
    np.testing.assert_allclose(v.get_ydata(), -0.05 * OMEGA * np.sin(OMEGA * res.t),
                               atol=1e-6)
    _, mine = plt.subplots(2, 1)
    assert res.plot(ax=mine) == list(mine)              # the caller's Axes, one per unit
    _, one = plt.subplots()
    assert res.plot(ax=one) is one and len(one.get_lines()) == 2
    with pytest.raises(ValueError, match="2 panels"):
        res.plot(ax=plt.subplots(3, 1)[1])
    plt.close("all")


def test_static_reactions(compiled):
    """Started at rest in equilibrium it stays there; the walls carry the spring tension:
    left.flange.f = +F_EQ (pulled towards +s), right.flange.f = −F_EQ (Modelica: cut force
    positive into the component)."""
    assert F_EQ > 1.0
    res = compiled.simulate(1.0, x0={"mass.s": S_EQ, "mass.v": 0.0})
    np.testing.assert_allclose(res["mass.s"], S_EQ, atol=1e-10)
    np.testing.assert_allclose(res["spring1.f"], F_EQ, atol=1e-8)
    np.testing.assert_allclose(res["spring2.f"], F_EQ, atol=1e-8)
    np.testing.assert_allclose(res["left.flange.f"], F_EQ, atol=1e-8)
    np.testing.assert_allclose(res["right.flange.f"], -F_EQ, atol=1e-8)
    np.testing.assert_allclose(res["mass.flange_a.f"], -F_EQ, atol=1e-8)
    np.testing.assert_allclose(res["mass.flange_b.f"], F_EQ, atol=1e-8)


def test_dynamic_reactions(res):
    """While it oscillates each wall's cut force is the tension of the spring it holds."""
    s = S_EQ + 0.05 * np.cos(OMEGA * res.t)
    np.testing.assert_allclose(res["left.flange.f"], C1 * (s - LEN / 2 - S01), atol=1e-5)
    np.testing.assert_allclose(res["right.flange.f"], -C2 * (WALL - s - LEN / 2 - S02),
                               atol=1e-5)


def test_force_pushing_against_spring():
    """wall | spring | mass <- constant F0: at rest at s = s_rel0 + L/2 + F0/c; the wall's
    reaction is F0, the force element's flange flow −F0."""
    m = acausal.Model("push")
    m.wall = Fixed()
    m.spring = Spring(c=C1, s_rel0=S01)
    m.mass = Mass(m=1.0, L=LEN)
    m.force = Force()
    m.F = acausal.Input(start=3.0)
    m.connect(m.wall.flange, m.spring.flange_a)
    m.connect(m.spring.flange_b, m.mass.flange_a)
    m.connect(m.mass.flange_b, m.force.flange)
    m.connect(m.F.y, m.force.f)
    c = acausal.compile(m)
    s_eq = S01 + LEN / 2 + 3.0 / C1
    res = c.simulate(1.0, x0={"mass.s": s_eq})
    np.testing.assert_allclose(res["mass.s"], s_eq, atol=1e-10)
    np.testing.assert_allclose(res["wall.flange.f"], 3.0, atol=1e-8)
    np.testing.assert_allclose(res["force.flange.f"], -3.0, atol=1e-12)
    np.testing.assert_allclose(res["mass.flange_b.f"], 3.0, atol=1e-8)
    np.testing.assert_allclose(res["mass.flange_a.f"], -3.0, atol=1e-8)
    # a different force at simulation time moves the equilibrium accordingly
    res = c.simulate(1.0, inputs={"F": -6.0}, x0={"mass.s": S01 + LEN / 2 - 6.0 / C1})
    np.testing.assert_allclose(res["wall.flange.f"], -6.0, atol=1e-8)
    np.testing.assert_allclose(res["mass.v"], 0.0, atol=1e-10)


def test_input_units_follow_the_signal_and_unknown_names_are_named():
    """A model Input's unit is recorded for the input, its port and the port it drives; an
    unknown name raises acausal's VariableNameError (a KeyError) with a suggestion."""
    m = acausal.Model("pushed")
    m.wall, m.spring, m.mass = Fixed(), Spring(c=4.0), Mass(m=1.0)
    m.push, m.F = Force(), acausal.Input(unit="N")
    for a, b in [(m.wall.flange, m.spring.flange_a), (m.spring.flange_b, m.mass.flange_a),
                 (m.push.flange, m.mass.flange_b), (m.F.y, m.push.f)]:
        m.connect(a, b)
    c = acausal.compile(m)
    units = dict(zip(c.recorded_names, c.recorded_units))
    assert units["F"] == units["F.y"] == units["push.f"] == "N"
    with pytest.raises(acausal.VariableNameError, match=r"push\.f"):
        c.expression("push.ff")
    res = c.simulate(1.0, inputs={"F": 2.0})
    assert res.units["push.f"] == "N"
    np.testing.assert_allclose(res["push.f"], 2.0)
    with pytest.raises(KeyError, match="mass.s"):
        res["mass.ss"]
    with pytest.raises(acausal.VariableNameError, match="named by text.*got 3"):
        res[3]


def test_a_model_without_parameters_or_states():
    """A conversion block alone: no parameter, no state; its output is the closed form."""
    from acausal.components import fahrenheit
    res = acausal.compile(fahrenheit.ToKelvin()).simulate(1.0, inputs={"Fahrenheit": 212.0})
    np.testing.assert_allclose(res["Kelvin"], 373.15, rtol=1e-15)
