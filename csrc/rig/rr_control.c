/* rr_control.c - PI with limiter, drive lag, encoder, creepage controller (paper section 5). */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "rig/rr_control.h"

static double clip(double x, double lo, double hi)
{
    return x < lo ? lo : (x > hi ? hi : x);
}

/* ---- PI ------------------------------------------------------------------- */

int rr_pi_check(const rr_pi_params *p)
{
    if (!p)
        return RR_ERR_NULL;
    if (!isfinite(p->T) || !isfinite(p->Kp) || !isfinite(p->KI) || !isfinite(p->Tmax))
        return RR_ERR_NONFINITE;
    if (!(p->T > 0.0) || p->Kp < 0.0 || p->KI < 0.0 || !(p->Tmax > 0.0))
        return RR_ERR_PARAM;
    return RR_OK;
}

static void pi_set_nan(rr_pi_state *s)
{
    s->integral = s->u = NAN;
    s->saturated = 0;
}

int rr_pi_init(const rr_pi_params *p, rr_pi_state *s)
{
    return rr_pi_reset(p, s, 0.0);
}

int rr_pi_reset(const rr_pi_params *p, rr_pi_state *s, double torque0)
{
    int st = s ? rr_pi_check(p) : RR_ERR_NULL;

    if (!s)
        return st;
    if (st == RR_OK && !isfinite(torque0))
        st = RR_ERR_NONFINITE;
    if (st != RR_OK) {
        pi_set_nan(s);
        return st;
    }
    s->integral = s->u = clip(torque0, -p->Tmax, p->Tmax);
    s->saturated = 0;
    return RR_OK;
}

int rr_pi_update(const rr_pi_params *p, rr_pi_state *s, double w_ref, double w_m,
                 double *torque)
{
    double e, i0, In, v, Tmax;
    int st = s && torque ? rr_pi_check(p) : RR_ERR_NULL;

    if (!torque)
        return st;
    if (st == RR_OK && (!isfinite(w_ref) || !isfinite(w_m) || !isfinite(s->integral)))
        st = RR_ERR_NONFINITE;
    if (st == RR_OK && !isfinite(w_ref - w_m))
        st = RR_ERR_RANGE;          /* speeds near the largest double */
    if (st != RR_OK) {
        *torque = NAN;
        return st;
    }
    Tmax = p->Tmax;
    e = w_ref - w_m;
    /* a limit lowered since the last sample must bind the integral at once */
    i0 = clip(s->integral, -Tmax, Tmax);
    In = i0 + p->KI * e;
    v = p->Kp * e + In;
    s->saturated = v > Tmax ? 1 : (v < -Tmax ? -1 : 0);
    /* conditional integration: push the integral no further than the point
     * where the output meets the limit, and never back because of a large
     * proportional part (that would be back-calculation, not clamping) */
    if (v > Tmax && e > 0.0) {
        In = Tmax - p->Kp * e;
        if (In < i0)
            In = i0;
    } else if (v < -Tmax && e < 0.0) {
        In = -Tmax - p->Kp * e;
        if (In > i0)
            In = i0;
    }
    s->integral = In;
    s->u = clip(p->Kp * e + In, -Tmax, Tmax);
    *torque = s->u;
    return RR_OK;
}

/* ---- a drive's sampled speed loop ------------------------------------------ */

#define LOOP_N 5   /* speed, drive torque, angle increment, integral, reference */

static int loop_params_check(const rr_speed_loop *l)
{
    int st;
    if (!l)
        return RR_ERR_NULL;
    if ((st = rr_pi_check(&l->pi)) != RR_OK)
        return st;
    if (!isfinite(l->J) || !isfinite(l->tau) || !isfinite(l->alpha))
        return RR_ERR_NONFINITE;
    if (!(l->J > 0.0) || !(l->tau > 0.0) || !(l->alpha >= 0.0))
        return RR_ERR_PARAM;
    return RR_OK;
}

