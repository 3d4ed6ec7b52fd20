/*
 * rr_fft.c - mixed-radix Stockham FFT in batches of lines, and the 2-D
 * convolutions built on it (rr_fft.h).
 *
 * A "line" is a vector of vlen lanes (contiguous doubles, one plane for
 * the real parts, one for the imaginary parts); a pass transforms along
 * the line index, for all lanes at once.  Stage t of a length-n transform
 * (radix r, stride s = product of the earlier radices, m = n / (s r))
 * reads element p + j m (s lines each) and writes element r p + k:
 *     y[r p + k] = w_p^k sum_j x[p + j m] exp(-2 pi i j k / r),
 *     w_p = exp(-2 pi i p s / n)
 * (decimation in frequency, self-sorting: the last stage leaves the
 * output in natural order).  Each element is s consecutive lines, so one
 * butterfly call runs one loop over s vlen contiguous doubles with one
 * set of twiddles.  The inverse transform is the forward one with real
 * and imaginary planes swapped.
 */

/* The spectra and the convolutions are compiled twice on x86-64 with GCC or clang:
 * here for the baseline, and for AVX2 by rr_fft_avx2.c, which includes
 * this file; each call takes the AVX2 build where the processor has it.
 * The butterflies run on whole lines of lanes, so the wider vectors take
 * about a sixth off a product.  Floating-point contraction is off in ISO
 * C, so both builds round every operation alike and give the same doubles
 * (checked on the exact solver's 300 reference cases and by
 * csrc/tests/test_fft.c).  -DRR_PORTABLE keeps the baseline only. */

#include <math.h>
#include <stdint.h>
#include <string.h>
#include "util/rr_common.h"
#include "util/rr_fft.h"

#if !defined(RR_FFT_ISA_COPY) || RR_FFT_DISPATCH

#if defined(RR_FFT_ISA_COPY)
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC target("avx2")
#endif
#define HOT(name) name##_avx2
#elif RR_FFT_DISPATCH
#define HOT(name) name##_baseline
#else
#define HOT(name) name
#endif

/* scratch lines (of vmax doubles) for partial butterflies: r input and
 * r output lines, real and imaginary */
#define MAX_RADIX 9
#define TMP_LINES (4 * MAX_RADIX)
#define ALIGN_DOUBLES 8   /* planes start on 64-byte boundaries */
#define CAP_OFFSET 128    /* a plane component's length mod 512 doubles */

typedef ptrdiff_t idx;

#ifndef RR_FFT_ISA_COPY   /* sizes and plans: the baseline build only */
/* ---- sizes ------------------------------------------------------------------ */

int rr_fft_good_size(int n)
{
    long best = 0, p5, p35, v;
    if (n < 1 || n > RR_FFT_MAX_LEN)
        return 0;
    /* every 5^c 3^b <= 2n times the least power of 2 that reaches n */
    for (p5 = 1; p5 < 2L * n; p5 *= 5)
        for (p35 = p5; p35 < 2L * n; p35 *= 3) {
            v = p35;
            while (v < n)
                v *= 2;
            if (best == 0 || v < best)
                best = v;
        }
    return (int)best;
}

int rr_conv2d_torus_len(int n)
{
    int g, g4;
    if (n < 1 || n > RR_FFT_MAX_LEN / 2)
        return 0;
    g = rr_fft_good_size(n);
    g4 = 4 * rr_fft_good_size((n + 3) / 4);    /* 4 k is 5-smooth where k is */
    return g % 4 == 0 || 10 * (long)g > 9 * (long)g4 ? g4 : g;
}

/* ---- twiddles ----------------------------------------------------------------- */

/* cos and sin of 2 pi j / n, from an argument in [0, pi/4]: the octant
 * symmetries are exact, so e.g. j = n/4 gives exactly (0, 1). */
static void unit_root(long j, long n, double *c, double *s)
{
    long x;
    int neg_s = 0, neg_c = 0, swap = 0;
    double a, ca, sa;

    j %= n;
    if (j < 0)
        j += n;
    x = 8 * j;                   /* angle = (pi / 4) x / n */
    if (x > 4 * n) {             /* (pi, 2 pi): reflect, sin changes sign */
        x = 8 * n - x;
        neg_s = 1;
    }
    if (x > 2 * n) {             /* (pi/2, pi]: pi - angle, cos changes sign */
        x = 4 * n - x;
        neg_c = 1;
    }
    if (x > n) {                 /* (pi/4, pi/2]: pi/2 - angle, cos <-> sin */
        x = 2 * n - x;
        swap = 1;
    }
    a = (RR_PI / 4.0) * (double)x / (double)n;
    ca = cos(a);
    sa = sin(a);
    *c = swap ? sa : ca;
    *s = swap ? ca : sa;
    if (neg_c)
        *c = -*c;
    if (neg_s)
        *s = -*s;
}

/* Stage order of a length-n plan.  The radix at the pruned end is 4 (or 2)
 * when n allows: fwd, first: the forward transforms' input is zero from
 * n / 2 on, so the first stage is a half-size butterfly (or only twiddle
 * products); else last: the inverse transforms need only the first half
 * of their output, so the last stage computes half the outputs (or only
 * sums).  The other stages as few as the radices allow: 4s, or 8 for
 * factors 2^3 where that saves a stage, a lone 2 as 6 with a 3 (or 2), 9
 * for 3^2, 3, 5; each stage is one sweep over the data, the larger
 * radices also take fewer twiddle products.  Radix 8 only where it saves
 * a stage: at the same number of stages 4s were faster (64 = 4 4 4 takes
 * 8 % less than 4 8 2 at a 31 x 31 grid, 96 = 4 4 6 4 % less than 4 8 3:
 * eight input lines 4 KB apart share a cache set). */
static int inner_radices(int a, int b, int c, int use8, int *radix)
{
    int k = 0, i;
    if (use8) {
        for (i = 0; i < a / 3; i++)
            radix[k++] = 8;
        a %= 3;
    }
    for (i = 0; i < a / 2; i++)
        radix[k++] = 4;
    a %= 2;
    if (a == 1 && b > 0) {
        radix[k++] = 6;
        b--;
    } else if (a == 1) {
        radix[k++] = 2;
    }
    for (i = 0; i < b / 2; i++)
        radix[k++] = 9;
    if (b % 2)
        radix[k++] = 3;
    for (i = 0; i < c; i++)
        radix[k++] = 5;
    return k;
}

static int plan_radices(int n, int fwd, int *radix)
{
    int a = 0, b = 0, c = 0, k = 0, i, lead, t;
    while (n % 2 == 0) { n /= 2; a++; }
    while (n % 3 == 0) { n /= 3; b++; }
    while (n % 5 == 0) { n /= 5; c++; }
    if (n != 1)
        return -1;
    lead = a >= 2 ? 4 : a == 1 ? 2 : 0;
    a -= lead == 4 ? 2 : lead == 2 ? 1 : 0;
    {
        int r8[RR_FFT_MAX_STAGES];
        const int k8 = inner_radices(a, b, c, 1, r8);
        k = inner_radices(a, b, c, 0, radix);
        if (k8 < k) {
            memcpy(radix, r8, (size_t)k8 * sizeof *radix);
            k = k8;
        }
    }
    if (fwd) {
        if (lead) {
            for (i = k; i > 0; i--)
                radix[i] = radix[i - 1];
            radix[0] = lead;
            k++;
        }
    } else {
        for (i = 0; i < k / 2; i++) {
            t = radix[i];
            radix[i] = radix[k - 1 - i];
            radix[k - 1 - i] = t;
        }
        if (lead)
            radix[k++] = lead;
    }
    return k;
}

/* twiddle doubles of a plan: 2 (n - 1) (sum over stages of 2 (r-1) m) */
static size_t plan_tw_len(int n)
{
    return n > 1 ? 2 * (size_t)(n - 1) : 0;
}

/* Builds pl in tw (plan_tw_len(n) doubles). */
static void plan_build(rr_fft_plan *pl, int n, int fwd, double *tw)
{
    int t, p, k, s = 1;
    pl->n = n;
    pl->nstage = plan_radices(n, fwd, pl->radix);
    for (t = 0; t < pl->nstage; t++) {
        const int r = pl->radix[t], m = n / (s * r);
        pl->stride[t] = s;
        pl->tw[t] = tw;
        for (p = 0; p < m; p++)
            for (k = 1; k < r; k++) {
                double c, sn;
                unit_root((long)p * k * s, n, &c, &sn);
                *tw++ = c;
                *tw++ = -sn;
            }
        s *= r;
    }
}

#endif

/* ---- butterflies ----------------------------------------------------------------
 * len contiguous values; input j at x + j xs, output k at yk; w: the
 * twiddles w^1 .. w^(r-1) as (re, im) pairs, or NULL for none (p = 0). */

#define CMUL_STORE(yr_, yi_, i_, ar_, ai_, wr_, wi_) \
    do { (yr_)[i_] = (ar_) * (wr_) - (ai_) * (wi_); (yi_)[i_] = (ar_) * (wi_) + (ai_) * (wr_); } while (0)
#define PLAIN_STORE(yr_, yi_, i_, ar_, ai_, wr_, wi_) \
    do { (void)(wr_); (void)(wi_); (yr_)[i_] = (ar_); (yi_)[i_] = (ai_); } while (0)

