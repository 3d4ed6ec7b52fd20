/*
 * fuzz_exact.c - Kalker's exact theory (rr_exact.h): rr_exact_solve on
 * small grids, Hertzian or with any undeformed distance h, and the same h
 * as a contact problem on a grid (rr_contact_problem, RR_PATCH_GRID)
 * through the registry: the method "exact", and every method that takes
 * the ellipse only.
 *
 * Input: the grid (1 .. 14 elements a side, sometimes 0, negative or past
 * RR_EXACT_MAX_GRID), its element sizes and placement, h (a bowl, a bowl
 * with noise, two bowls, or any values, edges included) or the Hertzian
 * curvatures, the load, material, friction, creepages, spin shift,
 * tolerance and product cap, valid or not; the workspace exact, one double
 * short or NULL, zero-filled or full of NaN (as a failed case may leave
 * it); the fields wanted or not; an interrupt hook that stops at its n-th
 * poll.
 *
 * Oracles: a documented status; the documented errors for invalid inputs,
 * with NaN results and NaN fields; on success finite results, the normal
 * force N to 1e-6, |(fx, fy)| <= mu fn (the tractions are kept on the
 * bound), every field value finite, |p| <= mu pn per element, the counts
 * consistent with the state map; nothing written past the workspace or a
 * field; a second solve with the same workspace (its cached normal
 * solution and spectra) gives the same doubles, and so does a solve on a
 * fresh workspace where the first had one of NaN; the hook: stopped at the
 * poll it asks (RR_ERR_INTERRUPTED, NaN results), or never polled that
 * often and the doubles unchanged; after it, the workspace gives the first
 * solve's status and doubles.  The grid problem: rr_contact_problem_check
 * refuses exactly an invalid grid, h or number, naming a member at fault;
 * the method "exact" on a fresh workspace of rr_creep_workspace_len for the
 * grid (one double short refused) gives rr_exact_solve's status and doubles
 * where the problem is valid, an error with NaN forces where it is not, and
 * rr_creep_blame a member at fault; every method of the ellipse only
 * refuses it (RR_ERR_PATCH, NaN forces).  The warm start
 * (rr_exact_solve_from, warm_start below): starts from the solution
 * perturbed, from any values or bad ones, refused with their status or
 * solved with the oracles above, a cold solve after it unchanged.
 */
#include "fuzz.h"

#define MAX_SIDE 14

typedef struct {
    int polls, stop_at;
} poll_count;

static int count_polls(void *ctx)
{
    poll_count *c = ctx;
    return ++c->polls >= c->stop_at;
}

/* st and r as the first solve's st0, r0 (the doubles where st0 >= 0) */
static void same_solve(const char *what, int st, const rr_exact_result *r, int st0,
                       const rr_exact_result *r0)
{
    if (st != st0 || (st0 >= 0 && (memcmp(&r->fx, &r0->fx, sizeof r->fx) != 0
                                   || memcmp(&r->fy, &r0->fy, sizeof r->fy) != 0
                                   || memcmp(&r->mz, &r0->mz, sizeof r->mz) != 0)))
        fz_fail("rr_exact_solve: %s gave status %d (%.17g, %.17g, %.17g), the first %d "
                "(%.17g, %.17g, %.17g)", what, st, r->fx, r->fy, r->mz, st0, r0->fx, r0->fy,
                r0->mz);
}

static int grid_side(fz_in *in)
{
    switch (fz_choice(in, 16)) {
    case 0: return fz_int(in, -2, 0);
    case 1: return RR_EXACT_MAX_GRID + fz_range(in, 1, 3);
    default: return fz_int(in, 1, MAX_SIDE);
    }
}

