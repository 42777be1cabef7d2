/* acausal native FMU runtime (see runtime.h). Dense linear algebra throughout: meant for the
 * small and medium models FMUs are made of (tens to a few hundred states). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "runtime.h"
#include "model_data.h"     /* generated: value-reference table, defaults, names, functions */

typedef int (*ac_fn)(const double **arg, double **res, long long *iw, double *w, int mem);

#define AC_DRIFT_FACTOR 1e-3      /* ME: project when |Φ|, |Φ̇| > 1e-3 · rtol */
#define AC_NEWTON_MAX 50
#define AC_PROJ_MAX 200
#define AC_ASSEMBLY_RETRIES 4     /* assembly restarts from perturbed start values ... */
#define AC_ASSEMBLY_JITTER 0.1    /* ... moved by up to ±0.05·(1 + |start|) */

/* ---- logging ------------------------------------------------------------------------- */
void ac_logf(ac_inst *m, int status, const char *category, const char *fmt, ...) {
    va_list ap;
    if (!m->log || (status == AC_OK && !m->logging_on)) return;
    va_start(ap, fmt);
    vsnprintf(m->msg, sizeof(m->msg), fmt, ap);
    va_end(ap);
    m->log(m, status, category, m->msg);
}

#define ERR(...) (ac_logf(m, AC_ERROR, "logStatusError", __VA_ARGS__), AC_ERROR)

/* ---- dense LU, column-major a[i + j*n] ----------------------------------------------- */
static int lu(double *a, int n, int *piv) {
    int i, j, k;
    for (k = 0; k < n; k++) {
        int p = k;
        double best = fabs(a[k + k * n]);
        for (i = k + 1; i < n; i++)
            if (fabs(a[i + k * n]) > best) { best = fabs(a[i + k * n]); p = i; }
        piv[k] = p;
        if (!(best > 0.0) || !isfinite(best)) return -1;
        if (p != k)
            for (j = 0; j < n; j++) { double t = a[k + j * n]; a[k + j * n] = a[p + j * n]; a[p + j * n] = t; }
        for (i = k + 1; i < n; i++) a[i + k * n] /= a[k + k * n];
        for (j = k + 1; j < n; j++) {
            double akj = a[k + j * n];
            if (akj != 0.0)
                for (i = k + 1; i < n; i++) a[i + j * n] -= a[i + k * n] * akj;
        }
    }
    return 0;
}

static void lu_solve(const double *a, int n, const int *piv, double *b) {
    int i, j;
    for (i = 0; i < n; i++) {
        if (piv[i] != i) { double t = b[i]; b[i] = b[piv[i]]; b[piv[i]] = t; }
    }
    for (j = 0; j < n; j++) {
        double bj = b[j];
        if (bj != 0.0) for (i = j + 1; i < n; i++) b[i] -= a[i + j * n] * bj;
    }
    for (j = n - 1; j >= 0; j--) {
        b[j] /= a[j + j * n];
        for (i = 0; i < j; i++) b[i] -= a[i + j * n] * b[j];
    }
}

/* ---- evaluation of the generated functions ------------------------------------------- */
static int eval(ac_inst *m, ac_fn f, double t, const double *x, const double *z, double **out,
                int nout) {
    int i;
    double tt = t;
    m->arg[0] = &tt; m->arg[1] = x; m->arg[2] = z; m->arg[3] = m->d.p; m->arg[4] = m->d.u;
    for (i = 0; i < nout; i++) m->res[i] = out[i];
    return f(m->arg, m->res, m->iw, m->w, 0);
}

static int eval_p(ac_inst *m, ac_fn f, double *out) {
    m->arg[0] = m->d.p;
    m->res[0] = out;
    return f(m->arg, m->res, m->iw, m->w, 0);
}

static int all_finite(const double *v, int n) {
    int i;
    for (i = 0; i < n; i++) if (!isfinite(v[i])) return 0;
    return 1;
}

