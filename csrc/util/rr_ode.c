/* rr_ode.c - fixed-step Rosenbrock-W, TR-BDF2 and linearly implicit Euler. */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include "util/rr_common.h"
#include "util/rr_ode.h"

#define RR_SQRT2 1.41421356237309504880

/* ROS2: gamma = 1 + 1/sqrt(2) (Verwer et al. 1999) */
static const double ros2_gamma = 1.0 + 1.0 / RR_SQRT2;
/* TR-BDF2 (Hosea & Shampine 1996): gamma_TR = 2 - sqrt(2), d = gamma_TR/2, w = sqrt(2)/4 */
static const double trbdf2_c2 = 2.0 - RR_SQRT2;
static const double trbdf2_d = 1.0 - RR_SQRT2 / 2.0;
static const double trbdf2_w = RR_SQRT2 / 4.0;

int rr_lu_factor(int n, double *A, int *piv)
{
    double amax = 0.0, thresh;
    int i, j, k;

    if (!A || !piv)
        return RR_ERR_NULL;
    if (n < 1 || n > RR_ODE_MAXN)
        return RR_ERR_PARAM;

    for (i = 0; i < n * n; i++) {
        double a = fabs(A[i]);
        if (!isfinite(a))
            return RR_ERR_NONFINITE;
        if (a > amax)
            amax = a;
    }
    /* a pivot at rounding level of the largest entry means W is singular to
     * working precision: the solve would return noise */
    thresh = n * DBL_EPSILON * amax;
    for (k = 0; k < n; k++) {
        int p = k;
        double pmax = fabs(A[k * n + k]), inv;

        for (i = k + 1; i < n; i++)
            if (fabs(A[i * n + k]) > pmax) {
                pmax = fabs(A[i * n + k]);
                p = i;
            }
        piv[k] = p;
        if (!(pmax > thresh))
            return RR_ERR_SINGULAR;
        if (p != k)
            for (j = 0; j < n; j++) {
                double tmp = A[k * n + j];
                A[k * n + j] = A[p * n + j];
                A[p * n + j] = tmp;
            }
        inv = 1.0 / A[k * n + k];
        A[k * n + k] = inv;    /* the solve multiplies: no division in its chain */
        for (i = k + 1; i < n; i++) {
            double l = A[i * n + k] * inv;
            A[i * n + k] = l;
            /* no skip for l == 0: the work must not depend on the data */
            for (j = k + 1; j < n; j++)
                A[i * n + j] -= l * A[k * n + j];
        }
    }
    /* entries near the largest double overflow the elimination; a pivot
     * below 1/DBL_MAX passes the relative test but has no reciprocal */
    return rr_all_finite(A, n * n) ? RR_OK : RR_ERR_RANGE;
}

/* The solve on factors known to come from rr_lu_factor (the step's own). */
static void lu_solve(int n, const double *LU, const int *piv, double *b);

void rr_lu_solve(int n, const double *LU, const int *piv, double *b)
{
    int k;

    if (!LU || !piv || !b || n < 1 || n > RR_ODE_MAXN)
        return;
    for (k = 0; k < n; k++)
        if (piv[k] < k || piv[k] >= n)
            return;                 /* not factors of rr_lu_factor */
    lu_solve(n, LU, piv, b);
}

static void lu_solve(int n, const double *LU, const int *piv, double *b)
{
    int i, j, k;

    for (k = 0; k < n; k++)
        if (piv[k] != k) {
            double tmp = b[k];
            b[k] = b[piv[k]];
            b[piv[k]] = tmp;
        }
    /* column by column: the updates of one column are independent, so the
     * dependent chain is n long, not n^2/2 */
    for (j = 0; j < n; j++) {
        const double bj = b[j];
        for (i = j + 1; i < n; i++)
            b[i] -= LU[i * n + j] * bj;
    }
    for (j = n - 1; j >= 0; j--) {
        const double bj = b[j] * LU[j * n + j];
        b[j] = bj;
        for (i = 0; i < j; i++)
            b[i] -= LU[i * n + j] * bj;
    }
}

