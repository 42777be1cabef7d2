/* The model instance (see instance.h). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "instance.h"
#include "model_functions.h"

/* ---- logging ------------------------------------------------------------------------- */
static void vlogf(ac_inst *m, int status, const char *category, const char *fmt, va_list ap) {
    vsnprintf(m->msg, sizeof(m->msg), fmt, ap);
    m->log(m, status, category, m->msg);
}

void ac_logf(ac_inst *m, int status, const char *category, const char *fmt, ...) {
    va_list ap;
    if (!m->log || (status == AC_OK && !m->logging_on)) return;
    va_start(ap, fmt);
    vlogf(m, status, category, fmt, ap);
    va_end(ap);
}

void ac_notef(ac_inst *m, const char *category, const char *fmt, ...) {
    va_list ap;
    if (!m->log) return;
    va_start(ap, fmt);
    vlogf(m, AC_OK, category, fmt, ap);
    va_end(ap);
}

/* ---- parameters and start values ------------------------------------------------------ */
static int check_param(ac_inst *m, int i, double v) {
    unsigned char f = AC_P_FLAGS[i];
    if (!isfinite(v)) return ERR("parameter '%s' must be a finite number, got %g", AC_P_NAMES[i], v);
    if ((f & 1) && !(v > 0)) return ERR("parameter '%s' must be > 0, got %g", AC_P_NAMES[i], v);
    if ((f & 2) && !(v >= 0)) return ERR("parameter '%s' must be >= 0, got %g", AC_P_NAMES[i], v);
    if ((f & 4) && v == 0) return ERR("parameter '%s' must not be 0", AC_P_NAMES[i]);
    return AC_OK;
}

static int check_params(ac_inst *m) {
    int i;
    for (i = 0; i < AC_NP; i++) if (check_param(m, i, m->d.p[i])) return AC_ERROR;
    return AC_OK;
}

/* start values of the states the importer has not set, from the parameters */
static int update_starts(ac_inst *m) {
    double out[AC_D(AC_NX + AC_NZ)];
    int i;
    if (ac_eval_p(m, (ac_fn)ac_start, out)) return ERR("evaluating the start values failed");
    for (i = 0; i < AC_NX; i++) if (!m->d.x_set[i]) m->d.x[i] = out[i];
    for (i = 0; i < AC_NZ; i++) m->d.z[i] = out[AC_NX + i];
    ac_invalidate(m);
    return AC_OK;
}

/* ---- life cycle ------------------------------------------------------------------------ */
static const char *mode_name(int mode) {
    switch (mode) {
    case AC_INSTANTIATED: return "the instantiated state";
    case AC_INIT: return "initialization mode";
    case AC_EVENT: return "event mode";
    case AC_CONT: return "continuous-time mode";
    case AC_STEP: return "step mode";
    case AC_TERMINATED: return "the terminated state";
    default: return "the error state";
    }
}

int ac_allowed(ac_inst *m, int modes, const char *fn) {
    if (!m) return 0;
    if (m->d.mode & modes) return 1;
    ac_logf(m, AC_ERROR, "logStatusError", "%s is not allowed in %s", fn, mode_name(m->d.mode));
    return 0;
}

int ac_instantiate(ac_inst *m, const char *name, const char *token, int is_cs, int logging_on,
                   ac_log_fn log) {
    m->log = log;
    m->logging_on = logging_on;
    strncpy(m->name, name, sizeof(m->name) - 1);
    if (!token || strcmp(token, ac_guid) != 0) {
        ac_logf(m, AC_ERROR, "logStatusError", "instantiation token (GUID) %s does not match "
                "this FMU's %s", token ? token : "(null)", ac_guid);
        return AC_ERROR;
    }
    m->is_cs = is_cs;
    ac_defaults(m);
    return AC_OK;
}

