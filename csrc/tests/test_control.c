/*
 * test_control.c - drive and control elements (rr_control.h): PI speed
 * controller with limiter and anti-windup, drive lag, encoder, creepage
 * controller, and all of them closed around a small wheelset-on-roller model.
 *
 * Reference: the seed paper, section 5, eq. (10)-(16); domain notes section 7,
 * items 12-14.  The numbers of the plants below are test values chosen for a
 * well-damped loop, not the rig's defaults.
 *
 * Over 800 lines on purpose: one test program per module, each check a
 * function of its own read by its name (main lists them), so the file is
 * held a check at a time, not whole; split it where a second module appears.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "util/rr_common.h"
#include "rig/rr_control.h"
#include "rr_test.h"

/* ---- PI ------------------------------------------------------------------------ */

static void test_pi_bad_params(void)
{
    static const struct {
        double T, Kp, KI, Tmax;
        int status;
        const char *what;
    } t[] = {
        {NAN, 1.0, 1.0, 1.0, RR_ERR_NONFINITE, "PI T NaN"},
        {1e-3, NAN, 1.0, 1.0, RR_ERR_NONFINITE, "PI Kp NaN"},
        {1e-3, 1.0, NAN, 1.0, RR_ERR_NONFINITE, "PI KI NaN"},
        {1e-3, 1.0, 1.0, NAN, RR_ERR_NONFINITE, "PI Tmax NaN"},
        {1e-3, 1.0, 1.0, INFINITY, RR_ERR_NONFINITE, "PI Tmax inf"},
        {-1e-3, 1.0, 1.0, 1.0, RR_ERR_PARAM, "PI T < 0"},
        {0.0, 1.0, 1.0, 1.0, RR_ERR_PARAM, "PI T = 0"},
        {1e-3, -1.0, 1.0, 1.0, RR_ERR_PARAM, "PI Kp < 0"},
        {1e-3, 1.0, -1.0, 1.0, RR_ERR_PARAM, "PI KI < 0"},
        {1e-3, 1.0, 1.0, 0.0, RR_ERR_PARAM, "PI Tmax = 0"},
        {1e-3, 1.0, 1.0, -5.0, RR_ERR_PARAM, "PI Tmax < 0"}
    };
    unsigned i;

    for (i = 0; i < sizeof t / sizeof t[0]; i++) {
        rr_pi_params p;
        rr_pi_state s;
        double u = 1.0;
        p.T = t[i].T;
        p.Kp = t[i].Kp;
        p.KI = t[i].KI;
        p.Tmax = t[i].Tmax;
        CHECK_STATUS(rr_pi_check(&p), t[i].status, t[i].what);
        CHECK_STATUS(rr_pi_init(&p, &s), t[i].status, t[i].what);
        CHECK(isnan(s.integral) && isnan(s.u), t[i].what);
        CHECK_STATUS(rr_pi_update(&p, &s, 1.0, 0.0, &u), t[i].status, t[i].what);
        CHECK(isnan(u), t[i].what);
    }
    {
        rr_pi_params p = {1e-3, 2.0, 0.1, 10.0};
        rr_pi_state s, s0;
        double u = 1.0;
        CHECK_STATUS(rr_pi_check(&p), RR_OK, "PI good params");
        CHECK_STATUS(rr_pi_reset(&p, &s, NAN), RR_ERR_NONFINITE, "PI reset torque0 NaN");
        CHECK(isnan(s.integral), "PI reset torque0 NaN leaves a NaN state");
        CHECK_STATUS(rr_pi_update(&p, &s, 1.0, 0.0, &u), RR_ERR_NONFINITE,
                     "PI update on a NaN state");
        rr_pi_init(&p, &s);
        rr_pi_update(&p, &s, 1.0, 0.5, &u);
        s0 = s;
        CHECK_STATUS(rr_pi_update(&p, &s, NAN, 0.0, &u), RR_ERR_NONFINITE, "PI w_ref NaN");
        CHECK(isnan(u) && s.integral == s0.integral && s.u == s0.u, "PI w_ref NaN: NaN out, state kept");
        CHECK_STATUS(rr_pi_update(&p, &s, 1.0, INFINITY, &u), RR_ERR_NONFINITE, "PI w_m inf");
        CHECK(s.integral == s0.integral && s.u == s0.u, "PI w_m inf: state kept");
    }
}

/* Eq. (10) literally while unsaturated: T_ref(n) = Kp e(n) + KI sum_{j<=n} e(j). */
static void test_pi_eq10(void)
{
    rr_pi_params p = {1e-3, 3.0, 0.25, 1e6};
    rr_pi_state s;
    double sum = 0.0, u;
    int n, ok = 1;

    rr_pi_init(&p, &s);
    for (n = 0; n < 200; n++) {
        double e = sin(0.37 * n) + 0.1 * cos(1.3 * n);
        rr_pi_update(&p, &s, e, 0.0, &u);
        sum += e;
        /* the same sum accumulated in the same order: a few ulps of the
         * largest term */
        if (fabs(u - (p.Kp * e + p.KI * sum)) > 1e-13 * (1.0 + fabs(p.KI * sum)))
            ok = 0;
    }
    CHECK(ok, "PI output = Kp e(n) + KI sum_{j=0..n} e(j) (eq. 10, sum includes e(n))");
    CHECK(s.saturated == 0, "PI eq. 10 run never saturated");

    /* bumpless reset: with zero error the first output is the preset torque */
    rr_pi_reset(&p, &s, 7.5);
    rr_pi_update(&p, &s, 3.0, 3.0, &u);
    CHECK(u == 7.5, "PI reset(7.5): first output at zero error is 7.5");
    p.Tmax = 5.0;
    rr_pi_reset(&p, &s, 7.5);
    CHECK(s.integral == 5.0 && s.u == 5.0, "PI reset beyond the limit is clipped to Tmax");
}

/*
 * Zero steady-state error on a first-order plant J w' = Tq - d w - TL (a
 * constant load TL), advanced exactly over each sample with the torque held.
 * Continuous equivalent Ki = KI/T = 50 N m/rad: characteristic polynomial
 * J s^2 + (d + Kp) s + Ki = 0.2 s^2 + 2.5 s + 50, damping 0.4, decay rate
 * 6.25 1/s, so 10 s bring the initial error of 10 rad/s below 1e-25 of it
 * (in exact arithmetic).
 */
static void test_pi_steady_state(void)
{
    const double J = 0.2, d = 0.5, TL = 5.0, wref = 10.0;
    rr_pi_params p = {1e-3, 2.0, 0.05, 50.0};
    rr_pi_state s;
    double w = 0.0, u = 0.0, decay = exp(-d * p.T / J), umax = 0.0;
    int n, sat = 0, st = 0;

    rr_pi_init(&p, &s);
    for (n = 0; n < 10000; n++) {
        double winf;
        st |= rr_pi_update(&p, &s, wref, w, &u);
        if (s.saturated)
            sat = 1;
        if (fabs(u) > umax)
            umax = fabs(u);
        winf = (u - TL) / d;
        w = winf + (w - winf) * decay;
    }
    CHECK_STATUS(st, RR_OK, "PI updates on the plant");
    CHECK(!sat && umax < p.Tmax, "PI on the first-order plant never saturates");
    /* the residual is rounding in w ~ 10 (ulp 1.8e-15) amplified by the loop */
    CHECK_CLOSE(w, wref, 1e-12, 0.0, "PI steady state: zero speed error");
    /* the integral holds exactly the torque that balances load and damping */
    CHECK_CLOSE(s.integral, TL + d * wref, 1e-11, 0.0, "PI steady state: integral = TL + d w_ref");
}

/*
 * No windup.  A constant positive error for 2000 samples saturates the
 * output; then the error turns negative.  The clamped PI leaves the limit at
 * the first negative sample; a deliberately windup-prone PI (integrating
 * always, clipping only its output) has stored KI sum e >> Tmax and stays
 * at the limit for hundreds of samples.
 */
