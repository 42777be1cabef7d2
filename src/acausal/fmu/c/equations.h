/* The model's equations: the CasADi-generated functions (model_functions.c) evaluated at
 * (t, x, z, p, u); Newton's method for the algebraic variables z; the instance's state
 * derivatives, outputs and recorded variables, cached until a value changes; the total
 * Jacobian of [ẋ; y]; the time events. */
#ifndef AC_EQUATIONS_H
#define AC_EQUATIONS_H

#include "model.h"

#define AC_NW (AC_NX + AC_NU + 1)          /* columns of the Jacobians: x, u, t */
#define AC_NF (AC_NX + AC_NY)              /* rows: xdot, y */

typedef int (*ac_fn)(const double **arg, double **res, long long *iw, double *w, int mem);

typedef struct {
    /* cached values at the instance's (t, x) and their valid flags */
    int valid_z, valid_xdot, valid_y, valid_rec;
    double xdot[AC_D(AC_NX)], y[AC_D(AC_NY)], rec[AC_D(AC_NREC)];
    /* CasADi work */
    const double *arg[AC_D(AC_SZ_ARG)];
    double *res[AC_D(AC_SZ_RES)];
    long long iw[AC_D(AC_SZ_IW)];
    double w[AC_D(AC_SZ_W)];
    /* Newton for z and the Jacobians */
    double g[AC_D(AC_NZ)];
    double Fw[AC_D(AC_NF * AC_NW)], Fz[AC_D(AC_NF * AC_NZ)];
    double gw[AC_D(AC_NZ * AC_NW)], gz[AC_D(AC_NZ * AC_NZ)];
    int piv[AC_D(AC_NZ)];
    double T[AC_D(AC_NF * AC_NW)];     /* total derivative of [xdot; y] w.r.t. [x; u; t] */
} ac_equations;

struct ac_inst;
/* f(t, x, z, p, u) into out[0..nout-1]; f(p) into out */
int ac_eval(struct ac_inst *m, ac_fn f, double t, const double *x, const double *z,
            double **out, int nout);
int ac_eval_p(struct ac_inst *m, ac_fn f, double *out);
/* z solved at (t, x) by Newton's method from the warm start z (updated) */
int ac_solve_z(struct ac_inst *m, double t, const double *x, double *z);
/* state derivatives at (t, x), z solved by Newton from the warm start z (updated) */
int ac_rhs(struct ac_inst *m, double t, const double *x, double *z, double *xdot);
/* ac_jac at (t, x, z) into eq (F_w, F_z, g_w, g_z), g_z factored (eq.piv) */
int ac_jacobians(struct ac_inst *m, double t, const double *x, const double *z);
/* A_w −= A_z·g_z⁻¹·g_w over the first ncols columns of w = [x; u; t]: z eliminated from the
 * derivatives of nrows rows (column-major), g_w and g_z as ac_jacobians left them */
void ac_eliminate_z(struct ac_inst *m, const double *Az, int nrows, double *Aw, int ncols);
/* eq.T at (t, x, z): z eliminated, F_w − F_z g_z⁻¹ g_w */
int ac_total_jacobian(struct ac_inst *m, double t, const double *x, const double *z);

/* the instance's values at its own (t, x): solved and cached */
void ac_invalidate(struct ac_inst *m);
int ac_ensure_z(struct ac_inst *m);
int ac_derivatives(struct ac_inst *m, double *xdot);     /* xdot may be NULL: eq.xdot */
int ac_outputs(struct ac_inst *m);                       /* into eq.y */
int ac_recorded(struct ac_inst *m);                      /* into eq.rec */

double ac_next_event(struct ac_inst *m, double t);      /* strictly after t; HUGE_VAL if none */

#endif
