/*
 * rr_nonhertz_table.c - one row of the non-Hertzian contact's table by the
 * exact theory (rr_nonhertz_table.h): benchmarks/nonhertz_fast.py's
 * build_row on the C solver (rr_wheel_exact for the largest load's
 * lowering; rr_gap_build and rr_exact_solve for the nodes' poses, the load
 * each carries and the finer grids).
 */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "contact/rr_contact.h"
#include "contact/rr_exact.h"
#include "contact/rr_exact_table.h"
#include "contact/rr_kalker.h"
#include "geometry/rr_gap.h"
#include "geometry/rr_wheel_exact.h"
#include "geometry/rr_nonhertz_table.h"
#include "geometry/rr_nonhertz_row.h"

/* The nodes' lowerings as fractions of the largest (the study's NODES). */
static const double node_f[RR_NH_NODES] = {0.03, 0.1, 0.2, 0.33, 0.46, 0.6, 0.75, 0.88, 1.0};
static const int corr_node[RR_NH_CORR] = {RR_NH_CORR_NODE0, RR_NH_CORR_NODE1};
/* The tiny creepages of the linear coefficients (well inside adhesion:
 * the forces linear to 1e-9 of mu N). */
#define EPS_C 1e-7
#define EPS_PHI 1e-4
/* The finest element the workspace's profile samples allow [m]. */
#define DX_MIN 1e-5
#define AB_LO (0.1 * (1.0 + 1e-9))
#define AB_HI (10.0 * (1.0 - 1e-9))
/* A grid with fewer square elements than SHORT_FEW across its shorter side
 * gets SHORT_SIDE n there instead (n across its longer).  rr_gap's square
 * elements leave a flange patch (a/b over 10) 3 to 7 elements wide at n 30
 * to 40: with the flange's spin its exact fx then wanders by 0.05 mu N
 * between n and 2n, and Richardson's 2 F(2n) - F(n) doubles that (S1002
 * +6.5 mm: the correction at zero creepage 0.065 mu N where the
 * continuum's is 0.001).  Half the long side's count keeps fx within 0.002
 * mu N there (tests/test_nonhertz_fast.py).  Grids already SHORT_FEW wide
 * keep their square elements (refining them moved S1002's flange root,
 * +5.5 mm, by 0.002 to 0.004 mu N away from the reference). */
#define SHORT_FEW 8.0
#define SHORT_SIDE 0.5

void rr_nonhertz_row_default(rr_nh_row_problem *pb)
{
    if (!pb)
        return;
    memset(pb, 0, sizeof *pb);
    pb->E = 2.1e11;
    pb->nu = 0.28;
    pb->mu = 0.52;
    pb->vmin = 1e-3;
    pb->n = 40;
    pb->n_corr = 30;
    pb->richardson = 1;
    pb->combine = 4e-3;
    pb->tol = 1e-6;
    pb->maxit = 5000;
}

/* The gap options of the finer grids (their sample step: DX_MIN's). */
static void fine_opts(rr_gap_opts *o, double dx)
{
    rr_gap_opts_default(o);
    o->dx = o->dy = dx;
}

/* Element sizes for n across patch p's region: square, n across its
 * longer side (returns 0), or SHORT_SIDE n across its shorter where square
 * ones leave fewer than SHORT_FEW there (returns 1; rr_gap's region: half_length
 * along x, lo to hi along y, which the approach and cover fix, not the
 * elements); the narrower ones none under 2 DX_MIN (a patch whose square
 * ones are that small stays square), so that the finer
 * grids' halves stay within what the workspace's samples hold (Manchester's
 * right wheel at -10.4 mm, its smallest node, 96 N, asked for less). */
