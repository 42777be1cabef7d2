/* Closed kinematic loops and the initial equations (see loops.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "instance.h"
#include "linalg.h"
#include "model_functions.h"

#define AC_DRIFT_FACTOR 1e-3      /* project when |Φ|, |Φ̇| > 1e-3 · rtol */
#define AC_PROJECTION_MAX 200     /* projection steps at assembly ... */
#define AC_DRIFT_MAX 20           /* ... and for drift */
#define AC_DESCENT_MAX 100        /* Levenberg–Marquardt steps */
#define AC_MOST 0.3               /* the largest move of a position in a step of the assembly */
#define AC_RCOND 1e-12            /* rank truncation of the least-squares solutions */
#define AC_ASSEMBLY_RETRIES 4     /* assembly restarts from perturbed start values ... */
#define AC_ASSEMBLY_JITTER 0.1    /* ... moved by up to ±0.05·(1 + |start|) */

#if AC_NC > 0
/* the initial equations' rows E (l->H and l->Hx from row AC_NH on) at x, with z solved there
 * (m->d.z, warm-started) and eliminated from their gradients: ∂E/∂x − ∂E/∂z g_z⁻¹ g_x */
static int initial_rows(ac_inst *m, const double *x) {
#if AC_NIE > 0
    ac_loop_work *l = &m->loop;
    double E[AC_NIE], *Ex = l->work;           /* scratch: no least squares is running */
    double *out[3] = {E, Ex, l->Ez};
    int i, j;
    if (ac_solve_z(m, m->d.t, x, m->d.z)) return AC_ERROR;
    if (ac_eval(m, (ac_fn)ac_init, m->d.t, x, m->d.z, out, 3))
        return ERR("evaluating the initial equations failed");
#if AC_NZ > 0
    if (ac_jacobians(m, m->d.t, x, m->d.z)) return AC_ERROR;
    ac_eliminate_z(m, l->Ez, AC_NIE, Ex, AC_NX);
#endif
    for (i = 0; i < AC_NIE; i++) {
        l->H[AC_NH + i] = E[i];
        for (j = 0; j < AC_NX; j++) l->Hx[AC_NH + i + j * AC_NC] = Ex[i + j * AC_NIE];
    }
#else
    (void)m; (void)x;
#endif
    return AC_OK;
}

/* the rows in use of [H; E], their gradients ∂/∂x at x and the rows' scales
 * s_i = max_k |∂_i/∂x_k| (1 for a row without any): AC_OK; AC_DISCARD if they are not
 * finite; AC_ERROR, logged, if the evaluation failed */
static int constraints(ac_inst *m, const double *x) {
    ac_loop_work *l = &m->loop;
    int i, k, st;
    if (l->nrows > AC_NH && (st = initial_rows(m, x))) return st;
#if AC_NH > 0
    {
        double *Hx = l->work, *out[2] = {l->H, Hx};     /* scratch, as above */
        if (ac_eval(m, (ac_fn)ac_con, m->d.t, x, m->d.z, out, 2))
            return ERR("evaluating the loop constraints failed");
        for (k = 0; k < AC_NX; k++)
            for (i = 0; i < AC_NH; i++) l->Hx[i + k * AC_NC] = Hx[i + k * AC_NH];
    }
#endif
    for (i = 0; i < l->nrows; i++) {
        double big = 0.0;
        if (!isfinite(l->H[i])) return AC_DISCARD;
        for (k = 0; k < AC_NX; k++) {
            double v = l->Hx[i + k * AC_NC];
            if (!isfinite(v)) return AC_DISCARD;
            if (fabs(v) > big) big = fabs(v);
        }
        l->s[i] = big > 0 ? big : 1.0;
    }
    return AC_OK;
}

/* every row of H in use (as evaluated last), over its scale, below 1e-10·scale: a distance
 * in the states' own units */
