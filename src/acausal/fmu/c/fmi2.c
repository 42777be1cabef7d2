/* FMI 2.0 adapter (model exchange and co-simulation in one binary): translates the FMI 2
 * API to the instance's calls (instance.h). Every function with an instance first checks it
 * (NULL, or a call out of order: fmi2Error). */
#include <math.h>
#include <stdlib.h>

#include "fmi2Functions.h"
#include "instance.h"

typedef struct {
    ac_inst m;
    fmi2CallbackFunctions cb;
} fmu2;

#define M ((ac_inst *)c)
#define ST(x) ((fmi2Status)(x))
#define BEGIN(modes) if (!ac_allowed(M, (modes), __func__)) return fmi2Error
#define STATUS_MODES (AC_STEP | AC_TERMINATED | AC_FAILED)   /* fmi2Get*Status */

static void fmi2_log(ac_inst *m, int status, const char *category, const char *message) {
    fmu2 *f = (fmu2 *)m;
    char buf[2048];
    size_t i, j = 0;
    if (!f->cb.logger) return;
    for (i = 0; message[i] && j < sizeof(buf) - 2; i++) {   /* the logger takes a format */
        if (message[i] == '%') buf[j++] = '%';
        buf[j++] = message[i];
    }
    buf[j] = 0;
    f->cb.logger(f->cb.componentEnvironment, m->name, (fmi2Status)status, category, buf);
}

static fmi2Status no_such(fmi2Component c, size_t nvr, const char *type) {
    if (nvr == 0) return fmi2OK;
    ac_logf(M, AC_ERROR, "logStatusError", "this FMU has no %s variables", type);
    return fmi2Error;
}

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t n,
                               const fmi2String categories[]) {
    (void)n; (void)categories;
    BEGIN(AC_ANY);
    M->logging_on = loggingOn;
    return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String resourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn) {
    fmu2 *f;
    (void)resourceLocation; (void)visible;
    if (!instanceName || !functions) return NULL;
    f = (fmu2 *)calloc(1, sizeof(fmu2));
    if (!f) return NULL;
    f->cb = *functions;
    if (ac_instantiate(&f->m, instanceName, fmuGUID, fmuType == fmi2CoSimulation, loggingOn,
                       fmi2_log)) {
        free(f);
        return NULL;
    }
    return (fmi2Component)f;
}

void fmi2FreeInstance(fmi2Component c) { free(c); }

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    (void)stopTimeDefined; (void)stopTime;
    BEGIN(AC_INSTANTIATED);
    return ST(ac_setup(M, toleranceDefined, tolerance, startTime));
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    BEGIN(AC_INSTANTIATED);
    M->d.mode = AC_INIT;
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    BEGIN(AC_INIT);
    return ST(ac_exit_initialization(M));
}

fmi2Status fmi2Terminate(fmi2Component c) {
    BEGIN(AC_RUNNING);
    M->d.mode = AC_TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) {
    BEGIN(AC_ANY);
    ac_defaults(M);
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
    BEGIN(AC_ANY);
    return ST(ac_get_reals(M, vr, nvr, value));
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    BEGIN(AC_SETTABLE);
    return ST(ac_set_reals(M, vr, nvr, value));   /* a rejected value leaves the FMU usable */
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
    (void)vr; (void)value; BEGIN(AC_ANY); return no_such(c, nvr, "Integer");
}
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[]) {
    (void)vr; (void)value; BEGIN(AC_ANY); return no_such(c, nvr, "Boolean");
}
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[]) {
    (void)vr; (void)value; BEGIN(AC_ANY); return no_such(c, nvr, "String");
}
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[]) {
    (void)vr; (void)value; BEGIN(AC_SETTABLE); return no_such(c, nvr, "Integer");
}
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[]) {
    (void)vr; (void)value; BEGIN(AC_SETTABLE); return no_such(c, nvr, "Boolean");
}
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[]) {
    (void)vr; (void)value; BEGIN(AC_SETTABLE); return no_such(c, nvr, "String");
}

/* ---- FMU state ---------------------------------------------------------------------- */
fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *state) {
    BEGIN(AC_ANY);
    return ST(ac_state_get(M, state));
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state) {
    BEGIN(AC_ANY);
    return ST(ac_state_set(M, state));
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *state) {
    BEGIN(AC_ANY);
    ac_state_free(state);
    return fmi2OK;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate state, size_t *size) {
    (void)state;
    BEGIN(AC_ANY);
    *size = ac_state_size();
    return fmi2OK;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte bytes[], size_t size) {
    BEGIN(AC_ANY);
    return ST(ac_state_serialize(M, state, bytes, size));
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte bytes[], size_t size, fmi2FMUstate *state) {
    BEGIN(AC_ANY);
    return ST(ac_state_deserialize(M, bytes, size, state));
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[],
                                        size_t nUnknown, const fmi2ValueReference vKnown_ref[],
                                        size_t nKnown, const fmi2Real dvKnown[], fmi2Real dvUnknown[]) {
    BEGIN(AC_EVALUABLE);
    return ST(ac_directional(M, vUnknown_ref, nUnknown, vKnown_ref, nKnown, dvKnown, dvUnknown));
}