static int settings_check(const rr_ode *s)
{
    int i;

    if (s == NULL)
        return RR_ERR_NULL;
    if (s->n < 1 || s->n > RR_ODE_MAXN)
        return RR_ERR_PARAM;
    if (s->method != RR_ODE_ROS2 && s->method != RR_ODE_TRBDF2
        && s->method != RR_ODE_LINEULER)
        return RR_ERR_METHOD;
    if (s->nq < 0 || s->nq > s->n / 2 || (s->linear_tr != 0 && s->linear_tr != 1))
        return RR_ERR_PARAM;
    if (s->method == RR_ODE_TRBDF2
        && (s->newton_iters < 0 || s->newton_iters > RR_ODE_MAX_NEWTON
            || !(s->newton_tol > 0.0)))
        return RR_ERR_PARAM;
    for (i = 0; i < s->n; i++)
        if (!(s->ytyp[i] > 0.0) || !isfinite(s->ytyp[i]))
            return RR_ERR_PARAM;
    return RR_OK;
}

int rr_ode_init(rr_ode *s, int n, int method)
{
    int i;

    if (s == NULL)
        return RR_ERR_NULL;
    if (n < 1 || n > RR_ODE_MAXN)
        return RR_ERR_PARAM;
    s->n = n;
    s->method = method;
    s->newton_iters = 2;
    s->newton_tol = 1e-6;
    s->nq = 0;
    s->linear_tr = 0;
    s->model = NULL;
    for (i = 0; i < RR_ODE_MAXN; i++)
        s->ytyp[i] = 1.0;
    s->nfev = 0;
    s->nmev = 0;
    s->njev = 0;
    s->newton_err = 0.0;
    return settings_check(s);
}

int rr_ode_nfev(const rr_ode *s, int jac_given)
{
    int fd;

    if (settings_check(s) != RR_OK)
        return -1;
    fd = jac_given ? 0 : s->n;
    switch (s->method) {
    case RR_ODE_ROS2:
        return 2 + fd;
    case RR_ODE_TRBDF2:
        return 1 + (s->model ? 0 : (s->linear_tr ? 1 : 2) * s->newton_iters) + fd;
    default:
        return 1 + fd;
    }
}

/* A callback's status st merged into *warn (an error passed on) and its n
 * outputs v checked. */
static int merge(const rr_ode *s, int st, const double *v, int *warn)
{
    if (st < 0)
        return st;
    if (st > *warn)
        *warn = st;
    return rr_all_finite(v, s->n) ? RR_OK : RR_ERR_NONFINITE;
}

/* 0, or RR_ERR_RANGE if a stage value overflowed (the step's inputs are
 * checked finite, so only the arithmetic of the step can have made it). */
static int stage_finite(const rr_ode *s, const double *y)
{
    return rr_all_finite(y, s->n) ? RR_OK : RR_ERR_RANGE;
}

/* One call of f, counted. */
static int call_f(rr_ode *s, rr_ode_rhs f, void *ctx, double t, const double *y,
                  double *dydt, int *warn)
{
    const int st = stage_finite(s, y);
    if (st < 0)
        return st;
    s->nfev++;
    return merge(s, f(ctx, t, y, dydt), dydt, warn);
}

/* s->r <- f(t0, y0) + model(t, y0, z), counted. */
static int call_model(rr_ode *s, void *ctx, double t, const double *z, int *warn)
{
    int i, st;

    if ((st = stage_finite(s, z)) < 0)
        return st;
    s->nmev++;
    st = s->model(ctx, t, s->y0, z, s->r);
    if (st >= 0)
        for (i = 0; i < s->n; i++)
            s->r[i] += s->f0[i];
    return merge(s, st, s->r, warn);
}

