/*
 * fuzz_rig.c - the rig in time: rr_rig_check and rr_rig_init with parameters
 * perturbed from the default rig's (the adhesion's schedule and patch
 * among them), then a sequence of rr_rig_step, run, sample, advance, rhs,
 * jac, set_state, record, read and write (commands of every mode); and each
 * of these on a zeroed, never-initialised rr_rig.
 *
 * Input: a byte for the zeroed-rig case; the parameters (the default set,
 * or up to 8 fields chosen by the input, or all of them, each moved by a
 * factor or to an edge value; the integer settings anywhere, with nsub,
 * the grid and the Newton count kept small enough for one input to stay
 * below 0.1 s); the table (the default one, NULL, or without data); the
 * roller speed; then up to 8 operations with their references and states.
 *
 * Oracles: statuses in range; a rig whose parameters rr_rig_check refuses
 * (among them a method it does not step with, a drive's loop unstable at
 * T) does not initialise; every record of a success finite (the target is
 * NaN without creepage control, as documented) and carrying its status;
 * each wheel's creep force within mu0 N (every method it steps with); after an
 * error the state is that of the sample's start and the rig refuses to
 * step on; a failing rr_rig_sample or rr_rig_write changes nothing; a
 * reading out of order is refused (RR_ERR_SEQUENCE); a torque command is
 * held clipped at its limit; rr_rig_run's count and
 * status as documented; rhs and jac finite on success; set_state refuses
 * non-finite input and leaves the state alone.  The full state
 * (rr_rig_get_full_state, rr_rig_set_full_state): NaN on error, on success
 * no infinity and NaN only where documented (xi_ref, creepctl_w_ref); a
 * rig that never started refuses both; its own state set back leaves the
 * same bits (taken, or refused where rr_rig_set_state had put the plant
 * off its rollers); one value moved anywhere (NaN, infinities, huge, a flag or
 * counter off its values) either refused with nothing changed or taken,
 * and the rig then steps or refuses with a status.
 */
#include <stddef.h>
#include "fuzz_rig.h"

#define MAX_OPS 8
#define MAX_RUN 3

typedef struct {
    size_t offset;
    double factor;   /* a perturbation moves the default by up to this factor */
} double_field;

#define DF(member, f) {offsetof(rr_rig_params, member), f}

static const double_field double_fields[] = {
    DF(mass, 10.0), DF(Iyy, 10.0), DF(Izz, 10.0), DF(axlebox_y, 3.0), DF(kx, 100.0),
    DF(ky, 100.0), DF(kz, 100.0), DF(cx, 100.0), DF(cy, 100.0), DF(cz, 100.0),
    DF(preload, 10.0), DF(g, 3.0), DF(roller_inertia, 10.0), DF(contact.R0, 1.5),
    DF(contact.estar, 100.0), DF(contact.G, 100.0), DF(contact.nu, 1.7),
    DF(contact.friction.mu0, 2.5), DF(contact.friction.A, 2.5), DF(contact.friction.B, 10.0),
    DF(contact.vmin, 100.0), DF(T, 10.0),
    DF(roller_pi.T, 2.0), DF(roller_pi.Kp, 10.0), DF(roller_pi.KI, 10.0),
    DF(roller_pi.Tmax, 10.0), DF(wheelset_pi.T, 2.0), DF(wheelset_pi.Kp, 10.0),
    DF(wheelset_pi.KI, 10.0), DF(wheelset_pi.Tmax, 10.0), DF(roller_tau, 10.0),
    DF(wheelset_tau, 10.0), DF(roller_enc.T, 2.0), DF(wheelset_enc.T, 2.0),
    DF(creepctl.r_w, 1.5), DF(creepctl.r_r, 1.5), DF(creepctl.alpha, 10.0),
    DF(creepctl.beta, 10.0), DF(creepctl.vmin, 10.0)
};
#define NDOUBLE ((int)(sizeof double_fields / sizeof double_fields[0]))

typedef struct {
    size_t offset;
    int lo, hi;      /* the plausible range (fz_int adds the edges) */
} int_field;

#define IF(member, lo, hi) {offsetof(rr_rig_params, member), lo, hi}

static const int_field int_fields[] = {
    IF(nsub, 1, 4), IF(method, 0, 2), IF(newton_iters, 0, RR_ODE_MAX_NEWTON),
    IF(linear_tr, 0, 1), IF(newton_model, 0, 1),
    IF(roller_enc.counts, 1, 16777216), IF(wheelset_enc.counts, 1, 16777216),
    IF(creepctl.sense, -1, 1)
};
#define NINT ((int)(sizeof int_fields / sizeof int_fields[0]))

