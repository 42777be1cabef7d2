"""Start values by MSL's names of the angles and angle rates of free rotations (a
Spherical joint's, a FreeMotion's, a free Body's phi[3] and phi_d[3], in the sequence
sequence_angleStates) and of the free motions' positions and velocities, against the MSL
start parameters (angles_start about sequence_start, w_rel_a_start, w_0_start,
r_rel_a_start, r_0_start ...): the same motion. The angles of the other sequence and the
rates come from scipy's rotations and finite differences, not from the code under test."""
from __future__ import annotations

import numpy as np
from scipy.spatial.transform import Rotation

import acausal
from acausal.components.multibody import Body, BodyShape, FreeMotion, Spherical, World
from body_energy import G, orientation, vector
from wiring import model

TOL = dict(rtol=1e-11, atol=1e-13)
AXES = "XYZ"


def _T(sequence, angles) -> np.ndarray:
    """MSL's axesRotations(sequence, angles).T (world → frame): rotations about the
    frame's axes one after the other, scipy's intrinsic rotations, transposed."""
    return Rotation.from_euler("".join(AXES[k - 1] for k in sequence), angles).as_matrix().T


def _angles_123(sequence, angles) -> np.ndarray:
    """The same orientation's angles in the sequence {1, 2, 3}."""
    return Rotation.from_euler("".join(AXES[k - 1] for k in sequence), angles).as_euler("XYZ")


def _w_frame(phi, phi_d, h=1e-6) -> np.ndarray:
    """Angular velocity resolved in the frame of the angles phi {1, 2, 3} moving at phi_d:
    [w×] = −der(T)·Tᵀ, der(T) by central differences."""
    T = _T((1, 2, 3), phi)
    dT = (_T((1, 2, 3), phi + h * phi_d) - _T((1, 2, 3), phi - h * phi_d)) / (2 * h)
    W = -dT @ T.T
    return np.array([W[2, 1], W[0, 2], W[1, 0]])


def _rates_123(phi, w_frame) -> np.ndarray:
    """phi_d with _w_frame(phi, phi_d) = w_frame (linear in phi_d)."""
    J = np.stack([_w_frame(phi, e) for e in np.eye(3)], axis=1)
    return np.linalg.solve(J, w_frame)


ANGLES, SEQUENCE = np.array([2.9, -0.7, 2.4]), (3, 1, 2)
W_A = np.array([0.5, 1.0, -0.3])                  # resolved in frame_a / the world


def _x0_by_angles(prefix, T_to_frame):
    """x0 of phi, phi_d [rad, rad/s] for the orientation ANGLES about SEQUENCE and the
    angular velocity W_A resolved in the frame the rotation starts from."""
    phi = _angles_123(SEQUENCE, ANGLES)
    phi_d = _rates_123(phi, T_to_frame @ W_A)
    x0 = {f"{prefix}phi[{k + 1}]": v for k, v in enumerate(phi)}
    x0.update({f"{prefix}phi_d[{k + 1}]": v for k, v in enumerate(phi_d)})
    return x0, phi


def _same_motion(a, b, frame):
    assert np.max(np.abs(orientation(a, frame) - orientation(b, frame))) < 1e-8
    assert np.max(np.abs(vector(a, f"{frame}.r_0") - vector(b, f"{frame}.r_0"))) < 1e-8


def test_spherical_pendulum_by_angles_and_rates_moves_as_from_msl_start_parameters():
    """A bar on a Spherical joint: angles_start {2.9, −0.7, 2.4} rad about {3, 1, 2} and
    w_rel_a_start, or x0 of phi[1..3] (the same orientation's angles about {1, 2, 3}, beyond
    the range the recorded phi take) and phi_d[1..3]: the bar moves the same over 2 s (to
    1e-8), and guess by the angles gives that start too (nothing else holds it)."""
    def pendulum(**sph):
        return model("sphericalPendulum", lambda m: (
            (m.world.frame_b, m.sph.frame_a), (m.sph.frame_b, m.bar.frame_a)),
            world=World(), sph=Spherical(**sph),
            bar=BodyShape(r=(1.0, 0, 0), r_CM=(0.5, 0, 0), m=1.0, I_11=0.01, I_22=0.1,
                          I_33=0.1))

    t = np.linspace(0.0, 2.0, 41)
    a = acausal.compile(pendulum(angles_start=tuple(ANGLES), sequence_start=SEQUENCE,
                                 w_rel_a_start=tuple(W_A))).simulate(2.0, t=t, **TOL)
    x0, phi = _x0_by_angles("sph.", _T(SEQUENCE, ANGLES))
    assert abs(phi[0]) > np.pi / 2               # beyond the recorded angles' range
    compiled = acausal.compile(pendulum())
    b = compiled.simulate(2.0, t=t, x0=x0, **TOL)
    _same_motion(a, b, "bar.frame_b")
    assert np.max(np.abs(orientation(b, "bar.frame_a")[0] - _T(SEQUENCE, ANGLES))) < 1e-12
    c = compiled.simulate(2.0, t=t, guess=x0, **TOL)
    _same_motion(a, c, "bar.frame_b")


