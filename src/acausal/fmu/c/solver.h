/* The co-simulation solver: RODAS4 (Hairer & Wanner), a linearly implicit Rosenbrock method,
 * stiffly accurate, L-stable, order 4 with an embedded order-3 error estimate; the exact
 * Jacobian, step-size control on error ≤ atol·nominal + rtol·|x| (RMS norm), stops at time
 * events, the loops projected after every accepted step. State events (events.h): after an
 * accepted step the indicators' sides are checked; a crossing is located inside the step as
 * acausal.simulation.events locates it (secant steps on the crossed indicators, bisection
 * when the bracket shrinks slowly, to AC_EVENT_TOL·max(1, |t|)), each trial point a single
 * RODAS4 step from the step's start (no larger than the accepted one, so as accurate); the
 * bracket's end is the event's left limit, where the event is run and integration goes on. */
#ifndef AC_SOLVER_H
#define AC_SOLVER_H

#include "model.h"

typedef struct {
    double W[AC_D(AC_NX * AC_NX)], ft[AC_D(AC_NX)];    /* W = I/(γh) − J, ∂f/∂t */
    double K[6][AC_D(AC_NX)];                          /* stages */
    double ytmp[AC_D(AC_NX)], f0[AC_D(AC_NX)], zs[AC_D(AC_NZ)];
    int piv[AC_D(AC_NX)];
    /* state events: indicators at a step's end and the bracket's ends while locating */
    double g[AC_D(AC_NG)], g_lo[AC_D(AC_NG)], g_hi[AC_D(AC_NG)];
    double x_hi[AC_D(AC_NX)], z_hi[AC_D(AC_NZ)], zc[AC_D(AC_NZ)];
} ac_solver_work;

struct ac_inst;
/* integrate from the instance's time to t0 + H; t0 must be the instance's time (to within
 * the Reference FMUs' tolerance, 1e-5 absolute or relative) and H > 0. A termination
 * condition that holds after an event inside ends the step there: AC_OK with the instance
 * at the event's time and m->d.terminated set (the adapters report it) */
int ac_do_step(struct ac_inst *m, double t0, double H);

#endif
