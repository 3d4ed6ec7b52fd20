/* rr_fft.c - mixed-radix Stockham FFT on rows of vectors, and the 2-D
 * convolutions built on it (rr_fft.h). */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "util/rr_fft.h"

/* A plan: PLAN_HDR doubles (the number of passes, then each pass's radix),
 * then the twiddles of every pass, cos and sin interleaved. */
#define PLAN_HDR 16
#define MAX_GRID ((RR_FFT_MAX_LEN + 1) / 2)

int rr_fft_good_size(int n)
{
    int best = 0, p2, p3;
    if (n < 1 || n > RR_FFT_MAX_LEN)
        return 0;
    for (p2 = 1; p2 <= RR_FFT_MAX_LEN; p2 *= 2)
        for (p3 = p2; p3 <= RR_FFT_MAX_LEN; p3 *= 3) {
            int v = p3;
            while (v < n)
                v *= 5;
            if (v <= RR_FFT_MAX_LEN && (best == 0 || v < best))
                best = v;
        }
    return best;
}

static size_t plan_len(int L)
{
    return PLAN_HDR + 4 * (size_t)L;
}

/* Radices 4 first (fewest passes), then 2, 3, 5; the twiddles
 * w_n^(j p) = exp(-2 pi i j p / n) of each pass, n the pass's length. */
static void plan_init(double *tw, int L)
{
    int radix[PLAN_HDR - 1], np = 0, n = L, s = 1, k;
    double *t = tw + PLAN_HDR;
    while (n % 4 == 0) { radix[np++] = 4; n /= 4; }
    while (n % 2 == 0) { radix[np++] = 2; n /= 2; }
    while (n % 3 == 0) { radix[np++] = 3; n /= 3; }
    while (n % 5 == 0) { radix[np++] = 5; n /= 5; }
    tw[0] = np;
    for (k = 0; k < np; k++) {
        const int r = radix[k], len = L / s, m = len / r;
        int p, j;
        tw[1 + k] = r;
        for (p = 0; p < m; p++)
            for (j = 1; j < r; j++) {
                /* the angle reduced exactly in integers first */
                const double th = 2.0 * RR_PI * (double)(((long)j * p) % len) / len;
                *t++ = cos(th);
                *t++ = sin(th);
            }
        s *= r;
    }
}

/* One Stockham pass of radix r over `len` points (m = len / r butterflies
 * of stride s points), each point a vector of V complex values: for p < m,
 * the inputs at points q + s (p + k m), k < r, go to points q + s (r p + j),
 * times the twiddle w^(j p); q and the vector index together run over one
 * contiguous block of s V values.  dir -1 forward, +1 inverse. */
