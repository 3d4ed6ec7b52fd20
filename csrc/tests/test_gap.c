/* test_gap.c - the undeformed distance of a wheel on its roller (rr_gap) and
 * one wheel solved by the exact theory on it (rr_wheel_exact). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rr_test.h"
#include "rollerrig.h"

/* ---- a flat wheel on a roller crowned with a circle: h in closed form ---- */

#define NWF 61
#define NRC 241
#define RHO 0.05

static double fs[NWF], fz[NWF], fm[NWF], cs[NRC], cz[NRC], cm[NRC], iw[NRC];

/* A flat wheel (a cylinder of r0) on a roller crowned with a circle of RHO
 * (knots 0.25 mm apart), both at 0.75 m from the centre line. */
static void flat_on_crown(int side, rr_wheel_roller *p)
{
    int i;
    for (i = 0; i < NWF; i++) {
        fs[i] = -0.03 + 0.06 * i / (NWF - 1);
        fz[i] = 0.0;
    }
    for (i = 0; i < NRC; i++) {
        cs[i] = -0.03 + 0.06 * i / (NRC - 1);
        cz[i] = sqrt(RHO * RHO - cs[i] * cs[i]) - RHO;
    }
    rr_spline_init(NWF, fs, fz, fm, iw);
    rr_spline_init(NRC, cs, cz, cm, iw);
    p->wheel.n = NWF; p->wheel.s = fs; p->wheel.z = fz; p->wheel.m = fm;
    p->roller.n = NRC; p->roller.s = cs; p->roller.z = cz; p->roller.m = cm;
    p->r0 = 0.46;
    p->R0 = 0.46;
    p->wheel_y = 0.75;
    p->roller_y = 0.75;
    p->side = side;
}

/* R - sqrt(R^2 - x^2) */
static double drop(double R, double x)
{
    return x * x / (R + sqrt(R * R - x * x));
}

static size_t wl;
static double *work, *hbuf, *hbuf2;
#define HCAP (256 * 256)

