/* test_geometry.c - splines, contact search, wheelset pose and contact tables. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rr_test.h"
#include "rollerrig.h"

#define NW 121
#define NR 121

static double ws_[NW], wz[NW], wm[NW], rs[NR], rz[NR], rm[NR], work[NW + NR];

/* A conical wheel (z_w = s tan(alpha): the radius falls outward) on a roller
 * whose crown is a circle of radius rho (z_r = sqrt(rho^2 - s^2) - rho). */
static void conical_pair(double alpha, double rho, int side, rr_wheel_roller *p)
{
    int i;
    for (i = 0; i < NW; i++) {
        ws_[i] = -0.03 + 0.06 * i / (NW - 1);
        wz[i] = ws_[i] * tan(alpha);
    }
    for (i = 0; i < NR; i++) {
        rs[i] = -0.03 + 0.06 * i / (NR - 1);
        rz[i] = sqrt(rho * rho - rs[i] * rs[i]) - rho;
    }
    rr_spline_init(NW, ws_, wz, wm, work);
    rr_spline_init(NR, rs, rz, rm, work);
    p->wheel.n = NW; p->wheel.s = ws_; p->wheel.z = wz; p->wheel.m = wm;
    p->roller.n = NR; p->roller.s = rs; p->roller.z = rz; p->roller.m = rm;
    p->r0 = 0.1;
    p->R0 = 0.2;
    p->wheel_y = 0.75;
    p->roller_y = 0.75;
    p->side = side;
}

static void test_spline(void)
{
    double s[9], z[9], m[9], w[9], v, d1, d2;
    rr_spline sp;
    int i;
    for (i = 0; i < 9; i++) {
        s[i] = 0.1 * i * i;                  /* uneven knots */
        z[i] = 3.0 - 2.0 * s[i];
    }
    CHECK_STATUS(rr_spline_init(9, s, z, m, w), RR_OK, "spline init");
    sp.n = 9; sp.s = s; sp.z = z; sp.m = m;
    /* a straight line is reproduced exactly (to rounding) */
    rr_spline_eval(&sp, 2.345, &v, &d1, &d2);
    CHECK_CLOSE(v, 3.0 - 2.0 * 2.345, 1e-14, 0.0, "spline: line value");
    CHECK_CLOSE(d1, -2.0, 1e-13, 0.0, "spline: line slope");
    CHECK_CLOSE(d2, 0.0, 1e-12, 0.0, "spline: line curvature");
    rr_spline_eval(&sp, s[4], &v, 0, 0);
    CHECK(v == z[4] || fabs(v - z[4]) < 1e-15, "spline: exact at a knot");
    CHECK_STATUS(rr_spline_eval(&sp, 7.0, &v, 0, 0), RR_ERR_GEOMETRY, "spline: off the end");
    z[3] = NAN;
    CHECK_STATUS(rr_spline_init(9, s, z, m, w), RR_ERR_NONFINITE, "spline: NaN value");
    z[3] = 0.0;
    s[3] = s[2];
    CHECK_STATUS(rr_spline_init(9, s, z, m, w), RR_ERR_GEOMETRY, "spline: repeated knot");
}

