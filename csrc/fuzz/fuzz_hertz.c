/*
 * fuzz_hertz.c - the Hertzian contact: rr_estar, rr_hertz, rr_hertz_bodies, and the elliptic
 * integrals it stands on (rr_carlson_rf_rd, rr_ellip_ke, rr_ellip_agm).
 *
 * Input: one byte choosing the function, then its arguments (plausible
 * ranges: curvature sums 0.1 .. 1e4 1/m, loads 1 .. 1e6 N, moduli 1e9 ..
 * 1e12 Pa, Poisson ratios 0 .. 0.5).
 */
#include "fuzz.h"

static int bad_modulus(double E, double nu)
{
    return !isfinite(E) || !isfinite(nu) || !(E > 0.0) || !(nu >= 0.0) || !(nu <= 0.5);
}

/* Known: a subnormal modulus makes 1/E overflow: E* = 0, neither NaN nor usable. */
static int known_estar(double E1, double E2)
{
    return (E1 > 0.0 && E1 < DBL_MIN) || (E2 > 0.0 && E2 < DBL_MIN);
}

static int same(double x, double y)
{
    return x == y || (isnan(x) && isnan(y));
}

/* rr_hertz_bodies on the same moduli and the next bytes' A, B, N: a material
 * error exactly where rr_estar has no modulus, else rr_hertz, bitwise. */
static void check_bodies(fz_in *in, double E1, double nu1, double E2, double nu2, double e)
{
    const double A = fz_log(in, 0.1, 1e4), B = fz_log(in, 0.1, 1e4), N = fz_log(in, 1.0, 1e6);
    rr_hertz_result h, g;
    int st, want;
    fz_note("rr_hertz_bodies(A = %.17g, B = %.17g, N = %.17g, ...)", A, B, N);
    st = rr_hertz_bodies(A, B, N, E1, nu1, E2, nu2, &h);
    fz_status("rr_hertz_bodies", st);
    if (isnan(e)) {
        if (st != RR_ERR_MATERIAL || !isnan(h.a) || !isnan(h.b) || !isnan(h.p0)
            || !isnan(h.delta))
            fz_fail("rr_hertz_bodies: status %d (outputs a = %g) where rr_estar is NaN: "
                    "want RR_ERR_MATERIAL and NaN", st, h.a);
        return;
    }
    want = rr_hertz(A, B, N, e, &g);
    if (st != want || !same(h.a, g.a) || !same(h.b, g.b) || !same(h.p0, g.p0)
        || !same(h.delta, g.delta))
        fz_fail("rr_hertz_bodies: status %d, a = %.17g; rr_hertz on rr_estar: %d, a = %.17g",
                st, h.a, want, g.a);
}

static void check_estar(fz_in *in)
{
    const double E1 = fz_log(in, 1e9, 1e12), nu1 = fz_lin(in, 0.0, 0.5);
    const double E2 = fz_log(in, 1e9, 1e12), nu2 = fz_lin(in, 0.0, 0.5);
    const double e = rr_estar(E1, nu1, E2, nu2);
    const int invalid = bad_modulus(E1, nu1) || bad_modulus(E2, nu2);

    fz_note("rr_estar(E1 = %.17g, nu1 = %.17g, E2 = %.17g, nu2 = %.17g)", E1, nu1, E2, nu2);

    if (fz_known("estar", known_estar(E1, E2)))
        return;
    if (invalid && !isnan(e))
        fz_fail("rr_estar(%g, %g, %g, %g) = %g, not NaN, for an invalid argument", E1, nu1,
                E2, nu2, e);
    /* NaN says "cannot be computed"; any other value must be a usable E* */
    if (!isnan(e) && !(isfinite(e) && e > 0.0))
        fz_fail("rr_estar(%.17g, %.17g, %.17g, %.17g) = %g: neither NaN nor a finite E* > 0",
                E1, nu1, E2, nu2, e);
    check_bodies(in, E1, nu1, E2, nu2, e);
}

/* Known: rr_hertz's 3N/(2 pi E* A_min), its cube root, p0 and the approach
 * under- or overflow for extreme but finite arguments (a = b = 0, inf or
 * NaN with status 0). */
static int known_hertz(double A, double B, double N, double estar)
{
    const double amin = A < B ? A : B, q = N / (estar * amin);
    return !(q > 1e-200 && q < 1e200) || !(A > 1e-100 && A < 1e100) || !(B > 1e-100 && B < 1e100)
        || !(N > 1e-100 && N < 1e100) || !(estar > 1e-100 && estar < 1e100);
}

