"""Math (Modelica.Blocks.Math): gains, sums, products, functions of the inputs,
sampled means."""
from __future__ import annotations

import math
from functools import reduce

import casadi as ca
import numpy as np

from ...core import BooleanOutput, Component, Parameter, RealInput, RealOutput, VectorPort
from ...core.component import who
from ...errors import ParameterError
from .interfaces import (EPS, _matrix, _MultiInput, refuse_smooth, SI2SO, SISO, _Sized, SO,
                         _StartValues)
from .nonlinear import _limit, _limited, _limiter_region


class Gain(SISO):
    """y = k·u."""
    k = Parameter(1.0, "1", "gain value multiplied with input signal")

    def physics(self, e):
        e.output(self.y, self.k * e.input(self.u))


class Add(SI2SO):
    """y = k1·u1 + k2·u2."""
    k1 = Parameter(1.0, "", "gain of input signal 1")
    k2 = Parameter(1.0, "", "gain of input signal 2")

    def physics(self, e):
        e.output(self.y, self.k1 * e.input(self.u1) + self.k2 * e.input(self.u2))


class Add3(SO):
    """y = k1·u1 + k2·u2 + k3·u3."""
    k1 = Parameter(1.0, "", "gain of input signal 1")
    k2 = Parameter(1.0, "", "gain of input signal 2")
    k3 = Parameter(1.0, "", "gain of input signal 3")
    u1 = RealInput("connector of Real input signal 1")
    u2 = RealInput("connector of Real input signal 2")
    u3 = RealInput("connector of Real input signal 3")

    def physics(self, e):
        e.output(self.y, self.k1 * e.input(self.u1) + self.k2 * e.input(self.u2)
                 + self.k3 * e.input(self.u3))


class Feedback(SO):
    """y = u1 − u2 (commanded minus feedback signal)."""
    u1 = RealInput("commanded input")
    u2 = RealInput("feedback input")

    def physics(self, e):
        e.output(self.y, e.input(self.u1) - e.input(self.u2))


class Product(SI2SO):
    """y = u1·u2."""

    def physics(self, e):
        e.output(self.y, e.input(self.u1) * e.input(self.u2))


class Division(SI2SO):
    """y = u1/u2."""

    def physics(self, e):
        e.output(self.y, e.input(self.u1) / e.input(self.u2))


class Sum(_Sized, SO):
    """y = Σ k[i]·u[i], i = 1..nin.

    ``nin`` (constructor argument) is the number of inputs; the inputs are ``u[1]`` ..
    ``u[nin]`` and the gains parameters ``k[1]`` .. ``k[nin]`` (default 1; ``k=[...]`` at
    construction, ``params={"sum.k[2]": -1}`` at simulation time). ``sum.u`` is indexed from
    1 as in Modelica: ``connect(src.y, sum.u[1])``.
    """
    _classes: dict = {}

    def __new__(cls, name=None, *, nin: int = 1, k=None, **params):
        if isinstance(nin, bool) or not isinstance(nin, (int, np.integer)) or nin < 1:
            raise ParameterError(f"Sum: nin (number of inputs) must be an integer >= 1, "
                                 f"got {nin!r}")
        return super().__new__(cls._variant(int(nin)))

    @staticmethod
    def _declare(nin: int) -> dict:
        attrs = {f"k[{i}]": Parameter(1.0, "", f"gain of input u[{i}]")
                 for i in range(1, nin + 1)}
        attrs["u"] = VectorPort(RealInput, nin, tuple(
            f"connector of Real input signal {i}" for i in range(1, nin + 1)))
        return {"_nin": nin, **attrs}

    def __init__(self, name: str | None = None, *, nin: int = 1, k=None, **params):
        if params:
            raise ParameterError(f"Sum has parameters k[1]..k[{self._nin}] only, given as "
                                 f"k=[...]; got {', '.join(params)}")
        super().__init__(name)
        n = self._nin
        if k is not None:
            ks = np.atleast_1d(np.asarray(k, dtype=object)).ravel()
            if ks.size != n:
                raise ParameterError(f"Sum: k has {ks.size} elements but nin = {n}")
            for i, v in enumerate(ks, start=1):
                setattr(self, f"k[{i}]", v)

    @property
    def nin(self) -> int:
        return self._nin

    def physics(self, e):
        e.output(self.y, sum((getattr(self, f"k[{i}]") * e.input(p)
                              for i, p in enumerate(self.u, start=1)), ca.SX(0)))


