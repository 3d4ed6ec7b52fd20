/*
 * rr_exact_tangential.c - the exact solver's tangential problem
 * (rr_exact.h): steady rolling's slip equations by semismooth Newton with
 * GMRES, preconditioned by the steady operator's stencil, from a FASTSIM
 * start or the caller's (rr_exact_solve_from); the products by FFT.
 */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "util/rr_fft.h"
#include "contact/rr_exact.h"
#include "contact/rr_exact_solver.h"

/* ---- the tangential problem -------------------------------------------------- */

/* in (n values, a component) into rows j0 .. j1 of the halo plane h (the
 * grid's rows, clamped to it; their border elements 0), times mask (1 or
 * 0 an element); the halo's first and last rows 0 */
static void to_halo(const layout *L, const double *in, const double *mask, int j0, int j1,
                    double *h)
{
    const int mx = L->mx, my = L->my, w = mx + 2;
    int i, j;
    memset(h, 0, (size_t)w * sizeof *h);
    memset(h + (size_t)(my + 1) * w, 0, (size_t)w * sizeof *h);
    for (j = j0 > 0 ? j0 : 0; j <= j1 && j < my; j++) {
        const double *a = in + j * mx, *m = mask + j * mx;
        double *o = h + (size_t)(j + 1) * w;
        o[0] = o[mx + 1] = 0.0;
        for (i = 0; i < mx; i++)
            o[i + 1] = a[i] * m[i];
    }
}

/* |(x, y)|: the square root of the sum of squares where that can neither
 * overflow nor lose digits to underflow (tractions and slips are far from
 * both), else hypot, which costs several times more */
static double norm2(double x, double y)
{
    const double s = x * x + y * y;
    if (s > 1e-290 && s < 1e290)
        return sqrt(s);
    return hypot(x, y);
}

/* out = G M p (the product not divided by G: the callers fold 1/G into
 * their own passes) for p = (px, py) packed as p[0..n) and p[n..2n) */
static int tang_product_g(solver *S, const double *p, double *out)
{
    layout *L = S->L;
    const int n = L->n;
    int st;
    if (rr_interrupted(S->pb->interrupt))
        return RR_ERR_INTERRUPTED;
    st = rr_conv2d_apply2(S->cv, L->sxx, L->sxy, L->sxy, L->syy, p, p + n, out, out + n);
    S->products++;
    return st < 0 ? RR_ERR_RANGE : st;
}

/* The preconditioner's first part: out = P in, the inverse of the upwind difference
 * along each row from the leading edge (+x) down, which turns the steady
 * operator into the symmetric half-space one where elements adhere; a
 * slipping element takes its upstream neighbour's value only along the
 * traction bound's tangent and by the fraction g/|z| (its Jacobian's own
 * weight there).  This cut the tangential products by about 30 % against
 * restarting the sum at every slipping element. */
static void precondition(const layout *L, const double *in, double *out)
{
    const int mx = L->mx, my = L->my, n = L->n;
    int i, j, r;
    /* one recurrence for all states (newton_coeffs): o = a + f (u - n (n.u))
     * with u the upstream value, f = 0 without an upstream neighbour in
     * contact, n = 0 in adhesion.  Four rows at a time: the recurrence is a
     * chain of dependent operations along a row, and four independent
     * chains keep the processor busy (2.5 times faster than row by row). */
    for (j = 0; j + 4 <= my; j += 4) {
        double ux[4] = {0.0, 0.0, 0.0, 0.0}, uy[4] = {0.0, 0.0, 0.0, 0.0};
        for (i = mx - 1; i >= 0; i--)
            for (r = 0; r < 4; r++) {
                const int k = (j + r) * mx + i;
                const double nx = L->jn[k], ny = L->jn[k + n], f = L->pcf[k];
                const double d = nx * ux[r] + ny * uy[r];
                ux[r] = in[k] + f * (ux[r] - nx * d);
                uy[r] = in[k + n] + f * (uy[r] - ny * d);
                out[k] = ux[r];
                out[k + n] = uy[r];
            }
    }
    for (; j < my; j++) {
        double ux = 0.0, uy = 0.0;
        for (i = mx - 1; i >= 0; i--) {
            const int k = j * mx + i;
            const double nx = L->jn[k], ny = L->jn[k + n], f = L->pcf[k];
            const double d = nx * ux + ny * uy;
            ux = in[k] + f * (ux - nx * d);
            uy = in[k + n] + f * (uy - ny * d);
            out[k] = ux;
            out[k + n] = uy;
        }
    }
}