static int solved(const ac_loop_work *l, double scale) {
    int i;
    for (i = 0; i < l->nrows; i++) if (!(fabs(l->H[i]) / l->s[i] <= 1e-10 * scale)) return 0;
    return 1;
}

/* the least-squares problem A e = b, A = the rows in use of ∂H/∂x over their scales `s`, the
 * free columns only, transposed into l->at (column i: row i of A). Column by column of
 * ∂H/∂x: with the row loop outside, GCC 12 (-O1 and up) addressed l->at from the induction
 * variable of l->free scaled by 2, as an integer from a null base, after which its local
 * pure-const pass took this function for pure and dropped every call to it (the matrix
 * stayed 0: 3-D loops failed to assemble or to stay closed). */
static void scaled_rows(ac_loop_work *l, const double *s) {
    int i, j, nf = l->nfree, nr = l->nrows;
    for (j = 0; j < nf; j++) {
        const double *column = l->Hx + l->free[j] * AC_NC;
        for (i = 0; i < nr; i++) l->at[j + i * nf] = column[i] / s[i];
    }
}

/* l->d: the step from x onto H + ∂H/∂x d = 0 (least squares where inconsistent) whose free
 * part is closest to target − x (the held states do not move): with r = target − x and A, b
 * the rows scaled, d = r + A⁺ (b − A r) */
static void projection_step(ac_inst *m, const double *x, const double *target) {
    ac_loop_work *l = &m->loop;
    int i, j, nf = l->nfree;
    scaled_rows(l, l->s);
    for (i = 0; i < l->nrows; i++) {
        double c = -l->H[i] / l->s[i];
        for (j = 0; j < nf; j++) c -= l->at[j + i * nf] * (target[l->free[j]] - x[l->free[j]]);
        l->b[i] = c;
    }
    ac_min_norm_lstsq(l->at, nf, l->nrows, l->b, l->e, AC_RCOND, l->work, l->perm);
    memset(l->d, 0, sizeof(l->d));
    for (j = 0; j < nf; j++) l->d[l->free[j]] = target[l->free[j]] - x[l->free[j]] + l->e[j];
}

/* l->d scaled down so that no position moves by more than `most` (0: no limit) */
static void limit(ac_loop_work *l, double most) {
    double big = 0.0;
    int i;
    for (i = 0; i < AC_NPOS; i++)
        if (fabs(l->d[AC_POSITIONS[i]]) > big) big = fabs(l->d[AC_POSITIONS[i]]);
    if (most > 0 && big > most)
        for (i = 0; i < AC_NX; i++) l->d[i] *= most / big;
}

/* projection steps from x (updated) towards `target` until the step vanishes (at most `maxit`,
 * positions limited to `most`): AC_OK; AC_DISCARD when H is not finite; AC_ERROR */
static int iterate(ac_inst *m, double *x, const double *target, int maxit, double most) {
    ac_loop_work *l = &m->loop;
    int it, k, st;
    for (it = 0; it < maxit; it++) {
        double dn = 0.0, xn = 0.0;
        if ((st = constraints(m, x))) return st;
        projection_step(m, x, target);
        limit(l, most);
        for (k = 0; k < AC_NX; k++) {
            x[k] += l->d[k];
            dn += l->d[k] * l->d[k];
            xn += x[k] * x[k];
        }
        if (sqrt(dn) < 1e-13 * (1.0 + sqrt(xn))) break;
    }
    return AC_OK;
}

static double scaled_cost(const ac_loop_work *l, const double *s) {
    double c = 0.0;
    int i;
    for (i = 0; i < l->nrows; i++) c += (l->H[i] / s[i]) * (l->H[i] / s[i]);
    return c;
}

/* Levenberg–Marquardt on the row-scaled residual from x (updated to the best point reached):
 * steps d minimizing |A d + b|² + μ|d|², μ adapted to the progress (a singular Jacobian is
 * no obstacle), positions limited to AC_MOST; AC_OK, AC_DISCARD (H not finite at x) or
 * AC_ERROR */
