/* A portable FMI 2.0 Co-Simulation host (FMI 3.0 compiled with -DFMI3) that loads an FMU binary at run time
 * (dlopen on Linux, LoadLibrary on Windows), runs fixed communication steps and prints every requested output
 * after every step as the hexadecimal bits of its value, so that two platforms' runs compare bit for bit as text.
 * Used by python/tests/test_platforms.py, natively against binaries/linux64 (FMI 3.0: x86_64-linux) and under
 * Wine against binaries/win64 (x86_64-windows), compiled there with x86_64-w64-mingw32-gcc.
 *
 * Usage: trace <library> <guid> <resources> <steps> <step size> <real vrs,...> <integer vrs,...> [options]
 *   <resources>: FMI 2.0's resource URI, FMI 3.0's resource path; the GUID is FMI 3.0's instantiation token
 *   r:VR=VALUE  i:VR=VALUE  s:VR=TEXT   a parameter or input set before initialization
 *   save:K:FILE                          after step K, the serialized FMU state written to FILE
 *   load:K:FILE                          after initialization, the state read from FILE, then steps K+1..
 * Each printed line: the step number, then the reals, then the integers. Exit status 0 on success. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef FMI3
#include "fmi3FunctionTypes.h"
#else
#include "fmi2FunctionTypes.h"
#endif
#include "host_common.h"

#ifdef _WIN32
#define WIN32_LEAN_AND_MEAN
#include <windows.h>
#define OPEN(path) ((void *)LoadLibraryA(path))
#define SYMBOL(lib, name) ((void *)GetProcAddress((HMODULE)(lib), name))
#else
#include <dlfcn.h>
#define OPEN(path) dlopen(path, RTLD_NOW | RTLD_LOCAL)
#define SYMBOL(lib, name) dlsym(lib, name)
#endif

#define MAX_VARS 256

/* The FMI functions this host calls, looked up by name in `names` order; the version's types and calls. */
#ifdef FMI3
typedef fmi3Instance Instance;
typedef fmi3ValueReference ValueReference;
typedef fmi3Float64 Real;
typedef fmi3Int32 Integer;
typedef fmi3String String;
typedef fmi3FMUState State;
typedef fmi3Byte Byte;

static struct {
    fmi3InstantiateCoSimulationTYPE *instantiate;
    fmi3EnterInitializationModeTYPE *enter;
    fmi3ExitInitializationModeTYPE *exit_init;
    fmi3SetFloat64TYPE *set_real;
    fmi3SetInt32TYPE *set_integer;
    fmi3SetStringTYPE *set_string;
    fmi3GetFloat64TYPE *get_real;
    fmi3GetInt32TYPE *get_integer;
    fmi3DoStepTYPE *do_step;
    fmi3GetFMUStateTYPE *get_state;
    fmi3SetFMUStateTYPE *set_state;
    fmi3FreeFMUStateTYPE *free_state;
    fmi3SerializedFMUStateSizeTYPE *state_size;
    fmi3SerializeFMUStateTYPE *serialize;
    fmi3DeserializeFMUStateTYPE *deserialize;
    fmi3TerminateTYPE *terminate;
    fmi3FreeInstanceTYPE *free_instance;
} fmi;

static const char *names[] = {"fmi3InstantiateCoSimulation", "fmi3EnterInitializationMode",
                              "fmi3ExitInitializationMode", "fmi3SetFloat64", "fmi3SetInt32", "fmi3SetString",
                              "fmi3GetFloat64", "fmi3GetInt32", "fmi3DoStep", "fmi3GetFMUState", "fmi3SetFMUState",
                              "fmi3FreeFMUState", "fmi3SerializedFMUStateSize", "fmi3SerializeFMUState",
                              "fmi3DeserializeFMUState", "fmi3Terminate", "fmi3FreeInstance"};

static Instance instantiate(const char *guid, const char *resources) {
    return fmi.instantiate("trace", guid, resources, fmi3False, fmi3False, fmi3False, fmi3False, NULL, 0, NULL, logger,
                           NULL);
}

