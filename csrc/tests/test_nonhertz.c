/*
 * test_nonhertz.c - the non-Hertzian contact's run time (rr_nonhertz.h) on
 * a table written from Hertz's theory, where the method must give the
 * exact table's forces on the Hertz ellipse; its validation of the table
 * and the state; the row builder's (rr_nonhertz_table.h) of its inputs.
 * The builder's numbers are checked against the exact solver in
 * tests/test_nonhertz_fast.py.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rr_test.h"
#include "contact/rr_contact.h"
#include "contact/rr_exact_table.h"
#include "contact/rr_hertz.h"
#include "contact/rr_kalker.h"
#include "geometry/rr_nonhertz.h"
#include "geometry/rr_geometry.h"
#include "geometry/rr_nonhertz_table.h"

#define G_ 8.2e10
#define NU 0.28
#define A_ 2.0      /* curvature sums [1/m] */
#define B_ 6.0
#define R0_ 0.46
#define NROWS 3

static double rows[NROWS * RR_NH_ROW_LEN];

/* Hertz at load N: a, b, p0, approach. */
static rr_hertz_result hertz_at(double N)
{
    rr_hertz_result h;
    rr_hertz(A_, B_, N, G_ / (1.0 - NU), &h);
    return h;
}

/* A row of one patch: Hertz's contact of A_, B_ on a horizontal plane
 * through (0, 0.75, 0): q = N / e^1.5 constant, area and peak by N's
 * powers, the linear coefficients Kalker's, no correction. */
static void hertz_row(double *r, double y)
{
    const rr_hertz_result h1 = hertz_at(1.0);
    rr_kalker_coeffs kc;
    double *p = r + RR_NH_PATCH(0);
    int k, c;
    memset(r, 0, RR_NH_ROW_LEN * sizeof *r);
    rr_kalker(h1.a / h1.b, NU, &kc);
    r[0] = y;
    r[1] = 1.0;
    r[2] = R0_;
    for (k = 0; k < RR_NH_NODES; k++) {
        const double N = 1e3 * pow(2.0, k);
        const rr_hertz_result h = hertz_at(N);
        const double c2 = h.a * h.b;
        p[RR_NH_NODE(RR_NH_E, k)] = h.delta;
        p[RR_NH_NODE(RR_NH_Q, k)] = N / pow(h.delta, 1.5);
        p[RR_NH_NODE(RR_NH_PY, k)] = 0.75;
        p[RR_NH_NODE(RR_NH_PZ, k)] = 0.0;
        p[RR_NH_NODE(RR_NH_DELTA, k)] = 0.0;
        p[RR_NH_NODE(RR_NH_AREA, k)] = RR_PI * h.a * h.b / pow(N, 2.0 / 3.0);
        p[RR_NH_NODE(RR_NH_PMAX, k)] = h.p0 / cbrt(N);
        p[RR_NH_NODE(RR_NH_AB, k)] = h.a / h.b;
        p[RR_NH_NODE(RR_NH_K11, k)] = G_ * c2 * kc.c11;
        p[RR_NH_NODE(RR_NH_K22, k)] = G_ * c2 * kc.c22;
        p[RR_NH_NODE(RR_NH_K23, k)] = G_ * c2 * sqrt(c2) * kc.c23;
    }
    for (c = 0; c < RR_NH_CORR; c++)
        p[RR_NH_CORR_AT(c)] = p[RR_NH_NODE(RR_NH_E, c == 0 ? RR_NH_CORR_NODE0 : RR_NH_CORR_NODE1)];
}

static rr_nh_table table(void)
{
    rr_nh_table t;
    int i;
    for (i = 0; i < NROWS; i++)
        hertz_row(rows + i * RR_NH_ROW_LEN, -1e-3 + 1e-3 * i);
    t.nrows = NROWS;
    t.rows = rows;
    t.sigma = 1.0;
    t.R0 = R0_;
    t.G = G_;
    t.nu = NU;
    t.mu_ref = 0.4;
    return t;
}

/* A wheelset rolling at 10 rad/s on rollers at 10.1 rad/s (cx about
 * -0.01), sliding laterally at vy, spinning about Z at wz. */