/* Known: a parameter moved by more than 1e20 either way, or a speed,
 * reference or state of more than 1e20, overflows the contact evaluation
 * or the integrator: inf or NaN records with status 0.  Once such a value
 * has entered, the input is "tainted" and the finiteness oracles are
 * skipped (in the skip build only). */
static int tainted;

/* Known: rr_rig_rhs, rr_rig_jac and rr_rig_record do not look at whether
 * rr_rig_init succeeded: on a rig whose parameters it refused they
 * evaluate them anyway (Izz = 0: NaN with status 0). */
static int init_failed;

static void taint_param(double v, double d)
{
    if (isfinite(v) && (fabs(v) > 1e20 * fabs(d) || (v != 0.0 && fabs(v) < 1e-20 * fabs(d))))
        tainted = 1;
}

static void taint(double v)
{
    if (isfinite(v) && fabs(v) > 1e20)
        tainted = 1;
}

/* Settings that would let one input run long: nsub up to 1000 passes
 * rr_rig_check legitimately. */
static void cap_work(rr_rig_params *p)
{
    if (p->nsub > 5 && p->nsub <= 1000)
        p->nsub = 5;
    if (rr_creep_cost(&p->contact.creep) > 625.0) {
        p->contact.creep.v[RR_FASTSIM_NX] = 25;     /* a FASTSIM variant's grid */
        p->contact.creep.v[RR_FASTSIM_NY] = 25;
    }
}

static void perturb_field(fz_in *in, rr_rig_params *p, int which)
{
    if (which < NDOUBLE) {
        double *v = (double *)((char *)p + double_fields[which].offset);
        const double d = *v;
        *v = fz_near(in, d, double_fields[which].factor);
        taint_param(*v, d);
        fz_note(" double field %d (offset %lu) = %.17g;", which,
                (unsigned long)double_fields[which].offset, *v);
    } else if (which < NDOUBLE + NINT) {
        const int_field *f = &int_fields[which - NDOUBLE];
        int *v = (int *)((char *)p + f->offset);
        *v = fz_int(in, f->lo, f->hi);
        fz_note(" int field %d (offset %lu) = %d;", which - NDOUBLE, (unsigned long)f->offset,
                *v);
    } else if (which == NDOUBLE + NINT) {
        /* another method, its defaults (FASTSIM's grid as the default rig's) */
        rr_creep_opts *o = &p->contact.creep;
        rr_creep_opts_default(o, fz_int(in, 0, RR_METHOD_COUNT - 1));
        if (rr_creep_cost(o) > 400.0)
            o->v[RR_FASTSIM_NX] = o->v[RR_FASTSIM_NY] = 20;
        fz_note(" creep method %d;", o->method);
    } else if (which == NDOUBLE + NINT + 1) {
        /* one option of the method, from its descriptor: an integer or a
         * choice's index near its range, a real near its value */
        rr_creep_opts *o = &p->contact.creep;
        const rr_method_desc *d = rr_method_get(o->method);
        if (d && d->nopts > 0) {
            const int i = fz_choice(in, d->nopts);
            const rr_creep_option *op = &d->opts[i];
            if (op->type == RR_OPT_REAL) {
                const double was = o->v[i];
                o->v[i] = fz_near(in, was, 3.0);
                taint_param(o->v[i], was);
            } else {
                o->v[i] = fz_int(in, (int)op->lo, op->hi < 24.0 ? (int)op->hi : 24);
            }
            fz_note(" creep option %s = %.17g;", op->name, o->v[i]);
        }
    } else if (which == NDOUBLE + NINT + 2) {
        /* the adhesion: a schedule of up to 4 points, a patch */
        rr_rig_adhesion *a = &p->adhesion;
        int i;
        a->n = fz_int(in, 0, 4);
        for (i = 0; i < a->n && i < 4; i++) {
            a->t[i] = (i > 0 ? a->t[i - 1] : 0.0) + fz_lin(in, -0.01, 0.05);
            a->law[i].mu0 = fz_near(in, 0.3, 10.0);
            a->law[i].A = fz_lin(in, -0.1, 1.1);
            a->law[i].B = fz_near(in, 0.6, 10.0);
            taint(a->law[i].mu0);
            taint(a->law[i].B);
            fz_note(" schedule[%d] = (%.17g, %.17g, %.17g, %.17g);", i, a->t[i],
                    a->law[i].mu0, a->law[i].A, a->law[i].B);
        }
        a->patch_start = fz_lin(in, -1.0, 2.0);
        a->patch_length = fz_lin(in, -0.1, 1.1);
        a->patch_edge = fz_near(in, 0.002, 100.0);
        a->patch.mu0 = fz_near(in, 0.1, 10.0);
        a->patch.A = fz_lin(in, -0.1, 1.1);
        a->patch.B = fz_near(in, 0.2, 10.0);
        a->patch_rollers = fz_int(in, 0, 4);
        taint(a->patch.mu0);
        taint(a->patch.B);
        fz_note(" patch start %.17g length %.17g edge %.17g law (%.17g, %.17g, %.17g) on %d;",
                a->patch_start, a->patch_length, a->patch_edge, a->patch.mu0, a->patch.A,
                a->patch.B, a->patch_rollers);
    } else {
        /* the sample time of all sampled elements at once (they must agree) */
        const double T = fz_near(in, p->T, 10.0);
        taint_param(T, p->T);
        p->T = p->roller_pi.T = p->wheelset_pi.T = p->roller_enc.T = p->wheelset_enc.T = T;
        fz_note(" all T = %.17g;", T);
    }
}

