/* The co-simulation solver, RODAS4 (see solver.h). */
#include <math.h>
#include <string.h>

#include "instance.h"
#include "linalg.h"

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
    ac_solver_work *s = &m->solver;
    double *y = m->d.x, *yt = s->ytmp, (*K)[AC_D(AC_NX)] = s->K;
    double *z = s->zs;
    const double *T = m->eq.T;
    int i, j;
    /* Jacobian, time derivative and W = I/(γh) − J at (t, y) */
    memcpy(z, m->d.z, sizeof(double) * AC_NZ);
    if (ac_rhs(m, t, y, z, s->f0)) return AC_DISCARD;
    if (ac_total_jacobian(m, t, y, z)) return AC_DISCARD;
    for (j = 0; j < AC_NX; j++) {
        for (i = 0; i < AC_NX; i++) s->W[i + j * AC_NX] = -T[i + j * AC_NF];
        s->W[j + j * AC_NX] += 1.0 / (G_ * h);
    }
    for (i = 0; i < AC_NX; i++) s->ft[i] = T[i + (AC_NX + AC_NU) * AC_NF];
    if (ac_lu(s->W, AC_NX, s->piv)) return AC_DISCARD;
#define STAGE(k, tk, expr_y, expr_rhs)                                             \
    for (i = 0; i < AC_NX; i++) yt[i] = y[i] + (expr_y);                           \
    if (ac_rhs(m, t + (tk) * h, yt, z, K[k])) return AC_DISCARD;                   \
    for (i = 0; i < AC_NX; i++) K[k][i] += (expr_rhs);                             \
    ac_lu_solve(s->W, AC_NX, s->piv, K[k]);
    for (i = 0; i < AC_NX; i++) K[0][i] = s->f0[i] + h * D1 * s->ft[i];
    ac_lu_solve(s->W, AC_NX, s->piv, K[0]);
    STAGE(1, C2, A21 * K[0][i], h * D2 * s->ft[i] + C21 * K[0][i] / h)
    STAGE(2, C3, A31 * K[0][i] + A32 * K[1][i],
          h * D3 * s->ft[i] + (C31 * K[0][i] + C32 * K[1][i]) / h)
    STAGE(3, C4, A41 * K[0][i] + A42 * K[1][i] + A43 * K[2][i],
          h * D4 * s->ft[i] + (C41 * K[0][i] + C42 * K[1][i] + C43 * K[2][i]) / h)
    STAGE(4, 1.0, A51 * K[0][i] + A52 * K[1][i] + A53 * K[2][i] + A54 * K[3][i],
          (C51 * K[0][i] + C52 * K[1][i] + C53 * K[2][i] + C54 * K[3][i]) / h)
    /* stage 6 at y + Σ a5j Kj + K5; the error estimate is K6 */
    for (i = 0; i < AC_NX; i++)
        yt[i] = y[i] + A51 * K[0][i] + A52 * K[1][i] + A53 * K[2][i] + A54 * K[3][i] + K[4][i];
    if (ac_rhs(m, t + h, yt, z, K[5])) return AC_DISCARD;
    for (i = 0; i < AC_NX; i++)
        K[5][i] += (C61 * K[0][i] + C62 * K[1][i] + C63 * K[2][i] + C64 * K[3][i] + C65 * K[4][i]) / h;
    ac_lu_solve(s->W, AC_NX, s->piv, K[5]);
    for (i = 0; i < AC_NX; i++) yt[i] += K[5][i];
#undef STAGE
    if (!ac_all_finite(yt, AC_NX)) return AC_DISCARD;
    return AC_OK;
}

static double err_norm(ac_inst *m) {
    double s = 0.0;
    int i;
    for (i = 0; i < AC_NX; i++) {
        double a = fabs(m->d.x[i]), b = fabs(m->solver.ytmp[i]);
        double sc = m->d.atol * AC_X_NOMINAL[i] + m->d.rtol * (a > b ? a : b);
        double e = m->solver.K[5][i] / sc;
        s += e * e;
    }
    return AC_NX > 0 ? sqrt(s / AC_NX) : 0.0;
}

