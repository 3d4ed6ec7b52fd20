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
    k->work_len = k->d->workspace_len(o);
    k->cost = k->d->cost(o);
    k->ready = RR_CREEP_READY;
    return RR_OK;
}

int rr_creep_forces_checked(const rr_creep_checked *k, const rr_contact_case *c,
                            const rr_friction *fr, double *work, size_t work_len,
                            const rr_interrupt *stop, rr_forces *out)
{
    int st = RR_OK;

    if (!out || !k || k->ready != RR_CREEP_READY || !k->d || k->d != rr_method_get(k->o.method))
        st = RR_ERR_NULL;
    else if (k->work_len > 0 && (!work || work_len < k->work_len))
        st = RR_ERR_WORKSPACE;
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    if (k->d->forces_interruptible)
        return k->d->forces_interruptible(c, fr, &k->o, work, stop, out);
    return k->d->forces(c, fr, &k->o, work, out);
}

int rr_creep_forces_interruptible(const rr_contact_case *c, const rr_friction *fr,
                                  const rr_creep_opts *o, double *work, size_t work_len,
                                  const rr_interrupt *stop, rr_forces *out)
{
    rr_creep_checked k;
    const int st = out ? rr_creep_check(&k, o, NULL) : RR_ERR_NULL;

    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    return rr_creep_forces_checked(&k, c, fr, work, work_len, stop, out);
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
