/*
 * rr_nonhertz.c - one wheel's non-Hertzian contact from a table per lateral
 * shift (rr_nonhertz.h): the run time of benchmarks/NONHERTZ_STUDY.md's
 * recommended method, its C prototype (benchmarks/bench_nonhertz_runtime.c)
 * written as library code.
 */
#include <float.h>
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "contact/rr_contact.h"
#include "contact/rr_kalker.h"
#include "contact/rr_exact_table.h"
#include "geometry/rr_nonhertz.h"

const double rr_nh_corr_u[RR_NH_U] = {0.2, 0.4, 0.6, 0.8};

/* The tangential forces' vertical share settles to this fraction of Fz
 * (1e-4 Fz moves the forces by about 1e-4 mu N); passes at most. */
#define TZ_TOL 1e-4
#define TZ_PASSES 20
/* The lowering's secant: relative tolerance on the load, iterations.  The
 * balance it serves settles to TZ_TOL; 1e-10 before stop 37 took one to
 * two more load sums a row for nothing (the forces move by ~1e-6 mu N). */
#define DZ_TOL 1e-6
#define DZ_ITER 60
/* a/b inside the exact table's range (rr_exact_table_builtin: 0.1 to 10). */
#define AB_LO (0.1 * (1.0 + 1e-9))
#define AB_HI (10.0 * (1.0 - 1e-9))
#define TWO_PI (2.0 * RR_PI)
/* Loads are extrapolated by Hertz's law beyond the last node up to this
 * multiple of its lowering (2^1.5 = 2.8 times its load); beyond, the table
 * does not hold the load: RR_ERR_TABLE. */
#define E_BEYOND 2.0

/* ------------------------------------------------------------ the table */

static int patch_ok(const double *p)
{
    int k, c;
    if (!rr_all_finite(p, RR_NH_PATCH_LEN) || !(p[0] >= 0.0))
        return 0;
    for (k = 0; k < RR_NH_NODES; k++) {
        if (!(p[RR_NH_NODE(RR_NH_E, k)] > 0.0) || !(p[RR_NH_NODE(RR_NH_Q, k)] > 0.0)
            || !(fabs(p[RR_NH_NODE(RR_NH_DELTA, k)]) < 0.5 * RR_PI)
            || !(p[RR_NH_NODE(RR_NH_AREA, k)] > 0.0) || !(p[RR_NH_NODE(RR_NH_PMAX, k)] > 0.0)
            || !(p[RR_NH_NODE(RR_NH_AB, k)] >= 0.1 && p[RR_NH_NODE(RR_NH_AB, k)] <= 10.0)
            || !(p[RR_NH_NODE(RR_NH_K11, k)] > 0.0) || !(p[RR_NH_NODE(RR_NH_K22, k)] > 0.0))
            return 0;
        if (k > 0 && !(p[RR_NH_NODE(RR_NH_E, k)] > p[RR_NH_NODE(RR_NH_E, k - 1)]))
            return 0;
    }
    for (c = 0; c < RR_NH_CORR; c++)
        if (!(p[RR_NH_CORR_AT(c)] > 0.0)
            || (c > 0 && !(p[RR_NH_CORR_AT(c)] > p[RR_NH_CORR_AT(c - 1)])))
            return 0;
    return 1;
}

int rr_nonhertz_table_check(const rr_nh_table *t, int *bad_row)
{
    int i, j;
    if (bad_row)
        *bad_row = -1;
    if (!t || !t->rows)
        return RR_ERR_NULL;
    if (t->nrows < 2 || (t->sigma != 1.0 && t->sigma != -1.0) || !(t->R0 > 0.0)
        || !isfinite(t->R0) || !(t->G > 0.0) || !isfinite(t->G) || !(t->nu >= 0.0)
        || !(t->nu <= 0.5) || !(t->mu_ref > 0.0) || !isfinite(t->mu_ref))
        return RR_ERR_TABLE;
    for (i = 0; i < t->nrows; i++) {
        const double *r = t->rows + (size_t)i * RR_NH_ROW_LEN;
        const double np = r[1];
        if (bad_row)
            *bad_row = i;
        if (!rr_all_finite(r, RR_NH_ROW_HEAD) || !(np >= 1.0 && np <= RR_NH_MAX_PATCHES)
            || np != floor(np) || (i > 0 && !(r[0] > r[-RR_NH_ROW_LEN])))
            return RR_ERR_TABLE;
        for (j = 0; j < (int)np; j++)
            if (!patch_ok(r + RR_NH_PATCH(j)))
                return RR_ERR_TABLE;
    }
    if (bad_row)
        *bad_row = -1;
    return RR_OK;
}

