/*
 * fuzz_geometry.c - the contact geometry: rr_contact_search,
 * rr_wheelset_contact, rr_contact_table_build and rr_contact_table_lookup
 * on profiles built from the input as point lists, and
 * rr_contact_table_lookup on a table struct whose y0, dy, n and data come
 * from the input (data NULL, n < 2 or negative, y0 or dy NaN, rows of
 * garbage): a C caller fills that struct, and the lookup must refuse what
 * it can check.  (n larger than the buffer it cannot check: the struct has
 * no length, so n never exceeds the rows allocated here.)
 *
 * Profiles: the wheel's and the roller's from fuzz_profile.h (3 .. 80
 * points; base shape, perturbed, or a free point list).  The pair:
 * r0, R0 (20 .. 500 mm), the profiles' lateral places, side +-1 (or any
 * int).  Search options: nsamples 3 .. 2000 (400 for the Newton solves
 * and tables) or an edge, the two-point tolerances.  Tables: 2 .. 6 rows.
 *
 * Oracles: documented errors; on success every geometric output finite,
 * r, R, B, the Hertz factors positive, the contact on both profiles, the
 * two-point flag 0 or 1; rr_wheelset_contact's OK means both gaps within
 * 1e-9 m; a table built without error holds finite rows; a lookup's
 * success means finite outputs.
 */
#include "fuzz.h"
#include "fuzz_profile.h"

#define MAX_ROWS 6

static void set_spline(rr_spline *sp, const fz_profile *p)
{
    sp->n = p->n;
    sp->s = p->s;
    sp->z = p->z;
    sp->m = p->m;
}

static void decode_pair(fz_in *in, const fz_profile *w, const fz_profile *r, rr_wheel_roller *p)
{
    set_spline(&p->wheel, w);
    set_spline(&p->roller, r);
    p->r0 = fz_log(in, 0.02, 0.5);
    p->R0 = fz_log(in, 0.02, 0.5);
    p->wheel_y = fz_lin(in, 0.05, 0.8);
    p->roller_y = p->wheel_y + fz_lin(in, -0.005, 0.005);
    p->side = fz_choice(in, 16) == 0 ? fz_int(in, -1, 1) : 1;
    fz_note("pair r0 = %.17g, R0 = %.17g, wheel_y = %.17g, roller_y = %.17g, side %d; ", p->r0,
            p->R0, p->wheel_y, p->roller_y, p->side);
}

static void decode_opts(fz_in *in, rr_search_opts *o, int hi)
{
    rr_search_opts_default(o);
    if (fz_choice(in, 2) == 0)
        return;
    o->nsamples = fz_int(in, 3, hi);
    o->two_point_tol = fz_lin(in, 0.0, 1e-3);
    o->two_point_sep = fz_lin(in, 0.0, 5e-3);
    fz_note("opts nsamples %d, two_point_tol %.17g, two_point_sep %.17g; ", o->nsamples,
            o->two_point_tol, o->two_point_sep);
}

static int opts_invalid(const rr_search_opts *o)
{
    return o->nsamples < 3 || !(o->two_point_tol >= 0.0) || !(o->two_point_sep >= 0.0);
}

/* A pair whose numbers are not finite: the search must refuse it. */
static int pair_nonfinite(const rr_wheel_roller *p)
{
    return !isfinite(p->r0) || !isfinite(p->R0) || !isfinite(p->wheel_y)
        || !isfinite(p->roller_y);
}

/* Known: r0, R0, wheel_y, roller_y are not checked (R0 = inf gives R = inf
 * with status 0). */
static int known_pair(const rr_wheel_roller *l, const rr_wheel_roller *r)
{
    return pair_nonfinite(l) || pair_nonfinite(r);
}

/* Known: rr_contact_search's scan loop runs to nsamples inclusive with an
 * int counter: nsamples = INT_MAX overflows it (and nothing caps the work). */
static int known_nsamples(const rr_search_opts *o)
{
    return o->nsamples > 10000000;
}

