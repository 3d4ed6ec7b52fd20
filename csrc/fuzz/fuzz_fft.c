/*
 * fuzz_fft.c - the FFT convolutions: rr_conv2d_workspace_len,
 * rr_conv2d_init, rr_conv2d_spectrum, rr_conv2d_apply and rr_conv2d_apply2
 * on grids, kernels and fields from the input, against the direct sum.
 *
 * Input: mx, my (1 .. 12, one input in eight 1 .. 40; or an edge: 0, -1,
 * INT_MIN, INT_MAX, 13), the workspace (exact, one double short, NULL:
 * one in eight each for the last two), a byte allowing edge values, the
 * four kernels (which are NULL, Kxy and Kyx one array or not), their
 * values in [-1, 1] times a common scale (1e-100 .. 1e100), the two
 * fields likewise; then the calls' own NULL arguments (one in sixteen
 * each) and the aliasing of outputs and inputs (none, in place, crossed).
 * One input in sixteen instead calls the products on an rr_conv2d that
 * was never initialised (zeroed).
 *
 * Oracles: every caller buffer between canaries (nothing written beyond
 * the workspace's work_len, a spectrum's spectrum_len, the grid's mx my
 * outputs); the inputs and spectra left alone (unless aliased); the
 * statuses the header gives (RR_ERR_GRID, RR_ERR_WORKSPACE, RR_ERR_NULL,
 * RR_ERR_NONFINITE exactly when a kernel or field value is NaN or
 * infinite; RR_OK or RR_ERR_RANGE otherwise), NaN outputs on error,
 * finite ones on success; and for values of moderate magnitude (0 or
 * 1e-100 .. 1e100, so that no product under- or overflows) the results
 * within 1e-13 |K|_2 |in|_2 of the direct sum; for apply2 |K|_2 is the
 * sum over the kernels given and |in|_2 that of (inx, iny) together.
 * (The FFT's rounding is relative to the norms of its operands, not to
 * each output: a kernel value meeting an input only off the grid still
 * leaves its rounding on it; and apply2's two fields share one complex
 * transform, so a large iny leaves its rounding on Kxx * inx.)
 */
#include "fuzz.h"

#define MAX_SIDE 40

/* out = sum over the given kernels k of K_k * in_k (K_k NULL: none) */
static void direct(int mx, int my, const double *const *K, const double *const *in, int nk,
                   double *out)
{
    const int kw = 2 * mx - 1;
    int ix, iy, jx, jy, k;
    for (iy = 0; iy < my; iy++)
        for (ix = 0; ix < mx; ix++) {
            long double s = 0.0L;
            for (k = 0; k < nk; k++) {
                if (!K[k])
                    continue;
                for (jy = 0; jy < my; jy++)
                    for (jx = 0; jx < mx; jx++)
                        s += (long double)K[k][(iy - jy + my - 1) * kw + (ix - jx + mx - 1)]
                             * in[k][jy * mx + jx];
            }
            out[iy * mx + ix] = (double)s;
        }
}

static double norm2(const double *v, int n)
{
    long double s = 0.0L;
    int i;
    for (i = 0; i < n; i++)
        s += (long double)v[i] * v[i];
    return (double)sqrtl(s);
}

/* 0 if a value is not finite, 1 if all are finite and moderate, 2 else */
static int classify(const double *v, int n)
{
    int i, c = 1;
    for (i = 0; i < n; i++) {
        const double a = fabs(v[i]);
        if (!isfinite(v[i]))
            return 0;
        if (a != 0.0 && (a < 1e-100 || a > 1e100))
            c = 2;
    }
    return c;
}

static void check_close(const char *fn, const char *what, const double *got, const double *want,
                        int n, double scale)
{
    int i;
    for (i = 0; i < n; i++)
        if (!(fabs(got[i] - want[i]) <= 1e-13 * scale))
            fz_fail("%s: %s[%d] = %.17g, direct sum %.17g (error %.3g, allowed 1e-13 x %.3g)",
                    fn, what, i, got[i], want[i], fabs(got[i] - want[i]), scale);
}