int rr_nonhertz_locate(const rr_nh_table *t, double y, int *row, double *w)
{
    int lo, hi;
    const double *r;
    if (!t || !t->rows || !row || !w)
        return RR_ERR_NULL;
    if (!isfinite(y))
        return RR_ERR_NONFINITE;
    r = t->rows;
    if (t->nrows < 2 || !(y >= r[0] && y <= r[(size_t)(t->nrows - 1) * RR_NH_ROW_LEN]))
        return RR_ERR_TABLE;
    lo = 0;
    hi = t->nrows - 1;
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        if (r[(size_t)mid * RR_NH_ROW_LEN] <= y)
            lo = mid;
        else
            hi = mid;
    }
    *row = lo;
    *w = (y - r[(size_t)lo * RR_NH_ROW_LEN])
         / (r[(size_t)hi * RR_NH_ROW_LEN] - r[(size_t)lo * RR_NH_ROW_LEN]);
    return RR_OK;
}

/* --------------------------------------------------------- creepages */

void rr_nonhertz_frame(double PY, double PZ, double delta, double theta, double sigma,
                       double R0, rr_nh_frame *f)
{
    /* theta is 0 without yaw or x (the rig's usual state): its sine and
     * cosine are theta itself (+-0) and 1, without the calls */
    const double sd = sin(delta), cd = cos(delta);
    const double st = theta == 0.0 ? theta : sin(theta), ct = theta == 0.0 ? 1.0 : cos(theta);
    f->P[0] = (PZ + R0) * st;
    f->P[1] = PY;
    f->P[2] = theta == 0.0 ? PZ : (PZ + R0) * ct - R0;
    f->t1[0] = ct, f->t1[1] = 0.0, f->t1[2] = -st;
    f->n[0] = cd * st, f->n[1] = -sigma * sd, f->n[2] = cd * ct;
    f->t2[0] = sigma * sd * st, f->t2[1] = cd, f->t2[2] = sigma * sd * ct;
}

int rr_nonhertz_creepages(const rr_motion *ws, double roller_spin, double R0,
                          const rr_nh_frame *f, double pen, double dz, double vmin, double k[4])
{
    const double wr[3] = {0.0, -roller_spin, 0.0};
    double q[3], vw[3], vr[3], sum[3], slip[3], dw[3];
    int m;
    /* the wheel's point P - pen n from the centre lowered by dz; the
     * roller's point P from its axis (0, ., -R0) */
    for (m = 0; m < 3; m++)
        q[m] = f->P[m] - pen * f->n[m] - (m == 2 ? ws->c[2] - dz : ws->c[m]);
    rr_cross3(ws->w, q, vw);
    q[0] = f->P[0];
    q[1] = f->P[1];
    q[2] = f->P[2] + R0;
    rr_cross3(wr, q, vr);
    for (m = 0; m < 3; m++) {
        vw[m] += ws->v[m];
        sum[m] = vw[m] + vr[m];
        slip[m] = vw[m] - vr[m];
        dw[m] = ws->w[m] - wr[m];
    }
    k[3] = fmax(fabs(rr_dot3(sum, f->t1)) / 2.0, vmin);
    k[0] = rr_dot3(slip, f->t1) / k[3];
    k[1] = rr_dot3(slip, f->t2) / k[3];
    k[2] = rr_dot3(dw, f->n) / k[3];
    return rr_all_finite(k, 4) ? RR_OK : RR_ERR_RANGE;
}

/* ------------------------------------------------------------- a patch */

/* Interval k of v on the nodes x[0..n-1] and weight *t (held at the ends). */
static int locate_node(const double *x, int n, double v, double *t)
{
    int k = 0;
    if (v <= x[0]) {
        *t = 0.0;
        return 0;
    }
    if (v >= x[n - 1]) {
        *t = 1.0;
        return n - 2;
    }
    while (k < n - 2 && v > x[k + 1])
        k++;
    *t = (v - x[k]) / (x[k + 1] - x[k]);
    return k;
}

