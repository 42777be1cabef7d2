"""Semiconductors (after Modelica.Electrical.Analog.Semiconductors): the Diode, Diode2 and
the ZDiode, with MSL's exlin, the exponential continued linearly; the simple Thyristor and
the SimpleTriac made of two of them; the bipolar transistors NPN and PNP (Ebers–Moll) and
the MOSFETs NMOS and PMOS (Shichman–Hodges)."""
from __future__ import annotations

import casadi as ca

from ...core import (ConditionalPort, HeatPort_a, Model, NegativePin, Parameter, Pin,
                     PositivePin)
from ...core.component import BoundParameters, bound_twin, who
from ...errors import ParameterError
from ..signals.interfaces import refuse_smooth
from .ideal import IdealDiode
from .interfaces import OnePort, _ConditionalHeatPort


#: Boltzmann constant [J/K] and elementary charge [A.s], Modelica.Constants.k and .q
K_BOLTZMANN, Q_ELECTRON = 1.380649e-23, 1.602176634e-19


def exlin(x, Maxexp):
    """MSL's Semiconductors.exlin: exp(x), continued linearly (value and slope) above
    Maxexp; written exp(m)·(1 + x − m) with m = min(x, Maxexp), one expression whose
    derivative is exp(x) below Maxexp and exp(Maxexp) above (no exp of a large x)."""
    m = ca.fmin(x, Maxexp)
    return ca.exp(m) * (1 + x - m)


def exlin2(x, Minexp, Maxexp):
    """MSL's Semiconductors.exlin2: exp(x), continued linearly (value and slope) below
    Minexp and above Maxexp (``exlin``'s form at both ends)."""
    m = ca.fmax(ca.fmin(x, Maxexp), Minexp)
    return ca.exp(m) * (1 + x - m)


def _exp(x):
    """exp(x), continued linearly above x = 80 (``exlin``): finite in the branches of a law
    that are not taken and at the compiler's probe values, the same as exp wherever a
    diode's current is physical (Ids·e^80 is 5e21 A for Ids = 1e-13 A)."""
    return exlin(x, 80)


def powlin(x, y):
    """MSL's Semiconductors.powlin: (1 − x)^(−y), continued linearly (1 + y·x) for x > 0."""
    return ca.if_else(x > 0, 1 + y * x, (1 - ca.fmin(x, 0)) ** (-y))


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



class Diode2(BoundParameters, _ConditionalHeatPort, OnePort):
    """Improved diode model (MSL Semiconductors.Diode2): a pure diode (voltage vd [V],
    current id [A]) in series with the ohmic resistance Rs [Ohm], the parallel conductance
    Gp [S] across both: v = vd + id·Rs, i = id + v·Gp, with

        id = −Ids·(exp(−(vd + Bv)/(N·Vt_applied)) + 1 − 2·exp(−Bv/(2·N·Vt_applied)))
                                                    for vd < −Bv/2 (reverse breakdown),
             Ids·(exp(vd/(N·Vt_applied)) − 1)      for vd < VdMax,
             iVdMax + (vd − VdMax)·diVdMax         above (continued linearly),

    VdMax = Vf + N·Vt_applied, iVdMax and diVdMax the exponential's value and slope there
    (C1). Vt_applied = k·T_heatPort/q with ``useHeatPort``, else the parameter Vt [V],
    which is k·T/q (T = 293.15 K: 0.02526 V) unless given (MSL's binding R·T/F; it follows
    T when T is changed at simulation time). vd is an algebraic unknown. Vf [V] forward
    voltage, Ids [A] reverse saturation current, N [1] emission coefficient, Bv [V] reverse
    breakdown voltage (> 0). LossPower = v·i [W]. Records v, i, vd, id."""
    Vf = Parameter(0.7, "V", "forward voltage", positive=True)
    Ids = Parameter(1e-13, "A", "reverse saturation current")
    Rs = Parameter(16.0, "Ohm", "ohmic resistance")
    N = Parameter(1.0, "1", "emission coefficient", positive=True)
    Bv = Parameter(100.0, "V", "reverse breakdown voltage", positive=True)
    Gp = Parameter(1e-6, "S", "parallel conductance for numerical stability")
    T = Parameter(293.15, "K", "fixed device temperature if useHeatPort = false",
                  positive=True)

    @property
    def Vt(self):
        """Thermal voltage (kT/q) [V]: k·T/q (MSL's binding R·T/F)."""
        return K_BOLTZMANN / Q_ELECTRON * self.T

    def structure(self, s):
        s.algebraic("vd", 0.0, "V", "voltage across pure diode part")

    def physics(self, e):
        vd, v, T = e.state("vd"), self._v(e), self._T_heatPort(e)
        e.assertion(self.Vt > 0, "Vt must be greater than zero")
        nvt = self.N * (K_BOLTZMANN / Q_ELECTRON * T if self.useHeatPort else self.Vt)
        VdMax = self.Vf + nvt
        iVdMax = self.Ids * (_exp(VdMax / nvt) - 1)
        diVdMax = self.Ids * _exp(VdMax / nvt) / nvt
        i_d = ca.if_else(
            vd < -self.Bv / 2,
            -self.Ids * (_exp(-(vd + self.Bv) / nvt) + 1 - 2 * _exp(-self.Bv / (2 * nvt))),
            ca.if_else(vd < VdMax, self.Ids * (_exp(vd / nvt) - 1),
                       iVdMax + (vd - VdMax) * diVdMax))
        e.residual(v - (vd + i_d * self.Rs))
        i = self._current(e, i_d + v * self.Gp)
        self._record(e, v, i)
        e.variable("id", i_d, "A", "diode current")
        self._losses(e, v * i, T)


