/* test_tables.c - the profile spline (rr_spline_fit), the analytic
 * profiles, and contact tables from points and from the rig's geometry
 * (rr_tables.h), with every error status. */
#include <limits.h>
#include <math.h>
#include <string.h>
#include "rr_test.h"
#include "rollerrig.h"

#define NP 41

static int all_nan(const double *v, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!isnan(v[i]))
            return 0;
    return 1;
}

/* z at y from the fitted coefficients, as Profile evaluates it */
static double fitted(const double *y, const double *z, const double *s, const double *c2,
                     const double *c3, int i, double yy)
{
    const double t = yy - y[i];
    return z[i] + t * (s[i] + t * (c2[i] + t * c3[i]));
}

static void test_spline_fit(void)
{
    double y[NP], z[NP], s[NP], c2[NP], c3[NP], d2[NP], w[NP], m[NP];
    rr_spline sp;
    int i, end;
    for (i = 0; i < NP; i++)
        y[i] = -0.02 + 0.001 * i + 1e-5 * i * i;   /* uneven knots */
    /* a cubic: not-a-knot reproduces it (and its z''); natural ends have z'' = 0 */
    for (i = 0; i < NP; i++)
        z[i] = 1e-3 + 0.1 * y[i] - 3.0 * y[i] * y[i] + 40.0 * y[i] * y[i] * y[i];
    CHECK_STATUS(rr_spline_fit(NP, y, z, RR_SPLINE_NOT_A_KNOT, s, c2, c3, w), RR_OK,
                 "fit not-a-knot");
    for (i = 0; i < NP; i++)
        CHECK_CLOSE(s[i], 0.1 - 6.0 * y[i] + 120.0 * y[i] * y[i], 1e-12, 1e-10,
                    "not-a-knot: a cubic's slope");
    CHECK_CLOSE(fitted(y, z, s, c2, c3, 7, 0.5 * (y[7] + y[8])),
                1e-3 + 0.1 * 0.5 * (y[7] + y[8]) - 3.0 * pow(0.5 * (y[7] + y[8]), 2)
                + 40.0 * pow(0.5 * (y[7] + y[8]), 3), 1e-15, 1e-12, "not-a-knot: a cubic's value");
    CHECK_STATUS(rr_spline_knot_d2(NP, y, c2, c3, d2), RR_OK, "knot d2");
    for (i = 0; i < NP; i++)
        CHECK_CLOSE(d2[i], -6.0 + 240.0 * y[i], 1e-9, 1e-9, "not-a-knot: a cubic's z''");
    /* the knot second derivatives make the same curve for rr_spline_eval */
    sp.n = NP; sp.s = y; sp.z = z; sp.m = d2;
    for (i = 0; i < NP - 1; i++) {
        const double yy = y[i] + 0.3 * (y[i + 1] - y[i]);
        double v;
        rr_spline_eval(&sp, yy, &v, NULL, NULL);
        CHECK_CLOSE(v, fitted(y, z, s, c2, c3, i, yy), 1e-16, 1e-12, "knot d2: same curve");
    }
    CHECK_STATUS(rr_spline_fit(NP, y, z, RR_SPLINE_NATURAL, s, c2, c3, w), RR_OK, "fit natural");
    rr_spline_knot_d2(NP, y, c2, c3, d2);
    CHECK_CLOSE(d2[0], 0.0, 1e-9, 0.0, "natural: z''(y_0) = 0");
    CHECK_CLOSE(d2[NP - 1], 0.0, 1e-9, 0.0, "natural: z''(y_n-1) = 0");
    /* natural: the same curve as the geometry's own natural spline */
    CHECK_STATUS(rr_spline_init(NP, y, z, m, w), RR_OK, "rr_spline_init");
    for (i = 0; i < NP; i++)
        CHECK_CLOSE(d2[i], m[i], 1e-9, 1e-9, "natural: rr_spline_init's m");
    /* interpolation at the knots, both ends */
    for (end = 0; end < 2; end++) {
        rr_spline_fit(NP, y, z, end, s, c2, c3, w);
        for (i = 0; i < NP - 1; i++)
            CHECK_CLOSE(fitted(y, z, s, c2, c3, i, y[i + 1]), z[i + 1], 1e-16, 1e-12,
                        "fit: through the next knot");
    }

    /* errors: outputs NaN */
    CHECK_STATUS(rr_spline_fit(3, y, z, 0, s, c2, c3, w), RR_ERR_PARAM, "fit: n = 3");
    CHECK(all_nan(s, 3), "fit: n = 3 -> NaN");
    CHECK_STATUS(rr_spline_fit(RR_SPLINE_MAX_POINTS + 1, y, z, 0, s, c2, c3, w), RR_ERR_PARAM,
                 "fit: n too large");
    CHECK_STATUS(rr_spline_fit(-5, y, z, 0, s, c2, c3, w), RR_ERR_PARAM, "fit: n < 0");
    CHECK_STATUS(rr_spline_fit(NP, NULL, z, 0, s, c2, c3, w), RR_ERR_NULL, "fit: y NULL");
    CHECK(all_nan(s, NP) && all_nan(c2, NP - 1) && all_nan(c3, NP - 1), "fit: NULL -> NaN");
    CHECK_STATUS(rr_spline_fit(NP, y, NULL, 0, s, c2, c3, w), RR_ERR_NULL, "fit: z NULL");
    CHECK_STATUS(rr_spline_fit(NP, y, z, 0, NULL, c2, c3, w), RR_ERR_WORKSPACE, "fit: slope NULL");
    CHECK_STATUS(rr_spline_fit(NP, y, z, 0, s, NULL, c3, w), RR_ERR_WORKSPACE, "fit: c2 NULL");
    CHECK_STATUS(rr_spline_fit(NP, y, z, 0, s, c2, NULL, w), RR_ERR_WORKSPACE, "fit: c3 NULL");
    CHECK_STATUS(rr_spline_fit(NP, y, z, 0, s, c2, c3, NULL), RR_ERR_WORKSPACE, "fit: work NULL");
    CHECK_STATUS(rr_spline_fit(NP, y, z, 2, s, c2, c3, w), RR_ERR_PARAM, "fit: end unknown");
    CHECK_STATUS(rr_spline_fit(NP, y, z, -1, s, c2, c3, w), RR_ERR_PARAM, "fit: end -1");
    z[5] = NAN;
    CHECK_STATUS(rr_spline_fit(NP, y, z, 0, s, c2, c3, w), RR_ERR_NONFINITE, "fit: NaN z");
    CHECK(all_nan(s, NP), "fit: NaN -> NaN");
    z[5] = 0.0;
    y[9] = INFINITY;
    CHECK_STATUS(rr_spline_fit(NP, y, z, 1, s, c2, c3, w), RR_ERR_NONFINITE, "fit: inf y");
    y[9] = y[8];
    CHECK_STATUS(rr_spline_fit(NP, y, z, 0, s, c2, c3, w), RR_ERR_GEOMETRY, "fit: repeated y");
    y[9] = y[8] - 1e-3;
    CHECK_STATUS(rr_spline_fit(NP, y, z, 1, s, c2, c3, w), RR_ERR_GEOMETRY, "fit: y decreasing");
    for (i = 0; i < NP; i++) {
        y[i] = i * 1e-300;                 /* finite, increasing, but z/h overflows */
        z[i] = i % 2 ? 1e300 : -1e300;
    }
    CHECK_STATUS(rr_spline_fit(NP, y, z, 0, s, c2, c3, w), RR_ERR_RANGE, "fit: overflow");
    CHECK(all_nan(s, NP) && all_nan(c2, NP - 1) && all_nan(c3, NP - 1), "fit: overflow -> NaN");
    for (i = 0; i < NP; i++) {
        y[i] = i < NP - 1 ? i * 1e-3 : 1e150;   /* fuzz_spline_fit: h^3 overflows, c3 = 0 */
        z[i] = 3.5e-4;
    }
    z[1] = 0.0;
    CHECK_STATUS(rr_spline_fit(NP, y, z, 1, s, c2, c3, w), RR_ERR_RANGE, "fit: h^3 overflows");
    CHECK(all_nan(s, NP) && all_nan(c2, NP - 1) && all_nan(c3, NP - 1), "fit: h^3 -> NaN");
    {
        /* fuzz_spline_fit: finite coefficients, but over the 1000 m last
         * interval c2 h^2 and c3 h^3 each overflow (their sum does not) */
        const double yy[4] = {0.0, 0.00097855699711994477, 0.010978554118196935,
                              1000.0109785541182};
        const double zz[4] = {-4.017429170375668e+56, 1e300, 0.0073333333333333358, 1e300};
        CHECK_STATUS(rr_spline_fit(4, yy, zz, 0, s, c2, c3, w), RR_ERR_RANGE,
                     "fit: c2 h^2 overflows");
        CHECK(all_nan(s, 4) && all_nan(c2, 3) && all_nan(c3, 3), "fit: c2 h^2 -> NaN");
    }
    {
        /* fuzz_spline_fit: values near 1e-187 over intervals of 8e71 m:
         * c2 (about 1e-310) and c3 (1e-382) underflow, and the spline they
         * gave missed its second knot by 2e5 times its value */
        const double yy[5] = {7.845016548974284e-187, 7.7756037293369766e+71,
                              1.5551188174766575e+72, 2.3326772620196172e+72,
                              3.1102357065625769e+72};
        const double zz[5] = {1.7024806598384478e-166, 1.5804925908410008e-187,
                              1.5685542162784258e-187, 1.580497508713229e-187,
                              1.5804947031972617e-187};
        CHECK_STATUS(rr_spline_fit(5, yy, zz, 0, s, c2, c3, w), RR_ERR_RANGE,
                     "fit: coefficients underflow");
        CHECK(all_nan(s, 5) && all_nan(c2, 4) && all_nan(c3, 4), "fit: underflow -> NaN");
    }
    {
        /* but a flat profile's subnormal slopes lose nothing the values
         * hold (a cone of 2e-313 rad, the property tests' Profile.conical;
         * refused by the first form of the check above) */
        double yy[5], zz[5];
        for (i = 0; i < 5; i++) {
            yy[i] = -0.0625 + 0.03125 * i;
            zz[i] = 2.2250738585e-313 * yy[i];
        }
        CHECK_STATUS(rr_spline_fit(5, yy, zz, 0, s, c2, c3, w), RR_OK, "fit: a subnormal cone");
    }
    {
        /* fuzz_spline_fit: c3 finite but 6 c3 infinite, times t = 0 NaN */
        double cc2[NP], cc3[NP];
        for (i = 0; i < NP; i++) {
            y[i] = i * 1e-5;
            cc2[i] = 0.0;
            cc3[i] = 1e308;
        }
        CHECK_STATUS(rr_spline_knot_d2(NP, y, cc2, cc3, d2), RR_ERR_RANGE,
                     "knot d2: 6 c3 overflows");
        CHECK(all_nan(d2, NP), "knot d2: overflow -> NaN");
    }
    CHECK_STATUS(rr_spline_knot_d2(3, y, c2, c3, d2), RR_ERR_PARAM, "knot d2: n = 3");
    CHECK_STATUS(rr_spline_knot_d2(NP, NULL, c2, c3, d2), RR_ERR_NULL, "knot d2: y NULL");
    CHECK_STATUS(rr_spline_knot_d2(NP, y, c2, NULL, d2), RR_ERR_NULL, "knot d2: c3 NULL");
    CHECK_STATUS(rr_spline_knot_d2(NP, y, c2, c3, NULL), RR_ERR_WORKSPACE, "knot d2: d2 NULL");
}

