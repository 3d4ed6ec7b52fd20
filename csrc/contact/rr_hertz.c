/* rr_hertz.c - Hertzian contact ellipse (Johnson 1985, section 4.2). */
#include <math.h>
#include "util/rr_common.h"
#include "util/rr_elliptic.h"
#include "contact/rr_hertz.h"

double rr_estar(double E1, double nu1, double E2, double nu2)
{
    double r;
    if (!isfinite(E1) || !isfinite(E2) || !isfinite(nu1) || !isfinite(nu2)
        || E1 <= 0.0 || E2 <= 0.0 || nu1 < 0.0 || nu1 > 0.5 || nu2 < 0.0 || nu2 > 0.5)
        return NAN;
    r = 1.0 / ((1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2);
    /* a subnormal modulus overflows 1/E: no representable E* */
    return isfinite(r) && r > 0.0 ? r : NAN;
}

/* ln of the curvature ratio max/min produced by ellipticity k = exp(t):
 * (E/k^2 - K)/(K - E) = (E - k^2 K) / (k^2 (K - E)), both differences from
 * the AGM without cancellation (rr_ellip_agm). */
static double log_ratio(double t, double *K, double *d_lo)
{
    double k = exp(t), d_hi;
    rr_ellip_agm(k, K, d_lo, &d_hi);
    return log(d_hi / *d_lo) - 2.0 * t;
}

static void set_nan(rr_hertz_result *out)
{
    out->a = out->b = out->p0 = out->delta = NAN;
}

/* (num/den)^(1/3) without overflow or underflow on the way where the
 * result itself is representable: the direct quotient where it is a normal
 * number (so that ordinary inputs keep their rounding), else factor by factor. */
static double cbrt_ratio(double n1, double n2, double d1, double d2)
{
    const double num = n1 * n2, den = d1 * d2, q = num / den;
    if (isnormal(num) && isnormal(den) && isnormal(q))
        return cbrt(q);
    return cbrt(n1) * cbrt(n2) / (cbrt(d1) * cbrt(d2));
}

int rr_hertz(double A, double B, double N, double estar, rr_hertz_result *out)
{
    double amin, rho, lrho, K, d_lo, t, major, minor, k;

    if (!out)
        return RR_ERR_NULL;
    if (!isfinite(A) || !isfinite(B) || !isfinite(N)) {
        set_nan(out);
        return RR_ERR_NONFINITE;
    }
    if (A <= 0.0 || B <= 0.0) {
        set_nan(out);
        return RR_ERR_GEOMETRY;
    }
    if (N <= 0.0) {
        set_nan(out);
        return RR_ERR_LOAD;
    }
    if (!(estar > 0.0) || !isfinite(estar)) {
        set_nan(out);
        return RR_ERR_MATERIAL;
    }
    amin = A < B ? A : B;
    rho = (A < B ? B : A) / amin;
    if (rho > 1e250) {               /* beyond the secant's bracket, k < 1e-150 */
        set_nan(out);
        return RR_ERR_GEOMETRY;
    }
    lrho = log(rho);

    if (lrho < 1e-15) {
        t = 0.0;                          /* circular contact */
        K = 0.5 * RR_PI;
        d_lo = 0.0;
    } else {
        /* f(t) = log_ratio(t) - ln(rho) falls monotonically in t = ln k,
         * from +inf as t -> -inf to -ln(rho) at t = 0.  Greenwood's
         * k ~ rho^(-2/3) starts a secant whose slope is about -3/2
         * everywhere; the bracket [t_lo, t_hi] catches a wild step. */
        double t_lo = -350.0, t_hi = 0.0, t0, f0, t1, f1;
        int it;

        t0 = -2.0 / 3.0 * lrho;
        f0 = log_ratio(t0, &K, &d_lo) - lrho;
        t1 = t0 + f0 / 1.5;
        for (it = 0; it < 200; it++) {
            double tn;
            if (!(t1 > t_lo && t1 < t_hi))
                t1 = 0.5 * (t_lo + t_hi);
            f1 = log_ratio(t1, &K, &d_lo) - lrho;
            if (f1 > 0.0)
                t_lo = t1;
            else
                t_hi = t1;
            if (fabs(f1) < 2e-16 * (1.0 + lrho) || fabs(t1 - t0) < 1e-15 * fabs(t1))
                break;
            tn = (f1 != f0) ? t1 - f1 * (t1 - t0) / (f1 - f0) : 0.5 * (t_lo + t_hi);
            t0 = t1;
            f0 = f1;
            t1 = tn;
        }
        t = t1;
    }
    k = exp(t);
    {
        /* major^3 = 3N (K - E) / (2 pi E* e^2 A_min); (K - E)/e^2 -> pi/4 as e -> 0 */
        const double e2 = (1.0 - k) * (1.0 + k);
        const double kme_e2 = e2 > 0.0 ? K * d_lo / e2 : 0.25 * RR_PI;
        major = cbrt_ratio(3.0 * N, kme_e2, 2.0 * RR_PI * estar, amin);
    }
    minor = k * major;
    if (A <= B) {
        out->a = major;
        out->b = minor;
    } else {
        out->a = minor;
        out->b = major;
    }
    out->p0 = 1.5 * N / (RR_PI * out->a * out->b);
    if (!isnormal(out->p0))
        out->p0 = 1.5 / RR_PI * (N / major) / minor;      /* a b out of range */
    out->delta = out->p0 * minor * K / estar;    /* Johnson eq. (4.41) */
    if (!isnormal(out->delta))
        out->delta = 1.5 / RR_PI * (N / major) * (K / estar);
    if (!isnormal(out->a) || !isnormal(out->b) || !isnormal(out->p0)
        || !isnormal(out->delta)) {
        set_nan(out);
        return RR_ERR_RANGE;
    }
    return RR_OK;
}

int rr_hertz_bodies(double A, double B, double N, double E1, double nu1, double E2, double nu2,
                    rr_hertz_result *out)
{
    const double estar = rr_estar(E1, nu1, E2, nu2);
    if (!out)
        return RR_ERR_NULL;
    if (isnan(estar)) {
        set_nan(out);
        return RR_ERR_MATERIAL;
    }
    return rr_hertz(A, B, N, estar, out);
}

int rr_hertz_curvatures(double a, double b, double N, double estar, double *A, double *B)
{
    double major, minor, k, e2, K, d_lo, d_hi, p0, s, c_lo, c_hi;
    int st = RR_OK;

    if (!A || !B)
        return RR_ERR_NULL;
    if (!isfinite(a) || !isfinite(b) || !isfinite(N) || !isfinite(estar))
        st = RR_ERR_NONFINITE;
    else if (!(a > 0.0) || !(b > 0.0) || !isnormal(a) || !isnormal(b))
        st = RR_ERR_GEOMETRY;
    else if (!(N > 0.0))
        st = RR_ERR_LOAD;
    else if (!(estar > 0.0))
        st = RR_ERR_MATERIAL;
    if (st < 0) {
        *A = *B = NAN;
        return st;
    }
    major = a > b ? a : b;
    minor = a > b ? b : a;
    k = minor / major;
    if (!(k > 1e-150)) {
        *A = *B = NAN;
        return RR_ERR_GEOMETRY;
    }
    e2 = (1.0 - k) * (1.0 + k);
    rr_ellip_agm(k, &K, &d_lo, &d_hi);
    /* Johnson (3.64) with p0 = 3N/(2 pi a b): the major axis lies along the
     * smaller curvature, (p0 minor / (E* major^2)) (K - E)/e^2, the other
     * (.. ) (E/k^2 - K)/e^2 = (.. ) (E - k^2 K)/(k^2 e^2); both -> pi/4 as
     * e -> 0, where the AGM's differences are of order e^2 */
    if (e2 > 1e-12) {
        c_lo = K * d_lo / e2;
        c_hi = K * d_hi / (k * k * e2);
    } else {
        c_lo = c_hi = 0.25 * RR_PI;
    }
    p0 = 1.5 / RR_PI * (N / major) / minor;
    s = (p0 / estar) * (minor / major) / major;
    if (a >= b) {
        *A = s * c_lo;
        *B = s * c_hi;
    } else {
        *A = s * c_hi;
        *B = s * c_lo;
    }
    if (!isnormal(*A) || !isnormal(*B)) {
        *A = *B = NAN;
        return RR_ERR_RANGE;
    }
    return RR_OK;
}
