/* rr_tables.c - contact tables from profile points; the rig's default table. */
#include <math.h>
#include <stddef.h>
#include "util/rr_common.h"
#include "geometry/rr_tables.h"

static void fill_nan(double *v, long n)
{
    long i;
    if (v)
        for (i = 0; i < n; i++)
            v[i] = NAN;
}

/* What rollerrig.profiles._range_points checks of (y_min, y_max, n). */
static int range_check(double y_min, double y_max, int n)
{
    if (!(n >= RR_SPLINE_MIN_POINTS && n <= RR_SPLINE_MAX_POINTS))
        return RR_ERR_PARAM;
    if (!isfinite(y_min) || !isfinite(y_max))
        return RR_ERR_NONFINITE;
    if (!(y_max > y_min) || fabs(y_min) > RR_PROFILE_MAX_COORD
        || fabs(y_max) > RR_PROFILE_MAX_COORD || !(y_max - y_min >= RR_PROFILE_MIN_WIDTH))
        return RR_ERR_PARAM;
    return RR_OK;
}

/* numpy.linspace(y_min, y_max, n): i * step + y_min, the last point y_max
 * (step is never 0 here: the range is at least RR_PROFILE_MIN_WIDTH). */
static void linspace(double y_min, double y_max, int n, double *y)
{
    const double step = (y_max - y_min) / (double)(n - 1);
    int i;
    for (i = 0; i < n; i++)
        y[i] = (double)i * step + y_min;
    y[n - 1] = y_max;
}

/* A constructor's failure: st, its points NaN where n gives their length. */
static int points_failed(int st, int n, double *y, double *z)
{
    if (n >= 1 && n <= RR_SPLINE_MAX_POINTS) {      /* fill_nan skips a NULL */
        fill_nan(y, n);
        fill_nan(z, n);
    }
    return st;
}

int rr_profile_conical(double alpha, double y_min, double y_max, int n, double *y, double *z)
{
    int i, st;
    if (!y || !z)
        st = RR_ERR_NULL;
    else if ((st = range_check(y_min, y_max, n)) == RR_OK && !isfinite(alpha))
        st = RR_ERR_NONFINITE;
    else if (st == RR_OK && !(fabs(alpha) < RR_PI / 2.0))
        st = RR_ERR_PARAM;
    if (st != RR_OK)
        return points_failed(st, n, y, z);
    linspace(y_min, y_max, n, y);
    for (i = 0; i < n; i++)
        z[i] = -tan(alpha) * y[i];
    return RR_OK;
}

int rr_profile_crowned(double crown_radius, double y_min, double y_max, int n, double *y,
                       double *z)
{
    const double R = crown_radius;
    int i, st;
    if (!y || !z)
        st = RR_ERR_NULL;
    else if ((st = range_check(y_min, y_max, n)) == RR_OK && !isfinite(R))
        st = RR_ERR_NONFINITE;
    else if (st == RR_OK && !(R >= 0.0))
        st = RR_ERR_PARAM;
    else if (st == RR_OK && R > 0.0 && !(fmax(fabs(y_min), fabs(y_max)) < R))
        st = RR_ERR_GEOMETRY;
    if (st != RR_OK)
        return points_failed(st, n, y, z);
    linspace(y_min, y_max, n, y);
    for (i = 0; i < n; i++)
        z[i] = R == 0.0 ? 0.0 : y[i] * y[i] / (R + sqrt(R - y[i]) * sqrt(R + y[i]));
    return RR_OK;
}

static int count_ok(int n)
{
    return n >= RR_SPLINE_MIN_POINTS && n <= RR_SPLINE_MAX_POINTS;
}

