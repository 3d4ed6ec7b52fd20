/* test_rig.c - the rig in time: equilibrium, Jacobian, fixed cost, errors. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rr_test.h"
#include "rollerrig.h"

#define NP 61
#define NROWS 201

static double ws[NP], wz[NP], wm[NP], rs[NP], rz[NP], rm[NP], work[NP];
static double table_data[NROWS * RR_CONTACT_TABLE_ROW];

/* The default rig (rollerrig/data/rig_default.toml): 1:20 cone, r0 0.092 m,
 * on a roller R0 0.16 m with a 60 mm crown, contacts 0.15 m out. */
static void setup(rr_contact_table *t, rr_rig_params *p)
{
    rr_wheel_roller pair[2];
    rr_search_opts o;
    int i;
    for (i = 0; i < NP; i++) {
        ws[i] = rs[i] = -0.015 + 0.03 * i / (NP - 1);
        wz[i] = ws[i] * 0.05;
        rz[i] = sqrt(0.06 * 0.06 - rs[i] * rs[i]) - 0.06;
    }
    rr_spline_init(NP, ws, wz, wm, work);
    rr_spline_init(NP, rs, rz, rm, work);
    for (i = 0; i < 2; i++) {
        pair[i].wheel.n = NP; pair[i].wheel.s = ws; pair[i].wheel.z = wz; pair[i].wheel.m = wm;
        pair[i].roller.n = NP; pair[i].roller.s = rs; pair[i].roller.z = rz;
        pair[i].roller.m = rm;
        pair[i].r0 = 0.092; pair[i].R0 = 0.16;
        pair[i].wheel_y = pair[i].roller_y = 0.15;
        pair[i].side = i == 0 ? 1 : -1;
    }
    rr_search_opts_default(&o);
    t->y0 = -0.005; t->dy = 0.01 / (NROWS - 1); t->n = NROWS; t->data = table_data;
    CHECK_STATUS(rr_contact_table_build(&pair[0], &pair[1], &o, t, NULL), RR_OK, "table");

    memset(p, 0, sizeof *p);
    p->mass = 14.504; p->Iyy = 0.536; p->Izz = 0.3584; p->axlebox_y = 0.2;
    p->kx = 6.2782e6; p->ky = 7.768e5; p->kz = 2.44e5;
    p->cx = 4117.0; p->cy = 509.4; p->cz = 160.0;
    p->preload = 900.85; p->g = 9.81; p->roller_inertia = 1.5;
    p->contact.table = t; p->contact.R0 = 0.16;
    p->contact.estar = rr_estar(2.1e11, 0.28, 2.1e11, 0.28);
    p->contact.G = 2.1e11 / 2.56; p->contact.nu = 0.28;
    p->contact.friction.mu0 = 0.4; p->contact.friction.A = 0.4; p->contact.friction.B = 0.6;
    rr_creep_opts_default(&p->contact.creep, RR_METHOD_FASTSIM);
    p->contact.creep.v[RR_FASTSIM_NX] = p->contact.creep.v[RR_FASTSIM_NY] = 20;
    p->contact.creep.v[RR_FASTSIM_SLIP_SPEED] = RR_SLIP_RIGID;
    p->contact.vmin = 0.01;
    p->T = 0.004; p->nsub = 1; p->method = RR_ODE_TRBDF2; p->newton_iters = 1;
    p->linear_tr = 1;
    p->roller_pi.T = p->wheelset_pi.T = p->roller_enc.T = p->wheelset_enc.T = p->T;
    p->roller_pi.Kp = 300; p->roller_pi.KI = 2; p->roller_pi.Tmax = 100;
    p->wheelset_pi.Kp = 100; p->wheelset_pi.KI = 2; p->wheelset_pi.Tmax = 60;
    p->roller_tau = p->wheelset_tau = 1e-3;
    p->roller_enc.counts = p->wheelset_enc.counts = 8388608;
    {
        /* eq. 15-16 with the centred wheelset's rolling radii (calibrated) */
        rr_wheelset_pose pose;
        rr_contact_point cl, cr;
        rr_contact_table_lookup(t, 0.0, &pose, NULL, &cl, &cr);
        p->creepctl.r_w = cl.r;
        p->creepctl.r_r = cl.R;
    }
    p->creepctl.alpha = 0.01; p->creepctl.beta = 0.002; p->creepctl.vmin = 0.1;
    p->creepctl.sense = RR_CREEPCTL_BRAKING;
}