/* One row of tang_stencil: the rows j - 1, j, j + 1 of the halo planes
 * from their element 0 (xs, xc, xn; ys, yc, yn), st the two stencils and
 * the coupling (times c) */
static void tang_stencil_row(int mx, const double *st, const double *restrict xs,
                             const double *restrict xc, const double *restrict xn,
                             const double *restrict ys, const double *restrict yc,
                             const double *restrict yn, const double *restrict a,
                             double *io_x, double *io_y)
{
    const double x0 = st[0], x1 = st[1], x2 = st[2], x3 = st[3];
    const double y0 = st[4], y1 = st[5], y2 = st[6], y3 = st[7], xy = st[8];
    int i;
    for (i = 0; i < mx; i++) {
        const double dx = (xn[i - 1] + xn[i + 1]) + (xs[i - 1] + xs[i + 1]);
        const double dy = (yn[i - 1] + yn[i + 1]) + (ys[i - 1] + ys[i + 1]);
        /* the odd-odd coupling: S(o) = s sign(ox) sign(oy), out(i) = sum S(o) in(i - o) */
        const double cx = (xn[i + 1] - xn[i - 1]) - (xs[i + 1] - xs[i - 1]);
        const double cy = (yn[i + 1] - yn[i - 1]) - (ys[i + 1] - ys[i - 1]);
        const double sx = x0 * xc[i] + x1 * (xc[i - 1] + xc[i + 1]) + x2 * (xs[i] + xn[i])
                          + x3 * dx + xy * cy;
        const double sy = y0 * yc[i] + y1 * (yc[i - 1] + yc[i + 1]) + y2 * (ys[i] + yn[i])
                          + y3 * dy + xy * cx;
        /* a s + (1 - a) in with a 1 or 0: exactly one of them (in place:
         * element i's input is read here alone, the neighbours' from the
         * halo planes) */
        io_x[i] = a[i] * sx + (1.0 - a[i]) * io_x[i];
        io_y[i] = a[i] * sy + (1.0 - a[i]) * io_y[i];
    }
}

/* The tangential preconditioner's second part, in place: v = c S v on the
 * adhering elements, S the symmetric tangential operator's inverse
 * stencil, on the values of adhering elements alone (copied to the halo
 * planes first); v unchanged elsewhere (in place: no copy of the other
 * elements, which was a third of the stencil's instructions).
 * After the inverse upwind difference (precondition) the steady operator
 * acts on adhering elements as the symmetric one, and S undoes most of
 * that (GMRES took 27 % fewer products on the 300 random cases at 27
 * across, 30 % at 45).  c: 0.8 G / rho, the fewest products of 0.5 to
 * 4 times G / rho. */
static void tang_stencil(const layout *L, double c, double *v)
{
    const int mx = L->mx, my = L->my, n = L->n, w = mx + 2;
    const size_t hn = (size_t)w * (my + 2);
    const int i0 = L->ai0, nb = L->ai1 - L->ai0 + 1;
    double *hx = L->halo, *hy = L->halo + hn, st[9];
    int j;
    /* S on the adhering elements' bounding box, the halo rows around it
     * filled (each masked to the adhering elements) */
    if (L->stn[17] == 0.0 || L->ai1 < 0)
        return;
    for (j = 0; j < 9; j++)
        st[j] = c * L->stn[8 + j];
    to_halo(L, v, L->madh, L->aj0 - 1, L->aj1 + 1, hx);
    to_halo(L, v + n, L->madh, L->aj0 - 1, L->aj1 + 1, hy);
    for (j = L->aj0; j <= L->aj1; j++) {
        const int k = j * mx + i0;
        const double *xs = hx + (size_t)j * w + 1 + i0, *ys = hy + (size_t)j * w + 1 + i0;
        tang_stencil_row(nb, st, xs, xs + w, xs + 2 * w, ys, ys + w, ys + 2 * w, L->madh + k,
                         v + k, v + n + k);
    }
}

