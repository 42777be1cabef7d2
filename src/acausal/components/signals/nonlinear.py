"""Nonlinear blocks (Modelica.Blocks.Nonlinear): limiters, dead zone, slew rate limiter,
Padé delay."""
from __future__ import annotations

from enum import Enum

import casadi as ca
import numpy as np

from ...core import Parameter, RealInput
from ...core.component import BoundParameters, bound_twin, who
from ...errors import ParameterError
from .interfaces import Init, SISO, _size, _Sized, _StartValues


class LimiterHomotopy(str, Enum):
    """Modelica.Blocks.Types.LimiterHomotopy (accepted; it changes nothing here)."""
    NoHomotopy = "NoHomotopy"
    Linear = "Linear"
    UpperLimit = "UpperLimit"
    LowerLimit = "LowerLimit"


class VariableLimiterHomotopy(str, Enum):
    """Modelica.Blocks.Types.VariableLimiterHomotopy (accepted; it changes nothing here)."""
    NoHomotopy = "NoHomotopy"
    Linear = "Linear"
    Fixed = "Fixed"


def _limit(u, lower, upper):
    """MSL's ``if u > upper then upper else if u < lower then lower else u``."""
    return ca.if_else(u > upper, upper, ca.if_else(u < lower, lower, u))


def _check_limits(block, upper: str, lower: str) -> None:
    """A ParameterError when the values at construction have lower > upper (MSL's assert)."""
    hi, lo = getattr(block, upper), getattr(block, lower)
    if hi < lo:
        raise ParameterError(f"{who(block)}: limits must be consistent, but {upper} (= {hi}) "
                             f"< {lower} (= {lo})")


def _smooth_max(a, b, width):
    """max(a, b) with a rounded corner: (a + b + sqrt((a − b)² + width²))/2, above max(a, b)
    by at most width/2 (at a = b), by width²/(4|a − b|) far from it."""
    return (a + b + ca.sqrt((a - b) ** 2 + width ** 2)) / 2


def _smooth_min(a, b, width):
    """min(a, b) with a rounded corner, below it by at most width/2 (see _smooth_max)."""
    return (a + b - ca.sqrt((a - b) ** 2 + width ** 2)) / 2


class _Limiting(SISO):
    """A block that limits u to [lower, upper] (``limited``), as MSL's limiters: ``if u >
    upper then upper else if u < lower then lower else u``; events and smooth form as the
    Limiter's docstring says."""
    u_smooth = Parameter(1e-3, "", "smooth form only: width over which the corners at the "
                                   "limits are rounded (error <= u_smooth/2)", positive=True)

    def structure(self, s):
        _limiter_region(s, not getattr(self, "strict", False))

    def limited(self, e, u, lower, upper):
        """u limited to [lower, upper], and the events that go with it (Limiter)."""
        return _limited(e, u, lower, upper, self.u_smooth, not getattr(self, "strict", False))


def _limiter_region(s, events: bool, prefix: str = "") -> None:
    """Declare the mode ``<prefix>region`` of a limiter with events (not in smooth form)."""
    if events and not s.smooth:
        s.mode(f"{prefix}region", 0, values=(-1, 0, 1),
               description="branch of the limiter: 1 if u > upper limit, -1 if u < lower "
                           "limit, 0 between")


def _limited(e, u, lower, upper, width, events: bool, prefix: str = ""):
    """u limited to [lower, upper] as Limiter's docstring says: in smooth form its corners
    rounded over ``width``; with ``events`` on the mode ``<prefix>region`` and the
    indicators ``<prefix>upper``, ``<prefix>lower``; else the plain expression."""
    if e.smooth:
        return _smooth_min(_smooth_max(u, lower, width), upper, width)
    if not events:
        return _limit(u, lower, upper)
    region = e.mode(f"{prefix}region")
    e.mode_update(region, ca.if_else(u > upper, 1, ca.if_else(u < lower, -1, 0)))
    e.indicator(f"{prefix}upper", ca.if_else(region == 1, u - upper, upper - u), "",
                "distance of u from the upper limit, positive while the region holds")
    e.indicator(f"{prefix}lower", ca.if_else(region == -1, lower - u, u - lower), "",
                "distance of u from the lower limit, positive while the region holds")
    return ca.if_else(region == 1, upper, ca.if_else(region == -1, lower, u))


