/* rr_geometry.c - wheel-roller contact search, wheelset pose, contact tables. */
#include <float.h>
#include <stddef.h>
#include <math.h>
#include "util/rr_common.h"
#include "geometry/rr_geometry.h"
#include "contact/rr_hertz.h"

/* Newton iterations: the refinement and the pose converge in a few. */
#define MAX_ITER 50

void rr_search_opts_default(rr_search_opts *o)
{
    if (!o)
        return;
    o->nsamples = 400;
    o->two_point_tol = 1e-4;
    o->two_point_sep = 2e-3;
}

/* A wheel profile point mapped into the rig, with the roller below it. */
typedef struct {
    double Y, Z;      /* rig coordinates of the wheel point */
    double dY, dZ;    /* their derivatives along s */
    double ddY, ddZ;
    double zw1, zw2;  /* wheel slope and second derivative */
    double sr;        /* roller coordinate below */
    double zr, zr1, zr2;
    double gap, g1, g2;   /* gap and its derivatives along s */
    int kw, kr;           /* spline interval hints */
} probe;

/* Map wheel profile coordinate s; returns 0, or a status if s falls off
 * either profile.  q->kw, q->kr carry the spline intervals from call to
 * call (a scan along s finds them in O(1)).  deriv 0: the place and the gap
 * alone (Y, Z, sr, zr, gap: the same doubles), all a scan compares; the
 * derivatives took 16 % of a wheelset's contact search (6 % of its time). */
static int probe_at(const rr_wheel_roller *p, double y_ws, double z_ws, double c, double sn,
                    double s, int deriv, probe *q)
{
    double zw, dsr, ddsr;
    int st = rr_spline_eval_at(&p->wheel, s, &q->kw, &zw, deriv ? &q->zw1 : NULL,
                               deriv ? &q->zw2 : NULL);
    if (st)
        return st;
    {
        const double Yl = p->side * (p->wheel_y + s), Zl = -p->r0 + zw;
        q->Y = y_ws + Yl * c - Zl * sn;
        q->Z = z_ws + Yl * sn + Zl * c;
    }
    q->sr = p->side * q->Y - p->roller_y;
    st = rr_spline_eval_at(&p->roller, q->sr, &q->kr, &q->zr, deriv ? &q->zr1 : NULL,
                           deriv ? &q->zr2 : NULL);
    if (st)
        return st;
    q->gap = q->Z - q->zr;
    if (!deriv)
        return RR_OK;
    q->dY = p->side * c - q->zw1 * sn;
    q->dZ = p->side * sn + q->zw1 * c;
    q->ddY = -q->zw2 * sn;
    q->ddZ = q->zw2 * c;
    dsr = p->side * q->dY;
    ddsr = p->side * q->ddY;
    q->g1 = q->dZ - q->zr1 * dsr;
    q->g2 = q->ddZ - q->zr2 * dsr * dsr - q->zr1 * ddsr;
    return RR_OK;
}

static void point_nan(rr_contact_point *c)
{
    c->y = c->z = c->s_wheel = c->s_roller = c->r = c->R = c->delta = NAN;
    c->A = c->B = c->gap = c->y2 = c->gap2 = NAN;
    c->ha = c->hb = c->hd = NAN;
    c->two_point = 0;
}

/* What a caller can get wrong in a pair or the search options. */
static int pair_check(const rr_wheel_roller *p)
{
    int st;
    if (!p)
        return RR_ERR_NULL;
    if ((st = rr_spline_check(&p->wheel)) != RR_OK || (st = rr_spline_check(&p->roller)) != RR_OK)
        return st;
    if (!isfinite(p->r0) || !isfinite(p->R0) || !isfinite(p->wheel_y) || !isfinite(p->roller_y))
        return RR_ERR_NONFINITE;
    if (!(p->r0 > 0.0) || !(p->R0 > 0.0) || (p->side != 1 && p->side != -1))
        return RR_ERR_PARAM;
    return RR_OK;
}

