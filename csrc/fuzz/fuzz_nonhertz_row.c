/*
 * fuzz_nonhertz_row.c - one row of the non-Hertzian table built by the
 * exact theory (rr_nonhertz_row), on profiles, sites and problems from the
 * input.
 *
 * Profiles and pair: half the inputs the 1/5 rig's kind (a cone on a
 * crowned roller, its points now and then moved), the others fuzz_gap's
 * (fuzz_profile.h).  The site: the zero-gap
 * pose and contact point rr_wheelset_contact finds at the row's shift (the
 * right pair the left's mirror), now and then moved, else numbers from the
 * input; the wheelset's free-rolling motion there (as nonhertz_table
 * builds it) or any.  The problem: the loads (Fz_regions from 0 to Fz_max,
 * now and then beyond), material, friction, grids kept small (n 8 .. 12,
 * n_corr 8 .. n, Richardson one time in 8) so that a row takes
 * milliseconds, now and then any n, combine, tolerance and iterations;
 * the grid side n + 4 to n + 16 (or anything), the workspace as long as asked
 * or shorter; now and then a NULL.
 *
 * Oracles: a documented status; an invalid argument refused (a NULL, a
 * number not finite, a load out of order, n, n_corr, richardson or
 * combine out of range, a workspace shorter than
 * rr_nonhertz_row_workspace_len); on error the row all NaN and info's why
 * and places in range; on success info says OK, its patches the row's,
 * the row's head the shift and pose given, and the row a valid table row
 * (rr_nonhertz_table_check on a table of it and its copy 1 mm on); nothing
 * written outside the row, info or the workspace (guard bytes); a grid
 * beyond the side refused with the side it needs.
 */
#include "fuzz.h"
#include "fuzz_profile.h"

#define MAX_SIDE 40
#define MAX_WORK ((size_t)1 << 23)   /* doubles: 64 MB */

/* The 1/5 rig's kind of pair (a 1:20 cone, 60 mm wide, on a roller crowned
 * at 0.3 m), each profile's points now and then moved by up to a
 * micrometre: the rows the rig builds. */
static int plain_pair(fz_in *in, fz_profile *w, fz_profile *r, rr_wheel_roller *p)
{
    double work[FZ_PROFILE_POINTS];
    const double amp = fz_choice(in, 4) == 1 ? fz_log(in, 1e-9, 1e-6) : 0.0;
    int i, st;
    w->n = 41;
    r->n = 41;
    for (i = 0; i < 41; i++) {
        w->s[i] = -0.03 + 1.5e-3 * i;
        w->z[i] = 0.05 * w->s[i] + amp * fz_lin(in, -1.0, 1.0);
        r->s[i] = -0.02 + 1e-3 * i;
        r->z[i] = sqrt(0.09 - r->s[i] * r->s[i]) - 0.3 + amp * fz_lin(in, -1.0, 1.0);
    }
    if ((st = rr_spline_init(w->n, w->s, w->z, w->m, work)) != RR_OK
        || (st = rr_spline_init(r->n, r->s, r->z, r->m, work)) != RR_OK)
        return st;
    fz_attach_profiles(w, r, p);
    p->r0 = 0.09;
    p->R0 = 0.19;
    p->wheel_y = 0.15;
    p->roller_y = 0.15;
    p->side = 1;
    fz_note("plain pair, points moved by %.17g; ", amp);
    return RR_OK;
}

