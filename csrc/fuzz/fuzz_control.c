/*
 * fuzz_control.c - the drive and control elements: PI controller with
 * limiter, first-order lag, encoder, creepage controller; and
 * rr_status_message.
 *
 * Input: one byte choosing the element, its parameters (plausible: the
 * paper's gains and limits, sample times 0.1 .. 10 ms, counts 1 .. 2^24),
 * init or reset with an operating point, then up to 16 updates with their
 * inputs.  The parameters may be changed between updates (the header
 * allows it).
 *
 * Oracles: documented errors (parameters, non-finite inputs); on error in
 * an update the output NaN and the state unchanged, in init/reset the
 * state NaN; on success finite outputs and states, and the element's
 * promises: the PI's output and integral within [-Tmax, Tmax] and its
 * saturation flag -1, 0 or 1; the lag's output between its old value and
 * the input; the encoder's count an integer and theta_q = count 2 pi /
 * counts; the creepage controller's K >= 0.  A drive's sampled speed loop
 * (rr_speed_loop): its radius >= 0 (+inf where its numbers overflow), NaN
 * on error; check agreeing with the radius; no gains and no outer loop
 * stable (a held speed); its stable range inside the times asked, stable
 * at both ends, starting at the first time asked where that is stable.
 */
#include "fuzz.h"

#define MAX_UPDATES 16

static void check_pi(fz_in *in)
{
    rr_pi_params p;
    rr_pi_state s, before;
    int n, k, st;

    p.T = fz_log(in, 1e-4, 1e-2);
    p.Kp = fz_log(in, 1.0, 1e3);
    p.KI = fz_log(in, 1e-2, 1e2);
    p.Tmax = fz_log(in, 1.0, 1e3);
    fz_note("PI T %.17g, Kp %.17g, KI %.17g, Tmax %.17g", p.T, p.Kp, p.KI, p.Tmax);
    memset(&s, 0x55, sizeof s);
    st = fz_choice(in, 2) ? rr_pi_reset(&p, &s, fz_lin(in, -200.0, 200.0)) : rr_pi_init(&p, &s);
    fz_status("rr_pi_reset", st);
    if (st < 0) {
        if (!isnan(s.integral) || !isnan(s.u))
            fz_fail("rr_pi_reset: error %d but the state is not NaN", st);
        return;
    }
    n = fz_range(in, 1, MAX_UPDATES);
    for (k = 0; k < n; k++) {
        const double w_ref = fz_lin(in, -100.0, 100.0), w_m = fz_lin(in, -100.0, 100.0);
        int invalid_p;
        double torque = 7.0;
        if (fz_choice(in, 8) == 0)
            p.Tmax = fz_log(in, 1.0, 1e3);      /* a new limit between samples */
        invalid_p = !isfinite(p.T) || !isfinite(p.Kp) || !isfinite(p.KI)
                    || !isfinite(p.Tmax) || !(p.T > 0.0) || !(p.Kp >= 0.0)
                    || !(p.KI >= 0.0) || !(p.Tmax > 0.0);
        fz_note("; update(w_ref %.17g, w_m %.17g, Tmax %.17g)", w_ref, w_m, p.Tmax);
        before = s;
        st = rr_pi_update(&p, &s, w_ref, w_m, &torque);
        fz_status("rr_pi_update", st);
        fz_error("rr_pi_update", st, invalid_p || !isfinite(w_ref) || !isfinite(w_m),
                 "an argument is invalid");
        if (st < 0) {
            if (!isnan(torque))
                fz_fail("rr_pi_update: error %d but torque = %g", st, torque);
            fz_same("rr_pi_update", &before, &s, sizeof s, "the state (error)");
            continue;
        }
        FZ_FINITE("rr_pi_update", st, torque);
        FZ_FINITE("rr_pi_update", st, s.integral);
        if (!(fabs(torque) <= p.Tmax) || !(fabs(s.integral) <= p.Tmax) || torque != s.u
            || s.saturated < -1 || s.saturated > 1)
            fz_fail("rr_pi_update: torque %.17g, integral %.17g, u %.17g, saturated %d with "
                    "Tmax %.17g", torque, s.integral, s.u, s.saturated, p.Tmax);
    }
}

