"""Continuous blocks (Modelica.Blocks.Continuous): integrators, derivatives, first and
second order, controllers, transfer functions, state space, filters."""
from __future__ import annotations

import math
from enum import Enum

import casadi as ca
import numpy as np

from ...core import Component, ConditionalPort, Parameter, RealInput, RealOutput, VectorPort
from ...core.component import BoundParameters, bound_twin, who
from ...errors import ParameterError
from .filter_design import BESSEL_MAX_ORDER, AnalogFilter, FilterType, base_filter, filter_roots
from .interfaces import EPS, Init, _initial_equations, _matrix, SISO, _Sized, _start, _StartValues
from .nonlinear import _check_limits, _limited, _limiter_region, LimiterHomotopy


def _approx_derivative(u, x, k, T):
    """MSL Continuous.Derivative, k·s/(T·s + 1): (der(x), y); both 0 when |k| < eps."""
    zero_gain = ca.fabs(k) < EPS
    return (ca.if_else(zero_gain, 0, (u - x) / T),
            ca.if_else(zero_gain, 0, k / T * (u - x)))


class Integrator(_StartValues, SISO):
    """y = k·∫u dt: der(y) = k·u. Initialization (``initType``, MSL's default InitialState):
    NoInit and InitialState start at y = y_start; SteadyState: der(y) = 0, so k·u = 0 at the
    start (the input must be zero there, or depend on states that can make it zero);
    InitialOutput: y = y_start (held)."""
    _starts = ("y_start",)
    options = {"initType": Init.InitialState}
    k = Parameter(1.0, "1", "integrator gain")

    def structure(self, s):
        s.state("y", self.y_start, description="integrator output (state)")

    def physics(self, e):
        y = e.state("y")
        dy = self.k * e.input(self.u)
        e.derivative(y, dy)
        e.output(self.y, y)
        _initial_equations(e, self, {"y": dy}, {"y = y_start": y - self.y_start})


class Derivative(_StartValues, SISO):
    """Approximated derivative y = k·s/(T·s + 1)·u: der(x) = (u − x)/T, y = (k/T)·(u − x).
    With k = 0 the block gives y = 0. Initialization (``initType``, MSL's default NoInit):
    NoInit and InitialState start at x = x_start; SteadyState: der(x) = 0 (x = u, y = 0);
    InitialOutput: y = y_start (x = u when k = 0)."""
    _starts = ("x_start", "y_start")
    options = {"initType": Init.NoInit}
    k = Parameter(1.0, "1", "gain")
    T = Parameter(0.01, "s", "time constant (T > 0 required)", positive=True)

    def structure(self, s):
        s.state("x", self.x_start, description="state of block")

    def physics(self, e):
        x, u = e.state("x"), e.input(self.u)
        xdot, y = _approx_derivative(u, x, self.k, self.T)
        e.derivative(x, xdot)
        e.output(self.y, y)
        output = ca.if_else(ca.fabs(self.k) < EPS, x - u, y - self.y_start)
        _initial_equations(e, self, {"x": xdot}, {"y = y_start (x = u when k = 0)": output})


class FirstOrder(_StartValues, SISO):
    """First order y = k/(T·s + 1)·u: der(y) = (k·u − y)/T. Initialization (``initType``,
    MSL's default NoInit): NoInit and InitialState start at y = y_start; SteadyState:
    der(y) = 0 (y = k·u); InitialOutput: y = y_start (held)."""
    _starts = ("y_start",)
    options = {"initType": Init.NoInit}
    k = Parameter(1.0, "1", "gain")
    T = Parameter(1.0, "s", "time constant", nonzero=True)

    def structure(self, s):
        s.state("y", self.y_start, description="output (state)")

    def physics(self, e):
        y = e.state("y")
        dy = (self.k * e.input(self.u) - y) / self.T
        e.derivative(y, dy)
        e.output(self.y, y)
        _initial_equations(e, self, {"y": dy}, {"y = y_start": y - self.y_start})


class SecondOrder(_StartValues, SISO):
    """Second order y = k/((s/w)² + 2·D·(s/w) + 1)·u: der(y) = yd,
    der(yd) = w·(w·(k·u − y) − 2·D·yd). Initialization (``initType``, MSL's default
    NoInit): NoInit and InitialState start at y = y_start, yd = yd_start; SteadyState:
    der(y) = der(yd) = 0 (y = k·u, yd = 0); InitialOutput: y = y_start and yd = yd_start
    (held)."""
    _starts = ("y_start", "yd_start")
    options = {"initType": Init.NoInit}
    k = Parameter(1.0, "1", "gain")
    w = Parameter(1.0, "rad/s", "angular frequency")
    D = Parameter(1.0, "1", "damping")

    def structure(self, s):
        s.state("y", self.y_start, description="output (state)")
        s.state("yd", self.yd_start, description="derivative of y (state)")

    def physics(self, e):
        y, yd = e.state("y"), e.state("yd")
        ydd = self.w * (self.w * (self.k * e.input(self.u) - y) - 2 * self.D * yd)
        e.derivative(y, yd)
        e.derivative(yd, ydd)
        e.output(self.y, y)
        _initial_equations(e, self, {"y": yd, "yd": ydd}, {"y = y_start": y - self.y_start,
                                                            "yd = yd_start": yd - self.yd_start})


