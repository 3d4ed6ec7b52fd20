/*
 * fuzz_tables.c - contact tables from points (rr_tables.h): the analytic
 * profiles rr_profile_conical and rr_profile_crowned, rr_profile_surface,
 * rr_profile_table_work_len and rr_profile_table_build(_rows), and the
 * rig's table rr_rig_table_data_len and rr_rig_table_build(_rows), and on
 * profiles given as points rr_rig_profiles_check, rr_rig_profiles_work_len,
 * rr_rig_table_build_profiles_rows (oracles: the check against an
 * independent one of the documented rules, the build's status the check's,
 * a short workspace refused, rows finite, with no profile given
 * rr_rig_table_build's rows bit for bit).
 *
 * Input: one byte choosing the entry point, then its arguments: the cone
 * angle or crown radius, the range and n (4 .. 48 or an edge), NULLs; for
 * the tables two profiles (a cone on a crown, n 4 .. 24, perturbed or not),
 * their placement, search options with nsamples 3 .. 40, 2 .. 4 rows, a
 * row range, buffers one double short now and then; for the rig's table
 * its geometry near the paper's (fz_near) and 2 .. 3 rows (its search takes
 * the default 400 samples on 121 points: ~1 ms a row).
 *
 * Oracles: a documented status; every caller buffer between canaries, and
 * rows outside [i0, i1) left alone; NaN outputs on error where promised;
 * the analytic profiles as documented (linspace's points bit for bit,
 * z = -tan(alpha) y exactly, the crown symmetric-free checks z >= 0, z <= |y|);
 * rr_profile_surface's zup = -z and mup = -(rr_spline_knot_d2 of
 * rr_spline_fit) bit for bit; a table built without error finite; the same
 * table built in two row ranges bit for bit the whole build; *bad_y NaN or
 * one of the rows' shifts; the work and data lengths: 0 exactly for counts
 * out of range, and one double less refused with RR_ERR_WORKSPACE; the rig
 * table's t as documented, and rr_rig_params_set_table on it giving the
 * row at y = 0's radii.
 */
#include "fuzz.h"

#define MAX_PTS 48
#define MAX_TPTS 24
#define MAX_ROWS 4

static int one_of(int st, const int *want, int n)
{
    int k;
    for (k = 0; k < n; k++)
        if (st == want[k])
            return 1;
    return 0;
}