static void bf2(idx len, const double *restrict xr, const double *restrict xi, idx xs,
                double *restrict y0r, double *restrict y0i, double *restrict y1r,
                double *restrict y1i, const double *w)
{
    idx i;
    if (!w) {
        for (i = 0; i < len; i++) {
            const double ar = xr[i], ai = xi[i], br = xr[i + xs], bi = xi[i + xs];
            y0r[i] = ar + br;
            y0i[i] = ai + bi;
            y1r[i] = ar - br;
            y1i[i] = ai - bi;
        }
    } else {
        const double w1r = w[0], w1i = w[1];
        for (i = 0; i < len; i++) {
            const double ar = xr[i], ai = xi[i], br = xr[i + xs], bi = xi[i + xs];
            const double dr = ar - br, di = ai - bi;
            y0r[i] = ar + br;
            y0i[i] = ai + bi;
            CMUL_STORE(y1r, y1i, i, dr, di, w1r, w1i);
        }
    }
}

/* exp(-2 pi i / 3) = -1/2 - i sqrt(3)/2 */
#define S3 0.86602540378443864676

static void bf3(idx len, const double *restrict xr, const double *restrict xi, idx xs,
                double *restrict y0r, double *restrict y0i, double *restrict y1r,
                double *restrict y1i, double *restrict y2r, double *restrict y2i,
                const double *w)
{
    idx i;
    const double *x1r = xr + xs, *x1i = xi + xs, *x2r = xr + 2 * xs, *x2i = xi + 2 * xs;
    if (!w) {
        for (i = 0; i < len; i++) {
            const double sr = x1r[i] + x2r[i], si = x1i[i] + x2i[i];
            const double dr = x1r[i] - x2r[i], di = x1i[i] - x2i[i];
            const double tr = xr[i] - 0.5 * sr, ti = xi[i] - 0.5 * si;
            /* -i S3 (d) = S3 di - i S3 dr */
            const double ur = S3 * di, ui = -S3 * dr;
            y0r[i] = xr[i] + sr;
            y0i[i] = xi[i] + si;
            y1r[i] = tr + ur;
            y1i[i] = ti + ui;
            y2r[i] = tr - ur;
            y2i[i] = ti - ui;
        }
    } else {
        const double w1r = w[0], w1i = w[1], w2r = w[2], w2i = w[3];
        for (i = 0; i < len; i++) {
            const double sr = x1r[i] + x2r[i], si = x1i[i] + x2i[i];
            const double dr = x1r[i] - x2r[i], di = x1i[i] - x2i[i];
            const double tr = xr[i] - 0.5 * sr, ti = xi[i] - 0.5 * si;
            const double ur = S3 * di, ui = -S3 * dr;
            const double ar = tr + ur, ai = ti + ui, br = tr - ur, bi = ti - ui;
            y0r[i] = xr[i] + sr;
            y0i[i] = xi[i] + si;
            CMUL_STORE(y1r, y1i, i, ar, ai, w1r, w1i);
            CMUL_STORE(y2r, y2i, i, br, bi, w2r, w2i);
        }
    }
}

static void bf4(idx len, const double *restrict xr, const double *restrict xi, idx xs,
                double *restrict y0r, double *restrict y0i, double *restrict y1r,
                double *restrict y1i, double *restrict y2r, double *restrict y2i,
                double *restrict y3r, double *restrict y3i, const double *w)
{
    idx i;
    const double *x1r = xr + xs, *x1i = xi + xs, *x2r = xr + 2 * xs, *x2i = xi + 2 * xs;
    const double *x3r = xr + 3 * xs, *x3i = xi + 3 * xs;
    if (!w) {
        for (i = 0; i < len; i++) {
            const double t0r = xr[i] + x2r[i], t0i = xi[i] + x2i[i];
            const double t1r = xr[i] - x2r[i], t1i = xi[i] - x2i[i];
            const double t2r = x1r[i] + x3r[i], t2i = x1i[i] + x3i[i];
            /* -i (x1 - x3) */
            const double t3r = x1i[i] - x3i[i], t3i = x3r[i] - x1r[i];
            y0r[i] = t0r + t2r;
            y0i[i] = t0i + t2i;
            y2r[i] = t0r - t2r;
            y2i[i] = t0i - t2i;
            y1r[i] = t1r + t3r;
            y1i[i] = t1i + t3i;
            y3r[i] = t1r - t3r;
            y3i[i] = t1i - t3i;
        }
    } else {
        const double w1r = w[0], w1i = w[1], w2r = w[2], w2i = w[3], w3r = w[4], w3i = w[5];
        for (i = 0; i < len; i++) {
            const double t0r = xr[i] + x2r[i], t0i = xi[i] + x2i[i];
            const double t1r = xr[i] - x2r[i], t1i = xi[i] - x2i[i];
            const double t2r = x1r[i] + x3r[i], t2i = x1i[i] + x3i[i];
            const double t3r = x1i[i] - x3i[i], t3i = x3r[i] - x1r[i];
            const double ar = t1r + t3r, ai = t1i + t3i;
            const double br = t0r - t2r, bi = t0i - t2i;
            const double cr = t1r - t3r, ci = t1i - t3i;
            y0r[i] = t0r + t2r;
            y0i[i] = t0i + t2i;
            CMUL_STORE(y1r, y1i, i, ar, ai, w1r, w1i);
            CMUL_STORE(y2r, y2i, i, br, bi, w2r, w2i);
            CMUL_STORE(y3r, y3i, i, cr, ci, w3r, w3i);
        }
    }
}

/* exp(-2 pi i k / 5) = C1 - i S1 (k = 1), C2 - i S2 (k = 2) */
#define C51 0.30901699437494742410
#define C52 (-0.80901699437494742410)
#define S51 0.95105651629515357212
#define S52 0.58778525229247312917

static void bf5(idx len, const double *restrict xr, const double *restrict xi, idx xs,
                double *restrict y0r, double *restrict y0i, double *restrict y1r,
                double *restrict y1i, double *restrict y2r, double *restrict y2i,
                double *restrict y3r, double *restrict y3i, double *restrict y4r,
                double *restrict y4i, const double *w)
{
    idx i;
    const double *x1r = xr + xs, *x1i = xi + xs, *x2r = xr + 2 * xs, *x2i = xi + 2 * xs;
    const double *x3r = xr + 3 * xs, *x3i = xi + 3 * xs, *x4r = xr + 4 * xs, *x4i = xi + 4 * xs;
    const int tw = w != NULL;
    const double w1r = tw ? w[0] : 1.0, w1i = tw ? w[1] : 0.0, w2r = tw ? w[2] : 1.0;
    const double w2i = tw ? w[3] : 0.0, w3r = tw ? w[4] : 1.0, w3i = tw ? w[5] : 0.0;
    const double w4r = tw ? w[6] : 1.0, w4i = tw ? w[7] : 0.0;
#define BF5_BODY(STORE)                                                                   \
    for (i = 0; i < len; i++) {                                                           \
        const double b1r = x1r[i] + x4r[i], b1i = x1i[i] + x4i[i];                        \
        const double b2r = x2r[i] + x3r[i], b2i = x2i[i] + x3i[i];                        \
        const double d1r = x1r[i] - x4r[i], d1i = x1i[i] - x4i[i];                        \
        const double d2r = x2r[i] - x3r[i], d2i = x2i[i] - x3i[i];                        \
        const double ar = xr[i] + C51 * b1r + C52 * b2r, ai = xi[i] + C51 * b1i + C52 * b2i; \
        const double br = xr[i] + C52 * b1r + C51 * b2r, bi = xi[i] + C52 * b1i + C51 * b2i; \
        /* -i (S1 d1 + S2 d2) and -i (S2 d1 - S1 d2) */                                 \
        const double er = S51 * d1i + S52 * d2i, ei = -(S51 * d1r + S52 * d2r);           \
        const double fr = S52 * d1i - S51 * d2i, fi = -(S52 * d1r - S51 * d2r);           \
        y0r[i] = xr[i] + b1r + b2r;                                                       \
        y0i[i] = xi[i] + b1i + b2i;                                                       \
        STORE(y1r, y1i, i, ar + er, ai + ei, w1r, w1i);                                   \
        STORE(y2r, y2i, i, br + fr, bi + fi, w2r, w2i);                                   \
        STORE(y3r, y3i, i, br - fr, bi - fi, w3r, w3i);                                   \
        STORE(y4r, y4i, i, ar - er, ai - ei, w4r, w4i);                                   \
    }
    if (!tw) {
        BF5_BODY(PLAIN_STORE)
    } else {
        BF5_BODY(CMUL_STORE)
    }
#undef BF5_BODY
}

/* Declares o0, o1, o2 = DFT3(a0, a1, a2) (and temporaries named after o0). */
#define DFT3(a0r, a0i, a1r, a1i, a2r, a2i, o0r, o0i, o1r, o1i, o2r, o2i)        \
    const double o0r##s = (a1r) + (a2r), o0i##s = (a1i) + (a2i);                   \
    const double o0r##d = (a1r) - (a2r), o0i##d = (a1i) - (a2i);                   \
    const double o0r##t = (a0r) - 0.5 * o0r##s, o0i##t = (a0i) - 0.5 * o0i##s;     \
    const double o0r = (a0r) + o0r##s, o0i = (a0i) + o0i##s;                       \
    const double o1r = o0r##t + S3 * o0i##d, o1i = o0i##t - S3 * o0r##d;           \
    const double o2r = o0r##t - S3 * o0i##d, o2i = o0i##t + S3 * o0r##d

/* Radix 6 by the prime-factor map (6 = 2 x 3, no internal twiddles):
 * A = DFT3(x0, x2, x4), B = DFT3(x3, x5, x1); y0 = A0 + B0, y3 = A0 - B0,
 * y4 = A1 + B1, y1 = A1 - B1, y2 = A2 + B2, y5 = A2 - B2. */