def test_free_motion_by_msl_names_moves_as_from_msl_start_parameters():
    """A body on a FreeMotion from the world: r_rel_a, v_rel_a, phi, phi_d in x0, or MSL's
    r_rel_a_start, v_rel_a_start, angles_start / sequence_start, w_rel_a_start: the same
    motion (to 1e-8 over 2 s); the recorded phi_d is the rate of the recorded phi (central
    differences, to 1e-4 of its size)."""
    r, v = (0.3, -0.2, 0.5), (1.0, 2.0, -0.5)

    def free(**fm):
        return model("freeMotion", lambda m: (
            (m.world.frame_b, m.free.frame_a), (m.free.frame_b, m.body.frame_a)),
            world=World(), free=FreeMotion(**fm),
            body=Body(m=2.0, r_CM=(0.2, 0.1, 0), I_11=0.1, I_22=0.2, I_33=0.3))

    t = np.linspace(0.0, 2.0, 41)
    a = acausal.compile(free(r_rel_a_start=r, v_rel_a_start=v, angles_start=tuple(ANGLES),
                             sequence_start=SEQUENCE, w_rel_a_start=tuple(W_A))
                        ).simulate(2.0, t=t, **TOL)
    x0, _ = _x0_by_angles("free.", _T(SEQUENCE, ANGLES))
    x0.update({f"free.r_rel_a[{k + 1}]": r[k] for k in range(3)})
    x0.update({f"free.v_rel_a[{k + 1}]": v[k] for k in range(3)})
    b = acausal.compile(free()).simulate(2.0, t=t, x0=x0, **TOL)
    _same_motion(a, b, "body.frame_a")
    # independent of both routes: the start orientation is MSL's, and the centre of mass
    # falls freely, r_CM(t) = r_CM(0) + v_CM(0)·t − ½·g·t²·e_y
    T = orientation(a, "body.frame_a")
    assert np.max(np.abs(T[0] - _T(SEQUENCE, ANGLES))) < 1e-12
    cm = vector(a, "body.frame_a.r_0") + np.einsum("kji,j->ki", T, (0.2, 0.1, 0))
    parabola = np.polyfit(t, cm, 2)
    np.testing.assert_allclose(parabola[0], (0.0, -G / 2, 0.0), atol=1e-8)
    assert np.max(np.abs(np.polyval(parabola[:, 1], t) - cm[:, 1])) < 1e-9
    fine = acausal.compile(free()).simulate(0.5, t=np.linspace(0.0, 0.5, 501), x0=x0, **TOL)
    phi = np.unwrap(vector(fine, "free.phi"), axis=0)
    rate = np.gradient(phi, fine.t, axis=0)[1:-1]
    assert np.max(np.abs(vector(fine, "free.phi_d")[1:-1] - rate)) < 1e-4 * np.max(np.abs(rate))


def test_free_body_by_msl_names_moves_as_from_msl_start_parameters():
    """A free Body: r_0, v_0, phi, phi_d in x0, or MSL's r_0_start, v_0_start,
    angles_start / sequence_start, w_0_start (resolved in the world): the same motion (to
    1e-8 over 2 s)."""
    r, v = (0.3, -0.2, 0.5), (1.0, 2.0, -0.5)
    mass = dict(m=2.0, r_CM=(0.2, 0.1, 0), I_11=0.1, I_22=0.2, I_33=0.3)
    t = np.linspace(0.0, 2.0, 41)
    a = acausal.compile(model("freeBody", lambda m: (), world=World(), body=Body(
        r_0_start=r, v_0_start=v, angles_start=tuple(ANGLES), sequence_start=SEQUENCE,
        w_0_start=tuple(W_A), **mass))).simulate(2.0, t=t, **TOL)
    x0, _ = _x0_by_angles("body.", _T(SEQUENCE, ANGLES))
    x0.update({f"body.r_0[{k + 1}]": r[k] for k in range(3)})
    x0.update({f"body.v_0[{k + 1}]": v[k] for k in range(3)})
    b = acausal.compile(model("freeBody", lambda m: (), world=World(), body=Body(**mass))
                        ).simulate(2.0, t=t, x0=x0, **TOL)
    _same_motion(a, b, "body.frame_a")
    assert np.ptp(vector(b, "body.r_0")[:, 1]) > 1.0


def test_angles_given_in_part_keep_the_others_at_their_start_values():
    """x0 of phi[2] = 2.5 rad alone (beyond the range the recorded phi[2] takes with phi[1]
    in [−π/2, π/2]) on a Spherical joint starting at angles_start {0.2, 0.3, 0.4} about
    {1, 2, 3}: the bar starts at the angles {0.2, 2.5, 0.4} exactly (its frame's R.T)."""
    m = model("sphericalPendulum", lambda m: (
        (m.world.frame_b, m.sph.frame_a), (m.sph.frame_b, m.bar.frame_a)),
        world=World(), sph=Spherical(angles_start=(0.2, 0.3, 0.4)),
        bar=BodyShape(r=(1.0, 0, 0), r_CM=(0.5, 0, 0), m=1.0, I_11=0.01, I_22=0.1,
                      I_33=0.1))
    res = acausal.compile(m).simulate(0.1, t=np.linspace(0, 0.1, 3), x0={"sph.phi[2]": 2.5},
                                      **TOL)
    T0 = orientation(res, "bar.frame_a")[0]
    assert np.max(np.abs(T0 - _T((1, 2, 3), (0.2, 2.5, 0.4)))) < 1e-12