/* Quantity q of patch p at node interval k, weight t. */
static double node(const double *p, int q, int k, double t)
{
    return (1.0 - t) * p[RR_NH_NODE(q, k)] + t * p[RR_NH_NODE(q, k + 1)];
}

/* A patch's normal load at lowering e beyond its gap, and its n_z. */
static double load(const double *p, double e, double *nz)
{
    double t;
    int k;
    if (!(e > 0.0)) {
        *nz = 1.0;
        return 0.0;
    }
    k = locate_node(p + RR_NH_NODE(RR_NH_E, 0), RR_NH_NODES, e, &t);
    *nz = cos(node(p, RR_NH_DELTA, k, t));
    return e * sqrt(e) * node(p, RR_NH_Q, k, t);
}

/* Where a normalised creepage (x, y) lies on the correction's rings:
 * radially u = rho / (1 + rho) between the nodes rr_nh_corr_u (below the
 * first from 0, the centre's value; above the last to 1, none), in angle
 * between two of RR_NH_TH spokes.  Found once for both correction nodes. */
typedef struct {
    int i, j0, j1;          /* ring interval (-1: below the first, RR_NH_U - 1: above the last) */
    double tu, tj;          /* weights within it */
} corr_at;

static void corr_locate(double x, double y, corr_at *at)
{
    const double rho = hypot(x, y), u = rho / (1.0 + rho);
    double th = atan2(y, x), kk;
    if (th < 0.0)
        th += TWO_PI;
    kk = th / (TWO_PI / RR_NH_TH);
    at->j0 = (int)floor(kk);
    at->tj = kk - at->j0;
    at->j0 %= RR_NH_TH;
    at->j1 = (at->j0 + 1) % RR_NH_TH;
    if (u <= rr_nh_corr_u[0]) {
        at->i = -1;
        at->tu = u / rr_nh_corr_u[0];
    } else if (u >= rr_nh_corr_u[RR_NH_U - 1]) {
        at->i = RR_NH_U - 1;
        at->tu = (u - rr_nh_corr_u[RR_NH_U - 1]) / (1.0 - rr_nh_corr_u[RR_NH_U - 1]);
    } else {
        at->i = 0;
        while (u > rr_nh_corr_u[at->i + 1])
            at->i++;
        at->tu = (u - rr_nh_corr_u[at->i]) / (rr_nh_corr_u[at->i + 1] - rr_nh_corr_u[at->i]);
    }
}

/* Correction node c of patch p (over mu N) at a creepage located by at:
 * linear in u between 0 (R0), the nodes and 1 (none), periodic in theta. */
static void residual(const double *p, int c, const corr_at *at, double r[3])
{
    const double *cb = p + RR_NH_CORR_AT(c);
    const double tj = at->tj, tu = at->tu;
    const int i = at->i, j0 = at->j0, j1 = at->j1;
    double lo[3], hi[3];
    int m;
#define RING(i, j, m) cb[4 + ((i) * RR_NH_TH + (j)) * 3 + (m)]
    for (m = 0; m < 3; m++) {
        if (i < 0) {
            lo[m] = cb[1 + m];
            hi[m] = (1 - tj) * RING(0, j0, m) + tj * RING(0, j1, m);
        } else if (i == RR_NH_U - 1) {
            lo[m] = (1 - tj) * RING(RR_NH_U - 1, j0, m) + tj * RING(RR_NH_U - 1, j1, m);
            hi[m] = 0.0;
        } else {
            lo[m] = (1 - tj) * RING(i, j0, m) + tj * RING(i, j1, m);
            hi[m] = (1 - tj) * RING(i + 1, j0, m) + tj * RING(i + 1, j1, m);
        }
        r[m] = (1 - tu) * lo[m] + tu * hi[m];
    }
#undef RING
}

/* The correction at lowering e: linear in e between its two nodes, held
 * outside them. */
static void correction(const double *p, double e, double x, double y, double r[3])
{
    const double e0 = p[RR_NH_CORR_AT(0)], e1 = p[RR_NH_CORR_AT(1)];
    double r1[3], t;
    corr_at at;
    int m;
    corr_locate(x, y, &at);
    if (e <= e0) {
        residual(p, 0, &at, r);
        return;
    }
    if (e >= e1) {
        residual(p, 1, &at, r);
        return;
    }
    t = (e - e0) / (e1 - e0);
    residual(p, 0, &at, r);
    residual(p, 1, &at, r1);
    for (m = 0; m < 3; m++)
        r[m] = (1 - t) * r[m] + t * r1[m];
}

