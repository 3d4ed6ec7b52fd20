/* rr_exact_table.c - the exact theory's forces from a table, and the
 * method "exact_table" (see rr_exact_table.h). */
#include <math.h>
#include "util/rr_common.h"
#include "contact/rr_kalker.h"
#include "contact/rr_creep_opts.h"
#include "contact/rr_exact_table.h"

/* nu within this of the table's counts as the table's */
#define NU_TOL 1e-9
/* a/b within this (relative) of an end counts as inside: the ends round */
#define AOB_TOL 1e-12
#define MAX_NODES (1L << 28)

int rr_exact_table_check(const rr_exact_table *t)
{
    long nodes = 1;
    int d;
    if (!t || !t->v)
        return RR_ERR_NULL;
    if (!isfinite(t->r0) || !(t->r0 > 0.0) || !isfinite(t->nu))
        return RR_ERR_PARAM;
    for (d = 0; d < 4; d++) {
        if (t->n[d] < 4 || !isfinite(t->lo[d]) || !isfinite(t->hi[d])
            || !(t->lo[d] < t->hi[d]) || t->n[d] > MAX_NODES / nodes)
            return RR_ERR_PARAM;
        nodes *= t->n[d];
    }
    return RR_OK;
}

/* The four nodes j0 .. j0 + 3 and weights of coordinate q on axis d: a
 * Catmull-Rom cubic, its outer node past an end replaced by the quadratic
 * through the three nearest (f(-1) = 3 f0 - 3 f1 + f2), folded into the
 * weights of the nodes inside (the fourth node then has weight 0). */
static int weights(const rr_exact_table *t, int d, double q, double *w)
{
    const int n = t->n[d];
    double pos = (q - t->lo[d]) / (t->hi[d] - t->lo[d]) * (n - 1), s, s2, s3, g[4];
    int i;
    pos = pos < 0.0 ? 0.0 : pos > n - 1 ? n - 1 : pos;
    i = (int)pos;
    if (i > n - 2)
        i = n - 2;
    s = pos - i;
    s2 = s * s;
    s3 = s2 * s;
    g[0] = 0.5 * (-s3 + 2.0 * s2 - s);
    g[1] = 0.5 * (3.0 * s3 - 5.0 * s2 + 2.0);
    g[2] = 0.5 * (-3.0 * s3 + 4.0 * s2 + s);
    g[3] = 0.5 * (s3 - s2);
    if (i == 0) {                 /* nodes -1, 0, 1, 2 -> 0, 1, 2, 3 */
        w[0] = g[1] + 3.0 * g[0];
        w[1] = g[2] - 3.0 * g[0];
        w[2] = g[3] + g[0];
        w[3] = 0.0;
        return 0;
    }
    if (i == n - 2) {             /* nodes n-3 .. n -> n-4 .. n-1 */
        w[0] = 0.0;
        w[1] = g[0] + g[3];
        w[2] = g[1] - 3.0 * g[3];
        w[3] = g[2] + 3.0 * g[3];
        return n - 4;
    }
    w[0] = g[0];
    w[1] = g[1];
    w[2] = g[2];
    w[3] = g[3];
    return i - 1;
}

/* The nodes of the three outer axes (log(a/b), alpha, theta) to sum over:
 * on each axis those of non-zero weight, their offsets in floats and
 * weights.  A node of weight 0 adds nothing (the values are finite), so
 * leaving it out changes no bit, and saves a quarter of an axis's nodes at
 * an end interval, three quarters on a node: in the rig's cases (little
 * spin, no lateral creepage) alpha is in its last interval and theta on
 * the node at theta = 0, so 12 rows of the 64 remain. */
typedef struct {
    int m[3];
    long off[3][4];
    double w[3][4];
} node_rows;