/* Free rolling is an equilibrium: no creepage, no acceleration, the loads
 * carry the preload and the weight. */
static void test_equilibrium(rr_rig *rig)
{
    double f[RR_RIG_NSTATE], rec[RR_REC_COUNT];
    int j;
    CHECK_STATUS(rr_rig_rhs(rig, 0.0, rig->y, f), RR_OK, "rhs at rest");
    for (j = RR_RIG_VX; j < RR_RIG_NSTATE; j++)
        if (j != RR_RIG_SPIN)
            CHECK(fabs(f[j]) < 1e-6, "free rolling: no acceleration");
    /* the cone's spin moments have a component about the axle: a rolling
     * resistance of 1e-3 N m, small against 0.5 kg m^2 */
    CHECK(fabs(f[RR_RIG_SPIN]) < 1e-2, "free rolling: spin acceleration small");
    CHECK_STATUS(rr_rig_record(rig, rec), RR_OK, "record");
    /* the normal loads carry preload and weight through cos(delta) ~ 1 - 1.2e-3
     * and the spin forces' vertical parts: within 1e-3 */
    CHECK_CLOSE(rec[RR_REC_N_LEFT] + rec[RR_REC_N_RIGHT], 900.85 + 14.504 * 9.81, 0.0, 1e-3,
                "loads: preload and weight");
    CHECK_CLOSE(rec[RR_REC_N_LEFT], rec[RR_REC_N_RIGHT], 0.0, 1e-12, "loads: symmetric");
    CHECK(fabs(rec[RR_REC_CREEPAGE]) < 1e-12, "free rolling: no creepage");
}

/* The analytic Jacobian against central differences of the right-hand side
 * in the adhesion regime: the rows and columns the creep forces fill agree
 * to 15 % (the simplified theory's slope against FASTSIM's, first-order
 * high on a 20 x 20 grid); the spring and lag entries exactly. */
static void test_jacobian(rr_rig *rig)
{
    double y[RR_RIG_NSTATE], J[RR_RIG_NSTATE * RR_RIG_NSTATE], fp[RR_RIG_NSTATE],
        fm[RR_RIG_NSTATE];
    const int cols[] = {RR_RIG_VX, RR_RIG_SPIN, RR_RIG_ROLLER_SPIN, RR_RIG_T_WHEELSET};
    int c, i;
    memcpy(y, rig->y, sizeof y);
    y[RR_RIG_SPIN] *= 0.9995;         /* a braking creepage of 5e-4: adhesion */
    CHECK_STATUS(rr_rig_jac(rig, 0.0, y, J), RR_OK, "jacobian");
    for (c = 0; c < 4; c++) {
        const int j = cols[c];
        const double h = 1e-6 * (fabs(y[j]) + 1e-2);
        double yp[RR_RIG_NSTATE], ym[RR_RIG_NSTATE];
        memcpy(yp, y, sizeof y);
        memcpy(ym, y, sizeof y);
        yp[j] += h;
        ym[j] -= h;
        rr_rig_rhs(rig, 0.0, yp, fp);
        rr_rig_rhs(rig, 0.0, ym, fm);
        for (i = RR_RIG_VX; i <= RR_RIG_ROLLER_SPIN; i++) {
            const double fd = (fp[i] - fm[i]) / (2.0 * h), an = J[i * RR_RIG_NSTATE + j];
            if (fabs(fd) > 1.0 || fabs(an) > 1.0) {
                char what[96];
                snprintf(what, sizeof what, "jacobian d f%d / d y%d: %.4g vs %.4g", i, j, an, fd);
                CHECK(fabs(an - fd) <= 0.15 * fabs(fd) + 1e-6, what);
            }
        }
    }
}

