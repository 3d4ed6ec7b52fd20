/*
 * test_fft.c - the FFT convolutions (rr_fft): rr_fft_good_size, and
 * rr_conv2d_apply / rr_conv2d_apply2 against the direct sum
 *     out(ix, iy) = sum_{jx, jy} K(ix - jx, iy - jy) in(jx, jy)
 * (long double accumulation) on grids whose tori take every kind of stage:
 * one element, one row or column, odd and prime sides, the pruned radix-4
 * ends, the partial first and last stages of odd lengths (45 = 9 5,
 * 81 = 9 9), single-stage lengths (3, 5, 9), radix 6, 8 and 9 (96, 216).
 * Kernels are random, so not even in kx or ky; the 2x2 block with every
 * pattern of NULL spectra, Kxy == Kyx as one array, inputs and outputs
 * aliased.  Then every documented error status, NaN outputs on error,
 * and the workspace and spectrum left alone outside what they promise.
 * Where the AVX2 build exists and runs (rr_fft.h), it gives the
 * baseline's doubles bit for bit, spectra and both products.
 *
 * Tolerance: 1e-13 of max |out| (the brief of the module: a product's
 * error is a few 1e-16 of it).
 */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "util/rr_common.h"
#include "util/rr_fft.h"
#include "rr_test.h"

#define TOL 1e-13

static unsigned long long rng = 12345u;

static double urand(void)
{
    /* splitmix64, uniform in [-1, 1] */
    unsigned long long z = (rng += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) / 9007199254740992.0 * 2.0 - 1.0;
}

static void *xcalloc(size_t n, size_t size)
{
    void *p = calloc(n > 0 ? n : 1, size);
    if (!p) {
        printf("out of memory\n");
        exit(2);
    }
    return p;
}

/* out = sum of K_k * in_k over the nonzero kernels given (K may be NULL) */
static void direct(int mx, int my, const double *K1, const double *in1, const double *K2,
                   const double *in2, double *out)
{
    const int kw = 2 * mx - 1;
    int ix, iy, jx, jy;
    for (iy = 0; iy < my; iy++)
        for (ix = 0; ix < mx; ix++) {
            long double s = 0.0L;
            for (jy = 0; jy < my; jy++)
                for (jx = 0; jx < mx; jx++) {
                    const int o = (iy - jy + my - 1) * kw + (ix - jx + mx - 1);
                    if (K1)
                        s += (long double)K1[o] * in1[jy * mx + jx];
                    if (K2)
                        s += (long double)K2[o] * in2[jy * mx + jx];
                }
            out[iy * mx + ix] = (double)s;
        }
}

/* max |got - want| / max |want| (or the absolute error if want is 0) */
static double rel_err(int n, const double *got, const double *want)
{
    double e = 0.0, m = 0.0;
    int i;
    for (i = 0; i < n; i++) {
        if (isnan(got[i]))
            return INFINITY;
        e = fmax(e, fabs(got[i] - want[i]));
        m = fmax(m, fabs(want[i]));
    }
    return m > 0.0 ? e / m : e;
}

static int all_nan(const double *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (!isnan(v[i]))
            return 0;
    return 1;
}

/* ---- rr_fft_good_size ---------------------------------------------------------- */

static int smooth235(int v)
{
    while (v % 2 == 0)
        v /= 2;
    while (v % 3 == 0)
        v /= 3;
    while (v % 5 == 0)
        v /= 5;
    return v == 1;
}

