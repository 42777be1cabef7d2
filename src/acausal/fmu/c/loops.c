/* Closed kinematic loops (see loops.h). */
#include <math.h>
#include <string.h>

#include "instance.h"
#include "linalg.h"
#include "model_functions.h"

#define AC_DRIFT_FACTOR 1e-3      /* project when |Φ|, |Φ̇| > 1e-3 · rtol */
#define AC_PROJ_MAX 200
#define AC_ASSEMBLY_RETRIES 4     /* assembly restarts from perturbed start values ... */
#define AC_ASSEMBLY_JITTER 0.1    /* ... moved by up to ±0.05·(1 + |start|) */

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

/* The point closest to `target` (metric diag(D)) on H(x) = 0 by the iteration of
 * acausal.numerics.project, starting from x (updated in place):
 * x <- target + D Hxᵀ (Hx D Hxᵀ)⁻¹ (Hx (x − target) − H), steps limited to `maxstep` per
 * state. D = 0 holds a state fixed. Returns AC_ERROR, unlogged, when the iteration ends with
 * max |H| above 1e3·tol (the caller says what failed); evaluation failures are logged. */
static int project(ac_inst *m, double *x, const double *target, const double *D,
                   double maxstep, int maxit, double tol) {
    ac_loop_work *l = &m->loop;
    int it, i, j, k;
    for (it = 0; it < maxit; it++) {
        double *out[2] = {l->H, l->Hx}, big = 0.0, stepn = 0.0, xn = 0.0, reg = 0.0;
        if (ac_eval(m, (ac_fn)ac_con, m->d.t, x, m->d.z, out, 2)) return ERR("evaluating the loop constraints failed");
        if (!ac_all_finite(l->H, AC_NH) || !ac_all_finite(l->Hx, AC_NH * AC_NX))
            return ERR("the loop constraints are not finite at t = %g", m->d.t);
        for (i = 0; i < AC_NH; i++) if (fabs(l->H[i]) > big) big = fabs(l->H[i]);
        /* A = Hx D Hxᵀ (+ a tiny regularization for switched-off rows), rhs = Hx (x - target) - H */
        for (i = 0; i < AC_NH; i++) {
            double r = -l->H[i];
            for (k = 0; k < AC_NX; k++) r += l->Hx[i + k * AC_NH] * (x[k] - target[k]);
            l->lam[i] = r;
            for (j = 0; j < AC_NH; j++) {
                double a = 0.0;
                for (k = 0; k < AC_NX; k++) a += l->Hx[i + k * AC_NH] * D[k] * l->Hx[j + k * AC_NH];
                l->A[i + j * AC_NH] = a;
            }
            if (l->A[i + i * AC_NH] > reg) reg = l->A[i + i * AC_NH];
        }
        for (i = 0; i < AC_NH; i++) l->A[i + i * AC_NH] += 1e-14 * (reg > 0 ? reg : 1.0);
        if (ac_lu(l->A, AC_NH, l->piv)) return ERR("the loop constraints are singular at t = %g", m->d.t);
        ac_lu_solve(l->A, AC_NH, l->piv, l->lam);
        for (k = 0; k < AC_NX; k++) {
            double s = 0.0;
            for (i = 0; i < AC_NH; i++) s += l->Hx[i + k * AC_NH] * l->lam[i];
            l->xs[k] = target[k] + D[k] * s - x[k];
            if (fabs(l->xs[k]) > stepn) stepn = fabs(l->xs[k]);
            if (fabs(x[k]) > xn) xn = fabs(x[k]);
        }
        if (big <= tol && stepn <= 1e-12 * (1.0 + xn)) break;
        if (maxstep > 0 && stepn > maxstep)
            for (k = 0; k < AC_NX; k++) l->xs[k] *= maxstep / stepn;
        for (k = 0; k < AC_NX; k++) x[k] += l->xs[k];
        if (stepn <= 1e-14 * (1.0 + xn)) break;
    }
    if (con_norm(m, x) > 1e3 * tol + 1e-10) return AC_ERROR;
    ac_invalidate(m);
    return AC_OK;
}

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

int ac_assemble_loops(ac_inst *m) {
    /* states set by the importer are held, the others move least from their start values.
       A start at a singular configuration (e.g. a linkage with every joint at 0) can stall
       the iteration; it is retried from a few deterministic perturbations of the free
       states, as acausal.numerics.project does. */
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
    return select_loop_rows(m);
}

int ac_drift_exceeded(ac_inst *m) { return con_norm(m, m->d.x) > drift_tol(m); }

int ac_keep_loops_closed(ac_inst *m, double factor, int *projected) {
    double D[AC_NX], target[AC_NX];
    int k;
    if (projected) *projected = 0;
    if (con_norm(m, m->d.x) <= factor * drift_tol(m)) return AC_OK;
    for (k = 0; k < AC_NX; k++) D[k] = 1.0;
    memcpy(target, m->d.x, sizeof(target));
    if (project(m, m->d.x, target, D, 0.0, 20, 1e-3 * drift_tol(m))) {
        double residual = con_norm(m, m->d.x);
        memcpy(m->d.x, target, sizeof(target));       /* the states as they were */
        ac_invalidate(m);
        return ERR("cannot satisfy the loop constraints at t = %g (residual %g): the "
                   "mechanism has left its assembled configuration", m->d.t, residual);
    }
    if (projected) *projected = 1;
    return AC_OK;
}
#else
int ac_assemble_loops(ac_inst *m) { (void)m; return AC_OK; }
int ac_drift_exceeded(ac_inst *m) { (void)m; return 0; }
int ac_keep_loops_closed(ac_inst *m, double factor, int *projected) {
    (void)m; (void)factor;
    if (projected) *projected = 0;
    return AC_OK;
}
#endif
