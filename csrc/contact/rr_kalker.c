/* rr_kalker.c - Kalker's creep coefficients (Kalker 1990, Table E.3). */
#include <math.h>
#include "util/rr_common.h"
#include "contact/rr_kalker.h"

/* Table E.3: [half][row g = 0.1 * (i + 1)][coefficient C11, C22, C23, C33][nu = 0, 0.25, 0.5].
 * half 0: a <= b (g = a/b); half 1: a >= b (g = b/a).  Row 9 (g = 1) is shared.
 * C11, C22, C23 as transcribed in CONTACT (m_hertz.f90, linrol); C33, which
 * CONTACT does not carry, as transcribed in OpenVSD (WRcontForce.cpp). */
#define NCOEF 4
static const double kalker_table[2][10][NCOEF][3] = {
    {   /* a <= b */
        {{2.51, 3.31, 4.85}, {2.51, 2.52, 2.53}, {0.334, 0.473, 0.731}, {6.42, 8.28, 11.7}},
        {{2.59, 3.37, 4.81}, {2.59, 2.63, 2.66}, {0.483, 0.603, 0.809}, {3.46, 4.27, 5.66}},
        {{2.68, 3.44, 4.80}, {2.68, 2.75, 2.81}, {0.607, 0.715, 0.889}, {2.49, 2.96, 3.72}},
        {{2.78, 3.53, 4.82}, {2.78, 2.88, 2.98}, {0.720, 0.823, 0.977}, {2.02, 2.32, 2.77}},
        {{2.88, 3.62, 4.83}, {2.88, 3.01, 3.14}, {0.827, 0.929, 1.07}, {1.74, 1.93, 2.22}},
        {{2.98, 3.72, 4.91}, {2.98, 3.14, 3.31}, {0.930, 1.03, 1.18}, {1.56, 1.68, 1.86}},
        {{3.09, 3.81, 4.97}, {3.09, 3.28, 3.48}, {1.03, 1.14, 1.29}, {1.43, 1.50, 1.60}},
        {{3.19, 3.91, 5.05}, {3.19, 3.41, 3.65}, {1.13, 1.25, 1.40}, {1.34, 1.37, 1.42}},
        {{3.29, 4.01, 5.12}, {3.29, 3.54, 3.82}, {1.23, 1.36, 1.51}, {1.27, 1.27, 1.27}},
        {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}, {1.21, 1.19, 1.16}}
    },
    {   /* a >= b */
        {{10.7, 11.7, 12.9}, {10.7, 12.8, 16.0}, {12.2, 14.6, 18.0}, {0.795, 0.526, 0.228}},
        {{6.96, 7.78, 8.82}, {6.96, 8.14, 9.79}, {5.72, 6.63, 7.89}, {0.828, 0.601, 0.341}},
        {{5.57, 6.34, 7.34}, {5.57, 6.40, 7.51}, {3.79, 4.32, 5.01}, {0.868, 0.674, 0.446}},
        {{4.84, 5.57, 6.57}, {4.84, 5.48, 6.31}, {2.88, 3.24, 3.70}, {0.912, 0.747, 0.549}},
        {{4.37, 5.10, 6.11}, {4.37, 4.90, 5.56}, {2.35, 2.62, 2.96}, {0.958, 0.819, 0.650}},
        {{4.06, 4.78, 5.80}, {4.06, 4.50, 5.04}, {2.01, 2.23, 2.50}, {1.01, 0.892, 0.751}},
        {{3.82, 4.54, 5.58}, {3.82, 4.21, 4.67}, {1.76, 1.95, 2.18}, {1.05, 0.965, 0.852}},
        {{3.65, 4.36, 5.42}, {3.65, 3.99, 4.39}, {1.58, 1.75, 1.94}, {1.10, 1.04, 0.954}},
        {{3.51, 4.22, 5.30}, {3.51, 3.81, 4.16}, {1.44, 1.59, 1.77}, {1.16, 1.11, 1.06}},
        {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}, {1.21, 1.19, 1.16}}
    }
};

/* Lagrange parabola through 1/C at nu = 0, 0.25, 0.5, evaluated at nu;
 * at a node (node = 0, 1, 2; else -1) exactly its value. */
static double nu_parabola(const double c[3], double nu, int node)
{
    double inv;
    if (node >= 0)
        return c[node];
    inv = 8.0 * (nu - 0.25) * (nu - 0.5) / c[0]
               - 16.0 * nu * (nu - 0.5) / c[1]
               + 8.0 * nu * (nu - 0.25) / c[2];
    return 1.0 / inv;
}

/* Kalker's asymptotes for g = min(a/b, b/a) -> 0; for C33 (none in CONTACT)
 * the continuations the header describes, which meet the table's row
 * g = 0.1 at this nu (c33_row0). */
