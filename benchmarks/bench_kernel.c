/*
 * bench_kernel.c - time the rollerrig C kernels alone (no Python), on the
 * very cases that benchmarks/bench_contact.py times through the binding.
 *
 * Built and run by bench_contact.py:
 *   cc -O3 -std=c99 -I csrc benchmarks/bench_kernel.c csrc/{util,contact,geometry,rig}/rr_*.c -lm -o bench_kernel
 *   bench_kernel hertz FILE REPEATS
 *   bench_kernel creep FILE REPEATS METHOD NX NY GRID
 *
 * FILE (native byte order): int64 n, int64 ncols, then per column an int64
 * length (n, or 1 for a broadcast constant) and that many doubles.  Columns:
 *   hertz: A, B, N, E1, nu1, E2, nu2                      (7)
 *   creep: cx, cy, cphi, a, b, N, mu, G, nu, speed, A, B   (12)
 * the argument order of the binding.  The loop is the binding's inner
 * loop (rollerrig/_core_c/contact.c: py_hertz, py_creep_forces) without the GIL
 * release between chunks: read the inputs through a stride (0 for a
 * constant), call the kernel, store the outputs and the status into arrays
 * of length n.  The binding's per-call costs are deliberately left out.
 *
 * Prints one line of JSON: {"n": ..., "repeats": ..., "best_s": ...,
 * "median_s": ..., "bad": ..., "checksum": ...}; best_s is the fastest of
 * REPEATS passes over all n cases (clock_gettime, CLOCK_MONOTONIC).  The
 * output arrays are written once before the first pass, so no pass pays their
 * page faults.  bench_contact.py runs one pass per call and alternates the
 * calls with the Python timings.
 */
#define _POSIX_C_SOURCE 199309L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "rollerrig.h"

#define MAX_COLS 12

typedef struct {
    const double *data;
    long stride;   /* in doubles: 1, or 0 for a broadcast constant */
} column;

#define IN(col, i) ((col).data[(long)(i) * (col).stride])

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void die(const char *msg)
{
    fprintf(stderr, "bench_kernel: %s\n", msg);
    exit(2);
}