static void test_closed_form(void)
{
    /* The plane is horizontal (delta 0 at the crown's top), so h is the
     * wheel's height over the roller's at each (x, y): with the wheelset
     * lowered by d from the zero-gap pose,
     *   h = -d + drop(r0, x) + drop(R0 + zr(y), x) - zr(y) - min,
     * zr the crown.  Rows 0.2 mm apart fall on the 0.02 mm samples, so no
     * interpolation error enters; what is left is the spline's (a natural
     * cubic through the circle at 0.25 mm: (5/384) h^4 3/rho^3 = 1.2e-12 m)
     * and rounding: 5e-12 m, 1e-7 of the approach. */
    rr_wheel_roller pl, pr;
    rr_gap_site site;
    rr_gap_opts o;
    rr_gap_patch P, Q;
    const double d = 2e-5;
    double worst = 0.0, hmin = INFINITY, *ref = malloc(HCAP * sizeof(double));
    int i, j, st, border = 0;

    flat_on_crown(1, &pl);
    rr_gap_opts_default(&o);
    o.reference = RR_GAP_POINT;
    o.approach = 5e-5;
    o.dx = o.dy = 2e-4;
    site.pair = &pl;
    site.y_ws = 0.0;
    site.z = pl.r0 - d;
    site.roll = 0.0;
    site.s_roller = site.s_wheel = site.delta = 0.0;
    wl = rr_gap_workspace_len(&o);
    work = calloc(wl, sizeof(double));
    st = rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P);
    CHECK_STATUS(st, RR_OK, "closed form: build");
    CHECK(P.nregions == 1 && P.nexcluded == 0, "closed form: one interval");
    CHECK_CLOSE(P.delta, 0.0, 1e-15, 0.0, "closed form: the plane is horizontal");
    CHECK_CLOSE(P.pen, d, 1e-15, 0.0, "closed form: the pose's interpenetration is d");
    CHECK_CLOSE(P.point[1], 0.75, 1e-15, 0.0, "closed form: P at the crown's top");
    CHECK_CLOSE(P.wheel_point[2], -d, 1e-15, 0.0, "closed form: Q = P - pen n");
    CHECK_CLOSE(P.n[2], 1.0, 0.0, 0.0, "closed form: n up");
    CHECK_CLOSE(P.t2[1], 1.0, 0.0, 0.0, "closed form: t2 toward +Y");
    /* the grid on multiples of dx, dy from P, symmetric in x */
    CHECK_CLOSE(P.grid.x0 / P.grid.dx, floor(P.grid.x0 / P.grid.dx + 0.5), 1e-9, 0.0,
                "closed form: x0 on a multiple of dx");
    CHECK_CLOSE(P.grid.x0 + (P.grid.mx - 1) * P.grid.dx, -P.grid.x0, 1e-15, 0.0,
                "closed form: symmetric in x");
    for (j = 0; j < P.grid.my; j++)
        for (i = 0; i < P.grid.mx; i++) {
            const double x = P.grid.x0 + i * P.grid.dx, y = P.grid.y0 + j * P.grid.dy;
            const double zr = sqrt(RHO * RHO - y * y) - RHO;
            const double v = -d + drop(pl.r0, x) + drop(pl.R0 + zr, x) - zr;
            ref[j * P.grid.mx + i] = v;
            hmin = v < hmin ? v : hmin;
            if ((i == 0 || j == 0 || i == P.grid.mx - 1 || j == P.grid.my - 1)
                && hbuf[j * P.grid.mx + i] <= P.level)
                border = 1;
        }
    for (i = 0; i < P.grid.mx * P.grid.my; i++)
        worst = fmax(worst, fabs(hbuf[i] - (ref[i] - hmin)));
    CHECK_CLOSE(worst, 0.0, 5e-12, 0.0, "closed form: h");
    CHECK(!border, "closed form: the region leaves the border free");
    /* samples 8e-5 m apart (rr_wheel_exact's coarse pass), which the rows
     * 0.2 mm apart fall between: the same grid, h within the chord's
     * error over the crown of radius RHO, s^2 / (8 RHO) = 1.6e-8 m, with
     * its workspace the smaller */
    o.sample = 8e-5;
    CHECK(rr_gap_workspace_len(&o) < wl, "sample 8e-5: a smaller workspace");
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf2, HCAP, &Q), RR_OK, "sample 8e-5");
    CHECK(Q.grid.mx == P.grid.mx && Q.grid.my == P.grid.my && Q.step == 8e-5,
          "sample 8e-5: the same grid, the step given");
    worst = 0.0;
    for (i = 0; i < P.grid.mx * P.grid.my && Q.grid.my == P.grid.my && Q.grid.mx == P.grid.mx;
         i++)
        worst = fmax(worst, fabs(hbuf2[i] - hbuf[i]));
    CHECK_CLOSE(worst, 0.0, 1.1 * 8e-5 * 8e-5 / (8.0 * RHO), 0.0, "sample 8e-5: h");
    o.sample = 0.0;
    /* the weighted reference of a symmetric region is the same point */
    o.reference = RR_GAP_WEIGHTED;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf2, HCAP, &Q), RR_OK, "weighted");
    CHECK_CLOSE(Q.delta, 0.0, 1e-12, 0.0, "weighted: delta");
    CHECK_CLOSE(Q.s_roller, 0.0, 1e-9, 0.0, "weighted: the centre");
    /* the right wheel at -y_ws is the left one's mirror: rows reversed */
    flat_on_crown(-1, &pr);
    o.reference = RR_GAP_POINT;
    site.pair = &pr;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf2, HCAP, &Q), RR_OK, "right");
    CHECK(Q.grid.mx == P.grid.mx && Q.grid.my == P.grid.my, "right: the grid");
    worst = 0.0;
    for (j = 0; j < P.grid.my && Q.grid.my == P.grid.my; j++)
        for (i = 0; i < P.grid.mx; i++)
            worst = fmax(worst, fabs(hbuf2[j * P.grid.mx + i]
                                     - hbuf[(P.grid.my - 1 - j) * P.grid.mx + i]));
    CHECK_CLOSE(worst, 0.0, 1e-15, 0.0, "right: mirrored h");
    CHECK_CLOSE(Q.n[1], 0.0, 1e-15, 0.0, "right: n");
    free(ref);
    free(work);
}

/* ---- the rig's default pair against the Python construction ---- */