static rr_nh_state state(double y, double Fz, double vy, double wz)
{
    rr_nh_state s;
    int j;
    memset(&s, 0, sizeof s);
    s.y = y;
    s.Fz = Fz;
    s.mu = 0.3;
    s.roller_spin = 10.1;
    s.vmin = 1e-3;
    for (j = 0; j < 2; j++) {
        s.motion[j].c[1] = y;
        s.motion[j].c[2] = R0_;      /* a wheel of radius R0_ on the plane Z = 0 */
        s.motion[j].v[1] = vy;
        s.motion[j].w[1] = 10.0;
        s.motion[j].w[2] = wz;
    }
    return s;
}

/* The exact table's forces on the Hertz ellipse at the same creepages. */
static void reference(const rr_nh_state *s, const rr_nh_result *r, rr_forces *f)
{
    const rr_hertz_result h = hertz_at(s->Fz);
    rr_contact_problem cp;
    memset(&cp, 0, sizeof cp);
    cp.a = h.a;
    cp.b = h.b;
    cp.N = s->Fz;
    cp.G = G_;
    cp.nu = NU;
    cp.cx = r->patch[0].cx;
    cp.cy = r->patch[0].cy;
    cp.cphi = r->patch[0].cphi;
    cp.friction.mu0 = s->mu;
    cp.friction.A = 1.0;
    rr_exact_table_forces(&rr_exact_table_builtin, &cp, f);
}

static void test_hertz_table_gives_hertz(void)
{
    const rr_nh_table t = table();
    const double loads[] = {3e3, 5e4, 1.1e5};
    int i, bad = 7;
    CHECK_STATUS(rr_nonhertz_table_check(&t, &bad), RR_OK, "the Hertz table is valid");
    CHECK(bad == -1, "no row at fault");
    for (i = 0; i < 3; i++) {
        /* no spin, no lateral slip: q, area / N^(2/3) and K11 ~ e are exact in e */
        rr_nh_state s = state(-0.4e-3, loads[i], 0.0, 0.0);
        rr_nh_result r;
        rr_forces f;
        const rr_hertz_result h = hertz_at(s.Fz);
        CHECK_STATUS(rr_nonhertz_wheel(&t, &s, &r), RR_OK, "a Hertz table's wheel");
        reference(&s, &r, &f);
        CHECK(r.npatch == 1 && r.row == 0, "one patch, rows 0 and 1");
        /* a horizontal plane: N = Fz, no creep force in the vertical */
        CHECK_CLOSE(r.N, s.Fz, 0.0, 1e-9, "N = Fz");
        CHECK_CLOSE(r.force[2], s.Fz, 0.0, 1e-9, "vertical force = Fz");
        CHECK_CLOSE(r.area, RR_PI * h.a * h.b, 0.0, 1e-9, "area");
        CHECK_CLOSE(r.pmax, h.p0, 0.0, 1e-9, "peak pressure");
        CHECK_CLOSE(r.dz[0], h.delta, 0.0, 1e-9, "the lowering is Hertz's approach");
        CHECK(fabs(r.patch[0].cx) > 1e-3, "a longitudinal creepage");
        CHECK_CLOSE(r.force[0], f.fx, 1e-9 * s.mu * s.Fz, 1e-9, "fx: the exact table's");
        CHECK_CLOSE(r.patch[0].fy, f.fy, 1e-9 * s.mu * s.Fz, 1e-9, "fy: the exact table's");
        /* the moment about the centre (0, y, R0): r = (0, 0.75 - y, -R0) */
        CHECK_CLOSE(r.moment[1], -R0_ * r.force[0], 1e-9 * s.Fz, 1e-9, "My = -R0 fx");
    }
    {
        /* lateral slip and spin: K23 ~ e^1.5 interpolated linearly between
         * loads a factor 2 apart: the spin's scale within 1 % */
        rr_nh_state s = state(0.3e-3, 4e4, 0.02, 0.4);
        rr_nh_result r;
        rr_forces f;
        CHECK_STATUS(rr_nonhertz_wheel(&t, &s, &r), RR_OK, "slip and spin");
        reference(&s, &r, &f);
        CHECK(fabs(r.patch[0].cphi) > 0.01 && fabs(r.patch[0].cy) > 1e-4, "slip and spin");
        CHECK_CLOSE(r.patch[0].fx, f.fx, 1e-3 * s.mu * s.Fz, 0.0, "fx with spin");
        CHECK_CLOSE(r.patch[0].fy, f.fy, 1e-3 * s.mu * s.Fz, 0.0, "fy with spin");
        CHECK(r.w > 0.29 && r.w < 0.31 && r.row == 1, "rows 1 and 2, weight 0.3");
    }
}