/*
 * The transition matrix of the closed loop over one sample T, the states
 * in units of speed (the torques as the speed change they give over a
 * sample, T/J times them; the angle increment over the last sample as its
 * mean speed).  The drive torque m follows the held PI output u through
 * the lag, m' = (u - m)/tau; the speed w' = m/J.  Over T with a = T/tau,
 * E = exp(-a), G1 = (1 - E)/a, G2 = (1 - G1)/a:
 *     w+ = w + G1 m + (1 - G1) u,   m+ = E m + (1 - E) u,
 *     z+ = w + G2 m + (1/2 - G2) u                    (z: mean speed over it)
 * and at the sample, with the measured speed z (eq. 12):
 *     r+ = r - alpha z     (eq. 13's reference, before the PI reads it)
 *     e = r+ - z,  u = (kp + ki) e + I,  I+ = I + ki e     (eq. 10)
 * kp = Kp T/J, ki = KI T/J.  The integral without KI, and the reference
 * without alpha, are constants (an offset, the set point), not states of
 * the loop: left out, so that their pole at 1 does not hide the loop's.
 * Returns the order n (3 to 5), the n x n matrix in A; 0 where a number
 * overflows.
 */
static int loop_matrix(const rr_speed_loop *l, double T, double A[LOOP_N * LOOP_N])
{
    const double kp = l->pi.Kp * T / l->J, ki = l->pi.KI * T / l->J, a = T / l->tau;
    const double E = exp(-a), k = kp + ki;
    /* G2 = (a - 1 + exp(-a))/a^2 loses its digits for small a: its series;
     * G1 is 1 at a = 0 (T / tau underflows: a subnormal T, a huge tau) */
    const double G1 = a > 0.0 ? -expm1(-a) / a : 1.0;
    const double G2 = a < 1e-3 ? 0.5 - a / 6.0 + a * a / 24.0 : (1.0 - G1) / a;
    /* e and u as rows over the states (w, m, z, I, r) */
    const double e[LOOP_N] = {0.0, 0.0, -(1.0 + l->alpha), 0.0, 1.0};
    const double own[3][LOOP_N] = {{1.0, G1, 0.0, 0.0, 0.0},
                                   {0.0, E, 0.0, 0.0, 0.0},
                                   {1.0, G2, 0.0, 0.0, 0.0}};
    const double share[3] = {1.0 - G1, 1.0 - E, 0.5 - G2};
    double F[LOOP_N * LOOP_N];
    int keep[LOOP_N], n = 0, i, j;
    for (j = 0; j < LOOP_N; j++) {
        const double u = k * e[j] + (j == 3);
        for (i = 0; i < 3; i++)
            F[i * LOOP_N + j] = own[i][j] + share[i] * u;
        F[3 * LOOP_N + j] = (j == 3) + ki * e[j];
        F[4 * LOOP_N + j] = (j == 4) - (j == 2) * l->alpha;
    }
    for (j = 0; j < LOOP_N; j++)
        if (j < 3 || (j == 3 && ki > 0.0) || (j == 4 && l->alpha > 0.0))
            keep[n++] = j;
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++)
            A[i * n + j] = F[keep[i] * LOOP_N + keep[j]];
    return rr_all_finite(A, n * n) ? n : 0;
}

/* max row sum of |B|, B n x n */
static double norm_inf(const double *B, int n)
{
    double m = 0.0;
    int i, j;
    for (i = 0; i < n; i++) {
        double s = 0.0;
        for (j = 0; j < n; j++)
            s += fabs(B[i * n + j]);
        m = s > m ? s : m;
    }
    return m;
}

/*
 * log rho(A) = lim 2^-K log ||A^(2^K)||: with B_0 = A, s_k = ||B_k||,
 * B_(k+1) = (B_k / s_k)^2, log ||A^(2^K)|| = sum_k 2^(K-k) log s_k + log
 * ||B_K||, so log rho = sum_k 2^-k log s_k to within 2^-K log of the
 * eigenvectors' condition: no overflow, and each rounding weighed by 2^-k.
 */
static double loop_radius(const double *A, int n)
{
    double B[LOOP_N * LOOP_N], C[LOOP_N * LOOP_N], sum = 0.0, w = 1.0;
    int k, i, j, m;
    memcpy(B, A, (size_t)(n * n) * sizeof *B);
    for (k = 0; k < 60; k++, w *= 0.5) {
        const double s = norm_inf(B, n);
        if (!(s > 0.0))
            return 0.0;               /* nilpotent: every pole at 0 */
        sum += w * log(s);
        for (i = 0; i < n * n; i++)
            C[i] = B[i] / s;
        for (i = 0; i < n; i++)
            for (j = 0; j < n; j++) {
                double acc = 0.0;
                for (m = 0; m < n; m++)
                    acc += C[i * n + m] * C[m * n + j];
                B[i * n + j] = acc;
            }
    }
    return exp(sum);
}

