"""Inverse and mixed dynamics: the forces that make a mechanism follow a prescribed motion.

- ``inverse_dynamics``: the motion is prescribed inside the model (as many exact Position/
  Speed sources as degrees of freedom): the kinematic analysis, whose Result holds every
  port flow — the torques/forces the sources apply and every joint reaction (cut forces and
  torques, Modelica sign: positive into the component). ``result.drivers`` gathers the flows
  of the prescribed 1-D flanges (the source's flange and the driven joint's, equal and
  opposite), found as the flanges whose position depends on time but on no free coordinate.
- ``mixed_dynamics``: some forces unknown (model Inputs), as many motions prescribed by name
  (any recorded variable of the positions: a joint angle, a slider's position, a body's x), the
  rest of the loads known: the unknown inputs are solved with the accelerations at each time
  (see acausal.analysis.kinematics). ``result.drivers`` holds the unknown inputs' values.
  Motions prescribed here must fix every coordinate (with the loops); fewer motions than
  degrees of freedom would need a time integration of the others (not done here: simulate).
"""
from __future__ import annotations

import casadi as ca

from ..simulation.result import Result
from .kinematics import MotionSolver


def inverse_dynamics(model, t, *, params: dict | None = None, inputs: dict | None = None,
                     guess: dict | None = None, tol: float = 1e-12) -> Result:
    """Kinematic analysis (see ``kinematic_analysis``) of a model driven by prescribed motions,
    with ``result.drivers``: the cut torque [N.m] / force [N] at each prescribed flange by
    name (e.g. ``rev1.axis.tau``, the torque the drive applies to joint rev1)."""
    res = MotionSolver(model, t, params, inputs, {}, [], guess, tol).run()
    res.drivers = {n: res[n] for n in prescribed_flange_flows(model)}
    return res


def mixed_dynamics(model, t, motion: dict, unknown: list[str], *, params: dict | None = None,
                   inputs: dict | None = None, guess: dict | None = None,
                   tol: float = 1e-12) -> Result:
    """The unknown inputs (names of model Inputs: forces or torques) that make the variables
    in ``motion`` follow their prescribed motion, the other inputs being known (``inputs``,
    as for simulate), on the time grid t [s]; a Result of every variable (reactions
    included) with ``result.drivers`` = {unknown input: values}.

    motion: name -> a function of time (AD gives its rates; numpy ufuncs work), a number, or
    samples (times, positions) (cubic spline) or (times, positions, rates, accelerations)
    (exact at the sample times: e.g. a simulation's ``rev1.phi``, ``rev1.w``, ``rev1.z``).
    """
    res = MotionSolver(model, t, params, inputs, dict(motion), list(unknown), guess, tol).run()
    res.drivers = {n: res[n] for n in unknown}
    return res


def prescribed_flange_flows(model) -> list[str]:
    """Flow names of the 1-D flanges whose position is prescribed (depends on time or on
    non-mechanical states, not on the coordinates q, q̇)."""
    L = model.lagrange
    mech = ca.vertcat(L.q, L.qd)
    names = set(model.recorded_names)
    out = []
    for n in model.recorded_names:
        base, _, pot = n.rpartition(".")
        flow = {"phi": "tau", "s": "f"}.get(pot)
        if not base or flow is None or f"{base}.{flow}" not in names:
            continue
        ex = model.expression(n)
        if not ca.depends_on(ex, mech) and ca.depends_on(ex, ca.vertcat(model.t, model.x)):
            out.append(f"{base}.{flow}")
    return out