class _SymmetricLimits(BoundParameters, _Limiting):
    """MSL's ``uMax`` (required) and ``uMin`` bound to −uMax: uMin follows uMax, also at
    simulation time, unless it is given at construction, which makes it a parameter of its
    own (``core.component.bound_twin``). Limits with uMax < uMin are refused."""
    required = ("uMax",)

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        _check_limits(self, "uMax", "uMin")

    @property
    def uMin(self):
        """The lower limit: −uMax (MSL's binding)."""
        return -self.uMax


class Limiter(_SymmetricLimits):
    """Limit the range of a signal: y = uMax if u > uMax, uMin if u < uMin, else u
    (MSL Nonlinear.Limiter).

    Parameters: uMax (required, as in MSL), uMin (default −uMax, MSL's binding: it follows
    uMax, also at simulation time, unless given at construction, which makes it a parameter
    of its own); u_smooth (smooth form only). Options ``strict`` (False: state events at
    the limits, the mode ``region``; True: none, MSL's noEvent) and ``homotopyType``
    (accepted; it changes nothing: the initialization solves the actual model).

    With events (MSL's default, strict=false): the relations are discrete, as a Modelica
    tool makes them: the mode ``region`` (1: u > upper, −1: u < lower, 0: between) says
    which branch holds between events, and the indicators ``upper`` and ``lower`` (the
    distance of u from each limit, positive while the region holds) make the simulator
    locate where u reaches a limit, so a kink is never stepped across, nor missed by an
    integrator that rests (no step limit needed). With ``strict=True`` (MSL's noEvent) the
    plain expression, no events: the integrator's step control resolves the kinks.

    Smooth form (``compile(model, smooth=True)``): the corners rounded over ``u_smooth``,
    y = smooth_min(smooth_max(u, lower), upper) with smooth_max(a, b) = (a + b +
    sqrt((a − b)² + u_smooth²))/2; its error |y − y_exact| ≤ u_smooth/2, reached at the
    limits, decaying as u_smooth²/(4·d) at a distance d from the nearer one.
    """
    options = {"strict": False, "homotopyType": LimiterHomotopy.Linear}
    uMax = Parameter(1.0, "", "upper limits of input signals")

    def physics(self, e):
        e.output(self.y, self.limited(e, e.input(self.u), self.uMin, self.uMax))


bound_twin(Limiter, "uMin", Parameter(-1.0, "", "lower limits of input signals"))


class VariableLimiter(_Limiting):
    """Limit the range of a signal with variable limits: y = limit1 if u > limit1, limit2 if
    u < limit2, else u (MSL Nonlinear.VariableLimiter). Inputs ``u``, ``limit1`` (maximum),
    ``limit2`` (minimum). Options ``strict`` (events as Limiter's) and ``homotopyType``;
    u_smooth (smooth form only). Events and smooth form: as Limiter's.

    MSL differences: ``homotopyType`` changes nothing (and its ySimplified is not
    declared); MSL's run-time assert limit1 ≥ limit2 is not checked.
    """
    options = {"strict": False, "homotopyType": VariableLimiterHomotopy.Linear}
    limit1 = RealInput("connector of Real input signal used as maximum of input u")
    limit2 = RealInput("connector of Real input signal used as minimum of input u")

    def physics(self, e):
        e.output(self.y, self.limited(e, e.input(self.u), e.input(self.limit2),
                                      e.input(self.limit1)))


class DeadZone(_SymmetricLimits):
    """Region of zero output: y = u − uMax if u > uMax, u − uMin if u < uMin, else 0
    (MSL Nonlinear.DeadZone).

    Parameters: uMax (required, as in MSL), uMin (default −uMax, MSL's binding, as for
    Limiter); u_smooth (smooth form only). y = u − (u limited to [uMin, uMax]), with the
    state events at the zone's edges (mode ``region``) and the smooth form of Limiter
    (the same error bound u_smooth/2).
    """
    uMax = Parameter(1.0, "", "upper limits of dead zones")

    def physics(self, e):
        u = e.input(self.u)
        e.output(self.y, u - self.limited(e, u, self.uMin, self.uMax))


bound_twin(DeadZone, "uMin", Parameter(-1.0, "", "lower limits of dead zones"))


