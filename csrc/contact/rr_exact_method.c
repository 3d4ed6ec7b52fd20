/* rr_exact_method.c - the exact theory as a creep-force method of the
 * registry ("exact"): an ellipse problem on the ellipse's own grid with
 * Hertz's gap, a grid problem on its grid with its gap; Coulomb friction. */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "contact/rr_hertz.h"
#include "contact/rr_exact.h"
#include "contact/rr_creep_opts.h"

int rr_exact_problem_from(const rr_contact_problem *p, const rr_creep_opts *o,
                          rr_exact_problem *pb)
{
    int st;

    if (!pb)
        return RR_ERR_NULL;
    memset(pb, 0, sizeof *pb);
    if (!p || !o)
        return RR_ERR_NULL;
    st = rr_contact_problem_check(p, NULL);
    /* built for Coulomb friction: a falling law would need the slip speed in
     * the traction bound, which this solver does not iterate on */
    if (st == RR_OK && rr_friction_is_falling(&p->friction))
        st = RR_ERR_FRICTION;
    if (p->patch == RR_PATCH_GRID) {
        pb->grid = p->grid;
        pb->h = p->h;
    } else {
        if (st == RR_OK)
            st = rr_exact_hertz_grid(p->a, p->b, (int)o->v[RR_EXACT_NX],
                                     (int)o->v[RR_EXACT_NY], &pb->grid);
        /* G near the double's top: E* = G / (1 - nu) overflows (a finite
         * input too extreme, not a NaN one) */
        if (st == RR_OK && !isfinite(p->G / (1.0 - p->nu)))
            st = RR_ERR_RANGE;
        if (st == RR_OK)
            st = rr_hertz_curvatures(p->a, p->b, p->N, p->G / (1.0 - p->nu), &pb->A, &pb->B);
    }
    pb->N = p->N;
    pb->G = p->G;
    pb->nu = p->nu;
    pb->mu = p->friction.mu0;
    pb->cx = p->cx;
    pb->cy = p->cy;
    pb->cphi = p->cphi;
    pb->tol = o->v[RR_EXACT_TOL];
    pb->maxit = (int)o->v[RR_EXACT_MAXIT];
    pb->spin_shift = o->v[RR_EXACT_SPIN_SHIFT];
    return st;
}

static double exact_cost(const rr_creep_opts *o)
{
    /* some 60 products of about 10 N log2 N each, in FASTSIM elements (~10 flops) */
    const double n = (o->v[RR_EXACT_NX] + 2 * RR_EXACT_MARGIN)
                     * (o->v[RR_EXACT_NY] + 2 * RR_EXACT_MARGIN);
    return 60.0 * 4.0 * n * log2(4.0 * n);
}

/* the ellipse's grid (nx, ny across it and the margins), or the problem's */
static size_t exact_workspace(const rr_creep_opts *o, const rr_grid *grid)
{
    if (grid)
        return rr_exact_workspace_len(grid->mx, grid->my);
    return rr_exact_workspace_len((int)o->v[RR_EXACT_NX] + 2 * RR_EXACT_MARGIN,
                                  (int)o->v[RR_EXACT_NY] + 2 * RR_EXACT_MARGIN);
}

static int exact_forces_interruptible(const rr_contact_problem *p, const rr_creep_opts *o,
                                      double *work, const rr_interrupt *stop, rr_forces *out)
{
    rr_exact_problem pb;
    rr_exact_result res;
    int st;

    if (!out)
        return RR_ERR_NULL;
    st = rr_exact_problem_from(p, o, &pb);
    pb.interrupt = stop;
    if (st == RR_OK)
        st = rr_exact_solve(&pb, work, exact_workspace(o, p->patch == RR_PATCH_GRID
                                                           ? &p->grid : NULL),
                            &res, NULL);
    if (st < 0) {
        rr_forces_nan(out);
        return st;
    }
    out->fx = res.fx;
    out->fy = res.fy;
    out->mz = res.mz;
    return rr_forces_checked(st, out);
}

static int exact_forces(const rr_contact_problem *p, const rr_creep_opts *o, double *work,
                        rr_forces *out)
{
    return exact_forces_interruptible(p, o, work, NULL, out);
}

/* each option at its index of rr_exact.h */
static const rr_creep_option exact_opts[] = {
    [RR_EXACT_NX] = {"nx", RR_OPT_INT, "", 27.0, 1.0, RR_EXACT_MAX_GRID - 2 * RR_EXACT_MARGIN,
                     0, 0, NULL, RR_ERR_GRID,
                     "elements across the ellipse's 2a (the grid adds 2 on each side)"},
    [RR_EXACT_NY] = {"ny", RR_OPT_INT, "", 27.0, 1.0, RR_EXACT_MAX_GRID - 2 * RR_EXACT_MARGIN,
                     0, 0, NULL, RR_ERR_GRID, "elements across the ellipse's 2b"},
    [RR_EXACT_TOL] = {"tol", RR_OPT_REAL, "", 1e-6, 1e-14, 0.1, 0, 0, NULL, RR_ERR_PARAM,
                      "relative tolerance of the normal and the tangential solution"},
    [RR_EXACT_MAXIT] = {"maxit", RR_OPT_INT, "", 5000.0, 1.0, 1e7, 0, 0, NULL, RR_ERR_PARAM,
                        "most FFT products each problem may use (then the status warns)"},
    [RR_EXACT_SPIN_SHIFT] = {"spin_shift", RR_OPT_REAL, "", 1.0 / 6.0, -1.0, 1.0, 0, 0, NULL,
                             RR_ERR_PARAM, "spin's rigid slip taken at x + spin_shift dx: "
                             "CONTACT's 1/6; 0 keeps C23 = C32 on every grid"},
};

const rr_method_desc rr_method_exact = {
    .name = "exact",
    .doc = "Kalker's exact theory (CONTACT's discretisation: steady rolling on the "
           "half-space, Coulomb friction), FFT-accelerated",
    .nopts = RR_COUNTOF(exact_opts),
    .opts = exact_opts,
    .saturates = 1,
    .cost = exact_cost,
    .slope_scale = rr_method_unit_slope,
    .workspace_len = exact_workspace,
    .forces = exact_forces,
    .coulomb_only = 1,
    .forces_interruptible = exact_forces_interruptible,
    .takes_grid = 1,
    .iterative = 1,
};