class PI(_StartValues, SISO):
    """PI controller y = k·(1 + 1/(T·s))·u: der(x) = u/T, y = k·(x + u). Initialization
    (``initType``, MSL's default NoInit): NoInit and InitialState start at x = x_start;
    SteadyState: der(x) = 0, so u = 0 at the start (the input must be zero there, or
    depend on states that can make it zero); InitialOutput: y = y_start."""
    _starts = ("x_start", "y_start")
    options = {"initType": Init.NoInit}
    k = Parameter(1.0, "1", "gain")
    T = Parameter(1.0, "s", "time constant (T > 0 required)", positive=True)

    def structure(self, s):
        s.state("x", self.x_start, description="state of block")

    def physics(self, e):
        x = e.state("x")
        u = e.input(self.u)
        xdot, y = u / self.T, self.k * (x + u)
        e.derivative(x, xdot)
        e.output(self.y, y)
        _initial_equations(e, self, {"x": xdot}, {"y = y_start": y - self.y_start})


class PID(_StartValues, SISO):
    """PID controller in additive form (MSL Continuous.PID): y = k·(P.y + I.y + D.y) with
    P.y = u, I: der(I.y) = u/Ti, D: approximated derivative Td·s/(Td/Nd·s + 1)·u
    (der(D.x) = (u − D.x)/T, D.y = (Td/T)·(u − D.x), T = max(Td/Nd, 100·eps)).

    States ``I.y`` (start xi_start) and ``D.x`` (start xd_start), named as the states of the
    MSL block's sub-blocks (``PID.I.y``, ``PID.D.x``); ``P.y``, ``I.y``, ``D.y`` are recorded.
    Initialization (``initType``, MSL's default InitialState): NoInit and InitialState
    start at the start values; SteadyState: der(I.y) = der(D.x) = 0 (u = 0 at the start,
    as for Integrator); InitialOutput: y = y_start and der(D.x) = 0.
    """
    _starts = ("xi_start", "xd_start", "y_start")
    options = {"initType": Init.InitialState}
    k = Parameter(1.0, "1", "gain")
    Ti = Parameter(0.5, "s", "time constant of integrator", positive=True)
    Td = Parameter(0.1, "s", "time constant of derivative block", nonnegative=True)
    Nd = Parameter(10.0, "1", "the higher Nd, the more ideal the derivative block",
                   positive=True)

    def structure(self, s):
        s.state("I.y", self.xi_start, description="integral part (state)")
        s.state("D.x", self.xd_start, description="state of derivative block")

    def physics(self, e):
        xi, xd = e.state("I.y"), e.state("D.x")
        u = e.input(self.u)
        xi_dot = u / self.Ti
        e.derivative(xi, xi_dot)
        xd_dot, d_y = _approx_derivative(u, xd, self.Td, ca.fmax(self.Td / self.Nd, 100 * EPS))
        e.derivative(xd, xd_dot)
        e.variable("P.y", u, description="proportional part")
        e.variable("D.y", d_y, description="derivative part")
        y = self.k * (u + xi + d_y)
        e.output(self.y, y)
        _initial_equations(e, self, {"I.y": xi_dot, "D.x": xd_dot},
                           {"y = y_start": y - self.y_start}, steady_output=("D.x",))


class SimpleController(str, Enum):
    """Modelica.Blocks.Types.SimpleController: the parts of LimPID."""
    P = "P"
    PI = "PI"
    PD = "PD"
    PID = "PID"