static void test_analytic_profiles(void)
{
    double y[NP], z[NP];
    int i;
    CHECK_STATUS(rr_profile_conical(0.05, -0.015, 0.015, NP, y, z), RR_OK, "conical");
    CHECK(y[0] == -0.015 && y[NP - 1] == 0.015, "conical: the range's ends exactly");
    CHECK(y[20] == 20.0 * (0.03 / 40.0) + -0.015, "conical: linspace's i step + y_min");
    for (i = 0; i < NP; i++)
        CHECK(z[i] == -tan(0.05) * y[i], "conical: z = -tan(alpha) y");
    CHECK_STATUS(rr_profile_crowned(0.06, -0.015, 0.015, NP, y, z), RR_OK, "crowned");
    for (i = 0; i < NP; i++)
        CHECK_CLOSE(z[i], 0.06 - sqrt(0.06 * 0.06 - y[i] * y[i]), 1e-17, 1e-12,
                    "crowned: R - sqrt(R^2 - y^2)");
    CHECK(z[20] == 0.0 && z[0] == z[NP - 1], "crowned: symmetric, 0 at the centre");
    CHECK_STATUS(rr_profile_crowned(0.0, -0.015, 0.015, NP, y, z), RR_OK, "cylinder");
    for (i = 0; i < NP; i++)
        CHECK(z[i] == 0.0, "cylinder: z = 0");

    /* errors */
    CHECK_STATUS(rr_profile_conical(0.05, -0.015, 0.015, NP, NULL, z), RR_ERR_NULL, "conical: y NULL");
    CHECK(all_nan(z, NP), "conical: NULL -> NaN");
    CHECK_STATUS(rr_profile_conical(0.05, -0.015, 0.015, NP, y, NULL), RR_ERR_NULL, "conical: z NULL");
    CHECK_STATUS(rr_profile_conical(NAN, -0.015, 0.015, NP, y, z), RR_ERR_NONFINITE, "conical: NaN alpha");
    CHECK(all_nan(y, NP) && all_nan(z, NP), "conical: NaN -> NaN");
    CHECK_STATUS(rr_profile_conical(RR_PI / 2.0, -0.015, 0.015, NP, y, z), RR_ERR_PARAM,
                 "conical: alpha = pi/2");
    CHECK_STATUS(rr_profile_conical(0.05, -INFINITY, 0.015, NP, y, z), RR_ERR_NONFINITE,
                 "conical: infinite range");
    CHECK_STATUS(rr_profile_conical(0.05, 0.015, -0.015, NP, y, z), RR_ERR_PARAM, "conical: y_min > y_max");
    CHECK_STATUS(rr_profile_conical(0.05, -2.5, 0.015, NP, y, z), RR_ERR_PARAM, "conical: beyond 2 m");
    CHECK_STATUS(rr_profile_conical(0.05, 0.0, 0.9e-3, NP, y, z), RR_ERR_PARAM, "conical: under 1 mm");
    CHECK_STATUS(rr_profile_conical(0.05, -0.015, 0.015, 3, y, z), RR_ERR_PARAM, "conical: n = 3");
    CHECK_STATUS(rr_profile_conical(0.05, -0.015, 0.015, RR_SPLINE_MAX_POINTS + 1, y, z),
                 RR_ERR_PARAM, "conical: n too large");
    CHECK_STATUS(rr_profile_crowned(-0.06, -0.015, 0.015, NP, y, z), RR_ERR_PARAM, "crowned: R < 0");
    CHECK_STATUS(rr_profile_crowned(NAN, -0.015, 0.015, NP, y, z), RR_ERR_NONFINITE, "crowned: NaN R");
    CHECK_STATUS(rr_profile_crowned(0.015, -0.015, 0.01, NP, y, z), RR_ERR_GEOMETRY,
                 "crowned: range reaches R");
    CHECK(all_nan(y, NP) && all_nan(z, NP), "crowned: error -> NaN");
    CHECK_STATUS(rr_profile_crowned(0.06, -0.015, 0.015, NP, y, NULL), RR_ERR_NULL, "crowned: z NULL");
    CHECK_STATUS(rr_profile_crowned(0.06, 0.015, 0.015, NP, y, z), RR_ERR_PARAM, "crowned: empty range");
}