static void check_point(const char *fn, int st, const rr_contact_point *c, const rr_wheel_roller *p)
{
    const double f[] = {c->y, c->z, c->s_wheel, c->s_roller, c->r, c->R, c->delta, c->A, c->B,
                        c->gap, c->ha, c->hb, c->hd};
    const char *name[] = {"y", "z", "s_wheel", "s_roller", "r", "R", "delta", "A", "B", "gap",
                          "ha", "hb", "hd"};
    int i;
    if (st < 0)
        return;
    for (i = 0; i < 13; i++)
        fz_finite(fn, st, name[i], f[i]);
    if (c->two_point != 0 && c->two_point != 1)
        fz_fail("%s: two_point = %d", fn, c->two_point);
    if (c->two_point) {
        FZ_FINITE(fn, st, c->y2);
        FZ_FINITE(fn, st, c->gap2);
    }
    if (!(c->r > 0.0 && c->R > 0.0 && c->B > 0.0 && c->ha > 0.0 && c->hb > 0.0 && c->hd > 0.0))
        fz_fail("%s: status %d with r = %g, R = %g, B = %g, ha = %g, hb = %g, hd = %g (all "
                "must be > 0)", fn, st, c->r, c->R, c->B, c->ha, c->hb, c->hd);
    if (p && !(c->s_wheel >= p->wheel.s[0] && c->s_wheel <= p->wheel.s[p->wheel.n - 1]
               && c->s_roller >= p->roller.s[0] && c->s_roller <= p->roller.s[p->roller.n - 1]))
        fz_fail("%s: contact off the profiles: s_wheel = %.17g, s_roller = %.17g", fn,
                c->s_wheel, c->s_roller);
}

static void check_search(fz_in *in, const rr_wheel_roller *p)
{
    const char *fn = "rr_contact_search";
    const double y_ws = fz_lin(in, -0.01, 0.01);
    const double z_ws = p->r0 + fz_slog(in, 1e-9, 1e-3);
    const double roll = fz_slog(in, 1e-9, 0.05);
    rr_search_opts o;
    rr_contact_point c;
    int st;

    decode_opts(in, &o, 2000);
    fz_note("rr_contact_search(y_ws = %.17g, z_ws = %.17g, roll = %.17g)", y_ws, z_ws, roll);
    if (fz_known("nsamples", known_nsamples(&o)) || fz_known("pair", known_pair(p, p)))
        return;
    st = rr_contact_search(p, y_ws, z_ws, roll, &o, &c);
    fz_status(fn, st);
    fz_error(fn, st, !isfinite(y_ws) || !isfinite(z_ws) || !isfinite(roll) || opts_invalid(&o)
                         || pair_nonfinite(p), "an argument is invalid");
    check_point(fn, st, &c, p);
}

static void check_wheelset(fz_in *in, const rr_wheel_roller *l, const rr_wheel_roller *r)
{
    const char *fn = "rr_wheelset_contact";
    const double y_ws = fz_lin(in, -0.01, 0.01);
    rr_search_opts o;
    rr_wheelset_pose pose;
    rr_contact_point cl, cr;
    int st;

    decode_opts(in, &o, 400);
    fz_note("rr_wheelset_contact(y_ws = %.17g), right r0 = %.17g, wheel_y = %.17g", y_ws, r->r0,
            r->wheel_y);
    if (fz_known("nsamples", known_nsamples(&o)) || fz_known("pair", known_pair(l, r)))
        return;
    st = rr_wheelset_contact(l, r, y_ws, &o, &pose, &cl, &cr);
    fz_status(fn, st);
    fz_error(fn, st, !isfinite(y_ws) || opts_invalid(&o) || pair_nonfinite(l)
                         || pair_nonfinite(r), "an argument is invalid");
    FZ_FINITE(fn, st, pose.z);
    FZ_FINITE(fn, st, pose.roll);
    check_point(fn, st, &cl, l);
    check_point(fn, st, &cr, r);
    if (st == RR_OK && !(fabs(cl.gap) <= 1e-9 && fabs(cr.gap) <= 1e-9))
        fz_fail("%s: OK with gaps %.3g, %.3g m (documented: a warning beyond 1e-9)", fn, cl.gap,
                cr.gap);
}

/* Known: the lookup trusts the struct: y0 or dy NaN, dy <= 0, n < 2, data
 * NULL, and rows of NaN or huge values are not refused. */
