/*
 * bench_fmu.c - the FMU's doStep from C against the rig's own step, side by
 * side in one process (benchmarks/bench_fmu.py builds and runs it).
 *
 *   bench_fmu BINARY GUID SAMPLES ROUNDS
 *
 * BINARY an FMI 2.0 FMU's shared library (binaries/linux64/<id>.so of an
 * FMU of the default parameters), GUID its guid.  The rig: the paper's
 * scenario as examples/rig_paper.c runs it (rr_rig_schedule and rr_rig_step
 * per sample), compiled with the FMU's flags into this program.  The FMU:
 * dlopen'ed, fmi2DoStep of one sample per call, of 8 samples per call, and
 * of one sample followed by fmi2GetReal of the 28 record outputs (what a
 * master reads at each step).  Each run covers SAMPLES samples from the
 * start (rig and FMU initialised outside the timing); the runs take turns,
 * ROUNDS times, and each one's best time is kept (clock_gettime,
 * CLOCK_MONOTONIC).  The FMU's last record is checked bitwise against the
 * rig's.  Prints one line per run: "name ns_per_sample".
 */
#define _POSIX_C_SOURCE 200809L
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "rollerrig.h"

/* the FMI 2.0 functions used, as this program calls them */
typedef void *component;
typedef struct {
    void (*logger)(void *, const char *, int, const char *, const char *, ...);
    void *(*allocate)(size_t, size_t);
    void (*release)(void *);
    void (*step_finished)(void *, int);
    void *environment;
} callbacks;
typedef component (*instantiate_fn)(const char *, int, const char *, const char *,
                                    const callbacks *, int, int);
typedef int (*setup_fn)(component, int, double, double, int, double);
typedef int (*mode_fn)(component);
typedef int (*step_fn)(component, double, double, int);
typedef int (*get_real_fn)(component, const unsigned *, size_t, double *);
typedef void (*free_fn)(component);

static void logger(void *env, const char *name, int status, const char *category,
                   const char *message, ...)
{
    (void)env;
    (void)name;
    (void)category;
    fprintf(stderr, "FMU (status %d): %s\n", status, message);
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void *sym(void *lib, const char *name)
{
    void *p = dlsym(lib, name);
    if (!p) {
        fprintf(stderr, "bench_fmu: %s not exported\n", name);
        exit(1);
    }
    return p;
}

#define NOUT (RR_REC_COUNT - 2)     /* the record's Real outputs: not the time, not the status */

int main(int argc, char **argv)
{
    static double work[RR_RIG_TABLE_WORK_LEN];
    static rr_rig rig;
    callbacks cb = {logger, NULL, NULL, NULL, NULL};
    rr_rig_config c;
    rr_rig_geometry g;
    rr_contact_table t;
    rr_rig_params p;
    double rec[RR_REC_COUNT], out[NOUT], *data, best[4] = {1e30, 1e30, 1e30, 1e30};
    unsigned vrs[NOUT];
    const char *names[4] = {"rr_rig_step", "fmi2DoStep_1", "fmi2DoStep_8",
                            "fmi2DoStep_1_GetReal_28"};
    void *lib;
    instantiate_fn instantiate;
    setup_fn setup;
    mode_fn enter, exit_init, reset;
    step_fn do_step;
    get_real_fn get_real;
    free_fn free_instance;
    component fmu;
    long n, k, len;
    int rounds, r, run, i, st;
    const double T = 0.004;

    if (argc != 5) {
        fprintf(stderr, "usage: bench_fmu BINARY GUID SAMPLES ROUNDS\n");
        return 1;
    }
    n = atol(argv[3]) / 8 * 8;
    rounds = atoi(argv[4]);
    if (!(lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL))) {
        fprintf(stderr, "bench_fmu: %s\n", dlerror());
        return 1;
    }
    *(void **)(&instantiate) = sym(lib, "fmi2Instantiate");
    *(void **)(&setup) = sym(lib, "fmi2SetupExperiment");
    *(void **)(&enter) = sym(lib, "fmi2EnterInitializationMode");
    *(void **)(&exit_init) = sym(lib, "fmi2ExitInitializationMode");
    *(void **)(&reset) = sym(lib, "fmi2Reset");
    *(void **)(&do_step) = sym(lib, "fmi2DoStep");
    *(void **)(&get_real) = sym(lib, "fmi2GetReal");
    *(void **)(&free_instance) = sym(lib, "fmi2FreeInstance");
    for (i = 0; i < NOUT; i++)
        vrs[i] = RR_FMU_VR_RECORD + 1 + (unsigned)i;
    if (!(fmu = instantiate("bench", 1, argv[2], "", &cb, 0, 0)))
        return 1;

    rr_rig_config_default(&c);
    rr_rig_geometry_from(&c, &g);
    len = rr_rig_table_data_len(&g);
    data = malloc((size_t)len * sizeof *data);
    if (!data || rr_rig_table_build(&g, data, len, work, RR_RIG_TABLE_WORK_LEN, &t, NULL) < 0
        || rr_rig_params_from(&c, &t, &p) < 0)
        return 1;

    for (r = 0; r < rounds; r++) {
        for (run = 0; run < 4; run++) {
            double t0, t1;
            st = 0;
            if (run == 0) {
                double roller_ref, xi_ref;
                rr_rig_init(&p, c.roller_speed / c.roller_radius, NULL, 0, &rig);
                t0 = now();
                for (k = 0; k < n && st >= 0; k++) {
                    rr_rig_schedule(&c, k, &roller_ref, &xi_ref);
                    st = rr_rig_step(&rig, roller_ref, xi_ref, rec);
                }
                t1 = now();
            } else {
                reset(fmu);
                setup(fmu, 0, 0.0, 0.0, 0, 0.0);
                enter(fmu);
                exit_init(fmu);
                t0 = now();
                if (run == 2)
                    for (k = 0; k < n && st == 0; k += 8)
                        st = do_step(fmu, k * T, 8 * T, 1);
                else
                    for (k = 0; k < n && st == 0; k++) {
                        st = do_step(fmu, k * T, T, 1);
                        if (run == 3)
                            get_real(fmu, vrs, NOUT, out);
                    }
                t1 = now();
                get_real(fmu, vrs, NOUT, out);
                /* the FMU's record is the rig's, bit for bit */
                if (memcmp(out, rec + 1, sizeof out) != 0) {
                    fprintf(stderr, "bench_fmu: the FMU's record differs from the rig's "
                            "(run %s)\n", names[run]);
                    return 1;
                }
            }
            if (st != 0) {
                fprintf(stderr, "bench_fmu: run %s failed at sample %ld (status %d)\n",
                        names[run], k, st);
                return 1;
            }
            if (t1 - t0 < best[run])
                best[run] = t1 - t0;
        }
    }
    for (run = 0; run < 4; run++)
        printf("%s %.1f\n", names[run], best[run] / n * 1e9);
    printf("samples %ld rounds %d\n", n, rounds);
    free_instance(fmu);
    free(data);
    return 0;
}
