/*
 * test_influence.c - the half-space's influence coefficients (rr_influence.h)
 * and the inverse Hertz relation (rr_hertz_curvatures).
 *
 * References: (1) the coefficients' definition, the point-load kernels of
 * Boussinesq and Cerruti integrated over the element numerically (Gauss-
 * Legendre, 24 x 24 points on each of 4 x 4 sub-cells: the kernels are
 * smooth away from the loaded element, so the quadrature is good to about
 * 1e-12 of the coefficient); (2) the quadrant tables against the direct
 * corner formula (rr_influence_at), to round-off; (3) rr_hertz on the
 * curvatures, which must give the semi-axes back.
 */
#include <math.h>
#include "tests/rr_test.h"
#include "contact/rr_influence.h"
#include "contact/rr_hertz.h"

/* 24-point Gauss-Legendre on [-1, 1]: nodes and weights by Newton on P_n */
static void gauss(int n, double *x, double *w)
{
    int i, it, k;
    for (i = 0; i < n; i++) {
        double z = cos(RR_PI * (i + 0.75) / (n + 0.5)), dp = 1.0;
        for (it = 0; it < 100; it++) {
            double p0 = 1.0, p1 = z;
            for (k = 2; k <= n; k++) {
                const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (z * p1 - p0) / (z * z - 1.0);
            {
                const double dz = p1 / dp;
                z -= dz;
                if (fabs(dz) < 1e-16)
                    break;
            }
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
}

/* the four kernels integrated over the element centred at the origin,
 * observed at (X, Y): nn, xx, yy, xy (point kernels of rr_influence.h's
 * header, Kalker's for the difference of two bodies) */
static void numeric(double X, double Y, double dx, double dy, double nu, double out[4])
{
    enum { NG = 24, NS = 4 };
    double gx[NG], gw[NG];
    int i, j, si, sj, c;
    gauss(NG, gx, gw);
    for (c = 0; c < 4; c++)
        out[c] = 0.0;
    for (si = 0; si < NS; si++)
        for (sj = 0; sj < NS; sj++)
            for (i = 0; i < NG; i++)
                for (j = 0; j < NG; j++) {
                    const double xs = (-0.5 + (si + 0.5 + 0.5 * gx[i]) / NS) * dx;
                    const double ys = (-0.5 + (sj + 0.5 + 0.5 * gx[j]) / NS) * dy;
                    const double wt = gw[i] * gw[j] * 0.25 * dx * dy / (NS * NS);
                    const double u = X - xs, v = Y - ys, r = hypot(u, v);
                    out[0] += wt * (1.0 - nu) / (RR_PI * r);
                    out[1] += wt * ((1.0 - nu) / r + nu * u * u / (r * r * r)) / RR_PI;
                    out[2] += wt * ((1.0 - nu) / r + nu * v * v / (r * r * r)) / RR_PI;
                    out[3] += wt * nu * u * v / (RR_PI * r * r * r);
                }
}

static void test_against_quadrature(void)
{
    const int offs[][2] = {{2, 0}, {0, 3}, {1, 1}, {2, -1}, {-3, 2}, {5, 7}, {-4, -6}};
    const double dx = 1.0e-3, dy = 0.6e-3, nu = 0.28;
    size_t t;
    int c;
    for (t = 0; t < sizeof offs / sizeof offs[0]; t++) {
        double an[4], q[4], a00[4];
        rr_influence_at(offs[t][0], offs[t][1], dx, dy, nu, an);
        rr_influence_at(0, 0, dx, dy, nu, a00);
        numeric(offs[t][0] * dx, offs[t][1] * dy, dx, dy, nu, q);
        /* 1e-10 of the self-coefficient: the quadrature's own error */
        for (c = 0; c < 4; c++)
            CHECK_CLOSE(an[c], q[c], 1e-10 * a00[0], 0.0, "closed form against quadrature");
    }
    /* CONTACT's notes: A_nn(0,0) = 0.61380 dx for dx = 1, dy = 0.6, nu = 0.28 */
    {
        double a00[4];
        rr_influence_at(0, 0, 1.0, 0.6, 0.28, a00);
        CHECK_CLOSE(a00[0], 0.61380, 5e-6, 0.0, "A_nn(0,0), 5 digits as published");
    }
}

static void test_tables(void)
{
    enum { NKX = 9, NKY = 7 };
    double ta[NKX * NKY], tb[NKX * NKY], tr[NKX * NKY];
    const double dx = 2e-4, dy = 5e-4, nu = 0.3;
    int i, j;
    CHECK_STATUS(rr_influence_boxes(NKX, NKY, dx, dy, ta, tb, tr), RR_OK, "tables");
    for (j = 0; j < NKY; j++)
        for (i = 0; i < NKX; i++) {
            double an[4];
            const int k = j * NKX + i;
            rr_influence_at(i, j, dx, dy, nu, an);
            /* the same corner sums in another order: round-off of the terms */
            CHECK_CLOSE((1.0 - nu) / RR_PI * (ta[k] + tb[k]), an[0], 1e-13 * dx, 0.0, "nn");
            CHECK_CLOSE(((1.0 - nu) * ta[k] + tb[k]) / RR_PI, an[1], 1e-13 * dx, 0.0, "xx");
            CHECK_CLOSE((ta[k] + (1.0 - nu) * tb[k]) / RR_PI, an[2], 1e-13 * dx, 0.0, "yy");
            CHECK_CLOSE(-nu / RR_PI * tr[k], an[3], 1e-13 * dx, 0.0, "xy");
        }
    CHECK_STATUS(rr_influence_boxes(0, 3, dx, dy, ta, tb, tr), RR_ERR_GRID, "nkx 0");
    CHECK_STATUS(rr_influence_boxes(3, 3, -dx, dy, ta, tb, tr), RR_ERR_GEOMETRY, "dx < 0");
    CHECK_STATUS(rr_influence_boxes(3, 3, dx, NAN, ta, tb, tr), RR_ERR_NONFINITE, "dy NaN");
    CHECK_STATUS(rr_influence_boxes(3, 3, dx, dy, NULL, tb, tr), RR_ERR_NULL, "NULL");
    CHECK_STATUS(rr_influence_boxes(3, 3, 1.0, 1e-7, ta, tb, tr), RR_ERR_GEOMETRY,
                 "elongated");
}

static void test_curvatures(void)
{
    const double axes[][2] = {{5e-3, 5e-3}, {8e-3, 4e-3}, {3e-3, 9e-3}, {6e-3, 0.6e-3},
                              {5e-3, 5.0000001e-3}};
    const double estar = 82e9 / (1.0 - 0.28), N = 5e4;
    size_t t;
    for (t = 0; t < sizeof axes / sizeof axes[0]; t++) {
        double A, B;
        rr_hertz_result h;
        CHECK_STATUS(rr_hertz_curvatures(axes[t][0], axes[t][1], N, estar, &A, &B), RR_OK,
                     "curvatures");
        CHECK_STATUS(rr_hertz(A, B, N, estar, &h), RR_OK, "hertz");
        /* both directions to full precision, 1e-12 for the secant of rr_hertz */
        CHECK_CLOSE(h.a, axes[t][0], 0.0, 1e-12, "a back");
        CHECK_CLOSE(h.b, axes[t][1], 0.0, 1e-12, "b back");
    }
    {
        double A, B;
        CHECK_STATUS(rr_hertz_curvatures(-1.0, 1.0, N, estar, &A, &B), RR_ERR_GEOMETRY, "a<0");
        CHECK(isnan(A) && isnan(B), "NaN on error");
        CHECK_STATUS(rr_hertz_curvatures(1.0, 1.0, 0.0, estar, &A, &B), RR_ERR_LOAD, "N=0");
        CHECK_STATUS(rr_hertz_curvatures(1.0, NAN, 1.0, estar, &A, &B), RR_ERR_NONFINITE,
                     "NaN");
        CHECK_STATUS(rr_hertz_curvatures(1.0, 1.0, 1.0, 0.0, &A, &B), RR_ERR_MATERIAL, "E*");
        CHECK_STATUS(rr_hertz_curvatures(1.0, 1.0, 1.0, 1.0, NULL, &B), RR_ERR_NULL, "NULL");
        CHECK_STATUS(rr_hertz_curvatures(1e-300, 1e300, 1.0, 1.0, &A, &B), RR_ERR_GEOMETRY,
                     "ratio");
    }
}

int main(void)
{
    test_against_quadrature();
    test_tables();
    test_curvatures();
    return rr_test_summary();
}
