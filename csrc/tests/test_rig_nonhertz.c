/*
 * test_rig_nonhertz.c - the rig's contact on the non-Hertzian patch
 * (rr_rig_contact.h, Patch): the model's checks of its tables, and one
 * evaluation against the Hertz path on tables written from Hertz's theory
 * at the default rig's rigid contact points (the cone on its crowned
 * cylinder), where rr_nonhertz_wheel is Hertz's ellipse with the exact
 * table's forces: the Hertz path with method exact_table is the reference.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rr_test.h"
#include "rollerrig.h"

#define NROWS 5
#define DY 2e-4

static double rows[2][NROWS * RR_NH_ROW_LEN];
static double tdata[400 * RR_CONTACT_TABLE_ROW];
static double twork[RR_RIG_TABLE_WORK_LEN];

/* Row of side k at shift y: Hertz's patch at the table's rigid contact
 * point (plane through it at its contact angle), q = N / e^1.5 and the
 * coefficients Kalker's at nine loads, no correction. */
static void hertz_row(const rr_contact_table *t, const rr_rig_contact_model *m, int k, double y,
                      double *r)
{
    rr_wheelset_pose pose;
    rr_contact_point g[2];
    rr_kalker_coeffs kc;
    double *p = r + RR_NH_PATCH(0);
    int j, c;
    rr_contact_table_lookup(t, y, &pose, NULL, &g[0], &g[1]);
    memset(r, 0, RR_NH_ROW_LEN * sizeof *r);
    r[0] = y;
    r[1] = 1.0;
    r[2] = pose.z;
    r[3] = pose.roll;
    for (j = 0; j < RR_NH_NODES; j++) {
        const double N = 20.0 * pow(1.6, j);
        rr_hertz_result h;
        double c2;
        rr_hertz(g[k].A, g[k].B, N, m->estar, &h);
        rr_kalker(h.a / h.b, m->nu, &kc);
        c2 = h.a * h.b;
        p[RR_NH_NODE(RR_NH_E, j)] = h.delta;
        p[RR_NH_NODE(RR_NH_Q, j)] = N / pow(h.delta, 1.5);
        p[RR_NH_NODE(RR_NH_PY, j)] = g[k].y;
        p[RR_NH_NODE(RR_NH_PZ, j)] = g[k].z;
        p[RR_NH_NODE(RR_NH_DELTA, j)] = g[k].delta;
        p[RR_NH_NODE(RR_NH_AREA, j)] = RR_PI * c2 / pow(N, 2.0 / 3.0);
        p[RR_NH_NODE(RR_NH_PMAX, j)] = h.p0 / cbrt(N);
        p[RR_NH_NODE(RR_NH_AB, j)] = h.a / h.b;
        p[RR_NH_NODE(RR_NH_K11, j)] = m->G * c2 * kc.c11;
        p[RR_NH_NODE(RR_NH_K22, j)] = m->G * c2 * kc.c22;
        p[RR_NH_NODE(RR_NH_K23, j)] = m->G * c2 * sqrt(c2) * kc.c23;
    }
    for (c = 0; c < RR_NH_CORR; c++)
        p[RR_NH_CORR_AT(c)] = p[RR_NH_NODE(RR_NH_E, c == 0 ? RR_NH_CORR_NODE0 : RR_NH_CORR_NODE1)];
}