class LimPID(BoundParameters, _StartValues, Component):
    """P, PI, PD or PID controller with limited output, anti-windup, set-point weighting and
    optional feed-forward (MSL Continuous.LimPID), the equations of its internal blocks::

        controlError = u_s − u_m
        P.y  = wp·u_s − u_m
        D:   der(D.x) = (wd·u_s − u_m − D.x)/Tf,  D.y = (Td/Tf)·(wd·u_s − u_m − D.x),
             Tf = max(Td/Nd, 1e-14)   (D.y = 0, der(D.x) = 0 when Td < eps)
        I:   der(I.y) = (u_s − u_m + (y − limiter.u)/(k·Ni))/Ti
        limiter.u = k·(P.y + I.y + D.y) + kFF·u_ff
        y = limiter.u clamped to [yMin, yMax]

    Inputs ``u_s`` (set point), ``u_m`` (measurement), ``u_ff`` (feed-forward, with
    ``withFeedForward=True``); output ``y``. Options: ``controllerType`` (P, PI, PD, PID:
    without I or D part the state and its terms are absent), ``withFeedForward``,
    ``initType``, ``strict``, ``homotopyType``.

    Parameters: k [1] (non-zero), Ti [s] (> 0), Td [s] (≥ 0), yMax (required, as in MSL),
    yMin (default −yMax, MSL's binding: follows yMax unless given at construction), wp, wd
    [1] (set-point weights), Ni [1] (Ni·Ti is the anti-windup time constant), Nd [1] (the
    higher, the more ideal the derivative), kFF [1], y_smooth (smooth form only). Start
    values (constructor arguments): xi_start (I.y), xd_start (D.x), y_start. Recorded:
    controlError, P.y, D.y, limiter.u.

    Initialization (``initType``, MSL's default InitialState): NoInit and InitialState
    start the states at xi_start, xd_start; SteadyState: der(I.y) = der(D.x) = 0 (of the
    parts present); InitialOutput: k·(P.y + I.y + D.y) = y_start (the output before the
    feed-forward and the limiter, MSL's gainPID.y; y_start within [yMin, yMax]) and
    der(D.x) = 0.

    The output limiter is MSL's Limiter (``limiter``): with strict=False (MSL's default)
    state events where limiter.u reaches yMax or yMin (mode ``limiter.region``, indicators
    ``limiter.upper``, ``limiter.lower``), with strict=True none; in smooth form its
    corners rounded over ``y_smooth`` (error ≤ y_smooth/2; see Limiter).

    MSL differences: homotopyType changes nothing (the initialization solves the actual
    model).
    """
    _starts = ("xi_start", "xd_start", "y_start")
    options = {"controllerType": SimpleController.PID, "withFeedForward": False,
               "initType": Init.InitialState, "strict": False,
               "homotopyType": LimiterHomotopy.Linear}
    required = ("yMax",)
    u_s = RealInput("connector of setpoint input signal")
    u_m = RealInput("connector of measurement input signal")
    y = RealOutput("connector of actuator output signal")
    u_ff = ConditionalPort(RealInput("optional connector of feed-forward input signal"),
                           "withFeedForward")
    k = Parameter(1.0, "1", "gain of controller, must be non-zero", nonzero=True)
    Ti = Parameter(0.5, "s", "time constant of Integrator block", positive=True)
    Td = Parameter(0.1, "s", "time constant of Derivative block", nonnegative=True)
    yMax = Parameter(1.0, "", "upper limit of output")
    wp = Parameter(1.0, "1", "set-point weight for Proportional block (0..1)",
                   nonnegative=True)
    wd = Parameter(0.0, "1", "set-point weight for Derivative block (0..1)", nonnegative=True)
    Ni = Parameter(0.9, "1", "Ni*Ti is time constant of anti-windup compensation",
                   positive=True)
    Nd = Parameter(10.0, "1", "the higher Nd, the more ideal the derivative block",
                   positive=True)
    kFF = Parameter(1.0, "1", "gain of feed-forward input")
    y_smooth = Parameter(1e-3, "", "smooth form only: width over which the corners of the "
                                   "output limiter are rounded (error <= y_smooth/2)",
                         positive=True)

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        _check_limits(self, "yMax", "yMin")
        if self.initType is Init.InitialOutput and not self.yMin <= self.y_start <= self.yMax:
            raise ParameterError(f"{who(self)}: start value y_start (= {self.y_start}) is "
                                 f"outside of the limits yMin (= {self.yMin}) and yMax "
                                 f"(= {self.yMax}) (initType=InitialOutput)")

    @property
    def yMin(self):
        """Lower limit of output: −yMax (MSL's binding)."""
        return -self.yMax

    @property
    def _with_I(self) -> bool:
        return self.controllerType in (SimpleController.PI, SimpleController.PID)

    @property
    def _with_D(self) -> bool:
        return self.controllerType in (SimpleController.PD, SimpleController.PID)

    def structure(self, s):
        _limiter_region(s, not self.strict, "limiter.")
        if self._with_I:
            s.state("I.y", self.xi_start, description="integral part (state)")
        if self._with_D:
            s.state("D.x", self.xd_start, description="state of derivative block")

    def physics(self, e):
        u_s, u_m = e.input(self.u_s), e.input(self.u_m)
        p_y = self.wp * u_s - u_m
        d_y = 0
        if self._with_D:
            xd = e.state("D.x")
            xd_dot, d_y = _approx_derivative(self.wd * u_s - u_m, xd, self.Td,
                                             ca.fmax(self.Td / self.Nd, 1e-14))
            e.derivative(xd, xd_dot)
        i_y = e.state("I.y") if self._with_I else 0
        u_ff = e.input(self.u_ff) if self.withFeedForward else 0
        gain_y = self.k * (p_y + i_y + d_y)
        lim_u = gain_y + self.kFF * u_ff
        y = _limited(e, lim_u, self.yMin, self.yMax, self.y_smooth, not self.strict,
                     "limiter.")
        derivatives = {"D.x": xd_dot} if self._with_D else {}
        if self._with_I:
            track = (y - lim_u) / (self.k * self.Ni)
            derivatives["I.y"] = (u_s - u_m + track) / self.Ti
            e.derivative(i_y, derivatives["I.y"])
        _initial_equations(e, self, derivatives, {"k*(P.y + I.y + D.y) = y_start":
                                                  gain_y - self.y_start},
                           steady_output=("D.x",) if self._with_D else ())
        e.variable("controlError", u_s - u_m, description="control error (set point - "
                                                           "measurement)")
        e.variable("P.y", p_y, description="proportional part")
        e.variable("D.y", d_y, description="derivative part")
        e.variable("limiter.u", lim_u, description="controller output before the limiter")
        e.output(self.y, y)


bound_twin(LimPID, "yMin", Parameter(-1.0, "", "lower limit of output"))


class _Coefficients(_Sized):
    """The coefficients of a transfer function, b (numerator) and a (denominator), highest
    power first, given at construction: their sizes nb <= na fix the block's class, their
    values are the parameters ``b[1]`` .. ``b[nb]``, ``a[1]`` .. ``a[na]`` (changeable at
    simulation time); a[1] != 0."""

    def __new__(cls, name=None, *, b=(1.0,), a=(1.0,), **params):
        nb, na = (_matrix(v, f"{cls.__name__}: {n}", 1).size for v, n in ((b, "b"), (a, "a")))
        if nb > na:
            raise ParameterError(f"{cls.__name__}: transfer function is not proper: b has "
                                 f"{nb} coefficients, a {na} (nb <= na required: give b "
                                 f"at most as many coefficients as a)")
        return super().__new__(cls._variant(nb, na))

    @staticmethod
    def _declare(nb: int, na: int) -> dict:
        return {"b": Parameter((1.0,) * nb, "", "numerator coefficients of transfer "
                                                "function (e.g., 2*s+3 is specified as {2,3})"),
                "a": Parameter((1.0,) * na, "", "denominator coefficients of transfer "
                                                "function (e.g., 5*s+6 is specified as {5,6})")}

    def __init__(self, name: str | None = None, *, b=(1.0,), a=(1.0,), **params):
        what = type(self).__name__
        coeffs = {n: tuple(_matrix(v, f"{what}: {n}", 1).ravel()) for n, v in (("b", b),
                                                                             ("a", a))}
        super().__init__(name, **coeffs, **params)
        if coeffs["a"][0] == 0:
            raise ParameterError(f"{who(self)}: a[1] must be non-zero (the leading "
                                 f"denominator coefficient), got a = {[float(v) for v in coeffs['a']]}")

    @property
    def nx(self) -> int:
        """Number of states, na − 1."""
        return self._key[1] - 1

    def _start_size(self, name: str) -> int | None:
        return self.nx if name == "x_start" else None


