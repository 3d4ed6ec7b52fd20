/* rr_creep_opts.c - option checks driven by a method's descriptor, and
 * what every creep-force method starts with. */
#include <float.h>
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "contact/rr_creep_opts.h"

double rr_method_unit_cost(const rr_creep_opts *o)
{
    (void)o;
    return 1.0;
}

double rr_method_unit_slope(const rr_creep_opts *o)
{
    (void)o;
    return 1.0;
}

size_t rr_method_no_workspace(const rr_creep_opts *o, const rr_grid *grid)
{
    (void)o;
    (void)grid;
    return 0;
}

int rr_method_option(const rr_method_desc *d, const char *name)
{
    int i;
    if (!d || !name)
        return -1;
    for (i = 0; i < d->nopts; i++)
        if (strcmp(d->opts[i].name, name) == 0)
            return i;
    return -1;
}

int rr_method_option_check(const rr_creep_option *op, double x)
{
    if (!op)
        return RR_ERR_NULL;
    if (!isfinite(x))
        return op->type == RR_OPT_REAL ? RR_ERR_NONFINITE : op->status;
    if ((op->lo_open ? !(x > op->lo) : !(x >= op->lo))
        || (op->hi_open ? !(x < op->hi) : !(x <= op->hi)))
        return op->status;
    /* an integer or a choice's index: a C int (the cast, not floor(): this
     * check runs at every creep-force call, the rig's time step included) */
    if (op->type != RR_OPT_REAL && !(fabs(x) < 2147483647.0 && x == (double)(int)x))
        return op->status;
    return RR_OK;
}

int rr_method_check(const rr_method_desc *d, const rr_creep_opts *o, int *bad)
{
    int i, st;
    if (bad)
        *bad = -1;
    if (!d || !o)
        return RR_ERR_NULL;
    for (i = 0; i < d->nopts; i++)
        if ((st = rr_method_option_check(&d->opts[i], o->v[i])) != RR_OK) {
            if (bad)
                *bad = i;
            return st;
        }
    if (d->check) {
        int b = -1;
        if ((st = d->check(o, &b)) != RR_OK) {
            if (bad)
                *bad = b;
            return st;
        }
    }
    return RR_OK;
}

int rr_creep_kalker(const rr_contact_problem *p, rr_kalker_coeffs *k)
{
    const double q = p->a / p->b;
    if (!isnormal(q)) {
        k->c11 = k->c22 = k->c23 = k->c33 = NAN;
        return RR_ERR_RANGE;
    }
    return rr_kalker(q, p->nu, k);
}

int rr_creep_ellipse_check(const rr_contact_problem *p)
{
    return p && p->patch != RR_PATCH_ELLIPSE ? RR_ERR_PATCH : rr_contact_problem_check(p, NULL);
}

/* rr_creep_prepare's checks of the problem, p not NULL */
static int prepare_checks(const rr_contact_problem *p)
{
    int st;

    if (p->patch != RR_PATCH_ELLIPSE)
        return RR_ERR_PATCH;
    if ((st = rr_contact_problem_check(p, NULL)) < 0)
        return st;
    if (rr_friction_is_falling(&p->friction) && !(p->speed > 0.0))
        return RR_ERR_SPEED;
    /* the friction limit itself must have a double's digits: a subnormal
     * mu0 N rounds the saturated force above it */
    if (!isnormal(p->friction.mu0 * p->N))
        return RR_ERR_RANGE;
    return RR_OK;
}

int rr_creep_prepare(const rr_contact_problem *p, rr_kalker_coeffs *k)
{
    int st;

    if (!k || !p)
        return RR_ERR_NULL;
    if ((st = prepare_checks(p)) < 0)
        return st;
    return rr_creep_kalker(p, k);
}

int rr_creep_prepare_given(const rr_contact_problem *p, const rr_kalker_coeffs *given,
                           rr_kalker_coeffs *k)
{
    int st;

    if (!k || !p || !given)
        return RR_ERR_NULL;
    if ((st = prepare_checks(p)) < 0)
        return st;
    if (!(given->c11 > 0.0 && given->c22 > 0.0 && given->c23 > 0.0 && given->c33 > 0.0
          && given->c11 <= DBL_MAX && given->c22 <= DBL_MAX && given->c23 <= DBL_MAX
          && given->c33 <= DBL_MAX))
        return RR_ERR_PARAM;
    *k = *given;
    return RR_OK;
}