/* The zero-gap pose and this side's point at pb->y_ws, or numbers. */
static void decode_site(fz_in *in, const rr_wheel_roller *pl, rr_nh_row_problem *pb)
{
    rr_wheel_roller pr = *pl;
    rr_search_opts so;
    rr_contact_point cr;
    int found = 0;
    pr.side = pl->side == 1 ? -1 : 1;
    rr_search_opts_default(&so);
    memset(&pb->point, 0, sizeof pb->point);
    if (pl->side == 1 || pl->side == -1)
        found = rr_wheelset_contact(pl, &pr, pb->y_ws, &so, &pb->pose0, &pb->point, &cr) >= 0;
    if (!found || fz_choice(in, 16) == 1) {
        pb->pose0.z = pl->r0 + fz_lin(in, -0.01, 0.01);
        pb->pose0.roll = fz_lin(in, -0.05, 0.05);
        pb->point.s_roller = fz_lin(in, -0.02, 0.02);
        pb->point.s_wheel = fz_lin(in, -0.02, 0.02);
        pb->point.delta = fz_lin(in, -0.6, 0.6);
        pb->point.A = fz_log(in, 0.1, 100.0);
        pb->point.B = fz_log(in, 0.1, 100.0);
    }
    {
        /* free rolling about the rolled axle (nonhertz_table's motion) */
        const double spin = fz_choice(in, 8) == 1 ? fz_lin(in, -100.0, 100.0)
                                                  : 10.0 * pl->R0 / pl->r0;
        pb->roller_spin = fz_choice(in, 8) == 1 ? fz_lin(in, -100.0, 100.0) : 10.0;
        pb->wheelset.c[0] = 0.0;
        pb->wheelset.c[1] = pb->y_ws;
        pb->wheelset.c[2] = pb->pose0.z;
        pb->wheelset.v[0] = pb->wheelset.v[1] = pb->wheelset.v[2] = 0.0;
        pb->wheelset.w[0] = 0.0;
        pb->wheelset.w[1] = spin * cos(pb->pose0.roll);
        pb->wheelset.w[2] = spin * sin(pb->pose0.roll);
    }
    fz_note("site y_ws %.17g found %d z %.17g roll %.17g s_roller %.17g s_wheel %.17g "
            "delta %.17g A %.17g B %.17g roller_spin %.17g; ", pb->y_ws, found, pb->pose0.z,
            pb->pose0.roll, pb->point.s_roller, pb->point.s_wheel, pb->point.delta,
            pb->point.A, pb->point.B, pb->roller_spin);
}

static void decode_problem(fz_in *in, rr_nh_row_problem *pb)
{
    /* loads for the pair's scale: the rig's hundreds of N to full scale */
    pb->Fz_max = fz_log(in, 10.0, 1e5);
    pb->Fz_regions = fz_choice(in, 4) == 1 ? 0.0 : pb->Fz_max * fz_lin(in, 0.0, 1.0);
    if (fz_choice(in, 16) == 1)
        pb->Fz_regions = fz_lin(in, -1e5, 1e6);
    pb->E = fz_near(in, 2.1e11, 10.0);
    pb->nu = fz_choice(in, 8) == 1 ? fz_lin(in, 0.0, 0.5) : 0.28;   /* the tables' nu */
    pb->mu = fz_lin(in, 0.05, 1.0);
    pb->vmin = fz_log(in, 1e-4, 1e-2);
    pb->n = fz_choice(in, 16) == 1 ? fz_int(in, -1, 1000) : fz_range(in, 8, 12);
    pb->n_corr = fz_choice(in, 16) == 1 ? fz_int(in, -1, 1000) : fz_range(in, 8, pb->n);
    pb->richardson = fz_choice(in, 16) == 1 ? fz_int(in, -1, 2) : fz_choice(in, 8) == 1;
    pb->combine = fz_choice(in, 8) == 1 ? fz_lin(in, -1e-3, 1e-2) : 4e-3;
    pb->tol = fz_choice(in, 8) == 1 ? fz_log(in, 1e-9, 1.0) : fz_log(in, 1e-6, 1e-3);
    pb->maxit = fz_choice(in, 8) == 1 ? fz_int(in, -1, 50) : fz_range(in, 50, 400);
    fz_note("Fz_max %.17g Fz_regions %.17g E %.17g nu %.17g mu %.17g vmin %.17g n %d n_corr %d "
            "richardson %d combine %.17g tol %.17g maxit %d; ", pb->Fz_max, pb->Fz_regions,
            pb->E, pb->nu, pb->mu, pb->vmin, pb->n, pb->n_corr, pb->richardson, pb->combine,
            pb->tol, pb->maxit);
}