static void bf6(idx len, const double *restrict xr, const double *restrict xi, idx xs,
                double *restrict y0r, double *restrict y0i, double *restrict y1r,
                double *restrict y1i, double *restrict y2r, double *restrict y2i,
                double *restrict y3r, double *restrict y3i, double *restrict y4r,
                double *restrict y4i, double *restrict y5r, double *restrict y5i,
                const double *w)
{
    idx i;
    const double *x1r = xr + xs, *x1i = xi + xs, *x2r = xr + 2 * xs, *x2i = xi + 2 * xs;
    const double *x3r = xr + 3 * xs, *x3i = xi + 3 * xs, *x4r = xr + 4 * xs, *x4i = xi + 4 * xs;
    const double *x5r = xr + 5 * xs, *x5i = xi + 5 * xs;
    const int tw = w != NULL;
    const double w1r = tw ? w[0] : 1.0, w1i = tw ? w[1] : 0.0, w2r = tw ? w[2] : 1.0;
    const double w2i = tw ? w[3] : 0.0, w3r = tw ? w[4] : 1.0, w3i = tw ? w[5] : 0.0;
    const double w4r = tw ? w[6] : 1.0, w4i = tw ? w[7] : 0.0, w5r = tw ? w[8] : 1.0;
    const double w5i = tw ? w[9] : 0.0;
#define BF6_BODY(STORE)                                                             \
    for (i = 0; i < len; i++) {                                                     \
        DFT3(xr[i], xi[i], x2r[i], x2i[i], x4r[i], x4i[i], a0r, a0i, a1r, a1i, a2r, a2i); \
        DFT3(x3r[i], x3i[i], x5r[i], x5i[i], x1r[i], x1i[i], b0r, b0i, b1r, b1i, b2r, b2i); \
        y0r[i] = a0r + b0r;                                                         \
        y0i[i] = a0i + b0i;                                                         \
        STORE(y3r, y3i, i, a0r - b0r, a0i - b0i, w3r, w3i);                         \
        STORE(y4r, y4i, i, a1r + b1r, a1i + b1i, w4r, w4i);                         \
        STORE(y1r, y1i, i, a1r - b1r, a1i - b1i, w1r, w1i);                         \
        STORE(y2r, y2i, i, a2r + b2r, a2i + b2i, w2r, w2i);                         \
        STORE(y5r, y5i, i, a2r - b2r, a2i - b2i, w5r, w5i);                         \
    }
    if (!tw) {
        BF6_BODY(PLAIN_STORE)
    } else {
        BF6_BODY(CMUL_STORE)
    }
#undef BF6_BODY
}

/* exp(-2 pi i / 8) = (1 - i) / sqrt(2) */
#define SQH 0.70710678118654752440

/* Radix 8: radix 4 on the even and on the odd inputs, then radix 2 with
 * the factors exp(-2 pi i k / 8). */
static void bf8(idx len, const double *restrict xr, const double *restrict xi, idx xs,
                double *restrict y0r, double *restrict y0i, double *restrict y1r,
                double *restrict y1i, double *restrict y2r, double *restrict y2i,
                double *restrict y3r, double *restrict y3i, double *restrict y4r,
                double *restrict y4i, double *restrict y5r, double *restrict y5i,
                double *restrict y6r, double *restrict y6i, double *restrict y7r,
                double *restrict y7i, const double *w)
{
    idx i;
    const int tw = w != NULL;
    double wr[8], wi[8];
    int k;
    for (k = 1; k < 8; k++) {
        wr[k] = tw ? w[2 * (k - 1)] : 1.0;
        wi[k] = tw ? w[2 * (k - 1) + 1] : 0.0;
    }
    {
        const double w1r = wr[1], w1i = wi[1], w2r = wr[2], w2i = wi[2], w3r = wr[3];
        const double w3i = wi[3], w4r = wr[4], w4i = wi[4], w5r = wr[5], w5i = wi[5];
        const double w6r = wr[6], w6i = wi[6], w7r = wr[7], w7i = wi[7];
#define BF8_BODY(STORE)                                                                   \
        for (i = 0; i < len; i++) {                                                       \
            const double t0r = xr[i] + xr[i + 4 * xs], t0i = xi[i] + xi[i + 4 * xs];      \
            const double t1r = xr[i] - xr[i + 4 * xs], t1i = xi[i] - xi[i + 4 * xs];      \
            const double t2r = xr[i + 2 * xs] + xr[i + 6 * xs];                           \
            const double t2i = xi[i + 2 * xs] + xi[i + 6 * xs];                           \
            const double t3r = xi[i + 2 * xs] - xi[i + 6 * xs];                           \
            const double t3i = xr[i + 6 * xs] - xr[i + 2 * xs];                           \
            const double t4r = xr[i + xs] + xr[i + 5 * xs], t4i = xi[i + xs] + xi[i + 5 * xs]; \
            const double t5r = xr[i + xs] - xr[i + 5 * xs], t5i = xi[i + xs] - xi[i + 5 * xs]; \
            const double t6r = xr[i + 3 * xs] + xr[i + 7 * xs];                           \
            const double t6i = xi[i + 3 * xs] + xi[i + 7 * xs];                           \
            const double t7r = xi[i + 3 * xs] - xi[i + 7 * xs];                           \
            const double t7i = xr[i + 7 * xs] - xr[i + 3 * xs];                           \
            const double e0r = t0r + t2r, e0i = t0i + t2i, e2r = t0r - t2r, e2i = t0i - t2i; \
            const double e1r = t1r + t3r, e1i = t1i + t3i, e3r = t1r - t3r, e3i = t1i - t3i; \
            const double o0r = t4r + t6r, o0i = t4i + t6i, o2r = t4r - t6r, o2i = t4i - t6i; \
            const double o1r = t5r + t7r, o1i = t5i + t7i, o3r = t5r - t7r, o3i = t5i - t7i; \
            /* w8 o1, -i o2, w8^3 o3 */                                                   \
            const double p1r = SQH * (o1r + o1i), p1i = SQH * (o1i - o1r);                  \
            const double p2r = o2i, p2i = -o2r;                                           \
            const double p3r = SQH * (o3i - o3r), p3i = -SQH * (o3r + o3i);                 \
            y0r[i] = e0r + o0r;                                                           \
            y0i[i] = e0i + o0i;                                                           \
            STORE(y4r, y4i, i, e0r - o0r, e0i - o0i, w4r, w4i);                           \
            STORE(y1r, y1i, i, e1r + p1r, e1i + p1i, w1r, w1i);                           \
            STORE(y5r, y5i, i, e1r - p1r, e1i - p1i, w5r, w5i);                           \
            STORE(y2r, y2i, i, e2r + p2r, e2i + p2i, w2r, w2i);                           \
            STORE(y6r, y6i, i, e2r - p2r, e2i - p2i, w6r, w6i);                           \
            STORE(y3r, y3i, i, e3r + p3r, e3i + p3i, w3r, w3i);                           \
            STORE(y7r, y7i, i, e3r - p3r, e3i - p3i, w7r, w7i);                           \
        }
        if (!tw) {
            BF8_BODY(PLAIN_STORE)
        } else {
            BF8_BODY(CMUL_STORE)
        }
#undef BF8_BODY
    }
}

/* exp(-2 pi i k / 9), k = 1, 2, 4 */
#define C91 0.76604444311897803520
#define S91 0.64278760968653932632
#define C92 0.17364817766693034885
#define S92 0.98480775301220805936
#define C94 (-0.93969262078590838405)
#define S94 0.34202014332566873304

/* Radix 9 = 3 x 3: DFT3 of x(n1 + 3 n2) over n2, the factors
 * exp(-2 pi i n1 k2 / 9), DFT3 over n1: output k2 + 3 k1. */
