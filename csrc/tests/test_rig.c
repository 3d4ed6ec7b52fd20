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

/* The default rig (rr_rig_params_default, the declaration rig_default.toml is
 * generated from) on this test's own, smaller table of the same geometry:
 * 1:20 cone, r0 0.092 m, on a roller R0 0.16 m with a 60 mm crown, contacts
 * 0.15 m out, 61 profile points, rows over +-5 mm; the Newton iteration on
 * FASTSIM itself (newton_model 0). */
static void setup(rr_contact_table *t, rr_rig_params *p)
{
    rr_rig_config c;
    rr_wheel_roller pair[2];
    rr_search_opts o;
    int i;
    rr_rig_config_default(&c);
    for (i = 0; i < NP; i++) {
        ws[i] = rs[i] = -c.profile_half_width + 2.0 * c.profile_half_width * i / (NP - 1);
        wz[i] = ws[i] * c.conicity;
        rz[i] = sqrt(c.crown_radius * c.crown_radius - rs[i] * rs[i]) - c.crown_radius;
    }
    rr_spline_init(NP, ws, wz, wm, work);
    rr_spline_init(NP, rs, rz, rm, work);
    for (i = 0; i < 2; i++) {
        pair[i].wheel.n = NP; pair[i].wheel.s = ws; pair[i].wheel.z = wz; pair[i].wheel.m = wm;
        pair[i].roller.n = NP; pair[i].roller.s = rs; pair[i].roller.z = rz;
        pair[i].roller.m = rm;
        pair[i].r0 = c.wheel_radius; pair[i].R0 = c.roller_radius;
        pair[i].wheel_y = pair[i].roller_y = c.contact_half_spacing;
        pair[i].side = i == 0 ? 1 : -1;
    }
    rr_search_opts_default(&o);
    t->y0 = -0.005; t->dy = 0.01 / (NROWS - 1); t->n = NROWS; t->data = table_data;
    CHECK_STATUS(rr_contact_table_build(&pair[0], &pair[1], &o, t, NULL), RR_OK, "table");

    CHECK_STATUS(rr_rig_params_default(p), RR_OK, "default parameters");
    p->newton_model = 0;
    /* eq. 15-16 with the centred wheelset's rolling radii (calibrated) */
    CHECK_STATUS(rr_rig_params_set_table(p, t), RR_OK, "table and radii");
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
    CHECK_STATUS(rr_rig_init(p, 5.0 / 0.16, NULL, 0, &rig), RR_OK, "init");
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
    CHECK_STATUS(rr_rig_init(&p, 5.0 / 0.16, NULL, 0, &rig), RR_OK, "init with the model");
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
    CHECK_STATUS(rr_rig_init(&p, 31.25, NULL, 0, &rig), RR_ERR_PARAM, "negative mass");
    p = *good; p.kz = NAN;
    CHECK_STATUS(rr_rig_init(&p, 31.25, NULL, 0, &rig), RR_ERR_NONFINITE, "NaN stiffness");
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
    /* lateral dynamics (issue 25) */
    p = *good; p.gyro_inertia = -1.0;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "negative gyroscopic inertia");
    p = *good; p.gyro_inertia = NAN;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_NONFINITE, "NaN gyroscopic inertia");
    p = *good; p.track = 2;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "track neither 0 nor 1");
    CHECK_STATUS(rr_rig_init(good, NAN, NULL, 0, &rig), RR_ERR_NONFINITE, "NaN speed");
    /* a wheel off its roller: a clean stop at the sample's start */
    CHECK_STATUS(rr_rig_init(good, 31.25, NULL, 0, &rig), RR_OK, "init");
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
    CHECK_STATUS(rr_rig_init(good, 31.25, NULL, 0, NULL), RR_ERR_NULL, "init into NULL");
    CHECK_STATUS(rr_rig_init(NULL, 31.25, NULL, 0, &rig), RR_ERR_NULL, "init from NULL params");
    CHECK_STATUS(rr_rig_step(&rig, 31.25, 0.02, rec), RR_ERR_NULL, "after init from NULL");

    /* a failed init leaves a rig that reports the init's status */
    p = *good;
    p.mass = -1.0;
    CHECK_STATUS(rr_rig_init(&p, 31.25, NULL, 0, &rig), RR_ERR_PARAM, "bad mass");
    CHECK_STATUS(rr_rig_step(&rig, 31.25, 0.02, rec), RR_ERR_PARAM, "after a failed init: step");
    CHECK(isnan(rec[RR_REC_FX]), "after a failed init: NaN record");
    CHECK_STATUS(rr_rig_rhs(&rig, 0.0, y, J), RR_ERR_PARAM, "after a failed init: rhs");
    CHECK(rr_rig_run(&rig, 2, rr_, xr, recs, &st) == 0 && st == RR_ERR_PARAM,
          "after a failed init: run");
    /* and a good init afterwards works */
    CHECK_STATUS(rr_rig_init(good, 31.25, NULL, 0, &rig), RR_OK, "init again");
    CHECK_STATUS(rr_rig_step(&rig, 31.25, 0.02, rec), RR_OK, "then steps");
    CHECK(rr_rig_run(&rig, -1, rr_, xr, recs, &st) == 0 && st == RR_ERR_PARAM, "run n < 0");
    CHECK(rr_rig_run(&rig, 2, NULL, xr, recs, &st) == 0 && st == RR_ERR_NULL, "run refs NULL");
    CHECK_STATUS(rr_rig_record(&rig, NULL), RR_ERR_NULL, "record into NULL");
}