#define NP RR_RIG_PROFILE_POINTS
static double wy[NP], wz[NP], ry[NP], rz[NP], wzu[NP], wmu[NP], rzu[NP], rmu[NP], pw[4 * NP];

/* The rig's conical wheel on its crowned roller (rig_default.toml: r0 =
 * R0 = 92 mm, cone 1:20, crown 60 mm, +-15 mm, 0.15 m out): the splines of
 * rollerrig.Profile.conical and .cylinder, as RigGeometry hands them over. */
static void rig_pair(int side, rr_wheel_roller *p)
{
    rr_profile_points w, r;
    rr_profile_conical(atan(0.05), -0.015, 0.015, NP, wy, wz);
    rr_profile_crowned(0.06, -0.015, 0.015, NP, ry, rz);
    w.n = r.n = NP;
    w.y = wy; w.z = wz; r.y = ry; r.z = rz;
    w.end = r.end = RR_SPLINE_NOT_A_KNOT;
    rr_profile_surface(&w, wzu, wmu, pw);
    rr_profile_surface(&r, rzu, rmu, pw);
    p->wheel.n = NP; p->wheel.s = wy; p->wheel.z = wzu; p->wheel.m = wmu;
    p->roller.n = NP; p->roller.s = ry; p->roller.z = rzu; p->roller.m = rmu;
    p->r0 = p->R0 = 0.092;
    p->wheel_y = p->roller_y = 0.15;
    p->side = side;
}

/* tests/_nonhertz_python.undeformed_distance(RigGeometry of rig_pair, y_ws,
 * N=N, reference=ref, n=20) (E 2.1e11, nu 0.28): the grid, frame and h at
 * five elements, printed with repr (the C build gave them within 1e-17 m).
 * RigGeometry(Profile.conical(atan(0.05), (-0.015, 0.015), n=121, r0=0.092),
 * Profile.cylinder((-0.015, 0.015), crown_radius=0.06, n=121), 0.092, 0.092,
 * 0.15, 0.15); the pose's Newton of the exact d gap / d roll moved the
 * second case's zero-gap roll by 7e-13 rad (both within its 1e-13 m gap),
 * and the numbers with it (regenerated then) */
static const struct {
    double y_ws;
    int point;
    double N;
    int mx, my;
    double dx, x0, y0, delta, s_roller, s_wheel, approach;
    struct { int j, i; double h; } at[5];
} PY[] = {
    {0.0, 0, 2000.0, 21, 24, 0.0001628972817635012, -0.001628972817635012,
     -0.0017918700993985134, 0.04995529447757563, -0.002995978368700327,
     -0.0029959783687327135, 1.4868640134691847e-05,
     {{12, 10, 2.220960141875831e-07}, {12, 1, 2.3549394838149973e-05},
      {1, 10, 2.2109177602289434e-05}, {22, 18, 4.521733946197481e-05},
      {2, 3, 3.2009965804717225e-05}}},
    {0.002, 1, 2000.0, 21, 24, 0.0001629524987944814, -0.0016295249879448139,
     -0.001955429985533777, 0.05066066163561681, -0.0030383397570823145,
     -0.00510309167224208, 1.4867240176855572e-05,
     {{12, 10, 0.0}, {12, 1, 2.3328099662100944e-05}, {1, 10, 2.6781292961473385e-05},
      {22, 18, 4.0579126206711645e-05}, {2, 3, 3.6236084373666484e-05}}},
    {-0.003, 0, 8000.0, 21, 24, 0.0002589687442018683, -0.002589687442018683,
     -0.0028486561862205513, 0.048897378867666284, -0.0029324448277705797,
     0.00016454254030275075, 3.7471984972860165e-05,
     {{12, 10, 5.617696620128811e-07}, {12, 1, 5.9577502974333064e-05},
      {1, 10, 5.5883487110984077e-05}, {22, 18, 0.00011438914361024627},
      {2, 3, 8.092781133657966e-05}}},
};

