/* rr_spline.c - natural cubic spline (de Boor 1978, ch. IV). */
#include <float.h>
#include <math.h>
#include "util/rr_common.h"
#include "util/rr_spline.h"

int rr_spline_init(int n, const double *s, const double *z, double *m, double *work)
{
    int i;

    if (!s || !z)
        return RR_ERR_NULL;
    if (!m || !work)
        return RR_ERR_WORKSPACE;
    if (n < 2)
        return RR_ERR_GEOMETRY;
    for (i = 0; i < n; i++) {
        if (!isfinite(s[i]) || !isfinite(z[i]))
            return RR_ERR_NONFINITE;
        if (i > 0 && !(s[i] > s[i - 1]))
            return RR_ERR_GEOMETRY;
    }
    /* tridiagonal system for the interior second derivatives, solved by
     * forward elimination (work holds the modified super-diagonal) */
    m[0] = m[n - 1] = 0.0;
    work[0] = 0.0;
    for (i = 1; i < n - 1; i++) {
        const double h0 = s[i] - s[i - 1], h1 = s[i + 1] - s[i];
        const double rhs = 6.0 * ((z[i + 1] - z[i]) / h1 - (z[i] - z[i - 1]) / h0);
        const double diag = 2.0 * (h0 + h1) - h0 * work[i - 1];
        work[i] = h1 / diag;
        m[i] = (rhs - h0 * m[i - 1]) / diag;
    }
    for (i = n - 2; i > 0; i--)
        m[i] -= work[i] * m[i + 1];
    for (i = 0; i < n; i++)
        if (!isfinite(m[i])) {
            for (i = 0; i < n; i++)
                m[i] = NAN;         /* values near the largest double over close knots */
            return RR_ERR_RANGE;
        }
    return RR_OK;
}

int rr_spline_check(const rr_spline *sp)
{
    int i;
    if (!sp || !sp->s || !sp->z || !sp->m)
        return RR_ERR_NULL;
    if (sp->n < 2)
        return RR_ERR_GEOMETRY;
    for (i = 0; i < sp->n; i++) {
        if (!isfinite(sp->s[i]) || !isfinite(sp->z[i]) || !isfinite(sp->m[i]))
            return RR_ERR_NONFINITE;
        if (i > 0 && !(sp->s[i] > sp->s[i - 1]))
            return RR_ERR_GEOMETRY;
    }
    return RR_OK;
}

int rr_spline_eval(const rr_spline *sp, double s, double *z, double *d1, double *d2)
{
    int k = -1;
    return rr_spline_eval_at(sp, s, &k, z, d1, d2);
}

int rr_spline_eval_at(const rr_spline *sp, double s, int *k, double *z, double *d1, double *d2)
{
    int lo = 0, hi;
    double h, a, b;

    if (!z)
        return RR_ERR_NULL;
    if (!sp || !sp->s || !sp->z || !sp->m || sp->n < 2 || !k) {
        *z = NAN;
        if (d1) *d1 = NAN;
        if (d2) *d2 = NAN;
        return !sp || !sp->s || !sp->z || !sp->m || !k ? RR_ERR_NULL : RR_ERR_GEOMETRY;
    }
    hi = sp->n - 1;
    if (!isfinite(s) || s < sp->s[0] || s > sp->s[sp->n - 1]) {
        *z = NAN;
        if (d1) *d1 = NAN;
        if (d2) *d2 = NAN;
        return isfinite(s) ? RR_ERR_GEOMETRY : RR_ERR_NONFINITE;
    }
    /* the hinted interval or its right neighbour (a scan moving on), else bisect */
    if (*k >= 0 && *k < sp->n - 1 && sp->s[*k] <= s) {
        /* strict upper bounds: the interval bisection would pick */
        if (s < sp->s[*k + 1]) {
            lo = *k;
            hi = lo + 1;
        } else if (*k + 2 < sp->n && s < sp->s[*k + 2]) {
            lo = *k + 1;
            hi = lo + 1;
        }
    }
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        if (sp->s[mid] <= s)
            lo = mid;
        else
            hi = mid;
    }
    *k = lo;
    h = sp->s[hi] - sp->s[lo];
    a = (sp->s[hi] - s) / h;
    b = 1.0 - a;
    *z = a * sp->z[lo] + b * sp->z[hi]
       + ((a * a * a - a) * sp->m[lo] + (b * b * b - b) * sp->m[hi]) * h * h / 6.0;
    if (d1)
        *d1 = (sp->z[hi] - sp->z[lo]) / h
            + ((1.0 - 3.0 * a * a) * sp->m[lo] + (3.0 * b * b - 1.0) * sp->m[hi]) * h / 6.0;
    if (d2)
        *d2 = a * sp->m[lo] + b * sp->m[hi];
    if (!isfinite(0.0 * *z + (d1 ? 0.0 * *d1 : 0.0) + (d2 ? 0.0 * *d2 : 0.0))) {
        *z = NAN;                   /* a spline not made by rr_spline_init, or values */
        if (d1) *d1 = NAN;          /* near the largest double over close knots */
        if (d2) *d2 = NAN;
        return RR_ERR_RANGE;
    }
    return RR_OK;
}