static void list_rows(const rr_exact_table *t, const int j[3], double w[][4], node_rows *r)
{
    const long s2 = 3L * t->n[3], s1 = s2 * t->n[2], s0 = s1 * t->n[1];
    const long stride[3] = {s0, s1, s2};
    int d, k;
    for (d = 0; d < 3; d++) {       /* without branches */
        r->m[d] = 0;
        for (k = 0; k < 4; k++) {
            r->off[d][r->m[d]] = (j[d] + k) * stride[d];
            r->w[d][r->m[d]] = w[d][k];
            r->m[d] += w[d][k] != 0.0;
        }
    }
}

/* The rows (the 12 contiguous values of the four u nodes at a node of the
 * outer axes) times the products of their weights, summed lane by lane,
 * log(a/b) innermost (the axis seldom at an end or on a node: the inner
 * loop runs four times, where theta's would run once in the rig).
 * On x86-64 with GCC or clang the same sums in AVX2 registers where the
 * processor has them (each lane the same operations in the same order,
 * without contraction: the same doubles). */
static void rows_baseline(const float *v, const node_rows *r, double acc[12])
{
    int a, b, c, k;
    for (k = 0; k < 12; k++)
        acc[k] = 0.0;
    for (b = 0; b < r->m[1]; b++)
        for (c = 0; c < r->m[2]; c++) {
            const double wbc = r->w[1][b] * r->w[2][c];
            const float *vbc = v + r->off[1][b] + r->off[2][c];
            for (a = 0; a < r->m[0]; a++) {
                const double wabc = r->w[0][a] * wbc;
                const float *p = vbc + r->off[0][a];
                for (k = 0; k < 12; k++)
                    acc[k] += wabc * p[k];
            }
        }
}

#if defined(__GNUC__) && defined(__x86_64__) && !defined(RR_PORTABLE)
#define TABLE_DISPATCH 1
#include <immintrin.h>

__attribute__((target("avx2"))) static void rows_avx2(const float *v, const node_rows *r,
                                                      double acc[12])
{
    __m256d s0 = _mm256_setzero_pd(), s1 = s0, s2 = s0;
    int a, b, c;
    for (b = 0; b < r->m[1]; b++)
        for (c = 0; c < r->m[2]; c++) {
            const double wbc = r->w[1][b] * r->w[2][c];
            const float *vbc = v + r->off[1][b] + r->off[2][c];
            for (a = 0; a < r->m[0]; a++) {
                const __m256d w = _mm256_set1_pd(r->w[0][a] * wbc);
                const float *p = vbc + r->off[0][a];
                s0 = _mm256_add_pd(s0, _mm256_mul_pd(w, _mm256_cvtps_pd(_mm_loadu_ps(p))));
                s1 = _mm256_add_pd(s1, _mm256_mul_pd(w, _mm256_cvtps_pd(_mm_loadu_ps(p + 4))));
                s2 = _mm256_add_pd(s2, _mm256_mul_pd(w, _mm256_cvtps_pd(_mm_loadu_ps(p + 8))));
            }
        }
    _mm256_storeu_pd(acc, s0);
    _mm256_storeu_pd(acc + 4, s1);
    _mm256_storeu_pd(acc + 8, s2);
}
#else
#define TABLE_DISPATCH 0
#endif

/* simd 0: the baseline build alone */
static void rows(const float *v, const node_rows *r, int simd, double acc[12])
{
#if TABLE_DISPATCH
    if (simd && __builtin_cpu_supports("avx2")) {
        rows_avx2(v, r, acc);
        return;
    }
#else
    (void)simd;
#endif
    rows_baseline(v, r, acc);
}

/* sum over the 4^4 nodes of the weight products times the three values:
 * the u weights are common to every row of the outer axes, so the rows are
 * summed first (lanes of the four u nodes' three values) and the u
 * weights applied once at the end */
static void interpolate(const rr_exact_table *t, const double q[4], int simd, double f[3])
{
    node_rows r;
    double w[4][4], acc[12];
    int j[4], d, k;
    for (d = 0; d < 4; d++)
        j[d] = weights(t, d, q[d], w[d]);
    list_rows(t, j, w, &r);
    rows(t->v + 3L * j[3], &r, simd, acc);
    for (k = 0; k < 3; k++)
        f[k] = (w[3][0] * acc[k] + w[3][1] * acc[k + 3])
             + (w[3][2] * acc[k + 6] + w[3][3] * acc[k + 9]);
}