void ac_defaults(ac_inst *m) {
    int i;
    memset(&m->d, 0, sizeof(m->d));
    for (i = 0; i < AC_NP; i++) m->d.p[i] = AC_P_DEFAULT[i];
    for (i = 0; i < AC_NU; i++) m->d.u[i] = AC_U_START[i];
    m->d.rtol = AC_SOLVER_DEFAULT[0];
    m->d.atol = AC_SOLVER_DEFAULT[1];
    m->d.next_event = HUGE_VAL;
    m->d.mode = AC_INSTANTIATED;
    update_starts(m);
}

int ac_setup(ac_inst *m, int tolerance_defined, double tolerance, double start_time) {
    if (!isfinite(start_time)) return ERR("the start time must be a finite number, got %g", start_time);
    if (tolerance_defined && !(tolerance > 0 && isfinite(tolerance)))
        return ERR("the tolerance must be a finite number > 0, got %g", tolerance);
    if (tolerance_defined && !m->d.rtol_set) m->d.rtol = tolerance;
    if (tolerance_defined && !m->d.atol_set) m->d.atol = 1e-2 * tolerance;
    ac_set_time(m, start_time);
    return AC_OK;
}

static int initialize(ac_inst *m) {
    if (check_params(m)) return AC_ERROR;
    if (update_starts(m)) return AC_ERROR;
    if (ac_consistent_start(m)) return AC_ERROR;
    ac_invalidate(m);
    if (ac_ensure_z(m)) return AC_ERROR;
    if (ac_state_event(m, 1, NULL)) return AC_ERROR;     /* the modes consistent at the start */
    if (ac_derivatives(m, NULL)) return AC_ERROR;
    if (ac_check_assertions(m)) return AC_ERROR;
    m->d.next_event = ac_next_event(m, m->d.t);
    m->d.t_start = m->d.t;
    m->d.initialized = 1;
    return AC_OK;
}

int ac_exit_initialization(ac_inst *m) {
    if (initialize(m)) { m->d.mode = AC_FAILED; return AC_ERROR; }
    m->d.mode = m->is_cs ? AC_STEP : AC_EVENT;
    return AC_OK;
}

int ac_event_update(ac_inst *m, int *states_changed, int *terminate) {
    int event = 0;
    *terminate = 0;
    if (ac_keep_loops_closed(m, 1e-3, states_changed)) { m->d.mode = AC_FAILED; return AC_ERROR; }
    ac_invalidate(m);
    if (ac_state_event(m, 0, &event)) { m->d.mode = AC_FAILED; return AC_ERROR; }
    if (event) *states_changed = 1;
    if (ac_check_assertions(m) || (m->d.t > m->d.t_start && ac_termination(m, terminate))) {
        m->d.mode = AC_FAILED;
        return AC_ERROR;
    }
    m->d.next_event = ac_next_event(m, m->d.t);
    return AC_OK;
}

int ac_completed_step(ac_inst *m) {
    if (ac_check_assertions(m)) { m->d.mode = AC_FAILED; return AC_ERROR; }
    return AC_OK;
}

/* ---- values by value reference -------------------------------------------------------- */
static int vr_kind(unsigned vr, int *index) {
    if (vr >= AC_NVR) return AC_K_NONE;
    *index = AC_VR_INDEX[vr];
    return AC_VR_KIND[vr];
}