static void decode_params(fz_in *in, rr_rig_params *p)
{
    const int mode = fz_choice(in, 4);
    const int table = fz_choice(in, 32);
    int i;

    fz_rig_params_default(p);
    fz_note("params mode %d, table %s:", mode, table == 0 ? "NULL" : "default");
    if (mode == 1 || mode == 2) {
        const int k = fz_range(in, 1, 8);
        for (i = 0; i < k; i++)
            perturb_field(in, p, fz_choice(in, NDOUBLE + NINT + 4));
    } else if (mode == 3) {
        for (i = 0; i < NDOUBLE + NINT + 4; i++)
            perturb_field(in, p, i);
    }
    if (table == 0)
        p->contact.table = NULL;
    cap_work(p);
}

static int positive(double v)
{
    return isfinite(v) && v > 0.0;
}

static int nonneg(double v)
{
    return isfinite(v) && v >= 0.0;
}

/* rr_rig_adhesion's documentation. */
static int adhesion_invalid(const rr_rig_params *p)
{
    const rr_rig_adhesion *a = &p->adhesion;
    int i;
    if (a->n < 0 || a->n > RR_RIG_MAX_SCHEDULE)
        return 1;
    for (i = 0; i < a->n; i++)
        if (!isfinite(a->t[i]) || (i > 0 && !(a->t[i] >= a->t[i - 1]))
            || rr_friction_check(&a->law[i]) != RR_OK)
            return 1;
    return !isfinite(a->patch_start) || !(a->patch_length >= 0.0)
        || !(a->patch_length <= 2.0 * RR_PI * p->contact.R0) || !positive(a->patch_edge)
        || a->patch_rollers < 1 || a->patch_rollers > 3
        || (a->patch_length > 0.0 && rr_friction_check(&a->patch) != RR_OK);
}

/* A drive's loop unstable at T (rr_rig_check's rule): each drive turning
 * its own inertia, the wheelset's inside eq. 13's loop (rr_rig.h). */
static int loops_unstable(const rr_rig_params *p)
{
    rr_speed_loop roller, wheelset;
    roller.pi = p->roller_pi;
    roller.J = p->roller_inertia;
    roller.tau = p->roller_tau;
    roller.alpha = 0.0;
    wheelset.pi = p->wheelset_pi;
    wheelset.J = p->Iyy;
    wheelset.tau = p->wheelset_tau;
    wheelset.alpha = p->creepctl.alpha;
    return rr_speed_loop_check(&roller) != RR_OK || rr_speed_loop_check(&wheelset) != RR_OK;
}