static int opts_check(const rr_search_opts *o)
{
    if (!o)
        return RR_ERR_NULL;
    if (o->nsamples < 3 || o->nsamples > RR_SEARCH_MAX_SAMPLES
        || !(o->two_point_tol >= 0.0) || !(o->two_point_sep >= 0.0)
        || !isfinite(o->two_point_tol) || !isfinite(o->two_point_sep))
        return RR_ERR_PARAM;
    return RR_OK;
}

/* Refine a sampled minimum at sample s: Newton on the gap's slope, kept
 * inside the neighbouring samples (h apart), a step taken only where the gap
 * does not rise (to its rounding): a full step from a sample near one
 * minimum could leap into the next basin.  Where the gap is concave the step
 * goes downhill: stopping there reported a point that is no minimum while
 * the bodies overlapped beyond it (a coarse scan, the wheel's flange root on
 * the gauge corner).  Returns the point's s with *q probed there, or NAN. */
static double refine(const rr_wheel_roller *p, double y_ws, double z_ws, double c, double sn,
                     double s, double h, probe *q)
{
    const double s0 = p->wheel.s[0], s1 = p->wheel.s[p->wheel.n - 1];
    double lo = s - h, hi = s + h;
    int it;
    if (lo < s0) lo = s0;
    if (hi > s1) hi = s1;
    if (probe_at(p, y_ws, z_ws, c, sn, s, 1, q) != RR_OK)
        return NAN;                  /* a sample probed before: not reached */
    for (it = 0; it < MAX_ITER; it++) {
        /* the gap's rounding; a Newton step whose predicted fall is below
         * it is the end game, taken on the slope alone */
        const double noise = 8.0 * DBL_EPSILON * (fabs(q->Z) + fabs(q->zr));
        double ds, sn_;
        int half, taken = 0;
        if (q->g2 > 0.0)
            ds = q->g1 / q->g2;
        else if (q->g1 != 0.0)       /* concave here: downhill, halving */
            ds = q->g1 > 0.0 ? hi - lo : lo - hi;
        else
            break;
        for (half = 0; half < 40 && !taken; half++, ds *= 0.5) {
            probe qn = *q;
            sn_ = s - ds;
            if (sn_ < lo) sn_ = lo;
            if (sn_ > hi) sn_ = hi;
            if (fabs(sn_ - s) < 1e-15 * (1.0 + fabs(s)))
                break;               /* converged, or no step left */
            if (probe_at(p, y_ws, z_ws, c, sn, sn_, 1, &qn) == RR_OK
                && (qn.gap <= q->gap + noise
                    || (q->g2 > 0.0 && 0.5 * q->g1 * (s - sn_) <= 64.0 * noise))) {
                s = sn_;
                *q = qn;
                taken = 1;
            }
        }
        if (!taken)
            break;
    }
    return s;
}

/* The point's place, the wheel's profile coordinate s probed (q): where
 * it is, its gap and contact angle (the search's and a Newton step's). */
static void place(const probe *q, double s, rr_contact_point *out)
{
    out->y = q->Y;
    out->z = q->zr;
    out->s_wheel = s;
    out->s_roller = q->sr;
    out->gap = q->gap;
    out->delta = atan(q->zr1);
}

/* rr_contact_search on a pair and options already checked (a pose's
 * Newton searches several times; the profiles' check cost a tenth) */
