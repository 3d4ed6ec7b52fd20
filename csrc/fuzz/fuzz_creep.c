/*
 * fuzz_creep.c - the creep-force methods: rr_creep_forces over every method
 * and option, rr_linear, rr_polach, rr_fastsim with and without (parts of)
 * its traction field, and the checks and friction law they share; and the
 * registry: rr_method_count/get/find, rr_creep_opts_default/set/check_at,
 * rr_creep_cost/saturates/slope_scale/workspace_len, rr_creep_forces_work,
 * rr_creep_forces_interruptible and rr_creep_field.
 *
 * Input: one byte choosing the entry point, then the ellipse problem (semi-
 * axes 0.1 .. 20 mm, load 1 N .. 100 kN, G 1 .. 100 GPa, creepages of
 * either sign 1e-8 .. 1, spin 1e-6 .. 100 1/m, speed 0.01 .. 100 m/s), the
 * friction law, the options (every field, valid or not: unknown methods,
 * grids outside [1, 4096], k0 or kS out of range), and the field's make-up.
 * Decoded grids are capped at 32768 elements so that one input stays well
 * below 0.1 s; the registry's setter may still put any grid in range (the
 * oracles take the method's range, not the cap).
 *
 * Oracles: documented errors for invalid arguments, NaN outputs on error,
 * finite outputs on success, |(fx, fy)| <= mu0 N for every method but the
 * linear theory, the dispatcher giving exactly what the method it calls
 * gives, and for the traction field: finite values, pn >= 0, the traction
 * bound per element, the slip flags and their count, pressure summing to N
 * and tractions to (fx, fy) (on the rectangular grid, whose elements are
 * all 2a/nx by 2b/ny).  Registry: count, get and find agree (and refuse
 * what is none); a method's defaults its descriptor's, NaN past them; a
 * setter's status predicted from the option's type and range, the options
 * unchanged on error and only that value on success; check_at = check, *bad
 * an option's index (-1 for an unknown method); cost >= 1, slope scale > 0
 * finite and saturates as the descriptor (0 only for the linear theory)
 * for valid options, 0, NaN, 0, 0 else; rr_creep_forces_work with the
 * workspace asked for exactly rr_creep_forces, one double short refused;
 * rr_creep_forces_interruptible with a hook that never stops exactly
 * rr_creep_forces_work, with one that stops at its first poll that or
 * RR_ERR_INTERRUPTED with NaN forces (only a method with the hook's entry);
 * rr_creep_field's arrays of the descriptor's field_shape between canaries,
 * RR_ERR_METHOD for a method without a field, NaN forces on error;
 * rr_creep_check as rr_creep_opts_check_at (status and *bad, the record's
 * workspace and cost the getters'), rr_creep_forces_checked exactly
 * rr_creep_forces_work for a checked record, RR_ERR_NULL with NaN forces
 * for a refused one or one whose method was changed after the check.  The
 * problem's check: rr_contact_problem_check refuses exactly an invalid
 * ellipse or law, naming a member at fault as its status says (judged
 * member by member); rr_creep_blame of a method's error names such a member,
 * or for a valid problem the speed (falling friction at rest), the law
 * (a Coulomb-only method) or exact_table's nu or a/b, and no member only for
 * a result out of range, the exact solver's own refusals, or a problem the
 * check refuses for another reason than the method (the linear theory
 * judges the law first).  (The grid problem: fuzz_exact.)
 */
#include "fuzz.h"

#define MAX_ELEMENTS 32768
#define FIELD_MAX_ELEMENTS (1u << 20)
/* the most elements a valid grid option allows (rr_creep_opts_set takes any
 * grid in range, past the decoder's cap) */
#define MAX_GRID_ELEMENTS ((double)RR_FASTSIM_MAX_GRID * RR_FASTSIM_MAX_GRID \
                           + (double)RR_FASTRIP_MAX_GRID * RR_FASTRIP_MAX_GRID)

/* An interrupt hook that counts its polls; stops at the first where *ctx
 * holds 1 on entry. */
static int polled(void *ctx)
{
    int *c = ctx;
    return (*c)++ == 1;
}

static int contact_invalid(const rr_contact_problem *c)
{
    return !isfinite(c->a) || !isfinite(c->b) || !isfinite(c->N) || !isfinite(c->G)
        || !isfinite(c->nu) || !isfinite(c->cx) || !isfinite(c->cy) || !isfinite(c->cphi)
        || !isfinite(c->speed) || !(c->a > 0.0) || !(c->b > 0.0) || !(c->N > 0.0)
        || !(c->G > 0.0) || !(c->nu >= 0.0) || !(c->nu <= 0.5) || !(c->speed >= 0.0)
        || !isnormal(c->a) || !isnormal(c->b) || !isnormal(c->N) || !isnormal(c->G);
}

static int friction_invalid(const rr_friction *f)
{
    return !isfinite(f->mu0) || !isfinite(f->A) || !isfinite(f->B) || !(f->mu0 > 0.0)
        || !(f->A > 0.0) || !(f->A <= 1.0) || !(f->B >= 0.0)
        || f->mu0 > RR_FRICTION_MAX || f->B > RR_FRICTION_MAX;
}

/* the methods with a traction field: FASTSIM's variants, as the registry says */
static int is_fastsim(int m)
{
    const rr_method_desc *d = rr_method_get(m);
    return d && d->field;
}

/* not an integer in [lo, hi] (NaN included) */
static int bad_int(double v, double lo, double hi)
{
    return !(v >= lo && v <= hi && v == floor(v));
}

