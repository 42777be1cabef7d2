/* acausal native FMU runtime: the model instance, its evaluation (CasADi-generated functions),
 * Newton's method for algebraic variables, projection onto closed-loop constraints, and the
 * Rosenbrock solver (RODAS4) of co-simulation. Shared by fmi2.c and fmi3.c.
 * model.h (generated per model) gives the sizes. */
#ifndef AC_RUNTIME_H
#define AC_RUNTIME_H

#include <stddef.h>
#include "model.h"

#define AC_D(n) ((n) > 0 ? (n) : 1)
#define AC_NW (AC_NX + AC_NU + 1)          /* columns of the Jacobians: x, u, t */
#define AC_NF (AC_NX + AC_NY)              /* rows: xdot, y */

enum { AC_OK = 0, AC_WARNING = 1, AC_DISCARD = 2, AC_ERROR = 3, AC_FATAL = 4 };
/* kinds of value references */
enum { AC_K_PARAM = 0, AC_K_INPUT, AC_K_OUTPUT, AC_K_STATE, AC_K_DER, AC_K_REC, AC_K_SOLVER,
       AC_K_TIME, AC_K_NONE, AC_K_SWITCH };   /* AC_K_SWITCH: a loop-row switch (calculated) */
/* life cycle */
enum { AC_INSTANTIATED = 0, AC_INIT, AC_EVENT, AC_CONT, AC_STEP, AC_TERMINATED, AC_FAILED };

/* Everything the FMU state (get/set/serialize) saves. Plain data, no pointers. */
typedef struct {
    double t;
    double x[AC_D(AC_NX)];
    double z[AC_D(AC_NZ)];
    double p[AC_D(AC_NP)];
    double u[AC_D(AC_NU)];
    unsigned char x_set[AC_D(AC_NX)];   /* start value set by the importer */
    double rtol, atol;
    int rtol_set, atol_set;
    double h;                           /* co-simulation: step size carried between steps */
    double next_event;                  /* next time event (HUGE_VAL: none) */
    int mode;
    int initialized;
    long n_steps, n_rejected, n_projections;
} ac_data;

struct ac_inst;
typedef void (*ac_log_fn)(struct ac_inst *inst, int status, const char *category,
                          const char *message);

typedef struct ac_inst {
    ac_data d;
    int is_cs;
    int logging_on;
    ac_log_fn log;
    void *env;                /* the FMI wrapper's callbacks */
    char name[256];
    /* caches, valid flags */
    int valid_z, valid_xdot, valid_y, valid_rec;
    double xdot[AC_D(AC_NX)], y[AC_D(AC_NY)], rec[AC_D(AC_NREC)];
    /* CasADi work */
    const double *arg[AC_D(AC_SZ_ARG)];
    double *res[AC_D(AC_SZ_RES)];
    long long iw[AC_D(AC_SZ_IW)];
    double w[AC_D(AC_SZ_W)];
    /* Jacobians and solver work */
    double Fw[AC_D(AC_NF * AC_NW)], Fz[AC_D(AC_NF * AC_NZ)];
    double gw[AC_D(AC_NZ * AC_NW)], gz[AC_D(AC_NZ * AC_NZ)];
    double g[AC_D(AC_NZ)];
    double T[AC_D(AC_NF * AC_NW)];     /* total derivative of [xdot; y] w.r.t. [x; u; t] */
    double J[AC_D(AC_NX * AC_NX)], ft[AC_D(AC_NX)];
    double W[AC_D(AC_NX * AC_NX)];
    int piv[AC_D(AC_NX > AC_NH ? AC_NX : AC_NH)];
    int zpiv[AC_D(AC_NZ)];             /* Newton's for z: RODAS4's stages solve z between
                                          uses of the pivots of W */
    double K[6][AC_D(AC_NX)];
    double y0[AC_D(AC_NX)], ytmp[AC_D(AC_NX)], f0[AC_D(AC_NX)];
    double H[AC_D(AC_NH)], Hx[AC_D(AC_NH * AC_NX)], A[AC_D(AC_NH * AC_NH)];
    double lam[AC_D(AC_NH)], xs[AC_D(AC_NX)];
    double zs[AC_D(AC_NZ)];
    char msg[1024];
} ac_inst;

extern const char *ac_model_name;
extern const char *ac_guid;

/* lifecycle */
void ac_defaults(ac_inst *m);
int ac_initialize(ac_inst *m);                 /* exit initialization mode */
/* values */
int ac_vr_kind(unsigned vr, int *index);
int ac_get_real(ac_inst *m, unsigned vr, double *value);
int ac_set_real(ac_inst *m, unsigned vr, double value);
void ac_set_time(ac_inst *m, double t);
void ac_set_states(ac_inst *m, const double *x);
void ac_nominals(double *nominal, size_t n);        /* of the states */
int ac_derivatives(ac_inst *m, double *xdot);
void ac_invalidate(ac_inst *m);
/* FMU state: a copy of the instance data, serialized with a magic number and its size */
int ac_state_get(ac_inst *m, void **state);
int ac_state_set(ac_inst *m, const void *state);
void ac_state_free(void **state);
size_t ac_state_size(void);
int ac_state_serialize(ac_inst *m, const void *state, void *bytes, size_t size);
int ac_state_deserialize(ac_inst *m, const void *bytes, size_t size, void **state);
void ac_tolerance(ac_inst *m, int defined, double tol);
/* events: time events and the loop constraints' drift (ME) */
double ac_next_event(ac_inst *m, double t);      /* strictly after t; HUGE_VAL if none */
int ac_drift_exceeded(ac_inst *m, int *exceeded);
int ac_event_update(ac_inst *m, int *states_changed);
/* co-simulation */
int ac_do_step(ac_inst *m, double t, double h);
/* directional derivatives of [xdot; y] (and states) w.r.t. states and inputs */
int ac_directional(ac_inst *m, const unsigned *unknowns, size_t nu, const unsigned *knowns,
                   size_t nk, const double *seed, double *out);
void ac_logf(ac_inst *m, int status, const char *category, const char *fmt, ...);
int ac_check_params(ac_inst *m);

#endif
