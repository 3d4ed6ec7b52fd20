/*
 * rr_gap.c - the undeformed distance of one wheel on its roller (rr_gap.h).
 *
 * The construction is rollerrig/geometry/patch.py's, step for step, so that
 * h agrees with it to rounding: the profiles sampled on numpy's linspace,
 * each cross-section the run of samples around the reference along which
 * its lateral coordinate in the plane is strictly monotonic, numpy.interp's
 * formula between samples.  What is computed differs only where the
 * answer cannot: a cross-section at x != 0 is walked from the reference
 * outward only as far as the grid's rows need (the run is the same as far
 * as it goes), and a column at -x is the one at x (the cross-sections
 * depend on x^2 alone).  The samples and cross-sections are
 * rr_gap_section.h's; this file builds the plane, the regions and h.
 */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "geometry/rr_gap.h"
#include "geometry/rr_gap_section.h"

/* Iterations of the weighted reference's angle and of the grid's growth
 * (patch.py's). */
#define WEIGHT_ITER 50
#define GROW_ITER 1000

void rr_gap_opts_default(rr_gap_opts *o)
{
    if (!o)
        return;
    o->reference = RR_GAP_WEIGHTED;
    o->s_roller = 0.0;
    o->delta = 0.0;
    o->approach = 0.0;
    o->cover = 1.5;
    o->n = 40;
    o->dx = 0.0;
    o->dy = 0.0;
    o->combine = 4e-3;
    o->keep = 0;
    o->keep_lo = o->keep_hi = 0.0;
    o->sample = 0.0;
}

/* The samples' spacing (patch.py's step): the one given, else RR_GAP_SAMPLE,
 * or a tenth of the smallest element given, at least RR_GAP_SAMPLE_MIN; 0
 * for sizes that are not finite and >= 0 or a spacing out of its range. */
static double sample_step(const rr_gap_opts *o)
{
    double m = 1.0;
    if (!isfinite(o->dx) || !isfinite(o->dy) || !(o->dx >= 0.0) || !(o->dy >= 0.0))
        return 0.0;
    if (o->sample != 0.0)
        return o->sample >= RR_GAP_SAMPLE_MIN && o->sample <= RR_GAP_SAMPLE_MAX ? o->sample : 0.0;
    if (o->dx > 0.0 && o->dx < m)
        m = o->dx;
    if (o->dy > 0.0 && o->dy < m)
        m = o->dy;
    return fmax(fmin(RR_GAP_SAMPLE, 0.1 * m), RR_GAP_SAMPLE_MIN);
}

/* Samples a window holds at most (its linspace count, one for rounding). */
static size_t window_samples(double step)
{
    return (size_t)ceil(2.0 * RR_GAP_WINDOW / step) + 3;
}

/* The workspace, arrays of a window's samples: four of samples, four of
 * sections, four of the weighted reference and its mask (the lateral scan
 * reuses these: carve_work). */
#define NARRAYS 13

size_t rr_gap_workspace_len(const rr_gap_opts *o)
{
    double step;
    if (!o || !((step = sample_step(o)) > 0.0))
        return 0;
    return NARRAYS * window_samples(step);
}

/* ---- the region's intervals ------------------------------------------------- */

typedef struct {
    int n;
    int a[RR_GAP_MAX_RUNS], b[RR_GAP_MAX_RUNS];   /* index runs [a, b) */
    double lo[RR_GAP_MAX_RUNS], hi[RR_GAP_MAX_RUNS];  /* as y intervals */
    int kept[RR_GAP_MAX_RUNS];
} runs;

/* The runs of mask over [0, n) and their y intervals (patch.py's _runs and
 * _group's tuples); RR_ERR_RANGE (why RUNS) beyond RR_GAP_MAX_RUNS. */
