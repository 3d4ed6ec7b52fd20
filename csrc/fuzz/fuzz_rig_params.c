/*
 * fuzz_rig_params.c - the rig's declared parameters (rr_rig_params.h): the
 * table (rr_rig_param_at, _find, _choice), the config's setters
 * (rr_rig_config_set, _set_choice, _set_list, _put, _put_list),
 * rr_rig_config_check and rr_rig_config_report, and
 * what is derived from a config (rr_rig_params_from, rr_rig_params_default,
 * rr_rig_geometry_from, rr_rig_samples, rr_rig_schedule), rr_wheel_store.
 *
 * Input: up to 24 setter calls on the default config, each on a row (or a
 * name that is none, a creep row, NULL) with a value in the row's range,
 * near its default, an edge, or for a list 0 .. 8 entries (or an edge
 * count); one input in 8 instead writes raw values into the members; then
 * a few schedule samples k, and a wheel block's stride.
 *
 * Oracles: documented statuses, each setter's predicted from the row's type
 * and range (an independent reading of the header); a setter that fails
 * changes no byte of the config, one that succeeds only its member (to the
 * value); rr_rig_config_check's status as predicted from the rows and the
 * scenario's conditions and the drives' loops stable at the sample time
 * (scenario.control_sample_time_s at fault), *bad the row at fault (NULL on
 * success), so that after successful setters only the scenario can fail
 * it; rr_rig_config_speed_loops the loops of rr_rig_params_from's
 * parameters; on a config that
 * passes, rr_rig_params_from OK with every derived double finite, the
 * default config's equal to rr_rig_params_default bit for bit,
 * rr_rig_geometry_from as documented, rr_rig_samples round(duration / T)
 * >= 1, rr_rig_schedule's references finite (xi_ref the target of the last
 * start time <= k T, NaN before the first); rr_wheel_store writing exactly
 * RR_WHEEL_NVALUES values at the stride, the fields' values, nothing else;
 * then (issue 23) up to 12 values stored unchecked (rr_rig_config_put,
 * _put_list: statuses, the member's value, the problem of a value the
 * member cannot hold, nothing changed on error), and rr_rig_config_report
 * on the result: every problem (key, other key, status, rule, entry, value,
 * bounds) as an independent reading of the header predicts it, in its
 * order, the first cap written and nothing beyond, the count alone the
 * same, rr_rig_config_check its first.
 */
#include "fuzz.h"

#define MAX_CALLS 24

static int nchoices(const rr_rig_param *r)
{
    int n = 0;
    while (r->choices && r->choices[n])
        n++;
    return n;
}

static int in_range(const rr_rig_param *r, double v)
{
    if (!isfinite(v))
        return RR_ERR_NONFINITE;
    if ((r->lo_open ? !(v > r->lo) : !(v >= r->lo)) || (r->hi_open ? !(v < r->hi) : !(v <= r->hi)))
        return RR_ERR_PARAM;
    return RR_OK;
}

/* the status rr_rig_config_set must give for v on row r */
static int predict_set(const rr_rig_param *r, double v)
{
    int st;
    if (!r || r->creep)
        return RR_ERR_PARAM;
    switch (r->type) {
    case RR_RIG_REAL:
        return in_range(r, v);
    case RR_RIG_INT:
        if ((st = in_range(r, v)) != RR_OK)
            return st;
        return v == floor(v) ? RR_OK : RR_ERR_PARAM;
    case RR_RIG_FLAG:
        return !isfinite(v) ? RR_ERR_NONFINITE : (v == 0.0 || v == 1.0) ? RR_OK : RR_ERR_PARAM;
    case RR_RIG_CHOICE:
        return !isfinite(v) ? RR_ERR_NONFINITE
               : (v >= 0.0 && v < nchoices(r) && v == floor(v)) ? RR_OK : RR_ERR_PARAM;
    default:
        return RR_ERR_PARAM;
    }
}