/* rr_profile_conical (kind 0) or rr_profile_crowned (kind 1) */
static void run_analytic(fz_in *in, int kind)
{
    const char *fn = kind ? "rr_profile_crowned" : "rr_profile_conical";
    const double p = kind ? fz_log(in, 1e-3, 10.0) * (fz_choice(in, 8) == 0 ? 0.0 : 1.0)
                          : fz_lin(in, -1.6, 1.6);
    const double y_min = fz_lin(in, -2.1, 0.1), y_max = y_min + fz_log(in, 1e-4, 4.0);
    const int n = fz_int(in, RR_SPLINE_MIN_POINTS, MAX_PTS);
    const int ny = fz_choice(in, 16) == 0, nz = fz_choice(in, 16) == 0;
    const int np = n >= 1 && n <= MAX_PTS + 1 ? n : 1;
    const size_t nb = (size_t)np * sizeof(double);
    double *y = fz_guarded(nb), *z = fz_guarded(nb);
    int st, want[4], nw = 0, i, range_ok;

    fz_note("%s(%.17g, %.17g, %.17g, %d) NULL y%d z%d", fn, p, y_min, y_max, n, ny, nz);
    range_ok = n >= RR_SPLINE_MIN_POINTS && n <= RR_SPLINE_MAX_POINTS && isfinite(y_min)
               && isfinite(y_max) && y_max > y_min && fabs(y_min) <= RR_PROFILE_MAX_COORD
               && fabs(y_max) <= RR_PROFILE_MAX_COORD && y_max - y_min >= RR_PROFILE_MIN_WIDTH;
    if (ny || nz)
        want[nw++] = RR_ERR_NULL;
    if (!range_ok) {
        want[nw++] = RR_ERR_PARAM;
        if (!isfinite(y_min) || !isfinite(y_max))
            want[nw++] = RR_ERR_NONFINITE;
    }
    if (!isfinite(p))
        want[nw++] = RR_ERR_NONFINITE;
    else if (kind ? !(p >= 0.0) : !(fabs(p) < RR_PI / 2.0))
        want[nw++] = RR_ERR_PARAM;
    else if (kind && p > 0.0 && !(fmax(fabs(y_min), fabs(y_max)) < p))
        want[nw++] = RR_ERR_GEOMETRY;
    st = kind ? rr_profile_crowned(p, y_min, y_max, n, ny ? NULL : y, nz ? NULL : z)
              : rr_profile_conical(p, y_min, y_max, n, ny ? NULL : y, nz ? NULL : z);
    fz_status(fn, st);
    fz_guard_ok(fn, y, nb, "y[n]");
    fz_guard_ok(fn, z, nb, "z[n]");
    if (nw > 0 && !one_of(st, want, nw))
        fz_fail("%s: status %d, not one the arguments call for (first %d)", fn, st, want[0]);
    if (nw == 0 && st != RR_OK)
        fz_fail("%s: status %d for valid arguments", fn, st);
    if (st < 0 && n >= 1 && n <= RR_SPLINE_MAX_POINTS) {
        if ((!ny && !fz_all_nan(y, n)) || (!nz && !fz_all_nan(z, n)))
            fz_fail("%s: error %d but the points are not NaN", fn, st);
    } else if (st < 0 && (!fz_untouched(y, nb) || !fz_untouched(z, nb))) {
        fz_fail("%s: n = %d out of range, but a point was written", fn, n);
    }
    if (st == RR_OK) {
        const double step = (y_max - y_min) / (double)(n - 1);
        for (i = 0; i < n; i++) {
            const double yi = i == n - 1 ? y_max : (double)i * step + y_min;
            if (memcmp(&y[i], &yi, sizeof yi) != 0)
                fz_fail("%s: y[%d] = %.17g, not linspace's %.17g", fn, i, y[i], yi);
            if (i > 0 && !(y[i] > y[i - 1]))
                fz_fail("%s: y not increasing at %d", fn, i);
            if (!kind && !(z[i] == -tan(p) * y[i]))
                fz_fail("%s: z[%d] = %.17g, not -tan(alpha) y = %.17g", fn, i, z[i],
                        -tan(p) * y[i]);
            if (kind && !(isfinite(z[i]) && z[i] >= 0.0 && z[i] <= fabs(y[i])
                          && (p > 0.0 || z[i] == 0.0)))
                fz_fail("%s: z[%d] = %.17g at y = %.17g (R = %.17g): not in [0, |y|]", fn, i,
                        z[i], y[i], p);
            /* the reference as R (1 - sqrt(1 - (y/R)^2)): R^2 overflows for R
             * above 1e154, and the crown's own formula is not a reference */
            if (kind && p > 0.0 && fabs(y[i]) < 0.5 * p
                && !(fabs(z[i] - p * (1.0 - sqrt(1.0 - (y[i] / p) * (y[i] / p))))
                     <= 1e-9 * p))
                fz_fail("%s: z[%d] = %.17g, R - sqrt(R^2 - y^2) = %.17g", fn, i, z[i],
                        p * (1.0 - sqrt(1.0 - (y[i] / p) * (y[i] / p))));
            FZ_FINITE(fn, st, z[i]);
        }
    }
    fz_guard_free(y);
    fz_guard_free(z);
}

/* A profile: a cone (wheel) or crown (roller) on n points, perturbed or not,
 * or (one in 8) a free point list; in the caller's arrays of MAX_TPTS. */
static void decode_points(fz_in *in, int roller, int nmax, double *y, double *z,
                          rr_profile_points *p)
{
    const int mode = fz_choice(in, 8);
    const int n = mode == 7 ? fz_int(in, RR_SPLINE_MIN_POINTS, nmax)
                            : fz_range(in, RR_SPLINE_MIN_POINTS, nmax);
    const int nn = n >= 1 && n <= nmax + 1 ? n : 1;   /* arrays of nmax + 1 */
    const double hw = fz_lin(in, 0.005, 0.03);
    int i;

    p->n = n;
    p->y = y;
    p->z = z;
    p->end = fz_choice(in, 16) == 0 ? fz_int(in, 0, 1) : fz_choice(in, 2);
    if (mode == 7) {
        y[0] = fz_lin(in, -0.03, 0.0);
        z[0] = fz_lin(in, -1e-3, 1e-3);
        for (i = 1; i < nn; i++) {
            y[i] = y[i - 1] + fz_log(in, 1e-4, 1e-2);
            z[i] = fz_lin(in, -1e-3, 1e-3);
        }
        return;
    }
    if (roller)
        rr_profile_crowned(fz_lin(in, 0.04, 0.2), -hw, hw, n, y, z);
    else
        rr_profile_conical(fz_lin(in, -0.2, 0.2), -hw, hw, n, y, z);
    if (mode >= 5)
        for (i = 0; i < n; i++)
            z[i] += fz_log(in, 1e-9, 1e-5) * fz_lin(in, -1.0, 1.0);
}