int rr_speed_loop_radius(const rr_speed_loop *l, double *rho)
{
    double A[LOOP_N * LOOP_N];
    int st = rho ? loop_params_check(l) : RR_ERR_NULL, n;
    if (!rho)
        return st;
    *rho = NAN;
    if (st != RR_OK)
        return st;
    n = loop_matrix(l, l->pi.T, A);
    *rho = n > 0 ? loop_radius(A, n) : INFINITY;
    return RR_OK;
}

int rr_speed_loop_check(const rr_speed_loop *l)
{
    double rho;
    const int st = rr_speed_loop_radius(l, &rho);
    if (st != RR_OK)
        return st;
    return rho <= 1.0 + RR_SPEED_LOOP_SLACK ? RR_OK : RR_ERR_PARAM;
}

/* 1 if the loop is stable at sample time T (parameters checked) */
static int stable_at(const rr_speed_loop *l, double T)
{
    double A[LOOP_N * LOOP_N];
    const int n = loop_matrix(l, T, A);
    return n > 0 && loop_radius(A, n) <= 1.0 + RR_SPEED_LOOP_SLACK;
}

/* the edge between a stable and an unstable time (either order), to 1e-9
 * relative: the stable end */
static double edge(const rr_speed_loop *l, double stable, double unstable)
{
    int i;
    for (i = 0; i < 200 && fabs(unstable - stable) > 1e-9 * stable; i++) {
        /* the geometric mean, each root apart: stable * unstable
         * underflows to 0 (or overflows) at the ends of the double range */
        const double mid = sqrt(stable) * sqrt(unstable);
        if (stable_at(l, mid))
            stable = mid;
        else
            unstable = mid;
    }
    return stable;
}

int rr_speed_loop_range(const rr_speed_loop *l, double Tlo, double Thi, double *lo,
                        double *hi)
{
    double first = NAN, last = NAN, prev = NAN;
    rr_speed_loop at;
    int st = lo && hi && l ? RR_OK : RR_ERR_NULL, n, i, prev_ok = 0;
    if (lo)
        *lo = NAN;
    if (hi)
        *hi = NAN;
    if (st == RR_OK && (!isfinite(Tlo) || !isfinite(Thi)))
        st = RR_ERR_NONFINITE;
    if (st == RR_OK && !(Tlo > 0.0 && Tlo <= Thi))
        st = RR_ERR_PARAM;
    if (st == RR_OK) {
        /* the loop's own sample time is not used: checked at Tlo */
        at = *l;
        at.pi.T = Tlo;
        st = loop_params_check(&at);
    }
    if (st != RR_OK)
        return st;
    /* 40 points a decade, on the logarithms (Thi / Tlo may overflow): the
     * whole double range is 632 decades, 25 281 points */
    n = 1 + (int)ceil(40.0 * (log10(Thi) - log10(Tlo)));
    for (i = 0; i < n; i++) {
        const double T = i == 0 ? Tlo : i == n - 1 ? Thi
                       : exp(log(Tlo) + (log(Thi) - log(Tlo)) * i / (n - 1));
        const int ok = stable_at(l, T);
        if (ok && isnan(first))
            first = i == 0 ? T : edge(l, T, prev);
        if (!ok && prev_ok)
            last = edge(l, prev, T);
        if (ok && i == n - 1)
            last = T;
        prev = T;
        prev_ok = ok;
    }
    if (isnan(first))
        return RR_ERR_PARAM;
    *lo = first;
    *hi = last;
    return RR_OK;
}

/* ---- lag ------------------------------------------------------------------- */

int rr_lag_check(const rr_lag_params *p)
{
    if (!p)
        return RR_ERR_NULL;
    if (!isfinite(p->tau))
        return RR_ERR_NONFINITE;
    if (p->tau < 0.0)
        return RR_ERR_PARAM;
    return RR_OK;
}

