"""sweep(): many runs of one model against a loop of simulate() with the same settings, the
ways of giving the runs, failed runs, and the same sweep on a dask LocalCluster."""
import numpy as np
import pandas as pd
import pytest

import acausal
from acausal import models
from acausal.errors import VariableNameError

pytest.importorskip("xarray")

T_END = 1.0
GRID = np.linspace(0.0, T_END, 101)


def road(t):
    """Road height [m] at time t [s] (two waves, as examples/road_profile.py at 10 m/s)."""
    return 0.02 * np.sin(9.0 * t) + 0.006 * np.sin(41.0 * t + 0.4)


@pytest.fixture(scope="module")
def quarter_car():
    return acausal.compile(models.QuarterCar())


@pytest.fixture(scope="module")
def pendulum():
    return acausal.compile(models.PendulumChain(2))


def assert_as_loop(compiled, result, inputs=None, atol=1e-8, **settings):
    """Every run of ``result`` equals simulate() of that run (with the same solver) to
    ``atol`` (relative to the variable's magnitude when above 1)."""
    for k, run in enumerate(result.runs):
        ref = compiled.simulate(T_END, t=GRID, params=run["params"], x0=run["x0"],
                                inputs={**(inputs or {}), **run["inputs"]}, **settings)
        assert result.dataset["solver"].values[k] == ref.solver
        for name in result.dataset.data_vars:
            np.testing.assert_allclose(result[name][k], ref[name], rtol=0,
                                       atol=atol * max(1.0, np.max(np.abs(ref[name]))),
                                       err_msg=f"run {k}, {name}")


def test_quarter_car_grid_equals_simulate_loop(quarter_car):
    c, d = [10e3, 16e3, 25e3], [500.0, 1500.0]
    res = quarter_car.sweep(T_END, t=GRID, params={"suspension.c": c, "suspension.d": d},
                            inputs={"road": road})
    assert res.method == "map" and not res.failed and len(res) == 6
    assert list(res.dataset.data_vars) == quarter_car.x_names + ["a_body", "travel"]
    # the grid: the Cartesian product, the last list varying fastest
    np.testing.assert_array_equal(res.dataset["suspension.c"], np.repeat(c, 2))
    np.testing.assert_array_equal(res.dataset["suspension.d"], np.tile(d, 3))
    assert_as_loop(quarter_car, res, inputs={"road": road})
    # the recorded outputs are the model's: travel = body.s - wheel.s
    np.testing.assert_allclose(res["travel"], res["body.s"] - res["wheel.s"], atol=1e-15)


def assert_within_own_error(result, k, ref, tight):
    """Run k of a sweep is as accurate as simulate()'s ``ref``: its error against
    ``tight`` at most twice ref's (or round-off). Where BDF's Newton iterations round
    differently with the parameters as symbols than as folded numbers, or Adams' step
    choices at an input's kinks follow round-off, the two differ at the size of the
    integration error, not of round-off."""
    for name in result.dataset.data_vars:
        own_error = np.max(np.abs(ref[name] - tight[name]))
        error = np.max(np.abs(result[name][k] - tight[name]))
        assert error <= 2 * own_error + 1e-14, (name, error, own_error)


def test_solver_given_and_stiff_choice(quarter_car):
    """A run stiff enough for simulate() to choose BDF (a 2.7 kHz tyre mode) next to one
    it integrates with Adams: each with simulate()'s solver and result; with
    solver='cvodes' for every run too."""
    stiff = {"tyre.k": 1e10}
    res = quarter_car.sweep(T_END, t=GRID, params={"tyre.k": [160e3, stiff["tyre.k"]]},
                            inputs={"road": road})
    np.testing.assert_array_equal(res.dataset["solver"], ["adams", "cvodes"])
    ref = quarter_car.simulate(T_END, t=GRID, inputs={"road": road})
    for name in res.dataset.data_vars:
        np.testing.assert_allclose(res[name][0], ref[name], rtol=0, atol=1e-8)
    ref = quarter_car.simulate(T_END, t=GRID, params=stiff, inputs={"road": road})
    tight = quarter_car.simulate(T_END, t=GRID, params=stiff, inputs={"road": road},
                                 solver="cvodes", rtol=1e-10, atol=1e-12)
    assert ref.solver == "cvodes"
    assert_within_own_error(res, 1, ref, tight)
    given = quarter_car.sweep(T_END, t=GRID, params={"body.m": [200.0, 300.0]},
                              inputs={"road": road}, solver="cvodes", rtol=1e-6, atol=1e-9)
    for k, m in enumerate((200.0, 300.0)):
        kw = dict(t=GRID, params={"body.m": m}, inputs={"road": road}, solver="cvodes")
        ref = quarter_car.simulate(T_END, rtol=1e-6, atol=1e-9, **kw)
        assert_within_own_error(given, k, ref,
                                quarter_car.simulate(T_END, rtol=1e-11, atol=1e-13, **kw))