static int problem_invalid(const rr_exact_problem *pb)
{
    const rr_grid *g = &pb->grid;
    int k, n;
    if (g->mx < 1 || g->my < 1 || g->mx > RR_EXACT_MAX_GRID || g->my > RR_EXACT_MAX_GRID)
        return 1;
    if (!isfinite(g->dx) || !isfinite(g->dy) || !isfinite(g->x0) || !isfinite(g->y0)
        || !isfinite(pb->N) || !isfinite(pb->G) || !isfinite(pb->nu) || !isfinite(pb->mu)
        || !isfinite(pb->cx) || !isfinite(pb->cy) || !isfinite(pb->cphi)
        || !isfinite(pb->spin_shift) || !isfinite(pb->tol))
        return 1;
    n = g->mx * g->my;
    if (pb->h) {
        for (k = 0; k < n; k++)
            if (!isfinite(pb->h[k]))
                return 1;
    } else if (!isfinite(pb->A) || !isfinite(pb->B) || !(pb->A > 0.0) || !(pb->B > 0.0)) {
        return 1;
    }
    return !(g->dx > 0.0) || !(g->dy > 0.0) || !isnormal(g->dx) || !isnormal(g->dy)
        || !isnormal(g->dx * g->dy) || g->dx / g->dy > 1e6 || g->dy / g->dx > 1e6
        || !(pb->N > 0.0) || !(pb->G > 0.0) || !isnormal(pb->G)
        || !(pb->nu >= 0.0 && pb->nu <= 0.5) || !(pb->mu > 0.0)
        || !(pb->tol >= 1e-14 && pb->tol <= 0.1) || pb->maxit < 1
        || !(pb->spin_shift >= -1.0 && pb->spin_shift <= 1.0);
}

static void decode_h(fz_in *in, const rr_grid *g, double *h)
{
    const int kind = fz_choice(in, 4), n = g->mx * g->my;
    const double A = fz_log(in, 0.01, 100.0), B = fz_log(in, 0.01, 100.0);
    const double noise = fz_log(in, 1e-12, 1e-5);
    const double sep = fz_lin(in, 0.0, 0.6) * g->mx * g->dx;
    int i, j;
    for (j = 0; j < g->my; j++)
        for (i = 0; i < g->mx; i++) {
            const double x = g->x0 + i * g->dx, y = g->y0 + j * g->dy;
            double v;
            switch (kind) {
            case 0: v = A * x * x + B * y * y; break;
            case 1: v = A * x * x + B * y * y + noise * fz_lin(in, -1.0, 1.0); break;
            case 2: v = fmin(A * (x - sep) * (x - sep), A * (x + sep) * (x + sep)) + B * y * y;
                    break;
            default: v = fz_slog(in, 1e-9, 1e-2); break;
            }
            h[j * g->mx + i] = v;
        }
    (void)n;
}

static void check_fields(const rr_exact_problem *pb, int st, const rr_exact_result *r,
                         const rr_exact_field *f)
{
    const int n = pb->grid.mx * pb->grid.my;
    int k, nc = 0, ns = 0;
    for (k = 0; k < n; k++) {
        const double pn = f->pn[k], px = f->px[k], py = f->py[k];
        if (st < 0) {
            if (!isnan(pn) || !isnan(px) || !isnan(py) || !isnan(f->sx[k]) || !isnan(f->sy[k]))
                fz_fail("rr_exact_solve: error %d but field value %d is not NaN", st, k);
            continue;
        }
        if (!isfinite(pn) || !isfinite(px) || !isfinite(py) || !isfinite(f->sx[k])
            || !isfinite(f->sy[k]))
            fz_fail("rr_exact_solve: status %d with a non-finite field at %d", st, k);
        if (pn < 0.0 || (f->state[k] < 0) != !(pn > 0.0) || f->state[k] < -1 || f->state[k] > 1)
            fz_fail("rr_exact_solve: element %d: pn %.17g, state %d", k, pn, f->state[k]);
        /* 1e-300: the rounding of subnormal tractions at the patch's edge */
        if (!(hypot(px, py) <= pb->mu * pn * (1.0 + 1e-12) + 1e-300))
            fz_fail("rr_exact_solve: element %d: |p| %.17g above mu pn %.17g", k,
                    hypot(px, py), pb->mu * pn);
        nc += f->state[k] >= 0;
        ns += f->state[k] == 1;
    }
    if (st >= 0 && (nc != r->ncontact || ns != r->nslip))
        fz_fail("rr_exact_solve: counts %d, %d but the map says %d, %d", r->ncontact, r->nslip,
                nc, ns);
}

