/*
 * rr_wheel_exact.c - one wheel of the rig by the exact theory on its own
 * patch (rr_wheel_exact.h): rollerrig/rig/exact.py's rig_exact, its steps
 * in the same order, each patch built by rr_gap_build and solved by
 * rr_exact_solve_from on one workspace (the kernel spectra of a grid are
 * built once for every solve on it), each solve after the first from the
 * last one's solution.
 */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "contact/rr_hertz.h"
#include "geometry/rr_wheel_exact.h"

/* The balance of the vertical load: its iterations, the grid's rebuilds
 * when the contact reaches its edge (rig_exact's), and the least tolerance
 * of the balance, relative to Fz.  The balance is held to the solver's own
 * tolerance tol (at least FZ_TOL): fy, which sets it, is known to no
 * better, and a balance ten times tighter than the default tol (1e-7, as
 * before, and still on cold starts: the doubles before) cost the secant a
 * step on most cases.  At tol = 1e-6: the 72 cases' forces moved by 2e-6
 * mu N at most, their departures from CONTACT's the same to the digits
 * shown (stop 36). */
#define FZ_TOL 1e-7
#define FZ_ITER 30
#define EDGE_REBUILDS 4
/* A grid is rebuilt at the pose of the load found where the approach found
 * differs from the one it was built for by more than this (relative).  On
 * CONTACT's 72 roller cases (0.4 mm) the coarse pass's approach is within
 * 1 % of the one found in all but 3: keeping the grid saved the rebuild,
 * its patch and one or two solves, and moved the forces by 2.8e-4 mu N at
 * most (median 4e-6), their largest departures from CONTACT's not at all
 * (1.07e-3 mu N on S1002; 7.4e-5 before, 7.0e-5 after on MiniProf; areas
 * and peak pressures the same maxima).  Elements from n, sized by the
 * grid's extent at its approach, were rebuilt whatever until stop 36: kept
 * within the same 1 %, their size is within 0.5 % of the rebuilt one's,
 * the same n across, and on the 72 cases (n = 40) the forces moved by
 * 1.2e-3 mu N at most (median 3e-5; the grid's own distance from the
 * continuum is 0.01-0.02), the departures from CONTACT's the same (p95
 * 0.0040 / 0.0095 mu N, max 0.0049 / 0.0140 on MiniProf / S1002), for a
 * third fewer instructions. */
#define REBUILD_TOL 0.01
/* A grid to be rebuilt (the approach moved beyond REBUILD_TOL) is left
 * once the balance on it is within this of Fz (relative), not settled to
 * the tolerance: the rebuilt grid's pose is then within 0.1 % of the
 * load's, and the secant goes on from there.  On CONTACT's flange cases
 * at 5.5 mm on S1002 (N 10 % below its first estimate) 8-9 solves became
 * 7; the 72 cases' forces moved by 2.3e-5 mu N at most (0.4 mm; 7e-6 on
 * n = 40), their departures from CONTACT's by as much (S1002 max
 * 1.066e-3 -> 1.092e-3 mu N).  At 1e-2, 6 solves, but 1.39e-3. */
#define EARLY_TOL 1e-3
/* The solver's tolerance on a warm start, times the caller's: from within a
 * Newton step of the answer a warm solve stops just under the tolerance,
 * where a cold one's last step overshoots it, so the final warm solution
 * stood up to 1.3 tol from its patch's cold solve in the spin moment
 * (tests/test_exact_warm.py, MiniProf at 3.5 mm on n = 40, after the
 * coarse pass's samples changed its path); at half the tolerance 0.54 at
 * most on those cases, for 2 % more instructions (callgrind, 12 cases). */
#define WARM_TOL 0.5
/* The tolerance of the loaded grid's first solve on a vertical load (warm
 * starts): the secant moves N from it at once, and only its fy is used (to
 * 1e-3, its step's slope to as much), so its last Newton steps were spent
 * for nothing; the secant's solves that follow are at the tolerance, and a
 * balance found on the loose one is solved again.  At 1e-4 against the
 * caller's tolerance: 12 profiled cases 9 % fewer instructions, the same
 * solves; then 1e-3 took more secant steps.  Since the secant's steps start
 * from the last two solutions extrapolated and solve the normal problem on
 * the contact's box (stop 34), 1e-3 pays (stop 35): every sixth case 331.3
 * -> 318.0 M instructions on 0.4 mm (the C call 8 % faster a case alone),
 * 460.7 -> 455.7 M on n = 40, the 72 in turn 1543.3 -> 1513.5 M, with 4 %
 * more solves; forces within 5.0e-6 mu N of 1e-4's (3.0e-6 on n = 40).
 * 5e-4 fell between (323.7, 454.3, 1516.5 M). */