bound_twin(Diode2, "Vt", Parameter(0.025, "V", "thermal voltage (kT/q), 0.026 at normal "
                                                "conditions (around 20 degC)", positive=True))

class Thyristor(_ConditionalHeatPort):
    """Simple thyristor model (MSL Semiconductors.Thyristor) between Anode, Cathode and
    Gate, with MSL's equations:

    - gate: iGK = Gate.i = vGK·IGT/VGT [A] below vRef [V], (vGK − vRef²/VGT)·IGT/(VGT −
      vRef) above (vGK = Gate.v − Cathode.v);
    - control voltage: vControl [V] (a state, start 0) follows vContot = vConmain + a gate
      term (0 for iGK < 0.95·IGT, 10000·(iGK − 0.95·IGT)·vAK within 1 mA above it, 10·vAK
      beyond) with the time constant 1.87·TON rising, 0.638·TOFF falling [s];
    - anode current: Anode.i = vAK/Roff while vControl < Voff = 1.5 V, vAK/Ron above Von =
      5 V, vAK/(sqrt(Ron·Roff)·(Ron/Roff)^((3x − 4x³)/2)) between (x = (2·vControl − Von −
      Voff)/(2·(Von − Voff))), and the reverse breakthrough −VRRM/Roff·exp(−(vAK +
      VRRM)/(Nbv·Vt)) below vAK = −VRRM; Ron = (VTM − 0.7 V)/ITM, Roff = VDRM²/VTM/IH
      [Ohm] (MSL's protected parameters);
    - holding and forward breakthrough: vConmain = Von while Anode.i > IH or vAK > VDRM,
      else 0: the Boolean mode ``main``, switched at the state events where Anode.i − IH
      (indicator ``holding``) or vAK − VDRM (``breakthrough``) crosses 0.

    So a gate current above IGT fires the thyristor (within about TON), which then conducts
    until its current falls below IH; there is no turning it off by the gate. Cathode.i =
    −(Anode.i + Gate.i); LossPower = Σ pin.i·pin.v [W]. IDRM is declared as in MSL and not
    used by its equations. The rise/fall switch of the time constant is integrated across
    (continuous there). Records vAK, vGK, iGK, vControl, vContot, vConmain. No smooth
    form."""
    VDRM = Parameter(100.0, "V", "forward breakthrough voltage", positive=True)
    VRRM = Parameter(100.0, "V", "reverse breakthrough voltage", nonnegative=True)
    IDRM = Parameter(0.1, "A", "saturation current")
    VTM = Parameter(1.7, "V", "conducting voltage")
    IH = Parameter(6e-3, "A", "holding current", positive=True)
    ITM = Parameter(25.0, "A", "conducting current", positive=True)
    VGT = Parameter(0.7, "V", "gate trigger voltage")
    IGT = Parameter(5e-3, "A", "gate trigger current", positive=True)
    TON = Parameter(1e-6, "s", "switch on time", positive=True)
    TOFF = Parameter(15e-6, "s", "switch off time", positive=True)
    Vt = Parameter(0.04, "V", "voltage equivalent of temperature (kT/qn)", positive=True)
    Nbv = Parameter(0.74, "1", "reverse breakthrough emission coefficient", positive=True)
    vRef = Parameter(0.65, "V", "gate voltage where the gate characteristic bends")
    T = Parameter(293.15, "K", "fixed device temperature if useHeatPort = false",
                  positive=True)
    Anode = PositivePin("anode")
    Cathode = NegativePin("cathode")
    Gate = PositivePin("gate")
    #: MSL's protected Von, Voff [V]: the control voltages of full and no conduction
    Von, Voff = 5.0, 1.5

    def __init__(self, name: str | None = None, **params):
        super().__init__(name, **params)
        if not self.VTM > 0.7:
            raise ParameterError(f"{who(self)}: VTM (= {self.VTM:g} V) must exceed 0.7 V: the "
                                 f"conducting resistance Ron = (VTM - 0.7 V)/ITM must be > 0")
        if not self.VGT > self.vRef:
            raise ParameterError(f"{who(self)}: VGT (= {self.VGT:g} V) must exceed vRef (= "
                                 f"{self.vRef:g} V): the gate characteristic's slope above "
                                 f"vRef is IGT/(VGT - vRef)")

    def structure(self, s):
        refuse_smooth(self, s)
        s.state("vControl", 0.0, "V", "control voltage")
        s.mode("main", 0, values=(0, 1), description="holding or forward breakthrough "
                                                      "(vConmain = Von)")

    def physics(self, e):
        vA, vK, vG = (e.potential(p) for p in (self.Anode, self.Cathode, self.Gate))
        vAK, vGK = vA - vK, vG - vK
        iGK = ca.if_else(vGK < self.vRef, vGK * self.IGT / self.VGT,
                         (vGK - self.vRef ** 2 / self.VGT) * self.IGT / (self.VGT - self.vRef))
        main, vControl = e.mode("main"), e.state("vControl")
        Von, Voff = self.Von, self.Voff
        vConmain = Von * main
        trigger = 0.95 * self.IGT
        vContot = vConmain + ca.if_else(iGK < trigger, 0.0, ca.if_else(
            iGK < trigger + 1e-3, 10000 * (iGK - trigger) * vAK, 10 * vAK))
        rise = vContot - vControl
        e.derivative(vControl, rise / ca.if_else(rise > 0, 1.87 * self.TON, 0.638 * self.TOFF))
        Ron = (self.VTM - 0.7) / self.ITM
        Roff = self.VDRM ** 2 / self.VTM / self.IH
        x = (2 * vControl - Von - Voff) / (2 * (Von - Voff))
        iA = ca.if_else(
            vAK < -self.VRRM,
            -self.VRRM / Roff * ca.exp(-(vAK + self.VRRM) / (self.Nbv * self.Vt)),
            ca.if_else(vControl < Voff, vAK / Roff, ca.if_else(
                vControl < Von,
                vAK / (ca.sqrt(Ron * Roff) * (Ron / Roff) ** ((3 * x - 4 * x ** 3) / 2)),
                vAK / Ron)))
        e.mode_update(main, ca.logic_or(iA > self.IH, vAK > self.VDRM))
        e.indicator("holding", iA - self.IH, "A", "Anode.i - IH: the holding current")
        e.indicator("breakthrough", vAK - self.VDRM, "V", "vAK - VDRM: forward breakthrough")
        e.flow(self.Anode, iA)
        e.flow(self.Gate, iGK)
        e.flow(self.Cathode, -(iA + iGK))
        for name, value, unit, text in (
                ("vAK", vAK, "V", "voltage between anode and cathode"),
                ("vGK", vGK, "V", "voltage between gate and cathode"),
                ("iGK", iGK, "A", "gate current"),
                ("vContot", vContot, "V", "total control voltage"),
                ("vConmain", vConmain, "V", "control voltage of holding and breakthrough")):
            e.variable(name, value, unit, text)
        self._losses(e, iA * vA - (iA + iGK) * vK + iGK * vG, self._T_heatPort(e))