static void test_python_values(void)
{
    /* the same splines, samples and interpolation: h to rounding (1e-14 m:
     * the spline's two forms and the reference's sums, 1e-9 of h) */
    rr_wheel_roller pair[2];
    rr_search_opts so;
    rr_gap_opts o;
    rr_gap_patch P;
    int c, k;
    rig_pair(1, &pair[0]);
    pair[1] = pair[0];
    pair[1].side = -1;
    rr_search_opts_default(&so);
    rr_gap_opts_default(&o);
    o.n = 20;
    wl = rr_gap_workspace_len(&o);
    work = calloc(wl, sizeof(double));
    for (c = 0; c < RR_COUNTOF(PY); c++) {
        rr_wheelset_pose pose;
        rr_contact_point cl, cr;
        rr_hertz_result hz;
        rr_gap_site site;
        char what[64];
        CHECK_STATUS(rr_wheelset_contact(&pair[0], &pair[1], PY[c].y_ws, &so, &pose, &cl, &cr),
                     RR_OK, "python values: the zero-gap pose");
        rr_hertz(cl.A, cl.B, PY[c].N, rr_estar(2.1e11, 0.28, 2.1e11, 0.28), &hz);
        CHECK_CLOSE(hz.delta, PY[c].approach, 0.0, 1e-14, "python values: Hertz's approach");
        site.pair = &pair[0];
        site.y_ws = PY[c].y_ws;
        site.z = pose.z;
        site.roll = pose.roll;
        site.s_roller = cl.s_roller;
        site.s_wheel = cl.s_wheel;
        site.delta = cl.delta;
        o.reference = PY[c].point ? RR_GAP_POINT : RR_GAP_WEIGHTED;
        o.approach = hz.delta;
        snprintf(what, sizeof what, "python values, case %d", c);
        CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_OK, what);
        CHECK(P.grid.mx == PY[c].mx && P.grid.my == PY[c].my, what);
        CHECK_CLOSE(P.grid.dx, PY[c].dx, 0.0, 1e-12, what);
        CHECK_CLOSE(P.grid.x0, PY[c].x0, 1e-15, 0.0, what);
        CHECK_CLOSE(P.grid.y0, PY[c].y0, 1e-15, 0.0, what);
        CHECK_CLOSE(P.delta, PY[c].delta, 1e-13, 0.0, what);
        CHECK_CLOSE(P.s_roller, PY[c].s_roller, 1e-14, 0.0, what);
        CHECK_CLOSE(P.s_wheel, PY[c].s_wheel, 1e-14, 0.0, what);
        for (k = 0; k < 5; k++)
            CHECK_CLOSE(hbuf[PY[c].at[k].j * P.grid.mx + PY[c].at[k].i], PY[c].at[k].h, 1e-14,
                        0.0, what);
    }
    free(work);
}

/* keep = 1 with a band holding the whole region gives the same patch and
 * h as CONTACT's grouping (one region); a band over half of it holds that
 * half: its lateral extent within the band (plus the grid's exterior
 * element), the same plane construction. */
static void test_keep_band(void)
{
    rr_wheel_roller p;
    rr_gap_site site;
    rr_gap_opts o;
    rr_gap_patch P, Q;
    static double h2[HCAP];
    size_t k;
    int same = 1;
    flat_on_crown(1, &p);
    rr_gap_opts_default(&o);
    o.approach = 5e-5;
    site.pair = &p;
    site.y_ws = 0.0;
    site.z = p.r0;
    site.roll = 0.0;
    site.s_roller = site.s_wheel = site.delta = 0.0;
    wl = rr_gap_workspace_len(&o);
    work = calloc(wl, sizeof(double));
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_OK, "keep: CONTACT's");
    o.keep = 1;
    o.keep_lo = -1.0;
    o.keep_hi = 1.0;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, h2, HCAP, &Q), RR_OK, "keep: a wide band");
    CHECK(Q.grid.mx == P.grid.mx && Q.grid.my == P.grid.my && Q.delta == P.delta
          && Q.pen == P.pen, "keep: a wide band, the same grid and plane");
    for (k = 0; k < (size_t)P.grid.mx * (size_t)P.grid.my; k++)
        same &= hbuf[k] == h2[k];
    CHECK(same, "keep: a wide band, the same h");
    o.keep_lo = P.point[1];          /* from P's lateral place on */
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, h2, HCAP, &Q), RR_OK, "keep: half");
    /* in rig Y (each plane has its own reference point): from the band's
     * start to the region's end, a sample apart */
    CHECK(fabs(Q.point[1] + Q.lo * Q.t2[1] - P.point[1]) <= 2.0 * Q.step
          && fabs(Q.point[1] + Q.hi * Q.t2[1] - (P.point[1] + P.hi * P.t2[1])) <= 2.0 * Q.step
          && Q.grid.my < P.grid.my, "keep: half the band, half the region");
    free(work);
}