#define LOOSE_TOL 1e-3
/* The coarse pass's profile samples' spacing [m] (RR_GAP_SAMPLE's 4 times):
 * its patch cost as much as the loaded one's (the windows' samples,
 * sections and lateral scan do not depend on the grid); at 4 times the
 * spacing the 12 profiled cases took 8 % fewer instructions, and CONTACT's
 * 72 cases' forces moved by 2.5e-6 mu N at most (their departures from
 * CONTACT's the same maxima). */
#define COARSE_SAMPLE (4.0 * RR_GAP_SAMPLE)
/* The loaded grid's cover of the coarse pass's approach (it holds every
 * element h reaches the approach at while the approach found is within it;
 * beyond it the grid is built again, 1.3 times).  Elements of given size
 * stand on the same lattice whatever the cover, so a tighter one changes
 * no element of the contact, only the exterior: at 1.03 instead of 1.1
 * CONTACT's 72 roller cases took 3.5 % fewer instructions (12 profiled
 * cases), the same solves, forces within 6e-13 mu N.  Elements from n are
 * sized by the grid's extent, so their cover stays 1.1 (the doubles before). */
#define GIVEN_COVER 1.03

void rr_wheel_exact_default(rr_wheel_exact_problem *pb)
{
    if (!pb)
        return;
    memset(pb, 0, sizeof *pb);
    pb->E = 2.1e11;
    pb->nu = 0.28;
    pb->creep_given = 1;
    pb->vmin = 1e-3;
    rr_gap_opts_default(&pb->gap);
    pb->z = pb->roll = NAN;
    pb->loaded = 1;
    pb->passes = 2;
    pb->tol = 1e-6;
    pb->maxit = 5000;
    pb->spin_shift = 1.0 / 6.0;
}

/* Doubles of the contact-state scratch for cells elements (bytes). */
static size_t state_len(size_t cells)
{
    return cells / sizeof(double) + 1;
}

/* Doubles of the last solution (pn, px, py), of its map onto the next
 * grid, and of the solution before it, for cells elements. */
static size_t warm_len(size_t cells)
{
    return 9 * cells;
}

/* The solvers' share of the workspace: the loaded grids' (ex, for grids
 * up to the caller's size) and a third more for the coarse pass's (a
 * quarter of the share), each grid's spectra kept in its own from call to
 * call (the grids of a sweep's next case have the same sizes more often
 * than not: on CONTACT's 72 roller cases in turn, the coarse pass's 53
 * times, the loaded grid's 51); one double after them says whether the
 * coarse share was written over. */
static size_t solvers_len(size_t ex)
{
    return ex + (ex + 2) / 3 + 1;
}

size_t rr_wheel_exact_workspace_len(const rr_wheel_exact_problem *pb, int mx, int my)
{
    size_t ex, gw, cells = (size_t)mx * (size_t)my;
    if (!pb || !(ex = rr_exact_workspace_len(mx, my)) || !(gw = rr_gap_workspace_len(&pb->gap)))
        return 0;
    return solvers_len(ex) + warm_len(cells) + state_len(cells) + gw + 1;
}

/* The call's state: the problem, its buffers carved from the caller's, the
 * result being filled. */
typedef struct {
    const rr_wheel_exact_problem *pb;
    double *exact, *gap;          /* the solvers' workspace (at the start), the gap's */
    size_t exact_len, gap_len;    /* exact: the loaded grids' share (main_len), the coarse
                                     pass's (coarse_len) after it, its flag, all */
    size_t main_len, coarse_len;
    double *coarse_dirty;         /* 1: the coarse share's memory last held a grid too large
                                     for its own share (it takes all); 0: the coarse pass's */
    signed char *state;           /* the contact's state, for the grid's edge */
    double *last, *mapped;        /* the last solution's pn, px, py (cells each), and
                                     those mapped onto a new grid */
    int have_last, last_normal;   /* a last solution; one of the normal problem alone */
    double *prev;                 /* the solution before it (pn, px, py), where prev_N is
                                     not NaN: on the same patch, at the load prev_N */
    double last_N, prev_N;
    int loose;                    /* solves at LOOSE_TOL (the load's first, on Fz) */
    rr_gap_patch last_patch;      /* its grid and frame */
    double *h;
    size_t cells;                 /* capacity of h, the state and the caller's fields */
    const rr_exact_field *field;
    double estar, G, z0, roll0, delta0;
    rr_wheel_exact_result *res;
} call;

/* The patch for load N: n elements across (coarse: elements twice dx, dy),
 * approach a (0: Hertz's at the contact point for N), cover cov, the
 * reference ref, at the loaded pose (lower) or the zero-gap one. */
