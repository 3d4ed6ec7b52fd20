/*
 * test_exact.c - Kalker's exact theory (rr_exact.h) from C: the Hertzian
 * normal problem against Hertz's closed form (approach and peak pressure
 * to 0.2 %, the discretisation error at 15 elements across), full sliding
 * (|F| = mu N to 1e-6), a creepage-free case (no traction at all), the
 * workspace's cached normal solution giving a fresh solve's doubles, a
 * workspace of NaN (as a failed case may leave it) giving them too, the
 * interrupt hook (polled, never changing a double, stopping at once), the
 * field's sums, the steady-rolling equations checked by direct sums (no
 * FFT), every documented error, and the warm start (rr_exact_solve_from:
 * the cold solution to the tolerance on two grid shapes, fewer products,
 * the default path untouched, bad starts refused; test_warm_start).
 */
#include <stdlib.h>
#include <string.h>
#include "tests/rr_test.h"
#include "contact/rr_exact.h"
#include "contact/rr_hertz.h"
#include "contact/rr_influence.h"
#include "contact/rr_creep.h"

/* problem c with the friction law fr (the tests vary the two apart): c's
 * law set to *fr, c returned (NULL stays NULL) */
static const rr_contact_problem *with_law(rr_contact_problem *c, const rr_friction *fr)
{
    if (c && fr)
        c->friction = *fr;
    return c;
}

/* An interrupt hook that counts its polls and asks to stop at poll number
 * stop_at (0: never). */
typedef struct {
    int polls, stop_at;
} counter;

static int count_polls(void *ctx)
{
    counter *c = ctx;
    c->polls++;
    return c->stop_at > 0 && c->polls >= c->stop_at;
}

static rr_exact_problem hertz_case(double a, double b, int n)
{
    rr_exact_problem pb;
    memset(&pb, 0, sizeof pb);
    rr_exact_hertz_grid(a, b, n, n, &pb.grid);
    pb.N = 5e4;
    pb.G = 8.2e10;
    pb.nu = 0.28;
    pb.mu = 0.3;
    rr_hertz_curvatures(a, b, pb.N, pb.G / (1.0 - pb.nu), &pb.A, &pb.B);
    pb.tol = 1e-9;
    pb.maxit = 2000;
    pb.spin_shift = 1.0 / 6.0;
    return pb;
}

/* The solution of pb satisfies the discrete steady-rolling equations, its
 * slip recomputed by direct sums over the influence coefficients (no FFT):
 * s = w + (1/G) sum_j (A(i - j) - A(i - j + e_x)) p_j in units of dx
 * (rr_exact.h), s = 0 in adhesion, s the field's slip in slip, p opposite to
 * it at the bound.  Independent of how the solver builds its spectra (from
 * the symmetric kernels shifted, or on a torus too short for the shift, the
 * steady kernels themselves).  Returns the largest error relative to |w|. */
static double steady_equations_error(const rr_exact_problem *pb, double *w, size_t len)
{
    const int mx = pb->grid.mx, my = pb->grid.my, n = mx * my;
    const double aspect = pb->grid.dy / pb->grid.dx;
    double *px = calloc(n, sizeof *px), *py = calloc(n, sizeof *py), *sx = calloc(n, sizeof *sx);
    double *sy = calloc(n, sizeof *sy), *pn = calloc(n, sizeof *pn), err = 0.0, wmax;
    signed char *state = calloc(n, 1);
    rr_exact_field f;
    rr_exact_result r;
    int i, j;
    f.pn = pn;
    f.px = px;
    f.py = py;
    f.sx = sx;
    f.sy = sy;
    f.state = state;
    CHECK_STATUS(rr_exact_solve(pb, w, len, &r, &f), RR_OK, "solve for the direct check");
    wmax = hypot(pb->cx, pb->cy) + fabs(pb->cphi) * 0.5 * mx * pb->grid.dx;
    for (i = 0; i < n; i++) {
        const int ix = i % mx, iy = i / mx;
        const double x = pb->grid.x0 + ix * pb->grid.dx, y = pb->grid.y0 + iy * pb->grid.dy;
        double s1 = pb->cx - pb->cphi * y;
        double s2 = pb->cy + pb->cphi * (x + pb->spin_shift * pb->grid.dx);
        if (state[i] < 0)
            continue;
        for (j = 0; j < n; j++) {
            const int kx = ix - j % mx, ky = iy - j / mx;
            double a0[4], a1[4];
            if (px[j] == 0.0 && py[j] == 0.0)
                continue;
            rr_influence_at(kx, ky, 1.0, aspect, pb->nu, a0);
            rr_influence_at(kx + 1, ky, 1.0, aspect, pb->nu, a1);
            s1 += ((a0[1] - a1[1]) * px[j] + (a0[3] - a1[3]) * py[j]) / pb->G;
            s2 += ((a0[3] - a1[3]) * px[j] + (a0[2] - a1[2]) * py[j]) / pb->G;
        }
        if (state[i] == 0) {
            err = fmax(err, hypot(s1, s2) / wmax);
        } else {
            const double t = hypot(px[i], py[i]), v = hypot(s1, s2);
            err = fmax(err, hypot(s1 - sx[i], s2 - sy[i]) / wmax);
            /* p = -mu pn s / |s| */
            err = fmax(err, hypot(px[i] / t + s1 / v, py[i] / t + s2 / v) * 1e-3);
            err = fmax(err, fabs(t - pb->mu * pn[i]) / (pb->mu * pn[i]) * 1e-3);
        }
    }
    free(px);
    free(py);
    free(sx);
    free(sy);
    free(pn);
    free(state);
    return err;
}

