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

/* The contact model of the default rig: FASTSIM 20 x 20 with falling
 * friction at the rigid slip speed. */
static inline void fz_rig_contact_default(rr_rig_contact_model *m)
{
    memset(m, 0, sizeof *m);
    m->table = fz_rig_table();
    m->R0 = 0.16;
    m->estar = rr_estar(2.1e11, 0.28, 2.1e11, 0.28);
    m->G = 2.1e11 / 2.56;
    m->nu = 0.28;
    m->friction.mu0 = 0.4;
    m->friction.A = 0.4;
    m->friction.B = 0.6;
    rr_creep_opts_default(&m->creep, RR_METHOD_FASTSIM);
    m->creep.v[RR_FASTSIM_NX] = m->creep.v[RR_FASTSIM_NY] = 20;
    m->creep.v[RR_FASTSIM_SLIP_SPEED] = RR_SLIP_RIGID;
    m->vmin = 0.01;
}

/* The default rig's parameters at sample time 4 ms (TR-BDF2, one Newton
 * iteration on the simplified theory, as rig_default.toml). */
static inline void fz_rig_params_default(rr_rig_params *p)
{
    const rr_contact_table *t = fz_rig_table();
    rr_wheelset_pose pose;
    rr_contact_point cl, cr;

    memset(p, 0, sizeof *p);
    p->mass = 14.504;
    p->Iyy = 0.536;
    p->Izz = 0.3584;
    p->axlebox_y = 0.2;
    p->kx = 6.2782e6;
    p->ky = 7.768e5;
    p->kz = 2.44e5;
    p->cx = 4117.0;
    p->cy = 509.4;
    p->cz = 160.0;
    p->preload = 900.85;
    p->g = 9.81;
    p->roller_inertia = 1.5;
    fz_rig_contact_default(&p->contact);
    p->T = 0.004;
    p->nsub = 1;
    p->method = RR_ODE_TRBDF2;
    p->newton_iters = 1;
    p->linear_tr = 1;
    p->newton_model = 1;
    p->roller_pi.T = p->wheelset_pi.T = p->roller_enc.T = p->wheelset_enc.T = p->T;
    p->roller_pi.Kp = 300.0;
    p->roller_pi.KI = 2.0;
    p->roller_pi.Tmax = 100.0;
    p->wheelset_pi.Kp = 100.0;
    p->wheelset_pi.KI = 2.0;
    p->wheelset_pi.Tmax = 60.0;
    p->roller_tau = p->wheelset_tau = 1e-3;
    p->roller_enc.counts = p->wheelset_enc.counts = 8388608;
    rr_contact_table_lookup(t, 0.0, &pose, NULL, &cl, &cr);
    p->creepctl.r_w = cl.r;
    p->creepctl.r_r = cl.R;
    p->creepctl.alpha = 0.01;
    p->creepctl.beta = 0.002;
    p->creepctl.vmin = 0.1;
    p->creepctl.sense = RR_CREEPCTL_BRAKING;
}

#endif