class TransferFunction(_Coefficients, _StartValues, SISO):
    """Linear transfer function (MSL Continuous.TransferFunction)::

                b[1]·s^(nb−1) + b[2]·s^(nb−2) + ... + b[nb]
        y(s) = --------------------------------------------- · u(s)
                a[1]·s^(na−1) + a[2]·s^(na−2) + ... + a[na]

    ``b`` and ``a`` (given at construction; their sizes nb ≤ na fix the block, their
    values are the parameters ``b[1]`` .. ``b[nb]``, ``a[1]`` .. ``a[na]``, changeable at
    simulation time). The states are MSL's: the controller canonical form scaled by
    a_end = a[na] if a[na] > 100·eps·|a|, else 1 (MSL's test, without abs),
    ``x_scaled[1]`` .. ``x_scaled[nx]``
    (nx = na − 1)::

        der(x_scaled[1])    = (−a[2:na]·x_scaled + a_end·u)/a[1]
        der(x_scaled[2:nx]) = x_scaled[1:nx−1]
        y = ((bb[2:na] − d·a[2:na])·x_scaled)/a_end + d·u,  x = x_scaled/a_end

    with bb = b padded with leading zeros to na, d = bb[1]/a[1]; ``x[i]`` are recorded
    (nx = 0: y = d·u). Initialization (``initType``, MSL's default NoInit): NoInit and
    InitialState start at x = x_start; SteadyState: der(x_scaled) = 0; InitialOutput:
    y = y_start and der(x_scaled[2:nx]) = 0. Start values (constructor arguments):
    ``x_start`` (nx values), ``y_start``.
    """
    _starts = ("x_start", "y_start")
    options = {"initType": Init.NoInit}
    _classes: dict = {}

    def __init__(self, name: str | None = None, *, b=(1.0,), a=(1.0,), **params):
        super().__init__(name, b=b, a=a, **params)
        if self.initType is Init.InitialOutput and self.nx == 0:
            raise ParameterError(f"{who(self)}: initType=InitialOutput needs a state (a has "
                                 f"one coefficient: y = d*u, with no initial value to give)")

    def _a_end(self):
        """a[na], or 1 when it is ≈ 0 (MSL's scaling of the states)."""
        a = self.a
        return ca.if_else(a[-1] > 100 * EPS * ca.norm_2(a), a[-1], 1.0)

    def structure(self, s):
        a_end = self._a_end()
        for i in range(self.nx):
            s.state(f"x_scaled[{i + 1}]", self.x_start[i] * a_end,
                    description="scaled state of the controller canonical form")

    def physics(self, e):
        u, a, nb, na = e.input(self.u), self.a, *self._key
        bb = [0] * (na - nb) + [self.b[i] for i in range(nb)]
        d = bb[0] / a[0]
        if self.nx == 0:
            e.output(self.y, d * u)
            return
        a_end = self._a_end()
        xs = [e.state(f"x_scaled[{i + 1}]") for i in range(self.nx)]
        der = [(-sum(a[i + 1] * x for i, x in enumerate(xs)) + a_end * u) / a[0]] + xs[:-1]
        for x, dx in zip(xs, der):
            e.derivative(x, dx)
        y = sum((bb[i + 1] - d * a[i + 1]) * x for i, x in enumerate(xs)) / a_end + d * u
        e.output(self.y, y)
        for i, x in enumerate(xs, start=1):
            e.variable(f"x[{i}]", x / a_end,
                       description="state of transfer function from controller canonical form")
        names = [f"x_scaled[{i}]" for i in range(1, self.nx + 1)]
        _initial_equations(e, self, dict(zip(names, der)), {"y = y_start": y - self.y_start},
                           steady_output=names[1:])


