/* rr_contact.c - the contact problem's check and its report. */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include "util/rr_common.h"
#include "contact/rr_contact.h"

static const char *const field_names[] = {
#define RR_PF_NAME(tag, name) [RR_PF_##tag] = name,
    RR_PROBLEM_FIELDS(RR_PF_NAME)
#undef RR_PF_NAME
};
RR_STATIC_ASSERT(RR_COUNTOF(field_names) == RR_PF_COUNT, one_name_per_field);

const char *rr_problem_field_name(int field)
{
    return field >= 0 && field < RR_PF_COUNT ? field_names[field] : NULL;
}

/* status st blaming member f (field may be NULL) */
static int blame(int st, int f, int *field)
{
    if (field)
        *field = f;
    return st;
}

/* The first member of v[] (their members m[]) that is not finite, or -1. */
static int first_nonfinite(const double *v, const int *m, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return m[i];
    return -1;
}

/* rr_friction_check with the member at fault */
static int friction_check(const rr_friction *f, int *field)
{
    if (!isfinite(f->mu0) || !isfinite(f->A) || !isfinite(f->B))
        return blame(RR_ERR_NONFINITE, !isfinite(f->mu0) ? RR_PF_MU0
                                       : !isfinite(f->A) ? RR_PF_FRICTION_A : RR_PF_FRICTION_B,
                     field);
    if (f->mu0 <= 0.0)
        return blame(RR_ERR_FRICTION, RR_PF_MU0, field);
    if (f->A <= 0.0 || f->A > 1.0)
        return blame(RR_ERR_FRICTION, RR_PF_FRICTION_A, field);
    if (f->B < 0.0)
        return blame(RR_ERR_FRICTION, RR_PF_FRICTION_B, field);
    /* as rr_friction_check: beyond these a force or the law's slope overflows */
    if (f->mu0 > RR_FRICTION_MAX)
        return blame(RR_ERR_RANGE, RR_PF_MU0, field);
    if (f->B > RR_FRICTION_MAX)
        return blame(RR_ERR_RANGE, RR_PF_FRICTION_B, field);
    return blame(RR_OK, RR_PF_NONE, field);
}

/* What both patches share, after their sizes sz[0..1] (a, b or dx, dy;
 * their members m0, m1), all finite: the load, material, speed, the sizes'
 * and the load's digits, then the friction law. */
static int shared_check(const rr_contact_problem *p, const double sz[2], int m0, int m1,
                        int *field)
{
    if (!(sz[0] > 0.0))
        return blame(RR_ERR_GEOMETRY, m0, field);
    if (!(sz[1] > 0.0))
        return blame(RR_ERR_GEOMETRY, m1, field);
    if (p->N <= 0.0)
        return blame(RR_ERR_LOAD, RR_PF_N, field);
    if (p->G <= 0.0)
        return blame(RR_ERR_MATERIAL, RR_PF_G, field);
    if (p->nu < 0.0 || p->nu > 0.5)
        return blame(RR_ERR_MATERIAL, RR_PF_NU, field);
    if (p->speed < 0.0)
        return blame(RR_ERR_SPEED, RR_PF_SPEED, field);
    /* subnormal sizes, loads or moduli carry too few digits for a force */
    if (!isnormal(sz[0]))
        return blame(RR_ERR_RANGE, m0, field);
    if (!isnormal(sz[1]))
        return blame(RR_ERR_RANGE, m1, field);
    if (!isnormal(p->N))
        return blame(RR_ERR_RANGE, RR_PF_N, field);
    if (!isnormal(p->G))
        return blame(RR_ERR_RANGE, RR_PF_G, field);
    return friction_check(&p->friction, field);
}