#: The smallest positive normal double: Log and Log10 evaluate at max(u, _TINY).
_TINY = 2.2250738585072014e-308


def _sign(e, u, events: bool, width):
    """MSL's ``if u > 0 then 1 elseif u < 0 then -1 else 0``: with ``events`` the mode
    ``region`` of a limiter at [0, 0] (its indicators ``upper`` and ``lower`` locate where u
    crosses 0); in smooth form u/sqrt(u² + width²); else the plain expression (noEvent)."""
    if e.smooth:
        return u / ca.sqrt(u ** 2 + width ** 2)
    if not events:
        return ca.sign(u)
    _limited(e, u, 0, 0, width, True)
    return e.mode("region")


class _Signed(SISO):
    """Abs and Sign: MSL's option ``generateEvent`` (False: noEvent, the plain expression;
    True: state events where u crosses 0, the mode ``region`` = sign(u) between them) and,
    in smooth form, sign(u) ≈ u/sqrt(u² + u_smooth²)."""
    options = {"generateEvent": False}
    u_smooth = Parameter(1e-3, "", "smooth form only: width over which sign(u) is rounded at "
                                   "u = 0", positive=True)

    def structure(self, s):
        _limiter_region(s, self.generateEvent)

    def sign(self, e):
        """sign(u), with the events or in the smooth form that go with it."""
        return _sign(e, e.input(self.u), self.generateEvent, self.u_smooth)


class Abs(_Signed):
    """y = |u| (MSL Math.Abs: ``if u >= 0 then u else -u``). Option ``generateEvent``
    (MSL's default False: no events, the integrator's step control resolves the kink; True:
    state events where u crosses 0, so the kink is located; y = |u| all the same, also at
    an event's left limit, where u may be past 0 by the event tolerance: y is never
    negative, e.g. under a Sqrt). Smooth form (``compile(model, smooth=True)``):
    y = u·u/sqrt(u² + u_smooth²), below |u| by at most 0.3003·u_smooth (at |u| ≈
    0.786·u_smooth), by u_smooth²/(2|u|) far from 0."""

    def physics(self, e):
        u, sign = e.input(self.u), self.sign(e)
        e.output(self.y, u * sign if e.smooth else ca.fabs(u))


class Sign(_Signed):
    """y = sign(u): 1 if u > 0, −1 if u < 0, 0 if u = 0 (MSL Math.Sign). Option
    ``generateEvent`` as Abs's. Smooth form: y = u/sqrt(u² + u_smooth²), off by
    u_smooth²/(2u²) far from 0."""

    def physics(self, e):
        e.output(self.y, self.sign(e))


class _Function(SISO):
    """y = f(u) (``function``). Where MSL requires u in a domain (``domain``: the condition,
    its message, u clipped into the domain) the requirement is an assertion: simulate()
    stops with a SimulationError naming the block, the message and the first output time
    where u is outside (``PhysicsBuilder.assertion``), and f is evaluated at the clipped u,
    so the equations stay finite (no NaN in the integrator) up to there; a violation that
    begins and ends between two output times passes unseen."""

    def function(self, u):
        raise NotImplementedError

    def domain(self, u) -> tuple | None:
        """(condition on u, what MSL requires, u clipped into the domain), or None."""
        return None

    def physics(self, e):
        u = e.input(self.u)
        required = self.domain(u)
        if required is not None:
            holds, what, u = required
            e.assertion(holds, what)
        e.output(self.y, self.function(u))


class Sqrt(_Function):
    """y = sqrt(u), u ≥ 0 required (asserted) (MSL Math.Sqrt)."""

    def function(self, u):
        return ca.sqrt(u)

    def domain(self, u):
        return u >= 0, "the input of Sqrt must be >= 0", ca.fmax(u, 0)


class Sin(_Function):
    """y = sin(u), u [rad] (MSL Math.Sin)."""

    def function(self, u):
        return ca.sin(u)


class Cos(_Function):
    """y = cos(u), u [rad] (MSL Math.Cos)."""

    def function(self, u):
        return ca.cos(u)


class Tan(_Function):
    """y = tan(u), u [rad] (MSL Math.Tan)."""

    def function(self, u):
        return ca.tan(u)