static void test_pi_windup(void)
{
    rr_pi_params p = {1e-3, 10.0, 2.0, 50.0};
    rr_pi_state s;
    double u = 0.0, Inaive = 0.0, unaive = 0.0, I_sat = NAN;
    int n, first_sat = -1, frozen = 1, left = -1, left_naive = -1;
    const double e_hi = 3.0, e_lo = -0.5;

    rr_pi_init(&p, &s);
    for (n = 0; n < 2000; n++) {
        rr_pi_update(&p, &s, e_hi, 0.0, &u);
        Inaive += p.KI * e_hi;
        unaive = fmin(fmax(p.Kp * e_hi + Inaive, -p.Tmax), p.Tmax);
        if (u == p.Tmax && first_sat < 0) {
            first_sat = n;
            I_sat = s.integral;
        } else if (first_sat >= 0 && s.integral != I_sat)
            frozen = 0;
    }
    CHECK(first_sat >= 0 && u == p.Tmax && unaive == p.Tmax, "PI windup run saturates");
    CHECK(s.saturated == 1, "PI reports saturation at +Tmax");
    CHECK(frozen, "PI integral does not move while the limiter holds");
    /* the integral stopped where Kp e + I met the limit */
    CHECK_CLOSE(s.integral, p.Tmax - p.Kp * e_hi, 1e-12, 0.0, "PI integral clamped at Tmax - Kp e");
    CHECK(Inaive > 50.0 * p.Tmax, "windup-prone PI integral has wound far beyond Tmax");

    for (n = 0; n < 20000 && (left < 0 || left_naive < 0); n++) {
        rr_pi_update(&p, &s, e_lo, 0.0, &u);
        Inaive += p.KI * e_lo;
        unaive = fmin(fmax(p.Kp * e_lo + Inaive, -p.Tmax), p.Tmax);
        if (left < 0 && u < p.Tmax)
            left = n;
        if (left_naive < 0 && unaive < p.Tmax)
            left_naive = n;
    }
    CHECK(left == 0, "clamped PI leaves the limit at the first sample with negative error");
    /* it must first unwind 2000 KI e_hi = 12000 N m at KI |e_lo| = 1 N m per
     * sample, down to Tmax - Kp e_lo = 55: after sample 11944 (integers: exact) */
    CHECK(left_naive == 11945, "windup-prone PI stays at the limit 11945 samples");

    /* the same at the negative limit */
    rr_pi_init(&p, &s);
    for (n = 0; n < 2000; n++)
        rr_pi_update(&p, &s, -e_hi, 0.0, &u);
    CHECK(u == -p.Tmax && s.saturated == -1, "PI saturates at -Tmax");
    CHECK(s.integral >= -p.Tmax, "PI integral within -Tmax");
    rr_pi_update(&p, &s, -e_lo, 0.0, &u);
    CHECK(u > -p.Tmax, "clamped PI leaves -Tmax at the first positive error");

    /* a limit lowered between samples binds the integral at once */
    rr_pi_reset(&p, &s, 40.0);
    p.Tmax = 20.0;
    rr_pi_update(&p, &s, 0.0, 0.0, &u);
    CHECK(u == 20.0 && s.integral == 20.0, "PI: lowered Tmax clips the integral");
}

/* ---- lag --------------------------------------------------------------------------- */

static void test_lag(void)
{
    rr_lag_params p = {0.02};
    rr_lag_state s;
    double y, t = 0.0, y0 = -3.0, err = 0.0;
    /* sub-steps of irregular length, as a plant integrator may take */
    static const double hs[] = {1e-4, 3.7e-4, 2.5e-5, 1e-3, 4e-3, 7e-7, 2.2e-3};
    int n, k;

    CHECK_STATUS(rr_lag_reset(&p, &s, y0), RR_OK, "lag reset");
    /* held input u = 10 for 0.1 s: y(t) = u + (y0 - u) exp(-t/tau) */
    for (n = 0; t < 0.1; n++) {
        double h = hs[n % 7], want;
        CHECK_STATUS(rr_lag_update(&p, &s, 10.0, h, &y), RR_OK, "lag update");
        t += h;
        want = 10.0 + (y0 - 10.0) * exp(-t / p.tau);
        if (fabs(y - want) > err)
            err = fabs(y - want);
    }
    /* each step is exact but rounds, ~1 ulp of 10 per step over ~100 steps,
     * and t accumulates its own rounding: 1e-13 */
    CHECK(err < 1e-13, "lag sub-stepped = analytic exponential (held input)");

    /* piecewise-constant input over 4 ms samples, each cut into 1..8 sub-steps:
     * the result must match one exact step per sample */
    {
        rr_lag_state a, b;
        double ya = 0.0, yb = 0.0, maxd = 0.0;
        rr_lag_init(&p, &a);
        rr_lag_init(&p, &b);
        for (n = 0; n < 500; n++) {
            double u = 30.0 * sin(0.05 * n), T = 4e-3;
            int m = 1 + n % 8;
            rr_lag_update(&p, &a, u, T, &ya);
            for (k = 0; k < m; k++)
                rr_lag_update(&p, &b, u, T / m, &yb);
            if (fabs(ya - yb) > maxd)
                maxd = fabs(ya - yb);
        }
        /* up to 8 roundings of a value ~30 per sample, not accumulating
         * (the lag forgets): 1e-12 */
        CHECK(maxd < 1e-12, "lag: sub-stepping a sample gives the single-step result");
    }
    /* small steps keep their precision (expm1; 1 - exp(-x) would lose 4 of
     * the 16 digits at x = 1e-12): x - x^2/2 + x^3/6 is exact to 1e-48 here */
    rr_lag_reset(&p, &s, 0.0);
    rr_lag_update(&p, &s, 1.0, 1e-12 * p.tau, &y);
    CHECK_CLOSE(y, 1e-12 - 0.5e-24 + 1e-36 / 6.0, 0.0, 4.5e-16,
                "lag: tiny step to full precision");
    /* h = 0 changes nothing; tau = 0 passes through */
    rr_lag_reset(&p, &s, 2.0);
    rr_lag_update(&p, &s, 9.0, 0.0, &y);
    CHECK(y == 2.0, "lag: h = 0 leaves the output");
    p.tau = 0.0;
    rr_lag_update(&p, &s, 9.0, 1e-3, &y);
    CHECK(y == 9.0, "lag: tau = 0 is a pass-through");
    rr_lag_update(&p, &s, -4.0, 0.0, &y);
    CHECK(y == -4.0, "lag: tau = 0 passes through even at h = 0");

    /* bad parameters and inputs */
    p.tau = -1e-3;
    CHECK_STATUS(rr_lag_check(&p), RR_ERR_PARAM, "lag tau < 0");
    CHECK_STATUS(rr_lag_init(&p, &s), RR_ERR_PARAM, "lag init tau < 0");
    CHECK(isnan(s.y), "lag init tau < 0: NaN state");
    p.tau = NAN;
    CHECK_STATUS(rr_lag_check(&p), RR_ERR_NONFINITE, "lag tau NaN");
    p.tau = 0.01;
    rr_lag_reset(&p, &s, 1.0);
    y = 0.0;
    CHECK_STATUS(rr_lag_update(&p, &s, 1.0, -1e-3, &y), RR_ERR_PARAM, "lag h < 0");
    CHECK(isnan(y) && s.y == 1.0, "lag h < 0: NaN out, state kept");
    CHECK_STATUS(rr_lag_update(&p, &s, NAN, 1e-3, &y), RR_ERR_NONFINITE, "lag u NaN");
    CHECK_STATUS(rr_lag_update(&p, &s, 1.0, INFINITY, &y), RR_ERR_NONFINITE, "lag h inf");
    CHECK_STATUS(rr_lag_reset(&p, &s, INFINITY), RR_ERR_NONFINITE, "lag reset y0 inf");
}

/* ---- encoder ------------------------------------------------------------------------- */

