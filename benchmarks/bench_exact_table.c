/*
 * bench_exact_table.c - time the exact-theory table's lookup alone
 * (rr_exact_table_forces on the built-in table, through the method's
 * dispatcher as the batch API and the rig call it), in C alone, on seeded
 * random cases drawn as tests/test_exact_table.py draws them: a/b
 * log-uniform over [0.1, 10], c = sqrt(ab) 3-9 mm, N 5-100 kN, mu 0.1-0.5,
 * each creepage's magnitude log-uniform from 1e-4 to 1e3 times the
 * saturation scale, its sign -1, 0, +1, +1 with equal chances; Coulomb
 * friction.  Also the instruction-count harness (valgrind --tool=callgrind
 * with --repeats 1; the drawing of the cases is a small, fixed part).
 *
 *   cc -O3 -std=c99 -fno-wrapv -ffp-contract=off -I csrc \
 *      benchmarks/bench_exact_table.c csrc/{util,contact,geometry,rig}/rr_*.c \
 *      -lm -o bench_exact_table
 *   ./bench_exact_table [--n N] [--repeats R] [--seed S]     (100000, 7, 1)
 *
 * Prints one line of JSON: n, repeats, the best and median time per case
 * [us] over the passes (clock_gettime, CLOCK_MONOTONIC), cases with an
 * error status, and a checksum of the forces (the same on every build that
 * rounds alike).
 */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "rollerrig.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static uint64_t rng_state;

static double uniform(double lo, double hi)   /* splitmix64 */
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return lo + (hi - lo) * (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

static int cmp(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

int main(int argc, char **argv)
{
    const double G = 8.2e10, nu = 0.28;
    long n = 100000, i;
    int repeats = 7, r, k, bad = 0, method;
    double times[101], sum = 0.0;
    rr_contact_problem *cs;
    rr_forces *out;
    rr_creep_opts o;

    rng_state = 1;
    for (k = 1; k < argc; k++) {
        if (strcmp(argv[k], "--n") == 0 && k + 1 < argc)
            n = atol(argv[++k]);
        else if (strcmp(argv[k], "--repeats") == 0 && k + 1 < argc)
            repeats = atoi(argv[++k]);
        else if (strcmp(argv[k], "--seed") == 0 && k + 1 < argc)
            rng_state = (uint64_t)atol(argv[++k]);
    }
    if (n < 1 || repeats < 1 || repeats > 101)
        return 1;
    method = rr_method_find("exact_table");
    if (method < 0 || rr_creep_opts_default(&o, method) != RR_OK)
        return 1;
    cs = calloc((size_t)n, sizeof *cs);          /* zeroed: ellipse problems */
    out = malloc((size_t)n * sizeof *out);
    if (!cs || !out)
        return 1;
    for (i = 0; i < n; i++) {
        const double aob = exp(uniform(log(0.1), log(10.0))), c = uniform(3e-3, 9e-3);
        const double N = uniform(5e3, 1e5), mu = uniform(0.1, 0.5), s = mu * N / (G * c * c);
        double mag[3];
        for (k = 0; k < 3; k++) {
            const double u = uniform(0.0, 4.0);
            mag[k] = s * exp(uniform(log(1e-4), log(1e3)))
                   * (u < 1.0 ? -1.0 : u < 2.0 ? 0.0 : 1.0);
        }
        cs[i].a = c * sqrt(aob);
        cs[i].b = c / sqrt(aob);
        cs[i].N = N;
        cs[i].G = G;
        cs[i].nu = nu;
        cs[i].cx = mag[0] / 4.0;
        cs[i].cy = mag[1] / 4.0;
        cs[i].cphi = mag[2] / (4.0 * c);
        cs[i].speed = 0.0;
        cs[i].friction.mu0 = mu;     /* Coulomb */
        cs[i].friction.A = 1.0;
        cs[i].friction.B = 0.0;
    }
    for (i = 0; i < n; i++)
        out[i].fx = out[i].fy = out[i].mz = 0.0;
    for (r = 0; r < repeats; r++) {
        const double t0 = now();
        for (i = 0; i < n; i++)
            if (rr_creep_forces(&cs[i], &o, &out[i]) < 0)
                bad++;
        times[r] = (now() - t0) / (double)n;
    }
    for (i = 0; i < n; i++)
        sum += out[i].fx / cs[i].N + 2.0 * out[i].fy / cs[i].N
             + 3.0 * out[i].mz / (cs[i].N * sqrt(cs[i].a * cs[i].b));
    qsort(times, (size_t)repeats, sizeof times[0], cmp);
    printf("{\"n\": %ld, \"repeats\": %d, \"best_us\": %.4f, \"median_us\": %.4f, "
           "\"bad\": %d, \"checksum\": %.17g}\n",
           n, repeats, times[0] * 1e6, times[repeats / 2] * 1e6, bad, sum);
    free(cs);
    free(out);
    return 0;
}