static int known_table(const rr_contact_table *t, int nrows)
{
    int i;
    if (!t->data || t->n < 2 || !isfinite(t->y0) || !isfinite(t->dy) || !(t->dy > 0.0))
        return 1;
    for (i = 0; i < nrows * RR_CONTACT_TABLE_ROW; i++)
        if (!(fabs(t->data[i]) < 1e100))
            return 1;
    return 0;
}

static void check_lookup(fz_in *in, const rr_contact_table *t, int skip_known)
{
    const char *fn = "rr_contact_table_lookup";
    const int nl = fz_range(in, 1, 4);
    /* the table's range: its first and last rows' shifts, exactly */
    const double end = t->y0 + ((double)t->n - 1.0) * t->dy;
    const int bad_struct = !t->data || t->n < 2 || !isfinite(t->y0) || !isfinite(t->dy)
                           || !(t->dy > 0.0);
    int k;

    for (k = 0; k < nl; k++) {
        const int within = fz_choice(in, 4) != 0;
        const double y = within ? t->y0 + fz_lin(in, 0.0, 1.0) * (end - t->y0)
                                : fz_lin(in, -0.02, 0.02);
        const int want_slope = fz_choice(in, 2);
        const int off = !isfinite(y) || y < t->y0 || y > end;
        rr_wheelset_pose pose, slope;
        rr_contact_point cl, cr;
        int st;

        fz_note("; lookup y = %.17g, slope %d", y, want_slope);
        if (skip_known)
            return;
        st = rr_contact_table_lookup(t, y, &pose, want_slope ? &slope : NULL, &cl, &cr);
        fz_status(fn, st);
        if ((bad_struct || off) && st >= 0)
            fz_fail("%s: status %d for y0 = %g, dy = %g, n = %d, data %s, y = %.17g", fn, st,
                    t->y0, t->dy, t->n, t->data ? "set" : "NULL", y);
        if (st < 0)
            continue;
        FZ_FINITE(fn, st, pose.z);
        FZ_FINITE(fn, st, pose.roll);
        if (want_slope) {
            FZ_FINITE(fn, st, slope.z);
            FZ_FINITE(fn, st, slope.roll);
        }
        {
            const double f[] = {cl.y, cl.z, cl.s_wheel, cl.s_roller, cl.r, cl.R, cl.delta, cl.A,
                                cl.B, cl.ha, cl.hb, cl.hd, cr.y, cr.z, cr.s_wheel, cr.s_roller,
                                cr.r, cr.R, cr.delta, cr.A, cr.B, cr.ha, cr.hb, cr.hd};
            fz_finite_n(fn, st, "contact point field", f, 24);
        }
        if ((cl.two_point != 0 && cl.two_point != 1) || (cr.two_point != 0 && cr.two_point != 1))
            fz_fail("%s: two_point flags %d, %d", fn, cl.two_point, cr.two_point);
    }
}

