/* The model instance of a native FMU, shared by the FMI 2 and FMI 3 adapters (fmi2.c,
 * fmi3.c): its data, life cycle, variables by value reference, start values, parameters,
 * states, the FMU state and the logger. The model's sizes and tables are generated per model
 * (model.h, model_data.c); its equations are evaluated by equations.c, its closed loops kept
 * by loops.c and its co-simulation steps taken by solver.c. */
#ifndef AC_INSTANCE_H
#define AC_INSTANCE_H

#include <stddef.h>

#include "model.h"
#include "equations.h"
#include "events.h"
#include "loops.h"
#include "solver.h"

enum { AC_OK = 0, AC_WARNING = 1, AC_DISCARD = 2, AC_ERROR = 3, AC_FATAL = 4 };
/* kinds of value references (export.py's KINDS) */
enum { AC_K_PARAM = 0, AC_K_INPUT, AC_K_OUTPUT, AC_K_STATE, AC_K_DER, AC_K_REC, AC_K_SOLVER,
       AC_K_TIME, AC_K_NONE, AC_K_SWITCH,   /* AC_K_SWITCH: a loop-row switch (calculated) */
       AC_K_MODE, AC_K_IND };               /* a discrete mode (in p), an event indicator */
/* life-cycle modes, bits so that a set of them is a mask. AC_FAILED: a computation failed
 * (initialization, a step, an event update); the instance can then be read, restored from
 * an FMU state, reset or freed. */
enum { AC_INSTANTIATED = 1, AC_INIT = 2, AC_EVENT = 4, AC_CONT = 8, AC_STEP = 16,
       AC_TERMINATED = 32, AC_FAILED = 64 };
/* the modes each kind of call is allowed in (the Reference FMUs' masks of FMI 3, which FMI 2
 * follows where its functions correspond) */
#define AC_ANY 127
#define AC_SETTABLE (AC_INSTANTIATED | AC_INIT | AC_EVENT | AC_CONT | AC_STEP)  /* set values */
#define AC_RUNNING (AC_EVENT | AC_CONT | AC_STEP)                               /* terminate */
#define AC_EVALUABLE (AC_INIT | AC_RUNNING | AC_TERMINATED)   /* directional derivatives */
#define AC_STATES_READABLE (AC_INIT | AC_EVENT | AC_CONT | AC_TERMINATED | AC_FAILED)

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
    double last_tick[AC_D(AC_NCLOCK)];  /* when each sample trigger last ticked (or the
                                           start) */
    double sides[AC_D(AC_NG)];          /* the indicators' sides at the last accepted step or
                                           event (events.h); the modes are in p */
    double recent_t[AC_CHATTER_EVENTS]; /* the last state events (a ring): time, indicator */
    int recent_g[AC_CHATTER_EVENTS], n_recent;
    int mode;
    int initialized;
    double t_start;                     /* the time at initialization */
    int terminated;                     /* a termination condition ended the run (events.h) */
} ac_data;

struct ac_inst;
typedef void (*ac_log_fn)(struct ac_inst *inst, int status, const char *category,
                          const char *message);

typedef struct ac_inst {
    ac_data d;
    int is_cs;
    int logging_on;
    ac_log_fn log;            /* the adapter's: forwards to the importer's logger */
    char name[256];
    ac_equations eq;          /* cached values and evaluation work */
    ac_loop_work loop;
    ac_solver_work solver;
    char msg[1024];
} ac_inst;

/* logging: through the adapter's logger; AC_OK messages only with logging on */
void ac_logf(ac_inst *m, int status, const char *category, const char *fmt, ...);
/* an AC_OK message the importer sees whatever its logging setting (a termination's) */
void ac_notef(ac_inst *m, const char *category, const char *fmt, ...);
#define ERR(...) (ac_logf(m, AC_ERROR, "logStatusError", __VA_ARGS__), AC_ERROR)

/* life cycle. ac_allowed: 1 if the instance is in one of `modes`; else 0, logged naming
 * the FMI function `fn` (a NULL instance: 0, unlogged) */
int ac_allowed(ac_inst *m, int modes, const char *fn);
int ac_instantiate(ac_inst *m, const char *name, const char *token, int is_cs, int logging_on,
                   ac_log_fn log);             /* AC_ERROR (logged): not this FMU's token */
void ac_defaults(ac_inst *m);                  /* instantiated: defaults and start values */
int ac_setup(ac_inst *m, int tolerance_defined, double tolerance, double start_time);
int ac_exit_initialization(ac_inst *m);        /* to event mode (ME) or step mode (CS) */
/* ME: project the loops, the state event (reinits, event iteration of the modes), next event;
 * *states_changed: states projected or reinitialized, or modes changed; *terminate: a
 * termination condition holds after the event (not at the start time, as events.py) */
int ac_event_update(ac_inst *m, int *states_changed, int *terminate);
/* after an accepted step of the importer's integrator (model exchange): the assertions */
int ac_completed_step(ac_inst *m);
/* values by value reference */
int ac_get_reals(ac_inst *m, const unsigned *vr, size_t n, double *values);
int ac_set_reals(ac_inst *m, const unsigned *vr, size_t n, const double *values);
int ac_set_time(ac_inst *m, double t);
/* the continuous states: n must be AC_NX */
int ac_get_states(ac_inst *m, double *x, size_t n);
int ac_set_states(ac_inst *m, const double *x, size_t n);
int ac_get_derivatives(ac_inst *m, double *xdot, size_t n);
void ac_nominals(double *nominal, size_t n);
/* directional derivatives of [xdot; y] (and states) w.r.t. states and inputs */
int ac_directional(ac_inst *m, const unsigned *unknowns, size_t nu, const unsigned *knowns,
                   size_t nk, const double *seed, double *out);
/* FMU state: a copy of the instance data, serialized with a magic number and its size */
int ac_state_get(ac_inst *m, void **state);
int ac_state_set(ac_inst *m, const void *state);
void ac_state_free(void **state);
size_t ac_state_size(void);
int ac_state_serialize(ac_inst *m, const void *state, void *bytes, size_t size);
int ac_state_deserialize(ac_inst *m, const void *bytes, size_t size, void **state);

#endif