static void run_surface(fz_in *in)
{
    const char *fn = "rr_profile_surface";
    double ybuf[MAX_PTS + 1], zbuf[MAX_PTS + 1];
    rr_profile_points p;
    int np, st, i, nzu, nmu, nw;
    size_t nb;
    double *zup, *mup, *work;

    decode_points(in, fz_choice(in, 2), MAX_PTS, ybuf, zbuf, &p);
    nzu = fz_choice(in, 16) == 0;
    nmu = fz_choice(in, 16) == 0;
    nw = fz_choice(in, 16) == 0;
    np = p.n >= 1 && p.n <= MAX_PTS + 1 ? p.n : 1;
    nb = (size_t)np * sizeof(double);
    zup = fz_guarded(nb);
    mup = fz_guarded(nb);
    work = fz_guarded(4 * nb);
    fz_note("surface n = %d end %d NULL zup%d mup%d work%d", p.n, p.end, nzu, nmu, nw);
    st = rr_profile_surface(fz_choice(in, 32) == 0 ? NULL : &p, nzu ? NULL : zup,
                            nmu ? NULL : mup, nw ? NULL : work);
    fz_status(fn, st);
    fz_guard_ok(fn, zup, nb, "zup[n]");
    fz_guard_ok(fn, mup, nb, "mup[n]");
    fz_guard_ok(fn, work, 4 * nb, "work[4 n]");
    if ((nzu || nmu || nw) && st != RR_ERR_WORKSPACE && st != RR_ERR_NULL)
        fz_fail("%s: a NULL buffer, status %d", fn, st);
    if (st < 0 && st != RR_ERR_NULL && p.n >= 1 && p.n <= MAX_PTS + 1
        && ((!nzu && !fz_all_nan(zup, p.n)) || (!nmu && !fz_all_nan(mup, p.n))))
        fz_fail("%s: error %d but zup, mup not NaN", fn, st);
    if (st == RR_OK) {
        double s[MAX_PTS + 1], c2[MAX_PTS + 1], c3[MAX_PTS + 1], w[MAX_PTS + 1];
        double d2[MAX_PTS + 1];
        if (rr_spline_fit(p.n, p.y, p.z, p.end, s, c2, c3, w) != RR_OK
            || rr_spline_knot_d2(p.n, p.y, c2, c3, d2) != RR_OK)
            fz_fail("%s: OK, but rr_spline_fit or knot_d2 refuse the points", fn);
        for (i = 0; i < p.n; i++) {
            const double a = -p.z[i], b = -d2[i];
            if (memcmp(&zup[i], &a, sizeof a) != 0 || memcmp(&mup[i], &b, sizeof b) != 0)
                fz_fail("%s: point %d: (%.17g, %.17g), not (-z, -z'') = (%.17g, %.17g)", fn,
                        i, zup[i], mup[i], a, b);
        }
        fz_finite_n(fn, st, "zup", zup, p.n);
        fz_finite_n(fn, st, "mup", mup, p.n);
    }
    fz_guard_free(zup);
    fz_guard_free(mup);
    fz_guard_free(work);
}

/* *bad_y: NaN, or the shift of one of the rows [i0, i1) */
static void check_bad_y(const char *fn, int st, double bad, const rr_contact_table *t, int i0,
                        int i1)
{
    int i;
    if (isnan(bad))
        return;
    if (st >= 0)
        fz_fail("%s: status %d but *bad_y = %.17g", fn, st, bad);
    for (i = i0; i < i1; i++)
        if (bad == t->y0 + i * t->dy)
            return;
    fz_fail("%s: *bad_y = %.17g, not a row's shift in [%d, %d)", fn, bad, i0, i1);
}

