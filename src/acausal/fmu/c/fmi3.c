/* FMI 3.0 adapter (model exchange and co-simulation): translates the FMI 3 API to the
 * instance's calls (instance.h). Every function with an instance first checks it (NULL, or
 * a call out of order: fmi3Error). */
#include <math.h>
#include <stdlib.h>

#include "fmi3Functions.h"
#include "instance.h"

typedef struct {
    ac_inst m;
    fmi3LogMessageCallback logger;
    fmi3InstanceEnvironment env;
    int early_return;         /* co-simulation: earlyReturnAllowed */
} fmu3;

#define M ((ac_inst *)instance)
#define ST(x) ((fmi3Status)(x))
#define BEGIN(modes) if (!ac_allowed(M, (modes), __func__)) return fmi3Error

static void fmi3_log(ac_inst *m, int status, const char *category, const char *message) {
    fmu3 *f = (fmu3 *)m;
    if (f->logger) f->logger(f->env, (fmi3Status)status, category, message);
}

static fmi3Status unsupported(fmi3Instance instance, const char *what) {
    if (instance) ac_logf(M, AC_ERROR, "logStatusError", "%s is not supported by this FMU", what);
    return fmi3Error;
}

const char *fmi3GetVersion(void) { return fmi3Version; }

fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn, size_t n,
                               const fmi3String categories[]) {
    (void)n; (void)categories;
    BEGIN(AC_ANY);
    M->logging_on = loggingOn;
    return fmi3OK;
}

static fmi3Instance instantiate(fmi3String name, fmi3String token, fmi3Boolean loggingOn,
                                fmi3InstanceEnvironment env, fmi3LogMessageCallback logger,
                                int cs) {
    fmu3 *f;
    if (!name) return NULL;
    f = (fmu3 *)calloc(1, sizeof(fmu3));
    if (!f) return NULL;
    f->logger = logger;
    f->env = env;
    if (ac_instantiate(&f->m, name, token, cs, loggingOn, fmi3_log)) {
        free(f);
        return NULL;
    }
    return (fmi3Instance)f;
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName, fmi3String instantiationToken,
                                          fmi3String resourcePath, fmi3Boolean visible,
                                          fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
                                          fmi3LogMessageCallback logMessage) {
    (void)resourcePath; (void)visible;
    return instantiate(instanceName, instantiationToken, loggingOn, instanceEnvironment, logMessage, 0);
}

fmi3Instance fmi3InstantiateCoSimulation(fmi3String instanceName, fmi3String instantiationToken,
                                         fmi3String resourcePath, fmi3Boolean visible,
                                         fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
                                         fmi3Boolean earlyReturnAllowed,
                                         const fmi3ValueReference requiredIntermediateVariables[],
                                         size_t nRequiredIntermediateVariables,
                                         fmi3InstanceEnvironment instanceEnvironment,
                                         fmi3LogMessageCallback logMessage,
                                         fmi3IntermediateUpdateCallback intermediateUpdate) {
    fmi3Instance f;
    (void)resourcePath; (void)visible;
    (void)requiredIntermediateVariables; (void)nRequiredIntermediateVariables; (void)intermediateUpdate;
    if (eventModeUsed) {
        if (logMessage) logMessage(instanceEnvironment, fmi3Error, "logStatusError",
                                   "event mode in co-simulation is not supported by this FMU");
        return NULL;
    }
    f = instantiate(instanceName, instantiationToken, loggingOn, instanceEnvironment, logMessage, 1);
    if (f) ((fmu3 *)f)->early_return = earlyReturnAllowed != fmi3False;
    return f;
}

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String instanceName, fmi3String instantiationToken,
                                               fmi3String resourcePath, fmi3Boolean visible,
                                               fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
                                               fmi3LogMessageCallback logMessage,
                                               fmi3ClockUpdateCallback clockUpdate,
                                               fmi3LockPreemptionCallback lockPreemption,
                                               fmi3UnlockPreemptionCallback unlockPreemption) {
    (void)instanceName; (void)instantiationToken; (void)resourcePath; (void)visible; (void)loggingOn;
    (void)clockUpdate; (void)lockPreemption; (void)unlockPreemption;
    if (logMessage) logMessage(instanceEnvironment, fmi3Error, "logStatusError",
                               "scheduled execution is not supported by this FMU");
    return NULL;
}

void fmi3FreeInstance(fmi3Instance instance) { free(instance); }

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean toleranceDefined,
                                       fmi3Float64 tolerance, fmi3Float64 startTime,
                                       fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
    (void)stopTimeDefined; (void)stopTime;
    BEGIN(AC_INSTANTIATED);
    if (ac_setup(M, toleranceDefined, tolerance, startTime)) return fmi3Error;
    M->d.mode = AC_INIT;
    return fmi3OK;
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
    BEGIN(AC_INIT);
    return ST(ac_exit_initialization(M));
}

