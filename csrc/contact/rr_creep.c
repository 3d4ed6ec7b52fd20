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

size_t rr_creep_workspace_len(const rr_creep_opts *o)
{
    const rr_method_desc *d = checked(o);
    return d ? d->workspace_len(o) : 0;
}

int rr_creep_forces_interruptible(const rr_contact_case *c, const rr_friction *fr,
                                  const rr_creep_opts *o, double *work, size_t work_len,
                                  const rr_interrupt *stop, rr_forces *out)
{
    int st = out ? rr_creep_opts_check(o) : RR_ERR_NULL;
    const rr_method_desc *d = st == RR_OK ? methods[o->method] : NULL;

    if (d) {
        const size_t need = d->workspace_len(o);
        if (need > 0 && (!work || work_len < need))
            st = RR_ERR_WORKSPACE;
    }
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    if (d->forces_interruptible)
        return d->forces_interruptible(c, fr, o, work, stop, out);
    return d->forces(c, fr, o, work, out);
}

int rr_creep_forces_work(const rr_contact_case *c, const rr_friction *fr,
                         const rr_creep_opts *o, double *work, size_t work_len,
                         rr_forces *out)
{
    return rr_creep_forces_interruptible(c, fr, o, work, work_len, NULL, out);
}

int rr_creep_forces(const rr_contact_case *c, const rr_friction *fr,
                    const rr_creep_opts *o, rr_forces *out)
{
    return rr_creep_forces_work(c, fr, o, NULL, 0, out);
}

int rr_creep_field(const rr_contact_case *c, const rr_friction *fr, const rr_creep_opts *o,
                   rr_forces *out, rr_traction_field *field)
{
    int st = out ? rr_creep_opts_check(o) : RR_ERR_NULL;
    const rr_method_desc *d = st == RR_OK ? methods[o->method] : NULL;

    if (d && !d->field)
        st = RR_ERR_METHOD;
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    return d->field(c, fr, o, out, field);
}