static void test_conical(void)
{
    const double alpha = 0.05, rho = 0.1;
    rr_wheel_roller l, r;
    rr_search_opts o;
    double y;
    conical_pair(alpha, rho, +1, &l);
    r = l;
    r.side = -1;
    rr_search_opts_default(&o);
    for (y = -0.005; y <= 0.00501; y += 0.0025) {
        rr_wheelset_pose pose;
        rr_contact_point cl, cr;
        int st = rr_wheelset_contact(&l, &r, y, &o, &pose, &cl, &cr);
        char buf[120];
        snprintf(buf, sizeof buf, "conical y = %g mm: status", y * 1e3);
        CHECK_STATUS(st, RR_OK, buf);
        /* both wheels touch: the pose solve drives the gaps below 1e-13 m */
        CHECK(fabs(cl.gap) < 1e-12 && fabs(cr.gap) < 1e-12, "conical: both wheels touch");
        /* rolling-radius difference 2 tan(alpha) y plus what the wheelset's
         * roll phi adds: the contact points move on the crowns by
         * rho (sin(alpha + phi) - sin(alpha - phi)) and on the wheels by
         * r0 phi each (first order in phi); 2e-7 m: the second-order terms,
         * phi s tan(alpha) with s up to 5 mm */
        CHECK_CLOSE(cl.r - cr.r, tan(alpha) * (2.0 * y + 2.0 * l.r0 * pose.roll
                    + rho * (sin(alpha + pose.roll) - sin(alpha - pose.roll))),
                    2e-7, 0.0, "conical: r_l - r_r = 2 tan(alpha) y + roll terms");
        /* the roll term is small: within 1.5 % of 2 tan(alpha) y */
        CHECK_CLOSE(cl.r - cr.r, 2.0 * tan(alpha) * y, 1e-12, 0.015,
                    "conical: r_l - r_r ~ 2 tan(alpha) y");
        /* the contact angle is alpha tilted by the roll, +roll on the left and
         * -roll on the right; their mean is alpha to the Newton tolerance */
        CHECK_CLOSE(0.5 * (cl.delta + cr.delta), alpha, 1e-9, 0.0, "conical: mean contact angle");
        CHECK_CLOSE(cl.delta - cr.delta, 2.0 * pose.roll, 1e-9, 0.0,
                    "conical: contact angles differ by twice the roll");
        CHECK(!cl.two_point && !cr.two_point, "conical: one contact point");
        /* Hertz curvatures: the cone is straight, so B is half the crown's
         * curvature 1/rho; 1e-4: the spline of the sampled circle */
        CHECK_CLOSE(cl.B, 0.5 / rho, 0.0, 1e-4, "conical: B = 1/(2 rho)");
        CHECK_CLOSE(cl.A, 0.5 * cos(cl.delta) * (1.0 / cl.r + 1.0 / cl.R), 0.0, 1e-14,
                    "conical: A = cos(delta)(1/r + 1/R)/2");
    }
}

static void test_table(void)
{
    const double alpha = 0.05, rho = 0.1;
    rr_wheel_roller l, r;
    rr_search_opts o;
    static double data[201 * RR_CONTACT_TABLE_ROW];
    rr_contact_table t;
    double y, worst = 0.0;
    conical_pair(alpha, rho, +1, &l);
    r = l;
    r.side = -1;
    rr_search_opts_default(&o);
    CHECK(rr_contact_table_len(201) == 201 * RR_CONTACT_TABLE_ROW, "table length");
    t.y0 = -0.01; t.dy = 1e-4; t.n = 201; t.data = data;
    CHECK_STATUS(rr_contact_table_build(&l, &r, &o, &t, 0), RR_OK, "table build");
    for (y = -0.0099; y < 0.0099; y += 0.00037) {
        rr_wheelset_pose p1, p2;
        rr_contact_point a1, b1, a2, b2;
        rr_wheelset_contact(&l, &r, y, &o, &p1, &a1, &b1);
        rr_contact_table_lookup(&t, y, &p2, 0, &a2, &b2);
        if (fabs(a1.r - a2.r) > worst) worst = fabs(a1.r - a2.r);
    }
    /* linear interpolation of a smooth function at 0.1 mm spacing */
    CHECK(worst < 1e-10, "table: rolling radius within 1e-10 m of the direct search");
    {
        rr_wheelset_pose p;
        rr_contact_point a, b;
        CHECK_STATUS(rr_contact_table_lookup(&t, 0.02, &p, 0, &a, &b), RR_ERR_GEOMETRY,
                     "table: outside its range");
        CHECK(a.r != a.r, "table: outside gives NaN");
    }
}

/* The lookup at every row of a table, both ends included, succeeds; a shift
 * an ulp outside either end does not.  The last row's shift divided back
 * into a row index may land an ulp past n - 1 (issue 22: 10 of 1 500 random
 * tables refused their last row), so the range is the rows' own shifts. */
