/*
 * test_kalker.c - Kalker's creep coefficients C11, C22, C23, C33 (rr_kalker).
 *
 * The table below is this test's own copy of
 * tests/data/kalker_creep_coefficients.csv (C11, C22, C23), whose source line
 * reads: Kalker (1990) 'Three-Dimensional Elastic Bodies in Rolling Contact',
 * Table E.3, as transcribed in github.com/eve70a/CONTACT (Apache-2.0) commit
 * d431cdbd1250, src/m_hertz.f90, subroutine linrol (data statement), and of
 * tests/data/kalker_c33.csv (C33: the same table as transcribed in
 * github.com/wangjianbin123/OpenVSD, WRcontForce.cpp, a single transcription).
 * The asymptotic formulas for g < 0.1 of C11, C22, C23 are retyped from the
 * same subroutine (Kalker's thesis, 1967), the reference the header cites;
 * C33's continuations below g = 0.1 from the header (CONTACT has none).
 */
#include <math.h>
#include <stdio.h>
#include "util/rr_common.h"
#include "contact/rr_kalker.h"
#include "rr_test.h"

/* [half][row: g = 0.1 (row + 1)][nu = 0, 0.25, 0.5][C11, C22, C23, C33],
 * half 0: a <= b (g = a/b), half 1: a >= b (g = b/a); CSV row order. */
static const double table[2][10][3][4] = {
    {   /* a <= b */
        {{2.51, 2.51, 0.334, 6.42}, {3.31, 2.52, 0.473, 8.28}, {4.85, 2.53, 0.731, 11.7}},
        {{2.59, 2.59, 0.483, 3.46}, {3.37, 2.63, 0.603, 4.27}, {4.81, 2.66, 0.809, 5.66}},
        {{2.68, 2.68, 0.607, 2.49}, {3.44, 2.75, 0.715, 2.96}, {4.8, 2.81, 0.889, 3.72}},
        {{2.78, 2.78, 0.72, 2.02}, {3.53, 2.88, 0.823, 2.32}, {4.82, 2.98, 0.977, 2.77}},
        {{2.88, 2.88, 0.827, 1.74}, {3.62, 3.01, 0.929, 1.93}, {4.83, 3.14, 1.07, 2.22}},
        {{2.98, 2.98, 0.93, 1.56}, {3.72, 3.14, 1.03, 1.68}, {4.91, 3.31, 1.18, 1.86}},
        {{3.09, 3.09, 1.03, 1.43}, {3.81, 3.28, 1.14, 1.5}, {4.97, 3.48, 1.29, 1.6}},
        {{3.19, 3.19, 1.13, 1.34}, {3.91, 3.41, 1.25, 1.37}, {5.05, 3.65, 1.4, 1.42}},
        {{3.29, 3.29, 1.23, 1.27}, {4.01, 3.54, 1.36, 1.27}, {5.12, 3.82, 1.51, 1.27}},
        {{3.4, 3.4, 1.33, 1.21}, {4.12, 3.67, 1.47, 1.19}, {5.2, 3.98, 1.63, 1.16}}
    },
    {   /* a >= b */
        {{10.7, 10.7, 12.2, 0.795}, {11.7, 12.8, 14.6, 0.526}, {12.9, 16.0, 18.0, 0.228}},
        {{6.96, 6.96, 5.72, 0.828}, {7.78, 8.14, 6.63, 0.601}, {8.82, 9.79, 7.89, 0.341}},
        {{5.57, 5.57, 3.79, 0.868}, {6.34, 6.4, 4.32, 0.674}, {7.34, 7.51, 5.01, 0.446}},
        {{4.84, 4.84, 2.88, 0.912}, {5.57, 5.48, 3.24, 0.747}, {6.57, 6.31, 3.7, 0.549}},
        {{4.37, 4.37, 2.35, 0.958}, {5.1, 4.9, 2.62, 0.819}, {6.11, 5.56, 2.96, 0.65}},
        {{4.06, 4.06, 2.01, 1.01}, {4.78, 4.5, 2.23, 0.892}, {5.8, 5.04, 2.5, 0.751}},
        {{3.82, 3.82, 1.76, 1.05}, {4.54, 4.21, 1.95, 0.965}, {5.58, 4.67, 2.18, 0.852}},
        {{3.65, 3.65, 1.58, 1.1}, {4.36, 3.99, 1.75, 1.04}, {5.42, 4.39, 1.94, 0.954}},
        {{3.51, 3.51, 1.44, 1.16}, {4.22, 3.81, 1.59, 1.11}, {5.3, 4.16, 1.77, 1.06}},
        {{3.4, 3.4, 1.33, 1.21}, {4.12, 3.67, 1.47, 1.19}, {5.2, 3.98, 1.63, 1.16}}
    }
};
static const double table_nu[3] = {0.0, 0.25, 0.5};
static const char *const half_name[2] = {"a <= b", "a >= b"};
static const char *const coef_name[4] = {"C11", "C22", "C23", "C33"};