static void test_encoder_bad(void)
{
    rr_encoder_params p = {1e-3, 1024};
    rr_encoder_state s;
    double w = 0.0;

    CHECK_STATUS(rr_encoder_check(&p), RR_OK, "encoder good params");
    p.counts = 0;
    CHECK_STATUS(rr_encoder_check(&p), RR_ERR_PARAM, "encoder counts = 0");
    CHECK_STATUS(rr_encoder_init(&p, &s), RR_ERR_PARAM, "encoder init counts = 0");
    CHECK(isnan(s.w), "encoder init counts = 0: NaN state");
    CHECK_STATUS(rr_encoder_update(&p, &s, 1.0, &w), RR_ERR_PARAM, "encoder update counts = 0");
    CHECK(isnan(w), "encoder update counts = 0: NaN out");
    p.counts = -8;
    CHECK_STATUS(rr_encoder_check(&p), RR_ERR_PARAM, "encoder counts < 0");
    p.counts = 1;
    CHECK_STATUS(rr_encoder_check(&p), RR_OK, "encoder counts = 1 is valid");
    p.T = -1e-3;
    CHECK_STATUS(rr_encoder_check(&p), RR_ERR_PARAM, "encoder T < 0");
    p.T = 0.0;
    CHECK_STATUS(rr_encoder_check(&p), RR_ERR_PARAM, "encoder T = 0");
    p.T = NAN;
    CHECK_STATUS(rr_encoder_check(&p), RR_ERR_NONFINITE, "encoder T NaN");
    p.T = 1e-3;
    CHECK_STATUS(rr_encoder_reset(&p, &s, NAN), RR_ERR_NONFINITE, "encoder reset w0 NaN");
    CHECK_STATUS(rr_encoder_update(&p, &s, 0.0, &w), RR_ERR_NONFINITE,
                 "encoder update on a NaN state");
    rr_encoder_init(&p, &s);
    CHECK_STATUS(rr_encoder_update(&p, &s, NAN, &w), RR_ERR_NONFINITE, "encoder theta NaN");
    CHECK(isnan(w) && s.primed == 0, "encoder theta NaN: NaN out, state kept");
}

/*
 * Constant speed with a whole number m of counts per sample: exact from the
 * second sample.  The angle starts half a count past an edge, so that no
 * sample lands on an edge, where floor() of a rounded angle is a coin toss
 * (as it is for the physical encoder).
 */
static void test_encoder_constant(void)
{
    static const int ms[] = {1, 7, 250, -3, 0};
    const int counts = 4096;
    const double T = 1e-3, q = 2.0 * RR_PI / counts;
    unsigned i;
    char buf[120];

    for (i = 0; i < sizeof ms / sizeof ms[0]; i++) {
        rr_encoder_params p;
        rr_encoder_state s;
        double w, wtrue = ms[i] * q / T, theta0 = 123.5 * q, maxerr = 0.0;
        int k, inside = 1;
        p.T = T;
        p.counts = counts;
        rr_encoder_reset(&p, &s, 42.0);
        rr_encoder_update(&p, &s, theta0, &w);
        snprintf(buf, sizeof buf, "encoder m = %d: first sample reports w0", ms[i]);
        CHECK(w == 42.0, buf);
        for (k = 1; k <= 1000; k++) {
            double theta = theta0 + wtrue * k * T;
            rr_encoder_update(&p, &s, theta, &w);
            if (fabs(w - wtrue) > maxerr)
                maxerr = fabs(w - wtrue);
            if (!(s.theta_q <= theta && theta < s.theta_q + q))
                inside = 0;
        }
        snprintf(buf, sizeof buf, "encoder m = %d counts/sample: exact from the 2nd sample",
                 ms[i]);
        /* (m q)/T in both, evaluated with the same operations: exact */
        CHECK(maxerr == 0.0, buf);
        snprintf(buf, sizeof buf, "encoder m = %d: theta_q <= theta < theta_q + q", ms[i]);
        CHECK(inside, buf);
    }
}

/*
 * Ramp: constant acceleration a.  The difference quotient is the mean speed
 * over the last sample, w(t_k - T/2): half a sample of lag.
 * (1) Built so that every sample sits half a count past an edge:
 *     theta_k = q (c k^2 + 1/2), a = 2 c q / T^2; then the estimate equals
 *     w(t_k - T/2) = c q (2k - 1)/T exactly, and misses w(t_k) by a T/2.
 * (2) Generic acceleration and a fine encoder: |w_est - w(t_k - T/2)| stays
 *     below the quantisation bound q/T, and the mean lag over N samples is
 *     a T/2 within 2 q/(N T) (the counts telescope).
 */
static void test_encoder_ramp(void)
{
    const double T = 2e-3;
    {
        const int counts = 1000, c = 3;
        const double q = 2.0 * RR_PI / counts, a = 2.0 * c * q / (T * T);
        rr_encoder_params p;
        rr_encoder_state s;
        double w, maxerr = 0.0, maxlag = 0.0;
        int k;
        p.T = T;
        p.counts = counts;
        rr_encoder_init(&p, &s);
        rr_encoder_update(&p, &s, 0.5 * q, &w);
        CHECK(w == 0.0, "encoder init: first sample reports 0");
        for (k = 1; k <= 400; k++) {
            double theta = q * ((double)c * k * k + 0.5);
            double want = c * q * (2.0 * k - 1.0) / T;
            rr_encoder_update(&p, &s, theta, &w);
            if (fabs(w - want) > maxerr)
                maxerr = fabs(w - want);
            if (fabs(a * k * T - w - 0.5 * a * T) > maxlag)
                maxlag = fabs(a * k * T - w - 0.5 * a * T);
        }
        /* integer count differences times q/T: a few ulps of w <= 3.8e3 rad/s */
        CHECK(maxerr < 1e-11, "encoder ramp (whole counts): estimate = w(t_k - T/2)");
        CHECK(maxlag < 1e-11, "encoder ramp (whole counts): w(t_k) - estimate = a T/2");
    }
    {
        const int counts = 1 << 20, N = 5000;
        const double q = 2.0 * RR_PI / counts, a = 37.3, w0 = 11.1, th0 = 0.3;
        rr_encoder_params p;
        rr_encoder_state s;
        double w, maxerr = 0.0, lagsum = 0.0;
        int k;
        p.T = T;
        p.counts = counts;
        rr_encoder_reset(&p, &s, w0);
        rr_encoder_update(&p, &s, th0, &w);
        for (k = 1; k <= N; k++) {
            double t = k * T, theta = th0 + w0 * t + 0.5 * a * t * t;
            double wmid = w0 + a * (t - 0.5 * T);
            rr_encoder_update(&p, &s, theta, &w);
            if (fabs(w - wmid) > maxerr)
                maxerr = fabs(w - wmid);
            lagsum += (w0 + a * t) - w;
        }
        CHECK(maxerr < q / T, "encoder ramp (generic): |estimate - w(t_k - T/2)| < q/T");
        CHECK_CLOSE(lagsum / N, 0.5 * a * T, 2.0 * q / (N * T), 0.0,
                    "encoder ramp (generic): mean lag = a T/2 (half a sample)");
    }
}

/* ---- creepage controller -------------------------------------------------------------- */

/* test rig: 5 m/s roller surface speed (the paper's); radii are test values */
#define R_W 0.0915
#define R_R 0.1
#define V_ROLLER 5.0

static rr_creepctl_params creepctl_paper(int sense)
{
    rr_creepctl_params p;
    p.r_w = R_W;
    p.r_r = R_R;
    p.alpha = 0.01;  /* the paper's alpha and beta */
    p.beta = 0.002;
    p.vmin = 0.01;
    p.sense = sense;
    return p;
}

