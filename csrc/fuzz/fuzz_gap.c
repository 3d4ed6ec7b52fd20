/*
 * fuzz_gap.c - the undeformed distance of a wheel on its roller
 * (rr_gap_build) and one wheel solved by the exact theory on it
 * (rr_wheel_exact), on profiles, poses and options from the input.
 *
 * Profiles: the wheel a cone, the roller a circular crown, each on 4 .. 80
 * points (or that shape perturbed point by point, or a free point list);
 * the pair's radii, places and side (now and then not +-1).  The site: the
 * zero-gap pose and contact point of rr_wheelset_contact where it has one
 * (the right pair the left's mirror), lowered by a little or by anything,
 * else numbers from the input; the options: each reference, approach,
 * cover, n, element sizes (none, plausible, or extreme), combine, now and
 * then out of range; the workspace as long as asked or shorter, h from
 * none to 4096 cells.  rr_wheel_exact on small grids (n 4 .. 12, maxit up
 * to 300) with N or Fz, creepages given or from a rigid motion.
 *
 * Oracles: a documented status; an invalid option refused; on success a
 * grid of 1 .. RR_EXACT_MAX_GRID a side within the caller's h, h finite
 * with least value 0, a unit frame with n = t1 x t2, x0 and y0 on whole
 * elements, at least one region; a short h refused with the grid it needs
 * (and that grid beyond h_len); nothing written outside the workspace or
 * h (guard bytes); rr_wheel_exact's success: finite forces, Coulomb's
 * bound mu fn, the force in the rig frame from its parts, the vertical
 * balance (Fz given) to the solver's load tolerance; the same call on the
 * workspace kept through one carved otherwise (h of half the length): the
 * fresh workspace's status and doubles.
 */
#include "fuzz.h"
#include "fuzz_profile.h"

#define MAX_CELLS 4096

static void decode_gap_opts(fz_in *in, rr_gap_opts *o, double approach_hint, int small)
{
    rr_gap_opts_default(o);
    o->reference = fz_choice(in, 8) == 0 ? fz_int(in, -1, 3) : fz_choice(in, 3);
    o->s_roller = fz_lin(in, -0.02, 0.02);
    o->delta = fz_lin(in, -0.6, 0.6);
    o->approach = fz_choice(in, 4) == 0 ? fz_log(in, 1e-9, 1e-2)
                                        : approach_hint * fz_log(in, 0.3, 3.0);
    o->cover = fz_choice(in, 8) == 0 ? fz_lin(in, 0.0, 10.0) : fz_lin(in, 1.0, 2.0);
    o->n = small ? fz_range(in, 4, 12) : (fz_choice(in, 8) == 0 ? fz_int(in, 0, 2000)
                                                               : fz_range(in, 4, 60));
    if (fz_choice(in, 3) == 0) {
        o->dx = fz_log(in, small ? 2e-4 : 5e-5, 5e-3);
        o->dy = fz_choice(in, 2) ? o->dx : fz_log(in, small ? 2e-4 : 5e-5, 5e-3);
    }
    o->combine = fz_choice(in, 8) == 0 ? fz_lin(in, -0.01, 0.01) : fz_lin(in, 0.0, 0.01);
    if (fz_choice(in, 4) == 0) {
        /* a band of rig Y (rr_nonhertz_table's patches): anywhere, any width,
         * sometimes empty or reversed, sometimes keep out of {0, 1} */
        o->keep = fz_choice(in, 16) == 0 ? fz_int(in, -1, 3) : 1;
        o->keep_lo = fz_lin(in, -1.0, 1.0);
        o->keep_hi = o->keep_lo + (fz_choice(in, 16) == 0 ? fz_lin(in, -0.01, 0.0)
                                                          : fz_log(in, 1e-5, 0.5));
    }
    if (fz_choice(in, 8) == 0)           /* the samples' spacing: in range, or out of it */
        o->sample = fz_choice(in, 4) == 0 ? fz_lin(in, -1e-3, 3e-3) : fz_log(in, 5e-6, 1e-4);
    fz_note("keep %d [%.17g, %.17g] sample %.17g ", o->keep, o->keep_lo, o->keep_hi,
            o->sample);
    fz_note("opts ref %d (%.17g, %.17g) approach %.17g cover %.17g n %d dx %.17g dy %.17g "
            "combine %.17g; ", o->reference, o->s_roller, o->delta, o->approach, o->cover, o->n,
            o->dx, o->dy, o->combine);
}