static int element_sizes(const rr_gap_patch *p, int n, double *dx, double *dy)
{
    const double lx = 2.0 * p->half_length, ly = p->hi - p->lo, m = ceil(SHORT_SIDE * n);
    const double d = fmax(lx, ly) / n;
    *dx = *dy = d;
    if (fmin(lx, ly) >= SHORT_FEW * d || d <= 2.0 * DX_MIN)
        return 0;
    *dx = fmax(fmin(d, lx / m), fmin(d, 2.0 * DX_MIN));
    *dy = fmax(fmin(d, ly / m), fmin(d, 2.0 * DX_MIN));
    return 1;
}

/* The problem of node solves: rr_wheel_exact at vertical load Fz, no creepage. */
static void node_problem(const rr_nh_row_problem *pb, double Fz, rr_wheel_exact_problem *we)
{
    rr_wheel_exact_default(we);
    we->pair = pb->pair;
    we->y_ws = pb->y_ws;
    we->pose0 = pb->pose0;
    we->point = pb->point;
    we->Fz = Fz;
    we->E = pb->E;
    we->nu = pb->nu;
    we->mu = pb->mu;
    we->creep_given = 1;
    we->vmin = pb->vmin;
    we->gap.n = pb->n;
    we->gap.combine = pb->combine;
    we->tol = pb->tol;
    we->maxit = pb->maxit;
    we->interrupt = pb->interrupt;
}

static size_t lens(const rr_nh_row_problem *pb, int side, size_t part[4])
{
    rr_wheel_exact_problem we;
    rr_gap_opts o;
    if (!pb || side < 8 || side > RR_EXACT_MAX_GRID / 2)
        return 0;
    node_problem(pb, 1.0, &we);
    fine_opts(&o, DX_MIN);
    part[0] = rr_wheel_exact_workspace_len(&we, side, side);
    part[1] = rr_exact_workspace_len(2 * side, 2 * side);
    part[2] = rr_gap_workspace_len(&o);
    part[3] = (size_t)side * (size_t)side * 12;
    if (!part[0] || !part[1] || !part[2])
        return 0;
    return part[0] + part[1] + part[2] + part[3];
}

size_t rr_nonhertz_row_workspace_len(const rr_nh_row_problem *pb, int side)
{
    size_t part[4];
    return lens(pb, side, part);
}

int rr_nh_grid_failed(rr_nh_call *c, int st, const rr_gap_patch *p, int scale)
{
    const int m = p->grid.mx > p->grid.my ? p->grid.mx : p->grid.my;
    c->info->why = RR_NH_ROW_GRID;
    c->info->gap_why = p->why;
    if (st == RR_ERR_WORKSPACE)
        c->info->need = (size_t)((m + scale - 1) / scale);
    return st;
}

/* A grid for a solver of scale x side elements a side (the coarse grids'
 * 1, the fine's 2): rr_gap_build holds it to the cells, scale^2 side^2,
 * but the solver's transforms to its side along each axis (a 13 x 11 grid
 * fits 144 cells, not a 12 x 12 transform).  RR_ERR_WORKSPACE beyond it. */
static int grid_fits(rr_nh_call *c, rr_gap_patch *p, int scale)
{
    if (p->grid.mx <= scale * c->b.side && p->grid.my <= scale * c->b.side)
        return RR_OK;
    p->why = RR_GAP_H_BUFFER;
    return rr_nh_grid_failed(c, RR_ERR_WORKSPACE, p, scale);
}

/* A grid of elements dx, dy (from n by element_sizes when dx = 0) on the
 * node's plane and pose (patch p of result r) into h, for a solver of
 * scale x side a side (grid_fits). */
