/*
 * fuzz_spline.c - natural cubic splines: rr_spline_init, rr_spline_eval and
 * rr_spline_eval_at on point lists from the input, and evaluations of a
 * spline struct that a C caller filled in wrongly.
 *
 * Input: the number of knots n (2 .. 64, or an edge: 0, 1, negative), a
 * byte allowing edge values in the point list, the knots as a start and
 * increments (plausible: 1e-5 .. 1e-2 m, so that they increase), the
 * values (within 1 cm), whether m or work is NULL; then up to 16
 * evaluations, each at a point within the knots or anywhere, with a hint
 * k from the input (any int) and d1, d2 asked for or not.  One input in
 * eight instead evaluates a struct with n = 1, 0 or negative, or a NULL
 * array, over valid buffers: the functions take the struct from the caller
 * and must refuse it, not read outside it.
 *
 * Oracles: documented errors; on success finite m; every evaluation: NaN
 * outputs on error, finite on success, eval and eval_at (with any hint)
 * equal to the last bit, the hint left on an interval [0, n - 2] holding s.
 */
#include "fuzz.h"

#define MAX_KNOTS 64
#define MAX_EVALS 16

static void check_eval(fz_in *in, const rr_spline *sp, int usable)
{
    const int nev = fz_range(in, 1, MAX_EVALS);
    int e, k = fz_int(in, -1, sp->n);

    for (e = 0; e < nev; e++) {
        const int within = usable && fz_choice(in, 4) != 0;
        const double u = fz_lin(in, 0.0, 1.0);
        const double s = within ? sp->s[0] + u * (sp->s[sp->n - 1] - sp->s[0])
                                : fz_lin(in, -0.1, 0.1);
        const int want = fz_choice(in, 4);
        double z1 = 7.0, a1 = 7.0, b1 = 7.0, z2 = 7.0, a2 = 7.0, b2 = 7.0;
        const int off = !isfinite(s) || (usable && (s < sp->s[0] || s > sp->s[sp->n - 1]));
        int st1, st2;

        if (fz_choice(in, 4) == 0)
            k = fz_int(in, -1, sp->n);         /* a fresh hint, valid or not */
        fz_note("; eval s = %.17g hint %d want %d", s, k, want);
        st1 = rr_spline_eval(sp, s, &z1, (want & 1) ? &a1 : NULL, (want & 2) ? &b1 : NULL);
        st2 = rr_spline_eval_at(sp, s, &k, &z2, (want & 1) ? &a2 : NULL,
                                (want & 2) ? &b2 : NULL);
        fz_status("rr_spline_eval", st1);
        fz_status("rr_spline_eval_at", st2);
        fz_error("rr_spline_eval", st1, !usable || off, "s is off the profile or the spline invalid");
        if (st1 < 0) {
            if (!isnan(z1) || ((want & 1) && !isnan(a1)) || ((want & 2) && !isnan(b1)))
                fz_fail("rr_spline_eval: error %d but the outputs are not NaN", st1);
        }
        FZ_FINITE("rr_spline_eval", st1, z1);
        if (want & 1)
            FZ_FINITE("rr_spline_eval", st1, a1);
        if (want & 2)
            FZ_FINITE("rr_spline_eval", st1, b1);
        /* the same results, whatever the hint */
        if (st1 != st2 || memcmp(&z1, &z2, sizeof z1) != 0
            || ((want & 1) && memcmp(&a1, &a2, sizeof a1) != 0)
            || ((want & 2) && memcmp(&b1, &b2, sizeof b1) != 0))
            fz_fail("rr_spline_eval_at: status %d (%.17g, %.17g, %.17g) but rr_spline_eval %d "
                    "(%.17g, %.17g, %.17g) at s = %.17g", st2, z2, a2, b2, st1, z1, a1, b1, s);
        if (st2 >= 0 && usable) {
            if (k < 0 || k > sp->n - 2)
                fz_fail("rr_spline_eval_at: hint left at %d, outside [0, %d]", k, sp->n - 2);
            if (!(sp->s[k] <= s && s <= sp->s[k + 1]))
                fz_fail("rr_spline_eval_at: hint %d: s = %.17g not in [%.17g, %.17g]", k, s,
                        sp->s[k], sp->s[k + 1]);
        }
    }
}