/* the status rr_rig_config_check must give, and the row at fault */
static int predict_check(const rr_rig_config *c, const char **bad)
{
    int i, k;
    *bad = NULL;
    for (i = 0; i < rr_rig_param_count(); i++) {
        const rr_rig_param *r = rr_rig_param_at(i);
        const char *at = (const char *)c + r->offset;
        int st = RR_OK;
        if (r->creep)
            continue;
        if (r->type == RR_RIG_LIST) {
            const rr_rig_list *l = (const rr_rig_list *)(const void *)at;
            /* a list whose default is empty may be empty */
            st = l->n >= (r->nlist > 0) && l->n <= RR_RIG_MAX_LIST ? RR_OK : RR_ERR_PARAM;
            for (k = 0; st == RR_OK && k < l->n; k++)
                st = in_range(r, l->v[k]);
        } else {
            st = predict_set(r, r->type == RR_RIG_REAL ? *(const double *)(const void *)at
                                                       : (double)*(const int *)(const void *)at);
        }
        if (st != RR_OK) {
            *bad = r->name;
            return st;
        }
    }
    if (c->target_start.n != c->targets.n) {
        *bad = "scenario.target_start_s";
        return RR_ERR_PARAM;
    }
    for (k = 1; k < c->target_start.n; k++)
        if (!(c->target_start.v[k] > c->target_start.v[k - 1])) {
            *bad = "scenario.target_start_s";
            return RR_ERR_PARAM;
        }
    if (!(c->target_start.v[c->target_start.n - 1] < c->duration)) {
        *bad = "scenario.target_start_s";
        return RR_ERR_PARAM;
    }
    if (!(c->duration >= c->T * (1.0 - 1e-9))) {
        *bad = "scenario.duration_s";
        return RR_ERR_PARAM;
    }
    /* the adhesion: one mu0 per time, A and B one each or none, times in
     * order, the patch on the roller */
    *bad = c->schedule_mu0.n != c->schedule_t.n ? "adhesion.schedule_mu0"
         : c->schedule_A.n && c->schedule_A.n != c->schedule_t.n ? "adhesion.schedule_polach_A"
         : c->schedule_B.n && c->schedule_B.n != c->schedule_t.n
           ? "adhesion.schedule_polach_B_s_per_m" : NULL;
    for (k = 1; !*bad && k < c->schedule_t.n; k++)
        if (c->schedule_t.v[k] < c->schedule_t.v[k - 1])
            *bad = "adhesion.schedule_times_s";
    /* the lateral force: one per time, the times in order */
    if (!*bad && c->lateral_f.n != c->lateral_t.n)
        *bad = "disturbance.lateral_force_N";
    for (k = 1; !*bad && k < c->lateral_t.n; k++)
        if (c->lateral_t.v[k] < c->lateral_t.v[k - 1])
            *bad = "disturbance.lateral_force_times_s";
    if (!*bad && c->patch_length > 2.0 * RR_PI * c->roller_radius)
        *bad = "adhesion.patch_length_m";
    if (!*bad) {
        /* each drive's loop stable at T: the roller's PI on the rollers, the
         * wheelset's on the wheelset with its drive, inside eq. 13's loop */
        rr_speed_loop roller, wheelset;
        roller.pi.T = wheelset.pi.T = c->T;
        roller.pi.Kp = c->roller_kp;
        roller.pi.KI = c->roller_ki;
        roller.pi.Tmax = c->roller_tmax;
        roller.J = c->roller_inertia;
        roller.tau = c->roller_tau;
        roller.alpha = 0.0;
        wheelset.pi.Kp = c->wheelset_kp;
        wheelset.pi.KI = c->wheelset_ki;
        wheelset.pi.Tmax = c->wheelset_tmax;
        wheelset.J = c->spin_inertia + c->drive_inertia;
        wheelset.tau = c->wheelset_tau;
        wheelset.alpha = c->ctl_alpha;
        if (rr_speed_loop_check(&roller) == RR_ERR_PARAM
            || rr_speed_loop_check(&wheelset) == RR_ERR_PARAM)
            *bad = "scenario.control_sample_time_s";
    }
    if (*bad)
        return RR_ERR_PARAM;
    /* the wheelset's inertia with its drive's, a finite double */
    if (!isfinite(c->spin_inertia + c->drive_inertia)) {
        *bad = "wheelset.spin_inertia_kg_m2";
        return RR_ERR_RANGE;
    }
    return RR_OK;
}

/* a value for row r: in its range, near its default, or an edge */
static double decode_value(fz_in *in, const rr_rig_param *r)
{
    const int how = fz_choice(in, 4);
    double lo = r ? r->lo : 0.0, hi = r ? r->hi : 1.0;
    if (!r || r->type == RR_RIG_CHOICE || r->type == RR_RIG_FLAG)
        return (double)fz_int(in, 0, r ? nchoices(r) : 1) + (fz_choice(in, 16) == 0 ? 0.5 : 0.0);
    if (!isfinite(lo))
        lo = -1e6;
    if (!isfinite(hi))
        hi = fmax(lo, 0.0) + 1e6 * (fabs(r->value) + 1.0);
    if (how == 0)
        return fz_near(in, r->value != 0.0 ? r->value : 1.0, 10.0);
    if (how == 1) {
        const double v = fz_lin(in, lo, hi);
        return r->type == RR_RIG_INT ? floor(v) : v;
    }
    if (how == 2)
        return fz_lin(in, lo, hi) * fz_log(in, 1e-3, 1e3);
    return fz_lin(in, -1e300, 1e300);
}

static const char *decode_name(fz_in *in, const rr_rig_param **row)
{
    const int n = rr_rig_param_count(), k = fz_int(in, 0, n - 1);
    *row = rr_rig_param_at(k);
    if (*row)
        return (*row)->name;
    switch (fz_choice(in, 3)) {
    case 0: return NULL;
    case 1: return "scenario";
    default: return "no.such_row";
    }
}