/* ------------------------------------------------------------ the profile spline */

/* One row of the slopes' tridiagonal system: sub s_(i-1) + diag s_i + sup s_(i+1) = rhs. */
typedef struct {
    double sub, diag, sup, rhs;
} tri_row;

/* Interior row i (1 <= i <= n-2): continuity of z'' at knot i. */
static tri_row interior_row(const double *y, const double *z, int i)
{
    const double h0 = y[i] - y[i - 1], h1 = y[i + 1] - y[i];
    const double d0 = (z[i] - z[i - 1]) / h0, d1 = (z[i + 1] - z[i]) / h1;
    tri_row r;
    r.sub = h1;
    r.diag = 2.0 * (h0 + h1);
    r.sup = h0;
    r.rhs = 3.0 * (h1 * d0 + h0 * d1);
    return r;
}

/* Thomas' algorithm on rows lo..hi of the system: rows lo and hi given
 * (first, last), the others interior rows.  x[lo..hi] the solution, c[]
 * the modified super-diagonal.  The operations, in their order, are those
 * of the numpy version this replaced (profiles._solve_tridiagonal), so the
 * slopes are bitwise the same. */
static void solve_rows(const double *y, const double *z, int lo, int hi, tri_row first,
                       tri_row last, double *x, double *c)
{
    int i;
    c[lo] = first.sup / first.diag;
    x[lo] = first.rhs / first.diag;
    for (i = lo + 1; i <= hi; i++) {
        const tri_row r = i == hi ? last : interior_row(y, z, i);
        const double m = r.diag - r.sub * c[i - 1];
        c[i] = i < hi ? r.sup / m : 0.0;
        x[i] = (r.rhs - r.sub * x[i - 1]) / m;
    }
    for (i = hi - 1; i >= lo; i--)
        x[i] -= c[i] * x[i + 1];
}

/* q = num / h^k, nonzero in exact arithmetic, below DBL_MIN, where the
 * subnormals' spacing over the interval (its term q h^k) is coarser than
 * the values' own rounding (eps |z|, and never finer than DBL_MIN: a
 * profile of 1e-315 m, a crown of 1e300 m, is flat, not lost) */
static int underflows(double num, double q, double hk, double zs)
{
    return num != 0.0 && fabs(q) < DBL_MIN && 0x1p-1074 * hk > fmax(DBL_EPSILON * zs, DBL_MIN);
}

static void fill_nan(double *v, int n)
{
    int i;
    if (v)
        for (i = 0; i < n; i++)
            v[i] = NAN;
}