static void test_bad_state_and_table(void)
{
    rr_nh_table t = table();
    rr_nh_state s = state(0.0, 5e4, 0.0, 0.0);
    rr_nh_result r;
    int bad, row;
    double w;
    CHECK_STATUS(rr_nonhertz_wheel(NULL, &s, &r), RR_ERR_NULL, "no table");
    CHECK(isnan(r.force[0]) && isnan(r.N), "NaN out on error");
    CHECK_STATUS(rr_nonhertz_wheel(&t, NULL, &r), RR_ERR_NULL, "no state");
    CHECK_STATUS(rr_nonhertz_wheel(&t, &s, NULL), RR_ERR_NULL, "no result");
    s.y = 1.5e-3;
    CHECK_STATUS(rr_nonhertz_wheel(&t, &s, &r), RR_ERR_TABLE, "y beyond the rows");
    s.y = -1.0000001e-3;
    CHECK_STATUS(rr_nonhertz_wheel(&t, &s, &r), RR_ERR_TABLE, "y before the rows");
    s.y = NAN;
    CHECK_STATUS(rr_nonhertz_wheel(&t, &s, &r), RR_ERR_NONFINITE, "y NaN");
    s = state(1e-3, 5e4, 0.0, 0.0);
    CHECK_STATUS(rr_nonhertz_wheel(&t, &s, &r), RR_OK, "y on the last row");
    s.motion[1].w[1] = INFINITY;
    CHECK_STATUS(rr_nonhertz_wheel(&t, &s, &r), RR_ERR_NONFINITE, "a motion not finite");
    s = state(0.0, -1.0, 0.0, 0.0);
    CHECK_STATUS(rr_nonhertz_wheel(&t, &s, &r), RR_ERR_LOAD, "Fz < 0");
    /* the last node carries 256 kN: 2^1.5 times that is the table's end */
    s = state(0.0, 7.0e5, 0.0, 0.0);
    CHECK_STATUS(rr_nonhertz_wheel(&t, &s, &r), RR_OK, "2.7 times the last node's load");
    s = state(0.0, 7.5e5, 0.0, 0.0);
    CHECK_STATUS(rr_nonhertz_wheel(&t, &s, &r), RR_ERR_TABLE, "a load beyond the table");
    s = state(0.0, 5e4, 0.0, 0.0);
    s.mu = 0.0;
    CHECK_STATUS(rr_nonhertz_wheel(&t, &s, &r), RR_ERR_FRICTION, "mu = 0");
    s.mu = 0.3;
    s.vmin = 0.0;
    CHECK_STATUS(rr_nonhertz_wheel(&t, &s, &r), RR_ERR_SPEED, "vmin = 0");
    CHECK_STATUS(rr_nonhertz_locate(&t, 0.5e-3, &row, &w), RR_OK, "locate");
    CHECK(row == 1 && fabs(w - 0.5) < 1e-12, "locate: row 1, half-way");
    /* the table's checks */
    rows[RR_NH_ROW_LEN + RR_NH_PATCH(0) + RR_NH_NODE(RR_NH_K11, 3)] = NAN;
    CHECK_STATUS(rr_nonhertz_table_check(&t, &bad), RR_ERR_TABLE, "a NaN coefficient");
    CHECK(bad == 1, "row 1 at fault");
    t = table();
    rows[2 * RR_NH_ROW_LEN] = 0.0;     /* y not increasing */
    CHECK_STATUS(rr_nonhertz_table_check(&t, &bad), RR_ERR_TABLE, "y not increasing");
    CHECK(bad == 2, "row 2 at fault");
    t = table();
    rows[1] = 3.0;
    CHECK_STATUS(rr_nonhertz_table_check(&t, &bad), RR_ERR_TABLE, "three patches");
    s = state(-0.5e-3, 5e4, 0.0, 0.0);
    CHECK_STATUS(rr_nonhertz_wheel(&t, &s, &r), RR_ERR_TABLE, "a row's patch count");
    t = table();
    t.sigma = 0.5;
    CHECK_STATUS(rr_nonhertz_table_check(&t, &bad), RR_ERR_TABLE, "sigma");
    CHECK(bad == -1, "the header at fault");
    t = table();
    t.nrows = 1;
    CHECK_STATUS(rr_nonhertz_table_check(&t, &bad), RR_ERR_TABLE, "one row");
    CHECK_STATUS(rr_nonhertz_table_check(NULL, &bad), RR_ERR_NULL, "no table");
}