class _Matrices(_Sized):
    """The matrices A (nx × nx), B (nx × nin), C (nout × nx), D (nout × nin, default zeros)
    of a state space system, given at construction (MSL's defaults: A = [1, 0; 0, 1],
    B = [1; 1], C = [1, 1]): their shapes fix the block's class, their values are the
    parameters ``A[1]`` .. ``A[nx·nx]`` (row by row, as a table's values), likewise B, C, D;
    inputs ``u[1]`` .. ``u[nin]``, outputs ``y[1]`` .. ``y[nout]``."""
    _defaults = {"A": [[1.0, 0.0], [0.0, 1.0]], "B": [[1.0], [1.0]], "C": [[1.0, 1.0]]}

    def __new__(cls, name=None, *, A=None, B=None, C=None, D=None, **params):
        A, _, _, D = cls._matrices(A, B, C, D)
        return super().__new__(cls._variant(A.shape[0], *D.shape))

    @classmethod
    def _matrices(cls, A, B, C, D) -> tuple:
        """A, B, C, D as arrays of consistent shapes (MSL's defaults for those not given)."""
        d, what = _Matrices._defaults, cls.__name__
        A = _matrix(d["A"] if A is None else A, f"{what}: A")
        nx = A.shape[0]
        if A.shape != (nx, nx) or nx == 0:
            raise ParameterError(f"{what}: A must be square with at least one row, got "
                                 f"shape {A.shape}")
        B = _matrix(d["B"] if B is None else B, f"{what}: B", nx)
        C = _matrix(d["C"] if C is None else C, f"{what}: C", None, nx)
        D = _matrix(np.zeros((C.shape[0], B.shape[1])) if D is None else D, f"{what}: D",
                    C.shape[0], B.shape[1])
        return A, B, C, D

    @staticmethod
    def _declare(nx: int, nout: int, nin: int) -> dict:
        def matrix(rows, cols, what):
            return Parameter((0.0,) * (rows * cols), "", f"matrix {what} of state space model "
                                                         f"({rows} x {cols}, row by row)")
        return {"A": matrix(nx, nx, "A"), "B": matrix(nx, nin, "B"),
                "C": matrix(nout, nx, "C"), "D": matrix(nout, nin, "D"),
                "u": VectorPort(RealInput, nin, "connector of Real input signals"),
                "y": VectorPort(RealOutput, nout, "connector of Real output signals")}

    def __init__(self, name: str | None = None, *, A=None, B=None, C=None, D=None, **params):
        matrices = self._matrices(A, B, C, D)
        super().__init__(name, **dict(zip("ABCD", (tuple(m.ravel()) for m in matrices))),
                         **params)

    @property
    def nx(self) -> int:
        """Number of states."""
        return self._key[0]

    @property
    def nin(self) -> int:
        """Number of inputs."""
        return self._key[2]

    @property
    def nout(self) -> int:
        """Number of outputs."""
        return self._key[1]

    def _start_size(self, name: str) -> int | None:
        return {"x_start": self.nx, "y_start": self.nout}[name]

    def _symbolic(self, name: str, rows: int, cols: int) -> ca.SX:
        return ca.reshape(getattr(self, name), cols, rows).T

    def _system(self) -> tuple:
        """The symbolic A, B, C, D (of the parameters)."""
        nx, nin, nout = self.nx, self.nin, self.nout
        return (self._symbolic("A", nx, nx), self._symbolic("B", nx, nin),
                self._symbolic("C", nout, nx), self._symbolic("D", nout, nin))


class StateSpace(_Matrices, _StartValues, Component):
    """Linear state space system (MSL Continuous.StateSpace), MIMO::

        der(x) = A·x + B·u
            y  = C·x + D·u

    ``A`` (nx × nx), ``B`` (nx × nin), ``C`` (nout × nx), ``D`` (nout × nin, default
    zeros), given at construction (MSL's defaults: A = [1, 0; 0, 1], B = [1; 1],
    C = [1, 1]); their shapes fix the block, their values are the parameters ``A[1]`` ..
    ``A[nx·nx]`` (row by row, as a table's values; ``params={"<name>.A": matrix}`` changes
    them at simulation time), likewise B, C, D. Inputs ``u[1]`` .. ``u[nin]``, outputs
    ``y[1]`` .. ``y[nout]``, states ``x[1]`` .. ``x[nx]``.

    Initialization (``initType``, MSL's default NoInit): NoInit and InitialState start at
    x = x_start; SteadyState: der(x) = 0; InitialOutput: y = y_start with the remaining
    states in steady state as far as possible, MSL's
    x = equalityLeastSquares(A, −B·u, C, y_start − D·u), written as its optimality
    conditions C·x = y_start − D·u, P·Aᵀ·(A·x + B·u) = 0 with P = I − Cᵀ(C·Cᵀ)⁻¹C (C of
    full row rank). Start values (constructor arguments): ``x_start`` (nx values),
    ``y_start`` (nout values).
    """
    _starts = ("x_start", "y_start")
    options = {"initType": Init.NoInit}
    _classes: dict = {}

    def __init__(self, name: str | None = None, *, A=None, B=None, C=None, D=None, **params):
        super().__init__(name, A=A, B=B, C=C, D=D, **params)
        C = self._matrices(A, B, C, D)[2]
        if self.initType is Init.InitialOutput and np.linalg.matrix_rank(C) < C.shape[0]:
            raise ParameterError(f"{who(self)}: initType=InitialOutput needs C of full row "
                                 f"rank ({C.shape[0]} independent outputs to start at "
                                 f"y_start), got rank {np.linalg.matrix_rank(C)}")

    def structure(self, s):
        for i in range(self.nx):
            s.state(f"x[{i + 1}]", self.x_start[i], description="state vector")

    def physics(self, e):
        nx, nout = self.nx, self.nout
        A, B, C, D = self._system()
        states = [e.state(f"x[{i + 1}]") for i in range(nx)]
        x, u = ca.vertcat(*states), ca.vertcat(*(e.input(p) for p in self.u))
        xdot, y = A @ x + B @ u, C @ x + D @ u
        for i, state in enumerate(states):
            e.derivative(state, xdot[i])
        for i, port in enumerate(self.y):
            e.output(port, y[i])
        output = {f"y[{i + 1}] = y_start[{i + 1}]": y[i] - self.y_start[i]
                  for i in range(nout)}
        if self.initType is Init.InitialOutput:
            rest = (ca.SX.eye(nx) - C.T @ ca.solve(C @ C.T, C)) @ A.T @ xdot
            output.update({f"der(x) least squares, row {i + 1}": rest[i] for i in range(nx)})
        _initial_equations(e, self, {f"x[{i + 1}]": xdot[i] for i in range(nx)}, output)


def _smoothstep(x):
    """0 for x ≤ 0, 1 for x ≥ 1, x²·(3 − 2x) between: a step with continuous slope."""
    return ca.if_else(x <= 0, 0, ca.if_else(x >= 1, 1, x * x * (3 - 2 * x)))


