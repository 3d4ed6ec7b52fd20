/*
 * rr_fmu_unit.c - the roller rig as a co-simulation unit (rr_fmu.h), its
 * second half: the unit's life (instantiated, initialisation, stepping,
 * terminated, failed), the rig built from its parameters, a step over whole
 * control samples, get and set with range checks and messages, reset and
 * FMU states.  Its variables and configuration are rr_fmu.c's.
 */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "util/rr_common.h"
#include "contact/rr_creep.h"
#include "rig/rr_rig_params.h"
#include "fmu/rr_fmu.h"

/* ------------------------------------------------------------------ tables */

static const char *const default_type_names[] = {
    [RR_FMU_REAL] = "Real", [RR_FMU_INTEGER] = "Integer", [RR_FMU_BOOLEAN] = "Boolean",
    [RR_FMU_ENUMERATION] = "Enumeration"};
static const char *const causality_names[] = {
    [RR_FMU_INDEPENDENT] = "independent", [RR_FMU_PARAMETER] = "parameter",
    [RR_FMU_INPUT] = "input", [RR_FMU_OUTPUT] = "output"};
static const char *const mode_names[] = {
    [RR_FMU_INSTANTIATED] = "instantiated", [RR_FMU_INITIALIZATION] = "initialization mode",
    [RR_FMU_STEPPING] = "stepping", [RR_FMU_TERMINATED] = "terminated",
    [RR_FMU_FAILED] = "failed"};

RR_STATIC_ASSERT(RR_COUNTOF(default_type_names) == RR_FMU_ENUMERATION + 1, one_type_name_each);
RR_STATIC_ASSERT(RR_COUNTOF(causality_names) == RR_FMU_OUTPUT + 1, one_causality_name_each);
RR_STATIC_ASSERT(RR_COUNTOF(mode_names) == RR_FMU_FAILED + 1, one_mode_name_each);

static int fail(rr_fmu *m, int st, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(m->msg, sizeof m->msg, fmt, ap);
    va_end(ap);
    return st;
}

/* ------------------------------------------------------------------ checks with messages */

static void range_text(const rr_fmu_var *v, char *buf, size_t len)
{
    char lo[32], hi[32];
    rr_fmu_format_number(v->lo, lo, sizeof lo);
    rr_fmu_format_number(v->hi, hi, sizeof hi);
    snprintf(buf, len, "%s%s, %s%s", v->lo_open || isinf(v->lo) ? "(" : "[", lo, hi,
             v->hi_open || isinf(v->hi) ? ")" : "]");
}

/* 0 if x is a value of v, else the status with the message. */
static int check_value(rr_fmu *m, const rr_fmu_var *v, double x)
{
    char name[RR_FMU_NAME_LEN], num[32], range[80];
    const char *item;
    int i, value, in_range;
    rr_fmu_var_name(v, name, sizeof name);
    rr_fmu_format_number(x, num, sizeof num);
    switch (v->type) {
    case RR_FMU_BOOLEAN:
        return RR_OK;
    case RR_FMU_ENUMERATION:
        for (i = 0; rr_fmu_var_item(v, i, &item, &value); i++)
            if (x == value)
                return RR_OK;
        {
            char items[256];
            size_t n = 0;
            items[0] = '\0';
            for (i = 0; rr_fmu_var_item(v, i, &item, &value) && n < sizeof items; i++)
                n += (size_t)snprintf(items + n, sizeof items - n, "%s%d (%s)", i ? ", " : "",
                                      value, item);
            return fail(m, RR_ERR_PARAM, "%s = %s is not one of its values: %s", name, num,
                        items);
        }
    default:
        break;
    }
    if (!isfinite(x))
        return fail(m, RR_ERR_NONFINITE, "%s = %s: the value must be a finite number", name,
                    num);
    in_range = (v->lo_open ? x > v->lo : x >= v->lo) && (v->hi_open ? x < v->hi : x <= v->hi);
    if (v->type == RR_FMU_INTEGER && x != floor(x))
        in_range = 0;
    if (!in_range) {
        range_text(v, range, sizeof range);
        return fail(m, RR_ERR_PARAM, "%s = %s is out of range: it must be %s in %s%s%s", name,
                    num, v->type == RR_FMU_INTEGER ? "an integer" : "a number", range,
                    v->unit[0] && strcmp(v->unit, "-") != 0 ? " " : "",
                    strcmp(v->unit, "-") != 0 ? v->unit : "");
    }
    return RR_OK;
}