/* The options the method has, against rr_creep_opts_check's documentation. */
static int opts_invalid(const rr_creep_opts *o)
{
    const double *v = o->v;
    if (o->method < 0 || o->method >= RR_METHOD_COUNT)
        return 1;
    if (is_fastsim(o->method)
        && (bad_int(v[RR_FASTSIM_BOUND], 0, 1) || bad_int(v[RR_FASTSIM_GRID], 0, 1)
            || bad_int(v[RR_FASTSIM_SLIP_SPEED], 0, 1)
            || bad_int(v[RR_FASTSIM_NX], 1, RR_FASTSIM_MAX_GRID)
            || bad_int(v[RR_FASTSIM_NY], 1, RR_FASTSIM_MAX_GRID)))
        return 1;
    if (o->method == RR_METHOD_FASTSIM_BLENDED && bad_int(v[RR_FASTSIM_BLEND_RULE], 0, 1))
        return 1;
    if (o->method == RR_METHOD_MODIFIED_FASTSIM
        && !(isfinite(v[RR_FASTSIM_K0]) && isfinite(v[RR_FASTSIM_ALPHA_INF])
             && isfinite(v[RR_FASTSIM_BETA]) && v[RR_FASTSIM_K0] > 0.0 && v[RR_FASTSIM_K0] <= 1.0
             && v[RR_FASTSIM_ALPHA_INF] >= 0.0 && v[RR_FASTSIM_ALPHA_INF] <= 1.0
             && v[RR_FASTSIM_BETA] >= 0.0))
        return 1;
    if (o->method == RR_METHOD_EXACT
        && (bad_int(v[RR_EXACT_NX], 1, RR_EXACT_MAX_GRID - 2 * RR_EXACT_MARGIN)
            || bad_int(v[RR_EXACT_NY], 1, RR_EXACT_MAX_GRID - 2 * RR_EXACT_MARGIN)
            || bad_int(v[RR_EXACT_MAXIT], 1, 1e7)
            || !(v[RR_EXACT_TOL] >= 1e-14 && v[RR_EXACT_TOL] <= 0.1)
            || !(v[RR_EXACT_SPIN_SHIFT] >= -1.0 && v[RR_EXACT_SPIN_SHIFT] <= 1.0)))
        return 1;
    if (o->method == RR_METHOD_FASTRIP
        && (bad_int(v[RR_FASTRIP_NX], 1, RR_FASTRIP_MAX_GRID)
            || bad_int(v[RR_FASTRIP_NY], 1, RR_FASTRIP_MAX_GRID)
            || bad_int(v[RR_FASTRIP_FLEX], 0, 1) || bad_int(v[RR_FASTRIP_GEOMETRY], 0, 1)
            || !(isfinite(v[RR_FASTRIP_K0]) && isfinite(v[RR_FASTRIP_ALPHA_INF])
                 && isfinite(v[RR_FASTRIP_BETA]) && v[RR_FASTRIP_K0] > 0.0
                 && v[RR_FASTRIP_K0] <= 1.0 && v[RR_FASTRIP_ALPHA_INF] >= 0.0
                 && v[RR_FASTRIP_ALPHA_INF] <= 1.0 && v[RR_FASTRIP_BETA] >= 0.0)))
        return 1;
    if (o->method == RR_METHOD_POLACH
        && !(isfinite(v[RR_POLACH_KA]) && isfinite(v[RR_POLACH_KS]) && v[RR_POLACH_KS] > 0.0
             && v[RR_POLACH_KS] <= v[RR_POLACH_KA] && v[RR_POLACH_KA] <= 1.0))
        return 1;
    return 0;
}

static int falling(const rr_friction *f)
{
    return f->A < 1.0 && f->B > 0.0;
}

static void decode_case(fz_in *in, rr_contact_problem *c)
{
    c->a = fz_log(in, 1e-4, 2e-2);
    c->b = fz_log(in, 1e-4, 2e-2);
    c->N = fz_log(in, 1.0, 1e5);
    c->G = fz_log(in, 1e9, 1e11);
    c->nu = fz_lin(in, 0.0, 0.5);
    c->cx = fz_slog(in, 1e-8, 1.0);
    c->cy = fz_slog(in, 1e-8, 1.0);
    c->cphi = fz_slog(in, 1e-6, 100.0);
    c->speed = fz_log(in, 0.01, 100.0);
}

static void decode_friction(fz_in *in, rr_friction *f)
{
    f->mu0 = fz_lin(in, 0.05, 1.0);
    f->A = fz_choice(in, 4) == 0 ? 1.0 : fz_lin(in, 0.05, 1.0);   /* Coulomb, or falling */
    f->B = fz_lin(in, 0.0, 3.0);
}

/* A grid dimension: usually 1 .. 48, sometimes anywhere up to one past the limit. */
static int decode_dim(fz_in *in)
{
    const int big = fz_choice(in, 8) == 7;
    const int small = fz_int(in, 1, 48);
    return big ? fz_range(in, 1, RR_FASTSIM_MAX_GRID + 1) : small;
}

/* A method's defaults, or (half the time) every option of the method drawn,
 * valid or not: grids outside [1, 4096] or not integers, k0 or kS out of
 * range; the method itself may be unknown. */
