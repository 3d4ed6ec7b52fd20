/* rr_friction.c - Coulomb and Polach (2005) falling friction. */
#include <math.h>
#include "util/rr_common.h"
#include "contact/rr_friction.h"

int rr_friction_check(const rr_friction *f)
{
    if (!f)
        return RR_ERR_NULL;
    if (!isfinite(f->mu0) || !isfinite(f->A) || !isfinite(f->B))
        return RR_ERR_NONFINITE;
    if (f->mu0 <= 0.0 || f->A <= 0.0 || f->A > 1.0 || f->B < 0.0)
        return RR_ERR_FRICTION;
    /* beyond these a force or the law's slope mu0 (1 - A) B overflows */
    if (f->mu0 > RR_FRICTION_MAX || f->B > RR_FRICTION_MAX)
        return RR_ERR_RANGE;
    return RR_OK;
}

int rr_friction_is_falling(const rr_friction *f)
{
    return f && f->A < 1.0 && f->B > 0.0;
}

/* exp(-B w), with B = 0 meaning no decay even at w = inf (not exp(NaN)). */
static double decay(const rr_friction *f, double w)
{
    return f->B > 0.0 ? exp(-f->B * w) : 1.0;
}

double rr_friction_mu(const rr_friction *f, double w)
{
    if (!f)
        return NAN;
    return f->mu0 * ((1.0 - f->A) * decay(f, w) + f->A);
}

double rr_friction_dmu(const rr_friction *f, double w)
{
    if (!f)
        return NAN;
    return -f->mu0 * (1.0 - f->A) * f->B * decay(f, w);
}