/* ------------------------------------------------------------------ the unit */

int rr_fmu_init(rr_fmu *m, const rr_fmu_config *start, rr_fmu_alloc alloc, rr_fmu_free release,
                void *ctx, const char *const *type_names)
{
    if (!m || !start || !alloc || !release)
        return RR_ERR_NULL;
    memset(m, 0, sizeof *m);
    m->start = *start;
    m->alloc = alloc;
    m->release = release;
    m->mem_ctx = ctx;
    m->type_names = type_names ? type_names : default_type_names;
    return rr_fmu_reset(m);
}

void rr_fmu_release(rr_fmu *m)
{
    if (!m)
        return;
    if (m->table_data)
        m->release(m->mem_ctx, m->table_data);
    m->table_data = NULL;
    m->table_cap = 0;
    if (m->profile_work)
        m->release(m->mem_ctx, m->profile_work);
    m->profile_work = NULL;
    m->profile_work_cap = 0;
    if (m->rig_work)
        m->release(m->mem_ctx, m->rig_work);
    m->rig_work = NULL;
    m->rig_work_cap = 0;
    m->table_ok = 0;
    m->s.ready = 0;
}

const char *rr_fmu_message(const rr_fmu *m)
{
    return m ? m->msg : "";
}

int rr_fmu_reset(rr_fmu *m)
{
    rr_fmu_state *s;
    if (!m)
        return RR_ERR_NULL;
    s = &m->s;
    memset(s, 0, sizeof *s);
    s->cfg = m->start;
    rr_fmu_input_starts(&m->start, s->in);
    s->mode = RR_FMU_INSTANTIATED;
    m->msg[0] = '\0';
    return RR_OK;
}

static const char *mode_name(int mode)
{
    return mode >= 0 && mode <= RR_FMU_FAILED ? mode_names[mode] : "unknown";
}

static int wrong_mode(rr_fmu *m, const char *what, const char *need)
{
    if (m->s.mode == RR_FMU_FAILED)
        return fail(m, RR_ERR_SEQUENCE, "%s: the unit failed (%s) and cannot go on: reset "
                    "it, or set an FMU state saved before", what,
                    rr_status_message(m->s.failed_status));
    return fail(m, RR_ERR_SEQUENCE, "%s: not allowed when the unit is %s (it must be %s)", what,
                mode_name(m->s.mode), need);
}

int rr_fmu_set_profiles(rr_fmu *m, const rr_rig_profiles *pr)
{
    rr_rig_profiles keep;
    int st;
    if (!m || !pr)
        return RR_ERR_NULL;
    if (m->s.mode != RR_FMU_INSTANTIATED)
        return wrong_mode(m, "rr_fmu_set_profiles", "instantiated");
    memset(&keep, 0, sizeof keep);
    keep.wheel_scale = keep.roller_scale = keep.gauge = 1.0;   /* the points alone checked */
    if (pr->wheel.n > 0)
        keep.wheel = pr->wheel;
    if (pr->roller.n > 0)
        keep.roller = pr->roller;
    if (pr->wheel_right.n > 0)
        keep.wheel_right = pr->wheel_right;
    if (pr->roller_right.n > 0)
        keep.roller_right = pr->roller_right;
    memset(&m->points, 0, sizeof m->points);
    if ((st = rr_rig_profiles_check(&keep, NULL, NULL)) != RR_OK)
        return fail(m, st, "rr_fmu_set_profiles: the points: %s", rr_status_message(st));
    m->points = keep;
    m->table_ok = 0;
    return RR_OK;
}

int rr_fmu_set_nonhertz(rr_fmu *m, const rr_nh_table *left, const rr_nh_table *right)
{
    int k, st, bad;
    if (!m)
        return RR_ERR_NULL;
    if (m->s.mode != RR_FMU_INSTANTIATED)
        return wrong_mode(m, "rr_fmu_set_nonhertz", "instantiated");
    m->nonhertz_ok = 0;
    if (!left && !right)
        return RR_OK;
    if (!left || !right)
        return fail(m, RR_ERR_NULL, "rr_fmu_set_nonhertz: give both sides' tables");
    for (k = 0; k < 2; k++) {
        const rr_nh_table *t = k == 0 ? left : right;
        if ((st = rr_nonhertz_table_check(t, &bad)) != RR_OK)
            return fail(m, st, "rr_fmu_set_nonhertz: the %s table, row %d: %s",
                        k == 0 ? "left" : "right", bad, rr_status_message(st));
        m->nonhertz[k] = *t;
    }
    m->nonhertz_ok = 1;
    return RR_OK;
}