static double coef(const rr_kalker_coeffs *k, int i)
{
    return i == 0 ? k->c11 : i == 1 ? k->c22 : i == 2 ? k->c23 : k->c33;
}

/* a/b of the point g in a table half */
static double a_over_b(int half, double g)
{
    return half == 0 ? g : 1.0 / g;
}

/* nu = 0.5 (incompressible) is the table's third column and accepted. */
static double usable_nu(int inu)
{
    return table_nu[inu];
}

static void test_nodes(void)
{
    int half, row, inu, ic;
    char buf[160];

    for (half = 0; half < 2; half++)
        for (row = 0; row < 10; row++)
            for (inu = 0; inu < 3; inu++) {
                rr_kalker_coeffs k;
                double g = (row + 1) / 10.0;
                int st = rr_kalker(a_over_b(half, g), usable_nu(inu), &k);
                snprintf(buf, sizeof buf, "node %s g = %.1f nu = %.2f: status",
                         half_name[half], g, table_nu[inu]);
                CHECK_STATUS(st, RR_OK, buf);
                for (ic = 0; ic < 4; ic++) {
                    snprintf(buf, sizeof buf, "node %s g = %.1f nu = %.2f: %s",
                             half_name[half], g, table_nu[inu], coef_name[ic]);
                    /* nodes: 1/(1/C) and g = 1/(1/g) round-trip within an ulp or
                     * two: 1e-12 */
                    CHECK_CLOSE(coef(&k, ic), table[half][row][inu][ic], 0.0, 1e-12, buf);
                }
            }
    /* nu = 0.5 is accepted and exactly the table's column; just above it is not */
    {
        rr_kalker_coeffs k;
        int st = rr_kalker(0.5, 0.5, &k);
        CHECK_STATUS(st, RR_OK, "nu = 0.5 accepted (range [0, 0.5])");
        CHECK(k.c11 == 4.83 && k.c22 == 3.14 && k.c23 == 1.07 && k.c33 == 2.22,
              "nu = 0.5, a/b = 0.5: the node");
        st = rr_kalker(0.5, nextafter(0.5, 1.0), &k);
        CHECK_STATUS(st, RR_ERR_MATERIAL, "nu just above 0.5 rejected");
        CHECK(isnan(k.c11) && isnan(k.c22) && isnan(k.c23) && isnan(k.c33),
              "nu > 0.5: NaN outputs");
    }
    /* a = b: both halves' shared row, same answer whichever side it is met from */
    {
        rr_kalker_coeffs lo, hi;
        rr_kalker(nextafter(1.0, 0.0), 0.28, &lo);
        rr_kalker(nextafter(1.0, 2.0), 0.28, &hi);
        /* continuous across a/b = 1: the two halves share row g = 1 */
        CHECK_CLOSE(lo.c11, hi.c11, 0.0, 1e-12, "C11 continuous across a/b = 1");
        CHECK_CLOSE(lo.c22, hi.c22, 0.0, 1e-12, "C22 continuous across a/b = 1");
        CHECK_CLOSE(lo.c23, hi.c23, 0.0, 1e-12, "C23 continuous across a/b = 1");
        CHECK_CLOSE(lo.c33, hi.c33, 0.0, 1e-12, "C33 continuous across a/b = 1");
    }
}

