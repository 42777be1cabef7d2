/* State events and discrete modes (see events.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "instance.h"
#include "model_functions.h"

double ac_side(double g, double before) { return g > 0 ? 1.0 : g < 0 ? -1.0 : before; }

double ac_reported(double g, double side) { return g + (side < 0 ? -AC_HYSTERESIS : AC_HYSTERESIS); }

int ac_indicators_at(ac_inst *m, double t, const double *x, double *z, double *g) {
#if AC_NG > 0
    double *out[1] = {g};
    int i;
    if (ac_solve_z(m, t, x, z)) return AC_ERROR;
    if (ac_eval(m, (ac_fn)ac_ind, t, x, z, out, 1)) return ERR("evaluating the event indicators failed");
    for (i = 0; i < AC_NG; i++)
        if (!isfinite(g[i])) return ERR("the event indicator '%s' is not finite at t = %g", AC_G_NAMES[i], t);
#else
    (void)m; (void)t; (void)x; (void)z; (void)g;
#endif
    return AC_OK;
}

/* g at the instance's own point */
static int here(ac_inst *m, double *g) {
    if (ac_ensure_z(m)) return AC_ERROR;
    return ac_indicators_at(m, m->d.t, m->d.x, m->d.z, g);
}

/* whether crossings in directions `dir` (0: not crossed) change nothing: no modes, no reinit
 * of these indicators in these directions (events.py's _inert) */
static int inert(const int *dir) {
    int j;
    if (AC_NMODE > 0) return 0;
    for (j = 0; j < AC_NREINIT; j++) {
        int d = dir[AC_RE_IND[j]];
        if (d && (AC_RE_DIR[j] == 0 || AC_RE_DIR[j] == d)) return 0;
    }
    return 1;
}

int ac_crossing(ac_inst *m, const double *g) {
    int dir[AC_D(AC_NG)], i, any = 0;
    for (i = 0; i < AC_NG; i++) {
        double s = ac_side(ac_reported(g[i], m->d.sides[i]), m->d.sides[i]);
        dir[i] = s != m->d.sides[i] ? (int)s : 0;
        any |= dir[i] != 0;
    }
    if (!any) return 0;
    if (!inert(dir)) return 1;
    for (i = 0; i < AC_NG; i++) m->d.sides[i] = ac_side(ac_reported(g[i], m->d.sides[i]), m->d.sides[i]);
    return 0;
}

int ac_event_indicators(ac_inst *m, double *g, size_t n) {
    int i;
    if (n != AC_NG) return ERR("expected %d event indicators, got %d", AC_NG, (int)n);
    if (AC_NG == 0) return AC_OK;
    if (here(m, g)) return AC_ERROR;
    for (i = 0; i < AC_NG; i++) {    /* an exact zero is on the side it was on */
        g[i] = ac_reported(g[i], m->d.sides[i]);
        if (g[i] == 0.0) g[i] = (m->d.sides[i] < 0 ? -1.0 : 1.0) * 1e-300;
    }
    return AC_OK;
}

int ac_step_crossed(ac_inst *m) {
    double g[AC_D(AC_NG)];
    if (AC_NG == 0 || here(m, g)) return 0;   /* a failed evaluation shows in the next call */
    return ac_crossing(m, g);
}

#if AC_NMODE > 0
/* every mode declared with values has one of them (events.py's _check_values); only the
   event iteration of a model with modes calls it */
static int check_values(ac_inst *m) {
    int k, j;
    for (k = 0; k < AC_NMODE; k++) {
        double v = m->d.p[AC_MODE_P[k]];
        int ok = AC_MODE_FIRST[k] == AC_MODE_FIRST[k + 1];
        for (j = AC_MODE_FIRST[k]; j < AC_MODE_FIRST[k + 1]; j++) ok |= v == AC_MODE_VALUES[j];
        if (!ok) return ERR("at t = %g s the mode_update of '%s' gives %s = %g, not one of its "
                            "values", m->d.t, AC_MODE_OWNER[k], AC_MODE_NAMES[k], v);
    }
    return AC_OK;
}
#endif

