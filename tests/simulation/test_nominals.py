"""Nominals: a state's absolute tolerance is atol·nominal (Modelica's nominal attribute).

References:
- MSL's Modelica.Mechanics.Rotational.Examples.ElasticBearing, its reference result of the
  Modelica Association (MAP-LIB_ReferenceResults, DASSL at Tolerance 1e-6, the example's own
  experiment; read from shared/ when at hand, see tests/conftest.py) and a run of the
  same model at rtol 1e-12;
- a translational spring-damper on a mass against the damped oscillator's closed form;
- the rule that maps a variable's nominal onto the state it coincides with, checked by hand
  on small models (a gear scales the nominal by its ratio).
"""
from __future__ import annotations

import numpy as np
import pytest

import acausal
from acausal.components import rotational as rot
from acausal.components import translational as tr
from acausal.errors import ParameterError, SimulationError, StructureError, VariableNameError
from acausal.models import ElasticBearing

# ---- MSL's ElasticBearing ---------------------------------------------------------------------
GRID = np.linspace(0.0, 10.0, 2001)          # the reference's interval, 0.005 s
EXPERIMENT = {"rtol": 1e-6, "atol": 1e-8}    # MSL's Tolerance; abstol = 0.01·reltol·nominal
                                             # (Rotational.UsersGuide.StateSelection)
@pytest.fixture(scope="module")
def bearing():
    compiled = acausal.compile(ElasticBearing())
    tight = compiled.simulate(10.0, t=GRID, rtol=1e-12, atol=1e-14)
    return compiled, tight


def test_elastic_bearing_carries_msl_nominals(bearing):
    """The housing's angle is springDamper.phi_rel (flange_a fixed): MSL's phi_nominal;
    its speed is w_rel, the example's nominal 1e-4; the others keep 1."""
    compiled, _ = bearing
    nominal = {v.name: v.nominal for v in compiled.states}
    assert nominal == {"shaft.phi": 1.0, "load.phi": 1.0, "housing.phi": 1e-4,
                       "shaft.w": 1.0, "load.w": 1.0, "housing.w": 1e-4}
    changed = compiled.nominals(compiled.param_vector({"springDamper.phi_nominal": 1e-3}))
    assert changed[compiled.x_names.index("housing.phi")] == pytest.approx(1e-3)


def test_elastic_bearing_at_the_experiment_tolerance(bearing):
    """At MSL's tolerance 1e-6 the bearing's w_rel is within 2e-3 of its peak of a run at
    1e-12 (3e-4 here); without the nominals it is off by more than 4e-3."""
    compiled, tight = bearing
    res = compiled.simulate(10.0, t=GRID, **EXPERIMENT)
    peak = np.max(np.abs(tight["springDamper.w_rel"]))
    assert np.max(np.abs(res["springDamper.w_rel"] - tight["springDamper.w_rel"])) \
        < 2e-3 * peak
    # the same run with every nominal 1: the error control misses the bearing's motion
    plain = compiled.simulate(10.0, t=GRID, nominal={"housing.phi": 1.0, "housing.w": 1.0},
                              **EXPERIMENT)
    assert np.max(np.abs(plain["springDamper.w_rel"] - tight["springDamper.w_rel"])) \
        > 4e-3 * peak


def test_elastic_bearing_matches_the_msl_reference(bearing, reference_result):
    """The Modelica Association's reference result (Dymola, DASSL at the experiment's
    tolerance 1e-6): every signal within 2e-3 of its peak on the reference's grid, at the
    same tolerance."""
    ref = reference_result("MAP-LIB_ReferenceResults",
                           "Modelica.Mechanics.Rotational.Examples.ElasticBearing")
    compiled, _ = bearing
    t = ref["time"]
    res = compiled.simulate(float(t[-1]), t=t, **EXPERIMENT)
    for name, values in ref.items():
        if name != "time":
            assert np.max(np.abs(res[name] - values)) < 2e-3 * np.max(np.abs(values)), name


# ---- the damped oscillator ----------------------------------------------------------------------
M, C, D, X0 = 1.0, 1e4, 20.0, 1e-4          # kg, N/m, N.s/m, m: a stiff mount, 0.1 mm


def mount(**params):
    model = acausal.Model("mount")
    model.fixed = tr.Fixed()
    model.springDamper = tr.SpringDamper(c=C, d=D, **params)
    model.mass = tr.Mass(m=M)
    model.connect(model.fixed.flange, model.springDamper.flange_a)
    model.connect(model.springDamper.flange_b, model.mass.flange_a)
    return model


def closed_form(t):
    w0, zeta = np.sqrt(C / M), D / (2 * np.sqrt(C * M))
    wd = w0 * np.sqrt(1 - zeta ** 2)
    return np.exp(-zeta * w0 * t) * (X0 * np.cos(wd * t) + zeta * w0 * X0 / wd * np.sin(wd * t))


