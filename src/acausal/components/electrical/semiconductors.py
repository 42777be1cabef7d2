"""Semiconductors (after Modelica.Electrical.Analog.Semiconductors): the Diode and the ZDiode,
with MSL's exlin, the exponential continued linearly."""
from __future__ import annotations

import casadi as ca

from ...core import Parameter
from .interfaces import OnePort, _ConditionalHeatPort


#: Boltzmann constant [J/K] and elementary charge [A.s], Modelica.Constants.k and .q
K_BOLTZMANN, Q_ELECTRON = 1.380649e-23, 1.602176634e-19


def exlin(x, Maxexp):
    """MSL's Semiconductors.exlin: exp(x), continued linearly (value and slope) above
    Maxexp; written exp(m)·(1 + x − m) with m = min(x, Maxexp), one expression whose
    derivative is exp(x) below Maxexp and exp(Maxexp) above (no exp of a large x)."""
    m = ca.fmin(x, Maxexp)
    return ca.exp(m) * (1 + x - m)


class Diode(_ConditionalHeatPort, OnePort):
    """Simple diode (MSL Semiconductors.Diode): an exponential diode in parallel with the
    ohmic resistance R [Ohm], i = id + v/R with id = Ids·(exlin(v/Vt, Maxexp) − 1) [A];
    Ids [A] saturation current, Vt [V] voltage equivalent of temperature (kT/qn), Maxexp
    [1] the exponent above which the characteristic is continued linearly (``exlin``).

    With the option ``useTemperatureDependency`` the device temperature T_heatPort [K]
    enters: vt_t = k·T_heatPort/q, id = Ids·(exlin(v/(N·vt_t), Maxexp) − 1) and
    i = id·(T_heatPort/TNOM)^(XTI/N)·exp((T_heatPort/TNOM − 1)·EG/(N·vt_t)) + v/R, with EG
    [eV] the activation energy, N [1] the emission coefficient, TNOM [K] the parameter
    measurement temperature, XTI [1] the saturation current's temperature exponent.
    ``useHeatPort`` defaults to useTemperatureDependency (MSL's binding); T_heatPort is
    heatPort.T with it, the parameter T (293.15 K) without. LossPower = v·i [W]. Records v,
    i, id, vt_t, LossPower, T_heatPort. The law is smooth (C1 at the knee of exlin): no
    events, and the same form with smooth=True."""
    options = {"useHeatPort": False, "useTemperatureDependency": False}
    Ids = Parameter(1e-6, "A", "saturation current")
    Vt = Parameter(0.04, "V", "voltage equivalent of temperature (kT/qn)")
    Maxexp = Parameter(15.0, "1", "max. exponent for linear continuation", positive=True)
    R = Parameter(1e8, "Ohm", "parallel ohmic resistance")
    EG = Parameter(1.11, "", "activation energy (MSL: a Real; in eV, as EG/(N*vt_t))")
    N = Parameter(1.0, "1", "emission coefficient")
    TNOM = Parameter(300.15, "K", "parameter measurement temperature", positive=True)
    XTI = Parameter(3.0, "1", "temperature exponent of saturation current")
    T = Parameter(293.15, "K", "fixed device temperature if useHeatPort = false",
                  positive=True)

    def __init__(self, name: str | None = None, **params):
        params.setdefault("useHeatPort", params.get("useTemperatureDependency", False))
        super().__init__(name, **params)

    def physics(self, e):
        v, T = self._v(e), self._T_heatPort(e)
        vt_t = K_BOLTZMANN * T / Q_ELECTRON
        if self.useTemperatureDependency:
            i_d = self.Ids * (exlin(v / (self.N * vt_t), self.Maxexp) - 1)
            aux = (T / self.TNOM - 1) * self.EG / (self.N * vt_t)
            law = i_d * (T / self.TNOM) ** (self.XTI / self.N) * ca.exp(aux) + v / self.R
        else:
            i_d = self.Ids * (exlin(v / self.Vt, self.Maxexp) - 1)
            law = i_d + v / self.R
        i = self._current(e, law)
        self._record(e, v, i)
        e.variable("id", i_d, "A", "diode current")
        e.variable("vt_t", vt_t, "V", "temperature voltage")
        self._losses(e, v * i, T)


class ZDiode(_ConditionalHeatPort, OnePort):
    """Zener diode with 3 working areas (MSL Semiconductors.ZDiode): with the ohmic
    parallel conductance v/R [A] in all three,
    forward (v > Maxexp·Vt): i = Ids·(exlin(v/Vt, Maxexp) − 1), the exponential continued
    linearly; breakdown (v + Bv < −Maxexp·Nbv·Vt): i = −Ids − Ibv·exlin(−(v + Bv)/(Nbv·Vt),
    Maxexp), the breakdown exponential continued linearly; between: i = Ids·(exp(v/Vt) − 1)
    − Ibv·exp(−(v + Bv)/(Nbv·Vt)). Ids [A] saturation current, Vt [V] voltage equivalent of
    temperature, Maxexp [1] the exponent of the linear continuation (30), R [Ohm] parallel
    resistance, Bv [V] breakthrough (Zener) voltage, Ibv [A] breakthrough knee current, Nbv
    [1] breakthrough emission coefficient. The device temperature (T [K] 293.15, or
    heatPort.T with ``useHeatPort``) does not enter the law (MSL's); LossPower = v·i [W].
    The law is continuous to round-off (MSL's smooth(1, ...)): no events."""
    Ids = Parameter(1e-6, "A", "saturation current")
    Vt = Parameter(0.04, "V", "voltage equivalent of temperature (kT/qn)", positive=True)
    Maxexp = Parameter(30.0, "1", "max. exponent for linear continuation", positive=True)
    R = Parameter(1e8, "Ohm", "parallel ohmic resistance", positive=True)
    Bv = Parameter(5.1, "V", "breakthrough voltage = Zener- or Z-voltage")
    Ibv = Parameter(0.7, "A", "breakthrough knee current")
    Nbv = Parameter(0.74, "1", "breakthrough emission coefficient", positive=True)
    T = Parameter(293.15, "K", "fixed device temperature if useHeatPort = false",
                  positive=True)

    def physics(self, e):
        v = self._v(e)
        x_forward, x_breakdown = v / self.Vt, -(v + self.Bv) / (self.Nbv * self.Vt)
        forward = self.Ids * (exlin(x_forward, self.Maxexp) - 1)
        breakdown = self.Ibv * exlin(x_breakdown, self.Maxexp)
        i = self._current(e, v / self.R + ca.if_else(
            x_forward > self.Maxexp, forward,
            ca.if_else(x_breakdown > self.Maxexp, -self.Ids - breakdown, forward - breakdown)))
        self._record(e, v, i)
        self._losses(e, v * i, self._T_heatPort(e))
