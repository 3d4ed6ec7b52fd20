/*
 * fuzz_kalker.c - Kalker's creep coefficients rr_kalker(a/b, nu).
 *
 * Input: a/b (plausibly 1e-4 .. 1e4), nu (0 .. 0.5).  Besides finiteness
 * the coefficients must be positive, and the header's promise that the
 * asymptotic formulas meet the table at g = 0.1 "within about 6 %" is
 * held to 10 %; C33's continuations meet it (to 1e-9).
 */
#include "fuzz.h"

/* Known: g = min(a/b, b/a) so small that the asymptotes overflow (c33 ~
 * 1/g for a subnormal a/b; a/b above about 1e205 makes g^1.5 underflow). */
static int known_kalker(double a_over_b)
{
    return a_over_b < 1e-290 || a_over_b > 1e200;
}

static void check(const char *fn, double a_over_b, double nu, int st, const rr_kalker_coeffs *k)
{
    const int invalid = !isfinite(a_over_b) || !isfinite(nu) || !(a_over_b > 0.0)
                        || !(nu >= 0.0) || !(nu <= 0.5);
    fz_status(fn, st);
    fz_error(fn, st, invalid, "an argument is invalid");
    if (st < 0) {
        if (!isnan(k->c11) || !isnan(k->c22) || !isnan(k->c23) || !isnan(k->c33))
            fz_fail("%s: error %d but the coefficients are not NaN", fn, st);
        return;
    }
    if (fz_known("kalker", known_kalker(a_over_b)))
        return;
    if (!(isfinite(k->c11) && k->c11 > 0.0 && isfinite(k->c22) && k->c22 > 0.0
          && isfinite(k->c23) && k->c23 > 0.0 && isfinite(k->c33) && k->c33 > 0.0))
        fz_fail("%s(%.17g, %.17g): status %d with C11 = %g, C22 = %g, C23 = %g, C33 = %g "
                "(each must be finite and > 0)", fn, a_over_b, nu, st, k->c11, k->c22,
                k->c23, k->c33);
}

static void check_seam(double nu, int half)
{
    /* g = 0.1 from the table and just below it from the asymptotes */
    const double g_in = 0.1, g_out = nextafter(0.1, 0.0);
    const double r_in = half ? 1.0 / g_in : g_in, r_out = half ? 1.0 / g_out : g_out;
    rr_kalker_coeffs a, b;
    int i;

    if (rr_kalker(r_in, nu, &a) != RR_OK || rr_kalker(r_out, nu, &b) != RR_OK)
        return;
    for (i = 0; i < 4; i++) {
        static const char *const name[4] = {"11", "22", "23", "33"};
        const double x = i == 0 ? a.c11 : i == 1 ? a.c22 : i == 2 ? a.c23 : a.c33;
        const double y = i == 0 ? b.c11 : i == 1 ? b.c22 : i == 2 ? b.c23 : b.c33;
        /* C33's continuations meet the table by construction: one ulp of g
         * and rounding, 1e-9 */
        const double tol = i == 3 ? 1e-9 : 0.10;
        if (!(fabs(x - y) <= tol * fabs(x)))
            fz_fail("rr_kalker: at g = 0.1 (a/b = %.17g, nu = %.17g) C%s jumps from %.6g "
                    "(table) to %.6g (asymptote), more than %g %%", r_in, nu, name[i], x, y,
                    100.0 * tol);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    const double a_over_b = fz_log(&in, 1e-4, 1e4), nu = fz_lin(&in, 0.0, 0.5);
    rr_kalker_coeffs k;
    int st;

    fz_note("rr_kalker(a_over_b = %.17g, nu = %.17g)", a_over_b, nu);
    memset(&k, 0x55, sizeof k);
    st = rr_kalker(a_over_b, nu, &k);
    check("rr_kalker", a_over_b, nu, st, &k);
    if (isfinite(nu) && nu >= 0.0 && nu <= 0.5)
        check_seam(nu, fz_choice(&in, 2));
    return 0;
}