static void bf9(idx len, const double *restrict xr, const double *restrict xi, idx xs,
                double *restrict y0r, double *restrict y0i, double *restrict y1r,
                double *restrict y1i, double *restrict y2r, double *restrict y2i,
                double *restrict y3r, double *restrict y3i, double *restrict y4r,
                double *restrict y4i, double *restrict y5r, double *restrict y5i,
                double *restrict y6r, double *restrict y6i, double *restrict y7r,
                double *restrict y7i, double *restrict y8r, double *restrict y8i,
                const double *w)
{
    idx i;
    const int tw = w != NULL;
    double wr[9], wi[9];
    int k;
    for (k = 1; k < 9; k++) {
        wr[k] = tw ? w[2 * (k - 1)] : 1.0;
        wi[k] = tw ? w[2 * (k - 1) + 1] : 0.0;
    }
    {
        const double w1r = wr[1], w1i = wi[1], w2r = wr[2], w2i = wi[2], w3r = wr[3];
        const double w3i = wi[3], w4r = wr[4], w4i = wi[4], w5r = wr[5], w5i = wi[5];
        const double w6r = wr[6], w6i = wi[6], w7r = wr[7], w7i = wi[7], w8r = wr[8];
        const double w8i = wi[8];
/* (a + i b) (C - i S) */
#define ROT9(ar_, ai_, C, S, or_, oi_) \
    const double or_ = (ar_) * (C) + (ai_) * (S), oi_ = (ai_) * (C) - (ar_) * (S)
#define BF9_BODY(STORE)                                                                   \
        for (i = 0; i < len; i++) {                                                       \
            DFT3(xr[i], xi[i], xr[i + 3 * xs], xi[i + 3 * xs], xr[i + 6 * xs],            \
                 xi[i + 6 * xs], a0r, a0i, a1r, a1i, a2r, a2i);                           \
            DFT3(xr[i + xs], xi[i + xs], xr[i + 4 * xs], xi[i + 4 * xs], xr[i + 7 * xs],  \
                 xi[i + 7 * xs], b0r, b0i, u1r, u1i, u2r, u2i);                           \
            DFT3(xr[i + 2 * xs], xi[i + 2 * xs], xr[i + 5 * xs], xi[i + 5 * xs],          \
                 xr[i + 8 * xs], xi[i + 8 * xs], c0r, c0i, v1r, v1i, v2r, v2i);           \
            ROT9(u1r, u1i, C91, S91, b1r, b1i);                                           \
            ROT9(u2r, u2i, C92, S92, b2r, b2i);                                           \
            ROT9(v1r, v1i, C92, S92, c1r, c1i);                                           \
            ROT9(v2r, v2i, C94, S94, c2r, c2i);                                           \
            {                                                                             \
                DFT3(a0r, a0i, b0r, b0i, c0r, c0i, z0r, z0i, z3r, z3i, z6r, z6i);         \
                DFT3(a1r, a1i, b1r, b1i, c1r, c1i, z1r, z1i, z4r, z4i, z7r, z7i);         \
                DFT3(a2r, a2i, b2r, b2i, c2r, c2i, z2r, z2i, z5r, z5i, z8r, z8i);         \
                y0r[i] = z0r;                                                             \
                y0i[i] = z0i;                                                             \
                STORE(y1r, y1i, i, z1r, z1i, w1r, w1i);                                   \
                STORE(y2r, y2i, i, z2r, z2i, w2r, w2i);                                   \
                STORE(y3r, y3i, i, z3r, z3i, w3r, w3i);                                   \
                STORE(y4r, y4i, i, z4r, z4i, w4r, w4i);                                   \
                STORE(y5r, y5i, i, z5r, z5i, w5r, w5i);                                   \
                STORE(y6r, y6i, i, z6r, z6i, w6r, w6i);                                   \
                STORE(y7r, y7i, i, z7r, z7i, w7r, w7i);                                   \
                STORE(y8r, y8i, i, z8r, z8i, w8r, w8i);                                   \
            }                                                                             \
        }
        if (!tw) {
            BF9_BODY(PLAIN_STORE)
        } else {
            BF9_BODY(CMUL_STORE)
        }
#undef BF9_BODY
#undef ROT9
    }
}

/* radix-r butterfly, outputs k at y + k ys */
static void bf(int r, idx len, const double *xr, const double *xi, idx xs, double *yr,
               double *yi, idx ys, const double *w)
{
    switch (r) {
    case 2:
        bf2(len, xr, xi, xs, yr, yi, yr + ys, yi + ys, w);
        break;
    case 3:
        bf3(len, xr, xi, xs, yr, yi, yr + ys, yi + ys, yr + 2 * ys, yi + 2 * ys, w);
        break;
    case 4:
        bf4(len, xr, xi, xs, yr, yi, yr + ys, yi + ys, yr + 2 * ys, yi + 2 * ys, yr + 3 * ys,
            yi + 3 * ys, w);
        break;
    case 5:
        bf5(len, xr, xi, xs, yr, yi, yr + ys, yi + ys, yr + 2 * ys, yi + 2 * ys, yr + 3 * ys,
            yi + 3 * ys, yr + 4 * ys, yi + 4 * ys, w);
        break;
    case 6:
        bf6(len, xr, xi, xs, yr, yi, yr + ys, yi + ys, yr + 2 * ys, yi + 2 * ys, yr + 3 * ys,
            yi + 3 * ys, yr + 4 * ys, yi + 4 * ys, yr + 5 * ys, yi + 5 * ys, w);
        break;
    case 8:
        bf8(len, xr, xi, xs, yr, yi, yr + ys, yi + ys, yr + 2 * ys, yi + 2 * ys, yr + 3 * ys,
            yi + 3 * ys, yr + 4 * ys, yi + 4 * ys, yr + 5 * ys, yi + 5 * ys, yr + 6 * ys,
            yi + 6 * ys, yr + 7 * ys, yi + 7 * ys, w);
        break;
    default:
        bf9(len, xr, xi, xs, yr, yi, yr + ys, yi + ys, yr + 2 * ys, yi + 2 * ys, yr + 3 * ys,
            yi + 3 * ys, yr + 4 * ys, yi + 4 * ys, yr + 5 * ys, yi + 5 * ys, yr + 6 * ys,
            yi + 6 * ys, yr + 7 * ys, yi + 7 * ys, yr + 8 * ys, yi + 8 * ys, w);
        break;
    }
}

/* y = w x (w NULL: copy) */
static void cscale(idx len, const double *restrict xr, const double *restrict xi,
                   double *restrict yr, double *restrict yi, const double *w)
{
    idx i;
    if (!w) {
        memcpy(yr, xr, (size_t)len * sizeof *yr);
        memcpy(yi, xi, (size_t)len * sizeof *yi);
    } else {
        const double wr = w[0], wi = w[1];
        for (i = 0; i < len; i++) {
            const double ar = xr[i], ai = xi[i];
            CMUL_STORE(yr, yi, i, ar, ai, wr, wi);
        }
    }
}

/* y = sum_j x + j xs, j < r: output 0 of a butterfly without twiddles */
static void bsum(int r, idx len, const double *restrict xr, const double *restrict xi, idx xs,
                 double *restrict yr, double *restrict yi)
{
    idx i;
    switch (r) {
    case 2:
        for (i = 0; i < len; i++) {
            yr[i] = xr[i] + xr[i + xs];
            yi[i] = xi[i] + xi[i + xs];
        }
        break;
    case 3:
        for (i = 0; i < len; i++) {
            yr[i] = xr[i] + (xr[i + xs] + xr[i + 2 * xs]);
            yi[i] = xi[i] + (xi[i + xs] + xi[i + 2 * xs]);
        }
        break;
    case 4:
        for (i = 0; i < len; i++) {
            yr[i] = (xr[i] + xr[i + 2 * xs]) + (xr[i + xs] + xr[i + 3 * xs]);
            yi[i] = (xi[i] + xi[i + 2 * xs]) + (xi[i + xs] + xi[i + 3 * xs]);
        }
        break;
    case 5:
        for (i = 0; i < len; i++) {
            yr[i] = xr[i] + (xr[i + xs] + xr[i + 4 * xs]) + (xr[i + 2 * xs] + xr[i + 3 * xs]);
            yi[i] = xi[i] + (xi[i + xs] + xi[i + 4 * xs]) + (xi[i + 2 * xs] + xi[i + 3 * xs]);
        }
        break;
    default: {
        int j;
        for (i = 0; i < len; i++) {
            yr[i] = xr[i];
            yi[i] = xi[i];
        }
        for (j = 1; j < r; j++)
            for (i = 0; i < len; i++) {
                yr[i] += xr[i + j * xs];
                yi[i] += xi[i + j * xs];
            }
        break;
    }
    }
}

/* Radix 4 with inputs 2 and 3 zero: y_k = w^k (x0 + (-i)^k x1). */
static void bf4_in2(idx len, const double *restrict xr, const double *restrict xi, idx xs,
                    double *restrict y0r, double *restrict y0i, double *restrict y1r,
                    double *restrict y1i, double *restrict y2r, double *restrict y2i,
                    double *restrict y3r, double *restrict y3i, const double *w)
{
    idx i;
    const double *x1r = xr + xs, *x1i = xi + xs;
    if (!w) {
        for (i = 0; i < len; i++) {
            const double ar = xr[i], ai = xi[i], br = x1r[i], bi = x1i[i];
            y0r[i] = ar + br;
            y0i[i] = ai + bi;
            y1r[i] = ar + bi;
            y1i[i] = ai - br;
            y2r[i] = ar - br;
            y2i[i] = ai - bi;
            y3r[i] = ar - bi;
            y3i[i] = ai + br;
        }
    } else {
        const double w1r = w[0], w1i = w[1], w2r = w[2], w2i = w[3], w3r = w[4], w3i = w[5];
        for (i = 0; i < len; i++) {
            const double ar = xr[i], ai = xi[i], br = x1r[i], bi = x1i[i];
            const double pr = ar + bi, pi = ai - br, qr = ar - br, qi = ai - bi;
            const double ur = ar - bi, ui = ai + br;
            y0r[i] = ar + br;
            y0i[i] = ai + bi;
            CMUL_STORE(y1r, y1i, i, pr, pi, w1r, w1i);
            CMUL_STORE(y2r, y2i, i, qr, qi, w2r, w2i);
            CMUL_STORE(y3r, y3i, i, ur, ui, w3r, w3i);
        }
    }
}

/* Radix 4 without twiddles, outputs 0 and 1 only. */
static void bf4_out2(idx len, const double *restrict xr, const double *restrict xi, idx xs,
                     double *restrict y0r, double *restrict y0i, double *restrict y1r,
                     double *restrict y1i)
{
    idx i;
    const double *x1r = xr + xs, *x1i = xi + xs, *x2r = xr + 2 * xs, *x2i = xi + 2 * xs;
    const double *x3r = xr + 3 * xs, *x3i = xi + 3 * xs;
    for (i = 0; i < len; i++) {
        const double t0r = xr[i] + x2r[i], t0i = xi[i] + x2i[i];
        const double t1r = xr[i] - x2r[i], t1i = xi[i] - x2i[i];
        const double t2r = x1r[i] + x3r[i], t2i = x1i[i] + x3i[i];
        const double t3r = x1i[i] - x3i[i], t3i = x3r[i] - x1r[i];
        y0r[i] = t0r + t2r;
        y0i[i] = t0i + t2i;
        y1r[i] = t1r + t3r;
        y1i[i] = t1i + t3i;
    }
}

