/*
 * rr_gap_section.h - the profiles' samples and their cross-sections in the
 * contact plane, for rr_gap.c alone (not a header of the library: static
 * functions, included once, so that the per-element interpolation of the
 * grid's fill stays inlined).  A cross-section is the run of a body's
 * samples along which its lateral coordinate in the plane is strictly
 * monotonic (patch.py's _single_valued), interpolated as numpy.interp.
 * Included after geometry/rr_gap.h (its types), which it does not include
 * itself: a part of rr_gap, not a module the layers' check would see as one.
 */
#ifndef RR_GAP_SECTION_H
#define RR_GAP_SECTION_H

#include <math.h>

/* The sections' loops get an AVX2 build on x86-64 with GCC or clang, as
 * the FFT's (util/rr_fft.c); -DRR_PORTABLE keeps the baseline only. */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(RR_PORTABLE)
#define RR_GAP_AVX2 1
#define RR_GAP_INLINE inline __attribute__((always_inline))
#else
#define RR_GAP_AVX2 0
#define RR_GAP_INLINE inline
#endif

/* ---- profile samples ------------------------------------------------------- */

typedef struct {
    double *s, *z;   /* positions and heights (up) */
    int k;           /* count */
    int k0;          /* the sample nearest the centre */
    const rr_spline *sp;     /* the profile and window sampled (sp NULL: none yet): */
    double lo, hi, step;     /* a window the same as the last is not sampled again */
} samples;

/* rr_spline_eval_at's values at the increasing positions s[0 .. k) (NaN
 * off the knots) into z: its interval (the last knot at or below s, at
 * most the last but one) stepped on from the last sample's, and the
 * samples of each interval in one loop with the interval's numbers read
 * once, which vectorises; its formula as written there, so the same
 * doubles (the samples below are the build's largest loop over a
 * spline). */
static void spline_samples(const rr_spline *sp, const double *s, int k, double *z)
{
    const double *x = sp->s, x0 = x[0], xn = x[sp->n - 1];
    int i = 0, lo = 0, e;
    while (i < k) {
        double xl, xh, h, zl, zh, ml, mh;
        if (!(s[i] >= x0 && s[i] <= xn)) {
            z[i++] = NAN;
            continue;
        }
        while (lo < sp->n - 2 && x[lo + 1] <= s[i])
            lo++;
        xl = x[lo];
        xh = x[lo + 1];
        /* the interval's samples: below its upper knot, or on the last
         * interval up to the profile's end */
        for (e = i + 1; e < k && (lo < sp->n - 2 ? s[e] < xh : s[e] <= xn); e++)
            ;
        h = xh - xl;
        zl = sp->z[lo];
        zh = sp->z[lo + 1];
        ml = sp->m[lo];
        mh = sp->m[lo + 1];
        for (; i < e; i++) {
            const double a = (xh - s[i]) / h, b = 1.0 - a;
            z[i] = a * zl + b * zh + ((a * a * a - a) * ml + (b * b * b - b) * mh) * h * h / 6.0;
        }
    }
}

/* numpy.linspace over the profile within RR_GAP_WINDOW of centre, heights
 * by the spline (NaN where a rounded position leaves it), and the nearest
 * sample (numpy.argmin: the first of equals). */