static int any_crossed(ac_inst *m, const double *g) {
    int i;
    for (i = 0; i < AC_NG; i++) {
        double s = m->d.sides[i];
        if (ac_side(ac_reported(g[i], s), s) != s) return 1;
    }
    return 0;
}

/* a step from (t, m->d.x) to te crossed (solver.g at its end, solver.zc its z): the
 * crossing located, the instance put at the bracket's end after it, the event's left limit */
static int locate(ac_inst *m, double t, double te) {
    ac_solver_work *s = &m->solver;
    double H = te - t, lo = 0.0, hi = H, w[3] = {H, H, H};
    double tol = AC_EVENT_TOL * (fabs(te) > 1 ? fabs(te) : 1);
    int i, n = 0;
    memcpy(s->g_hi, s->g, sizeof(s->g));
    memcpy(s->x_hi, s->ytmp, sizeof(s->x_hi));
    memcpy(s->z_hi, s->zc, sizeof(s->z_hi));
    memcpy(s->zc, m->d.z, sizeof(s->zc));
    if (ac_indicators_at(m, t, m->d.x, s->zc, s->g_lo)) return AC_ERROR;
    while (hi - lo > tol) {
        double a;
        if (n >= 2 && w[2] > 0.5 * w[0]) a = 0.5 * (lo + hi);        /* slow: bisect */
        else {          /* the earliest secant estimate among the crossed indicators */
            double frac = 1.0;
            for (i = 0; i < AC_NG; i++) {
                double side = m->d.sides[i], f;
                double ga = ac_reported(s->g_lo[i], side), gb = ac_reported(s->g_hi[i], side);
                if (ac_side(gb, side) == side) continue;
                f = ga / (ga == gb ? 1.0 : ga - gb);
                f = f < 0 ? 0 : f > 1 ? 1 : f;
                if (f < frac) frac = f;
            }
            a = lo + frac * (hi - lo);
        }
        if (a < lo + 0.25 * tol) a = lo + 0.25 * tol;
        if (a > hi - 0.25 * tol) a = hi - 0.25 * tol;
        if (rodas_step(m, t, a) != AC_OK)
            return ERR("co-simulation solver: locating a state event failed at t = %.17g", t + a);
        memcpy(s->zc, s->zs, sizeof(s->zc));
        if (ac_indicators_at(m, t + a, s->ytmp, s->zc, s->g)) return AC_ERROR;
        if (any_crossed(m, s->g)) {
            hi = a;
            memcpy(s->g_hi, s->g, sizeof(s->g));
            memcpy(s->x_hi, s->ytmp, sizeof(s->x_hi));
            memcpy(s->z_hi, s->zc, sizeof(s->z_hi));
        } else {
            lo = a;
            memcpy(s->g_lo, s->g, sizeof(s->g));
        }
        w[0] = w[1]; w[1] = w[2]; w[2] = hi - lo;
        n++;
    }
    memcpy(m->d.x, s->x_hi, sizeof(double) * AC_NX);
    memcpy(m->d.z, s->z_hi, sizeof(double) * AC_NZ);
    m->d.t = hi == H ? te : t + hi;
    ac_invalidate(m);
    return AC_OK;
}

/* integrate the states from m->d.t to t1 (no time event inside), running the state events;
 * ends at an event after which a termination condition holds (m->d.terminated) */