static void test_good_size(void)
{
    static const int table[][2] = {
        {1, 1}, {2, 2}, {3, 3}, {7, 8}, {11, 12}, {13, 15}, {17, 18}, {21, 24}, {57, 60},
        {93, 96}, {97, 100}, {201, 216}, {1000, 1000}, {4095, 4096}, {8191, 8192},
        {1000003, 1012500}, {1048575, 1048576}, {1048576, 1048576}
    };
    char buf[80];
    int i, n, bad = 0;
    for (i = 0; i < (int)(sizeof table / sizeof table[0]); i++) {
        snprintf(buf, sizeof buf, "rr_fft_good_size(%d) = %d", table[i][0], table[i][1]);
        CHECK(rr_fft_good_size(table[i][0]) == table[i][1], buf);
    }
    /* the least 2^a 3^b 5^c >= n, for every n up to 3000 */
    for (n = 1; n <= 3000; n++) {
        const int g = rr_fft_good_size(n);
        int v;
        if (g < n || !smooth235(g))
            bad++;
        for (v = n; v < g; v++)
            if (smooth235(v))
                bad++;
    }
    CHECK(bad == 0, "rr_fft_good_size(n) is the least 5-smooth number >= n, n <= 3000");
    CHECK(rr_fft_good_size(0) == 0, "rr_fft_good_size(0) = 0");
    {
        /* the torus: a multiple of 4 unless the good size is 10 % shorter */
        static const int tl[][2] = {{1, 1}, {2, 2}, {5, 5}, {13, 16}, {25, 25}, {29, 32},
                                    {49, 50}, {61, 64}, {89, 96}, {97, 100}, {121, 128},
                                    {129, 144}, {169, 180}, {8191, 8192}};
        int bad4 = 0, m;
        for (i = 0; i < (int)(sizeof tl / sizeof tl[0]); i++) {
            snprintf(buf, sizeof buf, "rr_conv2d_torus_len(%d) = %d", tl[i][0], tl[i][1]);
            CHECK(rr_conv2d_torus_len(tl[i][0]) == tl[i][1], buf);
        }
        for (m = 1; m <= 3000; m++) {
            const int t = rr_conv2d_torus_len(m), g = rr_fft_good_size(m);
            bad4 += t < m || rr_fft_good_size(t) != t || (t != g && t % 4 != 0);
        }
        CHECK(bad4 == 0, "rr_conv2d_torus_len(n): 5-smooth, >= n, the good size or a multiple of 4");
        CHECK(rr_conv2d_torus_len(0) == 0 && rr_conv2d_torus_len(RR_FFT_MAX_LEN) == 0,
              "rr_conv2d_torus_len out of range = 0");
    }
    CHECK(rr_fft_good_size(-5) == 0, "rr_fft_good_size(-5) = 0");
    CHECK(rr_fft_good_size(INT_MIN) == 0, "rr_fft_good_size(INT_MIN) = 0");
    CHECK(rr_fft_good_size(RR_FFT_MAX_LEN + 1) == 0, "rr_fft_good_size above the cap = 0");
    CHECK(rr_fft_good_size(INT_MAX) == 0, "rr_fft_good_size(INT_MAX) = 0");
}

/* ---- products against the direct sum ----------------------------------------------- */

typedef struct {
    int mx, my;
    double *work;
    size_t work_len;
    rr_conv2d cv;
    size_t sl;
    int n, nk;
    double *K[4], *S[4];
} engine;

static int engine_open(engine *e, int mx, int my)
{
    int k, i, st;
    e->mx = mx;
    e->my = my;
    e->n = mx * my;
    e->nk = (2 * mx - 1) * (2 * my - 1);
    e->work_len = rr_conv2d_workspace_len(mx, my);
    e->work = xcalloc(e->work_len, sizeof(double));
    st = rr_conv2d_init(&e->cv, mx, my, e->work, e->work_len);
    if (st != RR_OK)
        return st;
    e->sl = rr_conv2d_spectrum_len(&e->cv);
    for (k = 0; k < 4; k++) {
        e->K[k] = xcalloc((size_t)e->nk, sizeof(double));
        e->S[k] = xcalloc(e->sl, sizeof(double));
        for (i = 0; i < e->nk; i++)
            e->K[k][i] = urand();
        st = rr_conv2d_spectrum(&e->cv, e->K[k], e->S[k]);
        if (st != RR_OK)
            return st;
    }
    return RR_OK;
}

static void engine_close(engine *e)
{
    int k;
    for (k = 0; k < 4; k++) {
        free(e->K[k]);
        free(e->S[k]);
    }
    free(e->work);
}

/* The AVX2 build against the baseline: the same doubles (no contraction,
 * the same operations in the same order, only wider registers). */