/* Every sample costs the same number of right-hand sides, and braking
 * under creepage control reaches the target. */
static void test_steps(const rr_rig_params *p)
{
    static rr_rig rig;
    double rec[RR_REC_COUNT], sum = 0.0;
    int k, n = 0, nfev = -1, same = 1;
    CHECK_STATUS(rr_rig_init(p, 5.0 / 0.16, &rig), RR_OK, "init");
    for (k = 0; k < 1500; k++) {
        CHECK(rr_rig_step(&rig, 5.0 / 0.16, 0.03, rec) >= 0, "step");
        if (nfev >= 0 && rig.ode.nfev != nfev)
            same = 0;
        nfev = rig.ode.nfev;
        if (k >= 1000) {
            sum += rec[RR_REC_CREEPAGE];
            n++;
        }
        CHECK(fabs(rec[RR_REC_FX]) <= 0.4 * (rec[RR_REC_N_LEFT] + rec[RR_REC_N_RIGHT]) + 1e-9,
              "force within mu0 N");
    }
    CHECK(same && nfev == rr_ode_nfev(&rig.ode, 1), "fixed number of f evaluations per step");
    CHECK_CLOSE(sum / n, 0.03, 0.0, 0.05, "creepage held within 5 % of 0.03");
}

/* The integrator's model of the rig (rr_ode_model): no change at y0; its
 * derivative there is the Jacobian; over a finite change of the
 * creepage its creep forces (the simplified theory's) follow FASTSIM's. */
static void test_model(const rr_rig_params *good)
{
    static rr_rig rig;
    static rr_rig_params p;
    double rec[RR_REC_COUNT], y0[RR_RIG_NSTATE], J[RR_RIG_NSTATE * RR_RIG_NSTATE];
    double df[RR_RIG_NSTATE], f0[RR_RIG_NSTATE], f1[RR_RIG_NSTATE], z[RR_RIG_NSTATE];
    const double xi[2] = {5e-4, 0.03};
    char what[160];
    int c, i, j, k;

    p = *good;
    p.newton_model = 1;
    CHECK_STATUS(rr_rig_init(&p, 5.0 / 0.16, &rig), RR_OK, "init with the model");
    CHECK(rig.ode.model != NULL && rr_ode_nfev(&rig.ode, 1) == 1,
          "newton_model: one f evaluation per step");
    for (c = 0; c < 2; c++) {
        memcpy(y0, rig.y, sizeof y0);
        y0[RR_RIG_SPIN] = rig.y[RR_RIG_ROLLER_SPIN] * 0.16 / good->creepctl.r_w * (1.0 - xi[c]);
        CHECK_STATUS(rig.ode.model(&rig, 0.0, y0, y0, df), RR_OK, "model at y0");
        for (i = 0, k = 1; i < RR_RIG_NSTATE; i++)
            k &= df[i] == 0.0;
        CHECK(k, "model: no change at y0");
        CHECK_STATUS(rr_rig_jac(&rig, 0.0, y0, J), RR_OK, "jacobian");
        for (j = 0; j < RR_RIG_NSTATE; j++) {
            const double h = 1e-7 * (fabs(y0[j]) + 1e-2);
            double worst = 0.0, scale = 0.0, dm[RR_RIG_NSTATE];
            memcpy(z, y0, sizeof z);
            z[j] = y0[j] + h;
            rig.ode.model(&rig, 0.0, y0, z, df);
            z[j] = y0[j] - h;
            rig.ode.model(&rig, 0.0, y0, z, dm);
            for (i = 0; i < RR_RIG_NSTATE; i++) {
                const double an = J[i * RR_RIG_NSTATE + j], fd = (df[i] - dm[i]) / (2.0 * h);
                if (fabs(an - fd) > worst)
                    worst = fabs(an - fd);
                if (fabs(an) > scale)
                    scale = fabs(an);
            }
            /* 1e-6: the central difference's truncation and rounding at h = 1e-7 y */
            snprintf(what, sizeof what, "creepage %g: model's derivative along y%d = J's "
                     "column (%.3g of %.3g)", xi[c], j, worst, scale);
            CHECK(worst <= 1e-6 * scale + 1e-9, what);
        }
        /* a change of the creepage by a fifth of its value */
        memcpy(z, y0, sizeof z);
        z[RR_RIG_SPIN] *= 1.0 - 0.2 * xi[c];
        rig.ode.model(&rig, 0.0, y0, z, df);
        rr_rig_rhs(&rig, 0.0, y0, f0);
        rr_rig_rhs(&rig, 0.0, z, f1);
        for (i = RR_RIG_VX; i <= RR_RIG_ROLLER_SPIN; i++)
            if (fabs(f1[i] - f0[i]) > 1e-3) {
                snprintf(what, sizeof what, "creepage %g -> x1.2: model's change of f%d %.5g, "
                         "FASTSIM's %.5g", xi[c], i, df[i], f1[i] - f0[i]);
                /* 5 %: the simplified theory is FASTSIM's curve to a few per cent
                 * (measured 2.6 % in adhesion, 0.2 % beyond the knee) */
                CHECK(fabs(df[i] - (f1[i] - f0[i])) <= 0.05 * fabs(f1[i] - f0[i]), what);
            }
    }
    /* braking beyond the knee with the model: held, one f per step */
    for (k = 0; k < 1500; k++) {
        rr_rig_step(&rig, 5.0 / 0.16, 0.03, rec);
        if (k >= 1000)
            CHECK(rig.ode.nfev == 1 && rig.ode.nmev == 1, "model: 1 f, 1 model call per step");
    }
    CHECK_CLOSE(rec[RR_REC_CREEPAGE], 0.03, 0.0, 0.05, "model: creepage held within 5 % of 0.03");
}