/* Patch p of a row at the row's lowering dz: *out, and *vert the vertical
 * component of its force. */
static int patch_forces(const rr_nh_table *tb, const double *p, double dz, const rr_motion *ws,
                        const rr_nh_state *s, const double law[2], rr_nh_patch *out,
                        double *vert, int *calls)
{
    const double e = dz - p[0], sig = tb->sigma;
    double t, d, PY, PZ, xc, yc, ab, K11, K22, K23, N, k[4], theta = 0.0;
    double cxc, cyc, c2, cc, sy, sp, muN, corr[3];
    rr_nh_frame fr;
    rr_kalker_coeffs kc;
    rr_contact_problem cp;
    rr_forces f;
    int kn, st, m;
    memset(out, 0, sizeof *out);
    *vert = 0.0;
    if (!(e > 0.0))
        return RR_OK;
    kn = locate_node(p + RR_NH_NODE(RR_NH_E, 0), RR_NH_NODES, e, &t);
    N = e * sqrt(e) * node(p, RR_NH_Q, kn, t);
    d = node(p, RR_NH_DELTA, kn, t);
    PY = node(p, RR_NH_PY, kn, t);
    PZ = node(p, RR_NH_PZ, kn, t);
    xc = node(p, RR_NH_XC, kn, t);
    yc = node(p, RR_NH_YC, kn, t);
    ab = node(p, RR_NH_AB, kn, t);
    ab = ab < AB_LO ? AB_LO : ab > AB_HI ? AB_HI : ab;
    K11 = node(p, RR_NH_K11, kn, t);
    K22 = node(p, RR_NH_K22, kn, t);
    K23 = node(p, RR_NH_K23, kn, t);
    if (s->x != 0.0 || s->yaw != 0.0) {
        /* the rig's law: the wheel's centre at x_j = x - a sin(yaw), the
         * contact point led round it by sigma r tan(delta) yaw; the angle
         * round the roller axis from both (r, R the patch's radii) */
        const double r = ws->c[2] - dz - PZ, R = PZ + tb->R0;
        const double xj = s->x - (PY - ws->c[1]) * sin(s->yaw);
        theta = asin(xj / (r + R)) + sig * r * tan(d) * s->yaw / (r + R);
    }
    rr_nonhertz_frame(PY, PZ, d, theta, sig, tb->R0, &fr);
    /* the frame's t2[1] is cos(d) */
    if ((st = rr_nonhertz_creepages(ws, s->roller_spin, tb->R0, &fr, e * fr.t2[1], dz, s->vmin,
                                    k)) < 0)
        return st;
    /* the creepages at the centroid; the calibrated ellipse there */
    cxc = k[0] - k[2] * yc;
    cyc = k[1] + k[2] * xc;
    if ((st = rr_kalker(ab, tb->nu, &kc)) < 0)
        return st;
    c2 = K11 / (tb->G * kc.c11);
    cc = sqrt(c2);
    sy = K22 / (tb->G * c2 * kc.c22);
    sp = K23 / (tb->G * c2 * cc * kc.c23);
    memset(&cp, 0, sizeof cp);          /* a zeroed problem is an ellipse, Coulomb */
    cp.a = cc * sqrt(ab);
    cp.b = cc / sqrt(ab);
    cp.N = N;
    cp.G = tb->G;
    cp.nu = tb->nu;
    cp.cx = cxc;
    cp.cy = sy * cyc;
    cp.cphi = sp * k[2];
    cp.friction.mu0 = s->mu;
    cp.friction.A = 1.0;
    if (law[0] != 1.0 && law[1] != 0.0)
        /* the falling law at the patch's rigid slip speed: one Coulomb mu */
        cp.friction.mu0 = s->mu * ((1.0 - law[0]) * exp(-law[1] * k[3] * hypot(cxc, cyc))
                                   + law[0]);
    (*calls)++;
    /* the calibration's Kalker coefficients are the ellipse's (a / b = ab
     * to rounding): not computed again */
    if ((st = rr_exact_table_forces_kalker(&rr_exact_table_builtin, &cp, &kc, &f)) < 0)
        return st;
    /* plus the tabulated exact departure (normalised by this friction) */
    muN = cp.friction.mu0 * N;
    correction(p, e, K11 * cxc / muN, K22 * cyc / muN, corr);
    out->N = N;
    out->fx = f.fx + muN * corr[0];
    out->fy = f.fy + muN * corr[1];
    out->mz = f.mz + muN * corr[2];
    {
        /* the exact theory's traction never passes mu N; the correction,
         * interpolated between its nodes, can by ~1e-5 mu N near saturation
         * (a rig checks the bound): held at it */
        const double ft = hypot(out->fx, out->fy);
        if (ft > muN) {
            out->fx *= muN / ft;
            out->fy *= muN / ft;
        }
    }
    out->delta = d;
    out->cx = cxc;
    out->cy = cyc;
    out->cphi = k[2];
    for (m = 0; m < 3; m++) {
        out->force[m] = out->fx * fr.t1[m] + out->fy * fr.t2[m] + N * fr.n[m];
        out->point[m] = fr.P[m] + xc * fr.t1[m] + yc * fr.t2[m];
        out->t1[m] = fr.t1[m];
        out->t2[m] = fr.t2[m];
        out->n[m] = fr.n[m];
    }
    out->a = cp.a;
    out->b = cp.b;
    {
        const double cn = cbrt(N);
        out->area = node(p, RR_NH_AREA, kn, t) * (cn * cn);
        out->pmax = node(p, RR_NH_PMAX, kn, t) * cn;
    }
    *vert = out->force[2];
    return RR_OK;
}