/* Between two rows, at a tabulated nu, C is linear in g (g = a/b or b/a). */
static void test_linear_in_g(void)
{
    static const double fr[] = {0.125, 0.25, 0.5, 0.73, 0.9};
    int half, row, inu, ic;
    unsigned f;
    char buf[160];

    for (half = 0; half < 2; half++)
        for (row = 0; row < 9; row++)
            for (f = 0; f < sizeof fr / sizeof fr[0]; f++)
                for (inu = 0; inu < 3; inu++) {
                    rr_kalker_coeffs k;
                    double g = (row + 1 + fr[f]) / 10.0;
                    int st = rr_kalker(a_over_b(half, g), usable_nu(inu), &k);
                    if (!CHECK_STATUS(st, RR_OK, "rr_kalker status between nodes"))
                        continue;
                    for (ic = 0; ic < 4; ic++) {
                        double c0 = table[half][row][inu][ic];
                        double c1 = table[half][row + 1][inu][ic];
                        double w = 10.0 * g - (row + 1);   /* the g actually passed */
                        snprintf(buf, sizeof buf, "%s g = %.4f nu = %.2f: %s linear in g",
                                 half_name[half], g, table_nu[inu], coef_name[ic]);
                        /* the interpolation weight is recomputed from g (and
                         * from 1/(1/g) in the a >= b half): ~1e-15 */
                        CHECK_CLOSE(coef(&k, ic), c0 + w * (c1 - c0), 0.0, 1e-12, buf);
                    }
                }
}

/* Between tabulated nu, 1/C is the parabola through the three nodes. */
static void test_nu_parabola(void)
{
    static const double nus[] = {0.1, 0.28, 0.3, 0.4, 0.49};
    int half, row, ic;
    unsigned j;
    char buf[160];

    for (half = 0; half < 2; half++)
        for (row = 0; row < 10; row += 3)
            for (j = 0; j < sizeof nus / sizeof nus[0]; j++) {
                rr_kalker_coeffs k;
                double g = (row + 1) / 10.0, nu = nus[j];
                rr_kalker(a_over_b(half, g), nu, &k);
                for (ic = 0; ic < 4; ic++) {
                    const double *c0 = table[half][row][0], *c1 = table[half][row][1],
                                 *c2 = table[half][row][2];
                    double l0 = (nu - 0.25) * (nu - 0.5) / ((0.0 - 0.25) * (0.0 - 0.5));
                    double l1 = (nu - 0.0) * (nu - 0.5) / ((0.25 - 0.0) * (0.25 - 0.5));
                    double l2 = (nu - 0.0) * (nu - 0.25) / ((0.5 - 0.0) * (0.5 - 0.25));
                    double inv = l0 / c0[ic] + l1 / c1[ic] + l2 / c2[ic];
                    snprintf(buf, sizeof buf, "%s g = %.1f nu = %.2f: 1/%s parabolic in nu",
                             half_name[half], g, nu, coef_name[ic]);
                    /* the same Lagrange sum in another order: ~1e-15 */
                    CHECK_CLOSE(1.0 / coef(&k, ic), inv, 0.0, 1e-12, buf);
                }
            }
}

/* The table's value of coefficient ic in row 0 (g = 0.1) at nu: the nodes
 * as typed, else 1 over the Lagrange parabola through 1/C. */
static double row0(int half, int ic, double nu)
{
    const double c0 = table[half][0][0][ic], c1 = table[half][0][1][ic],
                 c2 = table[half][0][2][ic];
    if (nu == 0.0 || nu == 0.25 || nu == 0.5)
        return nu == 0.0 ? c0 : nu == 0.25 ? c1 : c2;
    return 1.0 / ((nu - 0.25) * (nu - 0.5) / 0.125 / c0 - nu * (nu - 0.5) / 0.0625 / c1
                  + nu * (nu - 0.25) / 0.125 / c2);
}

/* Kalker's asymptotes for g -> 0, as in CONTACT's linrol; C33's
 * continuations as the header states them. */