/* The Jacobian's coefficients for the states of the last residual, which
 * hold through a GMRES solve: J v = v - f (e - n (n.e)), e = v - rho M v,
 * with (f, n) = (1, 0) in adhesion (J v = rho M v), (g/|z|, z/|z|) in slip,
 * (0, 0) outside (v is 0 there); pcf: f where the upstream neighbour is in
 * contact, else 0 (precondition); madh: 1 in adhesion, else 0. */
static void newton_coeffs(layout *L)
{
    const int n = L->n, mx = L->mx;
    int k;
    for (k = 0; k < n; k++) {
        const int st = L->state[k];
        L->jf[k] = st == ADHESION ? 1.0 : st == SLIP ? L->fac[k] : 0.0;
        L->jn[k] = st == SLIP ? L->nz[k] : 0.0;
        L->jn[k + n] = st == SLIP ? L->nz[k + n] : 0.0;
        L->madh[k] = st == ADHESION;
    }
    L->ai0 = mx;
    L->ai1 = -1;
    L->aj0 = L->my;
    L->aj1 = -1;
    for (k = 0; k < n; k++) {
        const int i = k % mx, j = k / mx;
        L->pcf[k] = i + 1 < mx && L->state[k + 1] != OUTSIDE ? L->jf[k] : 0.0;
        if (L->state[k] == ADHESION) {
            L->ai0 = i < L->ai0 ? i : L->ai0;
            L->ai1 = i > L->ai1 ? i : L->ai1;
            L->aj0 = j < L->aj0 ? j : L->aj0;
            L->aj1 = j > L->aj1 ? j : L->aj1;
        }
    }
}

/* out = J v, J = I - D (I - rho M) on C, given Mv = G M v (a product
 * not yet divided by G) and rg = rho / G */
static void jacobian(const layout *L, double rg, const double *restrict v,
                     const double *restrict Mv, double *restrict out)
{
    const int n = L->n;
    const double *restrict jf = L->jf, *restrict jnx = L->jn, *restrict jny = L->jn + n;
    int k;
    for (k = 0; k < n; k++) {
        const double ex = v[k] - rg * Mv[k], ey = v[k + n] - rg * Mv[k + n];
        const double nx = jnx[k], ny = jny[k], dot = nx * ex + ny * ey;
        out[k] = v[k] - jf[k] * (ex - nx * dot);
        out[k + n] = v[k + n] - jf[k] * (ey - ny * dot);
    }
}

/* a.b with four partial sums (independent chains: the loop pipelines and
 * vectorises without reassociating a single sum) */
static double dot2(const double *a, const double *b, int n2)
{
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    int k;
    for (k = 0; k + 4 <= n2; k += 4) {
        s0 += a[k] * b[k];
        s1 += a[k + 1] * b[k + 1];
        s2 += a[k + 2] * b[k + 2];
        s3 += a[k + 3] * b[k + 3];
    }
    for (; k < n2; k++)
        s0 += a[k] * b[k];
    return (s0 + s1) + (s2 + s3);
}

/* w += a x, then w . y, or w . w where y is NULL (four partial sums, as
 * dot2) */