static int get_real(ac_inst *m, unsigned vr, double *v) {
    int i, k = vr_kind(vr, &i);
    switch (k) {
    case AC_K_PARAM: case AC_K_SWITCH: case AC_K_MODE: *v = m->d.p[i]; return AC_OK;
    case AC_K_IND: {
        double g[AC_D(AC_NG)];
        if (ac_event_indicators(m, g, AC_NG)) return AC_ERROR;
        *v = g[i];
        return AC_OK;
    }
    case AC_K_INPUT: *v = m->d.u[i]; return AC_OK;
    case AC_K_STATE: *v = m->d.x[i]; return AC_OK;
    case AC_K_TIME: *v = m->d.t; return AC_OK;
    case AC_K_SOLVER: *v = i == 0 ? m->d.rtol : m->d.atol; return AC_OK;
    case AC_K_OUTPUT: if (ac_outputs(m)) return AC_ERROR; *v = m->eq.y[i]; return AC_OK;
    case AC_K_DER: if (ac_derivatives(m, NULL)) return AC_ERROR; *v = m->eq.xdot[i]; return AC_OK;
    case AC_K_REC: if (ac_recorded(m)) return AC_ERROR; *v = m->eq.rec[i]; return AC_OK;
    default: return ERR("no variable with value reference %u", vr);
    }
}

static int set_real(ac_inst *m, unsigned vr, double v) {
    int i, k = vr_kind(vr, &i);
    switch (k) {
    case AC_K_PARAM:
        if (check_param(m, i, v)) return AC_ERROR;
        m->d.p[i] = v;
        if (!m->d.initialized) return update_starts(m);
        ac_invalidate(m);
        return AC_OK;
    case AC_K_INPUT:
        if (!isfinite(v)) return ERR("input %u: value %g is not finite", vr, v);
        m->d.u[i] = v;
        ac_invalidate(m);
        return AC_OK;
    case AC_K_STATE:
        if (m->d.initialized && m->is_cs)
            return ERR("the state '%s' cannot be set after initialization in co-simulation", AC_X_NAMES[i]);
        if (!isfinite(v)) return ERR("state '%s': value %g is not finite", AC_X_NAMES[i], v);
        m->d.x[i] = v;
        if (!m->d.initialized) m->d.x_set[i] = 1;
        ac_invalidate(m);
        return AC_OK;
    case AC_K_SOLVER:
        if (!(v > 0) || !isfinite(v)) return ERR("solver tolerance must be > 0, got %g", v);
        if (i == 0) { m->d.rtol = v; m->d.rtol_set = 1; } else { m->d.atol = v; m->d.atol_set = 1; }
        return AC_OK;
    case AC_K_NONE: return ERR("no variable with value reference %u", vr);
    default: return ERR("variable %u is calculated by the model and cannot be set", vr);
    }
}

int ac_get_reals(ac_inst *m, const unsigned *vr, size_t n, double *values) {
    size_t i;
    for (i = 0; i < n; i++) if (get_real(m, vr[i], &values[i])) return AC_ERROR;
    return AC_OK;
}

int ac_set_reals(ac_inst *m, const unsigned *vr, size_t n, const double *values) {
    size_t i;
    for (i = 0; i < n; i++) if (set_real(m, vr[i], values[i])) return AC_ERROR;
    return AC_OK;
}

int ac_set_time(ac_inst *m, double t) {
    if (!isfinite(t)) return ERR("the time must be a finite number, got %g", t);
    if (t != m->d.t) { m->d.t = t; ac_invalidate(m); }
    return AC_OK;
}

/* ---- continuous states ------------------------------------------------------------------ */
static int check_nx(ac_inst *m, size_t n) {
    if (n == AC_NX) return AC_OK;
    return ERR("expected %d continuous states, got %d", AC_NX, (int)n);
}

int ac_get_states(ac_inst *m, double *x, size_t n) {
    if (check_nx(m, n)) return AC_ERROR;
    memcpy(x, m->d.x, sizeof(double) * n);
    return AC_OK;
}

int ac_set_states(ac_inst *m, const double *x, size_t n) {
    size_t i;
    if (check_nx(m, n)) return AC_ERROR;
    for (i = 0; i < n; i++)
        if (!isfinite(x[i])) return ERR("state '%s': value %g is not finite", AC_X_NAMES[i], x[i]);
    memcpy(m->d.x, x, sizeof(double) * n);
    ac_invalidate(m);
    return AC_OK;
}