/* pb's h as a contact problem on the grid through the registry (the
 * solve of pb gave st, r on a workspace that was zero-filled or NaN) */
static void grid_problem(const rr_exact_problem *pb, int st, const rr_exact_result *r)
{
    rr_contact_problem g;
    rr_creep_opts o;
    rr_creep_checked k;
    rr_forces f;
    size_t wl;
    double *work;
    int field = -99, pst, st2, m, fst;

    memset(&g, 0, sizeof g);
    g.patch = RR_PATCH_GRID;
    g.grid = pb->grid;
    g.h = pb->h;
    g.N = pb->N;
    g.G = pb->G;
    g.nu = pb->nu;
    g.friction.mu0 = pb->mu;
    g.friction.A = 1.0;
    g.cx = pb->cx;
    g.cy = pb->cy;
    g.cphi = pb->cphi;
    pst = rr_contact_problem_check(&g, &field);
    fz_status("rr_contact_problem_check (grid)", pst);
    if (pst < 0 ? !fz_member_at_fault(&g, field, pst) : field != RR_PF_NONE)
        fz_fail("rr_contact_problem_check (grid): status %d names member %d (%s)", pst, field,
                rr_problem_field_name(field) ? rr_problem_field_name(field) : "none");
    /* the method "exact" with pb's settings, where they are valid options */
    rr_creep_opts_default(&o, RR_METHOD_EXACT);
    o.v[RR_EXACT_TOL] = pb->tol;
    o.v[RR_EXACT_MAXIT] = pb->maxit;
    o.v[RR_EXACT_SPIN_SHIFT] = pb->spin_shift;
    if (rr_creep_check(&k, &o, NULL) != RR_OK)
        return;
    wl = rr_creep_workspace_len(&o, &g.grid);
    if (wl != rr_exact_workspace_len(g.grid.mx, g.grid.my))
        fz_fail("rr_creep_workspace_len: %zu for a %d x %d grid, the solver's %zu", wl,
                g.grid.mx, g.grid.my, rr_exact_workspace_len(g.grid.mx, g.grid.my));
    work = fz_guarded((wl > 0 ? wl : 1) * sizeof *work);
    memset(work, 0, (wl > 0 ? wl : 1) * sizeof *work);
    fst = rr_creep_forces_work(&g, &o, work, wl, &f);
    fz_status("rr_creep_forces_work (grid)", fst);
    fz_guard_ok("rr_creep_forces_work (grid)", work, (wl > 0 ? wl : 1) * sizeof *work, "work");
    if (pst == RR_OK && (fst != st || (st >= 0 && (memcmp(&f.fx, &r->fx, sizeof f.fx) != 0
                                                   || memcmp(&f.fy, &r->fy, sizeof f.fy) != 0
                                                   || memcmp(&f.mz, &r->mz, sizeof f.mz) != 0))))
        fz_fail("the grid problem: status %d (%.17g, %.17g, %.17g), rr_exact_solve %d "
                "(%.17g, %.17g, %.17g)", fst, f.fx, f.fy, f.mz, st, r->fx, r->fy, r->mz);
    if (pst < 0 && fst >= 0)
        fz_fail("the grid problem: status %d for an invalid problem (%d)", fst, pst);
    if (fst < 0) {
        const int blamed = rr_creep_blame(&k, &g, fst);
        if (!isnan(f.fx) || !isnan(f.fy) || !isnan(f.mz))
            fz_fail("the grid problem: error %d but the forces are not NaN", fst);
        if (blamed != RR_PF_NONE && !fz_member_at_fault(&g, blamed, fst))
            fz_fail("rr_creep_blame (grid): status %d blames member %d (%s)", fst, blamed,
                    rr_problem_field_name(blamed));
        if (pst < 0 && pst == fst && blamed != field)
            fz_fail("rr_creep_blame (grid): member %d, the check's %d", blamed, field);
    }
    if (wl > 0 && rr_creep_forces_work(&g, &o, work, wl - 1, &f) != RR_ERR_WORKSPACE)
        fz_fail("the grid problem: a workspace one double short not refused");
    fz_guard_free(work);
    /* the methods of the ellipse only */
    for (m = 0; m < RR_METHOD_COUNT; m++) {
        if (rr_method_get(m)->takes_grid)
            continue;
        rr_creep_opts_default(&o, m);
        st2 = rr_creep_forces(&g, &o, &f);
        if (st2 != RR_ERR_PATCH || !isnan(f.fx) || !isnan(f.fy) || !isnan(f.mz))
            fz_fail("%s: status %d for a grid problem, not RR_ERR_PATCH with NaN forces",
                    rr_method_get(m)->name, st2);
        if (rr_creep_check(&k, &o, NULL) == RR_OK && rr_creep_blame(&k, &g, st2) != RR_PF_PATCH)
            fz_fail("rr_creep_blame: %s's RR_ERR_PATCH not the patch's", rr_method_get(m)->name);
    }
}