/* the rig's default geometry (rig_default.toml) */
static rr_rig_geometry rig_geometry(void)
{
    rr_rig_geometry g;
    g.wheel_radius = 0.092;
    g.roller_radius = 0.160;
    g.profile_half_width = 0.015;
    g.cone_angle = atan(0.05);
    g.crown_radius = 0.060;
    g.contact_half_spacing = 0.15;
    g.table_half_range = 0.008;
    g.table_rows = 161;
    return g;
}

#define ROWS 161
static double data[RR_CONTACT_TABLE_ROW * ROWS], data2[RR_CONTACT_TABLE_ROW * ROWS];
static double work[RR_RIG_TABLE_WORK_LEN];

static void test_rig_table(void)
{
    rr_rig_geometry g = rig_geometry(), b;
    rr_contact_table t, t2;
    rr_profile_points wheel, roller;
    rr_profile_placement place;
    rr_search_opts o;
    rr_wheelset_pose pose;
    rr_contact_point cl, cr;
    double wy[RR_RIG_PROFILE_POINTS], wz[RR_RIG_PROFILE_POINTS];
    double ry[RR_RIG_PROFILE_POINTS], rz[RR_RIG_PROFILE_POINTS], bad_y, zup[NP], mup[NP];
    const long len = rr_rig_table_data_len(&g);

    CHECK(len == (long)RR_CONTACT_TABLE_ROW * ROWS, "rig table: data length");
    CHECK_STATUS(rr_rig_table_build(&g, data, len, work, RR_RIG_TABLE_WORK_LEN, &t, &bad_y),
                 RR_OK, "rig table");
    CHECK(t.n == ROWS && t.y0 == -0.008 && t.dy == 0.016 / 160.0 && t.data == data,
          "rig table: y0, dy, n, data");
    CHECK(isnan(bad_y), "rig table: no bad shift");
    CHECK_STATUS(rr_contact_table_lookup(&t, 0.0, &pose, NULL, &cl, &cr), RR_OK, "lookup");
    CHECK_CLOSE(pose.roll, 0.0, 1e-15, 0.0, "centred: no roll");
    /* the cone touches the crown where their slopes match: s ~ R_crown tan(alpha) */
    CHECK_CLOSE(cl.r, 0.092 + 0.05 * 0.06 * 0.05, 2e-6, 0.0, "centred: r0 + tan(alpha) s");
    CHECK_CLOSE(cl.r, cr.r, 1e-15, 0.0, "centred: equal radii");
    rr_contact_table_lookup(&t, 0.004, &pose, NULL, &cl, &cr);
    CHECK_CLOSE(cl.r - cr.r, 2.0 * 0.05 * 0.004, 0.0, 0.1, "radius difference ~ 2 lambda y");

    /* the same table from the points and rr_profile_table_build, bit for bit */
    rr_profile_conical(g.cone_angle, -0.015, 0.015, RR_RIG_PROFILE_POINTS, wy, wz);
    rr_profile_crowned(g.crown_radius, -0.015, 0.015, RR_RIG_PROFILE_POINTS, ry, rz);
    wheel.n = roller.n = RR_RIG_PROFILE_POINTS;
    wheel.y = wy; wheel.z = wz; roller.y = ry; roller.z = rz;
    wheel.end = roller.end = RR_SPLINE_NOT_A_KNOT;
    place.wheel_radius = 0.092;
    place.roller_radius = 0.160;
    place.wheel_y = place.roller_y = 0.15;
    rr_search_opts_default(&o);
    t2.y0 = t.y0; t2.dy = t.dy; t2.n = ROWS; t2.data = data2;
    CHECK(rr_profile_table_work_len(RR_RIG_PROFILE_POINTS, RR_RIG_PROFILE_POINTS)
          <= RR_RIG_TABLE_WORK_LEN, "work length");
    CHECK_STATUS(rr_profile_table_build(&wheel, &roller, &place, &o, &t2, len, work,
                                        RR_RIG_TABLE_WORK_LEN, &bad_y), RR_OK, "points table");
    CHECK(memcmp(data, data2, sizeof data) == 0, "points table == rig table, bitwise");

    /* rr_profile_surface: heights up */
    wheel.n = NP;
    CHECK_STATUS(rr_profile_surface(&wheel, zup, mup, work), RR_OK, "surface");
    CHECK(zup[3] == -wz[3], "surface: -z");
    CHECK_STATUS(rr_profile_surface(NULL, zup, mup, work), RR_ERR_NULL, "surface: NULL");
    CHECK_STATUS(rr_profile_surface(&wheel, zup, NULL, work), RR_ERR_WORKSPACE, "surface: no mup");
    CHECK(all_nan(zup, NP), "surface: error -> NaN");
    wheel.end = 7;
    CHECK_STATUS(rr_profile_surface(&wheel, zup, mup, work), RR_ERR_PARAM, "surface: bad end");
    wheel.end = RR_SPLINE_NOT_A_KNOT;
    /* fuzz_tables: n out of range refused before work + 3 n (2 INT_MIN
     * overflowed), nothing written */
    zup[0] = mup[0] = 7.0;
    wheel.n = INT_MIN;
    CHECK_STATUS(rr_profile_surface(&wheel, zup, mup, work), RR_ERR_PARAM, "surface: n INT_MIN");
    wheel.n = INT_MAX;
    CHECK_STATUS(rr_profile_surface(&wheel, zup, mup, work), RR_ERR_PARAM, "surface: n INT_MAX");
    CHECK(zup[0] == 7.0 && mup[0] == 7.0, "surface: n out of range writes nothing");
    wheel.n = 3;
    CHECK_STATUS(rr_profile_surface(&wheel, zup, mup, work), RR_ERR_PARAM, "surface: n = 3");
    CHECK(all_nan(zup, 3) && all_nan(mup, 3), "surface: n = 3 -> NaN");
    wheel.n = RR_RIG_PROFILE_POINTS;

    /* rr_profile_table_build's errors */
#define PT(w, r, p, oo, tt, dl, wk, wl) rr_profile_table_build(w, r, p, oo, tt, dl, wk, wl, &bad_y)
    CHECK_STATUS(PT(NULL, &roller, &place, &o, &t2, len, work, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_NULL, "points table: wheel NULL");
    CHECK_STATUS(PT(&wheel, &roller, &place, NULL, &t2, len, work, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_NULL, "points table: opts NULL");
    CHECK_STATUS(PT(&wheel, &roller, NULL, &o, &t2, len, work, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_NULL, "points table: placement NULL");
    CHECK_STATUS(PT(&wheel, &roller, &place, &o, NULL, len, work, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_NULL, "points table: table NULL");
    CHECK_STATUS(PT(&wheel, &roller, &place, &o, &t2, len - 1, work, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_WORKSPACE, "points table: data too short");
    CHECK_STATUS(PT(&wheel, &roller, &place, &o, &t2, len, work, 100), RR_ERR_WORKSPACE,
                 "points table: work too short");
    CHECK_STATUS(PT(&wheel, &roller, &place, &o, &t2, len, NULL, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_WORKSPACE, "points table: work NULL");
    roller.y = NULL;
    CHECK_STATUS(PT(&wheel, &roller, &place, &o, &t2, len, work, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_NULL, "points table: roller y NULL");
    roller.y = ry;
    roller.n = 2;
    CHECK_STATUS(PT(&wheel, &roller, &place, &o, &t2, len, work, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_PARAM, "points table: 2 roller points");
    CHECK(rr_profile_table_work_len(2, 10) == 0, "work length: bad count");
    roller.n = RR_RIG_PROFILE_POINTS;
    place.roller_radius = 0.0;
    CHECK_STATUS(PT(&wheel, &roller, &place, &o, &t2, len, work, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_PARAM, "points table: R0 = 0");
    place.roller_radius = 0.16;
    place.wheel_y = NAN;
    CHECK_STATUS(PT(&wheel, &roller, &place, &o, &t2, len, work, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_NONFINITE, "points table: NaN wheel_y");
    place.wheel_y = 0.15;
    wz[7] = wz[8];
    wy[7] = wy[8];
    CHECK_STATUS(PT(&wheel, &roller, &place, &o, &t2, len, work, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_GEOMETRY, "points table: repeated y");
    rr_profile_conical(g.cone_angle, -0.015, 0.015, RR_RIG_PROFILE_POINTS, wy, wz);
    t2.n = 1;
    CHECK_STATUS(PT(&wheel, &roller, &place, &o, &t2, len, work, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_PARAM, "points table: one row");
    t2.n = ROWS;
    t2.dy = -1.0;
    CHECK_STATUS(PT(&wheel, &roller, &place, &o, &t2, len, work, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_PARAM, "points table: dy < 0");
    t2.dy = t.dy;
    o.nsamples = 2;
    CHECK_STATUS(PT(&wheel, &roller, &place, &o, &t2, len, work, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_PARAM, "points table: nsamples = 2");
    rr_search_opts_default(&o);
    t2.y0 = -0.05;                          /* the wheel leaves its roller */
    CHECK_STATUS(PT(&wheel, &roller, &place, &o, &t2, len, work, RR_RIG_TABLE_WORK_LEN),
                 RR_ERR_GEOMETRY, "points table: off the roller");
    CHECK(bad_y == -0.05, "points table: the bad shift");
#undef PT

    /* rr_rig_table_build's errors */
#define RT(gg, d, dl, wk, wl) rr_rig_table_build(gg, d, dl, wk, wl, &t, &bad_y)
    CHECK_STATUS(RT(NULL, data, len, work, RR_RIG_TABLE_WORK_LEN), RR_ERR_NULL, "rig: g NULL");
    CHECK(rr_rig_table_data_len(NULL) == 0, "rig: data length of NULL");
    CHECK_STATUS(rr_rig_table_build(&g, data, len, work, RR_RIG_TABLE_WORK_LEN, NULL, &bad_y),
                 RR_ERR_NULL, "rig: t NULL");
    CHECK_STATUS(RT(&g, NULL, len, work, RR_RIG_TABLE_WORK_LEN), RR_ERR_WORKSPACE, "rig: data NULL");
    CHECK_STATUS(RT(&g, data, len - 1, work, RR_RIG_TABLE_WORK_LEN), RR_ERR_WORKSPACE,
                 "rig: data too short");
    CHECK_STATUS(RT(&g, data, len, work, RR_RIG_TABLE_WORK_LEN - 1), RR_ERR_WORKSPACE,
                 "rig: work too short");
    CHECK_STATUS(RT(&g, data, len, NULL, RR_RIG_TABLE_WORK_LEN), RR_ERR_WORKSPACE, "rig: work NULL");
    b = g; b.crown_radius = NAN;
    CHECK_STATUS(RT(&b, data, len, work, RR_RIG_TABLE_WORK_LEN), RR_ERR_NONFINITE, "rig: NaN crown");
    b = g; b.table_half_range = INFINITY;
    CHECK_STATUS(RT(&b, data, len, work, RR_RIG_TABLE_WORK_LEN), RR_ERR_NONFINITE, "rig: inf reach");
    b = g; b.table_rows = 1;
    CHECK_STATUS(RT(&b, data, len, work, RR_RIG_TABLE_WORK_LEN), RR_ERR_PARAM, "rig: one row");
    CHECK(rr_rig_table_data_len(&b) == 0, "rig: data length of one row");
    b = g; b.table_rows = RR_RIG_TABLE_MAX_ROWS + 1;
    CHECK_STATUS(RT(&b, data, len, work, RR_RIG_TABLE_WORK_LEN), RR_ERR_PARAM, "rig: too many rows");
    b = g; b.wheel_radius = -0.1;
    CHECK_STATUS(RT(&b, data, len, work, RR_RIG_TABLE_WORK_LEN), RR_ERR_PARAM, "rig: r0 < 0");
    b = g; b.roller_radius = 0.0;
    CHECK_STATUS(RT(&b, data, len, work, RR_RIG_TABLE_WORK_LEN), RR_ERR_PARAM, "rig: R0 = 0");
    b = g; b.profile_half_width = 0.0;
    CHECK_STATUS(RT(&b, data, len, work, RR_RIG_TABLE_WORK_LEN), RR_ERR_PARAM, "rig: half width 0");
    b = g; b.table_half_range = -0.008;
    CHECK_STATUS(RT(&b, data, len, work, RR_RIG_TABLE_WORK_LEN), RR_ERR_PARAM, "rig: reach < 0");
    b = g; b.cone_angle = 2.0;
    CHECK_STATUS(RT(&b, data, len, work, RR_RIG_TABLE_WORK_LEN), RR_ERR_PARAM, "rig: alpha 2 rad");
    b = g; b.crown_radius = 0.01;
    CHECK_STATUS(RT(&b, data, len, work, RR_RIG_TABLE_WORK_LEN), RR_ERR_GEOMETRY,
                 "rig: crown inside the half width");
    b = g; b.table_half_range = 0.05;
    CHECK_STATUS(RT(&b, data, len, work, RR_RIG_TABLE_WORK_LEN), RR_ERR_GEOMETRY,
                 "rig: the wheel leaves its roller");
    CHECK(bad_y == -0.05, "rig: the bad shift");
#undef RT
}

int main(void)
{
    test_spline_fit();
    test_analytic_profiles();
    test_rig_table();
    return rr_test_summary();
}