static void asymptote(int half, double g, double nu, double c[4])
{
    if (half == 0) {
        const double k = RR_PI * RR_PI / 16.0 / (1.0 - nu);
        c[0] = RR_PI * RR_PI / 4.0 / (1.0 - nu);
        c[1] = RR_PI * RR_PI / 4.0;
        c[2] = RR_PI * sqrt(g) / 3.0 / (1.0 - nu) * (1.0 + nu * (log(16.0 / g) - 5.0));
        c[3] = k / g + row0(0, 3, nu) - k / 0.1;    /* strip theory + constant */
    } else {
        double al = log(16.0 / (g * g));
        c[0] = 2.0 * RR_PI / (al - 2.0 * nu) / g * (1.0 + (3.0 - log(4.0)) / (al - 2.0 * nu));
        c[1] = 2.0 * RR_PI / g
             * (1.0 + (1.0 - nu) * (3.0 - log(4.0)) / ((1.0 - nu) * al + 2.0 * nu))
             / ((1.0 - nu) * al + 2.0 * nu);
        c[2] = 2.0 * RR_PI / 3.0 / pow(g, 1.5) / ((1.0 - nu) * al - 2.0 + 4.0 * nu);
        c[3] = row0(1, 3, nu);                       /* held at g = 0.1 */
    }
}

static void test_asymptotic(void)
{
    static const double gs[] = {0.0999, 0.05, 0.01, 1e-3, 1e-6, 1e-12, 1e-100};
    static const double nus[] = {0.0, 0.25, 0.28, 0.49};
    int half, ic;
    unsigned i, j;
    char buf[160];
    double maxgap = 0.0;

    for (half = 0; half < 2; half++)
        for (j = 0; j < sizeof nus / sizeof nus[0]; j++) {
            double prev[4] = {0.0, 0.0, 0.0, 0.0};
            for (i = 0; i < sizeof gs / sizeof gs[0]; i++) {
                rr_kalker_coeffs k;
                double want[4];
                int st = rr_kalker(a_over_b(half, gs[i]), nus[j], &k);
                asymptote(half, gs[i], nus[j], want);
                /* the header documents status 0 below g = 0.1 (not
                 * RR_WARN_EXTRAPOLATED; see the report) */
                snprintf(buf, sizeof buf, "asymptotic %s g = %g nu = %.2f: status",
                         half_name[half], gs[i], nus[j]);
                CHECK_STATUS(st, RR_OK, buf);
                for (ic = 0; ic < 4; ic++) {
                    double c = coef(&k, ic);
                    snprintf(buf, sizeof buf, "asymptotic %s g = %g nu = %.2f: %s finite > 0",
                             half_name[half], gs[i], nus[j], coef_name[ic]);
                    CHECK(isfinite(c) && c > 0.0, buf);
                    snprintf(buf, sizeof buf, "asymptotic %s g = %g nu = %.2f: %s formula",
                             half_name[half], gs[i], nus[j], coef_name[ic]);
                    /* same closed forms, differently grouped; g = 1/(1/g) in the
                     * a >= b half; C33's offset k/g - 10 k cancels to ~1e-15 of
                     * k/g at g = 0.0999: 1e-13 */
                    CHECK_CLOSE(c, want[ic], 0.0, 1e-13, buf);
                    /* as g falls: C11, C22 of a >= b grow like 1/g, C23 like
                     * g^-3/2, C33 stays; for a <= b C23 falls like sqrt(g),
                     * C33 grows like 1/g */
                    if (i > 0) {
                        snprintf(buf, sizeof buf, "asymptotic %s g = %g nu = %.2f: %s trend",
                                 half_name[half], gs[i], nus[j], coef_name[ic]);
                        if (ic == 3)
                            CHECK(half == 1 ? c == prev[ic] : c > prev[ic], buf);
                        else if (half == 1)
                            CHECK(c > prev[ic], buf);
                        else if (ic == 2)
                            CHECK(c < prev[ic], buf);
                        else
                            CHECK(c == prev[ic], buf);   /* constant in g */
                    }
                    prev[ic] = c;
                }
            }
        }

    /* Continuity from the left at g = 0.1: the asymptotic branch has a limit
     * there (values at 0.1 (1 - 1e-9) and 0.1 (1 - 1e-7) agree), and it meets
     * the table at g = 0.1 with a bounded jump. */
    for (half = 0; half < 2; half++)
        for (j = 0; j < 3; j++) {
            rr_kalker_coeffs k1, k2, kt;
            double nu = usable_nu((int)j);
            rr_kalker(a_over_b(half, 0.1 * (1.0 - 1e-9)), nu, &k1);
            rr_kalker(a_over_b(half, 0.1 * (1.0 - 1e-7)), nu, &k2);
            rr_kalker(a_over_b(half, 0.1), nu, &kt);
            for (ic = 0; ic < 4; ic++) {
                double gap = fabs(coef(&k1, ic) / coef(&kt, ic) - 1.0);
                snprintf(buf, sizeof buf, "%s nu = %.2f: %s left limit at g = 0.1 exists",
                         half_name[half], table_nu[j], coef_name[ic]);
                /* smooth closed forms, |dlnC/dlng| <= 2: a step of 1e-7 in ln g
                 * moves C by < 2e-7: 1e-6 */
                CHECK_CLOSE(coef(&k2, ic), coef(&k1, ic), 0.0, 1e-6, buf);
                snprintf(buf, sizeof buf, "%s nu = %.2f: %s jump at g = 0.1 (%.2f %%)",
                         half_name[half], table_nu[j], coef_name[ic], 100.0 * gap);
                /* measured: up to 6.0 % (C23, a <= b, nu -> 0.5); the header says
                 * "within 2 %", true only for some coefficients (see the report) */
                CHECK(gap < 0.065, buf);
                if (ic == 3) {
                    snprintf(buf, sizeof buf, "%s nu = %.2f: C33 continuous at g = 0.1",
                             half_name[half], table_nu[j]);
                    /* C33's continuations meet the table by construction: a step
                     * of 1e-9 in g moves C33 ~ 1/g by 1e-9, rounding ~1e-15: 2e-9 */
                    CHECK(gap <= 2e-9, buf);
                } else if (gap > maxgap) {
                    maxgap = gap;
                }
            }
        }
    CHECK(maxgap > 0.0, "the asymptotes and the table differ at g = 0.1 (no exact match)");
    {
        /* the header's own example: C11 for a << b at nu = 0, 2.47 against 2.51 */
        rr_kalker_coeffs k;
        rr_kalker(0.0999999, 0.0, &k);
        /* the header's rounded numbers: 2 figures after the point */
        CHECK_CLOSE(k.c11, 2.47, 0.005, 0.0, "header example: C11(a << b, nu = 0) = 2.47");
        /* within the documented 2 % of the table's 2.51 */
        CHECK_CLOSE(k.c11, 2.51, 0.0, 0.02, "header example: within 2 % of 2.51");
    }
}