class Asin(_Function):
    """y = asin(u) [rad], |u| ≤ 1 required (asserted) (MSL Math.Asin)."""

    def function(self, u):
        return ca.asin(u)

    def domain(self, u):
        return ca.fabs(u) <= 1, "the input of Asin must be within [-1, 1]", _limit(u, -1, 1)


class Acos(_Function):
    """y = acos(u) [rad], |u| ≤ 1 required (asserted) (MSL Math.Acos)."""

    def function(self, u):
        return ca.acos(u)

    def domain(self, u):
        return ca.fabs(u) <= 1, "the input of Acos must be within [-1, 1]", _limit(u, -1, 1)


class Atan(_Function):
    """y = atan(u) [rad] in [−π/2, π/2] (MSL Math.Atan)."""

    def function(self, u):
        return ca.atan(u)


class Sinh(_Function):
    """y = sinh(u) (MSL Math.Sinh)."""

    def function(self, u):
        return ca.sinh(u)


class Cosh(_Function):
    """y = cosh(u) (MSL Math.Cosh)."""

    def function(self, u):
        return ca.cosh(u)


class Tanh(_Function):
    """y = tanh(u) (MSL Math.Tanh)."""

    def function(self, u):
        return ca.tanh(u)


class Exp(_Function):
    """y = exp(u) (MSL Math.Exp)."""

    def function(self, u):
        return ca.exp(u)


class Power(_Function):
    """y = base^u (MSL Math.Power): with ``useExp`` (MSL's default True) written
    exp(u·log(base)), base > 0 required (checked at construction); without, base^u, where a
    base ≤ 0 needs an integer u (asserted; outside, y is NaN, not clipped: the assertion
    stops a simulation where y is an output only, the integrator fails first where it
    feeds a state)."""
    options = {"useExp": True}
    base = Parameter(math.e, "", "base of power")

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        if self.useExp and not self.base > 0:
            raise ParameterError(f"{who(self)}: base must be > 0 with useExp=True (y = "
                                 f"exp(u*log(base))), got {self.base}; give base > 0 or "
                                 f"useExp=False")

    def function(self, u):
        return ca.exp(u * ca.log(self.base)) if self.useExp else self.base ** u

    def domain(self, u):
        if self.useExp:
            return None
        return (ca.logic_or(self.base > 0, u == ca.floor(u)),
                "Power: base^u with base <= 0 needs an integer input u", u)


class Exponentiation(_Function):
    """y = u^exponent (MSL Math.Exponentiation); a u < 0 needs an integer exponent, u = 0
    an exponent ≥ 0 (asserted; outside, y is NaN or infinite, not clipped, as for
    Power)."""
    exponent = Parameter(2.0, "", "exponent of power")

    def function(self, u):
        return u ** self.exponent

    def domain(self, u):
        p = self.exponent
        integer = p == ca.floor(p)
        return (ca.logic_and(ca.logic_or(u >= 0, integer), ca.logic_or(u != 0, p >= 0)),
                "Exponentiation: u^exponent needs u >= 0 or an integer exponent, and u != 0 "
                "for an exponent < 0", u)


class Log(_Function):
    """y = log(u)/log(base) (MSL Math.Log: natural logarithm by default), u > 0 required
    (asserted); base > 0 and ≠ 1 (checked at construction)."""
    base = Parameter(math.e, "", "base of logarithm")

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        if not (self.base > 0 and self.base != 1):
            raise ParameterError(f"{who(self)}: base must be > 0 and != 1, got {self.base}")

    def function(self, u):
        return ca.log(u) / ca.log(self.base)

    def domain(self, u):
        return u > 0, "the input of Log must be > 0", ca.fmax(u, _TINY)


class Log10(_Function):
    """y = log10(u), u > 0 required (asserted) (MSL Math.Log10)."""

    def function(self, u):
        return ca.log10(u)

    def domain(self, u):
        return u > 0, "the input of Log10 must be > 0", ca.fmax(u, _TINY)


class Atan2(SI2SO):
    """y = atan2(u1, u2) [rad] in [−π, π], the angle of the point (u2, u1) (MSL Math.Atan2;
    u1 = u2 = 0 gives 0)."""

    def physics(self, e):
        e.output(self.y, ca.atan2(e.input(self.u1), e.input(self.u2)))


class Max(SI2SO):
    """y = max(u1, u2) (MSL Math.Max: Modelica's max, no events; the integrator's step
    control resolves the kink, also in smooth form)."""

    def physics(self, e):
        e.output(self.y, ca.fmax(e.input(self.u1), e.input(self.u2)))