static int grid_at(rr_nh_call *c, const rr_wheel_exact_result *r, int n, double dx, double dy,
                   double *h, int scale, rr_gap_patch *out)
{
    const size_t hlen = (size_t)(scale * scale) * c->b.cells;
    const rr_nh_row_problem *pb = c->pb;
    rr_gap_site site;
    rr_gap_opts o;
    int st;
    rr_gap_opts_default(&o);
    o.reference = RR_GAP_GIVEN;
    o.s_roller = r->patch.s_roller;
    o.delta = r->patch.delta;
    o.approach = r->approach;
    o.cover = r->cover;
    o.n = n;
    /* square elements from n are rr_gap's own (its samples RR_GAP_SAMPLE
     * apart): sizes given would set the samples a tenth of an element
     * apart, finer than the workspace holds on a rig-scale patch's lightest
     * node (elements under DX_MIN) */
    if (!(dx > 0.0) && !element_sizes(&r->patch, n, &dx, &dy))
        dx = dy = 0.0;
    o.dx = dx;
    o.dy = dy;
    /* elements under DX_MIN (the Richardson halves of a small patch's, a
     * light node at a fine n): samples no finer than the workspace holds,
     * DX_MIN / 10, some five to ten to an element where rr_gap's own rule
     * (a tenth of it) would refuse the grid; the same step as rr_gap's
     * from DX_MIN up */
    if (o.dx > 0.0)
        o.sample = fmax(fmin(RR_GAP_SAMPLE, 0.1 * fmin(o.dx, o.dy)), 0.1 * DX_MIN);
    o.keep = 1;
    o.keep_lo = c->bd->lo;
    o.keep_hi = c->bd->hi;
    if (rr_gap_workspace_len(&o) > c->b.gap_len) {
        c->info->why = RR_NH_ROW_GRID;
        return RR_ERR_WORKSPACE;
    }
    site.pair = pb->pair;
    site.y_ws = pb->y_ws;
    site.z = r->z;
    site.roll = r->roll;
    site.s_roller = c->bd->s_roller;
    site.s_wheel = c->bd->s_wheel;
    site.delta = c->bd->delta;
    st = rr_gap_build(&site, &o, c->b.gap, c->b.gap_len, h, hlen, out);
    if (st < 0)
        return rr_nh_grid_failed(c, st, out, scale);
    if (grid_fits(c, out, scale) != RR_OK)
        return RR_ERR_WORKSPACE;
    rr_nh_clip_band(c->bd, out, h);
    return st;
}

/* The exact forces (fx, fy, mz about P) on grid g, h at load N. */
static int solve(rr_nh_call *c, const rr_grid *g, const double *h, double N, double cx, double cy,
                 double cphi, int fine, double F[3], rr_exact_field *field)
{
    const rr_nh_row_problem *pb = c->pb;
    rr_exact_problem ep;
    rr_exact_result res;
    int st;
    memset(&ep, 0, sizeof ep);
    ep.grid = *g;
    ep.h = h;
    ep.N = N;
    ep.G = c->G;
    ep.nu = pb->nu;
    ep.mu = pb->mu;
    ep.cx = cx;
    ep.cy = cy;
    ep.cphi = cphi;
    ep.spin_shift = 1.0 / 6.0;
    ep.tol = pb->tol;
    ep.maxit = pb->maxit;
    ep.interrupt = pb->interrupt;
    c->info->solves++;
    if (fine)
        st = rr_exact_solve(&ep, c->b.fine_ex, c->b.fine_len, &res, field);
    else
        st = rr_exact_solve(&ep, c->b.wex, c->b.coarse_len, &res, field);
    if (st < 0) {
        c->info->why = RR_NH_ROW_SOLVE;
        return st;
    }
    F[0] = res.fx;
    F[1] = res.fy;
    F[2] = res.mz;
    return st;
}

static int worse(int a, int b)
{
    return a < 0 || b < 0 ? (a < b ? a : b) : (a > b ? a : b);
}

/* The forces at a batch of creepages cr[i] = (cx, cy, cphi), i < m, on the
 * coarse grid and (Richardson) the fine one: F[i] = 2 F_fine - F_coarse. */