static int descend(ac_inst *m, double *x, double scale) {
    ac_loop_work *l = &m->loop;
    double s[AC_NC], cost, mu = 1e-3;
    int it, i, j, k, st, nf = l->nfree, nr = l->nrows;
    if ((st = constraints(m, x))) return st;
    memcpy(s, l->s, sizeof(s));                  /* the scales of the start point throughout */
    cost = scaled_cost(l, s);
    for (it = 0; it < AC_DESCENT_MAX; it++) {
        scaled_rows(l, s);                       /* [A; √μ I] d = [−h/s; 0] */
        for (i = 0; i < nr; i++) l->b[i] = -l->H[i] / s[i];
        for (i = 0; i < nf; i++) {
            for (j = 0; j < nf; j++) l->at[j + (nr + i) * nf] = i == j ? sqrt(mu) : 0.0;
            l->b[nr + i] = 0.0;
        }
        ac_min_norm_lstsq(l->at, nf, nr + nf, l->b, l->e, AC_RCOND, l->work, l->perm);
        memset(l->d, 0, sizeof(l->d));
        for (j = 0; j < nf; j++) l->d[l->free[j]] = l->e[j];
        limit(l, AC_MOST);
        for (k = 0; k < AC_NX; k++) l->trial[k] = x[k] + l->d[k];
        if ((st = constraints(m, l->trial)) == AC_ERROR) return st;
        if (st == AC_OK && scaled_cost(l, s) < cost) {
            memcpy(x, l->trial, sizeof(double) * AC_NX);
            cost = scaled_cost(l, s);
            mu = mu / 10 > 1e-12 ? mu / 10 : 1e-12;
            if (solved(l, scale)) break;
        } else {
            mu *= 10;
            if (mu > 1e12) break;
            if ((st = constraints(m, x))) return st;     /* back at x */
        }
    }
    return AC_OK;
}

/* the assembly from x (updated): the projection, then, should it stall, the descent and the
 * projection again. AC_OK when it ends on H = 0, AC_DISCARD when not, AC_ERROR */
static int close_loops(ac_inst *m, double *x, double scale) {
    const double *start = m->loop.target;
    int st = iterate(m, x, start, AC_PROJECTION_MAX, AC_MOST);
    if (st == AC_ERROR) return st;
    if (st == AC_OK && (st = constraints(m, x)) == AC_OK && solved(&m->loop, scale)) return AC_OK;
    if (st == AC_ERROR || (st = descend(m, x, scale)) == AC_ERROR) return AC_ERROR;
    if ((st = iterate(m, x, start, AC_PROJECTION_MAX, AC_MOST)) == AC_ERROR) return st;
    if ((st = constraints(m, x))) return st;
    return solved(&m->loop, scale) ? AC_OK : AC_DISCARD;
}

#if AC_NH > 0
/* The loop rows to enforce at the current configuration, as simulate() chooses them
 * (acausal.numerics.independent_rows, the same rule): in row order, a row is on when
 * its Gram–Schmidt residual against the rows on before it exceeds 1e-9·max(1, max |Φ_q|);
 * the others are redundant there and switched off (loops.active_i = 0). */
static int select_loop_rows(ac_inst *m) {
    double J[AC_NPHI * AC_NQ], B[AC_NPHI * AC_NQ], r[AC_NQ], big = 0.0, tol;
    double *out[1] = {J};
    int i, j, k, pass, nb = 0;
    if (ac_eval(m, (ac_fn)ac_phiq, m->d.t, m->d.x, m->d.z, out, 1))
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
    return AC_OK;
}
#endif

/* ", "-separated into buf: the names of the rows first..last-1 of [H; E] whose scaled
 * residual (as evaluated last) exceeds 1e-10 */
static void unsatisfied(const ac_loop_work *l, int first, int last, char *buf, size_t size) {
    size_t n = 0;
    int i;
    buf[0] = '\0';
    for (i = first; i < last && n < size; i++)
        if (!(fabs(l->H[i]) / l->s[i] <= 1e-10))
            n += snprintf(buf + n, size - n, "%s%s", n ? ", " : "",
                          i < AC_NH ? AC_H_NAMES[i] : AC_IE_NAMES[i - AC_NH]);
}