fmi3Status fmi3EnterEventMode(fmi3Instance instance) {
    BEGIN(AC_EVENT | AC_CONT);
    M->d.mode = AC_EVENT;
    return fmi3OK;
}

fmi3Status fmi3Terminate(fmi3Instance instance) {
    BEGIN(AC_RUNNING);
    M->d.mode = AC_TERMINATED;
    return fmi3OK;
}

fmi3Status fmi3Reset(fmi3Instance instance) {
    BEGIN(AC_ANY);
    ac_defaults(M);
    return fmi3OK;
}

/* ---- values ------------------------------------------------------------------------------ */
fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Float64 values[], size_t nValues) {
    BEGIN(AC_ANY);
    if (nValues < nvr) return unsupported(instance, "arrays");
    return ST(ac_get_reals(M, vr, nvr, values));
}

fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Float64 values[], size_t nValues) {
    BEGIN(AC_SETTABLE);
    if (nValues < nvr) return unsupported(instance, "arrays");
    return ST(ac_set_reals(M, vr, nvr, values));   /* a rejected value leaves the FMU usable */
}

#define NO_VARS(NAME, CT, TYPE)                                                                  \
    fmi3Status NAME(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,            \
                    CT values[], size_t nValues) {                                               \
        (void)vr; (void)values; (void)nValues;                                                   \
        BEGIN(AC_ANY);                                                                           \
        if (nvr == 0) return fmi3OK;                                                             \
        return unsupported(instance, "variables of type " TYPE);                                 \
    }
NO_VARS(fmi3GetFloat32, fmi3Float32, "Float32")
NO_VARS(fmi3GetInt8, fmi3Int8, "Int8")
NO_VARS(fmi3GetUInt8, fmi3UInt8, "UInt8")
NO_VARS(fmi3GetInt16, fmi3Int16, "Int16")
NO_VARS(fmi3GetUInt16, fmi3UInt16, "UInt16")
NO_VARS(fmi3GetInt32, fmi3Int32, "Int32")
NO_VARS(fmi3GetUInt32, fmi3UInt32, "UInt32")
NO_VARS(fmi3GetInt64, fmi3Int64, "Int64")
NO_VARS(fmi3GetUInt64, fmi3UInt64, "UInt64")
NO_VARS(fmi3GetBoolean, fmi3Boolean, "Boolean")
NO_VARS(fmi3GetString, fmi3String, "String")
NO_VARS(fmi3SetFloat32, const fmi3Float32, "Float32")
NO_VARS(fmi3SetInt8, const fmi3Int8, "Int8")
NO_VARS(fmi3SetUInt8, const fmi3UInt8, "UInt8")
NO_VARS(fmi3SetInt16, const fmi3Int16, "Int16")
NO_VARS(fmi3SetUInt16, const fmi3UInt16, "UInt16")
NO_VARS(fmi3SetInt32, const fmi3Int32, "Int32")
NO_VARS(fmi3SetUInt32, const fmi3UInt32, "UInt32")
NO_VARS(fmi3SetInt64, const fmi3Int64, "Int64")
NO_VARS(fmi3SetUInt64, const fmi3UInt64, "UInt64")
NO_VARS(fmi3SetBoolean, const fmi3Boolean, "Boolean")
NO_VARS(fmi3SetString, const fmi3String, "String")

fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                         size_t valueSizes[], fmi3Binary values[], size_t nValues) {
    (void)vr; (void)valueSizes; (void)values; (void)nValues;
    BEGIN(AC_ANY);
    return nvr ? unsupported(instance, "Binary variables") : fmi3OK;
}
fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                         const size_t valueSizes[], const fmi3Binary values[], size_t nValues) {
    (void)vr; (void)valueSizes; (void)values; (void)nValues;
    BEGIN(AC_ANY);
    return nvr ? unsupported(instance, "Binary variables") : fmi3OK;
}
fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Clock values[]) {
    (void)vr; (void)values;
    BEGIN(AC_ANY);
    return nvr ? unsupported(instance, "clocks") : fmi3OK;
}
fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Clock values[]) {
    (void)vr; (void)values;
    BEGIN(AC_ANY);
    return nvr ? unsupported(instance, "clocks") : fmi3OK;
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance, fmi3ValueReference vr, size_t *n) {
    (void)vr; (void)n;
    return unsupported(instance, "fmi3GetNumberOfVariableDependencies (see ModelStructure)");
}
fmi3Status fmi3GetVariableDependencies(fmi3Instance instance, fmi3ValueReference dependent,
                                       size_t elementIndicesOfDependent[], fmi3ValueReference independents[],
                                       size_t elementIndicesOfIndependents[], fmi3DependencyKind dependencyKinds[],
                                       size_t nDependencies) {
    (void)dependent; (void)elementIndicesOfDependent; (void)independents;
    (void)elementIndicesOfIndependents; (void)dependencyKinds; (void)nDependencies;
    return unsupported(instance, "fmi3GetVariableDependencies (see ModelStructure)");
}