class LimIntegrator(BoundParameters, _StartValues, SISO):
    """Integrator with limited output (MSL Continuous.LimIntegrator): der(y) = k·u, halted
    at the limits: der(y) = 0 if y > outMax and k·u > 0 or y < outMin and k·u < 0.

    Parameters: k, outMax (required, as in MSL), outMin (default −outMax, MSL's binding: it
    follows outMax, also at simulation time, unless given at construction, which makes it
    a parameter of its own); y_smooth (smooth form only). Options ``initType`` (MSL's
    default InitialState: y starts at y_start; InitialOutput: y = y_start held;
    SteadyState: der(y) = 0), ``limitsAtInit`` (False: the SteadyState equation is
    k·u = 0, the limits ignored), ``strict`` (False: state events; True: none, MSL's
    noEvent). Start value (constructor argument): ``y_start``.

    With events (strict=False) the relations y > outMax, y < outMin, k·u > 0 are discrete
    as in a Modelica tool: the indicators ``upper`` (y − outMax), ``lower`` (y − outMin)
    and ``input`` (k·u) locate where they change, and the mode ``region`` (1: halted at
    outMax, −1: halted at outMin, 0: integrating) is set from them at every event. In
    smooth form (``compile(model, smooth=True)``) der(y) = k·u − s(1 + (y − outMax)/y_smooth)
    ·max(k·u, 0) − s(1 + (outMin − y)/y_smooth)·min(k·u, 0), s the smoothstep (0 → 1 with
    continuous slope): the integration slows within y_smooth of a limit and never passes it.
    With strict=True nothing tells the integrator where k·u changes sign while y rests at
    a limit (der(y) = 0 exactly, its steps grow): give ``simulate(max_step=...)`` shorter
    than the input's changes, or keep the events.

    MSL differences: no reset/set ports (use_reset, use_set); limitsAtInit=False does not
    check that y is within the limits after the initialization.
    """
    _starts = ("y_start",)
    options = {"initType": Init.InitialState, "limitsAtInit": True, "strict": False}
    required = ("outMax",)
    k = Parameter(1.0, "1", "integrator gain")
    outMax = Parameter(1.0, "", "upper limit of output")
    y_smooth = Parameter(1e-3, "", "smooth form only: width below each limit over which the "
                                   "integration is halted gradually", positive=True)

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        _check_limits(self, "outMax", "outMin")

    @property
    def outMin(self):
        """Lower limit of output: −outMax (MSL's binding)."""
        return -self.outMax

    def structure(self, s):
        s.state("y", self.y_start, description="integrator output (state)")
        if not (self.strict or s.smooth):
            s.mode("region", 0, values=(-1, 0, 1),
                   description="1 if halted at outMax, -1 if halted at outMin, 0 integrating")

    def physics(self, e):
        y, ku = e.state("y"), self.k * e.input(self.u)
        upper, lower = self.outMax, self.outMin
        if e.smooth:
            width = self.y_smooth
            dy = (ku - _smoothstep(1 + (y - upper) / width) * ca.fmax(ku, 0)
                  - _smoothstep(1 + (lower - y) / width) * ca.fmin(ku, 0))
        else:
            held = ca.if_else(ca.logic_and(y > upper, ku > 0), 1,
                              ca.if_else(ca.logic_and(y < lower, ku < 0), -1, 0))
            if self.strict:
                dy = ca.if_else(held == 0, ku, 0)
            else:
                region = e.mode("region")
                e.mode_update(region, held)
                e.indicator("upper", y - upper, "", "y - outMax (the relation y > outMax)")
                e.indicator("lower", y - lower, "", "y - outMin (the relation y < outMin)")
                e.indicator("input", ku, "", "k*u (the relations k*u > 0, k*u < 0)")
                dy = ca.if_else(region == 0, ku, 0)
        e.derivative(y, dy)
        e.output(self.y, y)
        _initial_equations(e, self, {"y": dy if self.limitsAtInit else ku},
                           {"y = y_start": y - self.y_start})


bound_twin(LimIntegrator, "outMin", Parameter(-1.0, "", "lower limit of output"))


class Der(SISO):
    """Exact derivative of the input, y = der(u) (MSL Continuous.Der): u's expression is
    differentiated symbolically, as a Modelica tool differentiates the equations that give
    u. The input must therefore be differentiable: a function of states, time and
    parameters (a filter's output, a source; a step's jump contributes nothing), up to
    three Der blocks in a chain of the same signal; a model input or an algebraic variable
    has no known derivative (a StructureError when compiled; filter it, e.g. with
    Derivative or Filter, instead)."""

    def physics(self, e):
        e.output(self.y, e.der(e.input(self.u)))