static double axpy_dot(double *restrict w, double a, const double *restrict x,
                       const double *restrict y, int n2)
{
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    int k;
    if (y) {
        for (k = 0; k + 4 <= n2; k += 4) {
            const double w0 = w[k] + a * x[k], w1 = w[k + 1] + a * x[k + 1];
            const double w2 = w[k + 2] + a * x[k + 2], w3 = w[k + 3] + a * x[k + 3];
            w[k] = w0;
            w[k + 1] = w1;
            w[k + 2] = w2;
            w[k + 3] = w3;
            s0 += w0 * y[k];
            s1 += w1 * y[k + 1];
            s2 += w2 * y[k + 2];
            s3 += w3 * y[k + 3];
        }
    } else {
        for (k = 0; k + 4 <= n2; k += 4) {
            const double w0 = w[k] + a * x[k], w1 = w[k + 1] + a * x[k + 1];
            const double w2 = w[k + 2] + a * x[k + 2], w3 = w[k + 3] + a * x[k + 3];
            w[k] = w0;
            w[k + 1] = w1;
            w[k + 2] = w2;
            w[k + 3] = w3;
            s0 += w0 * w0;
            s1 += w1 * w1;
            s2 += w2 * w2;
            s3 += w3 * w3;
        }
    }
    for (; k < n2; k++) {
        w[k] += a * x[k];
        s0 += w[k] * (y ? y[k] : w[k]);
    }
    return (s0 + s1) + (s2 + s3);
}

static void scale_by(double *v, double a, int n2)
{
    int k;
    for (k = 0; k < n2; k++)
        v[k] *= a;
}

/* F = p - Proj_g(p - rho s) on C; also the states and the projection's
 * derivative data (unit z and g/|z| of slipping elements).  Returns ||F||. */
static double residual(layout *L, double rho, const double *p, const double *s, double *F)
{
    const int n = L->n;
    double f2 = 0.0;
    int k;
    for (k = 0; k < n; k++) {
        double zx, zy, z, g;
        if (L->state[k] == OUTSIDE) {
            F[k] = F[k + n] = 0.0;
            continue;
        }
        g = L->fac[k + n];               /* the traction bound, kept in fac's upper half */
        zx = p[k] - rho * s[k];
        zy = p[k + n] - rho * s[k + n];
        z = norm2(zx, zy);
        if (z <= g) {
            L->state[k] = ADHESION;
            F[k] = p[k] - zx;
            F[k + n] = p[k + n] - zy;
        } else {
            const double f = g / z;
            L->state[k] = SLIP;
            L->nz[k] = zx / z;
            L->nz[k + n] = zy / z;
            L->fac[k] = f;
            F[k] = p[k] - f * zx;
            F[k + n] = p[k + n] - f * zy;
        }
        f2 += F[k] * F[k] + F[k + n] * F[k + n];
    }
    return sqrt(f2);
}

/* GMRES(m) on J P u = -F (the Newton step), right-preconditioned by P =
 * the inverse upwind difference (precondition), then the stencil on the
 * adhering elements (tang_stencil); on return dlt = P u and mdl = M dlt
 * (kept from the products, no extra one).  Stops at ||F + J P u|| <= eta
 * ||F|| or when the product budget is spent. */