/* A non-Hertzian gap on pb's grid: Hertz's plus a quartic along y that
 * flattens the middle (a patch wider than the ellipse, its pressure with
 * two shoulders), as the rig's worn profiles give. */
static void flat_gap(const rr_exact_problem *pb, double *h)
{
    int k;
    for (k = 0; k < pb->grid.mx * pb->grid.my; k++) {
        const double x = pb->grid.x0 + (k % pb->grid.mx) * pb->grid.dx;
        const double y = pb->grid.y0 + (k / pb->grid.mx) * pb->grid.dy;
        h[k] = pb->A * x * x + 0.3 * pb->B * y * y + 2e4 * pb->B * y * y * y * y;
    }
}

typedef struct {
    double *pn, *px, *py;
} fields;

static fields fields_new(int n)
{
    fields f;
    f.pn = calloc(n, sizeof(double));
    f.px = calloc(n, sizeof(double));
    f.py = calloc(n, sizeof(double));
    return f;
}

static void fields_free(fields *f)
{
    free(f->pn);
    free(f->px);
    free(f->py);
}

/* rr_exact_solve_from against rr_exact_solve.  The warm start's solution is
 * the cold one's to the solver's tolerance: both stop where the normal
 * step and the tangential residual are below tol relative to the
 * pressure and traction found, so each lies within a few tol of the
 * discrete solution; here tol = 1e-9 and the forces agree to 1e-8 mu N,
 * the pressure to 1e-8 of its peak (measured 1.2e-10 and 1e-10: the bound,
 * ten times tol, leaves room for the conditioning of the partial-slip
 * problem).  Checked on two grid shapes, with the start
 * the solution of another load and creepage (N 1 % larger, cx 5 %, cphi
 * 10 %: the rig's load iteration and a table's neighbour), which must save
 * products; the default path and the cached normal solution untouched;
 * every bad start refused before any work. */
