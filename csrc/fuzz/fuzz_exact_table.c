/*
 * fuzz_exact_table.c - the exact theory's table: rr_exact_table_check and
 * rr_exact_table_forces on the built-in table (nu mostly its own 0.28) and
 * on tables from the input (4 .. 6 nodes an axis, or a bad count; ends,
 * r0 and nu anything; values in [-2, 2] or NaN and huge ones).
 *
 * Oracles: the statuses the header gives (RR_ERR_PARAM exactly for a bad
 * table, RR_ERR_NULL for NULL pointers, RR_ERR_TABLE only where a/b is
 * outside the table or nu is not its own); NaN forces on error, finite ones
 * on success with |(fx, fy)| <= mu0 N; on the built-in table, reversing
 * every creepage reverses the forces bit for bit and a creepage-free case
 * has no force; Kalker's coefficients of the case given
 * (rr_exact_table_forces_kalker) give the same status and doubles, a
 * negative one an error with NaN forces.
 */
#include "fuzz.h"

#define MAX_NODES 6

static void decode_case(fz_in *in, rr_contact_problem *c, double nu)
{
    c->a = fz_log(in, 1e-4, 2e-2);
    c->b = fz_log(in, 1e-4, 2e-2);
    c->N = fz_log(in, 1.0, 1e5);
    c->G = fz_log(in, 1e9, 1e11);
    c->nu = fz_choice(in, 8) ? nu : fz_lin(in, 0.0, 0.5);
    c->cx = fz_slog(in, 1e-8, 1.0);
    c->cy = fz_slog(in, 1e-8, 1.0);
    c->cphi = fz_slog(in, 1e-6, 100.0);
    c->speed = fz_log(in, 0.01, 100.0);
}

static int table_invalid(const rr_exact_table *t)
{
    long nodes = 1;
    int d;
    if (!isfinite(t->r0) || !(t->r0 > 0.0) || !isfinite(t->nu))
        return 1;
    for (d = 0; d < 4; d++) {
        if (t->n[d] < 4 || !isfinite(t->lo[d]) || !isfinite(t->hi[d]) || !(t->lo[d] < t->hi[d]))
            return 1;
        nodes *= t->n[d];
    }
    return nodes > (1L << 28);
}