class Min(SI2SO):
    """y = min(u1, u2) (MSL Math.Min: no events, as Max)."""

    def physics(self, e):
        e.output(self.y, ca.fmin(e.input(self.u1), e.input(self.u2)))


class MultiSum(_MultiInput, SO):
    """y = k[1]·u[1] + ... + k[nu]·u[nu] (MSL Math.MultiSum). ``nu`` (constructor argument,
    ≥ 1) inputs ``u[1]`` .. ``u[nu]``; the gains, the vector parameter ``k`` (``k[1]`` ..
    ``k[nu]``, default 1; ``k=[...]`` at construction, ``params={"<name>.k": [...]}`` at
    simulation time)."""
    _classes: dict = {}

    @staticmethod
    def _declare(nu: int) -> dict:
        return {**_MultiInput._declare(nu), "k": Parameter((1.0,) * nu, "", "input gains")}

    def __init__(self, name: str | None = None, *, nu: int = 1, k=None, **params):
        if k is not None:                   # a number is every input's gain
            params["k"] = tuple(np.ravel(k)) if np.ndim(k) else (k,) * self.nu
        super().__init__(name, **params)

    def physics(self, e):
        e.output(self.y, sum((self.k[i] * u for i, u in enumerate(self.inputs(e))),
                             ca.SX(0)))


class MultiProduct(_MultiInput, SO):
    """y = u[1]·u[2]·...·u[nu] (MSL Math.MultiProduct); ``nu`` (constructor argument, ≥ 1)
    inputs ``u[1]`` .. ``u[nu]``."""
    _classes: dict = {}

    def physics(self, e):
        y = ca.SX(1)
        for u in self.inputs(e):
            y = y * u
        e.output(self.y, y)


class MinMax(_MultiInput):
    """The largest and the smallest of the inputs (MSL Math.MinMax): yMax = max(u),
    yMin = min(u) (no events); ``nu`` (constructor argument, ≥ 1) inputs ``u[1]`` ..
    ``u[nu]``."""
    _classes: dict = {}
    yMax = RealOutput("maximal element of u")
    yMin = RealOutput("minimal element of u")

    def physics(self, e):
        u = self.inputs(e)
        e.output(self.yMax, reduce(ca.fmax, u))
        e.output(self.yMin, reduce(ca.fmin, u))


class MatrixGain(_Sized, Component):
    """y = K·u (MSL Math.MatrixGain): ``K`` (nout × nin, given at construction; MSL's
    default [1, 0; 0, 1]) fixes the block's sizes, its values are the parameter ``K``
    (``K[1]`` .. ``K[nout·nin]``, row by row as StateSpace's matrices; ``params={"<name>.K":
    matrix}`` changes them at simulation time). Inputs ``u[1]`` .. ``u[nin]``, outputs
    ``y[1]`` .. ``y[nout]``."""
    _classes: dict = {}

    def __new__(cls, name=None, *, K=((1.0, 0.0), (0.0, 1.0)), **params):
        return super().__new__(cls._variant(*_matrix(K, f"{cls.__name__}: K").shape))

    @staticmethod
    def _declare(nout: int, nin: int) -> dict:
        return {"K": Parameter((0.0,) * (nout * nin), "", f"gain matrix which is multiplied "
                                                          f"with the input ({nout} x {nin}, "
                                                          f"row by row)"),
                "u": VectorPort(RealInput, nin, "connector of Real input signals"),
                "y": VectorPort(RealOutput, nout, "connector of Real output signals")}

    def __init__(self, name: str | None = None, *, K=((1.0, 0.0), (0.0, 1.0)), **params):
        super().__init__(name, K=tuple(_matrix(K, f"{type(self).__name__}: K").ravel()),
                         **params)

    @property
    def nout(self) -> int:
        """Number of outputs, the rows of K."""
        return self._key[0]

    @property
    def nin(self) -> int:
        """Number of inputs, the columns of K."""
        return self._key[1]

    def physics(self, e):
        K = ca.reshape(self.K, self.nin, self.nout).T
        y = K @ ca.vertcat(*(e.input(p) for p in self.u))
        for i, port in enumerate(self.y):
            e.output(port, y[i])