static int find_runs(const unsigned char *mask, const double *y, int n, runs *R,
                     rr_gap_patch *out)
{
    int i = 0;
    R->n = 0;
    while (i < n) {
        int j;
        if (!mask[i]) {
            i++;
            continue;
        }
        for (j = i; j < n && mask[j]; j++)
            ;
        if (R->n == RR_GAP_MAX_RUNS) {
            out->why = RR_GAP_RUNS;
            return RR_ERR_RANGE;
        }
        R->a[R->n] = i;
        R->b[R->n] = j;
        R->lo[R->n] = fmin(y[i], y[j - 1]);
        R->hi[R->n] = fmax(y[i], y[j - 1]);
        R->n++;
        i = j;
    }
    return RR_OK;
}

/* patch.py's _group: the run holding y_deep, and every run within combine
 * of the growing hull, to the fixed point (the order of the passes does
 * not change it); the hull in *lo, *hi. */
static void group_runs(runs *R, double y_deep, double combine, double *lo, double *hi)
{
    int i, grown = 1;
    for (i = 0; i < R->n; i++)
        R->kept[i] = 0;
    for (i = 0; i < R->n; i++)
        if (R->lo[i] <= y_deep && y_deep <= R->hi[i])
            break;
    if (i == R->n)
        i = 0;                      /* not reached: the deepest sample is in a run */
    *lo = R->lo[i];
    *hi = R->hi[i];
    while (grown) {
        grown = 0;
        for (i = 0; i < R->n; i++)
            if (!R->kept[i] && R->lo[i] - *hi <= combine && *lo - R->hi[i] <= combine) {
                *lo = fmin(*lo, R->lo[i]);
                *hi = fmax(*hi, R->hi[i]);
                R->kept[i] = 1;
                grown = 1;
            }
    }
}

/* keep = 1: every run (the mask held them within [klo, khi], the same
 * coordinate as the runs'), their hull in *lo, *hi (the deepest point of
 * the band is in one). */
static void keep_runs(runs *R, double klo, double khi, double *lo, double *hi)
{
    int i;
    *lo = INFINITY;
    *hi = -INFINITY;
    for (i = 0; i < R->n; i++) {
        R->kept[i] = R->hi[i] >= klo && R->lo[i] <= khi;
        if (R->kept[i]) {
            *lo = fmin(*lo, R->lo[i]);
            *hi = fmax(*hi, R->hi[i]);
        }
    }
}

/* ---- the weighted reference ------------------------------------------------- */

/* Per roller sample: its rig Y, the vertical gap g, and a, alpha (filled
 * where a weight needs them, NaN until then). */
typedef struct {
    double *Y, *g, *a, *alpha;
    unsigned char *mask;
} weights;

/* CONTACT's reference of a patch (patch.py's _weighted_reference, its
 * locate_interpen_1d and set_cpatch_reference): at the pose's vertical gap
 * g(Y) (shifted to least 0), the centre of pen = approach / cos(delta) - g
 * and the roller's mean inclination, each lateral strip weighted by the
 * integral over x of its squared interpenetration, pen^2.5 / sqrt(a),
 * a = (1/r + 1/R)/2, over the runs of pen > 0 grouped as the region's;
 * delta iterated.  rs, ws: the samples around the rigid contact point;
 * wsec: the wheel's section (scratch).  Returns the reference's roller
 * coordinate in *sr_out and its angle in *delta. */