static void check(const rr_exact_table *t, const rr_contact_problem *c, int builtin)
{
    const rr_friction *fr = &c->friction;
    const char *fn = "rr_exact_table_forces";
    rr_forces f, r;
    int st;
    memset(&f, 0x55, sizeof f);
    st = rr_exact_table_forces(t, c, &f);
    fz_status(fn, st);
    {
        /* Kalker's coefficients of the same a/b and nu given: the same */
        rr_kalker_coeffs k;
        rr_forces g;
        int sg;
        if (isnormal(c->a / c->b) && rr_kalker(c->a / c->b, c->nu, &k) == RR_OK) {
            memset(&g, 0x55, sizeof g);
            sg = rr_exact_table_forces_kalker(t, c, &k, &g);
            if (sg != st || (st >= 0 && memcmp(&f, &g, sizeof f) != 0)
                || (st < 0 && !(isnan(g.fx) && isnan(g.fy) && isnan(g.mz))))
                fz_fail("rr_exact_table_forces_kalker: status %d (%.17g, %.17g, %.17g) against "
                        "%s's %d (%.17g, %.17g, %.17g)", sg, g.fx, g.fy, g.mz, fn, st, f.fx,
                        f.fy, f.mz);
            /* a coefficient a caller got wrong: refused, NaN forces */
            k.c22 = -k.c22;
            memset(&g, 0x55, sizeof g);
            sg = rr_exact_table_forces_kalker(t, c, &k, &g);
            if (sg >= 0 || !(isnan(g.fx) && isnan(g.fy) && isnan(g.mz)))
                fz_fail("rr_exact_table_forces_kalker: c22 < 0 gave status %d", sg);
        }
    }
    if (table_invalid(t) && st != RR_ERR_PARAM)
        fz_fail("%s: a bad table gave status %d, not RR_ERR_PARAM", fn, st);
    if (st < 0) {
        if (!isnan(f.fx) || !isnan(f.fy) || !isnan(f.mz))
            fz_fail("%s: error %d but forces not NaN", fn, st);
        if (st == RR_ERR_TABLE) {
            const double la = log(c->a / c->b);
            const int outside = fabs(c->nu - t->nu) > 1e-9 || la < t->lo[0] - 1e-12 * fabs(t->lo[0])
                                || la > t->hi[0] + 1e-12 * fabs(t->hi[0]);
            if (!outside)
                fz_fail("%s: RR_ERR_TABLE inside the table (a/b = %.17g, nu = %.17g)", fn,
                        c->a / c->b, c->nu);
        }
        return;
    }
    FZ_FINITE(fn, st, f.fx);
    FZ_FINITE(fn, st, f.fy);
    FZ_FINITE(fn, st, f.mz);
    if (!(hypot(f.fx, f.fy) <= fr->mu0 * c->N * (1.0 + 1e-12)))
        fz_fail("%s: |F| = %.17g above mu0 N = %.17g", fn, hypot(f.fx, f.fy), fr->mu0 * c->N);
    if (builtin) {
        rr_contact_problem m = *c;
        m.cx = -m.cx;
        m.cy = -m.cy;
        m.cphi = -m.cphi;
        if (rr_exact_table_forces(t, &m, &r) != st || r.fx != -f.fx || r.fy != -f.fy
            || r.mz != -f.mz)
            fz_fail("%s: reversed creepages do not reverse the forces: (%.17g, %.17g, %.17g) "
                    "against (%.17g, %.17g, %.17g)", fn, f.fx, f.fy, f.mz, r.fx, r.fy, r.mz);
        if (c->cx == 0.0 && c->cy == 0.0 && c->cphi == 0.0
            && (f.fx != 0.0 || f.fy != 0.0 || f.mz != 0.0))
            fz_fail("%s: force without creepage", fn);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static float values[MAX_NODES * MAX_NODES * MAX_NODES * MAX_NODES * 3];
    fz_in in = fz_start(data, size);
    const int builtin = fz_choice(&in, 4) != 0;
    rr_exact_table t = rr_exact_table_builtin;
    rr_contact_problem c = {0};     /* an ellipse problem */
    rr_friction fr;
    int d, i, n = 1;

    if (!builtin) {
        /* a table of the input's: small, its numbers anything */
        for (d = 0; d < 4; d++) {
            static const int bad[4] = {3, 0, -1, INT_MIN};
            t.n[d] = fz_choice(&in, 16) ? fz_range(&in, 4, MAX_NODES) : bad[fz_choice(&in, 4)];
            t.lo[d] = fz_lin(&in, -3.0, 0.0);
            t.hi[d] = fz_choice(&in, 16) ? t.lo[d] + fz_log(&in, 0.1, 5.0) : fz_lin(&in, -3, 3);
            n *= t.n[d] >= 4 ? t.n[d] : 1;
        }
        t.r0 = fz_choice(&in, 16) ? fz_log(&in, 0.1, 10.0) : fz_lin(&in, -1.0, 1.0);
        t.nu = fz_lin(&in, 0.0, 0.5);
        t.nx = 1;
        for (i = 0; i < 3 * n; i++)
            values[i] = (float)(fz_choice(&in, 64) ? 4.0 * fz_unit(&in) - 2.0
                                                   : fz_lin(&in, -1e30, 1e30));
        t.v = values;
    }
    decode_case(&in, &c, t.nu);
    fr.mu0 = fz_lin(&in, 0.05, 1.0);
    fr.A = fz_choice(&in, 4) == 0 ? 1.0 : fz_lin(&in, 0.05, 1.0);
    fr.B = fz_lin(&in, 0.0, 3.0);
    fz_note("table %s n %d %d %d %d r0 %.17g nu %.17g; case a %.17g b %.17g N %.17g G %.17g "
            "nu %.17g cx %.17g cy %.17g cphi %.17g speed %.17g; mu0 %.17g A %.17g B %.17g",
            builtin ? "built-in" : "input", t.n[0], t.n[1], t.n[2], t.n[3], t.r0, t.nu, c.a, c.b,
            c.N, c.G, c.nu, c.cx, c.cy, c.cphi, c.speed, fr.mu0, fr.A, fr.B);
    fz_status("rr_exact_table_check", rr_exact_table_check(&t));
    if (rr_exact_table_check(NULL) != RR_ERR_NULL)
        fz_fail("rr_exact_table_check(NULL) is not RR_ERR_NULL");
    c.friction = fr;
    check(&t, &c, builtin);
    {
        rr_forces f;
        if (rr_exact_table_forces(&t, &c, NULL) != RR_ERR_NULL
            || rr_exact_table_forces(NULL, &c, &f) != RR_ERR_NULL || !isnan(f.fx)
            || rr_exact_table_forces(&rr_exact_table_builtin, NULL, &f) != RR_ERR_NULL
            || !isnan(f.fx))
            fz_fail("rr_exact_table_forces: NULL arguments not refused with NaN forces");
    }
    {
        /* a grid problem: not the table's */
        rr_contact_problem g = c;
        rr_forces f;
        g.patch = RR_PATCH_GRID;
        if (rr_exact_table_forces(rr_exact_table_check(&t) == RR_OK ? &t
                                  : &rr_exact_table_builtin, &g, &f) != RR_ERR_PATCH
            || !isnan(f.fx))
            fz_fail("rr_exact_table_forces: a grid problem not refused (RR_ERR_PATCH)");
    }
    return 0;
}