static int take_samples(const rr_spline *sp, double centre, double step, size_t kmax,
                        samples *q, rr_gap_patch *out, int body)
{
    const double y0 = sp->s[0], y1 = sp->s[sp->n - 1];
    const double lo = fmax(y0, centre - RR_GAP_WINDOW), hi = fmin(y1, centre + RR_GAP_WINDOW);
    double cnt, d, best;
    int i, c;
    if (!(hi > lo)) {
        out->why = RR_GAP_OFF_PROFILE;
        out->off_body = body;
        out->off_s = centre;
        out->off_lo = y0;
        out->off_hi = y1;
        return RR_ERR_GEOMETRY;
    }
    cnt = ceil((hi - lo) / step) + 1.0;
    if (!(cnt <= (double)kmax))
        return RR_ERR_WORKSPACE;        /* not reached: kmax bounds any window */
    d = (hi - lo) / (cnt - 1.0);
    /* the same window of the same profile (the roller's, clipped at the
     * profile's end, about half the time): the same samples */
    if (!(q->sp == sp && q->lo == lo && q->hi == hi && q->step == step && q->k == (int)cnt)) {
        q->k = (int)cnt;
        for (i = 0; i < q->k; i++)
            q->s[i] = i < q->k - 1 ? (double)i * d + lo : hi;
        spline_samples(sp, q->s, q->k, q->z);
        q->sp = sp;
        q->lo = lo;
        q->hi = hi;
        q->step = step;
    }
    /* |s - centre| falls then rises along the samples: the least is within
     * one of the rounded position (the window holds at least two) */
    c = (int)fmin(fmax(floor((centre - lo) / d + 0.5), 1.0), (double)(q->k - 1));
    q->k0 = c - 1;
    best = fabs(q->s[c - 1] - centre);
    for (i = c; i <= c + 1 && i < q->k; i++)
        if (fabs(q->s[i] - centre) < best) {
            best = fabs(q->s[i] - centre);
            q->k0 = i;
        }
    return RR_OK;
}

/* ---- the plane and the cross-sections -------------------------------------- */

typedef struct {
    const rr_wheel_roller *p;
    double sigma;            /* +1 left, -1 right */
    double y_ws, z;          /* the wheelset's pose */
    double cr, sr;           /* cos, sin of its roll */
    double P0, P1;           /* the reference point, rig (Y, Z) */
    double t2y, t2z, ny, nz; /* t2 and n in the rig's (Y, Z) */
} plane;

static void plane_set(plane *f, double P0, double P1, double delta)
{
    const double c = cos(delta), s = sin(delta);
    f->P0 = P0;
    f->P1 = P1;
    f->t2y = c;
    f->t2z = f->sigma * s;
    f->ny = -f->sigma * s;
    f->nz = c;
}

/* A body's cross-section at x in the plane: sample i at (yc[i], ze[i]); the
 * run [a, b] of samples around k0 along which yc is strictly monotonic
 * (dir +1 increasing with the index, -1 decreasing), known to end at a
 * (a_end) or b (b_end), or computed only as far as a caller needed. */
typedef struct {
    const samples *q;
    int body;                /* 0 roller, 1 wheel */
    int k0;                  /* the sample the run holds */
    double *yc, *ze;
    int a, b, dir, a_end, b_end;
    int hint;                /* the last interpolation's interval */
} section;

/* A section's numbers for a loop over its samples, read once (the walk's
 * loop is the build's largest: a sample's point in few instructions). */
typedef struct {
    const double *s, *z;
    double *yc, *ze;
    double x, sigma, body_y, radius, y_ws, cr, sr, z0, P0, P1, t2y, t2z, ny, nz;
    int body;
} walker;

static void walker_set(const plane *f, const section *c, double x, walker *w)
{
    const rr_wheel_roller *p = f->p;
    w->s = c->q->s;
    w->z = c->q->z;
    w->yc = c->yc;
    w->ze = c->ze;
    w->x = x;
    w->sigma = f->sigma;
    w->body = c->body;
    w->body_y = c->body == 0 ? p->roller_y : p->wheel_y;
    w->radius = c->body == 0 ? p->R0 : p->r0;
    w->y_ws = f->y_ws;
    w->cr = f->cr;
    w->sr = f->sr;
    w->z0 = f->z;
    w->P0 = f->P0;
    w->P1 = f->P1;
    w->t2y = f->t2y;
    w->t2z = f->t2z;
    w->ny = f->ny;
    w->nz = f->nz;
}

/* samples i0 .. i1 (i0 <= i1) of w's section at x: their (yc, ze) in the
 * plane, a loop per body, whose samples are independent, so that the
 * compiler computes several at once (the walk's loop of checks follows).
 * A body of radius r drops by r - sqrt(r^2 - x^2) at x, written
 * x^2 / (r + sqrt(r^2 - x^2)) against cancellation (patch.py's _drop; its
 * numpy.maximum keeps a NaN, as the comparison here does). */