static void check_rows(const char *fn, const double *a, const double *b, int i0, int i1,
                       const char *what)
{
    const size_t row = RR_CONTACT_TABLE_ROW * sizeof(double);
    if (i1 > i0 && memcmp(a + (long)i0 * RR_CONTACT_TABLE_ROW, b + (long)i0 * RR_CONTACT_TABLE_ROW,
                          (size_t)(i1 - i0) * row) != 0)
        fz_fail("%s: rows [%d, %d) %s", fn, i0, i1, what);
}

static void run_profile_table(fz_in *in)
{
    const char *fn = "rr_profile_table_build";
    double wy[MAX_TPTS + 1], wz[MAX_TPTS + 1], ry[MAX_TPTS + 1], rz[MAX_TPTS + 1], bad = 0.0;
    rr_profile_points wheel, roller;
    rr_profile_placement place;
    rr_search_opts o;
    rr_contact_table t;
    long need_w, need_d, data_len, work_len;
    int rows, i0, i1, st, st_all, wshort, dshort, want_bad;
    double *data, *data2, *work;

    decode_points(in, 0, MAX_TPTS, wy, wz, &wheel);
    decode_points(in, 1, MAX_TPTS, ry, rz, &roller);
    place.wheel_radius = fz_near(in, 0.092, 3.0);
    place.roller_radius = fz_near(in, 0.16, 3.0);
    place.wheel_y = fz_near(in, 0.15, 1.5);
    place.roller_y = place.wheel_y + fz_lin(in, -0.003, 0.003);
    rr_search_opts_default(&o);
    o.nsamples = fz_range(in, 3, 40);
    rows = fz_int(in, 2, MAX_ROWS);   /* an edge: 0, 1, -1, MAX_ROWS + 1, INT_MIN, INT_MAX */
    t.n = rows;
    t.y0 = fz_lin(in, -0.004, 0.0);
    t.dy = fz_log(in, 1e-4, 2e-3);
    i0 = fz_int(in, 0, rows > 0 ? rows : 0);
    i1 = fz_choice(in, 4) == 0 ? fz_int(in, 0, rows) : rows;
    wshort = fz_choice(in, 16) == 0;
    dshort = fz_choice(in, 16) == 0;
    need_w = rr_profile_table_work_len(wheel.n, roller.n);
    need_d = rr_contact_table_len(rows >= 2 && rows <= MAX_ROWS + 1 ? rows : 0);
    /* the lengths: 0 exactly for counts out of range */
    if ((need_w == 0) != (wheel.n < RR_SPLINE_MIN_POINTS || wheel.n > RR_SPLINE_MAX_POINTS
                          || roller.n < RR_SPLINE_MIN_POINTS || roller.n > RR_SPLINE_MAX_POINTS))
        fz_fail("rr_profile_table_work_len(%d, %d) = %ld", wheel.n, roller.n, need_w);
    work_len = need_w > 0 ? need_w - wshort : 0;
    data_len = need_d > 0 ? need_d - dshort : 0;
    work = fz_guarded((size_t)(work_len > 0 ? work_len : 0) * sizeof(double));
    data = fz_guarded((size_t)(data_len > 0 ? data_len : 0) * sizeof(double));
    data2 = fz_guarded((size_t)(data_len > 0 ? data_len : 0) * sizeof(double));
    fz_note("profile table: wheel n %d end %d, roller n %d end %d, r0 %.17g R0 %.17g y %.17g "
            "%.17g, nsamples %d, rows %d y0 %.17g dy %.17g [%d, %d) short w%d d%d",
            wheel.n, wheel.end, roller.n, roller.end, place.wheel_radius, place.roller_radius,
            place.wheel_y, place.roller_y, o.nsamples, rows, t.y0, t.dy, i0, i1, wshort, dshort);
    t.data = data;
    want_bad = fz_choice(in, 8) != 0;
    st = rr_profile_table_build_rows(&wheel, &roller, &place, &o, &t, data_len, work, work_len,
                                     i0, i1, want_bad ? &bad : NULL);
    fz_status(fn, st);
    fz_guard_ok(fn, data, (size_t)(data_len > 0 ? data_len : 0) * sizeof(double), "data");
    fz_guard_ok(fn, work, (size_t)(work_len > 0 ? work_len : 0) * sizeof(double), "work");
    if ((wshort || dshort) && rows >= 2 && need_w > 0 && st != RR_ERR_WORKSPACE)
        fz_fail("%s: a buffer one double short, status %d", fn, st);
    if (!(i0 >= 0 && i0 <= i1 && i1 <= rows) && st >= 0)
        fz_fail("%s: rows [%d, %d) of %d, status %d", fn, i0, i1, rows, st);
    if (want_bad)
        check_bad_y(fn, st, bad, &t, i0, i1);
    if (rows >= 2 && data_len > 0) {
        /* the rows outside [i0, i1) left alone */
        const size_t row = RR_CONTACT_TABLE_ROW * sizeof(double);
        if (st >= 0 && (!fz_untouched(data, (size_t)(i0 > 0 ? i0 : 0) * row)
                        || !fz_untouched(data + (long)i1 * RR_CONTACT_TABLE_ROW,
                                         (size_t)(rows - i1) * row)))
            fz_fail("%s: wrote rows outside [%d, %d)", fn, i0, i1);
    }
    if (st == RR_OK && i1 > i0) {
        fz_finite_n(fn, st, "row", data + (long)i0 * RR_CONTACT_TABLE_ROW,
                    (i1 - i0) * RR_CONTACT_TABLE_ROW);
        /* the whole build into a second buffer: the same rows, bit for bit;
         * then the rest of the table in the two ranges around [i0, i1) */
        t.data = data2;
        st_all = rr_profile_table_build(&wheel, &roller, &place, &o, &t, data_len, work,
                                        work_len, NULL);
        if (st_all == RR_OK) {
            check_rows(fn, data, data2, i0, i1, "of a range build differ from the whole build");
            t.data = data;
            if (rr_profile_table_build_rows(&wheel, &roller, &place, &o, &t, data_len, work,
                                            work_len, 0, i0, NULL) != RR_OK
                || rr_profile_table_build_rows(&wheel, &roller, &place, &o, &t, data_len, work,
                                               work_len, i1, rows, NULL) != RR_OK)
                fz_fail("%s: the whole build OK, but a part of it fails", fn);
            check_rows(fn, data, data2, 0, rows, "built in three ranges differ from the whole");
        } else if (i0 == 0 && i1 == rows) {
            fz_fail("%s: rows [0, n) OK but the whole build %d", fn, st_all);
        }
    }
    fz_guard_free(work);
    fz_guard_free(data);
    fz_guard_free(data2);
}

