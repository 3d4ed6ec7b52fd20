/*
 * rr_exact_normal.c - the exact solver's normal problem (rr_exact.h):
 * NormCG (Kalker's, as CONTACT's) on the contact set with the inverse
 * stencil as preconditioner, from the Hertzian start, one from h or the
 * caller's (rr_exact_solve_from), the products by FFT.
 */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "util/rr_fft.h"
#include "contact/rr_hertz.h"
#include "contact/rr_exact.h"
#include "contact/rr_exact_solver.h"

/* ---- the normal problem ---------------------------------------------------- */

/* NormCG's residual and its preconditioned form: r = delta - g on the
 * contact set (0 elsewhere) and z = S r there, S the normal operator's
 * inverse stencil; returns the mean of z on the set, *count its elements */
static double normal_residual_stencil(const layout *L, double delta, const double *g,
                                      double *r, double *z, int *count)
{
    const int mx = L->mx, my = L->my, w = mx + 2;
    const double s0 = L->stn[0], s1 = L->stn[1], s2 = L->stn[2], s3 = L->stn[3];
    const signed char *in = L->state;
    double *h = L->halo, sum = 0.0;
    int i, j, c = 0;
    memset(h, 0, (size_t)w * sizeof *h);
    memset(h + (size_t)(my + 1) * w, 0, (size_t)w * sizeof *h);
    for (j = 0; j < my; j++) {
        double *o = h + (size_t)(j + 1) * w;
        o[0] = o[mx + 1] = 0.0;
        for (i = 0; i < mx; i++) {
            const int k = j * mx + i;
            r[k] = in[k] != OUTSIDE ? delta - g[k] : 0.0;
            o[i + 1] = r[k];
        }
    }
    for (j = 0; j < my; j++)
        for (i = 0; i < mx; i++) {
            const int k = j * mx + i, q = (j + 1) * w + i + 1;
            if (in[k] != OUTSIDE) {
                z[k] = STENCIL3(s0, s1, s2, s3, h, q, w);
                sum += z[k];
                c++;
            } else {
                z[k] = 0.0;
            }
        }
    *count = c;
    return c ? sum / c : 0.0;
}

/* u = (dx/G) A_nn * p; the caller's interrupt hook is polled before every
 * product, the unit of the solver's work (RR_ERR_INTERRUPTED) */
static int normal_product(solver *S, const double *p, double *u)
{
    const double sc = S->pb->grid.dx / S->pb->G;
    int k, st;
    if (rr_interrupted(S->pb->interrupt))
        return RR_ERR_INTERRUPTED;
    st = rr_conv2d_apply(S->cv, S->L->snn, p, u);
    for (k = 0; k < S->L->n; k++)
        u[k] *= sc;
    S->products++;
    /* the inputs were checked: a product that fails has overflowed */
    return st < 0 ? RR_ERR_RANGE : st;
}

/* g = h + u(p): the gap before the approach, from a fresh product */
static int gap_of(solver *S, const double *p, double *g)
{
    int k, st = normal_product(S, p, g);
    for (k = 0; k < S->L->n; k++)
        g[k] += S->L->h[k];
    return st;
}

int rr_exact_normal_displacement(solver *S, const double *p, double *u)
{
    return normal_product(S, p, u);
}

static double mean_on(const double *v, const signed char *in, int n, int *count)
{
    double sum = 0.0;
    int k, c = 0;
    for (k = 0; k < n; k++)
        if (in[k] != OUTSIDE) {
            sum += v[k];
            c++;
        }
    *count = c;
    return c ? sum / c : 0.0;
}

/* A start from q (in p on entry): the pressure sqrt(q) where q > 0 (those
 * elements make the first contact set), scaled to the load N.  Returns the
 * elements in contact, 0 where none or not finite. */
static int start_from_q(const rr_exact_problem *pb, layout *L, double *p)
{
    const int n = L->n;
    double psum = 0.0;
    int k, cnt = 0;
    for (k = 0; k < n; k++) {
        const double q = p[k];
        L->state[k] = q > 0.0 ? ADHESION : OUTSIDE;
        p[k] = q > 0.0 ? sqrt(q) : 0.0;
        psum += p[k];
        cnt += q > 0.0;
    }
    if (cnt == 0 || !(psum > 0.0))
        return 0;
    for (k = 0; k < n; k++)
        p[k] *= pb->N / (pb->grid.dx * pb->grid.dy * psum);
    return rr_all_finite(p, n) ? cnt : 0;
}

/* A start for any h: Hertz's pressure of the curvatures of h at its
 * lowest element (second differences), laid over the level sets of h:
 * p = sqrt(1 - h/h_c) with h_c the gap at the Hertzian ellipse's rim.  A
 * patch that is not elliptic gets the right shape roughly, which saves CG
 * steps against a uniform start.  Returns the elements in contact, 0 where
 * h has no usable curvature there (the caller starts otherwise). */
