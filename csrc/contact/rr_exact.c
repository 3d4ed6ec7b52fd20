/*
 * rr_exact.c - Kalker's exact theory of steady rolling (rr_exact.h): the
 * driver of one case (its checks, the workspace, the spectra of its grid
 * built or kept, the normal solution of the previous case reused, then the
 * normal and the tangential problem), from the solver's own starts or the
 * caller's (rr_exact_solve_from), the workspace's length and the Hertzian
 * grid.  The operators are rr_exact_ops.c, the problems rr_exact_normal.c
 * and rr_exact_tangential.c (rr_exact_solver.h between them).
 */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "util/rr_fft.h"
#include "contact/rr_exact.h"
#include "contact/rr_exact_solver.h"

/* The workspace: the grid's layout, then room for the layout of the box the
 * tangential problem is solved on (tangential_on_contact), at most the
 * grid's own. */
size_t rr_exact_workspace_len(int mx, int my)
{
    layout L;
    if (mx < 1 || my < 1 || mx > RR_EXACT_MAX_GRID || my > RR_EXACT_MAX_GRID)
        return 0;
    return 2 * rr_exact_carve(&L, mx, my, NULL);
}

int rr_exact_hertz_grid(double a, double b, int nx, int ny, rr_grid *g)
{
    if (!g)
        return RR_ERR_NULL;
    memset(g, 0, sizeof *g);
    if (!isfinite(a) || !isfinite(b))
        return RR_ERR_NONFINITE;
    if (!(a > 0.0) || !(b > 0.0))
        return RR_ERR_GEOMETRY;
    if (nx < 1 || ny < 1 || nx > RR_EXACT_MAX_GRID - 2 * RR_EXACT_MARGIN
        || ny > RR_EXACT_MAX_GRID - 2 * RR_EXACT_MARGIN)
        return RR_ERR_GRID;
    g->mx = nx + 2 * RR_EXACT_MARGIN;
    g->my = ny + 2 * RR_EXACT_MARGIN;
    g->dx = 2.0 * a / nx;
    g->dy = 2.0 * b / ny;
    if (!isnormal(g->dx) || !isnormal(g->dy))
        return RR_ERR_GEOMETRY;
    g->x0 = -0.5 * (g->mx - 1) * g->dx;
    g->y0 = -0.5 * (g->my - 1) * g->dy;
    return RR_OK;
}

/* ---- the normal solution of the previous case ------------------------------- */

/* The numbers that decide the normal problem, in key order. */
static void normal_key(const rr_exact_problem *pb, double *k)
{
    k[0] = pb->grid.mx;
    k[1] = pb->grid.my;
    k[2] = pb->grid.dx;
    k[3] = pb->grid.dy;
    k[4] = pb->grid.x0;
    k[5] = pb->grid.y0;
    k[6] = pb->N;
    k[7] = pb->G;
    k[8] = pb->nu;
    k[9] = pb->tol;
    k[10] = pb->maxit;
    k[11] = pb->h ? 1.0 : 0.0;
    k[12] = pb->h ? 0.0 : pb->A;     /* the Hertzian start depends on them */
    k[13] = pb->h ? 0.0 : pb->B;
}
#define NKEY_USED 14

/* A sweep over creepages (a creep curve, a table) repeats the normal
 * problem: where every number of it and every value of h equal the last
 * one's bit for bit, its solution is the one a fresh solve would give
 * (the same operations on the same doubles), so it is reused.  Returns the
 * cached status (pressure in L->pn), or 2 where there is none. */
static int normal_cached(const rr_exact_problem *pb, layout *L, rr_exact_result *res)
{
    double k[NKEY_USED];
    normal_key(pb, k);
    if (L->nkey[0] != NKEY_TAG || memcmp(L->nkey + 1, k, sizeof k) != 0
        || memcmp(L->h_cache, L->h, (size_t)L->n * sizeof(double)) != 0)
        return 2;
    memcpy(L->pn, L->pn_cache, (size_t)L->n * sizeof(double));
    res->delta = L->nkey[1 + NKEY_USED + 1];
    res->normal_residual = L->nkey[1 + NKEY_USED + 2];
    res->normal_products = 0;
    return (int)L->nkey[1 + NKEY_USED];
}