static void test_isa_builds(engine *e, const double *inx, const double *iny)
{
#if RR_FFT_DISPATCH
    const size_t n = (size_t)e->n, sb = e->sl * sizeof(double), vb = n * sizeof(double);
    double *s1, *s2, *o[6];
    int k, st;
    char buf[160];
    if (!__builtin_cpu_supports("avx2"))
        return;
    s1 = xcalloc(e->sl, sizeof(double));
    s2 = xcalloc(e->sl, sizeof(double));
    for (k = 0; k < 6; k++)
        o[k] = xcalloc(n, sizeof(double));
    st = rr_conv2d_spectrum_baseline(&e->cv, e->K[1], s1);
    st |= rr_conv2d_spectrum_avx2(&e->cv, e->K[1], s2);
    st |= rr_conv2d_apply_baseline(&e->cv, e->S[0], inx, o[0]);
    st |= rr_conv2d_apply_avx2(&e->cv, e->S[0], inx, o[1]);
    st |= rr_conv2d_apply2_baseline(&e->cv, e->S[0], e->S[1], e->S[2], e->S[3], inx, iny, o[2],
                                    o[3]);
    st |= rr_conv2d_apply2_avx2(&e->cv, e->S[0], e->S[1], e->S[2], e->S[3], inx, iny, o[4],
                                o[5]);
    snprintf(buf, sizeof buf, "%dx%d: the AVX2 build gives the baseline's doubles", e->mx,
             e->my);
    CHECK(st == RR_OK && memcmp(s1, s2, sb) == 0 && memcmp(o[0], o[1], vb) == 0
          && memcmp(o[2], o[4], vb) == 0 && memcmp(o[3], o[5], vb) == 0, buf);
    free(s1);
    free(s2);
    for (k = 0; k < 6; k++)
        free(o[k]);
#else
    (void)e;
    (void)inx;
    (void)iny;
#endif
}

/* rr_conv2d_spectrum_torus of a kernel laid on the torus by hand (zero
 * between the grid's offsets) gives rr_conv2d_spectrum's bits: the same
 * field is transformed; and its own refusals. */
static void test_torus(engine *e)
{
    const int L1 = e->cv.L1, L2 = e->cv.L2, mx = e->mx, my = e->my;
    double *t = xcalloc((size_t)L1 * L2, sizeof(double)), *s = xcalloc(e->sl, sizeof(double));
    int kx, ky, st;
    char buf[160];
    for (ky = -(my - 1); ky < my; ky++)
        for (kx = -(mx - 1); kx < mx; kx++)
            t[(size_t)(ky < 0 ? ky + L2 : ky) * L1 + (kx < 0 ? kx + L1 : kx)] =
                e->K[2][(size_t)(ky + my - 1) * (2 * mx - 1) + (kx + mx - 1)];
    st = rr_conv2d_spectrum_torus(&e->cv, t, s);
    snprintf(buf, sizeof buf, "%dx%d: the torus spectrum is the grid kernel's", mx, my);
    CHECK(st == RR_OK && memcmp(s, e->S[2], e->sl * sizeof *s) == 0, buf);
#if RR_FFT_DISPATCH
    if (__builtin_cpu_supports("avx2")) {
        double *s2 = xcalloc(e->sl, sizeof(double));
        st = rr_conv2d_spectrum_torus_baseline(&e->cv, t, s);
        st |= rr_conv2d_spectrum_torus_avx2(&e->cv, t, s2);
        snprintf(buf, sizeof buf, "%dx%d: torus spectrum, AVX2 = baseline", mx, my);
        CHECK(st == RR_OK && memcmp(s, s2, e->sl * sizeof *s) == 0, buf);
        free(s2);
    }
#endif
    t[0] = NAN;
    CHECK_STATUS(rr_conv2d_spectrum_torus(&e->cv, t, s), RR_ERR_NONFINITE, "torus: NaN kernel");
    CHECK(isnan(s[0]) && isnan(s[e->sl - 1]), "torus: NaN spectrum on error");
    CHECK_STATUS(rr_conv2d_spectrum_torus(&e->cv, NULL, s), RR_ERR_NULL, "torus: kern NULL");
    CHECK_STATUS(rr_conv2d_spectrum_torus(NULL, t, s), RR_ERR_NULL, "torus: cv NULL");
    free(t);
    free(s);
}

