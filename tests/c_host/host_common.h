/* What the C hosts share: a logger that prints each message to stderr and counts them, and CHECK, which
 * returns 1 from the calling function when an FMI call does not return fmi2OK (fmi3OK where FMI3 is defined:
 * the logger is then FMI 3.0's). Included after the FMI headers. */
#ifndef HOST_COMMON_H
#define HOST_COMMON_H

#include <stdarg.h>
#include <stdio.h>

static int logged = 0;

#ifdef FMI3
#define HOST_OK fmi3OK

static void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message) {
    (void)env;
    fprintf(stderr, "[%d %s] %s\n", (int)status, category, message);
    logged++;
}
#else
#define HOST_OK fmi2OK

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                   fmi2String message, ...) {
    va_list args;
    (void)env;
    va_start(args, message);
    fprintf(stderr, "[%s %d %s] ", name, (int)status, category);
    vfprintf(stderr, message, args);
    fprintf(stderr, "\n");
    va_end(args);
    logged++;
}
#endif

#define CHECK(call)                                                   \
    do {                                                              \
        int s_ = (int)(call);                                         \
        if (s_ != HOST_OK) {                                          \
            fprintf(stderr, "%s returned %d\n", #call, s_);           \
            return 1;                                                 \
        }                                                             \
    } while (0)

#endif