int rr_profile_surface(const rr_profile_points *p, double *zup, double *mup, double *work)
{
    int i, st;
    if (!p)
        return RR_ERR_NULL;
    if (!zup || !mup || !work) {
        if (p->n >= 1 && p->n <= RR_SPLINE_MAX_POINTS) {
            fill_nan(zup, p->n);
            fill_nan(mup, p->n);
        }
        return RR_ERR_WORKSPACE;
    }
    /* a count out of range is refused before work + 3 n is formed (for
     * n near INT_MAX or INT_MIN the products overflow, and any n beyond the
     * buffer makes the pointers undefined) */
    if (!count_ok(p->n)) {
        if (p->n >= 1 && p->n <= RR_SPLINE_MAX_POINTS) {
            fill_nan(zup, p->n);
            fill_nan(mup, p->n);
        }
        return RR_ERR_PARAM;
    }
    /* work: slopes, c2, c3 (n - 1 used), the fit's own n */
    st = rr_spline_fit(p->n, p->y, p->z, p->end, work, work + p->n, work + 2 * p->n,
                       work + 3 * p->n);
    if (st == RR_OK)
        st = rr_spline_knot_d2(p->n, p->y, work + p->n, work + 2 * p->n, mup);
    if (st != RR_OK) {
        if (p->n >= 1 && p->n <= RR_SPLINE_MAX_POINTS) {
            fill_nan(zup, p->n);
            fill_nan(mup, p->n);
        }
        return st;
    }
    for (i = 0; i < p->n; i++) {
        zup[i] = -p->z[i];
        mup[i] = -mup[i];
    }
    return RR_OK;
}

long rr_profile_table_work_len(int n_wheel, int n_roller)
{
    if (!count_ok(n_wheel) || !count_ok(n_roller))
        return 0;
    return 2L * n_wheel + 2L * n_roller + 4L * (n_wheel > n_roller ? n_wheel : n_roller);
}

int rr_profile_table_build(const rr_profile_points *wheel, const rr_profile_points *roller,
                           const rr_profile_placement *place, const rr_search_opts *o,
                           rr_contact_table *t, long data_len, double *work, long work_len,
                           double *bad_y)
{
    if (!t) {
        if (bad_y)
            *bad_y = NAN;
        return RR_ERR_NULL;
    }
    return rr_profile_table_build_rows(wheel, roller, place, o, t, data_len, work, work_len,
                                       0, t->n, bad_y);
}

int rr_profile_table_build_rows(const rr_profile_points *wheel,
                                const rr_profile_points *roller,
                                const rr_profile_placement *place, const rr_search_opts *o,
                                rr_contact_table *t, long data_len, double *work,
                                long work_len, int i0, int i1, double *bad_y)
{
    rr_wheel_roller pair[2];
    double *wz, *wm, *rz, *rm, *scratch;
    int k, st;

    if (bad_y)
        *bad_y = NAN;
    if (!wheel || !roller || !place || !o || !t || !wheel->y || !wheel->z || !roller->y
        || !roller->z)
        return RR_ERR_NULL;
    if (!count_ok(wheel->n) || !count_ok(roller->n))
        return RR_ERR_PARAM;
    if (!work || !t->data || work_len < rr_profile_table_work_len(wheel->n, roller->n)
        || t->n < 2 || data_len < rr_contact_table_len(t->n))
        return t->n < 2 ? RR_ERR_PARAM : RR_ERR_WORKSPACE;
    if (!isfinite(place->wheel_radius) || !isfinite(place->roller_radius)
        || !isfinite(place->wheel_y) || !isfinite(place->roller_y))
        return RR_ERR_NONFINITE;
    if (!(place->wheel_radius > 0.0) || !(place->roller_radius > 0.0))
        return RR_ERR_PARAM;
    wz = work;
    wm = wz + wheel->n;
    rz = wm + wheel->n;
    rm = rz + roller->n;
    scratch = rm + roller->n;
    if ((st = rr_profile_surface(wheel, wz, wm, scratch)) != RR_OK
        || (st = rr_profile_surface(roller, rz, rm, scratch)) != RR_OK)
        return st;
    for (k = 0; k < 2; k++) {
        pair[k].wheel.n = wheel->n;
        pair[k].wheel.s = wheel->y;
        pair[k].wheel.z = wz;
        pair[k].wheel.m = wm;
        pair[k].roller.n = roller->n;
        pair[k].roller.s = roller->y;
        pair[k].roller.z = rz;
        pair[k].roller.m = rm;
        pair[k].r0 = place->wheel_radius;
        pair[k].R0 = place->roller_radius;
        pair[k].wheel_y = place->wheel_y;
        pair[k].roller_y = place->roller_y;
        pair[k].side = k == 0 ? 1 : -1;
    }
    return rr_contact_table_build_rows(&pair[0], &pair[1], o, t, i0, i1, bad_y);
}