/* rr_rig_read + rr_rig_write with the built-in command + rr_rig_advance is
 * rr_rig_step, bit for bit; the calls out of order are refused. */
static void test_external_builtin(const rr_rig_params *p)
{
    static rr_rig a, b;
    rr_rig_signals s;
    rr_rig_command c;
    double ra[RR_REC_COUNT], rb[RR_REC_COUNT];
    int k, same = 1;

    CHECK_STATUS(rr_rig_init(p, 31.25, NULL, 0, &a), RR_OK, "init a");
    CHECK_STATUS(rr_rig_init(p, 31.25, NULL, 0, &b), RR_OK, "init b");
    rr_rig_command_builtin(&c, 31.25, 0.02);
    CHECK_STATUS(rr_rig_write(&b, &c), RR_ERR_SEQUENCE, "write before read");
    for (k = 0; k < 200; k++) {
        const double xi = k < 20 ? NAN : k < 120 ? 0.03 : 0.01;
        rr_rig_step(&a, 31.25, xi, ra);
        CHECK_STATUS(rr_rig_read(&b, &s), RR_OK, "read");
        if (k == 0) {
            CHECK(s.t == 0.0 && s.roller_angle == s.roller_count * (2.0 * RR_PI
                                                                     / p->roller_enc.counts),
                  "signals: time, quantised angle");
            CHECK(s.roller_speed == 31.25, "signals: the first speed is the initial one");
            CHECK_STATUS(rr_rig_read(&b, &s), RR_ERR_SEQUENCE, "a second read");
            CHECK(isnan(s.t) && isnan(s.xi_est), "refused: NaN signals");
        }
        rr_rig_command_builtin(&c, 31.25, xi);
        CHECK_STATUS(rr_rig_write(&b, &c), RR_OK, "write");
        if (k == 0)
            CHECK_STATUS(rr_rig_write(&b, &c), RR_ERR_SEQUENCE, "a second write");
        rr_rig_advance(&b, rb);
        same &= memcmp(ra, rb, sizeof ra) == 0;
    }
    CHECK(same, "read, write (built-in), advance == step, bit for bit");
}

/* Torque and speed commands: held as given (a torque clipped at its limit),
 * the wheelset's speed reference NaN under torque; bad commands refused
 * with nothing changed. */