static int start_from_h(const rr_exact_problem *pb, layout *L, const double *h, double *p)
{
    const int mx = L->mx, my = L->my, n = L->n;
    const double dx = pb->grid.dx, dy = pb->grid.dy;
    int k, i, j, km = 0;
    double A, B, hc;
    rr_hertz_result hz;

    for (k = 1; k < n; k++)
        if (h[k] < h[km])
            km = k;
    i = km % mx;
    j = km / mx;
    if (i < 1 || i > mx - 2 || j < 1 || j > my - 2)
        return 0;
    A = (h[km + 1] - 2.0 * h[km] + h[km - 1]) / (2.0 * dx * dx);
    B = (h[km + mx] - 2.0 * h[km] + h[km - mx]) / (2.0 * dy * dy);
    if (!(A > 0.0) || !(B > 0.0)
        || rr_hertz(A, B, pb->N, pb->G / (1.0 - pb->nu), &hz) != RR_OK)
        return 0;
    hc = 0.5 * (A * hz.a * hz.a + B * hz.b * hz.b);
    if (!(hc > 0.0) || !isfinite(hc))
        return 0;
    for (k = 0; k < n; k++)
        p[k] = 1.0 - (h[k] - h[km]) / hc;
    return start_from_q(pb, L, p);
}

/* The caller's start (rr_exact_start, checked: finite, >= 0, some > 0):
 * its positive elements the first contact set, its shape scaled to the
 * load N (through its largest value, so that no sum overflows).  Returns
 * the elements in contact. */
static int start_from_caller(const rr_exact_problem *pb, layout *L, const double *pn, double *p)
{
    const int n = L->n;
    double pmax = 0.0, psum = 0.0;
    int k, cnt = 0;
    for (k = 0; k < n; k++)
        pmax = pn[k] > pmax ? pn[k] : pmax;
    for (k = 0; k < n; k++) {
        L->state[k] = pn[k] > 0.0 ? ADHESION : OUTSIDE;
        p[k] = pn[k] / pmax;
        psum += p[k];
        cnt += pn[k] > 0.0;
    }
    for (k = 0; k < n; k++)
        p[k] *= pb->N / (pb->grid.dx * pb->grid.dy * psum);
    return cnt;
}

/* NormCG: min 1/2 p.Ap + h.p over p >= 0 with dA sum p = N; the approach is
 * the multiplier, eliminated by keeping every search direction mean-free on
 * the contact set C.  Preconditioned, as Vollebregt's NormCG, by an
 * approximate inverse of A restricted to C and made mean-free there: here
 * the 3 x 3 stencil of the inverse (normal_stencil in rr_exact_ops.c), which costs a
 * stencil instead of a product and took the products on the 300 random
 * cases from 18.4 to 10.0 at 27 across, 20.7 to 10.8 at 45.  Returns the
 * status; res gets delta, the products and the residual. */
