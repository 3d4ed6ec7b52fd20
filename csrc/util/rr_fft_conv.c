/*
 * rr_fft_conv.c - mixed-radix Stockham FFT in batches of lines, and the 2-D
 * convolutions built on it (rr_fft.h), the second half: the passes, the
 * transposes, the spectral products and the public products; the sizes,
 * plans and set-up are rr_fft.c, the butterflies rr_fft_butterflies.h.
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
 * r output lines, real and imaginary (rr_fft_init's RR_CONV2D_TMP_LINES) */
#define MAX_RADIX 9
RR_STATIC_ASSERT(RR_CONV2D_TMP_LINES == 4 * MAX_RADIX, scratch_lines_for_the_largest_radix);

typedef ptrdiff_t idx;

/* ---- butterflies: rr_fft_butterflies.h (bf2 .. bf9, bf, cscale, bsum, bf4_in2,
 * bf4_out2), included here once per build of this file */
#include "util/rr_fft_butterflies.h"
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

/* ---- the public products ----------------------------------------------------------- */

static int ready(const rr_conv2d *cv)
{
    return cv && cv->ready == RR_CONV2D_READY;
}

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