/* Newton's method for the algebraic variables z at (t, x), warm-started from z. */
static int solve_z(ac_inst *m, double t, const double *x, double *z) {
#if AC_NZ > 0
    int it, i;
    for (it = 0; it < AC_NEWTON_MAX; it++) {
        double *out[2] = {m->g, m->gz}, step = 0.0, size = 0.0;
        if (eval(m, (ac_fn)ac_alg, t, x, z, out, 2)) return ERR("evaluating the algebraic equations failed");
        if (!all_finite(m->g, AC_NZ) || !all_finite(m->gz, AC_NZ * AC_NZ))
            return ERR("the algebraic equations are not finite at t = %g", t);
        if (lu(m->gz, AC_NZ, m->zpiv))
            return ERR("the algebraic equations for %s are singular at t = %g", AC_Z_NAMES[0], t);
        for (i = 0; i < AC_NZ; i++) m->g[i] = -m->g[i];
        lu_solve(m->gz, AC_NZ, m->zpiv, m->g);
        for (i = 0; i < AC_NZ; i++) {
            z[i] += m->g[i];
            if (fabs(m->g[i]) > step) step = fabs(m->g[i]);
            if (fabs(z[i]) > size) size = fabs(z[i]);
        }
        if (step <= 1e-13 * (1.0 + size)) return AC_OK;
    }
    return ERR("Newton's method for the algebraic variables (%s, ...) did not converge at t = %g",
               AC_Z_NAMES[0], t);
#else
    (void)m; (void)t; (void)x; (void)z;
    return AC_OK;
#endif
}

/* state derivatives at (t, x): z solved from the warm start z */
static int rhs(ac_inst *m, double t, const double *x, double *z, double *xdot) {
    double *out[1] = {xdot};
    if (solve_z(m, t, x, z)) return AC_ERROR;
    if (eval(m, (ac_fn)ac_ode, t, x, z, out, 1)) return ERR("evaluating the derivatives failed");
    if (!all_finite(xdot, AC_NX)) return ERR("the state derivatives are not finite at t = %g", t);
    return AC_OK;
}

/* T = d[xdot; y]/d[x; u; t] in total (z eliminated: F_w - F_z g_z^-1 g_w) at (t, x, z) */
static int total_jacobian(ac_inst *m, double t, const double *x, const double *z) {
    double *out[4] = {m->Fw, m->Fz, m->gw, m->gz};
    int i, j;
    if (eval(m, (ac_fn)ac_jac, t, x, z, out, 4)) return ERR("evaluating the Jacobian failed");
    memcpy(m->T, m->Fw, sizeof(double) * AC_NF * AC_NW);
#if AC_NZ > 0
    if (lu(m->gz, AC_NZ, m->zpiv)) return ERR("the algebraic equations are singular at t = %g", t);
    for (j = 0; j < AC_NW; j++) {
        double *s = m->g;        /* scratch: solve_z is not running here */
        int k;
        for (i = 0; i < AC_NZ; i++) s[i] = m->gw[i + j * AC_NZ];
        lu_solve(m->gz, AC_NZ, m->zpiv, s);
        for (i = 0; i < AC_NF; i++) {
            double acc = 0.0;
            for (k = 0; k < AC_NZ; k++) acc += m->Fz[i + k * AC_NF] * s[k];
            m->T[i + j * AC_NF] -= acc;
        }
    }
#else
    (void)i; (void)j;
#endif
    if (!all_finite(m->T, AC_NF * AC_NW)) return ERR("the Jacobian is not finite at t = %g", t);
    return AC_OK;
}

/* ---- caches -------------------------------------------------------------------------- */
void ac_invalidate(ac_inst *m) { m->valid_z = m->valid_xdot = m->valid_y = m->valid_rec = 0; }

/* ---- FMU state ---------------------------------------------------------------------------- */
#define AC_MAGIC 0x41434653u   /* "ACFS" */
#define AC_HEAD (sizeof(unsigned) + sizeof(size_t))

int ac_state_get(ac_inst *m, void **state) {
    ac_data *d = *state ? (ac_data *)*state : (ac_data *)malloc(sizeof(ac_data));
    if (!d) { ac_logf(m, AC_ERROR, "logStatusError", "FMU state: out of memory"); return AC_ERROR; }
    *d = m->d;
    *state = d;
    return AC_OK;
}

int ac_state_set(ac_inst *m, const void *state) {
    if (!state) { ac_logf(m, AC_ERROR, "logStatusError", "FMU state: none given"); return AC_ERROR; }
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
    if (!state || size < AC_HEAD + n) {
        ac_logf(m, AC_ERROR, "logStatusError", "FMU state: serialization buffer too small");
        return AC_ERROR;
    }
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
    ac_logf(m, AC_ERROR, "logStatusError", "FMU state: the bytes are not a state of this FMU");
    return AC_ERROR;
}