/* ---- bad inputs ---- */

static void test_bad_inputs(void)
{
    rr_wheel_roller p, q;
    rr_gap_site site;
    rr_gap_opts o;
    rr_gap_patch P;
    double saved;
    flat_on_crown(1, &p);
    rr_gap_opts_default(&o);
    o.approach = 5e-5;
    site.pair = &p;
    site.y_ws = 0.0;
    site.z = p.r0;
    site.roll = 0.0;
    site.s_roller = site.s_wheel = site.delta = 0.0;
    wl = rr_gap_workspace_len(&o);
    work = calloc(wl, sizeof(double));
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, NULL), RR_ERR_NULL, "out NULL");
    CHECK_STATUS(rr_gap_build(NULL, &o, work, wl, hbuf, HCAP, &P), RR_ERR_NULL, "site NULL");
    CHECK(isnan(P.delta) && isnan(P.grid.dx), "NULL: the outputs NaN");
    CHECK_STATUS(rr_gap_build(&site, NULL, work, wl, hbuf, HCAP, &P), RR_ERR_NULL, "opts NULL");
    CHECK_STATUS(rr_gap_build(&site, &o, NULL, wl, hbuf, HCAP, &P), RR_ERR_WORKSPACE, "work");
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl - 1, hbuf, HCAP, &P), RR_ERR_WORKSPACE,
                 "work short");
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, NULL, 0, &P), RR_ERR_WORKSPACE, "h NULL");
    CHECK(P.why == RR_GAP_H_BUFFER && P.grid.mx > 0 && P.grid.my > 0,
          "h NULL: the grid it needs is given");
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, 10, &P), RR_ERR_WORKSPACE, "h short");
    site.z = NAN;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_NONFINITE, "z NaN");
    site.z = p.r0;
    saved = o.approach;
    o.approach = 0.0;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_PARAM, "approach 0");
    o.approach = saved;
    o.cover = 0.5;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_PARAM, "cover");
    o.cover = 1.5;
    o.n = 3;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_PARAM, "n");
    o.n = 40;
    o.combine = -1e-3;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_PARAM, "combine");
    o.combine = 4e-3;
    o.sample = -1e-5;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_PARAM, "sample < 0");
    CHECK(rr_gap_workspace_len(&o) == 0, "sample < 0: no workspace length");
    o.sample = 0.5 * RR_GAP_SAMPLE_MIN;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_PARAM,
                 "sample below its least");
    o.sample = 2.0 * RR_GAP_SAMPLE_MAX;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_PARAM,
                 "sample beyond its most");
    o.sample = NAN;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_NONFINITE,
                 "sample NaN");
    o.sample = 0.0;
    o.keep = 2;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_PARAM, "keep 2");
    o.keep = 1;
    o.keep_lo = NAN;
    o.keep_hi = 1.0;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_NONFINITE,
                 "keep_lo NaN");
    o.keep_lo = 1.0;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_PARAM,
                 "keep_lo = keep_hi");
    o.keep_lo = 2.0;              /* a band the gap does not reach */
    o.keep_hi = 3.0;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_GEOMETRY,
                 "keep: no sample in the band");
    CHECK(P.why == RR_GAP_KEEP, "keep: the band named");
    o.keep = 0;
    o.reference = 7;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_PARAM, "reference");
    o.reference = RR_GAP_GIVEN;
    o.delta = 2.0;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_PARAM,
                 "reference angle beyond pi/2");
    o.delta = 0.0;
    o.s_roller = 0.035;            /* within the window, off the profile */
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_GEOMETRY, "off");
    CHECK(P.why == RR_GAP_OFF_PROFILE && P.off_body == 0 && P.off_s == 0.035,
          "off the roller's profile, named");
    o.reference = RR_GAP_WEIGHTED;
    q = p;
    q.side = 0;
    site.pair = &q;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_PARAM, "side 0");
    q = p;
    q.R0 = -1.0;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_PARAM, "R0 < 0");
    q = p;
    q.roller.m = NULL;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_NULL, "spline");
    site.pair = &p;
    /* an approach whose region reaches the profiles' ends in the plane */
    o.approach = 0.01;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_RANGE, "huge");
    CHECK(P.why == RR_GAP_REGION_ENDS && P.plane_lo < P.plane_hi, "huge: the ends, named");
    /* one that underflows the reference's weights */
    o.approach = 1e-130;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_RANGE, "tiny");
    CHECK(P.why == RR_GAP_WEIGHTS, "tiny: the weights, named");
    o.approach = 5e-5;
    /* elements far too small: counted and refused before h is touched */
    o.dx = o.dy = 1e-9;
    free(work);
    wl = rr_gap_workspace_len(&o);
    work = calloc(wl, sizeof(double));
    CHECK(work != NULL, "1e-7 m samples: 13 windows of 800 003");
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, NULL, 0, &P), RR_ERR_GRID, "tiny elements");
    CHECK(P.why == RR_GAP_TOO_MANY && P.need_mx > 1e6 && P.need_my > 1e6,
          "tiny elements: the counts it would need");
    o.dx = o.dy = 1e-300;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, NULL, 0, &P), RR_ERR_GRID, "1e-300 m");
    CHECK(!(P.need_mx <= RR_EXACT_MAX_GRID), "1e-300 m: counted in doubles");
    o.dx = o.dy = 0.0;
    /* the wheel beside its roller */
    site.y_ws = 0.2;
    CHECK_STATUS(rr_gap_build(&site, &o, work, wl, hbuf, HCAP, &P), RR_ERR_GEOMETRY, "apart");
    CHECK(P.why == RR_GAP_APART, "apart, named");
    CHECK_CLOSE((double)rr_gap_workspace_len(NULL), 0.0, 0.0, 0.0, "workspace: NULL");
    o.dx = NAN;
    CHECK_CLOSE((double)rr_gap_workspace_len(&o), 0.0, 0.0, 0.0, "workspace: dx NaN");
    free(work);
}

