/*
 * fuzz_rig_contact.c - one contact evaluation of the rig: rr_rig_contact_check,
 * rr_rig_kinematics, rr_rig_contact, rr_rig_contact_loads, on the default
 * rig's contact table (built once per process).
 *
 * Input: the contact model perturbed from the default rig's (R0, E*, G,
 * nu, friction, every creep option, vmin; the table pointer NULL, a table
 * without data, or one whose y0, dy, n are moved within the real rows),
 * the state (x, y within and beyond the table, yaw, the rates, spin and
 * roller speed around free rolling at 0 .. 100 rad/s), the loads.
 *
 * Oracles: documented errors; NaN outputs on error; on success every pose
 * and wheel output finite; rr_rig_kinematics leaves the load fields alone;
 * each wheel with status >= 0 finite, its force within mu0 N for every
 * frictional method, its normal along t1 x t2; rr_rig_contact equal to
 * rr_rig_kinematics followed by rr_rig_contact_loads; rr_rig_contact_bind
 * as rr_rig_contact_check, and the checked evaluations (kinematics, the
 * whole, the loads) exactly the unchecked ones for a bound model,
 * RR_ERR_NULL for a refused one.
 */
#include "fuzz_rig.h"

static void decode_model(fz_in *in, rr_rig_contact_model *m, rr_contact_table *t)
{
    const int perturb = fz_choice(in, 2);
    const int table = fz_choice(in, 16);

    fz_rig_contact_default(m);
    *t = *m->table;
    m->table = t;
    if (table == 0)
        m->table = NULL;
    else if (table == 1)
        t->data = NULL;
    else if (table == 2) {
        /* a sub-table of the real rows, or a struct the caller got wrong */
        const int first = fz_range(in, 0, FZ_RIG_NROWS - 2);
        t->data += (long)first * RR_CONTACT_TABLE_ROW;
        t->y0 += first * t->dy;
        t->n = fz_int(in, 2, FZ_RIG_NROWS - first);
        if (t->n > FZ_RIG_NROWS - first)
            t->n = FZ_RIG_NROWS - first;
    }
    if (!perturb)
        return;
    m->R0 = fz_near(in, m->R0, 2.0);
    m->estar = fz_near(in, m->estar, 100.0);
    m->G = fz_near(in, m->G, 100.0);
    m->nu = fz_lin(in, 0.0, 0.5);
    m->friction.mu0 = fz_lin(in, 0.05, 1.0);
    m->friction.A = fz_lin(in, 0.05, 1.0);
    m->friction.B = fz_lin(in, 0.0, 3.0);
    rr_creep_opts_default(&m->creep, fz_int(in, 0, RR_METHOD_COUNT - 1));
    {
        /* each method's own options: FASTSIM's grid and choices (and modified
         * FASTSIM's k0, alpha_inf, beta), Polach's kA, kS */
        const rr_method_desc *d = rr_method_get(m->creep.method);
        double *v = m->creep.v;
        if (d && d->field) {
            v[RR_FASTSIM_NX] = fz_int(in, 1, 24);
            v[RR_FASTSIM_NY] = fz_int(in, 1, 24);
            v[RR_FASTSIM_BOUND] = fz_int(in, 0, 1);
            v[RR_FASTSIM_GRID] = fz_int(in, 0, 1);
            v[RR_FASTSIM_SLIP_SPEED] = fz_int(in, 0, 1);
            if (m->creep.method == RR_METHOD_MODIFIED_FASTSIM) {
                v[RR_FASTSIM_K0] = fz_near(in, v[RR_FASTSIM_K0], 1.5);
                v[RR_FASTSIM_ALPHA_INF] = fz_near(in, v[RR_FASTSIM_ALPHA_INF], 3.0);
                v[RR_FASTSIM_BETA] = fz_near(in, v[RR_FASTSIM_BETA], 3.0);
            }
        } else if (m->creep.method == RR_METHOD_POLACH) {
            v[RR_POLACH_KA] = fz_lin(in, 0.01, 1.0);
            v[RR_POLACH_KS] = v[RR_POLACH_KA] * fz_lin(in, 0.01, 1.0);
        }
    }
    m->vmin = fz_near(in, m->vmin, 100.0);
}

