/* rr_control.c - PI with limiter, drive lag, encoder, creepage controller (paper section 5). */
#include <math.h>
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
