/*
 * bench_rig_method.c - the paper's scenario (as examples/rig_paper.c runs
 * it) on several creep-force methods, timed in C alone: the rig's real-time
 * factor per method without Python's per-chunk costs, the methods taking
 * turns in each round, best and median of the rounds.  Also the harness
 * for instruction counts of one method's run (valgrind --tool=callgrind
 * with --rounds 1 and one method).
 *
 *   cc -O3 -std=c99 -fno-wrapv -ffp-contract=off -I csrc \
 *      benchmarks/bench_rig_method.c csrc/{util,contact,geometry,rig}/rr_*.c \
 *      -lm -o bench_rig_method
 *   ./bench_rig_method [--rounds R] METHOD [METHOD ...]     (default: fastsim
 *      exact_table polach, 7 rounds)
 *
 * The flags are those of setup.py's build of the extension.  Each method
 * runs at its registry defaults, with the rig's defaults otherwise (falling
 * friction; FASTSIM at the rig's 20 x 20, rigid slip speed, as rr_rig_params_from
 * sets it).  Prints per method the samples, the held creepage at the end
 * and the best and median wall time of the step loop and its real-time
 * factor (simulated time over wall time).
 */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "rollerrig.h"

#define MAXM 8
#define MAXR 101

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static rr_rig rig;

/* one run of the scenario; the wall time of its step loop, or -1 */
static double run(const rr_rig_config *c, const rr_rig_params *p, double *last)
{
    double rec[RR_REC_COUNT], roller_ref, xi_ref, t0;
    long k, n = rr_rig_samples(c);
    int st;
    if ((st = rr_rig_init(p, c->roller_speed / c->roller_radius, NULL, 0, &rig)) < 0) {
        fprintf(stderr, "init: %s\n", rr_status_message(st));
        return -1.0;
    }
    t0 = now();
    for (k = 0; k < n; k++) {
        rr_rig_schedule(c, k, &roller_ref, &xi_ref);
        st = rr_rig_step(&rig, roller_ref, xi_ref, rec);
        if (st < 0) {
            fprintf(stderr, "sample %ld: %s\n", k, rr_status_message(st));
            return -1.0;
        }
    }
    *last = rec[0];
    return now() - t0;
}

int main(int argc, char **argv)
{
    static double work[RR_RIG_TABLE_WORK_LEN];
    static const char *defaults[] = {"fastsim", "exact_table", "polach"};
    const char *names[MAXM];
    rr_rig_config c;
    rr_rig_geometry g;
    rr_contact_table t;
    rr_rig_params p[MAXM];
    double times[MAXM][MAXR], *data, last = 0.0;
    long len;
    int i, m, nm = 0, rounds = 7, st;

    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--rounds") == 0 && i + 1 < argc)
            rounds = atoi(argv[++i]);
        else if (nm < MAXM)
            names[nm++] = argv[i];
    }
    if (rounds < 1 || rounds > MAXR) {
        fprintf(stderr, "--rounds: 1 .. %d\n", MAXR);
        return 1;
    }
    if (nm == 0)
        for (nm = 0; nm < 3; nm++)
            names[nm] = defaults[nm];

    rr_rig_config_default(&c);
    rr_rig_geometry_from(&c, &g);
    len = rr_rig_table_data_len(&g);
    if (!(data = malloc((size_t)len * sizeof *data)))
        return 1;
    if ((st = rr_rig_table_build(&g, data, len, work, RR_RIG_TABLE_WORK_LEN, &t, NULL)) < 0) {
        fprintf(stderr, "table: %s\n", rr_status_message(st));
        return 1;
    }
    for (m = 0; m < nm; m++) {
        if ((st = rr_rig_params_from(&c, &t, &p[m])) < 0) {
            fprintf(stderr, "params: %s\n", rr_status_message(st));
            return 1;
        }
        if (strcmp(names[m], "fastsim") != 0) {
            const int id = rr_method_find(names[m]);
            if (id < 0 || rr_creep_opts_default(&p[m].contact.creep, id) < 0) {
                fprintf(stderr, "unknown method %s\n", names[m]);
                return 1;
            }
        }
    }
    for (i = 0; i < rounds; i++)
        for (m = 0; m < nm; m++)
            if ((times[m][i] = run(&c, &p[m], &last)) < 0.0)
                return 1;
    for (m = 0; m < nm; m++) {
        const double dur = (double)rr_rig_samples(&c) * c.T;
        double best;
        qsort(times[m], (size_t)rounds, sizeof times[m][0], cmp);
        best = times[m][0];
        printf("%-14s samples %ld  best %.3f ms (RTF %.0f)  median %.3f ms (RTF %.0f)\n",
               names[m], rr_rig_samples(&c), best * 1e3, dur / best,
               times[m][rounds / 2] * 1e3, dur / times[m][rounds / 2]);
    }
    (void)last;
    free(data);
    return 0;
}