static void test_grid(int mx, int my)
{
    engine e;
    double *inx, *iny, *ox, *oy, *rx, *ry, *cx, *cy, err;
    int st, i, mask;
    char buf[160];

    st = engine_open(&e, mx, my);
    snprintf(buf, sizeof buf, "%dx%d: init and spectra", mx, my);
    if (!CHECK_STATUS(st, RR_OK, buf))
        return;
    inx = xcalloc((size_t)e.n, sizeof(double));
    iny = xcalloc((size_t)e.n, sizeof(double));
    ox = xcalloc((size_t)e.n, sizeof(double));
    oy = xcalloc((size_t)e.n, sizeof(double));
    rx = xcalloc((size_t)e.n, sizeof(double));
    ry = xcalloc((size_t)e.n, sizeof(double));
    cx = xcalloc((size_t)e.n, sizeof(double));
    cy = xcalloc((size_t)e.n, sizeof(double));
    for (i = 0; i < e.n; i++) {
        inx[i] = urand();
        iny[i] = urand();
    }

    /* scalar */
    st = rr_conv2d_apply(&e.cv, e.S[0], inx, ox);
    direct(mx, my, e.K[0], inx, NULL, NULL, rx);
    err = rel_err(e.n, ox, rx);
    snprintf(buf, sizeof buf, "%dx%d (torus %dx%d): apply vs direct sum, error %.2e", mx, my,
             e.cv.L1, e.cv.L2, err);
    CHECK(st == RR_OK && err <= TOL, buf);

    /* in place: out == in */
    memcpy(cx, inx, (size_t)e.n * sizeof *cx);
    st = rr_conv2d_apply(&e.cv, e.S[0], cx, cx);
    snprintf(buf, sizeof buf, "%dx%d: apply in place (out == in) gives the same bits", mx, my);
    CHECK(st == RR_OK && memcmp(cx, ox, (size_t)e.n * sizeof *cx) == 0, buf);

    /* 2x2 block, every pattern of NULL spectra */
    for (mask = 0; mask < 16; mask++) {
        const double *sxx = mask & 1 ? e.S[0] : NULL, *sxy = mask & 2 ? e.S[1] : NULL;
        const double *syx = mask & 4 ? e.S[2] : NULL, *syy = mask & 8 ? e.S[3] : NULL;
        st = rr_conv2d_apply2(&e.cv, sxx, sxy, syx, syy, inx, iny, ox, oy);
        direct(mx, my, sxx ? e.K[0] : NULL, inx, sxy ? e.K[1] : NULL, iny, rx);
        direct(mx, my, syx ? e.K[2] : NULL, inx, syy ? e.K[3] : NULL, iny, ry);
        err = fmax(rel_err(e.n, ox, rx), rel_err(e.n, oy, ry));
        snprintf(buf, sizeof buf, "%dx%d: apply2 (Kxx %s, Kxy %s, Kyx %s, Kyy %s) vs direct, "
                 "error %.2e", mx, my, sxx ? "set" : "NULL", sxy ? "set" : "NULL",
                 syx ? "set" : "NULL", syy ? "set" : "NULL", err);
        CHECK(st == RR_OK && err <= TOL, buf);
        if (mask == 0) {
            int zero = 1;
            for (i = 0; i < e.n; i++)
                zero &= ox[i] == 0.0 && oy[i] == 0.0;
            snprintf(buf, sizeof buf, "%dx%d: apply2 with four NULL spectra gives zeros", mx, my);
            CHECK(zero, buf);
        }
    }

    /* Kxy == Kyx, one array for both */
    st = rr_conv2d_apply2(&e.cv, e.S[0], e.S[1], e.S[1], e.S[3], inx, iny, ox, oy);
    direct(mx, my, e.K[0], inx, e.K[1], iny, rx);
    direct(mx, my, e.K[1], inx, e.K[3], iny, ry);
    err = fmax(rel_err(e.n, ox, rx), rel_err(e.n, oy, ry));
    snprintf(buf, sizeof buf, "%dx%d: apply2 with sxy == syx (one array), error %.2e", mx, my,
             err);
    CHECK(st == RR_OK && err <= TOL, buf);

    /* aliasing: in place, and crossed (outx = iny, outy = inx) */
    st = rr_conv2d_apply2(&e.cv, e.S[0], e.S[1], e.S[2], e.S[3], inx, iny, ox, oy);
    memcpy(cx, inx, (size_t)e.n * sizeof *cx);
    memcpy(cy, iny, (size_t)e.n * sizeof *cy);
    st |= rr_conv2d_apply2(&e.cv, e.S[0], e.S[1], e.S[2], e.S[3], cx, cy, cx, cy);
    snprintf(buf, sizeof buf, "%dx%d: apply2 in place (outx == inx, outy == iny)", mx, my);
    CHECK(st == RR_OK && memcmp(cx, ox, (size_t)e.n * sizeof *cx) == 0
          && memcmp(cy, oy, (size_t)e.n * sizeof *cy) == 0, buf);
    memcpy(cx, inx, (size_t)e.n * sizeof *cx);
    memcpy(cy, iny, (size_t)e.n * sizeof *cy);
    st = rr_conv2d_apply2(&e.cv, e.S[0], e.S[1], e.S[2], e.S[3], cx, cy, cy, cx);
    snprintf(buf, sizeof buf, "%dx%d: apply2 crossed (outx == iny, outy == inx)", mx, my);
    CHECK(st == RR_OK && memcmp(cy, ox, (size_t)e.n * sizeof *cy) == 0
          && memcmp(cx, oy, (size_t)e.n * sizeof *cx) == 0, buf);

    test_isa_builds(&e, inx, iny);
    test_torus(&e);
    free(inx);
    free(iny);
    free(ox);
    free(oy);
    free(rx);
    free(ry);
    free(cx);
    free(cy);
    engine_close(&e);
}