/* the event iteration at the instance's point (events.py's iterate) */
static int iterate(ac_inst *m, int *changed) {
#if AC_NMODE > 0
    double next[AC_NMODE], re[AC_D(AC_NREINIT)];
    double *out[2] = {next, re};
    unsigned char moving[AC_NMODE];
    int it, k;
    memset(moving, 0, sizeof(moving));
    for (it = 0; it < AC_EVENT_ITERATIONS; it++) {
        int diff = 0;
        if (ac_ensure_z(m)) return AC_ERROR;
        if (ac_eval(m, (ac_fn)ac_upd, m->d.t, m->d.x, m->d.z, out, 2))
            return ERR("evaluating the modes' updates failed");
        for (k = 0; k < AC_NMODE; k++) {
            double v = AC_MODE_INT[k] ? round(next[k]) : next[k];   /* discrete Reals: as they are */
            if (!isfinite(v)) return ERR("the mode_update of '%s' is not finite at t = %g", AC_MODE_OWNER[k], m->d.t);
            if (v != m->d.p[AC_MODE_P[k]]) { m->d.p[AC_MODE_P[k]] = v; moving[k] = 1; diff = 1; }
        }
        if (!diff) return check_values(m);
        *changed = 1;
        ac_invalidate(m);
    }
    {   /* the owners of the modes that kept changing, each once */
        char names[512] = "";
        for (k = 0; k < AC_NMODE; k++) {
            int j, seen = 0;
            if (!moving[k]) continue;
            for (j = 0; j < k; j++) if (moving[j] && !strcmp(AC_MODE_OWNER[j], AC_MODE_OWNER[k])) seen = 1;
            if (seen) continue;
            if (names[0]) strncat(names, ", ", sizeof(names) - strlen(names) - 1);
            strncat(names, AC_MODE_OWNER[k], sizeof(names) - strlen(names) - 1);
        }
        return ERR("event iteration at t = %g s does not settle: the modes of %s keep changing "
                   "(%d rounds); check their mode_update for a cycle", m->d.t, names,
                   AC_EVENT_ITERATIONS);
    }
#else
    (void)m; (void)changed;
    return AC_OK;
#endif
}

/* the sample triggers that tick at the instance's time (events.py's `ticking`): at the start
 * those declared `initial` (whatever the time); later those with an instant first + k·period
 * (k >= 0, the numbers ac_events reports as time events) within AC_EVENT_TOL·max(1, |t|) s,
 * the tolerance of events.py's `instant`, once per instant (an importer may run the event
 * update twice at one time: a UnitDelay would shift twice). An instant passed since the
 * trigger last ticked is an error: the importer stepped over a time event (nextEventTime),
 * and the sample would be lost */
static int ticking(ac_inst *m, int start, unsigned char *tick, int *any) {
#if AC_NCLOCK > 0
    double cl[2 * AC_NCLOCK], t = m->d.t, tol = AC_EVENT_TOL * (fabs(t) > 1 ? fabs(t) : 1);
    int c;
    if (ac_eval_p(m, (ac_fn)ac_clocks, cl)) return ERR("evaluating the sample instants failed");
    for (c = 0; c < AC_NCLOCK; c++) {
        double first = cl[c], period = cl[AC_NCLOCK + c], k, last;
        if (!(period > 0) || !isfinite(period) || !isfinite(first))
            return ERR("the sample period of '%s' must be > 0 s, got %g (first instant %g s)",
                       AC_MODE_OWNER[AC_CLOCK_MODE[c]], period, first);
        if (start) {
            tick[c] = AC_CLOCK_INITIAL[c] != 0;
            m->d.last_tick[c] = t;
        } else {
            k = floor((t + tol - first) / period);       /* the last instant up to t */
            last = first + k * period;
            tick[c] = k >= 0 && last > m->d.last_tick[c] + tol;
            if (tick[c] && last < t - tol)
                return ERR("the sample instant t = %.17g s of '%s' was passed without an event "
                           "at it (the FMU is at t = %.17g s): an importer must stop at "
                           "nextEventTime", last, AC_MODE_OWNER[AC_CLOCK_MODE[c]], t);
            if (tick[c]) m->d.last_tick[c] = t;
        }
        *any |= tick[c];
    }
#else
    (void)m; (void)start; (void)tick; (void)any;
#endif
    return AC_OK;
}

/* the ticking triggers set to `value` (1: through the event iteration, then 0) */
static void set_triggers(ac_inst *m, const unsigned char *tick, double value) {
#if AC_NCLOCK > 0
    int c;
    for (c = 0; c < AC_NCLOCK; c++) if (tick[c]) m->d.p[AC_MODE_P[AC_CLOCK_MODE[c]]] = value;
    ac_invalidate(m);
#else
    (void)m; (void)tick; (void)value;
#endif
}

/* the crossed indicators `dir` logged at the instance's time; chattering is an error */
static int chattering(ac_inst *m, const int *dir) {
    int i, k, n = AC_CHATTER_EVENTS, oldest, worst = 0, hits[AC_D(AC_NG)];
    for (i = 0; i < AC_NG; i++) {
        if (!dir[i]) continue;
        m->d.recent_t[m->d.n_recent % n] = m->d.t;
        m->d.recent_g[m->d.n_recent % n] = i;
        m->d.n_recent++;
    }
    if (m->d.n_recent < n) return AC_OK;
    oldest = m->d.n_recent % n;        /* the ring is full: the next slot is the oldest */
    if (m->d.t - m->d.recent_t[oldest] > AC_CHATTER_SPAN * (fabs(m->d.t) > 1 ? fabs(m->d.t) : 1))
        return AC_OK;
    for (i = 0; i < AC_NG; i++) hits[i] = 0;
    for (k = 0; k < n; k++)            /* by owner: an indicator's hits count for its owner */
        for (i = 0; i < AC_NG; i++)
            if (!strcmp(AC_G_OWNER[i], AC_G_OWNER[m->d.recent_g[k]])) hits[i]++;
    for (i = 1; i < AC_NG; i++) if (hits[i] > hits[worst]) worst = i;
    return ERR("chattering: %d events within %.3g s after t = %.9g s, %d of them of component "
               "'%s': its modes switch back and forth without end (an ideal relay, a sliding "
               "mode, a Zeno accumulation of impacts); give it a mode that holds at the "
               "switching surface (a stuck mode) or end the simulation before", n,
               m->d.t - m->d.recent_t[oldest], m->d.recent_t[oldest], hits[worst],
               AC_G_OWNER[worst]);
}