static int ensure_z(ac_inst *m) {
    if (m->valid_z) return AC_OK;
    if (solve_z(m, m->d.t, m->d.x, m->d.z)) return AC_ERROR;
    m->valid_z = 1;
    return AC_OK;
}

int ac_derivatives(ac_inst *m, double *xdot) {
    if (!m->valid_xdot) {
        double *out[1] = {m->xdot};
        if (ensure_z(m)) return AC_ERROR;
        if (eval(m, (ac_fn)ac_ode, m->d.t, m->d.x, m->d.z, out, 1)) return ERR("evaluating the derivatives failed");
        if (!all_finite(m->xdot, AC_NX)) return ERR("the state derivatives are not finite at t = %g", m->d.t);
        m->valid_xdot = 1;
    }
    if (xdot) memcpy(xdot, m->xdot, sizeof(double) * AC_NX);
    return AC_OK;
}

static int ensure_y(ac_inst *m) {
    if (m->valid_y) return AC_OK;
    {
        double *out[1] = {m->y};
        if (ensure_z(m)) return AC_ERROR;
        if (eval(m, (ac_fn)ac_out, m->d.t, m->d.x, m->d.z, out, 1)) return ERR("evaluating the outputs failed");
    }
    m->valid_y = 1;
    return AC_OK;
}