static int grid_check(const rr_contact_problem *p, int *field)
{
    const rr_grid *g = &p->grid;
    const double v[11] = {g->dx, g->dy, g->x0, g->y0, p->N, p->G, p->nu, p->cx, p->cy,
                          p->cphi, p->speed};
    static const int m[11] = {RR_PF_DX, RR_PF_DY, RR_PF_X0, RR_PF_Y0, RR_PF_N, RR_PF_G,
                              RR_PF_NU, RR_PF_CX, RR_PF_CY, RR_PF_CPHI, RR_PF_SPEED};
    int bad;
    if (g->mx < 1 || g->mx > RR_CONTACT_MAX_GRID)
        return blame(RR_ERR_GRID, RR_PF_MX, field);
    if (g->my < 1 || g->my > RR_CONTACT_MAX_GRID)
        return blame(RR_ERR_GRID, RR_PF_MY, field);
    if ((bad = first_nonfinite(v, m, 11)) >= 0)
        return blame(RR_ERR_NONFINITE, bad, field);
    if (!p->h)
        return blame(RR_ERR_NULL, RR_PF_H, field);
    if (!rr_all_finite(p->h, g->mx * g->my))
        return blame(RR_ERR_NONFINITE, RR_PF_H, field);
    return shared_check(p, v, RR_PF_DX, RR_PF_DY, field);
}

/* 1 where an ellipse problem passes every check below (the time step's
 * path: one test while all is well, without branches; the report only on
 * failure).  A comparison with NaN is false, so each range refuses it; a
 * value in [DBL_MIN, DBL_MAX] is a positive normal double; 0 x is NaN
 * exactly for x NaN or infinite. */
static int ellipse_ok(const rr_contact_problem *p)
{
    const rr_friction *f = &p->friction;
    return (p->a >= DBL_MIN) & (p->a <= DBL_MAX) & (p->b >= DBL_MIN) & (p->b <= DBL_MAX)
           & (p->N >= DBL_MIN) & (p->N <= DBL_MAX) & (p->G >= DBL_MIN) & (p->G <= DBL_MAX)
           & (p->nu >= 0.0) & (p->nu <= 0.5) & (p->speed >= 0.0) & (p->speed <= DBL_MAX)
           & (0.0 * p->cx + 0.0 * p->cy + 0.0 * p->cphi == 0.0)
           & (f->mu0 > 0.0) & (f->mu0 <= RR_FRICTION_MAX) & (f->A > 0.0) & (f->A <= 1.0)
           & (f->B >= 0.0) & (f->B <= RR_FRICTION_MAX);
}

int rr_contact_problem_check(const rr_contact_problem *p, int *field)
{
    if (!p)
        return blame(RR_ERR_NULL, RR_PF_NONE, field);
    if (p->patch == RR_PATCH_ELLIPSE && ellipse_ok(p))
        return blame(RR_OK, RR_PF_NONE, field);
    if (p->patch == RR_PATCH_GRID)
        return grid_check(p, field);
    if (p->patch != RR_PATCH_ELLIPSE)
        return blame(RR_ERR_PATCH, RR_PF_PATCH, field);
    /* the ellipse: what the former rr_contact_check, then rr_friction_check
     * did, in their order */
    if (!isfinite(p->a) || !isfinite(p->b) || !isfinite(p->N) || !isfinite(p->G)
        || !isfinite(p->nu) || !isfinite(p->cx) || !isfinite(p->cy) || !isfinite(p->cphi)
        || !isfinite(p->speed)) {
        const double v[9] = {p->a, p->b, p->N, p->G, p->nu, p->cx, p->cy, p->cphi, p->speed};
        static const int m[9] = {RR_PF_A, RR_PF_B, RR_PF_N, RR_PF_G, RR_PF_NU, RR_PF_CX,
                                 RR_PF_CY, RR_PF_CPHI, RR_PF_SPEED};
        return blame(RR_ERR_NONFINITE, first_nonfinite(v, m, 9), field);
    }
    {
        const double sz[2] = {p->a, p->b};
        return shared_check(p, sz, RR_PF_A, RR_PF_B, field);
    }
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
