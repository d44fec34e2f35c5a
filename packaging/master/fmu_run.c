/* fmu_run: a minimal FMI 2.0 and FMI 3.0 co-simulation master in portable C, for comparing the
 * FMU's binaries across platforms and FMI versions bit for bit.
 *
 *   fmu_run LIBRARY GUID STOP_TIME STEP REAL_VRS OUT [--save-at K STATE] [--restore-at K STATE]
 *           [--fmi3]
 *
 * Loads LIBRARY (dlopen, or LoadLibrary on Windows), instantiates it with GUID, runs from 0 to
 * STOP_TIME in communication steps STEP, and writes one line per communication point to OUT:
 * the point's index and, for every value reference of the comma-separated list REAL_VRS, the 64
 * bits of its value in hexadecimal (so that the files compare bit for bit, whatever the C
 * library's printf). --save-at K STATE serializes the FMU state at point K into the file STATE;
 * --restore-at K STATE starts instead by restoring that state and continues from point K.
 * --fmi3 drives the library's fmi3* functions instead (GUID is then the instantiation token).
 * OUT "-" reads the values at every point but writes nothing (for timing the FMU alone).
 * The environment variable FMU_RUN_SET="VR=VALUE,iVR=VALUE…" sets those Real (Float64) variables,
 * and with the prefix i those Integer (Int32) ones, after instantiation, before initialization
 * (parameters such as rod.dampingRatio or joint.model).
 * Exit status 0 on success; every failing call is reported on stderr with its status.
 */
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _WIN32
#include <windows.h>
#define LOAD(path) ((void *)LoadLibraryA(path))
#define SYMBOL(lib, name) ((void *)GetProcAddress((HMODULE)(lib), name))
#else
#include <dlfcn.h>
#define LOAD(path) dlopen(path, RTLD_NOW | RTLD_LOCAL)
#define SYMBOL(lib, name) dlsym(lib, name)
#endif

typedef void *fmi2Component;
typedef void *fmi2FMUstate;
typedef unsigned int fmi2ValueReference;
typedef int fmi2Boolean;
typedef int fmi2Status;
typedef void (*fmi2CallbackLogger)(void *, const char *, fmi2Status, const char *, const char *, ...);
typedef struct {
    fmi2CallbackLogger logger;
    void *(*allocateMemory)(size_t, size_t);
    void (*freeMemory)(void *);
    void (*stepFinished)(void *, fmi2Status);
    void *componentEnvironment;
} fmi2CallbackFunctions;

typedef fmi2Component (*Instantiate)(const char *, int, const char *, const char *,
                                     const fmi2CallbackFunctions *, fmi2Boolean, fmi2Boolean);
typedef fmi2Status (*SetupExperiment)(fmi2Component, fmi2Boolean, double, double, fmi2Boolean, double);
typedef fmi2Status (*OneArg)(fmi2Component);
typedef fmi2Status (*GetReal)(fmi2Component, const fmi2ValueReference *, size_t, double *);
typedef fmi2Status (*DoStep)(fmi2Component, double, double, fmi2Boolean);
typedef fmi2Status (*GetState)(fmi2Component, fmi2FMUstate *);
typedef fmi2Status (*StateSize)(fmi2Component, fmi2FMUstate, size_t *);
typedef fmi2Status (*Serialize)(fmi2Component, fmi2FMUstate, char *, size_t);
typedef fmi2Status (*Deserialize)(fmi2Component, const char *, size_t, fmi2FMUstate *);
typedef fmi2Status (*SetState)(fmi2Component, fmi2FMUstate);
typedef void (*FreeInstance)(fmi2Component);

/* FMI 3.0: the functions whose signatures differ from FMI 2's. */
typedef void (*fmi3LogMessage)(void *, int, const char *, const char *);
typedef fmi2Component (*Instantiate3)(const char *, const char *, const char *, bool, bool, bool, bool,
                                      const fmi2ValueReference *, size_t, void *, fmi3LogMessage, void *);
typedef fmi2Status (*EnterInitialization3)(fmi2Component, bool, double, double, bool, double);
typedef fmi2Status (*GetFloat64)(fmi2Component, const fmi2ValueReference *, size_t, double *, size_t);
typedef fmi2Status (*SetReal)(fmi2Component, const fmi2ValueReference *, size_t, const double *);
typedef fmi2Status (*SetFloat64)(fmi2Component, const fmi2ValueReference *, size_t, const double *, size_t);
typedef fmi2Status (*SetInteger)(fmi2Component, const fmi2ValueReference *, size_t, const int *);
typedef fmi2Status (*SetInt32)(fmi2Component, const fmi2ValueReference *, size_t, const int32_t *, size_t);
typedef fmi2Status (*DoStep3)(fmi2Component, double, double, bool, bool *, bool *, bool *, double *);

