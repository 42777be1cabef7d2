/* Time of an FMI 2.0 model-exchange FMU's own right-hand side, without an importer around it:
   fmi2SetTime + fmi2SetContinuousStates + fmi2GetDerivatives, the three calls an importer's ODE
   solver makes per evaluation, repeated with the state moved each time (no cached result).
   Used by fmu.py to say which share of fmpy's model-exchange time is the FMU's.
   Build: cc -O2 -I<fmpy's FMI 2 headers> fmu_rhs.c -o fmu_rhs -ldl
   Run:   fmu_rhs <binary.so> <guid> <resource URI> <number of states> <calls> [vr=value ...]
   (start values of Real variables by value reference, set before initialization). Prints the seconds per evaluation. */
#include <dlfcn.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "fmi2Functions.h"

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                   fmi2String category, fmi2String message, ...) {
    (void)env; (void)name; (void)status; (void)category;
    fprintf(stderr, "%s\n", message);
}

#define LOAD(var, type, name) type var = (type)dlsym(lib, name); \
    if (!var) { fprintf(stderr, "%s not found\n", name); return 1; }

int main(int argc, char **argv) {
    void *lib;
    fmi2Component c;
    fmi2CallbackFunctions cb = {logger, calloc, free, NULL, NULL};
    double *x, *dx, t0, t1;
    size_t nx, i, calls;
    struct timespec a, b;
    int k;
    if (argc < 6) {
        fprintf(stderr, "usage: %s so guid resources nx calls [vr=value ...]\n", argv[0]);
        return 2;
    }
    lib = dlopen(argv[1], RTLD_NOW);
    if (!lib) { fprintf(stderr, "%s\n", dlerror()); return 1; }
    LOAD(instantiate, fmi2InstantiateTYPE *, "fmi2Instantiate")
    LOAD(setup, fmi2SetupExperimentTYPE *, "fmi2SetupExperiment")
    LOAD(enter_init, fmi2EnterInitializationModeTYPE *, "fmi2EnterInitializationMode")
    LOAD(exit_init, fmi2ExitInitializationModeTYPE *, "fmi2ExitInitializationMode")
    LOAD(enter_ct, fmi2EnterContinuousTimeModeTYPE *, "fmi2EnterContinuousTimeMode")
    LOAD(get_x, fmi2GetContinuousStatesTYPE *, "fmi2GetContinuousStates")
    LOAD(set_time, fmi2SetTimeTYPE *, "fmi2SetTime")
    LOAD(set_x, fmi2SetContinuousStatesTYPE *, "fmi2SetContinuousStates")
    LOAD(get_dx, fmi2GetDerivativesTYPE *, "fmi2GetDerivatives")
    LOAD(set_real, fmi2SetRealTYPE *, "fmi2SetReal")
    LOAD(free_instance, fmi2FreeInstanceTYPE *, "fmi2FreeInstance")
    nx = (size_t)atol(argv[4]);
    calls = (size_t)atol(argv[5]);
    c = instantiate("rhs", fmi2ModelExchange, argv[2], argv[3], &cb, fmi2False, fmi2False);
    if (!c) { fprintf(stderr, "instantiation failed\n"); return 1; }
    for (k = 6; k < argc; k++) {
        fmi2ValueReference vr = (fmi2ValueReference)strtoul(argv[k], NULL, 10);
        fmi2Real value = atof(strchr(argv[k], '=') ? strchr(argv[k], '=') + 1 : "nan");
        if (set_real(c, &vr, 1, &value) > fmi2Warning) { fprintf(stderr, "%s\n", argv[k]); return 1; }
    }
    if (setup(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) > fmi2Warning
        || enter_init(c) > fmi2Warning || exit_init(c) > fmi2Warning
        || enter_ct(c) > fmi2Warning) { fprintf(stderr, "initialization failed\n"); return 1; }
    x = calloc(nx + 1, sizeof(double));
    dx = calloc(nx + 1, sizeof(double));
    get_x(c, x, nx);
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (i = 0; i < calls; i++) {
        x[0] += 1e-12;
        if (set_time(c, 1e-9 * (double)i) > fmi2Warning || set_x(c, x, nx) > fmi2Warning
            || get_dx(c, dx, nx) > fmi2Warning) { fprintf(stderr, "call %zu failed\n", i); return 1; }
    }
    clock_gettime(CLOCK_MONOTONIC, &b);
    t0 = (double)a.tv_sec + 1e-9 * (double)a.tv_nsec;
    t1 = (double)b.tv_sec + 1e-9 * (double)b.tv_nsec;
    printf("%.6e\n", (t1 - t0) / (double)calls);
    free_instance(c);
    free(x);
    free(dx);
    return 0;
}