static int build(call *c, double N, int n, double a, double cov, int ref, int lower,
                 int coarse, rr_gap_patch *p)
{
    const rr_wheel_exact_problem *pb = c->pb;
    rr_gap_site site;
    rr_gap_opts o = pb->gap;
    int st;
    if (!(a > 0.0)) {
        rr_hertz_result hz;
        if ((st = rr_hertz(pb->point.A, pb->point.B, N, c->estar, &hz)) != RR_OK) {
            c->res->why = RR_WHEEL_EXACT_HERTZ;
            c->res->fail_pass = coarse;
            c->res->fail_N = N;
            return st;
        }
        a = hz.delta;
    }
    site.pair = pb->pair;
    site.y_ws = pb->y_ws;
    site.z = isnan(pb->z) ? (lower ? c->z0 - a / cos(c->delta0) : c->z0) : pb->z;
    site.roll = isnan(pb->roll) ? c->roll0 : pb->roll;
    site.s_roller = pb->point.s_roller;
    site.s_wheel = pb->point.s_wheel;
    site.delta = pb->point.delta;
    o.n = n;
    o.approach = a;
    o.cover = cov;
    o.reference = ref;
    if (coarse) {
        o.dx *= 2.0;
        o.dy *= 2.0;
    }
    if (coarse && !pb->cold_start) {
        /* its approach alone is used, to within REBUILD_TOL: profile samples
         * COARSE_SAMPLE apart (a tenth of its elements where given and
         * smaller), not the loaded grid's, which made this patch as dear as
         * the loaded one (the windows' samples, sections and scan); cold
         * starts keep the samples before (the doubles before) */
        o.sample = o.dx > 0.0 && o.dy > 0.0 ? fmin(COARSE_SAMPLE, 0.1 * fmin(o.dx, o.dy))
                                             : COARSE_SAMPLE;
        o.sample = fmax(o.sample, RR_GAP_SAMPLE_MIN);
    }
    c->res->builds++;
    st = rr_gap_build(&site, &o, c->gap, c->gap_len, c->h, c->cells, p);
    if (st < 0) {
        c->res->why = RR_WHEEL_EXACT_GAP;
        c->res->fail_pass = coarse;
        c->res->fail_N = N;
        if (st == RR_ERR_WORKSPACE && p->why == RR_GAP_H_BUFFER)
            c->res->need = rr_wheel_exact_workspace_len(pb, p->grid.mx, p->grid.my);
        return st;
    }
    c->res->z = site.z;
    c->res->roll = site.roll;
    c->res->lowered = c->z0 - site.z;
    c->res->approach = a;
    c->res->cover = cov;
    return RR_OK;
}

/* Kalker's creepages of patch p (rig_exact's _creepages): the slip of the
 * wheel's material point at p->wheel_point (the wheelset's centre lowered
 * with the pose) relative to the roller's at P, over the rolling speed. */
static int creepages(const call *c, const rr_gap_patch *p, double k[4])
{
    const rr_wheel_exact_problem *pb = c->pb;
    const rr_motion *m = &pb->wheelset;
    const double wr[3] = {0.0, -pb->roller_spin, 0.0};
    double r[3], vw[3], vr[3], s[3], sum[3], dw[3];
    int i;
    for (i = 0; i < 3; i++)
        r[i] = p->wheel_point[i] - (i == 2 ? m->c[2] - c->res->lowered : m->c[i]);
    rr_cross3(m->w, r, vw);
    for (i = 0; i < 3; i++) {
        vw[i] += m->v[i];
        r[i] = p->point[i] - (i == 2 ? -pb->pair->R0 : 0.0);
    }
    rr_cross3(wr, r, vr);
    for (i = 0; i < 3; i++) {
        sum[i] = vw[i] + vr[i];
        s[i] = vw[i] - vr[i];
        dw[i] = m->w[i] - wr[i];
    }
    k[3] = fmax(fabs(rr_dot3(sum, p->t1)) / 2.0, pb->vmin);
    k[0] = rr_dot3(s, p->t1) / k[3];
    k[1] = rr_dot3(s, p->t2) / k[3];
    k[2] = rr_dot3(dw, p->n) / k[3];
    if (!rr_all_finite(k, 4)) {
        c->res->why = RR_WHEEL_EXACT_CREEP;
        return RR_ERR_RANGE;
    }
    return RR_OK;
}

/* The last solution at the element centres of patch p, which may lie on
 * another grid and frame (a rebuild, the coarse pass's): the same points
 * of the rig (in the patch's plane) interpolated bilinearly between the
 * last grid's centres, 0 beyond them.  Only a start (the solver converges
 * from any): its pressure's shape and contact set need only be near.
 * Returns the elements of positive pressure. */