static void misuse(fz_in *in)
{
    rr_conv2d cv;
    double buf[16] = {0.0};
    int st;
    memset(&cv, 0, sizeof cv);
    fz_note("never initialised rr_conv2d");
    (void)in;
    st = rr_conv2d_apply(&cv, buf, buf, buf + 8);
    fz_status("rr_conv2d_apply", st);
    if (st != RR_ERR_NULL)
        fz_fail("rr_conv2d_apply: status %d on a zeroed rr_conv2d, not RR_ERR_NULL", st);
    st = rr_conv2d_apply2(&cv, buf, buf, buf, buf, buf, buf, buf + 8, buf + 12);
    if (st != RR_ERR_NULL)
        fz_fail("rr_conv2d_apply2: status %d on a zeroed rr_conv2d, not RR_ERR_NULL", st);
    st = rr_conv2d_spectrum(&cv, buf, buf + 8);
    if (st != RR_ERR_NULL)
        fz_fail("rr_conv2d_spectrum: status %d on a zeroed rr_conv2d, not RR_ERR_NULL", st);
    if (rr_conv2d_spectrum_len(&cv) != 0)
        fz_fail("rr_conv2d_spectrum_len: not 0 on a zeroed rr_conv2d");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    const int big = fz_choice(&in, 8) == 0;
    const int mx = fz_int(&in, 1, big ? MAX_SIDE : 12), my = fz_int(&in, 1, big ? MAX_SIDE : 12);
    const int wsel = fz_choice(&in, 8);
    const int valid = mx >= 1 && my >= 1 && mx <= RR_CONV2D_MAX_GRID && my <= RR_CONV2D_MAX_GRID;
    size_t need, wlen, wbytes, sl, nb;
    double *work, *spec[4], *kern[4], *fx, *fy, *ox, *oy, *keep_x, *keep_y, *rx, *ry, *spec0;
    double scale_k, scale_f, bound;
    const double *K[4];
    rr_conv2d cv;
    int n, nk, i, k, st, kmask, shared, alias, kclass = 1, fclass, null_sel, spec_st[4];

    if (fz_choice(&in, 16) == 0) {
        misuse(&in);
        return 0;
    }
    need = rr_conv2d_workspace_len(mx, my);
    fz_note("mx = %d, my = %d, workspace %s", mx, my,
            wsel == 0 ? "NULL" : wsel == 1 ? "one short" : "exact");
    if (!valid) {
        double w[4];
        if (need != 0)
            fz_fail("rr_conv2d_workspace_len(%d, %d) = %zu for an invalid grid", mx, my, need);
        st = rr_conv2d_init(&cv, mx, my, w, 4);
        fz_status("rr_conv2d_init", st);
        if (st != RR_ERR_GRID)
            fz_fail("rr_conv2d_init: status %d for grid %d x %d, not RR_ERR_GRID", st, mx, my);
        if (rr_conv2d_spectrum_len(&cv) != 0)
            fz_fail("rr_conv2d_spectrum_len: not 0 after a failed init");
        return 0;
    }
    if (need == 0)
        fz_fail("rr_conv2d_workspace_len(%d, %d) = 0 for a valid grid", mx, my);
    wlen = wsel == 1 ? need - 1 : need;
    wbytes = wlen * sizeof(double);
    work = wsel == 0 ? NULL : fz_guarded(wbytes);
    st = rr_conv2d_init(&cv, mx, my, work, wlen);
    fz_status("rr_conv2d_init", st);
    if (work)
        fz_guard_ok("rr_conv2d_init", work, wbytes, "the workspace");
    if (wsel <= 1) {
        if (st != RR_ERR_WORKSPACE)
            fz_fail("rr_conv2d_init: status %d with the workspace %s, not RR_ERR_WORKSPACE", st,
                    wsel == 0 ? "NULL" : "one double short");
        fz_guard_free(work);
        return 0;
    }
    if (st != RR_OK)
        fz_fail("rr_conv2d_init: status %d for a valid grid and workspace", st);

    n = mx * my;
    nk = (2 * mx - 1) * (2 * my - 1);
    nb = (size_t)n * sizeof(double);
    sl = rr_conv2d_spectrum_len(&cv);
    if (sl != 2 * (size_t)cv.L1 * (size_t)(cv.L2 / 2 + 1))
        fz_fail("rr_conv2d_spectrum_len = %zu, not 2 L1 (L2/2 + 1) (L1 = %d, L2 = %d)", sl,
                cv.L1, cv.L2);

    /* kernels */
    in.edges = fz_choice(&in, 4) == 0;
    kmask = (int)fz_u8(&in) & 15;
    shared = fz_choice(&in, 4) == 0;
    scale_k = fz_choice(&in, 2) ? 1.0 : fz_log(&in, 1e-100, 1e100);
    for (k = 0; k < 4; k++) {
        kern[k] = fz_alloc((size_t)nk * sizeof(double));
        spec[k] = fz_guarded(sl * sizeof(double));
        for (i = 0; i < nk; i++)
            kern[k][i] = fz_lin(&in, -1.0, 1.0) * scale_k;
    }
    scale_f = fz_choice(&in, 2) ? 1.0 : fz_log(&in, 1e-100, 1e100);
    fx = fz_guarded(nb);
    fy = fz_guarded(nb);
    for (i = 0; i < n; i++) {
        fx[i] = fz_lin(&in, -1.0, 1.0) * scale_f;
        fy[i] = fz_lin(&in, -1.0, 1.0) * scale_f;
    }
    in.edges = 1;
    null_sel = fz_choice(&in, 16);
    alias = fz_choice(&in, 3);
    fz_note("; kernels mask %d%s, scale %.3g; fields scale %.3g; null %d, alias %d", kmask,
            shared ? " (Kyx = Kxy)" : "", scale_k, scale_f, null_sel, alias);

    /* spectra */
    for (k = 0; k < 4; k++) {
        const int c = classify(kern[k], nk);
        double *kc = fz_alloc((size_t)nk * sizeof(double));
        memcpy(kc, kern[k], (size_t)nk * sizeof(double));
        st = rr_conv2d_spectrum(&cv, kern[k], spec[k]);
        fz_status("rr_conv2d_spectrum", st);
        fz_guard_ok("rr_conv2d_spectrum", spec[k], sl * sizeof(double), "the spectrum");
        fz_guard_ok("rr_conv2d_spectrum", work, wbytes, "the workspace");
        fz_same("rr_conv2d_spectrum", kc, kern[k], (size_t)nk * sizeof(double), "the kernel");
        free(kc);
        if (c == 0 && st != RR_ERR_NONFINITE)
            fz_fail("rr_conv2d_spectrum: status %d for a kernel with a NaN or inf", st);
        if (c != 0 && st != RR_OK && st != RR_ERR_RANGE)
            fz_fail("rr_conv2d_spectrum: status %d for a finite kernel", st);
        if (c == 1 && st != RR_OK)
            fz_fail("rr_conv2d_spectrum: status %d for a kernel of moderate values", st);
        if (st < 0 && !fz_all_nan(spec[k], (long)sl))
            fz_fail("rr_conv2d_spectrum: error %d but the spectrum is not NaN", st);
        fz_finite_n("rr_conv2d_spectrum", st, "spec", spec[k], (int)sl);
        spec_st[k] = st;
        /* the kernels apply2 uses: 0 if one has no spectrum (NaN), 2 if one is
         * not moderate, else 1 */
        if ((kmask >> k) & 1 && !(shared && k == 2)) {
            if (st != RR_OK)
                kclass = 0;
            else if (c == 2 && kclass == 1)
                kclass = 2;
        }
    }
    for (k = 0; k < 4; k++)
        K[k] = (kmask >> k) & 1 ? kern[k] : NULL;
    if (shared)
        K[2] = K[1];
    fclass = classify(fx, n) == 0 || classify(fy, n) == 0 ? 0
             : classify(fx, n) == 2 || classify(fy, n) == 2 ? 2 : 1;

    ox = fz_guarded(nb);
    oy = fz_guarded(nb);
    rx = fz_alloc(nb);
    ry = fz_alloc(nb);
    keep_x = fz_alloc(nb);
    keep_y = fz_alloc(nb);
    memcpy(keep_x, fx, nb);
    memcpy(keep_y, fy, nb);
    spec0 = fz_alloc(sl * sizeof(double));
    memcpy(spec0, spec[0], sl * sizeof(double));

    /* ---- apply: K0 * fx ---- */
    {
        const double *const Ka[1] = {kern[0]};
        const double *const Ia[1] = {keep_x};
        const int null_arg = null_sel >= 1 && null_sel <= 3 ? null_sel : 0;
        const int cf = classify(keep_x, n);
        const double *sp = null_arg == 1 ? NULL : spec[0];
        const double *src = null_arg == 2 ? NULL : alias == 1 ? ox : fx;
        double *dst = null_arg == 3 ? NULL : ox;
        if (alias == 1)
            memcpy(ox, fx, nb);
        st = rr_conv2d_apply(&cv, sp, src, dst);
        fz_status("rr_conv2d_apply", st);
        fz_guard_ok("rr_conv2d_apply", ox, nb, "out");
        fz_guard_ok("rr_conv2d_apply", work, wbytes, "the workspace");
        fz_same("rr_conv2d_apply", spec0, spec[0], sl * sizeof(double), "the spectrum");
        fz_same("rr_conv2d_apply", keep_x, fx, nb, "in");
        if (null_arg) {
            if (st != RR_ERR_NULL)
                fz_fail("rr_conv2d_apply: status %d with argument %d NULL", st, null_arg + 1);
            if (dst && !fz_all_nan(ox, n))
                fz_fail("rr_conv2d_apply: RR_ERR_NULL but out is not NaN");
        } else {
            if (cf == 0 && st != RR_ERR_NONFINITE)
                fz_fail("rr_conv2d_apply: status %d for a field with a NaN or inf", st);
            if (cf != 0 && spec_st[0] != RR_OK && st != RR_ERR_RANGE)
                fz_fail("rr_conv2d_apply: status %d with a NaN spectrum", st);
            if (cf != 0 && st != RR_OK && st != RR_ERR_RANGE)
                fz_fail("rr_conv2d_apply: status %d for a finite field", st);
            if (st < 0 && !fz_all_nan(ox, n))
                fz_fail("rr_conv2d_apply: error %d but out is not NaN", st);
            fz_finite_n("rr_conv2d_apply", st, "out", ox, n);
            if (cf == 1 && spec_st[0] == RR_OK && classify(kern[0], nk) == 1) {
                if (st != RR_OK)
                    fz_fail("rr_conv2d_apply: status %d for moderate values", st);
                direct(mx, my, Ka, Ia, 1, rx);
                check_close("rr_conv2d_apply", "out", ox, rx, n,
                            norm2(kern[0], nk) * norm2(keep_x, n));
            }
        }
    }

    /* ---- apply2 ---- */
    {
        const int null_arg = null_sel >= 4 && null_sel <= 7 ? null_sel - 3 : 0;
        const double *sxx = K[0] ? spec[0] : NULL, *sxy = K[1] ? spec[1] : NULL;
        const double *syx = K[2] ? (shared ? spec[1] : spec[2]) : NULL;
        const double *syy = K[3] ? spec[3] : NULL;
        const double *ix = fx, *iy = fy;
        double *outx = ox, *outy = oy;
        if (alias == 1) {
            memcpy(ox, fx, nb);
            memcpy(oy, fy, nb);
            ix = ox;
            iy = oy;
        } else if (alias == 2) {
            memcpy(oy, fx, nb);
            memcpy(ox, fy, nb);
            ix = oy;
            iy = ox;
        }
        if (null_arg == 1)
            ix = NULL;
        else if (null_arg == 2)
            iy = NULL;
        else if (null_arg == 3)
            outx = NULL;
        else if (null_arg == 4)
            outy = NULL;
        st = rr_conv2d_apply2(&cv, sxx, sxy, syx, syy, ix, iy, outx, outy);
        fz_status("rr_conv2d_apply2", st);
        fz_guard_ok("rr_conv2d_apply2", ox, nb, "outx");
        fz_guard_ok("rr_conv2d_apply2", oy, nb, "outy");
        fz_guard_ok("rr_conv2d_apply2", work, wbytes, "the workspace");
        fz_same("rr_conv2d_apply2", spec0, spec[0], sl * sizeof(double), "a spectrum");
        fz_same("rr_conv2d_apply2", keep_x, fx, nb, "inx");
        fz_same("rr_conv2d_apply2", keep_y, fy, nb, "iny");
        if (null_arg) {
            if (st != RR_ERR_NULL)
                fz_fail("rr_conv2d_apply2: status %d with an input or output NULL", st);
            if (outx && !fz_all_nan(ox, n))
                fz_fail("rr_conv2d_apply2: RR_ERR_NULL but outx is not NaN");
            if (outy && !fz_all_nan(oy, n))
                fz_fail("rr_conv2d_apply2: RR_ERR_NULL but outy is not NaN");
        } else {
            if (fclass == 0 && st != RR_ERR_NONFINITE)
                fz_fail("rr_conv2d_apply2: status %d for a field with a NaN or inf", st);
            if (fclass != 0 && st != RR_OK && st != RR_ERR_RANGE)
                fz_fail("rr_conv2d_apply2: status %d for finite fields", st);
            if (fclass != 0 && kclass == 0 && st != RR_ERR_RANGE)
                fz_fail("rr_conv2d_apply2: status %d with a NaN spectrum", st);
            if (st < 0 && (!fz_all_nan(ox, n) || !fz_all_nan(oy, n)))
                fz_fail("rr_conv2d_apply2: error %d but the outputs are not NaN", st);
            fz_finite_n("rr_conv2d_apply2", st, "outx", ox, n);
            fz_finite_n("rr_conv2d_apply2", st, "outy", oy, n);
            if (fclass == 1 && kclass == 1) {
                const double *const Kx[2] = {K[0], K[1]}, *const Ky[2] = {K[2], K[3]};
                const double *const I2[2] = {keep_x, keep_y};
                if (st != RR_OK)
                    fz_fail("rr_conv2d_apply2: status %d for moderate values", st);
                direct(mx, my, Kx, I2, 2, rx);
                direct(mx, my, Ky, I2, 2, ry);
                /* both fields share one complex transform: the rounding of
                 * either reaches both outputs */
                bound = 0.0;
                for (k = 0; k < 4; k++)
                    if (K[k])
                        bound += norm2(K[k], nk);
                bound *= hypot(norm2(keep_x, n), norm2(keep_y, n));
                check_close("rr_conv2d_apply2", "outx", ox, rx, n, bound);
                check_close("rr_conv2d_apply2", "outy", oy, ry, n, bound);
            }
        }
    }

    for (k = 0; k < 4; k++) {
        free(kern[k]);
        fz_guard_free(spec[k]);
    }
    fz_guard_free(fx);
    fz_guard_free(fy);
    fz_guard_free(ox);
    fz_guard_free(oy);
    free(rx);
    free(ry);
    free(keep_x);
    free(keep_y);
    free(spec0);
    fz_guard_free(work);
    return 0;
}