int ac_get_derivatives(ac_inst *m, double *xdot, size_t n) {
    if (check_nx(m, n)) return AC_ERROR;
    return ac_derivatives(m, xdot);
}

void ac_nominals(double *nominal, size_t n) {
    size_t i;
    for (i = 0; i < n && i < AC_NX; i++) nominal[i] = AC_X_NOMINAL[i];
}

/* ---- directional derivatives ------------------------------------------------------------ */
int ac_directional(ac_inst *m, const unsigned *unknowns, size_t nun, const unsigned *knowns,
                   size_t nk, const double *seed, double *out) {
    size_t a, b;
    if (ac_ensure_z(m)) return AC_ERROR;
    if (ac_total_jacobian(m, m->d.t, m->d.x, m->d.z)) return AC_ERROR;
    for (a = 0; a < nun; a++) {
        int iu, ku = vr_kind(unknowns[a], &iu), row;
        double s = 0.0;
        if (ku == AC_K_DER) row = iu;
        else if (ku == AC_K_OUTPUT) row = AC_NX + iu;
        else if (ku == AC_K_STATE) row = -1 - iu;
        else return ERR("directional derivatives: unknown %u is not a state derivative, output or state", unknowns[a]);
        for (b = 0; b < nk; b++) {
            int ik, kk = vr_kind(knowns[b], &ik), col;
            if (kk == AC_K_STATE) col = ik;
            else if (kk == AC_K_INPUT) col = AC_NX + ik;
            else return ERR("directional derivatives: known %u is not a state or input", knowns[b]);
            if (row < 0) s += (kk == AC_K_STATE && ik == -1 - row) ? seed[b] : 0.0;
            else s += m->eq.T[row + col * AC_NF] * seed[b];
        }
        out[a] = s;
    }
    return AC_OK;
}

/* ---- FMU state ---------------------------------------------------------------------------- */
#define AC_MAGIC 0x41434653u   /* "ACFS" */
#define AC_HEAD (sizeof(unsigned) + sizeof(size_t))

int ac_state_get(ac_inst *m, void **state) {
    ac_data *d = *state ? (ac_data *)*state : (ac_data *)malloc(sizeof(ac_data));
    if (!d) return ERR("FMU state: out of memory");
    *d = m->d;
    *state = d;
    return AC_OK;
}

int ac_state_set(ac_inst *m, const void *state) {
    if (!state) return ERR("FMU state: none given");
    m->d = *(const ac_data *)state;
    ac_invalidate(m);
    return AC_OK;
}

void ac_state_free(void **state) {
    if (state && *state) { free(*state); *state = NULL; }
}

size_t ac_state_size(void) { return AC_HEAD + sizeof(ac_data); }

int ac_state_serialize(ac_inst *m, const void *state, void *bytes, size_t size) {
    unsigned magic = AC_MAGIC;
    size_t n = sizeof(ac_data);
    char *b = (char *)bytes;
    if (!state || size < AC_HEAD + n) return ERR("FMU state: serialization buffer too small");
    memcpy(b, &magic, sizeof(magic));
    memcpy(b + sizeof(magic), &n, sizeof(n));
    memcpy(b + AC_HEAD, state, n);
    return AC_OK;
}

int ac_state_deserialize(ac_inst *m, const void *bytes, size_t size, void **state) {
    unsigned magic;
    size_t n;
    const char *b = (const char *)bytes;
    ac_data *d;
    if (size >= AC_HEAD) {
        memcpy(&magic, b, sizeof(magic));
        memcpy(&n, b + sizeof(magic), sizeof(n));
        if (magic == AC_MAGIC && n == sizeof(ac_data) && size >= AC_HEAD + n) {
            d = *state ? (ac_data *)*state : (ac_data *)malloc(sizeof(ac_data));
            if (d) {
                memcpy(d, b + AC_HEAD, n);
                *state = d;
                return AC_OK;
            }
        }
    }
    return ERR("FMU state: the bytes are not a state of this FMU");
}