class InverseBlockConstraints(Component):
    """Exchanges the inputs and outputs of a block, to build an inverse model (MSL
    Math.InverseBlockConstraints): u1 = u2 and y1 = y2. Connect the inverted block's output
    to u2 and the value it shall have to u1, its input from y2 (and y1 wherever the
    computed input is wanted): y1 = y2 is an unknown of the DAE (an algebraic variable,
    recorded as ``<block>.y1``), fixed by u1 = u2.

    When the inverted block has states between its input and its output (a FirstOrder:
    no direct feedthrough, the usual case), u1 = u2 holds no unknown: it constrains states
    (a higher-index DAE), and the model is compiled with
    ``acausal.compile(model, index_reduction=True)``: a state of the inverted block then
    becomes an expression of the others and the unknown follows from the constraint's
    rate (``acausal.compiler.index``). The signal at u1 must then be differentiable as
    often as the inverted block's relative degree: filter it (CriticalDamping of that
    order, MSL's Blocks.Examples.InverseModel) or give it as a smooth function of time."""
    u1 = RealInput("input signal 1 (u1 = u2)")
    u2 = RealInput("input signal 2 (u1 = u2)")
    y1 = RealOutput("output signal 1 (y1 = y2)")
    y2 = RealOutput("output signal 2 (y1 = y2)")

    def structure(self, s):
        s.algebraic("y1", description="the outputs y1 = y2, fixed by u1 = u2")

    def physics(self, e):
        y = e.state("y1")
        e.output(self.y1, y)
        e.output(self.y2, y)
        e.residual(e.input(self.u1) - e.input(self.u2))


class _Sampled(_StartValues):
    """What the blocks built on MSL Math.Mean share (Mean, RootMeanSquare, Harmonic,
    TotalHarmonicDistortion): Mean's equations (see Mean) for one or more signals, each
    under the names ``<prefix>integral``, ``<prefix>integral_last``, ``<prefix>x``,
    ``<prefix>y_last`` (``_means``: prefix, x0, y0 of each), all sampled at the instants
    k/f of one trigger."""
    f = Parameter(50.0, "Hz", "base frequency", positive=True)

    def _means(self) -> list[tuple[str, float, float]]:
        """(prefix, start of the integral, start of the mean) of each mean."""
        return [("", self.x0, self.y0)]

    def structure(self, s):
        refuse_smooth(self, s)
        s.sample("sampleTrigger", 1 / self.f, 1 / self.f,
                 description="true at the sample instants k/f")
        s.mode("sampled", 0, values=(0, 1),
               description="true, once the integral is read at the present sample instant")
        for p, x0, y0 in self._means():
            s.state(f"{p}integral", x0, description="integral of the averaged signal from "
                                                    "the start (with x0)")
            s.discrete(f"{p}integral_last", 0.0,
                       description="integral at the last sample instant")
            s.discrete(f"{p}y_last", y0, description="last sampled mean value")

    def first_round(self, e) -> ca.SX:
        """True in the event iteration's first round at a sample instant (where the integrals
        are read); call once in physics."""
        trigger, sampled = e.mode("sampleTrigger"), e.mode("sampled")
        e.mode_update(sampled, trigger)
        return ca.logic_and(trigger, ca.logic_not(sampled))

    def mean(self, e, v, nonnegative: bool, first: ca.SX, prefix: str = "") -> ca.SX:
        """The sampled mean of v over the last period (y_last) of the mean ``prefix``, its
        equations written; ``first`` from ``first_round``."""
        p = prefix
        integral, last, y_last = (e.state(f"{p}integral"), e.mode(f"{p}integral_last"),
                                  e.mode(f"{p}y_last"))
        e.derivative(integral, v)
        y_new = self.f * (integral - last)
        e.mode_update(y_last, ca.if_else(first, ca.fmax(0, y_new) if nonnegative else y_new,
                                         y_last))
        e.mode_update(last, ca.if_else(first, integral, last))
        e.variable(f"{p}x", integral - last, description="integrator state (reset at the "
                                                         "sample instants)")
        return y_last

    def root_mean_square(self, e, u, first: ca.SX, prefix: str = "") -> ca.SX:
        """MSL Math.RootMeanSquare's output sqrt(mean.y) for the input u, its inner Mean
        (of u·u, yGreaterOrEqualZero) under ``<prefix>mean.``."""
        mean = self.mean(e, u * u, True, first, f"{prefix}mean.")
        e.variable(f"{prefix}mean.y", mean, description="mean of u*u over the last period")
        return ca.sqrt(mean)

    def harmonic(self, e, u, k, first: ca.SX, prefix: str = "") -> tuple[ca.SX, ca.SX]:
        """MSL Math.Harmonic's (y_rms, y_arg before its gain) of harmonic k of u: the means
        ``<prefix>mean1`` of u·√2·cos(2π·k·f·t) and ``<prefix>mean2`` of u·√2·sin(2π·k·f·t)
        (its sources sin1, sin2), in polar form."""
        wt = 2 * math.pi * k * self.f * e.time
        re = self.mean(e, u * math.sqrt(2) * ca.cos(wt), False, first, f"{prefix}mean1.")
        im = self.mean(e, u * math.sqrt(2) * ca.sin(wt), False, first, f"{prefix}mean2.")
        return ca.sqrt(re * re + im * im), ca.atan2(im, re)


