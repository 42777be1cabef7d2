/* Closed kinematic loops: the states kept on the constraints H = [Φ; Φ̇] = 0 by projection
 * (Gauss–Newton, the iteration of acausal.numerics.project), the assembly at
 * initialization and the choice of the loop rows to enforce (loops.active_i). Without loops
 * (AC_NH = 0) every function here does nothing and succeeds. */
#ifndef AC_LOOPS_H
#define AC_LOOPS_H

#include "model.h"

typedef struct {
    double H[AC_D(AC_NH)], Hx[AC_D(AC_NH * AC_NX)], A[AC_D(AC_NH * AC_NH)];
    double lam[AC_D(AC_NH)], xs[AC_D(AC_NX)];
    int piv[AC_D(AC_NH)];
} ac_loop_work;

struct ac_inst;
/* initialization: close the loops from the start values (the states the importer set are
 * held) and switch off the rows redundant at the assembled configuration */
int ac_assemble_loops(struct ac_inst *m);
/* max |H| above the drift threshold 1e-3·rtol (model exchange: ask for an event) */
int ac_drift_exceeded(struct ac_inst *m);
/* project the states onto H = 0 when max |H| exceeds factor·(the drift threshold);
 * *projected (may be NULL) says whether it did */
int ac_keep_loops_closed(struct ac_inst *m, double factor, int *projected);

#endif
