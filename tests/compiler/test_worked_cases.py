"""The worked cases of machine-dynamics courses (gantry crane, hard-disk head, pendulum on a spring-mounted
cart), built from planar and 1-D components in acausal.models, against their closed forms.

1. compiled.lagrange's M, C, K, gravity, coriolis, B and Q_rest equal the textbook formulas at 25
   random states and parameter sets (parameters through compiled.param_vector) to 1e-12, and
   so do the accelerations of the compiled ODE right-hand side (to 1e-10 relative);
2. simulations with forcing equal hand-written CasADi ODEs of the closed forms (cvodes,
   rtol 1e-12) to 1e-7.

Coordinate maps, textbook → compiled (same sign: the checks below would fail otherwise):
    gantry crane     x = rail.s      θ = hinge.phi   (θ from the downward vertical, CCW)
    hard-disk head   θ = pivot.phi   δ = flexure.s   (δ along the arm's normal, towards +θ)
    pendulum on cart x = rail.s      φ = hinge.phi   (φ from the downward vertical, CCW)
The maps are applied by name (lagrange.q_names), so they do not depend on the order in which
the compiler lists its coordinates.
"""
import casadi as ca
import numpy as np
import pytest

import acausal
from acausal.models import DiskDriveHead, GantryCrane, PendulumOnCart

N_RANDOM = 25
EXACT = dict(rtol=1e-12, atol=1e-12)
PIECES = ("M", "C", "K", "gravity", "coriolis", "B", "Q_rest")
SIM = dict(rtol=1e-10, atol=1e-12)            # compiled model's integrator
HAND = {"reltol": 1e-12, "abstol": 1e-14}     # hand-written model's cvodes
SIM_TOL = 1e-7

CRANE_MAP = ("rail.s", "hinge.phi")           # the textbook's [x, θ]
DISK_MAP = ("pivot.phi", "flexure.s")         # the textbook's [θ, δ]
CART_MAP = ("rail.s", "hinge.phi")            # the textbook's [x, φ]


# ---- closed forms, all in the textbook's coordinates ---------------------------------------
def crane_closed(q, qd, u, t, P):
    """Gantry crane, q = [x, θ], u = [F]: M q'' + C q' + K q = grav + nonlin + B u + Q_rest."""
    M, m, L, c, cT, g = P["M"], P["m"], P["L"], P["c"], P["c_T"], P["g"]
    th, thd = q[1], qd[1]
    return {"M": [[M + m, m * L * ca.cos(th)], [m * L * ca.cos(th), m * L ** 2]],
            "C": [[c, 0], [0, cT]], "K": [[0, 0], [0, 0]],
            "gravity": [0, -m * g * L * ca.sin(th)],
            "coriolis": [m * L * ca.sin(th) * thd ** 2, 0],
            "B": [[1], [0]], "Q_rest": [0, 0]}


def disk_closed(q, qd, u, t, P):
    """Hard-disk head, q = [θ, δ], u = [T]."""
    I, m, L, k, cT = P["I"], P["m"], P["L"], P["k"], P["c_T"]
    d, thd, dd = q[1], qd[0], qd[1]
    return {"M": [[I + m * (L ** 2 + d ** 2), m * L], [m * L, m]],
            "C": [[cT, 0], [0, 0]], "K": [[0, 0], [0, k]], "gravity": [0, 0],
            "coriolis": [-2 * m * d * thd * dd, m * d * thd ** 2],
            "B": [[1], [0]], "Q_rest": [0, 0]}


def sine_u(t, P):
    """u(t) = U sin(2π f t + phase), the spring end of the pendulum-on-cart case."""
    return P["U"] * ca.sin(2 * ca.pi * P["f"] * t + P["phase"])


def cart_closed(q, qd, u, t, P, drive="position"):
    """Pendulum on a spring-mounted cart, q = [x, φ]; the textbook's two equations written as
    M q'' + K q = gravity + coriolis + (k u(t) as Q_rest, or B u with the model Input u)."""
    m1, m2, l, JS, k, g = P["m1"], P["m2"], P["l"], P["J_S"], P["k"], P["g"]
    ph, phd = q[1], qd[1]
    out = {"M": [[m1 + m2, m2 * l * ca.cos(ph)], [m2 * l * ca.cos(ph), JS + m2 * l ** 2]],
           "C": [[0, 0], [0, 0]], "K": [[k, 0], [0, 0]],
           "gravity": [0, -m2 * g * l * ca.sin(ph)],
           "coriolis": [m2 * l * ca.sin(ph) * phd ** 2, 0]}
    if drive == "position":
        out.update(B=np.zeros((2, 0)), Q_rest=[k * sine_u(t, P), 0])
    else:
        out.update(B=[[k], [0]], Q_rest=[0, 0])
    return out