/* 1 where an argument rr_nonhertz_row checks itself is wrong (the solver's
 * own refusals, of E, nu, mu, tol or maxit, come as any error). */
static int row_invalid(const rr_nh_row_problem *pb)
{
    const double v[] = {pb->y_ws, pb->pose0.z, pb->pose0.roll, pb->Fz_max, pb->Fz_regions,
                        pb->E, pb->nu, pb->mu, pb->roller_spin, pb->vmin, pb->combine,
                        pb->tol, pb->point.s_roller, pb->point.s_wheel, pb->point.delta,
                        pb->point.A, pb->point.B};
    size_t i;
    for (i = 0; i < sizeof v / sizeof v[0]; i++)
        if (!isfinite(v[i]))
            return 1;
    for (i = 0; i < 3; i++)
        if (!isfinite(pb->wheelset.c[i]) || !isfinite(pb->wheelset.v[i])
            || !isfinite(pb->wheelset.w[i]))
            return 1;
    return !(pb->Fz_max > 0.0) || !(pb->Fz_regions >= 0.0) || !(pb->Fz_regions <= pb->Fz_max)
        || pb->n < 8 || pb->n > RR_GAP_MAX_N / 2 || pb->n_corr < 8 || pb->n_corr > pb->n
        || (pb->richardson != 0 && pb->richardson != 1) || !(pb->combine >= 0.0);
}