/* The member of a valid ellipse problem c (q = log(a/b)) outside table t,
 * RR_PF_NU (not the table's nu) or RR_PF_A (a/b beyond its range), else
 * RR_PF_NONE. */
static int outside(const rr_exact_table *t, const rr_contact_problem *c, double q)
{
    if (fabs(c->nu - t->nu) > NU_TOL)
        return RR_PF_NU;
    if (q < t->lo[0] - AOB_TOL * fabs(t->lo[0]) || q > t->hi[0] + AOB_TOL * fabs(t->hi[0]))
        return RR_PF_A;
    return RR_PF_NONE;
}

/* the forces of a checked table */
static int forces(const rr_exact_table *t, const rr_contact_problem *c, int simd,
                  const rr_kalker_coeffs *given, rr_forces *out)
{
    const rr_friction *fr;
    rr_kalker_coeffs k;
    double q[4], f[3], cc, mu, muN, x, y, z, m, R, sign = 1.0, sx = 1.0, sy = 1.0, aob;
    double sat;
    int e = 0;
    int st;

    st = given ? rr_creep_prepare_given(c, given, &k) : rr_creep_prepare(c, &k);
    if (st == RR_OK) {
        aob = c->a / c->b;
        q[0] = log(aob);
        if (outside(t, c, q[0]) != RR_PF_NONE)
            st = RR_ERR_TABLE;
    }
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    fr = &c->friction;
    out->fx = out->fy = out->mz = 0.0;
    cc = sqrt(c->a) * sqrt(c->b);
    /* the creepages times s (the saturation scale cancels in the direction);
     * where a product overflows (a, b and the creepages may be anything
     * finite), scaled down by 2^-600 at a time until none does */
    x = c->cx * k.c11;
    y = c->cy * k.c22;
    z = c->cphi * cc * k.c11;
    while (!(isfinite(x) && isfinite(y) && isfinite(z)) && e < 4) {
        e++;
        x = ldexp(c->cx, -600 * e) * k.c11;
        y = ldexp(c->cy, -600 * e) * k.c22;
        z = ldexp(c->cphi, -600 * e) * cc * k.c11;
    }
    m = fabs(x) > fabs(y) ? fabs(x) : fabs(y);
    m = fabs(z) > m ? fabs(z) : m;
    if (m == 0.0)
        return RR_OK;
    /* falling friction at the rigid slip speed (the speed matters only to a
     * falling law); the saturation scale s of the normalised creepages must
     * be a normal double (else the inputs are too extreme for the table's
     * coordinates) */
    mu = rr_friction_mu(fr, fr->B > 0.0 ? c->speed * hypot(c->cx, c->cy) : 0.0);
    muN = mu * c->N;
    sat = muN / c->G / cc / cc;
    if (!isnormal(muN) || !isnormal(sat)) {
        rr_forces_nan(out);
        return RR_ERR_RANGE;
    }
    if (z < 0.0) {                  /* all creepages reversed */
        sign = -1.0;
        x = -x;
        y = -y;
        z = -z;
    }
    if (x < 0.0) {                  /* ... and the patch mirrored in y */
        sx = -1.0;
        x = -x;
    }
    if (z == 0.0 && y < 0.0) {      /* without spin the mirror alone: y >= 0 */
        sy = -1.0;
        y = -y;
    }
    /* R = |(x, y, z)| / s, scaled by m so that no square overflows */
    R = m * sqrt((x / m) * (x / m) + (y / m) * (y / m) + (z / m) * (z / m)) / sat;
    if (e > 0)
        R = ldexp(R, 600 * e);
    /* little lateral creepage, |y| <= 2^-30 x (the rig's cases): hypot(x, y)
     * = x and atan2(y, x) = y / x to rounding (the next terms, x (y/x)^2 / 2
     * and (y/x)^3 / 3, are below 2^-60 of them), without the calls */
    if (x > 0.0 && fabs(y) <= 0x1p-30 * x) {
        q[1] = atan2(x, z);
        q[2] = y / x;
    } else {
        q[1] = atan2(hypot(x, y), z);
        q[2] = atan2(y, x);
    }
    q[3] = 1.0 / (1.0 + t->r0 / R);  /* R = inf: full sliding, u = 1 */
    interpolate(t, q, simd, f);
    /* points that the symmetries map onto themselves with a force reversed
     * have no such force (the nodes hold the solver's round-off there):
     * fx at x = 0 (reversed and mirrored), fy and mz at y = z = 0 (mirrored) */
    if (x == 0.0)
        f[0] = 0.0;
    if (y == 0.0 && z == 0.0)
        f[1] = f[2] = 0.0;
    /* the cubic may overshoot the bound near full sliding by its error;
     * hypot (the exact test) only where the sum of squares, within a few
     * ulps of the true one, does not rule that out */
    if (f[0] * f[0] + f[1] * f[1] > 1.0 - 1e-12) {
        const double h = hypot(f[0], f[1]);
        if (h > 1.0) {
            f[0] /= h;
            f[1] /= h;
        }
    }
    out->fx = sign * sx * f[0] * muN;
    out->fy = sign * sy * f[1] * muN;
    out->mz = sign * sy * f[2] * muN * cc;
    return rr_forces_checked(RR_OK, out);
}