static int weighted_reference(const plane *f, const samples *rs, section *wsec, double sr_P,
                              const rr_gap_opts *o, weights *W, double *sr_out,
                              double *delta, rr_gap_patch *out)
{
    const rr_wheel_roller *p = f->p;
    const double target = f->sigma * (p->roller_y + sr_P);
    plane id = *f;
    section run;
    walker w;
    cursor k;
    double best = INFINITY, gmin = INFINITY, sw = 0.0, swa = 0.0, swy = 0.0;
    int i, i0 = rs->k, i1 = -1, n, deep = 0, it, st;

    /* the wheel's cross-section in the rig's (Y, Z) at x = 0 (an identity
     * plane), its run around the sample nearest P's Y */
    id.P0 = id.P1 = 0.0;
    id.t2y = id.nz = 1.0;
    id.t2z = id.ny = 0.0;
    wsec->k0 = 0;
    walker_set(&id, wsec, 0.0, &w);
    walk_points(&w, 0, wsec->q->k - 1);
    for (i = 0; i < wsec->q->k; i++) {
        const double d = fabs(wsec->yc[i] - target);
        if (d < best) {
            best = d;
            wsec->k0 = i;
        }
    }
    if ((st = sec_walk(&id, wsec, 0.0, 0.0, 0.0, 1, out)) != RR_OK)
        return st;
    /* the roller's samples below it (their Y is monotonic in the index) */
    for (i = 0; i < rs->k; i++) {
        W->Y[i] = f->sigma * (p->roller_y + rs->s[i]);
        if (W->Y[i] >= sec_first(wsec) && W->Y[i] <= sec_last(wsec)) {
            i0 = i < i0 ? i : i0;
            i1 = i;
        }
    }
    if (i1 < i0) {
        out->why = RR_GAP_APART;
        return RR_ERR_GEOMETRY;
    }
    n = i1 - i0 + 1;
    cursor_set(wsec, &k);
    for (i = i0; i <= i1; i++) {
        W->g[i] = cursor_at(&k, W->Y[i]) - rs->z[i];      /* Y monotonic: the cursor's steps */
        W->a[i] = W->alpha[i] = NAN;
        if (o->keep && !(W->Y[i] >= o->keep_lo && W->Y[i] <= o->keep_hi))
            continue;
        if (W->g[i] < gmin) {
            gmin = W->g[i];
            deep = i;
        }
    }
    if (!isfinite(gmin)) {
        out->why = gmin == INFINITY && o->keep ? RR_GAP_KEEP : RR_GAP_WEIGHTS;
        return gmin == INFINITY && o->keep ? RR_ERR_GEOMETRY : RR_ERR_RANGE;
    }
    for (i = i0; i <= i1; i++)
        W->g[i] -= gmin;
    for (it = 0; it < WEIGHT_ITER; it++) {
        const double top = o->approach / cos(*delta);
        double lo, hi, nd;
        int r, done;
        runs R;
        for (i = 0; i < n; i++)
            W->mask[i] = top - W->g[i0 + i] > 0.0
                         && (!o->keep || (W->Y[i0 + i] >= o->keep_lo
                                          && W->Y[i0 + i] <= o->keep_hi));
        if ((st = find_runs(W->mask, W->Y + i0, n, &R, out)) != RR_OK)
            return st;
        if (o->keep)
            keep_runs(&R, o->keep_lo, o->keep_hi, &lo, &hi);
        else
            group_runs(&R, W->Y[deep], o->combine, &lo, &hi);
        sw = swa = swy = 0.0;
        for (r = 0; r < R.n; r++)
            for (i = i0 + R.a[r]; R.kept[r] && i < i0 + R.b[r]; i++) {
                const double pen = top - W->g[i];
                double w;
                if (isnan(W->a[i])) {
                    /* r at the wheel's point above (its coordinate by the run),
                     * R and the inclination at the roller's */
                    const double s_w = sec_interp(wsec, W->Y[i], wsec->q->s);
                    double zw, zr, dzr;
                    int hw = -1, hr = -1;
                    if (rr_spline_eval_at(&p->wheel, s_w, &hw, &zw, NULL, NULL) != RR_OK)
                        zw = NAN;
                    if (rr_spline_eval_at(&p->roller, rs->s[i], &hr, &zr, &dzr, NULL) != RR_OK)
                        dzr = NAN;
                    W->a[i] = 0.5 * (1.0 / (p->r0 - zw) + 1.0 / (p->R0 + rs->z[i]));
                    W->alpha[i] = atan(dzr);
                }
                w = pen * pen * sqrt(pen) / sqrt(W->a[i]);
                sw += w;
                swa += w * W->alpha[i];
                swy += w * W->Y[i];
            }
        if (!(sw > 0.0) || !isfinite(sw) || !isfinite(swa) || !isfinite(swy)) {
            out->why = RR_GAP_WEIGHTS;
            return RR_ERR_RANGE;
        }
        nd = swa / sw;
        done = fabs(nd - *delta) < 1e-13;
        *delta = nd;
        if (done)
            break;
    }
    /* the roller's coordinate at the centre: numpy.interp over the samples
     * in increasing Y (a "section" of the roller in rig Y) */
    run.yc = W->Y;
    run.a = i0;
    run.b = i1;
    run.dir = n > 1 && W->Y[i1] < W->Y[i0] ? -1 : 1;
    run.hint = 0;
    *sr_out = sec_interp(&run, swy / sw, rs->s);
    return RR_OK;
}