static int integrate(ac_inst *m, double t1) {
    double t = m->d.t, h = m->d.h, span = t1 - t;
    int rejected = 0, ends = 0;
    if (span <= 0) return AC_OK;
    if (AC_NX == 0) { m->d.t = t1; return AC_OK; }
    if (!(h > 0)) {   /* initial step from the size of the derivatives */
        double d0 = 0.0, d1 = 0.0;
        int i;
        if (ac_derivatives(m, NULL)) return AC_ERROR;
        for (i = 0; i < AC_NX; i++) {
            double sc = m->d.atol * AC_X_NOMINAL[i] + m->d.rtol * fabs(m->d.x[i]);
            d0 += (m->d.x[i] / sc) * (m->d.x[i] / sc);
            d1 += (m->eq.xdot[i] / sc) * (m->eq.xdot[i] / sc);
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
            h = 0.25 * hs;
            rejected = 1;
            continue;
        }
        err = err_norm(m);
        fac = err > 0 ? 0.9 * pow(err, -0.25) : 5.0;
        if (fac > 5.0) fac = 5.0;
        if (fac < 0.2) fac = 0.2;
        if (err <= 1.0 && AC_NG > 0) {     /* a state event inside the step? */
            double te = last ? t1 : t + hs;
            memcpy(m->solver.zc, m->solver.zs, sizeof(m->solver.zc));
            if (ac_indicators_at(m, te, m->solver.ytmp, m->solver.zc, m->solver.g)) return AC_ERROR;
            if (ac_crossing(m, m->solver.g)) {
                if (locate(m, t, te)) return AC_ERROR;
                if (ac_state_event(m, 0, NULL)) return AC_ERROR;
                if (ac_keep_loops_closed(m, 1e-3, NULL)) return AC_ERROR;
                if (ac_check_assertions(m)) return AC_ERROR;
                if (ac_termination(m, &ends)) return AC_ERROR;
                if (ends) return AC_OK;
                t = m->d.t;
                rejected = 0;
                continue;
            }
        }
        if (err <= 1.0) {
            memcpy(m->d.x, m->solver.ytmp, sizeof(double) * AC_NX);
            memcpy(m->d.z, m->solver.zs, sizeof(double) * AC_NZ);
            t = last ? t1 : t + hs;
            m->d.t = t;
            ac_invalidate(m);
            if (ac_keep_loops_closed(m, 1e-3, NULL)) return AC_ERROR;
            if (ac_check_assertions(m)) return AC_ERROR;
            if (rejected && fac > 1.0) fac = 1.0;
            rejected = 0;
            if (last) { if (hs * fac > h) h = hs * fac; }
            else h = hs * fac;
        } else {
            rejected = 1;
            h = hs * fac;
        }
    }
    m->d.h = h;
    return AC_OK;
}

/* to t1 from the instance's time, stopping just before every time event and restarting at
 * it; at a termination (m->d.terminated) the instance stays at its event */
static int advance(ac_inst *m, double t1) {
    double tol = 1e-10 * (fabs(t1) > 1 ? fabs(t1) : 1);
    int ends = 0;
    /* a parameter changed between steps may have opened the loops */
    if (ac_keep_loops_closed(m, 1.0, NULL)) return AC_ERROR;
    while (m->d.t < t1 - tol) {
        double te = ac_next_event(m, m->d.t);
        if (te < t1 + tol) {
            double end = te - 1e-12 * (fabs(te) > 1 ? fabs(te) : 1);
            if (end > m->d.t && integrate(m, end)) return AC_ERROR;
            if (m->d.terminated) return AC_OK;
            m->d.t = te > t1 ? t1 : te;
            ac_invalidate(m);
            if (ac_state_event(m, 0, NULL)) return AC_ERROR;     /* crossings there, modes */
            if (ac_check_assertions(m)) return AC_ERROR;
            if (ac_termination(m, &ends)) return AC_ERROR;
            if (ends) return AC_OK;
        } else {
            if (integrate(m, t1)) return AC_ERROR;
            if (m->d.terminated) return AC_OK;
        }
    }
    m->d.t = t1;
    ac_invalidate(m);
    return AC_OK;
}

/* the Reference FMUs' rule for a communication point at the FMU's time */
static int is_close(double a, double b) {
    double d = fabs(a - b), big = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
    return d <= 1e-5 || d <= 1e-5 * big;
}

int ac_do_step(ac_inst *m, double t0, double H) {
    double t1 = t0 + H;
    if (!isfinite(t0) || !isfinite(H) || !(H > 0))
        return ERR("doStep from t = %g over %g: the communication point must be finite and "
                   "the step size finite and > 0", t0, H);
    if (m->d.terminated)
        return ERR("doStep from t = %.17g: the simulation has terminated at t = %.17g (a "
                   "termination condition); call terminate", t0, m->d.t);
    if (!is_close(t0, m->d.t))
        return ERR("doStep from t = %.17g but the FMU is at t = %.17g", t0, m->d.t);
    if (!(t1 > m->d.t))
        return ERR("doStep to t = %.17g: the FMU is already at t = %.17g", t1, m->d.t);
    if (advance(m, t1)) { m->d.mode = AC_FAILED; return AC_ERROR; }
    return AC_OK;
}