static void test_creepctl_bad(void)
{
    rr_creepctl_params p = creepctl_paper(RR_CREEPCTL_BRAKING), b;
    rr_creepctl_state s, s0;
    double w = 0.0;

    CHECK_STATUS(rr_creepctl_check(&p), RR_OK, "creepctl good params");
    b = p; b.r_w = NAN;
    CHECK_STATUS(rr_creepctl_check(&b), RR_ERR_NONFINITE, "creepctl r_w NaN");
    b = p; b.alpha = INFINITY;
    CHECK_STATUS(rr_creepctl_check(&b), RR_ERR_NONFINITE, "creepctl alpha inf");
    b = p; b.r_r = 0.0;
    CHECK_STATUS(rr_creepctl_check(&b), RR_ERR_GEOMETRY, "creepctl r_r = 0");
    b = p; b.r_w = -0.1;
    CHECK_STATUS(rr_creepctl_check(&b), RR_ERR_GEOMETRY, "creepctl r_w < 0");
    b = p; b.alpha = -0.1;
    CHECK_STATUS(rr_creepctl_check(&b), RR_ERR_PARAM, "creepctl alpha < 0");
    b = p; b.beta = -0.1;
    CHECK_STATUS(rr_creepctl_check(&b), RR_ERR_PARAM, "creepctl beta < 0");
    b = p; b.sense = 0;
    CHECK_STATUS(rr_creepctl_check(&b), RR_ERR_PARAM, "creepctl sense 0");
    b = p; b.vmin = 0.0;
    CHECK_STATUS(rr_creepctl_check(&b), RR_ERR_SPEED, "creepctl vmin = 0");
    CHECK_STATUS(rr_creepctl_init(&b, &s, 1.0, 50.0), RR_ERR_SPEED, "creepctl init vmin = 0");
    CHECK(isnan(s.K) && isnan(s.w_ref) && isnan(s.xi_est) && isnan(s.dxi),
          "creepctl init error: NaN state");
    CHECK_STATUS(rr_creepctl_update(&b, &s, 0.04, 50.0, 50.0, &w), RR_ERR_SPEED,
                 "creepctl update vmin = 0");
    CHECK(isnan(w), "creepctl update error: NaN out");
    CHECK_STATUS(rr_creepctl_init(&p, &s, -0.5, 50.0), RR_ERR_PARAM, "creepctl init K < 0");
    CHECK(isnan(s.K) && isnan(s.w_ref), "creepctl init K < 0: NaN state");
    CHECK_STATUS(rr_creepctl_init(&p, &s, NAN, 50.0), RR_ERR_NONFINITE, "creepctl init K NaN");
    CHECK(isnan(s.K) && isnan(s.w_ref), "creepctl init K NaN: NaN state");
    CHECK_STATUS(rr_creepctl_init(&p, &s, INFINITY, 50.0), RR_ERR_NONFINITE,
                 "creepctl init K inf");
    CHECK_STATUS(rr_creepctl_init(&p, &s, 1.0, NAN), RR_ERR_NONFINITE,
                 "creepctl init w_roller NaN");
    CHECK_STATUS(rr_creepctl_update(&p, &s, 0.04, 50.0, 50.0, &w), RR_ERR_NONFINITE,
                 "creepctl update on a NaN state");
    CHECK(isnan(w), "creepctl update on a NaN state: NaN out");
    CHECK_STATUS(rr_creepctl_init(&p, &s, 0.0, 50.0), RR_OK, "creepctl init K = 0 is valid");
    CHECK(s.K == 0.0 && s.w_ref == 0.0, "creepctl init K = 0: w_ref = 0");
    rr_creepctl_init(&p, &s, 0.97, 50.0);
    rr_creepctl_update(&p, &s, 0.04, 45.0, 50.0, &w);
    s0 = s;
    CHECK_STATUS(rr_creepctl_update(&p, &s, NAN, 50.0, 50.0, &w), RR_ERR_NONFINITE,
                 "creepctl xi_ref NaN");
    CHECK(isnan(w) && s.K == s0.K && s.w_ref == s0.w_ref && s.xi_est == s0.xi_est
          && s.dxi == s0.dxi, "creepctl xi_ref NaN: NaN out, state kept");
    CHECK_STATUS(rr_creepctl_update(&p, &s, 0.04, 50.0, -INFINITY, &w), RR_ERR_NONFINITE,
                 "creepctl w_roller -inf");
    CHECK(isnan(w) && s.K == s0.K && s.w_ref == s0.w_ref, "creepctl w_roller -inf: state kept");
    CHECK_STATUS(rr_creepctl_update(&p, &s, 0.04, NAN, 50.0, &w), RR_ERR_NONFINITE,
                 "creepctl w_wheelset NaN");
    CHECK(s.K == s0.K, "creepctl w_wheelset NaN: state kept");
    CHECK_STATUS(rr_creepctl_xi(&p, INFINITY, 50.0, &w), RR_ERR_NONFINITE,
                 "creepctl_xi w_wheelset inf");
    CHECK(isnan(w), "creepctl_xi error: NaN out");
}

/*
 * Eq. (15), eq. (16) in both senses, the standstill guard, and one step of
 * eq. (13)-(14) on K in each case, with the exact K and w_ref expected.  The
 * wheel is measured 4 % slower than the roller, so dxi is the target minus
 * 0.04 (braking) or minus -0.04 (traction) up to a few ulps, which move K
 * by alpha times that, far below K's ulp: K is expected to 1e-15.
 */