/* The profiles of configuration c: its scales and gauge, and for each row
 * that says "points" the unit's points (n = -1 where it holds none). */
static void profiles_for(const rr_fmu *m, const rr_rig_config *c, rr_rig_profiles *pr)
{
    rr_rig_profiles_from(c, pr);
    if (pr->wheel.n < 0 && m->points.wheel.n > 0)
        pr->wheel = m->points.wheel;
    if (pr->roller.n < 0 && m->points.roller.n > 0)
        pr->roller = m->points.roller;
    if (pr->wheel_right.n < 0 && m->points.wheel_right.n > 0)
        pr->wheel_right = m->points.wheel_right;
    if (pr->roller_right.n < 0 && m->points.roller_right.n > 0)
        pr->roller_right = m->points.roller_right;
}

static int same_points(const rr_profile_points *a, const rr_profile_points *b)
{
    return a->n == b->n && a->y == b->y && a->z == b->z && a->end == b->end;
}

static int same_profiles(const rr_rig_profiles *a, const rr_rig_profiles *b)
{
    return same_points(&a->wheel, &b->wheel) && same_points(&a->roller, &b->roller)
        && same_points(&a->wheel_right, &b->wheel_right)
        && same_points(&a->roller_right, &b->roller_right) && a->wheel_scale == b->wheel_scale
        && a->roller_scale == b->roller_scale && a->gauge == b->gauge;
}

static const char *const slot_rows[] = {"wheelset.profile", "roller.profile",
                                        "wheelset.profile_right", "roller.profile_right"};

/* *buf holding at least need doubles (its *cap), the old one released
 * once the new one is had: RR_OK, or RR_ERR_WORKSPACE said. */
static int grow(rr_fmu *m, double **buf, long *cap, long need)
{
    double *data;
    if (need <= *cap)
        return RR_OK;
    data = m->alloc(m->mem_ctx, (size_t)need * sizeof *data);
    if (!data)
        return fail(m, RR_ERR_WORKSPACE, "the contact table: out of memory (%ld doubles)",
                    need);
    if (*buf)
        m->release(m->mem_ctx, *buf);
    *buf = data;
    *cap = need;
    return RR_OK;
}

/* The table on real profiles into m->table (workspace allocated as needed). */
static int profile_table(rr_fmu *m, const rr_rig_geometry *g, const rr_rig_profiles *pr,
                         double *bad_y)
{
    int which = -1, point = -1, st;
    long need;
    if ((st = rr_rig_profiles_check(pr, &which, &point)) != RR_OK) {
        if (which < 0)
            return fail(m, st, "the real profiles' scales (wheelset.profile_scale, "
                        "roller.profile_scale) or roller.gauge_m: %s", rr_status_message(st));
        return fail(m, st, "%s = \"points\": %s%s", slot_rows[which],
                    st == RR_ERR_NULL ? "this FMU carries no points for it (build it from a "
                                        "scenario that names the profile)"
                                      : "its points: ", st == RR_ERR_NULL ? ""
                                      : rr_status_message(st));
    }
    need = rr_rig_profiles_work_len(pr);
    if ((st = grow(m, &m->profile_work, &m->profile_work_cap, need)) != RR_OK)
        return st;
    return rr_rig_table_build_profiles(g, pr, m->table_data, m->table_cap, m->profile_work,
                                       m->profile_work_cap, &m->table, bad_y);
}

/* The contact table of the configuration's geometry, built if it is not
 * the one held (allocating its rows). */
