/*
 * test_exact_table.c - the exact-theory table's lookup (rr_exact_table.h).
 *
 * The interpolation against its definition on tables whose values are
 * quadratic in the node indices: the Catmull-Rom cubic, with its node past
 * an end replaced by the quadratic through the nearest three, reproduces a
 * quadratic (and along each axis a tensor product of them), so the lookup
 * must give the polynomial at the case's coordinates, which this test
 * computes from their definition in the header (Kalker's coefficients from
 * rr_kalker, hypot and atan2), to rounding: 1e-12 of the forces.  The
 * cases fall inside the axes, in their end intervals and on nodes (where
 * nodes of weight 0 are skipped), and near theta = 0 (where the lookup
 * takes y / x for atan2).  Then the built-in table: it passes its check; the
 * method's path (rr_creep_forces, which skips the check) gives the checked
 * lookup's doubles; the AVX2 build of the sums gives the baseline's
 * doubles; the limits of no creepage and full sliding; the refusals.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "util/rr_common.h"
#include "contact/rr_kalker.h"
#include "contact/rr_creep.h"
#include "contact/rr_exact_table.h"
#include "rr_test.h"

/* problem c with the friction law fr (the tests vary the two apart): c's
 * law set to *fr, c returned (NULL stays NULL) */
static const rr_contact_problem *with_law(rr_contact_problem *c, const rr_friction *fr)
{
    if (c && fr)
        c->friction = *fr;
    return c;
}

#define G_MOD 8.2e10
#define NU 0.28

static uint64_t rng = 12345;

