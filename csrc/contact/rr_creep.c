/* rr_creep.c - the registry of creep-force methods (rr_methods.def), the
 * options filled and checked from their descriptors, and the dispatcher. */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "contact/rr_creep.h"

#define RR_METHOD(tag, desc) extern const rr_method_desc desc;
#include "contact/rr_methods.def"
#undef RR_METHOD

static const rr_method_desc *const methods[RR_METHOD_COUNT] = {
#define RR_METHOD(tag, desc) &desc,
#include "contact/rr_methods.def"
#undef RR_METHOD
};

int rr_method_count(void)
{
    return RR_METHOD_COUNT;
}

const rr_method_desc *rr_method_get(int i)
{
    return i >= 0 && i < RR_METHOD_COUNT ? methods[i] : NULL;
}

int rr_method_find(const char *name)
{
    int i;
    if (!name)
        return RR_ERR_NULL;
    for (i = 0; i < RR_METHOD_COUNT; i++)
        if (strcmp(methods[i]->name, name) == 0)
            return i;
    return RR_ERR_METHOD;
}

int rr_creep_opts_default(rr_creep_opts *o, int method)
{
    const rr_method_desc *d = rr_method_get(method);
    int i;
    if (!o)
        return RR_ERR_NULL;
    o->method = method;
    for (i = 0; i < RR_CREEP_MAX_OPTS; i++)
        o->v[i] = d && i < d->nopts ? d->opts[i].def : NAN;
    return d ? RR_OK : RR_ERR_METHOD;
}

int rr_creep_opts_set(rr_creep_opts *o, const char *name, double value)
{
    const rr_method_desc *d;
    int i, st;
    if (!o || !name)
        return RR_ERR_NULL;
    if (!(d = rr_method_get(o->method)))
        return RR_ERR_METHOD;
    if ((i = rr_method_option(d, name)) < 0)
        return RR_ERR_PARAM;
    if ((st = rr_method_option_check(&d->opts[i], value)) != RR_OK)
        return st;
    o->v[i] = value;
    return RR_OK;
}

int rr_creep_opts_check_at(const rr_creep_opts *o, int *bad)
{
    const rr_method_desc *d;
    if (bad)
        *bad = -1;
    if (!o)
        return RR_ERR_NULL;
    if (!(d = rr_method_get(o->method)) || d->nopts > RR_CREEP_MAX_OPTS)
        return RR_ERR_METHOD;
    return rr_method_check(d, o, bad);
}

int rr_creep_opts_check(const rr_creep_opts *o)
{
    return rr_creep_opts_check_at(o, NULL);
}

/* The descriptor of valid options, else NULL. */
static const rr_method_desc *checked(const rr_creep_opts *o)
{
    return rr_creep_opts_check(o) == RR_OK ? methods[o->method] : NULL;
}

double rr_creep_cost(const rr_creep_opts *o)
{
    const rr_method_desc *d = checked(o);
    return d ? d->cost(o) : 0.0;
}

int rr_creep_saturates(const rr_creep_opts *o)
{
    const rr_method_desc *d = checked(o);
    return d ? d->saturates : 0;
}

double rr_creep_slope_scale(const rr_creep_opts *o)
{
    const rr_method_desc *d = checked(o);
    return d ? d->slope_scale(o) : NAN;
}

int rr_creep_takes_grid(const rr_creep_opts *o)
{
    const rr_method_desc *d = checked(o);
    return d ? d->takes_grid : 0;
}

int rr_creep_iterative(const rr_creep_opts *o)
{
    const rr_method_desc *d = checked(o);
    return d ? d->iterative : 0;
}

size_t rr_creep_workspace_len(const rr_creep_opts *o, const rr_grid *grid)
{
    const rr_method_desc *d = checked(o);
    return d && (!grid || d->takes_grid) ? d->workspace_len(o, grid) : 0;
}

int rr_creep_check(rr_creep_checked *k, const rr_creep_opts *o, int *bad)
{
    int st;
    if (bad)
        *bad = -1;
    if (!k)
        return RR_ERR_NULL;
    k->ready = 0;
    k->d = NULL;
    if ((st = rr_creep_opts_check_at(o, bad)) != RR_OK)
        return st;
    k->o = *o;
    k->d = methods[o->method];
    k->work_len = k->d->workspace_len(o, NULL);
    k->cost = k->d->cost(o);
    k->ready = RR_CREEP_READY;
    return RR_OK;
}