/* Read FILE into cols[0..want-1]; returns n. */
static long read_cases(const char *path, int want, column *cols)
{
    FILE *f = fopen(path, "rb");
    int64_t n, ncols, len;
    int k;

    if (!f)
        die("cannot open the case file");
    if (fread(&n, sizeof n, 1, f) != 1 || fread(&ncols, sizeof ncols, 1, f) != 1)
        die("short case file header");
    if (n < 1 || ncols != want)
        die("case file: wrong number of cases or columns");
    for (k = 0; k < want; k++) {
        double *buf;
        if (fread(&len, sizeof len, 1, f) != 1 || (len != 1 && len != n))
            die("case file: bad column length");
        buf = malloc((size_t)len * sizeof *buf);
        if (!buf)
            die("out of memory");
        if (fread(buf, sizeof *buf, (size_t)len, f) != (size_t)len)
            die("case file: short column");
        cols[k].data = buf;
        cols[k].stride = len == 1 ? 0 : 1;
    }
    fclose(f);
    return (long)n;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

int main(int argc, char **argv)
{
    column in[MAX_COLS];
    double *o1, *o2, *o3, *o4, *times, checksum = 0.0;
    signed char *st;
    long n, i, bad = 0;
    int repeats, r, hertz;
    rr_creep_opts opts;
    rr_creep_checked checked;

    if (argc < 4)
        die("usage: bench_kernel hertz FILE REPEATS | creep FILE REPEATS METHOD NX NY GRID");
    hertz = strcmp(argv[1], "hertz") == 0;
    if (!hertz && strcmp(argv[1], "creep") != 0)
        die("first argument must be hertz or creep");
    repeats = atoi(argv[3]);
    if (repeats < 1)
        die("REPEATS must be >= 1");
    if (!hertz) {
        if (argc != 8)
            die("creep needs METHOD NX NY GRID");
        /* METHOD by name; NX, NY, GRID (its index) where the method has them */
        if (rr_creep_opts_default(&opts, rr_method_find(argv[4])) < 0)
            die("unknown METHOD");
        if (rr_method_option(rr_method_get(opts.method), "nx") >= 0
            && (rr_creep_opts_set(&opts, "nx", atof(argv[5])) < 0
                || rr_creep_opts_set(&opts, "ny", atof(argv[6])) < 0))
            die("invalid creep options");
        if (rr_method_option(rr_method_get(opts.method), "grid") >= 0
            && rr_creep_opts_set(&opts, "grid", atof(argv[7])) < 0)
            die("invalid creep options");
        /* checked once for the batch, as the binding does (rr_creep_check) */
        if (rr_creep_check(&checked, &opts, NULL) < 0 || checked.work_len > 0)
            die("invalid creep options (or a method with a workspace)");
    }
    n = read_cases(argv[2], hertz ? 7 : 12, in);
    o1 = malloc((size_t)n * sizeof *o1);
    o2 = malloc((size_t)n * sizeof *o2);
    o3 = malloc((size_t)n * sizeof *o3);
    o4 = malloc((size_t)n * sizeof *o4);
    st = malloc((size_t)n);
    times = malloc((size_t)repeats * sizeof *times);
    if (!o1 || !o2 || !o3 || !o4 || !st || !times)
        die("out of memory");
    /* touch the outputs once, so that no pass pays their page faults */
    memset(o1, 0, (size_t)n * sizeof *o1);
    memset(o2, 0, (size_t)n * sizeof *o2);
    memset(o3, 0, (size_t)n * sizeof *o3);
    memset(o4, 0, (size_t)n * sizeof *o4);
    memset(st, 0, (size_t)n);

    for (r = 0; r < repeats; r++) {
        double t0 = now();
        if (hertz) {
            /* as py_hertz */
            for (i = 0; i < n; i++) {
                rr_hertz_result h;
                const int s = rr_hertz_bodies(IN(in[0], i), IN(in[1], i), IN(in[2], i),
                                              IN(in[3], i), IN(in[4], i), IN(in[5], i),
                                              IN(in[6], i), &h);
                o1[i] = h.a;
                o2[i] = h.b;
                o3[i] = h.p0;
                o4[i] = h.delta;
                st[i] = (signed char)s;
            }
        } else {
            /* as py_creep_forces and its load_case */
            for (i = 0; i < n; i++) {
                rr_contact_problem c;
                rr_forces f;
                c.cx = IN(in[0], i);
                c.cy = IN(in[1], i);
                c.cphi = IN(in[2], i);
                c.a = IN(in[3], i);
                c.b = IN(in[4], i);
                c.N = IN(in[5], i);
                c.friction.mu0 = IN(in[6], i);
                c.G = IN(in[7], i);
                c.nu = IN(in[8], i);
                c.speed = IN(in[9], i);
                c.friction.A = IN(in[10], i);
                c.friction.B = IN(in[11], i);
                c.patch = RR_PATCH_ELLIPSE;
                st[i] = (signed char)rr_creep_forces_checked(&checked, &c, NULL, 0, NULL, &f);
                o1[i] = f.fx;
                o2[i] = f.fy;
                o3[i] = f.mz;
            }
        }
        times[r] = now() - t0;
    }

    for (i = 0; i < n; i++) {
        if (st[i] < 0) {
            bad++;
            continue;
        }
        checksum += o1[i] + o2[i] + o3[i] + (hertz ? o4[i] : 0.0);
    }
    {
        double best = times[0];
        for (r = 1; r < repeats; r++)
            if (times[r] < best)
                best = times[r];
        qsort(times, (size_t)repeats, sizeof *times, cmp_double);
        printf("{\"n\": %ld, \"repeats\": %d, \"best_s\": %.9e, \"median_s\": %.9e, "
               "\"bad\": %ld, \"checksum\": %.17g}\n",
               n, repeats, best, times[repeats / 2], bad, checksum);
    }
    return 0;
}