static int search(const rr_wheel_roller *p, double y_ws, double z_ws, double roll,
                  const rr_search_opts *o, rr_contact_point *out)
{
    double c, sn, s0, s1;
    int ns;
    double best = INFINITY, second = INFINITY, sbest = 0.0, ybest = 0.0, ysecond = NAN;
    double ssecond = 0.0;
    double prev2 = INFINITY, prev1 = INFINITY, sprev1 = 0.0, yprev1 = 0.0;
    double s, k_w, k_r;
    probe q;
    int i, ok = 0;

    q.kw = q.kr = -1;
    if (!isfinite(y_ws) || !isfinite(z_ws) || !isfinite(roll)) {
        point_nan(out);
        return RR_ERR_NONFINITE;
    }
    c = cos(roll);
    sn = sin(roll);
    s0 = p->wheel.s[0];
    s1 = p->wheel.s[p->wheel.n - 1];
    ns = o->nsamples;
    /* coarse scan: the global minimum of the gap, and the deepest other
     * local minimum at least two_point_sep away from it */
    for (i = 0; i <= ns; i++) {
        const double si = s0 + (s1 - s0) * i / ns;
        double g = INFINITY, y = 0.0;
        if (probe_at(p, y_ws, z_ws, c, sn, si, 0, &q) == RR_OK) {
            g = q.gap;
            y = q.Y;
            ok = 1;
        }
        /* the previous sample is a local minimum if below both neighbours */
        if (i >= 1 && prev1 < prev2 && prev1 <= g) {
            if (prev1 < best) {
                if (fabs(yprev1 - ybest) > o->two_point_sep || best == INFINITY) {
                    second = best;
                    ysecond = ybest;
                    ssecond = sbest;
                }
                best = prev1;
                sbest = sprev1;
                ybest = yprev1;
            } else if (prev1 < second && fabs(yprev1 - ybest) > o->two_point_sep) {
                second = prev1;
                ysecond = yprev1;
                ssecond = sprev1;
            }
        }
        prev2 = prev1;
        prev1 = g;
        sprev1 = si;
        yprev1 = y;
    }
    if (!ok || best == INFINITY) {
        point_nan(out);
        return RR_ERR_GEOMETRY;     /* the wheel is off its roller */
    }
    if (second < INFINITY && fabs(ysecond - ybest) <= o->two_point_sep)
        second = INFINITY;

    /* refine the deepest sampled minimum and the deepest other one: gaps a
     * fraction of a micrometre apart are below what the samples resolve,
     * so the refined gaps decide which is the contact (S1002 at y = 4.9 mm:
     * two minima 10 mm apart, 0.36 um deep apart) */
    s = refine(p, y_ws, z_ws, c, sn, sbest, (s1 - s0) / ns, &q);
    if (isnan(s)) {
        point_nan(out);
        return RR_ERR_GEOMETRY;
    }
    if (second < INFINITY) {
        probe q2 = q;
        const double s2 = refine(p, y_ws, z_ws, c, sn, ssecond, (s1 - s0) / ns, &q2);
        if (isnan(s2) || fabs(q2.Y - q.Y) <= o->two_point_sep) {
            second = INFINITY;       /* both refined to one minimum */
        } else if (q2.gap < q.gap) {
            second = q.gap;
            ysecond = q.Y;
            s = s2;
            q = q2;
        } else {
            second = q2.gap;
            ysecond = q2.Y;
        }
    }
    place(&q, s, out);
    {
        double zw;
        rr_spline_eval(&p->wheel, s, &zw, 0, 0);
        out->r = p->r0 - zw;
    }
    out->R = p->R0 + q.zr;
    /* profile curvatures, convex toward the other body positive */
    k_w = q.zw2 / pow(1.0 + q.zw1 * q.zw1, 1.5);
    k_r = -q.zr2 / pow(1.0 + q.zr1 * q.zr1, 1.5);
    out->A = 0.5 * cos(out->delta) * (1.0 / out->r + 1.0 / out->R);
    out->B = 0.5 * (k_w + k_r);
    out->two_point = second - q.gap <= o->two_point_tol;
    out->y2 = out->two_point ? ysecond : NAN;
    out->gap2 = out->two_point ? second : NAN;
    out->ha = out->hb = out->hd = NAN;
    if (!(out->B > 0.0) || !(out->r > 0.0) || !(out->R > 0.0))
        return RR_ERR_GEOMETRY;
    {
        rr_hertz_result h;
        if (rr_hertz(out->A, out->B, 1.0, 1.0, &h) != RR_OK)
            return RR_ERR_GEOMETRY;
        out->ha = h.a;
        out->hb = h.b;
        out->hd = h.delta;
    }
    return RR_OK;
}

int rr_contact_search(const rr_wheel_roller *p, double y_ws, double z_ws, double roll,
                      const rr_search_opts *o, rr_contact_point *out)
{
    int st;
    if (!out)
        return RR_ERR_NULL;
    if ((st = pair_check(p)) != RR_OK || (st = opts_check(o)) != RR_OK) {
        point_nan(out);
        return st;
    }
    return search(p, y_ws, z_ws, roll, o, out);
}