int rr_exact_solve_normal(solver *S, rr_exact_result *res)
{
    const rr_exact_problem *pb = S->pb;
    layout *L = S->L;
    const int n = L->n;
    const double dA = pb->grid.dx * pb->grid.dy;
    double *h = L->h, *p = L->pn, *g = L->gap, *r = L->r, *rold = L->rold, *d = L->d,
           *v = L->v, *z = L->stn[4] != 0.0 ? L->z : L->r;
    signed char *in = L->state;
    double hmin = HUGE_VAL, hmax = -HUGE_VAL, delta = 0.0, rz_old = 0.0, step_rms = 1.0;
    double h0;
    rr_hertz_result hz;
    int k, cnt, restart = 1, st, converged = 0, have_delta = 0;

    for (k = 0; k < n; k++) {
        if (h[k] < hmin) hmin = h[k];
        if (h[k] > hmax) hmax = h[k];
    }
    /* h from its lowest value: a large offset would drown the gap's
     * variation in round-off (the approach absorbs any constant) */
    for (k = 0; k < n; k++)
        h[k] -= hmin;
    hmax -= hmin;
    h0 = hmin;
    hmin = 0.0;
    /* start: the caller's; else Hertz's pressure where h is Hertzian (the
     * discrete solution differs by about 1 % rms: a few CG steps), else the
     * lowest tenth of h under a uniform pressure */
    cnt = 0;
    if (S->start)
        cnt = start_from_caller(pb, L, S->start->pn, p);
    else if (!pb->h && rr_hertz(pb->A, pb->B, pb->N, pb->G / (1.0 - pb->nu), &hz) == RR_OK) {
        for (k = 0; k < n; k++) {
            const double x = (pb->grid.x0 + (k % L->mx) * pb->grid.dx) / hz.a;
            const double y = (pb->grid.y0 + (k / L->mx) * pb->grid.dy) / hz.b;
            p[k] = 1.0 - x * x - y * y;
        }
        cnt = start_from_q(pb, L, p);
    }
    if (cnt == 0)
        cnt = start_from_h(pb, L, h, p);
    if (cnt == 0) {
        for (k = 0; k < n; k++) {
            in[k] = (h[k] <= hmin + 0.1 * (hmax - hmin)) ? ADHESION : OUTSIDE;
            cnt += in[k] != OUTSIDE;
        }
        for (k = 0; k < n; k++)
            p[k] = in[k] != OUTSIDE ? pb->N / (dA * cnt) : 0.0;
    }
    if ((st = gap_of(S, p, g)) < 0)
        return st;

    /* the passes over the grid fused where one can follow another: r with
     * its halo copy, the stencil with z's sum, z's projection with the dot
     * products, d with its sum, d's projection with r.d, the update with
     * the checks and the next approach */
    while (S->products < pb->maxit) {
        double rz = 0.0, rzold = 0.0, rd = 0.0, dv = 0.0, alpha, beta, psum = 0.0, p2 = 0.0,
               s2 = 0.0, dsum = 0.0, gsum = 0.0, dm;
        int changed = 0, nc;

        if (!have_delta)
            delta = mean_on(g, in, n, &nc);
        /* z: the preconditioned residual (z = r without a stencil) */
        if (L->stn[4] != 0.0) {
            const double zm = normal_residual_stencil(L, delta, g, r, z, &nc);
            for (k = 0; k < n; k++)
                if (in[k] != OUTSIDE) {
                    z[k] -= zm;
                    rz += r[k] * z[k];
                    if (!restart)
                        rzold += z[k] * rold[k];
                }
        } else {
            nc = 0;
            for (k = 0; k < n; k++) {
                r[k] = in[k] != OUTSIDE ? delta - g[k] : 0.0;
                nc += in[k] != OUTSIDE;
                rz += r[k] * r[k];
                if (!restart)
                    rzold += r[k] * rold[k];
            }
        }
        if (rz == 0.0) {
            /* no residual on C (a set of one element has none): converged
             * unless exterior elements that the surfaces penetrate join C
             * (a start of too few elements, the caller's) */
            int joined = 0;
            for (k = 0; k < n; k++)
                if (in[k] == OUTSIDE && g[k] < delta) {
                    in[k] = ADHESION;
                    joined = 1;
                }
            if (!joined) {
                converged = 1;
                step_rms = 0.0;          /* nothing left to move */
                break;
            }
            restart = 1;
            have_delta = 0;
            continue;
        }
        /* Polak-Ribiere, reset to steepest descent after a change of C; a
         * restart never reads d (what the workspace holds from another
         * case, a NaN of a failed one, would survive 0 d) */
        beta = restart ? 0.0 : fmax(0.0, (rz - rzold) / rz_old);
        for (k = 0; k < n; k++) {
            d[k] = in[k] == OUTSIDE ? 0.0 : restart ? z[k] : z[k] + beta * d[k];
            rold[k] = r[k];
            dsum += d[k];
        }
        /* mean-free on C to round-off, so that the load stays N */
        dm = nc ? dsum / nc : 0.0;
        for (k = 0; k < n; k++)
            if (in[k] != OUTSIDE) {
                d[k] -= dm;
                rd += r[k] * d[k];
            }
        rz_old = rz;
        restart = 0;
        if ((st = normal_product(S, d, v)) < 0)
            return st;
        for (k = 0; k < n; k++)
            dv += d[k] * v[k];
        /* d.v overflowing (elements of 1e62 m: the gap's 1e127 m against
         * displacements scaled by dx / G) made alpha 0, and the unmoved
         * pressure passed for converged: scales beyond the doubles */
        if (!(dv > 0.0) || !(dv < HUGE_VAL) || !isfinite(rd))
            return RR_ERR_RANGE;
        alpha = rd / dv;
        /* the gap changes everywhere, the pressure only on C; elements
         * pulled below zero leave C (the load is then restored by scaling) */
        for (k = 0; k < n; k++) {
            g[k] += alpha * v[k];
            if (in[k] != OUTSIDE) {
                p[k] += alpha * d[k];
                s2 += (alpha * d[k]) * (alpha * d[k]);
                if (p[k] < 0.0) {
                    p[k] = 0.0;
                    in[k] = OUTSIDE;
                    changed = 1;
                } else {
                    p2 += p[k] * p[k];
                    gsum += g[k];
                }
            }
        }
        if (changed) {
            for (k = 0; k < n; k++)
                psum += p[k];
            if (!(psum > 0.0))
                return RR_ERR_GEOMETRY;
            for (k = 0; k < n; k++)
                p[k] *= pb->N / (dA * psum);
            if ((st = gap_of(S, p, g)) < 0)
                return st;
            restart = 1;
            have_delta = 0;
            continue;
        }
        /* exterior elements that the surfaces would penetrate join C */
        delta = nc ? gsum / nc : 0.0;
        for (k = 0; k < n; k++)
            if (in[k] == OUTSIDE && g[k] < delta) {
                in[k] = ADHESION;
                changed = 1;
            }
        step_rms = sqrt(s2 / (p2 > 0.0 ? p2 : 1.0));
        if (changed) {
            restart = 1;
            have_delta = 0;
            continue;
        }
        have_delta = 1;
        if (step_rms <= pb->tol) {
            converged = 1;
            break;
        }
    }
    res->delta = mean_on(g, in, n, &cnt) + h0;
    res->normal_products = S->products;
    res->normal_residual = step_rms;
    return converged ? RR_OK : RR_WARN_NOT_CONVERGED;
}
