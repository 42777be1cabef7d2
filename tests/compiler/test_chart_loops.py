"""Closed loops whose spanning tree holds a Spherical or FreeMotion joint (quaternion states,
``compiler.charts``): the loop constraints Φ in the chart coordinates (at θ = 0, functions
of Q), Φ_q in the quasi-velocities w, and the stabilized index-2 correction moving the
quaternion too. Checked against tree models of the same mechanism, loop closure over the
run and the energy balance from the recorded motion."""
from __future__ import annotations

import math
import warnings

import numpy as np

import acausal
from acausal.components.multibody import (Body, BodyShape, FixedTranslation, FreeMotion,
                                          Revolute, Spherical, SphericalSpherical, World)
from body_energy import body_energy, orientation, vector
from wiring import model

TOL = dict(rtol=1e-10, atol=1e-12)
BAR = dict(r=(1.0, 0, 0), r_CM=(0.5, 0, 0), m=1.0, I_11=0.01, I_22=0.1, I_33=0.1)
AXIS = np.array([1.0, 1.0, 0.0]) / math.sqrt(2)


def _simulate(m, t_final, t, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")          # start speeds moved onto the loop
        return acausal.compile(m).simulate(t_final, t=t, **kwargs)


def test_spherical_joint_in_a_loop_closed_by_a_rod_moves_as_the_tree_of_two_revolutes():
    """A bar on a Spherical joint at the origin, its tip {1, 0, 0} tied to {1, 1, 0} by a
    SphericalSpherical rod of 1 m: the tip stays on the circle about the axis {1, 1, 0}/√2
    through the origin, so the bar turns about that axis and spins about its own: the tree
    Revolute({1, 1, 0}/√2) + Revolute({1, 0, 0}) with the same start speeds. 3 chart
    coordinates, 1 loop row; the bar's tip and orientation agree to 1e-7 over 5 s, the rod's
    length holds to 1e-9."""
    om, spin = 2.0, 3.0
    loop = model("sphericalRod", lambda m: (
        (m.world.frame_b, m.sph.frame_a), (m.sph.frame_b, m.bar.frame_a),
        (m.world.frame_b, m.fix.frame_a), (m.bar.frame_b, m.rod.frame_a),
        (m.fix.frame_b, m.rod.frame_b)),
        world=World(), sph=Spherical(w_rel_a_start=tuple(om * AXIS + (spin, 0, 0))),
        bar=BodyShape(**BAR), fix=FixedTranslation(r=(1.0, 1.0, 0)),
        rod=SphericalSpherical(rodLength=1.0))
    compiled = acausal.compile(loop)
    assert (len(compiled.coordinates), compiled.loop_rows) == (3, ["rod.rodLength"])
    tree = model("tree", lambda m: (
        (m.world.frame_b, m.r1.frame_a), (m.r1.frame_b, m.r2.frame_a),
        (m.r2.frame_b, m.bar.frame_a)),
        world=World(), r1=Revolute(n=tuple(AXIS)), r2=Revolute(n=(1, 0, 0)),
        bar=BodyShape(**BAR))
    t = np.linspace(0.0, 5.0, 101)
    a = _simulate(loop, 5.0, t, **TOL)
    b = acausal.compile(tree).simulate(5.0, t=t, x0={"r1.w": om, "r2.w": spin}, rtol=1e-12,
                                       atol=1e-14)
    tip = vector(a, "bar.frame_b.r_0")
    assert np.max(np.abs(np.linalg.norm(tip - (1, 1, 0), axis=1) - 1.0)) < 1e-9
    assert np.max(np.abs(tip - vector(b, "bar.frame_b.r_0"))) < 1e-7
    assert np.max(np.abs(orientation(a, "bar.frame_a") - orientation(b, "bar.frame_a"))) < 1e-7
    assert np.ptp(tip[:, 2]) > 0.5
    # no friction, no drive: the bar's energy from its recorded motion alone is constant
    kinetic, potential = body_energy(a, "bar", BAR["m"], BAR["r_CM"],
                                     np.diag([BAR["I_11"], BAR["I_22"], BAR["I_33"]]),
                                     "bar.body.w_a")
    energy = kinetic + potential
    assert np.max(np.abs(energy - energy[0])) < 1e-7 * np.ptp(kinetic)


def test_free_body_held_by_a_revolute_is_a_pendulum():
    """A body on a FreeMotion from the world, also hinged to the world by a Revolute about z
    (6 loop rows; 7 coordinates, 1 degree of freedom): the revolute's pendulum, its angle to
    1e-8 rad over 5 s; the free motion's relative position stays 0 and its orientation the
    rotation about z by that angle (to 1e-9)."""
    body = dict(m=1.0, r_CM=(0.5, 0, 0), I_11=0.01, I_22=0.1, I_33=0.1)
    loop = model("freeHinged", lambda m: (
        (m.world.frame_b, m.free.frame_a), (m.free.frame_b, m.body.frame_a),
        (m.world.frame_b, m.rev.frame_a), (m.rev.frame_b, m.body.frame_a)),
        world=World(), free=FreeMotion(), body=Body(**body), rev=Revolute())
    pendulum = model("pendulum", lambda m: (
        (m.world.frame_b, m.rev.frame_a), (m.rev.frame_b, m.body.frame_a)),
        world=World(), body=Body(**body), rev=Revolute())
    t = np.linspace(0.0, 5.0, 101)
    a = _simulate(loop, 5.0, t, x0={"rev.phi": 0.3}, rtol=1e-12, atol=1e-14)
    b = acausal.compile(pendulum).simulate(5.0, t=t, x0={"rev.phi": 0.3}, rtol=1e-12,
                                           atol=1e-14)
    phi = a["rev.phi"]
    assert np.max(np.abs(phi - b["rev.phi"])) < 1e-8
    assert np.max(np.abs(vector(a, "free.r_rel_a"))) < 1e-9
    T = orientation(a, "body.frame_a")
    assert np.max(np.abs(T[:, 0, 0] - np.cos(phi))) < 1e-9
    assert np.max(np.abs(T[:, 0, 1] - np.sin(phi))) < 1e-9
    assert np.max(np.abs(T[:, 2, 2] - 1.0)) < 1e-9


def test_spatial_four_bar_through_two_spherical_joints_stays_closed_and_keeps_its_energy():
    """An RSSR linkage: crank Revolute about z, coupler between two Spherical joints (it
    may spin about its own line, a second degree of freedom), rocker Revolute about x; the
    rocker's revolute closes the loop (6 rows). Over 3 s: the rocker's pivot stays at the
    ground point and its orientation the rotation about x by its angle (loop closure to
    1e-9), and the energy of the three bodies (from their recorded motion) is constant to
    1e-8 of the kinetic energy's swing."""
    I = dict(I_11=0.01, I_22=0.02, I_33=0.03)
    links = {"crank": ((0.5, 0, 0), 1.0), "coupler": ((1.0, 0.4, 0.3), 1.0),
             "rocker": ((0, 0.4, 0), 1.0)}
    parts = {k: BodyShape(r=r, r_CM=tuple(x / 2 for x in r), m=mass, **I)
             for k, (r, mass) in links.items()}
    m = model("rssr", lambda m: (
        (m.world.frame_b, m.j1.frame_a), (m.j1.frame_b, m.crank.frame_a),
        (m.crank.frame_b, m.s1.frame_a), (m.s1.frame_b, m.coupler.frame_a),
        (m.coupler.frame_b, m.s2.frame_a), (m.s2.frame_b, m.rocker.frame_b),
        (m.world.frame_b, m.ground.frame_a), (m.ground.frame_b, m.j4.frame_a),
        (m.j4.frame_b, m.rocker.frame_a)),
        world=World(), j1=Revolute(), s1=Spherical(), s2=Spherical(),
        ground=FixedTranslation(r=(1.5, 0, 0.3)), j4=Revolute(n=(1, 0, 0)), **parts)
    compiled = acausal.compile(m)
    assert len(compiled.coordinates) == 8 and len(compiled.loop_rows) == 6
    res = _simulate(m, 3.0, np.linspace(0.0, 3.0, 121), x0={"j1.w": 2.0}, **TOL)
    assert np.max(np.abs(vector(res, "rocker.frame_a.r_0") - (1.5, 0, 0.3))) < 1e-9
    T, psi = orientation(res, "rocker.frame_a"), res["j4.phi"]
    assert np.max(np.abs(T[:, 1, 1] - np.cos(psi))) + np.max(np.abs(T[:, 1, 2] - np.sin(psi))) \
        + np.max(np.abs(T[:, 0, 0] - 1.0)) < 1e-9
    assert np.ptp(psi) > 1.0
    energies = [body_energy(res, k, mass, tuple(x / 2 for x in r),
                            np.diag([I["I_11"], I["I_22"], I["I_33"]]), f"{k}.body.w_a")
                for k, (r, mass) in links.items()]
    kinetic = sum(e[0] for e in energies)
    energy = kinetic + sum(e[1] for e in energies)
    assert np.max(np.abs(energy - energy[0])) < 1e-8 * np.ptp(kinetic)