static void run_setters(fz_in *in, rr_rig_config *c)
{
    const int ncalls = fz_range(in, 0, MAX_CALLS);
    const double one = 1.0;
    int call, i;
    for (call = 0; call < ncalls; call++) {
        const rr_rig_param *r;
        const char *name = decode_name(in, &r);
        const int kind = fz_choice(in, 3);
        rr_rig_config before = *c;
        int st, want;
        const char *fn;

        if (kind == 0 || (kind == 2 && (!r || r->type != RR_RIG_LIST) && fz_choice(in, 2))) {
            const double v = decode_value(in, r);
            fn = "rr_rig_config_set";
            st = rr_rig_config_set(c, name, v);
            want = !name ? RR_ERR_NULL : predict_set(r, v);
            fz_note("; set %s = %.17g: %d", name ? name : "NULL", v, st);
            if (st == RR_OK) {
                const char *at = (const char *)c + r->offset;
                const double got = r->type == RR_RIG_REAL ? *(const double *)(const void *)at
                                                          : (double)*(const int *)(const void *)at;
                if (memcmp(&got, &v, sizeof v) != 0 && !(got == v))
                    fz_fail("%s: %s = %.17g, but the member holds %.17g", fn, name, v, got);
            }
        } else if (kind == 1) {
            const int nc = r ? nchoices(r) : 0, j = fz_int(in, 0, nc > 0 ? nc - 1 : 0);
            const char *choice = j >= 0 && j < nc ? r->choices[j]
                                 : fz_choice(in, 4) == 0 ? NULL : "no-such-choice";
            fn = "rr_rig_config_set_choice";
            st = rr_rig_config_set_choice(c, name, choice);
            want = !name || !choice ? RR_ERR_NULL
                   : (!r || r->creep || r->type != RR_RIG_CHOICE || !(j >= 0 && j < nc))
                         ? RR_ERR_PARAM : RR_OK;
            fz_note("; set_choice %s = %s: %d", name ? name : "NULL", choice ? choice : "NULL",
                    st);
            if (st == RR_OK && *(const int *)(const void *)((const char *)c + r->offset) != j)
                fz_fail("%s: %s = %s, but the member holds %d", fn, name, choice,
                        *(const int *)(const void *)((const char *)c + r->offset));
        } else {
            double v[RR_RIG_MAX_LIST + 1];
            int n = fz_int(in, 1, 8), ok = 1;
            const int nv = n >= 0 && n <= RR_RIG_MAX_LIST + 1 ? n : 0;
            const int vnull = fz_choice(in, 16) == 0;
            double t = 0.0;
            if (n > RR_RIG_MAX_LIST + 1)
                n = RR_RIG_MAX_LIST + 1;       /* INT_MAX: too long, the buffer holds 257 */
            for (i = 0; i < (n >= 0 ? n : 0) && i <= RR_RIG_MAX_LIST; i++) {
                /* mostly increasing, within [0, 1] for targets */
                t += fz_log(in, 1e-3, 2.0);
                v[i] = i < nv && fz_choice(in, 8) == 0 ? decode_value(in, r)
                       : r && r->hi <= 1.0 ? fz_lin(in, 0.0, 1.0) : t;
            }
            fn = "rr_rig_config_set_list";
            st = rr_rig_config_set_list(c, name, n, vnull ? NULL : v);
            if (!name)
                want = RR_ERR_NULL;
            else if (vnull && n > 0)
                want = RR_ERR_NULL;
            else if (!r || r->creep || r->type != RR_RIG_LIST || n < (r->nlist > 0)
                     || n > RR_RIG_MAX_LIST)
                want = RR_ERR_PARAM;
            else {
                want = RR_OK;
                for (i = 0; ok && i < n; i++)
                    if ((want = in_range(r, v[i])) != RR_OK)
                        ok = 0;
            }
            fz_note("; set_list %s n %d: %d", name ? name : "NULL", n, st);
            if (st == RR_OK) {
                const rr_rig_list *l = (const rr_rig_list *)(const void *)((const char *)c
                                                                           + r->offset);
                if (l->n != n || memcmp(l->v, v, (size_t)n * sizeof v[0]) != 0)
                    fz_fail("%s: %s not the %d values given", fn, name, n);
            }
        }
        fz_status(fn, st);
        if (st != want)
            fz_fail("%s: status %d, the header's %d", fn, st, want);
        if (st != RR_OK)
            fz_same(fn, &before, c, sizeof *c, "the config (on error)");
        else {
            /* only the row's member may change */
            const size_t off = (size_t)r->offset;
            const size_t len = r->type == RR_RIG_REAL ? sizeof(double)
                               : r->type == RR_RIG_LIST ? sizeof(rr_rig_list) : sizeof(int);
            if (memcmp(&before, c, off) != 0
                || memcmp((const char *)&before + off + len, (const char *)c + off + len,
                          sizeof *c - off - len) != 0)
                fz_fail("%s: %s changed another member", fn, name);
        }
        /* the NULL config */
        if (rr_rig_config_set(NULL, name, 1.0) != RR_ERR_NULL
            || rr_rig_config_set_list(NULL, name, 1, &one) != RR_ERR_NULL
            || rr_rig_config_set_choice(NULL, name, "conical") != RR_ERR_NULL)
            fz_fail("rr_rig_config_set*: NULL config not RR_ERR_NULL");
    }
}

/* raw values in a few members, as a C caller may leave them */
static void corrupt(fz_in *in, rr_rig_config *c)
{
    const int n = fz_range(in, 1, 4);
    int k;
    for (k = 0; k < n; k++) {
        const rr_rig_param *r = rr_rig_param_at(fz_range(in, 0, rr_rig_param_count() - 1));
        char *at;
        if (r->creep)
            continue;
        at = (char *)c + r->offset;
        if (r->type == RR_RIG_REAL) {
            const double v = fz_slog(in, 1e-6, 1e6);
            memcpy(at, &v, sizeof v);
        } else if (r->type == RR_RIG_LIST) {
            rr_rig_list *l = (rr_rig_list *)(void *)at;
            l->n = fz_int(in, 0, 6);
            if (l->n >= 1 && l->n <= RR_RIG_MAX_LIST)
                l->v[fz_range(in, 0, l->n - 1)] = fz_lin(in, -1.0, 2.0);
        } else {
            const int v = fz_int(in, -1, 3);
            memcpy(at, &v, sizeof v);
        }
    }
}

