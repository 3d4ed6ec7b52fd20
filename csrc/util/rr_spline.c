/* rr_spline.c - natural cubic spline (de Boor 1978, ch. IV). */
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