/* ---- FMU state ---------------------------------------------------------------------------- */
fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState *state) {
    BEGIN(AC_ANY);
    return ST(ac_state_get(M, state));
}

fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState state) {
    BEGIN(AC_ANY);
    return ST(ac_state_set(M, state));
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState *state) {
    BEGIN(AC_ANY);
    ac_state_free(state);
    return fmi3OK;
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState state, size_t *size) {
    (void)state;
    BEGIN(AC_ANY);
    *size = ac_state_size();
    return fmi3OK;
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState state, fmi3Byte bytes[], size_t size) {
    BEGIN(AC_ANY);
    return ST(ac_state_serialize(M, state, bytes, size));
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte bytes[], size_t size, fmi3FMUState *state) {
    BEGIN(AC_ANY);
    return ST(ac_state_deserialize(M, bytes, size, state));
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[],
                                        size_t nUnknowns, const fmi3ValueReference knowns[], size_t nKnowns,
                                        const fmi3Float64 seed[], size_t nSeed, fmi3Float64 sensitivity[],
                                        size_t nSensitivity) {
    BEGIN(AC_EVALUABLE);
    if (nSeed != nKnowns || nSensitivity != nUnknowns) return unsupported(instance, "array variables");
    return ST(ac_directional(M, unknowns, nUnknowns, knowns, nKnowns, seed, sensitivity));
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[],
                                    size_t nUnknowns, const fmi3ValueReference knowns[], size_t nKnowns,
                                    const fmi3Float64 seed[], size_t nSeed, fmi3Float64 sensitivity[],
                                    size_t nSensitivity) {
    (void)unknowns; (void)nUnknowns; (void)knowns; (void)nKnowns; (void)seed; (void)nSeed;
    (void)sensitivity; (void)nSensitivity;
    return unsupported(instance, "fmi3GetAdjointDerivative (providesAdjointDerivatives=false)");
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance) { return unsupported(instance, "configuration mode"); }
fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance) { return unsupported(instance, "configuration mode"); }

fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference vr[], size_t n,
                                  fmi3Float64 intervals[], fmi3IntervalQualifier qualifiers[]) {
    (void)vr; (void)n; (void)intervals; (void)qualifiers; return unsupported(instance, "clocks");
}
fmi3Status fmi3GetIntervalFraction(fmi3Instance instance, const fmi3ValueReference vr[], size_t n,
                                   fmi3UInt64 counters[], fmi3UInt64 resolutions[], fmi3IntervalQualifier qualifiers[]) {
    (void)vr; (void)n; (void)counters; (void)resolutions; (void)qualifiers; return unsupported(instance, "clocks");
}
fmi3Status fmi3GetShiftDecimal(fmi3Instance instance, const fmi3ValueReference vr[], size_t n, fmi3Float64 shifts[]) {
    (void)vr; (void)n; (void)shifts; return unsupported(instance, "clocks");
}
fmi3Status fmi3GetShiftFraction(fmi3Instance instance, const fmi3ValueReference vr[], size_t n,
                                fmi3UInt64 counters[], fmi3UInt64 resolutions[]) {
    (void)vr; (void)n; (void)counters; (void)resolutions; return unsupported(instance, "clocks");
}
fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference vr[], size_t n,
                                  const fmi3Float64 intervals[]) {
    (void)vr; (void)n; (void)intervals; return unsupported(instance, "clocks");
}
fmi3Status fmi3SetIntervalFraction(fmi3Instance instance, const fmi3ValueReference vr[], size_t n,
                                   const fmi3UInt64 counters[], const fmi3UInt64 resolutions[]) {
    (void)vr; (void)n; (void)counters; (void)resolutions; return unsupported(instance, "clocks");
}
fmi3Status fmi3SetShiftDecimal(fmi3Instance instance, const fmi3ValueReference vr[], size_t n,
                               const fmi3Float64 shifts[]) {
    (void)vr; (void)n; (void)shifts; return unsupported(instance, "clocks");
}
fmi3Status fmi3SetShiftFraction(fmi3Instance instance, const fmi3ValueReference vr[], size_t n,
                                const fmi3UInt64 counters[], const fmi3UInt64 resolutions[]) {
    (void)vr; (void)n; (void)counters; (void)resolutions; return unsupported(instance, "clocks");
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance) {
    BEGIN(AC_RUNNING);         /* no discrete states */
    return fmi3OK;
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance, fmi3Boolean *discreteStatesNeedUpdate,
                                    fmi3Boolean *terminateSimulation,
                                    fmi3Boolean *nominalsOfContinuousStatesChanged,
                                    fmi3Boolean *valuesOfContinuousStatesChanged,
                                    fmi3Boolean *nextEventTimeDefined, fmi3Float64 *nextEventTime) {
    int changed = 0, ends = 0, st;
    BEGIN(AC_EVENT);
    st = ac_event_update(M, &changed, &ends);
    *discreteStatesNeedUpdate = fmi3False;
    *terminateSimulation = st || ends ? fmi3True : fmi3False;
    *nominalsOfContinuousStatesChanged = fmi3False;
    *valuesOfContinuousStatesChanged = changed ? fmi3True : fmi3False;
    *nextEventTimeDefined = isfinite(M->d.next_event) ? fmi3True : fmi3False;
    *nextEventTime = isfinite(M->d.next_event) ? M->d.next_event : 0.0;
    return ST(st);
}