static void test_creepctl_unit(void)
{
    rr_creepctl_params pb = creepctl_paper(RR_CREEPCTL_BRAKING);
    rr_creepctl_params pt = creepctl_paper(RR_CREEPCTL_TRACTION);
    rr_creepctl_state s;
    const double wr = V_ROLLER / R_R, g = R_R / R_W;
    double xi, w, ww = 0.96 * V_ROLLER / R_W;  /* wheel 4 % slower than the roller */

    CHECK_STATUS(rr_creepctl_init(&pb, &s, 0.96, wr), RR_OK, "creepctl init");
    CHECK(s.K == 0.96 && s.xi_est == 0.0 && s.dxi == 0.0, "creepctl init: K set, xi_est, dxi 0");
    /* K r_r/r_w w_roller, the same three products: a couple of ulps */
    CHECK_CLOSE(s.w_ref, 0.96 * g * wr, 0.0, 1e-15, "eq. 15: w_ref = K r_r/r_w w_roller");
    rr_creepctl_xi(&pb, ww, wr, &xi);
    CHECK_CLOSE(xi, 0.04, 1e-15, 0.0, "braking creepage of a wheel 4 % slow = +0.04");
    rr_creepctl_xi(&pb, s.w_ref, wr, &xi);
    CHECK_CLOSE(xi, 0.04, 1e-15, 0.0, "braking: a wheel at eq. 15's w_ref has xi = 1 - K");
    rr_creepctl_xi(&pt, ww, wr, &xi);
    CHECK_CLOSE(xi, -0.04, 1e-15, 0.0, "traction creepage (eq. 16) of a wheel 4 % slow = -0.04");
    /* both running backward: the same creepages */
    rr_creepctl_xi(&pb, -ww, -wr, &xi);
    CHECK_CLOSE(xi, 0.04, 1e-15, 0.0, "braking creepage, running backward = +0.04");
    /* standstill: the denominator is vmin, the estimate finite */
    CHECK_STATUS(rr_creepctl_xi(&pb, 0.0, 0.0, &xi), RR_OK, "creepctl_xi at standstill");
    CHECK(xi == 0.0, "creepctl_xi at standstill is 0");
    rr_creepctl_xi(&pb, -0.001, 0.0, &xi);
    CHECK_CLOSE(xi, 0.001 * R_W / pb.vmin, 1e-15, 0.0, "creepctl_xi below vmin uses vmin");

    /* braking, creepage below target (0.04 < 0.05): K -= alpha dxi, the
     * wheel slows: K = 0.96 - 0.01 * 0.01 = 0.9599 */
    rr_creepctl_init(&pb, &s, 0.96, wr);
    CHECK_STATUS(rr_creepctl_update(&pb, &s, 0.05, ww, wr, &w), RR_OK, "creepctl update");
    CHECK_CLOSE(s.xi_est, 0.04, 1e-15, 0.0, "creepctl xi_est = eq. 16 in the sense");
    CHECK_CLOSE(s.dxi, 0.01, 1e-15, 0.0, "creepctl dxi = xi_ref - xi_est");
    CHECK_CLOSE(s.K, 0.9599, 1e-15, 0.0, "braking, dxi > 0: K -= alpha dxi");
    CHECK_CLOSE(w, 0.9599 * g * wr, 0.0, 2e-15, "braking, dxi > 0: w_ref = K r_r/r_w w_roller");
    CHECK(w == s.w_ref, "creepctl update: the returned w_ref is the stored one");
    /* braking, creepage above target (0.04 > 0.03): recover, K += beta */
    rr_creepctl_init(&pb, &s, 0.96, wr);
    rr_creepctl_update(&pb, &s, 0.03, ww, wr, &w);
    CHECK_CLOSE(s.K, 0.962, 1e-15, 0.0, "braking, dxi < 0: K += beta (recovery)");
    CHECK_CLOSE(w, 0.962 * g * wr, 0.0, 2e-15, "braking, dxi < 0: w_ref rises");
    /* the reference follows the measured roller speed of the sample */
    rr_creepctl_init(&pb, &s, 0.96, wr);
    rr_creepctl_update(&pb, &s, 0.03, 0.5 * ww, 0.5 * wr, &w);
    CHECK_CLOSE(w, 0.962 * g * 0.5 * wr, 0.0, 2e-15, "eq. 15 uses this sample's roller speed");
    /* traction is eq. (13)-(14) literally: creepage -0.04 below 0, K += alpha 0.04 */
    rr_creepctl_init(&pt, &s, 0.96, wr);
    rr_creepctl_update(&pt, &s, 0.0, ww, wr, &w);
    CHECK_CLOSE(s.K, 0.9604, 1e-15, 0.0, "traction, dxi > 0: K += alpha dxi");
    CHECK_CLOSE(w, 0.9604 * g * wr, 0.0, 2e-15, "traction, dxi > 0: w_ref rises");
    rr_creepctl_init(&pt, &s, 0.96, wr);
    rr_creepctl_update(&pt, &s, -0.05, ww, wr, &w);
    CHECK_CLOSE(s.K, 0.958, 1e-15, 0.0, "traction, dxi < 0: K -= beta");
    CHECK_CLOSE(w, 0.958 * g * wr, 0.0, 2e-15, "traction, dxi < 0: w_ref falls");
    /* running backward: K moves as forward, w_ref mirrors with w_roller */
    rr_creepctl_init(&pb, &s, 0.96, -wr);
    CHECK_CLOSE(s.w_ref, -0.96 * g * wr, 0.0, 1e-15, "eq. 15 backward: w_ref < 0");
    rr_creepctl_update(&pb, &s, 0.03, -ww, -wr, &w);
    CHECK_CLOSE(s.K, 0.962, 1e-15, 0.0, "braking backward, dxi < 0: K += beta");
    CHECK_CLOSE(w, -0.962 * g * wr, 0.0, 2e-15,
                "braking backward, dxi < 0: |w_ref| rises toward the roller's");
    rr_creepctl_init(&pb, &s, 0.96, -wr);
    rr_creepctl_update(&pb, &s, 0.05, -ww, -wr, &w);
    CHECK_CLOSE(s.K, 0.9599, 1e-15, 0.0, "braking backward, dxi > 0: K -= alpha dxi");
    CHECK_CLOSE(w, -0.9599 * g * wr, 0.0, 2e-15, "braking backward, dxi > 0: |w_ref| falls");
    rr_creepctl_init(&pt, &s, 0.96, -wr);
    rr_creepctl_update(&pt, &s, 0.0, -ww, -wr, &w);
    CHECK_CLOSE(w, -0.9604 * g * wr, 0.0, 2e-15, "traction backward, dxi > 0: |w_ref| rises");
    /* K is kept >= 0: traction K = 0.001 at creepage -0.999, target -1:
     * 0.001 - beta clips at 0; braking with alpha = 1, K = 0.01 and a wheel
     * at 0.02 of the roller's speed (xi 0.98) short of the target 1:
     * 0.01 - 0.02 clips at 0 */
    rr_creepctl_init(&pt, &s, 0.001, wr);
    rr_creepctl_update(&pt, &s, -1.0, s.w_ref, wr, &w);
    CHECK(s.K == 0.0 && w == 0.0, "traction recovery step clips K at 0");
    pb.alpha = 1.0;
    rr_creepctl_init(&pb, &s, 0.01, wr);
    rr_creepctl_update(&pb, &s, 1.0, 0.02 * g * wr, wr, &w);
    CHECK(s.K == 0.0 && w == 0.0, "braking gain step clips K at 0");
}

/*
 * Static wheel-roller model: the wheelset's speed loop is ideal, so the
 * measured wheel speed at each sample is the last reference, and the roller
 * turns steadily at 5 m/s.  Then xi_est = sense (K - 1) (up to rounding),
 * and with the paper's alpha = 0.01, beta = 0.002 the rule is, in creepage,
 *     below the target:  xi += alpha (xi_ref - xi)  (deficit x (1 - alpha))
 *     above it:          xi -= beta.
 * The paper's scenario: braking, targets 0.04, 0.015, 0.02, 0.03 in turn.
 * Predicted samples to within 1 % (and staying there): from a deficit d0,
 * ceil(ln(0.01 xi_ref/d0)/ln(1 - alpha)); coming down, first
 * ceil((xi_prev - xi_ref)/beta) recovery steps, then the approach from the
 * undershoot.  0.04 from free rolling: 459 samples; 0.015 from 0.04: 13 steps
 * to 0.014, then 0.001 -> 1.5e-4: 13 + 189; 0.02 from 0.015: 321; 0.03 from
 * 0.02: 349.  The count is checked against the prediction (+-1 for
 * rounding at the threshold) and against 500 samples.  Each target is held
 * 1500 samples (the deficit falls to 3e-7 of itself, far above rounding,
 * which could otherwise tip a converged xi_est over the target and fire a
 * recovery step).
 */
static int static_run(const rr_creepctl_params *p, rr_creepctl_state *s, double wr,
                      double xref, int nsamp, double *w, double *xi_end, double *over,
                      double *under, int *stays)
{
    int n, nconv = -1, below = 0;
    double xi = 0.0;

    *over = *under = 0.0;
    *stays = 1;
    for (n = 1; n <= nsamp; n++) {
        rr_creepctl_update(p, s, xref, *w, wr, w);
        rr_creepctl_xi(p, *w, wr, &xi);
        if (!below && xi <= xref) {
            below = 1;
            *under = xref - xi;
        }
        if (below && xi - xref > *over)
            *over = xi - xref;
        if (fabs(xi - xref) <= 0.01 * xref) {
            if (nconv < 0)
                nconv = n;
        } else if (nconv >= 0)
            *stays = 0;
    }
    *xi_end = xi;
    if (!below)
        *over = INFINITY;
    return nconv;
}

static int predicted_samples(double xprev, double xref, double alpha, double beta)
{
    int m = 0;
    double d;
    while (xprev > xref) {
        xprev -= beta;
        m++;
    }
    d = xref - xprev;
    if (d <= 0.01 * xref)
        return m;
    return m + (int)ceil(log(0.01 * xref / d) / log(1.0 - alpha));
}