int rr_lag_init(const rr_lag_params *p, rr_lag_state *s)
{
    return rr_lag_reset(p, s, 0.0);
}

int rr_lag_reset(const rr_lag_params *p, rr_lag_state *s, double y0)
{
    int st = s ? rr_lag_check(p) : RR_ERR_NULL;

    if (!s)
        return st;
    if (st == RR_OK && !isfinite(y0))
        st = RR_ERR_NONFINITE;
    s->y = st == RR_OK ? y0 : NAN;
    return st;
}

int rr_lag_update(const rr_lag_params *p, rr_lag_state *s, double u, double h, double *y)
{
    int st = s && y ? rr_lag_check(p) : RR_ERR_NULL;

    if (!y)
        return st;
    if (st == RR_OK && (!isfinite(u) || !isfinite(h) || !isfinite(s->y)))
        st = RR_ERR_NONFINITE;
    if (st == RR_OK && h < 0.0)
        st = RR_ERR_PARAM;
    if (st != RR_OK) {
        *y = NAN;
        return st;
    }
    {
        const double yn = p->tau == 0.0 ? u : s->y + -expm1(-h / p->tau) * (u - s->y);
        if (!isfinite(yn)) {
            *y = NAN;               /* values near the largest double */
            return RR_ERR_RANGE;
        }
        s->y = yn;
    }
    *y = s->y;
    return RR_OK;
}

/* ---- encoder ---------------------------------------------------------------- */

int rr_encoder_check(const rr_encoder_params *p)
{
    if (!p)
        return RR_ERR_NULL;
    if (!isfinite(p->T))
        return RR_ERR_NONFINITE;
    if (!(p->T > 0.0) || p->counts < 1)
        return RR_ERR_PARAM;
    return RR_OK;
}

int rr_encoder_init(const rr_encoder_params *p, rr_encoder_state *s)
{
    return rr_encoder_reset(p, s, 0.0);
}

int rr_encoder_reset(const rr_encoder_params *p, rr_encoder_state *s, double w0)
{
    int st = s ? rr_encoder_check(p) : RR_ERR_NULL;

    if (!s)
        return st;
    if (st == RR_OK && !isfinite(w0))
        st = RR_ERR_NONFINITE;
    s->primed = 0;
    if (st != RR_OK) {
        s->count = s->theta_q = s->w = NAN;
        return st;
    }
    /* count and theta_q are meaningless until the first sample; 0 keeps
     * them finite for a caller who reads them early */
    s->count = s->theta_q = 0.0;
    s->w = w0;
    return RR_OK;
}

int rr_encoder_update(const rr_encoder_params *p, rr_encoder_state *s, double theta,
                      double *w)
{
    double q, c, wn;
    int st = s && w ? rr_encoder_check(p) : RR_ERR_NULL;

    if (!w)
        return st;
    if (st == RR_OK && (!isfinite(theta) || !isfinite(s->w) || !isfinite(s->count)))
        st = RR_ERR_NONFINITE;
    if (st != RR_OK) {
        *w = NAN;
        return st;
    }
    q = 2.0 * RR_PI / p->counts;
    c = floor(theta * p->counts / (2.0 * RR_PI));
    wn = s->primed ? (c - s->count) * q / p->T : s->w;
    if (!isfinite(c) || !isfinite(wn)) {
        *w = NAN;                   /* an angle near the largest double */
        return RR_ERR_RANGE;
    }
    /* the difference of two integer counts is exact, so at a whole number
     * of counts per sample the estimate carries no rounding beyond q/T */
    s->w = wn;
    s->primed = 1;
    s->count = c;
    s->theta_q = c * q;
    *w = s->w;
    return RR_OK;
}

/* ---- creepage controller ---------------------------------------------------- */

int rr_creepctl_check(const rr_creepctl_params *p)
{
    if (!p)
        return RR_ERR_NULL;
    if (!isfinite(p->r_w) || !isfinite(p->r_r) || !isfinite(p->alpha) || !isfinite(p->beta)
        || !isfinite(p->vmin))
        return RR_ERR_NONFINITE;
    if (!(p->r_w > 0.0) || !(p->r_r > 0.0))
        return RR_ERR_GEOMETRY;
    if (p->alpha < 0.0 || p->beta < 0.0
        || (p->sense != RR_CREEPCTL_TRACTION && p->sense != RR_CREEPCTL_BRAKING))
        return RR_ERR_PARAM;
    if (!(p->vmin > 0.0))
        return RR_ERR_SPEED;
    return RR_OK;
}