static int forces(rr_nh_call *c, const rr_gap_patch *g, const double *h, const rr_gap_patch *gf,
                  const double *hf, double N, const double (*cr)[3], int m, double (*F)[3],
                  int *warn)
{
    double Ff[3];
    int i, k, st;
    for (i = 0; i < m; i++) {
        if ((st = solve(c, &g->grid, h, N, cr[i][0], cr[i][1], cr[i][2], 0, F[i], NULL)) < 0)
            return st;
        *warn = worse(*warn, st);
    }
    if (!c->pb->richardson)
        return RR_OK;
    for (i = 0; i < m; i++) {
        if ((st = solve(c, &gf->grid, hf, N, cr[i][0], cr[i][1], cr[i][2], 1, Ff, NULL)) < 0)
            return st;
        *warn = worse(*warn, st);
        for (k = 0; k < 3; k++)
            F[i][k] = 2.0 * Ff[k] - F[i][k];
    }
    return RR_OK;
}

/* Node data of a solved node: centroid, moments, coefficients. */
typedef struct {
    double N, e, xc, yc, ab, K11, K22, K23, pen;
    rr_wheel_exact_result r;
} node_data;

/* The calibrated ellipse of a node: semi-axes a, b and the scales of cy
 * and the spin that give its exact K22, K23 (nonhertz_fast.calibrated_ellipse). */
static int calibrated(const rr_nh_call *c, const node_data *d, double *a, double *b, double *sy,
                      double *sp)
{
    rr_kalker_coeffs kc;
    double c2, cc;
    int st;
    if ((st = rr_kalker(d->ab, c->pb->nu, &kc)) < 0)
        return st;
    c2 = d->K11 / (c->G * kc.c11);
    cc = sqrt(c2);
    *a = cc * sqrt(d->ab);
    *b = cc / sqrt(d->ab);
    *sy = d->K22 / (c->G * c2 * kc.c22);
    *sp = d->K23 / (c->G * c2 * cc * kc.c23);
    return RR_OK;
}

/* The lowering of the largest load: rr_wheel_exact at Fz_max (the nodes'
 * scale; zero creepage). */
static int largest_lowering(rr_nh_call *c, double *e_max)
{
    const rr_nh_row_problem *pb = c->pb;
    rr_wheel_exact_problem we;
    rr_wheel_exact_result *r = &c->scratch;
    int st;
    node_problem(pb, pb->Fz_max, &we);
    st = rr_wheel_exact(&we, c->b.wex, c->b.wex_len, c->b.h, c->b.cells, NULL, 0, r);
    c->info->solves += r->passes;
    if (st < 0) {
        c->info->why = RR_NH_ROW_NODE;
        c->info->wheel_why = r->why;
        if (r->why == RR_WHEEL_EXACT_GAP)
            c->info->gap_why = r->patch.why;
        if (st == RR_ERR_WORKSPACE)
            c->info->need = (size_t)(r->patch.grid.mx > r->patch.grid.my ? r->patch.grid.mx
                                                                         : r->patch.grid.my);
        return st;
    }
    *e_max = r->lowered;
    return RR_OK;
}

/* The patch at lowering e (CONTACT's weighted plane at its own approach,
 * cover cov) and the load whose approach is the pose's interpenetration
 * (the exact normal solution at that pose): d->r's patch, sol, N. */