static void test_row_inputs(void)
{
    rr_nh_row_problem pb;
    rr_nh_row_info info;
    rr_wheel_roller pair;
    double row[RR_NH_ROW_LEN], work[4];
    memset(&pair, 0, sizeof pair);
    rr_nonhertz_row_default(&pb);
    CHECK(pb.n == 40 && pb.n_corr == 30 && pb.richardson == 1, "defaults");
    CHECK_STATUS(rr_nonhertz_row(&pb, work, 4, 48, row, NULL), RR_ERR_NULL, "no info");
    CHECK_STATUS(rr_nonhertz_row(&pb, work, 4, 48, row, &info), RR_ERR_NULL, "no pair");
    CHECK(isnan(row[0]), "the row NaN on error");
    pb.pair = &pair;
    pb.Fz_max = NAN;
    CHECK_STATUS(rr_nonhertz_row(&pb, work, 4, 48, row, &info), RR_ERR_NONFINITE, "Fz_max NaN");
    pb.Fz_max = -1.0;
    CHECK_STATUS(rr_nonhertz_row(&pb, work, 4, 48, row, &info), RR_ERR_LOAD, "Fz_max < 0");
    pb.Fz_max = 1e4;
    pb.Fz_regions = NAN;
    CHECK_STATUS(rr_nonhertz_row(&pb, work, 4, 48, row, &info), RR_ERR_NONFINITE,
                 "Fz_regions NaN");
    pb.Fz_regions = 2e4;
    CHECK_STATUS(rr_nonhertz_row(&pb, work, 4, 48, row, &info), RR_ERR_LOAD,
                 "Fz_regions beyond Fz_max");
    pb.Fz_regions = -1.0;
    CHECK_STATUS(rr_nonhertz_row(&pb, work, 4, 48, row, &info), RR_ERR_LOAD, "Fz_regions < 0");
    CHECK(info.patch == -1 && info.node == -1 && info.patches == 0, "no patch at fault");
    pb.Fz_regions = 5e3;
    pb.n_corr = 50;
    CHECK_STATUS(rr_nonhertz_row(&pb, work, 4, 48, row, &info), RR_ERR_PARAM, "n_corr > n");
    pb.n_corr = 30;
    CHECK_STATUS(rr_nonhertz_row(&pb, work, 4, 48, row, &info), RR_ERR_WORKSPACE,
                 "a short workspace");
    CHECK(rr_nonhertz_row_workspace_len(&pb, 48) > 4, "the workspace's length");
    CHECK(rr_nonhertz_row_workspace_len(&pb, 4) == 0, "a side below 8");
    CHECK(rr_nonhertz_row_workspace_len(NULL, 48) == 0, "no problem");
}

/* A row on too small a side says the side it needs (info.need > side), so
 * that a caller can grow it: a coarse grid may fit side^2 cells but not the
 * side along one axis (13 x 11 on side 12), and the bands' probe may need
 * more cells than side^2.  fuzz_nonhertz_row's find: a 1:14 cone on a
 * roller crowned at 22.5 mm, 3.4 mm wide, at the rig's loads; sides 8 to 40
 * each give a row or that refusal, and the side grown by it gives a row. */