static void pass(int r, int m, int s, int V, const double *tw, double dir, const double *xr,
                 const double *xi, double *yr, double *yi)
{
    const size_t blk = (size_t)s * V;
    int p;
    size_t t;
    for (p = 0; p < m; p++) {
        const double *w = tw + (size_t)2 * (r - 1) * p;
        const size_t in0 = (size_t)p * blk, stepk = (size_t)m * blk, out0 = (size_t)r * p * blk;
        if (r == 2) {
            const double c1 = w[0], s1 = dir * w[1];
            const double *ar = xr + in0, *ai = xi + in0, *br = ar + stepk, *bi = ai + stepk;
            double *y0r = yr + out0, *y0i = yi + out0, *y1r = y0r + blk, *y1i = y0i + blk;
            for (t = 0; t < blk; t++) {
                const double dr = ar[t] - br[t], di = ai[t] - bi[t];
                y0r[t] = ar[t] + br[t];
                y0i[t] = ai[t] + bi[t];
                y1r[t] = dr * c1 - di * s1;
                y1i[t] = dr * s1 + di * c1;
            }
        } else if (r == 4) {
            const double c1 = w[0], s1 = dir * w[1], c2 = w[2], s2 = dir * w[3], c3 = w[4],
                         s3 = dir * w[5];
            const double *a0r = xr + in0, *a0i = xi + in0;
            const double *a1r = a0r + stepk, *a1i = a0i + stepk;
            const double *a2r = a1r + stepk, *a2i = a1i + stepk;
            const double *a3r = a2r + stepk, *a3i = a2i + stepk;
            double *y0r = yr + out0, *y0i = yi + out0;
            double *y1r = y0r + blk, *y1i = y0i + blk, *y2r = y1r + blk, *y2i = y1i + blk;
            double *y3r = y2r + blk, *y3i = y2i + blk;
            for (t = 0; t < blk; t++) {
                const double b0r = a0r[t] + a2r[t], b0i = a0i[t] + a2i[t];
                const double b1r = a0r[t] - a2r[t], b1i = a0i[t] - a2i[t];
                const double b2r = a1r[t] + a3r[t], b2i = a1i[t] + a3i[t];
                /* (a1 - a3) times w_4 = dir i */
                const double b3r = -dir * (a1i[t] - a3i[t]), b3i = dir * (a1r[t] - a3r[t]);
                const double z1r = b1r + b3r, z1i = b1i + b3i;
                const double z2r = b0r - b2r, z2i = b0i - b2i;
                const double z3r = b1r - b3r, z3i = b1i - b3i;
                y0r[t] = b0r + b2r;
                y0i[t] = b0i + b2i;
                y1r[t] = z1r * c1 - z1i * s1;
                y1i[t] = z1r * s1 + z1i * c1;
                y2r[t] = z2r * c2 - z2i * s2;
                y2i[t] = z2r * s2 + z2i * c2;
                y3r[t] = z3r * c3 - z3i * s3;
                y3i[t] = z3r * s3 + z3i * c3;
            }
        } else if (r == 3) {
            const double c1 = w[0], s1 = dir * w[1], c2 = w[2], s2 = dir * w[3];
            const double h = dir * 0.86602540378443864676;   /* sin(2 pi / 3) */
            const double *a0r = xr + in0, *a0i = xi + in0;
            const double *a1r = a0r + stepk, *a1i = a0i + stepk;
            const double *a2r = a1r + stepk, *a2i = a1i + stepk;
            double *y0r = yr + out0, *y0i = yi + out0;
            double *y1r = y0r + blk, *y1i = y0i + blk, *y2r = y1r + blk, *y2i = y1i + blk;
            for (t = 0; t < blk; t++) {
                const double tr = a1r[t] + a2r[t], ti = a1i[t] + a2i[t];
                const double dr = a1r[t] - a2r[t], di = a1i[t] - a2i[t];
                const double mr = a0r[t] - 0.5 * tr, mi = a0i[t] - 0.5 * ti;
                const double z1r = mr - h * di, z1i = mi + h * dr;
                const double z2r = mr + h * di, z2i = mi - h * dr;
                y0r[t] = a0r[t] + tr;
                y0i[t] = a0i[t] + ti;
                y1r[t] = z1r * c1 - z1i * s1;
                y1i[t] = z1r * s1 + z1i * c1;
                y2r[t] = z2r * c2 - z2i * s2;
                y2i[t] = z2r * s2 + z2i * c2;
            }
        } else {
            /* radix 5: cos and sin of 2 pi/5 and 4 pi/5 */
            const double k1 = 0.30901699437494742410, k2 = -0.80901699437494742410;
            const double q1 = dir * 0.95105651629515357212, q2 = dir * 0.58778525229247312917;
            const double c1 = w[0], s1 = dir * w[1], c2 = w[2], s2 = dir * w[3];
            const double c3 = w[4], s3 = dir * w[5], c4 = w[6], s4 = dir * w[7];
            const double *a0r = xr + in0, *a0i = xi + in0;
            const double *a1r = a0r + stepk, *a1i = a0i + stepk;
            const double *a2r = a1r + stepk, *a2i = a1i + stepk;
            const double *a3r = a2r + stepk, *a3i = a2i + stepk;
            const double *a4r = a3r + stepk, *a4i = a3i + stepk;
            double *y0r = yr + out0, *y0i = yi + out0;
            double *y1r = y0r + blk, *y1i = y0i + blk, *y2r = y1r + blk, *y2i = y1i + blk;
            double *y3r = y2r + blk, *y3i = y2i + blk, *y4r = y3r + blk, *y4i = y3i + blk;
            for (t = 0; t < blk; t++) {
                const double t1r = a1r[t] + a4r[t], t1i = a1i[t] + a4i[t];
                const double t2r = a2r[t] + a3r[t], t2i = a2i[t] + a3i[t];
                const double d1r = a1r[t] - a4r[t], d1i = a1i[t] - a4i[t];
                const double d2r = a2r[t] - a3r[t], d2i = a2i[t] - a3i[t];
                const double b1r = a0r[t] + k1 * t1r + k2 * t2r, b1i = a0i[t] + k1 * t1i + k2 * t2i;
                const double b2r = a0r[t] + k2 * t1r + k1 * t2r, b2i = a0i[t] + k2 * t1i + k1 * t2i;
                /* i (q1 d1 + q2 d2) and i (q2 d1 - q1 d2) */
                const double e1r = -(q1 * d1i + q2 * d2i), e1i = q1 * d1r + q2 * d2r;
                const double e2r = -(q2 * d1i - q1 * d2i), e2i = q2 * d1r - q1 * d2r;
                const double z1r = b1r + e1r, z1i = b1i + e1i, z4r = b1r - e1r, z4i = b1i - e1i;
                const double z2r = b2r + e2r, z2i = b2i + e2i, z3r = b2r - e2r, z3i = b2i - e2i;
                y0r[t] = a0r[t] + t1r + t2r;
                y0i[t] = a0i[t] + t1i + t2i;
                y1r[t] = z1r * c1 - z1i * s1;
                y1i[t] = z1r * s1 + z1i * c1;
                y2r[t] = z2r * c2 - z2i * s2;
                y2i[t] = z2r * s2 + z2i * c2;
                y3r[t] = z3r * c3 - z3i * s3;
                y3i[t] = z3r * s3 + z3i * c3;
                y4r[t] = z4r * c4 - z4i * s4;
                y4i[t] = z4r * s4 + z4i * c4;
            }
        }
    }
}