static void test_table_ends(void)
{
    enum { MAXN = 16, CASES = 20000 };
    static double data[MAXN * RR_CONTACT_TABLE_ROW];
    rr_contact_table t;
    rr_wheelset_pose p;
    rr_contact_point a, b;
    unsigned long seed = 12345u;
    int k, i, refused = 0, outside = 0;
    for (k = 0; k < MAXN * RR_CONTACT_TABLE_ROW; k++)
        data[k] = 1.0 + 1e-3 * (k % 7);   /* any finite rows */
    t.data = data;
    for (k = 0; k < CASES; k++) {
        double u[3], y_max, last;
        for (i = 0; i < 3; i++) {        /* a 32-bit LCG: the same cases on every machine */
            seed = (seed * 1664525u + 1013904223u) & 0xffffffffu;
            u[i] = seed / 4294967296.0;
        }
        t.n = 2 + (int)(u[2] * (MAXN - 1));
        t.y0 = -0.012 * u[0];
        y_max = 0.012 * u[1] + 1e-6;
        if (k == 0) {                    /* the reproducer */
            t.y0 = -0.002164674744325865; y_max = 0.0075946696529369225; t.n = 8;
        }
        t.dy = (y_max - t.y0) / (t.n - 1);   /* as rollerrig.contact_table */
        for (i = 0; i < t.n; i++)
            if (rr_contact_table_lookup(&t, t.y0 + i * t.dy, &p, 0, &a, &b) != RR_OK)
                refused++;
        last = t.y0 + (t.n - 1) * t.dy;
        if (rr_contact_table_lookup(&t, nextafter(last, INFINITY), &p, 0, &a, &b)
                != RR_ERR_GEOMETRY
            || rr_contact_table_lookup(&t, nextafter(t.y0, -INFINITY), &p, 0, &a, &b)
                != RR_ERR_GEOMETRY)
            outside++;
    }
    CHECK(refused == 0, "table: the lookup at every row succeeds, both ends included");
    if (refused)
        printf("    %d rows of %d tables refused\n", refused, (int)CASES);
    CHECK(outside == 0, "table: an ulp outside either end is RR_ERR_GEOMETRY");
    t.y0 = -0.002164674744325865; t.n = 8; t.dy = (0.0075946696529369225 - t.y0) / 7;
    CHECK_STATUS(rr_contact_table_lookup(&t, t.y0 + 7 * t.dy, &p, 0, &a, &b), RR_OK,
                 "table: the reproducer's last row");
    /* 1e-15: a + f (b - a) at f = 1 is b within an ulp */
    CHECK_CLOSE(a.r, data[7 * RR_CONTACT_TABLE_ROW + 4], 0.0, 1e-15, "table: last row's r");
    CHECK_CLOSE(p.z, data[7 * RR_CONTACT_TABLE_ROW + 26], 0.0, 1e-15, "table: last row's z");
}

static void test_off_roller(void)
{
    rr_wheel_roller l;
    rr_search_opts o;
    rr_contact_point c;
    conical_pair(0.05, 0.1, +1, &l);
    rr_search_opts_default(&o);
    /* shifted by 10 cm the wheel has left its 6 cm wide roller */
    CHECK_STATUS(rr_contact_search(&l, 0.1, 0.1, 0.0, &o, &c), RR_ERR_GEOMETRY,
                 "wheel off the roller");
    CHECK(c.r != c.r, "off the roller: NaN");
    CHECK_STATUS(rr_contact_search(&l, NAN, 0.1, 0.0, &o, &c), RR_ERR_NONFINITE, "NaN shift");
}

/* Two evaluations the same bytes: the pose, and each wheel's values as the
 * binding stores them (rr_wheel_store: no padding compared) and status. */
static int same_wheels(const rr_rig_pose *p, const rr_wheel_contact *w, const rr_rig_pose *q,
                       const rr_wheel_contact *v)
{
    double a[RR_WHEEL_NVALUES], b[RR_WHEEL_NVALUES];
    int k;
    if (memcmp(p, q, sizeof *p) != 0)
        return 0;
    for (k = 0; k < 2; k++) {
        rr_wheel_store(&w[k], a, 1);
        rr_wheel_store(&v[k], b, 1);
        if (memcmp(a, b, sizeof a) != 0 || w[k].status != v[k].status)
            return 0;
    }
    return 1;
}

/* The model checked once (rr_rig_contact_bind) and evaluated without
 * checking it again: the unchecked functions' bytes and statuses, at good
 * and bad states and loads; an unbound record refused; the bound copy
 * unmoved by later changes to the model. */
