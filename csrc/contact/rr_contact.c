/* rr_contact.c - validation shared by the creep-force methods. */
#include <math.h>
#include "util/rr_common.h"
#include "contact/rr_contact.h"

int rr_contact_check(const rr_contact_case *c)
{
    if (!c)
        return RR_ERR_NULL;
    if (!isfinite(c->a) || !isfinite(c->b) || !isfinite(c->N) || !isfinite(c->G)
        || !isfinite(c->nu) || !isfinite(c->cx) || !isfinite(c->cy)
        || !isfinite(c->cphi) || !isfinite(c->speed))
        return RR_ERR_NONFINITE;
    if (c->a <= 0.0 || c->b <= 0.0)
        return RR_ERR_GEOMETRY;
    if (c->N <= 0.0)
        return RR_ERR_LOAD;
    if (c->G <= 0.0 || c->nu < 0.0 || c->nu > 0.5)
        return RR_ERR_MATERIAL;
    if (c->speed < 0.0)
        return RR_ERR_SPEED;
    /* subnormal sizes, loads or moduli carry too few digits for a force */
    if (!isnormal(c->a) || !isnormal(c->b) || !isnormal(c->N) || !isnormal(c->G))
        return RR_ERR_RANGE;
    return RR_OK;
}

void rr_forces_nan(rr_forces *f)
{
    if (f)
        f->fx = f->fy = f->mz = NAN;
}

int rr_forces_checked(int st, rr_forces *f)
{
    if (st < 0 || (isfinite(f->fx) && isfinite(f->fy) && isfinite(f->mz)))
        return st;
    rr_forces_nan(f);
    return RR_ERR_RANGE;
}