/* ---- model exchange ------------------------------------------------------------------------ */
fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance) {
    BEGIN(AC_EVENT);
    M->d.mode = AC_CONT;
    return fmi3OK;
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi3Boolean *enterEventMode, fmi3Boolean *terminateSimulation) {
    (void)noSetFMUStatePriorToCurrentPoint;
    BEGIN(AC_CONT);
    *enterEventMode = ac_drift_exceeded(M) || ac_step_crossed(M) ? fmi3True : fmi3False;
    *terminateSimulation = fmi3False;
    return ST(ac_completed_step(M));
}

fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time) {
    BEGIN(AC_EVENT | AC_CONT);
    return ST(ac_set_time(M, time));
}

fmi3Status fmi3SetContinuousStates(fmi3Instance instance, const fmi3Float64 x[], size_t n) {
    BEGIN(AC_CONT);
    return ST(ac_set_states(M, x, n));
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance, fmi3Float64 dx[], size_t n) {
    BEGIN(AC_STATES_READABLE);
    return ST(ac_get_derivatives(M, dx, n));
}

fmi3Status fmi3GetEventIndicators(fmi3Instance instance, fmi3Float64 z[], size_t n) {
    BEGIN(AC_STATES_READABLE);
    return ST(ac_event_indicators(M, z, n));
}

fmi3Status fmi3GetContinuousStates(fmi3Instance instance, fmi3Float64 x[], size_t n) {
    BEGIN(AC_STATES_READABLE);
    return ST(ac_get_states(M, x, n));
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance, fmi3Float64 nominals[], size_t n) {
    BEGIN(AC_ANY);
    ac_nominals(nominals, n);
    return fmi3OK;
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance, size_t *n) {
    BEGIN(AC_ANY);
    *n = AC_NG;
    return fmi3OK;
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance, size_t *n) {
    BEGIN(AC_ANY);
    *n = AC_NX;
    return fmi3OK;
}

/* ---- co-simulation -------------------------------------------------------------------------- */
fmi3Status fmi3EnterStepMode(fmi3Instance instance) {   /* co-simulation starts in step mode */
    return unsupported(instance, "fmi3EnterStepMode (no event mode: hasEventMode=false)");
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                                    const fmi3Int32 orders[], fmi3Float64 values[], size_t nValues) {
    (void)vr; (void)orders; (void)values; (void)nValues;
    BEGIN(AC_ANY);
    return nvr ? unsupported(instance, "output derivatives (maxOutputDerivativeOrder=0)") : fmi3OK;
}

fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation,
                      fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime) {
    int st;
    (void)noSetFMUStatePriorToCurrentPoint;
    BEGIN(AC_STEP);
    st = ac_do_step(M, currentCommunicationPoint, communicationStepSize);
    *eventHandlingNeeded = fmi3False;
    /* a termination ends the step early at its event (lastSuccessfulTime): returned early
     * where the importer allows it (earlyReturnAllowed), else reported at the step's end */
    *terminateSimulation = st == AC_OK && M->d.terminated ? fmi3True : fmi3False;
    *earlyReturn = *terminateSimulation && ((fmu3 *)M)->early_return ? fmi3True : fmi3False;
    *lastSuccessfulTime = M->d.t;
    return ST(st);
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance instance, fmi3ValueReference clockReference,
                                      fmi3Float64 activationTime) {
    (void)clockReference; (void)activationTime;
    return unsupported(instance, "scheduled execution");
}
