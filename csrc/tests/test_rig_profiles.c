/* test_rig_profiles.c - the rig's table on profiles given as points
 * (rr_rig_profiles, rr_rig_table_build_profiles, rr_rig_profiles_check,
 * rr_rig_profiles_from).  The reference is rr_rig_table_build: the cone and
 * the crown given as points at scale 1 must give its table bit for bit. */
#include <math.h>
#include <string.h>
#include "rr_test.h"
#include "geometry/rr_tables.h"
#include "rig/rr_rig_params.h"
#include "fmu/rr_fmu.h"
#include <stdlib.h>

enum { N = RR_RIG_PROFILE_POINTS, ROWS = 161 };
static double data[RR_CONTACT_TABLE_ROW * ROWS], data2[RR_CONTACT_TABLE_ROW * ROWS];
static double work[RR_RIG_TABLE_WORK_LEN], pwork[40 * N];
static double wy[N], wz[N], ry[N], rz[N], by[N], bz[N];

static rr_rig_geometry geometry(void)
{
    rr_rig_config c;
    rr_rig_geometry g;
    rr_rig_config_default(&c);
    rr_rig_geometry_from(&c, &g);
    return g;
}

static rr_profile_points points(int n, const double *y, const double *z)
{
    rr_profile_points p;
    p.n = n;
    p.y = y;
    p.z = z;
    p.end = RR_SPLINE_NOT_A_KNOT;
    return p;
}

/* the rig's defaults: no profile given, scale 0.2, gauge 0.287 */
static rr_rig_profiles none(void)
{
    rr_rig_config c;
    rr_rig_profiles pr;
    rr_rig_config_default(&c);
    rr_rig_profiles_from(&c, &pr);
    return pr;
}

static void test_same_table(void)
{
    const rr_rig_geometry g = geometry();
    const long len = rr_rig_table_data_len(&g);
    rr_rig_profiles pr = none();
    rr_contact_table t, t2;
    double bad_y;

    CHECK(pr.wheel.n == 0 && pr.roller.n == 0 && pr.wheel_right.n == 0 && pr.roller_right.n == 0
          && pr.wheel_scale == 0.2 && pr.roller_scale == 0.2 && pr.gauge == 0.287,
          "profiles_from: the defaults");
    CHECK_STATUS(rr_rig_table_build(&g, data, len, work, RR_RIG_TABLE_WORK_LEN, &t, NULL), RR_OK,
                 "the cone's table");
    CHECK(rr_rig_profiles_work_len(&pr) <= (long)(sizeof pwork / sizeof *pwork), "work");
    CHECK_STATUS(rr_rig_table_build_profiles(&g, &pr, data2, len, pwork,
                                             rr_rig_profiles_work_len(&pr), &t2, &bad_y),
                 RR_OK, "no points");
    CHECK(memcmp(data, data2, sizeof data) == 0 && t.y0 == t2.y0 && t.dy == t2.dy,
          "no points: rr_rig_table_build's table, bitwise");

    /* the cone and the crown as points at scale 1, the right side the same points:
     * the same table; the crown's top at y = 0 under gauge / 2 = the half spacing */
    rr_profile_conical(g.cone_angle, -g.profile_half_width, g.profile_half_width, N, wy, wz);
    rr_profile_crowned(g.crown_radius, -g.profile_half_width, g.profile_half_width, N, ry, rz);
    pr.wheel = pr.wheel_right = points(N, wy, wz);
    pr.roller = pr.roller_right = points(N, ry, rz);
    pr.wheel_scale = pr.roller_scale = 1.0;
    pr.gauge = 2.0 * g.contact_half_spacing;
    memset(data2, 0, sizeof data2);
    CHECK_STATUS(rr_rig_table_build_profiles(&g, &pr, data2, len, pwork,
                                             rr_rig_profiles_work_len(&pr), &t2, &bad_y),
                 RR_OK, "points");
    CHECK(memcmp(data, data2, sizeof data) == 0, "points at scale 1: the same table, bitwise");
    CHECK(isnan(bad_y), "no bad shift");

    /* the points at 5 x size and scale 0.2: the same table to rounding */
    {
        static double y5[N], z5[N], q5[N], p5[N];
        int i;
        double most = 0.0;
        for (i = 0; i < N; i++) {
            y5[i] = 5.0 * wy[i];
            z5[i] = 5.0 * wz[i];
            q5[i] = 5.0 * ry[i];
            p5[i] = 5.0 * rz[i];
        }
        pr.wheel = points(N, y5, z5);
        pr.roller = points(N, q5, p5);
        pr.wheel_right.n = pr.roller_right.n = 0;
        pr.wheel_scale = pr.roller_scale = 0.2;
        CHECK_STATUS(rr_rig_table_build_profiles(&g, &pr, data2, len, pwork,
                                                 rr_rig_profiles_work_len(&pr), &t2, &bad_y),
                     RR_OK, "scaled points");
        for (i = 0; i < (int)(sizeof data / sizeof *data); i++)
            most = fmax(most, fabs(data[i] - data2[i]) / (1.0 + fabs(data[i])));
        CHECK(most < 1e-6, "scaled points: the same table to the search's tolerance");
    }
}

