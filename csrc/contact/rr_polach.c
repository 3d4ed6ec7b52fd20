/* rr_polach.c - Polach's creep-force method, and its descriptor. */
#include <math.h>
#include "util/rr_common.h"
#include "contact/rr_polach.h"

/* rr_polach for reduction factors already checked (the descriptor's entry
 * point: the registry checked them); the case and the law checked here */
static int polach_checked(const rr_contact_problem *c, double kA, double kS, rr_forces *out)
{
    const rr_friction *fr;
    rr_kalker_coeffs k;
    double syc, sc, s, cjj, mu, eps, F, Ft;
    int st;

    if (!out)
        return RR_ERR_NULL;
    st = rr_creep_prepare(c, &k);
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    fr = &c->friction;
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

int rr_polach(const rr_contact_problem *p, double kA, double kS, rr_forces *out)
{
    int st = RR_OK;

    if (!out)
        return RR_ERR_NULL;
    if (!isfinite(kA) || !isfinite(kS))
        st = RR_ERR_NONFINITE;
    else if (kS <= 0.0 || kS > kA || kA > 1.0)
        st = RR_ERR_PARAM;
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    return polach_checked(p, kA, kS, out);
}

/* Polach 2005: 0 < kS <= kA <= 1 (each option's range gives 0 < kS, kA <= 1) */
static int polach_check(const rr_creep_opts *o, int *bad)
{
    if (o->v[RR_POLACH_KS] > o->v[RR_POLACH_KA]) {
        *bad = RR_POLACH_KS;
        return RR_ERR_PARAM;
    }
    return RR_OK;
}

/* small creepage: Kalker's linear theory times (kA + kS)/2 */
static double polach_slope(const rr_creep_opts *o)
{
    return 0.5 * (o->v[RR_POLACH_KA] + o->v[RR_POLACH_KS]);
}

static int polach_forces(const rr_contact_problem *p, const rr_creep_opts *o, double *work,
                         rr_forces *out)
{
    (void)work;
    return polach_checked(p, o->v[RR_POLACH_KA], o->v[RR_POLACH_KS], out);
}

/* each option at its index of rr_polach.h */
static const rr_creep_option polach_opts[] = {
    [RR_POLACH_KA] = {"kA", RR_OPT_REAL, "", 1.0, 0.0, 1.0, 1, 0, NULL, RR_ERR_PARAM,
                      "adhesion reduction factor (small creepage)"},
    [RR_POLACH_KS] = {"kS", RR_OPT_REAL, "", 1.0, 0.0, 1.0, 1, 0, NULL, RR_ERR_PARAM,
                      "slip reduction factor (large creepage), kS <= kA"},
};

const rr_method_desc rr_method_polach = {
    .name = "polach",
    .doc = "Polach 1999/2005 with spin: reduction factors 0 < kS <= kA <= 1",
    .nopts = RR_COUNTOF(polach_opts),
    .opts = polach_opts,
    .saturates = 1,
    .check = polach_check,
    .check_doc = "0 < kS <= kA <= 1",
    .cost = rr_method_unit_cost,
    .slope_scale = polach_slope,
    .workspace_len = rr_method_no_workspace,
    .forces = polach_forces,
};