static void decode_state(fz_in *in, const rr_rig_contact_model *m, rr_rig_state *s)
{
    const double w = fz_lin(in, 0.0, 100.0);
    s->x = fz_slog(in, 1e-9, 0.05);
    s->y = fz_lin(in, -0.0055, 0.0055);
    s->yaw = fz_slog(in, 1e-9, 0.05);
    s->vx = fz_slog(in, 1e-9, 1.0);
    s->vy = fz_slog(in, 1e-9, 1.0);
    s->yaw_rate = fz_slog(in, 1e-9, 1.0);
    s->roller_spin = w;
    /* free rolling, spin r = roller_spin R, then a creepage */
    s->spin = w * (m->R0 / 0.092) * (1.0 + fz_slog(in, 1e-9, 0.5));
}

static int model_invalid(const rr_rig_contact_model *m)
{
    const rr_friction *f = &m->friction;
    const rr_creep_opts *o = &m->creep;
    return !m->table || !m->table->data || !isfinite(m->R0) || !isfinite(m->estar)
        || !isfinite(m->G) || !isfinite(m->nu) || !isfinite(m->vmin) || !(m->R0 > 0.0)
        || !(m->estar > 0.0) || !(m->G > 0.0) || !(m->nu >= 0.0 && m->nu <= 0.5)
        || !(m->vmin > 0.0) || rr_friction_check(f) != RR_OK || rr_creep_opts_check(o) != RR_OK
        || rr_creep_iterative(o);   /* the exact solver: not a time-step method */
}

static int state_nonfinite(const rr_rig_state *s)
{
    return !(isfinite(s->x) && isfinite(s->y) && isfinite(s->yaw) && isfinite(s->vx)
             && isfinite(s->vy) && isfinite(s->yaw_rate) && isfinite(s->spin)
             && isfinite(s->roller_spin));
}

static void check_pose(const char *fn, int st, const rr_rig_pose *p)
{
    fz_finite_n(fn, st, "pose.c", p->c, 3);
    fz_finite_n(fn, st, "pose.v", p->v, 3);
    fz_finite_n(fn, st, "pose.w", p->w, 3);
    FZ_FINITE(fn, st, p->roll);
    FZ_FINITE(fn, st, p->roll_rate);
    FZ_FINITE(fn, st, p->beta);
}

/* The kinematic half of one wheel. */
static void check_wheel_kin(const char *fn, const rr_wheel_contact *w)
{
    const int st = w->status;
    const double *t1 = w->frame.t1, *t2 = w->frame.t2;
    double n[3];
    int j;
    if (st < 0)
        return;
    fz_finite(fn, st, "theta", w->theta);
    fz_finite_n(fn, st, "frame.p", w->frame.p, 3);
    fz_finite_n(fn, st, "frame.t1", t1, 3);
    fz_finite_n(fn, st, "frame.t2", t2, 3);
    fz_finite_n(fn, st, "n", w->n, 3);
    FZ_FINITE(fn, st, w->creep.cx);
    FZ_FINITE(fn, st, w->creep.cy);
    FZ_FINITE(fn, st, w->creep.cphi);
    FZ_FINITE(fn, st, w->creep.V);
    n[0] = t1[1] * t2[2] - t1[2] * t2[1];
    n[1] = t1[2] * t2[0] - t1[0] * t2[2];
    n[2] = t1[0] * t2[1] - t1[1] * t2[0];
    for (j = 0; j < 3; j++)
        if (!(fabs(n[j] - w->n[j]) <= 1e-12))
            fz_fail("%s: n is not t1 x t2 (component %d: %.17g against %.17g)", fn, j, w->n[j],
                    n[j]);
}

static void check_wheel_loads(const char *fn, const rr_rig_contact_model *m,
                              const rr_wheel_contact *w)
{
    const int st = w->status;
    if (st < 0)
        return;
    /* known: Polach's spin force exceeds mu N (fuzz_creep) */
    if (fz_known("polach", m->creep.method == RR_METHOD_POLACH && w->creep.cphi != 0.0))
        return;
    /* known: blended FASTSIM on a creepage below 1e-150 is NaN (fuzz_creep) */
    {
        const double c = fmax(fabs(w->creep.cx), fmax(fabs(w->creep.cy), fabs(w->creep.cphi)));
        if (fz_known("blended", m->creep.method == RR_METHOD_FASTSIM_BLENDED && c > 0.0
                                    && c < 1e-150))
            return;
    }
    FZ_FINITE(fn, st, w->N);
    FZ_FINITE(fn, st, w->hertz.a);
    FZ_FINITE(fn, st, w->hertz.b);
    FZ_FINITE(fn, st, w->hertz.p0);
    FZ_FINITE(fn, st, w->hertz.delta);
    FZ_FINITE(fn, st, w->f.fx);
    FZ_FINITE(fn, st, w->f.fy);
    FZ_FINITE(fn, st, w->f.mz);
    fz_finite_n(fn, st, "force", w->force, 3);
    fz_finite_n(fn, st, "moment", w->moment, 3);
    if (m->creep.method != RR_METHOD_LINEAR)
        fz_bound(fn, st, w->f.fx, w->f.fy, m->friction.mu0, w->N);
}

