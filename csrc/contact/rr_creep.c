/* rr_creep.c - method options, Kalker's linear theory, Polach's method,
 * and the dispatcher over all creep-force methods. */
#include <math.h>
#include "util/rr_common.h"
#include "contact/rr_kalker.h"
#include "contact/rr_creep.h"
#include "contact/rr_fastsim.h"

void rr_creep_opts_default(int method, rr_creep_opts *o)
{
    if (!o)
        return;
    o->method = method;
    o->nx = 30;
    o->ny = 30;
    o->bound = RR_BOUND_PARABOLIC;
    o->grid = RR_GRID_RECT;
    o->slip_speed = method == RR_METHOD_MODIFIED_FASTSIM ? RR_SLIP_RIGID : RR_SLIP_LOCAL;
    o->k0 = 0.54;
    o->alpha_inf = 0.02;
    o->beta = 0.62;
    o->kA = 1.0;
    o->kS = 1.0;
}

static int is_fastsim(int method)
{
    return method == RR_METHOD_FASTSIM || method == RR_METHOD_FASTSIM_BLENDED
        || method == RR_METHOD_MODIFIED_FASTSIM;
}

int rr_creep_opts_check(const rr_creep_opts *o)
{
    if (!o)
        return RR_ERR_NULL;
    if (o->method < 0 || o->method >= RR_METHOD_COUNT)
        return RR_ERR_METHOD;
    if (is_fastsim(o->method)) {
        if (o->bound != RR_BOUND_PARABOLIC && o->bound != RR_BOUND_ELLIPTIC)
            return RR_ERR_METHOD;
        if (o->grid != RR_GRID_RECT && o->grid != RR_GRID_STRIPS)
            return RR_ERR_METHOD;
        if (o->slip_speed != RR_SLIP_LOCAL && o->slip_speed != RR_SLIP_RIGID)
            return RR_ERR_METHOD;
        if (o->nx < 1 || o->ny < 1 || o->nx > RR_FASTSIM_MAX_GRID
            || o->ny > RR_FASTSIM_MAX_GRID)
            return RR_ERR_GRID;
    }
    if (o->method == RR_METHOD_MODIFIED_FASTSIM) {
        if (!isfinite(o->k0) || !isfinite(o->alpha_inf) || !isfinite(o->beta))
            return RR_ERR_NONFINITE;
        if (o->k0 <= 0.0 || o->k0 > 1.0 || o->alpha_inf < 0.0 || o->alpha_inf > 1.0
            || o->beta < 0.0)
            return RR_ERR_PARAM;
    }
    if (o->method == RR_METHOD_POLACH) {
        if (!isfinite(o->kA) || !isfinite(o->kS))
            return RR_ERR_NONFINITE;
        if (o->kS <= 0.0 || o->kS > o->kA || o->kA > 1.0)
            return RR_ERR_PARAM;
    }
    return RR_OK;
}

/* Kalker's coefficients of a checked case; RR_ERR_RANGE where a/b is not
 * a normal double (semi-axes some 300 orders of magnitude apart). */
static int kalker_of(const rr_contact_case *c, rr_kalker_coeffs *k)
{
    const double q = c->a / c->b;
    if (!isnormal(q)) {
        k->c11 = k->c22 = k->c23 = NAN;
        return RR_ERR_RANGE;
    }
    return rr_kalker(q, c->nu, k);
}

int rr_linear(const rr_contact_case *c, rr_forces *out)
{
    rr_kalker_coeffs k;
    double ab, c3, c33;
    int st = out ? rr_contact_check(c) : RR_ERR_NULL;

    if (st == RR_OK)
        st = kalker_of(c, &k);
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    ab = c->a * c->b;
    c3 = ab * sqrt(ab);
    c33 = 32.0 / (15.0 * RR_PI) * k.c23 * pow(c->b / c->a, 1.5);
    out->fx = -c->G * ab * k.c11 * c->cx;
    out->fy = -c->G * (ab * k.c22 * c->cy + c3 * k.c23 * c->cphi);
    out->mz = c->G * (c3 * k.c23 * c->cy - ab * ab * c33 * c->cphi);
    return rr_forces_checked(st, out);    /* no saturation: large inputs overflow */
}

