/*
 * fuzz_spline_fit.c - the profile spline: rr_spline_fit (node slopes with
 * the not-a-knot or natural end condition, c2, c3) and rr_spline_knot_d2,
 * on point lists from the input, against an independent reading of the
 * spline: rr_spline_init and rr_spline_eval (the second-derivative form).
 *
 * Input: n (4 .. 64, or an edge: 0, -1, 1, 3, 65, INT_MIN, INT_MAX), the end
 * condition (0, 1 or any int), whether each pointer is NULL (one in 16
 * each), a byte allowing edge values in the points, the points as a start
 * and increments (1e-5 .. 1e-2 m) and values (within 1 cm, or a cubic, or
 * a line); then the knot_d2 call's own NULLs and count.
 *
 * Oracles: every caller buffer between canaries (nothing written beyond
 * slope[n], c2[n-1], c3[n-1], work[n], d2[n]) and the points left alone;
 * the status one of those the header gives for what is wrong with the
 * arguments (RR_OK or RR_ERR_RANGE only when nothing is); on error the
 * outputs it can reach NaN (n in [1, RR_SPLINE_MAX_POINTS]), none written
 * for n out of that; on success finite coefficients, and the spline
 * interpolates (z_i + h (s_i + h (c2_i + h c3_i)) = z_(i+1)), its slope is
 * continuous (s_i + 2 c2_i h + 3 c3_i h^2 = s_(i+1)), its second derivative
 * too, and the end condition holds (natural: z'' = 0 at both ends; not-a-
 * knot: c3_0 = c3_1, c3_(n-3) = c3_(n-2)), all within rounding; a line (and
 * with not-a-knot a cubic) reproduced; rr_spline_knot_d2 exactly 2 c2_i and
 * 2 c2 + 6 c3 h at the end, its statuses as documented; and an rr_spline
 * with m = d2 evaluates at the knots to z and (natural end) d2 agrees with
 * rr_spline_init's m.
 */
#include "fuzz.h"

#define MAX_PTS 64

/* |a - b| within tol times the scale (and an absolute 1e-280: values near
 * the subnormals round on their own scale) */
static int near(double a, double b, double scale, double tol)
{
    return fabs(a - b) <= tol * scale + 1e-280;
}