static void check_lag(fz_in *in)
{
    rr_lag_params p;
    rr_lag_state s, before;
    int n, k, st;

    p.tau = fz_choice(in, 8) == 0 ? 0.0 : fz_log(in, 1e-5, 1.0);
    fz_note("lag tau %.17g", p.tau);
    memset(&s, 0x55, sizeof s);
    st = fz_choice(in, 2) ? rr_lag_reset(&p, &s, fz_lin(in, -200.0, 200.0)) : rr_lag_init(&p, &s);
    fz_status("rr_lag_reset", st);
    if (st < 0) {
        if (!isnan(s.y))
            fz_fail("rr_lag_reset: error %d but the state is not NaN", st);
        return;
    }
    n = fz_range(in, 1, MAX_UPDATES);
    for (k = 0; k < n; k++) {
        const double u = fz_lin(in, -200.0, 200.0), h = fz_log(in, 1e-6, 1e-1);
        const int invalid = !isfinite(p.tau) || !(p.tau >= 0.0) || !isfinite(u) || !isfinite(h)
                            || !(h >= 0.0);
        double y = 7.0, lo, hi, tol;
        fz_note("; update(u %.17g, h %.17g) from y %.17g", u, h, s.y);
        before = s;
        st = rr_lag_update(&p, &s, u, h, &y);
        fz_status("rr_lag_update", st);
        fz_error("rr_lag_update", st, invalid, "an argument is invalid");
        if (st < 0) {
            if (!isnan(y))
                fz_fail("rr_lag_update: error %d but y = %g", st, y);
            fz_same("rr_lag_update", &before, &s, sizeof s, "the state (error)");
            continue;
        }
        FZ_FINITE("rr_lag_update", st, y);
        /* a convex combination of the old output and the held input */
        lo = before.y < u ? before.y : u;
        hi = before.y < u ? u : before.y;
        tol = 4.0 * DBL_EPSILON * (fabs(lo) + fabs(hi));
        if (!(y >= lo - tol && y <= hi + tol) || y != s.y)
            fz_fail("rr_lag_update: y = %.17g outside [%.17g, %.17g] (old output, input)", y,
                    lo, hi);
    }
}

static void check_encoder(fz_in *in)
{
    rr_encoder_params p;
    rr_encoder_state s, before;
    double theta;
    int n, k, st;

    p.T = fz_log(in, 1e-4, 1e-2);
    p.counts = fz_int(in, 1, 16777216);
    fz_note("encoder T %.17g, counts %d", p.T, p.counts);
    memset(&s, 0x55, sizeof s);
    st = fz_choice(in, 2) ? rr_encoder_reset(&p, &s, fz_lin(in, -100.0, 100.0))
                          : rr_encoder_init(&p, &s);
    fz_status("rr_encoder_reset", st);
    if (st < 0) {
        if (!isnan(s.count) || !isnan(s.theta_q) || !isnan(s.w))
            fz_fail("rr_encoder_reset: error %d but the state is not NaN", st);
        return;
    }
    n = fz_range(in, 1, MAX_UPDATES);
    theta = fz_lin(in, -1e3, 1e3);
    for (k = 0; k < n; k++) {
        const int invalid = !isfinite(p.T) || !(p.T > 0.0) || p.counts < 1;
        double w = 7.0;
        theta += fz_lin(in, -1.0, 1.0);          /* an angle that moves on */
        fz_note("; update(theta %.17g)", theta);
        before = s;
        st = rr_encoder_update(&p, &s, theta, &w);
        fz_status("rr_encoder_update", st);
        fz_error("rr_encoder_update", st, invalid || !isfinite(theta), "an argument is invalid");
        if (st < 0) {
            if (!isnan(w))
                fz_fail("rr_encoder_update: error %d but w = %g", st, w);
            fz_same("rr_encoder_update", &before, &s, sizeof s, "the state (error)");
            continue;
        }
        FZ_FINITE("rr_encoder_update", st, w);
        FZ_FINITE("rr_encoder_update", st, s.count);
        FZ_FINITE("rr_encoder_update", st, s.theta_q);
        if (s.count != floor(s.count) || s.primed != 1 || w != s.w)
            fz_fail("rr_encoder_update: count %.17g, primed %d, w %.17g / %.17g", s.count,
                    s.primed, w, s.w);
    }
}

static int creepctl_invalid(const rr_creepctl_params *p)
{
    return !isfinite(p->r_w) || !isfinite(p->r_r) || !isfinite(p->alpha) || !isfinite(p->beta)
        || !isfinite(p->vmin) || !(p->r_w > 0.0) || !(p->r_r > 0.0) || !(p->alpha >= 0.0)
        || !(p->beta >= 0.0) || (p->sense != 1 && p->sense != -1) || !(p->vmin > 0.0);
}