class SimpleTriac(Model):
    """Simple triac (MSL Semiconductors.SimpleTriac), made of MSL's parts: two Thyristors
    in antiparallel between the anode ``p`` and the cathode ``n`` (``thyristor1`` from p to
    n, ``thyristor`` from n to p), each fired from the gate ``g`` through an IdealDiode
    (Vknee = 0; ``idealDiode1``, ``idealDiode``), so a gate current into g fires the
    thyristor whose cathode lies below the gate::

        p ── thyristor1 (Anode → Cathode) ── n,   n ── thyristor (Anode → Cathode) ── p
        g ── idealDiode1 ── thyristor1.Gate,       g ── idealDiode ── thyristor.Gate

    Constructor keywords (MSL's parameters, set on both thyristors, by whose names they are
    changed at simulation time: ``thyristor.VDRM``, ``thyristor1.VDRM``, ...): VDRM, VRRM
    [V] (100), IDRM [A] (0.1), VTM [V] (1.7), IH [A] (6e-3), ITM [A] (25), VGT [V] (0.7), IGT
    [A] (5e-3), TON [s] (1e-6), TOFF [s] (15e-6), Vt [V] (0.04), Nbv [1] (0.74), T [K]
    (293.15); option useHeatPort (both thyristors' losses leave through ``heatPort``).

    Differences from MSL: the triac's LossPower is not recorded as one variable (an acausal
    Model has no equations of its own): it is thyristor.LossPower + thyristor1.LossPower +
    the diodes' v·i. As MSL warns, the thyristor model makes the triac sensitive to some
    parameters (VDRM, VRRM).
    """
    options = {"useHeatPort": False}
    p = PositivePin("anode")
    n = NegativePin("cathode")
    g = PositivePin("gate")
    heatPort = ConditionalPort(HeatPort_a("conditional heat port", required=True),
                               "useHeatPort")

    def __init__(self, name: str | None = None, *, useHeatPort: bool = False, **params):
        super().__init__(name, useHeatPort=useHeatPort)
        known = set(Thyristor.parameters()) - {"vRef"}
        unknown = sorted(set(params) - known)
        if unknown:
            raise ParameterError(f"SimpleTriac{f' {name!r}' if name else ''} has no parameter "
                                 f"{', '.join(repr(k) for k in unknown)} (its parameters: "
                                 f"{', '.join(sorted(known))})")
        self.thyristor = Thyristor(useHeatPort=useHeatPort, **params)
        self.thyristor1 = Thyristor(useHeatPort=useHeatPort, **params)
        self.idealDiode = IdealDiode(Vknee=0.0)
        self.idealDiode1 = IdealDiode(Vknee=0.0)
        for a, b in [(self.thyristor.Anode, self.n), (self.thyristor1.Anode, self.p),
                     (self.thyristor1.Anode, self.thyristor.Cathode),
                     (self.thyristor1.Cathode, self.thyristor.Anode),
                     (self.thyristor.Gate, self.idealDiode.n), (self.idealDiode.p, self.g),
                     (self.idealDiode1.n, self.thyristor1.Gate), (self.idealDiode1.p, self.g)]:
            self.connect(a, b)
        if useHeatPort:
            self.connect(self.heatPort, self.thyristor.heatPort)
            self.connect(self.heatPort, self.thyristor1.heatPort)


