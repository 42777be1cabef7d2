"""models.QuarterCar against its equations written by hand: m_u·z̈_u = c_t·(r − z_u) +
c_s·(z_s − z_u) + d_s·(ż_s − ż_u), m_s·z̈_s = −c_s·(z_s − z_u) − d_s·(ż_s − ż_u)."""
import numpy as np

import acausal
from acausal import models

M_S, M_U, C_S, D_S, C_T = 300.0, 40.0, 18e3, 1.2e3, 150e3


def hand(x, r):
    """(ż_u, ż_s, z̈_u, z̈_s), body acceleration and travel at x = (z_u, z_s, ż_u, ż_s), road r."""
    zu, zs, vu, vs = x
    f = C_S * (zs - zu) + D_S * (vs - vu)
    au, a_s = (C_T * (r - zu) + f) / M_U, -f / M_S
    return np.array([vu, vs, au, a_s]), a_s, zs - zu


def test_equations_and_outputs_by_hand():
    car = acausal.compile(models.QuarterCar(m_s=M_S, m_u=M_U, c_s=C_S, d_s=D_S, c_t=C_T))
    assert car.x_names == ["wheel.s", "body.s", "wheel.v", "body.v"]
    assert car.input_names == ["road"] and car.output_names == ["a_body", "travel"]
    p = car.param_vector()
    rng = np.random.default_rng(4)
    for _ in range(5):
        x, r = rng.normal(0.0, 0.05, 4), rng.normal(0.0, 0.02)
        xdot = np.array(car.f(x=x, u=r, p=p)["xdot"]).ravel()
        y = np.array(car.output_function(t=0.0, x=x, u=r, p=p)["y"]).ravel()
        ref, a_body, travel = hand(x, r)
        np.testing.assert_allclose(xdot, ref, rtol=1e-13, atol=1e-12)
        np.testing.assert_allclose(y, [a_body, travel], rtol=1e-13, atol=1e-12)


def test_road_table_is_linear_between_rows():
    """With a road table, the equations at any time see the road interpolated linearly."""
    times = np.array([0.0, 0.1, 0.3, 1.0])
    heights = np.array([0.0, 0.02, -0.01, 0.005])
    car = acausal.compile(models.QuarterCar(m_s=M_S, m_u=M_U, c_s=C_S, d_s=D_S, c_t=C_T,
                                            road=np.column_stack([times, heights])))
    assert car.input_names == []
    p = car.param_vector()
    rng = np.random.default_rng(5)
    for t in (0.05, 0.1, 0.2, 0.65, 0.99):
        x = rng.normal(0.0, 0.05, 4)
        xdot = np.array(car.f(t=t, x=x, p=p)["xdot"]).ravel()
        np.testing.assert_allclose(xdot, hand(x, np.interp(t, times, heights))[0],
                                   rtol=1e-13, atol=1e-12)