int ac_state_event(ac_inst *m, int start, int *changed) {
    double g[AC_D(AC_NG)], after[AC_D(AC_NG)];
    int dir[AC_D(AC_NG)], i, j, any = 0, ch = 0, ticks = 0;
    unsigned char tick[AC_D(AC_NCLOCK)];
    if (changed) *changed = 0;
    if (AC_NG == 0 && AC_NMODE == 0) return AC_OK;
    if (ticking(m, start, tick, &ticks)) return AC_ERROR;
    if (here(m, g)) return AC_ERROR;
    for (i = 0; i < AC_NG; i++) {
        double before = start ? 1.0 : m->d.sides[i];
        after[i] = ac_side(ac_reported(g[i], before), before);
        dir[i] = !start && after[i] != m->d.sides[i] ? (int)after[i] : 0;
        any |= dir[i] != 0;
    }
    if (any && chattering(m, dir)) return AC_ERROR;
    if (any && AC_NREINIT > 0) {      /* the reinits of the crossed indicators, at the left limit */
        double modes[AC_D(AC_NMODE)], re[AC_D(AC_NREINIT)];
        double *out[2] = {modes, re};
        int reinit = 0;
        if (ac_eval(m, (ac_fn)ac_upd, m->d.t, m->d.x, m->d.z, out, 2))
            return ERR("evaluating the reinits failed");
        for (j = 0; j < AC_NREINIT; j++) {
            int d = dir[AC_RE_IND[j]];
            if (d && (AC_RE_DIR[j] == 0 || AC_RE_DIR[j] == d)) {
                if (!isfinite(re[j])) return ERR("the reinit of '%s' at the event of '%s' is not finite",
                                                 AC_X_NAMES[AC_RE_STATE[j]], AC_G_NAMES[AC_RE_IND[j]]);
                m->d.x[AC_RE_STATE[j]] = re[j];
                reinit = 1;
            }
        }
        if (reinit) {
            ch = 1;
            ac_invalidate(m);
            if (ac_keep_loops_closed(m, 1.0, NULL)) return AC_ERROR;
        }
    }
    /* at a sample instant the triggers are true through the event iteration, so the sampled
     * values (and a chain of them) settle on the values of this instant; then once more
     * with them false, as events.py's `event` */
    if (ticks) set_triggers(m, tick, 1.0);
    if (iterate(m, &ch)) return AC_ERROR;
    if (ticks) {
        set_triggers(m, tick, 0.0);
        if (iterate(m, &ch)) return AC_ERROR;
    }
    if (here(m, g)) return AC_ERROR;          /* the sides at the right limit */
    for (i = 0; i < AC_NG; i++) m->d.sides[i] = ac_side(ac_reported(g[i], after[i]), after[i]);
    if (changed) *changed = ch;
    return AC_OK;
}

int ac_termination(ac_inst *m, int *terminate) {
#if AC_NTERM > 0
    double held[AC_NTERM], *out[1] = {held};
    int i;
    *terminate = 0;
    if (ac_ensure_z(m)) return AC_ERROR;
    if (ac_eval(m, (ac_fn)ac_term, m->d.t, m->d.x, m->d.z, out, 1))
        return ERR("evaluating the termination conditions failed");
    for (i = 0; i < AC_NTERM; i++)
        if (held[i] > 0.5) {
            m->d.terminated = *terminate = 1;
            ac_notef(m, "logEvents", "terminated at t = %.12g s by '%s': %s", m->d.t,
                     AC_TERM_OWNER[i], AC_TERM_TEXT[i]);
            return AC_OK;
        }
#else
    (void)m;
    *terminate = 0;
#endif
    return AC_OK;
}

int ac_check_assertions(ac_inst *m) {
#if AC_NASSERT > 0
    double held[AC_NASSERT], *out[1] = {held};
    int i;
    if (ac_ensure_z(m)) return AC_ERROR;
    if (ac_eval(m, (ac_fn)ac_assert, m->d.t, m->d.x, m->d.z, out, 1))
        return ERR("evaluating the assertions failed");
    for (i = 0; i < AC_NASSERT; i++)
        if (!(held[i] > 0.5))
            return ERR("'%s': %s (assertion failed at t = %.6g s)", AC_ASSERT_OWNER[i],
                       AC_ASSERT_TEXT[i], m->d.t);
#else
    (void)m;
#endif
    return AC_OK;
}