/* ---- model exchange ---------------------------------------------------------------------- */
fmi2Status fmi2EnterEventMode(fmi2Component c) {
    BEGIN(AC_EVENT | AC_CONT);
    M->d.mode = AC_EVENT;
    return fmi2OK;
}

fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *info) {
    int changed = 0, ends = 0, st;
    BEGIN(AC_EVENT);
    st = ac_event_update(M, &changed, &ends);
    info->newDiscreteStatesNeeded = fmi2False;
    info->terminateSimulation = st || ends ? fmi2True : fmi2False;
    info->nominalsOfContinuousStatesChanged = fmi2False;
    info->valuesOfContinuousStatesChanged = changed ? fmi2True : fmi2False;
    info->nextEventTimeDefined = isfinite(M->d.next_event) ? fmi2True : fmi2False;
    info->nextEventTime = isfinite(M->d.next_event) ? M->d.next_event : 0.0;
    return ST(st);
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) {
    BEGIN(AC_EVENT);
    M->d.mode = AC_CONT;
    return fmi2OK;
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi2Boolean *enterEventMode, fmi2Boolean *terminateSimulation) {
    (void)noSetFMUStatePriorToCurrentPoint;
    BEGIN(AC_CONT);
    *enterEventMode = ac_drift_exceeded(M) || ac_step_crossed(M) ? fmi2True : fmi2False;
    *terminateSimulation = fmi2False;
    return ST(ac_completed_step(M));
}

fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time) {
    BEGIN(AC_EVENT | AC_CONT);
    return ST(ac_set_time(M, time));
}

fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t nx) {
    BEGIN(AC_CONT);
    return ST(ac_set_states(M, x, nx));
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real derivatives[], size_t nx) {
    BEGIN(AC_STATES_READABLE);
    return ST(ac_get_derivatives(M, derivatives, nx));
}

fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real eventIndicators[], size_t ni) {
    BEGIN(AC_STATES_READABLE);
    return ST(ac_event_indicators(M, eventIndicators, ni));
}

fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx) {
    BEGIN(AC_STATES_READABLE);
    return ST(ac_get_states(M, x, nx));
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[], size_t nx) {
    BEGIN(AC_ANY);
    ac_nominals(x_nominal, nx);
    return fmi2OK;
}

/* ---- co-simulation --------------------------------------------------------------------- */
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    (void)vr; (void)order; (void)value;
    BEGIN(AC_ANY);
    return no_such(c, nvr, "input derivative (canInterpolateInputs=false)");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[]) {
    (void)vr; (void)order; (void)value;
    BEGIN(AC_ANY);
    return no_such(c, nvr, "output derivative (maxOutputDerivativeOrder=0)");
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize, fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    int st;
    (void)noSetFMUStatePriorToCurrentPoint;
    BEGIN(AC_STEP);
    st = ac_do_step(M, currentCommunicationPoint, communicationStepSize);
    /* a termination: fmi2Discard, fmi2Terminated true, fmi2LastSuccessfulTime its time */
    return st == AC_OK && M->d.terminated ? fmi2Discard : ST(st);
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    BEGIN(AC_ANY);
    ac_logf(M, AC_ERROR, "logStatusError", "fmi2CancelStep: doStep is synchronous");
    return fmi2Error;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    (void)s;
    BEGIN(STATUS_MODES);
    *value = M->d.mode == AC_FAILED ? fmi2Error : fmi2OK;
    return fmi2OK;
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    BEGIN(STATUS_MODES);
    if (s == fmi2LastSuccessfulTime) { *value = M->d.t; return fmi2OK; }
    return fmi2Discard;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    (void)s; (void)value;
    BEGIN(STATUS_MODES);
    return fmi2Discard;
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    BEGIN(STATUS_MODES);
    *value = s == fmi2Terminated && M->d.terminated ? fmi2True : fmi2False;
    return s == fmi2Terminated ? fmi2OK : fmi2Discard;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    (void)s; (void)value;
    BEGIN(STATUS_MODES);
    return fmi2Discard;
}