static int map_last(call *c, const rr_gap_patch *p)
{
    const rr_gap_patch *q = &c->last_patch;
    const rr_grid *g = &p->grid, *o = &q->grid;
    const size_t n0 = (size_t)o->mx * (size_t)o->my;
    double *pn = c->mapped, *px = pn + c->cells, *py = px + c->cells;
    const double *l = c->last;
    int i, j, k, positive = 0;
    for (j = 0; j < g->my; j++)
        for (i = 0; i < g->mx; i++) {
            const double x = g->x0 + i * g->dx, y = g->y0 + j * g->dy;
            double r[3], u, v, fu, fv, w[4], acc[3] = {0.0, 0.0, 0.0};
            long iu, iv;
            int near = 0;
            const size_t e = (size_t)j * g->mx + i;
            for (k = 0; k < 3; k++)
                r[k] = p->point[k] + x * p->t1[k] + y * p->t2[k] - q->point[k];
            u = (rr_dot3(r, q->t1) - o->x0) / o->dx;
            v = (rr_dot3(r, q->t2) - o->y0) / o->dy;
            if (u > -1.0 && v > -1.0 && u < o->mx && v < o->my) {
                iu = (long)floor(u);
                iv = (long)floor(v);
                fu = u - iu;
                fv = v - iv;
                w[0] = (1.0 - fu) * (1.0 - fv);
                w[1] = fu * (1.0 - fv);
                w[2] = (1.0 - fu) * fv;
                w[3] = fu * fv;
                for (k = 0; k < 4; k++) {
                    const long a = iu + (k & 1), b = iv + (k >> 1);
                    size_t m;
                    if (a < 0 || b < 0 || a >= o->mx || b >= o->my)
                        continue;
                    m = (size_t)b * o->mx + (size_t)a;
                    acc[0] += w[k] * l[m];
                    acc[1] += w[k] * l[m + n0];
                    acc[2] += w[k] * l[m + 2 * n0];
                }
                /* in contact where the nearest last element was: an
                 * element brought in by the interpolation's reach alone
                 * would leave the contact set again, each a restart of the
                 * normal solver */
                iu += fu >= 0.5;
                iv += fv >= 0.5;
                near = iu >= 0 && iv >= 0 && iu < o->mx && iv < o->my
                       && l[(size_t)iv * o->mx + (size_t)iu] > 0.0;
            }
            pn[e] = near && acc[0] > 0.0 ? acc[0] : 0.0;
            px[e] = acc[1];
            py[e] = acc[2];
            positive += pn[e] > 0.0;
        }
    return positive;
}

/* The start of a solve at load N on the last solution's patch where the
 * one before was solved there too (the load's secant, whose steps shrink):
 * the two solutions extrapolated to N, element by element (the pressure
 * kept >= 0), into mapped (n elements a field).  The last step's start
 * from the last solution alone is off by the load's change, which the
 * solvers then iterate away (3 to 6 products); extrapolated, it is off by
 * that change's square and by the solution before's tolerance times the
 * steps' ratio.  0 where there are not two solutions or the step is
 * longer than the last (no extrapolation: the last solution as it is). */
static int extrapolate(call *c, size_t n, double N)
{
    const double *l = c->last, *q = c->prev;
    double *o = c->mapped, r;
    size_t k;
    if (isnan(c->prev_N) || c->last_N == c->prev_N)
        return 0;
    r = (N - c->last_N) / (c->last_N - c->prev_N);
    if (!(fabs(r) <= 1.0))
        return 0;
    for (k = 0; k < n; k++) {
        const double v = l[k] + r * (l[k] - q[k]);
        o[k] = v > 0.0 && l[k] > 0.0 ? v : 0.0;
    }
    for (k = n; k < 3 * n; k++)
        o[k] = l[k] + r * (l[k] - q[k]);
    return 1;
}

/* 1 where patch p has the last solution's grid and frame (the load's
 * iteration on one patch): the start is that solution as it is. */
static int same_patch(const rr_gap_patch *a, const rr_gap_patch *b)
{
    return memcmp(&a->grid, &b->grid, sizeof a->grid) == 0
           && memcmp(a->point, b->point, sizeof a->point) == 0
           && memcmp(a->t1, b->t1, sizeof a->t1) == 0 && memcmp(a->t2, b->t2, sizeof a->t2) == 0;
}

/* Patch p solved for load N: its creepages, the solver; *edge where the
 * contact reaches the grid's border (taken: it sizes the next grid).
 * normal_only: the creepages zero (the first pass, whose approach alone is
 * used: the normal problem does not depend on them, and with none the
 * tangential one is p = 0 at once). */