static int gmres(solver *S, double rho, const double *F, double eta, double *dlt, double *mdl)
{
    layout *L = S->L;
    const int n2 = 2 * L->n, m = GMRES_M;
    const double bnorm = sqrt(dot2(F, F, n2)), rg = rho / S->pb->G, ig = 1.0 / S->pb->G;
    double *V = L->V, *MV = L->MV, *H = L->H, *gv = L->gv, *cs = L->cs, *sn = L->sn,
           *y = L->y, *t = L->t1, *q = L->t2;
    const double cst = 0.8 * S->pb->G / rho;
    double beta = bnorm;
    int k, j, i, st;

    memset(dlt, 0, (size_t)n2 * sizeof *dlt);
    memset(mdl, 0, (size_t)n2 * sizeof *mdl);
    if (bnorm == 0.0)
        return RR_OK;
    newton_coeffs(L);
    for (k = 0; k < n2; k++)
        V[k] = -F[k];
    while (S->products < S->pb->maxit) {
        int jm = 0;
        /* V[0] = r / |r| */
        scale_by(V, 1.0 / beta, n2);
        memset(gv, 0, (GMRES_M + 1) * sizeof *gv);
        gv[0] = beta;
        for (j = 0; j < m && S->products < S->pb->maxit; j++) {
            double *w = V + (size_t)(j + 1) * n2, *mvj = MV + (size_t)j * n2, h, hn;
            precondition(L, V + (size_t)j * n2, t);
            tang_stencil(L, cst, t);
            /* the products kept times G, divided once at the end */
            if ((st = tang_product_g(S, t, mvj)) < 0)
                return st;
            /* modified Gram-Schmidt, each pass subtracting one basis vector
             * and taking the dot product with the next (the last: |w|^2) */
            jacobian(L, rg, t, mvj, w);
            h = dot2(w, V, n2);
            for (i = 0; i <= j; i++) {
                H[i * m + j] = h;
                h = axpy_dot(w, -h, V + (size_t)i * n2, i < j ? V + (size_t)(i + 1) * n2 : NULL,
                             n2);
            }
            hn = sqrt(h);
            H[(j + 1) * m + j] = hn;
            if (hn > 0.0)
                scale_by(w, 1.0 / hn, n2);
            /* Givens rotations keep H upper triangular and give the residual */
            for (i = 0; i < j; i++) {
                const double a = H[i * m + j], c = H[(i + 1) * m + j];
                H[i * m + j] = cs[i] * a + sn[i] * c;
                H[(i + 1) * m + j] = -sn[i] * a + cs[i] * c;
            }
            {
                const double a = H[j * m + j], c = H[(j + 1) * m + j], rr = hypot(a, c);
                cs[j] = rr > 0.0 ? a / rr : 1.0;
                sn[j] = rr > 0.0 ? c / rr : 0.0;
                H[j * m + j] = rr;
                H[(j + 1) * m + j] = 0.0;
                gv[j + 1] = -sn[j] * gv[j];
                gv[j] = cs[j] * gv[j];
            }
            jm = j + 1;
            if (fabs(gv[j + 1]) <= eta * bnorm || hn == 0.0)
                break;
        }
        /* y = H^-1 g, then dlt += P V y and mdl += (M P V) y (times G) */
        for (i = jm - 1; i >= 0; i--) {
            double sum = gv[i];
            for (k = i + 1; k < jm; k++)
                sum -= H[i * m + k] * y[k];
            y[i] = H[i * m + i] != 0.0 ? sum / H[i * m + i] : 0.0;
        }
        memset(q, 0, (size_t)n2 * sizeof *q);
        for (i = 0; i < jm; i++) {
            const double *vi = V + (size_t)i * n2, *mvi = MV + (size_t)i * n2, yi = y[i];
            for (k = 0; k < n2; k++) {
                q[k] += yi * vi[k];
                mdl[k] += yi * mvi[k];
            }
        }
        precondition(L, q, t);
        tang_stencil(L, cst, t);
        for (k = 0; k < n2; k++)
            dlt[k] += t[k];
        beta = fabs(gv[jm]);
        if (jm == 0 || beta <= eta * bnorm)
            break;
        /* restart from the true residual -F - J dlt */
        jacobian(L, rg, dlt, mdl, V);
        for (k = 0; k < n2; k++)
            V[k] = -F[k] - V[k];
        beta = sqrt(dot2(V, V, n2));
        if (beta <= eta * bnorm)
            break;
    }
    scale_by(mdl, ig, n2);
    return RR_OK;
}

/* A start for Newton: FASTSIM's traction on the solver's own grid and
 * bound (Kalker's simplified theory marched from the leading edge, each
 * element clipped to mu pn), with the flexibilities of the ellipse that the
 * contact set spans.  It puts the slip area about right, which saves
 * Newton steps; RR_OK, or RR_ERR_RANGE (no usable ellipse: start from 0). */
