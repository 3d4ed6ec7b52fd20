/* rr_influence.c - the half-space's influence coefficients on a grid. */
#include <math.h>
#include "util/rr_common.h"
#include "contact/rr_influence.h"

/* X log(Y + r), r = |(X, Y)|, 0 at X = 0 (its limit); for Y < 0 as
 * X (2 log|X| - log(r - Y)), since Y + r cancels there. */
static double x_log_yr_r(double X, double Y, double r)
{
    if (X == 0.0)
        return 0.0;
    if (Y >= 0.0)
        return X * log(Y + r);
    return X * (2.0 * log(fabs(X)) - log(r - Y));
}

static double x_log_yr(double X, double Y)
{
    return x_log_yr_r(X, Y, hypot(X, Y));
}

/* |(X, Y)|: the square root of the sum of squares where that neither
 * overflows nor underflows, else hypot (several times slower) */
static double radius(double X, double Y)
{
    const double s = X * X + Y * Y;
    return s > 1e-290 && s < 1e290 ? sqrt(s) : hypot(X, Y);
}

static int check_grid(int nkx, int nky, double dx, double dy)
{
    if (!isfinite(dx) || !isfinite(dy))
        return RR_ERR_NONFINITE;
    if (nkx < 1 || nky < 1)
        return RR_ERR_GRID;
    if (!(dx > 0.0) || !(dy > 0.0) || dx / dy > 1e6 || dy / dx > 1e6
        || !isnormal(dx) || !isnormal(dy))
        return RR_ERR_GEOMETRY;
    return RR_OK;
}

int rr_influence_boxes(int nkx, int nky, double dx, double dy, double *ta, double *tb,
                       double *tr)
{
    int st = check_grid(nkx, nky, dx, dy), i, j;

    if (!ta || !tb || !tr)
        return RR_ERR_NULL;
    if (st < 0)
        return st;
    /* The corners of the boxes are X = (kx -+ 1/2) dx, Y = (ky -+ 1/2) dy;
     * with kx, ky >= 0 they run over i = 0 .. nkx (X = (i - 1/2) dx) and
     * j = 0 .. nky.  Each box is the signed sum of its four corners; the
     * corner values are computed once each, row by row, and the boxes of a
     * row are finished as soon as its upper corner row is known. */
    for (j = 0; j <= nky; j++) {
        const double Y = (j - 0.5) * dy;
        double pa = 0.0, pb = 0.0, pr = 0.0;   /* corner (i - 1, j) */
        for (i = 0; i <= nkx; i++) {
            const double X = (i - 0.5) * dx;
            /* one radius for the corner's three primitives */
            const double fr = radius(X, Y), fa = x_log_yr_r(X, Y, fr), fb = x_log_yr_r(Y, X, fr);
            if (i > 0 && j > 0) {
                /* box (i-1, j-1): corners (i, j) + (i-1, j-1) - (i-1, j) - (i, j-1);
                 * the row below was stored in the output temporarily */
                const int k = (j - 1) * nkx + (i - 1);
                ta[k] = fa - pa - ta[k];
                tb[k] = fb - pb - tb[k];
                tr[k] = fr - pr - tr[k];
            }
            if (j < nky && i > 0) {
                /* prepare box (i-1, j): its lower corners (i, j) - (i-1, j) */
                const int k = j * nkx + (i - 1);
                ta[k] = fa - pa;
                tb[k] = fb - pb;
                tr[k] = fr - pr;
            }
            pa = fa;
            pb = fb;
            pr = fr;
        }
    }
    return RR_OK;
}

int rr_influence_at(int kx, int ky, double dx, double dy, double nu, double an[4])
{
    const double X = kx * dx, Y = ky * dy;
    const double xs[2] = {X + 0.5 * dx, X - 0.5 * dx}, ys[2] = {Y + 0.5 * dy, Y - 0.5 * dy};
    double a = 0.0, b = 0.0, r = 0.0;
    int st = check_grid(1, 1, dx, dy), i, j;

    if (!an)
        return RR_ERR_NULL;
    if (st == RR_OK && !isfinite(nu))
        st = RR_ERR_NONFINITE;
    if (st == RR_OK && !(nu >= 0.0 && nu <= 0.5))
        st = RR_ERR_MATERIAL;
    if (st < 0) {
        an[0] = an[1] = an[2] = an[3] = NAN;
        return st;
    }
    for (i = 0; i < 2; i++)
        for (j = 0; j < 2; j++) {
            const double sg = (i == j) ? 1.0 : -1.0;
            a += sg * x_log_yr(xs[i], ys[j]);
            b += sg * x_log_yr(ys[j], xs[i]);
            r += sg * hypot(xs[i], ys[j]);
        }
    an[0] = (1.0 - nu) / RR_PI * (a + b);
    an[1] = ((1.0 - nu) * a + b) / RR_PI;
    an[2] = (a + (1.0 - nu) * b) / RR_PI;
    an[3] = -nu / RR_PI * r;
    return RR_OK;
}
