"""Coulomb friction with stuck and sliding modes, shared by the translational and rotational
libraries, after MSL 4.1's ``Rotational.Interfaces.PartialFriction`` and
``Translational.Interfaces.PartialFriction``; written once over the domain's ``Axis``
(rotational names below, translational ones in brackets: v_relfric, f0, f0_max, v_small).

The mode machine is MSL's, with MSL's encoding of ``mode``: Unknown = 3 (the start value),
Free = 2 (the element is not active, e.g. a brake without normal force), Forward = 1
(w_relfric > 0), Stuck = 0, Backward = −1 (w_relfric < 0). On the state-event engine the
friction torque ``tau`` [N.m] (``f`` [N]) is an algebraic variable fixed by the mode:
stuck, a_relfric = 0 (tau is the torque that holds the surfaces together); forward, the
sliding characteristic tau = F(w_relfric); backward, tau = −F(−w_relfric); free, tau = 0.
Events: ``sliding`` (the relative speed falling through 0 while sliding), ``breakaway``
(tau0_max − |tau| falling through 0 while stuck), both setting the relative speed to 0
exactly (the stuck element's speed drifts by the integrator's tolerance otherwise), ``start``
(the relative speed leaving the round-off band W_NOISE around 0 after breaking away: sliding
on in the starting direction, stuck again the other way, see ``start_indicator``), ``fn``
(the normal force crossing 0, for elements that can be free). At every event the modes are updated
as MSL does: a stuck element slides forward when the torque that holds it exceeds tau0_max
(backward below −tau0_max; ``startForward``/``startBackward``, Boolean modes, are set then and
cleared at the next event), a sliding element that reaches w_relfric = 0 (within the
round-off band W_NOISE) keeps sliding only if its acceleration there (with the sliding
friction tau0) keeps its direction or it has just broken away, and sticks otherwise.

Smooth form (``compile(model, smooth=True)``, for gradient-based optimal control): no
modes, no indicators, no reinits, no algebraic variable; the friction torque is the
regularized law

    tau = F(|w_relfric|)·tanh(w_relfric / w_smooth)     (0 when free)

with F the forward sliding characteristic (tau_pos(w), or mu_pos(w)·cgeo·fn) and the
parameter ``w_smooth`` [rad/s] (``v_smooth`` [m/s]) of the element. Its error against the
exact form: (1) an element the exact form holds stuck, loaded by |tau_h| < tau0, creeps at
the speed w_smooth·artanh(|tau_h|/tau0) ≈ w_smooth·|tau_h|/tau0 (for |tau_h| ≪ tau0; e.g. a
block held by half its breakaway force creeps at 0.55·v_smooth); (2) sliding at |w| the
friction differs from F(|w|) by F·(1 − tanh(|w|/w_smooth)) ≤ 2·F·exp(−2|w|/w_smooth), i.e.
< 1e-3·F beyond |w| > 3.8·w_smooth; (3) there is no stiction peak: the smooth form breaks
away at tau0, not at tau0_max = peak·tau0 (the same for MSL's default peak = 1). Recorded
as in the exact form, without the modes: tau (f), w_relfric, a_relfric, tau0, tau0_max,
free, lossPower (and fn, mu of a normal-force element; mu = mu_pos(|w|)·tanh(w/w_smooth)).
No complementarity form yet (the friction torque as a bounded decision variable of an OCP
with complementarity constraints): it needs the builder to expose a component's force to
the transcription.

The characteristic tables (``tau_pos``, ``f_pos``, ``mu_pos``: rows [speed ≥ 0, value]) are
interpolated linearly and extrapolated through the last two rows (MSL's CombiTable1D with
Smoothness.LinearSegments and Extrapolation.LastTwoPoints, the only smoothness here).
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..core import Parameter
from ..errors import ParameterError
from .interfaces import Axis, PartialElementaryConditionalHeatPortWithoutT

UNKNOWN, FREE, FORWARD, STUCK, BACKWARD = 3, 2, 1, 0, -1
MODES = (BACKWARD, STUCK, FORWARD, FREE, UNKNOWN)
#: [rad/s, m/s] how far the relative speed must leave 0 to clear startForward/startBackward:
#: above the round-off a speed set to 0 drifts by while other elements hold the motion
W_NOISE = 1e-10


def start_indicator(e, w, starting, unit: str, speed: str) -> None:
    """The indicator ``start`` of an element that has just broken away (startForward or
    startBackward, ``starting``): W_NOISE − |w|, w its relative speed, falling through 0
    when w leaves the round-off band [−W_NOISE, W_NOISE] around 0, either way (1 otherwise).

    At breakaway the sliding acceleration is ~0 (peak = 1: the holding torque has just
    reached tau0_max = tau0), so the speed decides, as MSL's relations on w_relfric do: out
    of the band in the starting direction the element slides; back out of it on the other
    side the acceleration reversed before the element got going (the holding torque fell
    below tau0 again: MSL's ``pre(startForward) and sa > tau0`` turning false), and it
    sticks again, its speed left at the band's edge (as MSL leaves it: no reinit). While
    starting the element's sliding indicator is off: read as sliding, w dipping below 0 was
    a sliding element reaching w = 0, reinit to 0 and kept sliding by startForward, again
    and again (chattering)."""
    e.indicator("start", ca.if_else(starting, W_NOISE - ca.fabs(w), 1.0), unit,
                f"W_NOISE - |relative {speed}| after breaking away (leaving the round-off "
                f"band around 0)")


def direction(w):
    """The mode an element that engages (from Free or Unknown) takes from its relative speed
    w: FORWARD beyond W_NOISE, BACKWARD below −W_NOISE, STUCK within the round-off band
    (MSL: the sign of w_relfric; here parts at rest have speeds of round-off, ~1e-30, whose
    sign is noise: a clutch engaging between shafts at rest would slide either way)."""
    return ca.if_else(w > W_NOISE, FORWARD, ca.if_else(w < -W_NOISE, BACKWARD, STUCK))


def still_starting(start, w):
    """Whether a start (startForward or startBackward, pre-value ``start``) goes on: the
    relative speed w is still within the round-off band W_NOISE around 0."""
    return ca.logic_and(start, ca.fabs(w) <= W_NOISE)


def check_table(table, name: str, where: str) -> np.ndarray:
    """A characteristic table as an (n, 2) float array with n ≥ 1 and strictly increasing,
    nonnegative speeds in the first column, or a ParameterError naming ``where.name``."""
    try:
        tab = np.array(table, dtype=float).reshape(-1, 2) if np.size(table) % 2 == 0 \
            else None
    except (TypeError, ValueError):
        tab = None
    if tab is None or tab.shape[0] < 1 or not np.all(np.isfinite(tab)):
        raise ParameterError(f"parameter '{where}.{name}' must be a table of rows "
                             f"[speed, value] (finite numbers), got {table!r}")
    if tab[0, 0] < 0 or np.any(np.diff(tab[:, 0]) <= 0):
        raise ParameterError(f"parameter '{where}.{name}': its first column (the speed, >= 0) "
                             f"must be strictly increasing from a value >= 0, got "
                             f"{tab[:, 0].tolist()}")
    return tab


def table_value(tab: np.ndarray, x):
    """Linear interpolation in ``tab`` at x, extrapolated through the first or last two rows
    (MSL's CombiTable1D, LinearSegments, LastTwoPoints); a one-row table is constant."""
    if tab.shape[0] == 1:
        return ca.SX(tab[0, 1]) + 0 * x
    slopes = np.diff(tab[:, 1]) / np.diff(tab[:, 0])
    y = tab[0, 1] + slopes[0] * (x - tab[0, 0])
    for k in range(1, len(slopes)):
        y += (slopes[k] - slopes[k - 1]) * ca.fmax(x - tab[k, 0], 0.0)
    return y


class PartialFriction(PartialElementaryConditionalHeatPortWithoutT):
    """Coulomb friction between two surfaces with MSL's mode machine (see the module).

    A subclass names its table (``table_name``, a constructor keyword with MSL's default
    ``table_default``) and gives: ``_relfric(e)`` the relative speed and acceleration of the
    surfaces; ``_sliding(e, w)`` the forward sliding friction at speed w ≥ 0 (tau_pos(w), or
    mu_pos(w)·cgeo·fn); ``_free(e)`` whether the element is inactive (an expression, or None:
    never); ``_apply(e, tau)`` the flows; ``_stop(e)`` the state its relative speed is and
    the value that makes it 0 (reinit when it sticks); ``_can_slide(e)`` whether it may slide
    forward and backward (default: both; a hard stop blocks one direction). Records
    w_relfric, a_relfric, tau0, tau0_max, free, sa, locked, startForward, startBackward,
    lossPower [W] and the mode.
    The domain declares ``w_small`` (``v_small``) and ``w_smooth`` (``v_smooth``), the speed
    of the smooth form's regularization (see the module); a subclass that gives only these
    hooks has the smooth form too.
    """
    partial = True
    axis: Axis
    table_name = ""
    table_default = ((0.0, 1.0),)
    peak = Parameter(1.0, "1", "peak for maximum friction at w == 0 (tau0_max = peak*tau0)")

    def __init__(self, name: str | None = None, **params):
        table = params.pop(self.table_name, self.table_default)
        super().__init__(name, **params)
        kind = type(self).__name__
        if self.peak < 1:
            raise ParameterError(f"parameter '{kind}.peak' must be >= 1 (MSL: min = 1), got "
                                 f"{self.peak}")
        self.__dict__["table"] = check_table(table, self.table_name, kind)

    def _small(self):
        """MSL's w_small [rad/s] (v_small [m/s])."""
        return getattr(self, f"{self.axis.v}_small")

    # ---- what a subclass gives -----------------------------------------------------------
    def _relfric(self, e):
        raise NotImplementedError

    def _sliding(self, e, w):
        raise NotImplementedError

    def _free(self, e):
        return None

    def _apply(self, e, tau) -> None:
        raise NotImplementedError

    def _stop(self, e):
        raise NotImplementedError

    def _can_slide(self, e):
        """(forward, backward): whether the element may slide that way (expressions)."""
        return True, True

    # ---- the mode machine ----------------------------------------------------------------
    def structure(self, s):
        if s.smooth:                # no modes, no algebraic: tau is the regularized law
            return
        x = self.axis
        s.mode("mode", UNKNOWN, values=MODES,
               description="mode of friction (-1: backward sliding, 0: stuck, 1: forward "
                           "sliding, 2: inactive, 3: unknown)")
        s.mode("startForward", 0, values=(0, 1),
               description=f"= true, if {x.v}_relfric=0 and start of forward sliding")
        s.mode("startBackward", 0, values=(0, 1),
               description=f"= true, if {x.v}_relfric=0 and start of backward sliding")
        s.algebraic(x.f, unit=x.f_unit, description=f"friction {x.flow}")

    def physics(self, e):
        if e.smooth:
            self._smooth_physics(e)
            return
        x = self.axis
        mode, tau = e.mode("mode"), e.state(x.f)
        start_fwd, start_bwd = e.mode("startForward"), e.mode("startBackward")
        w, a = self._relfric(e)
        tau0 = self._sliding(e, 0.0)
        tau0_max = self.peak * tau0
        free_now = self._free(e)
        free_now = ca.SX(0) if free_now is None else free_now
        # MSL's relation free = fn <= 0 changes at events only: between them the mode says
        # it (an element engaged by a continuous fn stays free until the event at fn = 0)
        free = ca.logic_or(mode == FREE, ca.logic_and(mode == UNKNOWN, free_now))
        fwd = ca.logic_or(mode == FORWARD, start_fwd)
        bwd = ca.logic_or(mode == BACKWARD, start_bwd)
        forward, backward = tau - self._sliding(e, w), tau + self._sliding(e, -w)
        by_sign = ca.if_else(w > 0, forward, ca.if_else(w < 0, backward, a))
        e.residual(ca.if_else(free, tau, ca.if_else(fwd, forward, ca.if_else(
            bwd, backward, ca.if_else(mode == STUCK, a, by_sign)))))
        self._apply(e, tau)

        locked = ca.logic_and(ca.logic_not(free), mode == STUCK)
        starting = ca.logic_or(start_fwd, start_bwd)
        e.indicator("sliding", ca.if_else(starting, 1.0, ca.if_else(fwd, w, ca.if_else(
            bwd, -w, 1.0))), x.v_unit,
            f"relative {x.speed} while sliding (not starting), in its direction")
        e.indicator("breakaway", ca.if_else(locked, tau0_max - ca.fabs(tau), 1.0), x.f_unit,
                    f"{x.f}0_max - |{x.f}| while stuck")
        start_indicator(e, w, starting, x.v_unit, x.speed)
        state, zero = self._stop(e)
        e.reinit(state, zero, when="sliding", direction=-1)
        e.reinit(state, zero, when="breakaway", direction=-1)      # at rest exactly

        # startForward: broken away from stuck (the torque that held it beyond tau0_max),
        # kept while w_relfric stays within W_NOISE of 0 (see start_indicator): forward out
        # of the band it slides, backward out of it the start failed and it sticks again
        small = self._small()
        fwd_ok, bwd_ok = self._can_slide(e)
        breaks_fwd = ca.logic_and(ca.logic_and(mode == STUCK, tau > tau0_max), fwd_ok)
        breaks_bwd = ca.logic_and(ca.logic_and(mode == STUCK, tau < -tau0_max), bwd_ok)
        active = ca.logic_not(free_now)
        e.mode_update(start_fwd, ca.logic_and(active, ca.logic_or(breaks_fwd, ca.logic_and(
            mode == FORWARD, still_starting(start_fwd, w)))))
        e.mode_update(start_bwd, ca.logic_and(active, ca.logic_or(breaks_bwd, ca.logic_and(
            mode == BACKWARD, still_starting(start_bwd, w)))))
        sign_w = direction(w)
        from_stuck = ca.if_else(breaks_fwd, FORWARD, ca.if_else(breaks_bwd, BACKWARD, STUCK))
        # w within the round-off band counts as 0: a reinit of a speed that is a combination
        # of states (a clutch on a planetary's ring) leaves it at ~1e-16, not 0
        at_rest = ca.fabs(w) <= W_NOISE
        keeps_forward = ca.logic_and(fwd_ok, ca.logic_or(ca.logic_or(w > W_NOISE, start_fwd),
                                                         ca.logic_and(at_rest, a > 0)))
        keeps_backward = ca.logic_and(bwd_ok, ca.logic_or(ca.logic_or(w < -W_NOISE, start_bwd),
                                                          ca.logic_and(at_rest, a < 0)))
        from_forward = ca.if_else(keeps_forward, FORWARD, ca.if_else(w < -small, BACKWARD,
                                                                      STUCK))
        from_backward = ca.if_else(keeps_backward, BACKWARD, ca.if_else(w > small, FORWARD,
                                                                         STUCK))
        e.mode_update(mode, ca.if_else(free_now, FREE, ca.if_else(
            mode == STUCK, from_stuck, ca.if_else(mode == FORWARD, from_forward, ca.if_else(
                mode == BACKWARD, from_backward, sign_w)))))

        self._record(e, w, a, tau0, tau0_max, free, tau)
        e.variable("locked", locked, "", f"= true, if {x.v}_relfric=0 and not sliding")
        e.variable("sa", ca.if_else(locked, tau, ca.if_else(free, a, ca.if_else(
            fwd, a + tau0_max, ca.if_else(bwd, a - tau0_max, a)))),
            "1", f"path parameter of friction characteristic {x.f} = f(a_relfric)")

    # ---- the smooth form -----------------------------------------------------------------
    def _smooth_physics(self, e):
        """tau = F(|w_relfric|)·tanh(w_relfric/w_smooth), 0 when free (see the class)."""
        x = self.axis
        w, a = self._relfric(e)
        tau0 = self._sliding(e, 0.0)
        free = self._free(e)
        law = self._sliding(e, ca.fabs(w)) * self._smooth_sign(w)
        tau = law if free is None else ca.if_else(free, 0.0, law)
        self._apply(e, tau)
        e.variable(x.f, tau, x.f_unit, f"friction {x.flow} (smooth form)")
        self._record(e, w, a, tau0, self.peak * tau0, ca.SX(0) if free is None else free, tau)

    def _smooth_sign(self, w):
        """tanh(w/w_smooth): the smooth form's sign of the relative speed w."""
        return ca.tanh(w / getattr(self, f"{self.axis.v}_smooth"))

    def _record(self, e, w, a, tau0, tau0_max, free, tau):
        """The variables both forms record."""
        x = self.axis
        e.variable(f"{x.v}_relfric", w, x.v_unit,
                   f"relative {x.speed} between frictional surfaces")
        e.variable("a_relfric", a, x.a_unit,
                   f"relative {x.acceleration} between frictional surfaces")
        e.variable(f"{x.f}0", tau0, x.f_unit,
                   f"friction {x.flow} for {x.v}_relfric=0 and forward sliding")
        e.variable(f"{x.f}0_max", tau0_max, x.f_unit,
                   f"maximum friction {x.flow} for {x.v}_relfric=0 and locked")
        e.variable("free", free, "", "= true, if frictional element is not active")
        self._loss_power(e, tau * w)


class SupportedFriction(PartialFriction):
    """Friction of the rigidly joined flanges (flange_b = flange_a) against the support
    (MSL's BearingFriction, SupportFriction, Brake): w_relfric = der(flange_a − support);
    flange_a.tau + flange_b.tau = tau, support.tau = −tau. Records phi, w, a (s, v, a)."""
    partial = True

    def structure(self, s):
        s.linear({self.flange_b: 1.0, self.flange_a: -1.0}, 0.0,
                 f"{self.path}: flange_b = flange_a")
        super().structure(s)

    def _relfric(self, e):
        return self._rel_speed(e, self.flange_a), self._rel_acc(e, self.flange_a)

    def _apply(self, e, tau) -> None:
        e.flow(self.flange_a, tau)
        if self.useSupport:
            e.flow(self.support, -tau)

    def _stop(self, e):
        return e.vel(self.flange_a), e.vel(self.support) if self.useSupport else 0.0

    def physics(self, e):
        super().physics(e)
        x = self.axis
        e.variable(x.s, self._rel_position(e, self.flange_a), x.s_unit,
                   f"{x.position} of flange_a and flange_b with respect to support")
        e.variable(x.v, self._rel_speed(e, self.flange_a), x.v_unit,
                   f"{x.speed} of flange_a and flange_b with respect to support")
        e.variable("a", self._rel_acc(e, self.flange_a), x.a_unit,
                   f"{x.acceleration} of flange_a and flange_b with respect to support")


class TableFriction(PartialFriction):
    """The sliding friction is the table itself (tau_pos, f_pos): MSL's BearingFriction and
    SupportFriction."""
    partial = True

    def _sliding(self, e, w):
        return table_value(self.table, w)


class NormalForceFriction(PartialFriction):
    """Friction of a normal force fn = fn_max·f_normalized [N] (input, 0..1) with the
    coefficient mu_pos(w) [1] and the geometry constant cgeo: sliding friction
    mu·cgeo·fn; free (inactive, mode 2) when fn ≤ 0. MSL's Brake and Clutch. Records fn and
    mu (signed as the friction), indicator ``fn``."""
    partial = True
    table_name = "mu_pos"
    table_default = ((0.0, 0.5),)
    cgeo = Parameter(1.0, "1", "geometry constant containing friction distribution "
                               "assumption", nonnegative=True)
    fn_max = Parameter(1.0, "N", "maximum normal force", nonnegative=True)

    def _fn(self, e):
        return self.fn_max * e.input(self.f_normalized)

    def _sliding(self, e, w):
        return table_value(self.table, w) * self.cgeo * self._fn(e)

    def _free(self, e):
        return self._fn(e) <= 0

    def physics(self, e):
        super().physics(e)
        fn = self._fn(e)
        w = self._relfric(e)[0]
        e.variable("fn", fn, "N", "normal force (= fn_max*f_normalized)")
        if e.smooth:
            mu = table_value(self.table, ca.fabs(w)) * self._smooth_sign(w)
        else:
            # positive exactly when engaged (fn > 0): fn = 0 counts as free, so that fn
            # rising from 0 is an event
            e.indicator("fn", ca.if_else(fn > 0, fn, fn - self.fn_max - 1.0), "N",
                        "normal force, below 0 when free (fn <= 0)")
            mu = ca.if_else(e.mode("mode") == BACKWARD, -table_value(self.table, -w),
                            table_value(self.table, w))
        e.variable("mu", mu, "1", "friction coefficient")