class _BipolarTransistor(_ConditionalHeatPort):
    """MSL's NPN and PNP (Ebers–Moll with heating port), one model with the polarity ``_s``
    (+1 NPN, −1 PNP): the junction voltages vjc = s·(B.v − C.v), vje = s·(B.v − E.v) (MSL's
    vbc, vbe for the NPN, vcb, veb for the PNP) [V]; the diode currents ijc =
    is_t·(exlin2(vjc/(NR·vt_t), EMin, EMax) − 1) + vjc·Gbc, ije likewise with NF, Gbe [A];
    qbk = 1 − vjc·Vak; the capacitances cjc = Taur·is_t/(NR·vt_t)·exlin2(vjc/(NR·vt_t)) +
    Cjc·powlin(vjc/Phic, Mc), cje with Tauf, NF, Cje, Phie, Me [F]; then

        C.i = s·((ije − ijc)·qbk − ijc/br_t − cjc·der(vjc)) − iS,
        B.i = s·(ije/bf_t + ijc/br_t + cjc·der(vjc) + cje·der(vje)),
        E.i = −B.i − C.i − iS,   iS = −Ccs·der(vcs),  vcs = C.v − vS,

    vS the substrate's potential: the pin S (option useSubstrate, S.i = iS) or 0 (the
    substrate implicitly grounded). vjc, vje, vcs are states (start 0; MSL's UIC: vcs = IC
    at the start). Temperature (useTemperatureDependency; useHeatPort defaults to it):
    is_t = Is·(T/Tnom)^XTI·exlin2((T/Tnom − 1)·EG/vt_t, EMin, EMax), br_t, bf_t = Br, Bf
    ·(T/Tnom)^XTB, vt_t = k·T/q with T = T_heatPort; otherwise Is, Br, Bf and Vt.
    LossPower = vjc·ijc/br_t + vje·ije/bf_t + s·(ije − ijc)·qbk·(C.v − E.v) [W] (MSL's,
    without the capacitive currents).

    Cje, Cjc and Ccs must be > 0 here (the states' derivatives are solved for; MSL accepts
    0). The three capacitances join B–C, B–E and C–substrate: a circuit that also joins the
    emitter and the substrate (the emitter grounded while the substrate is implicitly
    grounded, or both on fixed potentials) closes a loop of capacitors, a higher-index
    network: compile it with ``index_reduction=True`` (one of the three voltages then
    follows from the other two). So do a collector on a supply rail (the collector–
    substrate capacitance across a voltage source) and two transistors joined at their
    emitters; a resistor in series breaks such a loop. The pF capacitances make a circuit
    stiff (ns time constants beside the circuit's own): where a source jumps (a step, a
    pulse) in a model without events, IDAS's restart at the jump fails on the capacitances'
    sudden currents: give the edge a finite rise (TrapezoidVoltage)."""
    options = {"useTemperatureDependency": False, "useSubstrate": False, "UIC": False,
               "useHeatPort": False}
    Bf = Parameter(50.0, "1", "forward beta")
    Br = Parameter(0.1, "1", "reverse beta")
    Is = Parameter(1e-16, "A", "transport saturation current")
    Vak = Parameter(0.02, "1/V", "early voltage (inverse), 1/Volt")
    Tauf = Parameter(0.12e-9, "s", "ideal forward transit time", nonnegative=True)
    Taur = Parameter(5e-9, "s", "ideal reverse transit time", nonnegative=True)
    Ccs = Parameter(1e-12, "F", "collector-substrate(ground) cap.", positive=True)
    Cje = Parameter(0.4e-12, "F", "base-emitter zero bias depletion cap.", positive=True)
    Cjc = Parameter(0.5e-12, "F", "base-coll. zero bias depletion cap.", positive=True)
    Phie = Parameter(0.8, "V", "base-emitter diffusion voltage", positive=True)
    Me = Parameter(0.4, "1", "base-emitter gradation exponent")
    Phic = Parameter(0.8, "V", "base-collector diffusion voltage", positive=True)
    Mc = Parameter(0.333, "1", "base-collector gradation exponent")
    Gbc = Parameter(1e-15, "S", "base-collector conductance")
    Gbe = Parameter(1e-15, "S", "base-emitter conductance")
    EMin = Parameter(-100.0, "1", "if x < EMin, the exp(x) function is linearized")
    EMax = Parameter(40.0, "1", "if x > EMax, the exp(x) function is linearized")
    Vt = Parameter(0.02585, "V", "voltage equivalent of temperature", positive=True)
    Tnom = Parameter(300.15, "K", "parameter measurement temperature", positive=True)
    XTI = Parameter(3.0, "1", "temperature exponent for effect on Is")
    XTB = Parameter(0.0, "1", "forward and reverse beta temperature exponent")
    EG = Parameter(1.11, "V", "energy gap for temperature effect on Is")
    NF = Parameter(1.0, "1", "forward current emission coefficient", positive=True)
    NR = Parameter(1.0, "1", "reverse current emission coefficient", positive=True)
    IC = Parameter(0.0, "V", "initial value of collector to substrate voltage")
    T = Parameter(293.15, "K", "fixed device temperature if useHeatPort = false",
                  positive=True)
    C = Pin("collector")
    B = Pin("base")
    E = Pin("emitter")
    S = ConditionalPort(NegativePin("substrate", required=True), "useSubstrate")
    _s: int

    def __init__(self, name: str | None = None, **params):
        params.setdefault("useHeatPort", params.get("useTemperatureDependency", False))
        super().__init__(name, **params)

    def structure(self, s):
        jc, je = self._junctions
        for name, text in ((f"v{jc}", "junction voltage " + jc),
                           (f"v{je}", "junction voltage " + je),
                           ("vcs", "collector-substrate voltage")):
            s.state(name, 0.0, "V", text)

    @property
    def _junctions(self) -> tuple[str, str]:
        """MSL's names of the collector and emitter junction voltages (vbc, vbe or vcb, veb)
        without the v."""
        return ("bc", "be") if self._s > 0 else ("cb", "eb")

    def physics(self, e):
        sign, (jc, je) = self._s, self._junctions
        vjc, vje, vcs = e.state("v" + jc), e.state("v" + je), e.state("vcs")
        vB, vC, vE = (e.potential(p) for p in (self.B, self.C, self.E))
        vS = e.potential(self.S) if self.useSubstrate else 0.0
        e.residual(vjc - sign * (vB - vC))
        e.residual(vje - sign * (vB - vE))
        e.residual(vcs - (vC - vS))
        T = self._T_heatPort(e)
        e.assertion(T > 0, "Temperature must be positive")
        ratio = T / self.Tnom
        if self.useTemperatureDependency:
            vt_t = K_BOLTZMANN / Q_ELECTRON * T
            hexp = (ratio - 1) * self.EG / vt_t
            is_t = self.Is * ratio ** self.XTI * exlin2(hexp, self.EMin, self.EMax)
            br_t, bf_t = self.Br * ratio ** self.XTB, self.Bf * ratio ** self.XTB
        else:
            vt_t, is_t, br_t, bf_t = self.Vt, self.Is, self.Br, self.Bf
        ec = exlin2(vjc / (self.NR * vt_t), self.EMin, self.EMax)
        ee = exlin2(vje / (self.NF * vt_t), self.EMin, self.EMax)
        ijc = is_t * (ec - 1) + vjc * self.Gbc
        ije = is_t * (ee - 1) + vje * self.Gbe
        cjc = (self.Taur * is_t / (self.NR * vt_t) * ec
               + self.Cjc * powlin(vjc / self.Phic, self.Mc))
        cje = (self.Tauf * is_t / (self.NF * vt_t) * ee
               + self.Cje * powlin(vje / self.Phie, self.Me))
        qbk = 1 - vjc * self.Vak
        # the pin currents are the unknowns (as a capacitor's current), the capacitive
        # currents follow from them by MSL's equations: i_ccs = Ccs·der(vcs) = −iS, ...
        iB, iC, iE = (e.flow_of(p) for p in (self.B, self.C, self.E))
        i_ccs = iB + iC + iE
        i_cjc = (ije - ijc) * qbk - ijc / br_t + sign * (i_ccs - iC)
        i_cje = sign * iB - ije / bf_t - ijc / br_t - i_cjc
        e.derivative(vjc, i_cjc / cjc)
        e.derivative(vje, i_cje / cje)
        e.derivative(vcs, i_ccs / self.Ccs)
        iS = -i_ccs
        if self.useSubstrate:
            e.flow(self.S, iS)
        if self.UIC:
            e.initial(vcs - self.IC, "vcs = IC (UIC = true)")
        for name, value, unit, text in (
                ("qbk", qbk, "1", "relative majority carrier charge, inverse"),
                ("i" + jc, ijc, "A", "collector junction diode current"),
                ("i" + je, ije, "A", "emitter junction diode current"),
                ("c" + jc, cjc, "F", "total collector junction capacitance"),
                ("c" + je, cje, "F", "total emitter junction capacitance"),
                ("is_t", is_t, "A", "temperature dependent transport saturation current"),
                ("br_t", br_t, "1", "temperature dependent reverse beta"),
                ("bf_t", bf_t, "1", "temperature dependent forward beta"),
                ("vt_t", vt_t, "V", "voltage equivalent of effective temperature"),
                ("iS", iS, "A", "substrate current")):
            e.variable(name, value, unit, text)
        loss = (vjc * ijc / br_t + vje * ije / bf_t
                + sign * (ije - ijc) * qbk * (vC - vE))
        self._losses(e, loss, T)