static void normal_keep(const rr_exact_problem *pb, layout *L, const rr_exact_result *res,
                        int st)
{
    normal_key(pb, L->nkey + 1);
    L->nkey[1 + NKEY_USED] = st;
    L->nkey[1 + NKEY_USED + 1] = res->delta;
    L->nkey[1 + NKEY_USED + 2] = res->normal_residual;
    memcpy(L->pn_cache, L->pn, (size_t)L->n * sizeof(double));
    L->nkey[0] = NKEY_TAG;        /* h_cache was kept before the solve */
}

/* ---- the driver ------------------------------------------------------------ */

static void result_nan(rr_exact_result *res)
{
    res->fx = res->fy = res->mz = res->fn = res->delta = res->area = res->pmax = NAN;
    res->normal_residual = res->tang_residual = NAN;
    res->ncontact = res->nslip = 0;
    res->normal_products = res->tang_products = res->newton_steps = 0;
}

static void field_nan(const rr_exact_problem *pb, rr_exact_field *f)
{
    size_t k, n;
    if (!f || !pb || pb->grid.mx < 1 || pb->grid.my < 1 || pb->grid.mx > RR_EXACT_MAX_GRID
        || pb->grid.my > RR_EXACT_MAX_GRID)
        return;
    n = (size_t)pb->grid.mx * (size_t)pb->grid.my;
    for (k = 0; k < n; k++) {
        if (f->pn) f->pn[k] = NAN;
        if (f->px) f->px[k] = NAN;
        if (f->py) f->py[k] = NAN;
        if (f->sx) f->sx[k] = NAN;
        if (f->sy) f->sy[k] = NAN;
        if (f->state) f->state[k] = OUTSIDE;
    }
}

static int check_problem(const rr_exact_problem *pb, size_t work_len)
{
    const rr_grid *g = &pb->grid;
    const double reals[] = {g->dx, g->dy, g->x0, g->y0, pb->N, pb->G, pb->nu, pb->mu,
                            pb->cx, pb->cy, pb->cphi, pb->spin_shift, pb->tol};
    size_t need;

    if (g->mx < 1 || g->my < 1 || g->mx > RR_EXACT_MAX_GRID || g->my > RR_EXACT_MAX_GRID)
        return RR_ERR_GRID;
    if (!rr_all_finite(reals, (int)(sizeof reals / sizeof reals[0])))
        return RR_ERR_NONFINITE;
    if (pb->h) {
        if (!rr_all_finite(pb->h, g->mx * g->my))
            return RR_ERR_NONFINITE;
    } else if (!isfinite(pb->A) || !isfinite(pb->B)) {
        return RR_ERR_NONFINITE;
    }
    if (!(g->dx > 0.0) || !(g->dy > 0.0) || !isnormal(g->dx) || !isnormal(g->dy)
        || !isnormal(g->dx * g->dy) || g->dx / g->dy > 1e6 || g->dy / g->dx > 1e6)
        return RR_ERR_GEOMETRY;
    if (!pb->h && (!(pb->A > 0.0) || !(pb->B > 0.0)))
        return RR_ERR_GEOMETRY;
    if (!(pb->N > 0.0))
        return RR_ERR_LOAD;
    if (!(pb->G > 0.0) || !isnormal(pb->G) || !(pb->nu >= 0.0 && pb->nu <= 0.5))
        return RR_ERR_MATERIAL;
    if (!(pb->mu > 0.0))
        return RR_ERR_FRICTION;
    if (!(pb->tol >= 1e-14 && pb->tol <= 0.1) || pb->maxit < 1
        || !(pb->spin_shift >= -1.0 && pb->spin_shift <= 1.0))
        return RR_ERR_PARAM;
    need = rr_exact_workspace_len(g->mx, g->my);
    if (work_len < need)
        return RR_ERR_WORKSPACE;
    /* the mean pressure and the tractions must be finite doubles, and their
     * squares too: the solvers' norms sum them (past 1e150 they overflow,
     * below 1e-150 they vanish, and the iteration runs to maxit on inf/inf) */
    {
        const double pmean = pb->N / (g->dx * g->dy) / ((double)g->mx * g->my);
        if (!isnormal(pmean) || !isfinite(pmean * pb->mu * 1e3) || !isfinite(pmean / pb->G)
            || !isnormal(pb->mu * pb->N) || !isnormal(pb->mu * pmean)
            || !(fmax(pmean, pb->mu * pmean) <= 1e140) || !(fmin(pmean, pb->mu * pmean) >= 1e-140))
            return RR_ERR_RANGE;      /* forces or bounds without a double's digits */
    }
    return RR_OK;
}

/* What a caller can get wrong in a start (rr_exact_start), for the grid
 * of pb (already checked). */