# ---- parameters: the textbook's symbols → the models' dotted parameter names ----------------------
def crane_params(P):
    return {"cart.m": P["M"], "load.m": P["m"], "rope.r[2]": -P["L"], "railDamper.d": P["c"],
            "hingeDamper.d": P["c_T"], "world.g": P["g"]}


def disk_params(P):
    return {"arm.I": P["I"], "arm.m": P["m_arm"], "head.m": P["m"], "tip.r[1]": P["L"],
            "flexureSpring.c": P["k"], "pivotDamper.d": P["c_T"]}


def cart_params(P, drive="position"):
    out = {"cart.m": P["m1"], "pendulum.m": P["m2"], "pendulum.I": P["J_S"],
           "arm.r[2]": -P["l"], "spring.c": P["k"], "world.g": P["g"]}
    if drive == "position":
        out.update({"u.amplitude": P["U"], "u.f": P["f"], "u.phase": P["phase"]})
    else:
        out["gain.k"] = P["k"]
    return out


def random_crane(rng):
    return dict(M=rng.uniform(0.5, 5), m=rng.uniform(0.1, 3), L=rng.uniform(0.2, 3),
                c=rng.uniform(0, 2), c_T=rng.uniform(0, 1), g=rng.uniform(1, 15))


def random_disk(rng):
    return dict(I=rng.uniform(0.05, 2), m_arm=rng.uniform(0.1, 3), m=rng.uniform(0.05, 1),
                L=rng.uniform(0.2, 2), k=rng.uniform(1, 100), c_T=rng.uniform(0, 1))


def random_cart(rng):
    return dict(m1=rng.uniform(0.5, 5), m2=rng.uniform(0.1, 3), l=rng.uniform(0.2, 2),
                J_S=rng.uniform(0, 1), k=rng.uniform(1, 100), g=rng.uniform(1, 15),
                U=rng.uniform(-1, 1), f=rng.uniform(0.1, 3), phase=rng.uniform(-3, 3))


# ---- helpers ---------------------------------------------------------------------------------
def _perm(compiled, cmap):
    """Index of each textbook coordinate among the compiled ones (by name)."""
    names = compiled.lagrange.q_names
    assert sorted(names) == sorted(cmap), f"coordinates {names}, expected {cmap}"
    return [names.index(n) for n in cmap]


def _compiled_pieces(compiled, cmap, q, qd, u, t, p):
    """lagrange's pieces at the textbook's (q, qd), rearranged into the textbook's coordinate order."""
    idx = _perm(compiled, cmap)
    qc, qdc = np.zeros(len(q)), np.zeros(len(q))
    qc[idx], qdc[idx] = q, qd
    f = compiled.lagrange.function(*PIECES)
    got = {k: np.array(v) for k, v in f(q=qc, qd=qdc, u=u, t=t, p=p).items()}
    out = {}
    for k, v in got.items():
        if k in ("M", "C", "K"):
            out[k] = v[np.ix_(idx, idx)]
        elif k == "B":
            out[k] = v.reshape(len(q), -1)[idx, :]
        else:
            out[k] = v.ravel()[idx]
    return out


def _num(x):
    """A closed-form piece (nested lists of numbers / DM) as a float array."""
    if isinstance(x, np.ndarray):
        return x.astype(float)
    return np.array([[float(e) for e in row] if isinstance(row, list) else float(row)
                     for row in x], dtype=float)


def _compiled_acc(compiled, cmap, q, qd, u, t, p):
    """q'' of the compiled ODE right-hand side, in the textbook's coordinate order."""
    x = np.zeros(len(compiled.x_names))
    vel = [compiled.lagrange.qd_names[compiled.lagrange.q_names.index(n)] for n in cmap]
    for n, qi in zip(cmap, q):
        x[compiled.x_names.index(n)] = qi
    for n, vi in zip(vel, qd):
        x[compiled.x_names.index(n)] = vi
    ode = np.array(compiled.f(x=x, u=u, p=p, t=t)["xdot"]).ravel()
    return np.array([ode[compiled.x_names.index(n)] for n in vel])