/* rr_rig_check's documentation, with the elements' own checks. */
static int params_invalid(const rr_rig_params *p)
{
    return adhesion_invalid(p) || loops_unstable(p)
        || rr_rig_method_check(&p->contact.creep) != RR_OK
        || !positive(p->mass) || !positive(p->Iyy) || !positive(p->Izz)
        || !positive(p->axlebox_y) || !positive(p->roller_inertia) || !nonneg(p->g)
        || !nonneg(p->kx) || !nonneg(p->ky) || !nonneg(p->kz) || !nonneg(p->cx)
        || !nonneg(p->cy) || !nonneg(p->cz) || !nonneg(p->preload) || !positive(p->T)
        || !positive(p->roller_tau) || !positive(p->wheelset_tau) || p->nsub < 1
        || p->nsub > 1000     /* rr_rig.c's cap; the header says only ">= 1" */
        || (p->method != RR_ODE_ROS2 && p->method != RR_ODE_TRBDF2
            && p->method != RR_ODE_LINEULER)
        || p->newton_iters < 0 || p->newton_iters > RR_ODE_MAX_NEWTON
        || (p->linear_tr != 0 && p->linear_tr != 1)
        || (p->newton_model != 0 && p->newton_model != 1)
        || rr_rig_contact_check(&p->contact) != RR_OK || rr_pi_check(&p->roller_pi) != RR_OK
        || rr_pi_check(&p->wheelset_pi) != RR_OK || rr_encoder_check(&p->roller_enc) != RR_OK
        || rr_encoder_check(&p->wheelset_enc) != RR_OK
        || rr_creepctl_check(&p->creepctl) != RR_OK || p->roller_pi.T != p->T
        || p->wheelset_pi.T != p->T || p->roller_enc.T != p->T || p->wheelset_enc.T != p->T;
}

/* control: whether the sample ran under creepage control (else the target is NaN) */
static void check_record(const char *fn, int st, int control, const double *rec)
{
    int j;
    if (rec[RR_REC_STATUS] != (double)st)
        fz_fail("%s: returned %d but recorded status %g", fn, st, rec[RR_REC_STATUS]);
    if (st < 0 || fz_known("extreme", tainted) || fz_known("failed_init", init_failed))
        return;
    for (j = 0; j < RR_REC_COUNT; j++) {
        if (j == RR_REC_XI_REF && !control)
            continue;       /* NaN: no target */
        if (j == RR_REC_W_REF && isnan(rec[j]))
            continue;       /* NaN: the wheelset's torque commanded */
        if (!isfinite(rec[j]))
            fz_fail("%s: status %d with non-finite record field %d = %g", fn, st, j, rec[j]);
    }
}

static void check_wheels(const char *fn, int st, const rr_rig *rig)
{
    int k;
    if (st < 0 || fz_known("extreme", tainted) || fz_known("failed_init", init_failed))
        return;
    for (k = 0; k < 2; k++)
        if (rig->w[k].status >= 0)       /* each wheel's own law: the adhesion's */
            fz_bound(fn, rig->w[k].status, rig->w[k].f.fx, rig->w[k].f.fy,
                     rig->w[k].friction.mu0, rig->w[k].N);
}

static double decode_xi(fz_in *in)
{
    const double xi = fz_choice(in, 4) == 0 ? NAN : fz_lin(in, 0.0, 0.1);
    taint(xi);
    return xi;
}

static double decode_ref(fz_in *in, const rr_rig *rig)
{
    const double w = rig->y[RR_RIG_ROLLER_SPIN];
    const double ref = fz_lin(in, 0.9 * w - 1.0, 1.1 * w + 1.0);
    taint(ref);
    return ref;
}

/* The state moved a little (or far, with edge values). */
static void decode_y(fz_in *in, const rr_rig *rig, double *y)
{
    const int k = fz_range(in, 0, 3);
    int i;
    memcpy(y, rig->y, RR_RIG_NSTATE * sizeof *y);
    for (i = 0; i < k; i++) {
        const int j = fz_choice(in, RR_RIG_NSTATE);
        y[j] += fz_slog(in, 1e-9, j == RR_RIG_Y || j == RR_RIG_X ? 1e-3 : 1.0);
        taint(y[j]);
        fz_note(" y[%d] = %.17g", j, y[j]);
    }
}

