/* Closed kinematic loops and the initial equations: the states kept on the constraints
 * H = [Φ; Φ̇] = 0, the consistent start at initialization (the loops closed and the components'
 * initial equations E = 0 held, as acausal.simulation.initialization.initial_state holds them
 * at a simulation's start) and the choice of the loop rows to enforce (loops.active_i). The
 * start is acausal.numerics.project's algorithm on the rows [H; E], so that the FMU and
 * simulate() reach the same states from the same start values:
 *   - each step is the one onto the equations linearized at the current point that moves the
 *     free states least from their start values (exact in one step when they are linear, as
 *     the velocity constraints are in the speeds), every row of H scaled by its gradient's
 *     size; a minimum-norm least-squares solution from orthogonal factorizations
 *     (ac_min_norm_lstsq), well conditioned where normal equations would square the
 *     condition, and exact on redundant rows (rank-truncated like numpy's lstsq);
 *   - a step moves no position (the coordinates, AC_POSITIONS) by more than 0.3, so that a
 *     guess keeps a linkage on its branch; speeds are never held back;
 *   - should the projection stall (a singular configuration), a Levenberg–Marquardt descent
 *     on the row-scaled residual takes over, its damped steps −Jᵀ(J Jᵀ + μI)⁻¹ h computed as
 *     the least-squares solution of [J; √μ I] d = [−h; 0] (the same factorization, no
 *     squared condition), and the projection resumes;
 *   - then restarts from deterministic perturbations of the free states (numerics.project's
 *     seed sequence);
 *   - converged when every row, over its gradient's size, is below 1e-10·(1 + max |start|).
 * The states the importer set are held (not unknowns). The algebraic variables z are solved
 * at every point where E is evaluated (E's rows, and their gradients, are those of z(x):
 * ∂E/∂x − ∂E/∂z (∂g/∂z)⁻¹ ∂g/∂x), where initial_state has them free unknowns of the
 * projection: the same solution. Drift (model exchange, co-simulation) is projected onto
 * H = 0 by the same steps, from the states as they are, unlimited. Without loops and initial
 * equations (AC_NH = AC_NIE = 0) every function here does nothing and succeeds. */
#ifndef AC_LOOPS_H
#define AC_LOOPS_H

#include "model.h"

#define AC_NC (AC_NH + AC_NIE)        /* rows at initialization: [H; E] */
#define AC_NLS (AC_NC + AC_NX)        /* rows of the largest least-squares problem */

typedef struct {
    /* [H; E], ∂/∂x at the last point evaluated (leading dimension AC_NC), their rows' scales */
    double H[AC_D(AC_NC)], Hx[AC_D(AC_NC * AC_NX)], s[AC_D(AC_NC)];
    double Ez[AC_D(AC_NIE * AC_NZ)];                     /* ∂E/∂z */
    double target[AC_D(AC_NX)];                        /* the states a projection stays near */
    double d[AC_D(AC_NX)], trial[AC_D(AC_NX)];         /* a step; the point it leads to */
    double at[AC_D(AC_NX * AC_NLS)], b[AC_D(AC_NLS)], e[AC_D(AC_NX)];  /* least squares */
    double work[AC_D(AC_NLS * AC_NX + 2 * AC_NX + AC_NLS)];
    int perm[AC_D(AC_NLS)];
    int free[AC_D(AC_NX)], nfree;                      /* the states that move */
    int nrows;                      /* the rows in use: Φ (AC_NH/2), H (AC_NH) or [H; E] */
} ac_loop_work;

struct ac_inst;
/* initialization: close the loops and satisfy the initial equations from the start values
 * (the states the importer set are held), then switch off the loop rows redundant at the
 * assembled configuration; on failure the message names the loop constraints or initial
 * equations that cannot be satisfied and the start values set */
int ac_consistent_start(struct ac_inst *m);
/* max |H| above the drift threshold 1e-3·rtol (model exchange: ask for an event) */
int ac_drift_exceeded(struct ac_inst *m);
/* project the states onto H = 0 when max |H| exceeds factor·(the drift threshold);
 * *projected (may be NULL) says whether it did */
int ac_keep_loops_closed(struct ac_inst *m, double factor, int *projected);

#endif
