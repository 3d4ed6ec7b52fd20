/*
 * rr_fft.c - our own mixed-radix FFT for the 2-D convolutions of the exact
 * solver (rr_fft.h), its first half: the transforms' sizes, their twiddles
 * and plans, and the convolution engine's workspace and set-up
 * (rr_conv2d_workspace_len, rr_conv2d_init, rr_conv2d_spectrum_len).  The
 * transforms themselves and the spectral products, compiled twice
 * (baseline and AVX2), are rr_fft_conv.c, with the butterflies in
 * rr_fft_butterflies.h.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "util/rr_common.h"
#include "util/rr_fft.h"

#define ALIGN_DOUBLES 8   /* planes start on 64-byte boundaries */
#define CAP_OFFSET 128    /* a plane component's length mod 512 doubles */

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

/* ---- the engine's workspace and set-up -------------------------------------------- */

static int ready(const rr_conv2d *cv)
{
    return cv && cv->ready == RR_CONV2D_READY;
}

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
    n = 2 * plan_tw_len(*L1) + 2 * plan_tw_len(*L2) + vmax + RR_CONV2D_TMP_LINES * vmax + 4 * c
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
    w += (size_t)RR_CONV2D_TMP_LINES * (size_t)cv->vmax;
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
