/*
 * fuzz_fmu.c - the rig as a co-simulation unit (csrc/fmu/rr_fmu.h), as an
 * FMI master (or a careless one) drives it: a unit made from a start
 * configuration (the defaults with up to 4 parameters set, the contact
 * table kept small so that an input stays fast), then up to 16 calls:
 * set and get of any variable (its own type or another, values in range,
 * near the start, at the edges, NaN and infinities), enter and exit
 * initialisation, steps of
 * any time and length, terminate, reset, a save and a restore (of a good
 * state, or one whose mode is no mode).
 *
 * Oracles: statuses in range; every error leaves a message; NaN and
 * infinities are no value of any variable: refused by every set (a start
 * value, an input, a tunable parameter while stepping) and by the start
 * configuration; a refused set changes nothing (get gives the old value);
 * an accepted set of a
 * parameter or input reads back as given (an INTEGER, ENUMERATION or
 * BOOLEAN as the whole number); a step refused changes the unit's time
 * not at all, a step done moves it by its length (within the sample's
 * rounding); after a successful step every REAL output is finite but the
 * record's xi_ref and w_ref (NaN as documented) and the contact blocks of
 * a wheel without contact; a restore of a saved state gives the saved
 * outputs back, bit for bit.
 */
#include "fuzz.h"

#define MAX_CALLS 16

static void *fz_malloc(void *ctx, size_t n)
{
    (void)ctx;
    return malloc(n);
}

static void fz_free(void *ctx, void *p)
{
    (void)ctx;
    free(p);
}

static int nvars;

/* Settings that are allowed but make one input slow (a table of 100000
 * rows takes a minute to build, a 1000 x 1000 FASTSIM grid a second a
 * sample): set back to a small value after any set that passes them. */
static const struct {
    const char *name;
    double most, instead;
} costly[] = {
    {"integration.table_rows", 41, 11}, {"integration.substeps", 20, 2},
    {"contact.fastsim_nx", 30, 10}, {"contact.fastsim_ny", 30, 10},
};
#define NCOSTLY ((int)(sizeof costly / sizeof costly[0]))
static unsigned costly_vr[NCOSTLY];

static void find_costly(const rr_fmu_config *start)
{
    int i, k;
    for (k = 0; k < NCOSTLY; k++)
        costly_vr[k] = 0;
    for (i = 0; i < nvars; i++) {
        rr_fmu_var v;
        char name[RR_FMU_NAME_LEN];
        rr_fmu_var_at(start, i, &v);
        rr_fmu_var_name(&v, name, sizeof name);
        for (k = 0; k < NCOSTLY; k++)
            if (strcmp(name, costly[k].name) == 0)
                costly_vr[k] = v.vr;
    }
}

/* x for variable vr, or the small value where x would make the input slow */
static double affordable(unsigned vr, double x)
{
    int k;
    for (k = 0; k < NCOSTLY; k++)
        if (vr == costly_vr[k] && x > costly[k].most)
            return costly[k].instead;
    return x;
}

/* A value for variable v: its start, inside its range, near an end, any,
 * or not a number at all (NaN, an infinity). */
static double decode_value(fz_in *in, const rr_fmu_config *start, const rr_fmu_var *v)
{
    static const double nonfinite[3] = {NAN, HUGE_VAL, -HUGE_VAL};
    double x0 = 0.0, lo = v->lo, hi = v->hi;
    const int sel = fz_choice(in, 6);
    if (sel == 5)
        return nonfinite[fz_choice(in, 3)];
    rr_fmu_var_start(start, v, &x0);
    if (!isfinite(x0))
        x0 = 0.0;
    if (v->type != RR_FMU_REAL) {
        const int a = isfinite(lo) ? (int)fmax(lo, -1e6) : -3;
        const int b = isfinite(hi) ? (int)fmin(hi, 1e6) : 30;
        return sel == 0 ? x0 : sel == 4 ? fz_lin(in, -1e10, 1e10) : fz_int(in, a - 1, b + 1);
    }
    switch (sel) {
    case 0: return x0;
    case 1: return fz_near(in, x0 != 0.0 ? x0 : 1.0, 3.0);
    case 2: return isfinite(lo) ? lo + fz_slog(in, 1e-12, 1.0) : fz_lin(in, -1e3, 1e3);
    case 3: return isfinite(hi) ? hi + fz_slog(in, 1e-12, 1.0) : fz_lin(in, -1e3, 1e3);
    default: return fz_lin(in, -1e6, 1e6);
    }
}

/* The outputs that may be NaN at a success: the target without creepage
 * control, the speed reference under a torque command, a wheel's block
 * without contact. */