static int start_fastsim(const rr_exact_problem *pb, layout *L, const double *w)
{
    const int mx = L->mx, my = L->my, n = L->n;
    const double dx = pb->grid.dx, dy = pb->grid.dy;
    int i, j, imin = mx, imax = -1, jmin = my, jmax = -1;
    double a, b, fl[3];
    rr_kalker_coeffs kc;

    for (j = 0; j < my; j++)
        for (i = 0; i < mx; i++)
            if (L->state[j * mx + i] != OUTSIDE) {
                imin = i < imin ? i : imin;
                imax = i > imax ? i : imax;
                jmin = j < jmin ? j : jmin;
                jmax = j > jmax ? j : jmax;
            }
    if (imax < 0)
        return RR_ERR_RANGE;
    a = 0.5 * (imax - imin + 1) * dx;
    b = 0.5 * (jmax - jmin + 1) * dy;
    if (rr_kalker(a / b, pb->nu, &kc) != RR_OK)
        return RR_ERR_RANGE;
    rr_kalker_flexibilities(a, b, pb->G, &kc, fl);
    for (j = 0; j < my; j++) {
        double qx = 0.0, qy = 0.0;
        for (i = mx - 1; i >= 0; i--) {
            const int k = j * mx + i;
            double g, t;
            if (L->state[k] == OUTSIDE) {
                qx = qy = 0.0;
                L->p[k] = L->p[k + n] = 0.0;
                continue;
            }
            /* the rigid slip split into its creepage and spin parts */
            {
                const double spx = w[k] - pb->cx, spy = w[k + n] - pb->cy;
                qx -= dx * (pb->cx / fl[0] + spx / fl[2]);
                qy -= dx * (pb->cy / fl[1] + spy / fl[2]);
            }
            g = L->fac[k + n];
            t = norm2(qx, qy);
            if (t > g) {
                qx *= g / t;
                qy *= g / t;
            }
            L->p[k] = qx;
            L->p[k + n] = qy;
        }
    }
    if (!rr_all_finite(L->p, 2 * n))
        return RR_ERR_RANGE;
    for (i = 0; i < 2 * n; i++)
        if (L->p[i] != 0.0)
            return RR_OK;
    return RR_ERR_RANGE;      /* no traction (no creepage): the zero start needs no product */
}

/* The caller's start (rr_exact_start, checked finite): its traction on
 * the elements in contact, clipped to the bound mu pn of this pressure.
 * RR_OK, or RR_ERR_RANGE where nothing is left (start from 0). */
static int start_from_caller(const rr_exact_start *st, layout *L)
{
    const int n = L->n;
    int k, any = 0;
    for (k = 0; k < n; k++) {
        double px = 0.0, py = 0.0;
        if (L->state[k] != OUTSIDE) {
            const double g = L->fac[k + n], t = norm2(st->px[k], st->py[k]);
            px = st->px[k];
            py = st->py[k];
            if (t > g) {
                /* t may be infinite (two finite values whose norm is not) */
                px = isfinite(t) ? px * (g / t) : 0.0;
                py = isfinite(t) ? py * (g / t) : 0.0;
            }
        }
        L->p[k] = px;
        L->p[k + n] = py;
        any |= px != 0.0 || py != 0.0;
    }
    return any ? RR_OK : RR_ERR_RANGE;
}