static void check_fit(int n, const double *y, const double *z, int end, const double *sl,
                      const double *c2, const double *c3, int shape, const double *a,
                      int plain)
{
    const char *fn = "rr_spline_fit";
    double sc2[MAX_PTS + 1], sc3[MAX_PTS + 1];
    double zs = 0.0, ss = 0.0, ds = 0.0, m[MAX_PTS + 1], w[MAX_PTS + 1], d2[MAX_PTS + 1];
    int i, st;

    for (i = 0; i < n; i++) {
        zs = fmax(zs, fabs(z[i]));
        ss = fmax(ss, fabs(sl[i]));
        /* values near the subnormals round on an absolute scale that the
         * relative checks below do not follow: finite outputs only */
        if ((z[i] != 0.0 && fabs(z[i]) < 1e-250) || (i > 0 && y[i] - y[i - 1] < 1e-100))
            return;
    }
    for (i = 0; i < n - 1; i++) {
        const double h = y[i + 1] - y[i];
        const double zi = z[i] + h * (sl[i] + h * (c2[i] + h * c3[i]));
        const double si = sl[i] + 2.0 * c2[i] * h + 3.0 * c3[i] * h * h;
        const double scale_z = fabs(z[i]) + fabs(z[i + 1])
                               + h * (fabs(sl[i]) + h * (fabs(c2[i]) + h * fabs(c3[i])));
        /* a coefficient below DBL_MIN keeps the subnormals' fixed spacing,
         * which its term carries to the slope (2 h, 3 h^2 of it; a few
         * spacings, for the fit's and this check's own roundings; the
         * scale is taken at 1e-12).  rr_spline_fit accepts that spacing
         * while its term over the interval stays under the values' own
         * rounding (CI's find: values near 3e-3 over intervals of 7e100 m,
         * c3 of 2e-314, the slope's identity off by 4e-10 of the slope) */
        const double sub = (fabs(c2[i]) < DBL_MIN ? 2.0 * h : 0.0)
                           + (fabs(c3[i]) < DBL_MIN ? 3.0 * h * h : 0.0);
        const double scale_s = fabs(sl[i]) + fabs(sl[i + 1]) + 2.0 * fabs(c2[i]) * h
                               + 3.0 * fabs(c3[i]) * h * h + 8e12 * 0x1p-1074 * sub;
        if (!near(zi, z[i + 1], scale_z, 1e-12))
            fz_fail("%s: interval %d ends at %.17g, not z = %.17g", fn, i, zi, z[i + 1]);
        if (!near(si, sl[i + 1], scale_s, 1e-12))
            fz_fail("%s: interval %d ends with slope %.17g, not s = %.17g", fn, i, si,
                    sl[i + 1]);
        ds = fmax(ds, fabs(2.0 * c2[i]) + fabs(6.0 * c3[i] * h));
    }
    /* z'' continuous at the interior knots and the end conditions, within
     * rounding: c2 and c3 are differences of slopes over h and h^2, so
     * their rounding is that of the slopes (and the data) over h, h^2 */
    for (i = 0; i < n - 1; i++) {
        const double h = y[i + 1] - y[i];
        const double e = fabs(sl[i]) + fabs(sl[i + 1]) + fabs((z[i + 1] - z[i]) / h)
                         + (fabs(z[i]) + fabs(z[i + 1])) / h;
        sc2[i] = fabs(2.0 * c2[i]) + fabs(6.0 * c3[i] * h) + 6.0 * e / h;
        sc3[i] = fabs(c3[i]) + 3.0 * e / (h * h);
    }
    /* (on plausible points: the system's conditioning grows with the ratio
     * of neighbouring intervals, which edge values make astronomical) */
    for (i = 1; plain && i < n - 1; i++) {
        const double h = y[i] - y[i - 1];
        const double left = 2.0 * c2[i - 1] + 6.0 * c3[i - 1] * h, right = 2.0 * c2[i];
        if (!near(left, right, sc2[i - 1] + sc2[i], 1e-9))
            fz_fail("%s: z'' jumps at knot %d: %.17g then %.17g (scale %g)", fn, i, left,
                    right, sc2[i - 1] + sc2[i]);
    }
    if (!plain) {
        /* only the local identities above */
    } else if (end == RR_SPLINE_NATURAL) {
        const double hl = y[n - 1] - y[n - 2];
        if (!near(2.0 * c2[0], 0.0, sc2[0], 1e-9)
            || !near(2.0 * c2[n - 2] + 6.0 * c3[n - 2] * hl, 0.0, sc2[n - 2], 1e-9))
            fz_fail("%s: natural end but z'' = %.17g, %.17g at the ends", fn, 2.0 * c2[0],
                    2.0 * c2[n - 2] + 6.0 * c3[n - 2] * hl);
    } else if (!near(c3[0], c3[1], sc3[0] + sc3[1], 1e-9)
               || !near(c3[n - 3], c3[n - 2], sc3[n - 3] + sc3[n - 2], 1e-9)) {
        /* c3 continuous at the second and the last-but-one knot */
        fz_fail("%s: not-a-knot but c3 = %.17g, %.17g and %.17g, %.17g", fn, c3[0], c3[1],
                c3[n - 3], c3[n - 2]);
    }
    /* a line (any end) or a cubic (not-a-knot) is its own spline: checked
     * on plausible points (an extreme spacing makes the not-a-knot ends
     * ill-conditioned by the ratio of neighbouring intervals) */
    if (plain && (shape == 1 || (shape == 2 && end == RR_SPLINE_NOT_A_KNOT))) {
        double hmin = HUGE_VAL;
        for (i = 0; i < n - 1; i++)
            hmin = fmin(hmin, y[i + 1] - y[i]);
        for (i = 0; i < n; i++) {
            const double t = y[i];
            const double d = shape == 1 ? 1e-2 * a[1]
                                        : 1e-2 * a[1] + 2.0 * a[2] * t + 30.0 * a[3] * t * t;
            const double sc = 1e-2 * fabs(a[1]) + zs / hmin
                              + (shape == 2 ? 2.0 * fabs(a[2] * t) + 30.0 * fabs(a[3]) * t * t : 0.0);
            if (!near(sl[i], d, sc, 1e-6))
                fz_fail("%s: a %s, slope %.17g at knot %d, but s = %.17g", fn,
                        shape == 1 ? "line" : "cubic", d, i, sl[i]);
        }
    }
    /* knot_d2 exactly as documented */
    memset(d2, 0, sizeof d2);
    st = rr_spline_knot_d2(n, y, c2, c3, d2);
    if (st == RR_ERR_RANGE) {
        /* finite coefficients whose z'' overflows (c3 near DBL_MAX / 6) */
        if (!fz_all_nan(d2, n))
            fz_fail("rr_spline_knot_d2: RR_ERR_RANGE but d2 not NaN");
        return;
    }
    if (st != RR_OK)
        fz_fail("rr_spline_knot_d2: status %d after a fit", st);
    for (i = 0; i < n - 1; i++)
        if (!(d2[i] == 2.0 * c2[i]))
            fz_fail("rr_spline_knot_d2: d2[%d] = %.17g, not 2 c2 = %.17g", i, d2[i],
                    2.0 * c2[i]);
    if (!(d2[n - 1] == 2.0 * c2[n - 2] + 6.0 * c3[n - 2] * (y[n - 1] - y[n - 2])))
        fz_fail("rr_spline_knot_d2: d2[n-1] = %.17g", d2[n - 1]);
    fz_finite_n("rr_spline_knot_d2", st, "d2", d2, n);
    {
        /* the same curve as an rr_spline: its values at the knots */
        rr_spline sp;
        sp.n = n;
        sp.s = y;
        sp.z = z;
        sp.m = d2;
        for (i = 0; i < n; i++) {
            double v = NAN;
            st = rr_spline_eval(&sp, y[i], &v, NULL, NULL);
            if (st != RR_OK || !near(v, z[i], zs + ds * (y[n - 1] - y[0]) * (y[n - 1] - y[0]), 1e-12))
                fz_fail("rr_spline_eval of the fit: status %d, %.17g at knot %d, not z = %.17g",
                        st, v, i, z[i]);
        }
    }
    if (plain && end == RR_SPLINE_NATURAL && rr_spline_init(n, y, z, m, w) == RR_OK) {
        double smax = 0.0;
        for (i = 0; i < n - 1; i++)
            smax = fmax(smax, sc2[i]);
        /* rr_spline_init solves for the same natural spline's z'' */
        for (i = 0; i < n; i++)
            if (!near(m[i], d2[i], smax + fabs(m[i]), 1e-8))
                fz_fail("rr_spline_fit (natural): z''(knot %d) = %.17g, rr_spline_init's "
                        "%.17g (scale %g)", i, d2[i], m[i], smax);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    const int n = fz_int(&in, RR_SPLINE_MIN_POINTS, MAX_PTS);
    const int end = fz_int(&in, 0, 1);
    const int null_y = fz_choice(&in, 16) == 0, null_z = fz_choice(&in, 16) == 0;
    const int null_s = fz_choice(&in, 16) == 0, null_c2 = fz_choice(&in, 16) == 0;
    const int null_c3 = fz_choice(&in, 16) == 0, null_w = fz_choice(&in, 16) == 0;
    const int shape = fz_choice(&in, 4);     /* 0, 3 free values; 1 a line; 2 a cubic */
    /* points and buffers: n of them where n is in [1, MAX_PTS + 1], else 1
     * (n out of range: nothing may be written) */
    const int np = n >= 1 && n <= MAX_PTS + 1 ? n : 1;
    const size_t nb = (size_t)np * sizeof(double), nb1 = (size_t)(np - 1) * sizeof(double);
    double *y = fz_guarded(nb), *z = fz_guarded(nb), *y0 = fz_alloc(nb), *z0 = fz_alloc(nb);
    double *sl = fz_guarded(nb), *c2 = fz_guarded(nb1), *c3 = fz_guarded(nb1);
    double *w = fz_guarded(nb), *d2 = fz_guarded(nb);
    double a[4];
    int i, st, want[16], nwant = 0, valid, reach, plain;

    in.edges = fz_choice(&in, 4) == 0;
    plain = !in.edges;
    for (i = 0; i < 4; i++)
        a[i] = fz_slog(&in, 1e-3, 1e3);
    y[0] = fz_lin(&in, -0.05, 0.05);
    for (i = 1; i < np; i++)
        y[i] = y[i - 1] + fz_log(&in, 1e-5, 1e-2);
    for (i = 0; i < np; i++) {
        const double t = y[i];
        z[i] = shape == 1 ? 1e-3 * a[0] + 1e-2 * a[1] * t
             : shape == 2 ? 1e-3 * a[0] + 1e-2 * a[1] * t + a[2] * t * t + 10.0 * a[3] * t * t * t
             : fz_lin(&in, -0.01, 0.01);
    }
    in.edges = 1;
    memcpy(y0, y, nb);
    memcpy(z0, z, nb);
    fz_note("n = %d end %d NULL y%d z%d s%d c2%d c3%d w%d shape %d; points:", n, end, null_y,
            null_z, null_s, null_c2, null_c3, null_w, shape);
    for (i = 0; i < np; i++)
        fz_note(" (%.17g, %.17g)", y[i], z[i]);

    /* the statuses the arguments call for (any one of them will do) */
    if (!(n >= RR_SPLINE_MIN_POINTS && n <= RR_SPLINE_MAX_POINTS)
        || (end != RR_SPLINE_NOT_A_KNOT && end != RR_SPLINE_NATURAL))
        want[nwant++] = RR_ERR_PARAM;
    if (null_y || null_z)
        want[nwant++] = RR_ERR_NULL;
    if (null_s || null_c2 || null_c3 || null_w)
        want[nwant++] = RR_ERR_WORKSPACE;
    if (nwant == 0) {
        int nonfinite = 0, order = 0;
        for (i = 0; i < n; i++) {
            nonfinite |= !isfinite(y[i]) || !isfinite(z[i]);
            if (i > 0 && !(y[i] > y[i - 1]))
                order = 1;
        }
        if (nonfinite)
            want[nwant++] = RR_ERR_NONFINITE;
        else if (order)
            want[nwant++] = RR_ERR_GEOMETRY;
    }
    valid = nwant == 0;

    st = rr_spline_fit(n, null_y ? NULL : y, null_z ? NULL : z, end, null_s ? NULL : sl,
                       null_c2 ? NULL : c2, null_c3 ? NULL : c3, null_w ? NULL : w);
    fz_status("rr_spline_fit", st);
    fz_guard_ok("rr_spline_fit", y, nb, "y");
    fz_guard_ok("rr_spline_fit", z, nb, "z");
    fz_same("rr_spline_fit", y0, y, nb, "y");
    fz_same("rr_spline_fit", z0, z, nb, "z");
    fz_guard_ok("rr_spline_fit", sl, nb, "slope[n]");
    fz_guard_ok("rr_spline_fit", c2, nb1, "c2[n-1]");
    fz_guard_ok("rr_spline_fit", c3, nb1, "c3[n-1]");
    fz_guard_ok("rr_spline_fit", w, nb, "work[n]");
    if (valid) {
        if (st != RR_OK && st != RR_ERR_RANGE)
            fz_fail("rr_spline_fit: status %d for valid arguments", st);
    } else {
        int k, ok = 0;
        for (k = 0; k < nwant; k++)
            ok |= st == want[k];
        if (!ok)
            fz_fail("rr_spline_fit: status %d, not one of the %d the arguments call for "
                    "(first %d)", st, nwant, want[0]);
    }
    reach = n >= 1 && n <= RR_SPLINE_MAX_POINTS;
    if (st < 0 && reach) {
        if ((!null_s && !fz_all_nan(sl, n)) || (!null_c2 && !fz_all_nan(c2, n - 1))
            || (!null_c3 && !fz_all_nan(c3, n - 1)))
            fz_fail("rr_spline_fit: error %d but the outputs are not NaN", st);
    } else if (st < 0) {
        if (!fz_untouched(sl, nb) || !fz_untouched(c2, nb1) || !fz_untouched(c3, nb1)
            || !fz_untouched(w, nb))
            fz_fail("rr_spline_fit: n = %d out of range, but an output was written", n);
    }
    if (st == RR_OK) {
        fz_finite_n("rr_spline_fit", st, "slope", sl, n);
        fz_finite_n("rr_spline_fit", st, "c2", c2, n - 1);
        fz_finite_n("rr_spline_fit", st, "c3", c3, n - 1);
        check_fit(n, y, z, end, sl, c2, c3, shape, a, plain);
    }

    /* rr_spline_knot_d2's own refusals, over whatever the fit left */
    {
        const int k0 = fz_int(&in, RR_SPLINE_MIN_POINTS, np);
        /* a count in range never beyond the buffers */
        const int k = k0 >= RR_SPLINE_MIN_POINTS && k0 <= RR_SPLINE_MAX_POINTS && k0 > np ? np : k0;
        const int ny = fz_choice(&in, 8) == 0, nc2 = fz_choice(&in, 8) == 0;
        const int nc3 = fz_choice(&in, 8) == 0, nd = fz_choice(&in, 8) == 0;
        const int st2 = rr_spline_knot_d2(k, ny ? NULL : y,
                                          nc2 ? NULL : c2, nc3 ? NULL : c3, nd ? NULL : d2);
        fz_note("; knot_d2 n = %d NULL y%d c2%d c3%d d2%d", k, ny, nc2, nc3, nd);
        fz_status("rr_spline_knot_d2", st2);
        if (!(k >= RR_SPLINE_MIN_POINTS && k <= RR_SPLINE_MAX_POINTS)) {
            if (st2 != RR_ERR_PARAM)
                fz_fail("rr_spline_knot_d2: n = %d, status %d, not RR_ERR_PARAM", k, st2);
        } else if (ny || nc2 || nc3) {
            if (st2 != RR_ERR_NULL)
                fz_fail("rr_spline_knot_d2: NULL input, status %d, not RR_ERR_NULL", st2);
        } else if (nd) {
            if (st2 != RR_ERR_WORKSPACE)
                fz_fail("rr_spline_knot_d2: NULL d2, status %d, not RR_ERR_WORKSPACE", st2);
        } else if (st2 != RR_OK && st2 != RR_ERR_RANGE) {
            fz_fail("rr_spline_knot_d2: status %d for valid arguments", st2);
        }
        if (st2 == RR_ERR_RANGE && !fz_all_nan(d2, k))
            fz_fail("rr_spline_knot_d2: RR_ERR_RANGE but d2 not NaN");
        if (st2 >= 0)
            fz_finite_n("rr_spline_knot_d2", st2, "d2", d2, k);
        if (st2 < 0 && st2 != RR_ERR_RANGE && !fz_untouched(d2, nb))
            fz_fail("rr_spline_knot_d2: error %d, but d2 was written", st2);
        fz_guard_ok("rr_spline_knot_d2", d2, nb, "d2[n]");
    }
    fz_guard_free(y);
    fz_guard_free(z);
    free(y0);
    free(z0);
    fz_guard_free(sl);
    fz_guard_free(c2);
    fz_guard_free(c3);
    fz_guard_free(w);
    fz_guard_free(d2);
    return 0;
}