def test_pendulum_parameters_and_start_values(pendulum):
    res = pendulum.sweep(T_END, t=GRID, params={"body1.m": [0.5, 2.0]},
                         x0={"rev1.phi": [0.3, 1.2], "rev2.w": 0.5})
    assert len(res) == 4 and not res.failed
    np.testing.assert_array_equal(res.dataset["rev1.phi(0)"], [0.3, 1.2, 0.3, 1.2])
    assert_as_loop(pendulum, res)
    np.testing.assert_allclose(res["rev1.phi"][:, 0], [0.3, 1.2, 0.3, 1.2], atol=1e-12)


def test_list_and_dataframe_forms_equal_the_grid(pendulum):
    grid = pendulum.sweep(T_END, t=GRID, params={"body2.m": [0.5, 1.5]},
                          x0={"rev2.phi": [0.1, -0.4]}, variables=["rev1.phi", "body2.m"])
    rows = [{"body2.m": m, "rev2.phi": phi} for m in (0.5, 1.5) for phi in (0.1, -0.4)]
    listed = pendulum.sweep(T_END, t=GRID, runs=rows, variables=["rev1.phi", "body2.m"])
    framed = pendulum.sweep(T_END, t=GRID, runs=pd.DataFrame(rows),
                            variables=["rev1.phi", "body2.m"])
    for other in (listed, framed):
        np.testing.assert_array_equal(other["rev1.phi"], grid["rev1.phi"])
        np.testing.assert_array_equal(other.dataset["rev2.phi(0)"],
                                      grid.dataset["rev2.phi(0)"])
    np.testing.assert_array_equal(grid["body2.m"][:, -1], [0.5, 0.5, 1.5, 1.5])
    frame = grid.as_frame()
    assert len(frame) == 4 * GRID.size
    assert {"run", "time", "body2.m", "rev2.phi(0)", "rev1.phi"} <= set(frame.columns)
    row = frame[(frame.run == 3) & (frame.time == GRID[-1])]
    assert float(row["rev1.phi"].iloc[0]) == grid["rev1.phi"][3, -1]


def test_input_variations_constant_and_on_the_grid(quarter_car):
    """The road per run: constants, and arrays on the grid (linear between the points, as
    simulate() takes them)."""
    constant = quarter_car.sweep(T_END, t=GRID, inputs={"road": [0.0, 0.01, -0.02]})
    np.testing.assert_array_equal(constant.dataset["road"], [0.0, 0.01, -0.02])
    assert_as_loop(quarter_car, constant)
    arrays = np.vstack([road(GRID), 0.5 * road(GRID), np.full(GRID.size, 0.01)])
    on_grid = quarter_car.sweep(T_END, t=GRID, inputs={"road": arrays},
                                variables=["body.s", "a_body", "road"])
    assert on_grid.method == "map"
    # a kink at every grid point: Adams' step choices there follow round-off (an
    # interpolant here, pw_lin in simulate), so the runs agree to the integration error
    for k in range(3):
        kw = dict(t=GRID, inputs={"road": arrays[k]})
        assert_within_own_error(on_grid, k, quarter_car.simulate(T_END, **kw),
                                quarter_car.simulate(T_END, rtol=1e-11, atol=1e-13, **kw))
    np.testing.assert_allclose(on_grid["road"], arrays, atol=1e-15)
    # one array on the grid is one signal for every run, as simulate() takes it
    fixed = quarter_car.sweep(T_END, t=GRID, inputs={"road": arrays[0]},
                              params={"body.m": [250.0, 300.0]})
    assert len(fixed) == 2
    assert_as_loop(quarter_car, fixed, inputs={"road": arrays[0]})