static void run_rig_table(fz_in *in)
{
    const char *fn = "rr_rig_table_build";
    rr_rig_geometry g;
    rr_contact_table t, t2;
    rr_rig_params p;
    double bad = 0.0, *data, *data2, *work;
    long need, data_len, work_len;
    int st, st2, i0, i1, dshort, wshort, rows_ok;

    g.wheel_radius = fz_near(in, 0.092, 2.0);
    g.roller_radius = fz_near(in, 0.16, 2.0);
    g.profile_half_width = fz_near(in, 0.015, 2.0);
    g.cone_angle = fz_near(in, atan(0.05), 4.0);
    g.crown_radius = fz_choice(in, 8) == 0 ? 0.0 : fz_near(in, 0.06, 2.0);
    g.contact_half_spacing = fz_near(in, 0.15, 1.5);
    g.table_half_range = fz_near(in, 0.008, 2.0);
    g.table_rows = fz_int(in, 2, 3);   /* an edge: 0, 1, -1, 4, INT_MIN, INT_MAX */
    rows_ok = g.table_rows >= 2 && g.table_rows <= 4;
    need = rr_rig_table_data_len(&g);
    if (need != (rows_ok ? rr_contact_table_len(g.table_rows) : 0))
        fz_fail("rr_rig_table_data_len: %ld for %d rows", need, g.table_rows);
    if (rr_rig_table_data_len(NULL) != 0)
        fz_fail("rr_rig_table_data_len(NULL) not 0");
    dshort = fz_choice(in, 16) == 0;
    wshort = fz_choice(in, 16) == 0;
    data_len = need > 0 ? need - dshort : 0;
    work_len = RR_RIG_TABLE_WORK_LEN - wshort;
    i0 = fz_int(in, 0, rows_ok ? g.table_rows : 0);
    i1 = fz_choice(in, 2) == 0 ? fz_int(in, 0, rows_ok ? g.table_rows : 0)
                               : (rows_ok ? g.table_rows : 0);
    data = fz_guarded((size_t)data_len * sizeof(double));
    data2 = fz_guarded((size_t)data_len * sizeof(double));
    work = fz_guarded((size_t)work_len * sizeof(double));
    fz_note("rig table: r0 %.17g R0 %.17g hw %.17g alpha %.17g crown %.17g spacing %.17g "
            "reach %.17g rows %d [%d, %d) short d%d w%d", g.wheel_radius, g.roller_radius,
            g.profile_half_width, g.cone_angle, g.crown_radius, g.contact_half_spacing,
            g.table_half_range, g.table_rows, i0, i1, dshort, wshort);
    memset(&t, 0, sizeof t);
    st = rr_rig_table_build_rows(&g, data, data_len, work, work_len, i0, i1, &t, &bad);
    fz_status(fn, st);
    fz_guard_ok(fn, data, (size_t)data_len * sizeof(double), "data");
    fz_guard_ok(fn, work, (size_t)work_len * sizeof(double), "work");
    if ((dshort || wshort) && st >= 0)
        fz_fail("%s: a buffer one double short, status %d", fn, st);
    if (!(i0 >= 0 && i0 <= i1 && i1 <= g.table_rows) && st >= 0)
        fz_fail("%s: rows [%d, %d) of %d, status %d", fn, i0, i1, g.table_rows, st);
    if (st >= 0) {
        const double reach = g.table_half_range;
        if (!(t.y0 == -reach && t.dy == 2.0 * reach / (double)(g.table_rows - 1)
              && t.n == g.table_rows && t.data == data))
            fz_fail("%s: t = (y0 %.17g, dy %.17g, n %d) not as documented", fn, t.y0, t.dy,
                    t.n);
        if (!isnan(bad))
            fz_fail("%s: OK but *bad_y = %.17g", fn, bad);
        fz_finite_n(fn, st, "row", data + (long)i0 * RR_CONTACT_TABLE_ROW,
                    (i1 - i0) * RR_CONTACT_TABLE_ROW);
    } else if (st < 0 && t.n == g.table_rows && t.data == data) {
        check_bad_y(fn, st, bad, &t, i0, i1);
    }
    if (st == RR_OK && i1 > i0) {
        st2 = rr_rig_table_build(&g, data2, data_len, work, work_len, &t2, NULL);
        if (st2 == RR_OK) {
            check_rows(fn, data, data2, i0, i1, "of a range build differ from the whole build");
            /* the calibrated radii: the row at y = 0 */
            if (rr_rig_params_default(&p) != RR_OK)
                fz_fail("rr_rig_params_default: not OK");
            st2 = rr_rig_params_set_table(&p, &t2);
            fz_status("rr_rig_params_set_table", st2);
            if (st2 >= 0) {
                rr_wheelset_pose pose;
                rr_contact_point cl, cr;
                if (rr_contact_table_lookup(&t2, 0.0, &pose, NULL, &cl, &cr) < 0
                    || !(p.creepctl.r_w == cl.r && p.creepctl.r_r == cl.R)
                    || p.contact.table != &t2)
                    fz_fail("rr_rig_params_set_table: r_w %.17g r_r %.17g, not the row at 0",
                            p.creepctl.r_w, p.creepctl.r_r);
                FZ_FINITE("rr_rig_params_set_table", st2, p.creepctl.r_w);
                FZ_FINITE("rr_rig_params_set_table", st2, p.creepctl.r_r);
            }
        } else if (i0 == 0 && i1 == g.table_rows) {
            fz_fail("%s: rows [0, n) OK but the whole build %d", fn, st2);
        }
    }
    fz_guard_free(data);
    fz_guard_free(data2);
    fz_guard_free(work);
}