/* 1 if v[0..n-1] are all finite: the test of rr_all_finite (0 x is NaN
 * exactly for NaN and inf) with eight sums, so that it vectorises. */
static int finite_n(const double *v, idx n)
{
    double a[8] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    idx i, k;
    for (i = 0; i + 8 <= n; i += 8)
        for (k = 0; k < 8; k++)
            a[k] += 0.0 * v[i + k];
    for (; i < n; i++)
        a[0] += 0.0 * v[i];
    return a[0] + a[1] + a[2] + a[3] + a[4] + a[5] + a[6] + a[7] == 0.0;
}

/* ---- one pass: a batch of 1-D transforms along the line index ------------------- */

typedef struct {
    const double *re, *im;
    idx ld;             /* doubles from one line to the next */
} src_lines;

typedef struct {
    double *re, *im;
    idx ld;
} dst_lines;

static void copy_lines(int nl, idx vlen, const double *sr, const double *si, idx lds,
                       double *dr, double *di, idx ldd)
{
    int l;
    for (l = 0; l < nl; l++) {
        memcpy(dr + l * ldd, sr + l * lds, (size_t)vlen * sizeof *dr);
        memcpy(di + l * ldd, si + l * lds, (size_t)vlen * sizeof *di);
    }
}

/* A transform of length r = n in one stage, from the n_in lines of x to the
 * n_out lines of y, through the scratch lines. */
static void stage_only(int r, idx vlen, src_lines x, int n_in, dst_lines y, int n_out,
                       double *tmp, idx tld)
{
    double *tir = tmp, *tii = tmp + MAX_RADIX * tld;
    double *tor = tmp + 2 * MAX_RADIX * tld, *toi = tmp + 3 * MAX_RADIX * tld;
    const int nz = n_in < r ? n_in : r, nk = n_out < r ? n_out : r;
    copy_lines(nz, vlen, x.re, x.im, x.ld, tir, tii, tld);
    memset(tir + nz * tld, 0, (size_t)(r - nz) * (size_t)tld * sizeof *tir);
    memset(tii + nz * tld, 0, (size_t)(r - nz) * (size_t)tld * sizeof *tii);
    bf(r, vlen, tir, tii, tld, tor, toi, tld, NULL);
    copy_lines(nk, vlen, tor, toi, tld, y.re, y.im, y.ld);
}

/* First stage (s = 1): lines p + j m of x are zero from n_in on. */
static void stage_first(const rr_fft_plan *pl, idx vlen, src_lines x, int n_in, double *yr,
                        double *yi, double *tmp, idx tld)
{
    const int r = pl->radix[0], m = pl->n / r;
    const double *tw = pl->tw[0];
    double *tir = tmp, *tii = tmp + MAX_RADIX * tld;
    int p, k;
    for (p = 0; p < m; p++) {
        const double *w = p ? tw + 2 * (r - 1) * p : NULL;
        const double *xr = x.re + p * x.ld, *xi = x.im + p * x.ld;
        double *ry = yr + (idx)r * p * vlen, *iy = yi + (idx)r * p * vlen;
        int nz = 0;
        if (p < n_in) {
            nz = (n_in - p + m - 1) / m;
            if (nz > r)
                nz = r;
        }
        if (nz == r) {
            bf(r, vlen, xr, xi, (idx)m * x.ld, ry, iy, vlen, w);
        } else if (nz == 0) {
            memset(ry, 0, (size_t)r * (size_t)vlen * sizeof *ry);
            memset(iy, 0, (size_t)r * (size_t)vlen * sizeof *iy);
        } else if (nz == 2 && r == 4) {
            bf4_in2(vlen, xr, xi, (idx)m * x.ld, ry, iy, ry + vlen, iy + vlen, ry + 2 * vlen,
                    iy + 2 * vlen, ry + 3 * vlen, iy + 3 * vlen, w);
        } else if (nz == 1) {
            /* one nonzero input: output k is w^k times it */
            cscale(vlen, xr, xi, ry, iy, NULL);
            for (k = 1; k < r; k++)
                cscale(vlen, xr, xi, ry + k * vlen, iy + k * vlen, w ? w + 2 * (k - 1) : NULL);
        } else {
            copy_lines(nz, vlen, xr, xi, (idx)m * x.ld, tir, tii, tld);
            memset(tir + nz * tld, 0, (size_t)(r - nz) * (size_t)tld * sizeof *tir);
            memset(tii + nz * tld, 0, (size_t)(r - nz) * (size_t)tld * sizeof *tii);
            bf(r, vlen, tir, tii, tld, ry, iy, vlen, w);
        }
    }
}

/* Middle stage t: compact lines in, compact lines out. */
static void stage_mid(const rr_fft_plan *pl, int t, idx vlen, const double *xr,
                      const double *xi, double *yr, double *yi)
{
    const int r = pl->radix[t], s = pl->stride[t], m = pl->n / (s * r);
    const double *tw = pl->tw[t];
    const idx blk = (idx)s * vlen, xs = (idx)m * blk;
    int p;
    for (p = 0; p < m; p++) {
        const double *w = p ? tw + 2 * (r - 1) * p : NULL;
        bf(r, blk, xr + p * blk, xi + p * blk, xs, yr + (idx)r * p * blk,
           yi + (idx)r * p * blk, blk, w);
    }
}

/* Last stage (m = 1, no twiddles): only lines q + s k < n_out of y are
 * written; for q with only k = 0 wanted, a sum. */
static void stage_last(const rr_fft_plan *pl, idx vlen, const double *xr, const double *xi,
                       dst_lines y, int n_out, double *tmp, idx tld)
{
    const int t = pl->nstage - 1, r = pl->radix[t], s = pl->stride[t];
    const int nq = n_out < s ? n_out : s;
    const idx xs = (idx)s * vlen, ys = (idx)s * y.ld;
    int qf = n_out - (r - 1) * s, q1 = n_out - s, q, k;
    double *tor = tmp + 2 * MAX_RADIX * tld, *toi = tmp + 3 * MAX_RADIX * tld;

    qf = qf < 0 ? 0 : qf > nq ? nq : qf;
    q1 = q1 < 0 ? 0 : q1 > nq ? nq : q1;
    if (y.ld == vlen) {
        if (qf > 0)
            bf(r, qf * vlen, xr, xi, xs, y.re, y.im, ys, NULL);
        if (nq > q1)
            bsum(r, (nq - q1) * vlen, xr + q1 * vlen, xi + q1 * vlen, xs, y.re + q1 * vlen,
                 y.im + q1 * vlen);
    } else {
        for (q = 0; q < qf; q++)
            bf(r, vlen, xr + q * vlen, xi + q * vlen, xs, y.re + q * y.ld, y.im + q * y.ld,
               ys, NULL);
        for (q = q1; q < nq; q++)
            bsum(r, vlen, xr + q * vlen, xi + q * vlen, xs, y.re + q * y.ld, y.im + q * y.ld);
    }
    /* radix 4, two outputs wanted */
    if (r == 4) {
        const int q2 = n_out - 2 * s < 0 ? 0 : n_out - 2 * s > nq ? nq : n_out - 2 * s;
        if (y.ld == vlen) {
            if (q1 > q2)
                bf4_out2((q1 - q2) * vlen, xr + q2 * vlen, xi + q2 * vlen, xs,
                         y.re + q2 * vlen, y.im + q2 * vlen, y.re + q2 * vlen + ys,
                         y.im + q2 * vlen + ys);
        } else {
            for (q = q2; q < q1; q++)
                bf4_out2(vlen, xr + q * vlen, xi + q * vlen, xs, y.re + q * y.ld,
                         y.im + q * y.ld, y.re + q * y.ld + ys, y.im + q * y.ld + ys);
        }
        q1 = q2;
    }
    /* some but not all outputs wanted: through the scratch lines */
    for (q = qf; q < q1; q++) {
        const int kk = (n_out - q + s - 1) / s;
        bf(r, vlen, xr + q * vlen, xi + q * vlen, xs, tor, toi, tld, NULL);
        for (k = 0; k < kk; k++) {
            memcpy(y.re + q * y.ld + k * ys, tor + k * tld, (size_t)vlen * sizeof *tor);
            memcpy(y.im + q * y.ld + k * ys, toi + k * tld, (size_t)vlen * sizeof *toi);
        }
    }
}

/*
 * A batch of vlen transforms of length pl->n along the lines: x has n_in
 * nonzero lines (the rest are not read), lines [0, n_out) of the result
 * are wanted.  The result goes to *dst if dst is not NULL, else to the
 * scratch plane whose index is returned (lines of vlen); x may be scratch
 * plane src_plane (or -1: neither).  inv: the inverse transform
 * (unnormalised), by swapping real and imaginary planes.
 */