/* A kernel that is one at offset (dx, dy): out is in shifted by (dx, dy),
 * zero where the shift brings in nothing (linear, not circular). */
static void test_shift(int mx, int my, int dx, int dy)
{
    engine e;
    double *in, *out, err = 0.0;
    int i, ix, iy, st;
    char buf[120];

    st = engine_open(&e, mx, my);
    if (!CHECK_STATUS(st, RR_OK, "shift: init"))
        return;
    memset(e.K[0], 0, (size_t)e.nk * sizeof(double));
    e.K[0][(dy + my - 1) * (2 * mx - 1) + (dx + mx - 1)] = 1.0;
    st = rr_conv2d_spectrum(&e.cv, e.K[0], e.S[0]);
    in = xcalloc((size_t)e.n, sizeof(double));
    out = xcalloc((size_t)e.n, sizeof(double));
    for (i = 0; i < e.n; i++)
        in[i] = urand();
    st |= rr_conv2d_apply(&e.cv, e.S[0], in, out);
    for (iy = 0; iy < my; iy++)
        for (ix = 0; ix < mx; ix++) {
            const int jx = ix - dx, jy = iy - dy;
            const double want = jx >= 0 && jx < mx && jy >= 0 && jy < my ? in[jy * mx + jx] : 0.0;
            err = fmax(err, fabs(out[iy * mx + ix] - want));
        }
    snprintf(buf, sizeof buf, "%dx%d: the kernel delta(%d, %d) shifts the field, error %.2e",
             mx, my, dx, dy, err);
    CHECK(st == RR_OK && err <= 1e-15, buf);
    free(in);
    free(out);
    engine_close(&e);
}

/* ---- errors ------------------------------------------------------------------------ */