static void test_bad_profiles(void)
{
    const rr_rig_geometry g = geometry();
    const long len = rr_rig_table_data_len(&g);
    rr_rig_profiles pr;
    rr_contact_table t;
    rr_rig_config c;
    double bad_y;
    int which, point, i;

#define BUILD(p) rr_rig_table_build_profiles(&g, p, data2, len, pwork, \
                                             (long)(sizeof pwork / sizeof *pwork), &t, &bad_y)
    rr_profile_conical(g.cone_angle, -0.075, 0.075, N, wy, wz);    /* full size */
    rr_profile_crowned(0.3, -0.075, 0.075, N, ry, rz);
    memcpy(by, wy, sizeof by);
    memcpy(bz, wz, sizeof bz);
    pr = none();
    pr.wheel = points(N, by, bz);
    pr.roller = points(N, ry, rz);
    pr.gauge = 0.30;          /* the crown's top (y = 0) under the wheel's origin */
    CHECK_STATUS(BUILD(&pr), RR_OK, "full-size cone on a full-size crown, scaled");

    bz[7] = NAN;
    CHECK_STATUS(rr_rig_profiles_check(&pr, &which, &point), RR_ERR_NONFINITE, "NaN");
    CHECK(which == RR_RIG_WHEEL && point == 7, "NaN: the wheel's point 7");
    CHECK_STATUS(BUILD(&pr), RR_ERR_NONFINITE, "NaN: refused by the build");
    bz[7] = wz[7];
    by[9] = by[8];                                           /* a vertical segment */
    CHECK_STATUS(rr_rig_profiles_check(&pr, &which, &point), RR_ERR_GEOMETRY, "vertical");
    CHECK(which == RR_RIG_WHEEL && point == 9, "vertical: point 9");
    by[9] = by[8] - 1e-4;                                    /* overhanging */
    CHECK_STATUS(rr_rig_profiles_check(&pr, &which, &point), RR_ERR_GEOMETRY, "overhang");
    by[9] = wy[9];
    pr.wheel.n = 4;                         /* 4 points 1.25 mm apart: fine; a gap: */
    by[3] = by[2] + 0.006;
    CHECK_STATUS(rr_rig_profiles_check(&pr, &which, &point), RR_ERR_GEOMETRY, "a 6 mm gap");
    CHECK(point == 3, "gap: at point 3");
    by[3] = wy[3];
    pr.wheel.n = N;
    for (i = 0; i < N; i++)                                  /* millimetres as metres */
        by[i] = 1000.0 * wy[i];
    CHECK_STATUS(rr_rig_profiles_check(&pr, &which, &point), RR_ERR_PARAM, "mm as metres");
    CHECK(which == RR_RIG_WHEEL && point == 0, "mm as metres: -75 at point 0");
    pr.wheel.n = 4;
    by[0] = 0.0; by[1] = 1.0e-3; by[2] = 2.0e-3; by[3] = 3.0;
    CHECK_STATUS(rr_rig_profiles_check(&pr, &which, &point), RR_ERR_PARAM, "3 m");
    CHECK(point == 3, "3 m: point 3");
    by[0] = 0.0; by[1] = 1e-4; by[2] = 2e-4; by[3] = 3e-4;   /* metres as millimetres */
    CHECK_STATUS(rr_rig_profiles_check(&pr, &which, &point), RR_ERR_PARAM, "0.3 mm wide");
    CHECK(which == RR_RIG_WHEEL && point == -1, "too narrow: the whole profile");
    bz[0] = 2.5;
    CHECK_STATUS(rr_rig_profiles_check(&pr, &which, &point), RR_ERR_PARAM, "z 2.5 m");
    CHECK(point == 0, "z 2.5 m: point 0");
    memcpy(by, wy, sizeof by);
    memcpy(bz, wz, sizeof bz);
    pr.wheel.n = N;
    pr.wheel.end = 7;
    CHECK_STATUS(rr_rig_profiles_check(&pr, &which, &point), RR_ERR_PARAM, "end condition");
    pr.wheel.end = RR_SPLINE_NOT_A_KNOT;
    pr.wheel.n = 3;
    CHECK_STATUS(rr_rig_profiles_check(&pr, &which, &point), RR_ERR_PARAM, "3 points");
    pr.wheel.n = N;
    pr.roller_right.n = 5;
    pr.roller_right.y = NULL;
    CHECK_STATUS(rr_rig_profiles_check(&pr, &which, &point), RR_ERR_NULL, "NULL points");
    CHECK(which == RR_RIG_ROLLER_RIGHT, "NULL: the right roller");
    pr.roller_right.n = 0;
    pr.wheel_scale = 0.0;
    CHECK_STATUS(rr_rig_profiles_check(&pr, &which, &point), RR_ERR_PARAM, "scale 0");
    CHECK(which == -1, "scale: no profile");
    pr.wheel_scale = 0.2;
    pr.gauge = NAN;
    CHECK_STATUS(BUILD(&pr), RR_ERR_NONFINITE, "gauge NaN");
    pr.gauge = 0.30;
    CHECK_STATUS(rr_rig_profiles_check(NULL, &which, &point), RR_ERR_NULL, "NULL");
    CHECK_STATUS(BUILD(NULL), RR_ERR_NULL, "build: NULL profiles");

    /* profiles that never touch in the table's range: the rollers 0.2 m outward */
    pr.gauge = 0.70;
    CHECK_STATUS(BUILD(&pr), RR_ERR_GEOMETRY, "never touch");
    CHECK(bad_y == -g.table_half_range, "never touch: the first row's shift");
    pr.gauge = 0.30;
    /* the workspace */
    CHECK_STATUS(rr_rig_table_build_profiles(&g, &pr, data2, len, pwork,
                                             rr_rig_profiles_work_len(&pr) - 1, &t, &bad_y),
                 RR_ERR_WORKSPACE, "work short");
    CHECK_STATUS(rr_rig_table_build_profiles(&g, &pr, data2, len - 1, pwork,
                                             rr_rig_profiles_work_len(&pr), &t, &bad_y),
                 RR_ERR_WORKSPACE, "data short");

    /* a configuration that says "points", and none given */
    rr_rig_config_default(&c);
    CHECK_STATUS(rr_rig_config_set_choice(&c, "wheelset.profile", "points"), RR_OK, "points");
    CHECK_STATUS(rr_rig_config_set_choice(&c, "roller.profile_right", "points"), RR_OK, "right");
    CHECK_STATUS(rr_rig_config_set_choice(&c, "roller.profile", "s1002"), RR_ERR_PARAM,
                 "a name is the binding's, not the C rig's");
    rr_rig_profiles_from(&c, &pr);
    CHECK(pr.wheel.n == -1 && pr.roller.n == 0 && pr.roller_right.n == -1, "to be given");
    CHECK_STATUS(rr_rig_profiles_check(&pr, &which, &point), RR_ERR_NULL, "not given");
    CHECK(which == RR_RIG_WHEEL, "not given: the wheel");
    CHECK(rr_rig_profiles_work_len(&pr) == 0, "no work length for a profile not given");
    CHECK_STATUS(BUILD(&pr), RR_ERR_NULL, "build: not given");