static int solve(call *c, const rr_gap_patch *p, double N, int normal_only, int *edge)
{
    const rr_wheel_exact_problem *pb = c->pb;
    rr_wheel_exact_result *res = c->res;
    rr_exact_problem ep;
    rr_exact_field f;
    rr_exact_start start;
    double k[4] = {pb->cx, pb->cy, pb->cphi, 0.0}, *work;
    size_t n, need, work_len;
    int st, warm, same = 0;
    if (normal_only)
        k[0] = k[1] = k[2] = 0.0;
    else if (!pb->creep_given && (st = creepages(c, p, k)) != RR_OK)
        return st;
    memset(&ep, 0, sizeof ep);
    ep.grid = p->grid;
    ep.h = c->h;
    ep.N = N;
    ep.G = c->G;
    ep.nu = pb->nu;
    ep.mu = pb->mu;
    ep.cx = k[0];
    ep.cy = k[1];
    ep.cphi = k[2];
    ep.spin_shift = pb->spin_shift;
    ep.tol = pb->tol;
    ep.maxit = pb->maxit;
    ep.interrupt = pb->interrupt;
    res->cx = k[0];
    res->cy = k[1];
    res->cphi = k[2];
    res->V = k[3];
    res->N = N;
    res->passes++;
    need = rr_exact_workspace_len(p->grid.mx, p->grid.my);
    if (need > c->exact_len) {
        res->need = rr_wheel_exact_workspace_len(pb, p->grid.mx, p->grid.my);
        res->why = RR_WHEEL_EXACT_SOLVE;
        return RR_ERR_WORKSPACE;
    }
    /* the coarse pass in its share, the loaded grids in theirs, each
     * keeping its spectra for the next call; a grid too large for its
     * share takes all.  That grid and the coarse pass then write over each
     * other's numbers (its box lies from the middle of all), not always
     * over their keys: whichever comes after the other forgets what its
     * memory kept */
    if (normal_only && need <= c->coarse_len) {
        work = c->exact + c->main_len;
        work_len = c->coarse_len;
        if (*c->coarse_dirty != 0.0) {
            rr_exact_workspace_forget(work, work_len);
            *c->coarse_dirty = 0.0;
        }
    } else {
        work = c->exact;
        work_len = need <= c->main_len ? c->main_len : c->exact_len;
        if (work_len > c->main_len && *c->coarse_dirty == 0.0) {
            rr_exact_workspace_forget(work, work_len);
            *c->coarse_dirty = 1.0;
        }
    }
    /* the solution's pn, px, py into last (the next solve's start; the
     * caller's field gets the final one's), its slip to the caller's */
    memset(&f, 0, sizeof f);
    if (c->field)
        f = *c->field;
    n = (size_t)p->grid.mx * (size_t)p->grid.my;
    f.pn = c->last;
    f.px = c->last + n;
    f.py = c->last + 2 * n;
    f.state = c->state;
    memset(&start, 0, sizeof start);
    start.mx = p->grid.mx;
    start.my = p->grid.my;
    if (!c->have_last || c->last_normal || pb->cold_start) {
        /* nothing to start from, or the coarse pass's pressure: on elements
         * twice as large, its contact set and shape are farther from this
         * grid's solution than the solver's own start from h (measured on
         * the 72 cases: 19 to 23 products against 13 to 16) */
        warm = 0;
    } else if ((same = same_patch(p, &c->last_patch))) {
        start.pn = f.pn;              /* read before the solver writes the field */
        start.px = f.px;
        start.py = f.py;
        warm = 1;
        if (extrapolate(c, n, N)) {
            start.pn = c->mapped;
            start.px = c->mapped + n;
            start.py = c->mapped + 2 * n;
        }
    } else {
        warm = map_last(c, p) > 0;
        start.pn = c->mapped;
        start.px = c->mapped + c->cells;
        start.py = c->mapped + 2 * c->cells;
    }
    if (c->loose && !normal_only)
        ep.tol = fmax(pb->tol, LOOSE_TOL);
    else if (warm)
        ep.tol = pb->tol * WARM_TOL;
    /* the last solution becomes the one before, where the next solve may
     * take both (the same patch, the creepages the same) */
    c->prev_N = NAN;
    if (same && !normal_only) {
        memcpy(c->prev, c->last, 3 * n * sizeof *c->prev);
        c->prev_N = c->last_N;
    }
    st = rr_exact_solve_from(&ep, warm ? &start : NULL, work, work_len, &res->sol, &f);
    c->have_last = 0;
    if (st < 0) {
        res->why = RR_WHEEL_EXACT_SOLVE;
        res->fail_N = N;
        return st;
    }
    c->have_last = 1;
    c->last_normal = normal_only;
    c->last_patch = *p;
    c->last_N = N;
    *edge = rr_exact_at_edge(c->state, p->grid.mx, p->grid.my);
    return st;
}

