/*
 * fuzz_nonhertz.c - the non-Hertzian contact's run time (rr_nonhertz.h):
 * rr_nonhertz_table_check, rr_nonhertz_locate, rr_nonhertz_wheel on tables
 * and states from the input.
 *
 * The table: 2 .. 6 rows (spacing from 1 um to 5 mm, now and then not
 * increasing), each of 1 or 2 patches (now and then 0 or 3): a Hertz-like
 * patch (curvatures, plane angle, a gap for the second) with every node
 * quantity scaled by a factor near 1 and now and then replaced by any
 * value (an edge value: 0, negative, NaN, huge); the correction small or
 * anything; the header's sigma, R0, G, nu, mu_ref plausible or not.  The
 * state: y inside or beyond the rows, Fz from 1 N to 1e7 N (or not
 * positive), mu, the rollers' and the wheelset's speeds (rolling, sliding,
 * spinning), vmin, half the time a longitudinal shift and a yaw, each now
 * and then an edge value.
 *
 * Oracles: a documented status; a table the check refuses is refused by
 * the wheel too; a non-finite state value gives RR_ERR_NONFINITE, y beyond
 * the rows RR_ERR_TABLE; on error the result is NaN; on success finite
 * force, moment, centre, N > 0, the patches' forces summing to the total,
 * rows i, i + 1 bracketing y with the weight in [0, 1].
 */
#include "fuzz.h"

#define MAX_ROWS 6

static double rows[MAX_ROWS * RR_NH_ROW_LEN];

/* A value v, or now and then an edge one. */
static double maybe(fz_in *in, double v)
{
    return fz_choice(in, 24) == 0 ? fz_edge_value(fz_u8(in)) : v;
}

/* A Hertz-like patch from a few numbers (the input is short): curvatures,
 * plane angle, place, scales of the coefficients, the correction's size;
 * every node quantity exact for that ellipse. */
static void decode_patch(fz_in *in, double *p, double g)
{
    const double A = fz_log(in, 0.1, 100.0), B = fz_log(in, 0.1, 100.0);
    const double delta = fz_lin(in, -1.2, 1.2), G = 8.2e10, nu = 0.28;
    const double ab = sqrt(B / A), PY = fz_lin(in, 0.5, 1.0), PZ = fz_lin(in, -0.02, 0.02);
    const double k11 = fz_lin(in, 0.5, 2.0), k22 = fz_lin(in, 0.5, 2.0);
    const double k23 = fz_lin(in, -1.0, 3.0), xc = fz_lin(in, -1e-4, 1e-4);
    const double yc = fz_lin(in, -1e-3, 1e-3), corr = fz_choice(in, 2) ? fz_slog(in, 1e-6, 0.2)
                                                                       : 0.0;
    int k, c, m;
    p[0] = g;
    for (k = 0; k < RR_NH_NODES; k++) {
        const double N = 10.0 * pow(3.0, k);
        /* Hertz's approach and ellipse, roughly (plausible sizes, not digits) */
        const double c2 = pow(3.0 * N * (1.0 - nu) / (8.0 * G * sqrt(A * B)), 2.0 / 3.0);
        const double e = c2 * sqrt(A * B) * 2.0;
        p[RR_NH_NODE(RR_NH_E, k)] = e;
        p[RR_NH_NODE(RR_NH_Q, k)] = N / pow(e, 1.5);
        p[RR_NH_NODE(RR_NH_PY, k)] = PY;
        p[RR_NH_NODE(RR_NH_PZ, k)] = PZ;
        p[RR_NH_NODE(RR_NH_DELTA, k)] = delta;
        p[RR_NH_NODE(RR_NH_XC, k)] = xc;
        p[RR_NH_NODE(RR_NH_YC, k)] = yc;
        p[RR_NH_NODE(RR_NH_AREA, k)] = RR_PI * c2 / pow(N, 2.0 / 3.0);
        p[RR_NH_NODE(RR_NH_PMAX, k)] = 1.5 * N / (RR_PI * c2) / cbrt(N);
        p[RR_NH_NODE(RR_NH_AB, k)] = ab < 0.1 ? 0.1 : ab > 10.0 ? 10.0 : ab;
        p[RR_NH_NODE(RR_NH_K11, k)] = G * c2 * 4.0 * k11;
        p[RR_NH_NODE(RR_NH_K22, k)] = G * c2 * 3.5 * k22;
        p[RR_NH_NODE(RR_NH_K23, k)] = G * c2 * sqrt(c2) * k23;
    }
    for (c = 0; c < RR_NH_CORR; c++) {
        double *cb = p + RR_NH_CORR_AT(c);
        cb[0] = p[RR_NH_NODE(RR_NH_E, c == 0 ? RR_NH_CORR_NODE0 : RR_NH_CORR_NODE1)];
        for (m = 1; m < RR_NH_CORR_LEN; m++)
            cb[m] = corr * sin(1.7 * m + c);
    }
}