static int opts_invalid(const rr_gap_opts *o, const rr_wheel_roller *p)
{
    const int ref_ok = o->reference == RR_GAP_WEIGHTED || o->reference == RR_GAP_POINT
                       || (o->reference == RR_GAP_GIVEN && isfinite(o->s_roller)
                           && fabs(o->delta) < 0.5 * RR_PI);
    return !ref_ok || !(o->approach > 0.0) || !isfinite(o->approach) || !(o->cover >= 1.0)
           || !isfinite(o->cover) || o->n < 4 || o->n > RR_GAP_MAX_N || !(o->dx >= 0.0)
           || !(o->dy >= 0.0) || !isfinite(o->dx) || !isfinite(o->dy)
           || !(o->combine >= 0.0) || !isfinite(o->combine) || (p->side != 1 && p->side != -1)
           || (o->keep != 0 && o->keep != 1) || (o->keep && !(o->keep_lo < o->keep_hi))
           || !(o->sample == 0.0
                || (o->sample >= RR_GAP_SAMPLE_MIN && o->sample <= RR_GAP_SAMPLE_MAX));
}

static void check_patch(const char *fn, int st, const rr_gap_patch *P, const double *h,
                        size_t h_len)
{
    const rr_grid *g = &P->grid;
    double cr[3], hmin = INFINITY;
    int k;
    if (st < 0)
        return;
    if (g->mx < 1 || g->my < 1 || g->mx > RR_EXACT_MAX_GRID || g->my > RR_EXACT_MAX_GRID
        || (size_t)g->mx * (size_t)g->my > h_len)
        fz_fail("%s: OK with a %d x %d grid in %zu cells", fn, g->my, g->mx, h_len);
    for (k = 0; k < g->mx * g->my; k++) {
        if (!isfinite(h[k]) || h[k] < 0.0)
            fz_fail("%s: OK with h[%d] = %g", fn, k, h[k]);
        hmin = h[k] < hmin ? h[k] : hmin;
    }
    if (hmin != 0.0)
        fz_fail("%s: OK with least h %g, not 0", fn, hmin);
    {
        const double f[] = {g->dx, g->dy, g->x0, g->y0, P->delta, P->s_roller, P->s_wheel,
                            P->r, P->R, P->pen, P->point[1], P->point[2], P->wheel_point[1],
                            P->wheel_point[2], P->lo, P->hi, P->half_length};
        fz_finite_n(fn, st, "patch number", f, RR_COUNTOF(f));
    }
    cr[0] = P->t1[1] * P->t2[2] - P->t1[2] * P->t2[1];
    cr[1] = P->t1[2] * P->t2[0] - P->t1[0] * P->t2[2];
    cr[2] = P->t1[0] * P->t2[1] - P->t1[1] * P->t2[0];
    for (k = 0; k < 3; k++)
        if (!(fabs(cr[k] - P->n[k]) < 1e-12))
            fz_fail("%s: n is not t1 x t2", fn);
    if (!(fabs(g->x0 / g->dx - floor(g->x0 / g->dx + 0.5)) < 1e-6)
        || !(fabs(g->y0 / g->dy - floor(g->y0 / g->dy + 0.5)) < 1e-6))
        fz_fail("%s: x0 %.17g, y0 %.17g not on whole elements %.17g, %.17g", fn, g->x0, g->y0,
                g->dx, g->dy);
    if (P->nregions < 1 || P->nregions > RR_GAP_MAX_RUNS || P->nexcluded < 0
        || P->nregions + P->nexcluded > RR_GAP_MAX_RUNS || !(P->pen >= 0.0))
        fz_fail("%s: regions %d, excluded %d, pen %g", fn, P->nregions, P->nexcluded, P->pen);
}

/* The site: the zero-gap pose's where the pair has one, else the input's. */
static void decode_site(fz_in *in, rr_wheel_roller *pl, rr_gap_site *site, double *hint,
                        rr_contact_point *cpt)
{
    rr_wheel_roller pr = *pl;
    rr_search_opts so;
    rr_wheelset_pose pose;
    rr_contact_point cl, cr;
    pr.side = pl->side == 1 ? -1 : 1;            /* used only for a side of +-1 */
    rr_search_opts_default(&so);
    site->pair = pl;
    site->y_ws = fz_lin(in, -0.005, 0.005);
    *hint = 5e-5;
    memset(cpt, 0, sizeof *cpt);
    if ((pl->side == 1 || pl->side == -1)
        && rr_wheelset_contact(pl, &pr, site->y_ws, &so, &pose, &cl, &cr) >= 0) {
        rr_hertz_result hz;
        site->z = pose.z - (fz_choice(in, 8) == 0 ? fz_lin(in, -0.01, 0.01)
                                                   : fz_log(in, 1e-9, 1e-4));
        site->roll = pose.roll;
        site->s_roller = cl.s_roller;
        site->s_wheel = cl.s_wheel;
        site->delta = cl.delta;
        *cpt = cl;
        if (rr_hertz(cl.A, cl.B, fz_log(in, 10.0, 1e5), rr_estar(2.1e11, 0.28, 2.1e11, 0.28),
                     &hz) == RR_OK)
            *hint = hz.delta;
    } else {
        site->z = pl->r0 + fz_lin(in, -0.01, 0.01);
        site->roll = fz_lin(in, -0.05, 0.05);
        site->s_roller = fz_lin(in, -0.02, 0.02);
        site->s_wheel = fz_lin(in, -0.02, 0.02);
        site->delta = fz_lin(in, -0.6, 0.6);
    }
    fz_note("site y_ws %.17g z %.17g roll %.17g s_roller %.17g s_wheel %.17g delta %.17g; ",
            site->y_ws, site->z, site->roll, site->s_roller, site->s_wheel, site->delta);
}