static void decode_opts(fz_in *in, rr_creep_opts *o)
{
    double *v = o->v;
    rr_creep_opts_default(o, fz_range(in, 0, RR_METHOD_COUNT - 1));
    if (fz_choice(in, 2) == 0)
        return;             /* the defaults of a method */
    rr_creep_opts_default(o, fz_int(in, 0, RR_METHOD_COUNT - 1));
    if (is_fastsim(o->method) || o->method < 0 || o->method >= RR_METHOD_COUNT) {
        v[RR_FASTSIM_NX] = decode_dim(in);
        v[RR_FASTSIM_NY] = decode_dim(in);
        if (v[RR_FASTSIM_NX] >= 1 && v[RR_FASTSIM_NY] >= 1
            && v[RR_FASTSIM_NX] <= RR_FASTSIM_MAX_GRID && v[RR_FASTSIM_NY] <= RR_FASTSIM_MAX_GRID
            && v[RR_FASTSIM_NX] * v[RR_FASTSIM_NY] > MAX_ELEMENTS)
            v[RR_FASTSIM_NY] = floor(MAX_ELEMENTS / v[RR_FASTSIM_NX]);
        if (fz_choice(in, 16) == 0)
            v[RR_FASTSIM_NX] += 0.5;            /* not an integer */
        v[RR_FASTSIM_BOUND] = fz_int(in, 0, 1);
        v[RR_FASTSIM_GRID] = fz_int(in, 0, 1);
        v[RR_FASTSIM_SLIP_SPEED] = fz_int(in, 0, 1);
        /* modified FASTSIM's (the other variants do not look at them) */
        v[RR_FASTSIM_K0] = fz_lin(in, 0.01, 1.0);
        v[RR_FASTSIM_ALPHA_INF] = fz_lin(in, 0.0, 1.0);
        v[RR_FASTSIM_BETA] = fz_lin(in, 0.0, 5.0);
        /* blended FASTSIM's blend_rule shares k0's index: 0, 1 or (k0 > 10/11)
         * the invalid 2, from the same byte */
        if (o->method == RR_METHOD_FASTSIM_BLENDED)
            v[RR_FASTSIM_BLEND_RULE] = floor(2.2 * v[RR_FASTSIM_K0]);
    } else if (o->method == RR_METHOD_POLACH) {
        v[RR_POLACH_KA] = fz_lin(in, 0.01, 1.0);
        v[RR_POLACH_KS] = v[RR_POLACH_KA] * fz_lin(in, 0.01, 1.0);
    } else if (o->method == RR_METHOD_FASTRIP) {
        v[RR_FASTRIP_NX] = decode_dim(in);
        v[RR_FASTRIP_NY] = decode_dim(in);
        if (v[RR_FASTRIP_NX] >= 1 && v[RR_FASTRIP_NY] >= 1
            && v[RR_FASTRIP_NX] <= RR_FASTRIP_MAX_GRID && v[RR_FASTRIP_NY] <= RR_FASTRIP_MAX_GRID
            && v[RR_FASTRIP_NX] * v[RR_FASTRIP_NY] > MAX_ELEMENTS)
            v[RR_FASTRIP_NY] = floor(MAX_ELEMENTS / v[RR_FASTRIP_NX]);
        if (fz_choice(in, 16) == 0)
            v[RR_FASTRIP_NY] += 0.5;            /* not an integer */
        v[RR_FASTRIP_FLEX] = fz_int(in, 0, 1);
        v[RR_FASTRIP_GEOMETRY] = fz_int(in, 0, 2);      /* 2: no such geometry */
        v[RR_FASTRIP_K0] = fz_lin(in, 0.0, 1.0);        /* 0: refused */
        v[RR_FASTRIP_ALPHA_INF] = fz_lin(in, 0.0, 1.0);
        v[RR_FASTRIP_BETA] = fz_lin(in, 0.0, 5.0);
    }
}

static int in_range(double v, double lo, double hi)
{
    return fabs(v) >= lo && fabs(v) <= hi;
}

/* Known: an extreme but finite case (sizes, load or modulus beyond 1e+-30,
 * creepages beyond 1e30, mu0 N near the underflow) overflows the products
 * of every method, and Kalker's coefficients are inf or NaN for extreme
 * ellipticities (fuzz_kalker); modified FASTSIM's eps overflows where A
 * mu0 is near zero, and beta = 0 times it is NaN: inf or NaN forces with
 * status 0; Polach's
 * F rounds above mu0 N where mu0 N is subnormal. */
static int known_extreme(const rr_contact_problem *c, const rr_friction *fr)
{
    return !in_range(c->a, 1e-30, 1e30) || !in_range(c->b, 1e-30, 1e30)
        || !in_range(c->a / c->b, 1e-30, 1e30) || !in_range(c->N, 1e-30, 1e30)
        || !in_range(c->G, 1e-30, 1e30) || !(fabs(c->cx) < 1e30 && fabs(c->cy) < 1e30
                                               && fabs(c->cphi) < 1e30 && c->speed < 1e30)
        || !(fr->mu0 * c->N > 1e-290) || !in_range(fr->mu0, 1e-30, 1e30) || !(fr->B < 1e30)
        || !(fr->A > 1e-30);
}

/* Known: blended FASTSIM with a creepage so small (< 1e-154) that its
 * square underflows: the single flexibility is 0/0, NaN forces, status 0. */
static int known_blended(const rr_contact_problem *c, int method)
{
    const double m = fmax(fabs(c->cx), fmax(fabs(c->cy), fabs(c->cphi)));
    return method == RR_METHOD_FASTSIM_BLENDED && m > 0.0 && m < 1e-150;
}

/* By design: FaStrip's geometry "contact" (CONTACT's) takes Hertz's pressure
 * at the element centres without summing it to N, so |F| may pass mu0 N by
 * the grid's quadrature error (0.1 % at 45 x 45, more on a coarse grid). */
static int unbounded_fastrip(const rr_creep_opts *o)
{
    return o->method == RR_METHOD_FASTRIP && o->v[RR_FASTRIP_GEOMETRY] == RR_FASTRIP_CONTACT;
}

/* Known: Polach's spin force is added outside the saturation, so that with
 * spin |F| exceeds mu N. */
static int known_polach(const rr_contact_problem *c)
{
    return c->cphi != 0.0;
}

static void check_forces(const char *fn, int st, const rr_contact_problem *c, const rr_friction *fr,
                         int frictional, int invalid, const rr_forces *f)
{
    fz_status(fn, st);
    fz_error(fn, st, invalid, "an argument is invalid");
    if (st < 0) {
        if (!isnan(f->fx) || !isnan(f->fy) || !isnan(f->mz))
            fz_fail("%s: error %d but the forces are not NaN", fn, st);
        return;
    }
    FZ_FINITE(fn, st, f->fx);
    FZ_FINITE(fn, st, f->fy);
    FZ_FINITE(fn, st, f->mz);
    if (frictional)
        fz_bound(fn, st, f->fx, f->fy, fr->mu0, c->N);
}

/* rr_creep_blame's member for status st of a checked method: one at fault
 * by the problem's check, or what a method asks of a valid problem: the
 * speed for falling friction at rest, the law for a Coulomb-only method,
 * exact_table's nu or a/b (outside [0.1, 10]) */
static int blame_right(const rr_creep_checked *k, const rr_contact_problem *c, int field, int st)
{
    if (rr_contact_problem_check(c, NULL) != RR_OK)
        return fz_member_at_fault(c, field, st);
    switch (st) {
    case RR_ERR_SPEED:
        return field == RR_PF_SPEED && falling(&c->friction) && c->speed == 0.0;
    case RR_ERR_FRICTION:
        return field == RR_PF_FRICTION_A && falling(&c->friction) && k->d->coulomb_only;
    case RR_ERR_TABLE:
        return k->o.method == RR_METHOD_EXACT_TABLE
               && (field == RR_PF_NU ? fabs(c->nu - 0.28) > 1e-9
                   : field == RR_PF_A && !(c->a / c->b >= 0.1 * (1 - 1e-9)
                                          && c->a / c->b <= 10.0 * (1 + 1e-9)));
    default:
        return 0;
    }
}