/* 1 where the elastic displacements (the mean pressure's over an element,
 * u = p dx / G) stand above h's rounding by a million ulps: below, the
 * contact within a row that h leaves flat is decided by h's round-off, and
 * a warm and a cold solve may settle on different pressures, both right
 * (G 1.6e183 on a Hertzian gap flat along y, B 5.8e-80: displacements of
 * 1e-177 m under an h of 1e-10 m; fx 1.2e-3 mu N apart, random seed 9001).
 * And where u is above 1e-140 m: below, the solver's sums of squared
 * residuals (u times its tolerance, squared) underflow, and a solve stops
 * at a residual of 0 on a contact set short of the answer (G 2e273, u
 * 1e-269 m: a flat column of 14 elements, 6 in contact, warm and cold
 * different 6; the next find of seed 9001).  The limit is the solver's,
 * noted in its closing note; the oracle compares only above it. */
static int determined(const rr_exact_problem *pb)
{
    const rr_grid *g = &pb->grid;
    const int n = g->mx * g->my;
    const double u = pb->N / (g->dy * n) / pb->G;
    double hs = 0.0;
    int k;
    for (k = 0; k < n; k++) {
        const double x = g->x0 + (k % g->mx) * g->dx, y = g->y0 + (k / g->mx) * g->dy;
        const double h = pb->h ? pb->h[k] : pb->A * x * x + pb->B * y * y;
        hs = fmax(hs, fabs(h));
    }
    return u > 1e6 * DBL_EPSILON * hs && u > 1e-140;
}

/* 1 where the start s is one rr_exact_solve_from refuses for pb's grid
 * (n elements), with the status it must give in *want. */
static int start_invalid(const rr_exact_problem *pb, const rr_exact_start *s, int n, int *want)
{
    int k, positive = 0;
    *want = RR_OK;
    if (s->mx != pb->grid.mx || s->my != pb->grid.my)
        *want = RR_ERR_GRID;
    else if (!s->pn || (!s->px) != (!s->py))
        *want = RR_ERR_NULL;
    else {
        for (k = 0; k < n && *want == RR_OK; k++)
            if (!isfinite(s->pn[k]) || (s->px && (!isfinite(s->px[k]) || !isfinite(s->py[k]))))
                *want = RR_ERR_NONFINITE;
        for (k = 0; k < n && *want == RR_OK; k++) {
            if (s->pn[k] < 0.0)
                *want = RR_ERR_PARAM;
            positive |= s->pn[k] > 0.0;
        }
        if (*want == RR_OK && !positive)
            *want = RR_ERR_PARAM;
    }
    return *want != RR_OK;
}

/* The warm start (rr_exact_solve_from) on the valid workspace work of wl
 * doubles after the cold solve st, r of pb: a start from the cold
 * solution's field perturbed (f, where wanted), from any values, or a bad
 * one (a value NaN or infinite, a pressure negative or none positive, a
 * grid of another size, a pointer NULL).  Oracles: a bad start refused
 * with its status and NaN out where the cold solve succeeded (else the
 * problem's own error may come first); on success rr_exact_solve's oracles, and where both
 * converged to a tolerance of at most 1e-8 the cold forces to 1e-3 mu N
 * (a start changes only where the iterations stop; the bound is loose for
 * the fuzzer's ill-conditioned gaps); a cold solve after it gives the
 * first solve's doubles (nothing of the warm solve reaches it). */