/* A Newton step's contact point (out from the step before): refined from
 * its last s alone at the new pose (z, roll), without the scan, within a
 * sample spacing of it (the pose moves little from step to step, the
 * minimum with it); out's place.  RR_ERR_GEOMETRY where
 * it leaves a profile. */
static int track(const rr_wheel_roller *p, double y_ws, double z, double roll,
                 const rr_search_opts *o, rr_contact_point *out)
{
    const double s0 = p->wheel.s[0], s1 = p->wheel.s[p->wheel.n - 1];
    probe q;
    double s;
    q.kw = q.kr = -1;
    s = refine(p, y_ws, z, cos(roll), sin(roll), out->s_wheel, (s1 - s0) / o->nsamples, &q);
    if (isnan(s))
        return RR_ERR_GEOMETRY;
    place(&q, s, out);
    return RR_OK;
}

/* d gap / d roll of a contact point: the wheel turns about its axle at
 * (y_ws, z), its point at (y, Z) rises by (y - y_ws) droll and moves
 * across by -(Z - z) droll, along a surface of the roller's slope there
 * (side tan delta in the rig): the lateral part, r tan delta, is 2 % of
 * the arm on a tread and near all of it on a flange.  With the arm alone
 * the pose's Newton contracted by that ratio a step: seven steps to
 * 1e-13 m on a tread where two now do, and on S1002's flange (6.4 mm out)
 * not within 50 (the axle 6 um off) */
static double gap_per_roll(const rr_wheel_roller *p, const rr_contact_point *q, double y_ws,
                           double z)
{
    return (q->y - y_ws) + p->side * tan(q->delta) * (q->z + q->gap - z);
}

int rr_wheelset_contact(const rr_wheel_roller *left, const rr_wheel_roller *right, double y_ws,
                        const rr_search_opts *o, rr_wheelset_pose *pose,
                        rr_contact_point *cl, rr_contact_point *cr)
{
    double z, roll = 0.0;
    int it, st = RR_OK, st_l = RR_OK, st_r = RR_OK, found = 0, scan = 1, always = 0;

    if (!pose || !cl || !cr)
        return RR_ERR_NULL;
    if ((st = pair_check(left)) != RR_OK || (st = pair_check(right)) != RR_OK
        || (st = opts_check(o)) != RR_OK) {
        pose->z = pose->roll = NAN;
        point_nan(cl);
        point_nan(cr);
        return st;
    }
    z = 0.5 * (left->r0 + right->r0);

    /* Newton on (z, roll): a gap moves one-for-one with z and by
     * j = gap_per_roll with roll; the 2 x 2 system dz + j_l droll = -g_l,
     * dz + j_r droll = -g_r is solved exactly.  A conformal point (B <= 0)
     * still has a gap: only a missing gap stops.  The first step scans, the
     * next ones track its points (track), and the pose they settle is
     * scanned again: found where the scans' points have no gap either
     * (on CONTACT's roller cases a third fewer instructions than a scan
     * every step; the pose within 3e-13 m of it) */
    for (it = 0; it < MAX_ITER; it++) {
        double droll, jl, jr;
        if (scan) {
            st = st_l = search(left, y_ws, z, roll, o, cl);
            if (!isfinite(cl->gap))
                break;
            st = st_r = search(right, y_ws, z, roll, o, cr);
            if (!isfinite(cr->gap))
                break;
        } else if (track(left, y_ws, z, roll, o, cl) != RR_OK
                   || track(right, y_ws, z, roll, o, cr) != RR_OK) {
            scan = always = 1;      /* off a profile: the scans from here */
            continue;
        }
        if (fabs(cl->gap) < 1e-13 && fabs(cr->gap) < 1e-13) {
            if (scan) {
                found = 1;          /* cl and cr are the final pose's points */
                break;
            }
            scan = 1;               /* the scans' minima at this pose */
            continue;
        }
        /* the points tracked from the first scan, until a scan at a pose
         * they settled finds other minima: the scans from there on */
        always |= scan && it > 0;
        scan = always;
        jl = gap_per_roll(left, cl, y_ws, z);
        jr = gap_per_roll(right, cr, y_ws, z);
        droll = -(cl->gap - cr->gap) / (jl - jr);
        /* dz from both rows' mean: the mirrored shift (sides swapped,
         * droll negated) then gives the same z bit for bit, where one
         * side's row alone rounds differently from the other's */
        z += -0.5 * (cl->gap + cr->gap) - 0.5 * (jl + jr) * droll;
        roll += droll;
    }
    if (!isfinite(cl->gap) || !isfinite(cr->gap)) {
        pose->z = pose->roll = NAN;
        point_nan(cl);
        point_nan(cr);
        return st < 0 ? st : RR_ERR_GEOMETRY;
    }
    pose->z = z;
    pose->roll = roll;
    /* the points of the final pose (where the last step moved it) */
    if (!found) {
        st_l = search(left, y_ws, z, roll, o, cl);
        st_r = st_l == RR_OK ? search(right, y_ws, z, roll, o, cr) : RR_OK;
    }
    st = st_l != RR_OK ? st_l : st_r;
    if (st < 0) {
        /* a point found but no Hertz ellipse (B <= 0): the pair fails whole */
        pose->z = pose->roll = NAN;
        point_nan(cl);
        point_nan(cr);
        return st;
    }
    /* a gap whose rounding exceeds 1e-9 m (an axle 1e300 m up: the
     * difference of two such heights) cannot be brought to zero: no pose */
    if (!(8.0 * DBL_EPSILON * fabs(z) <= 1e-9)) {
        pose->z = pose->roll = NAN;
        point_nan(cl);
        point_nan(cr);
        return RR_ERR_RANGE;
    }
    if (fabs(cl->gap) > 1e-9 || fabs(cr->gap) > 1e-9)
        return RR_WARN_NOT_CONVERGED;
    return RR_OK;
}