static void test_warm_start(void)
{
    const int shapes[2][2] = {{15, 15}, {21, 11}};
    int q, k;
    for (q = 0; q < 2; q++) {
        rr_exact_problem pb = hertz_case(0.006, 0.004, 15), near;
        size_t len;
        int n;
        double *w, *fresh, *h;
        fields f0, f1, f2;
        rr_exact_field o0, o1, o2;
        rr_exact_result r0, r1, r2, r3;
        rr_exact_start start;
        rr_exact_hertz_grid(0.006, 0.004, shapes[q][0], shapes[q][1], &pb.grid);
        n = pb.grid.mx * pb.grid.my;
        len = rr_exact_workspace_len(pb.grid.mx, pb.grid.my);
        w = calloc(len, sizeof *w);
        fresh = calloc(len, sizeof *fresh);
        h = malloc(n * sizeof *h);
        flat_gap(&pb, h);
        pb.h = h;
        pb.cx = 4e-4;
        pb.cy = -1e-4;
        pb.cphi = 0.8;
        f0 = fields_new(n);
        f1 = fields_new(n);
        f2 = fields_new(n);
        memset(&o0, 0, sizeof o0);
        o0.pn = f0.pn;
        o0.px = f0.px;
        o0.py = f0.py;
        o1 = o0;
        o1.pn = f1.pn;
        o1.px = f1.px;
        o1.py = f1.py;
        o2 = o0;
        o2.pn = f2.pn;
        o2.px = f2.px;
        o2.py = f2.py;
        /* the start: a nearby problem's solution */
        near = pb;
        near.N = pb.N / 1.01;
        near.cx = pb.cx / 1.05;
        near.cphi = pb.cphi / 1.1;
        CHECK_STATUS(rr_exact_solve(&near, w, len, &r0, &o0), RR_OK, "warm: the start's solve");
        CHECK(r0.nslip > 0 && r0.nslip < r0.ncontact, "warm: a partial-slip start");
        start.mx = pb.grid.mx;
        start.my = pb.grid.my;
        start.pn = f0.pn;
        start.px = f0.px;
        start.py = f0.py;
        CHECK_STATUS(rr_exact_solve(&pb, fresh, len, &r1, &o1), RR_OK, "warm: cold solve");
        CHECK_STATUS(rr_exact_solve_from(&pb, &start, w, len, &r2, &o2), RR_OK, "warm solve");
        {
            const double muN = pb.mu * pb.N;
            double dp = 0.0;
            CHECK_CLOSE(r2.fx, r1.fx, 1e-8 * muN, 0.0, "warm: fx the cold one's to the tolerance");
            CHECK_CLOSE(r2.fy, r1.fy, 1e-8 * muN, 0.0, "warm: fy");
            CHECK_CLOSE(r2.mz, r1.mz, 1e-8 * muN * pb.grid.dx, 0.0, "warm: mz");
            CHECK_CLOSE(r2.delta, r1.delta, 0.0, 1e-8, "warm: the approach");
            CHECK(r2.ncontact == r1.ncontact && r2.nslip == r1.nslip, "warm: the same areas");
            for (k = 0; k < n; k++)
                dp = fmax(dp, fabs(f2.pn[k] - f1.pn[k]) / r1.pmax);
            CHECK(dp < 1e-8, "warm: the pressure the cold one's to the tolerance");
            CHECK(r2.normal_products < r1.normal_products
                  && r2.tang_products < r1.tang_products, "warm: fewer products, both problems");
        }
        /* the start as the field written (the same arrays): read before the
         * field is written, the same doubles as from a copy */
        CHECK_STATUS(rr_exact_solve_from(&near, NULL, w, len, &r0, &o0), RR_OK, "warm: again");
        memcpy(f1.pn, f0.pn, n * sizeof(double));
        memcpy(f1.px, f0.px, n * sizeof(double));
        memcpy(f1.py, f0.py, n * sizeof(double));
        CHECK_STATUS(rr_exact_solve_from(&pb, &start, w, len, &r3, &o0), RR_OK, "warm: aliased");
        CHECK(memcmp(&r3.fx, &r2.fx, sizeof r2.fx) == 0 && memcmp(&r3.mz, &r2.mz, sizeof r2.mz) == 0
              && memcmp(f0.px, f2.px, n * sizeof(double)) == 0,
              "warm: the start may be the field");
        /* start NULL is rr_exact_solve; a warm solve leaves the cached normal
         * solution (a cold one's) in place: a cold solve after it gives a
         * fresh workspace's doubles */
        CHECK_STATUS(rr_exact_solve_from(&pb, NULL, w, len, &r3, NULL), RR_OK, "start NULL");
        CHECK(memcmp(&r3.fx, &r1.fx, sizeof r1.fx) == 0 && memcmp(&r3.mz, &r1.mz, sizeof r1.mz) == 0
              && r3.normal_products == r1.normal_products
              && r3.tang_products == r1.tang_products,
              "start NULL: rr_exact_solve's doubles after warm solves");
        /* the pressure alone: the tangential problem from FASTSIM, as cold */
        start.pn = f1.pn;
        start.px = start.py = NULL;
        CHECK_STATUS(rr_exact_solve_from(&pb, &start, w, len, &r3, NULL), RR_OK, "pressure alone");
        CHECK_CLOSE(r3.fx, r1.fx, 1e-8 * pb.mu * pb.N, 0.0, "pressure alone: fx");
        CHECK(r3.tang_products == r1.tang_products, "pressure alone: FASTSIM's start");
        /* tractions far beyond the bound: clipped to it, the same solution */
        for (k = 0; k < n; k++) {
            f2.px[k] = 1e300;
            f2.py[k] = -1e300;
        }
        start.px = f2.px;
        start.py = f2.py;
        CHECK_STATUS(rr_exact_solve_from(&pb, &start, w, len, &r3, NULL), RR_OK, "huge tractions");
        CHECK_CLOSE(r3.fx, r1.fx, 1e-8 * pb.mu * pb.N, 0.0, "huge tractions: clipped, fx");
        /* no creepage: no traction at all, whatever the start's */
        near = pb;
        near.cx = near.cy = near.cphi = 0.0;
        CHECK_STATUS(rr_exact_solve_from(&near, &start, w, len, &r3, NULL), RR_OK, "no creepage");
        CHECK(r3.fx == 0.0 && r3.fy == 0.0 && r3.tang_products == 0, "no creepage: no traction");
        /* bad starts: refused before any work, outputs NaN */
        start.px = f0.px;
        start.py = f0.py;
        start.mx = pb.grid.mx - 1;
        CHECK_STATUS(rr_exact_solve_from(&pb, &start, w, len, &r3, &o2), RR_ERR_GRID,
                     "a start on another grid");
        CHECK(isnan(r3.fx) && isnan(f2.pn[0]), "another grid: NaN out");
        start.mx = pb.grid.mx;
        start.my = pb.grid.my + 1;
        CHECK_STATUS(rr_exact_solve_from(&pb, &start, w, len, &r3, NULL), RR_ERR_GRID, "my");
        start.my = pb.grid.my;
        start.pn = NULL;
        CHECK_STATUS(rr_exact_solve_from(&pb, &start, w, len, &r3, NULL), RR_ERR_NULL, "pn NULL");
        start.pn = f0.pn;
        start.py = NULL;
        CHECK_STATUS(rr_exact_solve_from(&pb, &start, w, len, &r3, NULL), RR_ERR_NULL,
                     "px without py");
        start.py = f0.py;
        f0.pn[n / 2] = NAN;
        CHECK_STATUS(rr_exact_solve_from(&pb, &start, w, len, &r3, NULL), RR_ERR_NONFINITE,
                     "NaN pressure");
        f0.pn[n / 2] = 1e9;
        f0.py[n - 1] = INFINITY;
        CHECK_STATUS(rr_exact_solve_from(&pb, &start, w, len, &r3, NULL), RR_ERR_NONFINITE,
                     "infinite traction");
        f0.py[n - 1] = 0.0;
        f0.pn[0] = -1.0;
        CHECK_STATUS(rr_exact_solve_from(&pb, &start, w, len, &r3, NULL), RR_ERR_PARAM,
                     "negative pressure");
        for (k = 0; k < n; k++)
            f0.pn[k] = 0.0;
        CHECK_STATUS(rr_exact_solve_from(&pb, &start, w, len, &r3, NULL), RR_ERR_PARAM,
                     "no positive pressure");
        CHECK(isnan(r3.fn), "a bad start: NaN out");
        /* a start of one element in contact: still the solution */
        f0.pn[(pb.grid.my / 2) * pb.grid.mx + pb.grid.mx / 2] = 1.0;
        CHECK_STATUS(rr_exact_solve_from(&pb, &start, w, len, &r3, NULL), RR_OK, "one element");
        CHECK_CLOSE(r3.fx, r1.fx, 1e-8 * pb.mu * pb.N, 0.0, "one element: fx");
        fields_free(&f0);
        fields_free(&f1);
        fields_free(&f2);
        free(w);
        free(fresh);
        free(h);
    }
}