static int fft_pass(rr_conv2d *cv, const rr_fft_plan *pl, int inv, idx vlen, src_lines x,
                    int src_plane, int n_in, const dst_lines *dst, int n_out)
{
    const idx cap = (idx)cv->cap, tld = cv->vmax;
    const int S = pl->nstage, nt = S > 0 ? S : 1;
    int cur = src_plane, t;
    const double *cr = x.re, *ci = x.im;

    if (inv) {
        cr = x.im;
        ci = x.re;
    }
    for (t = 0; t < nt; t++) {
        dst_lines o;
        int next = -1;
        if (t == nt - 1 && dst) {
            o = *dst;
            if (inv) {
                o.re = dst->im;
                o.im = dst->re;
            }
        } else {
            next = cur == 0 ? 1 : 0;
            o.re = cv->plane[next] + (inv ? cap : 0);
            o.im = cv->plane[next] + (inv ? 0 : cap);
            o.ld = vlen;
        }
        if (S == 0) {
            /* n = 1: the identity */
            copy_lines(n_in > 0 && n_out > 0 ? 1 : 0, vlen, cr, ci, x.ld, o.re, o.im, o.ld);
        } else if (S == 1) {
            src_lines xi;
            xi.re = cr;
            xi.im = ci;
            xi.ld = x.ld;
            stage_only(pl->radix[0], vlen, xi, n_in, o, n_out, cv->tmp, tld);
        } else if (t == 0) {
            src_lines xi;
            xi.re = cr;
            xi.im = ci;
            xi.ld = x.ld;
            stage_first(pl, vlen, xi, n_in, o.re, o.im, cv->tmp, tld);
        } else if (t < S - 1) {
            stage_mid(pl, t, vlen, cr, ci, o.re, o.im);
        } else {
            stage_last(pl, vlen, cr, ci, o, n_out, cv->tmp, tld);
        }
        cr = o.re;
        ci = o.im;
        cur = next;
    }
    return cur;
}

/* ---- transposes and the spectral products ----------------------------------------- */

#define TB 16   /* transpose tile */

/* d[j ldd + i] = s[i lds + j], i < rows, j < cols: tiles of TB x TB, in
 * 2 x 2 blocks inside (two loads of a row pair, two stores of a column
 * pair: the compiler makes them vector loads, unpacks and stores) */
static void transpose(int rows, int cols, const double *restrict s, idx lds, double *restrict d,
                      idx ldd)
{
    int i0, j0, i, j;
    for (i0 = 0; i0 < rows; i0 += TB) {
        const int i1 = i0 + TB < rows ? i0 + TB : rows;
        for (j0 = 0; j0 < cols; j0 += TB) {
            const int j1 = j0 + TB < cols ? j0 + TB : cols;
            for (j = j0; j + 1 < j1; j += 2) {
                for (i = i0; i + 1 < i1; i += 2) {
                    const double a = s[i * lds + j], b = s[i * lds + j + 1];
                    const double c = s[(i + 1) * lds + j], e = s[(i + 1) * lds + j + 1];
                    d[j * ldd + i] = a;
                    d[j * ldd + i + 1] = c;
                    d[(j + 1) * ldd + i] = b;
                    d[(j + 1) * ldd + i + 1] = e;
                }
                if (i < i1) {
                    d[j * ldd + i] = s[i * lds + j];
                    d[(j + 1) * ldd + i] = s[i * lds + j + 1];
                }
            }
            if (j < j1)
                for (i = i0; i < i1; i++)
                    d[j * ldd + i] = s[i * lds + j];
        }
    }
}

static double *plane_re(const rr_conv2d *cv, int k)
{
    return cv->plane[k];
}

static double *plane_im(const rr_conv2d *cv, int k)
{
    return cv->plane[k] + cv->cap;
}

/* Scratch plane `from` (rows lines of cols lanes) transposed, both parts,
 * into the other plane: its cols lines of rows lanes, for the next pass. */
static src_lines transposed(const rr_conv2d *cv, int from, int rows, int cols)
{
    src_lines x;
    transpose(rows, cols, plane_re(cv, from), cols, plane_re(cv, 1 - from), rows);
    transpose(rows, cols, plane_im(cv, from), cols, plane_im(cv, 1 - from), rows);
    x.re = plane_re(cv, 1 - from);
    x.im = plane_im(cv, 1 - from);
    x.ld = rows;
    return x;
}

/* Plane a (L2 lines of hx lanes: the y transforms of the packed columns
 * z = in(ix) + i in(ix + hx)) to plane b (lines ix < mx of nh lanes ky):
 * the y spectra of the real columns, times 2 (the spectrum has the 1/2):
 *   col ix:      Z(ky) + conj Z(-ky)
 *   col ix + hx: -i (Z(ky) - conj Z(-ky)) */
static void untangle_cols(const rr_conv2d *cv, int a, int b, int hx)
{
    const int L2 = cv->L2, nh = cv->nh, mb = cv->mx - hx;
    const double *restrict zr = plane_re(cv, a), *restrict zi = plane_im(cv, a);
    double *restrict gr = plane_re(cv, b), *restrict gi = plane_im(cv, b);
    int k0, k, ix;
    for (k0 = 0; k0 < nh; k0 += TB) {
        const int k1 = k0 + TB < nh ? k0 + TB : nh;
        for (ix = 0; ix < hx; ix++) {
            for (k = k0; k < k1; k++) {
                const int kn = k ? L2 - k : 0;
                const double ar = zr[(idx)k * hx + ix], ai = zi[(idx)k * hx + ix];
                const double br = zr[(idx)kn * hx + ix], bi = zi[(idx)kn * hx + ix];
                gr[(idx)ix * nh + k] = ar + br;
                gi[(idx)ix * nh + k] = ai - bi;
                if (ix < mb) {
                    gr[(idx)(ix + hx) * nh + k] = ai + bi;
                    gi[(idx)(ix + hx) * nh + k] = br - ar;
                }
            }
        }
    }
}

/* The reverse: plane b (lines ix < mx of nh lanes: the y spectra of the
 * output's columns) to plane a (L2 lines of hx lanes):
 *   z(ky) = G(ix, ky) + i G(ix + hx, ky), G(., -ky) = conj G(., ky). */
static void tangle_cols(const rr_conv2d *cv, int b, int a, int hx)
{
    const int L2 = cv->L2, nh = cv->nh, mb = cv->mx - hx;
    const double *restrict gr = plane_re(cv, b), *restrict gi = plane_im(cv, b);
    double *restrict zr = plane_re(cv, a), *restrict zi = plane_im(cv, a);
    int k0, k, ix;
    for (k0 = 0; k0 < L2; k0 += TB) {
        const int k1 = k0 + TB < L2 ? k0 + TB : L2;
        for (ix = 0; ix < hx; ix++) {
            const double *ar = gr + (idx)ix * nh, *ai = gi + (idx)ix * nh;
            const double *br = gr + (idx)(ix + hx) * nh, *bi = gi + (idx)(ix + hx) * nh;
            const int hasb = ix < mb;
            for (k = k0; k < k1; k++) {
                double pr, pi, qr, qi;   /* G(ix, k), G(ix + hx, k) */
                if (k < nh) {
                    pr = ar[k];
                    pi = ai[k];
                    qr = hasb ? br[k] : 0.0;
                    qi = hasb ? bi[k] : 0.0;
                } else {
                    pr = ar[L2 - k];
                    pi = -ai[L2 - k];
                    qr = hasb ? br[L2 - k] : 0.0;
                    qi = hasb ? -bi[L2 - k] : 0.0;
                }
                zr[(idx)k * hx + ix] = pr - qi;
                zi[(idx)k * hx + ix] = pi + qr;
            }
        }
    }
}

/* W = S Z over L1 lines of nh lanes, in place */
static void mul1(idx n, const double *restrict sr, const double *restrict si,
                 double *restrict zr, double *restrict zi)
{
    idx i;
    for (i = 0; i < n; i++) {
        const double ar = zr[i], ai = zi[i];
        zr[i] = sr[i] * ar - si[i] * ai;
        zi[i] = sr[i] * ai + si[i] * ar;
    }
}

/*
 * The 2x2 product on one pair of lines a, b = -a of the spectrum Z of
 * z = inx + i iny, for lanes i in [i0, i1) paired with lanes L2 - i of
 * line b (i0 >= 1, so L2 - i stays in the line):
 *   W(k)  = C(k) Z(k) + D(k) conj Z(-k),   W(-k) = C(-k) Z(-k) + D(-k) conj Z(k),
 *   C = Sxx + Syy + i (Syx - Sxy), D = Sxx - Syy + i (Syx + Sxy) at k; at -k
 * each S is conj S(k).  The spectra's 1/2 makes these the untangled
 * products.  In place: the pair (k, -k) is read, then written, and no
 * other lane of the loop touches it.
 */
static void mul2_pair(int i0, int i1, idx L2, const double *restrict xxr,
                      const double *restrict xxi, const double *restrict xyr,
                      const double *restrict xyi, const double *restrict yxr,
                      const double *restrict yxi, const double *restrict yyr,
                      const double *restrict yyi, double *restrict ar, double *restrict ai,
                      double *restrict br, double *restrict bi)
{
    int i;
    for (i = i0; i < i1; i++) {
        const idx j = L2 - i;
        const double P = xxr[i] + yyr[i], Q = xxi[i] + yyi[i];
        const double R = yxr[i] - xyr[i], T = yxi[i] - xyi[i];
        const double P2 = xxr[i] - yyr[i], Q2 = xxi[i] - yyi[i];
        const double R2 = yxr[i] + xyr[i], T2 = yxi[i] + xyi[i];
        const double Cr = P - T, Ci = Q + R, Er = P + T, Ei = R - Q;       /* C(k), C(-k) */
        const double Dr = P2 - T2, Di = Q2 + R2, Fr = P2 + T2, Fi = R2 - Q2; /* D(k), D(-k) */
        const double zr = ar[i], zi = ai[i], yr = br[j], yi = bi[j];
        ar[i] = Cr * zr - Ci * zi + (Dr * yr + Di * yi);
        ai[i] = Cr * zi + Ci * zr + (Di * yr - Dr * yi);
        br[j] = Er * yr - Ei * yi + (Fr * zr + Fi * zi);
        bi[j] = Er * yi + Ei * yr + (Fi * zr - Fr * zi);
    }
}