static void test_bad_input(void)
{
    static const struct {
        double aob, nu;
        int status;
        const char *what;
    } t[] = {
        {0.0, 0.3, RR_ERR_GEOMETRY, "a/b = 0"},
        {-1.0, 0.3, RR_ERR_GEOMETRY, "a/b < 0"},
        {NAN, 0.3, RR_ERR_NONFINITE, "a/b NaN"},
        {INFINITY, 0.3, RR_ERR_NONFINITE, "a/b inf"},
        {1.0, NAN, RR_ERR_NONFINITE, "nu NaN"},
        {1.0, -0.01, RR_ERR_MATERIAL, "nu < 0"},
        {1.0, 0.5000000000000001, RR_ERR_MATERIAL, "nu just above 0.5"},
        {1.0, 0.7, RR_ERR_MATERIAL, "nu > 0.5"}
    };
    unsigned i;

    for (i = 0; i < sizeof t / sizeof t[0]; i++) {
        rr_kalker_coeffs k;
        int st;
        k.c11 = k.c22 = k.c23 = k.c33 = 1.0;
        st = rr_kalker(t[i].aob, t[i].nu, &k);
        CHECK_STATUS(st, t[i].status, t[i].what);
        CHECK(isnan(k.c11) && isnan(k.c22) && isnan(k.c23) && isnan(k.c33), t[i].what);
    }
}