static int normal_at(rr_nh_call *c, double e, double N, double cov, node_data *d, int *edge, int *warn)
{
    const rr_nh_row_problem *pb = c->pb;
    const rr_nh_bufs *b = &c->b;
    const rr_nh_band *bd = c->bd;
    rr_wheel_exact_result *r = &d->r;
    rr_gap_site site;
    rr_gap_opts o;
    rr_exact_problem ep;
    rr_exact_field field;
    double a = e * cos(bd->delta);
    int it, st;
    memset(r, 0, sizeof *r);
    site.pair = pb->pair;
    site.y_ws = pb->y_ws;
    site.z = pb->pose0.z - (bd->g + e);
    site.roll = pb->pose0.roll;
    site.s_roller = bd->s_roller;
    site.s_wheel = bd->s_wheel;
    site.delta = bd->delta;
    rr_gap_opts_default(&o);
    o.n = pb->n;
    o.cover = cov;
    o.keep = 1;
    o.keep_lo = bd->lo;
    o.keep_hi = bd->hi;
    /* the plane at the pose's own interpenetration, its elements by
     * element_sizes (the region's extent: the first build's, square) */
    for (it = 0; it < 6; it++) {
        double dx, dy;
        o.approach = a;
        st = rr_gap_build(&site, &o, b->gap, b->gap_len, b->h, b->cells, &r->patch);
        if (st < 0)
            return rr_nh_grid_failed(c, st, &r->patch, 1);
        rr_nh_clip_band(bd, &r->patch, b->h);
        if (!(r->patch.pen > 0.0)) {
            c->info->why = RR_NH_ROW_GRID;
            return RR_ERR_GEOMETRY;
        }
        if (!element_sizes(&r->patch, pb->n, &dx, &dy))
            dx = dy = 0.0;               /* square: rr_gap's own from n (grid_at's) */
        if (fabs(r->patch.pen / a - 1.0) < 1e-3
            && (dx > 0.0 ? fabs(r->patch.grid.dx / dx - 1.0) < 1e-9
                               && fabs(r->patch.grid.dy / dy - 1.0) < 1e-9
                         : o.dx == 0.0))
            break;
        a = fabs(r->patch.pen / a - 1.0) < 1e-3 ? a : r->patch.pen;
        o.dx = dx;
        o.dy = dy;
    }
    if ((st = grid_fits(c, &r->patch, 1)) != RR_OK)
        return st;
    /* the load: N ~ approach^1.5, iterated until the approach is pen */
    memset(&ep, 0, sizeof ep);
    ep.grid = r->patch.grid;
    ep.h = b->h;
    ep.G = c->G;
    ep.nu = pb->nu;
    ep.mu = pb->mu;
    ep.spin_shift = 1.0 / 6.0;
    ep.tol = pb->tol;
    ep.maxit = pb->maxit;
    ep.interrupt = pb->interrupt;
    memset(&field, 0, sizeof field);
    field.pn = b->pn;
    field.state = b->state;
    for (it = 0; it < 40; it++) {
        ep.N = N;
        c->info->solves++;
        st = rr_exact_solve(&ep, b->wex, b->coarse_len, &r->sol, &field);
        if (st < 0) {
            c->info->why = RR_NH_ROW_SOLVE;
            return st;
        }
        *warn = worse(*warn, st);
        if (fabs(r->sol.delta / r->patch.pen - 1.0) < 1e-7)
            break;
        N *= pow(r->patch.pen / r->sol.delta, 1.5);
    }
    if (it == 40) {
        c->info->why = RR_NH_ROW_SOLVE;
        return RR_ERR_RANGE;
    }
    *edge = rr_exact_at_edge(b->state, r->patch.grid.mx, r->patch.grid.my);
    r->N = N;
    r->z = site.z;
    r->roll = site.roll;
    r->lowered = bd->g + e;
    r->approach = a;
    r->cover = cov;
    return RR_OK;
}

/* One node at lowering e: its normal solution, then the coefficients on
 * its grid (and a finer one). */