static int finite_result(const rr_nh_result *r)
{
    const double v[] = {r->force[0], r->force[1], r->force[2], r->moment[0], r->moment[1],
                        r->moment[2], r->centre[0], r->centre[1], r->centre[2], r->N,
                        r->area, r->pmax};
    int k;
    for (k = 0; k < RR_COUNTOF(v); k++)
        if (!isfinite(v[k]))
            return 0;
    return 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    const char *fn = "rr_nonhertz_wheel";
    rr_nh_table t;
    rr_nh_state s;
    rr_nh_result r;
    double y = 0.0, w = -1.0, sum[3] = {0.0, 0.0, 0.0};
    int i, j, k, st, cst, bad, row = -1, nonfinite;

    /* the header and the state first (the rows take the rest of the input) */
    memset(&t, 0, sizeof t);
    t.nrows = fz_range(&in, 2, MAX_ROWS);
    t.sigma = fz_choice(&in, 16) == 0 ? fz_lin(&in, -2.0, 2.0) : (fz_choice(&in, 2) ? 1.0 : -1.0);
    t.R0 = maybe(&in, fz_lin(&in, 0.1, 1.0));
    t.G = maybe(&in, 8.2e10);
    t.nu = maybe(&in, 0.28);
    t.mu_ref = maybe(&in, 0.4);
    memset(&s, 0, sizeof s);
    s.y = fz_lin(&in, -1.2, 1.2);         /* where in the rows' span, below */
    s.Fz = maybe(&in, fz_log(&in, 1.0, 1e7));
    s.mu = maybe(&in, fz_lin(&in, 0.05, 1.0));
    s.roller_spin = maybe(&in, fz_slog(&in, 1e-3, 100.0));
    s.vmin = maybe(&in, fz_log(&in, 1e-4, 1.0));
    s.x = fz_choice(&in, 2) ? 0.0 : maybe(&in, fz_lin(&in, -0.02, 0.02));
    s.yaw = fz_choice(&in, 2) ? 0.0 : maybe(&in, fz_lin(&in, -0.05, 0.05));
    for (j = 0; j < 2; j++)
        for (k = 0; k < 3; k++) {
            s.motion[j].c[k] = maybe(&in, k == 2 ? fz_lin(&in, 0.3, 0.5) : fz_lin(&in, -0.01, 0.01));
            s.motion[j].v[k] = maybe(&in, fz_slog(&in, 1e-6, 1.0));
            s.motion[j].w[k] = maybe(&in, k == 1 ? fz_slog(&in, 1e-3, 100.0)
                                                 : fz_slog(&in, 1e-6, 1.0));
        }
    for (i = 0; i < t.nrows; i++) {
        double *rw = rows + i * RR_NH_ROW_LEN;
        memset(rw, 0, RR_NH_ROW_LEN * sizeof *rw);
        rw[0] = y;
        y += fz_log(&in, 1e-6, 5e-3) * (fz_choice(&in, 32) == 0 ? -1.0 : 1.0);
        rw[1] = fz_choice(&in, 16) == 0 ? fz_int(&in, 0, 3) : 1 + fz_choice(&in, 2);
        rw[2] = fz_lin(&in, 0.3, 0.5);
        rw[3] = fz_lin(&in, -1e-3, 1e-3);
        for (j = 0; j < RR_NH_MAX_PATCHES; j++)
            decode_patch(&in, rw + RR_NH_PATCH(j), j == 0 ? 0.0 : fz_log(&in, 1e-7, 1e-3));
        /* now and then one value of the row anything */
        if (fz_choice(&in, 8) == 0)
            rw[fz_range(&in, 0, RR_NH_ROW_LEN - 1)] = fz_edge_value(fz_u8(&in));
    }
    t.rows = rows;
    /* y: inside the rows' span for |s.y| <= 1, beyond it else */
    {
        const double y0 = rows[0], y1 = rows[(t.nrows - 1) * RR_NH_ROW_LEN];
        s.y = maybe(&in, 0.5 * (y0 + y1) + 0.5 * s.y * (y1 - y0));
    }
    fz_note("rows %d, y %.17g, Fz %.17g, mu %.17g, roller_spin %.17g, vmin %.17g, sigma %g",
            t.nrows, s.y, s.Fz, s.mu, s.roller_spin, s.vmin, t.sigma);

    cst = rr_nonhertz_table_check(&t, &bad);
    fz_status("rr_nonhertz_table_check", cst);
    if (cst < 0 && cst != RR_ERR_TABLE)
        fz_fail("rr_nonhertz_table_check: status %d (documented: RR_ERR_TABLE)", cst);
    if (cst < 0 && !(bad >= -1 && bad < t.nrows))
        fz_fail("rr_nonhertz_table_check: bad row %d of %d", bad, t.nrows);
    if (cst < 0)
        return 0;      /* the wheel takes checked tables (the binding checks first) */

    st = rr_nonhertz_locate(&t, s.y, &row, &w);
    fz_status("rr_nonhertz_locate", st);
    if (st == RR_OK && !(row >= 0 && row + 1 < t.nrows && w >= 0.0 && w <= 1.0
                         && rows[row * RR_NH_ROW_LEN] <= s.y
                         && s.y <= rows[(row + 1) * RR_NH_ROW_LEN]))
        fz_fail("rr_nonhertz_locate: row %d weight %.17g for y %.17g", row, w, s.y);

    nonfinite = !isfinite(s.y) || !isfinite(s.Fz) || !isfinite(s.mu) || !isfinite(s.roller_spin)
                || !isfinite(s.vmin) || !isfinite(s.x) || !isfinite(s.yaw);
    for (j = 0; j < 2; j++)
        for (k = 0; k < 3; k++)
            nonfinite |= !isfinite(s.motion[j].c[k]) || !isfinite(s.motion[j].v[k])
                         || !isfinite(s.motion[j].w[k]);
    memset(&r, 0x55, sizeof r);
    st = rr_nonhertz_wheel(&t, &s, &r);
    fz_status(fn, st);
    if (nonfinite && st != RR_ERR_NONFINITE)
        fz_fail("%s: status %d for a non-finite state (documented: RR_ERR_NONFINITE)", fn, st);
    if (!nonfinite && isfinite(s.y) && (s.y < rows[0] || s.y > rows[(t.nrows - 1) * RR_NH_ROW_LEN])
        && st != RR_ERR_TABLE && s.Fz > 0.0 && s.mu > 0.0 && s.vmin > 0.0)
        fz_fail("%s: status %d for y beyond the rows (documented: RR_ERR_TABLE)", fn, st);
    fz_error(fn, st, !(s.Fz > 0.0) || !(s.mu > 0.0) || !(s.vmin > 0.0), "a state value is invalid");
    if (st < 0) {
        if (!isnan(r.force[0]) || !isnan(r.N) || !isnan(r.moment[2]))
            fz_fail("%s: error %d but the result is not NaN", fn, st);
        return 0;
    }
    if (!finite_result(&r))
        fz_fail("%s: status %d with a non-finite result", fn, st);
    if (!(r.N > 0.0) || r.npatch < 1 || r.npatch > RR_NH_MAX_PATCHES || r.row != row)
        fz_fail("%s: N %.17g, %d patches, row %d (locate: %d)", fn, r.N, r.npatch, r.row, row);
    for (j = 0; j < r.npatch; j++)
        for (k = 0; k < 3; k++)
            sum[k] += r.patch[j].force[k];
    for (k = 0; k < 3; k++)
        if (!(fabs(sum[k] - r.force[k]) <= 1e-9 * (fabs(r.force[k]) + r.N)))
            fz_fail("%s: the patches' forces sum to %.17g, the total is %.17g", fn, sum[k],
                    r.force[k]);
    return 0;
}