static int all_finite(const double *v, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

/* After an error the rig must refuse to go on, from its last good state. */
static void check_refuses(const char *fn, rr_rig *rig, const double *y0, double t0)
{
    double *rec = fz_alloc(RR_REC_COUNT * sizeof *rec);
    int st;
    if (rig->status >= 0) {
        free(rec);
        return;
    }
    if (memcmp(rig->y, y0, sizeof rig->y) != 0 || memcmp(&rig->t, &t0, sizeof t0) != 0)
        fz_fail("%s: failed with status %d but moved the state", fn, rig->status);
    st = rr_rig_step(rig, rig->y[RR_RIG_ROLLER_SPIN], NAN, rec);
    if (st >= 0)
        fz_fail("%s: the rig stepped on (status %d) after the error %d", fn, st, rig->status);
    free(rec);
}

/* A command of any modes (an unknown one among them), references near the
 * rig's speeds, a torque up to twice the limits, mu0 NaN or near 0.4. */
static void decode_command(fz_in *in, const rr_rig *rig, rr_rig_command *c)
{
    const int sel = fz_choice(in, 4);
    c->roller_mode = fz_int(in, -1, 3);
    c->wheelset_mode = fz_int(in, -1, 3);
    c->roller_ref = c->roller_mode == RR_CMD_TORQUE
                  ? fz_lin(in, -2.0 * rig->p->roller_pi.Tmax, 2.0 * rig->p->roller_pi.Tmax)
                  : decode_ref(in, rig);
    c->wheelset_ref = c->wheelset_mode == RR_CMD_TORQUE
                    ? fz_lin(in, -2.0 * rig->p->wheelset_pi.Tmax, 2.0 * rig->p->wheelset_pi.Tmax)
                    : c->wheelset_mode == RR_CMD_SPEED ? fz_lin(in, 0.0, 80.0) : decode_xi(in);
    c->mu0 = sel == 0 ? NAN : sel == 1 ? fz_near(in, 0.4, 100.0) : 0.4;
    taint(c->roller_ref);
    taint(c->wheelset_ref);
    taint(c->mu0);
    fz_note(" command (%d, %.17g, %d, %.17g, mu0 %.17g)", c->roller_mode, c->roller_ref,
            c->wheelset_mode, c->wheelset_ref, c->mu0);
}

/* rr_rig_write's documentation: which commands it must refuse */
static int command_invalid(const rr_rig_command *c)
{
    const int rm = c->roller_mode, wm = c->wheelset_mode;
    return rm < RR_CMD_BUILTIN || rm > RR_CMD_TORQUE || wm < RR_CMD_BUILTIN
        || wm > RR_CMD_TORQUE || !isfinite(c->roller_ref) || isinf(c->wheelset_ref)
        || (isnan(c->wheelset_ref) && wm != RR_CMD_BUILTIN) || isinf(c->mu0)
        || (!isnan(c->mu0) && !(c->mu0 > 0.0 && c->mu0 <= RR_FRICTION_MAX));
}

/* NaN may stand in the full state only where rr_rig.h says so. */
static int nan_allowed(int k)
{
    return k == RR_FS_XI_REF || k == RR_FS_CREEPCTL_W_REF;
}

static void check_full_state(const char *fn, int st, const double *v)
{
    int k;
    if (st < 0) {
        if (!fz_all_nan(v, RR_FS_COUNT))
            fz_fail("%s: status %d but the state is not NaN", fn, st);
        return;
    }
    for (k = 0; k < RR_FS_COUNT; k++)
        if (isinf(v[k]) || (isnan(v[k]) && !nan_allowed(k)))
            fz_fail("%s: status %d, %s = %g", fn, st, rr_rig_full_state_names()[k], v[k]);
}

/* get, set it back (the same bits), then one value moved and set: refused
 * with nothing changed, or taken */
static void full_state_op(fz_in *in, rr_rig *rig)
{
    double v[RR_FS_COUNT], w[RR_FS_COUNT], u[RR_FS_COUNT];
    const int k = fz_choice(in, RR_FS_COUNT);
    const double moved = fz_slog(in, 1e-6, 1e6);
    int st;

    if (rr_rig_full_state_len() != RR_FS_COUNT)
        fz_fail("rr_rig_full_state_len: %d, not %d", rr_rig_full_state_len(), RR_FS_COUNT);
    st = rr_rig_get_full_state(rig, v);
    fz_status("rr_rig_get_full_state", st);
    check_full_state("rr_rig_get_full_state", st, v);
    if (init_failed && st >= 0)
        fz_fail("rr_rig_get_full_state: status %d on a rig whose init failed", st);
    if (st < 0)
        return;
    /* the rig's own state: taken back, or (a plant state rr_rig_set_state
     * took unchecked: a wheel off its roller) refused; either way the same
     * bits after */
    st = rr_rig_set_full_state(rig, v);
    fz_status("rr_rig_set_full_state", st);
    st = rr_rig_get_full_state(rig, w);
    if (st < 0 || memcmp(v, w, sizeof v) != 0)
        fz_fail("rr_rig_set_full_state: the rig's own state not the same bits after a set");
    memcpy(u, v, sizeof u);
    u[k] = moved;
    fz_note(" full state %s = %.17g", rr_rig_full_state_names()[k], moved);
    st = rr_rig_set_full_state(rig, u);
    fz_status("rr_rig_set_full_state", st);
    if (!isfinite(moved) && !nan_allowed(k) && st >= 0)
        fz_fail("rr_rig_set_full_state: status %d for %s = %g", st,
                rr_rig_full_state_names()[k], moved);
    {
        const int refused = st < 0;
        st = rr_rig_get_full_state(rig, w);
        check_full_state("rr_rig_get_full_state", st, w);
        if (refused && (st < 0 || memcmp(v, w, sizeof v) != 0))
            fz_fail("rr_rig_set_full_state: refused %s = %g but changed the state",
                    rr_rig_full_state_names()[k], moved);
    }
}

static void one_op(fz_in *in, rr_rig *rig)
{
    const int op = fz_choice(in, 11);
    double y0[RR_RIG_NSTATE], t0 = rig->t;
    double *rec = fz_alloc(RR_REC_COUNT * sizeof *rec);
    double y[RR_RIG_NSTATE], *J;
    int st;

    memcpy(y0, rig->y, sizeof y0);
    fz_note(" | op %d (rig status %d, t %.17g)", op, rig->status, rig->t);
    switch (op) {
    case 0: {
        const double ref = decode_ref(in, rig), xi = decode_xi(in);
        const int was_refusing = rig->status < 0;
        fz_note(" step(roller_ref %.17g, xi_ref %.17g)", ref, xi);
        st = rr_rig_step(rig, ref, xi, rec);
        fz_status("rr_rig_step", st);
        check_record("rr_rig_step", st, rig->creep_control, rec);
        check_wheels("rr_rig_step", st, rig);
        if (was_refusing && st >= 0)
            fz_fail("rr_rig_step: stepped after an error");
        if (st < 0 && (memcmp(rig->y, y0, sizeof y0) != 0 || memcmp(&rig->t, &t0, sizeof t0)))
            fz_fail("rr_rig_step: error %d but the state moved", st);
        check_refuses("rr_rig_step", rig, y0, t0);
        break;
    }
    case 1: {
        const long n = fz_range(in, 0, MAX_RUN);
        double *refs = fz_alloc((size_t)(n > 0 ? n : 1) * sizeof *refs);
        double *xis = fz_alloc((size_t)(n > 0 ? n : 1) * sizeof *xis);
        double *recs = fz_alloc((size_t)(n > 0 ? n : 1) * RR_REC_COUNT * sizeof *recs);
        const int want_status = fz_choice(in, 4) != 0;
        int status = 99;
        long k, done;
        for (k = 0; k < n; k++) {
            refs[k] = decode_ref(in, rig);
            xis[k] = decode_xi(in);
            fz_note(" run[%ld](%.17g, %.17g)", k, refs[k], xis[k]);
        }
        done = rr_rig_run(rig, n, refs, xis, recs, want_status ? &status : NULL);
        if (done < 0 || done > n)
            fz_fail("rr_rig_run: %ld samples done of %ld", done, n);
        if (want_status) {
            fz_status("rr_rig_run", status);
            if (done < n && status >= 0)
                fz_fail("rr_rig_run: stopped after %ld of %ld with status %d", done, n, status);
            if (done < n && recs[done * RR_REC_COUNT + RR_REC_STATUS] != status)
                fz_fail("rr_rig_run: stopped at row %ld whose status %g is not %d", done,
                        recs[done * RR_REC_COUNT + RR_REC_STATUS], status);
        }
        for (k = 0; k < done; k++)
            check_record("rr_rig_run", (int)recs[k * RR_REC_COUNT + RR_REC_STATUS],
                         !isnan(xis[k]), recs + k * RR_REC_COUNT);
        free(refs);
        free(xis);
        free(recs);
        break;
    }
    case 2: {
        const double ref = decode_ref(in, rig), xi = decode_xi(in);
        rr_rig *before = fz_alloc(sizeof *before);
        fz_note(" sample(roller_ref %.17g, xi_ref %.17g)", ref, xi);
        memcpy(before, rig, sizeof *rig);
        st = rr_rig_sample(rig, ref, xi);
        fz_status("rr_rig_sample", st);
        if (st < 0)
            fz_same("rr_rig_sample", before, rig, sizeof *rig, "the rig (error: nothing changes)");
        free(before);
        break;
    }
    case 8: {
        /* a reading: refused out of order, NaN signals then */
        rr_rig_signals sig;
        const int phase = rig->phase, was_refusing = rig->status < 0;
        st = rr_rig_read(rig, &sig);
        fz_note(" read");
        fz_status("rr_rig_read", st);
        if (!init_failed && !was_refusing && phase != 0 && st != RR_ERR_SEQUENCE)
            fz_fail("rr_rig_read: status %d in phase %d (a second reading)", st, phase);
        if (st < 0 && !isnan(sig.t))
            fz_fail("rr_rig_read: error %d with signals", st);
        if (st >= 0 && !fz_known("extreme", tainted))
            fz_finite_n("rr_rig_read", st, "signals", &sig.t, (int)(sizeof sig / sizeof sig.t));
        break;
    }
    case 9: {
        /* a command after a reading (or out of order: refused) */
        rr_rig_command c;
        rr_rig *before = fz_alloc(sizeof *before);
        const int phase = rig->phase;
        decode_command(in, rig, &c);
        memcpy(before, rig, sizeof *rig);
        st = rr_rig_write(rig, &c);
        fz_status("rr_rig_write", st);
        if (!init_failed && rig->status >= 0 && phase != 1 && st != RR_ERR_SEQUENCE)
            fz_fail("rr_rig_write: status %d in phase %d (no reading)", st, phase);
        if (phase == 1 && !init_failed && before->status >= 0 && command_invalid(&c)
            && st >= 0)
            fz_fail("rr_rig_write: took an invalid command (status %d)", st);
        if (st < 0)
            fz_same("rr_rig_write", before, rig, sizeof *rig, "the rig (error: nothing changes)");
        else if (c.roller_mode == RR_CMD_TORQUE
                 && rig->Tref_roller != fmin(rig->p->roller_pi.Tmax,
                                             fmax(-rig->p->roller_pi.Tmax, c.roller_ref)))
            fz_fail("rr_rig_write: roller torque %.17g held as %.17g", c.roller_ref,
                    rig->Tref_roller);
        free(before);
        break;
    }
    case 3: {
        const int was_refusing = rig->status < 0;
        st = rr_rig_advance(rig, rec);
        fz_status("rr_rig_advance", st);
        /* known: refusing to go on, it records the status of its record's
         * own evaluation (0), not the one it returns */
        if (!fz_known("advance_refusal", was_refusing))
            check_record("rr_rig_advance", st, rig->creep_control, rec);
        check_wheels("rr_rig_advance", st, rig);
        if (st < 0 && (memcmp(rig->y, y0, sizeof y0) != 0 || memcmp(&rig->t, &t0, sizeof t0)))
            fz_fail("rr_rig_advance: error %d but the state moved", st);
        check_refuses("rr_rig_advance", rig, y0, t0);
        break;
    }
    case 4: {
        double *dydt = fz_alloc(RR_RIG_NSTATE * sizeof *dydt);
        decode_y(in, rig, y);
        st = rr_rig_rhs(rig, rig->t, y, dydt);
        fz_status("rr_rig_rhs", st);
        /* known: only the states the contact uses are checked; a torque,
         * chi or theta_r of inf passes (inf derivatives with status 0) */
        if (fz_known("nonfinite_state", !all_finite(y, RR_RIG_NSTATE))) {
            free(dydt);
            break;
        }
        fz_error("rr_rig_rhs", st, !all_finite(y, RR_RIG_NSTATE), "the state is not finite");
        if (!fz_known("extreme", tainted) && !fz_known("failed_init", init_failed))
            fz_finite_n("rr_rig_rhs", st, "dydt", dydt, RR_RIG_NSTATE);
        check_wheels("rr_rig_rhs", st, rig);
        free(dydt);
        break;
    }
    case 5:
        J = fz_alloc(RR_RIG_NSTATE * RR_RIG_NSTATE * sizeof *J);
        decode_y(in, rig, y);
        st = rr_rig_jac(rig, rig->t, y, J);
        fz_status("rr_rig_jac", st);
        if (!fz_known("nonfinite_state", !all_finite(y, RR_RIG_NSTATE)))
            fz_error("rr_rig_jac", st, !all_finite(y, RR_RIG_NSTATE), "the state is not finite");
        if (!fz_known("extreme", tainted) && !fz_known("failed_init", init_failed))
            fz_finite_n("rr_rig_jac", st, "J", J, RR_RIG_NSTATE * RR_RIG_NSTATE);
        free(J);
        break;
    case 6: {
        const double t = fz_lin(in, 0.0, 10.0);
        taint(t);
        decode_y(in, rig, y);
        st = rr_rig_set_state(rig, t, y);
        fz_status("rr_rig_set_state", st);
        if (init_failed) {
            /* a rig that never started refuses whatever the state */
            if (st >= 0 || memcmp(rig->y, y0, sizeof y0) != 0)
                fz_fail("rr_rig_set_state: status %d on a rig whose init failed", st);
        } else if (!isfinite(t) || !all_finite(y, RR_RIG_NSTATE)) {
            if (st != RR_ERR_NONFINITE)
                fz_fail("rr_rig_set_state: status %d for a non-finite state", st);
            if (memcmp(rig->y, y0, sizeof y0) != 0 || memcmp(&rig->t, &t0, sizeof t0) != 0)
                fz_fail("rr_rig_set_state: refused the state but changed it");
        } else if (st != RR_OK || memcmp(rig->y, y, sizeof y) != 0 || rig->t != t) {
            fz_fail("rr_rig_set_state: status %d, the state not taken", st);
        }
        break;
    }
    case 10:
        full_state_op(in, rig);
        break;
    default:
        st = rr_rig_record(rig, rec);
        fz_status("rr_rig_record", st);
        check_record("rr_rig_record", st, rig->creep_control, rec);
        check_wheels("rr_rig_record", st, rig);
        break;
    }
    free(rec);
}

/* Each entry point on a zeroed rig that rr_rig_init never saw: an error,
 * not a crash (rr_rig_set_state may take the state). */
static void zeroed_rig(fz_in *in)
{
    rr_rig *rig = fz_alloc(sizeof *rig);
    double *rec = fz_alloc(RR_REC_COUNT * sizeof *rec);
    double *out = fz_alloc(RR_RIG_NSTATE * RR_RIG_NSTATE * sizeof *out);
    double y[RR_RIG_NSTATE] = {0.0}, ref = 30.0, xi = 0.01;
    const int op = fz_choice(in, 8);
    const char *name[] = {"rr_rig_step", "rr_rig_run", "rr_rig_sample", "rr_rig_advance",
                          "rr_rig_rhs", "rr_rig_jac", "rr_rig_record", "rr_rig_set_state"};
    int st = RR_ERR_PARAM;

    fz_note("zeroed rig, op %d", op);
    switch (op) {
    case 0: st = rr_rig_step(rig, ref, xi, rec); break;
    case 1: {
        int status = 0;
        if (rr_rig_run(rig, 1, &ref, &xi, rec, &status) != 0)
            fz_fail("rr_rig_run: a never-initialised rig ran");
        st = status;
        break;
    }
    case 2: st = rr_rig_sample(rig, ref, xi); break;
    case 3: st = rr_rig_advance(rig, rec); break;
    case 4: st = rr_rig_rhs(rig, 0.0, y, out); break;
    case 5: st = rr_rig_jac(rig, 0.0, y, out); break;
    case 6: st = rr_rig_record(rig, rec); break;
    default:
        fz_status(name[op], rr_rig_set_state(rig, 0.0, y));   /* may take the state */
        break;
    }
    fz_status(name[op], st);
    if (op != 7 && st >= 0)
        fz_fail("%s: status %d on a never-initialised rig", name[op], st);
    free(rig);
    free(rec);
    free(out);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    rr_rig_params *p;
    rr_rig *rig;
    double roller_speed;
    int st, nops, i, invalid;

    if (fz_choice(&in, 16) == 15) {
        /* known: every entry point but rr_rig_set_state dereferences rig->p */
        if (!fz_known("zeroed_rig", 1))
            zeroed_rig(&in);
        return 0;
    }
    p = fz_alloc(sizeof *p);
    rig = fz_alloc(sizeof *rig);
    tainted = 0;
    decode_params(&in, p);
    roller_speed = fz_near(&in, 31.25, 3.0);
    invalid = params_invalid(p);
    taint(roller_speed);
    fz_note(" roller_speed %.17g;", roller_speed);
    st = rr_rig_check(p);
    fz_status("rr_rig_check", st);
    if ((st < 0) != invalid)
        fz_fail("rr_rig_check: status %d for parameters that are %s", st,
                invalid ? "invalid" : "valid");
    st = rr_rig_init(p, roller_speed, NULL, 0, rig);
    fz_status("rr_rig_init", st);
    fz_error("rr_rig_init", st, invalid || !isfinite(roller_speed), "an argument is invalid");
    if (st != rig->status)
        fz_fail("rr_rig_init: returned %d, rig->status %d", st, rig->status);
    init_failed = st < 0;
    if (st >= 0 && !fz_known("extreme", tainted)) {
        fz_finite_n("rr_rig_init", st, "y", rig->y, RR_RIG_NSTATE);
        check_wheels("rr_rig_init", st, rig);
    }
    nops = fz_range(&in, 0, MAX_OPS);
    for (i = 0; i < nops; i++)
        one_op(&in, rig);
    free(rig);
    free(p);
    return 0;
}