static int check_start(const rr_exact_problem *pb, const rr_exact_start *s)
{
    const int n = pb->grid.mx * pb->grid.my;
    int k, positive = 0;
    if (s->mx != pb->grid.mx || s->my != pb->grid.my)
        return RR_ERR_GRID;
    if (!s->pn || (!s->px) != (!s->py))
        return RR_ERR_NULL;
    if (!rr_all_finite(s->pn, n) || (s->px && (!rr_all_finite(s->px, n)
                                               || !rr_all_finite(s->py, n))))
        return RR_ERR_NONFINITE;
    for (k = 0; k < n; k++) {
        if (s->pn[k] < 0.0)
            return RR_ERR_PARAM;
        positive |= s->pn[k] > 0.0;
    }
    return positive ? RR_OK : RR_ERR_PARAM;
}

/* ---- the tangential problem on the contact's box --------------------------- */

/* The tangential problem lives on the elements in contact: the tractions
 * are 0 elsewhere, and only there are slip equations.  So it is solved on
 * the grid's box around them, whose products run on a smaller torus: the
 * grid of a wheel's patch covers where h reaches the approach, which is
 * about twice the contact's area (Hertz: exactly), and its contact's box
 * is 0.2 to 0.5 of it (CONTACT's 72 roller cases).  The same equations on
 * the same elements: only the products' rounding differs. */

/* The box's side along an axis of m elements for a contact spanning w:
 * widened, at no cost, to the longest side on the same torus (the box's
 * spectra then serve every contact of a similar size: the load's steps)
 * that leaves the torus at least twice the side, where the steady kernels'
 * spectra follow from the symmetric ones (rr_exact_build_spectra: three
 * transforms, not six). */
static int box_side(int w, int m)
{
    const int T = rr_conv2d_torus_len(2 * w - 1);
    int c = T / 2 < m ? T / 2 : m;
    if (c < w)
        return w;                /* T = 2 w - 1 (odd): the contact's own */
    while (c > w && rr_conv2d_torus_len(2 * c - 1) != T)
        c--;
    return c;
}

/* The box's first element along an axis: the contact's [a, b] centred in
 * a side of c, kept on the grid's m elements. */
static int box_first(int a, int b, int c, int m)
{
    int f = a - (c - (b - a + 1)) / 2;
    f = f + c > m ? m - c : f;
    return f < 0 ? 0 : f;
}

/* 1 where the box of mx x my elements should be solved on (its torus at
 * most 4/5 of the grid's, which pays for its spectra) */
static int box_pays(int bx, int by, int mx, int my)
{
    const double b = (double)rr_conv2d_torus_len(2 * bx - 1) * rr_conv2d_torus_len(2 * by - 1);
    const double g = (double)rr_conv2d_torus_len(2 * mx - 1) * rr_conv2d_torus_len(2 * my - 1);
    return b <= 0.8 * g;
}

/* The tangential problem of S on its own grid, its tangential spectra
 * built first where missing. */
static int tangential_on_grid(solver *S, rr_exact_result *res)
{
    const rr_exact_problem *pb = S->pb;
    const int st = rr_exact_build_spectra(S->L, S->cv, pb->grid.dy / pb->grid.dx, pb->nu, 1,
                                          pb->interrupt);
    return st < 0 ? st : rr_exact_solve_tangential(S, res);
}

/* The tangential problem of S (its layout L holding the normal solution),
 * on the contact's box where that pays, else on the grid: the box's
 * layout at work + box_base (its spectra kept there, keyed as the grid's),
 * the solution put back into L's p, s and state. */
