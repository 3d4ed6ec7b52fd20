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
 * weights of the nodes inside. */
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

/* sum over the 4^4 nodes of the weight products times the three values:
 * along u (the last axis) the four nodes' 12 values are contiguous, so the
 * inner loop runs over those 12 lanes with the u weights spread over them
 * (it vectorises), the lanes summed per component at the end */
static void interpolate(const rr_exact_table *t, const double q[4], double f[3])
{
    double w[4][4], wu[12], acc[12] = {0.0};
    int j[4], a, b, c, k;
    const long s2 = 3L * t->n[3], s1 = s2 * t->n[2], s0 = s1 * t->n[1];
    for (a = 0; a < 4; a++)
        j[a] = weights(t, a, q[a], w[a]);
    for (k = 0; k < 12; k++)
        wu[k] = w[3][k / 3];
    for (a = 0; a < 4; a++)
        for (b = 0; b < 4; b++) {
            const double wab = w[0][a] * w[1][b];
            const float *vab = t->v + (j[0] + a) * s0 + (j[1] + b) * s1 + 3L * j[3];
            for (c = 0; c < 4; c++) {
                const double wabc = wab * w[2][c];
                const float *v = vab + (j[2] + c) * s2;
                for (k = 0; k < 12; k++)
                    acc[k] += wabc * (wu[k] * v[k]);
            }
        }
    for (k = 0; k < 3; k++)
        f[k] = (acc[k] + acc[k + 3]) + (acc[k + 6] + acc[k + 9]);
}

int rr_exact_table_forces(const rr_exact_table *t, const rr_contact_case *c,
                          const rr_friction *fr, rr_forces *out)
{
    rr_kalker_coeffs k;
    double q[4], f[3], cc, mu, muN, x, y, z, m, R, sign = 1.0, sx = 1.0, sy = 1.0, aob;
    double sat;
    int e;
    int st;

    if (!out)
        return RR_ERR_NULL;
    st = rr_exact_table_check(t);
    if (st == RR_OK)
        st = rr_creep_prepare(c, fr, &k);
    if (st == RR_OK) {
        aob = c->a / c->b;
        q[0] = log(aob);
        if (fabs(c->nu - t->nu) > NU_TOL
            || q[0] < t->lo[0] - AOB_TOL * fabs(t->lo[0])
            || q[0] > t->hi[0] + AOB_TOL * fabs(t->hi[0]))
            st = RR_ERR_TABLE;
    }
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    out->fx = out->fy = out->mz = 0.0;
    cc = sqrt(c->a) * sqrt(c->b);
    /* the creepages times s (the saturation scale cancels in the direction),
     * scaled down by 2^-600 at a time until no product overflows (a, b and
     * the creepages may be anything finite) */
    for (e = 0; e <= 4; e++) {
        x = ldexp(c->cx, -600 * e) * k.c11;
        y = ldexp(c->cy, -600 * e) * k.c22;
        z = ldexp(c->cphi, -600 * e) * cc * k.c11;
        if (isfinite(x) && isfinite(y) && isfinite(z))
            break;
    }
    m = fmax(fabs(x), fmax(fabs(y), fabs(z)));
    if (m == 0.0)
        return RR_OK;
    /* falling friction at the rigid slip speed; the saturation scale s of
     * the normalised creepages must be a normal double (else the inputs are
     * too extreme for the table's coordinates) */
    mu = rr_friction_mu(fr, c->speed * hypot(c->cx, c->cy));
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
    R = ldexp(R, 600 * e);
    q[1] = atan2(hypot(x, y), z);
    q[2] = atan2(y, x);
    q[3] = 1.0 / (1.0 + t->r0 / R);  /* R = inf: full sliding, u = 1 */
    interpolate(t, q, f);
    /* points that the symmetries map onto themselves with a force reversed
     * have no such force (the nodes hold the solver's round-off there):
     * fx at x = 0 (reversed and mirrored), fy and mz at y = z = 0 (mirrored) */
    if (x == 0.0)
        f[0] = 0.0;
    if (y == 0.0 && z == 0.0)
        f[1] = f[2] = 0.0;
    {
        /* the cubic may overshoot the bound near full sliding by its error */
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

/* ---- the method ---------------------------------------------------------------- */

static int table_forces(const rr_contact_case *c, const rr_friction *fr,
                        const rr_creep_opts *o, double *work, rr_forces *out)
{
    (void)o;
    (void)work;
    return rr_exact_table_forces(&rr_exact_table_builtin, c, fr, out);
}

const rr_method_desc rr_method_exact_table = {
    "exact_table",
    "Kalker's exact theory extrapolated to the continuum, from the built-in table "
    "(nu = 0.28, a/b in [0.1, 10]; falling friction at the rigid slip speed)",
    0, NULL, 1, NULL, NULL, rr_method_unit_cost, rr_method_unit_slope,
    rr_method_no_workspace, table_forces, NULL, NULL, 0
};
