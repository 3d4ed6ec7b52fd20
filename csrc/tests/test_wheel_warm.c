/* test_wheel_warm.c - rr_wheel_exact's warm starts (rr_wheel_exact.h): each
 * solve after the first starts from the last solution (rr_exact_solve_from;
 * onto a rebuilt grid, mapped).  cold_start = 1 gives the solves from the
 * solver's own starts: its final solution is rr_exact_solve's on the final
 * patch bit for bit (the results before warm starts).  The warm starts
 * give the same to the solver's tolerance: tol 1e-9 here, the forces to
 * 1e-7 mu N (measured 7e-11: each solve stops within a few tol of the
 * discrete solution; the bound leaves room for the pose, lowered by an
 * approach solved to the tolerance), the same elements in contact and in
 * slip, the vertical balance to the load iteration's 1e-7, with fewer
 * products in the final solve. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rr_test.h"
#include "rollerrig.h"

#define NP RR_RIG_PROFILE_POINTS
#define CELLS (48 * 48)
static double wy[NP], wz[NP], ry[NP], rz[NP], wzu[NP], wmu[NP], rzu[NP], rmu[NP], pw[4 * NP];

/* The rig's conical wheel on its crowned roller (test_gap.c's rig_pair:
 * r0 = R0 = 92 mm, cone 1:20, crown 60 mm, +-15 mm, 0.15 m out). */
static void rig_pair(int side, rr_wheel_roller *p)
{
    rr_profile_points w, r;
    rr_profile_conical(atan(0.05), -0.015, 0.015, NP, wy, wz);
    rr_profile_crowned(0.06, -0.015, 0.015, NP, ry, rz);
    w.n = r.n = NP;
    w.y = wy;
    w.z = wz;
    r.y = ry;
    r.z = rz;
    w.end = r.end = RR_SPLINE_NOT_A_KNOT;
    rr_profile_surface(&w, wzu, wmu, pw);
    rr_profile_surface(&r, rzu, rmu, pw);
    p->wheel.n = NP;
    p->wheel.s = wy;
    p->wheel.z = wzu;
    p->wheel.m = wmu;
    p->roller.n = NP;
    p->roller.s = ry;
    p->roller.z = rzu;
    p->roller.m = rmu;
    p->r0 = p->R0 = 0.092;
    p->wheel_y = p->roller_y = 0.15;
    p->side = side;
}

typedef struct {
    double h[CELLS], pn[CELLS], px[CELLS], py[CELLS];
    signed char state[CELLS];
} wheel_out;

static int run(const rr_wheel_exact_problem *pb, double *w, size_t len, wheel_out *o,
               rr_wheel_exact_result *r)
{
    rr_exact_field f;
    memset(&f, 0, sizeof f);
    f.pn = o->pn;
    f.px = o->px;
    f.py = o->py;
    f.state = o->state;
    memset(w, 0, len * sizeof *w);
    return rr_wheel_exact(pb, w, len, o->h, CELLS, &f, CELLS, r);
}

/* rr_exact_solve of the final patch of r (h in o) with pb's settings */
static int solve_patch(const rr_wheel_exact_problem *pb, const rr_wheel_exact_result *r,
                       const wheel_out *o, rr_exact_result *s)
{
    rr_exact_problem ep;
    size_t len = rr_exact_workspace_len(r->patch.grid.mx, r->patch.grid.my);
    double *w = calloc(len, sizeof *w);
    int st;
    memset(&ep, 0, sizeof ep);
    ep.grid = r->patch.grid;
    ep.h = o->h;
    ep.N = r->N;
    ep.G = pb->E / (2.0 * (1.0 + pb->nu));
    ep.nu = pb->nu;
    ep.mu = pb->mu;
    ep.cx = r->cx;
    ep.cy = r->cy;
    ep.cphi = r->cphi;
    ep.spin_shift = pb->spin_shift;
    ep.tol = pb->tol;
    ep.maxit = pb->maxit;
    st = rr_exact_solve(&ep, w, len, s, NULL);
    free(w);
    return st;
}