/* --------------------------------------------------------------- a row */

/* The patches' normal loads' vertical parts at lowering dz. */
static double vertical_normal(const double *row, double dz)
{
    double sum = 0.0, nz;
    int j;
    for (j = 0; j < (int)row[1]; j++) {
        const double *p = row + RR_NH_PATCH(j);
        const double N = load(p, dz - p[0], &nz);
        sum += N * nz;
    }
    return sum;
}

/* dz with vertical_normal(dz) = target: a secant on S^(2/3) (nearly
 * linear in dz; tt = target^(2/3)), its first step by slope0 (d S^(2/3) /
 * d dz from the nodes; not positive: Hertz's law from dz = 0), bisection
 * once bracketed and the secant leaves the bracket.  RR_ERR_RANGE if it
 * does not settle. */
static int solve_dz(const double *row, double target, double tt, double slope0, double *dz_io)
{
    double dz = *dz_io, d0 = 0.0, f0 = 0.0, lo = 0.0, hi = 0.0, S, f, step;
    int it, have = 0, hlo = 0, hhi = 0;
    for (it = 0; it < DZ_ITER; it++) {
        S = vertical_normal(row, dz);
        if (fabs(S - target) <= DZ_TOL * target) {
            *dz_io = dz;
            return RR_OK;
        }
        if (S < target && (!hlo || dz > lo))
            lo = dz, hlo = 1;
        if (S > target && (!hhi || dz < hi))
            hi = dz, hhi = 1;
        {
            const double cs = cbrt(S);
            f = cs * cs - tt;
        }
        if (have && f != f0 && dz != d0)
            step = dz - f * (dz - d0) / (f - f0);
        else if (slope0 > 0.0 && slope0 <= DBL_MAX)
            step = dz - f / slope0;
        else
            step = dz * pow(target / (S > 1e-3 * target ? S : 1e-3 * target), 2.0 / 3.0);
        if (hlo && hhi && !(lo < step && step < hi))
            step = 0.5 * (lo + hi);
        else if (!(isfinite(step) && step > 0.0))
            step = hhi ? 0.5 * dz : 2.0 * dz;
        d0 = dz, f0 = f, have = 1;
        dz = step;
    }
    return RR_ERR_RANGE;
}

/* The vertical part of patch p's normal load at its load node k. */
static double node_vertical(const double *p, int k)
{
    const double e = p[RR_NH_NODE(RR_NH_E, k)];
    return e * sqrt(e) * p[RR_NH_NODE(RR_NH_Q, k)] * cos(p[RR_NH_NODE(RR_NH_DELTA, k)]);
}

/* One row at vertical load Fz: its patches (out->patch, npatch) and sums;
 * *tz_io the creep forces' vertical share to start from (the other row's,
 * 0 for the first: neighbouring rows share most of it, so the second row
 * settles in one pass where it would take two), the row's on return. */