static int may_be_nan(const rr_fmu_var *v)
{
    return v->vr == RR_FMU_VR_RECORD + RR_REC_XI_REF
        || v->vr == RR_FMU_VR_RECORD + RR_REC_W_REF || v->vr >= RR_FMU_VR_WHEEL;
}

static void check_outputs(rr_fmu *m, const rr_fmu_config *start)
{
    int i;
    for (i = 0; i < nvars; i++) {
        rr_fmu_var v;
        double x;
        int st;
        if (rr_fmu_var_at(start, i, &v) != RR_OK)
            fz_fail("rr_fmu_var_at: variable %d of %d missing", i, nvars);
        if (v.causality != RR_FMU_OUTPUT || v.type != RR_FMU_REAL)
            continue;
        st = rr_fmu_get(m, v.type, v.vr, &x);
        fz_status("rr_fmu_get", st);
        if (st < 0)
            fz_fail("rr_fmu_get: output %u refused after a step (%d: %s)", v.vr, st,
                    rr_fmu_message(m));
        if (!isfinite(x) && !(isnan(x) && may_be_nan(&v)))
            fz_fail("rr_fmu_get: output %u is %g after a successful step", v.vr, x);
    }
}

static void one_call(fz_in *in, rr_fmu *m, const rr_fmu_config *start, rr_fmu_state *saved,
                     int *have_saved)
{
    const int op = fz_choice(in, 10);
    int st;
    fz_note(" | op %d (mode %d, t %.17g)", op, m->s.mode, rr_fmu_time(m));
    switch (op) {
    case 0:
    case 1: {
        /* set a variable (its own type mostly), then read it back */
        rr_fmu_var v;
        const int i = fz_range(in, 0, nvars - 1);
        double before = NAN, after = NAN, x;
        int type, gst;
        rr_fmu_var_at(start, i, &v);
        type = fz_choice(in, 8) == 0 ? fz_int(in, -1, 4) : v.type;
        x = decode_value(in, start, &v);
        fz_note(" set vr %u type %d = %.17g", v.vr, type, x);
        gst = rr_fmu_get(m, v.type, v.vr, &before);
        st = rr_fmu_set(m, type, v.vr, x);
        fz_status("rr_fmu_set", st);
        if (st < 0 && !rr_fmu_message(m)[0])
            fz_fail("rr_fmu_set: error %d without a message", st);
        if (st >= 0 && !isfinite(x))
            fz_fail("rr_fmu_set: took %g for vr %u (type %d, mode %d)", x, v.vr, type,
                    m->s.mode);
        if (rr_fmu_get(m, v.type, v.vr, &after) >= 0 && gst >= 0) {
            if (st < 0 && memcmp(&before, &after, sizeof before) != 0)
                fz_fail("rr_fmu_set: refused (%d) but the value moved %.17g -> %.17g", st,
                        before, after);
            if (st >= 0 && after != x)
                fz_fail("rr_fmu_set: took %.17g but reads %.17g", x, after);
        }
        if (st >= 0 && affordable(v.vr, x) != x)
            rr_fmu_set(m, v.type, v.vr, affordable(v.vr, x));
        break;
    }
    case 2: {
        rr_fmu_var v;
        double x;
        const unsigned vr = fz_choice(in, 4) == 0 ? (unsigned)fz_int(in, 0, 200000)
                          : (rr_fmu_var_at(start, fz_range(in, 0, nvars - 1), &v), v.vr);
        st = rr_fmu_get(m, fz_int(in, 0, 3), vr, &x);
        fz_note(" get vr %u", vr);
        fz_status("rr_fmu_get", st);
        if (st < 0 && !rr_fmu_message(m)[0])
            fz_fail("rr_fmu_get: error %d without a message", st);
        break;
    }
    case 3:
        st = rr_fmu_enter_init(m, fz_choice(in, 4) ? 0.0 : fz_lin(in, -10.0, 10.0));
        fz_status("rr_fmu_enter_init", st);
        break;
    case 4:
        st = rr_fmu_exit_init(m);
        fz_status("rr_fmu_exit_init", st);
        if (st < 0 && !rr_fmu_message(m)[0])
            fz_fail("rr_fmu_exit_init: error %d without a message", st);
        break;
    case 5:
    case 6: {
        /* a step: at the unit's time (or off it), of whole samples (or not) */
        const double T = m->s.cfg.c.T, t = rr_fmu_time(m);
        const int k = fz_range(in, 0, 6);       /* no edge values: INT_MAX samples run for days */
        double h = fz_choice(in, 4) ? k * T : fz_lin(in, -T, 7.0 * T);
        const double at = fz_choice(in, 6) ? t : t + fz_slog(in, 1e-9 * T, T);
        /* an extreme h of whole samples (1e6 s: 2.5e8 of them) runs for
         * minutes: made half a sample off, so that the step's refusal is
         * what it checks (the unit takes up to 1e15 samples) */
        if (h > 64.0 * T && h <= 2e15 * T)
            h += 0.5 * T;
        fz_note(" do_step(%.17g, %.17g)", at, h);
        st = rr_fmu_do_step(m, at, h);
        fz_status("rr_fmu_do_step", st);
        if (st < 0 && !rr_fmu_message(m)[0])
            fz_fail("rr_fmu_do_step: error %d without a message", st);
        if (st >= 0) {
            if (!(fabs(rr_fmu_time(m) - (t + h)) <= 1e-6 * T + 1e-12 * fabs(t + h)))
                fz_fail("rr_fmu_do_step: time %.17g after a step of %.17g from %.17g",
                        rr_fmu_time(m), h, t);
            check_outputs(m, start);
        } else if (st == RR_ERR_PARAM && rr_fmu_time(m) != t) {
            fz_fail("rr_fmu_do_step: refused the step but the time moved");
        }
        break;
    }
    case 7:
        st = fz_choice(in, 2) ? rr_fmu_terminate(m) : rr_fmu_reset(m);
        fz_status("rr_fmu_terminate/reset", st);
        break;
    case 8:
        st = rr_fmu_save(m, saved);
        fz_status("rr_fmu_save", st);
        *have_saved = st >= 0;
        break;
    default:
        if (*have_saved) {
            double a, b;
            const int corrupt = fz_choice(in, 6) == 0;
            rr_fmu_var v;
            rr_fmu_state *s = fz_alloc(sizeof *s);
            memcpy(s, saved, sizeof *s);
            if (corrupt)
                s->mode = fz_int(in, -5, 20);
            st = rr_fmu_restore(m, s);
            fz_status("rr_fmu_restore", st);
            if (st >= 0 && saved->ready) {
                /* the saved outputs back, bit for bit */
                rr_fmu_var_find(start, RR_FMU_VR_RECORD + RR_REC_CREEPAGE, &v);
                if (rr_fmu_get(m, v.type, v.vr, &a) >= 0) {
                    b = saved->rec[RR_REC_CREEPAGE];
                    if (memcmp(&a, &b, sizeof a) != 0)
                        fz_fail("rr_fmu_restore: creepage %.17g, saved %.17g", a, b);
                }
            }
            free(s);
        }
        break;
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    rr_fmu_config *start = fz_alloc(sizeof *start);
    rr_fmu *m = fz_alloc(sizeof *m);
    rr_fmu_state *saved = fz_alloc(sizeof *saved);
    int i, n, st, have_saved = 0;

    rr_fmu_config_default(start);
    /* a small contact table (the default one costs 0.1 s to build) */
    if (rr_fmu_config_set(start, "integration.table_rows", fz_int(&in, 2, 21)) < 0)
        rr_fmu_config_set(start, "integration.table_rows", 11);
    n = fz_range(&in, 0, 4);
    nvars = rr_fmu_var_count(start);
    find_costly(start);
    for (i = 0; i < n; i++) {
        rr_fmu_var v;
        char name[RR_FMU_NAME_LEN];
        double x;
        rr_fmu_var_at(start, fz_range(&in, 0, nvars - 1), &v);
        if (v.causality != RR_FMU_PARAMETER || v.entry >= 0)
            continue;
        rr_fmu_var_name(&v, name, sizeof name);
        x = affordable(v.vr, decode_value(&in, start, &v));
        fz_note(" start %s = %.17g;", name, x);
        st = rr_fmu_config_set(start, name, x);
        fz_status("rr_fmu_config_set", st);
        if (st >= 0 && !isfinite(x))
            fz_fail("rr_fmu_config_set: a start configuration took %s = %g", name, x);
    }
    nvars = rr_fmu_var_count(start);
    if (nvars < 1)
        fz_fail("rr_fmu_var_count: %d variables", nvars);
    find_costly(start);
    fz_status("rr_fmu_init", rr_fmu_init(m, start, fz_malloc, fz_free, NULL, NULL));
    n = fz_range(&in, 0, MAX_CALLS);
    for (i = 0; i < n; i++)
        one_call(&in, m, start, saved, &have_saved);
    rr_fmu_release(m);
    free(saved);
    free(m);
    free(start);
    return 0;
}