/* The worse of two statuses (errors before warnings). */
static int worse(int a, int b)
{
    return a < 0 || b < 0 ? (a < b ? a : b) : (a > b ? a : b);
}

/* Whether the approach found moved beyond REBUILD_TOL from the one the
 * grid was built for (the grid is then rebuilt at the load found). */
static int approach_moved(const rr_wheel_exact_result *res)
{
    return !(fabs(res->sol.delta / res->approach - 1.0) <= REBUILD_TOL);
}

/* The cover of a loaded grid built from an approach found. */
static double loaded_cover(const rr_wheel_exact_problem *pb)
{
    return pb->gap.dx > 0.0 && pb->gap.dy > 0.0 ? GIVEN_COVER : 1.1;
}

/* Patch, solution and creepages for the normal load N (rig_exact's at());
 * a: an estimate of the approach (0: find it). */
static int at(call *c, double N, double a, rr_gap_patch *p, int *warn)
{
    const rr_wheel_exact_problem *pb = c->pb;
    const int n = pb->gap.n;
    const int first_ref = pb->gap.reference == RR_GAP_WEIGHTED ? RR_GAP_POINT : pb->gap.reference;
    double cov = loaded_cover(pb);
    int st, edge, k;
    if (!(a > 0.0)) {
        if (pb->passes == 2) {
            if ((st = build(c, N, n / 2 > 4 ? n / 2 : 4, pb->gap.approach, pb->gap.cover,
                            first_ref, 0, 1, p)) < 0
                || (st = solve(c, p, N, 1, &edge)) < 0)
                return st;
            *warn = worse(*warn, st);
            a = c->res->sol.delta;
        } else {
            a = pb->gap.approach;            /* 0: Hertz's, in build */
            cov = pb->gap.cover;
        }
    }
    if ((st = build(c, N, n, a, cov, pb->gap.reference, pb->loaded, 0, p)) < 0
        || (st = solve(c, p, N, 0, &edge)) < 0)
        return st;
    *warn = worse(*warn, st);
    /* the contact lies where h <= the approach found: a grid that covers
     * less, or a contact that reaches the grid's edge, is solved again */
    for (k = 0; k < EDGE_REBUILDS; k++) {
        if (!(edge || c->res->sol.delta > c->res->approach * c->res->cover))
            return RR_OK;
        if ((st = build(c, N, n, c->res->sol.delta, 1.3, pb->gap.reference, pb->loaded, 0, p))
            < 0 || (st = solve(c, p, N, 0, &edge)) < 0)
            return st;
        *warn = worse(*warn, st);
    }
    if (!(edge || c->res->sol.delta > c->res->approach * c->res->cover))
        return RR_OK;
    c->res->why = RR_WHEEL_EXACT_EDGE;
    return RR_ERR_RANGE;
}

/* The first step of the load's secant from the solution at N: Newton's on
 * r(N) = (Fz - fy(N) t2z) / nz - N with fy's slope from its utilisation
 * f = |F| / (mu N) as in the Hertzian creep curve of the exact theory's
 * simplified form (Vermeulen-Johnson's 1 - (1 - k)^3, k ~ N^(-1/3) at a
 * given creepage): d ln fy / d ln N = 1 - k (1 - k)^2 / f, 2/3 at small
 * creepage, 1 in full slip.  Only a start for the secant (which converges
 * from any); before, the step was r itself (the slope 0), which left the
 * second step a tenth of the first on flange contact. */
static double first_step(const rr_wheel_exact_problem *pb, const rr_wheel_exact_result *res,
                         const rr_gap_patch *p, double N, double r)
{
    const double f = fmin(hypot(res->sol.fx, res->sol.fy) / (pb->mu * N), 1.0);
    const double k = 1.0 - cbrt(1.0 - f);
    const double slope = f > 0.0 ? 1.0 - k * (1.0 - k) * (1.0 - k) / f : 2.0 / 3.0;
    const double d = 1.0 + slope * res->sol.fy * p->t2[2] / (p->n[2] * N);
    return isfinite(d) && d > 0.2 ? r / d : r;
}

/* What a caller can get wrong in the problem (the gap's options are
 * rr_gap_build's to judge, at the first build). */