/* the same with Sxy = Syx = 0: C(-k) = conj C(k), D(-k) = conj D(k) */
static void mul2_pair_diag(int i0, int i1, idx L2, const double *restrict xxr,
                           const double *restrict xxi, const double *restrict yyr,
                           const double *restrict yyi, double *restrict ar,
                           double *restrict ai, double *restrict br, double *restrict bi)
{
    int i;
    for (i = i0; i < i1; i++) {
        const idx j = L2 - i;
        const double Cr = xxr[i] + yyr[i], Ci = xxi[i] + yyi[i];
        const double Dr = xxr[i] - yyr[i], Di = xxi[i] - yyi[i];
        const double zr = ar[i], zi = ai[i], yr = br[j], yi = bi[j];
        ar[i] = Cr * zr - Ci * zi + (Dr * yr + Di * yi);
        ai[i] = Cr * zi + Ci * zr + (Di * yr - Dr * yi);
        br[j] = Cr * yr + Ci * yi + (Dr * zr - Di * zi);
        bi[j] = Cr * yi - Ci * yr + (-Di * zr - Dr * zi);
    }
}

/* one point k (self-paired lane i of line a, its mirror at lane i of
 * line b): as mul2_pair, with j = i */
static void mul2_self(int i, const double *xxr, const double *xxi, const double *xyr,
                      const double *xyi, const double *yxr, const double *yxi,
                      const double *yyr, const double *yyi, double *ar, double *ai,
                      double *br, double *bi, int same)
{
    const double P = xxr[i] + yyr[i], Q = xxi[i] + yyi[i];
    const double R = yxr[i] - xyr[i], T = yxi[i] - xyi[i];
    const double P2 = xxr[i] - yyr[i], Q2 = xxi[i] - yyi[i];
    const double R2 = yxr[i] + xyr[i], T2 = yxi[i] + xyi[i];
    const double Cr = P - T, Ci = Q + R, Er = P + T, Ei = R - Q;
    const double Dr = P2 - T2, Di = Q2 + R2, Fr = P2 + T2, Fi = R2 - Q2;
    const double zr = ar[i], zi = ai[i], yr = br[i], yi = bi[i];
    ar[i] = Cr * zr - Ci * zi + (Dr * yr + Di * yi);
    ai[i] = Cr * zi + Ci * zr + (Di * yr - Dr * yi);
    if (!same) {
        br[i] = Er * yr - Ei * yi + (Fr * zr + Fi * zi);
        bi[i] = Er * yi + Ei * yr + (Fi * zr - Fr * zi);
    }
}

/* W = C Z + D conj Z(-k) over the whole torus, in place in plane p (L1
 * lines of L2 lanes); a NULL spectrum reads the zero line. */
static void mul2(const rr_conv2d *cv, int pl, const double *sxx, const double *sxy,
                 const double *syx, const double *syy)
{
    const int L1 = cv->L1, L2 = cv->L2, nh = cv->nh, ih = (L2 + 1) / 2;
    const idx sn = (idx)L1 * nh;
    const int diag = !sxy && !syx;
    double *zr = plane_re(cv, pl), *zi = plane_im(cv, pl);
    int a;
    for (a = 0; a < L1; a++) {
        const int b = a ? L1 - a : 0;
        const idx o = (idx)a * nh;
        const double *xxr = sxx ? sxx + o : cv->zero, *xxi = sxx ? sxx + sn + o : cv->zero;
        const double *xyr = sxy ? sxy + o : cv->zero, *xyi = sxy ? sxy + sn + o : cv->zero;
        const double *yxr = syx ? syx + o : cv->zero, *yxi = syx ? syx + sn + o : cv->zero;
        const double *yyr = syy ? syy + o : cv->zero, *yyi = syy ? syy + sn + o : cv->zero;
        double *ar = zr + (idx)a * L2, *ai = zi + (idx)a * L2;
        double *br = zr + (idx)b * L2, *bi = zi + (idx)b * L2;
        if (a <= b) {
            mul2_self(0, xxr, xxi, xyr, xyi, yxr, yxi, yyr, yyi, ar, ai, br, bi, a == b);
            if (L2 % 2 == 0 && L2 > 1)
                mul2_self(L2 / 2, xxr, xxi, xyr, xyi, yxr, yxi, yyr, yyi, ar, ai, br, bi,
                          a == b);
        }
        if (ih > 1) {
            if (diag)
                mul2_pair_diag(1, ih, L2, xxr, xxi, yyr, yyi, ar, ai, br, bi);
            else
                mul2_pair(1, ih, L2, xxr, xxi, xyr, xyi, yxr, yxi, yyr, yyi, ar, ai, br, bi);
        }
    }
}

/* ---- public functions ------------------------------------------------------------- */

static int ready(const rr_conv2d *cv)
{
    return cv && cv->ready == RR_CONV2D_READY;
}

/* twiddles, zero line, scratch lines, planes; cap: doubles of one plane
 * component.  0 for bad sizes. */
#ifndef RR_FFT_ISA_COPY
static size_t layout(int mx, int my, int *L1, int *L2, size_t *cap)
{
    size_t n, c, vmax;
    if (mx < 1 || my < 1 || mx > RR_CONV2D_MAX_GRID || my > RR_CONV2D_MAX_GRID)
        return 0;
    *L1 = rr_conv2d_torus_len(2 * mx - 1);
    *L2 = rr_conv2d_torus_len(2 * my - 1);
    vmax = (size_t)(*L1 > *L2 ? *L1 : *L2);
    /* planes hold L1 L2 values; rounded up so that the im part is aligned */
    c = (size_t)*L1 * (size_t)*L2;
    c = (c + ALIGN_DOUBLES - 1) / ALIGN_DOUBLES * ALIGN_DOUBLES;
    /* and to 128 past a multiple of 4 KB (512 doubles), so that the four
     * scratch arrays start 1 KB apart in the cache's sets: a 64 x 64 torus
     * put them 32 KB apart, and a product's lines of all four then
     * fought over the same sets (apply2 at 31 x 31 took 28 us, now 17) */
    c += (CAP_OFFSET + 512 - c % 512) % 512;
    *cap = c;
    n = 2 * plan_tw_len(*L1) + 2 * plan_tw_len(*L2) + vmax + TMP_LINES * vmax + 4 * c
        + 3 * ALIGN_DOUBLES;
    return n;
}

size_t rr_conv2d_workspace_len(int mx, int my)
{
    int L1, L2;
    size_t cap;
    return layout(mx, my, &L1, &L2, &cap);
}

static double *align_up(double *p)
{
    const uintptr_t a = (uintptr_t)p, m = ALIGN_DOUBLES * sizeof(double);
    return p + ((m - a % m) % m) / sizeof(double);
}

int rr_conv2d_init(rr_conv2d *cv, int mx, int my, double *work, size_t work_len)
{
    int L1 = 0, L2 = 0;
    size_t cap = 0, need;
    double *w;

    if (!cv)
        return RR_ERR_NULL;
    memset(cv, 0, sizeof *cv);
    need = layout(mx, my, &L1, &L2, &cap);
    if (need == 0)
        return RR_ERR_GRID;
    if (!work || work_len < need)
        return RR_ERR_WORKSPACE;
    cv->mx = mx;
    cv->my = my;
    cv->L1 = L1;
    cv->L2 = L2;
    cv->nh = L2 / 2 + 1;
    cv->vmax = L1 > L2 ? L1 : L2;
    cv->cap = cap;
    w = work;
    plan_build(&cv->xf, L1, 1, w);
    w += plan_tw_len(L1);
    plan_build(&cv->xb, L1, 0, w);
    w += plan_tw_len(L1);
    plan_build(&cv->yf, L2, 1, w);
    w += plan_tw_len(L2);
    plan_build(&cv->yb, L2, 0, w);
    w += plan_tw_len(L2);
    memset(w, 0, (size_t)cv->vmax * sizeof *w);
    cv->zero = w;
    w += cv->vmax;
    cv->tmp = w;
    w += (size_t)TMP_LINES * (size_t)cv->vmax;
    w = align_up(w);
    cv->plane[0] = w;
    w = align_up(w + 2 * cap);
    cv->plane[1] = w;
    cv->ready = RR_CONV2D_READY;
    return RR_OK;
}

size_t rr_conv2d_spectrum_len(const rr_conv2d *cv)
{
    if (!ready(cv))
        return 0;
    return 2 * (size_t)cv->L1 * (size_t)cv->nh;
}

#endif

static void fill_nan(double *v, size_t n)
{
    size_t i;
    if (!v)
        return;
    for (i = 0; i < n; i++)
        v[i] = NAN;
}

/* The spectrum of the real torus field in scratch plane 0 (its imaginary
 * part zero): along y (only ky < nh kept), transpose, along x, scaled. */
static int spectrum_of_plane(rr_conv2d *cv, double *spec, size_t ns)
{
    const int L1 = cv->L1, L2 = cv->L2, nh = cv->nh;
    double scale;
    src_lines x;
    int res;
    x.re = plane_re(cv, 0);
    x.im = plane_im(cv, 0);
    x.ld = L1;
    res = fft_pass(cv, &cv->yf, 0, L1, x, 0, L2, NULL, nh);
    x = transposed(cv, res, nh, L1);
    res = fft_pass(cv, &cv->xf, 0, nh, x, 1 - res, L1, NULL, L1);
    scale = 0.5 / ((double)L1 * (double)L2);
    {
        const double *sr = plane_re(cv, res), *si = plane_im(cv, res);
        const idx n = (idx)L1 * nh;
        idx i;
        for (i = 0; i < n; i++) {
            spec[i] = sr[i] * scale;
            spec[n + i] = si[i] * scale;
        }
    }
    if (!finite_n(spec, (idx)ns)) {
        fill_nan(spec, ns);
        return RR_ERR_RANGE;
    }
    return RR_OK;
}