static int eval_row(const rr_nh_table *tb, const double *row, const rr_motion *ws,
                    const rr_nh_state *s, const double law[2], rr_nh_result *out,
                    double *dz_out, double *tz_io)
{
    const int np = (int)row[1];
    const double *p0 = row + RR_NH_PATCH(0);
    double Tz = *tz_io < 0.5 * s->Fz ? *tz_io : 0.0;   /* a seed near Fz: from 0 */
    const double F0 = s->Fz - Tz;       /* the normal loads' vertical sum sought first */
    double T0 = 0.0, r0 = 0.0, r, step, dz, t, a0, a1, cF, vert, total, slope0 = NAN;
    int j, k, st, pass;
    /* a start: the shallowest-gap patch's nodes, N cos(delta) = F0, taken
     * between two nodes in (N cos delta)^(2/3), nearly linear in the
     * lowering (Hertz), whose slope there is the secant's first step.  In
     * the paper's scenario on the rig's pairs (stop 37): 2 to 2.25 load
     * sums a row where the load's linear interpolation (10^-2.3 of the
     * load off; now 10^-2.9 to 10^-3.6) and Hertz's step from dz = 0 took
     * 4 (DZ_TOL 1e-10; 3 to 4 at 1e-8) */
    for (j = 1; j < np; j++)
        if (row[RR_NH_PATCH(j)] < p0[0])
            p0 = row + RR_NH_PATCH(j);
    for (k = 0; k < RR_NH_NODES - 2; k++) {
        /* a node whose normal load is below F0 has its vertical part below
         * it too (cos delta <= 1): taken without the cosine */
        const double e = p0[RR_NH_NODE(RR_NH_E, k + 1)];
        if (e * sqrt(e) * p0[RR_NH_NODE(RR_NH_Q, k + 1)] >= F0 && node_vertical(p0, k + 1) >= F0)
            break;
    }
    {
        const double e0 = p0[RR_NH_NODE(RR_NH_E, k)], e1 = p0[RR_NH_NODE(RR_NH_E, k + 1)];
        double c0, c1;
        a0 = node_vertical(p0, k);      /* beyond the nodes: the last interval */
        a1 = node_vertical(p0, k + 1);
        c0 = cbrt(a0), c0 *= c0;
        c1 = cbrt(a1), c1 *= c1;
        cF = cbrt(F0), cF *= cF;
        if (c1 > c0) {
            t = (cF - c0) / (c1 - c0);
            slope0 = (c1 - c0) / (e1 - e0);
        } else {
            t = (F0 - a0) / (a1 - a0);
        }
        dz = p0[0] + e0 + t * (e1 - e0);
        if (!(dz > p0[0]))
            dz = p0[0] + e0;
    }
    for (pass = 0; pass < TZ_PASSES; pass++) {
        double Tn;
        if (!(s->Fz - Tz > 0.0))
            return RR_ERR_RANGE;
        if (pass > 0) {
            cF = cbrt(s->Fz - Tz);
            cF *= cF;
        }
        if ((st = solve_dz(row, s->Fz - Tz, cF, slope0, &dz)) < 0)
            return st;
        for (j = 0; j < np; j++) {
            const double *p = row + RR_NH_PATCH(j);
            if (dz - p[0] > E_BEYOND * p[RR_NH_NODE(RR_NH_E, RR_NH_NODES - 1)])
                return RR_ERR_TABLE;
        }
        total = 0.0;
        out->npatch = np;
        for (j = 0; j < np; j++) {
            if ((st = patch_forces(tb, row + RR_NH_PATCH(j), dz, ws, s, law, &out->patch[j],
                                   &vert, &out->table_calls)) < 0)
                return st;
            total += vert;
        }
        /* the creep forces' vertical share: the total's less the normal loads' */
        Tn = total - vertical_normal(row, dz);
        r = Tn - Tz;
        if (fabs(r) < TZ_TOL * s->Fz) {
            *dz_out = dz;
            *tz_io = Tn;
            return RR_OK;
        }
        /* a secant on the fixed point's residual (at the flange the share
         * is a large part of Fz and the plain iteration slow), kept below
         * Fz: halfway to Tn, or to Fz where the share reached it (a
         * saturated flange, mu tan(delta) > 1, whose share at the load
         * Fz exceeds Fz: the halfway to Tz that stood here stayed at Tz,
         * S1002 at -6.4 mm with lateral slip found no balance) */
        step = Tn;
        if (pass > 0 && r != r0)
            step = Tz - r * (Tz - T0) / (r - r0);
        if (!(step < s->Fz) || !isfinite(step))
            step = 0.5 * (Tz + (Tn < s->Fz ? Tn : s->Fz));
        T0 = Tz;
        r0 = r;
        Tz = step;
    }
    return RR_ERR_RANGE;
}