/* A struct that does not describe a spline: n < 2, or a NULL array. */
static void check_misuse(fz_in *in)
{
    double s[3] = {0.0, 1e-3, 2e-3}, z[3] = {0.0, 1e-4, 0.0}, m[3] = {0.0, 0.0, 0.0};
    double *heap_s = fz_alloc(sizeof s), *heap_z = fz_alloc(sizeof z);
    double *heap_m = fz_alloc(sizeof m);
    rr_spline sp;
    const int kind = fz_choice(in, 4);

    memcpy(heap_s, s, sizeof s);
    memcpy(heap_z, z, sizeof z);
    memcpy(heap_m, m, sizeof m);
    sp.n = 3;
    sp.s = heap_s;
    sp.z = heap_z;
    sp.m = heap_m;
    switch (kind) {
    case 0: sp.n = fz_int(in, -2, 1); if (sp.n >= 2) sp.n = 1; break;
    case 1: sp.s = NULL; break;
    case 2: sp.z = NULL; break;
    default: sp.m = NULL; break;
    }
    fz_note("misused struct: n = %d, s %s, z %s, m %s (knots 0, 1e-3, 2e-3)", sp.n,
            sp.s ? "set" : "NULL", sp.z ? "set" : "NULL", sp.m ? "set" : "NULL");
    /* known: the evaluation trusts the struct (reads s[n - 1] with n < 2,
     * n - 1 overflows for INT_MIN, NULL arrays are dereferenced) */
    if (!fz_known("spline_struct", 1))
        check_eval(in, &sp, 0);
    free(heap_s);
    free(heap_z);
    free(heap_m);
}

/* Known: values or knots beyond 1e100, or knots closer than 1e-100,
 * overflow the second derivatives or the evaluation: inf with status 0. */
static int extreme_points(const double *s, const double *z, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (fabs(s[i]) > 1e100 || fabs(z[i]) > 1e100 || (i > 0 && s[i] - s[i - 1] < 1e-100))
            return 1;
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    const int n = fz_int(&in, 2, MAX_KNOTS);
    const int nalloc = n >= 1 && n <= MAX_KNOTS ? n : 1;
    double *s, *z, *m, *work;
    rr_spline sp;
    int i, st, invalid = 0, null_m, null_w;

    if (fz_choice(&in, 8) == 0) {
        check_misuse(&in);
        return 0;
    }
    in.edges = fz_choice(&in, 4) == 0;
    s = fz_alloc((size_t)nalloc * sizeof *s);
    z = fz_alloc((size_t)nalloc * sizeof *z);
    m = fz_alloc((size_t)nalloc * sizeof *m);
    work = fz_alloc((size_t)nalloc * sizeof *work);
    s[0] = fz_lin(&in, -0.05, 0.05);
    z[0] = fz_lin(&in, -0.01, 0.01);
    for (i = 1; i < nalloc; i++) {
        s[i] = s[i - 1] + fz_log(&in, 1e-5, 1e-2);
        z[i] = fz_lin(&in, -0.01, 0.01);
    }
    in.edges = 1;
    null_m = fz_choice(&in, 16) == 0;
    null_w = fz_choice(&in, 16) == 0;
    for (i = 0; i < nalloc; i++) {
        invalid |= !isfinite(s[i]) || !isfinite(z[i]);
        if (i > 0 && !(s[i] > s[i - 1]))
            invalid = 1;
    }
    invalid |= n < 2 || n > MAX_KNOTS || null_m || null_w;
    fz_note("n = %d, m %s, work %s; knots (s, z):", n, null_m ? "NULL" : "set",
            null_w ? "NULL" : "set");
    for (i = 0; i < nalloc; i++)
        fz_note(" (%.17g, %.17g)", s[i], z[i]);

    if (n >= 1 && n <= MAX_KNOTS) {
        st = rr_spline_init(n, s, z, null_m ? NULL : m, null_w ? NULL : work);
    } else {
        /* n outside what was allocated: only n < 2 may be passed, and must be refused */
        st = n < 2 ? rr_spline_init(n, s, z, m, work) : RR_ERR_GEOMETRY;
    }
    fz_status("rr_spline_init", st);
    fz_error("rr_spline_init", st, invalid, "the knots, n or a buffer are invalid");
    if (st >= 0 && fz_known("spline_extreme", extreme_points(s, z, n)))
        st = -1;
    if (st >= 0) {
        fz_finite_n("rr_spline_init", st, "m", m, n);
        sp.n = n;
        sp.s = s;
        sp.z = z;
        sp.m = m;
        check_eval(&in, &sp, 1);
    }
    free(s);
    free(z);
    free(m);
    free(work);
    return 0;
}