/* The transform of L points, each a vector of V complex values (point p's
 * values at p V .. p V + V - 1 of ar, ai); br, bi scratch of the same size.
 * The result is left in ar, ai. */
static void fft_points(const double *tw, int L, int V, double dir, double *ar, double *ai,
                       double *br, double *bi)
{
    const int np = (int)tw[0];
    const double *t = tw + PLAN_HDR;
    double *xr = ar, *xi = ai, *yr = br, *yi = bi, *sw;
    int k, s = 1, len = L;
    for (k = 0; k < np; k++) {
        const int r = (int)tw[1 + k], m = len / r;
        pass(r, m, s, V, t, dir, xr, xi, yr, yi);
        t += (size_t)2 * (r - 1) * m;
        s *= r;
        len = m;
        sw = xr; xr = yr; yr = sw;
        sw = xi; xi = yi; yi = sw;
    }
    if (xr != ar) {
        memcpy(ar, xr, (size_t)L * V * sizeof *ar);
        memcpy(ai, xi, (size_t)L * V * sizeof *ai);
    }
}

/* dst[i * rows + j] = src[j * cols + i] for j < rows, i < cols (blocked) */
static void transpose(const double *src, int rows, int cols, double *dst)
{
    enum { B = 16 };
    int i0, j0, i, j;
    for (j0 = 0; j0 < rows; j0 += B)
        for (i0 = 0; i0 < cols; i0 += B) {
            const int jn = j0 + B < rows ? j0 + B : rows, in = i0 + B < cols ? i0 + B : cols;
            for (i = i0; i < in; i++)
                for (j = j0; j < jn; j++)
                    dst[(size_t)i * rows + j] = src[(size_t)j * cols + i];
        }
}

static int sizes_ok(int mx, int my)
{
    return mx >= 1 && my >= 1 && mx <= MAX_GRID && my <= MAX_GRID;
}

static void torus(int mx, int my, int *L1, int *L2)
{
    *L1 = rr_fft_good_size(2 * mx - 1);
    *L2 = rr_fft_good_size(2 * my - 1);
}

size_t rr_conv2d_spectrum_len(int mx, int my)
{
    int L1, L2;
    if (!sizes_ok(mx, my))
        return 0;
    torus(mx, my, &L1, &L2);
    return 2 * (size_t)L1 * L2;
}

size_t rr_conv2d_workspace_len(int mx, int my)
{
    int L1, L2;
    if (!sizes_ok(mx, my))
        return 0;
    torus(mx, my, &L1, &L2);
    return plan_len(L1) + plan_len(L2) + 4 * (size_t)L1 * L2;
}