static void check_derived(fz_in *in, const rr_rig_config *c)
{
    rr_rig_params p, p2;
    rr_rig_geometry g;
    rr_rig_config d;
    const double *v;
    long ns;
    int st, k;

    st = rr_rig_params_from(c, NULL, &p);
    if (st == RR_ERR_RANGE) {
        /* values each in range whose derived values overflow: p zeroed */
        rr_rig_params z;
        memset(&z, 0, sizeof z);
        fz_same("rr_rig_params_from", &z, &p, sizeof p, "p (not zeroed on error)");
    } else if (st != RR_OK)
        fz_fail("rr_rig_params_from: status %d for a config that passes the check", st);
    v = &p.mass;
    if (st == RR_OK) {
        /* every double the header derives */
        const double vals[] = {p.mass, p.Iyy, p.Izz, p.axlebox_y, p.kx, p.ky, p.kz, p.cx, p.cy,
                               p.cz, p.preload, p.g, p.roller_inertia, p.contact.R0,
                               p.contact.estar, p.contact.G, p.contact.nu,
                               p.contact.friction.mu0, p.contact.friction.A,
                               p.contact.friction.B, p.contact.vmin, p.T, p.roller_tau,
                               p.wheelset_tau, p.creepctl.r_w, p.creepctl.r_r,
                               p.creepctl.alpha, p.creepctl.beta, p.creepctl.vmin};
        fz_finite_n("rr_rig_params_from", st, "derived value", vals,
                    (int)(sizeof vals / sizeof vals[0]));
    }
    (void)v;
    if (st == RR_OK) {
        /* the config's loops are those of its parameters, and stable */
        rr_speed_loop a[2], b[2];
        rr_rig_config_speed_loops(c, a);
        rr_rig_speed_loops(&p, b);
        fz_same("rr_rig_config_speed_loops", b, a, sizeof a, "the loops of rr_rig_params_from");
        for (k = 0; k < 2; k++)
            if (rr_speed_loop_check(&a[k]) != RR_OK)
                fz_fail("rr_rig_config_check: passed with loop %d unstable", k);
    }
    if (st == RR_OK && rr_creep_opts_check(&p.contact.creep) != RR_OK)
        fz_fail("rr_rig_params_from: the rows' creep options do not pass rr_creep_opts_check");
    rr_rig_config_default(&d);
    if (memcmp(&d, c, sizeof d) == 0) {
        if (rr_rig_params_default(&p2) != RR_OK || memcmp(&p, &p2, sizeof p) != 0)
            fz_fail("rr_rig_params_default differs from rr_rig_params_from(default config)");
    }
    if (rr_rig_geometry_from(c, &g) != RR_OK || g.wheel_radius != c->wheel_radius
        || g.roller_radius != c->roller_radius || g.profile_half_width != c->profile_half_width
        || g.cone_angle != atan(c->conicity) || g.crown_radius != c->crown_radius
        || g.contact_half_spacing != c->contact_half_spacing
        || g.table_half_range != c->table_half_range || g.table_rows != c->table_rows)
        fz_fail("rr_rig_geometry_from: not the config's geometry");
    ns = rr_rig_samples(c);
    if (!(ns >= 1 && (double)ns == fmax(1.0, floor(c->duration / c->T + 0.5))))
        fz_fail("rr_rig_samples: %ld for duration %.17g, T %.17g", ns, c->duration, c->T);
    for (k = 0; k < 4; k++) {
        const long s = k == 0 ? 0 : k == 3 ? ns - 1 : (long)fz_range(in, 0, (int)(ns < 2147483647L ? ns : 2147483647L));
        const double t = (double)s * c->T;
        double rref = 7.0, xref = 7.0, want = NAN;
        int i;
        st = rr_rig_schedule(c, s, &rref, &xref);
        fz_status("rr_rig_schedule", st);
        if (st == RR_ERR_RANGE) {
            if (isfinite(c->roller_speed / c->roller_radius) || !isnan(rref) || !isnan(xref))
                fz_fail("rr_rig_schedule: RR_ERR_RANGE for a finite reference, or not NaN");
            continue;
        }
        if (st != RR_OK)
            fz_fail("rr_rig_schedule: status %d at sample %ld", st, s);
        for (i = 0; i < c->target_start.n; i++)
            if (c->target_start.v[i] <= t)
                want = c->targets.v[i];
        if (memcmp(&xref, &want, sizeof want) != 0 && !(xref == want))
            fz_fail("rr_rig_schedule: xi_ref %.17g at t = %.17g, the schedule's %.17g", xref, t,
                    want);
        FZ_FINITE("rr_rig_schedule", st, rref);
    }
    if (rr_rig_schedule(c, -1, &(double){0.0}, &(double){0.0}) != RR_ERR_PARAM
        || rr_rig_schedule(NULL, 0, &(double){0.0}, &(double){0.0}) != RR_ERR_NULL
        || rr_rig_samples(NULL) != 0)
        fz_fail("rr_rig_schedule / rr_rig_samples: refusals not as documented");
}