def _order(block: str, name: str, value, largest: int | None = None) -> int:
    """A filter's order given at construction, as int (a ParameterError otherwise)."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1 \
            or (largest is not None and value > largest):
        within = f"between 1 and {largest}" if largest else ">= 1"
        raise ParameterError(f"{block}: {name} (order of filter) must be an integer {within}, "
                             f"got {value!r}")
    return int(value)


class _Ordered(_StartValues):
    """A filter whose order (constructor argument ``n``) fixes its number of states."""

    def __init__(self, name: str | None = None, *, n: int = 2, **params):
        self.__dict__["n"] = _order(type(self).__name__ + (f" '{name}'" if name else ""),
                                    "n", n)
        super().__init__(name, **params)


class CriticalDamping(_Ordered, SISO):
    """Filter of order ``n`` with critical damping (MSL Continuous.CriticalDamping): n first
    order sections in series, y = 1/(s/w + 1)^n·u with w = 2π·f/alpha, alpha =
    sqrt(2^(1/n) − 1) if ``normalized`` (the amplitude at f is 1/sqrt(2)), else 1::

        der(x[1]) = (u − x[1])·w,  der(x[i]) = (x[i−1] − x[i])·w,  y = x[n]

    ``n`` (constructor argument, default 2) is the order; f [Hz] (required, as in MSL).
    Initialization (``initType``, MSL's default NoInit): NoInit and InitialState start at
    x = x_start; SteadyState: der(x) = 0 (y = u); InitialOutput: y = y_start and
    der(x[1:n−1]) = 0. Start values (constructor arguments): ``x_start`` (n values),
    ``y_start``.
    """
    _starts = ("x_start", "y_start")
    options = {"normalized": True, "initType": Init.NoInit}
    required = ("f",)
    f = Parameter(1.0, "Hz", "cut-off frequency", positive=True)

    def _start_size(self, name: str) -> int | None:
        return self.n if name == "x_start" else None

    def structure(self, s):
        for i in range(self.n):
            s.state(f"x[{i + 1}]", self.x_start[i], description="filter states")

    def physics(self, e):
        n = self.n
        alpha = math.sqrt(2 ** (1 / n) - 1) if self.normalized else 1.0
        w = 2 * math.pi * self.f / alpha
        x = [e.state(f"x[{i + 1}]") for i in range(n)]
        der = [(before - xi) * w for before, xi in zip([e.input(self.u)] + x[:-1], x)]
        for xi, dx in zip(x, der):
            e.derivative(xi, dx)
        e.output(self.y, x[-1])
        names = [f"x[{i + 1}]" for i in range(n)]
        _initial_equations(e, self, dict(zip(names, der)), {"y = y_start": x[-1] - self.y_start},
                           steady_output=names[:-1])


class LowpassButterworth(_Ordered, SISO):
    """Low pass Butterworth filter of order ``n`` (MSL Continuous.LowpassButterworth): the
    amplitude at the cut-off frequency f is 1/sqrt(2). MSL's realization: m = n div 2
    second order sections with w = 2π·f, D[i] = −cos(π/2 + π/n·(i − 1/2)),
    z[1] = u, z[i+1] = x1[i]::

        der(x1[i]) = x2[i],  der(x2[i]) = w²·z[i] − 2·D[i]·w·x2[i] − w²·x1[i]

    and for odd n a real pole der(xr) = (z[m+1] − xr)·w, y = xr (even n: y = z[m+1]).

    ``n`` (constructor argument, default 2) is the order; f [Hz] (required, as in MSL).
    Initialization (``initType``, MSL's default NoInit): NoInit and InitialState start at
    x1_start, x2_start (m values each), xr_start; SteadyState: all derivatives 0 (y = u);
    InitialOutput: y = y_start, der(x1) = 0 and der(x2[1:m−1]) = 0 (even n), der(x2) = 0
    (odd n: what MSL means by its second der(x1) = 0). For even n there is no state xr
    (MSL's dummy xr = 0).
    """
    _starts = ("x1_start", "x2_start", "xr_start", "y_start")
    options = {"initType": Init.NoInit}
    required = ("f",)
    f = Parameter(1.0, "Hz", "cut-off frequency", positive=True)

    def _start_size(self, name: str) -> int | None:
        return self.n // 2 if name in ("x1_start", "x2_start") else None

    def structure(self, s):
        for i in range(self.n // 2):
            s.state(f"x1[{i + 1}]", self.x1_start[i],
                    description="states 1 of second order filters (der(x1) = x2)")
            s.state(f"x2[{i + 1}]", self.x2_start[i],
                    description="states 2 of second order filters")
        if self.n % 2:
            s.state("xr", self.xr_start, description="state of real pole")

    def physics(self, e):
        n, m = self.n, self.n // 2
        w = 2 * math.pi * self.f
        z, der = e.input(self.u), {}
        for i in range(1, m + 1):
            D = -math.cos(math.pi / 2 + math.pi / n * (i - 0.5))
            x1, x2 = e.state(f"x1[{i}]"), e.state(f"x2[{i}]")
            der[f"x1[{i}]"], der[f"x2[{i}]"] = x2, w * w * (z - x1) - 2 * D * w * x2
            e.derivative(x1, x2)
            e.derivative(x2, der[f"x2[{i}]"])
            z = x1
        if n % 2:
            xr = e.state("xr")
            der["xr"] = (z - xr) * w
            e.derivative(xr, der["xr"])
            z = xr
        e.output(self.y, z)
        steady = [f"x1[{i}]" for i in range(1, m + 1)] + \
            [f"x2[{i}]" for i in range(1, (m if n % 2 else m - 1) + 1)]
        _initial_equations(e, self, der, {"y = y_start": z - self.y_start},
                           steady_output=tuple(steady))


class Filter(_StartValues, SISO):
    """Continuous low pass, high pass, band pass or band stop filter of type CriticalDamping,
    Bessel, Butterworth or ChebyshevI (MSL Continuous.Filter).

    Options: ``analogFilter`` (AnalogFilter, default CriticalDamping), ``filterType``
    (FilterType, default LowPass), ``normalized`` (True: the amplitude at f_cut is -3 dB =
    10^(-3/20) for CriticalDamping, Bessel, ChebyshevI, and 1/sqrt(2) for Butterworth, as
    in MSL), ``init`` (Init, MSL's default SteadyState). Design data, given at construction
    (the coefficients are computed from them then, as MSL computes them at initialization;
    build a new block to change them): ``order`` (default 2), ``f_cut`` [Hz] (required),
    ``A_ripple`` [dB] (ChebyshevI's pass band ripple, default 0.5, > 0), ``f_min`` [Hz]
    (band filters: the band is f_min .. f_cut, both at -3 dB). Parameters: gain (amplitude
    at zero frequency), u_nominal (scale of the states).

    MSL's realization (acausal.components.filter_design computes its coefficients exactly
    as MSL's Internal.Filter functions): real poles r, der(x) = r·(x − uu); conjugate
    complex pairs a ± j·b, der(x1) = a·x1 − b·x2 + ku·uu, der(x2) = b·x1 + a·x2, in
    series from uu = u/u_nominal; each section's output feeds the next: low pass x (x2),
    high pass uu − x (k1·x1 + k2·x2 + uu), band pass k1·x1 + k2·x2, band stop
    k1·x1 + k2·x2 + uu; y = gain·u_nominal·(the last output). States ``x[1]`` ..
    ``x[nx]`` (nx = order, band filters 2·order); MSL's output connectors x are not
    declared (read the states by name).

    Initialization (``init``): SteadyState der(x) = 0; NoInit and InitialState start at
    x = x_start (constructor argument, nx values); InitialOutput: y = y_start and
    der(x[1:nx−1]) = 0.

    Band filters as MSL 4.1 computes them: a band pass's sections have the numerator
    cn·s, cn = w_band·w_cut, without the base filter's c0 (cr), so its gain in the band is
    1 only where those are 1 (Butterworth); a band stop's two sections of a complex pair
    have the zeros s² + c0 of their own c0 (w_cut²/alpha², w_cut²·alpha²), not the double
    zero at w_cut of the exact transformation (exact for real poles: order 1). A band
    transformation that gives real poles (a wide band over CriticalDamping's real poles) is
    refused, as MSL's assert does.
    """
    _starts = ("x_start", "y_start")
    options = {"analogFilter": AnalogFilter.CriticalDamping, "filterType": FilterType.LowPass,
               "normalized": True, "init": Init.SteadyState}
    gain = Parameter(1.0, "1", "gain (= amplitude of frequency response at zero frequency)")
    u_nominal = Parameter(1.0, "", "nominal value of input (used for scaling the states)",
                          positive=True)

    def __init__(self, name: str | None = None, *, order: int = 2, f_cut: float | None = None,
                 A_ripple: float = 0.5, f_min: float = 0.0, **params):
        kind = "Filter" + (f" '{name}'" if name else "")
        given = params.get("filterType", FilterType.LowPass)
        band = given in (FilterType.BandPass, FilterType.BandStop, "BandPass", "BandStop")
        self.__dict__["order"] = _order(kind, "order", order)
        self.__dict__["nx"] = 2 * order if band else order
        super().__init__(name, **params)
        if f_cut is None:
            raise ParameterError(f"{kind}: f_cut (cut-off frequency [Hz]) has no default (as "
                                 f"in MSL); give it: Filter(f_cut=...)")
        f_cut, A_ripple, f_min = (_start(v, f"{kind}: {n}") for v, n in (
            (f_cut, "f_cut"), (A_ripple, "A_ripple"), (f_min, "f_min")))
        if f_cut <= 0:
            raise ParameterError(f"{kind}: f_cut (cut-off frequency) must be > 0 [Hz], got "
                                 f"{f_cut}")
        if A_ripple <= 0:
            raise ParameterError(f"{kind}: A_ripple (pass band ripple of ChebyshevI) must be "
                                 f"> 0 [dB] (MSL asserts it for every analogFilter), got "
                                 f"{A_ripple}")
        if band and not 0 < f_min < f_cut:
            raise ParameterError(f"{kind}: a {self.filterType.value} filter passes/stops the "
                                 f"band f_min .. f_cut: give 0 < f_min < f_cut [Hz], got "
                                 f"f_min = {f_min}, f_cut = {f_cut}")
        if self.analogFilter is AnalogFilter.Bessel:
            _order(kind, "order", order, BESSEL_MAX_ORDER)
        self.__dict__.update(f_cut=f_cut, A_ripple=A_ripple, f_min=f_min)
        base = base_filter(self.analogFilter, self.order, self.normalized, A_ripple)
        try:
            roots = filter_roots(base, self.filterType, f_cut, f_min)
        except ValueError as err:
            raise ParameterError(f"{kind}: {err} for a {self.filterType.value} filter (f_min "
                                 f"= {f_min}, f_cut = {f_cut})") from None
        self.__dict__["roots"] = roots

    def _start_size(self, name: str) -> int | None:
        return self.nx if name == "x_start" else None

    @property
    def initType(self) -> Init:
        """The initialization (the option ``init``)."""
        return self.init

    def structure(self, s):
        for i in range(self.nx):
            s.state(f"x[{i + 1}]", self.x_start[i], description="filter states")

    def physics(self, e):
        r, a, b, ku, k1, k2 = self.roots
        kind = self.filterType
        x = [e.state(f"x[{i + 1}]") for i in range(self.nx)]
        uu, der = e.input(self.u) / self.u_nominal, []
        for ri, xi in zip(r, x):
            der.append(ri * (xi - uu))
            uu = xi if kind is FilterType.LowPass else uu - xi
        for i in range(len(a)):
            x1, x2 = x[len(r) + 2 * i], x[len(r) + 2 * i + 1]
            der += [a[i] * x1 - b[i] * x2 + ku[i] * uu, b[i] * x1 + a[i] * x2]
            if kind is FilterType.LowPass:
                uu = x2
            elif kind is FilterType.BandPass:
                uu = k1[i] * x1 + k2[i] * x2
            else:
                uu = k1[i] * x1 + k2[i] * x2 + uu
        for xi, dx in zip(x, der):
            e.derivative(xi, dx)
        y = self.gain * self.u_nominal * uu
        e.output(self.y, y)
        names = [f"x[{i + 1}]" for i in range(self.nx)]
        _initial_equations(e, self, dict(zip(names, der)), {"y = y_start": y - self.y_start},
                           steady_output=tuple(names[:-1]))