static int tangential_on_contact(solver *S, double *work, size_t box_base, rr_exact_result *res)
{
    const rr_exact_problem *pb = S->pb;
    layout *L = S->L, B;
    rr_conv2d cvb;
    rr_exact_problem pbb;
    rr_exact_start sb;
    solver SB;
    const int mx = L->mx, my = L->my, n = L->n;
    int i0 = mx, i1 = -1, j0 = my, j1 = -1, bx, by, fi, fj, i, j, st;

    if (pb->cx == 0.0 && pb->cy == 0.0 && pb->cphi == 0.0)
        return rr_exact_solve_tangential(S, res);     /* no traction, no product */
    for (j = 0; j < my; j++)
        for (i = 0; i < mx; i++)
            if (L->pn[j * mx + i] > 0.0) {
                i0 = i < i0 ? i : i0;
                i1 = i > i1 ? i : i1;
                j0 = j < j0 ? j : j0;
                j1 = j > j1 ? j : j1;
            }
    if (i1 < 0)
        return tangential_on_grid(S, res);
    bx = box_side(i1 - i0 + 1, mx);
    by = box_side(j1 - j0 + 1, my);
    if (!box_pays(bx, by, mx, my) || rr_exact_carve(&B, bx, by, NULL) > box_base)
        return tangential_on_grid(S, res);
    fi = box_first(i0, i1, bx, mx);
    fj = box_first(j0, j1, by, my);
    rr_exact_carve(&B, bx, by, work + box_base);
    if ((st = rr_conv2d_init(&cvb, bx, by, B.conv, B.conv_len)) < 0
        || (st = rr_exact_build_spectra(&B, &cvb, pb->grid.dy / pb->grid.dx, pb->nu, 1,
                                        pb->interrupt)) < 0)
        return st;
    pbb = *pb;
    pbb.grid.mx = bx;
    pbb.grid.my = by;
    pbb.grid.x0 = pb->grid.x0 + fi * pb->grid.dx;
    pbb.grid.y0 = pb->grid.y0 + fj * pb->grid.dy;
    pbb.h = NULL;                      /* the tangential problem does not read it */
    for (j = 0; j < by; j++)
        memcpy(B.pn + j * bx, L->pn + (j + fj) * mx + fi, (size_t)bx * sizeof *B.pn);
    SB.pb = &pbb;
    SB.start = NULL;
    SB.L = &B;
    SB.cv = &cvb;
    SB.products = 0;
    if (S->start && S->start->px) {
        /* the caller's start, boxed into scratch the solver reads before
         * it writes (dlt: GMRES's, after the start is taken) */
        double *px = B.dlt, *py = B.dlt + B.n;
        for (j = 0; j < by; j++) {
            memcpy(px + j * bx, S->start->px + (j + fj) * mx + fi, (size_t)bx * sizeof *px);
            memcpy(py + j * bx, S->start->py + (j + fj) * mx + fi, (size_t)bx * sizeof *py);
        }
        sb = *S->start;
        sb.mx = bx;
        sb.my = by;
        sb.pn = B.pn;
        sb.px = px;
        sb.py = py;
        SB.start = &sb;
    }
    st = rr_exact_solve_tangential(&SB, res);
    /* back onto the grid: nothing outside the box (no pressure there) */
    for (i = 0; i < 2 * n; i++)
        L->p[i] = L->s[i] = 0.0;
    memset(L->state, OUTSIDE, (size_t)n);
    for (j = 0; j < by; j++)
        for (i = 0; i < bx; i++) {
            const int k = (j + fj) * mx + fi + i, q = j * bx + i;
            L->p[k] = B.p[q];
            L->p[k + n] = B.p[q + B.n];
            L->s[k] = B.s[q];
            L->s[k + n] = B.s[q + B.n];
            L->state[k] = B.state[q];
        }
    return st;
}

int rr_exact_solve(const rr_exact_problem *pb, double *work, size_t work_len,
                   rr_exact_result *res, rr_exact_field *field)
{
    return rr_exact_solve_from(pb, NULL, work, work_len, res, field);
}