class NPN(_BipolarTransistor):
    """Simple NPN bipolar transistor according to Ebers–Moll with heating port (MSL
    Semiconductors.NPN): ``_BipolarTransistor`` with vbc = B.v − C.v, vbe = B.v − E.v [V]
    (states), the diode currents ibc, ibe [A] and capacitances cbc, cbe [F]: C.i = (ibe −
    ibc)·qbk − ibc/br_t − cbc·der(vbc) − iS, B.i = ibe/bf_t + ibc/br_t + cbc·der(vbc) +
    cbe·der(vbe) [A]; so a forward-biased base-emitter junction draws the collector current
    Bf times the base current (less the Early effect qbk)."""
    _s = 1


class PNP(_BipolarTransistor):
    """Simple PNP bipolar transistor according to Ebers–Moll with heating port (MSL
    Semiconductors.PNP): ``_BipolarTransistor`` with vcb = C.v − B.v, veb = E.v − B.v [V]
    (states), icb, ieb [A], ccb, ceb [F]: C.i = icb/br_t + ccb·der(vcb) + (icb − ieb)·qbk −
    iS, B.i = −ieb/bf_t − icb/br_t − ceb·der(veb) − ccb·der(vcb) [A]: the NPN's laws with
    every voltage and current reversed."""
    _s = -1