static int table_for(rr_fmu *m, const rr_rig_config *c)
{
    rr_rig_geometry g;
    rr_rig_profiles pr;
    long len;
    double bad_y = NAN;
    int st, real;
    rr_rig_geometry_from(c, &g);
    profiles_for(m, c, &pr);
    real = pr.wheel.n != 0 || pr.roller.n != 0 || pr.wheel_right.n != 0
        || pr.roller_right.n != 0;
    if (m->table_ok && memcmp(&g, &m->g, sizeof g) == 0 && same_profiles(&pr, &m->table_pr))
        return RR_OK;
    m->table_ok = 0;
    len = rr_rig_table_data_len(&g);
    if (len <= 0)
        return fail(m, RR_ERR_PARAM, "the contact table: integration.table_rows = %d is out "
                    "of range", g.table_rows);
    if ((st = grow(m, &m->table_data, &m->table_cap, len)) != RR_OK)
        return st;
    if (real && (st = profile_table(m, &g, &pr, &bad_y)) < 0 && isnan(bad_y))
        return st;                                     /* the profiles' own fault: said */
    if (!real)
        st = rr_rig_table_build(&g, m->table_data, m->table_cap, m->table_work,
                                RR_RIG_TABLE_WORK_LEN, &m->table, &bad_y);
    if (st < 0) {
        char y[32];
        rr_fmu_format_number(bad_y, y, sizeof y);
        return fail(m, st, "the rig's geometry (wheelset.wheel_radius_m, roller.radius_m, "
                    "wheelset.profile_half_width_m, wheelset.conicity, roller.crown_radius_m, "
                    "wheelset.contact_half_spacing_m, integration.table_half_range_m, "
                    "integration.table_rows) gives no contact table%s%s: %s",
                    isnan(bad_y) ? "" : " at y_ws = ", isnan(bad_y) ? "" : y,
                    rr_status_message(st));
    }
    m->g = g;
    m->table_pr = pr;
    m->table_ok = 1;
    return RR_OK;
}

/* The rig's workspace of at least need doubles (allocating it, zeroed, if
 * the one held is shorter): its creep method's, the unit's to own. */
static int rig_work_for(rr_fmu *m, size_t need)
{
    double *work;
    size_t i;
    if (need <= m->rig_work_cap)
        return RR_OK;
    if (need > (size_t)-1 / sizeof *work
        || !(work = m->alloc(m->mem_ctx, need * sizeof *work)))
        return fail(m, RR_ERR_WORKSPACE, "the rig's workspace: out of memory (%lu doubles)",
                    (unsigned long)need);
    for (i = 0; i < need; i++)
        work[i] = 0.0;
    if (m->profile_work)
        m->release(m->mem_ctx, m->profile_work);
    m->profile_work = NULL;
    m->profile_work_cap = 0;
    if (m->rig_work)
        m->release(m->mem_ctx, m->rig_work);
    m->rig_work = work;
    m->rig_work_cap = need;
    return RR_OK;
}

/* The refusal of a sample time at which a drive's speed loop is unstable:
 * which drive, and the sample times at which it is stable. */
static int loop_fail(rr_fmu *m, const rr_rig_config *c, int st)
{
    static const char *const drive[2] = {"roller", "wheelset"};
    rr_speed_loop loops[2];
    double lo, hi;
    char T[32];
    int k = 0;
    rr_rig_config_speed_loops(c, loops);
    while (k < 1 && rr_speed_loop_check(&loops[k]) != RR_ERR_PARAM)
        k++;
    rr_fmu_format_number(c->T, T, sizeof T);
    if (rr_speed_loop_range(&loops[k], RR_RIG_MIN_T, RR_RIG_MAX_T, &lo, &hi) != RR_OK)
        return fail(m, st, "scenario.control_sample_time_s = %s s: the %s drive's sampled speed "
                    "loop (its PI gains on its inertia through its lag) is stable at no sample "
                    "time from %g to %g s", T, drive[k], RR_RIG_MIN_T, RR_RIG_MAX_T);
    return fail(m, st, "scenario.control_sample_time_s = %s s: the %s drive's sampled speed "
                "loop (its PI gains on its inertia through its lag) is unstable at this "
                "sample time; it is stable from %.3g to %.3g s", T, drive[k], lo, hi);
}