static void test_errors(void)
{
    const int mx = 7, my = 5, n = mx * my;
    engine e;
    rr_conv2d cv, zeroed;
    size_t need;
    double *work, *in, *iny, *out, *outy, *spec_copy;
    double kern[13 * 9];
    int st, i;

    /* sizes */
    CHECK(rr_conv2d_workspace_len(0, 5) == 0, "workspace_len(0, 5) = 0");
    CHECK(rr_conv2d_workspace_len(5, 0) == 0, "workspace_len(5, 0) = 0");
    CHECK(rr_conv2d_workspace_len(-1, 5) == 0, "workspace_len(-1, 5) = 0");
    CHECK(rr_conv2d_workspace_len(RR_CONV2D_MAX_GRID + 1, 5) == 0, "workspace_len above the cap");
    CHECK(rr_conv2d_workspace_len(5, INT_MAX) == 0, "workspace_len(5, INT_MAX) = 0");
    CHECK(rr_conv2d_workspace_len(INT_MIN, 5) == 0, "workspace_len(INT_MIN, 5) = 0");
    CHECK(rr_conv2d_workspace_len(RR_CONV2D_MAX_GRID, RR_CONV2D_MAX_GRID) > 0,
          "workspace_len at the cap > 0");
    need = rr_conv2d_workspace_len(mx, my);
    CHECK(need > 0, "workspace_len(7, 5) > 0");

    /* init */
    work = xcalloc(need + 16, sizeof(double));
    CHECK_STATUS(rr_conv2d_init(NULL, mx, my, work, need), RR_ERR_NULL, "init: cv NULL");
    CHECK_STATUS(rr_conv2d_init(&cv, 0, my, work, need), RR_ERR_GRID, "init: mx = 0");
    CHECK_STATUS(rr_conv2d_init(&cv, mx, -3, work, need), RR_ERR_GRID, "init: my < 0");
    CHECK_STATUS(rr_conv2d_init(&cv, RR_CONV2D_MAX_GRID + 1, my, work, need), RR_ERR_GRID,
                 "init: mx above RR_CONV2D_MAX_GRID");
    CHECK_STATUS(rr_conv2d_init(&cv, INT_MAX, my, work, need), RR_ERR_GRID, "init: mx INT_MAX");
    CHECK_STATUS(rr_conv2d_init(&cv, mx, my, NULL, need), RR_ERR_WORKSPACE, "init: work NULL");
    CHECK_STATUS(rr_conv2d_init(&cv, mx, my, work, need - 1), RR_ERR_WORKSPACE,
                 "init: work one double short");
    CHECK_STATUS(rr_conv2d_init(&cv, mx, my, work, 0), RR_ERR_WORKSPACE, "init: work_len 0");
    /* a failed init leaves cv unusable */
    CHECK(rr_conv2d_spectrum_len(&cv) == 0, "spectrum_len after a failed init = 0");
    in = xcalloc((size_t)n, sizeof(double));
    out = xcalloc((size_t)n, sizeof(double));
    CHECK_STATUS(rr_conv2d_apply(&cv, work, in, out), RR_ERR_NULL, "apply after a failed init");
    memset(&zeroed, 0, sizeof zeroed);
    CHECK_STATUS(rr_conv2d_apply(&zeroed, work, in, out), RR_ERR_NULL,
                 "apply on a zeroed (never initialised) rr_conv2d");
    CHECK_STATUS(rr_conv2d_apply2(&zeroed, NULL, NULL, NULL, NULL, in, in, out, out),
                 RR_ERR_NULL, "apply2 on a zeroed rr_conv2d");
    CHECK_STATUS(rr_conv2d_spectrum(&zeroed, kern, work), RR_ERR_NULL,
                 "spectrum on a zeroed rr_conv2d");
    CHECK_STATUS(rr_conv2d_apply(NULL, work, in, out), RR_ERR_NULL, "apply: cv NULL");
    CHECK(rr_conv2d_spectrum_len(NULL) == 0, "spectrum_len(NULL) = 0");

    /* the exact length is enough, and nothing beyond it is written */
    for (i = 0; i < 16; i++)
        work[need + (size_t)i] = 12345.0;
    st = rr_conv2d_init(&cv, mx, my, work, need);
    CHECK_STATUS(st, RR_OK, "init with exactly workspace_len doubles");
    {
        double *spec = xcalloc(rr_conv2d_spectrum_len(&cv), sizeof(double));
        int untouched = 1;
        for (i = 0; i < 13 * 9; i++)
            kern[i] = urand();
        st = rr_conv2d_spectrum(&cv, kern, spec);
        st |= rr_conv2d_apply(&cv, spec, kern, out);
        st |= rr_conv2d_apply2(&cv, spec, spec, spec, spec, kern, kern + n, out, in);
        for (i = 0; i < 16; i++)
            untouched &= work[need + (size_t)i] == 12345.0;
        CHECK(st == RR_OK && untouched, "the calls write nothing past workspace_len doubles");
        free(spec);
    }
    free(work);
    free(in);
    free(out);

    /* spectrum, apply, apply2 errors on a working engine */
    st = engine_open(&e, mx, my);
    if (!CHECK_STATUS(st, RR_OK, "errors: engine"))
        return;
    in = xcalloc((size_t)n, sizeof(double));
    iny = xcalloc((size_t)n, sizeof(double));
    out = xcalloc((size_t)n, sizeof(double));
    outy = xcalloc((size_t)n, sizeof(double));
    spec_copy = xcalloc(e.sl, sizeof(double));
    for (i = 0; i < n; i++) {
        in[i] = urand();
        iny[i] = urand();
    }

    CHECK(e.sl == 2 * (size_t)e.cv.L1 * (size_t)(e.cv.L2 / 2 + 1), "spectrum_len = 2 L1 (L2/2 + 1)");
    CHECK_STATUS(rr_conv2d_spectrum(&e.cv, NULL, e.S[3]), RR_ERR_NULL, "spectrum: kern NULL");
    CHECK(all_nan(e.S[3], e.sl), "spectrum: NaN after kern NULL");
    CHECK_STATUS(rr_conv2d_spectrum(&e.cv, e.K[3], NULL), RR_ERR_NULL, "spectrum: spec NULL");
    memcpy(kern, e.K[3], sizeof kern);
    kern[40] = NAN;
    CHECK_STATUS(rr_conv2d_spectrum(&e.cv, kern, e.S[3]), RR_ERR_NONFINITE, "spectrum: NaN kernel");
    CHECK(all_nan(e.S[3], e.sl), "spectrum: NaN after a NaN kernel");
    kern[40] = -INFINITY;
    CHECK_STATUS(rr_conv2d_spectrum(&e.cv, kern, e.S[3]), RR_ERR_NONFINITE, "spectrum: -inf kernel");
    for (i = 0; i < 13 * 9; i++)
        kern[i] = DBL_MAX;
    CHECK_STATUS(rr_conv2d_spectrum(&e.cv, kern, e.S[3]), RR_ERR_RANGE,
                 "spectrum: kernel of DBL_MAX overflows");
    CHECK(all_nan(e.S[3], e.sl), "spectrum: NaN after overflow");

    memcpy(spec_copy, e.S[0], e.sl * sizeof(double));
    CHECK_STATUS(rr_conv2d_apply(&e.cv, NULL, in, out), RR_ERR_NULL, "apply: spec NULL");
    CHECK(all_nan(out, (size_t)n), "apply: out NaN after spec NULL");
    CHECK_STATUS(rr_conv2d_apply(&e.cv, e.S[0], NULL, out), RR_ERR_NULL, "apply: in NULL");
    CHECK(all_nan(out, (size_t)n), "apply: out NaN after in NULL");
    CHECK_STATUS(rr_conv2d_apply(&e.cv, e.S[0], in, NULL), RR_ERR_NULL, "apply: out NULL");
    in[17] = NAN;
    CHECK_STATUS(rr_conv2d_apply(&e.cv, e.S[0], in, out), RR_ERR_NONFINITE, "apply: NaN input");
    CHECK(all_nan(out, (size_t)n), "apply: out NaN after a NaN input");
    in[17] = INFINITY;
    CHECK_STATUS(rr_conv2d_apply(&e.cv, e.S[0], in, out), RR_ERR_NONFINITE, "apply: inf input");
    in[17] = urand();
    for (i = 0; i < n; i++)
        out[i] = DBL_MAX;
    CHECK_STATUS(rr_conv2d_apply(&e.cv, e.S[0], out, out), RR_ERR_RANGE,
                 "apply: inputs of DBL_MAX overflow");
    CHECK(all_nan(out, (size_t)n), "apply: out NaN after overflow");
    CHECK(memcmp(spec_copy, e.S[0], e.sl * sizeof(double)) == 0, "apply leaves the spectrum alone");

    CHECK_STATUS(rr_conv2d_apply2(&e.cv, e.S[0], NULL, NULL, e.S[1], NULL, iny, out, outy),
                 RR_ERR_NULL, "apply2: inx NULL");
    CHECK(all_nan(out, (size_t)n) && all_nan(outy, (size_t)n), "apply2: outputs NaN after inx NULL");
    CHECK_STATUS(rr_conv2d_apply2(&e.cv, e.S[0], NULL, NULL, e.S[1], in, NULL, out, outy),
                 RR_ERR_NULL, "apply2: iny NULL");
    CHECK_STATUS(rr_conv2d_apply2(&e.cv, e.S[0], NULL, NULL, e.S[1], in, iny, NULL, outy),
                 RR_ERR_NULL, "apply2: outx NULL");
    CHECK(all_nan(outy, (size_t)n), "apply2: outy NaN after outx NULL");
    CHECK_STATUS(rr_conv2d_apply2(&e.cv, e.S[0], NULL, NULL, e.S[1], in, iny, out, NULL),
                 RR_ERR_NULL, "apply2: outy NULL");
    CHECK(all_nan(out, (size_t)n), "apply2: outx NaN after outy NULL");
    iny[3] = NAN;
    CHECK_STATUS(rr_conv2d_apply2(&e.cv, e.S[0], NULL, NULL, e.S[1], in, iny, out, outy),
                 RR_ERR_NONFINITE, "apply2: NaN in iny");
    CHECK(all_nan(out, (size_t)n) && all_nan(outy, (size_t)n), "apply2: outputs NaN after NaN");
    iny[3] = 0.0;
    for (i = 0; i < n; i++)
        in[i] = -DBL_MAX;
    CHECK_STATUS(rr_conv2d_apply2(&e.cv, e.S[0], e.S[1], e.S[2], e.S[3], in, iny, out, outy),
                 RR_ERR_RANGE, "apply2: inputs of -DBL_MAX overflow");
    CHECK(all_nan(out, (size_t)n) && all_nan(outy, (size_t)n), "apply2: outputs NaN after overflow");

    free(in);
    free(iny);
    free(out);
    free(outy);
    free(spec_copy);
    engine_close(&e);
}