#undef BUILD
}

static void *test_alloc(void *ctx, size_t n)
{
    (void)ctx;
    return malloc(n);
}

static void test_free(void *ctx, void *p)
{
    (void)ctx;
    free(p);
}

/* the FMU unit on profiles given as points (rr_fmu_set_profiles): none held
 * fails its initialisation; the cone as points at scale 1 gives
 * rr_rig_table_build's table, bit for bit */
static void test_fmu_profiles(void)
{
    static rr_fmu m;
    rr_fmu_config f;
    rr_rig_profiles pr;
    const rr_rig_geometry g = geometry();
    const long len = rr_rig_table_data_len(&g);
    rr_contact_table t;

    rr_fmu_config_default(&f);
    CHECK_STATUS(rr_fmu_config_set_choice(&f, "wheelset.profile", "points"), RR_OK, "points");
    CHECK_STATUS(rr_fmu_config_set(&f, "wheelset.profile_scale", 1.0), RR_OK, "scale 1");
    CHECK_STATUS(rr_fmu_init(&m, &f, test_alloc, test_free, NULL, NULL), RR_OK, "init");
    CHECK_STATUS(rr_fmu_enter_init(&m, 0.0), RR_OK, "enter");
    CHECK_STATUS(rr_fmu_exit_init(&m), RR_ERR_NULL, "no points held: refused");
    CHECK(strstr(rr_fmu_message(&m), "wheelset.profile = \"points\": this FMU carries no "
                                     "points") != NULL, "the message says which row");
    CHECK_STATUS(rr_fmu_set_profiles(&m, &pr), RR_ERR_SEQUENCE, "set after enter: refused");
    rr_fmu_release(&m);

    rr_profile_conical(g.cone_angle, -g.profile_half_width, g.profile_half_width, N, wy, wz);
    memset(&pr, 0, sizeof pr);
    pr.wheel = points(N, wy, wz);
    wy[5] = NAN;
    CHECK_STATUS(rr_fmu_init(&m, &f, test_alloc, test_free, NULL, NULL), RR_OK, "init");
    CHECK_STATUS(rr_fmu_set_profiles(&m, &pr), RR_ERR_NONFINITE, "a NaN point: refused");
    CHECK_STATUS(rr_fmu_set_profiles(NULL, &pr), RR_ERR_NULL, "NULL unit");
    rr_profile_conical(g.cone_angle, -g.profile_half_width, g.profile_half_width, N, wy, wz);
    CHECK_STATUS(rr_fmu_set_profiles(&m, &pr), RR_OK, "the cone's points");
    CHECK_STATUS(rr_fmu_enter_init(&m, 0.0), RR_OK, "enter");
    CHECK_STATUS(rr_fmu_exit_init(&m), RR_OK, "exit: the table from the points");
    CHECK_STATUS(rr_rig_table_build(&g, data, len, work, RR_RIG_TABLE_WORK_LEN, &t, NULL), RR_OK,
                 "the cone's table");
    CHECK(m.table.n == t.n && memcmp(m.table.data, data, (size_t)len * sizeof *data) == 0,
          "the unit's table is rr_rig_table_build's, bitwise");
    rr_fmu_release(&m);
}

int main(void)
{
    test_same_table();
    test_bad_profiles();
    test_fmu_profiles();
    return rr_test_summary();
}
