/*
 * fuzz_rig.h - the default rig of the fuzz targets (that of tests/test_rig.c
 * and rollerrig/data/rig_default.toml): a 1:20 conical wheel, r0 0.092 m,
 * on a roller R0 0.16 m with a 60 mm crown, contacts 0.15 m either side;
 * its contact table is built once per process (static storage: a test
 * driver may keep state, the core may not).
 */
#ifndef RR_FUZZ_RIG_H
#define RR_FUZZ_RIG_H

#include "fuzz.h"

#define FZ_RIG_NP 61
#define FZ_RIG_NROWS 201

/* The table, built on the first call; aborts if the build fails, since
 * every target using it would then test nothing. */
static inline const rr_contact_table *fz_rig_table(void)
{
    static double ws[FZ_RIG_NP], wz[FZ_RIG_NP], wm[FZ_RIG_NP];
    static double rs[FZ_RIG_NP], rz[FZ_RIG_NP], rm[FZ_RIG_NP], work[FZ_RIG_NP];
    static double data[FZ_RIG_NROWS * RR_CONTACT_TABLE_ROW];
    static rr_contact_table t;
    static int built = 0;
    rr_wheel_roller pair[2];
    rr_search_opts o;
    int i, st;

    if (built)
        return &t;
    for (i = 0; i < FZ_RIG_NP; i++) {
        ws[i] = rs[i] = -0.015 + 0.03 * i / (FZ_RIG_NP - 1);
        wz[i] = ws[i] * 0.05;
        rz[i] = sqrt(0.06 * 0.06 - rs[i] * rs[i]) - 0.06;
    }
    if (rr_spline_init(FZ_RIG_NP, ws, wz, wm, work) != RR_OK
        || rr_spline_init(FZ_RIG_NP, rs, rz, rm, work) != RR_OK)
        fz_fail("default rig: profile splines");
    for (i = 0; i < 2; i++) {
        pair[i].wheel.n = FZ_RIG_NP;
        pair[i].wheel.s = ws;
        pair[i].wheel.z = wz;
        pair[i].wheel.m = wm;
        pair[i].roller.n = FZ_RIG_NP;
        pair[i].roller.s = rs;
        pair[i].roller.z = rz;
        pair[i].roller.m = rm;
        pair[i].r0 = 0.092;
        pair[i].R0 = 0.16;
        pair[i].wheel_y = pair[i].roller_y = 0.15;
        pair[i].side = i == 0 ? 1 : -1;
    }
    rr_search_opts_default(&o);
    t.y0 = -0.005;
    t.dy = 0.01 / (FZ_RIG_NROWS - 1);
    t.n = FZ_RIG_NROWS;
    t.data = data;
    if ((st = rr_contact_table_build(&pair[0], &pair[1], &o, &t, NULL)) != RR_OK)
        fz_fail("default rig: contact table build: status %d", st);
    built = 1;
    return &t;
}

/* The default rig's parameters (rr_rig_params_default, the declaration
 * rig_default.toml is generated from: 4 ms, TR-BDF2, one Newton iteration on
 * the simplified theory, FASTSIM 20 x 20 with falling friction at the rigid
 * slip speed) on this table. */
static inline void fz_rig_params_default(rr_rig_params *p)
{
    if (rr_rig_params_default(p) != RR_OK || rr_rig_params_set_table(p, fz_rig_table()) < 0)
        fz_fail("default rig: parameters");
}

/* The contact model of the default rig. */
static inline void fz_rig_contact_default(rr_rig_contact_model *m)
{
    rr_rig_params p;
    fz_rig_params_default(&p);
    *m = p.contact;
}

#endif