def check_exact(compiled, cmap, closed, to_params, draw, seed, n_u, rand_q, rand_qd):
    assert compiled.lagrange.K is not None and compiled.lagrange.C is not None, \
        "stiffness and damping are linear here: K and C must come out constant"
    rng = np.random.default_rng(seed)
    worst = 0.0
    for _ in range(N_RANDOM):
        P = draw(rng)
        p = compiled.param_vector(to_params(P))
        q, qd = rand_q(rng), rand_qd(rng)
        u, t = rng.uniform(-2, 2, n_u), rng.uniform(0, 5)
        got = _compiled_pieces(compiled, cmap, q, qd, u, t, p)
        ref = {k: _num(v) for k, v in closed(q, qd, u, t, P).items()}
        for k in PIECES:
            np.testing.assert_allclose(got[k], np.reshape(ref[k], got[k].shape), **EXACT,
                                       err_msg=f"{k} at q={q}, qd={qd}, P={P}")
            worst = max(worst, float(np.max(np.abs(got[k] - np.reshape(ref[k], got[k].shape)),
                                            initial=0.0)))
        # the whole assembled ODE: q'' = M⁻¹(grav + coriolis + B u + Q_rest − C q' − K q)
        rhs = (ref["gravity"] + ref["coriolis"] + ref["B"].reshape(2, -1) @ u + ref["Q_rest"]
               - ref["C"] @ qd - ref["K"] @ q)
        acc_ref = np.linalg.solve(ref["M"], rhs)
        acc = _compiled_acc(compiled, cmap, q, qd, u, t, p)
        np.testing.assert_allclose(acc, acc_ref, rtol=1e-10,
                                   atol=1e-10 * max(1.0, np.max(np.abs(acc_ref))))
    return worst


def hand_ode(closed, P, u_of_t, grid, q0, qd0):
    """The textbook equations as a CasADi SX ODE in [q; q'], integrated with cvodes."""
    q, qd, t = ca.SX.sym("q", 2), ca.SX.sym("qd", 2), ca.SX.sym("t")
    u = u_of_t(t)
    pc = closed(q, qd, u, t, P)
    M = ca.blockcat(pc["M"])
    rhs = (ca.vertcat(*pc["gravity"]) + ca.vertcat(*pc["coriolis"]) + ca.vertcat(*pc["Q_rest"])
           - ca.mtimes(ca.blockcat(pc["C"]), qd) - ca.mtimes(ca.blockcat(pc["K"]), q))
    B = pc["B"]
    if np.size(B):
        rhs += ca.mtimes(ca.DM(np.array(B, dtype=float)), u)
    dae = {"x": ca.vertcat(q, qd), "t": t, "ode": ca.vertcat(qd, ca.solve(M, rhs))}
    F = ca.integrator("hand", "cvodes", dae, grid[0], grid[1:], HAND)
    x0 = np.r_[q0, qd0]
    return np.hstack([x0[:, None], np.array(F(x0=x0)["xf"])])


def check_simulation(compiled, cmap, ref):
    """Compiled trajectories of q and q' (res) against the hand model's rows."""
    res, hand = ref
    vel = [compiled.lagrange.qd_names[compiled.lagrange.q_names.index(n)] for n in cmap]
    err = 0.0
    for i, n in enumerate(list(cmap) + vel):
        np.testing.assert_allclose(res[n], hand[i], rtol=0, atol=SIM_TOL, err_msg=n)
        err = max(err, float(np.max(np.abs(res[n] - hand[i]))))
    return err


# ---- fixtures --------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def crane():
    return acausal.compile(GantryCrane())


@pytest.fixture(scope="module")
def disk():
    return acausal.compile(DiskDriveHead())


@pytest.fixture(scope="module")
def cart():
    return acausal.compile(PendulumOnCart())


@pytest.fixture(scope="module")
def cart_input():
    return acausal.compile(PendulumOnCart(drive="input"))


# ---- 1. exact pieces ------------------------------------------------------------------------
def test_crane_pieces_exact(crane):
    assert crane.lagrange.u_names == ["F"]
    worst = check_exact(crane, CRANE_MAP, crane_closed, crane_params, random_crane, 1, 1,
                        lambda r: np.r_[r.uniform(-2, 2), r.uniform(-np.pi, np.pi)],
                        lambda r: r.uniform(-3, 3, 2))
    assert worst < 1e-12


def test_disk_pieces_exact(disk):
    assert disk.lagrange.u_names == ["T"]
    worst = check_exact(disk, DISK_MAP, disk_closed, disk_params, random_disk, 2, 1,
                        lambda r: np.r_[r.uniform(-np.pi, np.pi), r.uniform(-0.5, 0.5)],
                        lambda r: r.uniform(-3, 3, 2))
    assert worst < 1e-12


def test_pendulum_on_cart_pieces_exact(cart):
    assert cart.lagrange.u_names == []
    worst = check_exact(cart, CART_MAP, cart_closed, cart_params, random_cart, 3, 0,
                        lambda r: np.r_[r.uniform(-2, 2), r.uniform(-np.pi, np.pi)],
                        lambda r: r.uniform(-3, 3, 2))
    assert worst < 1e-12