@pytest.mark.parametrize("solver", ["cvodes", "adams", "idas"])
def test_spring_damper_mount_against_its_closed_form(solver):
    """s_rel = mass.s: MSL's s_nominal 1e-4 m makes mass.s's absolute tolerance 1e-12 m at
    atol 1e-8 (here as large as rtol: the absolute tolerance decides for a state of 1e-4 m);
    every solver then follows the closed form to 1e-5 of the amplitude, and is more than 10
    times worse with s_nominal = 1."""
    compiled = acausal.compile(mount())
    assert compiled.states[0].name == "mass.s" and compiled.states[0].nominal == 1e-4
    t = np.linspace(0.0, 0.5, 501)
    ref = closed_form(t)
    errors = []
    for params in ({}, {"springDamper.s_nominal": 1.0}):
        res = compiled.simulate(0.5, t=t, x0={"mass.s": X0}, params=params, solver=solver,
                                rtol=1e-8, atol=1e-8)
        errors.append(np.max(np.abs(res["mass.s"] - ref)) / X0)
    assert errors[0] < 1e-5
    assert errors[1] > 10 * errors[0]


# ---- the rule: which state a variable's nominal reaches ------------------------------------------
def geared(between_inertias=False, **damper):
    """inertia ── gear (ratio 4) ── damper (``damper``: its keywords) ── fixed at 0.2 rad
    (or a second inertia)."""
    model = acausal.Model("geared")
    model.inertia = rot.Inertia(J=2.0)
    model.gear = rot.IdealGear(ratio=4.0)
    model.damper = rot.Damper(d=3.0, **damper)
    model.connect(model.inertia.flange_b, model.gear.flange_a)
    model.connect(model.gear.flange_b, model.damper.flange_b)
    if between_inertias:
        model.other = rot.Inertia(J=1.0)
        model.connect(model.damper.flange_a, model.other.flange_a)
    else:
        model.fixed = rot.Fixed(phi0=0.2)
        model.connect(model.damper.flange_a, model.fixed.flange)
    return model


def test_a_nominal_reaches_the_state_through_a_gear():
    """damper.phi_rel = inertia.phi/ratio − phi0: the inertia's angle gets phi_nominal·ratio,
    at the ratio and phi_nominal the parameters have when simulated."""
    compiled = acausal.compile(geared())
    x = compiled.x_names
    assert compiled.nominals(compiled.param_vector())[x.index("inertia.phi")] \
        == pytest.approx(4e-4)
    n = compiled.nominals(compiled.param_vector({"gear.ratio": 2.0,
                                                 "damper.phi_nominal": 1e-3}))
    assert n[x.index("inertia.phi")] == pytest.approx(2e-3)
    assert n[x.index("inertia.w")] == 1.0
    # MSL: a phi_nominal below machine epsilon means 1
    n = compiled.nominals(compiled.param_vector({"damper.phi_nominal": 0.0}))
    assert n[x.index("inertia.phi")] == pytest.approx(4.0)
    # simulate's nominal by a coinciding variable's name: value·ratio on the state
    n = compiled.nominals(compiled.param_vector(), {"damper.w_rel": 1e-3})
    assert n[x.index("inertia.w")] == pytest.approx(4e-3)


def test_a_nominal_of_no_single_state_leaves_the_states_alone():
    """Between two moving inertias phi_rel is a difference of two states: no state takes
    its nominal (MSL would pick phi_rel as a state; here the coordinates are absolute)."""
    compiled = acausal.compile(geared(between_inertias=True))
    assert all(v.nominal == 1.0 for v in compiled.states)
    with pytest.raises(SimulationError, match="damper.phi_rel.*no state"):
        compiled.nominals(compiled.param_vector(), {"damper.phi_rel": 1e-3})


def test_nominal_errors_name_the_variable():
    compiled = acausal.compile(geared())
    p = compiled.param_vector()
    with pytest.raises(VariableNameError, match="inertia.phi"):
        compiled.nominals(p, {"inertia.phii": 1e-3})
    for bad in (0.0, -1.0, float("inf"), "x"):
        with pytest.raises(SimulationError, match=r"nominal\['inertia.w'\]"):
            compiled.nominals(p, {"inertia.w": bad})
    with pytest.raises(ParameterError, match="nominal of 'w_rel'"):
        rot.Damper(nominal={"w_rel": 0.0})
    with pytest.raises(ParameterError, match="dict"):
        rot.Damper(nominal=1e-4)
    misspelt = acausal.Model("m")
    misspelt.inertia = rot.Inertia(nominal={"ww": 1e-3})
    with pytest.raises(StructureError, match="inertia.ww.*inertia.w"):
        acausal.compile(misspelt)


def test_a_components_nominal_keyword_replaces_its_declared_one():
    """nominal={"phi_rel": ...} on the damper replaces its phi_nominal for phi_rel."""
    compiled = acausal.compile(geared(nominal={"phi_rel": 5e-3}))
    assert compiled.states[compiled.x_names.index("inertia.phi")].nominal == pytest.approx(2e-2)