int rr_spline_fit(int n, const double *y, const double *z, int end, double *slope,
                  double *c2, double *c3, double *work)
{
    int i, st = RR_OK;

    if (!(n >= RR_SPLINE_MIN_POINTS && n <= RR_SPLINE_MAX_POINTS))
        st = RR_ERR_PARAM;
    else if (!y || !z)
        st = RR_ERR_NULL;
    else if (!slope || !c2 || !c3 || !work)
        st = RR_ERR_WORKSPACE;
    else if (end != RR_SPLINE_NOT_A_KNOT && end != RR_SPLINE_NATURAL)
        st = RR_ERR_PARAM;
    else if (!rr_all_finite(y, n) || !rr_all_finite(z, n))
        st = RR_ERR_NONFINITE;
    else
        for (i = 1; i < n; i++)
            if (!(y[i] > y[i - 1]))
                st = RR_ERR_GEOMETRY;
    if (st != RR_OK) {
        if (n >= 1 && n <= RR_SPLINE_MAX_POINTS) {
            fill_nan(slope, n);
            fill_nan(c2, n - 1);
            fill_nan(c3, n - 1);
        }
        return st;
    }
    if (end == RR_SPLINE_NATURAL) {
        const double d0 = (z[1] - z[0]) / (y[1] - y[0]);
        const double dn = (z[n - 1] - z[n - 2]) / (y[n - 1] - y[n - 2]);
        const tri_row first = {0.0, 2.0, 1.0, 3.0 * d0}, last = {1.0, 2.0, 0.0, 3.0 * dn};
        solve_rows(y, z, 0, n - 1, first, last, slope, work);
    } else {
        /* not-a-knot: each end row (not dominant) is eliminated into its
         * neighbour; s_0 and s_(n-1) follow from the end rows.  pow(h, 2.0),
         * not h * h: numpy's h ** 2 is libm's pow, and the two can differ in
         * the last bit (the slopes stay those the numpy version gave) */
        const double h0 = y[1] - y[0], h1 = y[2] - y[1];
        const double hl = y[n - 1] - y[n - 2], hm = y[n - 2] - y[n - 3];
        const double d0 = (z[1] - z[0]) / h0, d1 = (z[2] - z[1]) / h1;
        const double dl = (z[n - 1] - z[n - 2]) / hl, dm = (z[n - 2] - z[n - 3]) / hm;
        const double w0 = h0 + h1, a0 = h1, cc0 = w0;
        const double r0 = ((h0 + 2.0 * w0) * h1 * d0 + pow(h0, 2.0) * d1) / w0;
        const double w1 = hl + hm, an = hm, bn = w1;
        const double rn = (pow(hl, 2.0) * dm + (2.0 * w1 + hl) * hm * dl) / w1;
        tri_row first = interior_row(y, z, 1), last = interior_row(y, z, n - 2);
        const double f = first.sub / a0, g = last.sup / an;
        first.diag -= f * cc0;
        first.rhs -= f * r0;
        first.sub = 0.0;
        last.diag -= g * bn;
        last.rhs -= g * rn;
        last.sup = 0.0;
        solve_rows(y, z, 1, n - 2, first, last, slope, work);
        slope[0] = (r0 - cc0 * slope[1]) / a0;
        slope[n - 1] = (rn - bn * slope[n - 2]) / an;
    }
    for (i = 0; i < n - 1; i++) {
        const double h = y[i + 1] - y[i], d = (z[i + 1] - z[i]) / h;
        const double n2 = 3.0 * d - 2.0 * slope[i] - slope[i + 1];
        const double n3 = slope[i] + slope[i + 1] - 2.0 * d;
        c2[i] = n2 / h;
        c3[i] = n3 / (h * h);
        /* the other end of the range: a coefficient (or a slope) that
         * underflows below the smallest normal double keeps too few digits
         * to give the spline (values near 1e-166 over intervals of 8e71 m) */
        const double zs = fmax(fabs(z[i]), fabs(z[i + 1]));
        if (underflows(n2, c2[i], h * h, zs) || underflows(n3, c3[i], h * h * h, zs)
            || underflows(slope[i], slope[i], h, zs)
            || underflows(slope[i + 1], slope[i + 1], h, zs))
            c3[i] = NAN;
        /* an interval so long that h^3 overflows: c3 (of the order of
         * z / h^3) rounds to 0 and the coefficients no longer give the
         * spline (a finite wrong answer); and terms that overflow over
         * their interval (c2 h^2 against c3 h^3, each beyond DBL_MAX
         * though their sum is not): no one can evaluate that spline */
        if (!isfinite(h * h * h) || !isfinite(c2[i] * h * h) || !isfinite(c3[i] * h * h * h)
            || !isfinite(3.0 * c3[i] * h * h))
            c3[i] = NAN;
    }
    if (!rr_all_finite(slope, n) || !rr_all_finite(c2, n - 1) || !rr_all_finite(c3, n - 1)) {
        fill_nan(slope, n);
        fill_nan(c2, n - 1);
        fill_nan(c3, n - 1);
        return RR_ERR_RANGE;
    }
    return RR_OK;
}

int rr_spline_knot_d2(int n, const double *y, const double *c2, const double *c3, double *d2)
{
    int i;
    if (!(n >= RR_SPLINE_MIN_POINTS && n <= RR_SPLINE_MAX_POINTS))
        return RR_ERR_PARAM;
    if (!y || !c2 || !c3)
        return RR_ERR_NULL;
    if (!d2)
        return RR_ERR_WORKSPACE;
    /* z'' = 2 c2 + 6 c3 t as the Profile evaluates it, t = 0 written out so
     * that a zero keeps the sign that evaluation gives it */
    for (i = 0; i < n - 1; i++) {
        const double t = 0.0;
        d2[i] = 2.0 * c2[i] + 6.0 * c3[i] * t;
    }
    d2[n - 1] = 2.0 * c2[n - 2] + 6.0 * c3[n - 2] * (y[n - 1] - y[n - 2]);
    /* a c3 beyond DBL_MAX / 6 (finite, so the fit accepted it) makes 6 c3
     * infinite, and times t = 0 NaN: no second derivative to give */
    if (!rr_all_finite(d2, n)) {
        fill_nan(d2, n);
        return RR_ERR_RANGE;
    }
    return RR_OK;
}