long rr_rig_table_data_len(const rr_rig_geometry *g)
{
    if (!g || !(g->table_rows >= 2 && g->table_rows <= RR_RIG_TABLE_MAX_ROWS))
        return 0;
    return rr_contact_table_len(g->table_rows);
}

int rr_rig_table_build(const rr_rig_geometry *g, double *data, long data_len, double *work,
                       long work_len, rr_contact_table *t, double *bad_y)
{
    return rr_rig_table_build_rows(g, data, data_len, work, work_len, 0, g ? g->table_rows : 0,
                                   t, bad_y);
}

/* The rig geometry's own values (both table builders): RR_ERR_NONFINITE,
 * RR_ERR_PARAM or RR_OK. */
static int check_geometry(const rr_rig_geometry *g)
{
    const double v[7] = {g->wheel_radius, g->roller_radius, g->profile_half_width,
                         g->cone_angle, g->crown_radius, g->contact_half_spacing,
                         g->table_half_range};
    if (!rr_all_finite(v, 7))
        return RR_ERR_NONFINITE;
    if (!(g->table_rows >= 2 && g->table_rows <= RR_RIG_TABLE_MAX_ROWS)
        || !(g->wheel_radius > 0.0) || !(g->roller_radius > 0.0)
        || !(g->profile_half_width > 0.0) || !(g->table_half_range > 0.0))
        return RR_ERR_PARAM;
    return RR_OK;
}

int rr_rig_table_build_rows(const rr_rig_geometry *g, double *data, long data_len,
                            double *work, long work_len, int i0, int i1, rr_contact_table *t,
                            double *bad_y)
{
    enum { N = RR_RIG_PROFILE_POINTS };
    rr_profile_points wheel, roller;
    rr_profile_placement place;
    rr_search_opts o;
    double *wy, *wz, *ry, *rz, hw, reach;
    int st;

    if (bad_y)
        *bad_y = NAN;
    if (!g || !t)
        return RR_ERR_NULL;
    if ((st = check_geometry(g)) != RR_OK)
        return st;
    if (!data || !work || data_len < rr_rig_table_data_len(g) || work_len < RR_RIG_TABLE_WORK_LEN)
        return RR_ERR_WORKSPACE;
    hw = g->profile_half_width;
    reach = g->table_half_range;
    wy = work;
    wz = wy + N;
    ry = wz + N;
    rz = ry + N;
    if ((st = rr_profile_conical(g->cone_angle, -hw, hw, N, wy, wz)) != RR_OK
        || (st = rr_profile_crowned(g->crown_radius, -hw, hw, N, ry, rz)) != RR_OK)
        return st;
    wheel.n = roller.n = N;
    wheel.y = wy;
    wheel.z = wz;
    roller.y = ry;
    roller.z = rz;
    wheel.end = roller.end = RR_SPLINE_NOT_A_KNOT;
    place.wheel_radius = g->wheel_radius;
    place.roller_radius = g->roller_radius;
    place.wheel_y = place.roller_y = g->contact_half_spacing;
    rr_search_opts_default(&o);
    /* rollerrig.contact_table's rows: y0 = y_min, dy = (y_max - y_min)/(n - 1) */
    t->y0 = -reach;
    t->dy = (reach - -reach) / (double)(g->table_rows - 1);
    t->n = g->table_rows;
    t->data = data;
    return rr_profile_table_build_rows(&wheel, &roller, &place, &o, t, data_len, rz + N,
                                       work_len - 4L * N, i0, i1, bad_y);
}

/* ---------------------------------------------------------------- the rig's profiles as points */

static const rr_profile_points *slot_of(const rr_rig_profiles *pr, int k)
{
    return k == RR_RIG_WHEEL ? &pr->wheel : k == RR_RIG_ROLLER ? &pr->roller
         : k == RR_RIG_WHEEL_RIGHT ? &pr->wheel_right : &pr->roller_right;
}

static int fault(int st, int k, int i, int *which, int *point)
{
    if (which)
        *which = k;
    if (point)
        *point = i;
    return st;
}