static void test_external_commands(const rr_rig_params *p)
{
    static rr_rig rig;
    rr_rig_signals s;
    rr_rig_command c;
    double rec[RR_REC_COUNT];
    int k;

    CHECK_STATUS(rr_rig_init(p, 31.25, NULL, 0, &rig), RR_OK, "init");
    for (k = 0; k < 100; k++) {
        CHECK_STATUS(rr_rig_read(&rig, &s), RR_OK, "read");
        c.roller_mode = RR_CMD_SPEED;
        c.roller_ref = 31.25;
        c.wheelset_mode = RR_CMD_TORQUE;
        c.wheelset_ref = k < 50 ? -10.0 : -1e6;
        c.mu0 = NAN;
        if (k == 10) {
            rr_rig_command bad = c;
            bad.wheelset_mode = 7;
            CHECK_STATUS(rr_rig_write(&rig, &bad), RR_ERR_PARAM, "unknown mode");
            bad = c;
            bad.wheelset_ref = NAN;
            CHECK_STATUS(rr_rig_write(&rig, &bad), RR_ERR_NONFINITE, "NaN torque");
            bad = c;
            bad.mu0 = -0.1;
            CHECK_STATUS(rr_rig_write(&rig, &bad), RR_ERR_FRICTION, "mu0 < 0");
            CHECK_STATUS(rr_rig_write(&rig, NULL), RR_ERR_NULL, "NULL command");
        }
        CHECK_STATUS(rr_rig_write(&rig, &c), RR_OK, "torque command");
        CHECK(rr_rig_advance(&rig, rec) >= 0, "advance");
        CHECK(rec[RR_REC_TREF_WHEELSET] == (k < 50 ? -10.0 : -p->wheelset_pi.Tmax),
              "the torque held, clipped at the limit");
        CHECK(isnan(rec[RR_REC_W_REF]), "no speed reference under torque");
    }
    /* braking at the limit (60 N m against at most 0.4 x 1043 N x 0.092 m = 38 N m):
     * the wheel slows toward lock */
    CHECK(rec[RR_REC_WHEELSET_SPEED] < 0.9 * rec[RR_REC_ROLLER_SPEED], "the wheel slides");
    CHECK(rec[RR_REC_ADHESION] < 0.4, "adhesion below mu0");
    /* mu0 per sample: the record shows it at both contacts */
    CHECK_STATUS(rr_rig_read(&rig, &s), RR_OK, "read");
    c.wheelset_mode = RR_CMD_SPEED;
    c.wheelset_ref = s.roller_speed * p->creepctl.r_r / p->creepctl.r_w;
    c.mu0 = 0.15;
    CHECK_STATUS(rr_rig_write(&rig, &c), RR_OK, "speed command, mu0");
    CHECK(rr_rig_advance(&rig, rec) >= 0, "advance");
    CHECK(rec[RR_REC_MU_LEFT] == 0.15 && rec[RR_REC_MU_RIGHT] == 0.15, "mu0 of the command");
    CHECK(rec[RR_REC_W_REF] == c.wheelset_ref, "the speed reference held");
}

/* The adhesion: the schedule linear between its points, held outside them,
 * a step at a repeated time; the patch's fraction 1 inside, 0 outside,
 * linear over the edge, across the circumference's wrap; the checks. */
static void test_adhesion(const rr_rig_params *good)
{
    static rr_rig_params p;
    static rr_rig rig;
    const double C = 2.0 * RR_PI * good->contact.R0;
    rr_friction f;
    double rec[RR_REC_COUNT];
    int k, seen_low = 0, seen_high = 0;

    p = *good;
    p.adhesion.n = 4;
    p.adhesion.t[0] = 1.0; p.adhesion.t[1] = 2.0; p.adhesion.t[2] = 2.0; p.adhesion.t[3] = 3.0;
    for (k = 0; k < 4; k++)
        p.adhesion.law[k] = good->contact.friction;
    p.adhesion.law[0].mu0 = 0.4;
    p.adhesion.law[1].mu0 = 0.2;
    p.adhesion.law[2].mu0 = 0.1;
    p.adhesion.law[3].mu0 = 0.3;
    p.adhesion.law[3].B = 1.0;
    CHECK(rr_rig_friction_at(&p, 0.0, 0, NAN).mu0 == 0.4, "before the first point: held");
    CHECK_CLOSE(rr_rig_friction_at(&p, 1.5, 0, NAN).mu0, 0.3, 1e-15, 0.0, "linear between");
    CHECK(rr_rig_friction_at(&p, 2.0, 0, NAN).mu0 == 0.1, "a step: the later point at its time");
    f = rr_rig_friction_at(&p, 2.5, 1, NAN);
    CHECK_CLOSE(f.mu0, 0.2, 1e-15, 0.0, "after the step: linear");
    CHECK_CLOSE(f.B, 0.5 * (good->contact.friction.B + 1.0), 1e-15, 0.0, "B too");
    CHECK(rr_rig_friction_at(&p, 9.0, 0, NAN).mu0 == 0.3, "after the last point: held");
    CHECK(isnan(rr_rig_friction_at(NULL, 0.0, 0, 0.0).mu0), "NULL parameters: NaN");

    p.adhesion.n = 0;
    p.adhesion.patch_start = C - 0.05;          /* wraps past the mark */
    p.adhesion.patch_length = 0.1;
    p.adhesion.patch_edge = 0.002;
    p.adhesion.patch = good->contact.friction;
    p.adhesion.patch.mu0 = 0.1;
    p.adhesion.patch_rollers = 1;               /* left only */
    CHECK(rr_rig_friction_at(&p, 0.0, 0, 0.0).mu0 == 0.1, "inside the patch, at the wrap");
    CHECK(rr_rig_friction_at(&p, 0.0, 0, 2.0 * C + 0.02).mu0 == 0.1, "a turn later");
    CHECK(rr_rig_friction_at(&p, 0.0, 1, 0.0).mu0 == 0.4, "not on the right roller");
    CHECK(rr_rig_friction_at(&p, 0.0, 0, 0.3).mu0 == 0.4, "outside");
    CHECK_CLOSE(rr_rig_friction_at(&p, 0.0, 0, 0.05).mu0, 0.25, 1e-12, 0.0,
                "on the edge: half way");
    CHECK_CLOSE(rr_rig_friction_at(&p, 0.0, 0, 0.0505).mu0, 0.4 - 0.3 * 0.25, 1e-12, 0.0,
                "a quarter edge outside");
    CHECK_CLOSE(rr_rig_friction_at(&p, 0.0, 0, C - 0.0505).mu0, 0.4 - 0.3 * 0.25, 1e-12,
                0.0, "the other edge");

    /* in the loop: the left wheel meets the patch once a revolution */
    CHECK_STATUS(rr_rig_init(&p, 31.25, NULL, 0, &rig), RR_OK, "init with a patch");
    for (k = 0; k < 200; k++) {
        CHECK(rr_rig_step(&rig, 31.25, NAN, rec) >= 0, "steps through the patch");
        seen_low |= rec[RR_REC_MU_LEFT] == 0.1;
        seen_high |= rec[RR_REC_MU_LEFT] == 0.4;
        CHECK(rec[RR_REC_MU_RIGHT] == 0.4, "the right roller is clean");
    }
    CHECK(seen_low && seen_high, "the patch comes and goes");

    p = *good;
    p.adhesion.n = 2;
    p.adhesion.t[0] = 1.0;
    p.adhesion.t[1] = 0.5;
    p.adhesion.law[0] = p.adhesion.law[1] = good->contact.friction;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "times decreasing");
    p.adhesion.t[1] = NAN;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_NONFINITE, "a NaN time");
    p.adhesion.t[1] = 2.0;
    p.adhesion.law[1].A = 2.0;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_FRICTION, "A > 1");
    p = *good;
    p.adhesion.patch_length = 2.0 * C;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "a patch longer than the roller");
    p.adhesion.patch_length = 0.1;
    p.adhesion.patch_rollers = 0;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "a patch on no roller");
    p.adhesion.patch_rollers = 3;
    p.adhesion.patch_edge = 0.0;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "no edge");
    p.adhesion.patch_edge = 0.002;
    p.adhesion.patch.mu0 = 0.0;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_FRICTION, "patch mu0 0");
    p.adhesion.n = RR_RIG_MAX_SCHEDULE + 1;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "too many points");
}