static void test_creepctl_static(void)
{
    static const double targets[] = {0.04, 0.015, 0.02, 0.03};
    const int nsamp = 1500, nbound = 500;
    rr_creepctl_params p = creepctl_paper(RR_CREEPCTL_BRAKING);
    rr_creepctl_state s;
    const double wr = V_ROLLER / R_R;
    double w, xi = 0.0, xprev = 0.0, over, under;
    unsigned i;
    int nconv, npred, stays, dir;
    char buf[160];

    rr_creepctl_init(&p, &s, 1.0, wr);  /* start at free rolling */
    w = s.w_ref;
    for (i = 0; i < sizeof targets / sizeof targets[0]; i++) {
        double xref = targets[i];
        nconv = static_run(&p, &s, wr, xref, nsamp, &w, &xi, &over, &under, &stays);
        npred = predicted_samples(xprev, xref, p.alpha, p.beta);
        printf("  static braking %.3f: within 1 %% after %d samples (predicted %d), "
               "error at the end %.1e\n", xref, nconv, npred, xi / xref - 1.0);
        snprintf(buf, sizeof buf, "static braking: creepage %g reached within 1 %%", xref);
        CHECK_CLOSE(xi, xref, 0.0, 0.01, buf);
        snprintf(buf, sizeof buf, "static braking %g: within 1 %% after %d samples "
                 "(predicted %d, bound %d), and stays", xref, nconv, npred, nbound);
        CHECK(nconv > 0 && abs(nconv - npred) <= 1 && nconv <= nbound && stays, buf);
        /* from below the approach is monotone (each step closes the fraction
         * alpha < 1 of the deficit), so once at or below the target the
         * creepage never exceeds it (1e-12: rounding); coming down from a
         * higher target the last beta step undershoots by at most beta */
        snprintf(buf, sizeof buf, "static braking %g: never above the target once below it",
                 xref);
        CHECK(over <= 1e-12, buf);
        if (xprev > xref) {
            snprintf(buf, sizeof buf, "static braking %g: first undershoot at most one beta "
                     "step", xref);
            CHECK(under > 0.0 && under <= p.beta + 1e-12, buf);
        }
        snprintf(buf, sizeof buf, "static braking %g: wheel slower than the roller, "
                 "K = 1 - xi", xref);
        CHECK(w * R_W < V_ROLLER && fabs(s.K - (1.0 - xi)) < 1e-12, buf);
        xprev = xref;
    }

    /* traction mirrors it, and so does running backward (w_ref carries the
     * roller's sign): target 0.02 from free rolling, 459 samples predicted */
    for (dir = 1; dir >= -1; dir -= 2) {
        int sense;
        for (sense = -1; sense <= 1; sense += 2) {
            const double xref = 0.02;
            double wrd = dir * wr;
            p.sense = sense;
            rr_creepctl_init(&p, &s, 1.0, wrd);
            w = s.w_ref;
            nconv = static_run(&p, &s, wrd, xref, nsamp, &w, &xi, &over, &under, &stays);
            npred = predicted_samples(0.0, xref, p.alpha, p.beta);
            snprintf(buf, sizeof buf, "static %s %s: creepage 0.02 within 1 %% after %d "
                     "samples (predicted %d), and stays",
                     sense > 0 ? "traction" : "braking", dir > 0 ? "forward" : "backward",
                     nconv, npred);
            CHECK(nconv > 0 && abs(nconv - npred) <= 1 && stays, buf);
            CHECK_CLOSE(xi, xref, 0.0, 0.01, buf);
            snprintf(buf, sizeof buf, "static %s %s: wheel %s than the roller, same "
                     "direction", sense > 0 ? "traction" : "braking",
                     dir > 0 ? "forward" : "backward", sense > 0 ? "faster" : "slower");
            CHECK(w * wrd > 0.0
                  && (sense > 0 ? fabs(w) * R_W > V_ROLLER : fabs(w) * R_W < V_ROLLER), buf);
        }
    }

    /* coming down with the recovery step: each step lowers the creepage by
     * beta exactly (up to rounding) */
    p.sense = RR_CREEPCTL_BRAKING;
    rr_creepctl_init(&p, &s, 1.0 - 0.04, wr);
    w = s.w_ref;
    {
        int n, ok = 1;
        double x0, x1;
        rr_creepctl_xi(&p, w, wr, &x0);
        for (n = 0; n < 10; n++) {
            rr_creepctl_update(&p, &s, 0.015, w, wr, &w);
            rr_creepctl_xi(&p, w, wr, &x1);
            if (fabs(x0 - x1 - p.beta) > 1e-14)
                ok = 0;
            x0 = x1;
        }
        CHECK(ok, "static braking above the target: creepage falls by beta per sample");
    }
}

/* ---- closed loop ------------------------------------------------------------------------- */

/*
 * Every element in its place, around a two-inertia model:
 *   roller    J_r w_r' = T_r - r_r F - c_r w_r   (its drive holds 5 m/s)
 *   wheelset  J_w w_w' = T_w + r_w F             (its drive brakes)
 *   F = mu N (2/pi) atan(xi/xi0), xi = (w_r r_r - w_w r_w)/(w_r r_r),
 * F the creep force on the wheel (forward when the wheel is slower), bounded
 * by mu N.  Each drive: encoder -> PI (T = 1 ms) -> lag (tau = 5 ms) ->
 * torque; the creepage controller sets the wheelset's speed reference from
 * the two encoder speeds.  The plant is integrated by classical RK4 with 20
 * sub-steps per sample, far below its fastest time constant (~10 ms).
 * The paper's scenario with its alpha = 0.01 and beta = 0.002: braking,
 * targets 0.04, 0.015, 0.02, 0.03, each held 3 s.  The encoders have 2^22
 * counts (a sin/cos encoder with interpolation).
 * From free rolling the creepage reaches 0.04 within 1 % after 458 samples,
 * as the ideal-loop prediction (459): the speed loop (~10 ms) is much faster
 * than the adaptation of K (100 samples).  Held, it is biased low, because
 * any negative dxi, however small, fires the full recovery step beta while
 * a positive one only moves alpha dxi.  A count of encoder noise (one count
 * per sample is 2 pi r_w/(counts T V) = 2.7e-5 in creepage) or a slight
 * overshoot of the speed loop tips xi_est over the target every few hundred
 * samples; each time the creepage drops by beta and climbs back with the
 * factor (1 - alpha) per sample: a sawtooth one beta deep below the target.
 * Measured with this model (mean of the last second): 0.2 - 0.25 beta =
 * 4 - 5e-4 low, i.e. 1.3 % at 0.04, 2.7 % at 0.015, 2.4 % at 0.02, 1.6 % at
 * 0.03; in the last second the creepage stays below each target (at best
 * 0.05 % below) and dips at most 1.2 beta below it.  The bias is set by the
 * size of the recovery step more than by the noise: essentially noise-free
 * (2^30 counts) it is still 0.1 beta = 2e-4 (0.5 - 1.3 %), with 2^16 counts
 * 1.1 - 1.5 beta (5 - 15 %), and with beta/100 at 2^22 counts only
 * 0.1 - 0.25 %.  With the
 * earlier reading (eq. 13-14 on w_ref in rad/s, where beta = 0.002 rad/s
 * was a creepage step of 3.7e-5) the test needed alpha raised to 1 rad/s
 * and was 0.3 % low at 0.015: the noise bias is larger now, because the
 * paper's recovery step, read on K, is 54 times larger.
 */
typedef struct {
    double Jr, Jw, cr, mu, N, xi0;
    double Tr, Tw;  /* drive torques held over a sub-step [N m] */
} plant;

static double creep_force(const plant *m, double wr, double ww)
{
    double V = wr * R_R;
    double xi = (V - ww * R_W) / (V > 0.01 ? V : 0.01);
    return m->mu * m->N * (2.0 / RR_PI) * atan(xi / m->xi0);
}

/* y = (w_r, w_w, theta_r, theta_w) */
static void plant_rhs(const plant *m, const double y[4], double dy[4])
{
    double F = creep_force(m, y[0], y[1]);
    dy[0] = (m->Tr - R_R * F - m->cr * y[0]) / m->Jr;
    dy[1] = (m->Tw + R_W * F) / m->Jw;
    dy[2] = y[0];
    dy[3] = y[1];
}