static void check_table_api(fz_in *in)
{
    const int n = rr_rig_param_count(), i = fz_range(in, 0, n - 1);
    const rr_rig_param *r = rr_rig_param_at(i);
    int j;
    if (!r || rr_rig_param_find(r->name) != r || rr_rig_param_at(-1) || rr_rig_param_at(n)
        || rr_rig_param_find(NULL) || rr_rig_param_find("scenario"))
        fz_fail("rr_rig_param_at / _find: row %d not found by its name, or a non-row found", i);
    for (j = 0; j < nchoices(r); j++)
        if (rr_rig_param_choice(r, r->choices[j]) != j)
            fz_fail("rr_rig_param_choice: %s's %s not at %d", r->name, r->choices[j], j);
    if (rr_rig_param_choice(r, "no-such-choice") != -1 || rr_rig_param_choice(NULL, "x") != -1
        || rr_rig_param_choice(r, NULL) != -1
        || (r->type != RR_RIG_CHOICE && r->choices == NULL && rr_rig_param_choice(r, "") != -1))
        fz_fail("rr_rig_param_choice: an unknown choice not -1");
}

static void check_wheel_store(fz_in *in)
{
    const long stride = fz_range(in, 1, 4);
    const size_t nb = (size_t)((RR_WHEEL_NVALUES - 1) * stride + 1) * sizeof(double);
    double *v = fz_guarded(nb);
    rr_wheel_contact w;
    unsigned char *b = (unsigned char *)&w;
    size_t k;
    long idx = 0;
    int i, j;
    for (k = 0; k < sizeof w; k++)
        b[k] = (unsigned char)fz_u8(in) ^ (unsigned char)(k * 37u);
    rr_wheel_store(&w, v, stride);
    fz_guard_ok("rr_wheel_store", v, nb, "v[(RR_WHEEL_NVALUES - 1) stride + 1]");
    for (i = 0; i < RR_WHEEL_NFIELDS; i++) {
        const rr_rig_field *f = rr_wheel_field(i);
        const double *src = (const double *)(const void *)((const char *)&w + f->offset);
        for (j = 0; j < f->width; j++, idx++)
            if (memcmp(&v[idx * stride], &src[j], sizeof(double)) != 0)
                fz_fail("rr_wheel_store: value %ld is not field %s[%d]", idx, f->name, j);
    }
    if (idx != RR_WHEEL_NVALUES)
        fz_fail("rr_wheel_store: the fields have %ld values, not RR_WHEEL_NVALUES", idx);
    for (k = 0; k < (size_t)((RR_WHEEL_NVALUES - 1) * stride + 1); k++)
        if (k % (size_t)stride != 0 && !fz_untouched(&v[k], sizeof(double)))
            fz_fail("rr_wheel_store: wrote between the strided values (at %zu)", k);
    rr_wheel_store(NULL, v, stride);
    rr_wheel_store(&w, NULL, stride);
    fz_guard_free(v);
}

/* ------------------------------------------------------------------ the report */

#define MAX_PUTS 12

/* a problem as the header describes it */
static void problem(rr_rig_problem *p, const char *key, const char *other, int status, int rule,
                    int entry, double value, double lo, double hi)
{
    p->key = key;
    p->other = other;
    p->status = status;
    p->rule = rule;
    p->entry = entry;
    p->value = value;
    p->lo = lo;
    p->hi = hi;
}

static int same_double(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0 || a == b || (isnan(a) && isnan(b));
}

static int same_problem(const rr_rig_problem *a, const rr_rig_problem *b)
{
    return a->key && b->key && strcmp(a->key, b->key) == 0
           && ((!a->other && !b->other) || (a->other && b->other && strcmp(a->other, b->other) == 0))
           && a->status == b->status && a->rule == b->rule && a->entry == b->entry
           && same_double(a->value, b->value) && same_double(a->lo, b->lo)
           && same_double(a->hi, b->hi);
}

/* row r's own problem in c (the header's RANGE), or 0 */
static int predict_row(const rr_rig_config *c, const rr_rig_param *r, rr_rig_problem *p)
{
    const char *at = (const char *)c + r->offset;
    int k, st;
    if (r->type == RR_RIG_LIST) {
        const rr_rig_list *l = (const rr_rig_list *)(const void *)at;
        const int least = r->nlist > 0;
        if (l->n < least || l->n > RR_RIG_MAX_LIST) {
            problem(p, r->name, NULL, RR_ERR_PARAM, RR_RIG_RULE_RANGE, -1, l->n, least,
                    RR_RIG_MAX_LIST);
            return RR_ERR_PARAM;
        }
        for (k = 0; k < l->n; k++)
            if ((st = in_range(r, l->v[k])) != RR_OK) {
                problem(p, r->name, NULL, st, RR_RIG_RULE_RANGE, k, l->v[k], r->lo, r->hi);
                return st;
            }
        return RR_OK;
    }
    {
        const double v = r->type == RR_RIG_REAL ? *(const double *)(const void *)at
                                                : (double)*(const int *)(const void *)at;
        if ((st = predict_set(r, v)) != RR_OK) {
            const int choice = r->type == RR_RIG_CHOICE;
            problem(p, r->name, NULL, st, RR_RIG_RULE_RANGE, -1, v, choice ? 0.0 : r->lo,
                    choice ? nchoices(r) - 1.0 : r->hi);
        }
        return st;
    }
}

static int row_bad(const rr_rig_config *c, const char *name)
{
    rr_rig_problem p;
    return predict_row(c, rr_rig_param_find(name), &p) != RR_OK;
}