/* Extreme ratios: finite coefficients where representable, else RANGE. */
static void test_extremes(void)
{
    rr_kalker_coeffs k;
    int st = rr_kalker(1e-308, 0.28, &k);
    CHECK_STATUS(st, RR_OK, "a/b = 1e-308 (16/g overflows, its log does not)");
    CHECK(isfinite(k.c23) && k.c23 > 0.0, "a/b = 1e-308: C23 finite");
    /* C23 ~ pi sqrt(g)/(3 (1 - nu)) (1 + nu (ln(16/g) - 5)), ln(16/g) by parts */
    CHECK_CLOSE(k.c23, RR_PI * sqrt(1e-308) / (3.0 * 0.72)
                * (1.0 + 0.28 * (log(16.0) - log(1e-308) - 5.0)), 0.0, 1e-13,
                "a/b = 1e-308: C23 formula");
    /* C33 ~ pi^2/(16 (1 - nu) g) = 8.6e307, still a double; the offset is
     * below its ulp: 1e-13 */
    CHECK_CLOSE(k.c33, RR_PI * RR_PI / (16.0 * 0.72) / 1e-308, 0.0, 1e-13,
                "a/b = 1e-308: C33 formula");
    st = rr_kalker(5e-324, 0.28, &k);
    CHECK_STATUS(st, RR_ERR_RANGE, "a/b = 5e-324: C33 ~ 1/g overflows");
    CHECK(isnan(k.c11) && isnan(k.c22) && isnan(k.c23) && isnan(k.c33),
          "a/b = 5e-324, RANGE: NaN outputs");
    st = rr_kalker(1e300, 0.28, &k);
    CHECK_STATUS(st, RR_ERR_RANGE, "a/b = 1e300: C23 ~ g^(-3/2) overflows");
    CHECK(isnan(k.c11) && isnan(k.c22) && isnan(k.c23) && isnan(k.c33), "RANGE: NaN outputs");
    /* the smallest normal a/b (what rr_creep_kalker passes on) is representable */
    CHECK_STATUS(rr_kalker(2.2250738585072014e-308, 0.5, &k), RR_OK,
                 "a/b = DBL_MIN, nu = 0.5: C33 = 5.5e307 representable");
    CHECK_STATUS(rr_kalker(1.0, 0.28, NULL), RR_ERR_NULL, "out NULL");
}

/* C33 is positive and falls as a/b grows: strictly inside the table's
 * columns and the a << b continuation, flat for a >> b below g = 0.1. */
static void test_c33_monotone(void)
{
    static const double nodes_nu[] = {0.0, 0.25, 0.28, 0.5};
    int i, n = 4000;
    unsigned j;
    char buf[160];
    double worst = 0.0;

    for (j = 0; j < sizeof nodes_nu / sizeof nodes_nu[0]; j++) {
        double prev = INFINITY;
        int ok = 1, pos = 1;
        for (i = 0; i <= n; i++) {
            rr_kalker_coeffs k;
            double aob = pow(10.0, -3.0 + 6.0 * i / n);
            rr_kalker(aob, nodes_nu[j], &k);
            pos &= isfinite(k.c33) && k.c33 > 0.0;
            ok &= aob < 10.0 ? k.c33 < prev : k.c33 <= prev;
            prev = k.c33;
        }
        snprintf(buf, sizeof buf, "nu = %.2f: C33 finite > 0 for a/b in [1e-3, 1e3]",
                 nodes_nu[j]);
        CHECK(pos, buf);
        snprintf(buf, sizeof buf, "nu = %.2f: C33 decreasing in a/b (flat beyond 10)",
                 nodes_nu[j]);
        CHECK(ok, buf);
    }
    /* Between the tabulated nu the parabola through 1/C can bend C33 up a
     * little where the nu = 0.5 column is small (a/b near 10). */
    for (j = 0; j <= 50; j++) {
        double nu = 0.01 * j, low = INFINITY;
        for (i = 0; i <= n; i++) {
            rr_kalker_coeffs k;
            rr_kalker(pow(10.0, -3.0 + 6.0 * i / n), nu, &k);
            if (k.c33 < low)
                low = k.c33;
            if (k.c33 / low - 1.0 > worst)
                worst = k.c33 / low - 1.0;
        }
    }
    snprintf(buf, sizeof buf, "C33 rises by at most 1.5 %% in a/b at any nu (%.2f %%)",
             100.0 * worst);
    /* measured 0.98 % at nu = 0.085, a/b = 10 (a finer scan in nu) */
    CHECK(worst < 0.015, buf);
}

int main(void)
{
    test_nodes();
    test_linear_in_g();
    test_nu_parabola();
    test_asymptotic();
    test_c33_monotone();
    test_bad_input();
    test_extremes();
    return rr_test_summary();
}