static void check_field(int st, const rr_contact_problem *c, const rr_friction *fr,
                        const rr_creep_opts *o, const rr_forces *f, const rr_fastsim_field *fl)
{
    const char *fn = "rr_fastsim (field)";
    const int n = (int)(o->v[RR_FASTSIM_NX] * o->v[RR_FASTSIM_NY]);
    /* an element's sides: a sum times one, then the other (a and b near
     * 1e-92 and 1e-230 make their product subnormal, rounded to a few bits,
     * where sum dx dy stays a normal number) */
    const double dx = 2.0 * c->a / o->v[RR_FASTSIM_NX], dy = 2.0 * c->b / o->v[RR_FASTSIM_NY];
    const double area = dx * dy;
    double sum_p = 0.0, sum_x = 0.0, sum_y = 0.0, scale;
    int i, nslip = 0;

    if (st < 0)
        return;
    if (fl->nslip < 0 || fl->nslip > n)
        fz_fail("%s: nslip = %d outside [0, %d]", fn, fl->nslip, n);
    for (i = 0; i < n; i++) {
        if (fl->x && !isfinite(fl->x[i]))
            fz_fail("%s: x[%d] = %g", fn, i, fl->x[i]);
        if (fl->y && !isfinite(fl->y[i]))
            fz_fail("%s: y[%d] = %g", fn, i, fl->y[i]);
        if (fl->x && !(fabs(fl->x[i]) <= c->a * (1.0 + 1e-12)))
            fz_fail("%s: x[%d] = %g outside |x| <= a = %g", fn, i, fl->x[i], c->a);
        if (fl->y && !(fabs(fl->y[i]) <= c->b * (1.0 + 1e-12)))
            fz_fail("%s: y[%d] = %g outside |y| <= b = %g", fn, i, fl->y[i], c->b);
        if (fl->pn && !(isfinite(fl->pn[i]) && fl->pn[i] >= 0.0))
            fz_fail("%s: pn[%d] = %g (must be finite, >= 0)", fn, i, fl->pn[i]);
        if (fl->px && !isfinite(fl->px[i]))
            fz_fail("%s: px[%d] = %g", fn, i, fl->px[i]);
        if (fl->py && !isfinite(fl->py[i]))
            fz_fail("%s: py[%d] = %g", fn, i, fl->py[i]);
        if (fl->pn && fl->px && fl->py
            && !(hypot(fl->px[i], fl->py[i]) <= fr->mu0 * fl->pn[i] * (1.0 + 1e-9)))
            fz_fail("%s: element %d: |(px, py)| = %.17g above mu0 pn = %.17g", fn, i,
                    hypot(fl->px[i], fl->py[i]), fr->mu0 * fl->pn[i]);
        if (fl->slip) {
            if (fl->slip[i] != 0 && fl->slip[i] != 1)
                fz_fail("%s: slip[%d] = %d, not 0 or 1", fn, i, fl->slip[i]);
            nslip += fl->slip[i];
        }
        if (fl->pn) sum_p += fl->pn[i];
        if (fl->px) sum_x += fl->px[i];
        if (fl->py) sum_y += fl->py[i];
    }
    if (fl->slip && nslip != fl->nslip)
        fz_fail("%s: nslip = %d but %d elements flagged", fn, fl->nslip, nslip);
    if (o->v[RR_FASTSIM_GRID] != RR_GRID_RECT || !isfinite(area))
        return;
    if (fl->pn && isfinite(sum_p * dx * dy) && !(fabs(sum_p * dx * dy - c->N) <= 1e-9 * c->N))
        fz_fail("%s: pressure sums to %.17g, not N = %.17g", fn, sum_p * dx * dy, c->N);
    /* mu0 N first: 1e-9 mu0 underflows to 0 for a subnormal mu0 */
    scale = 1e-9 * (fr->mu0 * c->N);
    if (fl->px && isfinite(sum_x * dx * dy) && !(fabs(sum_x * dx * dy - f->fx) <= scale))
        fz_fail("%s: px sums to %.17g, not fx = %.17g", fn, sum_x * dx * dy, f->fx);
    if (fl->py && isfinite(sum_y * dx * dy) && !(fabs(sum_y * dx * dy - f->fy) <= scale))
        fz_fail("%s: py sums to %.17g, not fy = %.17g", fn, sum_y * dx * dy, f->fy);
}