/* The rig's parameters of the configuration, into *p (its table m's). */
static int derive(rr_fmu *m, const rr_fmu_config *f, rr_rig_params *p)
{
    const char *bad = NULL;
    rr_creep_opts o;
    int st;
    if ((st = rr_rig_config_check(&f->c, &bad)) < 0) {
        if (st == RR_ERR_PARAM && bad && strcmp(bad, "scenario.control_sample_time_s") == 0)
            return loop_fail(m, &f->c, st);
        return fail(m, st, "the parameters do not hold together: %s: %s", bad ? bad : "?",
                    rr_status_message(st));
    }
    if ((st = rr_fmu_creep_opts(f, &o, &bad)) < 0)
        return fail(m, st, "the creep-force method: %s: %s", bad ? bad : "?",
                    rr_status_message(st));
    if (rr_method_get(o.method)->coulomb_only
        && strcmp(rr_rig_param_find("contact.friction_law")->choices[f->c.friction_law],
                  "coulomb") != 0)
        return fail(m, RR_ERR_FRICTION, "contact.creep_method = %s is built for Coulomb "
                    "friction; the parameters' contact.friction_law is %s (set it to "
                    "coulomb)", rr_method_get(o.method)->name,
                    rr_rig_param_find("contact.friction_law")->choices[f->c.friction_law]);
    if ((st = table_for(m, &f->c)) < 0)
        return st;
    if ((st = rr_rig_params_from(&f->c, &m->table, p)) < 0)
        return fail(m, st, "the rig's parameters: %s", rr_status_message(st));
    p->contact.creep = o;
    if (p->contact.patch == RR_RIG_PATCH_NONHERTZ) {
        if (!m->nonhertz_ok)
            return fail(m, RR_ERR_NULL, "contact.patch = \"nonhertz\": this FMU carries no "
                        "non-Hertzian table (build it from a scenario with contact.patch = "
                        "\"nonhertz\")");
        rr_rig_params_set_nonhertz(p, &m->nonhertz[0], &m->nonhertz[1]);
    }
    if ((st = rr_rig_check(p)) < 0)
        return fail(m, st, "the rig's parameters: %s", rr_status_message(st));
    return RR_OK;
}

/* The rig built from the parameters, at the start: its record and the
 * encoders' first reading. */
static int build(rr_fmu *m)
{
    rr_fmu_state *s = &m->s;
    const rr_rig_config *c = &s->cfg.c;
    int st;
    if (s->ready)
        return RR_OK;
    if ((st = derive(m, &s->cfg, &s->p)) < 0
        || (st = rig_work_for(m, rr_rig_workspace_len(&s->p))) < 0)
        return st;
    st = rr_rig_init(&s->p, s->cfg.control[RR_FMU_START] == RR_FMU_START_REST
                                ? 0.0 : c->roller_speed / c->roller_radius,
                     m->rig_work, m->rig_work_cap, &s->rig);
    if (st < 0)
        return fail(m, st, "the rig cannot start: %s", rr_status_message(st));
    s->k = 0;
    s->retune = 0;
    st = rr_rig_record(&s->rig, s->rec);
    if (st >= 0)
        st = rr_rig_read(&s->rig, &s->sig);
    if (st < 0)
        return fail(m, st, "the rig cannot start: %s", rr_status_message(st));
    s->ready = 1;
    return RR_OK;
}

int rr_fmu_enter_init(rr_fmu *m, double t0)
{
    char num[32];
    if (!m)
        return RR_ERR_NULL;
    m->msg[0] = '\0';
    if (m->s.mode != RR_FMU_INSTANTIATED)
        return wrong_mode(m, "entering initialization mode", "instantiated");
    if (!isfinite(t0)) {
        rr_fmu_format_number(t0, num, sizeof num);
        return fail(m, RR_ERR_NONFINITE, "the start time must be finite, got %s", num);
    }
    m->s.t0 = t0;
    m->s.mode = RR_FMU_INITIALIZATION;
    return RR_OK;
}

int rr_fmu_exit_init(rr_fmu *m)
{
    int st;
    if (!m)
        return RR_ERR_NULL;
    m->msg[0] = '\0';
    if (m->s.mode != RR_FMU_INITIALIZATION)
        return wrong_mode(m, "exiting initialization mode", "in initialization mode");
    if ((st = build(m)) < 0)
        return st;
    m->s.mode = RR_FMU_STEPPING;
    return RR_OK;
}

int rr_fmu_terminate(rr_fmu *m)
{
    if (!m)
        return RR_ERR_NULL;
    m->msg[0] = '\0';
    if (m->s.mode != RR_FMU_STEPPING && m->s.mode != RR_FMU_INITIALIZATION
        && m->s.mode != RR_FMU_FAILED)
        return wrong_mode(m, "terminating", "initialised");
    m->s.mode = RR_FMU_TERMINATED;
    return RR_OK;
}

double rr_fmu_time(const rr_fmu *m)
{
    if (!m)
        return NAN;
    return m->s.t0 + (m->s.ready ? m->s.rig.t : 0.0);
}

/* The tunable parameters changed: the rig's parameters derived again. */
static int retune(rr_fmu *m)
{
    rr_rig_params p;
    int st;
    if ((st = derive(m, &m->s.cfg, &p)) < 0)
        return st;
    /* tried on the copy first: on error the unit keeps its parameters */
    if ((st = rr_rig_rebind(&m->s.rig, &p)) < 0)
        return st;
    m->s.p = p;
    st = rr_rig_rebind(&m->s.rig, &m->s.p);
    m->s.retune = 0;
    return st;
}