int HOT(rr_conv2d_spectrum)(rr_conv2d *cv, const double *kern, double *spec)
{
    int L1, L2, mx, my, kx, ky;
    idx kw;
    size_t ns;
    double *ar, *ai;

    if (!ready(cv))
        return RR_ERR_NULL;
    ns = rr_conv2d_spectrum_len(cv);
    if (!kern || !spec) {
        fill_nan(spec, ns);
        return RR_ERR_NULL;
    }
    L1 = cv->L1;
    L2 = cv->L2;
    mx = cv->mx;
    my = cv->my;
    kw = 2 * mx - 1;
    if (!finite_n(kern, kw * (2 * my - 1))) {
        fill_nan(spec, ns);
        return RR_ERR_NONFINITE;
    }
    /* the kernel wrapped onto the torus: L2 lines (ky) of L1 lanes (kx) */
    ar = plane_re(cv, 0);
    ai = plane_im(cv, 0);
    memset(ar, 0, (size_t)L1 * (size_t)L2 * sizeof *ar);
    memset(ai, 0, (size_t)L1 * (size_t)L2 * sizeof *ai);
    for (ky = -(my - 1); ky <= my - 1; ky++) {
        const idx row = (idx)(ky < 0 ? ky + L2 : ky) * L1;
        const double *k = kern + (idx)(ky + my - 1) * kw + (mx - 1);
        for (kx = -(mx - 1); kx <= mx - 1; kx++)
            ar[row + (kx < 0 ? kx + L1 : kx)] = k[kx];
    }
    return spectrum_of_plane(cv, spec, ns);
}

int HOT(rr_conv2d_spectrum_torus)(rr_conv2d *cv, const double *kern, double *spec)
{
    size_t ns, nt;

    if (!ready(cv))
        return RR_ERR_NULL;
    ns = rr_conv2d_spectrum_len(cv);
    if (!kern || !spec) {
        fill_nan(spec, ns);
        return RR_ERR_NULL;
    }
    nt = (size_t)cv->L1 * (size_t)cv->L2;
    if (!finite_n(kern, (idx)nt)) {
        fill_nan(spec, ns);
        return RR_ERR_NONFINITE;
    }
    memcpy(plane_re(cv, 0), kern, nt * sizeof *kern);
    memset(plane_im(cv, 0), 0, nt * sizeof *kern);
    return spectrum_of_plane(cv, spec, ns);
}

int HOT(rr_conv2d_apply)(rr_conv2d *cv, const double *spec, const double *in, double *out)
{
    int mx, my, L1, L2, nh, hx, res;
    size_t n;
    src_lines x;
    dst_lines y;

    if (!ready(cv))
        return RR_ERR_NULL;
    mx = cv->mx;
    my = cv->my;
    n = (size_t)mx * (size_t)my;
    if (!spec || !in || !out) {
        fill_nan(out, n);
        return RR_ERR_NULL;
    }
    if (!finite_n(in, (idx)n)) {
        fill_nan(out, n);
        return RR_ERR_NONFINITE;
    }
    L1 = cv->L1;
    L2 = cv->L2;
    nh = cv->nh;
    hx = (mx + 1) / 2;

    /* z = in(ix) + i in(ix + hx), ix < hx: my lines of hx lanes.  For odd mx
     * the last imaginary lane is past the grid: a zero-padded copy. */
    if (mx % 2 == 0) {
        x.re = in;
        x.im = in + hx;
        x.ld = mx;
        res = -1;
    } else {
        double *cr = plane_re(cv, 1), *ci = plane_im(cv, 1);
        int iy;
        for (iy = 0; iy < my; iy++) {
            memcpy(cr + (idx)iy * hx, in + (idx)iy * mx, (size_t)hx * sizeof *cr);
            memcpy(ci + (idx)iy * hx, in + (idx)iy * mx + hx, (size_t)(hx - 1) * sizeof *ci);
            ci[(idx)iy * hx + hx - 1] = 0.0;
        }
        x.re = cr;
        x.im = ci;
        x.ld = hx;
        res = 1;
    }
    res = fft_pass(cv, &cv->yf, 0, hx, x, res, my, NULL, L2);
    untangle_cols(cv, res, 1 - res, hx);
    x.re = plane_re(cv, 1 - res);
    x.im = plane_im(cv, 1 - res);
    x.ld = nh;
    res = fft_pass(cv, &cv->xf, 0, nh, x, 1 - res, mx, NULL, L1);
    mul1((idx)L1 * nh, spec, spec + (idx)L1 * nh, plane_re(cv, res), plane_im(cv, res));
    x.re = plane_re(cv, res);
    x.im = plane_im(cv, res);
    res = fft_pass(cv, &cv->xb, 1, nh, x, res, L1, NULL, mx);
    tangle_cols(cv, res, 1 - res, hx);
    x.re = plane_re(cv, 1 - res);
    x.im = plane_im(cv, 1 - res);
    x.ld = hx;
    if (mx % 2 == 0) {
        y.re = out;
        y.im = out + hx;
        y.ld = mx;
        fft_pass(cv, &cv->yb, 1, hx, x, 1 - res, L2, &y, my);
    } else {
        int iy;
        const double *cr, *ci;
        res = fft_pass(cv, &cv->yb, 1, hx, x, 1 - res, L2, NULL, my);
        cr = plane_re(cv, res);
        ci = plane_im(cv, res);
        for (iy = 0; iy < my; iy++) {
            memcpy(out + (idx)iy * mx, cr + (idx)iy * hx, (size_t)hx * sizeof *out);
            memcpy(out + (idx)iy * mx + hx, ci + (idx)iy * hx, (size_t)(hx - 1) * sizeof *out);
        }
    }
    if (!finite_n(out, (idx)n)) {
        fill_nan(out, n);
        return RR_ERR_RANGE;
    }
    return RR_OK;
}

int HOT(rr_conv2d_apply2)(rr_conv2d *cv, const double *sxx, const double *sxy,
                     const double *syx, const double *syy, const double *inx,
                     const double *iny, double *outx, double *outy)
{
    int mx, my, L1, L2, res;
    size_t n;
    src_lines x;
    dst_lines y;

    if (!ready(cv))
        return RR_ERR_NULL;
    mx = cv->mx;
    my = cv->my;
    n = (size_t)mx * (size_t)my;
    if (!inx || !iny || !outx || !outy) {
        fill_nan(outx, n);
        fill_nan(outy, n);
        return RR_ERR_NULL;
    }
    if (!finite_n(inx, (idx)n) || !finite_n(iny, (idx)n)) {
        fill_nan(outx, n);
        fill_nan(outy, n);
        return RR_ERR_NONFINITE;
    }
    L1 = cv->L1;
    L2 = cv->L2;
    /* along y: my lines of mx lanes, read in place */
    x.re = inx;
    x.im = iny;
    x.ld = mx;
    res = fft_pass(cv, &cv->yf, 0, mx, x, -1, my, NULL, L2);
    x = transposed(cv, res, L2, mx);
    res = fft_pass(cv, &cv->xf, 0, L2, x, 1 - res, mx, NULL, L1);
    mul2(cv, res, sxx, sxy, syx, syy);
    x.re = plane_re(cv, res);
    x.im = plane_im(cv, res);
    res = fft_pass(cv, &cv->xb, 1, L2, x, res, L1, NULL, mx);
    x = transposed(cv, res, mx, L2);
    y.re = outx;
    y.im = outy;
    y.ld = mx;
    fft_pass(cv, &cv->yb, 1, mx, x, 1 - res, L2, &y, my);
    if (!finite_n(outx, (idx)n) || !finite_n(outy, (idx)n)) {
        fill_nan(outx, n);
        fill_nan(outy, n);
        return RR_ERR_RANGE;
    }
    return RR_OK;
}

#if defined(RR_FFT_ISA_COPY)
#if defined(__clang__)
#pragma clang attribute pop
#endif
#elif RR_FFT_DISPATCH
/* the dispatch: the AVX2 build where the processor runs it */
int rr_conv2d_spectrum(rr_conv2d *cv, const double *kern, double *spec)
{
    return __builtin_cpu_supports("avx2") ? rr_conv2d_spectrum_avx2(cv, kern, spec)
                                          : rr_conv2d_spectrum_baseline(cv, kern, spec);
}

int rr_conv2d_spectrum_torus(rr_conv2d *cv, const double *kern, double *spec)
{
    return __builtin_cpu_supports("avx2") ? rr_conv2d_spectrum_torus_avx2(cv, kern, spec)
                                          : rr_conv2d_spectrum_torus_baseline(cv, kern, spec);
}

int rr_conv2d_apply(rr_conv2d *cv, const double *spec, const double *in, double *out)
{
    return __builtin_cpu_supports("avx2") ? rr_conv2d_apply_avx2(cv, spec, in, out)
                                          : rr_conv2d_apply_baseline(cv, spec, in, out);
}

int rr_conv2d_apply2(rr_conv2d *cv, const double *sxx, const double *sxy,
                     const double *syx, const double *syy, const double *inx,
                     const double *iny, double *outx, double *outy)
{
    return __builtin_cpu_supports("avx2")
               ? rr_conv2d_apply2_avx2(cv, sxx, sxy, syx, syy, inx, iny, outx, outy)
               : rr_conv2d_apply2_baseline(cv, sxx, sxy, syx, syy, inx, iny, outx, outy);
}
#endif

#endif /* !RR_FFT_ISA_COPY || RR_FFT_DISPATCH */