static void test_rig_contact_checked(rr_rig_contact_model *m, const rr_rig_state *s0)
{
    rr_rig_contact_checked k;
    rr_rig_state s;
    rr_rig_pose p1, p2;
    rr_wheel_contact w1[2], w2[2];
    const double loads[4][2] = {{1000.0, 900.0}, {-1.0, 1000.0}, {NAN, 1000.0},
                                {1000.0, 0.0}};
    const double spins[3] = {1.0, 0.98, 1.05}, ys[3] = {0.0, 2e-3, 0.01};
    int i, j, l, st;

    CHECK_STATUS(rr_rig_contact_bind(&k, m, NULL, 0), RR_OK, "rig: bound");
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            for (l = 0; l < 4; l++) {
                s = *s0;
                s.spin *= spins[i];
                s.y = ys[j];
                s.yaw_rate = l == 3 ? NAN : 0.0;
                memset(w1, 0, sizeof w1);
                memset(w2, 0, sizeof w2);
                st = rr_rig_contact(m, &s, loads[l], &p1, w1);
                CHECK_STATUS(rr_rig_contact_eval_checked(&k, &s, loads[l], &p2, w2), st,
                             "rig: checked evaluation's status");
                CHECK(same_wheels(&p1, w1, &p2, w2), "rig: checked evaluation, bit for bit");
                st = rr_rig_kinematics(m, &s, &p1, w1);
                CHECK_STATUS(rr_rig_kinematics_checked(&k, &s, &p2, w2), st,
                             "rig: checked kinematics");
                CHECK(same_wheels(&p1, w1, &p2, w2), "rig: checked kinematics, bit for bit");
                CHECK_STATUS(rr_rig_kinematics_rates_at(&k, &s, s.y, &p2, w2), st,
                             "rig: kinematics with the rates at its own y");
                CHECK(same_wheels(&p1, w1, &p2, w2), "rig: the rates at its own y, bit for bit");
                if (st >= 0) {
                    st = rr_rig_contact_loads(m, loads[l], &p1, w1);
                    CHECK_STATUS(rr_rig_contact_loads_checked(&k, loads[l], &p2, w2), st,
                                 "rig: checked loads");
                    CHECK(same_wheels(&p1, w1, &p2, w2), "rig: checked loads, bit for bit");
                }
            }
    /* the rates at another shift: the pose of its own y, the vertical and
     * roll rates of the state at y_rates (the table's slopes there) */
    s = *s0;
    s.vy = 0.01;
    s.y = 2e-3;
    CHECK_STATUS(rr_rig_kinematics_checked(&k, &s, &p1, w1), RR_OK, "rig: at 2 mm");
    s.y = 0.0;
    CHECK_STATUS(rr_rig_kinematics_rates_at(&k, &s, 2e-3, &p2, w2), RR_OK,
                 "rig: at 0 with 2 mm's rates");
    CHECK(p2.roll_rate == p1.roll_rate && p2.roll_rate != 0.0, "rig: 2 mm's roll rate");
    CHECK_STATUS(rr_rig_kinematics_checked(&k, &s, &p1, w1), RR_OK, "rig: at 0");
    CHECK(p2.c[1] == p1.c[1] && p2.c[2] == p1.c[2] && p2.roll == p1.roll,
          "rig: at 0 with 2 mm's rates: 0's pose");
    CHECK(p2.roll_rate != p1.roll_rate, "rig: the rates are 2 mm's, not 0's");
    CHECK_STATUS(rr_rig_kinematics_rates_at(&k, &s, NAN, &p2, w2), RR_ERR_NONFINITE,
                 "rig: y_rates NaN");
    CHECK(isnan(p2.c[0]) && isnan(p2.roll_rate) && w2[0].status == RR_ERR_NONFINITE,
          "rig: y_rates NaN: NaN pose");
    CHECK_STATUS(rr_rig_kinematics_rates_at(&k, &s, 1.0, &p2, w2), RR_ERR_GEOMETRY,
                 "rig: y_rates beyond the table");
    CHECK_STATUS(rr_rig_kinematics_rates_at(&k, &s, 0.0, NULL, w2), RR_ERR_NULL,
                 "rig: rates_at, NULL pose");
    CHECK_STATUS(rr_rig_kinematics_rates_at(&k, NULL, 0.0, &p2, w2), RR_ERR_NULL,
                 "rig: rates_at, NULL state");
    /* a copy: the model changed after the bind does not reach it */
    s = *s0;
    s.spin *= 0.98;
    rr_rig_contact_eval_checked(&k, &s, loads[0], &p1, w1);
    m->creep.v[RR_FASTSIM_NX] = 0.5;
    CHECK_STATUS(rr_rig_contact(m, &s, loads[0], &p2, w2), RR_ERR_GRID, "rig: nx = 0.5 refused");
    CHECK_STATUS(rr_rig_contact_eval_checked(&k, &s, loads[0], &p2, w2), RR_OK,
                 "rig: the bound copy is the checked model");
    CHECK(same_wheels(&p1, w1, &p2, w2), "rig: and evaluates as before");
    CHECK_STATUS(rr_rig_contact_bind(&k, m, NULL, 0), RR_ERR_GRID, "rig: the changed model refused");
    m->creep.v[RR_FASTSIM_NX] = 20;
    /* what a C caller can get wrong: an unbound or refused record, NULLs */
    CHECK_STATUS(rr_rig_contact_eval_checked(&k, &s, loads[0], &p2, w2), RR_ERR_NULL,
                 "rig: a refused bind is not used");
    CHECK(isnan(p2.c[0]) && isnan(w2[0].force[0]) && w2[1].status == RR_ERR_NULL,
          "rig: refused: NaN");
    memset(&k, 0, sizeof k);
    CHECK_STATUS(rr_rig_kinematics_checked(&k, &s, &p2, w2), RR_ERR_NULL, "rig: zeroed record");
    CHECK_STATUS(rr_rig_contact_loads_checked(&k, loads[0], &p2, w2), RR_ERR_NULL,
                 "rig: zeroed record's loads");
    CHECK_STATUS(rr_rig_contact_bind(&k, m, NULL, 0), RR_OK, "rig: bound again");
    CHECK_STATUS(rr_rig_kinematics_checked(NULL, &s, &p2, w2), RR_ERR_NULL, "rig: NULL record");
    CHECK_STATUS(rr_rig_kinematics_checked(&k, NULL, &p2, w2), RR_ERR_NULL, "rig: NULL state");
    CHECK_STATUS(rr_rig_kinematics_checked(&k, &s, NULL, w2), RR_ERR_NULL, "rig: NULL pose");
    CHECK_STATUS(rr_rig_contact_eval_checked(&k, &s, loads[0], &p2, NULL), RR_ERR_NULL,
                 "rig: NULL wheels");
    CHECK_STATUS(rr_rig_contact_loads_checked(&k, NULL, &p2, w2), RR_ERR_NULL,
                 "rig: NULL loads");
    CHECK_STATUS(rr_rig_contact_loads_checked(&k, loads[0], NULL, w2), RR_ERR_NULL,
                 "rig: NULL pose for the loads");
    CHECK_STATUS(rr_rig_contact_bind(NULL, m, NULL, 0), RR_ERR_NULL, "rig: NULL record to bind");
    CHECK_STATUS(rr_rig_contact_bind(&k, NULL, NULL, 0), RR_ERR_NULL, "rig: NULL model");
    /* the bound workspace reaches the creep method: a record whose method
     * asks 4 doubles (as one with a workspace would) is refused each wheel
     * without it, and evaluates as before with it */
    {
        double work[4];
        CHECK(rr_rig_contact_workspace_len(m) == 0, "rig: FASTSIM asks no workspace");
        CHECK(rr_rig_contact_workspace_len(NULL) == 0, "rig: a NULL model asks none");
        CHECK_STATUS(rr_rig_contact_bind(&k, m, work, 4), RR_OK, "rig: bound with a workspace");
        CHECK(k.work == work && k.work_len == 4, "rig: the workspace kept");
        s = *s0;
        s.spin *= 0.98;
        rr_rig_contact_eval_checked(&k, &s, loads[0], &p1, w1);
        k.creep.work_len = 4;
        k.work = NULL;
        k.work_len = 0;
        rr_rig_contact_eval_checked(&k, &s, loads[0], &p2, w2);
        CHECK(w2[0].status == RR_ERR_WORKSPACE && w2[1].status == RR_ERR_WORKSPACE,
              "rig: a method's workspace missing: each wheel refused");
        k.work = work;
        k.work_len = 4;
        CHECK_STATUS(rr_rig_contact_eval_checked(&k, &s, loads[0], &p2, w2), RR_OK,
                     "rig: with the workspace");
        CHECK(same_wheels(&p1, w1, &p2, w2), "rig: with the workspace, as before");
    }
}