/* The command of sample k from the control modes and the inputs; *which
 * names the input a refused command came from. */
static void command(const rr_fmu_state *s, rr_rig_command *cmd, const char **which)
{
    double roller_ref = NAN, xi_ref = NAN;
    if (s->cfg.control[RR_FMU_ROLLER_MODE] == RR_FMU_ROLLER_SCENARIO
        || s->cfg.control[RR_FMU_WHEELSET_MODE] == RR_FMU_WHEELSET_SCENARIO)
        rr_rig_schedule(&s->cfg.c, s->k, &roller_ref, &xi_ref);
    switch (s->cfg.control[RR_FMU_ROLLER_MODE]) {
    case RR_FMU_ROLLER_SPEED:
        cmd->roller_mode = RR_CMD_SPEED;
        cmd->roller_ref = s->in[RR_FMU_IN_ROLLER_SPEED];
        which[0] = rr_fmu_input_name(RR_FMU_IN_ROLLER_SPEED);
        break;
    case RR_FMU_ROLLER_TORQUE:
        cmd->roller_mode = RR_CMD_TORQUE;
        cmd->roller_ref = s->in[RR_FMU_IN_ROLLER_TORQUE];
        which[0] = rr_fmu_input_name(RR_FMU_IN_ROLLER_TORQUE);
        break;
    default:
        cmd->roller_mode = RR_CMD_BUILTIN;
        cmd->roller_ref = roller_ref;
        which[0] = "the scenario's roller speed";
    }
    switch (s->cfg.control[RR_FMU_WHEELSET_MODE]) {
    case RR_FMU_WHEELSET_CREEPAGE:
        cmd->wheelset_mode = RR_CMD_BUILTIN;
        cmd->wheelset_ref = s->in[RR_FMU_IN_CREEPAGE];
        which[1] = rr_fmu_input_name(RR_FMU_IN_CREEPAGE);
        break;
    case RR_FMU_WHEELSET_SPEED:
        cmd->wheelset_mode = RR_CMD_SPEED;
        cmd->wheelset_ref = s->in[RR_FMU_IN_WHEELSET_SPEED];
        which[1] = rr_fmu_input_name(RR_FMU_IN_WHEELSET_SPEED);
        break;
    case RR_FMU_WHEELSET_TORQUE:
        cmd->wheelset_mode = RR_CMD_TORQUE;
        cmd->wheelset_ref = s->in[RR_FMU_IN_WHEELSET_TORQUE];
        which[1] = rr_fmu_input_name(RR_FMU_IN_WHEELSET_TORQUE);
        break;
    case RR_FMU_WHEELSET_FREE:
        cmd->wheelset_mode = RR_CMD_BUILTIN;
        cmd->wheelset_ref = NAN;            /* rr_rig_write's "no target" */
        which[1] = "free rolling";
        break;
    default:
        cmd->wheelset_mode = RR_CMD_BUILTIN;
        cmd->wheelset_ref = xi_ref;
        which[1] = "the scenario's creepage target";
    }
    if (s->cfg.control[RR_FMU_MU_SOURCE] == RR_FMU_MU_INPUT) {
        cmd->mu0 = s->in[RR_FMU_IN_MU];
        which[2] = rr_fmu_input_name(RR_FMU_IN_MU);
    } else {
        cmd->mu0 = NAN;
        which[2] = "the adhesion";
    }
}