/* ---- rr_wheel_exact ---- */

static void test_wheel_exact(void)
{
    /* The rig's cone on its crowned roller, where the patch is an ellipse:
     * the exact solution's area and approach are Hertz's to the grid's
     * discretisation (30 elements across: 2 % and 0.5 %, as test_exact's
     * ellipses), the vertical balance holds to the solver's tolerance, a
     * grid beyond the workspace is refused with the workspace it needs. */
    rr_wheel_roller pair[2];
    rr_search_opts so;
    rr_wheel_exact_problem pb;
    rr_wheel_exact_result r, r2;
    rr_contact_point cl, cr;
    rr_hertz_result hz;
    rr_exact_field f;
    double *w, *pn = malloc(HCAP * sizeof(double));
    signed char *state = malloc(HCAP);
    size_t len, cells = 48 * 48;
    int st;
    rig_pair(1, &pair[0]);
    pair[1] = pair[0];
    pair[1].side = -1;
    rr_search_opts_default(&so);
    rr_wheel_exact_default(&pb);
    pb.pair = &pair[0];
    pb.y_ws = 0.001;
    rr_wheelset_contact(&pair[0], &pair[1], pb.y_ws, &so, &pb.pose0, &cl, &cr);
    pb.point = cl;
    pb.N = 5000.0;
    pb.mu = 0.3;
    pb.cx = 1e-3;
    pb.gap.n = 30;
    len = rr_wheel_exact_workspace_len(&pb, 48, 48);
    CHECK(len > 0, "wheel: workspace length");
    w = calloc(len, sizeof(double));
    memset(&f, 0, sizeof f);
    f.pn = pn;
    f.state = state;
    st = rr_wheel_exact(&pb, w, len, hbuf, cells, &f, cells, &r);
    CHECK_STATUS(st, RR_OK, "wheel: N given");
    rr_hertz(cl.A, cl.B, pb.N, rr_estar(pb.E, pb.nu, pb.E, pb.nu), &hz);
    CHECK_CLOSE(r.sol.area, RR_PI * hz.a * hz.b, 0.0, 0.03, "wheel: Hertz's area");
    CHECK_CLOSE(r.sol.delta, hz.delta, 0.0, 0.01, "wheel: Hertz's approach");
    CHECK_CLOSE(r.sol.fn, pb.N, 0.0, 1e-6, "wheel: the load");
    CHECK(r.passes == 2 && r.cx == 1e-3 && r.V == 0.0, "wheel: two passes, cx as given");
    CHECK_CLOSE(r.lowered * cos(cl.delta), r.approach, 0.0, 1e-12,
                "wheel: lowered by the approach over cos(delta)");
    CHECK_CLOSE(r.force[2], r.sol.fn * r.patch.n[2] + r.sol.fy * r.patch.t2[2], 1e-9, 0.0,
                "wheel: the force in the rig frame");
    {
        double sum = 0.0;
        int k;
        for (k = 0; k < r.patch.grid.mx * r.patch.grid.my; k++)
            sum += pn[k];
        CHECK_CLOSE(sum * r.patch.grid.dx * r.patch.grid.dy, pb.N, 0.0, 1e-6,
                    "wheel: the pressure field carries the load");
    }
    /* the vertical load */
    pb.N = 0.0;
    pb.Fz = 5000.0;
    st = rr_wheel_exact(&pb, w, len, hbuf, cells, NULL, 0, &r2);
    CHECK_STATUS(st, RR_OK, "wheel: Fz");
    /* to the solver's tolerance (rr_wheel_exact.c, FZ_TOL) */
    CHECK_CLOSE(r2.force[2], pb.Fz, 0.0, pb.tol, "wheel: the vertical balance");
    CHECK(r2.passes > r.passes, "wheel: Fz takes more solves");
    /* creepages from the motions: at the zero-gap pose with the rigid
     * contact point's frame, Q is P, and they are rr_creepage's there (the
     * rig's kinematics, rr_creepage.h) to rounding */
    {
        rr_motion roller;
        rr_contact_frame fr;
        rr_creepages kc;
        const double spin = 10.0 * cl.R / cl.r * (1.0 - 2e-3);   /* braked 0.2 % */
        int k;
        pb.creep_given = 0;
        pb.roller_spin = 10.0;
        pb.wheelset.c[0] = 0.0;
        pb.wheelset.c[1] = pb.y_ws;
        pb.wheelset.c[2] = pb.pose0.z;
        pb.wheelset.w[0] = 0.0;
        pb.wheelset.w[1] = spin * cos(pb.pose0.roll);
        pb.wheelset.w[2] = spin * sin(pb.pose0.roll);
        pb.wheelset.v[0] = pb.wheelset.v[1] = pb.wheelset.v[2] = 0.0;
        pb.gap.reference = RR_GAP_POINT;
        pb.loaded = 0;
        st = rr_wheel_exact(&pb, w, len, hbuf, cells, NULL, 0, &r2);
        CHECK_STATUS(st, RR_OK, "wheel: kinematics");
        memset(&roller, 0, sizeof roller);
        roller.c[2] = -pb.pair->R0;
        roller.w[1] = -pb.roller_spin;
        for (k = 0; k < 3; k++) {
            fr.p[k] = r2.patch.point[k];
            fr.t1[k] = r2.patch.t1[k];
            fr.t2[k] = r2.patch.t2[k];
        }
        CHECK_CLOSE(r2.patch.pen, 0.0, 1e-15, 0.0, "wheel: no interpenetration unloaded");
        CHECK_STATUS(rr_creepage(&pb.wheelset, &roller, &fr, pb.vmin, &kc), RR_OK, "creepage");
        CHECK_CLOSE(r2.cx, kc.cx, 1e-12, 0.0, "wheel: cx as rr_creepage");
        CHECK_CLOSE(r2.cy, kc.cy, 1e-12, 0.0, "wheel: cy as rr_creepage");
        CHECK_CLOSE(r2.cphi, kc.cphi, 1e-10, 1e-12, "wheel: cphi as rr_creepage");
        CHECK_CLOSE(r2.V, kc.V, 0.0, 1e-13, "wheel: V as rr_creepage");
        CHECK(fabs(r2.cx - 2e-3) < 1e-4 && r2.sol.fx < 0.0, "wheel: a braked wheel");
        pb.gap.reference = RR_GAP_WEIGHTED;
        pb.loaded = 1;
    }
    pb.creep_given = 1;
    /* the workspace for 48 x 48, a grid of 0.05 mm elements needs more */
    pb.gap.dx = pb.gap.dy = 5e-5;
    free(w);
    len = rr_wheel_exact_workspace_len(&pb, 48, 48);
    w = calloc(len, sizeof(double));
    st = rr_wheel_exact(&pb, w, len, hbuf, cells, NULL, 0, &r2);
    CHECK_STATUS(st, RR_ERR_WORKSPACE, "wheel: grid beyond the workspace");
    CHECK(r2.need > len && r2.patch.grid.mx > 48, "wheel: what it needs, named");
    CHECK(isnan(r2.force[2]), "wheel: a failure's force NaN");
    pb.gap.dx = pb.gap.dy = 0.0;
    /* bad inputs */
    CHECK_STATUS(rr_wheel_exact(&pb, w, len, hbuf, cells, NULL, 0, NULL), RR_ERR_NULL, "NULL");
    CHECK_STATUS(rr_wheel_exact(NULL, w, len, hbuf, cells, NULL, 0, &r2), RR_ERR_NULL, "pb");
    CHECK_STATUS(rr_wheel_exact(&pb, w, len, NULL, cells, NULL, 0, &r2), RR_ERR_NULL, "h");
    pb.N = 1.0;
    CHECK_STATUS(rr_wheel_exact(&pb, w, len, hbuf, cells, NULL, 0, &r2), RR_ERR_LOAD,
                 "N and Fz both");
    pb.N = pb.Fz = 0.0;
    CHECK_STATUS(rr_wheel_exact(&pb, w, len, hbuf, cells, NULL, 0, &r2), RR_ERR_LOAD,
                 "neither N nor Fz");
    pb.Fz = 5000.0;
    pb.mu = 0.0;
    CHECK_STATUS(rr_wheel_exact(&pb, w, len, hbuf, cells, NULL, 0, &r2), RR_ERR_FRICTION, "mu");
    pb.mu = 0.3;
    pb.nu = 0.6;
    CHECK_STATUS(rr_wheel_exact(&pb, w, len, hbuf, cells, NULL, 0, &r2), RR_ERR_MATERIAL, "nu");
    pb.nu = 0.28;
    pb.passes = 3;
    CHECK_STATUS(rr_wheel_exact(&pb, w, len, hbuf, cells, NULL, 0, &r2), RR_ERR_PARAM, "passes");
    pb.passes = 2;
    pb.vmin = 0.0;
    CHECK_STATUS(rr_wheel_exact(&pb, w, len, hbuf, cells, NULL, 0, &r2), RR_ERR_SPEED, "vmin");
    pb.vmin = 1e-3;
    pb.z = INFINITY;
    CHECK_STATUS(rr_wheel_exact(&pb, w, len, hbuf, cells, NULL, 0, &r2), RR_ERR_NONFINITE, "z");
    pb.z = NAN;
    pb.Fz = 1e12;                  /* the region runs off the profiles */
    st = rr_wheel_exact(&pb, w, len, hbuf, cells, NULL, 0, &r2);
    CHECK(st < 0 && r2.why == RR_WHEEL_EXACT_GAP && r2.fail_pass == 1,
          "wheel: a load beyond the profiles, named at the first pass");
    CHECK_STATUS(rr_wheel_exact(&pb, w, 10, hbuf, cells, NULL, 0, &r2), RR_ERR_WORKSPACE,
                 "wheel: workspace far too short");
    CHECK_CLOSE((double)rr_wheel_exact_workspace_len(&pb, 0, 5), 0.0, 0.0, 0.0,
                "wheel: a size of 0");
    free(w);
    free(pn);
    free(state);
}

int main(void)
{
    hbuf = malloc(HCAP * sizeof(double));
    hbuf2 = malloc(HCAP * sizeof(double));
    test_closed_form();
    test_python_values();
    test_keep_band();
    test_bad_inputs();
    test_wheel_exact();
    free(hbuf);
    free(hbuf2);
    return rr_test_summary();
}