/* The whole evaluation on the conical pair: free rolling, braking, bad input. */
static void test_rig_contact(void)
{
    const double alpha = 0.05, rho = 0.1, V = 5.0;
    rr_wheel_roller l, r;
    rr_search_opts o;
    static double data[101 * RR_CONTACT_TABLE_ROW];
    rr_contact_table t;
    rr_rig_contact_model m;
    rr_rig_state s;
    rr_rig_pose pose;
    rr_wheel_contact w[2];
    rr_wheelset_pose tp;
    rr_contact_point cl, cr;
    double N[2] = {1000.0, 1000.0};
    int k;

    conical_pair(alpha, rho, +1, &l);
    r = l;
    r.side = -1;
    rr_search_opts_default(&o);
    t.y0 = -0.005; t.dy = 1e-4; t.n = 101; t.data = data;
    CHECK_STATUS(rr_contact_table_build(&l, &r, &o, &t, 0), RR_OK, "rig: table");
    rr_contact_table_lookup(&t, 0.0, &tp, 0, &cl, &cr);
    memset(&m, 0, sizeof m);           /* Hertz: the non-Hertzian members zero */
    m.table = &t;
    m.R0 = 0.2;
    m.estar = rr_estar(2.1e11, 0.28, 2.1e11, 0.28);
    m.G = 2.1e11 / 2.56;
    m.nu = 0.28;
    m.friction.mu0 = 0.4; m.friction.A = 1.0; m.friction.B = 0.0;
    rr_creep_opts_default(&m.creep, RR_METHOD_FASTSIM);
    m.creep.v[RR_FASTSIM_NX] = m.creep.v[RR_FASTSIM_NY] = 20;
    m.vmin = 1e-3;
    CHECK_STATUS(rr_rig_contact_check(&m), RR_OK, "rig: model");

    s.x = s.y = s.yaw = s.vx = s.vy = s.yaw_rate = 0.0;
    s.spin = V / cl.r;
    s.roller_spin = V / cl.R;
    CHECK_STATUS(rr_rig_contact(&m, &s, N, &pose, w), RR_OK, "rig: free rolling");
    for (k = 0; k < 2; k++) {
        CHECK(fabs(w[k].creep.cx) < 1e-12 && fabs(w[k].creep.cy) < 1e-12,
              "rig: free rolling has no creepage");
        CHECK(fabs(w[k].f.fx) < 1e-9, "rig: free rolling has no longitudinal force");
        /* the normal force is N along n, n into the wheel (upward) */
        CHECK_CLOSE(w[k].force[2], N[k] * w[k].n[2] + w[k].f.fy * w[k].frame.t2[2], 1e-9, 0.0,
                    "rig: vertical force");
    }
    CHECK(fabs(w[0].force[1] + w[1].force[1]) < 1e-9, "rig: spin forces cancel");

    s.spin *= 0.98;     /* braked */
    CHECK_STATUS(rr_rig_contact(&m, &s, N, &pose, w), RR_OK, "rig: braked");
    CHECK(w[0].creep.cx > 0.0 && w[0].f.fx < 0.0 && w[0].force[0] < 0.0,
          "rig: braking pushes the wheel back");
    CHECK(w[0].moment[1] + w[1].moment[1] > 0.0, "rig: and spins it up");

    N[0] = -1.0;
    CHECK_STATUS(rr_rig_contact(&m, &s, N, &pose, w), RR_ERR_LOAD, "rig: negative load");
    CHECK(w[0].status == RR_ERR_LOAD && w[0].force[0] != w[0].force[0],
          "rig: the bad wheel is NaN");
    CHECK(w[1].status == RR_OK && isfinite(w[1].force[0]), "rig: the other wheel is valid");
    N[0] = 1000.0;
    s.y = 0.01;
    CHECK_STATUS(rr_rig_contact(&m, &s, N, &pose, w), RR_ERR_GEOMETRY, "rig: off the table");
    CHECK(pose.c[2] != pose.c[2] && w[1].creep.cx != w[1].creep.cx, "rig: NaN pose");
    s.y = 0.0;
    s.yaw_rate = NAN;
    CHECK_STATUS(rr_rig_contact(&m, &s, N, &pose, w), RR_ERR_NONFINITE, "rig: NaN state");
    s.yaw_rate = 0.0;
    s.x = 0.2;
    CHECK_STATUS(rr_rig_contact(&m, &s, N, &pose, w), RR_ERR_GEOMETRY,
                 "rig: far round the roller");
    s.x = 0.0;
    m.vmin = 0.0;
    CHECK_STATUS(rr_rig_contact(&m, &s, N, &pose, w), RR_ERR_SPEED, "rig: vmin = 0");
    m.vmin = 1e-3;
    test_rig_contact_checked(&m, &s);
    m.table = 0;
    CHECK_STATUS(rr_rig_contact_check(&m), RR_ERR_WORKSPACE, "rig: no table");
}