/* A byte copy of a rig, rebound to a copy of its parameters, steps on as
 * the original, bit for bit; a retuned gain takes effect; a bad set is
 * refused with the rig unchanged. */
static void test_rebind(const rr_rig_params *good)
{
    static rr_rig a, b, keep;
    static rr_rig_params q, bad;
    double ra[RR_REC_COUNT], rb[RR_REC_COUNT];
    int k, same = 1;

    CHECK_STATUS(rr_rig_init(good, 31.25, NULL, 0, &a), RR_OK, "init");
    for (k = 0; k < 50; k++)
        rr_rig_step(&a, 31.25, k < 10 ? NAN : 0.03, ra);
    q = *good;
    memcpy(&b, &a, sizeof b);
    CHECK_STATUS(rr_rig_rebind(&b, &q), RR_OK, "rebind the copy");
    CHECK(b.p == &q, "the copy points at its own parameters");
    for (k = 0; k < 100; k++) {
        rr_rig_step(&a, 31.25, 0.03, ra);
        rr_rig_step(&b, 31.25, 0.03, rb);
        same &= memcmp(ra, rb, sizeof ra) == 0;
    }
    CHECK(same, "the copy steps on as the original, bit for bit");
    q.creepctl.alpha = 0.0;
    q.creepctl.beta = 0.0;
    CHECK_STATUS(rr_rig_rebind(&b, &q), RR_OK, "retuned");
    rr_rig_step(&b, 31.25, 0.5, rb);
    rr_rig_step(&a, 31.25, 0.5, ra);
    CHECK(rb[RR_REC_W_REF] != ra[RR_REC_W_REF], "the retuned gains act");
    bad = q;
    bad.mass = -1.0;
    memcpy(&keep, &b, sizeof keep);
    CHECK_STATUS(rr_rig_rebind(&b, &bad), RR_ERR_PARAM, "bad parameters refused");
    CHECK(memcmp(&keep, &b, sizeof b) == 0, "refused: the rig unchanged");
    CHECK_STATUS(rr_rig_rebind(NULL, &q), RR_ERR_NULL, "NULL rig");
    CHECK_STATUS(rr_rig_rebind(&b, NULL), RR_ERR_NULL, "NULL parameters");

    /* the contact model is checked at rr_rig_init and rr_rig_rebind, never
     * per step: options changed under the rig (out of range, or a method it
     * does not step with) act only through a rebind, which refuses them */
    q = *good;
    CHECK_STATUS(rr_rig_init(&q, 31.25, NULL, 0, &a), RR_OK, "init");
    CHECK_STATUS(rr_rig_init(good, 31.25, NULL, 0, &b), RR_OK, "init the reference");
    q.contact.creep.v[RR_FASTSIM_NX] = 1e9;
    for (k = 0, same = 1; k < 20; k++) {
        same &= rr_rig_step(&a, 31.25, 0.03, ra) >= 0;
        rr_rig_step(&b, 31.25, 0.03, rb);
        same &= memcmp(ra, rb, sizeof ra) == 0;
    }
    CHECK(same, "nx = 1e9 under the rig: it steps on with the checked options");
    CHECK_STATUS(rr_rig_rebind(&a, &q), RR_ERR_GRID, "and the rebind refuses them");
    rr_creep_opts_default(&q.contact.creep, RR_METHOD_LINEAR);
    CHECK_STATUS(rr_rig_rebind(&a, &q), RR_ERR_METHOD, "as the linear theory");
    CHECK(rr_rig_step(&a, 31.25, 0.03, ra) >= 0, "the rig unchanged by the refusals");
    rr_creep_opts_default(&q.contact.creep, RR_METHOD_POLACH);
    CHECK_STATUS(rr_rig_rebind(&a, &q), RR_OK, "Polach taken at the rebind");
    CHECK(a.contact.creep.o.method == RR_METHOD_POLACH, "and stepped with from there");
}