static void rk4(const plant *m, double y[4], double h)
{
    double k1[4], k2[4], k3[4], k4[4], t[4];
    int i;
    plant_rhs(m, y, k1);
    for (i = 0; i < 4; i++) t[i] = y[i] + 0.5 * h * k1[i];
    plant_rhs(m, t, k2);
    for (i = 0; i < 4; i++) t[i] = y[i] + 0.5 * h * k2[i];
    plant_rhs(m, t, k3);
    for (i = 0; i < 4; i++) t[i] = y[i] + h * k3[i];
    plant_rhs(m, t, k4);
    for (i = 0; i < 4; i++) y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
}

/*
 * One closed-loop run: the paper's braking scenario, targets in turn, each
 * held nsamp samples; per target the mean and the extremes of the true
 * creepage over the last navg samples, the mean roller surface speed, and
 * the number of samples until the true creepage first came within 1 % of
 * the target.  Returns the OR of every status.
 */
typedef struct {
    double mean, lo, hi, v_roller, Tw_end;
    int nconv;
} cl_result;

static int closed_loop_run(int counts, double alpha, double beta, const double *targets,
                           int ntargets, int nsamp, int navg, cl_result *res, double *Fmax)
{
    const double T = 1e-3, wr0 = V_ROLLER / R_R;
    const int nsub = 20;
    plant m = {3.0, 1.0, 0.05, 0.4, 900.85, 0.01, 0.0, 0.0};
    rr_pi_params pir = {1e-3, 300.0, 2.0, 150.0}, piw = {1e-3, 100.0, 2.0, 60.0};
    rr_lag_params lag = {5e-3};
    rr_encoder_params enc;
    rr_creepctl_params cc = creepctl_paper(RR_CREEPCTL_BRAKING);
    rr_pi_state sr, sw;
    rr_lag_state lr, lw;
    rr_encoder_state er, ew;
    rr_creepctl_state sc;
    double y[4], wref_w;
    int i, st = 0;

    enc.T = T;
    enc.counts = counts;
    cc.alpha = alpha;
    cc.beta = beta;
    *Fmax = 0.0;
    y[0] = wr0;
    y[1] = wr0 * R_R / R_W;
    y[2] = y[3] = 0.0;
    /* start at free rolling, the roller's drive supplying its damping loss */
    st |= rr_pi_reset(&pir, &sr, m.cr * wr0);
    st |= rr_pi_init(&piw, &sw);
    st |= rr_lag_reset(&lag, &lr, m.cr * wr0);
    st |= rr_lag_init(&lag, &lw);
    st |= rr_encoder_reset(&enc, &er, y[0]);
    st |= rr_encoder_reset(&enc, &ew, y[1]);
    st |= rr_creepctl_init(&cc, &sc, 1.0, wr0);
    wref_w = sc.w_ref;

    for (i = 0; i < ntargets; i++) {
        double xsum = 0.0, wrsum = 0.0;
        int n, k;
        res[i].lo = INFINITY;
        res[i].hi = -INFINITY;
        res[i].nconv = -1;
        for (n = 0; n < nsamp; n++) {
            double wmr, wmw, ur, uw, xi, F;
            /* sample: encoders, creepage controller, PIs; outputs held */
            st |= rr_encoder_update(&enc, &er, y[2], &wmr);
            st |= rr_encoder_update(&enc, &ew, y[3], &wmw);
            st |= rr_creepctl_update(&cc, &sc, targets[i], wmw, wmr, &wref_w);
            st |= rr_pi_update(&pir, &sr, wr0, wmr, &ur);
            st |= rr_pi_update(&piw, &sw, wref_w, wmw, &uw);
            for (k = 0; k < nsub; k++) {
                st |= rr_lag_update(&lag, &lr, ur, T / nsub, &m.Tr);
                st |= rr_lag_update(&lag, &lw, uw, T / nsub, &m.Tw);
                rk4(&m, y, T / nsub);
            }
            F = fabs(creep_force(&m, y[0], y[1]));
            if (F > *Fmax)
                *Fmax = F;
            xi = (y[0] * R_R - y[1] * R_W) / (y[0] * R_R);
            if (res[i].nconv < 0 && fabs(xi - targets[i]) <= 0.01 * targets[i])
                res[i].nconv = n + 1;
            if (n >= nsamp - navg) {
                xsum += xi;
                wrsum += y[0];
                if (xi < res[i].lo)
                    res[i].lo = xi;
                if (xi > res[i].hi)
                    res[i].hi = xi;
            }
        }
        res[i].mean = xsum / navg;
        res[i].v_roller = wrsum / navg * R_R;
        res[i].Tw_end = m.Tw;
    }
    return st;
}

static void test_closed_loop(void)
{
    static const double targets[] = {0.04, 0.015, 0.02, 0.03};
    const int nt = 4, nsamp = 3000, navg = 1000, npred = 459;
    const double mu_N = 0.4 * 900.85, beta = 0.002;
    cl_result r[4];
    double Fmax;
    int i, st;
    char buf[160];

    st = closed_loop_run(1 << 22, 0.01, beta, targets, nt, nsamp, navg, r, &Fmax);
    CHECK_STATUS(st, RR_OK, "closed loop: every update OK");
    snprintf(buf, sizeof buf, "closed loop: 0.04 first reached within 1 %% after %d samples "
             "(ideal speed loop: %d)", r[0].nconv, npred);
    CHECK(r[0].nconv > 0 && abs(r[0].nconv - npred) <= 10, buf);
    for (i = 0; i < nt; i++) {
        const double x = targets[i];
        printf("  closed loop %.3f: mean creepage %+.2f %% (%+.1e) of the target, "
               "range %+.1f .. %+.2f %%\n", x, 100.0 * (r[i].mean / x - 1.0), r[i].mean - x,
               100.0 * (r[i].lo / x - 1.0), 100.0 * (r[i].hi / x - 1.0));
        snprintf(buf, sizeof buf, "closed loop braking %g: mean creepage of the last 1 s "
                 "below the target by less than 0.3 beta", x);
        CHECK(r[i].mean <= x && r[i].mean >= x - 0.3 * beta, buf);
        snprintf(buf, sizeof buf, "closed loop braking %g: never above the target by more "
                 "than 0.2 %%, never below by more than 1.3 beta", x);
        CHECK(r[i].hi <= 1.002 * x && r[i].lo >= x - 1.3 * beta, buf);
        snprintf(buf, sizeof buf, "closed loop, target %g: roller held at 5 m/s (0.1 %%)", x);
        CHECK_CLOSE(r[i].v_roller, V_ROLLER, 0.0, 1e-3, buf);
        snprintf(buf, sizeof buf, "closed loop, target %g: wheelset drive brakes", x);
        CHECK(r[i].Tw_end < 0.0, buf);
    }
    CHECK(Fmax <= mu_N, "closed loop: creep force never above mu N");

    /* the bias is the recovery step's: with beta / 100 the mean is within
     * 0.5 % of every target (measured: 0.10 .. 0.25 % low) */
    st = closed_loop_run(1 << 22, 0.01, beta / 100.0, targets, nt, nsamp, navg, r, &Fmax);
    CHECK_STATUS(st, RR_OK, "closed loop, beta/100: every update OK");
    for (i = 0; i < nt; i++) {
        snprintf(buf, sizeof buf, "closed loop, beta/100: creepage %g held within 0.5 %% "
                 "(mean of the last 1 s)", targets[i]);
        CHECK_CLOSE(r[i].mean, targets[i], 0.0, 5e-3, buf);
    }
}

/* A drive's sampled speed loop (rr_speed_loop): its radius against closed
 * forms, its stable range against the P loop's exact limit and the
 * continuous PI's Routh-Hurwitz limit, and its errors. */