static void creepctl_set_nan(rr_creepctl_state *s)
{
    s->K = s->w_ref = s->xi_est = s->dxi = NAN;
}

int rr_creepctl_init(const rr_creepctl_params *p, rr_creepctl_state *s, double K,
                     double w_roller)
{
    int st = s ? rr_creepctl_check(p) : RR_ERR_NULL;

    if (!s)
        return st;
    if (st == RR_OK && (!isfinite(K) || !isfinite(w_roller)))
        st = RR_ERR_NONFINITE;
    if (st == RR_OK && K < 0.0)
        st = RR_ERR_PARAM;
    if (st == RR_OK && !isfinite(K * p->r_r / p->r_w * w_roller))
        st = RR_ERR_RANGE;
    if (st != RR_OK) {
        creepctl_set_nan(s);
        return st;
    }
    s->K = K;
    s->w_ref = K * p->r_r / p->r_w * w_roller;
    s->xi_est = s->dxi = 0.0;
    return RR_OK;
}

/* Eq. (16) in the sense, with the guarded denominator.  Parameters checked. */
static double creepage(const rr_creepctl_params *p, double w_wheelset, double w_roller)
{
    double v = w_roller * p->r_r, d = v;

    /* standstill: a named floor instead of eq. (16)'s w_roller != 0, only in
     * the denominator, so that the slip itself is kept and the estimate is
     * 0 at rest; the sign is kept so that running backward gives the same
     * creepage as running forward */
    if (fabs(d) < p->vmin)
        d = d < 0.0 ? -p->vmin : p->vmin;
    return p->sense * (w_wheelset * p->r_w - v) / d;
}

int rr_creepctl_xi(const rr_creepctl_params *p, double w_wheelset, double w_roller,
                   double *xi)
{
    int st = xi ? rr_creepctl_check(p) : RR_ERR_NULL;

    if (!xi)
        return st;
    if (st == RR_OK && (!isfinite(w_wheelset) || !isfinite(w_roller)))
        st = RR_ERR_NONFINITE;
    if (st != RR_OK) {
        *xi = NAN;
        return st;
    }
    *xi = creepage(p, w_wheelset, w_roller);
    if (!isfinite(*xi)) {
        *xi = NAN;                  /* speeds near the largest double */
        return RR_ERR_RANGE;
    }
    return RR_OK;
}

int rr_creepctl_update(const rr_creepctl_params *p, rr_creepctl_state *s, double xi_ref,
                       double w_wheelset, double w_roller, double *w_ref)
{
    double xi, dxi, K, w;
    int st = s && w_ref ? rr_creepctl_check(p) : RR_ERR_NULL;

    if (!w_ref)
        return st;
    if (st == RR_OK && (!isfinite(xi_ref) || !isfinite(w_wheelset) || !isfinite(w_roller)
                        || !isfinite(s->K)))
        st = RR_ERR_NONFINITE;
    if (st != RR_OK) {
        *w_ref = NAN;
        return st;
    }
    xi = creepage(p, w_wheelset, w_roller);
    dxi = xi_ref - xi;
    /* K = 1 + sense xi for the kinematic creepage xi: more creepage in the
     * sense moves K by +sense, less by -sense; eq. (15) then carries the
     * roller's sign, so running backward needs no extra factor */
    if (dxi >= 0.0)
        K = s->K + p->sense * p->alpha * dxi;
    else
        K = s->K - p->sense * p->beta;
    if (K < 0.0)
        K = 0.0;
    w = K * p->r_r / p->r_w * w_roller;
    if (!isfinite(w) || !isfinite(xi + dxi)) {
        *w_ref = NAN;               /* speeds or gains near the largest double */
        return RR_ERR_RANGE;
    }
    s->K = K;
    s->w_ref = w;
    s->xi_est = xi;
    s->dxi = dxi;
    *w_ref = w;
    return RR_OK;
}