/* Issue 22: what the rig must not report as a success.  The linear theory
 * (no friction limit) and the exact solver (a workspace) are refused by
 * rr_rig_method_check; a sample time at which a drive's loop is unstable
 * by rr_rig_check and rr_rig_config_check (naming it); and a creep force
 * beyond mu N from any method stops the rig (RR_ERR_FRICTION_LIMIT). */
/* The rig's workspace: the caller's, given at rr_rig_init, kept by
 * rr_rig_rebind and handed to the creep method (none for the methods the
 * rig steps with today: each asks 0 doubles); no method is refused for
 * needing one (rr_rig_method_check: not iterative, saturates). */
static void test_workspace(const rr_rig_params *good)
{
    static rr_rig rig, ref;
    static double work[8];
    static rr_rig_params p;
    double rec[RR_REC_COUNT], rref[RR_REC_COUNT];
    int m, k;

    p = *good;
    for (m = 0; m < rr_method_count(); m++) {
        rr_creep_opts o;
        rr_creep_opts_default(&o, m);
        CHECK((rr_rig_method_check(&o) == RR_OK)
              == (!rr_method_get(m)->iterative && rr_method_get(m)->saturates),
              "rr_rig_method_check: not iterative and saturating, whatever the workspace");
        if (rr_rig_method_check(&o) == RR_OK) {
            p.contact.creep = o;
            CHECK(rr_rig_workspace_len(&p) == rr_creep_workspace_len(&o, NULL),
                  "rr_rig_workspace_len: the method's for the ellipse");
        }
    }
    CHECK(rr_rig_workspace_len(NULL) == 0, "rr_rig_workspace_len(NULL)");
    p = *good;
    CHECK_STATUS(rr_rig_init(&p, 31.25, work, 8, &rig), RR_OK, "init with a workspace");
    CHECK(rig.work == work && rig.work_len == 8 && rig.contact.work == work
          && rig.contact.work_len == 8, "the workspace kept, and bound to the contact model");
    CHECK_STATUS(rr_rig_rebind(&rig, &p), RR_OK, "rebind");
    CHECK(rig.work == work && rig.contact.work == work, "rebind keeps it");
    CHECK_STATUS(rr_rig_init(&p, 31.25, NULL, 0, &ref), RR_OK, "init without");
    for (k = 0; k < 40; k++) {
        const int st = rr_rig_step(&rig, 5.0, 0.02, rec);
        CHECK(st >= 0 && st == rr_rig_step(&ref, 5.0, 0.02, rref), "a step, as without");
    }
    CHECK(memcmp(rec, rref, sizeof rec) == 0, "a workspace no method reads changes nothing");
}