/* What a C caller can get wrong: tables, options and profiles (issue 11). */
static void test_caller_errors(void)
{
    const double alpha = 0.05, rho = 0.1;
    static double data[4 * RR_CONTACT_TABLE_ROW];
    rr_wheel_roller l, r;
    rr_search_opts o;
    rr_contact_table t;
    rr_wheelset_pose pose, slope;
    rr_contact_point cl, cr;
    int k;

    conical_pair(alpha, rho, +1, &l);
    r = l;
    r.side = -1;
    rr_search_opts_default(&o);
    t.y0 = -0.002; t.dy = 0.001; t.n = 4; t.data = data;
    CHECK_STATUS(rr_contact_table_build(&l, &r, &o, &t, NULL), RR_OK, "small table");
    CHECK_STATUS(rr_contact_table_lookup(&t, 0.0, &pose, &slope, &cl, &cr), RR_OK, "lookup");

    /* the reproducer: y0 = NaN made a float-to-int conversion out of range */
    t.y0 = NAN; t.dy = 0.0005;
    CHECK_STATUS(rr_contact_table_lookup(&t, 0.0, &pose, &slope, &cl, &cr), RR_ERR_PARAM,
                 "lookup y0 = NaN");
    CHECK(isnan(pose.z) && isnan(cl.r) && isnan(slope.z), "y0 NaN: NaN outputs");
    t.y0 = -0.002; t.dy = 0.0;
    CHECK_STATUS(rr_contact_table_lookup(&t, 0.0, &pose, NULL, &cl, &cr), RR_ERR_PARAM, "dy 0");
    t.dy = -0.001;
    CHECK_STATUS(rr_contact_table_lookup(&t, 0.0, &pose, NULL, &cl, &cr), RR_ERR_PARAM, "dy < 0");
    t.dy = 1e308;
    CHECK_STATUS(rr_contact_table_lookup(&t, 0.0, &pose, NULL, &cl, &cr), RR_ERR_PARAM,
                 "last row's shift overflows");
    t.dy = 0.001; t.n = 1;
    CHECK_STATUS(rr_contact_table_lookup(&t, 0.0, &pose, NULL, &cl, &cr), RR_ERR_PARAM, "n = 1");
    t.n = 4; t.data = NULL;
    CHECK_STATUS(rr_contact_table_lookup(&t, 0.0, &pose, NULL, &cl, &cr), RR_ERR_NULL,
                 "data NULL");
    CHECK_STATUS(rr_contact_table_build(&l, &r, &o, &t, NULL), RR_ERR_WORKSPACE,
                 "build into no data");
    t.data = data;
    CHECK_STATUS(rr_contact_table_lookup(NULL, 0.0, &pose, NULL, &cl, &cr), RR_ERR_NULL, "t NULL");
    CHECK_STATUS(rr_contact_table_lookup(&t, 0.0, NULL, NULL, &cl, &cr), RR_ERR_NULL, "pose NULL");
    CHECK_STATUS(rr_contact_table_build_rows(&l, &r, &o, &t, 2, 5, NULL), RR_ERR_PARAM,
                 "rows past the table");
    {
        /* rows built in parts equal the whole build, bit for bit */
        static double whole[4 * RR_CONTACT_TABLE_ROW];
        rr_contact_table w = t;
        w.data = whole;
        CHECK_STATUS(rr_contact_table_build(&l, &r, &o, &w, NULL), RR_OK, "whole build");
        CHECK_STATUS(rr_contact_table_build_rows(&l, &r, &o, &t, 0, 1, NULL), RR_OK, "rows 0-1");
        CHECK_STATUS(rr_contact_table_build_rows(&l, &r, &o, &t, 1, 4, NULL), RR_OK, "rows 1-4");
        for (k = 0; k < 4 * RR_CONTACT_TABLE_ROW; k++)
            if (!(data[k] == whole[k] || (isnan(data[k]) && isnan(whole[k]))))
                break;
        CHECK(k == 4 * RR_CONTACT_TABLE_ROW, "rows in parts: the same table");
    }

    /* the reproducer: nsamples = INT_MAX looped on i <= ns with signed overflow */
    o.nsamples = 2147483647;
    CHECK_STATUS(rr_contact_search(&l, 0.0, 0.1, 0.0, &o, &cl), RR_ERR_PARAM,
                 "nsamples INT_MAX refused");
    CHECK(isnan(cl.r), "refused: NaN");
    o.nsamples = RR_SEARCH_MAX_SAMPLES;
    CHECK_STATUS(rr_contact_search(&l, 0.0, 0.1, 0.0, &o, &cl), RR_OK, "nsamples at the cap");
    rr_search_opts_default(&o);
    o.two_point_tol = INFINITY;
    CHECK_STATUS(rr_contact_search(&l, 0.0, 0.1, 0.0, &o, &cl), RR_ERR_PARAM, "tol inf");
    rr_search_opts_default(&o);
    CHECK_STATUS(rr_contact_search(NULL, 0.0, 0.1, 0.0, &o, &cl), RR_ERR_NULL, "pair NULL");
    CHECK_STATUS(rr_contact_search(&l, 0.0, 0.1, 0.0, NULL, &cl), RR_ERR_NULL, "opts NULL");
    CHECK_STATUS(rr_wheelset_contact(&l, &r, 0.0, &o, &pose, NULL, &cr), RR_ERR_NULL, "cl NULL");
    /* profiles that a caller built wrong */
    l.side = 0;
    CHECK_STATUS(rr_contact_search(&l, 0.0, 0.1, 0.0, &o, &cl), RR_ERR_PARAM, "side 0");
    l.side = 1;
    l.wheel.n = 1;
    CHECK_STATUS(rr_contact_search(&l, 0.0, 0.1, 0.0, &o, &cl), RR_ERR_GEOMETRY, "one knot");
    l.wheel.n = NW;
    l.wheel.m = NULL;
    CHECK_STATUS(rr_contact_search(&l, 0.0, 0.1, 0.0, &o, &cl), RR_ERR_NULL, "no second derivatives");
    l.wheel.m = wm;
    {
        const double keep = ws_[10];
        ws_[10] = ws_[9];
        CHECK_STATUS(rr_contact_search(&l, 0.0, 0.1, 0.0, &o, &cl), RR_ERR_GEOMETRY,
                     "repeated knot");
        ws_[10] = keep;
    }
    {
        double v;
        rr_spline sp = l.wheel;
        sp.s = NULL;
        CHECK_STATUS(rr_spline_eval(&sp, 0.0, &v, NULL, NULL), RR_ERR_NULL, "eval knots NULL");
        CHECK(isnan(v), "eval knots NULL: NaN");
        CHECK_STATUS(rr_spline_eval(&l.wheel, 0.0, NULL, NULL, NULL), RR_ERR_NULL, "eval z NULL");
        CHECK_STATUS(rr_spline_init(3, NULL, wz, wm, work), RR_ERR_NULL, "init s NULL");
    }
}

int main(void)
{
    test_spline();
    test_conical();
    test_table();
    test_table_ends();
    test_off_roller();
    test_rig_contact();
    test_caller_errors();
    return rr_test_summary();
}
