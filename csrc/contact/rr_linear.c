/* rr_linear.c - Kalker's linear theory, and its descriptor. */
#include <math.h>
#include "util/rr_common.h"
#include "contact/rr_linear.h"

/* rr_linear of a checked ellipse problem */
static int linear_checked(const rr_contact_problem *c, rr_forces *out)
{
    rr_kalker_coeffs k;
    double ab, c3;
    const int st = rr_creep_kalker(c, &k);

    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    ab = c->a * c->b;
    c3 = ab * sqrt(ab);
    out->fx = -c->G * ab * k.c11 * c->cx;
    out->fy = -c->G * (ab * k.c22 * c->cy + c3 * k.c23 * c->cphi);
    out->mz = c->G * (c3 * k.c23 * c->cy - ab * ab * k.c33 * c->cphi);
    return rr_forces_checked(st, out);    /* no saturation: large inputs overflow */
}

int rr_linear(const rr_contact_problem *p, rr_forces *out)
{
    int st = !out ? RR_ERR_NULL : rr_creep_ellipse_check(p);

    /* the friction law goes unused, but a NaN or invalid one is still
     * refused, and before the rest of the problem (as always) */
    if (st < 0 && out && p && p->patch == RR_PATCH_ELLIPSE
        && rr_friction_check(&p->friction) < 0)
        st = rr_friction_check(&p->friction);
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    return linear_checked(p, out);
}

static int linear_forces(const rr_contact_problem *p, const rr_creep_opts *o, double *work,
                         rr_forces *out)
{
    (void)o;
    (void)work;
    return rr_linear(p, out);
}

const rr_method_desc rr_method_linear = {
    .name = "linear",
    .doc = "Kalker's linear theory (no saturation: the forces grow without bound)",
    .saturates = 0,
    .cost = rr_method_unit_cost,
    .slope_scale = rr_method_unit_slope,
    .workspace_len = rr_method_no_workspace,
    .forces = linear_forces,
};