static int initialize(Instance c) {
    CHECK(fmi.enter(c, fmi3False, 0.0, 0.0, fmi3False, 0.0));
    return 0;
}

static int do_step(Instance c, Real t, Real h) {
    fmi3Boolean event, terminate, early;
    fmi3Float64 reached;
    CHECK(fmi.do_step(c, t, h, fmi3True, &event, &terminate, &early, &reached));
    return event || terminate || early || reached != t + h;
}

#define SET(setter, c, vr, value) fmi.setter(c, vr, 1, value, 1)
#define GET(getter, c, vrs, n, values) fmi.getter(c, vrs, n, values, n)
#else
typedef fmi2Component Instance;
typedef fmi2ValueReference ValueReference;
typedef fmi2Real Real;
typedef fmi2Integer Integer;
typedef fmi2String String;
typedef fmi2FMUstate State;
typedef fmi2Byte Byte;

static struct {
    fmi2InstantiateTYPE *instantiate;
    fmi2SetupExperimentTYPE *setup;
    fmi2EnterInitializationModeTYPE *enter;
    fmi2ExitInitializationModeTYPE *exit_init;
    fmi2SetRealTYPE *set_real;
    fmi2SetIntegerTYPE *set_integer;
    fmi2SetStringTYPE *set_string;
    fmi2GetRealTYPE *get_real;
    fmi2GetIntegerTYPE *get_integer;
    fmi2DoStepTYPE *do_step;
    fmi2GetFMUstateTYPE *get_state;
    fmi2SetFMUstateTYPE *set_state;
    fmi2FreeFMUstateTYPE *free_state;
    fmi2SerializedFMUstateSizeTYPE *state_size;
    fmi2SerializeFMUstateTYPE *serialize;
    fmi2DeSerializeFMUstateTYPE *deserialize;
    fmi2TerminateTYPE *terminate;
    fmi2FreeInstanceTYPE *free_instance;
} fmi;

static const char *names[] = {"fmi2Instantiate", "fmi2SetupExperiment", "fmi2EnterInitializationMode",
                              "fmi2ExitInitializationMode", "fmi2SetReal", "fmi2SetInteger", "fmi2SetString",
                              "fmi2GetReal", "fmi2GetInteger", "fmi2DoStep", "fmi2GetFMUstate",
                              "fmi2SetFMUstate", "fmi2FreeFMUstate", "fmi2SerializedFMUstateSize",
                              "fmi2SerializeFMUstate", "fmi2DeSerializeFMUstate", "fmi2Terminate",
                              "fmi2FreeInstance"};

static fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};

static Instance instantiate(const char *guid, const char *resources) {
    return fmi.instantiate("trace", fmi2CoSimulation, guid, resources, &callbacks, fmi2False, fmi2False);
}

static int initialize(Instance c) {
    CHECK(fmi.setup(c, fmi2False, 0.0, 0.0, fmi2False, 0.0));
    CHECK(fmi.enter(c));
    return 0;
}

static int do_step(Instance c, Real t, Real h) {
    CHECK(fmi.do_step(c, t, h, fmi2True));
    return 0;
}

#define SET(setter, c, vr, value) fmi.setter(c, vr, 1, value)
#define GET(getter, c, vrs, n, values) fmi.getter(c, vrs, n, values)
#endif

static int bind_functions(void *lib) {
    void **slot = (void **)&fmi;
    size_t i;
    for (i = 0; i < sizeof names / sizeof names[0]; i++) {
        slot[i] = SYMBOL(lib, names[i]);
        if (!slot[i]) {
            fprintf(stderr, "%s not exported\n", names[i]);
            return 1;
        }
    }
    return 0;
}

/* A comma-separated list of value references; returns their count. */
static size_t parse_vrs(const char *text, ValueReference *vrs) {
    size_t n = 0;
    char *end;
    while (*text && n < MAX_VARS) {
        vrs[n++] = (ValueReference)strtoul(text, &end, 10);
        text = *end == ',' ? end + 1 : end;
    }
    return n;
}