/* Quantities stored per side, in this order, then z and roll. */
#define NSIDE 13
#define ROW (2 * NSIDE + 2)
#if ROW != RR_CONTACT_TABLE_ROW
#error "RR_CONTACT_TABLE_ROW does not match the row layout"
#endif

long rr_contact_table_len(int n)
{
    return n > 0 ? (long)n * ROW : 0;
}

/* What a caller can get wrong in a table: 0, RR_ERR_NULL, RR_ERR_PARAM. */
static int table_check(const rr_contact_table *t)
{
    if (!t || !t->data)
        return RR_ERR_NULL;
    if (t->n < 2 || !isfinite(t->y0) || !isfinite(t->dy) || !(t->dy > 0.0)
        || !isfinite(t->y0 + (t->n - 1) * t->dy))
        return RR_ERR_PARAM;
    return RR_OK;
}

static void store(double *d, const rr_contact_point *c)
{
    d[0] = c->y; d[1] = c->z; d[2] = c->s_wheel; d[3] = c->s_roller; d[4] = c->r;
    d[5] = c->R; d[6] = c->delta; d[7] = c->A; d[8] = c->B; d[9] = c->two_point;
    d[10] = c->ha; d[11] = c->hb; d[12] = c->hd;
}

/* One side of rows a, b interpolated at fraction f; 0, or RR_ERR_RANGE if
 * the caller's rows hold values that give no finite result. */
static int load(const double *a, const double *b, double f, rr_contact_point *c)
{
    double v[NSIDE];
    int k;
    for (k = 0; k < NSIDE; k++)
        v[k] = a[k] + f * (b[k] - a[k]);
    c->y = v[0]; c->z = v[1]; c->s_wheel = v[2]; c->s_roller = v[3]; c->r = v[4];
    c->R = v[5]; c->delta = v[6]; c->A = v[7]; c->B = v[8];
    c->ha = v[10]; c->hb = v[11]; c->hd = v[12];
    c->two_point = (f < 0.5 ? a[9] : b[9]) != 0.0;
    c->gap = 0.0;
    c->y2 = c->gap2 = NAN;
    return rr_all_finite(v, NSIDE) ? RR_OK : RR_ERR_RANGE;
}

