/*
 * rr_fft_butterflies.h - the FFT's butterflies (rr_fft_conv.c's stages):
 * radices 2, 3, 4, 5, 6, 8 and 9 over whole lines of lanes, the radix
 * dispatch, the scaled copy and the partial sums of the pruned stages, and
 * the pruned radix-4 first and last stages.  Not a header of its own:
 * rr_fft_conv.c includes it once per build of that file (the baseline and
 * the AVX2 one, rr_fft_avx2.c), after its typedef idx, so that every
 * butterfly is a static function of the build that calls it.
 */

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