static void logger3(void *env, int status, const char *category, const char *message) {
    (void)env;
    fprintf(stderr, "[fmi3] %s (status %d): %s\n", category, status, message);
}

static void logger(void *env, const char *name, fmi2Status status, const char *category,
                   const char *message, ...) {
    va_list args;
    (void)env;
    fprintf(stderr, "[%s] %s (status %d): ", name, category, status);
    va_start(args, message);
    vfprintf(stderr, message, args);
    va_end(args);
    fputc('\n', stderr);
}

static void *library;

static void *symbol(const char *name) {
    void *f = SYMBOL(library, name);
    if (!f) {
        fprintf(stderr, "fmu_run: %s not exported\n", name);
        exit(2);
    }
    return f;
}

static void check(fmi2Status status, const char *call) {
    if (status != 0) {
        fprintf(stderr, "fmu_run: %s returned status %d\n", call, status);
        exit(1);
    }
}

int main(int argc, char **argv) {
    if (argc < 7) {
        fprintf(stderr, "usage: fmu_run LIBRARY GUID STOP_TIME STEP REAL_VRS OUT "
                        "[--save-at K STATE | --restore-at K STATE]\n");
        return 2;
    }
    const char *guid = argv[2];
    double stop = strtod(argv[3], NULL), h = strtod(argv[4], NULL);
    fmi2ValueReference vrs[256];
    size_t nvr = 0;
    for (char *p = argv[5]; *p && nvr < 256;) {
        vrs[nvr++] = (fmi2ValueReference)strtoul(p, &p, 10);
        if (*p == ',') p++;
    }
    bool fmi3 = strcmp(argv[argc - 1], "--fmi3") == 0;
    if (fmi3) argc--;
    long save_at = -1, restore_at = -1;
    const char *state_file = NULL;
    if (argc == 10 && strcmp(argv[7], "--save-at") == 0) save_at = atol(argv[8]);
    if (argc == 10 && strcmp(argv[7], "--restore-at") == 0) restore_at = atol(argv[8]);
    if (argc == 10) state_file = argv[9];
    /* The FMU-state functions of either version (FMI 3 renames them, same signatures). */
    const char *get_state = fmi3 ? "fmi3GetFMUState" : "fmi2GetFMUstate";
    const char *state_size = fmi3 ? "fmi3SerializedFMUStateSize" : "fmi2SerializedFMUstateSize";
    const char *serialize = fmi3 ? "fmi3SerializeFMUState" : "fmi2SerializeFMUstate";
    const char *deserialize = fmi3 ? "fmi3DeserializeFMUState" : "fmi2DeSerializeFMUstate";
    const char *set_state = fmi3 ? "fmi3SetFMUState" : "fmi2SetFMUstate";

    library = LOAD(argv[1]);
    if (!library) {
        fprintf(stderr, "fmu_run: cannot load %s\n", argv[1]);
        return 2;
    }
    fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};
    fmi2Component c = fmi3 ? ((Instantiate3)symbol("fmi3InstantiateCoSimulation"))(
                                 "run", guid, NULL, false, false, false, false, NULL, 0, NULL, logger3, NULL)
                           : ((Instantiate)symbol("fmi2Instantiate"))("run", 1, guid, "file:///", &callbacks, 0, 0);
    if (!c) {
        fprintf(stderr, "fmu_run: instantiation failed\n");
        return 1;
    }
    const char *set = getenv("FMU_RUN_SET");
    for (const char *p = set ? set : ""; *p;) {
        bool integer = *p == 'i';
        char *end;
        fmi2ValueReference vr = (fmi2ValueReference)strtoul(p + integer, &end, 10);
        bool assigns = *end == '=';
        double value = assigns ? strtod(end + 1, &end) : 0.0;
        if (!assigns || (*end != ',' && *end != '\0')) {
            fprintf(stderr, "fmu_run: FMU_RUN_SET wants VR=VALUE or iVR=VALUE, comma-separated: %s\n", set);
            return 2;
        }
        int32_t n = (int32_t)value;
        if (integer && fmi3)
            check(((SetInt32)symbol("fmi3SetInt32"))(c, &vr, 1, &n, 1), "fmi3SetInt32");
        else if (integer)
            check(((SetInteger)symbol("fmi2SetInteger"))(c, &vr, 1, &n), "fmi2SetInteger");
        else if (fmi3)
            check(((SetFloat64)symbol("fmi3SetFloat64"))(c, &vr, 1, &value, 1), "fmi3SetFloat64");
        else
            check(((SetReal)symbol("fmi2SetReal"))(c, &vr, 1, &value), "fmi2SetReal");
        p = *end == ',' ? end + 1 : end;
    }
    if (fmi3) {
        check(((EnterInitialization3)symbol("fmi3EnterInitializationMode"))(c, false, 0.0, 0.0, true, stop),
              "fmi3EnterInitializationMode");
        check(((OneArg)symbol("fmi3ExitInitializationMode"))(c), "fmi3ExitInitializationMode");
    } else {
        check(((SetupExperiment)symbol("fmi2SetupExperiment"))(c, 0, 0.0, 0.0, 1, stop), "fmi2SetupExperiment");
        check(((OneArg)symbol("fmi2EnterInitializationMode"))(c), "fmi2EnterInitializationMode");
        check(((OneArg)symbol("fmi2ExitInitializationMode"))(c), "fmi2ExitInitializationMode");
    }

    long n = (long)(stop / h + 0.5), first = 0;
    if (restore_at >= 0) {
        FILE *f = fopen(state_file, "rb");
        if (!f) {
            fprintf(stderr, "fmu_run: cannot read %s\n", state_file);
            return 2;
        }
        static char bytes[1 << 24];
        size_t size = fread(bytes, 1, sizeof bytes, f);
        fclose(f);
        fmi2FMUstate s = NULL;
        check(((Deserialize)symbol(deserialize))(c, bytes, size, &s), deserialize);
        check(((SetState)symbol(set_state))(c, s), set_state);
        first = restore_at;
    }
    bool quiet = strcmp(argv[6], "-") == 0;
    FILE *out = quiet ? NULL : fopen(argv[6], "w");
    if (!quiet && !out) {
        fprintf(stderr, "fmu_run: cannot write %s\n", argv[6]);
        return 2;
    }
    GetReal get_real = fmi3 ? NULL : (GetReal)symbol("fmi2GetReal");
    DoStep do_step = fmi3 ? NULL : (DoStep)symbol("fmi2DoStep");
    GetFloat64 get_float64 = fmi3 ? (GetFloat64)symbol("fmi3GetFloat64") : NULL;
    DoStep3 do_step3 = fmi3 ? (DoStep3)symbol("fmi3DoStep") : NULL;
    double values[256];
    for (long k = first;; k++) {
        if (fmi3)
            check(get_float64(c, vrs, nvr, values, nvr), "fmi3GetFloat64");
        else
            check(get_real(c, vrs, nvr, values), "fmi2GetReal");
        if (!quiet) {
            fprintf(out, "%ld", k);
            for (size_t i = 0; i < nvr; i++) {
                uint64_t bits;
                memcpy(&bits, &values[i], sizeof bits);
                fprintf(out, " %016llx", (unsigned long long)bits);
            }
            fputc('\n', out);
        }
        if (k == save_at) {
            fmi2FMUstate s = NULL;
            size_t size = 0;
            check(((GetState)symbol(get_state))(c, &s), get_state);
            check(((StateSize)symbol(state_size))(c, s, &size), state_size);
            char *bytes = malloc(size);
            check(((Serialize)symbol(serialize))(c, s, bytes, size), serialize);
            FILE *f = fopen(state_file, "wb");
            if (!f || fwrite(bytes, 1, size, f) != size) {
                fprintf(stderr, "fmu_run: cannot write %s\n", state_file);
                return 2;
            }
            fclose(f);
            free(bytes);
        }
        if (k == n) break;
        /* The communication points as a master computes them: k h, in floating point. */
        if (fmi3) {
            bool event, terminate, early;
            double last;
            check(do_step3(c, (double)k * h, h, true, &event, &terminate, &early, &last), "fmi3DoStep");
        } else {
            check(do_step(c, (double)k * h, h, 1), "fmi2DoStep");
        }
    }
    if (out) fclose(out);
    check(((OneArg)symbol(fmi3 ? "fmi3Terminate" : "fmi2Terminate"))(c), "Terminate");
    ((FreeInstance)symbol(fmi3 ? "fmi3FreeInstance" : "fmi2FreeInstance"))(c);
    return 0;
}