/* ---- the build -------------------------------------------------------------- */

/* Every number of the frame NaN, counts 0: the state before a build. */
static void patch_nan(rr_gap_patch *o)
{
    int k;
    memset(o, 0, sizeof *o);
    o->grid.dx = o->grid.dy = o->grid.x0 = o->grid.y0 = NAN;
    for (k = 0; k < 3; k++)
        o->point[k] = o->wheel_point[k] = o->t1[k] = o->t2[k] = o->n[k] = NAN;
    o->delta = o->s_roller = o->s_wheel = o->r = o->R = o->pen = o->level = NAN;
    o->lo = o->hi = o->plane_lo = o->plane_hi = o->x_t = o->half_length = NAN;
    o->need_mx = o->need_my = o->step = o->off_s = o->off_lo = o->off_hi = NAN;
}

/* What a caller can get wrong: the site, the pair, the options. */
static int check_inputs(const rr_gap_site *site, const rr_gap_opts *o)
{
    const rr_wheel_roller *p = site->pair;
    const double v[] = {site->y_ws, site->z, site->roll, site->s_roller, site->s_wheel,
                        site->delta, p->r0, p->R0, p->wheel_y, p->roller_y, o->approach,
                        o->cover, o->dx, o->dy, o->combine, o->sample};
    int st;
    if ((st = rr_spline_check(&p->wheel)) != RR_OK || (st = rr_spline_check(&p->roller)) != RR_OK)
        return st;
    if (!rr_all_finite(v, RR_COUNTOF(v)))
        return RR_ERR_NONFINITE;
    if (o->reference == RR_GAP_GIVEN && !(isfinite(o->s_roller) && isfinite(o->delta)))
        return RR_ERR_NONFINITE;
    if (!(p->r0 > 0.0) || !(p->R0 > 0.0) || (p->side != 1 && p->side != -1)
        || (o->reference != RR_GAP_WEIGHTED && o->reference != RR_GAP_POINT
            && o->reference != RR_GAP_GIVEN)
        || (o->reference == RR_GAP_GIVEN && !(fabs(o->delta) < 0.5 * RR_PI))
        || !(fabs(site->delta) < 0.5 * RR_PI)
        || !(o->approach > 0.0) || !(o->cover >= 1.0) || o->n < 4 || o->n > RR_GAP_MAX_N
        || !(o->dx >= 0.0) || !(o->dy >= 0.0) || !(o->combine >= 0.0)
        || (o->keep != 0 && o->keep != 1)
        || !(o->sample == 0.0 || (o->sample >= RR_GAP_SAMPLE_MIN && o->sample <= RR_GAP_SAMPLE_MAX)))
        return RR_ERR_PARAM;
    if (o->keep && !(isfinite(o->keep_lo) && isfinite(o->keep_hi)))
        return RR_ERR_NONFINITE;
    if (o->keep && !(o->keep_lo < o->keep_hi))
        return RR_ERR_PARAM;
    return RR_OK;
}

/* The workspace's arrays (NARRAYS of kmax): the samples of both profiles,
 * both sections, the weighted reference's four and its mask; the lateral
 * scan reuses the reference's arrays after it (2 kmax positions, 2 kmax
 * gaps, the mask's 8 kmax bytes). */
typedef struct {
    samples rs, ws;
    double *ryc, *rze, *wyc, *wze;
    weights W;
    double *hy, *yf;
    unsigned char *mask;
    size_t kmax, nscan;
} carve;