/* a and b the same doubles (fx, fy, the load) */
static int same_doubles(const rr_wheel_exact_result *a, const rr_wheel_exact_result *b)
{
    return memcmp(&a->sol.fx, &b->sol.fx, sizeof a->sol.fx) == 0
           && memcmp(&a->sol.fy, &b->sol.fy, sizeof a->sol.fy) == 0
           && memcmp(&a->N, &b->N, sizeof a->N) == 0;
}

int main(void)
{
    rr_wheel_roller pair[2];
    rr_search_opts so;
    rr_wheel_exact_problem pb;
    rr_wheel_exact_result rc, rw;
    rr_contact_point cl, cr;
    rr_exact_result s;
    wheel_out *oc = malloc(sizeof *oc), *ow = malloc(sizeof *ow);
    size_t len;
    double *w, muN;
    int k, n, same;

    rig_pair(1, &pair[0]);
    pair[1] = pair[0];
    pair[1].side = -1;
    rr_search_opts_default(&so);
    rr_wheel_exact_default(&pb);
    CHECK(pb.cold_start == 0, "warm starts by default");
    pb.pair = &pair[0];
    pb.y_ws = 0.001;
    rr_wheelset_contact(&pair[0], &pair[1], pb.y_ws, &so, &pb.pose0, &cl, &cr);
    pb.point = cl;
    pb.Fz = 5000.0;
    pb.mu = 0.3;
    pb.cx = 1e-3;
    pb.cphi = 0.5;
    pb.gap.n = 30;
    pb.tol = 1e-9;
    len = rr_wheel_exact_workspace_len(&pb, 48, 48);
    w = malloc(len * sizeof *w);

    /* cold: the solves from the solver's own starts, the final one
     * rr_exact_solve's on the final patch bit for bit */
    pb.cold_start = 1;
    CHECK_STATUS(run(&pb, w, len, oc, &rc), RR_OK, "cold starts");
    CHECK(rc.passes >= 4, "coarse, loaded, the load's steps and the rebuild");
    CHECK_STATUS(solve_patch(&pb, &rc, oc, &s), RR_OK, "cold: the final patch solved");
    CHECK(memcmp(&s.fx, &rc.sol.fx, sizeof s.fx) == 0 && memcmp(&s.fy, &rc.sol.fy, sizeof s.fy) == 0
          && memcmp(&s.mz, &rc.sol.mz, sizeof s.mz) == 0,
          "cold: the final patch's rr_exact_solve, bit for bit");
    CHECK(s.nslip > 0 && s.nslip < s.ncontact, "partial slip");

    /* warm: the same to the tolerance */
    pb.cold_start = 0;
    CHECK_STATUS(run(&pb, w, len, ow, &rw), RR_OK, "warm starts");
    muN = pb.mu * rc.N;
    CHECK(abs(rw.passes - rc.passes) <= 1, "warm: the same steps, give or take the last");
    CHECK(rw.patch.grid.mx == rc.patch.grid.mx && rw.patch.grid.my == rc.patch.grid.my,
          "warm: the same final grid");
    /* the load: each within the balance's 1e-7 of Fz (tol 1e-9 here: the
     * balance's least, FZ_TOL), by different secant paths (warm: a first
     * step with fy's slope, cold: the slope 0) */
    CHECK_CLOSE(rw.N, rc.N, 0.0, 2e-7, "warm: the load");
    CHECK_CLOSE(rw.sol.fx, rc.sol.fx, 1e-7 * muN, 0.0, "warm: fx the cold one's");
    CHECK_CLOSE(rw.sol.fy, rc.sol.fy, 1e-7 * muN, 0.0, "warm: fy the cold one's");
    CHECK_CLOSE(rw.force[2], pb.Fz, 0.0, 1e-7, "warm: the vertical balance");
    CHECK(rw.sol.ncontact == rc.sol.ncontact && rw.sol.nslip == rc.sol.nslip,
          "warm: the same areas");
    n = rw.patch.grid.mx * rw.patch.grid.my;
    same = 1;
    for (k = 0; k < n; k++)
        same &= ow->state[k] == oc->state[k] && fabs(ow->pn[k] - oc->pn[k]) < 1e-6 * rc.sol.pmax
                && fabs(ow->px[k] - oc->px[k]) < 1e-6 * pb.mu * rc.sol.pmax;
    CHECK(same, "warm: the fields the cold ones' to the tolerance");
    /* and its final solution is a cold solve of its own final patch */
    CHECK_STATUS(solve_patch(&pb, &rw, ow, &s), RR_OK, "warm: the final patch solved");
    CHECK_CLOSE(rw.sol.fx, s.fx, 1e-7 * muN, 0.0, "warm: its patch's cold solve");
    CHECK(rw.sol.normal_products + rw.sol.tang_products
          < rc.sol.normal_products + rc.sol.tang_products, "warm: fewer products");

    /* elements of a given size: the loaded grid kept where the approach
     * found is within 1 % of the one it was built for (cold starts rebuild
     * it at the load found): a pose a fraction of a micrometre higher, the
     * forces within 1e-6 mu N (measured 8.9e-8) */
    pb.gap.dx = pb.gap.dy = rc.patch.grid.dx;
    pb.cold_start = 1;
    CHECK_STATUS(run(&pb, w, len, oc, &rc), RR_OK, "given dx, cold");
    pb.cold_start = 0;
    CHECK_STATUS(run(&pb, w, len, ow, &rw), RR_OK, "given dx, warm");
    CHECK(rw.builds == rc.builds - 1 && fabs(rw.sol.delta / rw.approach - 1.0) <= 0.01,
          "given dx: the loaded grid kept (the approach found within 1 % of its)");
    CHECK(fabs(rw.lowered - rc.lowered) <= 0.011 * rc.lowered, "given dx: the pose near");
    CHECK_CLOSE(rw.sol.fx, rc.sol.fx, 1e-6 * muN, 0.0, "given dx: fx");
    CHECK_CLOSE(rw.sol.fy, rc.sol.fy, 1e-6 * muN, 0.0, "given dx: fy");
    CHECK_CLOSE(rw.force[2], pb.Fz, 0.0, 1e-7, "given dx: the vertical balance");
    pb.gap.dx = pb.gap.dy = 0.0;

    /* with N given and a grid that covers: the coarse pass and one loaded
     * solve, which starts cold (not from the coarse pressure).  Without the
     * coarse pass, the doubles of cold_start; with it, the coarse patch's
     * samples differ (cold_start keeps 2e-5 m, warm takes COARSE_SAMPLE),
     * which moved the loaded grid's approach by 0.2 % and the forces by
     * 1.3e-7 mu N (the approach found 5e-9): within the solver's 1e-6 */
    pb.Fz = 0.0;
    pb.N = 5000.0;
    pb.passes = 1;
    CHECK_STATUS(run(&pb, w, len, ow, &rw), RR_OK, "N given, one pass, warm");
    pb.cold_start = 1;
    CHECK_STATUS(run(&pb, w, len, oc, &rc), RR_OK, "N given, one pass, cold");
    CHECK(rw.passes == 1 && memcmp(&rw.sol.fx, &rc.sol.fx, sizeof rc.sol.fx) == 0
          && memcmp(&rw.sol.fy, &rc.sol.fy, sizeof rc.sol.fy) == 0,
          "N given, one pass: the loaded solve cold either way");
    pb.passes = 2;
    pb.cold_start = 0;
    CHECK_STATUS(run(&pb, w, len, ow, &rw), RR_OK, "N given, warm");
    pb.cold_start = 1;
    CHECK_STATUS(run(&pb, w, len, oc, &rc), RR_OK, "N given, cold");
    CHECK(rw.passes == 2 && fabs(rw.approach / rc.approach - 1.0) < 0.01,
          "N given: coarse and loaded, the coarse approach within 1 %");
    CHECK_CLOSE(rw.sol.fx, rc.sol.fx, 1e-6 * pb.mu * pb.N, 0.0, "N given: fx");
    CHECK_CLOSE(rw.sol.fy, rc.sol.fy, 1e-6 * pb.mu * pb.N, 0.0, "N given: fy");
    /* the coarse pass's share of the workspace, kept from call to call
     * (a quarter of the solvers' share, after the loaded grids'; the layout of
     * rr_wheel_exact.c:
     * the solvers' share, the flag, the last solutions, the states, the
     * gap's, the carving's mark): its spectra are read again by the next
     * call (NaN over them, the key kept, fails it), and where the flag says
     * a larger grid wrote over them, built anew (that call gives a fresh
     * workspace's doubles), as where a call carved the workspace otherwise
     * (h and fields of another length) */
    {
        const size_t exact_len = len - 1 - rr_gap_workspace_len(&pb.gap) - (CELLS / 8 + 1)
                                 - 9 * (size_t)CELLS - 1;
        const size_t coarse_len = (exact_len + 3) / 4, main_len = exact_len - coarse_len;
        rr_wheel_exact_result r2;
        size_t i;
        pb.cold_start = 0;
        CHECK_STATUS(run(&pb, w, len, ow, &rw), RR_OK, "coarse share: fresh");
        for (i = main_len + 8; i < exact_len; i++)
            w[i] = NAN;
        CHECK(rr_wheel_exact(&pb, w, len, oc->h, CELLS, NULL, 0, &r2) < 0 && r2.passes == 1,
              "coarse share: its spectra read again by the next call");
        CHECK_STATUS(run(&pb, w, len, ow, &rw), RR_OK, "coarse share: fresh again");
        for (i = main_len + 8; i < exact_len; i++)
            w[i] = NAN;
        w[exact_len] = 1.0;
        CHECK_STATUS(rr_wheel_exact(&pb, w, len, oc->h, CELLS, NULL, 0, &r2), RR_OK,
                     "coarse share: written over, flagged");
        CHECK(same_doubles(&r2, &rw),
              "coarse share: written over, flagged: a fresh workspace's doubles");
        /* another carving between (h of half the length), whose scratch
         * wrote over the coarse spectra and not their key: built anew */
        {
            double key[8];
            CHECK_STATUS(run(&pb, w, len, ow, &rw), RR_OK, "carved otherwise: fresh");
            memcpy(key, w + main_len, sizeof key);
            CHECK_STATUS(rr_wheel_exact(&pb, w, len, oc->h, CELLS / 2, NULL, 0, &r2), RR_OK,
                         "carved otherwise: h of half the length");
            memcpy(w + main_len, key, sizeof key);
            for (i = main_len + 8; i < exact_len; i++)
                w[i] = NAN;
            CHECK_STATUS(rr_wheel_exact(&pb, w, len, ow->h, CELLS, NULL, 0, &r2), RR_OK,
                         "carved otherwise, then as before");
            CHECK(same_doubles(&r2, &rw), "carved otherwise between: a fresh workspace's doubles");
        }
    }
    /* a workspace whose loaded grid takes the coarse share too (a grid
     * too large for its own share): the calls after it on the kept
     * workspace, whose coarse pass writes over that grid's box, give a
     * fresh workspace's doubles */
    {
        const size_t rest = 1 + rr_gap_workspace_len(&pb.gap) + (CELLS / 8 + 1)
                            + 9 * (size_t)CELLS + 1;
        rr_wheel_exact_result r1, r2;
        size_t need, ex;
        double *w2;
        int q, ok = 1;
        pb.cold_start = 0;
        pb.N = 0.0;
        pb.Fz = 5000.0;
        CHECK_STATUS(run(&pb, w, len, ow, &rw), RR_OK, "takes all: the grid's size");
        need = rr_exact_workspace_len(rw.patch.grid.mx, rw.patch.grid.my);
        ex = need + need / 8;       /* the loaded grids' share 0.84 of need */
        w2 = calloc(ex + rest, sizeof *w2);
        CHECK_STATUS(rr_wheel_exact(&pb, w2, ex + rest, ow->h, CELLS, NULL, 0, &r1), RR_OK,
                     "takes all: fresh");
        for (q = 0; q < 3; q++) {
            /* the coarse share written over (as the coarse pass of a call
             * of another grid would) */
            size_t i;
            for (i = ex - (ex + 3) / 4; i < ex; i++)
                w2[i] = NAN;
            ok &= rr_wheel_exact(&pb, w2, ex + rest, ow->h, CELLS, NULL, 0, &r2) == RR_OK
                  && same_doubles(&r2, &r1);
        }
        CHECK(ok, "takes all, then kept: a fresh workspace's doubles");
        free(w2);
    }
    /* one workspace kept through calls that carve it differently (h and
     * fields of other lengths move the solvers' shares: a pool of
     * workspaces hands one to whichever call comes): each call gives a
     * fresh workspace's doubles, whatever ran there before */
    {
        enum { NCASE = 3, NCELL = 3, NRUN = 40 };
        static const size_t cells[NCELL] = {CELLS, CELLS * 3 / 4, CELLS / 2};
        rr_wheel_exact_problem cs[NCASE];
        static rr_wheel_exact_result ref[NCASE][NCELL];
        unsigned seed = 12345u;
        int i, j, ok = 1, ran = 0;
        pb.cold_start = 0;
        pb.N = 0.0;
        pb.Fz = 5000.0;
        for (i = 0; i < NCASE; i++)
            cs[i] = pb;
        cs[1].y_ws = -0.002;
        rr_wheelset_contact(&pair[0], &pair[1], cs[1].y_ws, &so, &cs[1].pose0, &cl, &cr);
        cs[1].point = cl;
        cs[1].gap.n = 24;
        cs[2].gap.dx = cs[2].gap.dy = 4e-4;
        cs[2].mu = 0.4;
        for (i = 0; i < NCASE; i++)
            for (j = 0; j < NCELL; j++) {
                memset(w, 0, len * sizeof *w);
                CHECK_STATUS(rr_wheel_exact(&cs[i], w, len, ow->h, cells[j], NULL, 0, &ref[i][j]),
                             RR_OK, "kept through other carvings: the fresh workspace's call");
            }
        memset(w, 0, len * sizeof *w);
        for (k = 0; k < NRUN; k++) {
            seed = seed * 1103515245u + 12345u;
            i = (int)((seed >> 16) % NCASE);
            seed = seed * 1103515245u + 12345u;
            j = (int)((seed >> 16) % NCELL);
            ok &= rr_wheel_exact(&cs[i], w, len, ow->h, cells[j], NULL, 0, &rw) == RR_OK
                  && same_doubles(&rw, &ref[i][j]);
            ran++;
        }
        CHECK(ok && ran == NRUN,
              "kept through calls of other carvings: each call a fresh workspace's doubles");
    }
    /* the workspace the warm starts need is in rr_wheel_exact_workspace_len:
     * one double short refused */
    pb.cold_start = 0;
    CHECK_STATUS(rr_wheel_exact(&pb, w, rr_wheel_exact_workspace_len(&pb, 1, 1) - 1, ow->h, 1,
                                NULL, 0, &rw), RR_ERR_WORKSPACE, "workspace one double short");
    free(w);
    free(oc);
    free(ow);
    return rr_test_summary();
}
