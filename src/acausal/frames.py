"""Orientations of 3-D frames, after Modelica.Mechanics.MultiBody.Frames, on CasADi SX.

A base leaf (imports only casadi): the components and the compiler share it. An orientation
is MSL's transformation matrix T = R.T from frame 1 to frame 2 (v_2 = T·v_1); a 3-D frame's
position is stored as ``pose(r_0, T)``: r_0 [m] resolved in the world, then T row by row
(the potentials r_0[1..3], R.T[1,1], R.T[1,2], ..., R.T[3,3] of the frame connector).
"""
from __future__ import annotations

import casadi as ca

__all__ = ["skew", "vee", "pose", "parts", "planar_rotation", "resolve1", "resolve_dyade1",
           "resolve2", "from_nxy", "equality_constraint", "FRAME_ROWS"]


def _sx(v) -> ca.SX:
    if isinstance(v, ca.SX):
        return v
    if isinstance(v, (list, tuple)):
        return ca.vertcat(*[ca.SX(x) if not isinstance(x, ca.SX) else x for x in v])
    return ca.SX(v)


def skew(w) -> ca.SX:
    """[w×]: the matrix of the cross product with the 3-vector w (MSL's skew)."""
    w = _sx(w)
    return ca.vertcat(ca.horzcat(0, -w[2], w[1]), ca.horzcat(w[2], 0, -w[0]),
                      ca.horzcat(-w[1], w[0], 0))


def vee(W) -> ca.SX:
    """The 3-vector of the skew-symmetric part of W (inverse of ``skew``)."""
    return 0.5 * ca.vertcat(W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1])


def pose(r, T) -> ca.SX:
    """A 3-D frame's position: r_0 [m] and T = R.T row by row (12 numbers)."""
    return ca.vertcat(_sx(r), ca.vec(_sx(T).T))


def parts(p) -> tuple[ca.SX, ca.SX]:
    """(r_0, T) of a 3-D frame's position ``pose``."""
    return p[:3], ca.reshape(p[3:12], 3, 3).T


def planar_rotation(e, angle) -> ca.SX:
    """MSL's Frames.planarRotation(e, angle).T: rotation by ``angle`` [rad] about the unit
    vector e (same in both frames): T = e·eᵀ + (I − e·eᵀ)·cos(angle) − [e×]·sin(angle)."""
    e = _sx(e)
    ee = ca.mtimes(e, e.T)
    return ee + (ca.SX.eye(3) - ee) * ca.cos(angle) - skew(e) * ca.sin(angle)


def resolve1(T, v) -> ca.SX:
    """v resolved in frame 2 -> resolved in frame 1: Tᵀ·v (MSL's resolve1)."""
    return ca.mtimes(_sx(T).T, _sx(v))


def resolve2(T, v) -> ca.SX:
    """v resolved in frame 1 -> resolved in frame 2: T·v (MSL's resolve2)."""
    return ca.mtimes(_sx(T), _sx(v))


def resolve_dyade1(T, D) -> ca.SX:
    """A second-order tensor resolved in frame 2 -> frame 1: Tᵀ·D·T (MSL's resolveDyade1)."""
    T = _sx(T)
    return ca.mtimes([T.T, _sx(D), T])


def from_nxy(n_x, n_y) -> ca.SX:
    """MSL's Frames.from_nxy(n_x, n_y).T: frame 2's x axis along n_x, its y axis in the
    plane of n_x and n_y (another axis if they are parallel, as MSL chooses), rows e_x,
    e_y, e_z. A vanishing n_x or n_y stands for {1,0,0} / {0,1,0}, as in MSL."""
    n_x, n_y = _sx(n_x), _sx(n_y)
    lx, ly = ca.norm_2(n_x), ca.norm_2(n_y)
    e_x = ca.if_else(lx < 1e-10, ca.vertcat(1, 0, 0), n_x / ca.fmax(lx, 1e-300))
    e_y = ca.if_else(ly < 1e-10, ca.vertcat(0, 1, 0), n_y / ca.fmax(ly, 1e-300))
    n_z_aux = ca.cross(e_x, e_y)
    n_y_aux = ca.if_else(ca.dot(n_z_aux, n_z_aux) > 1e-6, e_y,
                         ca.if_else(ca.fabs(e_x[0]) > 1e-6, ca.vertcat(0, 1, 0),
                                    ca.vertcat(1, 0, 0)))
    e_z_aux = ca.cross(e_x, n_y_aux)
    e_z = e_z_aux / ca.norm_2(e_z_aux)
    return ca.vertcat(e_x.T, ca.cross(e_z, e_x).T, e_z.T)


def equality_constraint(T1, T2) -> ca.SX:
    """MSL's Frames.Orientation.equalityConstraint: 3 residues that vanish when T1 = T2;
    for T2 = (I − [θ×])·T1 close to T1 they are θ [rad], the small rotation from frame 1
    to frame 2 (resolved in either). Atan2 of the axes' projections, so they stay regular
    up to a relative rotation of 90° about any axis."""
    T1, T2 = _sx(T1), _sx(T2)
    z1 = ca.cross(T1[0, :].T, T1[1, :].T)
    c = ca.dot(T1[0, :], T2[0, :])
    return ca.vertcat(ca.atan2(ca.dot(z1, T2[1, :].T), c),
                      ca.atan2(-ca.dot(z1, T2[0, :].T), c),
                      ca.atan2(ca.dot(T1[1, :], T2[0, :]), c))


#: names of the 6 rows that make two 3-D frames coincide: their position difference
#: resolved in the frame, then ``equality_constraint``
FRAME_ROWS = ("r_rel[1]", "r_rel[2]", "r_rel[3]", "residue[1]", "residue[2]", "residue[3]")