/* One `r:VR=VALUE`, `i:VR=VALUE` or `s:VR=TEXT` option applied; 1 when it is none of them. */
static int apply(Instance c, const char *option) {
    char *end;
    ValueReference vr = (ValueReference)strtoul(option + 2, &end, 10);
    if (*end != '=') return 1;
    if (option[0] == 'r') {
        Real value = strtod(end + 1, NULL);
        CHECK(SET(set_real, c, &vr, &value));
    } else if (option[0] == 'i') {
        Integer value = (Integer)strtol(end + 1, NULL, 10);
        CHECK(SET(set_integer, c, &vr, &value));
    } else if (option[0] == 's') {
        String value = end + 1;
        CHECK(SET(set_string, c, &vr, &value));
    } else {
        return 1;
    }
    return 0;
}

static int save_state(Instance c, const char *path) {
    State state = NULL;
    size_t size;
    Byte *bytes;
    FILE *file;
    CHECK(fmi.get_state(c, &state));
    CHECK(fmi.state_size(c, state, &size));
    bytes = malloc(size);
    if (!bytes) return 1;
    CHECK(fmi.serialize(c, state, bytes, size));
    CHECK(fmi.free_state(c, &state));
    file = fopen(path, "wb");
    if (!file || fwrite(bytes, 1, size, file) != size || fclose(file)) return 1;
    free(bytes);
    return 0;
}

static int load_state(Instance c, const char *path) {
    State state = NULL;
    Byte bytes[1 << 16];
    size_t size;
    FILE *file = fopen(path, "rb");
    if (!file) return 1;
    size = fread(bytes, 1, sizeof bytes, file);
    fclose(file);
    CHECK(fmi.deserialize(c, bytes, size, &state));
    CHECK(fmi.set_state(c, state));
    CHECK(fmi.free_state(c, &state));
    return 0;
}

int main(int argc, char **argv) {
    ValueReference reals[MAX_VARS], integers[MAX_VARS];
    Real real_values[MAX_VARS], h;
    Integer integer_values[MAX_VARS];
    size_t n_reals, n_integers, k;
    long steps, step, first = 0, save_at = -1;
    const char *save_path = NULL;
    Instance c;
    void *lib;
    int a;

    if (argc < 8) return 2;
    lib = OPEN(argv[1]);
    if (!lib) {
        fprintf(stderr, "cannot load %s\n", argv[1]);
        return 3;
    }
    if (bind_functions(lib)) return 3;
    steps = strtol(argv[4], NULL, 10);
    h = strtod(argv[5], NULL);
    n_reals = parse_vrs(argv[6], reals);
    n_integers = parse_vrs(argv[7], integers);
    c = instantiate(argv[2], argv[3]);
    if (!c) return 4;
    for (a = 8; a < argc; a++) {
        if (strncmp(argv[a], "save:", 5) == 0) {
            save_at = strtol(argv[a] + 5, NULL, 10);
            save_path = strchr(argv[a] + 5, ':') + 1;
        } else if (strncmp(argv[a], "load:", 5) != 0 && apply(c, argv[a])) {
            fprintf(stderr, "bad option %s\n", argv[a]);
            return 2;
        }
    }
    if (initialize(c)) return 1;
    CHECK(fmi.exit_init(c));
    for (a = 8; a < argc; a++) {
        if (strncmp(argv[a], "load:", 5) == 0) {
            first = strtol(argv[a] + 5, NULL, 10);
            if (load_state(c, strchr(argv[a] + 5, ':') + 1)) return 5;
        }
    }
    for (step = first; step < steps; step++) {
        if (do_step(c, step * h, h)) return 1;
        CHECK(GET(get_real, c, reals, n_reals, real_values));
        CHECK(GET(get_integer, c, integers, n_integers, integer_values));
        printf("%ld", step + 1);
        for (k = 0; k < n_reals; k++) {
            unsigned long long bits;
            memcpy(&bits, &real_values[k], sizeof bits);
            printf(" %016llx", bits);
        }
        for (k = 0; k < n_integers; k++) printf(" %ld", (long)integer_values[k]);
        printf("\n");
        if (step + 1 == save_at && save_state(c, save_path)) return 6;
    }
    CHECK(fmi.terminate(c));
    fmi.free_instance(c);
    return 0;
}