static void carve_work(double *work, size_t kmax, carve *c)
{
    c->kmax = kmax;
    c->rs.s = work;
    c->rs.z = work + kmax;
    c->rs.sp = c->ws.sp = NULL;
    c->ws.s = work + 2 * kmax;
    c->ws.z = work + 3 * kmax;
    c->ryc = work + 4 * kmax;
    c->rze = work + 5 * kmax;
    c->wyc = work + 6 * kmax;
    c->wze = work + 7 * kmax;
    c->W.Y = work + 8 * kmax;
    c->W.g = work + 9 * kmax;
    c->W.a = work + 10 * kmax;
    c->W.alpha = work + 11 * kmax;
    c->W.mask = (unsigned char *)(work + 12 * kmax);
    c->hy = work + 8 * kmax;
    c->yf = work + 10 * kmax;
    c->mask = c->W.mask;
    c->nscan = 2 * kmax;
}

/* The columns i_lo..i_hi of h (x = i dx), rows j_lo..j_hi (y = j dy), into
 * h (row-major, mx columns); a column at -x is the one at x, one walk of
 * both sections each.  RR_ERR_GEOMETRY (why FOLD) where a column's
 * sections do not start at the reference (patch.py raises there too). */
static int fill_h(const plane *f, section *r, section *w, double dx, double dy, int i_lo,
                  int i_hi, int j_lo, int j_hi, double *h, rr_gap_patch *out)
{
    const int mx = i_hi - i_lo + 1;
    const double y_lo = dy * (double)j_lo, y_hi = dy * (double)j_hi;
    int i, j, st;
    for (i = i_lo; i <= i_hi; i++) {
        const int m = -i;
        const int twin = m >= i_lo && m <= i_hi && m != i;
        if (i < 0 && twin)
            continue;                        /* done with its mirror */
        if ((st = sec_walk(f, r, dx * (double)i, y_lo, y_hi, 0, out)) != RR_OK
            || (st = sec_walk(f, w, dx * (double)i, y_lo, y_hi, 0, out)) != RR_OK)
            return st;
        gap_many(r, w, NULL, dy, j_lo, j_hi - j_lo + 1, h + (i - i_lo), (size_t)mx);
        if (twin)
            for (j = j_lo; j <= j_hi; j++)
                h[(size_t)(j - j_lo) * mx + (m - i_lo)] = h[(size_t)(j - j_lo) * mx + (i - i_lo)];
    }
    return RR_OK;
}

/* The grid's element counts for index bounds given as doubles (bounds far
 * beyond an int's are counted before any is converted): RR_ERR_GRID (why
 * TOO_MANY) beyond RR_EXACT_MAX_GRID a side. */
static int bounded(double fi_lo, double fi_hi, double fj_lo, double fj_hi, rr_gap_patch *out)
{
    out->need_mx = fi_hi - fi_lo + 1.0;
    out->need_my = fj_hi - fj_lo + 1.0;
    if (!(out->need_mx <= RR_EXACT_MAX_GRID) || !(out->need_my <= RR_EXACT_MAX_GRID)) {
        out->why = RR_GAP_TOO_MANY;
        return RR_ERR_GRID;
    }
    return RR_OK;
}

/* The frame: P, t1, t2, n and the reference's numbers into out. */
static void frame_out(const plane *f, double delta, double sr_P, double sw_P, rr_gap_patch *out)
{
    out->delta = delta;
    out->s_roller = sr_P;
    out->s_wheel = sw_P;
    out->point[0] = 0.0;
    out->point[1] = f->P0;
    out->point[2] = f->P1;
    out->t1[0] = 1.0;
    out->t1[1] = out->t1[2] = 0.0;
    out->t2[0] = 0.0;
    out->t2[1] = f->t2y;
    out->t2[2] = f->t2z;
    out->n[0] = 0.0;
    out->n[1] = f->ny;
    out->n[2] = f->nz;
}

/* The plane through the reference (sr_P, delta) and where its normal meets
 * the wheel (patch.py's sections(), wheel_at(0), sections() again): the
 * roller's samples around sr_P, the wheel's around that point, both
 * sections at x = 0 in full, where they overlap in *lo, *hi. */