int main(void)
{
    rr_rig_params prm;
    rr_rig_config cfg;
    rr_rig_geometry geo;
    rr_contact_table t;
    rr_rig_contact_model hz, nh;
    rr_nh_table tab[2], bad;
    rr_rig_state s;
    rr_rig_pose ph, pn;
    rr_wheel_contact wh[2], wn[2];
    rr_creep_checked ck;
    const double N[2] = {520.0, 530.0};
    double r0;
    int i, k, st;

    rr_rig_config_default(&cfg);
    rr_rig_geometry_from(&cfg, &geo);
    CHECK_STATUS(rr_rig_table_build(&geo, tdata, (long)RR_COUNTOF(tdata), twork,
                                    RR_RIG_TABLE_WORK_LEN, &t, NULL), RR_OK, "table");
    CHECK_STATUS(rr_rig_params_from(&cfg, &t, &prm), RR_OK, "params");
    hz = prm.contact;
    hz.friction.A = 1.0;                 /* Coulomb: the exact table's law */
    hz.friction.B = 0.0;
    rr_creep_opts_default(&hz.creep, rr_method_find("exact_table"));
    CHECK_STATUS(rr_creep_check(&ck, &hz.creep, NULL), RR_OK, "exact_table");
    for (k = 0; k < 2; k++) {
        for (i = 0; i < NROWS; i++)
            hertz_row(&t, &hz, k, (i - NROWS / 2) * DY, rows[k] + i * RR_NH_ROW_LEN);
        tab[k].nrows = NROWS;
        tab[k].rows = rows[k];
        tab[k].sigma = k == 0 ? 1.0 : -1.0;
        tab[k].R0 = hz.R0;
        tab[k].G = hz.G;
        tab[k].nu = hz.nu;
        tab[k].mu_ref = 0.4;
    }

    /* the model's checks */
    nh = hz;
    nh.patch = RR_RIG_PATCH_NONHERTZ;
    CHECK_STATUS(rr_rig_contact_check(&nh), RR_ERR_NULL, "nonhertz: no tables");
    CHECK_STATUS(rr_rig_params_set_nonhertz(&prm, &tab[0], NULL), RR_ERR_NULL,
                 "set_nonhertz: a side missing");
    nh.nonhertz[0] = &tab[1];
    nh.nonhertz[1] = &tab[0];
    CHECK_STATUS(rr_rig_contact_check(&nh), RR_ERR_TABLE, "nonhertz: sides swapped");
    nh.nonhertz[0] = &tab[0];
    nh.nonhertz[1] = &tab[1];
    CHECK_STATUS(rr_rig_contact_check(&nh), RR_OK, "nonhertz: the model");
    bad = tab[1];
    bad.G *= 1.01;
    nh.nonhertz[1] = &bad;
    CHECK_STATUS(rr_rig_contact_check(&nh), RR_ERR_TABLE, "nonhertz: another material");
    bad = tab[1];
    bad.nrows = 1;
    CHECK_STATUS(rr_rig_contact_check(&nh), RR_ERR_TABLE, "nonhertz: an invalid table");
    nh.nonhertz[1] = &tab[1];
    nh.patch = 2;
    CHECK_STATUS(rr_rig_contact_check(&nh), RR_ERR_PARAM, "an unknown patch");
    nh.patch = RR_RIG_PATCH_NONHERTZ;

    /* one braked, sliding state between rows: the two paths agree.  The
     * patch is Hertz's at the table's rows, its forces the exact table's
     * plus no correction; what differs: the rows' results blended in y
     * (Hertz's a, b move by 1e-4 between rows), the nonhertz load carrying
     * the vertical load N n_z with the creep forces' vertical share (its
     * normal load N - fy tan(delta): 0.4 % less here, where Hertz's
     * carries N along n), the creepages of each row's pose.  The creep
     * forces (per unit of the patches' load, at N) within 0.002 mu N; the
     * rig-frame force, at the patch's own normal load, within 0.005 mu N;
     * the equivalent ellipse within 3e-3 (a, b ~ N^(1/3)). */
    r0 = 0.092;
    memset(&s, 0, sizeof s);
    s.y = 0.5 * DY + 1e-5;
    s.vy = 0.002;
    s.roller_spin = 5.0 / hz.R0;
    s.spin = 5.0 / r0 * 0.995;
    st = rr_rig_contact(&hz, &s, N, &ph, wh);
    CHECK_STATUS(st, RR_OK, "hertz: evaluation");
    memset(wn, 0, sizeof wn);            /* no seed (rr_wheel_contact.nh_tz) */
    st = rr_rig_contact(&nh, &s, N, &pn, wn);
    CHECK_STATUS(st, RR_OK, "nonhertz: evaluation");
    for (k = 0; k < 2; k++) {
        const double muN = 0.4 * N[k];
        CHECK(fabs(wn[k].f.fx - wh[k].f.fx) < 0.002 * muN, "nonhertz: fx is Hertz's");
        CHECK(fabs(wn[k].f.fy - wh[k].f.fy) < 0.002 * muN, "nonhertz: fy is Hertz's");
        CHECK(fabs(wn[k].force[0] - wh[k].force[0]) < 0.005 * muN, "nonhertz: force x");
        CHECK(fabs(wn[k].force[1] - wh[k].force[1]) < 0.005 * muN, "nonhertz: force y");
        /* the vertical load given is N n_z, carried to the balance's 1e-4 */
        CHECK(fabs(wn[k].force[2] - N[k] * wn[k].n[2]) < 1e-4 * N[k], "nonhertz: force z");
        CHECK(hypot(wn[k].f.fx, wn[k].f.fy) <= muN, "nonhertz: within mu N");
        CHECK(fabs(wn[k].hertz.a / wh[k].hertz.a - 1.0) < 3e-3
                  && fabs(wn[k].hertz.b / wh[k].hertz.b - 1.0) < 3e-3,
              "nonhertz: the equivalent ellipse is Hertz's");
    }
    /* the checked path gives the same doubles */
    {
        rr_rig_contact_checked kc;
        rr_rig_pose p2;
        rr_wheel_contact w2[2];
        memset(w2, 0, sizeof w2);
        memset(wn, 0, sizeof wn);
        CHECK_STATUS(rr_rig_contact(&nh, &s, N, &pn, wn), RR_OK, "nonhertz: again");
        CHECK_STATUS(rr_rig_contact_bind(&kc, &nh, NULL, 0), RR_OK, "nonhertz: bound");
        CHECK_STATUS(rr_rig_contact_eval_checked(&kc, &s, N, &p2, w2), RR_OK,
                     "nonhertz: checked");
        CHECK(memcmp(w2[0].force, wn[0].force, sizeof w2[0].force) == 0
                  && memcmp(w2[1].moment, wn[1].moment, sizeof w2[1].moment) == 0,
              "nonhertz: checked, bit for bit");
        /* the same state and load again: the seed that evaluation started from,
         * the same doubles (a re-evaluation after a rebind, a restored state) */
        CHECK_STATUS(rr_rig_contact_eval_checked(&kc, &s, N, &p2, w2), RR_OK,
                     "nonhertz: again, seeded");
        CHECK(memcmp(w2[0].force, wn[0].force, sizeof w2[0].force) == 0,
              "nonhertz: the same state again, bit for bit");
        /* a neighbouring state: seeded by the evaluation before, the forces of
         * an unseeded evaluation within the balance's tolerance (1e-4 Fz moves
         * them by about 1e-4 mu N) */
        s.spin *= 1.0 + 1e-7;
        CHECK_STATUS(rr_rig_contact_eval_checked(&kc, &s, N, &p2, w2), RR_OK,
                     "nonhertz: seeded");
        memset(wn, 0, sizeof wn);
        CHECK_STATUS(rr_rig_contact(&nh, &s, N, &pn, wn), RR_OK, "nonhertz: unseeded");
        CHECK(fabs(w2[0].f.fx - wn[0].f.fx) < 1e-3 * 0.4 * N[0]
                  && fabs(w2[1].f.fy - wn[1].f.fy) < 1e-3 * 0.4 * N[1],
              "nonhertz: seeded, the same forces");
        s.spin /= 1.0 + 1e-7;
    }
    /* beyond the rows: that wheel's RR_ERR_TABLE, NaN; a falling law passes */
    s.y = (NROWS / 2 + 1) * DY;
    st = rr_rig_contact(&nh, &s, N, &pn, wn);
    CHECK_STATUS(st, RR_ERR_TABLE, "nonhertz: beyond the rows");
    CHECK(wn[0].status == RR_ERR_TABLE && wn[0].force[0] != wn[0].force[0],
          "nonhertz: the wheel off its table is NaN");
    s.y = 0.0;
    nh.friction.A = 0.4;
    nh.friction.B = 0.6;
    CHECK_STATUS(rr_rig_contact(&nh, &s, N, &pn, wn), RR_OK, "nonhertz: falling law");
    CHECK(fabs(wn[0].f.fx) < 0.4 * N[0], "nonhertz: falling law below mu0 N");
    return rr_test_summary();
}