static void check_hertz(fz_in *in)
{
    const double A = fz_log(in, 0.1, 1e4), B = fz_log(in, 0.1, 1e4);
    const double N = fz_log(in, 1.0, 1e6), estar = fz_log(in, 1e9, 1e12);
    const char *fn = "rr_hertz";
    rr_hertz_result h;
    const int invalid = !isfinite(A) || !isfinite(B) || !isfinite(N) || !isfinite(estar)
                        || !(A > 0.0) || !(B > 0.0) || !(N > 0.0) || !(estar > 0.0);
    int st;

    fz_note("rr_hertz(A = %.17g, B = %.17g, N = %.17g, estar = %.17g)", A, B, N, estar);
    memset(&h, 0x55, sizeof h);
    st = rr_hertz(A, B, N, estar, &h);
    fz_status(fn, st);
    fz_error(fn, st, invalid, "an argument is invalid");
    if (st < 0) {
        if (!isnan(h.a) || !isnan(h.b) || !isnan(h.p0) || !isnan(h.delta))
            fz_fail("rr_hertz: error %d but the outputs are not NaN", st);
        return;
    }
    if (fz_known("hertz", known_hertz(A, B, N, estar)))
        return;
    /* the approach may underflow to 0; the semi-axes may not, or p0 is infinite */
    if (!(isfinite(h.a) && h.a > 0.0 && isfinite(h.b) && h.b > 0.0 && isfinite(h.p0)
          && h.p0 > 0.0 && isfinite(h.delta) && h.delta >= 0.0))
        fz_fail("rr_hertz(%.17g, %.17g, %.17g, %.17g): status %d with a = %g, b = %g, "
                "p0 = %g, delta = %g (a, b, p0 finite and > 0, delta finite)", A, B, N, estar,
                st, h.a, h.b, h.p0, h.delta);
    /* the long axis lies along the smaller curvature sum */
    if ((A < B && h.a < h.b) || (A > B && h.a > h.b))
        fz_fail("rr_hertz(%.17g, %.17g, ...): a = %.17g, b = %.17g: the long axis is not "
                "along the smaller curvature sum", A, B, h.a, h.b);
}

/* Known: near DBL_MAX the duplication's sums overflow, a spread of many
 * hundred decades is not closed in its 60 steps (NaN with status 0), and
 * R_D ~ z^(-3/2) overflows for tiny arguments (inf with status 0). */
static int known_carlson(double x, double y, double z)
{
    const double hi = fmax(x, fmax(y, z));
    double lo = hi;
    if (x > 0.0) lo = fmin(lo, x);
    if (y > 0.0) lo = fmin(lo, y);
    lo = fmin(lo, z);
    return hi > 1e290 || lo < 1e-200 || hi / lo > 1e250;
}

static void check_carlson(fz_in *in)
{
    const double x = fz_log(in, 1e-6, 1e6), y = fz_log(in, 1e-6, 1e6);
    const double z = fz_log(in, 1e-6, 1e6);
    const char *fn = "rr_carlson_rf_rd";
    double rf = 7.0, rd = 7.0;
    const int invalid = !isfinite(x) || !isfinite(y) || !isfinite(z) || !(x >= 0.0)
                        || !(y >= 0.0) || !(z > 0.0) || (x == 0.0 && y == 0.0);
    int st;

    fz_note("rr_carlson_rf_rd(%.17g, %.17g, %.17g)", x, y, z);
    st = rr_carlson_rf_rd(x, y, z, &rf, &rd);

    fz_status(fn, st);
    fz_error(fn, st, invalid, "an argument is invalid");
    if (fz_known("carlson", known_carlson(x, y, z)))
        return;
    /* R_D ~ z^(-3/2) may underflow to 0: that is rounding, not an error */
    if (st >= 0 && !(isfinite(rf) && rf > 0.0 && isfinite(rd) && rd >= 0.0))
        fz_fail("rr_carlson_rf_rd(%.17g, %.17g, %.17g): status %d with R_F = %g, R_D = %g", x,
                y, z, st, rf, rd);
}

static void check_ke(fz_in *in)
{
    const double mc = fz_log(in, 1e-300, 1.0), kc = fz_log(in, 1e-150, 1.0);
    double K = 7.0, E = 7.0, d_lo = 7.0, d_hi = 7.0;
    int st;

    fz_note("rr_ellip_ke(mc = %.17g), rr_ellip_agm(kc = %.17g)", mc, kc);
    st = rr_ellip_ke(mc, &K, &E);

    fz_status("rr_ellip_ke", st);
    fz_error("rr_ellip_ke", st, !isfinite(mc) || !(mc > 0.0) || !(mc <= 1.0),
             "mc is outside (0, 1]");
    /* K >= pi/2 and 1 <= E <= pi/2 on (0, 1]; known: a subnormal mc gives E = inf
     * or NaN with status 0 */
    if (st >= 0 && !fz_known("ellip_ke", mc < DBL_MIN) && !(isfinite(K) && K >= 0.5 * RR_PI * (1.0 - 1e-14) && isfinite(E)
                     && E >= 1.0 - 1e-14 && E <= 0.5 * RR_PI * (1.0 + 1e-14)))
        fz_fail("rr_ellip_ke(%.17g): status %d with K = %.17g, E = %.17g", mc, st, K, E);

    st = rr_ellip_agm(kc, &K, &d_lo, &d_hi);
    fz_status("rr_ellip_agm", st);
    fz_error("rr_ellip_agm", st, !isfinite(kc) || !(kc > 0.0) || !(kc <= 1.0),
             "kc is outside (0, 1]");
    /* (K - E)/K and (E - kc^2 K)/K lie in [0, 1] */
    if (st >= 0 && !(isfinite(K) && K >= 0.5 * RR_PI * (1.0 - 1e-14) && d_lo >= 0.0
                     && d_lo <= 1.0 && d_hi >= 0.0 && d_hi <= 1.0))
        fz_fail("rr_ellip_agm(%.17g): status %d with K = %.17g, d_lo = %.17g, d_hi = %.17g",
                kc, st, K, d_lo, d_hi);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    switch (fz_choice(&in, 4)) {
    case 0:
        check_hertz(&in);
        break;
    case 1:
        check_estar(&in);
        break;
    case 2:
        check_carlson(&in);
        break;
    default:
        check_ke(&in);
        break;
    }
    return 0;
}