int rr_conv2d_init(rr_conv2d *cv, int mx, int my, double *work, size_t work_len)
{
    size_t n;
    if (!cv || !work)
        return RR_ERR_NULL;
    memset(cv, 0, sizeof *cv);
    if (!sizes_ok(mx, my))
        return RR_ERR_GRID;
    if (work_len < rr_conv2d_workspace_len(mx, my))
        return RR_ERR_WORKSPACE;
    cv->mx = mx;
    cv->my = my;
    torus(mx, my, &cv->L1, &cv->L2);
    n = (size_t)cv->L1 * cv->L2;
    cv->tw1 = work;
    cv->tw2 = cv->tw1 + plan_len(cv->L1);
    cv->re = cv->tw2 + plan_len(cv->L2);
    cv->im = cv->re + n;
    cv->re2 = cv->im + n;
    cv->im2 = cv->re2 + n;
    plan_init(cv->tw1, cv->L1);
    plan_init(cv->tw2, cv->L2);
    return RR_OK;
}

/* Forward: the field in re, im as L2 rows of V values (rows past the data
 * zero) -> its spectrum in re2, im2 as L1 rows (kx) of L2 values (ky);
 * columns past V are zero on the torus and never transformed. */
static void forward(rr_conv2d *cv, int V)
{
    const int L1 = cv->L1, L2 = cv->L2;
    fft_points(cv->tw2, L2, V, -1.0, cv->re, cv->im, cv->re2, cv->im2);
    transpose(cv->re, L2, V, cv->re2);
    transpose(cv->im, L2, V, cv->im2);
    memset(cv->re2 + (size_t)V * L2, 0, (size_t)(L1 - V) * L2 * sizeof(double));
    memset(cv->im2 + (size_t)V * L2, 0, (size_t)(L1 - V) * L2 * sizeof(double));
    fft_points(cv->tw1, L1, L2, -1.0, cv->re2, cv->im2, cv->re, cv->im);
}

/* Inverse: a spectrum in re2, im2 (L1 rows of L2) -> the first mx columns
 * of the field in re, im as L2 rows of mx values. */
static void inverse(rr_conv2d *cv)
{
    const int L1 = cv->L1, L2 = cv->L2, mx = cv->mx;
    fft_points(cv->tw1, L1, L2, 1.0, cv->re2, cv->im2, cv->re, cv->im);
    transpose(cv->re2, mx, L2, cv->re);
    transpose(cv->im2, mx, L2, cv->im);
    fft_points(cv->tw2, L2, mx, 1.0, cv->re, cv->im, cv->re2, cv->im2);
}

int rr_conv2d_spectrum(rr_conv2d *cv, const double *kern, double *spec)
{
    int L1, L2, mx, my, kx, ky;
    size_t n, k;
    double sc;
    if (!cv || !kern || !spec || !cv->re)
        return RR_ERR_NULL;
    L1 = cv->L1;
    L2 = cv->L2;
    mx = cv->mx;
    my = cv->my;
    n = (size_t)L1 * L2;
    /* the offsets wrapped onto the torus, L2 rows of L1 */
    memset(cv->re, 0, n * sizeof(double));
    memset(cv->im, 0, n * sizeof(double));
    for (ky = -(my - 1); ky < my; ky++)
        for (kx = -(mx - 1); kx < mx; kx++)
            cv->re[(size_t)((ky + L2) % L2) * L1 + (kx + L1) % L1] =
                kern[(size_t)(ky + my - 1) * (2 * mx - 1) + (kx + mx - 1)];
    forward(cv, L1);
    sc = 1.0 / (double)n;
    for (k = 0; k < n; k++) {
        spec[k] = cv->re2[k] * sc;
        spec[n + k] = cv->im2[k] * sc;
    }
    return RR_OK;
}