class Mean(_Sampled, SISO):
    """The mean of u over each period 1/f [Hz] (MSL Math.Mean): y = f·∫u dt over the last
    full period, updated at the instants k/f (time events), held in between; y = y0 before
    the first. Option ``yGreaterOrEqualZero`` (y = max(0, ...), for a mean ≥ 0 in exact
    arithmetic). Start values (constructor arguments): x0 (the integrator's state, so the
    first mean is f·(x0 + ∫u dt)), y0. MSL's equations::

        der(x) = u
        when sample(t0 + 1/f, 1/f) then
          y_last = f·pre(x)     (max(0, f·pre(x)) with yGreaterOrEqualZero)
          reinit(x, 0)
        end when
        y = y_last

    with x = x0 and y_last = y0 at the start. A sample instant reinitializes no state
    here, so the state is ``integral`` = ∫u dt (starting at x0), never reset; the discrete
    variable ``integral_last`` keeps its value at the last instant (0 before the first),
    and MSL's x = integral − integral_last is recorded (so is ``y_last``). The mode
    ``sampled`` tells the event iteration's first round at an instant (where the integral
    is read) from the next ones, as the discrete blocks' ``sampled`` does. Refused in
    smooth form (the output changes at events only).

    MSL differences: the instants are counted from time 0 (MSL's t0 is the simulation's
    start: a simulation started at t > 0 has the same instants k/f, its first period cut
    short); the integral over the whole run, not over one period, is the state, so its
    error control is relative to the integral's magnitude (for a long run of an input with
    a large mean, tighten rtol).
    """
    _starts = ("x0", "y0")
    options = {"yGreaterOrEqualZero": False}

    def physics(self, e):
        e.output(self.y, self.mean(e, e.input(self.u), self.yGreaterOrEqualZero,
                                   self.first_round(e)))


class RootMeanSquare(_Sampled, SISO):
    """The root mean square of u over each period 1/f [Hz] (MSL Math.RootMeanSquare):
    y = sqrt(mean.y), mean.y the Mean (with yGreaterOrEqualZero) of u·u, updated at the
    instants k/f, held in between; y = y0 (≥ 0) before the first. Start values
    (constructor arguments): x0 (the state of the Mean of u², MSL's mean.x0), y0 (≥ 0; the
    Mean of u² starts at y0²). The equations are Mean's (see Mean), recorded under MSL's
    names of the inner Mean: ``mean.x``, ``mean.y_last``, ``mean.y`` (and
    ``mean.integral``, ``mean.integral_last``)."""
    _starts = ("x0", "y0")

    def __init__(self, name: str | None = None, **kwargs):
        super().__init__(name, **kwargs)
        if self.y0 < 0:
            raise ParameterError(f"{who(self)}: y0 (start value of the output, a root mean "
                                 f"square) must be >= 0, got {self.y0}")

    def _means(self) -> list[tuple[str, float, float]]:
        return [("mean.", self.x0, self.y0 ** 2)]

    def physics(self, e):
        e.output(self.y, self.root_mean_square(e, e.input(self.u), self.first_round(e)))