/* ----------------------------------------------------------- the wheel */

static void nan_result(rr_nh_result *out)
{
    int m;
    memset(out, 0, sizeof *out);
    for (m = 0; m < 3; m++)
        out->force[m] = out->moment[m] = out->centre[m] = NAN;
    out->N = out->area = out->pmax = out->w = out->dz[0] = out->dz[1] = NAN;
}

/* a += w b for the blended fields of a patch: loads, forces and sizes by
 * the row's weight w, the place and the plane by w times the patch's load
 * (*wn its sum: an unloaded patch has no place, its zeros must not pull a
 * loaded one's). */
static void add_patch(rr_nh_patch *a, double *wn, const rr_nh_patch *b, double w)
{
    const double v = w * b->N;
    int m;
    a->N += w * b->N;
    a->fx += w * b->fx;
    a->fy += w * b->fy;
    a->mz += w * b->mz;
    a->cx += w * b->cx;
    a->cy += w * b->cy;
    a->cphi += w * b->cphi;
    a->area += w * b->area;
    a->pmax += w * b->pmax;
    a->a += w * b->a;
    a->b += w * b->b;
    *wn += v;
    a->delta += v * b->delta;
    for (m = 0; m < 3; m++) {
        a->force[m] += w * b->force[m];
        a->point[m] += v * b->point[m];
        a->t1[m] += v * b->t1[m];
        a->t2[m] += v * b->t2[m];
        a->n[m] += v * b->n[m];
    }
}

static void normalise(double *v)
{
    const double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= l;
    v[1] /= l;
    v[2] /= l;
}

/* The output slot of each row's patches: a row's patches are ordered by
 * rig Y (rr_nonhertz_bands.c), so rows of one count pair them in order;
 * where one row has a patch fewer, each of its patches takes the slot of
 * the other row's nearest (the same region a row away), so that no patch
 * blends one region's place with another's.  Rows of zero weight keep
 * their order. */
static void match_patches(const rr_nh_result rr[2], const double wt[2],
                          int slot[2][RR_NH_MAX_PATCHES])
{
    int j, k, m;
    for (j = 0; j < 2; j++)
        for (k = 0; k < RR_NH_MAX_PATCHES; k++)
            slot[j][k] = k;
    if (wt[0] == 0.0 || wt[1] == 0.0 || rr[0].npatch == rr[1].npatch)
        return;
    j = rr[0].npatch < rr[1].npatch ? 0 : 1;        /* the row with fewer */
    for (k = 0; k < rr[j].npatch; k++) {
        double best = INFINITY;
        for (m = 0; m < rr[1 - j].npatch; m++) {
            const double *a = rr[j].patch[k].point, *b = rr[1 - j].patch[m].point;
            const double d = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1])
                             + (a[2] - b[2]) * (a[2] - b[2]);
            if (d < best) {
                best = d;
                slot[j][k] = m;
            }
        }
    }
}

int rr_nonhertz_wheel(const rr_nh_table *t, const rr_nh_state *s, rr_nh_result *out)
{
    return rr_nonhertz_wheel_law(t, s, 1.0, 0.0, 0.0, out);
}