class _MOS(_ConditionalHeatPort):
    """MSL's NMOS and PMOS (simple Shichman–Hodges MOSFETs with heating port, no
    capacitances), one model with the polarity ``_s`` (+1 NMOS, −1 PMOS): with every
    potential multiplied by s (and the threshold vt_t by s), the NMOS law

        ud, us = max(D.v, S.v), min(D.v, S.v),  uds = ud − us,  ubs = min(B.v − us, 0),
        ugst = (G.v − us − vt_t + k2_t·ubs)·K5,  v = beta_t·(W + dW)/(L + dL),
        id = uds·gds                            if ugst ≤ 0 (cut off),
             v·uds·(ugst − uds/2) + uds·gds     if ugst > uds (linear region),
             v·ugst²/2 + uds·gds                otherwise (saturation),
        D.i = −id if D.v < S.v else id,  S.i = −D.i,  G.i = B.i = 0,

    and the currents multiplied by s: MSL's PMOS equations exactly (its mirrored
    comparisons and signs). gds = 1/RDS [S] (1e20 for |RDS| < 1e-20). With
    useTemperatureDependency (useHeatPort defaults to it): beta_t = Beta·(T/Tnom)^−1.5,
    vt_t = Vt·(1 + (T − Tnom)·kvt), k2_t = K2·(1 + (T − Tnom)·kk2), T = T_heatPort;
    otherwise Beta, Vt, K2. LossPower = D.i·(D.v − S.v) [W]. The law is continuous (MSL's
    smooth(0, ...)); its kinks are integrated across, no events. L + dL > 0 and W + dW > 0
    are checked at construction (and asserted while simulating). Records id, ugst, uds,
    ubs."""
    options = {"useTemperatureDependency": False, "useHeatPort": False}
    W = Parameter(20e-6, "m", "width")
    L = Parameter(6e-6, "m", "length")
    Beta: Parameter
    Vt: Parameter
    K2: Parameter
    K5: Parameter
    dW = Parameter(-2.5e-6, "m", "narrowing of channel")
    dL: Parameter
    RDS = Parameter(1e7, "Ohm", "drain-source-resistance")
    Tnom = Parameter(300.15, "K", "parameter measurement temperature", positive=True)
    kvt: Parameter
    kk2: Parameter
    T = Parameter(293.15, "K", "fixed device temperature if useHeatPort = false",
                  positive=True)
    D = Pin("drain")
    G = Pin("gate")
    S = Pin("source")
    B = Pin("bulk")
    _s: int

    def __init__(self, name: str | None = None, **params):
        params.setdefault("useHeatPort", params.get("useTemperatureDependency", False))
        super().__init__(name, **params)
        for size, text in (("L", "length"), ("W", "width")):
            value, change = getattr(self, size), getattr(self, "d" + size)
            if not value + change > 0:
                raise ParameterError(f"{who(self)}: the effective {text} {size} + d{size} = "
                                     f"{value:g} + {change:g} m must be positive")

    def physics(self, e):
        sign = self._s
        vD, vG, vS, vB = (sign * e.potential(p) for p in (self.D, self.G, self.S, self.B))
        T = self._T_heatPort(e)
        e.assertion(self.L + self.dL > 0, "Effective length must be positive")
        e.assertion(self.W + self.dW > 0, "Effective width must be positive")
        e.assertion(T > 0, "Temperature must be positive")
        if self.useTemperatureDependency:
            beta_t = self.Beta * (T / self.Tnom) ** -1.5
            vt_t = self.Vt * (1 + (T - self.Tnom) * self.kvt)
            k2_t = self.K2 * (1 + (T - self.Tnom) * self.kk2)
        else:
            beta_t, vt_t, k2_t = self.Beta, self.Vt, self.K2
        gds = ca.if_else(ca.fabs(self.RDS) < 1e-20, 1e20, 1 / self.RDS)
        v = beta_t * (self.W + self.dW) / (self.L + self.dL)
        reverse = vD < vS
        ud, us = ca.fmax(vD, vS), ca.fmin(vD, vS)
        uds = ud - us
        ubs = ca.fmin(vB - us, 0)
        ugst = (vG - us - sign * vt_t + k2_t * ubs) * self.K5
        i_d = ca.if_else(ugst <= 0, uds * gds, ca.if_else(
            ugst > uds, v * uds * (ugst - uds / 2) + uds * gds, v * ugst * ugst / 2 + uds * gds))
        iD = sign * ca.if_else(reverse, -i_d, i_d)
        e.flow(self.D, iD)
        e.flow(self.S, -iD)
        e.flow(self.G, 0.0)
        e.flow(self.B, 0.0)
        for name, value, text in (("id", sign * i_d, "drain current (from the higher to the "
                                                     "lower of drain and source)"),
                                  ("ugst", sign * ugst, "effective gate voltage"),
                                  ("uds", sign * uds, "drain-source voltage"),
                                  ("ubs", sign * ubs, "bulk-source voltage")):
            e.variable(name, value, "A" if name == "id" else "V", text)
        self._losses(e, iD * (e.potential(self.D) - e.potential(self.S)), T)