static int place_plane(plane *f, carve *c, section *rsec, section *wsec, double step,
                       double sr_P, double delta, double *sw_P, double *lo, double *hi,
                       rr_gap_patch *out)
{
    const rr_wheel_roller *p = f->p;
    double zP;
    int st;
    if (!(sr_P >= p->roller.s[0] && sr_P <= p->roller.s[p->roller.n - 1])) {
        out->why = RR_GAP_OFF_PROFILE;       /* P lies on the roller's profile */
        out->off_body = 0;
        out->off_s = sr_P;
        out->off_lo = p->roller.s[0];
        out->off_hi = p->roller.s[p->roller.n - 1];
        return RR_ERR_GEOMETRY;
    }
    if ((st = take_samples(&p->roller, sr_P, step, c->kmax, &c->rs, out, 0)) != RR_OK)
        return st;
    rr_spline_eval(&p->roller, sr_P, &zP, NULL, NULL);
    plane_set(f, f->sigma * (p->roller_y + sr_P), zP, delta);
    rsec->k0 = c->rs.k0;
    wsec->k0 = c->ws.k0;
    if ((st = sections0(f, 1, rsec, wsec, lo, hi, out)) != RR_OK)
        return st;
    *sw_P = sec_interp(wsec, 0.0, c->ws.s);
    if ((st = take_samples(&p->wheel, *sw_P, step, c->kmax, &c->ws, out, 1)) != RR_OK)
        return st;
    wsec->k0 = c->ws.k0;
    /* the roller's section is the one just walked (its samples and the
     * plane the same): the wheel's alone again */
    return sections0(f, 0, rsec, wsec, lo, hi, out);
}