def test_failed_runs_are_reported_by_index():
    """A softening spring started far out runs away (the integrator gives up) in run 1; run
    3 has a parameter out of its range; the others are simulate()'s runs."""
    duffing = acausal.compile(models.duffing_model())
    steps = {"max_num_steps": 5000}           # the runaway gives up sooner
    res = duffing.sweep(5.0, params={"spring.c3": [40.0, -40.0, 10.0, 20.0],
                                     "mass.m": [1.0]}, x0={"mass.s": 2.0}, options=steps)
    res_bad = duffing.sweep(5.0, runs=[{"spring.c": 4.0}, {"spring.c": -1.0}],
                            x0={"mass.s": 1.0})
    assert sorted(res.failed) == [1] and "failed" in res.failed[1]
    assert np.all(np.isnan(res["mass.s"][1])) and np.all(np.isfinite(res["mass.s"][[0, 2, 3]]))
    np.testing.assert_array_equal(res.dataset["failed"], [False, True, False, False])
    with pytest.raises(acausal.SimulationError):
        duffing.simulate(5.0, params={"spring.c3": -40.0}, x0={"mass.s": 2.0}, options=steps)
    for k in (0, 2, 3):
        ref = duffing.simulate(5.0, params={"spring.c3": res.dataset["spring.c3"].values[k]},
                               x0={"mass.s": 2.0}, options=steps)
        np.testing.assert_allclose(res["mass.s"][k], ref["mass.s"], atol=1e-8)
    assert sorted(res_bad.failed) == [1] and "spring.c" in res_bad.failed[1]
    assert np.all(np.isnan(res_bad["mass.s"][1]))


def test_a_model_with_one_state():
    """A FirstOrder block (one state) on a unit step: y = k·(1 − exp(−t/T)) for each T (its
    single nominal once sliced to no algebraic variables at all)."""
    from acausal.components import signals as sg
    m = acausal.Model("lag")
    m.u, m.lag = sg.Constant(k=1.0), sg.FirstOrder(k=2.0)
    m.connect(m.u.y, m.lag.u)
    grid = np.linspace(0.0, 2.0, 21)
    res = acausal.compile(m).sweep(2.0, t=grid, params={"lag.T": [0.5, 1.0]},
                                   variables=["lag.y"], rtol=1e-10, atol=1e-12)
    for k, T in enumerate((0.5, 1.0)):
        np.testing.assert_allclose(res["lag.y"][k], 2.0 * (1 - np.exp(-grid / T)), atol=1e-8)


def test_models_with_events_run_as_a_simulate_loop():
    ball = acausal.compile(models.BouncingBall())
    grid = np.linspace(0.0, 2.0, 201)
    res = ball.sweep(2.0, t=grid, params={"floor.e": [0.5, 0.8]}, variables=["ball.s"])
    assert res.method == "simulate" and not res.failed
    for k, e in enumerate((0.5, 0.8)):
        ref = ball.simulate(2.0, t=grid, params={"floor.e": e})
        at = np.searchsorted(ref.t, grid, side="right") - 1
        np.testing.assert_array_equal(res["ball.s"][k], ref["ball.s"][at])


def test_bad_arguments_are_named(quarter_car):
    with pytest.raises(VariableNameError, match="body.x"):
        quarter_car.sweep(T_END, params={"body.m": [1.0, 2.0]}, variables=["body.x"])
    with pytest.raises(VariableNameError, match="body.z"):
        quarter_car.sweep(T_END, runs=[{"body.z": 0.1}, {"body.z": 0.2}])
    with pytest.raises(acausal.ParameterError, match="body.mass"):
        quarter_car.sweep(T_END, params={"body.mass": [1.0, 2.0]})
    with pytest.raises(acausal.SimulationError, match="road"):
        quarter_car.sweep(T_END, t=GRID, inputs={"road": [np.zeros(7), np.ones(7)]})
    with pytest.raises(acausal.SimulationError, match="no option 'max_num_step'"):
        quarter_car.sweep(T_END, params={"body.m": [1.0, 2.0]}, solver="cvodes",
                          options={"max_num_step": 10})