static int solve_node(rr_nh_call *c, int k, double e, double Nguess, double *p, node_data *d,
                      int *warn)
{
    const rr_nh_row_problem *pb = c->pb;
    const rr_nh_bufs *b = &c->b;
    rr_gap_patch gf;
    const rr_gap_patch *g = &d->r.patch;
    double sw = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0, vx, vy, Nt, cov = 1.3;
    double cr[3][3] = {{EPS_C, 0.0, 0.0}, {0.0, EPS_C, 0.0}, {0.0, 0.0, EPS_PHI}}, F[3][3];
    int i, j, st, edge = 1, grow;
    for (grow = 0; grow < 4 && edge; grow++, cov *= 1.4)
        if ((st = normal_at(c, e, Nguess, cov, d, &edge, warn)) < 0)
            return st;
    if (edge) {
        c->info->why = RR_NH_ROW_NODE;
        c->info->wheel_why = RR_WHEEL_EXACT_EDGE;
        return RR_ERR_RANGE;
    }
    (void)k;
    d->N = d->r.N;
    d->e = e;
    d->pen = g->pen;
    for (j = 0; j < g->grid.my; j++)
        for (i = 0; i < g->grid.mx; i++) {
            const double w = b->pn[(size_t)j * g->grid.mx + i];
            const double x = g->grid.x0 + i * g->grid.dx, y = g->grid.y0 + j * g->grid.dy;
            sw += w;
            sx += w * x;
            sy += w * y;
            sxx += w * x * x;
            syy += w * y * y;
        }
    d->xc = sx / sw;
    d->yc = sy / sw;
    vx = sxx / sw - d->xc * d->xc;
    vy = syy / sw - d->yc * d->yc;
    d->ab = vy > 0.0 && vx > 0.0 ? sqrt(vx / vy) : AB_HI;
    d->ab = d->ab < AB_LO ? AB_LO : d->ab > AB_HI ? AB_HI : d->ab;
    /* the linear coefficients (Richardson where asked) */
    if (pb->richardson
        && (st = grid_at(c, &d->r, pb->n, 0.5 * g->grid.dx, 0.5 * g->grid.dy, b->hf, 2, &gf)) < 0)
        return st;
    if ((st = forces(c, g, b->h, &gf, b->hf, d->N, (const double (*)[3])cr, 3, F, warn)) < 0)
        return st;
    /* spin about the centroid: at P cx = cphi yc, cy = -cphi xc; mz about it */
    {
        double K[3][3];
        for (i = 0; i < 3; i++) {
            K[i][0] = F[0][i] / EPS_C;
            K[i][1] = F[1][i] / EPS_C;
            K[i][2] = F[2][i] / EPS_PHI + d->yc * F[0][i] / EPS_C - d->xc * F[1][i] / EPS_C;
        }
        d->K11 = -K[0][0];
        d->K22 = -K[1][1];
        d->K23 = -K[1][2];
    }
    if (!(d->K11 > 0.0) || !(d->K22 > 0.0) || !isfinite(d->K23)) {
        c->info->why = RR_NH_ROW_COEFF;
        return RR_ERR_GEOMETRY;
    }
    Nt = cbrt(d->N);
    p[RR_NH_NODE(RR_NH_E, k)] = d->e;
    p[RR_NH_NODE(RR_NH_Q, k)] = d->N / (d->e * sqrt(d->e));
    p[RR_NH_NODE(RR_NH_PY, k)] = g->point[1];
    p[RR_NH_NODE(RR_NH_PZ, k)] = g->point[2];
    p[RR_NH_NODE(RR_NH_DELTA, k)] = g->delta;
    p[RR_NH_NODE(RR_NH_XC, k)] = d->xc;
    p[RR_NH_NODE(RR_NH_YC, k)] = d->yc;
    p[RR_NH_NODE(RR_NH_AREA, k)] = d->r.sol.area / (Nt * Nt);
    p[RR_NH_NODE(RR_NH_PMAX, k)] = d->r.sol.pmax / Nt;
    p[RR_NH_NODE(RR_NH_AB, k)] = d->ab;
    p[RR_NH_NODE(RR_NH_K11, k)] = d->K11;
    p[RR_NH_NODE(RR_NH_K22, k)] = d->K22;
    p[RR_NH_NODE(RR_NH_K23, k)] = d->K23;
    return RR_OK;
}

/* The correction at a node (its block cb, RR_NH_CORR_LEN doubles): the
 * exact forces about the centroid less the calibrated ellipse's, over mu N,
 * at zero creepage and on the polar grid, at the row's free-rolling spin. */