static void test_row_says_the_side_it_needs(void)
{
    enum { NW = 30, NR = 24 };
    double ws[NW], wz[NW], wm[NW], rs[NR], rz[NR], rm[NR], scratch[NW];
    double row[RR_NH_ROW_LEN];
    rr_wheel_roller left, right;
    rr_search_opts so;
    rr_contact_point cr;
    rr_nh_row_problem pb;
    rr_nh_row_info info;
    int i, side, refused = 0, built = 0, grown_ok = 1;
    for (i = 0; i < NW; i++) {
        ws[i] = -0.0258783 + 2.0 * 0.0258783 * i / (NW - 1);
        wz[i] = 0.0693929 * ws[i];
    }
    for (i = 0; i < NR; i++) {
        rs[i] = -0.00337956 + 2.0 * 0.00337956 * i / (NR - 1);
        rz[i] = sqrt(0.0225353 * 0.0225353 - rs[i] * rs[i]) - 0.0225353;
    }
    CHECK(rr_spline_init(NW, ws, wz, wm, scratch) == RR_OK
          && rr_spline_init(NR, rs, rz, rm, scratch) == RR_OK, "the profiles' splines");
    memset(&left, 0, sizeof left);
    left.wheel.n = NW, left.wheel.s = ws, left.wheel.z = wz, left.wheel.m = wm;
    left.roller.n = NR, left.roller.s = rs, left.roller.z = rz, left.roller.m = rm;
    left.r0 = 0.0320864;
    left.R0 = 0.143133;
    left.wheel_y = 0.388111;
    left.roller_y = 0.390399;
    left.side = 1;
    right = left;
    right.side = -1;
    rr_search_opts_default(&so);
    rr_nonhertz_row_default(&pb);
    pb.pair = &left;
    pb.y_ws = -1.128026e-3;
    CHECK_STATUS(rr_wheelset_contact(&left, &right, pb.y_ws, &so, &pb.pose0, &pb.point, &cr),
                 RR_OK, "the zero-gap pose");
    pb.Fz_max = 52.41;
    pb.Fz_regions = 12.14;
    pb.mu = 0.18;
    pb.vmin = 3e-4;
    pb.n = pb.n_corr = 8;
    pb.richardson = 0;
    pb.combine = 3.087e-3;
    pb.tol = 2.42e-5;
    pb.maxit = 82;
    pb.roller_spin = 10.0;
    pb.wheelset.c[1] = pb.y_ws;
    pb.wheelset.c[2] = pb.pose0.z;
    pb.wheelset.w[1] = 10.0 * left.R0 / left.r0 * cos(pb.pose0.roll);
    pb.wheelset.w[2] = 10.0 * left.R0 / left.r0 * sin(pb.pose0.roll);
    for (side = 8; side <= 40; side++) {
        const size_t len = rr_nonhertz_row_workspace_len(&pb, side);
        double *work = calloc(len, sizeof *work);
        int st;
        if (!work) {
            CHECK(0, "memory for the workspace");
            return;
        }
        st = rr_nonhertz_row(&pb, work, len, side, row, &info);
        free(work);
        if (st >= 0) {
            built++;
            continue;
        }
        CHECK(st == RR_ERR_WORKSPACE && info.need > (size_t)side,
              "a refusal on its own side says a larger side");
        if (st != RR_ERR_WORKSPACE || info.need <= (size_t)side) {
            printf("  side %d: status %d, need %zu, why %d, gap_why %d\n", side, st, info.need,
                   info.why, info.gap_why);
            continue;
        }
        refused++;
        {
            /* grown to the side it says, again while refused (a larger
             * node's grid may need more: the binding's loop, without its
             * margin) */
            int s2 = side, tries, st2 = st;
            for (tries = 0; tries < 6 && st2 == RR_ERR_WORKSPACE && (int)info.need > s2; tries++) {
                const size_t len2 = rr_nonhertz_row_workspace_len(&pb, s2 = (int)info.need);
                double *w2 = calloc(len2, sizeof *w2);
                st2 = w2 ? rr_nonhertz_row(&pb, w2, len2, s2, row, &info) : RR_ERR_WORKSPACE;
                free(w2);
            }
            if (st2 < 0) {
                printf("  side %d grown to %d: status %d, need %zu\n", side, s2, st2, info.need);
                grown_ok = 0;
            }
        }
    }
    CHECK(refused > 0 && built > 0, "sides both too small and enough");
    CHECK(grown_ok, "each refused side, grown to the side it said, gives a row");
}

int main(void)
{
    test_hertz_table_gives_hertz();
    test_bad_state_and_table();
    test_row_inputs();
    test_row_says_the_side_it_needs();
    return rr_test_summary();
}
