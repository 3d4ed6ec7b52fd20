/* rr_elliptic.c - Carlson's R_F and R_D by duplication (Carlson 1995). */
#include <math.h>
#include "util/rr_common.h"
#include "util/rr_elliptic.h"

/* The duplication stops when every argument is within TOL of the mean;
 * the truncated series then errs by about TOL^6 (Carlson 1995, eq. 2.2). */
#define TOL 0.0008

/* The duplication on arguments of moderate size (their sum representable). */
static void rf_rd(double x, double y, double z, double *rf, double *rd);

int rr_carlson_rf_rd(double x, double y, double z, double *rf, double *rd)
{
    double m;
    int j = 0;

    if (!rf || !rd)
        return RR_ERR_NULL;
    if (!isfinite(x) || !isfinite(y) || !isfinite(z)) {
        *rf = *rd = NAN;
        return RR_ERR_NONFINITE;
    }
    if (x < 0.0 || y < 0.0 || z <= 0.0 || x + y <= 0.0) {
        *rf = *rd = NAN;
        return RR_ERR_GEOMETRY;
    }
    /* R_F and R_D are homogeneous of degree -1/2 and -3/2: arguments far from
     * 1 are scaled by 4^-j (exact), the results by 2^-j and 2^-3j, so that
     * no sum overflows and no product underflows on the way */
    m = x > y ? x : y;
    if (z > m)
        m = z;
    if (m > 1e100 || m < 1e-100) {
        frexp(m, &j);
        j /= 2;
        x = ldexp(x, -2 * j);
        y = ldexp(y, -2 * j);
        z = ldexp(z, -2 * j);
        if (!(x + y > 0.0) || !(z > 0.0)) {
            *rf = *rd = NAN;        /* the small arguments vanish beside the large */
            return RR_ERR_RANGE;
        }
    }
    rf_rd(x, y, z, rf, rd);
    *rf = ldexp(*rf, -j);
    *rd = ldexp(*rd, -3 * j);
    if (!isnormal(*rf) || !isnormal(*rd)) {
        *rf = *rd = NAN;            /* R_D ~ m^(-3/2) beyond the double range */
        return RR_ERR_RANGE;
    }
    return RR_OK;
}

static void rf_rd(double x, double y, double z, double *rf, double *rd)
{
    double sum = 0.0, fac = 1.0, mf, md, dx, dy, dz, e2, e3;
    double ea, eb, ec, ed, ee;
    int iter;

    /* 60 halvings of the spread are far beyond what double precision needs */
    for (iter = 0; iter < 60; iter++) {
        double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
        double lam = sx * (sy + sz) + sy * sz;
        mf = (x + y + z) / 3.0;
        md = 0.2 * (x + y + 3.0 * z);
        if (fabs(mf - x) < TOL * mf && fabs(mf - y) < TOL * mf && fabs(mf - z) < TOL * mf
            && fabs(md - x) < TOL * md && fabs(md - y) < TOL * md
            && fabs(md - z) < TOL * md)
            break;
        sum += fac / (sz * (z + lam));
        fac *= 0.25;
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
    }
    mf = (x + y + z) / 3.0;
    dx = (mf - x) / mf;
    dy = (mf - y) / mf;
    dz = -(dx + dy);
    e2 = dx * dy - dz * dz;
    e3 = dx * dy * dz;
    *rf = (1.0 + (e2 / 24.0 - 0.1 - 3.0 * e3 / 44.0) * e2 + e3 / 14.0) / sqrt(mf);

    md = 0.2 * (x + y + 3.0 * z);
    dx = (md - x) / md;
    dy = (md - y) / md;
    dz = (md - z) / md;
    ea = dx * dy;
    eb = dz * dz;
    ec = ea - eb;
    ed = ea - 6.0 * eb;
    ee = ed + ec + ec;
    *rd = 3.0 * sum
        + fac * (1.0 + ed * (-3.0 / 14.0 + 9.0 / 88.0 * ed - 9.0 / 52.0 * dz * ee)
                 + dz * (ee / 6.0 + dz * (-9.0 / 22.0 * ec + dz * 3.0 / 26.0 * ea)))
              / (md * sqrt(md));
}

int rr_ellip_agm(double kc, double *K, double *d_lo, double *d_hi)
{
    double a = 1.0, b = kc, e2, S = 0.0, pw = 1.0;
    int n;

    if (!K || !d_lo || !d_hi)
        return RR_ERR_NULL;
    if (!isfinite(kc)) {
        *K = *d_lo = *d_hi = NAN;
        return RR_ERR_NONFINITE;
    }
    if (kc <= 0.0 || kc > 1.0) {
        *K = *d_lo = *d_hi = NAN;
        return RR_ERR_GEOMETRY;
    }
    e2 = (1.0 - kc) * (1.0 + kc);
    /* convergence is quadratic: once c_n < 1e-9 a, c_(n+1) ~ c_n^2/(4a) no
     * longer shows in S or in the mean; 40 rounds cover kc down to 1e-300 */
    for (n = 0; n < 40; n++) {
        const double c = 0.5 * (a - b), an = 0.5 * (a + b);
        b = sqrt(a * b);
        a = an;
        S += pw * c * c;
        pw *= 2.0;
        if (c < 1e-9 * a)
            break;
    }
    *K = 0.5 * RR_PI / a;
    *d_lo = 0.5 * e2 + S;
    *d_hi = 0.5 * e2 - S;
    return RR_OK;
}

int rr_ellip_ke(double mc, double *K, double *E)
{
    double rf, rd;
    int st;

    if (!K || !E)
        return RR_ERR_NULL;
    if (!isfinite(mc)) {
        *K = *E = NAN;
        return RR_ERR_NONFINITE;
    }
    if (mc <= 0.0 || mc > 1.0) {
        *K = *E = NAN;
        return RR_ERR_GEOMETRY;
    }
    if (mc < 1e-150) {
        /* K = ln(4/k') + O(mc ln mc), E = 1 + O(mc ln mc) (DLMF 19.12.1, 19.12.2):
         * exact in double precision here, where R_D(0, 1, mc) ~ 3/mc overflows */
        *K = log(4.0) - 0.5 * log(mc);
        *E = 1.0;
        return RR_OK;
    }
    st = rr_carlson_rf_rd(0.0, mc, 1.0, &rf, &rd);
    *K = rf;
    /* E = K - (m/3) R_D(0, mc, 1) cancels as m -> 1; DLMF 19.25.1's
     * E = (mc/3) [R_D(0, mc, 1) + R_D(0, 1, mc)] has no difference */
    if (mc < 0.5) {
        double rf2, rd2;
        rr_carlson_rf_rd(0.0, 1.0, mc, &rf2, &rd2);
        *E = mc / 3.0 * (rd + rd2);
    } else {
        *E = rf - (1.0 - mc) / 3.0 * rd;
    }
    return st;
}