int main(void)
{
    rr_exact_problem pb = hertz_case(0.006, 0.004, 15);
    const size_t len = rr_exact_workspace_len(pb.grid.mx, pb.grid.my);
    const int n = pb.grid.mx * pb.grid.my;
    double *w = calloc(len, sizeof *w), *px = malloc(n * sizeof *px), *pn = malloc(n * sizeof *pn);
    signed char *state = malloc(n);
    rr_exact_result r, r2;
    rr_exact_field f;
    rr_hertz_result h;
    int st, k;

    CHECK(pb.grid.mx == 19 && pb.grid.my == 19, "15 across plus two margins a side");
    /* no creepage: Hertz's pressure, no traction */
    st = rr_exact_solve(&pb, w, len, &r, NULL);
    CHECK_STATUS(st, RR_OK, "Hertzian solve");
    rr_hertz(pb.A, pb.B, pb.N, pb.G / (1.0 - pb.nu), &h);
    CHECK_CLOSE(r.fn, pb.N, 0.0, 1e-9, "normal force");
    CHECK_CLOSE(r.delta, h.delta, 0.0, 2e-3, "approach against Hertz");
    CHECK_CLOSE(r.pmax, h.p0, 0.0, 2e-3, "peak pressure against Hertz");
    CHECK(r.fx == 0.0 && r.fy == 0.0 && r.mz == 0.0 && r.tang_products == 0,
          "no creepage, no traction, no tangential product");
    /* full sliding */
    pb.cx = 3.0;
    pb.cy = 4.0;
    st = rr_exact_solve(&pb, w, len, &r, NULL);
    CHECK_STATUS(st, RR_OK, "full sliding");
    CHECK_CLOSE(hypot(r.fx, r.fy), pb.mu * pb.N, 0.0, 1e-7, "|F| = mu N");
    CHECK_CLOSE(r.fx / r.fy, 0.75, 0.0, 1e-5, "along the creepage");
    CHECK(r.nslip == r.ncontact && r.normal_products == 0, "all slip; normal problem reused");
    /* partial slip with spin; the cached normal solution gives a fresh solve's doubles */
    pb.cx = 2e-4;
    pb.cy = 0.0;
    pb.cphi = 0.5;
    memset(&f, 0, sizeof f);
    f.px = px;
    f.pn = pn;
    f.state = state;
    st = rr_exact_solve(&pb, w, len, &r, &f);
    CHECK_STATUS(st, RR_OK, "partial slip");
    {
        double *fresh = calloc(len, sizeof *fresh), sum = 0.0;
        CHECK_STATUS(rr_exact_solve(&pb, fresh, len, &r2, NULL), RR_OK, "fresh workspace");
        CHECK(memcmp(&r.fx, &r2.fx, sizeof r.fx) == 0 && memcmp(&r.mz, &r2.mz, sizeof r.mz) == 0,
              "cached normal solution: the same doubles as a fresh solve");
        CHECK(r2.normal_products > 0 && r.normal_products == 0, "cache used, fresh solved");
        for (k = 0; k < n; k++)
            sum += px[k];
        CHECK_CLOSE(sum * pb.grid.dx * pb.grid.dy, r.fx, 0.0, 1e-12, "field sums to fx");
        CHECK(r.nslip > 0 && r.nslip < r.ncontact, "adhesion and slip");
        free(fresh);
    }
    /* errors: outputs NaN */
    CHECK_STATUS(rr_exact_solve(&pb, w, len - 1, &r, NULL), RR_ERR_WORKSPACE, "short workspace");
    CHECK(isnan(r.fx) && isnan(r.fn), "NaN on error");
    CHECK_STATUS(rr_exact_solve(&pb, NULL, len, &r, NULL), RR_ERR_NULL, "NULL workspace");
    CHECK_STATUS(rr_exact_solve(NULL, w, len, &r, NULL), RR_ERR_NULL, "NULL problem");
    CHECK_STATUS(rr_exact_solve(&pb, w, len, NULL, NULL), RR_ERR_NULL, "NULL result");
    {
        rr_exact_problem bad = pb;
        bad.tol = 0.5;
        CHECK_STATUS(rr_exact_solve(&bad, w, len, &r, &f), RR_ERR_PARAM, "tol");
        CHECK(isnan(f.px[0]) && isnan(f.pn[n - 1]) && f.state[0] == -1, "NaN field on error");
        bad = pb;
        bad.N = -1.0;
        CHECK_STATUS(rr_exact_solve(&bad, w, len, &r, NULL), RR_ERR_LOAD, "N < 0");
        bad = pb;
        bad.nu = 0.6;
        CHECK_STATUS(rr_exact_solve(&bad, w, len, &r, NULL), RR_ERR_MATERIAL, "nu");
        bad = pb;
        bad.mu = 0.0;
        CHECK_STATUS(rr_exact_solve(&bad, w, len, &r, NULL), RR_ERR_FRICTION, "mu");
        bad = pb;
        bad.cx = NAN;
        CHECK_STATUS(rr_exact_solve(&bad, w, len, &r, NULL), RR_ERR_NONFINITE, "NaN");
        bad = pb;
        bad.grid.mx = 0;
        CHECK_STATUS(rr_exact_solve(&bad, w, len, &r, NULL), RR_ERR_GRID, "grid");
        bad = pb;
        bad.B = -1.0;
        CHECK_STATUS(rr_exact_solve(&bad, w, len, &r, NULL), RR_ERR_GEOMETRY, "B < 0");
        bad = pb;
        bad.N = 1e-320;
        CHECK_STATUS(rr_exact_solve(&bad, w, len, &r, NULL), RR_ERR_RANGE, "subnormal load");
        bad = pb;
        bad.maxit = 3;
        CHECK_STATUS(rr_exact_solve(&bad, w, len, &r, NULL), RR_WARN_NOT_CONVERGED,
                     "the product cap warns");
        CHECK(isfinite(r.fx) && hypot(r.fx, r.fy) <= bad.mu * r.fn * (1 + 1e-12),
              "a capped solve still within mu N");
    }
    /* the discrete equations by direct sums, with spin, on a torus that
     * holds the shift (15 across: 19 elements, 40) and on one that does
     * not (9 across: 13 elements, 25 = 2 13 - 1) */
    {
        const int sizes[2] = {15, 9};
        int q;
        for (q = 0; q < 2; q++) {
            rr_exact_problem p2 = hertz_case(0.005, 0.003, sizes[q]);
            const size_t l2 = rr_exact_workspace_len(p2.grid.mx, p2.grid.my);
            double *w2 = calloc(l2, sizeof *w2), e;
            p2.cx = 3e-4;
            p2.cy = -1e-4;
            p2.cphi = 0.6;
            e = steady_equations_error(&p2, w2, l2);
            CHECK(e < 1e-7, sizes[q] == 15 ? "steady equations by direct sums, 15 across"
                                           : "steady equations by direct sums, 9 across");
            free(w2);
        }
    }
    /* the tangential problem on the contact's box (rr_exact.c): a grid with
     * 12 exterior elements on every side, on which the box pays, against
     * the Hertzian grid of 2 (the same element centres: the same discrete
     * problem on the elements in contact); the wide grid's solution holds
     * the discrete equations by direct sums on the whole grid; and a
     * workspace that a call of another length used in between (its box's
     * layout elsewhere, over this one's numbers) gives a fresh workspace's
     * doubles.  Tolerances: both solved to
     * tol 1e-9, so forces within a few 1e-9 mu N of each other. */
    {
        rr_exact_problem tight = hertz_case(0.005, 0.003, 15), wide = tight, big;
        size_t lw, lb;
        double *w1, *w2, *w3, muN = tight.mu * tight.N;
        rr_exact_result rt, rw, rb;
        tight.cx = 3e-4;
        tight.cy = -1e-4;
        tight.cphi = 0.6;
        wide = tight;
        wide.grid.mx += 24;
        wide.grid.my += 24;
        wide.grid.x0 -= 12 * wide.grid.dx;
        wide.grid.y0 -= 12 * wide.grid.dy;
        big = wide;
        big.grid.mx += 20;
        big.grid.my += 20;
        big.grid.x0 -= 10 * big.grid.dx;
        big.grid.y0 -= 10 * big.grid.dy;
        lw = rr_exact_workspace_len(wide.grid.mx, wide.grid.my);
        lb = rr_exact_workspace_len(big.grid.mx, big.grid.my);
        w1 = calloc(lb, sizeof *w1);
        w2 = calloc(lb, sizeof *w2);
        w3 = calloc(lw, sizeof *w3);
        CHECK_STATUS(rr_exact_solve(&tight, w1, lb, &rt, NULL), RR_OK, "box: the tight grid");
        CHECK_STATUS(rr_exact_solve(&wide, w2, lb, &rw, NULL), RR_OK, "box: the wide grid");
        CHECK(hypot(rw.fx - rt.fx, rw.fy - rt.fy) < 1e-8 * muN
                  && fabs(rw.mz - rt.mz) < 1e-8 * muN * wide.grid.dx
                  && rw.ncontact == rt.ncontact && rw.nslip == rt.nslip,
              "box: the wide grid's forces, contact and slip are the tight grid's");
        CHECK(steady_equations_error(&wide, w3, lw) < 1e-7,
              "box: the wide grid's solution holds the equations on the whole grid");
        {
            /* the box's layout starts at the middle of the workspace, its
             * key first; a call of another length has its box elsewhere,
             * and may write over this one's numbers and not over its key:
             * NaN after the key stands for that */
            size_t i;
            CHECK_STATUS(rr_exact_solve(&big, w2, lb - 64, &rb, NULL), RR_ERR_WORKSPACE,
                         "box: a workspace too short for the larger grid");
            CHECK_STATUS(rr_exact_solve(&wide, w2, lb - 64, &rb, NULL), RR_OK,
                         "box: a call of another length between");
            for (i = lb / 2 + 8; i < lb; i++)
                w2[i] = NAN;
        }
        CHECK_STATUS(rr_exact_solve(&wide, w2, lb, &rb, NULL), RR_OK, "box: the wide grid again");
        CHECK(memcmp(&rb.fx, &rw.fx, sizeof rb.fx) == 0 && memcmp(&rb.fy, &rw.fy, sizeof rb.fy) == 0
                  && memcmp(&rb.mz, &rw.mz, sizeof rb.mz) == 0
                  && rb.tang_products == rw.tang_products,
              "box: after a call of another length, a fresh workspace's doubles");
        free(w1);
        free(w2);
        free(w3);
    }
    /* the normal problem of a warm start on its contact's box (rr_exact.c):
     * on the wide grid, from the solution at a load 0.2 % higher (its
     * contact the new one's: the box's answer) and at a quarter of the
     * load (the contact grows out of the start's box: the grid's solve),
     * against cold solves of the grid.  Tolerances: all solved to tol
     * 1e-9, so forces within a few 1e-9 mu N, pressures' sums N to 1e-9. */
    {
        rr_exact_problem wide = hertz_case(0.005, 0.003, 15), near, far;
        size_t lw;
        double *w1, *w2, *f[3];
        const double loads[2] = {1.002, 0.25};
        rr_exact_result rc, rs, rwm;
        rr_exact_field fld;
        rr_exact_start st;
        int q, k;
        wide.cx = 3e-4;
        wide.cy = -1e-4;
        wide.cphi = 0.6;
        wide.grid.mx += 24;
        wide.grid.my += 24;
        wide.grid.x0 -= 12 * wide.grid.dx;
        wide.grid.y0 -= 12 * wide.grid.dy;
        near = far = wide;
        lw = rr_exact_workspace_len(wide.grid.mx, wide.grid.my);
        w1 = calloc(lw, sizeof *w1);
        w2 = calloc(lw, sizeof *w2);
        for (k = 0; k < 3; k++)
            f[k] = calloc((size_t)wide.grid.mx * wide.grid.my, sizeof *f[k]);
        CHECK_STATUS(rr_exact_solve(&wide, w1, lw, &rc, NULL), RR_OK, "normal box: cold");
        for (q = 0; q < 2; q++) {
            rr_exact_problem *from = q == 0 ? &near : &far;
            from->N = loads[q] * wide.N;
            memset(&fld, 0, sizeof fld);
            fld.pn = f[0];
            fld.px = f[1];
            fld.py = f[2];
            CHECK_STATUS(rr_exact_solve(from, w2, lw, &rs, &fld), RR_OK, "normal box: the start");
            st.mx = wide.grid.mx;
            st.my = wide.grid.my;
            st.pn = f[0];
            st.px = f[1];
            st.py = f[2];
            if (q == 0) {
                /* the box's solve out of products warns (no creepage: the
                 * normal problem's status alone; the fuzzer's find) */
                rr_exact_problem few = wide;
                few.cx = few.cy = few.cphi = 0.0;
                few.maxit = 2;
                CHECK_STATUS(rr_exact_solve_from(&few, &st, w2, lw, &rwm, NULL),
                             RR_WARN_NOT_CONVERGED, "normal box: out of products, a warning");
            }
            CHECK_STATUS(rr_exact_solve_from(&wide, &st, w2, lw, &rwm, NULL), RR_OK,
                         "normal box: warm");
            CHECK(hypot(rwm.fx - rc.fx, rwm.fy - rc.fy) < 1e-8 * wide.mu * wide.N
                      && fabs(rwm.fn - wide.N) < 1e-9 * wide.N && rwm.ncontact == rc.ncontact
                      && rwm.nslip == rc.nslip && fabs(rwm.delta - rc.delta) < 1e-8 * rc.delta,
                  q == 0 ? "normal box: warm from a near load, the cold solve's answer"
                         : "normal box: warm from a quarter of the load (the grid's), the cold "
                           "solve's answer");
        }
        free(w1);
        free(w2);
        for (k = 0; k < 3; k++)
            free(f[k]);
    }
    /* the box's check in the grid's own terms: a flat punch 1e130 m from
     * the plane (h the same everywhere), warm from a pressure on its first
     * rows alone.  Against the offset the displacements are lost to
     * round-off: the elements outside the box are penetrated only in h
     * taken from its lowest value, as the grid's solve takes it (a check
     * against the absolute h kept the box's contact: the fuzzer's find).
     * Tolerance: the cold solve's to tol 1e-9. */
    {
        rr_exact_problem fl = hertz_case(0.005, 0.003, 15);
        const int n = fl.grid.mx * fl.grid.my;
        size_t lf = rr_exact_workspace_len(fl.grid.mx, fl.grid.my);
        double *w1 = calloc(lf, sizeof *w1), *h = malloc((size_t)n * sizeof *h);
        double *pn = calloc((size_t)n, sizeof *pn);
        rr_exact_result rc, rwm;
        rr_exact_start st;
        int k;
        for (k = 0; k < n; k++)
            h[k] = 1e130;
        for (k = 0; k < 3 * fl.grid.mx; k++)
            pn[k] = 1.0;
        fl.h = h;
        CHECK_STATUS(rr_exact_solve(&fl, w1, lf, &rc, NULL), RR_OK, "flat punch: cold");
        memset(&st, 0, sizeof st);
        st.mx = fl.grid.mx;
        st.my = fl.grid.my;
        st.pn = pn;
        CHECK_STATUS(rr_exact_solve_from(&fl, &st, w1, lf, &rwm, NULL), RR_OK,
                     "flat punch: warm from its first rows");
        CHECK(rwm.ncontact == rc.ncontact && rc.ncontact == n,
              "flat punch: warm from its first rows, the whole grid in contact as cold");
        free(w1);
        free(h);
        free(pn);
    }
    /* the spectra's phases (rr_exact_build_spectra): a grid first solved
     * without creepage keeps the normal spectra alone; the next case of that
     * grid with creepage adds the tangential ones and gives a fresh
     * workspace's doubles (the tight Hertzian grid: no box) */
    {
        rr_exact_problem p2 = hertz_case(0.005, 0.003, 15), p0;
        const size_t l2 = rr_exact_workspace_len(p2.grid.mx, p2.grid.my);
        double *w1 = calloc(l2, sizeof *w1), *w2 = calloc(l2, sizeof *w2);
        p2.cx = 3e-4;
        p2.cphi = 0.6;
        p0 = p2;
        p0.cx = p0.cphi = 0.0;
        p0.N = 0.7 * p2.N;            /* another normal problem: no cached pressure */
        CHECK_STATUS(rr_exact_solve(&p2, w1, l2, &r, NULL), RR_OK, "phases: fresh");
        CHECK_STATUS(rr_exact_solve(&p0, w2, l2, &r2, NULL), RR_OK, "phases: no creepage");
        CHECK(r2.tang_products == 0 && r2.fx == 0.0, "phases: no creepage, no traction");
        CHECK_STATUS(rr_exact_solve(&p2, w2, l2, &r2, NULL), RR_OK, "phases: then creepage");
        CHECK(memcmp(&r.fx, &r2.fx, sizeof r.fx) == 0 && memcmp(&r.mz, &r2.mz, sizeof r.mz) == 0
                  && r.tang_products == r2.tang_products,
              "phases: the tangential spectra added later, a fresh workspace's doubles");
        free(w1);
        free(w2);
    }
    /* a workspace as any other case may leave it (NaN everywhere: a failed
     * one; the caches' tags then match nothing) gives a fresh workspace's
     * doubles: no start, search direction or scratch value of another
     * case reaches this one (a NaN left in NormCG's direction once failed
     * every later case of a batch) */
    {
        const int sizes[2][2] = {{5, 5}, {15, 9}};
        int q;
        for (q = 0; q < 2; q++) {
            rr_exact_problem p2 = hertz_case(0.005, 0.003, sizes[q][0]);
            size_t l2, i;
            double *w1, *w2;
            rr_exact_hertz_grid(0.005, 0.003, sizes[q][0], sizes[q][1], &p2.grid);
            l2 = rr_exact_workspace_len(p2.grid.mx, p2.grid.my);
            w1 = calloc(l2, sizeof *w1);
            w2 = malloc(l2 * sizeof *w2);
            for (i = 0; i < l2; i++)
                w2[i] = NAN;
            p2.cx = 3e-4;
            p2.cphi = 0.6;
            CHECK_STATUS(rr_exact_solve(&p2, w1, l2, &r, NULL), RR_OK, "fresh workspace");
            CHECK_STATUS(rr_exact_solve(&p2, w2, l2, &r2, NULL), RR_OK, "workspace of NaN");
            CHECK(memcmp(&r.fx, &r2.fx, sizeof r.fx) == 0 && memcmp(&r.fy, &r2.fy, sizeof r.fy) == 0
                  && memcmp(&r.mz, &r2.mz, sizeof r.mz) == 0
                  && r.normal_products == r2.normal_products
                  && r.tang_products == r2.tang_products,
                  "a workspace of NaN: a fresh workspace's doubles");
            free(w1);
            free(w2);
        }
    }
    /* rr_exact_workspace_forget: what the workspace keeps is built anew by
     * the next solve (its normal problem solved again, not taken from the
     * cache), with a fresh workspace's doubles */
    {
        rr_exact_problem p2 = hertz_case(0.005, 0.003, 15);
        const size_t l2 = rr_exact_workspace_len(p2.grid.mx, p2.grid.my);
        double *w1 = calloc(l2, sizeof *w1);
        rr_exact_result r3;
        p2.cx = 3e-4;
        CHECK_STATUS(rr_exact_solve(&p2, w1, l2, &r, NULL), RR_OK, "forget: fresh");
        CHECK_STATUS(rr_exact_solve(&p2, w1, l2, &r2, NULL), RR_OK, "forget: kept");
        CHECK(r.normal_products > 0 && r2.normal_products == 0, "forget: kept, the cache taken");
        rr_exact_workspace_forget(w1, l2);
        CHECK_STATUS(rr_exact_solve(&p2, w1, l2, &r3, NULL), RR_OK, "forget: forgotten");
        CHECK(r3.normal_products == r.normal_products && r3.tang_products == r.tang_products
                  && memcmp(&r.fx, &r3.fx, sizeof r.fx) == 0
                  && memcmp(&r.fy, &r3.fy, sizeof r.fy) == 0,
              "forget: solved anew, a fresh workspace's doubles");
        rr_exact_workspace_forget(NULL, l2);
        rr_exact_workspace_forget(w1, 3);      /* shorter than the header: nothing */
        free(w1);
    }
    /* the interrupt hook: polled before every product and kernel transform;
     * one that never stops leaves the doubles as they are, one that stops
     * gives RR_ERR_INTERRUPTED with NaN at once, and leaves nothing in the
     * workspace that a later case would take (its caches are not kept) */
    {
        rr_exact_problem p2 = hertz_case(0.005, 0.003, 15);
        const size_t l2 = rr_exact_workspace_len(p2.grid.mx, p2.grid.my);
        double *w1 = calloc(l2, sizeof *w1), *w2 = calloc(l2, sizeof *w2);
        counter c = {0, 0};
        rr_interrupt hook;
        int q;
        hook.poll = count_polls;
        hook.ctx = &c;
        p2.cx = 3e-4;
        p2.cphi = 0.6;
        CHECK_STATUS(rr_exact_solve(&p2, w1, l2, &r, NULL), RR_OK, "no hook");
        p2.interrupt = &hook;
        CHECK_STATUS(rr_exact_solve(&p2, w2, l2, &r2, NULL), RR_OK, "a hook that never stops");
        CHECK(memcmp(&r.fx, &r2.fx, sizeof r.fx) == 0 && memcmp(&r.mz, &r2.mz, sizeof r.mz) == 0,
              "a hook that never stops: the same doubles");
        CHECK(c.polls >= r2.normal_products + r2.tang_products + 3,
              "polled before every product and the kernels' transforms");
        for (q = 1; q <= 12; q += 11) {
            memset(w2, 0, l2 * sizeof *w2);
            c.polls = 0;
            c.stop_at = q;        /* 1: while the kernels are built; 12: in NormCG */
            CHECK_STATUS(rr_exact_solve(&p2, w2, l2, &r2, &f), RR_ERR_INTERRUPTED, "interrupted");
            CHECK(c.polls == q && isnan(r2.fx) && isnan(r2.fn) && isnan(f.px[0]),
                  "no poll after the stop; NaN results and field");
            c.stop_at = 0;
            CHECK_STATUS(rr_exact_solve(&p2, w2, l2, &r2, NULL), RR_OK, "after an interrupt");
            CHECK(memcmp(&r.fx, &r2.fx, sizeof r.fx) == 0
                  && memcmp(&r.mz, &r2.mz, sizeof r.mz) == 0,
                  "after an interrupt: a fresh workspace's doubles");
        }
        /* through the registry: the exact method polls, the others ignore it */
        {
            rr_contact_problem cc;
            rr_friction fr = {0.3, 1.0, 0.0};
            rr_creep_opts o;
            rr_forces fo;
            size_t lw;
            double *wk;
            memset(&cc, 0, sizeof cc);
            cc.cx = 1e-3;
            cc.a = 0.006;
            cc.b = 0.004;
            cc.N = 5e4;
            cc.G = 8.2e10;
            cc.nu = 0.28;
            rr_creep_opts_default(&o, rr_method_find("exact"));
            lw = rr_creep_workspace_len(&o, NULL);
            wk = calloc(lw, sizeof *wk);
            c.polls = 0;
            c.stop_at = 5;
            CHECK_STATUS(rr_creep_forces_interruptible(with_law(&cc, &fr), &o, wk, lw, &hook, &fo),
                         RR_ERR_INTERRUPTED, "the exact method interrupted");
            CHECK(isnan(fo.fx) && c.polls == 5, "NaN forces, no poll after the stop");
            rr_creep_opts_default(&o, rr_method_find("fastsim"));
            c.polls = 0;
            CHECK_STATUS(rr_creep_forces_interruptible(with_law(&cc, &fr), &o, NULL, 0, &hook, &fo), RR_OK,
                         "FASTSIM takes no hook");
            CHECK(c.polls == 0 && isfinite(fo.fx), "never polled");
            free(wk);
        }
        free(w1);
        free(w2);
    }
    CHECK(rr_exact_workspace_len(0, 5) == 0 && rr_exact_workspace_len(5, RR_EXACT_MAX_GRID + 1) == 0,
          "no workspace for bad sizes");
    {
        rr_grid g;
        CHECK_STATUS(rr_exact_hertz_grid(-1.0, 1.0, 5, 5, &g), RR_ERR_GEOMETRY, "a < 0");
        CHECK_STATUS(rr_exact_hertz_grid(1.0, 1.0, 0, 5, &g), RR_ERR_GRID, "nx 0");
        CHECK_STATUS(rr_exact_hertz_grid(1.0, 1.0, 5, 5, NULL), RR_ERR_NULL, "NULL grid");
    }
    test_warm_start();
    free(w);
    free(px);
    free(pn);
    free(state);
    return rr_test_summary();
}