int rr_fmu_do_step(rr_fmu *m, double t, double h)
{
    rr_fmu_state *s;
    double T, n_real, now;
    long n, i;
    int st, worst = RR_OK, warned = 0;
    char a[32], b[32];

    if (!m)
        return RR_ERR_NULL;
    s = &m->s;
    m->msg[0] = '\0';
    if (s->mode != RR_FMU_STEPPING)
        return wrong_mode(m, "doStep", "stepping (after the initialization)");
    T = s->p.T;
    n_real = floor(h / T + 0.5);
    now = s->t0 + (double)s->k * T;
    /* the step: a whole number of samples, but for the rounding of a
     * master's difference of two times */
    if (!(h > 0.0) || !isfinite(h) || n_real < 1.0 || n_real > 1e15
        || fabs(h - n_real * T) > 1e-6 * T + 4.0 * DBL_EPSILON * (fabs(now) + h)) {
        rr_fmu_format_number(h, a, sizeof a);
        rr_fmu_format_number(T, b, sizeof b);
        return fail(m, RR_ERR_PARAM, "the communication step %s s is not a whole "
                    "multiple of the control sample time %s s "
                    "(scenario.control_sample_time_s): the rig steps by whole samples", a, b);
    }
    /* the time: the unit's, within a thousandth of a sample (a master that
     * adds up its steps drifts from k T by rounding; a skipped or repeated
     * step is a whole sample off) */
    if (!(fabs(t - now) <= 1e-3 * T)) {
        rr_fmu_format_number(t, a, sizeof a);
        rr_fmu_format_number(now, b, sizeof b);
        return fail(m, RR_ERR_PARAM, "currentCommunicationPoint %s s is not the "
                    "unit's time %s s (the start time plus %ld samples)", a, b, s->k);
    }
    if (s->retune && (st = retune(m)) < 0)
        return st;
    n = (long)n_real;
    for (i = 0; i < n; i++) {
        rr_rig_command cmd;
        const char *which[3];
        command(s, &cmd, which);
        if ((st = rr_rig_write(&s->rig, &cmd)) < 0) {
            char r0[32], r1[32], mu[32];
            rr_fmu_format_number(cmd.roller_ref, r0, sizeof r0);
            rr_fmu_format_number(cmd.wheelset_ref, r1, sizeof r1);
            rr_fmu_format_number(cmd.mu0, mu, sizeof mu);
            rr_fmu_format_number(s->rig.t + s->t0, a, sizeof a);
            fail(m, st, "sample %ld (t = %s s): the rig refused the command (roller: "
                 "%s = %s; wheelset: %s = %s; mu0: %s = %s): %s", s->k, a, which[0], r0,
                 which[1], r1, which[2], mu, rr_status_message(st));
            if (i > 0) {
                s->mode = RR_FMU_FAILED;
                s->failed_status = st;
            }
            return st;
        }
        st = rr_rig_advance(&s->rig, s->rec);
        if (st >= 0) {
            s->k++;
            if (st > 0) {
                warned++;
                if (st > worst)
                    worst = st;
            }
            st = rr_rig_read(&s->rig, &s->sig);
        }
        if (st < 0) {
            rr_fmu_format_number(s->rig.t + s->t0, a, sizeof a);
            s->mode = RR_FMU_FAILED;
            s->failed_status = st;
            return fail(m, st, "sample %ld (t = %s s) failed: %s; the unit stops "
                        "there (its outputs are that sample's start)", s->k, a,
                        rr_status_message(st));
        }
    }
    if (worst > 0)
        return fail(m, worst, "%d of %ld samples warned: %s", warned, n,
                    rr_status_message(worst));
    return RR_OK;
}

/* ------------------------------------------------------------------ get and set */

static int lookup(rr_fmu *m, int type, unsigned vr, rr_fmu_var *v)
{
    char name[RR_FMU_NAME_LEN];
    if (rr_fmu_var_find(&m->start, vr, v) != RR_OK)
        return fail(m, RR_ERR_PARAM, "unknown value reference %u (no variable has it)", vr);
    if (v->type != type) {
        rr_fmu_var_name(v, name, sizeof name);
        return fail(m, RR_ERR_PARAM, "%s (value reference %u) is of type %s, not %s: use "
                    "the %s functions", name, vr, m->type_names[v->type],
                    m->type_names[type < 0 || type > 3 ? 0 : type], m->type_names[v->type]);
    }
    return RR_OK;
}

int rr_fmu_get(rr_fmu *m, int type, unsigned vr, double *x)
{
    rr_fmu_state *s;
    rr_fmu_var v;
    int st;
    if (!m || !x)
        return RR_ERR_NULL;
    s = &m->s;
    /* the record's real outputs, read at every step by a master: straight */
    if (type == RR_FMU_REAL && vr > RR_FMU_VR_RECORD && vr < RR_FMU_VR_RECORD + RR_REC_STATUS
        && s->ready && s->mode != RR_FMU_INSTANTIATED) {
        *x = s->rec[vr - RR_FMU_VR_RECORD];
        return RR_OK;
    }
    *x = NAN;
    if ((st = lookup(m, type, vr, &v)) < 0)
        return st;
    if (v.causality == RR_FMU_PARAMETER || v.causality == RR_FMU_INPUT) {
        *x = rr_fmu_value(&s->cfg, s->in, &v);
        return RR_OK;
    }
    if (s->mode == RR_FMU_INSTANTIATED) {
        char name[RR_FMU_NAME_LEN];
        rr_fmu_var_name(&v, name, sizeof name);
        return fail(m, RR_ERR_SEQUENCE, "%s: the %s is known from the initialization mode on",
                    name, v.causality == RR_FMU_OUTPUT ? "output" : "time");
    }
    if (!s->ready && (st = build(m)) < 0)
        return st;
    *x = rr_fmu_output(s, &v);
    return RR_OK;
}