int rr_gap_build(const rr_gap_site *site, const rr_gap_opts *o, double *work, size_t work_len,
                 double *h, size_t h_len, rr_gap_patch *out)
{
    const rr_wheel_roller *p;
    double step, sr_P, sw_P, delta, plo, phi, lo, hi, level, hmin, df, r_P, R_P, x_t, xh;
    double dx, dy, fi_lo, fi_hi, fj_lo, fj_hi, hmin_grid, klo, khi;
    plane f;
    carve c;
    section rsec, wsec;
    runs R;
    int st, nf, i, j, k, deep = 0, it, i_lo, i_hi, j_lo, j_hi, mx, my;

    if (!out)
        return RR_ERR_NULL;
    patch_nan(out);
    if (!site || !site->pair || !o)
        return RR_ERR_NULL;
    if ((st = check_inputs(site, o)) != RR_OK)
        return st;
    step = sample_step(o);
    if (!work || work_len < rr_gap_workspace_len(o))
        return RR_ERR_WORKSPACE;
    out->step = step;
    p = site->pair;
    carve_work(work, window_samples(step), &c);
    f.p = p;
    f.sigma = p->side;
    f.y_ws = site->y_ws;
    f.z = site->z;
    f.cr = cos(site->roll);
    f.sr = sin(site->roll);
    rsec.q = &c.rs;
    rsec.body = 0;
    rsec.yc = c.ryc;
    rsec.ze = c.rze;
    wsec.q = &c.ws;
    wsec.body = 1;
    wsec.yc = c.wyc;
    wsec.ze = c.wze;

    /* the reference point and angle, the plane, where its normal meets the wheel */
    sr_P = o->reference == RR_GAP_GIVEN ? o->s_roller : site->s_roller;
    delta = o->reference == RR_GAP_GIVEN ? o->delta : site->delta;
    sw_P = site->s_wheel;
    if ((st = take_samples(&p->wheel, sw_P, step, c.kmax, &c.ws, out, 1)) != RR_OK)
        return st;
    if (o->reference == RR_GAP_WEIGHTED) {
        if ((st = take_samples(&p->roller, sr_P, step, c.kmax, &c.rs, out, 0)) != RR_OK
            || (st = weighted_reference(&f, &c.rs, &wsec, sr_P, o, &c.W, &sr_P, &delta,
                                        out)) != RR_OK)
            return st;
    }
    if ((st = place_plane(&f, &c, &rsec, &wsec, step, sr_P, delta, &sw_P, &plo, &phi, out))
        != RR_OK)
        return st;
    frame_out(&f, delta, sr_P, sw_P, out);
    out->plane_lo = plo;
    out->plane_hi = phi;
    {
        double zw, zr;
        rr_spline_eval(&p->wheel, sw_P, &zw, NULL, NULL);
        rr_spline_eval(&p->roller, sr_P, &zr, NULL, NULL);
        out->r = r_P = p->r0 - zw;
        out->R = R_P = p->R0 + zr;
    }

    /* the region to cover, at x = 0: the lateral scan and its intervals */
    level = out->level = o->cover * o->approach;
    {
        const double cnt = ceil((phi - plo) / step) + 1.0;
        if (!(cnt <= (double)c.nscan)) {
            out->why = RR_GAP_SCAN;
            return RR_ERR_RANGE;
        }
        nf = (int)cnt;
    }
    df = (phi - plo) / (double)(nf - 1);
    hmin = INFINITY;
    /* keep = 1: the keep interval in the plane's y (rig Y = P's + y t2y at
     * the surfaces, which lie within a gap's height of the plane there) */
    klo = (o->keep_lo - f.P0) / f.t2y;
    khi = (o->keep_hi - f.P0) / f.t2y;
    for (i = 0; i < nf; i++)
        c.yf[i] = i < nf - 1 ? (double)i * df + plo : phi;     /* numpy.linspace */
    gap_many(&rsec, &wsec, c.yf, 0.0, 0, nf, c.hy, 1);
    for (i = 0; i < nf; i++) {
        if (o->keep && !(c.yf[i] >= klo && c.yf[i] <= khi))
            continue;
        if (c.hy[i] < hmin) {
            hmin = c.hy[i];
            deep = i;
        }
    }
    if (o->keep && hmin == INFINITY) {
        out->why = RR_GAP_KEEP;
        return RR_ERR_GEOMETRY;
    }
    for (i = 0; i < nf; i++)
        c.mask[i] = c.hy[i] - hmin <= level
                    && (!o->keep || (c.yf[i] >= klo && c.yf[i] <= khi));
    if ((st = find_runs(c.mask, c.yf, nf, &R, out)) != RR_OK)
        return st;
    if (R.n == 0) {                          /* hmin not finite: the plane's scan failed */
        out->why = RR_GAP_PATCH_NONFINITE;
        return RR_ERR_GEOMETRY;
    }
    if (o->keep)
        keep_runs(&R, klo, khi, &lo, &hi);
    else
        group_runs(&R, c.yf[deep], o->combine, &lo, &hi);
    for (k = 0; k < R.n; k++) {
        double *iv = R.kept[k] ? out->regions[out->nregions++] : out->excluded[out->nexcluded++];
        iv[0] = R.lo[k];
        iv[1] = R.hi[k];
    }
    out->lo = lo;
    out->hi = hi;
    if (lo <= plo || hi >= phi) {
        out->why = RR_GAP_REGION_ENDS;
        return RR_ERR_RANGE;
    }

    /* the half-length: where h reaches the level along x, at the widest strip */
    x_t = out->x_t = sqrt(2.0 * level / (cos(delta) * (1.0 / r_P + 1.0 / R_P)));
    if (!(x_t < 0.5 * fmin(r_P, R_P))) {
        out->why = RR_GAP_REGION_LONG;
        return RR_ERR_RANGE;
    }
    if ((st = sec_walk(&f, &rsec, x_t, lo, hi, 0, out)) != RR_OK
        || (st = sec_walk(&f, &wsec, x_t, lo, hi, 0, out)) != RR_OK)
        return st;
    xh = -INFINITY;
    for (i = 0; i < nf; i++) {
        double rise, v;
        if (!(c.yf[i] >= lo && c.yf[i] <= hi && c.mask[i]))
            continue;
        rise = gap_at(&rsec, &wsec, c.yf[i]) - c.hy[i];
        rise = (rise < 1e-3 * level ? 1e-3 * level : rise) / (x_t * x_t);
        v = sqrt((level - (c.hy[i] - hmin)) / rise);
        xh = isnan(v) || isnan(xh) ? NAN : fmax(xh, v);
    }
    out->half_length = xh;
    if (!isfinite(xh)) {
        out->why = RR_GAP_REGION_BEYOND;
        return RR_ERR_RANGE;
    }

    /* the grid: elements from n unless given, one exterior element around */
    dx = o->dx;
    dy = o->dy;
    if (!(dx > 0.0) || !(dy > 0.0)) {
        const double d = fmax(2.0 * xh, hi - lo) / o->n;
        dx = dx > 0.0 ? dx : d;
        dy = dy > 0.0 ? dy : d;
    }
    out->grid.dx = dx;
    out->grid.dy = dy;
    fi_lo = floor(-xh / dx) - 1.0;
    fi_hi = ceil(xh / dx) + 1.0;
    fj_lo = floor(lo / dy) - 1.0;
    fj_hi = ceil(hi / dy) + 1.0;
    if ((st = bounded(fi_lo, fi_hi, fj_lo, fj_hi, out)) != RR_OK)
        return st;
    if (!(fmax(fabs(fj_lo), fabs(fj_hi)) <= RR_GAP_MAX_INDEX)) {
        out->why = RR_GAP_FAR;               /* elements far smaller than the region's */
        return RR_ERR_RANGE;                 /* distance from P: indices beyond an int */
    }
    i_lo = (int)fi_lo;
    i_hi = (int)fi_hi;
    j_lo = (int)fj_lo;
    j_hi = (int)fj_hi;
    /* grow the grid until the region has an exterior element on every side */
    for (it = 0; it < GROW_ITER; it++) {
        int g0, g1, g2, g3;
        mx = i_hi - i_lo + 1;
        my = j_hi - j_lo + 1;
        out->grid.mx = mx;
        out->grid.my = my;
        out->grid.x0 = dx * (double)i_lo;
        out->grid.y0 = dy * (double)j_lo;
        if (dy * (double)j_lo < plo || dy * (double)j_hi > phi) {
            out->why = RR_GAP_PATCH_REACHES;
            return RR_ERR_GEOMETRY;
        }
        if (!h || h_len < (size_t)mx * (size_t)my) {
            out->why = RR_GAP_H_BUFFER;
            return RR_ERR_WORKSPACE;
        }
        if ((st = fill_h(&f, &rsec, &wsec, dx, dy, i_lo, i_hi, j_lo, j_hi, h, out)) != RR_OK)
            return st;
        g0 = g1 = g2 = g3 = 0;
        for (j = 0; j < my; j++) {
            const double y = dy * (double)(j_lo + j);
            if (y < lo - 0.5 * dy || y > hi + 0.5 * dy)
                continue;                    /* rows of the intervals left out */
            g0 |= h[(size_t)j * mx] - hmin <= level;
            g1 |= h[(size_t)j * mx + mx - 1] - hmin <= level;
            for (i = 0; i < mx && (j == 0 || j == my - 1); i++) {
                if (j == 0)
                    g2 |= h[i] - hmin <= level;
                if (j == my - 1)
                    g3 |= h[(size_t)j * mx + i] - hmin <= level;
            }
        }
        if (!(g0 || g1 || g2 || g3))
            break;
        i_lo -= g0;
        i_hi += g1;
        j_lo -= g2;
        j_hi += g3;
        if ((st = bounded(i_lo, i_hi, j_lo, j_hi, out)) != RR_OK)
            return st;
    }
    hmin_grid = INFINITY;
    for (k = 0; k < mx * my; k++) {
        if (!isfinite(h[k])) {
            out->why = RR_GAP_PATCH_NONFINITE;
            return RR_ERR_GEOMETRY;
        }
        hmin_grid = h[k] < hmin_grid ? h[k] : hmin_grid;
    }
    for (k = 0; k < mx * my; k++)
        h[k] -= hmin_grid;
    out->pen = fmax(0.0, -hmin_grid);
    for (k = 0; k < 3; k++)
        out->wheel_point[k] = out->point[k] - out->pen * out->n[k];
    return RR_OK;
}