class SlewRateLimiter(BoundParameters, _StartValues, _Limiting):
    """Limits the slew rate of a signal (MSL Nonlinear.SlewRateLimiter): the input
    differentiated with time constant Td [s], the rate limited to [Falling, Rising] [1/s]::

        val = (u − y)/Td
        der(y) = if val < Falling then Falling else if val > Rising then Rising else val

    Parameters: Rising [1/s] (> 0, default 1), Falling [1/s] (< 0; default −Rising, MSL's
    binding: it follows Rising, also at simulation time, unless given at construction, which
    makes it a parameter of its own), Td [s] (> 0, default 0.001); u_smooth [1/s] (smooth
    form only). Option ``strict``: events and smooth form as Limiter's (mode ``region``,
    indicators ``upper``, ``lower`` on val; ``val`` is recorded). Initialization
    (``initType``, MSL's default SteadyState): SteadyState: y = u; InitialState and
    InitialOutput: y = y_start; NoInit: y starts at y_start (constructor argument).
    """
    _starts = ("y_start",)
    options = {"initType": Init.SteadyState, "strict": False}
    Rising = Parameter(1.0, "1/s", "maximum rising slew rate [+small..+inf)", positive=True)
    Td = Parameter(0.001, "s", "derivative time constant", positive=True)
    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        if not self.Falling < 0:
            raise ParameterError(f"{who(self)}: Falling (maximum falling slew rate) must be "
                                 f"< 0, got {self.Falling}")

    @property
    def Falling(self):
        """Maximum falling slew rate [1/s]: −Rising (MSL's binding)."""
        return -self.Rising

    def structure(self, s):
        super().structure(s)
        s.state("y", self.y_start, description="output (state)")

    def physics(self, e):
        y, u = e.state("y"), e.input(self.u)
        val = (u - y) / self.Td
        e.variable("val", val, "1/s", "rate of the input differentiated with time constant Td")
        e.derivative(y, self.limited(e, val, self.Falling, self.Rising))
        e.output(self.y, y)
        if self.initType is Init.SteadyState:
            e.initial(y - u, "y = u (initType=SteadyState)")
        elif self.initType in (Init.InitialState, Init.InitialOutput):
            e.initial(y - self.y_start, f"y = y_start (initType={self.initType.value})")


bound_twin(SlewRateLimiter, "Falling",
           Parameter(-1.0, "1/s", "maximum falling slew rate (-inf..-small]"))


def pade_polynomials(T, n: int, m: int) -> tuple[list, list]:
    """The Padé approximant of exp(−T·s) of numerator order m and denominator order n
    (MSL Nonlinear.PadeDelay's padeCoefficients2): (b, a), the coefficients of the numerator
    and the denominator, highest power of s first (a[−1] = b[−1] = 1), of a number or a
    CasADi expression T [s]. Its Taylor expansion at s = 0 matches exp(−T·s) up to order
    n + m."""
    a, b = [1], [1]
    for i in range(1, n + 1):
        a.append(a[-1] * (T * ((n - i + 1) / (n + m - i + 1)) / i))
        if i <= m:
            b.append(-b[-1] * (T * ((m - i + 1) / (n + m - i + 1)) / i))
    return b[::-1], a[::-1]


def balance_abc(A: np.ndarray, B: np.ndarray, C: np.ndarray) -> np.ndarray:
    """MSL Modelica.Math.Matrices.balanceABC: the scaling (powers of 2, so no round-off)
    T = diag(scale) such that [T⁻¹·A·T, T⁻¹·B; C·T, 0] is better conditioned than
    [A, B; C, 0] (EISPACK's balance on the system matrix)."""
    As, Bs, Cs = (np.array(M, dtype=float) for M in (A, B, C))
    n = As.shape[0]
    scale, radix = np.ones(n), 2.0
    again = True
    while again:
        again = False
        for i in range(n):
            co = np.abs(As[:, i]).sum() - abs(As[i, i]) + np.abs(Cs[:, i]).sum()
            ro = np.abs(As[i, :]).sum() - abs(As[i, i]) + np.abs(Bs[i, :]).sum()
            g, f, s = ro / radix, 1.0, co + ro
            while not (co >= g or co == 0):
                f, co = f * radix, co * radix ** 2
            g = ro * radix
            while not (co < g or ro == 0):
                f, co = f / radix, co / radix ** 2
            if not (co + ro) / f >= 0.95 * s:
                scale[i] *= f
                As[i, :] /= f
                As[:, i] *= f
                Bs[i, :] /= f
                Cs[:, i] *= f
                again = True
    return scale