static void asymptotic(int half, double g, double nu, double c33_row0, rr_kalker_coeffs *out)
{
    if (half == 0) {            /* a << b: narrow in the rolling direction */
        const double q = 16.0 / g, lq = isfinite(q) ? log(q) : log(16.0) - log(g);
        /* strip theory's pi^2 / (16 (1 - nu) g), shifted to meet the table */
        const double k33 = RR_PI * RR_PI / (16.0 * (1.0 - nu));
        out->c11 = RR_PI * RR_PI / (4.0 * (1.0 - nu));
        out->c22 = RR_PI * RR_PI / 4.0;
        out->c23 = RR_PI * sqrt(g) / (3.0 * (1.0 - nu)) * (1.0 + nu * (lq - 5.0));
        out->c33 = k33 / g + (c33_row0 - 10.0 * k33);
    } else {                    /* a >> b: long in the rolling direction */
        double lam = log(16.0) - 2.0 * log(g);     /* g * g may underflow */
        double d22 = (1.0 - nu) * lam + 2.0 * nu;
        out->c11 = 2.0 * RR_PI / (g * (lam - 2.0 * nu))
                 * (1.0 + (3.0 - log(4.0)) / (lam - 2.0 * nu));
        out->c22 = 2.0 * RR_PI / g * (1.0 + (1.0 - nu) * (3.0 - log(4.0)) / d22) / d22;
        out->c23 = 2.0 * RR_PI / (3.0 * g * sqrt(g) * ((1.0 - nu) * lam - 2.0 + 4.0 * nu));
        out->c33 = c33_row0;    /* C33 tends to a finite limit: held at g = 0.1 */
    }
}

static void set_nan(rr_kalker_coeffs *out)
{
    out->c11 = out->c22 = out->c23 = out->c33 = NAN;
}

static int range_checked(rr_kalker_coeffs *out)
{
    if (isnormal(out->c11) && isnormal(out->c22) && isnormal(out->c23) && isnormal(out->c33))
        return RR_OK;
    set_nan(out);
    return RR_ERR_RANGE;
}

/* Coefficient k of row `row` of a table half at nu (the parabola over nu). */
static double row_value(int half, int row, int k, double nu, int node)
{
    return nu_parabola(kalker_table[half][row][k], nu, node);
}

int rr_kalker(double a_over_b, double nu, rr_kalker_coeffs *out)
{
    int half, row, j, k, node;
    double g, pos, frac, col[3];
    double *dst[NCOEF];

    if (!out)
        return RR_ERR_NULL;
    if (!isfinite(a_over_b) || !isfinite(nu)) {
        set_nan(out);
        return RR_ERR_NONFINITE;
    }
    if (a_over_b <= 0.0) {
        set_nan(out);
        return RR_ERR_GEOMETRY;
    }
    if (nu < 0.0 || nu > 0.5) {
        set_nan(out);
        return RR_ERR_MATERIAL;
    }
    half = a_over_b <= 1.0 ? 0 : 1;
    g = half == 0 ? a_over_b : 1.0 / a_over_b;
    node = nu == 0.0 ? 0 : nu == 0.25 ? 1 : nu == 0.5 ? 2 : -1;
    if (g < 0.1) {
        asymptotic(half, g, nu, row_value(half, 0, 3, nu, node), out);
        /* C23 ~ g^(-3/2) overflows for a/b beyond ~1e205, C33 ~ 1/g for a
         * subnormal a/b below ~5e-309 */
        return range_checked(out);
    }
    /* rows are g = 0.1 (row 0) ... 1.0 (row 9); the last interval ends at row 9 */
    pos = 10.0 * g - 1.0;
    {
        /* the nearest row: pos >= 0 here, so truncation is floor (and
         * quicker than floor without SSE4.1, a quarter of the time) */
        const double near = (double)(int)(pos + 0.5);
        if (fabs(pos - near) < 1e-12)
            pos = near;             /* 10 * 0.3 - 1 = 2.0000000000000004: a node */
    }
    row = (int)pos;
    if (row > 8)
        row = 8;
    frac = pos - row;
    dst[0] = &out->c11;
    dst[1] = &out->c22;
    dst[2] = &out->c23;
    dst[3] = &out->c33;
    for (k = 0; k < NCOEF; k++) {
        for (j = 0; j < 3; j++) {
            const double c0 = kalker_table[half][row][k][j];
            const double c1 = kalker_table[half][row + 1][k][j];
            col[j] = frac == 0.0 ? c0 : c0 + frac * (c1 - c0);
        }
        *dst[k] = nu_parabola(col, nu, node);
    }
    return RR_OK;
}

void rr_kalker_flexibilities(double a, double b, double G, const rr_kalker_coeffs *k,
                             double L[3])
{
    L[0] = 8.0 * a / (3.0 * k->c11 * G);
    L[1] = 8.0 * a / (3.0 * k->c22 * G);
    L[2] = RR_PI * a * sqrt(a / b) / (4.0 * k->c23 * G);
}