static void check_creepctl(fz_in *in)
{
    rr_creepctl_params p;
    rr_creepctl_state s, before;
    double K, w_roller, xi = 7.0;
    int n, k, st;

    p.r_w = fz_log(in, 0.01, 1.0);
    p.r_r = fz_log(in, 0.01, 1.0);
    p.alpha = fz_log(in, 1e-4, 1.0);
    p.beta = fz_log(in, 1e-5, 0.1);
    p.vmin = fz_log(in, 1e-3, 1.0);
    p.sense = fz_choice(in, 16) == 0 ? fz_int(in, -1, 1) : (fz_choice(in, 2) ? 1 : -1);
    K = fz_lin(in, 0.0, 1.5);
    w_roller = fz_lin(in, -100.0, 100.0);
    fz_note("creepctl r_w %.17g, r_r %.17g, alpha %.17g, beta %.17g, vmin %.17g, sense %d; "
            "init(K %.17g, w_roller %.17g)", p.r_w, p.r_r, p.alpha, p.beta, p.vmin, p.sense, K,
            w_roller);
    memset(&s, 0x55, sizeof s);
    st = rr_creepctl_init(&p, &s, K, w_roller);
    fz_status("rr_creepctl_init", st);
    fz_error("rr_creepctl_init", st, creepctl_invalid(&p) || !isfinite(K) || !(K >= 0.0)
                                         || !isfinite(w_roller), "an argument is invalid");
    if (st < 0) {
        if (!isnan(s.K) || !isnan(s.w_ref) || !isnan(s.xi_est) || !isnan(s.dxi))
            fz_fail("rr_creepctl_init: error %d but the state is not NaN", st);
        return;
    }
    FZ_FINITE("rr_creepctl_init", st, s.w_ref);
    n = fz_range(in, 1, MAX_UPDATES);
    for (k = 0; k < n; k++) {
        const double xi_ref = fz_lin(in, 0.0, 0.1);
        const double w_wheel = fz_lin(in, -100.0, 100.0);
        double w_ref = 7.0;
        w_roller = fz_lin(in, -100.0, 100.0);
        fz_note("; update(xi_ref %.17g, w_wheelset %.17g, w_roller %.17g)", xi_ref, w_wheel,
                w_roller);
        st = rr_creepctl_xi(&p, w_wheel, w_roller, &xi);
        fz_status("rr_creepctl_xi", st);
        fz_error("rr_creepctl_xi", st, !isfinite(w_wheel) || !isfinite(w_roller),
                 "an argument is invalid");
        FZ_FINITE("rr_creepctl_xi", st, xi);
        before = s;
        st = rr_creepctl_update(&p, &s, xi_ref, w_wheel, w_roller, &w_ref);
        fz_status("rr_creepctl_update", st);
        fz_error("rr_creepctl_update", st, !isfinite(xi_ref) || !isfinite(w_wheel)
                                               || !isfinite(w_roller), "an argument is invalid");
        if (st < 0) {
            if (!isnan(w_ref))
                fz_fail("rr_creepctl_update: error %d but w_ref = %g", st, w_ref);
            fz_same("rr_creepctl_update", &before, &s, sizeof s, "the state (error)");
            continue;
        }
        FZ_FINITE("rr_creepctl_update", st, w_ref);
        FZ_FINITE("rr_creepctl_update", st, s.K);
        FZ_FINITE("rr_creepctl_update", st, s.xi_est);
        FZ_FINITE("rr_creepctl_update", st, s.dxi);
        if (!(s.K >= 0.0) || w_ref != s.w_ref)
            fz_fail("rr_creepctl_update: K = %.17g, w_ref %.17g / %.17g", s.K, w_ref, s.w_ref);
    }
}