int rr_exact_solve_from(const rr_exact_problem *pb, const rr_exact_start *start, double *work,
                        size_t work_len, rr_exact_result *res, rr_exact_field *field)
{
    layout L;
    rr_conv2d cv;
    solver S;
    int st, st2, k, n, mx;
    size_t box_base;
    double fx = 0.0, fy = 0.0, mz = 0.0, fn = 0.0, pmax = 0.0, dA;

    if (!res)
        return RR_ERR_NULL;
    if (!pb || !work) {
        result_nan(res);
        field_nan(pb, field);
        return RR_ERR_NULL;
    }
    st = check_problem(pb, work_len);
    if (st == RR_OK && start)
        st = check_start(pb, start);
    if (st < 0) {
        result_nan(res);
        field_nan(pb, field);
        return st;
    }
    result_nan(res);
    mx = pb->grid.mx;
    n = mx * pb->grid.my;
    box_base = rr_exact_carve(&L, mx, pb->grid.my, work);
    st = rr_conv2d_init(&cv, mx, pb->grid.my, L.conv, L.conv_len);
    if (st == RR_OK && rr_conv2d_spectrum_len(&cv) > rr_exact_spectrum_len(mx, pb->grid.my))
        st = RR_ERR_WORKSPACE;
    if (st == RR_OK) {
        double key[HDR_LEN];
        memcpy(key, L.hdr, sizeof key);
        st = rr_exact_build_spectra(&L, &cv, pb->grid.dy / pb->grid.dx, pb->nu, 0,
                                    pb->interrupt);
        /* the grid's spectra built anew: the last grid may have been
         * larger, its layout over the box's, so the box's key goes too */
        if (memcmp(key, L.hdr, sizeof key) != 0)
            work[box_base] = 0.0;
    }
    if (st < 0) {
        field_nan(pb, field);
        return st;
    }
    for (k = 0; k < n; k++) {
        if (pb->h) {
            L.h[k] = pb->h[k];
        } else {
            const double x = pb->grid.x0 + (k % mx) * pb->grid.dx;
            const double y = pb->grid.y0 + (k / mx) * pb->grid.dy;
            L.h[k] = pb->A * x * x + pb->B * y * y;
        }
    }
    if (!rr_all_finite(L.h, n)) {
        result_nan(res);
        field_nan(pb, field);
        return RR_ERR_RANGE;
    }
    S.pb = pb;
    S.start = start;
    S.L = &L;
    S.cv = &cv;
    S.products = 0;
    if (start) {
        /* a warm solve: the cache (a cold solve's doubles) neither read nor
         * replaced */
        st = rr_exact_solve_normal(&S, res);
    } else if ((st = normal_cached(pb, &L, res)) == 2) {
        /* a new normal problem: solved, and kept for the next case */
        L.nkey[0] = 0.0;
        memcpy(L.h_cache, L.h, (size_t)n * sizeof(double));
        st = rr_exact_solve_normal(&S, res);
        if (st >= 0)
            normal_keep(pb, &L, res, st);
    }
    if (st >= 0)
        st2 = tangential_on_contact(&S, work, box_base, res);
    else
        st2 = st;
    if (st < 0 || st2 < 0) {
        result_nan(res);
        field_nan(pb, field);
        return st < 0 ? st : st2;
    }
    dA = pb->grid.dx * pb->grid.dy;
    res->ncontact = res->nslip = 0;
    for (k = 0; k < n; k++) {
        const double x = pb->grid.x0 + (k % mx) * pb->grid.dx;
        const double y = pb->grid.y0 + (k / mx) * pb->grid.dy;
        const double px = L.p[k], py = L.p[k + n];
        int state = L.pn[k] > 0.0 ? L.state[k] : OUTSIDE;
        fx += px;
        fy += py;
        mz += x * py - y * px;
        fn += L.pn[k];
        if (L.pn[k] > pmax)
            pmax = L.pn[k];
        res->ncontact += state != OUTSIDE;
        res->nslip += state == SLIP;
        if (field) {
            if (field->pn) field->pn[k] = L.pn[k];
            if (field->px) field->px[k] = px;
            if (field->py) field->py[k] = py;
            if (field->sx) field->sx[k] = state == SLIP ? L.s[k] : 0.0;
            if (field->sy) field->sy[k] = state == SLIP ? L.s[k + n] : 0.0;
            if (field->state) field->state[k] = (signed char)state;
        }
    }
    res->fx = fx * dA;
    res->fy = fy * dA;
    res->mz = mz * dA;
    res->fn = fn * dA;
    res->pmax = pmax;
    res->area = res->ncontact * dA;
    {
        const double out[] = {res->fx, res->fy, res->mz, res->fn, res->delta, res->area};
        /* the pressure must carry the load: a normal problem whose elastic
         * displacements lie below the rounding of its gap (a load of 1e-300 N
         * on a gap of micrometres: the fuzzer's find) loses it */
        if (!rr_all_finite(out, 6) || res->ncontact < 1
            || !(fabs(res->fn - pb->N) <= 1e-6 * pb->N)) {
            result_nan(res);
            field_nan(pb, field);
            return RR_ERR_RANGE;
        }
    }
    return st != RR_OK ? st : st2;
}

int rr_exact_at_edge(const signed char *state, int mx, int my)
{
    int i;
    if (!state || mx < 1 || my < 1)
        return 0;
    for (i = 0; i < mx; i++)
        if (state[i] >= 0 || state[(size_t)(my - 1) * mx + i] >= 0)
            return 1;
    for (i = 0; i < my; i++)
        if (state[(size_t)i * mx] >= 0 || state[(size_t)i * mx + mx - 1] >= 0)
            return 1;
    return 0;
}
