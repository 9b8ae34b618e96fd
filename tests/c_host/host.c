/* A minimal FMI 2.0 Co-Simulation host in C, compiled against fmi_headers/ and linked with the built
 * libpistonslap.so (its x86-64-v3 build beside it) by tests/fmi_c_abi.rs.
 * Usage: host <guid> <vr crank_angle> <vr impact_count> <vr crank_speed> [cycles]
 * Runs 50 steps of 1 ms twice: with a state saved at step 25 and restored after step 50 (then 25 steps
 * again), and straight through, that instance made with logging on so that it names its build. Then
 * cycles - 1 short cycles (instantiate, initialize, a few steps, an FMU state through bytes and back,
 * free: what a memory checker must see released). Prints "crank_angle=… impact_count=…
 * straight_crank_angle=… straight_impact_count=… errors=<refused misuses> logged=<messages>" and
 * exits 0 on success. */
#include <stdio.h>
#include <stdlib.h>
#include "fmi2Functions.h"
#include "host_common.h"

#define REFUSED(call)                                                 \
    do {                                                              \
        if ((call) != fmi2Error) {                                    \
            fprintf(stderr, "%s was not refused\n", #call);           \
            return 1;                                                 \
        }                                                             \
        errors++;                                                     \
    } while (0)

/* 50 steps of 1 ms from t = 0 on an initialized instance. */
static int run(fmi2Component c, int from) {
    int i;
    for (i = from; i < 50; i++) CHECK(fmi2DoStep(c, i * 1e-3, 1e-3, fmi2True));
    return 0;
}

/* One short cycle; returns 0 when every call succeeded. */
static int short_cycle(const char *guid, const fmi2CallbackFunctions *callbacks) {
    fmi2Component c = fmi2Instantiate("cycle", fmi2CoSimulation, guid, "file:///tmp", callbacks, fmi2False, fmi2False);
    fmi2FMUstate state = NULL, copy = NULL;
    fmi2Byte *bytes;
    size_t size;
    int i;

    if (!c) return 1;
    CHECK(fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0));
    CHECK(fmi2EnterInitializationMode(c));
    CHECK(fmi2ExitInitializationMode(c));
    /* Steps of one RK4 step each: memcheck runs ~50 times slower, and what is allocated and freed
     * does not depend on the step length. */
    for (i = 0; i < 3; i++) CHECK(fmi2DoStep(c, i * 1e-5, 1e-5, fmi2True));
    CHECK(fmi2GetFMUstate(c, &state));
    CHECK(fmi2SerializedFMUstateSize(c, state, &size));
    bytes = malloc(size);
    if (!bytes) return 1;
    CHECK(fmi2SerializeFMUstate(c, state, bytes, size));
    CHECK(fmi2DeSerializeFMUstate(c, bytes, size, &copy));
    free(bytes);
    CHECK(fmi2SetFMUstate(c, copy));
    CHECK(fmi2FreeFMUstate(c, &copy));
    CHECK(fmi2FreeFMUstate(c, &state));
    CHECK(fmi2Terminate(c));
    fmi2FreeInstance(c);
    return 0;
}

int main(int argc, char **argv) {
    fmi2CallbackFunctions callbacks = {logger, NULL, NULL, NULL, NULL};
    fmi2ValueReference angle, count, speed;
    fmi2Component c;
    fmi2FMUstate state = NULL;
    fmi2Component straight;
    fmi2Real value, straight_value, nan = 0.0;
    fmi2Integer impacts, straight_impacts;
    int i, cycles = 1, errors = 0;

    if (argc != 5 && argc != 6) return 2;
    if (argc == 6) cycles = atoi(argv[5]);
    angle = (fmi2ValueReference)atoi(argv[2]);
    count = (fmi2ValueReference)atoi(argv[3]);
    speed = (fmi2ValueReference)atoi(argv[4]);
    if (fmi2Instantiate("c_host", fmi2CoSimulation, "{wrong}", "file:///tmp", &callbacks, fmi2False, fmi2False)) return 3;
    c = fmi2Instantiate("c_host", fmi2CoSimulation, argv[1], "file:///tmp", &callbacks, fmi2False, fmi2False);
    if (!c) return 4;
    REFUSED(fmi2DoStep(c, 0.0, 1e-3, fmi2True));
    CHECK(fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2True, 0.05));
    CHECK(fmi2EnterInitializationMode(c));
    CHECK(fmi2ExitInitializationMode(c));
    nan = nan / nan;
    REFUSED(fmi2SetReal(c, &speed, 1, &nan));
    REFUSED(fmi2DoStep(c, 0.0, -1e-3, fmi2True));
    for (i = 0; i < 25; i++) CHECK(fmi2DoStep(c, i * 1e-3, 1e-3, fmi2True));
    CHECK(fmi2GetFMUstate(c, &state));
    if (run(c, 25)) return 1;
    CHECK(fmi2SetFMUstate(c, state));
    if (run(c, 25)) return 1;
    CHECK(fmi2FreeFMUstate(c, &state));
    CHECK(fmi2GetReal(c, &angle, 1, &value));
    CHECK(fmi2GetInteger(c, &count, 1, &impacts));
    CHECK(fmi2Terminate(c));
    fmi2FreeInstance(c);

    /* Logging on at instantiation only, switched off before anything would be logged. */
    straight = fmi2Instantiate("straight", fmi2CoSimulation, argv[1], "file:///tmp", &callbacks, fmi2False, fmi2True);
    if (!straight) return 5;
    CHECK(fmi2SetDebugLogging(straight, fmi2False, 0, NULL));
    CHECK(fmi2EnterInitializationMode(straight));
    CHECK(fmi2ExitInitializationMode(straight));
    if (run(straight, 0)) return 1;
    CHECK(fmi2GetReal(straight, &angle, 1, &straight_value));
    CHECK(fmi2GetInteger(straight, &count, 1, &straight_impacts));
    fmi2FreeInstance(straight);
    for (i = 1; i < cycles; i++)
        if (short_cycle(argv[1], &callbacks)) return 6;
    printf("crank_angle=%.17g impact_count=%d straight_crank_angle=%.17g straight_impact_count=%d errors=%d logged=%d\n",
           value, impacts, straight_value, straight_impacts, errors, logged);
    return 0;
}