static int is_position(int k) {
    int i;
    for (i = 0; i < AC_NPOS; i++) if (AC_POSITIONS[i] == k) return 1;
    return 0;
}

/* ", "-separated into buf: "name = value" of the start values the importer set (of the
 * positions only, or of every state) */
static void held(const ac_inst *m, int positions_only, char *buf, size_t size) {
    size_t n = 0;
    int k;
    buf[0] = '\0';
    for (k = 0; k < AC_NX && n < size; k++)
        if (m->d.x_set[k] && (!positions_only || is_position(k)))
            n += snprintf(buf + n, size - n, "%s%s = %g", n ? ", " : "", AC_X_NAMES[k],
                          m->d.x[k]);
}

#if AC_NH > 0
/* The error of an assembly that failed, naming the part at fault. `velocity_rows`: the
 * velocity constraints the first attempt left unsatisfied. The positions alone
 * (Φ, the first half of H) are assembled from the start values as above: if they close,
 * the speeds set contradict the velocity constraints Φ̇ = 0, which are linear in the
 * speeds; if not, the positions set or the parameters contradict Φ = 0. */
static int failed(ac_inst *m, double scale, const char *velocity_rows) {
    ac_loop_work *l = &m->loop;
    char rows[400], given[400];
    int st;
    memcpy(m->d.x, l->target, sizeof(l->target));
    l->nrows = AC_NH / 2;
    st = close_loops(m, m->d.x, scale);
    l->nrows = AC_NH;
    memcpy(m->d.x, l->target, sizeof(l->target));    /* the start values, as they were */
    ac_invalidate(m);
    if (st == AC_ERROR) return st;
    if (st == AC_OK) {
        held(m, 0, given, sizeof(given));
        return ERR("initialization: the kinematic loops cannot be closed: their positions "
                   "close but the speeds cannot satisfy %s; check the start values set "
                   "(%s): the loop leaves fewer speeds free; set fewer of them, or "
                   "consistent ones",
                   velocity_rows[0] ? velocity_rows : "the loop velocity constraints", given);
    }
    unsatisfied(l, 0, AC_NH / 2, rows, sizeof(rows));
    if (!rows[0]) snprintf(rows, sizeof(rows), "the loop constraints, not finite");
    held(m, 1, given, sizeof(given));
    return ERR("initialization: the kinematic loops cannot be closed (not satisfied: %s); "
               "check the parameters%s%s%s against the model's constraints", rows,
               given[0] ? " and the start values set (" : "", given, given[0] ? ")" : "");
}
#endif

/* The error of a start that failed where the initial equations `rows` (their labels, as the
 * first attempt left them) are not satisfied, with the loop constraints if any */
static int failed_initial(ac_inst *m, const char *rows) {
    char given[400];
    memcpy(m->d.x, m->loop.target, sizeof(m->loop.target));   /* the start values */
    ac_invalidate(m);
    held(m, 0, given, sizeof(given));
    return ERR("initialization: the initial equations cannot be satisfied (not satisfied: %s)%s; "
               "check them against the parameters, the inputs%s%s%s", rows,
               AC_NH > 0 ? " together with the loop constraints" : "",
               given[0] ? " and the start values set (" : " and the model's start values",
               given, given[0] ? ")" : "");
}