/* every problem rr_rig_config_report must give, in its order; their number
 * (a loop's pole and stable times only within the first cap: the scan of
 * sample times is the costly part, and the report's too) */
static int predict_report(const rr_rig_config *c, rr_rig_problem *out, int cap)
{
    static const char *const loop_rows[] = {
        "scenario.control_sample_time_s", "roller.inertia_kg_m2", "wheelset.spin_inertia_kg_m2",
        "wheelset_drive.drive_inertia_kg_m2", "roller_drive.kp_N_m_s_per_rad",
        "roller_drive.ki_N_m_s_per_rad", "roller_drive.torque_limit_N_m",
        "roller_drive.lag_time_constant_s", "wheelset_drive.kp_N_m_s_per_rad",
        "wheelset_drive.ki_N_m_s_per_rad", "wheelset_drive.torque_limit_N_m",
        "wheelset_drive.lag_time_constant_s", "creepage_controller.alpha"};
    const rr_rig_list *ts = &c->target_start, *st = &c->schedule_t;
    const rr_rig_list *sched[3] = {&c->schedule_mu0, &c->schedule_A, &c->schedule_B};
    const char *sched_names[3] = {"adhesion.schedule_mu0", "adhesion.schedule_polach_A",
                                  "adhesion.schedule_polach_B_s_per_m"};
    int n = 0, i, k, loops_ok = 1;
    for (i = 0; i < rr_rig_param_count(); i++) {
        const rr_rig_param *r = rr_rig_param_at(i);
        if (!r->creep && predict_row(c, r, &out[n]) != RR_OK)
            n++;
    }
    if (!row_bad(c, "scenario.targets") && !row_bad(c, "scenario.target_start_s")) {
        if (ts->n != c->targets.n) {
            problem(&out[n++], "scenario.target_start_s", "scenario.targets", RR_ERR_PARAM,
                    RR_RIG_RULE_COUNT, -1, ts->n, NAN, c->targets.n);
        } else {
            for (k = 1; k < ts->n; k++)
                if (!(ts->v[k] > ts->v[k - 1]))
                    break;
            if (k < ts->n)
                problem(&out[n++], "scenario.target_start_s", NULL, RR_ERR_PARAM,
                        RR_RIG_RULE_INCREASING, k, ts->v[k], NAN, NAN);
            else if (!row_bad(c, "scenario.duration_s") && !(ts->v[ts->n - 1] < c->duration))
                problem(&out[n++], "scenario.target_start_s", "scenario.duration_s",
                        RR_ERR_PARAM, RR_RIG_RULE_BEFORE, ts->n - 1, ts->v[ts->n - 1], NAN,
                        c->duration);
        }
    }
    if (!row_bad(c, "scenario.duration_s") && !row_bad(c, "scenario.control_sample_time_s")
        && !(c->duration >= c->T * (1.0 - 1e-9)))
        problem(&out[n++], "scenario.duration_s", "scenario.control_sample_time_s", RR_ERR_PARAM,
                RR_RIG_RULE_SAMPLE, -1, c->duration, c->T, NAN);
    if (!row_bad(c, "adhesion.schedule_times_s") && !row_bad(c, sched_names[0])
        && !row_bad(c, sched_names[1]) && !row_bad(c, sched_names[2])) {
        for (k = 0; k < 3; k++)
            if (sched[k]->n != st->n && !(k > 0 && sched[k]->n == 0))
                problem(&out[n++], sched_names[k], "adhesion.schedule_times_s", RR_ERR_PARAM,
                        RR_RIG_RULE_COUNT, -1, sched[k]->n, k > 0 ? 0.0 : NAN, st->n);
        for (k = 1; k < st->n; k++)
            if (!(st->v[k] >= st->v[k - 1]))
                break;
        if (k < st->n)
            problem(&out[n++], "adhesion.schedule_times_s", NULL, RR_ERR_PARAM,
                    RR_RIG_RULE_NONDECREASING, k, st->v[k], NAN, NAN);
    }
    if (!row_bad(c, "disturbance.lateral_force_times_s")
        && !row_bad(c, "disturbance.lateral_force_N")) {
        const rr_rig_list *lt = &c->lateral_t;
        if (c->lateral_f.n != lt->n)
            problem(&out[n++], "disturbance.lateral_force_N", "disturbance.lateral_force_times_s",
                    RR_ERR_PARAM, RR_RIG_RULE_COUNT, -1, c->lateral_f.n, NAN, lt->n);
        for (k = 1; k < lt->n; k++)
            if (!(lt->v[k] >= lt->v[k - 1]))
                break;
        if (k < lt->n)
            problem(&out[n++], "disturbance.lateral_force_times_s", NULL, RR_ERR_PARAM,
                    RR_RIG_RULE_NONDECREASING, k, lt->v[k], NAN, NAN);
    }
    if (!row_bad(c, "adhesion.patch_length_m") && !row_bad(c, "roller.radius_m")
        && !(c->patch_length <= 2.0 * RR_PI * c->roller_radius))
        problem(&out[n++], "adhesion.patch_length_m", "roller.radius_m", RR_ERR_PARAM,
                RR_RIG_RULE_CIRCUMFERENCE, -1, c->patch_length, NAN,
                2.0 * RR_PI * c->roller_radius);
    for (k = 0; k < (int)(sizeof loop_rows / sizeof loop_rows[0]); k++)
        loops_ok &= !row_bad(c, loop_rows[k]);
    if (loops_ok) {
        rr_speed_loop l[2];
        l[0].pi.T = l[1].pi.T = c->T;
        l[0].pi.Kp = c->roller_kp;
        l[0].pi.KI = c->roller_ki;
        l[0].pi.Tmax = c->roller_tmax;
        l[0].J = c->roller_inertia;
        l[0].tau = c->roller_tau;
        l[0].alpha = 0.0;
        l[1].pi.Kp = c->wheelset_kp;
        l[1].pi.KI = c->wheelset_ki;
        l[1].pi.Tmax = c->wheelset_tmax;
        l[1].J = c->spin_inertia + c->drive_inertia;
        l[1].tau = c->wheelset_tau;
        l[1].alpha = c->ctl_alpha;
        for (k = 0; k < 2; k++)
            if (rr_speed_loop_check(&l[k]) == RR_ERR_PARAM) {
                double rho = NAN, lo = NAN, hi = NAN;
                if (n < cap) {
                    rr_speed_loop_radius(&l[k], &rho);
                    rr_speed_loop_range(&l[k], RR_RIG_MIN_T, RR_RIG_MAX_T, &lo, &hi);
                }
                problem(&out[n++], "scenario.control_sample_time_s", NULL, RR_ERR_PARAM,
                        RR_RIG_RULE_LOOP, k, rho, lo, hi);
            }
    }
    if (!row_bad(c, "wheelset.spin_inertia_kg_m2")
        && !row_bad(c, "wheelset_drive.drive_inertia_kg_m2")
        && !isfinite(c->spin_inertia + c->drive_inertia))
        problem(&out[n++], "wheelset.spin_inertia_kg_m2", "wheelset_drive.drive_inertia_kg_m2",
                RR_ERR_RANGE, RR_RIG_RULE_SUM, -1, c->spin_inertia + c->drive_inertia, NAN, NAN);
    return n;
}