class NMOS(_MOS):
    """Simple n-channel MOSFET with heating port (MSL Semiconductors.NMOS), Shichman–Hodges
    without capacitances: ``_MOS`` with the NMOS's parameters; D.i > 0 flows from drain to
    source when G.v exceeds the source by more than the threshold Vt (0.8 V)."""
    Beta = Parameter(0.041e-3, "A/V2", "transconductance parameter")
    Vt = Parameter(0.8, "V", "zero bias threshold voltage")
    K2 = Parameter(1.144, "1", "bulk threshold parameter")
    K5 = Parameter(0.7311, "1", "reduction of pinch-off region")
    dL = Parameter(-1.5e-6, "m", "shortening of channel")
    kvt = Parameter(-6.96e-3, "1/K", "fitting parameter for Vt")
    kk2 = Parameter(6e-4, "1/K", "fitting parameter for K2")
    _s = 1


class PMOS(_MOS):
    """Simple p-channel MOSFET with heating port (MSL Semiconductors.PMOS), Shichman–Hodges
    without capacitances: ``_MOS`` with the PMOS's parameters; current flows from source
    to drain (D.i < 0) when G.v lies below the source by more than |Vt| (Vt = −1 V)."""
    Beta = Parameter(0.0105e-3, "A/V2", "transconductance parameter")
    Vt = Parameter(-1.0, "V", "zero bias threshold voltage")
    K2 = Parameter(0.41, "1", "bulk threshold parameter")
    K5 = Parameter(0.839, "1", "reduction of pinch-off region")
    dL = Parameter(-2.1e-6, "m", "shortening of channel")
    kvt = Parameter(-2.9e-3, "1/K", "fitting parameter for Vt")
    kk2 = Parameter(6.2e-4, "1/K", "fitting parameter for K2")
    _s = -1
