/*
 * bench_nonhertz_speed.c - one wheel's non-Hertzian contact in C
 * (rr_nonhertz_wheel) against Hertz + FASTSIM 20 x 20 on the same states,
 * per wheel.  Built and run by benchmarks/bench_nonhertz_table.py:
 *
 *   cc -O2 -std=c99 -I csrc benchmarks/bench_nonhertz_speed.c \
 *      csrc/{util,contact,geometry,rig}/rr_*.c -lm -o bench_nonhertz_speed
 *   bench_nonhertz_speed FILE REPEATS
 *
 * FILE (native doubles): nrows, sigma, R0, G, nu, mu_ref, the rows
 * (nrows x RR_NH_ROW_LEN), n, then per state: y, Fz, mu, roller_spin, vmin,
 * motion 0 (c, v, w), motion 1 (c, v, w), and the Hertzian contact's cx, cy,
 * cphi, a, b, N (rig_contact's at the same state: FASTSIM's inputs).
 * Prints one line of JSON: best and median microseconds per wheel of each,
 * exact_table calls per wheel, states that failed.
 */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "rollerrig.h"

#define NSTATE 29
#define MAX_REPEATS 101

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

int main(int argc, char **argv)
{
    FILE *f;
    long size, n, i, bad = 0, calls = 0;
    double *d, tn[MAX_REPEATS], tf[MAX_REPEATS], sink = 0.0;
    const double *st;
    int repeats, r, k;
    rr_nh_table t;
    rr_creep_opts opts;
    rr_creep_checked checked;
    if (argc != 3 || (repeats = atoi(argv[2])) < 1 || repeats > MAX_REPEATS
        || !(f = fopen(argv[1], "rb")))
        return fprintf(stderr, "usage: %s FILE REPEATS (1..%d)\n", argv[0], MAX_REPEATS), 1;
    fseek(f, 0, SEEK_END);
    size = ftell(f);
    fseek(f, 0, SEEK_SET);
    d = malloc((size_t)size);
    if (!d || fread(d, 1, (size_t)size, f) != (size_t)size)
        return 1;
    fclose(f);
    t.nrows = (int)d[0];
    t.sigma = d[1];
    t.R0 = d[2];
    t.G = d[3];
    t.nu = d[4];
    t.mu_ref = d[5];
    t.rows = d + 6;
    n = (long)d[6 + (size_t)t.nrows * RR_NH_ROW_LEN];
    st = d + 7 + (size_t)t.nrows * RR_NH_ROW_LEN;
    if (rr_nonhertz_table_check(&t, NULL) != RR_OK)
        return fprintf(stderr, "invalid table\n"), 1;
    if (rr_creep_opts_default(&opts, rr_method_find("fastsim")) < 0
        || rr_creep_opts_set(&opts, "nx", 20) < 0 || rr_creep_opts_set(&opts, "ny", 20) < 0
        || rr_creep_check(&checked, &opts, NULL) < 0)
        return 1;
    for (r = 0; r < repeats; r++) {
        double t0 = now();
        for (i = 0; i < n; i++) {
            const double *c = st + i * NSTATE;
            rr_nh_state s;
            rr_nh_result res;
            s.y = c[0];
            s.Fz = c[1];
            s.mu = c[2];
            s.roller_spin = c[3];
            s.vmin = c[4];
            for (k = 0; k < 2; k++) {
                memcpy(s.motion[k].c, c + 5 + 9 * k, 3 * sizeof(double));
                memcpy(s.motion[k].v, c + 8 + 9 * k, 3 * sizeof(double));
                memcpy(s.motion[k].w, c + 11 + 9 * k, 3 * sizeof(double));
            }
            if (rr_nonhertz_wheel(&t, &s, &res) < 0) {
                bad += r == 0;
                continue;
            }
            calls += r == 0 ? res.table_calls : 0;
            sink += res.force[0];
        }
        tn[r] = (now() - t0) / (double)n * 1e6;
        t0 = now();
        for (i = 0; i < n; i++) {
            const double *c = st + i * NSTATE;
            rr_contact_problem p;
            rr_forces fo;
            memset(&p, 0, sizeof p);
            p.cx = c[23];
            p.cy = c[24];
            p.cphi = c[25];
            p.a = c[26];
            p.b = c[27];
            p.N = c[28];
            p.G = t.G;
            p.nu = t.nu;
            p.friction.mu0 = c[2];
            p.friction.A = 1.0;
            p.patch = RR_PATCH_ELLIPSE;
            if (rr_creep_forces_checked(&checked, &p, NULL, 0, NULL, &fo) >= 0)
                sink += fo.fx;
        }
        tf[r] = (now() - t0) / (double)n * 1e6;
    }
    qsort(tn, (size_t)repeats, sizeof *tn, cmp);
    qsort(tf, (size_t)repeats, sizeof *tf, cmp);
    printf("{\"states\": %ld, \"nonhertz_best_us\": %.3f, \"nonhertz_median_us\": %.3f, "
           "\"fastsim20_best_us\": %.3f, \"fastsim20_median_us\": %.3f, "
           "\"table_calls_per_wheel\": %.2f, \"failed\": %ld, \"sink\": %g}\n", n, tn[0],
           tn[repeats / 2], tf[0], tf[repeats / 2], (double)calls / (double)n, bad, sink);
    free(d);
    return 0;
}