/* a few values stored unchecked (rr_rig_config_put, _put_list), each
 * status, stored value and problem as the header says */
static void run_puts(fz_in *in, rr_rig_config *c)
{
    const int nputs = fz_range(in, 0, MAX_PUTS);
    int call, i;
    for (call = 0; call < nputs; call++) {
        const rr_rig_param *r;
        const char *name = decode_name(in, &r);
        rr_rig_config before = *c;
        rr_rig_problem got, want;
        int st, wst;
        got.key = "canary";
        problem(&want, "canary", NULL, 0, 0, 0, 0.0, 0.0, 0.0);
        if (fz_choice(in, 2) == 0) {
            const double v = decode_value(in, r);
            st = rr_rig_config_put(c, name, v, &got);
            fz_note("; put %s = %.17g: %d", name ? name : "NULL", v, st);
            if (!name)
                wst = RR_ERR_NULL;
            else if (!r || r->creep || r->type == RR_RIG_LIST)
                wst = RR_ERR_PARAM;
            else if (r->type == RR_RIG_REAL || (v == floor(v) && fabs(v) <= 2147483647.0))
                wst = RR_OK;
            else {
                const int choice = r->type == RR_RIG_CHOICE;
                wst = predict_set(r, v);
                problem(&want, r->name, NULL, wst, RR_RIG_RULE_RANGE, -1, v,
                        choice ? 0.0 : r->lo, choice ? nchoices(r) - 1.0 : r->hi);
                if (wst == RR_OK)
                    fz_fail("rr_rig_config_put: %s cannot hold %.17g, yet it is in range",
                            name, v);
            }
            if (st == RR_OK && wst == RR_OK) {
                const char *at = (const char *)c + r->offset;
                const double held = r->type == RR_RIG_REAL ? *(const double *)(const void *)at
                                                          : (double)*(const int *)(const void *)at;
                if (!same_double(held, v))
                    fz_fail("rr_rig_config_put: %s = %.17g, the member holds %.17g", name, v,
                            held);
            }
        } else {
            double v[RR_RIG_MAX_LIST + 1];
            int n = fz_int(in, -1, 8);
            const int vnull = fz_choice(in, 16) == 0;
            if (n > RR_RIG_MAX_LIST + 1)
                n = RR_RIG_MAX_LIST + 1;
            for (i = 0; i < n && i <= RR_RIG_MAX_LIST; i++)
                v[i] = fz_choice(in, 4) == 0 ? decode_value(in, r)
                       : r && r->hi <= 1.0 ? fz_lin(in, 0.0, 1.0) : fz_log(in, 1e-3, 30.0);
            st = rr_rig_config_put_list(c, name, n, vnull ? NULL : v, &got);
            fz_note("; put_list %s n %d: %d", name ? name : "NULL", n, st);
            if (!name || (vnull && n > 0))
                wst = RR_ERR_NULL;
            else if (!r || r->creep || r->type != RR_RIG_LIST)
                wst = RR_ERR_PARAM;
            else if (n < 0 || n > RR_RIG_MAX_LIST) {
                wst = RR_ERR_PARAM;
                problem(&want, r->name, NULL, RR_ERR_PARAM, RR_RIG_RULE_RANGE, -1, n,
                        r->nlist > 0, RR_RIG_MAX_LIST);
            } else {
                const rr_rig_list *l = (const rr_rig_list *)(const void *)((const char *)c
                                                                           + r->offset);
                wst = RR_OK;
                if (st == RR_OK && (l->n != n || (n > 0 && memcmp(l->v, v, (size_t)n
                                                                           * sizeof v[0]))))
                    fz_fail("rr_rig_config_put_list: %s not the %d values given", name, n);
            }
        }
        fz_status("rr_rig_config_put", st);
        if (st != wst)
            fz_fail("rr_rig_config_put: %s status %d, the header's %d", name ? name : "NULL",
                    st, wst);
        if (strcmp(want.key, "canary") == 0 ? strcmp(got.key, "canary") != 0
                                            : !same_problem(&got, &want))
            fz_fail("rr_rig_config_put: %s's problem not the header's", name ? name : "NULL");
        if (st != RR_OK)
            fz_same("rr_rig_config_put", &before, c, sizeof *c, "the config (on error)");
    }
    if (rr_rig_config_put(NULL, "wheelset.mass_kg", 1.0, NULL) != RR_ERR_NULL
        || rr_rig_config_put_list(NULL, "scenario.targets", 0, NULL, NULL) != RR_ERR_NULL)
        fz_fail("rr_rig_config_put: a NULL config not RR_ERR_NULL");
}