/* Known: the table struct in the model is trusted as rr_contact_table_lookup
 * trusts it (fuzz_geometry): n < 2 or INT_MIN is not refused. */
static int known_table(const rr_rig_contact_model *m)
{
    return m->table && m->table->data && m->table->n < 2;
}

/* Known: a state, load or model value beyond about 1e+-30 (rates of 1e300,
 * loads of 1e250, mu0 of 1e-300) overflows the creepages or the forces: inf or NaN with
 * status 0. */
static int known_extreme(const rr_rig_contact_model *m, const rr_rig_state *s, const double N[2])
{
    const double v[] = {s->x, s->y, s->yaw, s->vx, s->vy, s->yaw_rate, s->spin, s->roller_spin};
    const double p[] = {m->R0, m->estar, m->G, m->vmin, N[0], N[1], m->friction.mu0};
    int i;
    for (i = 0; i < 8; i++)
        if (fabs(v[i]) > 1e30)
            return 1;
    for (i = 0; i < 7; i++)
        if (!(fabs(p[i]) < 1e30 && fabs(p[i]) > 1e-30))
            return 1;
    return !(m->friction.A > 1e-30) || !(m->friction.B < 1e30);
}

/* The worse of two statuses (errors before warnings), as documented. */
static int worse(int a, int b)
{
    if (a < 0 || b < 0)
        return a < b ? a : b;
    return a > b ? a : b;
}

static void check_worse(const char *fn, int st, const rr_wheel_contact w[2])
{
    if (st != worse(w[0].status, w[1].status))
        fz_fail("%s: status %d, but the wheels' are %d and %d", fn, st, w[0].status,
                w[1].status);
}

/* A checked evaluation (st2, pose2, w2) against the unchecked one (st, pose,
 * w): the same status, pose and wheels' forces for a bound model;
 * RR_ERR_NULL for a refused one. */
static void same_checked(const char *fn, int st, int st2, const rr_rig_pose *pose,
                         const rr_wheel_contact *w, const rr_rig_pose *pose2,
                         const rr_wheel_contact *w2, int refused)
{
    int k;
    fz_status(fn, st2);
    if (refused) {
        if (st2 != RR_ERR_NULL)
            fz_fail("%s: status %d for a refused model", fn, st2);
        return;
    }
    if (st2 != st || memcmp(pose, pose2, sizeof *pose) != 0)
        fz_fail("%s: status %d, the unchecked %d, or the pose differs", fn, st2, st);
    for (k = 0; k < 2; k++)
        if (w[k].status != w2[k].status
            || (w[k].status >= 0 && (memcmp(&w[k].f, &w2[k].f, sizeof w[k].f) != 0
                                     || memcmp(w[k].force, w2[k].force, sizeof w[k].force) != 0
                                     || memcmp(&w[k].creep, &w2[k].creep,
                                               sizeof w[k].creep) != 0)))
            fz_fail("%s: wheel %d differs from the unchecked evaluation", fn, k);
}

/* The fields rr_rig_kinematics must leave alone. */
typedef struct {
    double N;
    rr_hertz_result hertz;
    rr_forces f;
    double force[3], moment[3];
} load_fields;