/* One given profile's points: what rr_rig_profiles_check says of them. */
static int points_check(const rr_profile_points *p, int k, int *which, int *point)
{
    double lo, hi;
    int i;
    if (!count_ok(p->n) || (p->end != RR_SPLINE_NOT_A_KNOT && p->end != RR_SPLINE_NATURAL))
        return fault(RR_ERR_PARAM, k, -1, which, point);
    if (!p->y || !p->z)
        return fault(RR_ERR_NULL, k, -1, which, point);
    for (i = 0; i < p->n; i++) {
        if (!isfinite(p->y[i]) || !isfinite(p->z[i]))
            return fault(RR_ERR_NONFINITE, k, i, which, point);
        if (fabs(p->y[i]) > RR_PROFILE_MAX_COORD || fabs(p->z[i]) > RR_PROFILE_MAX_COORD)
            return fault(RR_ERR_PARAM, k, i, which, point);
        if (i > 0 && !(p->y[i] > p->y[i - 1]))        /* vertical or overhanging */
            return fault(RR_ERR_GEOMETRY, k, i, which, point);
        if (i > 0 && p->y[i] - p->y[i - 1] > RR_PROFILE_MAX_GAP)
            return fault(RR_ERR_GEOMETRY, k, i, which, point);
    }
    lo = p->y[0];
    hi = p->y[p->n - 1];
    if (!(hi - lo >= RR_PROFILE_MIN_WIDTH))
        return fault(RR_ERR_PARAM, k, -1, which, point);
    return fault(RR_OK, -1, -1, which, point);
}

int rr_rig_profiles_check(const rr_rig_profiles *pr, int *which, int *point)
{
    const double v[3] = {pr ? pr->wheel_scale : 0.0, pr ? pr->roller_scale : 0.0,
                         pr ? pr->gauge : 0.0};
    const int roller_given = pr && (pr->roller.n != 0 || pr->roller_right.n != 0);
    int k, st;
    if (!pr)
        return fault(RR_ERR_NULL, -1, -1, which, point);
    if (!rr_all_finite(v, roller_given ? 3 : 2))
        return fault(RR_ERR_NONFINITE, -1, -1, which, point);
    if (!(pr->wheel_scale > 0.0) || !(pr->roller_scale > 0.0)
        || (roller_given && !(pr->gauge > 0.0)))
        return fault(RR_ERR_PARAM, -1, -1, which, point);
    for (k = 0; k < 4; k++) {
        const rr_profile_points *p = slot_of(pr, k);
        if (p->n < 0)                         /* said to be given, and not */
            return fault(RR_ERR_NULL, k, -1, which, point);
        if (p->n != 0 && (st = points_check(p, k, which, point)) != RR_OK)
            return st;
    }
    return fault(RR_OK, -1, -1, which, point);
}

/* The points a slot's table side uses: its own (given), the analytic
 * profile (a left slot not given) or the left's (a right slot not given). */
static int slot_points(const rr_rig_profiles *pr, int k)
{
    const rr_profile_points *p = slot_of(pr, k);
    return p->n != 0 ? p->n : k < 2 ? RR_RIG_PROFILE_POINTS : 0;
}

long rr_rig_profiles_work_len(const rr_rig_profiles *pr)
{
    long len = 0, most = 0;
    int k;
    if (!pr)
        return 0;
    for (k = 0; k < 4; k++) {
        const int n = slot_points(pr, k);
        if (n != 0 && !count_ok(n))
            return 0;
        len += 4L * n;                       /* y, z (scaled or analytic), zup, m */
        most = n > most ? n : most;
    }
    return len + 4L * most;                  /* rr_profile_surface's scratch */
}

int rr_rig_table_build_profiles(const rr_rig_geometry *g, const rr_rig_profiles *pr,
                                double *data, long data_len, double *work, long work_len,
                                rr_contact_table *t, double *bad_y)
{
    return rr_rig_table_build_profiles_rows(g, pr, data, data_len, work, work_len, 0,
                                            g ? g->table_rows : 0, t, bad_y);
}

/* A side's surface: the slot's points (scaled into y, z) or the analytic
 * profile, then rr_profile_surface; s the surface as the geometry reads it. */