/* The independent oracle of rr_rig_profiles_check for one given slot's
 * points: the first problem's status and point (-1: the whole profile). */
static int slot_oracle(const rr_profile_points *p, int *point)
{
    int i;
    *point = -1;
    if (p->n < 0)
        return RR_ERR_NULL;
    if (p->n < RR_SPLINE_MIN_POINTS || p->n > RR_SPLINE_MAX_POINTS
        || (p->end != RR_SPLINE_NOT_A_KNOT && p->end != RR_SPLINE_NATURAL))
        return RR_ERR_PARAM;
    if (!p->y || !p->z)
        return RR_ERR_NULL;
    for (i = 0; i < p->n; i++) {
        *point = i;
        if (!isfinite(p->y[i]) || !isfinite(p->z[i]))
            return RR_ERR_NONFINITE;
        if (fabs(p->y[i]) > RR_PROFILE_MAX_COORD || fabs(p->z[i]) > RR_PROFILE_MAX_COORD)
            return RR_ERR_PARAM;
        if (i > 0 && (!(p->y[i] > p->y[i - 1]) || p->y[i] - p->y[i - 1] > RR_PROFILE_MAX_GAP))
            return RR_ERR_GEOMETRY;
    }
    *point = -1;
    return p->y[p->n - 1] - p->y[0] >= RR_PROFILE_MIN_WIDTH ? RR_OK : RR_ERR_PARAM;
}