/* J at (t, y0) into s->W, analytic or by forward differences from f0. */
static int jacobian(rr_ode *s, rr_ode_rhs f, rr_ode_jac jac, void *ctx, double t, int *warn)
{
    const int n = s->n;
    int i, j, st;

    if (jac != NULL) {
        s->njev++;
        st = jac(ctx, t, s->y0, s->W);
        if (st < 0)
            return st;
        if (st > *warn)
            *warn = st;
        {
            /* one test at the end, no branch per entry: an infinity or NaN
             * has every exponent bit set, and only then does adding the
             * exponent's lowest bit to them carry into the sign bit (integer
             * operations the compiler vectorises; the comparison per entry
             * it did not, 8 instructions an entry, 2 % of the rig's step) */
            const uint64_t exponent = 0x7ff0000000000000u, one = 0x0010000000000000u;
            uint64_t bad = 0, u;
            for (i = 0; i < n * n; i++) {
                memcpy(&u, &s->W[i], sizeof u);
                bad |= (u & exponent) + one;
            }
            if (bad >> 63)
                return RR_ERR_NONFINITE;
        }
        return RR_OK;
    }
    for (i = 0; i < n; i++)
        s->z[i] = s->y0[i];
    for (j = 0; j < n; j++) {
        double yj = s->y0[j], a = fabs(yj), delta;

        delta = sqrt(DBL_EPSILON) * (a > s->ytyp[j] ? a : s->ytyp[j]);
        s->z[j] = yj + delta;
        /* the increment actually represented, so the quotient has no extra rounding */
        delta = s->z[j] - yj;
        st = call_f(s, f, ctx, t, s->z, s->r, warn);
        s->z[j] = yj;
        if (st < 0)
            return st;
        for (i = 0; i < n; i++)
            s->W[i * n + j] = (s->r[i] - s->f0[i]) / delta;
    }
    return RR_OK;
}

/* The LU factors of the iteration matrix I - g J, J being in s->W.
 * Without structure (nq = 0) W itself is factored in place.  With nq
 * positions whose derivatives are the next nq states (rows q_i' = y_{nq+i}
 * of J are [0 I 0] by assumption, whatever jac wrote there), W d = r splits
 * into d_q = r_q + g d_v and a system in the other m = n - nq unknowns,
 *     M d_u = r_u + g J_uq r_q,   M = I - g J_uu - g^2 J_uq P,
 * P moving the q columns onto their v columns (the special structure of
 * Hairer and Wanner's RADAU5, its M1 = M2 = nq): an m x m LU instead of an
 * n x n one; J stays in W for the solves. */
static int iteration_matrix(rr_ode *s, double g)
{
    const int n = s->n, nq = s->nq, m = n - nq;
    int i, j;

    s->g = g;
    if (nq == 0) {
        for (i = 0; i < n * n; i++)
            s->W[i] *= -g;
        for (i = 0; i < n; i++)
            s->W[i * n + i] += 1.0;
        return rr_lu_factor(n, s->W, s->piv);
    }
    for (i = 0; i < m; i++) {
        const double *Ju = s->W + (nq + i) * n;
        for (j = 0; j < m; j++)
            s->M[i * m + j] = -g * Ju[nq + j];
        for (j = 0; j < nq; j++)
            s->M[i * m + j] -= g * g * Ju[j];
        s->M[i * m + i] += 1.0;
    }
    return rr_lu_factor(m, s->M, s->piv);
}

/* b <- (I - g J)^-1 b with the factors of iteration_matrix. */
static void solve(const rr_ode *s, double *b)
{
    const int n = s->n, nq = s->nq, m = n - nq;
    int i, j;

    if (nq == 0) {
        lu_solve(n, s->W, s->piv, b);
        return;
    }
    for (i = 0; i < m; i++) {
        const double *Ju = s->W + (nq + i) * n;
        double sum = 0.0;
        for (j = 0; j < nq; j++)
            sum += Ju[j] * b[j];
        b[nq + i] += s->g * sum;
    }
    lu_solve(m, s->M, s->piv, b + nq);
    for (j = 0; j < nq; j++)
        b[j] += s->g * b[nq + j];
}

