/*
 * fuzz_rig_params.c - the rig's declared parameters (rr_rig_params.h): the
 * table (rr_rig_param_at, _find, _choice), the config's setters
 * (rr_rig_config_set, _set_choice, _set_list) and rr_rig_config_check, and
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
 * RR_WHEEL_NVALUES values at the stride, the fields' values, nothing else.
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
    return *bad ? RR_ERR_PARAM : RR_OK;
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
    return 0;
}