int rr_creep_prepare(const rr_contact_case *c, const rr_friction *fr, rr_kalker_coeffs *k)
{
    int st = k ? rr_contact_check(c) : RR_ERR_NULL;

    if (st == RR_OK)
        st = rr_friction_check(fr);
    if (st == RR_OK && rr_friction_is_falling(fr) && !(c->speed > 0.0))
        st = RR_ERR_SPEED;
    if (st == RR_OK)
        st = kalker_of(c, k);
    return st;
}

int rr_polach(const rr_contact_case *c, const rr_friction *fr, double kA, double kS,
              rr_forces *out)
{
    rr_kalker_coeffs k;
    double syc, sc, s, cjj, mu, eps, F, Ft;
    int st = RR_OK;

    if (!out)
        return RR_ERR_NULL;
    if (!isfinite(kA) || !isfinite(kS))
        st = RR_ERR_NONFINITE;
    else if (kS <= 0.0 || kS > kA || kA > 1.0)
        st = RR_ERR_PARAM;
    else
        st = rr_creep_prepare(c, fr, &k);
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    out->fx = out->fy = out->mz = 0.0;

    /* spin adds to the lateral creepage only where it increases it */
    syc = c->cy + c->cphi * c->a;
    if (fabs(syc) <= fabs(c->cy))
        syc = c->cy;
    sc = hypot(c->cx, syc);
    if (sc == 0.0)
        return st;
    s = hypot(c->cx, c->cy);
    mu = rr_friction_mu(fr, c->speed * sc);
    if (s > 0.0) {
        double r;
        cjj = hypot(k.c11 * c->cx, k.c22 * c->cy) / s;
        eps = RR_PI * c->G * c->a * c->b * cjj * sc / (4.0 * c->N * mu);
        r = kA * eps;
        /* r/(1 + r^2), as 1/r where r^2 would overflow */
        F = 2.0 * c->N * mu / RR_PI * ((r < 1e150 ? r / (1.0 + r * kA * eps) : 1.0 / r)
                                       + atan(kS * eps));
        out->fx = -F * c->cx / sc;
        out->fy = -F * c->cy / sc;
    }
    if (c->cphi != 0.0) {
        /* Polach 1999: spin force through K_M; for cx = 0 its small-creepage
         * limit is Kalker's -G c^3 C23 cphi (the 9/16 and 8/3 are chosen for
         * that); with cx != 0 it is scaled by |s_yC| / s_C. */
        double ks = 1.0 + 6.3 * (1.0 - exp(-c->a / c->b));
        double epsm = 8.0 / 3.0 * c->G * c->b * sqrt(c->a * c->b) * k.c23 * fabs(syc)
                    / (c->N * mu * ks);
        double e2 = epsm * epsm;
        double d = (e2 - 1.0) / (e2 + 1.0);
        double q = 1.0 - d * d;
        /* K_M -> 0 (as -2/(3 eps_M^3)) where eps_M^2 overflows */
        double km = isfinite(e2) ? epsm * (d * d * d / 3.0 - d * d / 2.0 + 1.0 / 6.0)
                                       - sqrt(q * q * q) / 3.0
                                 : 0.0;
        out->fy += 9.0 / 16.0 * c->a * c->N * mu * km * ks * c->cphi / sc;
    }
    /* The spin force adds to the creep force unbounded: keep the sum on the
     * friction limit, |F| <= mu N (Coulomb's law holds for the total). */
    Ft = hypot(out->fx, out->fy);
    if (Ft > mu * c->N) {
        const double f = mu * c->N / Ft;
        out->fx *= f;
        out->fy *= f;
    }
    return rr_forces_checked(st, out);
}

int rr_creep_forces(const rr_contact_case *c, const rr_friction *fr,
                    const rr_creep_opts *o, rr_forces *out)
{
    int st = out ? rr_creep_opts_check(o) : RR_ERR_NULL;

    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    switch (o->method) {
    case RR_METHOD_LINEAR:
        /* the friction law goes unused, but a NaN or invalid one is still refused */
        if ((st = rr_friction_check(fr)) < 0) {
            rr_forces_nan(out);
            return st;
        }
        return rr_linear(c, out);
    case RR_METHOD_POLACH:
        return rr_polach(c, fr, o->kA, o->kS, out);
    default:
        return rr_fastsim(c, fr, o, out, 0);
    }
}
