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

/* The workspace: the grid's layout, then, from the middle, room for the
 * layout of the box the problems are solved on (normal_on_contact,
 * tangential_on_contact), at most the grid's own. */
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

void rr_exact_workspace_forget(double *work, size_t work_len)
{
    if (!work || work_len < HDR_LEN + STN_LEN + NKEY_LEN)
        return;
    /* the tags of the grid's spectra and of the normal solution (at fixed
     * places: rr_exact_carve), and where the box was (no box_base is
     * negative: its key goes at the next solve) */
    work[0] = 0.0;
    work[BOX_AT] = -1.0;
    work[HDR_LEN + STN_LEN] = 0.0;
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

/* ---- the contact's box ----------------------------------------------------- */

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

/* A box of the grid: its first element and sides (bx 0: none). */
typedef struct {
    int fi, fj, bx, by;
} box;

/* The box around elements [i0, i1] x [j0, j1] of L's grid, where it pays
 * and its layout fits in room doubles; 1 where there is one. */
static int box_around(const layout *L, int i0, int i1, int j0, int j1, size_t room, box *b)
{
    layout B;
    b->bx = box_side(i1 - i0 + 1, L->mx);
    b->by = box_side(j1 - j0 + 1, L->my);
    if (!box_pays(b->bx, b->by, L->mx, L->my) || rr_exact_carve(&B, b->bx, b->by, NULL) > room) {
        b->bx = 0;
        return 0;
    }
    b->fi = box_first(i0, i1, b->bx, L->mx);
    b->fj = box_first(j0, j1, b->by, L->my);
    return 1;
}

/* The bounding box of the positive values of v (mx x my); 0 where none. */
static int positive_bounds(const double *v, int mx, int my, int *i0, int *i1, int *j0, int *j1)
{
    int i, j;
    *i0 = mx;
    *i1 = -1;
    *j0 = my;
    *j1 = -1;
    for (j = 0; j < my; j++)
        for (i = 0; i < mx; i++)
            if (v[j * mx + i] > 0.0) {
                *i0 = i < *i0 ? i : *i0;
                *i1 = i > *i1 ? i : *i1;
                *j0 = j < *j0 ? j : *j0;
                *j1 = j > *j1 ? j : *j1;
            }
    return *i1 >= 0;
}

/* Values of size bytes each between the grid's rows (mx a row) and box
 * b's: grid into box (to_grid 0), or box into grid (1). */
static void box_rows(const box *b, int mx, size_t size, const void *from, void *to, int to_grid)
{
    const size_t row = (size_t)b->bx * size;
    int j;
    for (j = 0; j < b->by; j++) {
        const size_t g = ((size_t)(j + b->fj) * mx + b->fi) * size, q = (size_t)j * row;
        memcpy((char *)to + (to_grid ? g : q), (const char *)from + (to_grid ? q : g), row);
    }
}

/* in (the grid's rows of mx) boxed into out (b's rows) */
static void box_in(const box *b, int mx, const double *in, double *out)
{
    box_rows(b, mx, sizeof *in, in, out, 0);
}

/* in (b's rows) into out (the grid's rows of mx) */
static void box_out(const box *b, int mx, const double *in, double *out)
{
    box_rows(b, mx, sizeof *in, in, out, 1);
}

/* A problem of the grid's solver on a box of it: the box, its layout, FFT
 * engine, problem, start and solver. */
typedef struct {
    box b;
    layout L;
    rr_conv2d cv;
    rr_exact_problem pb;
    rr_exact_start start;
    solver S;
} boxed;

/* The solver X->S of S's problem on box X->b: its layout carved at bw (its
 * spectra kept there, keyed as the grid's; the tangential phase where
 * asked), its problem (no h: the callers fill the box's), no start. */
static int box_solver(const solver *S, double *bw, int tangential, boxed *X)
{
    const rr_exact_problem *pb = S->pb;
    int st;
    rr_exact_carve(&X->L, X->b.bx, X->b.by, bw);
    if ((st = rr_conv2d_init(&X->cv, X->b.bx, X->b.by, X->L.conv, X->L.conv_len)) < 0
        || (st = rr_exact_build_spectra(&X->L, &X->cv, pb->grid.dy / pb->grid.dx, pb->nu,
                                        tangential, pb->interrupt)) < 0)
        return st;
    X->pb = *pb;
    X->pb.grid.mx = X->b.bx;
    X->pb.grid.my = X->b.by;
    X->pb.grid.x0 = pb->grid.x0 + X->b.fi * pb->grid.dx;
    X->pb.grid.y0 = pb->grid.y0 + X->b.fj * pb->grid.dy;
    X->pb.h = NULL;
    X->S.pb = &X->pb;
    X->S.start = NULL;
    X->S.L = &X->L;
    X->S.cv = &X->cv;
    X->S.products = 0;
    return RR_OK;
}

/* The caller's start s boxed (its pressure pn, its tractions px, py or
 * NULL: arrays of the box's) as X's start. */
static void box_start(const rr_exact_start *s, const double *pn, const double *px,
                      const double *py, boxed *X)
{
    X->start = *s;
    X->start.mx = X->b.bx;
    X->start.my = X->b.by;
    X->start.pn = pn;
    X->start.px = px;
    X->start.py = py;
    X->S.start = &X->start;
}

/* ---- the normal problem on the contact's box -------------------------------- */

/* A warm start's contact (the caller's pressure) moves little: the normal
 * problem is solved on the box around it (widened to the longest side on
 * its torus, as the tangential one's: the same box, whose spectra serve
 * both), and the box's answer is the grid's where no element outside the
 * box is penetrated, which one product on the grid shows (the
 * displacements there are the box pressure's); an element that would be
 * penetrated sends the problem to the grid, from the caller's start.  The
 * same equations on the same elements where the contact stays inside:
 * only the products' rounding differs.  A margin of one element around
 * the start's contact changed the box's torus on some of CONTACT's roller
 * cases, and with it the tangential problem's: more instructions. */
static int normal_on_contact(solver *S, double *bw, size_t room, rr_exact_result *res,
                             box *used)
{
    layout *L = S->L;
    const int mx = L->mx, my = L->my, n = L->n;
    int i0, i1, j0, j1, st, pen = 0, k, j;
    double hmin = L->h[0];
    boxed X;

    used->bx = 0;
    if (!S->start || !positive_bounds(S->start->pn, mx, my, &i0, &i1, &j0, &j1)
        || !box_around(L, i0, i1, j0, j1, room, &X.b))
        return rr_exact_solve_normal(S, res);
    if ((st = box_solver(S, bw, 0, &X)) < 0)
        return st;
    /* h from the grid's lowest value, as the grid's solve takes it (a
     * large offset would drown the displacements in round-off: the
     * comparisons below are in these terms too) */
    for (k = 1; k < n; k++)
        hmin = L->h[k] < hmin ? L->h[k] : hmin;
    box_in(&X.b, mx, L->h, X.L.h);
    for (k = 0; k < X.L.n; k++)
        X.L.h[k] -= hmin;
    /* the start boxed into gap, which the solver writes after taking it */
    box_in(&X.b, mx, S->start->pn, X.L.gap);
    box_start(S->start, X.L.gap, NULL, NULL, &X);
    st = rr_exact_solve_normal(&X.S, res);
    S->products += X.S.products;         /* the cap (maxit) counts them too */
    if (st < 0)
        return st;
    /* back onto the grid, and the grid's displacements of that pressure */
    memset(L->pn, 0, (size_t)n * sizeof *L->pn);
    memset(L->state, OUTSIDE, (size_t)n);
    box_out(&X.b, mx, X.L.pn, L->pn);
    box_rows(&X.b, mx, 1, X.L.state, L->state, 1);
    if ((k = rr_exact_normal_displacement(S, L->pn, L->gap)) < 0)
        return k;                       /* st keeps the box's status (a warning) */
    for (j = 0; j < my && !pen; j++)
        for (k = 0; k < mx; k++)
            if ((k < X.b.fi || k >= X.b.fi + X.b.bx || j < X.b.fj || j >= X.b.fj + X.b.by)
                && L->gap[j * mx + k] + (L->h[j * mx + k] - hmin) < res->delta) {
                pen = 1;
                break;
            }
    if (pen)
        return rr_exact_solve_normal(S, res);
    res->delta += hmin;                 /* as the grid's solve gives it */
    res->normal_products = S->products;
    *used = X.b;
    return st;
}

/* ---- the tangential problem on the contact's box --------------------------- */

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
 * on the contact's box where that pays (the normal problem's box nb where
 * it had one: the contact lies in it, and its spectra are there), else on
 * the grid; the solution put back into L's p, s and state. */