static void save_loads(const rr_wheel_contact *w, load_fields *l)
{
    memset(l, 0, sizeof *l);
    l->N = w->N;
    l->hertz = w->hertz;
    l->f = w->f;
    memcpy(l->force, w->force, sizeof l->force);
    memcpy(l->moment, w->moment, sizeof l->moment);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_start(data, size);
    const int op = fz_choice(&in, 3);
    rr_rig_contact_model m;
    rr_contact_table t;
    rr_rig_state s;
    rr_rig_pose pose, pose2;
    rr_wheel_contact w[2], w2[2];
    double N[2];
    rr_rig_contact_checked checked;
    int st, st2, k, invalid;

    decode_model(&in, &m, &t);
    decode_state(&in, &m, &s);
    N[0] = fz_log(&in, 10.0, 1e4);
    N[1] = fz_choice(&in, 4) == 0 ? fz_log(&in, 10.0, 1e4) : N[0];
    invalid = model_invalid(&m) || state_nonfinite(&s);
    if (fz_known("table_struct", known_table(&m)) || fz_known("extreme", known_extreme(&m, &s, N)))
        return 0;
    fz_note("op %d; model table %s (y0 %.17g, dy %.17g, n %d, data %s), R0 %.17g, estar %.17g, "
            "G %.17g, nu %.17g, mu0 %.17g, A %.17g, B %.17g, method %d, options %.17g %.17g "
            "%.17g %.17g %.17g %.17g %.17g %.17g, vmin %.17g; state x %.17g, y %.17g, yaw %.17g, vx %.17g, vy %.17g, yaw_rate %.17g, "
            "spin %.17g, roller_spin %.17g; N %.17g, %.17g", op, m.table ? "set" : "NULL", t.y0,
            t.dy, t.n, t.data ? "set" : "NULL", m.R0, m.estar, m.G, m.nu, m.friction.mu0,
            m.friction.A, m.friction.B, m.creep.method, m.creep.v[0], m.creep.v[1], m.creep.v[2], m.creep.v[3],
            m.creep.v[4], m.creep.v[5], m.creep.v[6], m.creep.v[7], m.vmin, s.x, s.y, s.yaw, s.vx, s.vy, s.yaw_rate, s.spin,
            s.roller_spin, N[0], N[1]);

    st = rr_rig_contact_check(&m);
    fz_status("rr_rig_contact_check", st);
    if ((st < 0) != model_invalid(&m))
        fz_fail("rr_rig_contact_check: status %d for a model that is %s", st,
                model_invalid(&m) ? "invalid" : "valid");
    {
        /* the method's workspace, as long as it asks (and none for a
         * method that needs none): bound; a double short: refused */
        static double work[4096];      /* more than any time-loop method asks today */
        const size_t wl = rr_rig_contact_workspace_len(&m);
        if (st < 0 ? wl != 0 : wl != rr_creep_workspace_len(&m.creep, NULL))
            fz_fail("rr_rig_contact_workspace_len: %zu for a model of status %d", wl, st);
        if (wl > RR_COUNTOF(work))
            fz_fail("rr_rig_contact_workspace_len: %zu doubles, more than this target has", wl);
        if (wl > 0 && rr_rig_contact_bind(&checked, &m, work, wl - 1) != RR_ERR_WORKSPACE)
            fz_fail("rr_rig_contact_bind: a workspace one double short not refused");
        st2 = rr_rig_contact_bind(&checked, &m, wl > 0 ? work : NULL, wl);
        fz_status("rr_rig_contact_bind", st2);
        if (st2 != st)
            fz_fail("rr_rig_contact_bind: status %d, rr_rig_contact_check %d", st2, st);
    }

    memset(w, 0x55, sizeof w);
    memset(&pose, 0x55, sizeof pose);
    if (op == 0) {
        load_fields before[2], after[2];
        const char *fn = "rr_rig_kinematics";
        save_loads(&w[0], &before[0]);
        save_loads(&w[1], &before[1]);
        st = rr_rig_kinematics(&m, &s, &pose, w);
        fz_status(fn, st);
        fz_error(fn, st, invalid, "an argument is invalid");
        check_pose(fn, st, &pose);
        check_worse(fn, st, w);
        for (k = 0; k < 2; k++) {
            fz_status(fn, w[k].status);
            check_wheel_kin(fn, &w[k]);
            save_loads(&w[k], &after[k]);
            if (w[k].status >= 0)
                fz_same(fn, &before[k], &after[k], sizeof before[k], "a wheel's load fields");
        }
        memset(w2, 0x55, sizeof w2);       /* the load fields as untouched as w's */
        memset(&pose2, 0x55, sizeof pose2);
        st2 = rr_rig_kinematics_checked(&checked, &s, &pose2, w2);
        same_checked("rr_rig_kinematics_checked", st, st2, &pose, w, &pose2, w2,
                     model_invalid(&m));
        /* the rates at its own y: the same doubles */
        memset(w2, 0x55, sizeof w2);
        memset(&pose2, 0x55, sizeof pose2);
        st2 = rr_rig_kinematics_rates_at(&checked, &s, s.y, &pose2, w2);
        same_checked("rr_rig_kinematics_rates_at", st, st2, &pose, w, &pose2, w2,
                     model_invalid(&m));
        {
            /* at another shift: the pose of its own y, the roll rate of that
             * shift's kinematics (the table's slope there times vy) */
            const char *fr = "rr_rig_kinematics_rates_at";
            const double yr = fz_choice(&in, 8) == 0 ? NAN : s.y + fz_lin(&in, -3e-3, 3e-3);
            rr_rig_state s3 = s;
            rr_rig_pose pose3;
            rr_wheel_contact w3[2];
            fz_note("y_rates %.17g", yr);
            st2 = rr_rig_kinematics_rates_at(&checked, &s, yr, &pose2, w2);
            fz_status(fr, st2);
            check_pose(fr, st2, &pose2);
            if (model_invalid(&m) ? st2 != RR_ERR_NULL
                                  : (state_nonfinite(&s) || !isfinite(yr)) && st2 != RR_ERR_NONFINITE)
                fz_fail("%s: status %d for an invalid model, state or y_rates", fr, st2);
            s3.y = yr;
            if (st2 >= 0 && st >= 0
                && memcmp(pose.c, pose2.c, sizeof pose.c) != 0)
                fz_fail("%s: the centre is not its own y's", fr);
            if (st2 >= 0 && rr_rig_kinematics_checked(&checked, &s3, &pose3, w3) >= 0
                && !(pose2.roll_rate == pose3.roll_rate))
                fz_fail("%s: roll rate %.17g, that shift's %.17g", fr, pose2.roll_rate,
                        pose3.roll_rate);
        }
        return 0;
    }
    st = rr_rig_contact(&m, &s, N, &pose, w);
    fz_status("rr_rig_contact", st);
    fz_error("rr_rig_contact", st, invalid || !(N[0] > 0.0) || !(N[1] > 0.0) || !isfinite(N[0])
                                       || !isfinite(N[1]), "an argument is invalid");
    check_pose("rr_rig_contact", st, &pose);
    check_worse("rr_rig_contact", st, w);
    for (k = 0; k < 2; k++) {
        fz_status("rr_rig_contact (wheel)", w[k].status);
        check_wheel_kin("rr_rig_contact", &w[k]);
        check_wheel_loads("rr_rig_contact", &m, &w[k]);
    }
    memset(w2, 0x55, sizeof w2);
    memset(&pose2, 0x55, sizeof pose2);
    st2 = rr_rig_contact_eval_checked(&checked, &s, N, &pose2, w2);
    same_checked("rr_rig_contact_eval_checked", st, st2, &pose, w, &pose2, w2,
                 model_invalid(&m));
    if (op == 2 && !model_invalid(&m)) {
        /* the checked loads on the checked kinematics */
        memset(w2, 0x55, sizeof w2);
        memset(&pose2, 0x55, sizeof pose2);
        st2 = rr_rig_kinematics_checked(&checked, &s, &pose2, w2);
        if (!(st2 < 0 && !isfinite(pose2.c[0])))
            st2 = rr_rig_contact_loads_checked(&checked, N, &pose2, w2);
        same_checked("rr_rig_contact_loads_checked", st, st2, &pose, w, &pose2, w2, 0);
    }
    if (op == 2) {
        /* the same in two halves */
        memset(w2, 0x55, sizeof w2);
        memset(&pose2, 0x55, sizeof pose2);
        st2 = rr_rig_kinematics(&m, &s, &pose2, w2);
        if (!(st2 < 0 && !isfinite(pose2.c[0])))
            st2 = rr_rig_contact_loads(&m, N, &pose2, w2);
        if (st2 != st)
            fz_fail("rr_rig_contact: status %d, kinematics + loads %d", st, st2);
        for (k = 0; k < 2; k++)
            if (w[k].status >= 0
                && (memcmp(&w[k].f, &w2[k].f, sizeof w[k].f) != 0
                    || memcmp(w[k].force, w2[k].force, sizeof w[k].force) != 0))
                fz_fail("rr_rig_contact: wheel %d differs from kinematics + loads", k);
    }
    return 0;
}