int ac_consistent_start(ac_inst *m) {
    /* states set by the importer are held, the others move least from their start values;
       restarts from deterministic perturbations of the free states, numerics.project's */
    ac_loop_work *l = &m->loop;
    double *x = m->d.x, scale = 0.0;
    char velocity_rows[400], initial[400];
    unsigned seed = 12345u;
    int k, attempt, st;
    memcpy(l->target, x, sizeof(l->target));
    l->nrows = AC_NC;
    l->nfree = 0;
    for (k = 0; k < AC_NX; k++) {
        if (!m->d.x_set[k]) l->free[l->nfree++] = k;
        if (fabs(x[k]) > scale) scale = fabs(x[k]);
    }
    for (k = 0; k < AC_NZ; k++) if (fabs(m->d.z[k]) > scale) scale = fabs(m->d.z[k]);
    scale += 1.0;
    velocity_rows[0] = initial[0] = '\0';
    for (attempt = 0; attempt <= AC_ASSEMBLY_RETRIES; attempt++) {
        memcpy(x, l->target, sizeof(l->target));
        for (k = 0; k < AC_NX && attempt; k++) {
            seed = seed * 1103515245u + 12345u;
            if (!m->d.x_set[k])
                x[k] += AC_ASSEMBLY_JITTER * (1.0 + fabs(x[k]))
                        * ((double)((seed >> 8) & 0xffffu) / 65535.0 - 0.5);
        }
        st = close_loops(m, x, scale);
        if (st == AC_ERROR) return st;
        if (st == AC_OK) {
            ac_invalidate(m);
#if AC_NH > 0
            return select_loop_rows(m);
#else
            return AC_OK;
#endif
        }
        if (attempt == 0) {
            unsatisfied(l, AC_NH / 2, AC_NH, velocity_rows, sizeof(velocity_rows));
            unsatisfied(l, AC_NH, AC_NC, initial, sizeof(initial));
        }
    }
#if AC_NH > 0
    if (!initial[0]) return failed(m, scale, velocity_rows);
#endif
    return failed_initial(m, initial[0] ? initial : "the initial equations, not finite");
}
#else
int ac_consistent_start(ac_inst *m) { (void)m; return AC_OK; }
#endif

#if AC_NH > 0
static double drift_tol(ac_inst *m) { return AC_DRIFT_FACTOR * m->d.rtol; }

static double con_norm(ac_inst *m, const double *x) {
    double *out[2] = {m->loop.H, NULL}, big = 0.0;
    int i;
    if (ac_eval(m, (ac_fn)ac_con, m->d.t, x, m->d.z, out, 2)) return HUGE_VAL;
    for (i = 0; i < AC_NH; i++) {
        if (!isfinite(m->loop.H[i])) return HUGE_VAL;
        if (fabs(m->loop.H[i]) > big) big = fabs(m->loop.H[i]);
    }
    return big;
}

int ac_drift_exceeded(ac_inst *m) { return con_norm(m, m->d.x) > drift_tol(m); }

int ac_keep_loops_closed(ac_inst *m, double factor, int *projected) {
    ac_loop_work *l = &m->loop;
    int k, st;
    if (projected) *projected = 0;
    if (con_norm(m, m->d.x) <= factor * drift_tol(m)) return AC_OK;
    l->nrows = AC_NH;
    l->nfree = AC_NX;
    for (k = 0; k < AC_NX; k++) l->free[k] = k;
    memcpy(l->target, m->d.x, sizeof(l->target));
    st = iterate(m, m->d.x, l->target, AC_DRIFT_MAX, 0.0);
    ac_invalidate(m);
    if (st == AC_ERROR) return st;
    if (st != AC_OK || con_norm(m, m->d.x) > drift_tol(m)) {
        double residual = con_norm(m, m->d.x);
        memcpy(m->d.x, l->target, sizeof(l->target));     /* the states as they were */
        ac_invalidate(m);
        return ERR("cannot satisfy the loop constraints at t = %g (residual %g): the "
                   "mechanism has left its assembled configuration", m->d.t, residual);
    }
    if (projected) *projected = 1;
    return AC_OK;
}
#else
int ac_drift_exceeded(ac_inst *m) { (void)m; return 0; }
int ac_keep_loops_closed(ac_inst *m, double factor, int *projected) {
    (void)m; (void)factor;
    if (projected) *projected = 0;
    return AC_OK;
}
#endif