static void test_speed_loop(void)
{
    /* P only, no lag (tau 1e-12 s: E = 0, G1 = G2 = 1e-10), kp = Kp T / J:
     * w+ = w - kp z, z+ = w - kp z / 2 (z the mean speed over the sample,
     * eq. 12), so z^2 - (1 - kp/2) z + kp/2 = 0: complex poles of modulus
     * sqrt(kp / 2) for kp = 1, real ones for kp = 0.1; stable up to kp = 2,
     * T = 2 J / Kp. */
    rr_speed_loop l = {{0.01, 100.0, 0.0, 50.0}, 1.0, 1e-12, 0.0};
    double rho, lo, hi, b, c;
    CHECK_STATUS(rr_speed_loop_radius(&l, &rho), RR_OK, "P loop");
    CHECK_CLOSE(rho, sqrt(0.5), 1e-8, 0.0, "kp = 1: |z| = sqrt(kp / 2)");
    l.pi.T = 0.001;
    b = 1.0 - 0.05;
    c = 0.05;
    CHECK_STATUS(rr_speed_loop_radius(&l, &rho), RR_OK, "P loop, kp = 0.1");
    CHECK_CLOSE(rho, 0.5 * (b + sqrt(b * b - 4.0 * c)), 1e-8, 0.0, "kp = 0.1: the real root");
    CHECK_STATUS(rr_speed_loop_range(&l, 1e-6, 0.1, &lo, &hi), RR_OK, "P loop range");
    CHECK_CLOSE(hi, 2.0 * l.J / l.pi.Kp, 0.0, 1e-8, "stable up to T = 2 J / Kp");
    CHECK(lo == 1e-6, "and from the shortest time asked");
    l.pi.T = 0.0199;
    CHECK_STATUS(rr_speed_loop_check(&l), RR_OK, "kp = 1.99: stable");
    l.pi.T = 0.0201;
    CHECK_STATUS(rr_speed_loop_check(&l), RR_ERR_PARAM, "kp = 2.01: unstable");

    /* the roller's PI (Kp 300, KI 2 per sample on 1.5 kg m^2, 1 ms lag): at
     * short samples the loop nears the continuous one, J tau s^3 + J s^2 +
     * Kp s + KI / T, which Routh-Hurwitz keeps stable only for Kp T > tau KI:
     * the lower limit tau KI / Kp = 6.67 us, within 1 % (the encoder's half
     * sample of delay) */
    l.pi.Kp = 300.0;
    l.pi.KI = 2.0;
    l.J = 1.5;
    l.tau = 1e-3;
    CHECK_STATUS(rr_speed_loop_range(&l, 1e-6, 0.1, &lo, &hi), RR_OK, "roller range");
    CHECK_CLOSE(lo, l.tau * l.pi.KI / l.pi.Kp, 0.0, 0.01, "lower limit: Routh-Hurwitz");
    CHECK(hi > 0.008 && hi < 2.0 * l.J / l.pi.Kp, "upper limit below the lag-free P loop's");
    l.pi.T = 0.004;
    CHECK_STATUS(rr_speed_loop_radius(&l, &rho), RR_OK, "at 4 ms");
    CHECK(rho < 1.0 && rho > 0.99, "stable, the integral's slow pole near 1");

    /* no gains: the inertia keeps its speed (a pole at 1), at any sample */
    l.pi.Kp = l.pi.KI = 0.0;
    l.pi.T = 0.1;
    CHECK_STATUS(rr_speed_loop_radius(&l, &rho), RR_OK, "no gains");
    CHECK_CLOSE(rho, 1.0, 1e-12, 0.0, "a held speed: radius 1");
    CHECK_STATUS(rr_speed_loop_check(&l), RR_OK, "held, not growing: stable");
    /* the same where T / tau underflows to 0 (a subnormal sample, a huge lag:
     * G1 = (1 - exp(-a)) / a was 0/0 and the radius +inf; fuzz_control) */
    l.pi.T = 8.1482516377275492e-310;
    l.tau = 2.1789786685991768e+158;
    CHECK_STATUS(rr_speed_loop_radius(&l, &rho), RR_OK, "no gains, T / tau = 0");
    CHECK_CLOSE(rho, 1.0, 1e-12, 0.0, "T / tau = 0: radius 1");
    CHECK_STATUS(rr_speed_loop_check(&l), RR_OK, "T / tau = 0: stable");
    l.pi.T = 0.1;
    l.tau = 1e-3;
    /* gains beyond any stable value: no stable time, NaN limits */
    l.pi.Kp = 1e300;
    l.J = 1e-300;
    CHECK_STATUS(rr_speed_loop_radius(&l, &rho), RR_OK, "overflowing gains");
    CHECK(isinf(rho), "radius +inf");
    CHECK_STATUS(rr_speed_loop_range(&l, 1e-6, 0.1, &lo, &hi), RR_ERR_PARAM, "no stable time");
    CHECK(isnan(lo) && isnan(hi), "NaN limits");
    /* a stable range that ends among the tiniest times: the bisection's
     * geometric mean sqrt(a b) underflowed to 0, so the range ended at 0,
     * below its own start (fuzz_control) */
    l.pi.T = 1.0346860992996427e-06;
    l.pi.KI = 48.760403844664445;
    l.J = 8.620040870995247;
    l.tau = 1.1191909246743634e-204;
    CHECK_STATUS(rr_speed_loop_range(&l, 2.1502881457880059e-290, 2.1502881457880058e-210, &lo,
                                     &hi), RR_OK, "range among the tiniest times");
    CHECK(lo == 2.1502881457880059e-290 && hi >= lo && hi < 2.1502881457880058e-210,
          "the range inside the times asked");
    l.pi.T = hi;
    CHECK_STATUS(rr_speed_loop_check(&l), RR_OK, "stable at the range's end");
    l.pi.T = 0.1;
    l.pi.KI = 0.0;
    l.tau = 1e-3;

    /* errors */
    l.pi.Kp = 300.0;
    l.J = 1.5;
    CHECK_STATUS(rr_speed_loop_radius(NULL, &rho), RR_ERR_NULL, "NULL loop");
    CHECK_STATUS(rr_speed_loop_radius(&l, NULL), RR_ERR_NULL, "NULL radius");
    l.J = 0.0;
    CHECK_STATUS(rr_speed_loop_radius(&l, &rho), RR_ERR_PARAM, "J = 0");
    CHECK(isnan(rho), "NaN radius on error");
    l.J = 1.5;
    l.tau = NAN;
    CHECK_STATUS(rr_speed_loop_check(&l), RR_ERR_NONFINITE, "tau NaN");
    l.tau = 1e-3;
    l.alpha = -0.1;
    CHECK_STATUS(rr_speed_loop_check(&l), RR_ERR_PARAM, "alpha < 0");
    l.alpha = 0.0;
    l.pi.T = 0.0;
    CHECK_STATUS(rr_speed_loop_check(&l), RR_ERR_PARAM, "T = 0 (rr_pi_check)");
    CHECK_STATUS(rr_speed_loop_range(&l, 0.1, 1e-6, &lo, &hi), RR_ERR_PARAM,
                 "Tlo > Thi (pi.T not used)");
    CHECK_STATUS(rr_speed_loop_range(&l, 0.0, 0.1, &lo, &hi), RR_ERR_PARAM, "Tlo = 0");
    CHECK_STATUS(rr_speed_loop_range(&l, 1e-6, INFINITY, &lo, &hi), RR_ERR_NONFINITE, "Thi");
    CHECK_STATUS(rr_speed_loop_range(&l, 1e-6, 0.1, NULL, &hi), RR_ERR_NULL, "NULL lo");
    CHECK(isnan(hi), "NaN hi on error");
}

int main(void)
{
    test_pi_bad_params();
    test_pi_eq10();
    test_pi_steady_state();
    test_pi_windup();
    test_lag();
    test_encoder_bad();
    test_encoder_constant();
    test_encoder_ramp();
    test_creepctl_bad();
    test_creepctl_unit();
    test_creepctl_static();
    test_closed_loop();
    test_speed_loop();
    return rr_test_summary();
}