static void warm_start(fz_in *in, const rr_exact_problem *pb, double *work, size_t wl,
                       int st, const rr_exact_result *r, const rr_exact_field *f, int invalid)
{
    const int n = pb->grid.mx * pb->grid.my, kind = fz_choice(in, 4);
    double *pn = fz_guarded((size_t)n * sizeof(double)), *px = fz_guarded((size_t)n * sizeof(double));
    double *py = fz_guarded((size_t)n * sizeof(double));
    rr_exact_start s;
    rr_exact_result rw, r2;
    rr_exact_field fw;
    int k, sw, want, bad;
    s.mx = pb->grid.mx;
    s.my = pb->grid.my;
    s.pn = pn;
    s.px = px;
    s.py = py;
    for (k = 0; k < n; k++) {
        if (kind == 0 && f && f->pn && st >= 0) {
            /* the solution, each value scaled by up to 30 % either way */
            pn[k] = f->pn[k] * fz_lin(in, 0.7, 1.3);
            px[k] = f->px[k] * fz_lin(in, 0.7, 1.3);
            py[k] = f->py[k] * fz_lin(in, 0.7, 1.3);
        } else {
            pn[k] = fz_choice(in, 3) == 0 ? 0.0 : fz_log(in, 1e-3, 1e12);
            px[k] = fz_slog(in, 1e-3, 1e300);
            py[k] = fz_slog(in, 1e-3, 1e300);
        }
    }
    if (fz_choice(in, 4) == 0) {
        s.px = s.py = NULL;                    /* the pressure alone */
        fz_note("; start: pressure alone");
    }
    if (kind == 3) {
        /* a bad start */
        const int e = fz_range(in, 0, n - 1);
        switch (fz_choice(in, 8)) {
        case 0: pn[e] = NAN; break;
        case 1: px[e] = fz_choice(in, 2) ? INFINITY : NAN; break;
        case 2: pn[e] = -fz_log(in, 1e-300, 1e9); break;
        case 3: for (k = 0; k < n; k++) pn[k] = 0.0; break;
        case 4: s.mx += fz_choice(in, 2) ? 1 : -1; break;
        case 5: s.my += fz_choice(in, 2) ? 1 : -1; break;
        case 6: s.pn = NULL; break;
        default: s.py = NULL; s.px = px; break;
        }
    }
    bad = start_invalid(pb, &s, n, &want);
    fz_note("; warm start kind %d, bad %d", kind, bad);
    memset(&fw, 0, sizeof fw);
    if (f && f->pn) {
        /* the start may be the field it writes (read first): here a copy */
        fw = *f;
    }
    sw = rr_exact_solve_from(pb, &s, work, wl, &rw, f && f->pn ? &fw : NULL);
    fz_status("rr_exact_solve_from", sw);
    fz_guard_ok("rr_exact_solve_from", work, wl * sizeof *work, "work");
    fz_error("rr_exact_solve_from", sw, invalid || bad, "the problem or the start is invalid");
    /* the problem's own errors come first: where its cold solve succeeded */
    if (st >= 0 && bad && sw != want)
        fz_fail("rr_exact_solve_from: a bad start gave status %d, not %d", sw, want);
    if (sw < 0) {
        if (!isnan(rw.fx) || !isnan(rw.fy) || !isnan(rw.mz) || !isnan(rw.fn))
            fz_fail("rr_exact_solve_from: error %d but the results are not NaN", sw);
    } else {
        FZ_FINITE("rr_exact_solve_from", sw, rw.fx);
        FZ_FINITE("rr_exact_solve_from", sw, rw.fy);
        FZ_FINITE("rr_exact_solve_from", sw, rw.mz);
        FZ_FINITE("rr_exact_solve_from", sw, rw.delta);
        FZ_FINITE("rr_exact_solve_from", sw, rw.normal_residual);
        FZ_FINITE("rr_exact_solve_from", sw, rw.tang_residual);
        if (!(fabs(rw.fn - pb->N) <= 1e-6 * pb->N))
            fz_fail("rr_exact_solve_from: fn %.17g, not N %.17g", rw.fn, pb->N);
        if (!(hypot(rw.fx, rw.fy) <= pb->mu * rw.fn * (1.0 + 1e-9)))
            fz_fail("rr_exact_solve_from: |F| %.17g above mu fn %.17g", hypot(rw.fx, rw.fy),
                    pb->mu * rw.fn);
        if (f && f->pn)
            check_fields(pb, sw, &rw, &fw);
        if (st == RR_OK && sw == RR_OK && pb->tol <= 1e-8 && determined(pb)
            && !(hypot(rw.fx - r->fx, rw.fy - r->fy) <= 1e-3 * (pb->mu * pb->N)))
            fz_fail("rr_exact_solve_from: (%.17g, %.17g), the cold solve (%.17g, %.17g)", rw.fx,
                    rw.fy, r->fx, r->fy);
    }
    /* nothing of it reaches a cold solve */
    if (st >= 0) {
        sw = rr_exact_solve(pb, work, wl, &r2, NULL);
        same_solve("a solve after a warm one", sw, &r2, st, r);
    }
    fz_guard_free(pn);
    fz_guard_free(px);
    fz_guard_free(py);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    rr_exact_problem pb;
    rr_exact_result r, r2;
    rr_exact_field f;
    double *h = NULL, *work = NULL;
    size_t wl = 0, wgive = 0, k;
    int st, st2, n = 0, invalid, wmode, want_field, nan_work, stop_at;

    memset(&pb, 0, sizeof pb);
    memset(&f, 0, sizeof f);
    pb.grid.mx = grid_side(&in);
    pb.grid.my = grid_side(&in);
    pb.grid.dx = fz_log(&in, 1e-5, 1e-2);
    pb.grid.dy = pb.grid.dx * fz_log(&in, 0.1, 10.0);
    if (fz_choice(&in, 8) == 0)
        pb.grid.dy = fz_slog(&in, 1e-9, 1.0);                 /* any, valid or not */
    pb.grid.x0 = -0.5 * ((double)pb.grid.mx - 1.0) * pb.grid.dx * fz_lin(&in, 0.5, 1.5);
    pb.grid.y0 = -0.5 * ((double)pb.grid.my - 1.0) * pb.grid.dy * fz_lin(&in, 0.5, 1.5);
    pb.N = fz_log(&in, 1.0, 2e5);
    if (fz_choice(&in, 8) == 0)
        pb.N = fz_slog(&in, 1e-6, 1e6);
    pb.G = fz_log(&in, 1e9, 3e11);
    pb.nu = fz_choice(&in, 8) == 0 ? fz_lin(&in, -0.1, 0.6) : fz_lin(&in, 0.0, 0.5);
    pb.mu = fz_choice(&in, 8) == 0 ? fz_slog(&in, 1e-3, 2.0) : fz_lin(&in, 0.05, 0.8);
    pb.cx = fz_slog(&in, 1e-7, 0.05);
    pb.cy = fz_slog(&in, 1e-7, 0.05);
    pb.cphi = fz_choice(&in, 2) ? fz_slog(&in, 1e-4, 50.0) : 0.0;
    pb.spin_shift = fz_choice(&in, 8) == 0 ? fz_lin(&in, -2.0, 2.0) : 1.0 / 6.0;
    pb.tol = fz_choice(&in, 8) == 0 ? fz_slog(&in, 1e-16, 1.0) : fz_log(&in, 1e-10, 1e-3);
    pb.maxit = fz_choice(&in, 8) == 0 ? fz_int(&in, -2, 3) : fz_range(&in, 1, 400);
    if (pb.grid.mx >= 1 && pb.grid.my >= 1 && pb.grid.mx <= MAX_SIDE && pb.grid.my <= MAX_SIDE)
        n = pb.grid.mx * pb.grid.my;
    if (n > 0 && fz_choice(&in, 2)) {
        h = fz_alloc((size_t)n * sizeof *h);
        decode_h(&in, &pb.grid, h);
        pb.h = h;
    } else {
        pb.A = fz_log(&in, 0.01, 100.0);
        pb.B = fz_log(&in, 0.01, 100.0);
        if (fz_choice(&in, 8) == 0)
            pb.B = fz_slog(&in, 1e-3, 1.0);
    }
    wmode = fz_choice(&in, 8);            /* 0: one double short, 1: NULL, else exact */
    want_field = n > 0 && fz_choice(&in, 2);
    nan_work = fz_choice(&in, 4) == 3;    /* 0 where the input has ended: zero-filled */
    stop_at = fz_choice(&in, 2) ? fz_range(&in, 1, 60) : 0;
    invalid = problem_invalid(&pb) || n == 0;
    fz_note("grid %d x %d, d %.17g x %.17g at (%.17g, %.17g), h %s, A %.17g B %.17g, N %.17g, "
            "G %.17g nu %.17g mu %.17g, c (%.17g, %.17g, %.17g), shift %.17g tol %.17g maxit %d, "
            "work mode %d, field %d, NaN work %d, stop at %d", pb.grid.mx, pb.grid.my, pb.grid.dx, pb.grid.dy,
            pb.grid.x0, pb.grid.y0, pb.h ? "given" : "Hertz", pb.A, pb.B, pb.N, pb.G, pb.nu,
            pb.mu, pb.cx, pb.cy, pb.cphi, pb.spin_shift, pb.tol, pb.maxit, wmode, want_field,
            nan_work, stop_at);
    if (n == 0) {
        /* a grid outside the sizes this target allocates: only refusal is allowed */
        double w1[4];
        rr_contact_problem g;
        int field = -99;
        st = rr_exact_solve(&pb, w1, 4, &r, NULL);
        fz_status("rr_exact_solve", st);
        fz_error("rr_exact_solve", st, 1, "the grid is out of range or too large a workspace");
        /* as a contact problem: a grid out of range refused before h is read */
        memset(&g, 0, sizeof g);
        g.patch = RR_PATCH_GRID;
        g.grid = pb.grid;
        g.h = w1;
        if ((pb.grid.mx < 1 || pb.grid.my < 1 || pb.grid.mx > RR_CONTACT_MAX_GRID
             || pb.grid.my > RR_CONTACT_MAX_GRID)
            && ((st = rr_contact_problem_check(&g, &field)) != RR_ERR_GRID
                || !fz_member_at_fault(&g, field, st)))
            fz_fail("rr_contact_problem_check: a %d x %d grid gave status %d, member %d",
                    g.grid.mx, g.grid.my, st, field);
        free(h);
        return 0;
    }
    wl = rr_exact_workspace_len(pb.grid.mx, pb.grid.my);
    if (wl == 0)
        fz_fail("rr_exact_workspace_len(%d, %d) = 0", pb.grid.mx, pb.grid.my);
    wgive = wmode == 0 ? wl - 1 : wl;
    work = wmode == 1 ? NULL : fz_guarded(wl * sizeof *work);
    if (work)
        for (k = 0; k < wl; k++)
            work[k] = nan_work ? NAN : 0.0;
    if (want_field) {
        f.pn = fz_guarded((size_t)n * sizeof(double));
        f.px = fz_guarded((size_t)n * sizeof(double));
        f.py = fz_guarded((size_t)n * sizeof(double));
        f.sx = fz_guarded((size_t)n * sizeof(double));
        f.sy = fz_guarded((size_t)n * sizeof(double));
        f.state = fz_guarded((size_t)n);
    }
    st = rr_exact_solve(&pb, work, wgive, &r, want_field ? &f : NULL);
    fz_status("rr_exact_solve", st);
    fz_error("rr_exact_solve", st, invalid || wmode <= 1, "an input or the workspace is invalid");
    if (work)
        fz_guard_ok("rr_exact_solve", work, wl * sizeof *work, "work");
    if (want_field) {
        fz_guard_ok("rr_exact_solve", f.pn, (size_t)n * sizeof(double), "pn");
        fz_guard_ok("rr_exact_solve", f.sy, (size_t)n * sizeof(double), "sy");
        fz_guard_ok("rr_exact_solve", f.state, (size_t)n, "state");
    }
    if (st < 0) {
        if (!isnan(r.fx) || !isnan(r.fy) || !isnan(r.mz) || !isnan(r.fn))
            fz_fail("rr_exact_solve: error %d but the results are not NaN", st);
    } else {
        FZ_FINITE("rr_exact_solve", st, r.fx);
        FZ_FINITE("rr_exact_solve", st, r.fy);
        FZ_FINITE("rr_exact_solve", st, r.mz);
        FZ_FINITE("rr_exact_solve", st, r.fn);
        FZ_FINITE("rr_exact_solve", st, r.delta);
        FZ_FINITE("rr_exact_solve", st, r.area);
        FZ_FINITE("rr_exact_solve", st, r.pmax);
        FZ_FINITE("rr_exact_solve", st, r.normal_residual);
        FZ_FINITE("rr_exact_solve", st, r.tang_residual);
        if (!(fabs(r.fn - pb.N) <= 1e-6 * pb.N))
            fz_fail("rr_exact_solve: fn %.17g, not N %.17g", r.fn, pb.N);
        if (!(hypot(r.fx, r.fy) <= pb.mu * r.fn * (1.0 + 1e-9)))
            fz_fail("rr_exact_solve: |F| %.17g above mu fn %.17g", hypot(r.fx, r.fy),
                    pb.mu * r.fn);
        if (r.ncontact < 1 || r.nslip < 0 || r.nslip > r.ncontact)
            fz_fail("rr_exact_solve: %d elements in contact, %d slipping", r.ncontact, r.nslip);
    }
    if (want_field)
        check_fields(&pb, st, &r, &f);
    if (pb.h && wmode > 1)
        grid_problem(&pb, st, &r);
    if (st >= 0) {
        /* again, with the workspace as the first solve left it */
        st2 = rr_exact_solve(&pb, work, wgive, &r2, NULL);
        same_solve("a second solve", st2, &r2, st, &r);
    }
    if (work && wmode > 1) {
        if (nan_work) {
            /* what a case of NaN gave, a fresh workspace gives */
            double *fresh = fz_alloc(wl * sizeof *fresh);
            memset(fresh, 0, wl * sizeof *fresh);
            st2 = rr_exact_solve(&pb, fresh, wl, &r2, NULL);
            same_solve("a fresh workspace (the first had NaN)", st2, &r2, st, &r);
            free(fresh);
        }
        if (stop_at > 0) {
            poll_count c = {0, 0};
            rr_interrupt hook;
            rr_exact_problem p3 = pb;
            c.stop_at = stop_at;
            hook.poll = count_polls;
            hook.ctx = &c;
            p3.interrupt = &hook;
            st2 = rr_exact_solve(&p3, work, wgive, &r2, NULL);
            fz_status("rr_exact_solve", st2);
            if (c.polls > stop_at)
                fz_fail("rr_exact_solve: polled %d times after the hook stopped it at %d",
                        c.polls, stop_at);
            if (c.polls == stop_at && (st2 != RR_ERR_INTERRUPTED || !isnan(r2.fx)))
                fz_fail("rr_exact_solve: the hook stopped it, status %d, fx %.17g", st2, r2.fx);
            if (c.polls < stop_at)
                same_solve("a solve with a hook that did not stop it", st2, &r2, st, &r);
            /* and the workspace after the interrupted solve */
            st2 = rr_exact_solve(&pb, work, wgive, &r2, NULL);
            same_solve("a solve after an interrupted one", st2, &r2, st, &r);
        }
        if (fz_choice(&in, 2))
            warm_start(&in, &pb, work, wgive, st, &r, want_field ? &f : NULL, invalid);
    }
    free(h);
    fz_guard_free(work);
    fz_guard_free(f.pn);
    fz_guard_free(f.px);
    fz_guard_free(f.py);
    fz_guard_free(f.sx);
    fz_guard_free(f.sy);
    fz_guard_free(f.state);
    return 0;
}