int rr_nonhertz_wheel_law(const rr_nh_table *t, const rr_nh_state *s, double A, double B,
                          double tz_seed, rr_nh_result *out)
{
    const double law[2] = {A, B};
    double tz = isfinite(tz_seed) ? tz_seed : 0.0;
    rr_nh_result rr[2];
    const double *row[2];
    double w, wt[2];
    double wn[RR_NH_MAX_PATCHES] = {0.0};
    int i, j, k, m, st, calls, slot[2][RR_NH_MAX_PATCHES];
    if (!out)
        return RR_ERR_NULL;
    nan_result(out);
    if (!t || !t->rows || !s)
        return RR_ERR_NULL;
    {
        const double v[] = {s->y, s->Fz, s->mu, s->roller_spin, s->vmin, s->x, s->yaw};
        for (i = 0; i < 2; i++)
            if (!rr_all_finite(s->motion[i].c, 3) || !rr_all_finite(s->motion[i].v, 3)
                || !rr_all_finite(s->motion[i].w, 3))
                return RR_ERR_NONFINITE;
        if (!rr_all_finite(v, RR_COUNTOF(v)))
            return RR_ERR_NONFINITE;
    }
    if (!(s->Fz > 0.0))
        return RR_ERR_LOAD;
    if (!isfinite(A) || !isfinite(B))
        return RR_ERR_NONFINITE;
    if (!(s->mu > 0.0) || !(A > 0.0 && A <= 1.0) || !(B >= 0.0))
        return RR_ERR_FRICTION;
    if (!(s->vmin > 0.0))
        return RR_ERR_SPEED;
    if ((st = rr_nonhertz_locate(t, s->y, &i, &w)) < 0)
        return st;
    wt[0] = 1.0 - w;
    wt[1] = w;
    calls = 0;
    for (j = 0; j < 2; j++) {
        const double np = (row[j] = t->rows + (size_t)(i + j) * RR_NH_ROW_LEN)[1];
        if (!(np >= 1.0 && np <= RR_NH_MAX_PATCHES))
            return RR_ERR_TABLE;
        memset(&rr[j], 0, sizeof rr[j]);
        /* a row of zero weight is not needed (y on a row) */
        if (wt[j] == 0.0)
            continue;
        if ((st = eval_row(t, row[j], &s->motion[j], s, law, &rr[j], &rr[j].dz[0], &tz)) < 0) {
            nan_result(out);
            return st;
        }
        calls += rr[j].table_calls;
    }
    /* the blend: totals, moments about each row's centre, each patch with
     * its own region's in the other row (match_patches) */
    match_patches(rr, wt, slot);
    memset(out, 0, sizeof *out);
    out->tz = tz;
    out->row = i;
    out->w = w;
    out->table_calls = calls;
    for (j = 0; j < 2; j++) {
        out->dz[j] = wt[j] == 0.0 ? NAN : rr[j].dz[0];
        if (wt[j] == 0.0)
            continue;
        for (k = 0; k < rr[j].npatch; k++) {
            const rr_nh_patch *p = &rr[j].patch[k];
            const double *c = s->motion[j].c;
            const double r[3] = {p->point[0] - c[0], p->point[1] - c[1], p->point[2] - c[2]};
            const double *n = p->n;
            if (slot[j][k] + 1 > out->npatch)
                out->npatch = slot[j][k] + 1;
            add_patch(&out->patch[slot[j][k]], &wn[slot[j][k]], p, wt[j]);
            out->moment[0] += wt[j] * (r[1] * p->force[2] - r[2] * p->force[1] + p->mz * n[0]);
            out->moment[1] += wt[j] * (r[2] * p->force[0] - r[0] * p->force[2] + p->mz * n[1]);
            out->moment[2] += wt[j] * (r[0] * p->force[1] - r[1] * p->force[0] + p->mz * n[2]);
        }
    }
    /* the place and plane by load; an unloaded patch (a region that
     * touches only above this load, in both rows) left out */
    for (j = k = 0; j < out->npatch; j++) {
        rr_nh_patch *p = &out->patch[j];
        if (!(wn[j] > 0.0))
            continue;
        p->delta /= wn[j];
        for (m = 0; m < 3; m++)
            p->point[m] /= wn[j];
        normalise(p->t1);
        normalise(p->t2);
        normalise(p->n);
        if (k != j)
            out->patch[k] = *p;
        k++;
    }
    out->npatch = k;
    for (j = 0; j < out->npatch; j++) {
        const rr_nh_patch *p = &out->patch[j];
        out->N += p->N;
        out->area += p->area;
        out->pmax = p->pmax > out->pmax ? p->pmax : out->pmax;
        for (m = 0; m < 3; m++) {
            out->force[m] += p->force[m];
            out->centre[m] += p->N * p->point[m];
        }
    }
    for (m = 0; m < 3; m++)
        out->centre[m] = out->N > 0.0 ? out->centre[m] / out->N : NAN;
    if (!rr_all_finite(out->force, 3) || !rr_all_finite(out->moment, 3)
        || !rr_all_finite(out->centre, 3) || !isfinite(out->N) || !isfinite(out->area)
        || !isfinite(out->pmax)) {
        nan_result(out);
        return RR_ERR_RANGE;
    }
    return RR_OK;
}
