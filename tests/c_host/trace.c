/* A portable FMI 2.0 Co-Simulation host that loads an FMU binary at run time (dlopen on Linux, LoadLibrary
 * on Windows), runs fixed communication steps and prints every requested output after every step as the
 * hexadecimal bits of its value, so that two platforms' runs compare bit for bit as text.
 * Used by python/tests/test_platforms.py, natively against binaries/linux64 and under Wine against
 * binaries/win64 (compiled there with x86_64-w64-mingw32-gcc).
 *
 * Usage: trace <library> <guid> <resource URI> <steps> <step size> <real vrs,...> <integer vrs,...> [options]
 *   r:VR=VALUE  i:VR=VALUE  s:VR=TEXT   a parameter or input set before initialization
 *   save:K:FILE                          after step K, the serialized FMU state written to FILE
 *   load:K:FILE                          after initialization, the state read from FILE, then steps K+1..
 * Each printed line: the step number, then the reals, then the integers. Exit status 0 on success. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fmi2FunctionTypes.h"
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

/* The FMI functions this host calls, looked up by name. */
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

static int bind_functions(void *lib) {
    void **slot = (void **)&fmi;
    static const char *names[] = {"fmi2Instantiate", "fmi2SetupExperiment", "fmi2EnterInitializationMode",
                                  "fmi2ExitInitializationMode", "fmi2SetReal", "fmi2SetInteger", "fmi2SetString",
                                  "fmi2GetReal", "fmi2GetInteger", "fmi2DoStep", "fmi2GetFMUstate",
                                  "fmi2SetFMUstate", "fmi2FreeFMUstate", "fmi2SerializedFMUstateSize",
                                  "fmi2SerializeFMUstate", "fmi2DeSerializeFMUstate", "fmi2Terminate",
                                  "fmi2FreeInstance"};
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
static size_t parse_vrs(const char *text, fmi2ValueReference *vrs) {
    size_t n = 0;
    char *end;
    while (*text && n < MAX_VARS) {
        vrs[n++] = (fmi2ValueReference)strtoul(text, &end, 10);
        text = *end == ',' ? end + 1 : end;
    }
    return n;
}

/* One `r:VR=VALUE`, `i:VR=VALUE` or `s:VR=TEXT` option applied; 1 when it is none of them. */
static int apply(fmi2Component c, const char *option) {
    char *end;
    fmi2ValueReference vr = (fmi2ValueReference)strtoul(option + 2, &end, 10);
    if (*end != '=') return 1;
    if (option[0] == 'r') {
        fmi2Real value = strtod(end + 1, NULL);
        CHECK(fmi.set_real(c, &vr, 1, &value));
    } else if (option[0] == 'i') {
        fmi2Integer value = (fmi2Integer)strtol(end + 1, NULL, 10);
        CHECK(fmi.set_integer(c, &vr, 1, &value));
    } else if (option[0] == 's') {
        fmi2String value = end + 1;
        CHECK(fmi.set_string(c, &vr, 1, &value));
    } else {
        return 1;
    }
    return 0;
}

static int save_state(fmi2Component c, const char *path) {
    fmi2FMUstate state = NULL;
    size_t size;
    fmi2Byte *bytes;
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

static int load_state(fmi2Component c, const char *path) {
    fmi2FMUstate state = NULL;
    fmi2Byte bytes[1 << 16];
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
    fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};
    fmi2ValueReference reals[MAX_VARS], integers[MAX_VARS];
    fmi2Real real_values[MAX_VARS], h;
    fmi2Integer integer_values[MAX_VARS];
    size_t n_reals, n_integers, k;
    long steps, step, first = 0, save_at = -1;
    const char *save_path = NULL;
    fmi2Component c;
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
    c = fmi.instantiate("trace", fmi2CoSimulation, argv[2], argv[3], &callbacks, fmi2False, fmi2False);
    if (!c) return 4;
    CHECK(fmi.setup(c, fmi2False, 0.0, 0.0, fmi2False, 0.0));
    for (a = 8; a < argc; a++) {
        if (strncmp(argv[a], "save:", 5) == 0) {
            save_at = strtol(argv[a] + 5, NULL, 10);
            save_path = strchr(argv[a] + 5, ':') + 1;
        } else if (strncmp(argv[a], "load:", 5) != 0 && apply(c, argv[a])) {
            fprintf(stderr, "bad option %s\n", argv[a]);
            return 2;
        }
    }
    CHECK(fmi.enter(c));
    CHECK(fmi.exit_init(c));
    for (a = 8; a < argc; a++) {
        if (strncmp(argv[a], "load:", 5) == 0) {
            first = strtol(argv[a] + 5, NULL, 10);
            if (load_state(c, strchr(argv[a] + 5, ':') + 1)) return 5;
        }
    }
    for (step = first; step < steps; step++) {
        CHECK(fmi.do_step(c, step * h, h, fmi2True));
        CHECK(fmi.get_real(c, reals, n_reals, real_values));
        CHECK(fmi.get_integer(c, integers, n_integers, integer_values));
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
