/* The model's equations (see equations.h). */
#include <math.h>
#include <string.h>

#include "instance.h"
#include "linalg.h"
#include "model_functions.h"

#define AC_NEWTON_MAX 50

int ac_eval(ac_inst *m, ac_fn f, double t, const double *x, const double *z, double **out,
            int nout) {
    int i;
    double tt = t;
    m->eq.arg[0] = &tt; m->eq.arg[1] = x; m->eq.arg[2] = z;      /* (t, x, z, u, p) */
    m->eq.arg[3] = m->d.u; m->eq.arg[4] = m->d.p;
    for (i = 0; i < nout; i++) m->eq.res[i] = out[i];
    return f(m->eq.arg, m->eq.res, m->eq.iw, m->eq.w, 0);
}

int ac_eval_p(ac_inst *m, ac_fn f, double *out) {
    m->eq.arg[0] = m->d.p;
    m->eq.res[0] = out;
    return f(m->eq.arg, m->eq.res, m->eq.iw, m->eq.w, 0);
}

/* Newton's method for the algebraic variables z at (t, x), warm-started from z. */
int ac_solve_z(ac_inst *m, double t, const double *x, double *z) {
#if AC_NZ > 0
    ac_equations *e = &m->eq;
    int it, i;
    for (it = 0; it < AC_NEWTON_MAX; it++) {
        double *out[2] = {e->g, e->gz}, step = 0.0, size = 0.0;
        if (ac_eval(m, (ac_fn)ac_alg, t, x, z, out, 2)) return ERR("evaluating the algebraic equations failed");
        if (!ac_all_finite(e->g, AC_NZ) || !ac_all_finite(e->gz, AC_NZ * AC_NZ))
            return ERR("the algebraic equations are not finite at t = %g", t);
        if (ac_lu(e->gz, AC_NZ, e->piv))
            return ERR("the algebraic equations for %s are singular at t = %g", AC_Z_NAMES[0], t);
        for (i = 0; i < AC_NZ; i++) e->g[i] = -e->g[i];
        ac_lu_solve(e->gz, AC_NZ, e->piv, e->g);
        for (i = 0; i < AC_NZ; i++) {
            z[i] += e->g[i];
            if (fabs(e->g[i]) > step) step = fabs(e->g[i]);
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

int ac_rhs(ac_inst *m, double t, const double *x, double *z, double *xdot) {
    double *out[1] = {xdot};
    if (ac_solve_z(m, t, x, z)) return AC_ERROR;
    if (ac_eval(m, (ac_fn)ac_ode, t, x, z, out, 1)) return ERR("evaluating the derivatives failed");
    if (!ac_all_finite(xdot, AC_NX)) return ERR("the state derivatives are not finite at t = %g", t);
    return AC_OK;
}

int ac_jacobians(ac_inst *m, double t, const double *x, const double *z) {
    ac_equations *e = &m->eq;
    double *out[4] = {e->Fw, e->Fz, e->gw, e->gz};
    if (ac_eval(m, (ac_fn)ac_jac, t, x, z, out, 4)) return ERR("evaluating the Jacobian failed");
#if AC_NZ > 0
    if (ac_lu(e->gz, AC_NZ, e->piv)) return ERR("the algebraic equations are singular at t = %g", t);
#endif
    return AC_OK;
}

void ac_eliminate_z(ac_inst *m, const double *Az, int nrows, double *Aw, int ncols) {
#if AC_NZ > 0
    ac_equations *e = &m->eq;
    double *s = e->g;            /* scratch: ac_solve_z is not running here */
    int i, j, k;
    for (j = 0; j < ncols; j++) {
        for (k = 0; k < AC_NZ; k++) s[k] = e->gw[k + j * AC_NZ];
        ac_lu_solve(e->gz, AC_NZ, e->piv, s);
        for (i = 0; i < nrows; i++) {
            double acc = 0.0;
            for (k = 0; k < AC_NZ; k++) acc += Az[i + k * nrows] * s[k];
            Aw[i + j * nrows] -= acc;
        }
    }
#else
    (void)m; (void)Az; (void)nrows; (void)Aw; (void)ncols;
#endif
}

int ac_total_jacobian(ac_inst *m, double t, const double *x, const double *z) {
    ac_equations *e = &m->eq;
    if (ac_jacobians(m, t, x, z)) return AC_ERROR;
    memcpy(e->T, e->Fw, sizeof(double) * AC_NF * AC_NW);
    ac_eliminate_z(m, e->Fz, AC_NF, e->T, AC_NW);
    if (!ac_all_finite(e->T, AC_NF * AC_NW)) return ERR("the Jacobian is not finite at t = %g", t);
    return AC_OK;
}

/* ---- the instance's values, cached ---------------------------------------------------- */
void ac_invalidate(ac_inst *m) {
    m->eq.valid_z = m->eq.valid_xdot = m->eq.valid_y = m->eq.valid_rec = 0;
}

int ac_ensure_z(ac_inst *m) {
    if (m->eq.valid_z) return AC_OK;
    if (ac_solve_z(m, m->d.t, m->d.x, m->d.z)) return AC_ERROR;
    m->eq.valid_z = 1;
    return AC_OK;
}

int ac_derivatives(ac_inst *m, double *xdot) {
    if (!m->eq.valid_xdot) {
        double *out[1] = {m->eq.xdot};
        if (ac_ensure_z(m)) return AC_ERROR;
        if (ac_eval(m, (ac_fn)ac_ode, m->d.t, m->d.x, m->d.z, out, 1)) return ERR("evaluating the derivatives failed");
        if (!ac_all_finite(m->eq.xdot, AC_NX)) return ERR("the state derivatives are not finite at t = %g", m->d.t);
        m->eq.valid_xdot = 1;
    }
    if (xdot) memcpy(xdot, m->eq.xdot, sizeof(double) * AC_NX);
    return AC_OK;
}

int ac_outputs(ac_inst *m) {
    double *out[1] = {m->eq.y};
    if (m->eq.valid_y) return AC_OK;
    if (ac_ensure_z(m)) return AC_ERROR;
    if (ac_eval(m, (ac_fn)ac_out, m->d.t, m->d.x, m->d.z, out, 1)) return ERR("evaluating the outputs failed");
    m->eq.valid_y = 1;
    return AC_OK;
}

int ac_recorded(ac_inst *m) {
    double *out[1] = {m->eq.rec};
    if (m->eq.valid_rec) return AC_OK;
    if (ac_ensure_z(m)) return AC_ERROR;
    if (ac_eval(m, (ac_fn)ac_rec, m->d.t, m->d.x, m->d.z, out, 1)) return ERR("evaluating the variables failed");
    m->eq.valid_rec = 1;
    return AC_OK;
}

/* ---- time events ---------------------------------------------------------------------- */
double ac_next_event(ac_inst *m, double t) {
#if AC_NEV > 0
    double ev[2 * AC_NEV], best = HUGE_VAL, eps = 1e-13 * (fabs(t) > 1 ? fabs(t) : 1);
    int i;
    if (ac_eval_p(m, (ac_fn)ac_events, ev)) return HUGE_VAL;
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