static void test_errors(const rr_rig_params *good)
{
    static rr_rig rig;
    rr_rig_params p;
    double rec[RR_REC_COUNT], y[RR_RIG_NSTATE];
    p = *good; p.mass = -1.0;
    CHECK_STATUS(rr_rig_init(&p, 31.25, &rig), RR_ERR_PARAM, "negative mass");
    p = *good; p.kz = NAN;
    CHECK_STATUS(rr_rig_init(&p, 31.25, &rig), RR_ERR_NONFINITE, "NaN stiffness");
    p = *good; p.roller_pi.T = 0.001;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "controllers at another sample time");
    p = *good; p.nsub = 0;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "no sub-steps");
    p = *good; p.method = 7;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_METHOD, "unknown integrator");
    p = *good; p.newton_iters = -1;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "negative Newton count");
    p = *good; p.newton_iters = RR_ODE_MAX_NEWTON + 1;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "Newton count above the maximum");
    p = *good; p.linear_tr = 2;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "linear_tr neither 0 nor 1");
    p = *good; p.newton_model = 2;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "newton_model neither 0 nor 1");
    CHECK_STATUS(rr_rig_init(good, NAN, &rig), RR_ERR_NONFINITE, "NaN speed");
    /* a wheel off its roller: a clean stop at the sample's start */
    CHECK_STATUS(rr_rig_init(good, 31.25, &rig), RR_OK, "init");
    memcpy(y, rig.y, sizeof y);
    y[RR_RIG_Y] = 0.006;
    CHECK_STATUS(rr_rig_set_state(&rig, 0.0, y), RR_OK, "set state");
    CHECK_STATUS(rr_rig_step(&rig, 31.25, 0.02, rec), RR_ERR_GEOMETRY, "off the table");
    CHECK(rig.y[RR_RIG_Y] == 0.006 && rig.t == 0.0, "state kept");
    CHECK_STATUS(rr_rig_step(&rig, 31.25, 0.02, rec), RR_ERR_GEOMETRY, "and it stays stopped");
    CHECK(rec[RR_REC_STATUS] == RR_ERR_GEOMETRY, "the record says why");
}

/* A rig never initialised (zeroed memory) or whose rr_rig_init failed:
 * every entry point refuses with a status, none reads a NULL parameter
 * pointer (issue 11: the binding's uninitialised Rig segfaulted). */