/* rr_rig_config_report: every problem as predicted, in order; the cap
 * honoured; rr_rig_config_check its first */
static void check_report(fz_in *in, const rr_rig_config *c0)
{
    rr_rig_config c = *c0;
    rr_rig_problem want[RR_RIG_MAX_PROBLEMS], *got;
    const char *bad;
    int n, nw, cap, k, st;
    run_puts(in, &c);
    /* the cap: every problem one input in 32 (not where the input has ended:
     * zero bytes, the first choice); else short of the first loop's problem,
     * whose scan of sample times (in the report and in the prediction) took
     * the fuzzer from 311 inputs a second to 30 */
    nw = predict_report(&c, want, 0);
    if (nw > RR_RIG_MAX_PROBLEMS)
        fz_fail("rr_rig_config_report: %d problems, more than RR_RIG_MAX_PROBLEMS", nw);
    for (k = 0; k < nw && want[k].rule != RR_RIG_RULE_LOOP; k++)
        ;
    cap = fz_choice(in, 32) == 31 ? RR_RIG_MAX_PROBLEMS : fz_range(in, 0, k);
    if (cap > k)
        predict_report(&c, want, cap);
    got = fz_guarded((size_t)(cap > 0 ? cap : 1) * sizeof *got);
    n = rr_rig_config_report(&c, got, cap);
    fz_note("; report: %d problems (predicted %d), cap %d", n, nw, cap);
    if (n != nw)
        fz_fail("rr_rig_config_report: %d problems, predicted %d", n, nw);
    for (k = 0; k < n && k < cap; k++)
        if (!same_problem(&got[k], &want[k]))
            fz_fail("rr_rig_config_report: problem %d is %s (status %d, rule %d), predicted %s "
                    "(status %d, rule %d)", k, got[k].key, got[k].status, got[k].rule,
                    want[k].key, want[k].status, want[k].rule);
    if (cap < RR_RIG_MAX_PROBLEMS)
        fz_guard_ok("rr_rig_config_report", got, (size_t)(cap > 0 ? cap : 1) * sizeof *got,
                    "out[cap]");
    fz_guard_free(got);
    if (rr_rig_config_report(&c, NULL, 0) != n || rr_rig_config_report(NULL, NULL, 0)
                                                   != RR_ERR_NULL
        || rr_rig_config_report(&c, NULL, 1) != RR_ERR_NULL)
        fz_fail("rr_rig_config_report: the count alone, or a NULL, not as documented");
    st = rr_rig_config_check(&c, &bad);
    if (n == 0 ? st != RR_OK || bad != NULL
               : st != want[0].status || !bad || strcmp(bad, want[0].key) != 0)
        fz_fail("rr_rig_config_check: status %d at %s, not the report's first", st,
                bad ? bad : "NULL");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    rr_rig_config c;
    const char *bad = "unset", *want_bad;
    int st, want;

    if (rr_rig_config_default(&c) != RR_OK || rr_rig_config_default(NULL) != RR_ERR_NULL)
        fz_fail("rr_rig_config_default: statuses");
    if (rr_rig_config_check(&c, NULL) != RR_OK)
        fz_fail("rr_rig_config_check: the defaults do not pass");
    check_table_api(&in);
    if (fz_choice(&in, 8) == 0)
        corrupt(&in, &c);
    else
        run_setters(&in, &c);
    st = rr_rig_config_check(&c, &bad);
    fz_status("rr_rig_config_check", st);
    want = predict_check(&c, &want_bad);
    if (st != want || (st != RR_OK && (!bad || !want_bad || strcmp(bad, want_bad) != 0))
        || (st == RR_OK && bad != NULL))
        fz_fail("rr_rig_config_check: status %d at %s, predicted %d at %s", st,
                bad ? bad : "NULL", want, want_bad ? want_bad : "NULL");
    if (rr_rig_config_check(NULL, NULL) != RR_ERR_NULL)
        fz_fail("rr_rig_config_check(NULL) not RR_ERR_NULL");
    if (st == RR_OK)
        check_derived(&in, &c);
    else {
        rr_rig_params p;
        if (rr_rig_params_from(&c, NULL, &p) != st)
            fz_fail("rr_rig_params_from: not rr_rig_config_check's status");
    }
    check_wheel_store(&in);
    check_report(&in, &c);
    return 0;
}