int rr_fmu_set(rr_fmu *m, int type, unsigned vr, double x)
{
    rr_fmu_state *s;
    rr_fmu_var v;
    char name[RR_FMU_NAME_LEN];
    int st;
    if (!m)
        return RR_ERR_NULL;
    s = &m->s;
    if ((st = lookup(m, type, vr, &v)) < 0)
        return st;
    rr_fmu_var_name(&v, name, sizeof name);
    if (v.causality != RR_FMU_PARAMETER && v.causality != RR_FMU_INPUT)
        return fail(m, RR_ERR_PARAM, "%s (value reference %u) is an %s: it cannot be set",
                    name, vr, causality_names[v.causality]);
    if (s->mode == RR_FMU_TERMINATED || s->mode == RR_FMU_FAILED)
        return wrong_mode(m, name, "instantiated, initialised or stepping");
    if (s->mode == RR_FMU_STEPPING && v.causality == RR_FMU_PARAMETER
        && v.variability == RR_FMU_FIXED)
        return fail(m, RR_ERR_SEQUENCE, "%s is a fixed parameter: set it before the "
                    "initialization ends (or after a reset)", name);
    if ((st = check_value(m, &v, x)) < 0)
        return st;
    st = rr_fmu_store(&s->cfg, s->in, &v, x);
    if (v.kind == RR_FMU_K_INPUT)
        return RR_OK;
    if (st < 0) {
        char num[32];
        rr_fmu_format_number(x, num, sizeof num);
        return fail(m, st, "%s = %s: %s", name, num, rr_status_message(st));
    }
    if (v.kind == RR_FMU_K_CONTROL && v.index != RR_FMU_START)
        return RR_OK;               /* read at each sample */
    if (s->mode == RR_FMU_STEPPING)
        s->retune = 1;
    else
        s->ready = 0;
    return RR_OK;
}

/* ------------------------------------------------------------------ FMU states */

int rr_fmu_save(const rr_fmu *m, rr_fmu_state *st)
{
    if (!m || !st)
        return RR_ERR_NULL;
    *st = m->s;
    return RR_OK;
}

int rr_fmu_restore(rr_fmu *m, const rr_fmu_state *st)
{
    int status;
    if (!m || !st)
        return RR_ERR_NULL;
    m->msg[0] = '\0';
    if (st->mode < RR_FMU_INSTANTIATED || st->mode > RR_FMU_FAILED)
        return fail(m, RR_ERR_PARAM, "set FMU state: not a state of this unit");
    if (st->ready) {
        /* the pointers of the copy are remade: the rig's parameters, their
         * table (this unit's, of the state's geometry) and the
         * integrator's model function (this process's) */
        if ((status = table_for(m, &st->cfg.c)) < 0
            || (status = rig_work_for(m, rr_creep_workspace_len(&st->p.contact.creep, NULL)))
                   < 0)
            return status;
    }
    m->s = *st;
    if (m->s.ready) {
        m->s.p.contact.table = &m->table;
        /* the state's tables are this unit's (its patch needs them: rebind checks) */
        m->s.p.contact.nonhertz[0] = m->nonhertz_ok ? &m->nonhertz[0] : NULL;
        m->s.p.contact.nonhertz[1] = m->nonhertz_ok ? &m->nonhertz[1] : NULL;
        m->s.rig.work = m->rig_work;
        m->s.rig.work_len = m->rig_work_cap;
        if ((status = rr_rig_rebind(&m->s.rig, &m->s.p)) < 0)
            return fail(m, status, "set FMU state: the state's rig cannot go on: %s",
                        rr_status_message(status));
    } else {
        m->s.p.contact.table = NULL;
        m->s.p.contact.nonhertz[0] = m->s.p.contact.nonhertz[1] = NULL;
        m->s.rig.p = NULL;
        m->s.rig.ode.model = NULL;
    }
    return RR_OK;
}