int rr_exact_solve_tangential(solver *S, rr_exact_result *res)
{
    const rr_exact_problem *pb = S->pb;
    layout *L = S->L;
    const int n = L->n, mx = L->mx, n2 = 2 * n;
    /* rho: half the inverse diagonal of the steady operator (of the values
     * tried, 0.2 to 30 times it, the fewest products: 0.5) */
    const double rho = 0.5 * pb->G / rr_exact_steady_diagonal(pb->grid.dy / pb->grid.dx, pb->nu);
    double *p = L->p, *s = L->s, *w = L->w, *F = L->f, *dl = L->dlt, *md = L->mdl, *pt = L->t1,
           *stt = L->t2;
    double g2 = 0.0, nF, nFold = 0.0, eta = 0.3, goal = 0.0;
    int k, st = RR_OK, newton = 0, converged = 0, warm;
    S->products = 0;
    for (k = 0; k < n; k++) {
        const double x = pb->grid.x0 + (k % mx) * pb->grid.dx;
        const double y = pb->grid.y0 + (k / mx) * pb->grid.dy;
        const double xs = x + pb->spin_shift * pb->grid.dx;
        L->state[k] = L->pn[k] > 0.0 ? ADHESION : OUTSIDE;
        L->fac[k + n] = pb->mu * L->pn[k];     /* traction bound */
        g2 += L->fac[k + n] * L->fac[k + n];
        w[k] = L->state[k] != OUTSIDE ? pb->cx - pb->cphi * y : 0.0;
        w[k + n] = L->state[k] != OUTSIDE ? pb->cy + pb->cphi * xs : 0.0;
        p[k] = p[k + n] = 0.0;
        s[k] = w[k];
        s[k + n] = w[k + n];
    }
    g2 = sqrt(g2);
    /* no creepage: no traction, from the zero start at once (a start's
     * traction would have to be iterated away) */
    warm = S->start && S->start->px && (pb->cx != 0.0 || pb->cy != 0.0 || pb->cphi != 0.0);
    if (warm ? start_from_caller(S->start, L) == RR_OK : start_fastsim(pb, L, w) == RR_OK) {
        if ((st = tang_product_g(S, p, s)) < 0)
            return st;
        for (k = 0; k < n2; k++)
            s[k] = s[k] / pb->G + w[k];
    } else {
        memset(p, 0, (size_t)n2 * sizeof *p);       /* from zero traction: s = w */
    }
    nF = residual(L, rho, p, s, F);
    while (1) {
        double t = 1.0, nFt = 0.0;
        int ls;
        if (!isfinite(nF))
            return RR_ERR_RANGE;
        /* the tolerance is relative to the traction found, not to the
         * bound: at small creepage p is orders of magnitude below mu pn */
        goal = fmax(pb->tol * sqrt(dot2(p, p, n2)), 1e-15 * g2);
        if (nF <= goal) {
            converged = 1;
            break;
        }
        if (S->products >= pb->maxit)
            break;
        /* Eisenstat-Walker forcing, safeguarded, never finer than the goal */
        if (newton > 0) {
            double e = 0.9 * (nF / nFold) * (nF / nFold);
            if (0.9 * eta * eta > 0.1)
                e = fmax(e, 0.9 * eta * eta);
            eta = fmin(0.3, fmax(e, 1e-3));
        }
        eta = fmax(eta, 0.5 * goal / nF);
        if ((st = gmres(S, rho, F, eta, dl, md)) < 0)
            return st;
        newton++;
        nFold = nF;
        /* backtracking on ||F||: s(p + t dl) = s + t M dl, no product needed */
        for (ls = 0; ls < 30; ls++) {
            for (k = 0; k < n2; k++) {
                pt[k] = p[k] + t * dl[k];
                stt[k] = s[k] + t * md[k];
            }
            nFt = residual(L, rho, pt, stt, F);
            if (nFt <= (1.0 - 1e-4 * t) * nF)
                break;
            t *= 0.5;
        }
        /* the trial iterate becomes the iterate: the arrays trade places
         * (in the layout too: gmres takes its scratch from t1, t2) */
        L->p = pt;
        L->t1 = p;
        p = pt;
        pt = L->t1;
        L->s = stt;
        L->t2 = s;
        s = stt;
        stt = L->t2;
        if (ls == 30) {
            nF = nFt;
            break;               /* no descent: stalled */
        }
        nF = nFt;
    }
    /* the last iterate onto the traction bound (a change of the order of
     * the tolerance): |p| <= mu pn holds in every element, so |F| <= mu N
     * whatever the status */
    for (k = 0; k < n; k++) {
        const double g = L->fac[k + n], t = norm2(p[k], p[k + n]);
        if (t > g) {
            p[k] *= g / t;
            p[k + n] *= g / t;
        }
    }
    res->tang_products = S->products;
    res->newton_steps = newton;
    {
        const double pnorm = sqrt(dot2(p, p, n2));
        res->tang_residual = pnorm > 0.0 ? nF / pnorm : 0.0;
    }
    return converged ? RR_OK : RR_WARN_NOT_CONVERGED;
}