static RR_GAP_INLINE void walk_points_loops(const walker *w, int i0, int i1)
{
    const double *s = w->s, *z = w->z;
    const double x = w->x, x2 = x * x, sigma = w->sigma, body_y = w->body_y;
    const double radius = w->radius, P0 = w->P0, P1 = w->P1;
    const double t2y = w->t2y, t2z = w->t2z, ny = w->ny, nz = w->nz;
    double *restrict yc = w->yc, *restrict ze = w->ze;
    int i;
    if (w->body == 0) {
        for (i = i0; i <= i1; i++) {
            const double zi = z[i], r = radius + zi, v = r * r - x2;
            const double dY = sigma * (body_y + s[i]) - P0;
            const double dZ = zi - x2 / (r + sqrt(v < 0.0 ? 0.0 : v)) - P1;
            yc[i] = dY * t2y + dZ * t2z;
            ze[i] = dY * ny + dZ * nz;
        }
    } else {
        const double y_ws = w->y_ws, cr = w->cr, sr = w->sr, z0 = w->z0;
        for (i = i0; i <= i1; i++) {
            const double zi = z[i], r = radius - zi, v = r * r - x2;
            const double yl = sigma * (body_y + s[i]);
            const double zl = -radius + zi + x2 / (r + sqrt(v < 0.0 ? 0.0 : v));
            const double dY = y_ws + yl * cr - zl * sr - P0;
            const double dZ = z0 + yl * sr + zl * cr - P1;
            yc[i] = dY * t2y + dZ * t2z;
            ze[i] = dY * ny + dZ * nz;
        }
    }
}

/* walk_points_loops compiled for the processor at hand: with AVX2 where it
 * runs (four square roots at once; contraction is off in ISO C, so the
 * same doubles), else the baseline (two) */
static void walk_points_plain(const walker *w, int i0, int i1)
{
    walk_points_loops(w, i0, i1);
}

#if RR_GAP_AVX2
__attribute__((target("avx2"))) static void walk_points_avx2(const walker *w, int i0, int i1)
{
    walk_points_loops(w, i0, i1);
}
#endif

static void walk_points(const walker *w, int i0, int i1)
{
#if RR_GAP_AVX2
    if (__builtin_cpu_supports("avx2")) {
        walk_points_avx2(w, i0, i1);
        return;
    }
#endif
    walk_points_plain(w, i0, i1);
}

/* Samples the walk computes at a time: a few past the run's end are
 * computed for nothing, against ~800 a column walks. */
#define WALK_BLOCK 16

/* 1 where the step from sample i to j (= i +- 1) continues the run of
 * direction dir: the step along yc finite and of the run's sign, ze finite
 * (the comparisons are false for NaN: isfinite's tests in fewer
 * instructions) */
static int walk_good(const walker *w, int dir, int i, int j)
{
    const double d = j > i ? w->yc[j] - w->yc[i] : w->yc[i] - w->yc[j];
    const double sd = dir > 0 ? d : -d;
    return sd > 0.0 && sd < INFINITY && fabs(w->ze[j]) < INFINITY;
}

/* The run around the reference sample at x (patch.py's _single_valued),
 * computed outward until it covers [need_lo, need_hi] or ends (full: to
 * its ends).  RR_ERR_GEOMETRY (why FOLD) where it does not start. */