int rr_contact_table_build(const rr_wheel_roller *left, const rr_wheel_roller *right,
                           const rr_search_opts *o, rr_contact_table *t, double *bad_y)
{
    int st = t ? RR_OK : RR_ERR_NULL;
    return st == RR_OK ? rr_contact_table_build_rows(left, right, o, t, 0, t->n, bad_y) : st;
}

int rr_contact_table_build_rows(const rr_wheel_roller *left, const rr_wheel_roller *right,
                                const rr_search_opts *o, rr_contact_table *t, int i0, int i1,
                                double *bad_y)
{
    int i, st;
    if ((st = table_check(t)) != RR_OK)
        return st == RR_ERR_NULL && t ? RR_ERR_WORKSPACE : st;
    if (i0 < 0 || i1 > t->n || i0 > i1)
        return RR_ERR_PARAM;
    if ((st = pair_check(left)) != RR_OK || (st = pair_check(right)) != RR_OK
        || (st = opts_check(o)) != RR_OK)
        return st;
    for (i = i0; i < i1; i++) {
        const double y = t->y0 + i * t->dy;
        double *row = t->data + (long)i * ROW;
        rr_wheelset_pose pose;
        rr_contact_point cl, cr;
        st = rr_wheelset_contact(left, right, y, o, &pose, &cl, &cr);
        if (st < 0) {
            if (bad_y)
                *bad_y = y;
            return st;
        }
        store(row, &cl);
        store(row + NSIDE, &cr);
        row[2 * NSIDE] = pose.z;
        row[2 * NSIDE + 1] = pose.roll;
    }
    return RR_OK;
}

/* The lookup's error path: NaN outputs, the status. */
static int lookup_fail(int st, rr_wheelset_pose *pose, rr_wheelset_pose *slope,
                       rr_contact_point *cl, rr_contact_point *cr)
{
    point_nan(cl);
    point_nan(cr);
    pose->z = pose->roll = NAN;
    if (slope)
        slope->z = slope->roll = NAN;
    return st;
}

int rr_contact_table_lookup(const rr_contact_table *t, double y_ws, rr_wheelset_pose *pose,
                            rr_wheelset_pose *slope, rr_contact_point *cl, rr_contact_point *cr)
{
    double pos, f;
    int i, st;
    const double *a, *b;

    if (!pose || !cl || !cr)
        return RR_ERR_NULL;
    if ((st = table_check(t)) != RR_OK)
        return lookup_fail(st, pose, slope, cl, cr);
    if (!isfinite(y_ws))
        return lookup_fail(RR_ERR_NONFINITE, pose, slope, cl, cr);
    /* inside: between the first and the last row's shifts as the build
     * computes them (y0 + i dy), both included; the division may put the
     * last row an ulp past n - 1 */
    if (y_ws < t->y0 || y_ws > t->y0 + (t->n - 1) * t->dy)
        return lookup_fail(RR_ERR_GEOMETRY, pose, slope, cl, cr);
    pos = fmin((y_ws - t->y0) / t->dy, t->n - 1);
    i = (int)pos;
    if (i > t->n - 2)
        i = t->n - 2;
    f = pos - i;
    a = t->data + (long)i * ROW;
    b = a + ROW;
    st = load(a, b, f, cl);
    if (load(a + NSIDE, b + NSIDE, f, cr) != RR_OK)
        st = RR_ERR_RANGE;
    pose->z = a[2 * NSIDE] + f * (b[2 * NSIDE] - a[2 * NSIDE]);
    pose->roll = a[2 * NSIDE + 1] + f * (b[2 * NSIDE + 1] - a[2 * NSIDE + 1]);
    if (slope) {
        slope->z = (b[2 * NSIDE] - a[2 * NSIDE]) / t->dy;
        slope->roll = (b[2 * NSIDE + 1] - a[2 * NSIDE + 1]) / t->dy;
    }
    if (st != RR_OK || !isfinite(pose->z) || !isfinite(pose->roll)
        || (slope && !(isfinite(slope->z) && isfinite(slope->roll))))
        return lookup_fail(RR_ERR_RANGE, pose, slope, cl, cr);   /* rows not a table's */
    return RR_OK;
}