static double uniform(double lo, double hi)     /* splitmix64 */
{
    uint64_t z = (rng += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return lo + (hi - lo) * (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

/* ---- a table of quadratics ------------------------------------------------------ */

#define N0 5
#define N1 6
#define N2 7
#define N3 8
static float qvalues[N0 * N1 * N2 * N3 * 3];

/* value k at the node positions (or fractional positions) p: a constant,
 * per axis a linear and a square term, and a product of two axes; the
 * coefficients are multiples of 2^-12, so that the values at the nodes are
 * exact in float */
static double quad(int k, const double p[4])
{
    static const double c[3][10] = {
        {0.05, 0.01, -0.004, 0.006, 0.02, -0.001, 0.0015, -0.0008, 0.0007, 0.0011},
        {-0.03, 0.008, 0.005, -0.01, 0.015, 0.0012, -0.0009, 0.001, -0.0006, -0.0013},
        {0.02, -0.006, 0.007, 0.004, -0.012, -0.0007, 0.0008, 0.0012, 0.0009, 0.0004}};
    double a[10];
    int i;
    for (i = 0; i < 10; i++)
        a[i] = ldexp(floor(ldexp(c[k][i], 12) + 0.5), -12);
    return a[0] + a[1] * p[0] + a[2] * p[1] + a[3] * p[2] + a[4] * p[3] + a[5] * p[0] * p[0]
         + a[6] * p[1] * p[1] + a[7] * p[2] * p[2] + a[8] * p[3] * p[3] + a[9] * p[0] * p[3];
}

static void fill_quadratic(rr_exact_table *t)
{
    int i0, i1, i2, i3, k;
    long at = 0;
    const int n[4] = {N0, N1, N2, N3};
    for (i0 = 0; i0 < N0; i0++)
        for (i1 = 0; i1 < N1; i1++)
            for (i2 = 0; i2 < N2; i2++)
                for (i3 = 0; i3 < N3; i3++) {
                    const double p[4] = {i0, i1, i2, i3};
                    for (k = 0; k < 3; k++)
                        qvalues[at++] = (float)quad(k, p);
                }
    memcpy(t->n, n, sizeof n);
    t->lo[0] = log(0.5);
    t->hi[0] = log(2.0);
    t->lo[1] = 0.0;
    t->hi[1] = RR_PI / 2.0;
    t->lo[2] = -RR_PI / 2.0;
    t->hi[2] = RR_PI / 2.0;
    t->lo[3] = 0.0;
    t->hi[3] = 1.0;
    t->nu = NU;
    t->r0 = 1.5;
    t->nx = 0;
    t->v = qvalues;
}

/* The lookup's forces by the header's definition: the coordinates of the
 * case, the quadratic at their positions on the axes, the folding. */
static void by_definition(const rr_exact_table *t, const rr_contact_problem *c, double mu,
                          double f[3])
{
    rr_kalker_coeffs k;
    const double cc = sqrt(c->a * c->b), muN = mu * c->N, s = muN / (c->G * cc * cc);
    double x, y, z, sign = 1.0, sx = 1.0, sy = 1.0, q[4], p[4], R;
    int d;
    rr_kalker(c->a / c->b, c->nu, &k);
    x = c->cx * k.c11;
    y = c->cy * k.c22;
    z = c->cphi * cc * k.c11;
    if (z < 0.0) {
        sign = -1.0;
        x = -x;
        y = -y;
        z = -z;
    }
    if (x < 0.0) {
        sx = -1.0;
        x = -x;
    }
    R = sqrt(x * x + y * y + z * z) / s;
    q[0] = log(c->a / c->b);
    q[1] = atan2(hypot(x, y), z);
    q[2] = atan2(y, x);
    q[3] = R / (R + t->r0);
    for (d = 0; d < 4; d++)
        p[d] = (q[d] - t->lo[d]) / (t->hi[d] - t->lo[d]) * (t->n[d] - 1);
    f[0] = sign * sx * quad(0, p) * muN;
    f[1] = sign * sy * quad(1, p) * muN;
    f[2] = sign * sy * quad(2, p) * muN * cc;
}

static void test_quadratic_reproduced(void)
{
    static rr_exact_table t;
    const rr_friction fr = {0.3, 1.0, 0.0};
    int i, k, st;
    char what[160];
    fill_quadratic(&t);
    CHECK_STATUS(rr_exact_table_check(&t), RR_OK, "the quadratic table is valid");
    for (i = 0; i < 400; i++) {
        rr_contact_problem c = {0};    /* an ellipse problem */
        rr_forces got, base;
        double want[3], xs, ys, zs, scale;
        const double aob = exp(uniform(log(0.5), log(2.0))), cc = uniform(3e-3, 8e-3);
        c.a = cc * sqrt(aob);
        c.b = cc / sqrt(aob);
        c.N = uniform(1e3, 1e5);
        c.G = G_MOD;
        c.nu = NU;
        c.speed = 1.0;
        scale = fr.mu0 * c.N / (G_MOD * cc * cc);
        /* directions: generic, and with each coordinate near an end of its
         * axis or on a node (the weights of the skipped nodes are 0) */
        xs = uniform(0.05, 1.0);
        ys = uniform(-1.0, 1.0);
        zs = uniform(0.05, 1.0);
        switch (i % 5) {
        case 1:
            zs = 1e-3 * zs;             /* alpha near pi/2 */
            break;
        case 2:
            ys = 1e-3 * ys;             /* theta near 0: a node */
            xs *= 1e-3;                 /* ... and alpha near 0 */
            break;
        case 3:
            xs = 1e-3 * xs;             /* theta near +-pi/2 */
            break;
        case 4:
            ys = 1e-12 * ys;            /* theta near 0: without hypot and atan2 */
            break;
        default:
            break;
        }
        scale *= exp(uniform(log(1e-3), log(1e3)));     /* u from near 0 to near 1 */
        {
            rr_kalker_coeffs kc;
            rr_kalker(aob, NU, &kc);
            c.cx = (i & 8 ? -1.0 : 1.0) * xs * scale / kc.c11;
            c.cy = ys * scale / kc.c22;
            c.cphi = (i & 16 ? -1.0 : 1.0) * zs * scale / (cc * kc.c11);
        }
        st = rr_exact_table_forces(&t, with_law(&c, &fr), &got);
        st |= rr_exact_table_forces_baseline(&t, with_law(&c, &fr), &base);
        by_definition(&t, &c, fr.mu0, want);
        snprintf(what, sizeof what, "case %d: status", i);
        CHECK_STATUS(st, RR_OK, what);
        for (k = 0; k < 3; k++) {
            const double g = k == 0 ? got.fx : k == 1 ? got.fy : got.mz;
            const double unit = fr.mu0 * c.N * (k == 2 ? cc : 1.0);
            snprintf(what, sizeof what, "case %d: force %d is the quadratic's", i, k);
            CHECK_CLOSE(g, want[k], 1e-12 * unit, 0.0, what);
        }
        CHECK(memcmp(&got, &base, sizeof got) == 0, "the AVX2 sums give the baseline's doubles");
    }
}

/* ---- the built-in table ------------------------------------------------------- */

static void random_case(rr_contact_problem *c, rr_friction *fr)
{
    const double aob = exp(uniform(log(0.1), log(10.0))), cc = uniform(3e-3, 9e-3);
    const double N = uniform(5e3, 1e5), mu = uniform(0.1, 0.5), s = mu * N / (G_MOD * cc * cc);
    double mag[3];
    int k;
    for (k = 0; k < 3; k++) {
        const double u = uniform(0.0, 4.0);
        mag[k] = s * exp(uniform(log(1e-4), log(1e3))) * (u < 1.0 ? -1.0 : u < 2.0 ? 0.0 : 1.0);
    }
    c->a = cc * sqrt(aob);
    c->b = cc / sqrt(aob);
    c->N = N;
    c->G = G_MOD;
    c->nu = NU;
    c->cx = mag[0] / 4.0;
    c->cy = mag[1] / 4.0;
    c->cphi = mag[2] / (4.0 * cc);
    c->speed = uniform(0.0, 10.0);
    fr->mu0 = mu;
    fr->A = uniform(0.0, 1.0) < 0.5 ? 1.0 : 0.4;
    fr->B = fr->A < 1.0 ? 0.6 : 0.0;
}

static void test_builtin(void)
{
    const rr_exact_table *t = &rr_exact_table_builtin;
    const int m = rr_method_find("exact_table");
    rr_creep_opts o;
    int i, same = 1, same_isa = 1, same_given = 1, bad = 0, bound = 1;
    CHECK_STATUS(rr_exact_table_check(t), RR_OK, "the built-in table passes its check");
    CHECK(m >= 0 && rr_creep_opts_default(&o, m) == RR_OK, "method exact_table");
    for (i = 0; i < 20000; i++) {
        rr_contact_problem c = {0};    /* an ellipse problem */
        rr_friction fr;
        rr_forces f1, f2, f3, f4, f5;
        rr_kalker_coeffs kc;
        int s1, s2, s3, s4, s5;
        random_case(&c, &fr);
        s1 = rr_exact_table_forces(t, with_law(&c, &fr), &f1);
        s2 = rr_creep_forces(with_law(&c, &fr), &o, &f2);
        s3 = rr_exact_table_forces_baseline(t, with_law(&c, &fr), &f3);
        same &= s1 == s2 && memcmp(&f1, &f2, sizeof f1) == 0;
        same_isa &= s1 == s3 && memcmp(&f1, &f3, sizeof f1) == 0;
        /* Kalker's coefficients given (those of the same a/b and nu), or
         * NULL: the doubles computed */
        if (rr_kalker(c.a / c.b, c.nu, &kc) == RR_OK) {
            s4 = rr_exact_table_forces_kalker(t, with_law(&c, &fr), &kc, &f4);
            s5 = rr_exact_table_forces_kalker(t, with_law(&c, &fr), NULL, &f5);
            same_given &= s1 == s4 && memcmp(&f1, &f4, sizeof f1) == 0 && s1 == s5
                          && memcmp(&f1, &f5, sizeof f1) == 0;
        }
        bad += s1 != RR_OK;
        /* to rounding: the clipped forces times mu N */
        bound &= hypot(f1.fx, f1.fy)
                 <= (1.0 + 1e-15) * rr_friction_mu(&fr, c.speed * hypot(c.cx, c.cy)) * c.N;
    }
    CHECK(same, "the method (no table check) gives rr_exact_table_forces's doubles");
    CHECK(same_isa, "the AVX2 build of the sums gives the baseline's doubles");
    CHECK(same_given, "Kalker's coefficients given (or NULL) give rr_exact_table_forces's doubles");
    CHECK(bad == 0, "every random case inside the table is looked up");
    CHECK(bound, "|(fx, fy)| <= mu N");
    {
        rr_contact_problem c = {.a = 6e-3, .b = 4e-3, .N = 5e4, .G = G_MOD, .nu = NU,
                                .speed = 1.0, .friction = {0.3, 1.0, 0.0}};
        rr_forces f;
        CHECK_STATUS(rr_exact_table_forces(t, &c, &f), RR_OK, "no creepage");
        CHECK(f.fx == 0.0 && f.fy == 0.0 && f.mz == 0.0, "no creepage: no force");
        c.cx = 3.0;
        c.cy = -4.0;
        CHECK_STATUS(rr_exact_table_forces(t, &c, &f), RR_OK, "full sliding");
        CHECK_CLOSE(hypot(f.fx, f.fy), 0.3 * 5e4, 0.0, 1e-6, "full sliding: |F| = mu N");
        CHECK_CLOSE(f.fx / f.fy, -0.75, 0.0, 1e-3, "full sliding: F against the slip");
        c.nu = 0.3;
        CHECK_STATUS(rr_exact_table_forces(t, &c, &f), RR_ERR_TABLE, "nu not the table's");
        CHECK(isnan(f.fx) && isnan(f.fy) && isnan(f.mz), "refused: NaN forces");
        c.nu = NU;
        c.a = 0.3e-3;
        CHECK_STATUS(rr_exact_table_forces(t, &c, &f), RR_ERR_TABLE, "a/b below 0.1");
        CHECK_STATUS(rr_exact_table_forces(t, &c, NULL), RR_ERR_NULL, "out NULL");
        CHECK_STATUS(rr_exact_table_forces(NULL, &c, &f), RR_ERR_NULL, "table NULL");
        CHECK_STATUS(rr_creep_forces(&c, &o, NULL), RR_ERR_NULL, "method: out NULL");
    }
    {
        /* coefficients a caller can get wrong: refused, NaN forces */
        const rr_contact_problem c = {.a = 6e-3, .b = 4e-3, .N = 5e4, .G = G_MOD, .nu = NU,
                                      .cx = 1e-3, .speed = 1.0, .friction = {0.3, 1.0, 0.0}};
        const double bad_values[] = {0.0, -1.0, NAN, INFINITY};
        rr_kalker_coeffs kc, k;
        rr_forces f;
        int j, m;
        CHECK_STATUS(rr_kalker(c.a / c.b, c.nu, &kc), RR_OK, "Kalker's coefficients");
        for (j = 0; j < 4; j++)
            for (m = 0; m < 4; m++) {
                double *v[4];
                k = kc;
                v[0] = &k.c11, v[1] = &k.c22, v[2] = &k.c23, v[3] = &k.c33;
                *v[m] = bad_values[j];
                f.fx = 0.0;
                CHECK_STATUS(rr_exact_table_forces_kalker(t, &c, &k, &f), RR_ERR_PARAM,
                             "a coefficient not finite and positive");
                CHECK(isnan(f.fx) && isnan(f.fy) && isnan(f.mz), "refused: NaN forces");
            }
        CHECK_STATUS(rr_exact_table_forces_kalker(t, &c, &kc, NULL), RR_ERR_NULL, "out NULL");
        CHECK_STATUS(rr_exact_table_forces_kalker(t, NULL, &kc, &f), RR_ERR_NULL, "problem NULL");
        CHECK(isnan(f.fx), "problem NULL: NaN forces");
    }
}

static void test_bad_tables(void)
{
    rr_exact_table t = rr_exact_table_builtin;
    const rr_contact_problem c = {.a = 6e-3, .b = 4e-3, .N = 5e4, .G = G_MOD, .nu = NU,
                                  .cx = 1e-3, .speed = 1.0, .friction = {0.3, 1.0, 0.0}};
    rr_forces f;
    t.n[2] = 3;
    CHECK_STATUS(rr_exact_table_forces(&t, &c, &f), RR_ERR_PARAM, "3 nodes on an axis");
    CHECK(isnan(f.fx), "a bad table: NaN forces");
    t = rr_exact_table_builtin;
    t.r0 = 0.0;
    CHECK_STATUS(rr_exact_table_check(&t), RR_ERR_PARAM, "r0 = 0");
    t = rr_exact_table_builtin;
    t.hi[1] = t.lo[1];
    CHECK_STATUS(rr_exact_table_check(&t), RR_ERR_PARAM, "lo = hi");
    t = rr_exact_table_builtin;
    t.v = NULL;
    CHECK_STATUS(rr_exact_table_check(&t), RR_ERR_NULL, "no values");
}

int main(void)
{
    test_quadratic_reproduced();
    test_builtin();
    test_bad_tables();
    return rr_test_summary();
}