int rr_conv2d_apply(rr_conv2d *cv, const double *spec, const double *in, double *out)
{
    int mx, my, L2, j, half;
    size_t n, k, nd;
    const double *sr, *si;
    if (!cv || !spec || !in || !out || !cv->re)
        return RR_ERR_NULL;
    mx = cv->mx;
    my = cv->my;
    L2 = cv->L2;
    n = (size_t)cv->L1 * L2;
    nd = (size_t)mx * my;
    half = (my + 1) / 2;
    /* rows below half as the real part, the rest as the imaginary part:
     * the real kernel keeps them apart */
    memset(cv->re, 0, (size_t)L2 * mx * sizeof(double));
    memset(cv->im, 0, (size_t)L2 * mx * sizeof(double));
    memcpy(cv->re, in, (size_t)half * mx * sizeof(double));
    memcpy(cv->im + (size_t)half * mx, in + (size_t)half * mx,
           (size_t)(my - half) * mx * sizeof(double));
    forward(cv, mx);
    sr = spec;
    si = spec + n;
    for (k = 0; k < n; k++) {
        const double zr = cv->re2[k], zi = cv->im2[k];
        cv->re2[k] = zr * sr[k] - zi * si[k];
        cv->im2[k] = zr * si[k] + zi * sr[k];
    }
    inverse(cv);
    for (j = 0; j < my; j++) {
        const double *a = cv->re + (size_t)j * mx, *b = cv->im + (size_t)j * mx;
        double *o = out + (size_t)j * mx;
        int i;
        for (i = 0; i < mx; i++)
            o[i] = a[i] + b[i];
    }
    (void)nd;
    return RR_OK;
}

int rr_conv2d_apply2(rr_conv2d *cv, const double *sxx, const double *sxy, const double *syx,
                     const double *syy, const double *inx, const double *iny, double *outx,
                     double *outy)
{
    int mx, my, L1, L2, a, b;
    size_t n, nd;
    if (!cv || !inx || !iny || !outx || !outy || !cv->re)
        return RR_ERR_NULL;
    mx = cv->mx;
    my = cv->my;
    L1 = cv->L1;
    L2 = cv->L2;
    n = (size_t)L1 * L2;
    nd = (size_t)mx * my;
    memcpy(cv->re, inx, nd * sizeof(double));
    memcpy(cv->im, iny, nd * sizeof(double));
    memset(cv->re + nd, 0, (size_t)(L2 - my) * mx * sizeof(double));
    memset(cv->im + nd, 0, (size_t)(L2 - my) * mx * sizeof(double));
    forward(cv, mx);
    /* Z = X + iY with X, Y the spectra of the real fields: X(k) = (Z(k) +
     * conj Z(-k))/2, Y(k) = (Z(k) - conj Z(-k))/(2i); W = Ux + i Uy into
     * re, im, then back to re2, im2 for the inverse */
    for (a = 0; a < L1; a++) {
        const int am = a ? L1 - a : 0;
        for (b = 0; b < L2; b++) {
            const int bm = b ? L2 - b : 0;
            const size_t k = (size_t)a * L2 + b, km = (size_t)am * L2 + bm;
            const double zr = cv->re2[k], zi = cv->im2[k], wr = cv->re2[km], wi = -cv->im2[km];
            const double xr = 0.5 * (zr + wr), xi = 0.5 * (zi + wi);
            const double yr = 0.5 * (zi - wi), yi = -0.5 * (zr - wr);
            double uxr = 0.0, uxi = 0.0, uyr = 0.0, uyi = 0.0;
            if (sxx) {
                uxr += sxx[k] * xr - sxx[n + k] * xi;
                uxi += sxx[k] * xi + sxx[n + k] * xr;
            }
            if (sxy) {
                uxr += sxy[k] * yr - sxy[n + k] * yi;
                uxi += sxy[k] * yi + sxy[n + k] * yr;
            }
            if (syx) {
                uyr += syx[k] * xr - syx[n + k] * xi;
                uyi += syx[k] * xi + syx[n + k] * xr;
            }
            if (syy) {
                uyr += syy[k] * yr - syy[n + k] * yi;
                uyi += syy[k] * yi + syy[n + k] * yr;
            }
            cv->re[k] = uxr - uyi;
            cv->im[k] = uxi + uyr;
        }
    }
    memcpy(cv->re2, cv->re, n * sizeof(double));
    memcpy(cv->im2, cv->im, n * sizeof(double));
    inverse(cv);
    memcpy(outx, cv->re, nd * sizeof(double));
    memcpy(outy, cv->im, nd * sizeof(double));
    return RR_OK;
}