/* A successful row: info and the head as given, and a valid table row. */
static void check_row(const rr_nh_row_problem *pb, const rr_wheel_roller *pl, int st,
                      const double *row, const rr_nh_row_info *info)
{
    const char *fn = "rr_nonhertz_row";
    double rows[2 * RR_NH_ROW_LEN];
    rr_nh_table t;
    int bad = -2, tst;
    fz_finite_n(fn, st, "row", row, RR_NH_ROW_LEN);
    if (info->why != RR_NH_ROW_OK || info->patches < 1 || info->patches > RR_NH_MAX_PATCHES
        || row[1] != info->patches)
        fz_fail("%s: status %d but info why %d, patches %d, row's %.17g", fn, st, info->why,
                info->patches, row[1]);
    if (row[0] != pb->y_ws || row[2] != pb->pose0.z || row[3] != pb->pose0.roll)
        fz_fail("%s: head (%.17g, %.17g, %.17g), not the shift and pose given", fn, row[0],
                row[2], row[3]);
    if (pl->side != 1 && pl->side != -1)
        return;          /* no table side to check it on */
    memcpy(rows, row, sizeof rows / 2);
    memcpy(rows + RR_NH_ROW_LEN, row, sizeof rows / 2);
    rows[RR_NH_ROW_LEN] = row[0] + 1e-3;
    if (!(rows[RR_NH_ROW_LEN] > row[0]))
        return;          /* a shift so large that 1 mm on is itself */
    t.nrows = 2;
    t.rows = rows;
    t.sigma = pl->side;
    t.R0 = pl->R0;
    t.G = pb->E / (2.0 * (1.0 + pb->nu));
    t.nu = pb->nu;
    t.mu_ref = pb->mu;
    tst = rr_nonhertz_table_check(&t, &bad);
    if (tst != RR_OK)
        fz_fail("%s: status %d but rr_nonhertz_table_check says %d (row %d)", fn, st, tst, bad);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *fn = "rr_nonhertz_row";
    fz_in in = fz_start(data, size);
    fz_profile w, r;
    rr_wheel_roller p;
    rr_nh_row_problem pb;
    rr_nh_row_info info;
    double *work, *row;
    size_t need, len, work_bytes;
    int side, st, null_pb, null_pair, null_work, null_row, invalid;

    if (fz_choice(&in, 2) == 0) {
        if (plain_pair(&in, &w, &r, &p) != RR_OK)
            return 0;
    } else {
        in.edges = 0;
        if (fz_decode_profile(&in, &w, 0, 4, 0) != RR_OK
            || fz_decode_profile(&in, &r, 1, 4, 0) != RR_OK)
            return 0;
        in.edges = 1;
        fz_set_pair(&in, &w, &r, &p);
    }
    rr_nonhertz_row_default(&pb);
    pb.pair = &p;
    pb.y_ws = fz_lin(&in, -0.005, 0.005);
    decode_site(&in, &p, &pb);
    decode_problem(&in, &pb);
    /* the binding's side, n + 16, or a little less (a grid that needs more:
     * RR_ERR_WORKSPACE, the side it needs) */
    side = fz_choice(&in, 16) == 1 ? fz_int(&in, -1, 100) : pb.n + 16 - fz_range(&in, 0, 12);
    null_pb = fz_choice(&in, 32) == 1;
    null_pair = fz_choice(&in, 32) == 1;
    null_work = fz_choice(&in, 32) == 1;
    null_row = fz_choice(&in, 32) == 1;
    if (null_pair)
        pb.pair = NULL;
    need = rr_nonhertz_row_workspace_len(null_pb ? NULL : &pb, side);
    /* the length a row asks for, or short of it (a grid beyond the side's
     * comes as RR_ERR_WORKSPACE with the side it needs) */
    len = need;
    if (fz_choice(&in, 8) == 1)
        len = (size_t)((double)need * fz_lin(&in, 0.0, 1.0));
    if ((side > MAX_SIDE || len > MAX_WORK) && len > 0)
        len = 1;         /* the memory stays small: only the refusal is checked */
    fz_note("side %d workspace %zu of %zu; NULL pb %d pair %d work %d row %d", side, len, need,
            null_pb, null_pair, null_work, null_row);
    work_bytes = (len > 0 ? len : 1) * sizeof(double);
    work = fz_guarded(work_bytes);
    memset(work, 0, work_bytes);   /* zero-filled, as documented */
    row = fz_guarded(RR_NH_ROW_LEN * sizeof(double));
    invalid = null_pb || null_pair || null_work || null_row || row_invalid(&pb);

    st = rr_nonhertz_row(null_pb ? NULL : &pb, null_work ? NULL : work, len, side,
                         null_row ? NULL : row, &info);
    fz_status(fn, st);
    fz_error(fn, st, invalid, "an argument is invalid");
    fz_error(fn, st, !invalid && need == 0, "rr_nonhertz_row_workspace_len is 0");
    fz_error(fn, st, len < need, "the workspace is shorter than asked");
    if (st < 0) {
        if (!null_row && !fz_all_nan(row, RR_NH_ROW_LEN))
            fz_fail("%s: error %d but the row is not NaN", fn, st);
        if (st == RR_ERR_WORKSPACE && len >= need && need > 0 && !(info.need > (size_t)side))
            fz_fail("%s: RR_ERR_WORKSPACE on the length asked, but needs side %zu of %d", fn,
                    info.need, side);
        if (info.why < RR_NH_ROW_OK || info.why > RR_NH_ROW_COEFF
            || info.patch < -1 || info.patch >= RR_NH_MAX_PATCHES || info.node < -1
            || info.node >= RR_NH_NODES)
            fz_fail("%s: error %d with info why %d, patch %d, node %d", fn, st, info.why,
                    info.patch, info.node);
    } else {
        if (st != RR_OK && st != RR_WARN_NOT_CONVERGED)
            fz_fail("%s: status %d, not OK or not converged", fn, st);
        check_row(&pb, &p, st, row, &info);
    }
    fz_guard_ok(fn, work, work_bytes, "the workspace");
    fz_guard_ok(fn, row, RR_NH_ROW_LEN * sizeof(double), "row[RR_NH_ROW_LEN]");
    fz_guard_free(work);
    fz_guard_free(row);
    return 0;
}