static int correct_node(rr_nh_call *c, const node_data *d, double *cb, int *warn)
{
    const rr_nh_row_problem *pb = c->pb;
    const rr_nh_bufs *b = &c->b;
    const rr_gap_patch *g = &d->r.patch;
    const int m = 1 + RR_NH_U * RR_NH_TH;
    const double muN = pb->mu * d->N;
    double kin[4], cr[1 + RR_NH_U * RR_NH_TH][3], cc[1 + RR_NH_U * RR_NH_TH][2];
    double F[1 + RR_NH_U * RR_NH_TH][3], a, bb, sy, sp, cphi;
    rr_gap_patch gc, gcf;
    rr_nh_frame fr;
    int i, j, st;
    rr_nonhertz_frame(g->point[1], g->point[2], g->delta, 0.0, (double)pb->pair->side,
                      pb->pair->R0, &fr);
    if ((st = rr_nonhertz_creepages(&pb->wheelset, pb->roller_spin, pb->pair->R0, &fr, d->pen,
                                    c->bd->g + d->e, pb->vmin, kin)) < 0)
        return st;
    cphi = kin[2];
    if ((st = calibrated(c, d, &a, &bb, &sy, &sp)) < 0)
        return st;
    cc[0][0] = cc[0][1] = 0.0;
    for (i = 0; i < RR_NH_U; i++)
        for (j = 0; j < RR_NH_TH; j++) {
            const double rho = rr_nh_corr_u[i] / (1.0 - rr_nh_corr_u[i]);
            const double th = j * (2.0 * RR_PI / RR_NH_TH);
            cc[1 + i * RR_NH_TH + j][0] = rho * cos(th) * muN / d->K11;
            cc[1 + i * RR_NH_TH + j][1] = rho * sin(th) * muN / d->K22;
        }
    for (i = 0; i < m; i++) {
        cr[i][0] = cc[i][0] + cphi * d->yc;
        cr[i][1] = cc[i][1] - cphi * d->xc;
        cr[i][2] = cphi;
    }
    if ((st = grid_at(c, &d->r, pb->n_corr, 0.0, 0.0, b->hc, 1, &gc)) < 0)
        return st;
    if (pb->richardson
        && (st = grid_at(c, &d->r, pb->n_corr, 0.5 * gc.grid.dx, 0.5 * gc.grid.dy, b->hcf, 2, &gcf))
               < 0)
        return st;
    if ((st = forces(c, &gc, b->hc, &gcf, b->hcf, d->N, (const double (*)[3])cr, m, F, warn))
        < 0)
        return st;
    cb[0] = d->e;
    for (i = 0; i < m; i++) {
        rr_contact_problem cp;
        rr_forces f;
        memset(&cp, 0, sizeof cp);
        cp.a = a;
        cp.b = bb;
        cp.N = d->N;
        cp.G = c->G;
        cp.nu = pb->nu;
        cp.cx = cc[i][0];
        cp.cy = sy * cc[i][1];
        cp.cphi = sp * cphi;
        cp.friction.mu0 = pb->mu;
        cp.friction.A = 1.0;
        if ((st = rr_exact_table_forces(&rr_exact_table_builtin, &cp, &f)) < 0)
            return st;
        /* the exact moment about the centroid */
        F[i][2] -= d->xc * F[i][1] - d->yc * F[i][0];
        cb[1 + 3 * i] = (F[i][0] - f.fx) / muN;
        cb[2 + 3 * i] = (F[i][1] - f.fy) / muN;
        cb[3 + 3 * i] = (F[i][2] - f.mz) / muN;
    }
    return RR_OK;
}