static void run_fastsim(fz_in *in, const rr_contact_problem *c, const rr_friction *fr,
                        rr_creep_opts *o)
{
    const int mode = fz_choice(in, 3), mask = (int)fz_u8(in);
    int grid_ok;
    size_t n;
    rr_fastsim_field fl;
    rr_forces f, f2;
    int st, st2, invalid;

    if (fz_choice(in, 2)) {   /* mostly a FASTSIM method: the others must be refused */
        const int from = o->method;
        o->method = RR_METHOD_FASTSIM + fz_choice(in, 3);
        if (!is_fastsim(from))
            rr_creep_opts_default(o, o->method);    /* the others' values mean other options */
    }
    /* the grid of the options as they are now (a switch of method above
     * resets them: sized before it, the field was too short for them) */
    grid_ok = !bad_int(o->v[RR_FASTSIM_NX], 1, RR_FASTSIM_MAX_GRID)
              && !bad_int(o->v[RR_FASTSIM_NY], 1, RR_FASTSIM_MAX_GRID);
    n = grid_ok ? (size_t)o->v[RR_FASTSIM_NX] * (size_t)o->v[RR_FASTSIM_NY] : 0;
    fz_note("; rr_fastsim method %d, field mode %d mask %d", o->method, mode, mask);
    invalid = contact_invalid(c) || friction_invalid(fr) || opts_invalid(o) || !is_fastsim(o->method)
              || (falling(fr) && !(c->speed > 0.0));
    memset(&fl, 0, sizeof fl);
    fl.nslip = -7;
    if (mode > 0 && n > 0) {
        fl.x = (mode == 1 || (mask & 1)) ? fz_alloc(n * sizeof *fl.x) : NULL;
        fl.y = (mode == 1 || (mask & 2)) ? fz_alloc(n * sizeof *fl.y) : NULL;
        fl.pn = (mode == 1 || (mask & 4)) ? fz_alloc(n * sizeof *fl.pn) : NULL;
        fl.px = (mode == 1 || (mask & 8)) ? fz_alloc(n * sizeof *fl.px) : NULL;
        fl.py = (mode == 1 || (mask & 16)) ? fz_alloc(n * sizeof *fl.py) : NULL;
        fl.slip = (mode == 1 || (mask & 32)) ? fz_alloc(n * sizeof *fl.slip) : NULL;
    }
    st = rr_fastsim(c, o, &f, mode > 0 ? &fl : NULL);
    if (!(st >= 0 && (fz_known("extreme", known_extreme(c, fr))
                      || fz_known("blended", known_blended(c, o->method))))) {
        check_forces("rr_fastsim", st, c, fr, 1, invalid, &f);
        if (mode > 0 && n > 0)
            check_field(st, c, fr, o, &f, &fl);
        if (st >= 0 && mode == 0) {
            /* the dispatcher must give exactly the same */
            st2 = rr_creep_forces(c, o, &f2);
            if (st2 != st || memcmp(&f, &f2, sizeof f) != 0)
                fz_fail("rr_creep_forces: status %d (%g, %g, %g) but rr_fastsim %d (%g, %g, %g)",
                        st2, f2.fx, f2.fy, f2.mz, st, f.fx, f.fy, f.mz);
        }
    }
    free(fl.x);
    free(fl.y);
    free(fl.pn);
    free(fl.px);
    free(fl.py);
    free(fl.slip);
}

static void run_shared(fz_in *in, const rr_contact_problem *c, const rr_friction *fr,
                       const rr_creep_opts *o)
{
    rr_kalker_coeffs k;
    const double w = fz_log(in, 1e-6, 100.0);
    int st;

    fz_note("; slip speed w = %.17g", w);
    st = rr_creep_opts_check(o);
    fz_status("rr_creep_opts_check", st);
    if ((st < 0) != opts_invalid(o))
        fz_fail("rr_creep_opts_check: status %d for options that are %s", st,
                opts_invalid(o) ? "invalid" : "valid");
    {
        int field = -99;
        const int bad = contact_invalid(c) || friction_invalid(fr);
        st = rr_contact_problem_check(c, &field);
        fz_status("rr_contact_problem_check", st);
        if ((st < 0) != bad)
            fz_fail("rr_contact_problem_check: status %d for a problem that is %s", st,
                    bad ? "invalid" : "valid");
        if (st < 0 ? !fz_member_at_fault(c, field, st) : field != RR_PF_NONE)
            fz_fail("rr_contact_problem_check: status %d names member %d (%s)", st, field,
                    rr_problem_field_name(field) ? rr_problem_field_name(field) : "none");
        if (st != rr_contact_problem_check(c, NULL))
            fz_fail("rr_contact_problem_check: another status without the report");
    }
    st = rr_friction_check(fr);
    fz_status("rr_friction_check", st);
    if ((st < 0) != friction_invalid(fr))
        fz_fail("rr_friction_check: status %d for a law that is %s", st,
                friction_invalid(fr) ? "invalid" : "valid");
    st = rr_creep_prepare(c, &k);
    fz_status("rr_creep_prepare", st);
    fz_error("rr_creep_prepare", st,
             contact_invalid(c) || friction_invalid(fr) || (falling(fr) && !(c->speed > 0.0)),
             "an argument is invalid");
    if (!friction_invalid(fr) && isfinite(w) && w >= 0.0) {
        const double mu = rr_friction_mu(fr, w), dmu = rr_friction_dmu(fr, w);
        const double lo = fr->A * fr->mu0;
        /* mu falls from mu0 toward A mu0; its slope is never positive */
        if (!(mu >= lo * (1.0 - 1e-15) && mu <= fr->mu0 * (1.0 + 1e-15)))
            fz_fail("rr_friction_mu(%.17g) = %.17g outside [A mu0, mu0] = [%.17g, %.17g]", w,
                    mu, lo, fr->mu0);
        /* known: mu0 (1 - A) B overflows for huge B, times exp(-B w) = 0: NaN */
        if (!(isfinite(dmu) && dmu <= 0.0)
            && !fz_known("friction_dmu", !(fr->mu0 * fr->B < 1e300)))
            fz_fail("rr_friction_dmu(%.17g) = %.17g (must be finite, <= 0)", w, dmu);
    }
    {
        /* every method's defaults are valid options */
        rr_creep_opts d;
        int m;
        for (m = 0; m < RR_METHOD_COUNT; m++) {
            rr_creep_opts_default(&d, m);
            if ((st = rr_creep_opts_check(&d)) != RR_OK)
                fz_fail("rr_creep_opts_check: status %d for method %d's defaults", st, m);
        }
    }
}

/* the status rr_creep_opts_set must give for value on option op */
static int predict_option(const rr_creep_option *op, double x)
{
    if (op->type == RR_OPT_REAL && !isfinite(x))
        return RR_ERR_NONFINITE;
    if (!isfinite(x))
        return op->status;
    if ((op->lo_open ? !(x > op->lo) : !(x >= op->lo)) || (op->hi_open ? !(x < op->hi) : !(x <= op->hi)))
        return op->status;
    if (op->type == RR_OPT_INT && x != floor(x))
        return op->status;
    if (op->type == RR_OPT_CHOICE) {
        int n = 0;
        while (op->choices && op->choices[n])
            n++;
        if (!(x == floor(x) && x >= 0.0 && x < n))
            return op->status;
    }
    return RR_OK;
}

/* The registry: rr_method_count/get/find, rr_creep_opts_default/set/
 * check_at, cost, saturates, slope scale, workspace length, and
 * rr_creep_forces_work and rr_creep_field against rr_creep_forces. */