static int check_problem(const rr_wheel_exact_problem *pb)
{
    const rr_contact_point *q = &pb->point;
    const double v[] = {pb->y_ws, pb->pose0.z, pb->pose0.roll, pb->N, pb->Fz, pb->E, pb->nu,
                        pb->mu, pb->vmin, q->s_roller, q->s_wheel, q->delta, q->A, q->B,
                        pb->tol, pb->spin_shift};
    const double creep[] = {pb->cx, pb->cy, pb->cphi};
    const double motion[] = {pb->wheelset.c[0], pb->wheelset.c[1], pb->wheelset.c[2],
                             pb->wheelset.v[0], pb->wheelset.v[1], pb->wheelset.v[2],
                             pb->wheelset.w[0], pb->wheelset.w[1], pb->wheelset.w[2],
                             pb->roller_spin};
    if (!rr_all_finite(v, RR_COUNTOF(v))
        || (pb->creep_given ? !rr_all_finite(creep, 3) : !rr_all_finite(motion, 10))
        || (!isnan(pb->z) && !isfinite(pb->z)) || (!isnan(pb->roll) && !isfinite(pb->roll)))
        return RR_ERR_NONFINITE;
    if ((pb->N > 0.0) == (pb->Fz > 0.0) || pb->N < 0.0 || pb->Fz < 0.0)
        return RR_ERR_LOAD;
    if (!(pb->E > 0.0) || !(pb->nu >= 0.0 && pb->nu <= 0.5) || !isfinite(rr_estar(pb->E, pb->nu,
                                                                                  pb->E, pb->nu)))
        return RR_ERR_MATERIAL;
    if (!(pb->mu > 0.0))
        return RR_ERR_FRICTION;
    if (!(pb->vmin > 0.0))
        return RR_ERR_SPEED;
    if ((pb->passes != 1 && pb->passes != 2) || (pb->loaded != 0 && pb->loaded != 1)
        || (pb->creep_given != 0 && pb->creep_given != 1) || !(fabs(q->delta) < 0.5 * RR_PI)
        || !(pb->gap.approach >= 0.0))
        return RR_ERR_PARAM;
    return RR_OK;
}

static void result_init(rr_wheel_exact_result *res)
{
    memset(res, 0, sizeof *res);
    res->sol.fx = res->sol.fy = res->sol.mz = res->sol.fn = res->sol.delta = NAN;
    res->sol.area = res->sol.pmax = res->sol.normal_residual = res->sol.tang_residual = NAN;
    res->cx = res->cy = res->cphi = res->V = res->N = res->fail_N = NAN;
    res->force[0] = res->force[1] = res->force[2] = NAN;
    res->z = res->roll = res->lowered = res->approach = res->cover = NAN;
    res->patch.grid.dx = res->patch.grid.dy = NAN;
}

/* The failed call's numbers NaN (the why, the grid and the need kept). */
static int failed(rr_wheel_exact_result *res, int st)
{
    res->sol.fx = res->sol.fy = res->sol.mz = res->sol.fn = NAN;
    res->force[0] = res->force[1] = res->force[2] = NAN;
    return st;
}