/* max_i |dz_i| / (|z_i| + ytyp_i) */
static double scaled_norm(const rr_ode *s, const double *dz, const double *z)
{
    double m = 0.0;
    int i;

    for (i = 0; i < s->n; i++) {
        double e = fabs(dz[i]) / (fabs(z[i]) + s->ytyp[i]);
        if (e > m)
            m = e;
    }
    return m;
}

/*
 * Simplified Newton for z = base + hd f(tz, z), W = I - hd J factored.
 * A predictor correction from z (in/out) with fz0 standing for f(tz, z),
 * which needs no f evaluation, then s->newton_iters iterations, each with
 * the true residual.  Uses s->r.  *err: the error left in z, estimated
 * from the last two true corrections as theta/(1 - theta) |dz_m|, theta =
 * |dz_m|/|dz_{m-1}| (Hairer & Wanner, Solving ODEs II, IV.8, eq. (8.10)),
 * in the scaled norm (|dz_{m-1}| taken as at least newton_tol/1000, so
 * that two corrections at rounding level do not look like divergence);
 * infinite if they do not contract.  With one iteration there is no theta
 * and |dz_1| itself is the (pessimistic) estimate.  The predictor correction does not enter theta: its residual
 * is off by hd (f(tz, z) - fz0), which for a stiff t-dependent forcing is
 * as large as the correction itself.
 */
static int newton_stage(rr_ode *s, rr_ode_rhs f, void *ctx, double tz, double hd,
                        const double *base, const double *fz0, double *z, double *err,
                        int *warn, int iters)
{
    const int n = s->n;
    double prev = 0.0, cur = 0.0, theta;
    int it, i, st;

    for (it = 0; it <= iters; it++) {
        if (it == 0) {
            for (i = 0; i < n; i++)
                s->r[i] = fz0[i];
        } else if (s->model) {
            st = call_model(s, ctx, tz, z, warn);
            if (st < 0)
                return st;
        } else {
            st = call_f(s, f, ctx, tz, z, s->r, warn);
            if (st < 0)
                return st;
        }
        /* r <- -G(z) = base + hd f(z) - z */
        for (i = 0; i < n; i++)
            s->r[i] = base[i] + hd * s->r[i] - z[i];
        solve(s, s->r);
        for (i = 0; i < n; i++)
            z[i] += s->r[i];
        prev = cur;
        cur = scaled_norm(s, s->r, z);
    }
    if (iters == 0)
        *err = 0.0;     /* linearly implicit: nothing iterated, nothing to estimate */
    else if (iters == 1 || cur == 0.0)
        *err = cur;
    else {
        /* corrections below newton_tol/1000 are rounding noise, not a rate */
        double noise = 1e-3 * s->newton_tol;
        theta = cur / (prev > noise ? prev : noise);
        *err = theta < 1.0 ? theta / (1.0 - theta) * cur : INFINITY;
    }
    return RR_OK;
}

static int step_ros2(rr_ode *s, rr_ode_rhs f, void *ctx, double t, double h, int *warn)
{
    const int n = s->n;
    int i, st;

    for (i = 0; i < n; i++)
        s->k1[i] = s->f0[i];
    solve(s, s->k1);
    for (i = 0; i < n; i++)
        s->z[i] = s->y0[i] + h * s->k1[i];
    st = call_f(s, f, ctx, t + h, s->z, s->k2, warn);
    if (st < 0)
        return st;
    for (i = 0; i < n; i++)
        s->k2[i] -= 2.0 * s->k1[i];
    solve(s, s->k2);
    for (i = 0; i < n; i++)
        s->z[i] = s->y0[i] + h * (1.5 * s->k1[i] + 0.5 * s->k2[i]);
    return RR_OK;
}