static void test_unusable(const rr_rig_params *good)
{
    static rr_rig rig;
    rr_rig_params p;
    double rec[RR_REC_COUNT], y[RR_RIG_NSTATE] = {0}, J[RR_RIG_NSTATE * RR_RIG_NSTATE];
    const double rr_[2] = {31.25, 31.25}, xr[2] = {0.02, 0.02};
    double recs[2 * RR_REC_COUNT];
    int st;

    memset(&rig, 0, sizeof rig);
    CHECK_STATUS(rr_rig_step(&rig, 31.25, 0.02, rec), RR_ERR_NULL, "zeroed rig: step");
    CHECK(isnan(rec[RR_REC_T]) && rec[RR_REC_STATUS] == RR_ERR_NULL, "zeroed rig: record NaN");
    CHECK_STATUS(rr_rig_sample(&rig, 31.25, 0.02), RR_ERR_NULL, "zeroed rig: sample");
    CHECK_STATUS(rr_rig_advance(&rig, rec), RR_ERR_NULL, "zeroed rig: advance");
    CHECK_STATUS(rr_rig_record(&rig, rec), RR_ERR_NULL, "zeroed rig: record");
    CHECK_STATUS(rr_rig_rhs(&rig, 0.0, y, J), RR_ERR_NULL, "zeroed rig: rhs");
    CHECK_STATUS(rr_rig_jac(&rig, 0.0, y, J), RR_ERR_NULL, "zeroed rig: jac");
    CHECK_STATUS(rr_rig_set_state(&rig, 0.0, y), RR_ERR_NULL, "zeroed rig: set_state");
    CHECK(rr_rig_run(&rig, 2, rr_, xr, recs, &st) == 0 && st == RR_ERR_NULL, "zeroed rig: run");
    CHECK_STATUS(rr_rig_step(NULL, 31.25, 0.02, rec), RR_ERR_NULL, "rig NULL");
    CHECK_STATUS(rr_rig_init(good, 31.25, NULL), RR_ERR_NULL, "init into NULL");
    CHECK_STATUS(rr_rig_init(NULL, 31.25, &rig), RR_ERR_NULL, "init from NULL params");
    CHECK_STATUS(rr_rig_step(&rig, 31.25, 0.02, rec), RR_ERR_NULL, "after init from NULL");

    /* a failed init leaves a rig that reports the init's status */
    p = *good;
    p.mass = -1.0;
    CHECK_STATUS(rr_rig_init(&p, 31.25, &rig), RR_ERR_PARAM, "bad mass");
    CHECK_STATUS(rr_rig_step(&rig, 31.25, 0.02, rec), RR_ERR_PARAM, "after a failed init: step");
    CHECK(isnan(rec[RR_REC_FX]), "after a failed init: NaN record");
    CHECK_STATUS(rr_rig_rhs(&rig, 0.0, y, J), RR_ERR_PARAM, "after a failed init: rhs");
    CHECK(rr_rig_run(&rig, 2, rr_, xr, recs, &st) == 0 && st == RR_ERR_PARAM,
          "after a failed init: run");
    /* and a good init afterwards works */
    CHECK_STATUS(rr_rig_init(good, 31.25, &rig), RR_OK, "init again");
    CHECK_STATUS(rr_rig_step(&rig, 31.25, 0.02, rec), RR_OK, "then steps");
    CHECK(rr_rig_run(&rig, -1, rr_, xr, recs, &st) == 0 && st == RR_ERR_PARAM, "run n < 0");
    CHECK(rr_rig_run(&rig, 2, NULL, xr, recs, &st) == 0 && st == RR_ERR_NULL, "run refs NULL");
    CHECK_STATUS(rr_rig_record(&rig, NULL), RR_ERR_NULL, "record into NULL");
}

int main(void)
{
    static rr_contact_table t;
    static rr_rig_params p;
    static rr_rig rig;
    setup(&t, &p);
    CHECK_STATUS(rr_rig_init(&p, 5.0 / 0.16, &rig), RR_OK, "init");
    test_equilibrium(&rig);
    test_jacobian(&rig);
    test_steps(&p);
    test_model(&p);
    test_errors(&p);
    test_unusable(&p);
    return rr_test_summary();
}
