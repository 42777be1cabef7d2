/* State events and discrete modes, after acausal.simulation.events (the in-process engine):
 *   - the indicators g (ac_ind) and their sides: the sign of each, where it is exactly 0 the
 *     side it was on before (events.py's `side`); the instance keeps the sides of the last
 *     accepted step or event (ac_data.sides), and an indicator crossed when its side
 *     changed;
 *   - at an event: the reinits of the crossed indicators (in their direction, values at the
 *     left limit: ac_upd), then the event iteration: every mode updated from the present
 *     ones (ac_upd, rounded), the algebraic variables solved in between, until no mode
 *     changes (Integer/Boolean modes rounded, discrete Real variables
 *     as they are: AC_MODE_INT; AC_EVENT_ITERATIONS rounds; otherwise an error naming
 *     the components whose modes kept changing), each mode then one of its declared values
 *     (otherwise an error naming it); closed loops projected after a reinit;
 *   - sample triggers (StructureBuilder.sample; AC_CLOCK_MODE: their positions among the
 *     modes): their instants are among the time events (ac_events, so ME reports them as
 *     nextEventTime and CS stops at them); at an event within AC_EVENT_TOL·max(1, |t|) s of
 *     an instant of a trigger (once per instant: each trigger's last tick is kept), the
 *     trigger is 1 through the event iteration and then the iteration runs once more with
 *     it 0, as events.py's `event`; at the start only the triggers declared `initial`
 *     (AC_CLOCK_INITIAL) tick; an event past an instant the importer did not stop at is an
 *     error naming the block (the sample would be lost);
 *   - hysteresis, as Modelica tools shift their crossing functions: an indicator g on side s
 *     is reported as g + s·AC_HYSTERESIS, so it crosses once g is AC_HYSTERESIS past zero
 *     (in its own units); at the event the relations that the mode updates test (a torque
 *     beyond its breakaway value) are then past their thresholds by more than round-off,
 *     however tightly the importer locates the crossing, and after the event g stays on its
 *     new side within the band. The event instants differ from simulate()'s by
 *     AC_HYSTERESIS/|dg/dt| (1e-13 s for a clutch whose torque changes at 1000 N.m/s);
 *   - chattering, as events.py detects it: AC_CHATTER_EVENTS state events within
 *     AC_CHATTER_SPAN·max(1, |t|) s (events.py: of the simulated time, which the FMU does
 *     not know) are an error naming the component whose indicators fired the most;
 *   - a crossing that can change nothing (no modes in the model, no reinit of that indicator
 *     in that direction: a ball leaving the floor) is no event, as in events.py.
 * Model exchange reports the indicators (exact zeros shifted to the side they are on, so that
 * the importer's sign test and the FMU's agree: FMI's "z ≠ 0 after an event"), asks for an
 * event in completedIntegratorStep when a step crossed, and runs the event in the event
 * update; co-simulation locates crossings inside its steps (solver.c). Without modes and
 * indicators (AC_NG = AC_NMODE = 0) every function here does nothing and succeeds. */
#ifndef AC_EVENTS_H
#define AC_EVENTS_H

#include "model.h"

/* model.h defines, from acausal.simulation.events, AC_EVENT_ITERATIONS (MAX_ITERATIONS: rounds
 * of the event iteration) and AC_EVENT_TOL (EVENT_TOL: co-simulation locates events to
 * AC_EVENT_TOL·max(1, |t|) s) */

struct ac_inst;
#define AC_HYSTERESIS 1e-10

/* the side of an indicator's value g: its sign, `before` where it is exactly 0 */
double ac_side(double g, double before);
/* the value of g reported on side `side`, with the hysteresis (the crossings are its) */
double ac_reported(double g, double side);
/* g at (t, x), z solved from the warm start z (updated) */
int ac_indicators_at(struct ac_inst *m, double t, const double *x, double *z, double *g);
/* 1 if an indicator's side at g differs from the instance's sides and the crossing can change
 * something (an event), else 0; the sides of an inert crossing are updated */
int ac_crossing(struct ac_inst *m, const double *g);
/* the indicators at the instance's point as the importer sees them (n must be AC_NG) */
int ac_event_indicators(struct ac_inst *m, double *g, size_t n);
/* model exchange, completedIntegratorStep: 1 if the step crossed (ask for an event) */
int ac_step_crossed(struct ac_inst *m);
/* the event at the instance's point, its left limit: reinits of the indicators crossed since
 * the sides were kept, event iteration, sides kept at the right limit. *changed (may be
 * NULL): states reinitialized or modes changed. At the start (`start`), no crossing: the
 * modes made consistent with the start values and the sides taken (zeros on the positive
 * side), as events.py starts. */
int ac_state_event(struct ac_inst *m, int start, int *changed);
/* after an event (not the start): *terminate = 1 when a termination condition
 * (PhysicsBuilder.terminate, > 0.5) holds at the instance's point, its owner's text logged
 * and the instance marked terminated (ac_data.terminated), as events.py's _ends; 0 if not */
int ac_termination(struct ac_inst *m, int *terminate);
/* AC_ERROR, logging the component and its message, if an assertion fails at the present
 * point (checked after initialization, events and every integrator step) */
int ac_check_assertions(struct ac_inst *m);

#endif