class PadeDelay(_Sized, SISO):
    """Padé approximation of a delay y(t) ≈ u(t − delayTime) (MSL Nonlinear.PadeDelay): the
    transfer function b(s)/a(s) of ``pade_polynomials(delayTime, n, m)``, whose Taylor
    expansion matches exp(−delayTime·s) up to order n + m, in MSL's controller canonical
    form::

        der(x[1]) = a1·x + b11·u
        der(x[i]) = s[i−1]·x[i−1],  i = 2..n
        y = c·x + d·u

    with a1 = −a[2:n+1]/a[1], b11 = 1/a[1], c = bb[2:n+1] − d·a[2:n+1], d = bb[1]/a[1]
    (bb: b padded with zeros to n + 1), s = 1; with ``balance=True`` (MSL recommends it)
    the states scaled by ``balance_abc`` (scale), a1 = a1·scale/scale[1], b11/scale[1],
    c·scale, s[i] = scale[i]/scale[i+1]. delayTime [s] (> 0) is a parameter (changeable
    at simulation time: the coefficients are expressions of it); ``n`` (≥ 1, default 1) and
    ``m`` (1 ≤ m ≤ n, default n) are constructor arguments, ``balance`` an option.
    States ``x[1]`` .. ``x[n]``. Initialization (MSL's initial equations): with balance
    der(x) = 0 (steady state); without, x[n] = u, the other states at 0.

    MSL differences: the balancing scale is computed from the delayTime given at
    construction (MSL: at initialization): a delayTime changed at simulation time keeps
    that scale (the same transfer function, other states than MSL's).
    """
    options = {"balance": False}
    delayTime = Parameter(1.0, "s", "delay time of output with respect to input signal",
                          positive=True)
    _classes: dict = {}

    def __new__(cls, name=None, *, n: int = 1, m: int | None = None, **params):
        what = cls.__name__
        n = _size(n, f"{what}: n (order of the denominator)", 1)
        m = n if m is None else _size(m, f"{what}: m (order of the numerator)", 1)
        if m > n:
            raise ParameterError(f"{what}: m (order of the numerator, {m}) must be <= n (order "
                                 f"of the denominator, {n}); usually m = n or m = n - 1")
        return super().__new__(cls._variant(n, m))

    @staticmethod
    def _declare(n: int, m: int) -> dict:
        return {}

    def __init__(self, name: str | None = None, *, n: int = 1, m: int | None = None,
                 **params):
        super().__init__(name, **params)
        n = self.n
        scale = np.ones(n)
        if self.balance:
            a1, b11, c, _, _ = self.coefficients(self.delayTime, np.ones(n))
            A = np.diag(np.ones(n - 1), -1)
            A[0, :] = a1
            B = np.zeros((n, 1))
            B[0, 0] = b11
            scale = balance_abc(A, B, np.reshape(c, (1, n)))
        self.__dict__["scale"] = tuple(scale)

    @property
    def n(self) -> int:
        """Order of the denominator, the number of states."""
        return self._key[0]

    @property
    def m(self) -> int:
        """Order of the numerator."""
        return self._key[1]

    def coefficients(self, T, scale) -> tuple:
        """(a1, b11, c, d, s) of MSL's padeCoefficients2 for delay time T [s] (a number or
        an expression) and the states' scaling ``scale`` (n numbers)."""
        n = self.n
        b, a = pade_polynomials(T, n, self.m)
        bb = [0] * (n - self.m) + b
        d = bb[0] / a[0]
        a1 = [-a[i + 1] / a[0] * scale[i] / scale[0] for i in range(n)]
        c = [(bb[i + 1] - d * a[i + 1]) * scale[i] for i in range(n)]
        s = [scale[i] / scale[i + 1] for i in range(n - 1)]
        return a1, 1 / (a[0] * scale[0]), c, d, s

    def structure(self, s):
        for i in range(1, self.n + 1):
            s.state(f"x[{i}]", 0.0, description="state of the transfer function in (balanced) "
                                                "controller canonical form")

    def physics(self, e):
        u = e.input(self.u)
        x = [e.state(f"x[{i}]") for i in range(1, self.n + 1)]
        a1, b11, c, d, s = self.coefficients(self.delayTime, self.scale)
        der = [sum((ai * xi for ai, xi in zip(a1, x)), b11 * u)] + \
            [si * xi for si, xi in zip(s, x[:-1])]
        for xi, dx in zip(x, der):
            e.derivative(xi, dx)
        e.output(self.y, sum((ci * xi for ci, xi in zip(c, x)), d * u))
        if self.balance:
            for i, dx in enumerate(der, start=1):
                e.initial(dx, f"der(x[{i}]) = 0 (balance=true)")
        else:
            e.initial(x[-1] - u, "x[n] = u (balance=false)")
