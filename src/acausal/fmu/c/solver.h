/* The co-simulation solver: RODAS4 (Hairer & Wanner), a linearly implicit Rosenbrock method,
 * stiffly accurate, L-stable, order 4 with an embedded order-3 error estimate; the exact
 * Jacobian, step-size control on error ≤ atol·nominal + rtol·|x| (RMS norm), stops at time
 * events, the loops projected after every accepted step. */
#ifndef AC_SOLVER_H
#define AC_SOLVER_H

#include "model.h"

typedef struct {
    double W[AC_D(AC_NX * AC_NX)], ft[AC_D(AC_NX)];    /* W = I/(γh) − J, ∂f/∂t */
    double K[6][AC_D(AC_NX)];                          /* stages */
    double ytmp[AC_D(AC_NX)], f0[AC_D(AC_NX)], zs[AC_D(AC_NZ)];
    int piv[AC_D(AC_NX)];
} ac_solver_work;

struct ac_inst;
/* integrate from the instance's time to t0 + H; t0 must be the instance's time (to within
 * the Reference FMUs' tolerance, 1e-5 absolute or relative) and H > 0 */
int ac_do_step(struct ac_inst *m, double t0, double H);

#endif