static int tangential_on_contact(solver *S, double *bw, size_t room, const box *nb,
                                 rr_exact_result *res)
{
    layout *L = S->L;
    const int mx = L->mx, my = L->my, n = L->n;
    int i0, i1, j0, j1, i, st;
    boxed X;

    if (S->pb->cx == 0.0 && S->pb->cy == 0.0 && S->pb->cphi == 0.0)
        return rr_exact_solve_tangential(S, res);     /* no traction, no product */
    if (nb->bx > 0)
        X.b = *nb;
    else if (!positive_bounds(L->pn, mx, my, &i0, &i1, &j0, &j1)
             || !box_around(L, i0, i1, j0, j1, room, &X.b))
        return tangential_on_grid(S, res);
    if ((st = box_solver(S, bw, 1, &X)) < 0)
        return st;
    box_in(&X.b, mx, L->pn, X.L.pn);
    if (S->start && S->start->px) {
        /* the caller's start, boxed into scratch the solver reads before
         * it writes (dlt: GMRES's, after the start is taken) */
        box_in(&X.b, mx, S->start->px, X.L.dlt);
        box_in(&X.b, mx, S->start->py, X.L.dlt + X.L.n);
        box_start(S->start, X.L.pn, X.L.dlt, X.L.dlt + X.L.n, &X);
    }
    st = rr_exact_solve_tangential(&X.S, res);
    /* back onto the grid: nothing outside the box (no pressure there) */
    for (i = 0; i < 2 * n; i++)
        L->p[i] = L->s[i] = 0.0;
    memset(L->state, OUTSIDE, (size_t)n);
    box_out(&X.b, mx, X.L.p, L->p);
    box_out(&X.b, mx, X.L.p + X.L.n, L->p + n);
    box_out(&X.b, mx, X.L.s, L->s);
    box_out(&X.b, mx, X.L.s + X.L.n, L->s + n);
    box_rows(&X.b, mx, 1, X.L.state, L->state, 1);
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
    box nb = {0, 0, 0, 0};
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
    rr_exact_carve(&L, mx, pb->grid.my, work);
    box_base = work_len / 2;
    st = rr_conv2d_init(&cv, mx, pb->grid.my, L.conv, L.conv_len);
    if (st == RR_OK && rr_conv2d_spectrum_len(&cv) > rr_exact_spectrum_len(mx, pb->grid.my))
        st = RR_ERR_WORKSPACE;
    if (st == RR_OK) {
        st = rr_exact_build_spectra(&L, &cv, pb->grid.dy / pb->grid.dx, pb->nu, 0,
                                    pb->interrupt);
        /* the box's spectra are kept at the middle of the workspace, above
         * any grid's layout (the workspace holds two), from call to call;
         * the grid's header records where the last call had its box: a
         * call of another length may have written over this one's numbers
         * and not over its key, so the key goes where it moved */
        if (L.hdr[BOX_AT] != (double)box_base) {
            work[box_base] = 0.0;
            L.hdr[BOX_AT] = (double)box_base;
        }
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
        st = normal_on_contact(&S, work + box_base, work_len - box_base, res, &nb);
    } else if ((st = normal_cached(pb, &L, res)) == 2) {
        /* a new normal problem: solved, and kept for the next case */
        L.nkey[0] = 0.0;
        memcpy(L.h_cache, L.h, (size_t)n * sizeof(double));
        st = rr_exact_solve_normal(&S, res);
        if (st >= 0)
            normal_keep(pb, &L, res, st);
    }
    if (st >= 0)
        st2 = tangential_on_contact(&S, work + box_base, work_len - box_base, &nb, res);
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