int rr_wheel_exact(const rr_wheel_exact_problem *pb, double *work, size_t work_len, double *h,
                   size_t h_len, const rr_exact_field *field, size_t field_len,
                   rr_wheel_exact_result *res)
{
    rr_gap_patch *p;
    call c;
    int st, warn = RR_OK, k, it;
    double N;

    if (!res)
        return RR_ERR_NULL;
    result_init(res);
    if (!pb || !pb->pair || !work || !h)
        return RR_ERR_NULL;
    if ((st = check_problem(pb)) != RR_OK)
        return st;
    memset(&c, 0, sizeof c);
    c.pb = pb;
    c.res = res;
    c.field = field;
    c.h = h;
    c.cells = h_len < field_len || !field ? h_len : field_len;
    c.estar = rr_estar(pb->E, pb->nu, pb->E, pb->nu);
    c.G = pb->E / (2.0 * (1.0 + pb->nu));
    c.z0 = pb->pose0.z;
    c.roll0 = pb->pose0.roll;
    c.delta0 = pb->point.delta;
    /* the workspace: the solver's at its start (where it keeps its spectra
     * from call to call), the contact state, the gap's, and at the end how
     * the last call carved it */
    c.gap_len = rr_gap_workspace_len(&pb->gap);
    if (!c.gap_len) {
        res->why = RR_WHEEL_EXACT_GAP;
        return RR_ERR_PARAM;
    }
    if (work_len < c.gap_len + state_len(c.cells) + warm_len(c.cells) + 3) {
        res->need = c.gap_len + state_len(c.cells) + warm_len(c.cells)
                    + solvers_len(rr_exact_workspace_len(1, 1)) + 1;
        return RR_ERR_WORKSPACE;
    }
    c.gap = work + (work_len - 1 - c.gap_len);
    c.state = (signed char *)(c.gap - state_len(c.cells));
    c.last = c.gap - state_len(c.cells) - warm_len(c.cells);
    c.mapped = c.last + 3 * c.cells;
    c.prev = c.last + 6 * c.cells;
    c.prev_N = NAN;
    c.exact = work;
    c.exact_len = work_len - 1 - c.gap_len - state_len(c.cells) - warm_len(c.cells) - 1;
    c.coarse_dirty = work + c.exact_len;
    c.coarse_len = (c.exact_len + 3) / 4;
    c.main_len = c.exact_len - c.coarse_len;
    if (work[work_len - 1] != (double)c.exact_len) {
        /* carved otherwise than by the last call (h and fields of another
         * length move the shares): that call's scratch may lie on the
         * shares' kept spectra and not on their keys, so nothing kept is
         * trusted (a pool of workspaces, three threads, S1002's flange
         * after its tread: the tread case's coarse spectra half written
         * over, the solve not converged, until stop 37) */
        rr_exact_workspace_forget(c.exact, c.main_len);
        rr_exact_workspace_forget(c.exact + c.main_len, c.coarse_len);
        *c.coarse_dirty = 0.0;
        work[work_len - 1] = (double)c.exact_len;
    }
    p = &res->patch;

    if (pb->N > 0.0) {
        N = pb->N;
        st = at(&c, N, 0.0, p, &warn);
    } else {
        /* vertical balance: Fz = N n_z + fy t2_z (t1 is horizontal), by the
         * secant method on N on a fixed grid, then once more on the grid
         * and pose of the load found */
        const double ftol = (pb->cold_start ? FZ_TOL : fmax(pb->tol, FZ_TOL)) * pb->Fz;
        N = pb->Fz / cos(c.delta0);
        c.loose = !pb->cold_start;
        st = at(&c, N, 0.0, p, &warn);
        for (k = 0; k < 2 && st >= 0; k++) {
            double lastN = NAN, lastr = NAN;
            int edge;
            if (k == 1) {
                /* a grid built for an approach within REBUILD_TOL of the one
                 * found is the pose of the load found's; elements from n
                 * also need the cover a rebuild would take (they are sized
                 * by it: a grid rebuilt at the contact's edge, cover 1.3,
                 * has them 5 % larger); cold starts are rebuilt whatever
                 * (the doubles before) */
                const int given = pb->gap.dx > 0.0 && pb->gap.dy > 0.0;
                if (!pb->cold_start && (given || res->cover == loaded_cover(pb))
                    && !approach_moved(res))
                    break;
                if ((st = at(&c, N, res->sol.delta, p, &warn)) < 0)
                    break;
            }
            for (it = 0; it < FZ_ITER; it++) {
                const double r = (pb->Fz - res->sol.fy * p->t2[2]) / p->n[2] - N;
                double step;
                if (fabs(r) <= ftol && !c.loose)
                    break;
                if (k == 0 && !c.loose && !pb->cold_start && fabs(r) <= EARLY_TOL * pb->Fz
                    && approach_moved(res))
                    break;              /* the grid is rebuilt: no need to settle on it */
                if (fabs(r) <= ftol) {
                    step = 0.0;           /* balanced on a loose solve: solved again */
                } else {
                    if (!isnan(lastN))
                        step = lastr == r ? r : -r * (N - lastN) / (r - lastr);
                    else
                        step = pb->cold_start ? r : first_step(pb, res, p, N, r);
                    lastN = N;
                    lastr = r;
                }
                N += step;
                c.loose = 0;
                if ((st = solve(&c, p, N, 0, &edge)) < 0)
                    break;
                warn = worse(warn, st);
            }
            if (st >= 0 && it == FZ_ITER) {
                res->why = RR_WHEEL_EXACT_SETTLE;
                st = RR_ERR_RANGE;
            }
        }
    }
    if (st < 0)
        return failed(res, st);
    {
        const size_t n = (size_t)p->grid.mx * (size_t)p->grid.my;
        if (field && field->state)
            memcpy(field->state, c.state, n);
        if (field && field->pn)
            memcpy(field->pn, c.last, n * sizeof(double));
        if (field && field->px)
            memcpy(field->px, c.last + n, n * sizeof(double));
        if (field && field->py)
            memcpy(field->py, c.last + 2 * n, n * sizeof(double));
    }
    for (k = 0; k < 3; k++)
        res->force[k] = res->sol.fx * p->t1[k] + res->sol.fy * p->t2[k] + res->sol.fn * p->n[k];
    return warn;
}
