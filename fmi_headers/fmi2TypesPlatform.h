/* FMI 2.0 platform types for PistonSlap, written from the FMI 2.0 standard's type list.
 * The "default" platform: 32-bit int for Integer and Boolean, double for Real. */
#ifndef fmi2TypesPlatform_h
#define fmi2TypesPlatform_h

#define fmi2TypesPlatform "default"

typedef void*        fmi2Component;            /* the FMU instance */
typedef void*        fmi2ComponentEnvironment; /* the host's pointer, passed back to callbacks */
typedef void*        fmi2FMUstate;             /* an opaque saved state */
typedef unsigned int fmi2ValueReference;
typedef double       fmi2Real;
typedef int          fmi2Integer;
typedef int          fmi2Boolean;
typedef char         fmi2Char;
typedef const fmi2Char* fmi2String;
typedef char         fmi2Byte;

#define fmi2True  1
#define fmi2False 0

#endif