/* rr_rig_table_build_profiles(_rows) on the rig's geometry and up to four
 * given profiles (each not given, "to be given" (n = -1) or decode_points'
 * at full size, now and then spoilt: a NaN, a step back, a gap, x 1000). */
static void run_rig_profiles(fz_in *in)
{
    const char *fn = "rr_rig_table_build_profiles";
    static double py[4][MAX_TPTS + 1], pz[4][MAX_TPTS + 1];
    rr_rig_config c;
    rr_rig_geometry g;
    rr_rig_profiles pr;
    rr_contact_table t, t2;
    rr_profile_points *slot[4];
    double bad = 0.0, *data, *data2, *work;
    long need_w, need_d, work_len, data_len;
    int k, st, st_check, want, which, point, i0, i1, wshort, all_empty = 1;

    rr_rig_config_default(&c);
    rr_rig_geometry_from(&c, &g);
    rr_rig_profiles_from(&c, &pr);
    g.table_rows = fz_range(in, 2, 3);
    g.table_half_range = fz_log(in, 1e-4, 4e-3);
    slot[0] = &pr.wheel;
    slot[1] = &pr.roller;
    slot[2] = &pr.wheel_right;
    slot[3] = &pr.roller_right;
    for (k = 0; k < 4; k++) {
        const int mode = fz_choice(in, 8);
        if (mode <= 2 || (k >= 2 && mode <= 4))
            continue;                                    /* not given */
        if (mode == 3) {
            slot[k]->n = -1;                            /* said given, and not */
            all_empty = 0;
            continue;
        }
        decode_points(in, k & 1, MAX_TPTS, py[k], pz[k], slot[k]);
        all_empty = 0;
        {   /* full size: x 5, and the wheel's taping line over the crown */
            const int n = slot[k]->n >= 1 && slot[k]->n <= MAX_TPTS + 1 ? slot[k]->n : 0;
            const int spoil = fz_choice(in, 6), at = n > 1 ? fz_range(in, 1, n - 1) : 0;
            int i;
            for (i = 0; i < n; i++) {
                py[k][i] *= 5.0;
                pz[k][i] *= 5.0;
            }
            if (n > 1 && spoil == 0)
                pz[k][at] = NAN;
            else if (n > 1 && spoil == 1)
                py[k][at] = py[k][at - 1] - fz_log(in, 1e-9, 1e-3);
            else if (n > 1 && spoil == 2)
                for (i = at; i < n; i++)
                    py[k][i] += fz_log(in, 1e-3, 2e-2);
            else if (spoil == 3)
                for (i = 0; i < n; i++) {
                    py[k][i] *= 1000.0;
                    pz[k][i] *= 1000.0;
                }
        }
        if (fz_choice(in, 32) == 0)
            slot[k]->z = NULL;
    }
    pr.wheel_scale = fz_near(in, 0.2, 4.0);
    pr.roller_scale = fz_near(in, 0.2, 4.0);
    pr.gauge = fz_near(in, 0.30, 1.2);

    /* the check against the oracle: scales and gauge, then the slots in order */
    {
        const int roller_given = pr.roller.n != 0 || pr.roller_right.n != 0;
        int opoint = -1, owhich = -1;
        if (!isfinite(pr.wheel_scale) || !isfinite(pr.roller_scale)
            || (roller_given && !isfinite(pr.gauge)))
            want = RR_ERR_NONFINITE;
        else if (!(pr.wheel_scale > 0.0) || !(pr.roller_scale > 0.0)
                 || (roller_given && !(pr.gauge > 0.0)))
            want = RR_ERR_PARAM;
        else
            for (want = RR_OK, k = 0; k < 4 && want == RR_OK; k++)
                if (slot[k]->n != 0 && (want = slot_oracle(slot[k], &opoint)) != RR_OK)
                    owhich = k;
        st_check = rr_rig_profiles_check(&pr, &which, &point);
        fz_note("rig profiles: n %d %d %d %d scales %.17g %.17g gauge %.17g rows %d half "
                "%.17g: check %d (%d, %d), oracle %d (%d, %d)", pr.wheel.n, pr.roller.n,
                pr.wheel_right.n, pr.roller_right.n, pr.wheel_scale, pr.roller_scale, pr.gauge,
                g.table_rows, g.table_half_range, st_check, which, point, want, owhich, opoint);
        if (st_check != want || (want != RR_OK && (which != owhich || point != opoint)))
            fz_fail("rr_rig_profiles_check: %d at (%d, %d), the oracle %d at (%d, %d)",
                    st_check, which, point, want, owhich, opoint);
    }
    need_w = rr_rig_profiles_work_len(&pr);
    need_d = rr_rig_table_data_len(&g);
    wshort = fz_choice(in, 16) == 0;
    work_len = need_w > 0 ? need_w - wshort : 0;
    data_len = need_d;
    work = fz_guarded((size_t)work_len * sizeof(double));
    data = fz_guarded((size_t)data_len * sizeof(double));
    data2 = fz_guarded((size_t)data_len * sizeof(double));
    i0 = fz_range(in, 0, g.table_rows);
    i1 = fz_choice(in, 2) == 0 ? fz_range(in, i0, g.table_rows) : g.table_rows;
    st = rr_rig_table_build_profiles_rows(&g, &pr, data, data_len, work, work_len, i0, i1, &t,
                                          &bad);
    fz_status(fn, st);
    fz_guard_ok(fn, data, (size_t)data_len * sizeof(double), "data");
    fz_guard_ok(fn, work, (size_t)work_len * sizeof(double), "work");
    if (st_check != RR_OK && st != st_check)
        fz_fail("%s: %d, but the profiles' check says %d", fn, st, st_check);
    if (wshort && (st >= 0 || (st_check == RR_OK && isfinite(g.table_half_range)
                               && g.table_half_range > 0.0 && st != RR_ERR_WORKSPACE)))
        fz_fail("%s: work one double short, status %d", fn, st);
    if (st < 0 && !isnan(bad)) {
        int i, row = 0;
        for (i = i0; i < i1; i++)
            row |= bad == t.y0 + i * t.dy;
        if (!row)
            fz_fail("%s: *bad_y = %.17g, not a row's shift", fn, bad);
    }
    if (st == RR_OK)
        fz_finite_n(fn, st, "row", data + (long)i0 * RR_CONTACT_TABLE_ROW,
                    (i1 - i0) * RR_CONTACT_TABLE_ROW);
    if (st == RR_OK && all_empty) {
        /* no profile given: rr_rig_table_build's rows, bit for bit */
        static double w2[RR_RIG_TABLE_WORK_LEN];
        if (rr_rig_table_build_rows(&g, data2, data_len, w2, RR_RIG_TABLE_WORK_LEN, i0, i1, &t2,
                                    NULL) != RR_OK)
            fz_fail("%s: OK with no profile, rr_rig_table_build not", fn);
        check_rows(fn, data, data2, i0, i1, "differ from rr_rig_table_build's");
    }
    fz_guard_free(work);
    fz_guard_free(data);
    fz_guard_free(data2);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    switch (fz_choice(&in, 8)) {
    case 0: run_analytic(&in, 0); break;
    case 1: run_analytic(&in, 1); break;
    case 2: case 3: run_surface(&in); break;
    case 4: case 5: run_profile_table(&in); break;
    case 6: run_rig_table(&in); break;
    default: run_rig_profiles(&in); break;
    }
    return 0;
}
