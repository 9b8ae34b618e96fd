/* What the C hosts share: a logger that prints each message to stderr and counts them, and CHECK, which
 * returns 1 from the calling function when an FMI call does not return fmi2OK. Included after the FMI
 * headers. */
#ifndef HOST_COMMON_H
#define HOST_COMMON_H

#include <stdarg.h>
#include <stdio.h>

static int logged = 0;

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

#define CHECK(call)                                                   \
    do {                                                              \
        fmi2Status s_ = (call);                                       \
        if (s_ != fmi2OK) {                                           \
            fprintf(stderr, "%s returned %d\n", #call, (int)s_);      \
            return 1;                                                 \
        }                                                             \
    } while (0)

#endif