/* 1 if the method of descriptor d takes problem p's patch (p not NULL) */
static int takes(const rr_method_desc *d, const rr_contact_problem *p)
{
    return p->patch != RR_PATCH_GRID || d->takes_grid;
}

/* the method's entry for the checked record k, problem p */
static int method_forces(const rr_creep_checked *k, const rr_contact_problem *p, double *work,
                         const rr_interrupt *stop, rr_forces *out)
{
    if (k->d->forces_interruptible)
        return k->d->forces_interruptible(p, &k->o, work, stop, out);
    return k->d->forces(p, &k->o, work, out);
}

/* not inlined (where the compiler has the attribute): the path that calls
 * it then needs no stack frame of its own, the time step's ellipses none */
#if defined(__GNUC__)
#define NOINLINE __attribute__((noinline))
#else
#define NOINLINE
#endif

/* rr_creep_forces_checked of a problem that is not an ellipse (k ready):
 * a patch the method takes, with the workspace its descriptor asks for the
 * grid (apart, so that the ellipse's path calls nothing but the method) */
static NOINLINE int forces_other(const rr_creep_checked *k, const rr_contact_problem *p,
                                 double *work, size_t work_len, const rr_interrupt *stop,
                                 rr_forces *out)
{
    int st = RR_OK;
    size_t need;
    if (!takes(k->d, p))
        st = RR_ERR_PATCH;
    else if ((need = k->d->workspace_len(&k->o, &p->grid)) > 0 && (!work || work_len < need))
        st = RR_ERR_WORKSPACE;
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    return method_forces(k, p, work, stop, out);
}

int rr_creep_forces_checked(const rr_creep_checked *k, const rr_contact_problem *p,
                            double *work, size_t work_len, const rr_interrupt *stop,
                            rr_forces *out)
{
    int st = RR_OK;

    if (!out || !p || !k || k->ready != RR_CREEP_READY || !k->d
        || k->d != rr_method_get(k->o.method))
        st = RR_ERR_NULL;
    else if (p->patch != RR_PATCH_ELLIPSE)
        return forces_other(k, p, work, work_len, stop, out);
    else if (k->work_len > 0 && (!work || work_len < k->work_len))
        st = RR_ERR_WORKSPACE;
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    return method_forces(k, p, work, stop, out);
}

int rr_creep_forces_interruptible(const rr_contact_problem *p, const rr_creep_opts *o,
                                  double *work, size_t work_len, const rr_interrupt *stop,
                                  rr_forces *out)
{
    rr_creep_checked k;
    const int st = out ? rr_creep_check(&k, o, NULL) : RR_ERR_NULL;

    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    return rr_creep_forces_checked(&k, p, work, work_len, stop, out);
}

int rr_creep_forces_work(const rr_contact_problem *p, const rr_creep_opts *o, double *work,
                         size_t work_len, rr_forces *out)
{
    return rr_creep_forces_interruptible(p, o, work, work_len, NULL, out);
}

int rr_creep_forces(const rr_contact_problem *p, const rr_creep_opts *o, rr_forces *out)
{
    return rr_creep_forces_work(p, o, NULL, 0, out);
}

int rr_creep_field(const rr_contact_problem *p, const rr_creep_opts *o, rr_forces *out,
                   rr_traction_field *field)
{
    int st = out ? rr_creep_opts_check(o) : RR_ERR_NULL;
    const rr_method_desc *d = st == RR_OK ? methods[o->method] : NULL;

    if (d && !d->field)
        st = RR_ERR_METHOD;
    else if (d && p && !takes(d, p))
        st = RR_ERR_PATCH;
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    return d->field(p, o, out, field);
}

int rr_creep_blame(const rr_creep_checked *k, const rr_contact_problem *p, int st)
{
    int field = RR_PF_NONE;

    if (st >= 0 || !p || !k || k->ready != RR_CREEP_READY || !k->d)
        return RR_PF_NONE;
    if (!takes(k->d, p))
        return st == RR_ERR_PATCH ? RR_PF_PATCH : RR_PF_NONE;
    if (rr_contact_problem_check(p, &field) == st)
        return field;
    if (field != RR_PF_NONE)
        return RR_PF_NONE;        /* an invalid problem, but not what the method said */
    /* a valid problem the method refused on its own terms */
    if (st == RR_ERR_SPEED)
        return RR_PF_SPEED;       /* falling friction at rest */
    if (st == RR_ERR_FRICTION)
        return RR_PF_FRICTION_A;  /* a falling law, Coulomb friction only */
    return k->d->blame ? k->d->blame(p, &k->o, st) : RR_PF_NONE;
}