static void check_speed_loop(fz_in *in)
{
    rr_speed_loop l;
    double rho = 7.0, lo = 7.0, hi = 7.0, Tlo, Thi;
    int st, st_check, st_range, invalid;

    l.pi.T = fz_log(in, 1e-6, 0.1);
    l.pi.Kp = fz_choice(in, 8) == 0 ? 0.0 : fz_log(in, 1e-2, 1e4);
    l.pi.KI = fz_choice(in, 8) == 0 ? 0.0 : fz_log(in, 1e-3, 1e3);
    l.pi.Tmax = 100.0;
    l.J = fz_log(in, 1e-3, 1e2);
    l.tau = fz_log(in, 1e-5, 0.1);
    l.alpha = fz_choice(in, 3) == 0 ? 0.0 : fz_log(in, 1e-4, 3.0);
    Tlo = fz_log(in, 1e-6, 1e-3);
    Thi = fz_log(in, 1e-3, 1.0);
    /* a scan of at most 80 decades (3 200 points): the whole double range
     * (25 281 points) is valid but takes some 10 s under the fuzzer's
     * instrumentation, past its timeout; the extreme ends themselves stay */
    if (Tlo > 0.0 && Thi > Tlo && isfinite(Thi) && log10(Thi) - log10(Tlo) > 80.0) {
        if (fz_choice(in, 2) == 0)
            Thi = Tlo * 1e80;
        else
            Tlo = Thi * 1e-80;
    }
    fz_note("speed loop T %.17g, Kp %.17g, KI %.17g, J %.17g, tau %.17g, alpha %.17g; range "
            "%.17g .. %.17g", l.pi.T, l.pi.Kp, l.pi.KI, l.J, l.tau, l.alpha, Tlo, Thi);
    invalid = !isfinite(l.pi.Kp) || !isfinite(l.pi.KI) || !isfinite(l.J) || !isfinite(l.tau)
           || !isfinite(l.alpha) || l.pi.Kp < 0.0 || l.pi.KI < 0.0 || !(l.J > 0.0)
           || !(l.tau > 0.0) || !(l.alpha >= 0.0);
    st = rr_speed_loop_radius(&l, &rho);
    fz_status("rr_speed_loop_radius", st);
    fz_error("rr_speed_loop_radius", st, invalid || !isfinite(l.pi.T) || !(l.pi.T > 0.0),
             "an argument is invalid");
    if (st < 0 && !isnan(rho))
        fz_fail("rr_speed_loop_radius: error %d with radius %g", st, rho);
    if (st >= 0 && !(rho >= 0.0))
        fz_fail("rr_speed_loop_radius: radius %.17g", rho);
    st_check = rr_speed_loop_check(&l);
    fz_status("rr_speed_loop_check", st_check);
    if (st >= 0 && (st_check == RR_OK) != (rho <= 1.0 + RR_SPEED_LOOP_SLACK))
        fz_fail("rr_speed_loop_check: status %d for radius %.17g", st_check, rho);
    if (st >= 0 && l.pi.Kp == 0.0 && l.pi.KI == 0.0 && l.alpha == 0.0 && st_check != RR_OK)
        fz_fail("rr_speed_loop_check: no gains, status %d (radius %.17g)", st_check, rho);
    st_range = rr_speed_loop_range(&l, Tlo, Thi, &lo, &hi);
    fz_status("rr_speed_loop_range", st_range);
    fz_error("rr_speed_loop_range", st_range, invalid || !isfinite(Tlo) || !isfinite(Thi)
                                                  || !(Tlo > 0.0 && Tlo <= Thi),
             "an argument is invalid");
    if (st_range < 0) {
        if (!isnan(lo) || !isnan(hi))
            fz_fail("rr_speed_loop_range: error %d with %g .. %g", st_range, lo, hi);
        return;
    }
    if (!(Tlo <= lo && lo <= hi && hi <= Thi))
        fz_fail("rr_speed_loop_range: %.17g .. %.17g outside %.17g .. %.17g", lo, hi, Tlo, Thi);
    l.pi.T = lo;
    if (rr_speed_loop_check(&l) != RR_OK)
        fz_fail("rr_speed_loop_range: unstable at its lower end %.17g", lo);
    l.pi.T = hi;
    if (rr_speed_loop_check(&l) != RR_OK)
        fz_fail("rr_speed_loop_range: unstable at its upper end %.17g", hi);
    l.pi.T = Tlo;
    if (rr_speed_loop_check(&l) == RR_OK && lo != Tlo)
        fz_fail("rr_speed_loop_range: stable at %.17g but the range starts at %.17g", Tlo, lo);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    switch (fz_choice(&in, 5)) {
    case 0:
        check_pi(&in);
        break;
    case 1:
        check_lag(&in);
        break;
    case 2:
        check_encoder(&in);
        break;
    case 3:
        check_creepctl(&in);
        break;
    default: {
        /* (a selector inside this case keeps the older inputs' elements) */
        if (fz_choice(&in, 2) == 1) {
            check_speed_loop(&in);
        } else {
            const int st = fz_range(&in, INT_MIN, INT_MAX);
            const char *msg = rr_status_message(st);
            if (!msg || !msg[0])
                fz_fail("rr_status_message(%d): no message", st);
        }
        break;
    }
    }
    return 0;
}