/* the checked entries: simd 0 takes the baseline build of the sums; the
 * built-in table is not checked again at each call (it is constant data,
 * checked by csrc/tests/test_exact_table.c) */
static int checked(const rr_exact_table *t, const rr_contact_problem *p, int simd,
                   const rr_kalker_coeffs *given, rr_forces *out)
{
    int st;
    if (!out)
        return RR_ERR_NULL;
    if (t != &rr_exact_table_builtin && (st = rr_exact_table_check(t)) != RR_OK) {
        rr_forces_nan(out);
        return st;
    }
    return forces(t, p, simd, given, out);
}

int rr_exact_table_forces(const rr_exact_table *t, const rr_contact_problem *p,
                          rr_forces *out)
{
    return checked(t, p, 1, NULL, out);
}

int rr_exact_table_forces_kalker(const rr_exact_table *t, const rr_contact_problem *p,
                                 const rr_kalker_coeffs *k, rr_forces *out)
{
    return checked(t, p, 1, k, out);
}

int rr_exact_table_forces_baseline(const rr_exact_table *t, const rr_contact_problem *p,
                                   rr_forces *out)
{
    return checked(t, p, 0, NULL, out);
}

/* ---- the method ---------------------------------------------------------------- */

static int table_forces(const rr_contact_problem *p, const rr_creep_opts *o, double *work,
                        rr_forces *out)
{
    (void)o;
    (void)work;
    if (!out)
        return RR_ERR_NULL;
    if (!p) {
        rr_forces_nan(out);
        return RR_ERR_NULL;
    }
    /* the built-in table is checked by csrc/tests/test_exact_table.c */
    return forces(&rr_exact_table_builtin, p, 1, NULL, out);
}

/* outside the table: nu or a/b (the problem valid) */
static int table_blame(const rr_contact_problem *p, const rr_creep_opts *o, int st)
{
    (void)o;
    return st == RR_ERR_TABLE && p->patch == RR_PATCH_ELLIPSE
           ? outside(&rr_exact_table_builtin, p, log(p->a / p->b)) : RR_PF_NONE;
}

const rr_method_desc rr_method_exact_table = {
    .name = "exact_table",
    .doc = "Kalker's exact theory extrapolated to the continuum, from the built-in table "
           "(nu = 0.28, a/b in [0.1, 10]; falling friction at the rigid slip speed)",
    .saturates = 1,
    .cost = rr_method_unit_cost,
    .slope_scale = rr_method_unit_slope,
    .workspace_len = rr_method_no_workspace,
    .forces = table_forces,
    .blame = table_blame,
};
