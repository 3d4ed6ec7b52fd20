/* rr_linear.c - Kalker's linear theory, and its descriptor. */
#include <math.h>
#include "util/rr_common.h"
#include "contact/rr_linear.h"

int rr_linear(const rr_contact_case *c, rr_forces *out)
{
    rr_kalker_coeffs k;
    double ab, c3;
    int st = out ? rr_contact_check(c) : RR_ERR_NULL;

    if (st == RR_OK)
        st = rr_creep_kalker(c, &k);
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

static int linear_forces(const rr_contact_case *c, const rr_friction *fr,
                         const rr_creep_opts *o, double *work, rr_forces *out)
{
    /* the friction law goes unused, but a NaN or invalid one is still refused */
    int st = out ? rr_friction_check(fr) : RR_ERR_NULL;
    (void)o;
    (void)work;
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    return rr_linear(c, out);
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