class Harmonic(_Sampled, Component):
    """Root mean square and phase of harmonic ``k`` of u over each period 1/f [Hz] (MSL
    Math.Harmonic): the Means (see Mean) of u·√2·cos(2π·k·f·t) (``mean1``) and of
    u·√2·sin(2π·k·f·t) (``mean2``), in polar form: y_rms = sqrt(mean1² + mean2²),
    y_arg = atan2(mean2, mean1) [rad] (−atan2 with option ``useConjugateComplex``), so that
    u = √2·y_rms·cos(2π·k·f·t − y_arg) (+ y_arg with useConjugateComplex) when u is that
    harmonic. Updated at the instants k'/f (k' = 1, 2, ...), held in between. ``k``
    (constructor argument, an integer ≥ 1, default 1) is the order of the harmonic; start
    values (constructor arguments, default 0): x0Cos, x0Sin (the Means' integrator
    states), y0Cos, y0Sin (their outputs before the first instant). Recorded under MSL's
    names of the inner Means: ``mean1.x``, ``mean1.y_last``, ``mean2.x``, ... Refused in
    smooth form, as Mean."""
    _starts = ("x0Cos", "x0Sin", "y0Cos", "y0Sin")
    options = {"useConjugateComplex": False}
    u = RealInput("connector of Real input signal")
    y_rms = RealOutput("root mean square of polar representation")
    y_arg = RealOutput("angle of polar representation [rad]")

    def __init__(self, name: str | None = None, *, k: int = 1, **kwargs):
        if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or k < 1:
            raise ParameterError(f"Harmonic: k (order of the harmonic) must be an integer "
                                 f">= 1, got {k!r}")
        super().__init__(name, **kwargs)
        self.__dict__["k"] = int(k)

    def _means(self) -> list[tuple[str, float, float]]:
        return [("mean1.", self.x0Cos, self.y0Cos), ("mean2.", self.x0Sin, self.y0Sin)]

    def physics(self, e):
        y_rms, y_arg = self.harmonic(e, e.input(self.u), self.k, self.first_round(e))
        e.output(self.y_rms, y_rms)
        e.output(self.y_arg, -y_arg if self.useConjugateComplex else y_arg)


class TotalHarmonicDistortion(_Sampled, SISO):
    """Total harmonic distortion of u over each period 1/f [Hz] (MSL
    Math.TotalHarmonicDistortion), from the root mean square U of u (MSL's inner
    RootMeanSquare) and that of its first harmonic U1 (MSL's inner Harmonic, k = 1)::

        y = sqrt(U² − U1²)/U1   (option useFirstHarmonic, default: IEC 60050-551-20-13)
        y = sqrt(U² − U1²)/U    (useFirstHarmonic=False: with respect to the total RMS)

    (sqrt of 0 where U² < U1², denominators at least Modelica.Constants.eps), updated at
    the instants k/f, held in between. The BooleanOutput ``valid`` is true where
    U² ≥ U1² and U1 > 0: false before the first instant and for a zero input. All start
    values are 0 (MSL's finals). Recorded under MSL's names of the inner blocks:
    ``harmonic.mean1.x``, ``harmonic.mean2.x``, ``harmonic.y_rms``, ``harmonic.y_arg``,
    ``rootMeanSquare.mean.x``, ``rootMeanSquare.y``, ... Refused in smooth form, as Mean.

    MSL difference: MSL composes it of blocks (a Limiter, a GreaterThreshold, ...) whose
    relations may add events; here their equations are expressions of the sampled values,
    which change at the sample instants only, so the result is the same without them."""
    f = Parameter(1.0, "Hz", "base frequency", positive=True)
    options = {"useFirstHarmonic": True}
    valid = BooleanOutput("true, if output y is valid")

    def _means(self) -> list[tuple[str, float, float]]:
        return [("harmonic.mean1.", 0.0, 0.0), ("harmonic.mean2.", 0.0, 0.0),
                ("rootMeanSquare.mean.", 0.0, 0.0)]

    def physics(self, e):
        u, first = e.input(self.u), self.first_round(e)
        u1, arg = self.harmonic(e, u, 1, first, "harmonic.")
        rms = self.root_mean_square(e, u, first, "rootMeanSquare.")
        e.variable("harmonic.y_rms", u1, description="root mean square of the first harmonic")
        e.variable("harmonic.y_arg", arg, "rad", "angle of the first harmonic")
        e.variable("rootMeanSquare.y", rms, description="root mean square of u")
        y2 = rms * rms - u1 * u1
        reference = u1 if self.useFirstHarmonic else rms
        e.output(self.y, ca.sqrt(ca.fmax(y2, 0)) / ca.fmax(EPS, reference))
        e.output(self.valid, ca.logic_and(y2 >= 0, u1 > 0))