static int sec_walk(const plane *f, section *c, double x, double need_lo, double need_hi,
                    int full, rr_gap_patch *out)
{
    const int k = c->q->k;
    const int k0 = c->k0 < 0 ? 0 : c->k0 > k - 2 ? k - 2 : c->k0;
    walker w;
    double d;
    int a, b, dir, done;
    walker_set(f, c, x, &w);
    walk_points(&w, k0, k0 + 1);
    d = c->yc[k0 + 1] - c->yc[k0];
    if (!(isfinite(d) && d != 0.0 && isfinite(c->ze[k0]) && isfinite(c->ze[k0 + 1]))) {
        out->why = RR_GAP_FOLD;
        return RR_ERR_GEOMETRY;
    }
    dir = c->dir = d > 0.0 ? 1 : -1;
    a = k0;
    b = k0 + 1;
    c->a_end = c->b_end = 0;
    c->hint = 0;
    done = b;
    for (;;) {                              /* up the samples */
        if (b + 1 >= k) {
            c->b_end = 1;
            break;
        }
        if (!full && (dir > 0 ? w.yc[b] > need_hi : w.yc[b] < need_lo))
            break;
        if (b + 1 > done) {
            done = b + WALK_BLOCK < k - 1 ? b + WALK_BLOCK : k - 1;
            walk_points(&w, b + 1, done);
        }
        if (!walk_good(&w, dir, b, b + 1)) {
            c->b_end = 1;
            break;
        }
        b++;
    }
    done = a;
    for (;;) {                              /* down */
        if (a == 0) {
            c->a_end = 1;
            break;
        }
        if (!full && (dir > 0 ? w.yc[a] < need_lo : w.yc[a] > need_hi))
            break;
        if (a - 1 < done) {
            done = a - WALK_BLOCK > 0 ? a - WALK_BLOCK : 0;
            walk_points(&w, done, a - 1);
        }
        if (!walk_good(&w, dir, a, a - 1)) {
            c->a_end = 1;
            break;
        }
        a--;
    }
    c->a = a;
    c->b = b;
    return RR_OK;
}

/* The run's j-th sample in increasing yc. */
static int sec_index(const section *c, int j)
{
    return c->dir > 0 ? c->a + j : c->b - j;
}

static double sec_first(const section *c)
{
    return c->yc[sec_index(c, 0)];
}

static double sec_last(const section *c)
{
    return c->yc[sec_index(c, c->b - c->a)];
}

/* numpy.interp's special cases over a run (x[s j] its j-th point in
 * increasing order, f its values, n of them): y NaN, or beyond either
 * end (the end's value); 1 with *r set where y is one of them. */
static RR_GAP_INLINE int interp_outside(const double *x, const double *f, int s, int n,
                                        double y, double *r)
{
    if (isnan(y))
        *r = y;
    else if (y > x[s * (n - 1)])
        *r = f[s * (n - 1)];
    else if (y < x[0])
        *r = f[0];
    else
        return 0;
    return 1;
}

/* numpy.interp's formula in the run's interval j (x[s j] <= y, below the
 * next point unless j is the last), its special cases included */
static RR_GAP_INLINE double interp_in(const double *x, const double *f, int s, int n, int j,
                                      double y)
{
    const double xj = x[s * j], fj = f[s * j];
    double xj1, fj1, slope, r;
    if (j == n - 1 || xj == y)
        return fj;
    xj1 = x[s * (j + 1)];
    fj1 = f[s * (j + 1)];
    slope = (fj1 - fj) / (xj1 - xj);
    r = slope * (y - xj) + fj;
    if (isnan(r)) {
        r = slope * (y - xj1) + fj1;
        if (isnan(r) && fj == fj1)
            r = fj;
    }
    return r;
}

/* numpy.interp(y, yc of the run, v of the run) (v: ze, or the samples'
 * positions), its formula and special cases; c->hint keeps the interval of
 * the last call: queries in order (a scan, a column's rows) step on from
 * it, others bisect. */
static double sec_interp(section *c, double y, const double *v)
{
    const int n = c->b - c->a + 1, s = c->dir;
    const double *x = c->yc + (s > 0 ? c->a : c->b);   /* x[s j]: j-th in increasing yc */
    const double *f = v + (s > 0 ? c->a : c->b);
    int j, step;
    double r;
    if (interp_outside(x, f, s, n, y, &r))
        return r;
    j = c->hint < 0 ? 0 : c->hint > n - 1 ? n - 1 : c->hint;
    for (step = 0; step < 4 && j < n - 1 && x[s * (j + 1)] <= y; step++)
        j++;
    if (!(x[s * j] <= y && (j == n - 1 || y < x[s * (j + 1)]))) {
        int lo = 0, hi = n - 1;              /* bisect: x[lo] <= y < x[hi] */
        if (y >= x[s * hi]) {
            lo = hi;
        } else {
            while (hi - lo > 1) {
                const int mid = lo + (hi - lo) / 2;
                if (x[s * mid] <= y)
                    lo = mid;
                else
                    hi = mid;
            }
        }
        j = lo;
    }
    c->hint = j;
    return interp_in(x, f, s, n, j, y);
}