def test_local_cluster_equals_local_bit_for_bit(quarter_car, dask_scratch):
    pytest.importorskip("distributed")
    kw = dict(t=GRID, params={"suspension.c": [10e3, 16e3, 25e3], "body.m": [200.0, 300.0]},
              inputs={"road": road})
    here = quarter_car.sweep(T_END, **kw)
    there = quarter_car.sweep(T_END, cluster="local", workers=2, chunk=2, **kw)
    assert there.method == "map" and not there.failed
    for name in here.dataset.data_vars:
        np.testing.assert_array_equal(there[name], here[name])


def test_time_events_at_the_runs_parameters():
    """A road table starting at a parameter's time: a run whose start falls inside the
    grid has a time event (simulate() restarts there), so those runs go through simulate();
    runs without one share the mapped integrator."""
    x = np.linspace(0.0, 60.0, 300)
    car = acausal.compile(models.QuarterCar(road=np.column_stack([x / 10.0, road(x / 10.0)])))
    mapped = car.sweep(T_END, t=GRID, params={"body.m": [250.0, 300.0]}, variables=["body.s"])
    assert mapped.method == "map"
    moved = car.sweep(T_END, t=GRID, params={"roadTable.startTime": [0.0, 0.5]},
                      variables=["body.s"])
    assert moved.method == "simulate"
    for res, name, values in ((mapped, "body.m", (250.0, 300.0)),
                              (moved, "roadTable.startTime", (0.0, 0.5))):
        for k, v in enumerate(values):
            ref = car.simulate(T_END, t=GRID, params={name: v})
            np.testing.assert_allclose(res["body.s"][k], ref["body.s"], rtol=0, atol=1e-8)


def test_dae_runs_with_idas():
    """A massless node between a spring and a damper (an algebraic variable): IDAS, the
    runs as simulate()'s."""
    from acausal.components.translational import Damper, Fixed, Mass, Spring
    m = acausal.Model("node")
    m.wall, m.spring, m.node = Fixed(), Spring(c=100.0), Mass(m=0.0)
    m.damper, m.mass, m.spring2 = Damper(d=5.0), Mass(m=1.0), Spring(c=10.0)
    for a, b in [(m.wall.flange, m.spring.flange_a), (m.spring.flange_b, m.node.flange_a),
                 (m.node.flange_b, m.damper.flange_a), (m.damper.flange_b, m.mass.flange_a),
                 (m.wall.flange, m.spring2.flange_a), (m.spring2.flange_b, m.mass.flange_b)]:
        m.connect(a, b)
    compiled = acausal.compile(m)
    assert compiled.z_names == ["node.v"]
    res = compiled.sweep(T_END, t=GRID, params={"spring.c": [50.0, 100.0]},
                         x0={"mass.s": [0.3, -0.1]}, variables=["mass.s", "node.s", "node.v"])
    np.testing.assert_array_equal(res.dataset["solver"], ["idas"] * 4)
    assert_as_loop(compiled, res)


def test_failed_run_on_a_cluster_is_reported_as_here(dask_scratch):
    """A run that fails on a worker (the softening spring's runaway) is reported with the
    same index and message as in this process; the others are equal bit for bit."""
    distributed = pytest.importorskip("distributed")
    duffing = acausal.compile(models.duffing_model())
    kw = dict(params={"spring.c3": [40.0, -40.0, 10.0]}, x0={"mass.s": 2.0},
              options={"max_num_steps": 5000})
    here = duffing.sweep(5.0, **kw)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=":0") as cluster, \
            distributed.Client(cluster) as client:
        there = duffing.sweep(5.0, client=client, chunk=1, **kw)
    assert there.failed == here.failed and sorted(there.failed) == [1]
    np.testing.assert_array_equal(there["mass.s"], here["mass.s"])