static int step_trbdf2(rr_ode *s, rr_ode_rhs f, void *ctx, double t, double h, int *warn)
{
    const int n = s->n;
    const double hd = trbdf2_d * h;
    double err2, err3;
    int i, st;

    /* trapezoidal stage from z = y0, where f is known (up to the time shift) */
    for (i = 0; i < n; i++) {
        s->k1[i] = s->y0[i] + hd * s->f0[i];   /* base of the TR stage */
        s->z[i] = s->y0[i];
    }
    st = newton_stage(s, f, ctx, t + trbdf2_c2 * h, hd, s->k1, s->f0, s->z, &err2, warn,
                      s->linear_tr ? 0 : s->newton_iters);
    if (st < 0)
        return st;
    /* f2 implied by the trapezoidal equation, then the BDF2 stage's base */
    for (i = 0; i < n; i++) {
        s->k2[i] = (s->z[i] - s->k1[i]) / hd;
        s->k1[i] = s->y0[i] + trbdf2_w * h * (s->f0[i] + s->k2[i]);
    }
    /* BDF2 stage from z = z2, with f2 standing for f(t + h, z2) */
    st = newton_stage(s, f, ctx, t + h, hd, s->k1, s->k2, s->z, &err3, warn, s->newton_iters);
    if (st < 0)
        return st;
    s->newton_err = err2 > err3 ? err2 : err3;
    if (!(s->newton_err <= s->newton_tol) && *warn < RR_WARN_NOT_CONVERGED)
        *warn = RR_WARN_NOT_CONVERGED;
    return RR_OK;
}

int rr_ode_step(rr_ode *s, rr_ode_rhs f, rr_ode_jac jac, void *ctx, double t, double h,
                double *y)
{
    int i, n, st, warn = RR_OK;
    double g;

    st = settings_check(s);
    if (st != RR_OK)
        return st;
    s->nfev = 0;
    s->nmev = 0;
    s->njev = 0;
    s->newton_err = 0.0;
    if (f == NULL || y == NULL)
        return RR_ERR_NULL;
    if (!isfinite(t) || !isfinite(h))
        return RR_ERR_NONFINITE;
    if (!(h > 0.0))
        return RR_ERR_PARAM;
    n = s->n;
    /* work on a copy: y is only written once the step has succeeded */
    for (i = 0; i < n; i++) {
        if (!isfinite(y[i]))
            return RR_ERR_NONFINITE;
        s->y0[i] = y[i];
    }
    st = call_f(s, f, ctx, t, s->y0, s->f0, &warn);
    if (st < 0)
        return st;
    st = jacobian(s, f, jac, ctx, t, &warn);
    if (st < 0)
        return st;
    g = s->method == RR_ODE_ROS2 ? ros2_gamma : s->method == RR_ODE_TRBDF2 ? trbdf2_d : 1.0;
    st = iteration_matrix(s, g * h);
    if (st < 0)
        return st;
    switch (s->method) {
    case RR_ODE_ROS2:
        st = step_ros2(s, f, ctx, t, h, &warn);
        break;
    case RR_ODE_TRBDF2:
        st = step_trbdf2(s, f, ctx, t, h, &warn);
        break;
    default:
        for (i = 0; i < n; i++)
            s->k1[i] = s->f0[i];
        solve(s, s->k1);
        for (i = 0; i < n; i++)
            s->z[i] = s->y0[i] + h * s->k1[i];
        st = RR_OK;
        break;
    }
    if (st < 0)
        return st;
    for (i = 0; i < n; i++)
        if (!isfinite(s->z[i]))
            return RR_ERR_RANGE;    /* finite inputs, an overflowing step */
    for (i = 0; i < n; i++)
        y[i] = s->z[i];
    return warn;
}