static int ensure_rec(ac_inst *m) {
    if (m->valid_rec) return AC_OK;
    {
        double *out[1] = {m->rec};
        if (ensure_z(m)) return AC_ERROR;
        if (eval(m, (ac_fn)ac_rec, m->d.t, m->d.x, m->d.z, out, 1)) return ERR("evaluating the variables failed");
    }
    m->valid_rec = 1;
    return AC_OK;
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

int ac_check_params(ac_inst *m) {
    int i;
    for (i = 0; i < AC_NP; i++) if (check_param(m, i, m->d.p[i])) return AC_ERROR;
    return AC_OK;
}

/* start values of the states the importer has not set, from the parameters */
static int update_starts(ac_inst *m) {
    double out[AC_D(AC_NX + AC_NZ)];
    int i;
    if (eval_p(m, (ac_fn)ac_start, out)) return ERR("evaluating the start values failed");
    for (i = 0; i < AC_NX; i++) if (!m->d.x_set[i]) m->d.x[i] = out[i];
    for (i = 0; i < AC_NZ; i++) m->d.z[i] = out[AC_NX + i];
    ac_invalidate(m);
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

void ac_tolerance(ac_inst *m, int defined, double tol) {
    if (!defined || !(tol > 0)) return;
    if (!m->d.rtol_set) m->d.rtol = tol;
    if (!m->d.atol_set) m->d.atol = 1e-2 * tol;
}

int ac_vr_kind(unsigned vr, int *index) {
    if (vr >= AC_NVR) return AC_K_NONE;
    *index = AC_VR_INDEX[vr];
    return AC_VR_KIND[vr];
}

int ac_get_real(ac_inst *m, unsigned vr, double *v) {
    int i, k = ac_vr_kind(vr, &i);
    switch (k) {
    case AC_K_PARAM: case AC_K_SWITCH: *v = m->d.p[i]; return AC_OK;
    case AC_K_INPUT: *v = m->d.u[i]; return AC_OK;
    case AC_K_STATE: *v = m->d.x[i]; return AC_OK;
    case AC_K_TIME: *v = m->d.t; return AC_OK;
    case AC_K_SOLVER: *v = i == 0 ? m->d.rtol : m->d.atol; return AC_OK;
    case AC_K_OUTPUT: if (ensure_y(m)) return AC_ERROR; *v = m->y[i]; return AC_OK;
    case AC_K_DER: if (ac_derivatives(m, NULL)) return AC_ERROR; *v = m->xdot[i]; return AC_OK;
    case AC_K_REC: if (ensure_rec(m)) return AC_ERROR; *v = m->rec[i]; return AC_OK;
    default: return ERR("no variable with value reference %u", vr);
    }
}

int ac_set_real(ac_inst *m, unsigned vr, double v) {
    int i, k = ac_vr_kind(vr, &i);
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

void ac_set_time(ac_inst *m, double t) {
    if (t != m->d.t) { m->d.t = t; ac_invalidate(m); }
}

void ac_set_states(ac_inst *m, const double *x) {
    memcpy(m->d.x, x, sizeof(double) * AC_NX);
    ac_invalidate(m);
}

void ac_nominals(double *nominal, size_t n) {
    size_t i;
    for (i = 0; i < n && i < AC_NX; i++) nominal[i] = AC_X_NOMINAL[i];
}

/* ---- closed loops: projection onto H = [Φ; Φ̇] = 0 ------------------------------------- */
static double con_norm(ac_inst *m, const double *x) {
#if AC_NH > 0
    double *out[2] = {m->H, NULL}, big = 0.0;
    int i;
    if (eval(m, (ac_fn)ac_con, m->d.t, x, m->d.z, out, 2)) return HUGE_VAL;
    for (i = 0; i < AC_NH; i++) {
        if (!isfinite(m->H[i])) return HUGE_VAL;
        if (fabs(m->H[i]) > big) big = fabs(m->H[i]);
    }
    return big;
#else
    (void)m; (void)x;
    return 0.0;
#endif
}

/* The point closest to `target` (metric diag(D)) on H(x) = 0 by the iteration of
 * acausal.simulation.kernels.project, starting from x (updated in place):
 * x <- target + D Hxᵀ (Hx D Hxᵀ)⁻¹ (Hx (x − target) − H), steps limited to `maxstep` per
 * state. D = 0 holds a state fixed. Returns AC_ERROR, unlogged, when the iteration ends with
 * max |H| above 1e3·tol (the caller says what failed); evaluation failures are logged. */
static int project(ac_inst *m, double *x, const double *target, const double *D,
                   double maxstep, int maxit, double tol) {
#if AC_NH > 0
    int it, i, j, k;
    for (it = 0; it < maxit; it++) {
        double *out[2] = {m->H, m->Hx}, big = 0.0, stepn = 0.0, xn = 0.0, reg = 0.0;
        if (eval(m, (ac_fn)ac_con, m->d.t, x, m->d.z, out, 2)) return ERR("evaluating the loop constraints failed");
        if (!all_finite(m->H, AC_NH) || !all_finite(m->Hx, AC_NH * AC_NX))
            return ERR("the loop constraints are not finite at t = %g", m->d.t);
        for (i = 0; i < AC_NH; i++) if (fabs(m->H[i]) > big) big = fabs(m->H[i]);
        /* A = Hx D Hxᵀ (+ a tiny regularization for switched-off rows), rhs = Hx (x - target) - H */
        for (i = 0; i < AC_NH; i++) {
            double r = -m->H[i];
            for (k = 0; k < AC_NX; k++) r += m->Hx[i + k * AC_NH] * (x[k] - target[k]);
            m->lam[i] = r;
            for (j = 0; j < AC_NH; j++) {
                double a = 0.0;
                for (k = 0; k < AC_NX; k++) a += m->Hx[i + k * AC_NH] * D[k] * m->Hx[j + k * AC_NH];
                m->A[i + j * AC_NH] = a;
            }
            if (m->A[i + i * AC_NH] > reg) reg = m->A[i + i * AC_NH];
        }
        for (i = 0; i < AC_NH; i++) m->A[i + i * AC_NH] += 1e-14 * (reg > 0 ? reg : 1.0);
        if (lu(m->A, AC_NH, m->piv)) return ERR("the loop constraints are singular at t = %g", m->d.t);
        lu_solve(m->A, AC_NH, m->piv, m->lam);
        for (k = 0; k < AC_NX; k++) {
            double s = 0.0;
            for (i = 0; i < AC_NH; i++) s += m->Hx[i + k * AC_NH] * m->lam[i];
            m->xs[k] = target[k] + D[k] * s - x[k];
            if (fabs(m->xs[k]) > stepn) stepn = fabs(m->xs[k]);
            if (fabs(x[k]) > xn) xn = fabs(x[k]);
        }
        if (big <= tol && stepn <= 1e-12 * (1.0 + xn)) break;
        if (maxstep > 0 && stepn > maxstep)
            for (k = 0; k < AC_NX; k++) m->xs[k] *= maxstep / stepn;
        for (k = 0; k < AC_NX; k++) x[k] += m->xs[k];
        if (stepn <= 1e-14 * (1.0 + xn)) break;
    }
    if (con_norm(m, x) > 1e3 * tol + 1e-10) return AC_ERROR;
    ac_invalidate(m);
    m->d.n_projections++;
#else
    (void)m; (void)x; (void)target; (void)D; (void)maxstep; (void)maxit; (void)tol;
#endif
    return AC_OK;
}

static double drift_tol(ac_inst *m) { return AC_DRIFT_FACTOR * m->d.rtol; }

int ac_drift_exceeded(ac_inst *m, int *exceeded) {
    *exceeded = 0;
#if AC_NH > 0
    *exceeded = con_norm(m, m->d.x) > drift_tol(m);
#else
    (void)m;
#endif
    return AC_OK;
}

/* The loop rows to enforce at the current configuration, as simulate() chooses them
 * (acausal.simulation.kernels.independent_rows, the same rule): in row order, a row is on when
 * its Gram–Schmidt residual against the rows on before it exceeds 1e-9·max(1, max |Φ_q|);
 * the others are redundant there and switched off (loops.active_i = 0). */
static int select_loop_rows(ac_inst *m) {
#if AC_NPHI > 0
    double J[AC_NPHI * AC_NQ], B[AC_NPHI * AC_NQ], r[AC_NQ], big = 0.0, tol;
    double *out[1] = {J};
    int i, j, k, pass, nb = 0;
    if (eval(m, (ac_fn)ac_phiq, m->d.t, m->d.x, m->d.z, out, 1))
        return ERR("evaluating the loop constraints' Jacobian failed");
    for (k = 0; k < AC_NPHI * AC_NQ; k++) if (fabs(J[k]) > big) big = fabs(J[k]);
    tol = 1e-9 * (big > 1.0 ? big : 1.0);
    for (i = 0; i < AC_NPHI; i++) {
        double norm = 0.0;
        for (k = 0; k < AC_NQ; k++) r[k] = J[i + k * AC_NPHI];
        for (pass = 0; pass < 2; pass++)          /* twice: orthogonal to rounding */
            for (j = 0; j < nb; j++) {
                double c = 0.0;
                for (k = 0; k < AC_NQ; k++) c += B[j * AC_NQ + k] * r[k];
                for (k = 0; k < AC_NQ; k++) r[k] -= c * B[j * AC_NQ + k];
            }
        for (k = 0; k < AC_NQ; k++) norm += r[k] * r[k];
        norm = sqrt(norm);
        m->d.p[AC_SWITCH[i]] = norm > tol ? 1.0 : 0.0;
        if (norm > tol) {
            for (k = 0; k < AC_NQ; k++) B[nb * AC_NQ + k] = r[k] / norm;
            nb++;
        }
    }
    ac_invalidate(m);
#else
    (void)m;
#endif
    return AC_OK;
}

static int project_state(ac_inst *m, double *x) {
#if AC_NH > 0
    double D[AC_NX], target[AC_NX];
    int k;
    for (k = 0; k < AC_NX; k++) D[k] = 1.0;
    memcpy(target, x, sizeof(target));
    if (project(m, x, target, D, 0.0, 20, 1e-3 * drift_tol(m)))
        return ERR("cannot satisfy the loop constraints at t = %g (residual %g): the "
                   "mechanism has left its assembled configuration", m->d.t, con_norm(m, x));
    return AC_OK;
#else
    (void)m; (void)x;
    return AC_OK;
#endif
}

/* ---- time events ---------------------------------------------------------------------- */
double ac_next_event(ac_inst *m, double t) {
#if AC_NEV > 0
    double ev[2 * AC_NEV], best = HUGE_VAL, eps = 1e-13 * (fabs(t) > 1 ? fabs(t) : 1);
    int i;
    if (eval_p(m, (ac_fn)ac_events, ev)) return HUGE_VAL;
    for (i = 0; i < AC_NEV; i++) {
        double first = ev[i], period = ev[AC_NEV + i], te = first;
        if (period > 0 && first <= t + eps) {
            double k = ceil((t + eps - first) / period);
            te = first + k * period;
            while (te <= t + eps) te += period;
        }
        if (te > t + eps && te < best) best = te;
    }
    return best;
#else
    (void)m; (void)t;
    return HUGE_VAL;
#endif
}

/* ---- initialization ------------------------------------------------------------------- */
int ac_initialize(ac_inst *m) {
    if (ac_check_params(m)) return AC_ERROR;
    if (update_starts(m)) return AC_ERROR;
#if AC_NH > 0
    {   /* assemble the loops: states set by the importer are held, the others move least
           from their start values. A start at a singular configuration (e.g. a linkage with
           every joint at 0) can stall the iteration; it is retried from a few deterministic
           perturbations of the free states, as acausal.simulation.kernels.project does. */
        double D[AC_NX], start[AC_NX];
        unsigned seed = 12345u;
        int k, attempt;
        for (k = 0; k < AC_NX; k++) D[k] = m->d.x_set[k] ? 0.0 : 1.0;
        memcpy(start, m->d.x, sizeof(start));
        for (attempt = 0; project(m, m->d.x, start, D, 0.3, AC_PROJ_MAX, 1e-12); attempt++) {
            if (attempt == AC_ASSEMBLY_RETRIES)
                return ERR("initialization: the kinematic loops cannot be closed from the start "
                           "values (residual %g); set the start values of the joint coordinates "
                           "near an assembled configuration", con_norm(m, m->d.x));
            for (k = 0; k < AC_NX; k++) {
                seed = seed * 1103515245u + 12345u;
                m->d.x[k] = start[k] + D[k] * AC_ASSEMBLY_JITTER * (1.0 + fabs(start[k]))
                                       * ((double)((seed >> 8) & 0xffffu) / 65535.0 - 0.5);
            }
        }
    }
    if (select_loop_rows(m)) return AC_ERROR;
#endif
    ac_invalidate(m);
    if (ensure_z(m)) return AC_ERROR;
    if (ac_derivatives(m, NULL)) return AC_ERROR;
    m->d.next_event = ac_next_event(m, m->d.t);
    m->d.initialized = 1;
    return AC_OK;
}

int ac_event_update(ac_inst *m, int *states_changed) {
    *states_changed = 0;
#if AC_NH > 0
    if (con_norm(m, m->d.x) > 1e-3 * drift_tol(m)) {
        if (project_state(m, m->d.x)) return AC_ERROR;
        *states_changed = 1;
    }
#endif
    ac_invalidate(m);
    m->d.next_event = ac_next_event(m, m->d.t);
    return AC_OK;
}

/* ---- co-simulation: RODAS4 (Hairer & Wanner), stiffly accurate, L-stable, order 4(3) ---- */
static const double G_ = 0.25;
static const double C2 = 0.386, C3 = 0.21, C4 = 0.63;
static const double D1 = 0.25, D2 = -0.1043, D3 = 0.1035, D4 = -0.3620000000000023e-01;
static const double A21 = 1.544, A31 = 0.9466785280815826, A32 = 0.2557011698983284,
    A41 = 3.314825187068521, A42 = 2.896124015972201, A43 = 0.9986419139977817,
    A51 = 1.221224509226641, A52 = 6.019134481288629, A53 = 12.53708332932087,
    A54 = -0.6878860361058950;
static const double C21 = -5.6688, C31 = -2.430093356833875, C32 = -0.2063599157091915,
    C41 = -0.1073529058151375, C42 = -9.594562251023355, C43 = -20.47028614809616,
    C51 = 7.496443313967647, C52 = -10.24680431464352, C53 = -33.99990352819905,
    C54 = 11.70890893206160, C61 = 8.083246795921522, C62 = -7.981132988064893,
    C63 = -31.52159432874371, C64 = 16.31930543123136, C65 = -6.058818238834054;

/* one RODAS4 step of size h from (t, m->d.x): new state in ytmp, error estimate in K[5];
 * returns AC_OK, or AC_DISCARD if a stage could not be evaluated (the caller halves h) */
static int rodas_step(ac_inst *m, double t, double h) {
    double *y = m->d.x, *yt = m->ytmp, (*K)[AC_D(AC_NX)] = m->K;
    double *z = m->zs;
    int i, j;
    /* Jacobian, time derivative and W = I/(γh) − J at (t, y) */
    memcpy(z, m->d.z, sizeof(double) * AC_NZ);
    if (rhs(m, t, y, z, m->f0)) return AC_DISCARD;
    if (total_jacobian(m, t, y, z)) return AC_DISCARD;
    for (j = 0; j < AC_NX; j++) {
        for (i = 0; i < AC_NX; i++) m->W[i + j * AC_NX] = -m->T[i + j * AC_NF];
        m->W[j + j * AC_NX] += 1.0 / (G_ * h);
    }
    for (i = 0; i < AC_NX; i++) m->ft[i] = m->T[i + (AC_NX + AC_NU) * AC_NF];
    if (lu(m->W, AC_NX, m->piv)) return AC_DISCARD;
#define STAGE(k, tk, expr_y, expr_rhs)                                             \
    for (i = 0; i < AC_NX; i++) yt[i] = y[i] + (expr_y);                           \
    if (rhs(m, t + (tk) * h, yt, z, K[k])) return AC_DISCARD;                      \
    for (i = 0; i < AC_NX; i++) K[k][i] += (expr_rhs);                             \
    lu_solve(m->W, AC_NX, m->piv, K[k]);
    for (i = 0; i < AC_NX; i++) K[0][i] = m->f0[i] + h * D1 * m->ft[i];
    lu_solve(m->W, AC_NX, m->piv, K[0]);
    STAGE(1, C2, A21 * K[0][i], h * D2 * m->ft[i] + C21 * K[0][i] / h)
    STAGE(2, C3, A31 * K[0][i] + A32 * K[1][i],
          h * D3 * m->ft[i] + (C31 * K[0][i] + C32 * K[1][i]) / h)
    STAGE(3, C4, A41 * K[0][i] + A42 * K[1][i] + A43 * K[2][i],
          h * D4 * m->ft[i] + (C41 * K[0][i] + C42 * K[1][i] + C43 * K[2][i]) / h)
    STAGE(4, 1.0, A51 * K[0][i] + A52 * K[1][i] + A53 * K[2][i] + A54 * K[3][i],
          (C51 * K[0][i] + C52 * K[1][i] + C53 * K[2][i] + C54 * K[3][i]) / h)
    /* stage 6 at y + Σ a5j Kj + K5; the error estimate is K6 */
    for (i = 0; i < AC_NX; i++)
        yt[i] = y[i] + A51 * K[0][i] + A52 * K[1][i] + A53 * K[2][i] + A54 * K[3][i] + K[4][i];
    if (rhs(m, t + h, yt, z, K[5])) return AC_DISCARD;
    for (i = 0; i < AC_NX; i++)
        K[5][i] += (C61 * K[0][i] + C62 * K[1][i] + C63 * K[2][i] + C64 * K[3][i] + C65 * K[4][i]) / h;
    lu_solve(m->W, AC_NX, m->piv, K[5]);
    for (i = 0; i < AC_NX; i++) yt[i] += K[5][i];
#undef STAGE
    if (!all_finite(yt, AC_NX)) return AC_DISCARD;
    return AC_OK;
}

static double err_norm(ac_inst *m) {
    double s = 0.0;
    int i;
    for (i = 0; i < AC_NX; i++) {
        double a = fabs(m->d.x[i]), b = fabs(m->ytmp[i]);
        double sc = m->d.atol * AC_X_NOMINAL[i] + m->d.rtol * (a > b ? a : b);
        double e = m->K[5][i] / sc;
        s += e * e;
    }
    return AC_NX > 0 ? sqrt(s / AC_NX) : 0.0;
}

/* integrate the states from m->d.t to t1 (no event inside) */
static int integrate(ac_inst *m, double t1) {
    double t = m->d.t, h = m->d.h, span = t1 - t;
    int rejected = 0;
    if (span <= 0) return AC_OK;
    if (AC_NX == 0) { m->d.t = t1; return AC_OK; }
    if (!(h > 0)) {   /* initial step from the size of the derivatives */
        double d0 = 0.0, d1 = 0.0;
        int i;
        if (ac_derivatives(m, NULL)) return AC_ERROR;
        for (i = 0; i < AC_NX; i++) {
            double sc = m->d.atol * AC_X_NOMINAL[i] + m->d.rtol * fabs(m->d.x[i]);
            d0 += (m->d.x[i] / sc) * (m->d.x[i] / sc);
            d1 += (m->xdot[i] / sc) * (m->xdot[i] / sc);
        }
        d0 = sqrt(d0 / AC_NX); d1 = sqrt(d1 / AC_NX);
        h = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
        h *= 1e-2;
        if (h > span) h = span;
    }
    while (t < t1) {
        double hs = h, err, fac;
        int last = 0, st;
        if (t + h >= t1 - 1e-12 * span) { hs = t1 - t; last = 1; }
        if (hs < 1e-14 * (fabs(t) > 1 ? fabs(t) : 1))
            return ERR("co-simulation solver: step size too small at t = %.17g", t);
        st = rodas_step(m, t, hs);
        if (st != AC_OK) {     /* a stage failed: shrink and retry */
            m->d.n_rejected++;
            h = 0.25 * hs;
            rejected = 1;
            continue;
        }
        err = err_norm(m);
        fac = err > 0 ? 0.9 * pow(err, -0.25) : 5.0;
        if (fac > 5.0) fac = 5.0;
        if (fac < 0.2) fac = 0.2;
        if (err <= 1.0) {
            memcpy(m->d.x, m->ytmp, sizeof(double) * AC_NX);
            memcpy(m->d.z, m->zs, sizeof(double) * AC_NZ);
            t = last ? t1 : t + hs;
            m->d.t = t;
            ac_invalidate(m);
            m->d.n_steps++;
#if AC_NH > 0
            if (con_norm(m, m->d.x) > 1e-3 * drift_tol(m) && project_state(m, m->d.x)) return AC_ERROR;
#endif
            if (rejected && fac > 1.0) fac = 1.0;
            rejected = 0;
            if (last) { if (hs * fac > h) h = hs * fac; }
            else h = hs * fac;
        } else {
            m->d.n_rejected++;
            rejected = 1;
            h = hs * fac;
        }
    }
    m->d.h = h;
    return AC_OK;
}

int ac_do_step(ac_inst *m, double t0, double H) {
    double t1 = t0 + H, tol = 1e-10 * (fabs(t1) > 1 ? fabs(t1) : 1);
    if (fabs(t0 - m->d.t) > tol)
        return ERR("doStep from t = %.17g but the FMU is at t = %.17g", t0, m->d.t);
    if (H < 0) return ERR("doStep with a negative step size %g", H);
    m->d.t = t0;
#if AC_NH > 0   /* a parameter changed between steps may have opened the loops */
    if (con_norm(m, m->d.x) > drift_tol(m) && project_state(m, m->d.x)) return AC_ERROR;
#endif
    while (m->d.t < t1 - tol) {
        double te = ac_next_event(m, m->d.t);
        if (te < t1 + tol) {           /* stop just before a time event, restart at it */
            double end = te - 1e-12 * (fabs(te) > 1 ? fabs(te) : 1);
            if (end > m->d.t && integrate(m, end)) return AC_ERROR;
            m->d.t = te > t1 ? t1 : te;
            ac_invalidate(m);
        } else if (integrate(m, t1)) return AC_ERROR;
    }
    m->d.t = t1;
    ac_invalidate(m);
    return AC_OK;
}

/* ---- directional derivatives ------------------------------------------------------------ */
int ac_directional(ac_inst *m, const unsigned *unknowns, size_t nun, const unsigned *knowns,
                   size_t nk, const double *seed, double *out) {
    size_t a, b;
    if (ensure_z(m)) return AC_ERROR;
    if (total_jacobian(m, m->d.t, m->d.x, m->d.z)) return AC_ERROR;
    for (a = 0; a < nun; a++) {
        int iu, ku = ac_vr_kind(unknowns[a], &iu), row;
        double s = 0.0;
        if (ku == AC_K_DER) row = iu;
        else if (ku == AC_K_OUTPUT) row = AC_NX + iu;
        else if (ku == AC_K_STATE) row = -1 - iu;
        else return ERR("directional derivatives: unknown %u is not a state derivative, output or state", unknowns[a]);
        for (b = 0; b < nk; b++) {
            int ik, kk = ac_vr_kind(knowns[b], &ik), col;
            if (kk == AC_K_STATE) col = ik;
            else if (kk == AC_K_INPUT) col = AC_NX + ik;
            else return ERR("directional derivatives: known %u is not a state or input", knowns[b]);
            if (row < 0) s += (kk == AC_K_STATE && ik == -1 - row) ? seed[b] : 0.0;
            else s += m->T[row + col * AC_NF] * seed[b];
        }
        out[a] = s;
    }
    return AC_OK;
}
