/*
 * bench_fft.c - time the FFT convolutions of csrc/util/rr_fft.h in C alone:
 * rr_conv2d_apply (one real kernel) and rr_conv2d_apply2 (a 2x2 block of
 * four non-even kernels, and its diagonal case Kxy = Kyx = NULL), and
 * rr_conv2d_spectrum, on mx x my grids (default 11, 29, 47, 101 square).
 *
 * Build and run (from the repository root):
 *   cc -O3 -std=c99 -Wall -Wextra -pedantic -Werror -I csrc benchmarks/bench_fft.c \
 *      csrc/util/rr_fft.c csrc/util/rr_status.c -lm -o bench_fft
 *   ./bench_fft [--repeats R] [--min-ms T] [N ...]
 * (add -ffp-contract=off for the Python extension's flags).  Compare with
 *   python benchmarks/bench_fft_numpy.py [N ...]
 * which times numpy.fft.fft2 + ifft2 of a complex field on the same torus.
 *
 * Each item is timed in batches of calls lasting at least T ms (2); the
 * median over R batches (21) of the time per call is printed, the items
 * taking turns within each round (clock_gettime, CLOCK_MONOTONIC); the
 * fastest batch too (_best_us: steadier on a shared machine).  Inputs
 * are uniform random in [-1, 1] (fixed seed); before timing, each product
 * is checked against the direct sum (relative to max |out|), printed as
 * err.  One line of JSON per grid size.
 */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "util/rr_common.h"
#include "util/rr_fft.h"

#define MAX_REPEATS 201
#define NITEMS 4

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static unsigned long long rng_state = 0x9E3779B97F4A7C15ull;

static double urand(void)
{
    /* splitmix64 */
    unsigned long long z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) / 9007199254740992.0 * 2.0 - 1.0;
}

static void *xmalloc(size_t n)
{
    void *p = malloc(n > 0 ? n : 1);
    if (!p) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    return p;
}

/* out += K * in by the direct sum */
static void direct_add(int mx, int my, const double *K, const double *in, double *out)
{
    const int kw = 2 * mx - 1;
    int ix, iy, jx, jy;
    for (iy = 0; iy < my; iy++)
        for (ix = 0; ix < mx; ix++) {
            double s = 0.0;
            for (jy = 0; jy < my; jy++)
                for (jx = 0; jx < mx; jx++)
                    s += K[(iy - jy + my - 1) * kw + (ix - jx + mx - 1)] * in[jy * mx + jx];
            out[iy * mx + ix] += s;
        }
}