int rr_nonhertz_row(const rr_nh_row_problem *pb, double *work, size_t work_len, int side,
                    double *row, rr_nh_row_info *info)
{
    rr_nh_call c;
    size_t part[4], total;
    double *p;
    int k, j, st, warn = RR_OK, ci, nb = 1;
    double e_max;
    node_data d;
    rr_nh_band bd[RR_NH_MAX_PATCHES];

    if (!info)
        return RR_ERR_NULL;
    memset(info, 0, sizeof *info);
    info->node = info->patch = -1;
    if (!row)
        return RR_ERR_NULL;
    for (k = 0; k < RR_NH_ROW_LEN; k++)
        row[k] = NAN;
    if (!pb || !pb->pair || !work)
        return RR_ERR_NULL;
    {
        const double v[] = {pb->y_ws, pb->pose0.z, pb->pose0.roll, pb->Fz_max, pb->Fz_regions,
                            pb->E, pb->nu,
                            pb->mu, pb->roller_spin, pb->vmin, pb->combine, pb->tol,
                            pb->point.s_roller, pb->point.s_wheel, pb->point.delta,
                            pb->point.A, pb->point.B};
        if (!rr_all_finite(v, RR_COUNTOF(v)) || !rr_all_finite(pb->wheelset.c, 3)
            || !rr_all_finite(pb->wheelset.v, 3) || !rr_all_finite(pb->wheelset.w, 3))
            return RR_ERR_NONFINITE;
    }
    if (!(pb->Fz_max > 0.0) || !(pb->Fz_regions >= 0.0) || !(pb->Fz_regions <= pb->Fz_max))
        return RR_ERR_LOAD;
    if (pb->n < 8 || pb->n > RR_GAP_MAX_N / 2 || pb->n_corr < 8 || pb->n_corr > pb->n
        || (pb->richardson != 0 && pb->richardson != 1) || !(pb->combine >= 0.0))
        return RR_ERR_PARAM;
    if (!(total = lens(pb, side, part)))
        return RR_ERR_PARAM;
    if (work_len < total)
        return RR_ERR_WORKSPACE;
    memset(&c, 0, sizeof c);
    c.pb = pb;
    c.info = info;
    c.G = pb->E / (2.0 * (1.0 + pb->nu));
    c.b.wex = work;
    c.b.wex_len = part[0];
    c.b.coarse_len = rr_exact_workspace_len(side, side);
    c.b.fine_ex = work + part[0];
    c.b.fine_len = part[1];
    c.b.gap = c.b.fine_ex + part[1];
    c.b.gap_len = part[2];
    c.b.cells = (size_t)side * (size_t)side;
    c.b.side = side;
    c.b.h = c.b.gap + part[2];
    c.b.pn = c.b.h + c.b.cells;
    c.b.hf = c.b.pn + c.b.cells;
    c.b.hc = c.b.hf + 4 * c.b.cells;
    c.b.hcf = c.b.hc + c.b.cells;
    c.b.state = (signed char *)(c.b.hcf + 4 * c.b.cells);

    row[0] = pb->y_ws;
    row[2] = pb->pose0.z;
    row[3] = pb->pose0.roll;
    for (k = RR_NH_PATCH(0); k < RR_NH_ROW_LEN; k++)
        row[k] = 0.0;      /* a patch's place unused: zero */
    info->node = RR_NH_NODES - 1;
    if ((st = largest_lowering(&c, &e_max)) < 0 || (st = rr_nh_find_bands(&c, e_max, bd, &nb)) < 0) {
        for (k = 0; k < RR_NH_ROW_LEN; k++)
            row[k] = NAN;
        return st;
    }
    row[1] = nb;
    info->patches = nb;
    for (j = 0; j < nb; j++) {
        const double span = e_max - bd[j].g;
        c.bd = &bd[j];
        p = row + RR_NH_PATCH(j);
        p[0] = bd[j].g;
        info->patch = j;
        ci = 0;
        for (k = 0; k < RR_NH_NODES; k++) {
            info->node = k;
            st = solve_node(&c, k, node_f[k] * span,
                            pb->Fz_max * pow(node_f[k] * span / e_max, 1.5) / cos(bd[j].delta),
                            p, &d, &warn);
            if (st >= 0 && ci < RR_NH_CORR && k == corr_node[ci]) {
                st = correct_node(&c, &d, p + RR_NH_CORR_AT(ci), &warn);
                ci++;
            }
            if (st < 0) {
                for (k = 0; k < RR_NH_ROW_LEN; k++)
                    row[k] = NAN;
                return st;
            }
        }
    }
    info->patch = -1;
    info->node = -1;
    return warn;
}