static void check_gap(fz_in *in, rr_wheel_roller *p)
{
    const char *fn = "rr_gap_build";
    rr_gap_site site;
    rr_gap_opts o;
    rr_gap_patch P;
    rr_contact_point cpt;
    double hint, *work, *h;
    size_t need, wl, h_len;
    int st, short_work;

    decode_site(in, p, &site, &hint, &cpt);
    decode_gap_opts(in, &o, hint, 0);
    need = rr_gap_workspace_len(&o);
    short_work = fz_choice(in, 16) == 0;
    wl = short_work && need > 0 ? need - 1 - (size_t)fz_range(in, 0, 100) % need : need;
    h_len = fz_choice(in, 8) == 0 ? (size_t)fz_range(in, 0, 64) : MAX_CELLS;
    fz_note("work %zu of %zu, h %zu", wl, need, h_len);
    work = fz_guarded(wl * sizeof(double) + 1);
    h = fz_guarded(h_len * sizeof(double) + 1);
    st = rr_gap_build(&site, &o, work, wl, h, h_len, &P);
    fz_status(fn, st);
    fz_error(fn, st, opts_invalid(&o, p) || !isfinite(site.y_ws) || !isfinite(site.z)
                         || !(fabs(site.delta) < 0.5 * RR_PI) || wl < need,
             "an argument is invalid");
    check_patch(fn, st, &P, h, h_len);
    if (st == RR_ERR_WORKSPACE && P.why == RR_GAP_H_BUFFER
        && !((size_t)P.grid.mx * (size_t)P.grid.my > h_len))
        fz_fail("%s: h of %zu cells refused for a %d x %d grid", fn, h_len, P.grid.my,
                P.grid.mx);
    fz_guard_ok(fn, work, wl * sizeof(double), "the workspace");
    fz_guard_ok(fn, h, h_len * sizeof(double), "h");
    fz_guard_free(work);
    fz_guard_free(h);
}