static int side_surface(const rr_rig_geometry *g, const rr_profile_points *given, double scale,
                        int roller, double *y, double *z, double *zup, double *m,
                        double *scratch, rr_spline *s)
{
    rr_profile_points p;
    int i, st;
    if (given->n != 0) {
        for (i = 0; i < given->n; i++) {
            y[i] = scale * given->y[i];
            z[i] = scale * given->z[i];
        }
        p.n = given->n;
        p.end = given->end;
    } else {
        const double hw = g->profile_half_width;
        st = roller ? rr_profile_crowned(g->crown_radius, -hw, hw, RR_RIG_PROFILE_POINTS, y, z)
                    : rr_profile_conical(g->cone_angle, -hw, hw, RR_RIG_PROFILE_POINTS, y, z);
        if (st != RR_OK)
            return st;
        p.n = RR_RIG_PROFILE_POINTS;
        p.end = RR_SPLINE_NOT_A_KNOT;
    }
    p.y = y;
    p.z = z;
    if ((st = rr_profile_surface(&p, zup, m, scratch)) != RR_OK)
        return st;
    s->n = p.n;
    s->s = y;
    s->z = zup;
    s->m = m;
    return RR_OK;
}

int rr_rig_table_build_profiles_rows(const rr_rig_geometry *g, const rr_rig_profiles *pr,
                                     double *data, long data_len, double *work, long work_len,
                                     int i0, int i1, rr_contact_table *t, double *bad_y)
{
    rr_spline surf[4];
    rr_wheel_roller pair[2];
    rr_search_opts o;
    double *at, *scratch;
    long need;
    int k, st;

    if (bad_y)
        *bad_y = NAN;
    if (!g || !t || !pr)
        return RR_ERR_NULL;
    if ((st = rr_rig_profiles_check(pr, NULL, NULL)) != RR_OK)
        return st;
    if ((st = check_geometry(g)) != RR_OK)
        return st;
    need = rr_rig_profiles_work_len(pr);
    if (!data || !work || data_len < rr_rig_table_data_len(g) || work_len < need)
        return RR_ERR_WORKSPACE;
    /* work: per slot built, y, z, zup, m of its points; then the scratch */
    at = work;
    {
        long most = 0;
        for (k = 0; k < 4; k++)
            most = slot_points(pr, k) > most ? slot_points(pr, k) : most;
        scratch = work + (need - 4L * most);
    }
    for (k = 0; k < 4; k++) {
        const int n = slot_points(pr, k);
        const int roller = k == RR_RIG_ROLLER || k == RR_RIG_ROLLER_RIGHT;
        if (n == 0) {
            surf[k] = surf[k - 2];            /* a right slot: the left's */
            continue;
        }
        st = side_surface(g, slot_of(pr, k), roller ? pr->roller_scale : pr->wheel_scale,
                          roller, at, at + n, at + 2L * n, at + 3L * n, scratch, &surf[k]);
        if (st != RR_OK)
            return st;
        at += 4L * n;
    }
    for (k = 0; k < 2; k++) {
        const int roller_given = slot_of(pr, k ? RR_RIG_ROLLER_RIGHT : RR_RIG_ROLLER)->n != 0
                              || pr->roller.n != 0;
        pair[k].wheel = surf[k ? RR_RIG_WHEEL_RIGHT : RR_RIG_WHEEL];
        pair[k].roller = surf[k ? RR_RIG_ROLLER_RIGHT : RR_RIG_ROLLER];
        pair[k].r0 = g->wheel_radius;
        pair[k].R0 = g->roller_radius;
        pair[k].wheel_y = g->contact_half_spacing;
        /* a real roller's gauge point at half the gauge; the crown under the contact */
        pair[k].roller_y = roller_given ? 0.5 * pr->gauge : g->contact_half_spacing;
        pair[k].side = k == 0 ? 1 : -1;
    }
    rr_search_opts_default(&o);
    t->y0 = -g->table_half_range;
    t->dy = (g->table_half_range - -g->table_half_range) / (double)(g->table_rows - 1);
    t->n = g->table_rows;
    t->data = data;
    return rr_contact_table_build_rows(&pair[0], &pair[1], &o, t, i0, i1, bad_y);
}