static void run_registry(fz_in *in, const rr_contact_problem *c, const rr_friction *fr,
                         rr_creep_opts *o)
{
    const int m = fz_int(in, 0, RR_METHOD_COUNT - 1);
    const rr_method_desc *d = rr_method_get(m);
    const int nset = fz_range(in, 0, 4);
    rr_creep_opts before;
    rr_forces f, f2;
    int i, st, st2, ost, bad = -99;

    if (rr_method_count() != RR_METHOD_COUNT || rr_method_get(-1) || rr_method_get(RR_METHOD_COUNT)
        || rr_method_find(NULL) != RR_ERR_NULL || rr_method_find("no-such-method") != RR_ERR_METHOD)
        fz_fail("rr_method_count/get/find: the edges not as documented");
    if ((m >= 0 && m < RR_METHOD_COUNT) != (d != NULL)
        || (d && rr_method_find(d->name) != m))
        fz_fail("rr_method_get/find: method %d", m);
    /* the defaults of method m (known or not) */
    st = rr_creep_opts_default(o, m);
    if (st != (d ? RR_OK : RR_ERR_METHOD) || o->method != m)
        fz_fail("rr_creep_opts_default(%d): status %d, method %d", m, st, o->method);
    for (i = 0; i < RR_CREEP_MAX_OPTS; i++) {
        const int own = d && i < d->nopts;
        if (own ? !(o->v[i] == d->opts[i].def) : !isnan(o->v[i]))
            fz_fail("rr_creep_opts_default(%d): v[%d] = %g", m, i, o->v[i]);
    }
    if (rr_creep_opts_default(NULL, 0) != RR_ERR_NULL)
        fz_fail("rr_creep_opts_default(NULL): not RR_ERR_NULL");
    for (i = 0; i < nset; i++) {
        const int k = fz_int(in, 0, d ? d->nopts - 1 : 0);
        const rr_creep_option *op = d && k >= 0 && k < d->nopts ? &d->opts[k] : NULL;
        const char *name = op ? op->name : fz_choice(in, 4) == 0 ? NULL : "no-such-option";
        const double x = op && op->type != RR_OPT_REAL && fz_choice(in, 2)
                             ? (double)fz_int(in, (int)fmax(op->lo, -1e6), (int)fmin(op->hi, 64.0))
                             : fz_lin(in, op ? fmax(op->lo, -10.0) : 0.0, op ? fmin(op->hi, 10.0) : 1.0);
        const int want = !name ? RR_ERR_NULL : !d ? RR_ERR_METHOD : !op ? RR_ERR_PARAM
                         : predict_option(op, x);
        before = *o;
        st = rr_creep_opts_set(o, name, x);
        fz_note("; opts_set %s = %.17g: %d", name ? name : "NULL", x, st);
        fz_status("rr_creep_opts_set", st);
        if (st != want && !(want == RR_ERR_METHOD && st == RR_ERR_METHOD))
            fz_fail("rr_creep_opts_set: %s = %.17g: status %d, the header's %d",
                    name ? name : "NULL", x, st, want);
        if (st != RR_OK) {
            fz_same("rr_creep_opts_set", &before, o, sizeof *o, "the options (on error)");
        } else {
            before.v[k] = x;
            if (memcmp(&before, o, sizeof *o) != 0)
                fz_fail("rr_creep_opts_set: %s = %.17g: not exactly that option changed", name, x);
        }
    }
    if (fz_choice(in, 4) == 0 && d && d->nopts > 0)
        o->v[fz_range(in, 0, d->nopts - 1)] = fz_lin(in, -2.0, 5000.0);   /* by index, unchecked */
    st = rr_creep_opts_check_at(o, &bad);
    ost = st;
    st2 = rr_creep_opts_check(o);
    fz_status("rr_creep_opts_check_at", st);
    if (st != st2 || (st < 0) != opts_invalid(o))
        fz_fail("rr_creep_opts_check_at: status %d, rr_creep_opts_check %d, options %s", st, st2,
                opts_invalid(o) ? "invalid" : "valid");
    if (st < 0 && !(d ? bad >= 0 && bad < d->nopts : bad == -1))
        fz_fail("rr_creep_opts_check_at: *bad = %d for method %d", bad, m);
    {
        const double cost = rr_creep_cost(o), slope = rr_creep_slope_scale(o);
        const int sat = rr_creep_saturates(o);
        const size_t wl = rr_creep_workspace_len(o, NULL);
        if (st < 0 ? !(cost == 0.0 && isnan(slope) && sat == 0 && wl == 0)
                   : !(isfinite(cost) && cost >= 1.0 && isfinite(slope) && slope > 0.0
                       && sat == d->saturates && (sat == 0) == (m == RR_METHOD_LINEAR)))
            fz_fail("rr_creep_cost %g, slope_scale %g, saturates %d, workspace %zu for %s "
                    "options", cost, slope, sat, wl, st < 0 ? "invalid" : "valid");
        /* a closed form: no traction field, no workspace (the exact solver
         * has neither field entry nor a bounded cost) */
        if (st == RR_OK && !(cost <= 2.0 * MAX_GRID_ELEMENTS + 1.0)
            && d->field_shape == NULL && wl == 0)
            fz_fail("rr_creep_cost %g for a closed form", cost);
        /* rr_creep_forces_work with exactly the workspace asked for */
        {
            const size_t n = wl > 0 ? wl : 1;
            double *work = fz_guarded(n * sizeof(double));
            st = rr_creep_forces_work(c, o, work, wl, &f);
            fz_guard_ok("rr_creep_forces_work", work, n * sizeof(double), "work");
            st2 = rr_creep_forces(c, o, &f2);
            if (wl == 0 && (st != st2 || memcmp(&f, &f2, sizeof f) != 0))
                fz_fail("rr_creep_forces_work: status %d (%g, %g, %g), rr_creep_forces %d "
                        "(%g, %g, %g)", st, f.fx, f.fy, f.mz, st2, f2.fx, f2.fy, f2.mz);
            if (wl > 0 && (rr_creep_forces_work(c, o, work, wl - 1, &f2) != RR_ERR_WORKSPACE
                           || st2 != RR_ERR_WORKSPACE))
                fz_fail("rr_creep_forces_work: a workspace one double short not refused");
            if (st < 0 && (!isnan(f.fx) || !isnan(f.fy) || !isnan(f.mz)))
                fz_fail("rr_creep_forces_work: error %d but the forces are not NaN", st);
            /* checked once, then trusted: the same forces, or a refused record */
            {
                rr_creep_checked k;
                int kbad = -99, kst;
                kst = rr_creep_check(&k, o, &kbad);
                fz_status("rr_creep_check", kst);
                if (kst != ost || kbad != bad
                    || (kst == RR_OK && (k.work_len != wl || k.cost != cost)))
                    fz_fail("rr_creep_check: status %d, *bad %d; rr_creep_opts_check_at %d, %d",
                            kst, kbad, ost, bad);
                st2 = rr_creep_forces_checked(&k, c, work, wl, NULL, &f2);
                fz_status("rr_creep_forces_checked", st2);
                if (kst == RR_OK ? st2 != st || memcmp(&f, &f2, sizeof f) != 0
                                 : st2 != RR_ERR_NULL || !isnan(f2.fx) || !isnan(f2.fy)
                                   || !isnan(f2.mz))
                    fz_fail("rr_creep_forces_checked: status %d (%g, %g, %g), "
                            "rr_creep_forces_work %d (%g, %g, %g), the record %s", st2, f2.fx,
                            f2.fy, f2.mz, st, f.fx, f.fy, f.mz, kst ? "refused" : "checked");
                /* the member a method's status blames (for kst OK: the status it gave) */
                if (kst == RR_OK && st < 0) {
                    const int field = rr_creep_blame(&k, c, st);
                    if (field != RR_PF_NONE && !blame_right(&k, c, field, st))
                        fz_fail("rr_creep_blame: status %d of %s blames member %d (%s)", st,
                                k.d->name, field, rr_problem_field_name(field));
                    /* none: a result out of range, or a problem the check refuses
                     * for another reason than the method (the linear theory
                     * judges the friction law first) */
                    if (field == RR_PF_NONE && st != RR_ERR_RANGE && st != RR_ERR_NULL
                        && st != RR_ERR_WORKSPACE && rr_contact_problem_check(c, NULL) >= 0
                        && !(m == RR_METHOD_EXACT && (st == RR_ERR_GEOMETRY
                                                      || st == RR_ERR_GRID)))
                        fz_fail("rr_creep_blame: status %d of %s blames no member", st,
                                k.d->name);
                }
                if (rr_creep_blame(&k, c, RR_OK) != RR_PF_NONE
                    || rr_creep_blame(NULL, c, RR_ERR_LOAD) != RR_PF_NONE
                    || rr_creep_blame(&k, NULL, RR_ERR_LOAD) != RR_PF_NONE)
                    fz_fail("rr_creep_blame: a member for success or NULL arguments");
                /* the method changed after the check: not the record's */
                k.o.method = (k.o.method + 2) % (RR_METHOD_COUNT + 2) - 1;
                st2 = rr_creep_forces_checked(&k, c, work, wl, NULL, &f2);
                if (st2 != RR_ERR_NULL || !isnan(f2.fx) || !isnan(f2.fy) || !isnan(f2.mz))
                    fz_fail("rr_creep_forces_checked: status %d for a record whose method "
                            "changed to %d", st2, k.o.method);
            }
            /* the interrupt hook: counted from 2 (never stops) or from 1 (stops) */
            {
                int q, count;
                rr_interrupt hook;
                hook.poll = polled;
                hook.ctx = &count;
                for (q = 2; q >= 1; q--) {
                    count = q;
                    st2 = rr_creep_forces_interruptible(c, o, work, wl, &hook, &f2);
                    if (count > q && !(d && d->forces_interruptible))
                        fz_fail("rr_creep_forces_interruptible: a method without the hook's "
                                "entry polled it");
                    if (q == 1 && count > 1
                        ? st2 != RR_ERR_INTERRUPTED || !isnan(f2.fx) || count != 2
                        : st2 != st || memcmp(&f, &f2, sizeof f) != 0)
                        fz_fail("rr_creep_forces_interruptible: status %d (%g, %g, %g) after %d "
                                "polls, rr_creep_forces_work %d (%g, %g, %g)", st2, f2.fx, f2.fy,
                                f2.mz, count - q, st, f.fx, f.fy, f.mz);
                }
            }
            if (st >= 0 && !(fz_known("extreme", known_extreme(c, fr))
                             || fz_known("blended", known_blended(c, m))
                             || fz_known("polach", m == RR_METHOD_POLACH && known_polach(c)))) {
                FZ_FINITE("rr_creep_forces_work", st, f.fx);
                FZ_FINITE("rr_creep_forces_work", st, f.fy);
                FZ_FINITE("rr_creep_forces_work", st, f.mz);
            }
            fz_guard_free(work);
        }
    }
    /* rr_creep_field: the field's shape, every array between canaries */
    {
        rr_traction_field fl;
        int rows = 0, cols = 0;
        size_t n = 1;
        const int has = st2 >= 0 || (d && rr_creep_opts_check(o) == RR_OK);
        memset(&fl, 0, sizeof fl);
        if (has && d && d->field_shape) {
            d->field_shape(o, NULL, &rows, &cols);
            if (!(rows >= 1 && cols >= 1 && rows <= RR_FASTSIM_MAX_GRID
                  && cols <= RR_FASTSIM_MAX_GRID))
                fz_fail("field_shape: %d x %d for valid options", rows, cols);
            n = (size_t)rows * (size_t)cols;
            /* a grid set through rr_creep_opts_set (not capped as the
             * decoded ones are, e.g. 34 x 1000): the field of a million
             * elements at most, so that one input stays fast */
            if (n > FIELD_MAX_ELEMENTS)
                return;
        }
        fl.x = fz_guarded(n * sizeof(double));
        fl.y = fz_guarded(n * sizeof(double));
        fl.area = fz_guarded(n * sizeof(double));
        fl.pn = fz_guarded(n * sizeof(double));
        fl.px = fz_guarded(n * sizeof(double));
        fl.py = fz_guarded(n * sizeof(double));
        fl.slip = fz_guarded(n);
        st = rr_creep_field(c, o, &f, &fl);
        fz_status("rr_creep_field", st);
        fz_guard_ok("rr_creep_field", fl.x, n * sizeof(double), "x");
        fz_guard_ok("rr_creep_field", fl.y, n * sizeof(double), "y");
        fz_guard_ok("rr_creep_field", fl.area, n * sizeof(double), "area");
        fz_guard_ok("rr_creep_field", fl.pn, n * sizeof(double), "pn");
        fz_guard_ok("rr_creep_field", fl.px, n * sizeof(double), "px");
        fz_guard_ok("rr_creep_field", fl.py, n * sizeof(double), "py");
        fz_guard_ok("rr_creep_field", fl.slip, n, "slip");
        if (d && !d->field && rr_creep_opts_check(o) == RR_OK && st != RR_ERR_METHOD)
            fz_fail("rr_creep_field: method %s has no field, status %d", d->name, st);
        if (st < 0 && (!isnan(f.fx) || !isnan(f.fy) || !isnan(f.mz)))
            fz_fail("rr_creep_field: error %d but the forces are not NaN", st);
        if (st >= 0 && !(fz_known("extreme", known_extreme(c, fr))
                         || fz_known("blended", known_blended(c, m)))) {
            FZ_FINITE("rr_creep_field", st, f.fx);
            FZ_FINITE("rr_creep_field", st, f.fy);
            FZ_FINITE("rr_creep_field", st, f.mz);
            fz_bound("rr_creep_field", st, f.fx, f.fy, fr->mu0, c->N);
            if (!(fl.nslip >= 0 && (size_t)fl.nslip <= n))
                fz_fail("rr_creep_field: nslip = %d of %zu elements", fl.nslip, n);
        }
        fz_guard_free(fl.x);
        fz_guard_free(fl.y);
        fz_guard_free(fl.area);
        fz_guard_free(fl.pn);
        fz_guard_free(fl.px);
        fz_guard_free(fl.py);
        fz_guard_free(fl.slip);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    const int op = fz_choice(&in, 6);
    rr_contact_problem c = {0};     /* an ellipse problem */
    rr_friction fr;
    rr_creep_opts o;
    rr_forces f, f2;
    int st, st2;

    decode_case(&in, &c);
    decode_friction(&in, &fr);
    c.friction = fr;
    decode_opts(&in, &o);
    fz_note("op %d; case a = %.17g, b = %.17g, N = %.17g, G = %.17g, nu = %.17g, cx = %.17g, "
            "cy = %.17g, cphi = %.17g, speed = %.17g; friction mu0 = %.17g, A = %.17g, B = %.17g; "
            "opts method %d, v = %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g", op, c.a, c.b,
            c.N, c.G, c.nu, c.cx, c.cy, c.cphi, c.speed, fr.mu0, fr.A, fr.B, o.method, o.v[0],
            o.v[1], o.v[2], o.v[3], o.v[4], o.v[5], o.v[6], o.v[7]);
    switch (op) {
    case 0: {
        const int invalid = opts_invalid(&o) || contact_invalid(&c)
                            || (o.method != RR_METHOD_LINEAR
                                && (friction_invalid(&fr) || (falling(&fr) && !(c.speed > 0.0))))
                            || (o.method == RR_METHOD_FASTRIP && falling(&fr));   /* Coulomb only */
        st = rr_creep_forces(&c, &o, &f);
        if (st >= 0 && (fz_known("extreme", known_extreme(&c, &fr))
                        || fz_known("blended", known_blended(&c, o.method))
                        || fz_known("polach", o.method == RR_METHOD_POLACH && known_polach(&c))))
            break;
        check_forces("rr_creep_forces", st, &c, &fr,
                     o.method != RR_METHOD_LINEAR && !unbounded_fastrip(&o), invalid, &f);
        break;
    }
    case 1:
        st = rr_linear(&c, &f);
        if (st >= 0 && fz_known("extreme", known_extreme(&c, &fr)))
            break;
        /* an invalid friction law is refused, before the rest, though the
         * linear theory reads none */
        check_forces("rr_linear", st, &c, &fr, 0, contact_invalid(&c) || friction_invalid(&fr),
                     &f);
        if (friction_invalid(&fr) && st != rr_friction_check(&fr))
            fz_fail("rr_linear: status %d with an invalid law (its check: %d)", st,
                    rr_friction_check(&fr));
        o.method = RR_METHOD_LINEAR;
        st2 = rr_creep_forces(&c, &o, &f2);
        if (st2 != st || memcmp(&f, &f2, sizeof f) != 0)
            fz_fail("rr_creep_forces: linear theory differs from rr_linear");
        break;
    case 2: {
        const int invalid = contact_invalid(&c) || friction_invalid(&fr)
                            || (falling(&fr) && !(c.speed > 0.0))
                            || !(isfinite(o.v[RR_POLACH_KA]) && isfinite(o.v[RR_POLACH_KS]) && o.v[RR_POLACH_KS] > 0.0
                                 && o.v[RR_POLACH_KS] <= o.v[RR_POLACH_KA] && o.v[RR_POLACH_KA] <= 1.0);
        st = rr_polach(&c, o.v[RR_POLACH_KA], o.v[RR_POLACH_KS], &f);
        if (st >= 0 && (fz_known("extreme", known_extreme(&c, &fr))
                        || fz_known("polach", known_polach(&c))))
            break;
        check_forces("rr_polach", st, &c, &fr, 1, invalid, &f);
        o.method = RR_METHOD_POLACH;
        st2 = rr_creep_forces(&c, &o, &f2);
        /* the dispatcher checks the options first, in the descriptor's
         * order (kA, then kS); rr_polach both for finiteness first: with
         * invalid options only the dispatcher's own status is promised */
        if (rr_creep_opts_check(&o) != RR_OK) {
            if (st2 != rr_creep_opts_check(&o) || !isnan(f2.fx) || !isnan(f2.fy) || !isnan(f2.mz))
                fz_fail("rr_creep_forces: invalid Polach options, status %d (check %d)", st2,
                        rr_creep_opts_check(&o));
        } else if (st2 != st || memcmp(&f, &f2, sizeof f) != 0) {
            fz_fail("rr_creep_forces: Polach differs from rr_polach");
        }
        break;
    }
    case 3:
        run_fastsim(&in, &c, &fr, &o);
        break;
    case 4:
        run_shared(&in, &c, &fr, &o);
        break;
    default:
        run_registry(&in, &c, &fr, &o);
        break;
    }
    return 0;
}