def test_pendulum_on_cart_input_variant_pieces_exact(cart_input):
    assert cart_input.lagrange.u_names == ["u"]
    worst = check_exact(cart_input, CART_MAP,
                        lambda *a: cart_closed(*a, drive="input"),
                        lambda P: cart_params(P, drive="input"), random_cart, 4, 1,
                        lambda r: np.r_[r.uniform(-2, 2), r.uniform(-np.pi, np.pi)],
                        lambda r: r.uniform(-3, 3, 2))
    assert worst < 1e-12


# ---- 2. simulations against hand-written CasADi ODEs ----------------------------------------
def test_crane_simulation(crane):
    P = dict(M=1.5, m=0.8, L=1.2, c=0.4, c_T=0.15, g=9.81)
    grid = np.linspace(0.0, 4.0, 201)
    q0, qd0 = [0.1, 0.6], [0.2, -0.5]
    F = lambda t: 3.0 * ca.sin(1.5 * t)          # noqa: E731  (called with an SX time)
    res = crane.simulate(4.0, t=grid, params=crane_params(P), inputs={"F": F},
                         x0={"rail.s": q0[0], "hinge.phi": q0[1], "rail.v": qd0[0],
                             "hinge.w": qd0[1]}, **SIM)
    hand = hand_ode(crane_closed, P, lambda t: ca.vertcat(F(t)), grid, q0, qd0)
    assert np.ptp(hand[1]) > 0.5                 # a large swing: the nonlinear terms matter
    check_simulation(crane, CRANE_MAP, (res, hand))


def test_disk_simulation(disk):
    P = dict(I=0.4, m_arm=1.0, m=0.3, L=1.1, k=25.0, c_T=0.1)
    grid = np.linspace(0.0, 4.0, 201)
    q0, qd0 = [0.0, 0.05], [1.5, 0.0]
    T = lambda t: 0.8 * ca.sin(2.0 * t) + 0.3    # noqa: E731
    res = disk.simulate(4.0, t=grid, params=disk_params(P), inputs={"T": T},
                        x0={"pivot.phi": q0[0], "flexure.s": q0[1], "pivot.w": qd0[0],
                            "flexure.v": qd0[1]}, **SIM)
    hand = hand_ode(disk_closed, P, lambda t: ca.vertcat(T(t)), grid, q0, qd0)
    assert np.ptp(hand[0]) > 1.0 and np.ptp(hand[1]) > 0.05
    check_simulation(disk, DISK_MAP, (res, hand))


CART_P = dict(m1=1.2, m2=0.6, l=0.7, J_S=0.05, k=30.0, g=9.81, U=0.1, f=0.5, phase=0.0)


def test_pendulum_on_cart_simulation(cart):
    """Spring end moved by Position(exact=True) from a Sine: u(t) = U sin(2π f t)."""
    grid = np.linspace(0.0, 4.0, 201)
    q0, qd0 = [0.05, 0.9], [0.0, 0.4]
    res = cart.simulate(4.0, t=grid, params=cart_params(CART_P),
                        x0={"rail.s": q0[0], "hinge.phi": q0[1], "rail.v": qd0[0],
                            "hinge.w": qd0[1]}, **SIM)
    hand = hand_ode(cart_closed, CART_P, lambda t: ca.SX(0, 1), grid, q0, qd0)
    assert np.ptp(hand[0]) > 0.1 and np.ptp(hand[1]) > 1.0   # swings of ±0.75 rad
    check_simulation(cart, CART_MAP, (res, hand))
    # the prescribed spring end and the spring force follow from the hand model's x
    u = CART_P["U"] * np.sin(2 * np.pi * CART_P["f"] * grid)
    np.testing.assert_allclose(res["shaker.flange.s"], u, rtol=0, atol=1e-12)
    np.testing.assert_allclose(res["spring.f"], CART_P["k"] * (hand[0] - u), rtol=0,
                               atol=CART_P["k"] * SIM_TOL)


def test_pendulum_on_cart_input_variant_simulation(cart_input):
    """The same motion with u(t) as a model Input and the force k·u on the cart."""
    grid = np.linspace(0.0, 4.0, 201)
    q0, qd0 = [0.05, 0.9], [0.0, 0.4]
    w = 2 * np.pi * CART_P["f"]
    res = cart_input.simulate(4.0, t=grid, params=cart_params(CART_P, drive="input"),
                              inputs={"u": lambda t: CART_P["U"] * ca.sin(w * t)},
                              x0={"rail.s": q0[0], "hinge.phi": q0[1], "rail.v": qd0[0],
                                  "hinge.w": qd0[1]}, **SIM)
    hand = hand_ode(cart_closed, CART_P, lambda t: ca.SX(0, 1), grid, q0, qd0)
    check_simulation(cart_input, CART_MAP, (res, hand))