/* One spectrum, two engines of the same grid (one per thread, say): the
 * same results, bit for bit. */
static void test_shared_spectrum(void)
{
    engine a, b;
    double *in, *o1, *o2;
    int i, st;
    st = engine_open(&a, 13, 29);
    st |= engine_open(&b, 13, 29);
    if (!CHECK_STATUS(st, RR_OK, "shared spectrum: engines"))
        return;
    in = xcalloc((size_t)a.n, sizeof(double));
    o1 = xcalloc((size_t)a.n, sizeof(double));
    o2 = xcalloc((size_t)a.n, sizeof(double));
    for (i = 0; i < a.n; i++)
        in[i] = urand();
    st = rr_conv2d_apply(&a.cv, a.S[0], in, o1);
    st |= rr_conv2d_apply(&b.cv, a.S[0], in, o2);
    CHECK(st == RR_OK && memcmp(o1, o2, (size_t)a.n * sizeof *o1) == 0,
          "two engines, one spectrum: the same bits");
    free(in);
    free(o1);
    free(o2);
    engine_close(&a);
    engine_close(&b);
}

int main(void)
{
    /* mx, my: tori (L1 x L2) and what they exercise */
    static const int grids[][2] = {
        {1, 1},     /* 1 x 1: no stage at all */
        {1, 7},     /* 1 x 16 */
        {7, 1},     /* 16 x 1 */
        {2, 2},     /* 3 x 3: one stage */
        {3, 2},     /* 5 x 3 */
        {5, 4},     /* 9 x 8: one radix-9 stage; 8 = 4 2 */
        {7, 5},     /* 16 x 9: odd mx (the scalar path's padded copy) */
        {6, 11},    /* 12 x 24: 24 = 4 6 */
        {13, 29},   /* 25 x 60: 5 5, and 4 3 5 with the pruned radix-4 ends */
        {30, 30},   /* 60 x 60 */
        {14, 13},   /* 27 x 25: 9 3 and 5 5, partial first and last stages */
        {23, 17},   /* 48 x 36 */
        {41, 38},   /* 81 x 80: 9 9, 4 4 5 */
        {47, 3},    /* 96 x 5: 96 = 4 4 6 (a radix 8 would not save a stage) */
        {31, 16},   /* 64 x 32: 4 4 4, and 4 8 (it saves one) */
        {3, 101},   /* 5 x 216: 216 = 4 6 9 */
        {101, 2}    /* 216 x 3 */
    };
    int g;

    test_good_size();
    for (g = 0; g < (int)(sizeof grids / sizeof grids[0]); g++)
        test_grid(grids[g][0], grids[g][1]);
    test_shift(7, 5, 1, 0);
    test_shift(7, 5, -6, 4);
    test_shift(12, 9, 3, -8);
    test_errors();
    test_shared_spectrum();
    return rr_test_summary();
}