static void test_sanity(const rr_rig_params *good)
{
    static rr_rig rig;
    static rr_rig_params p;
    rr_rig_config c;
    rr_speed_loop loops[2];
    double rec[RR_REC_COUNT], lo, hi;
    const char *bad = NULL;
    int k, st = RR_OK;

    p = *good;
    CHECK_STATUS(rr_rig_method_check(&p.contact.creep), RR_OK, "FASTSIM: the rig's");
    rr_creep_opts_default(&p.contact.creep, RR_METHOD_LINEAR);
    CHECK_STATUS(rr_rig_method_check(&p.contact.creep), RR_ERR_METHOD, "linear: no limit");
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_METHOD, "the rig refuses the linear theory");
    CHECK_STATUS(rr_rig_init(&p, 31.25, NULL, 0, &rig), RR_ERR_METHOD, "and does not start with it");
    rr_creep_opts_default(&p.contact.creep, RR_METHOD_EXACT);
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_METHOD, "the exact solver: iterative");
    CHECK(rr_creep_iterative(&p.contact.creep) && rr_rig_workspace_len(&p) == 0,
          "the exact solver: refused for its iterations, so no workspace asked");
    rr_creep_opts_default(&p.contact.creep, RR_METHOD_POLACH);
    CHECK_STATUS(rr_rig_check(&p), RR_OK, "Polach saturates: taken");
    CHECK_STATUS(rr_rig_method_check(NULL), RR_ERR_NULL, "NULL options");

    /* the sample time: the paper's 4 ms in range, 10 ms beyond the roller's
     * loop (its limit 8.3 ms), 20 us below the wheelset's (6.7e-5 s) */
    p = *good;
    rr_rig_speed_loops(&p, loops);
    CHECK(loops[0].J == p.roller_inertia && loops[1].J == p.Iyy
          && loops[1].alpha == p.creepctl.alpha && loops[0].alpha == 0.0, "the loops");
    CHECK_STATUS(rr_speed_loop_range(&loops[0], RR_RIG_MIN_T, RR_RIG_MAX_T, &lo, &hi), RR_OK,
                 "roller range");
    CHECK_CLOSE(hi, 8.325e-3, 0.0, 1e-3, "roller: stable up to 8.3 ms");
    CHECK(lo < 1e-5, "roller: from a few microseconds");
    CHECK_STATUS(rr_speed_loop_range(&loops[1], RR_RIG_MIN_T, RR_RIG_MAX_T, &lo, &hi), RR_OK,
                 "wheelset range");
    CHECK_CLOSE(lo, 6.667e-5, 0.0, 1e-3, "wheelset: from 67 us (eq. 13 and the integral)");
    CHECK_CLOSE(hi, 8.768e-3, 0.0, 1e-3, "wheelset: up to 8.8 ms");
    p.T = p.roller_pi.T = p.wheelset_pi.T = p.roller_enc.T = p.wheelset_enc.T = 0.01;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "10 ms: the roller's loop unstable");
    CHECK_STATUS(rr_rig_init(&p, 31.25, NULL, 0, &rig), RR_ERR_PARAM, "and the rig does not start");
    p.T = p.roller_pi.T = p.wheelset_pi.T = p.roller_enc.T = p.wheelset_enc.T = 2e-5;
    CHECK_STATUS(rr_rig_check(&p), RR_ERR_PARAM, "20 us: the wheelset's loop unstable");
    p.roller_pi.Kp = p.roller_pi.KI = p.wheelset_pi.Kp = p.wheelset_pi.KI = 0.0;
    p.creepctl.alpha = 0.0;
    p.T = p.roller_pi.T = p.wheelset_pi.T = p.roller_enc.T = p.wheelset_enc.T = 0.05;
    CHECK_STATUS(rr_rig_check(&p), RR_OK, "no gains (torque commands): any sample time");
    rr_rig_config_default(&c);
    CHECK_STATUS(rr_rig_config_check(&c, &bad), RR_OK, "the defaults");
    CHECK_STATUS(rr_rig_config_set(&c, "scenario.control_sample_time_s", 0.0084), RR_OK, "set");
    CHECK_STATUS(rr_rig_config_check(&c, &bad), RR_ERR_PARAM, "8.4 ms refused");
    CHECK(bad && strcmp(bad, "scenario.control_sample_time_s") == 0, "naming the sample time");
    CHECK_STATUS(rr_rig_config_speed_loops(&c, loops), RR_OK, "the config's loops");
    CHECK_STATUS(rr_speed_loop_check(&loops[0]), RR_ERR_PARAM, "the roller's at 8.4 ms");
    CHECK_STATUS(rr_rig_config_speed_loops(NULL, loops), RR_ERR_NULL, "NULL config");

    /* a method that breaks its limit under the rig: FaStrip on CONTACT's
     * geometry passes mu N by up to 0.1 % in full sliding (rr_fastrip.h);
     * braked past the knee, the rig stops rather than record it */
    p = *good;
    rr_creep_opts_default(&p.contact.creep, RR_METHOD_FASTRIP);
    p.contact.creep.v[RR_FASTRIP_GEOMETRY] = RR_FASTRIP_CONTACT;
    p.contact.friction.A = 1.0;         /* Coulomb friction: FaStrip's */
    p.contact.friction.B = 0.0;
    p.adhesion.n = 0;
    CHECK_STATUS(rr_rig_init(&p, 31.25, NULL, 0, &rig), RR_OK, "init");
    for (k = 0; k < 500 && (st = rr_rig_step(&rig, 31.25, 0.04, rec)) >= 0; k++)
        CHECK(rec[RR_REC_ADHESION] <= p.contact.friction.mu0 * (1.0 + 1e-9),
              "no adhesion above mu0 recorded as a success");
    CHECK_STATUS(st, RR_ERR_FRICTION_LIMIT, "the force beyond mu N stops the rig");
    CHECK(k > 0 && k < 500, "after some samples of braking");
    CHECK(rig.status == RR_ERR_FRICTION_LIMIT && rec[RR_REC_STATUS] == RR_ERR_FRICTION_LIMIT,
          "the rig and the record say why");
}