static void check_wheel(fz_in *in, rr_wheel_roller *p)
{
    const char *fn = "rr_wheel_exact";
    rr_wheel_exact_problem pb;
    rr_wheel_exact_result r;
    rr_gap_site site;
    double hint, *work, *h, *pn;
    size_t wl, cells = 24 * 24;
    int st, k;

    rr_wheel_exact_default(&pb);
    decode_site(in, p, &site, &hint, &pb.point);
    pb.pair = p;
    pb.y_ws = site.y_ws;
    pb.pose0.z = site.z;
    pb.pose0.roll = site.roll;
    decode_gap_opts(in, &pb.gap, hint, 1);
    if (fz_choice(in, 2)) {
        pb.gap.approach = 0.0;                 /* Hertz's */
        fz_note("approach 0; ");
    }
    if (fz_choice(in, 2))
        pb.N = fz_log(in, 10.0, 1e5);
    else
        pb.Fz = fz_log(in, 10.0, 1e5);
    pb.mu = fz_log(in, 0.05, 1.0);
    pb.creep_given = fz_choice(in, 2);
    pb.cx = fz_slog(in, 1e-6, 1e-2);
    pb.cy = fz_slog(in, 1e-6, 1e-2);
    pb.cphi = fz_slog(in, 1e-3, 10.0);
    pb.roller_spin = fz_lin(in, -20.0, 20.0);
    for (k = 0; k < 3; k++) {
        pb.wheelset.c[k] = k == 2 ? site.z : 0.0;
        pb.wheelset.v[k] = fz_lin(in, -0.1, 0.1);
        pb.wheelset.w[k] = k == 1 ? fz_lin(in, -80.0, 80.0) : fz_lin(in, -0.1, 0.1);
    }
    pb.passes = fz_choice(in, 8) == 0 ? fz_int(in, 0, 3) : 1 + fz_choice(in, 2);
    pb.loaded = fz_choice(in, 2);
    pb.maxit = fz_range(in, 1, 300);
    pb.tol = 1e-4;
    fz_note("wheel N %.17g Fz %.17g mu %.17g creep %d (%.17g, %.17g, %.17g) passes %d loaded %d "
            "maxit %d", pb.N, pb.Fz, pb.mu, pb.creep_given, pb.cx, pb.cy, pb.cphi, pb.passes,
            pb.loaded, pb.maxit);
    wl = rr_wheel_exact_workspace_len(&pb, 24, 24);
    if (!wl)
        wl = 16;
    work = fz_guarded(wl * sizeof(double));
    memset(work, 0, wl * sizeof(double));      /* the solver's rule: zero-filled */
    h = fz_guarded(cells * sizeof(double));
    pn = fz_guarded(cells * sizeof(double));
    {
        rr_exact_field f;
        memset(&f, 0, sizeof f);
        f.pn = pn;
        st = rr_wheel_exact(&pb, work, wl, h, cells, &f, cells, &r);
    }
    fz_status(fn, st);
    {
        rr_gap_opts o = pb.gap;                  /* approach 0: Hertz's, valid here */
        o.approach = o.approach == 0.0 ? 1.0 : o.approach;
        fz_error(fn, st, opts_invalid(&o, p) || (pb.passes != 1 && pb.passes != 2),
                 "an option is invalid");
    }
    if (st >= 0) {
        const double f[] = {r.sol.fx, r.sol.fy, r.sol.mz, r.sol.fn, r.N, r.cx, r.cy, r.cphi,
                            r.force[0], r.force[1], r.force[2]};
        fz_finite_n(fn, st, "result", f, RR_COUNTOF(f));
        fz_bound(fn, st, r.sol.fx, r.sol.fy, pb.mu, r.sol.fn);
        for (k = 0; k < 3; k++)
            if (!(fabs(r.force[k] - (r.sol.fx * r.patch.t1[k] + r.sol.fy * r.patch.t2[k]
                                     + r.sol.fn * r.patch.n[k])) <= 1e-9 * (fabs(r.sol.fn) + 1.0)))
                fz_fail("%s: force[%d] is not fx t1 + fy t2 + fn n", fn, k);
        /* the balance is held to the solver's tolerance, at least 1e-7
         * (rr_wheel_exact.c's FZ_TOL; 1e-7 on cold starts) */
        if (pb.Fz > 0.0 && st == RR_OK
            && !(fabs(r.force[2] - pb.Fz) <= 1.001 * fmax(pb.tol, 1e-7) * pb.Fz))
            fz_fail("%s: OK with vertical force %.17g for Fz %.17g", fn, r.force[2], pb.Fz);
    }
    if (st >= 0) {
        /* the workspace kept through a call that carves it otherwise (h and
         * fields of half the length): the same call again gives the fresh
         * workspace's status and doubles */
        rr_exact_field f;
        rr_wheel_exact_result r2;
        int st2;
        memset(&f, 0, sizeof f);
        f.pn = pn;
        (void)rr_wheel_exact(&pb, work, wl, h, cells / 2, &f, cells / 2, &r2);
        st2 = rr_wheel_exact(&pb, work, wl, h, cells, &f, cells, &r2);
        if (st2 != st || memcmp(&r2.sol.fx, &r.sol.fx, sizeof r.sol.fx) != 0
            || memcmp(&r2.sol.fy, &r.sol.fy, sizeof r.sol.fy) != 0
            || memcmp(&r2.N, &r.N, sizeof r.N) != 0)
            fz_fail("%s: a kept workspace, carved otherwise between, gave status %d (%.17g, "
                    "%.17g, N %.17g), a fresh one %d (%.17g, %.17g, N %.17g)", fn, st2, r2.sol.fx,
                    r2.sol.fy, r2.N, st, r.sol.fx, r.sol.fy, r.N);
    }
    fz_guard_ok(fn, work, wl * sizeof(double), "the workspace");
    fz_guard_ok(fn, h, cells * sizeof(double), "h");
    fz_guard_ok(fn, pn, cells * sizeof(double), "pn");
    fz_guard_free(work);
    fz_guard_free(h);
    fz_guard_free(pn);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    fz_profile w, r;
    rr_wheel_roller p;
    const int which = fz_choice(&in, 4);
    in.edges = 0;
    if (fz_decode_profile(&in, &w, 0, 4, 0) != RR_OK || fz_decode_profile(&in, &r, 1, 4, 0) != RR_OK)
        return 0;
    in.edges = 1;
    fz_set_pair(&in, &w, &r, &p);
    if (which == 0)
        check_wheel(&in, &p);
    else
        check_gap(&in, &p);
    return 0;
}