static void check_table(fz_in *in, const rr_wheel_roller *l, const rr_wheel_roller *r)
{
    const char *fn = "rr_contact_table_build";
    const int n = fz_int(in, 2, MAX_ROWS);
    const int rows = n >= 1 && n <= MAX_ROWS ? n : 1;
    const int null_data = fz_choice(in, 16) == 0;
    double *data = fz_alloc((size_t)rows * RR_CONTACT_TABLE_ROW * sizeof *data);
    double bad_y = 7.0;
    rr_search_opts o;
    rr_contact_table t;
    int st, i;

    t.y0 = fz_lin(in, -0.006, 0.0);
    t.dy = fz_log(in, 1e-4, 2e-3);
    t.n = n <= MAX_ROWS ? n : rows;      /* never more rows than allocated */
    t.data = null_data ? NULL : data;
    decode_opts(in, &o, 400);
    fz_note("rr_contact_table_build(y0 = %.17g, dy = %.17g, n = %d, data %s)", t.y0, t.dy, t.n,
            t.data ? "set" : "NULL");
    if (fz_known("nsamples", known_nsamples(&o)) || fz_known("pair", known_pair(l, r))) {
        free(data);
        return;
    }
    st = rr_contact_table_build(l, r, &o, &t, fz_choice(in, 2) ? &bad_y : NULL);
    fz_status(fn, st);
    fz_error(fn, st, null_data || t.n < 2 || !isfinite(t.y0) || !isfinite(t.dy)
                         || !(t.dy > 0.0) || opts_invalid(&o) || pair_nonfinite(l)
                         || pair_nonfinite(r), "an argument is invalid");
    if (st >= 0) {
        for (i = 0; i < t.n * RR_CONTACT_TABLE_ROW; i++)
            if (!isfinite(data[i]))
                fz_fail("%s: status %d with row %d, column %d = %g", fn, st,
                        i / RR_CONTACT_TABLE_ROW, i % RR_CONTACT_TABLE_ROW, data[i]);
        /* every row's own shift, both ends included, is inside; an ulp past
         * either end is not (issue 22: the last row was refused) */
        for (i = 0; i < t.n; i++) {
            rr_wheelset_pose pose;
            rr_contact_point cl, cr;
            const double y = t.y0 + i * t.dy;
            if ((st = rr_contact_table_lookup(&t, y, &pose, NULL, &cl, &cr)) != RR_OK)
                fz_fail("rr_contact_table_lookup: status %d at row %d of %d, y = %.17g", st, i,
                        t.n, y);
            if ((i == 0 || i == t.n - 1)
                && rr_contact_table_lookup(&t, nextafter(y, i == 0 ? -HUGE_VAL : HUGE_VAL),
                                           &pose, NULL, &cl, &cr) != RR_ERR_GEOMETRY)
                fz_fail("rr_contact_table_lookup: an ulp past row %d of %d taken", i, t.n);
        }
        check_lookup(in, &t, 0);
    }
    free(data);
}

/* A table struct straight from the input. */
static void check_raw_table(fz_in *in)
{
    const int rows = fz_range(in, 0, 8);
    const int nchoice = fz_choice(in, 4);
    double *data = fz_alloc((size_t)(rows > 0 ? rows : 1) * RR_CONTACT_TABLE_ROW * sizeof *data);
    rr_contact_table t;
    int i;

    t.n = nchoice == 0 ? fz_int(in, -2, rows) : rows;
    if (t.n > rows)
        t.n = rows;                  /* a longer n than the buffer cannot be checked */
    t.y0 = fz_lin(in, -0.01, 0.01);
    t.dy = fz_log(in, 1e-5, 1e-2);
    t.data = fz_choice(in, 16) == 0 ? NULL : data;
    in->edges = fz_choice(in, 4) == 0;
    for (i = 0; i < rows * RR_CONTACT_TABLE_ROW; i++)
        data[i] = (i % RR_CONTACT_TABLE_ROW) == 9 ? (double)fz_choice(in, 2)
                                                  : fz_lin(in, 1e-3, 0.2);
    in->edges = 1;
    fz_note("table struct y0 = %.17g, dy = %.17g, n = %d over %d rows, data %s; rows:", t.y0,
            t.dy, t.n, rows, t.data ? "set" : "NULL");
    for (i = 0; i < rows * RR_CONTACT_TABLE_ROW; i++)
        fz_note(" %.17g", data[i]);
    check_lookup(in, &t, fz_known("table_struct", known_table(&t, rows)));
    free(data);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    const int op = fz_choice(&in, 4);
    fz_profile w, r;
    rr_wheel_roller left, right;

    if (op == 3) {
        check_raw_table(&in);
        return 0;
    }
    if (fz_decode_profile(&in, &w, 0, 3, 1) != RR_OK || fz_decode_profile(&in, &r, 1, 3, 1) != RR_OK)
        return 0;                    /* invalid point lists: fuzz_spline's business */
    decode_pair(&in, &w, &r, &left);
    right = left;
    right.side = left.side == INT_MIN ? INT_MAX : -left.side;
    if (fz_choice(&in, 4) == 0) {
        right.r0 = fz_log(&in, 0.02, 0.5);
        right.wheel_y = fz_lin(&in, 0.05, 0.8);
    }
    switch (op) {
    case 0:
        check_search(&in, &left);
        break;
    case 1:
        check_wheelset(&in, &left, &right);
        break;
    default:
        check_table(&in, &left, &right);
        break;
    }
    return 0;
}