/* The full state is a checkpoint: taken under creepage control, set back
 * after 40 samples, the same 40 samples follow bit for bit; a changed value
 * changes them; a state the rig cannot hold is refused and changes nothing. */
static void test_full_state(const rr_rig_params *p)
{
    static rr_rig rig;
    static double a[40 * RR_REC_COUNT], b[40 * RR_REC_COUNT];
    double v[RR_FS_COUNT], w[RR_FS_COUNT], u[RR_FS_COUNT], rr[40], xr[40];
    const char *const *names = rr_rig_full_state_names();
    rr_rig_signals sig;
    int k, j, st;
    CHECK(rr_rig_full_state_len() == RR_FS_COUNT && RR_FS_COUNT == 35, "full state length");
    CHECK(strcmp(names[0], "t") == 0 && strcmp(names[RR_FS_X + RR_RIG_Y], "y") == 0
          && strcmp(names[RR_FS_COUNT - 1], "creepctl_dxi") == 0, "full state names");
    CHECK(strcmp(rr_rig_full_state_units()[RR_FS_SPIN], "rad/s") == 0, "full state units");
    for (j = 0; j < RR_FS_COUNT; j++)
        for (k = 0; k < j; k++)
            CHECK(strcmp(names[j], names[k]) != 0, "full state names distinct");
    CHECK_STATUS(rr_rig_init(p, 5.0 / 0.16, NULL, 0, &rig), RR_OK, "init");
    for (k = 0; k < 40; k++) {
        rr[k] = 5.0 / 0.16;
        xr[k] = 0.01;
    }
    CHECK(rr_rig_run(&rig, 30, rr, xr, a, &st) == 30 && st >= 0, "run to the checkpoint");
    CHECK_STATUS(rr_rig_get_full_state(&rig, v), RR_OK, "get");
    CHECK(v[RR_FS_CREEP_CONTROL] == 1.0 && v[RR_FS_XI_REF] == 0.01
          && v[RR_FS_ROLLER_ENC_PRIMED] == 1.0 && v[RR_FS_T] == rig.t, "get: the controllers");
    CHECK(rr_rig_run(&rig, 40, rr, xr, a, &st) == 40 && st >= 0, "run from it");
    CHECK_STATUS(rr_rig_set_full_state(&rig, v), RR_OK, "set back");
    CHECK(rr_rig_run(&rig, 40, rr, xr, b, &st) == 40 && st >= 0, "run again");
    CHECK(memcmp(a, b, sizeof a) == 0, "checkpoint: the same records bit for bit");
    CHECK_STATUS(rr_rig_get_full_state(&rig, w), RR_OK, "get after");
    /* a changed lateral shift and integral change the run */
    memcpy(u, v, sizeof u);
    u[RR_FS_X + RR_RIG_Y] += 1e-4;
    u[RR_FS_WHEELSET_PI_INTEGRAL] += 0.1;
    CHECK_STATUS(rr_rig_set_full_state(&rig, u), RR_OK, "set changed");
    CHECK(rr_rig_run(&rig, 40, rr, xr, b, &st) == 40 && st >= 0, "run changed");
    CHECK(b[39 * RR_REC_COUNT + RR_REC_Y] != a[39 * RR_REC_COUNT + RR_REC_Y]
          && b[39 * RR_REC_COUNT + RR_REC_T_WHEELSET] != a[39 * RR_REC_COUNT + RR_REC_T_WHEELSET],
          "a changed state changes the run");
    /* refusals: nothing changes */
    CHECK_STATUS(rr_rig_get_full_state(&rig, w), RR_OK, "get before refusals");
#define REFUSE(index, value, status, what)                         \
    do {                                                           \
        memcpy(u, v, sizeof u);                                    \
        u[index] = value;                                          \
        CHECK_STATUS(rr_rig_set_full_state(&rig, u), status, what); \
        CHECK_STATUS(rr_rig_get_full_state(&rig, u), RR_OK, what); \
        CHECK(memcmp(u, w, sizeof u) == 0, what);                  \
    } while (0)
    REFUSE(RR_FS_X + RR_RIG_VY, NAN, RR_ERR_NONFINITE, "set: NaN");
    REFUSE(RR_FS_T, INFINITY, RR_ERR_NONFINITE, "set: inf time");
    REFUSE(RR_FS_CREEP_CONTROL, 2.0, RR_ERR_PARAM, "set: a flag 2");
    REFUSE(RR_FS_ROLLER_PI_SATURATED, 0.5, RR_ERR_PARAM, "set: a flag 0.5");
    REFUSE(RR_FS_WHEELSET_COUNT, 10.5, RR_ERR_PARAM, "set: a count not whole");
    REFUSE(RR_FS_ROLLER_COUNT, 1e17, RR_ERR_PARAM, "set: a count beyond 2^53");
    REFUSE(RR_FS_CREEPCTL_K, -0.1, RR_ERR_PARAM, "set: K < 0");
    REFUSE(RR_FS_XI_REF, NAN, RR_ERR_PARAM, "set: control without a target");
    REFUSE(RR_FS_CREEP_CONTROL, 0.0, RR_ERR_PARAM, "set: a target without control");
    REFUSE(RR_FS_MU0, -0.3, RR_ERR_FRICTION, "set: mu0 < 0");
    REFUSE(RR_FS_X + RR_RIG_Y, 0.02, RR_ERR_GEOMETRY, "set: the wheel off its table");
#undef REFUSE
    /* a rig that refused to step on goes on from a state set */
    rig.status = RR_ERR_GEOMETRY;
    CHECK_STATUS(rr_rig_get_full_state(&rig, u), RR_OK, "get: a refusing rig's state");
    CHECK_STATUS(rr_rig_step(&rig, 5.0 / 0.16, 0.01, a), RR_ERR_GEOMETRY, "refusing");
    CHECK_STATUS(rr_rig_set_full_state(&rig, v), RR_OK, "set clears the refusal");
    CHECK(rr_rig_run(&rig, 40, rr, xr, b, &st) == 40 && st >= 0, "run after the refusal");
    /* the same samples as the first run from v (its row 0 holds the refusal now) */
    CHECK(memcmp(a + RR_REC_COUNT, b + RR_REC_COUNT, 39 * RR_REC_COUNT * sizeof *a) == 0,
          "after the refusal: the checkpoint's records");
    CHECK_STATUS(rr_rig_set_full_state(&rig, NULL), RR_ERR_NULL, "set: NULL");
    CHECK_STATUS(rr_rig_get_full_state(NULL, u), RR_ERR_NULL, "get: NULL rig");
    CHECK(isnan(u[0]) && isnan(u[RR_FS_COUNT - 1]), "get: NaN on error");
    CHECK_STATUS(rr_rig_read(&rig, &sig), RR_OK, "read");
    CHECK_STATUS(rr_rig_get_full_state(&rig, u), RR_ERR_SEQUENCE, "get within a sample");
    CHECK_STATUS(rr_rig_set_full_state(&rig, v), RR_ERR_SEQUENCE, "set within a sample");
}

int main(void)
{
    static rr_contact_table t;
    static rr_rig_params p;
    static rr_rig rig;
    setup(&t, &p);
    CHECK_STATUS(rr_rig_init(&p, 5.0 / 0.16, NULL, 0, &rig), RR_OK, "init");
    test_equilibrium(&rig);
    test_jacobian(&rig);
    test_steps(&p);
    test_model(&p);
    test_errors(&p);
    test_unusable(&p);
    test_external_builtin(&p);
    test_external_commands(&p);
    test_adhesion(&p);
    test_rebind(&p);
    test_workspace(&p);
    test_sanity(&p);
    test_full_state(&p);
    return rr_test_summary();
}