static double rel_err(int n, const double *got, const double *want)
{
    double e = 0.0, m = 0.0;
    int i;
    for (i = 0; i < n; i++) {
        e = fmax(e, fabs(got[i] - want[i]));
        m = fmax(m, fabs(want[i]));
    }
    return e / (m > 0.0 ? m : 1.0);
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

typedef struct {
    rr_conv2d cv;
    double *spec[4], *kern[4], *inx, *iny, *outx, *outy;
    int n;
} bench_case;

static int run_item(bench_case *c, int item)
{
    switch (item) {
    case 0:
        return rr_conv2d_apply(&c->cv, c->spec[0], c->inx, c->outx);
    case 1:
        return rr_conv2d_apply2(&c->cv, c->spec[0], c->spec[1], c->spec[2], c->spec[3], c->inx,
                                c->iny, c->outx, c->outy);
    case 2:
        return rr_conv2d_apply2(&c->cv, c->spec[0], NULL, NULL, c->spec[3], c->inx, c->iny,
                                c->outx, c->outy);
    default:
        return rr_conv2d_spectrum(&c->cv, c->kern[0], c->spec[0]);
    }
}

static const char *const item_name[NITEMS] = {"apply", "apply2", "apply2_diag", "spectrum"};

int main(int argc, char **argv)
{
    int sizes[32], nsizes = 0, repeats = 21, a, si, k, i, item, rep;
    double min_s = 2e-3;

    for (a = 1; a < argc; a++) {
        if (strcmp(argv[a], "--repeats") == 0 && a + 1 < argc)
            repeats = atoi(argv[++a]);
        else if (strcmp(argv[a], "--min-ms") == 0 && a + 1 < argc)
            min_s = atof(argv[++a]) * 1e-3;
        else if (nsizes < 32 && atoi(argv[a]) > 0)
            sizes[nsizes++] = atoi(argv[a]);
        else {
            fprintf(stderr, "usage: %s [--repeats R] [--min-ms T] [N ...]\n", argv[0]);
            return 2;
        }
    }
    if (repeats < 1 || repeats > MAX_REPEATS)
        repeats = 21;
    if (nsizes == 0) {
        sizes[0] = 11;
        sizes[1] = 29;
        sizes[2] = 47;
        sizes[3] = 101;
        nsizes = 4;
    }
    for (si = 0; si < nsizes; si++) {
        const int m = sizes[si], n = m * m, nk = (2 * m - 1) * (2 * m - 1);
        const size_t wl = rr_conv2d_workspace_len(m, m);
        double *work = xmalloc(wl * sizeof *work), *rx, *ry;
        double t[NITEMS][MAX_REPEATS], med[NITEMS], best[NITEMS], err[3];
        long calls[NITEMS];
        bench_case c;
        size_t sl;
        int bad = 0;

        if (rr_conv2d_init(&c.cv, m, m, work, wl) != RR_OK) {
            fprintf(stderr, "init failed at %d\n", m);
            return 1;
        }
        sl = rr_conv2d_spectrum_len(&c.cv);
        c.n = n;
        for (k = 0; k < 4; k++) {
            c.kern[k] = xmalloc((size_t)nk * sizeof(double));
            c.spec[k] = xmalloc(sl * sizeof(double));
            for (i = 0; i < nk; i++)
                c.kern[k][i] = urand();
            bad |= rr_conv2d_spectrum(&c.cv, c.kern[k], c.spec[k]) != RR_OK;
        }
        c.inx = xmalloc((size_t)n * sizeof(double));
        c.iny = xmalloc((size_t)n * sizeof(double));
        c.outx = xmalloc((size_t)n * sizeof(double));
        c.outy = xmalloc((size_t)n * sizeof(double));
        rx = xmalloc((size_t)n * sizeof(double));
        ry = xmalloc((size_t)n * sizeof(double));
        for (i = 0; i < n; i++) {
            c.inx[i] = urand();
            c.iny[i] = urand();
        }
        /* check against the direct sum */
        bad |= run_item(&c, 0) != RR_OK;
        memset(rx, 0, (size_t)n * sizeof *rx);
        direct_add(m, m, c.kern[0], c.inx, rx);
        err[0] = rel_err(n, c.outx, rx);
        bad |= run_item(&c, 1) != RR_OK;
        memset(ry, 0, (size_t)n * sizeof *ry);
        direct_add(m, m, c.kern[1], c.iny, rx);
        direct_add(m, m, c.kern[2], c.inx, ry);
        direct_add(m, m, c.kern[3], c.iny, ry);
        err[1] = fmax(rel_err(n, c.outx, rx), rel_err(n, c.outy, ry));
        bad |= run_item(&c, 2) != RR_OK;
        memset(rx, 0, (size_t)n * sizeof *rx);
        memset(ry, 0, (size_t)n * sizeof *ry);
        direct_add(m, m, c.kern[0], c.inx, rx);
        direct_add(m, m, c.kern[3], c.iny, ry);
        err[2] = fmax(rel_err(n, c.outx, rx), rel_err(n, c.outy, ry));

        /* calls per batch: enough for min_s */
        for (item = 0; item < NITEMS; item++) {
            long nc = 1;
            for (;;) {
                double t0 = now(), dt;
                long j;
                for (j = 0; j < nc; j++)
                    run_item(&c, item);
                dt = now() - t0;
                if (dt >= min_s || nc > (1L << 24))
                    break;
                nc = dt > 0 ? (long)(nc * 1.2 * min_s / dt) + 1 : nc * 10;
            }
            calls[item] = nc;
        }
        for (rep = 0; rep < repeats; rep++)
            for (item = 0; item < NITEMS; item++) {
                double t0 = now();
                long j;
                for (j = 0; j < calls[item]; j++)
                    bad |= run_item(&c, item) != RR_OK;
                t[item][rep] = (now() - t0) / (double)calls[item];
            }
        for (item = 0; item < NITEMS; item++) {
            qsort(t[item], (size_t)repeats, sizeof(double), cmp_double);
            med[item] = t[item][repeats / 2];
            best[item] = t[item][0];
        }
        printf("{\"mx\": %d, \"my\": %d, \"L1\": %d, \"L2\": %d, \"repeats\": %d", m, m,
               c.cv.L1, c.cv.L2, repeats);
        for (item = 0; item < NITEMS; item++)
            printf(", \"%s_us\": %.3f", item_name[item], med[item] * 1e6);
        for (item = 0; item < NITEMS; item++)
            printf(", \"%s_best_us\": %.3f", item_name[item], best[item] * 1e6);
        printf(", \"err\": [%.2e, %.2e, %.2e], \"bad\": %d}\n", err[0], err[1], err[2], bad);
        fflush(stdout);
        for (k = 0; k < 4; k++) {
            free(c.kern[k]);
            free(c.spec[k]);
        }
        free(c.inx);
        free(c.iny);
        free(c.outx);
        free(c.outy);
        free(rx);
        free(ry);
        free(work);
    }
    return 0;
}