/* h along n at lateral y (patch.py's _Sections.gap): NaN outside both runs. */
static double gap_at(section *r, section *w, double y)
{
    const double lo = fmax(sec_first(r), sec_first(w)), hi = fmin(sec_last(r), sec_last(w));
    const double g = sec_interp(w, y, w->ze) - sec_interp(r, y, r->ze);
    return y < lo || y > hi ? NAN : g;
}

/* sec_interp of a run's ze for queries in monotonic y (a scan, a
 * column's rows), its numbers read once: the interval stepped on from the
 * last query's, and the same formula and special cases, so the same
 * doubles (a query's interval is the one whose ends hold it, found
 * either way).  The per-call overhead of sec_interp, its hint clamped and
 * its bisection where the hint was more than four samples behind, was the
 * patch's largest single cost. */
typedef struct {
    const double *x, *f;
    int n, s, j;
} cursor;

static void cursor_set(const section *c, cursor *k)
{
    k->n = c->b - c->a + 1;
    k->s = c->dir;
    k->x = c->yc + (k->s > 0 ? c->a : c->b);
    k->f = c->ze + (k->s > 0 ? c->a : c->b);
    k->j = c->hint < 0 ? 0 : c->hint > k->n - 1 ? k->n - 1 : c->hint;
}

static RR_GAP_INLINE double cursor_at(cursor *k, double y)
{
    const double *x = k->x, *f = k->f;
    const int n = k->n, s = k->s;
    int j = k->j;
    double r;
    if (interp_outside(x, f, s, n, y, &r))
        return r;
    while (j > 0 && x[s * j] > y)
        j--;
    while (j < n - 1 && x[s * (j + 1)] <= y)
        j++;
    k->j = j;
    return interp_in(x, f, s, n, j, y);
}

/* gap_at at m increasing y into out[i stride]: ys[i], or dy (j0 + i)
 * where ys is NULL (a column's rows) */
static void gap_many(section *r, section *w, const double *ys, double dy, int j0, int m,
                     double *out, size_t stride)
{
    const double lo = fmax(sec_first(r), sec_first(w)), hi = fmin(sec_last(r), sec_last(w));
    cursor kr, kw;
    int i;
    cursor_set(r, &kr);
    cursor_set(w, &kw);
    for (i = 0; i < m; i++) {
        const double y = ys ? ys[i] : dy * (double)(j0 + i);
        const double g = cursor_at(&kw, y) - cursor_at(&kr, y);
        out[(size_t)i * stride] = y < lo || y > hi ? NAN : g;
    }
    r->hint = kr.j;
    w->hint = kw.j;
}

/* Both runs at x = 0 in full (the roller's only where walk_r is set: r
 * may hold it already) and where they overlap; RR_ERR_GEOMETRY (why FOLD,
 * APART). */
static int sections0(const plane *f, int walk_r, section *r, section *w, double *lo,
                     double *hi, rr_gap_patch *out)
{
    int st;
    if ((walk_r && (st = sec_walk(f, r, 0.0, 0.0, 0.0, 1, out)) != RR_OK)
        || (st = sec_walk(f, w, 0.0, 0.0, 0.0, 1, out)) != RR_OK)
        return st;
    *lo = fmax(sec_first(r), sec_first(w));
    *hi = fmin(sec_last(r), sec_last(w));
    if (!(*hi > *lo)) {
        out->why = RR_GAP_APART;
        return RR_ERR_GEOMETRY;
    }
    return RR_OK;
}

#endif
